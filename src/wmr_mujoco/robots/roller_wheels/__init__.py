"""The roller-wheel family: omni3's omni wheels and mecanum4's mecanum wheels.

Code both robots (and a foreign omni-wheeled peer) share: reading a compiled model's
wheels and rollers (:mod:`.model_info`), their adapters (:mod:`.adapters`), per-step
probes (:mod:`.probes`), open-loop manoeuvres (:mod:`.inputs`), the twist errors of
their torque runs (:mod:`.twist_errors`) and the open-loop trials of the studies
(:mod:`.trials`).
"""

from wmr_mujoco.robots.roller_wheels.adapters import OmniAdapter, OmniDynamicsAdapter
from wmr_mujoco.robots.roller_wheels.inputs import (
    DIRECTIONS_DEG,
    RAMP,
    SPEED,
    YAW_RATE,
    translation,
    twist_inputs,
)
from wmr_mujoco.robots.roller_wheels.model_info import (
    OmniModelInfo,
    drive_from_model,
    dynamics_from_model,
    hybrid_from_model,
    lagrange_of,
    layout_from_model,
    roller_rates,
    static_penetration,
)
from wmr_mujoco.robots.roller_wheels.probes import (
    ROLLER_RATE_PCT,
    STEADY_AFTER,
    RollerRateProbe,
    WheelRateProbe,
    YawRippleProbe,
    omni_probes,
    roller_rate_errors,
    rolling_radius_profile,
)

__all__ = ["DIRECTIONS_DEG", "RAMP", "ROLLER_RATE_PCT", "SPEED", "STEADY_AFTER", "YAW_RATE",
           "OmniAdapter", "OmniDynamicsAdapter", "OmniModelInfo", "RollerRateProbe",
           "WheelRateProbe", "YawRippleProbe", "drive_from_model", "dynamics_from_model",
           "hybrid_from_model", "lagrange_of", "layout_from_model", "omni_probes",
           "roller_rate_errors", "roller_rates", "rolling_radius_profile",
           "static_penetration", "translation", "twist_inputs"]
