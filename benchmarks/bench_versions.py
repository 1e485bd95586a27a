"""Benchmark: two source trees of slipmaps side by side, in one run (issue 29's "speed kept").

Each tree runs in its own interpreter (a virtual environment with that tree installed), in its own
processes, interleaved: round 1 old, round 1 new, round 2 old, ... (``--rounds``); per measurement
the best over all rounds and repeats is kept. Only the public API is called, with the arguments both
trees take (``slipmaps.apex_return_batch(name, slipmaps.HUMAN_RUNNER, heights, speeds, angles)``:
the inputs a tree adds keep their defaults), on the maps both trees list (those in one tree only are
named in the report). Measured for the human runner:

- per map, ``slipmaps.apex_return_batch`` on N states and ``slipmaps.apex_return_jacobian_batch`` on
  N/10 states, ns per state, each after a warm-up call (compilation excluded), best of ``--repeat``
  per round; the ratio new/old (target: at most 1.1) and the Jacobian's cost in apex-return calls of
  the same N/10 states (target: at most 3); the statuses' counts of both trees, compared; the
  Jacobian's outputs x inputs in each tree and its new/old time per input (forward mode runs about
  one pass per input: the time of the same work where the new tree differentiates more inputs);
- per map, a warm scalar ``slipmaps.apex_return`` in us (``bench_calls.scalar_us``; target: at most
  10 us);
- Geyer's public ``slipmaps.stance_batch`` against the hand-written kernel (``handwritten_geyer.py``)
  on N touchdowns (target: at most 1.4x);
- the Jacobian / apex-return ratio also as the median over back-to-back pairs of calls, ``--repeat``
  pairs per round: two times taken a moment apart, which load from other jobs moves less than the
  ratio of two bests (a longer call gets a quiet stretch less often). Not Geyer's yardstick: after
  the hand-written kernel's parallel loop numba's OpenMP workers spin for a while, which slows a
  call right after it (its pairs' median came out 1.9x where the bests gave 1.3x);
- per map, the first ``slipmaps.apex_return`` and ``slipmaps.apex_return_jacobian`` in a fresh
  process with an empty ``NUMBA_CACHE_DIR`` (``bench_first_call.first_call``), old then new, elapsed
  and CPU seconds (targets: at most 5 s and 10 s).

The ground-truth map (``exact``) is timed in batches of N/100 and N/1000 states. States: apex
heights 1.0-1.1 m, speeds 3-7 m/s, touchdown angles 0.30-0.50 rad (uniform, seed 0; ``bench_maps.
states``, drawn once by the new tree and given to both). The warm processes of each tree share a
numba cache of their own (a temporary directory, compiled by the first round). The 1-min load is
printed beside each number; ratios are the result, absolute times move with the machine.
``--threads 1`` runs the warm workers on one numba thread: on a machine other jobs load, a batch
that takes longer (a Jacobian's) gets its second thread less often than a short one, and the
ratios of two-thread batches move with the load more than the work. Usage::

    python benchmarks/bench_versions.py --old OLD_PYTHON [--new NEW_PYTHON] [--n N] [--repeat R]
        [--rounds K] [--maps a,b] [--threads T] [--no-first-calls] [--json] [--save PATH]
    python benchmarks/bench_versions.py --from-json PATH    # the report of a saved record
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from bench_first_call import first_call  # noqa: E402

#: Targets of issue 29: new/old per state, Jacobian / apex return, public / hand-written Geyer,
#: warm scalar us, first-call seconds by role.
TARGET_NEW_OLD = 1.1
TARGET_JACOBIAN = 3.0
TARGET_GEYER = 1.4
TARGET_SCALAR_US = 10.0
TARGET_FIRST_S = {"apex_return": 5.0, "apex_return_jacobian": 10.0}
#: Batch sizes of the ground-truth map, as divisors of N (apex return, Jacobian).
EXACT_DIVISORS = (100, 1000)


# --- the worker: runs in each tree's interpreter (imports that tree's slipmaps) ----------------------


def _load() -> float:
    return os.getloadavg()[0]


def _statuses(status) -> dict[str, int]:
    import numpy as np
    import slipmaps

    codes, counts = np.unique(np.asarray(status).ravel(), return_counts=True)
    names = {int(s): s.name for s in slipmaps.Status}
    return {names.get(int(c), str(int(c))): int(k) for c, k in zip(codes, counts, strict=True)}


def _timed(fn, repeat: int) -> dict:
    """fn() once (warm), then its best time of ``repeat``, with the 1-min load before; and the
    statuses of the warm call."""
    from bench_maps import best_of

    res = fn()
    load = _load()
    return {"seconds": best_of(fn, repeat), "load_1min": load, "statuses": _statuses(res.status)}


def _pairs(first, second, repeat: int) -> list[float]:
    """``repeat`` ratios second() / first() of two calls made back to back: a ratio of two times
    taken a moment apart, which load from other jobs moves less than a ratio of two bests taken
    seconds apart (a longer call gets a quiet stretch less often than a short one)."""
    out = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        first()
        t1 = time.perf_counter()
        second()
        out.append((time.perf_counter() - t1) / (t1 - t0))
    return out


def worker_list() -> dict:
    import slipmaps

    return {"maps": [{"map": m.name, "ground_truth": bool(m.ground_truth)} for m in slipmaps.maps()]}


def worker_states(path: str, n: int) -> dict:
    import numpy as np
    from bench_maps import states

    h, v, th, td = states(n)
    np.savez(path, h=h, v=v, th=th, td=td)
    return {"path": path}


def worker_round(states_path: str, names: list[str], exact: list[str], repeat: int) -> dict:
    """One round of one tree: Geyer's yardstick, then every map's batches and scalar call."""
    import handwritten_geyer
    import numpy as np
    import slipmaps
    from bench_calls import scalar_us
    from bench_maps import best_of, machine

    P = slipmaps.HUMAN_RUNNER
    with np.load(states_path) as f:
        h, v, th, td = f["h"], f["v"], f["th"], f["td"]
    n = h.size
    out: dict = {"machine": machine(), "n": n, "maps": {}}

    prm = (P.m, P.l0, P.k, P.g_s, P.q_r_lo)
    hand = handwritten_geyer.stance_batch(td, *prm)
    api = slipmaps.stance_batch("geyer", P, td)
    load = _load()
    t_hand = best_of(lambda: handwritten_geyer.stance_batch(td, *prm), repeat)
    t_api = best_of(lambda: slipmaps.stance_batch("geyer", P, td), repeat)
    out["geyer"] = {
        "handwritten_ns": 1e9 * t_hand / n,
        "api_ns": 1e9 * t_api / n,
        "load_1min": load,
        "same_status": bool(np.array_equal(hand[1], api.status)),
    }

    for name in names:
        na = n // EXACT_DIVISORS[0] if name in exact else n
        nj = n // EXACT_DIVISORS[1] if name in exact else n // 10
        row: dict = {"n_apex": na, "n_jacobian": nj}
        for key, fn, m in (
            ("apex_return", slipmaps.apex_return_batch, na),
            ("apex_return_nj", slipmaps.apex_return_batch, nj),
            ("jacobian", slipmaps.apex_return_jacobian_batch, nj),
        ):
            row[key] = _timed(lambda fn=fn, m=m, name=name: fn(name, P, h[:m], v[:m], th[:m]), repeat)
            row[key]["ns"] = 1e9 * row[key]["seconds"] / m
        same = (name, P, h[:nj], v[:nj], th[:nj])  # the states of the jacobian batch
        row["pairs"] = _pairs(
            lambda same=same: slipmaps.apex_return_batch(*same),
            lambda same=same: slipmaps.apex_return_jacobian_batch(*same),
            repeat,
        )
        row["scalar"] = {"load_1min": _load(), **scalar_us(name, repeat)}
        # the Jacobian's outputs x inputs: forward mode costs about one pass per input (direction)
        jac = slipmaps.apex_return_jacobian(name, P, float(h[0]), float(v[0]), float(th[0]))
        row["jacobian_shape"] = list(jac.matrix.shape)
        out["maps"][name] = row
    return out


def worker(args) -> dict:
    if args.worker == "list":
        return worker_list()
    if args.worker == "states":
        return worker_states(args.states, args.n)
    return worker_round(args.states, args.maps.split(","), args.exact.split(","), args.repeat)


# --- the driver: runs the workers of both trees, interleaved -------------------------------------------


def _run(python: str, cache: str, *argv: str, threads: int | None = None) -> dict:
    env = dict(os.environ, NUMBA_CACHE_DIR=cache)
    if threads:
        env["NUMBA_NUM_THREADS"] = str(threads)
    done = subprocess.run(
        [python, str(Path(__file__).resolve()), "--worker", *argv],
        env=env,
        capture_output=True,
        text=True,
    )
    if done.returncode:
        raise RuntimeError(f"{python} {' '.join(argv)} failed:\n{done.stderr[-3000:]}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def _best(rounds: list[dict], path: tuple[str, ...], time_key: str) -> dict:
    """The record at ``path`` with the least ``time_key`` over the rounds."""

    def at(r):
        for key in path:
            r = r[key]
        return r

    return min((at(r) for r in rounds), key=lambda rec: rec[time_key])


def measure(
    old: str,
    new: str,
    n: int,
    repeat: int,
    rounds: int,
    only: list[str],
    first_calls: bool,
    threads: int | None = None,
) -> dict:
    versions = {"old": old, "new": new}
    with tempfile.TemporaryDirectory(prefix="slipmaps-versions-") as tmp:
        caches = {v: os.path.join(tmp, f"numba-{v}") for v in versions}
        listed = {v: _run(py, caches[v], "list")["maps"] for v, py in versions.items()}
        names_of = {v: [m["map"] for m in rows] for v, rows in listed.items()}
        names = [m for m in names_of["new"] if m in names_of["old"] and (not only or m in only)]
        exact = [m["map"] for m in listed["new"] if m["ground_truth"] and m["map"] in names]
        states = os.path.join(tmp, "states.npz")
        _run(new, caches["new"], "states", "--states", states, "--n", str(n))
        argv = ("round", "--states", states, "--maps", ",".join(names), "--exact", ",".join(exact))
        runs: dict[str, list[dict]] = {v: [] for v in versions}
        for _ in range(rounds):
            for v, py in versions.items():
                runs[v].append(_run(py, caches[v], *argv, "--repeat", str(repeat), threads=threads))
                print(f"round {len(runs[v])} of {v} done, load {_load():.2f}", file=sys.stderr, flush=True)
    out: dict = {
        "n": n,
        "repeat": repeat,
        "rounds": rounds,
        "python": versions,
        "only_in": {
            v: [m for m in names_of[v] if m not in names_of[w]] for v, w in (("old", "new"), ("new", "old"))
        },
        "machine": {v: runs[v][0]["machine"] for v in versions},
        "geyer": {v: _best(runs[v], ("geyer",), "api_ns") for v in versions},
        "maps": [],
        "first_calls": [],
    }
    for name in names:
        row = {"map": name, "exact": name in exact}
        for v in versions:
            row[v] = {
                key: _best(runs[v], ("maps", name, key), "seconds")
                for key in ("apex_return", "apex_return_nj", "jacobian")
            }
            row[v]["scalar"] = _best(runs[v], ("maps", name, "scalar"), "apex_return_us")
            row[v]["jacobian_shape"] = runs[v][0]["maps"][name]["jacobian_shape"]
            row[v]["pairs"] = [x for run in runs[v] for x in run["maps"][name].get("pairs", [])]
        out["maps"].append(row)
    if first_calls:
        for name in names:
            for role in TARGET_FIRST_S:
                for v, py in versions.items():
                    out["first_calls"].append({"version": v, **first_call(name, role, py)})
                    print(f"first call {name} {role} {v} done", file=sys.stderr, flush=True)
    return out


# --- the report -----------------------------------------------------------------------------------------


def _met(ok: bool) -> str:
    return "met" if ok else "NOT met"


def report(r: dict) -> str:
    lines = []
    for v in ("old", "new"):
        m = r["machine"][v]
        lines.append(
            f"{v}: {r['python'][v]}: numba {m['numba']} ({m['numba_threads']} threads), numpy {m['numpy']}, "
            f"Python {m['python']}; machine {m['cpu']}, {m['cpus']} CPUs"
        )
    lines.append(f"N = {r['n']} states, best of {r['repeat']} x {r['rounds']} rounds (old, new interleaved)")
    for v, names in r["only_in"].items():
        if names:
            lines.append(f"maps only in {v}: {', '.join(names)} (not timed)")
    lines += ["", *_report_batches(r), "", *_report_geyer(r)]
    if r.get("first_calls"):
        lines += ["", *_report_first_calls(r)]
    return "\n".join(lines)


def _report_batches(r: dict) -> list[str]:
    lines = [
        "public batch API, ns per state (new/old target <= "
        f"{TARGET_NEW_OLD:g}; jacobian / apex return of the same states <= {TARGET_JACOBIAN:g}),",
        f"warm scalar apex_return us (target <= {TARGET_SCALAR_US:g}), and the 1-min load at each best",
        "(apex return, jacobian: old / new):",
        f"    {'map':<17}{'apex return old/new':>23}{'ratio':>7}{'jacobian old/new':>21}{'ratio':>7}"
        f"{'jac/apex':>10}{'scalar us old/new':>18}   load",
    ]
    worst = {"apex": 0.0, "jac": 0.0, "jac_apex": 0.0, "scalar": 0.0, "per_input": 0.0}
    shapes = []
    statuses = []
    for row in r["maps"]:
        o, w = row["old"], row["new"]
        ra = w["apex_return"]["ns"] / o["apex_return"]["ns"]
        rj = w["jacobian"]["ns"] / o["jacobian"]["ns"]
        ja = w["jacobian"]["ns"] / w["apex_return_nj"]["ns"]
        worst["apex"], worst["jac"] = max(worst["apex"], ra), max(worst["jac"], rj)
        worst["jac_apex"] = max(worst["jac_apex"], ja)
        worst["scalar"] = max(worst["scalar"], w["scalar"]["apex_return_us"])
        if "jacobian_shape" in o and "jacobian_shape" in w:
            (ro, co), (rw, cw) = o["jacobian_shape"], w["jacobian_shape"]
            per_input = rj * co / cw
            worst["per_input"] = max(worst["per_input"], per_input)
            shapes.append(f"{row['map']} {ro}x{co} -> {rw}x{cw}: {per_input:.2f}")
        loads = " / ".join(
            ",".join(f"{x[k]['load_1min']:.1f}" for k in ("apex_return", "jacobian")) for x in (o, w)
        )
        name = row["map"] + (" *" if row["exact"] else "")
        lines.append(
            f"    {name:<17}{o['apex_return']['ns']:>10.0f} /{w['apex_return']['ns']:>8.0f} ns{ra:>7.2f}"
            f"{o['jacobian']['ns']:>9.0f} /{w['jacobian']['ns']:>7.0f} ns{rj:>7.2f}{ja:>9.2f}x"
            f"{o['scalar']['apex_return_us']:>10.2f} /{w['scalar']['apex_return_us']:>6.2f}   {loads}"
        )
        for key in ("apex_return", "jacobian"):
            if o[key]["statuses"] != w[key]["statuses"]:
                statuses.append(f"    {row['map']} {key}: old {o[key]['statuses']}, new {w[key]['statuses']}")
    if any(row["exact"] for row in r["maps"]):
        lines.append(
            f"    * the ground-truth map in batches of N/{EXACT_DIVISORS[0]} and N/{EXACT_DIVISORS[1]} states"
        )
    lines += [
        f"    slowest new/old: apex return {worst['apex']:.2f} ({_met(worst['apex'] <= TARGET_NEW_OLD)}), "
        f"jacobian {worst['jac']:.2f} ({_met(worst['jac'] <= TARGET_NEW_OLD)}); "
        f"jacobian / apex return {worst['jac_apex']:.2f} ({_met(worst['jac_apex'] <= TARGET_JACOBIAN)}); "
        f"scalar {worst['scalar']:.2f} us ({_met(worst['scalar'] <= TARGET_SCALAR_US)})",
    ]
    if shapes:
        lines.append(
            "    the jacobian's outputs x inputs old -> new and its new/old time per input (forward mode "
            f"runs a pass per input), slowest {worst['per_input']:.2f}:"
        )
        lines += [f"        {shape}" for shape in shapes]
    paired = [row for row in r["maps"] if row["old"].get("pairs") and row["new"].get("pairs")]
    if paired:
        lines.append(
            "    jacobian / apex return of the same states, the median of back-to-back pairs of calls "
            "(old / new; robust to other jobs' load):"
        )
        lines += [
            f"        {row['map']} {_median(row['old']['pairs']):.2f} / {_median(row['new']['pairs']):.2f}"
            f" ({len(row['new']['pairs'])} pairs)"
            for row in paired
        ]
    lines += [
        "    statuses: " + ("the same counts in both trees" if not statuses else "differ:"),
        *statuses,
    ]
    return lines


def _median(values: list[float]) -> float:
    return statistics.median(values) if values else float("nan")


def _report_geyer(r: dict) -> list[str]:
    lines = [f"Geyer's stance_batch against the hand-written kernel (target <= {TARGET_GEYER:g}x):"]
    for v in ("old", "new"):
        g = r["geyer"][v]
        ratio = g["api_ns"] / g["handwritten_ns"]
        lines.append(
            f"    {v}: public {g['api_ns']:.1f} ns, hand-written {g['handwritten_ns']:.1f} ns per state: "
            f"{ratio:.2f}x ({_met(ratio <= TARGET_GEYER)}); same statuses {g['same_status']}; "
            f"load {g['load_1min']:.2f}"
        )
    return lines


def _report_first_calls(r: dict) -> list[str]:
    lines = [
        "first call in a fresh process, empty NUMBA_CACHE_DIR, s elapsed (CPU), old / new, 1-min load:",
        f"    {'map':<19}{'apex_return':<40}apex_return_jacobian",
    ]
    calls = {(c["map"], c["role"], c["version"]): c for c in r["first_calls"]}
    worst = dict.fromkeys(TARGET_FIRST_S, 0.0)
    failed = [f"{c['map']} {c['role']} {c['version']}" for c in r["first_calls"] if not c.get("ok", True)]
    for name in dict.fromkeys(c["map"] for c in r["first_calls"]):
        cells = []
        for role in TARGET_FIRST_S:
            o, w = calls[(name, role, "old")], calls[(name, role, "new")]
            worst[role] = max(worst[role], w["first_call_s"])
            cells.append(
                f"{o['first_call_s']:5.1f} ({o['first_call_cpu_s']:4.1f}) / {w['first_call_s']:5.1f} "
                f"({w['first_call_cpu_s']:4.1f}) [{o['load_1min']:.1f}/{w['load_1min']:.1f}]"
            )
        lines.append(f"    {name:<17}" + "   ".join(cells))
    lines.append(
        "    slowest new: "
        + "; ".join(
            f"{role} {worst[role]:.1f} s ({_met(worst[role] <= t)})" for role, t in TARGET_FIRST_S.items()
        )
    )
    if failed:
        lines.append("    calls whose result was not OK: " + ", ".join(failed))
    return lines


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--old", help="the old tree's Python (its venv's interpreter)")
    parser.add_argument("--new", default=sys.executable, help="the new tree's Python (default: this one)")
    parser.add_argument("--n", type=int, default=200_000, help="states per batch (default %(default)s)")
    parser.add_argument("--repeat", type=int, default=3, help="timed calls per round (default %(default)s)")
    parser.add_argument("--rounds", type=int, default=3, help="rounds per tree (default %(default)s)")
    parser.add_argument("--maps", default="", help="these maps only, comma-separated (default: all)")
    parser.add_argument("--threads", type=int, help="numba threads of the warm workers (default: numba's)")
    parser.add_argument("--no-first-calls", action="store_true", help="skip the empty-cache first calls")
    parser.add_argument("--json", action="store_true", help="print JSON instead of the report")
    parser.add_argument("--save", metavar="PATH", help="also write the JSON record to PATH")
    parser.add_argument("--from-json", metavar="PATH", help="print the report of a saved JSON record")
    parser.add_argument("--worker", choices=("list", "states", "round"), help=argparse.SUPPRESS)
    parser.add_argument("--states", help=argparse.SUPPRESS)
    parser.add_argument("--exact", default="", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        print(json.dumps(worker(args)))
        return 0
    if args.from_json:
        print(report(json.loads(Path(args.from_json).read_text())))
        return 0
    if not args.old:
        parser.error("--old is required")
    only = [m for m in args.maps.split(",") if m]
    if args.threads is not None and args.threads < 1:
        parser.error(f"--threads must be at least 1, not {args.threads}")
    first_calls = not args.no_first_calls
    r = measure(args.old, args.new, args.n, args.repeat, args.rounds, only, first_calls, args.threads)
    if args.save:
        Path(args.save).write_text(json.dumps(r, indent=2) + "\n")
    print(json.dumps(r, indent=2) if args.json else report(r))
    return 0


if __name__ == "__main__":
    sys.exit(main())
