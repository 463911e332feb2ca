"""The docs' result and benchmark sections are pasted from the reports."""

import json

import pytest

from wmr_mujoco.docs_sync.markers import markers
from wmr_mujoco.docs_sync.readme_sync import PAGES, SECTIONS, main, section_text, sync
from wmr_mujoco.models.paths import REPO_ROOT


def test_the_docs_have_every_section():
    for key in SECTIONS:
        text = (REPO_ROOT / PAGES[key]).read_text()
        begin, end = markers(key)
        assert text.count(begin) == 1 and text.count(end) == 1


def _pages(root):
    """The generated pages under ``root``, each with its sections' markers around "old"."""
    for page in set(PAGES.values()):
        (root / page).parent.mkdir(parents=True, exist_ok=True)
        (root / page).write_text("\n".join(f"{b}\nold\n{e}" for k in SECTIONS
                                           if PAGES[k] == page for b, e in [markers(k)]))


def _text(root):
    return "\n".join((root / page).read_text() for page in sorted(set(PAGES.values())))


def test_section_text_demotes_headings():
    assert section_text("# Benchmarks\n\nintro\n\n## Speed\n| a |") == "intro\n\n#### Speed\n| a |"


def _complete(reports, quick=False, peer=True):
    """The JSON beside full reports: every scenario run, a full bench with the peer."""
    (reports / "validation.json").write_text(json.dumps({"complete": True, "missing": []}))
    (reports / "bench.json").write_text(json.dumps({"quick": quick,
                                                    "peer": [{}] if peer else None}))


def test_sync_pastes_each_report(tmp_path):
    _pages(tmp_path)
    reports = tmp_path / "reports"
    reports.mkdir()
    (reports / "summary.md").write_text("| robot | pass |\n|---|---|\n| disc | pass |\n")
    (reports / "bench.md").write_text("# Benchmarks\n\n## Speed\n\n| x |\n")
    (reports / "open.md").write_text("| omni3 | torque rotate | open |\n")
    (reports / "families.md").write_text("| disc | straight | 5 |\n")
    _complete(reports)
    assert sync(tmp_path, reports) == list(SECTIONS)
    text = _text(tmp_path)
    assert "old" not in text and "| disc | pass |" in text and "#### Speed" in text
    assert "| omni3 | torque rotate | open |" in text and "| disc | straight | 5 |" in text


def test_missing_report_names_the_command(tmp_path, capsys):
    with pytest.raises(FileNotFoundError, match="`make demo` writes it"):
        sync(tmp_path, tmp_path)
    assert main(["--root", str(tmp_path), "--reports", str(tmp_path)]) == 2
    assert "summary.md not found" in capsys.readouterr().err


def test_only_the_sections_asked_for_and_nothing_when_one_is_missing(tmp_path):
    _pages(tmp_path)
    original = _text(tmp_path)
    (tmp_path / "summary.md").write_text("| new |\n")
    (tmp_path / "open.md").write_text("No open targets.\n")
    (tmp_path / "families.md").write_text("| families |\n")
    _complete(tmp_path)
    with pytest.raises(FileNotFoundError, match="`make bench` writes it"):
        sync(tmp_path, tmp_path)
    assert _text(tmp_path) == original  # nothing written when a report is missing
    assert sync(tmp_path, tmp_path, ["validation results"]) == ["validation results"]
    assert _text(tmp_path).count("old") == 3 and "| new |" in _text(tmp_path)
    with pytest.raises(ValueError, match="unknown sections"):
        sync(tmp_path, tmp_path, ["results"])


def _refused(tmp_path, capsys):
    _pages(tmp_path)
    original = _text(tmp_path)
    assert main(["--root", str(tmp_path), "--reports", str(tmp_path)]) == 2
    assert _text(tmp_path) == original
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    return err


def _reports(tmp_path, summary="| disc | pass |\n", bench="# Benchmarks\n\n| x |\n"):
    (tmp_path / "summary.md").write_text(summary)
    (tmp_path / "open.md").write_text("No open targets.\n")
    (tmp_path / "families.md").write_text("| families |\n")
    (tmp_path / "bench.md").write_text(bench)


def test_a_quick_validation_report_is_refused(tmp_path, capsys):
    """Fewer draws than the families declare (``wmr validate --quick``): not for the docs."""
    _reports(tmp_path)
    _complete(tmp_path)
    doc = json.loads((tmp_path / "validation.json").read_text())
    (tmp_path / "validation.json").write_text(json.dumps({**doc, "quick": True}))
    assert "is from a quick run" in _refused(tmp_path, capsys)


def test_a_partial_validation_report_is_refused(tmp_path, capsys):
    _reports(tmp_path)
    _complete(tmp_path)
    (tmp_path / "validation.json").write_text(json.dumps(
        {"complete": False, "missing": ["disc/straight", "omni3/rotate"]}))
    err = _refused(tmp_path, capsys)
    assert "is partial (not run: disc/straight, omni3/rotate); run `make demo`" in err


def test_a_validation_report_without_its_json_is_refused(tmp_path, capsys):
    _reports(tmp_path)
    _complete(tmp_path)
    (tmp_path / "validation.json").unlink()
    assert "partial" in _refused(tmp_path, capsys)


@pytest.mark.parametrize("quick, peer, match", [
    (True, True, "is from `wmr bench --quick`"),
    (False, False, "is partial (the peer model was not found)"),
])
def test_a_quick_or_partial_bench_is_refused(tmp_path, capsys, quick, peer, match):
    _reports(tmp_path)
    _complete(tmp_path, quick=quick, peer=peer)
    assert match in _refused(tmp_path, capsys)


def test_a_report_with_a_path_of_this_machine_is_refused(tmp_path, capsys):
    _reports(tmp_path, bench="Left out: not found at `/home/me/shared/scene.xml`.\n")
    _complete(tmp_path)
    assert "names a path of this machine ('`/home/me/shared/scene.xml')" in _refused(
        tmp_path, capsys)


def test_units_with_slashes_are_not_paths(tmp_path):
    _reports(tmp_path, bench="1.5 m/s, 3 rad/s, N·m·s/rad, steps/s\n")
    _complete(tmp_path)
    _pages(tmp_path)
    assert sync(tmp_path, tmp_path) == list(SECTIONS)
