"""CPU cost of a run's measurement: ``python -m wmr_mujoco.bench.measure_cost``.

Each scenario named (``robot`` or ``robot/scenario``; a robot alone: its first kinematic
scenario) is prepared and simulated once, at its nominal values; then its measurement
(:func:`~wmr_mujoco.validation.runner.measure_metrics`: the rebuilt steps, the probes,
the poses, the judge) is timed ``--repeat`` times on the same states, in process CPU time
(``time.process_time``: the measurement is one thread), and the median and the least are
printed. What the per-sample code of the probes and adapters costs, apart from the
simulation; run it on two checkouts to compare. Prints only; nothing is written.
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Sequence

from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.engine import simulate
from wmr_mujoco.validation.runner import measure_metrics, prepare
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.traces import Trace

#: Scenarios timed by default: the omni, mecanum and tricycle families' measured runs.
DEFAULT = ("omni3/square with rotation", "omni3/translate+rotate", "omni3_reduced",
           "mecanum4", "tricycle")


def _scenario(name: str) -> tuple[str, Scenario]:
    """The robot and scenario a ``robot[/scenario]`` name stands for."""
    robot, _, scenario = name.partition("/")
    spec = get_spec(robot)
    if scenario:
        chosen = spec.scenario(scenario)
        if chosen.kind is ScenarioKind.MEASUREMENT:
            raise ValueError(f"{robot}/{chosen.name} is a measurement scenario (its own "
                             "evaluation, no rebuilt steps): name a kinematic or dynamic one")
        return robot, chosen
    kinematic = [s for s in spec.scenarios if s.kind is ScenarioKind.KINEMATIC]
    if not kinematic:
        raise ValueError(f"robot {robot!r} has no kinematic scenario; name one as "
                         f"{robot}/<scenario>")
    return robot, kinematic[0]


def measure_seconds(robot: str, scenario: Scenario, repeat: int) -> list[float]:
    """CPU seconds of each of ``repeat`` measurements of one simulated run."""
    spec = get_spec(robot)
    prep = prepare(spec, scenario)
    states = simulate(prep.model, prep.data, prep.controls)
    out = []
    for _ in range(repeat):
        start = time.process_time()
        measure_metrics(prep, states, Trace())
        out.append(time.process_time() - start)
    return out


def main(argv: Sequence[str] | None = None) -> None:
    """Print each scenario's median and least measurement CPU time, ms."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenarios", nargs="*", default=list(DEFAULT),
                        help="robot or robot/scenario (default: %(default)s)")
    parser.add_argument("--repeat", type=int, default=7, help="timed measurements each")
    args = parser.parse_args(argv)
    if args.repeat < 1:
        parser.error(f"--repeat {args.repeat}: must be at least 1")
    chosen = []
    for name in args.scenarios:
        try:
            chosen.append(_scenario(name))
        except (KeyError, ValueError) as err:
            parser.error(str(err))
    for robot, scenario in chosen:
        times = measure_seconds(robot, scenario, args.repeat)
        print(f"{robot}/{scenario.name}: measurement CPU median "
              f"{1e3 * statistics.median(times):.0f} ms, least {1e3 * min(times):.0f} ms "
              f"({args.repeat} runs)", flush=True)


if __name__ == "__main__":
    main()
