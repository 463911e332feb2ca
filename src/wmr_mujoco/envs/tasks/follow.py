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

import bisect
import math
from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np

from wmr_mujoco.control.paths import Path, extend, random_path
from wmr_mujoco.envs.tasks.base import Field, Task, check_options, effort, pose_of
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


_new = tuple.__new__  # a Projection in one C call


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
        #: Arc length of the path proper (the path runs on straight beyond it), m.
        self.end = o["path_length"]
        self._ahead = (AHEAD * scale).tolist()
        self.path = None

    @property
    def path(self) -> Path | None:
        """The episode's path (its samples are kept as floats for the per-step search)."""
        return self._path

    @path.setter
    def path(self, path: Path | None) -> None:
        self._path = path
        #: ``(state, projection, segment)`` of the last state projected.
        self._proj: tuple[Any, Projection, int] | None = None
        if path is None:
            return
        self._s = path.s.tolist()
        self._x, self._y = path.xy[:, 0].tolist(), path.xy[:, 1].tolist()
        self._heading = path.heading.tolist()
        #: Per segment: ``x`` and ``y`` increments and ``1 / Δs`` (0 for a segment of no
        #: length), so that a point at arc length ``q`` is ``x_k + t Δx_k``, bit for bit
        #: the interpolation ``x_k + t (x_{k+1} − x_k)``.
        self._gx = [b - a for a, b in zip(self._x, self._x[1:], strict=False)]
        self._gy = [b - a for a, b in zip(self._y, self._y[1:], strict=False)]
        self._ids = [_inverse(b - a) for a, b in zip(self._s, self._s[1:], strict=False)]
        #: Per segment ``(a_x, a_y, d_x, d_y, 1/|d|²)``: its start and its vector (a
        #: segment of no length: 0, its foot is its start).
        self._segments = [(ax, ay, bx - ax, by - ay, _inverse((bx - ax) ** 2 + (by - ay) ** 2))
                          for ax, ay, bx, by in zip(self._x, self._y, self._x[1:],
                                                    self._y[1:], strict=False)]

    def sample(self, rng: np.random.Generator) -> np.ndarray:
        """A new path and a start pose beside its start (docstring)."""
        o = self.options
        heading = rng.uniform(-math.pi, math.pi)
        self.path = extend(random_path(rng, np.array([0.0, 0.0, heading]), o["path_length"],
                                       o["max_curvature"]), 2.0 * self.scale)
        off = rng.uniform(-0.1, 0.1) * self.scale
        return np.array([-off * math.sin(heading), off * math.cos(heading),
                         heading + rng.uniform(-0.2, 0.2)])

    def project(self, state: Any) -> Projection:
        """The nearest path point to the robot (once a state).

        The first state of an episode searches the whole path
        (:meth:`~wmr_mujoco.loop.control.paths.Path.closest`); each later one walks the
        segments from the last one's while the distance shrinks (the robot moves a small
        fraction of a segment's neighbourhood in a step), on floats.
        """
        last = self._proj
        if last is not None and last[0] is state:
            return last[1]
        x, y, _ = pose_of(state)
        if last is None:
            s0 = self._path.closest((x, y)).s
            i = max(0, min(bisect.bisect_right(self._s, s0) - 1, len(self._segments) - 1))
        else:
            i = last[2]
        i, t = _walk(self._segments, x, y, i)
        ax, ay, dx, dy, _ = self._segments[i]
        rx, ry = x - ax - t * dx, y - ay - t * dy
        s, h = self._s, self._heading
        heading = h[i] + t * (h[i + 1] - h[i])
        side = math.cos(heading) * ry - math.sin(heading) * rx
        proj = _new(Projection, (s[i] + t * (s[i + 1] - s[i]),
                                 math.copysign(math.hypot(rx, ry), side), heading))
        self._proj = (state, proj, i)
        return proj

    def observe(self, state: Any) -> list[float]:
        """``(path_ahead, cross_track, sin e_ψ, cos e_ψ, remaining)``.

        The points ahead are interpolated linearly in arc length between the path's
        samples (clipped at its far end), in one pass over floats.
        """
        return self._observe(state, self.project(state))

    def _observe(self, state: Any, p: Projection) -> list[float]:
        """:meth:`observe` of the state's projection ``p``."""
        x, y, psi = pose_of(state)
        c, sn = math.cos(psi), math.sin(psi)
        sl, xl, yl, gx, gy, ids = self._s, self._x, self._y, self._gx, self._gy, self._ids
        n, end, k, out, s0 = len(sl) - 2, sl[-1], self._proj[2], [], p.s
        for d in self._ahead:
            q = s0 + d
            if q > end:
                q = end
            k = bisect.bisect_right(sl, q, k) - 1
            if k > n:
                k = n
            t = (q - sl[k]) * ids[k]
            dx, dy = xl[k] + t * gx[k] - x, yl[k] + t * gy[k] - y
            out.append(c * dx + sn * dy)
            out.append(c * dy - sn * dx)
        e = math.remainder(p.heading - psi, math.tau)  # wrap() on floats
        out += (p.cross_track, math.sin(e), math.cos(e), self.end - p.s)
        return out

    def reward_terms(self, prev: Any, state: Any, action: Sequence[float], dt: float
                     ) -> dict[str, float]:
        """Progress, cross-track, effort, success and failure terms (docstring)."""
        return self.evaluate(prev, state, action, dt)[0]

    def evaluate(self, prev: Any, state: Any, action: Sequence[float], dt: float
                 ) -> tuple[dict[str, float], bool, bool]:
        """The reward terms and the outcome, from one projection of each state."""
        s0 = self.project(prev).s
        p = self.project(state)
        dev = self.options["max_deviation"]
        failure = abs(p.cross_track) > dev
        success = p.s >= self.end and not failure
        return ({"progress": (p.s - s0) / self.scale,
                 "cross_track": -dt * (p.cross_track / dev) ** 2, "effort": effort(action),
                 "success": BONUS if success else 0.0, "failure": -BONUS if failure else 0.0},
                success, failure)

    def evaluate_observe(self, prev: Any, state: Any, action: Sequence[float], dt: float
                         ) -> tuple[dict[str, float], bool, bool, list[float]]:
        """:meth:`evaluate` and :meth:`observe`, from one projection of each state."""
        terms, success, failure = self.evaluate(prev, state, action, dt)
        return terms, success, failure, self._observe(state, self._proj[1])

    def outcome(self, state: Any) -> tuple[bool, bool]:
        """Success at the path's end; failure beyond ``max_deviation``."""
        p = self.project(state)
        failure = abs(p.cross_track) > self.options["max_deviation"]
        return p.s >= self.end and not failure, failure


def _inverse(x: float) -> float:
    """``1 / x``, 0 for ``x = 0``."""
    return 1.0 / x if x else 0.0


def _foot(segment: tuple[float, ...], px: float, py: float) -> tuple[float, float]:
    """``(squared distance, t)`` of the foot ``a + t d`` of ``(px, py)`` on a segment."""
    ax, ay, dx, dy, inv = segment
    t = ((px - ax) * dx + (py - ay) * dy) * inv
    t = 0.0 if t < 0.0 else 1.0 if t > 1.0 else t
    ex, ey = ax + t * dx - px, ay + t * dy - py
    return ex * ex + ey * ey, t


def _walk(segments: list[tuple[float, ...]], px: float, py: float, i: int) -> tuple[int, float]:
    """``(segment, t)`` of the nearest point to ``(px, py)``, walked to from segment ``i``.

    The foot on segment ``k`` is ``a + t d`` with ``t = clip((p − a)·d / |d|², 0, 1)``
    (:func:`_foot`, inlined here: the environments' hot path); the walk goes forward while
    the next segment's foot is nearer, else backward likewise.
    """
    best, t = _foot(segments[i], px, py)
    last, start = len(segments) - 1, i
    for step in (1, -1):
        j = i + step
        while 0 <= j <= last:
            ax, ay, dx, dy, inv = segments[j]
            u = ((px - ax) * dx + (py - ay) * dy) * inv
            u = 0.0 if u < 0.0 else 1.0 if u > 1.0 else u
            ex, ey = ax + u * dx - px, ay + u * dy - py
            d = ex * ex + ey * ey
            if d >= best:
                break
            i, best, t = j, d, u
            j += step
        if i != start:  # moved: the other way cannot be nearer
            break
    return i, t
