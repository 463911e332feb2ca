"""Campion class of a wheeled robot from its wheels: rolling-constraint ranks.

Campion, Bastin & d'Andréa-Novel (*IEEE T-RA* 12(1), 1996), in the form of Siegwart &
Nourbakhsh (§3.3). Body twist ``ν = (u, v, r)`` of the chassis origin O in the chassis
frame. A standard wheel whose contact lies at body position ``p = (p_x, p_y)`` with
horizontal axle direction ``a = (a_x, a_y)`` forbids motion of its contact point along
the axle (no sliding)::

    a · (u − r p_y, v + r p_x) = 0   ⇔   [a_x, a_y, a_y p_x − a_x p_y] ν = 0.

Stacking the rows of the fixed wheels (C1f, constant) and of the centred steerable wheels
(C1s(βs), the axle turning with β) gives ``C1(βs) = [C1f; C1s(βs)]``. Off-centred castors,
Swedish wheels (γ ≠ 90°) and ball wheels add no such row: their own free joint (castor
swivel, rollers, ball) absorbs any sideways motion. Then::

    δm = dim N(C1) = 3 − rank C1(βs),    δs = rank C1s(βs),    δM = δm + δs,

with the ranks taken at generic steering angles (the largest over random βs). The five
classes (δm, δs) are (3,0), (2,0), (2,1), (1,1), (1,2). When generic angles give
rank C1 = 3 the steering must be coordinated (one ICR); Campion's δs is then
``2 − rank C1f`` (the steering angles keep rank C1 ≤ 2), and the result says so.

The wheels themselves (:class:`Wheel`) are found in a compiled MuJoCo model by
:mod:`wmr_mujoco.models.classify`; this module is the theory only and needs no MuJoCo.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

#: Relative singular-value tolerance of the ranks (settled geometry is exact to µm).
RANK_RTOL = 1e-3
#: Random steering samples for the generic ranks.
STEER_SAMPLES = 8
FIVE_CLASSES = ((3, 0), (2, 0), (2, 1), (1, 1), (1, 2))
KINDS = ("fixed", "steerable", "castor", "swedish", "ball")


@dataclass(frozen=True)
class Wheel:
    """One wheel found in a model.

    Attributes:
        name: the spin joint (hub for Swedish wheels, the ball joint for ball wheels).
        kind: one of :data:`KINDS`.
        position: contact-point position (x, y) in the chassis frame, m (wheel centre
            or steering axis projected on the floor).
        axle: horizontal unit axle direction (x, y) in the chassis frame.
        steer_joint: the vertical hinge of steerable and castor wheels.
        offset: horizontal distance from the steering axis to the wheel centre, m.
        roller_angle: γ of a Swedish wheel, rad (median over its rollers).
        radius: height of the wheel centre above the floor, m.
    """

    name: str
    kind: str
    position: tuple[float, float]
    axle: tuple[float, float]
    steer_joint: str | None = None
    offset: float = 0.0
    roller_angle: float | None = None
    radius: float = 0.0


@dataclass(frozen=True)
class Classification:
    """Result of :func:`classify`.

    ``robot_class`` is ``(δm, δs)`` when it is one of Campion's five classes and None
    otherwise; ``reason`` then says why the model is outside the theory.
    """

    wheels: tuple[Wheel, ...]
    delta_m: int
    delta_s: int
    c1: np.ndarray = field(repr=False)
    notes: tuple[str, ...] = ()
    reason: str = ""

    @property
    def manoeuvrability(self) -> int:
        """δM = δm + δs."""
        return self.delta_m + self.delta_s

    @property
    def robot_class(self) -> tuple[int, int] | None:
        """``(δm, δs)``, or None outside the theory."""
        return None if self.reason else (self.delta_m, self.delta_s)

    def wheel_counts(self) -> dict[str, int]:
        """Number of wheels of each kind present."""
        return {k: n for k in KINDS if (n := sum(w.kind == k for w in self.wheels))}


def sliding_row(position: tuple[float, float], axle: np.ndarray) -> np.ndarray:
    """``[a_x, a_y, a_y p_x − a_x p_y]``: no sliding along the axle at ``p``."""
    px, py = position
    return np.array([axle[0], axle[1], axle[1] * px - axle[0] * py])


def _rank(m: np.ndarray) -> int:
    if m.size == 0:
        return 0
    s = np.linalg.svd(m, compute_uv=False)
    return int(np.sum(s > RANK_RTOL * max(s[0], 1e-12)))


def _rotate(a: tuple[float, float], beta: float) -> np.ndarray:
    c, s = np.cos(beta), np.sin(beta)
    return np.array([c * a[0] - s * a[1], s * a[0] + c * a[1]])


def classify_wheels(wheels: tuple[Wheel, ...], notes: tuple[str, ...] = (),
                    seed: int = 0) -> Classification:
    """δm, δs and the class from a list of wheels (see the module docstring)."""
    fixed = np.array([sliding_row(w.position, np.array(w.axle)) for w in wheels
                      if w.kind == "fixed"]).reshape(-1, 3)
    steer = [w for w in wheels if w.kind == "steerable"]
    rng = np.random.default_rng(seed)
    rank_f = _rank(fixed)
    rank_s = rank_c1 = rank_f
    c1 = fixed
    for _ in range(STEER_SAMPLES if steer else 1):
        betas = rng.uniform(-np.pi, np.pi, len(steer))
        c1s = np.array([sliding_row(w.position, _rotate(w.axle, b))
                        for w, b in zip(steer, betas, strict=True)]).reshape(-1, 3)
        rs, rc = _rank(c1s), _rank(np.vstack([fixed, c1s]))
        if rc >= rank_c1 or rs > rank_s:
            c1 = np.vstack([fixed, c1s])
        rank_s = max(rank_s, rs) if steer else 0
        rank_c1 = max(rank_c1, rc)
    notes_out = list(notes)
    reason = ""
    if rank_f >= 2:
        reason = (f"fixed wheels on more than one axle (rank C1f = {rank_f}): the robot "
                  f"{'cannot move' if rank_f == 3 else 'can only turn about one point'}")
        delta_s = 0
        delta_m = 3 - rank_f
    elif rank_c1 == 3:
        delta_s = 2 - rank_f
        delta_m = 3 - rank_f - delta_s
        notes_out.append(f"{len(steer)} steerable wheels reach rank C1 = 3 at generic angles:"
                         f" the steering must be coordinated (one ICR)")
    else:
        delta_s = rank_s
        delta_m = 3 - rank_c1
    if not reason and (delta_m, delta_s) not in FIVE_CLASSES:
        reason = f"(δm, δs) = ({delta_m}, {delta_s}) is none of the five classes"
    if not reason and any(n.endswith("outside the theory") for n in notes_out):
        reason = next(n for n in notes_out if n.endswith("outside the theory"))
    return Classification(tuple(wheels), delta_m, delta_s, c1, tuple(notes_out), reason)

def summary(c: Classification) -> str:
    """One line: wheels by kind, δm, δs, δM, class or reason."""
    kinds = ", ".join(f"{n} {k}" for k, n in c.wheel_counts().items())
    gam = sorted({round(float(np.degrees(abs(w.roller_angle))), 1) for w in c.wheels
                  if w.roller_angle is not None})
    if gam:
        kinds += f" (|γ| = {', '.join(f'{g:g}°' for g in gam)})"
    cls = f"({c.delta_m},{c.delta_s})" if c.robot_class else f"outside the theory: {c.reason}"
    return (f"wheels: {kinds}; δm = {c.delta_m}, δs = {c.delta_s}, "
            f"δM = {c.manoeuvrability}; class {cls}")
