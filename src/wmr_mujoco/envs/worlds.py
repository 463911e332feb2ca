"""n worlds stepped one after the other and read at once into arrays with a world axis.

The batched path of the native vector environment (:mod:`wmr_mujoco.envs.vector`): each
world's physics is its own :class:`~wmr_mujoco.envs.stepping.Stepper`'s (the same command
map and ``mj_step`` calls, bit for bit), but the command of every world and the reading of
every world are computed once per step on arrays of shape ``(n, …)``:

* command ``C = c + h A`` (``A``: the ``(n, m)`` normalised actions, elementwise, the
  floats of :meth:`~wmr_mujoco.envs.episode.Episode.command`);
* pose: the ``base`` site's ``x, y`` and ``ψ = ψ₋ + remainder(atan2(R₁₀, R₀₀) − ψ₋, 2π)``
  (unwrapped next to the last heading ``ψ₋``, as :meth:`Stepper.read`);
* twist ``(u, v, r)`` from ``mj_objectVelocity`` (local frame), one C call per world into
  a row of one ``(n, 6)`` buffer (made right after the world's physics where that is
  inlined, while its data is in the cache);
* wheel rates ``q̇[wheel rows]`` and the command map's extras, and ``time`` since the reset.

The transcendental functions run through :mod:`math` over the worlds' floats (a C loop:
``map``), so that every float equals the single environment's; the rest is numpy
elementwise arithmetic, which rounds as Python's floats do.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from itertools import repeat
from operator import add, sub
from typing import NamedTuple

import mujoco
import numpy as np

from wmr_mujoco.envs.episode import Episode
from wmr_mujoco.validation.command import RateCommand

#: ``mjOBJ_SITE`` as a Python int (MuJoCo's bindings convert an int faster than the enum).
_SITE = int(mujoco.mjtObj.mjOBJ_SITE)
#: ``(u, v, r)``'s columns in ``mj_objectVelocity``'s ``(ω, v)``.
_UVR = np.array([3, 4, 2])


def each(fn: Callable[..., float], a: np.ndarray, b: np.ndarray | float | None = None
         ) -> np.ndarray:
    """``fn`` of :mod:`math` applied world by world: ``fn(a_i)`` or ``fn(a_i, b_i)``.

    Runs ``map`` over the arrays' Python floats (a scalar ``b`` is used for every world):
    the same function as the single environment's scalar code, so the same floats (numpy's
    own ``exp``, ``hypot``, ``arctan2`` differ in the last bit for some arguments).
    """
    if b is None:
        it = map(fn, a.tolist())
    elif isinstance(b, np.ndarray):
        it = map(fn, a.tolist(), b.tolist())
    else:
        it = map(fn, a.tolist(), repeat(b, len(a)))
    return np.fromiter(it, float, len(a))


class Servo(NamedTuple):
    """A steering robot's command map as :class:`RateCommand`'s ``bind`` runs it.

    Servo channels ``ω = clip((φ_cmd − φ_target) / T, ±ω_max)``, then ``adjust`` (if any)
    on each world's inputs, then ``ctrl = W u``.

    Attributes:
        w: ``W``; acts: the servos' ``act`` rows (the targets ``φ_target``);
        channels: ``(channel, ω_max)`` per servo; period: ``T``, s;
        adjust: the command map's ``adjust`` or None; adapter: its kinematic adapter.
    """

    w: np.ndarray
    acts: list[int]
    channels: list[tuple[int, float]]
    period: float
    adjust: Callable[..., np.ndarray] | None
    adapter: object


def _servo(episode: Episode) -> Servo | None:
    """The :class:`Servo` of a steering robot's command map, or None.

    None unless the command map is one that
    :class:`~wmr_mujoco.validation.command.RateCommand`'s ``bind`` runs as servo channels,
    ``adjust``, then ``ctrl = W u`` (a linear, state-independent map).
    """
    robot, st = episode.robot, episode.stepper
    cmap = robot.spec.command
    if robot.mode != "command" or st.controller is None or not isinstance(cmap, RateCommand) \
            or type(cmap).bind is not RateCommand.bind or not cmap.servo:
        return None
    adapter = cmap.analytic(robot.params)
    w = cmap.matrix(adapter)
    if w is None:
        return None
    model = robot.model
    acts = [int(model.actuator_actadr[model.actuator(s.actuator).id]) for s in cmap.servo]
    channels = [(s.channel, limit) for s, limit in
                zip(cmap.servo, cmap.rate_limits(model).tolist(), strict=True)]
    return Servo(w, acts, channels, st.period, cmap.adjust, adapter)


class States(NamedTuple):
    """Every world's state after a step, one row per world (module docstring).

    Attributes:
        time: s since each world's reset, (n,).
        x, y, psi: the ``base`` site's pose, m, m, rad (ψ unwrapped), (n,) each.
        uvr: body-frame twist ``(u, v, r)``, m/s, m/s, rad/s, (n, 3).
        wheel_rates: rad/s, (n, wheels).
        extra: the command map's extras, name -> (n,).
    """

    time: np.ndarray
    x: np.ndarray
    y: np.ndarray
    psi: np.ndarray
    uvr: np.ndarray
    wheel_rates: np.ndarray
    extra: dict[str, np.ndarray]


class Worlds:
    """The physics and the reading of the worlds of ``episodes`` (module docstring).

    Args:
        episodes: one :class:`Episode` per world, all of one robot, mode and period.
    """

    def __init__(self, episodes: Sequence[Episode]) -> None:
        self.episodes = list(episodes)
        first = self.episodes[0]
        self.n = n = len(self.episodes)
        self.steppers = [e.stepper for e in self.episodes]
        self._advance = [s.advance for s in self.steppers]
        #: The usual physics inlined (a command map ``ctrl = W u``, a split step): each
        #: world's ``(W.dot, model, data, ctrl, site, twist row)``; None: each stepper's
        #: own ``advance``.
        st0 = first.stepper
        self._inline = None
        self._servo = _servo(first)
        self._cmap = first.robot.spec.command
        self._vel = np.zeros((n, 6))
        w = st0._w if self._servo is None else self._servo[0]
        if w is not None and st0.split and st0.nstep > 1:
            self._inline = [(w.dot, s.model, s.data, s._ctrl, s.site, self._vel[i])
                            for i, s in enumerate(self.steppers)]
            self._nstep = st0.nstep
        #: Whether ``_vel`` holds the twists of the last inlined physics (read there, while
        #: each world's data is in the cache).
        self._twists = False
        self._c, self._h = np.array(first._c), np.array(first._h)
        st = self.steppers
        self._datas = [s.data for s in st]
        #: Each world's ``act`` (the servo targets): a view per world, taken once (each
        #: attribute read makes a new one), as the stepper keeps its ``ctrl``.
        self._act = [d.act for d in self._datas]
        self._xpos = [s._xpos for s in st]
        self._xmat = [s._xmat for s in st]
        self._qvel = [s._qvel for s in st]
        self._warnings = [s._warnings for s in st]
        rows = first.stepper._rows  # a slice or indices
        self._rows = rows if isinstance(rows, slice) else np.asarray(rows, np.intp)
        self._objvel = [(s.model, s.data, _SITE, s.site, self._vel[i])
                        for i, s in enumerate(st)]
        self._extras = first.stepper.extras
        #: Each world's time at its reset, and its last heading (the unwrapping's anchor).
        self.t0 = np.zeros(n)
        self.heading = np.zeros(n)

    def load(self, i: int) -> None:
        """Take world ``i``'s reset (its stepper's time origin and heading)."""
        s = self.steppers[i]
        self.t0[i] = s._t0
        self.heading[i] = s._heading

    def push(self, actions: np.ndarray, active: np.ndarray | None = None) -> None:
        """Hold the command of ``actions`` (n, m), checked, in every world (or ``active``)."""
        commands = self._c + self._h * actions
        if active is None and self._inline is not None and self._servo is not None:
            # RateCommand.bind's servo channels: ω = clip((φ_cmd − φ_target) / T, ±ω_max),
            # the targets φ_target read from each world's ``act``
            _, acts, channels, period, adjust, adapter = self._servo
            targets = np.array(self._act)[:, acts]
            if adjust is not None:  # world by world anyway: the command map's own inputs
                inputs = self._cmap._inputs
                u = np.array([inputs(adapter, row, phi, period, channels) for row, phi in
                              zip(commands.tolist(), targets.tolist(), strict=True)])
            else:
                u = commands.copy()
                for k, (channel, limit) in enumerate(channels):
                    u[:, channel] = np.minimum(limit, np.maximum(
                        -limit, (commands[:, channel] - targets[:, k]) / period))
            commands = u
        if active is None and self._inline is not None:  # Stepper.advance, inlined
            step1, step, step2 = mujoco.mj_step1, mujoco.mj_step, mujoco.mj_step2
            objvel, n1 = mujoco.mj_objectVelocity, self._nstep - 1
            for (dot, model, data, ctrl, site, vel), u in zip(self._inline, commands,
                                                              strict=True):
                dot(u, ctrl)  # ctrl = W u, as the stepper and the command map write it
                step2(model, data)
                step(model, data, n1)
                step1(model, data)
                objvel(model, data, _SITE, site, vel, 1)  # read's twist (local frame)
            self._twists = True
        elif active is None:
            for advance, u in zip(self._advance, commands, strict=True):
                advance(u)
        else:
            for i in np.flatnonzero(active).tolist():
                self._advance[i](commands[i])

    def read(self) -> States:
        """Every world's state now (raises on a world's divergence, as the stepper does).

        Raises:
            SimulationDivergedError: a world's physics diverged.
        """
        twists, self._twists = self._twists, False  # cleared even if a check raises
        if np.count_nonzero(np.concatenate(self._warnings)):
            for i, w in enumerate(self._warnings):
                if w.any():
                    self.steppers[i].reader.check()
        if not twists:  # not read with the physics
            objvel = mujoco.mj_objectVelocity
            for args in self._objvel:
                objvel(*args, 1)
        pos = np.array(self._xpos)
        mat = np.array(self._xmat)
        # ψ = ψ₋ + remainder(atan2(R₁₀, R₀₀) − ψ₋, 2π) on floats, in one pass (a C loop)
        h = self.heading.tolist()
        psi = np.fromiter(map(add, h, map(math.remainder, map(sub, map(
            math.atan2, mat[:, 3].tolist(), mat[:, 0].tolist()), h), repeat(math.tau))),
            float, self.n)
        self.heading = psi
        time = np.array([d.time for d in self._datas]) - self.t0
        extra: dict[str, np.ndarray] = {}
        if self._extras is not None:
            rows = [dict(self._extras(s.model, s.data)) for s in self.steppers]
            extra = {k: np.array([r[k] for r in rows]) for k in rows[0]}
        return States(time, pos[:, 0], pos[:, 1], psi, self._vel[:, _UVR],
                      np.array(self._qvel)[:, self._rows], extra)
