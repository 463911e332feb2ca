"""Where the model files are found: WMR_MODELS_DIR, the checkout, the installed package."""

import pytest

from wmr_mujoco.models import paths


def test_the_variable_wins(tmp_path, monkeypatch):
    monkeypatch.setenv("WMR_MODELS_DIR", str(tmp_path))
    assert paths.models_dir() == tmp_path


def test_a_checkout_uses_its_own_models_folder(monkeypatch):
    monkeypatch.delenv("WMR_MODELS_DIR", raising=False)
    assert paths.in_checkout() and paths.models_dir() == paths.REPO_ROOT / "models"
    assert (paths.models_dir() / "omni3" / "scene.xml").is_file()


def test_an_install_reads_the_package_data(tmp_path, monkeypatch):
    """Outside a checkout the files come through importlib.resources (a package on disk)."""
    monkeypatch.delenv("WMR_MODELS_DIR", raising=False)
    data = tmp_path / "site" / "stub_model_files"
    (data / "disc").mkdir(parents=True)
    (data / "__init__.py").write_text("")
    monkeypatch.syspath_prepend(str(tmp_path / "site"))
    monkeypatch.setattr(paths, "MODEL_FILES_PACKAGE", "stub_model_files")
    assert paths.models_dir(tmp_path / "not-a-checkout") == data


def test_neither_says_how_to_fix_it(tmp_path, monkeypatch):
    monkeypatch.delenv("WMR_MODELS_DIR", raising=False)
    monkeypatch.setattr(paths, "MODEL_FILES_PACKAGE", "wmr_mujoco_no_such_package")
    with pytest.raises(FileNotFoundError, match="reinstall wmr-mujoco, or set WMR_MODELS_DIR"):
        paths.models_dir(tmp_path)
