"""Accuracy of every map against the exact simulator (the measurements of ``slipmaps accuracy``).

For every grid of :mod:`.grids` and every point (apex height h, speed v, touchdown angle q_th_td):

* exact: :func:`~slipmaps.runtime.exact.reference.simulate_step` (closed-form descent, stance by
  ``solve_ivp`` DOP853 at rtol 1e-11, closed-form ascent);
* each map variant (a map of the index with some options, :func:`variants`): its stance from the
  SAME exact touchdown state (``stance_batch``: the stance errors are the map's alone) and its
  apex-return map from the same apex (``apex_return_batch``: the next apex).

Errors are ``map - exact``. The next-apex error of a step is the relative norm
``|(dh, dv)| / |(h, v)|`` of the Yu, Li and Cai protocol; per-quantity errors (:mod:`.quantities`)
are absolute and relative to a named scale. A point counts when both sides complete the step;
the others are counted by status: exact failures (including exact liftoffs that run backward,
left out as the protocol asks) and map failures where the exact step succeeds.

The maps and variants measured come from the index: every map, and the values of its options
that the option roles mark (:func:`variants`); :func:`maps_with` lists the maps of a map role.

With leg damping: :func:`measure_damping` runs the variants of the maps that take the leg damping
``c`` on the human runner's nonsymmetric grid at the damping ratios :data:`DAMPING_RATIOS`, the
exact map damped alike (the compiled exact map's batches: ``solve_ivp``'s reference does not take
``c``).

Public: :func:`variants`, :func:`measure` (one grid; :func:`run_maps` from given exact steps,
:func:`exact_steps` the grid's, simulated once per process; :func:`run_batch` with the exact steps
by the compiled exact map's batches, for large grids; :func:`run_variants` the variants on either),
:func:`measure_all`, :func:`compared`,
:func:`map_failures`, :func:`exact_failures` and the statistics that :mod:`.accuracy_report`
records and renders (docs/accuracy.json, .md, .png).
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import statistics
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np
from slipmaps.generated.status import Status

from ..api import index, model
from ..api.maps import apex_return_batch, stance_batch
from ..api.names import kernel_name, public
from ..api.progress import progress
from ..api.results import APEX_RETURN, STANCE
from ..exact.reference import StepResult, simulate_step, step_values
from .grids import GRIDS, Grid
from .quantities import QUANTITIES

__all__ = [
    "Variant",
    "ONE_PASS",
    "FIXED_POINT",
    "maps_with",
    "baseline",
    "options_with",
    "other_values",
    "variants",
    "GridRun",
    "VariantStats",
    "measure",
    "exact_steps",
    "run_maps",
    "run_batch",
    "run_variants",
    "measure_all",
    "DAMPING_RATIOS",
    "damped_grid",
    "measure_damping",
    "apex_errors",
    "compared",
    "map_failures",
    "exact_failures",
]

_OK = int(Status.OK)


@dataclass(frozen=True)
class Variant:
    """A map with options: one row of the accuracy tables."""

    map: str
    options: tuple[tuple[str, object], ...] = ()
    default: bool = True
    #: "" for the accuracy tables; "convergence" for the pass-count study (docs/convergence.md).
    study: str = ""

    @property
    def label(self) -> str:
        if not self.options:
            return self.map
        study = f"{self.study}: " if self.study else ""
        return f"{self.map} [{study}{', '.join(f'{k}={v}' for k, v in self.options)}]"

    @property
    def kwargs(self) -> dict:
        return dict(self.options)


#: The pass counts compared for maps with an iterated correction, by option role (the options with
#: roles "accuracy-passes" and "tolerance"): one pass, or the fixed point.
ONE_PASS = {"accuracy-passes": 1, "tolerance": 0.0}
FIXED_POINT = {"accuracy-passes": 100, "tolerance": 1e-12}


def maps_with(role: str) -> list[str]:
    """The maps of the index with the map role ``role`` (``MapInfo.roles``), in index order."""
    return [m.name for m in index.maps() if role in m.roles]


def baseline() -> str:
    """The accuracy study's reference (the map role "baseline": Geyer et al.'s map): the findings
    compare every map with it, and it is measured beside any chosen map."""
    (name,) = maps_with("baseline")
    return name


def options_with(info: index.MapInfo, role: str) -> list[index.Option]:
    """The options of map ``info`` that have ``role`` (the option roles of the index), in order."""
    return [o for o in info.options if role in o.roles]


def other_values(option: index.Option) -> list:
    """Every value of ``option`` but its default: a choice's other choices, an integer option's other
    whole numbers in [low, high]."""
    if option.kind == "choice":
        return [c for c in option.choices if c != option.default]
    if option.kind == "int" and option.low is not None and option.high is not None:
        return [v for v in range(int(option.low), int(option.high) + 1) if v != option.default]
    raise ValueError(f"option {option.name}: no values to vary (a float, or an integer without bounds)")


def _passes(info: index.MapInfo) -> list[dict]:
    """The pass-count settings of the accuracy study for ``info``: one pass and the fixed point
    (option name -> value), or a single empty setting for a map without an accuracy pass count."""
    if not options_with(info, "accuracy-passes"):
        return [{}]
    return [
        {o.name: passes[role] for role in passes for o in options_with(info, role)}
        for passes in (ONE_PASS, FIXED_POINT)
    ]


def variants(map_names: Iterable[str] | None = None) -> list[Variant]:
    """The measured variants of each map, derived from its options' roles in the index.

    Every map at its defaults; then every combination of the values of its "accuracy-readings"
    options at one pass and at the fixed point of its "accuracy-passes" option (with its "tolerance"
    option in step; the default combination left out); then each value but the default of each of
    its "accuracy-variants" options, the other options at their defaults.
    """
    names = [m.name for m in index.maps() if m.name != index.EXACT] if map_names is None else list(map_names)
    out: list[Variant] = []
    for name in names:
        info = index.get(name)
        out.append(Variant(name))
        defaults = info.resolve({})
        readings = options_with(info, "accuracy-readings")
        for combo in itertools.product(*(o.choices for o in readings)):
            for passes in _passes(info):
                chosen = {**{o.name: v for o, v in zip(readings, combo, strict=True)}, **passes}
                if any(defaults[k] != v for k, v in chosen.items()):
                    out.append(Variant(name, tuple(chosen.items()), default=False))
        for o in options_with(info, "accuracy-variants"):
            out.extend(Variant(name, ((o.name, alt),), default=False) for alt in other_values(o))
    return out


# ----------------------------------------------------------------------------------------------
# Measurement
# ----------------------------------------------------------------------------------------------
@dataclass
class GridRun:
    """One grid measured: the points, the exact steps and each variant's batch results."""

    grid: Grid
    points: np.ndarray  # (n, 3): apex height, apex speed, touchdown angle
    exact: list[StepResult | None]  # None where a symmetric point has no symmetric gait
    touchdowns: np.ndarray  # (n, 4), NaN where the exact step has no touchdown
    exact_status: np.ndarray  # (n,) int64, -1 where there is no exact step
    exact_columns: dict[str, np.ndarray]  # stance and apex-return values by result name, NaN unless OK
    results: dict[str, tuple] = field(default_factory=dict)  # label -> (variant, stance batch, apex batch)

    def exact_value(self, key: str) -> np.ndarray:
        return self.exact_columns[key]


#: The exact steps of each grid, simulated once per process (the accuracy and the convergence
#: studies run on the same steps).
_EXACT_STEPS: dict[Grid, tuple[StepResult | None, ...]] = {}


def exact_steps(grid: Grid, show_progress: bool | None = None) -> tuple[StepResult | None, ...]:
    """The exact step of every point of ``grid`` (None where a symmetric point has no symmetric gait)."""
    if grid not in _EXACT_STEPS:
        points = grid.points(show_progress)
        _EXACT_STEPS[grid] = tuple(
            simulate_step(grid.params, h, v, a) if math.isfinite(a) else None
            for h, v, a in progress(points, len(points), f"exact steps ({grid.name})", show_progress)
        )
    return _EXACT_STEPS[grid]


def measure(grid: Grid, chosen: Sequence[Variant], show_progress: bool | None = None) -> GridRun:
    """The exact steps of ``grid`` and every variant of ``chosen`` on it."""
    return run_maps(grid, grid.points(show_progress), exact_steps(grid, show_progress), chosen)


def run_maps(
    grid: Grid, points: np.ndarray, exact: Sequence[StepResult | None], chosen: Sequence[Variant]
) -> GridRun:
    """A grid's exact steps (one per row of ``points``, None where there is none) and every variant
    of ``chosen`` on the same points: its stance from each exact touchdown, its apex-return map."""
    exact = list(exact)
    tds = np.array(
        [s.touchdown if s is not None and s.touchdown is not None else (math.nan,) * 4 for s in exact]
    )
    status = np.array([int(s.status) if s is not None else -1 for s in exact], dtype=np.int64)
    names = tuple(dict.fromkeys(STANCE + APEX_RETURN))  # every stance output, then the step's others
    kernel = [kernel_name(n) for n in names]  # the simulator's names (step_values)
    rows = np.array(
        [[step_values(s)[k] if s is not None and s.ok else math.nan for k in kernel] for s in exact]
    )
    cols = {n: rows.reshape(-1, len(names))[:, j] for j, n in enumerate(names)}
    return run_variants(GridRun(grid, points, exact, tds.reshape(-1, 4), status, cols), chosen)


def run_batch(grid: Grid, points: np.ndarray, chosen: Sequence[Variant]) -> GridRun:
    """As :func:`run_maps`, the exact steps by the compiled exact map's batches instead of
    ``solve_ivp`` (the same steps to ~1e-14, the compiled simulator, generated/exact_stance.py; for grids of
    thousands of points): the exact apex return from each point, the exact stance from its
    closed-form touchdown (the model kernel ``apex_to_touchdown``). ``exact`` is empty (no
    StepResult)."""
    p = grid.params
    ap = apex_return_batch(index.EXACT, p, points[:, 0], points[:, 1], points[:, 2])
    code, td = model.rows(
        "apex_to_touchdown",
        b_y_apex=points[:, 0],
        b_xd_apex=points[:, 1],
        q_th_td=points[:, 2],
        q_r_td=p.q_r_td,
        g_f=p.g_f,
        ground=0.0,
    )
    tds = np.column_stack([td[f"touchdown_{q}"] for q in ("q_r", "q_rd", "q_th", "q_thd")])
    tds[code != _OK] = math.nan
    st = stance_batch(index.EXACT, p, tds)
    ok = ap.status == _OK
    cols = {n: np.where(ok, st[n], math.nan) for n in STANCE}
    cols.update({n: np.where(ok, ap[n], math.nan) for n in APEX_RETURN if n not in cols})
    return run_variants(GridRun(grid, points, [], tds, ap.status.astype(np.int64), cols), chosen)


def run_variants(run: GridRun, chosen: Sequence[Variant]) -> GridRun:
    """Every variant of ``chosen`` on ``run``'s points: its stance from each exact touchdown (into
    ``run.results``), its apex-return map from each apex; returns ``run``."""
    p, points = run.grid.params, run.points
    for var in chosen:
        st = stance_batch(var.map, p, run.touchdowns, **var.kwargs)
        ap = apex_return_batch(var.map, p, points[:, 0], points[:, 1], points[:, 2], **var.kwargs)
        run.results[var.label] = (var, st, ap)
    return run


def measure_all(
    chosen: Sequence[Variant] | None = None, grids: Sequence[Grid] = GRIDS, show_progress=None
) -> list[GridRun]:
    chosen = variants() if chosen is None else chosen
    return [measure(g, chosen, show_progress) for g in grids]


#: The damping ratios c / (2 sqrt(k_c m)) of the damping table (0: the lossless leg, for reference).
DAMPING_RATIOS = (0.0, 0.02, 0.05, 0.1, 0.2)


def damped_grid(grid: Grid, ratio: float) -> Grid:
    """``grid`` with the leg damping c = ``ratio`` times the critical damping 2 sqrt(k_c m)."""
    p = grid.params
    return dataclasses.replace(grid, params=p.with_(c=ratio * 2.0 * math.sqrt(p.k_c * p.m)))


def measure_damping(chosen: Sequence[Variant] | None = None, grid: Grid = GRIDS[0]) -> list[GridRun]:
    """The variants of ``chosen`` (default: :func:`variants`) whose map takes the leg damping c, on
    ``grid``'s points (the human runner's nonsymmetric grid) at each of :data:`DAMPING_RATIOS`, against
    the exact map with the same c (:func:`run_batch`). Empty where no map takes c."""
    chosen = variants() if chosen is None else chosen
    damped = [v for v in chosen if "c" in index.get(v.map).params]
    if not damped:
        return []
    points = grid.points()
    return [run_batch(damped_grid(grid, r), points, damped) for r in DAMPING_RATIOS]


# ----------------------------------------------------------------------------------------------
# Statistics
# ----------------------------------------------------------------------------------------------
def _stats(values: np.ndarray) -> dict[str, float]:
    values = values[np.isfinite(values)]
    if values.size == 0:
        return {"mean": math.nan, "median": math.nan, "max": math.nan}
    return {
        "mean": float(values.mean()),
        "median": float(statistics.median(values)),
        "max": float(values.max()),
    }


def apex_errors(run: GridRun, label: str) -> np.ndarray:
    """The next-apex relative error |(dh, dv)| / |(h, v)| per point (NaN unless both sides OK)."""
    _, _, ap = run.results[label]
    h, v = run.exact_value("next_apex_height"), run.exact_value("next_apex_speed")
    dh, dv = ap["next_apex_height"] - h, ap["next_apex_speed"] - v
    err = np.hypot(dh, dv) / np.hypot(h, v)
    return np.where(compared(run, label), err, math.nan)


def compared(run: GridRun, label: str) -> np.ndarray:
    """Per point: both sides complete the step (the exact step, the variant's stance and apex return)."""
    _, st, ap = run.results[label]
    return (run.exact_status == _OK) & (st.status == _OK) & (ap.status == _OK)


def map_failures(run: GridRun, label: str) -> Counter:
    """Where the exact step succeeds but the map fails: the stance status, else the apex-return's."""
    _, st, ap = run.results[label]
    out: Counter = Counter()
    for ex, s, a in zip(run.exact_status, st.status, ap.status, strict=True):
        if ex == _OK and (s != _OK or a != _OK):
            out[Status(int(s if s != _OK else a)).name] += 1
    return out


@dataclass(frozen=True)
class VariantStats:
    """Everything the report shows about one variant on one grid."""

    label: str
    map: str
    options: dict
    default: bool
    n_compared: int
    failures: dict[str, int]
    apex_error: dict[str, float]
    by_angle: list[dict]  # Yu protocol: per angle of attack
    quantities: dict[str, dict[str, float]]
    passes: dict[str, float] | None


def _rel_scale(run: GridRun, key: str, scale: str) -> np.ndarray:
    ref = run.exact_value(public(key))
    if scale == "self":
        return np.abs(ref)
    if scale == "compression":
        return run.grid.params.l0 - ref
    return np.abs(ref - run.points[:, 2])  # sweep from the touchdown angle


def variant_stats(run: GridRun, label: str) -> VariantStats:
    var, st, ap = run.results[label]
    ok = compared(run, label)
    # stance quantities compare the stance map from the same touchdown; the apex the apex-return map
    quantities = {}
    for q in QUANTITIES:
        source = ap if q.key.startswith("apex_") else st
        err = source[public(q.key)] - run.exact_value(public(q.key))
        err = np.where(ok, err, math.nan)
        rel = err / _rel_scale(run, q.key, q.rel_scale)
        a, r = _stats(np.abs(err)), _stats(np.abs(rel))
        quantities[q.key] = {
            "max_abs": a["max"],
            "median_abs": a["median"],
            "max_rel": r["max"],
            "median_rel": r["median"],
        }
    errors = apex_errors(run, label)
    by_angle = []
    if run.grid.kind == "yu":
        for angle in run.grid.angles:
            sel = np.isclose(run.points[:, 2], angle)
            s = _stats(errors[sel])
            by_angle.append(
                {
                    "angle_of_attack_deg": round(90.0 - math.degrees(angle), 6),
                    "n": int(np.isfinite(errors[sel]).sum()),
                    **s,
                    "map_failures": int(((run.exact_status == _OK) & sel & ~ok).sum()),
                }
            )
    passes = None
    if "passes" in st.names:
        p = st["passes"][np.isfinite(st["passes"]) & ok]
        passes = {"median": float(np.median(p)), "max": float(p.max())} if p.size else None
    return VariantStats(
        label=label,
        map=var.map,
        options=var.kwargs,
        default=var.default,
        n_compared=int(ok.sum()),
        failures=dict(sorted(map_failures(run, label).items())),
        apex_error=_stats(errors),
        by_angle=by_angle,
        quantities=quantities,
        passes=passes,
    )


def exact_failures(run: GridRun) -> dict[str, int]:
    counts = Counter(Status(int(c)).name for c in run.exact_status if c not in (_OK, -1))
    return dict(sorted(counts.items()))
