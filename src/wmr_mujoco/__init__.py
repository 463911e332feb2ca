"""wmr-mujoco: wheeled mobile robots in MuJoCo, beside their textbook models."""

import os

# Offscreen rendering goes through EGL unless the user chose otherwise; MuJoCo and
# dm_control read this once, when first imported.
os.environ.setdefault("MUJOCO_GL", "egl")


from wmr_mujoco.actuation import ActuationMode, set_actuation_mode
from wmr_mujoco.loading import build_scene, load
from wmr_mujoco.registry import ROBOTS, get_spec

__all__ = ["ROBOTS", "ActuationMode", "build_scene", "get_spec", "load",
           "set_actuation_mode"]
__version__ = "0.1.0"
