"""The documentation site's sources (docs/, built by docs/conf.py): fast checks on the text, no build
(CI builds the site with warnings as errors after the tests; the README says how).

- every public name of ``slipmaps.__all__`` is documented in the API reference, at ``slipmaps.NAME``;
- every page in docs/ is in the site (a toctree entry), the pages that commands write included as
  they are, never copied;
- the README sections that the site includes (``{include} ../README.md`` between two headings: the
  quick start, the first map call, the install extras) are there, each heading once, so a README edit
  that renames one fails here, not only in the build;
- the sections that moved from the README into the site (:data:`MOVED`) are on their page, each
  heading once, and no longer in the README (nothing held twice).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import slipmaps

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
#: The pages of the API reference.
API_PAGES = ("api.md",)
#: An ``{include}`` of the README, its options the group.
INCLUDE = r"^```\{include\} \.\./README\.md\n(.*?)^```"
#: The README's former sections, each the heading it has on the page that holds it now.
MOVED = {
    "## Python API": "getting_started.md",
    "## numba's cache": "performance.md",
    "## Derivatives": "getting_started.md",
    "## Periodic gaits and their stability": "control_planning.md",
    "## Control: deadbeat steps, runs on the exact plant": "control_planning.md",
    "# Sweeps and Dask": "sweeps.md",
    "# Accuracy (report sections 6-8, measured)": "findings.md",
    "# Performance": "performance.md",
    "## Cost against accuracy": "performance.md",
    "## The exact map": "performance.md",
    "# Layout": "layout.md",
    "# Adding a map": "adding_a_map.md",
    "## Regenerating": "adding_a_map.md",
    "# Design notes": "design.md",
    "# Status of the report's equations": "equations.md",
}


def _documented() -> list[str]:
    """The names the API pages document at the top level (``.. autoclass:: slipmaps.NAME``...)."""
    text = "\n".join((DOCS / page).read_text() for page in API_PAGES)
    return re.findall(r"^\.\. auto(?:class|function|data)::\s+slipmaps\.(\w+)\s*$", text, flags=re.M)


def test_every_public_name_is_in_the_api_reference():
    documented = _documented()
    assert sorted(set(slipmaps.__all__) - set(documented)) == []
    # and nothing else at the top level, each name once
    assert sorted(set(documented) - set(slipmaps.__all__)) == []
    assert len(documented) == len(set(documented))


def _toctree_entries() -> set[str]:
    entries = set()
    for page in DOCS.glob("*.md"):
        for block in re.findall(r"^```\{toctree\}\n(.*?)^```", page.read_text(), flags=re.S | re.M):
            entries |= {line.strip() for line in block.splitlines() if line.strip() and line[0] != ":"}
    return entries


def test_every_page_is_in_the_site():
    pages = {p.stem for p in DOCS.glob("*.md")} - {"index"}
    assert sorted(pages - _toctree_entries()) == []
    assert sorted(_toctree_entries() - pages) == []


@pytest.mark.parametrize(
    "page",
    ["maps", "equations", "accuracy", "convergence", "stiffness", "stability", "reproductions", "sections"],
)
def test_a_generated_page_is_a_page_of_the_site(page):
    head = "\n".join((DOCS / f"{page}.md").read_text().splitlines()[:3])
    assert "do not edit" in head, f"docs/{page}.md is no longer written by a command"
    assert page in _toctree_entries()


def _readme_includes() -> list[tuple[str, str, str]]:
    out = []
    for page in sorted(DOCS.glob("*.md")):
        for block in re.findall(INCLUDE, page.read_text(), flags=re.S | re.M):
            options = dict(re.findall(r'^:([\w-]+): "(.*)"$', block, flags=re.M))
            out += [(page.name, key, options[key]) for key in ("start-after", "end-before")]
    return out


def test_the_site_includes_readme_sections():
    assert len(_readme_includes()) >= 6
    assert len(_readme_includes()) + len(MOVED) >= 10


@pytest.mark.parametrize("heading, page", MOVED.items())
def test_a_moved_readme_section_is_on_its_page_once(heading, page):
    assert re.findall(rf"^{re.escape(heading)}$", (DOCS / page).read_text(), flags=re.M) == [heading]
    title = heading.lstrip("# ")
    readme = (ROOT / "README.md").read_text()
    assert not re.findall(rf"^#+ {re.escape(title)}$", readme, flags=re.M), f"{title} is in the README again"


@pytest.mark.parametrize("page, option, heading", _readme_includes())
def test_an_included_readme_heading_is_there_once(page, option, heading):
    readme = (ROOT / "README.md").read_text()
    assert re.findall(rf"^{re.escape(heading)}$", readme, flags=re.M) == [heading], (page, option)


def test_the_readmes_extras_table_lists_every_extra_of_the_package():
    """The table lacked `pandas` (the `to_pandas` docstrings ask for it): every extra of
    pyproject.toml is a row, and no row names an extra the package does not have."""
    try:
        import tomllib
    except ImportError:  # Python 3.10
        import tomli as tomllib
    extras = set(tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"])
    table = (ROOT / "README.md").read_text().split("| extra | for |\n", 1)[1].split("\n\n", 1)[0]
    rows = set(re.findall(r"^\| `([\w-]+)` \|", table, flags=re.M))
    assert "pandas" in extras and rows == extras


def test_the_docs_speak_of_the_project_not_of_sessions():
    """The changelog said "this session" (four places) and a performance page "the editor session":
    the docs speak of the project and the machine."""
    pages = [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]
    assert len(pages) > 20
    said = [
        f"{page.name}:{n}"
        for page in pages
        for n, line in enumerate(page.read_text().splitlines(), 1)
        if re.search(r"\bsessions?\b", line, flags=re.I)
    ]
    assert said == []
