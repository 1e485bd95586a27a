# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/exact.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   exact_stance.py sha256:ffbd69c8753c546e
#   flight_jacobian.py sha256:4de4ff5a5b5282af
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module exact: JVP kernels, and for a map
its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
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
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, rtol, atol, liftoff); writes the outputs below into
    out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`exact.exact_stance`, in its order.

    Writes into out:
        <output>: each output of :func:`exact.exact_stance`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d, c (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff,) = load(p, 0, 1, 2, 3, 4, 8, 7, 9, 10, 11)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol,
            liftoff,)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0))
            & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0)) & ((q_r_lo <= l0)
            and (q_r_lo > 0.0)) & ((rtol >= 1e-14) and (rtol <= 0.001)) & ((atol >= 1e-16) and (atol
            <= 0.001)) & ((liftoff == 0.0) or (liftoff == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the exact stance (exact_stance)
    _o0 = carray(stack(80), 80)
    _c0 = (stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol,
        liftoff, _o0))
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, _o0_3, _o0_4, _o0_5, _o0_6, _o0_7, _o0_8, _o0_9, _o0_10, _o0_11, _o0_12, _o0_13,
        _o0_14, _o0_15, _o0_16, _o0_17, _o0_18, _o0_19, _o0_20, _o0_21, _o0_22, _o0_23, _o0_24, _o0_25,
        _o0_26, _o0_27, _o0_28, _o0_29, _o0_30, _o0_31, _o0_32, _o0_33, _o0_34, _o0_35, _o0_36, _o0_37,
        _o0_38, _o0_39, _o0_40, _o0_41, _o0_42, _o0_43, _o0_44, _o0_45, _o0_46, _o0_47, _o0_48, _o0_49,
        _o0_50, _o0_51, _o0_52, _o0_53, _o0_54, _o0_55, _o0_56, _o0_57, _o0_58, _o0_59, _o0_60, _o0_61,
        _o0_62, _o0_63, _o0_64, _o0_65, _o0_66, _o0_67, _o0_68, _o0_69, _o0_70, _o0_71, _o0_72, _o0_73,
        _o0_74, _o0_75, _o0_76, _o0_77, _o0_78, _o0_79,) = (load(_o0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
        12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36,
        37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61,
        62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79))
    # every output finite, or the inputs were far outside a physical range
    store(out, (_o0_0, _o0_1, _o0_2, _o0_3, _o0_4, _o0_5, _o0_6, _o0_7, _o0_8, _o0_9, _o0_10, _o0_11, _o0_12,
        _o0_13, _o0_14, _o0_15, _o0_16, _o0_17, _o0_18, _o0_19, _o0_20, _o0_21, _o0_22, _o0_23, _o0_24,
        _o0_25, _o0_26, _o0_27, _o0_28, _o0_29, _o0_30, _o0_31, _o0_32, _o0_33, _o0_34, _o0_35, _o0_36,
        _o0_37, _o0_38, _o0_39, _o0_40, _o0_41, _o0_42, _o0_43, _o0_44, _o0_45, _o0_46, _o0_47, _o0_48,
        _o0_49, _o0_50, _o0_51, _o0_52, _o0_53, _o0_54, _o0_55, _o0_56, _o0_57, _o0_58, _o0_59, _o0_60,
        _o0_61, _o0_62, _o0_63, _o0_64, _o0_65, _o0_66, _o0_67, _o0_68, _o0_69, _o0_70, _o0_71, _o0_72,
        _o0_73, _o0_74, _o0_75, _o0_76, _o0_77, _o0_78, _o0_79,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def exact_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`exact_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = exact_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def exact_apex_return_jacobian(x, p, out):
    """Apex-return map by Exact stance by numerical integration (DOP853), and its derivatives with respect to
    the apex, the touchdown angle and the stiffness.

    Report equations: 1, 2, 3, 27.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, rtol, atol, liftoff); writes the outputs below into
    out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`exact.exact_apex_return`, in its order.

    Writes into out:
        <output>: each output of :func:`exact.exact_apex_return`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k_c, k_d, c (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 348
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k_c, k_d, g_s, c, g_f, q_r_td, q_r_lo, rtol, atol, liftoff,) = (load(p, 0, 1, 2, 3, 4, 8, 5, 6, 7,
        9, 10, 11))
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k_c, k_d, g_s, c, g_f,
            q_r_td, q_r_lo, rtol, atol, liftoff,)) & ((b_y_apex >= 0.0)) & ((abs(q_th_td) < (0.5)*math.pi))
            & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0))
            & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))
            & ((rtol >= 1e-14) and (rtol <= 0.001)) & ((atol >= 1e-16) and (atol <= 0.001)) & ((liftoff
            == 0.0) or (liftoff == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _o0 = carray(stack(36), 36)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate(b_y_apex, b_xd_apex,
        q_th_td, q_r_td, g_f, ground, retraction_rate, _o0))
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, _o0_3, _o0_4, foot_x, _j_td_q_rd__b_y_apex, _j_td_q_rd__b_xd_apex,
        _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _j_td_q_rd__retraction_rate, _j_td_q_th__b_y_apex,
        _j_td_q_th__q_th_td, _j_td_q_th__ground, _j_td_q_th__retraction_rate, _j_td_q_thd__b_y_apex,
        _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground, _j_td_q_thd__retraction_rate,
        _o0_26, _o0_28, _o0_29, _o0_30, _j_foot_x__b_y_apex, _j_foot_x__b_xd_apex, _j_foot_x__q_th_td,
        _j_foot_x__ground, _j_foot_x__retraction_rate,) = (load(_o0, 0, 1, 2, 3, 4, 5, 11, 12, 13, 14, 15, 16,
        18, 19, 20, 21, 22, 23, 24, 25, 26, 28, 29, 30, 31, 32, 33, 34, 35))
    # stance: Exact stance by numerical integration (DOP853)
    _x1 = carray(stack(4), 4)
    store(_x1, (_o0_0, _o0_1, _o0_2, _o0_3,))
    _o1 = carray(stack(80), 80)
    _c1 = exact_stance_jacobian(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _j_t_stance__q_rd_td,
        _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _o1_21, _o1_22, _o1_23, _j_liftoff_q_r__q_rd_td,
        _j_liftoff_q_r__q_th_td, _j_liftoff_q_r__q_thd_td, _j_liftoff_q_r__k_c, _j_liftoff_q_r__k_d,
        _j_liftoff_q_r__c, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__c, _j_liftoff_q_th__q_rd_td,
        _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d,
        _j_liftoff_q_th__c, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__c,) = (load(_o1, 1, 6, 7, 8, 9, 18,
        19, 20, 21, 22, 23, 53, 54, 55, 56, 57, 58, 60, 61, 62, 63, 64, 65, 67, 68, 69, 70, 71, 72, 74, 75,
        76, 77, 78, 79))
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
    (_o2_0, _o2_1, _o2_2, next_apex_x, _j_apex_height__q_r, _j_apex_height__q_rd, _j_apex_height__q_th,
        _j_apex_height__q_thd, _j_apex_speed__q_r, _j_apex_speed__q_rd, _j_apex_speed__q_th,
        _j_apex_speed__q_thd, _j_t_ascent__q_r, _j_t_ascent__q_rd, _j_t_ascent__q_th, _j_t_ascent__q_thd,
        _j_next_apex_x__q_r, _j_next_apex_x__q_rd, _j_next_apex_x__q_th, _j_next_apex_x__q_thd,) = (load(_o2,
        0, 1, 2, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 21, 22, 23, 24))
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
    d_apex_height__c = (_j_apex_height__q_r*_j_liftoff_q_r__c + _j_apex_height__q_rd*_j_liftoff_q_rd__c
        + _j_apex_height__q_th*_j_liftoff_q_th__c + _j_apex_height__q_thd*_j_liftoff_q_thd__c)
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
    d_apex_speed__c = (_j_apex_speed__q_r*_j_liftoff_q_r__c + _j_apex_speed__q_rd*_j_liftoff_q_rd__c
        + _j_apex_speed__q_th*_j_liftoff_q_th__c + _j_apex_speed__q_thd*_j_liftoff_q_thd__c)
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
    d_t_ascent__c = (_j_liftoff_q_r__c*_j_t_ascent__q_r + _j_liftoff_q_rd__c*_j_t_ascent__q_rd
        + _j_liftoff_q_th__c*_j_t_ascent__q_th + _j_liftoff_q_thd__c*_j_t_ascent__q_thd)
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
    d_next_apex_x__c = (_j_liftoff_q_r__c*_j_next_apex_x__q_r + _j_liftoff_q_rd__c*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__c*_j_next_apex_x__q_th + _j_liftoff_q_thd__c*_j_next_apex_x__q_thd)
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
    d_liftoff_q_r__c = _j_liftoff_q_r__c
    d_liftoff_q_rd__k_c = _j_liftoff_q_rd__k_c
    d_liftoff_q_rd__k_d = _j_liftoff_q_rd__k_d
    d_liftoff_q_rd__c = _j_liftoff_q_rd__c
    d_liftoff_q_th__k_c = _j_liftoff_q_th__k_c
    d_liftoff_q_th__k_d = _j_liftoff_q_th__k_d
    d_liftoff_q_th__c = _j_liftoff_q_th__c
    d_liftoff_q_thd__k_c = _j_liftoff_q_thd__k_c
    d_liftoff_q_thd__k_d = _j_liftoff_q_thd__k_d
    d_liftoff_q_thd__c = _j_liftoff_q_thd__c
    d_step_length__k_c = d_next_apex_x__k_c
    d_step_length__k_d = d_next_apex_x__k_d
    d_step_length__c = d_next_apex_x__c
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
    store(out, (_o2_0, _o2_1, _o0_4, _o1_1, _o2_2, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        step_length, foot_x, foot_y, _o0_2, d_apex_height__b_y_apex, d_apex_height__b_xd_apex,
        d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__retraction_rate, d_apex_height__k_c,
        d_apex_height__k_d, d_apex_height__c, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex,
        d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__retraction_rate, d_apex_speed__k_c,
        d_apex_speed__k_d, d_apex_speed__c, _o0_26, 0.0, _o0_28, _o0_29, _o0_30, 0.0, 0.0, 0.0,
        d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground,
        d_t_stance__retraction_rate, _o1_21, _o1_22, _o1_23, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex,
        d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__retraction_rate, d_t_ascent__k_c,
        d_t_ascent__k_d, d_t_ascent__c, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex,
        d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground, d_liftoff_q_r__retraction_rate, d_liftoff_q_r__k_c,
        d_liftoff_q_r__k_d, d_liftoff_q_r__c, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex,
        d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__retraction_rate, d_liftoff_q_rd__k_c,
        d_liftoff_q_rd__k_d, d_liftoff_q_rd__c, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex,
        d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground, d_liftoff_q_th__retraction_rate, d_liftoff_q_th__k_c,
        d_liftoff_q_th__k_d, d_liftoff_q_th__c, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex,
        d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__retraction_rate,
        d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_liftoff_q_thd__c, d_step_length__b_y_apex,
        d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground,
        d_step_length__retraction_rate, d_step_length__k_c, d_step_length__k_d, d_step_length__c,
        d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground,
        d_foot_x__retraction_rate, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0,
        d_touchdown_q_th__b_y_apex, 0.0, d_touchdown_q_th__q_th_td, d_touchdown_q_th__ground,
        d_touchdown_q_th__retraction_rate, 0.0, 0.0, 0.0,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def exact_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`exact_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = exact_apex_return_jacobian(row(X, i), p, row(OUT, i))
