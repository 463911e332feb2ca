"""The tricycle's free rear wheel takes the rate the common ICR predicts."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.robots.tricycle.params import TricycleParams
from wmr_mujoco.sim.stepping import rollout

#: Tolerance on the free-wheel rate, relative. The ICR prediction assumes rigid point
#: contacts at radius R. MuJoCo's soft contacts roll at R − δ/2 with a penetration
#: δ ≤ 20 µm here (checked below), i.e. a relative radius error ≤ δ/(2R) = 1e-4 per
#: wheel, so ≤ 2e-4 on the ratio of two wheel rates; the lateral creep of the soft
#: friction constraint under the centripetal load is of the same order.
RATE_RTOL = 2e-4
MAX_PENETRATION = 20e-6


def _steady_turn(params: TricycleParams, steer: float, speed: float = 1.0):
    model = load("tricycle", params)
    data = mujoco.MjData(model)
    r = params.rear_wheel.radius
    ramp = 0.5  # s to steer to the angle at a constant rate
    rollout(model, data, 0.3, lambda t: np.array([speed / r, 0.0]))
    rollout(model, data, ramp, lambda t: np.array([speed / r, steer / ramp]))
    rollout(model, data, 4.0, lambda t: np.array([speed / r, 0.0]))
    phi = data.joint("steer").qpos[0]
    rates = [data.joint(j).qvel[0] for j in ("rear_left_wheel", "rear_right_wheel")]
    depth = max(-data.contact[i].dist for i in range(data.ncon))
    return phi, rates, depth, data


@pytest.mark.parametrize("steer", [-0.5, 0.2, 0.6])
def test_free_wheel_rate_matches_icr(steer):
    """Left wheel driven at v_L; ICR at ℓ/tan φ from the axle midpoint (left is +y).

    v_mid = v_L / (1 − k),  v_R = v_mid (1 + k),  k = (w / 2ℓ) tan φ.
    """
    p = TricycleParams()
    phi, (rate_l, rate_r), depth, data = _steady_turn(p, steer)
    assert phi == pytest.approx(steer, abs=2e-3)
    assert depth < MAX_PENETRATION
    k = p.track / (2 * p.wheelbase) * math.tan(phi)
    predicted_r = rate_l / (1 - k) * (1 + k)
    assert rate_r == pytest.approx(predicted_r, rel=RATE_RTOL)
    # The body turns at ψ̇ = v_mid tan φ / ℓ about the vertical.
    v_mid = rate_l * p.rear_wheel.radius / (1 - k)
    assert data.qvel[5] == pytest.approx(v_mid * math.tan(phi) / p.wheelbase, rel=RATE_RTOL)


def test_differential_splits_rates_about_the_icr():
    """Open differential: (θ̇_L + θ̇_R)/2 is servoed, the difference follows the ICR."""
    p = TricycleParams(rear_drive="differential")
    phi, (rate_l, rate_r), _, _ = _steady_turn(p, 0.4)
    k = p.track / (2 * p.wheelbase) * math.tan(phi)
    assert 0.5 * (rate_l + rate_r) == pytest.approx(1.0 / p.rear_wheel.radius, rel=1e-4)
    assert rate_r / rate_l == pytest.approx((1 + k) / (1 - k), rel=RATE_RTOL)
