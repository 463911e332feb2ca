"""Explicit wheel-floor pairs with the remedy of a sliding soft contact, for any robot.

A wheel whose contact slides is pushed off the floor by its friction rows
(``docs/floor-contact.md``); the remedy (:func:`~wmr_mujoco.models.builders.common.\
sliding_pair_kwargs`, ``docs/rolling-disc.md`` § 8) needs an explicit ``<pair>`` per wheel
collider, since a geom has no ``solreffriction``. :func:`wheel_floor_pairs` makes the
``scene_extras`` that adds them for a robot from its builder alone.

The remedy sets the model's one ``impratio`` to ``SLIDING_GRIP / d``
(:func:`~wmr_mujoco.models.builders.common.sliding_impratio`), so every collider that
touches the floor gets a pair with the same impedance ``d``, the ball casters included.
A friction row's regulariser is its normal row's ``(1 − d)/d`` over ``impratio``, so its
stiffness ``D_f`` scales as ``impratio · d/(1 − d)``: a caster left at the collision
class's ``d ≈ 0.95`` had ``impratio · d ≈ 9500`` (the wheels: 10), friction rows about
10⁴ times stiffer than the wheels'. C MuJoCo (float64) runs that, but Newton's Hessian
``M + Jᵀ D J`` then holds an almost free direction (the ball's spin about the vertical,
inertia ``(2/5) m r²``) beside diagonal entries ``D_f r²`` some 10⁷ times larger, near
float32's resolution: MuJoCo Warp's float32 Cholesky lost the last pivot within 0.1 s of
driving, NaN (``python -m wmr_mujoco.bench.batch_parity`` measures it, ``docs/batch.md``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from dm_control import mjcf

from wmr_mujoco.models.builders.common import sliding_impratio, sliding_pair_kwargs
from wmr_mujoco.models.params import SimParams

#: Least ``t_c/Δt`` of :func:`wheel_floor_pairs`. The normal gain λ of the robots with a
#: few wheels is under MuJoCo's 2 at rest (``tests/models/builders/test_common.py``
#: computes it at every robot's defaults), but in motion 2 steps still let the wheels of
#: the robots with casters leave the floor under random steps; 3 keep them down (the
#: random-steps family, ``docs/floor-contact.md``).
WHEEL_PAIR_STEPS = 3


def wheel_collider_names(robot: mjcf.RootElement) -> list[str]:
    """Names of the wheel colliders of a built robot.

    Every named ``collision``-class geom of a body jointed to its parent by hinges only
    (a wheel, what :class:`~wmr_mujoco.sim.floor_contact.WheelMap` reads; not a ball
    caster, :func:`caster_collider_names`, nor the chassis on its free joint).
    """
    names = []
    for geom in robot.find_all("geom"):
        cls = getattr(geom.dclass, "dclass", geom.dclass)  # an element or its name
        if geom.name is None or cls != "collision":
            continue
        body = geom.parent
        joints = body.get_children("joint")
        if joints and not body.get_children("freejoint") and all(
                (j.type or "hinge") == "hinge" for j in joints):
            names.append(geom.name)
    return names


def caster_collider_names(robot: mjcf.RootElement) -> list[str]:
    """Names of the ball-caster colliders of a built robot.

    Every named ``collision``-class geom of a body jointed to its parent by one ball joint
    (:func:`~wmr_mujoco.models.builders.caster.add_ball_caster`).
    """
    names = []
    for geom in robot.find_all("geom"):
        cls = getattr(geom.dclass, "dclass", geom.dclass)
        if geom.name is None or cls != "collision":
            continue
        joints = geom.parent.get_children("joint")
        if len(joints) == 1 and joints[0].type == "ball":
            names.append(geom.name)
    return names


def wheel_floor_pairs(build: Callable[[Any], mjcf.RootElement]
                      ) -> Callable[[mjcf.RootElement, Any], None]:
    """The ``scene_extras`` of a robot built by ``build`` whose wheels take the remedy.

    The returned ``extras(scene, params)`` reads ``params.sim`` (:class:`SimParams`).
    With ``sim.floor_impedance`` > 0 it adds to the scene an explicit pair of every
    wheel collider (:func:`wheel_collider_names` of ``build(params)``) and every ball
    caster collider (:func:`caster_collider_names`, with the caster geom's own ``condim``:
    6 with rolling friction) with the ``floor``, with
    :func:`~wmr_mujoco.models.builders.common.sliding_pair_kwargs` at
    :data:`WHEEL_PAIR_STEPS` (MuJoCo makes no contact-bit contact for a geom pair a
    ``<pair>`` names), and sets the model's ``impratio`` to
    :func:`~wmr_mujoco.models.builders.common.sliding_impratio`. With 0 it adds nothing.
    """
    def extras(scene: mjcf.RootElement, params: Any) -> None:
        sim: SimParams = params.sim
        d = sim.floor_impedance
        if d == 0.0:
            return
        kwargs = sliding_pair_kwargs(sim, d, steps=WHEEL_PAIR_STEPS)
        robot = build(params)
        for name in wheel_collider_names(robot):
            scene.contact.add("pair", geom1="floor", geom2=name, **kwargs)
        for name in caster_collider_names(robot):
            condim = robot.find("geom", name).condim or kwargs["condim"]
            scene.contact.add("pair", geom1="floor", geom2=name, **{**kwargs, "condim": condim})
        scene.option.impratio = sliding_impratio(d)

    return extras
