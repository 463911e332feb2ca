"""What the stepping API costs: ``robot.step`` against a bare ``mj_step`` loop, per robot.

``python -m wmr_mujoco.bench.drive_overhead [--period 0.02] [--steps 50] [--rounds 7]``
prints one Markdown table: for every drivable robot on the ``"mujoco"`` backend, control
steps per second of

* **bare loop**: per control period, ``data.ctrl`` written once (the controls that
  ``robot.step`` applied in that period, recorded beforehand, so both runs simulate the
  same motion) and ``n = T/Δt`` calls of ``mujoco.mj_step`` in Python, nothing read;
* **robot.step**: :meth:`wmr_mujoco.drive.Robot.step` with the robot's natural command
  (a fifth of its limits): the command checked, turned into controls, the ``n`` timesteps,
  the health check and the :class:`~wmr_mujoco.drive.RobotState` read and recorded;

and their ratio (the median of per-pair ratios, the two timed alternately from the same
settled state), with the kinematic backend's steps per second beside them where the robot
has one. Times are this process's CPU time (``time.process_time``), not wall time: on a
shared machine the other processes' load then does not enter the figures.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Callable, Sequence

import mujoco
import numpy as np


def cpu_time(fn: Callable[[], object]) -> float:
    """CPU time of one call of ``fn``, s."""
    t0 = time.process_time()
    fn()
    return time.process_time() - t0


def paired(slow: Callable[[], object], fast: Callable[[], object], rounds: int
           ) -> tuple[float, float, float]:
    """Median CPU times of ``slow`` and ``fast``, and of their per-pair ratios.

    The two run alternately, after a warm-up each.
    """
    slow()
    fast()
    pairs = np.array([(cpu_time(slow), cpu_time(fast)) for _ in range(rounds)])
    return (float(np.median(pairs[:, 0])), float(np.median(pairs[:, 1])),
            float(np.median(pairs[:, 0] / pairs[:, 1])))


def measure(name: str, period: float, steps: int, rounds: int) -> dict[str, object]:
    """Figures of one robot (module docstring)."""
    from wmr_mujoco.drive import make

    robot = make(name, backend="mujoco", control_period=period)
    robot.reset()
    model, data = robot.model, robot.data
    start = mujoco.MjData(model)
    mujoco.mj_copyData(start, model, data)
    command = 0.2 * robot.command_space.high
    # The controls robot.step applies, period by period: the bare loop replays them, so
    # that both simulate the same motion.
    controls = []
    for _ in range(steps):
        robot.step(command)
        controls.append(data.ctrl.copy())
    bare_data = mujoco.MjData(model)
    n = robot.nstep

    def bare() -> None:
        mujoco.mj_copyData(bare_data, model, start)
        for ctrl in controls:
            bare_data.ctrl[:] = ctrl
            for _ in range(n):
                mujoco.mj_step(model, bare_data)

    def driven() -> None:
        mujoco.mj_copyData(data, model, start)
        for _ in range(steps):
            robot.step(command)

    t_bare, t_robot, ratio = paired(bare, driven, rounds)
    out: dict[str, object] = {"robot": name, "substeps": n, "bare": steps / t_bare,
                              "robot_step": steps / t_robot, "ratio": ratio,
                              "kinematic": None}
    if robot.spec.command.analytic(None) is not None:
        kin = make(name, backend="kinematic", control_period=period)
        kin.reset()

        def analytic() -> None:
            for _ in range(steps):
                kin.step(command)

        analytic()
        out["kinematic"] = steps / float(np.median([cpu_time(analytic)
                                                    for _ in range(rounds)]))
    return out


def table(rows: list[dict[str, object]], period: float) -> str:
    """The Markdown table of :func:`measure`'s rows."""
    lines = [f"`python -m wmr_mujoco.bench.drive_overhead`: control period {period:g} s, "
             f"MuJoCo {mujoco.__version__}; control steps per CPU second, medians; "
             "ratio = robot.step / bare loop (goal >= 0.8).", "",
             "| robot | substeps | bare mj_step loop | robot.step | ratio | kinematic "
             "backend |", "|---|---|---|---|---|---|"]
    for r in rows:
        kin = "-" if r["kinematic"] is None else f"{r['kinematic']:.0f}"
        lines.append(f"| {r['robot']} | {r['substeps']} | {r['bare']:.0f} | "
                     f"{r['robot_step']:.0f} | {r['ratio']:.2f} | {kin} |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    """Measure every drivable robot (or ``--robot``) and print the table."""
    from wmr_mujoco.drive import drivable

    parser = argparse.ArgumentParser(prog="python -m wmr_mujoco.bench.drive_overhead",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--robot", action="append", choices=drivable(),
                        help="robot to measure (repeatable; default: every drivable one)")
    parser.add_argument("--period", type=float, default=0.02, help="control period, s")
    parser.add_argument("--steps", type=int, default=200, help="control steps per run")
    parser.add_argument("--rounds", type=int, default=7, help="timed runs of each")
    args = parser.parse_args(argv)
    if args.steps < 1 or args.rounds < 1 or args.steps > 100_000 or args.rounds > 1000:
        parser.error(f"--steps {args.steps}, --rounds {args.rounds}: use 1..100000 steps "
                     "and 1..1000 rounds")
    try:
        rows = [measure(name, args.period, args.steps, args.rounds)
                for name in args.robot or drivable()]
    except ValueError as err:
        parser.error(str(err))
    print(table(rows, args.period))
    return 0


if __name__ == "__main__":
    sys.exit(main())
