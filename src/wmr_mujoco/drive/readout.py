"""Reading a :class:`~wmr_mujoco.drive.state.RobotState` from MuJoCo, and placing a robot.

Everything is looked up once per compiled model (:class:`Reader`, :func:`place`), so that a
control step reads its state with a few array reads and one ``mj_objectVelocity``.
"""

from __future__ import annotations

import math
from types import MappingProxyType

import mujoco
import numpy as np

from wmr_mujoco.drive.state import RobotState
from wmr_mujoco.robots.command import CommandMap

#: Free-joint type, and the axes of the planar pose joints (slides x, y; hinge z).
_FREE = int(mujoco.mjtJoint.mjJNT_FREE)
_SLIDE = int(mujoco.mjtJoint.mjJNT_SLIDE)
_HINGE = int(mujoco.mjtJoint.mjJNT_HINGE)


def wheel_of_body(model: mujoco.MjModel, wheels: tuple[str, ...]) -> np.ndarray:
    """For every body, the index of its wheel, or -1.

    A body belongs to the wheel whose hinge is on it or on an ancestor (rollers belong to
    their wheel).
    """
    owner = {int(model.jnt_bodyid[model.joint(w).id]): k for k, w in enumerate(wheels)}
    table = np.full(model.nbody, -1, dtype=int)
    for b in range(model.nbody):
        a = b
        while a > 0 and a not in owner:
            a = int(model.body_parentid[a])
        table[b] = owner.get(a, -1)
    return table


class Reader:
    """Reads the robot's state from ``data`` (pose, twist, wheels, steering, contacts).

    Args:
        model: the compiled scene.
        command: the robot's command map (its wheels, steering joints and extras).
    """

    def __init__(self, model: mujoco.MjModel, command: CommandMap) -> None:
        self.model = model
        self.site = model.site("base").id
        self.wheel_dofs = np.array([model.jnt_dofadr[model.joint(w).id]
                                    for w in command.wheels], dtype=int)
        self.steer_qpos = np.array([model.jnt_qposadr[model.joint(s).id]
                                    for s in command.steers], dtype=int)
        self.wheel_table = wheel_of_body(model, command.wheels)
        self.extras = command.extras
        self._vel = np.zeros(6)

    def heading(self, data: mujoco.MjData) -> float:
        """Heading of the ``base`` site in (−π, π]: ``atan2(R₁₀, R₀₀)``."""
        m = data.site_xmat[self.site]
        return math.atan2(m[3], m[0])

    def contacts(self, data: mujoco.MjData) -> np.ndarray:
        """Whether each wheel (or one of its rollers) has a contact."""
        out = np.zeros(len(self.wheel_dofs), dtype=bool)
        if data.ncon:
            owners = self.wheel_table[self.model.geom_bodyid[data.contact.geom]]
            out[owners[owners >= 0]] = True
        return out

    def read(self, data: mujoco.MjData, time: float, last_heading: float) -> RobotState:
        """The state in ``data``; the heading unwrapped next to ``last_heading``."""
        pos = data.site_xpos[self.site]
        h = self.heading(data)
        h = last_heading + math.remainder(h - last_heading, math.tau)
        vel = self._vel
        mujoco.mj_objectVelocity(self.model, data, mujoco.mjtObj.mjOBJ_SITE, self.site,
                                 vel, 1)
        extra = (MappingProxyType(dict(self.extras(self.model, data)))
                 if self.extras is not None else MappingProxyType({}))
        return RobotState(
            time=np.array(time), pose=np.array((pos[0], pos[1], h)),
            twist=np.array((vel[3], vel[4], vel[2])),
            wheel_rates=data.qvel[self.wheel_dofs],
            steer_angles=data.qpos[self.steer_qpos],
            wheel_contacts=self.contacts(data), extra=extra)


def _planar_joints(model: mujoco.MjModel) -> tuple[int, int, int]:
    """The ``(slide x, slide y, hinge z)`` joints above the ``base`` site's body.

    Raises:
        ValueError: the robot has neither a free joint nor these three joints.
    """
    found: dict[str, int] = {}
    b = int(model.site_bodyid[model.site("base").id])
    while b > 0:
        for j in range(model.body_jntadr[b], model.body_jntadr[b] + model.body_jntnum[b]):
            axis = tuple(np.round(model.jnt_axis[j], 12))
            kind = {(_SLIDE, (1.0, 0.0, 0.0)): "x", (_SLIDE, (0.0, 1.0, 0.0)): "y",
                    (_HINGE, (0.0, 0.0, 1.0)): "yaw"}.get((int(model.jnt_type[j]), axis))
            if kind is not None and kind not in found:
                found[kind] = j
        b = int(model.body_parentid[b])
    if len(found) != 3:
        raise ValueError("cannot place the robot: it has no free joint and no slide-x, "
                         f"slide-y and yaw-hinge joints (found {sorted(found)})")
    return found["x"], found["y"], found["yaw"]


def place(model: mujoco.MjModel, data: mujoco.MjData, pose: np.ndarray) -> None:
    """Move the robot, as it stands in ``data``, so that ``base`` is at ``pose``.

    A free root joint is turned about the vertical through ``base`` and shifted; a planar
    robot (slides along x and y and a yaw hinge above ``base``) gets the yaw hinge turned
    and the slides shifted. Heights and tilts are kept.
    """
    mujoco.mj_kinematics(model, data)
    site = model.site("base").id
    x0, y0 = data.site_xpos[site][:2]
    m = data.site_xmat[site]
    turn = float(pose[2]) - math.atan2(m[3], m[0])
    if model.jnt_type[0] == _FREE:
        adr = model.jnt_qposadr[0]
        c, s = math.cos(turn), math.sin(turn)
        dx, dy = data.qpos[adr] - x0, data.qpos[adr + 1] - y0
        data.qpos[adr] = pose[0] + c * dx - s * dy
        data.qpos[adr + 1] = pose[1] + s * dx + c * dy
        quat = np.zeros(4)
        mujoco.mju_mulQuat(quat, np.array([math.cos(turn / 2), 0.0, 0.0, math.sin(turn / 2)]),
                           data.qpos[adr + 3:adr + 7].copy())
        data.qpos[adr + 3:adr + 7] = quat
    else:
        jx, jy, jyaw = _planar_joints(model)
        data.qpos[model.jnt_qposadr[jyaw]] += turn
        mujoco.mj_kinematics(model, data)
        x1, y1 = data.site_xpos[site][:2]
        data.qpos[model.jnt_qposadr[jx]] += pose[0] - x1
        data.qpos[model.jnt_qposadr[jy]] += pose[1] - y1
    mujoco.mj_forward(model, data)
