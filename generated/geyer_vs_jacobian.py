# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/geyer_vs.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:93735a9cd1eada3e
#   geyer_jacobian.py sha256:2cc3bc7df9c66782
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module geyer_vs: JVP kernels, and for a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td_ground, liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd
from .geyer_jacobian import geyer_liftoff_phase_jvp_a_b, geyer_solution_jvp_q_r_td_q_rd_td_q_thd_td_k

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
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_0(E_td, E_td__tan, i_bottom_q_r, i_bottom_q_r__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m):
    """branch continuity = 0 of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_td: value of the caller's variable
        E_td__tan: value of the caller's variable
        i_bottom_q_r: value of the caller's variable
        i_bottom_q_r__tan: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable

    Returns a tuple:
        i_eps_ba: result for the caller
        i_eps_ba__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 24
    # eqs (97)-(99), E_ab the energy (27)
    _x0 = k_c - k_d
    _x1 = (-i_bottom_q_r + l0)**2
    _x2 = 1.0/(l0**2*m)
    _x3 = _x1*_x2
    i_eps_ba = _x2*(2.0*E_td - _x0*_x1)
    i_eps_ba__tan = 2.0*E_td__tan*_x2 - _x0*_x2*i_bottom_q_r__tan*(2.0*i_bottom_q_r - 2.0*l0) - _x3*k_c__tan + _x3*k_d__tan
    # (internal helper: its callers check that their outputs are finite)
    return (i_eps_ba, i_eps_ba__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_1(E_td, E_td__tan, i_bottom_q_r, i_bottom_q_r__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m):
    """branch continuity = 1 of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_td: value of the caller's variable
        E_td__tan: value of the caller's variable
        i_bottom_q_r: value of the caller's variable
        i_bottom_q_r__tan: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable

    Returns a tuple:
        i_eps_ba: result for the caller
        i_eps_ba__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 24
    # as report
    _x0 = k_c - k_d
    _x1 = (-i_bottom_q_r + l0)**2
    _x2 = 1.0/(l0**2*m)
    _x3 = _x1*_x2
    i_eps_ba = _x2*(2.0*E_td - _x0*_x1)
    i_eps_ba__tan = 2.0*E_td__tan*_x2 - _x0*_x2*i_bottom_q_r__tan*(2.0*i_bottom_q_r - 2.0*l0) - _x3*k_c__tan + _x3*k_d__tan
    # (internal helper: its callers check that their outputs are finite)
    return (i_eps_ba, i_eps_ba__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_2(g_s, i_ba_omega, i_ba_omega__tan, i_bottom_q_r, i_bottom_q_r__tan, i_rho_b, i_rho_b__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m):
    """branch continuity = 2 of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        i_ba_omega: value of the caller's variable
        i_ba_omega__tan: value of the caller's variable
        i_bottom_q_r: value of the caller's variable
        i_bottom_q_r__tan: value of the caller's variable
        i_rho_b: value of the caller's variable
        i_rho_b__tan: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable

    Returns a tuple:
        i_eps_ba: result for the caller
        i_eps_ba__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 50
    # eqs (97)-(99) with E_ab Geyer's energy (8) at the bottom
    _x9 = (1.0/l0)
    _x0 = i_ba_omega**2
    _x1 = 2.0*_x9*g_s
    _x2 = -2.0*_x0 + _x1
    _x3 = i_rho_b**2
    _x4 = (1.0/m)
    _x5 = 3.0*_x0 + _x4*k_c
    _x6 = k_c - k_d
    _x7 = _x4*_x9**2
    _x8 = _x7*(-i_bottom_q_r + l0)**2
    i_eps_ba = _x0 + _x1 + _x2*i_rho_b + _x3*_x5 - _x6*_x8
    i_eps_ba__tan = -_x6*_x7*i_bottom_q_r__tan*(2.0*i_bottom_q_r - 2.0*l0) + _x8*k_d__tan + i_ba_omega__tan*(6.0*_x3*i_ba_omega - 4.0*i_ba_omega*i_rho_b + 2.0*i_ba_omega) + i_rho_b__tan*(_x2 + 2.0*_x5*i_rho_b) + k_c__tan*(_x3*_x4 - _x8)
    # (internal helper: its callers check that their outputs are finite)
    return (i_eps_ba, i_eps_ba__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_3():
    """branch gravity = 0 of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:

    Returns a tuple:
        i_P_new1: result for the caller
        i_P_new2: result for the caller
        i_P_new1__tan: result for the caller
        i_P_new2__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    i_P_new1 = 0.0
    i_P_new2 = 0.0
    # tangents the other branches define
    i_P_new1__tan = 0.0
    i_P_new2__tan = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new1, i_P_new2, i_P_new1__tan, i_P_new2__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_4(g_s, i_bottom_q_r, i_bottom_q_r__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, m, q_r_lo, q_r_td, q_r_td__tan, q_th_td, q_th_td__tan):
    """branch gravity = 1 of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        i_bottom_q_r: value of the caller's variable
        i_bottom_q_r__tan: value of the caller's variable
        i_bottom_q_th: value of the caller's variable
        i_bottom_q_th__tan: value of the caller's variable
        i_liftoff_q_th: value of the caller's variable
        i_liftoff_q_th__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        m: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable

    Returns a tuple:
        i_P_new1: result for the caller
        i_P_new2: result for the caller
        i_P_new1__tan: result for the caller
        i_P_new2__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 54
    # eq (65) on each half
    _x0 = g_s*m
    _x1 = _x0*math.sin(i_bottom_q_th)
    _x2 = _x1*i_bottom_q_r
    _x3 = _x0*math.sin(q_th_td)
    _x4 = _x3*q_r_td
    _x5 = (0.5)*i_t_bottom
    _x6 = _x1*i_bottom_q_r__tan
    _x7 = _x0*_x5
    _x8 = i_bottom_q_r*i_bottom_q_th__tan*math.cos(i_bottom_q_th)
    _x9 = (0.5)*_x2
    _x10 = _x0*q_r_lo
    _x11 = _x10*math.sin(i_liftoff_q_th)
    _x12 = -0.5*i_t_bottom + (0.5)*i_t_stance
    _x13 = (0.5)*_x11 + _x9
    i_P_new1 = _x5*(_x2 + _x4)
    i_P_new1__tan = _x3*_x5*q_r_td__tan + _x5*_x6 + _x7*_x8 + _x7*q_r_td*q_th_td__tan*math.cos(q_th_td) + i_t_bottom__tan*((0.5)*_x4 + _x9)
    i_P_new2 = _x12*(_x11 + _x2)
    i_P_new2__tan = _x0*_x12*_x8 + _x10*_x12*i_liftoff_q_th__tan*math.cos(i_liftoff_q_th) + _x12*_x6 - _x13*i_t_bottom__tan + _x13*i_t_stance__tan
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new1, i_P_new2, i_P_new1__tan, i_P_new2__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_5(g_s, i_ab_a, i_ab_a__tan, i_ab_b, i_ab_b__tan, i_ab_omega0_hat, i_ab_omega0_hat__tan, i_ab_phase_td, i_ab_phase_td__tan, i_ba_a, i_ba_a__tan, i_ba_b, i_ba_b__tan, i_ba_omega0_hat, i_ba_omega0_hat__tan, i_ba_phase_lo, i_ba_phase_lo__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0, m, q_th_td, q_th_td__tan):
    """branch gravity = 2 of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        i_ab_a: value of the caller's variable
        i_ab_a__tan: value of the caller's variable
        i_ab_b: value of the caller's variable
        i_ab_b__tan: value of the caller's variable
        i_ab_omega0_hat: value of the caller's variable
        i_ab_omega0_hat__tan: value of the caller's variable
        i_ab_phase_td: value of the caller's variable
        i_ab_phase_td__tan: value of the caller's variable
        i_ba_a: value of the caller's variable
        i_ba_a__tan: value of the caller's variable
        i_ba_b: value of the caller's variable
        i_ba_b__tan: value of the caller's variable
        i_ba_omega0_hat: value of the caller's variable
        i_ba_omega0_hat__tan: value of the caller's variable
        i_ba_phase_lo: value of the caller's variable
        i_ba_phase_lo__tan: value of the caller's variable
        i_bottom_q_th: value of the caller's variable
        i_bottom_q_th__tan: value of the caller's variable
        i_liftoff_q_th: value of the caller's variable
        i_liftoff_q_th__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable

    Returns a tuple:
        i_P_new1: result for the caller
        i_P_new2: result for the caller
        i_P_new1__tan: result for the caller
        i_P_new2__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 150
    # eq (76) on each half, the average leg length of (11) on it
    _x0 = (1.0/i_ab_omega0_hat)
    _x14 = (1.0/i_ba_omega0_hat)
    _x1 = -_x0*i_ab_phase_td + (1.5)*math.pi*_x0
    _x2 = (1.0/_x1)
    _x3 = math.cos(i_ab_phase_td)
    _x4 = i_ab_a + 1.0
    _x5 = (1.5)*math.pi
    _x6 = l0*(_x3*i_ab_b + _x4*_x5 - _x4*i_ab_phase_td)
    _x7 = _x2*_x6
    _x8 = _x0*_x7
    _x9 = _x0*_x2*l0
    _x10 = -_x5
    _x11 = _x0**2
    _x12 = _x2**2*_x6
    _x13 = _x3*_x9*i_ab_b__tan + _x9*i_ab_a__tan*(-_x10 - i_ab_phase_td) + i_ab_omega0_hat__tan*(_x0*_x12*(-_x11*i_ab_phase_td + (1.5)*math.pi*_x11) - _x11*_x7) + i_ab_phase_td__tan*(_x11*_x12 + _x9*(-_x4 - i_ab_b*math.sin(i_ab_phase_td)))
    _x15 = -_x14*_x5 + _x14*i_ba_phase_lo
    _x16 = (1.0/_x15)
    _x17 = math.cos(i_ba_phase_lo)
    _x18 = i_ba_a + 1.0
    _x19 = l0*(-_x17*i_ba_b - _x18*_x5 + _x18*i_ba_phase_lo)
    _x20 = _x16*_x19
    _x21 = _x14*_x20
    _x22 = _x14*_x16*l0
    _x23 = _x14**2
    _x24 = _x16**2*_x19
    _x25 = -_x17*_x22*i_ba_b__tan + _x22*i_ba_a__tan*(_x10 + i_ba_phase_lo) + i_ba_omega0_hat__tan*(_x14*_x24*(-_x23*_x5 + _x23*i_ba_phase_lo) - _x20*_x23) + i_ba_phase_lo__tan*(_x22*(_x18 + i_ba_b*math.sin(i_ba_phase_lo)) - _x23*_x24)
    _x26 = g_s*m
    _x27 = _x26*math.sin(i_bottom_q_th)
    _x28 = _x27*_x8
    _x29 = _x26*math.sin(q_th_td)
    _x30 = _x29*_x8
    _x31 = (0.5)*i_t_bottom
    _x32 = _x26*_x31*_x8
    _x33 = i_bottom_q_th__tan*math.cos(i_bottom_q_th)
    _x34 = _x21*_x27
    _x35 = _x26*math.sin(i_liftoff_q_th)
    _x36 = _x21*_x35
    _x37 = -0.5*i_t_bottom + (0.5)*i_t_stance
    _x38 = _x21*_x26*_x37
    _x39 = (0.5)*_x34 + (0.5)*_x36
    _i_L1 = _x8
    _i_L1__tan = _x13
    _i_L2 = _x21
    _i_L2__tan = _x25
    i_P_new1 = _x31*(_x28 + _x30)
    i_P_new1__tan = _x13*_x31*(_x27 + _x29) + _x32*_x33 + _x32*q_th_td__tan*math.cos(q_th_td) + i_t_bottom__tan*((0.5)*_x28 + (0.5)*_x30)
    i_P_new2 = _x37*(_x34 + _x36)
    i_P_new2__tan = _x25*_x37*(_x27 + _x35) + _x33*_x38 + _x38*i_liftoff_q_th__tan*math.cos(i_liftoff_q_th) - _x39*i_t_bottom__tan + _x39*i_t_stance__tan
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new1, i_P_new2, i_P_new1__tan, i_P_new2__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_6(E_td, E_td__tan, P_c_compression, P_c_compression__tan, P_c_decompression, P_c_decompression__tan, continuity, g_s, gravity, k_c, k_c__tan, k_d, k_d__tan, l0, m, p_td, p_td__tan, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan):
    """loop body of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_td: value of the caller's variable
        E_td__tan: value of the caller's variable
        P_c_compression: value of the caller's variable
        P_c_compression__tan: value of the caller's variable
        P_c_decompression: value of the caller's variable
        P_c_decompression__tan: value of the caller's variable
        continuity: value of the caller's variable
        g_s: value of the caller's variable
        gravity: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        p_td: value of the caller's variable
        p_td__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable

    Returns a tuple:
        _next_P_c_compression: result for the caller
        _next_P_c_decompression: result for the caller
        _next_P_c_compression__tan: result for the caller
        _next_P_c_decompression__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 429
    # the first half's mean momentum as a touchdown rate
    _x3 = (1.0/q_r_td)
    _x0 = (0.5)*P_c_compression + p_td
    _x1 = (1.0/m)
    _x2 = _x1*_x3**2
    i_q_thd_eff = _x0*_x2
    i_q_thd_eff__tan = (0.5)*P_c_compression__tan*_x2 - 2.0*_x0*_x1*_x3**3*q_r_td__tan + _x2*p_td__tan
    # eqs (78), (82)-(87): Geyer's radial solution with k_c from the touchdown state
    _c0 = geyer_solution_jvp_q_r_td_q_rd_td_q_thd_td_k(q_r_td, q_rd_td, i_q_thd_eff, m, l0, k_c, g_s, q_r_td__tan, q_rd_td__tan, i_q_thd_eff__tan, k_c__tan)
    if _c0[12] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, _c0[12])
    i_ab_omega = _c0[0]
    i_ab_omega0_hat = _c0[1]
    i_ab_a = _c0[2]
    i_ab_b = _c0[3]
    i_ab_phase_td = _c0[4]
    i_ab_s_td = _c0[5]
    i_ab_omega__tan = _c0[6]
    i_ab_omega0_hat__tan = _c0[7]
    i_ab_a__tan = _c0[8]
    i_ab_b__tan = _c0[9]
    i_ab_phase_td__tan = _c0[10]
    i_ab_s_td__tan = _c0[11]
    # eqs (79)-(81): the bottom at phase 3 pi/2
    _x4 = (1.0/i_ab_omega0_hat)
    _x30 = (1.0/l0)
    _x5 = -i_ab_phase_td + (1.5)*math.pi
    _x6 = _x4**2
    _x7 = i_ab_a - i_ab_b
    _x8 = _x7 + 1.0
    _x29 = (1.0/_x8)
    _x9 = i_ab_a__tan*l0 - i_ab_b__tan*l0
    _x10 = (1.5)*math.pi
    _x11 = _x4*i_ab_omega
    _x12 = _x4*i_ab_phase_td
    _x13 = 3.0*math.pi
    _x14 = _x11*_x13
    _x15 = _x12*i_ab_a
    _x16 = math.sqrt(1.0 - i_ab_s_td**2)
    _x17 = _x16*i_ab_b
    _x18 = _x17*_x4
    _x19 = 2.0*i_ab_omega
    _x20 = 2.0*_x11
    _x21 = _x13*i_ab_a
    _x22 = _x6*i_ab_phase_td
    _x23 = _x6*i_ab_omega
    _x24 = P_c_compression + p_td
    _x25 = P_c_compression__tan + p_td__tan
    _x26 = (1.0/m)
    _x27 = _x24*_x26
    _x28 = _x29**2*_x30**2
    i_t_bottom = _x4*_x5
    i_t_bottom__tan = -_x4*i_ab_phase_td__tan - _x5*_x6*i_ab_omega0_hat__tan
    i_bottom_q_r = _x8*l0
    i_bottom_q_r__tan = _x9
    i_bottom_q_rd = 0.0
    i_bottom_q_th = _x10*_x11 - _x12*i_ab_omega - _x14*i_ab_a + _x19*(_x15 + _x18) + q_th_td
    i_bottom_q_th__tan = _x16*_x20*i_ab_b__tan + i_ab_a__tan*(_x12*_x19 - _x14) + i_ab_omega0_hat__tan*(-_x10*_x23 + _x19*(-_x17*_x6 - _x22*i_ab_a) + _x21*_x23 + _x22*i_ab_omega) + i_ab_omega__tan*(_x10*_x4 - _x12 + 2.0*_x15 + 2.0*_x18 - _x21*_x4) + i_ab_phase_td__tan*(-_x11 + _x20*i_ab_a) + q_th_td__tan - _x20*i_ab_b*i_ab_s_td*i_ab_s_td__tan/_x16
    i_p_b = _x24
    i_p_b__tan = _x25
    i_bottom_q_thd = _x27*_x28
    i_bottom_q_thd__tan = _x25*_x26*_x28 - 2.0*_x27*_x29**3*_x30**3*_x9
    i_rho_b = _x7
    i_rho_b__tan = _x30*_x9
    # eqs (100)-(103): omega_ba from the momentum, omega0_ba^2 = k_d/m
    _x47 = (1.0/l0)
    _x33 = (1.0/m)
    _x31 = (0.5)*P_c_decompression + i_p_b
    _x32 = _x47**2
    _x34 = _x32*_x33
    _x35 = (0.5)*P_c_decompression__tan*_x34 + _x34*i_p_b__tan
    _x36 = (1.0/math.sqrt(m))
    _x37 = _x31**2
    _x38 = 3.0*_x33*_x37*_x47**4 + k_d
    _x42 = (1.0/_x38)
    _x39 = math.sqrt(_x38)
    _x40 = _x36/_x39
    _x41 = _x31*_x32
    _x43 = _x47**3
    _x44 = m*(_x33**2*_x37*_x43 - g_s)
    _x45 = _x44*_x47
    _x46 = _x42**2
    i_ba_omega = _x31*_x34
    i_ba_omega__tan = _x35
    i_ba_omega0_hat = _x36*_x39
    i_ba_omega0_hat__tan = 3.0*_x35*_x40*_x41 + (0.5)*_x40*k_d__tan
    i_ba_a_free = _x42*_x45
    i_ba_a_free__tan = _x35*(-6.0*_x31*_x43*_x44*_x46 + 2.0*_x41*_x42) - _x45*_x46*k_d__tan
    # with k_d the bottom lies below the centre a_ba of (90): the leg extends
    if not ((i_rho_b < i_ba_a_free)):
        return (NAN, NAN, NAN, NAN, STATUS_RECOMPRESSION)
    # E_ab of (98)
    if continuity == 0.0:
        # branch continuity = 0
        _c1 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_0(E_td, E_td__tan, i_bottom_q_r, i_bottom_q_r__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m)
        if _c1[2] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, _c1[2])
        i_eps_ba = _c1[0]
        i_eps_ba__tan = _c1[1]
    elif continuity == 1.0:
        # branch continuity = 1
        _c2 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_1(E_td, E_td__tan, i_bottom_q_r, i_bottom_q_r__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m)
        if _c2[2] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, _c2[2])
        i_eps_ba = _c2[0]
        i_eps_ba__tan = _c2[1]
    elif continuity == 2.0:
        # branch continuity = 2
        _c3 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_2(g_s, i_ba_omega, i_ba_omega__tan, i_bottom_q_r, i_bottom_q_r__tan, i_rho_b, i_rho_b__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m)
        if _c3[2] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, _c3[2])
        i_eps_ba = _c3[0]
        i_eps_ba__tan = _c3[1]
    else:
        return (NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    _x48 = i_ba_omega**2
    _x49 = 3.0*_x48*m + k_d
    _x60 = (1.0/_x49)
    _x50 = _x60**2*m
    _x51 = l0**2
    _x52 = (1.0/_x51)
    _x53 = -_x48*l0 + g_s
    _x54 = 2.0*g_s - l0*(-_x48 + i_eps_ba)
    _x55 = _x54*l0
    _x56 = _x49*_x55 - _x53**2*m
    _x57 = _x52*_x56
    _x58 = _x60**3
    _x59 = i_ba_omega*m
    i_ba_b2 = -_x50*_x57
    i_ba_b2__tan = _x60*i_eps_ba__tan*m + i_ba_omega__tan*(-_x50*_x52*(2.0*_x49*_x51*i_ba_omega + 4.0*_x53*_x59*l0 + 6.0*_x55*_x59) + 12.0*_x57*_x58*i_ba_omega*m**2) + k_d__tan*(-_x50*_x54/l0 + 2.0*_x52*_x56*_x58*m)
    # eq (104): real amplitude b_ba
    if not ((i_ba_b2 > 0.0)):
        return (NAN, NAN, NAN, NAN, STATUS_NO_REAL_SOLUTION)
    # eq (104); eq (103), or (111) when constrained
    _x61 = math.sqrt(i_ba_b2)
    _x62 = (0.5)*i_ba_b2__tan/_x61
    _x63 = (continuity == 1.0)
    _x64 = ((1.0) if _x63 else (0.0))
    i_ba_b = _x61
    i_ba_b__tan = _x62
    i_ba_a = ((_x61 + i_rho_b) if _x63 else (i_ba_a_free))
    i_ba_a__tan = _x62*_x64 + _x64*i_rho_b__tan + i_ba_a_free__tan*((0.0) if _x63 else (1.0))
    # eq (94): the liftoff phase of the second half
    _c4 = geyer_liftoff_phase_jvp_a_b(i_ba_a, i_ba_b, l0, q_r_lo, i_ba_a__tan, i_ba_b__tan)
    if _c4[4] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, _c4[4])
    i_ba_phase_lo = _c4[0]
    i_ba_s_lo = _c4[1]
    i_ba_phase_lo__tan = _c4[2]
    i_ba_s_lo__tan = _c4[3]
    # eqs (90)-(94) at liftoff
    _x65 = (1.0/i_ba_omega0_hat)
    _x82 = (1.0/m)
    _x66 = (1.5)*math.pi
    _x67 = -_x66 + i_ba_phase_lo
    _x68 = _x65**2
    _x69 = _x65*i_ba_phase_lo
    _x70 = _x65*i_ba_omega
    _x71 = 3.0*math.pi
    _x72 = _x69*i_ba_a
    _x73 = math.sqrt(1.0 - i_ba_s_lo**2)
    _x74 = _x65*_x73*i_ba_b
    _x75 = 2.0*i_ba_omega
    _x76 = -_x66*_x70 + _x69*i_ba_omega + _x70*_x71*i_ba_a - _x75*(_x72 - _x74) + i_bottom_q_th
    _x77 = 2.0*_x70
    _x78 = _x71*i_ba_a
    _x79 = _x68*i_ba_phase_lo
    _x80 = _x73*_x77*i_ba_b__tan + i_ba_a__tan*(3.0*math.pi*_x65*i_ba_omega - _x69*_x75) + i_ba_omega0_hat__tan*(-_x68*_x78*i_ba_omega + (1.5)*math.pi*_x68*i_ba_omega - _x75*(_x68*_x73*i_ba_b - _x79*i_ba_a) - _x79*i_ba_omega) + i_ba_omega__tan*(-_x65*_x66 + _x65*_x78 + _x69 - 2.0*_x72 + 2.0*_x74) + i_ba_phase_lo__tan*(_x65*i_ba_omega - _x77*i_ba_a) + i_bottom_q_th__tan - _x77*i_ba_b*i_ba_s_lo*i_ba_s_lo__tan/_x73
    _x81 = P_c_decompression + i_p_b
    _x83 = q_r_lo**2
    _x84 = (1.0/_x83)
    _x85 = _x82*_x84
    _x86 = _x82*l0**2
    _x87 = _x82*_x83
    _x88 = _x82**2*_x84
    _x89 = k_c - k_d
    _x90 = (-i_bottom_q_r + l0)**2
    _x91 = _x88*(2.0*P_c_decompression + 2.0*i_p_b)
    i_t_stance = _x65*_x67 + i_t_bottom
    i_t_stance__tan = _x65*i_ba_phase_lo__tan - _x67*_x68*i_ba_omega0_hat__tan + i_t_bottom__tan
    i_liftoff_q_r = q_r_lo
    i_liftoff_q_th = _x76
    i_liftoff_q_th__tan = _x80
    i_liftoff_q_thd = _x81*_x85
    i_liftoff_q_thd__tan = P_c_decompression__tan*_x85 + _x85*i_p_b__tan
    i_q_rd_lo_sq = -_x81**2*_x88 + 2.0*_x82*k_d*l0*q_r_lo + 2.0*_x82*(E_td - 0.5*_x89*_x90) - _x86*k_d - _x87*k_d - 2.0*g_s*q_r_lo*math.cos(_x76)
    i_q_rd_lo_sq__tan = 2.0*E_td__tan*_x82 - P_c_decompression__tan*_x91 + 2.0*_x80*g_s*q_r_lo*math.sin(_x76) - _x82*_x89*i_bottom_q_r__tan*(2.0*i_bottom_q_r - 2.0*l0) - _x82*_x90*k_c__tan - _x91*i_p_b__tan + k_d__tan*(_x82*_x90 + 2.0*_x82*l0*q_r_lo - _x86 - _x87)
    # the leg stays above horizontal
    if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
        return (NAN, NAN, NAN, NAN, STATUS_FALL)
    # q_rd_lo^2 from the energy
    if not ((gravity == 0.0) or (i_q_rd_lo_sq >= 0.0)):
        return (NAN, NAN, NAN, NAN, STATUS_ENERGY_DEFICIT)
    # q_rd_lo: (11) without a gravity correction, the energy with one
    _x92 = math.sqrt(1.0 - i_ba_s_lo**2)
    _x93 = _x92*l0
    _x94 = _x93*i_ba_omega0_hat
    _x95 = (gravity == 0.0)
    _x96 = math.sqrt(i_q_rd_lo_sq)
    i_liftoff_q_rd = ((_x94*i_ba_b) if _x95 else (_x96))
    i_liftoff_q_rd__tan = i_ba_b__tan*((_x94) if _x95 else (0.0)) + i_ba_omega0_hat__tan*((_x93*i_ba_b) if _x95 else (0.0)) + i_ba_s_lo__tan*((-i_ba_b*i_ba_omega0_hat*i_ba_s_lo*l0/_x92) if _x95 else (0.0)) + i_q_rd_lo_sq__tan*((0.0) if _x95 else ((0.5)/_x96))
    # the virtual gravity effect of each half
    if gravity == 0.0:
        # branch gravity = 0
        _c5 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_3()
        if _c5[4] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, _c5[4])
        i_P_new1 = _c5[0]
        i_P_new2 = _c5[1]
        i_P_new1__tan = _c5[2]
        i_P_new2__tan = _c5[3]
    elif gravity == 1.0:
        # branch gravity = 1
        _c6 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_4(g_s, i_bottom_q_r, i_bottom_q_r__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, m, q_r_lo, q_r_td, q_r_td__tan, q_th_td, q_th_td__tan)
        if _c6[4] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, _c6[4])
        i_P_new1 = _c6[0]
        i_P_new2 = _c6[1]
        i_P_new1__tan = _c6[2]
        i_P_new2__tan = _c6[3]
    elif gravity == 2.0:
        # branch gravity = 2
        _c7 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_5(g_s, i_ab_a, i_ab_a__tan, i_ab_b, i_ab_b__tan, i_ab_omega0_hat, i_ab_omega0_hat__tan, i_ab_phase_td, i_ab_phase_td__tan, i_ba_a, i_ba_a__tan, i_ba_b, i_ba_b__tan, i_ba_omega0_hat, i_ba_omega0_hat__tan, i_ba_phase_lo, i_ba_phase_lo__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0, m, q_th_td, q_th_td__tan)
        if _c7[4] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, _c7[4])
        i_P_new1 = _c7[0]
        i_P_new2 = _c7[1]
        i_P_new1__tan = _c7[2]
        i_P_new2__tan = _c7[3]
    else:
        return (NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # next values
    _next_P_c_compression = i_P_new1
    _next_P_c_decompression = i_P_new2
    _next_P_c_compression__tan = i_P_new1__tan
    _next_P_c_decompression__tan = i_P_new2__tan
    # (internal helper: its callers check that their outputs are finite)
    return (_next_P_c_compression, _next_P_c_decompression, _next_P_c_compression__tan, _next_P_c_decompression__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_7(E_td, E_td__tan, bottom_q_r, bottom_q_r__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m):
    """branch continuity = 0 of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_td: value of the caller's variable
        E_td__tan: value of the caller's variable
        bottom_q_r: value of the caller's variable
        bottom_q_r__tan: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable

    Returns a tuple:
        eps_ba: result for the caller
        eps_ba__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 24
    # eqs (97)-(99), E_ab the energy (27)
    _x0 = k_c - k_d
    _x1 = (-bottom_q_r + l0)**2
    _x2 = 1.0/(l0**2*m)
    _x3 = _x1*_x2
    eps_ba = _x2*(2.0*E_td - _x0*_x1)
    eps_ba__tan = 2.0*E_td__tan*_x2 - _x0*_x2*bottom_q_r__tan*(2.0*bottom_q_r - 2.0*l0) - _x3*k_c__tan + _x3*k_d__tan
    # (internal helper: its callers check that their outputs are finite)
    return (eps_ba, eps_ba__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_8(E_td, E_td__tan, bottom_q_r, bottom_q_r__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m):
    """branch continuity = 1 of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_td: value of the caller's variable
        E_td__tan: value of the caller's variable
        bottom_q_r: value of the caller's variable
        bottom_q_r__tan: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable

    Returns a tuple:
        eps_ba: result for the caller
        eps_ba__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 24
    # as report
    _x0 = k_c - k_d
    _x1 = (-bottom_q_r + l0)**2
    _x2 = 1.0/(l0**2*m)
    _x3 = _x1*_x2
    eps_ba = _x2*(2.0*E_td - _x0*_x1)
    eps_ba__tan = 2.0*E_td__tan*_x2 - _x0*_x2*bottom_q_r__tan*(2.0*bottom_q_r - 2.0*l0) - _x3*k_c__tan + _x3*k_d__tan
    # (internal helper: its callers check that their outputs are finite)
    return (eps_ba, eps_ba__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_9(ba_omega, ba_omega__tan, bottom_q_r, bottom_q_r__tan, g_s, k_c, k_c__tan, k_d, k_d__tan, l0, m, rho_b, rho_b__tan):
    """branch continuity = 2 of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        ba_omega: value of the caller's variable
        ba_omega__tan: value of the caller's variable
        bottom_q_r: value of the caller's variable
        bottom_q_r__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        rho_b: value of the caller's variable
        rho_b__tan: value of the caller's variable

    Returns a tuple:
        eps_ba: result for the caller
        eps_ba__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 53
    # eqs (97)-(99) with E_ab Geyer's energy (8) at the bottom
    _x1 = (1.0/l0)
    _x0 = ba_omega**2
    _x2 = 2.0*_x1*g_s
    _x3 = 2.0*_x0
    _x4 = rho_b**2
    _x5 = (1.0/m)
    _x6 = 3.0*_x0 + _x5*k_c
    _x7 = k_c - k_d
    _x8 = _x1**2*_x5
    _x9 = _x8*(-bottom_q_r + l0)**2
    eps_ba = _x0 + _x2 + _x4*_x6 - _x7*_x9 + rho_b*(2.0*_x1*g_s - _x3)
    eps_ba__tan = -_x7*_x8*bottom_q_r__tan*(2.0*bottom_q_r - 2.0*l0) + _x9*k_d__tan + ba_omega__tan*(6.0*_x4*ba_omega - 4.0*ba_omega*rho_b + 2.0*ba_omega) + k_c__tan*(_x4*_x5 - _x9) + rho_b__tan*(_x2 - _x3 + 2.0*_x6*rho_b)
    # (internal helper: its callers check that their outputs are finite)
    return (eps_ba, eps_ba__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_10(E_td, E_td__tan, P_c_compression, P_c_compression__tan, P_c_decompression, P_c_decompression__tan, continuity, g_s, gravity, k_c, k_c__tan, k_d, k_d__tan, l0, m, p_td, p_td__tan, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan):
    """continuation of geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_td: value of the caller's variable
        E_td__tan: value of the caller's variable
        P_c_compression: value of the caller's variable
        P_c_compression__tan: value of the caller's variable
        P_c_decompression: value of the caller's variable
        P_c_decompression__tan: value of the caller's variable
        continuity: value of the caller's variable
        g_s: value of the caller's variable
        gravity: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        p_td: value of the caller's variable
        p_td__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable

    Returns a tuple:
        t_bottom: result for the caller
        t_stance: result for the caller
        bottom_q_r: result for the caller
        bottom_q_rd: result for the caller
        bottom_q_th: result for the caller
        bottom_q_thd: result for the caller
        liftoff_q_r: result for the caller
        liftoff_q_rd: result for the caller
        liftoff_q_th: result for the caller
        liftoff_q_thd: result for the caller
        t_bottom__tan: result for the caller
        t_stance__tan: result for the caller
        bottom_q_r__tan: result for the caller
        bottom_q_rd__tan: result for the caller
        bottom_q_th__tan: result for the caller
        bottom_q_thd__tan: result for the caller
        liftoff_q_r__tan: result for the caller
        liftoff_q_rd__tan: result for the caller
        liftoff_q_th__tan: result for the caller
        liftoff_q_thd__tan: result for the caller
        passes__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 429
    # the first half's mean momentum as a touchdown rate
    _x3 = (1.0/q_r_td)
    _x0 = (0.5)*P_c_compression + p_td
    _x1 = (1.0/m)
    _x2 = _x1*_x3**2
    q_thd_eff = _x0*_x2
    q_thd_eff__tan = (0.5)*P_c_compression__tan*_x2 - 2.0*_x0*_x1*_x3**3*q_r_td__tan + _x2*p_td__tan
    # eqs (78), (82)-(87): Geyer's radial solution with k_c from the touchdown state
    _c0 = geyer_solution_jvp_q_r_td_q_rd_td_q_thd_td_k(q_r_td, q_rd_td, q_thd_eff, m, l0, k_c, g_s, q_r_td__tan, q_rd_td__tan, q_thd_eff__tan, k_c__tan)
    if _c0[12] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[12])
    ab_omega = _c0[0]
    ab_omega0_hat = _c0[1]
    ab_a = _c0[2]
    ab_b = _c0[3]
    ab_phase_td = _c0[4]
    ab_s_td = _c0[5]
    ab_omega__tan = _c0[6]
    ab_omega0_hat__tan = _c0[7]
    ab_a__tan = _c0[8]
    ab_b__tan = _c0[9]
    ab_phase_td__tan = _c0[10]
    ab_s_td__tan = _c0[11]
    # eqs (79)-(81): the bottom at phase 3 pi/2
    _x4 = (1.0/ab_omega0_hat)
    _x30 = (1.0/l0)
    _x5 = -ab_phase_td + (1.5)*math.pi
    _x6 = _x4**2
    _x7 = ab_a - ab_b
    _x8 = _x7 + 1.0
    _x29 = (1.0/_x8)
    _x9 = ab_a__tan*l0 - ab_b__tan*l0
    _x10 = (1.5)*math.pi
    _x11 = _x4*ab_omega
    _x12 = _x4*ab_phase_td
    _x13 = 3.0*math.pi
    _x14 = _x11*_x13
    _x15 = _x12*ab_a
    _x16 = math.sqrt(1.0 - ab_s_td**2)
    _x17 = _x16*ab_b
    _x18 = _x17*_x4
    _x19 = 2.0*ab_omega
    _x20 = 2.0*_x11
    _x21 = _x13*ab_a
    _x22 = _x6*ab_phase_td
    _x23 = _x6*ab_omega
    _x24 = P_c_compression + p_td
    _x25 = P_c_compression__tan + p_td__tan
    _x26 = (1.0/m)
    _x27 = _x24*_x26
    _x28 = _x29**2*_x30**2
    t_bottom = _x4*_x5
    t_bottom__tan = -_x4*ab_phase_td__tan - _x5*_x6*ab_omega0_hat__tan
    bottom_q_r = _x8*l0
    bottom_q_r__tan = _x9
    bottom_q_rd = 0.0
    bottom_q_th = _x10*_x11 - _x12*ab_omega - _x14*ab_a + _x19*(_x15 + _x18) + q_th_td
    bottom_q_th__tan = _x16*_x20*ab_b__tan + ab_a__tan*(_x12*_x19 - _x14) + ab_omega0_hat__tan*(-_x10*_x23 + _x19*(-_x17*_x6 - _x22*ab_a) + _x21*_x23 + _x22*ab_omega) + ab_omega__tan*(_x10*_x4 - _x12 + 2.0*_x15 + 2.0*_x18 - _x21*_x4) + ab_phase_td__tan*(-_x11 + _x20*ab_a) + q_th_td__tan - _x20*ab_b*ab_s_td*ab_s_td__tan/_x16
    p_b = _x24
    p_b__tan = _x25
    bottom_q_thd = _x27*_x28
    bottom_q_thd__tan = _x25*_x26*_x28 - 2.0*_x27*_x29**3*_x30**3*_x9
    rho_b = _x7
    rho_b__tan = _x30*_x9
    # eqs (100)-(103): omega_ba from the momentum, omega0_ba^2 = k_d/m
    _x47 = (1.0/l0)
    _x33 = (1.0/m)
    _x31 = (0.5)*P_c_decompression + p_b
    _x32 = _x47**2
    _x34 = _x32*_x33
    _x35 = (0.5)*P_c_decompression__tan*_x34 + _x34*p_b__tan
    _x36 = (1.0/math.sqrt(m))
    _x37 = _x31**2
    _x38 = 3.0*_x33*_x37*_x47**4 + k_d
    _x42 = (1.0/_x38)
    _x39 = math.sqrt(_x38)
    _x40 = _x36/_x39
    _x41 = _x31*_x32
    _x43 = _x47**3
    _x44 = m*(_x33**2*_x37*_x43 - g_s)
    _x45 = _x44*_x47
    _x46 = _x42**2
    ba_omega = _x31*_x34
    ba_omega__tan = _x35
    ba_omega0_hat = _x36*_x39
    ba_omega0_hat__tan = 3.0*_x35*_x40*_x41 + (0.5)*_x40*k_d__tan
    ba_a_free = _x42*_x45
    ba_a_free__tan = _x35*(-6.0*_x31*_x43*_x44*_x46 + 2.0*_x41*_x42) - _x45*_x46*k_d__tan
    # with k_d the bottom lies below the centre a_ba of (90): the leg extends
    if not ((rho_b < ba_a_free)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_RECOMPRESSION)
    # E_ab of (98)
    if continuity == 0.0:
        # branch continuity = 0
        _c1 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_7(E_td, E_td__tan, bottom_q_r, bottom_q_r__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m)
        if _c1[2] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[2])
        eps_ba = _c1[0]
        eps_ba__tan = _c1[1]
    elif continuity == 1.0:
        # branch continuity = 1
        _c2 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_8(E_td, E_td__tan, bottom_q_r, bottom_q_r__tan, k_c, k_c__tan, k_d, k_d__tan, l0, m)
        if _c2[2] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[2])
        eps_ba = _c2[0]
        eps_ba__tan = _c2[1]
    elif continuity == 2.0:
        # branch continuity = 2
        _c3 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_9(ba_omega, ba_omega__tan, bottom_q_r, bottom_q_r__tan, g_s, k_c, k_c__tan, k_d, k_d__tan, l0, m, rho_b, rho_b__tan)
        if _c3[2] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[2])
        eps_ba = _c3[0]
        eps_ba__tan = _c3[1]
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    _x48 = ba_omega**2
    _x49 = 3.0*_x48*m + k_d
    _x60 = (1.0/_x49)
    _x50 = _x60**2*m
    _x51 = l0**2
    _x52 = (1.0/_x51)
    _x53 = -_x48*l0 + g_s
    _x54 = 2.0*g_s - l0*(-_x48 + eps_ba)
    _x55 = _x54*l0
    _x56 = _x49*_x55 - _x53**2*m
    _x57 = _x52*_x56
    _x58 = _x60**3
    _x59 = ba_omega*m
    ba_b2 = -_x50*_x57
    ba_b2__tan = _x60*eps_ba__tan*m + ba_omega__tan*(-_x50*_x52*(2.0*_x49*_x51*ba_omega + 4.0*_x53*_x59*l0 + 6.0*_x55*_x59) + 12.0*_x57*_x58*ba_omega*m**2) + k_d__tan*(-_x50*_x54/l0 + 2.0*_x52*_x56*_x58*m)
    # eq (104): real amplitude b_ba
    if not ((ba_b2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_REAL_SOLUTION)
    # eq (104); eq (103), or (111) when constrained
    _x61 = math.sqrt(ba_b2)
    _x62 = (0.5)*ba_b2__tan/_x61
    _x63 = (continuity == 1.0)
    _x64 = ((1.0) if _x63 else (0.0))
    ba_b = _x61
    ba_b__tan = _x62
    ba_a = ((_x61 + rho_b) if _x63 else (ba_a_free))
    ba_a__tan = _x62*_x64 + _x64*rho_b__tan + ba_a_free__tan*((0.0) if _x63 else (1.0))
    # eq (94): the liftoff phase of the second half
    _c4 = geyer_liftoff_phase_jvp_a_b(ba_a, ba_b, l0, q_r_lo, ba_a__tan, ba_b__tan)
    if _c4[4] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[4])
    ba_phase_lo = _c4[0]
    ba_s_lo = _c4[1]
    ba_phase_lo__tan = _c4[2]
    ba_s_lo__tan = _c4[3]
    # eqs (90)-(94) at liftoff
    _x65 = (1.0/ba_omega0_hat)
    _x82 = (1.0/m)
    _x66 = (1.5)*math.pi
    _x67 = -_x66 + ba_phase_lo
    _x68 = _x65**2
    _x69 = _x65*ba_phase_lo
    _x70 = _x65*ba_omega
    _x71 = 3.0*math.pi
    _x72 = _x69*ba_a
    _x73 = math.sqrt(1.0 - ba_s_lo**2)
    _x74 = _x65*_x73*ba_b
    _x75 = 2.0*ba_omega
    _x76 = -_x66*_x70 + _x69*ba_omega + _x70*_x71*ba_a - _x75*(_x72 - _x74) + bottom_q_th
    _x77 = 2.0*_x70
    _x78 = _x71*ba_a
    _x79 = _x68*ba_phase_lo
    _x80 = _x73*_x77*ba_b__tan + ba_a__tan*(3.0*math.pi*_x65*ba_omega - _x69*_x75) + ba_omega0_hat__tan*(-_x68*_x78*ba_omega + (1.5)*math.pi*_x68*ba_omega - _x75*(_x68*_x73*ba_b - _x79*ba_a) - _x79*ba_omega) + ba_omega__tan*(-_x65*_x66 + _x65*_x78 + _x69 - 2.0*_x72 + 2.0*_x74) + ba_phase_lo__tan*(_x65*ba_omega - _x77*ba_a) + bottom_q_th__tan - _x77*ba_b*ba_s_lo*ba_s_lo__tan/_x73
    _x81 = P_c_decompression + p_b
    _x83 = q_r_lo**2
    _x84 = (1.0/_x83)
    _x85 = _x82*_x84
    _x86 = _x82*l0**2
    _x87 = _x82*_x83
    _x88 = _x82**2*_x84
    _x89 = k_c - k_d
    _x90 = (-bottom_q_r + l0)**2
    _x91 = _x88*(2.0*P_c_decompression + 2.0*p_b)
    t_stance = _x65*_x67 + t_bottom
    t_stance__tan = _x65*ba_phase_lo__tan - _x67*_x68*ba_omega0_hat__tan + t_bottom__tan
    liftoff_q_r = q_r_lo
    liftoff_q_th = _x76
    liftoff_q_th__tan = _x80
    liftoff_q_thd = _x81*_x85
    liftoff_q_thd__tan = P_c_decompression__tan*_x85 + _x85*p_b__tan
    q_rd_lo_sq = -_x81**2*_x88 + 2.0*_x82*k_d*l0*q_r_lo + 2.0*_x82*(E_td - 0.5*_x89*_x90) - _x86*k_d - _x87*k_d - 2.0*g_s*q_r_lo*math.cos(_x76)
    q_rd_lo_sq__tan = 2.0*E_td__tan*_x82 - P_c_decompression__tan*_x91 + 2.0*_x80*g_s*q_r_lo*math.sin(_x76) - _x82*_x89*bottom_q_r__tan*(2.0*bottom_q_r - 2.0*l0) - _x82*_x90*k_c__tan - _x91*p_b__tan + k_d__tan*(_x82*_x90 + 2.0*_x82*l0*q_r_lo - _x86 - _x87)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # q_rd_lo^2 from the energy
    if not ((gravity == 0.0) or (q_rd_lo_sq >= 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_ENERGY_DEFICIT)
    # q_rd_lo: (11) without a gravity correction, the energy with one
    _x92 = math.sqrt(1.0 - ba_s_lo**2)
    _x93 = _x92*l0
    _x94 = _x93*ba_omega0_hat
    _x95 = (gravity == 0.0)
    _x96 = math.sqrt(q_rd_lo_sq)
    liftoff_q_rd = ((_x94*ba_b) if _x95 else (_x96))
    liftoff_q_rd__tan = ba_b__tan*((_x94) if _x95 else (0.0)) + ba_omega0_hat__tan*((_x93*ba_b) if _x95 else (0.0)) + ba_s_lo__tan*((-ba_b*ba_omega0_hat*ba_s_lo*l0/_x92) if _x95 else (0.0)) + q_rd_lo_sq__tan*((0.0) if _x95 else ((0.5)/_x96))
    # derivatives that are identically zero
    bottom_q_rd__tan = 0.0
    liftoff_q_r__tan = 0.0
    passes__tan = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, k_d__tan):
    """Simple variable-stiffness map (Geyer et al. per half): touchdown state -> bottom and liftoff states, with the derivative of every output along the direction (q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, k_d__tan).

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113.

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
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0 = report, 1 = constrained, 2 = energy
        gravity: option gravity: virtual gravity effect on p_th per half (report 4.4-4.5 on [t_td, t_b] and [t_b, t_lo]); each half runs with its mean momentum, the rates with the momentum at that instant: 0 = none, 1 = type3, 2 = type4
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0, 1]
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
        P_c_compression: virtual gravity effect of the first half (0 unless gravity) [N m s]
        P_c_decompression: virtual gravity effect of the second half [N m s]
        passes: fixed-point passes run (0 unless gravity)
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
        P_c_compression__tan: derivative of P_c_compression along the direction
        P_c_decompression__tan: derivative of P_c_decompression along the direction
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 52
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(continuity) and math.isfinite(gravity) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(q_r_td__tan) and math.isfinite(q_rd_td__tan) and math.isfinite(q_th_td__tan) and math.isfinite(q_thd_td__tan) and math.isfinite(k_c__tan) and math.isfinite(k_d__tan) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((continuity == 0.0) or (continuity == 1.0) or (continuity == 2.0)) and ((gravity == 0.0) or (gravity == 1.0) or (gravity == 2.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = _x1*q_thd_td
    _x3 = l0*q_r_td
    _x4 = (0.5)*l0**2
    _x5 = (0.5)*_x0
    _x6 = g_s*m
    _x7 = _x6*math.cos(q_th_td)
    _x8 = m*q_thd_td**2
    p_td = _x2
    p_td__tan = _x1*q_thd_td__tan + 2.0*m*q_r_td*q_r_td__tan*q_thd_td
    E_td = -_x3*k_c + _x4*k_c + _x5*_x8 + _x5*k_c + _x7*q_r_td + (0.5)*m*q_rd_td**2
    E_td__tan = _x2*q_thd_td__tan - _x6*q_r_td*q_th_td__tan*math.sin(q_th_td) + k_c__tan*(-_x3 + _x4 + _x5) + m*q_rd_td*q_rd_td__tan + q_r_td__tan*(_x7 + _x8*q_r_td - k_c*l0 + k_c*q_r_td)
    # fixed point of the two halves' virtual gravity effects, from 0 (none: no pass)
    P_c_compression = 0.0
    P_c_decompression = 0.0
    P_c_compression__tan = 0.0
    P_c_decompression__tan = 0.0
    passes = 0.0
    _conv0 = False
    for _it0 in range(int(((0.0) if (gravity == 0.0) else (iterations)))):
        # loop body
        _c0 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_6(E_td, E_td__tan, P_c_compression, P_c_compression__tan, P_c_decompression, P_c_decompression__tan, continuity, g_s, gravity, k_c, k_c__tan, k_d, k_d__tan, l0, m, p_td, p_td__tan, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan)
        if _c0[4] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[4])
        _next_P_c_compression = _c0[0]
        _next_P_c_decompression = _c0[1]
        _next_P_c_compression__tan = _c0[2]
        _next_P_c_decompression__tan = _c0[3]
        _n0_0 = _next_P_c_compression
        _n0_1 = _next_P_c_decompression
        _n0_2 = _next_P_c_compression__tan
        _n0_3 = _next_P_c_decompression__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - P_c_compression) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + abs(p_td))) and (abs(_n0_1 - P_c_decompression) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + abs(p_td)))
        P_c_compression = _n0_0
        P_c_decompression = _n0_1
        P_c_compression__tan = _n0_2
        P_c_decompression__tan = _n0_3
        passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_10(E_td, E_td__tan, P_c_compression, P_c_compression__tan, P_c_decompression, P_c_decompression__tan, continuity, g_s, gravity, k_c, k_c__tan, k_d, k_d__tan, l0, m, p_td, p_td__tan, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan)
    if _c1[21] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[21])
    t_bottom = _c1[0]
    t_stance = _c1[1]
    bottom_q_r = _c1[2]
    bottom_q_rd = _c1[3]
    bottom_q_th = _c1[4]
    bottom_q_thd = _c1[5]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    t_bottom__tan = _c1[10]
    t_stance__tan = _c1[11]
    bottom_q_r__tan = _c1[12]
    bottom_q_rd__tan = _c1[13]
    bottom_q_th__tan = _c1[14]
    bottom_q_thd__tan = _c1[15]
    liftoff_q_r__tan = _c1[16]
    liftoff_q_rd__tan = _c1[17]
    liftoff_q_th__tan = _c1[18]
    liftoff_q_thd__tan = _c1[19]
    passes__tan = _c1[20]
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c_compression, P_c_decompression, passes, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, P_c_compression__tan, P_c_decompression__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def bottom_quartic_jvp_p_E_ab_k_c_0(E_ab, E_ab__tan, g_s, k_c, k_c__tan, l0, m, p, p__tan, qb, qb__tan):
    """loop body of bottom_quartic_jvp_p_E_ab_k_c (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_ab: value of the caller's variable
        E_ab__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        p: value of the caller's variable
        p__tan: value of the caller's variable
        qb: value of the caller's variable
        qb__tan: value of the caller's variable

    Returns a tuple:
        _next_qb: result for the caller
        _next_qb__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 75
    _x3 = (1.0/qb)
    _x0 = _x3**3
    _x1 = (1.0/m)
    _x2 = _x1*p**2
    slope = -_x0*_x2 + g_s*m - k_c*l0 + k_c*qb
    slope__tan = -2.0*_x0*_x1*p*p__tan + k_c__tan*(-l0 + qb) + qb__tan*(3.0*_x2*_x3**4 + k_c)
    # V decreasing left of the root
    if not ((slope < 0.0)):
        return (NAN, NAN, STATUS_NO_REAL_SOLUTION)
    # next values
    _x4 = (1.0/slope)
    _x5 = g_s*m
    _x6 = k_c*qb
    _x7 = (0.5)*l0**2
    _x8 = qb**2
    _x9 = (0.5)*_x8
    _x10 = (1.0/_x8)
    _x11 = (1.0/m)
    _x12 = _x11*p**2
    _x13 = -E_ab + (0.5)*_x10*_x12 + _x5*qb - _x6*l0 + _x7*k_c + _x9*k_c
    _next_qb = -_x13*_x4 + qb
    _next_qb__tan = E_ab__tan*_x4 - _x10*_x11*_x4*p*p__tan + _x13*_x4**2*slope__tan - _x4*k_c__tan*(_x7 + _x9 - l0*qb) + qb__tan*(-_x4*(-_x12/qb**3 + _x5 + _x6 - k_c*l0) + 1.0)
    # (internal helper: its callers check that their outputs are finite)
    return (_next_qb, _next_qb__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def bottom_quartic_jvp_p_E_ab_k_c_1(l0, qb, qb__tan):
    """continuation of bottom_quartic_jvp_p_E_ab_k_c (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        l0: value of the caller's variable
        qb: value of the caller's variable
        qb__tan: value of the caller's variable

    Returns a tuple:
        q_r_b: result for the caller
        q_r_b__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    q_r_b = qb
    q_r_b__tan = qb__tan
    # the bottom root is at most l0
    if not ((qb <= l0)):
        return (NAN, NAN, STATUS_NO_REAL_SOLUTION)
    # (internal helper: its callers check that their outputs are finite)
    return (q_r_b, q_r_b__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def bottom_quartic_jvp_p_E_ab_k_c(p, E_ab, m, l0, k_c, g_s, p__tan, E_ab__tan, k_c__tan):
    """Bottom leg length of (153): the compressing root of the quartic in (0, l0] (Newton), with the derivative of every output along the direction (p__tan, E_ab__tan, k_c__tan).

    Report equations: 153.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        p: angular momentum p_th [kg m^2/s]
        E_ab: total energy E_ab [J]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        p__tan: direction: its component along p
        E_ab__tan: direction: its component along E_ab
        k_c__tan: direction: its component along k_c

    Returns a tuple:
        q_r_b: bottom leg length of (153) [m]
        q_r_b__tan: derivative of q_r_b along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 237
    # inputs: finite and inside their domains
    if not (math.isfinite(p) and math.isfinite(E_ab) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s) and math.isfinite(p__tan) and math.isfinite(E_ab__tan) and math.isfinite(k_c__tan) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))):
        return (NAN, NAN, STATUS_INVALID_INPUT)
    # a start left of the root: V >= E there
    _x74 = (1.0/k_c)
    _x0 = (0.5)*l0
    _x1 = g_s*m
    _x2 = _x1*_x74
    _x3 = (0.5)*_x2
    _x4 = (1.0/math.sqrt(k_c))
    _x5 = _x2 - l0
    _x6 = -_x5
    _x7 = _x6**2
    _x8 = _x7*k_c
    _x9 = _x1*_x6
    _x10 = l0**2
    _x11 = _x10*k_c
    _x12 = -2.0*E_ab + _x11
    _x13 = -_x12 + 2.0*_x6*k_c*l0 - _x8 - 2.0*_x9
    _x14 = math.sqrt(_x13)
    _x15 = _x14*_x4
    _x16 = -E_ab + (0.5)*_x11
    _x17 = -_x16 + _x6*k_c*l0 - 0.5*_x8 - _x9
    _x18 = (1.0/math.sqrt(_x17))
    _x19 = math.sqrt(2.0)
    _x20 = (1.0/math.sqrt(m))
    _x21 = _x19*_x20
    _x22 = _x21*abs(p)
    _x23 = _x18*_x22
    _x24 = _x15 + _x5
    _x25 = (0.0 if p == 0 else math.copysign(1, p))
    _x26 = _x18*_x21
    _x27 = (0.5)*math.atan2(0.0, _x13)
    _x28 = math.sin(_x27)
    _x29 = _x5**2
    _x30 = _x29*k_c
    _x31 = _x1*_x5
    _x32 = _x5*l0
    _x33 = _x32*k_c
    _x34 = _x12 + _x30 - 2.0*_x31 + 2.0*_x33
    _x35 = (0.0 if _x34 == 0 else math.copysign(1, _x34))
    _x36 = math.sqrt(_x34/_x35)
    _x37 = (0.5)*math.atan2(0.0, _x17)
    _x38 = math.sin(_x37)
    _x39 = p/_x25
    _x40 = (0.5)*_x39
    _x41 = _x16 + (0.5)*_x30 - _x31 + _x33
    _x42 = (0.0 if _x41 == 0 else math.copysign(1, _x41))
    _x43 = _x41/_x42
    _x44 = (1.0/math.sqrt(_x43))
    _x45 = _x21*_x44
    _x46 = _x40*_x45
    _x47 = _x28*_x36*_x4 - _x38*_x46
    _x48 = math.cos(_x37)
    _x49 = math.cos(_x27)
    _x50 = _x36*_x4*_x49 + _x46*_x48 + _x5
    _x51 = _x24 + _x26*_x40
    _x52 = (1.0/_x51)
    _x53 = (0.0 if _x51 == 0 else math.copysign(1, _x51))
    _x54 = (0.5)*_x52*_x53
    _x55 = (0.5)*_x4
    _x56 = _x55/_x14
    _x57 = _x22/_x17**(1.5)
    _x58 = (1.0/_x36)
    _x59 = _x35*_x58
    _x60 = _x4*_x59
    _x61 = (0.25)*_x21*_x39*_x42/_x43**(1.5)
    _x62 = _x38*_x61
    _x63 = _x48*_x61
    _x64 = _x74**2
    _x65 = _x1*_x64
    _x66 = k_c**(-1.5)
    _x67 = _x64*g_s**2*m**2
    _x68 = _x2*l0
    _x69 = (0.5)*_x10 + _x67 - _x68
    _x70 = (0.5)*_x36*_x66
    _x71 = _x2*_x5
    _x72 = _x10 + _x29 + 2.0*_x32 + 2.0*_x67 - 2.0*_x68 - 2.0*_x71
    _x73 = (0.5)*_x29 + _x32 + _x69 - _x71
    q_start = _x0 - 0.5*_x15 + (0.25)*_x23 - _x3 + (0.5)*abs((0.5)*_x23 + _x24)
    q_start__tan = E_ab__tan*((0.5)*_x52*_x53*(_x47*(-_x28*_x60 - _x62) + _x50*(-_x49*_x60 + _x63)) - _x56 - 0.125*_x57) + k_c__tan*((0.25)*_x14*_x66 + _x54*(_x47*(_x28*_x55*_x59*_x72 - _x28*_x70 + _x62*_x73) + _x50*((0.5)*_x35*_x4*_x49*_x58*_x72 - _x49*_x70 - _x63*_x73 - _x65)) - _x56*(-_x2*_x6 + _x6*l0 - _x69 - 0.5*_x7) + (0.25)*_x57*(-_x0*_x2 - _x0*_x6 + (0.25)*_x10 + _x3*_x6 + (0.5)*_x67 + (0.25)*_x7) + (0.5)*_x65) + p__tan*((0.25)*_x25*_x26 + _x54*((0.5)*_x19*_x20*_x25*_x44*_x48*_x50 - 0.5*_x25*_x38*_x45*_x47))
    # E_ab above the minimum of the potential
    if not ((E_ab > g_s*m*(-g_s*m/k_c + l0) + (0.5)*k_c*l0**2 - k_c*l0*(-g_s*m/k_c + l0) + (0.5)*k_c*(-g_s*m/k_c + l0)**2)):
        return (NAN, NAN, STATUS_NO_REAL_SOLUTION)
    # Newton's method on V - E: monotone from the left
    qb = q_start
    qb__tan = q_start__tan
    passes = 0.0
    _conv0 = False
    for _it0 in range(int(60.0)):
        # loop body
        _c0 = bottom_quartic_jvp_p_E_ab_k_c_0(E_ab, E_ab__tan, g_s, k_c, k_c__tan, l0, m, p, p__tan, qb, qb__tan)
        if _c0[2] != STATUS_OK:
            return (NAN, NAN, _c0[2])
        _next_qb = _c0[0]
        _next_qb__tan = _c0[1]
        _n0_0 = _next_qb
        _n0_1 = _next_qb__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = 1e-12 > 0.0 and (abs(_n0_0 - qb) <= 1e-12*(l0))
        qb = _n0_0
        qb__tan = _n0_1
        passes += 1.0
        if _conv0:
            break
    if not _conv0 and 1e-12 > 0.0 and passes > 0.0:
        return (NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = bottom_quartic_jvp_p_E_ab_k_c_1(l0, qb, qb__tan)
    if _c1[2] != STATUS_OK:
        return (NAN, NAN, _c1[2])
    q_r_b = _c1[0]
    q_r_b__tan = _c1[1]
    # (internal helper: its callers check that their outputs are finite)
    return (q_r_b, q_r_b__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol):
    """Simple variable-stiffness map (Geyer et al. per half): stance outputs and their derivatives with respect to the touchdown state and the stiffness.

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113.

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
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0 = report, 1 = constrained, 2 = energy
        gravity: option gravity: virtual gravity effect on p_th per half (report 4.4-4.5 on [t_td, t_b] and [t_b, t_lo]); each half runs with its mean momentum, the rates with the momentum at that instant: 0 = none, 1 = type3, 2 = type4
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0, 1]

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
        P_c_compression: virtual gravity effect of the first half (0 unless gravity) [N m s]
        P_c_decompression: virtual gravity effect of the second half [N m s]
        passes: fixed-point passes run (0 unless gravity)
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
        d_P_c_compression__q_r_td: d P_c_compression / d q_r_td
        d_P_c_compression__q_rd_td: d P_c_compression / d q_rd_td
        d_P_c_compression__q_th_td: d P_c_compression / d q_th_td
        d_P_c_compression__q_thd_td: d P_c_compression / d q_thd_td
        d_P_c_compression__k_c: d P_c_compression / d k_c
        d_P_c_compression__k_d: d P_c_compression / d k_d
        d_P_c_decompression__q_r_td: d P_c_decompression / d q_r_td
        d_P_c_decompression__q_rd_td: d P_c_decompression / d q_rd_td
        d_P_c_decompression__q_th_td: d P_c_decompression / d q_th_td
        d_P_c_decompression__q_thd_td: d P_c_decompression / d q_thd_td
        d_P_c_decompression__k_c: d P_c_decompression / d k_c
        d_P_c_decompression__k_d: d P_c_decompression / d k_d
        d_passes__q_r_td: d passes / d q_r_td
        d_passes__q_rd_td: d passes / d q_rd_td
        d_passes__q_th_td: d passes / d q_th_td
        d_passes__q_thd_td: d passes / d q_thd_td
        d_passes__k_c: d passes / d k_c
        d_passes__k_d: d passes / d k_d
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(continuity) and math.isfinite(gravity) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((continuity == 0.0) or (continuity == 1.0) or (continuity == 2.0)) and ((gravity == 0.0) or (gravity == 1.0) or (gravity == 2.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives with respect to q_r_td
    _c0 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if _c0[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[26])
    d_t_bottom__q_r_td = _c0[13]
    d_t_stance__q_r_td = _c0[14]
    d_bottom_q_r__q_r_td = _c0[15]
    d_bottom_q_rd__q_r_td = _c0[16]
    d_bottom_q_th__q_r_td = _c0[17]
    d_bottom_q_thd__q_r_td = _c0[18]
    d_liftoff_q_r__q_r_td = _c0[19]
    d_liftoff_q_rd__q_r_td = _c0[20]
    d_liftoff_q_th__q_r_td = _c0[21]
    d_liftoff_q_thd__q_r_td = _c0[22]
    d_P_c_compression__q_r_td = _c0[23]
    d_P_c_decompression__q_r_td = _c0[24]
    d_passes__q_r_td = _c0[25]
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
    P_c_compression = _c0[10]
    P_c_decompression = _c0[11]
    passes = _c0[12]
    # derivatives with respect to q_rd_td
    _c1 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    if _c1[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[26])
    d_t_bottom__q_rd_td = _c1[13]
    d_t_stance__q_rd_td = _c1[14]
    d_bottom_q_r__q_rd_td = _c1[15]
    d_bottom_q_rd__q_rd_td = _c1[16]
    d_bottom_q_th__q_rd_td = _c1[17]
    d_bottom_q_thd__q_rd_td = _c1[18]
    d_liftoff_q_r__q_rd_td = _c1[19]
    d_liftoff_q_rd__q_rd_td = _c1[20]
    d_liftoff_q_th__q_rd_td = _c1[21]
    d_liftoff_q_thd__q_rd_td = _c1[22]
    d_P_c_compression__q_rd_td = _c1[23]
    d_P_c_decompression__q_rd_td = _c1[24]
    d_passes__q_rd_td = _c1[25]
    # derivatives with respect to q_th_td
    _c2 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    if _c2[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[26])
    d_t_bottom__q_th_td = _c2[13]
    d_t_stance__q_th_td = _c2[14]
    d_bottom_q_r__q_th_td = _c2[15]
    d_bottom_q_rd__q_th_td = _c2[16]
    d_bottom_q_th__q_th_td = _c2[17]
    d_bottom_q_thd__q_th_td = _c2[18]
    d_liftoff_q_r__q_th_td = _c2[19]
    d_liftoff_q_rd__q_th_td = _c2[20]
    d_liftoff_q_th__q_th_td = _c2[21]
    d_liftoff_q_thd__q_th_td = _c2[22]
    d_P_c_compression__q_th_td = _c2[23]
    d_P_c_decompression__q_th_td = _c2[24]
    d_passes__q_th_td = _c2[25]
    # derivatives with respect to q_thd_td
    _c3 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    if _c3[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[26])
    d_t_bottom__q_thd_td = _c3[13]
    d_t_stance__q_thd_td = _c3[14]
    d_bottom_q_r__q_thd_td = _c3[15]
    d_bottom_q_rd__q_thd_td = _c3[16]
    d_bottom_q_th__q_thd_td = _c3[17]
    d_bottom_q_thd__q_thd_td = _c3[18]
    d_liftoff_q_r__q_thd_td = _c3[19]
    d_liftoff_q_rd__q_thd_td = _c3[20]
    d_liftoff_q_th__q_thd_td = _c3[21]
    d_liftoff_q_thd__q_thd_td = _c3[22]
    d_P_c_compression__q_thd_td = _c3[23]
    d_P_c_decompression__q_thd_td = _c3[24]
    d_passes__q_thd_td = _c3[25]
    # derivatives with respect to k_c
    _c4 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    if _c4[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[26])
    d_t_bottom__k_c = _c4[13]
    d_t_stance__k_c = _c4[14]
    d_bottom_q_r__k_c = _c4[15]
    d_bottom_q_rd__k_c = _c4[16]
    d_bottom_q_th__k_c = _c4[17]
    d_bottom_q_thd__k_c = _c4[18]
    d_liftoff_q_r__k_c = _c4[19]
    d_liftoff_q_rd__k_c = _c4[20]
    d_liftoff_q_th__k_c = _c4[21]
    d_liftoff_q_thd__k_c = _c4[22]
    d_P_c_compression__k_c = _c4[23]
    d_P_c_decompression__k_c = _c4[24]
    d_passes__k_c = _c4[25]
    # derivatives with respect to k_d
    _c5 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    if _c5[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c5[26])
    d_t_bottom__k_d = _c5[13]
    d_t_stance__k_d = _c5[14]
    d_bottom_q_r__k_d = _c5[15]
    d_bottom_q_rd__k_d = _c5[16]
    d_bottom_q_th__k_d = _c5[17]
    d_bottom_q_thd__k_d = _c5[18]
    d_liftoff_q_r__k_d = _c5[19]
    d_liftoff_q_rd__k_d = _c5[20]
    d_liftoff_q_th__k_d = _c5[21]
    d_liftoff_q_thd__k_d = _c5[22]
    d_P_c_compression__k_d = _c5[23]
    d_P_c_decompression__k_d = _c5[24]
    d_passes__k_d = _c5[25]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r) and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(P_c_compression) and math.isfinite(P_c_decompression) and math.isfinite(passes) and math.isfinite(d_t_bottom__q_r_td) and math.isfinite(d_t_bottom__q_rd_td) and math.isfinite(d_t_bottom__q_th_td) and math.isfinite(d_t_bottom__q_thd_td) and math.isfinite(d_t_bottom__k_c) and math.isfinite(d_t_bottom__k_d) and math.isfinite(d_t_stance__q_r_td) and math.isfinite(d_t_stance__q_rd_td) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__q_thd_td) and math.isfinite(d_t_stance__k_c) and math.isfinite(d_t_stance__k_d) and math.isfinite(d_bottom_q_r__q_r_td) and math.isfinite(d_bottom_q_r__q_rd_td) and math.isfinite(d_bottom_q_r__q_th_td) and math.isfinite(d_bottom_q_r__q_thd_td) and math.isfinite(d_bottom_q_r__k_c) and math.isfinite(d_bottom_q_r__k_d) and math.isfinite(d_bottom_q_rd__q_r_td) and math.isfinite(d_bottom_q_rd__q_rd_td) and math.isfinite(d_bottom_q_rd__q_th_td) and math.isfinite(d_bottom_q_rd__q_thd_td) and math.isfinite(d_bottom_q_rd__k_c) and math.isfinite(d_bottom_q_rd__k_d) and math.isfinite(d_bottom_q_th__q_r_td) and math.isfinite(d_bottom_q_th__q_rd_td) and math.isfinite(d_bottom_q_th__q_th_td) and math.isfinite(d_bottom_q_th__q_thd_td) and math.isfinite(d_bottom_q_th__k_c) and math.isfinite(d_bottom_q_th__k_d) and math.isfinite(d_bottom_q_thd__q_r_td) and math.isfinite(d_bottom_q_thd__q_rd_td) and math.isfinite(d_bottom_q_thd__q_th_td) and math.isfinite(d_bottom_q_thd__q_thd_td) and math.isfinite(d_bottom_q_thd__k_c) and math.isfinite(d_bottom_q_thd__k_d) and math.isfinite(d_liftoff_q_r__q_r_td) and math.isfinite(d_liftoff_q_r__q_rd_td) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__q_thd_td) and math.isfinite(d_liftoff_q_r__k_c) and math.isfinite(d_liftoff_q_r__k_d) and math.isfinite(d_liftoff_q_rd__q_r_td) and math.isfinite(d_liftoff_q_rd__q_rd_td) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__q_thd_td) and math.isfinite(d_liftoff_q_rd__k_c) and math.isfinite(d_liftoff_q_rd__k_d) and math.isfinite(d_liftoff_q_th__q_r_td) and math.isfinite(d_liftoff_q_th__q_rd_td) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__q_thd_td) and math.isfinite(d_liftoff_q_th__k_c) and math.isfinite(d_liftoff_q_th__k_d) and math.isfinite(d_liftoff_q_thd__q_r_td) and math.isfinite(d_liftoff_q_thd__q_rd_td) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__q_thd_td) and math.isfinite(d_liftoff_q_thd__k_c) and math.isfinite(d_liftoff_q_thd__k_d) and math.isfinite(d_P_c_compression__q_r_td) and math.isfinite(d_P_c_compression__q_rd_td) and math.isfinite(d_P_c_compression__q_th_td) and math.isfinite(d_P_c_compression__q_thd_td) and math.isfinite(d_P_c_compression__k_c) and math.isfinite(d_P_c_compression__k_d) and math.isfinite(d_P_c_decompression__q_r_td) and math.isfinite(d_P_c_decompression__q_rd_td) and math.isfinite(d_P_c_decompression__q_th_td) and math.isfinite(d_P_c_decompression__q_thd_td) and math.isfinite(d_P_c_decompression__k_c) and math.isfinite(d_P_c_decompression__k_d) and math.isfinite(d_passes__q_r_td) and math.isfinite(d_passes__q_rd_td) and math.isfinite(d_passes__q_th_td) and math.isfinite(d_passes__q_thd_td) and math.isfinite(d_passes__k_c) and math.isfinite(d_passes__k_d)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c_compression, P_c_decompression, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_P_c_compression__q_r_td, d_P_c_compression__q_rd_td, d_P_c_compression__q_th_td, d_P_c_compression__q_thd_td, d_P_c_compression__k_c, d_P_c_compression__k_d, d_P_c_decompression__q_r_td, d_P_c_decompression__q_rd_td, d_P_c_decompression__q_th_td, d_P_c_decompression__q_thd_td, d_P_c_decompression__k_c, d_P_c_decompression__k_d, d_passes__q_r_td, d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_vs_stance_jacobian_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol, out, status):
    """Parallel batch form of :func:`geyer_vs_stance_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 91)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c_compression, P_c_decompression, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_P_c_compression__q_r_td, d_P_c_compression__q_rd_td, d_P_c_compression__q_th_td, d_P_c_compression__q_thd_td, d_P_c_compression__k_c, d_P_c_compression__k_d, d_P_c_decompression__q_r_td, d_P_c_decompression__q_rd_td, d_P_c_decompression__q_th_td, d_P_c_decompression__q_thd_td, d_P_c_decompression__k_c, d_P_c_decompression__k_d, d_passes__q_r_td, d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d.
    """
    for i in prange(out.shape[0]):
        res = geyer_vs_stance_jacobian(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol)
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
        out[i, 84] = res[84]
        out[i, 85] = res[85]
        out[i, 86] = res[86]
        out[i, 87] = res[87]
        out[i, 88] = res[88]
        out[i, 89] = res[89]
        out[i, 90] = res[90]
        status[i] = res[91]


@njit(cache=True, error_model="numpy")
def geyer_vs_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan, k_c__tan, k_d__tan):
    """Apex-return map: exact flights, stance by Simple variable-stiffness map (Geyer et al. per half), with the derivative of every output along the direction (b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan, k_c__tan, k_d__tan).

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113.

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
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0 = report, 1 = constrained, 2 = energy
        gravity: option gravity: virtual gravity effect on p_th per half (report 4.4-4.5 on [t_td, t_b] and [t_b, t_lo]); each half runs with its mean momentum, the rates with the momentum at that instant: 0 = none, 1 = type3, 2 = type4
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0, 1]
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
        P_c_compression: virtual gravity effect of the first half (0 unless gravity) [N m s]
        P_c_decompression: virtual gravity effect of the second half [N m s]
        passes: fixed-point passes run (0 unless gravity)
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
        P_c_compression__tan: derivative of P_c_compression along the direction
        P_c_decompression__tan: derivative of P_c_decompression along the direction
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 5
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(continuity) and math.isfinite(gravity) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(b_y_apex__tan) and math.isfinite(b_xd_apex__tan) and math.isfinite(q_th_td__tan) and math.isfinite(ground__tan) and math.isfinite(k_c__tan) and math.isfinite(k_d__tan) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((continuity == 0.0) or (continuity == 1.0) or (continuity == 2.0)) and ((gravity == 0.0) or (gravity == 1.0) or (gravity == 2.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan)
    if _c0[12] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[12])
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
    # stance: Simple variable-stiffness map (Geyer et al. per half)
    _c1 = geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, k_c__tan, k_d__tan)
    if _c1[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[26])
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    P_c_compression = _c1[10]
    P_c_decompression = _c1[11]
    passes = _c1[12]
    t_stance__tan = _c1[14]
    liftoff_q_r__tan = _c1[19]
    liftoff_q_rd__tan = _c1[20]
    liftoff_q_th__tan = _c1[21]
    liftoff_q_thd__tan = _c1[22]
    P_c_compression__tan = _c1[23]
    P_c_decompression__tan = _c1[24]
    passes__tan = _c1[25]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan)
    if _c2[10] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[10])
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
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, P_c_compression, P_c_decompression, passes, apex_height__tan, apex_speed__tan, t_descent__tan, t_stance__tan, t_ascent__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, step_length__tan, foot_x__tan, foot_y__tan, P_c_compression__tan, P_c_decompression__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_apex_return_jacobian(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol):
    """Apex-return map by Simple variable-stiffness map (Geyer et al. per half), and its derivatives with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113.

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
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0 = report, 1 = constrained, 2 = energy
        gravity: option gravity: virtual gravity effect on p_th per half (report 4.4-4.5 on [t_td, t_b] and [t_b, t_lo]); each half runs with its mean momentum, the rates with the momentum at that instant: 0 = none, 1 = type3, 2 = type4
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0, 1]

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
        P_c_compression: virtual gravity effect of the first half (0 unless gravity) [N m s]
        P_c_decompression: virtual gravity effect of the second half [N m s]
        passes: fixed-point passes run (0 unless gravity)
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
        d_P_c_compression__b_y_apex: d P_c_compression / d b_y_apex
        d_P_c_compression__b_xd_apex: d P_c_compression / d b_xd_apex
        d_P_c_compression__q_th_td: d P_c_compression / d q_th_td
        d_P_c_compression__ground: d P_c_compression / d ground
        d_P_c_compression__k_c: d P_c_compression / d k_c
        d_P_c_compression__k_d: d P_c_compression / d k_d
        d_P_c_decompression__b_y_apex: d P_c_decompression / d b_y_apex
        d_P_c_decompression__b_xd_apex: d P_c_decompression / d b_xd_apex
        d_P_c_decompression__q_th_td: d P_c_decompression / d q_th_td
        d_P_c_decompression__ground: d P_c_decompression / d ground
        d_P_c_decompression__k_c: d P_c_decompression / d k_c
        d_P_c_decompression__k_d: d P_c_decompression / d k_d
        d_passes__b_y_apex: d passes / d b_y_apex
        d_passes__b_xd_apex: d passes / d b_xd_apex
        d_passes__q_th_td: d passes / d q_th_td
        d_passes__ground: d passes / d ground
        d_passes__k_c: d passes / d k_c
        d_passes__k_d: d passes / d k_d
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(continuity) and math.isfinite(gravity) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((continuity == 0.0) or (continuity == 1.0) or (continuity == 2.0)) and ((gravity == 0.0) or (gravity == 1.0) or (gravity == 2.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives with respect to b_y_apex
    _c0 = geyer_vs_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if _c0[30] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[30])
    d_apex_height__b_y_apex = _c0[15]
    d_apex_speed__b_y_apex = _c0[16]
    d_t_descent__b_y_apex = _c0[17]
    d_t_stance__b_y_apex = _c0[18]
    d_t_ascent__b_y_apex = _c0[19]
    d_liftoff_q_r__b_y_apex = _c0[20]
    d_liftoff_q_rd__b_y_apex = _c0[21]
    d_liftoff_q_th__b_y_apex = _c0[22]
    d_liftoff_q_thd__b_y_apex = _c0[23]
    d_step_length__b_y_apex = _c0[24]
    d_foot_x__b_y_apex = _c0[25]
    d_foot_y__b_y_apex = _c0[26]
    d_P_c_compression__b_y_apex = _c0[27]
    d_P_c_decompression__b_y_apex = _c0[28]
    d_passes__b_y_apex = _c0[29]
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
    P_c_compression = _c0[12]
    P_c_decompression = _c0[13]
    passes = _c0[14]
    # derivatives with respect to b_xd_apex
    _c1 = geyer_vs_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    if _c1[30] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[30])
    d_apex_height__b_xd_apex = _c1[15]
    d_apex_speed__b_xd_apex = _c1[16]
    d_t_descent__b_xd_apex = _c1[17]
    d_t_stance__b_xd_apex = _c1[18]
    d_t_ascent__b_xd_apex = _c1[19]
    d_liftoff_q_r__b_xd_apex = _c1[20]
    d_liftoff_q_rd__b_xd_apex = _c1[21]
    d_liftoff_q_th__b_xd_apex = _c1[22]
    d_liftoff_q_thd__b_xd_apex = _c1[23]
    d_step_length__b_xd_apex = _c1[24]
    d_foot_x__b_xd_apex = _c1[25]
    d_foot_y__b_xd_apex = _c1[26]
    d_P_c_compression__b_xd_apex = _c1[27]
    d_P_c_decompression__b_xd_apex = _c1[28]
    d_passes__b_xd_apex = _c1[29]
    # derivatives with respect to q_th_td
    _c2 = geyer_vs_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    if _c2[30] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[30])
    d_apex_height__q_th_td = _c2[15]
    d_apex_speed__q_th_td = _c2[16]
    d_t_descent__q_th_td = _c2[17]
    d_t_stance__q_th_td = _c2[18]
    d_t_ascent__q_th_td = _c2[19]
    d_liftoff_q_r__q_th_td = _c2[20]
    d_liftoff_q_rd__q_th_td = _c2[21]
    d_liftoff_q_th__q_th_td = _c2[22]
    d_liftoff_q_thd__q_th_td = _c2[23]
    d_step_length__q_th_td = _c2[24]
    d_foot_x__q_th_td = _c2[25]
    d_foot_y__q_th_td = _c2[26]
    d_P_c_compression__q_th_td = _c2[27]
    d_P_c_decompression__q_th_td = _c2[28]
    d_passes__q_th_td = _c2[29]
    # derivatives with respect to ground
    _c3 = geyer_vs_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    if _c3[30] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[30])
    d_apex_height__ground = _c3[15]
    d_apex_speed__ground = _c3[16]
    d_t_descent__ground = _c3[17]
    d_t_stance__ground = _c3[18]
    d_t_ascent__ground = _c3[19]
    d_liftoff_q_r__ground = _c3[20]
    d_liftoff_q_rd__ground = _c3[21]
    d_liftoff_q_th__ground = _c3[22]
    d_liftoff_q_thd__ground = _c3[23]
    d_step_length__ground = _c3[24]
    d_foot_x__ground = _c3[25]
    d_foot_y__ground = _c3[26]
    d_P_c_compression__ground = _c3[27]
    d_P_c_decompression__ground = _c3[28]
    d_passes__ground = _c3[29]
    # derivatives with respect to k_c
    _c4 = geyer_vs_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    if _c4[30] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[30])
    d_apex_height__k_c = _c4[15]
    d_apex_speed__k_c = _c4[16]
    d_t_descent__k_c = _c4[17]
    d_t_stance__k_c = _c4[18]
    d_t_ascent__k_c = _c4[19]
    d_liftoff_q_r__k_c = _c4[20]
    d_liftoff_q_rd__k_c = _c4[21]
    d_liftoff_q_th__k_c = _c4[22]
    d_liftoff_q_thd__k_c = _c4[23]
    d_step_length__k_c = _c4[24]
    d_foot_x__k_c = _c4[25]
    d_foot_y__k_c = _c4[26]
    d_P_c_compression__k_c = _c4[27]
    d_P_c_decompression__k_c = _c4[28]
    d_passes__k_c = _c4[29]
    # derivatives with respect to k_d
    _c5 = geyer_vs_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    if _c5[30] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c5[30])
    d_apex_height__k_d = _c5[15]
    d_apex_speed__k_d = _c5[16]
    d_t_descent__k_d = _c5[17]
    d_t_stance__k_d = _c5[18]
    d_t_ascent__k_d = _c5[19]
    d_liftoff_q_r__k_d = _c5[20]
    d_liftoff_q_rd__k_d = _c5[21]
    d_liftoff_q_th__k_d = _c5[22]
    d_liftoff_q_thd__k_d = _c5[23]
    d_step_length__k_d = _c5[24]
    d_foot_x__k_d = _c5[25]
    d_foot_y__k_d = _c5[26]
    d_P_c_compression__k_d = _c5[27]
    d_P_c_decompression__k_d = _c5[28]
    d_passes__k_d = _c5[29]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent) and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y) and math.isfinite(P_c_compression) and math.isfinite(P_c_decompression) and math.isfinite(passes) and math.isfinite(d_apex_height__b_y_apex) and math.isfinite(d_apex_height__b_xd_apex) and math.isfinite(d_apex_height__q_th_td) and math.isfinite(d_apex_height__ground) and math.isfinite(d_apex_height__k_c) and math.isfinite(d_apex_height__k_d) and math.isfinite(d_apex_speed__b_y_apex) and math.isfinite(d_apex_speed__b_xd_apex) and math.isfinite(d_apex_speed__q_th_td) and math.isfinite(d_apex_speed__ground) and math.isfinite(d_apex_speed__k_c) and math.isfinite(d_apex_speed__k_d) and math.isfinite(d_t_descent__b_y_apex) and math.isfinite(d_t_descent__b_xd_apex) and math.isfinite(d_t_descent__q_th_td) and math.isfinite(d_t_descent__ground) and math.isfinite(d_t_descent__k_c) and math.isfinite(d_t_descent__k_d) and math.isfinite(d_t_stance__b_y_apex) and math.isfinite(d_t_stance__b_xd_apex) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__ground) and math.isfinite(d_t_stance__k_c) and math.isfinite(d_t_stance__k_d) and math.isfinite(d_t_ascent__b_y_apex) and math.isfinite(d_t_ascent__b_xd_apex) and math.isfinite(d_t_ascent__q_th_td) and math.isfinite(d_t_ascent__ground) and math.isfinite(d_t_ascent__k_c) and math.isfinite(d_t_ascent__k_d) and math.isfinite(d_liftoff_q_r__b_y_apex) and math.isfinite(d_liftoff_q_r__b_xd_apex) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__ground) and math.isfinite(d_liftoff_q_r__k_c) and math.isfinite(d_liftoff_q_r__k_d) and math.isfinite(d_liftoff_q_rd__b_y_apex) and math.isfinite(d_liftoff_q_rd__b_xd_apex) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__ground) and math.isfinite(d_liftoff_q_rd__k_c) and math.isfinite(d_liftoff_q_rd__k_d) and math.isfinite(d_liftoff_q_th__b_y_apex) and math.isfinite(d_liftoff_q_th__b_xd_apex) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__ground) and math.isfinite(d_liftoff_q_th__k_c) and math.isfinite(d_liftoff_q_th__k_d) and math.isfinite(d_liftoff_q_thd__b_y_apex) and math.isfinite(d_liftoff_q_thd__b_xd_apex) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__ground) and math.isfinite(d_liftoff_q_thd__k_c) and math.isfinite(d_liftoff_q_thd__k_d) and math.isfinite(d_step_length__b_y_apex) and math.isfinite(d_step_length__b_xd_apex) and math.isfinite(d_step_length__q_th_td) and math.isfinite(d_step_length__ground) and math.isfinite(d_step_length__k_c) and math.isfinite(d_step_length__k_d) and math.isfinite(d_foot_x__b_y_apex) and math.isfinite(d_foot_x__b_xd_apex) and math.isfinite(d_foot_x__q_th_td) and math.isfinite(d_foot_x__ground) and math.isfinite(d_foot_x__k_c) and math.isfinite(d_foot_x__k_d) and math.isfinite(d_foot_y__b_y_apex) and math.isfinite(d_foot_y__b_xd_apex) and math.isfinite(d_foot_y__q_th_td) and math.isfinite(d_foot_y__ground) and math.isfinite(d_foot_y__k_c) and math.isfinite(d_foot_y__k_d) and math.isfinite(d_P_c_compression__b_y_apex) and math.isfinite(d_P_c_compression__b_xd_apex) and math.isfinite(d_P_c_compression__q_th_td) and math.isfinite(d_P_c_compression__ground) and math.isfinite(d_P_c_compression__k_c) and math.isfinite(d_P_c_compression__k_d) and math.isfinite(d_P_c_decompression__b_y_apex) and math.isfinite(d_P_c_decompression__b_xd_apex) and math.isfinite(d_P_c_decompression__q_th_td) and math.isfinite(d_P_c_decompression__ground) and math.isfinite(d_P_c_decompression__k_c) and math.isfinite(d_P_c_decompression__k_d) and math.isfinite(d_passes__b_y_apex) and math.isfinite(d_passes__b_xd_apex) and math.isfinite(d_passes__q_th_td) and math.isfinite(d_passes__ground) and math.isfinite(d_passes__k_c) and math.isfinite(d_passes__k_d)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, P_c_compression, P_c_decompression, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__k_c, d_t_descent__k_d, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__k_c, d_t_stance__k_d, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__k_c, d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__k_c, d_foot_x__k_d, d_foot_y__b_y_apex, d_foot_y__b_xd_apex, d_foot_y__q_th_td, d_foot_y__ground, d_foot_y__k_c, d_foot_y__k_d, d_P_c_compression__b_y_apex, d_P_c_compression__b_xd_apex, d_P_c_compression__q_th_td, d_P_c_compression__ground, d_P_c_compression__k_c, d_P_c_compression__k_d, d_P_c_decompression__b_y_apex, d_P_c_decompression__b_xd_apex, d_P_c_decompression__q_th_td, d_P_c_decompression__ground, d_P_c_decompression__k_c, d_P_c_decompression__k_d, d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__ground, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_vs_apex_return_jacobian_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol, out, status):
    """Parallel batch form of :func:`geyer_vs_apex_return_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 105)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, P_c_compression, P_c_decompression, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__k_c, d_t_descent__k_d, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__k_c, d_t_stance__k_d, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__k_c, d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__k_c, d_foot_x__k_d, d_foot_y__b_y_apex, d_foot_y__b_xd_apex, d_foot_y__q_th_td, d_foot_y__ground, d_foot_y__k_c, d_foot_y__k_d, d_P_c_compression__b_y_apex, d_P_c_compression__b_xd_apex, d_P_c_compression__q_th_td, d_P_c_compression__ground, d_P_c_compression__k_c, d_P_c_compression__k_d, d_P_c_decompression__b_y_apex, d_P_c_decompression__b_xd_apex, d_P_c_decompression__q_th_td, d_P_c_decompression__ground, d_P_c_decompression__k_c, d_P_c_decompression__k_d, d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__ground, d_passes__k_c, d_passes__k_d.
    """
    for i in prange(out.shape[0]):
        res = geyer_vs_apex_return_jacobian(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol)
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
        out[i, 84] = res[84]
        out[i, 85] = res[85]
        out[i, 86] = res[86]
        out[i, 87] = res[87]
        out[i, 88] = res[88]
        out[i, 89] = res[89]
        out[i, 90] = res[90]
        out[i, 91] = res[91]
        out[i, 92] = res[92]
        out[i, 93] = res[93]
        out[i, 94] = res[94]
        out[i, 95] = res[95]
        out[i, 96] = res[96]
        out[i, 97] = res[97]
        out[i, 98] = res[98]
        out[i, 99] = res[99]
        out[i, 100] = res[100]
        out[i, 101] = res[101]
        out[i, 102] = res[102]
        out[i, 103] = res[103]
        out[i, 104] = res[104]
        status[i] = res[105]
