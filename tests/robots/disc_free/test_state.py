"""The free disc's state in MuJoCo against the analytic disc's, both ways."""

import math

import mujoco
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots.disc.params import DiscParams
from wmr_mujoco.robots.disc_free.state import (
    FreeRun,
    disc_from_model,
    free_pose,
    set_free_state,
)


@pytest.fixture(scope="module")
def free():
    return load("disc_free")


def test_disc_constants_come_from_the_model(free):
    d = disc_from_model(free)
    p = DiscParams().wheel
    assert (d.radius, d.mass) == (p.radius, p.mass)
    # Thin-disc formulas, independently: C = m R²/2, A = m R²/4 + m w²/12.
    assert d.axial_inertia == pytest.approx(p.mass * p.radius**2 / 2)
    assert d.diametral_inertia == pytest.approx(p.mass * (p.radius**2 / 4 + p.width**2 / 12))


def test_set_free_state_puts_the_analytic_state_into_mujoco(free):
    disc = disc_from_model(free)
    state = disc.steady_motion(0.3, 0.6).state
    data = mujoco.MjData(free)
    set_free_state(free, data, disc, state)
    pose = free_pose(free, data, disc.radius)
    # The ellipsoid's rim b moves the contact by b² sin θ / a ≈ 0.008 mm from the thin
    # disc's: 1 mm is far above it and far below the judged path errors.
    assert pose[:2] == pytest.approx([0, 0], abs=1e-3)
    assert pose[3] == pytest.approx(0.3, abs=1e-12)
    assert pose[4:7] == pytest.approx(state[5:8], abs=1e-12)
    # Energy read back against the analytic energy of the same state: the ellipsoid's
    # centre stands higher than the thin disc's a cos θ by √(a² cos² θ + b² sin² θ) −
    # a cos θ (about 1.2 µm), i.e. m g times that more potential energy.
    a, b = free.geom("disc_collision").size[:2]
    lift = math.hypot(a * math.cos(0.3), b * math.sin(0.3)) - a * math.cos(0.3)
    assert pose[7] - disc.energy(state) == pytest.approx(disc.mass * disc.gravity * lift,
                                                         rel=1e-3)
    mujoco.mj_step(free, data, nstep=2)
    assert data.ncon == 1  # placed at zero gap: one point contact


def test_run_stops_where_asked(free):
    disc = disc_from_model(free)
    run = FreeRun(free, disc.initial_state(0.0, 0.5, lean_rate=0.5), 2.0,
                  stop=lambda row: abs(row[4]) > 0.05)
    rows = run.rows()
    assert abs(rows[-1, 4]) > 0.05 >= abs(rows[-2, 4])
    assert rows[-1, 0] < 2.0
