"""Loading robots: the checked-in scene files, or a scene built from parameters.

These functions receive the robot's description (a
:class:`~wmr_mujoco.validation.spec.RobotSpec`, or anything with the fields of
:class:`SceneSource`), never a name: looking a name up in the registry is the
application's job (:func:`wmr_mujoco.load`).

Compiling a scene costs tens of milliseconds; :func:`load` keeps the last
:data:`CACHE_SIZE` compiled scenes (by scene file and its modification times, or by
builder and parameters) and hands out a copy (``mj_copyModel``, a few milliseconds, the
same model array for array), so that the validation's many runs of one robot compile it
once and every caller may still modify the model it gets.
"""

from __future__ import annotations

import copy
from collections import OrderedDict
from collections.abc import Callable, Hashable
from pathlib import Path
from typing import Any, Protocol

import mujoco
from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.models.builders.scene import add_scene
from wmr_mujoco.models.params import RobotParams, params_or_default


class SceneSource(Protocol):
    """What loading needs to know of a robot (a ``RobotSpec`` has all of it).

    Attributes:
        name: the robot's name, for messages.
        params_type: its parameter dataclass (None: a foreign model file).
        build: ``params -> mjcf.RootElement`` of the robot alone (None: foreign).
        scene_extras: ``(scene root, params) -> None``, scene elements after the floor.
        has_files: whether checked-in MJCF files (or a foreign scene) exist.
        scene_path: the scene file.
        robot_path: the robot-only file.
    """

    name: str
    params_type: type[Any] | None
    build: Callable[[Any], mjcf.RootElement] | None
    scene_extras: Callable[[mjcf.RootElement, Any], None] | None
    has_files: bool
    scene_path: Path
    robot_path: Path


def build_scene(spec: SceneSource, params: RobotParams | None = None) -> mjcf.RootElement:
    """Build the robot from ``params`` (its defaults if None) and add floor and light.

    The result compiles to the same model as the checked-in ``scene.xml``, which
    ``<include>``s the robot file and then declares the same scene elements.

    Raises:
        ValueError: a robot without a builder (a foreign model file), or ``params`` of
            the wrong type.
    """
    if spec.build is None or spec.params_type is None:
        raise ValueError(f"robot {spec.name!r} is a model file ({spec.scene_path}) without "
                         "a builder; it takes no parameters")
    try:
        params = params_or_default(params, spec.params_type)
    except ValueError as err:
        raise ValueError(f"params for {spec.name!r}: {err}") from None
    root = spec.build(params)
    root.model = f"{root.model} scene"
    add_scene(root)
    if spec.scene_extras is not None:
        spec.scene_extras(root, params)
    return root


def load(spec: SceneSource, params: RobotParams | None = None) -> mujoco.MjModel:
    """Return the compiled scene of the robot ``spec`` describes.

    Args:
        spec: the robot.
        params: None to load the checked-in ``scene.xml`` (a robot without files is built
            from its defaults); otherwise an instance of the robot's parameter
            dataclass, built with dm_control ``mjcf``.

    Raises:
        ValueError: wrong parameter type.
        FileNotFoundError: the scene file is missing (the message names the path).
    """
    if params is not None or not spec.has_files:
        key: Hashable = ("built", spec.name, spec.build, spec.scene_extras, spec.params_type,
                         params)
        return _cached(key, lambda: mujoco.MjModel.from_xml_string(
            common.to_xml(build_scene(spec, params))))
    path = spec.scene_path
    for needed in (path, spec.robot_path):
        if not needed.is_file():
            raise FileNotFoundError(
                f"model file for {spec.name!r} not found: {needed} "
                f"(regenerate with `make models`)"
            )
    key = ("file", str(path.resolve()), path.stat().st_mtime_ns,
           str(spec.robot_path.resolve()), spec.robot_path.stat().st_mtime_ns)
    return _cached(key, lambda: mujoco.MjModel.from_xml_path(str(path)))


#: Compiled scenes kept by :func:`load` (the most recently used).
CACHE_SIZE = 32
_COMPILED: OrderedDict[Hashable, mujoco.MjModel] = OrderedDict()


def _cached(key: Hashable, compile_: Callable[[], mujoco.MjModel]) -> mujoco.MjModel:
    """A copy of the scene compiled for ``key``, compiled now if not kept.

    An unhashable key (parameters holding a list) is compiled every time.
    """
    try:
        model = _COMPILED.get(key)
    except TypeError:
        return compile_()
    if model is None:
        model = compile_()
        _COMPILED[key] = model
        while len(_COMPILED) > CACHE_SIZE:
            _COMPILED.popitem(last=False)
    else:
        _COMPILED.move_to_end(key)
    return copy.copy(model)


def clear_cache() -> None:
    """Forget the compiled scenes (the next :func:`load` of each compiles it)."""
    _COMPILED.clear()
