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
    assert main(["demo", "--quick"]) == 0
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


@pytest.mark.gl  # the OpenGL check comes first (exit 3 where none)
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


@pytest.mark.gl  # the OpenGL check comes first (exit 3 where none)
def test_render_duration_past_the_scenario_needs_hold(tmp_path, capsys):
    out = tmp_path / "a.gif"
    assert main(["render", "disc", "--out", str(out), "--duration", "1000"]) == 2
    assert "valid range is (0, " in capsys.readouterr().err and not out.exists()


def test_demo_is_the_main_job_as_make_demo(monkeypatch, tmp_path):
    """``wmr demo`` is ``make demo``'s ``wmr validate``: every scenario, one report."""
    from wmr_mujoco import cli

    seen = []
    monkeypatch.setattr(cli, "_cmd_validate", lambda args: seen.append(args) or 0)
    assert main(["demo", "--out", str(tmp_path)]) == 0
    assert [(a.robots, a.scenario, a.out) for a in seen] == [([], None, tmp_path)]


def test_version(capsys):
    from wmr_mujoco import __version__

    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0
    assert capsys.readouterr().out.strip() == f"wmr {__version__}"


@pytest.mark.parametrize("typed, meant", [("OMNI3", "omni3"), ("mec", "mecanum4"),
                                          ("Disc", "disc")])
def test_robot_names_any_case_or_a_unique_prefix(capsys, typed, meant):
    assert main(["info", typed]) == 0
    assert capsys.readouterr().out.startswith(f"{meant}: ")


def test_a_misspelt_robot_gets_a_suggestion(capsys):
    assert main(["info", "omin3"]) == 2
    assert "unknown robot 'omin3'; did you mean 'omni3'?" in capsys.readouterr().err


def test_an_ambiguous_prefix_lists_the_robots_it_begins(capsys):
    assert main(["info", "di"]) == 2
    assert "'disc', 'disc_free', 'diffdrive'" in capsys.readouterr().err


@pytest.mark.parametrize("suffix", [".XML", ".Xml"])
def test_info_takes_an_xml_file_in_any_case(tmp_path, capsys, suffix):
    path = tmp_path / f"Scene{suffix}"
    path.write_text('<mujoco><worldbody><geom name="floor" type="plane" size="1 1 .1"/>'
                    "</worldbody></mujoco>")
    assert main(["info", str(path)]) == 0
    assert f"model file {path.name}" in capsys.readouterr().out


def test_info_on_malformed_xml_names_the_file(tmp_path, capsys):
    path = tmp_path / "broken.xml"
    path.write_text("<mujoco><worldbody><body></mujoco>")
    assert main(["info", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"wmr: error: {path}: MuJoCo cannot read this file: XML")
    assert len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("argv", [
    pytest.param(["render", "{f}", "--out", "{d}/a.mp4"], marks=pytest.mark.gl),
    ["validate", "{f}", "--out", "{d}/r"]])
def test_render_and_validate_say_they_take_robot_names_not_files(tmp_path, capsys, argv):
    path = tmp_path / "robot.xml"
    path.write_text("<mujoco/>")
    argv = [a.format(f=path, d=tmp_path) for a in argv]
    assert main(argv) == 2
    assert f"takes robot names (see `wmr list`), not a model file ({path})" in (
        capsys.readouterr().err)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["robot.xml"]


def test_validate_scenario_typed_loosely(tmp_path, monkeypatch, capsys):
    """``translate 45`` is ``translate 45°``; the scenarios chosen reach the runner."""
    from wmr_mujoco.validation import members

    chosen = []

    def fake_run_families(scenarios, **_):
        chosen.extend(s.name for _, s in scenarios)
        raise KeyboardInterrupt  # stop before any work

    monkeypatch.setattr(members, "run_families", fake_run_families)
    assert main(["validate", "omni3", "--scenario", "Translate 45", "--out",
                 str(tmp_path / "r"), "-q"]) == 130
    assert chosen == ["translate 45°"]


def test_a_full_disk_is_one_line_and_exit_5(tmp_path, monkeypatch, capsys):
    """Disk full while the report is written: one line naming the file, exit 5."""
    import errno

    from wmr_mujoco.validation import report

    def full(path, text):
        raise OSError(errno.ENOSPC, "No space left on device", str(path))

    monkeypatch.setattr(report, "write_text_atomic", full)
    assert main(["validate", "disc", "--scenario", "straight", "--out",
                 str(tmp_path / "r"), "-q"]) == 5
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"wmr: I/O error: No space left on device: {tmp_path / 'r'}"
                   "/validation.json"]


def test_a_folder_named_like_a_robot_does_not_make_it_a_file(tmp_path, monkeypatch, capsys):
    (tmp_path / "disc").mkdir()
    monkeypatch.chdir(tmp_path)
    assert main(["info", "disc"]) == 0
    assert capsys.readouterr().out.startswith("disc: ")
