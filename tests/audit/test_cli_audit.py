"""``wmr audit`` exit codes and report files."""

from __future__ import annotations

import json

from wmr_mujoco.cli import main

from .conftest import DIFF, LEGS


def test_audit_writes_its_report_and_exits_0(write, tmp_path, capsys):
    out = tmp_path / "report"
    assert main(["audit", str(write(DIFF)), "--out", str(out), "--duration", "0.6",
                 "--no-diagnose", "--draws", "1", "-q"]) == 0
    report = json.loads((out / "audit.json").read_text())
    assert report["class"] == [2, 0]
    assert {m["name"] for m in report["manoeuvres"]} == {"straight", "arc", "spin"}
    assert (out / "path_arc.png").stat().st_size > 0
    assert "class (2,0)" in capsys.readouterr().out


def test_not_wheeled_exits_4_without_traceback(write, capsys):
    assert main(["audit", str(write(LEGS)), "-q"]) == 4
    err = capsys.readouterr().err
    assert "not a wheeled robot" in err and "Traceback" not in err


def test_bad_input_exits_2(tmp_path, capsys):
    assert main(["audit", str(tmp_path / "missing.xml")]) == 2
    assert "no such file" in capsys.readouterr().err
    assert main(["audit", str(tmp_path), "--duration", "0"]) == 2


def test_out_parent_must_exist_checked_before_work(write, tmp_path, capsys):
    assert main(["audit", str(write(DIFF)), "--out", str(tmp_path / "a" / "b")]) == 2
    assert "does not exist" in capsys.readouterr().err


def test_registering_the_commands_does_not_import_mujoco():
    import subprocess
    import sys

    code = ("import sys, wmr_mujoco.cli as c; c.build_parser(); "
            "sys.exit('mujoco' in sys.modules)")
    assert subprocess.run([sys.executable, "-c", code]).returncode == 0
