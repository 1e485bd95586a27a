"""The periodic-gait study rendered: docs/stability.md (fixed points against the exact ones, the
self-stable region, the comparison with Seyfarth et al.) and docs/stability.png, both from the
record docs/stability.json (:mod:`.stability` measures it; :class:`StabilityStudy` writes the three
through :mod:`.study`).

Deterministic: numbers to 3 significant digits, every statement computed from the record.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..api.index import EXACT
from ..api.paths import save_figure
from . import study as pipeline
from .report_format import sig
from .stability import measure

__all__ = [
    "REGION_TITLE",
    "REGION_MARKS",
    "StabilityStudy",
    "matches",
    "grid_rows",
    "region_facts",
    "render_markdown",
    "figure",
]

#: The speeds v0 [m/s] of the region table (every other metre per second of the grid).
TABLE_SPEEDS = (3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0)
#: Seyfarth, Geyer and Herr, J Exp Biol 206 (2003) 2547-2555, figure captions (same model and
#: parameters): no stable fixed point at a fixed angle of attack at the energy of 3 m/s at 1 m
#: (Fig. 4), the return map of alpha0 = 68 deg at the energy of 5 m/s at 1 m (Fig. 6).
JEB_NO_STABLE_SPEED = 3.0
JEB_EXAMPLE = (5.0, 68.0)
#: The figure's title: what it reproduces is the self-stable region of Seyfarth, Geyer, Guenther and
#: Blickhan 2002 (docs/control_planning.md and docs/stability.md cite the same paper); the two marks
#: come from the captions of the 2003 follow-up (:data:`JEB_NO_STABLE_SPEED`, :data:`JEB_EXAMPLE`),
#: named as such.
REGION_TITLE = (
    'Self-stable region of the SLIP as in Seyfarth et al. 2002 ("A movement criterion for running", '
    "J Biomech): human runner (80 kg, 1 m, 20 kN/m); grey: unstable only, white: none"
)
REGION_MARKS = (
    "red dotted: 3 m/s, red star: 68 deg at 5 m/s (reference points from the figure captions of Seyfarth "
    'et al. 2003, "Swing-leg retraction", J Exp Biol)'
)


# ----------------------------------------------------------------------------------------------
# Statistics from the record
# ----------------------------------------------------------------------------------------------
def _ok(points: list[dict]) -> list[dict]:
    return [p for p in points if p["status"] == "OK"]


def _stable(p: dict) -> bool:
    return abs(p["eigenvalue"]) < 1.0


def _mu(p: dict) -> complex:
    re, im = p["multiplier"]
    return complex(re, im)


def matches(exact: list[dict], approx: list[dict], unknown: str) -> tuple[list[tuple[dict, dict]], int, int]:
    """Each completed exact fixed point paired with the nearest unused completed map fixed point in
    the unknown (in order of distance): (pairs, missing exact points, extra map points)."""
    ex, ap = _ok(exact), _ok(approx)
    cand = sorted((abs(e[unknown] - a[unknown]), i, j) for i, e in enumerate(ex) for j, a in enumerate(ap))
    used_e, used_a, pairs = set(), set(), []
    for _, i, j in cand:
        if i not in used_e and j not in used_a:
            used_e.add(i)
            used_a.add(j)
            pairs.append((ex[i], ap[j]))
    pairs.sort(key=lambda pa: pa[0][unknown])
    return pairs, len(ex) - len(pairs), len(ap) - len(pairs)


def _names(grid: dict) -> list[str]:
    return list(grid["lines"][0]["maps"])


def grid_rows(grid: dict) -> list[dict]:
    """Per map: compared fixed points, largest errors of the unknown, the eigenvalue and the non-unit
    multiplier, stability disagreements, missing / extra fixed points, failed refinements."""
    rows = []
    for name in _names(grid):
        pairs, missing, extra, failed = [], 0, 0, 0
        for line in grid["lines"]:
            p, mi, ex = matches(line["exact"], line["maps"][name], grid["unknown"])
            pairs += p
            missing, extra = missing + mi, extra + ex
            failed += sum(q["status"] != "OK" for q in line["maps"][name])

        def worst(err, pairs=pairs) -> float:
            return max((err(e, a) for e, a in pairs), default=math.nan)

        rows.append(
            {
                "map": name,
                "compared": len(pairs),
                "unknown": worst(lambda e, a: abs(a[grid["unknown"]] - e[grid["unknown"]])),
                "eigenvalue": worst(lambda e, a: abs(a["eigenvalue"] - e["eigenvalue"])),
                "multiplier": worst(lambda e, a: abs(_mu(a) - _mu(e))),
                "speed_residual": max((abs(a["speed_residual"]) for _, a in pairs), default=math.nan),
                "stability_differs": sum(_stable(e) != _stable(a) for e, a in pairs),
                "missing": missing,
                "extra": extra,
                "failed": failed,
            }
        )
    return rows


def _row_index(region: dict, v0: float) -> int | None:
    speeds = region["speeds"]
    return next((i for i, v in enumerate(speeds) if math.isclose(v, v0)), None)


def _stable_range(region: dict, name: str, v0: float) -> tuple[float, float] | None:
    i = _row_index(region, v0)
    if i is None:
        return None
    aoa = [a for a, c in zip(region["angles_of_attack_deg"], region["maps"][name]["classes"][i], strict=True)
           if c == "S"]  # fmt: skip
    return (min(aoa), max(aoa)) if aoa else None


def _cell(region: dict, name: str, v0: float, aoa: float) -> str | None:
    i = _row_index(region, v0)
    j = next((j for j, a in enumerate(region["angles_of_attack_deg"]) if math.isclose(a, aoa)), None)
    return None if i is None or j is None else region["maps"][name]["classes"][i][j]


def region_facts(region: dict, name: str) -> dict:
    """From map ``name``'s classes: the slowest v0 with a self-stable cell, the cell counts, and
    against the exact map the share of cells of the same class and of the exact stable cells that
    the map also finds stable (and of its stable cells that are stable exactly)."""
    rows = region["maps"][name]["classes"]
    speeds = region["speeds"]
    slowest = next((v for v, r in zip(speeds, rows, strict=True) if "S" in r), None)
    cells = "".join(rows)
    out = {
        "slowest_stable_speed": slowest,
        "counts": {c: cells.count(c) for c in "Su.!"},
    }
    exact = "".join(region["maps"][EXACT]["classes"]) if EXACT in region["maps"] else None
    if exact is not None and name != EXACT:
        both = sum(a == b == "S" for a, b in zip(cells, exact, strict=True))
        out["same_class"] = sum(a == b for a, b in zip(cells, exact, strict=True)) / len(cells)
        out["exact_stable_found"] = both / exact.count("S") if exact.count("S") else math.nan
        out["stable_also_exact"] = both / cells.count("S") if cells.count("S") else math.nan
    return out


# ----------------------------------------------------------------------------------------------
# Markdown
# ----------------------------------------------------------------------------------------------
def _paragraph(text: str) -> str:
    return " ".join(text.split())


def _frac(x: float) -> str:
    return "n/a" if x is None or not math.isfinite(x) else f"{sig(100.0 * x)} %"


def _given(grid: dict, line: dict) -> str:
    g = line["given"]
    if grid["kind"] == "angle":
        return f"h = {sig(g['apex_height'])} m, v = {sig(g['speed'])} m/s"
    return f"alpha0 = {sig(90.0 - math.degrees(g['angle']))} deg"


def _unknown_label(grid: dict) -> tuple[str, str]:
    return ("touchdown angle q_th_td", "rad") if grid["kind"] == "angle" else ("apex height h", "m")


def _exact_table(grid: dict) -> list[str]:
    label, unit = _unknown_label(grid)
    lines = [
        f"| line | {label} [{unit}] | apex speed [m/s] | angle of attack [deg] | eigenvalue | Floquet "
        "multipliers | abs(h' - h) [m] | abs(v' - v) [m/s] |",
        "| --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for line in grid["lines"]:
        pts = _ok(line["exact"])
        if not pts:
            lines.append(f"| {_given(grid, line)} | none | | | | | | |")
        for p in pts:
            mu = _mu(p)
            lines.append(
                f"| {_given(grid, line)} | {sig(p[grid['unknown']], 6)} | {sig(p['apex_speed'], 4)} "
                f"| {sig(90.0 - math.degrees(p['touchdown_angle']), 4)} | {sig(p['eigenvalue'], 4)} "
                f"| 1 (off by {sig(p['energy_multiplier_deviation'], 2)}), {sig(mu.real, 4)}"
                f"{'' if mu.imag == 0 else f' {mu.imag:+.3g}i'} "
                f"| {sig(abs(p['residual']), 2)} | {sig(abs(p['speed_residual']), 2)} |"
            )
    return lines


def _error_table(grid: dict) -> list[str]:
    label, unit = _unknown_label(grid)
    lines = [
        f"| map | compared | max abs error of {label} [{unit}] | max abs error of the eigenvalue | max abs "
        "error of the non-unit multiplier | max abs(v' - v) [m/s] | stability differs | missing / extra "
        "| failed |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in grid_rows(grid):
        lines.append(
            f"| `{r['map']}` | {r['compared']} | {sig(r['unknown'])} | {sig(r['eigenvalue'])} "
            f"| {sig(r['multiplier'])} | {sig(r['speed_residual'])} | {r['stability_differs']} "
            f"| {r['missing']} / {r['extra']} | {r['failed']} |"
        )
    return lines


def _side_by_side(grid: dict, names: list[str]) -> list[str]:
    """Per line and fixed point: the unknown and the eigenvalue of the exact map and of ``names``."""
    label, unit = _unknown_label(grid)
    head = " | ".join(f"`{n}`" for n in [EXACT, *names])
    lines = [f"| line | {head} |", "| --- |" + " --- |" * (len(names) + 1)]
    for line in grid["lines"]:
        for e in _ok(line["exact"]):
            cells = [f"{sig(e[grid['unknown']], 5)}, {sig(e['eigenvalue'], 3)}"]
            for n in names:
                pairs, _, _ = matches([e], line["maps"][n], grid["unknown"])
                cells.append(
                    f"{sig(pairs[0][1][grid['unknown']], 5)}, {sig(pairs[0][1]['eigenvalue'], 3)}"
                    if pairs
                    else "none"
                )
            lines.append(f"| {_given(grid, line)} | " + " | ".join(cells) + " |")
    return [f"{label} [{unit}], eigenvalue:", "", *lines]


def _range_text(r: tuple[float, float] | None) -> str:
    return "none" if r is None else f"{sig(r[0])}-{sig(r[1])}"


def _region_table(region: dict) -> list[str]:
    names = list(region["maps"])
    head = " | ".join(f"`{n}`" for n in names)
    lines = [f"| v0 [m/s] | {head} |", "| --- |" + " --- |" * len(names)]
    for v in TABLE_SPEEDS:
        if _row_index(region, v) is not None:
            lines.append(
                f"| {sig(v)} | " + " | ".join(_range_text(_stable_range(region, n, v)) for n in names) + " |"
            )
    return lines


def _region_findings(region: dict) -> list[str]:
    out = []
    for name in region["maps"]:
        f = region_facts(region, name)
        c = f["counts"]
        slow = (
            "none on the grid"
            if f["slowest_stable_speed"] is None
            else f"{sig(f['slowest_stable_speed'])} m/s"
        )
        text = (
            f"- `{name}`: {c['S']} self-stable cells, {c['u']} with only unstable fixed points, {c['.']} "
            f"without a fixed point, {c['!']} with only failed refinements; slowest self-stable v0: {slow}."
        )
        if "same_class" in f:
            text += (
                f" Same class as the exact map in {_frac(f['same_class'])} of the cells; it finds "
                f"{_frac(f['exact_stable_found'])} of the exact self-stable cells stable, and "
                f"{_frac(f['stable_also_exact'])} of its self-stable cells are self-stable exactly."
            )
        out.append(text)
    return out


def _seyfarth(record: dict) -> list[str]:
    region = record["region"]
    facts = region_facts(region, EXACT) if EXACT in region["maps"] else None
    if facts is None:
        return ["The exact map's region was not measured; no comparison."]
    slow = facts["slowest_stable_speed"]
    at3 = _stable_range(region, EXACT, JEB_NO_STABLE_SPEED)
    v, a = JEB_EXAMPLE
    example = _cell(region, EXACT, v, a)
    widths = []
    for s in TABLE_SPEEDS:
        r = _stable_range(region, EXACT, s)
        if r is not None:
            widths.append(f"{sig(r[1] - r[0] + 0.5)} deg at {sig(s)} m/s")
    seyfarth_grid = next((g for g in record["grids"] if g["kind"] == "height"), None)
    stable_68 = ""
    if seyfarth_grid is not None:
        for line in seyfarth_grid["lines"]:
            if math.isclose(90.0 - math.degrees(line["given"]["angle"]), a, abs_tol=1e-9):
                pts = [p for p in _ok(line["exact"]) if _stable(p)]
                if pts:
                    p = pts[0]
                    stable_68 = (
                        f" (the exact stable fixed point there: apex height {sig(p['apex_height'], 4)} m, "
                        f"speed {sig(p['apex_speed'], 4)} m/s, eigenvalue {sig(p['eigenvalue'], 3)})"
                    )
    return [
        _paragraph(
            """Seyfarth, Geyer, Guenther and Blickhan, "A movement criterion for running", J Biomech 35
            (2002) 649-655, study the same model (point mass on a massless linear leg spring, a fixed
            angle of attack at touchdown, energy conserved) with human-like parameters m = 80 kg,
            l0 = 1 m, k = 20 kN/m, and the apex height return map at a given system energy, given as
            a speed at apex height 1 m. What we could check offline: the paper's abstract (self-stable
            running for certain angles of attack once a minimum speed is exceeded; the leg adjustment
            becomes less critical with speed) and the figure captions of the follow-up by Seyfarth,
            Geyer and Herr, J Exp Biol 206 (2003) 2547-2555, on the same model and parameters (at the
            energy of 3 m/s at 1 m a fixed angle of attack has no stable fixed point, Fig. 4; the
            return map of alpha0 = 68 deg at the energy of 5 m/s at 1 m, Fig. 6). We could not read
            the 2002 paper's figures, so its region's boundaries (and its minimum speed) are not
            compared number by number."""
        ),
        "",
        "- A minimum speed: "
        + (
            f"the exact map has no self-stable cell below v0 = {sig(slow)} m/s on this grid (step "
            f"{sig(region['speeds'][1] - region['speeds'][0])} m/s): agrees with the abstract."
            if slow is not None
            else "the exact map has no self-stable cell on the grid: does NOT agree."
        ),
        f"- At the energy of {sig(JEB_NO_STABLE_SPEED)} m/s at 1 m: "
        + (
            "no self-stable angle of attack: agrees with the 2003 Fig. 4 caption."
            if at3 is None
            else f"self-stable for alpha0 {_range_text(at3)} deg: does NOT agree with the 2003 Fig. 4 "
            "caption."
        ),
        f"- At the energy of {sig(v)} m/s at 1 m and alpha0 = {sig(a)} deg (the 2003 Fig. 6 example): "
        + (
            f"self-stable{stable_68}: consistent with its choice as the example (the caption does not say "
            "stable in the text we could read)."
            if example == "S"
            else f"cell class `{example}`: not self-stable here."
        ),
        "- The leg adjustment becomes less critical with speed: the width of the exact self-stable band "
        "of angles of attack (grid step 0.5 deg) is " + ", ".join(widths) + "; it moves to flatter angles "
        "(smaller alpha0) as the speed grows.",
    ]


_INTRO = """
Periodic (one-step) running gaits are the fixed points of the apex-return map: an apex (height h,
speed v) and the touchdown leg angle q_th_td (from the vertical; the angle of attack from the ground
is alpha0 = 90 deg - q_th_td) that the step returns to. With k_c = k_d, g_s = g_f and q_r_td =
q_r_lo a step conserves the flight energy E = m (g_f h + v^2/2), and the apex height return map on
an energy level is one-dimensional (Seyfarth et al. 2002): its eigenvalue lambda = dh'/dh + dh'/dv
dv/dh with dv/dh = -g_f/v on the level; the gait is self-stable when abs(lambda) < 1. The Floquet
multipliers are the eigenvalues of the 2x2 apex Jacobian d(h', v')/d(h, v): on an energy-conserving
step one is 1 and the other is lambda. `slipmaps.fixed_points` (runtime/analysis/gait.py) finds every fixed
point on a line (a batch scan brackets the sign changes of h' - h, a safeguarded Newton method
refines each); `slipmaps gait` prints them. Exact: the `solve_ivp` simulator (DOP853, rtol 1e-11).
Numbers have 3 significant digits (more for the fixed points themselves); docs/stability.json has 6.
"""


def render_markdown(record: dict, figure_name: str = "stability.png") -> str:
    region = record["region"]
    names = [n for n in region["maps"] if n != EXACT]
    out = [
        "# Periodic gaits and their stability: the maps against the exact fixed points",
        "",
        "<!-- generated by `slipmaps accuracy` (runtime/studies/stability.py, stability_report.py); "
        "do not edit -->",
        "",
        _paragraph(_INTRO),
        "",
        "## Self-stable region",
        "",
        _paragraph(
            f"""The human runner (m = {region["params"]["m"]:g} kg, l0 = {region["params"]["l0"]:g} m,
            k = {region["params"]["k_c"]:g} N/m); the energy of each row is that of speed v0 at apex
            height l0, E = m (g_f l0 + v0^2/2), v0 = {sig(region["speeds"][0])} to
            {sig(region["speeds"][-1])} m/s; angles of attack alpha0 =
            {sig(region["angles_of_attack_deg"][0])} to {sig(region["angles_of_attack_deg"][-1])} deg.
            A cell is self-stable when one of the apex heights on its energy level that the step
            returns to has abs(lambda) < 1 (colour: the smallest abs(lambda)); grey: fixed points, none
            stable; white: none. On each map's panel the black line is the exact self-stable
            region's boundary."""
        ),
        "",
        f"![self-stable region]({figure_name})",
        "",
        *_region_findings(region),
        "",
        "Self-stable angles of attack alpha0 [deg] (smallest-largest on the grid) per speed v0:",
        "",
        *_region_table(region),
        "",
        "## Comparison with Seyfarth et al. (2002)",
        "",
        *_seyfarth(record),
    ]
    for grid in record["grids"]:
        p = grid["params"]
        out += [
            "",
            f"## Fixed points: {grid['name']}",
            "",
            f"m = {p['m']:g} kg, l0 = {p['l0']:g} m, k = {p['k_c']:g} N/m; {grid['description']}. The exact "
            "fixed points (Floquet multipliers: the one nearest 1 with its distance from 1, then the other):",
            "",
            *_exact_table(grid),
            "",
            "Each map at its defaults against the exact fixed points (each exact fixed point paired with "
            "the map's nearest; stability differs: one side has abs(lambda) < 1, the other not; "
            "missing: exact fixed points the map does not have, extra: the map's unpaired ones):",
            "",
            *_error_table(grid),
        ]
        shown = [n for n in names if n in _names(grid)]
        if shown:
            out += ["", *_side_by_side(grid, shown)]
    return "\n".join(out) + "\n"


# ----------------------------------------------------------------------------------------------
# Figure
# ----------------------------------------------------------------------------------------------
def _mask(region: dict, name: str, cls: str) -> np.ndarray:
    return np.array([[c == cls for c in row] for row in region["maps"][name]["classes"]]).T


def figure(record: dict, path: str | Path) -> Path:
    """The self-stable region of every map of the record's region, one panel each: angle of attack
    against v0, self-stable cells coloured by their smallest abs(eigenvalue), the exact boundary
    drawn on every other panel, the 2003 captions' reference points marked."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap

    region = record["region"]
    names = list(region["maps"])
    speeds = np.array(region["speeds"])
    aoa = np.array(region["angles_of_attack_deg"])
    ncol = min(len(names), 2)
    nrow = math.ceil(len(names) / ncol)
    fig, axes = plt.subplots(
        nrow, ncol, figsize=(6.0 * ncol, 4.6 * nrow), squeeze=False, layout="constrained"
    )
    im = None
    for ax, name in zip(axes.flat, names, strict=False):
        eig = np.array(region["maps"][name]["min_abs_eigenvalue"], dtype=float).T
        stable = _mask(region, name, "S")
        ax.pcolormesh(speeds, aoa, np.ma.masked_where(~_mask(region, name, "u"), np.ones_like(eig)),
                      cmap=ListedColormap(["0.8"]), shading="nearest")  # fmt: skip
        failed = _mask(region, name, "!")
        if failed.any():
            ax.pcolormesh(speeds, aoa, np.ma.masked_where(~failed, np.ones_like(eig)),
                          cmap=ListedColormap(["tab:red"]), shading="nearest")  # fmt: skip
        im = ax.pcolormesh(speeds, aoa, np.ma.masked_where(~stable, eig), cmap="viridis", vmin=0.0,
                           vmax=1.0, shading="nearest")  # fmt: skip
        if name != EXACT and EXACT in names:
            ax.contour(speeds, aoa, _mask(region, EXACT, "S").astype(float), levels=[0.5], colors="k",
                       linewidths=1.0)  # fmt: skip
        ax.axvline(JEB_NO_STABLE_SPEED, color="tab:red", ls=":", lw=1.0)
        ax.plot(*JEB_EXAMPLE, marker="*", color="tab:red", ms=10, ls="none")
        ax.set_title(name, fontsize=10)
        ax.set_xlabel("v0: speed at apex height l0 with the same energy [m/s]")
        ax.set_ylabel("angle of attack alpha0 = 90 deg - q_th_td [deg]")
        ax.grid(True, alpha=0.3)
    for ax in list(axes.flat)[len(names) :]:
        ax.set_visible(False)
    fig.colorbar(im, ax=axes, label="smallest abs(eigenvalue) of a self-stable fixed point")
    fig.suptitle(f"{REGION_TITLE}\n{REGION_MARKS}", fontsize=9)
    return save_figure(fig, path, dpi=100)


class StabilityStudy(pipeline.Study):
    """docs/stability.*: the fixed points of every map of ``map_names`` (default: all) against the
    exact ones, and the self-stable region of :func:`.stability.region_maps`."""

    name = "stability"

    def __init__(self, map_names=None):
        self.map_names = map_names

    def measure(self, show_progress=None) -> dict:
        return measure(self.map_names, show_progress=show_progress)

    def markdown(self, record: dict, figure_name: str) -> str:
        return render_markdown(record, figure_name)

    def figure(self, record: dict, path: Path) -> Path:
        return figure(record, path)
