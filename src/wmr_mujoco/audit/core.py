"""``audit(path)``: read a robot, find its wheels and class, drive it, diagnose it.

The steps (each in its module): :mod:`~wmr_mujoco.audit.scene` reads the file and adds a
floor; :mod:`~wmr_mujoco.audit.wheels` finds the wheels, their kinds and rolling radii;
:mod:`~wmr_mujoco.audit.kinematics` derives the Jacobian and the manoeuvres;
:mod:`~wmr_mujoco.audit.drive` picks the servos; :mod:`~wmr_mujoco.audit.run` drives each
manoeuvre beside the ideal model; :mod:`~wmr_mujoco.audit.figures` measures;
:mod:`~wmr_mujoco.audit.diagnoses` looks for known pitfalls and confirms each with a
counterfactual run.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.audit.drive import Drive, make_drive
from wmr_mujoco.audit.errors import AuditInputError
from wmr_mujoco.audit.figures import Figures, figures, verdict
from wmr_mujoco.audit.kinematics import (
    Manoeuvre,
    infeasible,
    jacobian,
    manoeuvres,
    reference_point,
    span,
)
from wmr_mujoco.audit.limits import DRAWS, DRAWS_RANGE, DURATION, DURATION_RANGE, SPEED_FACTORS
from wmr_mujoco.audit.run import Record, run
from wmr_mujoco.audit.scene import Scene, read_scene
from wmr_mujoco.audit.wheels import Wheels, find


@dataclass
class Outcome:
    """One manoeuvre's worst draw: the record, its figures and the verdict line.

    ``draw`` is the index of that draw (0: nominal speed, wheels as built); ``manoeuvre``
    carries that draw's twist.
    """

    manoeuvre: Manoeuvre
    record: Record
    figures: Figures
    verdict: str
    draw: int = 0


@dataclass(frozen=True)
class Draw:
    """One seeded variant of every manoeuvre: a speed factor and the wheels' start phase."""

    speed: float
    phases: dict[int, float]


def make_draws(found: Wheels, n: int, seed: int) -> list[Draw]:
    """``n`` seeded draws: the first nominal, the others varied.

    The others run at speed × U(:data:`SPEED_FACTORS`) with each wheel's spin joint
    started at U(0, 2π) (which roller of a Swedish wheel is down), from ``seed``.
    """
    rng = np.random.default_rng(seed)
    out = [Draw(1.0, {})]
    for _ in range(n - 1):
        speed = float(rng.uniform(*SPEED_FACTORS))
        out.append(Draw(speed, {w.joint: float(rng.uniform(0.0, 2.0 * np.pi))
                                for w in found.wheels if w.kind != "ball"}))
    return out


def scaled(m: Manoeuvre, k: float) -> Manoeuvre:
    """``m`` at ``k`` times its speed."""
    if k == 1.0:
        return m
    return Manoeuvre(m.name, tuple(k * x for x in m.twist),
                     f"{m.description}, draw at {k:.2f}× that speed")


@dataclass
class Audit:
    """Everything the audit found (the report is written from this)."""

    scene: Scene
    wheels: Wheels
    drive: Drive
    jacobian_rows: tuple[str, ...]
    jacobian: np.ndarray
    reference: np.ndarray
    span: float
    duration: float
    outcomes: list[Outcome]
    draws: list[Draw] = field(default_factory=list)
    manoeuvres: list[Manoeuvre] = field(default_factory=list)
    skipped: dict[str, str] = field(default_factory=dict)
    diagnoses: list = field(default_factory=list)

    @property
    def robot_class(self) -> tuple[int, int]:
        """Campion's (δm, δs)."""
        return self.wheels.classification.robot_class

    def worst(self) -> Outcome:
        """The manoeuvre with the largest judged position error."""
        return max(self.outcomes, key=lambda o: judged(o.figures, self.span))


def steer_limits(model: mujoco.MjModel, found: Wheels) -> dict[str, tuple[float, float]]:
    """Wheel name -> the range of its steering joint, for the limited ones."""
    return {w.name: tuple(float(x) for x in model.jnt_range[w.steer_joint])
            for w in found.wheels if w.steer_joint >= 0 and model.jnt_limited[w.steer_joint]}


def judged(f: Figures, robot_span: float) -> float:
    """The judged position figure: % of path, or a spin's drift in % of the span."""
    return f.position_pct if f.position_pct is not None else 100.0 * f.drift_m / max(
        robot_span, 0.05)


def drive_all(a: Audit, model: mujoco.MjModel | None = None,
              only: tuple[str, ...] | None = None, drive: Drive | None = None
              ) -> list[Outcome]:
    """Run the audit's manoeuvres (``only`` those named).

    On ``model`` (default: the drive's), through ``drive``'s channels (default: the
    audit's).
    """
    out = []
    for m in a.manoeuvres:
        if only is not None and m.name not in only:
            continue
        worst: Outcome | None = None
        for i, d in enumerate(a.draws or [Draw(1.0, {})]):
            mi = scaled(m, d.speed)
            rec = run(drive or a.drive, a.wheels, mi, a.duration, a.reference, model,
                      d.phases)
            f = figures(rec)
            if worst is None or judged(f, a.span) > judged(worst.figures, a.span):
                worst = Outcome(mi, rec, f, verdict(f, a.span), i)
        out.append(worst)
    return out


def audit(path: Path | str, duration: float = DURATION, diagnose: bool = True,
          progress: Callable[[str], None] | None = None, draws: int = DRAWS,
          seed: int = 0) -> Audit:
    """Audit the robot in the MJCF file ``path`` (module docstring).

    Args:
        path: an MJCF scene with a floor, or a robot file (a floor is added).
        duration: seconds each manoeuvre is driven, in :data:`DURATION_RANGE`.
        diagnose: whether to look for pitfalls (and run their counterfactuals).
        progress: called with one line per step.
        draws: seeded variants of each manoeuvre (speed, wheel phase; the first nominal)
            in :data:`DRAWS_RANGE`; each figure is the worst draw's.
        seed: seed of the draws.

    Raises:
        AuditInputError: bad input (exit code 2), before any run.
        NotWheeledError: not a wheeled robot the audit can drive (exit code 4).
        SimulationDivergedError: a run diverged.
    """
    lo, hi = DURATION_RANGE
    if not isinstance(duration, (int, float)) or not lo <= duration <= hi:
        raise AuditInputError(f"duration {duration!r} s is outside [{lo:g}, {hi:g}] s")
    if not isinstance(draws, int) or not DRAWS_RANGE[0] <= draws <= DRAWS_RANGE[1]:
        raise AuditInputError(f"draws {draws!r} is outside [{DRAWS_RANGE[0]}, "
                              f"{DRAWS_RANGE[1]}]")
    say = progress or (lambda _: None)
    scene = read_scene(path)
    found = find(scene.model)
    names, jac = jacobian(found)
    ref = reference_point(found)
    a = Audit(scene, found, make_drive(scene, found), names, jac, ref, span(found, ref),
              float(duration), [])
    a.draws = make_draws(found, draws, seed)
    say(f"class {a.robot_class}; {a.drive.statement}")
    limits = steer_limits(a.drive.model, found)
    for m in manoeuvres(found):
        why = infeasible(found, m, set(a.drive.spin), limits)
        if why is None:
            a.manoeuvres.append(m)
        else:
            a.skipped[m.name] = why
    a.outcomes = drive_all(a)
    for o in a.outcomes:
        say(f"{o.manoeuvre.name}: {o.figures.error_label()}, {o.figures.heading_deg:.1f}°")
    if diagnose:
        from wmr_mujoco.audit.diagnoses import diagnose as find_pitfalls

        a.diagnoses = find_pitfalls(a, say)
    return a
