"""Every robot's scenarios declare their families by the project's rules."""

import pytest

from wmr_mujoco.loop.tasks.families import tracking_name
from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.validation.scenarios import ScenarioKind
from wmr_mujoco.validation.variations import DYNAMIC_DRAWS, KINEMATIC_DRAWS, is_generic

SCENARIOS = [s for spec in ROBOTS.values() for s in spec.scenarios]


@pytest.mark.parametrize("s", [s for s in SCENARIOS if s.kind is not ScenarioKind.MEASUREMENT],
                         ids=lambda s: s.key)
def test_every_signal_driven_scenario_is_a_family(s):
    assert s.family is not None, f"{s.key} declares no family"
    assert all(is_generic(v.name) for v in s.family.vary)
    # Fewer than 20 draws only for a kinematic family (its spread shown small by
    # `python -m wmr_mujoco.bench.family_spread`).
    least = KINEMATIC_DRAWS if s.kind is ScenarioKind.KINEMATIC else DYNAMIC_DRAWS
    assert s.family.draws >= least


@pytest.mark.parametrize("s", [s for s in SCENARIOS if s.family is not None
                               and s.kind is ScenarioKind.MEASUREMENT], ids=lambda s: s.key)
def test_every_measurement_family_has_twenty_draws(s):
    # A closed-loop tracking family is a kinematic controller's claim: it may judge the
    # kinematic families' number where its spread is shown small (family_spread).
    tracking = s.name.startswith(tracking_name("", "").split(":")[0] + ":")
    assert s.family.draws >= (KINEMATIC_DRAWS if tracking else DYNAMIC_DRAWS)
