"""Reading a :class:`~wmr_mujoco.loop.state.RobotState` from MuJoCo, and placing a robot.

Everything is looked up once per compiled model (:class:`Reader`, :func:`place`), so that a
control step reads its state with a few array reads and one ``mj_objectVelocity``; the
state's arrays are made from these raw readings when first read (:class:`MujocoState`), so
that a step whose state is not looked at pays for none of them.
"""

from __future__ import annotations

import math
from types import MappingProxyType

import mujoco
import numpy as np

from wmr_mujoco.loop.state import RobotState
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy
from wmr_mujoco.validation.command import CommandMap

_SITE = mujoco.mjtObj.mjOBJ_SITE
#: The ``steer_angles`` of a robot without steering joints (read-only).
_EMPTY = np.zeros(0)
_EMPTY.flags.writeable = False
#: The ``extra`` of a robot without extras.
NO_EXTRAS: MappingProxyType[str, float] = MappingProxyType({})

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
    """Reads the robot's state from its ``data`` (pose, twist, wheels, steering, contacts).

    The rows of ``data`` it reads are numpy views taken once (they stay valid while
    ``data`` lives), so that a control step reads them without attribute look-ups.

    Args:
        model: the compiled scene.
        data: the robot's data.
        command: the robot's command map (its wheels, steering joints and extras).
    """

    def __init__(self, model: mujoco.MjModel, data: mujoco.MjData,
                 command: CommandMap) -> None:
        self.model = model
        self.data = data
        self.site = model.site("base").id
        self.wheel_dofs = np.array([model.jnt_dofadr[model.joint(w).id]
                                    for w in command.wheels], dtype=int)
        dofs = self.wheel_dofs.tolist()
        #: The wheel rates' rows of ``qvel``: a slice where they are consecutive (a copy
        #: of a slice costs a third of fancy indexing), else the index array.
        self.wheel_rows: slice | np.ndarray = (
            slice(dofs[0], dofs[-1] + 1) if dofs and dofs == list(range(dofs[0], dofs[-1] + 1))
            else self.wheel_dofs)
        self.nsteer = len(command.steers)
        self.steer_qpos = np.array([model.jnt_qposadr[model.joint(s).id]
                                    for s in command.steers], dtype=int)
        nwheel = len(command.wheels)
        table = wheel_of_body(model, command.wheels)[model.geom_bodyid]
        #: Per geom, its wheel's index, or ``nwheel`` (a spare slot) for other geoms.
        self.geom_wheel = np.where(table >= 0, table, nwheel)
        #: ``geom_wheel`` as a list (a Python loop over a few contacts beats numpy).
        self.geom_wheel_list: list[int] = self.geom_wheel.tolist()
        self.nwheel = nwheel
        self.extras = command.extras
        self._vel = np.zeros(6)
        self._xpos = data.site_xpos[self.site]
        self._xmat = data.site_xmat[self.site]
        self._qpos = data.qpos
        self._qvel = data.qvel
        self._warnings = data.warning.number

    def heading(self) -> float:
        """Heading of the ``base`` site in (−π, π]: ``atan2(R₁₀, R₀₀)``."""
        m = self._xmat
        return math.atan2(m[3], m[0])

    def contacts(self) -> np.ndarray:
        """Whether each wheel (or one of its rollers) has a contact."""
        out = [False] * (self.nwheel + 1)
        owner = self.geom_wheel_list
        for g1, g2 in self.data.contact.geom.tolist():
            out[owner[g1]] = out[owner[g2]] = True
        return np.array(out[:self.nwheel])

    def check(self) -> None:
        """Raise :class:`SimulationDivergedError` on any MuJoCo warning.

        MuJoCo checks ``qpos``, ``qvel`` and ``qacc`` for NaN and huge values in every
        step and raises a warning (and resets the state) when one is bad, so the warning
        counters alone show a divergence; :func:`check_healthy` then names it.
        """
        if any(self._warnings.tolist()):
            check_healthy(self.model, self.data)
            raise SimulationDivergedError(f"MuJoCo warnings at t={self.data.time:.4f} s")

    def read(self, data: mujoco.MjData, time: float, last_heading: float) -> RobotState:
        """The state in ``data`` (the reader's own), heading unwrapped next to ``last_heading``.

        Raises:
            ValueError: ``data`` is not the data this reader was made with.
        """
        if data is not self.data:
            raise ValueError("this Reader reads only the MjData it was made with "
                             "(Reader(model, data, command))")
        return self.take(time, last_heading)[0]

    def take(self, time: float, last_heading: float) -> tuple[RobotState, np.ndarray, float]:
        """The state in ``data``, a copy of its ``qpos``, and the state's heading.

        The heading is unwrapped next to ``last_heading``. Only the raw readings are taken
        now (:class:`MujocoState`): the pose, the ``base`` site's velocity
        (``mj_objectVelocity``), a copy of ``qpos``, the wheel rates, the contacts' geom
        pairs and the extras; the other arrays are made from them when first read.
        """
        data = self.data
        x, y, _ = self._xpos.tolist()
        m = self._xmat.tolist()
        h = last_heading + math.remainder(math.atan2(m[3], m[0]) - last_heading, math.tau)
        vel = self._vel
        mujoco.mj_objectVelocity(self.model, data, _SITE, self.site, vel, 1)
        _, _, r, u, v, _ = vel.tolist()
        extra = (MappingProxyType(dict(self.extras(self.model, data)))
                 if self.extras is not None else NO_EXTRAS)
        qpos = self._qpos.copy()
        state = MujocoState(self, time, (x, y, h, u, v, r), qpos,
                            self._qvel[self.wheel_rows].copy(), data.contact.geom.copy(),
                            extra)
        return state, qpos, h


class MujocoState(RobotState):
    """A :class:`RobotState` read from MuJoCo, its arrays made when first read.

    A control step keeps raw readings (:meth:`Reader.read`); each field is computed from
    them on its first access and then kept (a frozen state: the same array every time).
    """

    def __init__(self, reader: Reader, time: float, pose_twist: tuple[float, ...],
                 qpos: np.ndarray, wheel_rates: np.ndarray, pairs: np.ndarray,
                 extra: MappingProxyType[str, float]) -> None:
        # Written into __dict__ as the frozen dataclass's own __init__ does; few Python
        # containers per state (the garbage collector tracks each one in the history),
        # and three keys: a small dict is never resized while the state is recorded.
        fields = self.__dict__
        fields["_raw"] = (reader, time, pose_twist, qpos, pairs)
        fields["wheel_rates"] = wheel_rates
        fields["extra"] = extra

    def __reduce__(self) -> tuple[type[RobotState], tuple[object, ...]]:
        """Copied as a plain :class:`RobotState` of the same arrays (all computed)."""
        return RobotState, (self.time, self.pose, self.twist, self.wheel_rates,
                            self.steer_angles, self.wheel_contacts, self.extra)

    def __getattr__(self, name: str) -> np.ndarray:
        """Compute a field on its first access (later ones find it in ``__dict__``)."""
        fields = self.__dict__
        raw = fields.get("_raw")
        if raw is None or name not in _LAZY:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        reader, time, pose_twist, qpos, pairs = raw
        if name in ("time", "pose", "twist"):  # read together (an environment's step does)
            both = np.array(pose_twist)  # one array, two views
            fields["pose"], fields["twist"] = both[:3], both[3:]
            fields["time"] = np.array(time)
        elif name == "steer_angles":
            fields[name] = qpos[reader.steer_qpos] if reader.nsteer else _EMPTY
        else:
            out = [False] * (reader.nwheel + 1)
            owner = reader.geom_wheel_list
            for g1, g2 in pairs.tolist():
                out[owner[g1]] = out[owner[g2]] = True
            fields[name] = np.array(out[:reader.nwheel])
        return fields[name]


#: The fields :class:`MujocoState` computes on first access.
_LAZY = frozenset(("time", "pose", "twist", "steer_angles", "wheel_contacts"))


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

    A free root joint is turned about the vertical through ``base`` and shifted (its
    world-frame linear velocity turned with it); a planar robot (slides along x and y and a
    yaw hinge above ``base``) gets the yaw hinge turned and the slides shifted. Heights and
    tilts are kept. Every integrator actuator on a joint (a steering servo, whose ``act``
    is its target angle) then targets the joint's angle, so that nothing moves by itself.
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
        vadr = model.jnt_dofadr[0]
        vx, vy = data.qvel[vadr], data.qvel[vadr + 1]
        data.qvel[vadr], data.qvel[vadr + 1] = c * vx - s * vy, s * vx + c * vy
    else:
        jx, jy, jyaw = _planar_joints(model)
        data.qpos[model.jnt_qposadr[jyaw]] += turn
        mujoco.mj_kinematics(model, data)
        x1, y1 = data.site_xpos[site][:2]
        data.qpos[model.jnt_qposadr[jx]] += pose[0] - x1
        data.qpos[model.jnt_qposadr[jy]] += pose[1] - y1
    joint = int(mujoco.mjtTrn.mjTRN_JOINT)
    for i in range(model.nu):
        if model.actuator_actadr[i] >= 0 and model.actuator_trntype[i] == joint:
            data.act[model.actuator_actadr[i]] = data.qpos[
                model.jnt_qposadr[model.actuator_trnid[i, 0]]]
    mujoco.mj_forward(model, data)
