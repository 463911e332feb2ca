"""Fidelity versus cost of the free rolling disc: ``python -m wmr_mujoco.bench.disc_study``.

Also writes every metric of the disc's rolling and sliding measurement scenarios at the
default settings (through the validation runner) between the ``disc dynamics`` markers.

Runs the free-disc measurements of :mod:`wmr_mujoco.robots.disc_free.measurements` under
a small set of
simulation settings (integrator, timestep, contact softness, noslip iterations,
impratio, collider) and writes a table of each setting's worst errors and real-time factor
between the ``disc study`` markers of ``models/disc/README.md``. The cheapest setting
that meets every target (fewest model evaluations per simulated second: RK4 evaluates
the model 4 times a step, the Euler-type integrators once) is marked; it is the
default in :class:`~wmr_mujoco.robots.disc.params.DiscParams` (``free_*``) when the table says
so.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from dataclasses import dataclass, replace

import mujoco
import numpy as np

from wmr_mujoco.docs_sync.markers import replace_between
from wmr_mujoco.lookup import build_scene
from wmr_mujoco.models.builders import common
from wmr_mujoco.models.paths import MODELS_DIR
from wmr_mujoco.robots import disc, disc_free
from wmr_mujoco.robots.disc.params import DiscParams, FreeDiscParams
from wmr_mujoco.robots.disc_free import measurements as ms
from wmr_mujoco.robots.disc_free.state import disc_from_model, set_free_state
from wmr_mujoco.validation.metrics import Metric
from wmr_mujoco.validation.report import markdown_table
from wmr_mujoco.validation.runner import run_all
from wmr_mujoco.validation.scenarios import MeasurementResult, ScenarioKind

MARKER = "disc study"
VALIDATION_MARKER = "disc dynamics"
README = MODELS_DIR / "disc" / "README.md"
#: The free-disc measurements at their default arguments, by scenario name.
MEASUREMENTS: dict[str, Callable[[mujoco.MjModel], MeasurementResult]] = {
    "incline": ms.incline, "stability sweep": ms.stability_sweep,
    "steady precession": ms.steady_precession, "leaning start": ms.leaning_start}
#: Columns of the table: (heading, scenario, judged metric name, unit).
COLUMNS = (
    ("incline a", "incline", "worst incline acceleration error", "%"),
    ("v_c", "stability sweep", "threshold speed error", "%"),
    ("precession θ", "steady precession", "worst lean error", "%"),
    ("precession R", "steady precession", "worst circle radius error", "%"),
    ("lean-start path", "leaning start", "worst contact path error, first 5 s", "% of path"),
    ("lean-start θ", "leaning start", "worst lean error, first 5 s", "deg"),
    ("energy", "leaning start", "worst energy drift", "%"),
)


#: The free disc's defaults: a setting changes only what its label names.
_DEFAULT = FreeDiscParams()


@dataclass(frozen=True)
class Setting:
    """One simulation setting of the free disc: the defaults but what ``label`` names.

    Attributes:
        label: short description.
        integrator: MuJoCo integrator name.
        timestep: s.
        rim: collision half-thickness (ellipsoid ``(R, rim, R)``; cylinder half-length).
        contact_timeconst: ``solref[0]``, s.
        solimp_width: ``solimp[1]`` (``solimp[0]`` is 0.04 below it); 0.99 is the default.
        noslip: ``noslip_iterations``.
        impratio: frictional/normal impedance ratio.
        collider: ``"ellipsoid"`` or ``"cylinder"``.
    """

    label: str
    integrator: str = _DEFAULT.free_integrator
    timestep: float = _DEFAULT.free_timestep
    rim: float = _DEFAULT.free_rim
    contact_timeconst: float = _DEFAULT.sim.contact_timeconst
    solimp_width: float = 0.99
    noslip: int = 0
    impratio: float = _DEFAULT.sim.impratio
    collider: str = "ellipsoid"

    @property
    def evaluations_per_second(self) -> float:
        """Model evaluations per simulated second (RK4: 4 a step)."""
        return (4.0 if self.integrator == "RK4" else 1.0) / self.timestep

    def model(self, params: DiscParams | None = None) -> mujoco.MjModel:
        """The free disc and floor compiled under this setting (``params`` None: defaults)."""
        params = FreeDiscParams() if params is None else params
        p = replace(params, free_integrator=self.integrator, free_timestep=self.timestep,
                    free_rim=self.rim,
                    sim=replace(params.sim, contact_timeconst=self.contact_timeconst,
                                impratio=self.impratio))
        root = build_scene("disc_free", p)
        root.option.noslip_iterations = self.noslip
        geom = root.find("geom", "disc_collision")
        geom.solimp = (self.solimp_width - 0.04, self.solimp_width, 0.001, 0.5, 2.0)
        if self.collider == "cylinder":
            r = p.wheel.radius
            geom.type = "cylinder"
            geom.size = (r, self.rim)
            geom.zaxis = (0, 1, 0)
        return mujoco.MjModel.from_xml_string(common.to_xml(root))


SETTINGS = (
    Setting("implicitfast 2 ms, 10 mm rim, t_c 4 ms (previous default)", "implicitfast", 0.002,
            0.01, contact_timeconst=0.004),
    Setting("implicitfast 2 ms", "implicitfast", 0.002),
    Setting("implicitfast 0.5 ms", "implicitfast", 0.0005),
    Setting("implicit 2 ms", "implicit", 0.002),
    Setting("implicit 0.5 ms", "implicit", 0.0005),
    Setting("RK4 2 ms, 10 mm rim", "RK4", 0.002, 0.01),
    Setting("RK4 2 ms", "RK4", 0.002),
    Setting("RK4 4 ms", "RK4", 0.004),
    Setting("RK4 8 ms", "RK4", 0.008),
    Setting("RK4 4 ms, solref 20 ms (softer)", contact_timeconst=0.02),
    Setting("RK4 4 ms, solimp 0.999 (harder)", solimp_width=0.999),
    Setting("RK4 4 ms, noslip 10", noslip=10),
    Setting("RK4 4 ms, impratio 1", impratio=1.0),
    Setting("RK4 4 ms, cylinder collider", collider="cylinder"),
)


def real_time_factor(model: mujoco.MjModel, sim_seconds: float = 2.0,
                     repeats: int = 3) -> float:
    """Simulated over wall-clock seconds of bare ``mj_step`` (leaning start, one thread).

    Best of ``repeats`` runs: on a shared machine the fastest run is the one least
    disturbed by other load.
    """
    data = mujoco.MjData(model)
    disc = disc_from_model(model)
    n = round(sim_seconds / model.opt.timestep)
    best = float("inf")
    for _ in range(repeats):
        set_free_state(model, data, disc, disc.initial_state(*ms.LEANING_START))
        start = time.perf_counter()
        for _ in range(n):
            mujoco.mj_step(model, data)
        best = min(best, time.perf_counter() - start)
    return sim_seconds / best


def _passed(m: Metric) -> bool:
    return m.target is None or bool(np.isfinite(m.value) and abs(m.value) <= m.target.value)


def evaluate(setting: Setting) -> dict[str, float | bool | str]:
    """Worst errors of every free-disc measurement, pass/fail and real-time factor.

    Pass: every judged metric of every measurement within its target (the targets of
    the measurements themselves).
    """
    model = setting.model()
    row: dict[str, float | bool | str] = {"label": setting.label}
    metrics: dict[tuple[str, str], Metric] = {}
    try:
        for name, measure in MEASUREMENTS.items():
            metrics.update({(name, m.name): m for m in measure(model).metrics})
        row["passed"] = all(_passed(m) for m in metrics.values())
    except Exception as exc:  # a diverging run is a result of the study, reported
        row.update(passed=False, error=f"{type(exc).__name__}")
    for head, scenario, name, _ in COLUMNS:
        m = metrics.get((scenario, name))
        row[head] = abs(m.value) if m is not None else float("nan")
        if m is not None and m.target is not None:
            row[f"{head} target"] = m.target.value
    row["rtf"] = real_time_factor(model)
    row["evals"] = setting.evaluations_per_second
    return row


def study(settings: tuple[Setting, ...] = SETTINGS) -> list[dict[str, float | bool | str]]:
    """Evaluate every setting."""
    return [evaluate(s) for s in settings]


def margin(row: dict[str, float | bool | str]) -> float:
    """Largest error/target ratio of a row (< 1: every target met; NaN-free rows only)."""
    return max(abs(float(row[h])) / float(row.get(f"{h} target", np.inf))
               for h, _, _, _ in COLUMNS)


def cheapest_passing(rows: list[dict[str, float | bool | str]]) -> int | None:
    """Index of the passing row with the fewest model evaluations per simulated second.

    Among equals, the one furthest inside its targets (not the wall clock: it is noisy).
    """
    ok = [i for i, r in enumerate(rows) if r.get("passed")]
    return min(ok, key=lambda i: (rows[i]["evals"], margin(rows[i]))) if ok else None


def table(rows: list[dict[str, float | bool | str]]) -> str:
    """Markdown table of the study; the chosen default in bold."""
    best = cheapest_passing(rows)
    heads = [f"{h} ({u})" for h, _, _, u in COLUMNS]
    lines = ["| setting | " + " | ".join(heads) + " | all targets | evals/s | RTF |",
             "|---|" + "---|" * (len(heads) + 3)]
    for i, r in enumerate(rows):
        label = f"**{r['label']}** (chosen)" if i == best else str(r["label"])
        cells = [f"{r[h]:.3g}" for h, _, _, _ in COLUMNS]
        verdict = "yes" if r.get("passed") else f"no {r.get('error', '')}".strip()
        lines.append(f"| {label} | " + " | ".join(cells)
                     + f" | {verdict} | {r['evals']:.0f} | {r['rtf']:.0f} |")
    targets = ("Targets (requirements, issue 13): incline 0.5 %, v_c 2 %, precession lean and "
               "radius 1 % over a full circle, leaning-start path 1 % of path and lean 1°, "
               "energy drift 0.5 % over 10 s. Errors are the worst over each run. RTF: "
               "simulated/wall seconds of bare `mj_step`, one thread, best of 3 on a shared "
               "machine.")
    return "\n".join(lines) + "\n\n" + targets


def validation_table() -> str:
    """Every metric of the disc's measurement scenarios at the defaults (Markdown).

    Run through the validation runner, tabulated as in the validation report.
    """
    work = [(spec, s) for spec in (disc_free.SPEC, disc.SPEC) for s in spec.scenarios
            if s.kind is ScenarioKind.MEASUREMENT]
    return markdown_table(run_all(work))


def main(argv: list[str] | None = None) -> None:
    """Run the study and paste the table into the disc README (``--dry-run``: print)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dry-run", action="store_true", help="print, do not write")
    args = parser.parse_args(argv)
    text = table(study())
    checks = validation_table()
    print(text, checks, sep="\n\n")
    if not args.dry_run:
        replace_between(README, MARKER, text)
        replace_between(README, VALIDATION_MARKER, checks)
        print(f"wrote {README}")


if __name__ == "__main__":
    main()

