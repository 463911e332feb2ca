"""The generic variations the runner applies to a signal-driven scenario's members.

A kinematic or dynamic scenario is driven by its input signals
(:mod:`wmr_mujoco.validation.signals`); a member of its family
(:mod:`wmr_mujoco.validation.family`) may vary these quantities, which the runner applies
itself, for every robot alike (a robot's registry entry only declares their ranges):

* ``input scale`` (:data:`INPUT_SCALE`, factor): every input channel multiplied by it,
  ``u_j(t) -> s u_j(t)`` (speeds, yaw rates and torques ±20 %: ``[0.8, 1.2]``);
* ``input scale j`` (:func:`input_scale`, factor): channel ``j`` (0-based, the adapter's
  input order) multiplied by it, on top of ``input scale``;
* ``lead-in`` (:data:`LEAD_IN`, s): every channel multiplied by the envelope
  ``min(1, t / T)``, a linear ramp from rest over ``T`` seconds (``T`` below one time step
  is a step);
* ``duration`` (:data:`DURATION`, s): the run's length after the settle (the signals hold
  their last value past their last knot);
* ``wheel phase`` (:data:`WHEEL_PHASE`, rad): added to every wheel joint's start angle
  (the adapter's ``wheel_joints``) before the settle, so that a roller wheel starts on
  another roller; over a full roller pitch ``2π / n`` for a wheel of ``n`` rollers.

The analytic model and the physics see the same varied inputs (the runner computes both
from :meth:`~wmr_mujoco.validation.scenarios.Scenario.input_at`), so a member is judged
like the nominal scenario. A measurement scenario reads its own varied quantities with
:meth:`~wmr_mujoco.validation.scenarios.Scenario.value`.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence

import mujoco
import numpy as np

from wmr_mujoco.validation.family import Vary

#: Factor on every input channel.
INPUT_SCALE = "input scale"
#: Ramp from rest over this many seconds, as an envelope on every channel.
LEAD_IN = "lead-in"
#: Seconds of the run after the settle.
DURATION = "duration"
#: Radians added to every wheel joint's start angle.
WHEEL_PHASE = "wheel phase"

_CHANNEL = re.compile(r"input scale (\d+)$")


def input_scale(channel: int) -> str:
    """Name of the factor on one input channel (0-based)."""
    if isinstance(channel, bool) or not isinstance(channel, int) or channel < 0:
        raise ValueError(f"channel = {channel!r}; must be an integer >= 0")
    return f"{INPUT_SCALE} {channel}"


def is_generic(name: str) -> bool:
    """Whether the runner applies the varied quantity ``name`` itself."""
    return name in (INPUT_SCALE, LEAD_IN, DURATION, WHEEL_PHASE) or bool(_CHANNEL.match(name))


def scale_factors(draw: Mapping[str, float], channels: int) -> np.ndarray:
    """Per-channel factors ``s · s_j`` of a draw (ones where nothing is drawn).

    Raises:
        ValueError: a drawn channel factor for a channel the scenario does not have.
    """
    factors = np.full(channels, float(draw.get(INPUT_SCALE, 1.0)))
    for name, value in draw.items():
        if (m := _CHANNEL.match(name)) is not None:
            j = int(m.group(1))
            if j >= channels:
                raise ValueError(f"draw scales input channel {j}; the scenario has "
                                 f"{channels} channels (0..{channels - 1})")
            factors[j] *= value
    return factors


def envelope(draw: Mapping[str, float], t: float) -> float:
    """The lead-in envelope ``min(1, t / T)`` at ``t`` (1 without a drawn lead-in)."""
    ramp = draw.get(LEAD_IN)
    if ramp is None or ramp <= 0.0:
        return 1.0
    return min(1.0, max(0.0, t / ramp))


def add_wheel_phase(model: mujoco.MjModel, data: mujoco.MjData, joints: Sequence[str],
                    phase: float) -> None:
    """Rotate every wheel joint by ``phase`` (rad) from its present angle; then forward.

    Raises:
        ValueError: a joint that is not a hinge of the model.
    """
    for name in joints:
        j = model.joint(name)
        if model.jnt_type[j.id] != mujoco.mjtJoint.mjJNT_HINGE:
            raise ValueError(f"wheel joint {name!r} is not a hinge; a wheel phase turns "
                             "hinges only")
        data.qpos[model.jnt_qposadr[j.id]] += phase
    mujoco.mj_forward(model, data)


def speeds(fraction: float = 0.2) -> Vary:
    """Every input ``±fraction`` (default ±20 %): :data:`INPUT_SCALE` in ``1 ± fraction``."""
    return Vary(INPUT_SCALE, 1.0 - fraction, 1.0 + fraction)


def channel(j: int, fraction: float = 0.2) -> Vary:
    """Channel ``j`` alone ``±fraction``: ``input scale j`` in ``1 ± fraction``."""
    return Vary(input_scale(j), 1.0 - fraction, 1.0 + fraction)


def roller_pitch(rollers: int) -> Vary:
    """Wheel phase over one full roller pitch ``[0, 2π / rollers)`` (rollers per row)."""
    if isinstance(rollers, bool) or not isinstance(rollers, int) or rollers < 1:
        raise ValueError(f"rollers = {rollers!r}; must be an integer >= 1")
    return Vary(WHEEL_PHASE, 0.0, 2.0 * math.pi / rollers, "rad")


def duration(low: float, high: float) -> Vary:
    """Run length in ``[low, high]`` seconds."""
    return Vary(DURATION, low, high, "s")


def lead_in(low: float, high: float) -> Vary:
    """Lead-in ramp in ``[low, high]`` seconds (below one time step: a step)."""
    return Vary(LEAD_IN, low, high, "s")


#: Draws of every dynamic family (the project's rule: at least 20).
DYNAMIC_DRAWS = 20
#: Draws of a cheap kinematic family whose spread is shown small: the worst of
#: :data:`DYNAMIC_DRAWS` draws within half its target (``python -m
#: wmr_mujoco.bench.family_spread`` prints it for every such family).
KINEMATIC_DRAWS = 3


def around(name: str, nominal: float, fraction: float = 0.2, unit: str = "s") -> Vary:
    """``name`` in ``nominal · (1 ± fraction)`` (e.g. a duration ±20 %)."""
    return Vary(name, nominal * (1.0 - fraction), nominal * (1.0 + fraction), unit)
