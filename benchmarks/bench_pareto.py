"""Benchmark: the cost-accuracy front of every map, its variants and the exact map's tolerances.

Every map and variant worth listing (``VARIANTS``: each map at its defaults, the iterative maps'
passes, the exact map at rtol 1e-3 ... 1e-11) runs its public batch API
``slipmaps.apex_return_batch(name, params, h, v, th, **options)`` in one process on the same
states: the points of two grids of the accuracy study (runtime/studies/grids.py, read only), Yu,
Li and Cai's protocol (k l0 / (m g) = 10) and the human runner's nonsymmetric grid. Per variant:

* ns per apex return on one numba thread and on all of them (best of ``--repeat`` rounds, each
  timing every variant once in turn, the grids' points tiled to a batch of about ``--seconds`` per
  call, compilation excluded) and their ratio (the batch kernels' scaling, issue 19 item 6);
* the mean and max next-apex error ``|(dh, dv)| / |(h, v)|`` (the accuracy study's) against the
  exact map at its defaults (rtol 1e-11), over the points where both complete the step, and the
  points where the variant fails and the exact map does not (printed with both grids pooled,
  kept per grid in the JSON);
* the cheapest other variant that dominates it (``slipmaps.runtime.api.front.dominated_by``: its
  map requires nothing more (``geyer``'s constant stiffness cannot stand in for ``geyer-vs``), no
  more costly on one thread, no larger mean error, max error or failures on either grid to
  round-off, better in one).

The exact rows also give the cost at each rtol relative to rtol 1e-11 (item 2's target: at most
0.4 at 1e-6). A figure (log cost against log mean error, max error as the bar's top, the front
drawn) is written to ``--figure`` (default docs/pareto.png) and the measured front to ``--front``
(default runtime/api/pareto.json: package data, what ``slipmaps maps`` shows per map; written by
this benchmark only). Absolute times move with the machine and its load (printed); the ratios are
measured side by side in one run. Usage::

    python benchmarks/bench_pareto.py [--repeat R] [--seconds S] [--figure PATH] [--front PATH]
                                      [--json] [--quick]

``--quick`` (a smoke run that CI can afford: every 7th point of each grid, one timed run of short
batches, neither figure nor front written unless given) checks that every variant runs and prints
the table; its times and dominance are too noisy to quote.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numba
import numpy as np
import slipmaps
from slipmaps.runtime.api.front import FRONT_FILE, dominated_by, errors_on
from slipmaps.runtime.api.index import lookup
from slipmaps.runtime.studies.grids import GRIDS

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_maps import best_of, machine, with_threads  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
#: The two grids, by name in runtime/studies/grids.py.
GRID_NAMES = ("Yu, Li and Cai protocol", "human runner, nonsymmetric")
EXACT_RTOLS = (1e-3, 1e-4, 1e-6, 1e-8, 1e-11)
#: The exact map at its defaults (rtol 1e-11, atol 1e-12): the errors' reference.
REFERENCE = ("exact", {})
REFERENCE_RTOL = 1e-11


def _rtol(r: float) -> str:
    return f"1e{round(math.log10(r))}"


#: The map whose pass counts get rows of their own (0-4 passes, then its default).
PASSES_MAP, PASSES = "iterative", (0, 1, 2, 3, 4)


def _map_rows(name: str) -> tuple[tuple[str, str, dict], ...]:
    if name != PASSES_MAP:
        return ((name, name, {}),)
    default = next(m for m in slipmaps.maps() if m.name == name).option("iterations").default
    return (
        *((f"{name}, {n} pass{'' if n == 1 else 'es'}", name, {"iterations": n}) for n in PASSES),
        (f"{name} (default, {default} passes)", name, {}),
    )


#: (label, map, options): each map of the index at its defaults (in its order), the iterative
#: map's passes, the exact map's tolerances (the last is the reference of the errors).
VARIANTS: tuple[tuple[str, str, dict], ...] = (
    *(row for m in slipmaps.maps() if m.name != REFERENCE[0] for row in _map_rows(m.name)),
    *((f"exact, rtol {_rtol(r)}", "exact", {"rtol": r}) for r in EXACT_RTOLS if r != REFERENCE_RTOL),
    (f"exact (default, rtol {_rtol(REFERENCE_RTOL)})", *REFERENCE),
)


def _grids():
    by_name = {g.name: g for g in GRIDS}
    return [by_name[n] for n in GRID_NAMES]


def _batch(name: str, options: dict, params, pt: list[np.ndarray], seconds: float):
    """A timing call of one variant on one grid: the points tiled to a batch of about ``seconds`` on
    one thread; returns (batch size, the call)."""
    pilot = with_threads(
        1, lambda: best_of(lambda: slipmaps.apex_return_batch(name, params, *pt, **options), 1)
    )
    reps = int(np.clip(seconds / max(pilot, 1e-9), 1, 2000))
    batch = [np.ascontiguousarray(np.tile(a, reps)) for a in pt]
    return batch[0].shape[0], lambda: slipmaps.apex_return_batch(name, params, *batch, **options)


def _times(calls: list, repeat: int) -> list[tuple[float, float]]:
    """Best (one thread, all threads) time of each call over ``repeat`` rounds; every round times
    every call once on each thread count in turn, so that a change in the machine's load falls on
    all the variants alike instead of on the ones measured while it lasted."""
    best = [[math.inf, math.inf] for _ in calls]
    for _ in range(repeat):
        for b, call in zip(best, calls, strict=True):
            b[0] = min(b[0], with_threads(1, lambda c=call: best_of(c, 1)))
            b[1] = min(b[1], best_of(call, 1))
    return [(a, b) for a, b in best]


def measure(repeat: int, seconds: float, every: int = 1) -> dict:
    grids = _grids()
    points = [[np.ascontiguousarray(a[::every]) for a in g.points().T] for g in grids]
    refs = [
        slipmaps.apex_return_batch(REFERENCE[0], g.params, *pt, **REFERENCE[1])
        for g, pt in zip(grids, points, strict=True)
    ]
    threads = numba.get_num_threads()
    rows, calls = [], []
    for label, name, options in VARIANTS:
        by_grid, n_total = [], 0
        pooled_ref = {k: [] for k in ("status", "next_apex_height", "next_apex_speed")}
        pooled_got = {k: [] for k in pooled_ref}
        for g, pt, ref in zip(grids, points, refs, strict=True):
            got = slipmaps.apex_return_batch(name, g.params, *pt, **options)  # compiles or loads
            by_grid.append(errors_on(got, ref))
            for k in pooled_ref:
                pooled_ref[k].append(np.asarray(ref[k]))
                pooled_got[k].append(np.asarray(got[k]))
            n, call = _batch(name, options, g.params, pt, seconds)
            n_total += n
            calls.append(call)
        pooled = errors_on(
            {k: np.concatenate(v) for k, v in pooled_got.items()},
            {k: np.concatenate(v) for k, v in pooled_ref.items()},
        )
        rows.append(
            {
                "label": label,
                "map": name,
                "options": options,
                "requires": list(lookup(name).requires),
                "states_timed": n_total,
                **pooled,
                "by_grid": by_grid,
            }
        )
    times = _times(calls, repeat)
    per_grid = len(grids)
    for i, r in enumerate(rows):
        t1 = sum(t[0] for t in times[i * per_grid : (i + 1) * per_grid])
        tn = sum(t[1] for t in times[i * per_grid : (i + 1) * per_grid])
        r["ns_1_thread"] = 1e9 * t1 / r["states_timed"]
        r["ns_all_threads"] = 1e9 * tn / r["states_timed"]
        r["scaling"] = t1 / tn
    for r, d in zip(rows, dominated_by(rows), strict=True):
        r["dominated_by"] = d
    exact = {r["options"].get("rtol", REFERENCE_RTOL): r for r in rows if r["map"] == "exact"}
    base = exact[REFERENCE_RTOL]["ns_1_thread"]
    return {
        "measured_by": "benchmarks/bench_pareto.py",
        "date": time.strftime("%Y-%m-%d"),
        "machine": machine(),
        "threads": threads,
        "grids": [f"{g.name} ({len(pt[0])} points)" for g, pt in zip(grids, points, strict=True)],
        "grid_names": list(GRID_NAMES),
        "every": every,
        "rows": rows,
        "exact_cost_ratio": {_rtol(r): exact[r]["ns_1_thread"] / base for r in EXACT_RTOLS},
    }


def _pct(x: float) -> str:
    if not math.isfinite(x):
        return "-"
    if x == 0.0:
        return "0"
    if x >= 0.1:
        return f"{100 * x:.0f} %"
    return f"{100 * x:.2g} %" if x >= 1e-5 else f"{100 * x:.1e} %"


def report(r: dict) -> str:
    m = r["machine"]
    lines = [
        f"machine: {m['cpu']}, {m['cpus']} CPUs, numba {m['numba']} ({r['threads']} threads), "
        f"Python {m['python']}, 1-min load {m['load_1min']}",
        "states: " + "; ".join(r["grids"]) + "; errors against the exact map at rtol 1e-11, "
        "both grids pooled; dominated: by a variant requiring nothing more, no more costly and no worse "
        "on either grid",
        "",
        f"| variant | ns per apex return, 1 thread | {r['threads']} threads | scaling | mean error | "
        "max error | failures | dominated by |",
        "| --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for row in r["rows"]:
        lines.append(
            f"| {row['label']} | {row['ns_1_thread']:,.0f} | {row['ns_all_threads']:,.0f} | "
            f"{row['scaling']:.2f}x | {_pct(row['mean_error'])} | {_pct(row['max_error'])} | "
            f"{row['failures']} | {row['dominated_by'] or '-'} |"
        )
    ratio = r["exact_cost_ratio"]
    met = "met" if ratio["1e-6"] <= 0.4 else "NOT met"
    lines += [
        "",
        "exact map, cost relative to rtol 1e-11 (1 thread): "
        + ", ".join(f"rtol {k}: {v:.2f}" for k, v in ratio.items())
        + f" (target at 1e-6: <= 0.4, {met})",
        f"scaling on {r['threads']} threads (target >= 1.8x): lowest "
        f"{min(x['scaling'] for x in r['rows']):.2f}x, highest {max(x['scaling'] for x in r['rows']):.2f}x",
    ]
    return "\n".join(lines)


def figure(r: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = [x for x in r["rows"] if x["mean_error"] > 0.0 and math.isfinite(x["mean_error"])]
    # the front in the figure's plane: each variant with a lower mean error than every cheaper one
    front, best = [], math.inf
    for x in sorted(rows, key=lambda x: (x["ns_1_thread"], x["mean_error"])):
        if x["mean_error"] < best:
            front.append(x)
            best = x["mean_error"]
    fig, ax = plt.subplots(figsize=(8.5, 6.0))
    for x in rows:
        exact = x["map"] == "exact"
        color = "tab:red" if exact else ("tab:blue" if x in front else "tab:gray")
        ax.plot([x["mean_error"], x["max_error"]], [x["ns_1_thread"]] * 2, color=color, lw=1, alpha=0.5)
        ax.plot(x["mean_error"], x["ns_1_thread"], "s" if exact else "o", color=color)
        ax.annotate(x["label"], (x["mean_error"], x["ns_1_thread"]), fontsize=7, xytext=(4, 3),
                    textcoords="offset points")  # fmt: skip
    front.sort(key=lambda x: x["mean_error"])
    ax.step([x["mean_error"] for x in front], [x["ns_1_thread"] for x in front], where="post", color="k",
            lw=1, ls="--", label="front: the cheapest variant at or below each mean error")  # fmt: skip
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("next-apex error against exact rtol 1e-11 (mean: marker; line to the max)")
    ax.set_ylabel("ns per apex return (1 thread)")
    ax.set_title(
        "Cost against accuracy: Yu, Li and Cai grid and human runner, "
        + f"load {r['machine']['load_1min']:.1f}"
    )
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=5, help="timed runs, best kept (default %(default)s)")
    parser.add_argument(
        "--seconds", type=float, default=0.1, help="about this long a batch (default %(default)s)"
    )
    parser.add_argument("--figure", type=Path, default=None, help="figure path (default docs/pareto.png)")
    parser.add_argument(
        "--front", type=Path, default=None, help=f"measured front (default runtime/api/{FRONT_FILE})"
    )
    parser.add_argument("--json", action="store_true", help="print JSON instead of the report")
    parser.add_argument("--quick", action="store_true", help="a smoke run: few points, one short timing")
    args = parser.parse_args()
    if args.quick:
        r = measure(1, 0.002, every=7)
    else:
        r = measure(args.repeat, args.seconds)
    path = args.figure if args.figure is not None or args.quick else ROOT / "docs" / "pareto.png"
    if path is not None:
        figure(r, path)
        print(f"figure: {path}", file=sys.stderr)
    front = args.front if args.front is not None or args.quick else ROOT / "runtime" / "api" / FRONT_FILE
    if front is not None:
        front.write_text(json.dumps(r, indent=1) + "\n")
        print(f"front: {front}", file=sys.stderr)
    print(json.dumps(r, indent=2) if args.json else report(r))
    return 0


if __name__ == "__main__":
    sys.exit(main())
