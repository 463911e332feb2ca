"""How much the ball caster resists motion: the ``caster drag`` measurement scenario.

The robot drives at constant wheel rates (after ``SETTLE`` s at rest, a ``RAMP`` s
ramp and ``HOLD`` s, then ``STEADY`` s measured) straight (the ball rolls forward) and turning in
place (it rolls sideways relative to the chassis). At every
step the floor's tangential force on the ball is resolved against the ball centre's
direction of motion, ``F_drag = −F_t · v̂`` (N), and given as a fraction of the robot's
weight ``M g``.

Why it is zero in the default model (condim 3): MuJoCo's contact there has sliding
friction only, a force at the contact point. A ball on a frictionless joint rolling at
constant velocity needs no force at all (``m_c a = F_t = 0`` and the torque ``r × F_t =
I α = 0``); in a turn the floor force only turns the ball's momentum and spin, ``F_t =
(7/5) m_c a_c`` perpendicular-ish to the motion and ``(2/7)`` of it along any
tangential acceleration, which is not a loss. A soft contact dissipates energy only in
the directions it resists, and nothing resists rolling: the drag is the solver's
residual.

With MuJoCo's rolling friction (``BallCasterParams.rolling_friction``: condim 6) the
contact also carries a torque opposing rolling, ``|τ_r| ≤ μ_r N`` (μ_r in m, the third
``friction`` coefficient). Steady rolling needs zero net torque on the ball about its
centre, ``r_c F_t = τ_r``, and MuJoCo's elliptic cone bounds all of a contact's
frictional components together, ``(F_t/μ)² + (τ_r/μ_r)² ≤ N²``. A ball that keeps
rolling sits on the cone's boundary, so::

    F_drag = (μ_r N / r_c) / sqrt(1 + (μ_r / (μ r_c))²)

the classical rolling resistance ``μ_r N / r_c`` with a correction of order
``(μ_r/μ r_c)²``. That run is judged against this prediction, with N, μ and μ_r read
from the same contact at the same step, on the means over the window (see
:data:`ROLLING_DRAG_REL`).
"""

from __future__ import annotations

import dataclasses
from typing import NamedTuple

import mujoco
import numpy as np

from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots.diffdrive import analytic as diffdrive
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.sim.stepping import check_healthy
from wmr_mujoco.validation.metrics import Metric, Series, Target
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario

GRAVITY = 9.81
#: Seconds at rest before the ramp, of the speed ramp, held before measuring, and of the
#: measured window. The hold skips the step where the ramp ends: until then the ball
#: accelerates and the floor pushes it with (2/5) m_c a (its spin-up), not a drag.
SETTLE = 0.3
RAMP = 0.5
HOLD = 0.2
STEADY = 1.0
#: ``(name, v, ω)``: midpoint speed (m/s) and yaw rate (rad/s) of each manoeuvre.
MANOEUVRES = (("straight", 0.5, 0.0), ("spin", 0.0, 1.5))
#: Relative bound on the window-mean rolling-friction drag against the window-mean
#: prediction. Derived: the prediction holds when the ball's spin does not accelerate
#: (``I α = 0``). On the geom's own contact (no floor pair, ``d`` ≈ 0.95) the condim-6
#: contact chatters (it is lost for one step in a few), so at single steps ``I α ≠ 0``;
#: over each chatter cycle the spin returns to its value and ``∫ I α dt = 0``. A window of
#: ``STEADY`` s holds ``n ≈ STEADY / T_c`` cycles (T_c ≈ 6 steps, 15 ms at the 2.5 ms
#: step: n ≈ 67) and at most one partial cycle, whose share of the mean is at most
#: (peak − mean)/mean / n ≈ 1/67; the bound is 1.7 times that. The default model pairs the
#: caster with the floor (the wheels' remedy, :mod:`wmr_mujoco.models.builders.wheel_pairs`):
#: it touches at every step, no cycle is partial, and the mean's only residual is the
#: ball's spin change across the window, which the same bound covers.
ROLLING_DRAG_REL = 0.025


class DragRecord(NamedTuple):
    """Per-step records of the measured window."""

    time: np.ndarray
    drag: np.ndarray
    predicted: np.ndarray
    contact: np.ndarray


def _contact(model: mujoco.MjModel, data: mujoco.MjData, geom: int) -> int | None:
    for i in range(data.ncon):
        if geom in (data.contact.geom[i][0], data.contact.geom[i][1]):
            return i
    return None


def caster_forces(model: mujoco.MjModel, data: mujoco.MjData) -> tuple[float, float]:
    """``(F_drag, F_pred)`` at the ball's floor contact, N (zeros without contact or motion).

    ``F_drag = −F_t · v̂`` with ``v̂`` the ball centre's horizontal direction of motion;
    ``F_pred`` the rolling-friction prediction (module docstring; 0 for condim 3).
    """
    geom = model.geom("caster_collision").id
    i = _contact(model, data, geom)
    if i is None:
        return 0.0, 0.0
    c = data.contact[i]
    f = np.zeros(6)
    mujoco.mj_contactForce(model, data, i, f)
    frame = c.frame.reshape(3, 3)
    # mj_contactForce gives the force on geom[1] from geom[0] in the contact frame.
    sign = 1.0 if c.geom[1] == geom else -1.0
    tangential = sign * (f[1] * frame[1] + f[2] * frame[2])
    vel = np.zeros(6)
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, model.body("caster").id,
                             vel, 0)
    speed = float(np.linalg.norm(vel[3:5]))
    if speed < 1e-6:
        return 0.0, 0.0
    drag = float(-tangential[:2] @ vel[3:5] / speed)
    if c.dim < 6:
        return drag, 0.0
    r = float(model.geom_size[geom][0])
    mu, mu_r = float(c.friction[0]), float(c.friction[3])
    return drag, (mu_r * f[0] / r) / np.sqrt(1.0 + (mu_r / (mu * r)) ** 2)


def steady_drag(model: mujoco.MjModel, params: DiffDriveParams, v: float, omega: float
                ) -> DragRecord:
    """Drive at ``(v, ω)`` from rest and record the caster forces over ``STEADY`` s.

    Raises:
        SimulationDivergedError: the run diverged.
    """
    data = mujoco.MjData(model)
    dt = model.opt.timestep
    target = np.array(diffdrive.wheel_speeds(v, omega, params.track)) / params.wheel.radius
    n_start = round((SETTLE + RAMP + HOLD) / dt)
    n = n_start + round(STEADY / dt)
    rec = np.zeros((n - n_start, 4))
    for k in range(n):
        data.ctrl[:] = float(np.clip((k * dt - SETTLE) / RAMP, 0.0, 1.0)) * target
        mujoco.mj_step(model, data)
        if k >= n_start:
            touching = _contact(model, data, model.geom("caster_collision").id) is not None
            rec[k - n_start] = (data.time - SETTLE - RAMP - HOLD, *caster_forces(model, data),
                                touching)
    check_healthy(model, data)
    return DragRecord(rec[:, 0], rec[:, 1], rec[:, 2], rec[:, 3])


def evaluate(scenario: Scenario, params: RobotParams | None) -> MeasurementResult:
    """Caster drag of every manoeuvre (reported) and with rolling friction (judged)."""
    from wmr_mujoco.models.loading import load
    from wmr_mujoco.robots.diffdrive import SPEC  # the entry imports this module

    p = params_or_default(params, DiffDriveParams)
    weight = p.total_mass * GRAVITY
    metrics: list[Metric] = []
    series: list[Series] = []
    free = load(SPEC, params)
    for name, v, omega in MANOEUVRES:
        rec = steady_drag(free, p, v, omega)
        metrics += [
            Metric(f"caster drag, {name}, mean", float(np.mean(rec.drag)), "N",
                   note="condim 3: nothing resists rolling; solver residual"),
            Metric(f"caster drag, {name}, worst / weight",
                   float(np.max(np.abs(rec.drag))) / weight, "")]
        series.append(Series(f"drag, {name}, condim 3", rec.time, rec.drag, "t [s]",
                             "caster drag [N]"))
    rolling = dataclasses.replace(p, caster=dataclasses.replace(p.caster,
                                                                rolling_friction=True))
    name, v, omega = MANOEUVRES[0]
    rec = steady_drag(load(SPEC, rolling), rolling, v, omega)
    mean, predicted = float(np.mean(rec.drag)), float(np.mean(rec.predicted))
    metrics += [
        Metric(f"caster drag with rolling friction, {name}, mean", mean, "N",
               note="condim 6, μ_r the collision class's rolling coefficient"),
        Metric(f"caster drag with rolling friction, {name}, mean / weight", mean / weight,
               ""),
        Metric("predicted (μ_r N/r_c)/√(1+(μ_r/μr_c)²), mean", predicted, "N"),
        Metric("rolling-friction drag vs prediction, window means",
               mean / predicted - 1.0, "ratio",
               Target.derived(ROLLING_DRAG_REL, "elliptic cone at steady rolling, r_c F_t "
                              "= τ_r; one partial contact-chatter cycle in the window "
                              "(caster_drag.ROLLING_DRAG_REL)")),
        Metric("caster contact present, condim 6", float(np.mean(rec.contact)),
               "fraction of steps", note="1 with the caster's floor pair; the geom's own "
               "condim-6 contact hops")]
    series += [Series(f"drag, {name}, condim 6", rec.time, rec.drag, "t [s]",
                      "caster drag [N]"),
               Series(f"predicted, {name}, condim 6", rec.time, rec.predicted, "t [s]",
                      "caster drag [N]")]
    return MeasurementResult(metrics, series)
