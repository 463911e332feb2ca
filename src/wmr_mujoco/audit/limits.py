"""What the audit accepts from a user, light enough to import before MuJoCo."""

from __future__ import annotations

#: Seconds each manoeuvre is driven (ramp included) unless told otherwise.
DURATION = 2.0
#: Accepted range of the duration, s (enough to pass the ramp; bounded run time).
DURATION_RANGE = (0.5, 30.0)
#: Seeded variants of each manoeuvre by default (the first nominal), and the accepted range.
DRAWS = 3
DRAWS_RANGE = (1, 20)
#: Range of the speed factor of the non-nominal draws.
SPEED_FACTORS = (0.5, 1.5)
