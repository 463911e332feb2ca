"""omni3 beside its peer, robot_soccer_kit (MuJoCo Menagerie), on the same open-loop trials.

The trials are the roller-wheel family's (:func:`~wmr_mujoco.robots.roller_wheels.trials.\
standard_trials`), run through the validation runner; :func:`summarise` reduces them to
worst cases. ``wmr bench`` shows the side-by-side (the registry entry's ``peer``) and
:mod:`wmr_mujoco.bench.omni_study` the roller design study built on the same summary.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.models.loading import load
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.roller_wheels import rolling_radius_profile
from wmr_mujoco.robots.roller_wheels.trials import (
    PEER_NAME,
    TrialRun,
    peer_spec,
    run_trial,
    standard_trials,
)
from wmr_mujoco.validation.scenarios import Scenario

#: The robot compared.
ROBOT = "omni3"
#: Trials of the peer comparison in a quick bench run.
QUICK_PEER_TRIALS = ("translate   0°", "rotate", "translate+rotate")


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


def _ripple(model: mujoco.MjModel) -> float:
    """Peak-to-peak rolling-radius ripple of wheel 1 over a revolution, % of its mean."""
    profile = rolling_radius_profile(model, "wheel1", "wheel1_roller")
    return 100.0 * float(np.ptp(profile) / np.mean(profile))


def measure_omni(params: OmniParams, label: str, names: Sequence[str] | None = None
                 ) -> Summary:
    """Ripple and trials (all, or those named) of the robot built from ``params``."""
    from wmr_mujoco.robots.omni3 import SPEC  # the entry imports this module

    trials = _pick(standard_trials(ROBOT), names)
    return summarise(label, [run_trial(SPEC, t, params) for t in trials],
                     _ripple(load(SPEC, params)))


def measure_peer(names: Sequence[str] | None = None, scene: Path | None = None) -> Summary:
    """The peer model on the same trials (its ripple is not measured: cylinder rollers).

    Raises:
        FileNotFoundError: the peer's scene is missing (the message says how to set it).
    """
    spec = peer_spec(scene)
    runs = [run_trial(spec, t) for t in _pick(spec.scenarios, names)]
    return summarise(f"{PEER_NAME} (peer, as published)", runs, float("nan"))


def peer_comparison(scene: Path, quick: bool) -> list[Mapping[str, object]]:
    """omni3 at its defaults and the peer robot_soccer_kit on the same open-loop trials.

    The two run trial by trial in turns (omni3's trial, then the peer's same trial), so
    that both real-time factors see the same load of a shared machine.
    """
    from wmr_mujoco.robots.omni3 import SPEC  # the entry imports this module

    names = QUICK_PEER_TRIALS if quick else None
    params, peer = OmniParams(), peer_spec(scene)
    theirs_by_name = {t.name: t for t in _pick(peer.scenarios, names)}
    ours, theirs = [], []
    for trial in _pick(standard_trials(ROBOT), names):
        ours.append(run_trial(SPEC, trial, params))
        theirs.append(run_trial(peer, theirs_by_name[trial.name]))
    return [dataclasses.asdict(s) for s in (
        summarise(f"{ROBOT} (default)", ours, _ripple(load(SPEC, params))),
        summarise(f"{PEER_NAME} (peer, as published)", theirs, float("nan")))]
