"""How much the ball caster resists motion: ``python -m wmr_mujoco.caster_drag``.

Two independent measurements on the differential drive (:mod:`wmr_mujoco.builders.diffdrive`):

1. **Contact force.** Driving at constant wheel rates, the floor's tangential force on
   the ball, resolved against the ball's contact-point velocity direction,
   ``F_drag = −F_t · v̂``, averaged over the steady window (and its worst value). A ball
   that rolls freely carries no tangential force at constant velocity; in a turn it
   carries ``(2/7)·`` the force accelerating it (:class:`BallCasterParams`), which is not a
   loss. Reported for a straight run, an arc and a spin in place, beside the wheels'
   total drive force ``Σ τ_i / R`` over the same window. With no losses that force is
   not zero in turns: it is the forward component of the CoM's centripetal force,
   ``M ω² d`` for a CoM a distance d behind the axle, not a resistance.
2. **Coasting.** From a steady straight run the motors switch to zero torque and the robot
   coasts for ``COAST_TIME``. The same run with the caster contact made frictionless
   (``condim = 1``: it can push up, never sideways) is the reference. The drag the
   rolling ball adds is ``F = m_eff (a_ball − a_ref)``, with
   ``m_eff = M + 2 (J_w + J_a)/R² + (2/5) m_c`` the mass that coasting decelerates (chassis
   and wheels translate, wheels and rotors spin, the ball spins).

Both are given in N and as a fraction of the robot's weight ``M g``.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.actuation import set_actuation_mode
from wmr_mujoco.analytic import diffdrive
from wmr_mujoco.builders import common
from wmr_mujoco.params_wheeled import DIFFDRIVE, DiffDriveParams
from wmr_mujoco.simulation import check_healthy

GRAVITY = 9.81
SETTLE = 0.3
RAMP = 0.5
STEADY = 2.0
COAST_TIME = 1.0


def _model(params: DiffDriveParams, frictionless_caster: bool = False) -> mujoco.MjModel:
    from wmr_mujoco.wheeled_scenarios import build_scene

    root = build_scene("diffdrive", params)
    if frictionless_caster:
        root.find("geom", "caster_collision").condim = 1
    return mujoco.MjModel.from_xml_string(common.to_xml(root))


def _run(model: mujoco.MjModel, params: DiffDriveParams, v: float, omega: float,
         seconds: float, data: mujoco.MjData | None = None,
         record=None) -> mujoco.MjData:
    data = data or mujoco.MjData(model)
    vl, vr = diffdrive.wheel_speeds(v, omega, params.track)
    target = np.array([vl, vr]) / params.wheel.radius
    for _ in range(round(seconds / model.opt.timestep)):
        # Speed ramps up over RAMP seconds after the settle, whichever call is running.
        ramp = min(1.0, max(0.0, (data.time - SETTLE) / RAMP))
        data.ctrl[:] = ramp * target
        mujoco.mj_step(model, data)
        if record is not None:
            record(data)
    check_healthy(model, data)
    return data


def caster_contact_drag(model: mujoco.MjModel, data: mujoco.MjData) -> float:
    """``−F_t · v̂`` at the ball's floor contact (0 without contact or motion), N."""
    ball = model.body("caster").id
    geom = model.geom("caster_collision").id
    for i in range(data.ncon):
        c = data.contact[i]
        if geom not in (c.geom[0], c.geom[1]):
            continue
        f = np.zeros(6)
        mujoco.mj_contactForce(model, data, i, f)
        frame = c.frame.reshape(3, 3)
        # Force on geom[1] from geom[0] along the contact frame; the ball is geom[1]
        # when the floor comes first, otherwise flip the sign.
        sign = 1.0 if c.geom[1] == geom else -1.0
        tangential = sign * (f[1] * frame[1] + f[2] * frame[2])
        vel = np.zeros(6)
        mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, ball, vel, 0)
        speed = np.linalg.norm(vel[3:5])
        return 0.0 if speed < 1e-6 else float(-tangential[:2] @ vel[3:5] / speed)
    return 0.0


@dataclass(frozen=True)
class DragFigures:
    """Caster drag of one manoeuvre: mean and worst over the steady window."""

    manoeuvre: str
    mean: float
    worst: float
    weight: float
    wheel_force: float

    def rows(self) -> list[tuple[str, float, str]]:
        """``(metric, value, unit)`` rows in N and as a fraction of the weight."""
        return [(f"caster contact drag, {self.manoeuvre}, mean", self.mean, "N"),
                (f"caster contact drag, {self.manoeuvre}, worst", self.worst, "N"),
                (f"caster contact drag, {self.manoeuvre}, mean / weight",
                 self.mean / self.weight, ""),
                (f"wheel drive force Σ τ/R, {self.manoeuvre}, mean", self.wheel_force, "N")]


def contact_drag(params: DiffDriveParams = DIFFDRIVE,
                 manoeuvres: tuple[tuple[str, float, float], ...] = (
                     ("straight 0.5 m/s", 0.5, 0.0), ("arc 0.5 m/s, 0.5 rad/s", 0.5, 0.5),
                     ("spin 1.5 rad/s", 0.0, 1.5)),
                 ) -> list[DragFigures]:
    """Measurement 1 for each ``(name, v, ω)`` manoeuvre."""
    model = _model(params)
    weight = params.total_mass * GRAVITY
    out = []
    for name, v, omega in manoeuvres:
        data = _run(model, params, 0.0, 0.0, SETTLE)
        data = _run(model, params, v, omega, RAMP + 0.5, data)
        drag: list[float] = []
        force: list[float] = []

        def record(d: mujoco.MjData, drag: list[float] = drag,
                   force: list[float] = force) -> None:
            drag.append(caster_contact_drag(model, d))
            force.append(float(d.actuator_force.sum()) / params.wheel.radius)

        _run(model, params, v, omega, STEADY, data, record=record)
        drag_arr = np.asarray(drag)
        out.append(DragFigures(name, float(drag_arr.mean()), float(np.abs(drag_arr).max()),
                               weight, float(np.mean(force))))
    return out


def _coast_deceleration(params: DiffDriveParams, frictionless: bool, v: float) -> float:
    model = _model(params, frictionless)
    data = _run(model, params, 0.0, 0.0, SETTLE)
    data = _run(model, params, v, 0.0, RAMP + 1.0, data)
    set_actuation_mode(model, "torque")
    data.ctrl[:] = 0.0
    speeds = []
    for _ in range(round(COAST_TIME / model.opt.timestep)):
        mujoco.mj_step(model, data)
        speeds.append(data.qvel[0])
    check_healthy(model, data)
    t = model.opt.timestep * np.arange(len(speeds))
    return float(-np.polyfit(t, speeds, 1)[0])


def coasting_drag(params: DiffDriveParams = DIFFDRIVE, v: float = 0.5
                  ) -> dict[str, float]:
    """Measurement 2: decelerations with the rolling ball and the frictionless reference."""
    a_ball = _coast_deceleration(params, False, v)
    a_ref = _coast_deceleration(params, True, v)
    w = params.wheel
    m_eff = (params.total_mass + 2.0 * (w.axial_inertia + params.drive.wheel_armature)
             / w.radius**2 + 0.4 * params.caster.mass)
    force = m_eff * (a_ball - a_ref)
    return {"coasting deceleration, rolling ball": a_ball,
            "coasting deceleration, frictionless caster": a_ref,
            "caster drag from coasting": force,
            "caster drag from coasting / weight": force / (params.total_mass * GRAVITY)}


def drag_table(params: DiffDriveParams = DIFFDRIVE) -> str:
    """Markdown table of both measurements."""
    rows = ["| measurement | value | unit |", "|---|---|---|"]
    for fig in contact_drag(params):
        rows += [f"| {n} | {v:.3g} | {u} |" for n, v, u in fig.rows()]
    units = {"coasting deceleration, rolling ball": "m/s²",
             "coasting deceleration, frictionless caster": "m/s²",
             "caster drag from coasting": "N", "caster drag from coasting / weight": ""}
    rows += [f"| {k} | {v:.3g} | {units[k]} |" for k, v in coasting_drag(params).items()]
    return "\n".join(rows)


if __name__ == "__main__":
    print(drag_table())
