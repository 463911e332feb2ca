"""A robot attached into a dm_control arena: it compiles and rolls as in its own scene."""

import mujoco
import numpy as np
import pytest
from dm_control import mjcf

import wmr_mujoco as wmr
from wmr_mujoco.lookup import attach
from wmr_mujoco.models.attach import attach_robot

#: Wheel-rate controls (rad/s) that drive each robot straight: omni3's wheels 2 and 3 in
#: opposite senses (wheel 1 across the motion), mecanum4's four alike, the disc's wheel
#: with its steering held.
CTRL = {"omni3": (0.0, 20.0, -20.0), "mecanum4": (10.0, 10.0, 10.0, 10.0),
        "disc": (10.0, 0.0)}
#: Simulated time, s.
DURATION = 0.5


def _arena() -> mjcf.RootElement:
    arena = mjcf.RootElement(model="arena")
    arena.worldbody.add("geom", name="ground", type="plane", size=(5, 5, 0.1))
    return arena


def _drive(model: mujoco.MjModel, ctrl_by_name: dict[str, float], base: str) -> np.ndarray:
    data = mujoco.MjData(model)
    for name, value in ctrl_by_name.items():
        data.ctrl[model.actuator(name).id] = value
    for _ in range(round(DURATION / model.opt.timestep)):
        mujoco.mj_step(model, data)
    return data.site_xpos[model.site(base).id].copy()


@pytest.mark.parametrize("robot", list(CTRL))
def test_an_attached_robot_rolls_on_the_arena_floor_as_in_its_own_scene(robot):
    """Same bodies, same contact parameters (the robot's geoms have contact priority;
    its scene's pairs are re-made against the arena's floor): the paths differ only by
    the solver's summation order, far under 0.1 mm after 0.5 s, while the robot rolls
    more than 0.2 m (1/2000 of it)."""
    arena = _arena()
    frame = attach(arena, robot)
    assert frame.freejoint is not None or robot == "disc"  # the disc rides on slides
    model = mujoco.MjModel.from_xml_string(arena.to_xml_string(), arena.get_assets())
    own = wmr.load(robot)
    names = [own.actuator(i).name for i in range(own.nu)]
    assert model.npair == own.npair  # mecanum4's and the disc's floor pairs came along
    end = _drive(model, {f"{robot}/{n}": c for n, c in zip(names, CTRL[robot], strict=True)},
                 f"{robot}/base")
    expected = _drive(own, dict(zip(names, CTRL[robot], strict=True)), "base")
    start = _drive(own, dict.fromkeys(names, 0.0), "base")
    assert np.linalg.norm(expected[:2] - start[:2]) > 0.2
    np.testing.assert_allclose(end, expected, atol=1e-4)


def test_the_plain_attach_fails_on_the_free_joint_which_is_why_attach_exists():
    arena = _arena()
    arena.attach(mjcf.from_path(str(wmr.get_spec("omni3").robot_path)))
    with pytest.raises(ValueError, match="free joint can only be used on top level"):
        mujoco.MjModel.from_xml_string(arena.to_xml_string(), arena.get_assets())


def test_without_its_scene_pairs_mecanum4_would_sink():
    """Attached without the pairs its scene adds, no roller touches the floor."""
    arena = _arena()
    attach_robot(arena, mjcf.from_path(str(wmr.get_spec("mecanum4").robot_path)))
    model = mujoco.MjModel.from_xml_string(arena.to_xml_string(), arena.get_assets())
    assert _drive(model, {}, "mecanum4/base")[2] < 0.0


def test_a_position_and_a_named_floor():
    arena = _arena()
    arena.worldbody.add("geom", name="ramp", type="plane", size=(1, 1, 0.1), pos=(9, 9, 0))
    with pytest.raises(ValueError, match=r"2 plane geoms .* name the floor: floor='...'"):
        attach(arena, "disc")
    with pytest.raises(ValueError, match="floor = 'nope': the arena has no geom"):
        attach(arena, "disc", floor="nope")
    attach(arena, "mecanum4", pos=(1.0, 2.0, 0.0), floor="ground")
    model = mujoco.MjModel.from_xml_string(arena.to_xml_string(), arena.get_assets())
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    np.testing.assert_allclose(data.site_xpos[model.site("mecanum4/base").id][:2], (1, 2),
                               atol=1e-9)


def test_the_composition_docs_example_runs():
    """docs/composition.md's example, executed as printed: the mecanum robot compiles in
    the arena at its position, with its wheel actuator found by its prefixed name."""
    import re
    from pathlib import Path

    doc = Path(__file__).resolve().parents[2] / "docs" / "composition.md"
    block = re.findall(r"```python\n(.*?)```", doc.read_text(), flags=re.DOTALL)[0]
    scope: dict[str, object] = {}
    exec(compile(block, str(doc), "exec"), scope)
    model, data = scope["model"], scope["data"]
    assert data.ctrl[model.actuator("mecanum4/wheel_fl").id] == 10.0
    mujoco.mj_forward(model, data)
    np.testing.assert_allclose(data.site_xpos[model.site("mecanum4/base").id][:2], (1, 0),
                               atol=1e-9)


def _attachable() -> list[str]:
    return [name for name, spec in wmr.ROBOTS.items() if spec.build is not None
            and spec.params_type is not None]


@pytest.mark.parametrize("robot", _attachable())
def test_an_attached_robot_keeps_its_scene_options(robot):
    """The floor pairs' impratio (10/d = 10⁴) is set by the robot's scene, not its file
    (10): attached, the arena must carry the scene's, or the pairs' friction rows are a
    thousand times softer. Every solver option equals the robot's own scene's."""
    arena = _arena()
    attach(arena, robot)
    model = mujoco.MjModel.from_xml_string(arena.to_xml_string(), arena.get_assets())
    own = wmr.load(robot)
    for name in ("timestep", "impratio", "integrator", "cone", "solver", "jacobian",
                 "iterations", "tolerance"):
        assert getattr(model.opt, name) == getattr(own.opt, name), name


def test_an_arena_option_at_odds_with_the_robot_scene_is_refused():
    arena = _arena()
    arena.option.impratio = 10.0
    with pytest.raises(ValueError, match=r"option impratio = 10000.*the arena 10\.0"):
        attach(arena, "diffdrive")


@pytest.mark.parametrize("robots", [("diffdrive", "diffdrive"), ("tricycle", "bicycle"),
                                    ("omni3", "diffdrive"), ("diffdrive", "omni3")])
def test_two_robots_with_the_same_scene_options_share_an_arena(robots):
    """Robots whose scenes set the same impratio attach side by side, in either order."""
    arena = _arena()
    for i, robot in enumerate(robots):
        attach(arena, robot, pos=(2.0 * i, 0.0, 0.0))
    model = mujoco.MjModel.from_xml_string(arena.to_xml_string(), arena.get_assets())
    assert model.opt.impratio == wmr.load(robots[0]).opt.impratio


def test_an_arena_that_sets_the_scene_value_itself_is_accepted():
    arena = _arena()
    arena.option.impratio = wmr.load("diffdrive").opt.impratio
    attach(arena, "diffdrive")
    model = mujoco.MjModel.from_xml_string(arena.to_xml_string(), arena.get_assets())
    assert model.opt.impratio == wmr.load("diffdrive").opt.impratio
