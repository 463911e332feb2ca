"""The ``wmr`` command line.

MuJoCo is imported only inside the commands, after :func:`gl_backend.select_backend`
for the commands that render, so that EGL can fall back to OSMesa.

Exit codes: 0 done; 1 a validation target missed or a simulation diverged; 2 bad input
(checked before any work starts); 3 no OpenGL; 4 not a wheeled robot (``wmr audit``,
``wmr export``); 5 an input/output error (disk full, a folder that is not writable, the
video encoder failing); 130 interrupted (Ctrl-C); 141 the reader of the output went away
(``wmr info omni3 | head -1``: the rest of the output is dropped quietly, as by ``cat``:
128 + SIGPIPE); 143 terminated (SIGTERM). An interrupted or failed command prints one
line and leaves no file behind (every output is written to a temporary file and renamed
when complete).

Output locations, the same rule for every command: ``wmr`` writes into a folder that
exists; ``wmr validate --out DIR`` creates ``DIR`` itself (not its parents), ``wmr
render --out F`` needs ``F``'s folder to exist.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
import time
from collections.abc import Sequence
from pathlib import Path

#: Commands that need an OpenGL context.
RENDERING_COMMANDS = ("render", "bench")
#: Exit codes (see the module docstring).
EXIT_IO_ERROR = 5
EXIT_BROKEN_PIPE = 141


def looks_like_file(name: str) -> bool:
    """Whether a command-line name means a model file rather than a robot.

    An ``.xml`` name (any case), a path with a folder in it, or an existing file; a
    folder named like a robot is not one.
    """
    return Path(name).suffix.lower() == ".xml" or os.sep in name or Path(name).is_file()


def _robots_only(command: str, names: Sequence[str], why: str) -> None:
    """Refuse model files where a command takes registered robots only.

    Raises:
        ValueError: one of ``names`` is a model file; the message says why and what to use.
    """
    for name in names:
        if name and looks_like_file(name):
            raise ValueError(f"wmr {command} takes robot names (see `wmr list`), not a model "
                             f"file ({name}): {why}; `wmr info {name}` describes the file")


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

    print(describe_file(Path(args.robot)) if looks_like_file(args.robot)
          else describe(args.robot))
    return 0


def _cmd_demo(args: argparse.Namespace) -> int:
    if not args.quick:  # the main job, as `make demo`: the full validation and its report
        from wmr_mujoco.validation.family import DEFAULT_SEED

        return _cmd_validate(argparse.Namespace(robots=[], scenario=None, out=args.out,
                                                quiet=args.quiet, all_metrics=False,
                                                seed=DEFAULT_SEED, draws=None))
    from wmr_mujoco.demo import run_demo

    print(run_demo())
    return 0


def _cmd_validate(args: argparse.Namespace) -> int:
    from wmr_mujoco.family_cli import draws_of, jobs_of
    from wmr_mujoco.lookup import validation_jobs
    from wmr_mujoco.progress import bar, shown
    from wmr_mujoco.robots import ROBOTS
    from wmr_mujoco.validation.family_report import slowest, spread_text
    from wmr_mujoco.validation.members import run_families
    from wmr_mujoco.validation.plots import scenario_png
    from wmr_mujoco.validation.pool import time_hints
    from wmr_mujoco.validation.report import (
        check_report_folder,
        summary_line,
        text_table,
        write_report,
    )

    _robots_only("validate", args.robots, "a model file has no analytic model or scenarios "
                 "to validate against")
    check_report_folder(args.out)
    work = validation_jobs(args.robots or None, args.scenario or None)
    progress_bar = bar(len(work), "wmr validate", unit="scenario")
    jobs = jobs_of(args)

    def progress(msg: str) -> None:
        if msg.startswith("["):  # "[i/n] robot/scenario": one scenario measured
            progress_bar.set_postfix_str(msg.split("] ", 1)[-1], refresh=False)
            progress_bar.update()
            if shown() or args.quiet:
                return
        progress_bar.write(msg, file=sys.stderr)

    start = time.perf_counter()
    try:
        results = run_families(work, progress=progress, seed=args.seed, draws=draws_of(args),
                               jobs=jobs, hints=time_hints(args.out), draw=scenario_png)
    finally:
        progress_bar.close()
    wall = time.perf_counter() - start
    print(text_table(results, judged_only=not args.all_metrics))
    print(f"\nover each family (seed {args.seed}):\n{spread_text(results)}\n"
          f"{slowest(results)}; the families and their figures took {wall:.1f} s of wall "
          f"time in {jobs} process{'es' if jobs > 1 else ''}")
    path = write_report(results, args.out, robots=ROBOTS, jobs=jobs)
    failed = [r.scenario.key for r in results if not r.passed]
    print(f"\n{summary_line(results)}; report: {path}")
    if failed:
        print(f"failed: {', '.join(failed)}", file=sys.stderr)
        return 1
    return 0


def _cmd_render(args: argparse.Namespace) -> int:
    from wmr_mujoco.render.video import render_clips, render_to_file

    backend = os.environ.get("MUJOCO_GL")
    _robots_only("render", args.robots, "a model file has no scenarios to film (`python -m "
                 "mujoco.viewer --mjcf FILE` opens it in MuJoCo's viewer)")
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
    from wmr_mujoco import __version__

    parser = argparse.ArgumentParser(
        prog="wmr", description="Wheeled mobile robots in MuJoCo beside their textbook models.")
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="list the robots").set_defaults(func=_cmd_list)
    scen = sub.add_parser("scenarios", help="list the validation scenarios, one line each")
    scen.add_argument("robot", nargs="?", help="a robot name (default: every robot)")
    scen.set_defaults(func=_cmd_scenarios)
    info = sub.add_parser("info", help="parameters, joints, actuators, mass, DoF, timestep")
    info.add_argument("robot", help="a robot name (see `wmr list`; any case, a unique "
                      "prefix) or an MJCF scene file (.xml in any case, or any path)")
    info.set_defaults(func=_cmd_info)
    demo = sub.add_parser("demo", help="the main job, as `make demo`: every scenario "
                          "validated, its table printed, its report written (--quick: one "
                          "scenario per robot, summarised)")
    demo.add_argument("--quick", action="store_true",
                      help="one short scenario per robot, summarised; nothing written")
    demo.add_argument("--out", type=Path, default=Path("reports"),
                      help="report folder, as `wmr validate --out` (default: reports)")
    demo.add_argument("-q", "--quiet", action="store_true", help="no progress output")
    demo.set_defaults(func=_cmd_demo)
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
    from wmr_mujoco import family_cli

    family_cli.add_options(val)
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
    from wmr_mujoco.audit.cli_audit import register as register_audit

    register_audit(sub)

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
        code = _run(args)
        sys.stdout.flush()  # a closed pipe shows here, not at the interpreter's exit
        return code
    except KeyboardInterrupt:
        print(f"wmr {args.command}: interrupted; nothing written", file=sys.stderr)
        return 130
    except Terminated:
        print(f"wmr {args.command}: terminated; nothing written", file=sys.stderr)
        return 143
    except BrokenPipeError:
        # The reader went away (``| head``): drop the rest of the output quietly; stdout
        # points at /dev/null so that the interpreter's last flush does not fail again.
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
        return EXIT_BROKEN_PIPE
    finally:
        signal.signal(signal.SIGTERM, previous)


def _interrupt_behind(err: BaseException) -> BaseException | None:
    """The interrupt (Ctrl-C, SIGTERM) that ``err`` was raised while handling, if any.

    A terminal's Ctrl-C reaches the whole process group: a helper process (ffmpeg) dies
    of it too, and the error of its death replaces the interrupt while the stack unwinds.
    """
    seen: set[int] = set()
    todo: list[BaseException | None] = [err.__cause__, err.__context__]
    while todo:
        e = todo.pop()
        if e is None or id(e) in seen:
            continue
        seen.add(id(e))
        if isinstance(e, (KeyboardInterrupt, Terminated)):
            return e
        todo += [e.__cause__, e.__context__]
    return None


def _run(args: argparse.Namespace) -> int:
    try:
        if args.command in RENDERING_COMMANDS:
            from wmr_mujoco.render.gl_backend import select_backend

            select_backend()
        return args.func(args)
    except BrokenPipeError:
        raise
    except Exception as err:
        interrupt = _interrupt_behind(err)
        if interrupt is not None:
            raise interrupt from None
        return _report_error(err)


def _report_error(err: Exception) -> int:
    """One line on stderr for an expected failure and its exit code; raise the others."""
    from wmr_mujoco.render.gl_backend import RenderingUnavailableError
    from wmr_mujoco.sim.stepping import SimulationDivergedError

    if isinstance(err, (ValueError, FileNotFoundError)):
        print(f"wmr: error: {err}", file=sys.stderr)
        return 2
    if isinstance(err, SimulationDivergedError):
        print(f"wmr: simulation diverged: {err}", file=sys.stderr)
        return 1
    if isinstance(err, RenderingUnavailableError):
        print(f"wmr: rendering unavailable: {err}", file=sys.stderr)
        return 3
    if isinstance(err, OSError):
        where = f": {err.filename}" if err.filename else ""
        print(f"wmr: I/O error: {err.strerror or err}{where}",
              file=sys.stderr)
        return EXIT_IO_ERROR
    raise err


if __name__ == "__main__":
    sys.exit(main())
