"""omni3's layout: three wheels at L, 120° apart, axles radial; rollers tangent, staggered."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.robots.omni3.params import OmniParams


@pytest.fixture(scope="module")
def compiled():
    model = load("omni3")
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    return model, data


def test_wheels_sit_at_the_wheel_distance_with_radial_axles(compiled):
    model, data = compiled
    p = OmniParams()
    centre = data.xpos[model.body("platform").id]
    for i in range(3):
        offset = data.xpos[model.body(f"wheel{i + 1}").id] - centre
        angle = 2.0 * math.pi * i / 3.0
        radial = np.array([math.cos(angle), math.sin(angle), 0.0])
        np.testing.assert_allclose(offset, p.wheel_distance * radial, atol=1e-9)
        np.testing.assert_allclose(data.xaxis[model.joint(f"wheel{i + 1}").id], -radial,
                                   atol=1e-12)


def test_rollers_are_tangent_at_one_axis_distance_in_two_staggered_rows(compiled):
    model, data = compiled
    p = OmniParams()
    for i in range(1, 4):
        wheel = model.body(f"wheel{i}").id
        axle = data.xaxis[model.joint(f"wheel{i}").id]
        names = [model.joint(j).name for j in range(model.njnt)
                 if model.joint(j).name.startswith(f"wheel{i}_roller")]
        assert len(names) == 2 * p.rollers_per_row
        rows: dict[float, list[float]] = {}
        ref = None
        for name in names:
            j = model.joint(name).id
            arm = data.xanchor[j] - data.xpos[wheel]
            axial = float(arm @ axle)
            radial = arm - axial * axle
            axis = data.xaxis[j]
            assert abs(axis @ axle) < 1e-12 and abs(axis @ radial) < 1e-9
            ref = ref if ref is not None else np.linalg.norm(radial)
            assert np.linalg.norm(radial) == pytest.approx(ref, rel=1e-9)
            if not rows:
                basis = (radial / np.linalg.norm(radial), np.cross(axle, radial) /
                         np.linalg.norm(radial))
            rows.setdefault(round(axial, 9), []).append(
                math.atan2(radial @ basis[1], radial @ basis[0]))
        assert len(rows) == 2 and sum(rows) == pytest.approx(0.0, abs=1e-12)  # ±e
        pitch = 2.0 * math.pi / p.rollers_per_row
        a, b = (np.sort(np.mod(v, 2.0 * math.pi)) for v in rows.values())
        np.testing.assert_allclose(np.diff(a), pitch, atol=1e-9)
        np.testing.assert_allclose(np.diff(b), pitch, atol=1e-9)
        stagger = math.remainder(b[0] - a[0], pitch)
        assert abs(stagger) == pytest.approx(pitch / 2.0, abs=1e-9)


# --- roller contacts through explicit floor pairs --------------------------------------

#: Steps of the pairs-vs-bits comparison: 0.5 s at the 1 ms step, several roller
#: hand-overs at the cruising wheel rates (a roller spans 2π/12 of a wheel turn).
COMPARE_STEPS = 500


def _cruise(model: mujoco.MjModel, steps: int) -> mujoco.MjData:
    from wmr_mujoco.bench.thread_scaling import driving_controls

    data = mujoco.MjData(model)
    data.ctrl[:] = driving_controls(model, "omni3")
    for _ in range(steps):
        mujoco.mj_step(model, data)
    return data


def _plain_paired(params: OmniParams) -> mujoco.MjModel:
    """The scene with plain explicit pairs (``floor_pairs(plain=True)``) and no bits."""
    from wmr_mujoco.lookup import build_scene
    from wmr_mujoco.models.builders import common
    from wmr_mujoco.robots.omni3 import builder

    root = build_scene("omni3", params)
    builder.floor_pairs(root, params, plain=True)
    root.default.find("default", "roller").geom.conaffinity = 0
    return mujoco.MjModel.from_xml_string(common.to_xml(root))


def test_default_keeps_contact_bits_and_no_pairs():
    # The hybrid model reads the rollers (and their contact) from their contact bits.
    assert load("omni3").npair == 0


@pytest.mark.parametrize("params", [OmniParams(floor_impedance=0.001), None])
def test_floor_pairs_name_every_roller_collider_once(params):
    from wmr_mujoco.lookup import build_scene
    from wmr_mujoco.models.builders import common

    if params is None:
        model = _plain_paired(OmniParams())
    else:
        model = mujoco.MjModel.from_xml_string(common.to_xml(build_scene("omni3", params)))
    p = OmniParams()
    floor = model.geom("floor").id
    rollers = [g for g in range(model.ngeom) if model.geom_group[g] == 3
               and "_roller" in model.body(model.geom_bodyid[g]).name]
    assert len(rollers) == 3 * 2 * p.rollers_per_row
    assert model.npair == len(rollers)
    assert set(model.pair_geom1) == {floor}
    assert sorted(model.pair_geom2) == sorted(rollers)
    robot = [g for g in range(model.ngeom) if model.geom_bodyid[g] != 0]
    assert not model.geom_contype[robot].any()
    if params is None:  # plain pairs: no bits left, the broadphase skips the rollers
        assert not model.geom_conaffinity[robot].any()
    else:  # the remedy's rollers keep their bits (the hybrid model reads them) and the
        # pairs' solimp; MuJoCo makes no bit contact for a pair a <pair> names
        np.testing.assert_array_equal(model.geom_solimp[rollers], model.pair_solimp[:1].repeat(
            len(rollers), axis=0))
        data = _cruise(model, 300)
        assert data.ncon == len({(c.geom1, c.geom2) for c in data.contact[:data.ncon]})


def test_plain_pairs_move_the_robot_as_contact_bits():
    # The same contact set with the parameters MuJoCo combines from the geoms, so the same
    # constraint problem each step; only the contacts' order may differ (rounding). Pose
    # and wheel angles agree to 1e-9 (m, rad), far below any target.
    a = _cruise(_plain_paired(OmniParams()), COMPARE_STEPS)
    b = _cruise(load("omni3"), COMPARE_STEPS)
    assert a.ncon == b.ncon
    np.testing.assert_allclose(a.qpos[:7], b.qpos[:7], rtol=0, atol=1e-9)
    for i in range(3):
        assert a.joint(f"wheel{i + 1}").qpos[0] == pytest.approx(
            b.joint(f"wheel{i + 1}").qpos[0], abs=1e-9)


def test_remedy_pairs_carry_the_derived_impedance_and_friction_damping():
    from wmr_mujoco.lookup import build_scene
    from wmr_mujoco.models.builders import common

    p = OmniParams(floor_impedance=0.002)
    model = mujoco.MjModel.from_xml_string(common.to_xml(build_scene("omni3", p)))
    assert model.opt.impratio == pytest.approx(common.SLIDING_GRIP / 0.002)
    np.testing.assert_array_equal(model.pair_solimp[:, :2], 0.002)
    # MuJoCo's direct form (0, −B_f d) with B_f = 1/Δt (docs/rolling-disc.md § 8).
    np.testing.assert_allclose(model.pair_solreffriction[:, 1], -0.002 / p.sim.timestep)
    np.testing.assert_array_equal(model.pair_solreffriction[:, 0], 0.0)


@pytest.mark.parametrize("value", [-0.001, 5e-5, 0.02])
def test_bad_floor_impedance_is_named(value):
    with pytest.raises(ValueError, match="floor_impedance"):
        OmniParams(floor_impedance=value)
