"""Fidelity against cost of the Whipple model: ``python -m wmr_mujoco.whipple_study``.

For each simulation setting (integrator, timestep, contact ``solref``/``solimp``,
``impratio``, collider half-width) it measures the weave and capsize speeds, the worst
eigenvalue error at 1, 3, 5, 7, 10 m/s, the self-stability runs and the real-time factor,
and writes the table between the ``whipple study`` markers of ``models/whipple/README.md``;
a second table (``whipple contact split``) sets the contact's normal and frictional time
constants apart to show which one the eigenvalue errors come from.
It runs in well under a minute on one core.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.analytic import whipple as analytic
from wmr_mujoco.builders import whipple as builder
from wmr_mujoco.builders.common import to_xml
from wmr_mujoco.builders.scene import add_scene
from wmr_mujoco.markers import replace_between
from wmr_mujoco.paths import MODELS_DIR
from wmr_mujoco.whipple_measure import (
    evaluations_per_second,
    measure_modes,
    real_time_factor,
    with_sim,
)
from wmr_mujoco.whipple_params import DEFAULT_PARAMS, WhippleParams
from wmr_mujoco.whipple_validation import (
    TABLE_SPEEDS,
    critical_speeds,
    eigen_metrics,
    eigen_rows,
    passed,
    push_runs,
    speed_metrics,
    stability_metrics,
)

README = MODELS_DIR / "whipple" / "README.md"
MARKER = "whipple study"
SPLIT_MARKER = "whipple contact split"


@dataclass(frozen=True)
class StudyRow:
    """One setting's figures."""

    label: str
    params: WhippleParams
    weave_err_pct: float
    capsize_err_pct: float
    eig_ratio: float
    castering_err_10: float
    lean_ratio_5: float
    rtf: float
    meets_all: bool


def study_configs(base: WhippleParams = DEFAULT_PARAMS) -> list[tuple[str, WhippleParams]]:
    """The settings compared: the default and one change at a time."""
    s = base.sim
    cfg = [("default", base)]
    for dt in (0.002, 0.0015, 0.0005):
        cfg.append((f"timestep {dt * 1e3:g} ms",
                    with_sim(base, timestep=dt, contact_timeconst=2 * dt)))
    for integ in ("implicit", "RK4", "Euler"):
        if integ != s.integrator:
            cfg.append((f"{integ}", with_sim(base, integrator=integ)))
    cfg.append(("RK4, timestep 2 ms", with_sim(base, integrator="RK4", timestep=0.002,
                                               contact_timeconst=0.004)))
    cfg.append(("solref time constant ×2",
                 with_sim(base, contact_timeconst=2 * s.contact_timeconst)))
    cfg.append(("solref time constant ×2, implicit, 0.5 ms",
                 with_sim(base, integrator="implicit", timestep=0.0005,
                          contact_timeconst=2 * s.contact_timeconst)))
    cfg.append(("impratio 1", with_sim(base, impratio=1.0)))
    cfg.append(("impratio 100", with_sim(base, impratio=100.0)))
    cfg.append(("solimp d 0.9", with_sim(base, solimp_dmax=0.9)))
    cfg.append(("noslip 10 iterations", with_sim(base, noslip_iterations=10)))
    cfg.append(("collider half-width 5 mm", with_sim(base, wheel_half_width=0.005)))
    cfg.append(("collider half-width 20 mm", with_sim(base, wheel_half_width=0.02)))
    return cfg


def measure_row(label: str, params: WhippleParams) -> StudyRow:
    """All figures of one setting (a failure to measure shows as NaN and fails)."""
    nan = float("nan")
    try:
        speeds = critical_speeds(params)
        rows = eigen_rows(params, TABLE_SPEEDS)
        runs = push_runs(params)
    except (RuntimeError, ValueError):
        return StudyRow(label, params, nan, nan, nan, nan, nan,
                        real_time_factor(params), False)
    metrics = speed_metrics(speeds) + eigen_metrics(rows) + stability_metrics(params, runs)
    cast = next(r for r in rows if r.speed == 10.0)
    return StudyRow(
        label=label, params=params,
        weave_err_pct=metrics[0][1], capsize_err_pct=metrics[1][1],
        eig_ratio=metrics[2][1],
        castering_err_10=cast.measured.castering - cast.benchmark.castering,
        lean_ratio_5=runs[5.0].final_ratio, rtf=real_time_factor(params),
        meets_all=all(passed(m) for m in metrics))


def table(rows: Sequence[StudyRow]) -> str:
    """Markdown table of the study."""
    head = ("| setting | integrator | Δt (ms) | solref τ (ms) | impratio | weave speed err (%) "
            "| capsize speed err (%) | worst eig. err / tol, 1-10 m/s | castering err at "
            "10 m/s (1/s) | lean ratio at 5 m/s | real-time factor | meets all |")
    lines = [head, "|" + "---|" * 12]
    for r in rows:
        s = r.params.sim
        tau = max(s.contact_timeconst, 2 * s.timestep)
        lines.append(
            f"| {r.label} | {s.integrator} | {s.timestep * 1e3:g} | {tau * 1e3:g} | "
            f"{s.impratio:g} | {r.weave_err_pct:.3f} | {r.capsize_err_pct:.3f} | "
            f"{r.eig_ratio:.2f} | {r.castering_err_10:+.3f} | {r.lean_ratio_5:.3f} | "
            f"{r.rtf:.0f} | {'yes' if r.meets_all else 'no'} |")
    passing = [r for r in rows if r.meets_all]
    if passing:
        least = min(evaluations_per_second(r.params) for r in passing)
        cheapest = [r for r in passing if evaluations_per_second(r.params) == least]
        lines.append("")
        lines.append(
            f"Cheapest settings meeting every target (fewest force evaluations per "
            f"simulated second, {least:.0f}): "
            + ", ".join(f"**{r.label}**" for r in cheapest)
            + ". Real-time factors: one thread, best of three 2-s runs; expect ±20 % on "
            "a shared machine.")
    return "\n".join(lines)


def split_contact_model(params: WhippleParams, normal_timeconst: float,
                        friction_timeconst: float) -> mujoco.MjModel:
    """The model with explicit wheel-floor contact pairs.

    Their normal (``solref``) and frictional (``solreffriction``) time constants may
    differ; the wheels' own collisions are switched off.
    """
    root = builder.build(params)
    add_scene(root)
    s = params.sim
    for name in ("rear_wheel_collision", "front_wheel_collision"):
        geom = root.find("geom", name)
        geom.contype = 0
        geom.conaffinity = 0
        root.contact.add("pair", geom1=name, geom2="floor", condim=3,
                         friction=(s.friction, s.friction, 0.005, 0.0001, 0.0001),
                         solref=(normal_timeconst, s.contact_dampratio),
                         solreffriction=(friction_timeconst, s.contact_dampratio),
                         solimp=(s.solimp_dmax, s.solimp_dmax, 0.001, 0.5, 2.0))
    return mujoco.MjModel.from_xml_string(to_xml(root))


def contact_split_table(params: WhippleParams = DEFAULT_PARAMS, speed: float = 10.0) -> str:
    """Markdown: eigenvalue errors at ``speed``, normal and frictional τ set apart.

    Each of the two time constants is the default's or 4 × it.
    """
    tau = max(params.sim.contact_timeconst, 2 * params.sim.timestep)
    ref = analytic.modes(speed, analytic.matrices(params))
    lines = [f"| normal τ (ms) | friction τ (ms) | castering error at {speed:g} m/s (1/s) | "
             f"weave Re error (1/s) | weave Im error (1/s) | capsize error (1/s) |",
             "|---|---|---|---|---|---|"]
    for tn, tf in ((tau, tau), (4 * tau, tau), (tau, 4 * tau), (4 * tau, 4 * tau)):
        m = measure_modes(params, speed, split_contact_model(params, tn, tf)).modes
        lines.append(f"| {tn * 1e3:g} | {tf * 1e3:g} | {m.castering - ref.castering:+.3f} | "
                     f"{m.weave.real - ref.weave.real:+.3f} | "
                     f"{m.weave.imag - ref.weave.imag:+.3f} | {m.capsize - ref.capsize:+.4f} |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Run the study, print the table and paste it into the model README."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--no-write", action="store_true", help="print only")
    args = parser.parse_args(argv)
    rows = [measure_row(label, p) for label, p in study_configs()]
    text = table(rows)
    split = contact_split_table()
    print(text, split, sep="\n\n")
    if not args.no_write:
        replace_between(README, MARKER, text)
        replace_between(README, SPLIT_MARKER, split)
        print(f"wrote {README}")


if __name__ == "__main__":
    np.seterr(all="ignore")
    main()
