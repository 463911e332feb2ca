"""Every drivable robot's "random steps" family (:mod:`wmr_mujoco.validation.floor_family`).

:func:`with_floor_family` adds the family's scenario to a registry entry, built from the
entry alone (its kinematic adapter, command map and command range), for every robot the
family can drive; the registry applies it to each entry.
"""

from __future__ import annotations

import dataclasses

from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.validation import floor_family
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario
from wmr_mujoco.validation.spec import RobotSpec


def _evaluate(s: Scenario, params: RobotParams | None) -> MeasurementResult:
    """Measure one member on the registered robot ``s.robot``."""
    from wmr_mujoco.robots import get_spec

    return floor_family.measure(get_spec(s.robot), s, params)


def with_floor_family(spec: RobotSpec) -> RobotSpec:
    """``spec`` with the random-steps scenario appended.

    Unchanged where the family does not apply or the entry already has it.
    """
    if not floor_family.applies(spec) or any(s.name == floor_family.NAME
                                             for s in spec.scenarios):
        return spec
    scenario = floor_family.scenario(spec.name, _evaluate)
    return dataclasses.replace(spec, scenarios=(*spec.scenarios, scenario))
