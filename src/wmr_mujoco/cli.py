"""The ``wmr`` command line.

MuJoCo is imported only inside the commands, after :func:`gl_backend.select_backend`
for the commands that render, so that EGL can fall back to OSMesa.

Exit codes: 0 done; 1 a validation target missed or a simulation diverged; 2 bad input
(checked before any work starts); 3 no OpenGL; 130 interrupted (Ctrl-C); 143 terminated
(SIGTERM). An interrupted command prints one line and leaves no file behind (every
output is written to a temporary file and renamed when complete).

Output locations, the same rule for every command: ``wmr`` writes into a folder that
exists; ``wmr validate --out DIR`` creates ``DIR`` itself (not its parents), ``wmr
render --out F`` needs ``F``'s folder to exist.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
from collections.abc import Sequence
from pathlib import Path

#: Commands that need an OpenGL context.
RENDERING_COMMANDS = ("render", "bench")


def _cmd_list(_: argparse.Namespace) -> int:
    from wmr_mujoco.robots import ROBOTS

    width = max(map(len, ROBOTS))
    for spec in ROBOTS.values():
        print(f"{spec.name:<{width}}  {spec.description}")
    return 0


def _cmd_scenarios(args: argparse.Namespace) -> int:
    from wmr_mujoco.robots import ROBOTS, get_spec

    specs = [get_spec(args.robot)] if args.robot else list(ROBOTS.values())
    rows = [(spec.name, s.name, s.kind.value, s.description) for spec in specs
            for s in spec.scenarios]
    if not rows:
        print(f"{args.robot}: no scenarios")
        return 0
    widths = [max(len(r[i]) for r in rows) for i in range(3)]
    for row in rows:
        print("  ".join(c.ljust(w) for c, w in zip(row[:3], widths, strict=True))
              + f"  {row[3]}".rstrip())
    return 0


def _cmd_info(args: argparse.Namespace) -> int:
    from wmr_mujoco.info import describe, describe_file

    path = Path(args.robot)
    print(describe_file(path) if path.suffix == ".xml" else describe(args.robot))
    return 0


def _cmd_demo(_: argparse.Namespace) -> int:
    from wmr_mujoco.demo import run_demo

    print(run_demo())
    return 0


def _cmd_validate(args: argparse.Namespace) -> int:
    from wmr_mujoco.progress import bar, shown
    from wmr_mujoco.validation.pool import ValidationPool
    from wmr_mujoco.validation.report import (
        check_report_folder,
        summary_line,
        text_table,
        write_report,
    )
    from wmr_mujoco.validation.runner import run_all
    from wmr_mujoco.validation.scenarios import scenarios_for

    check_report_folder(args.out)
    scenarios = scenarios_for(args.robots or None)
    if args.scenario:
        names = [s.name for s in scenarios]
        unknown = [n for n in args.scenario if n not in names]
        if unknown:
            where = ", ".join(args.robots) or "any robot"
            raise ValueError(f"no scenario {unknown[0]!r} for {where}; valid: "
                             f"{', '.join(repr(n) for n in dict.fromkeys(names))}")
        scenarios = [s for s in scenarios if s.name in args.scenario]
    progress_bar = bar(len(scenarios), "wmr validate", unit="scenario")

    def progress(msg: str) -> None:
        if msg.startswith("["):  # "[i/n] robot/scenario": one scenario measured
            progress_bar.set_postfix_str(msg.split("] ", 1)[-1], refresh=False)
            progress_bar.update()
            if shown() or args.quiet:
                return
        progress_bar.write(msg, file=sys.stderr)

    # Worker processes run the scenarios (a batch or a measurement each) and draw each
    # scenario's plot as soon as its result is back.
    with ValidationPool(args.out) as pool:
        try:
            results = run_all(scenarios, progress=progress, on_result=pool.plot,
                              offload=pool.run)
        finally:
            progress_bar.close()
        print(text_table(results, judged_only=not args.all_metrics))
        path = write_report(results, args.out, pool.collect())
    failed = [r.scenario.key for r in results if not r.passed]
    print(f"\n{summary_line(results)}; report: {path}")
    if failed:
        print(f"failed: {', '.join(failed)}", file=sys.stderr)
        return 1
    return 0


def _cmd_render(args: argparse.Namespace) -> int:
    from wmr_mujoco.render.video import render_clips, render_to_file

    backend = os.environ.get("MUJOCO_GL")
    if args.all:
        clip_options = {"--scenario": args.scenario, "--duration": args.duration,
                        "--hold": args.hold or None}
        given = [k for k, v in clip_options.items() if v is not None]
        if given:
            raise ValueError(f"--all films each robot's listed clips; {', '.join(given)} "
                             "apply to one robot's clip only")
        render_clips(args.out, args.robots or None,
                     lambda path: print(f"wrote {path} ({backend} backend)"))
        return 0
    if len(args.robots) != 1:
        raise ValueError(f"render takes one robot, got {len(args.robots)}: "
                         f"{' '.join(args.robots) or '(none)'}; or --all with any number")
    path = render_to_file(args.robots[0], args.out, args.scenario, args.width, args.height,
                          args.fps, args.camera, args.duration, args.hold)
    print(f"wrote {path} ({backend} backend)")
    return 0


def _cmd_view(args: argparse.Namespace) -> int:
    if sys.platform.startswith("linux") and not (os.environ.get("DISPLAY")
                                                 or os.environ.get("WAYLAND_DISPLAY")):
        print("wmr view: no display here (DISPLAY and WAYLAND_DISPLAY are unset), so the "
              "interactive viewer cannot open. Use `wmr render ROBOT --out clip.mp4` "
              "for an offscreen video instead.", file=sys.stderr)
        return 2
    os.environ["MUJOCO_GL"] = "glfw"
    from wmr_mujoco.render.viewer import view

    view(args.robot, args.scenario)
    return 0


def _cmd_bench(args: argparse.Namespace) -> int:
    from wmr_mujoco.bench.bench import main as bench_main

    return bench_main(args)


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``wmr``."""
    parser = argparse.ArgumentParser(
        prog="wmr", description="Wheeled mobile robots in MuJoCo beside their textbook models.")
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="list the robots").set_defaults(func=_cmd_list)
    scen = sub.add_parser("scenarios", help="list the validation scenarios, one line each")
    scen.add_argument("robot", nargs="?", help="a robot name (default: every robot)")
    scen.set_defaults(func=_cmd_scenarios)
    info = sub.add_parser("info", help="parameters, joints, actuators, mass, DoF, timestep")
    info.add_argument("robot", help="a robot name (see `wmr list`) or an MJCF scene file "
                                    "(.xml, with its floor)")
    info.set_defaults(func=_cmd_info)
    sub.add_parser("demo", help="simulate a short manoeuvre of each robot").set_defaults(
        func=_cmd_demo)
    val = sub.add_parser("validate", help="compare MuJoCo with the analytic models; "
                         "exit 1 if a target is missed")
    val.add_argument("robots", nargs="*", help="robots to validate (default: all)")
    val.add_argument("--scenario", action="append",
                     help="run only this scenario (repeatable; see `wmr scenarios`)")
    val.add_argument("--out", type=Path, default=Path("reports"),
                     help="report folder, created if its parent exists (default: reports); "
                     "a partial run is merged into the report already there")
    val.add_argument("-q", "--quiet", action="store_true", help="no progress output")
    val.add_argument("--all-metrics", action="store_true",
                     help="print informative metrics too, not only judged ones")
    val.set_defaults(func=_cmd_validate)
    ren = sub.add_parser("render", help="offscreen video of a scenario (EGL, else OSMesa)")
    ren.add_argument("robots", nargs="*", metavar="robot",
                     help="a robot name (see `wmr list`); with --all, any number (default: "
                     "every robot)")
    ren.add_argument("--all", action="store_true",
                     help="film every clip the robots' registry entries list (the README's "
                     "clips) into the folder --out")
    ren.add_argument("--scenario", help="scenario name (default: the robot's first)")
    ren.add_argument("--out", type=Path, required=True,
                     help="output .mp4 or .gif (or .png: the last frame), in an existing "
                     "folder; with --all, that folder")
    ren.add_argument("--width", type=int, default=640)
    ren.add_argument("--height", type=int, default=480)
    ren.add_argument("--fps", type=int, default=30)
    ren.add_argument("--camera", default="track",
                     help="'track' (follows the robot) or a camera name in the model")
    ren.add_argument("--duration", type=float,
                     help="seconds to render (default: the scenario's); longer than the "
                     "scenario only with --hold")
    ren.add_argument("--hold", action="store_true",
                     help="past the scenario's end, keep its last input (the robot goes on "
                     "as at the end: straight, turning, ...)")
    ren.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    ren.set_defaults(func=_cmd_render)
    view = sub.add_parser("view", help="MuJoCo's interactive viewer (needs a display)")
    view.add_argument("robot")
    view.add_argument("--scenario")
    view.set_defaults(func=_cmd_view)
    bench = sub.add_parser("bench", help="speed, accuracy per compute, peer model, render fps")
    bench.add_argument("--out", type=Path, default=Path("reports"))
    bench.add_argument("--repeats", type=int, default=5, help="repeats for medians")
    bench.add_argument("--quick", action="store_true",
                       help="fewer repeats and cases (`make readme` refuses its report)")
    bench.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    bench.set_defaults(func=_cmd_bench)
    from wmr_mujoco.control.cli_drive import register as register_drive

    register_drive(sub)
    return parser


class Terminated(BaseException):
    """SIGTERM, raised in the main thread so that temporary files are removed."""


def _raise_terminated(signum: int, frame: object) -> None:
    raise Terminated


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point; returns the process exit code (see the module docstring)."""
    args = build_parser().parse_args(argv)
    from wmr_mujoco.progress import configure

    configure(getattr(args, "quiet", False))
    previous = signal.signal(signal.SIGTERM, _raise_terminated)
    try:
        return _run(args)
    except KeyboardInterrupt:
        print(f"wmr {args.command}: interrupted; nothing written", file=sys.stderr)
        return 130
    except Terminated:
        print(f"wmr {args.command}: terminated; nothing written", file=sys.stderr)
        return 143
    finally:
        signal.signal(signal.SIGTERM, previous)


def _run(args: argparse.Namespace) -> int:
    try:
        if args.command in RENDERING_COMMANDS:
            from wmr_mujoco.render.gl_backend import select_backend

            select_backend()
        return args.func(args)
    except (ValueError, FileNotFoundError) as err:
        print(f"wmr: error: {err}", file=sys.stderr)
        return 2
    except Exception as err:
        from wmr_mujoco.render.gl_backend import RenderingUnavailableError
        from wmr_mujoco.sim.stepping import SimulationDivergedError

        if isinstance(err, SimulationDivergedError):
            print(f"wmr: simulation diverged: {err}", file=sys.stderr)
            return 1
        if isinstance(err, RenderingUnavailableError):
            print(f"wmr: rendering unavailable: {err}", file=sys.stderr)
            return 3
        raise


if __name__ == "__main__":
    sys.exit(main())
