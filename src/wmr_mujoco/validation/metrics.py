"""Judged metrics: targets, rows, per-step probes and the pose-tracking judge.

A :class:`Target` is a **requirement** (a number the project was asked for), a **derived
bound** (a number that follows from the physics, with its derivation beside it), or an
**open** requirement (:meth:`Target.open`: asked for, but no model of the package meets it
yet; the row shows the target, the measured figure and the reason, and is counted as open
rather than judged, so that a run passes only if every judged target passes while the
miss stays visible); a metric without a target is reported, not judged.

Pose tracking (every scenario whose analytic state starts with ``(x, y, heading)``), with
``e(t) = |p_sim(t) − p_model(t)|`` the distance between the simulated and the analytic
reference point, ``L`` the analytic path length over the whole run, and ``Δψ(t)`` the
heading difference wrapped into (−180°, 180°]:

    worst position error  = max_t e(t) / L · 100 %      (judged)
    RMS position error    = sqrt(mean_t e(t)²)           (m)
    final position error  = e(T) / L · 100 %             (the old end-of-run figure)
    worst heading error   = max_t |Δψ(t)|                (judged where a target exists)
    final heading error   = Δψ(T)

All maxima and means are over the recorded samples of the whole run (every
:data:`RECORD_EVERY` steps and the last one). A run that
turns in place (``L`` < 1 mm) is judged on its centre's worst drift in metres instead.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, NamedTuple, Protocol, overload

import mujoco
import numpy as np

from wmr_mujoco.analytic.planar import cumulative_path, wrap_angle

if TYPE_CHECKING:
    from wmr_mujoco.validation.adapters import Adapter
    from wmr_mujoco.validation.scenarios import Scenario

#: Below this analytic path length (m) a run counts as turning in place.
MIN_PATH = 1e-3

#: Metrics are recorded every this many steps (and at the last one).
RECORD_EVERY = 5

#: How the report's pose metrics and targets are defined (Markdown, for the report).
DEFINITIONS = f"""\
- *Worst position error*: the largest distance, at any recorded instant of the run,
  between the simulated and the analytic reference point, in % of the analytic path
  length of the whole run (and in metres). Judged against the robot's target.
- *RMS position error*: root mean square of that distance over the run, m. *Final
  position error*: at the last instant, m and % (reported beside the worst).
- *Worst heading error*: the largest heading difference over the run, wrapped into
  (−180°, 180°]; *final heading error* at the last instant.
- A run that turns in place (path under 1 mm) is judged on its centre's worst drift, m.
- Samples: every {RECORD_EVERY}th simulation step and the last one.
- Each target is a **requirement** (an accuracy asked of the model; its basis says what
  it bounds and why) or a **derived bound**
  (it follows from the physics; its derivation is given); a metric without a target is
  reported, not judged.
- An **open** target is a requirement that no model meets yet: its row shows the
  target, the measured figure and why it is missed (verdict `open`, or `open (met)` once
  the figure meets it); it is counted in the summary line and does not decide whether
  the run passes."""

# Keys of a robot's target table used by the generic judges.
POSITION_PCT = "worst position error % of path"
CENTRE_DRIFT_M = "worst centre drift m"
HEADING_DEG = "worst heading error deg"
LATERAL_SLIP_RMS = "lateral slip RMS m/s"


@dataclass(frozen=True)
class Target:
    """A bound on a metric's magnitude, and where it comes from.

    Attributes:
        value: the bound (``|value| <= bound`` passes), in the metric's unit.
        kind: ``"requirement"`` or ``"derived bound"``.
        basis: the source of a requirement, or the derivation of a derived bound.
    """

    value: float
    kind: str
    basis: str

    KINDS = ("requirement", "derived bound", "open")

    def __post_init__(self) -> None:
        if self.kind not in self.KINDS:
            raise ValueError(f"Target.kind = {self.kind!r}; valid kinds are {self.KINDS}")
        if not (np.isfinite(self.value) and self.value > 0):
            raise ValueError(f"Target.value = {self.value!r}; must be a finite number > 0")

    @classmethod
    def requirement(cls, value: float, source: str) -> Target:
        """A required bound, with where it was asked for."""
        return cls(value, "requirement", source)

    @classmethod
    def derived(cls, value: float, derivation: str) -> Target:
        """A bound derived from the physics, with its derivation."""
        return cls(value, "derived bound", derivation)

    @classmethod
    def open(cls, value: float, source: str, reason: str) -> Target:
        """A requirement no model meets yet: shown with its figure, counted, not judged.

        Args:
            value: the required bound.
            source: where it was asked for (e.g. the issue).
            reason: why it is missed (what the model leaves out).
        """
        return cls(value, "open", f"{source}; not yet met: {reason}")

    @property
    def judged(self) -> bool:
        """Whether a row with this target decides pass or fail (not an open target)."""
        return self.kind != "open"

    @property
    def label(self) -> str:
        """``"requirement: source"`` or ``"derived bound: derivation"``."""
        return f"{self.kind}: {self.basis}"


class Metric(NamedTuple):
    """One measured quantity (``target`` None: reported, not judged)."""

    name: str
    value: float
    unit: str
    target: Target | None = None
    note: str = ""


@dataclass(frozen=True)
class Row:
    """One metric of one scenario, judged.

    ``passed`` None: not judged; ``open``: an open target, its figure shown against it.
    """

    robot: str
    scenario: str
    metric: str
    value: float
    unit: str
    target: float | None = None
    passed: bool | None = None
    note: str = ""
    basis: str = ""
    open: bool = False

    @staticmethod
    def of(robot: str, scenario: str, m: Metric) -> Row:
        """The row of a metric: passes when ``|value| <= target`` (and is finite).

        An open target's row is not judged (``passed`` None, ``open`` True).
        """
        t = m.target
        meets = t is not None and bool(np.isfinite(m.value) and abs(m.value) <= t.value)
        passed = None if t is None or not t.judged else meets
        return Row(robot, scenario, m.name, float(m.value), m.unit,
                   None if t is None else t.value, passed, m.note,
                   "" if t is None else t.label, open=t is not None and not t.judged)

    @property
    def verdict(self) -> str:
        """``pass``, ``FAIL``, ``open`` / ``open (met)``, or empty (reported only)."""
        if self.open:
            meets = np.isfinite(self.value) and self.target is not None and abs(
                self.value) <= self.target
            return "open (met)" if meets else "open"
        return "" if self.passed is None else ("pass" if self.passed else "FAIL")


@overload
def row_value(rows: Sequence[Row], metric: str, unit: str) -> float | None: ...


@overload
def row_value(rows: Sequence[Row], metric: str, unit: str, default: float) -> float: ...


def row_value(rows: Sequence[Row], metric: str, unit: str,
              default: float | None = None) -> float | None:
    """The value of the first row named ``metric`` in ``unit`` (``default`` if none)."""
    return next((r.value for r in rows if r.metric == metric and r.unit == unit), default)


@dataclass(frozen=True)
class Series:
    """A curve for the report's plots (a measurement scenario's own time series).

    Attributes:
        label: legend entry (one starting with ``_`` is left out of the legend).
        x, y: the points.
        xlabel, ylabel: axis labels; series with the same pair share a panel.
        style: matplotlib format string: ``"-"`` a curve, ``"o"`` points, ``"k--"`` ...
        color: matplotlib colour (None: the next of the cycle).
    """

    label: str
    x: np.ndarray
    y: np.ndarray
    xlabel: str = "t [s]"
    ylabel: str = ""
    style: str = "-"
    color: str | None = None


@dataclass
class Trace:
    """Time series of one run, for judges and plots.

    ``sim`` and ``analytic`` hold the adapter's state (``state_names``, ``state_units``)
    read from the physics and integrated by the model; ``slip`` the lateral slip speed of
    each conventional wheel; ``series`` any further curves.
    """

    time: list[float] = field(default_factory=list)
    sim: list[np.ndarray] = field(default_factory=list)
    analytic: list[np.ndarray] = field(default_factory=list)
    slip: list[np.ndarray] = field(default_factory=list)
    state_names: tuple[str, ...] = ()
    state_units: tuple[str, ...] = ()
    series: list[Series] = field(default_factory=list)

    def arrays(self) -> dict[str, np.ndarray]:
        """The series as arrays."""
        return {"time": np.asarray(self.time), "sim": np.asarray(self.sim),
                "analytic": np.asarray(self.analytic), "slip": np.asarray(self.slip)}

    @property
    def is_pose(self) -> bool:
        """Whether the state starts with a planar pose ``(x, y, heading)``."""
        return self.state_names[:3] == ("x", "y", "heading")


@dataclass(frozen=True)
class Sample:
    """What a probe sees at a recorded step ``k`` (data: after that step, live).

    Attributes:
        k: step index; ``t = k Δt`` seconds after the settle, at the step's start.
        t: that time, s.
        model, data: the simulation just after step ``k`` (contacts of its start).
        u: the scenario's input over the step.
        ctrl: the actuator controls over the step.
        x: the analytic state at the step's start.
    """

    k: int
    t: float
    model: mujoco.MjModel
    data: mujoco.MjData
    u: np.ndarray
    ctrl: np.ndarray
    x: np.ndarray


class Probe(Protocol):
    """A per-robot measurement taken during a run (e.g. a free wheel's rate)."""

    def observe(self, sample: Sample) -> None:
        """Take what it needs from one recorded step."""
        ...

    def metrics(self) -> list[Metric]:
        """Its metrics after the run."""
        ...


#: ``(scenario, model, adapter, targets) -> Probe``, or None where it does not apply.
ProbeFactory = Callable[["Scenario", mujoco.MjModel, "Adapter", Mapping[str, Target]],
                        "Probe | None"]

#: ``(scenario, trace, adapter, targets) -> metrics``: judges a run of one scenario kind.
Judge = Callable[["Scenario", Trace, "Adapter", Mapping[str, Target]], list[Metric]]


def rms(values: Sequence[float] | np.ndarray) -> float:
    """Root mean square (NaN for no values)."""
    v = np.asarray(values, float)
    return float(np.sqrt(np.mean(v ** 2))) if v.size else float("nan")


def worst_and_rms(name: str, err: np.ndarray, unit: str, target: Target,
               note: str = "") -> list[Metric]:
    """``worst <name>`` judged (``max |err|`` over the run) and ``RMS <name>`` reported.

    ``RMS = √(mean(err²))`` (:func:`rms`); both in ``unit``.
    """
    e = np.abs(np.asarray(err, float))
    return [Metric(f"worst {name}", float(e.max()), unit, target, note),
            Metric(f"RMS {name}", rms(e), unit)]


def event_aligned_error(ref: np.ndarray, other: np.ndarray, shift: int,
                        scale: Sequence[float] | np.ndarray | None = None) -> np.ndarray:
    """Per-sample error of two sampled traces whose jumps may land ``shift`` samples apart.

    The (τ, ε)-closeness of hybrid traces (H. Abbas, H. Mittelmann, G. Fainekos,
    "Formal property verification in a conformance testing framework", MEMOCODE 2014),
    on a common grid with τ = ``shift`` samples (s): each sample of either trace is
    matched with the nearest sample of the other within s, one match for all its
    components (the trace is retimed as a whole),

        j*_k = argmin_{|j| ≤ s} max_c |x_{k,c} − y_{k+j,c}| / σ_c,
        e_k  = max( |x_k − y_{k+j*_k}|,  |y_k − x_{k+j'*_k}| )   (per component),

    ``j'*`` the same match from y to x, indices clipped to the run, σ_c ``scale``; ``max_k
    e_k ≤ ε`` exactly when each trace is (τ, ε)-close to the other. It relaxes the
    Skorokhod distance (J. Deshmukh, R. Majumdar, V. Prabhu, CAV 2015) with its retiming
    bounded by τ: the matches need not be monotone. ``s = 0`` is the pointwise
    ``|x_k − y_k|``. A jump of either trace that the other makes within s samples adds
    nothing; one made later, or of another size, adds its full mismatch. Along a smooth
    stretch ``e_k`` is below the pointwise error by at most ``s · max |x_{k+1} − x_k|``.

    Args:
        ref: (N,) or (N, m) samples x_k.
        other: y_k, the same shape and grid.
        shift: s ≥ 0, samples.
        scale: (m,) σ_c > 0 weighing the components when choosing a match (None: 1).

    Raises:
        ValueError: a negative or non-integer shift, arrays of different shapes, or a
            non-positive scale.
    """
    if isinstance(shift, bool) or not isinstance(shift, int | np.integer) or shift < 0:
        raise ValueError(f"shift = {shift!r}; give a whole number of samples ≥ 0")
    x, y = np.asarray(ref, float), np.asarray(other, float)
    if x.shape != y.shape or x.ndim not in (1, 2) or not len(x):
        raise ValueError(f"ref {x.shape} and other {y.shape} must be the same (N,) or "
                         "(N, m) shape, N ≥ 1")
    flat = x.ndim == 1
    if flat:
        x, y = x[:, None], y[:, None]
    sigma = np.ones(x.shape[1]) if scale is None else np.asarray(scale, float)
    if sigma.shape != (x.shape[1],) or not np.all(np.isfinite(sigma) & (sigma > 0)):
        raise ValueError(f"scale = {scale!r}; give {x.shape[1]} positive numbers")
    n = len(x)
    rows = np.arange(n)

    def matched(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        offsets = np.arange(-shift, shift + 1)
        idx = np.clip(rows[:, None] + offsets[None, :], 0, n - 1)  # (N, 2s + 1)
        diff = np.abs(a[:, None, :] - b[idx])  # (N, 2s + 1, m)
        best = np.argmin(np.max(diff / sigma, axis=2), axis=1)
        return diff[rows, best]

    err = np.maximum(matched(x, y), matched(y, x))
    return err[:, 0] if flat else err


def twist_metrics(model: str, ref: np.ndarray, other: np.ndarray, distance: float,
                  targets: dict[str, Target | None] | None = None,
                  shift: int = 0) -> list[Metric]:
    """Worst error of u, v (m/s) and r (rad/s), each in % of its scale, and RMS.

    ``ref`` and ``other``: body twists ``(u, v, r)`` over the run, shape (N, 3). Scales,
    with ``L`` = ``distance`` the lever of ``r`` at the wheels: u and v,
    ``max(peak |(u, v)|, L · peak |r|)``; r, that over L (a component that stays zero is
    judged against the speed the run's motion gives the wheels). Each worst error is
    judged against ``targets[name]`` where given.

    ``shift`` > 0: the worst errors are :func:`event_aligned_error` with jumps allowed
    ``shift`` samples apart (a hybrid model's events against a time-stepping simulator's,
    which resolves an event only to its step; one match per sample for the whole twist,
    components weighed by their scales), and the pointwise worst error of each component
    is reported beside (``worst u error, sample by sample``). RMS errors are pointwise.
    """
    targets = targets or {}
    speed = float(np.max(np.linalg.norm(ref[:, :2], axis=1)))
    peak_r = float(np.max(np.abs(ref[:, 2])))
    lin = max(speed, distance * peak_r, 1e-9)
    scales = (lin, lin, lin / distance)
    aligned = event_aligned_error(ref, other, shift, scales)
    out = []
    for j, (name, unit, scale) in enumerate(zip(("u", "v", "r"), ("m/s", "m/s", "rad/s"),
                                                scales, strict=True)):
        err = aligned[:, j]
        point = np.abs(other[:, j] - ref[:, j])
        what = (f"(τ, ε)-closeness error, jumps up to {shift} sample"
                f"{'s' if shift > 1 else ''} apart" if shift else f"|{name} − {name}_{model}|")
        note = f"max {what} = {err.max():.3g} {unit}; scale {scale:.3g} {unit}"
        out += [Metric(f"{model}: worst {name} error", 100 * float(err.max()) / scale,
                       "% of peak", targets.get(name), note),
                Metric(f"{model}: RMS {name} error", rms(point), unit)]
        if shift:
            out.append(Metric(f"{model}: worst {name} error, sample by sample",
                              100 * float(point.max()) / scale, "% of peak",
                              note="the same samples compared at the same instant: a "
                                   "jump landing one sample apart counts whole"))
    return out


def pose_tracking(scenario: Scenario, trace: Trace, adapter: Adapter,
                  targets: Mapping[str, Target]) -> list[Metric]:
    """Worst, RMS and final position and heading errors over the run (module docstring)."""
    tr = trace.arrays()
    sim, ana = tr["sim"], tr["analytic"]
    err = np.linalg.norm(sim[:, :2] - ana[:, :2], axis=1)
    path = float(cumulative_path(ana[:, :2])[-1])
    heading = np.degrees(wrap_angle(sim[:, 2] - ana[:, 2]))
    worst_k = int(np.argmax(err))
    out = []
    if path > MIN_PATH:
        out.append(Metric("worst position error", 100.0 * err[worst_k] / path, "% of path",
                          targets.get(POSITION_PCT),
                          f"max over the run of |p_sim − p_model| / path, at "
                          f"t = {tr['time'][worst_k]:.2f} s"))
    else:
        out.append(Metric("worst centre drift", float(err[worst_k]), "m",
                          targets.get(CENTRE_DRIFT_M)))
    out += [Metric("worst position error", float(err[worst_k]), "m"),
            Metric("RMS position error", rms(err), "m"),
            Metric("final position error", float(err[-1]), "m")]
    if path > MIN_PATH:
        out.append(Metric("final position error", 100.0 * float(err[-1]) / path, "% of path"))
    out += [Metric("worst heading error", float(np.max(np.abs(heading))), "deg",
                   targets.get(HEADING_DEG)),
            Metric("final heading error", float(heading[-1]), "deg"),
            Metric("path length", path, "m")]
    return out


def slip_metrics(trace: Trace, wheels: Sequence[str], targets: Mapping[str, Target]
                 ) -> list[Metric]:
    """RMS (judged) and largest lateral slip speed at each conventional wheel's contact."""
    slip = trace.arrays()["slip"]
    out = []
    for i, wheel in enumerate(wheels):
        out.append(Metric(f"lateral slip RMS, {wheel}", rms(slip[:, i]), "m/s",
                          targets.get(LATERAL_SLIP_RMS)))
        out.append(Metric(f"largest lateral slip, {wheel}", float(np.max(np.abs(slip[:, i]))),
                          "m/s"))
    return out


def lateral_slip(model: mujoco.MjModel, data: mujoco.MjData,
                 wheels: Sequence[str]) -> np.ndarray:
    """Speed of each wheel's contact point along its axle (0 without contact), m/s.

    The non-holonomic constraint residual: for contact point ``c`` on the wheel body,
    ``v_slip = â · (J_p(c) q̇)`` with ``â`` the wheel axle in the world frame.
    """
    out = np.zeros(len(wheels))
    if not wheels or data.ncon == 0:
        return out
    jacp = np.zeros((3, model.nv))
    contact_bodies = model.geom_bodyid[data.contact.geom[:data.ncon]]
    positions = data.contact.pos[:data.ncon]
    for i, name in enumerate(wheels):
        jid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
        body = int(model.jnt_bodyid[jid])
        for c in np.flatnonzero((contact_bodies == body).any(axis=1)):
            mujoco.mj_jac(model, data, jacp, None, positions[c], body)
            out[i] = float(data.xaxis[jid] @ (jacp @ data.qvel))
    return out
