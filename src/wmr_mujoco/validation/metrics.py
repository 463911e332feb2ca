"""Judged metrics: one import for targets, traces and the generic judges.

The parts live in :mod:`~wmr_mujoco.validation.targets` (targets, metrics, rows),
:mod:`~wmr_mujoco.validation.traces` (what a run records, probes) and
:mod:`~wmr_mujoco.validation.judges` (pose tracking, lateral slip). The twist metrics of
the roller-wheel robots are in :mod:`wmr_mujoco.robots.roller_wheels.twist_errors`.
"""

from wmr_mujoco.validation.judges import (
    CENTRE_DRIFT_M,
    DEFINITIONS,
    HEADING_DEG,
    LATERAL_SLIP_RMS,
    MIN_PATH,
    POSITION_PCT,
    Judge,
    lateral_slip,
    pose_tracking,
    rms,
    slip_metrics,
    worst_and_rms,
)
from wmr_mujoco.validation.targets import Metric, Row, Target, row_value
from wmr_mujoco.validation.traces import (
    RECORD_EVERY,
    Probe,
    ProbeFactory,
    Sample,
    Series,
    Trace,
)

__all__ = ["CENTRE_DRIFT_M", "DEFINITIONS", "HEADING_DEG", "LATERAL_SLIP_RMS", "MIN_PATH",
           "POSITION_PCT", "RECORD_EVERY", "Judge", "Metric", "Probe", "ProbeFactory", "Row",
           "Sample", "Series", "Target", "Trace", "lateral_slip", "pose_tracking",
           "rms", "row_value", "slip_metrics", "worst_and_rms"]
