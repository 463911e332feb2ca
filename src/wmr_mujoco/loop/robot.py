"""The steppable robot: :class:`Robot`, the part every backend shares.

A backend implements :meth:`Robot._reset` (start at a pose) and :meth:`Robot._advance`
(hold a command for one control period); the base class checks inputs before any work,
clips commands to the command space (one warning per robot), keeps the clock and records
the history.
"""

from __future__ import annotations

import abc
import math
import warnings
from collections import deque
from collections.abc import Callable, Sequence
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.loop.state import CommandSpace, RobotState
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.validation.spec import RobotSpec

#: Most states :attr:`Robot.history` keeps (the oldest are dropped): 5·10⁴ periods, over
#: a quarter of an hour at 20 ms; about 1-2 kB each (with the MuJoCo backend's ``qpos``
#: for :meth:`Robot.film`), at most some 100 MB for the robot with the most joints.
HISTORY_LIMIT = 50_000
#: Longest control period, s: one step() then takes at most this long in the physics.
MAX_CONTROL_PERIOD = 10.0
#: Relative tolerance of "the control period is a whole number of timesteps".
PERIOD_RTOL = 1e-9
#: The dtype of native float64 arrays (a singleton: compared with ``is``).
_FLOAT64 = np.dtype(np.float64)


#: ``filmer(robot, path, **options) -> Path``, installed by :mod:`wmr_mujoco.drive`.
Filmer = Callable[..., Path]
_FILMER: Filmer | None = None


def set_filmer(filmer: Filmer) -> None:
    """Install the function :meth:`Robot.film` calls (rendering lives above this layer)."""
    global _FILMER
    _FILMER = filmer


def substeps(control_period: float, timestep: float) -> int:
    """Number of timesteps in one control period.

    Raises:
        ValueError: the period is not a positive finite multiple of the timestep
            (the message names both).
    """
    if isinstance(control_period, bool) or not isinstance(control_period, (int, float)):
        raise TypeError(f"control_period = {control_period!r}; expected a number of "
                        "seconds")
    if not (math.isfinite(control_period) and 0 < control_period <= MAX_CONTROL_PERIOD):
        raise ValueError(f"control_period = {control_period!r} s; must be in (0, "
                         f"{MAX_CONTROL_PERIOD:g}] s, a multiple of the model timestep "
                         f"{timestep:g} s")
    n = round(control_period / timestep)
    if n < 1 or abs(n * timestep - control_period) > PERIOD_RTOL * control_period:
        raise ValueError(f"control_period = {control_period!r} s is not a multiple of the "
                         f"model timestep {timestep:g} s (e.g. {max(n, 1) * timestep:g} s)")
    return n


def check_pose(pose: Sequence[float] | np.ndarray | None) -> np.ndarray:
    """``pose`` as ``(x, y, heading)`` floats (None: the origin, heading 0).

    Raises:
        ValueError: not three finite numbers.
    """
    if pose is None:
        return np.zeros(3)
    try:
        arr = np.asarray(pose, dtype=float)
    except (TypeError, ValueError):
        arr = None
    if arr is None or arr.shape != (3,) or not np.all(np.isfinite(arr)):
        raise ValueError(f"pose = {pose!r}; expected three finite numbers (x m, y m, "
                         "heading rad)")
    return arr


def check_seed(seed: int | None) -> int | None:
    """Raise ``ValueError`` unless ``seed`` is None or an integer >= 0."""
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, (int, np.integer))
                             or seed < 0):
        raise ValueError(f"seed = {seed!r}; expected None or an integer >= 0")
    return seed


class Robot(abc.ABC):
    """A robot driven one control period at a time (see :func:`wmr_mujoco.loop.build.build_robot`).

    Attributes:
        spec: the robot's registry entry.
        backend: ``"mujoco"``, ``"kinematic"``, ...
        mode: ``"command"``, ``"wheels"`` or ``"torque"``.
        control_period: s.
        command_space: what :meth:`step` accepts.
        wheel_names: the wheels of ``RobotState.wheel_rates``.
        steer_names: the steering joints of ``RobotState.steer_angles``.
        model: the MuJoCo model (None on the analytic backends).
        data: the MuJoCo data (None on the analytic backends).
    """

    backend: str = ""
    model: mujoco.MjModel | None = None
    data: mujoco.MjData | None = None
    #: The robot's parameters (None: the checked-in model), set by ``make``.
    params: RobotParams | None = None

    def __init__(self, spec: RobotSpec, mode: str, control_period: float,
                 command_space: CommandSpace) -> None:
        assert spec.command is not None
        self.spec = spec
        self.mode = mode
        self.control_period = float(control_period)
        self.command_space = command_space
        self.wheel_names = spec.command.wheels
        self.steer_names = spec.command.steers
        self._low = command_space.low
        self._high = command_space.high
        self._bounds = list(zip(command_space.low.tolist(), command_space.high.tolist(),
                                strict=True))
        self._shape = command_space.shape
        self._warned = False
        self._history: deque[RobotState] = deque(maxlen=HISTORY_LIMIT)
        self._commands: deque[np.ndarray] = deque(maxlen=HISTORY_LIMIT)
        self._state: RobotState | None = None

    # -- public API ---------------------------------------------------------------

    def reset(self, pose: Sequence[float] | np.ndarray | None = None,
              seed: int | None = None) -> RobotState:
        """Start again at ``pose`` = ``(x, y, heading)`` (m, m, rad; None: the origin).

        ``seed``: None starts every wheel at angle 0; an integer draws each wheel's angle
        uniformly in [0, 2π) (the roller phase of omni and mecanum wheels) from
        ``numpy.random.default_rng(seed)``; the analytic backends have no wheel angles.

        Raises:
            ValueError: a bad pose or seed (before anything is changed).
            SimulationDivergedError: the robot diverged while settling.
        """
        pose = check_pose(pose)
        seed = check_seed(seed)
        self._history.clear()
        self._commands.clear()
        self._state = self._reset(pose, seed)
        self._history.append(self._state)
        return self._state

    def step(self, command: Sequence[float] | np.ndarray) -> RobotState:
        """Hold ``command`` for one control period; return the state at its end.

        A command outside :attr:`command_space` is clipped to it, with one warning per
        robot (``warnings.warn``, naming the value and the limits).

        Raises:
            RuntimeError: :meth:`reset` was not called.
            ValueError: wrong length, non-numeric or non-finite command (before stepping).
            SimulationDivergedError: the simulation diverged (the state stays the last
                good one; :meth:`reset` before stepping again).
        """
        if self._state is None:
            raise RuntimeError("call robot.reset() before robot.step()")
        u = self._command(command)
        self._state = state = self._advance(u)
        self._history.append(state)
        self._commands.append(u)
        return state

    def _command(self, command: Sequence[float] | np.ndarray) -> np.ndarray:
        """``command`` checked and clipped, as a new float array (the robot's own copy).

        The common case, a float array or a tuple/list of floats inside the box, is
        checked on Python floats (a NaN fails the bounds and takes the full check).
        """
        kind = type(command)
        if kind is np.ndarray:
            if command.dtype is _FLOAT64 and command.shape == self._shape:
                for value, (lo, hi) in zip(command.tolist(), self._bounds, strict=True):
                    if not lo <= value <= hi:
                        break
                else:
                    return command.copy()
        elif (kind is tuple or kind is list) and len(command) == len(self._bounds):
            for value, (lo, hi) in zip(command, self._bounds, strict=True):
                if type(value) is not float or not lo <= value <= hi:
                    break
            else:
                return np.array(command)
        u = self.command_space.check(command)
        for value, (lo, hi) in zip(u.tolist(), self._bounds, strict=True):
            if not lo <= value <= hi:
                return self._clip(u, stacklevel=4)
        return u.copy()  # check() may hand back the caller's array, or a view of it

    def _clip(self, u: np.ndarray, stacklevel: int) -> np.ndarray:
        """``u`` clipped to the command space; the first time, a warning."""
        if not self._warned:
            self._warned = True
            warnings.warn(f"{self.spec.name}: command {u.tolist()} outside the command "
                          f"space ({self.command_space.describe()}); clipped (warned once "
                          "per robot)", stacklevel=stacklevel)
        return np.clip(u, self._low, self._high)

    @property
    def state(self) -> RobotState:
        """The current state (after the last reset or step)."""
        if self._state is None:
            raise RuntimeError("call robot.reset() first: the robot has no state yet")
        return self._state

    @property
    def time(self) -> float:
        """Seconds since the last reset."""
        return float(self.state.time)

    @property
    def history(self) -> list[RobotState]:
        """The states since the last reset (at most :data:`HISTORY_LIMIT`, newest last)."""
        return list(self._history)

    @property
    def commands(self) -> list[np.ndarray]:
        """The commands applied since the last reset (after clipping), one per step."""
        return list(self._commands)

    def history_arrays(self) -> dict[str, np.ndarray]:
        """The history as arrays by field, one row per state (``extra`` left out)."""
        fields = ("time", "pose", "twist", "wheel_rates", "steer_angles", "wheel_contacts")
        return {f: np.array([getattr(s, f) for s in self._history]) for f in fields}

    def film(self, path: str | Path, **options: object) -> Path:
        """Film the recorded run (see :func:`wmr_mujoco.drive.film.film`).

        Rendering is application layer: :mod:`wmr_mujoco.drive` installs the filmer
        (:func:`set_filmer`) when it is imported (``wmr_mujoco.make`` imports it).

        Raises:
            RuntimeError: no filmer is installed (import :mod:`wmr_mujoco.drive`).
        """
        if _FILMER is None:
            raise RuntimeError("no filmer installed: import wmr_mujoco.drive (wmr_mujoco.make "
                               "does) to film a run")
        return _FILMER(self, path, **options)

    def __repr__(self) -> str:
        return (f"<{type(self).__name__} {self.spec.name!r} backend={self.backend!r} "
                f"mode={self.mode!r} control_period={self.control_period:g}>")

    # -- backends -----------------------------------------------------------------

    @abc.abstractmethod
    def _reset(self, pose: np.ndarray, seed: int | None) -> RobotState:
        """Start at ``pose`` (checked); return the state at time 0."""

    @abc.abstractmethod
    def _advance(self, command: np.ndarray) -> RobotState:
        """Hold ``command`` (checked and clipped) for one period; return the new state."""
