"""Where omni3's coasting energy goes, and the dynamics tables of ``docs/omni-dynamics.md``.

``python -m wmr_mujoco.bench.omni_energy_study`` (``make study``, a few minutes):

1. the coasting energy budget (:func:`coast_energy_budget`) of four coasts: the default
   contacts, softer and stiffer ones (the roller-floor pairs' time constants of
   :data:`~wmr_mujoco.bench.omni_stiffness.SOFTER` and
   :data:`~wmr_mujoco.bench.omni_stiffness.STIFFER`, nearer the rigid limit), and a pure
   translation at the default;
2. omni3's dynamic scenarios (step commands, torque inputs, coasting, slip onset)
   through the one runner (:func:`~wmr_mujoco.validation.runner.run_all`), every row;
3. the torque runs and the coast at finer simulation steps
   (:mod:`~wmr_mujoco.bench.omni_timestep`);
4. the roller-row overlaps of the coast (:mod:`~wmr_mujoco.bench.omni_overlap`);
5. the dynamic targets against the contacts' stiffness, with the cost
   (:mod:`~wmr_mujoco.bench.omni_stiffness`, a couple of minutes);

and pastes the tables between the markers of ``docs/omni-dynamics.md``.

The budget instruments every step (too slow for ``wmr validate``): the work of every
contact constraint force over a step, ``f · J (q̇ₖ + q̇ₖ₊₁)/2 Δt``, split into its normal
row (contact damping: the hand-over impacts and the soft contact's own loss) and its
tangential rows (slip), and by whether two rollers of that wheel touch at once (the
rows' overlap). Their sum is checked against the change of kinetic + potential energy
(closure row).
"""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.bench import omni_stiffness
from wmr_mujoco.docs_sync.markers import publish, study_parser
from wmr_mujoco.models.builders.wheel_pairs import WHEEL_PAIR_STEPS
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import coast_start, contact_wheels
from wmr_mujoco.sim.stepping import check_healthy
from wmr_mujoco.validation.metrics import Metric

DOC = Path(__file__).resolve().parents[3] / "docs" / "omni-dynamics.md"


def contact_params(timeconst: float) -> OmniParams:
    """omni3 with roller-floor pairs of ``solref`` time constant ``timeconst``.

    The step is :data:`~wmr_mujoco.models.builders.wheel_pairs.WHEEL_PAIR_STEPS` times
    shorter (the pairs' least time constant; the defaults' ratio).

    Raises:
        ValueError: a time constant outside (0, 0.1] s.
    """
    if not (math.isfinite(timeconst) and 0 < timeconst <= 0.1):
        raise ValueError(f"contact_timeconst = {timeconst!r}; valid range is (0, 0.1] s")
    return omni_stiffness.stiff(timeconst, timeconst / WHEEL_PAIR_STEPS)


def coast_energy_budget(twist: tuple[float, float, float] = (0.3, 0.0, 1.0),
                        drive_time: float = 1.5, duration: float = 3.0,
                        contact_timeconst: float | None = None) -> list[Metric]:
    """Where a coast's kinetic energy goes, measured in the physics, step by step.

    ``contact_timeconst`` (None: the defaults): the roller-floor pairs' time constant, s
    (:func:`contact_params`).

    Raises:
        ValueError: non-finite twist, bad durations or contact time constant.
    """
    if not (math.isfinite(duration) and 0 < duration <= 30):
        raise ValueError(f"duration = {duration!r} s; valid range is (0, 30] s")
    params = None if contact_timeconst is None else contact_params(contact_timeconst)

    def setup(model: mujoco.MjModel) -> None:
        model.opt.enableflags |= mujoco.mjtEnableBit.mjENBL_ENERGY

    model, data = coast_start(twist, drive_time, setup, params)
    dt = model.opt.timestep
    energy0 = float(data.energy[0] + data.energy[1])
    work = {"single normal": 0.0, "single tangential": 0.0, "overlap normal": 0.0,
            "overlap tangential": 0.0}
    contact_floor = int(mujoco.mjtConstraint.mjCNSTR_CONTACT_FRICTIONLESS)
    for _ in range(round(duration / dt)):
        q0 = data.qvel.copy()
        mujoco.mj_step(model, data)
        jv = np.zeros(data.nefc)
        mujoco.mj_mulJacVec(model, data, jv, 0.5 * (q0 + data.qvel))
        wheel = contact_wheels(model, data)
        per_wheel = np.bincount(wheel[wheel >= 0], minlength=3)
        for j in range(data.nefc):
            ci = int(data.efc_id[j])
            if data.efc_type[j] < contact_floor or ci >= data.ncon or wheel[ci] < 0:
                continue
            normal = j == 0 or data.efc_id[j - 1] != ci or data.efc_type[j - 1] < contact_floor
            key = ("overlap " if per_wheel[wheel[ci]] >= 2 else "single ") + (
                "normal" if normal else "tangential")
            work[key] += float(data.efc_force[j] * jv[j]) * dt
    check_healthy(model, data)
    mujoco.mj_forward(model, data)
    change = float(data.energy[0] + data.energy[1]) - energy0
    total = sum(work.values())
    out = [Metric(f"contact work, {k}, per second", v / duration, "W") for k, v in work.items()]
    out += [Metric("contact work, total, per second", total / duration, "W"),
            Metric("mechanical energy change per second", change / duration, "W"),
            Metric("closure: |work − change| / |change|",
                   abs(total - change) / max(abs(change), 1e-12), "")]
    return out


def budget_table(budgets: dict[str, list[Metric]]) -> str:
    """Markdown table of budgets by label."""
    lines = ["| coast | metric | value | unit |", "|---|---|---|---|"]
    for label, rows in budgets.items():
        lines += [f"| {label} | {m.name.replace('|', chr(92) + '|')} | {m.value:.4g} | "
                  f"{m.unit} |" for m in rows]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:  # pragma: no cover - a few minutes
    """Run the budgets and omni3's dynamic scenarios; print and paste the tables."""
    from wmr_mujoco.bench import omni_overlap, omni_timestep
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.validation.report import markdown_table
    from wmr_mujoco.validation.runner import run_all
    from wmr_mujoco.validation.scenarios import ScenarioKind

    args = study_parser(__doc__.splitlines()[0]).parse_args(argv)
    default = f"default contacts (solref {1000 * OmniParams().sim.contact_timeconst:g} ms)"
    soft, stiff = omni_stiffness.SOFTER[0], omni_stiffness.STIFFER[0]
    budgets = {f"(0.3, 0, 1), {default}": coast_energy_budget(),
               f"(0.3, 0, 1), solref {1000 * soft:g} ms": coast_energy_budget(
                   contact_timeconst=soft),
               f"(0.3, 0, 1), solref {1000 * stiff:g} ms": coast_energy_budget(
                   contact_timeconst=stiff, duration=2.0),
               f"(0.3, 0, 0), {default}": coast_energy_budget((0.3, 0.0, 0.0))}
    spec = get_spec("omni3")
    work = [(spec, s) for s in spec.scenarios if s.kind is ScenarioKind.MEASUREMENT]
    publish(DOC, {
        "omni dynamics: results": markdown_table(run_all(work)),
        "omni dynamics: energy budget": budget_table(budgets),
        "omni dynamics: time step": omni_timestep.table(omni_timestep.convergence()),
        "omni dynamics: coast time step": omni_timestep.coast_table(
            omni_timestep.coast_convergence()),
        "omni dynamics: overlap windows": omni_overlap.table(omni_overlap.overlap_windows()),
        "omni dynamics: contact stiffness": omni_stiffness.table(omni_stiffness.study()),
    }, not args.no_write)


if __name__ == "__main__":  # pragma: no cover
    main()
