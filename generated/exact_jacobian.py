# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/exact.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:cd017e56afa49b84
#   exact_stance.py sha256:299560de25340ae1
#   flight_jacobian.py sha256:138a95b59cb50fe8
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module exact: JVP kernels, and for a map
its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import fail, finite, into_rows, row, stack
from .exact_stance import stance_jacobian
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate,
    liftoff_to_apex_jac_q_r_q_rd_q_th_q_thd)

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan


@njit(cache=True, error_model="numpy")
def exact_stance_jacobian(x, p, out):
    """Exact stance by numerical integration (DOP853): stance outputs and their derivatives with respect to
    the touchdown state and the stiffness.

    Report equations: 1, 2, 3, 27.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol); writes the outputs below into out, in order,
    and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`exact.exact_stance`, in its order.

    Writes into out:
        <output>: each output of :func:`exact.exact_stance`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol) = (p[0], p[1], p[2], p[3], p[4], p[7], p[8], p[9])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) & math.isfinite(q_rd_td) & math.isfinite(q_th_td) & math.isfinite(q_thd_td)
            & math.isfinite(m) & math.isfinite(l0) & math.isfinite(k_c) & math.isfinite(k_d)
            & math.isfinite(g_s) & math.isfinite(q_r_lo) & math.isfinite(rtol) & math.isfinite(atol)
            & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0
            > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))
            & ((rtol >= 1e-14) and (rtol <= 0.001)) & ((atol >= 1e-16) and (atol <= 0.001))):
        return fail(out, STATUS_INVALID_INPUT)
    # the exact stance (exact_stance)
    _o0 = carray(stack(70), 70)
    _c0 = stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    # every output finite, or the inputs were far outside a physical range
    (out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8], out[9], out[10], out[11],
        out[12], out[13], out[14], out[15], out[16], out[17], out[18], out[19], out[20], out[21], out[22],
        out[23], out[24], out[25], out[26], out[27], out[28], out[29], out[30], out[31], out[32], out[33],
        out[34], out[35], out[36], out[37], out[38], out[39], out[40], out[41], out[42], out[43], out[44],
        out[45], out[46], out[47], out[48], out[49], out[50], out[51], out[52], out[53], out[54], out[55],
        out[56], out[57], out[58], out[59], out[60], out[61], out[62], out[63], out[64], out[65], out[66],
        out[67], out[68], out[69],) = (_o0[0], _o0[1], _o0[2], _o0[3], _o0[4], _o0[5], _o0[6], _o0[7], _o0[8],
        _o0[9], _o0[10], _o0[11], _o0[12], _o0[13], _o0[14], _o0[15], _o0[16], _o0[17], _o0[18], _o0[19],
        _o0[20], _o0[21], _o0[22], _o0[23], _o0[24], _o0[25], _o0[26], _o0[27], _o0[28], _o0[29], _o0[30],
        _o0[31], _o0[32], _o0[33], _o0[34], _o0[35], _o0[36], _o0[37], _o0[38], _o0[39], _o0[40], _o0[41],
        _o0[42], _o0[43], _o0[44], _o0[45], _o0[46], _o0[47], _o0[48], _o0[49], _o0[50], _o0[51], _o0[52],
        _o0[53], _o0[54], _o0[55], _o0[56], _o0[57], _o0[58], _o0[59], _o0[60], _o0[61], _o0[62], _o0[63],
        _o0[64], _o0[65], _o0[66], _o0[67], _o0[68], _o0[69],)
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def exact_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`exact_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = exact_stance_jacobian(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def exact_apex_return_jacobian(x, p, out):
    """Apex-return map by Exact stance by numerical integration (DOP853), and its derivatives with respect to
    the apex, the touchdown angle and the stiffness.

    Report equations: 1, 2, 3, 27.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol); writes the outputs below into out, in order,
    and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`exact.exact_apex_return`, in its order.

    Writes into out:
        <output>: each output of :func:`exact.exact_apex_return`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 320
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) = (x[0], x[1], x[2], x[3], x[4])
    (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7],
        p[8], p[9])
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) & math.isfinite(b_xd_apex) & math.isfinite(q_th_td)
            & math.isfinite(ground) & math.isfinite(retraction_rate) & math.isfinite(m) & math.isfinite(l0)
            & math.isfinite(k_c) & math.isfinite(k_d) & math.isfinite(g_s) & math.isfinite(g_f)
            & math.isfinite(q_r_td) & math.isfinite(q_r_lo) & math.isfinite(rtol) & math.isfinite(atol)
            & ((b_y_apex >= 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c
            > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0))
            & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((rtol >= 1e-14) and (rtol <= 0.001)) & ((atol >= 1e-16)
            and (atol <= 0.001))):
        return fail(out, STATUS_INVALID_INPUT)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _o0 = carray(stack(36), 36)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate(b_y_apex, b_xd_apex,
        q_th_td, q_r_td, g_f, ground, retraction_rate, _o0))
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    foot_x = _o0[5]
    _j_td_q_rd__b_y_apex = _o0[11]
    _j_td_q_rd__b_xd_apex = _o0[12]
    _j_td_q_rd__q_th_td = _o0[13]
    _j_td_q_rd__ground = _o0[14]
    _j_td_q_rd__retraction_rate = _o0[15]
    _j_td_q_th__b_y_apex = _o0[16]
    _j_td_q_th__q_th_td = _o0[18]
    _j_td_q_th__ground = _o0[19]
    _j_td_q_th__retraction_rate = _o0[20]
    _j_td_q_thd__b_y_apex = _o0[21]
    _j_td_q_thd__b_xd_apex = _o0[22]
    _j_td_q_thd__q_th_td = _o0[23]
    _j_td_q_thd__ground = _o0[24]
    _j_td_q_thd__retraction_rate = _o0[25]
    _j_foot_x__b_y_apex = _o0[31]
    _j_foot_x__b_xd_apex = _o0[32]
    _j_foot_x__q_th_td = _o0[33]
    _j_foot_x__ground = _o0[34]
    _j_foot_x__retraction_rate = _o0[35]
    # stance: Exact stance by numerical integration (DOP853)
    _x1 = carray(stack(4), 4)
    (_x1[0], _x1[1], _x1[2], _x1[3],) = (_o0[0], _o0[1], _o0[2], _o0[3],)
    _o1 = carray(stack(70), 70)
    _c1 = exact_stance_jacobian(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    liftoff_q_r = _o1[6]
    liftoff_q_rd = _o1[7]
    liftoff_q_th = _o1[8]
    liftoff_q_thd = _o1[9]
    _j_t_stance__q_rd_td = _o1[17]
    _j_t_stance__q_th_td = _o1[18]
    _j_t_stance__q_thd_td = _o1[19]
    _j_liftoff_q_r__q_rd_td = _o1[47]
    _j_liftoff_q_r__q_th_td = _o1[48]
    _j_liftoff_q_r__q_thd_td = _o1[49]
    _j_liftoff_q_r__k_c = _o1[50]
    _j_liftoff_q_r__k_d = _o1[51]
    _j_liftoff_q_rd__q_rd_td = _o1[53]
    _j_liftoff_q_rd__q_th_td = _o1[54]
    _j_liftoff_q_rd__q_thd_td = _o1[55]
    _j_liftoff_q_rd__k_c = _o1[56]
    _j_liftoff_q_rd__k_d = _o1[57]
    _j_liftoff_q_th__q_rd_td = _o1[59]
    _j_liftoff_q_th__q_th_td = _o1[60]
    _j_liftoff_q_th__q_thd_td = _o1[61]
    _j_liftoff_q_th__k_c = _o1[62]
    _j_liftoff_q_th__k_d = _o1[63]
    _j_liftoff_q_thd__q_rd_td = _o1[65]
    _j_liftoff_q_thd__q_th_td = _o1[66]
    _j_liftoff_q_thd__q_thd_td = _o1[67]
    _j_liftoff_q_thd__k_c = _o1[68]
    _j_liftoff_q_thd__k_d = _o1[69]
    # chain rule through exact_stance
    d_t_stance__b_y_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_t_stance__q_th_td*_j_td_q_th__b_y_apex + _j_t_stance__q_thd_td*_j_td_q_thd__b_y_apex)
    d_t_stance__b_xd_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_t_stance__q_th_td = (_j_t_stance__q_rd_td*_j_td_q_rd__q_th_td + _j_t_stance__q_th_td*_j_td_q_th__q_th_td
        + _j_t_stance__q_thd_td*_j_td_q_thd__q_th_td)
    d_t_stance__ground = (_j_t_stance__q_rd_td*_j_td_q_rd__ground + _j_t_stance__q_th_td*_j_td_q_th__ground
        + _j_t_stance__q_thd_td*_j_td_q_thd__ground)
    d_t_stance__retraction_rate = (_j_t_stance__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_t_stance__q_th_td*_j_td_q_th__retraction_rate
        + _j_t_stance__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_r__b_y_apex = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_r__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_r__b_xd_apex = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_r__q_th_td = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_r__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_r__ground = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_r__q_th_td*_j_td_q_th__ground + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_r__retraction_rate = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_r__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_rd__b_y_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_rd__b_xd_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_rd__ground = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__ground + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_rd__retraction_rate = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_th__b_y_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_th__b_xd_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_th__ground = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__ground + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_th__retraction_rate = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_thd__b_y_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_thd__b_xd_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_thd__ground = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__ground + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_thd__retraction_rate = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__retraction_rate)
    # liftoff -> next apex: exact ballistic ascent
    _o2 = carray(stack(25), 25)
    _c2 = (liftoff_to_apex_jac_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        g_f, direction, _o2))
    if _c2 != STATUS_OK:
        return fail(out, _c2)
    next_apex_x = _o2[4]
    _j_apex_height__q_r = _o2[5]
    _j_apex_height__q_rd = _o2[6]
    _j_apex_height__q_th = _o2[7]
    _j_apex_height__q_thd = _o2[8]
    _j_apex_speed__q_r = _o2[9]
    _j_apex_speed__q_rd = _o2[10]
    _j_apex_speed__q_th = _o2[11]
    _j_apex_speed__q_thd = _o2[12]
    _j_t_ascent__q_r = _o2[13]
    _j_t_ascent__q_rd = _o2[14]
    _j_t_ascent__q_th = _o2[15]
    _j_t_ascent__q_thd = _o2[16]
    _j_next_apex_x__q_r = _o2[21]
    _j_next_apex_x__q_rd = _o2[22]
    _j_next_apex_x__q_th = _o2[23]
    _j_next_apex_x__q_thd = _o2[24]
    # chain rule through liftoff_to_apex
    d_apex_height__b_y_apex = (_j_apex_height__q_r*d_liftoff_q_r__b_y_apex
        + _j_apex_height__q_rd*d_liftoff_q_rd__b_y_apex + _j_apex_height__q_th*d_liftoff_q_th__b_y_apex
        + _j_apex_height__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_height__b_xd_apex = (_j_apex_height__q_r*d_liftoff_q_r__b_xd_apex
        + _j_apex_height__q_rd*d_liftoff_q_rd__b_xd_apex + _j_apex_height__q_th*d_liftoff_q_th__b_xd_apex
        + _j_apex_height__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_height__q_th_td = (_j_apex_height__q_r*d_liftoff_q_r__q_th_td
        + _j_apex_height__q_rd*d_liftoff_q_rd__q_th_td + _j_apex_height__q_th*d_liftoff_q_th__q_th_td
        + _j_apex_height__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_height__ground = (_j_apex_height__q_r*d_liftoff_q_r__ground
        + _j_apex_height__q_rd*d_liftoff_q_rd__ground + _j_apex_height__q_th*d_liftoff_q_th__ground
        + _j_apex_height__q_thd*d_liftoff_q_thd__ground)
    d_apex_height__retraction_rate = (_j_apex_height__q_r*d_liftoff_q_r__retraction_rate
        + _j_apex_height__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_apex_height__q_th*d_liftoff_q_th__retraction_rate
        + _j_apex_height__q_thd*d_liftoff_q_thd__retraction_rate)
    d_apex_height__k_c = (_j_apex_height__q_r*_j_liftoff_q_r__k_c + _j_apex_height__q_rd*_j_liftoff_q_rd__k_c
        + _j_apex_height__q_th*_j_liftoff_q_th__k_c + _j_apex_height__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_height__k_d = (_j_apex_height__q_r*_j_liftoff_q_r__k_d + _j_apex_height__q_rd*_j_liftoff_q_rd__k_d
        + _j_apex_height__q_th*_j_liftoff_q_th__k_d + _j_apex_height__q_thd*_j_liftoff_q_thd__k_d)
    d_apex_speed__b_y_apex = (_j_apex_speed__q_r*d_liftoff_q_r__b_y_apex
        + _j_apex_speed__q_rd*d_liftoff_q_rd__b_y_apex + _j_apex_speed__q_th*d_liftoff_q_th__b_y_apex
        + _j_apex_speed__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_speed__b_xd_apex = (_j_apex_speed__q_r*d_liftoff_q_r__b_xd_apex
        + _j_apex_speed__q_rd*d_liftoff_q_rd__b_xd_apex + _j_apex_speed__q_th*d_liftoff_q_th__b_xd_apex
        + _j_apex_speed__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_speed__q_th_td = (_j_apex_speed__q_r*d_liftoff_q_r__q_th_td
        + _j_apex_speed__q_rd*d_liftoff_q_rd__q_th_td + _j_apex_speed__q_th*d_liftoff_q_th__q_th_td
        + _j_apex_speed__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_speed__ground = (_j_apex_speed__q_r*d_liftoff_q_r__ground
        + _j_apex_speed__q_rd*d_liftoff_q_rd__ground + _j_apex_speed__q_th*d_liftoff_q_th__ground
        + _j_apex_speed__q_thd*d_liftoff_q_thd__ground)
    d_apex_speed__retraction_rate = (_j_apex_speed__q_r*d_liftoff_q_r__retraction_rate
        + _j_apex_speed__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_apex_speed__q_th*d_liftoff_q_th__retraction_rate
        + _j_apex_speed__q_thd*d_liftoff_q_thd__retraction_rate)
    d_apex_speed__k_c = (_j_apex_speed__q_r*_j_liftoff_q_r__k_c + _j_apex_speed__q_rd*_j_liftoff_q_rd__k_c
        + _j_apex_speed__q_th*_j_liftoff_q_th__k_c + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_speed__k_d = (_j_apex_speed__q_r*_j_liftoff_q_r__k_d + _j_apex_speed__q_rd*_j_liftoff_q_rd__k_d
        + _j_apex_speed__q_th*_j_liftoff_q_th__k_d + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_d)
    d_t_ascent__b_y_apex = (_j_t_ascent__q_r*d_liftoff_q_r__b_y_apex
        + _j_t_ascent__q_rd*d_liftoff_q_rd__b_y_apex + _j_t_ascent__q_th*d_liftoff_q_th__b_y_apex
        + _j_t_ascent__q_thd*d_liftoff_q_thd__b_y_apex)
    d_t_ascent__b_xd_apex = (_j_t_ascent__q_r*d_liftoff_q_r__b_xd_apex
        + _j_t_ascent__q_rd*d_liftoff_q_rd__b_xd_apex + _j_t_ascent__q_th*d_liftoff_q_th__b_xd_apex
        + _j_t_ascent__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_t_ascent__q_th_td = (_j_t_ascent__q_r*d_liftoff_q_r__q_th_td + _j_t_ascent__q_rd*d_liftoff_q_rd__q_th_td
        + _j_t_ascent__q_th*d_liftoff_q_th__q_th_td + _j_t_ascent__q_thd*d_liftoff_q_thd__q_th_td)
    d_t_ascent__ground = (_j_t_ascent__q_r*d_liftoff_q_r__ground + _j_t_ascent__q_rd*d_liftoff_q_rd__ground
        + _j_t_ascent__q_th*d_liftoff_q_th__ground + _j_t_ascent__q_thd*d_liftoff_q_thd__ground)
    d_t_ascent__retraction_rate = (_j_t_ascent__q_r*d_liftoff_q_r__retraction_rate
        + _j_t_ascent__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_t_ascent__q_th*d_liftoff_q_th__retraction_rate
        + _j_t_ascent__q_thd*d_liftoff_q_thd__retraction_rate)
    d_t_ascent__k_c = (_j_liftoff_q_r__k_c*_j_t_ascent__q_r + _j_liftoff_q_rd__k_c*_j_t_ascent__q_rd
        + _j_liftoff_q_th__k_c*_j_t_ascent__q_th + _j_liftoff_q_thd__k_c*_j_t_ascent__q_thd)
    d_t_ascent__k_d = (_j_liftoff_q_r__k_d*_j_t_ascent__q_r + _j_liftoff_q_rd__k_d*_j_t_ascent__q_rd
        + _j_liftoff_q_th__k_d*_j_t_ascent__q_th + _j_liftoff_q_thd__k_d*_j_t_ascent__q_thd)
    d_next_apex_x__b_y_apex = (_j_next_apex_x__q_r*d_liftoff_q_r__b_y_apex
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__b_y_apex + _j_next_apex_x__q_th*d_liftoff_q_th__b_y_apex
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_y_apex)
    d_next_apex_x__b_xd_apex = (_j_next_apex_x__q_r*d_liftoff_q_r__b_xd_apex
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__b_xd_apex + _j_next_apex_x__q_th*d_liftoff_q_th__b_xd_apex
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_next_apex_x__q_th_td = (_j_next_apex_x__q_r*d_liftoff_q_r__q_th_td
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__q_th_td + _j_next_apex_x__q_th*d_liftoff_q_th__q_th_td
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__q_th_td)
    d_next_apex_x__ground = (_j_next_apex_x__q_r*d_liftoff_q_r__ground
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__ground + _j_next_apex_x__q_th*d_liftoff_q_th__ground
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__ground)
    d_next_apex_x__retraction_rate = (_j_next_apex_x__q_r*d_liftoff_q_r__retraction_rate
        + _j_next_apex_x__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_next_apex_x__q_th*d_liftoff_q_th__retraction_rate
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__retraction_rate)
    d_next_apex_x__k_c = (_j_liftoff_q_r__k_c*_j_next_apex_x__q_r + _j_liftoff_q_rd__k_c*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_c*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_c*_j_next_apex_x__q_thd)
    d_next_apex_x__k_d = (_j_liftoff_q_r__k_d*_j_next_apex_x__q_r + _j_liftoff_q_rd__k_d*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_d*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_d*_j_next_apex_x__q_thd)
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    d_step_length__b_y_apex = _j_foot_x__b_y_apex + d_next_apex_x__b_y_apex
    d_step_length__b_xd_apex = _j_foot_x__b_xd_apex + d_next_apex_x__b_xd_apex
    d_step_length__q_th_td = _j_foot_x__q_th_td + d_next_apex_x__q_th_td
    d_step_length__ground = _j_foot_x__ground + d_next_apex_x__ground
    d_step_length__retraction_rate = _j_foot_x__retraction_rate + d_next_apex_x__retraction_rate
    foot_y = -b_y_apex + ground
    # derivatives of the outputs
    d_liftoff_q_r__k_c = _j_liftoff_q_r__k_c
    d_liftoff_q_r__k_d = _j_liftoff_q_r__k_d
    d_liftoff_q_rd__k_c = _j_liftoff_q_rd__k_c
    d_liftoff_q_rd__k_d = _j_liftoff_q_rd__k_d
    d_liftoff_q_th__k_c = _j_liftoff_q_th__k_c
    d_liftoff_q_th__k_d = _j_liftoff_q_th__k_d
    d_liftoff_q_thd__k_c = _j_liftoff_q_thd__k_c
    d_liftoff_q_thd__k_d = _j_liftoff_q_thd__k_d
    d_step_length__k_c = d_next_apex_x__k_c
    d_step_length__k_d = d_next_apex_x__k_d
    d_foot_x__b_y_apex = _j_foot_x__b_y_apex
    d_foot_x__b_xd_apex = _j_foot_x__b_xd_apex
    d_foot_x__q_th_td = _j_foot_x__q_th_td
    d_foot_x__ground = _j_foot_x__ground
    d_foot_x__retraction_rate = _j_foot_x__retraction_rate
    d_touchdown_q_th__b_y_apex = _j_td_q_th__b_y_apex
    d_touchdown_q_th__q_th_td = _j_td_q_th__q_th_td
    d_touchdown_q_th__ground = _j_td_q_th__ground
    d_touchdown_q_th__retraction_rate = _j_td_q_th__retraction_rate
    # every output finite, or the inputs were far outside a physical range
    (out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8], out[9], out[10], out[11],
        out[12], out[13], out[14], out[15], out[16], out[17], out[18], out[19], out[20], out[21], out[22],
        out[23], out[24], out[25], out[26], out[27], out[28], out[29], out[30], out[31], out[32], out[33],
        out[34], out[35], out[36], out[37], out[38], out[39], out[40], out[41], out[42], out[43], out[44],
        out[45], out[46], out[47], out[48], out[49], out[50], out[51], out[52], out[53], out[54], out[55],
        out[56], out[57], out[58], out[59], out[60], out[61], out[62], out[63], out[64], out[65], out[66],
        out[67], out[68], out[69], out[70], out[71], out[72], out[73], out[74], out[75], out[76], out[77],
        out[78], out[79], out[80], out[81], out[82], out[83], out[84], out[85], out[86], out[87], out[88],
        out[89], out[90], out[91], out[92], out[93], out[94], out[95], out[96], out[97], out[98], out[99],
        out[100], out[101], out[102], out[103],) = (_o2[0], _o2[1], _o0[4], _o1[1], _o2[2], liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, _o0[2],
        d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground,
        d_apex_height__retraction_rate, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex,
        d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__retraction_rate,
        d_apex_speed__k_c, d_apex_speed__k_d, _o0[26], 0.0, _o0[28], _o0[29], _o0[30], 0.0, 0.0,
        d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground,
        d_t_stance__retraction_rate, _o1[20], _o1[21], d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex,
        d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__retraction_rate, d_t_ascent__k_c,
        d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td,
        d_liftoff_q_r__ground, d_liftoff_q_r__retraction_rate, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d,
        d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground,
        d_liftoff_q_rd__retraction_rate, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex,
        d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground,
        d_liftoff_q_th__retraction_rate, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex,
        d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground,
        d_liftoff_q_thd__retraction_rate, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex,
        d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground,
        d_step_length__retraction_rate, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex,
        d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__retraction_rate, 0.0, 0.0, -1.0,
        0.0, 0.0, 1.0, 0.0, 0.0, 0.0, d_touchdown_q_th__b_y_apex, 0.0, d_touchdown_q_th__q_th_td,
        d_touchdown_q_th__ground, d_touchdown_q_th__retraction_rate, 0.0, 0.0,)
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def exact_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`exact_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = exact_apex_return_jacobian(row(X, i), row(P, min(i, last)), row(OUT, i))
