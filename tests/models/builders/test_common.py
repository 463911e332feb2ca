"""Masses and inertias of the compiled models against the documented parameters."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco import ROBOTS, load
from wmr_mujoco.models.builders.common import to_xml
from wmr_mujoco.robots.disc.builder import build
from wmr_mujoco.robots.disc.params import DiscParams

WHEELS = {
    "disc": {"wheel": lambda p: p.wheel},
    "bicycle": {"rear_wheel": lambda p: p.rear_wheel, "front_wheel": lambda p: p.front_wheel},
    "tricycle": {"rear_left_wheel": lambda p: p.rear_wheel,
                 "rear_right_wheel": lambda p: p.rear_wheel,
                 "front_wheel": lambda p: p.front_wheel},
}


def _inertia_about_joint_axis(model: mujoco.MjModel, joint: str) -> float:
    j = model.joint(joint)
    body = j.bodyid[0]
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, model.body_iquat[body])
    rot = rot.reshape(3, 3)
    inertia = rot @ np.diag(model.body_inertia[body]) @ rot.T
    axis = j.axis if hasattr(j, "axis") else model.jnt_axis[j.id]
    return float(axis @ inertia @ axis)


#: Every registered robot built from its parameters (read from the registry: a new robot
#: is checked with no edit here).
BUILT = [name for name, spec in ROBOTS.items() if spec.build is not None]


@pytest.mark.parametrize("robot", BUILT)
def test_total_mass_is_the_parameters_total_mass(robot):
    # Every body's mass is a parameter or a sum of them: the compiled total equals the
    # parameters' ``total_mass`` to rounding (rel 1e-12).
    params = ROBOTS[robot].params_type()
    model = load(robot)
    assert sum(model.body_mass[1:]) == pytest.approx(params.total_mass, rel=1e-12)


@pytest.mark.parametrize("robot", list(WHEELS))
def test_wheel_axial_inertia_is_the_thin_disc(robot):
    params = ROBOTS[robot].params_type()
    model = load(robot)
    for joint, wheel_of in WHEELS[robot].items():
        w = wheel_of(params)
        assert _inertia_about_joint_axis(model, joint) == pytest.approx(
            0.5 * w.mass * w.radius**2, rel=1e-12)


def test_free_disc_is_one_rigid_disc():
    params = ROBOTS["disc_free"].params_type()
    model = load("disc_free")
    assert model.nbody == 2 and model.nv == 6
    w = params.wheel
    np.testing.assert_allclose(sorted(model.body_inertia[1]), sorted(
        [0.5 * w.mass * w.radius**2] + [w.mass * (w.radius**2 / 4 + w.width**2 / 12)] * 2))


def test_exported_xml_is_clean():
    text = to_xml(build(DiscParams()))
    assert 'class="/"' not in text and "unnamed" not in text
    assert "0.15" in text and "0.1499999" not in text


# ---- Visual mounts, forks and stems leave the physics untouched (issue 17 item 8) ----

#: The robots whose wheels are held by visual motor mounts, axles, forks or caster stems:
#: every registered robot built from its parameters whose model has a visual geom.
MOUNTED = [name for name in BUILT
           if (load(name).geom_group == 2).any()]
#: Compiled arrays that define the dynamics: bodies, joints and dofs, actuators.
PHYSICS_ARRAYS = ("body_parentid", "body_pos", "body_quat", "body_mass", "body_inertia",
                  "body_ipos", "body_iquat", "jnt_type", "jnt_axis", "jnt_pos", "jnt_range",
                  "dof_armature", "dof_damping", "dof_frictionloss", "actuator_trnid",
                  "actuator_gainprm", "actuator_biasprm", "actuator_ctrlrange", "opt.timestep")
#: Compiled arrays of the colliders (every geom with a contact bit set).
COLLIDER_ARRAYS = ("geom_type", "geom_bodyid", "geom_size", "geom_pos", "geom_quat",
                   "geom_contype", "geom_conaffinity", "geom_condim", "geom_friction",
                   "geom_solref", "geom_solimp", "geom_margin")


def _compile(robot: str, strip_visual: bool) -> mujoco.MjModel:
    from wmr_mujoco.lookup import build_scene

    root = build_scene(robot)
    if strip_visual:
        for geom in root.find_all("geom"):
            if geom.dclass == "visual":
                geom.remove()
    return mujoco.MjModel.from_xml_string(to_xml(root), root.get_assets())


def _attr(model: mujoco.MjModel, name: str) -> np.ndarray:
    obj = model
    for part in name.split("."):
        obj = getattr(obj, part)
    return np.asarray(obj)


@pytest.mark.parametrize("robot", MOUNTED)
def test_visual_geoms_leave_the_physics_bit_identical(robot):
    # The mounts are geoms of class ``visual`` only: contype = conaffinity = 0 and density
    # 0 on bodies with explicit inertials. Removing every visual geom must therefore leave
    # every dynamics array and every collider exactly equal (no tolerance: the compiler
    # is deterministic), and a rollout of the two models must agree bit for bit.
    full, bare = _compile(robot, False), _compile(robot, True)
    assert full.ngeom > bare.ngeom
    visual = full.geom_group == 2
    assert np.all(full.geom_contype[visual] == 0) and np.all(full.geom_conaffinity[visual] == 0)
    assert (full.nq, full.nv, full.nu, full.nbody) == (bare.nq, bare.nv, bare.nu, bare.nbody)
    for name in PHYSICS_ARRAYS:
        np.testing.assert_array_equal(_attr(full, name), _attr(bare, name), err_msg=name)
    colliders = [(m.geom_contype | m.geom_conaffinity) != 0 for m in (full, bare)]
    for name in COLLIDER_ARRAYS:
        np.testing.assert_array_equal(_attr(full, name)[colliders[0]],
                                      _attr(bare, name)[colliders[1]], err_msg=name)
    rng = np.random.default_rng(0)
    ctrl = rng.uniform(full.actuator_ctrlrange[:, 0], full.actuator_ctrlrange[:, 1]) \
        if full.nu else np.zeros(0)
    runs = []
    for model in (full, bare):
        data = mujoco.MjData(model)
        if model.nkey:
            mujoco.mj_resetDataKeyframe(model, data, model.nkey - 1)
        data.ctrl[:] = ctrl
        for _ in range(100):
            mujoco.mj_step(model, data)
        runs.append(np.concatenate([data.qpos, data.qvel]))
    np.testing.assert_array_equal(runs[0], runs[1])


def test_sliding_pair_kwargs_is_the_disc_remedy():
    # d0 = d_width = d; friction damping B_f = 1/Δt in MuJoCo's direct form (0, −B_f d);
    # the rest of the pair is the collision class's (docs/rolling-disc.md § 8).
    from wmr_mujoco.models.builders.common import contact_pair_kwargs, sliding_pair_kwargs
    from wmr_mujoco.models.params import SimParams

    sim = SimParams(timestep=0.004, contact_timeconst=0.008)
    kw = sliding_pair_kwargs(sim, 0.002)
    assert kw["solimp"][:2] == (0.002, 0.002)
    assert kw["solreffriction"] == (0.0, -0.002 / 0.004)
    assert kw["solref"] == (3 * 0.004, 1.0)  # SLIDING_STEPS · Δt, above 2 Δt
    plain = contact_pair_kwargs(sim)
    for key in ("condim", "friction", "margin", "gap"):
        assert kw[key] == plain[key]
    assert sliding_pair_kwargs(sim, 0.0) == plain


def test_sliding_pair_kwargs_names_a_bad_impedance():
    import pytest

    from wmr_mujoco.models.builders.common import sliding_pair_kwargs
    from wmr_mujoco.models.params import SimParams

    with pytest.raises(ValueError, match="impedance"):
        sliding_pair_kwargs(SimParams(), 2.0)


def _normal_gain(robot: str, params) -> float:
    """Largest eigenvalue of the normal rows' gain ``A (A + R)⁻¹ / d`` at rest."""
    import mujoco
    import numpy as np

    from wmr_mujoco.bench.floor_runs import settled

    run = settled(robot, params)
    m, d = run.model, run.data
    m.opt.jacobian = mujoco.mjtJacobian.mjJAC_DENSE
    mujoco.mj_forward(m, d)
    n = d.nefc
    jac = np.array(d.efc_J[:n * m.nv]).reshape(n, m.nv)
    minv_jt = np.zeros((n, m.nv))
    mujoco.mj_solveM(m, d, minv_jt, jac)
    a = jac @ minv_jt.T
    gain = a @ np.linalg.inv(a + np.diag(d.efc_R[:n]))
    imp = np.array(d.efc_KBIP).reshape(-1, 4)[:n, 2]
    rows = np.flatnonzero(d.efc_type[:n] == mujoco.mjtConstraint.mjCNSTR_CONTACT_ELLIPTIC)
    normal = rows[::3]  # condim 3: normal, then two friction rows
    return float(np.max(np.linalg.eigvals(gain[np.ix_(normal, normal)] / imp[normal]).real))


ROBOTS_WITH_PAIRS = ("bicycle", "tricycle", "omni3", "omni3_reduced", "mecanum4", "diffdrive",
                     "single_steer", "double_steer")


@pytest.mark.parametrize("robot", ROBOTS_WITH_PAIRS)
def test_default_pair_time_constant_exceeds_the_normal_gain(robot):
    # Stability of a soft (d ≪ 1) contact's explicit damping needs λ < t_c/Δt
    # (sliding_pair_kwargs); every robot's default floor pairs must keep it, with the
    # pairs' own t_c and the model's step.
    from wmr_mujoco import load

    model = load(robot)
    assert model.npair > 0 and np.all(model.pair_solimp[:, 0] < 0.01)  # the remedy
    steps = float(np.min(model.pair_solref[:, 0])) / model.opt.timestep
    assert _normal_gain(robot, None) < steps


def test_mecanum4_needs_more_than_three_steps():
    # mecanum4's λ exceeds 2 (at t_c = 2 Δt it diverged, docs/floor-contact.md): its
    # default t_c is 4 steps, above SLIDING_STEPS.
    from wmr_mujoco import load
    from wmr_mujoco.models.builders.common import SLIDING_STEPS

    assert _normal_gain("mecanum4", None) > 2.0
    model = load("mecanum4")
    assert float(np.min(model.pair_solref[:, 0])) / model.opt.timestep > SLIDING_STEPS


def test_a_capsule_doubles_the_gain_of_one_touching_roller():
    # omni3_reduced's capsule touches the floor at both end caps, 2 h = 0.12 mm apart
    # along the axle: two nearly equal normal rows where omni3 has one touching roller
    # per wheel, so λ doubles (within 10 %: the caps' small lever arm about the axle and
    # the two models' different wheel inertias). Hence its pairs' four steps
    # (omni3_reduced.builder.CAPSULE_PAIR_STEPS) against the wheels' three.
    from wmr_mujoco.robots.omni3_reduced.builder import CAPSULE_PAIR_STEPS

    ratio = _normal_gain("omni3_reduced", None) / _normal_gain("omni3", None)
    assert ratio == pytest.approx(2.0, rel=0.1)
    assert _normal_gain("omni3_reduced", None) < CAPSULE_PAIR_STEPS


def test_sliding_impratio_keeps_impratio_times_d():
    # impratio · d is the friction rows' stiffness gain (docs/rolling-disc.md § 8): the
    # disc's product, 1e4 · 0.001, at any d.
    import pytest

    from wmr_mujoco.models.builders.common import sliding_impratio

    assert sliding_impratio(0.001) * 0.001 == pytest.approx(1e4 * 0.001)
    assert sliding_impratio(0.005) * 0.005 == pytest.approx(1e4 * 0.001)
    with pytest.raises(ValueError, match="impedance"):
        sliding_impratio(0.0)


@pytest.mark.parametrize("robot", sorted(ROBOTS))
def test_every_model_turns_island_discovery_off(robot):
    # new_root's option: one robot is one island, so discovery only adds its cost.
    model = load(robot)
    assert model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_ISLAND


@pytest.mark.parametrize("robot", sorted(ROBOTS))
def test_island_discovery_changes_no_bit_of_a_driven_run(robot):
    # One tree, one island: with discovery on, the solver solves the same problem in the
    # same order, so 0.5 s of random wheel commands from rest end in the same bytes.
    off = load(robot)
    on = load(robot)
    on.opt.disableflags &= ~int(mujoco.mjtDisableBit.mjDSBL_ISLAND)
    rng = np.random.default_rng(3)
    controls = rng.uniform(-1.0, 1.0, (5, off.nu)) * off.actuator_ctrlrange[:, 1]
    finals = []
    for model in (off, on):
        data = mujoco.MjData(model)
        for ctrl in controls:
            data.ctrl[:] = ctrl
            for _ in range(round(0.1 / model.opt.timestep)):
                mujoco.mj_step(model, data)
        assert data.ncon > 0  # on the floor: the contacts are in the constraint set
        finals.append(np.concatenate([data.qpos, data.qvel]).tobytes())
    assert finals[0] == finals[1]
