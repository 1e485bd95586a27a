# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative_report.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:93735a9cd1eada3e
#   geyer_jacobian.py sha256:2cc3bc7df9c66782
#   geyer_vs_jacobian.py sha256:27c237b92fe478ab
#   gravity_type0_jacobian.py sha256:82882201e605f9fc
#   gravity_type1_jacobian.py sha256:3202f1b84c0ddf87
#   gravity_type2_jacobian.py sha256:38cdb9055d649f09
#   gravity_type3_jacobian.py sha256:d59af6c680c78d17
#   gravity_type4_jacobian.py sha256:7ea1a5e7afabc60d
#   gravity_type5_jacobian.py sha256:91b9dbe5f11a434e
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module iterative_report: JVP kernels, and for a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td_ground, liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd
from .geyer_jacobian import geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k
from .geyer_vs_jacobian import bottom_quartic_jvp_p_E_ab_k_c, geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d
from .gravity_type0_jacobian import gravity_type0_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k
from .gravity_type1_jacobian import gravity_type1_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k
from .gravity_type2_jacobian import gravity_type2_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k
from .gravity_type3_jacobian import gravity_type3_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k
from .gravity_type4_jacobian import gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k
from .gravity_type5_jacobian import gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k

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
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_0(g_s, k_c, k_c__tan, l0, m, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 1 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        z_b_q_r: result for the caller
        z_b_q_r__tan: result for the caller
        z_b_q_th: result for the caller
        z_b_q_th__tan: result for the caller
        z_b_q_thd: result for the caller
        z_b_q_thd__tan: result for the caller
        z_lo_q_th: result for the caller
        z_lo_q_thd: result for the caller
        z_lo_q_th__tan: result for the caller
        z_lo_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 102
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = -q_r_td
    _x1 = k_c*q_r_td
    _x2 = g_s*m
    _x3 = _x2*math.cos(q_th_td)
    _x4 = q_thd_td**2
    _x5 = _x4*m
    _x6 = m*q_rd_td**2
    _x7 = -_x1 - _x3 + _x4*m*q_r_td + k_c*l0
    _x8 = math.sqrt(_x6*k_c + _x7**2)
    _x9 = -_x1 - _x3 + _x5*q_r_td + _x8 + k_c*l0
    _x10 = (1.0/_x9)
    _x11 = -_x0 - _x10*_x6
    _x25 = (1.0/_x11)
    _x12 = 2.0*q_r_td
    _x13 = _x12*q_thd_td
    _x14 = _x13*m
    _x15 = (1.0/_x8)
    _x16 = _x15*_x7
    _x17 = _x10**2
    _x18 = _x17*_x6
    _x19 = _x2*math.sin(q_th_td)
    _x20 = (0.5)*_x7
    _x21 = -_x18*k_c__tan*(-_x0 - _x15*(_x20*(-_x12 + 2.0*l0) + (0.5)*_x6) - l0) - _x18*q_th_td__tan*(-_x16*_x19 - _x19) - _x18*q_thd_td__tan*(-_x14*_x16 - _x14) + q_r_td__tan*(-_x18*(-_x15*_x20*(2.0*_x4*m - 2.0*k_c) - _x5 + k_c) + 1.0) + q_rd_td__tan*(-2.0*_x10*m*q_rd_td + _x15*_x17*k_c*m**2*q_rd_td**3)
    _x22 = q_r_td**2
    _x23 = _x25**2
    _x24 = _x22*_x23
    z_b_q_r = _x11
    z_b_q_r__tan = _x21
    z_b_q_th = q_th_td
    z_b_q_th__tan = q_th_td__tan
    z_b_q_thd = _x24*q_thd_td
    z_b_q_thd__tan = _x13*_x23*q_r_td__tan - 2.0*_x21*_x22*_x25**3*q_thd_td + _x24*q_thd_td__tan
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # tangents the other branches define
    z_lo_q_th__tan = 0.0
    z_lo_q_thd__tan = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_r__tan, z_b_q_th, z_b_q_th__tan, z_b_q_thd, z_b_q_thd__tan, z_lo_q_th, z_lo_q_thd, z_lo_q_th__tan, z_lo_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_1(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 0 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        z_b_q_r: result for the caller
        z_b_q_r__tan: result for the caller
        z_b_q_th: result for the caller
        z_b_q_th__tan: result for the caller
        z_b_q_thd: result for the caller
        z_b_q_thd__tan: result for the caller
        z_lo_q_th: result for the caller
        z_lo_q_thd: result for the caller
        z_lo_q_th__tan: result for the caller
        z_lo_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan)
    if _c0[20] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[20])
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    z_b_q_r__tan = _c0[12]
    z_b_q_th__tan = _c0[14]
    z_b_q_thd__tan = _c0[15]
    z_lo_q_th__tan = _c0[18]
    z_lo_q_thd__tan = _c0[19]
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_r__tan, z_b_q_th, z_b_q_th__tan, z_b_q_thd, z_b_q_thd__tan, z_lo_q_th, z_lo_q_thd, z_lo_q_th__tan, z_lo_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_2(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 2 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        z_b_q_r: result for the caller
        z_b_q_r__tan: result for the caller
        z_b_q_th: result for the caller
        z_b_q_th__tan: result for the caller
        z_b_q_thd: result for the caller
        z_b_q_thd__tan: result for the caller
        z_lo_q_th: result for the caller
        z_lo_q_thd: result for the caller
        z_lo_q_th__tan: result for the caller
        z_lo_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = gravity_type0_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 1.0, 0.0, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan)
    if _c0[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[24])
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    z_b_q_r__tan = _c0[14]
    z_b_q_th__tan = _c0[16]
    z_b_q_thd__tan = _c0[17]
    z_lo_q_th__tan = _c0[20]
    z_lo_q_thd__tan = _c0[21]
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_r__tan, z_b_q_th, z_b_q_th__tan, z_b_q_thd, z_b_q_thd__tan, z_lo_q_th, z_lo_q_thd, z_lo_q_th__tan, z_lo_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_3(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 3 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        z_b_q_r: result for the caller
        z_b_q_r__tan: result for the caller
        z_b_q_th: result for the caller
        z_b_q_th__tan: result for the caller
        z_b_q_thd: result for the caller
        z_b_q_thd__tan: result for the caller
        z_lo_q_th: result for the caller
        z_lo_q_thd: result for the caller
        z_lo_q_th__tan: result for the caller
        z_lo_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = gravity_type1_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 100.0, 1e-12, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan)
    if _c0[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[24])
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    z_b_q_r__tan = _c0[14]
    z_b_q_th__tan = _c0[16]
    z_b_q_thd__tan = _c0[17]
    z_lo_q_th__tan = _c0[20]
    z_lo_q_thd__tan = _c0[21]
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_r__tan, z_b_q_th, z_b_q_th__tan, z_b_q_thd, z_b_q_thd__tan, z_lo_q_th, z_lo_q_thd, z_lo_q_th__tan, z_lo_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_4(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 4 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        z_b_q_r: result for the caller
        z_b_q_r__tan: result for the caller
        z_b_q_th: result for the caller
        z_b_q_th__tan: result for the caller
        z_b_q_thd: result for the caller
        z_b_q_thd__tan: result for the caller
        z_lo_q_th: result for the caller
        z_lo_q_thd: result for the caller
        z_lo_q_th__tan: result for the caller
        z_lo_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = gravity_type2_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 0.0, 100.0, 1e-12, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan)
    if _c0[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[24])
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    z_b_q_r__tan = _c0[14]
    z_b_q_th__tan = _c0[16]
    z_b_q_thd__tan = _c0[17]
    z_lo_q_th__tan = _c0[20]
    z_lo_q_thd__tan = _c0[21]
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_r__tan, z_b_q_th, z_b_q_th__tan, z_b_q_thd, z_b_q_thd__tan, z_lo_q_th, z_lo_q_thd, z_lo_q_th__tan, z_lo_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_5(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 5 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        z_b_q_r: result for the caller
        z_b_q_r__tan: result for the caller
        z_b_q_th: result for the caller
        z_b_q_th__tan: result for the caller
        z_b_q_thd: result for the caller
        z_b_q_thd__tan: result for the caller
        z_lo_q_th: result for the caller
        z_lo_q_thd: result for the caller
        z_lo_q_th__tan: result for the caller
        z_lo_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = gravity_type3_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 100.0, 1e-12, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan)
    if _c0[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[24])
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    z_b_q_r__tan = _c0[14]
    z_b_q_th__tan = _c0[16]
    z_b_q_thd__tan = _c0[17]
    z_lo_q_th__tan = _c0[20]
    z_lo_q_thd__tan = _c0[21]
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_r__tan, z_b_q_th, z_b_q_th__tan, z_b_q_thd, z_b_q_thd__tan, z_lo_q_th, z_lo_q_thd, z_lo_q_th__tan, z_lo_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_6(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 6 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        z_b_q_r: result for the caller
        z_b_q_r__tan: result for the caller
        z_b_q_th: result for the caller
        z_b_q_th__tan: result for the caller
        z_b_q_thd: result for the caller
        z_b_q_thd__tan: result for the caller
        z_lo_q_th: result for the caller
        z_lo_q_thd: result for the caller
        z_lo_q_th__tan: result for the caller
        z_lo_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 0.0, 100.0, 1e-12, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan)
    if _c0[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[24])
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    z_b_q_r__tan = _c0[14]
    z_b_q_th__tan = _c0[16]
    z_b_q_thd__tan = _c0[17]
    z_lo_q_th__tan = _c0[20]
    z_lo_q_thd__tan = _c0[21]
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_r__tan, z_b_q_th, z_b_q_th__tan, z_b_q_thd, z_b_q_thd__tan, z_lo_q_th, z_lo_q_thd, z_lo_q_th__tan, z_lo_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_7(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 7 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        z_b_q_r: result for the caller
        z_b_q_r__tan: result for the caller
        z_b_q_th: result for the caller
        z_b_q_th__tan: result for the caller
        z_b_q_thd: result for the caller
        z_b_q_thd__tan: result for the caller
        z_lo_q_th: result for the caller
        z_lo_q_thd: result for the caller
        z_lo_q_th__tan: result for the caller
        z_lo_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0, 1e-12, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan)
    if _c0[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[24])
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    z_b_q_r__tan = _c0[14]
    z_b_q_th__tan = _c0[16]
    z_b_q_thd__tan = _c0[17]
    z_lo_q_th__tan = _c0[20]
    z_lo_q_thd__tan = _c0[21]
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_r__tan, z_b_q_th, z_b_q_th__tan, z_b_q_thd, z_b_q_thd__tan, z_lo_q_th, z_lo_q_thd, z_lo_q_th__tan, z_lo_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_8(g_s, k_c, k_c__tan, k_d, k_d__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 8 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        z_b_q_r: result for the caller
        z_b_q_r__tan: result for the caller
        z_b_q_th: result for the caller
        z_b_q_th__tan: result for the caller
        z_b_q_thd: result for the caller
        z_b_q_thd__tan: result for the caller
        z_lo_q_th: result for the caller
        z_lo_q_thd: result for the caller
        z_lo_q_th__tan: result for the caller
        z_lo_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0, 0.0, 100.0, 1e-12, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, k_d__tan)
    if _c0[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[26])
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    z_b_q_r__tan = _c0[15]
    z_b_q_th__tan = _c0[17]
    z_b_q_thd__tan = _c0[18]
    z_lo_q_th__tan = _c0[21]
    z_lo_q_thd__tan = _c0[22]
    # (internal helper: its callers check that their outputs are finite)
    return (z_b_q_r, z_b_q_r__tan, z_b_q_th, z_b_q_th__tan, z_b_q_thd, z_b_q_thd__tan, z_lo_q_th, z_lo_q_thd, z_lo_q_th__tan, z_lo_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_9(z_b_q_r, z_b_q_r__tan):
    """branch bottom_length = 0 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        z_b_q_r: value of the caller's variable
        z_b_q_r__tan: value of the caller's variable

    Returns a tuple:
        bottom_q_r: result for the caller
        bottom_q_r__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    bottom_q_r = z_b_q_r
    bottom_q_r__tan = z_b_q_r__tan
    # (internal helper: its callers check that their outputs are finite)
    return (bottom_q_r, bottom_q_r__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_10(E_ab, E_ab__tan, g_s, k_c, k_c__tan, l0, m, q_r_td, q_r_td__tan, q_thd_td, q_thd_td__tan):
    """branch bottom_length = 1 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_ab: value of the caller's variable
        E_ab__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable

    Returns a tuple:
        bottom_q_r: result for the caller
        bottom_q_r__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # (153): the vertical bottom's quartic
    _c0 = bottom_quartic_jvp_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s, m*q_r_td**2*q_thd_td__tan + 2.0*m*q_r_td*q_r_td__tan*q_thd_td, E_ab__tan, k_c__tan)
    if _c0[2] != STATUS_OK:
        return (NAN, NAN, _c0[2])
    bottom_q_r = _c0[0]
    bottom_q_r__tan = _c0[1]
    # (internal helper: its callers check that their outputs are finite)
    return (bottom_q_r, bottom_q_r__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_11(c_e_next, c_e_next__tan, c_x, c_x__tan):
    """branch variant = 0 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        c_e_next: value of the caller's variable
        c_e_next__tan: value of the caller's variable
        c_x: value of the caller's variable
        c_x__tan: value of the caller's variable

    Returns a tuple:
        c_wq: result for the caller
        c_wq__tan: result for the caller
        c_wp: result for the caller
        c_wp__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 12
    _x2 = (1.0/c_x)
    _x0 = _x2**2
    _x1 = c_e_next*c_x__tan
    c_wq = _x0*c_e_next
    c_wq__tan = _x0*c_e_next__tan - 2.0*_x1*_x2**3
    c_wp = c_e_next*c_x
    c_wp__tan = _x1 + c_e_next__tan*c_x
    # (internal helper: its callers check that their outputs are finite)
    return (c_wq, c_wq__tan, c_wp, c_wp__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_12(c_e_next, c_e_next__tan, q_r_td, q_r_td__tan):
    """branch variant = 1 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        c_e_next: value of the caller's variable
        c_e_next__tan: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable

    Returns a tuple:
        c_wq: result for the caller
        c_wq__tan: result for the caller
        c_wp: result for the caller
        c_wp__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 25
    _x0 = (1.0/q_r_td)
    _x1 = c_e_next + q_r_td
    _x2 = (1.0/_x1)
    _x3 = _x0*_x2**2*c_e_next
    c_wq = _x0*_x2*c_e_next
    c_wq__tan = c_e_next__tan*(_x0*_x2 - _x3) + q_r_td__tan*(-_x0**2*_x2*c_e_next - _x3)
    c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
    c_wp__tan = _x1*c_e_next__tan + c_e_next*q_r_td__tan
    # (internal helper: its callers check that their outputs are finite)
    return (c_wq, c_wq__tan, c_wp, c_wp__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_13(E_ab, E_ab__tan, c_P, c_P__tan, c_Q, c_Q__tan, c_e, c_e__tan, g_s, k_c, k_c__tan, l0, m, q_r_td, q_r_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan, variant):
    """loop body of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_ab: value of the caller's variable
        E_ab__tan: value of the caller's variable
        c_P: value of the caller's variable
        c_P__tan: value of the caller's variable
        c_Q: value of the caller's variable
        c_Q__tan: value of the caller's variable
        c_e: value of the caller's variable
        c_e__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        q_thd_td: value of the caller's variable
        q_thd_td__tan: value of the caller's variable
        variant: value of the caller's variable

    Returns a tuple:
        _next_c_e: result for the caller
        _next_c_Q: result for the caller
        _next_c_P: result for the caller
        _next_c_T: result for the caller
        _next_c_e__tan: result for the caller
        _next_c_Q__tan: result for the caller
        _next_c_P__tan: result for the caller
        _next_c_T__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 134
    _x0 = c_e + q_r_td
    _x1 = c_e__tan + q_r_td__tan
    _x2 = _x0**2
    _x3 = (1.0/_x2)
    _x4 = _x0**4*m
    _x5 = _x0**3
    _x6 = l0**2
    _x7 = _x2*_x6*m
    _x8 = m**2
    _x9 = _x8*g_s*math.cos(c_Q)
    _x10 = 2.0*E_ab*_x2*m - _x4*k_c - 2.0*_x5*_x9 + 2.0*_x5*k_c*l0*m - _x7*k_c - c_P**2
    _x11 = 2.0*m
    c_x = _x0
    c_x__tan = _x1
    c_rad = _x10*_x3
    c_rad__tan = E_ab__tan*_x11 + 2.0*_x0*_x8*c_Q__tan*g_s*math.sin(c_Q) + _x1*(-2.0*_x10/_x5 + _x3*(4.0*E_ab*_x0*m - _x0*_x11*_x6*k_c - 6.0*_x2*_x9 + 6.0*_x2*k_c*l0*m - 4.0*_x5*k_c*m)) - 2.0*_x3*c_P*c_P__tan + _x3*k_c__tan*(-_x4 + 2.0*_x5*l0*m - _x7)
    # H^{-1} real at x_{j+1} on the current iterate
    if not ((c_rad > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    _x12 = math.sqrt(c_rad)
    c_h = _x12
    c_h__tan = (0.5)*c_rad__tan/_x12
    c_e_next = 4.0*c_e
    c_e_next__tan = 4.0*c_e__tan
    # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
    if variant == 0.0:
        # branch variant = 0
        _c0 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_11(c_e_next, c_e_next__tan, c_x, c_x__tan)
        if _c0[4] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[4])
        c_wq = _c0[0]
        c_wq__tan = _c0[1]
        c_wp = _c0[2]
        c_wp__tan = _c0[3]
    elif variant == 1.0:
        # branch variant = 1
        _c1 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_12(c_e_next, c_e_next__tan, q_r_td, q_r_td__tan)
        if _c1[4] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[4])
        c_wq = _c1[0]
        c_wq__tan = _c1[1]
        c_wp = _c1[2]
        c_wp__tan = _c1[3]
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # next values
    _x13 = (1.0/c_h)
    _x14 = _x13*c_P
    _x15 = m*q_r_td**2
    _x16 = m**2
    _x17 = math.sin(c_Q)
    _x18 = _x13*_x16*_x17*g_s
    _x19 = _x13*m
    _x20 = _x13**2
    _x21 = _x20*c_h__tan
    _x22 = _x16*c_wp*g_s
    _next_c_e = c_e_next
    _next_c_Q = -_x14*c_wq + q_th_td
    _next_c_P = _x15*q_thd_td - _x18*c_wp
    _next_c_T = -_x19*c_e_next
    _next_c_e__tan = c_e_next__tan
    _next_c_Q__tan = -_x13*c_P__tan*c_wq - _x14*c_wq__tan + _x20*c_P*c_h__tan*c_wq + q_th_td__tan
    _next_c_P__tan = -_x13*_x22*c_Q__tan*math.cos(c_Q) + _x15*q_thd_td__tan + _x17*_x21*_x22 - _x18*c_wp__tan + 2.0*m*q_r_td*q_r_td__tan*q_thd_td
    _next_c_T__tan = -_x19*c_e_next__tan + _x21*c_e_next*m
    # (internal helper: its callers check that their outputs are finite)
    return (_next_c_e, _next_c_Q, _next_c_P, _next_c_T, _next_c_e__tan, _next_c_Q__tan, _next_c_P__tan, _next_c_T__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_14(d_e_next, d_e_next__tan, d_x, d_x__tan):
    """branch variant = 0 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        d_e_next: value of the caller's variable
        d_e_next__tan: value of the caller's variable
        d_x: value of the caller's variable
        d_x__tan: value of the caller's variable

    Returns a tuple:
        d_wq: result for the caller
        d_wq__tan: result for the caller
        d_wp: result for the caller
        d_wp__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 12
    _x2 = (1.0/d_x)
    _x0 = _x2**2
    _x1 = d_e_next*d_x__tan
    d_wq = _x0*d_e_next
    d_wq__tan = _x0*d_e_next__tan - 2.0*_x1*_x2**3
    d_wp = d_e_next*d_x
    d_wp__tan = _x1 + d_e_next__tan*d_x
    # (internal helper: its callers check that their outputs are finite)
    return (d_wq, d_wq__tan, d_wp, d_wp__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_15(bottom_q_r, bottom_q_r__tan, d_e_next, d_e_next__tan):
    """branch variant = 1 of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        bottom_q_r: value of the caller's variable
        bottom_q_r__tan: value of the caller's variable
        d_e_next: value of the caller's variable
        d_e_next__tan: value of the caller's variable

    Returns a tuple:
        d_wq: result for the caller
        d_wq__tan: result for the caller
        d_wp: result for the caller
        d_wp__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 25
    _x0 = (1.0/bottom_q_r)
    _x1 = bottom_q_r + d_e_next
    _x2 = (1.0/_x1)
    _x3 = _x0*_x2**2*d_e_next
    d_wq = _x0*_x2*d_e_next
    d_wq__tan = bottom_q_r__tan*(-_x0**2*_x2*d_e_next - _x3) + d_e_next__tan*(_x0*_x2 - _x3)
    d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
    d_wp__tan = _x1*d_e_next__tan + bottom_q_r__tan*d_e_next
    # (internal helper: its callers check that their outputs are finite)
    return (d_wq, d_wq__tan, d_wp, d_wp__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_16(E_ba, E_ba__tan, bottom_q_r, bottom_q_r__tan, bottom_q_th, bottom_q_th__tan, bottom_q_thd, bottom_q_thd__tan, d_P, d_P__tan, d_Q, d_Q__tan, d_e, d_e__tan, g_s, k_d, k_d__tan, l0, m, t_bottom, t_bottom__tan, variant):
    """loop body of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_ba: value of the caller's variable
        E_ba__tan: value of the caller's variable
        bottom_q_r: value of the caller's variable
        bottom_q_r__tan: value of the caller's variable
        bottom_q_th: value of the caller's variable
        bottom_q_th__tan: value of the caller's variable
        bottom_q_thd: value of the caller's variable
        bottom_q_thd__tan: value of the caller's variable
        d_P: value of the caller's variable
        d_P__tan: value of the caller's variable
        d_Q: value of the caller's variable
        d_Q__tan: value of the caller's variable
        d_e: value of the caller's variable
        d_e__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        t_bottom: value of the caller's variable
        t_bottom__tan: value of the caller's variable
        variant: value of the caller's variable

    Returns a tuple:
        _next_d_e: result for the caller
        _next_d_Q: result for the caller
        _next_d_P: result for the caller
        _next_d_T: result for the caller
        _next_d_e__tan: result for the caller
        _next_d_Q__tan: result for the caller
        _next_d_P__tan: result for the caller
        _next_d_T__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 134
    _x0 = bottom_q_r + d_e
    _x1 = bottom_q_r__tan + d_e__tan
    _x2 = _x0**2
    _x3 = (1.0/_x2)
    _x4 = _x0**4*m
    _x5 = _x0**3
    _x6 = l0**2
    _x7 = _x2*_x6*m
    _x8 = m**2
    _x9 = _x8*g_s*math.cos(d_Q)
    _x10 = 2.0*E_ba*_x2*m - _x4*k_d - 2.0*_x5*_x9 + 2.0*_x5*k_d*l0*m - _x7*k_d - d_P**2
    _x11 = 2.0*m
    d_x = _x0
    d_x__tan = _x1
    d_rad = _x10*_x3
    d_rad__tan = E_ba__tan*_x11 + 2.0*_x0*_x8*d_Q__tan*g_s*math.sin(d_Q) + _x1*(-2.0*_x10/_x5 + _x3*(4.0*E_ba*_x0*m - _x0*_x11*_x6*k_d - 6.0*_x2*_x9 + 6.0*_x2*k_d*l0*m - 4.0*_x5*k_d*m)) - 2.0*_x3*d_P*d_P__tan + _x3*k_d__tan*(-_x4 + 2.0*_x5*l0*m - _x7)
    # H^{-1} real at x_{j+1} on the current iterate
    if not ((d_rad > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    _x12 = math.sqrt(d_rad)
    d_h = _x12
    d_h__tan = (0.5)*d_rad__tan/_x12
    d_e_next = 4.0*d_e
    d_e_next__tan = 4.0*d_e__tan
    # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
    if variant == 0.0:
        # branch variant = 0
        _c0 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_14(d_e_next, d_e_next__tan, d_x, d_x__tan)
        if _c0[4] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[4])
        d_wq = _c0[0]
        d_wq__tan = _c0[1]
        d_wp = _c0[2]
        d_wp__tan = _c0[3]
    elif variant == 1.0:
        # branch variant = 1
        _c1 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_15(bottom_q_r, bottom_q_r__tan, d_e_next, d_e_next__tan)
        if _c1[4] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[4])
        d_wq = _c1[0]
        d_wq__tan = _c1[1]
        d_wp = _c1[2]
        d_wp__tan = _c1[3]
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # next values
    _x13 = (1.0/d_h)
    _x14 = _x13*d_P
    _x15 = bottom_q_r**2*m
    _x16 = m**2
    _x17 = math.sin(d_Q)
    _x18 = _x13*_x16*_x17*g_s
    _x19 = _x13*m
    _x20 = _x13**2*d_h__tan
    _x21 = _x16*d_wp*g_s
    _next_d_e = d_e_next
    _next_d_Q = _x14*d_wq + bottom_q_th
    _next_d_P = _x15*bottom_q_thd + _x18*d_wp
    _next_d_T = _x19*d_e_next + t_bottom
    _next_d_e__tan = d_e_next__tan
    _next_d_Q__tan = _x13*d_P__tan*d_wq + _x14*d_wq__tan - _x20*d_P*d_wq + bottom_q_th__tan
    _next_d_P__tan = _x13*_x21*d_Q__tan*math.cos(d_Q) + _x15*bottom_q_thd__tan - _x17*_x20*_x21 + _x18*d_wp__tan + 2.0*bottom_q_r*bottom_q_r__tan*bottom_q_thd*m
    _next_d_T__tan = _x19*d_e_next__tan - _x20*d_e_next*m + t_bottom__tan
    # (internal helper: its callers check that their outputs are finite)
    return (_next_d_e, _next_d_Q, _next_d_P, _next_d_T, _next_d_e__tan, _next_d_Q__tan, _next_d_P__tan, _next_d_T__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_17(E_ba, E_ba__tan, d_P, d_P__tan, d_Q, d_Q__tan, d_T, d_T__tan, g_s, k_d, k_d__tan, l0, m, q_r_lo):
    """continuation of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_ba: value of the caller's variable
        E_ba__tan: value of the caller's variable
        d_P: value of the caller's variable
        d_P__tan: value of the caller's variable
        d_Q: value of the caller's variable
        d_Q__tan: value of the caller's variable
        d_T: value of the caller's variable
        d_T__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable

    Returns a tuple:
        t_stance: result for the caller
        liftoff_q_r: result for the caller
        liftoff_q_rd: result for the caller
        liftoff_q_th: result for the caller
        liftoff_q_thd: result for the caller
        t_stance__tan: result for the caller
        bottom_q_rd__tan: result for the caller
        liftoff_q_r__tan: result for the caller
        liftoff_q_rd__tan: result for the caller
        liftoff_q_th__tan: result for the caller
        liftoff_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 60
    # (45) corrected: p_r of the iterate at q_r_lo
    _x0 = q_r_lo**2
    _x1 = (1.0/_x0)
    _x2 = m*q_r_lo**4
    _x3 = q_r_lo**3
    _x4 = _x0*l0**2*m
    _x5 = 2.0*g_s*m**2
    rad_lo = _x1*(2.0*E_ba*_x0*m - _x2*k_d - _x3*_x5*math.cos(d_Q) + 2.0*_x3*k_d*l0*m - _x4*k_d - d_P**2)
    rad_lo__tan = 2.0*E_ba__tan*m - 2.0*_x1*d_P*d_P__tan + _x1*k_d__tan*(-_x2 + 2.0*_x3*l0*m - _x4) + _x5*d_Q__tan*q_r_lo*math.sin(d_Q)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # liftoff state
    _x6 = (1.0/m)
    _x7 = math.sqrt(rad_lo)
    _x8 = _x6/q_r_lo**2
    t_stance = d_T
    t_stance__tan = d_T__tan
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x6*_x7
    liftoff_q_rd__tan = (0.5)*_x6*rad_lo__tan/_x7
    liftoff_q_th = d_Q
    liftoff_q_th__tan = d_Q__tan
    liftoff_q_thd = _x8*d_P
    liftoff_q_thd__tan = _x8*d_P__tan
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # derivatives that are identically zero
    bottom_q_rd__tan = 0.0
    liftoff_q_r__tan = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_stance, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_stance__tan, bottom_q_rd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_18(E_ab, E_ab__tan, bottom_q_r, bottom_q_r__tan, c_P, c_P__tan, c_Q, c_Q__tan, c_T, c_T__tan, g_s, iterations, k_c, k_c__tan, k_d, k_d__tan, l0, m, q_r_lo, variant, z_lo_q_th, z_lo_q_th__tan, z_lo_q_thd, z_lo_q_thd__tan, zeroth):
    """continuation of iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_ab: value of the caller's variable
        E_ab__tan: value of the caller's variable
        bottom_q_r: value of the caller's variable
        bottom_q_r__tan: value of the caller's variable
        c_P: value of the caller's variable
        c_P__tan: value of the caller's variable
        c_Q: value of the caller's variable
        c_Q__tan: value of the caller's variable
        c_T: value of the caller's variable
        c_T__tan: value of the caller's variable
        g_s: value of the caller's variable
        iterations: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        variant: value of the caller's variable
        z_lo_q_th: value of the caller's variable
        z_lo_q_th__tan: value of the caller's variable
        z_lo_q_thd: value of the caller's variable
        z_lo_q_thd__tan: value of the caller's variable
        zeroth: value of the caller's variable

    Returns a tuple:
        t_bottom: result for the caller
        t_stance: result for the caller
        bottom_q_rd: result for the caller
        bottom_q_th: result for the caller
        bottom_q_thd: result for the caller
        liftoff_q_r: result for the caller
        liftoff_q_rd: result for the caller
        liftoff_q_th: result for the caller
        liftoff_q_thd: result for the caller
        t_bottom__tan: result for the caller
        t_stance__tan: result for the caller
        bottom_q_rd__tan: result for the caller
        bottom_q_th__tan: result for the caller
        bottom_q_thd__tan: result for the caller
        liftoff_q_r__tan: result for the caller
        liftoff_q_rd__tan: result for the caller
        liftoff_q_th__tan: result for the caller
        liftoff_q_thd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 240
    # bottom state (p_r = 0)
    _x2 = (1.0/bottom_q_r)
    _x0 = (1.0/m)
    _x1 = _x0*_x2**2
    t_bottom = c_T
    t_bottom__tan = c_T__tan
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_th__tan = c_Q__tan
    bottom_q_thd = _x1*c_P
    bottom_q_thd__tan = -2.0*_x0*_x2**3*bottom_q_r__tan*c_P + _x1*c_P__tan
    # E_ba of (98): the energy jump of the stiffness switch
    _x3 = (-bottom_q_r + l0)**2
    _x4 = -0.5*k_c + (0.5)*k_d
    _x5 = (0.5)*_x3
    E_ba = E_ab + _x3*_x4
    E_ba__tan = E_ab__tan + _x4*bottom_q_r__tan*(2.0*bottom_q_r - 2.0*l0) - _x5*k_c__tan + _x5*k_d__tan
    # zeroth iterate at liftoff
    _x6 = (zeroth == 1.0)
    _x7 = ((0.0) if _x6 else (1.0))
    _x8 = q_r_lo**-2
    _x9 = _x8*bottom_q_r**2
    g_lo_q_th = ((bottom_q_th) if _x6 else (z_lo_q_th))
    g_lo_q_th__tan = _x7*z_lo_q_th__tan + bottom_q_th__tan*((1.0) if _x6 else (0.0))
    g_lo_q_thd = ((_x9*bottom_q_thd) if _x6 else (z_lo_q_thd))
    g_lo_q_thd__tan = _x7*z_lo_q_thd__tan + bottom_q_r__tan*((2.0*_x8*bottom_q_r*bottom_q_thd) if _x6 else (0.0)) + bottom_q_thd__tan*((_x9) if _x6 else (0.0))
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x10 = 4.0**(-iterations)
    _x11 = -bottom_q_r + q_r_lo
    _x12 = _x10*_x11
    _x13 = _x10*bottom_q_r__tan
    _x14 = (0.25)*_x12
    _x15 = (0.25)*_x13
    _x16 = _x14 + bottom_q_r
    _x17 = _x16**2
    _x18 = (1.0/_x17)
    _x19 = _x16**4*m
    _x20 = _x16**3
    _x21 = l0**2*m
    _x22 = _x17*_x21
    _x23 = bottom_q_r**2*m
    _x24 = _x23*bottom_q_thd
    _x25 = q_r_lo**2
    _x26 = -_x24 + _x25*g_lo_q_thd*m
    _x27 = 4.0**((0.5)*iterations)
    _x28 = (1.0/_x27)
    _x29 = (0.5)*_x28
    _x30 = _x26*_x29
    _x31 = _x24 + _x30
    _x32 = -bottom_q_th + g_lo_q_th
    _x33 = _x29*_x32 + bottom_q_th
    _x34 = m**2
    _x35 = _x34*g_s
    _x36 = _x35*math.cos(_x33)
    _x37 = 2.0*E_ba*_x17*m - _x19*k_d - 2.0*_x20*_x36 + 2.0*_x20*k_d*l0*m - _x22*k_d - _x31**2
    _x38 = _x18*_x37
    _x39 = _x28*g_lo_q_th__tan
    _x40 = math.sin(_x33)
    _x41 = _x16*_x35*_x40
    _x42 = _x18*_x31
    _x43 = _x25*_x28*g_lo_q_thd__tan*m
    _x44 = -_x23*_x28
    _x45 = -2.0*_x37/_x20
    _x46 = (1.0/_x11)
    _x47 = 2.0*bottom_q_r
    _x48 = (0.5)*_x12
    _x49 = _x47 + _x48
    _x50 = 4.0*m
    _x51 = -2.0*E_ba*_x49*m + 6.0*_x17*_x36 - 6.0*_x17*k_d*l0*m + _x20*_x50*k_d + _x21*_x49*k_d
    _x52 = _x30*_x46
    _x53 = _x47*bottom_q_thd*m
    _x54 = -_x28*_x53 + _x52
    _x55 = 2.0*E_ba__tan*m - _x15*(_x18*(2.0*_x20*_x27*_x32*_x34*_x40*_x46*g_s - 2.0*_x26*_x27*_x31*_x46 - _x51) + _x45) + _x18*k_d__tan*(-_x19 + 2.0*_x20*l0*m - _x22) + _x39*_x41 + 2.0*_x41*bottom_q_th__tan*(1.0 - _x29) - _x42*_x43 - _x42*bottom_q_thd__tan*(2.0*_x23 + _x44) + bottom_q_r__tan*(_x18*((0.5)*_x20*_x28*_x32*_x34*_x40*_x46*g_s - _x31*(_x50*bottom_q_r*bottom_q_thd + _x54) - _x51) + _x45)
    _x56 = m/math.sqrt(_x38)
    _x57 = (_x38 > 0.0)
    d_e_n = _x12
    d_e_n__tan = -_x13
    d_e_z = _x14
    d_e_z__tan = -_x15
    d_rad_z = _x38
    d_rad_z__tan = _x55
    d_Q0 = _x28*_x32 + bottom_q_th
    d_Q0__tan = _x39 + bottom_q_th__tan*(1.0 - _x28)
    d_P0 = _x24 + _x26*_x28
    d_P0__tan = _x43 - _x52*bottom_q_r__tan + bottom_q_r__tan*(_x53 + _x54) + bottom_q_thd__tan*(_x23 + _x44)
    d_T0 = ((_x12*_x56 + t_bottom) if _x57 else (t_bottom))
    d_T0__tan = -_x13*((_x56) if _x57 else (0.0)) + _x55*((-_x48*m/_x38**(1.5)) if _x57 else (0.0)) + t_bottom__tan
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_e__tan = d_e_n__tan
    d_Q__tan = d_Q0__tan
    d_P__tan = d_P0__tan
    d_T__tan = d_T0__tan
    d_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_16(E_ba, E_ba__tan, bottom_q_r, bottom_q_r__tan, bottom_q_th, bottom_q_th__tan, bottom_q_thd, bottom_q_thd__tan, d_P, d_P__tan, d_Q, d_Q__tan, d_e, d_e__tan, g_s, k_d, k_d__tan, l0, m, t_bottom, t_bottom__tan, variant)
        if _c0[8] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[8])
        _next_d_e = _c0[0]
        _next_d_Q = _c0[1]
        _next_d_P = _c0[2]
        _next_d_T = _c0[3]
        _next_d_e__tan = _c0[4]
        _next_d_Q__tan = _c0[5]
        _next_d_P__tan = _c0[6]
        _next_d_T__tan = _c0[7]
        _n0_0 = _next_d_e
        _n0_1 = _next_d_Q
        _n0_2 = _next_d_P
        _n0_3 = _next_d_T
        _n0_4 = _next_d_e__tan
        _n0_5 = _next_d_Q__tan
        _n0_6 = _next_d_P__tan
        _n0_7 = _next_d_T__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = 0.0 > 0.0 and (abs(_n0_0 - d_e) <= 0.0*(l0)) and (abs(_n0_1 - d_Q) <= 0.0*(1.0)) and (abs(_n0_2 - d_P) <= 0.0*(math.sqrt(g_s)*l0**(1.5)*m)) and (abs(_n0_3 - d_T) <= 0.0*(math.sqrt(l0)/math.sqrt(g_s)))
        d_e = _n0_0
        d_Q = _n0_1
        d_P = _n0_2
        d_T = _n0_3
        d_e__tan = _n0_4
        d_Q__tan = _n0_5
        d_P__tan = _n0_6
        d_T__tan = _n0_7
        d_steps += 1.0
        if _conv0:
            break
    # continuation
    _c1 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_17(E_ba, E_ba__tan, d_P, d_P__tan, d_Q, d_Q__tan, d_T, d_T__tan, g_s, k_d, k_d__tan, l0, m, q_r_lo)
    if _c1[11] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[11])
    t_stance = _c1[0]
    liftoff_q_r = _c1[1]
    liftoff_q_rd = _c1[2]
    liftoff_q_th = _c1[3]
    liftoff_q_thd = _c1[4]
    t_stance__tan = _c1[5]
    bottom_q_rd__tan = _c1[6]
    liftoff_q_r__tan = _c1[7]
    liftoff_q_rd__tan = _c1[8]
    liftoff_q_th__tan = _c1[9]
    liftoff_q_thd__tan = _c1[10]
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom__tan, t_stance__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, k_d__tan):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff states, with the derivative of every output along the direction (q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, k_d__tan).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140, 141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

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
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs
        bottom_length: option bottom_length: the bottom leg length q_r_b the chains run to and from (section 5.2, closing estimates): 0 = zeroth, 1 = eq153
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
    # Total ops: 275
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations) and math.isfinite(zeroth) and math.isfinite(bottom_length) and math.isfinite(q_r_td__tan) and math.isfinite(q_rd_td__tan) and math.isfinite(q_th_td__tan) and math.isfinite(q_thd_td__tan) and math.isfinite(k_c__tan) and math.isfinite(k_d__tan) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate
    if zeroth == 1.0:
        # branch zeroth = 1
        _c0 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_0(g_s, k_c, k_c__tan, l0, m, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c0[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[10])
        z_b_q_r = _c0[0]
        z_b_q_r__tan = _c0[1]
        z_b_q_th = _c0[2]
        z_b_q_th__tan = _c0[3]
        z_b_q_thd = _c0[4]
        z_b_q_thd__tan = _c0[5]
        z_lo_q_th = _c0[6]
        z_lo_q_thd = _c0[7]
        z_lo_q_th__tan = _c0[8]
        z_lo_q_thd__tan = _c0[9]
    elif zeroth == 0.0:
        # branch zeroth = 0
        _c1 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_1(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c1[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[10])
        z_b_q_r = _c1[0]
        z_b_q_r__tan = _c1[1]
        z_b_q_th = _c1[2]
        z_b_q_th__tan = _c1[3]
        z_b_q_thd = _c1[4]
        z_b_q_thd__tan = _c1[5]
        z_lo_q_th = _c1[6]
        z_lo_q_thd = _c1[7]
        z_lo_q_th__tan = _c1[8]
        z_lo_q_thd__tan = _c1[9]
    elif zeroth == 2.0:
        # branch zeroth = 2
        _c2 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_2(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c2[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[10])
        z_b_q_r = _c2[0]
        z_b_q_r__tan = _c2[1]
        z_b_q_th = _c2[2]
        z_b_q_th__tan = _c2[3]
        z_b_q_thd = _c2[4]
        z_b_q_thd__tan = _c2[5]
        z_lo_q_th = _c2[6]
        z_lo_q_thd = _c2[7]
        z_lo_q_th__tan = _c2[8]
        z_lo_q_thd__tan = _c2[9]
    elif zeroth == 3.0:
        # branch zeroth = 3
        _c3 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_3(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c3[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[10])
        z_b_q_r = _c3[0]
        z_b_q_r__tan = _c3[1]
        z_b_q_th = _c3[2]
        z_b_q_th__tan = _c3[3]
        z_b_q_thd = _c3[4]
        z_b_q_thd__tan = _c3[5]
        z_lo_q_th = _c3[6]
        z_lo_q_thd = _c3[7]
        z_lo_q_th__tan = _c3[8]
        z_lo_q_thd__tan = _c3[9]
    elif zeroth == 4.0:
        # branch zeroth = 4
        _c4 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_4(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c4[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[10])
        z_b_q_r = _c4[0]
        z_b_q_r__tan = _c4[1]
        z_b_q_th = _c4[2]
        z_b_q_th__tan = _c4[3]
        z_b_q_thd = _c4[4]
        z_b_q_thd__tan = _c4[5]
        z_lo_q_th = _c4[6]
        z_lo_q_thd = _c4[7]
        z_lo_q_th__tan = _c4[8]
        z_lo_q_thd__tan = _c4[9]
    elif zeroth == 5.0:
        # branch zeroth = 5
        _c5 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_5(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c5[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c5[10])
        z_b_q_r = _c5[0]
        z_b_q_r__tan = _c5[1]
        z_b_q_th = _c5[2]
        z_b_q_th__tan = _c5[3]
        z_b_q_thd = _c5[4]
        z_b_q_thd__tan = _c5[5]
        z_lo_q_th = _c5[6]
        z_lo_q_thd = _c5[7]
        z_lo_q_th__tan = _c5[8]
        z_lo_q_thd__tan = _c5[9]
    elif zeroth == 6.0:
        # branch zeroth = 6
        _c6 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_6(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c6[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c6[10])
        z_b_q_r = _c6[0]
        z_b_q_r__tan = _c6[1]
        z_b_q_th = _c6[2]
        z_b_q_th__tan = _c6[3]
        z_b_q_thd = _c6[4]
        z_b_q_thd__tan = _c6[5]
        z_lo_q_th = _c6[6]
        z_lo_q_thd = _c6[7]
        z_lo_q_th__tan = _c6[8]
        z_lo_q_thd__tan = _c6[9]
    elif zeroth == 7.0:
        # branch zeroth = 7
        _c7 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_7(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c7[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c7[10])
        z_b_q_r = _c7[0]
        z_b_q_r__tan = _c7[1]
        z_b_q_th = _c7[2]
        z_b_q_th__tan = _c7[3]
        z_b_q_thd = _c7[4]
        z_b_q_thd__tan = _c7[5]
        z_lo_q_th = _c7[6]
        z_lo_q_thd = _c7[7]
        z_lo_q_th__tan = _c7[8]
        z_lo_q_thd__tan = _c7[9]
    elif zeroth == 8.0:
        # branch zeroth = 8
        _c8 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_8(g_s, k_c, k_c__tan, k_d, k_d__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c8[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c8[10])
        z_b_q_r = _c8[0]
        z_b_q_r__tan = _c8[1]
        z_b_q_th = _c8[2]
        z_b_q_th__tan = _c8[3]
        z_b_q_thd = _c8[4]
        z_b_q_thd__tan = _c8[5]
        z_lo_q_th = _c8[6]
        z_lo_q_thd = _c8[7]
        z_lo_q_th__tan = _c8[8]
        z_lo_q_thd__tan = _c8[9]
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # E_ab (114) of the touchdown state
    _x0 = l0*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*k_c + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    E_ab__tan = _x2*m*q_thd_td*q_thd_td__tan - _x4*q_r_td*q_th_td__tan*math.sin(q_th_td) + k_c__tan*(-_x0 + _x1 + _x3) + m*q_rd_td*q_rd_td__tan + q_r_td__tan*(_x5 + _x6*q_r_td - k_c*l0 + k_c*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        # branch bottom_length = 0
        _c9 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_9(z_b_q_r, z_b_q_r__tan)
        if _c9[2] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c9[2])
        bottom_q_r = _c9[0]
        bottom_q_r__tan = _c9[1]
    elif bottom_length == 1.0:
        # branch bottom_length = 1
        _c10 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_10(E_ab, E_ab__tan, g_s, k_c, k_c__tan, l0, m, q_r_td, q_r_td__tan, q_thd_td, q_thd_td__tan)
        if _c10[2] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c10[2])
        bottom_q_r = _c10[0]
        bottom_q_r__tan = _c10[1]
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x7 = 4.0**(-iterations)
    _x8 = bottom_q_r - q_r_td
    _x9 = _x7*_x8
    _x10 = _x7*bottom_q_r__tan
    _x11 = _x7*q_r_td__tan
    _x12 = _x10 - _x11
    _x13 = (0.25)*_x9
    _x14 = (0.25)*_x10 - 0.25*_x11
    _x15 = _x13 + q_r_td
    _x16 = _x15**2
    _x17 = (1.0/_x16)
    _x18 = _x15**4*m
    _x19 = _x15**3
    _x20 = l0**2*m
    _x21 = _x16*_x20
    _x22 = z_b_q_r**2
    _x23 = _x22*m
    _x24 = _x23*z_b_q_thd
    _x25 = (0.25)*_x7
    _x26 = math.sqrt(1.0 - _x25)
    _x27 = m*q_r_td**2
    _x28 = -_x24 + _x27*q_thd_td
    _x29 = _x24 + _x26*_x28
    _x30 = m**2
    _x31 = q_th_td - z_b_q_th
    _x32 = _x26*_x31 + z_b_q_th
    _x33 = _x30*g_s*math.cos(_x32)
    _x34 = 2.0*E_ab*_x16*m - _x18*k_c - 2.0*_x19*_x33 + 2.0*_x19*k_c*l0*m - _x21*k_c - _x29**2
    _x35 = _x17*_x34
    _x36 = 2.0*m
    _x37 = 2.0*_x26
    _x38 = _x30*g_s*math.sin(_x32)
    _x39 = _x15*_x38
    _x40 = _x17*_x29
    _x41 = _x27*q_thd_td__tan
    _x42 = 4.0*m
    _x43 = z_b_q_r*z_b_q_thd
    _x44 = (1.0/_x26)
    _x45 = (1.0/_x8)
    _x46 = _x31*_x45
    _x47 = _x19*_x38*_x44*_x46
    _x48 = _x25*_x47
    _x49 = _x28*_x45
    _x50 = _x44*_x49
    _x51 = -2.0*_x34/_x19
    _x52 = 2.0*q_r_td
    _x53 = (0.5)*_x9
    _x54 = _x52 + _x53
    _x55 = -2.0*E_ab*_x54*m + 6.0*_x16*_x33 - 6.0*_x16*k_c*l0*m + _x19*_x42*k_c + _x20*_x54*k_c
    _x56 = E_ab__tan*_x36 + _x14*(_x17*(_x28*_x29*_x44*_x45 - _x47 - _x55) + _x51) + _x17*bottom_q_r__tan*(-_x25*_x29*_x50 + _x48) + _x17*k_c__tan*(-_x18 + 2.0*_x19*l0*m - _x21) + _x37*_x39*q_th_td__tan - _x37*_x40*_x41 + 2.0*_x39*z_b_q_th__tan*(1.0 - _x26) - _x40*z_b_q_r__tan*(-_x26*_x42*_x43 + 4.0*m*z_b_q_r*z_b_q_thd) - _x40*z_b_q_thd__tan*(2.0*_x22*m - 2.0*_x23*_x26) + q_r_td__tan*(_x17*(-_x29*(-_x25*_x50 + _x26*_x42*q_r_td*q_thd_td) - _x48 - _x55) + _x51)
    _x57 = math.sqrt(1.0 - _x7)
    _x58 = (0.5)/_x57
    _x59 = _x46*_x58
    _x60 = _x12*_x58
    _x61 = _x49*_x58
    _x62 = m/math.sqrt(_x35)
    _x63 = (_x35 > 0.0)
    c_e_n = _x9
    c_e_n__tan = _x12
    c_e_z = _x13
    c_e_z__tan = _x14
    c_rad_z = _x35
    c_rad_z__tan = _x56
    c_Q0 = _x31*_x57 + z_b_q_th
    c_Q0__tan = _x10*_x59 - _x11*_x59 - _x46*_x60 + _x57*q_th_td__tan + z_b_q_th__tan*(1.0 - _x57)
    c_P0 = _x24 + _x28*_x57
    c_P0__tan = _x10*_x61 + _x41*_x57 - _x49*_x60 + q_r_td__tan*(_x52*_x57*m*q_thd_td - _x61*_x7) + z_b_q_r__tan*(-_x36*_x43*_x57 + 2.0*m*z_b_q_r*z_b_q_thd) + z_b_q_thd__tan*(_x22*m - _x23*_x57)
    c_T0 = ((-_x62*_x9) if _x63 else (0.0))
    c_T0__tan = _x12*((-_x62) if _x63 else (0.0)) + _x56*((_x53*m/_x35**(1.5)) if _x63 else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_e__tan = c_e_n__tan
    c_Q__tan = c_Q0__tan
    c_P__tan = c_P0__tan
    c_T__tan = c_T0__tan
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c11 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_13(E_ab, E_ab__tan, c_P, c_P__tan, c_Q, c_Q__tan, c_e, c_e__tan, g_s, k_c, k_c__tan, l0, m, q_r_td, q_r_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan, variant)
        if _c11[8] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c11[8])
        _next_c_e = _c11[0]
        _next_c_Q = _c11[1]
        _next_c_P = _c11[2]
        _next_c_T = _c11[3]
        _next_c_e__tan = _c11[4]
        _next_c_Q__tan = _c11[5]
        _next_c_P__tan = _c11[6]
        _next_c_T__tan = _c11[7]
        _n0_0 = _next_c_e
        _n0_1 = _next_c_Q
        _n0_2 = _next_c_P
        _n0_3 = _next_c_T
        _n0_4 = _next_c_e__tan
        _n0_5 = _next_c_Q__tan
        _n0_6 = _next_c_P__tan
        _n0_7 = _next_c_T__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = 0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0)) and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*l0**(1.5)*m)) and (abs(_n0_3 - c_T) <= 0.0*(math.sqrt(l0)/math.sqrt(g_s)))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_e__tan = _n0_4
        c_Q__tan = _n0_5
        c_P__tan = _n0_6
        c_T__tan = _n0_7
        c_steps += 1.0
        if _conv0:
            break
    # continuation
    _c12 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_18(E_ab, E_ab__tan, bottom_q_r, bottom_q_r__tan, c_P, c_P__tan, c_Q, c_Q__tan, c_T, c_T__tan, g_s, iterations, k_c, k_c__tan, k_d, k_d__tan, l0, m, q_r_lo, variant, z_lo_q_th, z_lo_q_th__tan, z_lo_q_thd, z_lo_q_thd__tan, zeroth)
    if _c12[18] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c12[18])
    t_bottom = _c12[0]
    t_stance = _c12[1]
    bottom_q_rd = _c12[2]
    bottom_q_th = _c12[3]
    bottom_q_thd = _c12[4]
    liftoff_q_r = _c12[5]
    liftoff_q_rd = _c12[6]
    liftoff_q_th = _c12[7]
    liftoff_q_thd = _c12[8]
    t_bottom__tan = _c12[9]
    t_stance__tan = _c12[10]
    bottom_q_rd__tan = _c12[11]
    bottom_q_th__tan = _c12[12]
    bottom_q_thd__tan = _c12[13]
    liftoff_q_r__tan = _c12[14]
    liftoff_q_rd__tan = _c12[15]
    liftoff_q_th__tan = _c12[16]
    liftoff_q_thd__tan = _c12[17]
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140, 141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

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
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs
        bottom_length: option bottom_length: the bottom leg length q_r_b the chains run to and from (section 5.2, closing estimates): 0 = zeroth, 1 = eq153

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
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations) and math.isfinite(zeroth) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives with respect to q_r_td
    _c0 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
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
    _c1 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
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
    _c2 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
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
    _c3 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
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
    _c4 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
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
    _c5 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
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
def iterative_report_stance_jacobian_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length.
    Writes output j of row i to ``out[i, j]`` (shape (n, 70)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d.
    """
    for i in prange(out.shape[0]):
        res = iterative_report_stance_jacobian(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length)
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
def iterative_report_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan, k_c__tan, k_d__tan):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed), with the derivative of every output along the direction (b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan, k_c__tan, k_d__tan).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140, 141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

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
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs
        bottom_length: option bottom_length: the bottom leg length q_r_b the chains run to and from (section 5.2, closing estimates): 0 = zeroth, 1 = eq153
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
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations) and math.isfinite(zeroth) and math.isfinite(bottom_length) and math.isfinite(b_y_apex__tan) and math.isfinite(b_xd_apex__tan) and math.isfinite(q_th_td__tan) and math.isfinite(ground__tan) and math.isfinite(k_c__tan) and math.isfinite(k_d__tan) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = iterative_report_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, zeroth, bottom_length, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, k_c__tan, k_d__tan)
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
def iterative_report_apex_return_jacobian(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140, 141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

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
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs
        bottom_length: option bottom_length: the bottom leg length q_r_b the chains run to and from (section 5.2, closing estimates): 0 = zeroth, 1 = eq153

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
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations) and math.isfinite(zeroth) and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives with respect to b_y_apex
    _c0 = iterative_report_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
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
    _c1 = iterative_report_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
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
    _c2 = iterative_report_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
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
    _c3 = iterative_report_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
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
    _c4 = iterative_report_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
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
    _c5 = iterative_report_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
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
def iterative_report_apex_return_jacobian_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length.
    Writes output j of row i to ``out[i, j]`` (shape (n, 84)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__k_c, d_t_descent__k_d, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__k_c, d_t_stance__k_d, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__k_c, d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__k_c, d_foot_x__k_d, d_foot_y__b_y_apex, d_foot_y__b_xd_apex, d_foot_y__q_th_td, d_foot_y__ground, d_foot_y__k_c, d_foot_y__k_d.
    """
    for i in prange(out.shape[0]):
        res = iterative_report_apex_return_jacobian(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, zeroth, bottom_length)
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
