"""Known pitfalls: detected from the model, confirmed (or not) by a counterfactual run.

Each :class:`Pitfall` reads the compiled model, and if it finds its suspected cause it
builds a copy of the model without that cause and drives the same manoeuvres again.
A cause is CONFIRMED when removing it lowers the worst judged position error (% of path)
by more than :data:`CONFIRM_POINTS` percentage points and by more than
:data:`CONFIRM_SHARE` of its value (both, so that noise on a small error confirms
nothing); otherwise the finding is reported as "not confirmed" with both figures.

Pitfalls: passive joints whose friction loss, damping or armature brake rollers,
castors or balls; cylinder colliders on standard wheels (several contacts on the rim's
edges scrub in a turn); undriven fixed wheels off the drive axle (a caster wheel without
a swivel scrubs in every turn); a timestep larger than half the wheel contacts' time
constant (MuJoCo then softens the contact: ``mjENBL_REFSAFE``); the noslip solver (not
in MJX or MuJoCo Warp). A polygonal roller envelope (ripple) is reported from the
geometry, without a counterfactual (the audit does not rebuild rollers).
"""

from __future__ import annotations

import copy
import dataclasses
from collections.abc import Callable
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.audit.core import Audit, Outcome, drive_all, judged
from wmr_mujoco.audit.wheels import subtree_bodies

CONFIRM_POINTS = 1.0
#: Gears (m) read as an assumed wheel radius, and the relative mismatch that counts.
GEAR_RADIUS = (0.005, 2.0)
GEAR_TOL = 0.02
#: Wheel-floor sliding friction below which the floor is called slippery.
LOW_FRICTION = 0.5
CONFIRM_SHARE = 0.25
#: Envelope ripple above which a Swedish wheel's roller ring is called polygonal.
RIPPLE_FLAG = 0.005


@dataclass
class Diagnosis:
    """One finding: cause, figures with and without it, whether confirmed, what to do."""

    name: str
    cause: str
    with_cause: dict[str, float] | None
    without_cause: dict[str, float] | None
    confirmed: bool | None
    change: str

    def line(self, unit: str = "% of path") -> str:
        """``cause: <worst manoeuvre> 62 % of path; with 0: 4.9 %`` style sentence."""
        if self.with_cause is None or self.without_cause is None:
            return f"{self.cause} (not confirmed by a counterfactual run). Change: {self.change}"
        w = max(self.with_cause, key=self.with_cause.__getitem__)
        status = "CONFIRMED" if self.confirmed else "not confirmed"
        if self.name == "noslip":
            status = ("a feature MJX/Warp lack; its effect on the figures is "
                      + ("large" if self.confirmed else "small"))
        return (f"{self.cause}: {w} {self.with_cause[w]:.1f} {unit}; without it: "
                f"{self.without_cause[w]:.1f} {unit} (worst over the manoeuvres: "
                f"{max(self.with_cause.values()):.1f} vs "
                f"{max(self.without_cause.values()):.1f}) - {status}. Change: {self.change}")

    def as_dict(self) -> dict:
        """For the JSON report."""
        return {"name": self.name, "cause": self.cause, "with": self.with_cause,
                "without": self.without_cause, "confirmed": self.confirmed,
                "change": self.change, "line": self.line()}


def _scores(a: Audit, outcomes: list[Outcome]) -> dict[str, float]:
    return {o.manoeuvre.name: judged(o.figures, a.span) for o in outcomes}


def _counterfactual(a: Audit, name: str, cause: str, change: str, model: mujoco.MjModel,
                    only: tuple[str, ...] | None = None) -> Diagnosis:
    before = {k: v for k, v in _scores(a, a.outcomes).items() if only is None or k in only}
    after = _scores(a, drive_all(a, model, only))
    gain = max(before.values()) - max(after.values())
    ok = gain > CONFIRM_POINTS and gain > CONFIRM_SHARE * max(before.values())
    return Diagnosis(name, cause, before, after, ok, change)


def _passive_joints(a: Audit) -> dict[str, list[int]]:
    """Passive joints of the wheels by role: rollers, castors, balls, undriven wheels."""
    m = a.drive.model
    roles: dict[str, list[int]] = {}
    driven = {ch.joint for ch in (*a.drive.spin.values(), *a.drive.steer.values())}
    for w in a.wheels.wheels:
        bodies = subtree_bodies(m, int(m.jnt_bodyid[w.joint]))
        joints = [j for b in bodies for j in range(m.body_jntadr[b],
                                                   m.body_jntadr[b] + m.body_jntnum[b])]
        if w.steer_joint >= 0:
            joints.append(w.steer_joint)
        for j in joints:
            if j in driven:
                continue
            role = ("roller" if w.kind == "swedish" and j != w.joint else
                    "castor" if w.kind == "castor" else "ball" if w.kind == "ball" else
                    "undriven wheel")
            roles.setdefault(role, []).append(j)
    return roles


def _braked(m: mujoco.MjModel, joints: list[int]) -> tuple[list[int], str]:
    dofs = [int(m.jnt_dofadr[j]) + k for j in joints
            for k in range({0: 6, 1: 3}.get(int(m.jnt_type[j]), 1))]
    parts = []
    for field_, label in (("dof_frictionloss", "frictionloss"), ("dof_damping", "damping"),
                          ("dof_armature", "armature")):
        vals = getattr(m, field_)[dofs]
        if np.any(vals > 0):
            parts.append(f"{label} {np.max(vals):g}")
    return dofs, ", ".join(parts)


def passive_friction(a: Audit, say: Callable[[str], None]) -> list[Diagnosis]:
    """Passive wheel joints with friction loss, damping or armature."""
    out = []
    for role, joints in _passive_joints(a).items():
        dofs, what = _braked(a.drive.model, joints)
        if not what:
            continue
        m = copy.deepcopy(a.drive.model)
        m.dof_frictionloss[dofs] = 0.0
        m.dof_damping[dofs] = 0.0
        m.dof_armature[dofs] = 0.0
        say(f"counterfactual: {role} joints without {what}")
        out.append(_counterfactual(
            a, f"{role} friction", f"{len(joints)} {role} joint(s) with {what}",
            f"set frictionloss, damping and armature of the {role} joints to 0 (a default "
            f"class often gives them to every joint; give the {role}s their own class)", m))
    return out


def cylinder_wheels(a: Audit, say: Callable[[str], None]) -> list[Diagnosis]:
    """Standard wheels with cylinder colliders: test them as ellipsoids (R, R, half-width)."""
    m0 = a.drive.model
    cyl = [g for w in a.wheels.wheels if w.kind in ("fixed", "steerable", "castor")
           for g in w.geoms if int(m0.geom_type[g]) == int(mujoco.mjtGeom.mjGEOM_CYLINDER)]
    if not cyl:
        return []
    m = copy.deepcopy(m0)
    for g in cyl:
        r, h = m.geom_size[g, 0], m.geom_size[g, 1]
        m.geom_type[g] = mujoco.mjtGeom.mjGEOM_ELLIPSOID
        m.geom_size[g] = (r, r, h)
    turning = tuple(o.manoeuvre.name for o in a.outcomes if o.manoeuvre.twist[2] != 0.0)
    say("counterfactual: wheel cylinders as ellipsoids")
    return [_counterfactual(
        a, "cylinder wheels", f"{len(cyl)} cylinder wheel collider(s) (a cylinder on a plane "
        f"touches at up to 4 rim points, which scrub in a turn)",
        "collide the wheels as ellipsoids (R, R, half-width) or capsules/spheres, keep the "
        "cylinder as a visual geom", m, turning or None)]


def scrubbing_wheels(a: Audit, say: Callable[[str], None]) -> list[Diagnosis]:
    """Undriven fixed wheels off the drive axle: test them frictionless."""
    if not a.wheels.scrubbing:
        return []
    m = copy.deepcopy(a.drive.model)
    top = int(m.geom_priority.max()) + 1  # the higher priority sets the contact's condim
    for w in a.wheels.scrubbing:
        for g in w.geoms:
            m.geom_condim[g] = 1
            m.geom_priority[g] = top
    names = ", ".join(repr(w.name) for w in a.wheels.scrubbing)
    say(f"counterfactual: {names} frictionless")
    turning = tuple(o.manoeuvre.name for o in a.outcomes if o.manoeuvre.twist[2] != 0.0)
    return [_counterfactual(
        a, "caster without swivel", f"undriven wheel(s) {names} on a plain hinge off the "
        f"drive axle (a caster without a swivel joint scrubs sideways in every turn)",
        "give the caster wheel a vertical swivel hinge (offset behind its axle) or make it "
        "a ball caster", m, turning or None)]


def actuator_radius(a: Audit, say: Callable[[str], None]) -> list[Diagnosis]:
    """Wheel servos whose gear is a length other than the rolling radius.

    A servo with gear g on a wheel joint has length ``g q``: a gear other than MuJoCo's
    default 1 that is a length (:data:`GEAR_RADIUS` bounds) is the radius its author
    assumed, so that ``ctrl`` is the wheel's ground speed. Commanded that way the wheel
    moves at ``(R/g) ctrl``. The run "with the cause" commands ``ctrl = v`` as the author
    meant; the audit's own runs (``ctrl = g ω``, exact) are the ones without it.
    """
    lo, hi = GEAR_RADIUS
    bad = {n: ch for n, ch in a.drive.spin.items()
           if lo <= abs(ch.gear) <= hi and abs(ch.gear) != 1.0
           and abs(abs(ch.gear) / _radius(a, n) - 1) > GEAR_TOL}
    if not bad:
        return []
    drive = dataclasses.replace(a.drive, spin={
        n: dataclasses.replace(ch, gear=np.sign(ch.gear) * _radius(a, n)) if n in bad else ch
        for n, ch in a.drive.spin.items()})
    names = ", ".join(f"{n} gear {ch.gear:g} m vs rolling radius {_radius(a, n):.4g} m"
                      for n, ch in bad.items())
    say("counterfactual: wheels commanded in ground speed through their gear")
    after = _scores(a, drive_all(a, drive=drive))
    before = _scores(a, a.outcomes)
    gain = max(after.values()) - max(before.values())
    ok = gain > CONFIRM_POINTS and gain > CONFIRM_SHARE * max(after.values())
    return [Diagnosis("actuator radius", f"wheel servo(s) assume a radius other than the "
                      f"rolling radius ({names}) when ctrl is taken as ground speed", after,
                      before, ok, "set each wheel servo's gear to the rolling radius (or "
                      "command it in rad/s with gear 1)")]


def _radius(a: Audit, name: str) -> float:
    return next(w.radius for w in a.wheels.wheels if w.name == name)


def low_friction(a: Audit, say: Callable[[str], None]) -> list[Diagnosis]:
    """Wheel-floor contacts with a sliding friction below :data:`LOW_FRICTION`.

    MuJoCo takes the contact's friction from the geom of higher ``priority``, else the
    larger of the two (the default ``solmix`` rule for friction). The counterfactual sets
    the floor's and the wheels' sliding friction to 1.
    """
    m0 = a.drive.model
    floor = [g for g in range(m0.ngeom) if m0.geom_bodyid[g] == 0 and
             (m0.geom_contype[g] or m0.geom_conaffinity[g])]
    wheel_geoms = [g for w in a.wheels.wheels if w.kind != "ball" for g in w.geoms]

    def mu(g1: int, g2: int) -> float:
        p1, p2 = m0.geom_priority[g1], m0.geom_priority[g2]
        if p1 != p2:
            return float(m0.geom_friction[g1 if p1 > p2 else g2, 0])
        return float(max(m0.geom_friction[g1, 0], m0.geom_friction[g2, 0]))

    low = min((mu(f, g) for f in floor for g in wheel_geoms), default=1.0)
    if low >= LOW_FRICTION:
        return []
    m = copy.deepcopy(m0)
    m.geom_friction[floor + wheel_geoms, 0] = 1.0
    say("counterfactual: wheel-floor friction 1")
    return [_counterfactual(
        a, "low friction", f"wheel-floor sliding friction {low:g} (the wheels slip under "
        f"the drive torque)", "use a floor or tyre friction near 1 (rubber on a floor), or "
        "drive more gently", m)]


def timestep(a: Audit, say: Callable[[str], None]) -> list[Diagnosis]:
    """Wheel contacts whose time constant is below two timesteps."""
    m0 = a.drive.model
    dt = float(m0.opt.timestep)
    geoms = [g for w in a.wheels.wheels for g in w.geoms]
    tcs = [float(m0.geom_solref[g, 0]) for g in geoms if m0.geom_solref[g, 0] > 0]
    if not tcs or min(tcs) >= 2.0 * dt:
        return []
    tc = min(tcs)
    m = copy.deepcopy(m0)
    m.opt.timestep = tc / 2.0
    worst = a.worst().manoeuvre.name
    say(f"counterfactual: timestep {tc / 2:g} s")
    return [_counterfactual(
        a, "timestep", f"timestep {dt:g} s above half the wheel contacts' time constant "
        f"{tc:g} s (MuJoCo softens such contacts to 2 timesteps)",
        f"use a timestep of at most {tc / 2:g} s, or a contact time constant of at least "
        f"{2 * dt:g} s", m, (worst,))]


def noslip(a: Audit, say: Callable[[str], None]) -> list[Diagnosis]:
    """The noslip solver: MJX and MuJoCo Warp have none."""
    n = int(a.drive.model.opt.noslip_iterations)
    if n == 0:
        return []
    m = copy.deepcopy(a.drive.model)
    m.opt.noslip_iterations = 0
    say("counterfactual: noslip off")
    d = _counterfactual(
        a, "noslip", f"noslip_iterations {n} (the noslip solver is not in MJX or MuJoCo "
        f"Warp: the model cannot move to them as it is)",
        "drop noslip_iterations if the figures without it are acceptable", m)
    return [d]


def ripple(a: Audit, say: Callable[[str], None]) -> list[Diagnosis]:
    """Swedish wheels whose roller ring is a polygon (geometry only)."""
    poly = [w for w in a.wheels.wheels if w.kind == "swedish" and w.ripple > RIPPLE_FLAG]
    if not poly:
        return []
    worst = max(poly, key=lambda w: w.ripple)
    measured = max(o.figures.ripple_pct for o in a.outcomes)
    return [Diagnosis("roller envelope", f"polygonal roller envelope: {100 * worst.ripple:.2f} %"
                      f" geometric ripple of the rolling radius ({worst.name!r}); measured axle "
                      f"height ripple up to {measured:.2f} %", None, None, None,
                      "more or longer rollers (overlapping rows) to round the envelope")]


PITFALLS = (passive_friction, cylinder_wheels, scrubbing_wheels, low_friction,
            actuator_radius, timestep, noslip, ripple)


def diagnose(a: Audit, say: Callable[[str], None]) -> list[Diagnosis]:
    """Every pitfall found in ``a``'s model, each with its counterfactual."""
    return [d for check in PITFALLS for d in check(a, say)]
