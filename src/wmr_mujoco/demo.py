"""One validation scenario per robot, simulated and summarised (``wmr demo``).

A quick look at each robot: it reuses the validation scenarios and runner, and prints the
path driven, where the robot ended and how far it ended from the analytic model.
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.scenarios import SCENARIOS
from wmr_mujoco.validation import run_scenario

#: The scenario shown for each robot.
DEMO_SCENARIOS = {"disc": "constant steering", "bicycle": "lane change",
                  "tricycle": "figure eight", "omni3": "square with rotation"}


def run_demo() -> str:
    """Run each robot's demo scenario and return a text summary."""
    lines = [f"{'robot':<9} {'scenario':<22} {'path m':>7} {'end x, y (m)':>16} "
             f"{'heading':>8} {'off the model':>14}"]
    for robot, name in DEMO_SCENARIOS.items():
        scenario = next(s for s in SCENARIOS if s.robot == robot and s.name == name)
        result = run_scenario(scenario)
        if result.error:
            lines.append(f"{robot:<9} {name:<22} failed: {result.error}")
            continue
        sim = result.trace.arrays()["sim"]
        path = float(np.sum(np.linalg.norm(np.diff(sim[:, :2], axis=0), axis=1)))
        x, y, heading = sim[-1, :3]
        off = next(r.value for r in result.rows if r.unit == "% of path")
        lines.append(f"{robot:<9} {name:<22} {path:7.3f} {x:7.3f}, {y:7.3f} "
                     f"{math.degrees(heading):7.1f}° {off:12.3f} %")
    return "\n".join(lines)
