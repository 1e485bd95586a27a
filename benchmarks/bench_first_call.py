"""Benchmark: time to first result on an empty numba cache (issue 19 item 5).

Each map's first ``slipmaps.apex_return`` (and with ``--jacobian`` its first
``slipmaps.apex_return_jacobian``) runs in a fresh Python process whose ``NUMBA_CACHE_DIR`` is a new
empty directory, as a new user's first call does: the time printed is the call's own (numba
compiling the kernels it needs, then the step), ``import slipmaps`` timed apart. The processes run
one after another (one core each); on a shared machine the load is printed with each. Targets: the
first apex return of any map within 5 s, its Jacobian within 10 s (issue 29). ``--main-job`` also
times the README's main job, ``python -m slipmaps compare --plot FILE``, the same way: from the
start of its process to its first line (the table) and to its exit (target: 15 s). ``--batch``
also times the first ``slipmaps.apex_return_batch`` (with ``--jacobian`` also the first
``slipmaps.apex_return_jacobian_batch``) of two states the same way: a batch compiles the batch
form, the role kernel inlined in its loop, where a scalar call compiles the kernel alone. Usage::

    python benchmarks/bench_first_call.py [--maps NAME ...] [--jacobian] [--batch] [--main-job] [--json]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

CHILD = r"""
import json, sys, time
t0 = time.perf_counter()
import slipmaps
t1, c1 = time.perf_counter(), time.process_time()
name, role = sys.argv[1], sys.argv[2]
call = getattr(slipmaps, role)  # apex_return, apex_return_jacobian or their _batch
if role.endswith("_batch"):
    r = call(name, slipmaps.HUMAN_RUNNER, [1.0, 1.05], [5.0, 4.0], [0.35, 0.3])
    ok = bool(r.ok.all())
else:
    r = call(name, slipmaps.HUMAN_RUNNER, 1.0, 5.0, 0.35)
    ok = bool(r.ok)
t2, c2 = time.perf_counter(), time.process_time()
out = {"import_s": t1 - t0, "first_call_s": t2 - t1, "first_call_cpu_s": c2 - c1, "ok": ok}
print(json.dumps(out))
"""


def first_call(name: str, role: str, python: str = sys.executable) -> dict:
    """The first ``role`` call of map ``name`` in a new ``python`` process with an empty numba cache:
    its seconds (elapsed and the process's CPU), ``import slipmaps``'s, whether it succeeded, and the
    1-min load as it started."""
    with tempfile.TemporaryDirectory(prefix="slipmaps-first-call-") as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        load = os.getloadavg()[0]
        out = subprocess.run(
            [python, "-c", CHILD, name, role], env=env, capture_output=True, text=True, check=True
        )
    return {"map": name, "role": role, "load_1min": load, **json.loads(out.stdout.strip().splitlines()[-1])}


def main_job() -> dict:
    """The README's main job in a fresh process on an empty cache: seconds from its start to its
    first line (the table, printed before the plot is drawn) and to its exit."""
    with tempfile.TemporaryDirectory(prefix="slipmaps-first-call-") as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        load = os.getloadavg()[0]
        argv = [sys.executable, "-m", "slipmaps", "compare", "--plot", os.path.join(cache, "compare.png")]
        t0 = time.perf_counter()
        with subprocess.Popen(argv, env=env, stdout=subprocess.PIPE, text=True) as proc:
            proc.stdout.readline()
            first_line = time.perf_counter() - t0
            proc.stdout.read()
        seconds = time.perf_counter() - t0
        if proc.returncode != 0:
            raise RuntimeError(f"the main job exited with {proc.returncode}")
    return {
        "map": "README main job",
        "role": "compare --plot",
        "load_1min": load,
        "first_line_s": first_line,
        "first_call_s": seconds,
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--maps", nargs="*", help="these maps only (default: every map)")
    parser.add_argument("--jacobian", action="store_true", help="also the first apex_return_jacobian")
    parser.add_argument("--batch", action="store_true", help="also the first batch call (of two states)")
    parser.add_argument("--main-job", action="store_true", help="also the README's main job (target 15 s)")
    parser.add_argument("--json", action="store_true", help="print JSON instead of the report")
    args = parser.parse_args()
    from slipmaps.runtime.api.index import maps

    names = args.maps or [m.name for m in maps()]
    roles = ["apex_return"] + (["apex_return_jacobian"] if args.jacobian else [])
    if args.batch:
        roles += [f"{role}_batch" for role in roles]
    rows = []
    for name in names:
        for role in roles:
            rows.append(first_call(name, role))
            if not args.json:
                r = rows[-1]
                target = {"apex_return": 5.0, "apex_return_jacobian": 10.0}.get(role)
                met = "" if target is None else "met" if r["first_call_s"] <= target else "NOT met"
                print(
                    f"{name:<18} {role:<27} first call {r['first_call_s']:6.1f} s (CPU "
                    f"{r['first_call_cpu_s']:.1f} s"
                    + ("" if target is None else f"; target <= {target:g} s: {met}")
                    + f"); import {r['import_s']:.1f} s; 1-min load {r['load_1min']:.1f}",
                    flush=True,
                )
    if args.main_job:
        rows.append(main_job())
        if not args.json:
            r = rows[-1]
            met = "met" if r["first_call_s"] <= 15.0 else "NOT met"
            print(
                f"README main job (compare --plot): table after {r['first_line_s']:.1f} s, exit after "
                f"{r['first_call_s']:.1f} s (target 15 s: {met}); 1-min load {r['load_1min']:.1f}",
                flush=True,
            )
    if args.json:
        print(json.dumps(rows, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
