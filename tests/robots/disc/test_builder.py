"""The mounted disc rolls straight when spun with the steering held still."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.robots.disc.params import DiscParams
from wmr_mujoco.sim.stepping import rollout

#: Bound on lateral drift per metre rolled. The model is mirror-symmetric about the
#: wheel plane (single contact point directly below the axle, no torque about the
#: steering axis), so the exact drift is zero and what remains is round-off: about
#: N·ε·|x| ≈ 2500 steps × 2.2e-16 × 5 m ≈ 3e-12 m over the run. The bound is 1000 times
#: that per metre. Headings off the world axes make the arithmetic non-trivial.
DRIFT_PER_METRE = 1e-9


#: Seconds the wheel stands, then rolls, before a push: the floor's load builds up over a
#: few contact time constants as the wheel sinks to its static depth, and the rate servo
#: spins the wheel up (the spin-up slips: the servo's torque limit is above the traction
#: limit, and a sliding contact shares its friction between the two directions).
SETTLE = 0.2
SPIN_UP = 1.0


def _roll(heading: float, lateral_push: float = 0.0, duration: float = 5.0):
    p = DiscParams()
    model = load("disc")
    data = mujoco.MjData(model)
    data.joint("steer").qpos[0] = heading
    data.act[0] = heading  # steering servo target
    rollout(model, data, SETTLE, lambda t: np.zeros(2))
    x0, y0 = data.qpos[0], data.qpos[1]
    rollout(model, data, SPIN_UP, lambda t: np.array([1.0 / p.wheel.radius, 0.0]))
    data.qvel[0] += -lateral_push * np.sin(heading)
    data.qvel[1] += lateral_push * np.cos(heading)
    rollout(model, data, duration, lambda t: np.array([1.0 / p.wheel.radius, 0.0]))
    dx, dy = data.qpos[0] - x0, data.qpos[1] - y0
    along = dx * np.cos(heading) + dy * np.sin(heading)
    across = -dx * np.sin(heading) + dy * np.cos(heading)
    return along, across, data


@pytest.mark.parametrize("heading", [0.0, 0.7, 2.0, -2.5])
def test_rolls_straight(heading):
    along, across, data = _roll(heading)
    assert along > 5.5  # 1 s of spin-up, then 5 s at 1 m/s
    assert abs(across) / along < DRIFT_PER_METRE
    assert data.joint("steer").qpos[0] == pytest.approx(heading, abs=1e-9)


def test_sideways_push_is_absorbed_by_the_contact():
    """A sideways push v = 0.1 m/s on the loaded wheel is stopped by Coulomb friction:
    at most μ N decelerates the carriage, so it slides at most v²/(2 μ g) (N = m g of
    the carriage and wheel), plus one step's v Δt of the discrete friction impulse;
    then no drift."""
    p = DiscParams()
    v = 0.1
    _along, across, data = _roll(0.7, lateral_push=v)
    bound = v**2 / (2 * p.sim.friction * 9.81) + v * p.sim.timestep
    assert 0.0 < across < bound
    lateral_speed = -data.qvel[0] * np.sin(0.7) + data.qvel[1] * np.cos(0.7)
    assert abs(lateral_speed) < 1e-9


def test_rolling_speed_is_r_theta_dot():
    """In steady rolling the carriage moves at (R − δ/2) θ̇: the floor pair carries the
    wheel δ = (1 − d) g t_c² deep (impedance d, normal time constant t_c; MuJoCo's
    normal row a = −(1 − d) g + d a_ref with d a_ref = −r/t_c² at rest), and an ellipsoid
    pressed δ deep rolls on a radius between R − δ and R; tolerance 1e-4 relative."""
    p = DiscParams()
    model = load("disc")
    data = mujoco.MjData(model)
    rollout(model, data, 1.0, lambda t: np.array([8.0, 0.0]))
    depth = (1.0 - p.floor_impedance) * 9.81 * p.sim.contact_timeconst**2
    assert data.qvel[0] == pytest.approx(8.0 * (p.wheel.radius - depth / 2), rel=1e-4)
