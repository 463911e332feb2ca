"""The omni robot's roller design study and the side-by-side with the peer model.

``python -m wmr_mujoco.bench.omni_study`` runs both and writes their tables into
``models/omni3/README.md`` (between marker comments). Everything is measured in one run
on this machine: rolling-radius ripple on the collision geometry, open-loop tracking of
:func:`wmr_mujoco.robots.roller_wheels.trials.standard_trials` through the validation
runner (worst position and heading error over each run), yaw-rate ripple, roller spin rates, and the
real-time factor of the ``mj_step`` loop.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

import numpy as np

from wmr_mujoco.docs_sync.markers import fixed, publish, study_parser
from wmr_mujoco.lookup import load
from wmr_mujoco.models.paths import MODELS_DIR
from wmr_mujoco.robots import omni3
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.peer import Summary, measure_omni, measure_peer
from wmr_mujoco.robots.roller_wheels import rolling_radius_profile
from wmr_mujoco.sim.stepping import SimulationDivergedError

#: The robot this study is about (its own study: it names its model and wheels).
ROBOT = omni3.NAME
README = MODELS_DIR / ROBOT / "README.md"


#: The mesh roller shape (the exact barrel's convex hull).
MESH = "barrel"


def study_configs() -> list[tuple[str, OmniParams]]:
    """Roller shapes × roller counts; thickness b = 0.9 r / n keeps the rows comparable.

    The mesh ``"barrel"`` rollers run on contact bits (``floor_impedance`` 0, labelled):
    with the floor pairs' remedy they are refused (they throw the robot off the floor,
    :func:`~wmr_mujoco.models.params.fields._check_mesh_rollers`).
    """
    configs = []
    for n in (3, 6):
        for shape in OmniParams.ROLLER_SHAPES:
            bits = {"floor_impedance": 0.0} if shape == MESH else {}
            params = dataclasses.replace(OmniParams(), roller_shape=shape, rollers_per_row=n,
                                         roller_thickness=round(0.9 / n, 4), **bits)
            configs.append((f"{shape}, 2×{n}" + (" (contact bits)" if bits else ""), params))
    return configs


def measure_or_diverged(params: OmniParams, label: str) -> Summary:
    """:func:`measure_omni`, or, if a trial diverges, a row that says so.

    The divergence is printed (MuJoCo's warning and the time); the row keeps the
    geometry's ripple (wheel 1 over a revolution, as :func:`measure_omni` measures it),
    which needs no run, and is labelled diverged, its run figures ``n/a``.
    """
    try:
        return measure_omni(params, label)
    except SimulationDivergedError as err:
        print(f"{label} diverged: {err}", flush=True)
        profile = rolling_radius_profile(load(ROBOT, params), "wheel1", "wheel1_roller")
        nan = float("nan")
        return Summary(f"{label}: diverged", 100.0 * float(np.ptp(profile) / np.mean(profile)),
                       nan, nan, nan, nan, nan)


def times(rtf: float) -> str:
    """A real-time factor's cell: ``12×``, or ``n/a`` for a row that has none."""
    return f"{fixed(rtf, 0)}×" if np.isfinite(rtf) else fixed(rtf)


def table(rows: Sequence[Summary], default_label: str | None = None) -> str:
    """Markdown table of summaries."""
    lines = ["| model | rolling-radius ripple % | worst position error % of path | "
             "worst heading error ° | yaw-rate ripple % | roller rate error % | "
             "real-time factor |", "|---|---|---|---|---|---|---|"]
    for s in rows:
        label = f"**{s.label} (default)**" if s.label == default_label else s.label
        lines.append(f"| {label} | {fixed(s.ripple_pct, 3)} | {fixed(s.worst_position_pct, 3)} | "
                     f"{fixed(s.worst_heading_deg)} | {fixed(s.yaw_ripple_pct, 1)} | "
                     f"{fixed(s.roller_rate_err_pct, 1)} | {times(s.real_time_factor)} |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Run the study and the side-by-side; print the tables and update the README."""
    args = study_parser(__doc__).parse_args(argv)
    default = OmniParams()
    default_label = f"{default.roller_shape}, 2×{default.rollers_per_row}"
    study = []
    for label, params in study_configs():
        study.append(measure_or_diverged(params, label))
        print(table(study[-1:]).splitlines()[-1], flush=True)
    ours = measure_omni(default, f"{ROBOT} (this package, default)")
    peer = measure_peer()
    publish(README, {"roller study": table(study, default_label),
                     "side by side": table([ours, peer])}, not args.no_write)


if __name__ == "__main__":
    main()
