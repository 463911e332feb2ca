"""Several kinematic runs of ``mecanum4`` judged as one measurement scenario.

The eight translations with ramps (and again with steps) are eight ordinary kinematic
scenarios: each is prepared, simulated and measured by the one runner
(:func:`~wmr_mujoco.validation.runner.prepare`, one batched
:func:`~wmr_mujoco.sim.engine.simulate_batch` for the group,
:func:`~wmr_mujoco.validation.runner.measure_metrics` with ``mecanum4``'s judge and probes)
and judged run by run, worst over each run. Grouping shares one settled start and one
rollout, and gives one plot of the eight error curves instead of eight plots.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.planar import cumulative_path
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.sim.engine import simulate_batch
from wmr_mujoco.validation.metrics import Metric, Series, Trace
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario

#: The metrics of each member kept in the group's rows: the judged ones (they have a
#: target), the other models' beside them (:data:`BESIDE`) and the RMS errors.
KEPT = ("RMS position error", "RMS heading error")
#: Name endings of the reported models' metrics (kinematic model of a step run, ideal).
BESIDE = ("kinematic model", "ideal model")


@dataclass(frozen=True)
class Group:
    """Kinematic member scenarios evaluated together (``evaluate`` of a measurement)."""

    members: tuple[Scenario, ...]

    def __call__(self, scenario: Scenario, params: RobotParams | None) -> MeasurementResult:
        """Run, measure and judge every member; one error curve each.

        A member of the group scenario's family passes its draw to every run (they
        declare the same family).
        """
        runs = [m.member(scenario.draw) for m in self.members] if scenario.draw \
            else list(self.members)
        return evaluate_group(runs, params)


def evaluate_group(members: Sequence[Scenario], params: RobotParams | None
                   ) -> MeasurementResult:
    """Each member through the runner's stages, simulated in one batch.

    The members share the first one's model and settled start (as a rollout batch of
    the runner does). Metric names carry the member's name; every member's judged
    metrics keep their targets. Series: the position error in % of the member's path
    over time.

    Raises:
        ValueError: members that differ in robot, kind or settle time.
    """
    from wmr_mujoco.robots.mecanum4 import SPEC  # the entry imports this module
    from wmr_mujoco.validation.runner import (
        Prepared,
        make_adapter,
        measure_metrics,
        prepare,
        schedule,
    )

    first = prepare(SPEC, members[0], params)
    model, data = first.model, first.data
    prepared = [first]
    for s in members[1:]:
        if (s.robot, s.kind, s.settle) != (first.scenario.robot, first.scenario.kind,
                                           first.scenario.settle):
            raise ValueError(f"{s.key}: a group shares one settled start; its members "
                             "need the same robot, kind and settle")
        adapter = make_adapter(SPEC, s, model, params)
        nstep = round(s.duration / model.opt.timestep)
        schedule_ = schedule(s, adapter, adapter.sim_state(model, data),
                             model.opt.timestep, nstep)
        prepared.append(Prepared(SPEC, s, model, data, adapter, *schedule_))
    nthread = max(1, (os.cpu_count() or 1) - 1)
    batch = simulate_batch(model, data, [p.controls for p in prepared], nthread)
    metrics: list[Metric] = []
    series: list[Series] = []
    for prep, states in zip(prepared, batch, strict=True):
        trace = Trace()
        name = prep.scenario.name
        for m in measure_metrics(prep, states, trace):
            if m.target is not None or m.name.endswith(BESIDE) or m.name in KEPT:
                metrics.append(m._replace(name=f"{name}: {m.name}"))
        tr = trace.arrays()
        err = np.linalg.norm(tr["sim"][:, :2] - tr["analytic"][:, :2], axis=1)
        path = float(cumulative_path(tr["analytic"][:, :2])[-1])
        series.append(Series(name, tr["time"], 100.0 * err / path, "t [s]",
                             "position error [% of path]"))
    return MeasurementResult(metrics, series)
