"""Audits on robots nobody here wrote (read in place from shared/anchors) and on ours."""

from __future__ import annotations

import pytest

from wmr_mujoco.audit.core import audit, judged
from wmr_mujoco.models.paths import MODELS_DIR

from .conftest import anchor


@pytest.fixture(scope="module")
def soccer():
    return audit(anchor("robot_soccer_kit"), duration=1.5, draws=1)


def test_soccer_kit_is_holonomic_and_off_its_kinematics(soccer):
    assert soccer.robot_class == (3, 0)
    assert [o.manoeuvre.name for o in soccer.outcomes] == ["straight", "arc", "spin",
                                                            "strafe", "diagonal"]
    # Published (shared/anchors NOTE): 46-62 % of path off as shipped; translations only.
    worst = max(o.figures.position_pct for o in soccer.outcomes
                if o.figures.position_pct is not None)
    assert worst > 30.0


def test_soccer_kit_roller_friction_is_named_with_both_figures(soccer):
    roller = [d for d in soccer.diagnoses if d.name == "roller friction"]
    assert len(roller) == 1
    d = roller[0]
    assert d.confirmed
    assert "frictionloss 0.1" in d.cause and "armature 0.005" in d.cause
    # Published: 3.2-4.9 % once the rollers' friction and armature are 0 (4 s runs); the
    # 1.5 s runs here carry the ramp's lag too, so allow up to 10 %.
    assert max(d.without_cause.values()) < 10.0
    assert max(d.with_cause.values()) > 30.0
    assert "without it" in d.line()


def test_diffdrive_of_this_package_follows_its_kinematics():
    a = audit(MODELS_DIR / "diffdrive" / "scene.xml", duration=1.0, diagnose=False, draws=1)
    assert a.robot_class == (2, 0)
    assert not a.drive.imposed
    # wmr validate's diffdrive target is a few % of path; the audit's verdict "follows"
    # means <= 5 % of path and 5° on every manoeuvre.
    assert all(o.verdict == "follows the ideal model" for o in a.outcomes), \
        [(o.manoeuvre.name, o.figures.error_label()) for o in a.outcomes]


def test_each_figure_is_the_worst_of_its_seeded_draws():
    scene = MODELS_DIR / "diffdrive" / "scene.xml"
    one = audit(scene, duration=1.0, diagnose=False, draws=1)
    three = audit(scene, duration=1.0, diagnose=False, draws=3, seed=7)
    assert three.draws[0].speed == 1.0 and len(three.draws) == 3
    again = audit(scene, duration=1.0, diagnose=False, draws=3, seed=7)
    for o1, o3, oa in zip(one.outcomes, three.outcomes, again.outcomes, strict=True):
        # Draw 0 is the single nominal run, so the worst of three is at least as large in
        # the judged figure that picks the worst (the other figures are that draw's own).
        assert judged(o3.figures, three.span) >= judged(o1.figures, one.span) - 1e-12
        # Seeded: the same draws give the same figures (all but the wall-clock one).
        same, other = o3.figures.as_dict(), oa.figures.as_dict()
        same.pop("real_time_factor")
        other.pop("real_time_factor")
        assert same == other


def test_andino_caster_without_swivel_is_confirmed():
    a = audit(anchor("andino"), duration=1.5, draws=1)
    assert a.robot_class == (2, 0) and not a.drive.imposed
    d = next(d for d in a.diagnoses if d.name == "caster without swivel")
    assert d.confirmed
    assert max(d.with_cause.values()) > max(d.without_cause.values())


def test_mujoco_car_gets_imposed_servos_and_its_skid_is_a_ball_caster():
    a = audit(anchor("mujoco_car"), duration=1.0, diagnose=False, draws=1)
    assert a.robot_class == (2, 0)
    # Its actuators are motors on tendons: the audit removes them and, under the car's
    # Euler integrator, tracks the integrated wheel angle with position servos.
    assert a.drive.imposed and "position servos" in a.drive.statement
    assert "removed: forward, turn" in a.drive.statement
    assert any("ideal ball caster" in n for n in a.wheels.notes)
