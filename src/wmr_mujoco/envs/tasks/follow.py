"""FollowPath: follow a seeded random smooth path to its end.

Episode: a path of ``path_length`` m from a uniform heading at the origin
(:func:`~wmr_mujoco.envs.paths.random_path`, ``|κ| ≤ max_curvature``); the robot starts
at rest beside its start, offset laterally by ``U(±0.1 L)`` and in heading by ``U(±0.2)`` rad.

Observation block (body frame):

* ``path_ahead`` (10, m): the path at arc lengths ``s* + (0.25, 0.5, 0.75, 1, 1.5) L``
  ahead of the nearest point ``s*``, as body-frame ``(x, y)`` pairs;
* ``cross_track`` (1, m): signed distance to the path (> 0: the robot is left of it);
* ``path_heading`` (2, 1): ``(sin e_ψ, cos e_ψ)``, ``e_ψ = wrap(ψ_path(s*) − ψ)``;
* ``remaining`` (1, m): ``length − s*``.

Reward terms: ``progress = Δs* / L``, ``cross_track = −dt (e / max_deviation)²``,
``effort = −0.01 mean(a²)``, ``success = +10``, ``failure = −10``.
Success: ``s*`` reaches the end. Failure: ``|e| > max_deviation``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from wmr_mujoco.envs.paths import Path, Projection, random_path
from wmr_mujoco.envs.tasks.base import Field, Task, check_options, effort, to_body, wrap
from wmr_mujoco.envs.tasks.goal import BONUS

#: Look-ahead distances of the observation, in units of the robot's length scale.
AHEAD = np.array([0.25, 0.5, 0.75, 1.0, 1.5])


class FollowPath(Task):
    """Follow a random smooth path (module docstring)."""

    name = "FollowPath"
    fields = (Field("path_ahead (x, y) x 5", 10, "m"), Field("cross_track", 1, "m"),
              Field("path_heading (sin, cos)", 2, "1"), Field("remaining", 1, "m"))

    def __init__(self, scale: float, max_curvature: float, **options: float) -> None:
        super().__init__(scale, max_curvature)
        o = check_options(self.name, options, {
            "time_limit": 30.0, "path_length": 4.0 * scale, "max_deviation": 0.5 * scale,
            "max_curvature": max_curvature})
        self.options = o
        self.time_limit = o["time_limit"]
        self.path: Path | None = None
        self._proj: tuple[bytes, Projection] | None = None

    def sample(self, rng: np.random.Generator) -> np.ndarray:
        """A new path and a start pose beside its start (docstring)."""
        o = self.options
        heading = rng.uniform(-math.pi, math.pi)
        self.path = random_path(rng, np.array([0.0, 0.0, heading]), o["path_length"],
                                o["max_curvature"], run_out=2.0 * self.scale)
        self._proj = None
        off = rng.uniform(-0.1, 0.1) * self.scale
        return np.array([-off * math.sin(heading), off * math.cos(heading),
                         heading + rng.uniform(-0.2, 0.2)])

    def project(self, state: Any) -> Projection:
        """Nearest path point to the robot (searched near the last one)."""
        xy = np.asarray(state.pose[:2], float)
        if self._proj is not None and self._proj[0] == xy.tobytes():
            return self._proj[1]
        hint = None if self._proj is None else self._proj[1].index
        proj = self.path.project(xy, hint)
        self._proj = (xy.tobytes(), proj)
        return proj

    def observe(self, state: Any) -> np.ndarray:
        """``(path_ahead, cross_track, sin e_ψ, cos e_ψ, remaining)``."""
        p = self.project(state)
        pose = np.asarray(state.pose, float)
        ahead = to_body(pose, self.path.ahead(p.index, AHEAD * self.scale)).ravel()
        e = wrap(p.heading - pose[2])
        return np.array([*ahead, p.cross_track, math.sin(e), math.cos(e),
                         self.path.length - p.s])

    def reward_terms(self, prev: Any, state: Any, action: np.ndarray, dt: float
                     ) -> Mapping[str, float]:
        """Progress, cross-track, effort, success and failure terms (docstring)."""
        s0 = self.project(prev).s
        p = self.project(state)
        success, failure = self.outcome(state)
        return {"progress": (p.s - s0) / self.scale,
                "cross_track": -dt * (p.cross_track / self.options["max_deviation"]) ** 2,
                "effort": effort(action),
                "success": BONUS * success, "failure": -BONUS * failure}

    def outcome(self, state: Any) -> tuple[bool, bool]:
        """Success at the path's end; failure beyond ``max_deviation``."""
        p = self.project(state)
        failure = abs(p.cross_track) > self.options["max_deviation"]
        return p.s >= self.path.length and not failure, failure
