"""Benchmark: what the leg damping c costs each map that takes it, side by side in one run.

For every map whose declaration lists ``c`` (``slipmaps.maps()``, nothing listed here), its
public apex-return batch (``slipmaps.apex_return_batch``) per state on one numba thread, best of
``--repeat``, at 10 % of the human runner's critical damping (c = 0.1 * 2 sqrt(k_c m)) against the
same map at c = 0; for a map that extends a lossless one (``geyer-damped`` extends ``geyer``), also
against that map (its "undamped cost"). The issue's target: a damped map within 1.3x its undamped
cost per state. States: apex heights 1.0-1.1 m, speeds 3-7 m/s, touchdown angles 0.30-0.50 rad
(bench_maps.states, seed 0); the exact map runs on a tenth of them. Usage::

    python benchmarks/bench_damping.py [--n N] [--repeat R] [--json]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np
import slipmaps

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import best_of, machine, states, with_threads  # noqa: E402

P = slipmaps.HUMAN_RUNNER
#: 10 % of the human runner's critical damping.
DAMPED = P.with_(c=0.1 * 2.0 * math.sqrt(P.k_c * P.m))
#: The lossless map a damped map extends (its name without the suffix), where one exists.
SUFFIX = "-damped"
TARGET = 1.3


def _per_state(name: str, params, h, v, th, repeat: int) -> float:
    def run():
        return slipmaps.apex_return_batch(name, params, h, v, th)

    run()  # warm-up: compile or load from the cache
    return with_threads(1, lambda: best_of(run, repeat)) / len(h)


def run(n: int, repeat: int) -> dict:
    h, v, th, _ = states(n)
    rows = {}
    for info in slipmaps.maps():
        if "c" not in info.params:
            continue
        k = max(1, n // 10) if info.name == "exact" else n
        args = (h[:k], v[:k], th[:k])
        times = {
            "damped": _per_state(info.name, DAMPED, *args, repeat),
            "c0": _per_state(info.name, P, *args, repeat),
        }
        base = info.name.removesuffix(SUFFIX)
        if base != info.name and any(m.name == base for m in slipmaps.maps()):
            times["lossless"] = _per_state(base, P, *args, repeat)
        ok = slipmaps.apex_return_batch(info.name, DAMPED, *args)["status"] == 0
        rows[info.name] = {
            "states": k,
            "ok_fraction": float(np.mean(ok)),
            **{f"{key}_ns": 1e9 * t for key, t in times.items()},
            "ratio_c0": times["damped"] / times["c0"],
            **(
                {"ratio_lossless": times["damped"] / times["lossless"], "lossless_map": base}
                if "lossless" in times
                else {}
            ),
        }
    return {"machine": machine(), "n": n, "repeat": repeat, "c": DAMPED.c, "maps": rows}


def report(r: dict) -> str:
    lines = [
        f"damping benchmark: c = {r['c']:.1f} N s/m (10 % critical), n = {r['n']}, best of {r['repeat']}, "
        f"one thread; {r['machine']['cpu']}",
        f"{'map':<16} {'damped ns':>10} {'c=0 ns':>9} {'ratio':>6} {'lossless map':>22} {'ratio':>6}  ok",
    ]
    for name, row in r["maps"].items():
        lossless = f"{'-':>22} {'-':>6}"
        if "ratio_lossless" in row:
            base = f"{row['lossless_map']} {row['lossless_ns']:.0f}"
            lossless = f"{base:>22} {row['ratio_lossless']:>6.2f}"
        lines.append(
            f"{name:<16} {row['damped_ns']:>10.0f} {row['c0_ns']:>9.0f} {row['ratio_c0']:>6.2f} {lossless}  "
            f"{row['ok_fraction']:.0%}"
        )
    worst = max(max(row["ratio_c0"], row.get("ratio_lossless", 0.0)) for row in r["maps"].values())
    lines.append(f"largest ratio {worst:.2f} (target: at most {TARGET})")
    return "\n".join(lines)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=100_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    r = run(args.n, args.repeat)
    print(json.dumps(r, indent=1) if args.json else report(r))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
