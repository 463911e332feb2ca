"""omni3's fidelity ladder: each rung's cost, and its errors on the same scenarios.

``python -m wmr_mujoco.bench.ladder [--quick] [--no-write]`` measures every rung of
:data:`RUNGS` in one run and pastes the table into ``docs/ladder.md``:

* **cost**: degrees of freedom (``nv``), floor contacts per step (mean over the bench
  scenario), steps per second of C MuJoCo on one thread (``mujoco.rollout``, median of
  :data:`REPEATS`, the rungs timed round robin), and robot-steps per second of
  ``simulate_batch``'s ``"rollout"`` backend at :data:`WORLDS` worlds on every core
  (and ``"warp"`` at :data:`WARP_WORLDS` worlds where MuJoCo Warp is installed);
* **kinematic errors**: worst position (% of path) and heading (°) errors over omni3's
  kinematic scenarios, judged against the ideal kinematics as ``wmr validate`` does;
* **dynamic errors**: omni3's dynamic runs (step commands on the rate servo, constant
  wheel torques from rest, the coast after a drive; :data:`DYNAMIC_SPECS`), the same
  inputs on each rung against omni3's own physics, the reference: the worst distance
  between the two poses over the run as % of the reference's path
  (:func:`~wmr_mujoco.robots.omni3.dynamics.path_length`, lever L), and the worst heading
  difference (°), worst over the runs of each group.
"""

from __future__ import annotations

import dataclasses
import functools
import logging
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.docs_sync.markers import fixed, publish, study_parser
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots.spec import RobotSpec

DOC = Path(__file__).resolve().parents[3] / "docs" / "ladder.md"
MARKER = "ladder"
REFERENCE = "omni3"
#: Worlds of the batched columns.
WORLDS = 64
WARP_WORLDS = 8
#: Timed repeats of the one-thread column (median).
REPEATS = 5
#: Steps of the bench scenario over which contacts are counted.
CONTACT_STEPS = 2000
#: The runner's rows read for the kinematic errors: (metric, unit).
POSITION_ROW = ("worst position error", "% of path")
HEADING_ROW = ("worst heading error", "deg")
#: Dynamic run groups: label -> the name prefix of omni3's runs in it.
GROUPS = {"step commands": "step", "torques": "torque", "coast": "coast"}
#: The logger MuJoCo's warnings reach Python through (the bindings' warning callback).
MUJOCO_LOGGER = "absl"
#: The settle before each dynamic run and the lead-in's ramp, s (omni3's runs).
SETTLE = 0.5
RAMP = 0.5


@dataclass(frozen=True)
class Rung:
    """One rung: a registered robot, possibly with a design alternative of its builder.

    Attributes:
        label: its row's name.
        robot: registry name.
        build: a builder replacing the robot's (None: the robot as registered).
        scene_extras: scene elements replacing the robot's (None: as registered).
    """

    label: str
    robot: str
    build: Callable | None = None
    scene_extras: Callable | None = None

    @property
    def registered(self) -> bool:
        """Whether this is the registry's robot as it is (batched columns apply)."""
        return self.build is None and self.scene_extras is None

    def spec(self) -> RobotSpec:
        """The robot's registry entry with this rung's builder."""
        from wmr_mujoco.robots import get_spec

        spec = get_spec(self.robot)
        changes = {k: v for k, v in (("build", self.build),
                                     ("scene_extras", self.scene_extras)) if v is not None}
        return dataclasses.replace(spec, **changes) if changes else spec

    def params(self) -> RobotParams | None:
        """None (the checked-in files) for a registered rung, else default parameters."""
        return None if self.registered else self.spec().params_type()


def _rungs() -> tuple[Rung, ...]:
    from wmr_mujoco.robots.omni3_reduced import builder, sphere

    return (
        Rung(REFERENCE, REFERENCE),
        Rung("omni3_reduced", "omni3_reduced"),
        Rung("omni3_reduced, capsule ends at the rows (±e)", "omni3_reduced",
             build=functools.partial(builder.build, row_fraction=1.0)),
        Rung("omni3_reduced, capsule ends 0.1 e from the mid-plane", "omni3_reduced",
             build=functools.partial(builder.build, row_fraction=0.1)),
        Rung("spheres on ball joints, driven through sites", "omni3_reduced",
             build=sphere.build, scene_extras=sphere.no_pairs),
        Rung("omni3_reduced, roller friction 0.001", "omni3_reduced",
             scene_extras=functools.partial(builder.floor_pairs, roller_friction=1e-3)),
    )


@functools.cache
def _dynamic_specs() -> tuple:
    from wmr_mujoco.robots import omni3

    return tuple(omni3.DYNAMIC_SPECS)


@dataclass
class RungFigures:
    """What the ladder measured of one rung (NaN: not measured)."""

    label: str
    dof: int
    contacts: float
    steps_per_s: float
    batched: float = math.nan
    warp: float = math.nan
    kin_path_pct: float = math.nan
    kin_heading_deg: float = math.nan
    dynamic: dict[str, tuple[float, float]] = dataclasses.field(default_factory=dict)
    messages: int = 0


class _Counter(logging.Handler):
    """Counts the warnings MuJoCo's Python bindings log (through ``absl``)."""

    def __init__(self) -> None:
        super().__init__(logging.WARNING)
        self.count = 0

    def emit(self, record: logging.LogRecord) -> None:
        self.count += 1


@dataclass(frozen=True)
class BenchRun:
    """A rung's bench scenario, settled and scheduled, ready to step from ``start``."""

    model: mujoco.MjModel
    start: mujoco.MjData
    controls: np.ndarray

    @classmethod
    def of(cls, rung: Rung) -> BenchRun:
        """Prepared as the validation runner prepares it."""
        from wmr_mujoco.validation.runner import prepare

        spec = rung.spec()
        prep = prepare(spec, spec.scenario(spec.bench_scenario), rung.params())
        return cls(prep.model, prep.data, prep.controls)

    def seconds(self) -> float:
        """CPU time (this process's) of one ``mujoco.rollout`` of the run on one thread."""
        from wmr_mujoco.sim.engine import Engine, simulate

        data = mujoco.MjData(self.model)
        mujoco.mj_copyData(data, self.model, self.start)
        t0 = time.process_time()
        simulate(self.model, data, self.controls, Engine.ROLLOUT)
        return time.process_time() - t0

    def contacts(self) -> float:
        """Mean contacts per step over the first :data:`CONTACT_STEPS` steps."""
        data = mujoco.MjData(self.model)
        mujoco.mj_copyData(data, self.model, self.start)
        counts = []
        for ctrl in self.controls[:CONTACT_STEPS]:
            data.ctrl[:] = ctrl
            mujoco.mj_step(self.model, data)
            counts.append(data.ncon)
        return float(np.mean(counts))


def one_thread_speeds(runs: Sequence[BenchRun], repeats: int = REPEATS) -> list[float]:
    """Steps per second of each run, median of ``repeats`` timed round robin.

    Round robin, a load on the machine that comes and goes falls on every run alike.
    """
    times: list[list[float]] = [[] for _ in runs]
    for _ in range(repeats):
        for i, run in enumerate(runs):
            times[i].append(run.seconds())
    return [len(run.controls) / float(np.median(t)) for run, t in zip(runs, times, strict=True)]


def cost(rung: Rung) -> tuple[int, float, float]:
    """``(nv, mean contacts per step, one-thread steps/s)`` on the robot's bench scenario."""
    run = BenchRun.of(rung)
    return run.model.nv, run.contacts(), one_thread_speeds([run])[0]


def kinematic_errors(rung: Rung, quick: bool = False) -> tuple[float, float]:
    """Worst position error (% of path) and heading error (°) over the kinematic scenarios.

    Raises:
        RuntimeError: a scenario failed to run (diverged); the message names it.
    """
    from wmr_mujoco.validation.runner import run_scenario
    from wmr_mujoco.validation.scenarios import ScenarioKind

    spec = rung.spec()
    scenarios = [s for s in spec.scenarios if s.kind is ScenarioKind.KINEMATIC]
    if quick:
        scenarios = [spec.scenario(spec.bench_scenario)]
    path, heading = 0.0, 0.0
    for s in scenarios:
        result = run_scenario(spec, s, params=rung.params())
        if result.error:
            raise RuntimeError(f"{rung.label}: {s.name}: {result.error}")
        for row in result.rows:
            if (row.metric, row.unit) == POSITION_ROW:
                path = max(path, row.value)
            if (row.metric, row.unit) == HEADING_ROW:
                heading = max(heading, row.value)
    return path, heading


def dynamic_poses(rung: Rung, specs: Sequence) -> dict[str, np.ndarray]:
    """Each run's base pose ``(X, Y, ψ)`` in its start frame, per step: (N + 1, 3).

    As omni3's runs: settled at rest for :data:`SETTLE` s on the rate servo; a lead-in
    drives its twist (``θ̇ = H ν``, ramped over :data:`RAMP` s) for its lead time; then the
    run's mode (rate servo or torque) holds its command for its duration.

    Raises:
        SimulationDivergedError: a run diverged.
    """
    from wmr_mujoco.models.actuation import ActuationMode, set_actuation_mode
    from wmr_mujoco.models.loading import load
    from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
    from wmr_mujoco.sim.stepping import check_healthy
    from wmr_mujoco.validation.adapters import base_pose

    spec = rung.spec()
    p = spec.params_type() if rung.params() is None else rung.params()
    H = ok.wheel_jacobian(ok.symmetric_layout(p.wheel_radius, p.wheel_distance))
    out = {}
    for run in specs:
        model = load(spec, rung.params())
        set_actuation_mode(model, ActuationMode.RATE)
        data = mujoco.MjData(model)
        dt = model.opt.timestep
        for _ in range(round(SETTLE / dt)):
            mujoco.mj_step(model, data)
        if run.lead_in is not None:
            for k in range(round(run.lead_time / dt)):
                data.ctrl[:] = min(1.0, k * dt / RAMP) * (H @ np.asarray(run.lead_in))
                mujoco.mj_step(model, data)
        set_actuation_mode(model, run.mode)
        data.ctrl[:] = run.command
        mujoco.mj_forward(model, data)
        poses = [base_pose(model, data)]
        for _ in range(round(run.duration / dt)):
            mujoco.mj_step(model, data)
            poses.append(base_pose(model, data))
        check_healthy(model, data)
        pose = np.array(poses)
        pose[:, 2] = np.unwrap(pose[:, 2])
        c, s = math.cos(pose[0, 2]), math.sin(pose[0, 2])
        rel = pose - pose[0]
        out[run.name] = np.column_stack([c * rel[:, 0] + s * rel[:, 1],
                                         -s * rel[:, 0] + c * rel[:, 1], rel[:, 2]])
    return out


def dynamic_errors(poses: dict[str, np.ndarray], reference: dict[str, np.ndarray],
                   distance: float) -> dict[str, tuple[float, float]]:
    """Per group of :data:`GROUPS`: worst position (%) and heading (°) errors.

    ``poses`` against ``reference``, worst over the group's runs. A run's errors are
    ``max_k |p_k − p*_k| / path*`` and ``max_k |ψ_k − ψ*_k|``, ``path*``
    :func:`~wmr_mujoco.robots.omni3.dynamics.path_length` of the reference with lever
    ``distance``; a rung on another timestep is interpolated onto the reference's instants.

    Raises:
        ValueError: runs of other pose columns.
    """
    from wmr_mujoco.robots.omni3.dynamics import path_length

    out: dict[str, tuple[float, float]] = {}
    for group, prefix in GROUPS.items():
        worst = (0.0, 0.0)
        for name, ref in reference.items():
            if not name.startswith(prefix):
                continue
            got = poses[name]
            if got.ndim != 2 or got.shape[1] != ref.shape[1] or len(got) < 2:
                raise ValueError(f"{name}: poses {got.shape} against {ref.shape}")
            if len(got) != len(ref):  # the same duration on another timestep
                at, of = np.linspace(0, 1, len(ref)), np.linspace(0, 1, len(got))
                got = np.column_stack([np.interp(at, of, col) for col in got.T])
            pos = 100 * float(np.max(np.linalg.norm(got[:, :2] - ref[:, :2], axis=1))
                              ) / path_length(ref, distance)
            head = math.degrees(float(np.max(np.abs(got[:, 2] - ref[:, 2]))))
            worst = (max(worst[0], pos), max(worst[1], head))
        out[group] = worst
    return out


def measure(rungs: Sequence[Rung], quick: bool = False) -> list[RungFigures]:
    """Every figure of every rung, one rung after another (see the module docstring).

    MuJoCo's warnings logged while a rung is measured are counted into its row.
    """
    specs = _dynamic_specs()
    if quick:
        specs = tuple(next(s for s in specs if s.name.startswith(p)) for p in GROUPS.values())
    reference = dynamic_poses(Rung(REFERENCE, REFERENCE), specs)
    distance = Rung(REFERENCE, REFERENCE).spec().params_type().wheel_distance
    runs = [BenchRun.of(rung) for rung in rungs]
    speeds = one_thread_speeds(runs)
    figures = []
    logger = logging.getLogger(MUJOCO_LOGGER)
    for rung, run, speed in zip(rungs, runs, speeds, strict=True):
        counter = _Counter()
        logger.addHandler(counter)
        try:
            fig = RungFigures(rung.label, run.model.nv, run.contacts(), speed)
            figures.append(_measure_rung(rung, fig, reference, specs, distance, quick))
        finally:
            logger.removeHandler(counter)
        fig.messages = counter.count
    return figures


def _measure_rung(rung: Rung, fig: RungFigures, reference: dict[str, np.ndarray],
                  specs: Sequence, distance: float, quick: bool) -> RungFigures:
    """The rest of one rung's figures (:func:`measure`): batched, kinematic, dynamic."""
    from wmr_mujoco.batch.simulate import installed_backends
    from wmr_mujoco.bench.batch_throughput import measure as throughput

    if rung.registered:
        fig.batched = throughput(rung.robot, "rollout", WORLDS, REPEATS).throughput
        if "warp" in installed_backends():
            fig.warp = throughput(rung.robot, "warp", WARP_WORLDS, REPEATS).throughput
    fig.kin_path_pct, fig.kin_heading_deg = kinematic_errors(rung, quick)
    if rung.robot != REFERENCE:
        fig.dynamic = dynamic_errors(dynamic_poses(rung, specs), reference, distance)
    return fig


def _pair(values: tuple[float, float] | None) -> str:
    return "reference" if values is None else f"{fixed(values[0])} / {fixed(values[1])}"


def table(figures: Sequence[RungFigures], quick: bool = False) -> str:
    """Markdown: one row per rung."""
    import os
    import platform

    from wmr_mujoco.batch.simulate import installed_backends

    warp = ("warp" in installed_backends())
    head = ["rung", "DoF", "contacts / step", "steps/s, 1 thread (k)",
            f"rollout, {WORLDS} worlds (k robot-steps/s)"]
    head += [f"warp, {WARP_WORLDS} worlds (k robot-steps/s)"] if warp else []
    head += ["MuJoCo warnings logged", "kinematic: position % of path / heading °"]
    head += [f"{g}: position % of path / heading °" for g in GROUPS]
    lines = [f"`python -m wmr_mujoco.bench.ladder{' --quick' if quick else ''}`: MuJoCo "
             f"{mujoco.__version__}, {platform.machine()}, {os.cpu_count()} CPU cores"
             f"{'' if warp else '; MuJoCo Warp not installed here (no warp column)'}. "
             "Kinematic: worst over omni3's kinematic scenarios against the ideal "
             "kinematics; dynamic: worst over omni3's runs of each group against omni3's "
             "physics.", "",
             "| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for f in figures:
        cells = [f.label, str(f.dof), fixed(f.contacts, 1), f"{f.steps_per_s / 1e3:.3g}",
                 "-" if math.isnan(f.batched) else f"{f.batched / 1e3:.3g}"]
        cells += (["-" if math.isnan(f.warp) else f"{f.warp / 1e3:.3g}"] if warp else [])
        cells += [str(f.messages), _pair((f.kin_path_pct, f.kin_heading_deg))]
        cells += [_pair(f.dynamic.get(g) if f.dynamic else None) for g in GROUPS]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Measure every rung, print the table, paste it into docs/ladder.md (not with --no-write)."""
    parser = study_parser(__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help="one kinematic scenario and one run per dynamic group")
    args = parser.parse_args(argv)
    figures = measure(_rungs(), args.quick)
    publish(DOC, {MARKER: table(figures, args.quick)}, not args.no_write)


if __name__ == "__main__":
    main()
