"""The hybrid model's kinetic energy and rolling rates, vectorised over samples.

:meth:`~wmr_mujoco.robots.roller_wheels.omni_hybrid.OmniHybrid.kinetic_energy` and
``θ̇ = H(σ) ν`` at (N, 3) wheel angles, σ the lowest rollers
(:func:`~wmr_mujoco.robots.roller_wheels.omni_batch._geometry`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from wmr_mujoco.robots.roller_wheels.omni_batch import _geometry

if TYPE_CHECKING:
    from wmr_mujoco.robots.roller_wheels.omni_hybrid import OmniHybrid


def kinetic_energies(model: OmniHybrid, twists: np.ndarray, thetas: np.ndarray) -> np.ndarray:
    """``½ νᵀ (P + I_w H(σ)ᵀH(σ) + I_r Σ k kᵀ) ν`` of (N, 3) twists at (N, 3) wheel angles.

    σ the lowest rollers: :meth:`OmniHybrid.kinetic_energy`, vectorised.
    """
    geo = _geometry(model, np.asarray(thetas, float))
    H, ks = geo.H, geo.ks
    m = (model.wheel_inertia * H.transpose(0, 2, 1) @ H
         + model.roller_axial * ks.transpose(0, 2, 1) @ ks)
    m += np.diag([model.mass, model.mass, model.inertia[2, 2]])
    return 0.5 * np.einsum("ni,nij,nj->n", twists, m, twists)


def rolling_rates(model: OmniHybrid, twists: np.ndarray, thetas: np.ndarray) -> np.ndarray:
    """``θ̇ = H(σ) ν`` of (N, 3) twists at (N, 3) wheel angles (σ the lowest rollers)."""
    H = _geometry(model, np.asarray(thetas, float)).H
    return (H @ np.asarray(twists, float)[..., None])[..., 0]
