"""What one run may ask for, checked before it starts: its memory, its step, its inputs.

* :func:`check_steps`: a duration of at least one timestep, and a trajectory that fits the
  memory cap (:data:`MAX_MEMORY`, ``WMR_MAX_MEMORY`` or the call's ``max_memory``), so that
  nothing a user types can exhaust the machine's memory;
* :func:`check_frame`: world-frame inputs only for a robot whose model takes them;
* :func:`warn_clipped`: inputs that ask an actuator for more than its ``ctrlrange``
  (MuJoCo clips the control; the analytic model does not) give one
  :class:`InputClippedWarning` naming each actuator, the value asked and the limit.
"""

from __future__ import annotations

import numbers
import os
import warnings

import mujoco
import numpy as np

from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.sim.engine import STATE_SPEC
from wmr_mujoco.validation.adapters import Adapter
from wmr_mujoco.validation.runner import Prepared
from wmr_mujoco.validation.scenarios import Scenario

#: Largest trajectory one call may build, bytes (2 GiB: of the order of 1000 s of omni3 or
#: mecanum4 at their default steps; a refused run's message gives its robot's figure).
#: The environment variable ``WMR_MAX_MEMORY`` (bytes, or with a K, M or G suffix) or a
#: call's ``max_memory`` raise it.
MAX_MEMORY = 2 * 2**30
_SUFFIXES = {"K": 2**10, "M": 2**20, "G": 2**30, "T": 2**40}


class InputClippedWarning(UserWarning):
    """An input asks an actuator for more than its ``ctrlrange``: MuJoCo clips it."""


def max_memory_default() -> int:
    """The memory cap of a run, bytes: ``WMR_MAX_MEMORY`` if set, else :data:`MAX_MEMORY`.

    Raises:
        ValueError: ``WMR_MAX_MEMORY`` is not a positive number of bytes (K, M, G, T
            suffixes allowed).
    """
    text = os.environ.get("WMR_MAX_MEMORY", "").strip()
    if not text:
        return MAX_MEMORY
    scale = _SUFFIXES.get(text[-1].upper(), 1)
    try:
        value = float(text[:-1] if scale > 1 else text) * scale
    except ValueError:
        value = -1.0
    if not (np.isfinite(value) and value > 0):
        raise ValueError(f"WMR_MAX_MEMORY = {text!r}; give a number of bytes > 0, e.g. "
                         "8G or 500M")
    return int(value)


def _size(nbytes: float) -> str:
    for unit, scale in (("TiB", 2**40), ("GiB", 2**30), ("MiB", 2**20), ("KiB", 2**10)):
        if nbytes >= scale:
            return f"{nbytes / scale:.3g} {unit}"
    return f"{nbytes:.0f} B"


def check_steps(s: Scenario, model: mujoco.MjModel, adapter: Adapter,
                 max_memory: float | None) -> None:
    """Refuse a run shorter than a step or whose trajectory would not fit the cap.

    The settle keeps no trajectory, but may not step longer than the longest run the cap
    allows (a settle of 1e9 s would step for days).

    Per step a run keeps the physics state twice (the rollout's output and its copy),
    the input, the controls and the analytic and measured states (8 bytes each), plus
    about 400 bytes of Python objects of the schedule.

    Raises:
        ValueError: named with the step, the estimate, the cap and how to raise it.
    """
    dt = model.opt.timestep
    nstep = round(s.duration / dt)
    if nstep < 1:
        raise ValueError(f"duration = {s.duration!r} s is shorter than one timestep of "
                         f"{s.robot} ({dt:g} s); give at least {dt:g} s")
    cap = max_memory_default() if max_memory is None else max_memory
    if isinstance(cap, bool) or not isinstance(cap, numbers.Real) or not cap > 0:
        raise ValueError(f"max_memory = {max_memory!r}; give a number of bytes > 0")
    nstate = mujoco.mj_stateSize(model, STATE_SPEC)
    per_step = 8 * (2 * nstate + len(s.inputs) + model.nu
                    + 2 * len(adapter.state_names)) + 400
    if nstep * per_step > cap:
        raise ValueError(
            f"duration = {s.duration:g} s is {nstep:.3g} steps of {dt:g} s: its trajectory "
            f"would take about {_size(nstep * per_step)}, over the memory cap of "
            f"{_size(cap)} (at most {cap / per_step * dt:.3g} s of {s.robot}); shorten the "
            "run, or raise the cap with max_memory=BYTES or the environment variable "
            "WMR_MAX_MEMORY (e.g. WMR_MAX_MEMORY=8G)")
    longest = cap / per_step * dt
    if s.settle > longest:  # kept nothing, but would step as long as that run (hours)
        raise ValueError(f"settle = {s.settle:g} s is longer than the longest run the memory "
                         f"cap allows ({longest:.3g} s of {s.robot}); settle for less, or "
                         "raise the cap (max_memory=BYTES or WMR_MAX_MEMORY)")


def check_frame(s: Scenario, adapter: Adapter) -> None:
    """Refuse ``world_frame`` where the robot's model takes no world rates.

    An adapter that takes them says so with its ``world_frame`` attribute.

    Raises:
        ValueError: named with the robots whose inputs can be world rates.
    """
    if s.world_frame and not hasattr(adapter, "world_frame"):
        takers = [spec.name for spec in ROBOTS.values()
                  if any(o.world_frame and o.kind is s.kind for o in spec.scenarios)]
        raise ValueError(f"world_frame=True: {s.robot}'s {s.kind.value} inputs are its own "
                         "rates, never world rates; robots whose inputs can be world rates: "
                         f"{', '.join(takers) or 'none'}")


def warn_clipped(prep: Prepared) -> None:
    """One :class:`InputClippedWarning` naming the actuators the inputs overdrive.

    For each actuator with a ``ctrlrange``: the control furthest outside it, the input
    that asked for it and when.
    """
    model, controls = prep.model, prep.controls
    lines = []
    for a in np.flatnonzero(model.actuator_ctrllimited):
        lo, hi = model.actuator_ctrlrange[a]
        excess = np.maximum(controls[:, a] - hi, lo - controls[:, a])
        k = int(np.argmax(excess))
        if excess[k] > 1e-9 * max(1.0, abs(hi), abs(lo)):
            name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, a) or f"#{a}"
            u = ", ".join(f"{x:g}" for x in prep.inputs[k])
            lines.append(f"actuator {name!r} asked for {controls[k, a]:.4g} (inputs ({u}) at "
                         f"t = {k * model.opt.timestep:g} s), beyond its ctrlrange "
                         f"[{lo:g}, {hi:g}]")
    if lines:
        robot = prep.scenario.robot
        warnings.warn(f"{robot}: inputs beyond the actuators' limits: {'; '.join(lines)}. "
                      "MuJoCo clips these controls and the analytic model does not, so the "
                      f"physics falls behind the model (the limits: `wmr info {robot}`)",
                      InputClippedWarning, stacklevel=4)
