"""``wmr audit SCENE.xml [--out DIR]`` and ``wmr export ROBOT [--set F=V ...] --out DIR``.

Exit codes: 0 the audit ran (whatever it found); 2 bad input; 4 not a wheeled robot (or
wheels the audit cannot classify); 1 a run diverged; as every ``wmr`` command, 130/143
when interrupted. See :mod:`wmr_mujoco.audit.errors`.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from wmr_mujoco.audit.errors import EXIT_NOT_WHEELED, NotWheeledError


def _run_audit(path: Path, out: Path | None, args: argparse.Namespace) -> int:
    from wmr_mujoco.audit.core import audit
    from wmr_mujoco.audit.report import summary_text, write_report

    say = (lambda _: None) if args.quiet else (lambda m: print(f"  {m}", file=sys.stderr))
    try:
        a = audit(path, duration=args.duration, diagnose=not args.no_diagnose, progress=say,
                  draws=args.draws, seed=args.seed)
    except NotWheeledError as err:
        print(f"wmr: {path}: {err}", file=sys.stderr)
        return EXIT_NOT_WHEELED
    print(summary_text(a))
    if out is not None:
        written = write_report(a, out)
        print(f"report: {written[-1]}")
    return 0


def _cmd_audit(args: argparse.Namespace) -> int:
    if args.out is not None:
        from wmr_mujoco.validation.report import check_report_folder

        check_report_folder(args.out)
    return _run_audit(args.scene, args.out, args)


def _cmd_export(args: argparse.Namespace) -> int:
    from wmr_mujoco.audit.export_robot import export_robot
    from wmr_mujoco.validation.report import check_report_folder

    check_report_folder(args.out)
    scene = export_robot(args.robot, args.set or [], args.out)
    print(f"wrote {args.out}")
    return _run_audit(scene, args.out / "audit", args)


def _common(p: argparse.ArgumentParser) -> None:
    from wmr_mujoco.audit.limits import DRAWS, DURATION

    p.add_argument("--duration", type=float, default=DURATION,
                   help=f"seconds per manoeuvre (default {DURATION:g})")
    p.add_argument("--draws", type=int, default=DRAWS,
                   help=f"seeded variants of each manoeuvre, speed and wheel phase, the worst "
                   f"reported (default {DRAWS})")
    p.add_argument("--seed", type=int, default=0, help="seed of the draws (default 0)")
    p.add_argument("--no-diagnose", action="store_true", help="skip the counterfactual runs")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress lines")


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add ``audit`` and ``export`` to ``wmr``'s subcommands."""
    p = subparsers.add_parser(
        "audit", help="audit any MJCF wheeled robot: class, ideal kinematics, manoeuvres, "
        "pitfalls (exit 0 ran, 2 bad input, 4 not a wheeled robot)")
    p.add_argument("scene", type=Path, help="an MJCF scene with a floor, or a robot file "
                   "(a floor is added)")
    p.add_argument("--out", type=Path, help="report folder (audit.md, audit.json, plots), "
                   "created if its parent exists")
    _common(p)
    p.set_defaults(func=_cmd_audit)
    e = subparsers.add_parser(
        "export", help="write a Menagerie-style folder of a robot with your dimensions, "
        "then audit it")
    e.add_argument("robot", help="a registered robot (see `wmr list`)")
    e.add_argument("--set", action="append", metavar="FIELD=VALUE",
                   help="a parameter (dotted, as `wmr info ROBOT` lists them); repeatable")
    e.add_argument("--out", type=Path, required=True,
                   help="folder to write, created if its parent exists")
    _common(e)
    e.set_defaults(func=_cmd_export)
