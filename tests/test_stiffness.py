"""The variable-stiffness study (docs/stiffness.md, .json, .png) re-measured, its findings, and the
bottom leg length of (153) (kernel ``bottom_quartic``) against the exact simulator.

The study runs once per module (the exact steps of 4 grids at 8 ratios k_d/k_c and 5 map variants:
about 6-12 s after compilation, less when tests/test_accuracy.py has found the symmetric gaits in
the same session). The re-measured numbers must match the committed docs/stiffness.json
(tolerances: tests/records.py); docs/stiffness.md must be exactly the rendering of that record.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from records import assert_close
from slipmaps import HUMAN_RUNNER
from slipmaps.generated import slip_model
from slipmaps.generated.geyer_vs import bottom_quartic
from slipmaps.runtime.exact.reference import simulate_step
from slipmaps.runtime.studies import stiffness
from slipmaps.runtime.studies.grids import Grid
from slipmaps.runtime.studies.stiffness_report import TARGET, render_markdown, target_rows

DOCS = Path(__file__).resolve().parent.parent / "docs"


@pytest.fixture(scope="module")
def measured() -> list[dict]:
    return stiffness.summarize(stiffness.measure(show_progress=False))


@pytest.fixture(scope="module")
def record() -> list[dict]:
    return stiffness.from_json((DOCS / "stiffness.json").read_text())


def test_stiffness_record_is_current(measured, record):
    """docs/stiffness.json re-measured (regenerate with `slipmaps accuracy` after changing a map)."""
    assert_close(measured, record, "grids")


def test_stiffness_markdown_renders_the_record(record):
    assert (DOCS / "stiffness.md").read_text() == render_markdown(record)


def _finite_stats(stats: dict, path: str) -> None:
    assert set(stats) == {"mean", "max"}, path
    assert all(isinstance(x, float) and math.isfinite(x) and x >= 0.0 for x in stats.values()), (path, stats)
    assert stats["mean"] <= stats["max"], (path, stats)


def test_summary_of_a_tiny_grid_has_every_key_and_finite_values():
    grid = Grid("tiny", "nonsymmetric", HUMAN_RUNNER, heights=(1.0,), speeds=(3.5, 4.0), angles=(0.3, 0.35))
    study = stiffness.measure(chosen_grids=[grid], ratios=(0.8, 1.25), show_progress=False)
    (g,) = stiffness.summarize(study)
    assert set(g) == {
        "name",
        "kind",
        "description",
        "params",
        "n_points",
        "no_symmetric_gait",
        "ratios",
        "bottom",
    }
    assert g["n_points"] == 4 and [r["ratio"] for r in g["ratios"]] == [0.8, 1.25]
    labels = [v.label for v in stiffness.variants()]
    for r in g["ratios"]:
        assert set(r) == {"ratio", "exact_ok", "exact_failures", "variants"}
        assert r["exact_ok"] == 4 and not r["exact_failures"]
        assert [v["label"] for v in r["variants"]] == labels
        for v in r["variants"]:
            assert v["n_compared"] >= 1, v["label"]
            assert v["n_compared"] + sum(v["failures"].values()) == r["exact_ok"], v["label"]
            for e in stiffness.ERRORS:
                _finite_stats(v[e.key], f"{r['ratio']} {v['label']} {e.key}")
    b = g["bottom"]
    assert b["n_bottoms"] == 4 and [e["equation"] for e in b["estimates"]] == list(stiffness.BOTTOM_ESTIMATES)
    for e in b["estimates"]:
        assert e["n_compared"] == 4 and not e["failures"]
        _finite_stats(e["of_compression"], e["equation"])
        _finite_stats(e["of_length"], e["equation"])


def test_study_covers_every_variable_stiffness_map_and_every_continuity_and_gravity():
    labels = {v.label for v in stiffness.variants()}
    assert labels == {
        "geyer-damped",
        "geyer-vs",
        "geyer-vs [continuity=report]",
        "geyer-vs [continuity=constrained]",
        "geyer-vs [gravity=type3]",
        "geyer-vs [gravity=type4]",
        "iterative",
        "iterative-report",
    }


def test_issue_target_met_by_the_iterative_map(record):
    """Target: the next apex height within 1 % of l0 and speed within 2 % over k_d/k_c in
    [0.8, 1.25] on the human runner grids, no map failure (measured for `iterative`: 7.13e-04 % of
    l0 and 0.00628 %; 0.00115 % and 0.00910 % over [0.6, 1.5]). No other variant meets it (geyer-vs
    misses the height by up to 6.6 % of l0 on the nonsymmetric grid)."""
    rows = {r["label"]: r for r in target_rows(record)}
    best = rows["iterative"]
    assert best["met"] and best["all"]["failures"] == 0
    assert all(best["all"][k] < t for k, t in TARGET.items())
    others = [r for label, r in rows.items() if label != "iterative"]
    assert others and not any(r["met"] for r in others)


def _bottom(record: list[dict], kind: str, key: str) -> list[dict]:
    rows = [
        next(e for e in g["bottom"]["estimates"] if e["equation"] == key)
        for g in record
        if (g["kind"] == "symmetric") == (kind == "symmetric")
    ]
    assert rows, (kind, key)
    return rows


def test_eq153_with_the_touchdown_momentum_misses_the_bottom_and_eq154_is_closer(record):
    """Finding: with the touchdown p_th, (153) misses even the vertical bottom of a symmetric gait by
    a mean 8.5-9.8 % of the compression (measured; the gravity torque changes p_th by a few % during
    the compression); Geyer et al.'s bottom (154) is closer on every grid (mean 1.2-5.1 %)."""
    for kind in ("symmetric", "nonsymmetric"):
        for e153, e154 in zip(_bottom(record, kind, "153"), _bottom(record, kind, "154"), strict=True):
            assert e153["of_compression"]["mean"] > 0.05
            assert e154["of_compression"]["mean"] < e153["of_compression"]["mean"]


def test_eq153_quartic_root_is_the_exact_bottom_of_symmetric_gaits():
    """(153) holds at a vertical bottom: with the exact bottom's angular momentum and the touchdown's
    total energy (27) with k_c, the quartic's root is the exact bottom leg length of a symmetric gait
    (bottom at q_th = 0). Measured on the 30 symmetric gaits of the study: within 2.4e-12 of q_r_b
    and 1.43e-11 of the compression l0 - q_r_b (the exact simulator's precision); tolerance 1e-9 of
    the compression. The exact bottom depends on k_c only, so the check holds for any k_d."""
    symmetric = [g for g in stiffness.grids() if g.kind == "symmetric"]
    assert symmetric
    for grid in symmetric:
        p = grid.params.with_(k_d=0.8 * grid.params.k_c)
        points = grid.points()[::4]
        assert len(points), grid.name
        for h, v, angle in points:
            step = simulate_step(p, h, v, angle)
            q_r, _, q_th, q_thd = step.bottom
            assert abs(q_th) < 1e-12
            energy = slip_model.stance_energy(*step.touchdown, p.m, p.l0, p.k_c, p.g_s)
            root, status = bottom_quartic(p.m * q_r**2 * q_thd, energy, p.m, p.l0, p.k_c, p.g_s)
            assert status == 0
            np.testing.assert_allclose(root, q_r, rtol=0.0, atol=1e-9 * (p.l0 - q_r))
