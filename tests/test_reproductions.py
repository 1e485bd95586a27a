"""The reproductions study (docs/reproductions.md, .json, .png): published claims checked by code.

A slice of every claim is re-measured against the committed docs/reproductions.json (to its 6
digits: tests/records.py): Geyer et al.'s stances at one stiffness of each setting, the Yu protocol
at one angle of attack, Seyfarth et al.'s fixed points and return map of the exact and Geyer et
al.'s maps, the notebook's stiffness scan of the exact map with its bisected ranges, Heim and
Spröwitz's viable set on vibly's SLIP grid (whose published numbers are checked against vibly's
arrays, tests/data/vibly_slip_map.npz). Every verdict
of the record follows from its numbers by the rules of runtime/studies/reproductions.py, and the
committed docs/reproductions.md is the rendering of the record. A few seconds once compiled.
"""

from __future__ import annotations

import copy
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from records import assert_close
from slipmaps.runtime.api.index import EXACT
from slipmaps.runtime.studies import reproductions as rp
from slipmaps.runtime.studies import reproductions_gaits as gaits
from slipmaps.runtime.studies import reproductions_stance as stance
from slipmaps.runtime.studies import reproductions_viability as heim
from slipmaps.runtime.studies import study as pipeline
from slipmaps.runtime.studies.reproductions_report import render_markdown

DOCS = Path(__file__).resolve().parent.parent / "docs"
DATA = Path(__file__).resolve().parent / "data"


@pytest.fixture(scope="module")
def record() -> dict:
    return rp.from_json((DOCS / "reproductions.json").read_text())


def _as_written(x):
    """``x`` as the record's file holds it (6 significant digits, NaN as None)."""
    return pipeline.from_json(pipeline.to_json({"x": x}))["x"]


def _setting(record: dict, name: str) -> dict:
    return next(s for s in record["geyer"]["settings"] if s["name"] == name)


@pytest.mark.parametrize("name, stiffness, every", [("periodic", 30e3, 1), ("grid", 20e3, 17)])
def test_geyer_stance_errors_are_current(record, name, stiffness, every):
    """One stiffness of each setting (the grid's every 17th touchdown), each re-measured row against
    the recorded row of the same state."""
    states = stance.geyer_states(name, (stiffness,))[::every]
    rows, failed = stance.geyer_rows(states, show_progress=False)
    assert rows and failed == 0  # the slice is not empty
    recorded = _setting(record, name)["rows"]
    for row in _as_written(rows):
        same = [
            r
            for r in recorded
            if all(math.isclose(a, b, rel_tol=1e-5) for a, b in zip(r[:4], row[:4], strict=True))
        ]
        assert len(same) == 1, row[:4]
        assert_close(row, same[0], f"geyer.{name}{row[:4]}")


def test_yu_protocol_at_68_deg_is_current(record):
    """Every map on the protocol's 68 deg states (11 apex heights x 41 speeds), against its recorded
    statistics at that angle."""
    grid = replace(stance.YU_GRID, angles=(round(math.radians(90.0 - 68.0), 12),))
    measured = _as_written(stance.yu_record(grid, stance.yu_maps()))
    assert measured["states"] == 11 * 41 and measured["exact_ok"] > 0
    for m, r in zip(measured["maps"], record["yu"]["maps"], strict=True):
        assert m["map"] == r["map"]
        (at68,) = [a for a in r["by_angle"] if a["attack_deg"] == 68.0]
        assert_close(m["by_angle"], [at68], f"yu.{m['map']}.by_angle[68]")


def test_seyfarth_fixed_points_and_return_map_are_current(record):
    measured = _as_written(gaits.measure_seyfarth(names=[EXACT, "geyer"]))
    recorded = record["seyfarth"]
    for name in (EXACT, "geyer"):
        assert measured["fixed_points"][name], name
        assert_close(measured["fixed_points"][name], recorded["fixed_points"][name], f"seyfarth.{name}")
    assert_close(measured["return_map"], recorded["return_map"], "seyfarth.return_map")
    assert_close(measured["setting"], recorded["setting"], "seyfarth.setting")


def test_drake_exact_scan_and_stiffness_ranges_are_current(record):
    """The exact map's fixed points at 10.7 and 10.8, over the whole scan, and its bisected ranges."""
    measured = _as_written(gaits.measure_drake(show_progress=False, names=[EXACT]))
    assert_close(measured["subjects"][EXACT], record["drake"]["subjects"][EXACT], "drake.exact")


def test_heim_published_numbers_are_vibly_arrays():
    """The paper's numbers of the claim are those of vibly's published arrays (sheim/vibly's
    tests/integration/data/slip_map.npz), on the demo's grids."""
    ref = np.load(DATA / "vibly_slip_map.npz")
    _, s, _, angles = heim.vibly_grid()
    assert np.array_equal(ref["s_grid"], s) and np.array_equal(ref["a_grid"], angles)
    peak = int(np.argmax(ref["S_M"]))
    published = {
        "pairs": int(ref["Q_F"].size),
        "failed_pairs": int(ref["Q_F"].sum()),
        "viable_pairs": int(ref["Q_V"].sum()),
        "kernel_states": int((ref["S_M"] > 0).sum()),
        "measure_max": float(ref["S_M"][peak]),
        "measure_max_s": float(s[peak]),
        "measure_top": float(ref["S_M"][-1]),
        "failed_fingerprint": heim.fingerprint(ref["Q_F"]),
        "viable_fingerprint": heim.fingerprint(ref["Q_V"]),
    }
    assert _as_written(published) == heim.VIBLY
    # the fingerprint tells one pair apart
    flipped = ref["Q_V"].copy()
    flipped[90, 80] = not flipped[90, 80]
    assert heim.fingerprint(flipped) != heim.VIBLY["viable_fingerprint"]


def test_heim_viable_set_is_current(record):
    """vibly's SLIP grid on the exact map, both rules for the grid's border, against the record."""
    measured = _as_written(heim.measure_heim(show_progress=False))
    recorded = {k: v for k, v in record["heim"].items() if k != "verdict"}
    assert_close(measured, recorded, "heim")
    assert rp.heim_verdict(measured) == rp.HOLDS


def test_heim_verdict_refuses_a_record_that_contradicts_vibly(record):
    """One viable pair more (another fingerprint and count), or a lower peak of the measure: the
    claim does not hold."""
    for key, value in (("viable_fingerprint", "0" * 16), ("viable_pairs", 5067), ("measure_max", 0.28)):
        changed = copy.deepcopy(record["heim"])
        changed["ours"][key] = value
        assert rp.heim_verdict(changed) == rp.FAILS, key


def test_every_verdict_follows_from_its_numbers(record):
    """The verdicts and the numbers they are read from, recomputed from the record's other numbers
    by the same rules, are the recorded ones; every verdict is one of the three words."""
    stripped = copy.deepcopy(record)
    for s in stripped["geyer"]["settings"]:
        del s["summary"]
    for m in stripped["yu"]["maps"]:
        del m["verdict"], m["holds_at_attack_deg"]
    del stripped["seyfarth"]["verdicts"], stripped["drake"]["verdicts"], stripped["heim"]["verdict"]
    assert rp.add_verdicts(stripped) == record
    verdicts = [s["summary"]["verdict"] for s in record["geyer"]["settings"]]
    verdicts += [m["verdict"] for m in record["yu"]["maps"]]
    verdicts += [*record["seyfarth"]["verdicts"].values(), *record["drake"]["verdicts"].values()]
    verdicts += [record["heim"]["verdict"]]
    assert len(verdicts) == 3 + len(record["yu"]["maps"]) + 2 * len(record["drake"]["subjects"])
    assert set(verdicts) <= set(rp.VERDICTS)


def test_each_claims_filtered_statistics_are_over_some_states(record):
    """Geyer et al.'s domain and the Yu states kept are not empty, and the Yu counts add up: every
    state is kept or an exact failure, every kept state is compared or a map failure."""
    for s in record["geyer"]["settings"]:
        assert s["summary"]["domain_rows"] > 0, s["name"]
    yu = record["yu"]
    assert yu["states"] == 11 * 41 * 15
    assert 0 < yu["exact_ok"] == yu["states"] - sum(yu["exact_failures"].values())
    for m in yu["maps"]:
        assert 0 < m["compared"] == yu["exact_ok"] - sum(m["map_failures"].values()), m["map"]
        assert sum(a["n"] for a in m["by_angle"]) == m["compared"], m["map"]


def test_geyer_rule_names_the_narrower_domain():
    """Toy rows (k, h, v, attack, compression, sweep, q_r error, of compression, q_th error [deg]):
    within both tolerances up to 10 % compression, then 0.7 deg: holds up to 10 %; rows outside the
    domain (attack 58 deg, sweep 61 deg, compression 25 %) are ignored."""
    ok, bad = [0.001, 0.01, 0.1], [0.001, 0.01, 0.7]
    rows = [
        [1, 1, 1, 70.0, 0.05, 30.0, *ok],
        [1, 1, 1, 70.0, 0.10, 30.0, *ok],
        [1, 1, 1, 70.0, 0.15, 30.0, *bad],
        [1, 1, 1, 58.0, 0.02, 30.0, *bad],
        [1, 1, 1, 70.0, 0.02, 61.0, *bad],
        [1, 1, 1, 70.0, 0.25, 30.0, *bad],
    ]
    s = rp.geyer_summary({"rows": rows})
    assert (s["domain_rows"], s["verdict"], s["holds_up_to_compression"]) == (3, rp.NARROWER, 0.10)
    assert s["first_violation_compression"] == 0.15 and s["q_r_holds_up_to_compression"] == 0.15
    assert rp.geyer_summary({"rows": rows[:2]})["verdict"] == rp.HOLDS
    assert rp.geyer_summary({"rows": rows[2:]})["verdict"] == rp.FAILS


def test_reproductions_markdown_renders_the_record(record):
    text = (DOCS / "reproductions.md").read_text()
    assert text == render_markdown(record)
    assert text.startswith("<!-- GENERATED by `slipmaps accuracy`") and "do not edit" in text.splitlines()[0]
