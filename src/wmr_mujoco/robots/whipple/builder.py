"""Builder of the Whipple benchmark bicycle (Meijaard et al. 2007) for MuJoCo.

World frame: x forward, y left, z up, origin at the rear contact of the upright bicycle.
The paper's frame is x forward, y right, z down; the map between them is the rotation by
π about x, ``P = diag(1, -1, -1)``:

    p_mj = P p_paper = (x, -y, -z),     I_mj = P I_paper Pᵀ

so the diagonal of an inertia tensor is unchanged and the product ``I_xz`` changes sign
(``I_xy`` would too; it is zero by symmetry). MuJoCo's ``fullinertia`` is
``(I_xx, I_yy, I_zz, I_xy, I_xz, I_yz)`` in tensor elements, in the body frame; every body
here keeps the world's axes at the reference pose, so it is ``P I Pᵀ`` directly.

Kinematic tree::

    world ─ rear_frame [free joint, origin at the rear axle]
             ├─ rear_wheel [hinge about y]
             └─ front_frame [hinge "steer" about the head axis]
                  └─ front_wheel [hinge about y]

The steer hinge's axis is the head axis pointing DOWN, ``(sin λ, 0, -cos λ)``, so its
angle is the paper's δ (positive: steer to the right); lean to the right is a positive
rotation of the rear frame about +x (the paper's φ). The head axis meets the floor the
trail ``c`` ahead of the front contact, at ``(w + c, 0, 0)``.

Wheels are knife edges: each collider is an ellipsoid ``(R, b, R)`` with a small half-width
``b``; its lowest point is the knife edge's contact at zero lean, and at lean φ it sits
``b² sin φ / R`` sideways (a tyre of crown radius ``b²/R``). No rider control; two motors
(steer torque, rear-wheel torque) are there for experiments, with ``ctrl = 0`` by default.
"""

from __future__ import annotations

import math

import numpy as np
from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.models.params import WheelParams
from wmr_mujoco.robots.whipple.params import DEFAULT_PARAMS, WhippleParams

#: Paper frame to MuJoCo world: rotation by π about x.
PAPER_TO_MJ = np.diag([1.0, -1.0, -1.0])
#: Torque range of the experiment motors, N·m.
MOTOR_LIMIT = 100.0
#: Speed of the ``rolling`` keyframe, m/s (inside the self-stable range).
KEY_SPEED = 5.0
FRAME_RGBA = (0.75, 0.2, 0.15, 1.0)
FORK_RGBA = (0.8, 0.8, 0.85, 1.0)
#: Half-width of the drawn wheels, m (the collider is the thin ellipsoid).
WHEEL_VISUAL_HALF_WIDTH = 0.012


def mj_tensor(tensor_paper: np.ndarray) -> np.ndarray:
    """``P I Pᵀ``: a paper-frame (z down) tensor in MuJoCo's z-up frame."""
    return PAPER_TO_MJ @ tensor_paper @ PAPER_TO_MJ.T


def full_inertia(tensor_mj: np.ndarray) -> tuple[float, ...]:
    """MuJoCo's ``fullinertia`` order ``(I_xx, I_yy, I_zz, I_xy, I_xz, I_yz)``."""
    t = tensor_mj
    return (t[0, 0], t[1, 1], t[2, 2], t[0, 1], t[0, 2], t[1, 2])


def mj_point(x: float, z: float) -> np.ndarray:
    """A point of the paper's symmetry plane ``(x, 0, z)`` in MuJoCo's frame."""
    return PAPER_TO_MJ @ np.array([x, 0.0, z])


def head_axis_down(p: WhippleParams) -> np.ndarray:
    """Unit vector along the head axis, pointing down, in MuJoCo's frame."""
    return np.array([math.sin(p.head_angle), 0.0, -math.cos(p.head_angle)])


def steer_pivot(p: WhippleParams) -> np.ndarray:
    """The point of the head axis nearest the front wheel centre (front frame origin)."""
    ground = np.array([p.wheelbase + p.trail, 0.0, 0.0])
    axis = head_axis_down(p)
    centre = np.array([p.wheelbase, 0.0, p.front_radius])
    return ground + np.dot(centre - ground, axis) * axis


def _add_wheel(parent: mjcf.Element, name: str, pos: np.ndarray, radius: float,
               mass: float, inertia: tuple[float, float], half_width: float) -> None:
    body = parent.add("body", name=name, pos=list(pos))
    body.add("joint", name=name, type="hinge", axis=(0, 1, 0))
    ixx, iyy = inertia
    body.add("inertial", pos=(0, 0, 0), mass=mass, diaginertia=(ixx, iyy, ixx))
    body.add("geom", name=f"{name}_collision", dclass="collision", type="ellipsoid",
             size=(radius, half_width, radius))
    body.add("geom", dclass="visual", type="cylinder", size=(radius, WHEEL_VISUAL_HALF_WIDTH),
             zaxis=(0, 1, 0), rgba=common.WHEEL_RGBA)
    for side in (-1.0, 1.0):
        body.add("geom", dclass="visual", type="box",
                 size=(0.08 * radius, 0.001, 0.45 * radius),
                 pos=(0.0, side * 0.013, 0.5 * radius), rgba=common.MARK_RGBA)


def _tube(body: mjcf.Element, a: np.ndarray, b: np.ndarray, rgba: tuple,
          radius: float = 0.015) -> None:
    body.add("geom", dclass="visual", type="capsule", fromto=[*a, *b], size=(radius,),
             rgba=rgba)


def _visual_wheel(radius: float) -> WheelParams:
    """The drawn wheel (the visual cylinder's width) for sizing its fork.

    Its mass is a placeholder: :func:`common.add_fork` uses only radius and width.
    """
    return WheelParams(radius=radius, width=2.0 * WHEEL_VISUAL_HALF_WIDTH, mass=1.0)


def build(params: WhippleParams = DEFAULT_PARAMS) -> mjcf.RootElement:
    """The benchmark bicycle on a free joint, rolling on point-contact (knife-edge) wheels.

    Contacts: ``solref = (contact_timeconst, contact_dampratio)``,
    ``solimp = (d, d, 0.001, 0.5, 2)`` with ``d = solimp_dmax``, elliptic cones with
    ``impratio``, condim 3 (no torsional or rolling friction, like a knife edge).
    """
    p = params
    s = p.sim
    root = common.new_root("whipple", s)
    root.option.integrator = s.integrator
    root.option.gravity = (0.0, 0.0, -p.gravity)  # the benchmark's g, z up
    if s.noslip_iterations:
        root.option.noslip_iterations = s.noslip_iterations
    root.size.nuser_actuator = 0
    collision = root.default.find("default", "collision")
    collision.geom.solref = (s.contact_timeconst, s.contact_dampratio)
    collision.geom.solimp = (s.solimp_dmax, s.solimp_dmax, 0.001, 0.5, 2.0)

    axle_r = mj_point(0.0, -p.rear_radius)
    rear = root.worldbody.add("body", name="rear_frame", pos=list(axle_r))
    rear.add("freejoint", name="rear_frame")
    com_b = mj_point(*p.rear_frame_com) - axle_r
    rear.add("inertial", pos=list(com_b), mass=p.rear_frame_mass,
             fullinertia=full_inertia(mj_tensor(p.tensor("rear_frame_inertia"))))
    site = rear.add("site", name="base", pos=(0, 0, 0))
    _add_wheel(rear, "rear_wheel", np.zeros(3), p.rear_radius, p.rear_mass,
               p.rear_inertia, s.wheel_half_width)

    pivot = steer_pivot(p)
    axis = head_axis_down(p)
    head_top = pivot - 0.25 * axis
    _tube(rear, np.zeros(3), head_top - axle_r, FRAME_RGBA)
    _tube(rear, np.zeros(3), com_b, FRAME_RGBA)
    # Stays either side of the rear wheel, from its axle to the frame's joints.
    common.add_fork(rear, _visual_wheel(p.rear_radius),
                    tops=((com_b[0], com_b[2]), ((head_top - axle_r)[0], (head_top - axle_r)[2])),
                    rgba=FRAME_RGBA)
    _tube(rear, com_b, head_top - axle_r, FRAME_RGBA)
    rear.add("geom", dclass="visual", type="sphere", size=(0.05,), pos=list(com_b),
             rgba=FRAME_RGBA)

    front = rear.add("body", name="front_frame", pos=list(pivot - axle_r))
    front.add("joint", name="steer", type="hinge", axis=list(axis))
    com_h = mj_point(*p.front_frame_com) - pivot
    front.add("inertial", pos=list(com_h), mass=p.front_frame_mass,
              fullinertia=full_inertia(mj_tensor(p.tensor("front_frame_inertia"))))
    centre_f = mj_point(p.wheelbase, -p.front_radius) - pivot
    _tube(front, -0.25 * axis, centre_f, FORK_RGBA, 0.012)
    # Fork blades either side of the front wheel, from its axle up to the steer axis.
    crown = -0.2 * axis
    common.add_fork(front, _visual_wheel(p.front_radius), tops=((crown[0], crown[2]),),
                    rgba=FORK_RGBA, centre=(centre_f[0], centre_f[2]))
    bar = -0.3 * axis
    _tube(front, bar + np.array([0, 0.25, 0]), bar - np.array([0, 0.25, 0]), FORK_RGBA,
          0.012)
    _add_wheel(front, "front_wheel", centre_f, p.front_radius, p.front_mass,
               p.front_inertia, s.wheel_half_width)

    root.actuator.add("motor", name="steer_torque", joint="steer",
                      ctrlrange=(-MOTOR_LIMIT, MOTOR_LIMIT))
    root.actuator.add("motor", name="rear_torque", joint="rear_wheel",
                      ctrlrange=(-MOTOR_LIMIT, MOTOR_LIMIT))
    root.sensor.add("jointpos", name="steer_angle", joint="steer")
    root.sensor.add("jointvel", name="rear_wheel_rate", joint="rear_wheel")
    common.add_frame_sensors(root, site)

    qpos, qvel = rolling_state(p, KEY_SPEED)
    root.keyframe.add("key", name="upright", qpos=rolling_state(p, 0.0)[0],
                      qvel=np.zeros(len(qvel)))
    root.keyframe.add("key", name="rolling", qpos=qpos, qvel=qvel)
    return root


def rolling_state(p: WhippleParams, speed: float) -> tuple[np.ndarray, np.ndarray]:
    """``qpos, qvel`` of upright straight rolling at ``speed`` (touching, no penetration).

    ``qpos = (x, y, z, quat, θ_R, δ, θ_F)``, ``qvel = (v_world, ω_body, θ̇_R, δ̇, θ̇_F)``
    with wheel rates ``v / r`` (rolling without slip).
    """
    qpos = np.array([0.0, 0.0, p.rear_radius, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    qvel = np.array([speed, 0.0, 0.0, 0.0, 0.0, 0.0, speed / p.rear_radius, 0.0,
                     speed / p.front_radius])
    return qpos, qvel
