"""MuJoCo Warp against C MuJoCo on one robot: the same members through both backends.

Members are seeded draws from the robot's own kinematic validation scenarios: a scenario,
a speed scale ``a`` in :data:`SCALE` and a start phase ``t_0`` in ``[0, T_s / 2]`` (``T_s``
the scenario's duration), so member inputs are ``u(t) = a · u_s(t + t_0)``. Both backends
run them from the same settled starts; the difference is judged as the validation judges
a model: the worst base position difference over the run,

    e = max_k |p_warp(t_k) − p_C(t_k)|,

as a percentage of the C run's path length against ``SHARE`` × the robot's target
``worst position error % of path`` (a path under ``MIN_PATH``: ``e`` in metres against
``SHARE`` × its ``worst centre drift m`` target). With ``SHARE`` below one, the engine
changes a validation error by less than that share of its budget.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.batch.simulate import simulate_batch
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation.metrics import CENTRE_DRIFT_M, MIN_PATH, POSITION_PCT
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind

#: Range of the speed scale of the drawn members.
SCALE = (0.5, 1.0)
#: The share of the robot's position target that the engines' difference may take: a
#: quarter of the validation budget, so that the engine never decides a verdict that has
#: more than 25 % margin.
SHARE = 0.25


@dataclass(frozen=True)
class Parity:
    """The worst member's difference between the backends.

    Attributes:
        robot: the robot.
        members: members run.
        duration: seconds per member.
        worst: the worst member's judged difference, in ``unit``.
        unit: ``"% of path"`` or ``"m"`` (path under ``MIN_PATH``).
        worst_m: the largest position difference of any member, m.
        tolerance: ``SHARE`` × the robot's target, in ``unit``.
    """

    robot: str
    members: int
    duration: float
    worst: float
    unit: str
    worst_m: float
    tolerance: float

    @property
    def passed(self) -> bool:
        """Within the tolerance."""
        return self.worst <= self.tolerance


def _scaled(s: Scenario, j: int, a: float, t0: float) -> Callable[[float], float]:
    return lambda t: a * float(s.inputs[j](t + t0))


def draws(robot: str, members: int, seed: int) -> list[list[Callable[[float], float]]]:
    """Seeded member inputs from the robot's kinematic body-frame scenarios.

    Raises:
        ValueError: the robot has no such scenario.
    """
    pool = [s for s in get_spec(robot).scenarios
            if s.kind is ScenarioKind.KINEMATIC and not s.world_frame]
    if not pool:
        raise ValueError(f"robot {robot!r} has no kinematic body-frame scenarios to draw from")
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(members):
        s = pool[rng.integers(len(pool))]
        a, t0 = rng.uniform(*SCALE), rng.uniform(0.0, s.duration / 2)
        out.append([_scaled(s, j, a, t0) for j in range(len(s.inputs))])
    return out


def parity(robot: str, members: int = 3, duration: float = 1.0, seed: int = 0,
           params: RobotParams | None = None, **warp_options: object) -> Parity:
    """Run the draws through ``"rollout"`` and ``"warp"``; the worst member's difference.

    ``params``: the robot built from these parameters on both backends (None: defaults).

    Raises:
        ValueError: as :func:`~wmr_mujoco.batch.simulate_batch`; a robot without a
            position target.
        SimulationDivergedError: a backend diverged.
    """
    targets = get_spec(robot).targets
    if POSITION_PCT not in targets:
        raise ValueError(f"robot {robot!r} has no {POSITION_PCT!r} target to judge parity by")
    inputs = draws(robot, members, seed)
    ref = simulate_batch(robot, inputs, duration, backend="rollout", params=params
                         ).pose[:, :, :2]
    got = simulate_batch(robot, inputs, duration, backend="warp", params=params,
                         **warp_options).pose[:, :, :2]
    err = np.linalg.norm(got - ref, axis=2).max(axis=1)
    path = np.linalg.norm(np.diff(ref, axis=1), axis=2).sum(axis=1)
    pct_tol = SHARE * targets[POSITION_PCT].value
    drift = targets.get(CENTRE_DRIFT_M)
    drift_tol = SHARE * (drift.value if drift else targets[POSITION_PCT].value / 100 * MIN_PATH)
    # Judge every member by its own unit; report the one nearest its tolerance.
    ratios = [(e / p * 100 / pct_tol, e / p * 100, "% of path", pct_tol) if p > MIN_PATH
              else (e / drift_tol, e, "m", drift_tol) for e, p in zip(err, path, strict=True)]
    _, worst, unit, tol = max(ratios)
    return Parity(robot, members, duration, float(worst), unit, float(err.max()), tol)
