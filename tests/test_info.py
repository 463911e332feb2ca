"""``wmr info``: the Campion class line, a foreign scene file described by path, and only
the parameters a robot's model uses."""

import dataclasses
import functools

import pytest

from wmr_mujoco.info import describe, describe_file, used_params
from wmr_mujoco.lookup import build_scene
from wmr_mujoco.models.builders import common
from wmr_mujoco.robots import ROBOTS, get_spec

DECLARED = [(name, field) for name, spec in ROBOTS.items() if spec.params_type is not None
            for field in getattr(spec.params_type, "UNUSED", ())]
SHOWN = [(name, field) for name, spec in ROBOTS.items() if spec.params_type is not None
         for field in used_params(spec.params_type())]

#: A valid other value of each text field (numbers are scaled instead).
_OTHER_TEXT = {"RK4": "Euler", "implicit": "RK4", "ellipsoid": "sphere",
               "left": "differential", "Newton": "PGS", "CG": "Newton", "sparse": "dense",
               "auto": "dense",
               "elliptic": "pyramidal"}


def _changed(value):
    """A nearby valid value: numbers by -10 % (a zero by 1e-4), a bool flipped, text swapped."""
    if isinstance(value, bool):
        return not value
    if isinstance(value, int):
        return value + 1
    if isinstance(value, float):
        return 0.9 * value if value else 1e-4
    if isinstance(value, tuple):
        return tuple(0.9 * v for v in value)
    return _OTHER_TEXT[value]


def _with(params, dotted):
    """``params`` with one (possibly nested) field changed by :func:`_changed`."""
    head, _, rest = dotted.partition(".")
    value = getattr(params, head)
    new = _with(value, rest) if rest else _changed(value)
    return dataclasses.replace(params, **{head: new})


def test_omni3_has_no_steering_parameters_to_show():
    shown = used_params(ROBOTS["omni3"].params_type())
    assert "drive.wheel_kv" in shown and not [k for k in shown if "steer" in k]


def _scene_xml(robot, params):
    """The robot in its scene (the scene may carry robot elements, e.g. contact pairs)."""
    return common.to_xml(build_scene(robot, params))


@functools.cache
def _default_xml(robot):
    return _scene_xml(robot, ROBOTS[robot].params_type())


@pytest.mark.parametrize("robot, field", DECLARED)
def test_a_field_declared_unused_leaves_the_model_unchanged(robot, field):
    """Independent of the declaration: build the model with the field changed."""
    spec = ROBOTS[robot]
    changed = _with(spec.params_type(), field)
    assert _scene_xml(robot, changed) == _default_xml(robot)


@pytest.mark.parametrize("robot, field", SHOWN)
def test_every_field_info_shows_changes_the_model(robot, field):
    """The converse: ``wmr info`` and the model READMEs show no parameter the model ignores.

    A field whose change leaves the compiled model as it is must be declared ``UNUSED``.
    """
    spec = ROBOTS[robot]
    changed = _with(spec.params_type(), field)
    assert _scene_xml(robot, changed) != _default_xml(robot), (
        f"{robot}: {field} does not change the model; declare it UNUSED")


@pytest.mark.parametrize("robot", list(ROBOTS))
def test_info_lists_exactly_the_used_parameters(robot):
    """``wmr info ROBOT`` prints one line per used parameter and none of the unused."""
    spec = ROBOTS[robot]
    text = describe(robot).splitlines()
    start = text.index("parameters (SI units, radians):") + 1
    end = next(i for i, line in enumerate(text) if line.startswith("total mass:"))
    names = [line.split()[0] for line in text[start:end]]
    assert names == list(used_params(spec.params_type()))
    assert not set(names) & set(getattr(spec.params_type, "UNUSED", ()))
    assert "torque [0, 0]" not in "\n".join(text)  # an unlimited motor is said so


def test_a_used_field_does_change_the_model():
    """The check above can fail: a steering gain the tricycle uses changes its model."""
    spec = ROBOTS["tricycle"]
    default = spec.params_type()
    changed = _with(default, "drive.steer_kp")
    assert common.to_xml(spec.build(changed)) != common.to_xml(spec.build(default))


def test_info_shows_the_computed_class():
    assert ("Campion class: wheels: 2 steerable, 1 ball; δm = 1, δs = 2, δM = 3; class (1,2)"
            in describe("double_steer"))


def test_info_says_why_a_model_has_no_class():
    assert "Campion class: none (no wheels" in describe("disc_free")


def test_info_on_a_scene_file_reads_it_and_leaves_the_registry_alone():
    before = list(ROBOTS)
    text = describe_file(get_spec("diffdrive").scene_path)
    assert "class (2,0)" in text and "parameters: none" in text
    assert list(ROBOTS) == before


def test_info_on_a_registered_robots_own_file_does_not_clash():
    """``wmr info models/omni3/omni3.xml``: the file's stem is a registered robot's name."""
    before = list(ROBOTS)
    text = describe_file(get_spec("omni3").scene_path.parent / "omni3.xml")
    assert text.startswith("omni3 (file omni3.xml): model file omni3.xml")
    assert "parameters: none" in text and "wheel1" in text
    assert list(ROBOTS) == before


def test_info_on_a_missing_file_is_a_clear_error(tmp_path):
    with pytest.raises(ValueError, match="not found"):
        describe_file(tmp_path / "none.xml")


@pytest.mark.parametrize("robot", list(ROBOTS))
def test_total_mass_is_the_compiled_models_mass(robot):
    """The parameters' ``total_mass`` (shown in the README tables) is what MuJoCo weighs;
    float sums of a few masses agree to 1e-12 kg."""
    import mujoco

    spec = ROBOTS[robot]
    model = mujoco.MjModel.from_xml_string(_default_xml(robot))
    assert spec.params_type().total_mass == pytest.approx(model.body_mass[1:].sum(), abs=1e-12)
