"""The required accuracy (issues 3 and 5), shared by the robots judged on it.

Every figure here is a **requirement**: a number asked for, not derived. Robot modules
pick from these and add their own derived bounds beside them.
"""

from __future__ import annotations

from wmr_mujoco.validation import metrics as mt
from wmr_mujoco.validation.metrics import Target

#: What the requirements ask for (the basis column of the report).
SOURCE = "accuracy asked of the analytic model"


def position_pct(value: float, source: str = SOURCE) -> Target:
    """Worst position error over the run, % of the analytic path length."""
    return Target.requirement(value, f"{source}: position within {value:g} % of path "
                                     "over the whole run")


def heading_deg(value: float, source: str) -> Target:
    """Worst heading error over the run, degrees."""
    return Target.requirement(value, f"{source}: heading within {value:g}° over the whole run")


def vehicle_targets(position: float) -> dict[str, Target]:
    """Targets of a wheeled vehicle on rate inputs: worst position error and lateral slip."""
    return {mt.POSITION_PCT: position_pct(position), mt.LATERAL_SLIP_RMS: LATERAL_SLIP_RMS}


#: Lateral slip speed at a conventional wheel's contact, RMS over the run, m/s.
LATERAL_SLIP_RMS = Target.requirement(1e-3, f"{SOURCE}: non-holonomic constraint residual "
                                            "≤ 1 mm/s RMS")
#: Worst heading error over the run, degrees.
HEADING_DEG = heading_deg(1.0, SOURCE)
