"""Each robot's real-time factor at its default settings, beside the peer (issue 24 § 4).

``python -m wmr_mujoco.bench.default_speed [--quick] [robots ...]`` prints, for every
robot the random-steps family drives (:mod:`wmr_mujoco.validation.floor_family`):

* the real-time factor of a bare one-thread ``mj_step`` loop at the robot's defaults on
  one run of the family (seed 0: a step from rest, then a new command every 0.1 s),
  after the 0.5 s settle;
* the same at :data:`PREVIOUS_DEFAULTS`, the settings main shipped before issue 24 § 4
  (contact bits or the collision class's floor pairs, and the timesteps then), and the
  ratio of the two; both settings timed in alternating rounds of one run, median of the
  rounds;
* for a robot with a peer (its registry entry's ``peer``): the robot at its defaults and
  the peer model on the same open-loop trials, in the same run, and their ratio
  (:mod:`wmr_mujoco.bench.bench`'s peer table).

The speed goals of issue 24 § 4 are printed beside the figures: ≥ 100× real time for
every robot, and ≥ 5× the peer's speed for a robot with a peer.
"""

from __future__ import annotations

import argparse
import dataclasses
import time
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import set_actuation_mode
from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import ROBOTS, get_spec
from wmr_mujoco.robots.roller_wheels.trials import find_peer
from wmr_mujoco.robots.spec import RobotSpec
from wmr_mujoco.sim.stepped_inputs import CONTROL_PERIOD
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy
from wmr_mujoco.validation import floor_family
from wmr_mujoco.validation.scenarios import ScenarioKind

#: Speed goals of issue 24 § 4.
RTF_GOAL = 100.0
PEER_GOAL = 5.0

#: main's defaults before issue 24 § 4 (commit f5c9b14), as overrides of today's: a
#: record to compare with, not a setting of any robot. Keys are parameter fields,
#: ``sim.<field>`` those of :class:`~wmr_mujoco.models.params.SimParams`.
PREVIOUS_DEFAULTS: Mapping[str, Mapping[str, float | str]] = {
    "disc": {"sim.timestep": 0.002, "sim.contact_timeconst": 0.004},
    "bicycle": {"sim.timestep": 0.002, "sim.contact_timeconst": 0.004,
                "sim.floor_impedance": 0.0},
    "tricycle": {"sim.timestep": 0.002, "sim.contact_timeconst": 0.004,
                 "sim.floor_impedance": 0.0},
    "omni3": {"floor_impedance": 0.0, "sim.timestep": 0.001, "sim.contact_timeconst": 0.002,
              "jacobian": "auto"},
    "omni3_reduced": {"floor_impedance": 0.0, "sim.timestep": 0.001,
                      "sim.contact_timeconst": 0.002},
    "mecanum4": {"floor_impedance": 0.0, "sim.timestep": 0.004,
                 "sim.contact_timeconst": 0.008},
    "diffdrive": {"sim.timestep": 0.002, "sim.contact_timeconst": 0.004,
                  "sim.floor_impedance": 0.0},
    "single_steer": {"sim.timestep": 0.002, "sim.contact_timeconst": 0.004,
                     "sim.floor_impedance": 0.0},
    "double_steer": {"sim.timestep": 0.002, "sim.floor_impedance": 0.0},
}


@dataclasses.dataclass(frozen=True)
class Rounds:
    """How long and how often each setting is timed."""

    seconds: float
    rounds: int


FULL = Rounds(seconds=3.0, rounds=5)
QUICK = Rounds(seconds=1.0, rounds=2)


def previous(spec: RobotSpec) -> RobotParams | None:
    """The robot's parameters at :data:`PREVIOUS_DEFAULTS` (None: no record)."""
    changes = PREVIOUS_DEFAULTS.get(spec.name)
    if changes is None or spec.params_type is None:
        return None
    params: Any = spec.params_type()
    sim = {k.removeprefix("sim."): v for k, v in changes.items() if k.startswith("sim.")}
    top = {k: v for k, v in changes.items() if not k.startswith("sim.")}
    return dataclasses.replace(params, sim=dataclasses.replace(params.sim, **sim), **top)


@dataclasses.dataclass
class Timed:
    """A robot settled at one setting, ready to be timed."""

    model: mujoco.MjModel
    data: mujoco.MjData
    state: np.ndarray
    controls: np.ndarray  # one row per control period


def prepare_timed(spec: RobotSpec, params: RobotParams | None, seconds: float) -> Timed:
    """Load, settle and precompute the controls of the first ``seconds`` of a run.

    The controls are the adapter's for the schedule of member 0 of the family (seed 0)
    read at the settled state (the state-dependent part of a steering adapter is read
    once: the timing does not depend on it).
    """
    model = load(spec, params)
    nominal = floor_family.body_frame_scenario(spec)
    assert nominal is not None
    adapter = spec.adapters[ScenarioKind.KINEMATIC](nominal, model, params)
    if adapter.mode is not None:
        set_actuation_mode(model, adapter.mode)
    data = mujoco.MjData(model)
    for _ in range(round(nominal.settle / model.opt.timestep)):
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    x = np.asarray(adapter.sim_state(model, data), float)
    inputs = floor_family.schedule(floor_family.command_bounds(spec), 0, seconds)
    controls = np.array([adapter.controls(u, x) for u in inputs])
    state = np.empty(mujoco.mj_stateSize(model, mujoco.mjtState.mjSTATE_INTEGRATION))
    mujoco.mj_getState(model, data, state, mujoco.mjtState.mjSTATE_INTEGRATION)
    return Timed(model, data, state, controls)


def wall_seconds(t: Timed, clock: Callable[[], float] = time.perf_counter) -> float:
    """Elapsed time, s, by ``clock`` of the prepared run in a bare one-thread ``mj_step`` loop.

    Args:
        t: the prepared run.
        clock: the timer: wall time by default; ``time.process_time`` for this process's
            CPU time, which other work on a shared machine moves less.
    """
    m, d = t.model, t.data
    mujoco.mj_setState(m, d, t.state, mujoco.mjtState.mjSTATE_INTEGRATION)
    per = max(1, round(CONTROL_PERIOD / m.opt.timestep))
    start = clock()
    for ctrl in t.controls:
        d.ctrl[:] = ctrl
        for _ in range(per):
            mujoco.mj_step(m, d)
    wall = clock() - start
    check_healthy(m, d)
    return wall


def real_time_factors(spec: RobotSpec, settings: Sequence[RobotParams | None],
                      how: Rounds, clock: Callable[[], float] = time.perf_counter,
                      diverged_nan: bool = False) -> list[float]:
    """Real-time factor of each setting, timed in alternating rounds; median of rounds.

    Args:
        spec: the robot.
        settings: its parameters per setting (None: the defaults).
        how: the length of each timed run and the number of rounds.
        clock: the timer (:func:`wall_seconds`).
        diverged_nan: a setting whose settle or drive diverges is NaN and left out of the
            later rounds (a candidate study); False: the divergence raises.

    Raises:
        SimulationDivergedError: a setting diverged and ``diverged_nan`` is False.
    """
    prepared: list[Timed | None] = []
    for p in settings:
        try:
            prepared.append(prepare_timed(spec, p, how.seconds))
        except SimulationDivergedError:
            if not diverged_nan:
                raise
            prepared.append(None)
    walls: list[list[float]] = [[] for _ in settings]
    for _ in range(how.rounds):
        for k, t in enumerate(prepared):
            if t is None:
                continue
            try:
                walls[k].append(wall_seconds(t, clock))
            except SimulationDivergedError:
                if not diverged_nan:
                    raise
                prepared[k], walls[k] = None, []
    return [len(t.controls) * CONTROL_PERIOD / float(np.median(w)) if t is not None and w
            else float("nan") for t, w in zip(prepared, walls, strict=True)]


def describe(params: Any) -> str:
    """``<timestep> ms, <floor contact>`` of a robot's parameters."""
    sim = params.sim
    d = getattr(params, "floor_impedance", sim.floor_impedance)
    zeta = sim.floor_dampratio
    contact = (f"floor pairs d = {d:g}" + (f", ζ = {zeta:g}" if zeta != 1.0 else "")
               if d else "collision class")
    return f"{1e3 * sim.timestep:g} ms, {contact}"


def rows(robots: Sequence[str], how: Rounds) -> list[dict[str, object]]:
    """One row per robot: defaults and previous defaults, their real-time factors."""
    out = []
    for name in robots:
        spec = get_spec(name)
        before = previous(spec)
        if before == spec.params_type():
            before = None  # unchanged: nothing to compare
        settings = [None] if before is None else [None, before]
        rtf = real_time_factors(spec, settings, how)
        out.append({"robot": name, "default": describe(spec.params_type()),
                    "rtf": rtf[0],
                    "previous": None if before is None else describe(before),
                    "rtf_previous": rtf[1] if before is not None else None})
        print(f"{name}: done", flush=True)
    return out


def peer_rows(robots: Sequence[str], quick: bool) -> list[dict[str, object]]:
    """The robot at its defaults beside its peer, same trials, same run."""
    peer = find_peer()
    if peer is None:
        return []
    out = []
    for name in robots:
        spec = get_spec(name)
        if spec.peer is None:
            continue
        ours, theirs = spec.peer(peer.scene, quick)[:2]
        out.append({"robot": name, "peer": str(theirs["label"]),
                    "rtf": float(ours["real_time_factor"]),  # type: ignore[arg-type]
                    "rtf_peer": float(theirs["real_time_factor"])})  # type: ignore[arg-type]
    return out


def table(results: list[dict[str, object]], peers: list[dict[str, object]],
          how: Rounds, quick: bool) -> str:
    """The markdown tables of :func:`rows` and :func:`peer_rows`."""
    lines = [f"{'QUICK run: ' if quick else ''}one-thread `mj_step` loop, {how.seconds:g} s of "
             f"member 0 of the random-steps family after the settle, median of "
             f"{how.rounds} alternating rounds; goal ≥ {RTF_GOAL:g}× real time.", "",
             "| robot | default | real-time × | previous default | real-time × | "
             "cost ratio (previous / default) | goal met |", "|---" * 7 + "|"]
    for r in results:
        rtf = float(r["rtf"])  # type: ignore[arg-type]
        prev = r["rtf_previous"]
        ratio = "" if prev is None else f"{float(prev) / rtf:.2f}"  # type: ignore[arg-type]
        lines.append(f"| {r['robot']} | {r['default']} | {rtf:.0f}× | {r['previous'] or ''} "
                     f"| {'' if prev is None else f'{float(prev):.0f}×'} | {ratio} "  # type: ignore[arg-type]
                     f"| {'yes' if rtf >= RTF_GOAL else 'no'} |")
    if peers:
        lines += ["", f"Beside the peer ({'a few' if quick else 'all'} open-loop trials of "
                      f"`wmr bench`'s peer table, same run); goal ≥ {PEER_GOAL:g}× the peer.",
                  "", "| robot (default) | real-time × | peer | real-time × | ratio | "
                      "goal met |", "|---" * 6 + "|"]
        for p in peers:
            ratio = float(p["rtf"]) / float(p["rtf_peer"])  # type: ignore[arg-type]
            lines.append(f"| {p['robot']} | {float(p['rtf']):.1f}× | {p['peer']} "  # type: ignore[arg-type]
                         f"| {float(p['rtf_peer']):.1f}× | {ratio:.2f} "  # type: ignore[arg-type]
                         f"| {'yes' if ratio >= PEER_GOAL else 'no'} |")
    else:
        lines += ["", "Peer left out: its scene was not found (install mujoco-menagerie, or "
                      "set WMR_PEER_SCENE)."]
    return "\n".join(lines)


def drivable() -> list[str]:
    """Robots the random-steps family drives, in registry order."""
    return [n for n, s in ROBOTS.items() if floor_family.applies(s)]


def chosen(parser: argparse.ArgumentParser, names: Sequence[str]) -> list[str]:
    """The drivable robots a command line names (none: every one), checked before any work.

    Raises:
        ValueError: an unknown name (:func:`~wmr_mujoco.robots.get_spec`'s message).
        SystemExit: through ``parser.error``, a robot the random-steps family does not drive.
    """
    robots = [get_spec(r).name for r in names] or drivable()
    for r in robots:
        if r not in drivable():
            parser.error(f"robot {r!r} is not driven by the random-steps family; valid: "
                         f"{', '.join(drivable())}")
    return robots


def main(argv: list[str] | None = None) -> None:
    """Command line: print the tables."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="shorter, fewer rounds")
    parser.add_argument("robots", nargs="*", help="robots (default: every drivable robot)")
    args = parser.parse_args(argv)
    robots = chosen(parser, args.robots)
    how = QUICK if args.quick else FULL
    print(table(rows(robots, how), peer_rows(robots, args.quick), how, args.quick))


if __name__ == "__main__":
    main()
