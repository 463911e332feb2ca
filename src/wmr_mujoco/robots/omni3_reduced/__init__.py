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
from wmr_mujoco.robots.learning import NO_RADIUS_BANDS, Learning
from wmr_mujoco.robots.omni3_reduced import builder
from wmr_mujoco.robots.omni3_reduced.params import OmniReducedParams
from wmr_mujoco.robots.spec import Clip, RobotSpec
from wmr_mujoco.validation import metrics as mt
from wmr_mujoco.validation import variations as var
from wmr_mujoco.validation.metrics import Target
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind

NAME = "omni3_reduced"

#: omni3's kinematic targets (the roller-rate target has no rollers to judge).
TARGETS: Mapping[str, Target] = {k: omni3.TARGETS[k] for k in
                                 (mt.POSITION_PCT, mt.HEADING_DEG, mt.CENTRE_DRIFT_M)}

#: Families whose spread is not small on this robot (``python -m
#: wmr_mujoco.bench.family_spread omni3_reduced``: the worst of 20 draws beyond half the
#: target): judged on 20 draws.
WIDE = ("translate 45°", "translate 90°", "translate 135°", "translate 225°",
        "translate 270°", "translate+rotate")


def _own(s: Scenario) -> Scenario:
    """omni3's kinematic scenario under this robot's name, with this robot's draws.

    omni3's open targets stay omni3's (their reason is its roller rows).
    """
    family = s.family
    if family is not None and s.name in WIDE:
        family = dataclasses.replace(family, draws=var.DYNAMIC_DRAWS)
    return dataclasses.replace(s, robot=NAME, family=family, open_targets={})


#: omni3's kinematic scenarios, under this robot's name.
SCENARIOS = tuple(_own(s) for s in omni3.SCENARIOS if s.kind is ScenarioKind.KINEMATIC)

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
    # omni3's size; its wheels touch the floor through one low-friction capsule each.
    learning=Learning("Omni3Reduced", scale=0.5, max_curvature=3.0,
                      bands=NO_RADIUS_BANDS),
)
