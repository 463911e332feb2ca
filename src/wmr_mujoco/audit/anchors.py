"""Where the outside robots (``shared/anchors``) are, read in place, never copied here.

Looked up beside the checkout: ``<repo root>/../shared/anchors``, then one level up
(a worktree inside a folder of worktrees), or the ``WMR_ANCHORS`` variable first.
"""

from __future__ import annotations

import os
from pathlib import Path

from wmr_mujoco.models.paths import REPO_ROOT


def anchors_dir(root: Path = REPO_ROOT) -> Path | None:
    """The ``shared/anchors`` folder, or None where there is none."""
    env = os.environ.get("WMR_ANCHORS")
    candidates = ([Path(env)] if env else []) + [root.parent / "shared" / "anchors",
                                                 root.parent.parent / "shared" / "anchors"]
    return next((c for c in candidates if c.is_dir()), None)


def anchor_scene(name: str, root: Path = REPO_ROOT) -> Path | None:
    """``<anchors>/<name>/scene.xml``, or None where it is missing."""
    base = anchors_dir(root)
    scene = base / name / "scene.xml" if base else None
    return scene if scene is not None and scene.is_file() else None
