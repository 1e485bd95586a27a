"""benchmarks/bench_versions.py without timing anything: its command line parses (``--help``) and its
report reads a record as the benchmark writes it (a made-up one: ratios, targets met or not, a
status difference between the trees, a map only one tree lists, the medians of back-to-back pairs
where the record has them)."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import pytest

PATH = Path(__file__).resolve().parent.parent / "benchmarks" / "bench_versions.py"


@pytest.fixture(scope="module")
def bench():
    spec = importlib.util.spec_from_file_location("bench_versions", PATH)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _timing(ns: float, statuses: dict | None = None) -> dict:
    return {"seconds": ns * 1e-9, "ns": ns, "load_1min": 0.5, "statuses": statuses or {"OK": 10}}


def _side(apex: float, jacobian: float, scalar: float, statuses: dict | None = None) -> dict:
    return {
        "apex_return": _timing(apex),
        "apex_return_nj": _timing(apex),
        "jacobian": _timing(jacobian, statuses),
        "scalar": {"apex_return_us": scalar, "stance_us": scalar, "load_1min": 0.5},
    }


def _record() -> dict:
    machine = {"numba": "0", "numba_threads": 2, "numpy": "0", "python": "3", "cpu": "CPU", "cpus": 2}
    first = [
        {
            "map": "geyer",
            "role": role,
            "version": v,
            "first_call_s": s,
            "first_call_cpu_s": s,
            "load_1min": 1.0,
        }
        for role, s in (("apex_return", 4.0), ("apex_return_jacobian", 12.0))
        for v in ("old", "new")
    ]
    return {
        "n": 1000,
        "repeat": 1,
        "rounds": 1,
        "python": {"old": "old/python", "new": "new/python"},
        "only_in": {"old": [], "new": ["newmap"]},
        "machine": {"old": machine, "new": machine},
        "geyer": {
            v: {"handwritten_ns": 20.0, "api_ns": api, "load_1min": 0.5, "same_status": True}
            for v, api in (("old", 30.0), ("new", 40.0))
        },
        "maps": [
            {
                "map": "geyer",
                "exact": False,
                "old": {**_side(100, 200, 9.0), "jacobian_shape": [12, 5], "pairs": [2.0, 2.4, 9.0]},
                "new": {**_side(105, 250, 9.5), "jacobian_shape": [13, 6], "pairs": [2.1, 2.2, 2.3, 8.0]},
            },
            {
                "map": "exact",
                "exact": True,
                "old": _side(1000, 2000, 20.0),
                "new": _side(1500, 2200, 21.0, {"OK": 9, "FALL": 1}),
            },
        ],
        "first_calls": first,
    }


def test_the_command_line_parses(bench, capsys):
    with pytest.raises(SystemExit) as exc:
        bench.main(["--help"])
    assert exc.value.code == 0
    assert "--old" in capsys.readouterr().out


def test_the_report_of_a_record(bench, tmp_path, capsys):
    text = bench.report(_record())
    rows: dict[str, str] = {}  # each map's row of the batch table (its first-call row comes later)
    for line in text.splitlines():
        if line.startswith("    "):
            rows.setdefault(line.split()[0], line)
    assert " 1.05 " in rows["geyer"] and " 1.25 " in rows["geyer"] and " 2.38x" in rows["geyer"]
    assert " 1.50 " in rows["exact"]
    assert "slowest new/old: apex return 1.50 (NOT met), jacobian 1.25 (NOT met)" in text
    assert "jacobian / apex return 2.38 (met)" in text and "scalar 21.00 us (NOT met)" in text
    assert "exact jacobian: old {'OK': 10}, new {'OK': 9, 'FALL': 1}" in text
    assert "maps only in new: newmap" in text
    # the same work per input: 1.25 x 5 / 6 (exact's record has no shapes: left out)
    assert "runs a pass per input), slowest 1.04:\n        geyer 12x5 -> 13x6: 1.04\n" in text
    assert "exact 12" not in text
    assert "old: public 30.0 ns, hand-written 20.0 ns per state: 1.50x (NOT met)" in text
    assert "new: public 40.0 ns, hand-written 20.0 ns per state: 2.00x (NOT met)" in text
    assert "apex_return 4.0 s (met); apex_return_jacobian 12.0 s (NOT met)" in text
    # the medians of the back-to-back pairs, where a record has them (exact's has none: left out)
    assert (
        "median of back-to-back pairs of calls" in text and "\n        geyer 2.40 / 2.25 (4 pairs)\n" in text
    )
    # the same report from the saved JSON record
    saved = tmp_path / "record.json"
    saved.write_text(json.dumps(_record()))
    assert bench.main(["--from-json", str(saved)]) == 0
    assert capsys.readouterr().out.strip() == text.strip()
