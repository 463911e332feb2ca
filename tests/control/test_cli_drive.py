"""``wmr drive``: checks before any work, figures printed, the plot written atomically."""

from __future__ import annotations

import pytest

from wmr_mujoco.cli import main as cli_main


def main(argv: list[str]) -> int:
    """The exit code, whether argparse exits (bad choices) or main returns."""
    try:
        return cli_main(argv)
    except SystemExit as exc:
        return int(exc.code)


@pytest.mark.parametrize(("argv", "names"), [
    (["diffdrive", "--controller", "mpc", "--path", "line"], "pure_pursuit"),
    (["diffdrive", "--controller", "stanley", "--path", "spiral"], "figure_eight"),
])
def test_unknown_names_exit_2_listing_the_valid_ones(argv, names, tmp_path, capsys):
    assert main(["drive", *argv, "--out", str(tmp_path)]) == 2
    assert names in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("argv", [
    ["omni3", "--controller", "stanley"],                       # a car law on omni3
    ["nosuchrobot", "--controller", "stanley"],
    ["diffdrive", "--controller", "stanley", "--seed", "-1"],
    ["diffdrive", "--controller", "stanley", "--out", "/no/such/folder"],
    ["diffdrive", "--controller", "stanley", "--clip"],         # a clip needs --out
    ["diffdrive", "--controller", "whipple_lean"],
])
def test_bad_input_exits_2(argv, capsys):
    assert main(["drive", *argv]) == 2
    assert "error" in capsys.readouterr().err


def test_runs_both_backends_and_writes_the_plot(tmp_path, capsys):
    """Kanayama on the circle: both columns printed, a PNG and nothing else in the folder.
    The closed loop corrects the 0.1 m start offset: the final position errors are under
    the 0.5 % of the 12.6 m lap that the diffdrive's open-loop target allows (63 mm)."""
    assert main(["drive", "diffdrive", "--controller", "kanayama", "--path", "circle",
                 "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    row = next(line for line in out.splitlines() if line.startswith("final position"))
    physics, model = (float(x) for x in row.split()[-2:])
    assert physics < 0.063 and model < 0.063
    assert [p.name for p in tmp_path.iterdir()] == ["drive.png"]
    assert (tmp_path / "drive.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_whipple_upright(tmp_path, capsys):
    """At 2 m/s the uncontrolled bicycle falls within the 10 s, the LQR keeps it up."""
    assert main(["drive", "whipple", "--controller", "whipple_lean", "--speed", "2",
                 "--out", str(tmp_path)]) == 0
    lines = capsys.readouterr().out.splitlines()
    free = next(line for line in lines if line.startswith("none"))
    held = next(line for line in lines if line.startswith("LQR"))
    assert float(free.split()[1]) < 10.0
    assert float(held.split()[1]) == pytest.approx(10.0)
    assert (tmp_path / "drive.png").is_file()
