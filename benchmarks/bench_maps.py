"""Benchmark: every map's public batch API, a hand-written kernel, and solve_ivp, in one run.

Measured side by side, for the human runner (``slipmaps.HUMAN_RUNNER``):

(a) the yardstick: Geyer et al.'s stance map written by hand as one parallel numba kernel
    (``handwritten_geyer.py``), called on an (N, 4) array of touchdown states, output allocation
    included, and the public API ``slipmaps.stance_batch("geyer", ...)`` on the same array (what a
    user calls: option handling, allocation, the generated parallel kernel); their ratio (target:
    at most 1.4) and their agreement (max relative difference, same statuses);
(b) for every map of the index: ``slipmaps.stance_batch`` and ``slipmaps.apex_return_batch`` per
    state at N states, each after a warm-up call (compilation excluded), best of ``--repeat``;
(c) the exact stance (``solve_ivp`` DOP853, rtol 1e-11) per call over 50 touchdown states, and each
    map's speed-up over it;
(d) the iterative maps' cost against their number of passes;
(e) every map's apex-return Jacobian (``slipmaps.apex_return_jacobian_batch``, N/10 states) per state
    and as a multiple of its apex-return map (target: at most 3x), its stance Jacobian as a
    multiple of its stance map, and the generated kernels alone: the scalar apex-return Jacobian
    kernel against the scalar apex-return kernel, called in a numba loop on one thread (CPU time;
    without the batch API's allocation and checks of the larger Jacobian output);
(f) the first call of every map's apex-return Jacobian (``slipmaps.apex_return_jacobian``) in a
    fresh process with an empty ``NUMBA_CACHE_DIR``: the seconds a new user waits while numba
    compiles the Jacobian kernel and everything it calls (target: at most 10 s for the slowest, issue 29);
(g) the generated Jacobian modules' sizes (lines, longest line).

The leg damping's cost is measured by benchmarks/bench_damping.py.

States: apex heights 1.0-1.1 m, speeds 3-7 m/s, touchdown angles 0.30-0.50 rad (uniform, seed 0);
the stance states are their touchdowns. Ratios are measured in one run; absolute times move with the
machine and its load (printed). Usage::

    python benchmarks/bench_maps.py [--n N] [--repeat R] [--sections abcdefg] [--json]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numba
import numpy as np
import scipy
import slipmaps
from slipmaps.runtime.exact.reference import simulate_stance

sys.path.insert(0, str(Path(__file__).resolve().parent))
import handwritten_geyer  # noqa: E402

P = slipmaps.HUMAN_RUNNER
TARGET_RATIO = 1.4
#: Targets of the Jacobians (issue 17, item 6): cost in apex-return calls, first-call compile seconds.
TARGET_JACOBIAN_RATIO = 3.0
TARGET_FIRST_CALL_S = 10.0
GENERATED = Path(slipmaps.__file__).resolve().parent.parent.parent / "generated"

#: (f): one first call, timed in a fresh interpreter (its own empty numba cache).
_FIRST_CALL = """
import sys, time
import slipmaps
t0, c0 = time.perf_counter(), time.process_time()
jac = slipmaps.apex_return_jacobian(sys.argv[1], slipmaps.HUMAN_RUNNER, 1.0, 5.0, 0.35)
t1, c1 = time.perf_counter(), time.process_time()
assert jac.ok, jac.message
print(t1 - t0, c1 - c0)
"""


def machine() -> dict:
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            cpu = next((ln.split(":", 1)[1].strip() for ln in f if ln.lower().startswith("model name")), cpu)
    except OSError:
        pass
    return {
        "cpu": cpu,
        "cpus": len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count(),
        "numba_threads": numba.get_num_threads(),
        "python": platform.python_version(),
        "numba": numba.__version__,
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "load_1min": os.getloadavg()[0] if hasattr(os, "getloadavg") else None,
    }


def states(n: int, seed: int = 0) -> tuple[np.ndarray, ...]:
    from slipmaps.runtime.api import model  # here: the module's other helpers import with older trees

    rng = np.random.default_rng(seed)
    h, v, th = rng.uniform(1.0, 1.1, n), rng.uniform(3.0, 7.0, n), rng.uniform(0.30, 0.50, n)
    unique = min(n, 20_000)
    apex = {"b_y_apex": h[:unique], "b_xd_apex": v[:unique], "q_th_td": th[:unique]}
    _, down = model.rows("apex_to_touchdown", **apex, q_r_td=P.q_r_td, g_f=P.g_f)
    td = np.column_stack([down[f"touchdown_{q}"] for q in ("q_r", "q_rd", "q_th", "q_thd")])
    return h, v, th, np.ascontiguousarray(np.resize(td, (n, 4)))


def with_threads(n: int, fn):
    """fn() on n numba threads (the count restored after)."""
    before = numba.get_num_threads()
    numba.set_num_threads(n)
    try:
        return fn()
    finally:
        numba.set_num_threads(before)


def best_of(fn, repeat: int) -> float:
    best = math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def first_call_seconds(name: str) -> tuple[float, float]:
    """Seconds of the first ``apex_return_jacobian(name, ...)`` in a new process, empty numba cache:
    elapsed and CPU (the process's own, which other load on the machine disturbs less)."""
    with tempfile.TemporaryDirectory(prefix="slipmaps-numba-") as cache:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache}
        done = subprocess.run(
            [sys.executable, "-c", _FIRST_CALL, name], env=env, capture_output=True, text=True, check=True
        )
    wall, cpu = done.stdout.strip().splitlines()[-1].split()
    return float(wall), float(cpu)


def module_sizes() -> list[dict]:
    """Lines and longest line of every generated Jacobian module (and the total of generated/)."""
    rows = []
    for path in sorted(GENERATED.glob("*_jacobian.py")):
        lines = path.read_text().splitlines()
        rows.append({"module": path.name, "lines": len(lines), "longest": max(map(len, lines))})
    return rows


def run(n: int, repeat: int, sections: str = "abcdefg") -> dict:
    h, v, th, td = states(n)
    out: dict = {"machine": machine(), "n": n, "repeat": repeat}
    if "g" in sections:
        out["sizes"] = module_sizes()
        out["generated_lines"] = sum(len(p.read_text().splitlines()) for p in GENERATED.glob("*.py"))
    if "f" in sections:
        # first, on an idle interpreter: compile times are the most load-sensitive numbers
        out["first_call"] = []
        for info in slipmaps.maps():
            if info.has("apex_return_jacobian"):
                load = os.getloadavg()[0] if hasattr(os, "getloadavg") else None
                wall, cpu = first_call_seconds(info.name)
                out["first_call"].append(
                    {"map": info.name, "seconds": wall, "cpu_seconds": cpu, "load_1min": load}
                )
    if "e" in sections:
        out["jacobians"] = jacobians(h, v, th, td, max(1, n // 10), repeat)
    if not set(sections) & set("abcd"):
        return out
    prm = (P.m, P.l0, P.k, P.g_s, P.q_r_lo)

    # (a) yardstick, both called once first (compilation or cache load excluded)
    hand = handwritten_geyer.stance_batch(td, *prm)
    api = slipmaps.stance_batch("geyer", P, td)
    ok = hand[1] == 0
    api_out = np.column_stack([api[name] for name in api.names])
    diff = np.abs(hand[0][ok] - api_out[ok]) / np.maximum(1.0, np.abs(hand[0][ok]))
    t_hand = best_of(lambda: handwritten_geyer.stance_batch(td, *prm), repeat)
    t_api = best_of(lambda: slipmaps.stance_batch("geyer", P, td), repeat)
    out["yardstick"] = {
        "handwritten_ns": 1e9 * t_hand / n,
        "api_ns": 1e9 * t_api / n,
        "ratio": t_api / t_hand,
        "target": TARGET_RATIO,
        "same_status": bool(np.array_equal(hand[1], api["status"])),
        "max_rel_diff": float(diff.max()) if diff.size else math.nan,
    }

    # (c) the exact stance
    m = 50
    t_exact = best_of(lambda: [simulate_stance(P, td[i]) for i in range(m)], 3) / m
    out["exact_stance_us"] = 1e6 * t_exact

    # (b) every map
    out["maps"] = []
    for info in slipmaps.maps():
        if info.ground_truth:
            continue  # measured in (c)
        slipmaps.stance_batch(info.name, P, td[:1000])
        slipmaps.apex_return_batch(info.name, P, h[:1000], v[:1000], th[:1000])
        if info.name == "geyer":  # measured in (a), side by side with the yardstick
            t_st = t_api
        else:
            t_st = best_of(lambda name=info.name: slipmaps.stance_batch(name, P, td), repeat)
        t_ap = best_of(lambda name=info.name: slipmaps.apex_return_batch(name, P, h, v, th), repeat)
        res = slipmaps.stance_batch(info.name, P, td)
        passes = res["passes"][res.ok] if "passes" in res.names else None
        out["maps"].append(
            {
                "map": info.name,
                "stance_ns": 1e9 * t_st / n,
                "apex_return_ns": 1e9 * t_ap / n,
                "speedup_vs_solve_ivp": t_exact / (t_st / n),
                "ok_fraction": float(res.ok.mean()),
                "median_passes": float(np.median(passes)) if passes is not None and passes.size else None,
            }
        )

    # (d) cost against the number of passes of the iterative maps (tol = 0: exactly n passes)
    from slipmaps.runtime.api import index
    from slipmaps.runtime.studies import convergence
    from slipmaps.runtime.studies.accuracy import options_with

    out["passes"] = []
    for name in convergence.study_maps():
        tolerance = {o.name: 0.0 for o in options_with(index.get(name), "tolerance")}
        for k in convergence.PASSES:
            opts = {convergence.pass_option(name): k, **tolerance}
            t = best_of(lambda name=name, opts=opts: slipmaps.stance_batch(name, P, td, **opts), repeat)
            out["passes"].append({"map": name, "n": k, "stance_ns": 1e9 * t / len(td)})
    return out


@numba.njit
def _kernel_loop(kernel, X, p, out):
    """Calls the role ``kernel`` once per row of ``X`` (its ``x`` layout) with the parameter record
    ``p``, writing ``out``: the writes go to an array the caller holds, so the compiler cannot drop
    any output's code; returns the sum of the first outputs and statuses (a checksum)."""
    s = 0.0
    for i in range(X.shape[0]):
        s += kernel(X[i], p, out) + out[0]
    return s


def kernel_seconds(info, h, v, th, repeat: int) -> tuple[float, float]:
    """CPU seconds of the scalar apex-return kernel and of its Jacobian kernel over the states, on
    one thread (best of ``repeat``): inputs and parameters by name from the index's layouts
    (runtime/api/calls.py), the other inputs at their defaults (the ground 0, the leg held still)."""
    from slipmaps.derive.params import APEX_INPUTS
    from slipmaps.runtime.api.calls import Call, kernel_functions, layout_rows

    defaults = {r["arg"]: float(r["default"]) for r in APEX_INPUTS if "default" in r}
    call = Call.of(info.name, P, {})
    rows = {"b_y_apex": h, "b_xd_apex": v, "q_th_td": th}
    out = []
    for role in ("apex_return", "apex_return_jacobian"):
        spec = call.spec(role)
        kern = kernel_functions(spec)[0]
        X, p = layout_rows(spec, call.record(spec, rows=True), rows, defaults, len(h))
        res = np.empty(spec.width)
        _kernel_loop(kern, X[:10], p[0], res)
        best = math.inf
        for _ in range(repeat):
            c0 = time.process_time()
            _kernel_loop(kern, X, p[0], res)
            best = min(best, time.process_time() - c0)
        out.append(best)
    return out[0], out[1]


def jacobians(h, v, th, td, nj: int, repeat: int) -> list[dict]:
    """(e) every map's apex-return Jacobian (batch, ``nj`` states) against its apex-return map, and
    its stance Jacobian against its stance map (each after a warm-up call)."""
    rows = []
    for info in slipmaps.maps():
        args = (info.name, P, h[:nj], v[:nj], th[:nj])
        sargs = (info.name, P, td[:nj])
        slipmaps.apex_return_jacobian_batch(*args)
        slipmaps.apex_return_batch(*args)
        slipmaps.stance_jacobian_batch(*sargs)
        slipmaps.stance_batch(*sargs)
        t_j = best_of(lambda args=args: slipmaps.apex_return_jacobian_batch(*args), repeat)
        t_a = best_of(lambda args=args: slipmaps.apex_return_batch(*args), repeat)
        t_sj = best_of(lambda sargs=sargs: slipmaps.stance_jacobian_batch(*sargs), repeat)
        t_s = best_of(lambda sargs=sargs: slipmaps.stance_batch(*sargs), repeat)
        k_a, k_j = kernel_seconds(info, h[: nj // 4], v[: nj // 4], th[: nj // 4], repeat)
        rows.append(
            {
                "map": info.name,
                "jacobian_ns": 1e9 * t_j / nj,
                "apex_return_ns": 1e9 * t_a / nj,
                "ratio": t_j / t_a,
                "stance_jacobian_ns": 1e9 * t_sj / nj,
                "stance_ratio": t_sj / t_s,
                "kernel_jacobian_ns": 1e9 * k_j / (nj // 4),
                "kernel_apex_return_ns": 1e9 * k_a / (nj // 4),
                "kernel_ratio": k_j / k_a,
            }
        )
    return rows


def report(r: dict) -> str:
    mach = r["machine"]
    lines = [
        f"machine: {mach['cpu']}, {mach['cpus']} CPUs, numba {mach['numba']} "
        f"({mach['numba_threads']} threads), numpy {mach['numpy']}, scipy {mach['scipy']}, "
        f"Python {mach['python']}, 1-min load {mach['load_1min']}",
        f"N = {r['n']} states, best of {r['repeat']}",
        "",
    ]
    if "yardstick" in r:
        lines += _report_maps(r)
    lines += _report_jacobians(r)
    return "\n".join(lines)


def _report_maps(r: dict) -> list[str]:
    y = r["yardstick"]
    lines = [
        "(a) Geyer's stance map, public batch API vs a hand-written njit kernel of the same math:",
        f"    hand-written {y['handwritten_ns']:.1f} ns/state, "
        f"slipmaps.stance_batch {y['api_ns']:.1f} ns/state: ratio {y['ratio']:.2f} "
        f"(target <= {y['target']:g}: {'met' if y['ratio'] <= y['target'] else 'NOT met'})",
        f"    agreement: same statuses {y['same_status']}, max relative difference {y['max_rel_diff']:.1e}",
        "",
        f"(c) exact stance (solve_ivp DOP853, rtol 1e-11): {r['exact_stance_us']:.0f} us per call",
        "",
        "(b) every map, public batch API (ns per state) and speed-up of its stance over solve_ivp:",
        f"    {'map':<16}{'stance':>10}{'apex return':>13}{'x solve_ivp':>13}{'ok':>7}{'passes':>8}",
    ]
    for m in r["maps"]:
        passes = f"{m['median_passes']:g}" if m["median_passes"] is not None else "-"
        lines.append(
            f"    {m['map']:<16}{m['stance_ns']:>10.1f}{m['apex_return_ns']:>13.1f}"
            f"{m['speedup_vs_solve_ivp']:>13.3g}{m['ok_fraction']:>7.2f}{passes:>8}"
        )
    if r.get("passes"):
        lines += ["", "(d) iterative maps: stance ns per state against the number of passes n (tol = 0):"]
        for name in dict.fromkeys(row["map"] for row in r["passes"]):
            rows = [row for row in r["passes"] if row["map"] == name]
            lines.append(
                f"    {name:<18}" + " ".join(f"n={row['n']}: {row['stance_ns']:.0f}" for row in rows)
            )
    return lines


def _report_jacobians(r: dict) -> list[str]:
    lines = []
    if r.get("jacobians"):
        worst = max(row["ratio"] for row in r["jacobians"])
        lines += [
            "",
            "(e) apex-return Jacobian (next apex, liftoff and times against apex height, speed, angle and",
            "    stiffness), public batch API, ns per state and its cost in apex-return calls (target <= "
            f"{TARGET_JACOBIAN_RATIO:g}x: {'met' if worst <= TARGET_JACOBIAN_RATIO else 'NOT met'}); the",
            "    stance Jacobian in stance calls; the kernels alone (scalar, one thread, CPU time):",
            f"    {'map':<18}{'jacobian':>10}{'apex return':>14}{'ratio':>8}{'stance jac':>12}{'ratio':>8}"
            f"{'kernels':>22}{'ratio':>7}",
        ]
        for row in r["jacobians"]:
            kern = (
                f"{row['kernel_jacobian_ns']:>7.0f} / {row['kernel_apex_return_ns']:.0f} ns"
                f"{row['kernel_ratio']:>7.1f}x"
                if "kernel_ratio" in row
                else ""
            )
            lines.append(
                f"    {row['map']:<18}{row['jacobian_ns']:>7.0f} ns{row['apex_return_ns']:>11.0f} ns"
                f"{row['ratio']:>7.1f}x{row['stance_jacobian_ns']:>9.0f} ns{row['stance_ratio']:>7.1f}x"
                f"  {kern}"
            )
    if r.get("first_call"):
        worst = max(row["seconds"] for row in r["first_call"])
        lines += [
            "",
            "(f) first call of slipmaps.apex_return_jacobian in a fresh process, empty NUMBA_CACHE_DIR",
            f"    (compile time; target <= {TARGET_FIRST_CALL_S:g} s for the slowest: "
            f"{'met' if worst <= TARGET_FIRST_CALL_S else 'NOT met'}), with the 1-min load when it started:",
        ]
        for row in r["first_call"]:
            lines.append(
                f"    {row['map']:<18}{row['seconds']:>7.1f} s elapsed, "
                f"{row.get('cpu_seconds', math.nan):>6.1f} s CPU   (load {row['load_1min']:.2f})"
            )
    if r.get("sizes"):
        lines += ["", f"(g) generated Jacobian modules (all of generated/: {r['generated_lines']} lines):"]
        for row in r["sizes"]:
            lines.append(f"    {row['module']:<34}{row['lines']:>7} lines, longest {row['longest']:>5} chars")
    return lines


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=1_000_000, help="states per batch (default %(default)s)")
    parser.add_argument("--repeat", type=int, default=5, help="timed runs, best kept (default %(default)s)")
    parser.add_argument(
        "--sections", default="abcdefg", help="sections to run, e.g. efg (default %(default)s)"
    )
    parser.add_argument("--json", action="store_true", help="print JSON instead of the report")
    args = parser.parse_args()
    r = run(args.n, args.repeat, args.sections)
    print(json.dumps(r, indent=2) if args.json else report(r))
    return 0


if __name__ == "__main__":
    sys.exit(main())
