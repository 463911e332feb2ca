"""The ``"mujoco"`` backend against the robots' analytic models and its own servo laws."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.drive import drivable, make
from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.robots.whipple.builder import KEY_SPEED

PERIOD = 0.02


SERVOED = [name for name in drivable() if getattr(ROBOTS[name].command, "servo", ())]


@pytest.mark.parametrize("name", SERVOED)
@pytest.mark.parametrize("fraction", [0.8, 2.5])
def test_steering_angle_servo_reaches_the_command(name: str, fraction: float) -> None:
    """The steering target reaches φ in ⌈|φ| / (ω_max T)⌉ periods, the joint two later.

    Target: the integrator's ``act`` moves at ``clip(Δφ/T, ±ω_max)`` and so lands on φ
    exactly (1e-12). Joint: the PD servo ``J φ̈ = kp (φ_t − φ) − kv φ̇`` of the model's
    gains and the steering dof's inertia ``J`` (its mass-matrix diagonal) leaves at most
    the envelope ``|φ| e^{−ζ ωn t} / sqrt(1 − ζ²)`` (ωn = sqrt(kp/J), ζ = kv / 2 sqrt(kp J))
    of the whole step 2 periods after the target stops, plus ``1 N·m / kp`` for the
    tyre's scrub torque while rolling (a contact patch under a millimetre wide).
    """
    robot = make(name)
    robot.reset()
    m, d = robot.model, robot.data
    servo = robot.spec.command.servo
    act = m.actuator(servo[0].actuator)
    kp, kv, rate = act.gainprm[0], -act.biasprm[2], act.ctrlrange[1]
    speed = 0.2 * robot.command_space.high[0]
    n = len(robot.command_space.names)
    for k in range(25):  # roll at a fifth of the top speed after a 0.5 s ramp
        robot.step([speed * min(k / 25, 1.0)] + [0.0] * (n - 1))
    phi = fraction * rate * PERIOD
    command = [speed] + [phi] * (n - 1)
    periods = math.ceil(round(phi / (rate * PERIOD), 9))
    for _ in range(periods):
        state = robot.step(command)
    targets = [d.act[m.actuator_actadr[m.actuator(s.actuator).id]] for s in servo]
    np.testing.assert_allclose(targets, phi, atol=1e-12)
    for _ in range(2):
        state = robot.step(command)
    full = np.zeros((m.nv, m.nv))
    mujoco.mj_fullM(m, d, full)
    dof = m.jnt_dofadr[act.trnid[0]]
    inertia = full[dof, dof]
    wn, zeta = math.sqrt(kp / inertia), kv / (2 * math.sqrt(kp * inertia))
    envelope = math.exp(-zeta * wn * 2 * PERIOD) / math.sqrt(1 - zeta ** 2)
    np.testing.assert_allclose(state.steer_angles, phi, atol=phi * envelope + 1.0 / kp)


@pytest.mark.parametrize("name", drivable())
def test_every_wheel_touches_the_floor_after_a_reset(name: str) -> None:
    robot = make(name)
    assert robot.reset(seed=2).wheel_contacts.all()


def test_wheels_mode_drives_the_rate_servos_directly() -> None:
    """Equal wheel rates θ̇ drive straight, as the command ``(v, ω) = (R θ̇, 0)``."""
    wheels, natural = make("diffdrive", mode="wheels"), make("diffdrive")
    assert wheels.command_space.names == ("left_wheel", "right_wheel")
    assert wheels.command_space.units == ("rad/s", "rad/s")
    np.testing.assert_array_equal(wheels.command_space.high, [40.0, 40.0])
    radius = natural.spec.params_type().wheel.radius
    wheels.reset()
    natural.reset()
    for k in range(50):
        rate = 5.0 * min(k / 25, 1.0)
        a = wheels.step((rate, rate))
        b = natural.step((radius * rate, 0.0))
    # The same controls up to the round-off of R θ̇ / R.
    np.testing.assert_allclose(a.pose, b.pose, atol=1e-9)


def test_torque_mode_accelerates_no_faster_than_the_wheel_force_allows() -> None:
    """Torque τ on both wheels: forward, at most ``a = 2τ / (R m)`` (wheel inertia and the
    caster only slow it), and not slower than half that at 0.2 s (well below slip:
    2τ/R = 25 N < μ m g = 57 N)."""
    robot = make("diffdrive", mode="torque")
    assert robot.command_space.units == ("N·m", "N·m")
    robot.reset()
    tau = 1.0
    for _ in range(10):
        state = robot.step((tau, tau))
    p = robot.spec.params_type()
    mass = float(np.sum(robot.model.body_mass))
    bound = 2 * tau / (p.wheel.radius * mass) * 10 * PERIOD
    assert 0.5 * bound < state.twist[0] <= bound


def test_whipple_starts_rolling_upright_and_reports_its_lean() -> None:
    robot = make("whipple")
    state = robot.reset(pose=(0.0, 0.0, 1.0))
    assert state.twist[0] == pytest.approx(KEY_SPEED, rel=1e-6)
    assert set(state.extra) == {"lean", "lean_rate", "steer", "steer_rate"}
    assert state.extra["lean"] == pytest.approx(0.0, abs=1e-9)
    state = robot.step((0.0, 0.0))
    # Self-stable at the keyframe speed: it rolls on, upright, along its heading.
    assert abs(state.extra["lean"]) < 0.01 and state.pose[2] == pytest.approx(1.0, abs=0.01)


@pytest.mark.parametrize("name", ["diffdrive", "bicycle", "whipple"])
def test_a_period_is_n_timesteps_of_mj_step_bit_for_bit(name: str) -> None:
    """Split into ``mj_step2``, ``mj_step(n − 1)``, ``mj_step1``, a period simulates what
    ``n`` calls of ``mj_step`` with the applied controls simulate, exactly."""
    robot = make(name)
    robot.reset(pose=(0.1, 0.2, 0.3))
    m = robot.model
    start = mujoco.MjData(m)
    mujoco.mj_copyData(start, m, robot.data)
    controls = []
    for k in range(10):
        robot.step(0.1 * robot.command_space.high * (1 + k % 3))
        controls.append(robot.data.ctrl.copy())
    for ctrl in controls:
        start.ctrl[:] = ctrl
        for _ in range(robot.nstep):
            mujoco.mj_step(m, start)
    np.testing.assert_array_equal(robot.data.qpos, start.qpos)
    np.testing.assert_array_equal(robot.data.qvel, start.qvel)
