"""The floor reading against MuJoCo's own distances: robots raised, tilted and sunk."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.sim.floor_contact import FloorRecorder, WheelMap

#: Agreement of the reading's depth with ``mj_geomDistance``, m: both come from MuJoCo's
#: exact ellipsoid/cylinder-plane distance, so only rounding separates them; 1 µm is
#: 0.2 % of the 0.5 mm penetration bound the reading is judged against.
DEPTH_TOL = 1e-6


def settle(model: mujoco.MjModel, seconds: float = 0.3) -> mujoco.MjData:
    data = mujoco.MjData(model)
    for _ in range(round(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
    return data


def wheel_distances(model: mujoco.MjModel, data: mujoco.MjData, wm: WheelMap) -> np.ndarray:
    """Per wheel, the smallest signed distance of its geoms to the floor (the oracle)."""
    out = np.full(len(wm.wheels), np.inf)
    for g in np.flatnonzero(wm.geom_wheel >= 0):
        dist = mujoco.mj_geomDistance(model, data, int(g), wm.floor, 0.05, None)
        out[wm.geom_wheel[g]] = min(out[wm.geom_wheel[g]], dist)
    return out


@pytest.mark.parametrize(("robot", "wheels"), [
    ("omni3", ("wheel1", "wheel2", "wheel3")),
    ("mecanum4", ("wheel_fl", "wheel_fr", "wheel_rl", "wheel_rr")),
    ("diffdrive", ("left_wheel", "right_wheel")),
])
def test_wheels_are_found_from_the_tree(robot, wheels):
    wm = WheelMap.of(load(robot))
    assert set(wheels) <= set(wm.wheels)


def test_a_model_without_floor_is_refused():
    model = mujoco.MjModel.from_xml_string(
        "<mujoco><worldbody><body><joint type='hinge'/><geom size='0.1'/></body>"
        "</worldbody></mujoco>")
    with pytest.raises(ValueError, match="floor"):
        WheelMap.of(model)


@pytest.mark.parametrize("robot", ["omni3", "mecanum4", "diffdrive"])
def test_settled_wheels_touch_and_their_depth_is_mujocos(robot):
    model = load(robot)
    wm = WheelMap.of(model)
    data = settle(model)
    touching, depth = wm.read(data)
    oracle = wheel_distances(model, data, wm)
    assert touching.all(), (wm.wheels, oracle)
    assert depth == pytest.approx(max(0.0, -oracle.min()), abs=DEPTH_TOL)


def _free_joint_qpos(model: mujoco.MjModel) -> int:
    j = int(np.flatnonzero(model.jnt_type == mujoco.mjtJoint.mjJNT_FREE)[0])
    return int(model.jnt_qposadr[j])


@pytest.mark.parametrize("robot", ["omni3", "mecanum4"])
def test_raised_robot_has_every_wheel_off(robot):
    # 5 mm up: far above any rest depth (micrometres), so no geom may touch.
    model = load(robot)
    wm = WheelMap.of(model)
    data = settle(model)
    data.qpos[_free_joint_qpos(model) + 2] += 0.005
    mujoco.mj_forward(model, data)
    touching, depth = wm.read(data)
    assert (wheel_distances(model, data, wm) > 0).all()
    assert not touching.any() and depth == 0.0


@pytest.mark.parametrize("robot", ["omni3", "mecanum4"])
def test_tilted_robot_lifts_exactly_the_wheels_mujoco_lifts(robot):
    # Tilt about the body x axis by 3°: the wheels on +y rise by up to ~8 mm, those on −y
    # sink; the reading must name the wheels whose geoms MuJoCo puts above the floor.
    model = load(robot)
    wm = WheelMap.of(model)
    data = settle(model)
    a = _free_joint_qpos(model)
    quat = np.empty(4)
    mujoco.mju_axisAngle2Quat(quat, np.array([1.0, 0.0, 0.0]), np.radians(3.0))
    out = np.empty(4)
    mujoco.mju_mulQuat(out, quat, data.qpos[a + 3:a + 7])
    data.qpos[a + 3:a + 7] = out
    mujoco.mj_forward(model, data)
    touching, depth = wm.read(data)
    oracle = wheel_distances(model, data, wm)
    lifted = oracle > 0
    assert lifted.any() and not lifted.all()
    np.testing.assert_array_equal(touching, ~lifted)
    assert depth == pytest.approx(max(0.0, -oracle.min()), abs=DEPTH_TOL)


@pytest.mark.parametrize("robot", ["omni3", "mecanum4"])
def test_sunk_robot_reads_its_depth(robot):
    # 1 mm down: every wheel touches and the depth is MuJoCo's, about 1 mm.
    model = load(robot)
    wm = WheelMap.of(model)
    data = settle(model)
    data.qpos[_free_joint_qpos(model) + 2] -= 0.001
    mujoco.mj_forward(model, data)
    touching, depth = wm.read(data)
    assert touching.all()
    oracle = wheel_distances(model, data, wm)
    assert depth == pytest.approx(-oracle.min(), abs=DEPTH_TOL)
    assert depth > 0.001 - DEPTH_TOL


def test_recorder_collects_and_refuses_overflow():
    model = load("omni3")
    wm = WheelMap.of(model)
    data = settle(model)
    rec = FloorRecorder(wm, 2)
    rec.record(data)
    data.qpos[_free_joint_qpos(model) + 2] += 0.005
    mujoco.mj_forward(model, data)
    rec.record(data)
    reading = rec.reading()
    assert reading.off_floor.shape == (2, 3)
    assert reading.off_floor_share == pytest.approx(0.5)  # one of two samples all off
    with pytest.raises(ValueError, match="full"):
        rec.record(data)
    with pytest.raises(ValueError, match="steps"):
        FloorRecorder(wm, 0)
