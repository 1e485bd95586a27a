"""Benchmark: a footholds replan (``slipmaps.footholds``, issue 53) on one core, at horizons 1-3,
beside the deadbeat solve of one hop.

Per model (``iterative``, ``geyer``) and horizon: a run of ``--replans`` hops over the second
family's course 0 of the footholds study (stepping stones 0.3-0.6 m wide, gaps 0.2-0.8 m, the human
runner at 5 m/s), then each of its apexes planned again ``--repeat`` times, warm-started from the
plan before as in the run (``slipmaps.runtime.studies.footholds.replan_times``: the study's page
shows the same); the median and the 95th percentile of each apex's best, and the candidate stone
sequences per plan. Beside them one deadbeat solve of the same map (``Deadbeat.plan``, the apex to
itself), so the ratio says how many hops' solves a replan costs. Targets at horizon 2: at most 2 ms
with ``iterative`` and 0.5 ms with ``geyer`` (the 95th percentile; absolute: they move with the
machine and its load, printed).

    python benchmarks/bench_footholds.py [--replans N] [--repeat R] [--json]
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np
import slipmaps
from slipmaps.runtime.control.deadbeat import Deadbeat
from slipmaps.runtime.studies.footholds import APEX, SPEED, replan_times

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import machine  # noqa: E402

TARGETS_US = {"iterative": 2000.0, "geyer": 500.0}


def _deadbeat_us(name: str, repeat: int = 200) -> float:
    """The median of ``repeat`` deadbeat solves of ``name`` from the study's apex to itself [us]."""
    params = slipmaps.HUMAN_RUNNER
    ctl = Deadbeat(name, params).warm()
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        ctl.plan(APEX, SPEED, APEX, SPEED)
        out.append(time.perf_counter() - t)
    return float(np.median(out) * 1e6)


def measure(replans: int, repeat: int) -> dict:
    rows = {}
    for name in ("iterative", "geyer"):
        one = _deadbeat_us(name)
        for horizon in (1, 2, 3):
            t = replan_times(name, horizon=horizon, replans=replans, repeat=repeat)
            rows[f"{name}, horizon {horizon}"] = {
                **t,
                "deadbeat_us": one,
                "target_us": TARGETS_US[name] if horizon == 2 else None,
            }
    return {"machine": machine(), "rows": rows}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--replans", type=int, default=40)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args(argv)
    rec = measure(args.replans, args.repeat)
    if args.json:
        print(json.dumps(rec, indent=1))
        return 0
    m = rec["machine"]
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"footholds replan, one core; {m['cpu']}, {m['cpus']} cpus, load {load}")
    print(
        f"{'model, horizon':22s} {'replans':>7s} {'median us':>10s} {'p95 us':>8s} {'sequences':>9s} "
        f"{'deadbeat us':>11s} {'ratio':>6s} {'target':>14s}"
    )
    for label, r in rec["rows"].items():
        target = r["target_us"]
        verdict = "" if target is None else f"{target:g} us {'met' if r['p95_us'] <= target else 'NOT met'}"
        ratio = r["median_us"] / r["deadbeat_us"]
        print(
            f"{label:22s} {r['replans']:7d} {r['median_us']:10.0f} {r['p95_us']:8.0f} "
            f"{r['candidates_median']:9.0f} {r['deadbeat_us']:11.1f} {ratio:6.1f} {verdict:>14s}"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
