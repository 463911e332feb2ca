"""The omni trials through the validation runner: omni3 against ideal omni kinematics.

Targets (omni3's registry entry, issue 3): worst position error over the run ≤ 1 % of
path, worst heading error ≤ 1°, median roller-rate error ≤ 5 %; a pure rotation keeps the
centre within 1 % of the wheel distance. Each trial starts settled, reached by a 0.5 s
ramp that keeps traction below μN.

The translations, the rotation and translate+rotate are omni3's registered scenarios,
judged over their whole 5 s by ``wmr validate`` (``make demo``). Here four trials, one of
each kind and the diagonal+rotate trial that only the studies run, shortened to
:data:`SHORT_S`: the targets are worst-over-the-run bounds, so a shorter run is held to
the same ones.
"""

import dataclasses

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels.trials import peer_spec, run_trial, standard_trials

#: Seconds each trial runs here: the ramp, then 1.5 s at speed (the roller-rate probe
#: starts after 1 s).
SHORT_S = 2.0
TRIALS = [dataclasses.replace(t, duration=SHORT_S) for t in standard_trials("omni3")
          if t.name in ("translate   0°", "translate  45°", "rotate", "diagonal+rotate")]


@pytest.fixture(scope="module")
def runs():
    from wmr_mujoco.robots import get_spec

    return {t.name: run_trial(get_spec("omni3"), t) for t in TRIALS}


@pytest.mark.parametrize("name", [t.name for t in TRIALS])
def test_tracks_ideal_kinematics(runs, name):
    run = runs[name]
    assert run.result.error is None, run.result.error
    judged = [r for r in run.result.rows if r.passed is not None]
    assert {r.metric for r in judged} >= {"worst heading error"}
    assert all(r.passed for r in judged), judged
    assert run.real_time_factor > 0


def test_rollers_turn_at_the_kinematic_rate(runs):
    errors = [run.value("roller rate error (median)", "%") for run in runs.values()]
    measured = [e for e in errors if np.isfinite(e)]
    assert len(measured) >= 3  # every trial with sideways slide measured rollers
    assert max(measured) <= 5.0


def _peer_stand_in(folder):
    """A small stand-in for the peer's scene (the peer is not copied here): omni3's scene
    with the peer's wheel joint names and, like the peer, one angle servo per wheel."""
    import mujoco

    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.robots.roller_wheels.trials import PEER_WHEELS

    spec = mujoco.MjSpec.from_file(str(get_spec("omni3").scene_path))
    for element in [*spec.actuators, *spec.sensors]:
        spec.delete(element)
    for i, name in enumerate(PEER_WHEELS, 1):
        spec.joint(f"wheel{i}").name = name
        spec.add_actuator(name=name, target=name,
                          trntype=mujoco.mjtTrn.mjTRN_JOINT).set_to_position(kp=2.0)
    scene = folder / "scene.xml"
    scene.write_text(spec.to_xml())
    return scene


def test_peer_runs_through_the_same_runner(tmp_path):
    """The peer's angle servos get the integrated wheel angles; its layout is read from
    its model. Only that it runs and is measured is asserted: its figures are the study's.
    It runs on a stand-in scene with the peer's joint names and servo kind (always here)."""
    from wmr_mujoco.validation.runner import make_adapter

    spec = peer_spec(_peer_stand_in(tmp_path))
    trial = dataclasses.replace(spec.scenarios[0], duration=1.0)
    import mujoco

    adapter = make_adapter(spec, trial, mujoco.MjModel.from_xml_path(str(spec.scene_path)))
    assert all(adapter.info.angle_servo)  # read from the model: position servos
    run = run_trial(spec, trial)
    assert run.result.error is None, run.result.error
    assert np.isfinite(run.value("worst position error", "% of path"))
    assert any(run.result.trace.state_names[3:])  # the wheel angles are part of the state


def _menagerie_stub(scene):
    """A stand-in for the mujoco-menagerie package (offline): ``get(name)`` gives a robot
    whose ``path(entry)`` is the scene file (None: the package knows no such robot)."""
    import types

    class Robot:
        default_scene = "scene"

        def path(self, entry):
            assert entry == "scene"
            return scene

    def get(name):
        if scene is None:
            raise KeyError(name)
        assert name == "robot_soccer_kit"
        return Robot()

    return types.SimpleNamespace(get=get)


def _importer(module):
    def importer(name):
        assert name == "mujoco_menagerie"
        if module is None:
            raise ImportError(name)
        return module
    return importer


def test_peer_through_the_package_spec_when_its_handle_has_no_path(tmp_path):
    """The documented route: ``spec(entry)`` (a MjSpec) and the file in its folder."""
    import types

    from wmr_mujoco.robots.roller_wheels.trials import find_peer

    scene = tmp_path / "robot_soccer_kit" / "scene.xml"
    scene.parent.mkdir()
    scene.write_text("<mujoco/>")
    robot = types.SimpleNamespace(
        default_scene="scene",
        spec=lambda entry: types.SimpleNamespace(modelfiledir=str(scene.parent) + "/"))
    module = types.SimpleNamespace(get=lambda name: robot)
    found = find_peer({}, _importer(module), tmp_path / "none.xml")
    assert found.scene == scene and "mujoco-menagerie" in found.source


def test_peer_order_package_then_variable_then_sibling(tmp_path):
    from wmr_mujoco.robots.roller_wheels.trials import find_peer

    files = {}
    for name in ("package", "variable", "sibling"):
        files[name] = tmp_path / name / "scene.xml"
        files[name].parent.mkdir()
        files[name].write_text("<mujoco/>")
    env = {"WMR_PEER_SCENE": str(files["variable"])}
    found = find_peer(env, _importer(_menagerie_stub(files["package"])), files["sibling"])
    assert found.scene == files["package"] and "mujoco-menagerie" in found.source
    # Installed, but it cannot give the model (offline, say): the variable is next.
    found = find_peer(env, _importer(_menagerie_stub(None)), files["sibling"])
    assert found.scene == files["variable"] and found.source == "WMR_PEER_SCENE"
    found = find_peer(env, _importer(None), files["sibling"])
    assert found.source == "WMR_PEER_SCENE"
    found = find_peer({}, _importer(None), files["sibling"])
    assert found.scene == files["sibling"] and "beside the checkout" in found.source
    assert find_peer({}, _importer(None), tmp_path / "none.xml") is None
