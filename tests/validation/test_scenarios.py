"""Scenario data: kinds, measurement hooks and their checks."""

import mujoco
import pytest

from wmr_mujoco.validation.metrics import Metric, Series
from wmr_mujoco.validation.scenarios import (
    MeasurementResult,
    Scenario,
    ScenarioKind,
    free_run,
)
from wmr_mujoco.validation.signals import const


def evaluate(scenario, params):
    return MeasurementResult([])


def film(scenario, params):
    yield from ()


def test_every_robot_has_its_scenarios():
    from wmr_mujoco.lookup import validation_jobs

    scenarios = [s for _, s in validation_jobs()]
    names = {s.key for s in scenarios}
    assert len(names) == len(scenarios), "scenario names must be unique per robot"
    # The robots validated since the first release keep their scenarios; every robot added
    # since brings its own (the registry test checks a spec's scenarios belong to it).
    assert {s.robot for s in scenarios} >= {"disc", "bicycle", "tricycle", "omni3"}
    assert "disc" in {s.robot for s in scenarios if s.kind is ScenarioKind.DYNAMIC}
    # omni3's torque inputs are judged against its hybrid model (measurement scenarios).
    assert {s.name for s in scenarios if s.robot == "omni3"
            and s.kind is ScenarioKind.MEASUREMENT} >= {"torque along x", "slip onset"}
    assert sum(s.name.startswith("translate ") for s in scenarios) >= 8


def test_selection_and_bad_robot():
    from wmr_mujoco.lookup import validation_jobs

    assert all(s.robot == "bicycle" for _, s in validation_jobs(["bicycle"]))
    assert [s.name for _, s in validation_jobs(["disc"], ["torque"])] == ["torque"]
    with pytest.raises(ValueError, match="unknown robot 'tank'"):
        validation_jobs(["tank"])
    with pytest.raises(ValueError, match="no scenario 'fly' for disc; valid: "):
        validation_jobs(["disc"], ["fly"])


def test_kind_from_its_string_and_bad_kind():
    assert Scenario("disc", "a", (const(1.0),), kind="dynamic").kind is ScenarioKind.DYNAMIC
    with pytest.raises(ValueError, match="unknown scenario kind 'static'; valid scenario "
                                         "kinds are: kinematic, dynamic, measurement"):
        Scenario("disc", "a", kind="static")


def test_measurement_scenarios_carry_their_evaluate():
    def evaluate_one(scenario, params):
        return MeasurementResult([Metric("x", 1.0, "m")], [Series("x", [0, 1], [0, 1])])

    s = Scenario("disc", "m", kind=ScenarioKind.MEASUREMENT, evaluate=evaluate_one)
    assert s.evaluate(s, None).metrics[0].value == 1.0


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


def test_free_run_films_one_uncontrolled_run_from_its_start_state():
    """A free body thrown upwards at 1 m/s (the free disc, set above the floor): the film
    steps it for the scenario's duration with the controls at zero, one frame per step,
    and its height follows z0 + v t − g t²/2 until it lands (no contact before)."""
    from wmr_mujoco import load

    def start(model, data, params):
        data.qpos[2] = 1.0
        data.qvel[2] = 1.0
        mujoco.mj_forward(model, data)

    s = Scenario("disc_free", "throw", kind=ScenarioKind.MEASUREMENT, evaluate=evaluate,
                 film=free_run(start, lambda p: load("disc_free", p)), duration=0.2,
                 settle=0.0)
    frames = list(s.film(s, None))
    model = frames[0].model
    assert len(frames) == round(0.2 / model.opt.timestep)
    assert all(f.data is frames[0].data for f in frames), "one run, one data"
    data = frames[-1].data
    g = -model.opt.gravity[2]
    t = data.time
    # RK4 (the free disc's integrator) is exact for a parabola up to round-off.
    assert data.qpos[2] == pytest.approx(1.0 + t - 0.5 * g * t**2, abs=1e-9)


@pytest.mark.parametrize(("field", "value"), [("duration", 0.0), ("settle", -1.0)])
def test_bad_times_are_refused(field, value):
    with pytest.raises(ValueError, match=f"disc/a: {field} = "):
        Scenario("disc", "a", (const(1.0),), **{field: value})


@pytest.mark.parametrize(("robot", "name"), [("omni3", "square with rotation"),
                                             ("diffdrive", "figure eight"),
                                             ("disc", "torque")])
def test_inputs_on_the_grid_are_input_at_bit_for_bit(robot, name):
    """The schedule's inputs at once are the floats of ``input_at`` one time at a time.

    Exact equality: the same signal calls at the same times, the draw's factors and the
    lead-in envelope multiplied in the same order (members with drawn lead-ins and
    scales, and the nominal run).
    """
    import numpy as np

    from wmr_mujoco.robots import get_spec

    s = get_spec(robot).scenario(name)
    dt, n = 0.002, 700
    for m in [s, *s.members(0, 4)]:
        want = np.array([m.input_at(k * dt) for k in range(n)])
        np.testing.assert_array_equal(m.inputs_on(n, dt), want)
    assert robot != "disc" or all(m.draw["lead-in"] > 0 for m in s.members(0, 4))
