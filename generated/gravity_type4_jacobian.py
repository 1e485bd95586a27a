# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/gravity.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:e58e885f76eb1aa8
#   geyer_jacobian.py sha256:849e7410cc446e23
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module gravity_type4: JVP kernels, and for a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td, liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd
from .geyer_jacobian import geyer_liftoff_phase_jvp_a_b, geyer_solution_jvp_q_r_td_q_rd_td_q_thd_td_k

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_FALL, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED, STATUS_ENERGY_DEFICIT

NAN = math.nan
_NAN2 = (NAN,) * 2
_NAN21 = (NAN,) * 21
_NAN22 = (NAN,) * 22
_NAN24 = (NAN,) * 24
_NAN55 = (NAN,) * 55
_NAN72 = (NAN,) * 72


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_0():
    """branch reading = 0 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:

    Returns a tuple:
        share: result for the caller
        ramp: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1
    share = 0.5
    ramp = 1.0
    # (internal helper: its callers check that their outputs are finite)
    return (share, ramp, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_1():
    """branch reading = 1 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:

    Returns a tuple:
        share: result for the caller
        ramp: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    share = 1.0
    ramp = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (share, ramp, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_2(P_c, P_c__tan, g_s, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, share):
    """evaluation of the iterate of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        P_c: value of the caller's variable
        P_c__tan: value of the caller's variable
        g_s: value of the caller's variable
        k: value of the caller's variable
        k__tan: value of the caller's variable
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
        share: value of the caller's variable

    Returns a tuple:
        i_q_thd_eff: result for the caller
        i_q_thd_eff__tan: result for the caller
        i_omega0_hat: result for the caller
        i_a: result for the caller
        i_b: result for the caller
        i_phase_td: result for the caller
        i_omega0_hat__tan: result for the caller
        i_a__tan: result for the caller
        i_b__tan: result for the caller
        i_phase_td__tan: result for the caller
        i_t_bottom: result for the caller
        i_t_bottom__tan: result for the caller
        i_t_stance: result for the caller
        i_t_stance__tan: result for the caller
        i_bottom_q_r: result for the caller
        i_bottom_q_r__tan: result for the caller
        i_bottom_q_th: result for the caller
        i_bottom_q_th__tan: result for the caller
        i_liftoff_q_rd: result for the caller
        i_liftoff_q_rd__tan: result for the caller
        i_liftoff_q_th: result for the caller
        i_liftoff_q_th__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 194
    # effective touchdown rate
    _x3 = (1.0/q_r_td)
    _x0 = P_c*share + p_td
    _x1 = (1.0/m)
    _x2 = _x1*_x3**2
    i_q_thd_eff = _x0*_x2
    i_q_thd_eff__tan = P_c__tan*_x2*share - 2.0*_x0*_x1*_x3**3*q_r_td__tan + _x2*p_td__tan
    # eqs (7)-(12): Geyer et al.'s radial solution from the touchdown state
    _c0 = geyer_solution_jvp_q_r_td_q_rd_td_q_thd_td_k(q_r_td, q_rd_td, i_q_thd_eff, m, l0, k, g_s, q_r_td__tan, q_rd_td__tan, i_q_thd_eff__tan, k__tan)
    if _c0[12] != STATUS_OK:
        return _NAN22 + (_c0[12],)
    (i_omega, i_omega0_hat, i_a, i_b, i_phase_td, i_s_td, i_omega__tan, i_omega0_hat__tan, i_a__tan, i_b__tan, i_phase_td__tan, i_s_td__tan, _) = _c0
    _c1 = geyer_liftoff_phase_jvp_a_b(i_a, i_b, l0, q_r_lo, i_a__tan, i_b__tan)
    if _c1[4] != STATUS_OK:
        return _NAN22 + (_c1[4],)
    i_phase_lo = _c1[0]
    i_s_lo = _c1[1]
    i_phase_lo__tan = _c1[2]
    i_s_lo__tan = _c1[3]
    # eqs (13)-(14) minus (12), (11), (19), (17) at the bottom and at liftoff
    _x4 = (1.0/i_omega0_hat)
    _x5 = -i_phase_td + (1.5)*math.pi
    _x6 = _x4*i_phase_td__tan
    _x7 = _x4**2
    _x8 = _x7*i_omega0_hat__tan
    _x9 = i_phase_lo - i_phase_td
    _x10 = i_a + 1.0
    _x11 = _x10 - i_b
    _x48 = (1.0/_x11)
    _x12 = i_b__tan*l0
    _x13 = (1.5)*math.pi
    _x14 = _x4*i_omega
    _x15 = 3.0*math.pi
    _x16 = _x14*_x15
    _x17 = _x4*i_phase_td
    _x18 = _x17*i_a
    _x19 = math.sqrt(1.0 - i_s_td**2)
    _x20 = _x19*i_b
    _x21 = _x20*_x4
    _x22 = 2.0*i_omega
    _x23 = -_x17*i_omega + _x22*(_x18 + _x21) + q_th_td
    _x24 = _x7*i_phase_td
    _x25 = _x7*i_omega
    _x26 = _x15*i_a
    _x27 = -_x20*_x7 - _x24*i_a
    _x28 = -_x17 + 2.0*_x18 + 2.0*_x21
    _x29 = 2.0*_x14
    _x30 = _x19*_x29
    _x31 = -_x14 + _x29*i_a
    _x32 = _x31*i_phase_td__tan + q_th_td__tan - _x29*i_b*i_s_td*i_s_td__tan/_x19
    _x33 = _x48**2
    _x34 = _x22*_x48**3
    _x35 = math.sqrt(1.0 - i_s_lo**2)
    _x36 = _x35*i_b
    _x37 = _x36*l0
    _x38 = i_b*i_s_lo
    _x39 = _x38*i_s_lo__tan/_x35
    _x40 = _x4*i_phase_lo
    _x41 = _x40*i_a
    _x42 = _x36*_x4
    _x43 = _x14*i_phase_lo
    _x44 = _x7*i_phase_lo
    _x45 = _x10 + _x38
    _x49 = (1.0/_x45)
    _x46 = _x49**2
    _x47 = _x22*_x49**3
    i_t_bottom = _x4*_x5
    i_t_bottom__tan = -_x5*_x8 - _x6
    i_t_stance = _x4*_x9
    i_t_stance__tan = _x4*i_phase_lo__tan - _x6 - _x8*_x9
    i_bottom_q_r = _x11*l0
    i_bottom_q_r__tan = -_x12 + i_a__tan*l0
    i_bottom_q_rd = 0.0
    i_bottom_q_th = _x13*_x14 - _x16*i_a + _x23
    i_bottom_q_th__tan = _x30*i_b__tan + _x32 + i_a__tan*(-_x16 + _x17*_x22) + i_omega0_hat__tan*(-_x13*_x25 + _x22*_x27 + _x24*i_omega + _x25*_x26) + i_omega__tan*(_x13*_x4 - _x26*_x4 + _x28)
    i_bottom_q_thd = _x33*i_omega
    i_bottom_q_thd__tan = _x33*i_omega__tan - _x34*i_a__tan + _x34*i_b__tan
    i_liftoff_q_r = q_r_lo
    i_liftoff_q_rd = _x37*i_omega0_hat
    i_liftoff_q_rd__tan = _x12*_x35*i_omega0_hat + _x37*i_omega0_hat__tan - _x39*i_omega0_hat*l0
    i_liftoff_q_th = -_x22*(_x41 - _x42) + _x23 + _x43
    i_liftoff_q_th__tan = -_x29*_x39 - _x31*i_phase_lo__tan + _x32 + i_a__tan*(2.0*_x4*i_omega*i_phase_td - 2.0*_x43) + i_b__tan*(_x29*_x35 + _x30) + i_omega0_hat__tan*(-_x22*(_x35*_x7*i_b - _x44*i_a) + 2.0*_x27*i_omega - _x44*i_omega + _x7*i_omega*i_phase_td) + i_omega__tan*(_x28 + _x40 - 2.0*_x41 + 2.0*_x42)
    i_liftoff_q_thd = _x46*i_omega
    i_liftoff_q_thd__tan = _x46*i_omega__tan - _x47*i_a__tan - _x47*i_b*i_s_lo__tan - _x47*i_b__tan*i_s_lo
    # the leg stays above horizontal
    if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
        return _NAN22 + (STATUS_FALL,)
    # (internal helper: its callers check that their outputs are finite)
    return (i_q_thd_eff, i_q_thd_eff__tan, i_omega0_hat, i_a, i_b, i_phase_td, i_omega0_hat__tan, i_a__tan, i_b__tan, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, i_bottom_q_r, i_bottom_q_r__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_rd, i_liftoff_q_rd__tan, i_liftoff_q_th, i_liftoff_q_th__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_3(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_t_stance, i_t_stance__tan, l0):
    """branch leg_length = 0 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_phase_td: value of the caller's variable
        i_phase_td__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        l0: value of the caller's variable

    Returns a tuple:
        _i_L: result for the caller
        _i_L__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 57
    _x2 = (1.0/i_omega0_hat)
    _x8 = (1.0/i_t_stance)
    _x0 = math.cos(i_phase_td)
    _x1 = i_a + 1.0
    _x3 = _x2*i_phase_td
    _x4 = _x3 + i_t_stance
    _x5 = _x4*i_omega0_hat
    _x6 = math.cos(_x5)
    _x7 = _x0*i_b + _x1*_x5 - _x1*i_phase_td - _x6*i_b
    _x9 = _x2*_x8*l0
    _x10 = math.sin(_x5)
    _x11 = _x10*i_b
    _x12 = _x7*l0
    _i_L = _x7*_x9
    _i_L__tan = _x9*i_a__tan*(_x5 - i_phase_td) + _x9*i_b__tan*(_x0 - _x6) + _x9*i_phase_td__tan*(_x10*i_b - i_b*math.sin(i_phase_td)) + i_omega0_hat__tan*(-_x12*_x2**2*_x8 + _x9*(-_x1*_x3 + _x1*_x4 + _x11*i_t_stance)) + i_t_stance__tan*(-_x12*_x2*_x8**2 + _x9*(_x1*i_omega0_hat + _x11*i_omega0_hat))
    # (internal helper: its callers check that their outputs are finite)
    return (_i_L, _i_L__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_4(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_t_stance, i_t_stance__tan, l0):
    """branch leg_length = 1 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        l0: value of the caller's variable

    Returns a tuple:
        _i_L: result for the caller
        _i_L__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 81
    _x9 = (1.0/i_omega0_hat)
    _x10 = (1.0/i_t_stance)
    _x0 = i_omega0_hat*i_t_stance
    _x1 = math.sin(_x0)
    _x2 = i_a*i_t_stance
    _x3 = i_b**2
    _x4 = _x3 - i_a**2
    _x5 = math.sqrt(_x4/_x3)
    _x6 = _x5*i_b
    _x7 = math.cos(_x0)
    _x8 = -_x1*i_a + _x5*_x7*i_b - _x6 + i_omega0_hat*(_x2 + i_t_stance)
    _x11 = _x10*_x9*l0
    _x12 = (1.0/_x4)
    _x13 = _x1*_x6
    _x14 = _x8*l0
    _x15 = _x5*_x7
    _x16 = i_b**3
    _x17 = _x12*_x16*((1.0/i_b) - _x4/_x16)
    _i_L = _x11*_x8
    _i_L__tan = _x11*i_a__tan*(-_x1 + _x12*_x5*i_a*i_b - _x12*_x6*_x7*i_a + i_omega0_hat*i_t_stance) + _x11*i_b__tan*(_x15*_x17 + _x15 - _x17*_x5 - _x5) + i_omega0_hat__tan*(-_x10*_x14*_x9**2 + _x11*(-_x13*i_t_stance - _x2*_x7 + i_a*i_t_stance + i_t_stance)) + i_t_stance__tan*(-_x10**2*_x14*_x9 + _x11*(-_x13*i_omega0_hat - _x7*i_a*i_omega0_hat + i_omega0_hat*(i_a + 1.0)))
    # (internal helper: its callers check that their outputs are finite)
    return (_i_L, _i_L__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_5(g_s, i_omega0_hat, i_omega0_hat__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_stance, i_t_stance__tan, l0, q_rd_td, q_rd_td__tan):
    """branch leg_length = 2 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_q_thd_eff: value of the caller's variable
        i_q_thd_eff__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        l0: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable

    Returns a tuple:
        _i_L: result for the caller
        _i_L__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 78
    _x17 = (1.0/i_omega0_hat)
    _x12 = (1.0/i_t_stance)
    _x0 = i_omega0_hat*q_rd_td
    _x1 = i_omega0_hat*i_t_stance
    _x2 = math.sin(_x1)
    _x3 = i_q_thd_eff**2*l0
    _x4 = g_s*i_t_stance
    _x5 = math.cos(_x1)
    _x6 = _x5*q_rd_td
    _x7 = i_omega0_hat**2*l0
    _x8 = _x7*i_t_stance
    _x9 = _x3*i_t_stance
    _x10 = _x0 - _x2*_x3 + _x2*g_s - i_omega0_hat*(_x4 + _x6 - _x8 - _x9)
    _x11 = _x17**3
    _x13 = _x11*_x12
    _x14 = _x5*i_omega0_hat
    _x15 = 2.0*l0
    _x16 = _x1*_x15
    _i_L = _x10*_x13
    _i_L__tan = _x13*i_q_thd_eff__tan*(-_x15*_x2*i_q_thd_eff + _x16*i_q_thd_eff) + _x13*q_rd_td__tan*(-_x14 + i_omega0_hat) + i_omega0_hat__tan*(-3.0*_x10*_x12*_x17**4 + _x13*(_x4*_x5 - _x4 - _x5*_x9 - _x6 + _x8 + _x9 - i_omega0_hat*(-_x16 - _x2*i_t_stance*q_rd_td) + q_rd_td)) + i_t_stance__tan*(-_x10*_x11*_x12**2 + _x13*(-_x14*_x3 + _x5*g_s*i_omega0_hat - i_omega0_hat*(-_x0*_x2 - _x3 - _x7 + g_s)))
    # (internal helper: its callers check that their outputs are finite)
    return (_i_L, _i_L__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_6(g_s, i_a, i_a__tan, i_b, i_b__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_stance, i_t_stance__tan, l0, leg_length, m, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan):
    """branch interval = 0 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_liftoff_q_th: value of the caller's variable
        i_liftoff_q_th__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_phase_td: value of the caller's variable
        i_phase_td__tan: value of the caller's variable
        i_q_thd_eff: value of the caller's variable
        i_q_thd_eff__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        l0: value of the caller's variable
        leg_length: value of the caller's variable
        m: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable

    Returns a tuple:
        i_P_new: result for the caller
        i_P_new__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 28
    # average leg length, eqs (55)-(61) / (67)-(75)
    if leg_length == 0.0:
        # branch leg_length = 0
        _c0 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_3(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_t_stance, i_t_stance__tan, l0)
        if _c0[2] != STATUS_OK:
            return _NAN2 + (_c0[2],)
        _i_L = _c0[0]
        _i_L__tan = _c0[1]
    elif leg_length == 1.0:
        # branch leg_length = 1
        _c1 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_4(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_t_stance, i_t_stance__tan, l0)
        if _c1[2] != STATUS_OK:
            return _NAN2 + (_c1[2],)
        _i_L = _c1[0]
        _i_L__tan = _c1[1]
    elif leg_length == 2.0:
        # branch leg_length = 2
        _c2 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_5(g_s, i_omega0_hat, i_omega0_hat__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_stance, i_t_stance__tan, l0, q_rd_td, q_rd_td__tan)
        if _c2[2] != STATUS_OK:
            return _NAN2 + (_c2[2],)
        _i_L = _c2[0]
        _i_L__tan = _c2[1]
    else:
        return _NAN2 + (STATUS_INVALID_INPUT,)
    _x0 = g_s*m
    _x1 = _x0*math.sin(i_liftoff_q_th)
    _x2 = _i_L*_x1
    _x3 = _x0*math.sin(q_th_td)
    _x4 = _i_L*_x3
    _x5 = (0.5)*i_t_stance
    _x6 = _i_L*_x0*_x5
    i_P_new = _x5*(_x2 + _x4)
    i_P_new__tan = _i_L__tan*_x5*(_x1 + _x3) + _x6*i_liftoff_q_th__tan*math.cos(i_liftoff_q_th) + _x6*q_th_td__tan*math.cos(q_th_td) + i_t_stance__tan*((0.5)*_x2 + (0.5)*_x4)
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new, i_P_new__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_7(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, l0):
    """branch leg_length = 0 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_phase_td: value of the caller's variable
        i_phase_td__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        l0: value of the caller's variable

    Returns a tuple:
        _i_L1: result for the caller
        _i_L1__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 57
    _x2 = (1.0/i_omega0_hat)
    _x8 = (1.0/i_t_bottom)
    _x0 = math.cos(i_phase_td)
    _x1 = i_a + 1.0
    _x3 = _x2*i_phase_td
    _x4 = _x3 + i_t_bottom
    _x5 = _x4*i_omega0_hat
    _x6 = math.cos(_x5)
    _x7 = _x0*i_b + _x1*_x5 - _x1*i_phase_td - _x6*i_b
    _x9 = _x2*_x8*l0
    _x10 = math.sin(_x5)
    _x11 = _x10*i_b
    _x12 = _x7*l0
    _i_L1 = _x7*_x9
    _i_L1__tan = _x9*i_a__tan*(_x5 - i_phase_td) + _x9*i_b__tan*(_x0 - _x6) + _x9*i_phase_td__tan*(_x10*i_b - i_b*math.sin(i_phase_td)) + i_omega0_hat__tan*(-_x12*_x2**2*_x8 + _x9*(-_x1*_x3 + _x1*_x4 + _x11*i_t_bottom)) + i_t_bottom__tan*(-_x12*_x2*_x8**2 + _x9*(_x1*i_omega0_hat + _x11*i_omega0_hat))
    # (internal helper: its callers check that their outputs are finite)
    return (_i_L1, _i_L1__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_8(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_t_bottom, i_t_bottom__tan, l0):
    """branch leg_length = 1 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        l0: value of the caller's variable

    Returns a tuple:
        _i_L1: result for the caller
        _i_L1__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 81
    _x9 = (1.0/i_omega0_hat)
    _x10 = (1.0/i_t_bottom)
    _x0 = i_omega0_hat*i_t_bottom
    _x1 = math.sin(_x0)
    _x2 = i_a*i_t_bottom
    _x3 = i_b**2
    _x4 = _x3 - i_a**2
    _x5 = math.sqrt(_x4/_x3)
    _x6 = _x5*i_b
    _x7 = math.cos(_x0)
    _x8 = -_x1*i_a + _x5*_x7*i_b - _x6 + i_omega0_hat*(_x2 + i_t_bottom)
    _x11 = _x10*_x9*l0
    _x12 = (1.0/_x4)
    _x13 = _x1*_x6
    _x14 = _x8*l0
    _x15 = _x5*_x7
    _x16 = i_b**3
    _x17 = _x12*_x16*((1.0/i_b) - _x4/_x16)
    _i_L1 = _x11*_x8
    _i_L1__tan = _x11*i_a__tan*(-_x1 + _x12*_x5*i_a*i_b - _x12*_x6*_x7*i_a + i_omega0_hat*i_t_bottom) + _x11*i_b__tan*(_x15*_x17 + _x15 - _x17*_x5 - _x5) + i_omega0_hat__tan*(-_x10*_x14*_x9**2 + _x11*(-_x13*i_t_bottom - _x2*_x7 + i_a*i_t_bottom + i_t_bottom)) + i_t_bottom__tan*(-_x10**2*_x14*_x9 + _x11*(-_x13*i_omega0_hat - _x7*i_a*i_omega0_hat + i_omega0_hat*(i_a + 1.0)))
    # (internal helper: its callers check that their outputs are finite)
    return (_i_L1, _i_L1__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_9(g_s, i_omega0_hat, i_omega0_hat__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_bottom, i_t_bottom__tan, l0, q_rd_td, q_rd_td__tan):
    """branch leg_length = 2 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_q_thd_eff: value of the caller's variable
        i_q_thd_eff__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        l0: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable

    Returns a tuple:
        _i_L1: result for the caller
        _i_L1__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 78
    _x17 = (1.0/i_omega0_hat)
    _x12 = (1.0/i_t_bottom)
    _x0 = i_omega0_hat*q_rd_td
    _x1 = i_omega0_hat*i_t_bottom
    _x2 = math.sin(_x1)
    _x3 = i_q_thd_eff**2*l0
    _x4 = g_s*i_t_bottom
    _x5 = math.cos(_x1)
    _x6 = _x5*q_rd_td
    _x7 = i_omega0_hat**2*l0
    _x8 = _x7*i_t_bottom
    _x9 = _x3*i_t_bottom
    _x10 = _x0 - _x2*_x3 + _x2*g_s - i_omega0_hat*(_x4 + _x6 - _x8 - _x9)
    _x11 = _x17**3
    _x13 = _x11*_x12
    _x14 = _x5*i_omega0_hat
    _x15 = 2.0*l0
    _x16 = _x1*_x15
    _i_L1 = _x10*_x13
    _i_L1__tan = _x13*i_q_thd_eff__tan*(-_x15*_x2*i_q_thd_eff + _x16*i_q_thd_eff) + _x13*q_rd_td__tan*(-_x14 + i_omega0_hat) + i_omega0_hat__tan*(-3.0*_x10*_x12*_x17**4 + _x13*(_x4*_x5 - _x4 - _x5*_x9 - _x6 + _x8 + _x9 - i_omega0_hat*(-_x16 - _x2*i_t_bottom*q_rd_td) + q_rd_td)) + i_t_bottom__tan*(-_x10*_x11*_x12**2 + _x13*(-_x14*_x3 + _x5*g_s*i_omega0_hat - i_omega0_hat*(-_x0*_x2 - _x3 - _x7 + g_s)))
    # (internal helper: its callers check that their outputs are finite)
    return (_i_L1, _i_L1__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_10(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0):
    """branch leg_length = 0 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_phase_td: value of the caller's variable
        i_phase_td__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        l0: value of the caller's variable

    Returns a tuple:
        _i_L2: result for the caller
        _i_L2__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 71
    _x0 = (1.0/i_omega0_hat)
    _x1 = _x0*i_phase_td
    _x2 = _x1 + i_t_bottom
    _x3 = _x2*i_omega0_hat
    _x4 = math.cos(_x3)
    _x5 = i_a + 1.0
    _x6 = _x1 + i_t_stance
    _x7 = _x6*i_omega0_hat
    _x8 = math.cos(_x7)
    _x9 = -_x3*_x5 + _x4*i_b + _x5*_x7 - _x8*i_b
    _x10 = -i_t_bottom + i_t_stance
    _x11 = (1.0/_x10)
    _x12 = _x0*_x11*l0
    _x13 = i_b*math.sin(_x3)
    _x14 = math.sin(_x7)
    _x15 = _x5*i_omega0_hat
    _x16 = _x9*l0
    _x17 = _x0*_x11**2*_x16
    _i_L2 = _x12*_x9
    _i_L2__tan = _x12*i_a__tan*(-_x3 + _x6*i_omega0_hat) + _x12*i_b__tan*(_x4 - _x8) + _x12*i_phase_td__tan*(-_x13 + _x14*i_b) + i_omega0_hat__tan*(-_x0**2*_x11*_x16 + _x12*(-_x13*i_t_bottom + _x14*i_b*i_t_stance - _x2*_x5 + _x5*_x6)) + i_t_bottom__tan*(_x12*(-_x13*i_omega0_hat - _x15) + _x17) + i_t_stance__tan*(_x12*(_x14*i_b*i_omega0_hat + _x15) - _x17)
    # (internal helper: its callers check that their outputs are finite)
    return (_i_L2, _i_L2__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_11(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0):
    """branch leg_length = 1 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        l0: value of the caller's variable

    Returns a tuple:
        _i_L2: result for the caller
        _i_L2__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 109
    _x15 = (1.0/i_omega0_hat)
    _x0 = i_omega0_hat*i_t_bottom
    _x1 = math.sin(_x0)
    _x2 = i_omega0_hat*i_t_stance
    _x3 = math.sin(_x2)
    _x4 = i_a*i_t_bottom
    _x5 = i_t_bottom - i_t_stance
    _x6 = math.cos(_x2)
    _x7 = i_b**2
    _x8 = _x7 - i_a**2
    _x9 = math.sqrt(_x8/_x7)
    _x10 = _x6*_x9*i_b
    _x11 = math.cos(_x0)
    _x12 = _x11*_x9
    _x13 = _x12*i_b
    _x14 = _x1*i_a + _x10 - _x13 - _x3*i_a + i_omega0_hat*(-_x4 - _x5 + i_a*i_t_stance)
    _x16 = -_x5
    _x17 = (1.0/_x16)
    _x18 = _x15*_x17*l0
    _x19 = (1.0/_x8)
    _x20 = _x19*i_a
    _x21 = i_a + 1.0
    _x22 = i_a*i_omega0_hat
    _x23 = _x9*i_b
    _x24 = _x1*_x23
    _x25 = _x14*l0
    _x26 = _x15*_x17**2*_x25
    _x27 = _x23*_x3
    _x28 = i_b**3
    _x29 = (1.0/i_b) - _x8/_x28
    _x30 = i_a*i_t_stance
    _i_L2 = _x14*_x18
    _i_L2__tan = _x18*i_a__tan*(_x1 - _x10*_x20 + _x13*_x20 + _x16*i_omega0_hat - _x3) + _x18*i_b__tan*(-_x12*_x19*_x28*_x29 - _x12 + _x19*_x28*_x29*_x6*_x9 + _x6*_x9) + i_omega0_hat__tan*(-_x15**2*_x17*_x25 + _x18*(_x11*_x4 + _x24*i_t_bottom - _x27*i_t_stance - _x30*_x6 + _x30 - _x4 - i_t_bottom + i_t_stance)) + i_t_bottom__tan*(_x18*(_x11*_x22 - _x21*i_omega0_hat + _x24*i_omega0_hat) + _x26) + i_t_stance__tan*(_x18*(_x21*i_omega0_hat - _x22*_x6 - _x27*i_omega0_hat) - _x26)
    # (internal helper: its callers check that their outputs are finite)
    return (_i_L2, _i_L2__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_12(g_s, i_omega0_hat, i_omega0_hat__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0, q_rd_td, q_rd_td__tan):
    """branch leg_length = 2 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_q_thd_eff: value of the caller's variable
        i_q_thd_eff__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        l0: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable

    Returns a tuple:
        _i_L2: result for the caller
        _i_L2__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 133
    _x27 = (1.0/i_omega0_hat)
    _x0 = i_omega0_hat*i_t_bottom
    _x1 = math.sin(_x0)
    _x2 = i_omega0_hat*i_t_stance
    _x3 = math.sin(_x2)
    _x4 = i_q_thd_eff**2
    _x5 = _x4*l0
    _x6 = math.cos(_x2)
    _x7 = i_omega0_hat**2*l0
    _x8 = _x5*i_t_stance
    _x9 = _x6*q_rd_td - _x7*i_t_stance - _x8 + g_s*i_t_stance
    _x10 = g_s*i_t_bottom
    _x11 = math.cos(_x0)
    _x12 = _x7*i_t_bottom
    _x13 = _x5*i_t_bottom
    _x14 = _x1*_x4*l0 - _x1*g_s - _x3*_x5 + _x3*g_s - _x9*i_omega0_hat + i_omega0_hat*(_x10 + _x11*q_rd_td - _x12 - _x13)
    _x15 = _x27**3
    _x16 = -i_t_bottom + i_t_stance
    _x17 = (1.0/_x16)
    _x18 = _x15*_x17
    _x19 = _x11*i_omega0_hat
    _x20 = _x6*i_omega0_hat
    _x21 = 2.0*l0
    _x22 = _x0*_x21
    _x23 = _x1*q_rd_td
    _x24 = _x5 + _x7 - g_s
    _x25 = _x14*_x15*_x17**2
    _x26 = _x3*q_rd_td
    _i_L2 = _x14*_x18
    _i_L2__tan = _x18*i_q_thd_eff__tan*(2.0*_x1*i_q_thd_eff*l0 - _x21*_x3*i_q_thd_eff - _x22*i_q_thd_eff + 2.0*i_omega0_hat*i_q_thd_eff*i_t_stance*l0) + _x18*q_rd_td__tan*(_x19 - _x20) + i_omega0_hat__tan*(-3.0*_x14*_x17*_x27**4 + _x18*(-_x10*_x11 + _x11*_x4*i_t_bottom*l0 + _x11*q_rd_td - _x12 - _x13 - _x6*_x8 + _x6*g_s*i_t_stance - _x9 + g_s*i_t_bottom + i_omega0_hat*(-_x22 - _x23*i_t_bottom) - i_omega0_hat*(-_x2*_x21 - _x26*i_t_stance))) + i_t_bottom__tan*(_x18*(_x19*_x5 - _x19*g_s + i_omega0_hat*(-_x23*i_omega0_hat - _x24)) + _x25) + i_t_stance__tan*(_x18*(-_x20*_x5 + _x6*g_s*i_omega0_hat - i_omega0_hat*(-_x24 - _x26*i_omega0_hat)) - _x25)
    # (internal helper: its callers check that their outputs are finite)
    return (_i_L2, _i_L2__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_13(g_s, i_a, i_a__tan, i_b, i_b__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0, leg_length, m, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan):
    """branch interval = 1 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_bottom_q_th: value of the caller's variable
        i_bottom_q_th__tan: value of the caller's variable
        i_liftoff_q_th: value of the caller's variable
        i_liftoff_q_th__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_phase_td: value of the caller's variable
        i_phase_td__tan: value of the caller's variable
        i_q_thd_eff: value of the caller's variable
        i_q_thd_eff__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        l0: value of the caller's variable
        leg_length: value of the caller's variable
        m: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable

    Returns a tuple:
        i_P_new: result for the caller
        i_P_new__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 58
    # average leg length, eqs (55)-(61) / (67)-(75)
    if leg_length == 0.0:
        # branch leg_length = 0
        _c0 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_7(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, l0)
        if _c0[2] != STATUS_OK:
            return _NAN2 + (_c0[2],)
        _i_L1 = _c0[0]
        _i_L1__tan = _c0[1]
    elif leg_length == 1.0:
        # branch leg_length = 1
        _c1 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_8(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_t_bottom, i_t_bottom__tan, l0)
        if _c1[2] != STATUS_OK:
            return _NAN2 + (_c1[2],)
        _i_L1 = _c1[0]
        _i_L1__tan = _c1[1]
    elif leg_length == 2.0:
        # branch leg_length = 2
        _c2 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_9(g_s, i_omega0_hat, i_omega0_hat__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_bottom, i_t_bottom__tan, l0, q_rd_td, q_rd_td__tan)
        if _c2[2] != STATUS_OK:
            return _NAN2 + (_c2[2],)
        _i_L1 = _c2[0]
        _i_L1__tan = _c2[1]
    else:
        return _NAN2 + (STATUS_INVALID_INPUT,)
    # average leg length, eqs (55)-(61) / (67)-(75)
    if leg_length == 0.0:
        # branch leg_length = 0
        _c3 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_10(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0)
        if _c3[2] != STATUS_OK:
            return _NAN2 + (_c3[2],)
        _i_L2 = _c3[0]
        _i_L2__tan = _c3[1]
    elif leg_length == 1.0:
        # branch leg_length = 1
        _c4 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_11(i_a, i_a__tan, i_b, i_b__tan, i_omega0_hat, i_omega0_hat__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0)
        if _c4[2] != STATUS_OK:
            return _NAN2 + (_c4[2],)
        _i_L2 = _c4[0]
        _i_L2__tan = _c4[1]
    elif leg_length == 2.0:
        # branch leg_length = 2
        _c5 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_12(g_s, i_omega0_hat, i_omega0_hat__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0, q_rd_td, q_rd_td__tan)
        if _c5[2] != STATUS_OK:
            return _NAN2 + (_c5[2],)
        _i_L2 = _c5[0]
        _i_L2__tan = _c5[1]
    else:
        return _NAN2 + (STATUS_INVALID_INPUT,)
    _x0 = g_s*m
    _x1 = _x0*math.sin(i_bottom_q_th)
    _x2 = _i_L1*_x1
    _x3 = _x0*math.sin(q_th_td)
    _x4 = _i_L1*_x3
    _x5 = (0.5)*i_t_bottom
    _x6 = _i_L2*_x1
    _x7 = _x0*math.sin(i_liftoff_q_th)
    _x8 = _i_L2*_x7
    _x9 = -0.5*i_t_bottom + (0.5)*i_t_stance
    _x10 = _i_L1*_x5
    _x11 = _i_L2*_x9
    _x12 = (0.5)*_x6
    _x13 = (0.5)*_x8
    _x14 = _x0*math.cos(i_bottom_q_th)
    i_P_new = _x5*(_x2 + _x4) + _x9*(_x6 + _x8)
    i_P_new__tan = _i_L1__tan*_x5*(_x1 + _x3) + _i_L2__tan*_x9*(_x1 + _x7) + _x0*_x10*q_th_td__tan*math.cos(q_th_td) + _x0*_x11*i_liftoff_q_th__tan*math.cos(i_liftoff_q_th) + i_bottom_q_th__tan*(_x10*_x14 + _x11*_x14) + i_t_bottom__tan*(-_x12 - _x13 + (0.5)*_x2 + (0.5)*_x4) + i_t_stance__tan*(_x12 + _x13)
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new, i_P_new__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_14(g_s, i_a, i_a__tan, i_b, i_b__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, interval, l0, leg_length, m, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan):
    """loop body of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_bottom_q_th: value of the caller's variable
        i_bottom_q_th__tan: value of the caller's variable
        i_liftoff_q_th: value of the caller's variable
        i_liftoff_q_th__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_phase_td: value of the caller's variable
        i_phase_td__tan: value of the caller's variable
        i_q_thd_eff: value of the caller's variable
        i_q_thd_eff__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        interval: value of the caller's variable
        l0: value of the caller's variable
        leg_length: value of the caller's variable
        m: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable

    Returns a tuple:
        _next_P_c: result for the caller
        _next_P_c__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # eq (76)
    if interval == 0.0:
        # branch interval = 0
        _c0 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_6(g_s, i_a, i_a__tan, i_b, i_b__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_stance, i_t_stance__tan, l0, leg_length, m, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan)
        if _c0[2] != STATUS_OK:
            return _NAN2 + (_c0[2],)
        i_P_new = _c0[0]
        i_P_new__tan = _c0[1]
    elif interval == 1.0:
        # branch interval = 1
        _c1 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_13(g_s, i_a, i_a__tan, i_b, i_b__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, l0, leg_length, m, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan)
        if _c1[2] != STATUS_OK:
            return _NAN2 + (_c1[2],)
        i_P_new = _c1[0]
        i_P_new__tan = _c1[1]
    else:
        return _NAN2 + (STATUS_INVALID_INPUT,)
    # next values
    _next_P_c = i_P_new
    _next_P_c__tan = i_P_new__tan
    # (internal helper: its callers check that their outputs are finite)
    return (_next_P_c, _next_P_c__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_15(E_td, E_td__tan, P_c, P_c__tan, g_s, i_liftoff_q_th, i_liftoff_q_th__tan, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo):
    """branch reading = 0 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_td: value of the caller's variable
        E_td__tan: value of the caller's variable
        P_c: value of the caller's variable
        P_c__tan: value of the caller's variable
        g_s: value of the caller's variable
        i_liftoff_q_th: value of the caller's variable
        i_liftoff_q_th__tan: value of the caller's variable
        k: value of the caller's variable
        k__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        p_td: value of the caller's variable
        p_td__tan: value of the caller's variable
        q_r_lo: value of the caller's variable

    Returns a tuple:
        liftoff_q_rd: result for the caller
        liftoff_q_rd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 52
    _x0 = (1.0/m)
    _x1 = 2.0*g_s*q_r_lo
    _x2 = _x0*l0**2
    _x3 = q_r_lo**2
    _x4 = _x0*_x3
    _x5 = _x0**2/_x3
    _x6 = _x5*(2.0*P_c + 2.0*p_td)
    _q_rd_lo_sq = 2.0*E_td*_x0 + 2.0*_x0*k*l0*q_r_lo - _x1*math.cos(i_liftoff_q_th) - _x2*k - _x4*k - _x5*(P_c + p_td)**2
    _q_rd_lo_sq__tan = 2.0*E_td__tan*_x0 - P_c__tan*_x6 + _x1*i_liftoff_q_th__tan*math.sin(i_liftoff_q_th) - _x6*p_td__tan + k__tan*(2.0*_x0*l0*q_r_lo - _x2 - _x4)
    # q_rd_lo^2 from the energy (27)
    if not ((_q_rd_lo_sq >= 0.0)):
        return _NAN2 + (STATUS_ENERGY_DEFICIT,)
    # q_rd_lo from the energy
    _x7 = math.sqrt(_q_rd_lo_sq)
    liftoff_q_rd = _x7
    liftoff_q_rd__tan = (0.5)*_q_rd_lo_sq__tan/_x7
    # (internal helper: its callers check that their outputs are finite)
    return (liftoff_q_rd, liftoff_q_rd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_16(i_liftoff_q_rd, i_liftoff_q_rd__tan):
    """branch reading = 1 of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        i_liftoff_q_rd: value of the caller's variable
        i_liftoff_q_rd__tan: value of the caller's variable

    Returns a tuple:
        liftoff_q_rd: result for the caller
        liftoff_q_rd__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # from (11)
    liftoff_q_rd = i_liftoff_q_rd
    liftoff_q_rd__tan = i_liftoff_q_rd__tan
    # (internal helper: its callers check that their outputs are finite)
    return (liftoff_q_rd, liftoff_q_rd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_17(E_td, E_td__tan, P_c, P_c__tan, g_s, i_bottom_q_r, i_bottom_q_r__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_rd, i_liftoff_q_rd__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo, ramp, reading):
    """continuation of gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_td: value of the caller's variable
        E_td__tan: value of the caller's variable
        P_c: value of the caller's variable
        P_c__tan: value of the caller's variable
        g_s: value of the caller's variable
        i_bottom_q_r: value of the caller's variable
        i_bottom_q_r__tan: value of the caller's variable
        i_bottom_q_th: value of the caller's variable
        i_bottom_q_th__tan: value of the caller's variable
        i_liftoff_q_rd: value of the caller's variable
        i_liftoff_q_rd__tan: value of the caller's variable
        i_liftoff_q_th: value of the caller's variable
        i_liftoff_q_th__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        k: value of the caller's variable
        k__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        p_td: value of the caller's variable
        p_td__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        ramp: value of the caller's variable
        reading: value of the caller's variable

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
    # Total ops: 39
    # the rates from the momentum at that instant; p_td + P_c at liftoff, eq (50)
    _x7 = (1.0/i_bottom_q_r)
    _x8 = (1.0/i_t_stance)
    _x0 = _x8*ramp
    _x1 = _x0*i_t_bottom - ramp + 1.0
    _x2 = P_c*_x1 + p_td
    _x3 = (1.0/m)
    _x4 = _x3*_x7**2
    _x5 = P_c*_x4
    _x6 = _x3/q_r_lo**2
    t_bottom = i_t_bottom
    t_bottom__tan = i_t_bottom__tan
    t_stance = i_t_stance
    t_stance__tan = i_t_stance__tan
    bottom_q_r = i_bottom_q_r
    bottom_q_r__tan = i_bottom_q_r__tan
    bottom_q_rd = 0.0
    bottom_q_th = i_bottom_q_th
    bottom_q_th__tan = i_bottom_q_th__tan
    bottom_q_thd = _x2*_x4
    bottom_q_thd__tan = P_c__tan*_x1*_x4 + _x0*_x5*i_t_bottom__tan - 2.0*_x2*_x3*_x7**3*i_bottom_q_r__tan + _x4*p_td__tan - _x5*_x8**2*i_t_bottom*i_t_stance__tan*ramp
    liftoff_q_r = q_r_lo
    liftoff_q_th = i_liftoff_q_th
    liftoff_q_th__tan = i_liftoff_q_th__tan
    liftoff_q_thd = _x6*(P_c + p_td)
    liftoff_q_thd__tan = P_c__tan*_x6 + _x6*p_td__tan
    if reading == 0.0:
        # branch reading = 0
        _c0 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_15(E_td, E_td__tan, P_c, P_c__tan, g_s, i_liftoff_q_th, i_liftoff_q_th__tan, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo)
        if _c0[2] != STATUS_OK:
            return _NAN21 + (_c0[2],)
        liftoff_q_rd = _c0[0]
        liftoff_q_rd__tan = _c0[1]
    elif reading == 1.0:
        # branch reading = 1
        _c1 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_16(i_liftoff_q_rd, i_liftoff_q_rd__tan)
        if _c1[2] != STATUS_OK:
            return _NAN21 + (_c1[2],)
        liftoff_q_rd = _c1[0]
        liftoff_q_rd__tan = _c1[1]
    else:
        return _NAN21 + (STATUS_INVALID_INPUT,)
    # derivatives that are identically zero
    bottom_q_rd__tan = 0.0
    liftoff_q_r__tan = 0.0
    passes__tan = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k__tan):
    """Gravity correction type 4 (average leg length on [t_i, t_f]): touchdown state -> bottom and liftoff states, with the derivative of every output along the direction (q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k__tan).

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        reading: option reading: how P_c enters Geyer's formulas, eq (50): 0 = mean, 1 = report
        interval: option interval: the intervals [t_i, t_f] of the correction: 0 = stance, 1 = halves
        leg_length: option leg_length: the stance solution the average leg length is taken from: 0 = eq11, 1 = eq21, 2 = eq23
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0, 1]
        q_r_td__tan: direction: its component along q_r_td
        q_rd_td__tan: direction: its component along q_rd_td
        q_th_td__tan: direction: its component along q_th_td
        q_thd_td__tan: direction: its component along q_thd_td
        k__tan: direction: its component along k

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
        P_c: virtual gravity effect: the stance impulse added to p_th [N m s]
        passes: fixed-point passes run
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
        P_c__tan: derivative of P_c along the direction
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 52
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(reading) and math.isfinite(interval) and math.isfinite(leg_length) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(q_r_td__tan) and math.isfinite(q_rd_td__tan) and math.isfinite(q_th_td__tan) and math.isfinite(q_thd_td__tan) and math.isfinite(k__tan) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((reading == 0.0) or (reading == 1.0)) and ((interval == 0.0) or (interval == 1.0)) and ((leg_length == 0.0) or (leg_length == 1.0) or (leg_length == 2.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN24 + (STATUS_INVALID_INPUT,)
    # leg_length eq21/eq23 need q_r_td = l0
    if not ((leg_length == 0.0) or (abs(l0 - q_r_td) <= 1e-09*l0)):
        return _NAN24 + (STATUS_INVALID_INPUT,)
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
    E_td = -_x3*k + _x4*k + _x5*_x8 + _x5*k + _x7*q_r_td + (0.5)*m*q_rd_td**2
    E_td__tan = _x2*q_thd_td__tan - _x6*q_r_td*q_th_td__tan*math.sin(q_th_td) + k__tan*(-_x3 + _x4 + _x5) + m*q_rd_td*q_rd_td__tan + q_r_td__tan*(_x7 + _x8*q_r_td - k*l0 + k*q_r_td)
    # trajectory momentum p_td + share P_c: the stance mean (P_c/2) or the report's
    if reading == 0.0:
        # branch reading = 0
        _c0 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_0()
        if _c0[2] != STATUS_OK:
            return _NAN24 + (_c0[2],)
        share = _c0[0]
        ramp = _c0[1]
    elif reading == 1.0:
        # branch reading = 1
        _c1 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_1()
        if _c1[2] != STATUS_OK:
            return _NAN24 + (_c1[2],)
        share = _c1[0]
        ramp = _c1[1]
    else:
        return _NAN24 + (STATUS_INVALID_INPUT,)
    # fixed point of the virtual gravity effect, from P_c = 0 (Geyer's map)
    P_c = 0.0
    P_c__tan = 0.0
    passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return _NAN24 + (STATUS_NOT_CONVERGED,)
        # evaluation of the iterate
        _c2 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_2(P_c, P_c__tan, g_s, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, share)
        if _c2[22] != STATUS_OK:
            return _NAN24 + (_c2[22],)
        (i_q_thd_eff, i_q_thd_eff__tan, i_omega0_hat, i_a, i_b, i_phase_td, i_omega0_hat__tan, i_a__tan, i_b__tan, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, i_bottom_q_r, i_bottom_q_r__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_rd, i_liftoff_q_rd__tan, i_liftoff_q_th, i_liftoff_q_th__tan, _) = _c2
        if _conv0 or _it0 == _last0:
            break
        # loop body
        _c3 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_14(g_s, i_a, i_a__tan, i_b, i_b__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_q_thd_eff, i_q_thd_eff__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, interval, l0, leg_length, m, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan)
        if _c3[2] != STATUS_OK:
            return _NAN24 + (_c3[2],)
        _next_P_c = _c3[0]
        _next_P_c__tan = _c3[1]
        _n0_0 = _next_P_c
        _n0_1 = _next_P_c__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - P_c) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + abs(p_td)))
        P_c = _n0_0
        P_c__tan = _n0_1
        passes += 1.0
    # continuation
    _c4 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_17(E_td, E_td__tan, P_c, P_c__tan, g_s, i_bottom_q_r, i_bottom_q_r__tan, i_bottom_q_th, i_bottom_q_th__tan, i_liftoff_q_rd, i_liftoff_q_rd__tan, i_liftoff_q_th, i_liftoff_q_th__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo, ramp, reading)
    if _c4[21] != STATUS_OK:
        return _NAN24 + (_c4[21],)
    (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, passes__tan, _) = _c4
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, P_c__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol):
    """Gravity correction type 4 (average leg length on [t_i, t_f]): stance outputs and their derivatives with respect to the touchdown state and the stiffness.

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        reading: option reading: how P_c enters Geyer's formulas, eq (50): 0 = mean, 1 = report
        interval: option interval: the intervals [t_i, t_f] of the correction: 0 = stance, 1 = halves
        leg_length: option leg_length: the stance solution the average leg length is taken from: 0 = eq11, 1 = eq21, 2 = eq23
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
        P_c: virtual gravity effect: the stance impulse added to p_th [N m s]
        passes: fixed-point passes run
        d_t_bottom__q_r_td: d t_bottom / d q_r_td
        d_t_bottom__q_rd_td: d t_bottom / d q_rd_td
        d_t_bottom__q_th_td: d t_bottom / d q_th_td
        d_t_bottom__q_thd_td: d t_bottom / d q_thd_td
        d_t_bottom__k: d t_bottom / d k
        d_t_stance__q_r_td: d t_stance / d q_r_td
        d_t_stance__q_rd_td: d t_stance / d q_rd_td
        d_t_stance__q_th_td: d t_stance / d q_th_td
        d_t_stance__q_thd_td: d t_stance / d q_thd_td
        d_t_stance__k: d t_stance / d k
        d_bottom_q_r__q_r_td: d bottom_q_r / d q_r_td
        d_bottom_q_r__q_rd_td: d bottom_q_r / d q_rd_td
        d_bottom_q_r__q_th_td: d bottom_q_r / d q_th_td
        d_bottom_q_r__q_thd_td: d bottom_q_r / d q_thd_td
        d_bottom_q_r__k: d bottom_q_r / d k
        d_bottom_q_rd__q_r_td: d bottom_q_rd / d q_r_td
        d_bottom_q_rd__q_rd_td: d bottom_q_rd / d q_rd_td
        d_bottom_q_rd__q_th_td: d bottom_q_rd / d q_th_td
        d_bottom_q_rd__q_thd_td: d bottom_q_rd / d q_thd_td
        d_bottom_q_rd__k: d bottom_q_rd / d k
        d_bottom_q_th__q_r_td: d bottom_q_th / d q_r_td
        d_bottom_q_th__q_rd_td: d bottom_q_th / d q_rd_td
        d_bottom_q_th__q_th_td: d bottom_q_th / d q_th_td
        d_bottom_q_th__q_thd_td: d bottom_q_th / d q_thd_td
        d_bottom_q_th__k: d bottom_q_th / d k
        d_bottom_q_thd__q_r_td: d bottom_q_thd / d q_r_td
        d_bottom_q_thd__q_rd_td: d bottom_q_thd / d q_rd_td
        d_bottom_q_thd__q_th_td: d bottom_q_thd / d q_th_td
        d_bottom_q_thd__q_thd_td: d bottom_q_thd / d q_thd_td
        d_bottom_q_thd__k: d bottom_q_thd / d k
        d_liftoff_q_r__q_r_td: d liftoff_q_r / d q_r_td
        d_liftoff_q_r__q_rd_td: d liftoff_q_r / d q_rd_td
        d_liftoff_q_r__q_th_td: d liftoff_q_r / d q_th_td
        d_liftoff_q_r__q_thd_td: d liftoff_q_r / d q_thd_td
        d_liftoff_q_r__k: d liftoff_q_r / d k
        d_liftoff_q_rd__q_r_td: d liftoff_q_rd / d q_r_td
        d_liftoff_q_rd__q_rd_td: d liftoff_q_rd / d q_rd_td
        d_liftoff_q_rd__q_th_td: d liftoff_q_rd / d q_th_td
        d_liftoff_q_rd__q_thd_td: d liftoff_q_rd / d q_thd_td
        d_liftoff_q_rd__k: d liftoff_q_rd / d k
        d_liftoff_q_th__q_r_td: d liftoff_q_th / d q_r_td
        d_liftoff_q_th__q_rd_td: d liftoff_q_th / d q_rd_td
        d_liftoff_q_th__q_th_td: d liftoff_q_th / d q_th_td
        d_liftoff_q_th__q_thd_td: d liftoff_q_th / d q_thd_td
        d_liftoff_q_th__k: d liftoff_q_th / d k
        d_liftoff_q_thd__q_r_td: d liftoff_q_thd / d q_r_td
        d_liftoff_q_thd__q_rd_td: d liftoff_q_thd / d q_rd_td
        d_liftoff_q_thd__q_th_td: d liftoff_q_thd / d q_th_td
        d_liftoff_q_thd__q_thd_td: d liftoff_q_thd / d q_thd_td
        d_liftoff_q_thd__k: d liftoff_q_thd / d k
        d_P_c__q_r_td: d P_c / d q_r_td
        d_P_c__q_rd_td: d P_c / d q_rd_td
        d_P_c__q_th_td: d P_c / d q_th_td
        d_P_c__q_thd_td: d P_c / d q_thd_td
        d_P_c__k: d P_c / d k
        d_passes__q_r_td: d passes / d q_r_td
        d_passes__q_rd_td: d passes / d q_rd_td
        d_passes__q_th_td: d passes / d q_th_td
        d_passes__q_thd_td: d passes / d q_thd_td
        d_passes__k: d passes / d k
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(reading) and math.isfinite(interval) and math.isfinite(leg_length) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((reading == 0.0) or (reading == 1.0)) and ((interval == 0.0) or (interval == 1.0)) and ((leg_length == 0.0) or (leg_length == 1.0) or (leg_length == 2.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN72 + (STATUS_INVALID_INPUT,)
    # derivatives with respect to q_r_td
    _c0 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol, 1.0, 0.0, 0.0, 0.0, 0.0)
    if _c0[24] != STATUS_OK:
        return _NAN72 + (_c0[24],)
    (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_t_bottom__q_r_td, d_t_stance__q_r_td, d_bottom_q_r__q_r_td, d_bottom_q_rd__q_r_td, d_bottom_q_th__q_r_td, d_bottom_q_thd__q_r_td, d_liftoff_q_r__q_r_td, d_liftoff_q_rd__q_r_td, d_liftoff_q_th__q_r_td, d_liftoff_q_thd__q_r_td, d_P_c__q_r_td, d_passes__q_r_td, _) = _c0
    # derivatives with respect to q_rd_td
    _c1 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol, 0.0, 1.0, 0.0, 0.0, 0.0)
    if _c1[24] != STATUS_OK:
        return _NAN72 + (_c1[24],)
    (_, _, _, _, _, _, _, _, _, _, _, _, d_t_bottom__q_rd_td, d_t_stance__q_rd_td, d_bottom_q_r__q_rd_td, d_bottom_q_rd__q_rd_td, d_bottom_q_th__q_rd_td, d_bottom_q_thd__q_rd_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_thd__q_rd_td, d_P_c__q_rd_td, d_passes__q_rd_td, _) = _c1
    # derivatives with respect to q_th_td
    _c2 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol, 0.0, 0.0, 1.0, 0.0, 0.0)
    if _c2[24] != STATUS_OK:
        return _NAN72 + (_c2[24],)
    (_, _, _, _, _, _, _, _, _, _, _, _, d_t_bottom__q_th_td, d_t_stance__q_th_td, d_bottom_q_r__q_th_td, d_bottom_q_rd__q_th_td, d_bottom_q_th__q_th_td, d_bottom_q_thd__q_th_td, d_liftoff_q_r__q_th_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_th__q_th_td, d_liftoff_q_thd__q_th_td, d_P_c__q_th_td, d_passes__q_th_td, _) = _c2
    # derivatives with respect to q_thd_td
    _c3 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol, 0.0, 0.0, 0.0, 1.0, 0.0)
    if _c3[24] != STATUS_OK:
        return _NAN72 + (_c3[24],)
    (_, _, _, _, _, _, _, _, _, _, _, _, d_t_bottom__q_thd_td, d_t_stance__q_thd_td, d_bottom_q_r__q_thd_td, d_bottom_q_rd__q_thd_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__q_thd_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_thd__q_thd_td, d_P_c__q_thd_td, d_passes__q_thd_td, _) = _c3
    # derivatives with respect to k
    _c4 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol, 0.0, 0.0, 0.0, 0.0, 1.0)
    if _c4[24] != STATUS_OK:
        return _NAN72 + (_c4[24],)
    (_, _, _, _, _, _, _, _, _, _, _, _, d_t_bottom__k, d_t_stance__k, d_bottom_q_r__k, d_bottom_q_rd__k, d_bottom_q_th__k, d_bottom_q_thd__k, d_liftoff_q_r__k, d_liftoff_q_rd__k, d_liftoff_q_th__k, d_liftoff_q_thd__k, d_P_c__k, d_passes__k, _) = _c4
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r) and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(P_c) and math.isfinite(passes) and math.isfinite(d_t_bottom__q_r_td) and math.isfinite(d_t_bottom__q_rd_td) and math.isfinite(d_t_bottom__q_th_td) and math.isfinite(d_t_bottom__q_thd_td) and math.isfinite(d_t_bottom__k) and math.isfinite(d_t_stance__q_r_td) and math.isfinite(d_t_stance__q_rd_td) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__q_thd_td) and math.isfinite(d_t_stance__k) and math.isfinite(d_bottom_q_r__q_r_td) and math.isfinite(d_bottom_q_r__q_rd_td) and math.isfinite(d_bottom_q_r__q_th_td) and math.isfinite(d_bottom_q_r__q_thd_td) and math.isfinite(d_bottom_q_r__k) and math.isfinite(d_bottom_q_rd__q_r_td) and math.isfinite(d_bottom_q_rd__q_rd_td) and math.isfinite(d_bottom_q_rd__q_th_td) and math.isfinite(d_bottom_q_rd__q_thd_td) and math.isfinite(d_bottom_q_rd__k) and math.isfinite(d_bottom_q_th__q_r_td) and math.isfinite(d_bottom_q_th__q_rd_td) and math.isfinite(d_bottom_q_th__q_th_td) and math.isfinite(d_bottom_q_th__q_thd_td) and math.isfinite(d_bottom_q_th__k) and math.isfinite(d_bottom_q_thd__q_r_td) and math.isfinite(d_bottom_q_thd__q_rd_td) and math.isfinite(d_bottom_q_thd__q_th_td) and math.isfinite(d_bottom_q_thd__q_thd_td) and math.isfinite(d_bottom_q_thd__k) and math.isfinite(d_liftoff_q_r__q_r_td) and math.isfinite(d_liftoff_q_r__q_rd_td) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__q_thd_td) and math.isfinite(d_liftoff_q_r__k) and math.isfinite(d_liftoff_q_rd__q_r_td) and math.isfinite(d_liftoff_q_rd__q_rd_td) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__q_thd_td) and math.isfinite(d_liftoff_q_rd__k) and math.isfinite(d_liftoff_q_th__q_r_td) and math.isfinite(d_liftoff_q_th__q_rd_td) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__q_thd_td) and math.isfinite(d_liftoff_q_th__k) and math.isfinite(d_liftoff_q_thd__q_r_td) and math.isfinite(d_liftoff_q_thd__q_rd_td) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__q_thd_td) and math.isfinite(d_liftoff_q_thd__k) and math.isfinite(d_P_c__q_r_td) and math.isfinite(d_P_c__q_rd_td) and math.isfinite(d_P_c__q_th_td) and math.isfinite(d_P_c__q_thd_td) and math.isfinite(d_P_c__k) and math.isfinite(d_passes__q_r_td) and math.isfinite(d_passes__q_rd_td) and math.isfinite(d_passes__q_th_td) and math.isfinite(d_passes__q_thd_td) and math.isfinite(d_passes__k)):
        return _NAN72 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k, d_P_c__q_r_td, d_P_c__q_rd_td, d_P_c__q_th_td, d_P_c__q_thd_td, d_P_c__k, d_passes__q_r_td, d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def gravity_type4_stance_jacobian_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol, out, status):
    """Parallel batch form of :func:`gravity_type4_stance_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 72)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k, d_P_c__q_r_td, d_P_c__q_rd_td, d_P_c__q_th_td, d_P_c__q_thd_td, d_P_c__k, d_passes__q_r_td, d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k.
    """
    for i in prange(out.shape[0]):
        res = gravity_type4_stance_jacobian(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol)
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
        status[i] = res[72]


@njit(cache=True, error_model="numpy")
def gravity_type4_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, k__tan):
    """Apex-return map: exact flights, stance by Gravity correction type 4 (average leg length on [t_i, t_f]), with the derivative of every output along the direction (b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, k__tan).

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground [m], >= 0
        b_xd_apex: horizontal apex speed [m/s], >= 0 (the runner moves in +x)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        g_f: gravitational acceleration in flight g_f [m/s^2], positive
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        reading: option reading: how P_c enters Geyer's formulas, eq (50): 0 = mean, 1 = report
        interval: option interval: the intervals [t_i, t_f] of the correction: 0 = stance, 1 = halves
        leg_length: option leg_length: the stance solution the average leg length is taken from: 0 = eq11, 1 = eq21, 2 = eq23
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0, 1]
        b_y_apex__tan: direction: its component along b_y_apex
        b_xd_apex__tan: direction: its component along b_xd_apex
        q_th_td__tan: direction: its component along q_th_td
        k__tan: direction: its component along k

    Returns a tuple:
        apex_height: next apex height above the ground [m]
        apex_speed: next apex horizontal speed [m/s]
        t_descent: flight time from the apex to touchdown [s]
        t_stance: stance time, touchdown to liftoff [s]
        t_ascent: flight time from liftoff to the next apex [s]
        liftoff_q_r: leg length [m]
        liftoff_q_rd: leg length rate [m/s]
        liftoff_q_th: leg angle from the vertical, counterclockwise positive [rad]
        liftoff_q_thd: leg angle rate [rad/s]
        P_c: virtual gravity effect: the stance impulse added to p_th [N m s]
        passes: fixed-point passes run
        apex_height__tan: derivative of apex_height along the direction
        apex_speed__tan: derivative of apex_speed along the direction
        t_descent__tan: derivative of t_descent along the direction
        t_stance__tan: derivative of t_stance along the direction
        t_ascent__tan: derivative of t_ascent along the direction
        liftoff_q_r__tan: derivative of liftoff_q_r along the direction
        liftoff_q_rd__tan: derivative of liftoff_q_rd along the direction
        liftoff_q_th__tan: derivative of liftoff_q_th along the direction
        liftoff_q_thd__tan: derivative of liftoff_q_thd along the direction
        P_c__tan: derivative of P_c along the direction
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(reading) and math.isfinite(interval) and math.isfinite(leg_length) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(b_y_apex__tan) and math.isfinite(b_xd_apex__tan) and math.isfinite(q_th_td__tan) and math.isfinite(k__tan) and ((b_y_apex >= 0.0)) and ((b_xd_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((reading == 0.0) or (reading == 1.0)) and ((interval == 0.0) or (interval == 1.0)) and ((leg_length == 0.0) or (leg_length == 1.0) or (leg_length == 2.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN22 + (STATUS_INVALID_INPUT,)
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan)
    if _c0[10] != STATUS_OK:
        return _NAN22 + (_c0[10],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, t_descent__tan, _) = _c0
    # stance: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c1 = gravity_type4_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, k__tan)
    if _c1[24] != STATUS_OK:
        return _NAN22 + (_c1[24],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, _, t_stance__tan, _, _, _, _, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, P_c__tan, passes__tan, _) = _c1
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan)
    if _c2[8] != STATUS_OK:
        return _NAN22 + (_c2[8],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    apex_height__tan = _c2[4]
    apex_speed__tan = _c2[5]
    t_ascent__tan = _c2[6]
    # (internal helper: its callers check that their outputs are finite)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, apex_height__tan, apex_speed__tan, t_descent__tan, t_stance__tan, t_ascent__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, P_c__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_apex_return_jacobian(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol):
    """Apex-return map by Gravity correction type 4 (average leg length on [t_i, t_f]), and its derivatives with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground [m], >= 0
        b_xd_apex: horizontal apex speed [m/s], >= 0 (the runner moves in +x)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        g_f: gravitational acceleration in flight g_f [m/s^2], positive
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        reading: option reading: how P_c enters Geyer's formulas, eq (50): 0 = mean, 1 = report
        interval: option interval: the intervals [t_i, t_f] of the correction: 0 = stance, 1 = halves
        leg_length: option leg_length: the stance solution the average leg length is taken from: 0 = eq11, 1 = eq21, 2 = eq23
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0, 1]

    Returns a tuple:
        apex_height: next apex height above the ground [m]
        apex_speed: next apex horizontal speed [m/s]
        t_descent: flight time from the apex to touchdown [s]
        t_stance: stance time, touchdown to liftoff [s]
        t_ascent: flight time from liftoff to the next apex [s]
        liftoff_q_r: leg length [m]
        liftoff_q_rd: leg length rate [m/s]
        liftoff_q_th: leg angle from the vertical, counterclockwise positive [rad]
        liftoff_q_thd: leg angle rate [rad/s]
        P_c: virtual gravity effect: the stance impulse added to p_th [N m s]
        passes: fixed-point passes run
        d_apex_height__b_y_apex: d apex_height / d b_y_apex
        d_apex_height__b_xd_apex: d apex_height / d b_xd_apex
        d_apex_height__q_th_td: d apex_height / d q_th_td
        d_apex_height__k: d apex_height / d k
        d_apex_speed__b_y_apex: d apex_speed / d b_y_apex
        d_apex_speed__b_xd_apex: d apex_speed / d b_xd_apex
        d_apex_speed__q_th_td: d apex_speed / d q_th_td
        d_apex_speed__k: d apex_speed / d k
        d_t_descent__b_y_apex: d t_descent / d b_y_apex
        d_t_descent__b_xd_apex: d t_descent / d b_xd_apex
        d_t_descent__q_th_td: d t_descent / d q_th_td
        d_t_descent__k: d t_descent / d k
        d_t_stance__b_y_apex: d t_stance / d b_y_apex
        d_t_stance__b_xd_apex: d t_stance / d b_xd_apex
        d_t_stance__q_th_td: d t_stance / d q_th_td
        d_t_stance__k: d t_stance / d k
        d_t_ascent__b_y_apex: d t_ascent / d b_y_apex
        d_t_ascent__b_xd_apex: d t_ascent / d b_xd_apex
        d_t_ascent__q_th_td: d t_ascent / d q_th_td
        d_t_ascent__k: d t_ascent / d k
        d_liftoff_q_r__b_y_apex: d liftoff_q_r / d b_y_apex
        d_liftoff_q_r__b_xd_apex: d liftoff_q_r / d b_xd_apex
        d_liftoff_q_r__q_th_td: d liftoff_q_r / d q_th_td
        d_liftoff_q_r__k: d liftoff_q_r / d k
        d_liftoff_q_rd__b_y_apex: d liftoff_q_rd / d b_y_apex
        d_liftoff_q_rd__b_xd_apex: d liftoff_q_rd / d b_xd_apex
        d_liftoff_q_rd__q_th_td: d liftoff_q_rd / d q_th_td
        d_liftoff_q_rd__k: d liftoff_q_rd / d k
        d_liftoff_q_th__b_y_apex: d liftoff_q_th / d b_y_apex
        d_liftoff_q_th__b_xd_apex: d liftoff_q_th / d b_xd_apex
        d_liftoff_q_th__q_th_td: d liftoff_q_th / d q_th_td
        d_liftoff_q_th__k: d liftoff_q_th / d k
        d_liftoff_q_thd__b_y_apex: d liftoff_q_thd / d b_y_apex
        d_liftoff_q_thd__b_xd_apex: d liftoff_q_thd / d b_xd_apex
        d_liftoff_q_thd__q_th_td: d liftoff_q_thd / d q_th_td
        d_liftoff_q_thd__k: d liftoff_q_thd / d k
        d_P_c__b_y_apex: d P_c / d b_y_apex
        d_P_c__b_xd_apex: d P_c / d b_xd_apex
        d_P_c__q_th_td: d P_c / d q_th_td
        d_P_c__k: d P_c / d k
        d_passes__b_y_apex: d passes / d b_y_apex
        d_passes__b_xd_apex: d passes / d b_xd_apex
        d_passes__q_th_td: d passes / d q_th_td
        d_passes__k: d passes / d k
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(reading) and math.isfinite(interval) and math.isfinite(leg_length) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex >= 0.0)) and ((b_xd_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((reading == 0.0) or (reading == 1.0)) and ((interval == 0.0) or (interval == 1.0)) and ((leg_length == 0.0) or (leg_length == 1.0) or (leg_length == 2.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN55 + (STATUS_INVALID_INPUT,)
    # derivatives with respect to b_y_apex
    _c0 = gravity_type4_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol, 1.0, 0.0, 0.0, 0.0)
    if _c0[22] != STATUS_OK:
        return _NAN55 + (_c0[22],)
    (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_apex_height__b_y_apex, d_apex_speed__b_y_apex, d_t_descent__b_y_apex, d_t_stance__b_y_apex, d_t_ascent__b_y_apex, d_liftoff_q_r__b_y_apex, d_liftoff_q_rd__b_y_apex, d_liftoff_q_th__b_y_apex, d_liftoff_q_thd__b_y_apex, d_P_c__b_y_apex, d_passes__b_y_apex, _) = _c0
    # derivatives with respect to b_xd_apex
    _c1 = gravity_type4_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol, 0.0, 1.0, 0.0, 0.0)
    if _c1[22] != STATUS_OK:
        return _NAN55 + (_c1[22],)
    (_, _, _, _, _, _, _, _, _, _, _, d_apex_height__b_xd_apex, d_apex_speed__b_xd_apex, d_t_descent__b_xd_apex, d_t_stance__b_xd_apex, d_t_ascent__b_xd_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_thd__b_xd_apex, d_P_c__b_xd_apex, d_passes__b_xd_apex, _) = _c1
    # derivatives with respect to q_th_td
    _c2 = gravity_type4_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol, 0.0, 0.0, 1.0, 0.0)
    if _c2[22] != STATUS_OK:
        return _NAN55 + (_c2[22],)
    (_, _, _, _, _, _, _, _, _, _, _, d_apex_height__q_th_td, d_apex_speed__q_th_td, d_t_descent__q_th_td, d_t_stance__q_th_td, d_t_ascent__q_th_td, d_liftoff_q_r__q_th_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_th__q_th_td, d_liftoff_q_thd__q_th_td, d_P_c__q_th_td, d_passes__q_th_td, _) = _c2
    # derivatives with respect to k
    _c3 = gravity_type4_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol, 0.0, 0.0, 0.0, 1.0)
    if _c3[22] != STATUS_OK:
        return _NAN55 + (_c3[22],)
    (_, _, _, _, _, _, _, _, _, _, _, d_apex_height__k, d_apex_speed__k, d_t_descent__k, d_t_stance__k, d_t_ascent__k, d_liftoff_q_r__k, d_liftoff_q_rd__k, d_liftoff_q_th__k, d_liftoff_q_thd__k, d_P_c__k, d_passes__k, _) = _c3
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent) and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(P_c) and math.isfinite(passes) and math.isfinite(d_apex_height__b_y_apex) and math.isfinite(d_apex_height__b_xd_apex) and math.isfinite(d_apex_height__q_th_td) and math.isfinite(d_apex_height__k) and math.isfinite(d_apex_speed__b_y_apex) and math.isfinite(d_apex_speed__b_xd_apex) and math.isfinite(d_apex_speed__q_th_td) and math.isfinite(d_apex_speed__k) and math.isfinite(d_t_descent__b_y_apex) and math.isfinite(d_t_descent__b_xd_apex) and math.isfinite(d_t_descent__q_th_td) and math.isfinite(d_t_descent__k) and math.isfinite(d_t_stance__b_y_apex) and math.isfinite(d_t_stance__b_xd_apex) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__k) and math.isfinite(d_t_ascent__b_y_apex) and math.isfinite(d_t_ascent__b_xd_apex) and math.isfinite(d_t_ascent__q_th_td) and math.isfinite(d_t_ascent__k) and math.isfinite(d_liftoff_q_r__b_y_apex) and math.isfinite(d_liftoff_q_r__b_xd_apex) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__k) and math.isfinite(d_liftoff_q_rd__b_y_apex) and math.isfinite(d_liftoff_q_rd__b_xd_apex) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__k) and math.isfinite(d_liftoff_q_th__b_y_apex) and math.isfinite(d_liftoff_q_th__b_xd_apex) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__k) and math.isfinite(d_liftoff_q_thd__b_y_apex) and math.isfinite(d_liftoff_q_thd__b_xd_apex) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__k) and math.isfinite(d_P_c__b_y_apex) and math.isfinite(d_P_c__b_xd_apex) and math.isfinite(d_P_c__q_th_td) and math.isfinite(d_P_c__k) and math.isfinite(d_passes__b_y_apex) and math.isfinite(d_passes__b_xd_apex) and math.isfinite(d_passes__q_th_td) and math.isfinite(d_passes__k)):
        return _NAN55 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__k, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__k, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__k, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__k, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__k, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__k, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__k, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__k, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__k, d_P_c__b_y_apex, d_P_c__b_xd_apex, d_P_c__q_th_td, d_P_c__k, d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__k, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def gravity_type4_apex_return_jacobian_batch(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol, out, status):
    """Parallel batch form of :func:`gravity_type4_apex_return_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td.
    Scalar arguments shared by every row: m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 55)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__k, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__k, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__k, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__k, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__k, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__k, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__k, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__k, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__k, d_P_c__b_y_apex, d_P_c__b_xd_apex, d_P_c__q_th_td, d_P_c__k, d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__k.
    """
    for i in prange(out.shape[0]):
        res = gravity_type4_apex_return_jacobian(b_y_apex[i], b_xd_apex[i], q_th_td[i], m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol)
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
        status[i] = res[55]
