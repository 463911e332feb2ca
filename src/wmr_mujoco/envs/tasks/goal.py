"""GoToGoal: reach a goal pose ``(x_g, y_g, ψ_g)``.

Episode: the robot starts at rest at the origin with a uniform heading; the goal lies at a
distance ``d ~ U(min_distance, max_distance)`` and a bearing within ±120° of the start
heading; the goal heading is within ±60° of that bearing (reachable driving forward).

Observation block (body frame of the robot's ``base`` pose):

* ``goal_xy`` (2, m): ``Rᵀ(ψ)(p_g − p)``;
* ``goal_heading`` (2, 1): ``(sin e_ψ, cos e_ψ)``, ``e_ψ = wrap(ψ_g − ψ)``;
* ``goal_distance`` (1, m): ``d = |p_g − p|``.

Reward terms (their sum is the reward): potential differences ``Φ(s′) − Φ(s)`` of
``Φ_d = −d / L`` (``progress``) and ``Φ_ψ = −½ (|e_ψ| / π) e^{−d/L}`` (``heading``; matters
near the goal), ``effort = −0.01 mean(a²)``, ``success = +10`` once, ``failure = −10`` once.
Success: ``d < position_tolerance`` and ``|e_ψ| < heading_tolerance``. Failure: ``d`` above
``arena`` (the robot left).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from wmr_mujoco.envs.tasks.base import EFFORT, Field, Task, check_options, pose_of, wrap

BONUS = 10.0


class GoToGoal(Task):
    """Reach a goal pose (module docstring)."""

    name = "GoToGoal"
    fields = (Field("goal_xy", 2, "m"), Field("goal_heading (sin, cos)", 2, "1"),
              Field("goal_distance", 1, "m"))

    def __init__(self, scale: float, max_curvature: float, **options: float) -> None:
        super().__init__(scale, max_curvature)
        o = check_options(self.name, options, {
            "time_limit": 20.0, "min_distance": 1.0 * scale, "max_distance": 2.5 * scale,
            "position_tolerance": 0.1 * scale, "heading_tolerance": 0.3, "arena": 5.0 * scale},
            lengths=("arena",))
        if not o["min_distance"] <= o["max_distance"] < o["arena"]:
            raise ValueError(f"GoToGoal: need min_distance <= max_distance < arena (a goal "
                             f"outside the arena fails at once); got {o['min_distance']}, "
                             f"{o['max_distance']}, {o['arena']} m")
        self.options = o
        self.time_limit = o["time_limit"]
        self.goal = np.zeros(3)

    @property
    def goal(self) -> np.ndarray:
        """The goal pose ``(x_g, y_g, ψ_g)``, m, m, rad."""
        return self._goal_array

    @goal.setter
    def goal(self, pose: np.ndarray) -> None:
        self._goal_array = np.asarray(pose, float)
        self._goal = self._goal_array.tolist()
        #: ``(state, measure)`` of the last state measured, then of the one before.
        self._cache: tuple[Any, Any, Any, Any] = (None, None, None, None)

    def sample(self, rng: np.random.Generator) -> np.ndarray:
        """Goal ahead within ±120°, its heading within ±60° of the bearing (docstring)."""
        o = self.options
        heading = rng.uniform(-math.pi, math.pi)
        bearing = heading + rng.uniform(-2 * math.pi / 3, 2 * math.pi / 3)
        d = rng.uniform(o["min_distance"], o["max_distance"])
        self.goal = np.array([d * math.cos(bearing), d * math.sin(bearing),
                              wrap(bearing + rng.uniform(-math.pi / 3, math.pi / 3))])
        return np.array([0.0, 0.0, heading])

    def measure(self, state: Any) -> tuple[float, float, float, float]:
        """``(x_g, y_g, d, e_ψ)``: body-frame goal, m, distance, m, heading error, rad.

        Computed once per state: the last two are kept (a step reads the previous state
        and the new one).
        """
        cache = self._cache
        if cache[0] is state:
            return cache[1]
        if cache[2] is state:
            return cache[3]
        x, y, psi = pose_of(state)
        gx, gy, gpsi = self._goal
        dx, dy = gx - x, gy - y
        c, s = math.cos(psi), math.sin(psi)
        e = math.remainder(gpsi - psi, math.tau)  # wrap() on a float, inlined
        out = c * dx + s * dy, c * dy - s * dx, math.hypot(dx, dy), math.pi if e == -math.pi else e
        self._cache = (state, out, cache[0], cache[1])
        return out

    def errors(self, state: Any) -> tuple[float, float]:
        """``(d, e_ψ)``: distance to the goal, m, and heading error, rad."""
        return self.measure(state)[2:]

    def observe(self, state: Any) -> list[float]:
        """``(goal_xy, sin e_ψ, cos e_ψ, d)``."""
        bx, by, d, e = self.measure(state)
        return [bx, by, math.sin(e), math.cos(e), d]

    def reward_terms(self, prev: Any, state: Any, action: Sequence[float], dt: float
                     ) -> dict[str, float]:
        """Progress, heading, effort, success and failure terms (docstring)."""
        return self.evaluate(prev, state, action, dt)[0]

    def outcome(self, state: Any) -> tuple[bool, bool]:
        """Success inside both tolerances; failure outside the arena."""
        _, _, d, e = self.measure(state)
        o = self.options
        return (d < o["position_tolerance"] and abs(e) < o["heading_tolerance"],
                d > o["arena"])

    def evaluate(self, prev: Any, state: Any, action: Sequence[float], dt: float
                 ) -> tuple[dict[str, float], bool, bool]:
        """The reward terms and the outcome, from one measurement of each state."""
        _, _, d0, e0 = self.measure(prev)
        _, _, d, e = self.measure(state)
        o, scale = self.options, self.scale
        # Φ_ψ(s′) − Φ_ψ(s) with Φ_ψ = −½ (|e_ψ| / π) e^{−d/L}
        heading = 0.5 / math.pi * (abs(e0) * math.exp(-d0 / scale) - abs(e) * math.exp(-d / scale))
        success = d < o["position_tolerance"] and abs(e) < o["heading_tolerance"]
        failure = d > o["arena"]
        total = 0.0
        for v in action:  # effort(action), inlined (the environments' hot path)
            total += v * v
        return ({"progress": (d0 - d) / scale, "heading": heading,
                 "effort": -EFFORT * total / len(action),
                 "success": BONUS if success else 0.0, "failure": -BONUS if failure else 0.0},
                success, failure)
