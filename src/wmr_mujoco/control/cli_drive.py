"""``wmr drive ROBOT --controller C --path P``: one closed-loop task on both backends.

Runs the controller on the path in the contact physics and on the robot's kinematic
model from the same start (:func:`wmr_mujoco.control.closed_loop.compare`), prints the
tracking figures, and with ``--out DIR`` writes ``DIR/drive.png`` (both trajectories over
the path, and the cross-track errors against time) and with ``--clip`` also
``DIR/drive.mp4`` (the physics run). The Whipple bicycle's ``whipple_lean`` follows no
path: it rides at ``--speed`` after a push, uncontrolled and controlled, in the physics
and on the linear model (:mod:`wmr_mujoco.control.whipple_upright`).

Every input is checked before any simulation; unknown controllers and paths exit 2
with the valid names. Files are written atomically into a folder that exists.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from wmr_mujoco.control.registry import CONTROLLERS
from wmr_mujoco.loop.control.paths import PATHS

#: The clip's size and frame rate (small: a lap is a minute of run).
CLIP = {"width": 320, "height": 240, "fps": 10}


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add the ``drive`` command to ``wmr``'s subcommands."""
    p = subparsers.add_parser("drive", help="one controller on one path, physics beside "
                              "the kinematic model")
    p.add_argument("robot", help="a robot name (see `wmr list`)")
    p.add_argument("--controller", required=True, choices=list(CONTROLLERS),
                   help="feedback law")
    p.add_argument("--path", default="circle", choices=list(PATHS),
                   help="reference path (default: circle)")
    p.add_argument("--seed", type=int, default=0,
                   help="seed of the random spline and of the start offset (default 0)")
    p.add_argument("--offset", type=float, nargs=2, default=(0.1, 0.1),
                   metavar=("LATERAL", "HEADING"),
                   help="start offset from the path: m, rad (default 0.1 0.1)")
    p.add_argument("--speed", type=float, default=3.0,
                   help="whipple_lean only: riding speed, m/s (default 3)")
    p.add_argument("--out", type=Path, help="existing folder for drive.png (and the clip)")
    p.add_argument("--clip", action="store_true", help="also film the physics run "
                   "into --out (needs OpenGL)")
    p.set_defaults(func=run_command)


def _check(args: argparse.Namespace) -> None:
    """Every input checked before any work (``ValueError``: exit 2)."""
    if args.seed < 0:
        raise ValueError(f"--seed {args.seed}: must be an integer >= 0")
    if args.out is not None and not args.out.is_dir():
        raise ValueError(f"--out {args.out}: not an existing folder")
    if args.clip and args.out is None:
        raise ValueError("--clip needs --out DIR")
    if args.clip and args.controller == "whipple_lean":
        raise ValueError("--clip: only path-following tasks are filmed, not whipple_lean")
    if not all(abs(x) < 10 for x in args.offset):
        raise ValueError(f"--offset {args.offset}: each must be within ±10")


def run_command(args: argparse.Namespace) -> int:
    """The ``drive`` command; returns the exit code."""
    _check(args)
    if args.controller == "whipple_lean":
        return _whipple(args)
    from wmr_mujoco.control import closed_loop

    closed_loop.check_task(args.robot, args.controller, args.path, args.seed)
    if args.clip:
        from wmr_mujoco.render.gl_backend import select_backend

        select_backend()
    offset = (0.0, float(args.offset[0]), float(args.offset[1]))
    comp, robots, path = closed_loop.compare_robots(args.robot, args.controller, args.path,
                                                    args.seed, offset)
    print(f"{args.robot} {args.controller} on {path.name} from offset "
          f"{offset[1]:g} m, {offset[2]:g} rad:")
    print(f"{'':28s}{'physics':>10s}{'model':>10s}")
    for label, fig in closed_loop.FIGURES.items():
        print(f"{label:28s}{fig(comp.physics):10.4f}{fig(comp.model):10.4f}")
    print(f"{'physics-model deviation [m]':28s}{comp.max_deviation:10.4f}")
    if args.out is not None:
        from wmr_mujoco.control.plot import plot_comparison

        print(f"wrote {plot_comparison(comp, path, args.out / 'drive.png')}")
        if args.clip:
            clip = robots["mujoco"].film(args.out / "drive.mp4", **CLIP)
            print(f"wrote {clip}")
    return 0


def _whipple(args: argparse.Namespace) -> int:
    from wmr_mujoco.control import whipple_upright as wu
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.robots.whipple import rolling

    if get_spec(args.robot).command is None or \
            get_spec(args.robot).command.names != ("rear_torque", "steer_torque"):
        raise ValueError(f"controller 'whipple_lean' drives the whipple bicycle's "
                         f"(rear_torque, steer_torque), not {args.robot!r}")
    rolling.check_speed(args.speed)
    if args.speed <= 0:
        raise ValueError(f"--speed {args.speed}: must be > 0 m/s")
    print(f"whipple at {args.speed:g} m/s after a {wu.PUSH:g} rad/s lean-rate push "
          f"({wu.DURATION:g} s; fallen: |lean| > {wu.FALLEN:g} rad):")
    print(f"{'law':12s}{'upright s (physics | linear)':>32s}{'peak lean rad':>22s}")
    runs = []
    for controlled in (False, True):
        p = wu.physics(args.speed, controlled=controlled)
        m = wu.linear(args.speed, controlled=controlled)
        runs.append((controlled, p, m))
        print(f"{'LQR' if controlled else 'none':12s}{p.upright_time:16.2f} | "
              f"{m.upright_time:<13.2f}{p.peak_lean:12.3f} | {m.peak_lean:.3f}")
    if args.out is not None:
        from wmr_mujoco.control.plot import plot_leans

        print(f"wrote {plot_leans(runs, args.out / 'drive.png')}")
    return 0
