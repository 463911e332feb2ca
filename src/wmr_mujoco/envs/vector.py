"""The native vector environment: ``gymnasium.make_vec(id, n)`` steps n worlds in one loop.

Each environment id registers :class:`WmrVectorEnv` as its ``vector_entry_point``, so that
``gymnasium.make_vec(id, num_envs=n)`` (the default ``vectorization_mode``) returns it;
``"sync"`` and ``"async"`` still wrap n single environments. The n worlds are n
:class:`~wmr_mujoco.envs.env.WmrEnv`, each with its own model and data (so that each draws
its own domain randomisation), stepped one after the other by the single environment's
own step (:meth:`~wmr_mujoco.envs.episode.Episode.push`, then
:meth:`~wmr_mujoco.envs.episode.Episode.pull`): world ``i`` gives bit for bit the
observations, rewards and flags of a single environment reset with its seed. What this
class saves is the generic wrapper's work around each world's step: the whole batch of
actions is checked once (a bad action of any world raises before any world steps), every
world's physics is stepped before every world is read (the reading and task code, Python,
then runs with its caches warm for all worlds but the first), and the results and infos are
gathered into arrays once per step.

Semantics are Gymnasium 1.x's (:class:`gymnasium.vector.SyncVectorEnv`, whose results this
class reproduces, infos included):

* ``reset(seed=s)``: world ``i`` is reset with seed ``s + i`` (a list: one seed per world);
  ``options={"reset_mask": mask}`` resets only the masked worlds (``AutoresetMode.DISABLED``).
* ``autoreset_mode`` (a keyword of ``make_vec``): ``NEXT_STEP`` (the default: the step after
  an episode ends resets that world, ignoring its action, and returns its first
  observation with reward 0 and both flags false), ``SAME_STEP`` (the ending step resets
  at once; its last observation and info are in ``info["final_obs"]``,
  ``info["final_info"]``) or ``DISABLED`` (the caller resets ended worlds with a mask).
* ``info``: each key of the worlds' infos as an array over the worlds, beside a mask
  ``"_key"`` of the worlds that gave it (nested for ``reward_terms``). In a step where
  every world stepped, the masks are one shared read-only all-True array.

Rendering: ``render_mode="rgb_array"`` only (``render()`` gives one frame per world).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium.vector import AutoresetMode
from gymnasium.vector.utils import batch_space

from wmr_mujoco.envs.env import WmrEnv

#: Most worlds in one vector environment: each holds its own compiled model and data
#: (measured: about 1.6 MB for the disc, 6 MB for the mecanum platform), so 256 worlds stay
#: under 2 GB whatever a user types; more worlds belong in more processes.
MAX_ENVS = 256


def check_actions(actions: Any, shape: tuple[int, int]) -> list[list[float]]:
    """A batch of actions as one list of floats per world, each clipped to ``[-1, 1]``.

    Raises:
        ValueError: not numeric, not of ``shape``, or not finite (before any world steps).
    """
    if type(actions) is np.ndarray and actions.shape == shape and actions.dtype.kind == "f":
        rows = actions.tolist()
        for row in rows:  # the usual case: checked on Python floats
            for v in row:
                if not -1.0 <= v <= 1.0:
                    break
            else:
                continue
            break
        else:
            return rows
    try:
        a = np.asarray(actions)
        if a.dtype.kind not in "biuf":
            raise TypeError
        a = a.astype(float)
    except (TypeError, ValueError):
        raise ValueError(f"actions {actions!r} are not numeric (real); expected an array of "
                         f"shape {shape} in [-1, 1]") from None
    if a.shape != shape:
        raise ValueError(f"actions have shape {a.shape}; expected {shape} (worlds, action "
                         "channels) in [-1, 1]")
    bad = np.flatnonzero(~np.isfinite(a).all(axis=1))
    if bad.size:
        raise ValueError(f"actions of world(s) {bad.tolist()} are not finite: "
                         f"{a[bad].tolist()}; expected finite numbers in [-1, 1]")
    return np.clip(a, -1.0, 1.0).tolist()


def _seeds(seed: int | list[int | None] | None, n: int) -> list[int | None]:
    """One seed per world: None each, ``seed + i``, or the list given (module docstring)."""
    if seed is None:
        return [None] * n
    if isinstance(seed, (int, np.integer)) and not isinstance(seed, bool):
        return [int(seed) + i for i in range(n)]
    seeds = list(seed)
    if len(seeds) != n:
        raise ValueError(f"{len(seeds)} seeds for {n} worlds; give one seed per world, an "
                         "int (world i gets seed + i) or None")
    return seeds


class WmrVectorEnv(gym.vector.VectorEnv):
    """n worlds of one robot and task (module docstring).

    Args:
        robot: registry name of a drivable robot.
        task: the task's name.
        num_envs: number of worlds, 1 to :data:`MAX_ENVS`.
        autoreset_mode: an :class:`~gymnasium.vector.AutoresetMode` or its value.
        **options: the single environment's options (:class:`WmrEnv`).

    Raises:
        ValueError: a bad ``num_envs``, ``autoreset_mode`` or ``render_mode="human"``
            (before any world is built), or a bad option (:class:`WmrEnv`).
    """

    def __init__(self, robot: str, task: str, num_envs: int = 1,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP,
                 **options: Any) -> None:
        if isinstance(num_envs, bool) or not isinstance(num_envs, (int, np.integer)) or \
                not 1 <= num_envs <= MAX_ENVS:
            raise ValueError(f"num_envs={num_envs!r}; valid: an integer in [1, {MAX_ENVS}]")
        if options.get("render_mode") == "human":
            raise ValueError("render_mode='human' opens one viewer per world; the vector "
                             "environment renders render_mode='rgb_array' (or None)")
        try:
            mode = AutoresetMode(autoreset_mode)
        except ValueError:
            raise ValueError(f"autoreset_mode={autoreset_mode!r}; valid: "
                             f"{', '.join(m.value for m in AutoresetMode)}") from None
        self.envs = [WmrEnv(robot, task, **options) for _ in range(int(num_envs))]
        self.episodes = [e.episode for e in self.envs]
        self.num_envs = n = int(num_envs)
        self.autoreset_mode = mode
        first = self.envs[0]
        self.render_mode = first.render_mode
        self.metadata = {**first.metadata, "autoreset_mode": mode}
        self.single_action_space = first.action_space
        self.single_observation_space = first.observation_space
        self.action_space = batch_space(self.single_action_space, n)
        self.observation_space = batch_space(self.single_observation_space, n)
        self.dt = first.dt
        self._shape = (n, first.episode.n_action)
        #: Each world's latest observation (a masked reset returns the others' too).
        self._last: list[np.ndarray] = [np.zeros(first.episode.size, np.float32)] * n
        #: The worlds whose episode ended in the last step, and whether there is one.
        self._autoreset = np.zeros(n, np.bool_)
        self._ended = False
        #: The mask of an info key that every world gave (read-only, shared).
        self._full = np.ones(n, np.bool_)
        self._full.flags.writeable = False
        #: Whether every world has been reset once.
        self._started = False

    def reset(self, *, seed: int | list[int | None] | None = None,
              options: Mapping[str, Any] | None = None) -> tuple[np.ndarray, dict]:
        """Reset every world, or those of ``options["reset_mask"]`` (module docstring).

        Raises:
            ValueError: seeds not one per world, a bad mask, or other options.
        """
        n = self.num_envs
        seeds = _seeds(seed, n)
        options = dict(options or {})
        mask = options.pop("reset_mask", None)
        if options:
            raise ValueError(f"reset() takes only the option 'reset_mask', got "
                             f"{sorted(options)}")
        if mask is None:
            mask = np.ones(n, np.bool_)
        elif not (isinstance(mask, np.ndarray) and mask.dtype == np.bool_ and
                  mask.shape == (n,) and mask.any()):
            raise ValueError(f"options['reset_mask']={mask!r}: need a numpy bool array of "
                             f"shape ({n},) with at least one True")
        infos: dict[str, Any] = {}
        for i in np.flatnonzero(mask).tolist():
            self._last[i], info = self.envs[i].reset(seed=seeds[i])
            infos = self._add_info(infos, info, i)
        self._autoreset = np.where(mask, False, self._autoreset)
        self._ended = bool(self._autoreset.any())
        self._started = all(e.state is not None for e in self.episodes)
        return np.array(self._last), infos

    def step(self, actions: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray,
                                          dict]:
        """One control period of every world (an ended world resets as the mode says).

        Raises:
            ValueError: bad actions (:func:`check_actions`), before any world steps.
            RuntimeError: a world never reset, or (``DISABLED``) an ended world not reset.
            SimulationDivergedError: a world's physics diverged.
        """
        rows = check_actions(actions, self._shape)
        if not self._started:
            raise RuntimeError("call reset() before step()")
        mode = self.autoreset_mode
        if self._ended:  # an episode ended in the last step
            if mode is AutoresetMode.DISABLED:
                raise RuntimeError(f"world(s) {np.flatnonzero(self._autoreset).tolist()} "
                                   "ended and were not reset (autoreset_mode DISABLED): call "
                                   "reset(options={'reset_mask': mask}) first")
            if mode is AutoresetMode.NEXT_STEP:
                return self._step_each(rows)
        # The usual step: every world steps, its results gathered column by column (few
        # numpy calls per batch: each costs as much as a world's step of Python).
        episodes = self.episodes
        for e, a in zip(episodes, rows, strict=True):  # every world's physics, then
            e.push(a)  # every world's reading and task: that Python code then runs warm
        steps = [e.pull() for e in episodes]
        obs, rewards, terms, truncs, infos = zip(*steps, strict=True)
        self._ended = ended = True in terms or True in truncs
        self._last = list(obs)
        terms, truncs = np.array(terms), np.array(truncs)
        if ended:
            self._autoreset = terms | truncs
            if mode is AutoresetMode.SAME_STEP:
                return self._finish_same_step(obs, rewards, terms, truncs, infos)
        return np.array(obs), np.array(rewards), terms, truncs, self._gather(infos)

    def _finish_same_step(self, obs: tuple[np.ndarray, ...], rewards: tuple[float, ...],
                          terms: np.ndarray, truncs: np.ndarray, infos: tuple[dict, ...]
                          ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict]:
        """``SAME_STEP``: reset the worlds that ended, their last step in the info."""
        merged: dict[str, Any] = {}
        out = np.array(obs)
        for i, info in enumerate(infos):
            if terms[i] or truncs[i]:
                merged = self._add_info(merged, {"final_obs": obs[i], "final_info": info}, i)
                out[i], info = self.envs[i].reset()
            merged = self._add_info(merged, info, i)
        self._last = [row.copy() for row in out]
        self._ended = False
        self._autoreset = np.zeros(self.num_envs, np.bool_)
        return out, np.array(rewards), terms, truncs, merged

    def _step_each(self, rows: list[list[float]]) -> tuple[np.ndarray, np.ndarray,
                                                           np.ndarray, np.ndarray, dict]:
        """``NEXT_STEP`` after an episode's end: world by world, the ended ones reset."""
        n = self.num_envs
        obs = np.zeros(self.observation_space.shape, np.float32)
        rewards, terms, truncs = np.zeros(n), np.zeros(n, np.bool_), np.zeros(n, np.bool_)
        merged: dict[str, Any] = {}
        for i, (episode, a) in enumerate(zip(self.episodes, rows, strict=True)):
            if self._autoreset[i]:
                obs[i], info = self.envs[i].reset()
            else:
                obs[i], rewards[i], terms[i], truncs[i], info = episode.advance(a)
            merged = self._add_info(merged, info, i)
        self._last = [row.copy() for row in obs]
        self._autoreset = terms | truncs
        self._ended = bool(self._autoreset.any())
        return obs, rewards, terms, truncs, merged

    def _gather(self, infos: tuple[dict, ...]) -> dict[str, Any]:
        """The infos of a step of every world, as ``_add_info`` would merge them.

        Each key an array over the worlds (a column of one array per type); every mask is
        the one all-True array :attr:`_full` (read-only: one array per step, not one per key).
        """
        first, full = infos[0]["reward_terms"], self._full
        values = np.array([(*s["reward_terms"].values(), s["time"]) for s in infos])
        flags = np.array([(s["is_success"], s["failed"]) for s in infos])
        out: dict[str, Any] = {}
        for j, k in enumerate(first):
            out[k] = values[:, j]
            out[f"_{k}"] = full
        return {"reward_terms": out, "_reward_terms": full, "is_success": flags[:, 0],
                "_is_success": full, "failed": flags[:, 1], "_failed": full,
                "time": values[:, len(first)], "_time": full}

    def render(self) -> tuple[Any, ...] | None:
        """Each world's frame (``render_mode="rgb_array"``), None without a render mode."""
        if self.render_mode is None:
            gym.logger.warn("render() called without a render_mode; pass render_mode="
                            "'rgb_array' to gymnasium.make_vec")
            return None
        return tuple(e.render() for e in self.envs)

    def close_extras(self, **kwargs: Any) -> None:
        """Close every world (renderers, viewers)."""
        for e in self.envs:
            e.close()

