# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/exact.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:2e171e0cb588eb80
#   rows.py sha256:0089f4b891692c1b
#   runtime/exact/__init__.py sha256:b5581c4eb9fb8f73
#   runtime/exact/compiled.py sha256:f1ea68408082b7bb
#   runtime/exact/dop853.py sha256:6f313c10a1dd1ef4
#   runtime/exact/jacobian.py sha256:079e967891f96aa1
#   runtime/exact/kernels.py sha256:39d1598d210616fc
#   runtime/exact/reference.py sha256:1a2d2771848fe471
#   generated/flight.py sha256:8b20bd5230ccfe19
#   generated/maps_index.py sha256:ea8038b15fb7ac02
#   generated/slip_model.py sha256:1a04cccc79c2015a
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module exact: JVP kernels, and for a map
its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground,
    liftoff_to_apex_jac_q_r_q_rd_q_th_q_thd)
from .rows import store_row_10_70, store_row_12_84
from slipmaps.runtime.exact.kernels import stance_jacobian

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan
_NAN70 = (NAN,) * 70
_NAN84 = (NAN,) * 84


@njit(cache=True, error_model="numpy")
def exact_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """Exact stance by numerical integration (DOP853): stance outputs and their derivatives with respect to
    the touchdown state and the stiffness.

    Report equations: 1, 2, 3, 27.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        rtol: option rtol: relative tolerance of the DOP853 integration in [1e-14, 0.001]
        atol: option atol: absolute tolerance of the DOP853 integration in [1e-16, 0.001]

    Returns a tuple:
        t_bottom: time from touchdown to the bottom [s]
        t_stance: stance time, touchdown to liftoff [s]
        bottom_q_r: leg length [m]
        bottom_q_rd: leg length rate [m/s]
        bottom_q_th: leg angle from the vertical, counterclockwise positive [rad]
        bottom_q_thd: leg angle rate [rad/s]
        liftoff_q_r: leg length [m]
        liftoff_q_rd: leg length rate [m/s]
        liftoff_q_th: leg angle from the vertical, counterclockwise positive [rad]
        liftoff_q_thd: leg angle rate [rad/s]
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(rtol)
            and math.isfinite(atol) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s
            > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((rtol >= 1e-14) and (rtol <= 0.001))
            and ((atol >= 1e-16) and (atol <= 0.001))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # the exact stance (runtime/exact/kernels.py)
    _c0 = stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol)
    if _c0[70] != STATUS_OK:
        return _NAN70 + (_c0[70],)
    (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, dext_t_bottom__q_r_td, dext_t_bottom__q_rd_td, dext_t_bottom__q_th_td,
        dext_t_bottom__q_thd_td, dext_t_bottom__k_c, dext_t_bottom__k_d, dext_t_stance__q_r_td,
        dext_t_stance__q_rd_td, dext_t_stance__q_th_td, dext_t_stance__q_thd_td, dext_t_stance__k_c,
        dext_t_stance__k_d, dext_bottom_q_r__q_r_td, dext_bottom_q_r__q_rd_td, dext_bottom_q_r__q_th_td,
        dext_bottom_q_r__q_thd_td, dext_bottom_q_r__k_c, dext_bottom_q_r__k_d, dext_bottom_q_rd__q_r_td,
        dext_bottom_q_rd__q_rd_td, dext_bottom_q_rd__q_th_td, dext_bottom_q_rd__q_thd_td,
        dext_bottom_q_rd__k_c, dext_bottom_q_rd__k_d, dext_bottom_q_th__q_r_td, dext_bottom_q_th__q_rd_td,
        dext_bottom_q_th__q_th_td, dext_bottom_q_th__q_thd_td, dext_bottom_q_th__k_c, dext_bottom_q_th__k_d,
        dext_bottom_q_thd__q_r_td, dext_bottom_q_thd__q_rd_td, dext_bottom_q_thd__q_th_td,
        dext_bottom_q_thd__q_thd_td, dext_bottom_q_thd__k_c, dext_bottom_q_thd__k_d, dext_liftoff_q_r__q_r_td,
        dext_liftoff_q_r__q_rd_td, dext_liftoff_q_r__q_th_td, dext_liftoff_q_r__q_thd_td,
        dext_liftoff_q_r__k_c, dext_liftoff_q_r__k_d, dext_liftoff_q_rd__q_r_td, dext_liftoff_q_rd__q_rd_td,
        dext_liftoff_q_rd__q_th_td, dext_liftoff_q_rd__q_thd_td, dext_liftoff_q_rd__k_c,
        dext_liftoff_q_rd__k_d, dext_liftoff_q_th__q_r_td, dext_liftoff_q_th__q_rd_td,
        dext_liftoff_q_th__q_th_td, dext_liftoff_q_th__q_thd_td, dext_liftoff_q_th__k_c,
        dext_liftoff_q_th__k_d, dext_liftoff_q_thd__q_r_td, dext_liftoff_q_thd__q_rd_td,
        dext_liftoff_q_thd__q_th_td, dext_liftoff_q_thd__q_thd_td, dext_liftoff_q_thd__k_c,
        dext_liftoff_q_thd__k_d, _) = _c0
    # derivatives of the outputs
    d_t_bottom__q_r_td = dext_t_bottom__q_r_td
    d_t_bottom__q_rd_td = dext_t_bottom__q_rd_td
    d_t_bottom__q_th_td = dext_t_bottom__q_th_td
    d_t_bottom__q_thd_td = dext_t_bottom__q_thd_td
    d_t_bottom__k_c = dext_t_bottom__k_c
    d_t_bottom__k_d = dext_t_bottom__k_d
    d_t_stance__q_r_td = dext_t_stance__q_r_td
    d_t_stance__q_rd_td = dext_t_stance__q_rd_td
    d_t_stance__q_th_td = dext_t_stance__q_th_td
    d_t_stance__q_thd_td = dext_t_stance__q_thd_td
    d_t_stance__k_c = dext_t_stance__k_c
    d_t_stance__k_d = dext_t_stance__k_d
    d_bottom_q_r__q_r_td = dext_bottom_q_r__q_r_td
    d_bottom_q_r__q_rd_td = dext_bottom_q_r__q_rd_td
    d_bottom_q_r__q_th_td = dext_bottom_q_r__q_th_td
    d_bottom_q_r__q_thd_td = dext_bottom_q_r__q_thd_td
    d_bottom_q_r__k_c = dext_bottom_q_r__k_c
    d_bottom_q_r__k_d = dext_bottom_q_r__k_d
    d_bottom_q_rd__q_r_td = dext_bottom_q_rd__q_r_td
    d_bottom_q_rd__q_rd_td = dext_bottom_q_rd__q_rd_td
    d_bottom_q_rd__q_th_td = dext_bottom_q_rd__q_th_td
    d_bottom_q_rd__q_thd_td = dext_bottom_q_rd__q_thd_td
    d_bottom_q_rd__k_c = dext_bottom_q_rd__k_c
    d_bottom_q_rd__k_d = dext_bottom_q_rd__k_d
    d_bottom_q_th__q_r_td = dext_bottom_q_th__q_r_td
    d_bottom_q_th__q_rd_td = dext_bottom_q_th__q_rd_td
    d_bottom_q_th__q_th_td = dext_bottom_q_th__q_th_td
    d_bottom_q_th__q_thd_td = dext_bottom_q_th__q_thd_td
    d_bottom_q_th__k_c = dext_bottom_q_th__k_c
    d_bottom_q_th__k_d = dext_bottom_q_th__k_d
    d_bottom_q_thd__q_r_td = dext_bottom_q_thd__q_r_td
    d_bottom_q_thd__q_rd_td = dext_bottom_q_thd__q_rd_td
    d_bottom_q_thd__q_th_td = dext_bottom_q_thd__q_th_td
    d_bottom_q_thd__q_thd_td = dext_bottom_q_thd__q_thd_td
    d_bottom_q_thd__k_c = dext_bottom_q_thd__k_c
    d_bottom_q_thd__k_d = dext_bottom_q_thd__k_d
    d_liftoff_q_r__q_r_td = dext_liftoff_q_r__q_r_td
    d_liftoff_q_r__q_rd_td = dext_liftoff_q_r__q_rd_td
    d_liftoff_q_r__q_th_td = dext_liftoff_q_r__q_th_td
    d_liftoff_q_r__q_thd_td = dext_liftoff_q_r__q_thd_td
    d_liftoff_q_r__k_c = dext_liftoff_q_r__k_c
    d_liftoff_q_r__k_d = dext_liftoff_q_r__k_d
    d_liftoff_q_rd__q_r_td = dext_liftoff_q_rd__q_r_td
    d_liftoff_q_rd__q_rd_td = dext_liftoff_q_rd__q_rd_td
    d_liftoff_q_rd__q_th_td = dext_liftoff_q_rd__q_th_td
    d_liftoff_q_rd__q_thd_td = dext_liftoff_q_rd__q_thd_td
    d_liftoff_q_rd__k_c = dext_liftoff_q_rd__k_c
    d_liftoff_q_rd__k_d = dext_liftoff_q_rd__k_d
    d_liftoff_q_th__q_r_td = dext_liftoff_q_th__q_r_td
    d_liftoff_q_th__q_rd_td = dext_liftoff_q_th__q_rd_td
    d_liftoff_q_th__q_th_td = dext_liftoff_q_th__q_th_td
    d_liftoff_q_th__q_thd_td = dext_liftoff_q_th__q_thd_td
    d_liftoff_q_th__k_c = dext_liftoff_q_th__k_c
    d_liftoff_q_th__k_d = dext_liftoff_q_th__k_d
    d_liftoff_q_thd__q_r_td = dext_liftoff_q_thd__q_r_td
    d_liftoff_q_thd__q_rd_td = dext_liftoff_q_thd__q_rd_td
    d_liftoff_q_thd__q_th_td = dext_liftoff_q_thd__q_th_td
    d_liftoff_q_thd__q_thd_td = dext_liftoff_q_thd__q_thd_td
    d_liftoff_q_thd__k_c = dext_liftoff_q_thd__k_c
    d_liftoff_q_thd__k_d = dext_liftoff_q_thd__k_d
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by their users: runtime/api/jacobian.py)
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td,
        d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td,
        d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c,
        d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td,
        d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td,
        d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c,
        d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td,
        d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c,
        d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td,
        d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td,
        d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c,
        d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td,
        d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def exact_stance_jacobian_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol,
        out, status):
    """Parallel batch form of :func:`exact_stance_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 70); the columns are the outputs of
    :func:`exact_stance_jacobian`, in order) and its status code to ``status[i]`` (int64).
    A row whose values exist but a derivative does not is NUMERICAL_RANGE (:func:`store_row_10_70`).
    """
    for i in prange(out.shape[0]):
        res = (exact_stance_jacobian(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c, k_d, g_s,
            q_r_lo, rtol, atol))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def exact_apex_return_jacobian(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td,
        q_r_lo, rtol, atol):
    """Apex-return map by Exact stance by numerical integration (DOP853), and its derivatives with respect to
    the apex, the touchdown angle and the stiffness.

    Report equations: 1, 2, 3, 27.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground under it b_y_apex [m], >= 0
        b_xd_apex: horizontal apex speed, signed: negative runs toward -x (the mirror image of running toward
            +x, with the touchdown angle mirrored too); 0 is a hop in place b_xd_apex [m/s]
        q_th_td: touchdown leg angle from the vertical, counterclockwise positive q_th_td [rad]
        ground: height of the touchdown ground above the ground under the apex (a step up is positive) ground
            [m]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        rtol: option rtol: relative tolerance of the DOP853 integration in [1e-14, 0.001]
        atol: option atol: absolute tolerance of the DOP853 integration in [1e-16, 0.001]

    Returns a tuple:
        apex_height: next apex height above the ground the foot stood on [m]
        apex_speed: next apex horizontal speed (signed) [m/s]
        t_descent: flight time from the apex to touchdown [s]
        t_stance: stance time, touchdown to liftoff [s]
        t_ascent: flight time from liftoff to the next apex [s]
        liftoff_q_r: leg length [m]
        liftoff_q_rd: leg length rate [m/s]
        liftoff_q_th: leg angle from the vertical, counterclockwise positive [rad]
        liftoff_q_thd: leg angle rate [rad/s]
        step_length: horizontal distance from the apex to the next apex (signed) [m]
        foot_x: horizontal position of the foot at touchdown relative to the apex [m]
        foot_y: height of the foot (the touchdown ground) relative to the apex: ground - apex height [m]
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 246
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(rtol) and math.isfinite(atol) and ((b_y_apex >= 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo
            <= l0) and (q_r_lo > 0.0)) and ((rtol >= 1e-14) and (rtol <= 0.001)) and ((atol >= 1e-16)
            and (atol <= 0.001))):
        return _NAN84 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f,
        ground))
    if _c0[30] != STATUS_OK:
        return _NAN84 + (_c0[30],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, foot_x, _, _, _, _, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _, _, _j_td_q_th__q_th_td, _,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground,
        _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _j_t_descent__ground, _j_foot_x__b_y_apex,
        _j_foot_x__b_xd_apex, _j_foot_x__q_th_td, _j_foot_x__ground, _) = _c0
    # stance: Exact stance by numerical integration (DOP853)
    _c1 = exact_stance_jacobian(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol)
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _j_liftoff_q_r__q_rd_td,
        _j_liftoff_q_r__q_th_td, _j_liftoff_q_r__q_thd_td, _j_liftoff_q_r__k_c, _j_liftoff_q_r__k_d, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # chain rule through exact_stance
    d_t_stance__b_y_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_y_apex)
    d_t_stance__b_xd_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_t_stance__q_th_td = (_j_t_stance__q_rd_td*_j_td_q_rd__q_th_td + _j_t_stance__q_th_td*_j_td_q_th__q_th_td
        + _j_t_stance__q_thd_td*_j_td_q_thd__q_th_td)
    d_t_stance__ground = _j_t_stance__q_rd_td*_j_td_q_rd__ground + _j_t_stance__q_thd_td*_j_td_q_thd__ground
    d_liftoff_q_r__b_y_apex = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_r__b_xd_apex = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_r__q_th_td = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_r__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_r__ground = (_j_liftoff_q_r__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_r__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_rd__b_y_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_rd__b_xd_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_rd__ground = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_th__b_y_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_th__b_xd_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_th__ground = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_thd__b_y_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_thd__b_xd_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_thd__ground = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__ground)
    # liftoff -> next apex: exact ballistic ascent
    _c2 = (liftoff_to_apex_jac_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        g_f, direction))
    if _c2[25] != STATUS_OK:
        return _NAN84 + (_c2[25],)
    (apex_height, apex_speed, t_ascent, _, next_apex_x, _j_apex_height__q_r, _j_apex_height__q_rd,
        _j_apex_height__q_th, _j_apex_height__q_thd, _j_apex_speed__q_r, _j_apex_speed__q_rd,
        _j_apex_speed__q_th, _j_apex_speed__q_thd, _j_t_ascent__q_r, _j_t_ascent__q_rd, _j_t_ascent__q_th,
        _j_t_ascent__q_thd, _, _, _, _, _j_next_apex_x__q_r, _j_next_apex_x__q_rd, _j_next_apex_x__q_th,
        _j_next_apex_x__q_thd, _) = _c2
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
    foot_y = -b_y_apex + ground
    # derivatives of the outputs
    d_t_descent__b_y_apex = _j_t_descent__b_y_apex
    d_t_descent__b_xd_apex = 0.0
    d_t_descent__q_th_td = _j_t_descent__q_th_td
    d_t_descent__ground = _j_t_descent__ground
    d_t_descent__k_c = 0.0
    d_t_descent__k_d = 0.0
    d_t_stance__k_c = _j_t_stance__k_c
    d_t_stance__k_d = _j_t_stance__k_d
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
    d_foot_x__k_c = 0.0
    d_foot_x__k_d = 0.0
    d_foot_y__b_y_apex = -1.0
    d_foot_y__b_xd_apex = 0.0
    d_foot_y__q_th_td = 0.0
    d_foot_y__ground = 1.0
    d_foot_y__k_c = 0.0
    d_foot_y__k_d = 0.0
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by their users: runtime/api/jacobian.py)
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)):
        return _NAN84 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, d_apex_height__b_y_apex, d_apex_height__b_xd_apex,
        d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__k_c, d_apex_height__k_d,
        d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground,
        d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, d_t_descent__b_xd_apex,
        d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__k_c, d_t_descent__k_d, d_t_stance__b_y_apex,
        d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__k_c, d_t_stance__k_d,
        d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__k_c,
        d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td,
        d_liftoff_q_r__ground, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex,
        d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__k_c,
        d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td,
        d_liftoff_q_th__ground, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex,
        d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__k_c,
        d_liftoff_q_thd__k_d, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td,
        d_step_length__ground, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex,
        d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__k_c, d_foot_x__k_d,
        d_foot_y__b_y_apex, d_foot_y__b_xd_apex, d_foot_y__q_th_td, d_foot_y__ground, d_foot_y__k_c,
        d_foot_y__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def exact_apex_return_jacobian_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td,
        q_r_lo, rtol, atol, out, status):
    """Parallel batch form of :func:`exact_apex_return_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 84); the columns are the outputs of
    :func:`exact_apex_return_jacobian`, in order) and its status code to ``status[i]`` (int64).
    A row whose values exist but a derivative does not is NUMERICAL_RANGE (:func:`store_row_12_84`).
    """
    for i in prange(out.shape[0]):
        res = (exact_apex_return_jacobian(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m, l0, k_c, k_d,
            g_s, g_f, q_r_td, q_r_lo, rtol, atol))
        store_row_12_84(out, status, i, res)
