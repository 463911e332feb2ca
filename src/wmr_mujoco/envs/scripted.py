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
* ``(rear_torque, steer_torque)`` of the Whipple bicycle: the control package's LQR
  steer-into-the-lean law with its rear-wheel speed hold
  (:class:`~wmr_mujoco.control.whipple_lean.WhippleLean`), designed at the task's speed.

GoToGoal (non-holonomic) follows a cubic Hermite path from the start pose to the goal pose
(:func:`~wmr_mujoco.control.paths.hermite_path`), so the goal is reached with its heading.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from wmr_mujoco.control.paths import Path, extend, hermite_path
from wmr_mujoco.control.whipple_lean import WhippleLean
from wmr_mujoco.envs.episode import Episode
from wmr_mujoco.envs.tasks import FollowPath, GoToGoal, StayUpright
from wmr_mujoco.envs.tasks.base import to_body, wrap

#: Cruise speed in robot lengths per second (``V = SPEED · L``, at most half the limit).
SPEED = 0.5
#: Look-ahead distance, in robot lengths.
LOOKAHEAD = 0.35
#: Heading gain of the holonomic controller, 1/s; position gain, 1/s.
K_HEADING, K_POSITION = 2.0, 1.5


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
        #: Arc length of the last nearest point on the path (the search's hint), m.
        self.s: float | None = None
        if self.kind == "carlike":
            self.wheelbase = float(params.wheelbase)
        if self.kind == "double":
            self.wheelbase = float(params.half_wheelbase)
        self.steer_limit = float(high[1]) if len(high) > 1 else math.pi
        self.balance: WhippleLean | None = None

    def reset(self) -> None:
        """Plan the episode: the path to follow, or the balance gains at the target speed."""
        task, state = self.ep.task, self.ep.state
        self.s = None
        if isinstance(task, FollowPath):
            self.path = task.path
        elif isinstance(task, GoToGoal):
            self.path = extend(hermite_path(np.asarray(state.pose, float), task.goal),
                               2.0 * self.ep.profile.scale)
        else:
            self.balance = WhippleLean(speed=task.speed)

    def command(self, state: Any) -> np.ndarray:
        """The natural command for ``state``."""
        if self.kind == "balance":
            return self._balance(state)
        if self.kind == "holonomic" and isinstance(self.ep.task, GoToGoal):
            return self._holonomic_goal(state)
        pose = np.asarray(state.pose, float)
        near = (self.path.closest(pose[:2]) if self.s is None
                else self.path.track(pose[:2], self.s))
        self.s = near.s
        target = to_body(pose, self.path.positions(near.s + self.lookahead))
        if self.kind == "holonomic":
            e = wrap(near.heading - pose[2])
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
        return self.balance(state, None, float(state.time))

    def action(self, state: Any) -> np.ndarray:
        """The normalised action of :meth:`command`, clipped to ``[-1, 1]``."""
        return np.clip(self.ep.action(self.command(state)), -1.0, 1.0)


def run_episode(episode: Episode, rng: np.random.Generator) -> tuple[bool, dict]:
    """One scripted episode; ``(success, last info)``."""
    episode.reset(rng)
    ctrl = Scripted(episode)
    ctrl.reset()
    while True:
        _, _, terminated, truncated, info = episode.step(ctrl.action(episode.state))
        if terminated or truncated:
            return bool(info["is_success"]), info
