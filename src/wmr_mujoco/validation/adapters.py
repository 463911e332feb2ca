"""What ties a robot's MuJoCo model to its analytic model: the :class:`Adapter` protocol.

An adapter says, for one robot and one kind of input: how the lecture's inputs become
actuator controls, the analytic state and its derivative, how to read that state from the
simulation, and which wheels are conventional (for lateral-slip measurement). Each robot
module (:mod:`wmr_mujoco.robots`) defines its adapters and lists a factory per
:class:`~wmr_mujoco.validation.scenarios.ScenarioKind`; the runner uses nothing of an
adapter beyond this protocol.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol

import mujoco
import numpy as np

from wmr_mujoco.analytic.planar import yaw_from_rotation
from wmr_mujoco.models.actuation import ActuationMode

if TYPE_CHECKING:
    from wmr_mujoco.models.params import RobotParams
    from wmr_mujoco.validation.scenarios import Scenario


class Adapter(Protocol):
    """Interface of a robot adapter (see the module docstring).

    Attributes:
        mode: the actuation mode the controls are meant for; None leaves the model's
            actuators as they are (a foreign model with its own servos).
        state_names: names of the analytic state's components; a state that starts
            with ``("x", "y", "heading")`` is judged on pose tracking.
        state_units: their units.
        wheel_joints: the wheel hinges, in input order.
        lateral_wheels: conventional wheels whose contact's sideways speed is measured.
    """

    mode: ActuationMode | None
    state_names: tuple[str, ...]
    state_units: tuple[str, ...]
    wheel_joints: tuple[str, ...]
    lateral_wheels: tuple[str, ...]

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Actuator controls for input ``u``.

        The analytic state is passed for open-loop schedules that depend on it.
        """
        ...

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Analytic state derivative ``ẋ = f(x, u)``."""
        ...

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """The analytic state's quantities, read from the simulation.

        It may read the state, frames, centres of mass and body velocities (the runner
        computes those stages: :func:`~wmr_mujoco.validation.resample.sync_kinematics`),
        not contacts, forces or sensors.
        """
        ...

    # Optional: ``exact_step(x, u, dt) -> x⁺``, the exact solution of ``ẋ = rhs(x, u)`` over
    # ``dt`` with ``u`` held; the runner then uses it instead of an RK4 step.
    # Optional: ``trajectory(x0, inputs, dt) -> (N + 1, n) states``, every step of the
    # runner's schedule at once (vectorised): the same floats as its steps one by one.
    # Optional: ``frames_only = True``: ``sim_state`` reads the state and frames alone
    # (``mj_kinematics``), so the runner leaves out the centres of mass and velocities.


#: ``factory(scenario, model, params) -> Adapter`` (params: the robot's, defaults if None).
AdapterFactory = Callable[["Scenario", mujoco.MjModel, "RobotParams | None"], Adapter]

#: Units of a planar pose state.
POSE_UNITS = ("m", "m", "rad")


def body_pose(model: mujoco.MjModel, data: mujoco.MjData, body: int) -> np.ndarray:
    """World ``(x, y, heading)`` of a body's frame."""
    return np.array([data.xpos[body][0], data.xpos[body][1],
                     yaw_from_rotation(data.xmat[body])])


#: The last model :func:`base_site` looked up (weakly held) and its ``base`` site's id,
#: read and replaced as one tuple: a run reads one model's pose many times.
_BASE_SITE: list[tuple[weakref.ref[mujoco.MjModel] | None, int]] = [(None, -1)]


def base_site(model: mujoco.MjModel) -> int:
    """Id of the model's ``base`` site (looked up by name once per model in a row).

    Raises:
        KeyError: the model has no site named ``base``.
    """
    ref, site = _BASE_SITE[0]
    if ref is not None and ref() is model:
        return site
    site = model.site("base").id
    _BASE_SITE[0] = (weakref.ref(model), site)
    return site


def base_pose(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
    """World ``(x, y, heading)`` of the ``base`` site."""
    site = base_site(model)
    x, y, _ = data.site_xpos[site].tolist()
    return np.array([x, y, yaw_from_rotation(data.site_xmat[site])])


def body_twist(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
    """Body-frame ``(u, v, r)`` of the ``base`` site."""
    site = base_site(model)
    vel = np.zeros(6)
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_SITE, site, vel, 1)
    return np.array([vel[3], vel[4], vel[2]])


def per_distinct_row(fn: Callable[[np.ndarray], object], rows: np.ndarray,
                     width: int) -> np.ndarray:
    """``np.array([fn(r) for r in rows])`` with ``fn`` called once per distinct row.

    Rows are told apart by their bytes (a −0.0 is not a 0.0), and each distinct row's
    ``fn`` is called in order of first appearance, as the row-by-row calls would
    (``fn`` must be a function of the row alone). ``width``: entries of ``fn``'s value.

    Returns:
        (len(rows), width).
    """
    rows = np.ascontiguousarray(rows, float)
    if not len(rows):
        return np.empty((0, width))
    keys = rows.reshape(len(rows), -1).view(np.dtype((np.void, rows[0].nbytes))).ravel()
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    values = np.empty((len(first), width))
    for j in np.argsort(first, kind="stable"):
        values[j] = fn(rows[first[j]])
    return values[inverse.ravel()]
