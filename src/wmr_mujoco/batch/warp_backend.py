"""The ``"warp"`` backend: MuJoCo Warp, one world per member, on GPUs (else the CPU).

Each member starts from the state C MuJoCo settled it into (its ``qpos``, ``qvel``,
``act``, solver warm start) and is stepped by ``mujoco_warp.step`` with its own
open-loop controls. Members built from different parameters share one Warp model whose
differing fields are batched per world (``put_model(batch_sizes=...)``: masses,
frictions, geometry sizes, ...); a difference Warp cannot batch is refused before work.

Members are split over the devices (:mod:`wmr_mujoco.batch.shard`); each device steps
its shard in chunks of :data:`CHUNK` steps, all devices' chunks launched before any is
read back, so GPUs work at once. After every chunk the overflow flags (contact and
constraint buffers, :mod:`wmr_mujoco.batch.buffers`) and the states' finiteness are
checked: an overflow is a :class:`RuntimeError`, a non-finite state a
:class:`~wmr_mujoco.sim.stepping.SimulationDivergedError`, both naming the member.
On a CUDA device ``mujoco_warp.step`` is captured once as a CUDA graph and replayed for
every step (``graph=True``, the default): the host then launches one graph, not the step's
hundreds of kernels, between the copies of the step's controls in and its state out.

MuJoCo Warp computes in float32 (C MuJoCo: float64); its results differ from
``"rollout"``'s by the amounts ``tests/batch/test_parity.py`` measures per robot.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Sequence
from typing import Any

import mujoco
import numpy as np

from wmr_mujoco.batch import buffers, shard, warp_setup
from wmr_mujoco.batch.backend import Backend, full_states
from wmr_mujoco.sim.engine import get_state
from wmr_mujoco.sim.stepping import SimulationDivergedError
from wmr_mujoco.validation.runner import Prepared

#: Steps between two checks of the overflow flags and the states.
CHUNK = 250
#: ``mujoco_warp.OverflowType`` bits that mean a buffer ran out (results wrong), by name:
#: every bit but ITERATIONS and LS_ITERATIONS (the solver's iteration caps, reached without
#: dropping anything, as in C MuJoCo).
OVERFLOW_BITS = ("NEFC", "NJMAX_NNZ", "BROADPHASE", "NARROWPHASE", "CCD", "HFIELD",
                 "CONTACT_MATCH", "NVMAX", "EPA_HORIZON", "TACTILE")

#: Appended to a divergence: what differs from C MuJoCo and where to read about it.
FLOAT32_HINT = ("MuJoCo Warp steps in float32, where a model C MuJoCo runs in float64 can "
                "still diverge (e.g. friction rows far stiffer than the bodies they act on "
                "make Newton's Hessian too ill-conditioned: docs/batch.md, 'Float32 and the "
                "ball casters'); backend='rollout' runs it in float64")


class WarpBackend(Backend):
    """MuJoCo Warp, members sharded over devices.

    Args:
        devices: Warp device names (None: every CUDA device, else ``"cpu"``); a name may
            repeat (more shards on one device).
        probe_steps: steps of the C MuJoCo run that sizes the buffers.
        graph: replay the step as a captured CUDA graph on CUDA devices (no effect on the
            CPU, where Warp has no graphs).
    """

    name = "warp"
    extra = warp_setup.EXTRA

    def __init__(self, devices: Sequence[str] | None = None,
                 probe_steps: int = buffers.PROBE_STEPS, graph: bool = True) -> None:
        if devices is not None and (isinstance(devices, str) or not devices):
            raise ValueError(f"devices = {devices!r}; give a non-empty list of Warp device "
                             "names, e.g. ['cuda:0', 'cuda:1'] or ['cpu']")
        if isinstance(probe_steps, bool) or not isinstance(probe_steps, int) or probe_steps < 0:
            raise ValueError(f"probe_steps = {probe_steps!r}; give an integer >= 0")
        if not isinstance(graph, bool):
            raise ValueError(f"graph = {graph!r}; give True or False")
        self.devices = None if devices is None else list(devices)
        self.probe_steps = probe_steps
        self.graph = graph

    @classmethod
    def installed(cls) -> bool:
        """Whether MuJoCo Warp imports."""
        return warp_setup.installed()

    def check(self, robot: str, models: Sequence[mujoco.MjModel]) -> None:
        """Refuse what MuJoCo Warp cannot run, before any stepping.

        Raises:
            ValueError: PGS solver; a feature ``put_model`` refuses; members whose models
                differ in a field Warp cannot batch per world.
        """
        _, mjw = warp_setup.init()
        if models[0].opt.solver == mujoco.mjtSolver.mjSOL_PGS:
            raise ValueError(f"backend 'warp' cannot run robot {robot!r}: its solver is PGS, "
                             "which MuJoCo Warp does not implement; nearest that works: "
                             "solver Newton or CG, or backend='rollout'")
        with _device("cpu"):
            _batched_fields(robot, mjw, _distinct(models))

    def run(self, preps: Sequence[Prepared]) -> list[np.ndarray]:
        """Each member's states; see :meth:`Backend.run`.

        Raises:
            RuntimeError: a contact or constraint buffer overflowed (member and buffer
                named).
            SimulationDivergedError: a member's state became non-finite.
        """
        warp_setup.init()
        sizes = buffers.measure(preps, self.probe_steps)
        devices = self.devices or warp_setup.devices()
        ranges = shard.split(len(preps), len(devices))
        runs = [_ShardRun([preps[i] for i in r], r.start, dev, sizes, self.graph)
                for r, dev in zip(ranges, devices, strict=False)]
        nstep = len(preps[0].controls)
        self.step_seconds = 0.0
        for k0 in range(0, nstep, CHUNK):
            k1 = min(k0 + CHUNK, nstep)
            start = time.perf_counter()
            for run in runs:
                run.launch(k0, k1)
            for run in runs:
                run.wait()
            self.step_seconds += time.perf_counter() - start
            for run in runs:
                run.collect(k0, k1)
        return shard.join([run.states() for run in runs], ranges)


def _device(name: str) -> Any:
    import warp as wp

    return wp.ScopedDevice(name)


def _distinct(models: Sequence[mujoco.MjModel]) -> list[mujoco.MjModel]:
    out: list[mujoco.MjModel] = []
    for m in models:
        if not any(m is o for o in out):
            out.append(m)
    return out


def _batched_fields(robot: str, mjw: Any, models: Sequence[mujoco.MjModel]) -> list[str]:
    """Model fields that differ between ``models`` (all batchable per world).

    Raises:
        ValueError: ``put_model`` refuses the model, or a differing field cannot be
            batched (named).
    """
    try:
        wms = [mjw.put_model(m) for m in models]
    except (NotImplementedError, ValueError) as err:
        raise ValueError(f"backend 'warp' cannot run robot {robot!r}: MuJoCo Warp refuses "
                         f"its model ({err}); use backend='rollout'") from err
    out = []
    for f in dataclasses.fields(wms[0]):
        values = [getattr(w, f.name) for w in wms]
        if all(_equal(values[0], v) for v in values[1:]):
            continue
        shape = getattr(f.type, "shape", ())
        if not (shape and shape[0] == "*"):
            raise ValueError(f"backend 'warp' cannot vary {f.name!r} between members of robot "
                             f"{robot!r}: MuJoCo Warp shares it across worlds; vary only "
                             "masses, frictions, sizes and the like, or use backend='rollout'")
        out.append(f.name)
    return out


def _equal(a: Any, b: Any) -> bool:
    """Field equality: arrays by value, nested dataclasses field by field."""
    if hasattr(a, "numpy") and hasattr(b, "numpy"):
        x, y = a.numpy(), b.numpy()
        return x.shape == y.shape and bool(np.array_equal(x, y, equal_nan=True))
    if isinstance(a, (tuple, list)) and isinstance(b, (tuple, list)):
        return len(a) == len(b) and all(_equal(x, y) for x, y in zip(a, b, strict=True))
    if dataclasses.is_dataclass(a) and dataclasses.is_dataclass(b):
        return all(_equal(getattr(a, f.name), getattr(b, f.name))
                   for f in dataclasses.fields(a))
    try:
        return bool(a == b)
    except (ValueError, TypeError):  # numpy arrays and the like
        return bool(np.array_equal(np.asarray(a), np.asarray(b)))


class _ShardRun:
    """One device's members: Warp model and data, controls, and the states read back."""

    def __init__(self, preps: list[Prepared], first: int, device: str,
                 sizes: buffers.Buffers, graph: bool = False) -> None:
        import warp as wp

        _, mjw = warp_setup.init()
        self.preps, self.first, self.device = preps, first, device
        self.capture = graph and wp.get_device(device).is_cuda
        self.graph: Any = None
        self.mjw, self.wp = mjw, wp
        base = preps[0]
        nw = len(preps)
        self.initial = [get_state(p.model, p.data) for p in preps]
        nstep = len(base.controls)
        with _device(device):
            models = _distinct([p.model for p in preps])
            names = _batched_fields(base.scenario.robot, mjw, models) if len(models) > 1 else []
            self.m = mjw.put_model(base.model, batch_sizes=dict.fromkeys(names, nw))
            self.m.opt.warn_overflow = 0  # no printing: collect() raises instead
            if names:
                per_model = {id(m): mjw.put_model(m) for m in models}
                for name in names:
                    stacked = np.concatenate([getattr(per_model[id(p.model)], name).numpy()
                                              for p in preps])
                    getattr(self.m, name).assign(stacked)
            self.d = mjw.put_data(base.model, base.data, nworld=nw, nconmax=sizes.nconmax,
                                  njmax=sizes.njmax)
            for field in ("qpos", "qvel", "act", "qacc_warmstart"):
                values = np.stack([getattr(p.data, field) for p in preps])
                if values.shape[1]:
                    getattr(self.d, field).assign(values)
            self.d.time.assign(np.array([p.data.time for p in preps]))
            controls = np.stack([p.controls for p in preps], axis=1)  # (N, nw, nu)
            self.ctrl = wp.array(controls, dtype=self.d.ctrl.dtype)
            sizes_of = {"qpos": base.model.nq, "qvel": base.model.nv, "act": base.model.na}
            self.hist = {f: wp.zeros((min(CHUNK, nstep), nw, n), dtype=getattr(self.d, f).dtype)
                         for f, n in sizes_of.items() if n}
        self.out = {f: np.empty((nstep + 1, nw, n)) for f, n in sizes_of.items()}
        for f in self.out:
            self.out[f][0] = np.stack([getattr(p.data, f) for p in preps])

    def launch(self, k0: int, k1: int) -> None:
        """Queue steps ``k0 .. k1 - 1`` on the device (asynchronous on a GPU)."""
        wp = self.wp
        with _device(self.device):
            for k in range(k0, k1):
                wp.copy(self.d.ctrl, self.ctrl[k])
                self._step()
                for f, h in self.hist.items():
                    wp.copy(h[k - k0], getattr(self.d, f))

    def _step(self) -> None:
        """One ``mujoco_warp.step``: on a CUDA device the replay of its captured graph."""
        if not self.capture:
            self.mjw.step(self.m, self.d)
            return
        if self.graph is None:  # capturing records the kernels without running them
            with self.wp.ScopedCapture() as capture:
                self.mjw.step(self.m, self.d)
            self.graph = capture.graph
        self.wp.capture_launch(self.graph)

    def wait(self) -> None:
        """Wait until the device has done the queued steps."""
        self.wp.synchronize_device(self.device)

    def collect(self, k0: int, k1: int) -> None:
        """Read the chunk's states back (after :meth:`wait`), check overflow and finiteness.

        Raises:
            RuntimeError: a buffer overflowed.
            SimulationDivergedError: a non-finite state.
        """
        flags = self.d.overflow.numpy()
        bad = [name for name in OVERFLOW_BITS
               if np.any(flags & int(getattr(self.mjw.OverflowType, name)))]
        nacon = int(self.d.nacon.numpy()[0])
        if bad or nacon > self.d.naconmax:
            world = int(np.argmax(flags != 0)) if bad else 0
            raise RuntimeError(
                f"MuJoCo Warp buffer overflow ({', '.join(bad) or 'contacts'}) by step {k1} "
                f"in member {self.first + world}: contacts {nacon} of {self.d.naconmax}, "
                f"buffers nconmax {self.d.naconmax // len(self.preps)}, njmax {self.d.njmax} "
                f"per world (wmr_mujoco.batch.buffers: raise MARGIN or SLACK)")
        for f, h in self.hist.items():
            self.out[f][k0 + 1:k1 + 1] = h.numpy()[:k1 - k0]
        for f in ("qpos", "qvel"):
            finite = np.isfinite(self.out[f][k0 + 1:k1 + 1]).all(axis=(0, 2))
            if not finite.all():
                raise SimulationDivergedError(
                    f"member {self.first + int(np.argmin(finite))} of the batch: non-finite "
                    f"{f} by step {k1} (backend 'warp'); {FLOAT32_HINT}")

    def states(self) -> list[np.ndarray]:
        """Each member's full-physics states."""
        return [full_states(p.model, self.initial[j], self.out["qpos"][:, j],
                            self.out["qvel"][:, j], self.out["act"][:, j])
                for j, p in enumerate(self.preps)]
