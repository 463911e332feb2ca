import mujoco
import numpy as np
import pytest

import wmr_mujoco
from wmr_mujoco.envs.profiles import drivable, profile
from wmr_mujoco.envs.randomization import Bands, Randomizer, wheel_geoms


def test_default_bands_are_physical():
    Bands()  # does not raise


@pytest.mark.parametrize("band", [
    {"friction": (0.0, 1.0)},        # frictionless floor: outside (0.1, 3)
    {"mass": (0.8, 2.5)},            # more than double the mass
    {"wheel_radius": (0.5, 1.0)},    # half the wheel
    {"servo_gain": (1.2, 1.1)},      # lo > hi
    {"friction": (0.5, float("nan"))},
])
def test_unphysical_bands_are_refused(band):
    with pytest.raises(ValueError, match="physical range"):
        Bands(**band)


def test_unknown_band_is_named():
    with pytest.raises(ValueError, match="valid: friction, mass, wheel_radius, servo_gain"):
        Bands().replace(gravity=(0.9, 1.1))


def test_draws_stay_in_their_bands_and_restore():
    model = wmr_mujoco.load("diffdrive")
    data = mujoco.MjData(model)
    bands = Bands(friction=(0.5, 0.6), mass=(1.1, 1.2), wheel_radius=(1.01, 1.02),
                  servo_gain=(0.3, 0.4))
    rnd = Randomizer(model, bands, ("left_wheel", "right_wheel"))
    nominal = {k: v.copy() for k, v in rnd.nominal.items()}
    factors = rnd.apply(np.random.default_rng(0), data)
    for key, band in (("friction", bands.friction), ("servo_gain", bands.servo_gain),
                      ("wheel_radius", bands.wheel_radius)):
        assert np.all((factors[key] >= band[0]) & (factors[key] <= band[1]))
    # The floor's μ and each actuator's kv are the nominal ones times the drawn factor.
    assert model.geom_friction[0, 0] == pytest.approx(nominal["geom_friction"][0, 0]
                                                      * factors["friction"][0])
    np.testing.assert_allclose(model.actuator_gainprm[:, 0],
                               nominal["actuator_gainprm"][:, 0] * factors["servo_gain"])
    np.testing.assert_allclose(model.actuator_biasprm[:, 2],
                               nominal["actuator_biasprm"][:, 2] * factors["servo_gain"])
    ratio = model.body_mass[1:] / nominal["body_mass"][1:]
    assert np.all((ratio >= 1.1 - 1e-12) & (ratio <= 1.2 + 1e-12))
    (g, _mask), _ = wheel_geoms(model, ("left_wheel", "right_wheel"))
    assert model.geom_size[g, 0] == pytest.approx(0.08 * factors["wheel_radius"][0])
    rnd.restore(data)
    for key, value in nominal.items():
        np.testing.assert_array_equal(getattr(model, key), value)


def test_draws_are_seeded():
    model = wmr_mujoco.load("diffdrive")
    rnd = Randomizer(model, Bands(), ("left_wheel", "right_wheel"))
    a = rnd.apply(np.random.default_rng(7), mujoco.MjData(model))
    b = rnd.apply(np.random.default_rng(7), mujoco.MjData(model))
    for key in a:
        np.testing.assert_array_equal(a[key], b[key])


def test_roller_wheels_refuse_a_radius_band():
    model = wmr_mujoco.load("omni3")
    with pytest.raises(ValueError, match="wheel_radius=None"):
        Randomizer(model, Bands(), ("wheel1",))
    Randomizer(model, Bands(wheel_radius=None), ("wheel1",))


class _Extremes(np.random.Generator):
    """A generator whose wheel-radius draw puts the first wheel at ``first`` and the
    others at ``rest`` (every other draw as usual)."""

    def __init__(self, band, first, rest):
        super().__init__(np.random.PCG64(0))
        self.band, self.first, self.rest = band, first, rest

    def uniform(self, low=0.0, high=1.0, size=None):
        if (low, high) == self.band and size is not None:
            return np.array([self.first] + [self.rest] * (size - 1))
        return super().uniform(low, high, size)


@pytest.mark.parametrize("robot", [r for r in drivable() if profile(r).bands.wheel_radius])
def test_wheels_touch_the_floor_at_the_ends_of_the_radius_band(robot):
    # Each wheel's radius is drawn on its own: with the first wheel at one end of the band
    # and the others at the other end, the robot settles so that every wheel still touches
    # the floor (a chassis that cannot pitch or heave would lift a wheel off).
    from wmr_mujoco.envs import WmrEnv

    band = profile(robot).bands.wheel_radius
    for first, rest in (band, band[::-1]):
        env = WmrEnv(robot, profile(robot).tasks[0],
                     randomize=Bands(friction=None, mass=None, wheel_radius=band,
                                     servo_gain=None))

        env.episode.reset(_Extremes(band, first, rest))
        for _ in range(10):
            env.step(np.zeros(env.action_space.shape))
        assert env.episode.state.wheel_contacts.all(), (robot, first, rest)
