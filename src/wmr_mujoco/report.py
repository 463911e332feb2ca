"""Validation report: a table on the terminal, Markdown with PNG plots, and JSON.

Every file is written atomically (temporary file, then rename), so an interrupted or
failed run never leaves a half-written report.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from wmr_mujoco.atomic import atomic_path, write_text_atomic
from wmr_mujoco.validation import Row, ScenarioResult

#: Default output folder of ``wmr validate``.
REPORTS_DIR = Path("reports")


def _fmt(value: float) -> str:
    if not math.isfinite(value):
        return "n/a"
    if value == 0 or 1e-3 <= abs(value) < 1e5:
        return f"{value:.4g}"
    return f"{value:.3e}"


def _verdict(row: Row) -> str:
    return "" if row.passed is None else ("pass" if row.passed else "FAIL")


def text_table(results: Sequence[ScenarioResult], judged_only: bool = False) -> str:
    """Fixed-width table: robot, scenario, metric, value, target, pass."""
    rows = [r for res in results for r in res.rows if not judged_only or r.passed is not None]
    header = ("robot", "scenario", "metric", "value", "target", "pass")
    body = [(r.robot, r.scenario, r.metric, f"{_fmt(r.value)} {r.unit}".strip(),
             "" if r.target is None else f"≤ {_fmt(r.target)} {r.unit}".strip(),
             _verdict(r) + (f" ({r.note})" if r.note else "")) for r in rows]
    widths = [max(len(x[i]) for x in [header, *body]) for i in range(len(header))]
    lines = ["  ".join(h.ljust(w) for h, w in zip(header, widths, strict=True))]
    lines += ["  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)) for row in body]
    return "\n".join(lines)


def markdown_table(results: Sequence[ScenarioResult]) -> str:
    """The judged rows and the informative ones, as a Markdown table."""
    lines = ["| robot | scenario | metric | value | target | pass |", "|---|---|---|---|---|---|"]
    for res in results:
        for r in res.rows:
            target = "" if r.target is None else f"≤ {_fmt(r.target)} {r.unit}"
            verdict = _verdict(r) + (f": {r.note}" if r.note else "")
            lines.append(f"| {r.robot} | {r.scenario} | {r.metric} | {_fmt(r.value)} {r.unit} "
                         f"| {target} | {verdict} |")
    return "\n".join(lines)


def summary_table(results: Sequence[ScenarioResult]) -> str:
    """One row per scenario: its headline judged metric, heading, worst slip, verdict."""
    lines = ["| robot | scenario | headline metric | heading error | worst lateral slip RMS | "
             "pass |", "|---|---|---|---|---|---|"]
    for res in results:
        judged = [r for r in res.rows if r.target is not None]
        head = judged[0] if judged else (res.rows[0] if res.rows else None)
        headline = f"{head.metric}: {_fmt(head.value)} {head.unit}" if head else ""
        heading = next((f"{_fmt(r.value)}°" for r in res.rows
                        if r.metric == "final heading error"), "")
        slips = [r.value for r in res.rows if r.metric.startswith("lateral slip")]
        slip = f"{1000 * max(slips):.3f} mm/s" if slips else ""
        verdict = "pass" if res.passed else f"FAIL{': ' + res.error if res.error else ''}"
        lines.append(f"| {res.scenario.robot} | {res.scenario.name} | {headline} | {heading} | "
                     f"{slip} | {verdict} |")
    return "\n".join(lines)


def slug(text: str) -> str:
    """File-name-safe version of a label."""
    return re.sub(r"[^a-z0-9]+", "-", text.lower().replace("°", "deg")).strip("-")


def plot_scenario(result: ScenarioResult, path: Path) -> Path | None:
    """Trajectory (physics over analytic), error over time, slip or velocity over time."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    tr = result.trace.arrays()
    if tr["time"].size < 2:
        return None
    t, sim, ana = tr["time"], tr["sim"], tr["analytic"]
    s = result.scenario
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    if s.kind == "dynamic" and s.robot == "disc":
        axes[0].plot(t, sim[:, 0], label="MuJoCo")
        axes[0].plot(t, ana[:, 0], "--", label="τR/(J+mR²)")
        axes[0].set(xlabel="t [s]", ylabel="distance [m]", title="distance rolled")
        axes[1].plot(t, sim[:, 1] - ana[:, 1])
        axes[1].set(xlabel="t [s]", ylabel="speed error [m/s]", title="speed, MuJoCo − model")
    else:
        axes[0].plot(sim[:, 0], sim[:, 1], label="MuJoCo")
        axes[0].plot(ana[:, 0], ana[:, 1], "--", label="analytic")
        axes[0].set(xlabel="x [m]", ylabel="y [m]", title="trajectory")
        axes[0].set_aspect("equal", adjustable="datalim")
        axes[1].plot(t, 1000 * np.linalg.norm(sim[:, :2] - ana[:, :2], axis=1))
        axes[1].set(xlabel="t [s]", ylabel="position error [mm]", title="error over time")
    axes[0].legend()
    if s.kind == "dynamic" and s.robot == "omni3":
        for i, name in enumerate(("u [m/s]", "v [m/s]", "r [rad/s]")):
            axes[2].plot(t, sim[:, 3 + i], label=f"{name} MuJoCo")
            axes[2].plot(t, ana[:, 3 + i], "--", label=f"{name} Lagrange")
        axes[2].set(xlabel="t [s]", title="body velocities")
        axes[2].legend(fontsize=7)
    elif tr["slip"].ndim == 2 and tr["slip"].shape[1]:
        axes[2].plot(t, 1000 * tr["slip"])
        axes[2].set(xlabel="t [s]", ylabel="lateral slip [mm/s]", title="slip at wheel contacts")
    else:
        axes[2].plot(t, np.degrees(np.angle(np.exp(1j * (sim[:, 2] - ana[:, 2])))))
        axes[2].set(xlabel="t [s]", ylabel="heading error [deg]", title="heading error")
    fig.suptitle(s.key)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=80)
    plt.close(fig)
    return path


def to_json(results: Sequence[ScenarioResult]) -> str:
    """Every metric of every scenario as JSON."""
    def clean(x: float) -> float | None:
        return x if math.isfinite(x) else None

    doc = {"passed": all(r.passed for r in results), "scenarios": [
        {"robot": r.scenario.robot, "scenario": r.scenario.name, "kind": r.scenario.kind,
         "passed": r.passed, "error": r.error,
         "metrics": [{"metric": m.metric, "value": clean(m.value), "unit": m.unit,
                      "target": m.target, "passed": m.passed, "note": m.note}
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
             f"**{len(results) - len(failed)} of {len(results)} scenarios pass.**", ""]
    if failed:
        lines += ["Failed: " + ", ".join(f"`{r.scenario.key}`" for r in failed), ""]
    lines += ["## Summary", "", summary_table(results), "", "## Every metric", "",
              markdown_table(results), "", "## Plots", ""]
    for r in results:
        png = plot_scenario(r, plots / f"{slug(r.scenario.key)}.png")
        if png is not None:
            lines += [f"### {r.scenario.key}", "", f"![{r.scenario.key}](validation/{png.name})",
                      ""]
    write_text_atomic(folder / "validation.json", to_json(results))
    write_text_atomic(folder / "summary.md", summary_table(results) + "\n")
    return write_text_atomic(folder / "validation.md", "\n".join(lines) + "\n")
