"""The generic judges: pose tracking and lateral slip.

Pose tracking (every scenario whose analytic state starts with ``(x, y, heading)``), with
``e(t) = |p_sim(t) − p_model(t)|`` the distance between the simulated and the analytic
reference point, ``L`` the analytic path length over the whole run, and ``Δψ(t)`` the
heading difference wrapped into (−180°, 180°]:

    worst position error  = max_t e(t) / L · 100 %      (judged)
    RMS position error    = sqrt(mean_t e(t)²)           (m)
    final position error  = e(T) / L · 100 %             (the old end-of-run figure)
    worst heading error   = max_t |Δψ(t)|                (judged where a target exists)
    final heading error   = Δψ(T)

All maxima and means are over the recorded samples of the whole run (every
:data:`RECORD_EVERY` steps and the last one). A run that
turns in place (``L`` < 1 mm) is judged on its centre's worst drift in metres instead.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wmr_mujoco.analytic.planar import cumulative_path, wrap_angle
from wmr_mujoco.validation.targets import Metric, Target
from wmr_mujoco.validation.traces import RECORD_EVERY, Trace

if TYPE_CHECKING:
    from wmr_mujoco.validation.adapters import Adapter
    from wmr_mujoco.validation.scenarios import Scenario

#: Below this analytic path length (m) a run counts as turning in place.
MIN_PATH = 1e-3

#: How the report's pose metrics and targets are defined (Markdown, for the report).
DEFINITIONS = f"""\
- *Worst position error*: the largest distance, at any recorded instant of the run,
  between the simulated and the analytic reference point, in % of the analytic path
  length of the whole run (and in metres). Judged against the robot's target.
- *RMS position error*: root mean square of that distance over the run, m. *Final
  position error*: at the last instant, m and % (reported beside the worst).
- *Worst heading error*: the largest heading difference over the run, wrapped into
  (−180°, 180°]; *final heading error* at the last instant.
- A run that turns in place (path under 1 mm) is judged on its centre's worst drift, m.
- Samples: every {RECORD_EVERY}th simulation step and the last one.
- Each target is a **requirement** (an accuracy asked of the model; its basis says what
  it bounds and why) or a **derived bound**
  (it follows from the physics; its derivation is given); a metric without a target is
  reported, not judged.
- An **open** target is a requirement that no model meets yet: its row shows the
  target, the measured figure and why it is missed (verdict `open`, or `open (met)` once
  the figure meets it); it is counted in the summary line and does not decide whether
  the run passes."""

# Keys of a robot's target table used by the generic judges.
POSITION_PCT = "worst position error % of path"
CENTRE_DRIFT_M = "worst centre drift m"
HEADING_DEG = "worst heading error deg"
LATERAL_SLIP_RMS = "lateral slip RMS m/s"


#: ``(scenario, trace, adapter, targets) -> metrics``: judges a run of one scenario kind.
Judge = Callable[["Scenario", Trace, "Adapter", Mapping[str, Target]], list[Metric]]


def rms(values: Sequence[float] | np.ndarray) -> float:
    """Root mean square (NaN for no values)."""
    v = np.asarray(values, float)
    return float(np.sqrt(np.mean(v ** 2))) if v.size else float("nan")


def worst_and_rms(name: str, err: np.ndarray, unit: str, target: Target,
               note: str = "") -> list[Metric]:
    """``worst <name>`` judged (``max |err|`` over the run) and ``RMS <name>`` reported.

    ``RMS = √(mean(err²))`` (:func:`rms`); both in ``unit``.
    """
    e = np.abs(np.asarray(err, float))
    return [Metric(f"worst {name}", float(e.max()), unit, target, note),
            Metric(f"RMS {name}", rms(e), unit)]


def pose_tracking(scenario: Scenario, trace: Trace, adapter: Adapter,
                  targets: Mapping[str, Target]) -> list[Metric]:
    """Worst, RMS and final position and heading errors over the run (module docstring)."""
    tr = trace.arrays()
    sim, ana = tr["sim"], tr["analytic"]
    err = np.linalg.norm(sim[:, :2] - ana[:, :2], axis=1)
    path = float(cumulative_path(ana[:, :2])[-1])
    heading = np.degrees(wrap_angle(sim[:, 2] - ana[:, 2]))
    worst_k = int(np.argmax(err))
    out = []
    if path > MIN_PATH:
        out.append(Metric("worst position error", 100.0 * err[worst_k] / path, "% of path",
                          targets.get(POSITION_PCT),
                          f"max over the run of |p_sim − p_model| / path, at "
                          f"t = {tr['time'][worst_k]:.2f} s"))
    else:
        out.append(Metric("worst centre drift", float(err[worst_k]), "m",
                          targets.get(CENTRE_DRIFT_M)))
    out += [Metric("worst position error", float(err[worst_k]), "m"),
            Metric("RMS position error", rms(err), "m"),
            Metric("final position error", float(err[-1]), "m")]
    if path > MIN_PATH:
        out.append(Metric("final position error", 100.0 * float(err[-1]) / path, "% of path"))
    out += [Metric("worst heading error", float(np.max(np.abs(heading))), "deg",
                   targets.get(HEADING_DEG)),
            Metric("final heading error", float(heading[-1]), "deg"),
            Metric("path length", path, "m")]
    return out


def slip_metrics(trace: Trace, wheels: Sequence[str], targets: Mapping[str, Target]
                 ) -> list[Metric]:
    """RMS (judged) and largest lateral slip speed at each conventional wheel's contact."""
    slip = trace.arrays()["slip"]
    out = []
    for i, wheel in enumerate(wheels):
        out.append(Metric(f"lateral slip RMS, {wheel}", rms(slip[:, i]), "m/s",
                          targets.get(LATERAL_SLIP_RMS)))
        out.append(Metric(f"largest lateral slip, {wheel}", float(np.max(np.abs(slip[:, i]))),
                          "m/s"))
    return out


def lateral_slip(model: mujoco.MjModel, data: mujoco.MjData,
                 wheels: Sequence[str]) -> np.ndarray:
    """Speed of each wheel's contact point along its axle (0 without contact), m/s.

    The non-holonomic constraint residual: for contact point ``c`` on the wheel body,
    ``v_slip = â · (J_p(c) q̇)`` with ``â`` the wheel axle in the world frame.
    """
    out = np.zeros(len(wheels))
    if not wheels or data.ncon == 0:
        return out
    jacp = np.zeros((3, model.nv))
    con = data.contact
    contact_bodies = model.geom_bodyid[con.geom[:data.ncon]].tolist()
    positions = con.pos[:data.ncon]
    for i, (jid, body) in enumerate(_wheel_joints(model, tuple(wheels))):
        for c, pair in enumerate(contact_bodies):
            if body in pair:  # the contacts of this wheel's body, in order
                mujoco.mj_jac(model, data, jacp, None, positions[c], body)
                out[i] = float(data.xaxis[jid] @ (jacp @ data.qvel))
    return out


def _wheel_joints(model: mujoco.MjModel, wheels: tuple[str, ...]
                  ) -> list[tuple[int, int]]:
    """``(joint id, body id)`` of each named wheel hinge (kept per model and names)."""
    key = (id(model), wheels)
    got = _WHEEL_JOINTS.get(key)
    if got is None or got[0] is not model:
        if len(_WHEEL_JOINTS) > 64:
            _WHEEL_JOINTS.clear()
        ids = [mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, n) for n in wheels]
        got = _WHEEL_JOINTS[key] = (model, [(j, int(model.jnt_bodyid[j])) for j in ids])
    return got[1]


#: :func:`_wheel_joints` per (model, wheel names); the model is kept with its entry so that
#: an id reused by a later model is not mistaken for it.
_WHEEL_JOINTS: dict[tuple[int, tuple[str, ...]], tuple[mujoco.MjModel, list]] = {}
