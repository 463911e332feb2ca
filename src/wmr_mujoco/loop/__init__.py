"""Closing the loop, below the registry: the steppable robot, controllers, paths and tasks.

The layer between :mod:`wmr_mujoco.validation` and the registry (:mod:`wmr_mujoco.robots`):
everything here receives a :class:`~wmr_mujoco.validation.spec.RobotSpec`, never a name
to look up, so that validation scenarios close loops on the robots and the registry adds
them to its entries.

* The steppable robot: :func:`~wmr_mujoco.loop.build.build_robot` (spec -> robot) and its
  backends :mod:`.physics` (MuJoCo), :mod:`.kinematic` and :mod:`.dynamic` (the analytic
  models), with :mod:`.robot` (the shared ``reset``/``step``), :mod:`.state` and
  :mod:`.readout`;
* :mod:`wmr_mujoco.loop.control`: reference paths and feedback controllers;
* :mod:`wmr_mujoco.loop.tasks`: closed-loop tasks and their judged scenario families.

Users drive robots by name through :func:`wmr_mujoco.make` (:mod:`wmr_mujoco.drive`).
"""
