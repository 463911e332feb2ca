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
                  stop_lean=0.05)
    rows = run.rows()
    assert abs(rows[-1, 4]) > 0.05 >= abs(rows[-2, 4])
    assert rows[-1, 0] < 2.0


def test_cross_gives_numpys_floats():
    # _cross replaces np.cross in the per-step readout: the same two products and one
    # difference per entry, so the same floats bit for bit (signed zeros included).
    import numpy as np

    from wmr_mujoco.robots.disc_free.state import _cross

    rng = np.random.default_rng(3)
    for _ in range(2000):
        a = rng.normal(size=3) * 10.0 ** rng.integers(-6, 6)
        b = rng.normal(size=3) if rng.random() < 0.8 else np.array([0.0, 0.0, 1.0])
        a[rng.integers(3)] *= rng.choice([0.0, -0.0, 1.0])
        assert _cross(a.tolist(), b.tolist()).tobytes() == np.cross(a, b).tobytes()


def test_free_pose_reads_the_tilted_frame_as_numpy_did(free):
    # The readout's floats against the same formulas written with np.cross and np.clip
    # (what free_pose computed before): a speed-up may not move a judged number.
    import numpy as np

    data = mujoco.MjData(free)
    disc = disc_from_model(free)
    set_free_state(free, data, disc, np.array([0.1, -0.2, 0.7, 0.3, 0.0, 1.5, -8.0, 0.4]))
    for _ in range(200):
        mujoco.mj_step(free, data)
        b = free.body("disc").id
        rot = data.xmat[b].reshape(3, 3)
        e2 = rot[:, 1]
        th = math.asin(float(np.clip(e2[2], -1.0, 1.0)))
        e1 = np.cross(e2, [0.0, 0.0, 1.0])
        e1 /= np.linalg.norm(e1)
        e3 = np.cross(e1, e2)
        p = data.xpos[b] - disc.radius * e3
        w = rot @ data.qvel[3:6]
        got = free_pose(free, data, disc.radius)
        want = [p[0], p[1], math.atan2(e1[1], e1[0]), th, w @ e1, w @ e2, w @ e3]
        assert got[:7].tobytes() == np.array(want).tobytes()


def test_a_runs_rows_are_free_pose_bit_for_bit(free):
    # FreeRun reads each step through a readout with the model's constants taken once:
    # every row (energy included) must be free_pose's floats at that step, time in front.
    import numpy as np

    disc = disc_from_model(free)
    run = FreeRun(free, disc.initial_state(0.2, 0.8, lean_rate=0.3), 0.3)
    n = 0
    for data, row in run.steps():
        want = np.concatenate([[data.time], free_pose(free, data, disc.radius)])
        assert row.tobytes() == want.tobytes()
        n += 1
    assert n == round(0.3 / free.opt.timestep) + 1


@pytest.mark.parametrize("state", ["leaning", "steady", "stopped"])
def test_rows_read_at_once_are_the_steps_rows(free, state):
    # FreeRun.rows reads all steps at once (stacked products): bit for bit the rows its
    # steps give one by one (a leaning start, a steady circling, a run that stops when
    # its lean passes 0.05 rad: the same last row).
    import numpy as np

    disc = disc_from_model(free)
    start = (disc.initial_state(0.15, 1.0) if state == "leaning"
             else disc.steady_motion(0.3, 0.6).state)
    if state == "stopped":
        start = disc.initial_state(0.0, 0.5, lean_rate=0.5)
    run = FreeRun(free, start, 0.5, stop_lean=0.05 if state == "stopped" else None)
    at_once = run.rows()
    one_by_one = np.array([row for _, row in run.steps()])
    assert at_once.shape == one_by_one.shape
    assert at_once.tobytes() == one_by_one.tobytes()


@pytest.mark.parametrize("bad", [0.0, -0.1, float("nan"), float("inf"), "0.1"])
def test_a_bad_stop_lean_is_refused(free, bad):
    disc = disc_from_model(free)
    with pytest.raises(ValueError, match="stop_lean"):
        FreeRun(free, disc.initial_state(0.0, 0.5), 1.0, stop_lean=bad)
