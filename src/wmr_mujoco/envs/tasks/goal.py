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
from collections.abc import Mapping
from typing import Any

import numpy as np

from wmr_mujoco.envs.tasks.base import Field, Task, check_options, effort, to_body, wrap

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
            "position_tolerance": 0.1 * scale, "heading_tolerance": 0.3, "arena": 5.0 * scale})
        if o["min_distance"] > o["max_distance"]:
            raise ValueError(f"GoToGoal: min_distance={o['min_distance']} m is above "
                             f"max_distance={o['max_distance']} m")
        self.options = o
        self.time_limit = o["time_limit"]
        self.goal = np.zeros(3)
        self._cache: tuple[Any, tuple[float, float]] | None = None

    def sample(self, rng: np.random.Generator) -> np.ndarray:
        """Goal ahead within ±120°, its heading within ±60° of the bearing (docstring)."""
        o = self.options
        heading = rng.uniform(-math.pi, math.pi)
        bearing = heading + rng.uniform(-2 * math.pi / 3, 2 * math.pi / 3)
        d = rng.uniform(o["min_distance"], o["max_distance"])
        self.goal = np.array([d * math.cos(bearing), d * math.sin(bearing),
                              wrap(bearing + rng.uniform(-math.pi / 3, math.pi / 3))])
        self._cache = None
        return np.array([0.0, 0.0, heading])

    def errors(self, state: Any) -> tuple[float, float]:
        """``(d, e_ψ)``: distance to the goal, m, and heading error, rad."""
        if self._cache is not None and self._cache[0] is state:
            return self._cache[1]
        x, y, psi = state.pose.tolist()
        gx, gy, gpsi = self.goal.tolist()
        out = math.hypot(gx - x, gy - y), wrap(gpsi - psi)
        self._cache = (state, out)
        return out

    def observe(self, state: Any) -> np.ndarray:
        """``(goal_xy, sin e_ψ, cos e_ψ, d)``."""
        d, e = self.errors(state)
        return np.array([*to_body(np.asarray(state.pose), self.goal[:2]), math.sin(e),
                         math.cos(e), d])

    def _potentials(self, state: Any) -> tuple[float, float]:
        d, e = self.errors(state)
        return -d / self.scale, -0.5 * abs(e) / math.pi * math.exp(-d / self.scale)

    def reward_terms(self, prev: Any, state: Any, action: np.ndarray, dt: float
                     ) -> Mapping[str, float]:
        """Progress, heading, effort, success and failure terms (docstring)."""
        (d0, h0), (d1, h1) = self._potentials(prev), self._potentials(state)
        success, failure = self.outcome(state)
        return {"progress": d1 - d0, "heading": h1 - h0,
                "effort": effort(action),
                "success": BONUS * success, "failure": -BONUS * failure}

    def outcome(self, state: Any) -> tuple[bool, bool]:
        """Success inside both tolerances; failure outside the arena."""
        d, e = self.errors(state)
        o = self.options
        return (d < o["position_tolerance"] and abs(e) < o["heading_tolerance"],
                d > o["arena"])
