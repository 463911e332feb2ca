"""The public names of :mod:`wmr_mujoco.loop.control.paths`, importable from here.

The controllers and paths live below the registry (:mod:`wmr_mujoco.loop`), so that
validation scenarios close loops with them.
"""

from wmr_mujoco.loop.control.paths import (
    DS,
    HINT_WINDOW,
    PATHS,
    SAMPLES,
    Curve,
    Path,
    PathPoint,
    circle,
    extend,
    figure_eight,
    from_curve,
    hermite_path,
    lane_change,
    line,
    make_path,
    random_path,
    random_spline,
)

__all__ = [
    "DS", "HINT_WINDOW", "PATHS", "SAMPLES", "Curve", "Path", "PathPoint", "circle", "extend",
    "figure_eight", "from_curve", "hermite_path", "lane_change", "line", "make_path",
    "random_path", "random_spline"
]
