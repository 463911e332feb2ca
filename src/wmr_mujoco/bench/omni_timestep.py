"""omni3's torque runs at several simulation steps: how far the physics is from itself.

``python -m wmr_mujoco.bench.omni_timestep`` (part of ``make study`` through
:mod:`~wmr_mujoco.bench.omni_energy_study`, which pastes the table into
``docs/omni-dynamics.md``).

The judged torque figures compare the hybrid model with MuJoCo at the model's own step
Δt. The physics is itself a discretisation: this study runs the same torque inputs at
finer steps and reports, per run and step,

1. the physics against the physics at the finest step (``REFERENCE``), sampled on the
   coarsest grid: how much of a figure is the simulator's time discretisation (each
   roller hand-over is a velocity jump the simulator resolves on its step grid);
   each figure twice: the same samples at the same instant, and with jumps allowed one
   sample of the coarse grid apart
   (:func:`~wmr_mujoco.robots.roller_wheels.twist_errors.event_aligned_error`);
2. the hybrid model against the physics at that step (the judged figures at the model's
   own step), sample by sample and with jumps allowed one sample apart (judged where the
   model's wheel phase stays within one step's turn); as judged (the weight's moment
   over the roller arc, each hand-over spread as the soft contact does it at that step),
   with each hand-over made at once (the rigid impact map), and without the arc's
   moment (:data:`VARIANTS`; ``docs/omni-dynamics.md`` §§ 5, 10-11); with the model's
   hand-over relaxation ρ at that step (``sim/soft_contact.py``; 0 where the variant
   makes each hand-over at once) and its worst wheel phase against the physics' in
   steps' turns, signed (:func:`~wmr_mujoco.robots.omni3.runs.phase_lag_steps`: how many
   samples its hand-overs fall from the physics'; the premise of the allowance);
3. the semi-implicit position lead: MuJoCo advances ``q_{n+1} = q_n + Δt v_{n+1}``, so

       q_n − q_0 = Δt Σ_{k=1..n} v_k = Δt Σ (v_{k−1} + v_k)/2 + (Δt/2)(v_n − v_0),

   i.e. its positions lead the trapezoidal integral of its own velocity samples by
   ``(Δt/2)(v_n − v_0)`` (:func:`position_lead`), a first-order start-up term of the
   integrator; its worst size is given in % of path.

4. the coast after (0.3, 0, 1) at each step and at the reference (:func:`coast_convergence`):
   the coast's three figures (yaw-rate decay, velocity-direction turn rate, energy lost
   per second) of the physics and of the hybrid model, and their relative difference as
   judged (the hybrid model as judged).

Scales as the judged metrics (:func:`~wmr_mujoco.robots.roller_wheels.twist_errors.twist_metrics`,
:func:`~wmr_mujoco.robots.omni3.dynamics.pose_metrics`).
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Sequence

import numpy as np

from wmr_mujoco.robots.omni3.coasting import COAST_SPEC, coast_figures
from wmr_mujoco.robots.omni3.dynamics import (
    EVENT_SHIFT,
    TORQUE_SPECS,
    path_length,
    pose_metrics,
)
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import hybrid, hybrid_at, phase_lag_steps, simulate_runs
from wmr_mujoco.robots.roller_wheels import omni_hybrid as oh
from wmr_mujoco.robots.roller_wheels.twist_errors import twist_metrics

#: Steps compared, s (the first is the model's own, as ``wmr validate`` runs it; then
#: half and a quarter of it), and the reference step (a quarter of it).
MODEL_STEP = OmniParams().sim.timestep
STEPS = (MODEL_STEP, MODEL_STEP / 2, MODEL_STEP / 4)
REFERENCE = MODEL_STEP / 4
#: Hybrid models compared: label, the weight's moment over the arc, the soft contact's
#: hand-over relaxation (:func:`~wmr_mujoco.robots.omni3.runs.simulate_runs`).
VARIANTS = (("with the arc's moment (as judged)", True, True),
            ("hand-overs at once (rigid impact)", True, False),
            ("without the arc's moment", False, True))


def world_velocity(pose: np.ndarray, twist: np.ndarray) -> np.ndarray:
    """``(Ẋ, Ẏ) = R(ψ) (u, v)`` of (N, 3) poses and body twists, (N, 2)."""
    c, s = np.cos(pose[:, 2]), np.sin(pose[:, 2])
    return np.column_stack([c * twist[:, 0] - s * twist[:, 1],
                            s * twist[:, 0] + c * twist[:, 1]])


def position_lead(pose: np.ndarray, twist: np.ndarray, dt: float) -> np.ndarray:
    """Semi-implicit Euler's lead over the trapezoidal integral, ``(Δt/2)(v_n − v_0)``, (N, 2).

    Raises:
        ValueError: a non-positive or non-finite ``dt``, or mismatched arrays.
    """
    if not (math.isfinite(dt) and dt > 0):
        raise ValueError(f"dt = {dt!r} s; valid range is (0, inf)")
    if pose.shape != twist.shape or pose.ndim != 2 or pose.shape[1] != 3:
        raise ValueError(f"pose {pose.shape} and twist {twist.shape} must both be (N, 3)")
    v = world_velocity(pose, twist)
    return 0.5 * dt * (v - v[0])


def _worst(metrics: list, prefix: str) -> dict[str, float]:
    """Worst figures of twist and pose metric lists.

    Keys: ``u``, ``v``, ``r``, ``position``, and ``<c> sample by sample`` where reported.
    """
    out = {}
    for m in metrics:
        for key in ("u", "v", "r"):
            if m.name == f"{prefix}: worst {key} error":
                out[key] = m.value
            if m.name == f"{prefix}: worst {key} error, sample by sample":
                out[f"{key} sample by sample"] = m.value
        if m.name == f"{prefix}: worst position error":
            out["position"] = m.value
    return out


def convergence(steps: Sequence[float] = STEPS, reference: float = REFERENCE,
                specs: Sequence = TORQUE_SPECS) -> list[dict[str, object]]:
    """One row per (run, step): physics vs reference, hybrid vs physics, position lead.

    Every step must be a whole multiple of ``reference``; all runs are sampled on the
    grid of the coarsest step.

    Raises:
        ValueError: an empty or bad list of steps, or a step that is not a multiple of
            the reference.
    """
    if not steps:
        raise ValueError("steps is empty; give at least one simulation step")
    for h in (*steps, reference):
        if not (math.isfinite(h) and 0 < h <= 0.01):
            raise ValueError(f"step = {h!r} s; valid range is (0, 0.01] s")
    coarse = max(steps)
    for h in steps:
        if abs(coarse / h - round(coarse / h)) > 1e-9 or abs(h / reference
                                                            - round(h / reference)) > 1e-9:
            raise ValueError(f"step = {h!r} s must divide {coarse!r} s and be a multiple "
                             f"of the reference {reference!r} s")
    L = hybrid(None).distance
    ref = simulate_runs(specs, timestep=reference)
    rows: list[dict[str, object]] = []
    rho = {h: hybrid_at(h).handover_relaxation for h in steps}
    for h, (variant, arc, relax) in ((h, v) for h in steps for v in VARIANTS):
        runs = simulate_runs(specs, timestep=h, arc=arc, relax=relax)
        for spec in specs:
            run, base = runs[spec.name], ref[spec.name]
            s, sr = round(coarse / h), round(coarse / reference)
            n = min(len(run.t[::s]), len(base.t[::sr]))
            phys = _worst(twist_metrics("p", base.twist[::sr][:n], run.twist[::s][:n], L,
                                        shift=EVENT_SHIFT)
                          + pose_metrics("p", base.pose[::sr][:n], run.pose[::s][:n], L), "p")
            dyn = run.hybrid
            model = _worst(twist_metrics("h", run.twist, dyn.twist, L, shift=EVENT_SHIFT)
                           + pose_metrics("h", run.pose, dyn.pose, L), "h")
            lead = np.linalg.norm(position_lead(run.pose, run.twist, h), axis=1).max()
            rows.append({"run": spec.name, "step": h, "rho": rho[h] if relax else 0.0,
                         "variant": variant, "physics": phys,
                         "hybrid": model, "phase": phase_lag_steps(run),
                         "lead": 100 * float(lead) / max(path_length(run.pose, L), 1e-9)})
    return rows


def table(rows: list[dict[str, object]], reference: float = REFERENCE) -> str:
    """Markdown table of :func:`convergence` rows."""
    ref = f"{1000 * reference:g} ms"
    lines = [f"| run | Δt | hybrid model | ρ, a hand-over's share left after a step | "
             f"physics vs physics at {ref}: worst u, v, r "
             "(% of peak), sample by sample | the same, jumps one sample apart | "
             f"physics vs physics at {ref}: worst position (% of path) | "
             "hybrid vs physics: worst u, v, r (% of peak), sample by sample | "
             "the same, jumps one sample apart (judged where the wheel phase is within a "
             "step's turn) | "
             "hybrid vs physics: worst position (% of path) | "
             "hybrid vs physics: worst wheel phase (steps' turns, − behind) | "
             "semi-implicit position lead (% of path) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]

    def trio(figures: dict[str, float], suffix: str = "") -> str:
        return " / ".join(f"{figures[c + suffix]:.3g}" for c in "uvr")

    for row in rows:
        p, h = row["physics"], row["hybrid"]
        variant = row["variant"]
        point = " sample by sample"
        lines.append(f"| {row['run']} | {1000 * float(row['step']):g} ms | {variant} | "
                     f"{float(row['rho']):.3g} | "
                     f"{trio(p, point)} | {trio(p)} | {p['position']:.3g} | "
                     f"{trio(h, point)} | {trio(h)} | {h['position']:.3g} | "
                     f"{float(row['phase']):+.2f} | {float(row['lead']):.3g} |")
    return "\n".join(lines)


#: The coast's figures, in the order of :func:`~wmr_mujoco.robots.omni3.coasting.coast_figures`.
COAST_FIGURES = (("yaw-rate decay", "rad/s²"), ("velocity-direction turn rate", "rad/s"),
                 ("energy lost per second", "W"))


def coast_convergence(steps: Sequence[float] = tuple(dict.fromkeys((*STEPS, REFERENCE)))
                      ) -> list[dict[str, object]]:
    """One row per step: the coast's figures, physics and hybrid model (as judged).

    Raises:
        ValueError: an empty list, or a step outside (0, 0.01] s.
    """
    if not steps:
        raise ValueError("steps is empty; give at least one simulation step")
    hy = hybrid(None)
    rows: list[dict[str, object]] = []
    for h in steps:
        run = simulate_runs([COAST_SPEC], timestep=h)[COAST_SPEC.name]
        dyn = run.hybrid
        phys = coast_figures(run.t, run.pose, run.twist,
                             oh.kinetic_energies(hy, run.twist, run.wheel_angles))
        model = coast_figures(run.t, dyn.pose, dyn.twist,
                              oh.kinetic_energies(hy, dyn.twist, dyn.thetas))
        rows.append({"step": h, "physics": phys, "hybrid": model})
    return rows


def coast_table(rows: list[dict[str, object]]) -> str:
    """Markdown table of :func:`coast_convergence` rows."""
    head = ["Δt"]
    for name, unit in COAST_FIGURES:
        head += [f"{name}, physics ({unit})", f"{name}, hybrid ({unit})",
                 f"{name}: hybrid vs physics (% of physics)"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for row in rows:
        cells = [f"{1000 * float(row['step']):g} ms"]
        for p, h in zip(row["physics"], row["hybrid"], strict=True):  # type: ignore[call-overload]
            cells += [f"{p:.4g}", f"{h:.4g}", f"{100 * abs(h - p) / max(abs(p), 1e-12):.3g}"]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:  # pragma: no cover - about half a minute
    """Print the convergence table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.parse_args(argv)
    print(table(convergence()), "", coast_table(coast_convergence()), sep="\n")


if __name__ == "__main__":  # pragma: no cover
    main()
