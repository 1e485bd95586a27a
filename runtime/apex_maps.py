"""Apex-return maps: apex (height, speed) + touchdown angle -> next apex, exact or approximate.

Both maps share the exact ballistic flight (generated ``flight`` kernels, g_f); they differ in the
stance: :func:`apex_return_exact` integrates it with ``solve_ivp`` (:mod:`.simulate`),
:func:`apex_return_geyer` uses Geyer et al.'s map (report section 3.1) through the generated
``geyer_apex_return`` kernel, and :func:`apex_return_geyer_batch` runs that kernel in parallel
over arrays. Apex height in m above flat ground, apex speed in m/s (the runner moves in +x),
touchdown angle in rad from the vertical, counterclockwise positive (positive = toe ahead).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from slipmaps.generated import geyer as gen_geyer
from slipmaps.generated.status import MESSAGES, Status

from .params import SlipParams
from .simulate import StepResult, simulate_step
from .validate import broadcast_params, check_params, check_range, float_array, leg_angle, non_negative

__all__ = ["ApexReturn", "APEX_COLUMNS", "apex_return_exact", "apex_return_geyer", "apex_return_geyer_batch"]

#: Column order of the batch output (the generated kernel's outputs).
APEX_COLUMNS = (
    "apex_height",
    "apex_speed",
    "t_descent",
    "t_stance",
    "t_ascent",
    "lo_q_r",
    "lo_q_rd",
    "lo_q_th",
    "lo_q_thd",
)


@dataclass(frozen=True)
class ApexReturn:
    """One approximate apex-return step (NaN fields unless ``status`` is OK)."""

    status: Status
    message: str
    next_apex: tuple[float, float]  # (height [m], speed [m/s])
    t_descent: float
    t_stance: float
    t_ascent: float
    liftoff: tuple[float, float, float, float]

    @property
    def ok(self) -> bool:
        return self.status == Status.OK


def _check_apex(apex_height, apex_speed, q_th_td) -> tuple[float, float, float]:
    return (
        non_negative("apex_height", apex_height),
        non_negative("apex_speed", apex_speed),
        leg_angle("q_th_td", q_th_td),
    )


def apex_return_exact(
    params: SlipParams, apex_height, apex_speed, q_th_td, *, dense: bool = False
) -> StepResult:
    """Exact apex-return map: ballistic flight + numerically integrated stance."""
    return simulate_step(params, apex_height, apex_speed, q_th_td, dense=dense)


def apex_return_geyer(params: SlipParams, apex_height, apex_speed, q_th_td) -> ApexReturn:
    """Approximate apex-return map with Geyer et al.'s stance map (constant stiffness)."""
    params = check_params(params)
    h, v, th = _check_apex(apex_height, apex_speed, q_th_td)
    res = gen_geyer.geyer_apex_return(
        h, v, th, params.m, params.l0, params.k, params.g_s, params.g_f, params.q_r_td, params.q_r_lo
    )
    status = Status(res[-1])
    return ApexReturn(
        status=status,
        message=MESSAGES[int(status)],
        next_apex=(res[0], res[1]),
        t_descent=res[2],
        t_stance=res[3],
        t_ascent=res[4],
        liftoff=tuple(res[5:9]),
    )


def apex_return_geyer_batch(
    params: SlipParams, apex_height, apex_speed, q_th_td
) -> tuple[np.ndarray, np.ndarray]:
    """Geyer apex-return map over arrays (scalars broadcast), run in parallel by numba.

    Returns ``(out, status)``: ``out`` of shape (n, 9) in the order of :data:`APEX_COLUMNS` (NaN
    rows where ``status != 0``) and ``status`` (n,) int64 codes
    (:class:`~slipmaps.generated.status.Status`).
    """
    params = check_params(params)
    shapes = [np.shape(x) for x in (apex_height, apex_speed, q_th_td)]
    n = max((s[0] for s in shapes if len(s) == 1), default=1)
    h = float_array("apex_height", apex_height, n)
    v = float_array("apex_speed", apex_speed, n)
    th = float_array("q_th_td", q_th_td, n)
    check_range("apex_height", h, h >= 0, "apex_height >= 0")
    check_range("apex_speed", v, v >= 0, "apex_speed >= 0")
    check_range("q_th_td", th, np.abs(th) < math.pi / 2, "|q_th_td| < pi/2")
    prm = broadcast_params(
        n, params.m, params.l0, params.k, params.g_s, params.g_f, params.q_r_td, params.q_r_lo
    )
    out = np.empty((n, len(APEX_COLUMNS)))
    status = np.empty(n, dtype=np.int64)
    gen_geyer.geyer_apex_return_batch(h, v, th, *prm, out, status)
    return out, status
