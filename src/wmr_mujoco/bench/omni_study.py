"""The omni robot's roller design study and the side-by-side with the peer model.

``python -m wmr_mujoco.bench.omni_study`` runs both and writes their tables into
``models/omni3/README.md`` (between marker comments). Everything is measured in one run
on this machine: rolling-radius ripple on the collision geometry, open-loop tracking of
:func:`wmr_mujoco.bench.trials.standard_trials` through the validation runner (worst
position and heading error over each run), yaw-rate ripple, roller spin rates, and the
real-time factor of the ``mj_step`` loop.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from wmr_mujoco.bench.trials import (
    PEER_NAME,
    TrialRun,
    peer_spec,
    run_trial,
    standard_trials,
)
from wmr_mujoco.docs_sync.markers import fixed, publish, study_parser
from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params import OmniParams
from wmr_mujoco.models.paths import MODELS_DIR
from wmr_mujoco.robots import omni3, registered
from wmr_mujoco.validation.omni_wheels import rolling_radius_profile
from wmr_mujoco.validation.scenarios import Scenario

#: The robot this study is about (its own study: it names its model and wheels).
ROBOT = omni3.NAME
README = MODELS_DIR / ROBOT / "README.md"


@dataclass(frozen=True)
class Summary:
    """Worst cases over a set of trials, and the median real-time factor.

    Position and heading are the worst over each whole run (not its last instant), then
    the worst over the trials.
    """

    label: str
    ripple_pct: float
    worst_position_pct: float
    worst_heading_deg: float
    yaw_ripple_pct: float
    roller_rate_err_pct: float
    real_time_factor: float


def summarise(label: str, runs: Sequence[TrialRun], ripple_pct: float) -> Summary:
    """Reduce trial runs to worst cases (NaNs ignored) and the median real-time factor.

    Raises:
        RuntimeError: a trial failed (its reason is named).
    """
    failed = [f"{r.result.scenario.key}: {r.result.error}" for r in runs if r.result.error]
    if failed:
        raise RuntimeError(f"trials failed: {failed}")

    def worst(metric: str, unit: str) -> float:
        vals = [abs(v) for r in runs if np.isfinite(v := r.value(metric, unit))]
        return max(vals) if vals else float("nan")

    return Summary(
        label=label, ripple_pct=ripple_pct,
        worst_position_pct=worst("worst position error", "% of path"),
        worst_heading_deg=worst("worst heading error", "deg"),
        yaw_ripple_pct=worst("yaw-rate ripple", "% of commanded"),
        roller_rate_err_pct=worst("roller rate error (median)", "%"),
        real_time_factor=float(np.median([r.real_time_factor for r in runs])))


def _pick(trials: Sequence[Scenario], names: Sequence[str] | None) -> list[Scenario]:
    return [t for t in trials if names is None or t.name in names]


def measure_omni(params: OmniParams, label: str, names: Sequence[str] | None = None
                 ) -> Summary:
    """Ripple and trials (all, or those named) of the robot built from ``params``."""
    model = load(ROBOT, params)
    profile = rolling_radius_profile(model, "wheel1", "wheel1_roller")
    ripple = 100.0 * float(np.ptp(profile) / np.mean(profile))
    trials = _pick(standard_trials(ROBOT), names)
    return summarise(label, [run_trial(t, params) for t in trials], ripple)


def measure_peer(names: Sequence[str] | None = None, scene: Path | None = None) -> Summary:
    """The peer model on the same trials (its ripple is not measured: cylinder rollers).

    Raises:
        FileNotFoundError: the peer's scene is missing (the message says how to set it).
    """
    with registered(peer_spec(scene)) as spec:
        runs = [run_trial(t) for t in _pick(spec.scenarios, names)]
    return summarise(f"{PEER_NAME} (peer, as published)", runs, float("nan"))


def study_configs() -> list[tuple[str, OmniParams]]:
    """Roller shapes × roller counts; thickness b = 0.9 r / n keeps the rows comparable."""
    configs = []
    for n in (3, 6):
        for shape in OmniParams.ROLLER_SHAPES:
            params = dataclasses.replace(OmniParams(), roller_shape=shape, rollers_per_row=n,
                                         roller_thickness=round(0.9 / n, 4))
            configs.append((f"{shape}, 2×{n}", params))
    return configs


def table(rows: Sequence[Summary], default_label: str | None = None) -> str:
    """Markdown table of summaries."""
    lines = ["| model | rolling-radius ripple % | worst position error % of path | "
             "worst heading error ° | yaw-rate ripple % | roller rate error % | "
             "real-time factor |", "|---|---|---|---|---|---|---|"]
    for s in rows:
        label = f"**{s.label} (default)**" if s.label == default_label else s.label
        lines.append(f"| {label} | {fixed(s.ripple_pct, 3)} | {fixed(s.worst_position_pct, 3)} | "
                     f"{fixed(s.worst_heading_deg)} | {fixed(s.yaw_ripple_pct, 1)} | "
                     f"{fixed(s.roller_rate_err_pct, 1)} | {fixed(s.real_time_factor, 0)}× |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Run the study and the side-by-side; print the tables and update the README."""
    args = study_parser(__doc__).parse_args(argv)
    default = OmniParams()
    default_label = f"{default.roller_shape}, 2×{default.rollers_per_row}"
    study = []
    for label, params in study_configs():
        study.append(measure_omni(params, label))
        print(table(study[-1:]).splitlines()[-1], flush=True)
    ours = measure_omni(default, f"{ROBOT} (this package, default)")
    peer = measure_peer()
    publish(README, {"roller study": table(study, default_label),
                     "side by side": table([ours, peer])}, not args.no_write)


if __name__ == "__main__":
    main()
