"""Each pitfall planted in this package's diffdrive robot file, found and judged.

The clean robot follows its ideal kinematics to 0.2 % of path (1 s runs); each variant
changes one thing, so the counterfactual run is the clean robot again.
"""

from __future__ import annotations

import pytest

from wmr_mujoco.audit.core import audit
from wmr_mujoco.models.paths import MODELS_DIR

BASE = (MODELS_DIR / "diffdrive" / "diffdrive.xml").read_text()
#: Short runs: the figures are rates of error growth, visible within 1 s.
DURATION = 1.0


def _audit(write, old: str, new: str):
    assert old in BASE  # the variant really changes the file
    return audit(write(BASE.replace(old, new)), duration=DURATION, draws=1)


def _only(a, name):
    found = [d for d in a.diagnoses if d.name == name]
    assert len(found) == 1, [d.name for d in a.diagnoses]
    return found[0]


def test_clean_robot_has_no_diagnosis(write):
    a = audit(write(BASE), duration=DURATION, draws=1)
    assert a.scene.floor_added
    assert a.diagnoses == []


def test_gear_as_radius_is_confirmed_with_the_radius_ratio(write):
    # Gear 0.1 m on wheels of rolling radius 0.08 m (kv scaled by 1/g² to keep the joint
    # gain): commanded in ground speed, the robot moves at R/g = 0.8 of it, so its error
    # grows at 20 % of the path; ±2 points for servo lag and contact compliance.
    a = _audit(write, 'kv="10"', 'kv="1000" gear="0.1"')
    d = _only(a, "actuator radius")
    assert d.confirmed
    assert max(d.with_cause.values()) == pytest.approx(20.0, abs=2.0)
    assert max(d.without_cause.values()) < 1.0


def test_cylinder_wheels_are_confirmed(write):
    a = _audit(write, 'type="ellipsoid" size="0.08 0.015 0.08"',
               'type="cylinder" size="0.08 0.015" zaxis="0 1 0"')
    d = _only(a, "cylinder wheels")
    assert d.confirmed
    assert max(d.with_cause.values()) > max(d.without_cause.values())


def test_large_timestep_is_confirmed(write):
    # Contact time constant 5 ms (the robot's solref, twice its 2.5 ms step) under an 8 ms
    # step: MuJoCo softens the contacts to 16 ms; the counterfactual runs at t_c/2 = 2.5 ms.
    a = _audit(write, 'timestep="0.0025"', 'timestep="0.008"')
    d = _only(a, "timestep")
    assert d.confirmed
    assert "0.0025 s" in d.change


def test_a_cause_without_effect_is_not_confirmed(write):
    # Friction loss on the caster's ball joint: the ball slides instead of rolling and its
    # contact friction caps the drag, so the figures barely move: reported, not confirmed.
    a = _audit(write, 'type="ball"', 'type="ball" frictionloss="2"')
    d = _only(a, "ball friction")
    assert "frictionloss 2" in d.cause
    assert d.confirmed is False
    assert "not confirmed" in d.line()
