"""The README and the site pages that hold what the README handed over to the site: the documents
whose examples, import paths and measured numbers the tests check (test_readme.py runs every example
of them, in this order, later ones using the names of earlier ones: ``params``, ``td``, ``down``)."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: The README first, then the pages, in the order their python blocks run.
DOCUMENTS = (
    "README.md",
    "docs/getting_started.md",
    "docs/control_planning.md",
    "docs/sweeps.md",
    "docs/performance.md",
    "docs/findings.md",
    "docs/layout.md",
    "docs/adding_a_map.md",
    "docs/design.md",
)


def text(name: str) -> str:
    """One document's Markdown."""
    return (ROOT / name).read_text()


def blocks(language: str, name: str | None = None) -> list[tuple[str, str]]:
    """(document, code) of every fenced block of ``language``, of one document or of them all."""
    names = DOCUMENTS if name is None else (name,)
    return [
        (n, code)
        for n in names
        for code in re.findall(rf"^```{language}\n(.*?)^```", text(n), flags=re.S | re.M)
    ]


def section_block(name: str, heading: str) -> str:
    """The first python block after ``## heading`` of a document."""
    return text(name).split(f"## {heading}\n", 1)[1].split("```python\n", 1)[1].split("```", 1)[0]
