"""Physics against the analytic models: signals, scenarios, adapters, metrics, runner, report.

The flow: a :mod:`~wmr_mujoco.validation.scenarios` entry (inputs as
:mod:`~wmr_mujoco.validation.signals`) goes through the robot's adapter
(:mod:`~wmr_mujoco.validation.adapters`) in the :mod:`~wmr_mujoco.validation.runner`,
which judges it with :mod:`~wmr_mujoco.validation.metrics`; the
:mod:`~wmr_mujoco.validation.report` writes the tables and plots.
"""
