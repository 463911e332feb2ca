"""``simulate_batch``: many members of one robot, each with its own inputs and parameters.

Member ``i`` is what ``wmr.simulate(robot, inputs[i], duration, params[i])`` gives: the
same scenario checks, the same settle at rest in C MuJoCo, the same open-loop schedule
(:func:`wmr_mujoco.validation.runner.prepare`); then one batched engine steps every member
(:mod:`wmr_mujoco.batch.rollout`, :mod:`wmr_mujoco.batch.warp_backend`). Members with equal
parameters share one loaded model and one settled start.
"""

from __future__ import annotations

import inspect
from collections.abc import Sequence
from typing import Any

import mujoco
import numpy as np

import wmr_mujoco
from wmr_mujoco.api import Input, _scenario, _sim_trajectory
from wmr_mujoco.batch.backend import Backend
from wmr_mujoco.batch.rollout import RolloutBackend
from wmr_mujoco.batch.trajectory import BatchTrajectory
from wmr_mujoco.batch.warp_backend import WarpBackend
from wmr_mujoco.models.actuation import set_actuation_mode
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import get_spec
from wmr_mujoco.run_limits import check_frame, check_steps, max_memory_default, warn_clipped
from wmr_mujoco.sim.engine import STATE_SPEC
from wmr_mujoco.validation.runner import (
    Prepared,
    check_runnable,
    make_adapter,
    prepare,
    schedule,
)
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.spec import RobotSpec

#: The batched engines by name.
BACKENDS: dict[str, type[Backend]] = {b.name: b for b in (RolloutBackend, WarpBackend)}
#: Engines weighed and not offered, with the reason (the error names it and what to use).
REFUSED: dict[str, str] = {
    "mjx": "MJX's JAX engine (impl='jax') is not offered: issue 27's probe measured it 3 mm "
           "(diffdrive) to 12.5 cm (bicycle) away from C MuJoCo after 500 steps in 64-bit "
           "floats (the engine differs, not the precision), it refuses the implicit "
           "integrator (whipple), keeps a contact slot for every possible pair (omni3: 36 "
           "contacts and 108 rows per world against 3 and 9) and froze on omni3 batches; "
           "use backend='warp' (MuJoCo Warp, the engine MJX's impl='warp' runs, within "
           "microns of C MuJoCo) or 'rollout' (C MuJoCo)",
}
#: The most distinct parameter sets (compiled models) of one call.
MAX_MODELS = 1024
#: The most members of one call (checked before any per-member object is made).
MAX_MEMBERS = 65_536


def installed_backends() -> list[str]:
    """The backends whose packages import here."""
    return [name for name, b in BACKENDS.items() if b.installed()]


def make_backend(backend: str | Backend, **options: Any) -> Backend:
    """A backend by name (``options`` go to its constructor), or the instance given.

    Raises:
        ValueError: unknown or not installed (the message lists the installed ones and
            the extra that installs the missing one), or weighed and refused
            (:data:`REFUSED`: the reason and the backend to use instead).
    """
    if isinstance(backend, Backend):
        if options:
            raise ValueError(f"options {sorted(options)} given with a backend instance; "
                             "give them to its constructor")
        return backend
    cls = BACKENDS.get(backend) if isinstance(backend, str) else None
    if isinstance(backend, str) and backend in REFUSED:
        raise ValueError(f"backend = {backend!r}: {REFUSED[backend]}")
    if cls is None:
        raise ValueError(f"backend = {backend!r}; installed backends: "
                         f"{', '.join(installed_backends())} (all: {', '.join(BACKENDS)})")
    if not cls.installed():
        raise ValueError(f"backend {backend!r} is not installed: pip install "
                         f"'wmr-mujoco[{cls.extra}]'; installed: "
                         f"{', '.join(installed_backends())}")
    valid = [n for n in inspect.signature(cls).parameters if n != "self"]
    unknown = sorted(set(options) - set(valid))
    if unknown:
        raise ValueError(f"backend {backend!r} has no option {', '.join(unknown)}; its options: "
                         f"{', '.join(valid) or 'none'}")
    return cls(**options)


def member_inputs(inputs: object) -> list[Sequence[Input]]:
    """One entry per member: a sequence of channels, or a ``(members, channels)`` array.

    Raises:
        ValueError: not a non-empty sequence of per-member inputs.
    """
    if isinstance(inputs, np.ndarray):
        if inputs.ndim != 2 or inputs.shape[0] == 0:
            raise ValueError(f"inputs has shape {inputs.shape}; give (members, channels), "
                             "one row of constant inputs per member")
        if inputs.shape[0] > MAX_MEMBERS:
            raise ValueError(f"{inputs.shape[0]} members; at most {MAX_MEMBERS} per call: "
                             "split the batch into several calls")
        return [[float(v) for v in row] for row in inputs]
    if isinstance(inputs, (str, bytes)) or not isinstance(inputs, Sequence) or not inputs:
        raise ValueError(f"inputs = {inputs!r}; give one entry per member, each what "
                         "wmr.simulate takes (one number or function of time per channel)")
    if len(inputs) > MAX_MEMBERS:
        raise ValueError(f"{len(inputs)} members; at most {MAX_MEMBERS} per call: split the "
                         "batch into several calls")
    out = []
    for i, member in enumerate(inputs):
        if isinstance(member, np.ndarray) and member.ndim == 1:
            member = [float(v) for v in member]
        if isinstance(member, (str, bytes)) or not isinstance(member, Sequence):
            raise ValueError(f"inputs[{i}] = {member!r}; each member's inputs are a sequence "
                             "of channels (numbers or functions of time)")
        out.append(member)
    return out


def member_params(params: RobotParams | Sequence[RobotParams | None] | None,
                  members: int) -> list[RobotParams | None]:
    """One parameter set (or None) per member.

    Raises:
        ValueError: a sequence of the wrong length.
    """
    if params is None or not isinstance(params, Sequence):
        return [params] * members
    if len(params) != members:
        raise ValueError(f"params has {len(params)} entries for {members} members; give "
                         "one parameter set per member, or one for all")
    return list(params)


def _key(p: RobotParams | None) -> object:
    try:
        hash(p)
    except TypeError:
        return id(p)
    return p


def _check_memory(members: int, nstep: int, model: mujoco.MjModel, nu: int) -> None:
    nstate = mujoco.mj_stateSize(model, STATE_SPEC)
    need = 8 * members * ((nstep + 1) * 2 * nstate + nstep * 2 * max(nu, 1))
    cap = max_memory_default()
    if need > cap:
        raise ValueError(f"{members} members x {nstep} steps would need about "
                         f"{need / 2**30:.1f} GiB, over the memory cap of "
                         f"{cap / 2**30:.3g} GiB; use fewer members or a shorter duration, in "
                         "several calls, or raise the cap with WMR_MAX_MEMORY (e.g. 8G)")


def prepare_members(spec: RobotSpec, scenarios: Sequence[Scenario],
                    params: Sequence[RobotParams | None],
                    backend: Backend) -> list[Prepared]:
    """Load, check, settle and schedule every member (equal parameters: shared model).

    Raises:
        ValueError: the backend cannot run the model, members' models differ in size,
            or the batch would pass the memory cap of :func:`wmr_mujoco.simulate`
            (:func:`~wmr_mujoco.run_limits.max_memory_default`).
    """
    groups: dict[object, list[int]] = {}
    for i, p in enumerate(params):
        groups.setdefault(_key(p), []).append(i)
    if len(groups) > MAX_MODELS:
        raise ValueError(f"{len(groups)} distinct parameter sets, one compiled model each; "
                         f"at most {MAX_MODELS} per call: split the batch into several calls")
    models = {}
    for key, idx in groups.items():
        models[key] = wmr_mujoco.load(scenarios[idx[0]].robot, params[idx[0]])
        adapter = make_adapter(spec, scenarios[idx[0]], models[key], params[idx[0]])
        for i in idx:  # steps, settle and memory of one member; the frame; before any work
            check_steps(scenarios[i], models[key], adapter, None)
            check_frame(scenarios[i], adapter)
    first = next(iter(models.values()))
    sizes = ("nq", "nv", "nu", "na", "nbody", "ngeom")
    for key, m in models.items():
        if any(getattr(m, s) != getattr(first, s) for s in sizes):
            i = groups[key][0]
            raise ValueError(f"member {i}'s model has sizes "
                             f"{ {s: getattr(m, s) for s in sizes} }, member 0's "
                             f"{ {s: getattr(first, s) for s in sizes} }; members of one "
                             "batch must share the model's structure")
    nstep = round(scenarios[0].duration / first.opt.timestep)
    _check_memory(len(scenarios), nstep, first, first.nu)
    backend.check(scenarios[0].robot, list(models.values()))
    out: list[Prepared | None] = [None] * len(scenarios)
    for key, idx in groups.items():
        lead = prepare(spec, scenarios[idx[0]], params[idx[0]], models[key])
        out[idx[0]] = lead
        x0 = lead.adapter.sim_state(lead.model, lead.data)
        for i in idx[1:]:
            adapter = make_adapter(spec, scenarios[i], lead.model, params[i])
            if adapter.mode is not None:
                set_actuation_mode(lead.model, adapter.mode)
            inputs, controls, analytic = schedule(scenarios[i], adapter, x0,
                                                  lead.model.opt.timestep, nstep)
            out[i] = Prepared(spec, scenarios[i], lead.model, lead.data, adapter, inputs,
                              controls, analytic)
    return out  # type: ignore[return-value]


def simulate_batch(robot: str, inputs: Sequence[Sequence[Input]] | np.ndarray,
                   duration: float,
                   params: RobotParams | Sequence[RobotParams | None] | None = None, *,
                   backend: str | Backend = "rollout", kind: ScenarioKind | str = "kinematic",
                   settle: float = 0.5, world_frame: bool = False,
                   **options: Any) -> BatchTrajectory:
    """Drive many members of ``robot`` in MuJoCo at once, each with its own inputs.

    Args:
        robot: a registered robot (``wmr list``).
        inputs: one entry per member, each what :func:`wmr_mujoco.simulate` takes (one
            constant or function of time per channel), or a ``(members, channels)`` array
            of constants.
        duration: seconds after the settle, the same for every member.
        params: one parameter dataclass for all, or one per member (None: the checked-in
            model). ``"warp"`` varies only fields it can batch per world.
        backend: ``"rollout"`` (C MuJoCo, threads; member ``i`` equals
            ``wmr.simulate(robot, inputs[i], duration, params[i])`` exactly) or
            ``"warp"`` (MuJoCo Warp on GPUs, else the CPU; float32), or a
            :class:`~wmr_mujoco.batch.backend.Backend`.
        kind: ``"kinematic"`` (rates) or ``"dynamic"`` (torques).
        settle: seconds at rest first.
        world_frame: the inputs are world rates (robots whose adapter takes them).
        **options: the backend's own (``nthread`` for rollout; ``devices``,
            ``probe_steps`` for warp).

    Returns:
        Every member's trajectory at every step, member first.

    Raises:
        ValueError: unknown or missing backend, robot or kind; bad inputs, duration or
            params; a model the backend cannot run (with the reason) - all before any work.
        SimulationDivergedError: a member's run diverged (named).
        RuntimeError: a Warp buffer overflowed (named).
    """
    engine = make_backend(backend, **options)
    spec = get_spec(robot)
    per_member = member_inputs(inputs)
    scenarios = []
    for i, member in enumerate(per_member):
        try:
            scenarios.append(_scenario(spec.name, member, duration, kind, settle, world_frame))
        except ValueError as err:
            raise ValueError(f"member {i}: {err}") from None
    for i, s in enumerate(scenarios):
        try:
            check_runnable(spec, s)
        except ValueError as err:
            raise ValueError(f"member {i}: {err}") from None
    preps = prepare_members(spec, scenarios, member_params(params, len(scenarios)), engine)
    for prep in preps:
        warn_clipped(prep)
    states = engine.run(preps)
    members = [_sim_trajectory(p, s) for p, s in zip(preps, states, strict=True)]
    return BatchTrajectory(members[0].time, np.stack([t.states for t in members]),
                           np.stack([t.inputs for t in members]), members[0].state_names,
                           members[0].state_units, engine.name)
