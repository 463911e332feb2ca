"""omni3 coasting: drive at (u, 0, r), motors off, and compare how the motion decays.

The physics and the hybrid model start the coast from the same measured state (twist,
wheel angles, roller spins; :mod:`~wmr_mujoco.robots.omni3.runs`). Figures, each the
least-squares slope over the whole coast (the twist and the energy ripple within every
roller pitch, so two end samples would depend on where in a pitch they fall):

    yaw-rate decay          −dr/dt                     rad/s²
    velocity turn rate      dχ/dt, χ = atan2(Ẏ, Ẋ)       rad/s
    energy lost per second  −dT/dt, T = ½ νᵀ 𝕄(σ, θ) ν   W

with 𝕄(σ, θ) the hybrid model's planar mass matrix evaluated on both (the physics at its
measured wheel angles). Each is judged as ``|hybrid − physics| / |physics|`` against issue
16's 5 %.
"""

from __future__ import annotations

import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots.omni3.dynamics import _run
from wmr_mujoco.robots.omni3.runs import RunSpec, hybrid
from wmr_mujoco.robots.roller_wheels import SPEED, YAW_RATE
from wmr_mujoco.robots.roller_wheels import omni_hybrid as oh
from wmr_mujoco.validation.metrics import Metric, Series, Target
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario

COAST = Target.open(5.0, "accuracy asked of the coasting model: within 5 % of the physics",
                    "over speeds, yaw rates, durations, lead-ins and start phases the "
                    "figures are relative errors of small slopes, moved by tens of % where "
                    "a wheel lingers in a valley with both rows touching at its turning "
                    "point (docs/omni-dynamics.md § 13)")
#: Drive (with a 0.5 s ramp) and coast, s.
DRIVE_TIME = 1.5
COAST_TIME = 3.0
COAST_TWIST = (SPEED, 0.0, YAW_RATE)
COAST_SPEC = RunSpec("coast after (0.3, 0, 1)", ActuationMode.TORQUE, (0.0, 0.0, 0.0),
                     COAST_TIME, lead_in=COAST_TWIST, lead_time=DRIVE_TIME)


def slope(t: np.ndarray, y: np.ndarray) -> float:
    """Least-squares slope of ``y(t)`` over the whole run."""
    return float(np.polyfit(t, y, 1)[0])


def velocity_direction(pose: np.ndarray, twist: np.ndarray) -> np.ndarray:
    """χ = world direction of the centre's velocity, unwrapped, rad."""
    c, s = np.cos(pose[:, 2]), np.sin(pose[:, 2])
    return np.unwrap(np.arctan2(s * twist[:, 0] + c * twist[:, 1],
                                c * twist[:, 0] - s * twist[:, 1]))


def coast_figures(t: np.ndarray, pose: np.ndarray, twist: np.ndarray, energy: np.ndarray
                  ) -> tuple[float, float, float]:
    """Yaw-rate decay (rad/s²), velocity-direction turn rate (rad/s), energy loss (W)."""
    return (-slope(t, twist[:, 2]), slope(t, velocity_direction(pose, twist)),
            -slope(t, energy))


def evaluate_coast(scenario: Scenario, params: RobotParams | None) -> MeasurementResult:
    """The coast's three figures, physics against the hybrid model."""
    run = _run(scenario, params, (COAST_SPEC,))
    hy = hybrid(params)  # type: ignore[arg-type]
    dyn = run.hybrid
    e_phys = oh.kinetic_energies(hy, run.twist, run.wheel_angles)
    e_dyn = oh.kinetic_energies(hy, dyn.twist, dyn.thetas)
    fp = coast_figures(run.t, run.pose, run.twist, e_phys)
    fd = coast_figures(run.t, dyn.pose, dyn.twist, e_dyn)
    metrics = []
    for (name, unit, target), a, b in zip((("yaw-rate decay", "rad/s²", COAST),
                                           ("velocity-direction turn rate", "rad/s", COAST),
                                           ("energy lost per second", "W", COAST)),
                                          fp, fd, strict=True):
        metrics.append(Metric(f"{name}: hybrid vs physics", 100 * abs(b - a) / max(abs(a),
                                                                                  1e-12),
                              "% of physics", target,
                              f"physics {a:.4g} {unit}, hybrid {b:.4g} {unit}; the Lagrange "
                              "model gives 0"))
        metrics += [Metric(f"{name}, physics", a, unit), Metric(f"{name}, hybrid", b, unit)]
    impacts = sum(s[2] for s in dyn.switches) / (run.t[-1] - run.t[0])
    metrics.append(Metric("hand-over impact energy per second, hybrid", impacts, "W",
                          note="the impact maps' share of the hybrid model's loss"))
    metrics.append(Metric("impact share of the hybrid model's loss", 100 * impacts
                          / max(fd[2], 1e-12), "%"))
    chi_p, chi_d = velocity_direction(run.pose, run.twist), velocity_direction(dyn.pose,
                                                                               dyn.twist)
    series = [Series("physics", run.t, run.twist[:, 2], ylabel="yaw rate r [rad/s]"),
              Series("hybrid", run.t, dyn.twist[:, 2], ylabel="yaw rate r [rad/s]"),
              Series("kinematic (held)", run.t, np.full_like(run.t, run.twist[0, 2]),
                     ylabel="yaw rate r [rad/s]"),
              Series("physics", run.t, e_phys, ylabel="kinetic energy [J]"),
              Series("hybrid", run.t, e_dyn, ylabel="kinetic energy [J]"),
              Series("physics", run.t, chi_p, ylabel="velocity direction χ [rad]"),
              Series("hybrid", run.t, chi_d, ylabel="velocity direction χ [rad]")]
    return MeasurementResult(metrics, series)
