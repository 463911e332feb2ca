"""The mecanum design study: one short measurement, the table, the configurations."""

from wmr_mujoco.bench.mecanum_study import COUNTS, measure, study_configs, study_scenarios, table
from wmr_mujoco.models.params_mecanum import MecanumParams


def test_measure_splits_ramps_and_steps_and_marks_the_default():
    scen = [s for s in study_scenarios(1.0)
            if s.name in ("translate 0° (ramp)", "translate 0° (step)")]
    s = measure(MecanumParams(), scen, "ellipsoid, 16")
    assert set(s.tracking) == {"ramp", "step"}
    # A step lags more than a ramp of the same run (friction-limited acceleration).
    assert s.tracking["step"][0] > s.tracking["ramp"][0]
    assert 0.0 < s.ripple_pct <= 0.3
    assert "**ellipsoid, 16 (default)**" in table([s], "ellipsoid, 16")


def test_configs_are_shapes_times_counts():
    labels = [label for label, _ in study_configs()]
    assert len(labels) == len(set(labels)) == len(COUNTS) * len(MecanumParams.ROLLER_SHAPES)
