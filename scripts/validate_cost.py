"""CPU seconds of ``wmr validate ROBOT`` and how many of them MuJoCo's stepping takes.

Usage: ``python scripts/validate_cost.py ROBOT [--out FOLDER]`` (one process, seed 0).

Prints the process's CPU seconds over the whole command (families, report, imports) and
those spent inside ``mujoco.rollout.rollout``, ``mujoco.mj_step`` and ``mujoco.mj_forward``
(the physics: what no change to the Python around it can save). CPU seconds, not wall
time: on a shared machine they depend less on the load (compare runs made together).
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable

import mujoco
from mujoco import rollout

from wmr_mujoco.cli import main as wmr

SPENT = {"rollout": 0.0, "mj_step": 0.0, "mj_forward": 0.0}


def _timed(fn: Callable, key: str) -> Callable:
    def call(*args, **kwargs):
        start = time.process_time()
        try:
            return fn(*args, **kwargs)
        finally:
            SPENT[key] += time.process_time() - start
    return call


def main(argv: list[str]) -> int:
    """Run ``wmr validate`` on ``argv`` with its stepping timed; its exit status."""
    if not argv or argv[0].startswith("-"):
        print(__doc__)
        return 2
    rollout.rollout = _timed(rollout.rollout, "rollout")
    mujoco.mj_step = _timed(mujoco.mj_step, "mj_step")
    mujoco.mj_forward = _timed(mujoco.mj_forward, "mj_forward")
    start = time.process_time()
    code = wmr(["validate", argv[0], "--jobs", "1", "--seed", "0", "-q", *argv[1:]])
    total = time.process_time() - start
    stepping = sum(SPENT.values())
    print(f"{argv[0]}: {total:.1f} CPU s in all, {stepping:.1f} in MuJoCo's stepping "
          f"({', '.join(f'{k} {v:.1f}' for k, v in SPENT.items())}), "
          f"{total - stepping:.1f} around it")
    return code


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
