"""Self-stability of the uncontrolled Whipple bicycle after a sideways push.

The bicycle rolls steadily at ``v``, gets a lean rate ``φ̇₀`` = :data:`PUSH_LEAN_RATE`
about the ground line (:mod:`~wmr_mujoco.robots.whipple.rolling`) and runs free (no
control, actuators at zero) for :data:`PUSH_DURATION` s; its lean ``φ(t)`` is sampled
every 10 ms. The same push through the benchmark's linear equations gives
``φ_lin(t) = [e^{A(v) t} x₀]_φ`` with ``x₀ = (0, 0, φ̇₀, 0)``.

Targets:

* self-stable speeds (issue 14, requirement): the largest ``|φ|`` over the last 2 s of the
  10-s run is under 10 % of the run's largest ``|φ|``.
* where the benchmark's own linear equations, given the same push, do not meet that
  (their ratio ``ρ_lin ≥ 0.1``: at 5.5 m/s the capsize eigenvalue is near −0.12 s⁻¹ and
  needs about 20 s to fall to 10 %), the requirement is out of reach of the benchmark
  itself, and the physics is judged against the benchmark instead (derived bound): the
  late lean is dominated by the slowest mode, capsize, ``∝ e^{s t}``; an eigenvalue error
  within the requirement's 0.05 s⁻¹ changes it at ``t = 10 s`` by a factor of at most
  ``e^{0.05 · 10}``, so ``|ρ − ρ_lin| ≤ ρ_lin (e^{0.5} − 1)``.
* falling speed (requirement "at 3 m/s it grows"): the lean passes 1.2 rad (the
  bicycle has fallen) within the 10-s run; judged as that time ≤ 10 s.
"""

from __future__ import annotations

import functools
import math
import time
from collections.abc import Callable
from dataclasses import dataclass

import mujoco
import numpy as np
from scipy.linalg import expm

from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots.whipple import analytic
from wmr_mujoco.robots.whipple.params import WhippleParams
from wmr_mujoco.robots.whipple.rolling import compile_model, lean_angle, push, roll_steadily
from wmr_mujoco.sim.stepping import check_healthy
from wmr_mujoco.validation.metrics import Metric, Series, Target
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario

#: Speeds of the self-stability runs, m/s, and the one that must fall.
STABLE_SPEEDS = (4.6, 5.0, 5.5)
UNSTABLE_SPEED = 3.0
#: The push: lean rate about the ground line, rad/s.
PUSH_LEAN_RATE = 0.5
#: Name of the push's lean rate in a push scenario's family draw.
PUSH = "push lean rate"
#: Length of a push run, s; the late window judged, s; sampling, s.
PUSH_DURATION, WINDOW, SAMPLE = 10.0, 2.0, 0.01
#: Lean ratio requirement.
LEAN_RATIO_MAX = 0.10
#: The lean at which the bicycle counts as fallen, rad.
FALLEN = 1.2
#: Eigenvalue tolerance behind the derived bound, 1/s (issue 14's absolute tolerance).
EIG_ABS = 0.05

RATIO_TARGET = Target.requirement(
    LEAN_RATIO_MAX, "self-stability of the benchmark bicycle (Meijaard et al. 2007): at 4.6-5.5 "
                    "m/s the lean after a push decays to under 10 % "
                    "of its peak within 10 s")
FALL_TARGET = Target.requirement(
    PUSH_DURATION, "below its weave speed the benchmark bicycle is unstable: at 3 m/s the "
                   "lean grows (the bicycle falls: |lean| passes "
                   f"{FALLEN} rad within the {PUSH_DURATION:g}-s run)")


def linear_bound(ratio_lin: float) -> float:
    """``ρ_lin (e^{0.05 · 10} − 1)``: the derived bound on ``|ρ − ρ_lin|``."""
    return ratio_lin * (math.exp(EIG_ABS * PUSH_DURATION) - 1.0)


@dataclass(frozen=True)
class PushResponse:
    """Lean after a sideways push.

    Attributes:
        speed: forward speed before the push, m/s.
        time: sample times after the push, s.
        lean: lean angle φ, rad.
        peak: largest |φ| over the run, rad.
        final_ratio: largest |φ| over the last :data:`WINDOW` s over the peak.
        fallen_at: time |φ| passed :data:`FALLEN`, s (NaN: it did not fall).
        wall_time: wall-clock time of the run, s.
    """

    speed: float
    time: np.ndarray
    lean: np.ndarray
    peak: float
    final_ratio: float
    fallen_at: float
    wall_time: float


def pushed_start(model: mujoco.MjModel, data: mujoco.MjData, params: RobotParams | None,
                 speed: float, lean_rate: float = PUSH_LEAN_RATE) -> None:
    """Steady rolling at ``speed``, then the push: a scenario's start state."""
    roll_steadily(model, data, params_or_default(params, WhippleParams), speed)
    push(model, data, lean_rate)


def push_response(params: WhippleParams | None, speed: float,
                  lean_rate: float = PUSH_LEAN_RATE, duration: float = PUSH_DURATION,
                  model: mujoco.MjModel | None = None,
                  observer: Callable[[float, mujoco.MjData], None] | None = None
                  ) -> PushResponse:
    """Roll at ``speed``, push sideways, and follow the lean without control.

    The run stops early once the bicycle has fallen (|φ| > 1.2 rad).

    Raises:
        ValueError: bad speed or push.
        SimulationDivergedError: the run diverged.
    """
    model = compile_model(params) if model is None else model
    data = mujoco.MjData(model)
    pushed_start(model, data, params, speed, lean_rate)
    dt = model.opt.timestep
    n = round(duration / dt)
    every = max(1, round(SAMPLE / dt))
    times, leans = [], []
    t0 = time.perf_counter()
    k = 0
    while k <= n:  # steps 0..n, a sample before every every-th: the steps between in C
        times.append(k * dt)
        leans.append(lean_angle(data.qpos[3:7]))
        if observer is not None:
            observer(k * dt, data)
        if abs(leans[-1]) > FALLEN:
            break
        ahead = min(k + every, n + 1)
        mujoco.mj_step(model, data, ahead - k)  # the same steps as one by one
        k = ahead
    wall = time.perf_counter() - t0
    check_healthy(model, data)
    t, lean = np.array(times), np.array(leans)
    peak = float(np.abs(lean).max())
    fallen = np.flatnonzero(np.abs(lean) > FALLEN)
    return PushResponse(speed=speed, time=t, lean=lean, peak=peak,
                        final_ratio=late_ratio(t, lean),
                        fallen_at=float(t[fallen[0]]) if fallen.size else math.nan,
                        wall_time=wall)


def linear_lean(params: WhippleParams | None, speed: float, times: np.ndarray,
                lean_rate: float = PUSH_LEAN_RATE) -> np.ndarray:
    """Lean of the benchmark's linear equations after the same push, ``φ_lin(t)``.

    ``times`` must be evenly spaced from 0: ``x_{k+1} = e^{A Δt} x_k``.
    """
    p = params_or_default(params, WhippleParams)
    a = analytic.state_matrix(speed, analytic.matrices(p))
    step = expm(a * float(times[1] - times[0]))
    x = np.array([0.0, 0.0, lean_rate, 0.0])
    out = np.empty(len(times))
    for k in range(len(times)):
        out[k] = x[0]
        x = step @ x
    return out


def late_ratio(times: np.ndarray, lean: np.ndarray, window: float = WINDOW) -> float:
    """Largest |φ| over the last ``window`` s over the largest |φ| of the run."""
    return float(np.abs(lean[times >= times[-1] - window]).max() / np.abs(lean).max())


def stability_metrics(params: WhippleParams | None, run: PushResponse) -> list[Metric]:
    """The judged lean ratio of one push run (module docstring), and what it rests on."""
    v = run.speed
    lin_t = np.arange(0.0, PUSH_DURATION + SAMPLE / 2, SAMPLE)
    lin = late_ratio(lin_t, linear_lean(params, v, lin_t))
    if v not in STABLE_SPEEDS:
        grow = float(np.abs(run.lean).max() / np.abs(run.lean[run.time <= 1.0]).max())
        return [Metric("time to fall (|lean| > 1.2 rad)", run.fallen_at, "s", FALL_TARGET,
                       "" if np.isfinite(run.fallen_at) else "it did not fall"),
                Metric("largest lean / largest lean in the first second", grow, "1"),
                Metric("linear benchmark: lean over the last 2 s / peak", lin, "1")]
    out = [Metric("lean over the last 2 s / peak", run.final_ratio, "1",
                  RATIO_TARGET if lin < LEAN_RATIO_MAX else None,
                  "" if lin < LEAN_RATIO_MAX else
                  "not judged against 10 %: the linear benchmark itself cannot meet it here"),
           Metric("linear benchmark: lean over the last 2 s / peak", lin, "1")]
    if lin >= LEAN_RATIO_MAX:
        cap = analytic.modes(v, analytic.matrices(params_or_default(params, WhippleParams))
                             ).capsize
        out.append(Metric(
            "|lean ratio − linear benchmark's|", abs(run.final_ratio - lin), "1",
            Target.derived(linear_bound(lin),
                           f"ρ_lin (e^(0.05 1/s · 10 s) − 1) = {lin:.3f} · 0.649: the late "
                           f"lean ∝ e^(s t) of capsize; an eigenvalue error within the "
                           f"requirement's 0.05 1/s scales it at 10 s by at most e^0.5. "
                           f"The 10 % requirement is out of reach of the benchmark itself: "
                           f"its capsize eigenvalue {cap:.3f} 1/s needs ln 10 / "
                           f"{abs(cap):.3f} = {math.log(10) / abs(cap):.0f} s to fall to "
                           f"10 %")))
    return out


def evaluate_push(scenario: Scenario, params: WhippleParams | None, speed: float
                  ) -> MeasurementResult:
    """One push run: its judged metrics and its lean beside the linear benchmark's.

    The push's lean rate is the scenario's drawn :data:`PUSH` (nominal
    :data:`PUSH_LEAN_RATE`).
    """
    lean_rate = scenario.value(PUSH, PUSH_LEAN_RATE)
    run = push_response(params, speed, lean_rate)
    lin = linear_lean(params, speed, run.time, lean_rate)
    series = [Series("MuJoCo", run.time, run.lean, "t [s]", "lean φ [rad]"),
              Series("linear benchmark", run.time, lin, "t [s]", "lean φ [rad]",
                     style="--")]
    return MeasurementResult(stability_metrics(params, run), series)


def push_scenario_parts(speed: float) -> tuple[Callable, Callable]:
    """``(evaluate, start)`` of the push scenario at ``speed``."""
    return (functools.partial(evaluate_push, speed=speed),
            functools.partial(pushed_start, speed=speed))
