"""Where one step of a robot's time goes, by MuJoCo's own timers.

For :mod:`wmr_mujoco.bench.solver_cost`: :func:`profile` runs a prepared drive
(:mod:`wmr_mujoco.bench.default_speed`'s: the random-steps family's member 0 from the
settled robot) and reads ``data.timer`` of each
stage of ``mj_step`` (:data:`STAGES`) and the solver's counts per step: iterations
``solver_niter``, line-search cost evaluations ``Σ solver[i].neval``, contacts ``ncon``
and constraint rows ``nefc``.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import mujoco
import numpy as np

from wmr_mujoco.bench.default_speed import Timed
from wmr_mujoco.sim.stepped_inputs import CONTROL_PERIOD

#: MuJoCo's timers of one step's stages, in the order of ``mj_step``.
STAGES = ("POS_KINEMATICS", "POS_INERTIA", "COL_BROAD", "COL_NARROW", "POS_MAKE",
          "POS_PROJECT", "VELOCITY", "ACTUATION", "CONSTRAINT", "ADVANCE")


@dataclasses.dataclass(frozen=True)
class Profile:
    """Where one step's time goes, averaged over a drive.

    Attributes:
        us: µs per step of each of :data:`STAGES`, then ``"STEP"`` (the whole step).
        niter: mean solver iterations per step.
        neval: mean line-search cost evaluations per step.
        ncon: mean contacts per step.
        nefc: mean constraint rows per step.
        timestep: the model's step, s.
    """

    us: dict[str, float]
    niter: float
    neval: float
    ncon: float
    nefc: float
    timestep: float

    @property
    def free_solver_speedup(self) -> float:
        """How much faster a step would be with a free solver: ``step / (step − solver)``.

        What no solver setting can beat at this timestep: the other stages' cost stays. A
        share, so it carries over to a real-time factor timed at another moment of a
        shared machine (:mod:`wmr_mujoco.bench.solver_cost`'s table).
        """
        return self.us["STEP"] / (self.us["STEP"] - self.us["CONSTRAINT"])


def run_drive(t: Timed, per_step: Any = None) -> int:
    """Run the prepared drive from its settled state; ``per_step(data)`` after each step."""
    m, d = t.model, t.data
    mujoco.mj_setState(m, d, t.state, mujoco.mjtState.mjSTATE_INTEGRATION)
    per = max(1, round(CONTROL_PERIOD / m.opt.timestep))
    for ctrl in t.controls:
        d.ctrl[:] = ctrl
        for _ in range(per):
            mujoco.mj_step(m, d)
            if per_step is not None:
                per_step(d)
    return per * len(t.controls)


def profile(t: Timed, rounds: int = 1) -> Profile:
    """MuJoCo's timers and solver counts over the prepared drive.

    The drive runs ``rounds`` times from the same settled state; each stage's µs per step
    is the median over the rounds (a preempted round on a shared machine inflates the
    stage it hit), the counts are the same every round (the run is deterministic).
    """
    d = t.data
    names = (*STAGES, "STEP")
    timers = [getattr(mujoco.mjtTimer, f"mjTIMER_{n}") for n in names]
    counts: list[tuple[int, int, int, int]] = []

    def record(data: mujoco.MjData) -> None:
        n = int(data.solver_niter[0])
        neval = sum(data.solver[i].neval for i in range(min(n, mujoco.mjNSOLVER)))
        counts.append((n, neval, data.ncon, data.nefc))

    per_round = []
    for k in range(rounds):
        before = np.array([d.timer[i].duration for i in timers])
        nstep = run_drive(t, record if k == 0 else None)
        per_round.append((np.array([d.timer[i].duration for i in timers]) - before)
                         / nstep * 1e6)
    us = np.median(np.array(per_round), axis=0)
    mean = np.mean(np.array(counts, float), axis=0)
    return Profile(dict(zip(names, us.tolist(), strict=True)), *mean.tolist(),
                   timestep=float(t.model.opt.timestep))


def profile_text(robot: str, p: Profile) -> str:
    """The profile as lines: each stage's µs and share of the step, then the counts."""
    total = p.us["STEP"]
    lines = [f"{robot}: one default step, {total:.1f} µs (MuJoCo's timers, median of rounds)"]
    for name in STAGES:
        lines.append(f"  {name.lower():15s} {p.us[name]:7.1f} µs  {p.us[name] / total:5.1%}")
    lines.append(f"  per step: {p.niter:.2f} solver iterations, {p.neval:.1f} line-search "
                 f"evaluations, {p.ncon:.1f} contacts, {p.nefc:.1f} constraint rows")
    lines.append(f"  the other stages alone: {p.us['STEP'] - p.us['CONSTRAINT']:.1f} µs: a free "
                 f"solver would make a step at most {p.free_solver_speedup:.2f}× faster")
    return "\n".join(lines)
