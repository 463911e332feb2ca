""":class:`RobotSpec`: everything the generic code knows about one robot."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from types import MappingProxyType
from typing import Generic, TypeVar

from dm_control import mjcf

from wmr_mujoco.choices import match_name
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.models.paths import MODELS_DIR
from wmr_mujoco.validation.adapters import AdapterFactory
from wmr_mujoco.validation.command import CommandMap
from wmr_mujoco.validation.metrics import Judge, ProbeFactory, Target, pose_tracking
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind

P = TypeVar("P", bound=RobotParams)

#: Judges used for a kind when the robot gives none: pose tracking for rate inputs.
DEFAULT_JUDGES: Mapping[ScenarioKind, Judge] = MappingProxyType(
    {ScenarioKind.KINEMATIC: pose_tracking})


@dataclass(frozen=True)
class Picture:
    """How the robot is posed for its README picture (``make pictures``).

    Attributes:
        keyframe: a keyframe to start from (None: the model's rest pose).
        joint_angles: hinge angles to set, rad; an integrator actuator (a steering servo)
            on such a joint gets the same angle as its target.
    """

    keyframe: str | None = None
    joint_angles: Mapping[str, float] = field(default_factory=dict)


@dataclass(frozen=True)
class Clip:
    """One clip of the robot in ``renders/`` (``wmr render --all``, ``make renders``).

    Attributes:
        scenario: the scenario filmed (None: the robot's render scenario).
        file: file name in the output folder, ``.gif``, ``.mp4`` or ``.png`` (the last
            frame; None: ``<robot>.gif``).
        duration: seconds filmed (None: the whole scenario).
        width: pixels.
        height: pixels.
        fps: frames per second.
    """

    scenario: str | None = None
    file: str | None = None
    duration: float | None = None
    width: int = 200
    height: int = 150
    fps: int = 8


#: ``peer(scene, quick) -> rows``: the robot and the foreign model in ``scene`` on the same
#: trials (fewer if ``quick``), one row each with ``label``, ``worst_position_pct``,
#: ``worst_heading_deg`` and ``real_time_factor``.
PeerComparison = Callable[[Path, bool], list[Mapping[str, object]]]


@dataclass(frozen=True)
class RobotSpec(Generic[P]):
    """Everything the package knows about one robot.

    Attributes:
        name: registry key, also the model name.
        description: one line for ``wmr list``.
        params_type: frozen dataclass of the robot's physical parameters (None for a
            foreign model read from a file, without parameters).
        build: builder ``params -> mjcf.RootElement`` of the robot alone (None: foreign).
        folder: model folder under :data:`~wmr_mujoco.models.paths.MODELS_DIR` holding
            ``robot_file`` and ``scene_file`` (None: always built from ``params``).
        robot_file: robot-only MJCF file in that folder.
        scene_file: MJCF file that includes the robot and adds floor and light.
        scene: absolute path of a foreign scene file (overrides the folder).
        adapters: per scenario kind, the factory of the analytic model's adapter.
        judges: per scenario kind, the judge of a run (default: :data:`DEFAULT_JUDGES`).
        probes: per-robot measurements taken during every run (each decides whether it
            applies to a scenario).
        targets: the robot's targets by key (see :mod:`wmr_mujoco.validation.metrics`).
        scenarios: its validation scenarios.
        demo_scenario: the scenario ``wmr demo`` shows (None: not shown).
        bench_scenario: the scenario of ``wmr bench``'s accuracy-against-timestep table.
        render_scenario: the default scenario of ``wmr render`` (None: first kinematic).
        picture: the pose of the README picture.
        clips: its clips in ``renders/`` (default: one GIF of the render scenario).
        peer: the robot's side-by-side with a foreign model on the same trials, for
            ``wmr bench`` (see :data:`PeerComparison`; None: the robot has no peer).
        scene_extras: ``(scene root, params) -> None``, elements that name the scene's
            geoms (contact pairs with the ``floor``), added after the floor in the built
            and the checked-in scene (None: nothing).
        command: how the robot is driven step by step (:mod:`wmr_mujoco.drive`): its
            natural command space and wheels (None: it cannot be driven, no actuators).
        command_range: per kinematic input, the largest magnitude a user commands (the
            range of the random stepped inputs, :mod:`wmr_mujoco.bench.floor_runs`; None:
            the largest its kinematic scenarios command).
        open_targets: scenario name -> (metric name -> reason): requirements the robot's
            worst draws miss in scenarios it does not declare itself (the families every
            drivable robot gets: random steps, closed loop), shown open with the reason.
        prepare: ``(members, params) -> None``, runs the given members of its measurement
            families at once (batched) before they are evaluated one by one, so that each
            ``evaluate`` finds its run ready (None: each member runs on its own; a member
            not prepared still evaluates correctly, only slower).
        prepared_together: names of measurement scenarios whose families' members
            ``prepare`` best runs in one call (runs of one length: a batched model's
            cost is per step); ``wmr validate`` runs those families as one unit of work
            (:mod:`wmr_mujoco.validation.units`), with the same results.
    """

    name: str
    description: str
    params_type: type[P] | None
    build: Callable[[P], mjcf.RootElement] | None
    folder: str | None = None
    robot_file: str = ""
    scene_file: str = "scene.xml"
    scene: Path | None = None
    adapters: Mapping[ScenarioKind, AdapterFactory] = field(default_factory=dict)
    judges: Mapping[ScenarioKind, Judge] = field(default_factory=dict)
    probes: tuple[ProbeFactory, ...] = ()
    targets: Mapping[str, Target] = field(default_factory=dict)
    scenarios: tuple[Scenario, ...] = ()
    demo_scenario: str | None = None
    bench_scenario: str | None = None
    render_scenario: str | None = None
    picture: Picture = Picture()
    clips: tuple[Clip, ...] = (Clip(),)
    peer: PeerComparison | None = None
    scene_extras: Callable[[mjcf.RootElement, P], None] | None = None
    command: CommandMap | None = None
    command_range: tuple[float, ...] | None = None
    prepare: Callable[[Sequence[Scenario], P | None], None] | None = None
    open_targets: Mapping[str, Mapping[str, str]] = field(default_factory=dict)
    prepared_together: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if self.open_targets:  # also for scenarios appended later (dataclasses.replace)
            object.__setattr__(self, "scenarios", tuple(
                replace(s, open_targets={**s.open_targets, **self.open_targets[s.name]})
                if s.name in self.open_targets and not set(self.open_targets[s.name])
                <= set(s.open_targets) else s for s in self.scenarios))
        names = [s.name for s in self.scenarios]
        if len(set(names)) != len(names):
            raise ValueError(f"robot {self.name!r}: scenario names repeat: {names}")
        measured = {s.name for s in self.scenarios if s.kind is ScenarioKind.MEASUREMENT}
        if self.prepared_together and (self.prepare is None or not set(
                self.prepared_together) <= measured):
            raise ValueError(f"robot {self.name!r}: prepared_together "
                             f"{sorted(set(self.prepared_together) - measured)} are not its "
                             "measurement scenarios, or it has no prepare")
        wrong = [s.key for s in self.scenarios if s.robot != self.name]
        if wrong:
            raise ValueError(f"robot {self.name!r} lists scenarios of other robots: {wrong}")
        for s in self.scenarios:
            if s.kind is ScenarioKind.MEASUREMENT:
                continue
            if s.kind not in self.adapters:
                raise ValueError(f"{s.key}: robot {self.name!r} has no {s.kind.value} "
                                 f"adapter; it has: {[k.value for k in self.adapters]}")
            if self.judge(s.kind) is None:
                raise ValueError(f"{s.key}: robot {self.name!r} has no judge for "
                                 f"{s.kind.value} scenarios")
        for label, chosen in (("demo", self.demo_scenario), ("bench", self.bench_scenario),
                              ("render", self.render_scenario)):
            if chosen is not None and chosen not in names:
                raise ValueError(f"robot {self.name!r}: {label} scenario {chosen!r} is not "
                                 f"one of its scenarios {names}")
        for clip in self.clips:
            if clip.scenario is not None and clip.scenario not in names:
                raise ValueError(f"robot {self.name!r}: clip scenario {clip.scenario!r} is "
                                 f"not one of its scenarios {names}")
        files = [self.clip_file(c) for c in self.clips]
        if len(set(files)) != len(files):
            raise ValueError(f"robot {self.name!r}: clip files repeat: {files}")
        if (self.build is None) != (self.params_type is None):
            raise ValueError(f"robot {self.name!r}: give both build and params_type, or "
                             "neither (a foreign model file)")
        if self.build is None and self.scene is None:
            raise ValueError(f"robot {self.name!r}: a foreign model needs its scene path")

    @property
    def robot_path(self) -> Path:
        """Absolute path of the robot-only MJCF file (foreign: the scene)."""
        if self.scene is not None:
            return self.scene
        return MODELS_DIR / (self.folder or self.name) / self.robot_file

    @property
    def scene_path(self) -> Path:
        """Absolute path of the scene MJCF file."""
        if self.scene is not None:
            return self.scene
        return MODELS_DIR / (self.folder or self.name) / self.scene_file

    @property
    def has_files(self) -> bool:
        """Whether the robot has checked-in MJCF files (or a foreign scene)."""
        return self.scene is not None or self.folder is not None

    def clip_file(self, clip: Clip) -> str:
        """File name of one of its clips."""
        return clip.file or f"{self.name}.gif"

    def judge(self, kind: ScenarioKind) -> Judge | None:
        """The judge of a scenario kind: the robot's own, else the default."""
        return self.judges.get(kind, DEFAULT_JUDGES.get(kind))

    def scenario(self, name: str) -> Scenario:
        """One of its scenarios by name, typed loosely (any case, ``°`` optional, a prefix).

        Raises:
            ValueError: no such scenario (the message suggests the nearest and lists the
                valid ones), or a prefix of several.
        """
        names = [s.name for s in self.scenarios]
        found = match_name(name, names, "scenario", f"no scenario {name!r} for {self.name!r}",
                           f"valid scenarios: {', '.join(map(repr, names)) or 'none'}")
        return self.scenarios[names.index(found)]
