"""A closed loop on the kinematic models, independent of the stepping API under test.

The plant integrates a held body twist exactly over each control period (the SE(2)
exponential, :func:`wmr_mujoco.analytic.planar.twist_step`): unicycle ``(v, ω)`` →
twist ``(v, 0, ω)``; car ``(v, δ)`` → ``(v, 0, v tan δ / ℓ)``; holonomic ``(u, v, r)``.
The only error against the continuous-time closed loop is the zero-order hold of the
command (O(Δt)).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
import pytest

from wmr_mujoco.analytic.planar import twist_step
from wmr_mujoco.loop.control.base import CommandKind


@dataclass(frozen=True)
class State:
    """The fields a controller reads."""

    pose: np.ndarray
    twist: np.ndarray = field(default_factory=lambda: np.zeros(3))
    extra: Mapping[str, float] = field(default_factory=dict)


def body_twist(kind: CommandKind, cmd: np.ndarray, wheelbase: float | None) -> np.ndarray:
    if kind is CommandKind.UNICYCLE:
        return np.array([cmd[0], 0.0, cmd[1]])
    if kind is CommandKind.CAR:
        return np.array([cmd[0], 0.0, cmd[0] * np.tan(cmd[1]) / wheelbase])
    return np.asarray(cmd, float)


def kinematic_loop(controller, reference, pose0, duration: float, dt: float,
                   wheelbase: float | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(times, poses, commands)`` of the controller closing the loop on the model."""
    controller.reset()
    pose = np.asarray(pose0, float)
    times, poses, cmds = [0.0], [pose], []
    for k in range(round(duration / dt)):
        cmd = controller(State(pose), reference, k * dt)
        pose = twist_step(pose, body_twist(controller.kind, cmd, wheelbase), dt)
        times.append((k + 1) * dt)
        poses.append(pose)
        cmds.append(cmd)
    return np.array(times), np.array(poses), np.array(cmds)


@pytest.fixture
def loop():
    """:func:`kinematic_loop`."""
    return kinematic_loop


def decay_rate(t: np.ndarray, err: np.ndarray) -> float:
    """Least-squares slope of ``−log |err|`` against ``t``, 1/s."""
    return float(-np.polyfit(t, np.log(np.abs(err)), 1)[0])


@pytest.fixture
def rate():
    """:func:`decay_rate`."""
    return decay_rate


@pytest.fixture
def state():
    """The :class:`State` type."""
    return State
