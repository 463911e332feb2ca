"""What the audit accepts from a user, light enough to import before MuJoCo."""

from __future__ import annotations

#: Seconds each manoeuvre is driven (ramp included) unless told otherwise.
DURATION = 2.0
#: Accepted range of the duration, s (enough to pass the ramp; bounded run time).
DURATION_RANGE = (0.5, 30.0)
