"""Benchmark: the compiled exact simulator against the solve_ivp reference, in one run.

Both integrate the same stances with DOP853 at equal tolerances (rtol 1e-11, atol 1e-12, the
``"exact"`` map's defaults), human runner (``slipmaps.HUMAN_RUNNER``), touchdowns reached from apex
heights 1.0-1.1 m, speeds 3-7 m/s and touchdown angles 0.30-0.50 rad (bench_maps.py's states):

(a) per stance: ``runtime.exact.reference.simulate_stance`` (solve_ivp) per call over 50 states, against the
    compiled batch kernel on one numba thread (per state) and the public scalar call
    ``slipmaps.stance("exact", ...)`` (Python validation included); the speed-up (target >= 100x)
    and the agreement on the 50 states (same statuses, max relative difference);
(b) batch throughput of ``slipmaps.stance_batch("exact", ...)`` and ``apex_return_batch`` on all
    of numba's threads, and its speed-up over one thread;
(c) the stance with its Jacobian (``generated/exact_stance.py``'s ``jacobian_into``, variational
    equations), per state on one thread, and its cost relative to the stance alone;
(d) with ``--first-class``: the right-hand side passed to the integrator as a first-class function
    (a function pointer, no inlining) instead of an njit dispatcher (the shipped form), compression
    phases per microsecond of each (compiles two extra specialisations: ~15 s);
(e) the external kernels of ``generated/exact_stance.py`` (the map ``"exact"``'s generated code
    calls them), per state in an njit loop on one thread: ``stance``, ``compression`` then
    ``decompression`` (the same stance in two calls), ``state_at`` at mid-stance, each relative
    to ``stance``;
(f) the stance against its floor (issue 19 item 3): the right-hand side's evaluations per stance
    (``exact_stance.stance_evaluations``) times the cost of one evaluation (an njit loop of
    evaluations, each from the state the one before moved: the latency a Runge-Kutta stage waits
    for; independent evaluations' throughput printed too), against the stance's time from (e);
    target: within 2.5x;
(g) the damped stance (leg damping c at 10 % of the critical 2 sqrt(k_c m), issue 54): the batch
    kernel on one thread with ``liftoff="force"`` and ``"length"``, relative to the lossless stance
    (c = 0) measured side by side.

Best of ``--repeat`` after a warm-up call (compilation excluded); ratios are measured in one run,
absolute times move with the machine and its load (printed). Usage::

    python benchmarks/bench_exact.py [--n N] [--repeat R] [--first-class] [--json]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numba
import numpy as np
import slipmaps
from numba import njit
from slipmaps.generated import dop853
from slipmaps.generated import exact_stance as ec
from slipmaps.generated.slip_model import stance_time_limit
from slipmaps.runtime.exact.reference import DEFAULT_ATOL, DEFAULT_RTOL, simulate_stance

ek = ec  # the external kernels the map "exact" calls live in the same generated module

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import best_of, machine, states, with_threads  # noqa: E402

P = slipmaps.HUMAN_RUNNER
TARGET_SPEEDUP = 100.0
N_SCIPY = 50


def _stance_rows(rows: np.ndarray, params=P, **options):
    """The exact map's batch (the generated parallel kernel around the compiled stance)."""
    res = slipmaps.stance_batch("exact", params, rows, **options)
    return np.column_stack([res[n] for n in res.names]), res["status"]


#: The leg damping of (g): 10 % of the critical damping of the human runner's leg.
DAMPED = P.with_(c=0.1 * 2.0 * math.sqrt(P.k_c * P.m))


def damped(td: np.ndarray, repeat: int) -> dict:
    """(g): the damped stance against the lossless one, batch kernel on one thread, side by side."""
    cases = {"lossless": (P, {}), "force": (DAMPED, {}), "length": (DAMPED, {"liftoff": "length"})}
    for params, options in cases.values():
        _stance_rows(td[:10], params, **options)  # warm-up
    times = {
        name: with_threads(1, lambda p=p, o=o: best_of(lambda: _stance_rows(td, p, **o), repeat)) / len(td)
        for name, (p, o) in cases.items()
    }
    return {
        "c": DAMPED.c,
        "lossless_us": 1e6 * times["lossless"],
        "force_us": 1e6 * times["force"],
        "length_us": 1e6 * times["length"],
        "force_ratio": times["force"] / times["lossless"],
        "length_ratio": times["length"] / times["lossless"],
    }


def per_stance(td: np.ndarray, repeat: int) -> dict:
    few = td[:N_SCIPY]
    t_scipy = best_of(lambda: [simulate_stance(P, row) for row in few], 3) / len(few)
    _stance_rows(td[:10])  # warm-up (cache load or compilation)
    t_one = with_threads(1, lambda: best_of(lambda: _stance_rows(td), repeat)) / len(td)
    slipmaps.stance("exact", P, few[0])
    t_api = best_of(lambda: [slipmaps.stance("exact", P, row) for row in few], repeat) / len(few)
    ref = [simulate_stance(P, row) for row in few]
    got, status = _stance_rows(few)
    same = all(int(r.status) == int(s) for r, s in zip(ref, status, strict=True))
    diff = 0.0
    for r, row in zip(ref, got, strict=True):
        if r.ok:
            want = np.array([r.t_bottom, r.t_stance, *r.bottom, *r.liftoff])
            diff = max(diff, float(np.max(np.abs(row - want) / np.maximum(1.0, np.abs(want)))))
    return {
        "scipy_us": 1e6 * t_scipy,
        "compiled_us": 1e6 * t_one,
        "api_scalar_us": 1e6 * t_api,
        "speedup": t_scipy / t_one,
        "speedup_api_scalar": t_scipy / t_api,
        "target": TARGET_SPEEDUP,
        "same_status": same,
        "max_rel_diff": diff,
    }


def jacobian(td: np.ndarray, repeat: int) -> dict:
    """The stance with its Jacobian (variational equations), batch kernel on one thread."""
    slipmaps.stance_jacobian_batch("exact", P, td[:10])
    t_jac = with_threads(
        1, lambda: best_of(lambda: slipmaps.stance_jacobian_batch("exact", P, td), repeat)
    ) / len(td)
    t_st = with_threads(1, lambda: best_of(lambda: _stance_rows(td), repeat)) / len(td)
    return {"jacobian_us": 1e6 * t_jac, "ratio_to_stance": t_jac / t_st}


@njit
def _kernel_loop(which, td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff):
    """Sum of an output of one external kernel over the rows of td (0 stance, 1 the halves,
    2 state_at at half the stance time)."""
    acc = 0.0
    for i in range(td.shape[0]):
        q_r, q_rd, q_th, q_thd = td[i, 0], td[i, 1], td[i, 2], td[i, 3]
        if which == 0:
            acc += ek.stance(q_r, q_rd, q_th, q_thd, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff)[1]
        elif which == 1:
            down = ek.compression(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, q_r_lo, c, rtol, atol)
            up = ek.decompression(
                down[1], down[2], down[3], down[4], m, l0, k_d, g_s, q_r_lo, c, rtol, atol, liftoff
            )
            acc += down[0] + up[0]
        else:
            acc += ek.state_at(
                0.07, q_r, q_rd, q_th, q_thd, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff
            )[0]
    return acc


def _external_args() -> tuple[float, ...]:
    """The external stance kernels' arguments after the touchdown state (:func:`_kernel_loop`'s)."""
    return (
        P.m,
        P.l0,
        P.k_c,
        P.k_d,
        P.g_s,
        P.c,
        P.q_r_lo,
        DEFAULT_RTOL,
        DEFAULT_ATOL,
        float(ek.LIFTOFF_FORCE),
    )


def external(td: np.ndarray, repeat: int) -> dict:
    """The external kernels per state (one thread: no prange)."""
    rows = np.ascontiguousarray(td[:20_000])
    args = _external_args()
    times = {}
    for which, name in enumerate(("stance", "halves", "state_at")):
        _kernel_loop(which, rows[:10], *args)
        times[name] = best_of(lambda w=which: _kernel_loop(w, rows, *args), repeat) / len(rows)
    return {
        "stance_us": 1e6 * times["stance"],
        "halves_us": 1e6 * times["halves"],
        "state_at_us": 1e6 * times["state_at"],
        "halves_ratio": times["halves"] / times["stance"],
        "state_at_ratio": times["state_at"] / times["stance"],
    }


@njit
def _rhs_chain(y0, p, reps):
    """``reps`` evaluations of the stance field, each from a state moved along the previous one's
    slope (each evaluation waits for the one before, as a Runge-Kutta stage does)."""
    y = y0.copy()
    dy = np.empty(4)
    for _ in range(reps):
        ec.polar_field(0.0, y, p, dy)
        for i in range(4):
            y[i] += 1e-7 * dy[i]
    return y[0]


@njit
def _rhs_independent(rows, p):
    """One evaluation of the stance field per row (independent: as many in flight as the CPU can)."""
    dy = np.empty(4)
    acc = 0.0
    for i in range(rows.shape[0]):
        ec.polar_field(0.0, rows[i], p, dy)
        acc += dy[1] + dy[3]
    return acc


@njit
def _step_chain(y0, p, h, reps):
    """``reps`` Runge-Kutta steps of the stance field with their error norm (what an accepted step
    of :func:`.dop853.solve` costs before its event checks), each from the one before's end."""
    n = y0.shape[0]
    K = np.empty((dop853.N_STAGES_EXTENDED, n))
    y = y0.copy()
    y_new = np.empty(n)
    f = np.empty(n)
    ys = np.empty(n)
    dy = np.empty(n)
    ec.polar_field(0.0, y, p, f)
    acc = 0.0
    t = 0.0
    for _ in range(reps):
        dop853._rk_step(ec.POLAR_FIELD(), p, t, y, f, h, K, y_new, ys, dy)
        acc += dop853._error_norm(K, h, y, y_new, 1e-11, 1e-12, n)
        for i in range(n):
            y[i] = y_new[i]
            f[i] = K[dop853.N_STAGES, i]
        t += h
        if y[0] < 0.5 * y0[0] or y[0] > y0[0]:  # keep the state in the stance's range
            y[:] = y0
            ec.polar_field(0.0, y, p, f)
    return acc


def floor(td: np.ndarray, repeat: int) -> dict:
    """The stance against its floor: (right-hand side evaluations per stance) x (cost of one
    evaluation), both measured here, against the stance's own time (the external kernel in an njit
    loop on one thread, as (e)); target: within 2.5x."""
    rows = np.ascontiguousarray(td[:20_000])
    t_max = stance_time_limit(P.m, P.l0, P.k_c, P.k_d, P.g_s)
    record = ec.Stance(P.m, P.l0, P.k_c, P.k_d, P.g_s, P.q_r_lo, DEFAULT_RTOL, DEFAULT_ATOL, t_max, P.c)
    args = _external_args()
    counts = [ec.stance_evaluations(*row, record) for row in rows[:2000]]
    evaluations = float(np.mean([n for status, n in counts if status == ec.OK]))
    p = (P.m, P.l0, P.k_c, P.g_s, P.c)
    reps = 1_000_000
    _rhs_chain(rows[0], p, 10)
    _rhs_independent(rows[:10], p)
    t_chain = best_of(lambda: _rhs_chain(rows[0], p, reps), repeat) / reps
    t_indep = best_of(lambda: _rhs_independent(rows, p), repeat) / len(rows)
    _kernel_loop(0, rows[:10], *args)
    t_stance = best_of(lambda: _kernel_loop(0, rows, *args), repeat) / len(rows)
    # where the rest goes: the steps (12 evaluations each; 2 per subphase start and 3 per event's
    # interpolant are the others) at the cost of one step with its error norm, measured the same way
    steps = (evaluations - 2 * (2 + 3)) / dop853.N_STAGES
    _step_chain(rows[0], p, 1e-4, 10)
    t_step = best_of(lambda: _step_chain(rows[0], p, 1e-4, reps // 20), repeat) / (reps // 20)
    return {
        "steps": steps,
        "step_ns": 1e9 * t_step,
        "steps_us": 1e6 * steps * t_step,
        "evaluations": evaluations,
        "rhs_chain_ns": 1e9 * t_chain,
        "rhs_independent_ns": 1e9 * t_indep,
        "stance_us": 1e6 * t_stance,
        "ratio": t_stance / (evaluations * t_chain),
        "ratio_independent": t_stance / (evaluations * t_indep),
        "target": 2.5,
    }


def throughput(h, v, th, td, repeat: int) -> dict:
    threads = numba.get_num_threads()
    slipmaps.stance_batch("exact", P, td[:10])
    slipmaps.apex_return_batch("exact", P, h[:10], v[:10], th[:10])
    t_st = best_of(lambda: slipmaps.stance_batch("exact", P, td), repeat)
    t_ap = best_of(lambda: slipmaps.apex_return_batch("exact", P, h, v, th), repeat)
    t_st1 = with_threads(1, lambda: best_of(lambda: slipmaps.stance_batch("exact", P, td), repeat))
    return {
        "threads": threads,
        "stance_per_s": len(td) / t_st,
        "apex_return_per_s": len(h) / t_ap,
        "parallel_speedup": t_st1 / t_st,
    }


def first_class(td: np.ndarray, repeat: int) -> dict:
    """Compression phases with the right-hand side and events as first-class functions vs dispatchers."""
    from numba import njit, types

    f8, arr = types.float64, types.float64[::1]
    p4, p2 = types.UniTuple(f8, 5), types.UniTuple(f8, 5)  # the field's (m, l0, k, g_s, c), the events'
    rhs_sig, ev_sig = types.void(f8, arr, p4, arr), types.void(f8, arr, p2, arr)
    rhs, ev = njit(rhs_sig)(ec.polar_field.py_func), njit(ev_sig)(ec.stance_events.py_func)
    out_ty = types.Tuple((types.int64, f8, types.int64, types.int64, types.int64))
    solve_fc = njit(
        out_ty(
            types.FunctionType(rhs_sig),
            p4,
            types.FunctionType(ev_sig),
            p2,
            arr,
            f8,
            arr,
            f8,
            f8,
            f8,
            f8,
            types.int64,
            arr,
            f8,
            arr,
            f8,
        )
    )(dop853.solve.py_func)

    rtol, atol = DEFAULT_RTOL, DEFAULT_ATOL

    @njit
    def run_fc(rows, rhs, ev, p, pe, direction, cap, y_end):
        acc = 0.0
        for i in range(rows.shape[0]):
            acc += solve_fc(
                rhs,
                p,
                ev,
                pe,
                direction,
                0.0,
                rows[i],
                10.0,
                rtol,
                atol,
                cap,
                4,
                y_end,
                math.inf,
                y_end,
                dop853.GOES_ON,
            )[1]
        return acc

    @njit
    def run_disp(rows, rhs, ev, p, pe, direction, cap, y_end):
        acc = 0.0
        for i in range(rows.shape[0]):
            acc += dop853.solve(
                rhs,
                p,
                ev,
                pe,
                direction,
                0.0,
                rows[i],
                10.0,
                rtol,
                atol,
                cap,
                4,
                y_end,
                math.inf,
                y_end,
                dop853.GOES_ON,
            )[1]
        return acc

    rows = np.ascontiguousarray(td[:2000])
    p, pe = (P.m, P.l0, P.k_c, P.g_s, P.c), (P.q_r_lo, 1e-3 * P.l0, P.k_d, P.l0, P.c)
    direction = np.array(ec.COMPRESSION_DIRECTIONS)
    cap, y_end = ec.step_cap(P.m, P.l0, P.k_c, P.g_s, DEFAULT_RTOL), np.empty(4)
    fc = (rows, rhs, ev, p, pe, direction, cap, y_end)
    # the same njit functions as dispatchers: not registered with dop853.static's state_length, so both
    # run the step's loops (the registered polar field's step is written out: another body)
    disp = (rows, rhs, ev, p, pe, direction, cap, y_end)
    same = run_fc(*fc) == run_disp(*disp)
    t_fc = best_of(lambda: run_fc(*fc), repeat) / len(rows)
    t_disp = best_of(lambda: run_disp(*disp), repeat) / len(rows)
    return {"first_class_us": 1e6 * t_fc, "dispatcher_us": 1e6 * t_disp, "ratio": t_fc / t_disp, "same": same}


def run(n: int, repeat: int, with_first_class: bool) -> dict:
    h, v, th, td = states(n)
    out = {"machine": machine(), "n": n, "repeat": repeat, "rtol": DEFAULT_RTOL, "atol": DEFAULT_ATOL}
    out["per_stance"] = per_stance(td, repeat)
    out["throughput"] = throughput(h, v, th, td, repeat)
    out["jacobian"] = jacobian(td, repeat)
    out["external"] = external(td, repeat)
    out["floor"] = floor(td, repeat)
    out["damped"] = damped(td, repeat)
    if with_first_class:
        out["first_class"] = first_class(td, repeat)
    return out


def report(r: dict) -> str:
    m, s, b = r["machine"], r["per_stance"], r["throughput"]
    met = "met" if s["speedup"] >= s["target"] else "NOT met"
    lines = [
        f"machine: {m['cpu']}, {m['cpus']} CPUs, numba {m['numba']} ({m['numba_threads']} threads), "
        f"scipy {m['scipy']}, Python {m['python']}, 1-min load {m['load_1min']}",
        f"N = {r['n']} touchdowns (human runner), best of {r['repeat']}, "
        f"rtol {r['rtol']:g}, atol {r['atol']:g}",
        "",
        "(a) exact stance, per state:",
        f"    solve_ivp (runtime/exact/reference.py)        {s['scipy_us']:9.1f} us",
        f"    compiled, batch kernel on 1 thread      {s['compiled_us']:9.2f} us: {s['speedup']:.0f}x "
        f"(target >= {s['target']:g}x: {met})",
        f"    compiled, slipmaps.stance scalar call   {s['api_scalar_us']:9.2f} us: "
        f"{s['speedup_api_scalar']:.0f}x",
        f"    agreement on {N_SCIPY} states: same statuses {s['same_status']}, "
        f"max relative difference {s['max_rel_diff']:.1e}",
        "",
        f"(b) batch throughput on {b['threads']} numba threads: "
        f"stance_batch {b['stance_per_s']:.3g} stances/s ({b['parallel_speedup']:.2f}x one thread), "
        f"apex_return_batch {b['apex_return_per_s']:.3g} steps/s",
    ]
    j = r["jacobian"]
    lines += [
        "",
        f"(c) stance with its 10 x {ec.N_IN} Jacobian (exact_jacobian, 1 thread): {j['jacobian_us']:.1f} us "
        f"per state, {j['ratio_to_stance']:.1f}x the stance alone",
    ]
    e = r["external"]
    lines += [
        "",
        "(e) external kernels (generated/exact_stance.py, njit loop, 1 thread): "
        f"stance {e['stance_us']:.2f} us, compression + decompression {e['halves_us']:.2f} us "
        f"({e['halves_ratio']:.2f}x), "
        f"state_at mid-stance {e['state_at_us']:.2f} us ({e['state_at_ratio']:.2f}x)",
    ]
    f = r["floor"]
    met = "met" if f["ratio"] <= f["target"] else "NOT met"
    lines += [
        "",
        f"(f) the stance against its floor (rtol {r['rtol']:g}): {f['evaluations']:.1f} right-hand side "
        f"evaluations per stance x {f['rhs_chain_ns']:.1f} ns per evaluation (each waiting for the one "
        f"before, as a stage does) = {f['evaluations'] * f['rhs_chain_ns'] / 1e3:.2f} us; the stance "
        f"{f['stance_us']:.2f} us: {f['ratio']:.2f}x its floor (target <= {f['target']:g}x: {met}); "
        f"against independent evaluations ({f['rhs_independent_ns']:.1f} ns each) "
        f"{f['ratio_independent']:.2f}x",
        f"    where it goes: {f['steps']:.1f} steps tried per stance x {f['step_ns']:.0f} ns per step with "
        f"its error norm ({f['step_ns'] / (dop853.N_STAGES * f['rhs_chain_ns']):.2f}x its 12 evaluations) = "
        f"{f['steps_us']:.2f} us; the rest (subphase starts, event checks at each step end, event "
        f"location on the interpolant, the kernel call and its arrays) "
        f"{f['stance_us'] - f['steps_us']:.2f} us",
    ]
    d = r["damped"]
    lines += [
        "",
        f"(g) damped stance, c = {d['c']:.0f} N s/m (10 % of critical; batch kernel, 1 thread): "
        f"liftoff force {d['force_us']:.2f} us ({d['force_ratio']:.2f}x the lossless "
        f"{d['lossless_us']:.2f} us), "
        f"length {d['length_us']:.2f} us ({d['length_ratio']:.2f}x)",
    ]
    if "first_class" in r:
        f = r["first_class"]
        lines += [
            "",
            "(d) compression phase, right-hand side as a first-class function "
            f"{f['first_class_us']:.2f} us, as an njit dispatcher {f['dispatcher_us']:.2f} us: "
            f"ratio {f['ratio']:.2f} (same results {f['same']})",
        ]
    return "\n".join(lines)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=100_000, help="states per batch (default %(default)s)")
    parser.add_argument("--repeat", type=int, default=5, help="timed runs, best kept (default %(default)s)")
    parser.add_argument("--first-class", action="store_true", help="also time a first-class right-hand side")
    parser.add_argument("--json", action="store_true", help="print JSON instead of the report")
    args = parser.parse_args()
    r = run(args.n, args.repeat, args.first_class)
    print(json.dumps(r, indent=2) if args.json else report(r))
    return 0 if math.isfinite(r["per_stance"]["speedup"]) else 1


if __name__ == "__main__":
    sys.exit(main())
