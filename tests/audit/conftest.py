"""Helpers of the audit tests: small MJCF robots written in the test, and the anchors."""

from __future__ import annotations

from pathlib import Path

import pytest

from wmr_mujoco.audit.anchors import anchor_scene


def anchor(name: str) -> Path:
    """An outside robot's scene, read in place; skip when shared/anchors is absent."""
    scene = anchor_scene(name)
    if scene is None:
        pytest.skip(f"shared/anchors/{name} is not beside the checkout (nor WMR_ANCHORS)")
    return scene


#: A two-legged body: hinged capsule legs touch the floor (no wheels).
LEGS = """<mujoco><worldbody><geom type="plane" size="2 2 .1"/>
<body name="torso" pos="0 0 .55"><freejoint/><geom type="box" size=".1 .1 .1"/>
<body name="leg_l" pos="0 .08 -.1"><joint name="hip_l" axis="0 1 0"/>
<geom type="capsule" fromto="0 0 0 0 0 -.4" size=".03"/></body>
<body name="leg_r" pos="0 -.08 -.1"><joint name="hip_r" axis="0 1 0"/>
<geom type="capsule" fromto="0 0 0 0 0 -.4" size=".03"/></body>
</body></worldbody></mujoco>"""



def diff_xml(wheel: str = 'type="sphere" size=".05"', servo: str = 'kv="2"',
             option: str = 'timestep="0.002" integrator="implicitfast"',
             caster: str = "") -> str:
    """A differential drive (robot file, no floor) with its parts as options.

    Args:
        wheel: the wheels' geom attributes (shape and size; centre 5 cm above the floor).
        servo: the velocity servos' attributes.
        option: the ``<option>`` attributes.
        caster: attributes of a ball caster's ball joint; empty: a frictionless skid
            (``condim`` 1 with a higher ``priority`` than the floor, whose condim 3 would
            otherwise win).
    """
    rear = (f'<body name="caster" pos="-.08 0 -.03"><joint name="ball" type="ball" {caster}/>'
            '<geom type="sphere" size=".02" mass=".05"/></body>' if caster else
            '<geom name="skid" type="sphere" size=".02" pos="-.08 0 -.03" condim="1" '
            'priority="1"/>')
    wheels = "".join(f'<body name="w{s}" pos=".03 {y} 0"><joint name="{s}" axis="0 1 0"/>'
                     f'<geom {wheel} mass=".1"/></body>'
                     for s, y in (("left", ".1"), ("right", "-.1")))
    return (f'<mujoco><option {option}/><worldbody><body name="base" pos="0 0 .05">'
            f'<freejoint/><geom type="box" size=".1 .08 .02" mass="2"/>{rear}{wheels}'
            f'</body></worldbody><actuator><velocity joint="left" {servo}/>'
            f'<velocity joint="right" {servo}/></actuator></mujoco>')


#: The plain differential drive: sphere wheels, velocity servos, a frictionless skid.
DIFF = diff_xml()


@pytest.fixture
def write(tmp_path: Path):
    """``write(text, name)``: an MJCF file in the test's folder."""
    def _write(text: str, name: str = "robot.xml") -> Path:
        path = tmp_path / name
        path.write_text(text)
        return path
    return _write
