"""The report of each scenario's family: N, median, spread, worst and target per metric.

A scenario with a family is judged by its worst member (:mod:`wmr_mujoco.validation.worst`);
this module shows the spread behind that verdict, as a terminal table
(:func:`spread_text`), a Markdown table (:func:`spread_markdown`, ``reports/families.md``)
and the members' figures in the JSON report (:func:`members_record`, read back by
:func:`restore_members`). A run with fewer draws than a family declares (``wmr validate
--quick`` or ``--draws``) is labelled quick (:func:`quick_label`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from wmr_mujoco.validation.family import describe
from wmr_mujoco.validation.metrics import Trace
from wmr_mujoco.validation.runner import ScenarioResult
from wmr_mujoco.validation.targets import Row
from wmr_mujoco.validation.worst import Spread, spreads, worst_member


def _fmt(value: float) -> str:
    if not math.isfinite(value):
        return "n/a"
    if value == 0 or 1e-3 <= abs(value) < 1e5:
        return f"{value:.4g}"
    return f"{value:.3e}"


def member_rows(result: ScenarioResult) -> list[list[Row]]:
    """The rows of each member (the result's own rows for a single run)."""
    return [m.rows for m in result.members] if result.members else [result.rows]


def declared_draws(result: ScenarioResult) -> int:
    """Draws the scenario's family declares (1 without a family)."""
    family = result.scenario.family
    return 1 if family is None else family.draws


def is_quick(result: ScenarioResult) -> bool:
    """Whether fewer members ran than the family declares."""
    return len(member_rows(result)) < declared_draws(result)


def quick_label(results: Sequence[ScenarioResult]) -> str:
    """``"quick: N of M declared draws in K families"``, or empty for a full run."""
    quick = [r for r in results if is_quick(r)]
    if not quick:
        return ""
    ran = sorted({len(member_rows(r)) for r in quick})
    return (f"quick: {'/'.join(map(str, ran))} draws instead of the declared ones in "
            f"{len(quick)} families (not the judged claim)")


def judged_spreads(result: ScenarioResult) -> list[Spread]:
    """The spreads of the metrics with a target (judged or open)."""
    return [s for s in spreads(member_rows(result)) if s.target is not None]


def _verdict(s: Spread) -> str:
    if s.open:
        ok = math.isfinite(s.worst) and abs(s.worst) <= (s.target or math.nan)
        return "open (met)" if ok else "open"
    return "pass" if s.passed else "FAIL"


def _with_unit(text: str, unit: str) -> str:
    return text if unit in ("", "1", "-") else f"{text} {unit}"


def _cells(res: ScenarioResult, s: Spread) -> list[str]:
    """Row cells: robot, scenario, metric, N, median, p10..p90, min..max, worst, target."""
    return [res.scenario.robot, res.scenario.name, s.metric, str(s.n),
            _with_unit(_fmt(s.median), s.unit),
            f"{_fmt(s.percentile(10))}..{_fmt(s.percentile(90))}",
            f"{_fmt(s.low)}..{_fmt(s.high)}", _with_unit(_fmt(s.worst), s.unit),
            _with_unit(f"≤ {_fmt(s.target or math.nan)}", s.unit), _verdict(s)]


HEADER = ("robot", "scenario", "metric", "N", "median", "p10..p90", "min..max", "worst",
          "target", "verdict")


def spread_text(results: Sequence[ScenarioResult]) -> str:
    """Fixed-width table of every judged or open metric over its family."""
    body = [_cells(res, s) for res in results for s in judged_spreads(res)]
    widths = [max(len(x[i]) for x in [HEADER, *body]) for i in range(len(HEADER))]
    lines = ["  ".join(h.ljust(w) for h, w in zip(HEADER, widths, strict=True))]
    lines += ["  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)) for row in body]
    return "\n".join(lines)


def spread_markdown(results: Sequence[ScenarioResult]) -> str:
    """Markdown table of every judged or open metric over its family (and the seed)."""
    lines = ["| " + " | ".join(HEADER) + " | seed |", "|" + "---|" * (len(HEADER) + 1)]
    for res in results:
        seed = "one run" if res.seed is None else str(res.seed)
        for s in judged_spreads(res):
            cells = [c.replace("|", "\\|") for c in _cells(res, s)]
            lines.append("| " + " | ".join(cells) + f" | {seed} |")
    return "\n".join(lines)


def families_markdown(results: Sequence[ScenarioResult]) -> str:
    """``reports/families.md``: what a family is, the quick label if any, the table."""
    label = quick_label(results)
    intro = ("Each scenario is judged over its family: N seeded draws of what a user "
             "would vary (declared in each robot's registry entry), the worst draw "
             "judged. Spread: 10th..90th percentile and min..max over the draws.")
    return "\n\n".join([intro, *([f"**{label}.**"] if label else []),
                        spread_markdown(results)])


def members_record(result: ScenarioResult) -> dict[str, object] | None:
    """The members of a family as JSON (None: a single run)."""
    if not result.members:
        return None

    def clean(x: float) -> float | None:
        return x if math.isfinite(x) else None

    return {"seed": result.seed, "declared": declared_draws(result),
            "members": [{"draw": dict(m.scenario.draw), "passed": m.passed,
                         "error": m.error,
                         "metrics": [[r.metric, r.unit, clean(r.value), r.passed]
                                     for r in m.rows]} for m in result.members]}


def restore_members(record: Mapping[str, object] | None, result: ScenarioResult
                    ) -> ScenarioResult:
    """``result`` (read back from JSON) with its members from :func:`members_record`.

    A member row takes its target, basis and open flag from the family's row of the
    same metric. A malformed record gives the result without members.
    """
    if not isinstance(record, Mapping):
        return result
    try:
        family = {(r.metric, r.unit): r for r in result.rows}
        members = []
        for m in record["members"]:  # type: ignore[index, union-attr]
            scenario = result.scenario.member(m["draw"])
            rows = []
            for metric, unit, value, passed in m["metrics"]:
                base = family.get((metric, unit))
                rows.append(Row(scenario.robot, scenario.name, metric,
                                math.nan if value is None else float(value), unit,
                                base.target if base else None, passed, "",
                                base.basis if base else "", bool(base and base.open)))
            members.append(ScenarioResult(scenario, rows, Trace(), m.get("error")))
        seed = record.get("seed")
        result.members = members
        result.seed = int(seed) if isinstance(seed, int) else None
    except (KeyError, TypeError, ValueError):
        return result
    return result


def slowest(results: Sequence[ScenarioResult], n: int = 5) -> str:
    """``K families, X s summed; slowest: robot/scenario (N draws) Y s, ...``.

    Each family's wall time (``ScenarioResult.seconds``, also in the JSON report, without
    drawing its figure), summed over the families: about the run's wall time in one
    process, more than it with ``--jobs``.
    """
    timed = [r for r in results if r.seconds is not None]
    top = sorted(timed, key=lambda r: -(r.seconds or 0.0))[:n]
    total = sum(r.seconds or 0.0 for r in timed)
    return (f"{len(timed)} families, {total:.1f} s summed over them; slowest: " + ", ".join(
        f"{r.scenario.key} ({len(member_rows(r))} draws) {r.seconds:.1f} s" for r in top))


def worst_draw(result: ScenarioResult) -> str:
    """The draw of the member whose headline is worst (``nominal`` for a single run)."""
    if not result.members:
        return "nominal"
    return describe(result.members[worst_member(member_rows(result))].scenario.draw)
