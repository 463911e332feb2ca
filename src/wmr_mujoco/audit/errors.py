"""What can stop an audit before it starts, and the exit code ``wmr audit`` gives for it.

Exit codes of ``wmr audit`` and ``wmr export``: 0 the audit ran (whatever it found);
2 bad input (:class:`AuditInputError`: not a readable MJCF file, no floor and no way
to add one, several robots, a bad ``--set``); 4 not a wheeled robot the audit can drive
(:class:`NotWheeledError`: no wheels, such as a humanoid, or wheels it cannot classify,
each named with the reason).
"""

from __future__ import annotations

#: Exit code for "not a wheeled robot" (and wheels the audit cannot classify).
EXIT_NOT_WHEELED = 4
#: Exit code for bad input (the CLI's usual one).
EXIT_BAD_INPUT = 2


class AuditInputError(ValueError):
    """The input is not something the audit can read: exit code 2."""


class NotWheeledError(ValueError):
    """The model is readable but not a wheeled robot the audit can drive: exit code 4."""
