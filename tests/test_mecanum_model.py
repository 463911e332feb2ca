"""mecanum4 loading: checked-in scene, built scene, wrong parameter type."""

import pytest

from wmr_mujoco.mecanum_model import SPEC, load_mecanum
from wmr_mujoco.params import OmniParams


def test_load_rejects_foreign_params():
    with pytest.raises(ValueError, match="MecanumParams"):
        load_mecanum(OmniParams())


def test_spec_points_at_the_model_folder():
    assert SPEC.scene_path.is_file() and SPEC.robot_path.is_file()
    model = load_mecanum()
    assert model.nu == 4 and model.opt.timestep == pytest.approx(0.004)
