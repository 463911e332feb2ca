"""The disc study's choice and settings (the study itself runs by ``make study``)."""

import math

import mujoco
import pytest

from wmr_mujoco.bench import disc_study as ds
from wmr_mujoco.robots.disc.params import DiscParams


def row(label, evals, err, passed=True):
    r = {h: err for h, _, _, _ in ds.COLUMNS}
    r.update({f"{h} target": 1.0 for h, _, _, _ in ds.COLUMNS})
    r.update(label=label, evals=evals, rtf=100.0, passed=passed)
    return r


def test_cheapest_passing_prefers_fewer_evaluations_then_margin():
    rows = [row("a", 2000, 0.1), row("b", 500, 0.1, passed=False), row("c", 1000, 0.4),
            row("d", 1000, 0.2)]
    assert ds.cheapest_passing(rows) == 3
    assert ds.cheapest_passing([row("x", 1, 9, passed=False)]) is None
    assert "**d** (chosen)" in ds.table(rows)


def test_setting_compiles_what_it_names():
    m = ds.Setting("t", "implicit", 0.001, 0.003, noslip=4, impratio=2.0,
                   collider="cylinder").model()
    assert m.opt.integrator == mujoco.mjtIntegrator.mjINT_IMPLICIT
    assert (m.opt.timestep, m.opt.noslip_iterations, m.opt.impratio) == (0.001, 4, 2.0)
    g = m.geom("disc_collision")
    assert g.type[0] == mujoco.mjtGeom.mjGEOM_CYLINDER
    assert g.size[:2] == pytest.approx([0.15, 0.003])


def test_default_free_disc_is_a_row_of_the_study():
    p = DiscParams()
    assert any((s.integrator, s.timestep, s.rim) == (p.free_integrator, p.free_timestep,
                                                      p.free_rim) and s.noslip == 0
               for s in ds.SETTINGS)


def test_a_row_reads_every_judged_column():
    """One setting through every measurement: the columns are the measurements' own
    judged metrics (a renamed metric would leave a NaN)."""
    r = ds.evaluate(ds.Setting("default"))
    assert all(math.isfinite(float(r[h])) for h, _, _, _ in ds.COLUMNS)
    assert r["passed"] is True and r["rtf"] > 0


def test_a_setting_is_the_shipped_free_disc_but_its_label():
    """A setting changes only what it names: with nothing named it is the free disc users
    get, step for step (bit for bit: the same compiled numbers). Rows such as "RK4 2 ms"
    then run at the shipped contact time constant, not at one of the study's own."""
    import numpy as np

    from wmr_mujoco.models.loading import load
    from wmr_mujoco.robots import disc_free
    from wmr_mujoco.robots.disc_free import measurements as ms
    from wmr_mujoco.robots.disc_free.state import FreeRun

    shipped = load(disc_free.SPEC)
    ours = ds.Setting("defaults").model()
    disc = FreeRun(shipped, np.zeros(8), 0.2).disc
    state = disc.initial_state(*ms.LEANING_START)
    np.testing.assert_array_equal(FreeRun(shipped, state, 0.2).rows(),
                                  FreeRun(ours, state, 0.2).rows())
    # The run alone cannot see the contact's time constant below 2 Δt (MuJoCo's refsafe
    # clamps it at run time); the compiled numbers can.
    for field in ("geom_solref", "geom_solimp", "geom_size", "geom_friction"):
        np.testing.assert_array_equal(getattr(ours, field), getattr(shipped, field))
    assert (ours.opt.timestep, ours.opt.impratio, ours.opt.integrator) == (
        shipped.opt.timestep, shipped.opt.impratio, shipped.opt.integrator)
    # The previous default's row keeps the time constant it ran at, which its label names.
    previous = next(s for s in ds.SETTINGS if "previous default" in s.label)
    assert "t_c 4 ms" in previous.label and previous.contact_timeconst == 0.004
