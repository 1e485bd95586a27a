"""The variable-stiffness study rendered: docs/stiffness.md (tables, the target, findings) and
docs/stiffness.png, both from the record docs/stiffness.json (:mod:`.stiffness` measures it;
:class:`StiffnessStudy` writes the three through :mod:`.study`).

Deterministic: numbers to 3 significant digits, every statement computed from the record.
"""

from __future__ import annotations

import math
from pathlib import Path

from ..api.paths import save_figure
from . import study as pipeline
from .report_format import fails, pct, sig
from .stiffness import BOTTOM_MAP, ERRORS, SUBSAMPLED, measure, summarize, variants

__all__ = [
    "TARGET",
    "TARGET_RANGE",
    "TARGET_GRIDS",
    "StiffnessStudy",
    "target_rows",
    "render_markdown",
    "figure",
]

#: The issue's target: the next apex height within 1 % of l0 and its speed within 2 % ...
TARGET = {"apex_height": 0.01, "apex_speed": 0.02}
#: ... over k_d/k_c in this range ...
TARGET_RANGE = (0.8, 1.25)
#: ... on the grids of this parameter set (grid names start with it).
TARGET_GRIDS = "human runner"
#: An estimate within this fraction of the exact compression agrees to the exact simulator's precision.
AGREEMENT = 1e-6


def _num(x) -> float:
    """A recorded statistic; a missing one (no step compared) is infinitely bad."""
    return math.inf if x is None else float(x)


def _labels(record: list[dict]) -> list[str]:
    return [v["label"] for v in record[0]["ratios"][0]["variants"]]


def _variant(ratio_row: dict, label: str) -> dict:
    return next(v for v in ratio_row["variants"] if v["label"] == label)


def _worst(grids: list[dict], label: str, low: float, high: float) -> dict:
    """Over ``grids`` and the ratios in [low, high]: the largest max of every error, map failures."""
    rows = [_variant(r, label) for g in grids for r in g["ratios"] if low <= r["ratio"] <= high]
    out = {e.key: max(_num(v[e.key]["max"]) for v in rows) for e in ERRORS}
    out["failures"] = sum(sum(v["failures"].values()) for v in rows)
    return out


def _range(record: list[dict]) -> tuple[float, float]:
    ratios = [r["ratio"] for r in record[0]["ratios"]]
    return min(ratios), max(ratios)


def target_rows(record: list[dict], prefix: str = TARGET_GRIDS) -> list[dict]:
    """Per variant, on the grids named ``prefix...``: the worst errors and failures over the target
    range and over every ratio, and whether the target holds (both errors below it, no failure)."""
    grids = [g for g in record if g["name"].startswith(prefix)]
    out = []
    for label in _labels(record):
        inside, whole = _worst(grids, label, *TARGET_RANGE), _worst(grids, label, *_range(record))
        met = all(inside[k] < t for k, t in TARGET.items()) and inside["failures"] == 0
        score = max(inside[k] / t for k, t in TARGET.items()) if inside["failures"] == 0 else math.inf
        out.append({"label": label, "target": inside, "all": whole, "met": met, "score": score})
    return out


# ----------------------------------------------------------------------------------------------
# Markdown
# ----------------------------------------------------------------------------------------------
def _paragraph(text: str) -> str:
    return " ".join(text.split())


def _target_table(rows: list[dict], record: list[dict], verdict: str = "target", words=("met", "not met")):
    lo, hi = TARGET_RANGE
    a, b = _range(record)
    lines = [
        f"| variant | height, [{lo:g}, {hi:g}] | speed, [{lo:g}, {hi:g}] | map failures, [{lo:g}, {hi:g}] "
        f"| height, [{a:g}, {b:g}] | speed, [{a:g}, {b:g}] | map failures, [{a:g}, {b:g}] | {verdict} |",
        "| --- |" + " --- |" * 7,
    ]
    for r in rows:
        t, w = r["target"], r["all"]
        lines.append(
            f"| `{r['label']}` | {pct(t['apex_height'])} | {pct(t['apex_speed'])} | {t['failures']} "
            f"| {pct(w['apex_height'])} | {pct(w['apex_speed'])} | {w['failures']} "
            f"| {words[0] if r['met'] else words[1]} |"
        )
    return lines


def _target_section(record: list[dict]) -> list[str]:
    rows = target_rows(record)
    best = min(rows, key=lambda r: r["score"])
    t = best["target"]
    lo, hi = TARGET_RANGE
    names = " and ".join(g["name"].split(", ")[1] for g in record if g["name"].startswith(TARGET_GRIDS))
    verdict = "met" if best["met"] else "NOT met"
    others = [f"`{r['label']}`" for r in rows if r["met"] and r is not best]
    lines = [
        f"The issue's target: the best variable-stiffness map predicts the next apex height within "
        f"{pct(TARGET['apex_height'])} of l0 and its speed within {pct(TARGET['apex_speed'])} over k_d/k_c "
        f"in [{lo:g}, {hi:g}] on the {TARGET_GRIDS} grids ({names}); checked as the largest error over "
        "every step the exact simulator completes, a map failure on such a step counting against it.",
        "",
        f"- The best is `{best['label']}`: largest height error {pct(t['apex_height'])} of l0, speed error "
        f"{pct(t['apex_speed'])}, map failures: {t['failures']}; target **{verdict}**"
        + (f" (also met by {', '.join(others)})." if others else " (no other variant meets it)."),
        f"- Over the whole range [{_range(record)[0]:g}, {_range(record)[1]:g}] its largest errors are "
        f"{pct(best['all']['apex_height'])} of l0 and {pct(best['all']['apex_speed'])} "
        f"(map failures: {best['all']['failures']}).",
        "",
        f"Largest next-apex errors on the {TARGET_GRIDS} grids (height in % of l0, speed in % of the exact "
        "speed; max over the steps and the ratios of the range):",
        "",
        *_target_table(rows, record),
    ]
    for prefix in dict.fromkeys(g["name"].split(", ")[0] for g in record):
        if prefix == TARGET_GRIDS:
            continue
        lines += [
            "",
            f"The same on the {prefix} grids (not part of the target):",
            "",
            *_target_table(
                target_rows(record, prefix), record, "within the target's bounds", ("within", "not within")
            ),
        ]
    return lines


def _bottom_table(record: list[dict]) -> list[str]:
    lines = [
        "| grid | exact max abs(q_th_b) | estimate | compared | error / (l0 - q_r_b) mean / max "
        "| error / q_r_b mean / max | failures |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    for g in record:
        b = g["bottom"]
        for e in b["estimates"]:
            c, n = e["of_compression"], e["of_length"]
            lines.append(
                f"| {g['name']} | {sig(b['exact_bottom_angle_max'])} rad | {e['label']} | {e['n_compared']} "
                f"| {pct(c['mean'])} / {pct(c['max'])} | {pct(n['mean'])} / {pct(n['max'])} "
                f"| {fails(e['failures'])} |"
            )
    return lines


def _estimate(g: dict, key: str) -> dict:
    return next(e for e in g["bottom"]["estimates"] if e["equation"] == key)


def _spread(grids: list[dict], key: str, stat: str) -> str:
    """The smallest and largest of a bottom statistic over ``grids``, as a range of percentages."""
    values = sorted(_num(_estimate(g, key)["of_compression"][stat]) for g in grids)
    return pct(values[0]) if values[0] == values[-1] else f"{pct(values[0])} to {pct(values[-1])}"


def _bottom_findings(record: list[dict]) -> list[str]:
    sym = [g for g in record if g["kind"] == "symmetric"]
    non = [g for g in record if g["kind"] != "symmetric"]
    angle = max(_num(g["bottom"]["exact_bottom_angle_max"]) for g in sym)
    tilt = max(_num(g["bottom"]["exact_bottom_angle_max"]) for g in non)
    exact_p = max(_num(_estimate(g, "153-exact-p")["of_compression"]["max"]) for g in sym)
    lines = [
        f"- (153) with the touchdown p_th, on the symmetric grids (exact bottom vertical: abs(q_th_b) <= "
        f"{sig(angle)} rad): mean error {_spread(sym, '153', 'mean')} of the compression, max "
        f"{_spread(sym, '153', 'max')}; on the nonsymmetric grids mean {_spread(non, '153', 'mean')}, max "
        f"{_spread(non, '153', 'max')}.",
    ]
    if exact_p < AGREEMENT:
        lines.append(
            f"- With the exact bottom p_th the same quartic is within "
            f"{_spread(sym, '153-exact-p', 'max')} of the compression on the symmetric grids (the exact "
            "simulator's precision): there the error of (153) is all in p_th, which the gravity torque "
            "changes between touchdown and the bottom and (153) takes as conserved."
        )
    else:
        lines.append(
            f"- With the exact bottom p_th the quartic is within {_spread(sym, '153-exact-p', 'max')} of the "
            "compression on the symmetric grids."
        )
    lines += [
        f"- With the exact bottom p_th, on the nonsymmetric grids (abs(q_th_b) up to {sig(tilt)} rad) "
        f"the vertical bottom that (153) assumes costs a mean {_spread(non, '153-exact-p', 'mean')} of "
        f"the compression, max {_spread(non, '153-exact-p', 'max')}.",
        f"- (154), Geyer et al.'s bottom: mean {_spread(sym, '154', 'mean')} of the compression, max "
        f"{_spread(sym, '154', 'max')} on the symmetric grids; mean {_spread(non, '154', 'mean')}, max "
        f"{_spread(non, '154', 'max')} on the nonsymmetric ones.",
    ]
    return lines


def _cell(s: dict) -> str:
    return f"{pct(s['mean'])} / {pct(s['max'])}"


def _grid_section(g: dict) -> list[str]:
    p = g["params"]
    stiff = p["k_c"] * p["l0"] / (p["m"] * p["g_s"])
    extra = f", {g['no_symmetric_gait']} without a symmetric gait" if g["no_symmetric_gait"] else ""
    exact = "; ".join(
        f"{r['ratio']:g}: {r['exact_ok']}"
        + (f" ({fails(r['exact_failures'])})" if r["exact_failures"] else "")
        for r in g["ratios"]
    )
    head = " | ".join(e.column for e in ERRORS)
    lines = [
        "",
        f"## {g['name'][0].upper()}{g['name'][1:]}",
        "",
        f"m = {p['m']:g} kg, l0 = {p['l0']:g} m, k_c = {p['k_c']:g} N/m (k_c l0/(m g_s) = {stiff:.3g}); "
        f"{g['description']}: {g['n_points']} points{extra}. Exact steps complete per k_d/k_c: {exact}.",
        "",
        f"| variant | k_d/k_c | compared | {head} | map failures |",
        "| --- | --- | --- |" + " --- |" * len(ERRORS) + " --- |",
    ]
    for label in [v["label"] for v in g["ratios"][0]["variants"]]:
        for r in g["ratios"]:
            v = _variant(r, label)
            cells = " | ".join(_cell(v[e.key]) for e in ERRORS)
            lines.append(
                f"| `{label}` | {r['ratio']:g} | {v['n_compared']} | {cells} | {fails(v['failures'])} |"
            )
    return lines


_INTRO = f"""
Every map that accepts a leg stiffness k_c while compressing different from k_d after the bottom,
at its defaults{{series}}, against the exact simulator (`solve_ivp` DOP853, rtol 1e-11) for k_d/k_c
in {{ratios}}, k_c the parameter set's k, on the {{sets}} grids of docs/accuracy.md: the symmetric
ones whole, the nonsymmetric ones at {SUBSAMPLED} apex speed and touchdown angle (all apex heights,
both ends of both axes kept) so that the study adds seconds, not minutes, to `slipmaps accuracy`.
Each map's stance starts from the exact touchdown state; its apex-return map (exact flights) gives
the next apex. Errors of the map (absolute differences to the exact step, scaled), as mean / max
over the steps both sides complete: {{errors}}. The exact E_ba is (27) with k_d at the exact bottom
(the exact decompression conserves it). Map failures are steps the exact simulator completes and
the map does not. Numbers have 3 significant digits; docs/stiffness.json has 6.
"""


def _intro(record: list[dict]) -> str:
    variants = record[0]["ratios"][0]["variants"]
    series = {}
    for v in variants:
        for key in v["options"]:
            series.setdefault(v["map"], set()).add(key)
    extra = "; ".join(
        f"`{m}` also at every value of {', '.join(f'`{x}`' for x in sorted(k))}" for m, k in series.items()
    )
    return _paragraph(
        _INTRO.format(
            series=f" ({extra})" if extra else "",
            ratios=", ".join(f"{r['ratio']:g}" for r in record[0]["ratios"]),
            sets=" and ".join(dict.fromkeys(g["name"].split(", ")[0] for g in record)),
            errors="; ".join(f"{e.column}: {e.description}" for e in ERRORS),
        )
    )


def render_markdown(record: list[dict], figure_name: str = "stiffness.png") -> str:
    out = [
        "# Variable stiffness: the maps against the exact stance over k_d/k_c",
        "",
        "<!-- generated by `slipmaps accuracy` (runtime/studies/stiffness.py, stiffness_report.py); "
        "do not edit -->",
        "",
        _intro(record),
        "",
        f"![next-apex error against k_d/k_c]({figure_name})",
        "",
        "## Target",
        "",
        *_target_section(record),
        "",
        "## Bottom leg length: (153) and (154)",
        "",
        _paragraph(
            f"""The bottom ends the compression, so it depends on k_c only. (153): the root of the
            quartic of a vertical bottom, V(q) = p_th^2/(2 m q^2) + k_c (l0 - q)^2/2 + m g_s q = E_ab,
            with E_ab the total energy (27) with k_c at touchdown (kernel `bottom_quartic`), p_th the
            touchdown angular momentum m q_r^2 q_thd, and, as a check, the exact bottom's. (154):
            Geyer et al.'s bottom l0 (1 + a_ab - b_ab), the `bottom_q_r` of `{BOTTOM_MAP}` at k_d =
            k_c. Against the exact bottom of every step that reaches one."""
        ),
        "",
        *_bottom_findings(record),
        "",
        *_bottom_table(record),
    ]
    for g in record:
        out += _grid_section(g)
    return "\n".join(out) + "\n"


# ----------------------------------------------------------------------------------------------
# Figure
# ----------------------------------------------------------------------------------------------
def figure(record: list[dict], path: str | Path) -> Path:
    """Next apex height and speed errors against k_d/k_c: one column per grid, one colour per
    variant, max (solid) and mean (dotted) over the compared steps, log scale."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    keys = ("apex_height", "apex_speed")
    units = {"apex_height": "next apex height error [% of l0]", "apex_speed": "next apex speed error [%]"}
    labels = _labels(record)
    fig, axes = plt.subplots(
        len(keys), len(record), figsize=(4.2 * len(record), 7.5), squeeze=False, sharex=True
    )
    for col, g in enumerate(record):
        ratios = [r["ratio"] for r in g["ratios"]]
        for row, key in enumerate(keys):
            ax = axes[row, col]
            ax.axvspan(*TARGET_RANGE, color="0.92", zorder=0)
            if g["name"].startswith(TARGET_GRIDS):
                ax.axhline(100 * TARGET[key], color="k", ls="--", lw=0.8, label="target")
            for i, label in enumerate(labels):
                stats = [_variant(r, label)[key] for r in g["ratios"]]
                for stat, style in (("max", "o-"), ("mean", ":")):
                    values = [math.nan if s[stat] is None else 100 * s[stat] for s in stats]
                    ax.plot(
                        ratios,
                        values,
                        style,
                        color=f"C{i}",
                        ms=3,
                        label=f"{label} ({stat})" if stat == "max" else None,
                    )
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
            if row == 0:
                ax.set_title(g["name"], fontsize=10)
            if row == len(keys) - 1:
                ax.set_xlabel("k_d / k_c")
            if col == 0:
                ax.set_ylabel(units[key])
    handles, names = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, names, loc="lower center", ncol=min(len(names), 6), fontsize=8)
    fig.suptitle(
        "Max (solid) and mean (dotted) error over the compared steps; shaded: the target range", fontsize=11
    )
    fig.tight_layout(rect=(0, 0.06, 1, 0.97))
    return save_figure(fig, path, dpi=100)


class StiffnessStudy(pipeline.Study):
    """docs/stiffness.*: the maps of ``map_names`` (default: all) that accept k_c != k_d, over k_d/k_c."""

    name = "stiffness"

    def __init__(self, map_names=None):
        self.map_names = map_names

    def applies(self) -> bool:
        return bool(variants(self.map_names))

    def measure(self, show_progress=None) -> dict:
        return {"grids": summarize(measure(variants(self.map_names), show_progress=show_progress))}

    def markdown(self, record: dict, figure_name: str) -> str:
        return render_markdown(record["grids"], figure_name)

    def figure(self, record: dict, path: Path) -> Path:
        return figure(record["grids"], path)
