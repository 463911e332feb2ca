"""Filesystem locations: the model files and the repository's README.

The model folders (``models/<robot>/``, MuJoCo Menagerie layout) stay at the repository
root and ship in the wheel as the data package ``wmr_mujoco.model_files`` (see
``setup.py``). They are found, first match wins:

1. ``WMR_MODELS_DIR``, if set;
2. the ``models/`` folder of the source checkout this module runs from (a clone with
   ``PYTHONPATH=src``, or an editable install);
3. the installed package data, through :mod:`importlib.resources`.
"""

from __future__ import annotations

import importlib.resources
import os
from pathlib import Path

#: Root of the source checkout (``src/wmr_mujoco/models`` is three levels below it); in
#: an installed wheel this is a folder of the environment, without a ``pyproject.toml``.
REPO_ROOT: Path = Path(__file__).resolve().parents[3]

#: The data package that holds the model folders in an installed wheel.
MODEL_FILES_PACKAGE = "wmr_mujoco.model_files"


def in_checkout(root: Path = REPO_ROOT) -> bool:
    """Whether ``root`` is a source checkout with its ``models/`` folder."""
    return (root / "pyproject.toml").is_file() and (root / "models").is_dir()


def models_dir(root: Path = REPO_ROOT) -> Path:
    """The folder holding one sub-folder per robot (see the module docstring).

    Raises:
        FileNotFoundError: neither a checkout nor the installed package data has it.
    """
    override = os.environ.get("WMR_MODELS_DIR")
    if override:
        return Path(override)
    if in_checkout(root):
        return root / "models"
    try:
        files = importlib.resources.files(MODEL_FILES_PACKAGE)
    except ModuleNotFoundError:
        files = None
    # The data package has no __init__.py (it is the models/ folder itself), so files()
    # gives a namespace package's Traversable; its children are real paths, as wheels
    # install unzipped.
    children = list(files.iterdir()) if files is not None and files.is_dir() else []
    if not children:
        raise FileNotFoundError(f"model files not found: no {root / 'models'} and no "
                                f"package {MODEL_FILES_PACKAGE} (reinstall wmr-mujoco, or set "
                                "WMR_MODELS_DIR to a models/ folder)")
    return Path(str(children[0])).parent


#: Root of the ``models/`` folder (one sub-folder per robot), resolved at import (when
#: nothing is found, the checkout's path, which loading names in its error).
try:
    MODELS_DIR: Path = models_dir()
except FileNotFoundError:
    MODELS_DIR = REPO_ROOT / "models"

#: The repository README, whose result and benchmark tables ``make readme`` regenerates.
README_PATH: Path = REPO_ROOT / "README.md"


#: Default output folder of ``wmr validate`` (and of the reports ``make readme`` reads).
REPORTS_DIR = Path("reports")

#: The documentation pages, some with generated sections (``make readme``, ``make models``).
DOCS_DIR: Path = REPO_ROOT / "docs"
