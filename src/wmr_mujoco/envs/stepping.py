"""The environments' own physics loop: the stepping API's step, recording nothing.

An environment steps millions of times and looks back at none of them, so it does not
go through ``robot.step`` (:mod:`wmr_mujoco.drive`), which checks a command of any type,
keeps the history (states, commands, ``qpos`` for filming) and reads a full
:class:`~wmr_mujoco.loop.state.RobotState`. :class:`Stepper` runs the same physics on the
robot's own ``model`` and ``data``, through the same command map
(``RobotSpec.command.bind``): the controls are written once and held for the control
period, ``mj_step2``, ``mj_step(n − 1)``, ``mj_step1`` (``n = T / Δt`` timesteps, bit for bit
those of ``mj_step(n)``, with frames and velocities then up to date for the reading;
an RK4 model steps ``n`` whole timesteps and brings them up to date, as the robot does),
then MuJoCo's warning counters are checked (a divergence raises
:class:`~wmr_mujoco.sim.stepping.SimulationDivergedError`) and a :class:`Snapshot` is read:

* ``xyh``: ``(x, y, ψ)`` of the ``base`` site, m, m, rad (ψ unwrapped, continuous);
* ``uvr``: its body-frame twist ``(u, v, r)``, m/s, m/s, rad/s (``mj_objectVelocity``);
* ``wheel_rates_list``: rad/s per wheel; ``extra``: the command map's extras;
* ``time``: s since the reset.

The robot's own ``state`` and ``history`` stay at its last ``reset`` meanwhile.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any, NamedTuple

import mujoco
import numpy as np

from wmr_mujoco.loop.readout import NO_EXTRAS
from wmr_mujoco.validation.command import RateCommand

#: ``mjOBJ_SITE`` as a Python int (MuJoCo's bindings convert an int faster than the enum).
_SITE = int(mujoco.mjtObj.mjOBJ_SITE)


class Snapshot(NamedTuple):
    """The robot's state after a reset or a step, as floats (module docstring).

    ``pose``, ``twist`` and ``wheel_rates`` give the arrays of a
    :class:`~wmr_mujoco.loop.state.RobotState`; ``steer_angles`` and ``wheel_contacts`` are
    read from the robot's ``data`` and so only while the snapshot is the latest one. (A
    tuple: made in one C call per step.)
    """

    time: float
    xyh: tuple[float, float, float]
    uvr: tuple[float, float, float]
    wheel_rates_list: list[float]
    extra: Mapping[str, float]
    serial: int
    stepper: Stepper

    @property
    def pose(self) -> np.ndarray:
        """``(x, y, ψ)``, m, m, rad."""
        return np.array(self.xyh)

    @property
    def twist(self) -> np.ndarray:
        """Body-frame ``(u, v, r)``, m/s, m/s, rad/s."""
        return np.array(self.uvr)

    @property
    def wheel_rates(self) -> np.ndarray:
        """rad/s, one per wheel."""
        return np.array(self.wheel_rates_list)

    def _live(self) -> Any:
        if self.serial != self.stepper.serial:
            raise RuntimeError("this snapshot is no longer the robot's state: read "
                               "steer_angles and wheel_contacts before the next step")
        return self.stepper.reader

    @property
    def steer_angles(self) -> np.ndarray:
        """rad, one per steering joint (the latest snapshot only)."""
        reader = self._live()
        return reader.data.qpos[reader.steer_qpos].copy()

    @property
    def wheel_contacts(self) -> np.ndarray:
        """Whether each wheel touches anything (the latest snapshot only)."""
        return self._live().contacts()


_new = tuple.__new__


class Stepper:
    """Steps a MuJoCo-backend robot (``wmr_mujoco.drive.make``) as the module docstring says.

    Args:
        robot: the robot (its ``model``, ``data``, ``reader``, ``nstep``, mode and spec).
    """

    def __init__(self, robot: Any) -> None:
        model, data, cmap = robot.model, robot.data, robot.spec.command
        self.robot, self.model, self.data = robot, model, data
        self.nstep = int(robot.nstep)
        self.period = float(robot.control_period)
        #: natural command -> controls (the robot's command map), None: the controls.
        self.controller = None
        #: ``W`` of a command map that is ``ctrl = W u`` (:meth:`RateCommand.matrix`, no
        #: steering servo, no adjustment): applied here as ``bind``'s controller applies
        #: it, ``W.dot(u, out=ctrl)``, without the call around it.
        self._w: np.ndarray | None = None
        if robot.mode == "command":
            adapter = cmap.analytic(robot.params)
            if type(cmap).bind is RateCommand.bind and not cmap.servo and cmap.adjust is None:
                self._w = cmap.matrix(adapter)
            if self._w is None:
                self.controller = cmap.bind(model, adapter)
        self._u = np.zeros(len(data.ctrl) if self._w is None else self._w.shape[1])
        self._dot = None if self._w is None else self._w.dot
        self.split = model.opt.integrator != mujoco.mjtIntegrator.mjINT_RK4
        reader = robot.reader
        self.reader, self.site = reader, reader.site
        self.extras = cmap.extras
        self._ctrl, self._warnings = data.ctrl, data.warning.number
        self._xpos, self._xmat = data.site_xpos[reader.site], data.site_xmat[reader.site]
        self._qvel, self._rows, self._vel = data.qvel, reader.wheel_rows, np.zeros(6)
        self._t0 = 0.0
        self._heading = 0.0
        #: Counts the snapshots read (a snapshot knows whether it is the latest).
        self.serial = 0

    def start(self, heading: float) -> Snapshot:
        """The state after the robot's ``reset`` (and whatever the task set), time 0.

        ``heading``: the reset's heading, rad (the readings unwrap the heading next to it).
        """
        self._t0 = self.data.time
        self._heading = float(heading)
        return self.read()

    def step(self, command: list[float]) -> Snapshot:
        """Hold ``command`` (checked, inside the command space) for one control period."""
        self.advance(command)
        return self.finish()

    def advance(self, command: list[float]) -> None:
        """The physics of :meth:`step`; :meth:`finish` then checks and reads it.

        (Apart so that a vector environment steps every world's physics, then reads every
        world: the reading's Python code runs warm for all worlds but the first.)
        """
        model, data = self.model, self.data
        if self._dot is not None:
            u = self._u
            u[:] = command
            self._dot(u, self._ctrl)
        elif self.controller is None:
            self._ctrl[:] = command
        else:
            self.controller(data, np.array(command), self.period, self._ctrl)
        if self.split:
            mujoco.mj_step2(model, data)
            if self.nstep > 1:
                mujoco.mj_step(model, data, self.nstep - 1)
            mujoco.mj_step1(model, data)
        else:
            mujoco.mj_step(model, data, self.nstep)
            mujoco.mj_kinematics(model, data)
            mujoco.mj_comPos(model, data)
            mujoco.mj_comVel(model, data)

    def finish(self) -> Snapshot:
        """After :meth:`advance`: raise on a divergence, else the new snapshot."""
        if any(self._warnings.tolist()):
            self.reader.check()
        return self.read()

    def read(self) -> Snapshot:
        """The snapshot of ``data`` now (the heading unwrapped next to the last one)."""
        x, y, _ = self._xpos.tolist()
        m = self._xmat.tolist()
        h = self._heading
        self._heading = psi = h + math.remainder(math.atan2(m[3], m[0]) - h, math.tau)
        vel, model, data = self._vel, self.model, self.data
        mujoco.mj_objectVelocity(model, data, _SITE, self.site, vel, 1)
        _, _, r, u, v, _ = vel.tolist()
        extra = dict(self.extras(model, data)) if self.extras is not None else NO_EXTRAS
        self.serial = serial = self.serial + 1
        return _new(Snapshot, (data.time - self._t0, (x, y, psi), (u, v, r),
                               self._qvel[self._rows].tolist(), extra, serial, self))
