"""The free thin disc on a free joint: no actuators, contact only (issue 13).

Its scenarios are measurements against the classic rolling-disc solutions
(:mod:`.measurements`): rolling down an incline, a sweep of speeds across the
upright-stability threshold, steady precession over a full circle, and a leaning rolling
start against the nonlinear equations with its energy on the flat. Each can be filmed
(``wmr render disc_free --scenario NAME``) from the same runs it measures.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import mujoco
import numpy as np

from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots.disc import builder
from wmr_mujoco.robots.disc.params import FreeDiscParams
from wmr_mujoco.robots.disc_free import measurements as ms
from wmr_mujoco.robots.disc_free.state import FreeRun
from wmr_mujoco.robots.spec import Clip, Picture, RobotSpec
from wmr_mujoco.validation.family import Family, Vary
from wmr_mujoco.validation.scenarios import FilmFrame, MeasurementResult, Scenario, ScenarioKind
from wmr_mujoco.validation.variations import DYNAMIC_DRAWS

NAME = "disc_free"

Measure = Callable[[mujoco.MjModel], MeasurementResult]
Runs = Callable[[mujoco.MjModel], list[FreeRun]]


def _model(params: RobotParams | None) -> mujoco.MjModel:
    from wmr_mujoco.models.loading import load

    return load(SPEC, params)


def _evaluate(measure: Callable[..., MeasurementResult]
              ) -> Callable[[Scenario, RobotParams | None], MeasurementResult]:
    """``measure(model, **drawn)``, as a measurement scenario's ``evaluate``.

    A member's drawn values are the measurement's keyword arguments of the same names
    (its own defaults where nothing is drawn).
    """
    def evaluate(scenario: Scenario, params: RobotParams | None) -> MeasurementResult:
        return measure(_model(params), **dict(scenario.draw))
    return evaluate


def _around(name: str, nominal: float, unit: str) -> Vary:
    """``name`` within ±20 % of ``nominal``."""
    return Vary(name, 0.8 * nominal, 1.2 * nominal, unit)


def _film(runs: Runs, reference: Callable[[FreeRun], np.ndarray] | None = None
          ) -> Callable[[Scenario, RobotParams | None], Iterator[FilmFrame]]:
    """Frames of ``runs`` one after the other, with ``reference(run)`` drawn.

    ``reference`` gives the analytic path of the centre (the physics trail is the
    centre's, the ``base`` site).
    """
    def film(scenario: Scenario, params: RobotParams | None) -> Iterator[FilmFrame]:
        for run in runs(_model(params)):
            path = None if reference is None else reference(run)
            for data, _ in run.steps():
                yield FilmFrame(run.model, data, path)
    return film


def _circle(run: FreeRun) -> np.ndarray:
    """The steady solution's centre circle: about (0, −R), radius ``R − a sin θ``."""
    lean, radius = ms.PRECESSION
    r = run.disc.steady_motion(lean, radius).centre_radius
    a = np.linspace(0.0, 2 * np.pi, 91)
    return np.column_stack([r * np.sin(a), r * np.cos(a) - radius])


def _nonlinear(run: FreeRun) -> np.ndarray:
    """The nonlinear equations' centre path over the run."""
    t = np.linspace(0.0, run.duration, 201)
    return np.array([run.disc.centre(x)[:2] for x in ms.analytic_run(run.disc, run.state, t)])


def _sweep_clip(model: mujoco.MjModel) -> list[FreeRun]:
    """The sweep's extreme speeds (0.8 and 1.2 v_c), kicked 15× harder to be seen.

    2 s each: below v_c the lean grows to tens of degrees, above it stays a few degrees.
    """
    lo, hi = ms.SWEEP_RATIOS[0], ms.SWEEP_RATIOS[-1]
    return ms.stability_runs(model, (lo, hi), kick=15 * ms.SWEEP_KICK, duration=2.0,
                             stop_lean=1.2)


#: The leaning start's requirements are open over its family: the slower draws (below the
#: nominal speed, toward the upright disc's stability limit) miss all three, the energy
#: drift too. The errors follow the contact's effective time constant ``max(t_c, 2 Δt)``
#: (MuJoCo's refsafe; 8 ms at the defaults), not the timestep: they are the soft
#: contact's (``python -m wmr_mujoco.bench.disc_leaning``, table in models/disc/README.md).
LEANING_OPEN = dict.fromkeys(
    ("worst contact path error, first 5 s", "worst lean error, first 5 s",
     "worst energy drift"),
    "the family's slower draws miss it: the errors follow the soft contact's effective "
    "time constant max(t_c, 2 Δt), not the timestep; the stiffer contact that meets it "
    "costs the timestep in models/disc/README.md's leaning-family table "
    "(python -m wmr_mujoco.bench.disc_leaning)")

SCENARIOS = (
    Scenario(NAME, "incline", duration=1.0, kind=ScenarioKind.MEASUREMENT,
             evaluate=_evaluate(ms.incline), film=_film(ms.incline_runs),
             description="upright rolling down 0.1 rad: g sin β/(1 + C/(m a²))",
             family=Family((_around("slope", 0.1, "rad"), _around("speed", 1.0, "m/s")),
                           DYNAMIC_DRAWS)),
    Scenario(NAME, "stability sweep", duration=4.0, kind=ScenarioKind.MEASUREMENT,
             evaluate=_evaluate(ms.stability_sweep), film=_film(_sweep_clip),
             description="upright rolling at 0.8 to 1.2 v_c with a lean kick: threshold "
                         "speed and lean growth rate",
             family=Family((_around("kick", ms.SWEEP_KICK, "rad/s"),), DYNAMIC_DRAWS)),
    Scenario(NAME, "steady precession", duration=3.5, kind=ScenarioKind.MEASUREMENT,
             evaluate=_evaluate(ms.steady_precession),
             film=_film(ms.precession_runs, _circle),
             description="steady circling at 0.3 rad lean on a 0.6 m circle, one full "
                         "circle",
             family=Family((_around("lean", ms.PRECESSION[0], "rad"),
                            _around("radius", ms.PRECESSION[1], "m")), DYNAMIC_DRAWS)),
    Scenario(NAME, "leaning start", duration=10.0, kind=ScenarioKind.MEASUREMENT,
             evaluate=_evaluate(ms.leaning_start), film=_film(ms.leaning_runs, _nonlinear),
             description="leaning rolling start: path and lean against the nonlinear "
                         "equations over 5 s, energy over 10 s",
             family=Family((_around("lean", ms.LEANING_START[0], "rad"),
                            _around("speed", ms.LEANING_START[1], "m/s")), DYNAMIC_DRAWS),
             open_targets=LEANING_OPEN),
)

SPEC = RobotSpec(
    name=NAME,
    description="free thin disc on a free joint, no actuators; rolling-disc dynamics "
                "against the classic solutions",
    params_type=FreeDiscParams, build=builder.build_free, folder="disc",
    robot_file="disc_free.xml", scene_file="scene_free.xml", scenarios=SCENARIOS,
    render_scenario="steady precession", picture=Picture(keyframe="leaning"),
    clips=(Clip(), Clip("stability sweep", "disc_free_stability.gif")),
)
