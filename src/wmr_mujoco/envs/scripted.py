"""Scripted controllers in the robots' natural commands: proof that each task is solvable.

The controller is chosen by the command space's channel names (never by robot name):

* ``(u, v, r)`` holonomic: move toward a look-ahead point at speed ``V``,
  ``(u, v) = V p_L / |p_L|`` (body frame), and turn toward the path's heading,
  ``r = k_ψ e_ψ``. GoToGoal: straight at the goal, ``(u, v) = k_p p_g`` (capped at ``V``).
* ``(v, omega)`` unicycle: pure pursuit (Coulter 1992) of a look-ahead point ``p_L`` at
  distance ``L_d``: ``κ = 2 y_L / |p_L|²``, ``v = V``, ``ω = V κ``.
* ``(v, steer)`` car-like (parameters with a ``wheelbase`` ℓ): the same ``κ`` through the
  bicycle's kinematics, ``φ = atan(ℓ κ)``.
* ``(v, steer)`` with one centred steered wheel (no wheelbase; the yaw is free, a
  Chaplygin sleigh): steer the wheel at the look-ahead point, ``β = atan2(y_L, x_L)``
  (clipped to the steering range), ``v = V``; a point behind (``|β| > π/2``) is reached
  rolling backwards, ``β → β + π``, ``v = −V``. GoToGoal: ``p_L`` is the goal and
  ``V → min(V, k_p d)``.
* ``(v, front_steer, rear_steer)``: two steered wheels at ``±h`` along the body, turned
  symmetrically about the centre, ``δ_f = −δ_r = atan(h κ)``: the centre then moves
  along the body axis on curvature κ.
* ``(rear_torque, steer_torque)``-like torques of the Whipple bicycle: discrete LQR on the
  benchmark's linearised equations at the target speed,
  ``x = (φ, δ, φ̇, δ̇)``, ``ẋ = A(v) x + B T_δ``, ``B = [0; M⁻¹ e₂]``,
  ``Q = diag(10, 10, 1, 1)``, ``R = 0.1``; and a speed loop ``T_r = k_v (v* − u)``.

GoToGoal (non-holonomic) follows a cubic Hermite path from the start pose to the goal pose
(:func:`~wmr_mujoco.envs.paths.hermite_path`), so the goal is reached with its heading.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from scipy.linalg import expm, solve_discrete_are

from wmr_mujoco.envs.episode import Episode
from wmr_mujoco.envs.paths import Path, hermite_path
from wmr_mujoco.envs.tasks import FollowPath, GoToGoal, StayUpright
from wmr_mujoco.envs.tasks.base import to_body, wrap
from wmr_mujoco.robots.whipple import analytic
from wmr_mujoco.robots.whipple.params import WhippleParams

#: Cruise speed in robot lengths per second (``V = SPEED · L``, at most half the limit).
SPEED = 0.5
#: Look-ahead distance, in robot lengths.
LOOKAHEAD = 0.35
#: Heading gain of the holonomic controller, 1/s; position gain, 1/s.
K_HEADING, K_POSITION = 2.0, 1.5
#: Speed gain of the Whipple bicycle's rear wheel, N m per m/s.
K_SPEED = 60.0


class Scripted:
    """A controller of one :class:`Episode`: call :meth:`reset` after each episode reset.

    Raises:
        ValueError: the robot's command space has no scripted controller here.
    """

    def __init__(self, episode: Episode) -> None:
        self.ep = episode
        names = tuple(episode.robot.command_space.names)
        params = (episode.robot.spec.params_type() if episode.robot.spec.params_type
                  else None)
        self.kind = {("u", "v", "r"): "holonomic", ("v", "omega"): "unicycle",
                     ("v", "steer"): "carlike" if hasattr(params, "wheelbase") else "wheel",
                     ("v", "front_steer", "rear_steer"): "double"}.get(names)
        if isinstance(episode.task, StayUpright):
            self.kind = "balance"
        if self.kind is None:
            raise ValueError(f"no scripted controller for the command {names}; scripted "
                             "commands: (u, v, r), (v, omega), (v, steer), and the Whipple "
                             "bicycle's torques")
        high = episode.robot.command_space.high
        self.speed = min(SPEED * episode.profile.scale, 0.5 * float(high[0]))
        self.lookahead = LOOKAHEAD * episode.profile.scale
        self.path: Path | None = None
        self.index: int | None = None
        if self.kind == "carlike":
            self.wheelbase = float(params.wheelbase)
        if self.kind == "double":
            self.wheelbase = float(params.half_wheelbase)
        self.steer_limit = float(high[1]) if len(high) > 1 else math.pi
        self.gain: np.ndarray | None = None

    def reset(self) -> None:
        """Plan the episode: the path to follow, or the balance gains at the target speed."""
        task, state = self.ep.task, self.ep.state
        self.index = None
        if isinstance(task, FollowPath):
            self.path = task.path
        elif isinstance(task, GoToGoal):
            self.path = hermite_path(np.asarray(state.pose, float), task.goal,
                                     run_out=2.0 * self.ep.profile.scale)
        else:
            self.gain = lqr_gain(task.speed, self.ep.dt)

    def command(self, state: Any) -> np.ndarray:
        """The natural command for ``state``."""
        if self.kind == "balance":
            return self._balance(state)
        if self.kind == "holonomic" and isinstance(self.ep.task, GoToGoal):
            return self._holonomic_goal(state)
        pose = np.asarray(state.pose, float)
        proj = self.path.project(pose[:2], self.index)
        self.index = proj.index
        target = to_body(pose, self.path.ahead(proj.index, np.array([self.lookahead]))[0])
        if self.kind == "holonomic":
            e = wrap(proj.heading - pose[2])
            return np.array([*(self.speed * target / max(np.linalg.norm(target), 1e-6)),
                             K_HEADING * e])
        kappa = 2.0 * target[1] / max(float(target @ target), 1e-6)
        if self.kind == "unicycle":
            return np.array([self.speed, self.speed * kappa])
        if self.kind == "wheel":
            speed = self.speed
            if isinstance(self.ep.task, GoToGoal):  # its goal is a position: head for it
                target = to_body(pose, self.ep.task.goal[:2])
                speed = min(speed, K_POSITION * float(np.hypot(*target)))
            beta, v = math.atan2(target[1], target[0]), speed
            if abs(beta) > math.pi / 2:  # the point is behind: roll the wheel backwards
                beta, v = wrap(beta + math.pi), -v
            return np.array([v, min(self.steer_limit, max(-self.steer_limit, beta))])
        delta = math.atan(self.wheelbase * kappa)
        if self.kind == "double":
            return np.array([self.speed, delta, -delta])
        return np.array([self.speed, delta])

    def _holonomic_goal(self, state: Any) -> np.ndarray:
        pose = np.asarray(state.pose, float)
        goal = self.ep.task.goal
        p = to_body(pose, goal[:2])
        v = K_POSITION * p
        n = float(np.linalg.norm(v))
        if n > self.speed:
            v *= self.speed / n
        return np.array([*v, K_HEADING * wrap(goal[2] - pose[2])])

    def _balance(self, state: Any) -> np.ndarray:
        x = state.extra
        z = np.array([x["lean"], x["steer"], x["lean_rate"], x["steer_rate"]])
        steer_torque = float(-(self.gain @ z)[0])
        rear = K_SPEED * (self.ep.task.speed - float(state.twist[0]))
        cmd = np.zeros(2)
        cmd[list(self.order)] = rear, steer_torque
        return cmd

    @property
    def order(self) -> tuple[int, int]:
        """Where (rear torque, steer torque) go in the command (by channel name)."""
        names = self.ep.robot.command_space.names
        rear = next(i for i, n in enumerate(names) if "rear" in n or "drive" in n)
        return (rear, 1 - rear)

    def action(self, state: Any) -> np.ndarray:
        """The normalised action of :meth:`command`, clipped to ``[-1, 1]``."""
        return np.clip(self.ep.action(self.command(state)), -1.0, 1.0)


def lqr_gain(speed: float, dt: float, params: WhippleParams | None = None) -> np.ndarray:
    """Discrete LQR gain ``K`` (1×4) of the linear benchmark at ``speed`` (module docstring).

    Zero-order hold over ``dt``: ``[A_d B_d] = expm([[A, B], [0, 0]] dt)``.
    """
    mats = analytic.matrices(params or WhippleParams())
    a = analytic.state_matrix(speed, mats)
    b = np.concatenate([np.zeros(2), np.linalg.solve(mats.M, [0.0, 1.0])])[:, None]
    block = np.zeros((5, 5))
    block[:4, :4], block[:4, 4:] = a, b
    e = expm(block * dt)
    ad, bd = e[:4, :4], e[:4, 4:]
    q, r = np.diag([10.0, 10.0, 1.0, 1.0]), np.array([[0.1]])
    p = solve_discrete_are(ad, bd, q, r)
    return np.linalg.solve(r + bd.T @ p @ bd, bd.T @ p @ ad)


def run_episode(episode: Episode, rng: np.random.Generator) -> tuple[bool, dict]:
    """One scripted episode; ``(success, last info)``."""
    episode.reset(rng)
    ctrl = Scripted(episode)
    ctrl.reset()
    while True:
        _, _, terminated, truncated, info = episode.step(ctrl.action(episode.state))
        if terminated or truncated:
            return bool(info["is_success"]), info
