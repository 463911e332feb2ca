"""Progress bars show on a terminal only, and never with --quiet."""

import io
import sys

import pytest

from wmr_mujoco import progress


class Terminal(io.StringIO):
    def isatty(self):
        return True


@pytest.fixture(autouse=True)
def loud():
    progress.configure(False)
    yield
    progress.configure(False)


@pytest.mark.parametrize("stream, quiet, drawn", [
    (Terminal(), False, True), (Terminal(), True, False), (io.StringIO(), False, False)])
def test_a_bar_is_drawn_on_a_terminal_unless_quiet(monkeypatch, stream, quiet, drawn):
    monkeypatch.setattr(sys, "stderr", stream)
    progress.configure(quiet)
    bar = progress.bar(3, "wmr validate", unit="scenario")
    try:
        assert progress.shown() is drawn and bar.disable is not drawn
    finally:
        bar.close()
