"""The robot study (runtime/studies/robot.py, robot_report.py): its committed record and page, the
gains Raibert's controller defaults to, its helpers. CI runs ``slipmaps robot --quick`` itself."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from slipmaps.runtime.control.raibert import RaibertGains
from slipmaps.runtime.studies.robot import _settle, controllers, excitation, ramp_grounds
from slipmaps.runtime.studies.robot_report import TARGETS, render, verdicts
from slipmaps.runtime.studies.study import from_json

DOCS = Path(__file__).resolve().parent.parent / "docs"


@pytest.fixture(scope="module")
def record():
    return from_json((DOCS / "robot.json").read_text())


def test_the_page_is_the_record_rendered(record):
    assert (DOCS / "robot.md").read_text() == render(record)
    for name in ("robot_tracking.png", "robot_ramps.png", "robot.gif"):
        assert (DOCS / name).stat().st_size > 10_000, name


def test_raiberts_default_gains_are_the_searchs_best(record):
    best = record["raibert_search"]["best"]
    assert RaibertGains() == RaibertGains(**{k: best[k] for k in record["raibert_search"]["grid"]})
    assert not record["quick"] and len(record["raibert_search"]["scores"]) >= 100


def test_every_target_is_judged_with_what_was_measured(record):
    rows = verdicts(record)
    assert [t for t, _, _ in rows] == list(TARGETS.values())
    assert all(text for _, _, text in rows)


def test_settling_counts_the_hops_after_each_change():
    targets = np.array([3.0] * 3 + [5.0] * 4 + [3.0] * 3)
    values = np.array([3.0, 3.0, 3.0, 3.8, 4.6, 5.01, 5.0, 3.5, 3.02, 3.0])
    assert _settle(values, targets) == [3, 2]
    values[-1] = np.nan  # a fall: never settled
    assert _settle(values, targets) == [3, None]


def test_the_studys_inputs_are_seeded_and_in_their_ranges():
    a, b = ramp_grounds(0.1, 5, 30, seed=40), ramp_grounds(0.1, 5, 30, seed=40)
    assert np.array_equal(a, b) and np.abs(a).max() <= 0.1 and a.std() > 0.03
    runs = excitation(3, 20)
    assert runs == excitation(3, 20)
    for heights, speeds in runs:
        assert min(heights) >= 1.05 and max(heights) <= 1.15
        assert min(speeds) >= 3.0 and max(speeds) <= 5.0 and np.abs(np.diff(speeds)).max() <= 0.3
    ctl = controllers({"params": None, "model_loss": 0.02}, {"k_v": 0.3, "score": 0.1})
    assert list(ctl) == ["Raibert", "slipmaps", "slipmaps, identified", "slipmaps, identified + correction"]
    assert (
        ctl["Raibert"]["raibert"].k_v == 0.3 and ctl["slipmaps, identified + correction"]["correction"] == 3
    )


def test_the_record_is_json_with_no_nan_in_the_page(record):
    assert "nan" not in (DOCS / "robot.md").read_text().lower()
    json.dumps(record)
