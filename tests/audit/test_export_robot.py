"""``wmr export``: the user's dimensions reach the model; bad settings exit 2 first."""

from __future__ import annotations

import json

import pytest

from wmr_mujoco.audit.errors import AuditInputError
from wmr_mujoco.audit.export_robot import params_with
from wmr_mujoco.cli import main
from wmr_mujoco.robots import get_spec


def test_export_writes_the_folder_and_audits_the_new_radius(tmp_path):
    out = tmp_path / "mine"
    assert main(["export", "diffdrive", "--set", "wheel.radius=0.1", "--out", str(out),
                 "--duration", "0.6", "--no-diagnose", "--draws", "1", "-q"]) == 0
    assert {p.name for p in out.iterdir()} >= {"diffdrive.xml", "scene.xml", "README.md",
                                               "audit"}
    report = json.loads((out / "audit" / "audit.json").read_text())
    # The audit reads the rolling radius from the colliders: the radius the user set.
    assert [w["radius"] for w in report["wheels"] if w["kind"] == "fixed"] == \
        pytest.approx([0.1, 0.1], abs=1e-9)
    assert "| `wheel.radius` | 0.1 |" in (out / "README.md").read_text()


def test_bad_field_names_the_valid_ones():
    with pytest.raises(AuditInputError, match="valid: wheel.radius"):
        params_with(get_spec("diffdrive"), ["wheel.radiu=0.1"])


def test_bad_value_names_the_range(tmp_path, capsys):
    assert main(["export", "diffdrive", "--set", "wheel.radius=-1", "--out",
                 str(tmp_path / "x")]) == 2
    assert "valid range" in capsys.readouterr().err
    assert not (tmp_path / "x").exists()


def test_the_exported_robot_loads_and_validates(tmp_path):
    """The folder written compiles to the robot built from the user's parameters, and
    those parameters meet the robot's own kinematic targets (its arc scenario, judged as
    `wmr validate` judges it: 0.5 % of path, lateral slip)."""
    import mujoco

    import wmr_mujoco as wmr
    from wmr_mujoco.audit.export_robot import export_robot

    from conftest import model_differences

    spec = get_spec("diffdrive")
    settings = ["wheel.radius=0.1", "track=0.5"]
    params = params_with(spec, settings)
    scene = export_robot("diffdrive", settings, tmp_path / "mine")
    assert model_differences(mujoco.MjModel.from_xml_path(str(scene)),
                             wmr.load("diffdrive", params)) == []
    arc = spec.scenario("arc")
    run = wmr.compare("diffdrive", list(arc.inputs), arc.duration, params=params)
    assert run.passed, [r for r in run.metrics if r.passed is False]
