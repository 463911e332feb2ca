"""Physical parameters of the robots, as frozen dataclasses with validated ranges.

Every length is in metres, every mass in kilograms, every angle in radians, every
rate in rad/s and every torque in N·m. Wheels are modelled, as in the lecture, as
thin uniform discs of radius ``R``, width ``w`` and mass ``m``:

    I_axial    = m R² / 2
    I_diameter = m R² / 4 + m w² / 12

Each dataclass checks its own fields in ``__post_init__`` and raises ``ValueError``
naming the field, its value and the valid range. The field checks are in
:mod:`.fields`, the parts several robots share in :mod:`.parts` and :mod:`.wheeled`, the
protocol every robot's parameters follow in :mod:`.protocol`. Each robot's own parameters
are in its folder, ``wmr_mujoco.robots.<robot>.params``.
"""

from wmr_mujoco.models.params.fields import (
    _check_choice,
    _check_count,
    _check_floor_pair,
    _check_mesh_rollers,
    _check_positive_fields,
    _check_range,
    _check_types,
    _is_number,
)
from wmr_mujoco.models.params.parts import (
    MAX_GAIN,
    MAX_RATE,
    MAX_TORQUE,
    MAX_WHEEL_MASS,
    MAX_WHEEL_RADIUS,
    PAIRS_SET_IMPRATIO,
    SIM_PAIR_FIELDS,
    STEERING_FIELDS,
    DriveParams,
    SimParams,
    WheelParams,
)
from wmr_mujoco.models.params.protocol import ParamsT, RobotParams, params_or_default

__all__ = ["MAX_GAIN", "MAX_RATE", "MAX_TORQUE", "MAX_WHEEL_MASS",
           "MAX_WHEEL_RADIUS", "PAIRS_SET_IMPRATIO", "SIM_PAIR_FIELDS", "STEERING_FIELDS",
           "DriveParams",
           "ParamsT", "RobotParams", "SimParams",
           "WheelParams", "_check_choice", "_check_count",
           "_check_floor_pair", "_check_mesh_rollers", "_check_positive_fields",
           "_check_range", "_check_types",
           "_is_number",
           "params_or_default"]
