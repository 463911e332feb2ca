"""Robots by name: the application layer's look-ups of the registry.

Generic code (models, simulation, validation) receives a :class:`RobotSpec`; only the
application looks a name up (:func:`wmr_mujoco.robots.get_spec`, loosely: any case, a
unique prefix, suggestions). These are the public entry points that take a name:
:func:`load` and :func:`build_scene` (the compiled or unbuilt scene), :func:`attach`
(a robot into a dm_control arena) and :func:`validation_jobs` (the scenarios to run).
"""

from __future__ import annotations

from collections.abc import Sequence

import mujoco
from dm_control import mjcf

from wmr_mujoco.choices import match_name
from wmr_mujoco.models import loading
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation.runner import Job, jobs
from wmr_mujoco.validation.spec import RobotSpec


def _spec(robot: str | RobotSpec) -> RobotSpec:
    """The registry entry of a robot name; a spec as it is.

    Raises:
        ValueError: unknown robot name (the message lists the valid ones).
    """
    return robot if isinstance(robot, RobotSpec) else get_spec(robot)


def load(robot: str | RobotSpec, params: RobotParams | None = None) -> mujoco.MjModel:
    """The compiled scene (robot, floor, light) of a registered robot or a spec.

    Args:
        robot: a name from :data:`wmr_mujoco.robots.ROBOTS`, or a ``RobotSpec``.
        params: None to load the checked-in ``scene.xml`` (a robot without files is built
            from its defaults); otherwise an instance of the robot's parameter dataclass.

    Raises:
        ValueError: unknown robot name (the message lists the valid ones) or wrong
            parameter type.
        FileNotFoundError: the scene file is missing (the message names the path).
    """
    return loading.load(_spec(robot), params)


def build_scene(robot: str | RobotSpec, params: RobotParams | None = None
                ) -> mjcf.RootElement:
    """The robot built from ``params`` (defaults if None) with floor and light, unbuilt.

    Raises:
        ValueError: unknown robot name, a robot without a builder, or wrong ``params``.
    """
    return loading.build_scene(_spec(robot), params)


def validation_jobs(robots: Sequence[str] | None = None,
                    names: Sequence[str] | None = None) -> list[Job]:
    """The registered scenarios of ``robots`` (all if None), each with its robot.

    Args:
        robots: registry names, in the order wanted (None: every robot, registry order).
        names: keep only the scenarios of these names (None: all).

    Raises:
        ValueError: an unknown robot, one without scenarios, or a name none of the chosen
            robots has; the message lists the valid ones.
    """
    from wmr_mujoco.robots import ROBOTS

    if robots is None:
        specs = list(ROBOTS.values())
    else:
        have = [name for name, spec in ROBOTS.items() if spec.scenarios]
        specs = [get_spec(r) for r in robots]
        for spec in specs:
            if not spec.scenarios:
                raise ValueError(f"no validation scenarios for robot {spec.name!r}; robots "
                                 f"with scenarios: {', '.join(have)}")
    work = jobs(specs)
    if names:
        valid = list(dict.fromkeys(s.name for _, s in work))
        where = ", ".join(robots or ()) or "any robot"
        chosen = {match_name(n, valid, "scenario", f"no scenario {n!r} for {where}",
                             f"valid: {', '.join(map(repr, valid))}") for n in names}
        work = [(spec, s) for spec, s in work if s.name in chosen]
    return work


def attach(arena: mjcf.RootElement, robot: str, pos: Sequence[float] = (0.0, 0.0, 0.0),
           quat: Sequence[float] | None = None, params: RobotParams | None = None,
           floor: str | None = None) -> mjcf.Element:
    """Attach a registered robot to a dm_control ``mjcf`` arena; return the frame.

    ``arena.attach(mjcf.from_path("models/omni3/omni3.xml"))`` fails on the robot's free
    joint and drops the contact pairs its scene adds; this loads the robot file (built
    from ``params`` if given), moves the free joint to the frame and adds the pairs
    against the arena's floor (:func:`~wmr_mujoco.models.attach.attach_robot`). Names
    inside the arena are prefixed with the robot's (``"omni3/wheel1"``).

    Raises:
        ValueError: unknown robot, a foreign model file, or the arena's floor not found.
    """
    from wmr_mujoco.models.attach import attach_robot

    spec = get_spec(robot)
    if spec.build is None or spec.params_type is None:
        raise ValueError(f"robot {spec.name!r} is a model file without a robot-only file; "
                         "attach it with arena.attach(mjcf.from_path(...)) yourself")
    chosen = params if params is not None else spec.params_type()
    if params is None and spec.folder is not None:
        root = mjcf.from_path(str(spec.robot_path))
    else:
        root = spec.build(chosen)
    return attach_robot(arena, root, pos, quat, spec.scene_extras, chosen, floor)
