"""How many worker processes a run may use: light enough to import before MuJoCo.

The command line checks ``--jobs`` with these while it builds its parser, which must
not import MuJoCo (``tests/audit/test_cli_audit.py``);
:mod:`wmr_mujoco.validation.pool` runs the workers.
"""

from __future__ import annotations

import os

#: Most worker processes ``--jobs`` may ask for (a typed number may not exhaust memory).
MAX_JOBS = 64


def usable_cores() -> int:
    """Cores this process may run on (``os.sched_getaffinity``; ``os.cpu_count`` elsewhere)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def check_jobs(jobs: object) -> int:
    """``jobs`` as an int, if it is an integer in ``1..MAX_JOBS``.

    Raises:
        ValueError: anything else (a bool, a float, zero, a negative number).
    """
    if isinstance(jobs, bool) or not isinstance(jobs, int) or not 1 <= jobs <= MAX_JOBS:
        raise ValueError(f"jobs = {jobs!r}; must be an integer in 1..{MAX_JOBS}")
    return jobs
