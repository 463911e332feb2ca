"""Validation report: a table on the terminal, Markdown with PNG plots, and JSON.

Every file is written atomically (temporary file, then rename), so an interrupted or
failed run never leaves a half-written report.
"""

from __future__ import annotations

import json
import math
import multiprocessing
import os
import re
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from wmr_mujoco.analytic.planar import wrap_angle
from wmr_mujoco.atomic import atomic_path, write_text_atomic
from wmr_mujoco.validation.metrics import DEFINITIONS, Row, Series, Trace
from wmr_mujoco.validation.runner import ScenarioResult

if TYPE_CHECKING:
    from matplotlib.axes import Axes

#: Default output folder of ``wmr validate``.
REPORTS_DIR = Path("reports")


def _fmt(value: float) -> str:
    if not math.isfinite(value):
        return "n/a"
    if value == 0 or 1e-3 <= abs(value) < 1e5:
        return f"{value:.4g}"
    return f"{value:.3e}"


def _verdict(row: Row) -> str:
    return row.verdict


def summary_line(results: Sequence[ScenarioResult]) -> str:
    """``N of M scenarios pass; K targets open (...)``: open targets counted, not judged."""
    failed = [r for r in results if not r.passed]
    opened = [r for res in results for r in res.rows if r.open]
    line = f"{len(results) - len(failed)} of {len(results)} scenarios pass"
    if opened:
        met = sum(r.verdict == "open (met)" for r in opened)
        line += (f"; {len(opened)} targets open (shown with their figures, not judged"
                 f"{f'; {met} of them now met' if met else ''})")
    return line


def text_table(results: Sequence[ScenarioResult], judged_only: bool = False) -> str:
    """Fixed-width table: robot, scenario, metric, value, target, pass (open rows shown)."""
    rows = [r for res in results for r in res.rows
            if not judged_only or r.passed is not None or r.open]
    header = ("robot", "scenario", "metric", "value", "target", "pass")
    body = [(r.robot, r.scenario, r.metric, f"{_fmt(r.value)} {r.unit}".strip(),
             "" if r.target is None else f"≤ {_fmt(r.target)} {r.unit}".strip(),
             _verdict(r) + (f" ({r.note})" if r.note and (r.passed is False or r.open)
                            else ""))
            for r in rows]
    widths = [max(len(x[i]) for x in [header, *body]) for i in range(len(header))]
    lines = ["  ".join(h.ljust(w) for h, w in zip(header, widths, strict=True))]
    lines += ["  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)) for row in body]
    return "\n".join(lines)


def _cell_text(text: str) -> str:
    """Text safe inside a Markdown table cell (``|`` escaped)."""
    return text.replace("|", "\\|")


def markdown_table(results: Sequence[ScenarioResult]) -> str:
    """Every row: value, target with its basis (requirement or derived bound), verdict."""
    lines = ["| robot | scenario | metric | value | target | basis of the target | pass | note |",
             "|---|---|---|---|---|---|---|---|"]
    for res in results:
        for r in res.rows:
            target = "" if r.target is None else f"≤ {_fmt(r.target)} {r.unit}"
            lines.append(f"| {r.robot} | {res.scenario.name} | {_cell_text(r.metric)} | "
                         f"{_fmt(r.value)} {r.unit} | {target} | {_cell_text(r.basis)} | "
                         f"{_verdict(r)} | {_cell_text(r.note)} |")
    return "\n".join(lines)


def _value(res: ScenarioResult, metric: str, unit: str) -> float | None:
    return next((r.value for r in res.rows if r.metric == metric and r.unit == unit), None)


def _cell(value: float | None, suffix: str = "") -> str:
    return "" if value is None else f"{_fmt(value)}{suffix}"


def summary_table(results: Sequence[ScenarioResult]) -> str:
    """One row per scenario: headline judged metric, worst/RMS/final errors, slip, verdict.

    The pose columns are over the whole run (see :mod:`wmr_mujoco.validation.metrics`):
    worst and final position error in % of path, RMS in mm, worst and final heading error.
    """
    lines = ["| robot | scenario | headline (judged) | worst position error | RMS position "
             "error | final position error | worst heading error | final heading error | "
             "worst lateral slip RMS | pass |", "|---|---|---|---|---|---|---|---|---|---|"]
    for res in results:
        judged = [r for r in res.rows if r.target is not None]
        head = judged[0] if judged else (res.rows[0] if res.rows else None)
        headline = f"{head.metric}: {_fmt(head.value)} {head.unit}" if head else ""
        rms_m = _value(res, "RMS position error", "m")
        slips = [r.value for r in res.rows if r.metric.startswith("lateral slip RMS")]
        slip = f"{1000 * max(slips):.3f} mm/s" if slips else ""
        verdict = "pass" if res.passed else f"FAIL{': ' + res.error if res.error else ''}"
        cells = [_cell(_value(res, "worst position error", "% of path"), " %"),
                 _cell(None if rms_m is None else 1000 * rms_m, " mm"),
                 _cell(_value(res, "final position error", "% of path"), " %"),
                 _cell(_value(res, "worst heading error", "deg"), "°"),
                 _cell(_value(res, "final heading error", "deg"), "°"), slip]
        lines.append(f"| {res.scenario.robot} | {res.scenario.name} | {_cell_text(headline)} | "
                     f"{' | '.join(cells)} | {verdict} |")
    return "\n".join(lines)


def open_table(results: Sequence[ScenarioResult]) -> str:
    """Every open target: figure, required bound, where it was asked and why it is missed.

    An empty string when none is open.
    """
    rows = [(res, r) for res in results for r in res.rows if r.open]
    if not rows:
        return ""
    lines = ["| robot | scenario | metric | figure | target | verdict | asked for; why open |",
             "|---|---|---|---|---|---|---|"]
    for res, r in rows:
        lines.append(f"| {r.robot} | {res.scenario.name} | {_cell_text(r.metric)} | "
                     f"{_fmt(r.value)} {r.unit} | ≤ {_fmt(r.target or math.nan)} {r.unit} | "
                     f"{r.verdict} | {_cell_text(r.basis)} |")
    return "\n".join(lines)


def slug(text: str) -> str:
    """File-name-safe version of a label."""
    return re.sub(r"[^a-z0-9]+", "-", text.lower().replace("°", "deg")).strip("-")


def _plot_states(axes: Sequence[Axes], tr: dict[str, np.ndarray], trace: Trace) -> None:
    """Panels of a kinematic or dynamic run, chosen by the adapter's state."""
    t, sim, ana = tr["time"], tr["sim"], tr["analytic"]
    names, units = trace.state_names, trace.state_units
    if trace.is_pose:
        axes[0].plot(sim[:, 0], sim[:, 1], label="MuJoCo")
        axes[0].plot(ana[:, 0], ana[:, 1], "--", label="analytic")
        axes[0].set(xlabel="x [m]", ylabel="y [m]", title="trajectory")
        axes[0].set_aspect("equal", adjustable="datalim")
        axes[1].plot(t, 1000 * np.linalg.norm(sim[:, :2] - ana[:, :2], axis=1))
        axes[1].set(xlabel="t [s]", ylabel="position error [mm]", title="error over time")
        rest = range(3, len(names))
    else:
        axes[0].plot(t, sim[:, 0], label="MuJoCo")
        axes[0].plot(t, ana[:, 0], "--", label="analytic")
        axes[0].set(xlabel="t [s]", ylabel=f"{names[0]} [{units[0]}]", title=names[0])
        axes[1].plot(t, sim[:, 1:] - ana[:, 1:])
        axes[1].set(xlabel="t [s]", title="MuJoCo − model",
                    ylabel=", ".join(f"{n} [{u}]" for n, u in zip(names[1:], units[1:],
                                                                   strict=True)))
        rest = range(len(names), len(names))
    axes[0].legend()
    if len(rest):
        for i in rest:
            axes[2].plot(t, sim[:, i], label=f"{names[i]} [{units[i]}] MuJoCo")
            axes[2].plot(t, ana[:, i], "--", label=f"{names[i]} model")
        axes[2].set(xlabel="t [s]", title="further states")
        axes[2].legend(fontsize=7)
    elif tr["slip"].ndim == 2 and tr["slip"].shape[1]:
        axes[2].plot(t, 1000 * tr["slip"])
        axes[2].set(xlabel="t [s]", ylabel="lateral slip [mm/s]", title="slip at wheel contacts")
    elif trace.is_pose:
        axes[2].plot(t, np.degrees(wrap_angle(sim[:, 2] - ana[:, 2])))
        axes[2].set(xlabel="t [s]", ylabel="heading error [deg]", title="heading error")
    else:
        axes[2].set_axis_off()


def _plot_series(axes: Sequence[Axes], series: Sequence[Series]) -> None:
    """A measurement's own curves, one panel per pair of axis labels (three at most)."""
    groups: dict[tuple[str, str], list[Series]] = {}
    for s in series:
        groups.setdefault((s.xlabel, s.ylabel), []).append(s)
    for ax, ((xlabel, ylabel), members) in zip(axes, list(groups.items())[:len(axes)],
                                                strict=False):
        for s in members:
            colour = {} if s.color is None else {"color": s.color}
            ax.plot(s.x, s.y, s.style, label=s.label, ms=4, **colour)
        ax.set(xlabel=xlabel, ylabel=ylabel)
        ax.legend(fontsize=7)
    for ax in axes[len(groups):]:
        ax.set_axis_off()


def plot_series(series: Sequence[Series], path: Path, title: str = "") -> Path:
    """One figure of curves alone (e.g. a measurement's series for a model README).

    One panel per pair of axis labels, as in the report (three at most).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = min(3, max(1, len({(s.xlabel, s.ylabel) for s in series})))
    fig, axes = plt.subplots(1, panels, figsize=(7 * panels, 4.5), squeeze=False)
    _plot_series(axes[0], series)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=100)
    plt.close(fig)
    return path


def plot_scenario(result: ScenarioResult, path: Path) -> Path | None:
    """Trajectory (physics over analytic), error over time, slip or further states.

    A measurement scenario's own curves are plotted instead. Returns None when there is
    nothing to plot.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    trace = result.trace
    tr = trace.arrays()
    if tr["time"].size < 2 and not trace.series:
        return None
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    if trace.series:
        _plot_series(axes, trace.series)
    else:
        _plot_states(axes, tr, trace)
    fig.suptitle(result.scenario.key)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=80)
    plt.close(fig)
    return path


#: The plots :func:`plot_all` hands to its forked workers (inherited, never pickled).
_PLOT_JOBS: list[tuple[ScenarioResult, Path]] = []


def _plot_job(i: int) -> Path | None:
    result, path = _PLOT_JOBS[i]
    return plot_scenario(result, path)


def plot_all(results: Sequence[ScenarioResult], folder: Path) -> list[Path | None]:
    """:func:`plot_scenario` of every result into ``folder``, on every core.

    Drawing is pure Python (matplotlib holds the GIL), so the plots are shared among
    forked worker processes, which inherit the results instead of receiving copies;
    where ``fork`` is unavailable, or for a single core, they are drawn one by one.
    """
    global _PLOT_JOBS
    jobs = [(r, Path(folder) / f"{slug(r.scenario.key)}.png") for r in results]
    workers = min(len(jobs), os.cpu_count() or 1)
    if workers < 2 or "fork" not in multiprocessing.get_all_start_methods():
        return [plot_scenario(r, p) for r, p in jobs]
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot  # imported once, inherited by the workers

    _PLOT_JOBS = jobs
    try:
        with multiprocessing.get_context("fork").Pool(workers) as pool:
            return pool.map(_plot_job, range(len(jobs)), chunksize=1)
    finally:
        _PLOT_JOBS = []


def to_json(results: Sequence[ScenarioResult]) -> str:
    """Every metric of every scenario as JSON."""
    def clean(x: float) -> float | None:
        return x if math.isfinite(x) else None

    doc = {"passed": all(r.passed for r in results), "scenarios": [
        {"robot": r.scenario.robot, "scenario": r.scenario.name, "kind": r.scenario.kind.value,
         "passed": r.passed, "error": r.error,
         "metrics": [{"metric": m.metric, "value": clean(m.value), "unit": m.unit,
                      "target": m.target, "basis": m.basis, "passed": m.passed,
                      "open": m.open, "note": m.note}
                     for m in r.rows]} for r in results]}
    return json.dumps(doc, indent=2)


def write_report(results: Sequence[ScenarioResult], folder: Path = REPORTS_DIR) -> Path:
    """Write ``validation.md``, ``validation.json`` and one PNG per scenario.

    Returns:
        Path of the Markdown report.
    """
    folder = Path(folder)
    plots = folder / "validation"
    plots.mkdir(parents=True, exist_ok=True)
    failed = [r for r in results if not r.passed]
    lines = ["# Validation: MuJoCo contact physics against the analytic models", "",
             "Generated by `wmr validate`; every figure below comes from that run.", "",
             f"**{summary_line(results)}.**", ""]
    if failed:
        lines += ["Failed: " + ", ".join(f"`{r.scenario.key}`" for r in failed), ""]
    lines += ["## Summary", "", summary_table(results), ""]
    if open_table(results):
        lines += ["## Open targets", "", "Required, not yet met by any model: shown with "
                  "their figures, counted, not judged.", "", open_table(results), ""]
    lines += ["## How the metrics are judged",
              "", DEFINITIONS, "", "## Every metric", "",
              markdown_table(results), "", "## Plots", ""]
    for r, png in zip(results, plot_all(results, plots), strict=True):
        if png is not None:
            lines += [f"### {r.scenario.key}", "", f"![{r.scenario.key}](validation/{png.name})",
                      ""]
    write_text_atomic(folder / "validation.json", to_json(results))
    write_text_atomic(folder / "summary.md", summary_table(results) + "\n")
    write_text_atomic(folder / "open.md", (open_table(results)
                                           or "No open targets.") + "\n")
    return write_text_atomic(folder / "validation.md", "\n".join(lines) + "\n")
