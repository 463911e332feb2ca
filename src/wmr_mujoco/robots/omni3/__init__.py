"""The omni robot: three omni wheels at 120°, two staggered rows of free barrel rollers each.

Kinematic inputs ``(u, v, r)``: body twist (``world_frame`` scenarios give world rates
``(Ẋ, Ẏ, ψ̇)``), driven as wheel rates ``θ̇ = H ν``; state ``(X, Y, ψ)``. The dynamic
scenarios of issue 16 are measurement scenarios, one module per concept: step commands
and torque inputs (:mod:`.dynamics`), coasting (:mod:`.coasting`) and the slip onset
(:mod:`.traction`), all against the hybrid model
(:mod:`wmr_mujoco.robots.roller_wheels.omni_hybrid`) read from the compiled model (:mod:`.model`);
the dynamic runs are simulated together (:mod:`.runs`).
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import ClassVar

import mujoco
import numpy as np

from wmr_mujoco.analytic.planar import twist_step, twist_steps
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots import requirements as req
from wmr_mujoco.robots.learning import NO_RADIUS_BANDS, Learning
from wmr_mujoco.robots.omni3 import builder, coasting, dynamics, families, peer, traction
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import CENTRE_BODY, WHEELS
from wmr_mujoco.robots.roller_wheels import (
    DIRECTIONS_DEG,
    ROLLER_RATE_PCT,
    SPEED,
    YAW_RATE,
    OmniDynamicsAdapter,
    dynamics_from_model,
    omni_probes,
    translation,
    twist_inputs,
)
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.spec import Clip, RobotSpec
from wmr_mujoco.validation import metrics as mt
from wmr_mujoco.validation import variations as var
from wmr_mujoco.validation.adapters import POSE_UNITS, base_pose, per_distinct_row
from wmr_mujoco.validation.command import RateCommand
from wmr_mujoco.validation.family import Family
from wmr_mujoco.validation.metrics import Target
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import Piecewise, Signal, const

NAME = "omni3"


@dataclass(frozen=True)
class OmniKinematics:
    """Omni robot: ``x = (X, Y, ψ)``; controls ``θ̇ = H ν``.

    With ``world_frame`` the inputs are world rates ``(Ẋ, Ẏ, ψ̇)``, turned into a body
    twist with the analytic heading (an open-loop schedule, known in advance).
    """

    #: ``sim_state`` reads the pose and joint positions alone (the runner's frames only).
    frames_only: ClassVar[bool] = True

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

    def controls_on(self, inputs: np.ndarray, states: np.ndarray) -> np.ndarray:
        """(N, 3) :meth:`controls` of every step: once per distinct input for body rates."""
        if self.world_frame:  # the twist turns with the analytic heading
            w = np.asarray(inputs, float).reshape(-1, 3)
            if not np.isfinite(w).all():  # world_to_body raises there, naming it
                return np.array([self.controls(u, x) for u, x in zip(inputs, states,
                                                                    strict=True)])
            # world_to_body's floats row by row (its math.cos and math.sin), then H ν by
            # a stacked matmul (each row's own BLAS product, as H @ ν)
            psi = np.asarray(states, float)[:, 2].tolist()
            c, s = np.array([math.cos(p) for p in psi]), np.array([math.sin(p) for p in psi])
            nu = np.stack([c * w[:, 0] + s * w[:, 1], -s * w[:, 0] + c * w[:, 1], w[:, 2]], 1)
            return np.matmul(self.jacobian, nu[:, :, None])[:, :, 0]
        return per_distinct_row(lambda u: self.controls(u, None), inputs, 3)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """``(Ẋ, Ẏ, ψ̇) = R(ψ) ν`` (scalar arithmetic: called four times per step)."""
        uu, vv, rr = self.twist(u, x)
        c, s = math.cos(x[2]), math.sin(x[2])
        return np.array([c * uu - s * vv, s * uu + c * vv, rr])

    def exact_step(self, x: np.ndarray, u: np.ndarray, dt: float) -> np.ndarray:
        """Exact step under the held input.

        World rates move the pose linearly; a body twist along the arc of
        :func:`~wmr_mujoco.analytic.planar.twist_step`.
        """
        if self.world_frame:
            return x + dt * np.asarray(u, float)
        return twist_step(x, u, dt)

    def trajectory(self, x0: np.ndarray, inputs: np.ndarray, dt: float) -> np.ndarray:
        """Every step's pose at once: the floats of :meth:`exact_step` step after step.

        World rates: the running sum ``x + Δt u_k`` (one sequential ``np.cumsum``); a body
        twist: :func:`~wmr_mujoco.analytic.planar.twist_steps`.
        """
        u = np.asarray(inputs, float).reshape(-1, 3)
        if self.world_frame:
            return np.cumsum(np.concatenate([np.asarray(x0, float)[None], dt * u]), axis=0)
        return twist_steps(x0, u, dt)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose of the ``base`` site."""
        return base_pose(model, data)


def dynamic_adapter(scenario: Scenario, model: mujoco.MjModel,
                    params: RobotParams | None) -> OmniDynamicsAdapter:
    """The reduced Lagrange model of the compiled omni3 (``make(..., backend="dynamic")``).

    No roller hand-overs (the hybrid model of :mod:`.dynamics` has them); no scenario of
    omni3 is judged on it.
    """
    p = params_or_default(params, OmniParams)
    layout = ok.symmetric_layout(p.wheel_radius, p.wheel_distance)
    return OmniDynamicsAdapter(dynamics_from_model(model, layout, CENTRE_BODY, WHEELS[0]),
                               WHEELS, friction=p.sim.friction)


def kinematic_adapter(scenario: Scenario, model: mujoco.MjModel,
                      params: RobotParams | None) -> OmniKinematics:
    """The ideal omni kinematics."""
    return OmniKinematics(params_or_default(params, OmniParams),
                          world_frame=scenario.world_frame)


TARGETS: Mapping[str, Target] = {
    mt.POSITION_PCT: req.position_pct(1.0),
    mt.HEADING_DEG: req.HEADING_DEG,
    mt.CENTRE_DRIFT_M: Target.requirement(
        0.01 * OmniParams().wheel_distance,
        f"{req.SOURCE}: turning in place keeps the centre within 1 % of the wheel "
        "distance L"),
    ROLLER_RATE_PCT: Target.requirement(5.0, "accuracy asked of the roller model: spin rates "
                                             "within 5 % of "
                                             "slide speed / ρ (median over contacts)"),
}
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


#: Every dynamic run, simulated together once per parameter set (:mod:`.runs`).
DYNAMIC_SPECS = (*dynamics.STEP_SPECS, *dynamics.TORQUE_SPECS, coasting.COAST_SPEC)

#: What a user would vary in a kinematic run: speeds and yaw rate ±20 %, the wheels' start
#: angle over one full roller pitch (both rows: the pattern repeats after ``2π / n`` for
#: ``n`` rollers per row).
KINEMATIC_FAMILY = Family((var.speeds(), var.roller_pitch(OmniParams().rollers_per_row)),
                          var.KINEMATIC_DRAWS)
#: The square with rotation's heading requirement is open over its family: the two roller
#: rows put the contact at L ± e in turn, so the yaw rate ripples and the heading drifts
#: (models/omni3/README.md), which the ideal kinematics leaves out; over the family's
#: start angles and speeds its worst draws miss 1° (seeds other than the default too).
SQUARE_OPEN = {"worst heading error": "the roller rows' contact at L ± e makes the heading "
               "drift, which the ideal kinematics leaves out; the family's worst draws "
               "miss it (spread in the families table)"}
#: The same family where its spread is not small: 20 draws.
WIDE_FAMILY = dataclasses.replace(KINEMATIC_FAMILY, draws=var.DYNAMIC_DRAWS)

SCENARIOS = (
    *(Scenario(NAME, f"translate {deg}°", twist_inputs(translation(deg)),
               family=KINEMATIC_FAMILY) for deg in DIRECTIONS_DEG),
    # The turning runs' heading spread is not small (python -m
    # wmr_mujoco.bench.family_spread omni3): 20 draws.
    Scenario(NAME, "rotate", twist_inputs((0.0, 0.0, YAW_RATE)), family=WIDE_FAMILY),
    Scenario(NAME, "translate+rotate", twist_inputs((SPEED, 0.0, 0.5 * YAW_RATE)),
             family=WIDE_FAMILY),
    Scenario(NAME, "square with rotation", square_with_rotation(), world_frame=True,
             family=WIDE_FAMILY, open_targets=SQUARE_OPEN),
    *(Scenario(NAME, s.name, kind=ScenarioKind.MEASUREMENT, evaluate=dynamics.evaluate_step,
               duration=s.duration, family=families.STEP_FAMILY,
               description="rate servo stepped to a twist (no ramp): physics vs the hybrid "
                           "model (servo law, torque limit) and the kinematics")
      for s in dynamics.STEP_SPECS),
    *(Scenario(NAME, s.name, kind=ScenarioKind.MEASUREMENT, evaluate=dynamics.evaluate_torque,
               duration=s.duration, family=families.TORQUE_FAMILY,
               description="constant wheel torques from rest: physics vs the hybrid, "
                           "Lagrange and kinematic models, windowed over the run")
      for s in dynamics.TORQUE_SPECS),
    Scenario(NAME, coasting.COAST_SPEC.name, kind=ScenarioKind.MEASUREMENT,
             evaluate=coasting.evaluate_coast, duration=coasting.COAST_TIME,
             family=families.COAST_FAMILY,
             description="drive at (u, 0, r), motors off: yaw-rate decay, turn rate of "
                         "the velocity, energy lost per second"),
    Scenario(NAME, "slip onset", kind=ScenarioKind.MEASUREMENT,
             evaluate=traction.evaluate_slip, duration=traction.RAMP_TIME,
             family=families.SLIP_FAMILY,
             description="one slowly ramped push along x: the torque at which a wheel "
                         "slips, against the traction limit μ N with load transfer"),
)

#: Driven by the body twist ``(u, v, r)``.
COMMAND = RateCommand(("u", "v", "r"), ("m/s", "m/s", "rad/s"), wheels=WHEELS,
                      kinematics=lambda p: OmniKinematics(params_or_default(p, OmniParams)))

#: The step families' hybrid-model requirements, checked at the collision-class contact
#: they were derived for (tests/robots/omni3 pin them there), are open at the default
#: floor pairs (issue 24: wheels on the floor): worst draws miss them (families table).
STEP_OPEN_REASON = ("derived at the collision-class contact; at the default floor pairs "
                    "the hybrid model's hand-overs drift from the physics' and the worst "
                    "draws miss it (spread in the families table)")
STEP_OPEN = {name: {"hybrid: worst position error": STEP_OPEN_REASON,
                    "hybrid: worst heading error": STEP_OPEN_REASON}
             for name in dynamics.STEP_TWISTS}

SPEC = RobotSpec(
    name=NAME,
    description="three omni wheels at 120 degrees, each with two staggered rows of "
                "passive barrel rollers on free hinges",
    params_type=OmniParams, build=builder.build, folder="omni3", robot_file="omni3.xml",
    adapters={ScenarioKind.KINEMATIC: kinematic_adapter, ScenarioKind.DYNAMIC: dynamic_adapter},
    probes=(omni_probes,),
    targets=TARGETS, scenarios=SCENARIOS, demo_scenario="square with rotation",
    bench_scenario="translate+rotate", render_scenario="square with rotation",
    clips=(Clip(), Clip("translate+rotate", "trails.png", width=480, height=360)),
    peer=peer.peer_comparison, command=COMMAND,
    scene_extras=builder.floor_pairs, prepare=families.prepare, open_targets=STEP_OPEN,
    # The step and torque runs (2 s each): one batch, the hybrid model's cost per step.
    prepared_together=tuple(s.name for s in (*dynamics.STEP_SPECS, *dynamics.TORQUE_SPECS)),
    learning=Learning("Omni3", scale=0.5, max_curvature=3.0, bands=NO_RADIUS_BANDS),
)
