"""Stepping a model with divergence detection.

A run that produces NaN/Inf in the state or raises any MuJoCo warning (bad qacc,
which makes MuJoCo silently reset the state; full contact or constraint buffers;
bad controls) is reported by :class:`SimulationDivergedError`, never returned.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import mujoco
import numpy as np

#: Names of MuJoCo's warning slots, indexed by ``mjtWarning``.
WARNING_NAMES = tuple(
    name for name, value in sorted(mujoco.mjtWarning.__members__.items(),
                                   key=lambda kv: int(kv[1])) if name != "mjNWARNING")


class SimulationDivergedError(RuntimeError):
    """The simulation produced non-finite values or MuJoCo warnings."""


def check_healthy(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """Raise :class:`SimulationDivergedError` if ``data`` shows a warning or NaN.

    Raises:
        SimulationDivergedError: naming the warnings (and counts) or non-finite fields,
            and the simulation time.

    """
    counts = data.warning.number  # one array read, not one struct per warning
    if not counts.any():
        # Python's float sums: no floating-point flags to set or silence (numpy's sum
        # would warn on an overflow), at a third of the cost of np.errstate and np.sum.
        total = sum(data.qpos.tolist()) + sum(data.qvel.tolist()) + sum(data.act.tolist())
        if math.isfinite(total):
            # NaN and ±Inf survive a sum (or make NaN): a finite sum means finite fields.
            # (A sum of finite values may still overflow: the field by field check below.)
            return
    raised = [f"{name} x{counts[i]}" for i, name in enumerate(WARNING_NAMES)
              if counts[i] > 0] if counts.any() else []
    bad = [f for f in ("qpos", "qvel", "act") if not np.isfinite(getattr(data, f)).all()]
    if raised or bad:
        what = "; ".join(filter(None, [", ".join(raised),
                                       bad and f"non-finite {', '.join(bad)}"]))
        raise SimulationDivergedError(
            f"simulation of {model.nbody}-body model diverged at t={data.time:.4f} s: {what}"
        )


ControlFn = Callable[[float], np.ndarray]


def rollout(model: mujoco.MjModel, data: mujoco.MjData, duration: float,
            control: ControlFn | None = None, record_every: int = 1,
            recorder: Callable[[mujoco.MjModel, mujoco.MjData], np.ndarray] | None = None,
            ) -> np.ndarray:
    """Step ``data`` for ``duration`` seconds, setting ``data.ctrl = control(t)``.

    Args:
        model: compiled model.
        data: state to advance in place.
        duration: simulated seconds (> 0); rounded to whole timesteps.
        control: maps time to a control vector of length ``model.nu`` (None: keep ctrl).
        record_every: record every this many steps (and the initial state).
        recorder: maps ``(model, data)`` to a 1-D array; default ``[time, qpos, qvel]``.

    Returns:
        Array of recorded rows.

    Raises:
        ValueError: bad duration, record interval or control length.
        SimulationDivergedError: the run diverged (checked every recorded step and at
            the end).

    """
    if not np.isfinite(duration) or duration <= 0:
        raise ValueError(f"duration = {duration!r} s; must be a finite number > 0")
    if record_every < 1:
        raise ValueError(f"record_every = {record_every!r}; must be an integer >= 1")
    rec = recorder or (lambda m, d: np.concatenate([[d.time], d.qpos, d.qvel]))
    nstep = round(duration / model.opt.timestep)
    rows = [rec(model, data)]
    for k in range(1, nstep + 1):
        if control is not None:
            u = np.asarray(control(data.time), dtype=float)
            if u.shape != (model.nu,):
                raise ValueError(f"control returned shape {u.shape}; expected ({model.nu},)")
            data.ctrl[:] = u
        mujoco.mj_step(model, data)
        if k % record_every == 0 or k == nstep:
            check_healthy(model, data)
            rows.append(rec(model, data))
    return np.asarray(rows)
