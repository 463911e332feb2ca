"""The native vector environment: ``gymnasium.make_vec(id, n)`` steps n worlds in one loop.

Each environment id registers :class:`WmrVectorEnv` as its ``vector_entry_point``, so that
``gymnasium.make_vec(id, num_envs=n)`` (the default ``vectorization_mode``) returns it;
``"sync"`` and ``"async"`` still wrap n single environments. The n worlds are n
:class:`~wmr_mujoco.envs.env.WmrEnv`, each with its own model and data (so that each draws
its own domain randomisation) and its own reset (task draw, randomisation, settling). A
step checks the whole batch of actions once (a bad action of any world raises before any
world steps), then steps the worlds by one of two paths, which give the same results:

* below :data:`BATCHED_FROM` worlds, each world through its single environment's step
  (:mod:`wmr_mujoco.envs.serial`), the batch assembled from their results;
* from :data:`BATCHED_FROM` on, every world's physics, then the reading, the task and the
  bookkeeping once for all worlds on arrays (:mod:`wmr_mujoco.envs.batched`).

Worlds whose episode ended are reset one by one (their single environment's reset). World
``i`` gives bit for bit the observations, rewards, flags and infos of a single environment
reset with its seed (``tests/envs/test_vector.py``, both paths).

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

from wmr_mujoco.envs.batched import Batched
from wmr_mujoco.envs.env import WmrEnv
from wmr_mujoco.envs.serial import Serial

#: Most worlds in one vector environment: each holds its own compiled model and data
#: (measured: about 1.6 MB for the disc, 6 MB for the mecanum platform), so 256 worlds stay
#: under 2 GB whatever a user types; more worlds belong in more processes.
MAX_ENVS = 256

#: The fewest worlds stepped by the batched path (:mod:`wmr_mujoco.envs.batched`); fewer go
#: through their single environments (:mod:`wmr_mujoco.envs.serial`). Chosen from
#: ``python -m wmr_mujoco.bench.vector_paths --paths --sizes 4,8,12,16,24,64 ID ...`` on the
#: Disc, DiffDrive and Bicycle GoToGoal and FollowPath environments (both paths' steps/s at
#: each size, paired with a bare loop in each round, one process, CPU time): its last line
#: prints the span of the crossovers (the fewest worlds from which the batched path stays
#: the faster) and this constant beside it, chosen within the span: there the two paths'
#: figures are close, so either path costs little at those sizes. Above it the batched
#: path's fixed cost per step (a hundred numpy calls) is spread over more worlds.
BATCHED_FROM = 12


_max, _abs = np.maximum.reduce, np.abs


def check_actions(actions: Any, shape: tuple[int, int]) -> np.ndarray:
    """A batch of actions as a float array of ``shape``, each entry clipped to ``[-1, 1]``.

    Raises:
        ValueError: not numeric, not of ``shape``, or not finite (before any world steps).
    """
    if type(actions) is np.ndarray and actions.shape == shape and actions.dtype.kind == "f":
        a = actions.astype(float)
        if _max(_abs(a), axis=None) <= 1.0:  # the usual batch: nothing to clip (NaN fails)
            return a
    else:
        try:
            a = np.asarray(actions)
            if a.dtype.kind not in "biuf":
                raise TypeError
            a = a.astype(float)
        except (TypeError, ValueError):
            raise ValueError(f"actions {actions!r} are not numeric (real); expected an array "
                             f"of shape {shape} in [-1, 1]") from None
        if a.shape != shape:
            raise ValueError(f"actions have shape {a.shape}; expected {shape} (worlds, action "
                             "channels) in [-1, 1]")
    if not np.isfinite(a).all():
        bad = np.flatnonzero(~np.isfinite(a).all(axis=1))
        raise ValueError(f"actions of world(s) {bad.tolist()} are not finite: "
                         f"{a[bad].tolist()}; expected finite numbers in [-1, 1]")
    return np.clip(a, -1.0, 1.0, out=a)


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
        batched: step by the batched path (True) or world by world (False); None: batched
            from :data:`BATCHED_FROM` worlds on (the faster one; the results are the same).
        **options: the single environment's options (:class:`WmrEnv`).

    Raises:
        ValueError: a bad ``num_envs``, ``autoreset_mode`` or ``render_mode="human"``
            (before any world is built), a ``batched`` not a bool or None, or a bad option
            (:class:`WmrEnv`).
    """

    def __init__(self, robot: str, task: str, num_envs: int = 1,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP,
                 batched: bool | None = None, **options: Any) -> None:
        if isinstance(num_envs, bool) or not isinstance(num_envs, (int, np.integer)) or \
                not 1 <= num_envs <= MAX_ENVS:
            raise ValueError(f"num_envs={num_envs!r}; valid: an integer in [1, {MAX_ENVS}]")
        if batched is not None and not isinstance(batched, bool):
            raise ValueError(f"batched={batched!r}; valid: True (the batched path), False "
                             "(world by world) or None (by the number of worlds)")
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
        #: Every world's latest observation (a masked reset returns the others' too).
        self._obs = np.zeros((n, first.episode.size), np.float32)
        #: How the worlds step: one by one through their single environments, or batched.
        if batched is None:
            batched = n >= BATCHED_FROM
        self.engine = Batched(self.episodes) if batched else Serial(self.episodes)
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
            infos = self._add_info(infos, self._reset_world(i, seeds[i]), i)
        self._autoreset = np.where(mask, False, self._autoreset)
        self._ended = bool(self._autoreset.any())
        self._started = all(e.state is not None for e in self.episodes)
        return self._obs.copy(), infos

    def _reset_world(self, i: int, seed: int | None = None) -> dict:
        """Reset world ``i`` (its single environment's reset) and load it into the arrays."""
        self._obs[i], info = self.envs[i].reset(seed=seed)
        self.engine.load(i)
        return info

    def step(self, actions: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray,
                                          dict]:
        """One control period of every world (an ended world resets as the mode says).

        Raises:
            ValueError: bad actions (:func:`check_actions`), before any world steps.
            RuntimeError: a world never reset, or (``DISABLED``) an ended world not reset.
            SimulationDivergedError: a world's physics diverged.
        """
        a = check_actions(actions, self._shape)
        if not self._started:
            raise RuntimeError("call reset() before step()")
        mode = self.autoreset_mode
        resets: list[tuple[int, dict]] = []
        active = None
        if self._ended:  # an episode ended in the last step
            if mode is AutoresetMode.DISABLED:
                raise RuntimeError(f"world(s) {np.flatnonzero(self._autoreset).tolist()} "
                                   "ended and were not reset (autoreset_mode DISABLED): call "
                                   "reset(options={'reset_mask': mask}) first")
            # NEXT_STEP: the ended worlds reset (their actions ignored), the others step
            active = ~self._autoreset
            resets = [(i, self._reset_world(i)) for i in
                      np.flatnonzero(self._autoreset).tolist()]
        obs, reward, terms_, truncs, flags = self.engine.step(a, active)
        if active is not None:  # the reset worlds: first observation, reward 0, no flags
            for i, _ in resets:
                self.engine.load(i)
            obs[~active] = self._obs[~active]
            reward[~active] = 0.0
            terms_ &= active
            truncs &= active
        ended = terms_ | truncs
        self._autoreset = ended
        self._ended = ended.tobytes().count(1) > 0
        if self._ended and mode is AutoresetMode.SAME_STEP:
            return self._finish_same_step(obs, reward, terms_, truncs, flags)
        self._obs = obs
        return obs.copy(), reward, terms_, truncs, self._infos(flags, active, resets)

    def _infos(self, flags: tuple, stepped: np.ndarray | None,
               others: list[tuple[int, dict]]) -> dict[str, Any]:
        """The step's infos as ``_add_info`` would merge the worlds' infos in world order.

        ``flags``: the reward terms, success, failure and time arrays; ``stepped``: the
        worlds that stepped (None: all: every mask is the one read-only all-True array
        :attr:`_full`); ``others``: ``(world, info)`` of the worlds that did not step.
        """
        terms, success, failure, time = flags
        if stepped is None:
            mask = self._full
            if not others:  # the usual step: every world stepped, no reset
                return {"reward_terms": {k2: v2 for k, v in terms.items()
                                         for k2, v2 in ((k, v), (f"_{k}", mask))},
                        "_reward_terms": mask, "is_success": success, "_is_success": mask,
                        "failed": failure, "_failed": mask, "time": time, "_time": mask}
        else:
            mask = stepped.copy()
            terms = {k: np.where(mask, v, 0.0) for k, v in terms.items()}
            success, failure, time = success & mask, failure & mask, np.where(mask, time, 0.0)
        out: dict[str, Any] = {}
        first = int(np.argmax(mask)) if mask.any() else self.num_envs
        for i, info in others:  # the worlds before the first that stepped: keys first
            if i < first:
                out = self._add_info(out, info, i)
        if first < self.num_envs:
            nested: dict[str, Any] = {}
            for k, v in terms.items():
                nested[k], nested[f"_{k}"] = v, mask
            out.update({"reward_terms": nested, "_reward_terms": mask,
                        "is_success": success, "_is_success": mask, "failed": failure,
                        "_failed": mask, "time": time, "_time": mask})
            if stepped is not None:  # own arrays: the later _add_info write into them
                for k in ("_reward_terms", "_is_success", "_failed", "_time"):
                    out[k] = mask.copy()
                for k in list(nested):
                    if k.startswith("_"):
                        nested[k] = mask.copy()
        for i, info in others:
            if i >= first:
                out = self._add_info(out, info, i)
        return out

    def _finish_same_step(self, obs: np.ndarray, reward: np.ndarray, terms: np.ndarray,
                          truncs: np.ndarray, flags: tuple
                          ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict]:
        """``SAME_STEP``: reset the worlds that ended, their last step in the info."""
        ended = terms | truncs
        t, success, failure, time = flags
        others = []
        for i in np.flatnonzero(ended).tolist():
            last = {"reward_terms": {k: v[i].item() for k, v in t.items()},
                    "is_success": bool(success[i]), "failed": bool(failure[i]),
                    "time": time[i].item()}
            final = {"final_obs": obs[i].copy(), "final_info": last}
            final.update(self._reset_world(i))
            others.append((i, final))
        out = np.where(ended[:, None], self._obs, obs)
        self._obs = out
        self._ended = False
        self._autoreset = np.zeros(self.num_envs, np.bool_)
        return out.copy(), reward, terms, truncs, self._infos(flags, ~ended, others)

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

