"""The main job: one SLIP step, exact (``solve_ivp``) versus Geyer et al.'s approximate stance map.

Both sides start from the same touchdown state (reached from an apex by exact ballistic flight,
or given directly) and fly from their own liftoff to the next apex exactly; only the stance
differs. :func:`compare` returns the rows of the table (quantity, unit, exact, approximate,
absolute and relative error); :func:`format_table` prints them and :func:`plot` draws q_r(t) and
q_th(t) of both stances.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np
from slipmaps.generated import flight as gen_flight
from slipmaps.generated.status import MESSAGES, Status

from .observables import QUANTITIES, approx_values, exact_values
from .params import SlipParams
from .simulate import StepResult, simulate_from_touchdown, simulate_step
from .stance_maps import geyer_stance, geyer_stance_trajectory

__all__ = ["Row", "Comparison", "compare", "format_table", "plot", "DEFAULT_APEX"]

#: The documented default case: apex 1.0 m high at 5 m/s, touchdown angle 0.35 rad (about 20 deg).
DEFAULT_APEX = {"apex_height": 1.0, "apex_speed": 5.0, "q_th_td": 0.35}


@dataclass(frozen=True)
class Row:
    quantity: str
    unit: str
    exact: float
    approx: float

    @property
    def abs_error(self) -> float:
        return self.approx - self.exact

    @property
    def rel_error(self) -> float:
        return self.abs_error / abs(self.exact) if self.exact != 0.0 else math.nan


@dataclass(frozen=True)
class Comparison:
    params: SlipParams
    touchdown: tuple[float, float, float, float]
    exact_status: Status
    approx_status: Status
    rows: tuple[Row, ...]
    exact: StepResult
    approx_t_stance: float

    def to_dict(self) -> dict:
        return {
            "params": asdict(self.params),
            "touchdown": dict(zip(("q_r", "q_rd", "q_th", "q_thd"), self.touchdown, strict=True)),
            "exact_status": self.exact_status.name,
            "exact_message": MESSAGES[int(self.exact_status)],
            "approx_status": self.approx_status.name,
            "approx_message": MESSAGES[int(self.approx_status)],
            "rows": [
                {
                    "quantity": r.quantity,
                    "unit": r.unit,
                    "exact": _json_float(r.exact),
                    "approx": _json_float(r.approx),
                    "abs_error": _json_float(r.abs_error),
                    "rel_error": _json_float(r.rel_error),
                }
                for r in self.rows
            ],
        }


def _json_float(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def compare(
    params: SlipParams,
    *,
    apex_height: float | None = None,
    apex_speed: float | None = None,
    q_th_td: float | None = None,
    touchdown=None,
) -> Comparison:
    """Run one step both ways, from an apex (height, speed, touchdown angle) or a touchdown state."""
    params.k  # noqa: B018 - Geyer's map needs k_c == k_d; raises ValueError with both values otherwise
    if touchdown is not None:
        if apex_height is not None or apex_speed is not None or q_th_td is not None:
            raise ValueError(
                "give either an apex (height, speed, touchdown angle) or a touchdown state, not both"
            )
        exact = simulate_from_touchdown(params, touchdown, dense=True)
    else:
        apex = {**DEFAULT_APEX}
        for key, value in (("apex_height", apex_height), ("apex_speed", apex_speed), ("q_th_td", q_th_td)):
            if value is not None:
                apex[key] = value
        exact = simulate_step(params, apex["apex_height"], apex["apex_speed"], apex["q_th_td"], dense=True)
    if exact.touchdown is None:
        raise ValueError(f"no touchdown: {exact.message}")
    td = tuple(exact.touchdown)
    approx = geyer_stance(params, td)
    if approx.ok:
        up = gen_flight.liftoff_to_apex(*approx.liftoff, params.g_f)
        approx_status = Status(up[-1])
        next_apex = (up[0], up[1])
    else:
        approx_status, next_apex = approx.status, (math.nan, math.nan)
    ex_vals, ap_vals = exact_values(exact), approx_values(approx, next_apex)
    rows = tuple(Row(q.label, q.unit, ex_vals[q.key], ap_vals[q.key]) for q in QUANTITIES)
    return Comparison(params, td, exact.status, approx_status, rows, exact, approx.t_stance)


def _fmt(x: float, spec: str) -> str:
    return format(x, spec) if math.isfinite(x) else "n/a"


def format_table(c: Comparison) -> str:
    """The comparison as an aligned text table with a header naming the case."""
    p = c.params
    td = c.touchdown
    lines = [
        f"SLIP step: m={p.m:g} kg, l0={p.l0:g} m, k_c={p.k_c:g} N/m, k_d={p.k_d:g} N/m, "
        f"g_s={p.g_s:g}, g_f={p.g_f:g} m/s^2, q_r_td={p.q_r_td:g} m, q_r_lo={p.q_r_lo:g} m",
        f"touchdown: q_r={td[0]:.6g} m, q_rd={td[1]:.6g} m/s, q_th={td[2]:.6g} rad, q_thd={td[3]:.6g} rad/s",
        f"exact (solve_ivp DOP853, rtol=1e-11): {MESSAGES[int(c.exact_status)]}; "
        f"approximate (Geyer et al., report 3.1): {MESSAGES[int(c.approx_status)]}",
        "",
        f"{'quantity':<30}{'unit':>7}{'exact':>14}{'approx':>14}{'abs err':>13}{'rel err':>11}",
        "-" * 89,
    ]
    for r in c.rows:
        lines.append(
            f"{r.quantity:<30}{r.unit:>7}{_fmt(r.exact, '14.6f')}{_fmt(r.approx, '14.6f')}"
            f"{_fmt(r.abs_error, '+13.2e')}{_fmt(r.rel_error, '+11.2%')}"
        )
    return "\n".join(lines)


def plot(c: Comparison, path: str) -> str:
    """Write a PNG of q_r(t) and q_th(t), exact vs approximate, and return its path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ex = c.exact.stance
    fig, axes = plt.subplots(2, 1, figsize=(7.5, 6.5), sharex=True)
    if ex is not None and ex.t is not None:
        axes[0].plot(ex.t, ex.states[0], "k-", lw=2, label="exact (solve_ivp)")
        axes[1].plot(ex.t, ex.states[2], "k-", lw=2, label="exact (solve_ivp)")
    if math.isfinite(c.approx_t_stance):
        t = np.linspace(0.0, c.approx_t_stance, 400)
        states, _ = geyer_stance_trajectory(c.params, c.touchdown, t)
        axes[0].plot(t, states[0], "C1--", lw=2, label="Geyer et al. (approx.)")
        axes[1].plot(t, states[2], "C1--", lw=2, label="Geyer et al. (approx.)")
    axes[0].set_ylabel("leg length q_r [m]")
    axes[1].set_ylabel("leg angle q_th [rad]")
    axes[1].set_xlabel("time since touchdown [s]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best")
    p = c.params
    axes[0].set_title(
        f"SLIP stance: m={p.m:g} kg, l0={p.l0:g} m, k={p.k_c:g} N/m, q_th_td={c.touchdown[2]:.3f} rad"
    )
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
