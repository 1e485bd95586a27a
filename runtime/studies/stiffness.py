"""The variable-stiffness study (measurements): every map that accepts k_c != k_d against the exact
simulator over k_d/k_c, and the bottom leg length estimates (153) and (154).

``slipmaps accuracy`` writes docs/stiffness.json, .md, .png from it (:func:`summarize` is the
record; :class:`.stiffness_report.StiffnessStudy` renders it, through :mod:`.study`). For every
grid of :func:`grids` (the human runner's and the robot hopper's of docs/accuracy.md, the
nonsymmetric ones subsampled) and every k_d/k_c of :data:`RATIOS` (k_c the parameter set's k):

* exact: :func:`~slipmaps.runtime.exact.reference.simulate_step` with (k_c, k_d);
* each variant of :func:`variants` (every map whose parameters include k_d but the exact one, at
  its defaults, and once per other value of each of its options with the role
  "stiffness-variants" in the index): its stance from the same exact touchdown and its apex-return
  map from the same apex (:func:`.accuracy.run_maps`).

Errors (:data:`ERRORS`) are absolute differences to the exact step, scaled: the next apex height by
l0, its speed by the exact one; the liftoff velocity |d(b_xd, b_yd)| by the exact |(b_xd, b_yd)|, the
liftoff angle by the exact sweep |q_th_lo - q_th_td|; the energy after the bottom, (27) with k_d at
the map's bottom state (E_ba) or at its liftoff state, by the exact E_ba ((27) with k_d at the exact
bottom; the exact decompression conserves it to 1e-11). A step is compared when both sides complete
it; map failures are steps the exact simulator completes and the map does not.

The bottom leg length does not depend on k_d (it ends the compression). Against the exact bottom of
every step that reaches one, as a fraction of the exact compression l0 - q_r_b and of q_r_b
(:data:`BOTTOM_ESTIMATES`): (153), the root of the quartic kernel ``bottom_quartic`` with the
touchdown angular momentum and total energy (27) with k_c; the same with the exact bottom's angular
momentum (a check that isolates the vertical-bottom assumption: the gravity torque changes p_th
during the compression); and (154), Geyer et al.'s bottom l0 (1 + a_ab - b_ab) (``bottom_q_r`` of
``geyer-vs`` at k_d = k_c).
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np
from slipmaps.generated.status import Status

from ..api import index, model
from ..api.maps import stance_batch
from ..api.params import SlipParams
from ..api.progress import progress
from ..api.results import GROUPS
from ..exact.reference import simulate_step
from . import study as pipeline
from .accuracy import (
    GridRun,
    Variant,
    compared,
    exact_failures,
    map_failures,
    options_with,
    other_values,
    run_maps,
)
from .grids import GRIDS, Grid
from .report_format import rounded

__all__ = [
    "RATIOS",
    "ERRORS",
    "GridStudy",
    "variants",
    "grids",
    "measure",
    "errors",
    "summarize",
    "from_json",
]

#: The stiffness ratios k_d/k_c of the study (k_c = the parameter set's k).
RATIOS = (0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.25, 1.5)
#: The nonsymmetric grids keep every SUBSAMPLE-th apex speed and touchdown angle (all heights; with 9
#: of each, both ends stay): the study then adds seconds, not minutes, to ``slipmaps accuracy``.
SUBSAMPLE = 2
SUBSAMPLED = "every other" if SUBSAMPLE == 2 else f"every {SUBSAMPLE}th"
#: The map whose ``bottom_q_r`` at k_d = k_c is (154), Geyer et al.'s bottom with k_c.
BOTTOM_MAP = "geyer-vs"
_OK = int(Status.OK)


@dataclass(frozen=True)
class Error:
    """One measured error: ``key`` in the record, a table column and what it measures."""

    key: str
    column: str
    description: str


ERRORS: tuple[Error, ...] = (
    Error("apex_height", "next apex height", "the next apex height as a fraction of l0"),
    Error("apex_speed", "next apex speed", "the next apex speed as a fraction of the exact one"),
    Error(
        "liftoff_velocity",
        "liftoff velocity",
        "the liftoff velocity, norm of (d b_xd, d b_yd) as a fraction of the exact speed at liftoff",
    ),
    Error(
        "liftoff_angle",
        "liftoff angle",
        "the liftoff angle q_th_lo as a fraction of the exact sweep abs(q_th_lo - q_th_td)",
    ),
    Error(
        "energy_bottom",
        "E_ba at the bottom",
        "the energy after the bottom E_ba, (27) with k_d at the map's bottom state, as a fraction of "
        "the exact E_ba",
    ),
    Error(
        "energy_liftoff",
        "energy at liftoff",
        "the energy at liftoff, (27) with k_d at the map's liftoff state, as a fraction of the exact E_ba",
    ),
)


def variants(map_names: Sequence[str] | None = None) -> list[Variant]:
    """Every map of ``map_names`` (default: all) whose parameters include k_d, except the exact one,
    at its defaults and at every other value of each of its options with the role
    "stiffness-variants" (``geyer-vs``: how q_r joins at the bottom, its gravity correction)."""
    names = [m.name for m in index.maps()] if map_names is None else list(map_names)
    out: list[Variant] = []
    for name in names:
        info = index.get(name)
        if name == index.EXACT or "k_d" not in info.params:
            continue
        out.append(Variant(name))
        for o in options_with(info, "stiffness-variants"):
            out += [Variant(name, ((o.name, c),), default=False) for c in other_values(o)]
    return out


def grids(source: Sequence[Grid] = GRIDS) -> list[Grid]:
    """The nonsymmetric and symmetric grids of ``source``, the nonsymmetric ones subsampled."""
    out = []
    for g in source:
        if g.kind == "symmetric":
            out.append(g)
        elif g.kind == "nonsymmetric":
            speeds, angles = g.speeds[::SUBSAMPLE], g.angles[::SUBSAMPLE]
            n = f"{len(speeds)} x {len(angles)}"
            text = f"{g.description} of docs/accuracy.md, {SUBSAMPLED} speed and angle ({n})"
            out.append(replace(g, speeds=speeds, angles=angles, description=text))
    return out


# ----------------------------------------------------------------------------------------------
# Measurement
# ----------------------------------------------------------------------------------------------
@dataclass
class GridStudy:
    """One grid over the stiffness ratios: its points and, per k_d/k_c, the measured run."""

    grid: Grid  # the parameter set with k_d = k_c
    points: np.ndarray
    runs: dict[float, GridRun]


def _with_ratio(params: SlipParams, ratio: float) -> SlipParams:
    return params.with_(k_d=params.k_c * ratio)


def measure(
    chosen: Sequence[Variant] | None = None,
    chosen_grids: Sequence[Grid] | None = None,
    ratios: Sequence[float] = RATIOS,
    show_progress: bool | None = None,
) -> list[GridStudy]:
    """The exact steps of every grid at every k_d/k_c and every variant of ``chosen`` on them."""
    chosen = variants() if chosen is None else list(chosen)
    chosen_grids = grids() if chosen_grids is None else list(chosen_grids)
    points = [g.points(show_progress) for g in chosen_grids]
    params = {(i, r): _with_ratio(g.params, r) for i, g in enumerate(chosen_grids) for r in ratios}
    jobs = [(i, r, row) for i, pts in enumerate(points) for r in ratios for row in pts]
    steps = iter(
        [
            simulate_step(params[i, r], h, v, a) if math.isfinite(a) else None
            for i, r, (h, v, a) in progress(jobs, len(jobs), "exact steps over k_d/k_c", show_progress)
        ]
    )
    out = []
    for i, (g, pts) in enumerate(zip(chosen_grids, points, strict=True)):
        runs = {}
        for r in ratios:
            exact = [next(steps) for _ in range(len(pts))]
            runs[r] = run_maps(replace(g, params=params[i, r]), pts, exact, chosen)
        out.append(GridStudy(g, pts, runs))
    return out


def _states(source, group: str) -> np.ndarray:
    """(n, 4) polar states of ``group`` ("bottom", "liftoff") from result columns by name."""
    return np.column_stack([source[name] for name in GROUPS[group]])


def _energy(states: np.ndarray, p: SlipParams, k: float) -> np.ndarray:
    """The total energy (27) with stiffness ``k`` of each polar state (NaN rows stay NaN)."""
    _, out = model.rows("stance_energy", **_polar(states), m=p.m, l0=p.l0, k=k, g_s=p.g_s)
    return out["energy"]


def _velocity(states: np.ndarray) -> np.ndarray:
    """(n, 2) Cartesian body velocity (b_xd, b_yd) of each polar state."""
    _, out = model.rows("polar_to_cartesian", **_polar(states))
    return np.column_stack([out["out_b_xd"], out["out_b_yd"]])


def _polar(states: np.ndarray) -> dict[str, np.ndarray]:
    """The columns of (n, 4) polar states by the model kernels' argument names."""
    return {q: states[:, j] for j, q in enumerate(("q_r", "q_rd", "q_th", "q_thd"))}


def errors(run: GridRun, label: str) -> dict[str, np.ndarray]:
    """Per point, every error of :data:`ERRORS` of variant ``label`` (NaN unless both sides OK)."""
    _, st, ap = run.results[label]
    p, ex = run.grid.params, run.exact_columns
    lo_ex, lo_map = _states(ex, "liftoff"), _states(st, "liftoff")
    e_ba = _energy(_states(ex, "bottom"), p, p.k_d)
    v_ex = _velocity(lo_ex)
    with np.errstate(invalid="ignore", divide="ignore"):
        raw = {
            "apex_height": np.abs(ap["next_apex_height"] - ex["next_apex_height"]) / p.l0,
            "apex_speed": np.abs(ap["next_apex_speed"] - ex["next_apex_speed"])
            / np.abs(ex["next_apex_speed"]),
            "liftoff_velocity": np.linalg.norm(_velocity(lo_map) - v_ex, axis=1)
            / np.linalg.norm(v_ex, axis=1),
            "liftoff_angle": np.abs(lo_map[:, 2] - lo_ex[:, 2]) / np.abs(lo_ex[:, 2] - run.touchdowns[:, 2]),
            "energy_bottom": np.abs(_energy(_states(st, "bottom"), p, p.k_d) - e_ba) / np.abs(e_ba),
            "energy_liftoff": np.abs(_energy(lo_map, p, p.k_d) - e_ba) / np.abs(e_ba),
        }
    ok = compared(run, label)
    return {e.key: np.where(ok, raw[e.key], math.nan) for e in ERRORS}


def _stats(values: np.ndarray) -> dict[str, float]:
    values = values[np.isfinite(values)]
    if values.size == 0:
        return {"mean": math.nan, "max": math.nan}
    return {"mean": float(values.mean()), "max": float(values.max())}


def _quartic(p: SlipParams, p_th: np.ndarray, touchdowns: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The root of (153) (kernel ``bottom_quartic``) per row: angular momentum ``p_th``, the energy
    (27) with k_c of the touchdown state; and its status."""
    energy = _energy(np.asarray(touchdowns, dtype=float).reshape(-1, 4), p, p.k_c)
    status, out = model.rows("bottom_quartic", p_b=p_th, E_ab=energy, m=p.m, l0=p.l0, k_c=p.k_c, g_s=p.g_s)
    return out["q_r_b"], status


#: The bottom leg length estimates, by key: how each is computed.
BOTTOM_ESTIMATES = {
    "153": "(153) with the touchdown p_th",
    "153-exact-p": "(153) with the exact bottom p_th (a check: only the vertical bottom assumed)",
    "154": "(154) Geyer et al.'s bottom l0 (1 + a_ab - b_ab)",
}


def bottom_lengths(study: GridStudy) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Per point: the exact bottom (q_r_b, q_th_b) and each estimate of :data:`BOTTOM_ESTIMATES` with
    its status.

    The exact bottom ends the compression (k_c), so any ratio's steps give it; it exists where the
    step reaches the bottom, also when it fails later. (153) takes the total energy (27) with k_c at
    touchdown and an angular momentum p_th = m q_r^2 q_thd: the touchdown's (the estimate), or the
    exact bottom's (gravity's torque changes p_th during the compression; with the bottom's, only
    the vertical bottom is assumed). (154) is ``bottom_q_r`` of :data:`BOTTOM_MAP` at k_d = k_c (NaN,
    with its status, where that stance fails).
    """
    run = next(iter(study.runs.values()))
    p = study.grid.params
    bottoms = [s.bottom if s is not None and s.bottom is not None else (math.nan,) * 4 for s in run.exact]
    q_b, _, th_b, thd_b = np.array(bottoms, dtype=float).reshape(-1, 4).T
    td = run.touchdowns
    geyer = stance_batch(BOTTOM_MAP, p.with_(k_d=p.k_c), td)
    return {
        "exact": (q_b, th_b),
        "153": _quartic(p, p.m * td[:, 0] ** 2 * td[:, 3], td),
        "153-exact-p": _quartic(p, p.m * q_b**2 * thd_b, td),
        "154": (np.asarray(geyer["bottom_q_r"]), np.asarray(geyer["status"])),
    }


def _bottom_summary(study: GridStudy) -> dict:
    b = bottom_lengths(study)
    q_ex, th_ex = b["exact"]
    has = np.isfinite(q_ex)
    out = {
        "n_bottoms": int(has.sum()),
        "exact_bottom_angle_max": float(np.nanmax(np.abs(th_ex), initial=0.0)),
    }
    rows = []
    for key, label in BOTTOM_ESTIMATES.items():
        q, status = b[key]
        ok = has & (status == _OK)
        err = np.where(ok, np.abs(q - q_ex), math.nan)
        with np.errstate(invalid="ignore", divide="ignore"):
            rows.append(
                {
                    "equation": key,
                    "label": label,
                    "n_compared": int(ok.sum()),
                    "failures": dict(sorted(Counter(Status(int(c)).name for c in status[has & ~ok]).items())),
                    "of_compression": _stats(err / (study.grid.params.l0 - q_ex)),
                    "of_length": _stats(err / q_ex),
                }
            )
    out["estimates"] = rows
    return out


def _variant_summary(run: GridRun, label: str) -> dict:
    var = run.results[label][0]
    errs = errors(run, label)
    return {
        "label": label,
        "map": var.map,
        "options": var.kwargs,
        "default": var.default,
        "n_compared": int(compared(run, label).sum()),
        "failures": dict(sorted(map_failures(run, label).items())),
        **{e.key: _stats(errs[e.key]) for e in ERRORS},
    }


def summarize(studies: Sequence[GridStudy]) -> list[dict]:
    """Per grid: its facts, per k_d/k_c the statistics of every variant, and the bottom estimates,
    as JSON-ready data (6 significant digits); docs/stiffness.md is rendered from it."""
    out = []
    for s in studies:
        g = s.grid
        by_ratio = [
            {
                "ratio": float(r),
                "exact_ok": int((run.exact_status == _OK).sum()),
                "exact_failures": exact_failures(run),
                "variants": [_variant_summary(run, label) for label in run.results],
            }
            for r, run in s.runs.items()
        ]
        out.append(
            {
                "name": g.name,
                "kind": g.kind,
                "description": g.description,
                "params": g.params.as_dict(),
                "n_points": int(len(s.points)),
                "no_symmetric_gait": int(np.isnan(s.points[:, 2]).sum()),
                "ratios": by_ratio,
                "bottom": _bottom_summary(s),
            }
        )
    return rounded(out)


def from_json(text: str) -> list[dict]:
    """The grids of docs/stiffness.json (:func:`summarize`'s list)."""
    return pipeline.from_json(text)["grids"]
