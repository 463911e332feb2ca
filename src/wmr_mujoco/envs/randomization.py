"""Domain randomisation of a compiled model: floor friction, masses, wheel radius, servo gain.

Every quantity is scaled by a factor drawn uniformly from its band ``(lo, hi)`` at each
reset, from the environment's seeded generator, starting from the nominal model each time:

* ``friction``: the sliding friction of every geom and contact pair (MuJoCo takes the
  larger of the two geoms' coefficients, so scaling all of them scales the contact's
  ``μ``); one factor per episode.
* ``mass``: each body's mass and rotational inertia (a uniform change of density), one
  factor per body; ``mj_setConst`` then recomputes the derived constants.
* ``wheel_radius``: the radius of each wheel's colliding geom (sphere, cylinder, or the
  equal axes of an ellipsoid), one factor per wheel; the robot settles onto the new
  wheels in its first steps.
* ``servo_gain``: each actuator's gain and affine bias (``kv`` of a velocity servo,
  ``kp, kv`` of a steering servo, the torque constant of a motor), one factor per actuator.

The bands (:class:`~wmr_mujoco.robots.learning.Bands`, declared in each robot's registry
entry) must lie inside :data:`~wmr_mujoco.robots.learning.PHYSICAL` (otherwise
``ValueError``).
"""

from __future__ import annotations

from collections.abc import Sequence

import mujoco
import numpy as np

from wmr_mujoco.robots.learning import PHYSICAL, Band, Bands

__all__ = ["PHYSICAL", "Band", "Bands", "Randomizer", "wheel_geoms"]


def wheel_geoms(model: mujoco.MjModel, wheels: Sequence[str]) -> list[tuple[int, np.ndarray]]:
    """``(geom id, mask of its size entries that are the radius)`` of each wheel's collider.

    Raises:
        ValueError: a wheel whose colliding geoms are not spheres, cylinders or ellipsoids,
            or that touches the floor through other bodies (rollers).
    """
    out = []
    for name in wheels:
        body = model.jnt_bodyid[model.joint(name).id]
        n_before = len(out)
        for g in np.flatnonzero(model.geom_bodyid == body):
            if not (model.geom_contype[g] or model.geom_conaffinity[g]):
                continue
            kind, size = model.geom_type[g], model.geom_size[g]
            if kind == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
                mask = np.isclose(size, size.max())
            elif kind in (mujoco.mjtGeom.mjGEOM_SPHERE, mujoco.mjtGeom.mjGEOM_CYLINDER):
                mask = np.array([True, False, False])
            else:
                raise ValueError(f"wheel {name!r} collides through a geom of type "
                                 f"{mujoco.mjtGeom(kind).name}; its radius cannot be "
                                 "randomised (set wheel_radius=None)")
            out.append((int(g), mask))
        if len(out) == n_before:
            raise ValueError(f"wheel {name!r} has no colliding geom of its own (it rolls on "
                             "rollers); its radius cannot be randomised (set "
                             "wheel_radius=None)")
    return out


class Randomizer:
    """Draws and applies the bands to one compiled model (module docstring)."""

    _FIELDS = ("geom_friction", "pair_friction", "body_mass", "body_inertia", "geom_size",
               "geom_rbound", "geom_aabb", "actuator_gainprm", "actuator_biasprm")

    def __init__(self, model: mujoco.MjModel, bands: Bands, wheels: Sequence[str]) -> None:
        self.model, self.bands = model, bands
        self.wheels = wheel_geoms(model, wheels) if bands.wheel_radius else []
        self.nominal = {f: getattr(model, f).copy() for f in self._FIELDS}

    def restore(self, data: mujoco.MjData | None = None) -> None:
        """Put the nominal values back."""
        for f, value in self.nominal.items():
            getattr(self.model, f)[:] = value
        if data is not None:
            mujoco.mj_setConst(self.model, data)

    def apply(self, rng: np.random.Generator, data: mujoco.MjData) -> dict[str, np.ndarray]:
        """Restore the nominal model, draw new factors and apply them; return the factors."""
        m, b, nom = self.model, self.bands, self.nominal
        self.restore()
        drawn: dict[str, np.ndarray] = {}
        if b.friction:
            f = drawn["friction"] = rng.uniform(*b.friction, size=1)
            m.geom_friction[:, 0] = nom["geom_friction"][:, 0] * f
            m.pair_friction[:, :2] = nom["pair_friction"][:, :2] * f
        if b.mass:
            f = drawn["mass"] = rng.uniform(*b.mass, size=m.nbody)
            f[0] = 1.0  # the world
            m.body_mass[:] = nom["body_mass"] * f
            m.body_inertia[:] = nom["body_inertia"] * f[:, None]
        if b.wheel_radius and self.wheels:
            f = drawn["wheel_radius"] = rng.uniform(*b.wheel_radius, size=len(self.wheels))
            for (g, mask), k in zip(self.wheels, f, strict=True):
                m.geom_size[g, mask] = nom["geom_size"][g, mask] * k
                # Bounding sphere and box only for the broad phase: grown with the radius
                # (never shrunk, so that no contact is missed whatever axes the radius is).
                grow = max(float(k), 1.0)
                m.geom_rbound[g] = nom["geom_rbound"][g] * grow
                m.geom_aabb[g, 3:] = nom["geom_aabb"][g, 3:] * grow
        if b.servo_gain:
            f = drawn["servo_gain"] = rng.uniform(*b.servo_gain, size=m.nu)
            m.actuator_gainprm[:, 0] = nom["actuator_gainprm"][:, 0] * f
            m.actuator_biasprm[:, 1:3] = nom["actuator_biasprm"][:, 1:3] * f[:, None]
        mujoco.mj_setConst(m, data)
        return drawn
