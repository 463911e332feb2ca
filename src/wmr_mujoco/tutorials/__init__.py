"""Helpers of the tutorials in ``docs/tutorials/``: exercise checks and input schedules.

Application layer: the checks read the robots' registry, compiled models and analytic
models; nothing below imports this package.

* :mod:`~wmr_mujoco.tutorials.checks`: one check per exercise; a wrong or malformed
  answer gets a :class:`~wmr_mujoco.tutorials.checks.CheckResult` whose message names
  what differs (never an exception);
* :mod:`~wmr_mujoco.tutorials.schedule`: open-loop manoeuvres as segments of constant
  inputs, with smooth speed ramps, as functions of time for ``wmr.simulate``.
"""

from wmr_mujoco.tutorials.checks import CheckResult
from wmr_mujoco.tutorials.schedule import Segment, segment_inputs

__all__ = ["CheckResult", "Segment", "segment_inputs"]
