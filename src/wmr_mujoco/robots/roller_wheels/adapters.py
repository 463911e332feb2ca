"""Adapters of roller-wheeled robots.

The protocol the probes read (:class:`OmniAdapter`), and the torque-driven reduced
Lagrange model (:class:`OmniDynamicsAdapter`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.omni_dynamics import OmniDynamics, rk4_trajectory
from wmr_mujoco.validation.adapters import POSE_UNITS, Adapter, base_pose, body_twist


@runtime_checkable
class OmniAdapter(Adapter, Protocol):
    """An adapter of an omni-wheeled robot."""

    @property
    def layout(self) -> ok.WheelLayout:
        """The analytic model's wheel layout."""
        ...

    def twist(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Body twist ``ν = (u, v, r)`` commanded by input ``u``."""
        ...


@dataclass(frozen=True)
class OmniDynamicsAdapter:
    """An omni-wheeled robot under wheel torques: ``x = (X, Y, ψ, u, v, r)``.

    The reduced Lagrange equations
    (:meth:`~wmr_mujoco.robots.roller_wheels.omni_dynamics.OmniDynamics.state_derivative`) against
    the ``base`` site's pose and body twist.

    Attributes:
        dynamics: the reduced model (e.g. from :func:`dynamics_from_model`).
        wheel_joints: the wheel hinges, in the torques' order.
        friction: the floor's Coulomb coefficient μ (for traction checks).
    """

    dynamics: OmniDynamics
    wheel_joints: tuple[str, ...]
    friction: float = 1.0
    mode: ActuationMode = ActuationMode.TORQUE
    state_names: tuple[str, ...] = ("x", "y", "heading", "u", "v", "r")
    state_units: tuple[str, ...] = (*POSE_UNITS, "m/s", "m/s", "rad/s")
    lateral_wheels: tuple[str, ...] = ()

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Torques as given."""
        return np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Reduced Lagrange equations with the world pose."""
        return self.dynamics.state_derivative(x, u)

    def trajectory(self, x0: np.ndarray, inputs: np.ndarray, dt: float) -> np.ndarray:
        """Every step's state at once: the floats of RK4 on :meth:`rhs`.

        :func:`~wmr_mujoco.robots.roller_wheels.omni_dynamics.rk4_trajectory`.
        """
        return rk4_trajectory(self.dynamics, x0, inputs, dt)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose and body twist of the ``base`` site."""
        return np.concatenate([base_pose(model, data), body_twist(model, data)])
