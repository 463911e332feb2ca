"""Generated README sections: replaced between their markers, nothing else touched."""

import pytest

from wmr_mujoco.docs_sync.markers import (
    between,
    fixed,
    has_markers,
    markers,
    publish,
    replace_between,
    study_parser,
)


def test_replace_between_keeps_the_rest(tmp_path):
    begin, end = markers("table")
    path = tmp_path / "README.md"
    path.write_text(f"intro\n{begin}\nold\n{end}\noutro\n")
    replace_between(path, "table", "\nnew | row\n")
    assert path.read_text() == f"intro\n{begin}\nnew | row\n{end}\noutro\n"
    assert has_markers(path, "table") and not has_markers(path, "other")
    assert between(path, "table") == "new | row"
    with pytest.raises(ValueError, match="must hold '<!-- other: begin -->' once"):
        between(path, "other")


@pytest.mark.parametrize("text", ["no markers", "<!-- t: end -->\n<!-- t: begin -->",
                                  "<!-- t: begin -->\n<!-- t: begin -->\n<!-- t: end -->"])
def test_bad_markers_are_refused_and_the_file_kept(tmp_path, text):
    path = tmp_path / "README.md"
    path.write_text(text)
    with pytest.raises(ValueError, match="must hold '<!-- t: begin -->' once"):
        replace_between(path, "t", "x")
    assert path.read_text() == text


def test_fixed_cells():
    assert (fixed(1.23456), fixed(1.23456, 3), fixed(2.5, 0)) == ("1.23", "1.235", "2")
    assert fixed(float("nan")) == fixed(float("inf")) == "n/a"


def test_publish_prints_always_and_pastes_only_when_asked(tmp_path, capsys):
    doc = tmp_path / "README.md"
    original = ("a\n<!-- t1: begin -->\nold\n<!-- t1: end -->\nb\n"
                "<!-- t2: begin -->\n<!-- t2: end -->\n")
    doc.write_text(original)
    tables = {"t1": "| new |", "t2": "| two |"}
    assert study_parser("x").parse_args(["--no-write"]).no_write
    publish(doc, tables, write=False)
    assert doc.read_text() == original and "| new |\n\n| two |" in capsys.readouterr().out
    publish(doc, tables, write=True)
    assert doc.read_text() == ("a\n<!-- t1: begin -->\n| new |\n<!-- t1: end -->\nb\n"
                               "<!-- t2: begin -->\n| two |\n<!-- t2: end -->\n")
    assert f"wrote {doc}" in capsys.readouterr().out
