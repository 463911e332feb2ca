"""The audit's report: ``audit.md``, ``audit.json`` and one path plot per manoeuvre.

Every file is written atomically (:mod:`wmr_mujoco.atomic`): an interrupted audit leaves
no half-written file. The plots draw the reference point's path in MuJoCo over the ideal
model's (matplotlib, Agg backend).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from wmr_mujoco.analytic.campion import summary
from wmr_mujoco.atomic import atomic_path, write_text_atomic
from wmr_mujoco.audit.core import Audit
from wmr_mujoco.audit.figures import DRIFTS, FOLLOWS


def _fmt(x: float | None, digits: int = 1) -> str:
    return "n/a" if x is None or not np.isfinite(x) else f"{x:.{digits}f}"


def verdict_lines(a: Audit) -> list[str]:
    """One line per manoeuvre: name, verdict, worst position and heading errors."""
    return [f"{o.manoeuvre.name}: {o.verdict} (worst {o.figures.error_label()}, "
            f"{o.figures.heading_deg:.1f}° heading; {o.manoeuvre.description})"
            for o in a.outcomes] + [f"{n}: not driven ({why})" for n, why in a.skipped.items()]


def summary_text(a: Audit) -> str:
    """The short summary printed by ``wmr audit`` (and shown in the README)."""
    lines = [f"{a.scene.path.name}: {summary(a.wheels.classification)}",
             f"drive: {a.drive.statement}"]
    lines += [f"  {v}" for v in verdict_lines(a)]
    lines += [f"  diagnosis: {d.line()}" for d in a.diagnoses]
    return "\n".join(lines)


def _matrix(a: Audit) -> list[str]:
    rows = ["| wheel | ∂ω/∂u | ∂ω/∂v | ∂ω/∂r |", "|---|---|---|---|"]
    rows += [f"| {n} | {r[0]:.3f} | {r[1]:.3f} | {r[2]:.3f} |"
             for n, r in zip(a.jacobian_rows, a.jacobian, strict=True)]
    return rows


def markdown(a: Audit) -> str:
    """The text of ``audit.md``."""
    c = a.wheels.classification
    out = [f"# Audit of {a.scene.path.name}", "",
           f"File: `{a.scene.path}`" + (" (no floor: the audit added one)"
                                        if a.scene.floor_added else ""), "",
           f"**Class** (Campion): ({c.delta_m},{c.delta_s}): {summary(c)}", "",
           "## Wheels", "", "| wheel | kind | centre (x, y) m | axle | rolling radius m "
           "| envelope ripple % | γ deg | driven |", "|---|---|---|---|---|---|---|---|"]
    for w in a.wheels.wheels:
        g = ("" if w.wheel.roller_angle is None else
             f"{round(float(np.degrees(w.wheel.roller_angle)), 1) + 0.0:.1f}")
        out.append(f"| {w.name} | {w.kind} | ({w.wheel.position[0]:.4f}, "
                   f"{w.wheel.position[1]:.4f}) | ({w.wheel.axle[0]:.3f}, {w.wheel.axle[1]:.3f}) "
                   f"| {w.radius:.4f} | {_fmt(100 * w.ripple, 2)} | {g} | "
                   f"{'yes' if w.name in a.drive.spin else 'no'} |")
    out += ["", "Notes: " + ("; ".join(a.wheels.notes) or "none"), "",
            "## Ideal kinematic model", "",
            "Wheel rates ω = J ν for the body twist ν = (u, v, r) of the chassis origin "
            "(rolling radius from the colliders' envelope, docs/audit.md):", ""]
    out += _matrix(a)
    out += ["", f"Reference point (chassis frame): ({a.reference[0]:.4f}, {a.reference[1]:.4f})"
            f" m; robot span {a.span:.4f} m.", "", f"**Drive**: {a.drive.statement}.", "",
            "## Verdicts", "", f"Thresholds: follows ≤ {FOLLOWS[0]:g} % of path and "
            f"{FOLLOWS[1]:g}°; drifts ≤ {DRIFTS[0]:g} % and {DRIFTS[1]:g}°; a spin in place by "
            f"its drift in % of the span. Each manoeuvre {a.duration:g} s, {len(a.draws)} "
            f"seeded draw(s) (speed × 0.5-1.5, wheel phase; the first nominal): the worst "
            f"draw is reported.", ""]
    out += [f"- {v}" for v in verdict_lines(a)]
    out += ["", "## Figures", "", "| manoeuvre | worst position error | worst heading deg | "
            "lateral slip m/s (% of wheel speed) | radius ripple % | off floor % | "
            "penetration mm | coasting energy drift % | real-time factor |",
            "|---|---|---|---|---|---|---|---|---|"]
    for o in a.outcomes:
        f = o.figures
        out.append(f"| {o.manoeuvre.name} | {f.error_label()} | {f.heading_deg:.1f} | "
                   f"{f.slip_ms:.4f} ({f.slip_pct:.0f}) | {f.ripple_pct:.2f} | "
                   f"{f.off_floor_pct:.1f} | {f.penetration_mm:.2f} | "
                   f"{f.energy_drift_pct:.2f} | {f.real_time_factor:.1f} |")
    out += ["", "## Diagnoses", ""]
    out += [f"- {d.line()}" for d in a.diagnoses] or ["- none of the known pitfalls found"]
    out += ["", "## Paths", ""] + [f"![{o.manoeuvre.name}](path_{o.manoeuvre.name}.png)"
                                    for o in a.outcomes]
    return "\n".join(out) + "\n"


def as_json(a: Audit) -> dict:
    """The content of ``audit.json``."""
    c = a.wheels.classification
    return {
        "file": str(a.scene.path), "floor_added": a.scene.floor_added,
        "class": [c.delta_m, c.delta_s], "summary": summary(c), "notes": list(a.wheels.notes),
        "wheels": [{"name": w.name, "kind": w.kind, "position": list(w.wheel.position),
                    "axle": list(w.wheel.axle), "radius": w.radius, "ripple": w.ripple,
                    "roller_angle": w.wheel.roller_angle, "driven": w.name in a.drive.spin}
                   for w in a.wheels.wheels],
        "jacobian": {"rows": list(a.jacobian_rows), "matrix": a.jacobian.tolist()},
        "reference_point": a.reference.tolist(), "span": a.span,
        "drive": {"imposed": a.drive.imposed, "statement": a.drive.statement},
        "duration": a.duration, "skipped": a.skipped,
        "draws": [{"speed": d.speed, "phases": {str(k): v for k, v in d.phases.items()}}
                  for d in a.draws],
        "manoeuvres": [{"name": o.manoeuvre.name, "twist": list(o.manoeuvre.twist),
                        "worst_draw": o.draw, "verdict": o.verdict,
                        "figures": o.figures.as_dict()}
                       for o in a.outcomes],
        "diagnoses": [d.as_dict() for d in a.diagnoses],
    }


def _plot(a: Audit, out: Path) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    paths = []
    for o in a.outcomes:
        fig, ax = plt.subplots(figsize=(4.5, 4.0))
        r = o.record
        ax.plot(r.ideal[:, 0], r.ideal[:, 1], "k--", label="ideal model")
        ax.plot(r.sim[:, 0], r.sim[:, 1], "C0-", label="MuJoCo")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.set_title(f"{o.manoeuvre.name}: {o.figures.error_label()}", fontsize=9)
        ax.legend(fontsize=8)
        fig.tight_layout()
        path = out / f"path_{o.manoeuvre.name}.png"
        with atomic_path(path) as tmp:
            fig.savefig(tmp, dpi=80)
        plt.close(fig)
        paths.append(path)
    return paths


def write_report(a: Audit, out: Path | str) -> list[Path]:
    """Write ``audit.md``, ``audit.json`` and the plots into ``out``.

    ``out`` is created, not its parents (the CLI checks it first with
    :func:`~wmr_mujoco.validation.report.check_report_folder`).
    """
    out = Path(out)
    out.mkdir(exist_ok=True)
    written = _plot(a, out)
    written.append(write_text_atomic(out / "audit.json", json.dumps(as_json(a), indent=1)))
    written.append(write_text_atomic(out / "audit.md", markdown(a)))
    return written
