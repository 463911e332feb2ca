"""MuJoCo's soft contact in closed form: impedance, and how fast friction removes a slip.

MuJoCo solves each constraint row for the acceleration (MuJoCo documentation,
*Computation*, "Solver parameters")

    a₁ + d (b v + k r) = (1 − d) a₀,

``a₀`` the unconstrained acceleration, ``v`` and ``r`` the row's velocity and violation,
``d ∈ (0, 1)`` the impedance of ``solimp = (d₀, d_w, width, mid, p)`` at the violation
(:func:`impedance`), and, for ``solref = (t_c, ζ)`` with ``t_c > 0``,

    b = 2 / (d_w t_c),    k = d / (d_w² t_c² ζ²),

or, for the direct form ``solref = (−K, −B)``, ``b = B / d_w`` and ``k = K / d_w²``
(:func:`friction_damping`; a contact pair's friction rows take its ``solreffriction``
where it is set),

with ``t_c`` raised to ``2 Δt`` where it is shorter (MuJoCo's ``refsafe``, on unless
disabled). A friction row has no position term (``k r`` absent). MuJoCo's regulariser of
a row is ``R = (1 − d)/d · Â``, Â its diagonal approximation of the row's inverse
inertia; in an elliptic cone the friction rows' is the normal row's divided by
``impratio``. A row whose true inverse inertia A equals Â (a point mass on its contact:
the exact case) then behaves as the row of impedance

    d_f = d · impratio / (d · impratio + 1 − d);

for ``A = a Â`` it is ``a / (a + (1 − d_f)/d_f)``, between ``d_f`` and 1 for ``a ≥ 1`` (a
body that also turns at the contact), so ρ below is then high by at most
``Δt b (1 − d_f)``.

A gripping contact's slip ``s`` (tangential velocity, ``a₀ ≈ 0`` over a step) therefore
follows ``ṡ = −d_f b s``, which MuJoCo's step (the velocity updated from the force at the
step's start) discretises as

    s_{n+1} = ρ s_n,    ρ = 1 − Δt d_f b                                  (slip_relaxation)

per step Δt: at ``Δt = t_c/2`` and ``d_f → d_w``, ρ → 0 (the slip gone in one step; a
shorter ``t_c`` is raised to ``2 Δt``), at ``Δt = t_c/4`` about ½, and so on. The tests
check ρ against MuJoCo itself: a point mass (exact) and a free sphere (within the bound).
"""

from __future__ import annotations

import math
from collections.abc import Sequence


def impedance(violation: float, solimp: Sequence[float]) -> float:
    """MuJoCo's impedance ``d(r)`` of a constraint violated by ``r`` ≥ 0.

    With ``x = min(r / width, 1)`` and the sigmoid of ``mid`` and power ``p``:
    ``y = x^p / mid^(p−1)`` for ``x ≤ mid``, else ``y = 1 − (1 − x)^p / (1 − mid)^(p−1)``;
    ``d = d₀ + y (d_w − d₀)``.

    Args:
        violation: r, the penetration, m (≥ 0).
        solimp: ``(d₀, d_w, width, mid, p)`` as MuJoCo's ``solimp``.

    Raises:
        ValueError: a negative or non-finite violation, or a solimp outside MuJoCo's range
            (``0 < d₀, d_w < 1``, ``width > 0``, ``0 < mid < 1``, ``p ≥ 1``).
    """
    if not (math.isfinite(violation) and violation >= 0):
        raise ValueError(f"violation = {violation!r} m; valid range is [0, inf)")
    if len(solimp) != 5:
        raise ValueError(f"solimp = {tuple(solimp)!r}; give 5 numbers (d0, dwidth, width, "
                         "mid, power)")
    d0, dw, width, mid, power = (float(v) for v in solimp)
    if not (0 < d0 < 1 and 0 < dw < 1 and width > 0 and 0 < mid < 1 and power >= 1):
        raise ValueError(f"solimp = {tuple(solimp)!r}; needs 0 < d0, dwidth < 1, width > 0, "
                         "0 < mid < 1, power >= 1")
    x = min(violation / width, 1.0)
    if x <= mid:
        y = x ** power / mid ** (power - 1)
    else:
        y = 1.0 - (1.0 - x) ** power / (1.0 - mid) ** (power - 1)
    return d0 + y * (dw - d0)


def friction_impedance(d: float, impratio: float) -> float:
    """``d_f = d · impratio / (d · impratio + 1 − d)`` (module docstring).

    Raises:
        ValueError: ``d`` outside (0, 1) or ``impratio`` ≤ 0.
    """
    if not (0 < d < 1):
        raise ValueError(f"d = {d!r}; valid range is (0, 1)")
    if not (math.isfinite(impratio) and impratio > 0):
        raise ValueError(f"impratio = {impratio!r}; valid range is (0, inf)")
    return d * impratio / (d * impratio + 1.0 - d)


def friction_damping(timestep: float, solref: Sequence[float], solimp: Sequence[float],
                     refsafe: bool = True) -> float:
    """``b`` of a friction row with reference ``solref`` (its ``solreffriction`` if set).

    MuJoCo's two forms: ``(t_c, ζ)`` with ``t_c > 0`` gives ``b = 2 / (d_w t_c)``
    (``t_c`` raised to ``2 Δt`` by refsafe); the direct form ``(−K, −B)`` gives
    ``b = B / d_w`` (no refsafe), ``d_w = solimp[1]``.

    Raises:
        ValueError: a step ≤ 0, or a solref that is neither form.
    """
    if not (math.isfinite(timestep) and timestep > 0):
        raise ValueError(f"timestep = {timestep!r} s; valid range is (0, inf)")
    t_c, second = (float(v) for v in solref[:2])
    d_w = float(solimp[1])
    if t_c > 0:
        return 2.0 / (d_w * (max(t_c, 2.0 * timestep) if refsafe else t_c))
    if t_c <= 0 and second < 0:
        return -second / d_w
    raise ValueError(f"solref = {tuple(solref)!r}; give (timeconst > 0, dampratio) or the "
                     "direct form (-stiffness <= 0, -damping < 0)")


def slip_relaxation(timestep: float, timeconst: float, solimp: Sequence[float],
                    violation: float, impratio: float = 1.0, refsafe: bool = True,
                    friction_ref: Sequence[float] | None = None) -> float:
    """``ρ = 1 − Δt d_f b``: the share of a gripping contact's slip left after one step.

    Exact for a row whose inverse inertia is MuJoCo's diagonal approximation of it (a
    point mass on the contact); otherwise high by at most ``Δt b (1 − d_f)`` (module
    docstring).

    Args:
        timestep: Δt, s.
        timeconst: ``t_c`` of the contact's ``solref`` (friction rows: ``solreffriction``
            where a pair sets it), s.
        solimp: the contact's ``solimp``.
        violation: its penetration, m (the loaded contact's static one).
        impratio: MuJoCo's ``impratio`` (elliptic cones; 1 for pyramidal).
        refsafe: MuJoCo raises ``t_c`` to ``2 Δt`` (its ``refsafe``; False where the
            model disables it).
        friction_ref: the friction rows' own reference (a pair's ``solreffriction``,
            either form, :func:`friction_damping`); None or zeros: ``(timeconst, 1)``.

    Raises:
        ValueError: a non-positive step or time constant, or bad impedance input.
    """
    for name, value in (("timestep", timestep), ("timeconst", timeconst)):
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"{name} = {value!r} s; valid range is (0, inf)")
    d_f = friction_impedance(impedance(violation, solimp), impratio)
    ref = (timeconst, 1.0) if friction_ref is None or not any(friction_ref) else friction_ref
    return 1.0 - timestep * d_f * friction_damping(timestep, ref, solimp, refsafe)
