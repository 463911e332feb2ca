"""Support functions of MuJoCo collision geoms, and a wheel's rolling envelope from them.

The support function of a convex body K in the unit direction d is
``h_K(d) = max_{x ∈ K} x · d``. For the primitive geoms in their own frame (half-sizes
``s``; ``d = (d_x, d_y, d_z)`` expressed in that frame)::

    sphere      s₀
    capsule     s₀ + s₁ |d_z|
    cylinder    s₀ √(1 − d_z²) + s₁ |d_z|
    ellipsoid   √((s₀ d_x)² + (s₁ d_y)² + (s₂ d_z)²)
    box         s₀|d_x| + s₁|d_y| + s₂|d_z|
    mesh        max over the vertices v of v · d

A wheel (a hub and whatever turns with it, rollers included) spinning about the unit axis
n through the point c touches a level floor with the point of its colliders farthest from
the axis in the downward direction. Turning the wheel by θ is turning that direction by
−θ in the wheel, so the distance from the axis to the floor is
``h(θ) = max_g [(x_g − c) · d(θ) + h_g(d(θ))]`` with ``d(θ) = cos θ e₁ + sin θ e₂`` ⊥ n.
By Cauchy's formula the perimeter of a convex curve is ``∫₀^{2π} h(θ) dθ``, so the
distance the wheel rolls per turn is ``2π h̄``: the rolling radius is the mean ``h̄`` and
the envelope's ripple is ``(max h − min h) / h̄`` (zero for a round wheel, a few per cent
for a ring of cylinder rollers).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

#: Directions sampled around the axle; fine enough for 60 rollers (6 per roller pitch).
ENVELOPE_SAMPLES = 720
_G = mujoco.mjtGeom


def geom_support(model: mujoco.MjModel, data: mujoco.MjData, geom: int,
                 directions: np.ndarray) -> np.ndarray | None:
    """``h(d)`` of ``geom`` about its own centre, for world unit directions ``(k, 3)``.

    The geom is posed as in ``data``. None for a type without a support function (plane,
    height field, SDF).
    """
    d = directions @ data.geom_xmat[geom].reshape(3, 3)  # rows: d in the geom frame
    s = model.geom_size[geom]
    t = model.geom_type[geom]
    if t == _G.mjGEOM_SPHERE:
        return np.full(len(d), s[0])
    if t == _G.mjGEOM_CAPSULE:
        return s[0] + s[1] * np.abs(d[:, 2])
    if t == _G.mjGEOM_CYLINDER:
        return s[0] * np.sqrt(np.clip(1.0 - d[:, 2] ** 2, 0.0, 1.0)) + s[1] * np.abs(d[:, 2])
    if t == _G.mjGEOM_ELLIPSOID:
        return np.sqrt(((d * s) ** 2).sum(axis=1))
    if t == _G.mjGEOM_BOX:
        return np.abs(d) @ s
    if t == _G.mjGEOM_MESH:
        m = model.geom_dataid[geom]
        adr, num = model.mesh_vertadr[m], model.mesh_vertnum[m]
        return (model.mesh_vert[adr:adr + num] @ d.T).max(axis=0)
    return None


def lowest_point(model: mujoco.MjModel, data: mujoco.MjData, geoms: Sequence[int]) -> float:
    """Lowest z reached by ``geoms`` as posed in ``data`` (``inf`` if none has a support)."""
    down = np.array([[0.0, 0.0, -1.0]])
    low = np.inf
    for g in geoms:
        h = geom_support(model, data, g, down)
        if h is not None:
            low = min(low, float(data.geom_xpos[g][2] - h[0]))
    return low


@dataclass(frozen=True)
class Envelope:
    """A wheel's rolling envelope about its axle.

    Attributes:
        radius: rolling radius, mean of h(θ), m.
        low: smallest h(θ), m.
        high: largest h(θ), m.
    """

    radius: float
    low: float
    high: float

    @property
    def ripple(self) -> float:
        """(max h − min h) / mean h, a fraction."""
        return (self.high - self.low) / self.radius if self.radius > 0 else float("nan")


def envelope(model: mujoco.MjModel, data: mujoco.MjData, geoms: Sequence[int],
             centre: np.ndarray, axis: np.ndarray, samples: int = ENVELOPE_SAMPLES
             ) -> Envelope | None:
    """The envelope of ``geoms`` turning about ``axis`` through ``centre`` (world frame).

    None if no geom has a support function.
    """
    n = axis / np.linalg.norm(axis)
    e1 = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    theta = np.linspace(0.0, 2.0 * np.pi, samples, endpoint=False)
    dirs = np.outer(np.cos(theta), e1) + np.outer(np.sin(theta), e2)
    h = np.full(samples, -np.inf)
    for g in geoms:
        hg = geom_support(model, data, g, dirs)
        if hg is not None:
            h = np.maximum(h, (data.geom_xpos[g] - centre) @ dirs.T + hg)
    if not np.isfinite(h).all():
        return None
    return Envelope(float(h.mean()), float(h.min()), float(h.max()))
