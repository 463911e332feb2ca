"""Judged metrics of the Whipple model against the benchmark, and the eigenvalue figure.

Every metric is ``(name, value, unit, target, kind)`` with ``kind`` either
``"requirement"`` (issue 14's targets) or ``"derived bound: ..."``; the value is the WORST
over the speeds named. Targets:

* Weave and capsize speeds from the physics within 1 % of the benchmark's (requirement).
* Real and imaginary parts of weave, capsize and castering at 1-10 m/s within
  ``max(2 %, 0.05 s⁻¹)`` of the benchmark (requirement); the metric is the worst
  ``|error| / tolerance`` (pass: ≤ 1), with the worst absolute error beside it.
* Self-stability (requirement): after a push at 4.6, 5.0 and 5.5 m/s the largest lean over
  the last 2 s of 10 s is under 10 % of the peak; at 3 m/s it grows. The benchmark's own
  linear equations, given the same push, reach ``ratio_lin``; where ``ratio_lin ≥ 0.1``
  (at 5.5 m/s the capsize eigenvalue is only about -0.117 s⁻¹, so the lean needs about
  20 s to fall to 10 %) the requirement cannot be met by the benchmark itself, and the
  derived bound judges the physics against ``ratio_lin``. The late lean is dominated by
  the capsize mode, ``∝ exp(s_capsize t)``; an eigenvalue error within the requirement's
  ``0.05 s⁻¹`` changes it by a factor of at most ``exp(0.05 · 10 s)``, so the bound is
  ``|ratio - ratio_lin| ≤ ratio_lin (exp(0.5) - 1)``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.linalg import expm

from wmr_mujoco.analytic import whipple as analytic
from wmr_mujoco.whipple_measure import (
    PushResponse,
    capsize_speed,
    compile_model,
    measure_modes,
    push_response,
    weave_speed,
)
from wmr_mujoco.whipple_params import DEFAULT_PARAMS, WhippleParams

Metric = tuple[str, float, str, float, str]

#: Speeds of the eigenvalue table (issue 14), m/s.
TABLE_SPEEDS = (1.0, 3.0, 5.0, 7.0, 10.0)
#: Speeds of the self-stability runs, m/s, and the one that must fall.
STABLE_SPEEDS = (4.6, 5.0, 5.5)
UNSTABLE_SPEED = 3.0
#: The push: lean rate about the ground line, rad/s.
PUSH_LEAN_RATE = 0.5
#: Relative and absolute eigenvalue tolerance (requirement).
EIG_REL, EIG_ABS = 0.02, 0.05
#: Lean ratio requirement.
LEAN_RATIO_MAX = 0.10
#: Length of the push runs, s.
PUSH_DURATION = 10.0


def eigen_tolerance(reference: float) -> float:
    """``max(2 % of |reference|, 0.05 s⁻¹)``."""
    return max(EIG_REL * abs(reference), EIG_ABS)


@dataclass(frozen=True)
class EigenRow:
    """Measured and benchmark modes at one speed."""

    speed: float
    measured: analytic.Modes
    benchmark: analytic.Modes

    def parts(self) -> list[tuple[str, float, float]]:
        """``(label, measured, benchmark)`` of the six compared numbers."""
        m, b = self.measured, self.benchmark
        return [("weave Re", m.weave.real, b.weave.real),
                ("weave Im", m.weave.imag, b.weave.imag),
                ("capsize", m.capsize, b.capsize),
                ("castering", m.castering, b.castering)]


def eigen_rows(params: WhippleParams, speeds: Sequence[float] = TABLE_SPEEDS
               ) -> list[EigenRow]:
    """Measured (physics) and benchmark modes at each speed."""
    model = compile_model(params)
    mats = analytic.matrices(params)
    return [EigenRow(v, measure_modes(params, v, model).modes, analytic.modes(v, mats))
            for v in speeds]


def eigen_metrics(rows: Sequence[EigenRow]) -> list[Metric]:
    """Worst ``|error| / tolerance`` and worst absolute error over all modes and speeds."""
    ratios, errors = [], []
    for row in rows:
        for _, meas, ref in row.parts():
            err = abs(meas - ref) if np.isfinite(meas) else np.inf
            ratios.append(err / eigen_tolerance(ref))
            errors.append(err)
    span = f"{min(r.speed for r in rows):g}-{max(r.speed for r in rows):g} m/s"
    rms = float(np.sqrt(np.mean(np.square(ratios))))
    return [(f"eigenvalue error / tolerance, worst over {span}", float(max(ratios)), "1",
             1.0, "requirement: each part within max(2 %, 0.05 1/s)"),
            (f"eigenvalue error / tolerance, RMS over {span}", rms, "1", float("nan"),
             "reported"),
            (f"eigenvalue error, worst over {span}", float(max(errors)), "1/s",
             float("nan"), "reported (the tolerance scales with the eigenvalue)")]


def critical_speeds(params: WhippleParams) -> dict[str, tuple[float, float]]:
    """``{"weave": (physics, benchmark), "capsize": (...)}``, m/s."""
    mats = analytic.matrices(params)
    return {"weave": (weave_speed(params), analytic.weave_speed(mats)),
            "capsize": (capsize_speed(params), analytic.capsize_speed(mats))}


def speed_metrics(speeds: dict[str, tuple[float, float]]) -> list[Metric]:
    """Relative error of the weave and capsize speeds, %."""
    return [(f"{name} speed error ({meas:.4f} vs {ref:.4f} m/s)",
             100.0 * abs(meas - ref) / ref, "%", 1.0, "requirement")
            for name, (meas, ref) in speeds.items()]


def linear_lean(params: WhippleParams, speed: float, times: np.ndarray,
                lean_rate: float = PUSH_LEAN_RATE) -> np.ndarray:
    """Lean of the benchmark's linear equations after the same push, ``φ(t)``."""
    a = analytic.state_matrix(speed, analytic.matrices(params))
    x0 = np.array([0.0, 0.0, lean_rate, 0.0])
    dt = float(times[1] - times[0])
    step = expm(a * dt)
    out = np.empty(len(times))
    x = x0
    for k in range(len(times)):
        out[k] = x[0]
        x = step @ x
    return out


def late_ratio(times: np.ndarray, lean: np.ndarray, window: float = 2.0) -> float:
    """Largest |φ| over the last ``window`` s over the largest |φ| of the run."""
    return float(np.abs(lean[times >= times[-1] - window]).max() / np.abs(lean).max())


def push_runs(params: WhippleParams) -> dict[float, PushResponse]:
    """The push runs at the self-stable speeds and at the falling speed."""
    model = compile_model(params)
    return {v: push_response(params, v, PUSH_LEAN_RATE, duration=PUSH_DURATION, model=model)
            for v in (*STABLE_SPEEDS, UNSTABLE_SPEED)}


def stability_metrics(params: WhippleParams, runs: dict[float, PushResponse]
                      ) -> list[Metric]:
    """Lean ratios after 10 s against the requirement or the linear benchmark."""
    out: list[Metric] = []
    mats = analytic.matrices(params)
    for v in STABLE_SPEEDS:
        r = runs[v]
        lin = late_ratio(r.time, linear_lean(params, v, r.time))
        if lin < LEAN_RATIO_MAX:
            out.append((f"lean after 10 s / peak at {v:g} m/s (linear benchmark {lin:.3f})",
                        r.final_ratio, "1", LEAN_RATIO_MAX, "requirement"))
        else:
            cap = analytic.modes(v, mats).capsize
            bound = lin * (np.exp(EIG_ABS * PUSH_DURATION) - 1.0)
            out.append((f"lean after 10 s / peak at {v:g} m/s: {r.final_ratio:.3f}, minus "
                        f"the linear benchmark's {lin:.3f}", abs(r.final_ratio - lin), "1",
                        float(bound),
                        f"derived bound: ratio_lin (exp(0.05 1/s · 10 s) - 1). The 10 % "
                        f"requirement is out of reach of the benchmark itself here: its "
                        f"capsize eigenvalue {cap:.3f} 1/s needs ln(10)/{abs(cap):.3f} = "
                        f"{np.log(10) / abs(cap):.0f} s to fall to 10 %"))
    r = runs[UNSTABLE_SPEED]
    out.append((f"lean growth at {UNSTABLE_SPEED:g} m/s: largest lean / largest lean in "
                f"the first second (falls past 1.2 rad at {r.time[-1]:.2f} s)",
                float(np.abs(r.lean).max() / np.abs(r.lean[r.time <= 1.0]).max()), "1",
                1.0, "requirement: > 1 (grows)"))
    return out


def passed(metric: Metric) -> bool:
    """Whether a metric meets its target (``> target`` for growth, else ``<=``)."""
    _, value, _, target, kind = metric
    if np.isnan(target):
        return True
    return value > target if "grows" in kind else value <= target


def all_metrics(params: WhippleParams = DEFAULT_PARAMS) -> list[Metric]:
    """Every judged metric of the model at ``params`` (about a second of CPU)."""
    return (speed_metrics(critical_speeds(params))
            + eigen_metrics(eigen_rows(params, np.arange(1.0, 10.01, 1.0)))
            + stability_metrics(params, push_runs(params)))


def eigen_series(params: WhippleParams, physics_speeds: Sequence[float],
                 curve_speeds: Sequence[float]) -> dict[str, np.ndarray]:
    """Series of the eigenvalue figure: analytic curves and physics points.

    Returns ``curve_v`` (n,), ``curve_eig`` (n, 4) complex, ``physics_v`` (k,) and
    ``physics_eig`` (k, 4) complex (the four benchmark modes measured at each speed).
    """
    mats = analytic.matrices(params)
    model = compile_model(params)
    phys = [measure_modes(params, float(v), model) for v in physics_speeds]
    return {"curve_v": np.asarray(curve_speeds, float),
            "curve_eig": analytic.eigen_series(np.asarray(curve_speeds, float), mats),
            "physics_v": np.array([m.speed for m in phys]),
            "physics_eig": np.array([m.benchmark for m in phys])}


def write_figure(path: Path, series: dict[str, np.ndarray]) -> Path:
    """The benchmark's eigenvalue-versus-speed figure with the physics points over it."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=110)
    v, eig = series["curve_v"], series["curve_eig"]
    # Dots, not lines: the four branches cross and change order with speed.
    vv = np.repeat(v[:, None], eig.shape[1], axis=1)
    ax.plot(vv.ravel(), eig.real.ravel(), "k.", ms=1.5)
    has_im = np.abs(eig.imag) > 1e-9
    ax.plot(vv[has_im], np.abs(eig.imag[has_im]), ".", color="0.55", ms=1.5)
    pv, pe = series["physics_v"], series["physics_eig"]
    for k in range(pe.shape[1]):
        ax.plot(pv, pe[:, k].real, "o", color="tab:red", ms=4,
                label="MuJoCo, real part" if k == 0 else None)
        im = np.abs(pe[:, k].imag) > 1e-9
        ax.plot(pv[im], np.abs(pe[im, k].imag), "s", color="tab:blue", ms=4, mfc="none",
                label="MuJoCo, |imaginary part|" if k == 0 else None)
    ax.plot([], [], "k-", label="benchmark, real part")
    ax.plot([], [], "-", color="0.55", label="benchmark, |imaginary part|")
    ax.set_ylim(-10, 10)
    ax.set_xlim(v[0], v[-1])
    ax.axhline(0.0, color="0.6", lw=0.5)
    ax.set_xlabel("forward speed v (m/s)")
    ax.set_ylabel("eigenvalue (1/s)")
    ax.set_title("Whipple benchmark bicycle: eigenvalues (Meijaard et al. 2007)")
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)
    return path
