"""Mass properties of the primitive solids the builders use, and the steered fork's box.

Parameter layer: the builders give these inertias to MuJoCo bodies, and the analytic
models (:mod:`wmr_mujoco.robots.steered.analytic`) read the same numbers, so neither imports the
other.
"""

from __future__ import annotations

from collections.abc import Sequence

#: Full edge lengths of the steered robots' fork box, m: width, length, height (the
#: steering column's height above the wheel centre).
FORK_BOX = (0.04, 0.06, 0.12)


def box_inertia(mass: float, size: Sequence[float]) -> tuple[float, float, float]:
    """Principal inertia of a uniform box of full edge lengths ``(a, b, c)``.

    ``I_x = m (b² + c²)/12``, ``I_y = m (a² + c²)/12``, ``I_z = m (a² + b²)/12``.
    """
    a, b, c = size
    return (mass * (b * b + c * c) / 12.0, mass * (a * a + c * c) / 12.0,
            mass * (a * a + b * b) / 12.0)


def fork_yaw_inertia(fork_mass: float) -> float:
    """Yaw inertia of the steered robots' fork alone (the box :data:`FORK_BOX`), kg·m²."""
    return box_inertia(fork_mass, FORK_BOX)[2]
