"""The footholds study (runtime/studies/footholds.py, footholds_report.py): its committed record,
page and figures, the family it finds, its helpers. CI runs ``slipmaps footholds --quick`` itself."""

from __future__ import annotations

from pathlib import Path

import pytest
from slipmaps.runtime.studies.footholds import FAMILIES, PLANNERS, _summary, course, separating
from slipmaps.runtime.studies.footholds_report import TARGETS, render, verdicts
from slipmaps.runtime.studies.study import from_json

DOCS = Path(__file__).resolve().parent.parent / "docs"


@pytest.fixture(scope="module")
def record():
    return from_json((DOCS / "footholds.json").read_text())


def test_the_page_is_the_record_rendered(record):
    assert (DOCS / "footholds.md").read_text() == render(record)
    for name in ("footholds_course.png", "footholds_success.png", "footholds.gif"):
        assert (DOCS / name).stat().st_size > 10_000, name


def test_the_full_study_ran(record):
    assert not record["quick"] and record["plan"]["courses"] == 200 and record["plan"]["hops"] == 30
    assert list(record["courses"]) == list(FAMILIES) and list(record["planners"]) == list(PLANNERS)
    for planners in record["courses"].values():
        assert all(s["runs"] == 200 for s in planners.values())


def test_every_target_is_judged_with_what_was_measured(record):
    rows = verdicts(record)
    assert [t for t, _, _ in rows] == list(TARGETS.values())
    assert all(text for _, _, text in rows)
    assert record["separating"] == separating(record["courses"])


def test_the_separating_family_is_the_first_that_separates():
    def rates(one, two):
        return {"horizon 1": {"success": one}, "horizon 2": {"success": two}}

    assert separating({"a": rates(0.9, 1.0), "b": rates(0.5, 0.99), "c": rates(0.1, 1.0)}) == "b"
    assert separating({"a": rates(0.79, 0.98)}) is None


def test_a_summary_counts_the_runs_and_their_ends():
    got = {"succeeded": 3, "runs": 4, "ended": {"MISSED": 1}, "hops": [30, 30, 30, 12], "error": [0.0, 2e-3]}
    got |= {"margin": [0.1, float("nan"), 0.3], "us": [100.0, 300.0]}
    s = _summary(got, 30)
    assert s["success"] == 0.75 and s["ended"] == {"MISSED": 1} and s["hops_mean"] == 25.5
    assert (
        s["error_max"] == 2e-3 and s["placements"] == 2 and s["margin_min"] == 0.1 and s["us_median"] == 200.0
    )


def test_a_familys_courses_are_seeded_apart():
    a, b = course("stepping stones", 0), course("stepping stones", 1)
    assert a == course("stepping stones", 0) and a != b
    assert course("long stones", 0) != a


@pytest.mark.parametrize("command", ["footholds", "robot"])
@pytest.mark.parametrize(
    ("flags", "words"),
    [
        (["--quick"], "--quick writes a reduced study: give --out DIR"),
        (["--jobs", "0"], "--jobs must be at least 1"),
    ],
)
def test_a_study_commands_bad_flags_are_one_line(command, flags, words, capsys):
    from slipmaps.runtime.cli import main

    assert main([command, *flags]) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1
