"""omni3's time-step study: the semi-implicit position lead, and bad input."""

import numpy as np
import pytest

from wmr_mujoco.bench import omni_timestep as ts
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.robots.omni3.runs import RunSpec, settled, simulate_runs


def test_position_lead_is_the_simulators_quadrature():
    """MuJoCo's positions minus the trapezoidal integral of its own velocity samples are
    exactly ``(Δt/2)(v_n − v_0)`` (the module docstring's identity for
    ``q_{n+1} = q_n + Δt v_{n+1}``). Tolerance 1e-7 m: the planar velocity is rebuilt from
    the body twist with the heading alone, so the platform's tilt (under 1e-3 rad on the
    roller contacts) times its vertical speed (under 1e-3 m/s) over 0.3 s bounds what it
    misses by 3e-7 m; the lead itself (Δt/2 times a speed change of a few cm/s) is over a
    hundred times that tolerance."""
    spec = RunSpec("push", ActuationMode.TORQUE, (0.0, -0.03, 0.03), 0.3)
    run = simulate_runs([spec])["push"]
    v = ts.world_velocity(run.pose, run.twist)
    trapezoid = np.vstack([np.zeros(2), np.cumsum(0.5 * (v[1:] + v[:-1]), axis=0) * run.dt])
    lead = ts.position_lead(run.pose, run.twist, run.dt)
    np.testing.assert_allclose(run.pose[:, :2] - trapezoid, lead, rtol=0, atol=1e-7)
    assert np.abs(lead).max() > 1e-5


@pytest.mark.parametrize("call, match", [
    (lambda: ts.position_lead(np.zeros((3, 3)), np.zeros((3, 3)), 0.0), "dt"),
    (lambda: ts.position_lead(np.zeros((3, 3)), np.zeros((2, 3)), 0.004), "pose"),
    (lambda: ts.convergence(steps=()), "steps"),
    (lambda: ts.coast_convergence(steps=()), "steps"),
    (lambda: ts.coast_convergence(steps=(0.02,)), "timestep"),
    (lambda: ts.convergence(steps=(0.004, 0.003)), "divide"),
    (lambda: ts.convergence(steps=(float("nan"),)), "step"),
    (lambda: settled(ActuationMode.TORQUE, timestep=-1.0), "timestep"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_table_gives_both_twist_figures_per_row():
    """One synthetic row: the physics' and the hybrid model's twist figures appear
    sample by sample and with jumps one sample apart, each row as wide as the header."""
    fig = {"u": 0.1, "v": 0.2, "r": 0.3, "u sample by sample": 1.5,
           "v sample by sample": 2.5, "r sample by sample": 6.5, "position": 0.04}
    text = ts.table([{"run": "torque rotate", "step": 0.001, "variant": ts.VARIANTS[0][0],
                      "physics": fig, "hybrid": fig, "phase": 0.25, "lead": 0.05,
                      "rho": -0.005}])
    lines = text.splitlines()
    assert len(lines) == 3
    assert all(line.count("|") == lines[0].count("|") for line in lines)
    assert lines[2].count("1.5 / 2.5 / 6.5") == 2 and lines[2].count("0.1 / 0.2 / 0.3") == 2
    assert "jumps one sample apart (judged where the wheel phase" in lines[0]
