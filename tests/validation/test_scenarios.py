"""Scenario data: kinds, measurement hooks and their checks."""

import pytest

from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario, ScenarioKind


def evaluate(scenario, params):
    return MeasurementResult([])


def film(scenario, params):
    yield from ()


def test_a_measurement_may_carry_a_film():
    s = Scenario("r", "m", kind=ScenarioKind.MEASUREMENT, evaluate=evaluate, film=film)
    assert s.film is film


@pytest.mark.parametrize("kwargs, match", [
    ({"kind": "measurement"}, "needs evaluate"),
    ({"evaluate": evaluate}, "takes no evaluate"),
    ({"film": film}, "takes no film"),
])
def test_hooks_belong_to_measurements(kwargs, match):
    with pytest.raises(ValueError, match=match):
        Scenario("r", "k", **kwargs)
