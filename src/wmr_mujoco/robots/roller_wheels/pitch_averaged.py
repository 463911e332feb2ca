"""Roller-pitch-averaged kinematics of wheels with a finite number of rollers.

Lynch & Park's wheel formula (:mod:`wmr_mujoco.robots.roller_wheels.omni_kinematics`) takes the
contact roller's axis horizontal. A real wheel with ``n`` rollers touches the floor with a
roller tilted by the wheel angle φ from that roller's middle, ``φ ∈ [−π/n, π/n]``; the
direction its contact cannot slide along turns to (docs/mecanum.md §3)::

    tan γ_eff(φ) = tan γ / cos φ.

For a wheel driving along ``x̂`` (β = 0) with contact velocity ``v_c`` the instantaneous
rolling constraint is ``R θ̇ = v_cx + v_cy tan γ sec φ``. The wheel turns uniformly, so over
one roller pitch φ is uniform on ``[−φ_m, φ_m]``, ``φ_m = π/n``, and the mean constraint is

    R θ̇ = v_cx + v_cy tan γ ⟨sec φ⟩,     ⟨sec φ⟩ = artanh(sin φ_m) / φ_m
                                                  = ln(sec φ_m + tan φ_m) / φ_m,

which is Lynch & Park's constraint for the **pitch-averaged roller angle**

    tan γ̄ = ⟨sec φ⟩ tan γ.

A wheel held at rest does not sweep its rollers: its contact roller stays at the rest
phase φ₀ and its constraint is the instantaneous one, ``sec φ₀`` for ``⟨sec φ⟩``
(``mecanum4`` rests with a roller's middle at the bottom, φ₀ = 0: the ideal constraint).
So the averaged model depends on which wheels turn; driving along a diagonal of
``mecanum4`` only two wheels turn.

Driven by wheel rates from the ideal formula, ``θ̇ = H(γ) ν_cmd``, the chassis moves at the
twist that satisfies the averaged constraints, ``H(γ̄) ν = H(γ) ν_cmd`` (solved in the least
squares sense where the wheels over-constrain the chassis; exact for ``mecanum4``, whose
columns of ``H(γ)`` and ``H(γ̄)`` span the same space). For ``mecanum4`` (wheels at
``(±a, ±w)``, γ = ±45°) this gives ``u = u_cmd``, ``v = v_cmd / ⟨sec φ⟩`` and
``r = r_cmd (a + w) / (a ⟨sec φ⟩ + w)``: sideways runs fall short by
``1 − 1/⟨sec φ⟩ ≈ φ_m²/6`` and turns by about half that. With ``γ = 0`` (omni wheels) the
average changes nothing: their rollers' tilt does not turn a constraint along the axle.
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok


def roller_half_pitch(rollers: int) -> float:
    """``φ_m = π / n``: the contact hands over to the next roller at ``±π/n``.

    Raises:
        ValueError: ``rollers`` is not an integer ≥ 2.
    """
    if isinstance(rollers, bool) or not isinstance(rollers, (int, np.integer)) or rollers < 2:
        raise ValueError(f"rollers = {rollers!r}; valid values are integers >= 2")
    return math.pi / int(rollers)


def mean_secant(half_span: float) -> float:
    """``⟨sec φ⟩`` over ``φ ∈ [−φ_m, φ_m]``: ``artanh(sin φ_m) / φ_m``.

    Raises:
        ValueError: ``half_span`` outside ``(0, π/2)``.
    """
    if not (math.isfinite(half_span) and 0.0 < half_span < math.pi / 2.0):
        raise ValueError(f"half_span = {half_span!r} rad; valid range is (0, π/2)")
    return math.atanh(math.sin(half_span)) / half_span


def averaged_layout(layout: ok.WheelLayout, rollers: int,
                    turning: np.ndarray | None = None) -> ok.WheelLayout:
    """Roller angles ``atan(⟨sec φ⟩ tan γ)`` (φ_m = π/n) on the wheels that turn.

    Args:
        layout: the ideal layout.
        rollers: rollers per wheel, n.
        turning: (n_wheels,) which wheels turn (None: all); the others keep ``γ``
            (rest phase φ₀ = 0).
    """
    k = mean_secant(roller_half_pitch(rollers))
    mask = np.ones(layout.n, bool) if turning is None else np.asarray(turning, bool)
    if mask.shape != (layout.n,):
        raise ValueError(f"turning has shape {mask.shape}; need ({layout.n},)")
    gamma = np.where(mask, np.arctan(k * np.tan(layout.roller_angles)), layout.roller_angles)
    return ok.WheelLayout(layout.positions, layout.drive_angles, gamma, layout.radii)


def realised_twist_map(layout: ok.WheelLayout, rollers: int,
                       turning: np.ndarray | None = None) -> np.ndarray:
    """``S`` with ``ν = S ν_cmd``: the averaged model's twist under ideal wheel rates.

    ``S = H(γ̄)⁺ H(γ)`` (Moore-Penrose pseudo-inverse; least squares over the wheels),
    with γ̄ on the ``turning`` wheels (:func:`averaged_layout`).
    """
    ideal = ok.wheel_jacobian(layout)
    averaged = ok.wheel_jacobian(averaged_layout(layout, rollers, turning))
    return np.linalg.pinv(averaged) @ ideal
