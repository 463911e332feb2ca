"""The registry: every robot's entry, and a throw-away robot that no generic module knows.

The throw-away robot is the disc with a wider wheel under a new name, built from its
parameters (no model files), with its own scenario and targets. It goes through the same
runner, report and renderer as the registered robots.
"""

import dataclasses
import json

import numpy as np
import pytest

from wmr_mujoco.models.params import WheelParams, params_or_default
from wmr_mujoco.robots import ROBOTS, RobotSpec, disc, get_spec, register, registered
from wmr_mujoco.robots.disc import builder as disc_builder
from wmr_mujoco.robots.disc.params import DiscParams
from wmr_mujoco.validation.metrics import Metric, Series
from wmr_mujoco.validation.runner import jobs, run_all
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario, ScenarioKind
from wmr_mujoco.validation.signals import const

NAME = "wide_disc"


def test_every_robot_has_files_and_description():
    for spec in ROBOTS.values():
        assert spec.robot_path.is_file(), spec.robot_path
        assert spec.scene_path.is_file(), spec.scene_path
        assert len(spec.description) > 20


def test_unknown_robot_lists_valid_names():
    with pytest.raises(ValueError, match="unknown robot 'unicycle'.*disc, disc_free, bicycle"):
        get_spec("unicycle")


def test_every_target_says_requirement_or_derived_bound():
    for spec in ROBOTS.values():
        for key, target in spec.targets.items():
            assert target.kind in ("requirement", "derived bound", "open"), key
            assert len(target.basis) > 10, key


def test_each_robot_owns_its_parameters_and_builder():
    # A robot is a folder: its parameter dataclass and its builder live under
    # wmr_mujoco.robots (its own folder or its family's), never in a generic layer.
    for name, spec in ROBOTS.items():
        for part in (spec.params_type, spec.build):
            if part is not None:
                assert part.__module__.startswith("wmr_mujoco.robots."), (name, part)
        assert type(get_spec(name)).__module__ == RobotSpec.__module__


@dataclasses.dataclass(frozen=True)
class WideDiscParams(DiscParams):
    """The disc's parameters with a wider, larger wheel by default."""

    wheel: WheelParams = dataclasses.field(
        default_factory=lambda: WheelParams(radius=0.2, width=0.04, mass=2.0))


def _measure(scenario, params):
    """A measurement scenario: the wheel's axial inertia against m R²/2 (closed form)."""
    p = params_or_default(params, WideDiscParams)
    expected = 0.5 * p.wheel.mass * p.wheel.radius ** 2
    return MeasurementResult([Metric("axial inertia / (m R²/2)",
                                     p.wheel.axial_inertia / expected, "ratio")],
                             [Series("R", np.array([0.0, 1.0]), np.array([0.0, 1.0]))])


def wide_disc_spec() -> RobotSpec:
    """A disc variant with its own defaults, scenario and targets."""
    scenarios = (Scenario(NAME, "gentle arc", (const(0.8, 0.5), const(0.2)), duration=1.5),
                 Scenario(NAME, "inertia", kind=ScenarioKind.MEASUREMENT, evaluate=_measure))
    return RobotSpec(
        name=NAME, description="a wider disc, registered by a test only",
        params_type=WideDiscParams, build=disc_builder.build,
        adapters={ScenarioKind.KINEMATIC: lambda s, m, p: disc.DiscKinematics(
            params_or_default(p, WideDiscParams))},
        targets=disc.TARGETS, scenarios=scenarios, demo_scenario="gentle arc")


def test_a_new_robot_runs_through_validate_report_and_render(tmp_path):
    from wmr_mujoco.render.video import render_scenario
    from wmr_mujoco.validation.report import write_report

    spec = wide_disc_spec()
    with registered(spec):
        assert NAME in ROBOTS
        results = run_all(jobs([spec]))
        path = write_report(results, tmp_path, robots=ROBOTS)
        frames = render_scenario(dataclasses.replace(spec.scenarios[0], duration=0.3),
                                 width=64, height=48, fps=10)
    assert NAME not in ROBOTS
    arc, inertia = results
    assert arc.error is None and arc.passed, arc.rows
    worst = next(r for r in arc.rows
                 if r.metric == "worst position error" and r.unit == "% of path")
    assert worst.target == 0.5 and worst.basis.startswith("requirement")
    # The wider wheel (R = 0.2 m) is what was simulated: 0.8 m/s for 1.5 s after a
    # 0.5 s ramp is 1.0 m of path whatever the radius, and the wheel turned v/R; less
    # 0.8 Δt/2, as each step holds the input read at its start (the ramp lags by Δt/2),
    # and less what the (equally lagging) ramp covers before the first trace sample t₁,
    # from which the path is summed: (0.8/0.5) (t₁ − Δt/2)²/2. Tolerance 1e-5 of the path:
    # the arc's chords between samples (yaw rate 0.2 rad/s) and round-off.
    dt = spec.params_type().sim.timestep
    arc_times = next(r for r in results if r is arc).trace.arrays()["time"]
    t1 = float(arc_times[0])
    path_m = next(r.value for r in arc.rows if r.metric == "path length")
    expected = 0.8 * 1.5 - 0.8 * 0.5 / 2 - 0.8 * dt / 2 - 0.8 / 0.5 * (t1 - dt / 2) ** 2 / 2
    assert path_m == pytest.approx(expected, rel=1e-5)
    assert inertia.rows[0].value == pytest.approx(1.0, rel=1e-12)
    assert f"{NAME}/gentle arc" in path.read_text()
    doc = json.loads((tmp_path / "validation.json").read_text())
    assert [s["robot"] for s in doc["scenarios"]] == [NAME, NAME]
    assert (tmp_path / "validation" / NAME / "inertia.png").stat().st_size > 1000
    assert frames.shape == (3, 48, 64, 3) and frames.std() > 0


def test_a_name_cannot_be_registered_twice():
    with pytest.raises(ValueError, match="robot 'disc' is already registered"):
        register(get_spec("disc"))


def test_every_declared_open_target_names_a_scenario_and_a_judged_metric_target():
    """A robot's ``open_targets`` names one of its scenarios (appended ones included), and
    that scenario then carries the reasons (so the runner shows the metric open)."""
    for spec in ROBOTS.values():
        names = {s.name: s for s in spec.scenarios}
        for scenario, reasons in spec.open_targets.items():
            assert scenario in names, f"{spec.name}: open target of unknown {scenario!r}"
            assert set(reasons) <= set(names[scenario].open_targets)
            assert all(r for r in reasons.values()), "every open target gives its reason"
