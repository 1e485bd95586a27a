"""The main job: one SLIP step by two maps from the same touchdown (default Geyer et al. vs exact).

Both sides start from the same touchdown state (reached from an apex by the exact ballistic
flight, or given directly) and fly from their own liftoff to the next apex exactly; only the
stance differs. :func:`compare` returns the rows of the table (quantity, unit, reference value,
map value, absolute and relative error: ``map - against``); :func:`format_table` prints them and
:func:`plot` draws q_r(t) and q_th(t) of both stances.

The default step scales with the leg (:func:`~.apex_defaults.default_apex`): apex height
``APEX_HEIGHT_L0 * l0``, speed ``APEX_FROUDE * sqrt(g_f l0)`` (a Froude number) and a touchdown angle
scaled by the dimensionless stiffness, so the human runner's step is 1.0 m high at 5 m/s with the leg
at 0.35 rad and the robot hopper's (0.25 m, 2.5 m/s, 0.495 rad) is as high, as fast and sweeps as
far relative to its leg.

One rule for physical failures: an apex below the touchdown height, a stance or an ascent that fails
is a status of the side it happened to (both sides when there is no touchdown), with NaN values and
a message; only invalid arguments raise (ValueError/TypeError). A touchdown state given directly
sets the touchdown leg length: the comparison's parameters carry ``q_r_td`` = its ``q_r``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from slipmaps.generated.status import MESSAGES, Status

from ..api import index
from ..api.maps import half_stance, stance, trajectory
from ..api.numeric import num
from ..api.params import HUMAN_RUNNER, SlipParams
from ..api.paths import save_figure
from ..api.results import Result
from ..api.validate import leg_angle, non_negative, polar_state
from ..studies.quantities import QUANTITIES
from . import flight
from .defaults import APEX_FROUDE, APEX_HEIGHT_L0, TOUCHDOWN_ANGLE, default_apex

__all__ = [
    "Row",
    "Side",
    "Comparison",
    "compare",
    "default_map",
    "default_apex",
    "format_table",
    "plot",
    "APEX_HEIGHT_L0",
    "APEX_FROUDE",
    "TOUCHDOWN_ANGLE",
    "DEFAULT_APEX",
]

#: The documented default case, the human runner's: apex 1.0 m high at 5 m/s, touchdown angle 0.35 rad.
DEFAULT_APEX = default_apex(HUMAN_RUNNER)


@dataclass(frozen=True)
class Row:
    quantity: str
    unit: str
    reference: float  # the ``against`` map
    value: float  # the compared map

    @property
    def abs_error(self) -> float:
        return self.value - self.reference

    @property
    def rel_error(self) -> float:
        return self.abs_error / abs(self.reference) if self.reference != 0.0 else math.nan


@dataclass(frozen=True)
class Side:
    """One map's step: its stance result and the next apex after its liftoff."""

    map: str
    options: dict
    stance: Result
    status: Status  # the stance's status, else the ascent's
    next_apex: tuple[float, float]

    @property
    def message(self) -> str:
        """The stance result's own message when its status is the side's, else the status's."""
        return self.stance.message if self.stance.status == self.status else MESSAGES[int(self.status)]

    @property
    def ok(self) -> bool:
        return self.status == Status.OK

    def value(self, key: str) -> float:
        if key == "apex_height":
            return self.next_apex[0]
        if key == "apex_speed":
            return self.next_apex[1]
        return float(self.stance.values.get(key, math.nan))


@dataclass(frozen=True)
class Comparison:
    params: SlipParams
    touchdown: tuple[float, float, float, float]
    map: Side
    against: Side
    rows: tuple[Row, ...] = field(default=())
    #: A half-stance map compared (``touchdown`` is then its start state: touchdown or bottom).
    half: index.HalfInfo | None = None
    #: True when the touchdown state was given (``params.q_r_td`` is then its q_r), False from an apex.
    touchdown_given: bool = False
    #: The touchdown state of the whole stance, where ``touchdown`` is a half's bottom start state
    #: (None: ``touchdown`` is the touchdown state); the plot draws the reference's stance from it.
    stance_touchdown: tuple[float, float, float, float] | None = None

    @property
    def ok(self) -> bool:
        """True when both sides ran to the end (status OK)."""
        return self.map.ok and self.against.ok

    def to_dict(self) -> dict:
        return {
            "params": self.params.as_dict(),
            "touchdown": {
                q: _json_float(x)
                for q, x in zip(("q_r", "q_rd", "q_th", "q_thd"), self.touchdown, strict=True)
            },
            "touchdown_given": self.touchdown_given,
            "ok": self.ok,
            "map": self.map.map,
            "map_options": self.map.options,
            "against": self.against.map,
            "against_options": self.against.options,
            "map_status": self.map.status.name,
            "map_message": self.map.message,
            "against_status": self.against.status.name,
            "against_message": self.against.message,
            # the names of the exact-vs-approximate default, kept for scripts
            "approx_status": self.map.status.name,
            "exact_status": self.against.status.name,
            "rows": [
                {
                    "quantity": r.quantity,
                    "unit": r.unit,
                    "reference": _json_float(r.reference),
                    "value": _json_float(r.value),
                    "abs_error": _json_float(r.abs_error),
                    "rel_error": _json_float(r.rel_error),
                }
                for r in self.rows
            ],
        }


def _json_float(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def _not_run(name: str, kind: str, options: dict, status: Status, message: str) -> Side:
    """A side that never started (no touchdown): NaN values, ``status`` and ``message``."""
    return Side(name, options, Result(name, kind, status, message, {}), status, (math.nan, math.nan))


def _side(name: str, params: SlipParams, td, options: dict) -> Side:
    res = stance(name, params, td, **options)
    if not res.ok:
        return Side(name, options, res, res.status, (math.nan, math.nan))
    status, h, v = flight.next_apex(params, res.liftoff, flight.direction(td))
    return Side(name, options, res, status, (h, v))


#: The role (``MapInfo.roles``) of the maps compared by default: Geyer et al.'s (report 3.1), and
#: its split form (5.1) that accepts k_c != k_d.
DEFAULT_ROLE = "default"


def default_map(params: SlipParams) -> str:
    """The first map with the role :data:`DEFAULT_ROLE` (index order) whose requirements ``params``
    meet: Geyer et al.'s map for a constant stiffness, the simple variable-stiffness map otherwise."""
    for info in index.maps():
        if DEFAULT_ROLE in info.roles and (
            params.constant_stiffness or "constant_stiffness" not in info.requires
        ):
            return info.name
    raise ValueError("no map with the role 'default' accepts these parameters")


def compare(
    params: SlipParams,
    *,
    map: str | None = None,  # noqa: A002 - the CLI's --map
    against: str = index.EXACT,
    apex_height: float | None = None,
    apex_speed: float | None = None,
    touchdown_angle: float | None = None,
    touchdown=None,
    options: dict | None = None,
    against_options: dict | None = None,
) -> Comparison:
    """One step by ``map`` and by ``against`` from an apex (height [m], speed [m/s], touchdown angle
    [rad]; each None: :func:`default_apex`'s) or a polar touchdown state (``map`` None:
    :func:`default_map`).

    A touchdown state sets the touchdown leg length: the result's ``params.q_r_td`` is its q_r. An
    apex below the touchdown height is the status APEX_TOO_LOW of both sides (NaN values, see the
    module docstring); ValueError/TypeError only for invalid arguments (an unknown map or option, a
    map that refuses the parameters, a NaN, an apex together with a touchdown state)."""
    map = default_map(params) if map is None else map  # noqa: A001
    info = index.lookup(map)
    half = info if isinstance(info, index.HalfInfo) else None
    for name in (map, against):
        index.lookup(name).check_params(params)  # ValueError naming the requirement, before any work
    options = one_step_options(index.lookup(map), dict(options or {}))
    against_options = one_step_options(index.lookup(against), dict(against_options or {}))
    if touchdown is not None:
        if apex_height is not None or apex_speed is not None or touchdown_angle is not None:
            raise ValueError(
                "give either an apex (height, speed, touchdown angle) or a touchdown state, not both"
            )
        td = polar_state(params, touchdown)
        if td[0] != params.q_r_td:
            params = params.with_(q_r_td=td[0])
    else:
        apex = default_apex(params)
        given = {"apex_height": apex_height, "apex_speed": apex_speed, "touchdown_angle": touchdown_angle}
        apex.update({key: value for key, value in given.items() if value is not None})
        h = non_negative("apex_height", apex["apex_height"])
        v = non_negative("apex_speed", apex["apex_speed"])
        th = leg_angle("touchdown_angle", apex["touchdown_angle"])
        status, td, _ = flight.touchdown(params, h, v, th)
        if status != Status.OK:
            message = f"{MESSAGES[int(status)]} (apex height {num(h)} m"
            message += f", touchdown height {params.q_r_td * math.cos(th):.6g} m)"
            sides = (
                _not_run(map, "half" if half else "stance", options, status, message),
                _not_run(against, "stance", against_options, status, message),
            )
            labels = _HALF_ROWS if half else tuple((q.label, q.unit, q.key) for q in QUANTITIES)
            rows = tuple(Row(label, unit, math.nan, math.nan) for label, unit, _ in labels)
            return Comparison(params, td, *sides, rows, half=half)
    ref = _side(against, params, td, against_options)
    if half:
        return _compare_half(params, td, half, ref, options, touchdown is not None)
    mine = _side(map, params, td, options)
    rows = tuple(Row(q.label, q.unit, ref.value(q.key), mine.value(q.key)) for q in QUANTITIES)
    return Comparison(params, td, mine, ref, rows, touchdown_given=touchdown is not None)


#: A half-stance map's outputs against the whole stance's: (label, unit, half key, stance keys).
_HALF_ROWS = (
    ("half time", "s", "t_half"),
    ("end leg length q_r", "m", "end_q_r"),
    ("end leg rate q_rd", "m/s", "end_q_rd"),
    ("end leg angle q_th", "rad", "end_q_th"),
    ("end angle rate q_thd", "rad/s", "end_q_thd"),
)


def _compare_half(
    params: SlipParams, td, half: index.HalfInfo, ref: Side, options: dict, touchdown_given: bool
) -> Comparison:
    """A half-stance map against the reference's same half: the compression half from the touchdown
    state against the reference's bottom; the decompression half from the reference's bottom
    state against its liftoff (so only the half itself differs)."""
    whole = ref.stance.values
    if half.start == "touchdown":
        start, t_ref = td, whole.get("t_bottom", math.nan)
    else:
        start = tuple(whole.get(f"bottom_{q}", math.nan) for q in ("q_r", "q_rd", "q_th", "q_thd"))
        t_ref = whole.get("t_stance", math.nan) - whole.get("t_bottom", math.nan)
    if half.start == "touchdown" or ref.stance.ok:
        res = half_stance(half.name, params, start, **options)
    else:  # the reference has no bottom state to start from: the half does not run
        res = Result(half.name, "half", ref.status, f"not run: {ref.stance.message}", {}, {})
    values = dict(res.values)
    mine = Side(half.name, options, res, res.status, (math.nan, math.nan))
    rows = tuple(
        Row(
            label,
            unit,
            t_ref if key == "t_half" else whole.get(f"{half.end}_{key[4:]}", math.nan),
            values.get(key, math.nan),
        )
        for label, unit, key in _HALF_ROWS
    )
    return Comparison(
        params,
        tuple(start),
        mine,
        ref,
        rows,
        half=half,
        touchdown_given=touchdown_given,
        stance_touchdown=None if half.start == "touchdown" else tuple(td),
    )


def _fmt(x: float, spec: str) -> str:
    """``x`` formatted by ``spec`` (a width first after an optional sign); n/a, right-aligned to
    that width, when it is not finite."""
    width = int(spec.lstrip("+").split(".")[0])
    return format(x, spec) if math.isfinite(x) else "n/a".rjust(width)


def _title(side: Side) -> str:
    info = index.lookup(side.map)
    opts = ", ".join(f"{k}={v}" for k, v in side.options.items())
    return f"{side.map} ({info.title}, report {info.section}{'; ' + opts if opts else ''})"


def format_table(c: Comparison) -> str:
    """The comparison as an aligned text table: a header naming the case and each side's status,
    the rows (``n/a`` where a value is missing), and under them each failed side's status and
    message."""
    p = c.params
    td = c.touchdown
    q_r_td = f"q_r_td={p.q_r_td:g} m" + (" (the touchdown state's q_r)" if c.touchdown_given else "")
    start = c.half.start if c.half else "touchdown"
    lines = [
        f"SLIP step: m={p.m:g} kg, l0={p.l0:g} m, k_c={p.k_c:g} N/m, k_d={p.k_d:g} N/m, "
        f"g_s={p.g_s:g}, g_f={p.g_f:g} m/s^2, {q_r_td}, q_r_lo={p.q_r_lo:g} m",
        f"{start}: q_r={td[0]:.6g} m, q_rd={td[1]:.6g} m/s, q_th={td[2]:.6g} rad, q_thd={td[3]:.6g} rad/s"
        if all(math.isfinite(x) for x in td)
        else f"{start}: none",
        f"reference: {_title(c.against)}: {c.against.status.name}",
        f"map:       {_title(c.map)}: {c.map.status.name}",
        "",
        f"{'quantity':<30}{'unit':>7}{'reference':>14}{'map':>14}{'abs err':>13}{'rel err':>11}",
        "-" * 89,
    ]
    for r in c.rows:
        lines.append(
            f"{r.quantity:<30}{r.unit:>7}{_fmt(r.reference, '14.6f')}{_fmt(r.value, '14.6f')}"
            f"{_fmt(r.abs_error, '+13.2e')}{_fmt(r.rel_error, '+11.2%')}"
        )
    failed = [(role, side) for role, side in (("reference", c.against), ("map", c.map)) if not side.ok]
    if failed:
        lines.append("")
    for role, side in failed:
        lines.append(f"{role} {side.map}: {side.status.name}: {side.message}")
    return "\n".join(lines)


def _mark_states(axes, t, states, events, label: str, color: str) -> None:
    """The states a map computes at its events only (no trajectory between them): a marker at each
    event on the q_r and q_th axes, named beside it, and no line joining them (a line would draw a
    path the map never computed)."""
    t, states = np.asarray(t, dtype=float), np.asarray(states, dtype=float)
    ok = np.all(np.isfinite(states), axis=1)
    last = t[ok].max(initial=-np.inf)
    for ax, j in ((axes[0], 0), (axes[1], 2)):
        ax.plot(
            t[ok], states[ok, j], ls="none", marker="o", ms=8, mfc="none", mew=2, color=color, label=label
        )
        for ti, yi, name in zip(t[ok], states[ok, j], np.asarray(events)[ok], strict=True):
            right = ti == last and ti > 0.0  # the last event's name to its left, inside the axes
            ax.annotate(
                name,
                (ti, yi),
                xytext=(-8 if right else 8, 8),
                textcoords="offset points",
                ha="right" if right else "left",
                fontsize=8,
                color=color,
            )
        ax.margins(y=0.12)


def one_step_options(info, options: dict) -> dict:
    """The options one step of ``info``'s map runs with: ``options``, except that a map with a
    ``solve_ivp`` backend (the exact map's ``method="scipy"``) runs the step, and draws its curve,
    through that backend unless a method was chosen. One stance integrates in a few milliseconds
    there, where the compiled simulator's first use on an empty numba cache compiles it for 10-15 s;
    the two agree to 1e-14 (docs/performance.md). ``--against-option method=compiled`` runs the
    compiled simulator."""
    for option in info.options:
        if option.name not in options and "scipy" in option.backends:
            return {**options, option.name: "scipy"}
    return options


def plot(c: Comparison, path: str) -> str:
    """Write a PNG of q_r(t) and q_th(t) of both stances and return its path. A map without a
    trajectory (``iterative``, ``iterative-report``, the half-stance maps) shows only the event
    states it computes, as markers labelled "event states only (no trajectory)"."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 1, figsize=(7.5, 6.5), sharex=True)
    sides = ((c.against, dict(color="k", ls="-", lw=2)), (c.map, dict(color="C1", ls="--", lw=2)))
    if c.half is not None:
        sides = sides[:1]
        if c.map.status == Status.OK:  # the half's start and end states, marked
            t0 = 0.0 if c.half.start == "touchdown" else c.against.stance.t_bottom
            t = np.array([t0, t0 + c.map.stance["t_half"]])
            states = np.array([c.touchdown, c.map.stance["end"]])
            label = f"{c.map.map}: {c.half.start} and {c.half.end} states only (no trajectory)"
            _mark_states(axes, t, states, (c.half.start, c.half.end), label, "C1")
    td = c.touchdown if c.stance_touchdown is None else c.stance_touchdown
    for side, style in sides:
        if not side.stance.ok:
            continue
        info = index.get(side.map)
        if not info.has_trajectory:
            st = side.stance
            t = np.array([0.0, st.t_bottom, st.t_stance])
            states = np.array([td, st.bottom, st.liftoff])
            label = f"{side.map}: event states only (no trajectory)"
            _mark_states(axes, t, states, ("touchdown", "bottom", "liftoff"), label, style["color"])
            continue
        label = f"{side.map} ({info.title})"
        t, states, _ = trajectory(side.map, c.params, td, **side.options)
        if t.size:
            ok = np.all(np.isfinite(states), axis=1)
            axes[0].plot(t[ok], states[ok, 0], label=label, **style)
            axes[1].plot(t[ok], states[ok, 2], label=label, **style)
    axes[0].set_ylabel("leg length q_r [m]")
    axes[1].set_ylabel("leg angle q_th [rad]")
    axes[1].set_xlabel("time since touchdown [s]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        if ax.get_legend_handles_labels()[0]:  # nothing to label when neither side ran
            ax.legend(loc="best", fontsize=8)
    p = c.params
    axes[0].set_title(
        f"SLIP stance: m={p.m:g} kg, l0={p.l0:g} m, "
        + (f"k={p.k_c:g} N/m" if p.constant_stiffness else f"k_c={p.k_c:g}, k_d={p.k_d:g} N/m")
        + f", q_th_td={td[2]:.3f} rad"
    )
    fig.tight_layout()
    save_figure(fig, path)
    return path
