"""Exact derivatives of the exact apex-return map: flights composed with the exact stance's.

One step (:func:`.compiled.step_into`) is apex -> touchdown (ballistic, generated kernel
``flight.apex_to_touchdown``) -> stance (integrated) -> liftoff -> next apex (ballistic,
``flight.liftoff_to_apex``). Its Jacobian with respect to :data:`INPUTS` (apex height, apex speed,
touchdown angle, k_c, k_d) is the chain rule over the three:

* the flights' derivatives are their generated JVP kernels (``generated/flight_jacobian.py``,
  forward-mode differentiation of the derived flight maps): the touchdown event of the descent is
  solved in closed form there, so its derivative is exact (it plays the part of the touchdown
  saltation); the descent's values and checks are the step's (:func:`.compiled.descent`);
* the stance's is :func:`.jacobian.jacobian_into` (variational equations with saltation at
  the bottom and the map to the liftoff surface).

Rows: the apex-return outputs of the index (:data:`OUTPUTS`: next apex height and speed, descent,
stance and ascent times, the liftoff state). SI units per unit input (per N/m for k_c and k_d).
NaN and the step's status unless OK.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange
from slipmaps.generated.flight_jacobian import (
    apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td as descent_jvp,
)
from slipmaps.generated.flight_jacobian import liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd as ascent_jvp

from ..api.results import columns
from . import compiled as ec
from . import jacobian as ej

__all__ = ["INPUTS", "OUTPUTS", "step_jacobian_into", "step_jacobian_batch"]

#: Rows: the apex-return outputs of every map.
OUTPUTS = columns("apex_return")
#: Columns: the apex, the touchdown angle, then the stiffnesses (named as in the public API).
INPUTS = ("apex_height", "apex_speed", "touchdown_angle", "k_c", "k_d")
N_OUT, N_IN = len(OUTPUTS), len(INPUTS)
N_APEX = 3  # the columns the flights see: apex height, apex speed, touchdown angle
_ROW = {n: i for i, n in enumerate(OUTPUTS)}
APEX_HEIGHT, APEX_SPEED = _ROW["apex_height"], _ROW["apex_speed"]
T_DESCENT, T_STANCE, T_ASCENT = _ROW["t_descent"], _ROW["t_stance"], _ROW["t_ascent"]
LIFTOFF = _ROW["liftoff_q_r"]
# Stance Jacobian columns (jacobian.INPUTS): the touchdown state, then k_c, k_d.
_S_TD = ej.TOUCHDOWN
_S_K = (ej.K_C, ej.K_D)
_K = (INPUTS.index("k_c"), INPUTS.index("k_d"))


@njit(cache=True, error_model="numpy")
def step_jacobian_into(h, v, th, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, t_max, out, jac):
    """One exact step (the :data:`OUTPUTS` row into ``out``) and d(OUTPUTS)/d(INPUTS) into ``jac``
    (N_OUT x N_IN); NaN unless OK; returns the status (that of :func:`.compiled.step_into`)."""
    for i in range(N_OUT):
        out[i] = math.nan
        for j in range(N_IN):
            jac[i, j] = math.nan
    q_r0, q_rd0, q_th0, q_thd0, t_descent, code = ec.descent(h, v, th, q_r_td, g_f)
    if code != ec.OK:
        return code
    # d(touchdown state, t_descent) / d(h, v, th): one JVP per direction
    d_td = np.empty((4, N_APEX))
    d_t_descent = np.empty(N_APEX)
    for j in range(N_APEX):
        seed = (1.0 if j == 0 else 0.0, 1.0 if j == 1 else 0.0, 1.0 if j == 2 else 0.0)
        _, _, _, _, _, d_q_r, d_q_rd, d_q_th, d_q_thd, d_t, code = descent_jvp(h, v, th, q_r_td, g_f, *seed)
        if code != ec.OK:
            return code
        d_td[0, j], d_td[1, j], d_td[2, j], d_td[3, j], d_t_descent[j] = d_q_r, d_q_rd, d_q_th, d_q_thd, d_t
    stance = np.empty(ej.N_OUT)
    s_jac = np.empty((ej.N_OUT, ej.N_IN))
    code = ej.jacobian_into(
        q_r0, q_rd0, q_th0, q_thd0, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, stance, s_jac
    )
    if code != ec.OK:
        return code
    lo = np.empty(4)
    for i in range(4):
        lo[i] = stance[ej.LIFTOFF + i]
    lo_t = (lo[0], lo[1], lo[2], lo[3])
    # d(liftoff state, t_stance) / d(INPUTS): the stance Jacobian times the descent's
    d_lo = np.zeros((5, N_IN))  # rows: liftoff q_r, q_rd, q_th, q_thd, then t_stance
    rows = (ej.LIFTOFF, ej.LIFTOFF + 1, ej.LIFTOFF + 2, ej.LIFTOFF + 3, ej.T_STANCE)
    for a in range(5):
        for j in range(N_APEX):
            acc = 0.0
            for b in range(4):
                acc += s_jac[rows[a], _S_TD[b]] * d_td[b, j]
            d_lo[a, j] = acc
        for c in range(2):
            d_lo[a, _K[c]] = s_jac[rows[a], _S_K[c]]
    # d(next apex height, speed, t_ascent) / d(liftoff state): one JVP per direction
    d_asc = np.empty((3, 4))
    apex_height = apex_speed = t_ascent = math.nan
    for b in range(4):
        seed = (
            1.0 if b == 0 else 0.0,
            1.0 if b == 1 else 0.0,
            1.0 if b == 2 else 0.0,
            1.0 if b == 3 else 0.0,
        )
        apex_height, apex_speed, t_ascent, _, d_y, d_xd, d_t, _, code = ascent_jvp(*lo_t, g_f, *seed)
        if code != ec.OK:
            return code
        d_asc[0, b], d_asc[1, b], d_asc[2, b] = d_y, d_xd, d_t
    out[APEX_HEIGHT] = apex_height
    out[APEX_SPEED] = apex_speed
    out[T_DESCENT] = t_descent
    out[T_STANCE] = stance[ej.T_STANCE]
    out[T_ASCENT] = t_ascent
    for i in range(4):
        out[LIFTOFF + i] = lo[i]
    targets = (APEX_HEIGHT, APEX_SPEED, T_ASCENT)
    for j in range(N_IN):
        for a in range(3):
            acc = 0.0
            for b in range(4):
                acc += d_asc[a, b] * d_lo[b, j]
            jac[targets[a], j] = acc
        jac[T_DESCENT, j] = d_t_descent[j] if j < N_APEX else 0.0
        jac[T_STANCE, j] = d_lo[4, j]
        for i in range(4):
            jac[LIFTOFF + i, j] = d_lo[i, j]
    return ec.OK


@njit(cache=True, parallel=True, error_model="numpy")
def step_jacobian_batch(
    h, v, th, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, t_max, out, jac, status
):
    """:func:`step_jacobian_into` over rows in parallel: out (n, N_OUT), jac (n, N_OUT, N_IN), status (n,)."""
    for i in prange(out.shape[0]):
        status[i] = step_jacobian_into(
            h[i], v[i], th[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, t_max, out[i], jac[i]
        )
