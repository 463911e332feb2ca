"""Warp's kernel cache folder: the environment variable, else a stable default."""

from pathlib import Path

import pytest

from wmr_mujoco.batch import warp_setup

pytestmark = pytest.mark.extra  # MuJoCo Warp (the gpu extra)


def test_cache_dir_follows_the_environment(monkeypatch, tmp_path):
    monkeypatch.setenv(warp_setup.CACHE_ENV, str(tmp_path))
    assert warp_setup.cache_dir() == tmp_path
    monkeypatch.delenv(warp_setup.CACHE_ENV)
    assert warp_setup.cache_dir() == Path.home() / ".cache" / "wmr-mujoco" / "warp"


def test_warp_is_installed_and_initialised_at_the_cache():
    wp, _mjw = warp_setup.init()
    # Warp keeps one sub-folder per version under the folder it is given.
    assert Path(wp.config.kernel_cache_dir).parent == warp_setup.cache_dir()
    assert "cpu" in warp_setup.devices() or warp_setup.devices()[0].startswith("cuda")
