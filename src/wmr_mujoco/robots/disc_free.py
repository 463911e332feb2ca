"""The free thin disc on a free joint: no actuators, keyframes for rolling starts.

No validation scenarios yet (its rolling dynamics are measured elsewhere); registered so
that its model files are exported, listed and pictured like the others.
"""

from __future__ import annotations

from wmr_mujoco.models.builders import disc as builder
from wmr_mujoco.models.params import DiscParams
from wmr_mujoco.robots.spec import Picture, RobotSpec

SPEC = RobotSpec(
    name="disc_free",
    description="free thin disc on a free joint, no actuators; keyframes for rolling, "
                "spinning and leaning starts",
    params_type=DiscParams, build=builder.build_free, folder="disc",
    robot_file="disc_free.xml", scene_file="scene_free.xml",
    picture=Picture(keyframe="leaning"),
)
