"""MuJoCo Warp (CPU here) against C MuJoCo, every robot, on seeded validation-style draws.

The tolerance is derived in :mod:`wmr_mujoco.batch.parity`: a quarter (``SHARE``) of the
robot's own ``worst position error % of path`` target, so that the engine never decides
a validation verdict with more than 25 % margin. Warp builds its kernels once per
process (tens of seconds on a CPU, then cached on disk), so each robot's run is measured
once per module (the ``measured`` fixture).
"""

import numpy as np
import pytest

from wmr_mujoco.batch import parity as parity_mod
from wmr_mujoco.batch.parity import SHARE, draws, parity
from wmr_mujoco.robots import get_spec

pytestmark = pytest.mark.extra  # MuJoCo Warp (the gpu extra)

#: In the default run: a wheeled robot and one on rollers (its own contact set).
QUICK = ("diffdrive", "omni3")
#: The rest, marked slow (still run in CI).
SLOW = ("disc", "bicycle", "tricycle", "single_steer", "double_steer", "mecanum4",
        "omni3_reduced")

_results: dict[str, parity_mod.Parity] = {}


@pytest.fixture(scope="module")
def measured():
    def get(robot: str) -> parity_mod.Parity:
        if robot not in _results:
            _results[robot] = parity(robot, members=3, duration=1.0, seed=7)
        return _results[robot]
    yield get
    for p in _results.values():  # the measured parity, shown with -s
        print(f"\nparity {p.robot}: {p.worst:.3g} {p.unit} (tolerance {p.tolerance:.3g}; "
              f"largest difference {p.worst_m:.3g} m)")


def _check(p: parity_mod.Parity) -> None:
    target = get_spec(p.robot).targets[parity_mod.POSITION_PCT].value
    assert p.unit == "m" or p.tolerance == pytest.approx(SHARE * target)
    assert p.passed, p


@pytest.mark.parametrize("robot", QUICK)
def test_warp_matches_c_mujoco(measured, robot):
    _check(measured(robot))


@pytest.mark.slow
@pytest.mark.parametrize("robot", SLOW)
def test_warp_matches_c_mujoco_every_robot(measured, robot):
    _check(measured(robot))


def test_every_robot_with_a_position_target_is_covered():
    from wmr_mujoco.robots import ROBOTS

    judged = {r for r in ROBOTS if parity_mod.POSITION_PCT in get_spec(r).targets}
    assert judged == set(QUICK) | set(SLOW)


def test_draws_are_seeded_scaled_and_shifted():
    a, b, c = draws("diffdrive", 4, 1), draws("diffdrive", 4, 1), draws("diffdrive", 4, 2)
    t = np.linspace(0.0, 1.0, 7)
    value = lambda d: np.array([[u(x) for x in t] for m in d for u in m])  # noqa: E731
    np.testing.assert_array_equal(value(a), value(b))
    assert not np.array_equal(value(a), value(c))
    with pytest.raises(ValueError, match="no kinematic body-frame scenarios"):
        draws("whipple", 1, 0)

