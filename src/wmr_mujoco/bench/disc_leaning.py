"""The free disc's leaning-start family against the contact's time constant.

``python -m wmr_mujoco.bench.disc_leaning`` runs every draw of ``disc_free``'s
``leaning start`` family (its declared draws, seed 0) under a few timestep and contact
settings and writes the worst errors of each between the ``disc leaning family``
markers of ``models/disc/README.md``.

Why: the family's slower draws (toward the upright disc's stability limit) miss the
leaning start's targets at the defaults. The rows separate the two candidate causes.
MuJoCo's ``refsafe`` flag clamps a contact's time constant to at least two timesteps,

    t_c,eff = max(t_c, 2 Δt),

so the default (RK4 at ``free_timestep``, ``solref`` ``sim.contact_timeconst``, both of
:class:`~wmr_mujoco.robots.disc.params.FreeDiscParams`) simulates a contact of two of its
steps whenever its time constant is shorter than that. Rows that
change ``Δt`` at a fixed ``t_c,eff`` isolate the integrator; rows that change ``t_c``
isolate the contact. The errors follow ``t_c,eff``, to first order, and not ``Δt``: they
are the soft contact's, and meeting the targets over the family costs the timestep the
last rows need (``evals/s``: model evaluations per simulated second, RK4 four a step).
"""

from __future__ import annotations

import argparse

from wmr_mujoco.bench.disc_study import Setting
from wmr_mujoco.docs_sync.markers import replace_between
from wmr_mujoco.models.paths import MODELS_DIR
from wmr_mujoco.robots import disc_free
from wmr_mujoco.robots.disc.params import FreeDiscParams
from wmr_mujoco.robots.disc_free import measurements as ms

MARKER = "disc leaning family"
README = MODELS_DIR / "disc" / "README.md"
SCENARIO = "leaning start"
#: Columns: (heading, judged metric of ``measurements.leaning_start``, unit).
COLUMNS = (
    ("path", "worst contact path error, first 5 s", "% of path"),
    ("lean", "worst lean error, first 5 s", "deg"),
    ("energy", "worst energy drift", "%"),
)


def rk4_setting(timestep: float, contact_timeconst: float) -> Setting:
    """The free disc under RK4 at ``timestep`` with ``contact_timeconst``, else the defaults.

    A :class:`~wmr_mujoco.bench.disc_study.Setting` (the fidelity study's), labelled with
    the time constant MuJoCo simulates.
    """
    label = (f"Δt {1e3 * timestep:g} ms, t_c {1e3 * contact_timeconst:g} ms (effective "
             f"{1e3 * effective_timeconst(timestep, contact_timeconst):g} ms)")
    return Setting(label, "RK4", timestep, contact_timeconst=contact_timeconst)


def effective_timeconst(timestep: float, contact_timeconst: float) -> float:
    """``max(t_c, 2 Δt)``: the time constant MuJoCo simulates (``refsafe``)."""
    return max(contact_timeconst, 2.0 * timestep)


#: The default first (its step and contact time constant read from ``FreeDiscParams``; the
#: label shows the clamped time constant), then the same effective contact (8 ms) at a smaller
#: timestep, then ever stiffer contacts at ``t_c = 2 Δt``.
SETTINGS = (
    rk4_setting(FreeDiscParams().free_timestep, FreeDiscParams().sim.contact_timeconst),
    rk4_setting(0.002, 0.008),
    rk4_setting(0.002, 0.004),
    rk4_setting(0.001, 0.004),
    rk4_setting(0.001, 0.002),
    rk4_setting(0.0005, 0.001),
)


def family_draws(seed: int = 0) -> list[dict[str, float]]:
    """The leaning start's draws (``lean``, ``speed``) at ``seed``."""
    scenario = next(s for s in disc_free.SPEC.scenarios if s.name == SCENARIO)
    return scenario.family.sample(seed, scenario.key)


def evaluate(setting: Setting, draws: list[dict[str, float]]) -> dict[str, float]:
    """Worst of each column over ``draws`` under ``setting``.

    Also the speed of the draw with the worst lean error, the targets (``"<column>
    target"``) and the model evaluations per simulated second.
    """
    model = setting.model()
    worst = {head: 0.0 for head, _, _ in COLUMNS}
    slowest = {head: float("nan") for head, _, _ in COLUMNS}
    targets: dict[str, float] = {}
    for draw in draws:
        result = ms.leaning_start(model, draw["lean"], draw["speed"])
        values = {m.name: abs(m.value) for m in result.metrics}
        targets = {m.name: m.target.value for m in result.metrics if m.target is not None}
        for head, name, _ in COLUMNS:
            if values[name] > worst[head]:
                worst[head], slowest[head] = values[name], draw["speed"]
    return {**worst, "speed": slowest["lean"], "evals": setting.evaluations_per_second,
            **{f"{head} target": targets[name] for head, name, _ in COLUMNS}}


def table(rows: list[tuple[Setting, dict[str, float]]], draws: int) -> str:
    """Markdown table of the study, with the targets."""
    first = rows[0][1]
    heads = [f"worst {h} ({u}; target {first[f'{h} target']:g})" for h, _, u in COLUMNS]
    lines = ["| RK4 setting | " + " | ".join(heads) + " | speed of the worst lean draw (m/s) "
             "| evals/s |", "|---|" + "---|" * (len(heads) + 2)]
    for setting, r in rows:
        cells = [f"{r[h]:.3g}" for h, _, _ in COLUMNS]
        lines.append(f"| {setting.label} | " + " | ".join(cells)
                     + f" | {r['speed']:.3g} | {r['evals']:.0f} |")
    return "\n".join(lines) + (
        f"\n\nEach row: the worst over the family's {draws} draws (seed 0, lean and speed "
        f"within ±20 % of {ms.LEANING_START[0]:g} rad and {ms.LEANING_START[1]:g} m/s), "
        "against the nonlinear rolling-disc equations. "
        "`python -m wmr_mujoco.bench.disc_leaning` regenerates it.")


def main(argv: list[str] | None = None) -> None:
    """Run the study and paste the table into the disc README (``--dry-run``: print)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dry-run", action="store_true", help="print, do not write")
    args = parser.parse_args(argv)
    draws = family_draws()
    rows = []
    for setting in SETTINGS:
        print(f"  {setting.label} ...", flush=True)
        rows.append((setting, evaluate(setting, draws)))
    text = table(rows, len(draws))
    print(text)
    if not args.dry_run:
        replace_between(README, MARKER, text)
        print(f"wrote {README}")


if __name__ == "__main__":
    main()
