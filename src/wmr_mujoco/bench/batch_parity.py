"""MuJoCo Warp against C MuJoCo on every robot: the measured parity, as a table.

``python -m wmr_mujoco.bench.batch_parity [--no-write]`` runs
:func:`wmr_mujoco.batch.parity.parity` (seeded validation-style draws through both
backends, the worst member's base position difference judged against a share of the
robot's own position target) for every robot with a position target, prints the table
and pastes it into ``docs/batch.md`` (under :data:`GPU_MARKER` when Warp runs on a
GPU). ``tests/batch/test_parity.py`` asserts the same on the same draws.
"""

from __future__ import annotations

from collections.abc import Sequence

from wmr_mujoco.bench.batch_throughput import DOC
from wmr_mujoco.docs_sync.markers import publish, study_parser
from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.stepping import SimulationDivergedError

MARKER = "batch-parity"
#: The marker of the table measured with Warp on a GPU.
GPU_MARKER = "batch-parity-gpu"
#: Members, seconds and seed of the draws (as in tests/batch/test_parity.py).
MEMBERS, DURATION, SEED = 3, 1.0, 7


def table() -> str:
    """One row per robot: worst difference, its tolerance, the largest difference in m."""
    from wmr_mujoco.batch import parity as par
    from wmr_mujoco.robots import ROBOTS

    lines = [f"`python -m wmr_mujoco.bench.batch_parity`: {MEMBERS} seeded members of "
             f"{DURATION:g} s per robot (seed {SEED}), warp on {_device()} against rollout; "
             f"tolerance {par.SHARE:g} × the robot's position target.", "",
             "| robot | worst member | tolerance | largest difference (m) | verdict |",
             "|---|---|---|---|---|"]
    for robot in ROBOTS:
        if par.POSITION_PCT not in get_spec(robot).targets:
            continue
        try:
            p = par.parity(robot, MEMBERS, DURATION, SEED)
        except SimulationDivergedError as e:  # reported as a row, never hidden
            lines.append(f"| {robot} | diverged: {e} | | | FAIL |")
            continue
        lines.append(f"| {robot} | {p.worst:.2g} {p.unit} | {p.tolerance:.3g} {p.unit} | "
                     f"{p.worst_m:.2g} | {'pass' if p.passed else 'FAIL'} |")
    return "\n".join(lines)


def _device() -> str:
    """Where Warp runs: the GPU's name, else "the CPU"."""
    from wmr_mujoco.batch import warp_setup

    wp, _ = warp_setup.init()
    device = warp_setup.devices()[0]
    return "the CPU" if device == "cpu" else f"{device} ({wp.get_device(device).name})"


def main(argv: Sequence[str] | None = None) -> None:
    """Measure, print, and paste the table into docs/batch.md (unless ``--no-write``)."""
    args = study_parser(__doc__.splitlines()[0]).parse_args(argv)
    marker = MARKER if _device() == "the CPU" else GPU_MARKER
    publish(DOC, {marker: table()}, not args.no_write)


if __name__ == "__main__":
    main()
