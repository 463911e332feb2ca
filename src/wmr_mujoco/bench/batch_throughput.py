"""Batched simulation throughput: robot-steps per second against the number of worlds.

``python -m wmr_mujoco.bench.batch_throughput [--quick] [--no-write]`` times each
backend of :func:`wmr_mujoco.simulate_batch` stepping ``N`` identical worlds of a robot
(its first kinematic validation scenario, from its settled start) and prints

    throughput = N · steps / t_step,

``t_step`` the median over ``--repeats`` runs (after one warm-up, which also builds
MuJoCo Warp's kernels) of the backend's stepping alone
(:attr:`~wmr_mujoco.batch.backend.Backend.step_seconds`: no settle, no schedule, no
reading of poses). Each run takes about :data:`BUDGET` robot-steps (``steps = BUDGET /
N``, within ``[MIN_STEPS, MAX_STEPS]``), so small and large batches do comparable work.
``"rollout"`` runs on every CPU core (threads); ``"warp"`` on the GPUs if there are any
(then with :data:`GPU_WORLDS` and :data:`GPU_BUDGET`), else on the CPU, where it is for
testing physics, not for speed. The table is pasted into ``docs/batch.md`` under the
marker of the machine's kind (:data:`MARKER`, or :data:`GPU_MARKER` with a GPU).
"""

from __future__ import annotations

import os
import platform
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from wmr_mujoco.docs_sync.markers import publish, study_parser

DOC = Path(__file__).resolve().parents[3] / "docs" / "batch.md"
MARKER = "batch-throughput"
#: The marker of the table measured on a machine with a GPU.
GPU_MARKER = "batch-throughput-gpu"
#: Worlds per backend on a CPU machine (warp on the CPU: small batches only).
WORLDS = {"rollout": (1, 8, 64, 512, 8192), "warp": (1, 8, 64)}
#: Worlds with ``--quick``.
QUICK_WORLDS = {"rollout": (1, 64, 1024), "warp": (1, 8)}
#: Robot-steps per timed run, per backend.
BUDGET = {"rollout": 40_000, "warp": 200}
#: Worlds and robot-steps per timed run for warp on CUDA devices.
GPU_WORLDS = (1, 64, 1024, 8192, 32768)
GPU_BUDGET = 4_000_000
MIN_STEPS, MAX_STEPS = 5, 500
ROBOTS = ("diffdrive", "omni3", "omni3_reduced", "mecanum4")
QUICK_ROBOTS = ("diffdrive",)


@dataclass(frozen=True)
class Point:
    """One timed batch."""

    robot: str
    backend: str
    worlds: int
    steps: int
    seconds: float

    @property
    def throughput(self) -> float:
        """Robot-steps per second."""
        return self.worlds * self.steps / self.seconds


def measure(robot: str, backend: str, worlds: int, repeats: int = 3,
            budget: int | None = None) -> Point:
    """Median stepping time of ``worlds`` copies of the robot's first kinematic scenario.

    ``budget`` robot-steps per run (default :data:`BUDGET` of the backend).

    Raises:
        ValueError: unknown robot or backend; ``worlds`` or ``repeats`` below 1.
    """
    import numpy as np

    from wmr_mujoco.batch.simulate import make_backend
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.validation.runner import prepare
    from wmr_mujoco.validation.scenarios import ScenarioKind

    if worlds < 1 or repeats < 1:
        raise ValueError(f"worlds = {worlds}, repeats = {repeats}; both must be >= 1")
    spec = get_spec(robot)
    scenario = next(s for s in spec.scenarios if s.kind is ScenarioKind.KINEMATIC)
    steps = int(np.clip((budget or BUDGET[backend]) // worlds, MIN_STEPS, MAX_STEPS))
    prep = prepare(spec, scenario, None)
    prep.controls = prep.controls[:steps]
    engine = make_backend(backend)
    engine.run([prep] * worlds)  # warm-up (and Warp's kernels)
    times = []
    for _ in range(repeats):
        engine.run([prep] * worlds)
        times.append(engine.step_seconds)
    return Point(robot, backend, worlds, steps, float(np.median(times)))


def table(points: Sequence[Point], cores: int | None = None, device: str | None = None) -> str:
    """Markdown: one row per robot and backend, one column per world count.

    ``cores`` and ``device`` (where Warp ran) describe the machine that measured
    ``points`` (default: this one).
    """
    import mujoco

    from wmr_mujoco.batch.simulate import installed_backends

    worlds = sorted({p.worlds for p in points})
    if device is None:
        device = "cpu"
        if "warp" in installed_backends():
            from wmr_mujoco.batch import warp_setup

            wp, _ = warp_setup.init()
            device = ", ".join(d if d == "cpu" else f"{d} ({wp.get_device(d).name})"
                               for d in warp_setup.devices())
    lines = [f"`python -m wmr_mujoco.bench.batch_throughput`: robot-steps per second "
             f"(thousands), medians; MuJoCo {mujoco.__version__}, {platform.machine()}, "
             f"{cores or os.cpu_count()} CPU cores; warp on {device}.", "",
             "| robot | backend | " + " | ".join(f"N = {n}" for n in worlds) + " |",
             "|---|---|" + "---|" * len(worlds)]
    rows: dict[tuple[str, str], dict[int, Point]] = {}
    for p in points:
        rows.setdefault((p.robot, p.backend), {})[p.worlds] = p
    for (robot, backend), by_n in rows.items():
        cells = [f"{by_n[n].throughput / 1e3:.3g}" if n in by_n else "-" for n in worlds]
        lines.append(f"| {robot} | {backend} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Measure, print, and paste the table into docs/batch.md (unless ``--no-write``)."""
    from wmr_mujoco.batch.simulate import installed_backends

    parser = study_parser(__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help=f"robots {', '.join(QUICK_ROBOTS)} and fewer world counts")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args(argv)
    if args.repeats < 1:
        parser.error(f"--repeats {args.repeats}; give an integer >= 1")
    robots, worlds = (QUICK_ROBOTS, QUICK_WORLDS) if args.quick else (ROBOTS, WORLDS)
    budget, marker = dict(BUDGET), MARKER
    if "warp" in installed_backends():
        from wmr_mujoco.batch import warp_setup

        if warp_setup.devices() != ["cpu"]:
            worlds = {**worlds, "warp": GPU_WORLDS}
            budget["warp"], marker = GPU_BUDGET, GPU_MARKER
    points = []
    for robot in robots:
        for backend in installed_backends():
            for n in worlds[backend]:
                points.append(measure(robot, backend, n, args.repeats, budget[backend]))
                print(points[-1], flush=True)
    publish(DOC, {marker: table(points)}, not args.no_write)


if __name__ == "__main__":
    main()
