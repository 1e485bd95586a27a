"""The facts of the report's sections 6-8 (docs/sections.md): its numbers, claims and tables.

Each a function of the records (:func:`slipmaps.runtime.report.sections.load`): :func:`numbers`
gives every placeholder's text (``{{ n.NAME }}`` of the template), :func:`claims` every claim's
condition (``{% call claim("NAME") %}``), :data:`TABLES` every table. A lookup of a record or a map
that was not measured raises :class:`MissingData`; :mod:`.sections` decides what that means
(strict: an error; lenient: a "not measured" mark).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..studies.accuracy_report import meets_yu_target
from ..studies.report_format import pct, sig

__all__ = [
    "BASELINE",
    "ITERATIVE",
    "CLAIMS",
    "MissingData",
    "Numbers",
    "TABLES",
    "claims",
    "need",
    "numbers",
]

#: The maps compared in the discussion, by role in the report: the closed-form baseline, the
#: converging iteration.
BASELINE, ITERATIVE = "geyer", "iterative"


class MissingData(LookupError):
    """A number or claim of the document needs a record (or a map in it) that was not measured."""


def _equations(r: dict) -> list[dict]:
    """The report's equations of the registry's record (its extensions, not in the report, left out)."""
    return [e for e in need(r, "equations")["equations"] if not e.get("extension")]


def need(records: dict, key: str):
    """Record ``key`` of ``records``; :class:`MissingData` when it was not measured."""
    if key not in records:
        raise MissingData(f"no {key} record")
    return records[key]


def _grids(records: dict, kind: str | None = None) -> list[dict]:
    grids = need(records, "accuracy")["grids"]
    return [g for g in grids if kind is None or g["kind"] == kind]


def _variant(grid: dict, label: str) -> dict:
    for v in grid["variants"]:
        if v["label"] == label:
            return v
    raise MissingData(f"{label} not measured on {grid['name']}")


def _mean(grid: dict, label: str) -> float:
    x = _variant(grid, label)["apex_error"]["mean"]
    return math.nan if x is None else float(x)


def _max(grid: dict, label: str) -> float:
    x = _variant(grid, label)["apex_error"]["max"]
    return math.nan if x is None else float(x)


def _defaults(records: dict) -> list[str]:
    """The maps at their defaults, in the accuracy record's order (the index's)."""
    return [v["label"] for v in _grids(records)[0]["variants"] if v["default"]]


def _gravity(records: dict) -> list[str]:
    return [m for m in _defaults(records) if m.startswith("gravity-")]


def _range(values) -> str:
    values = [v for v in values if math.isfinite(v)]
    if not values:
        raise MissingData("an empty range")
    lo, hi = min(values), max(values)
    return sig(lo, 2) if sig(lo, 2) == sig(hi, 2) else f"{sig(lo, 2)}-{sig(hi, 2)}"


def _convergence(records: dict, grid_name: str, map_name: str, prefix: str = "") -> list[float]:
    """The mean next-apex error of ``map_name`` after n = 0, 1, ... passes on a grid of the
    convergence record (the variants whose label starts with ``map_name [convergence: prefix``)."""
    grid = next((g for g in need(records, "convergence")["grids"] if g["name"] == grid_name), None)
    if grid is None:
        raise MissingData(f"no convergence grid {grid_name}")
    head = f"{map_name} [convergence: {prefix}"
    rows = [v for v in grid["variants"] if v["label"].startswith(head)]
    if not rows:
        raise MissingData(f"{map_name} not in the convergence record")
    rows.sort(key=lambda v: v["options"]["iterations"])
    return [math.nan if v["apex_error"]["mean"] is None else v["apex_error"]["mean"] for v in rows]


# ----------------------------------------------------------------------------------------------
# Numbers and claims: what the template's placeholders and claims read
# ----------------------------------------------------------------------------------------------
def _yu(records: dict) -> dict:
    grids = _grids(records, "yu")
    if not grids:
        raise MissingData("no Yu grid")
    return grids[0]


def _front(records: dict) -> list[dict]:
    return [r for r in records["pareto"]["rows"] if r["dominated_by"] is None]


def _pareto_row(records: dict, label: str) -> dict:
    for r in records["pareto"]["rows"]:
        if r["label"] == label:
            return r
    raise MissingData(f"{label} not in the cost-accuracy front")


def _stability_lines(records: dict, name: str) -> tuple[list[float], list[float]]:
    """Per fixed point found by both, |touchdown angle difference| [rad] and |eigenvalue
    difference| of map ``name`` against the exact map, over every line of the stability record."""
    da, de = [], []
    for g in need(records, "stability")["grids"]:
        for line in g["lines"]:
            mine = line["maps"].get(name)
            if mine is None:
                raise MissingData(f"{name} not in the stability record")
            for e, m in zip(line["exact"], mine, strict=False):
                if e["status"] == "OK" and m["status"] == "OK":
                    da.append(abs(m["touchdown_angle"] - e["touchdown_angle"]))
                    de.append(abs(m["eigenvalue"] - e["eigenvalue"]))
    return da, de


def _region_agreement(records: dict, name: str) -> float:
    maps = need(records, "stability")["region"]["maps"]
    if name not in maps:
        raise MissingData(f"{name} not in the stability region")
    exact = "".join(maps["exact"]["classes"])
    mine = "".join(maps[name]["classes"])
    return sum(a == b for a, b in zip(exact, mine, strict=True)) / len(exact)


def _stiffness(
    records: dict, name: str, key: str, kind: str, lo: float, hi: float, grid: str | None = None
) -> list[float]:
    """The ``kind`` ("mean" or "max") error ``key`` of map ``name`` at every stiffness ratio in
    [lo, hi], on grid ``grid`` of the stiffness record (None: every grid)."""
    grids = [g for g in need(records, "stiffness")["grids"] if grid is None or g["name"] == grid]
    if not grids:
        raise MissingData(f"no stiffness grid {grid}")
    out = []
    for g in grids:
        for r in g["ratios"]:
            if lo - 1e-12 <= r["ratio"] <= hi + 1e-12:
                v = next((v for v in r["variants"] if v["label"] == name), None)
                if v is None:
                    raise MissingData(f"{name} not in the stiffness record")
                out.append(v[key][kind])
    if not out:
        raise MissingData("no stiffness ratio in range")
    return out


def _heat(r: dict, name: str) -> np.ndarray:
    heat = need(r, "accuracy")["figure"]["apex_error"]
    if name not in heat:
        raise MissingData(f"{name} not in the accuracy figure")
    return np.array(heat[name], dtype=float)


def _corner(r: dict) -> tuple[int, int]:
    """The (angle, speed) cell of the largest error of the baseline map on the accuracy figure."""
    g = _heat(r, BASELINE)
    i, j = np.unravel_index(np.nanargmax(g), g.shape)
    return int(i), int(j)


#: The gravity corrections whose place on the cost-accuracy front the report states (types 1-4).
_GRAVITY_TYPES = ("gravity-type1", "gravity-type2", "gravity-type3", "gravity-type4")


def numbers(r: dict) -> dict[str, Callable[[], str]]:
    """Every placeholder of the template: name -> a function of the records giving its text."""

    def dominated(label: str) -> bool:
        return bool(_pareto_row(r, label)["dominated_by"])

    yu = lambda: _yu(r)  # noqa: E731
    nonsym = lambda: _grids(r, "nonsymmetric")  # noqa: E731
    sym = lambda: _grids(r, "symmetric")  # noqa: E731
    it_yu = lambda: _convergence(r, yu()["name"], ITERATIVE)  # noqa: E731
    rep_yu = lambda: _convergence(r, yu()["name"], "iterative-report", "variant=integrand")  # noqa: E731

    def gain_nonsym():
        return _range(_mean(g, BASELINE) / _mean(g, m) for g in nonsym() + [yu()] for m in _gravity(r))

    def loss_sym():
        return _range(_mean(g, m) / _mean(g, BASELINE) for g in sym() for m in _gravity(r))

    def best_yu():
        cands = [_variant(yu(), m) for m in _gravity(r)]
        return min(cands, key=lambda v: v["apex_error"]["mean"])

    def per_pass(values):
        ratios = [a / b for a, b in zip(values[:-1], values[1:], strict=True) if b > 0]
        return _range(ratios[: len(ratios) - 2])  # the passes before the quadrature floor

    def fp_angle(name):
        da, _ = _stability_lines(r, name)
        return sig(max(da), 2)

    def fp_eig(name):
        _, de = _stability_lines(r, name)
        return sig(max(de), 2)

    def ns(label):
        return sig(_pareto_row(r, label)["ns_1_thread"], 3)

    def corner_text():
        fig = need(r, "accuracy")["figure"]
        i, j = _corner(r)
        return f"{sig(fig['speeds'][j], 3)} m/s and {sig(fig['angles'][i], 3)} rad"

    def corner_gravity():
        i, j = _corner(r)
        gravity = [m for m in need(r, "accuracy")["figure"]["apex_error"] if m.startswith("gravity-")]
        return ", ".join(f"`{m}` {pct(_heat(r, m)[i, j])}" for m in gravity)

    def geyer_vs_speed():
        means = _stiffness(r, "geyer-vs", "apex_speed", "mean", 0.8, 1.25, "human runner, nonsymmetric")
        return f"{_range(100 * x for x in means)} %"

    rep = lambda: need(r, "reproductions")  # noqa: E731

    def holding(verdicts: dict[str, str]) -> str:
        return ", ".join(f"`{m}`" for m, v in verdicts.items() if v == "holds" and m != "exact") or "none"

    out: dict[str, Callable[[], str]] = {
        "repro_geyer": lambda: rep()["geyer"]["settings"][0]["summary"]["verdict"],
        "repro_geyer_up_to": lambda: pct(rep()["geyer"]["settings"][0]["summary"]["holds_up_to_compression"]),
        "repro_yu_states": lambda: str(rep()["yu"]["states"]),
        "repro_yu_holds": lambda: holding({m["map"]: m["verdict"] for m in rep()["yu"]["maps"]}),
        "repro_seyfarth": lambda: rep()["seyfarth"]["verdicts"]["exact"],
        "repro_drake": lambda: rep()["drake"]["verdicts"]["exact"],
        "repro_drake_maps": lambda: holding(rep()["drake"]["verdicts"]),
        "heat_geyer_max": lambda: pct(np.nanmax(_heat(r, BASELINE))),
        "heat_geyer_min": lambda: pct(np.nanmin(_heat(r, BASELINE))),
        "heat_iterative_max": lambda: pct(np.nanmax(_heat(r, ITERATIVE))),
        "heat_corner": corner_text,
        "heat_corner_gravity": corner_gravity,
        "n_grids": lambda: str(len(_grids(r))),
        "n_steps": lambda: str(sum(g["n_points"] for g in _grids(r))),
        "n_exact_ok": lambda: str(sum(g["exact_ok"] for g in _grids(r))),
        "n_maps": lambda: str(len(_defaults(r))),
        "n_variants": lambda: str(len({v["label"] for g in _grids(r) for v in g["variants"]})),
        "gravity_gain": gain_nonsym,
        "gravity_sym_loss": loss_sym,
        "best_yu": lambda: f"`{best_yu()['label']}`",
        "best_yu_mean": lambda: pct(best_yu()["apex_error"]["mean"]),
        "best_yu_max": lambda: pct(best_yu()["apex_error"]["max"]),
        "yu_meets": lambda: (
            ", ".join(f"`{m}`" for m in _gravity(r) if meets_yu_target(_variant(yu(), m))) or "none"
        ),
        "geyer_yu_mean": lambda: pct(_mean(yu(), BASELINE)),
        "geyer_yu_max": lambda: pct(_max(yu(), BASELINE)),
        "iterative_mean_range": lambda: f"{_range(100 * _mean(g, ITERATIVE) for g in _grids(r))} %",
        "iterative_max_all": lambda: pct(max(_max(g, ITERATIVE) for g in _grids(r))),
        "report_sym_loss": lambda: _range(_mean(g, "iterative-report") / _mean(g, BASELINE) for g in sym()),
        "report_n0": lambda: pct(rep_yu()[0]),
        "report_n_last": lambda: pct(rep_yu()[-1]),
        "report_passes": lambda: str(len(rep_yu()) - 1),
        "iterative_n0": lambda: pct(it_yu()[0]),
        "iterative_n_last": lambda: pct(it_yu()[-1]),
        "iterative_per_pass": lambda: per_pass(it_yu()),
        "iterative_kd_max": lambda: pct(
            max(max(_stiffness(r, ITERATIVE, k, "max", 0.6, 1.5)) for k in ("apex_height", "apex_speed"))
        ),
        "geyer_vs_kd_speed": geyer_vs_speed,
        "fp_angle_geyer": lambda: fp_angle(BASELINE),
        "fp_angle_iterative": lambda: fp_angle(ITERATIVE),
        "fp_eig_geyer": lambda: fp_eig(BASELINE),
        "fp_eig_iterative": lambda: fp_eig(ITERATIVE),
        "region_geyer": lambda: pct(_region_agreement(r, BASELINE)),
        "region_iterative": lambda: pct(_region_agreement(r, ITERATIVE)),
        "ns_geyer": lambda: ns(BASELINE),
        "ns_iterative": lambda: ns("iterative (default, 6 passes)"),
        "ns_exact": lambda: ns("exact (default, rtol 1e-11)"),
        "iterative_vs_exact_cost": lambda: sig(
            _pareto_row(r, "exact (default, rtol 1e-11)")["ns_1_thread"]
            / _pareto_row(r, "iterative (default, 6 passes)")["ns_1_thread"],
            2,
        ),
        "front": lambda: ", ".join(f"`{x['label']}`" for x in _front(r)),
        "dominated": lambda: (
            ", ".join(
                f"`{x['label']}` (by `{x['dominated_by']}`)" for x in r["pareto"]["rows"] if x["dominated_by"]
            )
            or "none"
        ),
        "types_dominated": lambda: ", ".join(
            f"type {m[-1]} by `{_pareto_row(r, m)['dominated_by']}`" for m in _GRAVITY_TYPES if dominated(m)
        ),
        "types_on_front": lambda: (
            " and ".join(f"type {m[-1]}" for m in _GRAVITY_TYPES if not dominated(m)) or "none of them"
        ),
        "pareto_grids": lambda: " and ".join(r["pareto"]["grid_names"]),
        "n_equations": lambda: str(len(_equations(r))),
        "n_verified": lambda: str(sum(e["status"] == "verified" for e in _equations(r))),
        "n_corrected": lambda: str(sum(e["status"] == "corrected" for e in _equations(r))),
        "n_definitions": lambda: str(sum(e["status"] == "definition" for e in _equations(r))),
    }
    return out


def claims(r: dict) -> dict[str, Callable[[], bool]]:
    """Every claim of the template: name -> a function of the records, True when they support it."""
    nonsym = lambda: _grids(r, "nonsymmetric") + [_yu(r)]  # noqa: E731
    sym = lambda: _grids(r, "symmetric")  # noqa: E731
    approx = lambda: [m for m in _defaults(r)]  # noqa: E731

    def it_converges():
        values = _convergence(r, _yu(r)["name"], ITERATIVE)
        return all(b < a for a, b in zip(values[:-1], values[1:], strict=True))

    def report_diverges():
        values = _convergence(r, _yu(r)["name"], "iterative-report", "variant=integrand")
        return values[-1] > values[0] and values[1] > values[0]

    def iterative_closest_fp():
        return max(_stability_lines(r, ITERATIVE)[0]) < min(max(_stability_lines(r, BASELINE)[0]), 1e-2)

    def front_has(label):
        return any(x["label"] == label for x in _front(r))

    def slow_flat():
        i, j = _corner(r)
        fig = need(r, "accuracy")["figure"]
        return j < len(fig["speeds"]) / 2 and i >= len(fig["angles"]) / 2

    def gravity_corner():
        i, j = _corner(r)
        gravity = [m for m in need(r, "accuracy")["figure"]["apex_error"] if m.startswith("gravity-")]
        return bool(gravity) and all(_heat(r, m)[i, j] < _heat(r, BASELINE)[i, j] for m in gravity)

    return {
        "heat_geyer_slow_flat": slow_flat,
        "heat_gravity_corner": gravity_corner,
        "heat_iterative_below": lambda: np.nanmax(_heat(r, ITERATIVE)) < np.nanmin(_heat(r, BASELINE)),
        "gravity_beats_geyer_nonsymmetric": lambda: all(
            _mean(g, m) < _mean(g, BASELINE) for g in nonsym() for m in _gravity(r)
        ),
        "gravity_loses_symmetric": lambda: all(
            _mean(g, m) > _mean(g, BASELINE) for g in sym() for m in _gravity(r)
        ),
        "iterative_most_accurate": lambda: all(
            _mean(g, ITERATIVE) <= min(_mean(g, m) for m in approx()) for g in _grids(r)
        ),
        "yu_target_met_by_type5": lambda: meets_yu_target(_variant(_yu(r), "gravity-type5")),
        "report_worse_than_geyer_symmetric": lambda: all(
            _mean(g, "iterative-report") > _mean(g, BASELINE) for g in sym()
        ),
        "iterative_converges": it_converges,
        "report_iteration_diverges": report_diverges,
        "iterative_kd_within_target": lambda: (
            max(max(_stiffness(r, ITERATIVE, k, "max", 0.8, 1.25)) for k in ("apex_height", "apex_speed"))
            < 0.01
        ),
        "iterative_fixed_points_closest": iterative_closest_fp,
        "geyer_on_front": lambda: front_has(BASELINE),
        "iterative_on_front": lambda: front_has("iterative (default, 6 passes)"),
        "gravity_type0_on_front": lambda: front_has("gravity-type0"),
        # most of types 1-4 dominated, by a two-pass iterative among others
        "types_dominated": lambda: (
            sum(bool(_pareto_row(r, m)["dominated_by"]) for m in _GRAVITY_TYPES) >= 3
            and any(
                (_pareto_row(r, m)["dominated_by"] or "").startswith(f"{ITERATIVE}, ") for m in _GRAVITY_TYPES
            )
        ),
        "repro_geyer_narrower": lambda: (
            need(r, "reproductions")["geyer"]["settings"][0]["summary"]["verdict"]
            == "holds on a narrower domain"
        ),
        "control_targets": lambda: _control_met(r, "tracking") and _control_met(r, "rough"),
    }


def _control_met(r: dict, key: str) -> bool:
    from ..control.report import TARGETS, verdicts

    by = {target: met for target, met, _ in verdicts(need(r, "control"))}
    if TARGETS[key] not in by:
        raise MissingData(f"the control target {key}")
    return by[TARGETS[key]]


#: The names of the template's claims (the conditions: :func:`_claims`).
CLAIMS = tuple(claims({}))


@dataclass
class Numbers:
    """The template's ``n``: ``n.NAME`` is the text of number NAME (:func:`numbers`); strict, a
    number the records cannot give raises :class:`MissingData`, else it reads "n/m"."""

    records: dict
    strict: bool = True
    #: The number functions of ``records``, built once.
    functions: dict[str, Callable[[], str]] = field(init=False, repr=False)

    def __post_init__(self):
        self.functions = numbers(self.records)

    def __getattr__(self, name: str) -> str:
        if name.startswith("__") or name == "functions":
            raise AttributeError(name)
        fns = self.functions
        if name not in fns:
            raise AttributeError(f"the document has no number {name!r}")
        try:
            return fns[name]()
        except (MissingData, KeyError, ValueError, TypeError, ZeroDivisionError) as exc:
            if self.strict:
                raise MissingData(f"number {name}: {exc}") from exc
            return "n/m"


# ----------------------------------------------------------------------------------------------
# Tables
# ----------------------------------------------------------------------------------------------
def _accuracy_table(r: dict) -> str:
    grids = _grids(r)
    head = "| map | " + " | ".join(g["name"] for g in grids) + " |"
    lines = [head, "| --- |" + " --- |" * len(grids)]
    for m in _defaults(r):
        cells = []
        for g in grids:
            try:
                cells.append(f"{pct(_mean(g, m))} / {pct(_max(g, m))}")
            except MissingData:
                cells.append("n/m")
        lines.append(f"| `{m}` | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def _grid_table(r: dict) -> str:
    lines = ["| grid | k l0/(m g) | steps | exact steps complete | what |", "| --- | --- | --- | --- | --- |"]
    for g in _grids(r):
        p = g["params"]
        lines.append(
            f"| {g['name']} | {sig(p['k_c'] * p['l0'] / (p['m'] * p['g_s']), 3)} | {g['n_points']} "
            f"| {g['exact_ok']} | {g['description']} |"
        )
    return "\n".join(lines)


def _convergence_table(r: dict) -> str:
    yu = _yu(r)["name"]
    series = []
    for label, name, prefix in (
        ("`iterative-report` (as printed)", "iterative-report", "variant=integrand"),
        ("`gravity-type5`", "gravity-type5", ""),
        ("`iterative`", ITERATIVE, ""),
    ):
        try:
            series.append((label, _convergence(r, yu, name, prefix)))
        except MissingData:
            continue
    if not series:
        raise MissingData("no convergence series")
    n = max(len(s) for _, s in series)
    lines = ["| passes n | " + " | ".join(lab for lab, _ in series) + " |"]
    lines.append("| --- |" + " --- |" * len(series))
    for i in range(n):
        lines.append(f"| {i} | " + " | ".join(pct(s[i]) if i < len(s) else "" for _, s in series) + " |")
    return "\n".join(lines)


def _cost_table(r: dict) -> str:
    lines = [
        "| variant | ns per apex return (one thread) | mean / max next-apex error | dominated by |",
        "| --- | --- | --- | --- |",
    ]
    for x in r["pareto"]["rows"]:
        lines.append(
            f"| `{x['label']}` | {sig(x['ns_1_thread'], 3)} | {pct(x['mean_error'])} / {pct(x['max_error'])} "
            f"| {'`' + x['dominated_by'] + '`' if x['dominated_by'] else 'on the front'} |"
        )
    return "\n".join(lines)


def _stability_table(r: dict) -> str:
    lines = [
        "| map | max touchdown angle difference [rad] | max eigenvalue difference | region cells as exact |",
        "| --- | --- | --- | --- |",
    ]
    names = [m for m in _defaults(r) if m in need(r, "stability")["grids"][0]["lines"][0]["maps"]]
    for m in names:
        da, de = _stability_lines(r, m)
        try:
            region = pct(_region_agreement(r, m))
        except MissingData:
            region = "-"
        lines.append(
            f"| `{m}` | {sig(max(da), 2) if da else 'n/a'} | {sig(max(de), 2) if de else 'n/a'} | {region} |"
        )
    return "\n".join(lines)


def _control_table(r: dict) -> str:
    from ..control.report import verdicts

    lines = ["| target | met | measured |", "| --- | --- | --- |"]
    for target, met, what in verdicts(need(r, "control")):
        lines.append(f"| {target} | {'yes' if met else 'no'} | {what} |")
    return "\n".join(lines)


def _errata_table(r: dict) -> str:
    lines = ["| eq | what | printed and corrected | proof |", "| --- | --- | --- | --- |"]
    for e in _equations(r):
        if e["status"] == "corrected":
            note = e["note"].replace("|", "\\|")
            lines.append(f"| ({e['key']}) | {e['title']} | {note} | `{e['proof']}` |")
    return "\n".join(lines)


def _reproductions_table(r: dict) -> str:
    from ..studies.reproductions_report import table_rows

    lines = ["| claim | paper | slipmaps | verdict |", "| --- | --- | --- | --- |"]
    for row in table_rows(need(r, "reproductions")):
        lines.append("| " + " | ".join(cell.replace("|", "\\|") for cell in row) + " |")
    return "\n".join(lines)


TABLES: dict[str, Callable[[dict], str]] = {
    "grids": _grid_table,
    "accuracy": _accuracy_table,
    "convergence": _convergence_table,
    "cost": _cost_table,
    "stability": _stability_table,
    "control": _control_table,
    "errata": _errata_table,
    "reproductions": _reproductions_table,
}


def _control_summary(r: dict) -> str:
    from ..control.report import summary

    return summary(need(r, "control"))
