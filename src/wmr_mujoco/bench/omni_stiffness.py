"""omni3's dynamic targets against the roller contacts' stiffness, with the cost.

``python -m wmr_mujoco.bench.omni_stiffness`` (part of ``make study`` through
:mod:`~wmr_mujoco.bench.omni_energy_study`, which pastes the table into
``docs/omni-dynamics.md``; a couple of minutes).

The hybrid model's compliant terms (hand-over loss ``½ N δ``, overlap friction) are
averages of what a soft contact does; as the contacts stiffen they vanish and the model
is the rigid one of ``docs/omni-dynamics.md`` §§ 1-5, with the weight's moment over the
roller arc. This study builds omni3 at several contact stiffnesses (:data:`SETTINGS`:
``solref`` time constant of the roller-floor pairs and step, the time constant at least
:data:`~wmr_mujoco.models.builders.wheel_pairs.WHEEL_PAIR_STEPS` steps as the pairs require):
the shipped setting (the defaults of :class:`~wmr_mujoco.robots.omni3.params.OmniParams`), a
softer one at twice its time constant and step (half the cost), and a stiffer one nearer
the rigid limit; and reports, per setting and per hybrid
model (with the weight's moment over the arc, as judged, and without it):

* issue 16's figures, each as judged in ``wmr validate`` (:func:`issue_figures`): step
  commands (worst over the ten), each torque run (worst twist component and position),
  the coast's three figures, and how many of the issue's judged rows meet their floor;
* the figures that must not get worse (:func:`other_figures`): the kinematic scenarios'
  worst position error and the slip onset;
* the cost: the physics' wall time per simulated second (:func:`wall_time`), measured.
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import time

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders.wheel_pairs import WHEEL_PAIR_STEPS
from wmr_mujoco.robots.omni3 import DYNAMIC_SPECS
from wmr_mujoco.robots.omni3.coasting import COAST_SPEC, coast_figures
from wmr_mujoco.robots.omni3.dynamics import (
    STEP_SPECS,
    TORQUE_SPECS,
    event_shift,
    pose_metrics,
)
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import hybrid, settled, simulate_runs
from wmr_mujoco.robots.roller_wheels import omni_hybrid as oh
from wmr_mujoco.robots.roller_wheels.twist_errors import twist_metrics

#: (contact time constant, step), s: the shipped setting (:data:`SHIPPED`) first, then
#: a softer one (:data:`SOFTER`: both doubled) and a stiffer one (:data:`STIFFER`: both
#: times 0.4, the step 0.5 ms).
SHIPPED = (OmniParams().sim.contact_timeconst, OmniParams().sim.timestep)
SOFTER = (2.0 * SHIPPED[0], 2.0 * SHIPPED[1])
STIFFER = (0.4 * SHIPPED[0], 0.4 * SHIPPED[1])
SETTINGS = (SHIPPED, SOFTER, STIFFER)
#: Issue 16's floors: step path (% of path) and heading (deg); torque twist (% of peak)
#: and position (% of path); coasting figures and slip onset (% of physics).
FLOORS = {"step position": 0.3, "step heading": 0.2, "torque twist": 1.0,
          "torque position": 0.5, "coast": 5.0, "slip": 5.0}


def stiff(timeconst: float, step: float) -> OmniParams:
    """omni3's parameters with roller contacts of ``solref`` time constant ``timeconst``.

    Raises:
        ValueError: a time constant under :data:`WHEEL_PAIR_STEPS` steps (the roller-floor
            pairs would take that many steps instead), or values outside the parameters'
            ranges.
    """
    n = WHEEL_PAIR_STEPS
    if not (math.isfinite(timeconst) and math.isfinite(step) and 0 < n * step <= timeconst
            * (1 + 1e-9)):
        raise ValueError(f"timeconst = {timeconst!r} s, step = {step!r} s; the step must be "
                         f"in (0, timeconst / {n}] (the roller-floor pairs' least "
                         "time constant)")
    p = OmniParams()
    return dataclasses.replace(p, sim=dataclasses.replace(p.sim, timestep=step,
                                                          contact_timeconst=timeconst))


def issue_figures(params: OmniParams, arc: bool) -> dict[str, float]:
    """Issue 16's figures of every dynamic run, as judged (see the module docstring).

    Keys: ``step position``, ``step heading`` (worst over the step commands), ``<torque
    run> twist`` and ``<torque run> position``, ``coast <figure>`` (% of physics),
    ``met`` and ``rows`` (issue rows meeting their floor, of all; slip onset excluded).
    """
    runs = simulate_runs(DYNAMIC_SPECS, params, arc=arc)
    hy = hybrid(params)
    L = hy.distance
    out: dict[str, float] = {}
    met = rows = 0

    def judge(value: float, floor: str) -> None:
        nonlocal met, rows
        rows += 1
        met += value <= FLOORS[floor]

    worst_path = worst_head = 0.0
    for spec in STEP_SPECS:
        run = runs[spec.name]
        pm = {m.name: m.value for m in pose_metrics("h", run.pose, run.hybrid.pose, L)}
        judge(pm["h: worst position error"], "step position")
        judge(pm["h: worst heading error"], "step heading")
        worst_path = max(worst_path, pm["h: worst position error"])
        worst_head = max(worst_head, pm["h: worst heading error"])
    out["step position"], out["step heading"] = worst_path, worst_head
    for spec in TORQUE_SPECS:
        run = runs[spec.name]
        tw = [m.value for m in twist_metrics("h", run.twist, run.hybrid.twist, L,
                                             shift=event_shift(run))
              if m.name.endswith("error") and "worst" in m.name]
        pos = pose_metrics("h", run.pose, run.hybrid.pose, L)[0].value
        for v in tw:
            judge(v, "torque twist")
        judge(pos, "torque position")
        key = spec.name.removeprefix("torque ")
        out[f"{key} twist"], out[f"{key} position"] = max(tw), pos
    run = runs[COAST_SPEC.name]
    phys = coast_figures(run.t, run.pose, run.twist,
                         oh.kinetic_energies(hy, run.twist, run.wheel_angles))
    model = coast_figures(run.t, run.hybrid.pose, run.hybrid.twist,
                          oh.kinetic_energies(hy, run.hybrid.twist, run.hybrid.thetas))
    for name, p, m in zip(("yaw-rate decay", "turn rate", "energy loss"), phys, model,
                          strict=True):
        out[f"coast {name}"] = 100 * abs(m - p) / max(abs(p), 1e-12)
        judge(out[f"coast {name}"], "coast")
    out["met"], out["rows"] = float(met), float(rows)
    return out


def other_figures(params: OmniParams) -> dict[str, float]:
    """Kinematic scenarios' worst position error and the slip onset, as judged.

    Through the runner as ``wmr validate`` judges them, each scenario's nominal member
    (no draw): % of path and % of physics.
    """
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.validation.runner import run_scenario
    from wmr_mujoco.validation.scenarios import ScenarioKind

    worst, slip = 0.0, math.nan
    spec = get_spec("omni3")
    for s in spec.scenarios:
        if s.kind is ScenarioKind.KINEMATIC:
            rows = run_scenario(spec, s, params=params).rows
            worst = max([worst] + [r.value for r in rows
                                   if r.metric == "worst position error"])
        elif s.name == "slip onset":
            rows = run_scenario(spec, s, params=params).rows
            # The row with a target (judged, or open over the family): the nominal draw.
            slip = next(r.value for r in rows if r.target is not None)
    return {"kinematic position": worst, "slip": slip}


def wall_time(params: OmniParams, seconds: float = 1.0) -> float:
    """Wall time of the physics per simulated second, s (constant wheel torques)."""
    model, data = settled(ActuationMode.TORQUE, params)
    data.ctrl[:] = (0.04, -0.03, 0.01)
    steps = round(seconds / model.opt.timestep)
    start = time.perf_counter()
    for _ in range(steps):
        mujoco.mj_step(model, data)
    return (time.perf_counter() - start) / seconds


def study(settings: tuple[tuple[float, float], ...] = SETTINGS) -> list[dict[str, object]]:
    """One row per (setting, hybrid model: judged first); see the module docstring."""
    rows: list[dict[str, object]] = []
    for timeconst, step in settings:
        params = stiff(timeconst, step)
        other = other_figures(params)
        cost = wall_time(params)
        for arc in (True, False):
            rows.append({"timeconst": timeconst, "step": step, "arc": arc,
                         **issue_figures(params, arc), **other, "wall": cost})
    return rows


def _variant(arc: bool, shipped: bool) -> str:
    """The hybrid model's label; "as judged" only for the model ``wmr validate`` judges."""
    if not arc:
        return "without the arc's moment"
    return "with the arc's moment (as judged)" if shipped else "with the arc's moment"


def table(rows: list[dict[str, object]]) -> str:
    """Markdown table of :func:`study` rows."""
    runs = [s.name.removeprefix("torque ") for s in TORQUE_SPECS]
    head = ["contact time constant / step", "hybrid model", "issue 16 rows met",
            "steps: worst position (% of path) / heading (deg)"]
    head += [f"torque {r}: worst twist (% of peak) / position (% of path)" for r in runs]
    head += ["coast: yaw-rate decay / turn rate / energy loss (% of physics)",
             "kinematic scenarios: worst position (% of path)",
             "slip onset (% of physics)", "physics wall time per simulated second (s)"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]

    def g(x: object) -> str:
        v = float(x)  # type: ignore[arg-type]
        return f"{v:.3g}" if np.isfinite(v) else "n/a"

    for r in rows:
        cells = [f"{1000 * float(r['timeconst']):g} ms / {1000 * float(r['step']):g} ms",
                 _variant(bool(r["arc"]),
                          (float(r["timeconst"]), float(r["step"])) == SHIPPED),
                 f"{int(float(r['met']))} of {int(float(r['rows']))}",
                 f"{g(r['step position'])} / {g(r['step heading'])}"]
        cells += [f"{g(r[f'{k} twist'])} / {g(r[f'{k} position'])}" for k in runs]
        cells += [f"{g(r['coast yaw-rate decay'])} / {g(r['coast turn rate'])} / "
                  f"{g(r['coast energy loss'])}", g(r["kinematic position"]), g(r["slip"]),
                  g(r["wall"])]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:  # pragma: no cover - a couple of minutes
    """Print the stiffness table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.parse_args(argv)
    print(table(study()))


if __name__ == "__main__":  # pragma: no cover
    main()
