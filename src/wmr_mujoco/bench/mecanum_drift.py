"""Why some ramped turns of ``mecanum4`` drift: ``python -m wmr_mujoco.bench.mecanum_drift``.

Runs members of the ``rotate (ramp)`` family (docs/mecanum.md §4, "Which start angles
drift") at the yaw-rate scale :data:`SCALE` and the start angles :data:`PHASES`, through the
validation runner itself, and records every step: the yaw rate, the analytic model's,
the wheel angles and each wheel's normal contact force (summed over its rollers,
``mj_contactForce``). For each second it gives

* the yaw rate over the judged model's, − 1;
* the diagonals' roller-phase offset ``|θ_FL| − |θ_FR|`` (deg of wheel angle; a start
  angle p puts the mirrored diagonals ``2p`` apart: ``θ_FL = p − ω t``, ``θ_FR = p + ω t``);
* what the kinematics say the measured offset and wheel rates do to the yaw rate, − 1:
  the colliders' least squares (:func:`wmr_mujoco.robots.mecanum4.contact.mean_twist`'s,
  with FL and RR started that offset ahead, :func:`offset_effect`) plus the wheels' mean
  rate over command − 1 (a turn on the spot's yaw row of ``H⁺`` is the mean of the four
  rates' magnitudes, ``r = R Σ|θ̇_i| / (4 (a + w))``);
* each wheel's mean rate over its command, − 1, FL, FR, RL, RR (a rate servo droops by
  its torque over its gain, so this is also each wheel's share of the drive torque);
* the power each wheel's contacts dissipate in slip, ``|f_t · v_t|`` (mW; f_t the contact's
  friction force, v_t the roller surface's velocity over the floor in the contact plane).

A second table scans the start angle over :data:`SCAN` at the same scale: each member's
yaw rate over the model's − 1 and the kinematics' (means over 2 s to the end), the loss
beyond the kinematics, and in how many of those seconds FL and RR carry the drive (fall
further short of their command than FR and RL). Both tables go between markers in
``docs/mecanum.md``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import mujoco
import numpy as np

from wmr_mujoco.docs_sync.markers import publish, study_parser
from wmr_mujoco.models.paths import REPO_ROOT
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.mecanum4 import collider
from wmr_mujoco.robots.mecanum4 import contact as mc
from wmr_mujoco.robots.mecanum4.builder import WHEEL_NAMES
from wmr_mujoco.robots.mecanum4.geometry import layout
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import YAW_RATE
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.validation.runner import run_scenario
from wmr_mujoco.validation.variations import INPUT_SCALE, WHEEL_PHASE

DOC = REPO_ROOT / "docs" / "mecanum.md"
MARKER = "mecanum start drift"
SCAN_MARKER = "mecanum start scan"
SCENARIO = "rotate (ramp)"
#: The yaw-rate scale of seed 1179's worst draw, and start angles (rad) 5 mrad and 12.5 mrad
#: past a roller's middle: the band's outside and inside (tests/robots/mecanum4/
#: test_rotation_family.py).
SCALE = 1.19
PHASES = (0.005, 0.0125)
#: Start angles of the scan, rad: finely through the band, then out to half a pitch.
SCAN = (0.0, 0.0025, 0.005, 0.0075, 0.01, 0.0125, 0.015, 0.02, 0.03, 0.06, 0.1, 0.196)


def record(phase: float, scale: float = SCALE) -> dict[str, np.ndarray]:
    """Run the family member at ``phase`` (rad) and ``scale``; every step's record.

    Returns:
        ``time`` (s), ``yaw_rate`` and ``model_yaw`` (rad/s, rad), ``wheel_angles`` (rad,
        FL, FR, RL, RR), ``normal`` (N) and ``slip_power`` (W), per wheel, and
        ``command`` (rad/s, the wheel rates the run commands at full yaw rate).

    Raises:
        ValueError: a phase outside one roller pitch, or a scale outside the family's.
    """
    spec = get_spec("mecanum4")
    s = spec.scenario(SCENARIO)
    pitch = 2.0 * math.pi / MecanumParams().rollers_per_wheel
    if not (math.isfinite(phase) and 0.0 <= phase < pitch):
        raise ValueError(f"phase = {phase!r} rad; valid range is [0, {pitch:.4f})")
    if not (math.isfinite(scale) and 0.8 <= scale <= 1.2):
        raise ValueError(f"scale = {scale!r}; valid range is the family's [0.8, 1.2]")
    rows: list[np.ndarray] = []
    force, vel = np.zeros(6), np.zeros(6)

    def observe(model, data, analytic, adapter) -> None:
        fz, power = np.zeros(4), np.zeros(4)
        for i in range(data.ncon):
            c = data.contact[i]
            for g in (c.geom1, c.geom2):
                body = model.geom_bodyid[g]
                name = model.body(body).name
                if "_roller" not in name:
                    continue
                w = WHEEL_NAMES.index(name.split("_roller")[0])
                mujoco.mj_contactForce(model, data, i, force)
                mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, body, vel, 0)
                v = vel[3:] + np.cross(vel[:3], c.pos - data.xpos[body])
                fz[w] += force[0]
                power[w] += abs(force[1:3] @ (c.frame.reshape(3, 3)[1:] @ v))
        th = [data.qpos[model.jnt_qposadr[model.joint(w).id]] for w in WHEEL_NAMES]
        rows.append(np.array([data.time, data.qvel[5], analytic[2], *th, *fz, *power]))

    result = run_scenario(spec, s.member({INPUT_SCALE: scale, WHEEL_PHASE: phase}),
                          observer=observe)
    if result.error:
        raise RuntimeError(f"{SCENARIO} at phase {phase}: {result.error}")
    a = np.asarray(rows)
    return {"time": a[:, 0] - a[0, 0], "yaw_rate": a[:, 1], "model_yaw": a[:, 2],
            "wheel_angles": a[:, 3:7], "normal": a[:, 7:11],
            "slip_power": a[:, 11:15],
            "command": scale * ok.wheel_jacobian(layout(MecanumParams())) @ np.array(
                [0.0, 0.0, YAW_RATE])}


def offset_effect(offset: float, params: MecanumParams | None = None,
                  samples: int = 4096) -> float:
    """Colliders' kinematics: yaw rate with FL, RR ``offset`` rad ahead, over none, − 1.

    The mean over one pitch of the least-squares twist ``G⁺ D θ̇`` (docs/mecanum.md §3),
    the turn on the spot at unit rate, the diagonal FL–RR started ``offset`` into the pitch.
    """
    p = params or MecanumParams()
    g, lay = collider.roller_geometry(p), layout(p)
    w = ok.wheel_jacobian(lay) @ np.array([0.0, 0.0, 1.0])
    t = (np.arange(samples) + 0.5) * g.pitch / float(np.max(np.abs(w))) / samples
    sg = np.sign(lay.roller_angles)

    def yaw(start: np.ndarray) -> float:
        G, rim = mc.slip_rows_at(g, lay.positions, sg, start[None, :] + w[None, :] * t[:, None])
        return float(np.einsum("kij,kj->ki", np.linalg.pinv(G), rim * w[None, :]).mean(0)[2])

    return yaw(np.array([offset, 0.0, 0.0, offset])) / yaw(np.zeros(4)) - 1.0


def per_second(phase: float, scale: float = SCALE) -> dict[str, np.ndarray]:
    """Each whole second after the ramp's transient (1–2 s on) of one member's record.

    Returns:
        ``measured`` (yaw rate / model − 1), ``offset`` (rad), ``kinematic`` (what the
        kinematics make of the offset and the wheel rates, − 1), ``rates`` (each wheel's
        rate / command − 1, (k, 4)) and ``slip_power`` (W, (k, 4)); module docstring.
    """
    r = record(phase, scale)
    t, th = r["time"], r["wheel_angles"]
    model_rate = np.gradient(r["model_yaw"], t)
    out: dict[str, list] = {k: [] for k in ("measured", "offset", "kinematic", "rates",
                                            "slip_power")}
    for k in range(1, round(t[-1])):
        s = (t > k) & (t <= k + 1)
        i0, i1 = int(np.searchsorted(t, k)), int(np.searchsorted(t, k + 1)) - 1
        rates = (th[i1] - th[i0]) / (t[i1] - t[i0]) / r["command"] - 1.0
        offset = float(np.mean(np.abs(th[s, 0]) - np.abs(th[s, 1])))
        out["measured"].append(float(r["yaw_rate"][s].mean() / model_rate[s].mean()) - 1.0)
        out["offset"].append(offset)
        out["kinematic"].append(offset_effect(offset) + float(np.mean(rates)))
        out["rates"].append(rates)
        out["slip_power"].append(np.mean(r["slip_power"][s], 0))
    return {k: np.asarray(v) for k, v in out.items()}


def table(phases: Sequence[float] = PHASES, scale: float = SCALE) -> str:
    """Markdown table: each second of each member (module docstring)."""
    lines = ["| start angle | second | yaw rate / model − 1 | phase offset | kinematics of "
             "offset and rates | wheel rate / command − 1, FL, FR, RL, RR | "
             "slip power FL, FR, RL, RR |", "|---|---|---|---|---|---|---|"]
    for phase in phases:
        r = per_second(phase, scale)
        for k, measured in enumerate(r["measured"]):
            droop = ", ".join(f"{100 * v:+.3f}" for v in r["rates"][k])
            power = ", ".join(f"{1e3 * v:.1f}" for v in r["slip_power"][k])
            lines.append(f"| {1e3 * phase:g} mrad | {k + 1}–{k + 2} s | {100 * measured:+.3f} % | "
                         f"{math.degrees(r['offset'][k]):+.2f}° | "
                         f"{100 * r['kinematic'][k]:+.3f} % | {droop} % | {power} mW |")
    return "\n".join(lines)


def scan(phases: Sequence[float] = SCAN, scale: float = SCALE) -> str:
    """Markdown table: the start-angle scan (module docstring)."""
    lines = ["| start angle | yaw rate / model − 1 | kinematics of offset and rates | "
             "beyond the kinematics | seconds FL, RR carry the drive |",
             "|---|---|---|---|---|"]
    for phase in phases:
        r = per_second(phase, scale)
        later = slice(1, None)  # from 2 s on
        measured = float(np.mean(r["measured"][later]))
        kinematic = float(np.mean(r["kinematic"][later]))
        rates = r["rates"][later]
        carry = int(np.sum(rates[:, [0, 3]].mean(1) < rates[:, [1, 2]].mean(1)))
        lines.append(f"| {1e3 * phase:g} mrad | {100 * measured:+.3f} % | "
                     f"{100 * kinematic:+.3f} % | {100 * (measured - kinematic):+.3f} % | "
                     f"{carry} of {len(rates)} |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Print the table and write it into docs/mecanum.md."""
    args = study_parser(__doc__).parse_args(argv)
    publish(DOC, {MARKER: table(), SCAN_MARKER: scan()}, not args.no_write)


if __name__ == "__main__":
    main()
