"""``wmr validate``'s family options: ``--seed S``, ``--draws N``, ``--quick``, ``--jobs N``.

Every scenario with a family runs as its seeded draws (:mod:`wmr_mujoco.validation.family`):
``--seed`` picks them (default :data:`~wmr_mujoco.validation.family.DEFAULT_SEED`; any
integer >= 0), ``--draws`` runs that many per family instead of each family's declared
number, ``--quick`` runs :data:`QUICK_DRAWS` per family. A run with fewer draws than
declared is labelled quick in the output and the report. ``--jobs`` runs the families in
that many worker processes (default: the cores this process may use), with the same
results and output as one (:mod:`wmr_mujoco.validation.pool`).
"""

from __future__ import annotations

import argparse

from wmr_mujoco.validation.family import DEFAULT_SEED, MAX_DRAWS, check_draws, check_seed
from wmr_mujoco.validation.jobs import MAX_JOBS, check_jobs, usable_cores

#: Draws per family of ``wmr validate --quick``.
QUICK_DRAWS = 3


def _seed(text: str) -> int:
    try:
        return check_seed(int(text))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"seed {text!r}: give an integer >= 0 (default {DEFAULT_SEED})") from None


def _draws(text: str) -> int:
    try:
        return check_draws(int(text))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"draws {text!r}: give an integer in 1..{MAX_DRAWS}") from None


def _jobs(text: str) -> int:
    try:
        return check_jobs(int(text))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"jobs {text!r}: give an integer in 1..{MAX_JOBS} (default: the usable "
            f"cores, {usable_cores()} here)") from None


def add_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--seed``, ``--jobs``, and ``--draws`` or ``--quick`` (one of them), to ``parser``."""
    parser.add_argument("--jobs", "-j", type=_jobs, default=None,
                        help="worker processes running the families (default: the cores "
                        "this process may use; 1: in this process); the results and "
                        "output do not depend on it")
    parser.add_argument("--seed", type=_seed, default=DEFAULT_SEED,
                        help=f"seed of every family's draws (default {DEFAULT_SEED}; any "
                        "integer >= 0)")
    how_many = parser.add_mutually_exclusive_group()
    how_many.add_argument("--draws", type=_draws, default=None,
                          help="draws per family instead of each family's declared number "
                          "(fewer: labelled quick)")
    how_many.add_argument("--quick", action="store_true",
                          help=f"{QUICK_DRAWS} draws per family, labelled quick (not the "
                          "judged claim)")


def draws_of(args: argparse.Namespace) -> int | None:
    """Draws per family the options ask for (None: each family's declared number)."""
    if getattr(args, "quick", False):
        return QUICK_DRAWS
    return getattr(args, "draws", None)


def jobs_of(args: argparse.Namespace) -> int:
    """Worker processes the options ask for (default: the usable cores, at most MAX_JOBS)."""
    jobs = getattr(args, "jobs", None)
    return min(usable_cores(), MAX_JOBS) if jobs is None else jobs
