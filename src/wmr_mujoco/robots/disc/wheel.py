"""The mounted disc's single-wheel model, with constants from the compiled model."""

from __future__ import annotations

import mujoco
import numpy as np

from wmr_mujoco.analytic.wheel_dynamics import WheelDynamics
from wmr_mujoco.sim.inertia import hinge_inertia


def mounted_wheel(model: mujoco.MjModel) -> WheelDynamics:
    """Single-wheel model of the mounted disc from the compiled model.

    ``m``: mass of everything the slides carry (the carriage subtree); ``J``: inertia
    about the wheel hinge, body inertia plus armature
    (:func:`~wmr_mujoco.sim.inertia.hinge_inertia`); ``R``: the collision radius;
    ``μ``: the wheel's friction (the floor's is the same); ``N = m g``.
    """
    carriage = model.body("carriage").id
    mass = float(model.body_subtreemass[carriage])
    collision = model.geom("wheel_collision")
    return WheelDynamics(mass=mass, inertia=hinge_inertia(model, "wheel"),
                         radius=float(collision.size[0]),
                         friction=float(collision.friction[0]),
                         normal_force=mass * float(np.linalg.norm(model.opt.gravity)))
