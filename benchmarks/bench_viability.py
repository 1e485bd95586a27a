"""Benchmark and study: viability (issue 31) with slipmaps' maps, the numbers of docs/viability.md.

Parts (``--part``, repeatable; default all but ``scale``):

- ``vibly``: Heim and Spröwitz's SLIP demo (vibly's demos/computeQ_slip.py: m 80 kg, k 8200 N/m,
  l0 1 m, E 1877.08 J, s = m g y / E on 180 points in [0.1, 0.995], angles -10 ... 70 deg in 161
  steps) with the exact map: the time of ``slipmaps.viability`` (best of ``--repeat`` after a warm-up
  call), the kernel's extent and the measure's peak, with ``outside="edge"`` (vibly's) and
  ``"fail"``; and against vibly's published arrays (tests/data/vibly_slip_map.npz).
- ``maps``: every approximate map on the same grid against the exact map: intersection over union of
  Q_V, the false-viable share (pairs the map calls viable that the exact map does not, over the
  map's viable pairs), the kernel states and the seconds.
- ``stiffness``: what a free k_d buys, on (height, speed) grids, vibly's runner and the human
  runner: the kernel and the measure with k_d = k_c against k_d on [k/2, 2k] (``--n`` points per
  axis), both discretisations (``outside`` fail and edge).
- ``maps2d``: ``iterative`` and ``geyer-vs`` against the exact map on the stiffness part's (height,
  speed) grid of vibly's runner with k_d free.
- ``iterative2d``: ``iterative``'s options (``nodes``, ``iterations``) on the ``maps2d`` grid
  against the exact map: the false-viable share, the cost per step, and where the false-viable pairs
  are (their states, next to the exact kernel's border or not; their exact next state's cell).
- ``retraction``: vibly's grid with a retraction rate (-3 ... 0 rad/s) as a second action.
- ``retraction2d``: retraction with k_d on a (height, speed) grid of vibly's runner (``--n`` x
  ``--n`` states, 2 ``--n`` + 1 angles, 5 k_d in [k/2, 2k], 5 rates in [-3, 0] rad/s; the exact map):
  the kernel and the measures with the actions angle; angle and k_d; angle and rate; all three; both
  rules for the grid's border.
- ``robust``: k_d chosen at the apex or at the bottom on an unknown ground (5 heights in
  [-d, d] per ``--depth`` d [m]; default 0.02, 0.05, 0.1, 0.2) with k_d = k_c as the baseline,
  both runners, ``iterative`` and the exact map (``slipmaps.robust_viability``); and with the
  ground known, whether the two stages give the same sets.
- ``scale``: ``--n``^4 pairs (height, speed, angle, k_d) with a map (``--scale-map``), in this
  process or (``--scale-scheduler local:2 --scale-out DIR``) as a sweep on a Dask cluster: seconds,
  peak memory (this process and its children, sampled) and the sets' fingerprints. The full run of
  the issue is ``--part scale --n 100 --scale-map iterative`` (minutes; CI runs small grids only).

Usage: ``python benchmarks/bench_viability.py [--part vibly ...] [--json PATH]``.
"""

from __future__ import annotations

import argparse
import json
import resource
import time
from pathlib import Path

import numpy as np
import slipmaps

ROOT = Path(__file__).resolve().parent.parent
VIBLY = slipmaps.SlipParams(m=80.0, l0=1.0, k=8200.0, g_s=9.81, g_f=9.81)
ENERGY = 1877.08
S_GRID = np.linspace(0.1, 1, 181)[:-1]
ANGLES = np.radians(np.linspace(-10.0, 70.0, 161))


def _demo(name: str = "exact", outside: str = "fail", **options):
    heights = S_GRID * ENERGY / (VIBLY.m * VIBLY.g_f)
    return slipmaps.viability(
        name, VIBLY, apex_height=heights, touchdown_angle=ANGLES, energy=ENERGY, outside=outside, **options
    )


def _shape(vs) -> dict:
    s = vs.summary()
    c = VIBLY.m * VIBLY.g_f / ENERGY
    lo_hi = s["kernel_extent"]["apex_height"]
    out = {
        "kernel_states": s["kernel_states"],
        "viable_pairs": s["viable_pairs"],
        "failed": s["failed"],
        "measure_max": s["measure_max"],
        "measure_peak_s": s["measure_peak"]["apex_height"] * c,
        "kernel_s": None if lo_hi is None else [lo_hi[0] * c, lo_hi[1] * c],
        "rounds": s["rounds"],
    }
    # where the viable angles lie at the measure's peak and the kernel's ends
    i = int(np.argmax(vs.measure))
    ang = np.degrees(ANGLES[vs.viable[i]])
    out["peak_angles_deg"] = [float(ang.min()), float(ang.max())]
    return out


def part_vibly(repeat: int) -> dict:
    _demo()  # compile or load
    out = {}
    for outside in ("edge", "fail"):
        times = []
        for _ in range(repeat):
            t = time.perf_counter()
            vs = _demo(outside=outside)
            times.append(time.perf_counter() - t)
        out[outside] = {"seconds": min(times), "seconds_map": vs.seconds["map"], **_shape(vs)}
        if outside == "edge":
            ref = np.load(ROOT / "tests" / "data" / "vibly_slip_map.npz")
            out["vibly_equal"] = {
                "Q_F": bool(np.array_equal(vs.failed, ref["Q_F"])),
                "Q_V": bool(np.array_equal(vs.viable, ref["Q_V"])),
                "S_M": bool(np.array_equal(vs.measure, ref["S_M"])),
            }
            statuses = {
                slipmaps.Status(int(c)).name: int((vs.status == c).sum()) for c in np.unique(vs.status)
            }
            statuses["OK, next speed not positive"] = int(((vs.status == 0) & vs.failed).sum())
            out["statuses"] = statuses
        else:
            out["fail_vs_edge_pairs"] = int(out["edge"]["viable_pairs"] - out["fail"]["viable_pairs"])
    out["pairs"] = int(S_GRID.size * ANGLES.size)
    return out


def _compare(vs, ref) -> dict:
    a, b = vs.viable, ref.viable
    union = (a | b).sum()
    return {
        "iou": float((a & b).sum() / union) if union else 1.0,
        "false_viable": float((a & ~b).sum() / a.sum()) if a.sum() else 0.0,
        "false_viable_pairs": int((a & ~b).sum()),
        "missed_pairs": int((b & ~a).sum()),
        "kernel_states": int(vs.kernel.sum()),
        "kernel_differs": int((vs.kernel != ref.kernel).sum()),
        "failed_differs": int((vs.failed != ref.failed).sum()),
    }


def _maps_figure(ref, sets: dict, path: str) -> None:
    """A panel per map: the state-action plane, pairs viable for both (green), for the map only
    (false-viable, red), for the exact map only (missed, blue)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap

    cols = 4
    rows = -(-len(sets) // cols)
    fig, axes = plt.subplots(
        rows, cols, figsize=(3.2 * cols, 2.7 * rows), sharex=True, sharey=True, constrained_layout=True
    )
    cmap = ListedColormap(["#f4f4f4", "#2a9d8f", "#d62828", "#1d4ed8"])
    deg = np.degrees(ANGLES)
    for ax, (name, vs) in zip(axes.ravel(), sets.items(), strict=False):
        a, b = vs.viable, ref.viable
        image = np.select([a & b, a & ~b, b & ~a], [1, 2, 3], 0)
        ax.pcolormesh(deg, S_GRID, image, cmap=cmap, vmin=0, vmax=3, shading="nearest", rasterized=True)
        ax.set_title(f"{name}: {int((a & ~b).sum())} false, {int((b & ~a).sum())} missed", fontsize=8)
    for ax in axes.ravel()[len(sets) :]:
        ax.axis("off")
    for ax in axes[-1]:
        ax.set_xlabel("touchdown angle [deg]")
    for ax in axes[:, 0]:
        ax.set_ylabel("s = m g y / E")
    fig.suptitle(
        "Q_V of each map against the exact map's (vibly's SLIP grid): green both, red the map "
        "only (false-viable), blue the exact map only",
        fontsize=9,
    )
    fig.savefig(path, dpi=100)
    plt.close(fig)


def part_maps(figure: str | None = None) -> dict:
    ref = _demo()
    out = {"exact": {"kernel_states": int(ref.kernel.sum()), "viable_pairs": int(ref.viable.sum())}}
    sets = {}
    for info in slipmaps.maps():
        if info.name == "exact":
            continue
        try:
            _demo(info.name)  # compile or load
        except ValueError as exc:
            out[info.name] = {"error": str(exc)}
            continue
        t = time.perf_counter()
        vs = _demo(info.name)
        out[info.name] = {"seconds": time.perf_counter() - t, **_compare(vs, ref)}
        sets[info.name] = vs
        print(info.name, out[info.name], flush=True)
    if figure:
        _maps_figure(ref, sets, figure)
    return out


def _stiffness_case(params, heights, speeds, angles, k_d) -> dict:
    out = {}
    grid = {"apex_height": heights, "apex_speed": speeds, "touchdown_angle": angles}
    for outside in ("fail", "edge"):
        fixed = slipmaps.viability("exact", params, **grid, outside=outside)
        free = slipmaps.viability("exact", params, **grid, k_d=k_d, outside=outside)
        row = {}
        for label, vs in (("k_d = k_c", fixed), ("k_d free", free)):
            safe = (~vs.failed).any(axis=tuple(range(2, vs.failed.ndim)))
            angles_ok = (
                vs.viable.any(axis=tuple(range(3, vs.viable.ndim))) if vs.viable.ndim > 3 else vs.viable
            )
            row[label] = {
                "kernel_states": int(vs.kernel.sum()),
                "mean_angle_share_in_kernel": float(angles_ok.mean(axis=2)[vs.kernel].mean())
                if vs.kernel.any()
                else 0.0,
                "states_with_a_safe_step": int(safe.sum()),
                "mean_measure_in_kernel": float(vs.measure[vs.kernel].mean()) if vs.kernel.any() else 0.0,
                "measure_max": float(vs.measure.max()),
                "rounds": vs.rounds,
                "seconds": vs.seconds["map"] + vs.seconds["kernel"],
            }
        both = fixed.kernel & free.kernel
        row["fixed_kernel_inside_free"] = bool(both.sum() == fixed.kernel.sum())
        out[outside] = row
    out["states"] = int(heights.size * speeds.size)
    return out


def per_level(params, heights, speeds, angles, levels: int = 80) -> dict:
    """k_d = k_c without the (height, speed) grid's erosion: each node (h, v) of a safe step judged on
    its own energy level's 1-D grid (``levels`` heights from the touchdown limit to 99.5 % of the
    level's top, with h inserted), the discretisation of vibly's setting."""
    kernel = np.zeros((heights.size, speeds.size), dtype=bool)
    measure = np.zeros((heights.size, speeds.size))
    g = params.g_f
    for i, h in enumerate(heights):
        for j, v in enumerate(speeds):
            energy = params.m * (g * h + 0.5 * v * v)
            top = energy / (params.m * g)
            grid = np.unique(np.append(np.linspace(0.3 * params.l0, 0.995 * top, levels), h))
            vs = slipmaps.viability("exact", params, apex_height=grid, touchdown_angle=angles, energy=energy)
            at = int(np.searchsorted(grid, h))
            kernel[i, j], measure[i, j] = vs.kernel[at], vs.measure[at]
    return {
        "kernel_states": int(kernel.sum()),
        "mean_measure_in_kernel": float(measure[kernel].mean()) if kernel.any() else 0.0,
        "measure_max": float(measure.max()),
    }


def part_stiffness(n: int, levels: bool = True) -> dict:
    angles = np.radians(np.linspace(-10.0, 70.0, 2 * n + 1))
    human = slipmaps.HUMAN_RUNNER
    cases = {
        "vibly (k 8200 N/m)": (VIBLY, np.linspace(0.5, 2.4, n), np.linspace(0.5, 7.0, n)),
        "human runner (k 20 kN/m)": (human, np.linspace(0.6, 1.6, n), np.linspace(1.0, 8.0, n)),
    }
    out = {}
    for label, (params, heights, speeds) in cases.items():
        k = params.k_c
        out[label] = {
            "grid": {
                "heights": [heights[0], heights[-1]],
                "speeds": [speeds[0], speeds[-1]],
                "n": n,
                "angles": angles.size,
                "k_d": [k / 2, 2 * k, 5],
            },
            **_stiffness_case(params, heights, speeds, angles, np.linspace(k / 2, 2 * k, 5)),
        }
        if not levels:
            print(label, out[label], flush=True)
            continue
        t = time.perf_counter()
        out[label]["k_d = k_c per energy level"] = per_level(params, heights, speeds, angles)
        out[label]["k_d = k_c per energy level"]["seconds"] = time.perf_counter() - t
        print(label, out[label], flush=True)
    return out


def part_maps2d(n: int) -> dict:
    """The variable-stiffness maps against the exact one on vibly's (height, speed) grid with k_d free
    (the stiffness part's grid)."""
    grid = _grid2d(n)
    ref = slipmaps.viability("exact", VIBLY, **grid)
    out = {"exact": {"kernel_states": int(ref.kernel.sum()), "viable_pairs": int(ref.viable.sum())}}
    for name in ("iterative", "geyer-vs"):
        t = time.perf_counter()
        vs = slipmaps.viability(name, VIBLY, **grid)
        out[name] = {"seconds": time.perf_counter() - t, **_compare(vs, ref)}
    return out


def _grid2d(n: int) -> dict:
    return {
        "apex_height": np.linspace(0.5, 2.4, n),
        "apex_speed": np.linspace(0.5, 7.0, n),
        "touchdown_angle": np.radians(np.linspace(-10.0, 70.0, 2 * n + 1)),
        "k_d": np.linspace(4100.0, 16400.0, 5),
    }


def _border(kernel: np.ndarray) -> np.ndarray:
    """The kernel's states with a 4-neighbour outside it (or on the grid's edge)."""
    pad = np.pad(kernel, 1, constant_values=False)
    inner = pad[:-2, 1:-1] & pad[2:, 1:-1] & pad[1:-1, :-2] & pad[1:-1, 2:]
    return kernel & ~inner


def _where_false_viable(vs, ref) -> dict:
    """Where the pairs ``vs`` calls viable and ``ref`` does not lie: their states (how many, how many
    on the exact kernel's border), the exact step (fails, leaves the grid, or its cell: how many of
    its 4 nodes are in the exact kernel), and how far the two next states are apart in grid cells."""
    fv = vs.viable & ~ref.viable
    idx = np.argwhere(fv)
    h, v = ref.states["apex_height"], ref.states["apex_speed"]
    states = {(int(i), int(j)) for i, j, *_ in idx}
    border = _border(ref.kernel)
    nxt = ref.next_state[fv]
    ok = ~ref.failed[fv]
    ci = np.digitize(nxt[ok, 0], h)
    cj = np.digitize(nxt[ok, 1], v)
    beyond = (ci == 0) | (ci == h.size) | (cj == 0) | (cj == v.size)
    nodes_in = []
    for a, b in zip(ci[~beyond], cj[~beyond], strict=True):
        nodes_in.append(int(ref.kernel[a - 1 : a + 1, b - 1 : b + 1].sum()))
    dh, dv = h[1] - h[0], v[1] - v[0]
    gap = np.abs(vs.next_state[fv] - ref.next_state[fv])[ok] / np.array([dh, dv])
    return {
        "pairs": int(fv.sum()),
        "states": len(states),
        "states_on_exact_kernel_border": int(sum(bool(border[s]) for s in states)),
        "states_in_exact_kernel": int(sum(bool(ref.kernel[s]) for s in states)),
        "exact_step_fails": int((~ok).sum()),
        "exact_next_beyond_grid": int(beyond.sum()),
        "exact_next_cell_kernel_nodes": {str(k): nodes_in.count(k) for k in range(5) if nodes_in.count(k)},
        "next_state_gap_cells_median": [float(x) for x in np.median(gap, axis=0)] if gap.size else None,
        "next_state_gap_cells_max": [float(x) for x in gap.max(axis=0)] if gap.size else None,
        "k_d": {f"{k:g}": int((idx[:, 3] == i).sum()) for i, k in enumerate(ref.actions["k_d"])},
    }


#: ``iterative``'s options measured by part ``iterative2d`` (the first is the default).
ITERATIVE_VARIANTS = (
    {},
    {"nodes": "6"},
    {"iterations": 8},
    {"iterations": 10},
    {"iterations": 20},
    {"nodes": "6", "iterations": 10},
    {"nodes": "6", "iterations": 20},
    {"nodes": "6", "iterations": 40},
)


def part_iterative2d(n: int) -> dict:
    """``iterative``'s options against the exact map on the ``maps2d`` grid (k_d free)."""
    grid = _grid2d(n)
    ref = slipmaps.viability("exact", VIBLY, **grid)
    out = {
        "exact": {
            "kernel_states": int(ref.kernel.sum()),
            "viable_pairs": int(ref.viable.sum()),
            "seconds_map": ref.seconds["map"],
            "ns_per_step": 1e9 * ref.seconds["map"] / ref.failed.size,
        }
    }
    for options in ITERATIVE_VARIANTS:
        label = "iterative " + (" ".join(f"{k}={v}" for k, v in options.items()) or "(default)")
        slipmaps.viability("iterative", VIBLY, **{**grid, "k_d": grid["k_d"][:1]}, **options)  # compile
        best = None
        for _ in range(2):
            vs = slipmaps.viability("iterative", VIBLY, **grid, **options)
            best = vs.seconds["map"] if best is None else min(best, vs.seconds["map"])
        out[label] = {
            "seconds_map": best,
            "ns_per_step": 1e9 * best / vs.failed.size,
            **_compare(vs, ref),
            "where": _where_false_viable(vs, ref),
        }
        print(label, json.dumps(out[label]), flush=True)
    return out


def part_retraction() -> dict:
    """vibly's grid with a swing-leg retraction rate as a second action (-3 ... 0 rad/s, within the maps'
    domain |rate| <= sqrt(g_f/q_r_td) = 3.13 rad/s): the kernel,
    the share of angles with some viable rate, against the leg held at the angle."""
    rates = np.linspace(-3.0, 0.0, 7)
    held = _demo()
    heights = S_GRID * ENERGY / (VIBLY.m * VIBLY.g_f)
    swung = slipmaps.viability(
        "exact", VIBLY, apex_height=heights, touchdown_angle=ANGLES, energy=ENERGY, retraction_rate=rates
    )
    angle_ok = swung.viable.any(axis=2)
    out = {"rates": rates.tolist(), "seconds": swung.seconds["map"] + swung.seconds["kernel"]}
    for label, vs, share in (
        ("held", held, held.measure),
        ("retraction free", swung, angle_ok.mean(axis=1)),
    ):
        c = VIBLY.m * VIBLY.g_f / ENERGY
        k = vs.summary()["kernel_extent"]["apex_height"]
        out[label] = {
            "kernel_states": int(vs.kernel.sum()),
            "kernel_s": None if k is None else [k[0] * c, k[1] * c],
            "mean_angle_share_in_kernel": float(share[vs.kernel].mean()),
            "angle_share_max": float(share.max()),
        }
    per_rate = {}
    for i, r in enumerate(rates):
        q = swung.viable[:, :, i]
        per_rate[f"{r:g}"] = int(q.sum())
    out["viable_pairs_per_rate"] = per_rate
    return out


def part_retraction2d(n: int) -> dict:
    """Retraction with k_d on vibly's (height, speed) grid: per set of actions and ``outside`` rule the
    kernel, the states with a step that does not fail, the mean over the kernel of the share of
    touchdown angles for which some choice of the other actions is viable, and of the measure (the
    share of all action tuples that are viable)."""
    heights, speeds = np.linspace(0.5, 2.4, n), np.linspace(0.5, 7.0, n)
    angles = np.radians(np.linspace(-10.0, 70.0, 2 * n + 1))
    k_d = np.linspace(4100.0, 16400.0, 5)
    rates = np.linspace(-3.0, 0.0, 5)
    cases = {
        "angle": {},
        "angle, k_d": {"k_d": k_d},
        "angle, rate": {"retraction_rate": rates},
        "angle, k_d, rate": {"k_d": k_d, "retraction_rate": rates},
    }
    out = {
        "grid": {"n": n, "angles": angles.size, "k_d": k_d.tolist(), "rates": rates.tolist()},
        "cases": {},
    }
    for outside in ("fail", "edge"):
        for label, actions in cases.items():
            vs = slipmaps.viability(
                "exact",
                VIBLY,
                apex_height=heights,
                apex_speed=speeds,
                touchdown_angle=angles,
                outside=outside,
                **actions,
            )
            extra = tuple(range(3, vs.viable.ndim))
            angle_ok = vs.viable.any(axis=extra) if extra else vs.viable
            safe = (~vs.failed).any(axis=tuple(range(2, vs.failed.ndim)))
            share = angle_ok.mean(axis=2)
            row = {
                "pairs": int(vs.failed.size),
                "kernel_states": int(vs.kernel.sum()),
                "states_with_a_safe_step": int(safe.sum()),
                "mean_angle_share_in_kernel": float(share[vs.kernel].mean()) if vs.kernel.any() else 0.0,
                "max_angle_share": float(share.max()),
                "mean_measure_in_kernel": float(vs.measure[vs.kernel].mean()) if vs.kernel.any() else 0.0,
                "rounds": vs.rounds,
                "seconds": vs.seconds["map"] + vs.seconds["kernel"],
            }
            if "retraction_rate" in actions:
                per_rate = vs.viable.sum(axis=tuple(range(vs.viable.ndim - 1)))
                counts = zip(rates, per_rate, strict=True)
                row["viable_pairs_per_rate"] = {f"{r:g}": int(c) for r, c in counts}
            out["cases"][f"{label} ({outside})"] = row
            print(label, outside, json.dumps(row), flush=True)
    return out


def _agreement(q: np.ndarray, ref: np.ndarray) -> dict:
    """A set of pairs against the exact map's: IoU, false-viable share and count, missed pairs."""
    union = int((q | ref).sum())
    false = int((q & ~ref).sum())
    return {
        "iou": int((q & ref).sum()) / union if union else 1.0,
        "false_viable": false,
        "false_viable_share": false / int(q.sum()) if q.any() else 0.0,
        "missed": int((ref & ~q).sum()),
    }


def part_robust(n: int, depths, maps=("iterative", "exact"), figure: str | None = None) -> dict:
    """k_d at the apex or at the bottom on an unknown ground (``slipmaps.robust_viability``): both
    runners of the stiffness part on ``--n`` x ``--n`` states, 2 ``--n`` + 1 angles, k_d on
    k_c 2^(-1 ... 1) in 5, the ground on 5 heights in [-d, d] per ``depths`` d; kernels and shares
    of viable angles per policy (also averaged over the two-stage kernel, 0 outside a policy's),
    each map against the exact map; and with the ground known (one height, 0) whether the two
    stages give the same sets. ``figure``: the human runner's sets on the largest depth (the exact
    map, the grid's border not viable) drawn there."""
    from slipmaps.runtime.analysis.viability_robust import robust_viability

    angles = np.radians(np.linspace(-10.0, 70.0, 2 * n + 1))
    cases = {
        "vibly (k 8200 N/m)": (VIBLY, np.linspace(0.5, 2.4, n), np.linspace(0.5, 7.0, n)),
        "human runner (k 20 kN/m)": (
            slipmaps.HUMAN_RUNNER,
            np.linspace(0.6, 1.6, n),
            np.linspace(1.0, 8.0, n),
        ),
    }
    out = {"depths": list(depths), "n": n, "angles": angles.size}
    for label, (params, heights, speeds) in cases.items():
        grid = {
            "apex_height": heights,
            "apex_speed": speeds,
            "touchdown_angle": angles,
            "k_d": params.k_c * 2.0 ** np.linspace(-1.0, 1.0, 5),
        }
        row: dict = {"heights": [heights[0], heights[-1]], "speeds": [speeds[0], speeds[-1]]}
        for outside in ("fail", "edge"):
            for name in maps:
                known = robust_viability(name, params, **grid, ground=[0.0], outside=outside)
                one, two = known.policies["one-stage"], known.policies["two-stage"]
                row[f"{name} ({outside}) known ground"] = {
                    "same_kernel": bool(np.array_equal(one.kernel, two.kernel)),
                    "same_viable_angles": bool(np.array_equal(one.viable.any(axis=-1), two.viable)),
                    "kernel_states": int(two.kernel.sum()),
                    "angles_in_kernel": two.summary()["angles_in_kernel"],
                }
            for depth in depths:
                sets = {}
                for name in maps:
                    rs = robust_viability(
                        name, params, **grid, ground=np.linspace(-depth, depth, 5), outside=outside
                    )
                    sets[name] = rs
                    if figure and name == "exact" and outside == "fail" and depth == max(depths):
                        if params is slipmaps.HUMAN_RUNNER:
                            rs.plot(figure)
                    cell = rs.summary() | {"seconds": dict(rs.seconds)}
                    inside = rs.policies["two-stage"].kernel
                    for policy, p in rs.policies.items():
                        cell[policy]["angles_in_two_stage_kernel"] = (
                            float(p.angles[inside].mean()) if inside.any() else 0.0
                        )
                    row[f"{name} ({outside}) d={depth:g}"] = cell
                if "exact" in sets:
                    for name, rs in sets.items():
                        if name != "exact":
                            row[f"{name} ({outside}) d={depth:g}"]["against exact"] = {
                                p: _agreement(rs.policies[p].viable, sets["exact"].policies[p].viable)
                                for p in rs.policies
                            }
                print(label, outside, depth, flush=True)
        out[label] = row
    return out


class PeakMemory:
    """The peak resident memory of this process and its descendants (a Dask cluster's workers and
    their nanny processes), sampled every ``every`` seconds by a thread: ``this`` (this process's
    peak), ``others`` (the peak of each other process by pid) and ``total`` (the peak of the
    sum over the tree at one sample), in bytes."""

    def __init__(self, every: float = 0.2) -> None:
        import threading

        import psutil

        self._me = psutil.Process()
        self._every = every
        self._stop = threading.Event()
        self.this = self.total = 0
        self.others: dict[int, int] = {}
        self._thread = threading.Thread(target=self._run, daemon=True)

    def _sample(self) -> None:
        import psutil

        total = 0
        for proc in [self._me, *self._me.children(recursive=True)]:
            try:
                rss = proc.memory_info().rss
            except psutil.Error:
                continue
            total += rss
            if proc.pid == self._me.pid:
                self.this = max(self.this, rss)
            else:
                self.others[proc.pid] = max(self.others.get(proc.pid, 0), rss)
        self.total = max(self.total, total)

    def _run(self) -> None:
        while not self._stop.wait(self._every):
            self._sample()

    def __enter__(self):
        self._sample()
        self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._stop.set()
        self._thread.join()
        self._sample()

    def as_dict(self) -> dict:
        return {
            "peak_this_process_GB": self.this / 1e9,
            "peak_other_processes_GB": sorted((v / 1e9 for v in self.others.values()), reverse=True),
            "peak_sum_GB": self.total / 1e9,
        }


def fingerprints(vs) -> dict:
    """SHA-256 (first 16 hex digits) of the study's arrays: equal fingerprints, equal arrays."""
    import hashlib

    def digest(a):
        return hashlib.sha256(np.ascontiguousarray(a).tobytes()).hexdigest()[:16]

    return {name: digest(getattr(vs, name)) for name in ("failed", "status", "viable", "kernel", "measure")}


def part_scale(
    n: int, name: str, n_k_d: int | None = None, scheduler: str | None = None, out: str | None = None
) -> dict:
    """``--n``^4 pairs with map ``name`` in this process (``scheduler`` None: ``slipmaps.viability``)
    or as a sweep into ``out`` on ``scheduler`` (``slipmaps.viability_sweep``, Parquet, next_state as
    float32): seconds, the peak memory of this process and its children, and the sets' fingerprints
    (equal to the in-process run's: the same sets)."""
    heights = np.linspace(0.5, 2.4, n)
    speeds = np.linspace(0.5, 7.0, n)
    angles = np.radians(np.linspace(-10.0, 70.0, n))
    k_d = np.linspace(4100.0, 16400.0, n if n_k_d is None else n_k_d)
    grid = {"apex_height": heights, "apex_speed": speeds, "touchdown_angle": angles[:2], "k_d": k_d[:2]}
    slipmaps.viability(name, VIBLY, **grid)  # compile or load
    grid = {"apex_height": heights, "apex_speed": speeds, "touchdown_angle": angles, "k_d": k_d}
    with PeakMemory() as memory:
        t = time.perf_counter()
        if scheduler is None:
            vs = slipmaps.viability(name, VIBLY, **grid, progress=True)
        else:
            if out is None:
                raise SystemExit("--scale-scheduler needs --scale-out DIR (the sweep's directory)")
            vs = slipmaps.viability_sweep(
                name,
                VIBLY,
                **grid,
                out=out,
                scheduler=scheduler,
                next_state_dtype="float32",
                progress=True,
            )
        total = time.perf_counter() - t
    return {
        "map": name,
        "scheduler": scheduler or "inprocess",
        "pairs": int(vs.failed.size),
        "seconds": total,
        "seconds_map": vs.seconds["map"],
        "seconds_kernel": vs.seconds["kernel"],
        "us_per_pair": 1e6 * vs.seconds["map"] / vs.failed.size,
        "max_rss_GB": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6,
        **memory.as_dict(),
        "kernel_states": int(vs.kernel.sum()),
        "viable_pairs": int(vs.viable.sum()),
        "mean_measure_in_kernel": float(vs.measure[vs.kernel].mean()) if vs.kernel.any() else 0.0,
        "rounds": vs.rounds,
        "fingerprints": fingerprints(vs),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parts = (
        "vibly",
        "maps",
        "maps2d",
        "iterative2d",
        "stiffness",
        "retraction",
        "retraction2d",
        "robust",
        "scale",
    )
    ap.add_argument("--part", action="append", choices=parts)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--n", type=int, default=30, help="points per axis (stiffness, scale)")
    ap.add_argument(
        "--depth", type=float, action="append", help="robust: the ground on [-depth, depth] m (repeatable)"
    )
    ap.add_argument("--scale-map", default="exact")
    ap.add_argument("--scale-k-d", type=int, default=None, help="k_d points of the scale grid (default --n)")
    ap.add_argument(
        "--scale-scheduler",
        default=None,
        help="scale: run the grid as a sweep (slipmaps.viability_sweep) on this scheduler, e.g. local:2",
    )
    ap.add_argument("--scale-out", default=None, help="scale: the sweep's directory (with --scale-scheduler)")
    ap.add_argument("--json", default=None, help="write the results here too")
    ap.add_argument("--figure", default=None, help="the figure of part maps, or of part robust")
    ap.add_argument("--no-levels", action="store_true", help="stiffness: skip the per-level kernels")
    args = ap.parse_args()
    parts = args.part or ["vibly", "maps", "stiffness"]
    out = {"machine": {"cpus": __import__("os").cpu_count(), "load": __import__("os").getloadavg()}}
    for part in parts:
        if part == "vibly":
            out["vibly"] = part_vibly(args.repeat)
        elif part == "maps":
            out["maps"] = part_maps(args.figure)
        elif part == "maps2d":
            out["maps2d"] = part_maps2d(args.n)
        elif part == "iterative2d":
            out["iterative2d"] = part_iterative2d(args.n)
        elif part == "retraction":
            out["retraction"] = part_retraction()
        elif part == "retraction2d":
            out["retraction2d"] = part_retraction2d(args.n)
        elif part == "robust":
            out["robust"] = part_robust(args.n, args.depth or [0.02, 0.05, 0.1, 0.2], figure=args.figure)
        elif part == "stiffness":
            out["stiffness"] = part_stiffness(args.n, not args.no_levels)
        else:
            out["scale"] = part_scale(
                args.n, args.scale_map, args.scale_k_d, args.scale_scheduler, args.scale_out
            )
        print(json.dumps({part: out[part]}, indent=1), flush=True)
    out["machine"]["load_after"] = __import__("os").getloadavg()
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1) + "\n")


if __name__ == "__main__":
    main()
