"""Benchmark: one swing-leg policy (``slipmaps.swing_policy``, issue 30) against the deadbeat solves it
is made of, in one run.

The policy of the blind-running example (the human runner's apex 1.3 m, 5 m/s, the same target, 64
grounds over +-0.3 l0) for ``geyer`` (the angle alone), ``iterative`` (the angle alone, and the angle
and k_d): per policy, the median and the best of ``--repeat`` calls (validation, the batch deadbeat,
the table and its slopes); beside it the batch deadbeat of the same 64 grounds alone
(``Deadbeat.plan_batch``) and 64 scalar solves (``Deadbeat.plan``, one per ground), so the ratios say
what the table costs over its solves. Targets: a policy within 1 ms with ``iterative`` and 0.2 ms with
``geyer`` (absolute: they move with the machine and its load, printed).

    python benchmarks/bench_swing.py [--repeat R] [--json]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np
import slipmaps
from slipmaps.runtime.control.deadbeat import controller

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import machine  # noqa: E402

P = slipmaps.HUMAN_RUNNER
H, V, D, N = 1.3, 5.0, 0.3, 64
TARGETS_MS = {"geyer": 0.2, "iterative": 1.0}
CASES = (
    ("geyer", ("touchdown_angle",)),
    ("iterative", ("touchdown_angle",)),
    ("iterative", ("touchdown_angle", "k_d")),
)


def _times(f, repeat: int) -> np.ndarray:
    f()
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        out.append(time.perf_counter() - t)
    return np.array(out) * 1e3


def measure(repeat: int) -> dict:
    grounds = np.linspace(D, -D, N)
    rows = {}
    for name, controls in CASES:
        target_h = H if len(controls) > 1 else None

        def policy(name=name, controls=controls, target_h=target_h):
            slipmaps.swing_policy(name, P, H, V, target_h, V, grounds=(-D, D), controls=controls, n=N)

        ctl = controller(name, P, controls, None, {"budget": False})

        def batch(ctl=ctl, target_h=target_h):
            ctl.plan_batch(H, V, target_h, V, ground=grounds)

        def scalar(ctl=ctl, target_h=target_h):
            for g in grounds:
                ctl.plan(H, V, target_h, V, ground=float(g))

        p, b, s = _times(policy, repeat), _times(batch, repeat), _times(scalar, max(3, repeat // 5))
        rows[f"{name}: {' and '.join(controls)}"] = {
            "policy_ms_median": float(np.median(p)),
            "policy_ms_best": float(p.min()),
            "batch_ms_median": float(np.median(b)),
            "scalar_ms_median": float(np.median(s)),
            "target_ms": TARGETS_MS[name] if controls == ("touchdown_angle",) else None,
        }
    return {"machine": machine(), "grounds": N, "rows": rows}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=50)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args(argv)
    rec = measure(args.repeat)
    if args.json:
        print(json.dumps(rec, indent=1))
        return 0
    m = rec["machine"]
    load = " ".join(f"{x:.2f}" for x in __import__("os").getloadavg())
    print(f"swing policy of {N} grounds; {m['cpu']}, {m['cpus']} cpus, load {load}")
    print(
        f"{'policy':36s} {'policy ms':>10s} {'best':>7s} {'batch ms':>9s} "
        f"{'64 scalar ms':>13s} {'target':>8s}"
    )
    for label, r in rec["rows"].items():
        target = r["target_ms"]
        verdict = (
            ""
            if target is None
            else f"{target:g} ms {'met' if r['policy_ms_median'] <= target else 'NOT met'}"
        )
        print(
            f"{label:36s} {r['policy_ms_median']:10.3f} {r['policy_ms_best']:7.3f} "
            f"{r['batch_ms_median']:9.3f} {r['scalar_ms_median']:13.3f} {verdict:>8s}"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
