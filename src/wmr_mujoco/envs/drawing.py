"""The task drawn into a rendered frame: the goal pose, or the path to follow."""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np

from wmr_mujoco.render.rendering import add_polyline

GOAL_RGBA = (0.95, 0.6, 0.1, 1.0)
PATH_RGBA = (0.1, 0.5, 0.95, 1.0)
#: Height of the drawings above the floor, m.
LIFT = 0.005


def draw_task(scene: mujoco.MjvScene, task: Any) -> None:
    """Add the task's goal (an arrow along its heading) or path (a line) to ``scene``."""
    width = 0.01 * task.scale
    goal = getattr(task, "goal", None)
    if goal is not None and not hasattr(task, "path"):
        tip = goal[:2] + 0.3 * task.scale * np.array([math.cos(goal[2]), math.sin(goal[2])])
        pts = np.array([[*goal[:2], LIFT], [*tip, LIFT]])
        add_polyline(scene, pts, GOAL_RGBA, 2 * width)
    path = getattr(task, "path", None)
    if path is not None:
        pts = path.xy[path.s <= task.end][::5]
        add_polyline(scene, np.column_stack([pts, np.full(len(pts), LIFT)]), PATH_RGBA, width)
