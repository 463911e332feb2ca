"""The rollout backend's options."""

import pytest

from wmr_mujoco.batch.rollout import RolloutBackend


@pytest.mark.parametrize("nthread", [0, -2, 1.5, True])
def test_bad_thread_count(nthread):
    with pytest.raises(ValueError, match=r"nthread = .*; give an integer >= 1"):
        RolloutBackend(nthread)
