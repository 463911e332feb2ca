"""What the stepping API costs: ``robot.step`` against a bare ``mj_step`` loop, per robot.

``python -m wmr_mujoco.bench.drive_overhead [--period 0.02] [--steps 200] [--rounds 7]
[--mode command|wheels]`` prints one Markdown table: for every drivable robot on the
``"mujoco"`` backend, control steps per second of

* **bare loop**: per control period, ``data.ctrl`` written once (the controls that
  ``robot.step`` applied in that period, recorded beforehand, so both runs simulate the
  same motion) and ``n = T/Δt`` calls of ``mujoco.mj_step`` in Python, nothing read;
* **bare mj_step(n)**: the same, the ``n`` timesteps in one ``mujoco.mj_step(m, d, n)``
  call (the fastest way to hold controls for a period from Python);
* **robot.step**: :meth:`wmr_mujoco.drive.Robot.step` with the robot's natural command
  (a fifth of its limits; ``--mode wheels``: a fifth of the actuators' ranges): the
  command checked, turned into controls, the ``n`` timesteps, the health check and the
  :class:`~wmr_mujoco.drive.RobotState` recorded (its arrays are made when first read);
* **step + read**: ``robot.step`` and every array field of the state read;

the ratios of ``robot.step`` to the two bare runs, and of ``step + read`` to the bare
loop (medians of per-round ratios, all four timed in turn from the same settled state),
with the kinematic backend's steps per second beside them where the robot has one.
Times are this process's CPU time (``time.process_time``), not wall time: on a shared
machine the other processes' load then does not enter the figures (it still slows the
Python part through the shared caches: compare ratios from one run).
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


def alternate(fns: Sequence[Callable[[], object]], rounds: int) -> np.ndarray:
    """CPU times, s: one row per round, one column per function (run in turn).

    Every function runs once first (a warm-up).
    """
    for fn in fns:
        fn()
    return np.array([[cpu_time(fn) for fn in fns] for _ in range(rounds)])


#: The state's array fields (``step + read`` reads them all).
FIELDS = ("time", "pose", "twist", "wheel_rates", "steer_angles", "wheel_contacts")


def measure(name: str, period: float, steps: int, rounds: int,
            mode: str = "command") -> dict[str, object]:
    """Figures of one robot (module docstring)."""
    from wmr_mujoco.drive import make

    robot = make(name, backend="mujoco", control_period=period, mode=mode)
    robot.reset()
    model, data = robot.model, robot.data
    start = mujoco.MjData(model)
    mujoco.mj_copyData(start, model, data)
    command = 0.2 * robot.command_space.high
    # The controls robot.step applies, period by period: the bare loops replay them, so
    # that all simulate the same motion.
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

    def bare_n() -> None:
        mujoco.mj_copyData(bare_data, model, start)
        for ctrl in controls:
            bare_data.ctrl[:] = ctrl
            mujoco.mj_step(model, bare_data, n)

    def driven() -> None:
        mujoco.mj_copyData(data, model, start)
        for _ in range(steps):
            robot.step(command)

    def driven_read() -> None:
        mujoco.mj_copyData(data, model, start)
        for _ in range(steps):
            state = robot.step(command)
            for field in FIELDS:
                getattr(state, field)

    t = alternate((bare, bare_n, driven, driven_read), rounds)
    median = np.median(t, axis=0)
    out: dict[str, object] = {
        "robot": name, "substeps": n, "bare": steps / median[0], "bare_n": steps / median[1],
        "robot_step": steps / median[2], "step_read": steps / median[3],
        "ratio": float(np.median(t[:, 0] / t[:, 2])),
        "ratio_n": float(np.median(t[:, 1] / t[:, 2])),
        "ratio_read": float(np.median(t[:, 0] / t[:, 3])), "kinematic": None}
    if mode == "command" and robot.spec.command.analytic(None) is not None:
        kin = make(name, backend="kinematic", control_period=period)
        kin.reset()

        def analytic() -> None:
            for _ in range(steps):
                kin.step(command)

        analytic()
        out["kinematic"] = steps / float(np.median([cpu_time(analytic)
                                                    for _ in range(rounds)]))
    return out


def table(rows: list[dict[str, object]], period: float, mode: str = "command") -> str:
    """The Markdown table of :func:`measure`'s rows."""
    lines = [f"`python -m wmr_mujoco.bench.drive_overhead`: control period {period:g} s, "
             f"mode {mode!r}, MuJoCo {mujoco.__version__}; control steps per CPU second, "
             "medians; ratio = robot.step / bare loop (goal >= 0.8).", "",
             "| robot | substeps | bare mj_step loop | robot.step | ratio | kinematic "
             "backend | bare mj_step(n) | ratio to mj_step(n) | step + read | ratio of "
             "step + read |", "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        kin = "-" if r["kinematic"] is None else f"{r['kinematic']:.0f}"
        lines.append(f"| {r['robot']} | {r['substeps']} | {r['bare']:.0f} | "
                     f"{r['robot_step']:.0f} | {r['ratio']:.2f} | {kin} | "
                     f"{r['bare_n']:.0f} | {r['ratio_n']:.2f} | {r['step_read']:.0f} | "
                     f"{r['ratio_read']:.2f} |")
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
    parser.add_argument("--mode", choices=("command", "wheels"), default="command",
                        help="what a command is (see wmr_mujoco.drive.make)")
    args = parser.parse_args(argv)
    if args.steps < 1 or args.rounds < 1 or args.steps > 100_000 or args.rounds > 1000:
        parser.error(f"--steps {args.steps}, --rounds {args.rounds}: use 1..100000 steps "
                     "and 1..1000 rounds")
    try:
        rows = [measure(name, args.period, args.steps, args.rounds, args.mode)
                for name in args.robot or drivable()]
    except ValueError as err:
        parser.error(str(err))
    print(table(rows, args.period, args.mode))
    return 0


if __name__ == "__main__":
    sys.exit(main())
