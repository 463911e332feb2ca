"""``python -m wmr_mujoco.bench.render_speed``: its table and its argument checks."""

import pytest

from wmr_mujoco.bench import render_speed


def _figures(encode):
    return {"robot": "omni3", "backend": "egl", "mujoco": "3.17.0", "draw_fps": 26.4,
            "draw_shadows_fps": 15.2, "film_fps": 12.0, "frames": 120, "encode_fps": encode,
            "machine": "x86_64, 2 CPU cores", "gl_vendor": "Mesa", "gl_renderer": "llvmpipe"}


def test_table_names_the_renderer_and_rounds_the_rates():
    text = render_speed.table(_figures(76.4))
    assert 'OpenGL renderer "llvmpipe" (Mesa)' in text
    assert text.splitlines()[-1] == "| 26 | 15 | 12 | 76 |"


def test_table_says_when_no_encoder_was_found():
    assert render_speed.table(_figures(None)).endswith("| no ffmpeg here |")


def test_a_missing_output_folder_is_refused_before_any_work(tmp_path, capsys):
    with pytest.raises(SystemExit) as exc:
        render_speed.main(["--out", str(tmp_path / "missing" / "r.md")])
    assert exc.value.code == 2
    assert "does not exist" in capsys.readouterr().err
