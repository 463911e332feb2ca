"""``wmr bench``: speed, accuracy per unit of compute, the peer model, rendering.

Prints its tables and writes ``reports/bench.md`` and ``reports/bench.json``. Timings are
medians of repeated runs (the machines are noisy); accuracy figures come from the
validation scenarios run at each timestep.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import subprocess
import sys
import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path

import mujoco

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.bench.env_section import env_section
from wmr_mujoco.bench.thread_scaling import TARGET_S, driving_controls, scaling
from wmr_mujoco.lookup import load
from wmr_mujoco.progress import bar
from wmr_mujoco.robots import ROBOTS, get_spec
from wmr_mujoco.robots.roller_wheels.trials import PeerModel, find_peer
from wmr_mujoco.sim.timing import median_time, paired_ratio, step_loop_time
from wmr_mujoco.validation.report import check_report_folder
from wmr_mujoco.validation.runner import run_scenario
from wmr_mujoco.validation.scenarios import ScenarioKind

#: Timesteps of the accuracy-against-cost study, s.
TIMESTEPS = (0.0005, 0.001, 0.002, 0.004)


def driven_robots() -> list[str]:
    """Robots with a kinematic scenario (they have cruising controls to time)."""
    return [name for name, spec in ROBOTS.items()
            if any(s.kind is ScenarioKind.KINEMATIC for s in spec.scenarios)]


def accuracy_robots() -> list[str]:
    """Robots whose registry entry names a scenario for the accuracy study."""
    return [name for name, spec in ROBOTS.items() if spec.bench_scenario is not None]


def step_speed(robots: Sequence[str], rounds: int, nstep: int = 2000,
               target_s: float = TARGET_S) -> dict[str, dict[str, float]]:
    """Per robot, steps/s and real-time factor: ``mj_step`` loop, rollout 1 thread, all cores.

    The loop time is the median of ``rounds`` runs of ``nstep`` steps. The rollout speedup
    is the median of ``rounds`` one-thread/all-core pairs, beside the machine's ceiling
    measured in the same rounds with processes
    (:func:`wmr_mujoco.bench.thread_scaling.scaling`).
    """
    out = {}
    for robot in robots:
        model = load(robot)
        t_loop = step_loop_time(model, driving_controls(model, robot), nstep, rounds)
        dt = model.opt.timestep
        out[robot] = {"timestep": dt, "loop_steps_per_s": nstep / t_loop,
                      "loop_rtf": nstep * dt / t_loop}
    for robot, figures in scaling(robots, rounds, target_s=target_s).items():
        out[robot].update(figures)
    return out


def accuracy_vs_timestep(robot: str, repeats: int) -> list[dict[str, float]]:
    """Worst position error over the run (% of path) and real-time factor per timestep.

    Raises:
        ValueError: the robot names no bench scenario, or has no parameters to vary.
    """
    spec = get_spec(robot)
    if spec.bench_scenario is None or spec.params_type is None:
        raise ValueError(f"robot {robot!r} has no bench scenario or no parameters")
    default = spec.params_type()
    scenario = spec.scenario(spec.bench_scenario)
    rows = []
    for dt in TIMESTEPS:
        params = dataclasses.replace(default, sim=dataclasses.replace(default.sim, timestep=dt))
        result = run_scenario(spec, scenario, params=params)
        err = next((r.value for r in result.rows if r.metric == "worst position error"
                    and r.unit == "% of path"), float("nan"))
        model = load(robot, params)
        rtf = 1000 * dt / step_loop_time(model, driving_controls(model, robot), 1000, repeats)
        rows.append({"timestep": dt, "position_error_pct": err, "rtf": rtf,
                     "default": dt == default.sim.timestep, "error": result.error})
    return rows


def render_fps(repeats: int, frames: int = 60) -> dict[str, float]:
    """Frames/s at 640×480 of the scene with the most geoms.

    Measured as ``wmr render`` draws (no shadows, no reflections) and with both.
    """
    from wmr_mujoco.render.rendering import CameraSettings, Filmer

    robot = max(driven_robots(), key=lambda r: load(r).ngeom)
    model = load(robot)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    out = {}
    for shadows in (False, True):
        settings = CameraSettings(shadows=shadows, reflections=shadows)
        with Filmer(model, 640, 480, settings) as filmer:
            t = median_time(lambda f=filmer: [f.frame(data) for _ in range(frames)], repeats)
        out["shadows" if shadows else "no_shadows"] = frames / t
    out["backend"] = os.environ.get("MUJOCO_GL", "")
    out["robot"] = robot
    return out


def validate_wall_time(repeats: int) -> float:
    """Median wall time of the whole ``wmr validate`` (report included) as a subprocess.

    Raises:
        RuntimeError: a run failed; its exit code and the end of its output are named.
    """
    def run() -> None:
        with tempfile.TemporaryDirectory() as tmp:
            proc = subprocess.run([sys.executable, "-m", "wmr_mujoco.cli", "validate",
                                   "--out", tmp], check=False, capture_output=True, text=True)
        if proc.returncode != 0:
            raise RuntimeError(f"wmr validate exited with {proc.returncode}: "
                               f"{(proc.stdout + proc.stderr)[-500:]}")
    return median_time(run, repeats, warmup=False)


def validation_engines(repeats: int) -> dict[str, float]:
    """Wall time of all validation scenarios (no report) through the one runner.

    Also times the simulation stage alone (scenarios prepared beforehand): every
    kinematic and dynamic scenario stepped by the Python ``mj_step`` loop against one
    ``mujoco.rollout`` call each (the runner's stepping; a measurement scenario steps its
    own runs). Medians of ``repeats`` alternating runs.
    """
    from wmr_mujoco.lookup import validation_jobs
    from wmr_mujoco.sim.engine import simulate
    from wmr_mujoco.validation.runner import prepare, run_all

    work = validation_jobs()
    t_all = median_time(lambda: run_all(work), repeats, warmup=False)
    prepared = [prepare(spec, s) for spec, s in work if s.kind is not ScenarioKind.MEASUREMENT]

    def stage(engine: str) -> Callable[[], None]:
        def run() -> None:
            for p in prepared:
                data = mujoco.MjData(p.model)
                mujoco.mj_copyData(data, p.model, p.data)
                simulate(p.model, data, p.controls, engine=engine)
        return run

    s_loop, s_rollout, s_ratio = paired_ratio(stage("loop"), stage("rollout"), repeats)
    return {"all": t_all, "sim_loop": s_loop, "sim_rollout": s_rollout,
            "sim_speedup": s_ratio}


def peer_side_by_side(quick: bool = False, scene: Path | None = None
                      ) -> list[dict[str, object]] | None:
    """Every robot with a peer (its registry entry's ``peer``) beside the peer, same run.

    ``scene`` None: wherever :func:`~wmr_mujoco.robots.roller_wheels.trials.find_peer` finds
    it. None
    without the peer's scene or a robot that compares with it.
    """
    if scene is None:
        peer = find_peer()
        scene = None if peer is None else peer.scene
    if scene is None or not scene.is_file():
        return None
    rows = [dict(r) for spec in ROBOTS.values() if spec.peer is not None
            for r in spec.peer(scene, quick)]
    return rows or None


def _peer_section(rows: list[dict[str, float]] | None, peer: PeerModel | None = None
                  ) -> str:
    if rows is None:
        return ("Left out: the peer model was not found (install mujoco-menagerie, or set "
                "WMR_PEER_SCENE to robot_soccer_kit's scene.xml).")
    found = "" if peer is None else f"The peer's scene file came from {peer.source}.\n\n"
    return found + _md_table(["model", "worst position error % of path", "worst heading error °",
                      "real-time ×"],
                     [[p["label"], f"{p['worst_position_pct']:.3f}",
                       f"{p['worst_heading_deg']:.2f}", f"{p['real_time_factor']:.0f}×"]
                      for p in rows])


def _md_table(header: list[str], rows: list[list[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines)


def main(args: argparse.Namespace) -> int:
    """Run every benchmark, print the tables, write the report."""
    repeats = 2 if args.quick else args.repeats
    if repeats < 1:
        raise ValueError(f"repeats = {repeats!r}; must be >= 1")
    out = check_report_folder(Path(args.out))
    results: dict[str, object] = {"machine": {"cpus": os.cpu_count(),
                                              "mujoco": mujoco.__version__},
                                  "quick": bool(args.quick)}
    stages = bar(7, "wmr bench", unit="stage")
    print("stepping speed ...", file=sys.stderr, flush=True)
    pairs = 3 if args.quick else max(15, repeats)
    speed = step_speed(driven_robots(), pairs)
    results["speed"] = speed
    stages.update()
    print("accuracy against timestep ...", file=sys.stderr, flush=True)
    accuracy = {r: accuracy_vs_timestep(r, repeats) for r in accuracy_robots()}
    results["accuracy"] = accuracy
    stages.update()
    print("peer model ...", file=sys.stderr, flush=True)
    peer = find_peer()
    results["peer"] = None if peer is None else peer_side_by_side(args.quick, peer.scene)
    results["peer_source"] = None if peer is None else peer.source
    if peer is None:
        print("warning: peer model not found (install mujoco-menagerie, or set "
              "WMR_PEER_SCENE to robot_soccer_kit's scene.xml); its comparison is left out",
              file=sys.stderr)
    else:
        print(f"peer model from {peer.source}: {peer.scene}", file=sys.stderr)
    stages.update()
    print("rendering ...", file=sys.stderr, flush=True)
    results["render"] = render_fps(repeats)
    stages.update()
    print("wmr validate ...", file=sys.stderr, flush=True)
    results["validate_wall_s"] = validate_wall_time(1 if args.quick else 3)
    stages.update()
    engines = validation_engines(1 if args.quick else 3)
    results["validation_engines_s"] = engines
    stages.update()
    print("learning environments ...", file=sys.stderr, flush=True)
    results["envs"], envs_md = env_section(bool(args.quick))
    stages.update()
    stages.close()

    sp = _md_table(["robot", "timestep", "mj_step loop steps/s", "real-time ×",
                    "rollout 1 thread steps/s", f"rollout {next(iter(speed.values()))['threads']} "
                    "threads steps/s", "thread speedup", "machine ceiling (processes)"],
                   [[r, f"{v['timestep'] * 1e3:g} ms", f"{v['loop_steps_per_s']:,.0f}",
                     f"{v['loop_rtf']:.0f}×", f"{v['rollout1_steps_per_s']:,.0f}",
                     f"{v['rolloutN_steps_per_s']:,.0f}", f"{v['rollout_speedup']:.2f}×",
                     f"{v['process_ceiling']:.2f}×"]
                    for r, v in speed.items()])
    acc = _md_table(["robot", "scenario", "timestep", "worst position error % of path",
                     "real-time ×"],
                    [[r, get_spec(r).bench_scenario or "",
                      f"{row['timestep'] * 1e3:g} ms" + (" (default)" if row["default"] else ""),
                      f"{row['position_error_pct']:.3f}", f"{row['rtf']:.0f}×"]
                     for r, rows in accuracy.items() for row in rows])
    peer_md = _peer_section(results["peer"], peer)
    peer_robots = ", ".join(n for n, spec in ROBOTS.items() if spec.peer is not None)
    quick = args.quick
    ren = results["render"]
    text = "\n\n".join([
        "# Benchmarks", f"`wmr bench` on {os.cpu_count()} cores, MuJoCo {mujoco.__version__}; "
        f"medians of {repeats} repeats unless said.", "## Stepping speed (default settings)",
        sp, f"The loop column is the median of {pairs} runs of 2000 steps.",
        f"Rollout columns: a batch of identical rollouts sized to about "
        f"{TARGET_S:g} s on one thread, timed in fresh processes; the speedup is the "
        f"median of {pairs} one-thread/all-core pairs, the robots taking turns. The "
        "machine ceiling is the same batch run by as many processes as cores at once, "
        "in the same rounds, against one thread alone: what the hardware gives to fully "
        "independent work, as noisy as the speedup.",
        "## Accuracy against cost", acc,
        f"## {peer_robots} and the peer model ({'a few' if quick else 'all'} open-loop "
        "trials, same run)", peer_md, "## Rendering, 640×480",
        f"{ren['no_shadows']:.1f} frames/s as `wmr render` draws (no shadows or "
        f"reflections), {ren['shadows']:.1f} with shadows and reflections "
        f"({ren['backend']} backend; {ren['robot']}, the scene with the most geoms).",
        "## Validation",
        f"Whole `wmr validate`: {results['validate_wall_s']:.1f} s wall time (median of "
        f"{1 if args.quick else 3} runs; report included). All scenarios without the "
        f"report, one after the other through the one runner: {engines['all']:.1f} s. The "
        "simulation stage alone: "
        f"{engines['sim_rollout']:.2f} s through one `mujoco.rollout` per scenario, "
        f"{engines['sim_loop']:.2f} s through a Python `mj_step` loop "
        f"({engines['sim_speedup']:.1f}×).", "## Learning environments", envs_md]) + "\n"
    print(text)
    out.mkdir(exist_ok=True)
    write_text_atomic(out / "bench.json", json.dumps(results, indent=2, default=float))
    write_text_atomic(out / "bench.md", text)
    print(f"wrote {out / 'bench.md'}", file=sys.stderr)
    return 0
