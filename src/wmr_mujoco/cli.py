"""The ``wmr`` command line."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

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
