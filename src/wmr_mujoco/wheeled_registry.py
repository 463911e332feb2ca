"""Registry entries of the caster robots, ready to merge into :data:`wmr_mujoco.registry.ROBOTS`.

Each entry is a :class:`wmr_mujoco.registry.RobotSpec`; integration is one line per robot
in the registry (or ``ROBOTS.update(SPECS)``).
"""

from __future__ import annotations

from wmr_mujoco.builders import diffdrive, steered
from wmr_mujoco.params_wheeled import DiffDriveParams, DoubleSteerParams, SingleSteerParams
from wmr_mujoco.registry import RobotSpec

SPECS: dict[str, RobotSpec] = {
    spec.name: spec
    for spec in (
        RobotSpec("diffdrive", "differential drive: two driven wheels on one axle and a "
                  "passive ball caster; Campion class (2,0)", "diffdrive", "diffdrive.xml",
                  "scene.xml", DiffDriveParams, diffdrive.build),
        RobotSpec("single_steer", "one centred steerable driven wheel and two ball casters; "
                  "Campion class (2,1)", "single_steer", "single_steer.xml", "scene.xml",
                  SingleSteerParams, steered.build_single),
        RobotSpec("double_steer", "two centred steerable driven wheels and a ball caster; "
                  "Campion class (1,2)", "double_steer", "double_steer.xml", "scene.xml",
                  DoubleSteerParams, steered.build_double),
    )
}


def get_spec(robot: str) -> RobotSpec:
    """Look a caster robot up by name.

    Raises:
        ValueError: unknown name; the message lists the valid ones.
    """
    try:
        return SPECS[robot]
    except (KeyError, TypeError):
        raise ValueError(f"unknown robot {robot!r}; valid robots are: "
                         f"{', '.join(SPECS)}") from None
