"""Roller-phase drift of ``mecanum4`` in a turn: ``python -m wmr_mujoco.bench.mecanum_phase``.

The turn on the spot (1 rad/s after a 0.5 s ramp) run twice on the default model: with
the robot's rate servos as built, and with a probe's angle term added to the wheel
commands, ``ω_i = ω_cmd,i + k_θ (θ_ref,i − θ_i)`` (``θ_ref`` the commanded angle), which
holds the wheels' roller phases together. For each second of the run: the mean yaw rate
over the colliders' kinematic model's (:func:`wmr_mujoco.robots.mecanum4.collider.
realised_twist`) and over the pitch-averaged model's, and the roller-phase offset of the
diagonals, ``|θ_FL| − |θ_FR|`` in degrees of wheel angle (a pitch is 360°/n). The table
goes between markers in ``docs/mecanum.md`` (docs/mecanum.md §4).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import mujoco
import numpy as np

from wmr_mujoco.docs_sync.markers import publish, study_parser
from wmr_mujoco.lookup import load
from wmr_mujoco.models.paths import REPO_ROOT
from wmr_mujoco.robots.mecanum4 import collider
from wmr_mujoco.robots.mecanum4.builder import WHEEL_NAMES
from wmr_mujoco.robots.mecanum4.geometry import layout
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels import pitch_averaged as pa

DOC = REPO_ROOT / "docs" / "mecanum.md"
MARKER = "mecanum phase drift"
#: The probe's angle gain, 1/s: well above the drift rates, well below the servo's k_v/I_w.
ANGLE_GAIN = 20.0
SETTLE, RAMP, DURATION, YAW_RATE = 0.5, 0.5, 10.0, 1.0


def run(angle_gain: float, duration: float = DURATION,
        params: MecanumParams | None = None) -> dict[str, np.ndarray]:
    """The turn with the given angle gain (0: the robot's rate servos as built).

    Returns:
        ``time`` (s, from the command's start), ``yaw_rate`` (rad/s, body frame) and
        ``wheel_angles`` (rad, FL, FR, RL, RR), every step.

    Raises:
        ValueError: a negative gain or a non-positive duration.
    """
    if not (math.isfinite(angle_gain) and angle_gain >= 0.0):
        raise ValueError(f"angle_gain = {angle_gain!r} 1/s; valid range is [0, inf)")
    if not (math.isfinite(duration) and duration > 0.0):
        raise ValueError(f"duration = {duration!r} s; valid range is (0, inf)")
    p = params or MecanumParams()
    model = load("mecanum4", p)
    data = mujoco.MjData(model)
    rates = ok.wheel_jacobian(layout(p)) @ np.array([0.0, 0.0, YAW_RATE])
    joints = [model.joint(w) for w in WHEEL_NAMES]
    qadr = [int(j.qposadr[0]) for j in joints]
    acts = [next(a for a in range(model.nu) if model.actuator_trnid[a, 0] == j.id)
            for j in joints]
    for _ in range(round(SETTLE / model.opt.timestep)):
        mujoco.mj_step(model, data)
    start, home = data.time, data.qpos[qadr].copy()
    out: dict[str, list] = {"time": [], "yaw_rate": [], "wheel_angles": []}
    for _ in range(round(duration / model.opt.timestep)):
        t = data.time - start
        # Commanded angle: the ramp's integral, then the held rate.
        travelled = 0.5 * t * t / RAMP if t < RAMP else t - 0.5 * RAMP
        data.ctrl[acts] = (min(t / RAMP, 1.0) * rates
                           + angle_gain * (home + travelled * rates - data.qpos[qadr]))
        mujoco.mj_step(model, data)
        out["time"].append(data.time - start)
        out["yaw_rate"].append(float(data.qvel[5]))
        out["wheel_angles"].append(data.qpos[qadr].copy())
    return {k: np.asarray(v) for k, v in out.items()}


def table(duration: float = DURATION) -> str:
    """Markdown table: each second of both runs (module docstring)."""
    p = MecanumParams()
    nu = np.array([0.0, 0.0, YAW_RATE])
    kin = collider.realised_twist(p, nu)[2]
    lay = layout(p)
    avg = (pa.realised_twist_map(lay, p.rollers_per_wheel) @ nu)[2]
    runs = {"rate servos (as built)": run(0.0, duration),
            f"probe: angle term {ANGLE_GAIN:g}/s": run(ANGLE_GAIN, duration)}
    lines = ["| drive | second | yaw rate / kinematic model − 1 | yaw rate / pitch-averaged "
             "− 1 | phase offset |θ_FL| − |θ_FR| |", "|---|---|---|---|---|"]
    for label, r in runs.items():
        for k in range(1, int(duration)):
            s = (r["time"] > k) & (r["time"] <= k + 1)
            mean = float(np.mean(r["yaw_rate"][s]))
            th = r["wheel_angles"][s]
            offset = math.degrees(float(np.mean(np.abs(th[:, 0]) - np.abs(th[:, 1]))))
            lines.append(f"| {label} | {k}–{k + 1} s | {100 * (mean / kin - 1):+.3f} % | "
                         f"{100 * (mean / avg - 1):+.3f} % | {offset:+.2f}° |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Print the table and write it into docs/mecanum.md."""
    args = study_parser(__doc__).parse_args(argv)
    publish(DOC, {MARKER: table()}, not args.no_write)


if __name__ == "__main__":
    main()
