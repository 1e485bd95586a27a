"""Approximate stance maps on the generated kernels: touchdown state -> bottom and liftoff states.

Conventions (README): polar stance state ``(q_r, q_rd, q_th, q_thd)`` in m, m/s, rad, rad/s, leg
angle from the vertical, counterclockwise positive, body at (-q_r sin q_th, q_r cos q_th) from the
toe. Times are measured from touchdown.

``geyer_stance`` is Geyer et al.'s map (report section 3.1, eqs 7-20, corrected forms of 23-26 in
docs/equations.md): a touchdown state maps to the bottom and the liftoff at leg length
``params.q_r_lo``. It assumes a constant stiffness (``k_c == k_d``; ValueError otherwise).
Inputs are validated here (ValueError naming the value); a state outside the map's domain is a
result with a :class:`~slipmaps.generated.status.Status` code and message, never an exception.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from slipmaps.generated import geyer as gen_geyer
from slipmaps.generated.status import MESSAGES, Status

from .params import SlipParams
from .validate import PolarState, broadcast_params, check_params, check_range, float_array, polar_state

__all__ = [
    "StanceMapResult",
    "geyer_stance",
    "geyer_stance_batch",
    "geyer_stance_trajectory",
    "STANCE_COLUMNS",
]

#: Column order of :func:`geyer_stance_batch`'s output (the generated kernel's outputs).
STANCE_COLUMNS = (
    "t_bottom",
    "t_stance",
    "b_q_r",
    "b_q_rd",
    "b_q_th",
    "b_q_thd",
    "lo_q_r",
    "lo_q_rd",
    "lo_q_th",
    "lo_q_thd",
)


@dataclass(frozen=True)
class StanceMapResult:
    """Output of an approximate stance map (NaN fields unless ``status`` is OK)."""

    status: Status
    message: str
    touchdown: PolarState
    bottom: PolarState
    liftoff: PolarState
    t_bottom: float
    t_stance: float

    @property
    def ok(self) -> bool:
        return self.status == Status.OK


def _params_tuple(params: SlipParams) -> tuple[float, float, float, float]:
    return (params.m, params.l0, params.k, params.g_s)


def geyer_stance(params: SlipParams, touchdown) -> StanceMapResult:
    """Geyer et al.'s approximate stance map (eqs 7-20) from a polar touchdown state."""
    params = check_params(params)
    td = polar_state(params, touchdown)
    res = gen_geyer.geyer_stance(*td, *_params_tuple(params), params.q_r_lo)
    status = Status(res[-1])
    return StanceMapResult(
        status=status,
        message=MESSAGES[int(status)],
        touchdown=td,
        bottom=tuple(res[2:6]),
        liftoff=tuple(res[6:10]),
        t_bottom=res[0],
        t_stance=res[1],
    )


def _touchdown_arrays(params: SlipParams, touchdowns) -> list[np.ndarray]:
    arr = np.asarray(touchdowns, dtype=float)
    if arr.ndim != 2 or arr.shape[1] != 4:
        raise ValueError(f"touchdowns must have shape (n, 4) (q_r, q_rd, q_th, q_thd), got {arr.shape}")
    cols = [float_array(f"touchdowns[:, {j}]", arr[:, j]) for j in range(4)]
    check_range(
        "touchdowns[:, 0] (q_r)", cols[0], (cols[0] > 0) & (cols[0] <= params.l0), f"0 < q_r <= {params.l0}"
    )
    check_range("touchdowns[:, 2] (q_th)", cols[2], np.abs(cols[2]) < math.pi / 2, "|q_th| < pi/2")
    return cols


def geyer_stance_batch(params: SlipParams, touchdowns) -> tuple[np.ndarray, np.ndarray]:
    """Geyer's map for many touchdown states at once, in parallel.

    ``touchdowns`` has shape (n, 4). Returns ``(out, status)``: ``out`` (n, 10) float64 in the order
    of :data:`STANCE_COLUMNS` (NaN rows where ``status != 0``) and ``status`` (n,) int64 codes.
    """
    params = check_params(params)
    cols = _touchdown_arrays(params, touchdowns)
    n = cols[0].shape[0]
    prm = broadcast_params(n, *_params_tuple(params), params.q_r_lo)
    out = np.empty((n, len(STANCE_COLUMNS)))
    status = np.empty(n, dtype=np.int64)
    gen_geyer.geyer_stance_batch(*cols, *prm, out, status)
    return out, status


def geyer_stance_trajectory(params: SlipParams, touchdown, t) -> tuple[np.ndarray, Status]:
    """The approximate stance trajectory (eqs 11, 17, 19) at times ``t`` after touchdown.

    Returns ``(states, status)`` with ``states`` of shape (4, len(t)): q_r, q_rd, q_th, q_thd.
    """
    params = check_params(params)
    td = polar_state(params, touchdown)
    times = float_array("t", np.atleast_1d(t))
    n = times.shape[0]
    args = broadcast_params(n, *td, *_params_tuple(params))
    out = np.empty((n, 4))
    status = np.empty(n, dtype=np.int64)
    gen_geyer.geyer_stance_state_at_batch(times, *args, out, status)
    return out.T.copy(), Status(int(status[0]) if n else 0)
