"""The stacked hand-over impact gives each run the scalar impact map's floats."""

import dataclasses

import numpy as np
import pytest

from wmr_mujoco.robots.omni3.runs import hybrid
from wmr_mujoco.robots.roller_wheels import omni_batch
from wmr_mujoco.robots.roller_wheels.omni_impact_batch import planar_impacts


def _impacts(model, seed: int, runs: int = 24):
    """Runs at random wheel angles, one to three wheels handing over to a neighbour."""
    rng = np.random.default_rng(seed)
    th = rng.uniform(-np.pi, np.pi, (runs, 3))
    old = omni_batch._lowest(model, th)
    new = old.copy()
    n = model.rollers.angles.size
    for b in range(runs):
        for i in rng.choice(3, rng.integers(1, 4), replace=False):
            new[b, i] = (new[b, i] + rng.choice([1, -1])) % n
    nu = rng.normal(size=(runs, 3)) * [0.3, 0.3, 1.0]
    nu[:3, 2] = 0.0  # no yaw rate: the overlap's damping force vanishes
    spins = rng.normal(size=(runs, 3)) * 30.0
    accels = rng.normal(size=(runs, 3)) * 5.0
    accels[:4] = 0.0  # the overlap's crossing time at the rate alone
    return nu, old, new, th, spins, accels


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("variant", ["omni3", "no accelerations", "massless rollers",
                                     "rigid contact"])
def test_each_run_gets_the_scalar_maps_floats(seed, variant):
    # Bit for bit (the speed-up may not move a judged number): every run's ν⁺ and ΔT
    # against HybridImpacts.planar_impact called on that run alone. Variants: omni3's
    # model (rollers with inertia, compliant contact), wheel accelerations not given,
    # massless rollers (the reduced constraint set), a rigid contact (no hand-over
    # dissipation or overlap).
    model = hybrid()
    if variant == "massless rollers":
        model = dataclasses.replace(model, roller_axial=0.0)
    elif variant == "rigid contact":
        model = dataclasses.replace(model, penetration=0.0)
    nu, old, new, th, spins, accels = _impacts(model, seed)
    if variant == "no accelerations":
        accels = None
    got_nu, got_lost = planar_impacts(model, nu, old, new, th, spins, accels)
    for b in range(len(nu)):
        want_nu, want_lost = model.planar_impact(
            nu[b], tuple(old[b]), tuple(new[b]), th[b], spins[b],
            None if accels is None else accels[b])
        assert got_nu[b].tobytes() == want_nu.tobytes()
        assert got_lost[b].tobytes() == np.float64(want_lost).tobytes()


def test_constraint_rows_and_roller_terms_are_the_scalar_ones():
    # The stacked constraint rows against HybridImpacts.constraint_rows, and R, x_c, ρ
    # against RollerGeometry's on one angle at a time, bit for bit over many angles (one
    # in a few hundred differs in the last bit where a square is a product, not pow).
    from wmr_mujoco.robots.roller_wheels.omni_impact_batch import (
        _constraint_rows,
        _roller_terms,
    )

    model = hybrid()
    rng = np.random.default_rng(7)
    th, modes = rng.uniform(-np.pi, np.pi, (1500, 3)), rng.integers(0, 12, (1500, 3))
    rows = _constraint_rows(model, modes, th)
    for b in range(len(th)):
        assert rows[b].tobytes() == model.constraint_rows(tuple(modes[b]), th[b]).tobytes()
    g, phi = model.rollers, rng.uniform(-0.6, 0.6, 3000)
    terms = np.stack(_roller_terms(model, phi), 1)
    want = np.array([[g.rolling_radius(p), g.contact_ahead(p), g.contact_radius(p)]
                     for p in phi.tolist()])
    assert terms.tobytes() == want.tobytes()


@pytest.mark.parametrize("seed", [0, 1])
def test_the_integrators_rows_give_the_same_floats(seed):
    # Bit for bit: H(σ) and k(σ) handed in by the integrator (its _geometry at the same
    # wheel angles) against those planar_impacts makes itself.
    model = hybrid()
    nu, old, new, th, spins, accels = _impacts(model, seed)
    g_old, g_new = omni_batch._geometry(model, th, old), omni_batch._geometry(model, th, new)
    got = planar_impacts(model, nu, old, new, th, spins, accels,
                         (g_old.H, g_new.H, g_old.ks, g_new.ks))
    ref = planar_impacts(model, nu, old, new, th, spins, accels)
    for a, b in zip(got, ref, strict=True):
        np.testing.assert_array_equal(a, b)
