"""Why the caster robots diverged on MuJoCo Warp: both caster settings, measured."""

import pytest

from wmr_mujoco.bench import caster_conditioning as cc
from wmr_mujoco.models.builders.common import SLIDING_GRIP


def test_only_robots_with_a_caster_pair_have_variants():
    assert set(cc.variants("diffdrive")) == {"paired (default)", "contact bits"}
    assert cc.variants("tricycle") == {}  # no ball caster
    bits = cc.variants("diffdrive")["contact bits"]
    assert bits.npair == 2  # the wheels keep theirs; the caster's alone is removed


def test_the_caster_pair_brings_impratio_d_to_the_grip_and_the_conditioning_down():
    paired, bits = (cc.measure("diffdrive", setting, model, warp=False)
                    for setting, model in cc.variants("diffdrive").items())
    # Every paired floor contact has impratio·d = SLIDING_GRIP (sliding_impratio).
    assert paired.impratio_d == pytest.approx(SLIDING_GRIP)
    # On contact bits the caster keeps the collision class's d ≈ 0.95 (CONTACT_SOLIMP's
    # d0 0.95 at zero depth, up to 0.99 deep) under the pairs' impratio 1e4.
    assert 0.95e4 * 0.99 < bits.impratio_d < 0.99e4
    # D_f ∝ impratio·d/(1 − d): paired, the caster's friction rows are as stiff as the
    # wheels' within their different inverse inertias (a factor of a few); on bits about
    # (9500/0.05)/(10/0.999) ≈ 1.9e4 times the paired caster's.
    assert 0.2 < paired.stiffness_ratio < 5
    assert bits.stiffness_ratio > 1e3 * paired.stiffness_ratio
    # The stiff rows raise Newton's Hessian's condition by about as much.
    assert bits.condition > 1e3 * paired.condition
    assert (paired.warp, bits.warp) == ("not run", "not run")


def test_docs_hold_the_markers():
    from wmr_mujoco.docs_sync.markers import has_markers

    assert has_markers(cc.DOC, cc.MARKER)
