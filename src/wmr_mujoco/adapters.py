"""What ties a robot's MuJoCo model to its analytic model.

Each adapter says, for one robot: how the lecture's inputs become actuator controls, the
analytic state and its derivative, how to read that state from the simulation, and which
wheels are conventional (for lateral-slip measurement). Kinematic adapters take rate
inputs; dynamic adapters take torques.

Inputs (lecture symbols):
    disc:      (v, ω)       wheel ground speed R θ̇, steering rate
    bicycle:   (v_r, ω)     rear wheel ground speed, steering rate
    tricycle:  (v_L, ω)     driven left rear wheel ground speed, steering rate
    omni3:     (u, v, r)    body twist; ``world_frame`` scenarios give (Ẋ, Ẏ, ψ̇)
    disc (torque):  (τ_wheel, τ_steer)
    omni3 (torque): (τ₁, τ₂, τ₃)
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Protocol

import mujoco
import numpy as np

from wmr_mujoco.analytic import bicycle, omni_kinematics, tricycle, unicycle
from wmr_mujoco.analytic.omni_dynamics import OmniDynamics
from wmr_mujoco.analytic.wheel_dynamics import WheelDynamics
from wmr_mujoco.params import BicycleParams, DiscParams, OmniParams, TricycleParams


def base_pose(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
    """World ``(x, y, heading)`` of the ``base`` site."""
    site = model.site("base").id
    xmat = data.site_xmat[site]
    return np.array([data.site_xpos[site][0], data.site_xpos[site][1],
                     np.arctan2(xmat[3], xmat[0])])


def body_twist(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
    """Body-frame ``(u, v, r)`` of the ``base`` site."""
    site = model.site("base").id
    vel = np.zeros(6)
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_SITE, site, vel, 1)
    return np.array([vel[3], vel[4], vel[2]])


class Adapter(Protocol):
    """Interface of a robot adapter (see the module docstring)."""

    robot: str
    mode: str
    state_names: tuple[str, ...]
    wheel_joints: tuple[str, ...]
    lateral_wheels: tuple[str, ...]

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Actuator controls for input ``u``.

        The analytic state is passed for open-loop schedules that depend on it.
        """
        ...

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Analytic state derivative ``ẋ = f(x, u)``."""
        ...

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """The analytic state's quantities, read from the simulation."""
        ...


@dataclass(frozen=True)
class DiscKinematics:
    """Disc: ``x = (x, y, φ)``; controls ``(v/R, ω)``."""

    params: DiscParams = DiscParams()
    robot: str = "disc"
    mode: str = "rate"
    state_names: tuple[str, ...] = ("x", "y", "heading")
    wheel_joints: tuple[str, ...] = ("wheel",)
    lateral_wheels: tuple[str, ...] = ("wheel",)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        return np.array([u[0] / self.params.wheel.radius, u[1]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        return unicycle.rates(x, u)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        return base_pose(model, data)


@dataclass(frozen=True)
class BicycleKinematics:
    """Bicycle: ``x = (x, y, ψ, φ)``; controls ``(v_r/R_r, ω)``."""

    params: BicycleParams = BicycleParams()
    robot: str = "bicycle"
    mode: str = "rate"
    state_names: tuple[str, ...] = ("x", "y", "heading", "steer")
    wheel_joints: tuple[str, ...] = ("rear_wheel", "front_wheel")
    lateral_wheels: tuple[str, ...] = ("rear_wheel", "front_wheel")

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        return np.array([u[0] / self.params.rear_wheel.radius, u[1]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        return bicycle.rates(x, u, self.params.wheelbase)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        return np.append(base_pose(model, data), data.joint("steer").qpos[0])


@dataclass(frozen=True)
class TricycleKinematics:
    """Tricycle: ``x = (x, y, ψ, φ)`` of the rear-axle midpoint; controls ``(v_L/R, ω)``.

    The driven left wheel at ``v_L`` moves the midpoint at ``v_L / (1 − k)``,
    ``k = (w/2ℓ) tan φ`` (:mod:`wmr_mujoco.analytic.tricycle`).
    """

    params: TricycleParams = TricycleParams()
    robot: str = "tricycle"
    mode: str = "rate"
    state_names: tuple[str, ...] = ("x", "y", "heading", "steer")
    wheel_joints: tuple[str, ...] = ("rear_left_wheel", "rear_right_wheel", "front_wheel")
    lateral_wheels: tuple[str, ...] = ("rear_left_wheel", "rear_right_wheel", "front_wheel")

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        return np.array([u[0] / self.params.rear_wheel.radius, u[1]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        p = self.params
        v_mid = tricycle.midpoint_speed_from_left(u[0], x[3], p.track, p.wheelbase)
        return tricycle.rates(x, np.array([v_mid, u[1]]), p.wheelbase)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        return np.append(base_pose(model, data), data.joint("steer").qpos[0])


@dataclass(frozen=True)
class OmniKinematics:
    """Omni robot: ``x = (X, Y, ψ)``; controls ``θ̇ = H ν``.

    With ``world_frame`` the inputs are world rates ``(Ẋ, Ẏ, ψ̇)``, turned into a body
    twist with the analytic heading (an open-loop schedule, known in advance).
    """

    params: OmniParams = OmniParams()
    world_frame: bool = False
    robot: str = "omni3"
    mode: str = "rate"
    state_names: tuple[str, ...] = ("x", "y", "heading")
    wheel_joints: tuple[str, ...] = ("wheel1", "wheel2", "wheel3")
    lateral_wheels: tuple[str, ...] = ()

    @functools.cached_property
    def layout(self) -> omni_kinematics.WheelLayout:
        """Ideal wheel layout."""
        return omni_kinematics.symmetric_layout(self.params.wheel_radius,
                                                self.params.wheel_distance)

    @functools.cached_property
    def jacobian(self) -> np.ndarray:
        """``H`` with ``θ̇ = H ν``."""
        return omni_kinematics.wheel_jacobian(self.layout)

    def twist(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Body twist commanded by input ``u``."""
        if self.world_frame:
            return omni_kinematics.world_to_body(analytic_state[2], u)
        return np.asarray(u, float)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        return self.jacobian @ self.twist(u, analytic_state)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        return omni_kinematics.body_to_world(x[2], self.twist(u, x))

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        return base_pose(model, data)


@dataclass(frozen=True)
class DiscDynamics:
    """Disc under wheel torque: ``x = (s, ṡ)`` distance and speed along the heading.

    Analytic model :class:`WheelDynamics` with the moving mass (disc + carriage) and the
    disc's axial inertia.
    """

    params: DiscParams = DiscParams()
    robot: str = "disc"
    mode: str = "torque"
    state_names: tuple[str, ...] = ("distance", "speed")
    wheel_joints: tuple[str, ...] = ("wheel",)
    lateral_wheels: tuple[str, ...] = ("wheel",)

    @property
    def wheel(self) -> WheelDynamics:
        """The single-wheel model."""
        p = self.params
        return WheelDynamics(mass=p.total_mass, inertia=p.wheel.axial_inertia,
                             radius=p.wheel.radius, friction=p.sim.friction)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        return np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        return np.array([x[1], self.wheel.rolling_acceleration(u[0])])

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        heading = data.joint("steer").qpos[0]
        direction = np.array([np.cos(heading), np.sin(heading)])
        return np.array([data.qpos[:2] @ direction, data.qvel[:2] @ direction])


def omni_dynamics_from_model(model: mujoco.MjModel, params: OmniParams) -> OmniDynamics:
    """Lagrange-model parameters read from the compiled omni model.

    ``M``: total mass; ``I_z``: composite yaw inertia about the centre; ``I_w``: each
    wheel's inertia about its axle (hub, rollers with parallel-axis terms, and the
    hinge's armature). The rollers' spin about their own axes is neglected.
    """
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    centre = data.xpos[model.body("platform").id]

    def inertia_about(bodies: list[int], point: np.ndarray, axis: np.ndarray) -> float:
        total = 0.0
        for b in bodies:
            rot = data.ximat[b].reshape(3, 3)
            inertia = rot @ np.diag(model.body_inertia[b]) @ rot.T
            r = data.xipos[b] - point
            r_perp = r - axis * (r @ axis)
            total += axis @ inertia @ axis + model.body_mass[b] * (r_perp @ r_perp)
        return float(total)

    robot = list(range(1, model.nbody))
    wheel = model.joint("wheel1")
    wheel_body = int(wheel.bodyid[0])
    subtree = [b for b in robot if b == wheel_body or model.body_parentid[b] == wheel_body]
    jid = wheel.id
    i_w = inertia_about(subtree, data.xanchor[jid], data.xaxis[jid]) + float(
        model.dof_armature[model.jnt_dofadr[jid]])
    return OmniDynamics(
        mass=float(sum(model.body_mass[robot])),
        yaw_inertia=inertia_about(robot, centre, np.array([0.0, 0.0, 1.0])),
        wheel_inertia=i_w,
        layout=omni_kinematics.symmetric_layout(params.wheel_radius, params.wheel_distance))


@dataclass(frozen=True)
class OmniDynamicsAdapter:
    """Omni robot under wheel torques: ``x = (X, Y, ψ, u, v, r)``, reduced Lagrange EOM."""

    dynamics: OmniDynamics
    friction: float = 1.0
    robot: str = "omni3"
    mode: str = "torque"
    state_names: tuple[str, ...] = ("x", "y", "heading", "u", "v", "r")
    wheel_joints: tuple[str, ...] = ("wheel1", "wheel2", "wheel3")
    lateral_wheels: tuple[str, ...] = ()

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        return np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        return self.dynamics.state_derivative(x, u)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        return np.concatenate([base_pose(model, data), body_twist(model, data)])
