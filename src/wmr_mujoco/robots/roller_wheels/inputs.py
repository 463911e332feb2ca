"""Open-loop manoeuvres of roller-wheeled robots: translations and turns from rest."""

from __future__ import annotations

import numpy as np

from wmr_mujoco.validation.signals import Signal, const

#: Open-loop manoeuvres of omni-wheeled robots: translation directions (degrees in the
#: body frame), speed (m/s), yaw rate (rad/s) and the ramp from rest (s).
DIRECTIONS_DEG = tuple(range(0, 360, 45))
SPEED = 0.3
YAW_RATE = 1.0
RAMP = 0.5


def twist_inputs(twist: tuple[float, float, float], ramp: float = RAMP) -> tuple[Signal, ...]:
    """Body twist ``(u, v, r)`` inputs, each reached from rest by a linear ramp."""
    return tuple(const(c, ramp) if c else const(0.0) for c in twist)


def translation(deg: float, speed: float = SPEED) -> tuple[float, float, float]:
    """Body twist ``(s cos α, s sin α, 0)`` of a translation at ``α`` degrees."""
    a = np.radians(deg)
    return (speed * float(np.cos(a)), speed * float(np.sin(a)), 0.0)
