"""Benchmark: what one call costs a user, warm, in one run (issue 29's call targets).

- a warm scalar call per map: ``slipmaps.apex_return(name, ...)`` and ``slipmaps.stance(name, ...)``
  (the public API: validation, the parameter record, the kernel, the result object), the best of
  ``--repeat`` rounds of 200 calls (target: at most 10 us);
- a batch of n rows (n = 1 ... 100) against n scalar calls on the same states
  (``slipmaps.apex_return_batch`` against a loop of ``slipmaps.apex_return``), per map: the batch
  must never be slower than the loop (target: ratio <= 1);
- a fresh process with a warm cache: the seconds from the end of ``import slipmaps`` to the first
  exact apex return's result (the kernels loaded from numba's cache, compiled once before in the
  same cache), median of ``--fresh`` processes (target: at most 1 s).

    python benchmarks/bench_calls.py [--repeat R] [--fresh F] [--maps a,b] [--json]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import slipmaps

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import machine  # noqa: E402

P = slipmaps.HUMAN_RUNNER
SIZES = (1, 2, 5, 10, 20, 50, 100)
SCALAR_TARGET_US = 10.0
FRESH_TARGET_S = 1.0

_FRESH = """
import time
t0 = time.perf_counter()
import slipmaps
t1 = time.perf_counter()
r = slipmaps.apex_return("exact", slipmaps.HUMAN_RUNNER, 1.0, 5.0, 0.35)
t2 = time.perf_counter()
assert r.ok, r.message
print(t1 - t0, t2 - t1)
"""


def _best_us(fn, calls: int, repeat: int) -> float:
    fn()
    rounds = []
    for _ in range(repeat):
        t = time.perf_counter()
        for _ in range(calls):
            fn()
        rounds.append((time.perf_counter() - t) / calls)
    return min(rounds) * 1e6


def scalar_us(name: str, repeat: int) -> dict:
    td = slipmaps.apex_return(name, P, 1.0, 5.0, 0.35)
    assert td.ok, (name, td.message)
    touchdown = (P.q_r_td, -1.5, 0.35, -4.5)
    return {
        "apex_return_us": _best_us(lambda: slipmaps.apex_return(name, P, 1.0, 5.0, 0.35), 200, repeat),
        "stance_us": _best_us(lambda: slipmaps.stance(name, P, touchdown), 200, repeat),
    }


def batch_against_loop(name: str, repeat: int) -> list[dict]:
    rng = np.random.default_rng(0)
    rows = []
    for n in SIZES:
        h, v, a = rng.uniform(1.0, 1.1, n), rng.uniform(3.0, 7.0, n), rng.uniform(0.30, 0.50, n)

        def batch(h=h, v=v, a=a):
            slipmaps.apex_return_batch(name, P, h, v, a)

        def loop(h=h, v=v, a=a):
            for i in range(h.size):
                slipmaps.apex_return(name, P, float(h[i]), float(v[i]), float(a[i]))

        calls = max(1, 200 // n)
        b, s = _best_us(batch, calls, repeat), _best_us(loop, calls, repeat)
        rows.append({"rows": n, "batch_us": b, "loop_us": s, "ratio": b / s})
    return rows


def fresh_seconds(processes: int) -> dict:
    """A first exact apex return in new processes sharing a cache it was compiled into before."""
    env = dict(os.environ)
    subprocess.run([sys.executable, "-c", _FRESH], env=env, check=True, capture_output=True)  # compiles
    runs = []
    for _ in range(processes):
        done = subprocess.run(
            [sys.executable, "-c", _FRESH], env=env, check=True, capture_output=True, text=True
        )
        imp, first = map(float, done.stdout.split())
        runs.append((imp, first))
    arr = np.array(runs)
    return {"import_s": float(np.median(arr[:, 0])), "first_exact_s": float(np.median(arr[:, 1]))}


def run(repeat: int, fresh: int, names: list[str]) -> dict:
    out = {"machine": machine(), "scalar": {}, "batch": {}}
    for name in names:
        out["scalar"][name] = scalar_us(name, repeat)
        out["batch"][name] = batch_against_loop(name, repeat)
    out["fresh"] = fresh_seconds(fresh)
    return out


def report(r: dict) -> str:
    m = r["machine"]
    lines = [
        f"machine: {m['cpu']}, {m['cpus']} CPUs, numba {m['numba']} ({m['numba_threads']} threads), "
        f"Python {m['python']}, 1-min load {m['load_1min']:.2f}",
        "",
        f"warm scalar calls, us per call (best round) (target <= {SCALAR_TARGET_US:g} us):",
    ]
    worst = 0.0
    for name, s in r["scalar"].items():
        worst = max(worst, s["apex_return_us"], s["stance_us"])
        lines.append(f"    {name:18s} apex_return {s['apex_return_us']:7.2f}   stance {s['stance_us']:7.2f}")
    lines.append(f"    worst {worst:.2f} us: {'met' if worst <= SCALAR_TARGET_US else 'NOT met'}")
    lines += ["", "batch of n rows against n scalar calls (ratio = batch / loop, target <= 1):"]
    lines.append("    map                " + "".join(f"{n:>8d}" for n in SIZES))
    highest = 0.0
    for name, rows in r["batch"].items():
        highest = max(highest, *(x["ratio"] for x in rows))
        lines.append(f"    {name:18s} " + "".join(f"{x['ratio']:8.2f}" for x in rows))
    lines.append(f"    highest ratio {highest:.2f}: {'met' if highest <= 1.0 else 'NOT met'}")
    f = r["fresh"]
    lines += [
        "",
        f"fresh process, warm cache: import slipmaps {f['import_s']:.2f} s, then the first exact apex return "
        f"{f['first_exact_s']:.2f} s (target <= {FRESH_TARGET_S:g} s: "
        f"{'met' if f['first_exact_s'] <= FRESH_TARGET_S else 'NOT met'})",
    ]
    return "\n".join(lines)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7, help="timed rounds, best kept (default 7)")
    ap.add_argument("--fresh", type=int, default=3, help="fresh processes, median kept (default 3)")
    ap.add_argument("--maps", default="", help="maps to time, comma-separated (default every map)")
    ap.add_argument("--json", action="store_true", help="print JSON instead of the report")
    args = ap.parse_args()
    names = [n for n in args.maps.split(",") if n] or [m.name for m in slipmaps.maps()]
    r = run(args.repeat, args.fresh, names)
    print(json.dumps(r, indent=1) if args.json else report(r))


if __name__ == "__main__":
    main()
