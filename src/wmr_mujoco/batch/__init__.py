"""Many robots at once: :func:`simulate_batch` over C MuJoCo's threaded rollout or MuJoCo Warp.

See ``docs/batch.md``.
"""

from wmr_mujoco.batch.simulate import BACKENDS, installed_backends, simulate_batch
from wmr_mujoco.batch.trajectory import BatchTrajectory

__all__ = ["BACKENDS", "BatchTrajectory", "installed_backends", "simulate_batch"]
