"""One validation scenario per robot, simulated and summarised (``wmr demo``).

A quick look at each robot: it runs the demo scenario its registry entry names through the
validation runner, and prints the path driven, where the robot ended, and how far it was
from the analytic model at worst over the run and at the end.
"""

from __future__ import annotations

import math

from wmr_mujoco.analytic.planar import path_length
from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.validation.metrics import row_value
from wmr_mujoco.validation.runner import run_scenario


def run_demo() -> str:
    """Run each robot's demo scenario and return a text summary."""
    lines = [f"{'robot':<9} {'scenario':<22} {'path m':>7} {'end x, y (m)':>16} "
             f"{'heading':>8} {'worst off, % path':>18} {'final off':>10}"]
    for spec in ROBOTS.values():
        if spec.demo_scenario is None:
            continue
        scenario = spec.scenario(spec.demo_scenario)
        result = run_scenario(spec, scenario)
        if result.error:
            lines.append(f"{spec.name:<9} {scenario.name:<22} failed: {result.error}")
            continue
        sim = result.trace.arrays()["sim"]
        x, y, heading = sim[-1, :3]
        worst, final = (row_value(result.rows, f"{which} position error", "% of path",
                                  math.nan) for which in ("worst", "final"))
        lines.append(f"{spec.name:<9} {scenario.name:<22} {path_length(sim[:, :2]):7.3f} "
                     f"{x:7.3f}, {y:7.3f} {math.degrees(heading):7.1f}° {worst:16.3f} % "
                     f"{final:8.3f} %")
    return "\n".join(lines)
