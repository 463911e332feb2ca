"""MuJoCo's timers and solver counts of a drive."""

from __future__ import annotations

import pytest

from wmr_mujoco.bench import solver_profile
from wmr_mujoco.bench.default_speed import prepare_timed
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.omni3.params import OmniParams


@pytest.mark.parametrize(("cone", "rows"), [("elliptic", 3), ("pyramidal", 4)])
def test_profile_counts_the_cones_rows_per_contact(cone, rows):
    """Every constraint row of omni3 is a roller contact (no limits, no friction loss): an
    elliptic condim-3 contact makes 3 rows (normal + 2 friction), a pyramidal one
    2 (condim − 1) = 4 edges; the solver iterates at least once per step with contacts,
    and the timed stages are parts of the step (their sum cannot exceed it). Built with
    the collision class's contact (``floor_impedance`` 0, impratio 10): the floor pairs'
    impratio 1e4 throws a pyramidal robot off the floor (test_solver_cost)."""
    spec = get_spec("omni3")
    t = prepare_timed(spec, OmniParams(cone=cone, floor_impedance=0.0), 0.2)
    p = solver_profile.profile(t)
    assert p.ncon > 1.0  # rollers touch
    assert p.nefc == pytest.approx(rows * p.ncon, rel=1e-12)
    assert p.niter >= 1.0
    assert sum(p.us[s] for s in solver_profile.STAGES) <= p.us["STEP"] * (1 + 1e-9)
    # a free solver saves the solver stage's share, no more
    assert p.free_solver_speedup == pytest.approx(
        1.0 / (1.0 - p.us["CONSTRAINT"] / p.us["STEP"]), rel=1e-12)
    assert p.free_solver_speedup > 1.0
