"""The ``"dynamic"`` backend: the robot's Lagrange model under wheel torques.

The model is the robot's dynamic validation adapter (``RobotSpec.adapters[DYNAMIC]``,
the one its torque scenarios judge the physics against): state ``x`` starting with the
pose ``(x, y, ψ)``, input the wheel torques ``τ`` in the adapter's wheel order. Over one
period ``T`` the torques are held and ``x`` advances by ``n = T/Δt`` classical RK4 steps
on the model's timestep (global error O(Δt⁴), :mod:`wmr_mujoco.analytic.integrate`), or
the adapter's ``exact_step`` where it has one.

The state reported: pose ``x[:3]``; twist ``(u, v, r)`` from the state where it holds
``("u", "v", "r")`` (the reduced Lagrange models of the omni-wheeled robots), else from
``rhs(x, τ)`` rotated into the body; wheel rates from rolling without slip
(:class:`~wmr_mujoco.loop.kinematic.WheelGeometry`, the model's own assumption); every
wheel in contact.

Only a robot whose dynamic model's state starts with a planar pose has this backend
(the disc's single-wheel model, ``(distance, speed)`` along a fixed heading, does not):
:func:`dynamic_adapter` says why not otherwise.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from wmr_mujoco.loop.kinematic import WheelGeometry, hold
from wmr_mujoco.loop.readout import place
from wmr_mujoco.loop.robot import Robot, substeps
from wmr_mujoco.loop.state import CommandSpace, RobotState
from wmr_mujoco.models.actuation import set_actuation_mode
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.validation.adapters import Adapter
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.spec import RobotSpec

#: The first state components of a model this backend can drive.
POSE = ("x", "y", "heading")
#: The state components that are the body twist, where a model has them.
TWIST = ("u", "v", "r")


def dynamic_adapter(spec: RobotSpec, model: mujoco.MjModel,
                    params: RobotParams | None) -> Adapter:
    """The robot's dynamic adapter for ``model`` (module docstring).

    Raises:
        ValueError: the robot has no dynamic model, or one whose state is not a pose
            (the message says which).
    """
    factory = spec.adapters.get(ScenarioKind.DYNAMIC)
    if factory is None:
        raise ValueError(f"robot {spec.name!r} has no Lagrange model in its registry entry")
    adapter = factory(Scenario(spec.name, "dynamic backend", kind=ScenarioKind.DYNAMIC),
                      model, params)
    if tuple(adapter.state_names[:3]) != POSE:
        raise ValueError(f"robot {spec.name!r}: its dynamic model's state "
                         f"{tuple(adapter.state_names)} does not start with a planar pose")
    return adapter


class DynamicRobot(Robot):
    """The Lagrange model driven by wheel torques (module docstring).

    Args:
        spec: the robot's registry entry.
        model: its compiled scene, read for timestep, torque limits and geometry.
        adapter: the dynamic model (state starting with the pose, wheel torques in).
        control_period: s, a multiple of the model's timestep.
    """

    backend = "dynamic"

    def __init__(self, spec: RobotSpec, model: mujoco.MjModel, adapter: Adapter,
                 control_period: float) -> None:
        self.nstep = substeps(control_period, model.opt.timestep)
        if adapter.mode is not None:
            set_actuation_mode(model, adapter.mode)
        acts = []
        for w in adapter.wheel_joints:
            j = model.joint(w).id
            ids = [i for i in range(model.nu) if int(model.actuator_trnid[i, 0]) == j]
            if not ids:
                raise ValueError(f"{spec.name}: wheel {w!r} of the dynamic model has no "
                                 "actuator")
            acts.append(ids[0])
        ranges = model.actuator_forcerange[acts]
        space = CommandSpace(tuple(f"{w}_torque" for w in adapter.wheel_joints),
                             ("N·m",) * len(acts), ranges[:, 0].copy(), ranges[:, 1].copy())
        super().__init__(spec, "torque", control_period, space)
        self.adapter = adapter
        self._model = model
        self.dt = control_period / self.nstep
        self._exact = getattr(adapter, "exact_step", None)
        names = tuple(adapter.state_names)
        self._twist_at = [names.index(n) for n in TWIST] if set(TWIST) <= set(names) else None
        self.geometry = WheelGeometry(model, spec.command)
        self._x = np.zeros(len(names))
        self._periods = 0

    @property
    def analytic_state(self) -> np.ndarray:
        """The model's state ``x`` (a copy; names: ``adapter.state_names``)."""
        return self._x.copy()

    def _reset(self, pose: np.ndarray, seed: int | None) -> RobotState:
        """At rest at ``pose`` (the model's state read from the placed MuJoCo model)."""
        data = mujoco.MjData(self._model)
        cmap = self.spec.command
        if cmap.keyframe is not None:
            mujoco.mj_resetDataKeyframe(self._model, data,
                                        self._model.keyframe(cmap.keyframe).id)
        data.qvel[:] = 0.0
        place(self._model, data, pose)
        x = np.array(self.adapter.sim_state(self._model, data), float)
        x[:3] = pose
        if self._twist_at is not None:
            x[self._twist_at] = 0.0
        self._x = x
        self._periods = 0
        return self._read(0.0, np.zeros(self.command_space.shape))

    def _advance(self, command: np.ndarray) -> RobotState:
        """Hold the torques for one period: exact step, or RK4 on the timestep."""
        self._x = hold(self, self._x, command, "dynamic")
        self._periods += 1
        return self._read(self._periods * self.control_period, command)

    def _read(self, time: float, torques: np.ndarray) -> RobotState:
        x = self._x
        if self._twist_at is not None:
            twist = x[self._twist_at].copy()
        else:
            dx = self.adapter.rhs(x, torques)
            c, s = math.cos(x[2]), math.sin(x[2])
            twist = np.array((c * dx[0] + s * dx[1], -s * dx[0] + c * dx[1], dx[2]))
        steer = np.zeros(len(self.steer_names))
        n = len(self.wheel_names)
        return RobotState(time=np.array(time), pose=np.array(x[:3]), twist=twist,
                          wheel_rates=self.geometry.rates(twist, steer),
                          wheel_contacts=np.ones(n, dtype=bool), steer_angles=steer)
