"""Benchmark: the exported C library (``slipmaps generate --target c``) against the numba kernels, side
by side in one run, one core.

For every analytic map at its default options: the apex return and its Jacobian per state, over the
same ``--n`` states near the human runner's gait (apex 0.9-1.3 m, 3-6 m/s, touchdown angle
0.2-0.4 rad): numba's generated batch form (``<kernel>_rows``, serial) and the C library's batch
driver ``slipmaps_rows`` (one ctypes call per batch: a C loop), compiled with ``-O2`` and with
``-O2 -fno-math-errno`` (the kernels never read errno: numba's error model is numpy's). Best of
``--repeat``. Target: the C apex return within 1.2x numba's per-state cost.

    python benchmarks/bench_c.py [--n N] [--repeat R] [--json]
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import slipmaps
from slipmaps.runtime.api.calls import Call
from slipmaps.runtime.export.clib import STRICT, CLibrary, compile_library, compiler

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import machine  # noqa: E402

#: The apex return's target: C per state over numba per state.
TARGET_RATIO = 1.2
BUILDS = {"O2": (), "O2-no-errno": ("-fno-math-errno",)}
#: The inputs' ranges (a forward gait near the human runner's).
RANGES = {
    "b_y_apex": (0.9, 1.3),
    "b_xd_apex": (3.0, 6.0),
    "q_th_td": (0.2, 0.4),
    "ground": (0.0, 0.0),
    "retraction_rate": (0.0, 0.0),
}


def build(out: Path) -> dict[str, CLibrary]:
    """Generate the C library into ``out`` and compile it once per build of :data:`BUILDS`."""
    from slipmaps.derive import ctarget

    ctarget.write(out)

    def one(item):
        name, extra = item
        lib = compile_library([out / ctarget.SOURCE], out / f"lib{name}.so", extra=extra)
        return name, CLibrary(lib)

    with ThreadPoolExecutor(2) as pool:
        return dict(pool.map(one, BUILDS.items()))


def _best(f, repeat: int) -> float:
    f()
    best = np.inf
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - t)
    return best


def _side_by_side(libs: dict[str, CLibrary], spec, X, P, repeat: int) -> dict:
    """Seconds per state of numba's batch form and of each C build, on the same rows."""
    n = X.shape[0]
    numba_rows = spec.functions()[1]
    OUT = np.empty((n, spec.width))
    STATUS = np.empty(n, dtype=np.int64)
    t_numba = _best(lambda: numba_rows(X, P, OUT, STATUS), repeat) / n
    row = {"ok": float(np.mean(STATUS == 0)), "numba_us": t_numba * 1e6}
    for name, lib in libs.items():
        t = _best(lambda lib=lib: lib.rows(spec.name, X, P, spec.width), repeat) / n
        row[f"c_{name}_us"] = t * 1e6
        row[f"ratio_{name}"] = t / t_numba
    return row


def measure(libs: dict[str, CLibrary], n: int, repeat: int) -> list[dict]:
    rng = np.random.default_rng(0)
    rows = []
    for info in slipmaps.maps():
        if info.name == "exact":
            continue
        call = Call.of(info.name, slipmaps.HUMAN_RUNNER, {})
        for role in ("apex_return", "apex_return_jacobian"):
            spec = call.kernels[role]
            X = np.column_stack([rng.uniform(*RANGES[x], n) for x in spec.x])
            P = call.record(spec)[None, :]
            rows.append({"map": info.name, "role": role, **_side_by_side(libs, spec, X, P, repeat)})
    return rows


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=100_000, help="states per map and role")
    ap.add_argument("--repeat", type=int, default=5, help="best of this many batches")
    ap.add_argument("--json", action="store_true", help="print the results as JSON")
    args = ap.parse_args(argv)
    cc = compiler()
    if cc is None:
        print("no C compiler (set CC, or install gcc or clang): nothing to measure")
        return 0
    with tempfile.TemporaryDirectory() as tmp:
        libs = build(Path(tmp))
        rows = measure(libs, args.n, args.repeat)
    info = {**machine(), "cc": cc, "flags": " ".join(STRICT)}
    if args.json:
        print(json.dumps({"machine": info, "rows": rows}, indent=1))
        return 0
    print(f"C library against numba, per state, one core ({args.n} states, best of {args.repeat})")
    print(f"machine: {info['cpu']}, load {info['load_1min']:.2f}; {cc} {info['flags']}")
    head = f"{'map':18s} {'role':22s} {'ok':>5s} {'numba us':>9s}"
    for name in BUILDS:
        head += f" {'C ' + name + ' us':>18s} {'ratio':>6s}"
    print(head)
    met = []
    for r in rows:
        line = f"{r['map']:18s} {r['role']:22s} {r['ok']:5.2f} {r['numba_us']:9.3f}"
        for name in BUILDS:
            line += f" {r[f'c_{name}_us']:18.3f} {r[f'ratio_{name}']:6.2f}"
        print(line)
        if r["role"] == "apex_return":
            met.append(r["ratio_O2"] <= TARGET_RATIO)
    print(
        f"target: the C apex return (-O2) within {TARGET_RATIO}x numba's per state: "
        f"met for {sum(met)} of {len(met)} maps"
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
