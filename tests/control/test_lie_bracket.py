"""The Lie-bracket parking cycle: closed forms, the kinematic backend and the physics."""

from __future__ import annotations

import math

import numpy as np
import pytest

from wmr_mujoco.control import lie_bracket as lb
from wmr_mujoco.drive import make


def test_exact_cycle_against_composed_rigid_motions():
    """The closed form (d(1 − cos Δ), −d sin Δ) against composing the four motions by hand:
    forward d along x; turn Δ; back d along the heading Δ; turn back."""
    d, turn = 0.4, 0.7
    after_back = np.array([d, 0.0]) - d * np.array([math.cos(turn), math.sin(turn)])
    np.testing.assert_allclose(lb.exact(d, turn)[:2], after_back, atol=1e-15)


def test_second_order_prediction_and_its_error():
    """[g₁, g₂] = (sin ψ, −cos ψ, 0) = (0, −1, 0) at ψ = 0, so the prediction is (0, −ε²);
    against the exact (ε³/2 + …, −ε² + ε⁴/6 + …) its relative error is ε/2 + O(ε²)."""
    for eps in (0.05, 0.1):
        np.testing.assert_allclose(lb.second_order(eps, eps), [0, -eps**2, 0], atol=1e-9)
        err = np.linalg.norm(lb.second_order(eps, eps)[:2] - lb.exact(eps, eps)[:2])
        assert err / eps**2 == pytest.approx(eps / 2, rel=0.05)


def test_kinematic_backend_reproduces_the_exact_cycle():
    """On the kinematic model the closed-loop segments stop within e^{-12} of their amount
    (k = 4 1/s for 3 s beyond the nominal time): the net motion is the exact one within
    1e-5 relative, the heading back to the start within 1e-7 rad."""
    robot = make("diffdrive", backend="kinematic", control_period=lb.PERIOD)
    net, d, turn = lb.run_cycle(robot, 0.3, 0.25, 0.5, start_heading=1.0)
    assert lb.relative_error(net, d, turn) < 1e-5
    assert abs(net[2]) < 1e-7


@pytest.mark.parametrize("robot", ["diffdrive", "disc"])
def test_physics_within_five_percent_of_the_exact_net_motion(robot):
    """The target: the contact physics' net sideways step within 5 % of the exact kinematic
    one, worst over 20 seeded draws of speed, turn rate and start heading, at ε = 0.2 (a
    4 cm step; the relative error shrinks as ε grows, ``python -m
    wmr_mujoco.control.study`` sweeps it)."""
    row = lb.measure(robot, 0.2, draws=20)
    assert row.physics_worst < 0.05, row
    assert row.physics_median <= row.physics_worst


def test_bad_input():
    robot = make("omni3", backend="kinematic")
    with pytest.raises(ValueError, match="v, omega"):
        lb.run_cycle(robot, 0.3)
    with pytest.raises(ValueError, match="eps"):
        lb.measure("diffdrive", 2.0)
    with pytest.raises(ValueError, match="draws"):
        lb.measure("diffdrive", 0.3, draws=0)
