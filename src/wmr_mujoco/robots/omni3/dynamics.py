"""omni3's step commands and torque inputs, judged over the whole run (issue 16).

Each scenario is one :class:`~wmr_mujoco.robots.omni3.runs.RunSpec`, simulated with all
the others by :func:`~wmr_mujoco.robots.omni3.runs.cached_runs`; its ``evaluate`` turns
the physics, the hybrid model's and the kinematic prediction into metrics and plot series.

* Step commands (rate servo, no ramp): the hybrid model with the servo law
  ``τ = clip(k_v (θ̇_cmd − θ̇), ±τ_max)`` read from the model; judged: worst position error
  in % of path and worst heading error (requirements of issue 16).
* Torque inputs (constant wheel torques from rest): the hybrid model with ``τ = u``; each
  body-velocity component's worst error in % of its scale and the worst position error
  in % of path are the issue's requirements, judged; each roller hand-over is a jump of
  the twist that the simulator resolves only to its step, so where the model's wheel
  phase stays within one step's turn of the physics' (:func:`event_shift`) the twist
  components are compared with jumps allowed :data:`EVENT_SHIFT` sample apart ((τ,
  ε)-closeness,
  :func:`~wmr_mujoco.robots.roller_wheels.twist_errors.event_aligned_error`), else at the
  same instant; the same-instant figures are reported beside. Reported too: the reduced
  Lagrange model's windowed errors and the old single-instant figure.

Path of a run: ``Σ √(|Δp|² + (L Δψ)²)``, the path of a point at radius L on the platform,
so that "% of path" is defined for a pure rotation too. Component scales: u and v:
``max(peak planar speed, L · peak |r|)``; r: ``max(peak |r|, peak speed / L)`` (a
component that stays zero is judged against the speed the run's motion gives the wheels).
"""

from __future__ import annotations

import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots.omni3.members import member_run, member_spec
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import (
    CONTACT_WINDOW,
    Run,
    RunSpec,
    hybrid,
    phase_lag_steps,
)
from wmr_mujoco.robots.roller_wheels import (
    DIRECTIONS_DEG,
    SPEED,
    YAW_RATE,
    lagrange_of,
    translation,
)
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.twist_errors import twist_metrics
from wmr_mujoco.validation.metrics import Metric, Series, Target, rms
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario

SOURCE = "accuracy asked of the dynamic models"
#: Requirements of issue 16.
STEP_PATH = Target.requirement(0.3, f"{SOURCE}: a step command within 0.3 % of path of "
                                    "the dynamic model, worst over the run")
STEP_HEADING = Target.requirement(0.2, f"{SOURCE}: a step command within 0.2° of the "
                                       "dynamic model, worst over the run")
#: Open over their families (issue 24; spreads: ``python -m wmr_mujoco.bench.omni_families``).
TORQUE_COMPONENT = Target.open(
    1.0, f"{SOURCE}: each body-velocity component within 1 % of its peak over the whole run",
    "over the start phase the model's hand-overs land a sample or more from the physics' "
    "(the one-sample allowance holds only where its wheel phase stays within one step's "
    "turn), and a wheel starting in a valley with both rows touching creeps out through "
    "the soft contact's slip, which the rigid-contact model does not hold "
    "(docs/omni-dynamics.md § 13)")
TORQUE_PATH = Target.open(0.5, f"{SOURCE}: pose within 0.5 % of path under torque "
                               "inputs, worst over the run",
                          "a wheel starting in a valley with both rows touching creeps out "
                          "through the soft contact's slip; the rigid-contact model keeps it "
                          "there (docs/omni-dynamics.md § 13)")
TRACTION = Target.derived(1.0, "Coulomb friction: a wheel rolls without slip while |F_t| ≤ "
                               "μ N, N from the robot's balance with load transfer; the "
                               "torque inputs must stay below it for the rolling models")
#: Run lengths, s.
STEP_TIME = 2.0
TORQUE_TIME = 2.0
#: Torque inputs, N·m: along x, along y, pure rotation, combined.
TORQUES = {"along x": (0.0, -0.03, 0.03), "along y": (0.04, -0.02, -0.02),
           "rotate": (0.02, 0.02, 0.02), "combined": (0.04, -0.03, 0.01)}
#: Samples a hand-over's jump may land apart in the physics and the hybrid model (derived,
#: docs/omni-dynamics.md § 10): MuJoCo detects contacts at the positions that start a
#: step and their impulse enters the velocity that ends it, so a roller that touches
#: within step k changes the velocity of step k + 1, while the continuous model jumps
#: at the touch itself; with the penetration and the semi-implicit position lead, both
#: fractions of a step, the physics' jump lands on the model's sample or the next one.
EVENT_SHIFT = 1


def event_shift(run: Run) -> int:
    """:data:`EVENT_SHIFT` where its premise holds over the run, else 0 (same instant).

    The premise of the one-sample allowance: the model's wheel phase stays within one
    step's turn of the physics' (:func:`~wmr_mujoco.robots.omni3.runs.phase_lag_steps`),
    so that each hand-over of the model falls within a sample of the physics' one.
    """
    return EVENT_SHIFT if abs(phase_lag_steps(run)) <= 1.0 else 0


def phase_metric(run: Run) -> Metric:
    """The model's worst wheel phase in steps' turns (reported; the allowance's premise)."""
    shift = event_shift(run)
    return Metric("hybrid: worst wheel phase", phase_lag_steps(run), "steps' turns",
                  note=("within one step's turn: twist compared with jumps one sample apart"
                        if shift else "beyond one step's turn: twist compared at the same "
                        "instant") + " (− behind the physics)")


def _rates(twist: tuple[float, float, float]) -> tuple[float, float, float]:
    """Wheel rates ``θ̇ = H ν`` of the default omni3 (kinematic model's H, lever L)."""
    p = OmniParams()
    H = ok.wheel_jacobian(ok.symmetric_layout(p.wheel_radius, p.wheel_distance))
    return tuple(float(x) for x in H @ np.asarray(twist))  # type: ignore[return-value]


STEP_TWISTS = {**{f"step {d}°": translation(d) for d in DIRECTIONS_DEG},
               "step rotate": (0.0, 0.0, YAW_RATE),
               "step translate+rotate": (SPEED, 0.0, 0.5 * YAW_RATE)}
STEP_SPECS = tuple(RunSpec(name, ActuationMode.RATE, _rates(tw), STEP_TIME)
                   for name, tw in STEP_TWISTS.items())
TORQUE_SPECS = tuple(RunSpec(f"torque {name}", ActuationMode.TORQUE, tau, TORQUE_TIME)
                     for name, tau in TORQUES.items())


def path_length(pose: np.ndarray, distance: float) -> float:
    """``Σ √(|Δp|² + (L Δψ)²)`` (module docstring), m."""
    step = np.diff(pose, axis=0)
    return float(np.sum(np.sqrt(np.sum(step[:, :2] ** 2, axis=1) + (distance * step[:, 2]) ** 2)))


def kinematic_pose(twist: np.ndarray, dt: float) -> np.ndarray:
    """Integrate a body-twist series (N + 1, 3) from the origin (midpoint rule)."""
    nu = 0.5 * (twist[1:] + twist[:-1])
    pose = np.zeros_like(twist)
    pose[1:, 2] = np.cumsum(nu[:, 2]) * dt
    psi = pose[:-1, 2] + 0.5 * dt * nu[:, 2]
    c, s = np.cos(psi), np.sin(psi)
    pose[1:, 0] = np.cumsum(c * nu[:, 0] - s * nu[:, 1]) * dt
    pose[1:, 1] = np.cumsum(s * nu[:, 0] + c * nu[:, 1]) * dt
    return pose


def pose_metrics(model: str, ref: np.ndarray, other: np.ndarray, distance: float,
                 path_target: Target | None = None, heading_target: Target | None = None
                 ) -> list[Metric]:
    """Worst (judged where a target is given) and RMS position and heading errors."""
    path = max(path_length(ref, distance), 1e-9)
    dist = np.linalg.norm(other[:, :2] - ref[:, :2], axis=1)
    head = np.degrees(np.abs(other[:, 2] - ref[:, 2]))
    return [Metric(f"{model}: worst position error", 100 * float(dist.max()) / path,
                   "% of path", path_target,
                   f"max |p − p_{model}| = {1000 * dist.max():.3g} mm over a path of "
                   f"{path:.3g} m"),
            Metric(f"{model}: RMS position error", 1000 * rms(dist), "mm"),
            Metric(f"{model}: worst heading error", float(head.max()), "deg", heading_target),
            Metric(f"{model}: RMS heading error", rms(head), "deg")]


def plot_series(run: Run, models: dict[str, tuple[np.ndarray, np.ndarray]]) -> list[Series]:
    """Trajectory of each model, and its position and heading error over time."""
    out = [Series("physics", run.pose[:, 0], run.pose[:, 1], "x [m]", "y [m]")]
    for name, (pose, _) in models.items():
        out.append(Series(name, pose[:, 0], pose[:, 1], "x [m]", "y [m]"))
    for name, (pose, _) in models.items():
        out.append(Series(name, run.t, 1000 * np.linalg.norm(pose[:, :2] - run.pose[:, :2],
                                                             axis=1),
                          ylabel="position error from the physics [mm]"))
    for name, (pose, _) in models.items():
        out.append(Series(name, run.t, np.degrees(pose[:, 2] - run.pose[:, 2]),
                          ylabel="heading error from the physics [deg]"))
    return out


#: Body-twist components of the torque runs' plots: name, unit.
TWIST_COMPONENTS = (("u", "m/s"), ("v", "m/s"), ("r", "rad/s"))


def twist_series(run: Run, models: dict[str, np.ndarray]) -> list[Series]:
    """The body twist over time, one panel per component: physics and each model.

    What the torque runs judge (each component against its own scale); the hand-overs'
    jumps show as steps of the physics and the hybrid model, which the Lagrange model
    (continuous) does not have.
    """
    out = []
    for j, (name, unit) in enumerate(TWIST_COMPONENTS):
        ylabel = f"{name} [{unit}]"
        out.append(Series("physics", run.t, run.twist[:, j], ylabel=ylabel))
        out += [Series(label, run.t, twist[:, j], ylabel=ylabel)
                for label, twist in models.items()]
    return out


def _run(scenario: Scenario, params: RobotParams | None, specs: tuple[RunSpec, ...]) -> Run:
    from wmr_mujoco.robots.omni3 import DYNAMIC_SPECS

    if params is not None and not isinstance(params, OmniParams):
        raise ValueError(f"params must be OmniParams, got {type(params).__name__}")
    base = {s.name: s for s in specs}.get(scenario.name)
    if base is None:
        raise ValueError(f"no dynamic run named {scenario.name!r}")
    return member_run(member_spec(scenario, base), params, DYNAMIC_SPECS)


def off_floor_metric(run: Run) -> Metric:
    """Share of wheel samples off the floor over the run's first :data:`CONTACT_WINDOW` s.

    No roller of the wheel touching the floor, % of the samples (reported: the hybrid
    model never leaves it; a sliding soft contact lifts its wheel,
    ``docs/omni-dynamics.md`` § 10).
    """
    return Metric(f"wheels off the floor, first {CONTACT_WINDOW:g} s",
                  100.0 * float(np.mean(run.off_floor)), "% of wheel samples",
                  note="no roller of the wheel touching the floor; the hybrid model "
                       "keeps every wheel on it")


def evaluate_step(scenario: Scenario, params: RobotParams | None) -> MeasurementResult:
    """A step command: the hybrid model judged, the kinematic prediction reported."""
    run = _run(scenario, params, STEP_SPECS)
    L = hybrid(params).distance  # type: ignore[arg-type]
    twist_cmd = np.linalg.solve(hybrid_jacobian(params), np.asarray(run.spec.command))
    kin_twist = np.vstack([run.twist[0], np.tile(twist_cmd, (len(run.t) - 1, 1))])
    kin = kinematic_pose(kin_twist, run.dt)
    dyn = run.hybrid
    metrics = (pose_metrics("hybrid", run.pose, dyn.pose, L, STEP_PATH, STEP_HEADING)
               + twist_metrics("hybrid", run.twist, dyn.twist, L, shift=event_shift(run))
               + [phase_metric(run), off_floor_metric(run)]
               + pose_metrics("kinematic", run.pose, kin, L))
    return MeasurementResult(metrics, plot_series(run, {"kinematic": (kin, kin_twist),
                                                        "hybrid": (dyn.pose, dyn.twist)}))


def hybrid_jacobian(params: RobotParams | None) -> np.ndarray:
    """The kinematic model's ``H`` (lever L) of the hybrid model's radius and distance."""
    hy = hybrid(params)  # type: ignore[arg-type]
    return ok.wheel_jacobian(ok.symmetric_layout(hy.radius, hy.distance))


def lagrange_twists(params: RobotParams | None, torques: np.ndarray, twist0: np.ndarray,
                    dt: float, n: int) -> np.ndarray:
    """Body twists of the reduced Lagrange model under constant torques (RK4 on Δt).

    ``(P + I_w HᵀH) ν̇ = Hᵀτ − c(ν)``, ``c = (−M r v, M r u, 0)``
    (:class:`~wmr_mujoco.robots.roller_wheels.omni_dynamics.OmniDynamics`).
    """
    dyn = lagrange_of(hybrid(params))  # type: ignore[arg-type]
    minv = np.linalg.inv(dyn.mass_matrix)
    force = minv @ dyn.H.T @ np.asarray(torques, float)
    # body_acceleration with c(ν) = (−M r v, M r u, 0): ν̇ = f − M r (−v m₀ + u m₁),
    # m_j the columns of the inverse mass matrix (plain floats: 4 stages × n steps).
    f = [float(x) for x in force]
    m0 = [float(x) * dyn.mass for x in minv[:, 0]]
    m1 = [float(x) * dyn.mass for x in minv[:, 1]]

    def accel(nu: list[float]) -> list[float]:
        u, v, r = nu
        return [f[j] + r * (v * m0[j] - u * m1[j]) for j in range(3)]

    out = np.zeros((n + 1, 3))
    out[0] = twist0
    nu = [float(x) for x in twist0]
    for k in range(n):  # RK4
        k1 = accel(nu)
        k2 = accel([nu[j] + 0.5 * dt * k1[j] for j in range(3)])
        k3 = accel([nu[j] + 0.5 * dt * k2[j] for j in range(3)])
        k4 = accel([nu[j] + dt * k3[j] for j in range(3)])
        nu = [nu[j] + dt / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]) for j in range(3)]
        out[k + 1] = nu
    return out


def traction_metric(params: RobotParams | None, torques: np.ndarray, twists: np.ndarray
                    ) -> Metric:
    """Largest ``|F_t,i| / (μ N_i)`` over the run, from the Lagrange model's twists.

    ``F_t = (τ − I_w H ν̇)/r`` (:meth:`OmniDynamics.traction_forces`), N from the robot's
    balance with the wheels' angular momentum (:meth:`OmniHybrid.normal_loads`).
    """
    hy = hybrid(params)  # type: ignore[arg-type]
    dyn = lagrange_of(hy)
    worst = 0.0
    for nu in twists:
        force = dyn.traction_forces(nu, torques)
        thdd = dyn.H @ dyn.body_acceleration(nu, torques)
        worst = max(worst, float(np.max(np.abs(force) / (hy.friction
                                                         * hy.normal_loads(force, thdd)))))
    return Metric("largest traction / μN", worst, "", TRACTION)


def evaluate_torque(scenario: Scenario, params: RobotParams | None) -> MeasurementResult:
    """Torque inputs: the hybrid model judged, Lagrange and the old figure reported.

    The old figure: ``|ν_Lagrange − ν| / |ν|`` at the last instant, mixed units.
    """
    run = _run(scenario, params, TORQUE_SPECS)
    L = hybrid(params).distance  # type: ignore[arg-type]
    tau = np.asarray(run.spec.command)
    dyn = run.hybrid
    kin_twist = np.linalg.solve(hybrid_jacobian(params), run.wheel_rates.T).T
    kin = kinematic_pose(kin_twist, run.dt)
    lag_twist = lagrange_twists(params, tau, run.twist[0], run.dt, len(run.t) - 1)
    lag = kinematic_pose(lag_twist, run.dt)
    final = float(np.linalg.norm(lag_twist[-1] - run.twist[-1]) / np.linalg.norm(run.twist[-1]))
    comp = dict.fromkeys("uvr", TORQUE_COMPONENT)
    metrics = (twist_metrics("hybrid", run.twist, dyn.twist, L, comp, event_shift(run))
               + pose_metrics("hybrid", run.pose, dyn.pose, L, TORQUE_PATH)
               + [phase_metric(run), traction_metric(params, tau, lag_twist[::5]),
                  off_floor_metric(run)]
               + twist_metrics("Lagrange", run.twist, lag_twist, L)
               + pose_metrics("Lagrange", run.pose, lag, L)
               + pose_metrics("kinematic", run.pose, kin, L)
               + [Metric("Lagrange: |Δν| / |ν| at the last instant", 100 * final, "%",
                         note="a single-instant figure (mixed units), not a "
                              "whole-run bound; kept for comparison only")])
    return MeasurementResult(metrics, twist_series(run, {
        "kinematic": kin_twist, "Lagrange": lag_twist, "hybrid": dyn.twist}))

