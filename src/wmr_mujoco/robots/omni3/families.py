"""omni3's measurement scenarios as families: what a user would vary, and how it is run.

Every measurement scenario varies the wheels' start phase over a full roller pitch of
one row (6 rollers a row: 60°, which holds a hand-over of each row and both rows'
roller centres; every wheel starts at the same angle). Beside it:

* step commands and torque inputs: the command's ``scale``, ±20 %;
* the coast: its lead-in ``speed`` and ``yaw_rate`` ±20 % of (0.3 m/s, 1 rad/s), the
  coast's duration ±20 % of 3 s, and the lead-in's ``ramp`` from 0 (a step) to 0.5 s;
* the slip onset: the phase alone (the ramp is the measurement).

20 draws each (issue 24: at least 20 for every dynamic family). :func:`prepare` runs
all the members it is given in one batch per kind (threaded rollouts and one vectorised
hybrid integration), so that each member's ``evaluate`` finds its run ready.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from wmr_mujoco.robots.omni3 import members, traction
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import RunSpec
from wmr_mujoco.validation.family import Family, Vary
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind

#: Draws of every omni3 measurement family.
DRAWS = 20
#: One roller pitch of a row, deg.
PITCH_DEG = 60.0
PHASE = Vary("phase", 0.0, PITCH_DEG, "deg")
SCALE = Vary("scale", 0.8, 1.2)
STEP_FAMILY = Family((PHASE, SCALE), draws=DRAWS)
TORQUE_FAMILY = Family((PHASE, SCALE), draws=DRAWS)
COAST_FAMILY = Family((PHASE, Vary("speed", 0.24, 0.36, "m/s"),
                       Vary("yaw_rate", 0.8, 1.2, "rad/s"), Vary("coast", 2.4, 3.6, "s"),
                       Vary("ramp", 0.0, 0.5, "s")), draws=DRAWS)
SLIP_FAMILY = Family((PHASE,), draws=DRAWS)


def prepare(scenarios: Sequence[Scenario], params: OmniParams | None) -> None:
    """Run every given omni3 measurement member at once (see the module docstring).

    Members of other scenarios are ignored; the dynamic runs are one batch (the physics
    in chunks, :data:`~wmr_mujoco.robots.omni3.runs.CHUNK`; the hybrid model vectorised
    over all), the slip ramps another.
    """
    from wmr_mujoco.robots.omni3 import DYNAMIC_SPECS

    base = {s.name: s for s in DYNAMIC_SPECS}
    specs: list[RunSpec] = []
    phases: list[float] = []
    for sc in scenarios:
        if sc.robot != "omni3" or sc.kind is not ScenarioKind.MEASUREMENT:
            continue
        if sc.name in base:
            specs.append(members.member_spec(sc, base[sc.name]))
        elif sc.name == "slip onset":
            phases.append(math.radians(sc.value("phase", 0.0)))
    if specs:
        members.prepare(specs, params)
    if phases:
        traction.prepare(phases, params)
