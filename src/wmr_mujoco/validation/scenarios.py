"""Validation scenarios, as data: robot, kind, inputs as signals, duration.

Every robot module (:mod:`wmr_mujoco.robots`) lists its own scenarios. A scenario is one
of three kinds (:class:`ScenarioKind`):

* ``KINEMATIC``: rate inputs in the lecture's terms, through the physics (servoed wheels
  and steering) and the robot's kinematic model;
* ``DYNAMIC``: torque inputs, through the physics and the robot's Lagrange model;
* ``MEASUREMENT``: the scenario carries its own ``evaluate(scenario, params)`` that
  measures something in the physics (an eigenvalue, a steady precession, an energy
  budget) and returns a :class:`MeasurementResult`; the runner judges and reports it
  like any other. It may also carry ``film(scenario, params)``, the simulation after each
  step of the runs it measures (:class:`FilmFrame`), which ``wmr render`` films.
"""

from __future__ import annotations

import enum
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import TYPE_CHECKING

import numpy as np

from wmr_mujoco.choices import parse_choice
from wmr_mujoco.validation.family import Family
from wmr_mujoco.validation.metrics import Metric, Series
from wmr_mujoco.validation.signals import Signal
from wmr_mujoco.validation.variations import (
    DURATION,
    LEAD_IN,
    envelope,
    is_generic,
    scale_factors,
)

if TYPE_CHECKING:
    import mujoco

    from wmr_mujoco.models.params import RobotParams


class ScenarioKind(str, enum.Enum):
    """What a scenario compares (see the module docstring)."""

    KINEMATIC = "kinematic"
    DYNAMIC = "dynamic"
    MEASUREMENT = "measurement"


@dataclass(frozen=True)
class MeasurementResult:
    """What a measurement scenario's ``evaluate`` returns.

    Attributes:
        metrics: the measured quantities, judged against their targets.
        series: curves for the report's plot (optional).
    """

    metrics: list[Metric]
    series: list[Series] = field(default_factory=list)


#: ``evaluate(scenario, params)`` of a measurement scenario (params None: defaults).
Evaluate = Callable[["Scenario", "RobotParams | None"], MeasurementResult]

#: ``start(model, data, params)``: puts ``data`` in the state a measurement's free run
#: (no control, actuators at zero) starts from, with ``data.time`` at 0.
Start = Callable[["mujoco.MjModel", "mujoco.MjData", "RobotParams | None"], None]


@dataclass(frozen=True)
class FilmFrame:
    """The simulation of a measurement scenario at one step, for ``wmr render``.

    Attributes:
        model, data: the simulation after the step (live; a new ``data`` object starts a
            new run, and its trail).
        reference: the analytic path of the run, ``(N, 2)`` floor points (None: none).
    """

    model: mujoco.MjModel
    data: mujoco.MjData
    reference: np.ndarray | None = None


#: ``film(scenario, params)``: every step of the runs a measurement scenario measures.
Film = Callable[["Scenario", "RobotParams | None"], Iterator[FilmFrame]]


def free_run(start: Start, model_of: Callable[[RobotParams | None], mujoco.MjModel]) -> Film:
    """The :data:`Film` of one uncontrolled run from ``start``'s state.

    For a measurement whose physics is a single free run (a push, a release): the robot's
    model is compiled (``model_of(params)``), ``start`` puts ``data`` in the run's first
    state, the controls stay at zero, and ``mj_step`` advances it over the scenario's
    ``duration``; every step is one :class:`FilmFrame` (no analytic path).

    Raises:
        SimulationDivergedError: (while iterating) the run diverged.
    """
    def film(scenario: Scenario, params: RobotParams | None) -> Iterator[FilmFrame]:
        import mujoco

        from wmr_mujoco.sim.stepping import check_healthy

        model = model_of(params)
        data = mujoco.MjData(model)
        start(model, data, params)
        data.ctrl[:] = 0.0
        for _ in range(round(scenario.duration / model.opt.timestep)):
            mujoco.mj_step(model, data)
            check_healthy(model, data)
            yield FilmFrame(model, data)

    return film


@dataclass(frozen=True)
class Scenario:
    """One validation run.

    Attributes:
        robot: registry name.
        name: short label, unique per robot.
        inputs: one signal per input channel (the robot's adapter says which).
        duration: seconds after the settle.
        kind: :class:`ScenarioKind` (its string value is accepted).
        world_frame: inputs are world rates (Ẋ, Ẏ, ψ̇) rather than body rates.
        settle: seconds at rest before the inputs start.
        evaluate: a ``MEASUREMENT`` scenario's own measurement (see :data:`Evaluate`).
        film: a ``MEASUREMENT`` scenario's runs step by step, for clips (see :data:`Film`).
        description: one line for the report.
        family: what a user would vary in it and how many draws are judged (None: the
            scenario is one run; see :mod:`wmr_mujoco.validation.family`).
        draw: the values of this member of the family (empty: the nominal scenario).
        open_targets: metric name -> reason, for the requirements this scenario's family
            misses (its worst members): those metrics' targets become open
            (:meth:`~wmr_mujoco.validation.targets.Target.opened`), shown, not judged.
    """

    robot: str
    name: str
    inputs: tuple[Signal, ...] = ()
    duration: float = 10.0
    kind: ScenarioKind = ScenarioKind.KINEMATIC
    world_frame: bool = False
    settle: float = 0.5
    evaluate: Evaluate | None = field(default=None, compare=False)
    film: Film | None = field(default=None, compare=False)
    description: str = field(default="", compare=False)
    family: Family | None = field(default=None, compare=False)
    draw: Mapping[str, float] = field(default_factory=lambda: MappingProxyType({}))
    open_targets: Mapping[str, str] = field(default_factory=lambda: MappingProxyType({}),
                                            compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "kind", parse_choice(ScenarioKind, self.kind, "scenario kind"))
        if (self.kind is ScenarioKind.MEASUREMENT) != (self.evaluate is not None):
            raise ValueError(f"{self.key}: a {self.kind.value} scenario "
                             f"{'needs' if self.evaluate is None else 'takes no'} evaluate")
        if self.film is not None and self.kind is not ScenarioKind.MEASUREMENT:
            raise ValueError(f"{self.key}: a {self.kind.value} scenario takes no film "
                             "(wmr render films its run itself)")
        if not (np.isfinite(self.duration) and self.duration > 0):
            raise ValueError(f"{self.key}: duration = {self.duration!r} s; must be > 0")
        if not (np.isfinite(self.settle) and self.settle >= 0):
            raise ValueError(f"{self.key}: settle = {self.settle!r} s; must be >= 0")
        if self.draw:
            varied = {v.name for v in self.family.vary} if self.family else set()
            unknown = sorted(set(self.draw) - varied)
            if unknown:
                raise ValueError(f"{self.key}: draw sets {unknown}, which the family does not "
                                 f"vary; it varies {sorted(varied)}")
        if self.family is not None and self.kind is not ScenarioKind.MEASUREMENT:
            own = sorted(v.name for v in self.family.vary if not is_generic(v.name))
            if own:
                raise ValueError(f"{self.key}: a {self.kind.value} scenario varies only what "
                                 f"the runner applies (validation.variations); not {own}")
        object.__setattr__(self, "draw", MappingProxyType(dict(self.draw)))
        if self.inputs:
            scale_factors(self.draw, len(self.inputs))  # a bad channel fails here

    def __hash__(self) -> int:
        return hash((self.robot, self.name, self.kind, tuple(sorted(self.draw.items()))))

    def member(self, draw: Mapping[str, float]) -> Scenario:
        """The member of this scenario's family with the values ``draw``.

        A drawn ``duration`` (:data:`~wmr_mujoco.validation.variations.DURATION`) becomes
        the member's ``duration``; call it on the nominal scenario.
        """
        return replace(self, draw=draw, duration=float(draw.get(DURATION, self.duration)))

    def members(self, seed: int, draws: int | None = None) -> list[Scenario]:
        """The family's members for ``seed`` (``draws``: how many, default the family's).

        A scenario without a family is its own only member.

        Raises:
            ValueError: a bad seed or number of draws (:meth:`Family.sample`).
        """
        if self.family is None:
            return [self]
        return [self.member(d) for d in self.family.sample(seed, self.key, draws)]

    def value(self, name: str, nominal: float) -> float:
        """The drawn value of a varied quantity, or ``nominal`` (the nominal scenario)."""
        return float(self.draw.get(name, nominal))

    def opened(self, metrics: list[Metric]) -> list[Metric]:
        """``metrics`` with the targets named in :attr:`open_targets` made open."""
        if not self.open_targets:
            return metrics
        return [m._replace(target=m.target.opened(self.open_targets[m.name]))
                if m.target is not None and m.target.judged and m.name in self.open_targets
                else m for m in metrics]

    @property
    def key(self) -> str:
        """``robot/name``."""
        return f"{self.robot}/{self.name}"

    def input_at(self, t: float) -> np.ndarray:
        """Input vector at time ``t`` after the settle, with the draw's generic variations.

        ``u(t) = min(1, t / T) · s ⊙ u_nominal(t)`` with the drawn per-channel factors ``s``
        and lead-in ``T`` (:mod:`wmr_mujoco.validation.variations`; ones and no envelope
        for the nominal scenario).
        """
        u = np.array([s(t) for s in self.inputs])
        if not self.draw:
            return u
        return envelope(self.draw, t) * scale_factors(self.draw, len(u)) * u

    def inputs_on(self, nstep: int, dt: float) -> np.ndarray:
        """(nstep, m) rows :meth:`input_at` ``(k dt)``, ``k = 0 .. nstep − 1``: the same floats.

        The signals are evaluated at all times at once (their ``on``: the same arithmetic,
        elementwise; a signal without it one time after the other); the draw's factors
        once, and the lead-in envelope ``min(1, max(0, t / T))`` elementwise, multiplied in
        the same order.
        """
        times = np.arange(nstep) * dt  # k Δt, each one product as there
        u = np.empty((nstep, len(self.inputs)))
        for j, signal in enumerate(self.inputs):
            u[:, j] = (signal.on(times) if hasattr(signal, "on")
                       else [signal(t) for t in times.tolist()])  # Python floats, as f(t) had
        if not self.draw:
            return u
        ramp = self.draw.get(LEAD_IN)
        if ramp is None or ramp <= 0.0:
            env = np.ones(nstep)
        else:
            env = np.minimum(1.0, np.maximum(0.0, np.asarray(times) / ramp))
        return env[:, None] * scale_factors(self.draw, len(self.inputs))[None, :] * u
