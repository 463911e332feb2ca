"""Physical parameters of the robots, as frozen dataclasses with validated ranges.

Every length is in metres, every mass in kilograms, every angle in radians, every
rate in rad/s and every torque in N·m. Wheels are modelled, as in the lecture, as
thin uniform discs of radius ``R``, width ``w`` and mass ``m``:

    I_axial    = m R² / 2
    I_diameter = m R² / 4 + m w² / 12

Each dataclass checks its own fields in ``__post_init__`` and raises ``ValueError``
naming the field, its value and the valid range. The field checks are in
:mod:`.fields`, the shared parts in :mod:`.parts`, each robot family's parameters in its
own module (and in ``models/params_<family>.py``).
"""

from wmr_mujoco.models.params.disc import FREE_INTEGRATORS, DiscParams, FreeDiscParams
from wmr_mujoco.models.params.fields import (
    _check_choice,
    _check_count,
    _check_floor_pair,
    _check_positive_fields,
    _check_range,
    _check_types,
    _is_number,
)
from wmr_mujoco.models.params.omni import OmniParams
from wmr_mujoco.models.params.parts import (
    MAX_GAIN,
    MAX_RATE,
    MAX_TORQUE,
    MAX_WHEEL_MASS,
    MAX_WHEEL_RADIUS,
    STEERING_FIELDS,
    DriveParams,
    SimParams,
    WheelParams,
)
from wmr_mujoco.models.params.protocol import ParamsT, RobotParams, params_or_default
from wmr_mujoco.models.params.vehicles import BicycleParams, TricycleParams

__all__ = ["FREE_INTEGRATORS", "MAX_GAIN", "MAX_RATE", "MAX_TORQUE", "MAX_WHEEL_MASS",
           "MAX_WHEEL_RADIUS", "STEERING_FIELDS", "BicycleParams", "DiscParams", "DriveParams",
           "FreeDiscParams", "OmniParams", "ParamsT", "RobotParams", "SimParams",
           "TricycleParams", "WheelParams", "_check_choice", "_check_count",
           "_check_floor_pair", "_check_positive_fields", "_check_range", "_check_types",
           "_is_number",
           "params_or_default"]
