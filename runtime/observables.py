"""The quantities by which an approximate step is compared with the exact one (one definition).

Used by the comparison job (:mod:`.compare`) and the accuracy table (:mod:`.accuracy`). Keys:
stance time, bottom time, bottom leg length and angle, liftoff leg rate, angle and angle rate,
next apex height and speed (SI units; times from touchdown).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .simulate import StepResult
from .stance_maps import StanceMapResult

__all__ = ["Quantity", "QUANTITIES", "exact_values", "approx_values"]

_NAN4 = (math.nan,) * 4


@dataclass(frozen=True)
class Quantity:
    """One compared quantity. ``rel_scale`` names the scale of its relative error in the accuracy
    table ("self": the exact value; "compression": l0 - exact q_r_b; "sweep": |exact q_th - q_th_td|)."""

    key: str
    label: str
    unit: str
    rel_scale: str


#: The compared quantities, in table order.
QUANTITIES: tuple[Quantity, ...] = (
    Quantity("t_stance", "stance time t_s", "s", "self"),
    Quantity("t_bottom", "bottom time t_b", "s", "self"),
    Quantity("b_q_r", "bottom leg length q_r_b", "m", "compression"),
    Quantity("b_q_th", "bottom leg angle q_th_b", "rad", "sweep"),
    Quantity("lo_q_rd", "liftoff leg rate q_rd_lo", "m/s", "self"),
    Quantity("lo_q_th", "liftoff leg angle q_th_lo", "rad", "sweep"),
    Quantity("lo_q_thd", "liftoff angle rate q_thd_lo", "rad/s", "self"),
    Quantity("apex_height", "next apex height", "m", "self"),
    Quantity("apex_speed", "next apex speed", "m/s", "self"),
)


def _values(t_stance, t_bottom, bottom, liftoff, next_apex) -> dict[str, float]:
    bottom = bottom or _NAN4
    liftoff = liftoff or _NAN4
    return {
        "t_stance": float(t_stance),
        "t_bottom": float(t_bottom),
        "b_q_r": float(bottom[0]),
        "b_q_th": float(bottom[2]),
        "lo_q_rd": float(liftoff[1]),
        "lo_q_th": float(liftoff[2]),
        "lo_q_thd": float(liftoff[3]),
        "apex_height": float(next_apex[0]),
        "apex_speed": float(next_apex[1]),
    }


def exact_values(step: StepResult) -> dict[str, float]:
    """The quantities of an exact step (NaN where a stage was not reached)."""
    return _values(step.t_stance, step.t_bottom, step.bottom, step.liftoff, step.next_apex)


def approx_values(stance: StanceMapResult | None, next_apex: tuple[float, float]) -> dict[str, float]:
    """The quantities of an approximate stance map result and the next apex it leads to."""
    if stance is None:
        return _values(math.nan, math.nan, None, None, next_apex)
    return _values(stance.t_stance, stance.t_bottom, stance.bottom, stance.liftoff, next_apex)
