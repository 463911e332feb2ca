"""``wmr validate``'s family options: ``--seed S``, ``--draws N``, ``--quick``.

Every scenario with a family runs as its seeded draws (:mod:`wmr_mujoco.validation.family`):
``--seed`` picks them (default :data:`~wmr_mujoco.validation.family.DEFAULT_SEED`; any
integer >= 0), ``--draws`` runs that many per family instead of each family's declared
number, ``--quick`` runs :data:`QUICK_DRAWS` per family. A run with fewer draws than
declared is labelled quick in the output and the report.
"""

from __future__ import annotations

import argparse

from wmr_mujoco.validation.family import DEFAULT_SEED, MAX_DRAWS, check_draws, check_seed

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


def add_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--seed``, and ``--draws`` or ``--quick`` (one of them), to ``parser``."""
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
