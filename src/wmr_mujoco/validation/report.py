"""Validation report: a table on the terminal, Markdown with PNG plots, and JSON.

Every file is written atomically (temporary file, then rename), so an interrupted or
failed run never leaves a half-written report.
"""

from __future__ import annotations

import json
import math
import os
import re
from collections.abc import Mapping, Sequence
from pathlib import Path

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.models.paths import REPORTS_DIR
from wmr_mujoco.validation.family_plots import plot_spreads
from wmr_mujoco.validation.family_report import (
    families_markdown,
    members_record,
    quick_label,
    restore_members,
)
from wmr_mujoco.validation.metrics import DEFINITIONS, Row, Trace
from wmr_mujoco.validation.plots import plot_scenario
from wmr_mujoco.validation.pool import run_calls
from wmr_mujoco.validation.runner import ScenarioResult
from wmr_mujoco.validation.scenarios import Scenario
from wmr_mujoco.validation.spec import RobotSpec

#: The robots a report covers, by name, in report order (the registry's ``ROBOTS``).
Robots = Mapping[str, RobotSpec]


def check_report_folder(folder: Path) -> Path:
    """Check a report folder before any work: a folder, or one to create in an existing one.

    The rule is the one of ``wmr render``'s output file: ``wmr`` writes into an existing
    folder; here it creates the report folder itself, never its parents.

    Raises:
        ValueError: ``folder`` is a file, its parent does not exist, or is not writable.
    """
    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        raise ValueError(f"--out {str(folder)!r} is a file; give a folder for the report "
                         "(created if its parent exists)")
    parent = folder if folder.is_dir() else (folder.parent if str(folder.parent) else Path("."))
    if not parent.is_dir():
        raise ValueError(f"--out {str(folder)!r}: folder {str(parent)!r} does not exist; "
                         "create it first (wmr creates only the report folder itself)")
    if not os.access(parent, os.W_OK):
        raise ValueError(f"--out {str(folder)!r}: folder {str(parent)!r} is not writable")
    return folder


def _fmt(value: float) -> str:
    if not math.isfinite(value):
        return "n/a"
    if value == 0 or 1e-3 <= abs(value) < 1e5:
        return f"{value:.4g}"
    return f"{value:.3e}"


#: Units of dimensionless values: printed as no unit at all.
DIMENSIONLESS = ("", "1", "-")


def _value(value: float, unit: str) -> str:
    """A value with its unit; a dimensionless one (unit ``1``) bare."""
    return _fmt(value) if unit in DIMENSIONLESS else f"{_fmt(value)} {unit}"


def _bound(target: float | None, unit: str) -> str:
    """``≤ target unit`` (empty without a target)."""
    return "" if target is None else f"≤ {_value(target, unit)}"


def _verdict(row: Row) -> str:
    return row.verdict


def summary_line(results: Sequence[ScenarioResult]) -> str:
    """``N of M scenarios pass; K targets open (...): list``, and the quick label if any.

    Open targets are counted and named (``robot/scenario: metric``), not judged.
    """
    failed = [r for r in results if not r.passed]
    opened = [(res, r) for res in results for r in res.rows if r.open]
    line = f"{len(results) - len(failed)} of {len(results)} scenarios pass"
    if opened:
        met = sum(r.verdict == "open (met)" for _, r in opened)
        named = "; ".join(f"{res.scenario.key}: {r.metric}" for res, r in opened)
        line += (f"; {len(opened)} targets open (shown with their figures, not judged"
                 f"{f'; {met} of them now met' if met else ''}): {named}")
    label = quick_label(results)
    return f"{line} [{label}]" if label else line


def text_table(results: Sequence[ScenarioResult], judged_only: bool = False) -> str:
    """Fixed-width table: robot, scenario, metric, value, target, pass (open rows shown)."""
    rows = [r for res in results for r in res.rows
            if not judged_only or r.passed is not None or r.open]
    header = ("robot", "scenario", "metric", "value", "target", "pass")
    body = [(r.robot, r.scenario, r.metric, _value(r.value, r.unit), _bound(r.target, r.unit),
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
            lines.append(f"| {r.robot} | {res.scenario.name} | {_cell_text(r.metric)} | "
                         f"{_value(r.value, r.unit)} | {_bound(r.target, r.unit)} | "
                         f"{_cell_text(r.basis)} | "
                         f"{_verdict(r)} | {_cell_text(r.note)} |")
    return "\n".join(lines)


def _cell(value: float | None, suffix: str = "") -> str:
    return "" if value is None else f"{_fmt(value)}{suffix}"


def _base_name(metric: str) -> str:
    """A metric's name without a group member's ``"member: "`` prefix."""
    return metric.rsplit(": ", 1)[-1]


def headline(rows: Sequence[Row]) -> Row | None:
    """The row a scenario's summary shows: its first judged metric, at its worst.

    A grouped scenario judges the same metric once per member (``"translate 45°: worst
    position error"``); the headline is the member nearest its target (the largest
    ``|value| / target``; a non-finite value counts as the worst), so that a group never
    shows a good member while another is far worse. None: no rows.
    """
    judged = [r for r in rows if r.target is not None and not r.open]
    if not judged:
        return rows[0] if rows else None
    first = judged[0]
    same = [r for r in judged if _base_name(r.metric) == _base_name(first.metric)
            and r.unit == first.unit]

    def ratio(r: Row) -> float:
        return abs(r.value) / r.target if math.isfinite(r.value) and r.target else math.inf

    return max(same, key=ratio)


def _worst(rows: Sequence[Row], metric: str, unit: str) -> float | None:
    """The metric's value, or the largest over a group's members; None: not measured."""
    values = [abs(r.value) for r in rows
              if r.unit == unit and _base_name(r.metric) == metric]
    if not values:
        return None
    return max(values, key=lambda v: v if math.isfinite(v) else math.inf)


def summary_table(results: Sequence[ScenarioResult]) -> str:
    """One row per scenario: headline judged metric, worst/RMS/final errors, slip, verdict.

    The pose columns are over the whole run (see :mod:`wmr_mujoco.validation.metrics`):
    worst and final position error in % of path, RMS in mm, worst and final heading error;
    a grouped scenario shows its worst member in each (:func:`headline`).
    """
    lines = ["| robot | scenario | headline (judged) | worst position error | RMS position "
             "error | final position error | worst heading error | final heading error | "
             "worst lateral slip RMS | pass |", "|---|---|---|---|---|---|---|---|---|---|"]
    for res in results:
        head = headline(res.rows)
        n_open = sum(r.open for r in res.rows)
        shown = f"{head.metric}: {_value(head.value, head.unit)}" if head else ""
        rms_m = _worst(res.rows, "RMS position error", "m")
        slips = [r.value for r in res.rows
                 if _base_name(r.metric).startswith("lateral slip RMS")]
        slip = f"{1000 * max(slips):.3f} mm/s" if slips else ""
        verdict = "pass" if res.passed else f"FAIL{': ' + res.error if res.error else ''}"
        if n_open:  # open targets never decide the verdict; say that they are there
            verdict += f" ({n_open} open)"
        cells = [_cell(_worst(res.rows, "worst position error", "% of path"), " %"),
                 _cell(None if rms_m is None else 1000 * rms_m, " mm"),
                 _cell(_worst(res.rows, "final position error", "% of path"), " %"),
                 _cell(_worst(res.rows, "worst heading error", "deg"), "°"),
                 _cell(_worst(res.rows, "final heading error", "deg"), "°"), slip]
        lines.append(f"| {res.scenario.robot} | {res.scenario.name} | {_cell_text(shown)} | "
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
                     f"{_value(r.value, r.unit)} | {_bound(r.target or math.nan, r.unit)} | "
                     f"{r.verdict} | {_cell_text(r.basis)} |")
    return "\n".join(lines)


def slug(text: str) -> str:
    """File-name-safe version of a label."""
    return re.sub(r"[^a-z0-9]+", "-", text.lower().replace("°", "deg")).strip("-")


def _record(r: ScenarioResult) -> dict[str, object]:
    """One scenario's JSON record: verdict, error and every metric."""
    def clean(x: float) -> float | None:
        return x if math.isfinite(x) else None

    return {"robot": r.scenario.robot, "scenario": r.scenario.name,
            "kind": r.scenario.kind.value, "passed": r.passed, "error": r.error,
            "metrics": [{"metric": m.metric, "value": clean(m.value), "unit": m.unit,
                         "target": m.target, "basis": m.basis, "passed": m.passed,
                         "open": m.open, "note": m.note} for m in r.rows],
            "family": members_record(r), "seconds": r.seconds}


def _restore(record: dict, robots: Robots) -> ScenarioResult | None:
    """A result from a JSON record of an earlier run; None if its scenario is gone."""
    spec = robots.get(str(record.get("robot")))
    scenario = next((s for s in (spec.scenarios if spec else ())
                     if s.name == record.get("scenario")), None)
    if scenario is None or scenario.kind.value != record.get("kind"):
        return None
    rows = [Row(scenario.robot, scenario.name, m["metric"],
                float("nan") if m["value"] is None else float(m["value"]), m["unit"],
                m["target"], m["passed"], m["note"], m["basis"], bool(m.get("open")))
            for m in record.get("metrics", [])]
    return restore_members(record.get("family"),
                           ScenarioResult(scenario, rows, Trace(), record.get("error")))


def _order(results: Sequence[ScenarioResult], robots: Robots) -> list[ScenarioResult]:
    """Registry order: robots as registered, each robot's scenarios as listed."""
    order = list(robots)

    def key(item: tuple[int, ScenarioResult]) -> tuple[int, int, int]:
        i, r = item
        spec = robots.get(r.scenario.robot)
        names = [s.name for s in spec.scenarios] if spec else []
        return (order.index(r.scenario.robot) if spec else len(order),
                names.index(r.scenario.name) if r.scenario.name in names else len(names), i)

    return [r for _, r in sorted(enumerate(results), key=key)]


def merge_results(new: Sequence[ScenarioResult], robots: Robots,
                  folder: Path = REPORTS_DIR) -> list[ScenarioResult]:
    """Merge this run's results into the report already in ``folder``.

    A scenario of this run replaces its earlier result; earlier results of the other
    registered scenarios are kept (so ``wmr validate omni3`` never clobbers the full
    report); results of scenarios no longer registered are dropped. An unreadable
    earlier report counts as none.
    """
    try:
        old = json.loads((Path(folder) / "validation.json").read_text())["scenarios"]
    except (OSError, ValueError, KeyError, TypeError):
        old = []
    ran = {r.scenario.key for r in new}
    kept = [res for rec in old if isinstance(rec, dict)
            and (res := _restore(rec, robots)) is not None and res.scenario.key not in ran]
    return _order([*new, *kept], robots)


def missing_scenarios(results: Sequence[ScenarioResult], robots: Robots) -> list[str]:
    """Scenarios of ``robots`` without a result (empty: the report is complete)."""
    have = {r.scenario.key for r in results}
    return [s.key for spec in robots.values() for s in spec.scenarios if s.key not in have]


def to_json(results: Sequence[ScenarioResult], robots: Robots) -> str:
    """Every metric of every scenario as JSON, with whether every scenario is there."""
    missing = missing_scenarios(results, robots)
    doc = {"passed": all(r.passed for r in results), "complete": not missing,
           "missing": missing, "quick": bool(quick_label(results)),
           "scenarios": [_record(r) for r in results]}
    return json.dumps(doc, indent=2)


def plot_path(folder: Path, scenario: Scenario) -> Path:
    """Where a scenario's plot goes: ``validation/<robot>/<scenario slug>.png``."""
    return Path(folder) / "validation" / scenario.robot / f"{slug(scenario.name)}.png"


def spread_path(folder: Path, robot: str) -> Path:
    """Where a robot's family spread plot goes: ``validation/<robot>/spread.png``."""
    return Path(folder) / "validation" / robot / "spread.png"


def _remove_stale_plots(folder: Path, robots: set[str], results: Sequence[ScenarioResult]
                        ) -> None:
    """Delete plots, in the folders of the robots this run covered, of no kept scenario."""
    kept = {plot_path(folder, r.scenario) for r in results}
    kept |= {spread_path(folder, robot) for robot in robots}
    for robot in robots:
        for png in (Path(folder) / "validation" / robot).glob("*.png"):
            if png not in kept:
                png.unlink(missing_ok=True)


def write_report(results: Sequence[ScenarioResult], folder: Path = REPORTS_DIR, *,
                 robots: Robots, jobs: int = 1) -> Path:
    """Merge this run into ``folder``'s report; write the Markdown, JSON and PNG plots.

    ``validation.md``, ``validation.json`` and ``summary.md`` cover this run's scenarios
    and the earlier results of the others (:func:`merge_results`); the JSON says whether
    every registered scenario is there (``complete``), which ``make readme`` requires.
    Each scenario of this run gets a fresh plot (the figure the run drew, ``figure``,
    written as it is); plots of the covered robots' scenarios that are no longer
    reported are removed, nobody else's. ``robots`` are the registered robots (which
    scenarios a complete report has, and their order); ``jobs`` > 1 draws the other
    plots in that many worker processes (:func:`~wmr_mujoco.validation.pool.run_calls`;
    the same files).

    Returns:
        Path of the Markdown report.
    """
    folder = Path(folder)
    folder.mkdir(exist_ok=True)
    merged = merge_results(results, robots, folder)
    fresh = {r.scenario.key for r in results}
    failed = [r for r in merged if not r.passed]
    missing = missing_scenarios(merged, robots)
    lines = ["# Validation: MuJoCo contact physics against the analytic models", "",
             "Generated by `wmr validate`; every figure below comes from a run of it "
             f"({len(fresh)} scenarios from the latest run, the others from earlier runs).",
             "", f"**{summary_line(merged)}.**", ""]
    if failed:
        lines += ["Failed: " + ", ".join(f"`{r.scenario.key}`" for r in failed), ""]
    if missing:
        lines += ["Not run yet: " + ", ".join(f"`{k}`" for k in missing), ""]
    lines += ["## Summary", "", summary_table(merged), ""]
    if open_table(merged):
        lines += ["## Open targets", "", "Required, not yet met by any model: shown with "
                  "their figures, counted, not judged.", "", open_table(merged), ""]
    lines += ["## Families", "", families_markdown(merged), ""]
    # The fresh plots first: those the run drew written here, the others drawn in ``jobs``
    # processes (each file written atomically).
    by_robot = {robot: [r for r in merged if r.scenario.robot == robot] for robot in robots}
    spread_plots = {robot: (mine, f"{robot}: each family's members against their targets",
                            spread_path(folder, robot)) for robot, mine in by_robot.items()
                    if any(r.scenario.key in fresh for r in mine)}
    scenario_plots = {r.scenario.key: (r, plot_path(folder, r.scenario)) for r in merged
                      if r.scenario.key in fresh}
    for png in [a[-1] for a in (*spread_plots.values(), *scenario_plots.values())]:
        png.parent.mkdir(parents=True, exist_ok=True)
    ready = {k: plot_scenario(*a) for k, a in scenario_plots.items()
             if a[0].figure is not None}
    todo = {k: a for k, a in scenario_plots.items() if k not in ready}  # still to draw
    drawn = run_calls([(plot_spreads, a) for a in spread_plots.values()]
                      + [(plot_scenario, a) for a in todo.values()], jobs)
    drawn_scenario = ready | dict(zip(todo, drawn[len(spread_plots):], strict=True))
    for robot in robots:
        png = spread_path(folder, robot)
        if png.is_file():
            lines += [f"![{robot} spread]({png.relative_to(folder).as_posix()})", ""]
    lines += ["## How the metrics are judged",
              "", DEFINITIONS, "", "## Every metric", "",
              markdown_table(merged), "", "## Plots", ""]
    for r in merged:
        png = drawn_scenario.get(r.scenario.key, plot_path(folder, r.scenario))
        if png is not None and png.is_file():
            rel = png.relative_to(folder).as_posix()
            lines += [f"### {r.scenario.key}", "", f"![{r.scenario.key}]({rel})", ""]
    _remove_stale_plots(folder, {r.scenario.robot for r in results}, merged)
    write_text_atomic(folder / "validation.json", to_json(merged, robots))
    write_text_atomic(folder / "summary.md", summary_table(merged) + "\n")
    write_text_atomic(folder / "open.md", (open_table(merged) or "No open targets.") + "\n")
    write_text_atomic(folder / "families.md", families_markdown(merged) + "\n")
    return write_text_atomic(folder / "validation.md", "\n".join(lines) + "\n")
