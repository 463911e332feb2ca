"""Wheels on the floor, per robot: off-floor share, penetration and cost (issue 24 § 3).

``python -m wmr_mujoco.bench.floor_study [--quick] [--no-write]`` runs, for every robot
the family drives, the members of the random-steps family
(:mod:`wmr_mujoco.validation.floor_family`: seeded random stepped commands, the first
a step from rest, the wheel phase drawn) for seeds 0 and 1, and prints, and pastes
between the ``floor contact`` markers of ``docs/floor-contact.md``, the family's judged
metrics (median and worst over the members):

* the share of wheel samples with no floor contact in the first 0.1 s after the step from
  rest, and over the whole run;
* the deepest penetration of a wheel into the floor;
* the real-time factor (simulated time over this process's CPU time) of bare ``mj_step``
  loops on random inputs, one thread, at the robot's timestep and at 2× and 4× it (the
  same model with ``opt.timestep`` scaled; MuJoCo keeps each contact's time constant at
  least twice the step), the settings timed in alternating rounds of one run, median of
  the rounds.

Each robot gets a row at its defaults and, where they differ, one at main's defaults
before issue 24 § 4 (:data:`~wmr_mujoco.bench.default_speed.PREVIOUS_DEFAULTS`: contact
bits, the older timesteps). ``--quick`` judges fewer draws and shorter runs, and its table
says so.
"""

from __future__ import annotations

import dataclasses
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
    settled,
)
from wmr_mujoco.docs_sync.markers import fixed, publish, study_parser
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.models.paths import REPO_ROOT
from wmr_mujoco.robots import ROBOTS, get_spec
from wmr_mujoco.sim.stepped_inputs import CONTROL_PERIOD, random_steps
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy
from wmr_mujoco.validation import floor_family

DOC = REPO_ROOT / "docs" / "floor-contact.md"
MARKER = "floor contact"
#: Bounds of issue 24 § 3: off-floor share after a step and over random steps, and depth.
STEP_BOUND_PCT = 1.0
RANDOM_BOUND_PCT = 0.1
DEPTH_BOUND_MM = 0.5
#: Timestep multiples timed.
STEP_FACTORS = (1, 2, 4)


@dataclass(frozen=True)
class Draws:
    """How many draws a run judges: ``draws`` members per seed of ``seeds``."""

    draws: int
    seeds: tuple[int, ...]
    duration: float
    timed: float
    rounds: int


FULL = Draws(draws=floor_family.DRAWS, seeds=(0, 1), duration=floor_family.DURATION,
             timed=2.0, rounds=3)
QUICK = Draws(draws=3, seeds=(0,), duration=2.0, timed=0.5, rounds=1)


def _kinematic_robots() -> list[str]:
    return [r for r in ROBOTS if floor_family.applies(get_spec(r))]


def family_figures(robot: str, params: RobotParams | None, draws: Draws) -> np.ndarray:
    """(members, 4) judged metrics of the random-steps family's members.

    Per member: off-floor share after the step from rest, %; over the run, %; deepest
    penetration, mm; largest chassis tilt, deg (reported).

    Raises:
        SimulationDivergedError: a member diverged.
    """
    spec = get_spec(robot)
    nominal = dataclasses.replace(spec.scenario(floor_family.NAME), duration=draws.duration)
    assert nominal.family is not None
    members = [nominal.member(d) for seed in draws.seeds
               for d in nominal.family.sample(seed, nominal.key, draws.draws)]
    return np.array([[m.value for m in floor_family.measure(spec, member, params).metrics]
                     for member in members])


def _settings(robot: str) -> list[tuple[str, RobotParams | None]]:
    """The robot's defaults, and main's previous defaults where they differ."""
    from wmr_mujoco.bench.default_speed import previous

    out: list[tuple[str, RobotParams | None]] = [("default", None)]
    before = previous(get_spec(robot))
    if before is not None and before != get_spec(robot).params_type():
        out.append(("previous default", before))
    return out


def _loop(run: Settled, inputs: np.ndarray, factor: int, seconds: float) -> float:
    """CPU time of this process, s, of ``seconds`` of the run of ``drive`` at ``factor`` × the step.

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
        start = time.process_time()  # CPU time: a shared machine's load is not counted
        for u in inputs[:round(seconds / CONTROL_PERIOD)]:
            d.ctrl[:] = ad.controls(u, np.asarray(ad.sim_state(m, d), float))
            for _ in range(per):
                mujoco.mj_step(m, d)
        cpu = time.process_time() - start
        check_healthy(m, d)
        return cpu
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
    """omni3's ``mj_collision`` time per call, µs: contact bits, plain explicit pairs.

    Both models settled 0.5 s at rest; the pairs are the collision class's contact
    (``floor_pairs(plain=True)``, the same physics), timed in alternating rounds in this
    process's CPU time (``time.process_time``), the clock of the table's other columns
    (:func:`_loop`): a shared machine's load is not counted.
    """
    from wmr_mujoco.lookup import build_scene, load
    from wmr_mujoco.models.builders import common
    from wmr_mujoco.robots.omni3 import builder
    from wmr_mujoco.robots.omni3.params import OmniParams

    bits = OmniParams(floor_impedance=0.0)
    root = build_scene("omni3", bits)
    builder.floor_pairs(root, bits, plain=True)
    root.default.find("default", "roller").geom.conaffinity = 0
    models = [load("omni3", bits), mujoco.MjModel.from_xml_string(common.to_xml(root))]
    datas = []
    for m in models:
        d = mujoco.MjData(m)
        for _ in range(500):
            mujoco.mj_step(m, d)
        datas.append(d)
    times: list[list[float]] = [[], []]
    for _ in range(rounds):
        for k, (m, d) in enumerate(zip(models, datas, strict=True)):
            start = time.process_time()
            for _ in range(calls):
                mujoco.mj_collision(m, d)
            times[k].append((time.process_time() - start) / calls * 1e6)
    return float(np.median(times[0])), float(np.median(times[1]))


def rows(draws: Draws, robots: Sequence[str] | None = None) -> list[dict[str, object]]:
    """One row per robot and setting (see the module docstring)."""
    out = []
    for robot in robots or _kinematic_robots():
        for label, params in _settings(robot):
            row: dict[str, object] = {"robot": robot, "setting": label,
                                      "params": _describe(params, robot)}
            try:
                f = family_figures(robot, params, draws)
            except SimulationDivergedError as err:
                row["diverged"] = str(err)
                out.append(row)
                continue
            row.update(median=np.median(f, axis=0), worst=f.max(axis=0), members=len(f),
                       rtf=real_time_factors(robot, params, draws))
            out.append(row)
            print(f"{robot} [{label}]: done", flush=True)
    return out


def _describe(params: RobotParams | None, robot: str) -> str:
    from wmr_mujoco.bench.default_speed import describe

    return describe(params if params is not None else get_spec(robot).params_type())


def table(results: list[dict[str, object]], draws: Draws, quick: bool) -> str:
    """The markdown table of :func:`rows`."""
    head = [f"{'QUICK run (fewer draws, shorter runs): ' if quick else ''}"
            f"{draws.draws} members of the random-steps family for each seed of "
            f"{', '.join(map(str, draws.seeds))}, {draws.duration:g} s each (a new command "
            f"every {CONTROL_PERIOD:g} s, the first a step from rest); median / worst over "
            f"the members. Requirements (issue 24 § 3): ≤ {STEP_BOUND_PCT:g} % in the first "
            f"{STEP_WINDOW:g} s after the step, ≤ {RANDOM_BOUND_PCT:g} % over the run, "
            f"≤ {DEPTH_BOUND_MM:g} mm.", "",
            "| robot | setting | off floor after the step, % | off floor over the run, % "
            "| deepest, mm | chassis tilt, deg "
            + "".join(f"| real-time factor ×{f} step " for f in STEP_FACTORS) + "|",
            "|---" * (6 + len(STEP_FACTORS)) + "|"]
    for r in results:
        setting = f"{r['setting']}: {r['params']}"
        if "diverged" in r:
            head.append(f"| {r['robot']} | {setting} | diverged: {r['diverged']} |"
                        + " |" * (3 + len(STEP_FACTORS)))
            continue
        med, worst = r["median"], r["worst"]
        rtf = "".join(f"| {'diverged' if not np.isfinite(x) else f'{x:.0f}×'} "
                      for x in r["rtf"])  # type: ignore[attr-defined]
        cells = [f"{fixed(med[k], n)} / {fixed(worst[k], n)}"  # type: ignore[index]
                 for k, n in ((0, 2), (1, 3), (2, 3), (3, 1))]
        head.append(f"| {r['robot']} | {setting} | " + " | ".join(cells) + f" {rtf}|")
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
    text += (f"\n\nomni3's collision (`mj_collision`, one thread, CPU time, median of "
             f"alternating rounds): contact bits {bits:.1f} µs, explicit roller-floor pairs "
             f"{pairs:.1f} µs per step ({bits / pairs:.1f}× less).")
    publish(Path(DOC), {MARKER: text}, not args.no_write and not args.robots)


if __name__ == "__main__":
    main()
