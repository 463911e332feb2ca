"""The roller study's peer measurement names a missing peer and how to point at it."""

import pytest

from wmr_mujoco.bench.omni_study import measure_peer


def test_missing_peer_names_the_path_and_the_variable(tmp_path):
    with pytest.raises(FileNotFoundError, match=r"scene\.xml \(install mujoco-menagerie, "
                                                  r"or set WMR_PEER_SCENE"):
        measure_peer(None, tmp_path / "scene.xml")
