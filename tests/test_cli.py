import pytest

from wmr_mujoco.cli import main
from wmr_mujoco.robots import get_spec


def test_list(capsys):
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    for robot in ("disc", "bicycle", "tricycle", "omni3"):
        assert robot in out


def test_info(capsys):
    assert main(["info", "bicycle"]) == 0
    out = capsys.readouterr().out
    assert "total mass: 14.4000 kg" in out and "rear_wheel" in out and "timestep: 0.002" in out


def test_info_of_a_model_without_switchable_actuators(capsys):
    """The Whipple bicycle's motors carry no rate/torque user data: listed, not switched."""
    assert main(["info", "whipple"]) == 0
    out = capsys.readouterr().out
    assert "total mass: 94.0000 kg" in out and "steer_torque" in out
    assert "without rate/torque switching" in out


def test_unknown_robot_is_exit_2(capsys):
    assert main(["info", "segway"]) == 2
    assert "valid robots are" in capsys.readouterr().err


def test_demo(capsys):
    assert main(["demo"]) == 0
    out = capsys.readouterr().out
    assert all(robot in out for robot in ("disc", "bicycle", "tricycle", "omni3"))
    assert "failed" not in out


def test_validate_one_robot_writes_report(tmp_path, capsys):
    assert main(["validate", "disc", "--out", str(tmp_path)]) == 0
    assert (tmp_path / "validation.md").is_file() and (tmp_path / "validation.json").is_file()
    n = len(get_spec("disc").scenarios)
    assert f"{n} of {n} scenarios pass" in capsys.readouterr().out


def test_view_without_display(monkeypatch, capsys):
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    assert main(["view", "disc"]) == 2
    assert "no display" in capsys.readouterr().err


def test_render_bad_size(tmp_path, capsys):
    assert main(["render", "disc", "--out", str(tmp_path / "a.mp4"), "--width", "3"]) == 2
    assert "width = 3" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_parser_rejects_missing_out():
    with pytest.raises(SystemExit):
        main(["render", "disc"])


def test_scenarios_one_line_each(capsys):
    from wmr_mujoco.robots import ROBOTS, get_spec

    assert main(["scenarios", "omni3"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == len(get_spec("omni3").scenarios)
    assert all(line.startswith("omni3  ") for line in lines)
    assert any("square with rotation" in line and "kinematic" in line for line in lines)
    assert main(["scenarios"]) == 0
    assert len(capsys.readouterr().out.splitlines()) == sum(
        len(spec.scenarios) for spec in ROBOTS.values())


def test_info_shows_only_the_parameters_the_robot_uses(capsys):
    assert main(["info", "omni3"]) == 0
    out = capsys.readouterr().out
    assert "wheel_kv" in out and "steer" not in out.split("total mass")[0]
    assert main(["info", "tricycle"]) == 0
    assert "drive.steer_kp" in capsys.readouterr().out


def test_validate_out_is_checked_before_any_work(tmp_path, capsys):
    afile = tmp_path / "report.txt"
    afile.write_text("keep me")
    assert main(["validate", "disc", "--out", str(afile)]) == 2
    err = capsys.readouterr().err
    assert "--out" in err and "is a file; give a folder" in err and "[1/" not in err
    assert afile.read_text() == "keep me"
    assert main(["validate", "disc", "--out", str(tmp_path / "missing" / "dir")]) == 2
    assert "does not exist; create it first" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == [afile]


def test_validate_one_scenario_and_unknown_scenario(tmp_path, capsys):
    assert main(["validate", "disc", "--scenario", "straight", "--quiet",
                 "--out", str(tmp_path)]) == 0
    assert "1 of 1 scenarios pass" in capsys.readouterr().out
    assert main(["validate", "disc", "--scenario", "loop", "--out", str(tmp_path)]) == 2
    assert "no scenario 'loop' for disc; valid: 'straight'" in capsys.readouterr().err


def test_render_duration_past_the_scenario_needs_hold(tmp_path, capsys):
    out = tmp_path / "a.gif"
    assert main(["render", "disc", "--out", str(out), "--duration", "1000"]) == 2
    assert "valid range is (0, " in capsys.readouterr().err and not out.exists()
