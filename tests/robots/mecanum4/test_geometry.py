"""The analytic layout of mecanum4 against the compiled model's geometry."""

import numpy as np

from wmr_mujoco.lookup import load
from wmr_mujoco.robots.mecanum4.builder import WHEEL_NAMES
from wmr_mujoco.robots.mecanum4.geometry import layout
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import layout_from_model


def test_layout_matches_the_compiled_model():
    # Positions and drive directions read from the settled model (independent of the
    # parameters); radii within the contact's penetration (0.1 mm).
    p = MecanumParams()
    ours = layout(p)
    info = layout_from_model(load("mecanum4"), WHEEL_NAMES)
    np.testing.assert_allclose(info.layout.positions, ours.positions, atol=1e-4)
    np.testing.assert_allclose(np.cos(info.layout.drive_angles), np.cos(ours.drive_angles),
                               atol=1e-6)
    np.testing.assert_allclose(info.layout.radii, ours.radii, atol=1e-4)
    np.testing.assert_allclose(ours.roller_angles, [-1, 1, 1, -1] * np.full(4, np.pi / 4))
