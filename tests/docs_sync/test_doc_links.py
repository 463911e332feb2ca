"""The documentation points only inside the repository (or to the web)."""

import re
from pathlib import Path

import pytest

from wmr_mujoco.docs_sync.readme_sync import LOCAL_PATH

ROOT = Path(__file__).resolve().parents[2]
DOCS = sorted(p for pattern in ("*.md", "docs/**/*.md", "models/**/*.md")
              for p in ROOT.glob(pattern))
LINK = re.compile(r"\]\(([^)#\s]+)")


@pytest.mark.parametrize("doc", DOCS, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_link_or_path_leaves_the_repository(doc):
    text = doc.read_text()
    assert "../shared" not in text
    assert not LOCAL_PATH.search(text), LOCAL_PATH.search(text)
    for target in LINK.findall(text):
        if re.match(r"[a-z]+://", target):
            continue
        resolved = (doc.parent / target).resolve()
        assert resolved.is_relative_to(ROOT) and resolved.exists(), target
