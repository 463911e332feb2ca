"""Steer into the lean: keeping the Whipple bicycle upright below its weave speed.

The linearised Whipple bicycle (Meijaard et al. 2007; :mod:`wmr_mujoco.robots.whipple.analytic`)
with the steer torque ``T_δ`` as input, state ``x = (φ, δ, φ̇, δ̇)`` (lean and steer,
positive to the right):

    ẋ = A(v) x + B T_δ,   A(v) = [[0, I], [−M⁻¹(g K0 + v² K2), −v M⁻¹ C1]],
    B = [0, 0, (M⁻¹ e_δ)ᵀ]ᵀ,   e_δ = (0, 1).

Below the weave speed (≈ 4.29 m/s for the benchmark) ``A(v)`` has an eigenvalue with
positive real part: uncontrolled, the bicycle falls. The gain is the linear-quadratic
regulator of this model at the riding speed,

    T_δ = −K x,   K = R⁻¹ Bᵀ P,   Aᵀ P + P A − P B R⁻¹ Bᵀ P + Q = 0,

with Bryson's weights ``Q = diag(1/φ_m², 1/δ_m², 1/φ̇_m², 1/δ̇_m²)``, ``R = 1/T_m²``
(the largest acceptable lean, steer, rates and torque). ``A − B K`` is Hurwitz whenever
``(A, B)`` is stabilisable; :meth:`WhippleLean.closed_loop_eigenvalues` gives them.
Positive lean gains steer into the fall, as a rider does.

The command is the bicycle's actuators' ``(T_r, T_δ)``; the rear-wheel torque holds the
riding speed ``v`` by a proportional law with time constant ``τ_v``,

    T_r = (m_e r_R / τ_v) (v − u),   m_e = m_T + I_Ryy / r_R² + I_Fyy / r_F²,

``u`` the measured forward speed and ``m_e`` the longitudinal inertia seen at the rear
contact (mass plus both wheels' spin inertia): the speed error decays as ``e^{−t/τ_v}``.

The law is the robot's own (it reads the robot's linear model): the registry entry hands
it to the generic balancing scenarios (``Balance.law``, :func:`law`), with the linear
model under the same law (:func:`linear_leans`: ``ẋ = A(v) x + B T_δ`` from
``x₀ = (0, 0, φ̇₀, 0)``, the law held over each control period, exact zero-order-hold
discretisation ``[Φ Γ; 0 I] = exp([A B; 0 0] T)``).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from scipy.linalg import expm, solve_continuous_are

from wmr_mujoco.loop.control.base import CommandKind, Controller, StateLike, positive
from wmr_mujoco.models.params import params_or_default
from wmr_mujoco.robots.whipple import analytic as whipple
from wmr_mujoco.robots.whipple.params import DEFAULT_PARAMS, WhippleParams
from wmr_mujoco.robots.whipple.stability import FALLEN

#: The state the law reads from ``RobotState.extra``.
STATE_KEYS = ("lean", "steer", "lean_rate", "steer_rate")
#: Speeds of the upright claim, m/s (below the weave speed: it falls uncontrolled); the
#: nominal push, rad/s; the drawn push sizes, rad/s; the drawn speeds of the study, m/s.
SPEEDS, PUSH, PUSH_RANGE, SPEED_RANGE = (3.0, 2.0), 0.5, (0.25, 0.75), (2.0, 3.0)
#: Control period, s (the closed loop's fastest pole, ≈ −43 1/s, moves by λT = 0.09 per
#: period).
PERIOD = 0.002


@dataclass(frozen=True)
class BrysonWeights:
    """Largest acceptable excursions (Bryson's rule): rad, rad, rad/s, rad/s, N·m."""

    lean: float = 0.05
    steer: float = 0.1
    lean_rate: float = 0.5
    steer_rate: float = 1.0
    torque: float = 10.0

    def matrices(self) -> tuple[np.ndarray, np.ndarray]:
        """``(Q, R)``."""
        scale = [positive(n, getattr(self, n)) for n in STATE_KEYS]
        return np.diag(1.0 / np.square(scale)), np.array([[1.0 / positive(
            "torque", self.torque) ** 2]])


def input_matrix(mats: whipple.WhippleMatrices) -> np.ndarray:
    """``B`` for the steer torque: ``(0, 0, M⁻¹ e_δ)``, shape (4, 1)."""
    return np.concatenate([np.zeros(2), np.linalg.solve(mats.M, [0.0, 1.0])])[:, None]


def lqr_gain(speed: float, params: WhippleParams = DEFAULT_PARAMS,
             weights: BrysonWeights = BrysonWeights()) -> np.ndarray:
    """``K`` (shape (4,)) of the LQR at ``speed`` (module docstring).

    Solved once per (speed, parameters, weights): the laws of a family's members share it.
    """
    return _lqr_gain(positive("speed", speed), params, weights).copy()


@functools.lru_cache(maxsize=256)
def _lqr_gain(speed: float, params: WhippleParams, weights: BrysonWeights) -> np.ndarray:
    """:func:`lqr_gain`, kept (``A(v)ᵀP + PA(v) − PBR⁻¹BᵀP + Q = 0``, ``K = R⁻¹BᵀP``)."""
    mats = whipple.matrices(params)
    a, b = whipple.state_matrix(positive("speed", speed), mats), input_matrix(mats)
    q, r = weights.matrices()
    p = solve_continuous_are(a, b, q, r)
    return (np.linalg.solve(r, b.T @ p))[0]


class WhippleLean(Controller):
    """LQR steer-torque law at the riding speed (module docstring); writes ``(T_r, T_δ)``.

    Args:
        speed: riding speed the gain is designed for and the rear wheel is held at, m/s.
        params: the bicycle's parameters (the linear model's coefficients).
        weights: Bryson's weights.
        max_torque: steer and rear torque limit, N·m.
        speed_time: ``τ_v`` of the speed hold, s.
    """

    name = "whipple_lean"
    kinds = (CommandKind.WHIPPLE,)
    reference_type = "upright"

    def __init__(self, speed: float = 3.0, params: WhippleParams = DEFAULT_PARAMS,
                 weights: BrysonWeights = BrysonWeights(), max_torque: float = 100.0,
                 speed_time: float = 0.5) -> None:
        self.speed = positive("speed", speed)
        self.params = params
        self.gain = lqr_gain(self.speed, params, weights)
        self.gain.flags.writeable = False  # read-only: −K is kept
        self._negative = (self.gain, -self.gain)
        self.max_torque = positive("max_torque", max_torque)
        p = params
        m_e = (p.rear_mass + p.rear_frame_mass + p.front_frame_mass + p.front_mass
               + p.rear_inertia[1] / p.rear_radius**2 + p.front_inertia[1] / p.front_radius**2)
        #: ``m_e r_R / τ_v``, N·m per m/s.
        self.speed_gain = m_e * p.rear_radius / positive("speed_time", speed_time)
        super().__init__(CommandKind.WHIPPLE)

    def closed_loop_matrix(self, speed: float | None = None) -> np.ndarray:
        """``A(v) − B K`` at ``speed`` (default the design speed)."""
        mats = whipple.matrices(self.params)
        v = self.speed if speed is None else speed
        return whipple.state_matrix(v, mats) - input_matrix(mats) @ self.gain[None, :]

    def closed_loop_eigenvalues(self, speed: float | None = None) -> np.ndarray:
        """Eigenvalues of :meth:`closed_loop_matrix`, s⁻¹."""
        return np.linalg.eigvals(self.closed_loop_matrix(speed))

    def torque(self, x: np.ndarray) -> float:
        """``T_δ = −K x``, clipped to the limit."""
        gain, negative = self._negative
        if gain is not self.gain:  # a new gain: its −K
            self._negative = gain, negative = self.gain, -self.gain
        return _clip(float(negative @ x), self.max_torque)

    def __call__(self, state: StateLike, reference: None, t: float) -> np.ndarray:
        """``(T_r, T_δ)`` from the speed, lean and steer (``state.twist``, ``state.extra``).

        Raises:
            ValueError: ``state.extra`` lacks one of :data:`STATE_KEYS`.
        """
        missing = [k for k in STATE_KEYS if k not in state.extra]
        if missing:
            raise ValueError(f"state.extra lacks {missing}; the Whipple law reads {STATE_KEYS}")
        x = np.array([state.extra[k] for k in STATE_KEYS], float)
        rear = self.speed_gain * (self.speed - float(state.twist[0]))
        return np.array([_clip(rear, self.max_torque),
                         self.torque(x)])


def _clip(value: float, limit: float) -> float:
    """``value`` clipped to ``[−limit, limit]``: ``np.clip``'s float without its per-call cost."""
    return min(max(value, -limit), limit)


def law(speed: float, params: WhippleParams | None) -> WhippleLean:
    """The balancing law at ``speed`` (``Balance.law`` of the registry entry)."""
    return WhippleLean(speed, params_or_default(params, WhippleParams))


def linear_leans(speed: float, push: float, controlled: bool, params: WhippleParams | None,
                 duration: float, period: float) -> np.ndarray:
    """Leans of the linearised benchmark after the push, every period (module docstring).

    Stops after the first lean past :data:`~wmr_mujoco.robots.whipple.stability.FALLEN`.
    """
    p = params_or_default(params, WhippleParams)
    mats = whipple.matrices(p)
    a, b = whipple.state_matrix(positive("speed", speed), mats), input_matrix(mats)
    big = np.zeros((5, 5))
    big[:4, :4], big[:4, 4:] = a * period, b * period
    e = expm(big)
    phi, gamma = e[:4, :4], e[:4, 4]
    controller = WhippleLean(speed, p)
    x = np.array([0.0, 0.0, push, 0.0])
    leans = [0.0]
    for _ in range(round(positive("duration", duration) / period)):
        x = phi @ x + gamma * (controller.torque(x) if controlled else 0.0)
        leans.append(x[0])
        if abs(x[0]) > FALLEN:
            break
    return np.array(leans)
