"""Which geoms of a compiled model can touch something: contact bits or explicit pairs.

MuJoCo makes a contact between two geoms either from their bits (``(contype₁ &
conaffinity₂) | (contype₂ & conaffinity₁) ≠ 0``, found by the broadphase) or from an
explicit ``<pair>`` that names both (no bits needed). A geom with both bits zero that a
pair names is a collider all the same; code that looks for colliders asks here.
"""

from __future__ import annotations

import mujoco
import numpy as np


def pair_geoms(model: mujoco.MjModel) -> set[int]:
    """Ids of the geoms named by an explicit ``<pair>``."""
    return {int(g) for g in (*model.pair_geom1, *model.pair_geom2)}


def is_collider(model: mujoco.MjModel, geom: int, paired: set[int] | None = None) -> bool:
    """True if ``geom`` has a contact bit set or is named by a ``<pair>``.

    Args:
        model: the compiled model.
        geom: geom id.
        paired: :func:`pair_geoms` of ``model`` when asking for many geoms (else read here).
    """
    if model.geom_contype[geom] or model.geom_conaffinity[geom]:
        return True
    return geom in (pair_geoms(model) if paired is None else paired)


def colliders(model: mujoco.MjModel) -> list[int]:
    """Ids of every geom that :func:`is_collider`, ascending."""
    paired = pair_geoms(model)
    return [g for g in range(model.ngeom) if is_collider(model, g, paired)]


def pair_with(model: mujoco.MjModel, geom1: int, geom2: int) -> int | None:
    """Id of the explicit pair of the two geoms (either order), None if there is none."""
    for p in range(model.npair):
        if {int(model.pair_geom1[p]), int(model.pair_geom2[p])} == {geom1, geom2}:
            return p
    return None


#: A floor contact whose friction along the wheel's axle is below this fraction of the
#: friction across it leaves the wheel free sideways (:func:`free_sideways`).
SIDEWAYS_FRICTION_RATIO = 0.1


def free_sideways(data: mujoco.MjData, geoms: set[int], axle: np.ndarray) -> bool:
    """Whether a wheel's ``geoms`` slide freely along its ``axle`` where they touch.

    True when they have contacts (in ``data``) and each has a frame tangent along the
    axle (within 5°) whose friction is below :data:`SIDEWAYS_FRICTION_RATIO` of the
    other tangent's: an explicit pair's anisotropic friction on a collider whose contact
    frame follows its axis (MuJoCo's plane-capsule), the rollers' freedom in the contact.
    """
    found = False
    for i in range(data.ncon):
        c = data.contact[i]
        if c.geom1 in geoms or c.geom2 in geoms:
            along = np.abs(c.frame.reshape(3, 3)[1:] @ axle)
            k = int(np.argmax(along))
            if (along[k] < np.cos(np.radians(5.0))
                    or c.friction[k] >= SIDEWAYS_FRICTION_RATIO * c.friction[1 - k]):
                return False
            found = True
    return found
