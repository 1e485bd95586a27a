"""The report's sections 6-8 (docs/sections.md, runtime/report/): prose and data agree.

- the committed page is the template rendered from the committed records (strict: every claim
  holds), so a record that changes without the page, or a claim the data no longer supports, fails;
- the template's prose types no number: every number is a placeholder filled from a record;
- a record that contradicts a claim fails the render naming the claim (the check can fail);
- every claim and number the template uses is defined, and every defined one is used;
- a reduced run (records missing, maps not measured) renders with "not measured" marks when
  lenient, and fails when strict.
"""

from __future__ import annotations

import copy
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from slipmaps.runtime.report import facts, sections

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"


@pytest.fixture(scope="module")
def records():
    return sections.load(DOCS)


def test_the_committed_page_is_rendered_from_the_records(records):
    page = (DOCS / sections.PAGE).read_text(encoding="utf-8")
    assert page == sections.render(records), "docs/sections.md is stale: run `slipmaps report --render-only`"
    assert (DOCS / sections.FIGURE).is_file()


#: What the template's prose may hold that has digits: equation numbers "(33)", "(98)-(111)", the
#: section numbers of headings and of "section 5.1", names with digits (DOP853, type5.md, ...).
_ALLOWED = (
    r"\{\{.*?\}\}",  # placeholders
    r"\{%.*?%\}",  # statements
    r"`[^`]*`",  # code
    r"\]\([^)]*\)",  # link targets
    r"^#+ [\d.]+",  # heading numbers
    r"\(\d+\)(-\(\d+\))?",  # equation numbers
    r"(?i:sections?)\s+\d+(\.\d+)*(-\d+)?",
    r"\b\w*[A-Za-z_]\w*\d\w*\b",  # names with digits
    r"<!--.*?-->",
)


def test_the_template_types_no_number():
    text = sections.template_text()
    for pattern in _ALLOWED:
        text = re.sub(pattern, " ", text, flags=re.M | re.S)
    numbers = re.findall(r".{0,30}\d.{0,30}", text)
    assert numbers == [], f"numbers typed in the template's prose: {numbers}"


def _used(kind: str) -> set[str]:
    text = sections.template_text()
    if kind == "claim":
        return set(re.findall(r'claim\("(\w+)"\)', text))
    return set(re.findall(r"\bn\.(\w+)", text))


def test_every_claim_and_number_of_the_template_is_defined_and_used(records):
    assert _used("claim") and _used("claim") == set(sections.CLAIMS)
    defined = set(facts.numbers(records))
    assert _used("number") and _used("number") <= defined
    # a number defined but not used is a table's or a leftover: none
    assert sorted(defined - _used("number")) == []


def _grid(records, kind):
    return next(g for g in records["accuracy"]["grids"] if g["kind"] == kind)


def _variant(grid, label):
    return next(v for v in grid["variants"] if v["label"] == label)


def test_claim_gravity_beats_geyer_fails_when_a_type_does_not(records):
    bad = copy.deepcopy(records)
    g = _grid(bad, "nonsymmetric")
    _variant(g, "gravity-type0")["apex_error"]["mean"] = 2 * _variant(g, "geyer")["apex_error"]["mean"]
    with pytest.raises(sections.ClaimFailed, match="gravity_beats_geyer_nonsymmetric"):
        sections.render(bad)


def test_claim_iterative_most_accurate_fails_when_another_map_is_better(records):
    bad = copy.deepcopy(records)
    g = _grid(bad, "yu")
    _variant(g, "gravity-type5")["apex_error"]["mean"] = 0.1 * _variant(g, "iterative")["apex_error"]["mean"]
    with pytest.raises(sections.ClaimFailed, match="iterative_most_accurate"):
        sections.render(bad)


def test_claim_of_the_front_fails_when_the_front_changes(records):
    bad = copy.deepcopy(records)
    for row in bad["pareto"]["rows"]:
        if row["label"] == "gravity-type0":
            row["dominated_by"] = "iterative, 2 passes"
    with pytest.raises(sections.ClaimFailed, match="gravity_type0_on_front"):
        sections.render(bad)


def test_claim_of_the_convergence_fails_when_a_pass_does_not_reduce_the_error(records):
    bad = copy.deepcopy(records)
    yu = next(g for g in bad["convergence"]["grids"] if g["kind"] == "yu")
    rows = [v for v in yu["variants"] if v["label"].startswith("iterative [convergence:")]
    assert len(rows) >= 3
    rows[2]["apex_error"]["mean"] = 10 * rows[1]["apex_error"]["mean"]
    with pytest.raises(sections.ClaimFailed, match="iterative_converges"):
        sections.render(bad)


def test_a_missing_record_fails_strict_and_is_marked_lenient(records):
    partial = {k: v for k, v in records.items() if k != "control"}
    with pytest.raises(sections.MissingData):
        sections.render(partial)
    text = sections.render(partial, strict=False)
    assert "not measured in this run" in text
    assert not re.search(r"\bnan\b", text, flags=re.I)


def test_report_render_only_writes_the_page_from_the_records_of_out(tmp_path):
    for f in DOCS.glob("*.json"):
        shutil.copy(f, tmp_path / f.name)
    subprocess.run(
        [sys.executable, "-m", "slipmaps", "report", "--render-only", "--out", str(tmp_path)],
        check=True,
        capture_output=True,
        text=True,
    )
    assert (tmp_path / sections.PAGE).read_text(encoding="utf-8") == (DOCS / sections.PAGE).read_text(
        encoding="utf-8"
    )
    assert (tmp_path / sections.FIGURE).stat().st_size > 10_000


def test_report_quick_needs_out():
    done = subprocess.run(
        [sys.executable, "-m", "slipmaps", "report", "--quick"], capture_output=True, text=True
    )
    assert done.returncode == 2
    assert "--out" in done.stderr


def test_report_render_only_on_records_missing_one_is_one_line_exit_1(tmp_path):
    for f in DOCS.glob("*.json"):
        if f.name != "control.json":
            shutil.copy(f, tmp_path / f.name)
    done = subprocess.run(
        [sys.executable, "-m", "slipmaps", "report", "--render-only", "--out", str(tmp_path)],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 1
    assert "Traceback" not in done.stderr
    assert len(done.stderr.strip().splitlines()) == 1 and "control" in done.stderr
