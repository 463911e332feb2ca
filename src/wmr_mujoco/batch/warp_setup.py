"""Importing MuJoCo Warp: its kernel cache at a stable path, quiet, its devices.

Warp compiles its kernels the first time a process steps a model (tens of seconds per
robot model on a CPU) and keeps them in a kernel cache; a later process loads them in
under a second. The cache is ``$WMR_WARP_CACHE`` if set, else
``~/.cache/wmr-mujoco/warp`` (Warp adds its version below it). Delete the folder to
force a rebuild.
"""

from __future__ import annotations

import os
from pathlib import Path
from types import ModuleType

#: Environment variable naming the kernel cache folder.
CACHE_ENV = "WMR_WARP_CACHE"
#: The kernel cache folder when :data:`CACHE_ENV` is unset.
DEFAULT_CACHE = Path("~/.cache/wmr-mujoco/warp")
#: The pip extra that installs MuJoCo Warp.
EXTRA = "gpu"

_ready = False


def cache_dir() -> Path:
    """Where Warp's kernel cache lives (:data:`CACHE_ENV`, else :data:`DEFAULT_CACHE`)."""
    return Path(os.environ.get(CACHE_ENV) or DEFAULT_CACHE).expanduser()


def installed() -> bool:
    """Whether ``warp`` and ``mujoco_warp`` can be imported (without importing them)."""
    from importlib.util import find_spec

    return find_spec("warp") is not None and find_spec("mujoco_warp") is not None


def init() -> tuple[ModuleType, ModuleType]:
    """``(warp, mujoco_warp)``, Warp initialised with the cache at :func:`cache_dir`.

    Warp reads the cache setting when it first initialises: a caller that initialised
    Warp before keeps its own cache folder.

    Raises:
        ValueError: the packages are not installed (the message names the extra).
    """
    if not installed():
        raise ValueError(f"backend 'warp' needs MuJoCo Warp: pip install 'wmr-mujoco[{EXTRA}]'")
    import warp as wp

    global _ready
    if not _ready:
        wp.config.kernel_cache_dir = str(cache_dir())
        wp.config.log_level = wp.LOG_WARNING  # no line per compiled module
        wp.init()
        _ready = True
    import mujoco_warp as mjw

    return wp, mjw


def devices() -> list[str]:
    """Every CUDA device, else the CPU."""
    wp, _ = init()
    cuda = [str(d) for d in wp.get_cuda_devices()]
    return cuda or ["cpu"]
