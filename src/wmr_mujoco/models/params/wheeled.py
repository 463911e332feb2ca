"""Parts shared by the caster-supported robots (differential drive, the steered classes).

The ball caster, the chassis-size and caster-fit checks and the default wheel, drive and
simulation settings; each robot's own parameters are in its folder
(``wmr_mujoco.robots.<robot>.params``).

Same conventions as :mod:`wmr_mujoco.models.params` (SI units, radians, frozen dataclasses that
check their ranges in ``__post_init__`` and raise ``ValueError`` naming field, value and
valid range). Wheels reuse :class:`~wmr_mujoco.models.params.WheelParams`; settings reuse
:class:`~wmr_mujoco.models.params.DriveParams` and :class:`~wmr_mujoco.models.params.SimParams`.

A ball caster is a uniform sphere of radius ``r_c`` and mass ``m_c`` on a frictionless
ball joint at its centre::

    I_c = (2/5) m_c r_c²

Rolling without slip on the floor, a ball pushed at its centre by force F accelerates at
``a = F / (m_c + I_c / r_c²) = F / ((7/5) m_c)``: seen from the chassis it is a point mass
``(7/5) m_c`` at its centre (:attr:`BallCasterParams.effective_mass`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from wmr_mujoco.models.params.fields import _check_positive_fields, _check_range
from wmr_mujoco.models.params.parts import DriveParams, SimParams, WheelParams

#: Densest engineering metal a caster ball could be made of (tungsten), kg/m³.
MAX_BALL_DENSITY = 2.0e4
#: Largest chassis plate edge, m: a modelling bound, ten times the default robots' size.
MAX_CHASSIS_EDGE = 5.0
#: Largest distance of a wheel or caster from the chassis origin, m (modelling bound,
#: the reach of a 4 m long platform, as :data:`MAX_CHASSIS_EDGE`).
MAX_REACH = 2.0


def _check_chassis_size(obj: object) -> None:
    """Each edge of ``obj.chassis_size`` in (0, :data:`MAX_CHASSIS_EDGE`] m."""
    size = obj.chassis_size  # type: ignore[attr-defined]
    if not all(0.0 < s <= MAX_CHASSIS_EDGE for s in size):
        raise ValueError(f"{type(obj).__name__}.chassis_size = {size!r} is not physical; "
                         f"valid range of each edge is (0, {MAX_CHASSIS_EDGE:g}] m")

#: Wheel, fork and drive shared by the three robots (the tricycle's proven sizes).
_WHEEL = WheelParams(radius=0.08, width=0.03, mass=0.4)
_SIM = SimParams()
_DRIVE = DriveParams(wheel_kv=10.0, wheel_armature=0.01, wheel_torque_limit=10.0,
                     steer_kp=100.0, steer_kv=0.5, steer_angle_limit=1.4)


@dataclass(frozen=True)
class BallCasterParams:
    """A passive ball caster: a sphere in a socket on the chassis.

    Attributes:
        radius: ball radius r_c, in [0.002, 0.2] m: the sizes ball transfer units are
            made in (2 mm to 200 mm balls).
        mass: ball mass m_c, in (0, ρ_max (4/3) π r_c³] kg: physically at most a solid
            ball of the densest engineering metal, tungsten (:data:`MAX_BALL_DENSITY`).
        rolling_friction: False (default): contact condim 3, sliding friction only, so
            the ball rolls and spins freely. True: condim 6, MuJoCo's torsional and
            rolling friction act too: a torque ``|τ_roll| ≤ μ_r N`` (``μ_r``, m, the
            third ``friction`` coefficient) opposes rolling, giving a steady drag
            ``F = μ_r N / r_c`` on the chassis.

    """

    radius: float = 0.02
    mass: float = 0.05
    rolling_friction: bool = False

    def __post_init__(self) -> None:
        _check_positive_fields(self)
        _check_range(self, "radius", 0.002, 0.2, low_inclusive=True)
        _check_range(self, "mass", 0.0, MAX_BALL_DENSITY * 4.0 / 3.0 * math.pi
                     * self.radius**3)

    @property
    def inertia(self) -> float:
        """Moment of inertia of the uniform ball about any diameter, ``(2/5) m r²``."""
        return 0.4 * self.mass * self.radius**2

    @property
    def effective_mass(self) -> float:
        """Mass the rolling ball adds at its centre, ``m + I/r² = (7/5) m``."""
        return self.mass + self.inertia / self.radius**2


_CASTER = BallCasterParams()


def _check_caster_fits(obj: object, wheel: WheelParams, caster: BallCasterParams) -> None:
    if caster.radius >= wheel.radius:
        raise ValueError(f"{type(obj).__name__}.caster.radius = {caster.radius!r} must be "
                         f"smaller than the wheel radius; valid range is (0, {wheel.radius:g})")
