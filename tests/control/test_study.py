"""The table generator of docs/control.md."""

from __future__ import annotations

import pytest

from wmr_mujoco.control import study
from wmr_mujoco.docs_sync.markers import has_markers


def test_doc_has_every_marker():
    for key in ("control tracking", "control whipple", "control lie bracket"):
        assert has_markers(study.DOC, key), key


def test_tracking_row(monkeypatch):
    """One task, one draw: a row with the task and both backends' figures."""
    monkeypatch.setattr(study, "TASKS", (("diffdrive", "kanayama", "circle"),))
    table = study.tracking_table(draws=1)
    row = table.splitlines()[2]
    assert row.startswith("| diffdrive | kanayama | circle |")
    assert row.count("\\|") == 8  # physics | model, worst and median, four columns


def test_bad_draws_exit_2():
    with pytest.raises(SystemExit) as exc:
        study.main(["--no-write", "--draws", "0"])
    assert exc.value.code == 2
