"""Each Jacobian row and steering angle against the textbook forms (docs/analytical.md)."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.analytic.campion import Wheel
from wmr_mujoco.audit.kinematics import steer_angle, wheel_row
from wmr_mujoco.audit.wheels import AuditWheel


def _wheel(kind: str, position, axle, gamma=None, radius=0.05) -> AuditWheel:
    return AuditWheel(Wheel("w", kind, position, axle, roller_angle=gamma, radius=radius),
                      0, (), radius, 0.0)


def test_fixed_wheel_rolls_forward_at_u_over_r_and_turns_with_its_track():
    # Left wheel of a diff drive (hinge +y at y = b/2): θ̇ = (u − r b/2)/R (§7).
    b, r_ = 0.3, 0.05
    row = wheel_row(_wheel("fixed", (0.0, b / 2), (0.0, 1.0), radius=r_))
    assert row == pytest.approx([1 / r_, 0.0, -b / 2 / r_], abs=1e-12)


@pytest.mark.parametrize("gamma_deg", [0.0, 45.0, -45.0])
def test_swedish_row_is_lynch_and_park(gamma_deg):
    """Lynch & Park's row 1/(r cos γ)[cos(β+γ), sin(β+γ), x sin(β+γ) − y cos(β+γ)] with
    the classifier's γ measured the other way round (γ_LP = −γ, kinematics.py)."""
    x, y, beta, r_ = 0.1, 0.05, np.radians(90.0), 0.04
    gamma = np.radians(gamma_deg)
    g = -gamma
    expect = np.array([np.cos(beta + g), np.sin(beta + g),
                       x * np.sin(beta + g) - y * np.cos(beta + g)]) / (r_ * np.cos(g))
    axle = (-np.sin(beta), np.cos(beta))  # rolling direction d = n × ẑ = (cos β, sin β)
    assert wheel_row(_wheel("swedish", (x, y), axle, gamma, r_)) == pytest.approx(expect,
                                                                                  abs=1e-9)


def test_steer_angle_points_the_wheel_along_its_contact_velocity():
    w = _wheel("steerable", (0.5, 0.0), (0.0, 1.0))
    twist = np.array([1.0, 0.0, 1.0])  # contact velocity (1, 0.5): atan(0.5) to the left
    assert steer_angle(w, twist, 1.0) == pytest.approx(np.arctan(0.5), abs=1e-12)
    assert steer_angle(w, twist, -1.0) == pytest.approx(-np.arctan(0.5), abs=1e-12)
    # Rolling backwards rather than turning beyond 90°:
    assert steer_angle(w, -twist, 1.0) == pytest.approx(np.arctan(0.5), abs=1e-12)


def test_infeasible_names_the_steering_range_and_undetermined_yaw():
    from wmr_mujoco.analytic.campion import classify_wheels
    from wmr_mujoco.audit.kinematics import Manoeuvre, infeasible
    from wmr_mujoco.audit.wheels import Wheels

    rear = _wheel("fixed", (0.0, 0.0), (0.0, 1.0))
    front = AuditWheel(Wheel("front", "steerable", (1.0, 0.0), (0.0, 1.0), radius=0.05),
                       1, (), 0.05, 0.0, steer_joint=2)
    found = Wheels((rear, front), classify_wheels((rear.wheel, front.wheel)), 0)
    spin = Manoeuvre("spin", (0.0, 0.0, 1.0), "")  # front wheel must steer 90°
    assert "outside its range" in infeasible(found, spin, {"w"}, {"front": (-1.0, 1.0)})
    # Spinning about the rear wheel's contact: the rear wheel stands still, so only a
    # driven front wheel determines the yaw rate.
    assert infeasible(found, spin, {"w", "front"}, {}) is None
    assert "do not determine" in infeasible(found, spin, {"w"}, {})
    unicycle = Wheels((rear,), classify_wheels((rear.wheel,)), 0)
    assert "do not determine" in infeasible(unicycle, spin, {"w"}, {})
    assert infeasible(unicycle, Manoeuvre("straight", (0.2, 0.0, 0.0), ""), {"w"}, {}) is None
