"""Parameter checks of the caster robots."""

import pytest

from wmr_mujoco.models.params.wheeled import BallCasterParams
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.robots.double_steer.params import DoubleSteerParams
from wmr_mujoco.robots.single_steer.params import SingleSteerParams


def test_ball_inertia_and_effective_mass():
    b = BallCasterParams(radius=0.02, mass=0.05)
    assert b.inertia == pytest.approx(0.4 * 0.05 * 0.02**2)
    assert b.effective_mass == pytest.approx(0.07)  # (7/5) m


@pytest.mark.parametrize("cls,kwargs,field", [
    (BallCasterParams, {"radius": -0.01}, "radius"),
    (DiffDriveParams, {"track": 0.0}, "track"),
    (DiffDriveParams, {"caster_x": 0.1}, "caster_x"),
    (DiffDriveParams, {"chassis_com_x": 0.05}, "chassis_com_x"),
    (DiffDriveParams, {"caster": BallCasterParams(radius=0.1)}, "caster.radius"),
    (SingleSteerParams, {"chassis_com_x": -0.1}, "chassis_com_x"),
    (DoubleSteerParams, {"chassis_com_y": 0.5}, "chassis_com_y"),
    (DoubleSteerParams, {"chassis_size": (0.5, -1.0, 0.05)}, "chassis_size"),
])
def test_bad_values_name_the_field_and_range(cls, kwargs, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.")) as err:
        cls(**kwargs)
    assert "valid" in str(err.value)
