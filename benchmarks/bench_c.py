"""Benchmark: the exported C library (``slipmaps generate --target c``) against the numba kernels, side
by side in one run, one core.

For every analytic map at its default options: the apex return and its Jacobian per state, over the
same ``--n`` states near the human runner's gait (apex 0.9-1.3 m, 3-6 m/s, touchdown angle
0.2-0.4 rad): numba's generated batch form (``<kernel>_rows``, serial) and the C library's batch
driver ``slipmaps_rows`` (one ctypes call per batch: a C loop), compiled with ``-O2`` and with
``-O2 -fno-math-errno`` (the kernels never read errno: numba's error model is numpy's). Then the
deadbeat step: the C solver on the C maps beside the numba solver on the numba maps, on the same warm
rows (``--n`` / 50 of them), with the same answers. Best of ``--repeat``. Targets: the C apex return
within 1.2x numba's per-state cost; the C deadbeat step within 1 us for geyer, 10 us for iterative.

    python benchmarks/bench_c.py [--n N] [--repeat R] [--json]
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import slipmaps
from slipmaps.runtime.api.calls import Call
from slipmaps.runtime.export.clib import STRICT, CLibrary, compile_library, compiler

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import best_of, machine  # noqa: E402

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
        lib = compile_library([out / s for s in ctarget.SOURCES], out / f"lib{name}.so", extra=extra)
        return name, CLibrary(lib)

    with ThreadPoolExecutor(2) as pool:
        return dict(pool.map(one, BUILDS.items()))


def _best(f, repeat: int) -> float:
    """bench_maps' best of ``repeat``, after one call that warms caches and compiles."""
    f()
    return best_of(f, repeat)


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


#: The deadbeat steps timed: (map, controls), warm (a reachable target near the apex, the start
#: controls near the ones that reach it, as in a run). Targets: a C step within 1 us for geyer and
#: 10 us for iterative.
DEADBEAT = (
    ("geyer", ("touchdown_angle",)),
    ("geyer", ("touchdown_angle", "k")),
    ("iterative", ("touchdown_angle",)),
    ("iterative", ("touchdown_angle", "k_d")),
)
DEADBEAT_TARGET_US = {"geyer": 1.0, "iterative": 10.0}


def _deadbeat_case(lib: CLibrary, name: str, controls: tuple, n: int, repeat: int, rng) -> dict:
    from slipmaps.runtime.control.deadbeat import Deadbeat, default_angle
    from slipmaps.runtime.export import deadbeat_c

    ctl = Deadbeat(name, slipmaps.HUMAN_RUNNER, controls=controls)
    h, v = rng.uniform(0.95, 1.1, n), rng.uniform(4.0, 5.0, n)
    angle = default_angle(slipmaps.HUMAN_RUNNER, v)
    X = ctl._inputs({"apex_height": h, "apex_speed": v, "touchdown_angle": angle, "ground": 0.0 * h}, n)
    P = ctl._record_clipped()[None, :]
    # reachable targets: the next apex of controls near the start (the angle +- 0.02 rad, a
    # stiffness control +- 10 %), run through the map
    apex = ctl.call.spec("apex_return")
    Xt, Pt = X.copy(), np.repeat(P, n, axis=0)
    Xt[:, apex.x.index("q_th_td")] += rng.uniform(-0.02, 0.02, n)
    for c in controls[1:]:
        Pt[:, apex.p.index(c)] *= rng.uniform(0.9, 1.1, n)
    nxt = np.empty((n, apex.width))
    apex.functions()[1](Xt, Pt, nxt, np.empty(n, dtype=np.int64))
    both = len(controls) > 1
    h_next, v_next = nxt[:, apex.outputs.index("apex_height")], nxt[:, apex.outputs.index("apex_speed")]
    T = np.column_stack([h_next if both else 0.0 * h, v_next])
    s = ctl._settings[(1, 1) if both else (0, 1)]
    a = lib.address(ctl.call.spec("apex_return").name)
    j = lib.address(ctl.call.spec("apex_return_jacobian").name)
    OUT = np.empty((n, ctl.solver.width))
    t_numba = _best(lambda: ctl.solver._rows(X, P, T, s, OUT), repeat) / n
    t_c = _best(lambda: deadbeat_c.solve_rows(lib.lib, a, j, X, P, T, s), repeat) / n
    out_c, _ = deadbeat_c.solve_rows(lib.lib, a, j, X, P, T, s)
    same = np.array_equal(out_c[:, :5], OUT[:, :5]) and np.allclose(out_c, OUT, rtol=1e-12, equal_nan=True)
    return {
        "map": name,
        "controls": "+".join(controls),
        "reached": float(np.mean(OUT[:, 0] == 0)),
        "evaluations": float(np.mean(OUT[:, 3])),
        "numba_us": t_numba * 1e6,
        "c_us": t_c * 1e6,
        "same": bool(same),
    }


def measure_deadbeat(lib: CLibrary, n: int, repeat: int) -> list[dict]:
    """Per step: the C solver on the C maps (one ctypes call: a C loop over the rows) beside the
    numba solver on the numba maps (its serial batch form), on the same rows, and the same answers."""
    from slipmaps.runtime.export import deadbeat_c

    deadbeat_c.bind(lib.lib)
    rng = np.random.default_rng(1)
    return [_deadbeat_case(lib, name, controls, n, repeat, rng) for name, controls in DEADBEAT]


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
        steps = measure_deadbeat(libs["O2"], max(args.n // 50, 200), args.repeat)
    info = {**machine(), "cc": cc, "flags": " ".join(STRICT)}
    if args.json:
        print(json.dumps({"machine": info, "rows": rows, "deadbeat": steps}, indent=1))
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
    print("\nthe deadbeat step (warm: a reachable target near the apex), per step, one core, -O2")
    head = f"{'map':10s} {'controls':22s} {'reached':>7s} {'evals':>6s} {'numba us':>9s} {'C us':>8s}"
    print(head + f" {'target':>7s} same")
    for r in steps:
        target = DEADBEAT_TARGET_US[r["map"]]
        print(
            f"{r['map']:10s} {r['controls']:22s} {r['reached']:7.2f} {r['evaluations']:6.1f} "
            f"{r['numba_us']:9.2f} {r['c_us']:8.2f} {target:7.1f} {'yes' if r['same'] else 'NO'}"
            + ("" if r["c_us"] <= target else "  (target not met)")
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
