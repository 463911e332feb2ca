"""omni3_reduced: omni3 with each omni wheel reduced to one capsule of anisotropic friction.

The cheapest rung of omni3's fidelity ladder (``docs/ladder.md``): per wheel one driven
hinge and one smooth collider, no roller joints (9 degrees of freedom against omni3's
45). The rollers' freedom is the contact's: the capsule lies along the axle, MuJoCo's
plane-capsule collider puts the contact frame's first tangent along the capsule's axis,
and the explicit floor pair gives that tangent friction :data:`builder.ROLLER_FRICTION`
(the sideways roll the rollers allow) and the second tangent, the drive direction, the
floor's μ. Same actuators (velocity servos ``wheel1..3``), wheel order, signs, kinematic
adapter, command and kinematic scenarios as omni3 (imported, not copied); omni3's
dynamic scenarios read its rollers and are omni3's alone (the ladder compares the rungs'
dynamics with omni3's physics instead).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

from wmr_mujoco.robots import omni3
from wmr_mujoco.robots.omni3_reduced import builder
from wmr_mujoco.robots.omni3_reduced.params import OmniReducedParams
from wmr_mujoco.robots.spec import Clip, RobotSpec
from wmr_mujoco.validation import metrics as mt
from wmr_mujoco.validation.metrics import Target
from wmr_mujoco.validation.scenarios import ScenarioKind

NAME = "omni3_reduced"

#: omni3's kinematic targets (the roller-rate target has no rollers to judge).
TARGETS: Mapping[str, Target] = {k: omni3.TARGETS[k] for k in
                                 (mt.POSITION_PCT, mt.HEADING_DEG, mt.CENTRE_DRIFT_M)}

#: omni3's kinematic scenarios, under this robot's name.
SCENARIOS = tuple(dataclasses.replace(s, robot=NAME, open_targets={}) for s in omni3.SCENARIOS
                  if s.kind is ScenarioKind.KINEMATIC)

SPEC = RobotSpec(
    name=NAME,
    description="omni3 reduced: each omni wheel one driven hinge carrying one capsule whose "
                "floor friction is low along the axle, where the rollers let it roll (no "
                "roller joints)",
    params_type=OmniReducedParams, build=builder.build, folder=NAME,
    robot_file=f"{NAME}.xml",
    adapters={ScenarioKind.KINEMATIC: omni3.kinematic_adapter},
    targets=TARGETS, scenarios=SCENARIOS, demo_scenario="square with rotation",
    bench_scenario="translate+rotate", render_scenario="square with rotation",
    clips=(Clip(),), command=omni3.COMMAND, scene_extras=builder.floor_pairs,
)
