"""Benchmark: rows per second of ``slipmaps.sweep`` beside the bare batch kernel, in one run.

For an approximate map (default ``geyer``, the cheapest, so the sweep's own cost shows most) and for
``exact``, over the same grid of apex speeds x touchdown angles (apex height 1 m, human runner):

- bare: one :func:`slipmaps.apex_return_batch` call over all N rows (inputs prepared; what the
  sweep's chunks call), best of ``--repeat``;
- sweep in-process: :func:`slipmaps.sweep` into a fresh directory, Parquet and CSV (computing the
  rows chunk by chunk from their indices, encoding and writing the chunk files, manifest, counts),
  best of ``--repeat``;
- sweep on a two-worker ``LocalCluster`` (one dask thread and one numba thread per worker, started
  and warmed before timing; its start-up time printed apart), Parquet.

Overhead = bare rate / sweep rate - 1 (the issue's target: under 20 % for the exact map). The exact
map's N is chosen so the bare call takes about ``--seconds`` (a probe measures its rate first), so
the same command stays meaningful when the exact simulator gets faster. Ratios are measured in one
run; absolute rates move with the machine and its load (printed). Usage::

    python benchmarks/bench_sweep.py [--map geyer] [--n N] [--seconds S] [--repeat R] [--json]
"""

from __future__ import annotations

import argparse
import json
import math
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import slipmaps
from slipmaps.runtime.sweep.compute import compute

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import machine  # noqa: E402

P = slipmaps.HUMAN_RUNNER
ANGLES = (0.25, 0.45)
SPEEDS = (3.0, 7.0)


def grid(n: int, n_angles: int) -> tuple[np.ndarray, np.ndarray]:
    return np.linspace(*SPEEDS, max(1, n // n_angles)), np.linspace(*ANGLES, n_angles)


def definition(name: str, n: int, n_angles: int, chunk_rows: int | None) -> slipmaps.Sweep:
    speeds, angles = grid(n, n_angles)
    axes = {
        "apex_speed": {"low": SPEEDS[0], "high": SPEEDS[1], "num": len(speeds)},
        "touchdown_angle": {"low": ANGLES[0], "high": ANGLES[1], "num": len(angles)},
    }
    return slipmaps.Sweep(name, axes, {"apex_height": 1.0}, params=P, chunk_rows=chunk_rows)


def timed(fn) -> float:
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def bare(sw: slipmaps.Sweep):
    """The bare batch call over the sweep's rows (a closure to time)."""
    speeds, angles = (np.asarray(sw.axes[i].grid_values()) for i in range(2))
    return lambda: slipmaps.apex_return_batch(sw.map, P, 1.0, speeds[:, None], angles)


def swept(sw: slipmaps.Sweep, fmt: str, root: Path, scheduler=None):
    """The sweep into a fresh directory under ``root`` each call (a closure to time)."""
    count = [0]
    where = "inprocess" if scheduler is None else "cluster"

    def once():
        count[0] += 1
        out = root / f"{where}-{fmt}-{count[0]}"
        slipmaps.sweep(sw, out, format=fmt, scheduler=scheduler, progress=False)

    return once


def exact_rows(seconds: float, n_angles: int) -> int:
    """Rows for which the bare exact batch takes about ``seconds`` (a 64-row probe, after a warm-up)."""
    probe = bare(definition("exact", 64, n_angles, None))
    probe()
    rate = 64 / timed(probe)
    return max(4 * n_angles, int(rate * seconds) // n_angles * n_angles)


def measure(name: str, n: int, n_angles: int, chunk_rows: int | None, repeat: int, client, formats) -> dict:
    """Rows per second of each way, best of ``repeat``, the ways interleaved within a repeat so that
    a change of the machine's load hits them alike."""
    sw = definition(name, n, n_angles, chunk_rows)
    compute(definition(name, 8, 4, None), 0)  # compile / load the kernels
    root = Path(tempfile.mkdtemp(prefix="bench_sweep_"))
    ways = {"bare": bare(sw)}
    ways.update({f"inprocess_{fmt}": swept(sw, fmt, root) for fmt in formats})
    if client is not None:
        client.run(compute, definition(name, 8, 4, None), 0)
        ways["cluster_parquet"] = swept(sw, "parquet", root, scheduler=client)
    best = dict.fromkeys(ways, math.inf)
    try:
        for _ in range(repeat):
            for key, fn in ways.items():
                best[key] = min(best[key], timed(fn))
            shutil.rmtree(root, ignore_errors=True)
    finally:
        shutil.rmtree(root, ignore_errors=True)
    row = {"map": name, "rows": sw.rows, "chunk_rows": sw.chunk_rows, "chunks": sw.chunks}
    row.update({key: sw.rows / t for key, t in best.items()})
    return row


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--map", default="geyer", help="the approximate map (default %(default)s)")
    ap.add_argument("--n", type=int, default=2_000_000, help="rows of the approximate map's sweep")
    ap.add_argument("--seconds", type=float, default=4.0, help="about how long the bare exact call runs")
    ap.add_argument("--chunks-exact", type=int, default=8, help="chunks of the exact sweep (default 8)")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-cluster", action="store_true", help="skip the LocalCluster measurements")
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args(argv)

    client = cluster = None
    startup = math.nan
    if not args.no_cluster:
        import distributed

        t0 = time.perf_counter()
        cluster = distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None
        )
        client = distributed.Client(cluster)
        startup = time.perf_counter() - t0
    try:
        rows = [measure(args.map, args.n, 200, None, args.repeat, client, ("parquet", "csv"))]
        n_exact = exact_rows(args.seconds, 20)
        chunk = max(1, -(-n_exact // args.chunks_exact))
        rows.append(measure("exact", n_exact, 20, chunk, args.repeat, client, ("parquet", "csv")))
    finally:
        if client is not None:
            client.close()
            cluster.close()

    info = machine()
    if args.json:
        print(json.dumps({"machine": info, "cluster_startup_s": startup, "rows": rows}, indent=2))
        return 0
    print(
        f"machine: {info['cpu']}, {info['cpus']} cores, numba {info['numba']} "
        f"({info['numba_threads']} threads), 1-minute load {info['load_1min']:.2f}; best of {args.repeat}"
    )
    if client is not None:
        print(f"LocalCluster(n_workers=2, threads_per_worker=1) start-up: {startup:.1f} s (not in the rates)")
    head = f"{'map':<8} {'rows':>9} {'chunk':>7} {'bare kernel':>12}"
    cols = [("inprocess_parquet", "in-process parquet"), ("inprocess_csv", "in-process csv")]
    cols += [("cluster_parquet", "cluster(2) parquet")] if client is not None else []
    print(head + "".join(f" {label:>28}" for _, label in cols))
    for r in rows:
        line = f"{r['map']:<8} {r['rows']:>9} {r['chunk_rows']:>7} {r['bare']:>12.4g}"
        for key, _ in cols:
            line += f" {r[key]:>14.4g} ({r['bare'] / r[key] - 1:>+8.1%})"
        print(line)
    print(
        "rates in rows/s; (overhead) = bare rate / sweep rate - 1, so negative is faster than the bare call"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
