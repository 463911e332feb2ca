"""One controller on one path by robot name, and its seeded family (``docs/control.md``).

The runs and their figures are :mod:`wmr_mujoco.loop.tasks.tracking`'s (re-exported
here); :func:`compare` looks the robot up by name, :func:`family` repeats a task over
seeded draws (start offsets and, for the random spline, the path) and reports the worst
and the median of each figure. A draw ``k`` uses ``numpy.random.default_rng(k)``:
lateral offset uniform in ``±LATERAL`` m, heading offset in ``±HEADING`` rad; path seed
``k``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from wmr_mujoco.control import registry
from wmr_mujoco.loop.control.paths import Path, make_path
from wmr_mujoco.loop.tasks import tracking
from wmr_mujoco.loop.tasks.tracking import (
    END_MARGIN,
    GOAL_EXTRA_TIME,
    HEADING,
    LATERAL,
    PERIOD,
    Comparison,
    Run,
    duration,
    goal,
    reference,
    run,
    start_pose,
)
from wmr_mujoco.models.params import RobotParams

__all__ = ["END_MARGIN", "FIGURES", "GOAL_EXTRA_TIME", "HEADING", "LATERAL", "PERIOD",
           "Comparison", "Run", "Summary", "check_task", "compare", "compare_robots", "draw",
           "duration", "duration_of", "family", "goal", "reference", "run", "start_pose"]


def compare(robot_name: str, controller_name: str, path_name: str, seed: int = 0,
            offset: tuple[float, float, float] = (0.0, 0.0, 0.0),
            params: RobotParams | None = None, control_period: float = PERIOD) -> Comparison:
    """One task on both backends (module docstring).

    Raises:
        ValueError: unknown robot, controller or path, a controller that cannot drive
            the robot, or a robot without a kinematic model (before any run).
        SimulationDivergedError: the physics diverged.
    """
    return compare_robots(robot_name, controller_name, path_name, seed, offset, params,
                          control_period)[0]


def check_task(robot_name: str, controller_name: str, path_name: str, seed: int = 0,
               params: RobotParams | None = None) -> tuple[Any, Path]:
    """The robot's parameters and the path, after checking the task (no simulation).

    Raises:
        ValueError: as :func:`compare`.
    """
    from wmr_mujoco.robots import get_spec

    spec = get_spec(robot_name)
    if spec.command is None or spec.params_type is None:
        raise ValueError(f"robot {robot_name!r} cannot be driven by a controller")
    p = params if params is not None else spec.params_type()
    if registry.build(controller_name, spec.command.names, p).reference_type == "upright":
        raise ValueError(f"controller {controller_name!r} follows no path")
    if spec.command.analytic(params) is None:
        raise ValueError(f"robot {robot_name!r} has no kinematic model to compare with")
    return p, make_path(path_name, seed)


def compare_robots(robot_name: str, controller_name: str, path_name: str, seed: int = 0,
                   offset: tuple[float, float, float] = (0.0, 0.0, 0.0),
                   params: RobotParams | None = None, control_period: float = PERIOD
                   ) -> tuple[Comparison, dict[str, Any], Path]:
    """:func:`compare`, with the two stepped robots (by backend) and the path."""
    from wmr_mujoco.drive import make
    from wmr_mujoco.robots import get_spec

    _, path = check_task(robot_name, controller_name, path_name, seed, params)
    robots = {b: make(robot_name, backend=b, control_period=control_period, params=params)
              for b in ("mujoco", "kinematic")}
    comp = tracking.compare(get_spec(robot_name), controller_name, path, offset, params,
                            control_period, robots)
    return comp, robots, path


def duration_of(r: Run) -> float:
    """Length of a run, s."""
    return float(r.time[-1])


def draw(k: int) -> tuple[float, float, float]:
    """Start offset of draw ``k`` (module docstring)."""
    rng = np.random.default_rng(k)
    return 0.0, float(rng.uniform(-LATERAL, LATERAL)), float(rng.uniform(-HEADING, HEADING))


@dataclass(frozen=True)
class Summary:
    """Worst and median of a family's figures, per backend.

    Attributes:
        draws: number of draws.
        worst: ``{figure: (physics, model)}``, the largest over the draws.
        median: the same, the medians.
    """

    draws: int
    worst: dict[str, tuple[float, float]]
    median: dict[str, tuple[float, float]]


#: The figures of a family, by name: a run -> value.
FIGURES = {
    "worst cross-track [m]": lambda r: r.worst_cross_track,
    "RMS cross-track [m]": lambda r: r.rms_cross_track,
    "settled worst cross-track [m]": lambda r: r.settled_cross_track,
    "final position error [m]": lambda r: r.final_position_error,
    "final heading error [rad]": lambda r: r.final_heading_error,
}


def family(robot_name: str, controller_name: str, path_name: str, draws: int = 20,
           params: RobotParams | None = None) -> Summary:
    """:func:`compare` over ``draws`` seeded draws; worst and median of each figure.

    Raises:
        ValueError: ``draws`` not an integer in [1, 1000], or as :func:`compare`.
    """
    if isinstance(draws, bool) or not isinstance(draws, int) or not 1 <= draws <= 1000:
        raise ValueError(f"draws = {draws!r}; must be an integer in [1, 1000]")
    results = [compare(robot_name, controller_name, path_name, k, draw(k), params)
               for k in range(draws)]
    worst, median = {}, {}
    for name, fig in FIGURES.items():
        phys = np.array([fig(c.physics) for c in results])
        model = np.array([fig(c.model) for c in results])
        worst[name] = (float(phys.max()), float(model.max()))
        median[name] = (float(np.median(phys)), float(np.median(model)))
    dev = np.array([c.max_deviation for c in results])
    worst["physics-model deviation [m]"] = (float(dev.max()), 0.0)
    median["physics-model deviation [m]"] = (float(np.median(dev)), 0.0)
    return Summary(draws, worst, median)
