"""The accuracy study (docs/accuracy.md, .json), re-measured: the committed record is current, and
the findings the docs (accuracy.md, findings.md) state hold.

The whole study runs once per session (about 10-20 s after compilation): every map and variant
on the five grids against the exact simulator. The re-measured numbers must match the committed
docs/accuracy.json (tolerances: tests/records.py). The committed docs/accuracy.md must be exactly
the rendering of that record.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import slipmaps
from records import assert_close
from slipmaps.generated import maps_index
from slipmaps.runtime.api import index
from slipmaps.runtime.studies import convergence
from slipmaps.runtime.studies import study as pipeline
from slipmaps.runtime.studies.accuracy import DAMPING_RATIOS, measure_all, measure_damping, variants
from slipmaps.runtime.studies.accuracy_report import (
    SYMMETRIC_RATIO,
    figure_record,
    from_json,
    render_markdown,
    summarize,
    summarize_damping,
)

DOCS = Path(__file__).resolve().parent.parent / "docs"


@pytest.fixture(scope="module")
def runs():
    return measure_all(variants() + convergence.variants(), show_progress=False)


@pytest.fixture(scope="module")
def measured(runs) -> list[dict]:
    return summarize(runs)


@pytest.fixture(scope="module")
def record() -> list[dict]:
    return from_json((DOCS / "accuracy.json").read_text())


@pytest.fixture(scope="module")
def study() -> list[dict]:
    return from_json((DOCS / "convergence.json").read_text())


def test_accuracy_record_is_current(measured, record):
    """docs/accuracy.json re-measured (regenerate with `slipmaps accuracy` after changing a map)."""
    assert_close(measured, record, "grids")


def test_accuracy_figure_record_is_current(runs):
    """docs/accuracy.json's "figure": the heatmaps' next-apex errors (maps with the role
    accuracy-figure, human runner, middle apex height), re-measured; docs/accuracy.png draws it."""
    recorded = pipeline.from_json((DOCS / "accuracy.json").read_text())["figure"]
    assert recorded["apex_error"], recorded
    assert_close(
        pipeline.from_json(pipeline.to_json({"figure": figure_record(runs)}))["figure"], recorded, "figure"
    )


def test_accuracy_damping_record_is_current():
    """docs/accuracy.json's "damping": every map that takes c, at damping ratios 0-0.2 against the
    exact map with the same c, re-measured; the table is not empty and covers every ratio."""
    recorded = pipeline.from_json((DOCS / "accuracy.json").read_text())["damping"]
    damped = [m.name for m in slipmaps.maps() if "c" in m.params and m.name != "exact"]
    assert damped and {r["map"] for r in recorded["rows"]} == set(damped)
    assert {r["ratio"] for r in recorded["rows"]} == set(DAMPING_RATIOS) and max(DAMPING_RATIOS) >= 0.2
    assert all(r["n_compared"] > 0.8 * r["exact_ok"] > 0 for r in recorded["rows"] if r["default"])
    measured = pipeline.from_json(pipeline.to_json({"damping": summarize_damping(measure_damping())}))
    assert_close(measured["damping"], recorded, "damping")


def test_accuracy_markdown_renders_the_record(record):
    damping = pipeline.from_json((DOCS / "accuracy.json").read_text())["damping"]
    assert (DOCS / "accuracy.md").read_text() == render_markdown(record, damping=damping)


def test_convergence_record_is_current(runs, study):
    """docs/convergence.json re-measured from the same exact steps (n = 0..8 passes)."""
    assert_close(summarize(runs, convergence.STUDY), study, "convergence")


def test_convergence_markdown_renders_the_record(study):
    damping = pipeline.from_json((DOCS / "convergence.json").read_text())["damping"]
    assert (DOCS / "convergence.md").read_text() == convergence.render_markdown(study, damping=damping)


def test_convergence_damping_record_is_current():
    """docs/convergence.json's "damping": the pass counts of the maps that take c at damping ratios
    0-0.2, re-measured."""
    recorded = pipeline.from_json((DOCS / "convergence.json").read_text())["damping"]
    damped = {v.map for v in convergence.variants() if "c" in index.get(v.map).params}
    assert {r["map"] for r in recorded.get("rows", [])} == damped
    if damped:
        assert {r["ratio"] for r in recorded["rows"]} == set(DAMPING_RATIOS)
    measured = summarize_damping(measure_damping(convergence.variants()))
    assert_close(pipeline.from_json(pipeline.to_json({"d": measured}))["d"], recorded, "damping")


def _passes(study: list[dict], grid_kind: str, name: str) -> list[dict]:
    grid = next(g for g in study if g["kind"] == grid_kind)
    rows = sorted((v for v in grid["variants"] if v["map"] == name), key=lambda v: v["options"]["iterations"])
    assert rows, (grid["name"], name)
    return rows


def test_eq42_eq151_iterative_map_improves_with_every_pass_up_to_its_default(study):
    """Target: the converging form never degrades as n grows up to its default (measured on every
    grid: each pass divides the mean next-apex error by 1.5-10 up to n = 6)."""
    from slipmaps.runtime.api.index import get

    default = get("iterative").resolve({})["iterations"]
    for grid in study:
        rows = _passes(study, grid["kind"], "iterative")
        means = [r["apex_error"]["mean"] for r in rows][: default + 1]
        assert len(means) == default + 1, (grid["name"], means)
        assert all(b < a for a, b in zip(means, means[1:], strict=False)), (grid["name"], means)


def test_iterative_map_meets_the_yu_target(record):
    """Target: mean < 3 % at every angle and < 1 % at 68 and 72 deg (measured at the defaults:
    0.00665 / 0.00228 / 0.00103 / 0.00144 %)."""
    yu = next(g for g in record if g["kind"] == "yu")
    v = next(v for v in yu["variants"] if v["label"] == "iterative")
    by = {a["angle_of_attack_deg"]: a for a in v["by_angle"]}
    assert (
        all(a["mean"] < 0.03 for a in v["by_angle"]) and by[68.0]["mean"] < 0.01 and by[72.0]["mean"] < 0.01
    )
    assert not v["failures"]


def test_one_node_rule_does_not_converge_to_the_exact_stance(record):
    """Finding: with one node (the report's mean value (41)) the iteration's limit is far from the
    exact stance (measured 7-24 % on every grid at 6 passes); it is the quadrature, not the pass
    count, that bounds the error."""
    for grid in record:
        one = next(v for v in grid["variants"] if v["label"] == "iterative [nodes=1]")
        assert one["apex_error"]["mean"] > 0.05, grid["name"]


def test_accuracy_covers_every_map(record):
    names = {row["name"] for row in maps_index.MAPS}
    for grid in record:
        assert {v["map"] for v in grid["variants"]} == names, grid["name"]


def _mean(grid: dict, label: str) -> float:
    return next(v for v in grid["variants"] if v["label"] == label)["apex_error"]["mean"]


def test_eq46_eq77_every_gravity_type_beats_geyer_on_nonsymmetric_steps(record):
    """Finding: every type at its defaults has a smaller mean next-apex error than Geyer's map on the
    nonsymmetric grids and the Yu protocol (measured: 0.06x-0.42x)."""
    grids = [grid for grid in record if grid["kind"] != "symmetric"]
    assert grids
    for grid in grids:
        types = [v for v in grid["variants"] if v["default"] and v["map"].startswith("gravity")]
        assert len(types) == 6, (grid["name"], [v["label"] for v in types])
        for v in types:
            assert v["apex_error"]["mean"] < _mean(grid, "geyer"), (grid["name"], v["label"])


def test_eq46_eq77_no_gravity_type_reaches_geyer_on_symmetric_steps(record):
    """Finding (the docs state it): on symmetric steps, where the exact impulse is 0, every type is
    more than 1.1x Geyer's error (measured 1.16x-1.51x): P_c is computed from the map's own sweep,
    which is wrong by Geyer's angle error, so the correction adds an error of the same size."""
    grids = [grid for grid in record if grid["kind"] == "symmetric"]
    assert grids
    for grid in grids:
        types = [v for v in grid["variants"] if v["default"] and v["map"].startswith("gravity")]
        assert len(types) == 6, (grid["name"], [v["label"] for v in types])
        for v in types:
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
        defaults = [v for v in grid["variants"] if v["default"]]
        assert len(defaults) == len(maps_index.MAPS), grid["name"]
        for v in defaults:
            assert "NOT_CONVERGED" not in v["failures"], (grid["name"], v["label"])


def test_eq42_eq151_printed_iteration_does_not_converge_to_the_exact_stance(study):
    """Finding: the report's recursion as printed (both variants) is worse after two iterations than
    its zeroth iterate on every grid (measured: 0.22-11.4 % at n = 0, 10.5-23.3 % at n = 2) and
    stays above 5 % at n = 8, where H^{-1} of (33) is imaginary on some Yu steps (19 and 62 of 340)."""
    assert any(grid["kind"] == "yu" for grid in study)
    for grid in study:
        for variant in ("integrand", "factor"):
            rows = [
                r
                for r in _passes(study, grid["kind"], "iterative-report")
                if r["options"]["variant"] == variant
            ]
            assert len(rows) == len(convergence.PASSES), (grid["name"], variant)
            means = [r["apex_error"]["mean"] for r in rows]
            assert means[2] > means[0] and means[8] > 0.05, (grid["name"], variant, means)
            if grid["kind"] == "yu":
                assert rows[8]["failures"].get("IMAGINARY_MOMENTUM", 0) > 0, (variant, rows[8]["failures"])
