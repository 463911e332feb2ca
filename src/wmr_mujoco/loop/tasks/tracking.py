"""One controller on one path, closing the loop in the physics and on the model.

:func:`run` drives a stepped robot (:func:`~wmr_mujoco.loop.build.build_robot`) with a
controller for a duration and measures how well it tracked:

* cross-track error ``e(t)``: signed distance from the path (> 0 left) of the point the
  controller steers onto it (the pose point; Stanley: the front axle), every control
  period; its worst ``max |e|`` and RMS ``√(mean e²)`` over the run, and the worst over
  the run's second half (the start offset has been corrected:
  what remains is the tracking of the path itself);
* final pose error: distance and heading difference at the end from the controller's
  own reference — the goal pose (go-to-pose: the end of an open path, the half-way
  point of a closed one), the reference at the final time
  (trajectory trackers), the path point nearest the tracking point and its tangent (path
  followers).

:func:`compare` runs the same task on the ``mujoco`` backend (contact physics) and the
``kinematic`` backend (the robot's analytic model), from the same start;
:mod:`wmr_mujoco.control.closed_loop` does so by robot name and over seeded families,
:mod:`wmr_mujoco.loop.tasks.families` as judged validation scenarios.

The start is the path's start pose offset by ``(along, lateral, heading)`` in the path's
frame. A draw ``k`` uses ``numpy.random.default_rng(k)``: lateral offset uniform in
``±LATERAL`` m, heading offset in ``±HEADING`` rad; path seed ``k``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.loop.build import build_robot
from wmr_mujoco.loop.control import registry
from wmr_mujoco.loop.control.base import Controller, Trajectory, wrap
from wmr_mujoco.loop.control.paths import Path
from wmr_mujoco.loop.robot import Robot
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.validation.spec import RobotSpec

#: Range of the drawn start offsets: lateral m, heading rad.
LATERAL, HEADING = 0.15, 0.2
#: Control period of the runs, s.
PERIOD = 0.02
#: Go-to-pose runs last the goal's distance at the speed limit, and this long more, s.
GOAL_EXTRA_TIME = 10.0
#: An open path is run until this far before its end (the followers look ahead), m.
END_MARGIN = 2.0


@dataclass(frozen=True)
class Run:
    """One closed-loop run.

    Attributes:
        backend: ``"mujoco"`` or ``"kinematic"``.
        time: ``(K + 1,)`` s.
        pose: ``(K + 1, 3)`` ``(x, y, ψ)``.
        cross_track: ``(K + 1,)`` signed cross-track error, m.
        final_position_error: m.
        final_heading_error: rad (wrapped, absolute).
    """

    backend: str
    time: np.ndarray
    pose: np.ndarray
    cross_track: np.ndarray
    final_position_error: float
    final_heading_error: float

    @property
    def worst_cross_track(self) -> float:
        """``max |e|``, m."""
        return float(np.abs(self.cross_track).max())

    @property
    def settled_cross_track(self) -> float:
        """``max |e|`` over the second half of the run, m."""
        return float(np.abs(self.cross_track[len(self.cross_track) // 2:]).max())

    @property
    def rms_cross_track(self) -> float:
        """``√(mean e²)``, m."""
        return float(np.sqrt(np.mean(np.square(self.cross_track))))


@dataclass(frozen=True)
class Comparison:
    """The same task in the physics and on the model.

    Attributes:
        physics: the ``mujoco`` run.
        model: the ``kinematic`` run.
    """

    physics: Run
    model: Run

    @property
    def max_deviation(self) -> float:
        """Largest distance between the two runs' positions at the same time, m."""
        n = min(len(self.physics.pose), len(self.model.pose))
        return float(np.linalg.norm(self.physics.pose[:n, :2] - self.model.pose[:n, :2],
                                    axis=1).max())


def reference(controller: Controller, path: Path, speed: float):
    """What ``controller`` tracks on ``path``: its end pose, the path, or the trajectory."""
    if controller.reference_type == "path":
        return path
    if controller.reference_type == "trajectory" or controller.name == "holonomic":
        return Trajectory(path, speed)
    if controller.reference_type == "pose":
        return goal(path)
    raise ValueError(f"controller {controller.name!r} does not follow paths "
                     f"(its reference: {controller.reference_type})")


def goal(path: Path) -> np.ndarray:
    """The goal pose of go-to-pose on ``path``: its end (a closed path: half-way)."""
    return path.at(path.length / 2 if path.closed else path.length).pose


def duration(controller: Controller, path: Path, speed: float) -> float:
    """Run time: the path at ``speed`` (open: to ``END_MARGIN`` short of the end), s."""
    if controller.reference_type == "pose" and controller.name != "holonomic":
        distance = np.hypot(*(goal(path)[:2] - path.start_pose[:2]))
        return float(distance / speed + GOAL_EXTRA_TIME)
    length = path.length if path.closed else path.length - END_MARGIN
    return length / speed


def start_pose(path: Path, offset: tuple[float, float, float]) -> np.ndarray:
    """The path's start pose moved by ``(along, lateral, heading)`` in its own frame."""
    x, y, psi = path.start_pose
    a, lat, dpsi = offset
    return np.array([x + a * math.cos(psi) - lat * math.sin(psi),
                     y + a * math.sin(psi) + lat * math.cos(psi), psi + dpsi])


def run(robot: Robot, controller: Controller, path: Path, start: np.ndarray, seconds: float,
        speed: float = registry.SPEED) -> Run:
    """Drive ``robot`` (a stepped robot) with ``controller`` on ``path``.

    Raises:
        SimulationDivergedError: the physics diverged.
    """
    ref = reference(controller, path, speed)
    controller.reset()
    state = robot.reset(pose=start)
    steps = round(seconds / robot.control_period)
    poses = [np.array(state.pose, float)]
    for _ in range(steps):
        state = robot.step(controller(state, ref, robot.time))
        poses.append(np.array(state.pose, float))
    pose = np.array(poses)
    errors, hint = [], 0.0  # the start lies by the path's start
    for p in pose:
        e, hint = path.cross_track(controller.tracking_point(p), hint)
        errors.append(e)
    final = pose[-1]
    point = final[:2]
    if isinstance(ref, Trajectory):
        target = ref.at(robot.time)[0].pose
    elif isinstance(ref, Path):
        point = controller.tracking_point(final)
        target = path.closest(point, hint).pose
    else:
        target = np.asarray(ref, float)
    return Run(robot.backend, np.arange(len(pose)) * robot.control_period, pose,
               np.array(errors), float(np.hypot(*(point - target[:2]))),
               abs(wrap(float(final[2] - target[2]))))


def compare(spec: RobotSpec, controller_name: str, path: Path,
            offset: tuple[float, float, float] = (0.0, 0.0, 0.0),
            params: RobotParams | None = None, control_period: float = PERIOD,
            robots: dict[str, Robot] | None = None,
            seconds: float | None = None) -> Comparison:
    """One task on both backends from the same start (module docstring).

    ``robots``: the two stepped robots by backend to reuse (None: built here);
    ``seconds``: the run's length (None: :func:`duration`, the whole path).

    Raises:
        ValueError: a controller that cannot drive the robot or follows no path, or a
            robot without a kinematic model (before any run).
        SimulationDivergedError: the physics diverged.
    """
    if spec.command is None or spec.params_type is None:
        raise ValueError(f"robot {spec.name!r} cannot be driven by a controller")
    p = params if params is not None else spec.params_type()
    if registry.build(controller_name, spec.command.names, p).reference_type == "upright":
        raise ValueError(f"controller {controller_name!r} follows no path")
    if spec.command.analytic(params) is None:
        raise ValueError(f"robot {spec.name!r} has no kinematic model to compare with")
    if robots is None:
        robots = {b: build_robot(spec, backend=b, control_period=control_period,
                                 params=params) for b in ("mujoco", "kinematic")}
    runs = {}
    for backend in ("mujoco", "kinematic"):
        controller = registry.build(controller_name, spec.command.names, p)
        length = duration(controller, path, registry.SPEED) if seconds is None else seconds
        runs[backend] = run(robots[backend], controller, path, start_pose(path, offset),
                            length)
    return Comparison(runs["mujoco"], runs["kinematic"])
