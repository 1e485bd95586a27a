"""The family pages of the site (docs/<page>.md, one per map module's ``PAGE``): each holds, between
its markers ``<!-- equations:begin -->`` / ``<!-- equations:end -->``, the report equations of its
maps as ``slipmaps generate`` writes them from the registry (derive/equations/).

- every declared map, half and the exact map lands on exactly one page, and the page exists;
- every equation a map declares is on its page, every ``corrected`` registry entry in some page's
  errata;
- the blocks are current (here, fast, from the pages alone; ``test_codegen``'s
  ``test_committed_generated_files_are_current`` checks them with every other generated file), and
  ``generate --check`` names a page whose block was edited by hand.
"""

from __future__ import annotations

import re
import shutil

import pytest
import sympy as sp
from slipmaps.derive import generate
from slipmaps.derive.equations import by_key, entries
from slipmaps.derive.maps import all_halves, all_maps, family_pages, ground_truth

ROOT = generate.ROOT
BLOCK = re.compile(r"<!-- equations:begin[^>]*-->\n(.*?)<!-- equations:end -->", re.S)


def _block(page: str) -> str:
    (body,) = BLOCK.findall((ROOT / "docs" / f"{page}.md").read_text())
    return body


def _labels(text: str, prefix: str) -> set[str]:
    """The registry keys of the entries ``text`` lists, each line starting ``prefix`` then
    ``**(key)`` or ``**`key```."""
    found = re.findall(rf"^{re.escape(prefix)}\*\*(?:\((\w+)\)|`([^`]+)`)", text, flags=re.M)
    return {a or b for a, b in found}


def test_every_map_lands_on_exactly_one_family_page():
    declared = [s.name for s in (*all_maps(), *all_halves(), ground_truth())]
    placed = [s.name for specs in family_pages().values() for s in specs]
    assert sorted(placed) == sorted(declared)
    for page in family_pages():
        assert (ROOT / "docs" / f"{page}.md").is_file(), page


@pytest.mark.parametrize("page", sorted(family_pages()))
def test_declared_equations_are_on_the_family_page(page):
    registry = by_key()
    shown = _labels(_block(page), "")
    for spec in family_pages()[page]:
        missing = [eq for eq in spec.equations if eq not in shown]
        assert missing == [], f"{spec.name}: equations {missing} not on docs/{page}.md"
        assert all(eq in registry for eq in spec.equations), spec.name


def test_every_corrected_equation_is_in_some_errata():
    errata = set()
    for page in family_pages():
        block = _block(page)
        if "### Errata" in block:
            errata |= _labels(block.split("### Errata", 1)[1], "- ")
    corrected = {e.key for e in entries() if e.status == "corrected"}
    assert sorted(corrected - errata) == []
    assert sorted(errata - corrected) == []


def test_every_entry_has_a_subsection_and_derived_forms_are_equations():
    for e in entries():
        assert re.fullmatch(r"\d+(\.\d+)*", e.subsection), e.key
        if e.derived is not None:
            forms = e.derived()
            assert forms and all(isinstance(f, sp.Eq) for f in forms), e.key


#: The least share of the entries a family page lists whose derived form the page renders as math
#: (measured when the forms were added: exact, geyer, type5 all; gravity 31 of 34, the two claims and
#: the empty (69) as text; iterative 46 of 61, the definitions (34), (36)-(40), (120)-(122), (128),
#: (144), the theorem (35) and the bottom (152)-(154) as text; variable 27 of 36, (106)-(113) and
#: the empty (95) as text; damping, section 3.1 with the damped extensions, all 33).
MIN_MATH_SHARE = {
    "exact": 1.0,
    "geyer": 1.0,
    "type5": 1.0,
    "gravity": 0.9,
    "iterative": 0.7,
    "variable": 0.7,
    "damping": 1.0,
}


def _rendered(block: str) -> dict[str, bool]:
    """Each entry the block lists (before its errata) and whether display math follows its line."""
    listing = block.split("### Errata", 1)[0]
    parts = re.split(r"^\*\*(?:\((\w+)\)|`([^`]+)`)", listing, flags=re.M)[1:]
    return {a or b: "$$" in body for a, b, body in zip(parts[::3], parts[1::3], parts[2::3], strict=True)}


@pytest.mark.parametrize("page", sorted(family_pages()))
def test_family_pages_render_their_equations_as_math(page):
    rendered = _rendered(_block(page))
    assert set(rendered) == _labels(_block(page).split("### Errata", 1)[0], "")
    share = sum(rendered.values()) / len(rendered)
    assert share >= MIN_MATH_SHARE[page], f"docs/{page}.md: {share:.0%} of its entries as math"
    registry = by_key()
    for key, math in rendered.items():
        assert math == (registry[key].derived is not None), key


def test_family_page_blocks_are_current():
    for rel, text in generate.family_pages().items():
        assert (ROOT / rel).read_text() == text, f"{rel}: run `slipmaps generate`"


def test_check_names_a_hand_edited_block(tmp_path, monkeypatch):
    (tmp_path / "docs").mkdir()
    shutil.copy(ROOT / "pyproject.toml", tmp_path / "pyproject.toml")
    for page in family_pages():
        shutil.copy(ROOT / "docs" / f"{page}.md", tmp_path / "docs" / f"{page}.md")
    page = tmp_path / "docs" / "geyer.md"
    page.write_text(page.read_text().replace(": corrected (errata below).", ": verified.", 1))
    monkeypatch.setattr(generate, "ROOT", tmp_path)
    monkeypatch.setattr(generate, "GENERATED", tmp_path / "generated")
    problems = generate.check(files=generate.family_pages())
    assert len(problems) == 1 and "a/docs/geyer.md (committed)" in problems[0]
