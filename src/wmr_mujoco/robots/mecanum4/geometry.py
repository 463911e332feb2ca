"""The analytic wheel layout of ``mecanum4`` from its parameters."""

from __future__ import annotations

import numpy as np

from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok


def layout(params: MecanumParams) -> ok.WheelLayout:
    """Ideal layout of the model's wheels in FL, FR, RL, RR order, roller angles ``∓γ``.

    Wheels at ``(±a, ±w)`` drive along +x; FL and RR carry ``−γ``, FR and RL ``+γ``
    (:func:`wmr_mujoco.robots.roller_wheels.omni_kinematics.mecanum_layout`, γ from the parameters).
    """
    lay = ok.mecanum_layout(params.wheel_radius, params.half_length, params.half_track)
    gamma = np.sign(lay.roller_angles) * params.roller_angle
    return ok.WheelLayout(lay.positions, lay.drive_angles, gamma, lay.radii)
