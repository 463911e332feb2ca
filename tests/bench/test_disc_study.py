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
