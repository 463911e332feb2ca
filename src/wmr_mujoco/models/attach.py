"""Attach a robot's MJCF into another model (a dm_control ``mjcf`` arena).

MuJoCo allows a free joint only on a top-level body, and ``arena.attach(robot)`` puts the
robot's top-level body under an attachment frame: a robot file with a free joint fails
to compile there (``free joint can only be used on top level``). The dm_control way is to
give the *frame* the free joint. Some robots also keep their wheel-floor contacts as
explicit ``<pair>`` elements naming the scene's ``floor`` (the rollers of mecanum4, the
disc's tuned contact), which a scene adds (``RobotSpec.scene_extras``): attached alone,
such a robot would lose them and sink through the arena's floor without a word.

:func:`attach_robot` does both: it removes the robot's top-level free joint (and its
keyframes, whose ``qpos`` no longer fits), attaches it at ``pos`` with a free joint on
the frame, and re-creates each contact pair the robot's scene would add against the
arena's floor, with the options that scene sets (the pairs' ``impratio``: MuJoCo has one
per model, and the robot file's own is the collision class's).
``wmr_mujoco.attach(arena, "omni3", pos=...)`` looks the robot up by name.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from dm_control import mjcf

#: ``extras(scene_root, params)``: adds the contact pairs a robot's scene needs, naming
#: the floor ``"floor"`` and the robot's geoms by their names in the robot file.
SceneExtras = Callable[[mjcf.RootElement, object], None]


def arena_floor(arena: mjcf.RootElement, floor: str | None = None) -> mjcf.Element:
    """The arena's floor geom: the one named ``floor``, else its only plane on the world.

    Raises:
        ValueError: no such geom, or no or several planes (the message lists them).
    """
    if floor is not None:
        geom = arena.find("geom", floor)
        if geom is None:
            names = [g.name for g in arena.worldbody.find_all("geom") if g.name]
            raise ValueError(f"floor = {floor!r}: the arena has no geom of that name; its "
                             f"named geoms: {', '.join(names) or 'none'}")
        return geom
    planes = [g for g in arena.worldbody.get_children("geom") if g.type == "plane"]
    if len(planes) != 1:
        found = ", ".join(repr(g.name) for g in planes) or "none"
        raise ValueError(f"the arena has {len(planes)} plane geoms on its world body "
                         f"({found}); name the floor: floor='...'")
    return planes[0]


def _top_free_joints(robot: mjcf.RootElement) -> list[mjcf.Element]:
    return [j for body in robot.worldbody.get_children("body") for j in body.all_children()
            if j.tag == "freejoint" or (j.tag == "joint" and j.type == "free")]


def attach_robot(arena: mjcf.RootElement, robot: mjcf.RootElement,
                 pos: Sequence[float] = (0.0, 0.0, 0.0), quat: Sequence[float] | None = None,
                 extras: SceneExtras | None = None, params: object = None,
                 floor: str | None = None) -> mjcf.Element:
    """Attach ``robot`` to ``arena`` at ``pos`` and return the attachment frame.

    The robot's top-level free joint moves to the frame (so it compiles below the
    arena's world body and still moves freely); a robot on other base joints (slides
    and a hinge) keeps them, relative to the frame. The robot's keyframes are dropped.
    The robot's ``<option>``, defaults and assets come along (dm_control merges them;
    a conflicting ``<option>`` is dm_control's error). ``extras`` (the robot's
    ``scene_extras`` and its ``params``) adds the contact pairs of the robot's scene,
    between the arena's floor (:func:`arena_floor`) and the robot's geoms, and the
    ``<option>`` attributes its scene sets over the robot file's (the floor pairs'
    ``impratio``, :mod:`wmr_mujoco.models.builders.wheel_pairs`).

    Args:
        arena: the model to attach to (it keeps its own floor, light, ...).
        robot: the robot's root element (e.g. ``mjcf.from_path(robot.xml)``); changed.
        pos: the frame's position in the arena, m: where the robot's file origin goes.
        quat: the frame's orientation (w, x, y, z); None: the arena's axes.
        extras: ``extras(scene, params)`` adding the robot's contact pairs (None: none).
        params: the robot's parameters, passed to ``extras``.
        floor: the arena's floor geom by name (None: its only plane).

    Raises:
        ValueError: several top-level bodies with free joints; a floor that cannot be
            found; a contact pair naming a geom the robot lacks; an arena whose own
            ``<option>`` sets another value than the robot's scene.
    """
    floor_geom = arena_floor(arena, floor) if extras is not None else None
    free = _top_free_joints(robot)
    if len(free) > 1:
        raise ValueError(f"robot {robot.model!r} has {len(free)} top-level bodies with free "
                         "joints; attach one body at a time")
    for joint in free:
        joint.remove()
    for key in robot.find_all("key"):
        key.remove()
    pairs, options = [], {}
    if extras is not None:
        scratch = mjcf.RootElement(model="scene")
        extras(scratch, params)
        pairs = [p.get_attributes() for p in scratch.contact.get_children("pair")]
        options = scratch.option.get_attributes()
    for name, value in options.items():  # over the robot file's, as its scene does
        setattr(robot.option, name, value)
        have = getattr(arena.option, name)
        if have is not None and not np.array_equal(have, value):
            raise ValueError(f"robot {robot.model!r}: its scene sets option {name} = "
                             f"{value!r}, the arena {have!r}; a model has one: leave the "
                             f"arena's {name} unset or set it to {value!r}")
    frame = arena.attach(robot)
    frame.pos = tuple(pos)
    if quat is not None:
        frame.quat = tuple(quat)
    if free:
        frame.add("freejoint")
    for attrs in pairs:
        attrs.pop("name", None)
        geoms = []
        for key in ("geom1", "geom2"):
            name = attrs.pop(key)
            name = getattr(name, "name", name)
            geom = floor_geom if name == "floor" else robot.find("geom", name)
            if geom is None:
                raise ValueError(f"robot {robot.model!r}: its scene's contact pair names "
                                 f"geom {name!r}, which the robot file lacks")
            geoms.append(geom)
        arena.contact.add("pair", geom1=geoms[0], geom2=geoms[1], **attrs)
    return frame
