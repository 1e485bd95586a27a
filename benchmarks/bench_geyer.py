"""Benchmark: Geyer et al.'s generated stance map (batch and scalar) versus the exact stance.

Measures in one run, for the human runner (runtime.params.HUMAN_RUNNER):

(a) batch throughput of ``apex_maps.apex_return_geyer_batch`` and ``stance_maps.geyer_stance_batch``
    over N states (default 1e6; numba ``parallel=True`` kernels through the runtime wrappers,
    input validation included), after a warm-up call so JIT compilation / cache loading is
    excluded; best of 5 runs;
(b) the per-call time of the scalar kernel called from Python, both through the runtime wrapper
    ``stance_maps.geyer_stance`` (validation + result dataclass) and the bare generated
    ``generated.geyer.geyer_stance`` (numba dispatch only); best of 5 runs;
(c) the per-call time of the exact stance, ``simulate.simulate_stance`` (``solve_ivp`` DOP853,
    rtol 1e-11), over 50 touchdown states; best of 3 runs;

and prints the speed-ups exact / batch and exact / scalar, with the machine facts (CPU model,
logical CPUs, numba threads and threading layer, Python / numba / numpy / scipy versions).

States: apex heights 1.0-1.1 m, speeds 3-7 m/s, touchdown angles 0.30-0.50 rad (uniform, seed 0);
the stance states are the touchdown states of those apexes. Usage::

    python benchmarks/bench_geyer.py [--n N] [--json]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import sys
import time

import numba
import numpy as np
import scipy
from slipmaps.generated import flight as gen_flight
from slipmaps.generated import geyer as gen_geyer
from slipmaps.runtime.apex_maps import apex_return_geyer_batch
from slipmaps.runtime.params import HUMAN_RUNNER
from slipmaps.runtime.simulate import simulate_stance
from slipmaps.runtime.stance_maps import geyer_stance, geyer_stance_batch

PARAMS = HUMAN_RUNNER


def cpu_model() -> str:
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.lower().startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine() or "unknown"


def machine() -> dict:
    try:
        affinity = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        affinity = os.cpu_count()
    return {
        "cpu": cpu_model(),
        "nproc": affinity,
        "cpu_count": os.cpu_count(),
        "numba_threads": numba.get_num_threads(),
        "numba_threading_layer": _threading_layer(),
        "python": platform.python_version(),
        "numba": numba.__version__,
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "platform": platform.platform(),
    }


def _threading_layer() -> str:
    try:
        return numba.threading_layer()
    except ValueError:  # no parallel kernel has run yet
        return "unknown"


def _load_average() -> float | None:
    """1-minute load average: other work on the machine slows the runs (and hides parallel gains)."""
    return os.getloadavg()[0] if hasattr(os, "getloadavg") else None


def apex_states(n: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    return rng.uniform(1.0, 1.1, n), rng.uniform(3.0, 7.0, n), rng.uniform(0.30, 0.50, n)


def touchdown_states(h: np.ndarray, v: np.ndarray, th: np.ndarray) -> np.ndarray:
    """Touchdown states of the apexes (exact ballistic descent, the generated flight kernel)."""
    out = np.empty((h.size, 4))
    for i in range(h.size):
        res = gen_flight.apex_to_touchdown(h[i], v[i], th[i], PARAMS.q_r_td, PARAMS.g_f)
        out[i] = res[:4]
    return out


def best_of(fn, repeat: int) -> float:
    best = math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def _rate(seconds: float, n: int, status: np.ndarray | None = None) -> dict:
    out = {"seconds": seconds, "calls_per_s": n / seconds, "ns_per_call": 1e9 * seconds / n}
    if status is not None:
        out["ok_fraction"] = float(np.mean(status == 0))
    return out


def run(n: int, repeat: int = 5, n_scalar: int = 20_000, n_exact: int = 50) -> dict:
    p = PARAMS
    load_before = _load_average()
    h, v, th = apex_states(n)
    # The stance states: touchdowns of the first apexes, tiled to n (the descent is not timed).
    n_unique = min(n, 100_000)
    td_unique = touchdown_states(h[:n_unique], v[:n_unique], th[:n_unique])
    tds = np.resize(td_unique, (n, 4))

    # (a) batch, after a warm-up call (JIT compile or cache load, thread pool start).
    apex_return_geyer_batch(p, h[:1000], v[:1000], th[:1000])
    geyer_stance_batch(p, tds[:1000])
    t_apex = best_of(lambda: apex_return_geyer_batch(p, h, v, th), repeat)
    t_stance = best_of(lambda: geyer_stance_batch(p, tds), repeat)
    _, st_apex = apex_return_geyer_batch(p, h, v, th)
    _, st_stance = geyer_stance_batch(p, tds)
    # The bare generated kernels on preallocated contiguous arrays (no validation, no allocation),
    # with all numba threads and with one, to separate the wrapper's cost and the parallel scaling.
    cols = [np.ascontiguousarray(tds[:, j]) for j in range(4)]
    prm_st = [np.full(n, x) for x in (p.m, p.l0, p.k, p.g_s, p.q_r_lo)]
    prm_ap = [np.full(n, x) for x in (p.m, p.l0, p.k, p.g_s, p.g_f, p.q_r_td, p.q_r_lo)]
    out_st, out_ap, status = np.empty((n, 10)), np.empty((n, 9)), np.empty(n, dtype=np.int64)

    def bare_stance():
        gen_geyer.geyer_stance_batch(*cols, *prm_st, out_st, status)

    def bare_apex():
        gen_geyer.geyer_apex_return_batch(h, v, th, *prm_ap, out_ap, status)

    threads = numba.get_num_threads()
    t_bare = {"apex": best_of(bare_apex, repeat), "stance": best_of(bare_stance, repeat)}
    numba.set_num_threads(1)
    try:
        t_bare1 = {"apex": best_of(bare_apex, repeat), "stance": best_of(bare_stance, repeat)}
    finally:
        numba.set_num_threads(threads)

    # (b) scalar calls from Python.
    sc = [tuple(float(x) for x in td) for td in td_unique[: min(n_scalar, n_unique)]]
    m, l0, k, g_s, q_r_lo = p.m, p.l0, p.k, p.g_s, p.q_r_lo
    kernel = gen_geyer.geyer_stance
    geyer_stance(p, sc[0])
    kernel(*sc[0], m, l0, k, g_s, q_r_lo)

    def wrapper_loop():
        for td in sc:
            geyer_stance(p, td)

    def kernel_loop():
        for td in sc:
            kernel(td[0], td[1], td[2], td[3], m, l0, k, g_s, q_r_lo)

    t_wrapper = best_of(wrapper_loop, repeat) / len(sc)
    t_kernel = best_of(kernel_loop, repeat) / len(sc)

    # (c) exact stance.
    ex_states = [tuple(float(x) for x in td) for td in td_unique[:n_exact]]
    simulate_stance(p, ex_states[0])
    ok_exact = sum(simulate_stance(p, td).ok for td in ex_states)

    def exact_loop():
        for td in ex_states:
            simulate_stance(p, td)

    t_exact = best_of(exact_loop, min(repeat, 3)) / len(ex_states)

    per_apex, per_stance = t_apex / n, t_stance / n
    return {
        "machine": {**machine(), "load_average_1min_before_run": load_before},
        "params": "HUMAN_RUNNER",
        "n": n,
        "repeat": repeat,
        "batch": {
            "apex_return_geyer_batch": _rate(t_apex, n, st_apex),
            "geyer_stance_batch": _rate(t_stance, n, st_stance),
            f"generated geyer_apex_return_batch, bare, {threads} threads": _rate(t_bare["apex"], n),
            f"generated geyer_stance_batch, bare, {threads} threads": _rate(t_bare["stance"], n),
            "generated geyer_apex_return_batch, bare, 1 thread": _rate(t_bare1["apex"], n),
            "generated geyer_stance_batch, bare, 1 thread": _rate(t_bare1["stance"], n),
        },
        "scalar": {
            "calls": len(sc),
            "geyer_stance_wrapper_us": 1e6 * t_wrapper,
            "geyer_stance_kernel_us": 1e6 * t_kernel,
        },
        "exact": {
            "calls": len(ex_states),
            "ok": ok_exact,
            "simulate_stance_ms": 1e3 * t_exact,
        },
        "ratios": {
            "exact_over_stance_batch": t_exact / per_stance,
            "exact_over_apex_batch": t_exact / per_apex,
            "exact_over_scalar_wrapper": t_exact / t_wrapper,
            "exact_over_scalar_kernel": t_exact / t_kernel,
        },
    }


def format_report(r: dict) -> str:
    mc, b, s, e, q = r["machine"], r["batch"], r["scalar"], r["exact"], r["ratios"]
    lines = [
        f"machine: {mc['cpu']}; nproc {mc['nproc']} (cpu_count {mc['cpu_count']}); numba threads "
        f"{mc['numba_threads']} ({mc['numba_threading_layer']} layer)",
        f"load average (1 min) before the run: {mc['load_average_1min_before_run']}",
        f"versions: Python {mc['python']}, numba {mc['numba']}, numpy {mc['numpy']}, scipy {mc['scipy']}",
        f"parameters: {r['params']}; N = {r['n']:,}; best of {r['repeat']} runs (exact: best of "
        f"{min(r['repeat'], 3)})",
        "",
        f"{'(a) batch (runtime wrappers unless bare)':<56}{'calls/s':>12}{'ns/call':>10}{'ok':>8}",
    ]
    for name, x in b.items():
        ok = f"{100 * x['ok_fraction']:>7.1f}%" if "ok_fraction" in x else ""
        lines.append(f"  {name:<54}{x['calls_per_s']:>12.3e}{x['ns_per_call']:>10.1f}{ok}")
    lines += [
        "",
        f"(b) scalar Geyer stance from Python ({s['calls']:,} calls)",
        f"  stance_maps.geyer_stance (wrapper)          {s['geyer_stance_wrapper_us']:10.2f} us/call",
        f"  generated.geyer.geyer_stance (kernel)       {s['geyer_stance_kernel_us']:10.2f} us/call",
        "",
        f"(c) exact stance, simulate_stance (solve_ivp DOP853, rtol 1e-11; {e['calls']} calls, {e['ok']} ok)",
        f"  {e['simulate_stance_ms']:.3f} ms/call",
        "",
        "speed-up of Geyer's map over the exact stance (exact time per call / map time per call)",
        f"  vs geyer_stance_batch        {q['exact_over_stance_batch']:12.3e}",
        f"  vs apex_return_geyer_batch   {q['exact_over_apex_batch']:12.3e}",
        f"  vs scalar wrapper            {q['exact_over_scalar_wrapper']:12.1f}",
        f"  vs scalar kernel             {q['exact_over_scalar_kernel']:12.1f}",
    ]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=float, default=1e6, help="number of batch states (default 1e6)")
    ap.add_argument("--repeat", type=int, default=5, help="timed runs, the best is kept (default 5)")
    ap.add_argument("--json", action="store_true", help="print the results as JSON")
    args = ap.parse_args(argv)
    n = int(args.n)
    if n < 1000 or args.repeat < 1:
        ap.error("--n must be >= 1000 and --repeat >= 1")
    result = run(n, repeat=args.repeat)
    print(json.dumps(result, indent=2) if args.json else format_report(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
