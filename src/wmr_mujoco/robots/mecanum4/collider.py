"""``mecanum4``'s rolling model from its own roller colliders (docs/mecanum.md §3).

:func:`realised_twist` is the mean chassis twist under the ideal wheel rates
``θ̇ = H(γ) ν_cmd`` with the rolling constraint of the colliders the model is built with
(:mod:`wmr_mujoco.robots.mecanum4.contact`): the ellipsoid's (or sphere's) exact lowest
point; the ideal profile's for ``roller_shape="profile"``; for capsules, which the
contact module does not cover, the pitch-averaged model
(:func:`wmr_mujoco.robots.roller_wheels.pitch_averaged.realised_twist_map`).
:func:`effective_layout` is a wheel layout whose rolling rows give that same twist, for
the step model (:mod:`.traction`).
"""

from __future__ import annotations

import functools

import numpy as np

from wmr_mujoco.robots.mecanum4 import contact as mc
from wmr_mujoco.robots.mecanum4 import roller as mr
from wmr_mujoco.robots.mecanum4.geometry import layout
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels import pitch_averaged as pa

#: A wheel whose commanded rate is below this (rad/s) is at rest.
AT_REST = 1e-9


def roller_geometry(params: MecanumParams) -> mc.RollerGeometry | None:
    """The contact module's description of the colliders; None for capsules."""
    p = params
    if p.roller_shape == "capsule":
        return None
    axis = {"ellipsoid": mr.ellipsoid_semi_axis(p.wheel_radius, p.roller_half_width,
                                                p.roller_angle),
            "sphere": p.roller_half_width, "profile": None}[p.roller_shape]
    return mc.RollerGeometry(p.wheel_radius, p.roller_half_width, p.roller_angle,
                             p.rollers_per_wheel, axis)


def realised_twist(params: MecanumParams, command: np.ndarray) -> np.ndarray:
    """Mean twist ``ν̄`` under the ideal wheel rates ``H(γ) ν_cmd`` (module docstring).

    Linear in the command's size for a fixed direction (the rows do not depend on the
    rates), so it is computed once per direction.
    """
    nu = np.asarray(command, float)
    size = float(np.linalg.norm(nu))
    if size == 0.0:
        return np.zeros(3)
    direction = tuple(np.round(nu / size, 12).tolist())
    return size * np.asarray(_unit_twist(params, direction))


@functools.lru_cache(maxsize=256)
def _unit_twist(params: MecanumParams, direction: tuple[float, ...]) -> tuple[float, ...]:
    lay = layout(params)
    nu = np.asarray(direction)
    rates = ok.wheel_jacobian(lay) @ nu
    geometry = roller_geometry(params)
    if geometry is None:
        out = pa.realised_twist_map(lay, params.rollers_per_wheel,
                                    np.abs(rates) > AT_REST) @ nu
    else:
        out = mc.mean_twist(geometry, lay.positions, np.sign(lay.roller_angles), rates)
    return tuple(float(v) for v in out)


def effective_layout(params: MecanumParams, command: np.ndarray) -> ok.WheelLayout:
    """A layout whose rows give :func:`realised_twist` under the ideal wheel rates.

    Start from the pitch-averaged layout ``L̄`` (γ̄ on the turning wheels), whose twist is
    ``S ν_cmd``, and scale each component of the twist by ``c_k = ν̄_k / (S ν_cmd)_k``
    (1 where ``(S ν_cmd)_k`` is 0): ``H_e = H(L̄) C⁻¹`` gives ``H_e⁺ = C H(L̄)⁺``. With every
    wheel driving along +x and one radius R, ``H(L̄)`` row i is
    ``[1, t_i, x_i t_i − y_i] / R`` (``t_i = tan γ̄_i``) and ``H(L̄) C⁻¹`` is the row of
    the layout with radius ``R c_u``, ``tan γ_e,i = t_i c_u / c_v`` and wheels at
    ``(x_i c_v / c_r, y_i c_u / c_r)``: the colliders' effective rolling radius, roller
    angle and contact lever.

    Raises:
        ValueError: a layout whose wheels do not all drive along +x with one radius.
    """
    lay = layout(params)
    if np.any(lay.drive_angles != 0.0) or np.ptp(lay.radii) != 0.0:
        raise ValueError("effective_layout needs wheels driving along +x with one radius")
    nu = np.asarray(command, float)
    rates = ok.wheel_jacobian(lay) @ nu
    averaged = pa.averaged_layout(lay, params.rollers_per_wheel, np.abs(rates) > AT_REST)
    base = np.linalg.pinv(ok.wheel_jacobian(averaged)) @ rates
    target = realised_twist(params, nu)
    scale = np.ones(3)
    moving = np.abs(base) > 1e-12
    scale[moving] = target[moving] / base[moving]
    cu, cv, cr = scale
    return ok.WheelLayout(averaged.positions * np.array([cv / cr, cu / cr]),
                          averaged.drive_angles,
                          np.arctan(np.tan(averaged.roller_angles) * cu / cv),
                          averaged.radii * cu)
