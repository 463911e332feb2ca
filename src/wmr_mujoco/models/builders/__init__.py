"""Parametric MJCF builders (dm_control ``mjcf``), one module per robot."""
