"""Do the wheels touch the floor? A per-step reading for any wheeled robot.

A *wheel* is found from the model alone: the collision geoms that can touch the scene's
``floor`` (an explicit ``<pair>`` with it, or contact bits that match its own), each
assigned to the top of its chain of hinge bodies, i.e. the highest ancestor reached from
the geom's body through bodies that are all jointed to their parents by hinges only.
A roller (hinge) on a wheel (hinge) on a free platform belongs to the wheel; a caster
wheel (hinge) in a swivelling fork (hinge) to the fork; a geom of a body on a free joint
or slides (a chassis) to no wheel.

Per step the reading is, for every wheel, whether any of its geoms is in contact with the
floor, and the deepest penetration of a wheel geom into the floor,
``max(0, −dist)`` over those contacts (MuJoCo's signed distance; the contact margin is 0
in this package, so a contact exists exactly when the surfaces overlap or touch).
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

#: Name of the scene's floor geom (:mod:`wmr_mujoco.models.builders.scene`).
FLOOR = "floor"


def _hinge_only(model: mujoco.MjModel, body: int) -> bool:
    """Whether ``body`` is jointed to its parent by one or more hinges and nothing else."""
    n = int(model.body_jntnum[body])
    if n == 0:
        return False
    adr = int(model.body_jntadr[body])
    return all(int(model.jnt_type[adr + k]) == mujoco.mjtJoint.mjJNT_HINGE for k in range(n))


def touches_floor(model: mujoco.MjModel, geom: int, floor: int) -> bool:
    """Whether MuJoCo may make a contact between ``geom`` and the floor."""
    for k in range(model.npair):
        if {int(model.pair_geom1[k]), int(model.pair_geom2[k])} == {geom, floor}:
            return True
    if int(model.geom_bodyid[geom]) == int(model.geom_bodyid[floor]):
        return False
    return bool((model.geom_contype[geom] & model.geom_conaffinity[floor])
                or (model.geom_contype[floor] & model.geom_conaffinity[geom]))


@dataclass(frozen=True)
class WheelMap:
    """The wheels of a model and which floor-touching geom belongs to which.

    Attributes:
        floor: the floor geom's id.
        wheels: names of the wheel bodies (unnamed bodies as ``body<id>``), in body order.
        geom_wheel: (ngeom,) index into ``wheels`` of each geom, −1 for geoms of no wheel
            or that cannot touch the floor.
    """

    floor: int
    wheels: tuple[str, ...]
    geom_wheel: np.ndarray

    @classmethod
    def of(cls, model: mujoco.MjModel) -> WheelMap:
        """The wheel map of ``model`` (see the module docstring).

        Raises:
            ValueError: the model has no geom named ``floor``, or no geom of a hinge body
                can touch it.
        """
        try:
            floor = int(model.geom(FLOOR).id)
        except KeyError:
            raise ValueError(f"the model has no geom named {FLOOR!r}: load the scene "
                             f"(wmr_mujoco.load), not the robot alone") from None
        top_of: dict[int, int] = {}
        for geom in range(model.ngeom):
            if geom == floor or not touches_floor(model, geom, floor):
                continue
            body = int(model.geom_bodyid[geom])
            if not _hinge_only(model, body):
                continue
            while _hinge_only(model, int(model.body_parentid[body])):
                body = int(model.body_parentid[body])
            top_of[geom] = body
        if not top_of:
            raise ValueError("no geom of a hinged body can touch the floor: the model has "
                             "no wheels")
        bodies = sorted(set(top_of.values()))
        index = {b: i for i, b in enumerate(bodies)}
        geom_wheel = np.full(model.ngeom, -1, dtype=int)
        for geom, body in top_of.items():
            geom_wheel[geom] = index[body]
        names = tuple(model.body(b).name or f"body{b}" for b in bodies)
        return cls(floor, names, geom_wheel)

    def read(self, data: mujoco.MjData) -> tuple[np.ndarray, float]:
        """The current contacts (as of the last ``mj_forward``/``mj_step``).

        Returns:
            ``(touching, depth)``: (len(wheels),) whether each wheel touches the floor,
            and the deepest penetration of a wheel geom into the floor, m (0 if none).
        """
        touching = np.zeros(len(self.wheels), dtype=bool)
        n = data.ncon
        if n == 0:
            return touching, 0.0
        geoms = data.contact.geom[:n]
        on_floor = (geoms == self.floor).any(axis=1)
        other = np.where(geoms[:, 0] == self.floor, geoms[:, 1], geoms[:, 0])
        wheel = np.where(on_floor, self.geom_wheel[other], -1)
        # A contact inside a geom's margin (dist > 0) or excluded does not touch.
        mine = (wheel >= 0) & (data.contact.dist[:n] <= 0) & (data.contact.exclude[:n] == 0)
        touching[wheel[mine]] = True
        depth = float(max(0.0, -data.contact.dist[:n][mine].min())) if mine.any() else 0.0
        return touching, depth


@dataclass(frozen=True)
class FloorReading:
    """Readings of a run, one row per step.

    Attributes:
        wheels: wheel names (:attr:`WheelMap.wheels`).
        off_floor: (K, len(wheels)) True where the wheel touches nothing of the floor.
        depth: (K,) deepest penetration of a wheel into the floor per step, m.
    """

    wheels: tuple[str, ...]
    off_floor: np.ndarray
    depth: np.ndarray

    @property
    def off_floor_share(self) -> float:
        """Share of wheel samples with no floor contact, in [0, 1]."""
        return float(np.mean(self.off_floor)) if self.off_floor.size else 0.0

    @property
    def max_depth(self) -> float:
        """Deepest penetration over the run, m."""
        return float(self.depth.max()) if self.depth.size else 0.0


class FloorRecorder:
    """Collects :meth:`WheelMap.read` after each step of a run into a :class:`FloorReading`.

    Memory is allocated up front for ``steps`` samples; recording more raises.
    """

    def __init__(self, wheel_map: WheelMap, steps: int) -> None:
        if not (isinstance(steps, int) and 0 < steps <= 10_000_000):
            raise ValueError(f"steps = {steps!r}; valid: an integer in [1, 1e7]")
        self.map = wheel_map
        self._off = np.zeros((steps, len(wheel_map.wheels)), dtype=bool)
        self._depth = np.zeros(steps)
        self._k = 0

    def record(self, data: mujoco.MjData) -> None:
        """Read the current contacts as the next sample."""
        if self._k >= len(self._depth):
            raise ValueError(f"recorder is full ({len(self._depth)} samples)")
        touching, depth = self.map.read(data)
        self._off[self._k] = ~touching
        self._depth[self._k] = depth
        self._k += 1

    def reading(self) -> FloorReading:
        """The samples recorded so far."""
        return FloorReading(self.map.wheels, self._off[:self._k].copy(),
                            self._depth[:self._k].copy())


#: Fields of a wheel's contact sensor (``mjtConDataField`` bits): ``found`` (the number of
#: matching contacts) and ``dist`` (MuJoCo's signed distance of the one kept).
SENSOR_FIELDS = (1 << int(mujoco.mjtConDataField.mjCONDATA_FOUND)) | (
    1 << int(mujoco.mjtConDataField.mjCONDATA_DIST))
#: The contact sensor's ``reduce`` code of ``"mindist"`` (the XML keyword; MuJoCo's
#: Python bindings name no enum for it).
REDUCE_MINDIST = 1
#: Values per wheel sensor: found, dist.
SENSOR_DIM = 2
#: Prefix of the floor sensors' names.
SENSOR_PREFIX = "floor_contact_"


def add_floor_sensors(spec: mujoco.MjSpec, wheels: tuple[str, ...]) -> None:
    """Add to ``spec``, per wheel, a contact sensor of its subtree with the ``floor``.

    Each reports the number of the wheel subtree's contacts with the floor and the
    smallest signed distance among them (``reduce="mindist"``, one contact kept), so that
    ``mujoco.rollout`` records the :meth:`WheelMap.read` of every step in ``sensordata``
    (:func:`sensor_reading`). The subtree of a wheel holds its rollers; its geoms that
    cannot touch the floor make no floor contact.

    Raises:
        ValueError: no wheels given.
    """
    if not wheels:
        raise ValueError("no wheels given; a floor sensor needs a wheel body")
    for w in wheels:
        spec.add_sensor(name=f"{SENSOR_PREFIX}{w}", type=mujoco.mjtSensor.mjSENS_CONTACT,
                        objtype=mujoco.mjtObj.mjOBJ_XBODY, objname=w,
                        reftype=mujoco.mjtObj.mjOBJ_GEOM, refname=FLOOR,
                        intprm=[SENSOR_FIELDS, REDUCE_MINDIST, 1])


def sensor_columns(model: mujoco.MjModel, wheels: tuple[str, ...]) -> np.ndarray:
    """(len(wheels),) index in ``sensordata`` of each wheel sensor's ``found`` value.

    Raises:
        ValueError: a wheel without its sensor (:func:`add_floor_sensors`).
    """
    out = []
    for w in wheels:
        try:
            sensor = model.sensor(f"{SENSOR_PREFIX}{w}")
        except KeyError:
            raise ValueError(f"the model has no floor sensor of wheel {w!r}; add it with "
                             f"add_floor_sensors") from None
        out.append(int(model.sensor_adr[sensor.id]))
    return np.asarray(out, dtype=int)


def sensor_reading(wheels: tuple[str, ...], columns: np.ndarray,
                   sensordata: np.ndarray) -> FloorReading:
    """The :class:`FloorReading` of recorded ``sensordata`` rows, (K, nsensordata).

    A wheel is off the floor where its sensor found no contact; the depth of a step is
    ``max(0, −dist)`` over the wheels in contact.
    """
    found = sensordata[:, columns] > 0
    dist = np.where(found, sensordata[:, columns + 1], np.inf)
    depth = np.maximum(0.0, -dist.min(axis=1)) if len(wheels) else np.zeros(len(found))
    return FloorReading(wheels, ~found, np.where(np.isfinite(depth), depth, 0.0))
