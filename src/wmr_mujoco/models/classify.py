"""Find the wheels of a compiled MuJoCo model and compute its Campion class.

``python -m wmr_mujoco.models.classify SCENE.xml ...`` prints each model's class; ``wmr
info`` shows it for every robot. The rank theory is :mod:`wmr_mujoco.analytic.campion`;
this module reads the model (any MJCF with a floor, including foreign ones).

How wheels are found (heuristics):
    1. Settle the model ``SETTLE_TIME`` s at zero controls; the floor is the collision
       geom(s) of the world body (a horizontal plane).
    2. The chassis is the top-level body (child of the world) carrying the colliders
       that touch the floor; its own joints (free joint, or slides and a yaw hinge) are
       the base's degrees of freedom and are not wheel joints. Its z axis is "vertical".
    3. For every collider body below the chassis, the joints on the path from the
       chassis down to it form its *chain*. Hinges are vertical (|axis·z| > cos 10°) or
       horizontal (|axis·z| < sin 10°); anything else is tilted (unsupported). Chains:
       ``[H]`` fixed wheel; ``[V, H]`` steerable wheel, *centred* if the vertical axis
       passes within ``CENTRED_TOL`` of the wheel centre (the H anchor) and an
       off-centred *castor* otherwise (offset d reported); ``[H, hinge]`` Swedish wheel
       (hub H, roller hinge at any orientation, since it turns with the hub), roller
       angle γ = angle of the roller axis to the wheel plane, signed against the
       rolling direction; ``[ball]`` ball wheel (sphere on a ball joint). An ``[H]`` wheel
       whose floor contacts are nearly frictionless along its axle (an explicit pair's
       anisotropic friction, the contact frame along a capsule) is Swedish with γ = 0:
       its rollers are in the contact
       (:func:`~wmr_mujoco.models.colliders.free_sideways`).
    4. A wheel rolls: a body of such a chain is a wheel (or a roller) only if one of its
       colliders is *round* about the joint it spins on (:func:`round_about`: a sphere,
       or a cylinder, capsule or ellipsoid of revolution whose symmetry axis is that
       joint's axis, centred on the axis; a ball wheel's sphere centred on the ball
       joint; a mesh whose rolling envelope about the joint ripples by at most
       ``ROUND_RIPPLE``, :mod:`wmr_mujoco.models.support`). A limb on a horizontal hinge
       (a humanoid's leg, an arm's link lying on the floor) is not round about it and is
       no wheel (a note names it if it touches).
    5. Wheels are grouped by their spin joint (the hub for Swedish wheels); a wheel none
       of whose colliders touches the floor after settling is an error.
"""

from __future__ import annotations

import copy
from collections.abc import Mapping
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.analytic.campion import Classification, Wheel, classify_wheels, summary
from wmr_mujoco.models.colliders import colliders, free_sideways, is_collider
from wmr_mujoco.models.support import envelope

SETTLE_TIME = 0.5
#: |cos| of the angle to the vertical above which a hinge counts as vertical.
VERTICAL_COS = np.cos(np.radians(10.0))
#: Horizontal distance between steering axis and wheel centre below which the wheel is
#: centred, m.
CENTRED_TOL = 2e-3
#: A round collider's centre lies within this fraction of its bounding radius of the
#: joint axis, and its symmetry axis within ROUND_ANGLE of the joint's.
ROUND_TOL = 0.02
ROUND_ANGLE = np.radians(2.0)
#: Envelope ripple, (max h − min h) / mean h, above which a mesh turning about a joint is
#: not round (a tessellated tyre of n facets ripples 1 − cos(π/n): 0.5 % for 32; a limb
#: seen from its joint, from about 0 to its length: over 100 %).
ROUND_RIPPLE = 0.25


def round_about(model: mujoco.MjModel, data: mujoco.MjData, g: int, j: int) -> bool:
    """Whether geom ``g`` is a body of revolution about joint ``j``'s axis (it can roll).

    A hinge: a sphere, or a cylinder, capsule or ellipsoid with two equal radii whose
    symmetry axis is parallel to the hinge (within ``ROUND_ANGLE``), in each case
    centred on the hinge's axis line (within ``ROUND_TOL`` of the geom's bounding
    radius); a mesh whose rolling envelope about the hinge ripples by at most
    ``ROUND_RIPPLE``. A ball joint: a sphere centred on the joint. Boxes and planes are
    never round here.
    """
    kind = int(model.geom_type[g])  # a NumPy int is not found by `in` on MuJoCo's enums
    centre, anchor, axis = data.geom_xpos[g], data.xanchor[j], data.xaxis[j]
    d = centre - anchor
    tol = ROUND_TOL * float(model.geom_rbound[g]) + 1e-9
    if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_BALL:
        return kind == mujoco.mjtGeom.mjGEOM_SPHERE and float(np.linalg.norm(d)) <= tol
    if float(np.linalg.norm(d - (d @ axis) * axis)) > tol:
        return False
    if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        return True
    if kind == mujoco.mjtGeom.mjGEOM_MESH:
        env = envelope(model, data, [g], anchor, axis)
        return env is not None and env.ripple <= ROUND_RIPPLE
    frame = data.geom_xmat[g].reshape(3, 3)
    if kind in (mujoco.mjtGeom.mjGEOM_CYLINDER, mujoco.mjtGeom.mjGEOM_CAPSULE):
        symmetric = [2]
    elif kind == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
        size = model.geom_size[g]
        symmetric = [k for k in range(3)
                     if np.isclose(*np.delete(size, k), rtol=1e-6)]  # the other two equal
    else:
        return False
    return any(abs(frame[:, k] @ axis) >= np.cos(ROUND_ANGLE) for k in symmetric)


def _name(model: mujoco.MjModel, objtype: mujoco.mjtObj, i: int) -> str:
    return mujoco.mj_id2name(model, objtype, i) or f"#{i}"


def _settle(model: mujoco.MjModel) -> mujoco.MjData:
    data = mujoco.MjData(model)
    for _ in range(max(1, round(SETTLE_TIME / model.opt.timestep))):
        mujoco.mj_step(model, data)
    if not (np.isfinite(data.qpos).all() and np.isfinite(data.qvel).all()):
        raise ValueError("the model diverged while settling at zero controls; "
                         "cannot find its wheels")
    return data


def _floor(model: mujoco.MjModel, data: mujoco.MjData) -> tuple[set[int], float]:
    floor = {g for g in colliders(model) if model.geom_bodyid[g] == 0}
    if not floor:
        raise ValueError("the model has no floor: no collision geom on the world body "
                         "(load the scene, not the robot file)")
    for g in floor:
        if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE and \
                abs(data.geom_xmat[g].reshape(3, 3)[2, 2]) < VERTICAL_COS:
            raise ValueError(f"floor plane {_name(model, mujoco.mjtObj.mjOBJ_GEOM, g)!r} is "
                             f"not horizontal; the classifier needs a level floor")
    z = max(float(data.geom_xpos[g][2]) for g in floor
            if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE) if any(
        model.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE for g in floor) else 0.0
    return floor, z


def _ancestors(model: mujoco.MjModel, body: int) -> list[int]:
    """Bodies from the top-level ancestor down to ``body`` (world excluded)."""
    path = [body]
    while model.body_parentid[path[-1]] != 0:
        path.append(int(model.body_parentid[path[-1]]))
    return path[::-1]


def _is_collider(model: mujoco.MjModel, g: int) -> bool:
    return is_collider(model, g)


@dataclass
class _Link:
    joint: int
    kind: str  # "V", "H", "T" (tilted hinge), "ball", "slide"


def _chain(model: mujoco.MjModel, data: mujoco.MjData, path: list[int]) -> list[_Link]:
    """Joints from below the chassis ``path[0]`` down to ``path[-1]``.

    Vertical and horizontal are judged against the chassis z axis, so that a chassis
    that tipped while settling is still read as built.
    """
    up = data.xmat[path[0]].reshape(3, 3)[:, 2]
    links = []
    for b in path[1:]:
        for j in range(model.body_jntadr[b], model.body_jntadr[b] + model.body_jntnum[b]):
            jt = model.jnt_type[j]
            if jt == mujoco.mjtJoint.mjJNT_HINGE:
                cz = abs(data.xaxis[j] @ up)
                kind = "V" if cz > VERTICAL_COS else ("H" if cz < np.sin(np.radians(10.0))
                                                       else "T")
            elif jt == mujoco.mjtJoint.mjJNT_BALL:
                kind = "ball"
            elif jt == mujoco.mjtJoint.mjJNT_SLIDE:
                kind = "slide"
            else:
                kind = "free"
            links.append(_Link(j, kind))
    return links


def _horizontal(v: np.ndarray) -> np.ndarray:
    h = np.array([v[0], v[1]])
    n = np.linalg.norm(h)
    return h / n if n > 1e-12 else h


def find_wheels(model: mujoco.MjModel) -> tuple[tuple[Wheel, ...], tuple[str, ...]]:
    """The wheels of ``model`` and notes on anything outside the theory.

    Raises:
        ValueError: no floor, no collider touching the floor, several robots, a chassis
            welded to the world, no wheels, or a wheel without floor contact.
    """
    data = _settle(model)
    floor, floor_z = _floor(model, data)
    touching: set[int] = set()
    for i in range(data.ncon):
        g1, g2 = data.contact.geom[i]
        if g1 in floor and g2 not in floor:
            touching.add(int(model.geom_bodyid[g2]))
        elif g2 in floor and g1 not in floor:
            touching.add(int(model.geom_bodyid[g1]))
    if not touching:
        raise ValueError("nothing touches the floor after settling: no wheels to classify")
    tops = {_ancestors(model, b)[0] for b in touching}
    if len(tops) > 1:
        names = ", ".join(sorted(_name(model, mujoco.mjtObj.mjOBJ_BODY, t) for t in tops))
        raise ValueError(f"several top-level bodies touch the floor ({names}); classify "
                         f"one robot at a time")
    chassis = tops.pop()
    if model.body_jntnum[chassis] == 0:
        raise ValueError(f"chassis {_name(model, mujoco.mjtObj.mjOBJ_BODY, chassis)!r} is "
                         f"welded to the world; a mobile robot needs a free or planar base")
    rot = data.xmat[chassis].reshape(3, 3)
    origin = data.xpos[chassis]

    def local(v: np.ndarray, point: bool) -> np.ndarray:
        return rot.T @ (v - origin if point else v)

    notes: list[str] = []
    groups: dict[int, dict] = {}
    for b in range(1, model.nbody):
        geoms = [g for g in range(model.body_geomadr[b], model.body_geomadr[b]
                                  + model.body_geomnum[b]) if _is_collider(model, g)]
        path = _ancestors(model, b)
        if not geoms or path[0] != chassis:
            continue
        links = _chain(model, data, path)
        kinds = [lk.kind for lk in links]
        if not links:
            if b in touching:
                notes.append(f"rigid collider on body {_name(model, mujoco.mjtObj.mjOBJ_BODY, b)!r}"
                             f" slides on the floor: a skid, outside the theory")
            continue
        if kinds == ["ball"]:
            key, kind = links[0].joint, "ball"
        elif kinds == ["H"]:
            key, kind = links[0].joint, "fixed"
        elif kinds == ["V", "H"]:
            key, kind = links[1].joint, "steer"
        elif len(kinds) == 2 and kinds[0] == "H" and kinds[1] in ("H", "V", "T"):
            # The roller axes turn with the hub: only the hub must be horizontal.
            key, kind = links[0].joint, "swedish"
        else:
            key, kind = links[-1].joint, "unsupported:" + "-".join(kinds)
        spin = links[-1].joint  # what the collider rolls on: wheel, roller or ball joint
        if not kind.startswith("unsupported") and not any(
                round_about(model, data, g, spin) for g in geoms):
            if b in touching:
                notes.append(f"body {_name(model, mujoco.mjtObj.mjOBJ_BODY, b)!r} turns on "
                             f"{_name(model, mujoco.mjtObj.mjOBJ_JOINT, spin)!r} but no "
                             "collider of it is round about that axis: not a wheel")
            continue
        g = groups.setdefault(key, {"kind": kind, "links": links, "bodies": [],
                                    "touch": False})
        g["bodies"].append(b)
        g["touch"] |= b in touching
    if not groups:
        why = "; ".join(notes) or ("what touches the floor is the chassis itself")
        raise ValueError(f"no wheels: no collider below the chassis "
                         f"{_name(model, mujoco.mjtObj.mjOBJ_BODY, chassis)!r} is round about "
                         f"a joint it turns on ({why})")
    wheels = []
    for key, g in groups.items():
        name = _name(model, mujoco.mjtObj.mjOBJ_JOINT, key)
        if not g["touch"]:
            raise ValueError(f"wheel {name!r} has no floor contact after settling "
                             f"(a wheel must rest on the floor)")
        links, kind = g["links"], g["kind"]
        if kind.startswith("unsupported"):
            chain = kind.split(":")[1]
            if chain == "T-H":  # a wheel hinge below a tilted steering hinge (a bicycle fork)
                tilt = np.degrees(np.arccos(min(1.0, abs(
                    data.xaxis[links[0].joint] @ data.xmat[chassis].reshape(3, 3)[:, 2]))))
                notes.append(f"wheel {name!r} steers about an axis tilted {tilt:.1f}° from the "
                             f"vertical (the theory's steering axes are vertical and its "
                             f"chassis does not lean): outside the theory")
            else:
                notes.append(f"joint chain {chain} at {name!r} is not a wheel type of the "
                             f"theory: outside the theory")
            continue
        centre = data.xanchor[key]
        radius = float(centre[2] - floor_z)
        if kind == "ball":
            p = local(centre, True)
            wheels.append(Wheel(name, "ball", (float(p[0]), float(p[1])), (0.0, 0.0),
                                radius=radius))
            continue
        axle = _horizontal(local(data.xaxis[key], False))
        if kind == "fixed":
            p = local(centre, True)
            geoms = {g for b in g["bodies"] for g in range(
                model.body_geomadr[b], model.body_geomadr[b] + model.body_geomnum[b])}
            free = free_sideways(data, geoms, data.xaxis[key])
            wheels.append(Wheel(name, "swedish" if free else "fixed", (float(p[0]), float(p[1])),
                                (float(axle[0]), float(axle[1])), radius=radius,
                                **({"roller_angle": 0.0} if free else {})))
        elif kind == "steer":
            sj = links[0].joint
            s_anchor, s_axis = data.xanchor[sj], data.xaxis[sj]
            d = centre - s_anchor
            d_perp = d - (d @ s_axis) * s_axis
            offset = float(np.linalg.norm(d_perp))
            foot = local(s_anchor + (floor_z - s_anchor[2]) / s_axis[2] * s_axis, True)
            wheels.append(Wheel(name, "steerable" if offset < CENTRED_TOL else "castor",
                                (float(foot[0]), float(foot[1])),
                                (float(axle[0]), float(axle[1])),
                                steer_joint=_name(model, mujoco.mjtObj.mjOBJ_JOINT, sj),
                                offset=offset, radius=radius))
        else:  # Swedish: hub links[0], rollers below
            n = data.xaxis[key]
            gammas = []
            for b in g["bodies"]:
                rj = _chain(model, data, _ancestors(model, b))[1].joint
                a = data.xaxis[rj]
                radial = data.xanchor[rj] - centre
                t = np.cross(n, radial)
                t /= np.linalg.norm(t)
                if a @ t < 0:
                    a = -a
                gammas.append(np.arctan2(a @ n, a @ t))
            gamma = float(np.median(gammas))
            if np.ptp(gammas) > np.radians(5.0):
                notes.append(f"rollers of {name!r} disagree on γ by "
                             f"{np.degrees(np.ptp(gammas)):.1f}°")
            p = local(centre, True)
            if abs(abs(gamma) - np.pi / 2) < np.radians(5.0):
                notes.append(f"Swedish wheel {name!r} has γ ≈ 90°: its rollers cannot roll "
                             f"sideways, it is a conventional wheel, outside the theory")
            wheels.append(Wheel(name, "swedish", (float(p[0]), float(p[1])),
                                (float(axle[0]), float(axle[1])), roller_angle=gamma,
                                radius=radius))
    if not wheels:
        raise ValueError("no wheels of a supported kind: " + "; ".join(notes))
    return tuple(wheels), tuple(notes)

def classify(model: mujoco.MjModel) -> Classification:
    """Find the wheels of a compiled model (with its floor) and compute its class.

    The model is copied; the caller's model is not changed.

    Raises:
        ValueError: see :func:`find_wheels`.
    """
    wheels, notes = find_wheels(copy.deepcopy(model))
    return classify_wheels(wheels, notes)


def class_table(models: Mapping[str, mujoco.MjModel]) -> str:
    """Markdown table: robot, wheels found, δm, δs, δM, class (or why it has none)."""
    rows = ["| robot | wheels found | δm | δs | δM | class |", "|---|---|---|---|---|---|"]
    for name, model in models.items():
        try:
            c = classify(model)
        except ValueError as err:
            rows.append(f"| {name} | none | | | | outside the theory: {err} |")
            continue
        kinds = ", ".join(f"{n} {k}" for k, n in c.wheel_counts().items())
        if c.robot_class is None:  # ranks of wheels the theory does not cover mean nothing
            rows.append(f"| {name} | {kinds} | | | | outside the theory: {c.reason} |")
            continue
        rows.append(f"| {name} | {kinds} | {c.delta_m} | {c.delta_s} | {c.manoeuvrability} "
                    f"| ({c.delta_m},{c.delta_s}) |")
    return "\n".join(rows)


def main(argv: list[str] | None = None) -> int:
    """``python -m wmr_mujoco.models.classify SCENE.xml ...``: print each model's class."""
    import sys

    paths = sys.argv[1:] if argv is None else argv
    if not paths:
        print("usage: python -m wmr_mujoco.models.classify SCENE.xml [...]")
        return 2
    status = 0
    for path in paths:
        try:
            c = classify(mujoco.MjModel.from_xml_path(path))
            print(f"{path}: {summary(c)}")
            for note in c.notes:
                print(f"  note: {note}")
        except ValueError as err:
            print(f"{path}: error: {err}")
            status = 1
    return status


if __name__ == "__main__":
    raise SystemExit(main())
