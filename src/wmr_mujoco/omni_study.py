"""The omni robot's roller design study and the side-by-side with the peer model.

``python -m wmr_mujoco.omni_study`` runs both and writes their tables into
``models/omni3/README.md`` (between marker comments). Everything is measured in one run
on this machine: rolling-radius ripple on the collision geometry, open-loop tracking of
:func:`wmr_mujoco.omni_trials.standard_trials`, yaw-rate ripple, roller spin rates, and
the real-time factor of ``mj_step``.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.loading import load
from wmr_mujoco.omni_trials import (
    OmniTrial,
    TrialResult,
    layout_from_model,
    rolling_radius_profile,
    run_trial,
    standard_trials,
)
from wmr_mujoco.params import OmniParams
from wmr_mujoco.paths import MODELS_DIR

#: The peer model (MuJoCo Menagerie robot_soccer_kit), measured only as a file, never
#: copied: ``../shared/anchors`` beside the checkout, or the ``WMR_PEER_SCENE`` variable.
PEER_SCENE = Path(os.environ.get(
    "WMR_PEER_SCENE",
    MODELS_DIR.parent.parent / "shared" / "anchors" / "robot_soccer_kit" / "scene.xml"))
PEER_WHEELS = ("wheel1_speed", "wheel2_speed", "wheel3_speed")
OMNI_WHEELS = ("wheel1", "wheel2", "wheel3")
README = MODELS_DIR / "omni3" / "README.md"


@dataclass(frozen=True)
class Summary:
    """Worst cases over a set of trials, and the median real-time factor."""

    label: str
    ripple_pct: float
    worst_position_pct: float
    worst_heading_deg: float
    yaw_ripple_pct: float
    roller_rate_err_pct: float
    real_time_factor: float


def summarise(label: str, results: Sequence[TrialResult], ripple_pct: float) -> Summary:
    """Reduce trial results to worst cases (NaNs ignored) and the median RTF."""
    def worst(values: list[float]) -> float:
        vals = [abs(v) for v in values if np.isfinite(v)]
        return max(vals) if vals else float("nan")

    return Summary(
        label=label, ripple_pct=ripple_pct,
        worst_position_pct=worst([r.position_error_pct for r in results]),
        worst_heading_deg=worst([r.heading_error for r in results]),
        yaw_ripple_pct=100.0 * worst([r.yaw_rate_ripple for r in results]),
        roller_rate_err_pct=100.0 * worst([r.roller_rate_error for r in results]),
        real_time_factor=float(np.median([r.real_time_factor for r in results])))


def measure_omni(params: OmniParams, trials: Sequence[OmniTrial], label: str) -> Summary:
    """Ripple and trials of the omni3 model built from ``params``."""
    model = load("omni3", params)
    profile = rolling_radius_profile(model, "wheel1", "wheel1_roller")
    ripple = 100.0 * float(np.ptp(profile) / np.mean(profile))
    info = layout_from_model(model, OMNI_WHEELS)
    return summarise(label, [run_trial(model, info, t) for t in trials], ripple)


def measure_peer(trials: Sequence[OmniTrial], scene: Path = PEER_SCENE) -> Summary:
    """The peer model on the same trials (its ripple is not measured: cylinder rollers)."""
    if not scene.is_file():
        raise FileNotFoundError(f"peer model not found: {scene} (set WMR_PEER_SCENE to "
                                "robot_soccer_kit's scene.xml)")
    model = mujoco.MjModel.from_xml_path(str(scene))
    info = layout_from_model(model, PEER_WHEELS)
    return summarise("robot_soccer_kit (peer, as published)",
                     [run_trial(model, info, t) for t in trials], float("nan"))


def study_configs() -> list[tuple[str, OmniParams]]:
    """Roller shapes × roller counts; thickness b = 0.9 r / n keeps the rows comparable."""
    configs = []
    for n in (3, 6):
        for shape in OmniParams.ROLLER_SHAPES:
            params = dataclasses.replace(OmniParams(), roller_shape=shape, rollers_per_row=n,
                                         roller_thickness=round(0.9 / n, 4))
            configs.append((f"{shape}, 2×{n}", params))
    return configs


def _fmt(x: float, digits: int = 2) -> str:
    return "n/a" if not np.isfinite(x) else f"{x:.{digits}f}"


def table(rows: Sequence[Summary], default_label: str | None = None) -> str:
    """Markdown table of summaries."""
    lines = ["| model | rolling-radius ripple % | worst position error % of path | "
             "worst heading error ° | yaw-rate ripple % | roller rate error % | "
             "real-time factor |", "|---|---|---|---|---|---|---|"]
    for s in rows:
        label = f"**{s.label} (default)**" if s.label == default_label else s.label
        lines.append(f"| {label} | {_fmt(s.ripple_pct, 3)} | {_fmt(s.worst_position_pct, 3)} | "
                     f"{_fmt(s.worst_heading_deg)} | {_fmt(s.yaw_ripple_pct, 1)} | "
                     f"{_fmt(s.roller_rate_err_pct, 1)} | {_fmt(s.real_time_factor, 0)}× |")
    return "\n".join(lines)


def replace_section(text: str, name: str, body: str) -> str:
    """Replace the text between ``<!-- name: begin -->`` and ``<!-- name: end -->``."""
    begin, end = f"<!-- {name}: begin -->", f"<!-- {name}: end -->"
    if begin not in text or end not in text:
        raise ValueError(f"README has no {begin} … {end} markers")
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    return f"{head}{begin}\n{body}\n{end}{tail}"


def main(argv: Sequence[str] | None = None) -> None:
    """Run the study and the side-by-side; print the tables and update the README."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--no-write", action="store_true", help="print only")
    args = parser.parse_args(argv)
    trials = standard_trials()
    default = OmniParams()
    default_label = f"{default.roller_shape}, 2×{default.rollers_per_row}"
    study = []
    for label, params in study_configs():
        study.append(measure_omni(params, trials, label))
        print(table(study[-1:]).splitlines()[-1], flush=True)
    ours = measure_omni(default, trials, "omni3 (this package, default)")
    peer = measure_peer(trials)
    study_md = table(study, default_label)
    side_md = table([ours, peer])
    print(study_md, "", side_md, sep="\n")
    if not args.no_write:
        text = README.read_text()
        text = replace_section(text, "roller study", study_md)
        text = replace_section(text, "side by side", side_md)
        write_text_atomic(README, text)
        print(f"wrote {README}")


if __name__ == "__main__":
    main()
