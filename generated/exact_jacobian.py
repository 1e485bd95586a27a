# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/exact.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:93735a9cd1eada3e
#   runtime/exact/__init__.py sha256:b5581c4eb9fb8f73
#   runtime/exact/compiled.py sha256:06f337539a4bc386
#   runtime/exact/dop853.py sha256:7cd47043700e95d7
#   runtime/exact/jacobian.py sha256:c33ac507e7dd844f
#   runtime/exact/kernels.py sha256:2bd1ad174519234a
#   runtime/exact/reference.py sha256:1a2d2771848fe471
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module exact: JVP kernels, and for a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td_ground, liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd
from slipmaps.runtime.exact.kernels import stance_jacobian

NAN = math.nan
STATUS_OK = 0
STATUS_INVALID_INPUT = 1
STATUS_APEX_TOO_LOW = 2
STATUS_TOUCHDOWN_NOT_COMPRESSING = 3
STATUS_NO_REAL_SOLUTION = 4
STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION = 5
STATUS_NO_LIFTOFF = 6
STATUS_FALL = 7
STATUS_LIFTOFF_DOWNWARD = 8
STATUS_LIFTOFF_BACKWARD = 9
STATUS_RECOMPRESSION = 10
STATUS_INTEGRATION_FAILED = 11
STATUS_NUMERICAL_RANGE = 12
STATUS_NOT_CONVERGED = 13
STATUS_ENERGY_DEFICIT = 14
STATUS_IMAGINARY_MOMENTUM = 15


@njit(cache=True, error_model="numpy")
def exact_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, k_d__tan):
    """Exact stance by numerical integration (DOP853): touchdown state -> bottom and liftoff states, with the derivative of every output along the direction (q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, k_d__tan).

    Report equations: 1, 2, 3, 27.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

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
        q_r_td__tan: direction: its component along q_r_td
        q_rd_td__tan: direction: its component along q_rd_td
        q_th_td__tan: direction: its component along q_th_td
        q_thd_td__tan: direction: its component along q_thd_td
        k_c__tan: direction: its component along k_c
        k_d__tan: direction: its component along k_d

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
        t_bottom__tan: derivative of t_bottom along the direction
        t_stance__tan: derivative of t_stance along the direction
        bottom_q_r__tan: derivative of bottom_q_r along the direction
        bottom_q_rd__tan: derivative of bottom_q_rd along the direction
        bottom_q_th__tan: derivative of bottom_q_th along the direction
        bottom_q_thd__tan: derivative of bottom_q_thd along the direction
        liftoff_q_r__tan: derivative of liftoff_q_r along the direction
        liftoff_q_rd__tan: derivative of liftoff_q_rd along the direction
        liftoff_q_th__tan: derivative of liftoff_q_th along the direction
        liftoff_q_thd__tan: derivative of liftoff_q_thd along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 110
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(rtol) and math.isfinite(atol) and math.isfinite(q_r_td__tan) and math.isfinite(q_rd_td__tan) and math.isfinite(q_th_td__tan) and math.isfinite(q_thd_td__tan) and math.isfinite(k_c__tan) and math.isfinite(k_d__tan) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((rtol >= 1e-14) and (rtol <= 0.001)) and ((atol >= 1e-16) and (atol <= 0.001))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # the exact stance (runtime/exact/kernels.py)
    _c0 = stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol)
    if _c0[70] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[70])
    t_bottom = _c0[0]
    t_stance = _c0[1]
    bottom_q_r = _c0[2]
    bottom_q_rd = _c0[3]
    bottom_q_th = _c0[4]
    bottom_q_thd = _c0[5]
    liftoff_q_r = _c0[6]
    liftoff_q_rd = _c0[7]
    liftoff_q_th = _c0[8]
    liftoff_q_thd = _c0[9]
    dext_t_bottom__q_r_td = _c0[10]
    dext_t_bottom__q_rd_td = _c0[11]
    dext_t_bottom__q_th_td = _c0[12]
    dext_t_bottom__q_thd_td = _c0[13]
    dext_t_bottom__k_c = _c0[14]
    dext_t_bottom__k_d = _c0[15]
    dext_t_stance__q_r_td = _c0[16]
    dext_t_stance__q_rd_td = _c0[17]
    dext_t_stance__q_th_td = _c0[18]
    dext_t_stance__q_thd_td = _c0[19]
    dext_t_stance__k_c = _c0[20]
    dext_t_stance__k_d = _c0[21]
    dext_bottom_q_r__q_r_td = _c0[22]
    dext_bottom_q_r__q_rd_td = _c0[23]
    dext_bottom_q_r__q_th_td = _c0[24]
    dext_bottom_q_r__q_thd_td = _c0[25]
    dext_bottom_q_r__k_c = _c0[26]
    dext_bottom_q_r__k_d = _c0[27]
    dext_bottom_q_rd__q_r_td = _c0[28]
    dext_bottom_q_rd__q_rd_td = _c0[29]
    dext_bottom_q_rd__q_th_td = _c0[30]
    dext_bottom_q_rd__q_thd_td = _c0[31]
    dext_bottom_q_rd__k_c = _c0[32]
    dext_bottom_q_rd__k_d = _c0[33]
    dext_bottom_q_th__q_r_td = _c0[34]
    dext_bottom_q_th__q_rd_td = _c0[35]
    dext_bottom_q_th__q_th_td = _c0[36]
    dext_bottom_q_th__q_thd_td = _c0[37]
    dext_bottom_q_th__k_c = _c0[38]
    dext_bottom_q_th__k_d = _c0[39]
    dext_bottom_q_thd__q_r_td = _c0[40]
    dext_bottom_q_thd__q_rd_td = _c0[41]
    dext_bottom_q_thd__q_th_td = _c0[42]
    dext_bottom_q_thd__q_thd_td = _c0[43]
    dext_bottom_q_thd__k_c = _c0[44]
    dext_bottom_q_thd__k_d = _c0[45]
    dext_liftoff_q_r__q_r_td = _c0[46]
    dext_liftoff_q_r__q_rd_td = _c0[47]
    dext_liftoff_q_r__q_th_td = _c0[48]
    dext_liftoff_q_r__q_thd_td = _c0[49]
    dext_liftoff_q_r__k_c = _c0[50]
    dext_liftoff_q_r__k_d = _c0[51]
    dext_liftoff_q_rd__q_r_td = _c0[52]
    dext_liftoff_q_rd__q_rd_td = _c0[53]
    dext_liftoff_q_rd__q_th_td = _c0[54]
    dext_liftoff_q_rd__q_thd_td = _c0[55]
    dext_liftoff_q_rd__k_c = _c0[56]
    dext_liftoff_q_rd__k_d = _c0[57]
    dext_liftoff_q_th__q_r_td = _c0[58]
    dext_liftoff_q_th__q_rd_td = _c0[59]
    dext_liftoff_q_th__q_th_td = _c0[60]
    dext_liftoff_q_th__q_thd_td = _c0[61]
    dext_liftoff_q_th__k_c = _c0[62]
    dext_liftoff_q_th__k_d = _c0[63]
    dext_liftoff_q_thd__q_r_td = _c0[64]
    dext_liftoff_q_thd__q_rd_td = _c0[65]
    dext_liftoff_q_thd__q_th_td = _c0[66]
    dext_liftoff_q_thd__q_thd_td = _c0[67]
    dext_liftoff_q_thd__k_c = _c0[68]
    dext_liftoff_q_thd__k_d = _c0[69]
    # tangents of stance's outputs: its Jacobian times the direction
    t_bottom__tan = dext_t_bottom__k_c*k_c__tan + dext_t_bottom__k_d*k_d__tan + dext_t_bottom__q_r_td*q_r_td__tan + dext_t_bottom__q_rd_td*q_rd_td__tan + dext_t_bottom__q_th_td*q_th_td__tan + dext_t_bottom__q_thd_td*q_thd_td__tan
    t_stance__tan = dext_t_stance__k_c*k_c__tan + dext_t_stance__k_d*k_d__tan + dext_t_stance__q_r_td*q_r_td__tan + dext_t_stance__q_rd_td*q_rd_td__tan + dext_t_stance__q_th_td*q_th_td__tan + dext_t_stance__q_thd_td*q_thd_td__tan
    bottom_q_r__tan = dext_bottom_q_r__k_c*k_c__tan + dext_bottom_q_r__k_d*k_d__tan + dext_bottom_q_r__q_r_td*q_r_td__tan + dext_bottom_q_r__q_rd_td*q_rd_td__tan + dext_bottom_q_r__q_th_td*q_th_td__tan + dext_bottom_q_r__q_thd_td*q_thd_td__tan
    bottom_q_rd__tan = dext_bottom_q_rd__k_c*k_c__tan + dext_bottom_q_rd__k_d*k_d__tan + dext_bottom_q_rd__q_r_td*q_r_td__tan + dext_bottom_q_rd__q_rd_td*q_rd_td__tan + dext_bottom_q_rd__q_th_td*q_th_td__tan + dext_bottom_q_rd__q_thd_td*q_thd_td__tan
    bottom_q_th__tan = dext_bottom_q_th__k_c*k_c__tan + dext_bottom_q_th__k_d*k_d__tan + dext_bottom_q_th__q_r_td*q_r_td__tan + dext_bottom_q_th__q_rd_td*q_rd_td__tan + dext_bottom_q_th__q_th_td*q_th_td__tan + dext_bottom_q_th__q_thd_td*q_thd_td__tan
    bottom_q_thd__tan = dext_bottom_q_thd__k_c*k_c__tan + dext_bottom_q_thd__k_d*k_d__tan + dext_bottom_q_thd__q_r_td*q_r_td__tan + dext_bottom_q_thd__q_rd_td*q_rd_td__tan + dext_bottom_q_thd__q_th_td*q_th_td__tan + dext_bottom_q_thd__q_thd_td*q_thd_td__tan
    liftoff_q_r__tan = dext_liftoff_q_r__k_c*k_c__tan + dext_liftoff_q_r__k_d*k_d__tan + dext_liftoff_q_r__q_r_td*q_r_td__tan + dext_liftoff_q_r__q_rd_td*q_rd_td__tan + dext_liftoff_q_r__q_th_td*q_th_td__tan + dext_liftoff_q_r__q_thd_td*q_thd_td__tan
    liftoff_q_rd__tan = dext_liftoff_q_rd__k_c*k_c__tan + dext_liftoff_q_rd__k_d*k_d__tan + dext_liftoff_q_rd__q_r_td*q_r_td__tan + dext_liftoff_q_rd__q_rd_td*q_rd_td__tan + dext_liftoff_q_rd__q_th_td*q_th_td__tan + dext_liftoff_q_rd__q_thd_td*q_thd_td__tan
    liftoff_q_th__tan = dext_liftoff_q_th__k_c*k_c__tan + dext_liftoff_q_th__k_d*k_d__tan + dext_liftoff_q_th__q_r_td*q_r_td__tan + dext_liftoff_q_th__q_rd_td*q_rd_td__tan + dext_liftoff_q_th__q_th_td*q_th_td__tan + dext_liftoff_q_th__q_thd_td*q_thd_td__tan
    liftoff_q_thd__tan = dext_liftoff_q_thd__k_c*k_c__tan + dext_liftoff_q_thd__k_d*k_d__tan + dext_liftoff_q_thd__q_r_td*q_r_td__tan + dext_liftoff_q_thd__q_rd_td*q_rd_td__tan + dext_liftoff_q_thd__q_th_td*q_th_td__tan + dext_liftoff_q_thd__q_thd_td*q_thd_td__tan
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def exact_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """Exact stance by numerical integration (DOP853): stance outputs and their derivatives with respect to the touchdown state and the stiffness.

    Report equations: 1, 2, 3, 27.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

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
        d_t_bottom__q_r_td: d t_bottom / d q_r_td
        d_t_bottom__q_rd_td: d t_bottom / d q_rd_td
        d_t_bottom__q_th_td: d t_bottom / d q_th_td
        d_t_bottom__q_thd_td: d t_bottom / d q_thd_td
        d_t_bottom__k_c: d t_bottom / d k_c
        d_t_bottom__k_d: d t_bottom / d k_d
        d_t_stance__q_r_td: d t_stance / d q_r_td
        d_t_stance__q_rd_td: d t_stance / d q_rd_td
        d_t_stance__q_th_td: d t_stance / d q_th_td
        d_t_stance__q_thd_td: d t_stance / d q_thd_td
        d_t_stance__k_c: d t_stance / d k_c
        d_t_stance__k_d: d t_stance / d k_d
        d_bottom_q_r__q_r_td: d bottom_q_r / d q_r_td
        d_bottom_q_r__q_rd_td: d bottom_q_r / d q_rd_td
        d_bottom_q_r__q_th_td: d bottom_q_r / d q_th_td
        d_bottom_q_r__q_thd_td: d bottom_q_r / d q_thd_td
        d_bottom_q_r__k_c: d bottom_q_r / d k_c
        d_bottom_q_r__k_d: d bottom_q_r / d k_d
        d_bottom_q_rd__q_r_td: d bottom_q_rd / d q_r_td
        d_bottom_q_rd__q_rd_td: d bottom_q_rd / d q_rd_td
        d_bottom_q_rd__q_th_td: d bottom_q_rd / d q_th_td
        d_bottom_q_rd__q_thd_td: d bottom_q_rd / d q_thd_td
        d_bottom_q_rd__k_c: d bottom_q_rd / d k_c
        d_bottom_q_rd__k_d: d bottom_q_rd / d k_d
        d_bottom_q_th__q_r_td: d bottom_q_th / d q_r_td
        d_bottom_q_th__q_rd_td: d bottom_q_th / d q_rd_td
        d_bottom_q_th__q_th_td: d bottom_q_th / d q_th_td
        d_bottom_q_th__q_thd_td: d bottom_q_th / d q_thd_td
        d_bottom_q_th__k_c: d bottom_q_th / d k_c
        d_bottom_q_th__k_d: d bottom_q_th / d k_d
        d_bottom_q_thd__q_r_td: d bottom_q_thd / d q_r_td
        d_bottom_q_thd__q_rd_td: d bottom_q_thd / d q_rd_td
        d_bottom_q_thd__q_th_td: d bottom_q_thd / d q_th_td
        d_bottom_q_thd__q_thd_td: d bottom_q_thd / d q_thd_td
        d_bottom_q_thd__k_c: d bottom_q_thd / d k_c
        d_bottom_q_thd__k_d: d bottom_q_thd / d k_d
        d_liftoff_q_r__q_r_td: d liftoff_q_r / d q_r_td
        d_liftoff_q_r__q_rd_td: d liftoff_q_r / d q_rd_td
        d_liftoff_q_r__q_th_td: d liftoff_q_r / d q_th_td
        d_liftoff_q_r__q_thd_td: d liftoff_q_r / d q_thd_td
        d_liftoff_q_r__k_c: d liftoff_q_r / d k_c
        d_liftoff_q_r__k_d: d liftoff_q_r / d k_d
        d_liftoff_q_rd__q_r_td: d liftoff_q_rd / d q_r_td
        d_liftoff_q_rd__q_rd_td: d liftoff_q_rd / d q_rd_td
        d_liftoff_q_rd__q_th_td: d liftoff_q_rd / d q_th_td
        d_liftoff_q_rd__q_thd_td: d liftoff_q_rd / d q_thd_td
        d_liftoff_q_rd__k_c: d liftoff_q_rd / d k_c
        d_liftoff_q_rd__k_d: d liftoff_q_rd / d k_d
        d_liftoff_q_th__q_r_td: d liftoff_q_th / d q_r_td
        d_liftoff_q_th__q_rd_td: d liftoff_q_th / d q_rd_td
        d_liftoff_q_th__q_th_td: d liftoff_q_th / d q_th_td
        d_liftoff_q_th__q_thd_td: d liftoff_q_th / d q_thd_td
        d_liftoff_q_th__k_c: d liftoff_q_th / d k_c
        d_liftoff_q_th__k_d: d liftoff_q_th / d k_d
        d_liftoff_q_thd__q_r_td: d liftoff_q_thd / d q_r_td
        d_liftoff_q_thd__q_rd_td: d liftoff_q_thd / d q_rd_td
        d_liftoff_q_thd__q_th_td: d liftoff_q_thd / d q_th_td
        d_liftoff_q_thd__q_thd_td: d liftoff_q_thd / d q_thd_td
        d_liftoff_q_thd__k_c: d liftoff_q_thd / d k_c
        d_liftoff_q_thd__k_d: d liftoff_q_thd / d k_d
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(rtol) and math.isfinite(atol) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((rtol >= 1e-14) and (rtol <= 0.001)) and ((atol >= 1e-16) and (atol <= 0.001))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives with respect to q_r_td
    _c0 = exact_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if _c0[20] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[20])
    d_t_bottom__q_r_td = _c0[10]
    d_t_stance__q_r_td = _c0[11]
    d_bottom_q_r__q_r_td = _c0[12]
    d_bottom_q_rd__q_r_td = _c0[13]
    d_bottom_q_th__q_r_td = _c0[14]
    d_bottom_q_thd__q_r_td = _c0[15]
    d_liftoff_q_r__q_r_td = _c0[16]
    d_liftoff_q_rd__q_r_td = _c0[17]
    d_liftoff_q_th__q_r_td = _c0[18]
    d_liftoff_q_thd__q_r_td = _c0[19]
    t_bottom = _c0[0]
    t_stance = _c0[1]
    bottom_q_r = _c0[2]
    bottom_q_rd = _c0[3]
    bottom_q_th = _c0[4]
    bottom_q_thd = _c0[5]
    liftoff_q_r = _c0[6]
    liftoff_q_rd = _c0[7]
    liftoff_q_th = _c0[8]
    liftoff_q_thd = _c0[9]
    # derivatives with respect to q_rd_td
    _c1 = exact_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    if _c1[20] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[20])
    d_t_bottom__q_rd_td = _c1[10]
    d_t_stance__q_rd_td = _c1[11]
    d_bottom_q_r__q_rd_td = _c1[12]
    d_bottom_q_rd__q_rd_td = _c1[13]
    d_bottom_q_th__q_rd_td = _c1[14]
    d_bottom_q_thd__q_rd_td = _c1[15]
    d_liftoff_q_r__q_rd_td = _c1[16]
    d_liftoff_q_rd__q_rd_td = _c1[17]
    d_liftoff_q_th__q_rd_td = _c1[18]
    d_liftoff_q_thd__q_rd_td = _c1[19]
    # derivatives with respect to q_th_td
    _c2 = exact_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    if _c2[20] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[20])
    d_t_bottom__q_th_td = _c2[10]
    d_t_stance__q_th_td = _c2[11]
    d_bottom_q_r__q_th_td = _c2[12]
    d_bottom_q_rd__q_th_td = _c2[13]
    d_bottom_q_th__q_th_td = _c2[14]
    d_bottom_q_thd__q_th_td = _c2[15]
    d_liftoff_q_r__q_th_td = _c2[16]
    d_liftoff_q_rd__q_th_td = _c2[17]
    d_liftoff_q_th__q_th_td = _c2[18]
    d_liftoff_q_thd__q_th_td = _c2[19]
    # derivatives with respect to q_thd_td
    _c3 = exact_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    if _c3[20] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[20])
    d_t_bottom__q_thd_td = _c3[10]
    d_t_stance__q_thd_td = _c3[11]
    d_bottom_q_r__q_thd_td = _c3[12]
    d_bottom_q_rd__q_thd_td = _c3[13]
    d_bottom_q_th__q_thd_td = _c3[14]
    d_bottom_q_thd__q_thd_td = _c3[15]
    d_liftoff_q_r__q_thd_td = _c3[16]
    d_liftoff_q_rd__q_thd_td = _c3[17]
    d_liftoff_q_th__q_thd_td = _c3[18]
    d_liftoff_q_thd__q_thd_td = _c3[19]
    # derivatives with respect to k_c
    _c4 = exact_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    if _c4[20] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[20])
    d_t_bottom__k_c = _c4[10]
    d_t_stance__k_c = _c4[11]
    d_bottom_q_r__k_c = _c4[12]
    d_bottom_q_rd__k_c = _c4[13]
    d_bottom_q_th__k_c = _c4[14]
    d_bottom_q_thd__k_c = _c4[15]
    d_liftoff_q_r__k_c = _c4[16]
    d_liftoff_q_rd__k_c = _c4[17]
    d_liftoff_q_th__k_c = _c4[18]
    d_liftoff_q_thd__k_c = _c4[19]
    # derivatives with respect to k_d
    _c5 = exact_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    if _c5[20] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c5[20])
    d_t_bottom__k_d = _c5[10]
    d_t_stance__k_d = _c5[11]
    d_bottom_q_r__k_d = _c5[12]
    d_bottom_q_rd__k_d = _c5[13]
    d_bottom_q_th__k_d = _c5[14]
    d_bottom_q_thd__k_d = _c5[15]
    d_liftoff_q_r__k_d = _c5[16]
    d_liftoff_q_rd__k_d = _c5[17]
    d_liftoff_q_th__k_d = _c5[18]
    d_liftoff_q_thd__k_d = _c5[19]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r) and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(d_t_bottom__q_r_td) and math.isfinite(d_t_bottom__q_rd_td) and math.isfinite(d_t_bottom__q_th_td) and math.isfinite(d_t_bottom__q_thd_td) and math.isfinite(d_t_bottom__k_c) and math.isfinite(d_t_bottom__k_d) and math.isfinite(d_t_stance__q_r_td) and math.isfinite(d_t_stance__q_rd_td) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__q_thd_td) and math.isfinite(d_t_stance__k_c) and math.isfinite(d_t_stance__k_d) and math.isfinite(d_bottom_q_r__q_r_td) and math.isfinite(d_bottom_q_r__q_rd_td) and math.isfinite(d_bottom_q_r__q_th_td) and math.isfinite(d_bottom_q_r__q_thd_td) and math.isfinite(d_bottom_q_r__k_c) and math.isfinite(d_bottom_q_r__k_d) and math.isfinite(d_bottom_q_rd__q_r_td) and math.isfinite(d_bottom_q_rd__q_rd_td) and math.isfinite(d_bottom_q_rd__q_th_td) and math.isfinite(d_bottom_q_rd__q_thd_td) and math.isfinite(d_bottom_q_rd__k_c) and math.isfinite(d_bottom_q_rd__k_d) and math.isfinite(d_bottom_q_th__q_r_td) and math.isfinite(d_bottom_q_th__q_rd_td) and math.isfinite(d_bottom_q_th__q_th_td) and math.isfinite(d_bottom_q_th__q_thd_td) and math.isfinite(d_bottom_q_th__k_c) and math.isfinite(d_bottom_q_th__k_d) and math.isfinite(d_bottom_q_thd__q_r_td) and math.isfinite(d_bottom_q_thd__q_rd_td) and math.isfinite(d_bottom_q_thd__q_th_td) and math.isfinite(d_bottom_q_thd__q_thd_td) and math.isfinite(d_bottom_q_thd__k_c) and math.isfinite(d_bottom_q_thd__k_d) and math.isfinite(d_liftoff_q_r__q_r_td) and math.isfinite(d_liftoff_q_r__q_rd_td) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__q_thd_td) and math.isfinite(d_liftoff_q_r__k_c) and math.isfinite(d_liftoff_q_r__k_d) and math.isfinite(d_liftoff_q_rd__q_r_td) and math.isfinite(d_liftoff_q_rd__q_rd_td) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__q_thd_td) and math.isfinite(d_liftoff_q_rd__k_c) and math.isfinite(d_liftoff_q_rd__k_d) and math.isfinite(d_liftoff_q_th__q_r_td) and math.isfinite(d_liftoff_q_th__q_rd_td) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__q_thd_td) and math.isfinite(d_liftoff_q_th__k_c) and math.isfinite(d_liftoff_q_th__k_d) and math.isfinite(d_liftoff_q_thd__q_r_td) and math.isfinite(d_liftoff_q_thd__q_rd_td) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__q_thd_td) and math.isfinite(d_liftoff_q_thd__k_c) and math.isfinite(d_liftoff_q_thd__k_d)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def exact_stance_jacobian_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, out, status):
    """Parallel batch form of :func:`exact_stance_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 70)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d.
    """
    for i in prange(out.shape[0]):
        res = exact_stance_jacobian(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol)
        out[i, 0] = res[0]
        out[i, 1] = res[1]
        out[i, 2] = res[2]
        out[i, 3] = res[3]
        out[i, 4] = res[4]
        out[i, 5] = res[5]
        out[i, 6] = res[6]
        out[i, 7] = res[7]
        out[i, 8] = res[8]
        out[i, 9] = res[9]
        out[i, 10] = res[10]
        out[i, 11] = res[11]
        out[i, 12] = res[12]
        out[i, 13] = res[13]
        out[i, 14] = res[14]
        out[i, 15] = res[15]
        out[i, 16] = res[16]
        out[i, 17] = res[17]
        out[i, 18] = res[18]
        out[i, 19] = res[19]
        out[i, 20] = res[20]
        out[i, 21] = res[21]
        out[i, 22] = res[22]
        out[i, 23] = res[23]
        out[i, 24] = res[24]
        out[i, 25] = res[25]
        out[i, 26] = res[26]
        out[i, 27] = res[27]
        out[i, 28] = res[28]
        out[i, 29] = res[29]
        out[i, 30] = res[30]
        out[i, 31] = res[31]
        out[i, 32] = res[32]
        out[i, 33] = res[33]
        out[i, 34] = res[34]
        out[i, 35] = res[35]
        out[i, 36] = res[36]
        out[i, 37] = res[37]
        out[i, 38] = res[38]
        out[i, 39] = res[39]
        out[i, 40] = res[40]
        out[i, 41] = res[41]
        out[i, 42] = res[42]
        out[i, 43] = res[43]
        out[i, 44] = res[44]
        out[i, 45] = res[45]
        out[i, 46] = res[46]
        out[i, 47] = res[47]
        out[i, 48] = res[48]
        out[i, 49] = res[49]
        out[i, 50] = res[50]
        out[i, 51] = res[51]
        out[i, 52] = res[52]
        out[i, 53] = res[53]
        out[i, 54] = res[54]
        out[i, 55] = res[55]
        out[i, 56] = res[56]
        out[i, 57] = res[57]
        out[i, 58] = res[58]
        out[i, 59] = res[59]
        out[i, 60] = res[60]
        out[i, 61] = res[61]
        out[i, 62] = res[62]
        out[i, 63] = res[63]
        out[i, 64] = res[64]
        out[i, 65] = res[65]
        out[i, 66] = res[66]
        out[i, 67] = res[67]
        out[i, 68] = res[68]
        out[i, 69] = res[69]
        status[i] = res[70]


@njit(cache=True, error_model="numpy")
def exact_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan, k_c__tan, k_d__tan):
    """Apex-return map: exact flights, stance by Exact stance by numerical integration (DOP853), with the derivative of every output along the direction (b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan, k_c__tan, k_d__tan).

    Report equations: 1, 2, 3, 27.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground under it b_y_apex [m], >= 0
        b_xd_apex: horizontal apex speed, signed: negative runs toward -x (the mirror image of running toward +x, with the touchdown angle mirrored too); 0 is a hop in place b_xd_apex [m/s]
        q_th_td: touchdown leg angle from the vertical, counterclockwise positive q_th_td [rad]
        ground: height of the touchdown ground above the ground under the apex (a step up is positive) ground [m]
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
        b_y_apex__tan: direction: its component along b_y_apex
        b_xd_apex__tan: direction: its component along b_xd_apex
        q_th_td__tan: direction: its component along q_th_td
        ground__tan: direction: its component along ground
        k_c__tan: direction: its component along k_c
        k_d__tan: direction: its component along k_d

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
        apex_height__tan: derivative of apex_height along the direction
        apex_speed__tan: derivative of apex_speed along the direction
        t_descent__tan: derivative of t_descent along the direction
        t_stance__tan: derivative of t_stance along the direction
        t_ascent__tan: derivative of t_ascent along the direction
        liftoff_q_r__tan: derivative of liftoff_q_r along the direction
        liftoff_q_rd__tan: derivative of liftoff_q_rd along the direction
        liftoff_q_th__tan: derivative of liftoff_q_th along the direction
        liftoff_q_thd__tan: derivative of liftoff_q_thd along the direction
        step_length__tan: derivative of step_length along the direction
        foot_x__tan: derivative of foot_x along the direction
        foot_y__tan: derivative of foot_y along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 5
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(rtol) and math.isfinite(atol) and math.isfinite(b_y_apex__tan) and math.isfinite(b_xd_apex__tan) and math.isfinite(q_th_td__tan) and math.isfinite(ground__tan) and math.isfinite(k_c__tan) and math.isfinite(k_d__tan) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((rtol >= 1e-14) and (rtol <= 0.001)) and ((atol >= 1e-16) and (atol <= 0.001))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan)
    if _c0[12] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[12])
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    td_q_r__tan = _c0[6]
    td_q_rd__tan = _c0[7]
    td_q_th__tan = _c0[8]
    td_q_thd__tan = _c0[9]
    t_descent__tan = _c0[10]
    foot_x__tan = _c0[11]
    # stance: Exact stance by numerical integration (DOP853)
    _c1 = exact_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, k_c__tan, k_d__tan)
    if _c1[20] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[20])
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    t_stance__tan = _c1[11]
    liftoff_q_r__tan = _c1[16]
    liftoff_q_rd__tan = _c1[17]
    liftoff_q_th__tan = _c1[18]
    liftoff_q_thd__tan = _c1[19]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan)
    if _c2[10] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[10])
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    apex_height__tan = _c2[5]
    apex_speed__tan = _c2[6]
    t_ascent__tan = _c2[7]
    next_apex_x__tan = _c2[9]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    step_length__tan = foot_x__tan + next_apex_x__tan
    foot_y = -b_y_apex + ground
    foot_y__tan = -b_y_apex__tan + ground__tan
    # (internal helper: its callers check that their outputs are finite)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, apex_height__tan, apex_speed__tan, t_descent__tan, t_stance__tan, t_ascent__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, step_length__tan, foot_x__tan, foot_y__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def exact_apex_return_jacobian(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol):
    """Apex-return map by Exact stance by numerical integration (DOP853), and its derivatives with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 1, 2, 3, 27.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground under it b_y_apex [m], >= 0
        b_xd_apex: horizontal apex speed, signed: negative runs toward -x (the mirror image of running toward +x, with the touchdown angle mirrored too); 0 is a hop in place b_xd_apex [m/s]
        q_th_td: touchdown leg angle from the vertical, counterclockwise positive q_th_td [rad]
        ground: height of the touchdown ground above the ground under the apex (a step up is positive) ground [m]
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
        d_apex_height__b_y_apex: d apex_height / d b_y_apex
        d_apex_height__b_xd_apex: d apex_height / d b_xd_apex
        d_apex_height__q_th_td: d apex_height / d q_th_td
        d_apex_height__ground: d apex_height / d ground
        d_apex_height__k_c: d apex_height / d k_c
        d_apex_height__k_d: d apex_height / d k_d
        d_apex_speed__b_y_apex: d apex_speed / d b_y_apex
        d_apex_speed__b_xd_apex: d apex_speed / d b_xd_apex
        d_apex_speed__q_th_td: d apex_speed / d q_th_td
        d_apex_speed__ground: d apex_speed / d ground
        d_apex_speed__k_c: d apex_speed / d k_c
        d_apex_speed__k_d: d apex_speed / d k_d
        d_t_descent__b_y_apex: d t_descent / d b_y_apex
        d_t_descent__b_xd_apex: d t_descent / d b_xd_apex
        d_t_descent__q_th_td: d t_descent / d q_th_td
        d_t_descent__ground: d t_descent / d ground
        d_t_descent__k_c: d t_descent / d k_c
        d_t_descent__k_d: d t_descent / d k_d
        d_t_stance__b_y_apex: d t_stance / d b_y_apex
        d_t_stance__b_xd_apex: d t_stance / d b_xd_apex
        d_t_stance__q_th_td: d t_stance / d q_th_td
        d_t_stance__ground: d t_stance / d ground
        d_t_stance__k_c: d t_stance / d k_c
        d_t_stance__k_d: d t_stance / d k_d
        d_t_ascent__b_y_apex: d t_ascent / d b_y_apex
        d_t_ascent__b_xd_apex: d t_ascent / d b_xd_apex
        d_t_ascent__q_th_td: d t_ascent / d q_th_td
        d_t_ascent__ground: d t_ascent / d ground
        d_t_ascent__k_c: d t_ascent / d k_c
        d_t_ascent__k_d: d t_ascent / d k_d
        d_liftoff_q_r__b_y_apex: d liftoff_q_r / d b_y_apex
        d_liftoff_q_r__b_xd_apex: d liftoff_q_r / d b_xd_apex
        d_liftoff_q_r__q_th_td: d liftoff_q_r / d q_th_td
        d_liftoff_q_r__ground: d liftoff_q_r / d ground
        d_liftoff_q_r__k_c: d liftoff_q_r / d k_c
        d_liftoff_q_r__k_d: d liftoff_q_r / d k_d
        d_liftoff_q_rd__b_y_apex: d liftoff_q_rd / d b_y_apex
        d_liftoff_q_rd__b_xd_apex: d liftoff_q_rd / d b_xd_apex
        d_liftoff_q_rd__q_th_td: d liftoff_q_rd / d q_th_td
        d_liftoff_q_rd__ground: d liftoff_q_rd / d ground
        d_liftoff_q_rd__k_c: d liftoff_q_rd / d k_c
        d_liftoff_q_rd__k_d: d liftoff_q_rd / d k_d
        d_liftoff_q_th__b_y_apex: d liftoff_q_th / d b_y_apex
        d_liftoff_q_th__b_xd_apex: d liftoff_q_th / d b_xd_apex
        d_liftoff_q_th__q_th_td: d liftoff_q_th / d q_th_td
        d_liftoff_q_th__ground: d liftoff_q_th / d ground
        d_liftoff_q_th__k_c: d liftoff_q_th / d k_c
        d_liftoff_q_th__k_d: d liftoff_q_th / d k_d
        d_liftoff_q_thd__b_y_apex: d liftoff_q_thd / d b_y_apex
        d_liftoff_q_thd__b_xd_apex: d liftoff_q_thd / d b_xd_apex
        d_liftoff_q_thd__q_th_td: d liftoff_q_thd / d q_th_td
        d_liftoff_q_thd__ground: d liftoff_q_thd / d ground
        d_liftoff_q_thd__k_c: d liftoff_q_thd / d k_c
        d_liftoff_q_thd__k_d: d liftoff_q_thd / d k_d
        d_step_length__b_y_apex: d step_length / d b_y_apex
        d_step_length__b_xd_apex: d step_length / d b_xd_apex
        d_step_length__q_th_td: d step_length / d q_th_td
        d_step_length__ground: d step_length / d ground
        d_step_length__k_c: d step_length / d k_c
        d_step_length__k_d: d step_length / d k_d
        d_foot_x__b_y_apex: d foot_x / d b_y_apex
        d_foot_x__b_xd_apex: d foot_x / d b_xd_apex
        d_foot_x__q_th_td: d foot_x / d q_th_td
        d_foot_x__ground: d foot_x / d ground
        d_foot_x__k_c: d foot_x / d k_c
        d_foot_x__k_d: d foot_x / d k_d
        d_foot_y__b_y_apex: d foot_y / d b_y_apex
        d_foot_y__b_xd_apex: d foot_y / d b_xd_apex
        d_foot_y__q_th_td: d foot_y / d q_th_td
        d_foot_y__ground: d foot_y / d ground
        d_foot_y__k_c: d foot_y / d k_c
        d_foot_y__k_d: d foot_y / d k_d
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(rtol) and math.isfinite(atol) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((rtol >= 1e-14) and (rtol <= 0.001)) and ((atol >= 1e-16) and (atol <= 0.001))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives with respect to b_y_apex
    _c0 = exact_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if _c0[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[24])
    d_apex_height__b_y_apex = _c0[12]
    d_apex_speed__b_y_apex = _c0[13]
    d_t_descent__b_y_apex = _c0[14]
    d_t_stance__b_y_apex = _c0[15]
    d_t_ascent__b_y_apex = _c0[16]
    d_liftoff_q_r__b_y_apex = _c0[17]
    d_liftoff_q_rd__b_y_apex = _c0[18]
    d_liftoff_q_th__b_y_apex = _c0[19]
    d_liftoff_q_thd__b_y_apex = _c0[20]
    d_step_length__b_y_apex = _c0[21]
    d_foot_x__b_y_apex = _c0[22]
    d_foot_y__b_y_apex = _c0[23]
    apex_height = _c0[0]
    apex_speed = _c0[1]
    t_descent = _c0[2]
    t_stance = _c0[3]
    t_ascent = _c0[4]
    liftoff_q_r = _c0[5]
    liftoff_q_rd = _c0[6]
    liftoff_q_th = _c0[7]
    liftoff_q_thd = _c0[8]
    step_length = _c0[9]
    foot_x = _c0[10]
    foot_y = _c0[11]
    # derivatives with respect to b_xd_apex
    _c1 = exact_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    if _c1[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[24])
    d_apex_height__b_xd_apex = _c1[12]
    d_apex_speed__b_xd_apex = _c1[13]
    d_t_descent__b_xd_apex = _c1[14]
    d_t_stance__b_xd_apex = _c1[15]
    d_t_ascent__b_xd_apex = _c1[16]
    d_liftoff_q_r__b_xd_apex = _c1[17]
    d_liftoff_q_rd__b_xd_apex = _c1[18]
    d_liftoff_q_th__b_xd_apex = _c1[19]
    d_liftoff_q_thd__b_xd_apex = _c1[20]
    d_step_length__b_xd_apex = _c1[21]
    d_foot_x__b_xd_apex = _c1[22]
    d_foot_y__b_xd_apex = _c1[23]
    # derivatives with respect to q_th_td
    _c2 = exact_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    if _c2[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[24])
    d_apex_height__q_th_td = _c2[12]
    d_apex_speed__q_th_td = _c2[13]
    d_t_descent__q_th_td = _c2[14]
    d_t_stance__q_th_td = _c2[15]
    d_t_ascent__q_th_td = _c2[16]
    d_liftoff_q_r__q_th_td = _c2[17]
    d_liftoff_q_rd__q_th_td = _c2[18]
    d_liftoff_q_th__q_th_td = _c2[19]
    d_liftoff_q_thd__q_th_td = _c2[20]
    d_step_length__q_th_td = _c2[21]
    d_foot_x__q_th_td = _c2[22]
    d_foot_y__q_th_td = _c2[23]
    # derivatives with respect to ground
    _c3 = exact_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    if _c3[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[24])
    d_apex_height__ground = _c3[12]
    d_apex_speed__ground = _c3[13]
    d_t_descent__ground = _c3[14]
    d_t_stance__ground = _c3[15]
    d_t_ascent__ground = _c3[16]
    d_liftoff_q_r__ground = _c3[17]
    d_liftoff_q_rd__ground = _c3[18]
    d_liftoff_q_th__ground = _c3[19]
    d_liftoff_q_thd__ground = _c3[20]
    d_step_length__ground = _c3[21]
    d_foot_x__ground = _c3[22]
    d_foot_y__ground = _c3[23]
    # derivatives with respect to k_c
    _c4 = exact_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    if _c4[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[24])
    d_apex_height__k_c = _c4[12]
    d_apex_speed__k_c = _c4[13]
    d_t_descent__k_c = _c4[14]
    d_t_stance__k_c = _c4[15]
    d_t_ascent__k_c = _c4[16]
    d_liftoff_q_r__k_c = _c4[17]
    d_liftoff_q_rd__k_c = _c4[18]
    d_liftoff_q_th__k_c = _c4[19]
    d_liftoff_q_thd__k_c = _c4[20]
    d_step_length__k_c = _c4[21]
    d_foot_x__k_c = _c4[22]
    d_foot_y__k_c = _c4[23]
    # derivatives with respect to k_d
    _c5 = exact_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    if _c5[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c5[24])
    d_apex_height__k_d = _c5[12]
    d_apex_speed__k_d = _c5[13]
    d_t_descent__k_d = _c5[14]
    d_t_stance__k_d = _c5[15]
    d_t_ascent__k_d = _c5[16]
    d_liftoff_q_r__k_d = _c5[17]
    d_liftoff_q_rd__k_d = _c5[18]
    d_liftoff_q_th__k_d = _c5[19]
    d_liftoff_q_thd__k_d = _c5[20]
    d_step_length__k_d = _c5[21]
    d_foot_x__k_d = _c5[22]
    d_foot_y__k_d = _c5[23]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent) and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y) and math.isfinite(d_apex_height__b_y_apex) and math.isfinite(d_apex_height__b_xd_apex) and math.isfinite(d_apex_height__q_th_td) and math.isfinite(d_apex_height__ground) and math.isfinite(d_apex_height__k_c) and math.isfinite(d_apex_height__k_d) and math.isfinite(d_apex_speed__b_y_apex) and math.isfinite(d_apex_speed__b_xd_apex) and math.isfinite(d_apex_speed__q_th_td) and math.isfinite(d_apex_speed__ground) and math.isfinite(d_apex_speed__k_c) and math.isfinite(d_apex_speed__k_d) and math.isfinite(d_t_descent__b_y_apex) and math.isfinite(d_t_descent__b_xd_apex) and math.isfinite(d_t_descent__q_th_td) and math.isfinite(d_t_descent__ground) and math.isfinite(d_t_descent__k_c) and math.isfinite(d_t_descent__k_d) and math.isfinite(d_t_stance__b_y_apex) and math.isfinite(d_t_stance__b_xd_apex) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__ground) and math.isfinite(d_t_stance__k_c) and math.isfinite(d_t_stance__k_d) and math.isfinite(d_t_ascent__b_y_apex) and math.isfinite(d_t_ascent__b_xd_apex) and math.isfinite(d_t_ascent__q_th_td) and math.isfinite(d_t_ascent__ground) and math.isfinite(d_t_ascent__k_c) and math.isfinite(d_t_ascent__k_d) and math.isfinite(d_liftoff_q_r__b_y_apex) and math.isfinite(d_liftoff_q_r__b_xd_apex) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__ground) and math.isfinite(d_liftoff_q_r__k_c) and math.isfinite(d_liftoff_q_r__k_d) and math.isfinite(d_liftoff_q_rd__b_y_apex) and math.isfinite(d_liftoff_q_rd__b_xd_apex) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__ground) and math.isfinite(d_liftoff_q_rd__k_c) and math.isfinite(d_liftoff_q_rd__k_d) and math.isfinite(d_liftoff_q_th__b_y_apex) and math.isfinite(d_liftoff_q_th__b_xd_apex) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__ground) and math.isfinite(d_liftoff_q_th__k_c) and math.isfinite(d_liftoff_q_th__k_d) and math.isfinite(d_liftoff_q_thd__b_y_apex) and math.isfinite(d_liftoff_q_thd__b_xd_apex) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__ground) and math.isfinite(d_liftoff_q_thd__k_c) and math.isfinite(d_liftoff_q_thd__k_d) and math.isfinite(d_step_length__b_y_apex) and math.isfinite(d_step_length__b_xd_apex) and math.isfinite(d_step_length__q_th_td) and math.isfinite(d_step_length__ground) and math.isfinite(d_step_length__k_c) and math.isfinite(d_step_length__k_d) and math.isfinite(d_foot_x__b_y_apex) and math.isfinite(d_foot_x__b_xd_apex) and math.isfinite(d_foot_x__q_th_td) and math.isfinite(d_foot_x__ground) and math.isfinite(d_foot_x__k_c) and math.isfinite(d_foot_x__k_d) and math.isfinite(d_foot_y__b_y_apex) and math.isfinite(d_foot_y__b_xd_apex) and math.isfinite(d_foot_y__q_th_td) and math.isfinite(d_foot_y__ground) and math.isfinite(d_foot_y__k_c) and math.isfinite(d_foot_y__k_d)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__k_c, d_t_descent__k_d, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__k_c, d_t_stance__k_d, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__k_c, d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__k_c, d_foot_x__k_d, d_foot_y__b_y_apex, d_foot_y__b_xd_apex, d_foot_y__q_th_td, d_foot_y__ground, d_foot_y__k_c, d_foot_y__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def exact_apex_return_jacobian_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol, out, status):
    """Parallel batch form of :func:`exact_apex_return_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 84)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__k_c, d_t_descent__k_d, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__k_c, d_t_stance__k_d, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__k_c, d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__k_c, d_foot_x__k_d, d_foot_y__b_y_apex, d_foot_y__b_xd_apex, d_foot_y__q_th_td, d_foot_y__ground, d_foot_y__k_c, d_foot_y__k_d.
    """
    for i in prange(out.shape[0]):
        res = exact_apex_return_jacobian(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, rtol, atol)
        out[i, 0] = res[0]
        out[i, 1] = res[1]
        out[i, 2] = res[2]
        out[i, 3] = res[3]
        out[i, 4] = res[4]
        out[i, 5] = res[5]
        out[i, 6] = res[6]
        out[i, 7] = res[7]
        out[i, 8] = res[8]
        out[i, 9] = res[9]
        out[i, 10] = res[10]
        out[i, 11] = res[11]
        out[i, 12] = res[12]
        out[i, 13] = res[13]
        out[i, 14] = res[14]
        out[i, 15] = res[15]
        out[i, 16] = res[16]
        out[i, 17] = res[17]
        out[i, 18] = res[18]
        out[i, 19] = res[19]
        out[i, 20] = res[20]
        out[i, 21] = res[21]
        out[i, 22] = res[22]
        out[i, 23] = res[23]
        out[i, 24] = res[24]
        out[i, 25] = res[25]
        out[i, 26] = res[26]
        out[i, 27] = res[27]
        out[i, 28] = res[28]
        out[i, 29] = res[29]
        out[i, 30] = res[30]
        out[i, 31] = res[31]
        out[i, 32] = res[32]
        out[i, 33] = res[33]
        out[i, 34] = res[34]
        out[i, 35] = res[35]
        out[i, 36] = res[36]
        out[i, 37] = res[37]
        out[i, 38] = res[38]
        out[i, 39] = res[39]
        out[i, 40] = res[40]
        out[i, 41] = res[41]
        out[i, 42] = res[42]
        out[i, 43] = res[43]
        out[i, 44] = res[44]
        out[i, 45] = res[45]
        out[i, 46] = res[46]
        out[i, 47] = res[47]
        out[i, 48] = res[48]
        out[i, 49] = res[49]
        out[i, 50] = res[50]
        out[i, 51] = res[51]
        out[i, 52] = res[52]
        out[i, 53] = res[53]
        out[i, 54] = res[54]
        out[i, 55] = res[55]
        out[i, 56] = res[56]
        out[i, 57] = res[57]
        out[i, 58] = res[58]
        out[i, 59] = res[59]
        out[i, 60] = res[60]
        out[i, 61] = res[61]
        out[i, 62] = res[62]
        out[i, 63] = res[63]
        out[i, 64] = res[64]
        out[i, 65] = res[65]
        out[i, 66] = res[66]
        out[i, 67] = res[67]
        out[i, 68] = res[68]
        out[i, 69] = res[69]
        out[i, 70] = res[70]
        out[i, 71] = res[71]
        out[i, 72] = res[72]
        out[i, 73] = res[73]
        out[i, 74] = res[74]
        out[i, 75] = res[75]
        out[i, 76] = res[76]
        out[i, 77] = res[77]
        out[i, 78] = res[78]
        out[i, 79] = res[79]
        out[i, 80] = res[80]
        out[i, 81] = res[81]
        out[i, 82] = res[82]
        out[i, 83] = res[83]
        status[i] = res[84]
