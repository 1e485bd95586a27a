"""The accuracy study reported: docs/accuracy.json (the record), docs/accuracy.md (tables and
findings) and docs/accuracy.png, through the pipeline of :mod:`.study` (:class:`AccuracyStudy`);
:mod:`.accuracy` measures.

The record has, per grid, the statistics of every variant (:func:`summarize`) and, for the figure,
the next-apex errors of the maps with the role "accuracy-figure" on the human runner's middle apex
height (:func:`figure_record`). Deterministic output: numbers to 3 significant digits in the
markdown, 6 in the JSON (which the tests re-measure against), no timings. The findings paragraphs
are computed from the numbers, so they cannot drift from the tables.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..api.paths import save_figure
from . import study as pipeline
from .accuracy import (
    DAMPING_RATIOS,
    GridRun,
    apex_errors,
    baseline,
    compared,
    exact_failures,
    map_failures,
    maps_with,
    measure_all,
    measure_damping,
    variant_stats,
    variants,
)
from .quantities import QUANTITIES
from .report_format import fails, pct, rounded, sig

__all__ = [
    "SYMMETRIC_RATIO",
    "YU_TARGET",
    "AccuracyStudy",
    "summarize",
    "summarize_damping",
    "damping_section",
    "figure_record",
    "from_json",
    "findings",
    "yu_target_stats",
    "meets_yu_target",
    "render_markdown",
    "error_heatmaps",
    "figure",
]

#: A map "is not worse than Geyer's on symmetric steps" when its mean error is at most this ratio.
SYMMETRIC_RATIO = 1.10
#: The targets of the gravity family on the Yu protocol (issue: mean < 2 % at 60 and 65 degrees,
#: < 5 % at every angle, max < 10 %), for the maps with the role "yu-target".
YU_TARGET = {"mean_60_65": 0.02, "mean_all": 0.05, "max": 0.10}


def summarize(runs: list[GridRun], study: str = "") -> list[dict]:
    """Per grid: its facts and the statistics of every variant, as JSON-ready data (6 digits).

    The markdown is rendered from this data (:func:`render_markdown`), so docs/accuracy.md is a
    function of docs/accuracy.json.
    """
    out = []
    for run in runs:
        g = run.grid
        stats = [
            variant_stats(run, label).__dict__ for label, r in run.results.items() if r[0].study == study
        ]
        out.append(
            {
                "name": g.name,
                "kind": g.kind,
                "description": g.description,
                "params": g.params.as_dict(),
                "n_points": int(len(run.points)),
                "no_symmetric_gait": int(sum(s is None for s in run.exact)),
                "exact_failures": exact_failures(run),
                "exact_ok": int((run.exact_status == 0).sum()),
                "variants": stats,
            }
        )
    return rounded(out)


def summarize_damping(runs: list[GridRun]) -> dict:
    """The damping table's data (:func:`~.accuracy.measure_damping`'s runs, one per damping ratio):
    per variant and ratio, the points compared, the map's failures and the next-apex error's mean,
    median and max (6 digits). Empty where no map takes c."""
    if not runs:
        return {}
    p = runs[0].grid.params
    rows = []
    for ratio, run in zip(DAMPING_RATIOS, runs, strict=True):
        for label, (var, _, _) in run.results.items():
            errors = apex_errors(run, label)
            finite = errors[np.isfinite(errors)]
            rows.append(
                {
                    "label": label,
                    "map": var.map,
                    "default": var.default,
                    "ratio": ratio,
                    "c": run.grid.params.c,
                    "n_compared": int(compared(run, label).sum()),
                    "exact_ok": int((run.exact_status == 0).sum()),
                    "failures": dict(sorted(map_failures(run, label).items())),
                    "mean": float(finite.mean()) if finite.size else math.nan,
                    "median": float(np.median(finite)) if finite.size else math.nan,
                    "max": float(finite.max()) if finite.size else math.nan,
                }
            )
    return rounded(
        {
            "grid": runs[0].grid.name,
            "n_points": int(len(runs[0].points)),
            "critical": 2.0 * math.sqrt(p.k_c * p.m),
            "ratios": list(DAMPING_RATIOS),
            "rows": rows,
        }
    )


def figure_record(runs: list[GridRun]) -> dict:
    """What the heatmaps of :func:`figure` draw: on the first nonsymmetric grid (the human runner's)
    at its middle apex height, the next-apex error of each measured map with the role
    "accuracy-figure", per touchdown angle (rows) and apex speed (columns); NaN where a side fails."""
    human = next(r for r in runs if r.grid.kind == "nonsymmetric")
    heights = sorted(set(human.points[:, 0]))
    height = heights[len(heights) // 2]
    sel = np.isclose(human.points[:, 0], height)
    speeds, angles = np.unique(human.points[sel, 1]), np.unique(human.points[sel, 2])
    errors = {}
    for label in (m for m in maps_with("accuracy-figure") if m in human.results):
        grid = np.full((len(angles), len(speeds)), np.nan)
        for (v, a), e in zip(human.points[sel, 1:], apex_errors(human, label)[sel], strict=True):
            grid[np.searchsorted(angles, a), np.searchsorted(speeds, v)] = e
        errors[label] = grid.tolist()
    return {
        "grid": human.grid.name,
        "apex_height": float(height),
        "speeds": speeds.tolist(),
        "angles": angles.tolist(),
        "apex_error": errors,
    }


def from_json(text: str) -> list[dict]:
    """The grids of docs/accuracy.json (:func:`summarize`'s list)."""
    return pipeline.from_json(text)["grids"]


# ----------------------------------------------------------------------------------------------
# Markdown
# ----------------------------------------------------------------------------------------------
def _grid(summary: list[dict], kind: str) -> dict | None:
    for g in summary:
        if g["kind"] == kind:
            return g
    return None


def _stat(g: dict, label: str) -> dict:
    return next(v for v in g["variants"] if v["label"] == label)


def _overview(summary: list[dict]) -> list[str]:
    cols = [g for g in summary]
    head = "| map | " + " | ".join(g["name"] for g in cols) + " |"
    lines = [head, "| --- |" + " --- |" * len(cols)]
    for v in cols[0]["variants"]:
        if not v["default"]:
            continue
        cells = []
        for g in cols:
            s = _stat(g, v["label"])["apex_error"]
            cells.append(f"{pct(s['mean'])} / {pct(s['max'])}")
        lines.append(f"| `{v['label']}` | " + " | ".join(cells) + " |")
    return lines


def _yu_table(g: dict, only_default: bool) -> list[str]:
    angles = [a["angle_of_attack_deg"] for a in g["variants"][0]["by_angle"]]
    lines = [
        "| variant | "
        + " | ".join(f"{a:g} deg mean / max" for a in angles)
        + " | map failures | passes (median / max) |",
        "| --- |" + " --- |" * (len(angles) + 2),
    ]
    for v in g["variants"]:
        if only_default and not v["default"]:
            continue
        cells = [f"{pct(a['mean'])} / {pct(a['max'])}" for a in v["by_angle"]]
        passes = f"{v['passes']['median']:g} / {v['passes']['max']:g}" if v["passes"] else "-"
        lines.append(f"| `{v['label']}` | " + " | ".join(cells) + f" | {fails(v['failures'])} | {passes} |")
    return lines


def _variants_table(g: dict) -> list[str]:
    lines = [
        "| variant | compared | next apex error mean / median / max | map failures | passes (median / max) |",
        "| --- | --- | --- | --- | --- |",
    ]
    for v in g["variants"]:
        e = v["apex_error"]
        passes = f"{v['passes']['median']:g} / {v['passes']['max']:g}" if v["passes"] else "-"
        lines.append(
            f"| `{v['label']}` | {v['n_compared']} "
            f"| {pct(e['mean'])} / {pct(e['median'])} / {pct(e['max'])} "
            f"| {fails(v['failures'])} | {passes} |"
        )
    return lines


def _quantity_table(g: dict) -> list[str]:
    defaults = [v for v in g["variants"] if v["default"]]
    lines = [
        "| quantity | unit | " + " | ".join(f"`{v['label']}`" for v in defaults) + " |",
        "| --- | --- |" + " --- |" * len(defaults),
    ]
    for q in QUANTITIES:
        cells = [
            f"{sig(v['quantities'][q.key]['median_abs'])} / {sig(v['quantities'][q.key]['max_abs'])}"
            for v in defaults
        ]
        lines.append(f"| {q.label} | {q.unit} | " + " | ".join(cells) + " |")
    return lines


def _ratio(a: float, b: float) -> float:
    return a / b if b and math.isfinite(a) and math.isfinite(b) else math.nan


def yu_target_stats(variant: dict) -> tuple[float, float, float]:
    """(largest mean at 60 and 65 deg, largest mean at any angle, max) of a variant of the Yu grid,
    the quantities of :data:`YU_TARGET`; KeyError when the grid lacks the 60 or 65 degree rows."""
    by = {a["angle_of_attack_deg"]: a for a in variant["by_angle"]}
    m60_65 = max(by[60.0]["mean"], by[65.0]["mean"])
    return m60_65, max(a["mean"] for a in variant["by_angle"]), max(a["max"] for a in variant["by_angle"])


def meets_yu_target(variant: dict) -> bool:
    """Whether a variant of the Yu grid meets :data:`YU_TARGET`."""
    m60_65, m_all, mx = yu_target_stats(variant)
    return m60_65 < YU_TARGET["mean_60_65"] and m_all < YU_TARGET["mean_all"] and mx < YU_TARGET["max"]


def findings(summary: list[dict]) -> list[str]:
    """Statements computed from the numbers: per map, against Geyer's on each kind of grid."""
    lines = []
    geyer = baseline()
    defaults = [v["label"] for v in summary[0]["variants"] if v["default"] and v["map"] != geyer]
    for label in defaults:
        parts = []
        for g in summary:
            mine, ref = _stat(g, label)["apex_error"]["mean"], _stat(g, geyer)["apex_error"]["mean"]
            parts.append(f"{g['name']} {pct(mine)} vs {pct(ref)} ({sig(_ratio(mine, ref))}x)")
        nonsym = [g for g in summary if g["kind"] in ("nonsymmetric", "yu")]
        sym = [g for g in summary if g["kind"] == "symmetric"]
        better = all(
            _stat(g, label)["apex_error"]["mean"] < _stat(g, geyer)["apex_error"]["mean"] for g in nonsym
        )
        sym_ok = all(
            _stat(g, label)["apex_error"]["mean"] <= SYMMETRIC_RATIO * _stat(g, geyer)["apex_error"]["mean"]
            for g in sym
        )
        verdict = "beats" if better else "does not beat"
        sym_text = "within" if sym_ok else "NOT within"
        lines.append(
            f"- `{label}` {verdict} Geyer's map on every nonsymmetric grid and is {sym_text} "
            f"{SYMMETRIC_RATIO:g}x of it on the symmetric grids (mean next-apex error: {'; '.join(parts)})."
        )
    yu = _grid(summary, "yu")
    if yu is not None:
        best = min(
            (v for v in yu["variants"] if v["map"] in maps_with("yu-target")),
            key=lambda v: v["apex_error"]["mean"],
            default=None,
        )
        if best is not None:
            by = {a["angle_of_attack_deg"]: a for a in best["by_angle"]}
            mx, met = yu_target_stats(best)[2], meets_yu_target(best)
            lines.append(
                "- Yu protocol target (mean < 2 % at 60 and 65 deg, < 5 % at every angle, max < 10 %): "
                f"the best variant of the family, `{best['label']}`, has mean "
                f"{', '.join(pct(a['mean']) for a in best['by_angle'])} "
                f"at {', '.join(f'{a:g}' for a in by)} deg and max {pct(mx)}: target "
                f"{'met' if met else 'NOT met'}."
            )
    return lines


_INTRO = """
Every map (and variants of its options) against the exact simulator (`solve_ivp` DOP853, rtol
1e-11). At every grid point the exact step runs from an apex (height h, speed v) with the leg held
at the touchdown angle q_th_td; each map's stance starts from the *same* exact touchdown state (so
stance errors are the map's alone), and its apex-return map (exact flights, the map's stance)
gives the next apex. The next-apex error of a step is the relative norm |(dh, dv)| / |(h, v)| of
the Yu, Li and Cai protocol. A point is compared when both sides complete the step; exact failures
(including liftoffs that run backward, left out as the protocol asks) and map failures are
counted. Numbers have 3 significant digits; docs/accuracy.json has 6.
"""

_GRIDS = """
Grids (runtime/studies/grids.py): *nonsymmetric*: apex speeds x touchdown angles x apex heights (the apex
height sets the touchdown vertical speed; slow speed with a flat leg is the hard corner);
*symmetric*: for each apex speed and height, the touchdown angle whose exact stance has its bottom
at q_th = 0 (found by root-finding), Geyer et al.'s setting; *Yu*: the ICRA 2012 protocol.
"""


def damping_section(damping: dict, what: str = "the maps that take the leg damping c") -> list[str]:
    """The damping table (:func:`summarize_damping`'s data): each variant of ``what``, mean / max
    next-apex error per damping ratio."""
    if not damping:
        return []
    labels = list(dict.fromkeys(r["label"] for r in damping["rows"]))
    ratios = damping["ratios"]
    cell = {(r["label"], r["ratio"]): r for r in damping["rows"]}
    lines = [
        "",
        "## Leg damping",
        "",
        _paragraph(
            f"{what[0].upper() + what[1:]} (docs/damping.md) on the {damping['grid']} grid "
            f"({damping['n_points']} points) with c a fraction of the critical damping "
            f"2 sqrt(k_c m) = {damping['critical']:.4g} N s/m, against the exact map with the same c: "
            "mean / max of |(dh, dv)| / |(h, v)| of the next apex over the points where both complete "
            "the step, and the map's failures where the exact step completes."
        ),
        "",
        "| map | " + " | ".join(f"damping ratio {x:g}" for x in ratios) + " |",
        "| --- |" + " --- |" * len(ratios),
    ]
    for label in labels:
        cells = []
        for x in ratios:
            r = cell[(label, x)]
            failed = sum(r["failures"].values())
            cells.append(f"{pct(r['mean'])} / {pct(r['max'])}" + (f" ({failed} failed)" if failed else ""))
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return lines


def _paragraph(text: str) -> str:
    return " ".join(text.split())


def render_markdown(
    summary: list[dict], figure_name: str = "accuracy.png", damping: dict | None = None
) -> str:
    out = [
        "# Accuracy of the maps against the exact stance",
        "",
        "<!-- generated by `slipmaps accuracy` (runtime/studies/accuracy.py, accuracy_report.py); "
        "do not edit -->",
        "",
        _paragraph(_INTRO),
        "",
        _paragraph(_GRIDS),
        "",
        f"![next-apex error]({figure_name})",
        "",
        "Beside this report: docs/convergence.md (the iterative maps' passes), docs/stiffness.md "
        "(k_d != k_c) and docs/stability.md (periodic gaits: each map's fixed points and eigenvalues "
        "against the exact ones, the self-stable region).",
        "",
        "## Findings",
        "",
        *findings(summary),
        "",
        "## Next-apex error, every map at its defaults (mean / max over the compared points)",
        "",
        *_overview(summary),
    ]
    yu = _grid(summary, "yu")
    if yu is not None:
        out += [
            "",
            "## Yu, Li and Cai protocol",
            "",
            f"{yu['description']}: {yu['n_points']} steps, {yu['exact_ok']} exact steps complete; left out: "
            f"{fails(yu['exact_failures'])}. Error: mean / max of |(dh, dv)| / |(h, v)| of the next apex "
            "per angle of attack; map failures are steps the exact simulator completes and the map does not.",
            "",
            *_yu_table(yu, only_default=False),
        ]
    for g in summary:
        if g["kind"] == "yu":
            continue
        title = g["name"][0].upper() + g["name"][1:]
        p = g["params"]
        stiff = p["k_c"] * p["l0"] / (p["m"] * p["g_s"])
        extra = f", {g['no_symmetric_gait']} without a symmetric gait" if g["no_symmetric_gait"] else ""
        out += [
            "",
            f"## {title}",
            "",
            f"m = {p['m']:g} kg, l0 = {p['l0']:g} m, k = {p['k_c']:g} N/m (k l0/(m g_s) = {stiff:.3g}); "
            f"{g['description']}: {g['n_points']} points{extra}, {g['exact_ok']} exact steps complete "
            f"(exact failures: {fails(g['exact_failures'])}).",
            "",
            *_variants_table(g),
            "",
            "Median / max absolute error of each quantity (maps at their defaults; stance quantities from "
            "the same exact touchdown):",
            "",
            *_quantity_table(g),
        ]
    out += damping_section(damping or {})
    return "\n".join(out) + "\n"


# ----------------------------------------------------------------------------------------------
# Figure
# ----------------------------------------------------------------------------------------------
def _nan(x) -> float:
    return math.nan if x is None else float(x)


def error_heatmaps(heat: dict, axes, bounds: tuple[float, float] | None = None, every_ylabel: bool = True):
    """Draw the heatmaps of ``heat`` (a record's ``figure``, :func:`figure_record`) onto ``axes``, one
    map per axes in turn: its next-apex error over apex speed and touchdown angle (white where a side
    fails), titled with its label; axes left over are hidden. One logarithmic color scale (viridis)
    for all, from ``bounds`` or by default from the decades that hold every positive error drawn;
    the touchdown-angle label on every panel or (``every_ylabel=False``, panels sharing y) the
    first. Returns the last panel's mesh, whose norm and colormap the colorbar needs."""
    from matplotlib.colors import LogNorm

    axes = list(np.atleast_1d(axes).flat)
    speeds, angles = np.array(heat["speeds"]), np.array(heat["angles"])
    grids = {label: np.array(errors, dtype=float) for label, errors in heat["apex_error"].items()}
    if bounds is None:
        finite = np.concatenate([g[np.isfinite(g) & (g > 0)] for g in grids.values()])
        bounds = 10.0 ** math.floor(math.log10(finite.min())), 10.0 ** math.ceil(math.log10(finite.max()))
    norm = LogNorm(vmin=bounds[0], vmax=bounds[1])
    for ax in axes[len(grids) :]:
        ax.set_visible(False)
    for i, (ax, (label, grid)) in enumerate(zip(axes, grids.items(), strict=False)):
        mesh = ax.pcolormesh(
            speeds, angles, np.ma.masked_invalid(grid), norm=norm, cmap="viridis", shading="nearest"
        )
        ax.set_title(label, fontsize=10)
        ax.set_xlabel("apex speed [m/s]")
        if every_ylabel or i == 0:
            ax.set_ylabel("touchdown angle q_th_td [rad]")
    return mesh


def figure(record: dict, path: str | Path) -> Path:
    """Next-apex error against touchdown angle and speed (heatmaps of the record's ``figure``) and,
    per angle of attack, the mean on the Yu protocol of every map at its defaults."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    heat = record["figure"]
    yu = _grid(record["grids"], "yu")
    shown = list(heat["apex_error"])
    fig = plt.figure(figsize=(12, 9), layout="constrained")
    top, bottom = fig.subfigures(2, 1, height_ratios=(1.0, 1.0))
    axes = top.subplots(1, len(shown), sharey=True)
    mesh = error_heatmaps(heat, axes, bounds=(1e-6, 0.3), every_ylabel=False)
    top.colorbar(mesh, ax=axes, label="next-apex error (white: a side fails)")
    top.suptitle(
        f"{heat['grid']}, apex height {heat['apex_height']:g} m: next-apex error |(dh, dv)| / |(h, v)|",
        fontsize=11,
    )
    if yu is not None:
        ax = bottom.subplots()
        for v in yu["variants"]:
            if not v["default"]:
                continue
            aoa = [a["angle_of_attack_deg"] for a in v["by_angle"]]
            ax.plot(aoa, 100 * np.array([_nan(a["mean"]) for a in v["by_angle"]]), "o-", label=v["label"])
        ax.set_yscale("log")
        ax.set_xlabel("angle of attack from the ground [deg]")
        ax.set_ylabel("mean next-apex error [%]")
        bottom.suptitle(f"{yu['name']}: mean over apex heights 0.95-1.05 m and speeds 2-6 m/s", fontsize=11)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, ncol=2)
    return save_figure(fig, path, dpi=100)


class AccuracyStudy(pipeline.Study):
    """docs/accuracy.*: every map of ``map_names`` (default: all) and its variants against the exact
    simulator on the grids of :mod:`.grids`."""

    name = "accuracy"

    def __init__(self, map_names=None):
        self.map_names = map_names

    def measure(self, show_progress=None) -> dict:
        chosen = variants(self.map_names)
        runs = measure_all(chosen, show_progress=show_progress)
        damping = summarize_damping(measure_damping(chosen))
        return {"grids": summarize(runs), "figure": figure_record(runs), "damping": damping}

    def markdown(self, record: dict, figure_name: str) -> str:
        return render_markdown(record["grids"], figure_name, record.get("damping"))

    def figure(self, record: dict, path: Path) -> Path:
        return figure(record, path)
