"""The ``"kinematic"`` backend: the robot's analytic kinematic model under the same commands.

The model is the robot's kinematic validation adapter (``RateCommand.kinematics``): state
``x`` starting with the pose ``(x, y, ψ)``, inputs ``u`` from the natural command
(steering angles servoed into rates exactly as on the MuJoCo backend, from the analytic
steering angle). Over one period ``T`` the input is held and ``x`` advances by the
adapter's ``exact_step`` where it has one, else by ``n = T/Δt`` classical RK4 steps on the
model's timestep (global error O(Δt⁴), :mod:`wmr_mujoco.analytic.integrate`).

The state reported: pose ``x[:3]``; twist ``(u, v, r) = (Rot(−ψ)(ẋ, ẏ), ψ̇)`` from
``rhs(x, u)``; steering angles from ``x``; wheel rates of driven wheels from the adapter's
controls (its inverse kinematics), of passive wheels from rolling without slip,

    θ̇ = v_c · (a × e_z) / R,    v_c = (u − r c_y, v + r c_x),

with ``c`` the wheel centre and ``a`` its axle in the ``base`` frame (read from the
compiled model at rest; a steered wheel's axle turned by its steering angle about the
vertical), ``R`` the centre's height at rest; every wheel is in contact.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from wmr_mujoco.analytic.integrate import rk4_step
from wmr_mujoco.loop.readout import place
from wmr_mujoco.loop.robot import Robot, substeps
from wmr_mujoco.loop.state import CommandSpace, RobotState
from wmr_mujoco.sim.stepping import SimulationDivergedError
from wmr_mujoco.validation.adapters import Adapter
from wmr_mujoco.validation.command import RateCommand
from wmr_mujoco.validation.spec import RobotSpec


def hold(robot: Robot, x: np.ndarray, u: np.ndarray, what: str) -> np.ndarray:
    """``x`` after one control period with ``u`` held: the model's exact step, else RK4.

    ``robot`` gives the adapter's ``rhs``, its exact step (None: none), the substeps
    ``nstep`` of ``dt`` and its name; ``what`` names the model in the error.

    Raises:
        SimulationDivergedError: the state became non-finite.
    """
    if robot._exact is not None:
        x = robot._exact(x, u, robot.control_period)
    elif (trajectory := getattr(robot.adapter, "trajectory", None)) is not None:
        # the adapter's RK4 over every substep at once: the floats of step after step
        held = np.broadcast_to(np.asarray(u, float), (robot.nstep, len(u)))
        x = trajectory(np.asarray(x, float), held, robot.dt)[-1]
    else:
        rhs = robot.adapter.rhs
        for _ in range(robot.nstep):
            x = rk4_step(rhs, x, u, robot.dt)
    x = np.asarray(x, float)
    if not all(map(math.isfinite, x.tolist())):
        raise SimulationDivergedError(f"{robot.spec.name}: the {what} model's state "
                                      f"became non-finite at t={robot.time:.4f} s: {x}")
    return x


class WheelGeometry:
    """Rolling rates of the wheels under a body twist (module docstring).

    Args:
        model: the compiled scene (read at its rest pose ``qpos0``).
        command: the wheels and steering joints.

    Attributes:
        centres: wheel centres in the ``base`` frame, ``(x, y)`` per wheel, m.
        axles: wheel axles in the ``base`` frame at zero steering, ``(x, y)`` per wheel.
        radii: wheel radii (centre heights at rest), m.
        steer_of_wheel: per wheel, the index of the steering joint that turns it, or -1.
    """

    def __init__(self, model: mujoco.MjModel, command: RateCommand) -> None:
        data = mujoco.MjData(model)
        mujoco.mj_kinematics(model, data)
        site = model.site("base").id
        rot = data.site_xmat[site].reshape(3, 3)
        origin = data.site_xpos[site]
        steer_bodies = {int(model.jnt_bodyid[model.joint(s).id]): k
                        for k, s in enumerate(command.steers)}
        centres, axles, radii, steer = [], [], [], []
        for w in command.wheels:
            j = model.joint(w).id
            b = int(model.jnt_bodyid[j])
            centres.append((rot.T @ (data.xpos[b] - origin))[:2])
            axle = rot.T @ data.xmat[b].reshape(3, 3) @ model.jnt_axis[j]
            axles.append(axle[:2])
            radii.append(data.xpos[b][2])
            a, k = b, -1
            while a > 0 and k < 0:
                k = steer_bodies.get(a, -1)
                a = int(model.body_parentid[a])
            steer.append(k)
        self.centres = np.array(centres)
        self.axles = np.array(axles)
        self.radii = np.array(radii)
        self.steer_of_wheel = np.array(steer, dtype=int)
        self._wheels = list(zip(self.centres.tolist(), self.axles.tolist(), steer,
                                self.radii.tolist(), strict=True))

    def rates(self, twist: np.ndarray, steer_angles: np.ndarray) -> np.ndarray:
        """``θ̇ = v_c · (a × e_z) / R`` of every wheel (on floats, in numpy's order)."""
        u, v, r = twist.tolist() if type(twist) is np.ndarray else twist
        out = []
        for (cx, cy), (ax, ay), k, radius in self._wheels:
            if k >= 0:
                c, s = math.cos(steer_angles[k]), math.sin(steer_angles[k])
                ax, ay = c * ax - s * ay, s * ax + c * ay
            # a × e_z = (a_y, −a_x) in the plane.
            out.append(((u - r * cy) * ay - (v + r * cx) * ax) / radius)
        return np.array(out, dtype=float)


class KinematicRobot(Robot):
    """The analytic kinematic model driven like the robot (see :func:`~wmr_mujoco.drive.make`).

    Args:
        spec: the robot's registry entry (a :class:`~wmr_mujoco.validation.command.RateCommand`).
        model: its compiled scene, read for timestep, limits and geometry (not stepped).
        adapter: the kinematic model.
        control_period: s, a multiple of the model's timestep.
        command_space: the natural command space.
    """

    backend = "kinematic"

    def __init__(self, spec: RobotSpec, model: mujoco.MjModel, adapter: Adapter,
                 control_period: float, command_space: CommandSpace) -> None:
        self.nstep = substeps(control_period, model.opt.timestep)
        super().__init__(spec, "command", control_period, command_space)
        cmap = spec.command
        assert isinstance(cmap, RateCommand)
        self.cmap = cmap
        self.adapter = adapter
        self._model = model
        self.dt = control_period / self.nstep
        self._exact = getattr(adapter, "exact_step", None)
        self._rate_limits = cmap.rate_limits(model)
        servo_of_joint = {int(model.actuator_trnid[model.actuator(s.actuator).id, 0]): s.state
                          for s in cmap.servo}
        self._steer_states = []
        for name in cmap.steers:
            j = model.joint(name).id
            if j not in servo_of_joint:
                raise ValueError(f"{spec.name}: steering joint {name!r} has no servo "
                                 "channel in the command map; the kinematic backend "
                                 "cannot report its angle")
            self._steer_states.append(servo_of_joint[j])
        self._servo_states = [s.state for s in cmap.servo]
        # Driven wheels: their actuator's control is their rate; the others roll.
        wheel_joint = {model.joint(w).id: k for k, w in enumerate(cmap.wheels)}
        self._driven = [(i, wheel_joint[int(model.actuator_trnid[i, 0])])
                        for i in range(model.nu)
                        if int(model.actuator_trnid[i, 0]) in wheel_joint]
        self.geometry = WheelGeometry(model, cmap)
        self._x = np.zeros(len(adapter.state_names))
        self._periods = 0

    @property
    def analytic_state(self) -> np.ndarray:
        """The analytic model's state ``x`` (a copy; names: ``adapter.state_names``)."""
        return self._x.copy()

    def _reset(self, pose: np.ndarray, seed: int | None) -> RobotState:
        """The model's state at rest at ``pose`` (read as ``sim_state`` of the placed model)."""
        data = mujoco.MjData(self._model)
        if self.cmap.keyframe is not None:
            mujoco.mj_resetDataKeyframe(self._model, data,
                                        self._model.keyframe(self.cmap.keyframe).id)
        place(self._model, data, pose)
        x = np.array(self.adapter.sim_state(self._model, data), float)
        x[:3] = pose
        self._x = x
        self._periods = 0
        return self._read(0.0, np.zeros(len(self.cmap.names)))

    def _advance(self, command: np.ndarray) -> RobotState:
        """Hold the inputs for one period: exact step, or RK4 on the timestep."""
        x = self._x
        u = self.cmap.inputs(self.adapter, command, x[self._servo_states],
                             self.control_period, self._rate_limits)
        self._x = hold(self, x, u, "kinematic")
        self._periods += 1
        return self._read(self._periods * self.control_period, u)

    def _read(self, time: float, u: np.ndarray) -> RobotState:
        """The state of ``x`` with input ``u`` held."""
        x = self._x
        dx = self.adapter.rhs(x, u)
        c, s = math.cos(x[2]), math.sin(x[2])
        twist = np.array((c * dx[0] + s * dx[1], -s * dx[0] + c * dx[1], dx[2]))
        steer = x[self._steer_states]
        rates = self.geometry.rates(twist, steer)
        if self._driven:
            ctrl = self.adapter.controls(u, x)
            for i, k in self._driven:
                rates[k] = ctrl[i]
        n = len(self.wheel_names)
        return RobotState(time=np.array(time), pose=np.array(x[:3]), twist=twist,
                          wheel_rates=rates, steer_angles=np.array(steer),
                          wheel_contacts=np.ones(n, dtype=bool))
