"""Read a user's MJCF file for the audit: check it, compile it, add a floor if it has none.

Everything here runs before any simulation, so that bad input fails at once with one
sentence naming the file (:class:`~wmr_mujoco.audit.errors.AuditInputError`).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import mujoco

from wmr_mujoco.audit.errors import AuditInputError
from wmr_mujoco.models.colliders import colliders
from wmr_mujoco.models.support import lowest_point

#: Largest MJCF file read, bytes (meshes are separate files; 64 MB of XML is no robot).
MAX_FILE_BYTES = 64 * 2**20
#: Name of the floor the audit adds to a robot file without one.
ADDED_FLOOR = "audit_floor"


@dataclass
class Scene:
    """A compiled scene ready for the audit.

    Attributes:
        path: the file read.
        spec: its :class:`mujoco.MjSpec`, with the added floor if any.
        model: ``spec`` compiled.
        floor_added: whether the audit added the floor (a robot file without one).
    """

    path: Path
    spec: mujoco.MjSpec
    model: mujoco.MjModel
    floor_added: bool


def _check_file(path: Path) -> None:
    if not path.exists():
        raise AuditInputError(f"{str(path)!r}: no such file; give an MJCF scene or robot file "
                              "(.xml)")
    if not path.is_file():
        raise AuditInputError(f"{str(path)!r} is not a file; give an MJCF scene or robot file")
    size = path.stat().st_size
    if size > MAX_FILE_BYTES:
        raise AuditInputError(f"{str(path)!r} is {size / 2**20:.0f} MiB; an MJCF file of at "
                              f"most {MAX_FILE_BYTES // 2**20} MiB is expected")
    with path.open("rb") as f:
        head = f.read(4096).decode("utf-8", errors="replace")
    if "<mujoco" not in head:
        raise AuditInputError(f"{str(path)!r} is not an MJCF file: no <mujoco> element in its "
                              "first 4 KiB (URDF and other formats are not read)")


def _compile(spec: mujoco.MjSpec, path: Path) -> mujoco.MjModel:
    try:
        return spec.compile()
    except Exception as err:  # MuJoCo's compiler errors are ValueError or mujoco errors
        raise AuditInputError(f"{str(path)!r} does not compile: "
                              f"{str(err).strip().splitlines()[0]}") from None


def has_floor(model: mujoco.MjModel) -> bool:
    """Whether a collision geom sits on the world body."""
    return any(model.geom_bodyid[g] == 0 for g in colliders(model))


def read_scene(path: Path | str) -> Scene:
    """Read, compile and (if needed) give a floor to the model in ``path``.

    A robot file without a floor gets a horizontal plane :data:`ADDED_FLOOR` at the
    height of its lowest collider (posed as built), so that it rests on it.

    Raises:
        AuditInputError: no such file, not MJCF, does not compile, or no floor and no
            collider to rest on one.
    """
    path = Path(path)
    _check_file(path)
    try:
        spec = mujoco.MjSpec.from_file(str(path))
    except Exception as err:
        raise AuditInputError(f"{str(path)!r} is not a valid MJCF file: "
                              f"{str(err).strip().splitlines()[0]}") from None
    model = _compile(spec, path)
    if has_floor(model):
        return Scene(path, spec, model, False)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    z = lowest_point(model, data, colliders(model))
    if z == float("inf"):
        raise AuditInputError(f"{str(path)!r} has no floor, and no collision geom that could "
                              "rest on one; give a scene with a floor or a robot with colliders")
    spec.worldbody.add_geom(name=ADDED_FLOOR, type=mujoco.mjtGeom.mjGEOM_PLANE,
                            size=[0.0, 0.0, 0.05], pos=[0.0, 0.0, z])
    return Scene(path, spec, _compile(spec, path), True)
