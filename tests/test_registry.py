"""Layer 1 of CODEGEN.md: the report's equations, checked symbolically (slipmaps.derive.equations).

Every registry entry gets one test (id = its key): running a ``verified`` entry's check proves the
printed equation equals the SymPy derivation, a ``corrected`` entry's check proves the printed form
differs and the corrected one equals it, a ``definition`` has no check; a failing check reports the
condition that failed. The remaining tests keep the registry's bookkeeping honest: valid statuses,
unique well-formed keys, the numbered equations all present and in report order, the generated
table (docs/equations.md) current, and failures reported as such.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from slipmaps.derive import equations
from slipmaps.derive.equations import STATUSES, CheckFailed, Entry, expect, expect_nonzero, expect_zero, run

ENTRIES = equations.entries()
ROOT = Path(__file__).resolve().parent.parent

#: Numbered report equations deliberately left out of the registry (none at present). Removing an
#: entry makes test_numbered_equations_all_present fail unless its number is added here.
DELIBERATELY_LEFT: frozenset[str] = frozenset()
#: Registered numbered equations: every number of the report, 1-154.
ALL_NUMBERED = frozenset(str(n) for n in range(1, 155))


@pytest.mark.parametrize("entry", ENTRIES, ids=[e.key for e in ENTRIES])
def test_registry_equation(entry):
    outcome = run(entry)
    assert outcome.status == entry.status, (
        f"eq {entry.key} ({entry.title}) is registered as {entry.status} "
        f"but its check failed: {outcome.message}"
    )
    assert outcome.message is None


def test_entry_statuses_valid():
    assert STATUSES == ("verified", "corrected", "definition")
    assert {e.status for e in ENTRIES} == set(STATUSES)  # each branch below is taken
    for e in ENTRIES:
        assert e.status in STATUSES, e
        assert e.title.strip(), f"entry {e.key} has no title"
        assert e.section in equations.SECTION_MODULES, f"entry {e.key}: unknown section {e.section!r}"
        if e.status == "definition":
            assert e.check is None, f"definition {e.key} should carry no check"
        else:
            assert callable(e.check), f"{e.status} entry {e.key} needs a check"
            doc = e.check.__doc__ or ""
            assert "Printed" in doc, f"the check of {e.key} must quote the printed form in its docstring"
        if e.status == "corrected":
            # A correction must say what is wrong in the printed form.
            assert len(e.note.strip()) > 20, f"corrected entry {e.key} needs a note saying how"


def test_entry_validation():
    with pytest.raises(ValueError, match="unknown status"):
        Entry("1", "t", "proved", "", lambda: None, "sec3")
    with pytest.raises(ValueError, match="needs a check"):
        Entry("1", "t", "verified", "", None, "sec3")


def test_keys_unique_and_well_formed():
    keys = [e.key for e in ENTRIES]
    dupes = sorted({k for k in keys if keys.count(k) > 1})
    assert not dupes, f"duplicate registry keys: {dupes}"
    assert list(equations.by_key()) == keys  # by_key keeps report order
    by_key = equations.by_key()
    assert any(k.isdigit() for k in keys) and any(not k.isdigit() for k in keys)
    for k in keys:
        assert k.isdigit() or re.fullmatch(r"sec\d+(\.\d+)*(-[a-z0-9]+)?", k), f"malformed key {k!r}"
        if not k.isdigit():
            section = "sec" + k[3:].split("-")[0].split(".")[0]
            assert by_key[k].section == section, f"key {k!r} registered in {by_key[k].section}, not {section}"


def test_numbered_equations_all_present():
    numbered = {e.key for e in ENTRIES if e.key.isdigit()}
    assert DELIBERATELY_LEFT <= ALL_NUMBERED
    assert numbered == ALL_NUMBERED - DELIBERATELY_LEFT, (
        f"missing: {sorted(ALL_NUMBERED - DELIBERATELY_LEFT - numbered, key=int)}, "
        f"unexpected: {sorted(numbered - ALL_NUMBERED, key=int)}"
    )


def test_numbered_entries_in_report_order():
    numbers = [int(e.key) for e in ENTRIES if e.key.isdigit()]
    assert numbers and numbers == sorted(numbers)
    sections = [e.section for e in ENTRIES]
    assert sections == sorted(sections, key=equations.SECTION_MODULES.index), "sections out of report order"


def test_equation_table_lists_every_entry_with_totals():
    table = equations.render_equation_table()
    rows = [line for line in table.splitlines() if line.startswith("| ") and not line.startswith("| eq ")]
    rows = [r for r in rows if not r.startswith("| ---")]
    assert rows
    assert [r.split(" | ")[0][2:] for r in rows] == [e.key for e in ENTRIES]
    for row, e in zip(rows, ENTRIES, strict=True):
        assert f"| {e.status} |" in row
    report = [e for e in ENTRIES if not e.extension]  # the extensions (not in the report) apart
    extensions = len(ENTRIES) - len(report)
    # the leg damping's sec2.2.1-damped and its Geyer et al. radial solution sec3.1-damped*
    assert [e.key for e in ENTRIES if e.extension] == [
        "sec2.2.1-damped",
        "sec3.1-damped",
        "sec3.1-dampedrho",
        "sec3.1-dampedevents",
        "sec3.1-dampedangle",
    ]
    counts = {s: sum(e.status == s for e in report) for s in STATUSES}
    assert f"Totals: {counts['verified']} verified, {counts['corrected']} corrected, " in table
    assert f"{counts['definition']} definition; and {extensions} not in the report" in table
    assert "from derive/equations/" in table.splitlines()[0]


def test_docs_equation_table_current():
    """docs/equations.md is exactly what the registry renders."""
    actual = (ROOT / "docs" / "equations.md").read_text()
    assert actual == equations.render_equation_table(), "docs/equations.md is out of date: re-render it"


def test_failing_check_reports_its_condition():
    """A failing check gives Outcome status "failed" and a message naming the condition that failed."""
    import sympy as sp

    x = sp.Symbol("x", real=True)

    def wrong_identity():
        """Printed: (x + 1)^2 = x^2 + 1 (deliberately wrong)."""
        expect_zero(sp.cos(x) ** 2 + sp.sin(x) ** 2 - 1, "trig identity holds")
        expect_zero((x + 1) ** 2 - (x**2 + 1), "printed square equals the expansion")

    outcome = run(Entry("sec9-demo", "demo", "verified", "", wrong_identity, "test"))
    assert outcome.status == "failed" and outcome.failed
    assert outcome.message == "printed square equals the expansion: difference simplifies to 2*x"
    [record] = equations.to_json([outcome])
    assert record["number"] == "sec9-demo" and record["status"] == "failed"
    assert record["message"] == outcome.message and record["section"] == "test"

    def crashes():
        raise ZeroDivisionError("boom")

    assert run(Entry("d", "d", "corrected", "", crashes, "test")).message == "ZeroDivisionError: boom"
    # Checks signal failure by raising: an old-style `return False` does not pass silently.
    assert run(Entry("d", "d", "verified", "", lambda: False, "test")).status == "failed"


def test_expect_helpers():
    import sympy as sp

    x = sp.Symbol("x")
    expect_zero(sp.sin(2 * x) - 2 * sp.sin(x) * sp.cos(x), "double angle")
    expect_nonzero(x, "x is not zero")
    expect(sp.Integer(2) > 1, "2 > 1")
    with pytest.raises(CheckFailed, match="^x is zero: difference simplifies to x$"):
        expect_zero(x, "x is zero")
    with pytest.raises(CheckFailed, match="^zero differs: difference simplifies to 0$"):
        expect_nonzero(x - x, "zero differs")
    with pytest.raises(CheckFailed, match="undecided"):
        expect(x > 0, "x is positive")  # a SymPy relational that does not evaluate fails
    with pytest.raises(CheckFailed, match="^false: condition is false$"):
        expect(1 > 2, "false")


def test_main_exit_code_and_json(capsys, monkeypatch):
    """``main`` prints the table or the JSON list and returns 1 exactly when a check fails."""
    import json

    demo = [
        Entry("1", "fine", "verified", "", lambda: None, "sec3"),
        Entry("2", "broken", "verified", "a note", lambda: expect(False, "eq 2 condition"), "sec3"),
        Entry("3", "a definition", "definition", "", None, "sec3"),
    ]
    monkeypatch.setattr(equations, "entries", lambda: demo)
    assert equations.main(json_output=True) == 1
    data = json.loads(capsys.readouterr().out)
    assert [d["number"] for d in data] == ["1", "2", "3"]
    assert [d["status"] for d in data] == ["verified", "failed", "definition"]
    assert data[1]["message"] == "eq 2 condition: condition is false" and data[1]["note"] == "a note"
    assert equations.main() == 1
    out = capsys.readouterr().out
    assert "FAILED" in out and "eq 2 condition: condition is false" in out and "1 check(s) failed" in out
    monkeypatch.setattr(equations, "entries", lambda: demo[::2])
    assert equations.main() == 0
    assert "all checks pass" in capsys.readouterr().out
