"""The mecanum roller design study: ``python -m wmr_mujoco.bench.mecanum_study``.

Roller colliders × roller counts, each measured in one run on this machine through the
validation runner (:func:`wmr_mujoco.robots.roller_wheels.trials.run_trial`, judged by
``mecanum4``'s registry entry): the rolling-radius ripple on the collision geometry
(:func:`wmr_mujoco.robots.mecanum4.ripple.ripple`); open-loop tracking of the robot's
kinematic scenarios (8 translations, rotation, translation+rotation; 0.5 s ramps and
steps), shortened to :data:`STUDY_DURATION` so that the study stays a few minutes, worst
over every run, against the roller-pitch-averaged kinematics and the ideal Lynch & Park
model; and the real-time factor of the step loop on one thread. ``omni3`` (default model)
is timed in the same process for the ratio; the default model's runs at the validation's
turning length (10 s) are tabled too; so is the cost of one ``mj_step`` of the default
model with its contacts from contact bits or from explicit floor pairs and with the Newton
or the PGS solver (:func:`cost_table`). The tables go between markers in
``models/mecanum4/README.md`` (``make study``).
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.bench.thread_scaling import driving_controls
from wmr_mujoco.docs_sync.markers import fixed, publish, study_parser
from wmr_mujoco.lookup import build_scene, load
from wmr_mujoco.models.builders import common
from wmr_mujoco.models.paths import MODELS_DIR
from wmr_mujoco.robots import get_spec, mecanum4, omni3
from wmr_mujoco.robots.mecanum4 import kinematics, ripple
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import pitch_averaged as pa
from wmr_mujoco.robots.roller_wheels.trials import TrialRun, run_trial
from wmr_mujoco.sim.stepping import SimulationDivergedError
from wmr_mujoco.validation.scenarios import Scenario

README = MODELS_DIR / mecanum4.NAME / "README.md"
COUNTS = (8, 12, 16, 20, 24)
#: Seconds per study run (2 shared cores; the validation's turning runs last 10 s).
STUDY_DURATION = 3.0
#: The manoeuvre timed against omni3 (both robots have one by this name).
TIMED = "translate+rotate"
#: Default-model runs at the validation's turning length, tabled by :func:`long_runs_table`.
LONG_RUNS = ("translate 90° (ramp)", "translate 45° (step)", "rotate (ramp)", "rotate (step)")
LONG_DURATION = 10.0
POSITION = ("worst position error", "% of path")
HEADING = ("worst heading error", "deg")


@dataclass(frozen=True)
class Summary:
    """One model's figures.

    ``tracking[kind]``, kind ``"ramp"`` or ``"step"``: worst over the runs of
    ``(position % of path, heading °)`` against the judged model (ramps: the colliders'
    kinematics; steps: the stick–slip step model) and then against the ideal one.
    ``diverged``: the first scenario whose run diverged (:func:`measure_or_diverged`;
    then no tracking and no real-time factor), empty if none did.
    """

    label: str
    ripple_pct: float
    sideways_shortfall_pct: float
    tracking: dict[str, tuple[float, float, float, float]]
    real_time_factor: float
    diverged: str = ""


class StudyRunDivergedError(SimulationDivergedError):
    """A study run diverged: ``scenario`` names it, the message says how and when."""

    def __init__(self, label: str, scenario: str, cause: Exception) -> None:
        super().__init__(f"{label}, {scenario}: {cause}")
        self.scenario = scenario


def study_scenarios(duration: float = STUDY_DURATION) -> list[Scenario]:
    """``mecanum4``'s kinematic scenarios, each lasting ``duration`` seconds."""
    return [dataclasses.replace(s, duration=duration) for s in mecanum4.kinematic_runs()]


def sideways_shortfall_pct(params: MecanumParams) -> float:
    """Derived sideways shortfall of the ideal n-roller wheel, ``100 (1 − 1/⟨sec φ⟩)`` %.

    The pitch average's value (φ_m = π/n): a property of the ideal wheel, not a bound.
    """
    k = pa.mean_secant(pa.roller_half_pitch(params.rollers_per_wheel))
    return 100.0 * (1.0 - 1.0 / k)


def _worst(runs: Sequence[TrialRun], metric: tuple[str, str]) -> float:
    values = [abs(r.value(*metric)) for r in runs]
    values = [v for v in values if np.isfinite(v)]
    return max(values) if values else float("nan")


def _ideal(metric: tuple[str, str]) -> tuple[str, str]:
    return (f"{metric[0]}, ideal model", metric[1])


def measure(params: MecanumParams, scenarios: Sequence[Scenario], label: str) -> Summary:
    """Ripple, tracking and real-time factor of the model built from ``params``.

    Raises:
        StudyRunDivergedError: a run diverged (a :class:`SimulationDivergedError`).
    """
    rip = ripple.ripple(scenarios[0], params).metrics[0].value
    runs = {"ramp": [], "step": []}
    rtf = []
    for s in scenarios:
        try:
            run = run_trial(get_spec(s.robot), s, params)
        except SimulationDivergedError as err:
            raise StudyRunDivergedError(label, s.name, err) from err
        if run.result.error:
            raise RuntimeError(f"{label}, {s.name}: {run.result.error}")
        runs["step" if kinematics.is_step(s) else "ramp"].append(run)
        rtf.append(run.real_time_factor)
    tracking = {kind: (_worst(r, POSITION), _worst(r, HEADING), _worst(r, _ideal(POSITION)),
                       _worst(r, _ideal(HEADING))) for kind, r in runs.items() if r}
    return Summary(label, rip, sideways_shortfall_pct(params), tracking,
                   float(np.median(rtf)))


def measure_or_diverged(params: MecanumParams, scenarios: Sequence[Scenario],
                        label: str) -> Summary:
    """:func:`measure`, or, if a run diverges, a row that says so.

    The divergence is printed (MuJoCo's warning and the time) and the row keeps the
    geometry's figures (ripple, shortfall), which need no run; the table reports it as
    diverged instead of leaving the configuration out.
    """
    try:
        return measure(params, scenarios, label)
    except StudyRunDivergedError as err:
        print(f"diverged: {err}", flush=True)
        rip = ripple.ripple(scenarios[0], params).metrics[0].value
        return Summary(label, rip, sideways_shortfall_pct(params), {}, float("nan"),
                       diverged=err.scenario)


#: The mesh roller shape (the ideal profile's convex hull).
MESH = "profile"


def study_configs() -> list[tuple[str, MecanumParams]]:
    """Roller shapes × roller counts, everything else at the defaults.

    The mesh ``"profile"`` rollers run on contact bits (``floor_impedance`` 0, labelled):
    with the floor pairs' remedy they are refused (they throw the robot off the floor,
    :func:`~wmr_mujoco.models.params.fields._check_mesh_rollers`).
    """
    out = []
    for n in COUNTS:
        for shape in MecanumParams.ROLLER_SHAPES:
            bits = shape == MESH
            out.append((f"{shape}, {n}" + (" (contact bits)" if bits else ""),
                        dataclasses.replace(MecanumParams(), roller_shape=shape,
                                            rollers_per_wheel=n,
                                            **({"floor_impedance": 0.0} if bits else {}))))
    return out


def times(rtf: float) -> str:
    """A real-time factor's cell: ``12×``, or ``n/a`` for a row that has none."""
    return f"{fixed(rtf, 0)}×" if np.isfinite(rtf) else fixed(rtf)


def table(rows: Sequence[Summary], default_label: str | None = None) -> str:
    """Markdown table: ramp (kinematic) and step (step model) tracking / ideal model."""
    lines = ["| rollers | ripple % | derived sideways shortfall % | ramps: worst position "
             "% of path, kinematic / ideal | ramps: worst heading °, kinematic / ideal | "
             "steps: worst position % of path, step model / ideal | steps: worst heading °, "
             "step model / ideal | real-time factor |", "|---|---|---|---|---|---|---|---|"]
    for s in rows:
        label = f"**{s.label} (default)**" if s.label == default_label else s.label
        cells = [f"diverged in {s.diverged}"] + ["diverged"] * 3 if s.diverged else []
        for kind in ("ramp", "step") if not s.diverged else ():
            pos, head, pos_i, head_i = s.tracking.get(kind, (np.nan,) * 4)
            cells += [f"{fixed(pos, 3)} / {fixed(pos_i, 3)}", f"{fixed(head)} / {fixed(head_i)}"]
        lines.append(f"| {label} | {fixed(s.ripple_pct, 3)} | "
                     f"{fixed(s.sideways_shortfall_pct)} | " + " | ".join(cells)
                     + f" | {times(s.real_time_factor)} |")
    return "\n".join(lines)


def timing_table(params: MecanumParams, rounds: int = 3,
                 duration: float = STUDY_DURATION) -> str:
    """Real-time factors of mecanum4 and omni3, interleaved, best of ``rounds`` each.

    Both on their translate+rotate scenario (0.3 m/s ahead at 0.5 rad/s), stepped in
    Python by the same runner. The machine is shared: the best of a few interleaved
    rounds is the figure least disturbed by other load.
    """
    ours_s = dataclasses.replace(mecanum4.SPEC.scenario(f"{TIMED} (ramp)"), duration=duration)
    omni_s = dataclasses.replace(omni3.SPEC.scenario(TIMED), duration=duration)
    ours, omni = [], []
    for _ in range(rounds):
        ours.append(run_trial(get_spec(ours_s.robot), ours_s, params).real_time_factor)
        omni.append(run_trial(get_spec(omni_s.robot), omni_s).real_time_factor)
    label = f"{params.roller_shape}, {params.rollers_per_wheel}"
    return "\n".join([
        f"| model (best of {rounds} interleaved runs, {TIMED}, {duration:g} s) | "
        "real-time factor (one thread) |", "|---|---|",
        f"| mecanum4 (default, {label}) | {max(ours):.0f}× |",
        f"| omni3 (default) | {max(omni):.0f}× |",
        f"| ratio mecanum4 / omni3 | {max(ours) / max(omni):.2f} |"])


#: Steps per timed loop of :func:`cost_table` (``COST_STEPS · sim.timestep`` of simulated
#: time: a few seconds at the default step), after :data:`COST_WARMUP` steps from rest, so
#: that the robot cruises.
COST_STEPS = 2000
COST_WARMUP = 200


def contact_variant(params: MecanumParams, pairs: bool) -> mujoco.MjModel:
    """The scene of ``params`` with its roller contacts from floor pairs or from bits.

    ``pairs=False``: the pairs removed and the roller colliders given ``conaffinity`` 1
    (``contype`` 0; the floor's ``contype`` is 1), so that the broadphase finds the same
    roller–floor contacts and MuJoCo combines the geoms' parameters itself. With
    ``floor_impedance`` 0 that is the same physics as the pairs; with ``floor_impedance``
    > 0 (the default) it is not: a geom carries no ``solreffriction``, so the bits give the
    collision class's contact, at the model's ``impratio`` (:data:`BITS_LABEL`).
    """
    root = build_scene(mecanum4.NAME, params)
    if not pairs:
        for pair in root.contact.get_children("pair"):
            pair.remove()
        root.default.find("default", "roller").geom.conaffinity = 1
    return mujoco.MjModel.from_xml_string(common.to_xml(root))


def _timed_loop(model: mujoco.MjModel, ctrl: np.ndarray) -> tuple[float, float, float]:
    """``(s per step, constraint s per step, collision s per step)`` of one loop."""
    data = mujoco.MjData(model)
    data.ctrl[:] = ctrl
    for _ in range(COST_WARMUP):
        mujoco.mj_step(model, data)
    for timer in data.timer:
        timer.duration, timer.number = 0.0, 0
    start = time.perf_counter()
    for _ in range(COST_STEPS):
        mujoco.mj_step(model, data)
    wall = (time.perf_counter() - start) / COST_STEPS
    stage = [data.timer[t].duration / COST_STEPS for t in
             (mujoco.mjtTimer.mjTIMER_CONSTRAINT, mujoco.mjtTimer.mjTIMER_POS_COLLISION)]
    return wall, stage[0], stage[1]


#: What the contact-bits rows of :func:`cost_table` are when the pairs carry the remedy.
BITS_LABEL = "contact bits (collision class's contact)"


def cost_table(rounds: int = 7) -> str:
    """µs per ``mj_step`` and real-time factor of the contact/solver variants and ``omni3``.

    The default parameters with contacts from bits or pairs and the Newton or PGS solver,
    and ``omni3``'s default model, each on its cruising controls
    (:func:`~wmr_mujoco.bench.thread_scaling.driving_controls`); ``rounds`` interleaved
    rounds of :data:`COST_STEPS` steps on one thread; median and range over the rounds.
    The stage columns (MuJoCo's own timers, median) show where the time goes. The bits
    rows cannot carry the pairs' remedy (:func:`contact_variant`); their label says so
    when the default has it.
    """
    default = MecanumParams()
    models = {}
    for pairs in (False, True):
        for solver in ("Newton", "PGS"):
            params = dataclasses.replace(default, solver=solver)
            bits = BITS_LABEL if default.floor_impedance > 0.0 else "contact bits"
            label = (f"mecanum4, {'floor pairs' if pairs else bits}, {solver}"
                     + (" (default)" if pairs and params == default else ""))
            models[label] = contact_variant(params, pairs)
    models["omni3 (default)"] = load(omni3.NAME)
    ctrls = {k: driving_controls(m, omni3.NAME if k.startswith("omni3") else mecanum4.NAME)
             for k, m in models.items()}
    loops = {k: [] for k in models}
    for _ in range(rounds):
        for k, m in models.items():
            loops[k].append(_timed_loop(m, ctrls[k]))
    lines = [f"| model (one thread, {rounds} interleaved rounds of {COST_STEPS} steps) | "
             "µs per step, median (range) | real-time factor, median (range) | "
             "constraint µs | collision µs |", "|---|---|---|---|---|"]
    for k, runs in loops.items():
        wall = np.array([r[0] for r in runs])
        dt = models[k].opt.timestep
        med = [1e6 * float(np.median([r[i] for r in runs])) for i in range(3)]
        lines.append(f"| {k} | {med[0]:.0f} ({1e6 * wall.min():.0f}–{1e6 * wall.max():.0f}) "
                     f"| {dt / np.median(wall):.0f}× ({dt / wall.max():.0f}–"
                     f"{dt / wall.min():.0f}×) | {med[1]:.0f} | {med[2]:.0f} |")
    return "\n".join(lines)


def long_runs_table(params: MecanumParams, duration: float = LONG_DURATION) -> str:
    """Worst position and heading errors of :data:`LONG_RUNS`, judged and ideal models.

    The judged model: ramps, the colliders' kinematics; steps, the stick–slip step model.
    """
    lines = ["| run (10 s) | metric | judged model (ramps: kinematic; steps: step model) "
             "| target | ideal model |", "|---|---|---|---|---|"]
    for name in LONG_RUNS:
        s = dataclasses.replace(next(k for k in mecanum4.kinematic_runs() if k.name == name),
                                duration=duration)
        rows = run_trial(get_spec(s.robot), s, params).result.rows
        for metric, unit in (POSITION, HEADING):
            judged = next((r for r in rows if (r.metric, r.unit) == (metric, unit)), None)
            ideal = next((r for r in rows if (r.metric, r.unit) == _ideal((metric, unit))),
                         None)
            if judged is None:
                continue
            target = "n/a" if judged.target is None else f"≤ {judged.target:.3g} {unit}"
            lines.append(f"| {name} | {metric} | {fixed(judged.value, 3)} {unit} | {target} "
                         f"| {fixed(ideal.value if ideal else np.nan, 3)} {unit} |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Run the study; print the tables and update the README."""
    parser = study_parser(__doc__)
    parser.add_argument("--duration", type=float, default=STUDY_DURATION,
                        help="seconds per study run")
    parser.add_argument("--timing-only", action="store_true",
                        help="only the mecanum4 / omni3 timing tables (best of 5 rounds)")
    args = parser.parse_args(argv)
    default = MecanumParams()
    if args.timing_only:
        publish(README, {"mecanum timing": timing_table(default, rounds=5,
                                                        duration=args.duration),
                         "mecanum cost": cost_table()}, not args.no_write)
        return
    scenarios = study_scenarios(args.duration)
    default_label = f"{default.roller_shape}, {default.rollers_per_wheel}"
    study = []
    for label, params in study_configs():
        study.append(measure_or_diverged(params, scenarios, label))
        print(table(study[-1:]).splitlines()[-1], flush=True)
    publish(README, {"mecanum roller study": table(study, default_label),
                     "mecanum timing": timing_table(default, duration=args.duration),
                     "mecanum cost": cost_table(),
                     "mecanum long runs": long_runs_table(default)}, not args.no_write)


if __name__ == "__main__":
    main()
