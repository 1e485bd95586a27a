"""The measured cost-accuracy front (runtime/api/pareto.json, written by benchmarks/bench_pareto.py)
that `slipmaps maps` shows: it covers every map at its defaults, its errors are what the maps
compute today (re-computed here on the same grids), its dominance follows from its costs and those
errors, it ships with the package, and the command line marks every dominated map with the variant
that dominates it. The costs are the benchmark's alone (no timing in the tests): a change that
moves a map's cost needs a new benchmark run, a change that moves its errors fails here."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest
import slipmaps
from slipmaps.runtime.api import index
from slipmaps.runtime.api.front import FRONT_FILE, at_defaults, dominated_by, errors_on, front, measurement
from slipmaps.runtime.cli.app import main
from slipmaps.runtime.studies.grids import GRIDS

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

ROOT = Path(__file__).resolve().parent.parent


def test_every_map_is_measured_at_its_defaults():
    assert {m.name for m in index.maps()} <= {v.map for v in front().values() if v.default}
    for m in index.maps():
        assert at_defaults(m.name) is not None, m.name
    labels = [r["label"] for r in measurement()["rows"]]
    assert len(labels) == len(set(labels))
    assert all(v.dominated_by is None or v.dominated_by in front() for v in front().values())


def test_the_front_ships_with_the_package():
    data = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]
    assert FRONT_FILE in data["slipmaps.runtime.api"]
    assert (ROOT / "runtime" / "api" / FRONT_FILE).is_file()


@pytest.fixture(scope="module")
def recomputed():
    """Every row's errors per grid, re-computed as the benchmark computes them."""
    meta = measurement()
    every = meta.get("every", 1)
    grids = [g for name in meta["grid_names"] for g in GRIDS if g.name == name]
    assert len(grids) == 2
    points = [[np.ascontiguousarray(a[::every]) for a in g.points().T] for g in grids]
    pairs = list(zip(grids, points, strict=True))
    refs = [slipmaps.apex_return_batch(index.EXACT, g.params, *pt) for g, pt in pairs]
    out = []
    for r in meta["rows"]:
        by_grid = [
            errors_on(slipmaps.apex_return_batch(r["map"], g.params, *pt, **r["options"]), ref)
            for g, pt, ref in zip(grids, points, refs, strict=True)
        ]
        out.append(
            {
                "label": r["label"],
                "ns_1_thread": r["ns_1_thread"],
                "requires": index.lookup(r["map"]).requires,
                "by_grid": by_grid,
            }
        )
    return out


def test_the_recorded_errors_are_todays(recomputed):
    for r, fresh in zip(measurement()["rows"], recomputed, strict=True):
        for old, new in zip(r["by_grid"], fresh["by_grid"], strict=True):
            assert old["failures"] == new["failures"], r["label"]
            assert old["compared"] == new["compared"], r["label"]
            for k in ("mean_error", "max_error"):
                assert new[k] == pytest.approx(old[k], rel=1e-3, abs=1e-13), (r["label"], k)


def test_the_dominance_follows_from_the_costs_and_todays_errors(recomputed):
    assert dominated_by(recomputed) == [r["dominated_by"] for r in measurement()["rows"]]


def test_a_map_is_dominated_only_by_one_that_runs_wherever_it_does():
    rows = measurement()["rows"]
    by_label = {r["label"]: r for r in rows}
    for r in rows:
        assert r["requires"] == list(index.lookup(r["map"]).requires)
        if r["dominated_by"] is not None:
            assert set(by_label[r["dominated_by"]]["requires"]) <= set(r["requires"])


def test_maps_marks_every_dominated_map_with_what_dominates_it(capsys):
    assert main(["maps"]) == 0
    out = capsys.readouterr().out
    for m in index.maps():
        v = at_defaults(m.name)
        first = next(line for line in out.splitlines() if line.split()[:1] == [m.name])
        assert first.split()[2] == ("front" if v.dominated_by is None else "dominated"), first
        if v.dominated_by is not None:
            by = front()[v.dominated_by]
            assert f"dominated by {by.label} ({by.command}:" in out
    assert main(["maps", "--json"]) == 0
    rows = {r["name"]: r for r in json.loads(capsys.readouterr().out)}
    for m in index.maps():
        assert rows[m.name]["dominated_by"] == at_defaults(m.name).dominated_by
    for h in index.halves():
        assert rows[h.name]["dominated_by"] is None and rows[h.name]["on_front"] is None
