"""The ideal kinematic model of a robot found by the audit, and the manoeuvres it allows.

Body twist ``ν = (u, v, r)`` of the chassis origin in the chassis frame (x forward as
the model is built, z up). A wheel whose centre is at body position ``p`` and whose spin
axis is the signed unit vector ``n`` (horizontal, chassis frame) has its contact point
moving at ``v_c = (u − r p_y, v + r p_x)``. Spinning at ``ω`` about ``n``, the rim's
material point at the contact (a radius R below the axle) moves at ``v_c + ω R s`` with
``s = ẑ × n``. Rolling without slip along the constrained direction gives the wheel's
row of the generic Jacobian (docs/analytical.md §4, Lynch & Park's row)::

    standard wheel (fixed, steered):  v_c + ω R s = 0  ⇒  ω = −(s · v_c) / R
    Swedish wheel, roller axis e = cos γ s + sin γ n at the contact (γ as
    :mod:`wmr_mujoco.models.classify` measures it):
        e · (v_c + ω R s) = 0  ⇒  ω = −(s + tan γ n) · v_c / R

so ``ω = J ν`` with ``J`` one row per driven wheel. A centred steerable wheel is first
turned about its (vertical) steering axis until its rolling direction ``d = −s`` is
parallel to ``v_c`` (the smaller of the two angles, the wheel then rolling either way).
Castors and ball wheels follow; they add no row. The manoeuvres (straight, arc, spin and,
for a holonomic robot, strafe and diagonal) are twists the sliding constraints of the
fixed wheels (the class's C1f, :mod:`wmr_mujoco.analytic.campion`) allow: translations
across the fixed axle and rotations about a point on it; :func:`infeasible` drops those
that need a steering angle beyond its joint's range or that the driven wheels do not
determine.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.campion import sliding_row
from wmr_mujoco.audit.wheels import AuditWheel, Wheels

#: Ground speed of the manoeuvres' reference point, m/s (the peer study's speed).
SPEED = 0.2
#: Largest spin rate of a spin manoeuvre, rad/s.
MAX_SPIN = 2.0
#: Smallest arc radius, m (three robot spans when larger).
MIN_ARC_RADIUS = 0.5
ROLLING_KINDS = ("fixed", "steerable", "swedish")


@dataclass(frozen=True)
class Manoeuvre:
    """One drive of the audit: a constant body twist ramped in.

    Attributes:
        name: straight, arc, spin, strafe or diagonal.
        twist: ``(u, v, r)`` of the chassis origin in the chassis frame.
        description: one line for the report.
    """

    name: str
    twist: tuple[float, float, float]
    description: str


def contact_velocity(p: tuple[float, float], twist: np.ndarray) -> np.ndarray:
    """``v_c = (u − r p_y, v + r p_x)``: velocity of the chassis point above ``p``."""
    u, v, r = twist
    return np.array([u - r * p[1], v + r * p[0]])


def _s(axle: np.ndarray) -> np.ndarray:
    """``s = ẑ × n`` for a horizontal axle ``n = (n_x, n_y, 0)``."""
    return np.array([-axle[1], axle[0]])


def steer_angle(w: AuditWheel, twist: np.ndarray, sense: float) -> float:
    """Steering angle that rolls ``w`` along its contact velocity (0 when it is still).

    About the steering joint's signed axis; ``sense`` = ±1 is the sign of its z component.
    """
    vc = contact_velocity(w.wheel.position, twist)
    if np.linalg.norm(vc) < 1e-9:
        return 0.0
    d0 = -_s(np.array(w.wheel.axle))
    turn = np.arctan2(d0[0] * vc[1] - d0[1] * vc[0], d0 @ vc)
    turn = (turn + np.pi / 2) % np.pi - np.pi / 2  # roll backwards rather than turn > 90°
    return float(sense * turn)


def wheel_row(w: AuditWheel, beta_world: float = 0.0) -> np.ndarray:
    """The wheel's Jacobian row ``ω = row · ν`` (module docstring).

    ``beta_world`` is the steering turn about +z already applied to the axle.
    """
    c, s_ = np.cos(beta_world), np.sin(beta_world)
    a = np.array(w.wheel.axle)
    n = np.array([c * a[0] - s_ * a[1], s_ * a[0] + c * a[1]])
    k = _s(n)
    if w.kind == "swedish":
        k = k + np.tan(w.wheel.roller_angle or 0.0) * n
    px, py = w.wheel.position
    return -np.array([k[0], k[1], k[1] * px - k[0] * py]) / w.radius


def jacobian(found: Wheels) -> tuple[tuple[str, ...], np.ndarray]:
    """Names and rows of ``J`` at zero steering for the rolling wheels.

    Fixed, steered (at zero) and Swedish wheels: ``ω = J ν``, rad/s per (m/s, m/s, rad/s).
    """
    rows = [w for w in found.wheels if w.kind in ROLLING_KINDS and w not in found.scrubbing]
    return tuple(w.name for w in rows), np.array([wheel_row(w) for w in rows]).reshape(-1, 3)


def reference_point(found: Wheels) -> np.ndarray:
    """The point whose path is judged.

    The middle of the fixed axle, else of the rolling wheels, else of all wheels (chassis
    frame).
    """
    used = [w for w in found.wheels if w not in found.scrubbing]
    for kinds in (("fixed",), ROLLING_KINDS, None):
        pts = [w.wheel.position for w in used if kinds is None or w.kind in kinds]
        if pts:
            return np.mean(np.array(pts), axis=0)
    raise AssertionError("a robot with wheels has a reference point")


def forward(found: Wheels) -> np.ndarray:
    """Unit direction the robot drives straight along.

    Across its fixed axle (the sign nearest the chassis +x), else the chassis +x.
    """
    fixed = [w for w in found.wheels if w.kind == "fixed" and w not in found.scrubbing]
    if not fixed:
        return np.array([1.0, 0.0])
    f = -_s(np.array(fixed[0].wheel.axle))
    f /= np.linalg.norm(f)
    return f if (f[0], f[1]) >= (-f[0], -f[1]) else -f


def span(found: Wheels, c: np.ndarray) -> float:
    """Largest horizontal distance of a wheel from ``c``, m."""
    return max(float(np.linalg.norm(np.array(w.wheel.position) - c)) for w in found.wheels)


def manoeuvres(found: Wheels, speed: float = SPEED) -> tuple[Manoeuvre, ...]:
    """The manoeuvres the robot's class allows (module docstring), at ``speed``."""
    c = reference_point(found)
    f = forward(found)
    reach = max(span(found, c), 1e-3)
    holonomic = found.classification.robot_class == (3, 0)

    def twist(direction: np.ndarray, rate: float) -> tuple[float, float, float]:
        u, v = speed * direction
        return (float(u + rate * c[1]), float(v - rate * c[0]), float(rate))

    spin_rate = min(MAX_SPIN, speed / reach)
    arc_radius = max(MIN_ARC_RADIUS, 3.0 * reach)
    out = [Manoeuvre("straight", twist(f, 0.0), f"straight at {speed:g} m/s"),
           Manoeuvre("arc", twist(f, speed / arc_radius),
                     f"left arc of radius {arc_radius:.2f} m at {speed:g} m/s")]
    out.append(Manoeuvre("spin", twist(np.zeros(2), spin_rate),
                         f"spin on the spot at {spin_rate:.2f} rad/s"))
    if holonomic:
        left = np.array([-f[1], f[0]])
        diag = (f + left) / np.sqrt(2.0)
        out += [Manoeuvre("strafe", twist(left, 0.0), f"sideways (left) at {speed:g} m/s"),
                Manoeuvre("diagonal", twist(diag, 0.0), f"diagonal (45° left) at {speed:g} m/s")]
    return tuple(out)


def infeasible(found: Wheels, man: Manoeuvre, driven: set[str],
               steer_limits: dict[str, tuple[float, float]]) -> str | None:
    """Why ``man`` cannot be driven kinematically, or None when it can.

    Two reasons: a steering angle outside its joint's range (``steer_limits``: wheel name
    -> range about the joint's own axis, from the model; ``sense`` +1 assumed there, the
    range being symmetric in practice); or a twist the wheels do not determine: the
    sliding rows (fixed and steered wheels) and the driven wheels' rows must have rank 3,
    else part of the motion (a unicycle's or a single steered wheel's yaw) is left to the
    dynamics, and only the straight run is kept.
    """
    twist = np.array(man.twist)
    rows = []
    for w in found.wheels:
        if w in found.scrubbing or w.kind not in ROLLING_KINDS:
            continue
        beta = steer_angle(w, twist, 1.0) if w.kind == "steerable" else 0.0
        if w.name in steer_limits:
            lo, hi = steer_limits[w.name]
            if not lo <= beta <= hi:
                return (f"needs {w.name} steered {beta:+.2f} rad, outside its range "
                        f"[{lo:g}, {hi:g}] rad")
        if w.kind != "swedish":
            c, s_ = np.cos(beta), np.sin(beta)
            a = np.array(w.wheel.axle)
            rows.append(sliding_row(w.wheel.position, np.array([c * a[0] - s_ * a[1],
                                                                s_ * a[0] + c * a[1]])))
        if w.name in driven:
            rows.append(wheel_row(w, beta))
    if man.name != "straight" and np.linalg.matrix_rank(np.array(rows), tol=1e-6) < 3:
        return ("the driven wheels do not determine this motion (rank of the sliding and "
                "driven-wheel rows < 3): its yaw is left to the dynamics")
    return None
