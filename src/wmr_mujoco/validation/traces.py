"""What a run records: the trace of states, the samples probes see, and probes.

The runner records every :data:`RECORD_EVERY`-th step (and the last one) into a
:class:`Trace`; a robot's :class:`Probe` sees each recorded step as a :class:`Sample`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol

import mujoco
import numpy as np

from wmr_mujoco.validation.targets import Metric, Target

if TYPE_CHECKING:
    from wmr_mujoco.validation.adapters import Adapter
    from wmr_mujoco.validation.scenarios import Scenario

#: Metrics are recorded every this many steps (and at the last one).
RECORD_EVERY = 5


@dataclass(frozen=True)
class Series:
    """A curve for the report's plots (a measurement scenario's own time series).

    Attributes:
        label: legend entry (one starting with ``_`` is left out of the legend).
        x, y: the points.
        xlabel, ylabel: axis labels; series with the same pair share a panel.
        style: matplotlib format string: ``"-"`` a curve, ``"o"`` points, ``"k--"`` ...
        color: matplotlib colour (None: the next of the cycle).
    """

    label: str
    x: np.ndarray
    y: np.ndarray
    xlabel: str = "t [s]"
    ylabel: str = ""
    style: str = "-"
    color: str | None = None


@dataclass
class Trace:
    """Time series of one run, for judges and plots.

    ``sim`` and ``analytic`` hold the adapter's state (``state_names``, ``state_units``)
    read from the physics and integrated by the model; ``slip`` the lateral slip speed of
    each conventional wheel; ``series`` any further curves.
    """

    time: list[float] = field(default_factory=list)
    sim: list[np.ndarray] = field(default_factory=list)
    analytic: list[np.ndarray] = field(default_factory=list)
    slip: list[np.ndarray] = field(default_factory=list)
    state_names: tuple[str, ...] = ()
    state_units: tuple[str, ...] = ()
    series: list[Series] = field(default_factory=list)

    def arrays(self) -> dict[str, np.ndarray]:
        """The series as arrays."""
        return {"time": np.asarray(self.time), "sim": np.asarray(self.sim),
                "analytic": np.asarray(self.analytic), "slip": np.asarray(self.slip)}

    @property
    def is_pose(self) -> bool:
        """Whether the state starts with a planar pose ``(x, y, heading)``."""
        return self.state_names[:3] == ("x", "y", "heading")


@dataclass(frozen=True)
class Sample:
    """What a probe sees at a recorded step ``k`` (data: after that step, live).

    Attributes:
        k: step index; ``t = k Δt`` seconds after the settle, at the step's start.
        t: that time, s.
        model, data: the simulation just after step ``k`` (contacts of its start).
        u: the scenario's input over the step.
        ctrl: the actuator controls over the step.
        x: the analytic state at the step's start.
    """

    k: int
    t: float
    model: mujoco.MjModel
    data: mujoco.MjData
    u: np.ndarray
    ctrl: np.ndarray
    x: np.ndarray


class Probe(Protocol):
    """A per-robot measurement taken during a run (e.g. a free wheel's rate).

    A probe may have an ``after`` attribute (s): it ignores the samples at ``t <= after``,
    and the runner need not rebuild those steps for it
    (:func:`~wmr_mujoco.validation.runner.first_read`); without it, every sample is read.
    """

    def observe(self, sample: Sample) -> None:
        """Take what it needs from one recorded step."""
        ...

    def metrics(self) -> list[Metric]:
        """Its metrics after the run."""
        ...


#: ``(scenario, model, adapter, targets) -> Probe``, or None where it does not apply.
ProbeFactory = Callable[["Scenario", mujoco.MjModel, "Adapter", Mapping[str, Target]],
                        "Probe | None"]
