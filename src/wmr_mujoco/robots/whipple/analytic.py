"""Linearised Whipple bicycle (Meijaard, Papadopoulos, Ruina & Schwab 2007, Appendix A).

About upright straight-ahead rolling at forward speed ``v`` (rear-wheel contact speed), the
lean φ and steer δ of the knife-edge, no-slip bicycle obey

    M q̈ + v C1 q̇ + (g K0 + v² K2) q = f,    q = (φ, δ),  f = (T_φ, T_δ).

Every entry is a formula of :class:`~wmr_mujoco.robots.whipple.params.WhippleParams` (paper
frame: x forward, y right, z down, origin at the rear contact). Whole-bicycle sums:

    m_T = m_R + m_B + m_H + m_F
    x_T = (x_B m_B + x_H m_H + w m_F) / m_T
    z_T = (-r_R m_R + z_B m_B + z_H m_H - r_F m_F) / m_T
    I_Txx = I_Rxx + I_Bxx + I_Hxx + I_Fxx + m_R r_R² + m_B z_B² + m_H z_H² + m_F r_F²
    I_Txz = I_Bxz + I_Hxz - m_B x_B z_B - m_H x_H z_H + m_F w r_F
    I_Tzz = I_Rxx + I_Bzz + I_Hzz + I_Fxx + m_B x_B² + m_H x_H² + m_F w²

Front assembly A = H + F (mass m_A, CoM (x_A, z_A), inertia I_A about its CoM), and the
perpendicular distance of its CoM ahead of the steer axis

    u_A = (x_A - w - c) cos λ - z_A sin λ,

its inertia about the steer axis and the products with the x and z axes through the rear
contact:

    I_Aλλ = m_A u_A² + I_Axx sin²λ + 2 I_Axz sin λ cos λ + I_Azz cos²λ
    I_Aλx = -m_A u_A z_A + I_Axx sin λ + I_Axz cos λ
    I_Aλz =  m_A u_A x_A + I_Axz sin λ + I_Azz cos λ

With the trail ratio ``μ = c cos λ / w``, the gyrostatic coefficients
``S_R = I_Ryy / r_R``, ``S_F = I_Fyy / r_F``, ``S_T = S_R + S_F`` and the static moment
``S_A = m_A u_A + μ m_T x_T``:

    M  = [[I_Txx, I_Aλx + μ I_Txz], [·, I_Aλλ + 2 μ I_Aλz + μ² I_Tzz]]
    K0 = [[m_T z_T, -S_A], [-S_A, -S_A sin λ]]
    K2 = [[0, (S_T - m_T z_T) cos λ / w], [0, (S_A + S_F sin λ) cos λ / w]]
    C1 = [[0, μ S_T + S_F cos λ + I_Txz cos λ / w - μ m_T z_T],
          [-(μ S_T + S_F cos λ), I_Aλz cos λ / w + μ (S_A + I_Tzz cos λ / w)]]

The first-order form ``ẋ = A(v) x`` with ``x = (φ, δ, φ̇, δ̇)`` has

    A(v) = [[0, I], [-M⁻¹ (g K0 + v² K2), -v M⁻¹ C1]].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from wmr_mujoco.robots.whipple.params import DEFAULT_PARAMS, WhippleParams


@dataclass(frozen=True)
class WhippleMatrices:
    """The benchmark's coefficient matrices (SI units: kg m², kg m, kg m² ... per entry)."""

    M: np.ndarray
    C1: np.ndarray
    K0: np.ndarray
    K2: np.ndarray
    gravity: float


def matrices(p: WhippleParams = DEFAULT_PARAMS) -> WhippleMatrices:
    """``M, C1, K0, K2`` of the benchmark from the parameters (Appendix A formulas)."""
    w, c, lam, g = p.wheelbase, p.trail, p.head_angle, p.gravity
    rr, mr = p.rear_radius, p.rear_mass
    irxx, iryy = p.rear_inertia
    xb, zb = p.rear_frame_com
    mb = p.rear_frame_mass
    ibxx, _, ibzz, ibxz = p.rear_frame_inertia
    xh, zh = p.front_frame_com
    mh = p.front_frame_mass
    ihxx, _, ihzz, ihxz = p.front_frame_inertia
    rf, mf = p.front_radius, p.front_mass
    ifxx, ifyy = p.front_inertia

    mt = mr + mb + mh + mf
    xt = (xb * mb + xh * mh + w * mf) / mt
    zt = (-rr * mr + zb * mb + zh * mh - rf * mf) / mt
    itxx = irxx + ibxx + ihxx + ifxx + mr * rr**2 + mb * zb**2 + mh * zh**2 + mf * rf**2
    itxz = ibxz + ihxz - mb * xb * zb - mh * xh * zh + mf * w * rf
    itzz = irxx + ibzz + ihzz + ifxx + mb * xb**2 + mh * xh**2 + mf * w**2

    ma = mh + mf
    xa = (xh * mh + w * mf) / ma
    za = (zh * mh - rf * mf) / ma
    iaxx = ihxx + ifxx + mh * (zh - za) ** 2 + mf * (rf + za) ** 2
    iaxz = ihxz - mh * (xh - xa) * (zh - za) + mf * (w - xa) * (rf + za)
    iazz = ihzz + ifxx + mh * (xh - xa) ** 2 + mf * (w - xa) ** 2
    ua = (xa - w - c) * math.cos(lam) - za * math.sin(lam)
    sl, cl = math.sin(lam), math.cos(lam)
    iall = ma * ua**2 + iaxx * sl**2 + 2.0 * iaxz * sl * cl + iazz * cl**2
    ialx = -ma * ua * za + iaxx * sl + iaxz * cl
    ialz = ma * ua * xa + iaxz * sl + iazz * cl

    mu = c * cl / w
    sr, sf = iryy / rr, ifyy / rf
    st = sr + sf
    sa = ma * ua + mu * mt * xt

    m_phd = ialx + mu * itxz
    M = np.array([[itxx, m_phd], [m_phd, iall + 2.0 * mu * ialz + mu**2 * itzz]])
    K0 = np.array([[mt * zt, -sa], [-sa, -sa * sl]])
    K2 = np.array([[0.0, (st - mt * zt) * cl / w], [0.0, (sa + sf * sl) * cl / w]])
    C1 = np.array([[0.0, mu * st + sf * cl + itxz * cl / w - mu * mt * zt],
                   [-(mu * st + sf * cl), ialz * cl / w + mu * (sa + itzz * cl / w)]])
    return WhippleMatrices(M=M, C1=C1, K0=K0, K2=K2, gravity=g)


def state_matrix(v: float, mats: WhippleMatrices) -> np.ndarray:
    """``A(v) = [[0, I], [-M⁻¹ (g K0 + v² K2), -v M⁻¹ C1]]`` for ``x = (φ, δ, φ̇, δ̇)``."""
    minv = np.linalg.inv(mats.M)
    stiff = mats.gravity * mats.K0 + v**2 * mats.K2
    top = np.hstack([np.zeros((2, 2)), np.eye(2)])
    bottom = np.hstack([-minv @ stiff, -v * minv @ mats.C1])
    return np.vstack([top, bottom])


def eigenvalues(v: float, mats: WhippleMatrices) -> np.ndarray:
    """The four eigenvalues of ``A(v)``, s⁻¹, sorted by real part then imaginary part."""
    ev = np.linalg.eigvals(state_matrix(v, mats))
    return ev[np.lexsort((ev.imag, ev.real))]


@dataclass(frozen=True)
class Modes:
    """The benchmark's named modes at one speed (NaN where a mode does not exist).

    Attributes:
        weave: the eigenvalue of the complex pair with positive imaginary part.
        capsize: the real eigenvalue nearest zero (of the two real ones beside weave).
        castering: the large negative real eigenvalue.
    """

    weave: complex
    capsize: float
    castering: float


def classify(ev: np.ndarray, imag_tol: float = 1e-9) -> Modes:
    """Name the modes of four eigenvalues.

    A complex pair is weave; of the two real ones the more negative is castering and the
    other capsize.

    Below the speed (≈ 0.7 m/s for the benchmark) where weave splits into two real
    eigenvalues there is no pair: the modes are returned as NaN.
    """
    ev = np.asarray(ev, complex)
    cplx = ev[np.abs(ev.imag) > imag_tol * np.maximum(1.0, np.abs(ev))]
    real = np.sort(ev[np.abs(ev.imag) <= imag_tol * np.maximum(1.0, np.abs(ev))].real)
    if len(cplx) != 2 or len(real) != 2:
        return Modes(weave=complex(np.nan, np.nan), capsize=np.nan, castering=np.nan)
    weave = cplx[np.argmax(cplx.imag)]
    return Modes(weave=complex(weave), capsize=float(real[1]), castering=float(real[0]))


def modes(v: float, mats: WhippleMatrices) -> Modes:
    """The named modes of the analytic model at speed ``v``."""
    return classify(eigenvalues(v, mats))


def weave_speed(mats: WhippleMatrices, bracket: tuple[float, float] = (2.0, 5.5)) -> float:
    """Speed where the weave pair's real part crosses zero, by ``brentq``, m/s."""
    return brentq(lambda v: modes(v, mats).weave.real, *bracket, xtol=1e-12)


def capsize_speed(mats: WhippleMatrices, bracket: tuple[float, float] = (5.0, 8.0)) -> float:
    """Speed where the capsize eigenvalue crosses zero, by ``brentq``, m/s."""
    return brentq(lambda v: modes(v, mats).capsize, *bracket, xtol=1e-12)


def eigen_series(speeds: np.ndarray, mats: WhippleMatrices) -> np.ndarray:
    """Eigenvalues at each speed, shape ``(len(speeds), 4)`` (for the figure)."""
    return np.array([eigenvalues(float(v), mats) for v in speeds])
