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
import time
from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
from mujoco import rollout

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.loading import load
from wmr_mujoco.omni_study import measure_omni, measure_peer
from wmr_mujoco.omni_trials import OmniTrial, standard_trials
from wmr_mujoco.registry import ROBOTS, get_spec
from wmr_mujoco.scenarios import scenarios_for
from wmr_mujoco.validation import run_scenario

#: Timesteps of the accuracy-against-cost study, s.
TIMESTEPS = (0.0005, 0.001, 0.002, 0.004)
#: Scenario used for each robot in the accuracy study.
ACCURACY_SCENARIOS = {"bicycle": "steady turn 0.3 rad", "omni3": "translate+rotate"}


def median_time(fn: Callable[[], None], repeats: int) -> float:
    """Median wall time of ``fn()`` over ``repeats`` runs (after one warm-up)."""
    fn()
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def paired_speedup(slow: Callable[[], None], fast: Callable[[], None], repeats: int
                   ) -> tuple[float, float, float]:
    """Median times of ``slow`` and ``fast``, and the median of their per-pair ratios.

    The two run alternately, which cancels the machine's slow drifts in load.
    """
    slow()
    fast()
    ts, tf, ratios = [], [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        slow()
        t1 = time.perf_counter()
        fast()
        t2 = time.perf_counter()
        ts.append(t1 - t0)
        tf.append(t2 - t1)
        ratios.append((t1 - t0) / (t2 - t1))
    return float(np.median(ts)), float(np.median(tf)), float(np.median(ratios))


def _driving_controls(model: mujoco.MjModel, robot: str) -> np.ndarray:
    """Steady controls of the robot's first validation scenario (its cruising inputs)."""
    from wmr_mujoco.validation import make_adapter

    scenario = scenarios_for([robot])[0]
    adapter = make_adapter(scenario, model)
    x0 = np.zeros(len(adapter.state_names))
    return np.asarray(adapter.controls(scenario.input_at(scenario.duration), x0))


def step_speed(robot: str, repeats: int, nstep: int = 2000) -> dict[str, float]:
    """Steps/s and real-time factor: Python ``mj_step`` loop, rollout 1 thread, all cores."""
    model = load(robot)
    data = mujoco.MjData(model)
    ctrl = _driving_controls(model, robot)
    for _ in range(200):  # settle
        mujoco.mj_step(model, data)

    def loop() -> None:
        d = mujoco.MjData(model)
        d.ctrl[:] = ctrl
        for _ in range(nstep):
            mujoco.mj_step(model, d)

    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    state0 = np.zeros(mujoco.mj_stateSize(model, spec))
    mujoco.mj_getState(model, data, state0, spec)
    nbatch = 16
    controls = np.tile(ctrl, (nbatch, nstep // 2, 1))
    init = np.tile(state0, (nbatch, 1))
    threads = os.cpu_count() or 1

    def batched(nthread: int) -> Callable[[], None]:
        datas = [mujoco.MjData(model) for _ in range(nthread)]
        return lambda: rollout.rollout(model, datas if nthread > 1 else datas[0], init,
                                       controls, persistent_pool=nthread > 1)

    t_loop = median_time(loop, repeats)
    t_r1, t_rn, speedup = paired_speedup(batched(1), batched(threads), max(repeats, 9))
    dt = model.opt.timestep
    batch_steps = nbatch * controls.shape[1]
    return {"timestep": dt, "loop_steps_per_s": nstep / t_loop,
            "loop_rtf": nstep * dt / t_loop,
            "rollout1_steps_per_s": batch_steps / t_r1,
            "rollout1_rtf": batch_steps * dt / t_r1,
            "rolloutN_steps_per_s": batch_steps / t_rn, "threads": threads,
            "rollout_speedup": speedup}


def accuracy_vs_timestep(robot: str, repeats: int) -> list[dict[str, float]]:
    """Final position error (% of path) and real-time factor at each timestep."""
    spec = get_spec(robot)
    default = spec.params_type()
    scenario = next(s for s in scenarios_for([robot]) if s.name == ACCURACY_SCENARIOS[robot])
    rows = []
    for dt in TIMESTEPS:
        params = dataclasses.replace(default, sim=dataclasses.replace(default.sim, timestep=dt))
        result = run_scenario(scenario, params=params)
        err = next((r.value for r in result.rows if r.metric == "final position error"
                    and r.unit == "% of path"), float("nan"))
        model = load(robot, params)
        ctrl = _driving_controls(model, robot)

        def loop(model: mujoco.MjModel = model, ctrl: np.ndarray = ctrl) -> None:
            d = mujoco.MjData(model)
            d.ctrl[:] = ctrl
            for _ in range(1000):
                mujoco.mj_step(model, d)

        rtf = 1000 * dt / median_time(loop, repeats)
        rows.append({"timestep": dt, "position_error_pct": err, "rtf": rtf,
                     "default": dt == default.sim.timestep, "error": result.error})
    return rows


def render_fps(repeats: int, frames: int = 60) -> dict[str, float]:
    """Frames/s at 640×480 of the omni robot, the scene with the most geoms.

    Measured as ``wmr render`` draws (no shadows, no reflections) and with both.
    """
    from wmr_mujoco.rendering import CameraSettings, Filmer

    model = load("omni3")
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    out = {}
    for shadows in (False, True):
        settings = CameraSettings(shadows=shadows, reflections=shadows)
        with Filmer(model, 640, 480, settings) as filmer:
            t = median_time(lambda f=filmer: [f.frame(data) for _ in range(frames)], repeats)
        out["shadows" if shadows else "no_shadows"] = frames / t
    out["backend"] = os.environ.get("MUJOCO_GL", "")
    return out


def validate_wall_time() -> float:
    """Wall time of the whole ``wmr validate`` as a subprocess."""
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-m", "wmr_mujoco.cli", "validate", "--out", tmp],
                       check=False, capture_output=True)
        return time.perf_counter() - t0


def validation_engines() -> dict[str, float]:
    """Wall time of all validation scenarios (no report) with each stepping engine."""
    from wmr_mujoco.validation import ENGINES, run_all

    out = {}
    for engine in ENGINES:
        t0 = time.perf_counter()
        run_all(scenarios_for(), engine=engine)
        out[engine] = time.perf_counter() - t0
    return out


def peer_side_by_side(trials: list[OmniTrial]) -> list[dict[str, float]]:
    """Our omni robot and the peer on the same trials, same run."""
    ours = measure_omni(get_spec("omni3").params_type(), trials, "omni3 (default)")
    peer = measure_peer(trials)
    return [dataclasses.asdict(s) for s in (ours, peer)]


def _md_table(header: list[str], rows: list[list[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines)


def main(args: argparse.Namespace) -> int:
    """Run every benchmark, print the tables, write the report."""
    repeats = 2 if args.quick else args.repeats
    if repeats < 1:
        raise ValueError(f"repeats = {repeats!r}; must be >= 1")
    results: dict[str, object] = {"machine": {"cpus": os.cpu_count(),
                                              "mujoco": mujoco.__version__}}
    print("stepping speed ...", file=sys.stderr, flush=True)
    speed = {r: step_speed(r, repeats) for r in ROBOTS if r != "disc_free"}
    results["speed"] = speed
    print("accuracy against timestep ...", file=sys.stderr, flush=True)
    accuracy = {r: accuracy_vs_timestep(r, repeats) for r in ACCURACY_SCENARIOS}
    results["accuracy"] = accuracy
    print("peer model ...", file=sys.stderr, flush=True)
    trials = standard_trials()
    if args.quick:
        trials = [t for t in trials if t.name in ("translate   0°", "rotate", "translate+rotate")]
    results["peer"] = peer_side_by_side(trials)
    print("rendering ...", file=sys.stderr, flush=True)
    results["render"] = render_fps(repeats)
    print("wmr validate ...", file=sys.stderr, flush=True)
    results["validate_wall_s"] = validate_wall_time()
    results["validation_engines_s"] = validation_engines()

    sp = _md_table(["robot", "timestep", "mj_step loop steps/s", "real-time ×",
                    "rollout 1 thread steps/s", f"rollout {next(iter(speed.values()))['threads']} "
                    "threads steps/s", "thread speedup"],
                   [[r, f"{v['timestep'] * 1e3:g} ms", f"{v['loop_steps_per_s']:,.0f}",
                     f"{v['loop_rtf']:.0f}×", f"{v['rollout1_steps_per_s']:,.0f}",
                     f"{v['rolloutN_steps_per_s']:,.0f}", f"{v['rollout_speedup']:.2f}×"]
                    for r, v in speed.items()])
    acc = _md_table(["robot", "scenario", "timestep", "final position error % of path",
                     "real-time ×"],
                    [[r, ACCURACY_SCENARIOS[r],
                      f"{row['timestep'] * 1e3:g} ms" + (" (default)" if row["default"] else ""),
                      f"{row['position_error_pct']:.3f}", f"{row['rtf']:.0f}×"]
                     for r, rows in accuracy.items() for row in rows])
    peer = _md_table(["model", "worst position error % of path", "worst heading error °",
                      "real-time ×"],
                     [[p["label"], f"{p['worst_position_pct']:.3f}",
                       f"{p['worst_heading_deg']:.2f}", f"{p['real_time_factor']:.0f}×"]
                      for p in results["peer"]])
    ren = results["render"]
    text = "\n\n".join([
        "# Benchmarks", f"`wmr bench` on {os.cpu_count()} cores, MuJoCo {mujoco.__version__}; "
        f"medians of {repeats} repeats.", "## Stepping speed (default settings)", sp,
        "## Accuracy against cost", acc, f"## Omni robot and the peer model ({len(trials)} "
        "open-loop trials, same run)", peer, "## Rendering, 640×480",
        f"{ren['no_shadows']:.1f} frames/s as `wmr render` draws (no shadows or "
        f"reflections), {ren['shadows']:.1f} with shadows and reflections "
        f"({ren['backend']} backend; omni3, the scene with the most geoms).", "## Validation",
        f"Whole `wmr validate`: {results['validate_wall_s']:.1f} s wall time. All "
        f"scenarios without the report: {results['validation_engines_s']['rollout']:.1f} s "
        "through batched `mujoco.rollout` (one threaded rollout per robot and actuation "
        f"mode), {results['validation_engines_s']['loop']:.1f} s through a Python `mj_step` "
        "loop, with identical metrics (tested)."]) + "\n"
    print(text)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    write_text_atomic(out / "bench.json", json.dumps(results, indent=2, default=float))
    write_text_atomic(out / "bench.md", text)
    print(f"wrote {out / 'bench.md'}", file=sys.stderr)
    return 0
