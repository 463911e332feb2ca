"""The step models of ``mecanum4``'s grouped step translations, computed together.

A member of the "8 translations (step)" family is eight step commands, each judged
against the stick–slip model's response from rest
(:func:`~wmr_mujoco.robots.mecanum4.kinematics.kinematic_adapter`). :func:`prepare` (the
registry entry's ``prepare``, called with every member of a measurement family before
they run) computes the responses of all the members' runs in one lockstep march
(:func:`~wmr_mujoco.robots.roller_wheels.roller_stick_slip.step_responses`: the same
floats as one at a time) and keeps each until its run's adapter takes it (:func:`take`);
a run not prepared computes its own.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots.mecanum4 import traction
from wmr_mujoco.robots.mecanum4.grouped import Group
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels.roller_stick_slip import StepResponse, step_responses
from wmr_mujoco.validation.scenarios import Scenario

#: Most responses kept at once (each ~0.3 MB; a family's 20 draws of 8 runs is 160).
MAX_READY = 400

_READY: dict[tuple[tuple[float, ...], float, RobotParams | None], StepResponse] = {}


def _key(twist: np.ndarray, duration: float, params: RobotParams | None
         ) -> tuple[tuple[float, ...], float, RobotParams | None]:
    return tuple(np.asarray(twist, float).tolist()), float(duration), params


def step_runs(scenarios: Sequence[Scenario]) -> list[Scenario]:
    """The runs with a step command that the grouped members among ``scenarios`` make.

    A group's member passes its draw to each of its runs (as
    :class:`~wmr_mujoco.robots.mecanum4.grouped.Group` does); runs whose command is not
    a step held over the run (the adapter refuses those) are left out.
    """
    out = []
    for sc in scenarios:
        if not isinstance(sc.evaluate, Group):
            continue
        for run in sc.evaluate.members:
            run = run.member(sc.draw) if sc.draw else run
            twist = run.input_at(0.0)
            if np.any(twist != 0.0) and np.array_equal(run.input_at(run.duration), twist):
                out.append(run)
    return out


def prepare(scenarios: Sequence[Scenario], params: RobotParams | None) -> None:
    """Compute the step responses of the grouped members' runs (module docstring).

    Responses kept from an earlier call are dropped first (its family has run).

    Raises:
        ValueError: more than :data:`MAX_READY` runs at once.
    """
    from wmr_mujoco.robots.mecanum4 import SPEC  # the entry imports this module

    _READY.clear()
    runs = step_runs(scenarios)
    if len(runs) > MAX_READY:
        raise ValueError(f"{len(runs)} step runs to prepare; at most {MAX_READY} at once")
    if not runs:
        return
    model = load(SPEC, params)
    p = params_or_default(params, MecanumParams)
    for duration in sorted({r.duration for r in runs}):
        same = [r for r in runs if r.duration == duration]
        twists = [r.input_at(0.0) for r in same]
        platforms, commands = zip(*(traction.step_platform(model, p, t) for t in twists),
                                  strict=True)
        for twist, response in zip(twists, step_responses(platforms, commands, duration),
                                   strict=True):
            if response is not None:  # else its own run raises and says why
                _READY[_key(twist, duration, params)] = response


def take(twist: np.ndarray, duration: float, params: RobotParams | None
         ) -> StepResponse | None:
    """The prepared response of a step to ``twist`` over ``duration`` (None: not prepared)."""
    return _READY.pop(_key(twist, duration, params), None)
