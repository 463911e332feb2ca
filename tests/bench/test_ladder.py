"""The fidelity ladder: its error measures, one rung's figures, and its table."""

import math

import numpy as np
import pytest

from wmr_mujoco.bench import ladder
from wmr_mujoco.robots.omni3.dynamics import path_length


def _line(n: int = 101) -> np.ndarray:
    """A straight run along x, 1 m, heading 0: (n, 3)."""
    return np.column_stack([np.linspace(0.0, 1.0, n), np.zeros(n), np.zeros(n)])


def test_dynamic_errors_are_the_worst_distance_over_the_reference_path():
    ref = {"step a": _line(), "torque b": _line(), "coast c": _line()}
    off = {k: v.copy() for k, v in ref.items()}
    off["step a"][:, 1] += 0.02  # 2 cm aside throughout: 2 % of a 1 m path
    off["coast c"][-1, 2] = math.radians(3.0)  # 3° of heading at the end
    errors = ladder.dynamic_errors(off, ref, distance=0.15)
    assert path_length(ref["step a"], 0.15) == pytest.approx(1.0)
    assert errors["step commands"] == pytest.approx((2.0, 0.0))
    assert errors["torques"] == (0.0, 0.0)
    assert errors["coast"][1] == pytest.approx(3.0)
    assert ladder.dynamic_errors(ref, ref, 0.15) == dict.fromkeys(ladder.GROUPS, (0.0, 0.0))
    # The same run on another timestep (half the samples) is interpolated: a straight line
    # at constant speed is linear in time, so it lands on the reference exactly.
    assert ladder.dynamic_errors({**ref, "step a": _line(len(ref["step a"]) // 2 + 1)},
                                 ref, 0.15)["step commands"] == pytest.approx((0.0, 0.0))
    with pytest.raises(ValueError, match="step a"):
        ladder.dynamic_errors({**ref, "step a": _line()[:, :2]}, ref, 0.15)


def test_the_reduced_rung_measured_on_one_run_per_group():
    """One rung through every measure (quick: the bench scenario, one run per group):
    its DoF is the model's, the capsules touch the floor (two contacts per wheel at most),
    it meets omni3's kinematic target (1 % of path), and its dynamic errors against
    omni3's physics are finite and those of the same robot against itself are zero."""
    rung = next(r for r in ladder._rungs() if r.robot == "omni3_reduced" and r.registered)
    specs = tuple(next(s for s in ladder._dynamic_specs() if s.name.startswith(p))
                  for p in ("step", "torque"))
    own = ladder.dynamic_poses(rung, specs)
    assert ladder.dynamic_errors(own, own, 0.15)["torques"] == (0.0, 0.0)
    dof, contacts, speed = ladder.cost(rung)
    assert dof == 9 and 3 <= contacts <= 6 and speed > 0
    path, heading = ladder.kinematic_errors(rung, quick=True)
    assert 0 <= path < 1.0 and heading >= 0


def test_table_has_a_row_per_rung(monkeypatch):
    from wmr_mujoco.batch import simulate

    monkeypatch.setattr(simulate, "installed_backends", lambda: ["rollout"])
    figs = [ladder.RungFigures("omni3", 45, 3.0, 13_400.0, batched=18_500.0),
            ladder.RungFigures("cheap", 9, 6.0, 26_000.0, kin_path_pct=0.1,
                               kin_heading_deg=0.3,
                               dynamic=dict.fromkeys(ladder.GROUPS, (1.0, 2.0)), messages=4)]
    text = ladder.table(figs)
    assert "| omni3 | 45 | 3.0 | 13.4 | 18.5 | 0 | n/a / n/a | reference |" in text
    assert "| cheap | 9 | 6.0 | 26 | - | 4 | 0.10 / 0.30 | 1.00 / 2.00 |" in text
    monkeypatch.setattr(simulate, "installed_backends", lambda: ["rollout", "warp"])
    text = ladder.table(figs)
    assert "| warp, 8 worlds (k robot-steps/s) |" in text
    assert "| omni3 | 45 | 3.0 | 13.4 | 18.5 | - | 0 |" in text


def test_docs_hold_the_markers():
    from wmr_mujoco.docs_sync.markers import has_markers

    assert has_markers(ladder.DOC, ladder.MARKER)
