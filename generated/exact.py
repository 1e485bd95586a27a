# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/exact.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight.py sha256:8b20bd5230ccfe19
#   runtime/exact/__init__.py sha256:b5581c4eb9fb8f73
#   runtime/exact/compiled.py sha256:f1ea68408082b7bb
#   runtime/exact/dop853.py sha256:6f313c10a1dd1ef4
#   runtime/exact/jacobian.py sha256:079e967891f96aa1
#   runtime/exact/kernels.py sha256:39d1598d210616fc
#   runtime/exact/reference.py sha256:1a2d2771848fe471
#   generated/maps_index.py sha256:ea8038b15fb7ac02
#   generated/slip_model.py sha256:1a04cccc79c2015a
# ----------------------------------------------------------------------------------------------
"""Exact stance by numerical integration (DOP853) (report section 2.2): stance, state-at-time and apex-return
kernels."""

import math

import numpy as np
from numba import njit, prange
from .flight import apex_to_touchdown, liftoff_to_apex
from slipmaps.runtime.exact.kernels import stance, state_at

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan
_NAN4 = (NAN,) * 4
_NAN10 = (NAN,) * 10
_NAN12 = (NAN,) * 12


@njit(cache=True, error_model="numpy")
def exact_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """Exact stance by numerical integration (DOP853): touchdown state -> bottom and liftoff states.

    Report equations: 1, 2, 3, 27.

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
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # the exact stance (runtime/exact/kernels.py)
    _c0 = stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol)
    if _c0[10] != STATUS_OK:
        return _NAN10 + (_c0[10],)
    (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, _) = _c0
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def exact_stance_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, out,
        status):
    """Parallel batch form of :func:`exact_stance`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 10); the columns are the outputs of
    :func:`exact_stance`, in order) and its status code to ``status[i]`` (int64).
    """
    for i in prange(out.shape[0]):
        res = (exact_stance(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo,
            rtol, atol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def exact_state_at(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """Exact stance by numerical integration (DOP853): the polar state a time t after touchdown.

    Report equations: 1, 2, 3, 27.

    Arguments:
        t: time since touchdown t [s], >= 0
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
        q_r: leg length [m]
        q_rd: leg length rate [m/s]
        q_th: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(t) and math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(rtol)
            and math.isfinite(atol) and ((t >= 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((rtol >= 1e-14) and (rtol
            <= 0.001)) and ((atol >= 1e-16) and (atol <= 0.001))):
        return _NAN4 + (STATUS_INVALID_INPUT,)
    # the exact state at t (runtime/exact/kernels.py)
    _c0 = state_at(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol)
    if _c0[4] != STATUS_OK:
        return _NAN4 + (_c0[4],)
    q_r = _c0[0]
    q_rd = _c0[1]
    q_th = _c0[2]
    q_thd = _c0[3]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)):
        return _NAN4 + (STATUS_NUMERICAL_RANGE,)
    return (q_r, q_rd, q_th, q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def exact_state_at_batch(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, out,
        status):
    """Parallel batch form of :func:`exact_state_at`.

    Row arguments (1-D float64 arrays of equal length n, any stride): t.
    Scalar arguments shared by every row: q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
    rtol, atol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 4); the columns are the outputs of
    :func:`exact_state_at`, in order) and its status code to ``status[i]`` (int64).
    """
    for i in prange(out.shape[0]):
        res = (exact_state_at(t[i], q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol,
            atol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], status[i]) = res


@njit(cache=True, error_model="numpy")
def exact_apex_return(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol,
        atol):
    """Apex-return map: exact flights, stance by Exact stance by numerical integration (DOP853).

    Report equations: 1, 2, 3, 27.

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
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 3
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(rtol) and math.isfinite(atol) and ((b_y_apex >= 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo
            <= l0) and (q_r_lo > 0.0)) and ((rtol >= 1e-14) and (rtol <= 0.001)) and ((atol >= 1e-16)
            and (atol <= 0.001))):
        return _NAN12 + (STATUS_INVALID_INPUT,)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground)
    if _c0[6] != STATUS_OK:
        return _NAN12 + (_c0[6],)
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Exact stance by numerical integration (DOP853)
    _c1 = exact_stance(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol)
    if _c1[10] != STATUS_OK:
        return _NAN12 + (_c1[10],)
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return _NAN12 + (_c2[5],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y)):
        return _NAN12 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def exact_apex_return_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
        rtol, atol, out, status):
    """Parallel batch form of :func:`exact_apex_return`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 12); the columns are the outputs of
    :func:`exact_apex_return`, in order) and its status code to ``status[i]`` (int64).
    """
    for i in prange(out.shape[0]):
        res = (exact_apex_return(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f,
            q_r_td, q_r_lo, rtol, atol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res
