"""The ``"mujoco"`` backend: the robot in contact physics, stepped one control period at a time.

A step writes the actuator controls once and advances ``n = T / Δt`` timesteps in one
``mj_step(model, data, n)`` call (the controls are held over the period, a zero-order hold
like the validation runner's), then checks the run's health and reads the state.

``mj_step`` leaves the derived quantities (frames, body velocities, contacts, sensors) at
the start of its last timestep. So a period runs as ``mj_step2`` (finishing the timestep
that the previous period's ``mj_step1`` began), ``mj_step(n − 1)``, then ``mj_step1``: the
same ``n`` timesteps, bit for bit (the controls enter in ``mj_step2``), with everything the
readout needs computed for the final ``qpos, qvel`` at no extra cost. (MuJoCo's RK4
integrator cannot be split: such a model steps ``n`` whole timesteps and brings frames and
body velocities up to date with ``mj_kinematics``, ``mj_comPos``, ``mj_comVel``; its
contacts are then one timestep old.)
"""

from __future__ import annotations

from collections import deque

import mujoco
import numpy as np

from wmr_mujoco.loop.readout import Reader, place
from wmr_mujoco.loop.robot import HISTORY_LIMIT, Robot, substeps
from wmr_mujoco.loop.state import CommandSpace, RobotState
from wmr_mujoco.models.actuation import ActuationMode, set_actuation_mode
from wmr_mujoco.sim.stepping import check_healthy
from wmr_mujoco.validation.command import Controller
from wmr_mujoco.validation.spec import RobotSpec


class MujocoRobot(Robot):
    """A robot in MuJoCo (see :func:`wmr_mujoco.drive.make`).

    Args:
        spec: the robot's registry entry (with a command map).
        model: its compiled scene (modified: actuation mode).
        mode: ``"command"``, ``"wheels"`` or ``"torque"``.
        control_period: s, a multiple of the model's timestep.
        command_space: the commands of ``mode``.
        controller: natural command -> controls (mode ``"command"``; None: the command
            is the controls).
        actuation: the actuation mode to switch the model to (None: leave as is).
    """

    backend = "mujoco"

    def __init__(self, spec: RobotSpec, model: mujoco.MjModel, mode: str,
                 control_period: float, command_space: CommandSpace,
                 controller: Controller | None, actuation: ActuationMode | None) -> None:
        self.nstep = substeps(control_period, model.opt.timestep)
        super().__init__(spec, mode, control_period, command_space)
        if actuation is not None:
            set_actuation_mode(model, actuation)
        self.model = model
        self.data = mujoco.MjData(model)
        self.reader = Reader(model, self.data, spec.command)
        #: MuJoCo's warning counters and the controls (live views of ``data``'s arrays).
        self._warnings = self.data.warning.number
        self._ctrl = self.data.ctrl
        self._heading = 0.0
        self._controller = controller
        self._wheel_qpos = np.array([model.jnt_qposadr[model.joint(w).id]
                                     for w in self.wheel_names], dtype=int)
        self._t0 = 0.0
        self._split = model.opt.integrator != mujoco.mjtIntegrator.mjINT_RK4
        #: Generalised positions after every period since the reset, for :meth:`film`.
        self.qpos_history: deque[np.ndarray] = deque(maxlen=HISTORY_LIMIT)

    def _reset(self, pose: np.ndarray, seed: int | None) -> RobotState:
        """Place at ``pose``, settle on the floor at rest, zero the velocities.

        Like the validation runner: the controls are 0 (wheel-rate servos hold the wheels,
        steering targets stay at 0) for the command map's ``settle`` seconds. A command
        map with a keyframe and no settling (the Whipple bicycle, which cannot stand
        still) starts from the keyframe's state, velocities included, turned to ``pose``.
        """
        model, data, cmap = self.model, self.data, self.spec.command
        if cmap.keyframe is not None:
            mujoco.mj_resetDataKeyframe(model, data, model.keyframe(cmap.keyframe).id)
        else:
            mujoco.mj_resetData(model, data)
        if seed is not None:
            rng = np.random.default_rng(seed)
            data.qpos[self._wheel_qpos] = rng.uniform(0.0, 2 * np.pi, len(self._wheel_qpos))
        place(model, data, pose)
        data.ctrl[:] = 0.0
        nsettle = round(cmap.settle / model.opt.timestep)
        if nsettle:
            mujoco.mj_step(model, data, nsettle)
            check_healthy(model, data)
            data.qvel[:] = 0.0
            mujoco.mj_forward(model, data)
        self._t0 = data.time
        self.qpos_history.clear()
        self._heading = float(pose[2])
        return self._read(0.0)

    def _advance(self, command: np.ndarray) -> RobotState:
        """Controls held for ``nstep`` timesteps, then the health check and the readout."""
        model, data = self.model, self.data
        if self._controller is None:
            self._ctrl[:] = command
        else:
            self._controller(data, command, self.control_period, self._ctrl)
        if self._split:
            mujoco.mj_step2(model, data)
            if self.nstep > 1:
                mujoco.mj_step(model, data, self.nstep - 1)
            mujoco.mj_step1(model, data)
            if any(self._warnings.tolist()):
                self.reader.check()
        else:
            mujoco.mj_step(model, data, self.nstep)
            if any(self._warnings.tolist()):
                self.reader.check()
            mujoco.mj_kinematics(model, data)
            mujoco.mj_comPos(model, data)
            mujoco.mj_comVel(model, data)
        return self._read(data.time - self._t0)

    def _read(self, time: float) -> RobotState:
        """The state in ``data`` at ``time`` (its ``qpos`` recorded for :meth:`film`)."""
        state, qpos, self._heading = self.reader.take(time, self._heading)
        self.qpos_history.append(qpos)
        return state
