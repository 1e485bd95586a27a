"""Accuracy of Geyer et al.'s approximate stance map (report section 3.1) against the exact stance.

What is measured
----------------
For every point of a grid of apex speeds ``v`` and touchdown angles of attack ``q_th_td`` (one
grid per parameter set, :data:`GRID`), from an apex at a fixed height ``h``:

* exact: :func:`~slipmaps.runtime.simulate.simulate_step` (ballistic descent in closed form,
  stance integrated with ``solve_ivp`` DOP853 at rtol 1e-11, ballistic ascent to the next apex);
* approximate stance: :func:`~slipmaps.runtime.stance_maps.geyer_stance` started from the SAME
  touchdown state as the exact step (so stance errors are those of the stance map alone);
* approximate step: :func:`~slipmaps.runtime.apex_maps.apex_return_geyer` (the same exact flights,
  Geyer's stance) from the same apex, for the next apex height and speed.

Quantities (:data:`QUANTITIES`): stance time ``t_s``, bottom time ``t_b``, bottom leg length
``q_r_b`` and leg angle ``q_th_b``, liftoff leg rate ``q_rd_lo``, leg angle ``q_th_lo`` and angle
rate ``q_thd_lo``, next apex height and speed. Errors are ``approx - exact``; a quantity's relative
error is taken with respect to a scale named in the table where a plain relative error says little:
the leg length against the exact compression ``l0 - q_r_b`` (the leg length itself is always close
to ``l0``), the leg angles against the exact sweep from touchdown ``|q_th - q_th_td|`` (``q_th_td``
is the same for both sides, so the angle error is the sweep error).

A point enters the statistics only when both sides complete the whole step (status OK for the
exact step, the stance map and the apex-return map); other points are skipped and counted by
status (:func:`count_failures`). Within Geyer's map the first failing stage is counted: the stance
map from the exact touchdown, then the apex-return map.

The grid (:data:`GRID`)
-----------------------
* Human runner (:data:`~slipmaps.runtime.params.HUMAN_RUNNER`, k l0/(m g) ~ 25): apex speeds 3.0 to
  7.0 m/s in steps of 0.5, touchdown angles 0.30 to 0.50 rad in steps of 0.025 (9 x 9 points).
* Robot hopper (:data:`~slipmaps.runtime.params.ROBOT_HOPPER`, k l0/(m g) ~ 13): the same Froude
  numbers ``v / sqrt(g l0)``, i.e. speeds scaled by ``sqrt(0.25 / 1) = 0.5`` to 1.5 to 3.5 m/s in
  steps of 0.25. Its softer leg stays longer on the ground and sweeps further at the same Froude
  number, so it needs flatter legs (larger angles of attack) to run: its angles are shifted up by
  0.10 rad to 0.40 to 0.60 rad in steps of 0.025 (9 x 9 points).
* Apex height ``h = 1.05 l0`` for both (1.05 m, 0.2625 m): the apex is 5 % of a leg length above
  the rest length, so the body falls ``l0 (0.05 + 1 - cos q_th_td)`` before touchdown and lands with
  a moderate vertical speed: 1.36-1.84 m/s for the human, 0.80-1.05 m/s for the hopper.

The feasible region of either model is a diagonal band in (speed, angle): at high speed with a
steep leg (small angle) the body vaults over the leg and leaves the ground moving downward
(``LIFTOFF_DOWNWARD``), so a rectangular grid has failing corners; they are counted, not hidden.

Runtime: ~160 exact steps at ~1-3 ms each, well under a second after the numba kernels are loaded.

Public API: :data:`GRID`, :func:`measure`, :func:`summarize`, :func:`count_failures`,
:func:`render_markdown` (a deterministic document: no timings, numbers to 3 significant digits) and
:func:`write` (``slipmaps accuracy``).
"""

from __future__ import annotations

import math
import statistics
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from slipmaps.generated.status import Status

from .apex_maps import apex_return_geyer
from .observables import QUANTITIES, Quantity, approx_values, exact_values
from .params import HUMAN_RUNNER, ROBOT_HOPPER, SlipParams
from .simulate import DEFAULT_RTOL, simulate_step
from .stance_maps import geyer_stance

__all__ = [
    "GRID",
    "GridSpec",
    "QUANTITIES",
    "Quantity",
    "Record",
    "ErrorStats",
    "measure",
    "measure_grid",
    "summarize",
    "count_failures",
    "render_markdown",
    "write",
]


# ----------------------------------------------------------------------------------------------
# Quantities
# ----------------------------------------------------------------------------------------------
_BY_KEY = {q.key: q for q in QUANTITIES}
_REL_SCALE_TEXT = {
    "self": "exact value",
    "compression": "exact compression l0 - q_r_b",
    "sweep": "exact sweep abs(q_th - q_th_td)",
}


# ----------------------------------------------------------------------------------------------
# The grid
# ----------------------------------------------------------------------------------------------
def _steps(start: float, step: float, n: int) -> tuple[float, ...]:
    """``n`` equispaced values, rounded so that they print exactly (0.30, not 0.30000000000000004)."""
    return tuple(round(start + i * step, 10) for i in range(n))


@dataclass(frozen=True)
class GridSpec:
    """One parameter set and its grid of apex speeds [m/s] and touchdown angles [rad]."""

    name: str
    params: SlipParams
    speeds: tuple[float, ...]
    angles: tuple[float, ...]
    apex_height: float

    @property
    def size(self) -> int:
        return len(self.speeds) * len(self.angles)

    def describe(self) -> str:
        s, a = self.speeds, self.angles
        return (
            f"apex height {self.apex_height:g} m; apex speed {s[0]:g} to {s[-1]:g} m/s in steps of "
            f"{s[1] - s[0]:g} ({len(s)} values); touchdown angle {a[0]:g} to {a[-1]:g} rad in steps of "
            f"{a[1] - a[0]:.3g} ({len(a)} values): {self.size} points"
        )


#: Apex height as a multiple of the rest leg length, for both parameter sets.
APEX_HEIGHT_FACTOR = 1.05

#: Froude scaling of the hopper's speeds: sqrt(g l0_hopper) / sqrt(g l0_human).
_FROUDE = math.sqrt(ROBOT_HOPPER.l0 / HUMAN_RUNNER.l0)

#: The accuracy grids (see the module docstring for the choice).
GRID: tuple[GridSpec, ...] = (
    GridSpec(
        name="human runner",
        params=HUMAN_RUNNER,
        speeds=_steps(3.0, 0.5, 9),
        angles=_steps(0.30, 0.025, 9),
        apex_height=round(APEX_HEIGHT_FACTOR * HUMAN_RUNNER.l0, 10),
    ),
    GridSpec(
        name="robot hopper",
        params=ROBOT_HOPPER,
        speeds=_steps(3.0 * _FROUDE, 0.5 * _FROUDE, 9),
        angles=_steps(0.40, 0.025, 9),
        apex_height=round(APEX_HEIGHT_FACTOR * ROBOT_HOPPER.l0, 10),
    ),
)


# ----------------------------------------------------------------------------------------------
# Measurement
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Record:
    """One grid point: statuses of both sides and, where available, the compared quantities.

    ``exact`` and ``approx`` map quantity keys (:data:`QUANTITIES`) to values (NaN where a side did
    not reach them). ``approx_status`` is the stance map's status from the exact touchdown when it
    failed, else the apex-return map's.
    """

    apex_height: float
    apex_speed: float
    q_th_td: float
    touchdown: tuple[float, float, float, float] | None
    exact_status: Status
    approx_status: Status
    exact: dict[str, float]
    approx: dict[str, float]

    @property
    def ok(self) -> bool:
        """Both sides completed the step: the point enters the statistics."""
        return self.exact_status == Status.OK and self.approx_status == Status.OK

    def abs_error(self, key: str) -> float:
        return self.approx[key] - self.exact[key]

    def rel_error(self, key: str) -> float:
        """Error relative to the quantity's scale (:attr:`Quantity.rel_scale`), NaN if it has none."""
        scale = _BY_KEY[key].rel_scale
        if scale is None:
            return math.nan
        if scale == "self":
            ref = abs(self.exact[key])
        elif scale == "compression":
            ref = self.exact["l0"] - self.exact["b_q_r"]
        else:  # sweep
            ref = abs(self.exact[key] - self.touchdown[2])
        return self.abs_error(key) / ref if ref > 0.0 else math.nan


def _point(params: SlipParams, h: float, v: float, th: float) -> Record:
    ex = simulate_step(params, h, v, th)
    ar = apex_return_geyer(params, h, v, th)
    approx_status = ar.status
    st = None
    if ex.touchdown is not None:
        st = geyer_stance(params, ex.touchdown)
        if not st.ok:
            approx_status = st.status
    exact = {"l0": params.l0, **exact_values(ex)}
    approx = {"l0": params.l0, **approx_values(st, ar.next_apex)}
    return Record(
        apex_height=h,
        apex_speed=v,
        q_th_td=th,
        touchdown=ex.touchdown,
        exact_status=ex.status,
        approx_status=approx_status,
        exact={k: float(x) for k, x in exact.items()},
        approx={k: float(x) for k, x in approx.items()},
    )


def measure(
    params: SlipParams, speeds: Sequence[float], angles: Sequence[float], apex_height: float
) -> list[Record]:
    """Exact vs approximate step at every (speed, angle) of the grid, apex at ``apex_height``.

    Records are in row-major order (speed outer, angle inner); failing points are included with
    their statuses (see :class:`Record`).
    """
    params.k  # noqa: B018 - Geyer's map needs k_c == k_d; ValueError naming both otherwise
    return [_point(params, float(apex_height), float(v), float(th)) for v in speeds for th in angles]


def measure_grid(spec: GridSpec) -> list[Record]:
    """:func:`measure` on one :data:`GRID` entry."""
    return measure(spec.params, spec.speeds, spec.angles, spec.apex_height)


# ----------------------------------------------------------------------------------------------
# Statistics
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ErrorStats:
    """Error statistics of one quantity over the compared points (errors are approx - exact)."""

    n: int
    max_abs: float
    median_abs: float
    max_rel: float
    median_rel: float
    worst: tuple[float, float]  # (apex speed, touchdown angle) of the largest absolute error
    worst_signed: float  # the signed error there


def summarize(records: Sequence[Record]) -> dict[str, ErrorStats]:
    """Per-quantity max and median absolute (and relative) errors over the records that are ``ok``."""
    ok = [r for r in records if r.ok]
    out: dict[str, ErrorStats] = {}
    for q in QUANTITIES:
        if not ok:
            out[q.key] = ErrorStats(0, math.nan, math.nan, math.nan, math.nan, (math.nan, math.nan), math.nan)
            continue
        errs = [r.abs_error(q.key) for r in ok]
        abs_errs = [abs(e) for e in errs]
        rels = [abs(r.rel_error(q.key)) for r in ok]
        rels = [x for x in rels if math.isfinite(x)]
        i = max(range(len(ok)), key=lambda j: abs_errs[j])
        out[q.key] = ErrorStats(
            n=len(ok),
            max_abs=abs_errs[i],
            median_abs=statistics.median(abs_errs),
            max_rel=max(rels) if rels else math.nan,
            median_rel=statistics.median(rels) if rels else math.nan,
            worst=(ok[i].apex_speed, ok[i].q_th_td),
            worst_signed=errs[i],
        )
    return out


def count_failures(records: Sequence[Record]) -> dict[str, Counter]:
    """Failure counts by status: ``{"exact": Counter, "approx": Counter}`` (OK points not counted)."""
    return {
        "exact": Counter(r.exact_status for r in records if r.exact_status != Status.OK),
        "approx": Counter(r.approx_status for r in records if r.approx_status != Status.OK),
    }


# ----------------------------------------------------------------------------------------------
# Rendering
# ----------------------------------------------------------------------------------------------
def _sig(x: float, digits: int = 3) -> str:
    """``x`` to ``digits`` significant digits, plain below 1e4 and above 1e-3, else exponent form."""
    if not math.isfinite(x):
        return "n/a"
    if x == 0.0:
        return "0"
    if 1e-3 <= abs(x) < 1e4:
        decimals = max(digits - 1 - math.floor(math.log10(abs(x))), 0)
        s = f"{x:.{decimals}f}"
        # rounding may carry into a new digit (0.09996 -> 0.100): re-round on the rounded value
        return f"{float(s):.{max(digits - 1 - math.floor(math.log10(abs(float(s)))), 0)}f}"
    return f"{x:.{digits - 1}e}"


def _pct(x: float) -> str:
    return "n/a" if not math.isfinite(x) else f"{_sig(100.0 * x)} %"


def _params_line(p: SlipParams) -> str:
    stiffness = p.k * p.l0 / (p.m * p.g_s)
    return (
        f"m = {p.m:g} kg, l0 = {p.l0:g} m, k = {p.k:g} N/m (k l0/(m g_s) = {stiffness:.3g}), "
        f"g_s = {p.g_s:g} m/s^2, g_f = {p.g_f:g} m/s^2, q_r_td = {p.q_r_td:g} m, q_r_lo = {p.q_r_lo:g} m"
    )


def _table(stats: dict[str, ErrorStats]) -> list[str]:
    lines = [
        "| quantity | unit | max abs error | median abs error | max rel error | median rel error "
        "| relative to | largest error at (v, q_th_td) |",
        "| --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for q in QUANTITIES:
        s = stats[q.key]
        where = (
            f"{s.worst[0]:g} m/s, {s.worst[1]:g} rad (error {_sig(s.worst_signed)})"
            if math.isfinite(s.max_abs)
            else "n/a"
        )
        lines.append(
            f"| {q.label} | {q.unit} | {_sig(s.max_abs)} | {_sig(s.median_abs)} | {_pct(s.max_rel)} "
            f"| {_pct(s.median_rel)} | {_REL_SCALE_TEXT.get(q.rel_scale, '-')} | {where} |"
        )
    return lines


def _failure_table(records: Sequence[Record]) -> list[str]:
    fails = count_failures(records)
    statuses = sorted(set(fails["exact"]) | set(fails["approx"]))
    n = len(records)
    n_ok = sum(r.ok for r in records)
    exact_only = sum(r.exact_status != Status.OK and r.approx_status == Status.OK for r in records)
    approx_only = sum(r.exact_status == Status.OK and r.approx_status != Status.OK for r in records)
    lines = [
        f"Compared: {n_ok} of {n} points. Skipped: {n - n_ok} "
        f"({exact_only} where only the exact step fails, {approx_only} where only Geyer's map fails).",
        "",
    ]
    if not statuses:
        return [*lines, "No failures."]
    lines += ["| status | exact step | Geyer's map |", "| --- | --- | --- |"]
    for s in statuses:
        lines.append(f"| `{s.name}` | {fails['exact'][s]} | {fails['approx'][s]} |")
    return lines


def render_markdown(grid: Sequence[GridSpec] = GRID) -> str:
    """The accuracy document (markdown): deterministic, no machine-dependent numbers."""
    out = [
        "# Accuracy of Geyer et al.'s approximate stance map",
        "",
        "<!-- generated by `slipmaps accuracy` (runtime/accuracy.py); do not edit by hand -->",
        "",
        "Geyer et al.'s approximate stance map (report section 3.1, eqs 7-20 with the corrected "
        "forms of 23-26; generated kernel `geyer_stance`) against the exact stance "
        f"(`solve_ivp` DOP853, rtol {DEFAULT_RTOL:g}). At every grid point the exact step runs from "
        "an apex (height h, speed v) with the leg held at the touchdown angle q_th_td; the "
        "approximate stance map starts from the *same* exact touchdown state, so the stance errors "
        "are those of the map alone. The next apex comes from the approximate apex-return map "
        "(`apex_return_geyer`: the same exact ballistic flights, Geyer's stance). Errors are "
        "approx - exact, in SI units; relative errors are taken with respect to the scale in the "
        "column *relative to* (the leg length against the compression, the leg angles against the "
        "sweep from touchdown). A point is compared only when both sides complete the step; the "
        "others are counted by status (for Geyer's map the first failing stage: stance map, then "
        "apex return). Numbers are rounded to 3 significant digits. The largest relative errors "
        "come from points where the exact value is small (at low speed and a flat leg the runner "
        "nearly stops: small next apex speed and liftoff angle rate); the medians describe the bulk "
        "of the grid.",
        "",
        "Grid: apex height h = 1.05 l0 (the body falls l0 (0.05 + 1 - cos q_th_td) to touchdown); "
        "the hopper's speeds are the human's at the same Froude number v / sqrt(g l0), its "
        "angles are shifted up by 0.10 rad: its softer leg sweeps further and needs a flatter touchdown "
        "angle to run.",
        "",
        "Regenerate with `slipmaps accuracy` (writes `docs/accuracy.md`).",
    ]
    for spec in grid:
        records = measure_grid(spec)
        out += [
            "",
            f"## {spec.name[0].upper()}{spec.name[1:]}",
            "",
            f"Parameters: {_params_line(spec.params)}.",
            "",
            f"Grid: {spec.describe()}.",
            "",
            *_table(summarize(records)),
            "",
            *_failure_table(records),
        ]
    return "\n".join(out) + "\n"


def write(path: str | Path = "docs/accuracy.md") -> Path:
    """Write :func:`render_markdown` to ``path`` (parent directories created) and return the path."""
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(render_markdown(), encoding="utf-8")
    return p
