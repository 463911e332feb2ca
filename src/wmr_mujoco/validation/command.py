"""How a robot is driven: its natural command and how it becomes actuator controls.

Each registry entry (:class:`~wmr_mujoco.robots.spec.RobotSpec`) may carry a
:class:`CommandMap`; the stepping API (:mod:`wmr_mujoco.drive`) reads robots only through
it. Two implementations:

* :class:`RateCommand`: the command is the input ``u`` of the robot's analytic kinematic
  model (its validation adapter, :mod:`wmr_mujoco.validation.adapters`): a body twist
  ``(u, v, r)`` (omni3, mecanum4), ``(v, ω)`` (diffdrive, disc), ... The adapter's
  ``controls(u, x)`` gives the actuator controls (wheel-rate servo targets), its
  ``rhs(x, u)`` the kinematic model. Channels listed in ``servo`` are steering ANGLES
  instead of the adapter's steering RATES: held over a control period ``T``, the rate is

      ω = clip((φ_cmd − φ_target) / T, −ω_max, ω_max)

  with ``φ_target`` the steering servo's integrated target (MuJoCo ``act``, or the
  analytic state's steering angle), so the target reaches ``φ_cmd`` within one period
  when ``|φ_cmd − φ_target| ≤ ω_max T``, otherwise at the rate limit.
* :class:`TorqueCommand`: the command is a subset of the actuators' controls, reordered
  (the Whipple bicycle's rear-wheel and steer torques); no analytic model.
"""

from __future__ import annotations

import abc
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.validation.adapters import Adapter

#: ``extras(model, data) -> {name: value}``: robot-specific readings of a MuJoCo state.
Extras = Callable[[mujoco.MjModel, mujoco.MjData], Mapping[str, float]]
#: ``controller(data, command, period, ctrl)``: writes into ``ctrl`` (length ``nu``, the
#: robot's ``data.ctrl``) the actuator controls that hold ``command`` over the next
#: ``period`` seconds.
Controller = Callable[[mujoco.MjData, np.ndarray, float, np.ndarray], None]
#: ``pushed(model, data, params, speed, lean_rate)``: puts ``data`` in upright straight
#: rolling at ``speed`` m/s with a sideways push, a lean rate ``lean_rate`` rad/s
#: (``data.time`` 0): the start of a balancing robot's upright scenarios.
Pushed = Callable[[mujoco.MjModel, mujoco.MjData, "RobotParams | None", float, float], None]
#: ``law(speed, params)``: a feedback law ``law(state, None, t) -> command`` (the robot's
#: natural command) that keeps the robot upright riding at ``speed``.
BalanceLaw = Callable[[float, "RobotParams | None"], Callable[[Any, None, float], np.ndarray]]
#: ``linear(speed, push, controlled, params, duration, period) -> leans``: the lean angle
#: after every period of the robot's linear model from the push, the law on (or the
#: torques zero), until it passes the fall threshold.
LinearLeans = Callable[[float, float, bool, "RobotParams | None", float, float], np.ndarray]


@dataclass(frozen=True)
class Balance:
    """How a robot that cannot stand still is pushed and kept upright (its own data).

    Attributes:
        pushed: its pushed start (:data:`Pushed`).
        law: its balancing law (:data:`BalanceLaw`).
        speeds: the riding speeds its upright claim is made at, m/s.
        push: the nominal push, a lean rate, rad/s.
        push_range: the range of push sizes drawn (the sign drawn too), rad/s.
        period: the law's control period, s.
        fallen: the lean past which it has fallen, rad.
        lean: the key of the lean angle in the command map's extras.
        linear: its linear model under the same law (:data:`LinearLeans`; None: none).
    """

    pushed: Pushed
    law: BalanceLaw
    speeds: tuple[float, ...]
    push: float
    push_range: tuple[float, float]
    period: float
    fallen: float
    lean: str = "lean"
    linear: LinearLeans | None = None


@dataclass(frozen=True)
class CommandMap(abc.ABC):
    """A robot's natural command space and its wheels (base class).

    Attributes:
        names: command channel names.
        units: their units.
        wheels: hinge joints of the driven or rolling wheels, in the order of
            ``RobotState.wheel_rates``.
        steers: steering hinge joints, in the order of ``RobotState.steer_angles``.
        settle: seconds at rest on the floor after a reset (the validation runner's 0.5 s;
            0 for a robot that cannot stand still, the Whipple bicycle).
        keyframe: keyframe a reset starts from (None: the model's rest pose ``qpos0``).
        extras: robot-specific readings of the MuJoCo state (None: none).
        balance: how a robot that cannot stand still is pushed and kept upright
            (:class:`Balance`; None: it stands by itself). With it, the validation closes
            the balancing loop (:mod:`wmr_mujoco.loop.tasks.families`).
    """

    names: tuple[str, ...]
    units: tuple[str, ...]
    wheels: tuple[str, ...]
    steers: tuple[str, ...] = ()
    settle: float = 0.5
    keyframe: str | None = None
    extras: Extras | None = None
    balance: Balance | None = None

    def __post_init__(self) -> None:
        if len(self.names) != len(self.units):
            raise ValueError(f"command names {self.names} and units {self.units} differ "
                             "in length")

    def analytic(self, params: RobotParams | None) -> Adapter | None:
        """The robot's analytic kinematic model driven by :meth:`inputs` (None: none)."""
        return None

    @abc.abstractmethod
    def limits(self, model: mujoco.MjModel,
               adapter: Adapter | None) -> tuple[np.ndarray, np.ndarray]:
        """``(low, high)`` of the command, from the model's actuator ranges."""

    @abc.abstractmethod
    def bind(self, model: mujoco.MjModel, adapter: Adapter | None) -> Controller:
        """The command-to-controls map of one compiled model (indices looked up once)."""


@dataclass(frozen=True)
class Servo:
    """A command channel that is a steering angle, servoed through a rate input.

    Attributes:
        channel: index of the channel in the command (and the adapter's input).
        actuator: the steering actuator (MuJoCo ``intvelocity``; its ``act`` is the
            target angle and its ctrl range the rate limit).
        state: index of the steering angle in the adapter's analytic state.
    """

    channel: int
    actuator: str
    state: int


def servo_rate(command: float, target: float, period: float, rate_limit: float) -> float:
    """``ω = clip((φ_cmd − φ_target) / T, −ω_max, ω_max)`` (module docstring)."""
    return min(rate_limit, max(-rate_limit, (command - target) / period))


@dataclass(frozen=True)
class RateCommand(CommandMap):
    """The analytic kinematic model's own inputs, steering rates replaced by angles.

    Attributes:
        kinematics: ``params -> adapter``, the robot's kinematic validation adapter.
        servo: the channels that are steering angles (module docstring).
        state_dependent: whether the adapter's ``controls`` read the analytic state's
            steering angles (the double steer's rear-wheel speed); the MuJoCo backend
            fills them from the steering joints every period (the rest of the state 0).
        adjust: ``(adapter, u, φ) -> u``, where a command channel is not the adapter's
            input (the tricycle's speed of the rear-axle midpoint, the adapter's the
            driven wheel's); ``φ`` are the servo channels' steering targets at the start
            of the period, an array or a list of floats (None: the command is the input).
    """

    kinematics: Callable[[RobotParams | None], Adapter] | None = None
    servo: tuple[Servo, ...] = ()
    state_dependent: bool = False
    adjust: Callable[[Adapter, np.ndarray, np.ndarray], np.ndarray] | None = None

    def __post_init__(self) -> None:
        super().__post_init__()
        if self.kinematics is None:
            raise ValueError(f"RateCommand {self.names}: give the kinematic adapter")

    def analytic(self, params: RobotParams | None) -> Adapter:
        """The kinematic adapter with the robot's parameters."""
        assert self.kinematics is not None  # checked in __post_init__
        return self.kinematics(params)

    def rate_limits(self, model: mujoco.MjModel) -> np.ndarray:
        """Steering-rate limits ``ω_max`` of the servo channels (their ctrl ranges)."""
        return np.array([model.actuator(s.actuator).ctrlrange[1] for s in self.servo])

    def inputs(self, adapter: Adapter, command: np.ndarray, targets: np.ndarray,
               period: float, rate_limits: np.ndarray) -> np.ndarray:
        """The adapter's input ``u``: servo angles turned into rates, then ``adjust``."""
        channels = [(s.channel, limit) for s, limit in
                    zip(self.servo, np.asarray(rate_limits, float).tolist(), strict=True)]
        return self._inputs(adapter, np.asarray(command, float).tolist(), targets, period,
                            channels)

    def _inputs(self, adapter: Adapter, values: list[float], targets: np.ndarray | list[float],
                period: float, channels: list[tuple[int, float]]) -> np.ndarray:
        """:meth:`inputs` of the command ``values``; ``channels``: ``(channel, ω_max)``.

        ``targets``: the steering targets, an array or (a control step's) a list of floats.
        """
        if channels:
            phi = targets if type(targets) is list else targets.tolist()
            for k, (channel, limit) in enumerate(channels):
                values[channel] = servo_rate(values[channel], phi[k], period, limit)
        u = np.array(values)
        return u if self.adjust is None else self.adjust(adapter, u, targets)

    def limits(self, model: mujoco.MjModel,
               adapter: Adapter | None) -> tuple[np.ndarray, np.ndarray]:
        """A box of commands whose controls all stay inside the ctrl ranges.

        Servo channels: the steering actuator's ``actrange`` (its angle limit). The
        others: with ``W`` the controls per unit of each rate channel (``controls(e_j)``
        at the rest state, all wheel-rate servos), channel j alone may reach
        ``c_j = min_i ū_i / |W_ij|``; the box ``±α c`` with
        ``α = 1 / max_i Σ_j |W_ij| c_j / ū_i`` keeps every wheel inside its limit ``ū_i``
        for every command in the box (``Σ_j |W_ij| α c_j ≤ ū_i``).
        """
        assert adapter is not None
        m = len(self.names)
        servo = {s.channel: s for s in self.servo}
        rate = [j for j in range(m) if j not in servo]
        rest = np.zeros(len(adapter.state_names))
        zero = np.zeros(len(self.servo))
        w = np.column_stack([adapter.controls(self.inputs(adapter, np.eye(m)[j], zero, 1.0,
                                                          zero), rest) for j in rate])
        steer_acts = {model.actuator(s.actuator).id for s in self.servo}
        rows = [i for i in range(model.nu) if i not in steer_acts]
        w = np.abs(w[rows])
        ubar = model.actuator_ctrlrange[rows, 1]
        with np.errstate(divide="ignore"):
            reach = np.min(ubar[:, None] / w, axis=0)
        alpha = 1.0 / np.max((w * reach[None, :]).sum(axis=1) / ubar)
        high = np.empty(m)
        high[rate] = alpha * reach
        for j, s in servo.items():
            high[j] = model.actuator(s.actuator).actrange[1]
        low = -high
        for j, s in servo.items():
            low[j] = model.actuator(s.actuator).actrange[0]
        return low, high

    def matrix(self, adapter: Adapter) -> np.ndarray | None:
        """``W`` with ``controls(u, x) = W u`` for every ``u``, or None.

        None where the controls depend on the state (``state_dependent``) or are not
        linear in ``u``: ``W``'s columns are the controls of the unit inputs at rest, and
        linearity is checked on three inputs (to 1e-12 of their size).
        """
        if self.state_dependent:
            return None
        m = len(self.names)
        rest = np.zeros(len(adapter.state_names))
        w = np.column_stack([adapter.controls(e, rest) for e in np.eye(m)])
        for u in np.random.default_rng(0).normal(size=(3, m)):
            if not np.allclose(adapter.controls(u, rest), w @ u, rtol=1e-12,
                               atol=1e-12 * np.abs(w).max()):
                return None
        return w

    def bind(self, model: mujoco.MjModel, adapter: Adapter | None) -> Controller:
        """``adapter.controls(u, x)``, the servo targets read from ``data.act``.

        A linear, state-independent map (:meth:`matrix`) is applied as ``W u``.
        """
        assert adapter is not None
        acts = np.array([model.actuator_actadr[model.actuator(s.actuator).id]
                         for s in self.servo], dtype=int)
        channels = [(s.channel, limit) for s, limit in
                    zip(self.servo, self.rate_limits(model).tolist(), strict=True)]
        rest = np.zeros(len(adapter.state_names))
        w = self.matrix(adapter)
        direct = not self.servo and self.adjust is None
        states = [s.state for s in self.servo]
        joints = np.array([model.jnt_qposadr[model.actuator_trnid[
            model.actuator(s.actuator).id, 0]] for s in self.servo], dtype=int)

        acts_list = acts.tolist()
        #: The analytic state's steering angles and their ``qpos`` rows.
        angles = list(zip(states, joints.tolist(), strict=True))
        state = rest.copy()
        #: The last ``data`` seen and its ``act`` and ``qpos`` arrays (a new view on every
        #: attribute read).
        seen: list[object] = [None, None, None, None]

        def controller(data: mujoco.MjData, command: np.ndarray, period: float,
                       ctrl: np.ndarray) -> None:
            if direct:
                u = command
            else:
                if seen[0] is not data:
                    seen[0], seen[1] = data, data.act
                act = seen[1].tolist()  # type: ignore[union-attr]
                u = self._inputs(adapter, command.tolist(), [act[i] for i in acts_list],
                                 period, channels)
            if w is not None:
                w.dot(u, out=ctrl)  # W u, written in place (faster than np.matmul, same bits)
                return
            x = rest
            if self.state_dependent:
                if seen[2] is not data:
                    seen[2], seen[3] = data, data.qpos
                q = seen[3].tolist()  # type: ignore[union-attr]
                x = state  # the controller's own buffer: the rest state but the angles
                for k, j in angles:
                    x[k] = q[j]
            ctrl[:] = adapter.controls(u, x)

        return controller


@dataclass(frozen=True)
class TorqueCommand(CommandMap):
    """Commands that are actuator controls as they are (torques), in a chosen order.

    Attributes:
        actuators: the actuator of each command channel; the others get 0.
    """

    actuators: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        super().__post_init__()
        if len(self.actuators) != len(self.names):
            raise ValueError(f"TorqueCommand {self.names}: one actuator per channel, got "
                             f"{self.actuators}")

    def limits(self, model: mujoco.MjModel,
               adapter: Adapter | None) -> tuple[np.ndarray, np.ndarray]:
        """The actuators' ctrl ranges."""
        ranges = np.array([model.actuator(a).ctrlrange for a in self.actuators])
        return ranges[:, 0].copy(), ranges[:, 1].copy()

    def bind(self, model: mujoco.MjModel, adapter: Adapter | None) -> Controller:
        """The command placed on its actuators."""
        ids = [model.actuator(a).id for a in self.actuators]

        def controller(data: mujoco.MjData, command: np.ndarray, period: float,
                       ctrl: np.ndarray) -> None:
            ctrl[:] = 0.0
            ctrl[ids] = command

        return controller
