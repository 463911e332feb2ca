"""The mecanum roller design study: ``python -m wmr_mujoco.mecanum_study``.

Roller colliders × roller counts, each measured in one run on this machine: the
rolling-radius ripple on the collision geometry (``mj_geomDistance`` over a wheel
revolution), open-loop tracking of :func:`~wmr_mujoco.mecanum_scenarios.standard_scenarios`
(0.5 s ramps and steps; worst over every run and RMS), and the real-time factor of
``mj_step`` on one thread. ``omni3`` (default model) is timed in the same process for the
ratio. The tables go between markers in ``models/mecanum4/README.md``.
"""

from __future__ import annotations

import argparse
import dataclasses
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.loading import load
from wmr_mujoco.markers import replace_between
from wmr_mujoco.mecanum_model import SPEC, load_mecanum
from wmr_mujoco.mecanum_scenarios import (
    MecanumScenario,
    ScenarioResult,
    judge,
    lateral_bound_pct,
    run_scenario,
    standard_scenarios,
)
from wmr_mujoco.omni_study import OMNI_WHEELS
from wmr_mujoco.omni_trials import layout_from_model, rolling_radius_profile, run_trial
from wmr_mujoco.omni_trials import standard_trials as omni_standard_trials
from wmr_mujoco.params_mecanum import MecanumParams

README = SPEC.robot_path.parent / "README.md"
COUNTS = (8, 12, 16, 20, 24)
#: Study trials are short (2 shared cores); the validation scenarios run 4 s.
STUDY_DURATION = 3.0


@dataclass(frozen=True)
class Summary:
    """One model's figures; tracking per command kind (``"ramp"``, ``"step"``).

    ``tracking[kind] = (worst position %, RMS position %, worst heading °, RMS heading °)``,
    position over the runs with ≥ 1 cm of path, worst and RMS over every run's series.
    """

    label: str
    ripple_pct: float
    lateral_bound_pct: float
    tracking: dict[str, tuple[float, float, float, float]]
    real_time_factor: float


def ripple_pct(model) -> float:
    """Peak-to-peak rolling radius of wheel FL over one revolution, % of its mean."""
    prof = rolling_radius_profile(model, "wheel_fl", "wheel_fl_roller", samples=721)
    return 100.0 * float(np.ptp(prof) / np.mean(prof))


def tracking(results: Sequence[ScenarioResult]) -> tuple[float, float, float, float]:
    """Worst and RMS position error (% of path) and heading error (°) over all series."""
    pos, pos_sq, head, head_sq = [], [], [], []
    for r in results:
        if r.path >= 0.01:
            pct = 100.0 * r.position_error / r.path
            pos.append(pct.max())
            pos_sq.append(np.mean(pct**2))
        h = r.heading_error
        head.append(np.abs(h).max())
        head_sq.append(np.mean(h**2))
    return (float(max(pos)), float(np.sqrt(np.mean(pos_sq))), float(max(head)),
            float(np.sqrt(np.mean(head_sq))))


def measure(params: MecanumParams, scenarios: Sequence[MecanumScenario],
            label: str) -> Summary:
    """Ripple, tracking and real-time factor of the model built from ``params``."""
    model = load_mecanum(params)
    results = [run_scenario(model, params, s) for s in scenarios]
    kinds = {"ramp": [r for r, s in zip(results, scenarios, strict=True) if s.ramp > 0],
             "step": [r for r, s in zip(results, scenarios, strict=True) if s.ramp == 0]}
    return Summary(label, ripple_pct(model), lateral_bound_pct(params),
                   {k: tracking(v) for k, v in kinds.items() if v},
                   float(np.median([r.real_time_factor for r in results])))


def omni3_real_time_factor(duration: float = STUDY_DURATION) -> float:
    """Real-time factor of the default ``omni3`` on its translate+rotate trial."""
    model = load("omni3")
    info = layout_from_model(model, OMNI_WHEELS)
    trial = next(t for t in omni_standard_trials() if t.name == "translate+rotate")
    return run_trial(model, info, dataclasses.replace(trial, duration=duration)
                     ).real_time_factor


def mecanum_real_time_factor(params: MecanumParams, duration: float = STUDY_DURATION
                             ) -> float:
    """Real-time factor of ``mecanum4`` on the same manoeuvre (0.3 m/s ahead, 0.5 rad/s)."""
    scenario = MecanumScenario("translate+rotate", (0.3, 0.0, 0.5), duration)
    return run_scenario(load_mecanum(params), params, scenario).real_time_factor


def timing_table(params: MecanumParams, rounds: int = 3,
                 duration: float = STUDY_DURATION) -> str:
    """Real-time factors of mecanum4 and omni3, interleaved, best of ``rounds`` each.

    The machine is shared: the best of a few interleaved rounds is the figure least
    disturbed by other load, and both models see the same conditions.
    """
    ours, omni = [], []
    for _ in range(rounds):
        ours.append(mecanum_real_time_factor(params, duration))
        omni.append(omni3_real_time_factor(duration))
    label = f"{params.roller_shape}, {params.rollers_per_wheel}"
    return "\n".join([
        f"| model (best of {rounds} interleaved runs, translate+rotate, {duration:g} s) | "
        "real-time factor (one thread) |", "|---|---|",
        f"| mecanum4 (default, {label}) | {max(ours):.0f}× |",
        f"| omni3 (default) | {max(omni):.0f}× |",
        f"| ratio mecanum4 / omni3 | {max(ours) / max(omni):.2f} |"])


def study_configs() -> list[tuple[str, MecanumParams]]:
    """Roller shapes × roller counts, everything else at the defaults."""
    return [(f"{shape}, {n}", dataclasses.replace(MecanumParams(), roller_shape=shape,
                                                   rollers_per_wheel=n))
            for n in COUNTS for shape in MecanumParams.ROLLER_SHAPES]


#: Validation-length runs of the default model (the omni validation scenarios last 10 s).
LONG_RUNS = (MecanumScenario("translate 90° (ramp)", (0.0, 0.3, 0.0), 10.0),
             MecanumScenario("translate 45° (step)", (0.3 * 0.5**0.5, 0.3 * 0.5**0.5, 0.0),
                             10.0, 0.0),
             MecanumScenario("rotate (ramp)", (0.0, 0.0, 1.0), 10.0),
             MecanumScenario("rotate (step)", (0.0, 0.0, 1.0), 10.0, 0.0))


def long_runs_table(params: MecanumParams) -> str:
    """Judged rows of :data:`LONG_RUNS` on the model built from ``params``."""
    model = load_mecanum(params)
    lines = ["| run | metric | value | unit | target | basis |", "|---|---|---|---|---|---|"]
    for s in LONG_RUNS:
        res = run_scenario(model, params, s)
        for metric, value, unit, target, basis in judge(res, params, s):
            if "RMS" in metric:
                continue
            lines.append(f"| {s.name} | {metric} | {_fmt(value, 3)} | {unit} | "
                         f"{_fmt(target, 1)} | {basis} |")
    return "\n".join(lines)


def _fmt(x: float, digits: int = 2) -> str:
    return "n/a" if not np.isfinite(x) else f"{x:.{digits}f}"


def table(rows: Sequence[Summary], default_label: str | None = None) -> str:
    """Markdown table of summaries: ramp and step tracking in their own columns."""
    lines = ["| rollers | ripple % | derived lateral shortfall % | ramps: worst / RMS "
             "position % of path | ramps: worst / RMS heading ° | steps: worst / RMS "
             "position % of path | steps: worst / RMS heading ° | real-time factor |",
             "|---|---|---|---|---|---|---|---|"]
    for s in rows:
        label = f"**{s.label} (default)**" if s.label == default_label else s.label
        cells = []
        for kind in ("ramp", "step"):
            wp, rp, wh, rh = s.tracking.get(kind, (np.nan,) * 4)
            cells += [f"{_fmt(wp, 3)} / {_fmt(rp, 3)}", f"{_fmt(wh)} / {_fmt(rh, 3)}"]
        lines.append(f"| {label} | {_fmt(s.ripple_pct, 3)} | {_fmt(s.lateral_bound_pct)} | "
                     + " | ".join(cells) + f" | {_fmt(s.real_time_factor, 0)}× |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Run the study; print the tables and update the README."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--no-write", action="store_true", help="print only")
    parser.add_argument("--duration", type=float, default=STUDY_DURATION,
                        help="seconds per trial")
    args = parser.parse_args(argv)
    scenarios = standard_scenarios(duration=args.duration)
    default = MecanumParams()
    default_label = f"{default.roller_shape}, {default.rollers_per_wheel}"
    study = []
    for label, params in study_configs():
        study.append(measure(params, scenarios, label))
        print(table(study[-1:]).splitlines()[-1], flush=True)
    # Default and omni3 timed back to back in the same process for the ratio.
    timing = timing_table(default, duration=args.duration)
    study_md = table(study, default_label)
    long_md = long_runs_table(default)
    print(study_md, "", timing, "", long_md, sep="\n")
    if not args.no_write:
        replace_between(README, "mecanum roller study", study_md)
        replace_between(README, "mecanum timing", timing)
        replace_between(README, "mecanum long runs", long_md)
        print(f"wrote {README}")


if __name__ == "__main__":
    main()
