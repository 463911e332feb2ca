"""Filesystem locations: the repository's model files and its README."""

from __future__ import annotations

import os
from pathlib import Path

#: Root of the source checkout (``src/wmr_mujoco/models`` is three levels below it).
REPO_ROOT: Path = Path(__file__).resolve().parents[3]

#: Root of the repository's ``models/`` folder (one sub-folder per robot).
#: Overridable with the ``WMR_MODELS_DIR`` environment variable.
MODELS_DIR: Path = Path(os.environ.get("WMR_MODELS_DIR", REPO_ROOT / "models"))

#: The repository README, whose result and benchmark tables ``make readme`` regenerates.
README_PATH: Path = REPO_ROOT / "README.md"
