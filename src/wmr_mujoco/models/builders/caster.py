"""A passive ball caster: a sphere on a ball joint in a socket on the chassis."""

from __future__ import annotations

from collections.abc import Sequence

from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.models.params.wheeled import BallCasterParams

SOCKET_RGBA = (0.6, 0.6, 0.65, 0.35)
BALL_RGBA = (0.85, 0.85, 0.88, 1.0)
#: Contact bits of the ball: ``contype = 0`` and ``conaffinity = 1``. Two geoms collide
#: when ``(contype₁ & conaffinity₂) | (contype₂ & conaffinity₁)`` is non-zero, so the
#: ball touches the floor (contype 1) and nothing whose contype is 0; its socket has no
#: collider at all, so ball and socket never collide.
BALL_CONTYPE = 0
BALL_CONAFFINITY = 1


def add_ball_caster(parent: mjcf.Element, name: str, caster: BallCasterParams,
                    pos: Sequence[float], mount_z: float | None = None) -> mjcf.Element:
    """Add a ball of radius r_c on a frictionless ball joint centred at ``pos``.

    The ball's inertia is the uniform sphere's ``(2/5) m r_c²`` about every axis. The
    joint has no damping, friction loss or armature, and the collider has condim 3 (no
    torsional or rolling friction), so the ball rolls and spins freely in every
    direction; with ``caster.rolling_friction`` it has condim 6 and the collision
    class's torsional and rolling coefficients resist spinning and rolling. The socket
    is a translucent visual cup on ``parent``.

    Args:
        parent: the chassis body.
        name: name of the ball body, its joint (``name``) and collider
            (``{name}_collision``).
        caster: ball radius and mass.
        pos: ball centre in the parent frame.
        mount_z: height of the chassis underside in the parent frame; when given, a
            visual stem joins the socket's top to it.

    Returns:
        The ball body.

    """
    r = caster.radius
    parent.add("geom", dclass="visual", type="cylinder", size=(1.15 * r, 0.6 * r),
               pos=(pos[0], pos[1], pos[2] + 0.6 * r), rgba=SOCKET_RGBA)
    if mount_z is not None and mount_z > pos[2] + 1.2 * r:
        parent.add("geom", dclass="visual", type="cylinder", size=(0.5 * r,),
                   fromto=(pos[0], pos[1], pos[2] + 1.2 * r, pos[0], pos[1], mount_z),
                   rgba=common.METAL_RGBA)
    body = parent.add("body", name=name, pos=list(pos))
    body.add("joint", name=name, type="ball")
    body.add("inertial", pos=(0, 0, 0), mass=caster.mass, diaginertia=(caster.inertia,) * 3)
    body.add("geom", name=f"{name}_collision", dclass="collision", type="sphere",
             size=(r,), contype=BALL_CONTYPE, conaffinity=BALL_CONAFFINITY,
             condim=6 if caster.rolling_friction else None)
    body.add("geom", dclass="visual", type="sphere", size=(0.98 * r,), rgba=BALL_RGBA)
    body.add("geom", dclass="visual", type="box", size=(0.2 * r, 0.2 * r, 0.99 * r),
             rgba=common.MARK_RGBA)
    return body
