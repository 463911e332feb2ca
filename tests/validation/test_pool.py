"""Families over a process pool: the same results, in the same order, as one process."""

import json

import numpy as np
import pytest

from wmr_mujoco.cli import main
from wmr_mujoco.lookup import validation_jobs
from wmr_mujoco.validation import jobs, pool
from wmr_mujoco.validation.jobs import check_jobs
from wmr_mujoco.validation.members import run_families
from wmr_mujoco.validation.pool import attach, detach, hand_out_order

needs_fork = pytest.mark.skipif(not pool.can_fork(), reason="no 'fork' start method here")


def _same(a, b, trace=True):
    """Rows, errors, seeds and the family's trace equal; members likewise, traceless.

    ``b`` came through a worker: its members carry no trace (``Detached``), the family's
    own is its worst member's.
    """
    assert a.scenario == b.scenario
    assert a.rows == b.rows and a.error == b.error and a.seed == b.seed
    for name, x in a.trace.arrays().items():
        if trace:
            np.testing.assert_array_equal(x, b.trace.arrays()[name], err_msg=name)
        else:
            assert b.trace.arrays()[name].size == 0, name
    assert len(a.members) == len(b.members)
    for m, n in zip(a.members, b.members, strict=True):
        _same(m, n, trace=False)


@needs_fork
def test_two_jobs_give_the_results_of_one_in_declared_order():
    """single_steer's families (2 draws each): bit-identical across process counts.

    Exact equality, no tolerance: a family's draws, model and run do not depend on the
    process that runs it, and the worker sends back the very floats it computed.
    """
    work = validation_jobs(["single_steer"])
    seen_one, seen_two = [], []
    one = run_families(work, draws=2, jobs=1, on_result=seen_one.append)
    lines = []
    two = run_families(work, draws=2, jobs=2, on_result=seen_two.append,
                       progress=lines.append)
    assert [r.scenario.key for r in two] == [s.key for _, s in work]
    for a, b in zip(one, two, strict=True):
        _same(a, b)
        assert b.seconds is not None and b.seconds > 0
    assert sorted(r.scenario.key for r in seen_two) == sorted(s.key for _, s in work)
    # one progress line per family, numbered by completion
    numbered = [line.split("] ")[0] for line in lines if line.startswith("[")]
    assert numbered == [f"[{k}/{len(work)}" for k in range(1, len(work) + 1)]


def test_detach_and_attach_give_back_the_result():
    work = validation_jobs(["single_steer"])
    spec, s = work[0]
    (res,) = run_families([(spec, s)], draws=2, jobs=1)
    back = attach(detach(res), s)
    _same(res, back)
    assert [m.scenario.draw for m in back.members] == [m.scenario.draw for m in res.members]
    # the family's trace is one of its members' (the worst's), and it survives
    assert any(m.trace is res.trace for m in res.members)
    assert back.trace.arrays()["time"].size > 1


def test_hand_out_order_puts_unknown_first_then_longest():
    work = validation_jobs(["single_steer"])
    keys = [s.key for _, s in work]
    assert hand_out_order(work, None) == list(range(len(work)))
    hints = {keys[0]: 1.0, keys[1]: 5.0}
    assert hand_out_order(work, hints) == [*range(2, len(work)), 1, 0]


def test_time_hints_read_an_earlier_report(tmp_path):
    assert pool.time_hints(tmp_path) == {}
    (tmp_path / "validation.json").write_text(json.dumps({"scenarios": [
        {"robot": "a", "scenario": "b", "seconds": 2.5},
        {"robot": "a", "scenario": "c", "seconds": None}]}))
    assert pool.time_hints(tmp_path) == {"a/b": 2.5}
    (tmp_path / "validation.json").write_text("not json")
    assert pool.time_hints(tmp_path) == {}


@pytest.mark.parametrize("bad", [0, -1, True, 1.5, "2", jobs.MAX_JOBS + 1])
def test_a_bad_job_count_is_refused(bad):
    with pytest.raises(ValueError, match="jobs"):
        check_jobs(bad)
    with pytest.raises(ValueError, match="jobs"):
        run_families(validation_jobs(["single_steer"]), jobs=bad)


@pytest.mark.parametrize("text", ["0", "-2", "x", str(jobs.MAX_JOBS + 1)])
def test_a_bad_jobs_option_is_exit_2_before_any_work(tmp_path, capsys, text):
    out = tmp_path / "r"
    with pytest.raises(SystemExit) as exit_:
        main(["validate", "single_steer", "--out", str(out), "--jobs", text])
    assert exit_.value.code == 2
    assert "--jobs" in capsys.readouterr().err
    assert not out.exists()


def test_jobs_reach_the_runner_default_the_usable_cores(tmp_path, monkeypatch):
    from wmr_mujoco.validation import members

    seen = []

    def fake(work, **kwargs):
        seen.append(kwargs["jobs"])
        raise KeyboardInterrupt  # stop before any work

    monkeypatch.setattr(members, "run_families", fake)
    out = str(tmp_path / "r")
    assert main(["validate", "single_steer", "--out", out, "-q"]) == 130
    assert main(["validate", "single_steer", "--out", out, "-q", "--jobs", "3"]) == 130
    assert seen == [min(jobs.usable_cores(), jobs.MAX_JOBS), 3]


def test_run_calls_keep_the_order():
    calls = [(divmod, (n, 3)) for n in range(7)]
    assert pool.run_calls(calls, 2) == [divmod(n, 3) for n in range(7)]
    assert pool.run_calls(calls, 1) == [divmod(n, 3) for n in range(7)]


@needs_fork
def test_a_report_drawn_in_two_processes_is_the_same(tmp_path):
    """The report's text and its plots' files do not depend on the processes drawing them."""
    from wmr_mujoco.robots import ROBOTS
    from wmr_mujoco.validation.report import write_report

    results = run_families(validation_jobs(["single_steer"]), draws=2, jobs=1)
    for r in results:
        r.seconds = 1.0  # the one figure that differs between runs
    one, two = tmp_path / "one", tmp_path / "two"
    write_report(results, one, robots=ROBOTS, jobs=1)
    write_report(results, two, robots=ROBOTS, jobs=2)
    files = sorted(p.relative_to(one) for p in one.rglob("*") if p.is_file())
    assert files == sorted(p.relative_to(two) for p in two.rglob("*") if p.is_file())
    assert any(f.suffix == ".png" for f in files)
    for f in files:
        if f.suffix != ".png":
            assert (one / f).read_text() == (two / f).read_text(), f


@needs_fork
def test_workers_draw_the_figures_the_report_would_draw(tmp_path):
    """With ``draw``, each family comes back from its worker with its figure: the very
    bytes drawn for the in-process result; and the whole report (text, JSON, every PNG)
    is the one a run in one process writes."""
    from wmr_mujoco.robots import ROBOTS
    from wmr_mujoco.validation.plots import scenario_png
    from wmr_mujoco.validation.report import write_report

    work = validation_jobs(["single_steer"])
    one = run_families(work, draws=2, jobs=1)
    two = run_families(work, draws=2, jobs=2, draw=scenario_png)
    assert all(r.figure is None for r in one)
    for a, b in zip(one, two, strict=True):
        assert b.figure is not None and b.figure == scenario_png(a)
        a.seconds = b.seconds = 1.0  # the one figure that differs between runs
    write_report(one, tmp_path / "one", robots=ROBOTS, jobs=1)
    write_report(two, tmp_path / "two", robots=ROBOTS, jobs=2)
    files = sorted(p.relative_to(tmp_path / "one") for p in (tmp_path / "one").rglob("*")
                   if p.is_file())
    assert any(f.suffix == ".png" for f in files)
    assert files == sorted(p.relative_to(tmp_path / "two")
                           for p in (tmp_path / "two").rglob("*") if p.is_file())
    for f in files:
        assert (tmp_path / "one" / f).read_bytes() == (tmp_path / "two" / f).read_bytes(), f


def test_the_report_writes_the_figures_the_run_drew(tmp_path, monkeypatch):
    """A drawn figure's bytes (a sentinel here) are written as they are, not drawn again."""
    from wmr_mujoco.robots import ROBOTS
    from wmr_mujoco.validation import plots
    from wmr_mujoco.validation.report import plot_path, write_report

    results = run_families(validation_jobs(["single_steer"]), draws=2, jobs=1,
                           draw=lambda r: b"sentinel " + r.scenario.key.encode())

    def no_drawing(*_):
        raise AssertionError("drawn again")

    monkeypatch.setattr(plots, "trace_png", no_drawing)
    write_report(results, tmp_path, robots=ROBOTS, jobs=1)
    for r in results:
        assert plot_path(tmp_path, r.scenario).read_bytes() == r.figure


@pytest.mark.parametrize("n_jobs", [1, pytest.param(2, marks=needs_fork)])
def test_a_figure_that_fails_to_draw_is_left_to_the_report(tmp_path, n_jobs):
    """A failed drawing is said (from the worker too) and the report draws the figure."""
    from wmr_mujoco.robots import ROBOTS
    from wmr_mujoco.validation.report import plot_path, write_report

    work = validation_jobs(["single_steer"])[:2]
    notes = []

    def broken(result):
        raise RuntimeError("no fonts")

    results = run_families(work, draws=2, jobs=n_jobs, draw=broken, progress=notes.append)
    assert all(r.figure is None and r.passed for r in results)
    failed = [n for n in notes if "drawing its figure failed" in n and "no fonts" in n]
    assert len(failed) == len(work)
    write_report(results, tmp_path, robots=ROBOTS, jobs=1)
    for r in results:
        assert plot_path(tmp_path, r.scenario).read_bytes().startswith(b"\x89PNG")
