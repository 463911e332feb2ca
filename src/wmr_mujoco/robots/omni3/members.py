"""Members of omni3's dynamic families: the run of a drawn scenario, simulated in batches.

A member of a step, torque or coasting family is its scenario's
:class:`~wmr_mujoco.robots.omni3.runs.RunSpec` with the draw applied
(:func:`member_spec`): the wheels' start phase, the command's scale, and for a coast its
speed, yaw rate, coast duration and lead-in ramp. :func:`prepare` simulates many members
in one batch (:func:`~wmr_mujoco.robots.omni3.runs.simulate_runs`: threaded rollouts, one
vectorised hybrid integration) and keeps each run until its ``evaluate`` takes it
(:func:`member_run`); a member not prepared runs on its own.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import replace

from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import Run, RunSpec, cached_runs, simulate_runs
from wmr_mujoco.validation.family import describe
from wmr_mujoco.validation.scenarios import Scenario

#: Most prepared runs kept at once (each ~0.3 MB; a batch larger than this is refused).
MAX_READY = 400

_READY: dict[tuple[RunSpec, OmniParams | None], Run] = {}


def member_spec(scenario: Scenario, base: RunSpec) -> RunSpec:
    """``base`` with the scenario's draw applied (the nominal values where undrawn).

    ``phase`` (deg): every wheel's start angle; ``scale``: the command's factor;
    coasts: ``speed`` (m/s) and ``yaw_rate`` (rad/s) of the lead-in twist, ``coast`` (s)
    its judged duration, ``ramp`` (s) the lead-in's ramp (0: a step).
    """
    if not scenario.draw:
        return base
    name = f"{base.name} [{describe(scenario.draw)}]"
    phase = math.radians(scenario.value("phase", math.degrees(base.phase)))
    if base.lead_in is not None:
        lead = (scenario.value("speed", base.lead_in[0]), base.lead_in[1],
                scenario.value("yaw_rate", base.lead_in[2]))
        return replace(base, name=name, phase=phase, lead_in=lead,
                       duration=scenario.value("coast", base.duration),
                       lead_ramp=scenario.value("ramp", base.lead_ramp))
    scale = scenario.value("scale", 1.0)
    return replace(base, name=name, phase=phase,
                   command=tuple(scale * c for c in base.command))  # type: ignore[arg-type]


def prepare(specs: Iterable[RunSpec], params: OmniParams | None, turning: bool = True
            ) -> None:
    """Simulate the members' runs in one batch and keep them for :func:`member_run`.

    ``turning``: :func:`~wmr_mujoco.robots.omni3.runs.simulate_runs`'s (False: the
    hybrid model before issue 24, for the before/after table).

    Raises:
        ValueError: more than :data:`MAX_READY` runs at once.
    """
    todo = list(dict.fromkeys(s for s in specs if (s, params) not in _READY))
    if len(todo) + len(_READY) > MAX_READY:
        raise ValueError(f"{len(todo)} runs to prepare with {len(_READY)} kept; at most "
                         f"{MAX_READY} at once")
    if todo:
        runs = simulate_runs(todo, params, turning=turning)
        _READY.update({(s, params): runs[s.name] for s in todo})


def member_run(spec: RunSpec, params: OmniParams | None, nominal: tuple[RunSpec, ...]
               ) -> Run:
    """The run of ``spec``: prepared (taken out), nominal (shared batch), or simulated alone."""
    run = _READY.pop((spec, params), None)
    if run is not None:
        return run
    if spec in nominal:
        return cached_runs(nominal, params)[spec.name]
    return simulate_runs((spec,), params)[spec.name]
