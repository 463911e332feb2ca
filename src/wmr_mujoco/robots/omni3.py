"""The omni robot: three omni wheels at 120°, two staggered rows of free barrel rollers each.

Kinematic inputs ``(u, v, r)``: body twist (``world_frame`` scenarios give world rates
``(Ẋ, Ẏ, ψ̇)``), driven as wheel rates ``θ̇ = H ν``; state ``(X, Y, ψ)``. Torque inputs
``(τ₁, τ₂, τ₃)``: state ``(X, Y, ψ, u, v, r)`` under the reduced Lagrange equations
(:mod:`wmr_mujoco.analytic.omni_dynamics`), parameters read from the compiled model.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.analytic.omni_dynamics import OmniDynamics
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders import omni3 as builder
from wmr_mujoco.models.params import OmniParams, RobotParams, params_or_default
from wmr_mujoco.robots import requirements as req
from wmr_mujoco.robots.spec import RobotSpec
from wmr_mujoco.validation import metrics as mt
from wmr_mujoco.validation.adapters import POSE_UNITS, base_pose, body_twist
from wmr_mujoco.validation.metrics import Metric, Target, Trace
from wmr_mujoco.validation.omni_wheels import (
    DIRECTIONS_DEG,
    ROLLER_RATE_PCT,
    SPEED,
    YAW_RATE,
    omni_probes,
    translation,
    twist_inputs,
)
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import Piecewise, Signal, const

NAME = "omni3"
WHEELS = ("wheel1", "wheel2", "wheel3")
#: Key of the body-velocity target of torque runs.
VELOCITY_PCT = "body velocity error % of peak"
#: Gravity, m/s².
GRAVITY = 9.81


@dataclass(frozen=True)
class OmniKinematics:
    """Omni robot: ``x = (X, Y, ψ)``; controls ``θ̇ = H ν``.

    With ``world_frame`` the inputs are world rates ``(Ẋ, Ẏ, ψ̇)``, turned into a body
    twist with the analytic heading (an open-loop schedule, known in advance).
    """

    params: OmniParams
    world_frame: bool = False
    mode: ActuationMode = ActuationMode.RATE
    state_names: tuple[str, ...] = ("x", "y", "heading")
    state_units: tuple[str, ...] = POSE_UNITS
    wheel_joints: tuple[str, ...] = WHEELS
    lateral_wheels: tuple[str, ...] = ()

    @functools.cached_property
    def layout(self) -> ok.WheelLayout:
        """Ideal wheel layout."""
        return ok.symmetric_layout(self.params.wheel_radius, self.params.wheel_distance)

    @functools.cached_property
    def jacobian(self) -> np.ndarray:
        """``H`` with ``θ̇ = H ν``."""
        return ok.wheel_jacobian(self.layout)

    def twist(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Body twist commanded by input ``u``."""
        if self.world_frame:
            return ok.world_to_body(analytic_state[2], u)
        return np.asarray(u, float)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Wheel rates ``θ̇ = H ν``."""
        return self.jacobian @ self.twist(u, analytic_state)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """``(Ẋ, Ẏ, ψ̇) = R(ψ) ν``."""
        return ok.body_to_world(x[2], self.twist(u, x))

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose of the ``base`` site."""
        return base_pose(model, data)


def dynamics_from_model(model: mujoco.MjModel, params: OmniParams) -> OmniDynamics:
    """Lagrange-model parameters read from the compiled omni model.

    ``M``: total mass; ``I_z``: composite yaw inertia about the centre; ``I_w``: each
    wheel's inertia about its axle (hub, rollers with parallel-axis terms, and the
    hinge's armature). The rollers' spin about their own axes is neglected.
    """
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    centre = data.xpos[model.body("platform").id]

    def inertia_about(bodies: list[int], point: np.ndarray, axis: np.ndarray) -> float:
        total = 0.0
        for b in bodies:
            rot = data.ximat[b].reshape(3, 3)
            inertia = rot @ np.diag(model.body_inertia[b]) @ rot.T
            r = data.xipos[b] - point
            r_perp = r - axis * (r @ axis)
            total += axis @ inertia @ axis + model.body_mass[b] * (r_perp @ r_perp)
        return float(total)

    robot = list(range(1, model.nbody))
    wheel = model.joint(WHEELS[0])
    wheel_body = int(wheel.bodyid[0])
    subtree = [b for b in robot if b == wheel_body or model.body_parentid[b] == wheel_body]
    jid = wheel.id
    i_w = inertia_about(subtree, data.xanchor[jid], data.xaxis[jid]) + float(
        model.dof_armature[model.jnt_dofadr[jid]])
    return OmniDynamics(
        mass=float(sum(model.body_mass[robot])),
        yaw_inertia=inertia_about(robot, centre, np.array([0.0, 0.0, 1.0])),
        wheel_inertia=i_w,
        layout=ok.symmetric_layout(params.wheel_radius, params.wheel_distance))


@dataclass(frozen=True)
class OmniDynamicsAdapter:
    """Omni robot under wheel torques: ``x = (X, Y, ψ, u, v, r)``, reduced Lagrange EOM."""

    dynamics: OmniDynamics
    friction: float = 1.0
    mode: ActuationMode = ActuationMode.TORQUE
    state_names: tuple[str, ...] = ("x", "y", "heading", "u", "v", "r")
    state_units: tuple[str, ...] = (*POSE_UNITS, "m/s", "m/s", "rad/s")
    wheel_joints: tuple[str, ...] = WHEELS
    lateral_wheels: tuple[str, ...] = ()

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Torques as given."""
        return np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Reduced Lagrange equations (:meth:`OmniDynamics.state_derivative`)."""
        return self.dynamics.state_derivative(x, u)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose and body twist of the ``base`` site."""
        return np.concatenate([base_pose(model, data), body_twist(model, data)])


def kinematic_adapter(scenario: Scenario, model: mujoco.MjModel,
                      params: RobotParams | None) -> OmniKinematics:
    """The ideal omni kinematics."""
    return OmniKinematics(params_or_default(params, OmniParams),
                          world_frame=scenario.world_frame)


def dynamic_adapter(scenario: Scenario, model: mujoco.MjModel,
                    params: RobotParams | None) -> OmniDynamicsAdapter:
    """The reduced Lagrange model, with parameters from the compiled model."""
    p = params_or_default(params, OmniParams)
    return OmniDynamicsAdapter(dynamics_from_model(model, p), friction=p.sim.friction)


def judge_torques(scenario: Scenario, trace: Trace, adapter: OmniDynamicsAdapter,
                  targets: Mapping[str, Target]) -> list[Metric]:
    """Each body-velocity component against the Lagrange model, worst over the run.

    For ``q ∈ {u, v, r}`` (m/s, m/s, rad/s, never mixed):
    ``max_t |q_sim(t) − q_model(t)| / max_t |q_model(t)|``. Traction: the largest wheel
    traction force over the run against the Coulomb limit μ N, ``N = M g / 3``.
    """
    tr = trace.arrays()
    sim, ana = tr["sim"], tr["analytic"]
    out = []
    for i, (name, unit) in enumerate(zip(("u", "v", "r"), ("m/s", "m/s", "rad/s"),
                                         strict=True)):
        q_sim, q_ana = sim[:, 3 + i], ana[:, 3 + i]
        peak = float(np.max(np.abs(q_ana)))
        worst = float(np.max(np.abs(q_sim - q_ana)))
        out.append(Metric(f"worst {name} error", 100.0 * worst / peak, "% of peak",
                          targets.get(VELOCITY_PCT),
                          f"max over the run of |{name} − {name}_model| = {worst:.3g} "
                          f"{unit}, peak |{name}_model| = {peak:.3g} {unit}; reported, not "
                          f"judged: the {VELOCITY_REQUIREMENT.value:g} % requirement "
                          "(issue 5) is not met component by component over the run by "
                          "the reduced model (no roller inertia, row hand-overs); issue 16 "
                          "addresses it"))
    for i, name in enumerate(("u", "v", "r")):
        out.append(Metric(f"final {name}: MuJoCo / Lagrange",
                          sim[-1, 3 + i] / ana[-1, 3 + i] if abs(ana[-1, 3 + i]) > 1e-9
                          else float("nan"), "ratio"))
    dyn = adapter.dynamics
    forces = [np.max(np.abs(dyn.traction_forces(x[3:6], scenario.input_at(t))))
              for t, x in zip(tr["time"], ana, strict=True)]
    limit = adapter.friction * dyn.mass * GRAVITY / 3.0
    out.append(Metric("largest traction / μN", float(np.max(forces)) / limit, "",
                      Target.derived(1.0, "Coulomb friction: a wheel rolls without slip "
                                          "while |F_t| ≤ μ N, with N = M g / 3 on each of "
                                          "three wheels around the centre of mass")))
    return out


TARGETS: Mapping[str, Target] = {
    mt.POSITION_PCT: req.position_pct(1.0),
    mt.HEADING_DEG: req.HEADING_DEG,
    mt.CENTRE_DRIFT_M: Target.requirement(
        0.01 * OmniParams().wheel_distance,
        "issue 3: turning in place keeps the centre within 1 % of the wheel distance L"),
    ROLLER_RATE_PCT: Target.requirement(5.0, "issue 3: roller spin rates within 5 % of "
                                             "slide speed / ρ (median over contacts)"),
}
#: Issue 5's body-velocity requirement; left out of :data:`TARGETS` until issue 16 (the
#: torque rows are reported with this figure in their note).
VELOCITY_REQUIREMENT = Target.requirement(3.0, f"{req.SOURCE}: body velocities within 3 % "
                                               "of the Lagrange model under constant torques")


def square_with_rotation(side: float = 0.6, speed: float = 0.24, yaw_rate: float = 0.4
                         ) -> tuple[Signal, ...]:
    """World-frame square (four legs) while the platform spins at a constant rate."""
    leg = side / speed
    ramp = 0.3
    xs, ys = [(0.0, 0.0)], [(0.0, 0.0)]
    for k in range(4):
        t0 = 0.5 + k * leg
        vx, vy = speed * math.cos(k * math.pi / 2), speed * math.sin(k * math.pi / 2)
        for knots, v in ((xs, vx), (ys, vy)):
            knots += [(t0, 0.0), (t0 + ramp, v), (t0 + leg - ramp, v), (t0 + leg, 0.0)]
    return (Piecewise(tuple(xs)), Piecewise(tuple(ys)), const(yaw_rate, 0.5))


SCENARIOS = (
    *(Scenario(NAME, f"translate {deg}°", twist_inputs(translation(deg)))
      for deg in DIRECTIONS_DEG),
    Scenario(NAME, "rotate", twist_inputs((0.0, 0.0, YAW_RATE))),
    Scenario(NAME, "translate+rotate", twist_inputs((SPEED, 0.0, 0.5 * YAW_RATE))),
    Scenario(NAME, "square with rotation", square_with_rotation(), world_frame=True),
    Scenario(NAME, "torque", (const(0.04), const(-0.03), const(0.01)), duration=2.0,
             kind=ScenarioKind.DYNAMIC),
)

SPEC = RobotSpec(
    name=NAME,
    description="three omni wheels at 120 degrees, each with two staggered rows of "
                "passive barrel rollers on free hinges",
    params_type=OmniParams, build=builder.build, folder="omni3", robot_file="omni3.xml",
    adapters={ScenarioKind.KINEMATIC: kinematic_adapter,
              ScenarioKind.DYNAMIC: dynamic_adapter},
    judges={ScenarioKind.DYNAMIC: judge_torques},
    probes=(omni_probes,),
    targets=TARGETS, scenarios=SCENARIOS, demo_scenario="square with rotation",
    bench_scenario="translate+rotate", render_scenario="square with rotation",
)
