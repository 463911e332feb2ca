"""The roller-phase probe of mecanum4's turn (bench.mecanum_phase)."""

import math

import numpy as np
import pytest

from wmr_mujoco.bench import mecanum_phase as mp
from wmr_mujoco.robots.mecanum4 import collider
from wmr_mujoco.robots.mecanum4.params import MecanumParams


def test_held_phases_turn_at_the_colliders_kinematics():
    # With the wheel angles held (angle term 20/s) the diagonals stay in phase (|offset|
    # below 1° of the 22.5° pitch) and the steady turn (1–2 s, after the 0.5 s ramp)
    # runs at the colliders' kinematic model to 1e-3, a third of the pitch average's own
    # turning shortfall 1 − (a+w)/(a⟨sec φ⟩+w) ≈ 3.2e-3 that the model resolves.
    r = mp.run(mp.ANGLE_GAIN, duration=2.0)
    s = r["time"] > 1.0
    kin = collider.realised_twist(MecanumParams(), np.array([0.0, 0.0, mp.YAW_RATE]))[2]
    assert float(np.mean(r["yaw_rate"][s])) / kin == pytest.approx(1.0, abs=1e-3)
    th = r["wheel_angles"][s]
    assert math.degrees(float(np.max(np.abs(np.abs(th[:, 0]) - np.abs(th[:, 1]))))) < 1.0


def test_bad_probe_inputs_are_refused():
    with pytest.raises(ValueError, match="angle_gain"):
        mp.run(-1.0)
    with pytest.raises(ValueError, match="duration"):
        mp.run(0.0, duration=0.0)
