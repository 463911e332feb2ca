"""One robot and one task stepped together: the core shared by Gymnasium and dm_control.

:class:`Episode` owns a driven robot (:func:`wmr_mujoco.drive.make`, MuJoCo backend), a
:class:`~wmr_mujoco.envs.tasks.Task` and optional domain randomisation. Actions are the
robot's command normalised to ``[-1, 1]`` per channel,

    command = c + h a,   c = (high + low) / 2,   h = (high − low) / 2,

(``a`` clipped to ``[-1, 1]``). The observation is the task's block followed by the
robot's own:

* ``twist`` (3, m/s, m/s, rad/s): body-frame ``(u, v, r)``;
* ``wheel_rates`` (one per wheel, rad/s);
* ``last_action`` (one per command channel, 1): the previous normalised action.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from wmr_mujoco.drive import make
from wmr_mujoco.envs.profiles import Profile, profile, robot_name
from wmr_mujoco.envs.randomization import Band, Bands, Randomizer
from wmr_mujoco.envs.stepping import Snapshot, Stepper
from wmr_mujoco.envs.tasks import Field, Task, task_class

MODES = ("command", "wheels")


def check_action(action: Any, n: int) -> list[float]:
    """``action`` as ``n`` Python floats, each clipped to ``[-1, 1]``.

    Raises:
        ValueError: not numeric, wrong shape, or not finite (before any stepping).
    """
    if type(action) is np.ndarray and action.shape == (n,) and action.dtype.kind == "f":
        out = []
        for v in action.tolist():  # the usual case, checked on Python floats
            if not -math.inf < v < math.inf:  # NaN fails too
                break
            out.append(-1.0 if v < -1.0 else 1.0 if v > 1.0 else v)
        else:
            return out
    try:
        a = np.asarray(action)
        if a.dtype.kind not in "biuf":  # complex, strings, objects: not real numbers
            raise TypeError
        a = a.astype(float)
    except (TypeError, ValueError):
        raise ValueError(f"action {action!r} is not numeric (real); expected {n} numbers in "
                         "[-1, 1]") from None
    if a.shape != (n,):
        raise ValueError(f"action has shape {a.shape}; expected ({n},) in [-1, 1]")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"action {a.tolist()} is not finite; expected {n} finite numbers "
                         "in [-1, 1]")
    return np.clip(a, -1.0, 1.0).tolist()


def box_scale(low: np.ndarray, high: np.ndarray) -> tuple[list[float], list[float]]:
    """``(c, h)`` per channel: ``c + h a`` lies in ``[low, high]`` for every ``a`` in [-1, 1].

    ``c = (high + low) / 2``, ``h = (high − low) / 2``, with ``h`` shrunk by an ulp where
    rounding would put ``c ± h`` outside the box: floating-point multiplication and
    addition are monotonic, so the two ends bound every action in between and a command
    needs no clipping.
    """
    cs, hs = [], []
    for lo, hi in zip(low.tolist(), high.tolist(), strict=True):
        c, h = (hi + lo) / 2, (hi - lo) / 2
        while h > 0 and (c + h > hi or c - h < lo):
            h = math.nextafter(h, 0.0)
        cs.append(c)
        hs.append(h)
    return cs, hs


class Episode:
    """A robot, a task, and the bookkeeping of one episode (module docstring).

    Args:
        robot: registry name of a drivable robot.
        task: task name (one of the robot's profile's tasks).
        mode: ``"command"`` (natural command) or ``"wheels"`` (raw wheel commands).
        randomize: apply the robot's randomisation bands at each reset (True), bands of
            your own (a :class:`Bands`, or a mapping of bands that replace the robot's,
            e.g. ``{"friction": (0.5, 1.0)}``), or none (False, the default).
        task_kwargs: the task's options (see its docstring).
        control_period: s per step (None: the robot's profile).

    Raises:
        ValueError: unknown robot, task, mode or option; the message lists valid ones.
    """

    def __init__(self, robot: str, task: str, mode: str = "command",
                 randomize: bool | Bands | Mapping[str, Band | None] = False,
                 task_kwargs: Mapping[str, float] | None = None,
                 control_period: float | None = None) -> None:
        robot = robot_name(robot)
        prof: Profile = profile(robot)
        if task not in prof.tasks:
            raise ValueError(f"robot {robot!r} has no task {task!r}; its tasks: "
                             f"{', '.join(prof.tasks)}")
        if mode not in MODES:
            raise ValueError(f"unknown mode {mode!r}; valid modes: {', '.join(MODES)}")
        if isinstance(randomize, Mapping):
            randomize = prof.bands.replace(**randomize)
        if not isinstance(randomize, (bool, Bands)):
            raise TypeError(f"randomize={randomize!r}: give True, False, a Bands or a mapping "
                            "of bands")
        self.profile = prof
        options = {**prof.task_options.get(task, {}), **dict(task_kwargs or {})}
        self.task: Task = task_class(task)(prof.scale, prof.max_curvature, **options)
        self.robot = make(robot, backend="mujoco", mode=mode,
                          control_period=prof.control_period if control_period is None
                          else control_period)
        space = self.robot.command_space
        self.center = (space.high + space.low) / 2
        self.half = (space.high - space.low) / 2
        #: ``c`` and ``h`` of each channel as floats (:func:`box_scale`).
        self._c, self._h = box_scale(space.low, space.high)
        self.bands = prof.bands if randomize is True else (randomize or None)
        self.randomizer = (Randomizer(self.robot.model, self.bands, self.robot.wheel_names)
                           if self.bands is not None else None)
        self.n_action = space.shape[0]
        self.fields: tuple[Field, ...] = (
            *self.task.fields, Field("twist (u, v, r)", 3, "m/s, m/s, rad/s"),
            Field("wheel_rates", len(self.robot.wheel_names), "rad/s"),
            Field("last_action", self.n_action, "1"))
        self.size = sum(f.size for f in self.fields)
        self.dt = self.robot.control_period
        #: The recording-free physics loop on the robot's model and data.
        self.stepper = Stepper(self.robot)
        self.state: Snapshot | None = None
        self._shape = (self.n_action,)
        self._channels = range(self.n_action)
        self.last_action = [0.0] * self.n_action
        self.factors: dict[str, np.ndarray] = {}

    def reset(self, rng: np.random.Generator) -> np.ndarray:
        """Draw the episode (randomisation, task), reset the robot; the first observation."""
        if self.randomizer is not None:
            self.factors = self.randomizer.apply(rng, self.robot.data)
        start = self.task.sample(rng)
        self.robot.reset(pose=start, seed=int(rng.integers(2**31)))
        self.task.start(self.robot, rng)  # it may set the robot in motion: read it after
        self.state = self.stepper.start(float(start[2]))
        self.last_action = [0.0] * self.n_action
        return self.observe()

    def command(self, action: Any) -> list[float]:
        """The robot command ``c + h a`` of a checked normalised action (kept in the box)."""
        return [c + h * a for c, h, a in zip(self._c, self._h, action, strict=True)]

    def action(self, command: np.ndarray) -> np.ndarray:
        """The normalised action of a robot command (the inverse of :meth:`command`)."""
        return (np.asarray(command, float) - self.center) / np.where(self.half > 0,
                                                                      self.half, 1.0)

    def step(self, action: Any) -> tuple[np.ndarray, float, bool, bool, dict]:
        """One control period: ``(observation, reward, terminated, truncated, info)``.

        Raises:
            ValueError: bad action (:func:`check_action`), before stepping.
            RuntimeError: no reset yet.
            SimulationDivergedError: the physics diverged.
        """
        if self.state is None:
            raise RuntimeError("call reset() before step()")
        # The usual action, a float array of the right shape inside [-1, 1], is checked on
        # Python floats; anything else (a NaN fails the bounds) goes through check_action,
        # which raises or clips.
        if type(action) is np.ndarray and action.shape == self._shape and \
                action.dtype.kind == "f":
            a = action.tolist()
            for v in a:
                if not -1.0 <= v <= 1.0:
                    a = check_action(action, self.n_action)
                    break
        else:
            a = check_action(action, self.n_action)
        return self.advance(a)

    def advance(self, a: list[float]) -> tuple[np.ndarray, float, bool, bool, dict]:
        """:meth:`step` of a checked action: ``n_action`` floats in ``[-1, 1]``.

        :meth:`push` then :meth:`pull` (the vector environment checks a whole batch before
        it steps any world, and pushes every world before it pulls them).
        """
        self.push(a)
        return self.pull()

    def push(self, a: list[float]) -> None:
        """The physics of :meth:`advance` (the command of ``a`` held for one period)."""
        c, h = self._c, self._h  # indexed: faster than a zip of three for a few channels
        self.stepper.advance([c[i] + h[i] * a[i] for i in self._channels])
        self.last_action = a

    def pull(self) -> tuple[np.ndarray, float, bool, bool, dict]:
        """After :meth:`push`: the step's ``(observation, reward, terminated, truncated, info)``.

        Raises:
            SimulationDivergedError: the physics diverged.
        """
        prev, task = self.state, self.task
        self.state = state = self.stepper.finish()
        a = self.last_action
        terms, success, failure, obs = task.evaluate_observe(prev, state, a, self.dt)
        time = state.time
        truncated = not (success or failure) and time >= task.time_limit - 1e-9
        if truncated:
            success = task.succeeded_at_time_limit(state)
        info = {"reward_terms": terms, "is_success": bool(success), "failed": bool(failure),
                "time": time}
        obs += state.uvr  # the task's block is a new list: extended in place (observe())
        obs += state.wheel_rates_list
        obs += a
        return (np.array(obs, np.float32), sum(terms.values()),
                not truncated and (success or failure), truncated, info)

    def observe(self) -> np.ndarray:
        """The observation vector (float32; module docstring)."""
        s = self.state
        obs = self.task.observe(s)  # a new list: extended in place
        obs += s.uvr
        obs += s.wheel_rates_list
        obs += self.last_action
        return np.array(obs, np.float32)

    def describe(self) -> str:
        """The observation's blocks with their units, one per line."""
        return "\n".join(f"{f.name} ({f.size}): {f.unit}" for f in self.fields)
