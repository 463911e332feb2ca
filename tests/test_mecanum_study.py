"""The mecanum design study: one short measurement, the table, the configurations."""

from wmr_mujoco.mecanum_scenarios import MecanumScenario
from wmr_mujoco.mecanum_study import COUNTS, measure, study_configs, table
from wmr_mujoco.params_mecanum import MecanumParams


def test_measure_splits_ramps_and_steps_and_marks_the_default():
    scen = [MecanumScenario("fwd ramp", (0.3, 0.0, 0.0), duration=1.0),
            MecanumScenario("fwd step", (0.3, 0.0, 0.0), duration=1.0, ramp=0.0)]
    s = measure(MecanumParams(), scen, "ellipsoid, 16")
    assert set(s.tracking) == {"ramp", "step"}
    # A step lags more than a ramp of the same run (friction-limited acceleration).
    assert s.tracking["step"][0] > s.tracking["ramp"][0]
    assert 0.0 < s.ripple_pct <= 0.3
    assert "**ellipsoid, 16 (default)**" in table([s], "ellipsoid, 16")


def test_configs_are_shapes_times_counts():
    labels = [label for label, _ in study_configs()]
    assert len(labels) == len(set(labels)) == len(COUNTS) * len(MecanumParams.ROLLER_SHAPES)
