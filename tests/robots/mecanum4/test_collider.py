"""mecanum4's rolling model from its colliders, and the step model's effective layout."""

import dataclasses
import math

import numpy as np
import pytest

from wmr_mujoco.robots.mecanum4 import collider
from wmr_mujoco.robots.mecanum4.geometry import layout
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels import pitch_averaged as pa

P = MecanumParams()
COMMANDS = [(0.3, 0.0, 0.0), (0.0, 0.3, 0.0), (0.0, 0.0, 1.0),
            (0.3 / math.sqrt(2), 0.3 / math.sqrt(2), 0.0), (0.3, 0.0, 0.5)]


def _averaged(params, nu):
    lay = layout(params)
    rates = ok.wheel_jacobian(lay) @ nu
    return pa.realised_twist_map(lay, params.rollers_per_wheel, np.abs(rates) > 1e-9) @ nu


@pytest.mark.parametrize("twist", COMMANDS)
def test_effective_layout_rolls_at_the_collider_twist(twist):
    # H_e = H(L̄) C⁻¹ realised as a layout: its least-squares twist under the ideal wheel
    # rates is the collider model's, to rounding.
    nu = np.array(twist)
    lay = collider.effective_layout(P, nu)
    got = np.linalg.pinv(ok.wheel_jacobian(lay)) @ (ok.wheel_jacobian(layout(P)) @ nu)
    np.testing.assert_allclose(got, collider.realised_twist(P, nu), atol=1e-12)


@pytest.mark.parametrize("twist", COMMANDS)
def test_collider_twist_is_near_the_pitch_averaged_one(twist):
    # The colliders move the averaged model by their rolling height and contact walk,
    # a second-order effect: more than 1e-4 and less than 1e-3 of each moving component
    # (⟨h⟩/R − 1 ≈ −3e-4 alone; docs/mecanum.md §3).
    nu = np.array(twist)
    ref = _averaged(P, nu)
    got = collider.realised_twist(P, nu)
    moving = np.abs(ref) > 1e-9
    rel = got[moving] / ref[moving] - 1.0
    assert np.all(rel < -1e-4) and np.all(rel > -1e-3)
    np.testing.assert_allclose(got[~moving], 0.0, atol=1e-12)


def test_collider_twist_scales_with_the_command():
    # The rows do not depend on the rates: twice the command, twice the twist.
    nu = np.array([0.1, -0.2, 0.4])
    np.testing.assert_allclose(collider.realised_twist(P, 2 * nu),
                               2 * collider.realised_twist(P, nu), rtol=1e-12)
    np.testing.assert_array_equal(collider.realised_twist(P, np.zeros(3)), np.zeros(3))


def test_capsules_keep_the_pitch_averaged_model():
    capsule = dataclasses.replace(P, roller_shape="capsule")
    assert collider.roller_geometry(capsule) is None
    nu = np.array([0.0, 0.0, 1.0])
    np.testing.assert_allclose(collider.realised_twist(capsule, nu), _averaged(capsule, nu),
                               atol=1e-12)


def test_rotation_falls_short_by_the_collider_terms():
    # On the spot the colliders add, to the pitch average's 1 − (a+w)/(a⟨sec φ⟩+w), the
    # mean rolling height's deficit and the walk's least-squares term: the turn is slower
    # than the averaged model's, and slower than the ideal profile's (which has the walk
    # but h = R): ordering from the geometry.
    nu = np.array([0.0, 0.0, 1.0])
    ideal = collider.realised_twist(dataclasses.replace(P, roller_shape="profile",
                                                        floor_impedance=0.0), nu)[2]
    ellipsoid = collider.realised_twist(P, nu)[2]
    assert ellipsoid < ideal < _averaged(P, nu)[2]
