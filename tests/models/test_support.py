"""Support functions and the rolling envelope against closed forms."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from wmr_mujoco.models.support import envelope, geom_support

XML = """<mujoco><worldbody><body>
<geom name="cyl" type="cylinder" size=".05 .01" euler="90 0 0"/>
<geom name="box" type="box" size=".02 .02 .02" pos="1 0 0"/>
</body></worldbody></mujoco>"""


@pytest.fixture(scope="module")
def posed():
    model = mujoco.MjModel.from_xml_string(XML)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model, data


def test_cylinder_support_is_radius_across_and_half_length_along(posed):
    model, data = posed
    dirs = np.array([[0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])  # across the axis; along it (y)
    # Closed form: R·sqrt(1 − d_z²) + h|d_z| in the geom frame; exact to rounding.
    assert geom_support(model, data, 0, dirs) == pytest.approx([0.05, 0.01], abs=1e-12)


def test_round_wheel_envelope_has_its_radius_and_no_ripple(posed):
    model, data = posed
    env = envelope(model, data, [0], data.geom_xpos[0], np.array([0.0, 1.0, 0.0]))
    assert env.radius == pytest.approx(0.05, abs=1e-12)
    assert env.ripple == pytest.approx(0.0, abs=1e-12)


def test_square_envelope_rolls_its_perimeter(posed):
    """A cube of half-side a turned about a face normal: by Cauchy the rolled distance per
    turn is the square's perimeter 8a, so the mean support is 8a/2π = 4a/π, and h runs
    from a (a face down) to a√2 (an edge down). Sampling 720 directions: the mean is good
    to 1e-5 relative, the extremes to cos(π/720) (the sampling grid)."""
    model, data = posed
    a = 0.02
    env = envelope(model, data, [1], data.geom_xpos[1], np.array([0.0, 1.0, 0.0]))
    assert env.radius == pytest.approx(4 * a / np.pi, rel=1e-5)
    assert env.low == pytest.approx(a, rel=1e-9)
    assert env.high == pytest.approx(a * np.sqrt(2), rel=1e-4)
