"""Open-loop trials of omni-wheeled models, through the validation runner.

A trial holds a body twist (reached by a linear ramp) for 5 s from a settled start, as
wheel commands from the ideal kinematics ``θ̇ = H ν``. Trials are ordinary kinematic
:class:`~wmr_mujoco.validation.scenarios.Scenario` objects, run by the one validation
runner and judged by the robot's registry entry. A foreign model (the peer) runs through
the same runner: :func:`peer_spec` wraps its scene file in a
:class:`~wmr_mujoco.validation.spec.RobotSpec` whose adapter (:class:`ServoOmniKinematics`) reads
the wheel layout from the compiled model and commands its angle (or rate) servos.
"""

from __future__ import annotations

import functools
import importlib
import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

import mujoco
import numpy as np

from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.models.paths import REPO_ROOT
from wmr_mujoco.robots.roller_wheels import (
    DIRECTIONS_DEG,
    SPEED,
    YAW_RATE,
    OmniModelInfo,
    layout_from_model,
    omni_probes,
    translation,
    twist_inputs,
)
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.sim.engine import Engine, simulate
from wmr_mujoco.sim.timing import timed
from wmr_mujoco.validation.adapters import AdapterFactory, body_pose
from wmr_mujoco.validation.metrics import Target, Trace, row_value
from wmr_mujoco.validation.runner import ScenarioResult, measure, prepare
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.spec import RobotSpec

#: Seconds each trial runs after the settle.
DURATION = 5.0

#: The peer model: MuJoCo Menagerie's robot_soccer_kit, measured, never copied here.
PEER_NAME = "robot_soccer_kit"
PEER_WHEELS = ("wheel1_speed", "wheel2_speed", "wheel3_speed")
#: The last place :func:`find_peer` looks: a ``shared/anchors`` folder beside the checkout.
PEER_SCENE = REPO_ROOT.parent / "shared" / "anchors" / PEER_NAME / "scene.xml"
#: The PyPI package that fetches Menagerie models (on first use, from the internet).
MENAGERIE_MODULE = "mujoco_menagerie"


@dataclass(frozen=True)
class PeerModel:
    """Where the peer's scene file was found, and how (said by ``wmr bench``)."""

    scene: Path
    source: str


def _menagerie_scene(module: ModuleType) -> Path | None:
    """The peer's default scene through the ``mujoco-menagerie`` package, if it has one.

    ``mm.get(name)`` is the package's handle on a robot (nothing downloaded yet) and
    ``default_scene`` its scene entry. The entry's file: ``path(entry)`` where the handle
    has it, else the folder of the entry's ``mujoco.MjSpec`` (``spec(entry)``, which
    downloads the model on first use) and ``<entry>.xml`` in it. Any failure (offline, no
    such robot) is None.
    """
    try:
        robot = module.get(PEER_NAME)
        entry = robot.default_scene
        if callable(getattr(robot, "path", None)):
            scene = Path(robot.path(entry))
        else:
            scene = Path(robot.spec(entry).modelfiledir) / f"{entry}.xml"
    except Exception:
        return None
    return scene if scene.is_file() else None


def find_peer(environ: Mapping[str, str] = os.environ,
              importer: Callable[[str], ModuleType] = importlib.import_module,
              sibling: Path = PEER_SCENE) -> PeerModel | None:
    """Find the peer's scene; None when no place has the file.

    In order: the ``mujoco-menagerie`` package (if installed; it downloads the model on
    first use), else the ``WMR_PEER_SCENE`` variable, else the sibling folder
    :data:`PEER_SCENE`.
    """
    try:
        scene = _menagerie_scene(importer(MENAGERIE_MODULE))
    except ImportError:
        scene = None
    if scene is not None:
        return PeerModel(scene, "the mujoco-menagerie package")
    if environ.get("WMR_PEER_SCENE"):
        scene = Path(environ["WMR_PEER_SCENE"])
        return PeerModel(scene, "WMR_PEER_SCENE") if scene.is_file() else None
    return PeerModel(sibling, "the shared/anchors folder beside the checkout") \
        if sibling.is_file() else None


def standard_trials(robot: str, speed: float = SPEED, yaw_rate: float = YAW_RATE
                    ) -> tuple[Scenario, ...]:
    """Translations in 8 directions, pure rotation, and two translation+rotation trials."""
    twists = [(f"translate {deg:>3d}°", translation(deg, speed)) for deg in DIRECTIONS_DEG]
    twists += [("rotate", (0.0, 0.0, yaw_rate)),
               ("translate+rotate", (speed, 0.0, 0.5 * yaw_rate)),
               ("diagonal+rotate", (-0.6 * speed, 0.6 * speed, -yaw_rate))]
    return tuple(Scenario(robot, name, twist_inputs(twist), duration=DURATION)
                 for name, twist in twists)


@dataclass(frozen=True)
class ServoOmniKinematics:
    """Ideal kinematics of a foreign omni-wheeled model, layout read from the model.

    State ``(X, Y, ψ, θ₁ … θₙ)``: the base pose and the wheel angles, ``θ̇ = H ν``. An
    angle servo gets the analytic wheel angle as its target, a rate servo ``H ν``; the
    model's actuators are left as they are (``mode`` None).
    """

    info: OmniModelInfo
    nu: int
    qpos_adr: tuple[int, ...]
    wheel_joints: tuple[str, ...]
    mode: None = None
    lateral_wheels: tuple[str, ...] = ()

    @property
    def layout(self) -> ok.WheelLayout:
        """The wheel layout read from the compiled model."""
        return self.info.layout

    @functools.cached_property
    def jacobian(self) -> np.ndarray:
        """``H`` with ``θ̇ = H ν``."""
        return ok.wheel_jacobian(self.layout)

    @property
    def state_names(self) -> tuple[str, ...]:
        """Pose, then one angle per wheel."""
        return ("x", "y", "heading", *(f"θ{i + 1}" for i in range(len(self.qpos_adr))))

    @property
    def state_units(self) -> tuple[str, ...]:
        """Metres and radians."""
        return ("m", "m", "rad", *("rad",) * len(self.qpos_adr))

    def twist(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """The body twist is the input."""
        return np.asarray(u, float)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Wheel angle targets (angle servos) or wheel rates (rate servos)."""
        ctrl = np.zeros(self.nu)
        rates = self.jacobian @ np.asarray(u, float)
        ctrl[list(self.info.wheel_actuators)] = np.where(self.info.angle_servo,
                                                         analytic_state[3:], rates)
        return ctrl

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """``(Ẋ, Ẏ, ψ̇) = R(ψ) ν`` and ``θ̇ = H ν``."""
        return np.concatenate([ok.body_to_world(x[2], u), self.jacobian @ np.asarray(u)])

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose of the free base body and the wheel angles."""
        return np.concatenate([body_pose(model, data, self.info.base_body),
                               data.qpos[list(self.qpos_adr)]])


def servo_omni_adapter(wheels: tuple[str, ...]) -> AdapterFactory:
    """The adapter factory of a foreign omni model whose wheel hinges are ``wheels``."""
    def factory(scenario: Scenario, model: mujoco.MjModel, params: RobotParams | None
                ) -> ServoOmniKinematics:
        info = layout_from_model(model, wheels)
        return ServoOmniKinematics(info, model.nu, tuple(int(model.jnt_qposadr[j])
                                                         for j in info.wheel_joints), wheels)
    return factory


def peer_spec(scene: Path | None = None, targets: dict[str, Target] | None = None
              ) -> RobotSpec:
    """The peer model as a registry entry with the standard trials (not registered).

    Args:
        scene: its scene file (None: :func:`find_peer`).
        targets: targets to judge it by.

    Raises:
        FileNotFoundError: no scene file there; the message says how to point at one.
    """
    if scene is None:
        peer = find_peer()
        scene = PEER_SCENE if peer is None else peer.scene
    if not Path(scene).is_file():
        raise FileNotFoundError(f"peer model not found: {scene} (install mujoco-menagerie, "
                                "or set WMR_PEER_SCENE to robot_soccer_kit's scene.xml)")
    return RobotSpec(
        name=PEER_NAME, description="robot_soccer_kit (MuJoCo Menagerie), as published",
        params_type=None, build=None, scene=Path(scene),
        adapters={ScenarioKind.KINEMATIC: servo_omni_adapter(PEER_WHEELS)},
        probes=(omni_probes,), targets=targets or {},
        scenarios=standard_trials(PEER_NAME))


@dataclass
class TrialRun:
    """A trial's judged result and the real-time factor of its ``mj_step`` loop."""

    result: ScenarioResult
    real_time_factor: float

    def value(self, metric: str, unit: str) -> float:
        """A metric's value (NaN if absent)."""
        return row_value(self.result.rows, metric, unit, float("nan"))


def run_trial(spec: RobotSpec, s: Scenario, params: RobotParams | None = None) -> TrialRun:
    """Run one trial of ``spec`` through the validation runner, stepping in Python to time it.

    The real-time factor is simulated time over the wall time of the step loop alone
    (:func:`wmr_mujoco.sim.engine.simulate`, with its state copies and health checks).

    Raises:
        SimulationDivergedError: the run diverged.
    """
    prep = prepare(spec, s, params)
    states: list[np.ndarray] = []
    wall = timed(lambda: states.append(simulate(prep.model, prep.data, prep.controls,
                                                Engine.LOOP)))
    trace = Trace()
    result = ScenarioResult(s, measure(prep, states[0], trace), trace)
    return TrialRun(result, len(prep.controls) * prep.model.opt.timestep / wall)
