"""FollowPath: follow a seeded random smooth path to its end.

Episode: a path of ``path_length`` m from a uniform heading at the origin
(:func:`~wmr_mujoco.control.paths.random_path`, ``|κ| ≤ max_curvature``, run on straight
for ``2 L`` beyond its end so that the look-ahead stays defined); the robot starts
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
from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np

from wmr_mujoco.control.paths import Path, extend, random_path
from wmr_mujoco.envs.tasks.base import Field, Task, check_options, effort, pose_of, wrap
from wmr_mujoco.envs.tasks.goal import BONUS

#: Look-ahead distances of the observation, in units of the robot's length scale.
AHEAD = np.array([0.25, 0.5, 0.75, 1.0, 1.5])


class Projection(NamedTuple):
    """Where the robot is along the path.

    Attributes:
        s: arc length ``s*`` of the nearest point, m.
        cross_track: signed distance, m (> 0: the robot is left of the path).
        heading: the path's heading at ``s*``, rad.
    """

    s: float
    cross_track: float
    heading: float


class FollowPath(Task):
    """Follow a random smooth path (module docstring)."""

    name = "FollowPath"
    fields = (Field("path_ahead (x, y) x 5", 10, "m"), Field("cross_track", 1, "m"),
              Field("path_heading (sin, cos)", 2, "1"), Field("remaining", 1, "m"))

    def __init__(self, scale: float, max_curvature: float, **options: float) -> None:
        super().__init__(scale, max_curvature)
        o = check_options(self.name, options, {
            "time_limit": 30.0, "path_length": 4.0 * scale, "max_deviation": 0.5 * scale,
            "max_curvature": max_curvature}, lengths=("path_length",))
        self.options = o
        self.time_limit = o["time_limit"]
        self.path: Path | None = None
        #: Arc length of the path proper (the path runs on straight beyond it), m.
        self.end = o["path_length"]
        self._ahead = AHEAD * scale
        self._proj: tuple[Any, Projection] | None = None

    def sample(self, rng: np.random.Generator) -> np.ndarray:
        """A new path and a start pose beside its start (docstring)."""
        o = self.options
        heading = rng.uniform(-math.pi, math.pi)
        self.path = extend(random_path(rng, np.array([0.0, 0.0, heading]), o["path_length"],
                                       o["max_curvature"]), 2.0 * self.scale)
        self._proj = None
        off = rng.uniform(-0.1, 0.1) * self.scale
        return np.array([-off * math.sin(heading), off * math.cos(heading),
                         heading + rng.uniform(-0.2, 0.2)])

    def project(self, state: Any) -> Projection:
        """The nearest path point to the robot (searched near the last one; once a state)."""
        last = self._proj
        if last is not None and last[0] is state:
            return last[1]
        x, y, _ = pose_of(state)
        q = self.path.closest((x, y)) if last is None else self.path.track((x, y), last[1].s)
        qx, qy = q.position.tolist()
        rx, ry = x - qx, y - qy
        side = math.cos(q.heading) * ry - math.sin(q.heading) * rx
        proj = Projection(q.s, math.copysign(math.hypot(rx, ry), side), q.heading)
        self._proj = (state, proj)
        return proj

    def observe(self, state: Any) -> list[float]:
        """``(path_ahead, cross_track, sin e_ψ, cos e_ψ, remaining)``."""
        p = self.project(state)
        x, y, psi = pose_of(state)
        c, s = math.cos(psi), math.sin(psi)
        ahead = []
        for px, py in self.path.positions(p.s + self._ahead).tolist():
            ahead += (c * (px - x) + s * (py - y), c * (py - y) - s * (px - x))
        e = wrap(p.heading - psi)
        return [*ahead, p.cross_track, math.sin(e), math.cos(e), self.end - p.s]

    def reward_terms(self, prev: Any, state: Any, action: Sequence[float], dt: float
                     ) -> dict[str, float]:
        """Progress, cross-track, effort, success and failure terms (docstring)."""
        s0 = self.project(prev).s
        p = self.project(state)
        success, failure = self.outcome(state)
        return {"progress": (p.s - s0) / self.scale,
                "cross_track": -dt * (p.cross_track / self.options["max_deviation"]) ** 2,
                "effort": effort(action),
                "success": BONUS if success else 0.0, "failure": -BONUS if failure else 0.0}

    def outcome(self, state: Any) -> tuple[bool, bool]:
        """Success at the path's end; failure beyond ``max_deviation``."""
        p = self.project(state)
        failure = abs(p.cross_track) > self.options["max_deviation"]
        return p.s >= self.end and not failure, failure
