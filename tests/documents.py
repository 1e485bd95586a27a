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
    "docs/damping.md",
)


def text(name: str) -> str:
    """One document's Markdown."""
    return (ROOT / name).read_text()


#: The mark of a tutorial step's block (docs/adding_a_map.md): an HTML comment on the line before
#: it, which the site does not show. tests/test_tutorial.py runs those blocks in a copy of the
#: project (they add a map); the other tests leave them out.
TUTORIAL = re.compile(r"^<!-- tutorial: (.+?) -->\n```(\w+)\n(.*?)^```", flags=re.S | re.M)


def blocks(language: str, name: str | None = None) -> list[tuple[str, str]]:
    """(document, code) of every fenced block of ``language``, of one document or of them all,
    but the tutorial's steps (:data:`TUTORIAL`)."""
    names = DOCUMENTS if name is None else (name,)
    return [
        (n, code)
        for n in names
        for code in re.findall(rf"^```{language}\n(.*?)^```", TUTORIAL.sub("", text(n)), flags=re.S | re.M)
    ]


def tutorial_steps(name: str = "docs/adding_a_map.md") -> dict[str, tuple[str, str]]:
    """The tutorial's marked blocks of a document: {mark: (language, code)}, in page order."""
    steps: dict[str, tuple[str, str]] = {}
    for mark, language, code in TUTORIAL.findall(text(name)):
        assert mark not in steps, f"{name}: tutorial mark {mark!r} twice"
        steps[mark] = (language, code)
    return steps


def section_block(name: str, heading: str) -> str:
    """The first python block after ``## heading`` of a document."""
    return text(name).split(f"## {heading}\n", 1)[1].split("```python\n", 1)[1].split("```", 1)[0]
