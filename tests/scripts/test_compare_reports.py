"""scripts/compare_reports.py: the same figures pass, a changed one is found and sized."""

import importlib.util
import json
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "compare_reports.py"


def _main():
    spec = importlib.util.spec_from_file_location("compare_reports", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.main


def _report(folder: Path, value: float, seconds: float) -> str:
    folder.mkdir()
    (folder / "validation.json").write_text(json.dumps(
        {"scenarios": [{"robot": "disc", "value": value, "seconds": seconds, "ok": True}]}))
    return str(folder)


def test_equal_figures_pass_and_wall_seconds_are_left_out(tmp_path, capsys):
    a = _report(tmp_path / "a", 0.25, 3.0)
    b = _report(tmp_path / "b", 0.25, 9.0)
    assert _main()([a, b]) == 0
    assert "largest relative change 0" in capsys.readouterr().out


def test_a_changed_figure_fails_with_its_relative_change(tmp_path, capsys):
    # 0.25 -> 0.2500001: relative change 1e-7 / 0.2500001 ≈ 4e-7, above the 1e-9 bar.
    a = _report(tmp_path / "a", 0.25, 3.0)
    b = _report(tmp_path / "b", 0.2500001, 3.0)
    assert _main()([a, b]) == 1
    assert "4e-07" in capsys.readouterr().out
