"""Filesystem locations of the package's model files."""

from __future__ import annotations

import os
from pathlib import Path

#: Root of the repository's ``models/`` folder (one sub-folder per robot).
#: Overridable with the ``WMR_MODELS_DIR`` environment variable.
MODELS_DIR: Path = Path(
    os.environ.get("WMR_MODELS_DIR", Path(__file__).resolve().parents[2] / "models")
)
