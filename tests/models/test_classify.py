"""Wheels found in compiled models and their Campion classes, against the theory."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.analytic import campion
from wmr_mujoco.lookup import load
from wmr_mujoco.models import classify

#: Campion, Bastin & d'Andréa-Novel (1996) / Siegwart & Nourbakhsh §3.3: the class of
#: each robot from its wheel set, by hand: three Swedish wheels (3,0); a fixed axle plus
#: a ball (2,0); one centred steerable wheel plus balls (2,1); a fixed axle plus one
#: steerable wheel (1,1); two steerable wheels plus a ball (1,2).
EXPECTED = {"omni3": ((3, 0), {"swedish": 3}), "bicycle": ((1, 1), {"fixed": 1, "steerable": 1}),
            "tricycle": ((1, 1), {"fixed": 2, "steerable": 1}),
            "diffdrive": ((2, 0), {"fixed": 2, "ball": 1}),
            "single_steer": ((2, 1), {"steerable": 1, "ball": 2}),
            "double_steer": ((1, 2), {"steerable": 2, "ball": 1})}


@pytest.mark.parametrize("name", list(EXPECTED))
def test_classes_of_the_package_robots(name):
    c = classify.classify(load(name))
    cls, counts = EXPECTED[name]
    assert c.robot_class == cls, campion.summary(c)
    assert c.wheel_counts() == counts
    assert c.manoeuvrability == sum(cls)


def test_the_whipple_fork_is_outside_the_theory_naming_its_tilt():
    """The benchmark's steer axis is tilted by λ = π/10 = 18° (Meijaard et al. 2007)."""
    c = classify.classify(load("whipple"))
    assert c.robot_class is None
    assert "tilted 18.0° from the vertical" in c.reason


def test_omni_rollers_are_at_zero_degrees():
    c = classify.classify(load("omni3"))
    assert all(abs(w.roller_angle) < math.radians(1.0) for w in c.wheels)


def test_classify_does_not_change_the_model():
    model = load("diffdrive")
    before = model.opt.timestep, model.body_mass.copy()
    classify.classify(model)
    assert (model.opt.timestep, list(model.body_mass)) == (before[0], list(before[1]))


FLOOR = '<geom name="floor" type="plane" size="0 0 0.05"/>'
WHEEL = ('<inertial pos="0 0 0" mass="0.2" diaginertia="1e-4 2e-4 1e-4"/>'
         '<geom type="ellipsoid" size="0.05 0.01 0.05"/>')


def _mecanum_xml(gamma_deg: float, n_rollers: int = 8) -> str:
    """Four wheels at (±0.15, ±0.12), hub hinge about y, ``n`` rollers whose axes make
    ``γ`` with the wheel plane (the roller axis turned about the radial direction)."""
    g = math.radians(gamma_deg)
    wheels = []
    for i, (x, y) in enumerate(((0.15, 0.12), (0.15, -0.12), (-0.15, 0.12), (-0.15, -0.12))):
        sign = 1 if i in (0, 3) else -1
        rollers = []
        for k in range(n_rollers):
            a = 2 * math.pi * k / n_rollers
            radial = np.array([math.sin(a), 0.0, -math.cos(a)])
            tangent = np.array([math.cos(a), 0.0, math.sin(a)])
            axis = math.cos(g) * tangent + sign * math.sin(g) * np.array([0.0, 1.0, 0.0])
            p = 0.04 * radial
            rollers.append(
                f'<body pos="{p[0]:.6f} 0 {p[2]:.6f}">'
                f'<joint name="w{i}_r{k}" type="hinge" axis="{axis[0]:.6f} {axis[1]:.6f} '
                f'{axis[2]:.6f}"/><inertial pos="0 0 0" mass="0.01" diaginertia="1e-6 1e-6 1e-6"/>'
                f'<geom type="sphere" size="0.01"/></body>')
        wheels.append(f'<body name="wheel{i}" pos="{x} {y} 0"><joint name="hub{i}" type="hinge" '
                      f'axis="0 1 0"/>'
                      f'<inertial pos="0 0 0" mass="0.2" diaginertia="1e-4 2e-4 1e-4"/>'
                      f'{"".join(rollers)}</body>')
    return (f'<mujoco><worldbody>{FLOOR}<body name="base" pos="0 0 0.05"><freejoint/>'
            f'<inertial pos="0 0 0" mass="3" diaginertia="0.03 0.03 0.05"/>'
            f'{"".join(wheels)}</body></worldbody></mujoco>')


def test_swedish_roller_angle_of_a_synthetic_mecanum():
    c = classify.classify(mujoco.MjModel.from_xml_string(_mecanum_xml(45.0)))
    assert c.robot_class == (3, 0)
    assert c.wheel_counts() == {"swedish": 4}
    # Built at ±45°: the measured angle is exact up to the XML's 6 printed digits.
    gammas = sorted(math.degrees(w.roller_angle) for w in c.wheels)
    assert gammas == pytest.approx([-45, -45, 45, 45], abs=1e-3)


def test_rollers_along_the_hub_axis_are_outside_the_theory():
    c = classify.classify(mujoco.MjModel.from_xml_string(_mecanum_xml(89.0)))
    assert c.robot_class is None
    assert "γ ≈ 90°" in c.reason


def _castor_xml(offset: float) -> str:
    """Two fixed wheels at y = ±0.15 and a swivel castor behind, trailing by ``offset``."""
    return (f'<mujoco><worldbody>{FLOOR}<body name="base" pos="0 0 0.05"><freejoint/>'
            f'<inertial pos="-0.1 0 0" mass="3" diaginertia="0.03 0.03 0.05"/>'
            f'<body pos="0 0.15 0"><joint name="left" axis="0 1 0"/>{WHEEL}</body>'
            f'<body pos="0 -0.15 0"><joint name="right" axis="0 1 0"/>{WHEEL}</body>'
            f'<body pos="-0.3 0 0"><joint name="swivel" axis="0 0 1"/>'
            f'<inertial pos="0 0 0" mass="0.05" diaginertia="1e-5 1e-5 1e-5"/>'
            f'<body pos="{-offset} 0 0"><joint name="castor" axis="0 1 0"/>{WHEEL}</body>'
            f'</body></body></worldbody></mujoco>')


def test_off_centred_castor_is_found_with_its_offset():
    c = classify.classify(mujoco.MjModel.from_xml_string(_castor_xml(0.03)))
    castor = next(w for w in c.wheels if w.kind == "castor")
    assert castor.offset == pytest.approx(0.03, abs=1e-4)  # settled geometry, µm exact
    assert castor.steer_joint == "swivel"
    assert c.robot_class == (2, 0)


def test_no_floor_is_an_error():
    xml = _castor_xml(0.03).replace(FLOOR, "")
    with pytest.raises(ValueError, match="no floor"):
        classify.classify(mujoco.MjModel.from_xml_string(xml))


def test_a_wheel_without_floor_contact_is_an_error():
    # A fourth wheel mounted 0.3 m up on the chassis, which rests on the other three.
    lifted = _castor_xml(0.03).replace(
        '<body pos="-0.3 0 0">', f'<body pos="0 0 0.3"><joint name="lifted" axis="0 1 0"/>'
        f'{WHEEL}</body><body pos="-0.3 0 0">')
    with pytest.raises(ValueError, match="'lifted' has no floor contact"):
        classify.classify(mujoco.MjModel.from_xml_string(lifted))


def test_a_robot_without_wheels_is_an_error():
    xml = (f'<mujoco><worldbody>{FLOOR}<body pos="0 0 0.05"><freejoint/>'
           f'<geom type="box" size="0.1 0.1 0.05"/></body></worldbody></mujoco>')
    with pytest.raises(ValueError, match="no wheels"):
        classify.classify(mujoco.MjModel.from_xml_string(xml))


def test_command_line_classifies_files(tmp_path, capsys):
    good = tmp_path / "castor.xml"
    good.write_text(_castor_xml(0.03))
    bad = tmp_path / "nofloor.xml"
    bad.write_text(_castor_xml(0.03).replace(FLOOR, ""))
    assert classify.main([str(good)]) == 0
    assert "class (2,0)" in capsys.readouterr().out
    assert classify.main([str(bad)]) == 1
    assert "no floor" in capsys.readouterr().out


#: A humanoid-like body: a torso on a free joint, two legs on horizontal hip hinges (a
#: capsule along the leg, across the hinge), two arms on a shoulder pair of hinges; it
#: stands on its leg capsules' ends. Every joint below the torso is a limb's, none a
#: wheel's: no collider is round about the hinge it turns on.
HUMANOID = f"""<mujoco><worldbody>{FLOOR}
  <body name="torso" pos="0 0 1.0"><freejoint/>
    <geom type="capsule" fromto="0 0 0 0 0 0.5" size="0.12"/>
    <body name="leg_l" pos="0 0.1 0"><joint name="hip_l" axis="0 1 0" damping="5"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.95" size="0.05"/></body>
    <body name="leg_r" pos="0 -0.1 0"><joint name="hip_r" axis="0 1 0" damping="5"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.95" size="0.05"/></body>
    <body name="arm_l" pos="0 0.2 0.45"><joint name="shoulder1_l" axis="0 1 0"/>
      <joint name="shoulder2_l" axis="1 0 0"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.5" size="0.04"/></body>
    <body name="arm_r" pos="0 -0.2 0.45"><joint name="shoulder1_r" axis="0 1 0"/>
      <joint name="shoulder2_r" axis="1 0 0"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.5" size="0.04"/></body>
  </body></worldbody></mujoco>"""

#: A robot arm on a mobile base that rests on the floor on its box: two links on
#: horizontal hinges, the forearm lying on the floor (a capsule along the link, across
#: its hinge): no wheels.
ARM = f"""<mujoco><worldbody>{FLOOR}
  <body name="base" pos="0 0 0.05"><freejoint/><geom type="box" size="0.1 0.1 0.05"/>
    <body name="upper" pos="0.1 0 0.05"><joint name="shoulder" axis="0 1 0" damping="1"/>
      <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.03"/>
      <body name="fore" pos="0.3 0 0"><joint name="elbow" axis="0 1 0" damping="1"/>
        <geom type="capsule" fromto="0 0 0 0.3 0 -0.06" size="0.03"/></body>
    </body></body></worldbody></mujoco>"""


@pytest.mark.parametrize("xml", [HUMANOID, ARM], ids=["humanoid", "robot arm"])
def test_a_limb_on_a_horizontal_hinge_is_no_wheel(xml):
    model = mujoco.MjModel.from_xml_string(xml)
    with pytest.raises(ValueError, match=r"^no wheels: .*body '\w+' turns on '\w+' but no "
                                         r"collider of it is round about that axis"):
        classify.classify(model)


def test_wmr_info_names_no_joint_of_a_humanoid_a_wheel(tmp_path):
    from wmr_mujoco.info import describe_file

    path = tmp_path / "humanoid.xml"
    path.write_text(HUMANOID)
    line = next(x for x in describe_file(path).splitlines() if x.startswith("Campion"))
    assert line.startswith("Campion class: none (no wheels")
    assert "wheel '" not in line


def test_a_round_collider_off_its_hinge_is_no_wheel():
    """The castor robot with its left wheel's disc 2 cm off the hinge axis (a cam, not a
    wheel): the two others still make a class, the cam is named in a note."""
    cam = _castor_xml(0.03).replace(
        f'<joint name="left" axis="0 1 0"/>{WHEEL}',
        '<joint name="left" axis="0 1 0"/><inertial pos="0 0 0" mass="0.2" '
        'diaginertia="1e-4 2e-4 1e-4"/><geom type="ellipsoid" pos="0.02 0 0" '
        'size="0.05 0.01 0.05"/>')
    wheels, notes = classify.find_wheels(mujoco.MjModel.from_xml_string(cam))
    assert sorted(w.name for w in wheels) == ["castor", "right"]
    assert any("turns on 'left' but no collider of it is round" in n for n in notes)


def test_a_thin_cylinder_roller_is_round_about_its_hinge():
    """A roller as an O-ring (a flat cylinder about its hinge) rolls: the element type
    MuJoCo reports is a NumPy integer, compared with the geom-type enum by value."""
    xml = """<mujoco><worldbody><body><joint name="h" type="hinge" axis="0 0 1"/>
      <geom name="g" type="cylinder" size="0.006 0.002" quat="0 1 0 0"/></body>
      </worldbody></mujoco>"""
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert classify.round_about(model, data, model.geom("g").id, model.joint("h").id)


def test_a_wheel_free_sideways_in_its_contact_is_swedish():
    """omni3_reduced's wheels are plain hinges, but their floor pairs are nearly
    frictionless along the axle (the contact frame follows the capsule): Swedish wheels of
    roller angle 0 and omni3's class (3,0). The same model with the pairs' friction made
    isotropic has three fixed wheels on three axles, outside the theory."""
    model = load("omni3_reduced")
    c = classify.classify(model)
    assert c.robot_class == (3, 0) and c.wheel_counts() == {"swedish": 3}
    assert all(w.roller_angle == 0.0 for w in c.wheels)
    model.pair_friction[:, 0] = model.pair_friction[:, 1]
    c = classify.classify(model)
    assert c.robot_class is None and c.wheel_counts() == {"fixed": 3}
