"""Each figure from a hand-made record whose answer is known in closed form."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.audit.figures import figures, verdict
from wmr_mujoco.audit.run import RAMP, Record

K = 101


def _record(**over) -> Record:
    t = np.linspace(0.0, 1.0, K)
    ideal = np.column_stack([0.2 * t, np.zeros(K), np.zeros(K)])  # 0.2 m straight
    base = dict(time=t, sim=ideal.copy(), ideal=ideal, height=np.full((K, 2), 0.05),
                slip=np.zeros((K, 2)), on_floor=np.ones((K, 2), bool), depth=0.0,
                energy=np.ones(10), kinetic0=1.0, wall=0.5, simulated=2.0, wheel_speed=0.2)
    base.update(over)
    return Record(**base)


def test_position_error_is_worst_distance_over_path():
    rec = _record()
    rec.sim[:, 1] = np.linspace(0.0, 0.01, K)  # 1 cm off at the end of a 0.2 m path
    f = figures(rec)
    assert f.position_pct == pytest.approx(5.0, rel=1e-9)
    assert f.path_m == pytest.approx(0.2, rel=1e-9)


def test_spin_in_place_reports_drift_not_percent():
    rec = _record(ideal=np.zeros((K, 3)))
    rec.sim[:] = 0.0
    rec.sim[:, 0] = 0.003
    f = figures(rec)
    assert f.position_pct is None
    assert f.drift_m == pytest.approx(0.003, rel=1e-9)
    # 3 mm on a 0.1 m robot is 3 % of its span: "follows".
    assert verdict(f, 0.1) == "follows the ideal model"


def test_heading_error_wraps():
    rec = _record()
    rec.sim[:, 2] = np.pi - 0.01
    rec.ideal[:, 2] = -np.pi + 0.01  # 0.02 rad apart across ±π
    assert figures(rec).heading_deg == pytest.approx(np.degrees(0.02), rel=1e-6)


def test_slip_is_rms_of_the_held_part_worst_wheel():
    slip = np.zeros((K, 2))
    slip[:, 1] = np.where(np.linspace(0, 1, K) >= RAMP, 0.01, 5.0)  # the ramp is not judged
    f = figures(_record(slip=slip))
    assert f.slip_ms == pytest.approx(0.01, rel=1e-9)
    assert f.slip_pct == pytest.approx(5.0, rel=1e-9)  # of the 0.2 m/s wheel speed


def test_ripple_off_floor_penetration_energy_and_speed():
    height = np.full((K, 2), 0.05)
    height[K // 2, 0] = 0.049  # 1 mm dip on one wheel
    on = np.ones((K, 2), bool)
    on[:10, 1] = False
    energy = np.array([1.0, 0.9, 0.95, 0.8])  # a 0.05 J rise after a loss counts
    f = figures(_record(height=height, on_floor=on, depth=0.0004,
                        energy=np.array([1.0, 1.02, 0.9]), kinetic0=0.5))
    assert f.ripple_pct == pytest.approx(100 * 0.001 / height[RAMP <= np.linspace(0, 1, K), 0]
                                         .mean(), rel=1e-9)
    assert f.off_floor_pct == pytest.approx(100 * 10 / (2 * K), rel=1e-9)
    assert f.penetration_mm == pytest.approx(0.4, rel=1e-9)
    assert f.energy_drift_pct == pytest.approx(100 * 0.02 / 0.5, rel=1e-9)
    assert f.real_time_factor == pytest.approx(4.0, rel=1e-9)
    assert figures(_record(energy=energy)).energy_drift_pct == pytest.approx(5.0, rel=1e-9)
    assert figures(_record(energy=np.array([1.0, 0.9, 0.8]))).energy_drift_pct == 0.0
