"""The measurement-cost benchmark: its choice of scenarios and its refusals."""

import pytest

from wmr_mujoco.bench import measure_cost


def test_a_robot_alone_is_its_first_kinematic_scenario_and_one_is_timed(capsys):
    robot, scenario = measure_cost._scenario("omni3_reduced")
    assert robot == "omni3_reduced" and scenario.kind.value == "kinematic"
    measure_cost.main(["omni3_reduced", "--repeat", "2"])
    out = capsys.readouterr().out
    assert out.startswith(f"omni3_reduced/{scenario.name}: measurement CPU median ")
    assert "(2 runs)" in out


@pytest.mark.parametrize("argv, match", [
    (["nosuch"], "unknown robot 'nosuch'"),
    (["omni3/nosuch"], "no scenario 'nosuch'"),
    (["omni3/slip onset"], "is a measurement scenario"),
    (["--repeat", "0"], "--repeat 0: must be at least 1"),
])
def test_bad_input_is_refused_before_any_run(argv, match, capsys):
    with pytest.raises(SystemExit) as err:
        measure_cost.main(argv)
    assert err.value.code == 2
    assert match in capsys.readouterr().err
