"""Wheels on the floor, per robot: off-floor share, penetration and cost (issue 24 § 3).

``python -m wmr_mujoco.bench.floor_study [--quick] [--no-write]`` runs, for every robot
with a kinematic adapter, the two input families of :mod:`wmr_mujoco.bench.floor_runs`
(steps from rest, read over their first 0.1 s; seeded random stepped inputs, a new input
every 0.1 s) and prints, and pastes between the ``floor contact`` markers of
``docs/floor-contact.md``:

* the share of wheel samples with no floor contact after the steps (mean over the draws
  and the worst draw) and over the random runs (the worst run);
* the deepest penetration of a wheel into the floor over every run;
* the real-time factor of bare ``mj_step`` loops on the random inputs, one thread, at the
  robot's timestep and at 2× and 4× it (the same model with ``opt.timestep`` scaled;
  MuJoCo keeps each contact's time constant at least twice the step), the settings timed
  in alternating rounds of one run, median of the rounds.

Robots with a ``floor_impedance`` parameter off by default (omni3, mecanum4) get a second
row with the disc's remedy (:func:`~wmr_mujoco.models.builders.common.sliding_pair_kwargs`)
at :data:`REMEDY_IMPEDANCE`, at the longest step whose
contact rests within the depth bound (:func:`remedy_timestep`). ``--quick`` judges fewer draws and
shorter runs, and its table says so.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.bench.floor_runs import (
    STATE,
    STEP_WINDOW,
    Settled,
    command_bounds,
    floor_figures,
    settled,
)
from wmr_mujoco.docs_sync.markers import fixed, publish, study_parser
from wmr_mujoco.models.builders.common import SLIDING_STEPS, sliding_impratio
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.models.paths import REPO_ROOT
from wmr_mujoco.robots import ROBOTS, get_spec
from wmr_mujoco.sim.stepped_inputs import CONTROL_PERIOD, random_steps
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy
from wmr_mujoco.validation.scenarios import ScenarioKind

DOC = REPO_ROOT / "docs" / "floor-contact.md"
MARKER = "floor contact"
#: Bounds of issue 24 § 3: off-floor share after a step and over random steps, and depth.
STEP_BOUND_PCT = 1.0
RANDOM_BOUND_PCT = 0.1
DEPTH_BOUND_MM = 0.5
#: The remedy's impedance: the disc's. Its push ``μ d s/Δt`` stays under g up to a slip of
#: ``g Δt/(μ d)``, above the largest slip a wheel at its rate limit can have against a
#: platform at full speed the other way, ``2 r ω_max`` (docs/floor-contact.md).
REMEDY_IMPEDANCE = 0.001
#: Gravity, m/s².
GRAVITY = 9.81
#: Grid of the remedy's timestep, s.
STEP_GRID = 0.0005
#: Timestep multiples timed.
STEP_FACTORS = (1, 2, 4)


@dataclass(frozen=True)
class Draws:
    """How many draws a run judges."""

    steps: int
    seeds: tuple[int, ...]
    duration: float
    timed: float
    rounds: int


FULL = Draws(steps=20, seeds=(1, 2, 3), duration=10.0, timed=2.0, rounds=3)
QUICK = Draws(steps=5, seeds=(1,), duration=2.0, timed=0.5, rounds=1)


def _kinematic_robots() -> list[str]:
    return [r for r in ROBOTS
            if ScenarioKind.KINEMATIC in get_spec(r).adapters
            and any(s.kind is ScenarioKind.KINEMATIC and not s.world_frame
                    for s in get_spec(r).scenarios)]


def _settings(robot: str) -> list[tuple[str, RobotParams | None]]:
    spec = get_spec(robot)
    out: list[tuple[str, RobotParams | None]] = [("default", None)]
    ptype = spec.params_type
    # A row with the remedy where the robot has it as an option, off by default.
    defaults = ({f.name: f.default for f in dataclasses.fields(ptype)}
                if ptype is not None else {})
    if defaults.get("floor_impedance") == 0.0:
        sim = defaults["sim"]
        dt = remedy_timestep(sim.timestep)
        params = ptype(floor_impedance=REMEDY_IMPEDANCE,
                       sim=dataclasses.replace(sim, timestep=dt,
                                               contact_timeconst=SLIDING_STEPS * dt))
        out.append((f"floor pairs d={REMEDY_IMPEDANCE:g}, impratio "
                    f"{sliding_impratio(REMEDY_IMPEDANCE):g}, "
                    f"step {1e3 * dt:g} ms, t_c {1e3 * SLIDING_STEPS * dt:g} ms", params))
    return out


def remedy_timestep(timestep: float) -> float:
    """The longest step (0.5 ms grid, at most ``timestep``) whose sliding pair rests in bound.

    The remedy's contact rests ``(1 − d) g t_c²`` deep with ``t_c`` =
    :data:`~wmr_mujoco.models.builders.common.SLIDING_STEPS` ``· Δt``, so
    ``Δt ≤ √(depth / ((1 − d) g)) / SLIDING_STEPS``.
    """
    bound = math.sqrt(DEPTH_BOUND_MM * 1e-3 / ((1.0 - REMEDY_IMPEDANCE) * GRAVITY))
    longest = bound / SLIDING_STEPS
    return min(timestep, math.floor(longest / STEP_GRID) * STEP_GRID)


def _loop(run: Settled, inputs: np.ndarray, factor: int, seconds: float) -> float:
    """Wall time, s, of ``seconds`` of the run of ``drive`` at ``factor`` × the step.

    The same controls as :func:`~wmr_mujoco.bench.floor_runs.drive`, without its reading.

    Raises:
        SimulationDivergedError: the run diverged.
    """
    m, ad = run.model, run.adapter
    d = mujoco.MjData(m)  # fresh: nothing of an earlier (diverged) run carries over
    base = m.opt.timestep
    m.opt.timestep = factor * base
    try:
        mujoco.mj_setState(m, d, run.state, STATE)
        mujoco.mj_forward(m, d)
        per = max(1, round(CONTROL_PERIOD / m.opt.timestep))
        start = time.perf_counter()
        for u in inputs[:round(seconds / CONTROL_PERIOD)]:
            d.ctrl[:] = ad.controls(u, np.asarray(ad.sim_state(m, d), float))
            for _ in range(per):
                mujoco.mj_step(m, d)
        wall = time.perf_counter() - start
        check_healthy(m, d)
        return wall
    finally:
        m.opt.timestep = base


def real_time_factors(robot: str, params: RobotParams | None, draws: Draws,
                      factors: Sequence[int] = STEP_FACTORS) -> list[float]:
    """Real-time factor at each timestep multiple (NaN where the run diverged)."""
    run = settled(robot, params)
    inputs = random_steps(command_bounds(robot), draws.timed, draws.seeds[0])
    walls: dict[int, list[float]] = {f: [] for f in factors}
    for _ in range(draws.rounds):
        for f in factors:
            if walls[f] and not np.isfinite(walls[f][0]):
                continue
            try:
                walls[f].append(_loop(run, inputs, f, draws.timed))
            except SimulationDivergedError:
                walls[f].append(float("nan"))
    return [draws.timed / float(np.median(walls[f])) for f in factors]


def collision_cost(rounds: int = 5, calls: int = 2000) -> tuple[float, float]:
    """omni3's ``mj_collision`` time per call, µs: contact bits (default), plain pairs.

    Both models settled 0.5 s at rest; the pairs are the collision class's contact
    (``floor_pairs(plain=True)``, the same physics), timed in alternating rounds.
    """
    from wmr_mujoco.lookup import build_scene, load
    from wmr_mujoco.models.builders import common
    from wmr_mujoco.robots.omni3 import builder
    from wmr_mujoco.robots.omni3.params import OmniParams

    root = build_scene("omni3")
    builder.floor_pairs(root, OmniParams(), plain=True)
    root.default.find("default", "roller").geom.conaffinity = 0
    models = [load("omni3"), mujoco.MjModel.from_xml_string(common.to_xml(root))]
    datas = []
    for m in models:
        d = mujoco.MjData(m)
        for _ in range(500):
            mujoco.mj_step(m, d)
        datas.append(d)
    times: list[list[float]] = [[], []]
    for _ in range(rounds):
        for k, (m, d) in enumerate(zip(models, datas, strict=True)):
            start = time.perf_counter()
            for _ in range(calls):
                mujoco.mj_collision(m, d)
            times[k].append((time.perf_counter() - start) / calls * 1e6)
    return float(np.median(times[0])), float(np.median(times[1]))


def rows(draws: Draws, robots: Sequence[str] | None = None) -> list[dict[str, object]]:
    """One row per robot and setting (see the module docstring)."""
    out = []
    for robot in robots or _kinematic_robots():
        for label, params in _settings(robot):
            row: dict[str, object] = {"robot": robot, "setting": label}
            try:
                f = floor_figures(robot, draws.steps, draws.seeds, params=params,
                                  random_duration=draws.duration)
            except SimulationDivergedError as err:
                row["diverged"] = str(err)
                out.append(row)
                continue
            row.update(wheels=len(f.wheels), step_mean=100 * f.steps.off_floor_share,
                       step_worst=100 * f.step_worst, random_worst=100 * f.random_worst,
                       depth_mm=1e3 * f.max_depth,
                       rtf=real_time_factors(robot, params, draws))
            out.append(row)
            print(f"{robot} [{label}]: done", flush=True)
    return out


def table(results: list[dict[str, object]], draws: Draws, quick: bool) -> str:
    """The markdown table of :func:`rows`."""
    head = [f"{'QUICK run (fewer draws, shorter runs): ' if quick else ''}"
            f"{draws.steps} steps from rest (off-floor read over their first "
            f"{STEP_WINDOW:g} s), {len(draws.seeds)} random stepped run(s) of "
            f"{draws.duration:g} s (a new input every {CONTROL_PERIOD:g} s); bounds: "
            f"≤ {STEP_BOUND_PCT:g} % after steps, ≤ {RANDOM_BOUND_PCT:g} % over random "
            f"steps, ≤ {DEPTH_BOUND_MM:g} mm.", "",
            "| robot | setting | wheels | off floor after steps, mean / worst % "
            "| off floor, random steps, worst % | deepest mm "
            + "".join(f"| real-time factor ×{f} step " for f in STEP_FACTORS) + "|",
            "|---" * (5 + len(STEP_FACTORS)) + "|"]
    for r in results:
        if "diverged" in r:
            head.append(f"| {r['robot']} | {r['setting']} | diverged: {r['diverged']} |"
                        + " |" * (2 + len(STEP_FACTORS)))
            continue
        rtf = "".join(f"| {'diverged' if not np.isfinite(x) else f'{x:.0f}×'} "
                      for x in r["rtf"])  # type: ignore[attr-defined]
        head.append(f"| {r['robot']} | {r['setting']} | {r['wheels']} "
                    f"| {fixed(r['step_mean'])} / {fixed(r['step_worst'])} "  # type: ignore[arg-type]
                    f"| {fixed(r['random_worst'], 3)} | {fixed(r['depth_mm'], 3)} {rtf}|")  # type: ignore[arg-type]
    return "\n".join(head)


def main(argv: list[str] | None = None) -> None:
    """Command line: print the table and paste it into ``docs/floor-contact.md``."""
    parser = study_parser(__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help="fewer draws and shorter runs (labelled in the table)")
    parser.add_argument("robots", nargs="*", help="robots (default: every robot with a "
                                                  "kinematic adapter)")
    args = parser.parse_args(argv)
    for r in args.robots:
        get_spec(r)  # an unknown name fails here, before any run
    draws = QUICK if args.quick else FULL
    text = table(rows(draws, args.robots or None), draws, args.quick)
    bits, pairs = collision_cost(rounds=draws.rounds + 2)
    text += (f"\n\nomni3's collision (`mj_collision`, one thread, median of alternating "
             f"rounds): contact bits {bits:.1f} µs, explicit roller-floor pairs "
             f"{pairs:.1f} µs per step ({bits / pairs:.1f}× less).")
    publish(Path(DOC), {MARKER: text}, not args.no_write and not args.robots)


if __name__ == "__main__":
    main()
