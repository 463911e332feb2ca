"""A registry entry checks itself: consistent scenarios, adapters, judges and files."""

import dataclasses
from pathlib import Path

import pytest

from wmr_mujoco.models.paths import MODELS_DIR
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.spec import DEFAULT_JUDGES
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import const

BASE = get_spec("disc")


@pytest.mark.parametrize(("change", "match"), [
    ({"demo_scenario": "nope"}, "demo scenario 'nope' is not one of its scenarios"),
    ({"render_scenario": "nope"}, "render scenario 'nope' is not one of its scenarios"),
    ({"scenarios": (Scenario("bicycle", "a", (const(1.0),)),)}, "scenarios of other robots"),
    ({"scenarios": (Scenario("disc", "a", (const(1.0), const(0.0))),) * 2,
      "demo_scenario": None, "bench_scenario": None, "render_scenario": None},
     "scenario names repeat"),
    ({"adapters": {}}, "has no kinematic adapter"),
    ({"build": None}, "give both build and params_type"),
    ({"build": None, "params_type": None}, "a foreign model needs its scene path"),
    ({"scenarios": (Scenario("disc", "t", (const(1.0),), kind="dynamic"),),
      "adapters": {ScenarioKind.DYNAMIC: lambda s, m, p: None}, "judges": {},
      "demo_scenario": None, "bench_scenario": None, "render_scenario": None},
     "has no judge for dynamic"),
])
def test_inconsistent_entries_are_refused(change, match):
    with pytest.raises(ValueError, match=match):
        dataclasses.replace(BASE, **change)


def test_paths_of_a_model_folder_and_of_a_foreign_scene(tmp_path):
    assert BASE.robot_path == MODELS_DIR / "disc" / BASE.robot_file
    assert BASE.scene_path == MODELS_DIR / "disc" / "scene.xml"
    assert BASE.has_files
    built = dataclasses.replace(BASE, folder=None)
    assert not built.has_files
    scene = Path(tmp_path / "peer.xml")
    foreign = dataclasses.replace(BASE, build=None, params_type=None, folder=None,
                                  scene=scene)
    assert foreign.robot_path == scene and foreign.scene_path == scene and foreign.has_files


def test_judges_fall_back_to_the_defaults():
    kinematic = tuple(s for s in BASE.scenarios if s.kind is ScenarioKind.KINEMATIC)
    bare = dataclasses.replace(BASE, judges={}, scenarios=kinematic, demo_scenario=None,
                               bench_scenario=None, render_scenario=None)
    assert bare.judge(ScenarioKind.KINEMATIC) is DEFAULT_JUDGES[ScenarioKind.KINEMATIC]
    assert bare.judge(ScenarioKind.DYNAMIC) is None


def test_scenario_lookup_lists_the_valid_names():
    first = BASE.scenarios[0]
    assert BASE.scenario(first.name) is first
    with pytest.raises(ValueError, match=f"no scenario 'nope' for 'disc'; valid scenarios: "
                                         f"'{first.name}'"):
        BASE.scenario("nope")


def test_clips_name_their_scenarios_and_files():
    from wmr_mujoco.robots import Clip

    assert BASE.clip_file(Clip()) == "disc.gif"
    assert BASE.clip_file(Clip(file="a.png")) == "a.png"
    with pytest.raises(ValueError, match="clip scenario 'nope' is not one of its scenarios"):
        dataclasses.replace(BASE, clips=(Clip("nope"),))
    with pytest.raises(ValueError, match=r"clip files repeat: \['disc.gif', 'disc.gif'\]"):
        dataclasses.replace(BASE, clips=(Clip(), Clip(BASE.scenarios[0].name)))


def test_open_targets_of_the_spec_reach_scenarios_appended_later():
    spec = get_spec("diffdrive")
    extra = Scenario("diffdrive", "appended", (const(0.1), const(0.0)), duration=1.0)
    opened = dataclasses.replace(spec, open_targets={"appended": {"worst position error": "x"}})
    appended = dataclasses.replace(opened, scenarios=(*opened.scenarios, extra))
    assert appended.scenario("appended").open_targets == {"worst position error": "x"}
    assert opened.scenario(spec.scenarios[0].name).open_targets == \
        spec.scenarios[0].open_targets
