"""Scripted controllers in the robots' natural commands: proof that each task is solvable.

The control laws are the loop layer's (:mod:`wmr_mujoco.loop.control`), chosen by the
command space's channel names (never by robot name), at cruise speed ``V = ½ L`` (``L``
the robot's task scale, at most half its speed limit) and look-ahead ``L_d = 0.35 L``:

* ``(u, v, r)`` holonomic: :class:`~wmr_mujoco.loop.control.holonomic.HolonomicPose`
  (gains ``k_p``, ``k_ψ``, translation capped at ``V``) toward the goal pose (GoToGoal),
  or toward the look-ahead point of the path with the path's heading at the nearest
  point (FollowPath: ``k_p L_d > V``, so it moves at ``V`` toward that point).
* ``(v, omega)`` unicycle: pure pursuit
  (:class:`~wmr_mujoco.loop.control.pure_pursuit.PurePursuit`), ``κ = 2 sin α / L_d``,
  ``v = V``, ``ω = V κ``.
* ``(v, steer)`` car-like (a robot whose registry entry declares the steering arm, the
  wheelbase ℓ: ``Learning.steer_arm`` names its parameter): the same pure pursuit
  writing ``δ = atan(ℓ κ)`` (clipped to the steering range).
* ``(v, front_steer, rear_steer)``: pure pursuit's ``κ`` for two steered wheels at ``±h``
  along the body turned symmetrically about the centre, ``δ_f = −δ_r = atan(h κ)``: the
  centre then moves along the body axis on curvature κ (``h``: the declared steering arm).
* ``(v, steer)`` with one centred steered wheel (no steering arm; the yaw is free, a
  Chaplygin sleigh): steer the wheel at pure pursuit's look-ahead point ``p_L``,
  ``β = atan2(y_L, x_L)`` (clipped to the steering range), ``v = V``; a point behind
  (``|β| > π/2``) is reached rolling backwards, ``β → β + π``, ``v = −V``. GoToGoal: ``p_L``
  is the goal and ``V → min(V, k_p d)``.
* A command map with a balancing law (``CommandMap.balance``, the Whipple bicycle's LQR
  steer-into-the-lean law with its speed hold): that law, designed at the task's speed.

GoToGoal (non-holonomic) follows a cubic Hermite path from the start pose to the goal pose
(:func:`~wmr_mujoco.loop.control.paths.hermite_path`), so the goal is reached with its heading.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from wmr_mujoco.envs.episode import Episode
from wmr_mujoco.envs.tasks import FollowPath, GoToGoal
from wmr_mujoco.envs.tasks.base import to_body, wrap
from wmr_mujoco.loop.control.holonomic import HolonomicPose
from wmr_mujoco.loop.control.paths import Path, extend, hermite_path
from wmr_mujoco.loop.control.pure_pursuit import PurePursuit

#: Cruise speed in robot lengths per second (``V = SPEED · L``, at most half the limit).
SPEED = 0.5
#: Look-ahead distance, in robot lengths.
LOOKAHEAD = 0.35
#: Heading gain of the holonomic controller, 1/s; position gain, 1/s.
K_HEADING, K_POSITION = 2.0, 1.5
#: The command kinds by channel names (``"car"`` needs a steering arm, else ``"wheel"``).
KINDS = {("u", "v", "r"): "holonomic", ("v", "omega"): "unicycle", ("v", "steer"): "car",
         ("v", "front_steer", "rear_steer"): "double"}


class Scripted:
    """A controller of one :class:`Episode`: call :meth:`reset` after each episode reset.

    Raises:
        ValueError: the robot's command space has no scripted controller here.
    """

    def __init__(self, episode: Episode) -> None:
        self.ep = episode
        robot = episode.robot
        names = tuple(robot.command_space.names)
        self.kind = KINDS.get(names)
        #: The steering arm ℓ (``Learning.steer_arm`` of the robot's entry), m; 0: none.
        self.arm = _arm(robot, episode.profile.steer_arm)
        if self.kind == "car" and not self.arm:
            self.kind = "wheel"
        if self.kind == "double" and not self.arm:
            raise ValueError(f"robot {robot.spec.name!r}: a (v, front_steer, rear_steer) "
                             "command needs its registry entry's Learning.steer_arm (the "
                             "half wheelbase's parameter)")
        if robot.mode == "command" and robot.spec.command.balance is not None:
            self.kind = "balance"
        if self.kind is None:
            raise ValueError(f"no scripted controller for the command {names}; scripted "
                             "commands: (u, v, r), (v, omega), (v, steer), (v, front_steer, "
                             "rear_steer), and a command map's balancing law")
        high = robot.command_space.high
        scale = episode.profile.scale
        self.speed = min(SPEED * scale, 0.5 * float(high[0]))
        self.lookahead = LOOKAHEAD * scale
        self.steer_limit = float(high[1]) if len(high) > 1 else math.pi
        self.path: Path | None = None
        #: Arc length of the last nearest point on the path (the search's hint), m.
        self.s = 0.0
        self.law: Any = None
        if self.kind == "holonomic":
            self.law = HolonomicPose(K_POSITION, K_HEADING, self.speed, float(high[2]))
        elif self.kind != "balance":
            wheelbase = self.arm if self.kind == "car" else None
            self.law = PurePursuit(self.speed, self.lookahead, wheelbase, self.steer_limit)

    def reset(self) -> None:
        """Plan the episode: the path to follow, or the balancing law at the target speed."""
        task, robot = self.ep.task, self.ep.robot
        if self.kind == "balance":
            self.law = robot.spec.command.balance.law(task.speed, robot.params)
            return
        self.law.reset()
        self.s = 0.0
        if isinstance(task, FollowPath):
            self.path = task.path
        elif isinstance(task, GoToGoal):
            self.path = extend(hermite_path(np.asarray(self.ep.state.pose, float), task.goal),
                               2.0 * self.ep.profile.scale)

    def command(self, state: Any) -> np.ndarray:
        """The natural command for ``state``."""
        kind, task, t = self.kind, self.ep.task, float(state.time)
        if kind == "balance":
            return self.law(state, None, t)
        if kind == "holonomic":
            if isinstance(task, GoToGoal):
                return self.law(state, task.goal, t)
            near, ahead = self._ahead(state)
            return self.law(state, np.array([*ahead.position, near.heading]), t)
        if kind == "unicycle" or kind == "car":
            return self.law(state, self.path, t)
        if kind == "double":
            delta = math.atan(self.arm * self.law.curvature(state, self.path))
            return np.array([self.speed, delta, -delta])
        return self._wheel(state)

    def _ahead(self, state: Any) -> tuple[Any, Any]:
        """The path's nearest point and pure pursuit's look-ahead point (Coulter's)."""
        xy = np.asarray(state.pose, float)[:2]
        near = self.path.closest(xy, self.s)
        self.s = near.s
        return near, self.path.lookahead(xy, self.lookahead, near.s)

    def _wheel(self, state: Any) -> np.ndarray:
        """The centred steered wheel (module docstring)."""
        pose = np.asarray(state.pose, float)
        speed = self.speed
        if isinstance(self.ep.task, GoToGoal):  # its goal is a position: head for it
            target = to_body(pose, self.ep.task.goal[:2])
            speed = min(speed, K_POSITION * float(np.hypot(*target)))
        else:
            target = to_body(pose, self._ahead(state)[1].position)
        beta, v = math.atan2(target[1], target[0]), speed
        if abs(beta) > math.pi / 2:  # the point is behind: roll the wheel backwards
            beta, v = wrap(beta + math.pi), -v
        return np.array([v, min(self.steer_limit, max(-self.steer_limit, beta))])

    def action(self, state: Any) -> np.ndarray:
        """The normalised action of :meth:`command`, clipped to ``[-1, 1]``."""
        return np.clip(self.ep.action(self.command(state)), -1.0, 1.0)


def _arm(robot: Any, name: str) -> float:
    """The steering arm: the robot's parameter ``name``, m (0.0 for no name).

    Raises:
        ValueError: the robot's parameters have no such field.
    """
    if not name:
        return 0.0
    params = robot.params if getattr(robot, "params", None) is not None else (
        robot.spec.params_type() if robot.spec.params_type else None)
    try:
        return float(getattr(params, name))
    except AttributeError:
        raise ValueError(f"robot {robot.spec.name!r}: Learning.steer_arm={name!r} is not a "
                         f"field of its parameters {type(params).__name__}") from None


def run_episode(episode: Episode, rng: np.random.Generator) -> tuple[bool, dict]:
    """One scripted episode; ``(success, last info)``."""
    episode.reset(rng)
    ctrl = Scripted(episode)
    ctrl.reset()
    while True:
        _, _, terminated, truncated, info = episode.step(ctrl.action(episode.state))
        if terminated or truncated:
            return bool(info["is_success"]), info
