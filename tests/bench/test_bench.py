"""The benchmark code runs and reports sane figures (no timing assertions)."""

import subprocess

import pytest

from wmr_mujoco.bench import bench
from wmr_mujoco.bench.bench import step_speed


def test_step_speed_reports_every_path():
    res = step_speed(["disc", "bicycle"], rounds=1, nstep=200, target_s=0.02)
    assert set(res) == {"disc", "bicycle"}
    for figures in res.values():
        assert set(figures) >= {"loop_steps_per_s", "rollout1_steps_per_s",
                                "rolloutN_steps_per_s", "rollout_speedup", "loop_rtf",
                                "process_ceiling"}
        assert all(v > 0 for v in figures.values())


def test_failed_validate_run_is_an_error_not_a_time(monkeypatch):
    monkeypatch.setattr(bench.subprocess, "run", lambda *a, **k: subprocess.CompletedProcess(
        a, 1, "24 of 25 scenarios pass", "failed: omni3/torque"))
    with pytest.raises(RuntimeError, match="exited with 1: .*failed: omni3/torque"):
        bench.validate_wall_time(1)


def test_missing_peer_is_left_out_not_fatal(tmp_path):
    assert bench.peer_side_by_side(False, tmp_path / "scene.xml") is None
    assert "Left out: the peer model was not found" in bench._peer_section(None)


def test_engine_timing_leaves_measurement_scenarios_to_their_own_runs(monkeypatch):
    """The simulation stage times kinematic/dynamic runs; a measurement scenario (which
    has no adapter to prepare) is timed only in the full validation."""
    import wmr_mujoco.lookup

    spec = bench.get_spec("disc")
    monkeypatch.setattr(wmr_mujoco.lookup, "validation_jobs",
                        lambda: [(spec, spec.scenario("torque")),
                                 (spec, spec.scenario("sliding wheel"))])
    res = bench.validation_engines(1)
    assert all(res[k] > 0 for k in ("all", "sim_loop", "sim_rollout"))


def test_the_bench_says_where_the_peer_came_from(tmp_path):
    from wmr_mujoco.robots.roller_wheels.trials import PeerModel

    row = {"label": "peer", "worst_position_pct": 1.0, "worst_heading_deg": 2.0,
           "real_time_factor": 3.0}
    text = bench._peer_section([row], PeerModel(tmp_path / "scene.xml", "WMR_PEER_SCENE"))
    assert text.startswith("The peer's scene file came from WMR_PEER_SCENE.")
    assert str(tmp_path) not in text  # no path of this machine in the report


@pytest.mark.parametrize("out, match", [
    ("missing/deeper", r"--out '.*missing/deeper': folder '.*missing' does not exist"),
    ("file.txt", r"--out '.*file.txt' is a file"),
])
def test_a_bad_out_folder_is_refused_before_any_work(tmp_path, monkeypatch, out, match):
    import argparse

    (tmp_path / "file.txt").write_text("")

    def worked(*args, **kwargs):
        raise AssertionError("benchmarked before the --out folder was checked")

    monkeypatch.setattr(bench, "step_speed", worked)
    args = argparse.Namespace(quick=True, repeats=1, out=str(tmp_path / out))
    with pytest.raises(ValueError, match=match):
        bench.main(args)
    assert not (tmp_path / "missing").exists()


def test_the_peer_comparison_comes_from_the_registry(tmp_path, monkeypatch):
    """Every robot whose entry carries a ``peer`` is compared; none is named by the bench."""
    import dataclasses

    from wmr_mujoco.robots import ROBOTS

    scene = tmp_path / "scene.xml"
    scene.write_text("<mujoco/>")
    calls = []

    def peer(path, quick):
        calls.append((path, quick))
        return [{"label": "stand-in", "worst_position_pct": 1.0, "worst_heading_deg": 2.0,
                 "real_time_factor": 3.0}]

    fake = {"disc": dataclasses.replace(ROBOTS["disc"], peer=peer)}
    monkeypatch.setattr(bench, "ROBOTS", fake)
    assert bench.peer_side_by_side(True, scene)[0]["label"] == "stand-in"
    assert calls == [(scene, True)]
    monkeypatch.setattr(bench, "ROBOTS", {"disc": ROBOTS["disc"]})
    assert bench.peer_side_by_side(True, scene) is None


def test_goals_section_judges_each_default_and_the_peer_ratio():
    from wmr_mujoco.bench.bench import _goals_section

    speed = {"fast": {"timestep": 0.002, "loop_rtf": 150.0},
             "slow": {"timestep": 0.001, "loop_rtf": 20.0}}
    peer = [{"label": "omni3 (default)", "real_time_factor": 30.0},
            {"label": "peer", "real_time_factor": 10.0}]
    text = _goals_section(speed, peer)
    assert "| fast | 2 ms | 150× | yes |" in text
    assert "| slow | 1 ms | 20× | no |" in text
    assert "3.00× the peer's speed" in text and "not met" in text  # 3 < 5
    assert "peer" not in _goals_section(speed, None)
