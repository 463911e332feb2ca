"""The ``wmr`` command line."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from wmr_mujoco.registry import ROBOTS
from wmr_mujoco.simulation import SimulationDivergedError


def _cmd_list(_: argparse.Namespace) -> int:
    width = max(map(len, ROBOTS))
    for spec in ROBOTS.values():
        print(f"{spec.name:<{width}}  {spec.description}")
    return 0


def _cmd_info(args: argparse.Namespace) -> int:
    from wmr_mujoco.info import describe

    print(describe(args.robot))
    return 0


def _cmd_demo(_: argparse.Namespace) -> int:
    from wmr_mujoco.demo import run_demo

    print(run_demo())
    return 0


def _cmd_validate(args: argparse.Namespace) -> int:
    from wmr_mujoco.report import text_table, write_report
    from wmr_mujoco.scenarios import scenarios_for
    from wmr_mujoco.validation import run_all

    scenarios = scenarios_for(args.robots or None)
    results = run_all(scenarios, progress=lambda msg: print(msg, file=sys.stderr, flush=True))
    print(text_table(results, judged_only=not args.all_metrics))
    path = write_report(results, args.out)
    failed = [r.scenario.key for r in results if not r.passed]
    print(f"\n{len(results) - len(failed)} of {len(results)} scenarios pass; report: {path}")
    if failed:
        print(f"failed: {', '.join(failed)}", file=sys.stderr)
        return 1
    return 0


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``wmr``."""
    parser = argparse.ArgumentParser(
        prog="wmr", description="Wheeled mobile robots in MuJoCo beside their textbook models.")
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("list", help="list the robots").set_defaults(func=_cmd_list)
    info = sub.add_parser("info", help="parameters, joints, actuators, mass, DoF, timestep")
    info.add_argument("robot", help=f"one of: {', '.join(ROBOTS)}")
    info.set_defaults(func=_cmd_info)
    sub.add_parser("demo", help="simulate a short manoeuvre of each robot").set_defaults(
        func=_cmd_demo)
    val = sub.add_parser("validate", help="compare MuJoCo with the analytic models; "
                         "exit 1 if a target is missed")
    val.add_argument("robots", nargs="*", help="robots to validate (default: all)")
    val.add_argument("--out", type=Path, default=Path("reports"),
                     help="report folder (default: reports)")
    val.add_argument("--all-metrics", action="store_true",
                     help="print informative metrics too, not only judged ones")
    val.set_defaults(func=_cmd_validate)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point; returns the process exit code (2 for a user error)."""
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except (ValueError, FileNotFoundError) as err:
        print(f"wmr: error: {err}", file=sys.stderr)
        return 2
    except SimulationDivergedError as err:
        print(f"wmr: simulation diverged: {err}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
