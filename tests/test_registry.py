"""Layer 1 of CODEGEN.md: the report's equations, checked symbolically (slipmaps.derive.registry).

Every registry entry (derive/report_eqs.py) gets one test: a ``verified`` entry's check proves the
printed equation equals the SymPy derivation, a ``corrected`` entry's check proves the printed form
differs and the corrected one equals it, and a ``definition`` has no check. The remaining tests
keep the registry's bookkeeping honest: valid statuses, unique keys, the numbered equations all
present, and the generated equation tables (docs/equations.md, README.md) current.
"""

from __future__ import annotations

import re

import pytest
from slipmaps.derive import generate, registry

ENTRIES = registry.entries()

#: Numbered report equations deliberately left out of the registry (none at present). Removing an
#: entry makes test_numbered_equations_all_present fail unless its number is added here.
DELIBERATELY_LEFT: frozenset[str] = frozenset()
ALL_NUMBERED = frozenset(str(n) for n in range(1, 30))


def _entry_id(entry) -> str:
    return f"eq{entry.key}" if entry.key.isdigit() else entry.key


@pytest.mark.parametrize("entry", ENTRIES, ids=[_entry_id(e) for e in ENTRIES])
def test_registry_equation(entry):
    if entry.status == "definition":
        assert entry.check is None, f"definition {entry.key} should carry no check"
        return
    assert callable(entry.check), f"{entry.status} entry {entry.key} needs a check"
    result = entry.check()
    # `is True`, not truthiness: a check returning a SymPy relational or a non-empty object must fail.
    assert result is True, (
        f"eq {entry.key} ({entry.title}) is registered as {entry.status} but its check returned {result!r}"
    )


def test_entry_statuses_valid():
    assert set(registry.STATUSES) == {"verified", "corrected", "definition"}
    for e in ENTRIES:
        assert e.status in registry.STATUSES, e
        assert e.title.strip(), f"entry {e.key} has no title"
        if e.status == "definition":
            assert e.check is None, e.key
        else:
            assert callable(e.check), e.key
        if e.status == "corrected":
            # A correction must say what is wrong in the printed form.
            assert len(e.note.strip()) > 20, f"corrected entry {e.key} needs a note saying how"


def test_keys_unique_and_well_formed():
    keys = [e.key for e in ENTRIES]
    dupes = sorted({k for k in keys if keys.count(k) > 1})
    assert not dupes, f"duplicate registry keys: {dupes}"
    assert registry.by_key().keys() == set(keys)
    for k in keys:
        assert k.isdigit() or re.fullmatch(r"sec\d+(\.\d+)*(-[a-z0-9]+)?", k), f"malformed key {k!r}"


def test_numbered_equations_all_present():
    numbered = {e.key for e in ENTRIES if e.key.isdigit()}
    assert DELIBERATELY_LEFT <= ALL_NUMBERED
    assert numbered == ALL_NUMBERED - DELIBERATELY_LEFT, (
        f"missing: {sorted(ALL_NUMBERED - DELIBERATELY_LEFT - numbered, key=int)}, "
        f"unexpected: {sorted(numbered - ALL_NUMBERED, key=int)}"
    )


def test_numbered_entries_in_report_order():
    numbers = [int(e.key) for e in ENTRIES if e.key.isdigit()]
    assert numbers == sorted(numbers)


def test_equation_table_lists_every_entry_with_totals():
    table = registry.render_equation_table()
    rows = [line for line in table.splitlines() if line.startswith("| ") and not line.startswith("| eq ")]
    rows = [r for r in rows if not r.startswith("| ---")]
    assert [r.split(" | ")[0][2:] for r in rows] == [e.key for e in ENTRIES]
    for row, e in zip(rows, ENTRIES, strict=True):
        assert f"| {e.status} |" in row
    counts = {s: sum(e.status == s for e in ENTRIES) for s in registry.STATUSES}
    assert f"Totals: {counts['verified']} verified, {counts['corrected']} corrected, " in table
    assert f"{counts['definition']} definition." in table


@pytest.mark.parametrize("rel", ["docs/equations.md", "README.md"])
def test_equation_tables_current(rel):
    """docs/equations.md and the README table are what `slipmaps generate` writes from the registry."""
    expected = generate.build_files()[rel]
    actual = (generate.ROOT / rel).read_text()
    assert actual == expected, f"{rel} is out of date: run `slipmaps generate`"


def test_readme_table_matches_docs_table():
    files = generate.build_files()
    readme = files["README.md"]
    body = readme.split(generate.README_BEGIN, 1)[1].split(generate.README_END, 1)[0]
    table = files["docs/equations.md"].split("\n", 2)[2]  # without the generated-comment and title lines
    assert body == "\n" + table
