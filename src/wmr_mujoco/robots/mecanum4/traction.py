"""Step commands on ``mecanum4``: the traction-limited rise time.

Derivation in :mod:`wmr_mujoco.analytic.roller_traction`; mass and yaw inertia are read
from the compiled model, the wheel loads are ``N_i = m g / 4`` (centre of mass at the
centre).
"""

from __future__ import annotations

import mujoco
import numpy as np

from wmr_mujoco.analytic.roller_traction import acceleration_time
from wmr_mujoco.models.builders.mecanum4 import WHEEL_NAMES
from wmr_mujoco.models.params_mecanum import MecanumParams
from wmr_mujoco.robots.mecanum4.geometry import layout
from wmr_mujoco.validation.omni_wheels import dynamics_from_model

#: Gravity, m/s².
GRAVITY = 9.81


def step_acceleration_time(model: mujoco.MjModel, params: MecanumParams,
                           twist: np.ndarray) -> float:
    """Least time to reach ``twist`` from rest with roller-axis forces ``|F_i| ≤ μ m g/4``."""
    lay = layout(params)
    dyn = dynamics_from_model(model, lay, "chassis", WHEEL_NAMES[0])
    loads = np.full(lay.n, dyn.mass * GRAVITY / lay.n)
    return acceleration_time(lay, dyn.mass, dyn.yaw_inertia, loads, params.sim.friction,
                             twist)
