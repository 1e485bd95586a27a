"""The accuracy study (docs/accuracy.md, .json), re-measured: the committed record is current, and
the findings the docs and the README state hold.

The whole study runs once per session (about 10-20 s after compilation): every map and variant
on the five grids against the exact simulator. The re-measured numbers must match the committed
docs/accuracy.json to 2e-5 relative (the record has 6 significant digits; the integrations are
deterministic, so the slack only covers the last digit of a different libm); an error below 1e-9
(SI units) is at the exact simulator's own precision (its integration agrees with an outside
reference to 2e-11 relative), where a reformulation of a kernel moves it by its round-off, so
those are compared to 1e-9 absolute. The committed docs/accuracy.md must be exactly the rendering
of that record.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from slipmaps.generated import maps_index
from slipmaps.runtime.accuracy import measure_all, variants
from slipmaps.runtime.accuracy_report import SYMMETRIC_RATIO, from_json, render_markdown, summarize

DOCS = Path(__file__).resolve().parent.parent / "docs"
REL = 2e-5
ABS = 1e-9


@pytest.fixture(scope="module")
def measured() -> list[dict]:
    return summarize(measure_all(variants(), show_progress=False))


@pytest.fixture(scope="module")
def record() -> list[dict]:
    return from_json((DOCS / "accuracy.json").read_text())


def _close(a, b, path: str) -> None:
    if isinstance(a, dict):
        assert set(a) == set(b), f"{path}: keys differ: {sorted(set(a) ^ set(b))}"
        for k in a:
            _close(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), f"{path}: lengths differ"
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _close(x, y, f"{path}[{i}]")
    elif isinstance(a, float) and isinstance(b, float):
        assert math.isclose(a, b, rel_tol=REL, abs_tol=ABS), f"{path}: measured {a!r}, recorded {b!r}"
    else:
        assert a == b, f"{path}: measured {a!r}, recorded {b!r}"


def test_accuracy_record_is_current(measured, record):
    """docs/accuracy.json re-measured (regenerate with `slipmaps accuracy` after changing a map)."""
    _close(measured, record, "grids")


def test_accuracy_markdown_renders_the_record(record):
    assert (DOCS / "accuracy.md").read_text() == render_markdown(record)


def test_accuracy_covers_every_map(record):
    names = {row["name"] for row in maps_index.MAPS}
    for grid in record:
        assert {v["map"] for v in grid["variants"]} == names, grid["name"]


def _mean(grid: dict, label: str) -> float:
    return next(v for v in grid["variants"] if v["label"] == label)["apex_error"]["mean"]


def test_eq46_eq77_every_gravity_type_beats_geyer_on_nonsymmetric_steps(record):
    """Finding: every type at its defaults has a smaller mean next-apex error than Geyer's map on the
    nonsymmetric grids and the Yu protocol (measured: 0.06x-0.42x)."""
    for grid in record:
        if grid["kind"] == "symmetric":
            continue
        for v in grid["variants"]:
            if v["default"] and v["map"].startswith("gravity"):
                assert v["apex_error"]["mean"] < _mean(grid, "geyer"), (grid["name"], v["label"])


def test_eq46_eq77_no_gravity_type_reaches_geyer_on_symmetric_steps(record):
    """Finding (the docs state it): on symmetric steps, where the exact impulse is 0, every type is
    more than 1.1x Geyer's error (measured 1.16x-1.51x): P_c is computed from the map's own sweep,
    which is wrong by Geyer's angle error, so the correction adds an error of the same size."""
    for grid in record:
        if grid["kind"] != "symmetric":
            continue
        for v in grid["variants"]:
            if v["default"] and v["map"].startswith("gravity"):
                assert v["apex_error"]["mean"] > SYMMETRIC_RATIO * _mean(grid, "geyer"), (
                    grid["name"],
                    v["label"],
                )


def test_yu_protocol_target_met_by_type5(record):
    """Target: mean < 2 % at 60 and 65 deg, < 5 % at every angle, max < 10 % (type 5 measured: 1.60,
    0.597, 0.628, 0.917 %, max 6.30 %); Geyer's map is far from it (14.5, 13.0, 8.42, 12.8 %)."""
    yu = next(g for g in record if g["kind"] == "yu")
    t5 = next(v for v in yu["variants"] if v["label"] == "gravity-type5")
    by = {a["angle_of_attack_deg"]: a for a in t5["by_angle"]}
    assert by[60.0]["mean"] < 0.02 and by[65.0]["mean"] < 0.02
    assert all(a["mean"] < 0.05 for a in t5["by_angle"])
    assert max(a["max"] for a in t5["by_angle"]) < 0.10
    geyer = next(v for v in yu["variants"] if v["label"] == "geyer")
    assert all(a["mean"] > 0.08 for a in geyer["by_angle"])


def test_fixed_points_converge_within_their_bound(record):
    """Every default fixed-point variant converges on every grid (no NOT_CONVERGED); the report's
    literal reading iterated does not always (measured: 4-7 of the Yu steps need over 100 passes)."""
    for grid in record:
        for v in grid["variants"]:
            if v["default"]:
                assert "NOT_CONVERGED" not in v["failures"], (grid["name"], v["label"])
