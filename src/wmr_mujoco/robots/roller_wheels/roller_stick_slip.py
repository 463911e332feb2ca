"""Stick–slip step response of a platform on free-roller wheels driven by rate servos.

The dynamic model behind ``mecanum4``'s step commands (derivation: docs/mecanum.md §4).
Generalised velocities ``q̇ = (ν, ω)``: body twist ``ν = (u, v, r)`` and the wheel rates
``ω``. Mass matrix ``M = diag(m, m, I_z, I_w, …, I_w)`` (total mass, yaw inertia about
the centre, each wheel's spin inertia with its rotor's armature). Forces:

* rate servo on wheel i: ``τ_i = clip(k_v (ω_cmd,i − ω_i), ±τ_max)``;
* body-frame rigid-body term ``c(ν) = (−m r v, m r u, 0)``;
* at each contact a force ``F_i`` along the contact roller's axis
  ``e_i = (cos(β_i+γ_i), sin(β_i+γ_i))`` only (the roller turns freely about it), with
  ``|F_i| ≤ μ N_i`` (Coulomb). Its slip velocity and generalised direction are the row

      s_i = J_i q̇ = g_iᵀ ν − R_i cos γ_i ω_i,     g_i = (e_i, p_i × e_i),

  (the contact's velocity along ``e_i`` less the rim's), and ``F_i`` acts on ``q̇`` as
  ``J_iᵀ F_i`` (virtual power ``F_i s_i``). Stick: ``s_i = 0, |F_i| ≤ μ N_i``; slip:
  ``F_i = −μ N_i sign(s_i)``.

Equations: ``M q̈ = (−c(ν), τ) + Jᵀ F``. Loads: ``N_i = m g/4`` plus the quasi-static
transfer of a centre of mass at height ``h`` under the body acceleration
``(a_x, a_y) = (u̇ − r v, v̇ + r u)``, the least-squares split over the wheels of the
pitch and roll moments ``−m h a``::

    N_i = m g / n − m h (a_x x_i / Σ x_j² + a_y y_i / Σ y_j²).

Integration: Moreau time-stepping at a small step ``h_s``: servo and rigid-body forces at
the step's start, then the contact impulses ``P = F h_s`` from the box-constrained LCP
``s⁺ = J q̇_free + W P``, ``W = J M⁻¹ Jᵀ`` (the Delassus matrix), ``|P_i| ≤ μ N_i h_s``
with ``P_i`` at ``∓`` its bound where ``s⁺_i ≷ 0`` (:func:`box_lcp`). Loads use the
previous step's acceleration. First order in ``h_s``.
"""

from __future__ import annotations

import functools
import itertools
from collections.abc import Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from wmr_mujoco.analytic.checks import as_array
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.roller_traction import traction_directions
from wmr_mujoco.robots.roller_wheels.stick_slip_batch import march_many
from wmr_mujoco.robots.roller_wheels.stick_slip_steps import march, moreau_step

#: Standard gravity, m/s².
GRAVITY = 9.81
#: Default internal step, s: well below the servo's time constant ``I_w / k_v``
#: (2.1 ms for ``mecanum4``) and the traction-limited rise times (10–60 ms). The scheme
#: is first order: for ``mecanum4``'s steps the lag ``∫(ν_end − ν) dt`` moves by 0.015 mm
#: (0.3 m/s) and 0.04 mrad (1 rad/s) from this step to its Richardson limit.
STEP = 1e-4


@dataclass(frozen=True)
class RollerPlatform:
    """Inertia, drive law and contact law of a free-roller platform.

    Attributes:
        layout: wheel geometry (body frame); its roller angles are the contact
            constraint directions (pass the pitch-averaged ones where they apply).
        mass: total mass m, kg.
        yaw_inertia: total yaw inertia I_z about the centre, kg·m².
        wheel_inertia: spin inertia I_w of a wheel, armature included, kg·m².
        servo_gain: k_v of the rate servos, N·m·s/rad.
        torque_limit: τ_max of the servos, N·m.
        friction: Coulomb coefficient μ at the contacts.
        com_height: height h of the centre of mass over the contacts, m (0: no load
            transfer).
        gravity: g, m/s².
    """

    layout: ok.WheelLayout
    mass: float
    yaw_inertia: float
    wheel_inertia: float
    servo_gain: float
    torque_limit: float
    friction: float
    com_height: float = 0.0
    gravity: float = GRAVITY

    def __post_init__(self) -> None:
        if not isinstance(self.layout, ok.WheelLayout):
            raise ValueError(f"layout must be a WheelLayout, got {type(self.layout).__name__}")
        for name in ("mass", "yaw_inertia", "wheel_inertia", "servo_gain", "torque_limit",
                     "friction", "gravity"):
            value = getattr(self, name)
            if not (np.isfinite(value) and value > 0.0):
                raise ValueError(f"RollerPlatform.{name} = {value!r}; valid range is "
                                 "(0, inf)")
        if not (np.isfinite(self.com_height) and 0.0 <= self.com_height <= 10.0):
            raise ValueError(f"RollerPlatform.com_height = {self.com_height!r} m; valid "
                             "range is [0, 10]")
        pos = self.layout.positions
        if self.com_height > 0.0 and (np.sum(pos[:, 0] ** 2) == 0.0
                                      or np.sum(pos[:, 1] ** 2) == 0.0):
            raise ValueError("com_height > 0 needs wheels off both body axes (load "
                             "transfer splits the moments over x_i and y_i)")

    @functools.cached_property
    def jacobian(self) -> np.ndarray:
        """(n, 3 + n) slip rows ``J_i = [g_iᵀ, −R_i cos γ_i e_iᵀ]``."""
        lay = self.layout
        return np.hstack([traction_directions(lay).T,
                          -np.diag(lay.radii * np.cos(lay.roller_angles))])

    @functools.cached_property
    def inverse_mass(self) -> np.ndarray:
        """``M⁻¹``, diagonal (n + 3,)."""
        return 1.0 / np.concatenate([[self.mass, self.mass, self.yaw_inertia],
                                     np.full(self.layout.n, self.wheel_inertia)])

    @functools.cached_property
    def delassus(self) -> np.ndarray:
        """``W = J M⁻¹ Jᵀ``: slip velocity change per unit contact impulse."""
        j = self.jacobian
        return (j * self.inverse_mass) @ j.T

    @functools.cached_property
    def _transfer(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Static loads and the load change per unit ``a_x`` and ``a_y``."""
        pos = self.layout.positions
        base = np.full(self.layout.n, self.mass * self.gravity / self.layout.n)
        if self.com_height == 0.0:
            return base, np.zeros(self.layout.n), np.zeros(self.layout.n)
        moment = self.mass * self.com_height
        return (base, -moment * pos[:, 0] / np.sum(pos[:, 0] ** 2),
                -moment * pos[:, 1] / np.sum(pos[:, 1] ** 2))

    def loads(self, accel: np.ndarray) -> np.ndarray:
        """Wheel loads ``N_i`` under body acceleration ``(a_x, a_y)`` (module docstring)."""
        a = as_array("accel", accel, (2,))
        base, per_ax, per_ay = self._transfer
        return base + a[0] * per_ax + a[1] * per_ay

    def servo_torques(self, rates: np.ndarray, commanded: np.ndarray) -> np.ndarray:
        """``clip(k_v (ω_cmd − ω), ±τ_max)``."""
        # np.clip's floats (NaN kept) without its per-call cost: a step calls this
        return np.minimum(np.maximum(self.servo_gain * (commanded - rates), -self.torque_limit),
                          self.torque_limit)


@functools.lru_cache(maxsize=8)
def _states(n: int) -> tuple[tuple[int, ...], ...]:
    """Every contact state (−1: at −bound, 0: stick, +1: at +bound), sticking first."""
    states = list(itertools.product((0, 1, -1), repeat=n))
    return tuple(sorted(states, key=lambda s: sum(map(abs, s))))


class _ActiveSet(NamedTuple):
    """One contact state of :class:`BoxLcp`: its signs, ``−W_FF⁻¹``, ``W_FB`` and indices."""

    signs: list[float]
    neg_inv: np.ndarray | None
    w_fa: np.ndarray | None
    free: np.ndarray
    bound: np.ndarray
    free_list: list[int]
    upper: list[int]
    lower: list[int]


class BoxLcp:
    """Coulomb impulses along fixed directions: the box-constrained LCP of one ``W``.

    Find ``P`` with ``s = s_free + W P`` such that for each i: ``|P_i| ≤ b_i`` and
    ``P_i = −b_i`` if ``s_i > 0``, ``P_i = +b_i`` if ``s_i < 0``, ``s_i = 0`` otherwise.
    Solved by active sets: a guess first (the previous step's), then every one of the
    ``3ⁿ`` sets, sticking contacts first; W symmetric positive definite makes the
    solution exist and be unique. For a set with free (sticking) contacts F and bound ones
    B: ``P_B = ±b_B``, ``P_F = −W_FF⁻¹ (s_free,F + W_FB P_B)``; it is the solution if
    ``|P_F| ≤ b_F`` and each bound contact slides away from its bound's sign. Each set's
    ``−W_FF⁻¹`` is kept once computed.
    """

    def __init__(self, delassus: np.ndarray) -> None:
        self.w = np.asarray(delassus, float)
        self._sets: dict[tuple[int, ...], _ActiveSet] = {}

    def _set(self, state: tuple[int, ...]) -> _ActiveSet:
        got = self._sets.get(state)
        if got is None:
            st = np.asarray(state)
            free = st == 0
            neg_inv = w_fa = None
            if np.any(free):
                neg_inv = -np.linalg.inv(self.w[np.ix_(free, free)])
                w_fa = self.w[np.ix_(free, ~free)]
            got = _ActiveSet([float(x) for x in state], neg_inv, w_fa, np.flatnonzero(free),
                             np.flatnonzero(~free), np.flatnonzero(free).tolist(),
                             np.flatnonzero(st > 0).tolist(), np.flatnonzero(st < 0).tolist())
            self._sets[state] = got
        return got

    def solve(self, slip_free: np.ndarray, bounds: np.ndarray,
              guess: tuple[int, ...] | None = None, tol: float = 1e-12
              ) -> tuple[np.ndarray, tuple[int, ...]]:
        """``(P, state)``, ``state_i`` −1, 0 or +1 (at −b, stick, at +b).

        Raises:
            ValueError: no active set satisfies the conditions (W not positive definite).
        """
        slip_free = np.asarray(slip_free, float)
        p, _, state = self.solve_slip(slip_free, slip_free.tolist(),
                                      np.asarray(bounds, float).tolist(), guess, tol)
        return p, state

    def solve_slip(self, slip_free: np.ndarray, sf: list[float], bounds: list[float],
                   guess: tuple[int, ...] | None = None, tol: float = 1e-12
                   ) -> tuple[np.ndarray, np.ndarray, tuple[int, ...]]:
        """:meth:`solve` with ``s⁺ = s_free + W P``: ``(P, s⁺, state)``.

        ``sf`` and ``bounds`` as Python floats (``sf``: ``slip_free.tolist()``): a Moreau
        step calls this with vectors of 4 entries, where numpy's per-call cost would be
        most of the work; the products of a matrix and a vector stay numpy's (BLAS).
        """
        # scale = tol (1 + max|s_free|), the tolerance of the slip's sign
        scale = tol * (1.0 + max(abs(x) for x in sf))
        w = self.w
        states = _states(len(bounds))
        for state in (states if guess is None else (guess, *states)):
            signs, neg_inv, w_fa, free, bound, free_list, upper, lower = self._set(state)
            p = np.array([si * bi for si, bi in zip(signs, bounds, strict=True)])  # ±b
            if neg_inv is not None:
                if bound.size == 0:  # s_free[F] + W_FB P_B with B empty: + zeros(n)
                    rhs = slip_free + 0.0
                else:
                    rhs = slip_free[free] + w_fa @ p[bound]
                pf = neg_inv @ rhs
                p[free] = pf
                if any(abs(x) > bounds[i] * (1.0 + 1e-9) + 1e-15
                       for x, i in zip(pf.tolist(), free_list, strict=True)):
                    continue
            s = slip_free + w @ p
            sl = s.tolist()
            if all(sl[i] <= scale for i in upper) and all(sl[i] >= -scale for i in lower):
                return p, s, state
        raise ValueError("box_lcp: no contact state satisfies the Coulomb conditions")


def box_lcp(delassus: np.ndarray, slip_free: np.ndarray, bounds: np.ndarray,
            guess: tuple[int, ...] | None = None) -> tuple[np.ndarray, tuple[int, ...]]:
    """One solve of :class:`BoxLcp` (see there)."""
    return BoxLcp(delassus).solve(np.asarray(slip_free, float), np.asarray(bounds, float),
                                  guess)


@dataclass(frozen=True)
class StepResponse:
    """A run of :func:`step_response` on its grid of internal steps.

    Attributes:
        time: (K,) s, from 0.
        twist: (K, 3) body twist ``(u, v, r)``.
        wheel_rates: (K, n) ω, rad/s.
        forces: (K, n) roller-axis contact forces ``F_i = P_i / h_s``, N (on the step that
            ends at ``time``; 0 at ``time = 0``).
        loads: (K, n) wheel loads ``N_i``, N.
        stuck: (K, n) whether each contact sticks.
        dissipated: (K,) friction work dissipated so far, ``−Σ P·s⁺`` summed, J.
    """

    time: np.ndarray
    twist: np.ndarray
    wheel_rates: np.ndarray
    forces: np.ndarray
    loads: np.ndarray
    stuck: np.ndarray
    dissipated: np.ndarray

    def twist_at(self, t: float) -> np.ndarray:
        """``ν(t)``, linear between steps; the last value after the end (steady)."""
        return np.array([np.interp(t, self.time, self.twist[:, k]) for k in range(3)])

    @property
    def rise_time(self) -> float:
        """The time from which every contact sticks to the end of the run, s."""
        slipping = np.flatnonzero(~np.all(self.stuck, axis=1))
        return 0.0 if slipping.size == 0 else float(self.time[slipping[-1]])


def advance(platform: RollerPlatform, lcp: BoxLcp, q_dot: np.ndarray,
            commanded: np.ndarray, accel: np.ndarray, step: float,
            guess: tuple[int, ...] | None = None
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray, tuple[int, ...], np.ndarray,
                       np.ndarray]:
    """One Moreau step of the velocities ``q̇ = (ν, ω)`` (module docstring).

    ``q̇_free = q̇ + h_s M⁻¹ (−c(ν), τ(ω))``; loads from the previous acceleration
    ``accel = (a_x, a_y)`` (negative ones clipped to 0: a wheel lifts off); impulses
    ``P`` from the box LCP with bounds ``μ N_i h_s``; ``q̇⁺ = q̇_free + M⁻¹ Jᵀ P``. The
    step is :func:`~wmr_mujoco.robots.roller_wheels.stick_slip_steps.moreau_step`'s (the
    one definition, on Python floats), on arrays.

    Returns:
        ``(q̇⁺, P, s⁺, contact state, loads, (a_x, a_y) of this step)``.
    """
    one = moreau_step(platform, lcp, step)
    q, p, slip, state, loads, ax, ay = one(
        np.asarray(q_dot, float).tolist(), np.asarray(commanded, float).tolist(),
        float(accel[0]), float(accel[1]), guess)
    return np.array(q), p, slip, state, np.array(loads), np.array([ax, ay])


def _check_run(duration: float, step: float) -> None:
    """Raise ValueError for a bad duration or internal step (before any work)."""
    if not (np.isfinite(duration) and duration > 0.0):
        raise ValueError(f"duration = {duration!r} s; valid range is (0, inf)")
    if not (np.isfinite(step) and 0.0 < step <= 1e-3):
        raise ValueError(f"step = {step!r} s; valid range is (0, 1e-3]")


def step_response(platform: RollerPlatform, commanded: np.ndarray, duration: float,
                  step: float = STEP, settle_tol: float = 1e-9,
                  chunk: float = 0.05) -> StepResponse:
    """From rest, wheel rates commanded to ``commanded`` at t = 0 and held.

    Integrated until ``duration`` or, earlier, until a whole ``chunk`` of time passes with
    every contact sticking and the twist changing by less than ``settle_tol`` (m/s,
    rad/s): the body-frame equations are autonomous under a held command, so the twist
    then stays at that fixed point (:meth:`StepResponse.twist_at` holds the last value).

    Raises:
        ValueError: a bad duration or step, a command of the wrong shape, or a run that
            diverges (non-finite state).
    """
    cmd = as_array("commanded", commanded, (platform.layout.n,))
    _check_run(duration, step)
    rows = march(platform, BoxLcp(platform.delassus), cmd, round(duration / step),
                 max(1, round(chunk / step)), step, settle_tol)
    return _response(platform, rows, step)


def step_responses(platforms: Sequence[RollerPlatform], commanded: Sequence[np.ndarray],
                   duration: float, step: float = STEP, settle_tol: float = 1e-9,
                   chunk: float = 0.05) -> list[StepResponse | None]:
    """:func:`step_response` of each platform under its command, marched together.

    The same responses, to the bit, as one call each
    (:func:`~wmr_mujoco.robots.roller_wheels.stick_slip_batch.march_many`); None where
    that call raises (a run that diverges), so that it is run alone and says why.

    Raises:
        ValueError: a bad duration or step, commands of the wrong shape or number, or
            platforms of different wheel counts.
    """
    if len(platforms) != len(commanded):
        raise ValueError(f"{len(platforms)} platforms and {len(commanded)} commands; "
                         "one command per platform")
    if not platforms:
        return []
    cmds = [as_array("commanded", c, (p.layout.n,)) for p, c in zip(platforms, commanded,
                                                                     strict=True)]
    _check_run(duration, step)
    runs = march_many(platforms, [BoxLcp(p.delassus) for p in platforms], cmds,
                      round(duration / step), max(1, round(chunk / step)), step, settle_tol)
    return [None if rows is None else _response(p, rows, step)
            for p, rows in zip(platforms, runs, strict=True)]


def _response(platform: RollerPlatform, rows: dict[str, list], step: float) -> StepResponse:
    """The :class:`StepResponse` of a march's rows (row 0: the start at rest)."""
    n = platform.layout.n
    q = np.concatenate([np.zeros((1, 3 + n)), np.asarray(rows["q"]).reshape(-1, 3 + n)])
    return StepResponse(
        time=np.asarray([0.0, *rows["time"]]), twist=q[:, :3], wheel_rates=q[:, 3:],
        forces=np.concatenate([np.zeros((1, n)),
                               np.asarray(rows["p"]).reshape(-1, n) / step]),
        loads=np.concatenate([platform.loads(np.zeros(2))[None],
                              np.asarray(rows["loads"]).reshape(-1, n)]),
        stuck=np.concatenate([np.ones((1, n), bool),
                              np.asarray(rows["state"]).reshape(-1, n) == 0]),
        dissipated=np.asarray([0.0, *rows["dissipated"]]))
