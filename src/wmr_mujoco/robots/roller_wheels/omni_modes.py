"""The hybrid model's wheel modes: which roller touches the floor, and when it hands over.

Vectorised over B runs' (B, 3) wheel angles, for
:func:`~wmr_mujoco.robots.roller_wheels.omni_batch.simulate_batch`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from wmr_mujoco.analytic.planar import wrap_angle

if TYPE_CHECKING:
    from wmr_mujoco.robots.roller_wheels.omni_hybrid import OmniHybrid


def lowest(model: OmniHybrid, thetas: np.ndarray) -> np.ndarray:
    """``σ = argmin_k |φ_k|`` for (B, 3) wheel angles, ``φ_k = wrap(ζ_k + θ − π)``.

    ``|wrap(x)|`` as ``|x − 2π rint(x / 2π)|``: within ``|x|·10⁻¹⁵ + 10⁻¹⁵`` rad of
    :func:`~wmr_mujoco.analytic.planar.wrap_angle`'s floats (``arg(exp(i x))``, a few
    ulp of π), at a quarter of its cost (no complex exponential). The second-lowest
    roller is at least ``s − |φ_σ|`` from the bottom (``s`` the least angular gap
    between two rollers, ``OmniHybrid.roller_gap``), so wherever
    ``|φ_σ| < s/2 − 10⁻⁹`` the argmin is ``wrap_angle``'s; the other wheels (near a
    hand-over's tie) take ``wrap_angle`` itself, and so do angles beyond 10⁴ rad.
    """
    angles = model.rollers.angles
    shifted = angles + thetas[..., None] - math.pi
    if not np.abs(thetas).max(initial=0.0) <= 1e4:
        return np.argmin(np.abs(wrap_angle(shifted)), axis=-1)
    dist = np.abs(shifted - 2.0 * math.pi * np.rint(shifted / (2.0 * math.pi)))
    sigma = np.argmin(dist, axis=-1)
    near = (np.take_along_axis(dist, sigma[..., None], -1)[..., 0]
            >= 0.5 * model.roller_gap - 1e-9)
    if near.any():
        sigma[near] = np.argmin(np.abs(wrap_angle(shifted[near])), axis=-1)
    return sigma


def switch_fraction(model: OmniHybrid, th0: np.ndarray, th1: np.ndarray, old: np.ndarray,
                     new: np.ndarray) -> np.ndarray:
    """Fraction of a step at which the first wheel hands over, per run (B,).

    The hand-over is where the two rollers are equally low, ``|φ_old| = |φ_new|``;
    ``g = |φ_old| − |φ_new|`` is linear in θ between the two, so the fraction is
    ``g₀ / (g₀ − g₁)`` of the step (θ linear over it).
    """
    ang = model.rollers.angles

    def g(th: np.ndarray) -> np.ndarray:
        def phi(m: np.ndarray) -> np.ndarray:
            return np.remainder(ang[m] + th, 2.0 * math.pi) - math.pi
        return np.abs(phi(old)) - np.abs(phi(new))

    g0, g1 = g(th0), g(th1)
    frac = np.where(old != new, np.clip(g0 / np.where(g0 != g1, g0 - g1, -1.0), 0, 1), 1.0)
    return frac.min(axis=1)
