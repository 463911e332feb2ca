"""Pose and trajectory control of a holonomic base (omni3, mecanum4).

A holonomic base can move in any direction while turning, so the position and heading
errors are controlled independently in the WORLD frame by a proportional law with
feed-forward, then rotated into the body frame (the command is the body twist):

    [Ẋ, Ẏ, ψ̇]_cmd = [Ẋ_r, Ẏ_r, ψ̇_r] + K [x_r − x, y_r − y, wrap(ψ_r − ψ)],
    u = cos ψ Ẋ + sin ψ Ẏ,   v = −sin ψ Ẋ + cos ψ Ẏ,   r = ψ̇.

With the kinematic model ``(Ẋ, Ẏ) = R(ψ) (u, v)`` the closed loop is three decoupled
first-order systems ``ė_i = −K_i e_i``: each error decays as ``exp(−K_i t)`` (for a
pose reference with no feed-forward), whatever the heading does meanwhile. (See e.g.
Lynch & Park, "Modern Robotics", §13.5, feedforward-plus-feedback control of a
kinematic mobile base.) Translation is saturated at ``max_speed`` by scaling.
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.loop.control.base import (
    CommandKind,
    Controller,
    StateLike,
    Trajectory,
    positive,
    wrap,
)


class HolonomicPose(Controller):
    """World-frame P law with feed-forward, rotated into the body frame.

    The reference is a goal pose ``(x, y, ψ)`` or a :class:`Trajectory` (its heading the
    path's tangent; feed-forward ``v_r`` along it and ``ω_r``).

    Args:
        k_xy: position gain, 1/s.
        k_heading: heading gain, 1/s.
        max_speed: translational speed limit, m/s.
        max_rate: yaw-rate limit, rad/s.
    """

    name = "holonomic"
    kinds = (CommandKind.HOLONOMIC,)
    reference_type = "pose"

    def __init__(self, k_xy: float = 2.0, k_heading: float = 2.0, max_speed: float = 0.6,
                 max_rate: float = 2.0) -> None:
        self.k_xy = positive("k_xy", k_xy)
        self.k_heading = positive("k_heading", k_heading)
        self.max_speed = positive("max_speed", max_speed)
        self.max_rate = positive("max_rate", max_rate)
        super().__init__(CommandKind.HOLONOMIC)

    def __call__(self, state: StateLike, reference: np.ndarray | Trajectory,
                 t: float) -> np.ndarray:
        """Body twist ``(u, v, r)`` toward the reference."""
        if isinstance(reference, Trajectory):
            point, v_r, omega_r = reference.at(t)
            goal = point.pose
            ff = np.array([v_r * math.cos(goal[2]), v_r * math.sin(goal[2]), omega_r])
        else:
            goal = np.asarray(reference, float)
            if goal.shape != (3,) or not np.isfinite(goal).all():
                raise ValueError(f"goal pose = {reference!r}; must be a finite "
                                 "(x, y, heading) or a Trajectory")
            ff = np.zeros(3)
        x, y, psi = np.asarray(state.pose, float)[:3]
        world = ff + np.array([self.k_xy * (goal[0] - x), self.k_xy * (goal[1] - y),
                               self.k_heading * wrap(goal[2] - psi)])
        speed = math.hypot(world[0], world[1])
        if speed > self.max_speed:
            world[:2] *= self.max_speed / speed
        world[2] = float(np.clip(world[2], -self.max_rate, self.max_rate))
        c, s = math.cos(psi), math.sin(psi)
        return np.array([c * world[0] + s * world[1], -s * world[0] + c * world[1], world[2]])
