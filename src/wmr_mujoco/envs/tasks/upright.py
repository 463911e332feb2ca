"""StayUpright: keep a leaning bicycle (Whipple) up at a commanded speed it cannot hold alone.

Below its weave speed ``v_w`` (≈ 4.3 m/s for the benchmark bicycle,
:func:`wmr_mujoco.robots.whipple.analytic.weave_speed`) the uncontrolled Whipple bicycle falls
over. Episode: steady upright rolling at ``v* ~ U(min_speed, max_speed)`` (``max_speed``
must lie below ``v_w``), then a sideways push: lean rate ``φ̇₀ ~ ±U(0.2, 1) max_push``
rad/s (:func:`wmr_mujoco.robots.whipple.rolling.push`).

Observation block:

* ``lean, lean_rate`` (2, rad, rad/s): ``φ``, ``φ̇`` of the rear frame (> 0: to the right);
* ``steer, steer_rate`` (2, rad, rad/s): ``δ``, ``δ̇``;
* ``speed_error`` (1, m/s): ``u − v*``;
* ``target_speed`` (1, m/s): ``v*``.

Reward terms: ``alive = +dt``, ``lean = −dt (φ / fall_lean)²``,
``speed = −dt ((u − v*) / v*)²``, ``effort = −0.01 mean(a²)``, ``failure = −10`` once.
Failure: ``|φ| > fall_lean`` (fallen). Success: the episode reaches its time limit
without falling, with ``|u − v*| ≤ speed_tolerance v*`` at the end.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from wmr_mujoco.envs.tasks.base import Field, Task, check_options, effort, speed_of
from wmr_mujoco.envs.tasks.goal import BONUS
from wmr_mujoco.robots.whipple import analytic
from wmr_mujoco.robots.whipple.params import WhippleParams
from wmr_mujoco.robots.whipple.rolling import push, roll_steadily


class StayUpright(Task):
    """Balance the Whipple bicycle below its self-stable speeds (module docstring)."""

    name = "StayUpright"
    fields = (Field("lean, lean_rate", 2, "rad, rad/s"), Field("steer, steer_rate", 2,
                                                               "rad, rad/s"),
              Field("speed_error", 1, "m/s"), Field("target_speed", 1, "m/s"))

    def __init__(self, scale: float, max_curvature: float, **options: float) -> None:
        super().__init__(scale, max_curvature)
        o = check_options(self.name, options, {
            "time_limit": 10.0, "min_speed": 2.5, "max_speed": 3.5, "max_push": 0.5,
            "fall_lean": 0.7, "speed_tolerance": 0.2})
        self.weave_speed = analytic.weave_speed(analytic.matrices(WhippleParams()))
        if not o["min_speed"] <= o["max_speed"] < self.weave_speed:
            raise ValueError(
                f"StayUpright: need min_speed <= max_speed < the weave speed "
                f"{self.weave_speed:.2f} m/s (below it the bicycle is not self-stable); got "
                f"min_speed={o['min_speed']}, max_speed={o['max_speed']} m/s")
        if o["fall_lean"] >= math.pi / 2:
            raise ValueError(f"StayUpright: fall_lean={o['fall_lean']} rad must be below π/2")
        self.options = o
        self.time_limit = o["time_limit"]
        self.speed = o["min_speed"]
        self._push = 0.0

    def sample(self, rng: np.random.Generator) -> np.ndarray:
        """Draw ``v*`` and the push; the bicycle starts at the origin heading along x."""
        o = self.options
        self.speed = float(rng.uniform(o["min_speed"], o["max_speed"]))
        self._push = float(rng.choice([-1.0, 1.0]) * rng.uniform(0.2, 1.0) * o["max_push"])
        return np.zeros(3)

    def start(self, robot: Any, rng: np.random.Generator) -> None:
        """Steady rolling at ``v*``, then the push (in ``robot.data``, MuJoCo backend)."""
        if robot.data is None:
            raise ValueError("StayUpright needs the MuJoCo backend (a rolling start state)")
        roll_steadily(robot.model, robot.data, getattr(robot, "params", None), self.speed)
        push(robot.model, robot.data, self._push)

    def observe(self, state: Any) -> list[float]:
        """``(φ, φ̇, δ, δ̇, u − v*, v*)``."""
        x = state.extra
        return [x["lean"], x["lean_rate"], x["steer"], x["steer_rate"],
                speed_of(state) - self.speed, self.speed]

    def reward_terms(self, prev: Any, state: Any, action: Sequence[float], dt: float
                     ) -> dict[str, float]:
        """Alive, lean, speed, effort and failure terms (docstring)."""
        fall = self.options["fall_lean"]
        lean = state.extra["lean"]
        rel = (speed_of(state) - self.speed) / self.speed
        return {"alive": dt, "lean": -dt * (lean / fall) ** 2, "speed": -dt * rel * rel,
                "effort": effort(action), "failure": -BONUS if abs(lean) > fall else 0.0}

    def outcome(self, state: Any) -> tuple[bool, bool]:
        """Never succeeds early; fails once fallen."""
        return False, abs(state.extra["lean"]) > self.options["fall_lean"]

    def succeeded_at_time_limit(self, state: Any) -> bool:
        """Up, and within the speed tolerance."""
        o = self.options
        return (abs(state.extra["lean"]) <= o["fall_lean"] and
                abs(speed_of(state) - self.speed) <= o["speed_tolerance"] * self.speed)
