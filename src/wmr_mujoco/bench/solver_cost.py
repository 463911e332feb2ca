"""The roller robots' constraint-solver cost at a fixed timestep (issue 24 § 4).

``python -m wmr_mujoco.bench.solver_cost [--quick] [--seeds 0 1] [--no-validate]
[--write] [robots ...]`` prints, for omni3, omni3_reduced and mecanum4 (default):

1. **Where a default step's time goes**, from MuJoCo's own timers
   (``data.timer[mjtTimer.mjTIMER_*]``) over the first seconds of the random-steps
   family's member 0 (seed 0, :mod:`wmr_mujoco.bench.default_speed`'s drive): kinematics,
   inertia, collision (broad and narrow phase), making the constraints, the constraint
   solver, and the solver's own counts per step: its iterations ``solver_niter``, line
   search cost evaluations ``Σ solver[i].neval``, contacts ``ncon`` and constraint rows
   ``nefc``.
2. **The cost of each solver setting** (:data:`SETTINGS`) at the robot's timestep: µs per
   step and × real time of a bare one-thread ``mj_step`` loop on that drive (every setting
   timed in alternating rounds of one run, median of the rounds), and its ratio to the
   default. A setting is a change of the compiled model's ``MjOption`` fields; the ones a
   robot's parameters can express (``solver``, ``jacobian``, ``cone``) and that cost at
   most :data:`CANDIDATE_RATIO` of the default, keeping the robot on the floor, are
   **validated**: every scenario's family of ``wmr validate ROBOT`` is run with the
   setting's parameters at each seed, beside the defaults at the same seed, and compared
   row by row (:mod:`wmr_mujoco.bench.solver_fidelity`). A setting is acceptable only if
   every target the defaults pass, it passes at every seed.

``physics`` marks the settings that change the equations: the pyramidal cone (a
``condim`` 3 pyramid reaches ``μ f_n`` only along the contact frame's axes,
``μ f_n / √2`` along their diagonals) and the other solvers (Newton, CG, PGS), each of
which stops at MuJoCo's tolerance or at its iteration limit at its own solution. The
others are the same equations solved another way:
Jacobian storage, islands, midphase and warm start to round-off; tolerances and
iteration limits by where the solver stops (timed only: no parameter expresses them).

``--physics`` also runs the validation of the candidates that change the physics (without
it, their verdicts come from figures kept by an earlier run, if any); the validated
figures are kept in ``reports/solver_cost/`` (named by the digest of the model files,
:func:`wmr_mujoco.bench.solver_fidelity.cache_file`), so a rerun times again and reuses
them. ``--write`` pastes the tables into ``docs/benchmarks.md`` (its ``solver-cost``
marker).
"""

from __future__ import annotations

import argparse
import dataclasses
import math
from collections.abc import Sequence

import mujoco
import numpy as np

from wmr_mujoco.bench.default_speed import RTF_GOAL, Rounds, Timed, prepare_timed, wall_seconds
from wmr_mujoco.bench.solver_profile import profile, profile_text, run_drive
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.spec import RobotSpec
from wmr_mujoco.sim.stepped_inputs import CONTROL_PERIOD
from wmr_mujoco.sim.stepping import check_healthy

#: The robots the study covers: the roller robots.
ROBOTS = ("omni3", "omni3_reduced", "mecanum4")

_S, _J, _C, _D = mujoco.mjtSolver, mujoco.mjtJacobian, mujoco.mjtCone, mujoco.mjtDisableBit


@dataclasses.dataclass(frozen=True)
class Setting:
    """One solver setting: ``MjOption`` fields over the robot's defaults.

    Attributes:
        label: the table's name of the setting.
        opt: ``(MjOption field, value)`` pairs set on the compiled model; ``disableflags``
            is OR-ed into the model's.
        params: the same setting as robot parameter fields (empty: not expressible as
            parameters, so timed only).
        physics: the setting changes the equations solved (see the module docstring).
    """

    label: str
    opt: tuple[tuple[str, float], ...] = ()
    params: tuple[tuple[str, str], ...] = ()
    physics: bool = False

    def apply(self, model: mujoco.MjModel) -> None:
        """Set the setting's options on a compiled model."""
        for name, value in self.opt:
            if name == "disableflags":
                model.opt.disableflags |= int(value)
            else:
                setattr(model.opt, name, type(getattr(model.opt, name))(value))

    def robot_params(self, spec: RobotSpec) -> RobotParams | None:
        """The robot's default parameters with the setting (None: not expressible).

        Only robots whose builder writes the fields (a parameter listed in the type's
        ``UNUSED`` has no effect) express it.
        """
        if spec.params_type is None or not self.params:
            return None
        names = {f.name for f in dataclasses.fields(spec.params_type)}
        unused = getattr(spec.params_type, "UNUSED", ())
        if any(k not in names or k in unused for k, _ in self.params):
            return None
        return spec.params_type(**dict(self.params))


DEFAULT = Setting("default")
SETTINGS: tuple[Setting, ...] = (
    DEFAULT,
    Setting("jacobian sparse", (("jacobian", _J.mjJAC_SPARSE),), (("jacobian", "sparse"),)),
    Setting("jacobian dense", (("jacobian", _J.mjJAC_DENSE),), (("jacobian", "dense"),)),
    Setting("jacobian auto", (("jacobian", _J.mjJAC_AUTO),), (("jacobian", "auto"),)),
    Setting("tolerance 1e-6", (("tolerance", 1e-6),)),
    Setting("tolerance 1e-4", (("tolerance", 1e-4),)),
    Setting("iterations 10", (("iterations", 10),)),
    Setting("ls_iterations 5", (("ls_iterations", 5),)),
    Setting("ls_tolerance 0.1", (("ls_tolerance", 0.1),)),
    Setting("no islands", (("disableflags", _D.mjDSBL_ISLAND),)),
    Setting("no midphase", (("disableflags", _D.mjDSBL_MIDPHASE),)),
    Setting("no warm start", (("disableflags", _D.mjDSBL_WARMSTART),)),
    Setting("sparse, no islands", (("jacobian", _J.mjJAC_SPARSE),
                                   ("disableflags", _D.mjDSBL_ISLAND))),
    Setting("Newton", (("solver", _S.mjSOL_NEWTON),), (("solver", "Newton"),), physics=True),
    Setting("CG", (("solver", _S.mjSOL_CG),), (("solver", "CG"),), physics=True),
    Setting("PGS", (("solver", _S.mjSOL_PGS),), (("solver", "PGS"),), physics=True),
    Setting("pyramidal", (("cone", _C.mjCONE_PYRAMIDAL),), (("cone", "pyramidal"),),
            physics=True),
    Setting("sparse, pyramidal", (("jacobian", _J.mjJAC_SPARSE), ("cone", _C.mjCONE_PYRAMIDAL)),
            (("jacobian", "sparse"), ("cone", "pyramidal")), physics=True),
)

#: The setting each robot's default replaced (issue 24 § 4), a record: validated beside
#: the default whatever its cost, so the table shows what the change did to the figures.
PREVIOUS: dict[str, str] = {"omni3": "jacobian auto"}

@dataclasses.dataclass(frozen=True)
class Cost:
    """One setting's cost on one robot's drive.

    Attributes:
        us_per_step: median over rounds of the wall time per ``mj_step``, µs.
        rtf: simulated seconds per wall second.
        ratio: this setting's median wall time over the default's (same run).
        contacts: mean contacts per step over the drive (an untimed pass).
        error: why the setting is no candidate (it diverged, or the robot left the
            floor: under half the default's contacts), else ``""``.
    """

    us_per_step: float
    rtf: float
    ratio: float
    contacts: float = float("nan")
    error: str = ""

    @property
    def candidate(self) -> bool:
        """Timed, on the floor, and cheaper than the default beyond the timing noise."""
        return not self.error and self.ratio <= CANDIDATE_RATIO


#: A setting is a candidate only at most this share of the default's cost: a cheaper
#: setting within the timing noise of the default (a few % on a shared machine) is none.
CANDIDATE_RATIO = 0.9
#: A setting whose drive averages under this share of the default's contacts per step
#: has thrown the robot off the floor (what makes it cheap): no candidate.
MIN_CONTACT_SHARE = 0.5


def _options(model: mujoco.MjModel) -> tuple[float, ...]:
    """The ``MjOption`` fields a setting may change (``auto`` resolved: dense below 60 DoF)."""
    jac = model.opt.jacobian
    if jac == _J.mjJAC_AUTO:
        jac = _J.mjJAC_SPARSE if model.nv >= 60 else _J.mjJAC_DENSE
    return (model.opt.solver, jac, model.opt.cone, model.opt.iterations,
            model.opt.tolerance, model.opt.ls_iterations, model.opt.ls_tolerance,
            model.opt.disableflags)


def contacts(t: Timed) -> float:
    """Mean contacts per step over the prepared drive (untimed; a divergence raises)."""
    n: list[int] = []
    run_drive(t, lambda d: n.append(d.ncon))
    check_healthy(t.model, t.data)
    return float(np.mean(n))


def costs(spec: RobotSpec, settings: Sequence[Setting], how: Rounds) -> list[Cost]:
    """Each setting's cost in alternating rounds of one run (the first must be the default).

    A setting whose run diverges is dropped from the later rounds and reported.
    """
    prepared: list[Timed | None] = []
    touching, errors = [], [""] * len(settings)
    for k, s in enumerate(settings):
        t = prepare_timed(spec, None, how.seconds)
        before = _options(t.model)
        s.apply(t.model)
        if k and _options(t.model) == before:  # e.g. "jacobian auto" where auto is sparse
            touching.append(float("nan"))
            errors[k], t = "the default's own options (nothing to time)", None
            prepared.append(t)
            continue
        try:
            touching.append(contacts(t))
        except Exception as err:  # a diverging setting is a row of the table
            touching.append(float("nan"))
            errors[k], t = f"{type(err).__name__}: {err}", None
        prepared.append(t)
    for k, n in enumerate(touching):
        if k and not errors[k] and n < MIN_CONTACT_SHARE * touching[0]:
            errors[k] = (f"left the floor: {n:.2f} contacts a step, the default "
                         f"{touching[0]:.2f}")
    walls: list[list[float]] = [[] for _ in settings]
    for _ in range(how.rounds):
        for k, t in enumerate(prepared):
            if t is None or errors[k]:
                continue
            try:
                walls[k].append(wall_seconds(t))
            except Exception as err:  # a diverging setting is a row of the table
                errors[k], prepared[k] = f"{type(err).__name__}: {err}", None
    if errors[0]:
        raise RuntimeError(f"{spec.name}: the default setting failed: {errors[0]}")
    nstep = len(prepared[0].controls) * max(1, round(CONTROL_PERIOD / spec_dt(prepared[0])))
    seconds = nstep * spec_dt(prepared[0])
    base = float(np.median(walls[0]))
    out = []
    for w, n, e in zip(walls, touching, errors, strict=True):
        if not w:
            out.append(Cost(float("nan"), float("nan"), float("nan"), n, e))
            continue
        med = float(np.median(w))
        out.append(Cost(med / nstep * 1e6, seconds / med, med / base, n, e))
    return out


def spec_dt(t: Timed | None) -> float:
    """The prepared model's timestep."""
    assert t is not None
    return float(t.model.opt.timestep)


def cost_rows(robot: str, settings: Sequence[Setting], cs: Sequence[Cost],
              fidelity: dict[str, str] | None = None) -> list[str]:
    """Table lines: setting, physics mark, µs/step, × real time, ratio, validation."""
    fidelity = fidelity or {}
    out = []
    for s, c in zip(settings, cs, strict=True):
        mark = "physics" if s.physics else ""
        label = s.label + (" (the previous default)" if s.label == PREVIOUS.get(robot) else "")
        if not math.isfinite(c.us_per_step):
            out.append(f"| {robot} | {label} | {mark} | | | | | {c.error[:70]} |")
            continue
        verdict = c.error or fidelity.get(s.label, _unvalidated(s, c))
        out.append(f"| {robot} | {label} | {mark} | {c.contacts:.2f} | {c.us_per_step:.1f} "
                   f"| {c.rtf:.0f}× | {c.ratio:.2f} | {verdict} |")
    return out


def _unvalidated(s: Setting, c: Cost, expressed: bool = True) -> str:
    """Why a timed setting has no validation (``expressed``: the robot's parameters can)."""
    if s == DEFAULT:
        return "the default: what the others are compared with"
    if not c.candidate:
        return f"no candidate (cost ratio above {CANDIDATE_RATIO})"
    if not s.params:
        return "candidate, not validated (no robot parameter expresses it)"
    if not expressed:
        return "candidate, not validated (this robot's parameters do not express it)"
    if s.physics:
        return "candidate, changes physics: not validated (run with --physics)"
    return "candidate, not validated (this robot's parameters do not express it)"


HEADER = ("| robot | setting | changes physics | contacts/step | µs/step | × real time "
          "| cost ratio | validation (worst over the families) |\n"
          "|---|---|---|---|---|---|---|---|")


def main(argv: Sequence[str] | None = None) -> int:
    """Print the profile and the cost table (and the validation of each candidate)."""
    from wmr_mujoco.bench import solver_fidelity

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("robots", nargs="*", default=list(ROBOTS))
    ap.add_argument("--quick", action="store_true", help="1 s drive, 2 rounds")
    ap.add_argument("--seeds", type=int, nargs="+", default=[0, 1])
    ap.add_argument("--no-validate", action="store_true", help="timing only")
    ap.add_argument("--physics", action="store_true",
                    help="validate the candidates that change the physics too")
    ap.add_argument("--jobs", type=int, default=2, help="processes for the validation")
    ap.add_argument("--write", action="store_true",
                    help="publish the tables in docs/benchmarks.md under its marker")
    args = ap.parse_args(argv)
    specs = [get_spec(r) for r in args.robots]  # a bad name fails before any work
    for seed in args.seeds:
        if seed < 0:
            raise SystemExit(f"--seeds: {seed} is negative; a seed is an integer >= 0")
    if args.jobs < 1:
        raise SystemExit(f"--jobs: {args.jobs}; give 1 or more processes")
    how = Rounds(1.0, 2) if args.quick else Rounds(2.0, 5)
    sections, table, ceilings = [], [HEADER], []
    for spec in specs:
        prof = profile(prepare_timed(spec, None, how.seconds), how.rounds)
        sections.append(profile_text(spec.name, prof))
        print(sections[-1], flush=True)
        cs = costs(spec, SETTINGS, how)
        chosen = [s for s, c in zip(SETTINGS, cs, strict=True)
                  if c.candidate or s.label == PREVIOUS.get(spec.name)]
        run = [s for s in chosen if args.physics or not s.physics]
        fid = {} if args.no_validate else {
            **solver_fidelity.judge_settings(spec, run, args.seeds, args.jobs),
            **solver_fidelity.judge_settings(spec, [s for s in chosen if s not in run],
                                             args.seeds, run=False)}
        for s, c in zip(SETTINGS, cs, strict=True):
            if c.candidate and s.label not in fid and s.params and s.robot_params(spec) is None:
                fid[s.label] = _unvalidated(s, c, expressed=False)
        rows = cost_rows(spec.name, SETTINGS, cs, fid)
        ceilings.append(f"{spec.name}: {cs[0].rtf:.0f}× real time at the default; a free "
                        f"solver: at most {cs[0].rtf * prof.free_solver_speedup:.0f}×")
        table += rows
        print("\n".join([HEADER, *rows]), flush=True)
    sections.append("\n".join([f"speed goal: ≥ {RTF_GOAL:.0f}× real time, one thread",
                                *ceilings]))
    text = "\n\n".join(["```text", *sections, "```", "\n".join(table)])
    text = text.replace("```text\n\n", "```text\n").replace("\n\n```", "\n```")
    print("\n" + sections[-1])
    if args.write:
        solver_fidelity.publish(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
