"""The README points only at files a clone has (not the developers' ../shared folder)."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_readme_links_and_doc_paths_exist_in_the_repository():
    text = (ROOT / "README.md").read_text()
    assert "../shared" not in text and "/work/" not in text
    links = re.findall(r"\]\(([^)#\s]+)\)", text)
    targets = links + re.findall(r"`((?:docs|experiments)/[\w./-]+\.md)`", text)
    assert "docs/design.md" in targets
    missing = [t for t in targets if not t.startswith("http") and "NAME" not in t
               and not (ROOT / t).exists()]
    assert missing == []
