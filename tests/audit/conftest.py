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

#: A differential drive without floor: two sphere wheels with velocity servos and a
#: frictionless ball skid (condim 1).
DIFF = """<mujoco><option timestep="0.002" integrator="implicitfast"/><worldbody>
<body name="base" pos="0 0 .05"><freejoint/><geom type="box" size=".1 .08 .02" mass="2"/>
<geom name="skid" type="sphere" size=".02" pos="-.08 0 -.03" condim="1"/>
<body name="wl" pos=".03 .1 0"><joint name="left" axis="0 1 0"/>
<geom type="sphere" size=".05" mass=".1"/></body>
<body name="wr" pos=".03 -.1 0"><joint name="right" axis="0 1 0"/>
<geom type="sphere" size=".05" mass=".1"/></body>
</body></worldbody><actuator><velocity joint="left" kv="2"/><velocity joint="right" kv="2"/>
</actuator></mujoco>"""


@pytest.fixture
def write(tmp_path: Path):
    """``write(text, name)``: an MJCF file in the test's folder."""
    def _write(text: str, name: str = "robot.xml") -> Path:
        path = tmp_path / name
        path.write_text(text)
        return path
    return _write
