"""Parameters of the Whipple benchmark bicycle (Meijaard et al. 2007, Table 1).

Frame of the paper (used for every field here): origin at the rear-wheel contact point of
the upright bicycle, ``x`` forward, ``y`` to the right, ``z`` DOWN. Heights of centres of
mass are therefore negative. Inertia tensors are tensor elements (products of inertia
``I_xz = -∫ x z dm``) about the body's centre of mass in that frame. By the bicycle's
left-right symmetry ``I_xy = I_yz = 0``, so a frame tensor is given by
``(I_xx, I_yy, I_zz, I_xz)``; a wheel is axisymmetric and given by its diametral and axial
inertia ``(I_xx, I_yy)`` (``I_zz = I_xx``).

MuJoCo's world is z-up with ``y`` to the left: the map is the rotation by π about ``x``,
``P = diag(1, -1, -1)``: positions ``(x, y, z) -> (x, -y, -z)``, tensors ``I -> P I Pᵀ``,
which keeps the diagonal and ``I_yz`` and flips the signs of ``I_xz`` and ``I_xy``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np

from wmr_mujoco.models.params import (
    MAX_WHEEL_MASS,
    MAX_WHEEL_RADIUS,
    SIM_PAIR_FIELDS,
    SimParams,
    _check_choice,
    _check_count,
    _check_positive_fields,
    _check_range,
    _check_types,
)

#: Largest gravity, N/kg: Jupiter's, 24.8 N/kg at its cloud tops, the strongest of any
#: planet in the solar system.
MAX_GRAVITY = 25.0
#: Largest trail magnitude, m: the steer axis meets the floor within a wheel diameter of
#: the front contact on any bicycle (motorcycles and choppers stay under 0.2 m).
MAX_TRAIL = 1.0

#: Integrators the study compares (MuJoCo names).
INTEGRATORS = ("implicitfast", "implicit", "RK4", "Euler")


@dataclass(frozen=True)
class WhippleSimParams(SimParams):
    """Simulation settings of the Whipple model: :class:`SimParams` and more.

    Attributes:
        timestep: integration step, s.
        integrator: MuJoCo integrator, one of :data:`INTEGRATORS`.
        contact_timeconst: ``solref`` time constant of the wheel-floor contact, s.
            MuJoCo clamps it to at least ``2 · timestep`` (``refsafe``).
        contact_dampratio: ``solref`` damping ratio.
        impratio: ratio of frictional to normal constraint impedance (elliptic cones);
            larger makes the no-slip (rolling) constraint stiffer.
        solimp_dmax: impedance ``d`` of the contact (``solimp = (d, d, ...)``): the
            fraction of a constraint violation the solver removes; 1 is a hard contact.
        friction: sliding friction coefficient wheel-floor.
        wheel_half_width: half-width ``b`` of the ellipsoid ``(R, b, R)`` that stands for
            a knife-edge wheel, m. Its crown radius ``b²/R`` is the tyre's lateral
            radius of curvature: the contact point moves sideways by ``b² sin φ / R`` at
            lean φ, where a knife edge would not move.
        noslip_iterations: MuJoCo's no-slip post-solver iterations (0: off).

    Bounds: ``timestep`` in (0, 0.01] s, a tenth of the fastest benchmark mode's time
    constant (the capsize/weave eigenvalues reach about 10 1/s over the studied speeds);
    ``contact_dampratio`` in (0, 10] (past critical damping, 1, a larger ratio only slows
    the contact); ``solimp_dmax`` in (0.5, 0.9999]: MuJoCo's impedance is a fraction below
    1, and below 0.5 the wheel sinks by half its load deflection; ``wheel_half_width`` in
    (0, 0.05] m, a bicycle tyre's half-width at most (knife-edge model: thinner is closer);
    ``noslip_iterations`` integers [0, 100] (numerical, no physical bound).

    """

    timestep: float = 0.001
    integrator: str = "implicit"
    contact_timeconst: float = 0.002
    contact_dampratio: float = 1.0
    impratio: float = 10.0
    solimp_dmax: float = 0.99
    friction: float = 1.0
    wheel_half_width: float = 0.001
    noslip_iterations: int = 0

    def __post_init__(self) -> None:
        super().__post_init__()  # the types of every field, then SimParams's ranges
        _check_range(self, "timestep", 0.0, 0.01)
        _check_choice(self, "integrator", INTEGRATORS)
        _check_range(self, "contact_dampratio", 0.0, 10.0)
        _check_range(self, "solimp_dmax", 0.5, 0.9999)
        _check_range(self, "wheel_half_width", 0.0, 0.05)
        _check_count(self, "noslip_iterations", 0, 100)


def _frame_tensor(i: tuple[float, float, float, float]) -> np.ndarray:
    """The 3×3 tensor of ``(I_xx, I_yy, I_zz, I_xz)`` (``I_xy = I_yz = 0``)."""
    ixx, iyy, izz, ixz = i
    return np.array([[ixx, 0.0, ixz], [0.0, iyy, 0.0], [ixz, 0.0, izz]])


@dataclass(frozen=True)
class WhippleParams:
    """The benchmark bicycle: rear wheel R, rear frame B, front frame H, front wheel F.

    Defaults are the benchmark's Table 1. Paper frame (x forward, y right, z down, origin
    at the rear contact); lean φ about ``x`` and steer δ about the steer axis, both
    positive to the right.

    Attributes:
        wheelbase: w, distance between the wheel contact points, m.
        trail: c, the steer axis meets the floor ``c`` ahead of the front contact, m.
        head_angle: λ, tilt of the steer axis from the vertical, rad, in (-π/2, π/2).
        gravity: g, N/kg.
        rear_radius, rear_mass: r_R, m_R.
        rear_inertia: (I_Rxx, I_Ryy), diametral and axial inertia of the rear wheel.
        rear_frame_com: (x_B, z_B) of the rear frame's centre of mass (z_B < 0: above
            the floor).
        rear_frame_mass: m_B.
        rear_frame_inertia: (I_Bxx, I_Byy, I_Bzz, I_Bxz) about the rear frame's CoM.
        front_frame_com: (x_H, z_H).
        front_frame_mass: m_H.
        front_frame_inertia: (I_Hxx, I_Hyy, I_Hzz, I_Hxz) about the front frame's CoM.
        front_radius, front_mass: r_F, m_F.
        front_inertia: (I_Fxx, I_Fyy).
        sim: simulation settings of the MuJoCo model.

    Bounds, physical: masses, lengths, ``gravity`` and the wheels' inertias positive;
    wheel radii at most :data:`~wmr_mujoco.models.params.MAX_WHEEL_RADIUS` = 2.5 m and
    wheel masses at most :data:`~wmr_mujoco.models.params.MAX_WHEEL_MASS` = 1e4 kg (the
    largest tyres built); ``gravity`` at most :data:`MAX_GRAVITY` = 25 N/kg (Jupiter);
    ``|trail|`` at most :data:`MAX_TRAIL` = 1 m; ``head_angle`` strictly inside
    (-π/2, π/2) (a horizontal steer axis never meets the floor); the two wheels fit in
    the wheelbase, ``r_R + r_F < w``; centres of mass above the floor (``z < 0``); every
    inertia tensor positive definite with principal moments satisfying ``A + B >= C``
    (a real body). The frame masses have no physical upper bound of their own.

    """

    #: Fields its model does not use (the knife-edge wheels keep the collision class's
    #: contact): ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = SIM_PAIR_FIELDS

    wheelbase: float = 1.02
    trail: float = 0.08
    head_angle: float = math.pi / 10.0
    gravity: float = 9.81
    rear_radius: float = 0.3
    rear_mass: float = 2.0
    rear_inertia: tuple[float, float] = (0.0603, 0.12)
    rear_frame_com: tuple[float, float] = (0.3, -0.9)
    rear_frame_mass: float = 85.0
    rear_frame_inertia: tuple[float, float, float, float] = (9.2, 11.0, 2.8, 2.4)
    front_frame_com: tuple[float, float] = (0.9, -0.7)
    front_frame_mass: float = 4.0
    front_frame_inertia: tuple[float, float, float, float] = (0.05892, 0.06, 0.00708,
                                                              -0.00756)
    front_radius: float = 0.35
    front_mass: float = 3.0
    front_inertia: tuple[float, float] = (0.1405, 0.28)
    sim: WhippleSimParams = WhippleSimParams()

    def __post_init__(self) -> None:
        name = type(self).__name__
        _check_types(self)  # before any range: a message that names the wrong type
        for f in ("rear_radius", "front_radius"):
            _check_range(self, f, 0.0, MAX_WHEEL_RADIUS)
        for f in ("rear_mass", "front_mass"):
            _check_range(self, f, 0.0, MAX_WHEEL_MASS)
        _check_range(self, "gravity", 0.0, MAX_GRAVITY)
        _check_positive_fields(self, exclude=("trail", "head_angle"))
        _check_range(self, "trail", -MAX_TRAIL, MAX_TRAIL, low_inclusive=True)
        _check_range(self, "head_angle", -math.pi / 2.0, math.pi / 2.0, high_inclusive=False)
        for f in ("rear_frame_com", "front_frame_com"):
            if not getattr(self, f)[1] < 0.0:
                raise ValueError(f"{name}.{f} = {getattr(self, f)!r} is not physical; "
                                 f"valid range is z in (-inf, 0) (z points down: the "
                                 f"centre of mass must be above the floor)")
        for f in ("rear_inertia", "front_inertia", "rear_frame_inertia",
                  "front_frame_inertia"):
            self._check_inertia(f)
        # Wheels "beyond the frame": the two wheels must fit within the wheelbase
        # without overlapping (each wheel's rim stops short of the other's), i.e.
        # r_R + r_F < w; a larger radius would put one wheel through the other.
        if self.rear_radius + self.front_radius >= self.wheelbase:
            raise ValueError(
                f"{name}.rear_radius + front_radius = "
                f"{self.rear_radius + self.front_radius!r} reaches beyond the frame: the "
                f"wheels would overlap; valid range is (0, wheelbase = {self.wheelbase:g})")

    def _check_inertia(self, field: str) -> None:
        """Positive definite, and satisfying the triangle inequality of a real body."""
        value = getattr(self, field)
        tensor = self.tensor(field)
        eig = np.linalg.eigvalsh(tensor) if np.all(np.isfinite(tensor)) else [np.nan] * 3
        ok = bool(np.all(np.isfinite(eig)) and min(eig) > 0.0)
        if ok:
            a, b, c = sorted(eig)
            ok = a + b >= c * (1.0 - 1e-9)
        if not ok:
            raise ValueError(
                f"{type(self).__name__}.{field} = {value!r} is not the inertia of a real "
                f"body: its principal moments {np.round(eig, 6).tolist()} must all lie in "
                f"(0, inf) and satisfy A + B >= C (positive definite tensor)")

    def tensor(self, field: str) -> np.ndarray:
        """The 3×3 inertia tensor of ``field`` in the paper frame (z down)."""
        value = getattr(self, field)
        if len(value) == 2:
            ixx, iyy = value
            return np.diag([ixx, iyy, ixx])
        return _frame_tensor(value)

    def with_sim(self, **changes: object) -> WhippleParams:
        """These parameters with some simulation settings changed (validated again)."""
        return replace(self, sim=replace(self.sim, **changes))

    @property
    def total_mass(self) -> float:
        """m_T, the mass of the four bodies."""
        return self.rear_mass + self.rear_frame_mass + self.front_frame_mass + self.front_mass


#: The benchmark bicycle with the default settings (a frozen, shared default argument).
DEFAULT_PARAMS = WhippleParams()
