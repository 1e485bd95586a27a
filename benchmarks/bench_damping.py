"""Benchmark: what the leg damping c costs each map that takes it, side by side in one run.

For every map whose declaration lists ``c`` (``slipmaps.maps()``, nothing listed here), its public
apex-return batch (``slipmaps.apex_return_batch``) per state on one numba thread, best of
``--repeat`` rounds that time every case once in turn (the load moves them alike): at 10 % and 20 %
of the human runner's critical damping 2 sqrt(k_c m) (both liftoff conventions at 10 % where the map
has the option ``liftoff``) against the same map at c = 0, and for a map that extends a lossless one
(``geyer-damped`` extends ``geyer``) against that map too. The issue's target: a damped map within
1.3x its undamped cost per state. States: apex heights 1.0-1.1 m, speeds 3-7 m/s, touchdown angles
0.30-0.50 rad (bench_maps.states, seed 0); the exact map runs on a tenth of them. Usage::

    python benchmarks/bench_damping.py [--n N] [--repeat R] [--json]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np
import slipmaps

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import machine, states, with_threads  # noqa: E402

P = slipmaps.HUMAN_RUNNER
CRITICAL = 2.0 * math.sqrt(P.k_c * P.m)
#: The name ending of a damped map that extends a lossless one (its name without it).
SUFFIX = "-damped"
TARGET = 1.3


def _cases(info) -> dict[str, tuple[str, object, dict]]:
    """Case label -> (map, parameters, options) of one map that takes c."""
    cases = {"c = 0": (info.name, P, {})}
    base = info.name.removesuffix(SUFFIX)
    if base != info.name and any(m.name == base for m in slipmaps.maps()):
        cases[f"{base} (lossless)"] = (base, P, {})
    has_liftoff = any(o.name == "liftoff" for o in info.options)
    for ratio in (0.1, 0.2):
        damped = P.with_(c=ratio * CRITICAL)
        cases[f"{ratio:.0%} force" if has_liftoff else f"{ratio:.0%}"] = (info.name, damped, {})
        if has_liftoff and ratio == 0.1:
            cases[f"{ratio:.0%} length"] = (info.name, damped, {"liftoff": "length"})
    return cases


def _measure(info, h, v, th, repeat: int) -> dict:
    cases = _cases(info)
    for name, params, options in cases.values():
        slipmaps.apex_return_batch(name, params, h[:100], v[:100], th[:100], **options)  # warm-up

    def once(name, params, options) -> float:
        t0 = time.perf_counter()
        slipmaps.apex_return_batch(name, params, h, v, th, **options)
        return time.perf_counter() - t0

    best = dict.fromkeys(cases, math.inf)
    for _ in range(repeat):
        for label, case in cases.items():
            best[label] = min(best[label], with_threads(1, lambda c=case: once(*c)))
    rows = {}
    for label, (name, params, options) in cases.items():
        ok = slipmaps.apex_return_batch(name, params, h, v, th, **options)["status"] == 0
        rows[label] = {
            "ns": 1e9 * best[label] / len(h),
            "ratio_c0": best[label] / best["c = 0"],
            "ok_fraction": float(np.mean(ok)),
        }
    lossless = next((k for k in cases if k.endswith("(lossless)")), None)
    if lossless:
        for row in rows.values():
            row["ratio_lossless"] = row["ns"] / rows[lossless]["ns"]
    return {"states": len(h), "cases": rows}


def run(n: int, repeat: int) -> dict:
    h, v, th, _ = states(n)
    out = {}
    for info in slipmaps.maps():
        if "c" in info.params:
            k = max(1, n // 10) if info.name == "exact" else n
            out[info.name] = _measure(info, h[:k], v[:k], th[:k], repeat)
    return {"machine": machine(), "n": n, "repeat": repeat, "critical": CRITICAL, "maps": out}


def report(r: dict) -> str:
    lines = [
        f"damping benchmark: apex_return_batch per state, one thread, best of {r['repeat']} interleaved "
        f"rounds; critical damping {r['critical']:.0f} N s/m; {r['machine']['cpu']}",
    ]
    worst = 0.0
    for name, m in r["maps"].items():
        lines += [
            "",
            f"{name} ({m['states']} states)",
            f"    {'case':<20}{'ns':>8}{'x c=0':>8}{'x lossless':>12}  ok",
        ]
        for label, row in m["cases"].items():
            vs = f"{row['ratio_lossless']:>12.2f}" if "ratio_lossless" in row else f"{'-':>12}"
            lines.append(
                f"    {label:<20}{row['ns']:>8.0f}{row['ratio_c0']:>8.2f}{vs}  {row['ok_fraction']:.0%}"
            )
            if "%" in label:
                worst = max(worst, row["ratio_c0"], row.get("ratio_lossless", 0.0))
    lines.append(f"\nlargest damped ratio {worst:.2f} (target: at most {TARGET})")
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
