"""The convergence study of the iterative maps: error against the exact stance for n = 0..8 passes.

A map takes part when one of its options has the role "convergence-passes" in the index (its pass
count; the gravity family's fixed points are studied in docs/accuracy.md), once per value of its
option with the role "convergence-series" (the report's mean-value variants) if it has one. Each
pass count runs at the map's other defaults with its "tolerance" option at 0 (exactly n passes) on
the accuracy grids; ``slipmaps accuracy`` writes docs/convergence.json, .md and .png
(:class:`ConvergenceStudy`, through :mod:`.study`) from the same exact steps as docs/accuracy.md;
the record is :func:`.accuracy_report.summarize` of the study's variants. With leg damping: the
variants of the maps that take c at the damping ratios of :data:`.accuracy.DAMPING_RATIOS`
(:func:`.accuracy.measure_damping`, the record's ``damping``).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..api import index
from ..api.paths import save_figure
from . import study as pipeline
from .accuracy import Variant, measure_all, measure_damping, options_with
from .accuracy_report import damping_section, from_json, summarize, summarize_damping

__all__ = [
    "PASSES",
    "STUDY",
    "ConvergenceStudy",
    "study_maps",
    "pass_option",
    "series_option",
    "variants",
    "from_json",
    "render_markdown",
    "figure",
]

#: Pass counts of the study.
PASSES = tuple(range(9))
STUDY = "convergence"


def study_maps(map_names=None) -> list[str]:
    """The maps of ``map_names`` (default: all) with a "convergence-passes" option, in index order."""
    names = [m.name for m in index.maps() if m.name != index.EXACT] if map_names is None else list(map_names)
    return [name for name in names if pass_option(name) is not None]


def _role_option(name: str, role: str) -> str | None:
    found = [o.name for o in options_with(index.get(name), role)]
    if len(found) > 1:
        raise ValueError(f"map {name!r}: more than one option with the role {role!r}: {found}")
    return found[0] if found else None


def pass_option(name: str) -> str | None:
    """The option the study varies, n = 0..8 (role "convergence-passes"), or None."""
    return _role_option(name, "convergence-passes")


def series_option(name: str) -> str | None:
    """The option whose every value is a series of its own (role "convergence-series"), or None."""
    return _role_option(name, "convergence-series")


def variants(map_names=None) -> list[Variant]:
    out = []
    for name in study_maps(map_names):
        info, series_name = index.get(name), series_option(name)
        series = info.option(series_name).choices if series_name else (None,)
        tolerance = [(o.name, 0.0) for o in options_with(info, "tolerance")]
        for value in series:
            fixed = ((series_name, value),) if value is not None else ()
            for n in PASSES:
                chosen = fixed + ((pass_option(name), n),) + tuple(tolerance)
                out.append(Variant(name, chosen, default=False, study=STUDY))
    return out


def _series(name: str, options: dict) -> str:
    """A study series: the map, and its series option's value when it has one."""
    key = series_option(name)
    return f"{name} ({key} = {options[key]})" if key in options else name


def _pct(x) -> str:
    return "n/a" if x is None or not math.isfinite(x) else f"{100 * x:.3g} %"


def _n(v: dict) -> int:
    return int(v["options"][pass_option(v["map"])])


def _by_map(grid: dict) -> dict[str, list[dict]]:
    out: dict[str, list[dict]] = {}
    for v in grid["variants"]:
        out.setdefault(_series(v["map"], v["options"]), []).append(v)
    return {k: sorted(vs, key=_n) for k, vs in out.items()}


def _fails(v: dict) -> int:
    return sum(v["failures"].values())


def _findings(summary: list[dict], name: str) -> list[str]:
    lines = []
    for g in summary:
        rows = _by_map(g).get(name, [])
        means = [r["apex_error"]["mean"] for r in rows]
        finite = [(i, e) for i, e in enumerate(means) if e is not None and math.isfinite(e)]
        if not finite:
            lines.append(f"- {g['name']}: no step compared at any n.")
            continue
        best = min(finite, key=lambda t: t[1])
        # first n after which no further pass improves the mean by more than 10 %
        stall = next(
            (
                i
                for i in range(len(means) - 1)
                if all(
                    means[j] is not None and means[i] is not None and means[j] > 0.9 * means[i]
                    for j in range(i + 1, len(means))
                )
            ),
            len(means) - 1,
        )
        rising = [
            i
            for i in range(1, len(means))
            if means[i] is not None and means[i - 1] is not None and means[i] > 1.1 * means[i - 1]
        ]
        fails = [_fails(r) for r in rows]
        lines.append(
            f"- {g['name']}: mean error {_pct(means[0])} at n = 0, "
            f"{_pct(means[-1])} at n = {len(means) - 1}; "
            f"smallest {_pct(best[1])} at n = {best[0]}; no pass after n = {stall} improves it by more "
            f"than 10 %"
            + (f"; it grows (> 10 %) at n = {', '.join(map(str, rising))}" if rising else "")
            + f"; map failures {fails[0]} at n = 0, {max(fails)} at most."
        )
    return lines


def _table(summary: list[dict], name: str) -> list[str]:
    grids = summary
    head = "| n | " + " | ".join(g["name"] for g in grids) + " |"
    lines = [head, "| --- |" + " --- |" * len(grids)]
    per = [_by_map(g).get(name, []) for g in grids]
    for i in range(len(PASSES)):
        cells = []
        for g, rows in zip(grids, per, strict=True):
            if i >= len(rows):
                cells.append("-")
                continue
            r = rows[i]
            text = _pct(r["apex_error"]["mean"])
            if g["kind"] == "yu":
                text = " / ".join(_pct(a["mean"]) for a in r["by_angle"])
            if _fails(r):
                text += f" ({_fails(r)} failed)"
            cells.append(text)
        lines.append(f"| {_n(per[0][i]) if per[0] else i} | " + " | ".join(cells) + " |")
    return lines


_INTRO = """
Each iterative map at its default options except the number of passes n (tol = 0: exactly n
passes; n = 0 is the zeroth iterate), against the exact simulator on the grids of
docs/accuracy.md (same exact steps, same error measure: the mean over the compared steps of the
next-apex error |(dh, dv)| / |(h, v)|; the Yu protocol per angle of attack 60 / 65 / 68 / 72 deg).
A step counts as failed when the exact simulator completes it and the map does not; n/a: every
step of that angle failed.
"""


def render_markdown(
    summary: list[dict], figure_name: str = "convergence.png", damping: dict | None = None
) -> str:
    series = {_series(v["map"], v["options"]): v for g in summary for v in g["variants"]}
    out = [
        "# Convergence of the iterative maps with the number of passes",
        "",
        "<!-- generated by `slipmaps accuracy` (runtime/studies/convergence.py); do not edit -->",
        "",
        " ".join(_INTRO.split()),
        "",
        f"![error against n]({figure_name})",
    ]
    for name, first in series.items():
        info = index.get(first["map"])
        varied = ("convergence-passes", "tolerance", "convergence-series")
        defaults = ", ".join(
            f"{o.name} = {o.default}" for o in info.options if not set(o.roles) & set(varied)
        )
        out += [
            "",
            f"## `{info.name}`{name.removeprefix(info.name)}: {info.title} (report section {info.section})",
            "",
            f"Other options at their defaults ({defaults}).",
            "",
            *_table(summary, name),
            "",
            *_findings(summary, name),
        ]
    out += damping_section(damping or {}, "the pass counts of the maps that take the leg damping c")
    return "\n".join(out) + "\n"


def _means(rows: list[dict], angle: int | None = None) -> np.ndarray:
    """Each row's mean next-apex error (of the Yu protocol's ``angle``-th angle), NaN (a gap in the
    line) where every step failed."""
    means = [r["apex_error"]["mean"] if angle is None else r["by_angle"][angle]["mean"] for r in rows]
    return np.array([math.nan if m is None else m for m in means], dtype=float)


def figure(summary: list[dict], path: str | Path) -> Path:
    """Mean next-apex error against n, one panel per series, one line per grid (Yu: per angle)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = list(dict.fromkeys(name for g in summary for name in _by_map(g)))
    fig, axes = plt.subplots(1, max(len(names), 1), figsize=(6 * max(len(names), 1), 4.5), squeeze=False)
    for ax, name in zip(axes[0], names, strict=False):
        for g in summary:
            rows = _by_map(g).get(name, [])
            ns = [_n(r) for r in rows]
            if g["kind"] == "yu":
                for i, a in enumerate(rows[0]["by_angle"] if rows else ()):
                    label = f"Yu {a['angle_of_attack_deg']:.0f} deg"
                    ax.plot(ns, 100 * _means(rows, i), "o--", ms=3, label=label)
            else:
                ax.plot(ns, 100 * _means(rows), "o-", ms=3, label=g["name"])
        ax.set_yscale("log")
        ax.set_xlabel("passes n")
        ax.set_ylabel("mean next-apex error [%]")
        ax.set_title(name, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    return save_figure(fig, path, dpi=100)


class ConvergenceStudy(pipeline.Study):
    """docs/convergence.*: the maps of ``map_names`` (default: all) with a pass count, n = 0..8."""

    name = STUDY

    def __init__(self, map_names=None):
        self.map_names = map_names

    def applies(self) -> bool:
        return bool(study_maps(self.map_names))

    def measure(self, show_progress=None) -> dict:
        chosen = variants(self.map_names)
        runs = measure_all(chosen, show_progress=show_progress)
        return {"grids": summarize(runs, STUDY), "damping": summarize_damping(measure_damping(chosen))}

    def markdown(self, record: dict, figure_name: str) -> str:
        return render_markdown(record["grids"], figure_name, record.get("damping"))

    def figure(self, record: dict, path: Path) -> Path:
        return figure(record["grids"], path)
