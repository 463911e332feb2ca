"""What MuJoCo's constraint-island discovery costs a robot, and that it changes nothing.

``python -m wmr_mujoco.bench.island_cost [--quick] [--write] [robots ...]`` times, for
every robot the random-steps family drives (default) or those named, its default model
(islands off, :func:`wmr_mujoco.models.builders.common.new_root`) against the same model
with island discovery on (MuJoCo's default since 3.3.6, ``mjDSBL_ISLAND`` cleared): a bare
one-thread ``mj_step`` loop over member 0 of the random-steps family after the settle
(:func:`~wmr_mujoco.bench.default_speed.prepare_timed`), in CPU time, the two taking turns
within each round; the figure is the median over the rounds of the ratio within a round,
so that a load that changes between rounds cancels out.

A robot is one kinematic tree whose chassis every contact and joint limit acts on, so
discovery can only find one island, the whole constraint set, and the solver then solves
the same problem. Each timed run also compares the two final states byte for byte:
``identical`` says the trajectories are the same to the bit. ``--write`` pastes the table
between the ``island cost`` markers of ``docs/benchmarks.md``.
"""

from __future__ import annotations

import argparse
import copy
import dataclasses
import time
from collections.abc import Sequence

import mujoco
import numpy as np

from wmr_mujoco.bench.default_speed import (
    FULL,
    QUICK,
    Rounds,
    Timed,
    chosen,
    prepare_timed,
    wall_seconds,
)
from wmr_mujoco.docs_sync.markers import replace_between
from wmr_mujoco.models.paths import DOCS_DIR
from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.stepped_inputs import CONTROL_PERIOD

DOC = DOCS_DIR / "benchmarks.md"
MARKER = "island cost"
_ISLAND = int(mujoco.mjtDisableBit.mjDSBL_ISLAND)
_STATE = mujoco.mjtState.mjSTATE_INTEGRATION


@dataclasses.dataclass(frozen=True)
class IslandCost:
    """One robot's timing.

    Attributes:
        robot: its name.
        rtf_off: real-time factor with islands off (the default), median of rounds.
        rtf_on: the same with island discovery on.
        ratio: median over rounds of (time off / time on) within a round.
        identical: the final states of both runs equal byte for byte.
    """

    robot: str
    rtf_off: float
    rtf_on: float
    ratio: float
    identical: bool


def with_islands(t: Timed) -> Timed:
    """The same prepared run on a copy of its model with island discovery on."""
    model = copy.copy(t.model)
    model.opt.disableflags &= ~_ISLAND
    return Timed(model, mujoco.MjData(model), t.state.copy(), t.controls)


def run(t: Timed) -> tuple[float, np.ndarray]:
    """CPU seconds of the prepared run in a bare ``mj_step`` loop, and its final state.

    The loop is :func:`~wmr_mujoco.bench.default_speed.wall_seconds` on the CPU clock.
    """
    cpu = wall_seconds(t, time.process_time)
    state = np.empty(mujoco.mj_stateSize(t.model, _STATE))
    mujoco.mj_getState(t.model, t.data, state, _STATE)
    return cpu, state


def measure(robot: str, how: Rounds) -> IslandCost:
    """Time ``robot``'s default model with islands off and on (see the module docstring).

    Raises:
        ValueError: the default model has island discovery on (nothing to compare).
    """
    off = prepare_timed(get_spec(robot), None, how.seconds)
    if not off.model.opt.disableflags & _ISLAND:
        raise ValueError(f"robot {robot!r}: its model has island discovery on")
    on = with_islands(off)
    times: list[tuple[float, float]] = []
    identical = True
    for _ in range(how.rounds):
        t_off, s_off = run(off)
        t_on, s_on = run(on)
        times.append((t_off, t_on))
        identical &= s_off.tobytes() == s_on.tobytes()
    simulated = len(off.controls) * CONTROL_PERIOD
    arr = np.array(times)
    return IslandCost(robot, simulated / float(np.median(arr[:, 0])),
                      simulated / float(np.median(arr[:, 1])),
                      float(np.median(arr[:, 0] / arr[:, 1])), identical)


def table(results: Sequence[IslandCost], how: Rounds) -> str:
    """Markdown table of :func:`measure`'s results."""
    lines = [f"`python -m wmr_mujoco.bench.island_cost`: one-thread `mj_step` loop, CPU "
             f"time, {how.seconds:g} s of the random-steps family's member 0, "
             f"{how.rounds} rounds, islands off and on taking turns.", "",
             "| robot | × real time, islands off (default) | × real time, islands on "
             "| cost ratio off/on (median of rounds) | final state |",
             "|---|---|---|---|---|"]
    for r in results:
        lines.append(f"| {r.robot} | {r.rtf_off:.0f}× | {r.rtf_on:.0f}× | {r.ratio:.3f} | "
                     f"{'identical to the bit' if r.identical else 'DIFFERS'} |")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:
    """Command line: print (and with ``--write`` publish) the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="1 s runs, 2 rounds")
    parser.add_argument("--write", action="store_true",
                        help=f"paste the table into {DOC.name} ({MARKER!r} markers)")
    parser.add_argument("robots", nargs="*", help="robots (default: every drivable robot)")
    args = parser.parse_args(argv)
    if args.write and args.robots:
        parser.error("--write publishes every robot's row: leave the robots out")
    robots = chosen(parser, args.robots)
    how = QUICK if args.quick else FULL
    results = []
    for name in robots:
        results.append(measure(name, how))
        print(f"{name}: done", flush=True)
    text = table(results, how)
    print(text)
    if args.write:
        replace_between(DOC, MARKER, text)
        print(f"wrote {DOC}")


if __name__ == "__main__":
    main()
