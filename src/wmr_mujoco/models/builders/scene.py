"""The floor, light and sky that every ``scene.xml`` adds around a robot."""

from __future__ import annotations

from dm_control import mjcf


def add_scene(root: mjcf.RootElement) -> None:
    """Add a checkered floor plane, a skybox, a directional light and headlight.

    Elements are appended, so calling this on a robot root gives the same compiled
    model as a ``scene.xml`` that ``<include>``s the robot file and then declares them.
    """
    root.statistic.center = (0.0, 0.0, 0.2)
    root.statistic.extent = 1.5
    root.visual.headlight.diffuse = (0.6, 0.6, 0.6)
    root.visual.headlight.ambient = (0.3, 0.3, 0.3)
    root.visual.headlight.specular = (0, 0, 0)
    root.visual.rgba.haze = (0.15, 0.25, 0.35, 1)
    root.visual.get_children("global").azimuth = 120
    root.visual.get_children("global").elevation = -20
    root.visual.get_children("global").offwidth = 1280
    root.visual.get_children("global").offheight = 720
    root.asset.add("texture", type="skybox", builtin="gradient", rgb1=(0.3, 0.5, 0.7),
                   rgb2=(0, 0, 0), width=512, height=3072)
    root.asset.add("texture", type="2d", name="groundplane", builtin="checker",
                   mark="edge", rgb1=(0.2, 0.3, 0.4), rgb2=(0.1, 0.2, 0.3),
                   markrgb=(0.8, 0.8, 0.8), width=300, height=300)
    root.asset.add("material", name="groundplane", texture="groundplane",
                   texuniform=True, texrepeat=(5, 5), reflectance=0.2)
    root.worldbody.add("light", pos=(0, 0, 3.5), dir=(0, 0, -1), directional=True)
    root.worldbody.add("geom", name="floor", size=(0, 0, 0.05), type="plane",
                       material="groundplane")
