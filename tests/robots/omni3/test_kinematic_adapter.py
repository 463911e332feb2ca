import numpy as np
import pytest

from wmr_mujoco.robots.omni3 import OmniKinematics
from wmr_mujoco.robots.omni3.params import OmniParams


@pytest.mark.parametrize("world_frame", [False, True])
def test_trajectory_is_exact_step_after_exact_step(world_frame):
    """All steps at once = the exact steps one by one (body twist arcs or world rates).

    Same arithmetic and order of sums; 1e-14 relative allows NumPy's and libm's sin/cos
    to differ in the last bit on some CPUs (bit for bit on the reference machine).
    """
    adapter = OmniKinematics(OmniParams(), world_frame=world_frame)
    rng = np.random.default_rng(5)
    inputs = rng.normal(size=(3000, 3)) * [0.3, 0.3, 1.0]
    x = np.array([0.1, 0.2, -0.3])
    ref = [x]
    for u in inputs:
        x = adapter.exact_step(x, u, 0.00125)
        ref.append(x)
    np.testing.assert_allclose(adapter.trajectory(ref[0], inputs, 0.00125), ref,
                               rtol=1e-14, atol=1e-14)


def test_world_rates_integrate_to_their_sum():
    """World-frame rates held per step: the pose moves by Σ u Δt (to round-off)."""
    adapter = OmniKinematics(OmniParams(), world_frame=True)
    inputs = np.tile([0.2, -0.1, 0.5], (1000, 1))
    out = adapter.trajectory(np.zeros(3), inputs, 0.001)
    np.testing.assert_allclose(out[-1], [0.2, -0.1, 0.5], atol=1e-12)



@pytest.mark.parametrize("world_frame", [True, False])
def test_controls_on_are_the_controls_of_every_step_bit_for_bit(world_frame):
    """All steps' wheel rates at once are ``controls`` step by step, to the bit (world
    rates turned by each step's heading; body rates once per distinct input)."""
    adapter = OmniKinematics(OmniParams(), world_frame=world_frame)
    rng = np.random.default_rng(0)
    inputs, states = rng.normal(0.0, 0.5, (2000, 3)), rng.normal(0.0, 3.0, (2000, 3))
    inputs[1000:] = inputs[999]  # held inputs too
    want = np.array([adapter.controls(u, x) for u, x in zip(inputs, states, strict=True)])
    assert adapter.controls_on(inputs, states).tobytes() == want.tobytes()


def test_controls_on_refuses_a_bad_world_rate_as_controls_does():
    adapter = OmniKinematics(OmniParams(), world_frame=True)
    inputs, states = np.zeros((10, 3)), np.zeros((10, 3))
    inputs[5, 1] = np.nan
    with pytest.raises(ValueError, match="world_rates"):
        adapter.controls_on(inputs, states)
