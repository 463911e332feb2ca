"""The Whipple model's mass properties, axes and knife-edge colliders.

The reference values are the paper's Table 1 (paper frame, z down) turned into MuJoCo's
frame here, independently of the builder: p → P p and I → P I Pᵀ with P = diag(1, -1, -1).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.robots.whipple.params import WhippleParams
from wmr_mujoco.robots.whipple.rolling import compile_model

P = np.diag([1.0, -1.0, -1.0])


def _paper_bodies(p: WhippleParams):
    """(mass, CoM, tensor about CoM) of the four bodies in the paper frame."""
    def frame(i):
        ixx, iyy, izz, ixz = i
        return np.array([[ixx, 0, ixz], [0, iyy, 0], [ixz, 0, izz]])

    def wheel(i):
        return np.diag([i[0], i[1], i[0]])

    return [(p.rear_mass, np.array([0, 0, -p.rear_radius]), wheel(p.rear_inertia)),
            (p.rear_frame_mass, np.array([p.rear_frame_com[0], 0, p.rear_frame_com[1]]),
             frame(p.rear_frame_inertia)),
            (p.front_frame_mass, np.array([p.front_frame_com[0], 0, p.front_frame_com[1]]),
             frame(p.front_frame_inertia)),
            (p.front_mass, np.array([p.wheelbase, 0, -p.front_radius]),
             wheel(p.front_inertia))]


def _about_origin(bodies):
    total = np.zeros((3, 3))
    for m, c, i in bodies:
        total += i + m * (c @ c * np.eye(3) - np.outer(c, c))
    return total


@pytest.fixture(scope="module")
def upright():
    model = compile_model(WhippleParams())
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("upright").id)
    mujoco.mj_forward(model, data)
    return model, data


def test_total_mass_and_com(upright):
    model, data = upright
    p = WhippleParams()
    bodies = _paper_bodies(p)
    mass = sum(m for m, _, _ in bodies)
    com_paper = sum(m * c for m, c, _ in bodies) / mass
    root = model.body("rear_frame").id
    assert model.body_subtreemass[root] == pytest.approx(mass, abs=1e-12)
    np.testing.assert_allclose(data.subtree_com[root], P @ com_paper, atol=1e-12)


def test_inertia_about_rear_contact(upright):
    """Whole bicycle's tensor about the rear contact: the paper's sum, turned by P, and
    I_xx equal to the published M_φφ = I_Txx = 80.81722 kg m² (the 12 significant digits
    written to the XML bound the error at ~1e-10)."""
    model, data = upright
    ref = P @ _about_origin(_paper_bodies(WhippleParams())) @ P.T
    got = np.zeros((3, 3))
    for b in range(1, model.nbody):
        r = data.ximat[b].reshape(3, 3)
        i_com = r @ np.diag(model.body_inertia[b]) @ r.T
        c = data.xipos[b]
        got += i_com + model.body_mass[b] * (c @ c * np.eye(3) - np.outer(c, c))
    np.testing.assert_allclose(got, ref, atol=1e-9)
    assert got[0, 0] == pytest.approx(80.81722, abs=1e-9)


def test_products_of_inertia_sign_per_body(upright):
    model, data = upright
    p = WhippleParams()
    for name, field in (("rear_frame", "rear_frame_inertia"),
                        ("front_frame", "front_frame_inertia")):
        b = model.body(name).id
        r = data.ximat[b].reshape(3, 3)
        tensor = r @ np.diag(model.body_inertia[b]) @ r.T
        assert tensor[0, 2] == pytest.approx(-getattr(p, field)[3], abs=1e-10)


def test_steer_axis_and_trail(upright):
    model, data = upright
    p = WhippleParams()
    j = model.joint("steer").id
    axis = data.xaxis[j]
    np.testing.assert_allclose(axis, [math.sin(p.head_angle), 0, -math.cos(p.head_angle)],
                               atol=1e-12)
    # The axis meets the floor the trail ahead of the front contact (x = w + c).
    anchor = data.xanchor[j]
    t = -anchor[2] / axis[2]
    np.testing.assert_allclose(anchor + t * axis, [p.wheelbase + p.trail, 0, 0], atol=1e-12)


def test_knife_edge_contact_offset():
    """Leaning by φ, the ellipsoid (R, b, R) touches the floor b² sinφ / sqrt(b² sin²φ +
    R² cos²φ) along the axle from the wheel plane (a knife edge: 0), and its centre stands
    sqrt(b² sin²φ + R² cos²φ) high. Checked with a wide collider (b = 20 mm, offset 0.4
    mm) so the formula is tested, not the noise. Bound: 1e-6 m (the test's 1 µm
    penetration)."""
    p = WhippleParams().with_sim(wheel_half_width=0.02)
    model = compile_model(p)
    data = mujoco.MjData(model)
    lean, b, r = 0.3, p.sim.wheel_half_width, p.rear_radius
    height = math.sqrt(b * b * math.sin(lean) ** 2 + r * r * math.cos(lean) ** 2)
    data.qpos[3:7] = [math.cos(lean / 2), math.sin(lean / 2), 0, 0]
    data.qpos[2] = height - 1e-6
    mujoco.mj_forward(model, data)
    geom = model.geom("rear_wheel_collision").id
    con = [c for c in data.contact[:data.ncon] if geom in (c.geom1, c.geom2)]
    assert len(con) == 1
    axle = data.xmat[model.body("rear_wheel").id].reshape(3, 3)[:, 1]
    offset = (con[0].pos - data.xpos[model.body("rear_wheel").id]) @ axle
    expected = -b * b * math.sin(lean) / height  # towards the floor side: -y_body
    assert offset == pytest.approx(expected, abs=1e-6)
    assert abs(expected) > 3e-4
