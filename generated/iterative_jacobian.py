# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
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
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module iterative: JVP kernels, and for a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td_ground, liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd
from .geyer_jacobian import geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k
from .geyer_vs_jacobian import geyer_vs_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d
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
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_0(_D, _D__tan, _P0, _P0__tan, _Q0, _Q0__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_P0: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_P0__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 202
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.75*_D - q_r
    _x1 = -_x0
    _x34 = (1.0/_x1)
    _x2 = -0.75*_D__tan + q_r__tan
    _x3 = k_c*l0
    _x4 = math.cos(_Q0)
    _x5 = g_s*m
    _x6 = _x4*_x5
    _x7 = _x1*k_c
    _x8 = _x34**3
    _x9 = (1.0/m)
    _x10 = _P0**2*_x9
    _x11 = _x10*_x8
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x5
    _x14 = k_c__tan*(_x0 + l0)
    _x15 = 2.0*_P0*_x8
    _x16 = _P0__tan*_x9
    _x17 = _x2*(-3.0*_x10*_x34**4 - k_c)
    _x18 = 0.5*_x11 + 0.5*_x3 - 0.5*_x6 - 0.5*_x7
    _x19 = 1.0*_P0*_x16*_x8 + 0.5*_x13 + 0.5*_x14 + 0.5*_x17
    _x20 = math.sqrt(_D)
    _x21 = math.sqrt(m)
    _x22 = (1.0/math.sqrt(_x18))
    _x23 = (1.0/_x20)
    _x24 = (0.5)*_x19*_x20/_x18**(1.5)
    _x25 = (1.0/_x21)
    _x26 = _x20*_x22
    _x27 = _x25*_x26
    _x28 = _x34**2
    _x29 = _P0*_x28
    _x30 = m**(1.5)
    _x31 = _x12*_x26*_x30*g_s
    _x32 = _x1*_x30*g_s
    _x33 = _x12*_x32
    _isigma0 = _x1
    _isigma0__tan = _x2
    _iF0 = _x11 + _x3 - _x6 - _x7
    _iF0__tan = _x13 + _x14 + _x15*_x16 + _x17
    _iPsi0 = _x18
    _iPsi0__tan = _x19
    _ift0 = _x20*_x21*_x22
    _ift0__tan = (0.5)*_D__tan*_x21*_x22*_x23 - _x21*_x24
    _ifq0 = _x27*_x29
    _ifq0__tan = (0.5)*_D__tan*_P0*_x22*_x23*_x25*_x28 + _P0__tan*_x20*_x22*_x25*_x28 - _x15*_x2*_x27 - _x24*_x25*_x29
    _ifp0 = _x1*_x31
    _ifp0__tan = (0.5)*_D__tan*_x22*_x23*_x33 + _Q0__tan*_x26*_x32*_x4 + _x2*_x31 - _x24*_x33
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x35 = m*q_rd**2
    _x36 = -q_r
    _x37 = k_c*(_x36 + l0)
    _x38 = 1.0*k_c
    _x39 = 1.0*_iF0 - _x38*(-_isigma0 + l0)
    _x40 = _x37 + _x39
    _x41 = math.sqrt(_x35*k_c + _x40**2)
    _x42 = _x40 + _x41
    _x43 = (1.0/_x42)
    _x44 = m*q_r**2
    _x45 = (1.0/_x41)
    _x46 = _x43**2
    _x47 = _x35*_x46
    _x48 = _x40*_x45
    _x49 = 2.0*q_r
    _next_D = _x35*_x43
    _next_Q0 = 0.5*_ifq0 + q_th
    _next_P0 = 0.5*_ifp0 + _x44*q_thd
    _next_D__tan = _iF0__tan*_x47*(-_x45*(1.0*_x37 + _x39) - 1.0) + _isigma0__tan*_x47*(-_x38*_x48 - _x38) + _x47*k_c__tan*(-1.0*_isigma0 - _x36 - _x45*((0.5)*_x35 + (0.5)*_x40*(2.0*_isigma0 - _x49))) + _x47*q_r__tan*(_x48*k_c + k_c) + q_rd__tan*(2.0*_x43*m*q_rd - _x45*_x46*k_c*m**2*q_rd**3)
    _next_Q0__tan = 0.5*_ifq0__tan + q_th__tan
    _next_P0__tan = 0.5*_ifp0__tan + _x44*q_thd__tan + _x49*m*q_r__tan*q_thd
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_P0, _next_D__tan, _next_Q0__tan, _next_P0__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_1(_D, _D__tan, _P0, _P0__tan, _Q0, _Q0__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 152
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.75*_D - q_r
    _x1 = -_x0
    _x34 = (1.0/_x1)
    _x2 = -0.75*_D__tan + q_r__tan
    _x3 = k_c*l0
    _x4 = math.cos(_Q0)
    _x5 = g_s*m
    _x6 = _x4*_x5
    _x7 = _x1*k_c
    _x8 = _x34**3
    _x9 = (1.0/m)
    _x10 = _P0**2*_x9
    _x11 = _x10*_x8
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x5
    _x14 = k_c__tan*(_x0 + l0)
    _x15 = 2.0*_P0*_x8
    _x16 = _P0__tan*_x9
    _x17 = _x2*(-3.0*_x10*_x34**4 - k_c)
    _x18 = 0.5*_x11 + 0.5*_x3 - 0.5*_x6 - 0.5*_x7
    _x19 = 1.0*_P0*_x16*_x8 + 0.5*_x13 + 0.5*_x14 + 0.5*_x17
    _x20 = math.sqrt(_D)
    _x21 = math.sqrt(m)
    _x22 = (1.0/math.sqrt(_x18))
    _x23 = (1.0/_x20)
    _x24 = (0.5)*_x19*_x20/_x18**(1.5)
    _x25 = (1.0/_x21)
    _x26 = _x20*_x22
    _x27 = _x25*_x26
    _x28 = _x34**2
    _x29 = _P0*_x28
    _x30 = m**(1.5)
    _x31 = _x12*_x26*_x30*g_s
    _x32 = _x1*_x30*g_s
    _x33 = _x12*_x32
    _fsigma0 = _x1
    _fsigma0__tan = _x2
    _fF0 = _x11 + _x3 - _x6 - _x7
    _fF0__tan = _x13 + _x14 + _x15*_x16 + _x17
    _fPsi0 = _x18
    _fPsi0__tan = _x19
    _fft0 = _x20*_x21*_x22
    _fft0__tan = (0.5)*_D__tan*_x21*_x22*_x23 - _x21*_x24
    _ffq0 = _x27*_x29
    _ffq0__tan = (0.5)*_D__tan*_P0*_x22*_x23*_x25*_x28 + _P0__tan*_x20*_x22*_x25*_x28 - _x15*_x2*_x27 - _x24*_x25*_x29
    _ffp0 = _x1*_x31
    _ffp0__tan = (0.5)*_D__tan*_x22*_x23*_x33 + _Q0__tan*_x26*_x32*_x4 + _x2*_x31 - _x24*_x33
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # bottom state
    _x35 = -_D + q_r
    _x42 = (1.0/_x35)
    _x36 = -_D__tan + q_r__tan
    _x37 = q_r**2
    _x38 = 1.0*_ffp0 + _x37*m*q_thd
    _x39 = (1.0/m)
    _x40 = _x42**2
    _x41 = _x39*_x40
    t_half = 1.0*_fft0
    t_half__tan = 1.0*_fft0__tan
    end_q_th = 1.0*_ffq0 + q_th
    end_q_th__tan = 1.0*_ffq0__tan + q_th__tan
    end_q_r = _x35
    end_q_r__tan = _x36
    end_q_rd = 0.0
    end_q_thd = _x38*_x41
    end_q_thd__tan = 1.0*_ffp0__tan*_x41 - 2.0*_x36*_x38*_x39*_x42**3 + _x37*_x40*q_thd__tan + 2.0*_x40*q_r*q_r__tan*q_thd
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_2(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 0 of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_r: value of the caller's variable
        guess_q_r__tan: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 1 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.5*guess_q_th + 0.5*q_th
    _P0 = 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd
    _D__tan = -guess_q_r__tan + q_r__tan
    _Q0__tan = 0.5*guess_q_th__tan + 0.5*q_th__tan
    _P0__tan = 0.5*guess_q_r**2*guess_q_thd__tan*m + 1.0*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.5*m*q_r**2*q_thd__tan + 1.0*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_0(_D, _D__tan, _P0, _P0__tan, _Q0, _Q0__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[6] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[6])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_P0 = _c0[2]
        _next_D__tan = _c0[3]
        _next_Q0__tan = _c0[4]
        _next_P0__tan = _c0[5]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_P0
        _n0_3 = _next_D__tan
        _n0_4 = _next_Q0__tan
        _n0_5 = _next_P0__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _P0 = _n0_2
        _D__tan = _n0_3
        _Q0__tan = _n0_4
        _P0__tan = _n0_5
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_1(_D, _D__tan, _P0, _P0__tan, _Q0, _Q0__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[22])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    t_half = _c1[12]
    t_half__tan = _c1[13]
    end_q_th = _c1[14]
    end_q_th__tan = _c1[15]
    end_q_r = _c1[16]
    end_q_r__tan = _c1[17]
    end_q_rd = _c1[18]
    end_q_thd = _c1[19]
    end_q_thd__tan = _c1[20]
    passes = _c1[21]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_3(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_Q1: result for the caller
        _next_P0: result for the caller
        _next_P1: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_Q1__tan: result for the caller
        _next_P0__tan: result for the caller
        _next_P1__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 413
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = -q_r
    _x1 = 0.9553418012614795*_D + _x0
    _x2 = -_x1
    _x68 = (1.0/_x2)
    _x3 = -q_r__tan
    _x4 = -0.9553418012614795*_D__tan - _x3
    _x5 = k_c*l0
    _x6 = math.cos(_Q0)
    _x7 = g_s*m
    _x8 = _x6*_x7
    _x9 = _x2*k_c
    _x10 = _x68**3
    _x11 = _P0**2
    _x12 = (1.0/m)
    _x13 = _x11*_x12
    _x14 = _x10*_x13
    _x15 = math.sin(_Q0)
    _x16 = _Q0__tan*_x15*_x7
    _x17 = k_c__tan*(_x1 + l0)
    _x18 = 2.0*_x12
    _x19 = _P0*_x10
    _x20 = _P0__tan*_x19
    _x21 = _x4*(-3.0*_x13*_x68**4 - k_c)
    _x22 = 0.37799153207185376*_D + _x0
    _x23 = -_x22
    _x69 = (1.0/_x23)
    _x24 = -0.37799153207185376*_D__tan - _x3
    _x25 = math.cos(_Q1)
    _x26 = _x25*_x7
    _x27 = _x23*k_c
    _x28 = _x69**3
    _x29 = _P1**2
    _x30 = _x12*_x29
    _x31 = _x28*_x30
    _x32 = math.sin(_Q1)
    _x33 = _Q1__tan*_x32*_x7
    _x34 = k_c__tan*(_x22 + l0)
    _x35 = _P1*_x28
    _x36 = _P1__tan*_x35
    _x37 = _x24*(-3.0*_x30*_x69**4 - k_c)
    _x38 = 0.5610042339640731*_x14 + 0.06100423396407311*_x26 + 0.06100423396407311*_x27 - 0.06100423396407311*_x31 + 0.5*_x5 - 0.5610042339640731*_x8 - 0.5610042339640731*_x9
    _x39 = _x12*_x20
    _x40 = _x12*_x36
    _x41 = 0.5610042339640731*_x16 + 0.5610042339640731*_x17 + 0.5610042339640731*_x21 - 0.06100423396407311*_x33 - 0.06100423396407311*_x34 - 0.06100423396407311*_x37 + 1.1220084679281461*_x39 - 0.12200846792814622*_x40
    _x42 = (1.0/math.sqrt(_x38))
    _x43 = math.sqrt(_D)
    _x44 = math.sqrt(m)
    _x45 = _x43*_x44
    _x46 = (1.0/_x43)
    _x47 = (0.5)*_x45
    _x48 = _x41/_x38**(1.5)
    _x49 = _x68**2
    _x50 = (1.0/_x44)
    _x51 = _x43*_x50
    _x52 = _x42*_x51
    _x53 = (0.5)*_x51
    _x54 = g_s*m**(1.5)
    _x55 = _x43*_x54
    _x56 = _x15*_x42*_x55
    _x57 = _x2*_x42
    _x58 = (0.5)*_D__tan*_x46*_x54
    _x59 = (0.5)*_x55
    _x60 = 0.22767090063073978*_x10*_x11*_x12 + 0.27232909936926025*_x12*_x28*_x29 - 0.27232909936926025*_x26 - 0.27232909936926025*_x27 - 0.22767090063073978*_x8 - 0.22767090063073978*_x9 + 0.5*k_c*l0
    _x61 = 0.22767090063073978*_x16 + 0.22767090063073978*_x17 + 0.22767090063073978*_x21 + 0.27232909936926025*_x33 + 0.27232909936926025*_x34 + 0.27232909936926025*_x37 + 0.45534180126147955*_x39 + 0.5446581987385205*_x40
    _x62 = (1.0/math.sqrt(_x60))
    _x63 = _x61/_x60**(1.5)
    _x64 = _x69**2
    _x65 = _x51*_x62
    _x66 = _x32*_x55*_x62
    _x67 = _x23*_x62
    _isigma0 = _x2
    _isigma0__tan = _x4
    _iF0 = _x14 + _x5 - _x8 - _x9
    _iF0__tan = _x16 + _x17 + _x18*_x20 + _x21
    _isigma1 = _x23
    _isigma1__tan = _x24
    _iF1 = -_x26 - _x27 + _x31 + _x5
    _iF1__tan = _x18*_x36 + _x33 + _x34 + _x37
    _iPsi0 = _x38
    _iPsi0__tan = _x41
    _ift0 = _x42*_x45
    _ift0__tan = (0.5)*_D__tan*_x42*_x44*_x46 - _x47*_x48
    _ifq0 = _P0*_x49*_x52
    _ifq0__tan = (0.5)*_D__tan*_P0*_x42*_x46*_x49*_x50 - _P0*_x48*_x49*_x53 + _P0__tan*_x42*_x43*_x49*_x50 - 2.0*_x19*_x4*_x52
    _ifp0 = _x2*_x56
    _ifp0__tan = _Q0__tan*_x55*_x57*_x6 - _x15*_x2*_x48*_x59 + _x15*_x57*_x58 + _x4*_x56
    _iPsi1 = _x60
    _iPsi1__tan = _x61
    _ift1 = _x45*_x62
    _ift1__tan = (0.5)*_D__tan*_x44*_x46*_x62 - _x47*_x63
    _ifq1 = _P1*_x64*_x65
    _ifq1__tan = (0.5)*_D__tan*_P1*_x46*_x50*_x62*_x64 - _P1*_x53*_x63*_x64 + _P1__tan*_x43*_x50*_x62*_x64 - 2.0*_x24*_x35*_x65
    _ifp1 = _x23*_x66
    _ifp1__tan = _Q1__tan*_x25*_x55*_x67 - _x23*_x32*_x59*_x63 + _x24*_x66 + _x32*_x58*_x67
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x70 = m*q_rd**2
    _x71 = -q_r
    _x72 = k_c*(_x71 + l0)
    _x73 = -l0
    _x74 = -_isigma0 - _x73
    _x75 = 0.2113248654051871*k_c
    _x76 = -_isigma1 - _x73
    _x77 = 0.7886751345948129*k_c
    _x78 = 0.2113248654051871*_iF0 + 0.7886751345948129*_iF1 + _x72 - _x74*_x75 - _x76*_x77
    _x79 = math.sqrt(_x70*k_c + _x78**2)
    _x80 = _x78 + _x79
    _x81 = (1.0/_x80)
    _x82 = m*q_r**2
    _x83 = _x82*q_thd
    _x84 = _x74*k_c
    _x85 = _x76*k_c
    _x86 = (1.0/_x79)
    _x87 = _x81**2
    _x88 = _x70*_x87
    _x89 = _x78*_x86
    _x90 = 2.0*q_r
    _x91 = _x82*q_thd__tan + _x90*m*q_r__tan*q_thd
    _next_D = _x70*_x81
    _next_Q0 = 0.25*_ifq0 + 0.5386751345948129*_ifq1 + q_th
    _next_Q1 = -0.03867513459481288*_ifq0 + 0.25*_ifq1 + q_th
    _next_P0 = 0.25*_ifp0 + 0.5386751345948129*_ifp1 + _x83
    _next_P1 = -0.03867513459481288*_ifp0 + 0.25*_ifp1 + _x83
    _next_D__tan = _iF0__tan*_x88*(-_x86*(0.04465819873852045*_iF0 + 0.16666666666666666*_iF1 + 0.2113248654051871*_x72 - 0.04465819873852045*_x84 - 0.16666666666666666*_x85) - 0.2113248654051871) + _iF1__tan*_x88*(-_x86*(0.16666666666666666*_iF0 + 0.6220084679281462*_iF1 + 0.7886751345948129*_x72 - 0.16666666666666666*_x84 - 0.6220084679281462*_x85) - 0.7886751345948129) + _isigma0__tan*_x88*(-_x75*_x89 - _x75) + _isigma1__tan*_x88*(-_x77*_x89 - _x77) + _x88*k_c__tan*(-0.2113248654051871*_isigma0 - 0.7886751345948129*_isigma1 - _x71 - _x86*((0.5)*_x70 + (0.5)*_x78*(0.4226497308103742*_isigma0 + 1.5773502691896257*_isigma1 - _x90 - 8.470329472543003e-22*l0)) + 4.235164736271502e-22*l0) + _x88*q_r__tan*(_x89*k_c + k_c) + q_rd__tan*(2.0*_x81*m*q_rd - _x86*_x87*k_c*m**2*q_rd**3)
    _next_Q0__tan = 0.25*_ifq0__tan + 0.5386751345948129*_ifq1__tan + q_th__tan
    _next_Q1__tan = -0.03867513459481288*_ifq0__tan + 0.25*_ifq1__tan + q_th__tan
    _next_P0__tan = 0.25*_ifp0__tan + 0.5386751345948129*_ifp1__tan + _x91
    _next_P1__tan = -0.03867513459481288*_ifp0__tan + 0.25*_ifp1__tan + _x91
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_Q1, _next_P0, _next_P1, _next_D__tan, _next_Q0__tan, _next_Q1__tan, _next_P0__tan, _next_P1__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_4(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 305
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = -q_r
    _x1 = 0.9553418012614795*_D + _x0
    _x2 = -_x1
    _x68 = (1.0/_x2)
    _x3 = -q_r__tan
    _x4 = -0.9553418012614795*_D__tan - _x3
    _x5 = k_c*l0
    _x6 = math.cos(_Q0)
    _x7 = g_s*m
    _x8 = _x6*_x7
    _x9 = _x2*k_c
    _x10 = _x68**3
    _x11 = _P0**2
    _x12 = (1.0/m)
    _x13 = _x11*_x12
    _x14 = _x10*_x13
    _x15 = math.sin(_Q0)
    _x16 = _Q0__tan*_x15*_x7
    _x17 = k_c__tan*(_x1 + l0)
    _x18 = 2.0*_x12
    _x19 = _P0*_x10
    _x20 = _P0__tan*_x19
    _x21 = _x4*(-3.0*_x13*_x68**4 - k_c)
    _x22 = 0.37799153207185376*_D + _x0
    _x23 = -_x22
    _x69 = (1.0/_x23)
    _x24 = -0.37799153207185376*_D__tan - _x3
    _x25 = math.cos(_Q1)
    _x26 = _x25*_x7
    _x27 = _x23*k_c
    _x28 = _x69**3
    _x29 = _P1**2
    _x30 = _x12*_x29
    _x31 = _x28*_x30
    _x32 = math.sin(_Q1)
    _x33 = _Q1__tan*_x32*_x7
    _x34 = k_c__tan*(_x22 + l0)
    _x35 = _P1*_x28
    _x36 = _P1__tan*_x35
    _x37 = _x24*(-3.0*_x30*_x69**4 - k_c)
    _x38 = 0.5610042339640731*_x14 + 0.06100423396407311*_x26 + 0.06100423396407311*_x27 - 0.06100423396407311*_x31 + 0.5*_x5 - 0.5610042339640731*_x8 - 0.5610042339640731*_x9
    _x39 = _x12*_x20
    _x40 = _x12*_x36
    _x41 = 0.5610042339640731*_x16 + 0.5610042339640731*_x17 + 0.5610042339640731*_x21 - 0.06100423396407311*_x33 - 0.06100423396407311*_x34 - 0.06100423396407311*_x37 + 1.1220084679281461*_x39 - 0.12200846792814622*_x40
    _x42 = (1.0/math.sqrt(_x38))
    _x43 = math.sqrt(_D)
    _x44 = math.sqrt(m)
    _x45 = _x43*_x44
    _x46 = (1.0/_x43)
    _x47 = (0.5)*_x45
    _x48 = _x41/_x38**(1.5)
    _x49 = _x68**2
    _x50 = (1.0/_x44)
    _x51 = _x43*_x50
    _x52 = _x42*_x51
    _x53 = (0.5)*_x51
    _x54 = g_s*m**(1.5)
    _x55 = _x43*_x54
    _x56 = _x15*_x42*_x55
    _x57 = _x2*_x42
    _x58 = (0.5)*_D__tan*_x46*_x54
    _x59 = (0.5)*_x55
    _x60 = 0.22767090063073978*_x10*_x11*_x12 + 0.27232909936926025*_x12*_x28*_x29 - 0.27232909936926025*_x26 - 0.27232909936926025*_x27 - 0.22767090063073978*_x8 - 0.22767090063073978*_x9 + 0.5*k_c*l0
    _x61 = 0.22767090063073978*_x16 + 0.22767090063073978*_x17 + 0.22767090063073978*_x21 + 0.27232909936926025*_x33 + 0.27232909936926025*_x34 + 0.27232909936926025*_x37 + 0.45534180126147955*_x39 + 0.5446581987385205*_x40
    _x62 = (1.0/math.sqrt(_x60))
    _x63 = _x61/_x60**(1.5)
    _x64 = _x69**2
    _x65 = _x51*_x62
    _x66 = _x32*_x55*_x62
    _x67 = _x23*_x62
    _fsigma0 = _x2
    _fsigma0__tan = _x4
    _fF0 = _x14 + _x5 - _x8 - _x9
    _fF0__tan = _x16 + _x17 + _x18*_x20 + _x21
    _fsigma1 = _x23
    _fsigma1__tan = _x24
    _fF1 = -_x26 - _x27 + _x31 + _x5
    _fF1__tan = _x18*_x36 + _x33 + _x34 + _x37
    _fPsi0 = _x38
    _fPsi0__tan = _x41
    _fft0 = _x42*_x45
    _fft0__tan = (0.5)*_D__tan*_x42*_x44*_x46 - _x47*_x48
    _ffq0 = _P0*_x49*_x52
    _ffq0__tan = (0.5)*_D__tan*_P0*_x42*_x46*_x49*_x50 - _P0*_x48*_x49*_x53 + _P0__tan*_x42*_x43*_x49*_x50 - 2.0*_x19*_x4*_x52
    _ffp0 = _x2*_x56
    _ffp0__tan = _Q0__tan*_x55*_x57*_x6 - _x15*_x2*_x48*_x59 + _x15*_x57*_x58 + _x4*_x56
    _fPsi1 = _x60
    _fPsi1__tan = _x61
    _fft1 = _x45*_x62
    _fft1__tan = (0.5)*_D__tan*_x44*_x46*_x62 - _x47*_x63
    _ffq1 = _P1*_x64*_x65
    _ffq1__tan = (0.5)*_D__tan*_P1*_x46*_x50*_x62*_x64 - _P1*_x53*_x63*_x64 + _P1__tan*_x43*_x50*_x62*_x64 - 2.0*_x24*_x35*_x65
    _ffp1 = _x23*_x66
    _ffp1__tan = _Q1__tan*_x25*_x55*_x67 - _x23*_x32*_x59*_x63 + _x24*_x66 + _x32*_x58*_x67
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # bottom state
    _x70 = -_D + q_r
    _x78 = (1.0/_x70)
    _x71 = -_D__tan + q_r__tan
    _x72 = q_r**2
    _x73 = 0.5*_ffp0 + 0.5*_ffp1 + _x72*m*q_thd
    _x74 = (1.0/m)
    _x75 = _x78**2
    _x76 = _x74*_x75
    _x77 = 0.5*_x76
    t_half = 0.5*_fft0 + 0.5*_fft1
    t_half__tan = 0.5*_fft0__tan + 0.5*_fft1__tan
    end_q_th = 0.5*_ffq0 + 0.5*_ffq1 + q_th
    end_q_th__tan = 0.5*_ffq0__tan + 0.5*_ffq1__tan + q_th__tan
    end_q_r = _x70
    end_q_r__tan = _x71
    end_q_rd = 0.0
    end_q_thd = _x73*_x76
    end_q_thd__tan = _ffp0__tan*_x77 + _ffp1__tan*_x77 - 2.0*_x71*_x73*_x74*_x78**3 + _x72*_x75*q_thd__tan + 2.0*_x75*q_r*q_r__tan*q_thd
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_5(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 1 of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_r: value of the caller's variable
        guess_q_r__tan: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 2 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th
    _Q1 = 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th
    _P0 = 0.7886751345948129*guess_q_r**2*guess_q_thd*m + 0.2113248654051871*m*q_r**2*q_thd
    _P1 = 0.2113248654051871*guess_q_r**2*guess_q_thd*m + 0.7886751345948129*m*q_r**2*q_thd
    _D__tan = -guess_q_r__tan + q_r__tan
    _Q0__tan = 0.7886751345948129*guess_q_th__tan + 0.2113248654051871*q_th__tan
    _Q1__tan = 0.2113248654051871*guess_q_th__tan + 0.7886751345948129*q_th__tan
    _P0__tan = 0.7886751345948129*guess_q_r**2*guess_q_thd__tan*m + 1.5773502691896257*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.2113248654051871*m*q_r**2*q_thd__tan + 0.4226497308103742*m*q_r*q_r__tan*q_thd
    _P1__tan = 0.2113248654051871*guess_q_r**2*guess_q_thd__tan*m + 0.4226497308103742*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.7886751345948129*m*q_r**2*q_thd__tan + 1.5773502691896257*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_3(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[10])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_Q1 = _c0[2]
        _next_P0 = _c0[3]
        _next_P1 = _c0[4]
        _next_D__tan = _c0[5]
        _next_Q0__tan = _c0[6]
        _next_Q1__tan = _c0[7]
        _next_P0__tan = _c0[8]
        _next_P1__tan = _c0[9]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_Q1
        _n0_3 = _next_P0
        _n0_4 = _next_P1
        _n0_5 = _next_D__tan
        _n0_6 = _next_Q0__tan
        _n0_7 = _next_Q1__tan
        _n0_8 = _next_P0__tan
        _n0_9 = _next_P1__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_4 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _P0 = _n0_3
        _P1 = _n0_4
        _D__tan = _n0_5
        _Q0__tan = _n0_6
        _Q1__tan = _n0_7
        _P0__tan = _n0_8
        _P1__tan = _n0_9
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_4(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[22])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    t_half = _c1[12]
    t_half__tan = _c1[13]
    end_q_th = _c1[14]
    end_q_th__tan = _c1[15]
    end_q_r = _c1[16]
    end_q_r__tan = _c1[17]
    end_q_rd = _c1[18]
    end_q_thd = _c1[19]
    end_q_thd__tan = _c1[20]
    passes = _c1[21]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_6(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_Q1: result for the caller
        _next_Q2: result for the caller
        _next_P0: result for the caller
        _next_P1: result for the caller
        _next_P2: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_Q1__tan: result for the caller
        _next_Q2__tan: result for the caller
        _next_P0__tan: result for the caller
        _next_P1__tan: result for the caller
        _next_P2__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 654
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = -q_r
    _x1 = 0.9872983346207417*_D + _x0
    _x2 = -_x1
    _x93 = (1.0/_x2)
    _x3 = -q_r__tan
    _x4 = -0.9872983346207417*_D__tan - _x3
    _x5 = k_c*l0
    _x6 = math.cos(_Q0)
    _x7 = g_s*m
    _x8 = _x6*_x7
    _x9 = _x2*k_c
    _x10 = _x93**3
    _x11 = _P0**2
    _x12 = (1.0/m)
    _x13 = _x11*_x12
    _x14 = _x10*_x13
    _x15 = math.sin(_Q0)
    _x16 = _Q0__tan*_x15*_x7
    _x17 = k_c__tan*(_x1 + l0)
    _x18 = 2.0*_x12
    _x19 = _P0*_x10
    _x20 = _P0__tan*_x19
    _x21 = _x4*(-3.0*_x13*_x93**4 - k_c)
    _x22 = 0.75*_D + _x0
    _x23 = -_x22
    _x94 = (1.0/_x23)
    _x24 = -0.75*_D__tan - _x3
    _x25 = math.cos(_Q1)
    _x26 = _x25*_x7
    _x27 = _x23*k_c
    _x28 = _x94**3
    _x29 = _P1**2
    _x30 = _x12*_x29
    _x31 = _x28*_x30
    _x32 = math.sin(_Q1)
    _x33 = _Q1__tan*_x32*_x7
    _x34 = k_c__tan*(_x22 + l0)
    _x35 = _P1*_x28
    _x36 = _P1__tan*_x35
    _x37 = _x24*(-3.0*_x30*_x94**4 - k_c)
    _x38 = 0.2127016653792583*_D + _x0
    _x39 = -_x38
    _x95 = (1.0/_x39)
    _x40 = -0.2127016653792583*_D__tan - _x3
    _x41 = math.cos(_Q2)
    _x42 = _x41*_x7
    _x43 = _x39*k_c
    _x44 = _x95**3
    _x45 = _P2**2
    _x46 = _x12*_x45
    _x47 = _x44*_x46
    _x48 = math.sin(_Q2)
    _x49 = _Q2__tan*_x48*_x7
    _x50 = k_c__tan*(_x38 + l0)
    _x51 = _P2*_x44
    _x52 = _P2__tan*_x51
    _x53 = _x40*(-3.0*_x46*_x95**4 - k_c)
    _x54 = 0.5762768525670787*_x14 + 0.1040546303448565*_x26 + 0.1040546303448565*_x27 - 0.1040546303448565*_x31 - 0.027777777777777776*_x42 - 0.027777777777777776*_x43 + 0.027777777777777776*_x47 + 0.5*_x5 - 0.5762768525670787*_x8 - 0.5762768525670787*_x9
    _x55 = _x12*_x20
    _x56 = _x12*_x36
    _x57 = _x12*_x52
    _x58 = 0.5762768525670787*_x16 + 0.5762768525670787*_x17 + 0.5762768525670787*_x21 - 0.1040546303448565*_x33 - 0.1040546303448565*_x34 - 0.1040546303448565*_x37 + 0.027777777777777776*_x49 + 0.027777777777777776*_x50 + 0.027777777777777776*_x53 + 1.1525537051341574*_x55 - 0.208109260689713*_x56 + 0.05555555555555555*_x57
    _x59 = (1.0/math.sqrt(_x54))
    _x60 = math.sqrt(_D)
    _x61 = math.sqrt(m)
    _x62 = _x60*_x61
    _x63 = (1.0/_x60)
    _x64 = (0.5)*_x62
    _x65 = _x58/_x54**(1.5)
    _x66 = _x93**2
    _x67 = (1.0/_x61)
    _x68 = _x60*_x67
    _x69 = _x59*_x68
    _x70 = (0.5)*_x68
    _x71 = g_s*m**(1.5)
    _x72 = _x60*_x71
    _x73 = _x15*_x59*_x72
    _x74 = _x2*_x59
    _x75 = (0.5)*_D__tan*_x63*_x71
    _x76 = (0.5)*_x72
    _x77 = 0.17702731517242826*_x14 - 0.3611111111111111*_x26 - 0.3611111111111111*_x27 + 0.3611111111111111*_x31 + 0.038138426283539355*_x42 + 0.038138426283539355*_x43 - 0.038138426283539355*_x47 + 0.5*_x5 - 0.17702731517242826*_x8 - 0.17702731517242826*_x9
    _x78 = 0.17702731517242826*_x16 + 0.17702731517242826*_x17 + 0.17702731517242826*_x21 + 0.3611111111111111*_x33 + 0.3611111111111111*_x34 + 0.3611111111111111*_x37 - 0.038138426283539355*_x49 - 0.038138426283539355*_x50 - 0.038138426283539355*_x53 + 0.3540546303448565*_x55 + 0.7222222222222222*_x56 - 0.07627685256707871*_x57
    _x79 = (1.0/math.sqrt(_x77))
    _x80 = _x78/_x77**(1.5)
    _x81 = _x94**2
    _x82 = _x68*_x79
    _x83 = _x32*_x72*_x79
    _x84 = _x23*_x79
    _x85 = 0.027777777777777776*_x10*_x11*_x12 + 0.3262768525670787*_x12*_x28*_x29 + 0.14594536965514351*_x12*_x44*_x45 - 0.3262768525670787*_x26 - 0.3262768525670787*_x27 - 0.14594536965514351*_x42 - 0.14594536965514351*_x43 - 0.027777777777777776*_x8 - 0.027777777777777776*_x9 + 0.5*k_c*l0
    _x86 = 0.027777777777777776*_x16 + 0.027777777777777776*_x17 + 0.027777777777777776*_x21 + 0.3262768525670787*_x33 + 0.3262768525670787*_x34 + 0.3262768525670787*_x37 + 0.14594536965514351*_x49 + 0.14594536965514351*_x50 + 0.14594536965514351*_x53 + 0.05555555555555555*_x55 + 0.6525537051341574*_x56 + 0.29189073931028703*_x57
    _x87 = (1.0/math.sqrt(_x85))
    _x88 = _x86/_x85**(1.5)
    _x89 = _x95**2
    _x90 = _x68*_x87
    _x91 = _x48*_x72*_x87
    _x92 = _x39*_x87
    _isigma0 = _x2
    _isigma0__tan = _x4
    _iF0 = _x14 + _x5 - _x8 - _x9
    _iF0__tan = _x16 + _x17 + _x18*_x20 + _x21
    _isigma1 = _x23
    _isigma1__tan = _x24
    _iF1 = -_x26 - _x27 + _x31 + _x5
    _iF1__tan = _x18*_x36 + _x33 + _x34 + _x37
    _isigma2 = _x39
    _isigma2__tan = _x40
    _iF2 = -_x42 - _x43 + _x47 + _x5
    _iF2__tan = _x18*_x52 + _x49 + _x50 + _x53
    _iPsi0 = _x54
    _iPsi0__tan = _x58
    _ift0 = _x59*_x62
    _ift0__tan = (0.5)*_D__tan*_x59*_x61*_x63 - _x64*_x65
    _ifq0 = _P0*_x66*_x69
    _ifq0__tan = (0.5)*_D__tan*_P0*_x59*_x63*_x66*_x67 - _P0*_x65*_x66*_x70 + _P0__tan*_x59*_x60*_x66*_x67 - 2.0*_x19*_x4*_x69
    _ifp0 = _x2*_x73
    _ifp0__tan = _Q0__tan*_x6*_x72*_x74 - _x15*_x2*_x65*_x76 + _x15*_x74*_x75 + _x4*_x73
    _iPsi1 = _x77
    _iPsi1__tan = _x78
    _ift1 = _x62*_x79
    _ift1__tan = (0.5)*_D__tan*_x61*_x63*_x79 - _x64*_x80
    _ifq1 = _P1*_x81*_x82
    _ifq1__tan = (0.5)*_D__tan*_P1*_x63*_x67*_x79*_x81 - _P1*_x70*_x80*_x81 + _P1__tan*_x60*_x67*_x79*_x81 - 2.0*_x24*_x35*_x82
    _ifp1 = _x23*_x83
    _ifp1__tan = _Q1__tan*_x25*_x72*_x84 - _x23*_x32*_x76*_x80 + _x24*_x83 + _x32*_x75*_x84
    _iPsi2 = _x85
    _iPsi2__tan = _x86
    _ift2 = _x62*_x87
    _ift2__tan = (0.5)*_D__tan*_x61*_x63*_x87 - _x64*_x88
    _ifq2 = _P2*_x89*_x90
    _ifq2__tan = (0.5)*_D__tan*_P2*_x63*_x67*_x87*_x89 - _P2*_x70*_x88*_x89 + _P2__tan*_x60*_x67*_x87*_x89 - 2.0*_x40*_x51*_x90
    _ifp2 = _x39*_x91
    _ifp2__tan = _Q2__tan*_x41*_x72*_x92 - _x39*_x48*_x76*_x88 + _x40*_x91 + _x48*_x75*_x92
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x96 = m*q_rd**2
    _x97 = -q_r
    _x98 = k_c*(_x97 + l0)
    _x99 = -l0
    _x100 = -_isigma0 - _x99
    _x101 = 0.06261203632181017*k_c
    _x102 = -_isigma1 - _x99
    _x103 = 0.4444444444444444*k_c
    _x104 = -_isigma2 - _x99
    _x105 = 0.4929435192337454*k_c
    _x106 = 0.06261203632181017*_iF0 + 0.4444444444444444*_iF1 + 0.4929435192337454*_iF2 - _x100*_x101 - _x102*_x103 - _x104*_x105 + _x98
    _x107 = math.sqrt(_x106**2 + _x96*k_c)
    _x108 = _x106 + _x107
    _x109 = (1.0/_x108)
    _x110 = m*q_r**2
    _x111 = _x110*q_thd
    _x112 = _x100*k_c
    _x113 = _x102*k_c
    _x114 = _x104*k_c
    _x115 = (1.0/_x107)
    _x116 = _x109**2
    _x117 = _x116*_x96
    _x118 = _x106*_x115
    _x119 = 2.0*q_r
    _x120 = _x110*q_thd__tan + _x119*m*q_r__tan*q_thd
    _next_D = _x109*_x96
    _next_Q0 = 0.1388888888888889*_ifq0 + 0.48042111196938336*_ifq1 + 0.26798833376246944*_ifq2 + q_th
    _next_Q1 = -0.022485417203086815*_ifq0 + 0.2222222222222222*_ifq1 + 0.30026319498086457*_ifq2 + q_th
    _next_Q2 = 0.009789444015308325*_ifq0 - 0.0359766675249389*_ifq1 + 0.1388888888888889*_ifq2 + q_th
    _next_P0 = 0.1388888888888889*_ifp0 + 0.48042111196938336*_ifp1 + 0.26798833376246944*_ifp2 + _x111
    _next_P1 = -0.022485417203086815*_ifp0 + 0.2222222222222222*_ifp1 + 0.30026319498086457*_ifp2 + _x111
    _next_P2 = 0.009789444015308325*_ifp0 - 0.0359766675249389*_ifp1 + 0.1388888888888889*_ifp2 + _x111
    _next_D__tan = _iF0__tan*_x117*(-_x115*(0.0039202670923636765*_iF0 + 0.0278275716985823*_iF1 + 0.030864197530864196*_iF2 - 0.0039202670923636765*_x112 - 0.0278275716985823*_x113 - 0.030864197530864196*_x114 + 0.06261203632181017*_x98) - 0.06261203632181017) + _iF1__tan*_x117*(-_x115*(0.0278275716985823*_iF0 + 0.19753086419753085*_iF1 + 0.21908600854833127*_iF2 - 0.0278275716985823*_x112 - 0.19753086419753085*_x113 - 0.21908600854833127*_x114 + 0.4444444444444444*_x98) - 0.4444444444444444) + _iF2__tan*_x117*(-_x115*(0.030864197530864196*_iF0 + 0.21908600854833127*_iF1 + 0.24299331315454992*_iF2 - 0.030864197530864196*_x112 - 0.21908600854833127*_x113 - 0.24299331315454992*_x114 + 0.4929435192337454*_x98) - 0.4929435192337454) + _isigma0__tan*_x117*(-_x101*_x118 - _x101) + _isigma1__tan*_x117*(-_x103*_x118 - _x103) + _isigma2__tan*_x117*(-_x105*_x118 - _x105) + _x117*k_c__tan*(-0.06261203632181017*_isigma0 - 0.4444444444444444*_isigma1 - 0.4929435192337454*_isigma2 - _x115*((0.5)*_x106*(0.12522407264362034*_isigma0 + 0.8888888888888888*_isigma1 + 0.9858870384674908*_isigma2 - _x119) + (0.5)*_x96) - _x97) + _x117*q_r__tan*(_x118*k_c + k_c) + q_rd__tan*(2.0*_x109*m*q_rd - _x115*_x116*k_c*m**2*q_rd**3)
    _next_Q0__tan = 0.1388888888888889*_ifq0__tan + 0.48042111196938336*_ifq1__tan + 0.26798833376246944*_ifq2__tan + q_th__tan
    _next_Q1__tan = -0.022485417203086815*_ifq0__tan + 0.2222222222222222*_ifq1__tan + 0.30026319498086457*_ifq2__tan + q_th__tan
    _next_Q2__tan = 0.009789444015308325*_ifq0__tan - 0.0359766675249389*_ifq1__tan + 0.1388888888888889*_ifq2__tan + q_th__tan
    _next_P0__tan = 0.1388888888888889*_ifp0__tan + 0.48042111196938336*_ifp1__tan + 0.26798833376246944*_ifp2__tan + _x120
    _next_P1__tan = -0.022485417203086815*_ifp0__tan + 0.2222222222222222*_ifp1__tan + 0.30026319498086457*_ifp2__tan + _x120
    _next_P2__tan = 0.009789444015308325*_ifp0__tan - 0.0359766675249389*_ifp1__tan + 0.1388888888888889*_ifp2__tan + _x120
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_Q1, _next_Q2, _next_P0, _next_P1, _next_P2, _next_D__tan, _next_Q0__tan, _next_Q1__tan, _next_Q2__tan, _next_P0__tan, _next_P1__tan, _next_P2__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_7(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 477
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = -q_r
    _x1 = 0.9872983346207417*_D + _x0
    _x2 = -_x1
    _x93 = (1.0/_x2)
    _x3 = -q_r__tan
    _x4 = -0.9872983346207417*_D__tan - _x3
    _x5 = k_c*l0
    _x6 = math.cos(_Q0)
    _x7 = g_s*m
    _x8 = _x6*_x7
    _x9 = _x2*k_c
    _x10 = _x93**3
    _x11 = _P0**2
    _x12 = (1.0/m)
    _x13 = _x11*_x12
    _x14 = _x10*_x13
    _x15 = math.sin(_Q0)
    _x16 = _Q0__tan*_x15*_x7
    _x17 = k_c__tan*(_x1 + l0)
    _x18 = 2.0*_x12
    _x19 = _P0*_x10
    _x20 = _P0__tan*_x19
    _x21 = _x4*(-3.0*_x13*_x93**4 - k_c)
    _x22 = 0.75*_D + _x0
    _x23 = -_x22
    _x94 = (1.0/_x23)
    _x24 = -0.75*_D__tan - _x3
    _x25 = math.cos(_Q1)
    _x26 = _x25*_x7
    _x27 = _x23*k_c
    _x28 = _x94**3
    _x29 = _P1**2
    _x30 = _x12*_x29
    _x31 = _x28*_x30
    _x32 = math.sin(_Q1)
    _x33 = _Q1__tan*_x32*_x7
    _x34 = k_c__tan*(_x22 + l0)
    _x35 = _P1*_x28
    _x36 = _P1__tan*_x35
    _x37 = _x24*(-3.0*_x30*_x94**4 - k_c)
    _x38 = 0.2127016653792583*_D + _x0
    _x39 = -_x38
    _x95 = (1.0/_x39)
    _x40 = -0.2127016653792583*_D__tan - _x3
    _x41 = math.cos(_Q2)
    _x42 = _x41*_x7
    _x43 = _x39*k_c
    _x44 = _x95**3
    _x45 = _P2**2
    _x46 = _x12*_x45
    _x47 = _x44*_x46
    _x48 = math.sin(_Q2)
    _x49 = _Q2__tan*_x48*_x7
    _x50 = k_c__tan*(_x38 + l0)
    _x51 = _P2*_x44
    _x52 = _P2__tan*_x51
    _x53 = _x40*(-3.0*_x46*_x95**4 - k_c)
    _x54 = 0.5762768525670787*_x14 + 0.1040546303448565*_x26 + 0.1040546303448565*_x27 - 0.1040546303448565*_x31 - 0.027777777777777776*_x42 - 0.027777777777777776*_x43 + 0.027777777777777776*_x47 + 0.5*_x5 - 0.5762768525670787*_x8 - 0.5762768525670787*_x9
    _x55 = _x12*_x20
    _x56 = _x12*_x36
    _x57 = _x12*_x52
    _x58 = 0.5762768525670787*_x16 + 0.5762768525670787*_x17 + 0.5762768525670787*_x21 - 0.1040546303448565*_x33 - 0.1040546303448565*_x34 - 0.1040546303448565*_x37 + 0.027777777777777776*_x49 + 0.027777777777777776*_x50 + 0.027777777777777776*_x53 + 1.1525537051341574*_x55 - 0.208109260689713*_x56 + 0.05555555555555555*_x57
    _x59 = (1.0/math.sqrt(_x54))
    _x60 = math.sqrt(_D)
    _x61 = math.sqrt(m)
    _x62 = _x60*_x61
    _x63 = (1.0/_x60)
    _x64 = (0.5)*_x62
    _x65 = _x58/_x54**(1.5)
    _x66 = _x93**2
    _x67 = (1.0/_x61)
    _x68 = _x60*_x67
    _x69 = _x59*_x68
    _x70 = (0.5)*_x68
    _x71 = g_s*m**(1.5)
    _x72 = _x60*_x71
    _x73 = _x15*_x59*_x72
    _x74 = _x2*_x59
    _x75 = (0.5)*_D__tan*_x63*_x71
    _x76 = (0.5)*_x72
    _x77 = 0.17702731517242826*_x14 - 0.3611111111111111*_x26 - 0.3611111111111111*_x27 + 0.3611111111111111*_x31 + 0.038138426283539355*_x42 + 0.038138426283539355*_x43 - 0.038138426283539355*_x47 + 0.5*_x5 - 0.17702731517242826*_x8 - 0.17702731517242826*_x9
    _x78 = 0.17702731517242826*_x16 + 0.17702731517242826*_x17 + 0.17702731517242826*_x21 + 0.3611111111111111*_x33 + 0.3611111111111111*_x34 + 0.3611111111111111*_x37 - 0.038138426283539355*_x49 - 0.038138426283539355*_x50 - 0.038138426283539355*_x53 + 0.3540546303448565*_x55 + 0.7222222222222222*_x56 - 0.07627685256707871*_x57
    _x79 = (1.0/math.sqrt(_x77))
    _x80 = _x78/_x77**(1.5)
    _x81 = _x94**2
    _x82 = _x68*_x79
    _x83 = _x32*_x72*_x79
    _x84 = _x23*_x79
    _x85 = 0.027777777777777776*_x10*_x11*_x12 + 0.3262768525670787*_x12*_x28*_x29 + 0.14594536965514351*_x12*_x44*_x45 - 0.3262768525670787*_x26 - 0.3262768525670787*_x27 - 0.14594536965514351*_x42 - 0.14594536965514351*_x43 - 0.027777777777777776*_x8 - 0.027777777777777776*_x9 + 0.5*k_c*l0
    _x86 = 0.027777777777777776*_x16 + 0.027777777777777776*_x17 + 0.027777777777777776*_x21 + 0.3262768525670787*_x33 + 0.3262768525670787*_x34 + 0.3262768525670787*_x37 + 0.14594536965514351*_x49 + 0.14594536965514351*_x50 + 0.14594536965514351*_x53 + 0.05555555555555555*_x55 + 0.6525537051341574*_x56 + 0.29189073931028703*_x57
    _x87 = (1.0/math.sqrt(_x85))
    _x88 = _x86/_x85**(1.5)
    _x89 = _x95**2
    _x90 = _x68*_x87
    _x91 = _x48*_x72*_x87
    _x92 = _x39*_x87
    _fsigma0 = _x2
    _fsigma0__tan = _x4
    _fF0 = _x14 + _x5 - _x8 - _x9
    _fF0__tan = _x16 + _x17 + _x18*_x20 + _x21
    _fsigma1 = _x23
    _fsigma1__tan = _x24
    _fF1 = -_x26 - _x27 + _x31 + _x5
    _fF1__tan = _x18*_x36 + _x33 + _x34 + _x37
    _fsigma2 = _x39
    _fsigma2__tan = _x40
    _fF2 = -_x42 - _x43 + _x47 + _x5
    _fF2__tan = _x18*_x52 + _x49 + _x50 + _x53
    _fPsi0 = _x54
    _fPsi0__tan = _x58
    _fft0 = _x59*_x62
    _fft0__tan = (0.5)*_D__tan*_x59*_x61*_x63 - _x64*_x65
    _ffq0 = _P0*_x66*_x69
    _ffq0__tan = (0.5)*_D__tan*_P0*_x59*_x63*_x66*_x67 - _P0*_x65*_x66*_x70 + _P0__tan*_x59*_x60*_x66*_x67 - 2.0*_x19*_x4*_x69
    _ffp0 = _x2*_x73
    _ffp0__tan = _Q0__tan*_x6*_x72*_x74 - _x15*_x2*_x65*_x76 + _x15*_x74*_x75 + _x4*_x73
    _fPsi1 = _x77
    _fPsi1__tan = _x78
    _fft1 = _x62*_x79
    _fft1__tan = (0.5)*_D__tan*_x61*_x63*_x79 - _x64*_x80
    _ffq1 = _P1*_x81*_x82
    _ffq1__tan = (0.5)*_D__tan*_P1*_x63*_x67*_x79*_x81 - _P1*_x70*_x80*_x81 + _P1__tan*_x60*_x67*_x79*_x81 - 2.0*_x24*_x35*_x82
    _ffp1 = _x23*_x83
    _ffp1__tan = _Q1__tan*_x25*_x72*_x84 - _x23*_x32*_x76*_x80 + _x24*_x83 + _x32*_x75*_x84
    _fPsi2 = _x85
    _fPsi2__tan = _x86
    _fft2 = _x62*_x87
    _fft2__tan = (0.5)*_D__tan*_x61*_x63*_x87 - _x64*_x88
    _ffq2 = _P2*_x89*_x90
    _ffq2__tan = (0.5)*_D__tan*_P2*_x63*_x67*_x87*_x89 - _P2*_x70*_x88*_x89 + _P2__tan*_x60*_x67*_x87*_x89 - 2.0*_x40*_x51*_x90
    _ffp2 = _x39*_x91
    _ffp2__tan = _Q2__tan*_x41*_x72*_x92 - _x39*_x48*_x76*_x88 + _x40*_x91 + _x48*_x75*_x92
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # bottom state
    _x96 = -_D + q_r
    _x104 = (1.0/_x96)
    _x97 = -_D__tan + q_r__tan
    _x98 = q_r**2
    _x99 = 0.2777777777777778*_ffp0 + 0.4444444444444444*_ffp1 + 0.2777777777777778*_ffp2 + _x98*m*q_thd
    _x100 = (1.0/m)
    _x101 = _x104**2
    _x102 = _x100*_x101
    _x103 = 0.2777777777777778*_x102
    t_half = 0.2777777777777778*_fft0 + 0.4444444444444444*_fft1 + 0.2777777777777778*_fft2
    t_half__tan = 0.2777777777777778*_fft0__tan + 0.4444444444444444*_fft1__tan + 0.2777777777777778*_fft2__tan
    end_q_th = 0.2777777777777778*_ffq0 + 0.4444444444444444*_ffq1 + 0.2777777777777778*_ffq2 + q_th
    end_q_th__tan = 0.2777777777777778*_ffq0__tan + 0.4444444444444444*_ffq1__tan + 0.2777777777777778*_ffq2__tan + q_th__tan
    end_q_r = _x96
    end_q_r__tan = _x97
    end_q_rd = 0.0
    end_q_thd = _x102*_x99
    end_q_thd__tan = _ffp0__tan*_x103 + 0.4444444444444444*_ffp1__tan*_x102 + _ffp2__tan*_x103 - 2.0*_x100*_x104**3*_x97*_x99 + _x101*_x98*q_thd__tan + 2.0*_x101*q_r*q_r__tan*q_thd
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_8(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 2 of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_r: value of the caller's variable
        guess_q_r__tan: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 3 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th
    _Q1 = 0.5*guess_q_th + 0.5*q_th
    _Q2 = 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th
    _P0 = 0.8872983346207417*guess_q_r**2*guess_q_thd*m + 0.11270166537925831*m*q_r**2*q_thd
    _P1 = 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd
    _P2 = 0.11270166537925831*guess_q_r**2*guess_q_thd*m + 0.8872983346207417*m*q_r**2*q_thd
    _D__tan = -guess_q_r__tan + q_r__tan
    _Q0__tan = 0.8872983346207417*guess_q_th__tan + 0.11270166537925831*q_th__tan
    _Q1__tan = 0.5*guess_q_th__tan + 0.5*q_th__tan
    _Q2__tan = 0.11270166537925831*guess_q_th__tan + 0.8872983346207417*q_th__tan
    _P0__tan = 0.8872983346207417*guess_q_r**2*guess_q_thd__tan*m + 1.7745966692414834*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.11270166537925831*m*q_r**2*q_thd__tan + 0.22540333075851662*m*q_r*q_r__tan*q_thd
    _P1__tan = 0.5*guess_q_r**2*guess_q_thd__tan*m + 1.0*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.5*m*q_r**2*q_thd__tan + 1.0*m*q_r*q_r__tan*q_thd
    _P2__tan = 0.11270166537925831*guess_q_r**2*guess_q_thd__tan*m + 0.22540333075851662*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.8872983346207417*m*q_r**2*q_thd__tan + 1.7745966692414834*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_6(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[14] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[14])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_Q1 = _c0[2]
        _next_Q2 = _c0[3]
        _next_P0 = _c0[4]
        _next_P1 = _c0[5]
        _next_P2 = _c0[6]
        _next_D__tan = _c0[7]
        _next_Q0__tan = _c0[8]
        _next_Q1__tan = _c0[9]
        _next_Q2__tan = _c0[10]
        _next_P0__tan = _c0[11]
        _next_P1__tan = _c0[12]
        _next_P2__tan = _c0[13]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_Q1
        _n0_3 = _next_Q2
        _n0_4 = _next_P0
        _n0_5 = _next_P1
        _n0_6 = _next_P2
        _n0_7 = _next_D__tan
        _n0_8 = _next_Q0__tan
        _n0_9 = _next_Q1__tan
        _n0_10 = _next_Q2__tan
        _n0_11 = _next_P0__tan
        _n0_12 = _next_P1__tan
        _n0_13 = _next_P2__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_5 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _P0 = _n0_4
        _P1 = _n0_5
        _P2 = _n0_6
        _D__tan = _n0_7
        _Q0__tan = _n0_8
        _Q1__tan = _n0_9
        _Q2__tan = _n0_10
        _P0__tan = _n0_11
        _P1__tan = _n0_12
        _P2__tan = _n0_13
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_7(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[22])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    t_half = _c1[12]
    t_half__tan = _c1[13]
    end_q_th = _c1[14]
    end_q_th__tan = _c1[15]
    end_q_r = _c1[16]
    end_q_r__tan = _c1[17]
    end_q_rd = _c1[18]
    end_q_thd = _c1[19]
    end_q_thd__tan = _c1[20]
    passes = _c1[21]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_9(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _P3: value of the caller's variable
        _P3__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _Q3: value of the caller's variable
        _Q3__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_Q1: result for the caller
        _next_Q2: result for the caller
        _next_Q3: result for the caller
        _next_P0: result for the caller
        _next_P1: result for the caller
        _next_P2: result for the caller
        _next_P3: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_Q1__tan: result for the caller
        _next_Q2__tan: result for the caller
        _next_Q3__tan: result for the caller
        _next_P0__tan: result for the caller
        _next_P1__tan: result for the caller
        _next_P2__tan: result for the caller
        _next_P3__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 974
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = -q_r
    _x1 = 0.9951792190105739*_D + _x0
    _x2 = -_x1
    _x118 = (1.0/_x2)
    _x3 = -q_r__tan
    _x4 = -0.9951792190105739*_D__tan - _x3
    _x5 = k_c*l0
    _x6 = math.cos(_Q0)
    _x7 = g_s*m
    _x8 = _x6*_x7
    _x9 = _x2*k_c
    _x10 = _x118**3
    _x11 = _P0**2
    _x12 = (1.0/m)
    _x13 = _x11*_x12
    _x14 = _x10*_x13
    _x15 = math.sin(_Q0)
    _x16 = _Q0__tan*_x15*_x7
    _x17 = k_c__tan*(_x1 + l0)
    _x18 = 2.0*_x12
    _x19 = _P0*_x10
    _x20 = _P0__tan*_x19
    _x21 = _x4*(-3.0*_x118**4*_x13 - k_c)
    _x22 = 0.8910937442931661*_D + _x0
    _x23 = -_x22
    _x119 = (1.0/_x23)
    _x24 = -0.8910937442931661*_D__tan - _x3
    _x25 = math.cos(_Q1)
    _x26 = _x25*_x7
    _x27 = _x23*k_c
    _x28 = _x119**3
    _x29 = _P1**2
    _x30 = _x12*_x29
    _x31 = _x28*_x30
    _x32 = math.sin(_Q1)
    _x33 = _Q1__tan*_x32*_x7
    _x34 = k_c__tan*(_x22 + l0)
    _x35 = _P1*_x28
    _x36 = _P1__tan*_x35
    _x37 = _x24*(-3.0*_x119**4*_x30 - k_c)
    _x38 = 0.5511127007083099*_D + _x0
    _x39 = -_x38
    _x120 = (1.0/_x39)
    _x40 = -0.5511127007083099*_D__tan - _x3
    _x41 = math.cos(_Q2)
    _x42 = _x41*_x7
    _x43 = _x39*k_c
    _x44 = _x120**3
    _x45 = _P2**2
    _x46 = _x12*_x45
    _x47 = _x44*_x46
    _x48 = math.sin(_Q2)
    _x49 = _Q2__tan*_x48*_x7
    _x50 = k_c__tan*(_x38 + l0)
    _x51 = _P2*_x44
    _x52 = _P2__tan*_x51
    _x53 = _x40*(-3.0*_x120**4*_x46 - k_c)
    _x54 = 0.13404290741652142*_D + _x0
    _x55 = -_x54
    _x121 = (1.0/_x55)
    _x56 = -0.13404290741652142*_D__tan - _x3
    _x57 = math.cos(_Q3)
    _x58 = _x57*_x7
    _x59 = _x55*k_c
    _x60 = _x121**3
    _x61 = _P3**2
    _x62 = _x12*_x61
    _x63 = _x60*_x62
    _x64 = math.sin(_Q3)
    _x65 = _Q3__tan*_x64*_x7
    _x66 = k_c__tan*(_x54 + l0)
    _x67 = _P3*_x60
    _x68 = _P3__tan*_x67
    _x69 = _x56*(-3.0*_x121**4*_x62 - k_c)
    _x70 = 0.582374038291501*_x14 + 0.12383458041329967*_x26 + 0.12383458041329967*_x27 - 0.12383458041329967*_x31 - 0.0575898635297681*_x42 - 0.0575898635297681*_x43 + 0.0575898635297681*_x47 + 0.5*_x5 + 0.016129321407969507*_x58 + 0.016129321407969507*_x59 - 0.016129321407969507*_x63 - 0.582374038291501*_x8 - 0.582374038291501*_x9
    _x71 = _x12*_x20
    _x72 = _x12*_x36
    _x73 = _x12*_x52
    _x74 = _x12*_x68
    _x75 = 0.582374038291501*_x16 + 0.582374038291501*_x17 + 0.582374038291501*_x21 - 0.12383458041329967*_x33 - 0.12383458041329967*_x34 - 0.12383458041329967*_x37 + 0.0575898635297681*_x49 + 0.0575898635297681*_x50 + 0.0575898635297681*_x53 - 0.016129321407969507*_x65 - 0.016129321407969507*_x66 - 0.016129321407969507*_x69 + 1.164748076583002*_x71 - 0.24766916082659934*_x72 + 0.1151797270595362*_x73 - 0.032258642815939015*_x74
    _x76 = (1.0/math.sqrt(_x70))
    _x77 = math.sqrt(_D)
    _x78 = math.sqrt(m)
    _x79 = _x77*_x78
    _x80 = (1.0/_x77)
    _x81 = (0.5)*_x79
    _x82 = _x75/_x70**(1.5)
    _x83 = _x118**2
    _x84 = (1.0/_x78)
    _x85 = _x77*_x84
    _x86 = _x76*_x85
    _x87 = (0.5)*_x85
    _x88 = g_s*m**(1.5)
    _x89 = _x77*_x88
    _x90 = _x15*_x76*_x89
    _x91 = _x2*_x76
    _x92 = (0.5)*_D__tan*_x80*_x88
    _x93 = (0.5)*_x89
    _x94 = 0.16000937841634696*_x10*_x11*_x12 + 0.39252437029865583*_x12*_x28*_x29 + 0.017475652789475504*_x12*_x60*_x61 - 0.39252437029865583*_x26 - 0.39252437029865583*_x27 + 0.0700094015044783*_x39*k_c + 0.0700094015044783*_x41*g_s*m - 0.0700094015044783*_x47 - 0.017475652789475504*_x58 - 0.017475652789475504*_x59 - 0.16000937841634696*_x8 - 0.16000937841634696*_x9 + 0.5*k_c*l0
    _x95 = 0.16000937841634696*_x16 + 0.16000937841634696*_x17 + 0.16000937841634696*_x21 + 0.39252437029865583*_x33 + 0.39252437029865583*_x34 + 0.39252437029865583*_x37 - 0.0700094015044783*_x49 - 0.0700094015044783*_x50 - 0.0700094015044783*_x53 + 0.017475652789475504*_x65 + 0.017475652789475504*_x66 + 0.017475652789475504*_x69 + 0.32001875683269393*_x71 + 0.7850487405973117*_x72 - 0.1400188030089566*_x73 + 0.03495130557895101*_x74
    _x96 = (1.0/math.sqrt(_x94))
    _x97 = _x95/_x94**(1.5)
    _x98 = _x119**2
    _x99 = _x85*_x96
    _x100 = _x32*_x89*_x96
    _x101 = _x23*_x96
    _x102 = 0.01613725546399532*_x10*_x11*_x12 + 0.2848443432415939*_x12*_x28*_x29 + 0.21871326539550162*_x12*_x44*_x45 - 0.2848443432415939*_x26 - 0.2848443432415939*_x27 - 0.21871326539550162*_x42 - 0.21871326539550162*_x43 + 0.019694864101090868*_x55*k_c + 0.019694864101090868*_x57*g_s*m - 0.019694864101090868*_x63 - 0.01613725546399532*_x8 - 0.01613725546399532*_x9 + 0.5*k_c*l0
    _x103 = 0.01613725546399532*_x16 + 0.01613725546399532*_x17 + 0.01613725546399532*_x21 + 0.2848443432415939*_x33 + 0.2848443432415939*_x34 + 0.2848443432415939*_x37 + 0.21871326539550162*_x49 + 0.21871326539550162*_x50 + 0.21871326539550162*_x53 - 0.019694864101090868*_x65 - 0.019694864101090868*_x66 - 0.019694864101090868*_x69 + 0.03227451092799064*_x71 + 0.5696886864831878*_x72 + 0.43742653079100324*_x73 - 0.039389728202181735*_x74
    _x104 = (1.0/math.sqrt(_x102))
    _x105 = _x103/_x102**(1.5)
    _x106 = _x120**2
    _x107 = _x104*_x85
    _x108 = _x104*_x48*_x89
    _x109 = _x104*_x39
    _x110 = 0.01796104633752054*_x10*_x11*_x12 + 0.11000222456933441*_x12*_x28*_x29 + 0.2823150697454702*_x12*_x44*_x45 + 0.08972165934767481*_x12*_x60*_x61 - 0.11000222456933441*_x26 - 0.11000222456933441*_x27 - 0.2823150697454702*_x42 - 0.2823150697454702*_x43 - 0.08972165934767481*_x58 - 0.08972165934767481*_x59 - 0.01796104633752054*_x8 - 0.01796104633752054*_x9 + 0.5*k_c*l0
    _x111 = 0.01796104633752054*_x16 + 0.01796104633752054*_x17 + 0.01796104633752054*_x21 + 0.11000222456933441*_x33 + 0.11000222456933441*_x34 + 0.11000222456933441*_x37 + 0.2823150697454702*_x49 + 0.2823150697454702*_x50 + 0.2823150697454702*_x53 + 0.08972165934767481*_x65 + 0.08972165934767481*_x66 + 0.08972165934767481*_x69 + 0.03592209267504108*_x71 + 0.22000444913866882*_x72 + 0.5646301394909404*_x73 + 0.17944331869534963*_x74
    _x112 = (1.0/math.sqrt(_x110))
    _x113 = _x111/_x110**(1.5)
    _x114 = _x121**2
    _x115 = _x112*_x85
    _x116 = _x112*_x64*_x89
    _x117 = _x112*_x55
    _isigma0 = _x2
    _isigma0__tan = _x4
    _iF0 = _x14 + _x5 - _x8 - _x9
    _iF0__tan = _x16 + _x17 + _x18*_x20 + _x21
    _isigma1 = _x23
    _isigma1__tan = _x24
    _iF1 = -_x26 - _x27 + _x31 + _x5
    _iF1__tan = _x18*_x36 + _x33 + _x34 + _x37
    _isigma2 = _x39
    _isigma2__tan = _x40
    _iF2 = -_x42 - _x43 + _x47 + _x5
    _iF2__tan = _x18*_x52 + _x49 + _x50 + _x53
    _isigma3 = _x55
    _isigma3__tan = _x56
    _iF3 = _x5 - _x58 - _x59 + _x63
    _iF3__tan = _x18*_x68 + _x65 + _x66 + _x69
    _iPsi0 = _x70
    _iPsi0__tan = _x75
    _ift0 = _x76*_x79
    _ift0__tan = (0.5)*_D__tan*_x76*_x78*_x80 - _x81*_x82
    _ifq0 = _P0*_x83*_x86
    _ifq0__tan = (0.5)*_D__tan*_P0*_x76*_x80*_x83*_x84 - _P0*_x82*_x83*_x87 + _P0__tan*_x76*_x77*_x83*_x84 - 2.0*_x19*_x4*_x86
    _ifp0 = _x2*_x90
    _ifp0__tan = _Q0__tan*_x6*_x89*_x91 - _x15*_x2*_x82*_x93 + _x15*_x91*_x92 + _x4*_x90
    _iPsi1 = _x94
    _iPsi1__tan = _x95
    _ift1 = _x79*_x96
    _ift1__tan = (0.5)*_D__tan*_x78*_x80*_x96 - _x81*_x97
    _ifq1 = _P1*_x98*_x99
    _ifq1__tan = (0.5)*_D__tan*_P1*_x80*_x84*_x96*_x98 - _P1*_x87*_x97*_x98 + _P1__tan*_x77*_x84*_x96*_x98 - 2.0*_x24*_x35*_x99
    _ifp1 = _x100*_x23
    _ifp1__tan = _Q1__tan*_x101*_x25*_x89 + _x100*_x24 + _x101*_x32*_x92 - _x23*_x32*_x93*_x97
    _iPsi2 = _x102
    _iPsi2__tan = _x103
    _ift2 = _x104*_x79
    _ift2__tan = (0.5)*_D__tan*_x104*_x78*_x80 - _x105*_x81
    _ifq2 = _P2*_x106*_x107
    _ifq2__tan = (0.5)*_D__tan*_P2*_x104*_x106*_x80*_x84 - _P2*_x105*_x106*_x87 + _P2__tan*_x104*_x106*_x77*_x84 - 2.0*_x107*_x40*_x51
    _ifp2 = _x108*_x39
    _ifp2__tan = _Q2__tan*_x109*_x41*_x89 - _x105*_x39*_x48*_x93 + _x108*_x40 + _x109*_x48*_x92
    _iPsi3 = _x110
    _iPsi3__tan = _x111
    _ift3 = _x112*_x79
    _ift3__tan = (0.5)*_D__tan*_x112*_x78*_x80 - _x113*_x81
    _ifq3 = _P3*_x114*_x115
    _ifq3__tan = (0.5)*_D__tan*_P3*_x112*_x114*_x80*_x84 - _P3*_x113*_x114*_x87 + _P3__tan*_x112*_x114*_x77*_x84 - 2.0*_x115*_x56*_x67
    _ifp3 = _x116*_x55
    _ifp3__tan = _Q3__tan*_x117*_x57*_x89 - _x113*_x55*_x64*_x93 + _x116*_x56 + _x117*_x64*_x92
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi3 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x122 = m*q_rd**2
    _x123 = -q_r
    _x124 = k_c*(_x123 + l0)
    _x125 = -l0
    _x126 = -_isigma0 - _x125
    _x127 = 0.024152203412833244*k_c
    _x128 = -_isigma1 - _x125
    _x129 = 0.215214082271785*k_c
    _x130 = -_isigma2 - _x125
    _x131 = 0.43693107259076114*k_c
    _x132 = -_isigma3 - _x125
    _x133 = 0.3237026417246206*k_c
    _x134 = 0.024152203412833244*_iF0 + 0.215214082271785*_iF1 + 0.43693107259076114*_iF2 + 0.3237026417246206*_iF3 + _x124 - _x126*_x127 - _x128*_x129 - _x130*_x131 - _x132*_x133
    _x135 = math.sqrt(_x122*k_c + _x134**2)
    _x136 = _x134 + _x135
    _x137 = (1.0/_x136)
    _x138 = m*q_r**2
    _x139 = _x138*q_thd
    _x140 = _x126*k_c
    _x141 = 0.0051978942923343804*k_c
    _x142 = _x130*k_c
    _x143 = _x132*k_c
    _x144 = (1.0/_x135)
    _x145 = _x137**2
    _x146 = _x122*_x145
    _x147 = _x128*k_c
    _x148 = _x134*_x144
    _x149 = 2.0*q_r
    _x150 = _x138*q_thd__tan + _x149*m*q_r__tan*q_thd
    _next_D = _x122*_x137
    _next_Q0 = 0.08696371128436346*_ifq0 + 0.35267675751627187*_ifq1 + 0.31344511474186837*_ifq2 + 0.1774825722545226*_ifq3 + q_th
    _next_Q1 = -0.014190694931141144*_ifq0 + 0.16303628871563652*_ifq1 + 0.35395300603374397*_ifq2 + 0.16719192197418878*_ifq3 + q_th
    _next_Q2 = 0.006735500594538156*_ifq0 - 0.027880428602470895*_ifq1 + 0.16303628871563652*_ifq2 + 0.18811811749986806*_ifq3 + q_th
    _next_Q3 = -0.0035551496857956833*_ifq0 + 0.012627462689404725*_ifq1 - 0.026604180084998794*_ifq2 + 0.08696371128436346*_ifq3 + q_th
    _next_P0 = 0.08696371128436346*_ifp0 + 0.35267675751627187*_ifp1 + 0.31344511474186837*_ifp2 + 0.1774825722545226*_ifp3 + _x139
    _next_P1 = -0.014190694931141144*_ifp0 + 0.16303628871563652*_ifp1 + 0.35395300603374397*_ifp2 + 0.16719192197418878*_ifp3 + _x139
    _next_P2 = 0.006735500594538156*_ifp0 - 0.027880428602470895*_ifp1 + 0.16303628871563652*_ifp2 + 0.18811811749986806*_ifp3 + _x139
    _next_P3 = -0.0035551496857956833*_ifp0 + 0.012627462689404725*_ifp1 - 0.026604180084998794*_ifp2 + 0.08696371128436346*_ifp3 + _x139
    _next_D__tan = _iF0__tan*_x146*(-_x144*(0.0005833289296948737*_iF0 + 0.0051978942923343804*_iF1 + 0.01055284814259947*_iF2 + 0.007818132048204519*_iF3 + 0.024152203412833244*_x124 - _x128*_x141 - 0.0005833289296948737*_x140 - 0.01055284814259947*_x142 - 0.007818132048204519*_x143) - 0.024152203412833244) + _iF1__tan*_x146*(-_x144*(0.0051978942923343804*_iF0 + 0.046317101208086645*_iF1 + 0.09403371980364733*_iF2 + 0.06966536696771665*_iF3 + 0.215214082271785*_x124 - _x126*_x141 - 0.09403371980364733*_x142 - 0.06966536696771665*_x143 - 0.046317101208086645*_x147) - 0.215214082271785) + _iF2__tan*_x146*(-_x144*(0.01055284814259947*_iF0 + 0.09403371980364733*_iF1 + 0.19090876219531297*_iF2 + 0.14143574244920135*_iF3 + 0.43693107259076114*_x124 - 0.01055284814259947*_x140 - 0.19090876219531297*_x142 - 0.14143574244920135*_x143 - 0.09403371980364733*_x147) - 0.43693107259076114) + _iF3__tan*_x146*(-_x144*(0.007818132048204519*_iF0 + 0.06966536696771665*_iF1 + 0.14143574244920135*_iF2 + 0.10478340025949809*_iF3 + 0.3237026417246206*_x124 - 0.007818132048204519*_x140 - 0.14143574244920135*_x142 - 0.10478340025949809*_x143 - 0.06966536696771665*_x147) - 0.3237026417246206) + _isigma0__tan*_x146*(-_x127*_x148 - _x127) + _isigma1__tan*_x146*(-_x129*_x148 - _x129) + _isigma2__tan*_x146*(-_x131*_x148 - _x131) + _isigma3__tan*_x146*(-_x133*_x148 - _x133) + _x146*k_c__tan*(-0.024152203412833244*_isigma0 - 0.215214082271785*_isigma1 - 0.43693107259076114*_isigma2 - 0.3237026417246206*_isigma3 - _x123 - _x144*((0.5)*_x122 + (0.5)*_x134*(0.04830440682566649*_isigma0 + 0.43042816454357*_isigma1 + 0.8738621451815223*_isigma2 + 0.6474052834492412*_isigma3 - _x149 - 8.470329472543003e-22*l0)) + 4.235164736271502e-22*l0) + _x146*q_r__tan*(_x148*k_c + k_c) + q_rd__tan*(2.0*_x137*m*q_rd - _x144*_x145*k_c*m**2*q_rd**3)
    _next_Q0__tan = 0.08696371128436346*_ifq0__tan + 0.35267675751627187*_ifq1__tan + 0.31344511474186837*_ifq2__tan + 0.1774825722545226*_ifq3__tan + q_th__tan
    _next_Q1__tan = -0.014190694931141144*_ifq0__tan + 0.16303628871563652*_ifq1__tan + 0.35395300603374397*_ifq2__tan + 0.16719192197418878*_ifq3__tan + q_th__tan
    _next_Q2__tan = 0.006735500594538156*_ifq0__tan - 0.027880428602470895*_ifq1__tan + 0.16303628871563652*_ifq2__tan + 0.18811811749986806*_ifq3__tan + q_th__tan
    _next_Q3__tan = -0.0035551496857956833*_ifq0__tan + 0.012627462689404725*_ifq1__tan - 0.026604180084998794*_ifq2__tan + 0.08696371128436346*_ifq3__tan + q_th__tan
    _next_P0__tan = 0.08696371128436346*_ifp0__tan + 0.35267675751627187*_ifp1__tan + 0.31344511474186837*_ifp2__tan + 0.1774825722545226*_ifp3__tan + _x150
    _next_P1__tan = -0.014190694931141144*_ifp0__tan + 0.16303628871563652*_ifp1__tan + 0.35395300603374397*_ifp2__tan + 0.16719192197418878*_ifp3__tan + _x150
    _next_P2__tan = 0.006735500594538156*_ifp0__tan - 0.027880428602470895*_ifp1__tan + 0.16303628871563652*_ifp2__tan + 0.18811811749986806*_ifp3__tan + _x150
    _next_P3__tan = -0.0035551496857956833*_ifp0__tan + 0.012627462689404725*_ifp1__tan - 0.026604180084998794*_ifp2__tan + 0.08696371128436346*_ifp3__tan + _x150
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_Q1, _next_Q2, _next_Q3, _next_P0, _next_P1, _next_P2, _next_P3, _next_D__tan, _next_Q0__tan, _next_Q1__tan, _next_Q2__tan, _next_Q3__tan, _next_P0__tan, _next_P1__tan, _next_P2__tan, _next_P3__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_10(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _P3: value of the caller's variable
        _P3__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _Q3: value of the caller's variable
        _Q3__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 696
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = -q_r
    _x1 = 0.9951792190105739*_D + _x0
    _x2 = -_x1
    _x118 = (1.0/_x2)
    _x3 = -q_r__tan
    _x4 = -0.9951792190105739*_D__tan - _x3
    _x5 = k_c*l0
    _x6 = math.cos(_Q0)
    _x7 = g_s*m
    _x8 = _x6*_x7
    _x9 = _x2*k_c
    _x10 = _x118**3
    _x11 = _P0**2
    _x12 = (1.0/m)
    _x13 = _x11*_x12
    _x14 = _x10*_x13
    _x15 = math.sin(_Q0)
    _x16 = _Q0__tan*_x15*_x7
    _x17 = k_c__tan*(_x1 + l0)
    _x18 = 2.0*_x12
    _x19 = _P0*_x10
    _x20 = _P0__tan*_x19
    _x21 = _x4*(-3.0*_x118**4*_x13 - k_c)
    _x22 = 0.8910937442931661*_D + _x0
    _x23 = -_x22
    _x119 = (1.0/_x23)
    _x24 = -0.8910937442931661*_D__tan - _x3
    _x25 = math.cos(_Q1)
    _x26 = _x25*_x7
    _x27 = _x23*k_c
    _x28 = _x119**3
    _x29 = _P1**2
    _x30 = _x12*_x29
    _x31 = _x28*_x30
    _x32 = math.sin(_Q1)
    _x33 = _Q1__tan*_x32*_x7
    _x34 = k_c__tan*(_x22 + l0)
    _x35 = _P1*_x28
    _x36 = _P1__tan*_x35
    _x37 = _x24*(-3.0*_x119**4*_x30 - k_c)
    _x38 = 0.5511127007083099*_D + _x0
    _x39 = -_x38
    _x120 = (1.0/_x39)
    _x40 = -0.5511127007083099*_D__tan - _x3
    _x41 = math.cos(_Q2)
    _x42 = _x41*_x7
    _x43 = _x39*k_c
    _x44 = _x120**3
    _x45 = _P2**2
    _x46 = _x12*_x45
    _x47 = _x44*_x46
    _x48 = math.sin(_Q2)
    _x49 = _Q2__tan*_x48*_x7
    _x50 = k_c__tan*(_x38 + l0)
    _x51 = _P2*_x44
    _x52 = _P2__tan*_x51
    _x53 = _x40*(-3.0*_x120**4*_x46 - k_c)
    _x54 = 0.13404290741652142*_D + _x0
    _x55 = -_x54
    _x121 = (1.0/_x55)
    _x56 = -0.13404290741652142*_D__tan - _x3
    _x57 = math.cos(_Q3)
    _x58 = _x57*_x7
    _x59 = _x55*k_c
    _x60 = _x121**3
    _x61 = _P3**2
    _x62 = _x12*_x61
    _x63 = _x60*_x62
    _x64 = math.sin(_Q3)
    _x65 = _Q3__tan*_x64*_x7
    _x66 = k_c__tan*(_x54 + l0)
    _x67 = _P3*_x60
    _x68 = _P3__tan*_x67
    _x69 = _x56*(-3.0*_x121**4*_x62 - k_c)
    _x70 = 0.582374038291501*_x14 + 0.12383458041329967*_x26 + 0.12383458041329967*_x27 - 0.12383458041329967*_x31 - 0.0575898635297681*_x42 - 0.0575898635297681*_x43 + 0.0575898635297681*_x47 + 0.5*_x5 + 0.016129321407969507*_x58 + 0.016129321407969507*_x59 - 0.016129321407969507*_x63 - 0.582374038291501*_x8 - 0.582374038291501*_x9
    _x71 = _x12*_x20
    _x72 = _x12*_x36
    _x73 = _x12*_x52
    _x74 = _x12*_x68
    _x75 = 0.582374038291501*_x16 + 0.582374038291501*_x17 + 0.582374038291501*_x21 - 0.12383458041329967*_x33 - 0.12383458041329967*_x34 - 0.12383458041329967*_x37 + 0.0575898635297681*_x49 + 0.0575898635297681*_x50 + 0.0575898635297681*_x53 - 0.016129321407969507*_x65 - 0.016129321407969507*_x66 - 0.016129321407969507*_x69 + 1.164748076583002*_x71 - 0.24766916082659934*_x72 + 0.1151797270595362*_x73 - 0.032258642815939015*_x74
    _x76 = (1.0/math.sqrt(_x70))
    _x77 = math.sqrt(_D)
    _x78 = math.sqrt(m)
    _x79 = _x77*_x78
    _x80 = (1.0/_x77)
    _x81 = (0.5)*_x79
    _x82 = _x75/_x70**(1.5)
    _x83 = _x118**2
    _x84 = (1.0/_x78)
    _x85 = _x77*_x84
    _x86 = _x76*_x85
    _x87 = (0.5)*_x85
    _x88 = g_s*m**(1.5)
    _x89 = _x77*_x88
    _x90 = _x15*_x76*_x89
    _x91 = _x2*_x76
    _x92 = (0.5)*_D__tan*_x80*_x88
    _x93 = (0.5)*_x89
    _x94 = 0.16000937841634696*_x10*_x11*_x12 + 0.39252437029865583*_x12*_x28*_x29 + 0.017475652789475504*_x12*_x60*_x61 - 0.39252437029865583*_x26 - 0.39252437029865583*_x27 + 0.0700094015044783*_x39*k_c + 0.0700094015044783*_x41*g_s*m - 0.0700094015044783*_x47 - 0.017475652789475504*_x58 - 0.017475652789475504*_x59 - 0.16000937841634696*_x8 - 0.16000937841634696*_x9 + 0.5*k_c*l0
    _x95 = 0.16000937841634696*_x16 + 0.16000937841634696*_x17 + 0.16000937841634696*_x21 + 0.39252437029865583*_x33 + 0.39252437029865583*_x34 + 0.39252437029865583*_x37 - 0.0700094015044783*_x49 - 0.0700094015044783*_x50 - 0.0700094015044783*_x53 + 0.017475652789475504*_x65 + 0.017475652789475504*_x66 + 0.017475652789475504*_x69 + 0.32001875683269393*_x71 + 0.7850487405973117*_x72 - 0.1400188030089566*_x73 + 0.03495130557895101*_x74
    _x96 = (1.0/math.sqrt(_x94))
    _x97 = _x95/_x94**(1.5)
    _x98 = _x119**2
    _x99 = _x85*_x96
    _x100 = _x32*_x89*_x96
    _x101 = _x23*_x96
    _x102 = 0.01613725546399532*_x10*_x11*_x12 + 0.2848443432415939*_x12*_x28*_x29 + 0.21871326539550162*_x12*_x44*_x45 - 0.2848443432415939*_x26 - 0.2848443432415939*_x27 - 0.21871326539550162*_x42 - 0.21871326539550162*_x43 + 0.019694864101090868*_x55*k_c + 0.019694864101090868*_x57*g_s*m - 0.019694864101090868*_x63 - 0.01613725546399532*_x8 - 0.01613725546399532*_x9 + 0.5*k_c*l0
    _x103 = 0.01613725546399532*_x16 + 0.01613725546399532*_x17 + 0.01613725546399532*_x21 + 0.2848443432415939*_x33 + 0.2848443432415939*_x34 + 0.2848443432415939*_x37 + 0.21871326539550162*_x49 + 0.21871326539550162*_x50 + 0.21871326539550162*_x53 - 0.019694864101090868*_x65 - 0.019694864101090868*_x66 - 0.019694864101090868*_x69 + 0.03227451092799064*_x71 + 0.5696886864831878*_x72 + 0.43742653079100324*_x73 - 0.039389728202181735*_x74
    _x104 = (1.0/math.sqrt(_x102))
    _x105 = _x103/_x102**(1.5)
    _x106 = _x120**2
    _x107 = _x104*_x85
    _x108 = _x104*_x48*_x89
    _x109 = _x104*_x39
    _x110 = 0.01796104633752054*_x10*_x11*_x12 + 0.11000222456933441*_x12*_x28*_x29 + 0.2823150697454702*_x12*_x44*_x45 + 0.08972165934767481*_x12*_x60*_x61 - 0.11000222456933441*_x26 - 0.11000222456933441*_x27 - 0.2823150697454702*_x42 - 0.2823150697454702*_x43 - 0.08972165934767481*_x58 - 0.08972165934767481*_x59 - 0.01796104633752054*_x8 - 0.01796104633752054*_x9 + 0.5*k_c*l0
    _x111 = 0.01796104633752054*_x16 + 0.01796104633752054*_x17 + 0.01796104633752054*_x21 + 0.11000222456933441*_x33 + 0.11000222456933441*_x34 + 0.11000222456933441*_x37 + 0.2823150697454702*_x49 + 0.2823150697454702*_x50 + 0.2823150697454702*_x53 + 0.08972165934767481*_x65 + 0.08972165934767481*_x66 + 0.08972165934767481*_x69 + 0.03592209267504108*_x71 + 0.22000444913866882*_x72 + 0.5646301394909404*_x73 + 0.17944331869534963*_x74
    _x112 = (1.0/math.sqrt(_x110))
    _x113 = _x111/_x110**(1.5)
    _x114 = _x121**2
    _x115 = _x112*_x85
    _x116 = _x112*_x64*_x89
    _x117 = _x112*_x55
    _fsigma0 = _x2
    _fsigma0__tan = _x4
    _fF0 = _x14 + _x5 - _x8 - _x9
    _fF0__tan = _x16 + _x17 + _x18*_x20 + _x21
    _fsigma1 = _x23
    _fsigma1__tan = _x24
    _fF1 = -_x26 - _x27 + _x31 + _x5
    _fF1__tan = _x18*_x36 + _x33 + _x34 + _x37
    _fsigma2 = _x39
    _fsigma2__tan = _x40
    _fF2 = -_x42 - _x43 + _x47 + _x5
    _fF2__tan = _x18*_x52 + _x49 + _x50 + _x53
    _fsigma3 = _x55
    _fsigma3__tan = _x56
    _fF3 = _x5 - _x58 - _x59 + _x63
    _fF3__tan = _x18*_x68 + _x65 + _x66 + _x69
    _fPsi0 = _x70
    _fPsi0__tan = _x75
    _fft0 = _x76*_x79
    _fft0__tan = (0.5)*_D__tan*_x76*_x78*_x80 - _x81*_x82
    _ffq0 = _P0*_x83*_x86
    _ffq0__tan = (0.5)*_D__tan*_P0*_x76*_x80*_x83*_x84 - _P0*_x82*_x83*_x87 + _P0__tan*_x76*_x77*_x83*_x84 - 2.0*_x19*_x4*_x86
    _ffp0 = _x2*_x90
    _ffp0__tan = _Q0__tan*_x6*_x89*_x91 - _x15*_x2*_x82*_x93 + _x15*_x91*_x92 + _x4*_x90
    _fPsi1 = _x94
    _fPsi1__tan = _x95
    _fft1 = _x79*_x96
    _fft1__tan = (0.5)*_D__tan*_x78*_x80*_x96 - _x81*_x97
    _ffq1 = _P1*_x98*_x99
    _ffq1__tan = (0.5)*_D__tan*_P1*_x80*_x84*_x96*_x98 - _P1*_x87*_x97*_x98 + _P1__tan*_x77*_x84*_x96*_x98 - 2.0*_x24*_x35*_x99
    _ffp1 = _x100*_x23
    _ffp1__tan = _Q1__tan*_x101*_x25*_x89 + _x100*_x24 + _x101*_x32*_x92 - _x23*_x32*_x93*_x97
    _fPsi2 = _x102
    _fPsi2__tan = _x103
    _fft2 = _x104*_x79
    _fft2__tan = (0.5)*_D__tan*_x104*_x78*_x80 - _x105*_x81
    _ffq2 = _P2*_x106*_x107
    _ffq2__tan = (0.5)*_D__tan*_P2*_x104*_x106*_x80*_x84 - _P2*_x105*_x106*_x87 + _P2__tan*_x104*_x106*_x77*_x84 - 2.0*_x107*_x40*_x51
    _ffp2 = _x108*_x39
    _ffp2__tan = _Q2__tan*_x109*_x41*_x89 - _x105*_x39*_x48*_x93 + _x108*_x40 + _x109*_x48*_x92
    _fPsi3 = _x110
    _fPsi3__tan = _x111
    _fft3 = _x112*_x79
    _fft3__tan = (0.5)*_D__tan*_x112*_x78*_x80 - _x113*_x81
    _ffq3 = _P3*_x114*_x115
    _ffq3__tan = (0.5)*_D__tan*_P3*_x112*_x114*_x80*_x84 - _P3*_x113*_x114*_x87 + _P3__tan*_x112*_x114*_x77*_x84 - 2.0*_x115*_x56*_x67
    _ffp3 = _x116*_x55
    _ffp3__tan = _Q3__tan*_x117*_x57*_x89 - _x113*_x55*_x64*_x93 + _x116*_x56 + _x117*_x64*_x92
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi3 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # bottom state
    _x122 = -_D + q_r
    _x131 = (1.0/_x122)
    _x123 = -_D__tan + q_r__tan
    _x124 = q_r**2
    _x125 = 0.17392742256872692*_ffp0 + 0.32607257743127305*_ffp1 + 0.32607257743127305*_ffp2 + 0.17392742256872692*_ffp3 + _x124*m*q_thd
    _x126 = (1.0/m)
    _x127 = _x131**2
    _x128 = _x126*_x127
    _x129 = 0.17392742256872692*_x128
    _x130 = 0.32607257743127305*_x128
    t_half = 0.17392742256872692*_fft0 + 0.32607257743127305*_fft1 + 0.32607257743127305*_fft2 + 0.17392742256872692*_fft3
    t_half__tan = 0.17392742256872692*_fft0__tan + 0.32607257743127305*_fft1__tan + 0.32607257743127305*_fft2__tan + 0.17392742256872692*_fft3__tan
    end_q_th = 0.17392742256872692*_ffq0 + 0.32607257743127305*_ffq1 + 0.32607257743127305*_ffq2 + 0.17392742256872692*_ffq3 + q_th
    end_q_th__tan = 0.17392742256872692*_ffq0__tan + 0.32607257743127305*_ffq1__tan + 0.32607257743127305*_ffq2__tan + 0.17392742256872692*_ffq3__tan + q_th__tan
    end_q_r = _x122
    end_q_r__tan = _x123
    end_q_rd = 0.0
    end_q_thd = _x125*_x128
    end_q_thd__tan = _ffp0__tan*_x129 + _ffp1__tan*_x130 + _ffp2__tan*_x130 + _ffp3__tan*_x129 - 2.0*_x123*_x125*_x126*_x131**3 + _x124*_x127*q_thd__tan + 2.0*_x127*q_r*q_r__tan*q_thd
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_11(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 3 of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_r: value of the caller's variable
        guess_q_r__tan: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 4 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.9305681557970263*guess_q_th + 0.06943184420297371*q_th
    _Q1 = 0.6699905217924281*guess_q_th + 0.33000947820757187*q_th
    _Q2 = 0.33000947820757187*guess_q_th + 0.6699905217924281*q_th
    _Q3 = 0.06943184420297371*guess_q_th + 0.9305681557970263*q_th
    _P0 = 0.9305681557970263*guess_q_r**2*guess_q_thd*m + 0.06943184420297371*m*q_r**2*q_thd
    _P1 = 0.6699905217924281*guess_q_r**2*guess_q_thd*m + 0.33000947820757187*m*q_r**2*q_thd
    _P2 = 0.33000947820757187*guess_q_r**2*guess_q_thd*m + 0.6699905217924281*m*q_r**2*q_thd
    _P3 = 0.06943184420297371*guess_q_r**2*guess_q_thd*m + 0.9305681557970263*m*q_r**2*q_thd
    _D__tan = -guess_q_r__tan + q_r__tan
    _Q0__tan = 0.9305681557970263*guess_q_th__tan + 0.06943184420297371*q_th__tan
    _Q1__tan = 0.6699905217924281*guess_q_th__tan + 0.33000947820757187*q_th__tan
    _Q2__tan = 0.33000947820757187*guess_q_th__tan + 0.6699905217924281*q_th__tan
    _Q3__tan = 0.06943184420297371*guess_q_th__tan + 0.9305681557970263*q_th__tan
    _P0__tan = 0.9305681557970263*guess_q_r**2*guess_q_thd__tan*m + 1.8611363115940527*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.06943184420297371*m*q_r**2*q_thd__tan + 0.13886368840594743*m*q_r*q_r__tan*q_thd
    _P1__tan = 0.6699905217924281*guess_q_r**2*guess_q_thd__tan*m + 1.3399810435848563*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.33000947820757187*m*q_r**2*q_thd__tan + 0.6600189564151437*m*q_r*q_r__tan*q_thd
    _P2__tan = 0.33000947820757187*guess_q_r**2*guess_q_thd__tan*m + 0.6600189564151437*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.6699905217924281*m*q_r**2*q_thd__tan + 1.3399810435848563*m*q_r*q_r__tan*q_thd
    _P3__tan = 0.06943184420297371*guess_q_r**2*guess_q_thd__tan*m + 0.13886368840594743*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.9305681557970263*m*q_r**2*q_thd__tan + 1.8611363115940527*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_9(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[18] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[18])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_Q1 = _c0[2]
        _next_Q2 = _c0[3]
        _next_Q3 = _c0[4]
        _next_P0 = _c0[5]
        _next_P1 = _c0[6]
        _next_P2 = _c0[7]
        _next_P3 = _c0[8]
        _next_D__tan = _c0[9]
        _next_Q0__tan = _c0[10]
        _next_Q1__tan = _c0[11]
        _next_Q2__tan = _c0[12]
        _next_Q3__tan = _c0[13]
        _next_P0__tan = _c0[14]
        _next_P1__tan = _c0[15]
        _next_P2__tan = _c0[16]
        _next_P3__tan = _c0[17]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_Q1
        _n0_3 = _next_Q2
        _n0_4 = _next_Q3
        _n0_5 = _next_P0
        _n0_6 = _next_P1
        _n0_7 = _next_P2
        _n0_8 = _next_P3
        _n0_9 = _next_D__tan
        _n0_10 = _next_Q0__tan
        _n0_11 = _next_Q1__tan
        _n0_12 = _next_Q2__tan
        _n0_13 = _next_Q3__tan
        _n0_14 = _next_P0__tan
        _n0_15 = _next_P1__tan
        _n0_16 = _next_P2__tan
        _n0_17 = _next_P3__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3) <= tol*(1.0)) and (abs(_n0_5 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_7 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _P0 = _n0_5
        _P1 = _n0_6
        _P2 = _n0_7
        _P3 = _n0_8
        _D__tan = _n0_9
        _Q0__tan = _n0_10
        _Q1__tan = _n0_11
        _Q2__tan = _n0_12
        _Q3__tan = _n0_13
        _P0__tan = _n0_14
        _P1__tan = _n0_15
        _P2__tan = _n0_16
        _P3__tan = _n0_17
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_10(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[22])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    t_half = _c1[12]
    t_half__tan = _c1[13]
    end_q_th = _c1[14]
    end_q_th__tan = _c1[15]
    end_q_r = _c1[16]
    end_q_r__tan = _c1[17]
    end_q_rd = _c1[18]
    end_q_thd = _c1[19]
    end_q_thd__tan = _c1[20]
    passes = _c1[21]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_12(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _P4, _P4__tan, _P5, _P5__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _Q4, _Q4__tan, _Q5, _Q5__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _P3: value of the caller's variable
        _P3__tan: value of the caller's variable
        _P4: value of the caller's variable
        _P4__tan: value of the caller's variable
        _P5: value of the caller's variable
        _P5__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _Q3: value of the caller's variable
        _Q3__tan: value of the caller's variable
        _Q4: value of the caller's variable
        _Q4__tan: value of the caller's variable
        _Q5: value of the caller's variable
        _Q5__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_Q1: result for the caller
        _next_Q2: result for the caller
        _next_Q3: result for the caller
        _next_Q4: result for the caller
        _next_Q5: result for the caller
        _next_P0: result for the caller
        _next_P1: result for the caller
        _next_P2: result for the caller
        _next_P3: result for the caller
        _next_P4: result for the caller
        _next_P5: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_Q1__tan: result for the caller
        _next_Q2__tan: result for the caller
        _next_Q3__tan: result for the caller
        _next_Q4__tan: result for the caller
        _next_Q5__tan: result for the caller
        _next_P0__tan: result for the caller
        _next_P1__tan: result for the caller
        _next_P2__tan: result for the caller
        _next_P3__tan: result for the caller
        _next_P4__tan: result for the caller
        _next_P5__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1755
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = -q_r
    _x1 = 0.9988599083720104*_D + _x0
    _x2 = -_x1
    _x170 = (1.0/_x2)
    _x3 = -q_r__tan
    _x4 = -0.9988599083720104*_D__tan - _x3
    _x5 = k_c*l0
    _x6 = math.cos(_Q0)
    _x7 = g_s*m
    _x8 = _x6*_x7
    _x9 = _x2*k_c
    _x10 = _x170**3
    _x11 = _P0**2
    _x12 = (1.0/m)
    _x13 = _x11*_x12
    _x14 = _x10*_x13
    _x15 = math.sin(_Q0)
    _x16 = _Q0__tan*_x15*_x7
    _x17 = k_c__tan*(_x1 + l0)
    _x18 = 2.0*_x12
    _x19 = _P0*_x10
    _x20 = _P0__tan*_x19
    _x21 = _x4*(-3.0*_x13*_x170**4 - k_c)
    _x22 = 0.9713052300453587*_D + _x0
    _x23 = -_x22
    _x171 = (1.0/_x23)
    _x24 = -0.9713052300453587*_D__tan - _x3
    _x25 = math.cos(_Q1)
    _x26 = _x25*_x7
    _x27 = _x23*k_c
    _x28 = _x171**3
    _x29 = _P1**2
    _x30 = _x12*_x29
    _x31 = _x28*_x30
    _x32 = math.sin(_Q1)
    _x33 = _Q1__tan*_x32*_x7
    _x34 = k_c__tan*(_x22 + l0)
    _x35 = _P1*_x28
    _x36 = _P1__tan*_x35
    _x37 = _x24*(-3.0*_x171**4*_x30 - k_c)
    _x38 = 0.8550748140498466*_D + _x0
    _x39 = -_x38
    _x172 = (1.0/_x39)
    _x40 = -0.8550748140498466*_D__tan - _x3
    _x41 = math.cos(_Q2)
    _x42 = _x41*_x7
    _x43 = _x39*k_c
    _x44 = _x172**3
    _x45 = _P2**2
    _x46 = _x12*_x45
    _x47 = _x44*_x46
    _x48 = math.sin(_Q2)
    _x49 = _Q2__tan*_x48*_x7
    _x50 = k_c__tan*(_x38 + l0)
    _x51 = _P2*_x44
    _x52 = _P2__tan*_x51
    _x53 = _x40*(-3.0*_x172**4*_x46 - k_c)
    _x54 = 0.6164556279666497*_D + _x0
    _x55 = -_x54
    _x173 = (1.0/_x55)
    _x56 = -0.6164556279666497*_D__tan - _x3
    _x57 = math.cos(_Q3)
    _x58 = _x57*_x7
    _x59 = _x55*k_c
    _x60 = _x173**3
    _x61 = _P3**2
    _x62 = _x12*_x61
    _x63 = _x60*_x62
    _x64 = math.sin(_Q3)
    _x65 = _Q3__tan*_x64*_x7
    _x66 = k_c__tan*(_x54 + l0)
    _x67 = _P3*_x60
    _x68 = _P3__tan*_x67
    _x69 = _x56*(-3.0*_x173**4*_x62 - k_c)
    _x70 = 0.31009584357909425*_D + _x0
    _x71 = -_x70
    _x174 = (1.0/_x71)
    _x72 = -0.31009584357909425*_D__tan - _x3
    _x73 = math.cos(_Q4)
    _x74 = _x7*_x73
    _x75 = _x71*k_c
    _x76 = _x174**3
    _x77 = _P4**2
    _x78 = _x12*_x77
    _x79 = _x76*_x78
    _x80 = math.sin(_Q4)
    _x81 = _Q4__tan*_x7*_x80
    _x82 = k_c__tan*(_x70 + l0)
    _x83 = _P4*_x76
    _x84 = _P4__tan*_x83
    _x85 = _x72*(-3.0*_x174**4*_x78 - k_c)
    _x86 = 0.0663903941688584*_D + _x0
    _x87 = -_x86
    _x175 = (1.0/_x87)
    _x88 = -0.0663903941688584*_D__tan - _x3
    _x89 = math.cos(_Q5)
    _x90 = _x7*_x89
    _x91 = _x87*k_c
    _x92 = _x175**3
    _x93 = _P5**2
    _x94 = _x12*_x93
    _x95 = _x92*_x94
    _x96 = math.sin(_Q5)
    _x97 = _Q5__tan*_x7*_x96
    _x98 = k_c__tan*(_x86 + l0)
    _x99 = _P5*_x92
    _x100 = _P5__tan*_x99
    _x101 = _x88*(-3.0*_x175**4*_x94 - k_c)
    _x102 = 0.5871580340658094*_x14 + 0.140380692261653*_x26 + 0.140380692261653*_x27 - 0.140380692261653*_x31 - 0.08683151831711133*_x42 - 0.08683151831711133*_x43 + 0.08683151831711133*_x47 + 0.5*_x5 + 0.052466581536012566*_x58 + 0.052466581536012566*_x59 - 0.052466581536012566*_x63 - 0.026354606039126004*_x74 - 0.026354606039126004*_x75 + 0.026354606039126004*_x79 - 0.5871580340658094*_x8 - 0.5871580340658094*_x9 + 0.007496884624381081*_x90 + 0.007496884624381081*_x91 - 0.007496884624381081*_x95
    _x103 = _x12*_x20
    _x104 = _x12*_x36
    _x105 = _x12*_x52
    _x106 = _x12*_x68
    _x107 = _x12*_x84
    _x108 = _x100*_x12
    _x109 = -0.007496884624381081*_x101 + 1.1743160681316187*_x103 - 0.280761384523306*_x104 + 0.17366303663422267*_x105 - 0.10493316307202513*_x106 + 0.05270921207825201*_x107 - 0.014993769248762162*_x108 + 0.5871580340658094*_x16 + 0.5871580340658094*_x17 + 0.5871580340658094*_x21 - 0.140380692261653*_x33 - 0.140380692261653*_x34 - 0.140380692261653*_x37 + 0.08683151831711133*_x49 + 0.08683151831711133*_x50 + 0.08683151831711133*_x53 - 0.052466581536012566*_x65 - 0.052466581536012566*_x66 - 0.052466581536012566*_x69 + 0.026354606039126004*_x81 + 0.026354606039126004*_x82 + 0.026354606039126004*_x85 - 0.007496884624381081*_x97 - 0.007496884624381081*_x98
    _x110 = (1.0/math.sqrt(_x102))
    _x111 = math.sqrt(_D)
    _x112 = math.sqrt(m)
    _x113 = _x111*_x112
    _x114 = (1.0/_x111)
    _x115 = (0.5)*_x113
    _x116 = _x109/_x102**(1.5)
    _x117 = _x170**2
    _x118 = (1.0/_x112)
    _x119 = _x111*_x118
    _x120 = _x110*_x119
    _x121 = (0.5)*_x119
    _x122 = g_s*m**(1.5)
    _x123 = _x111*_x122
    _x124 = _x110*_x123*_x15
    _x125 = _x110*_x2
    _x126 = (0.5)*_D__tan*_x114*_x122
    _x127 = (0.5)*_x123
    _x128 = -0.5*k_c*l0
    _x129 = 0.147790320897128*_x10*_x11*_x12 + 0.41567911405660357*_x12*_x28*_x29 + 0.05155355009455148*_x12*_x60*_x61 + 0.006904529857608445*_x12*_x92*_x93 - _x128 - 0.41567911405660357*_x26 - 0.41567911405660357*_x27 + 0.09720828549085844*_x39*k_c + 0.09720828549085844*_x41*g_s*m - 0.09720828549085844*_x47 - 0.05155355009455148*_x58 - 0.05155355009455148*_x59 + 0.024719229415033087*_x71*k_c + 0.024719229415033087*_x73*g_s*m - 0.024719229415033087*_x79 - 0.147790320897128*_x8 - 0.147790320897128*_x9 - 0.006904529857608445*_x90 - 0.006904529857608445*_x91
    _x130 = 0.006904529857608445*_x101 + 0.295580641794256*_x103 + 0.8313582281132071*_x104 - 0.19441657098171689*_x105 + 0.10310710018910296*_x106 - 0.04943845883006617*_x107 + 0.01380905971521689*_x108 + 0.147790320897128*_x16 + 0.147790320897128*_x17 + 0.147790320897128*_x21 + 0.41567911405660357*_x33 + 0.41567911405660357*_x34 + 0.41567911405660357*_x37 - 0.09720828549085844*_x49 - 0.09720828549085844*_x50 - 0.09720828549085844*_x53 + 0.05155355009455148*_x65 + 0.05155355009455148*_x66 + 0.05155355009455148*_x69 - 0.024719229415033087*_x81 - 0.024719229415033087*_x82 - 0.024719229415033087*_x85 + 0.006904529857608445*_x97 + 0.006904529857608445*_x98
    _x131 = (1.0/math.sqrt(_x129))
    _x132 = _x130/_x129**(1.5)
    _x133 = _x171**2
    _x134 = _x119*_x131
    _x135 = _x123*_x131*_x32
    _x136 = _x131*_x23
    _x137 = 0.010443786721981197*_x10*_x11*_x12 + 0.25540525119175433*_x12*_x28*_x29 + 0.2685463444140672*_x12*_x44*_x45 + 0.01951903325298492*_x12*_x76*_x77 - _x128 - 0.25540525119175433*_x26 - 0.25540525119175433*_x27 - 0.2685463444140672*_x42 - 0.2685463444140672*_x43 + 0.048794612428541204*_x55*k_c + 0.048794612428541204*_x57*g_s*m - 0.048794612428541204*_x63 - 0.01951903325298492*_x74 - 0.01951903325298492*_x75 - 0.010443786721981197*_x8 + 0.005119803152246505*_x87*k_c + 0.005119803152246505*_x89*g_s*m - 0.010443786721981197*_x9 - 0.005119803152246505*_x95
    _x138 = -0.005119803152246505*_x101 + 0.020887573443962394*_x103 + 0.5108105023835087*_x104 + 0.5370926888281344*_x105 - 0.09758922485708241*_x106 + 0.03903806650596984*_x107 - 0.01023960630449301*_x108 + 0.010443786721981197*_x16 + 0.010443786721981197*_x17 + 0.010443786721981197*_x21 + 0.25540525119175433*_x33 + 0.25540525119175433*_x34 + 0.25540525119175433*_x37 + 0.2685463444140672*_x49 + 0.2685463444140672*_x50 + 0.2685463444140672*_x53 - 0.048794612428541204*_x65 - 0.048794612428541204*_x66 - 0.048794612428541204*_x69 + 0.01951903325298492*_x81 + 0.01951903325298492*_x82 + 0.01951903325298492*_x85 - 0.005119803152246505*_x97 - 0.005119803152246505*_x98
    _x139 = (1.0/math.sqrt(_x137))
    _x140 = _x138/_x137**(1.5)
    _x141 = _x172**2
    _x142 = _x119*_x139
    _x143 = _x123*_x139*_x48
    _x144 = _x139*_x39
    _x145 = -0.5*k_c*l0
    _x146 = 0.01101839635505667*_x10*_x11*_x12 + 0.0662099828438604*_x12*_x28*_x29 + 0.2671819482314443*_x12*_x44*_x45 + 0.1742495636223592*_x12*_x60*_x61 + 0.00530703852813994*_x12*_x92*_x93 - _x145 - 0.0662099828438604*_x26 - 0.0662099828438604*_x27 - 0.2671819482314443*_x42 - 0.2671819482314443*_x43 - 0.1742495636223592*_x58 - 0.1742495636223592*_x59 + 0.02396692958086051*_x71*k_c + 0.02396692958086051*_x73*g_s*m - 0.02396692958086051*_x79 - 0.01101839635505667*_x8 - 0.01101839635505667*_x9 - 0.00530703852813994*_x90 - 0.00530703852813994*_x91
    _x147 = 0.00530703852813994*_x101 + 0.02203679271011334*_x103 + 0.1324199656877208*_x104 + 0.5343638964628886*_x105 + 0.3484991272447184*_x106 - 0.04793385916172102*_x107 + 0.01061407705627988*_x108 + 0.01101839635505667*_x16 + 0.01101839635505667*_x17 + 0.01101839635505667*_x21 + 0.0662099828438604*_x33 + 0.0662099828438604*_x34 + 0.0662099828438604*_x37 + 0.2671819482314443*_x49 + 0.2671819482314443*_x50 + 0.2671819482314443*_x53 + 0.1742495636223592*_x65 + 0.1742495636223592*_x66 + 0.1742495636223592*_x69 - 0.02396692958086051*_x81 - 0.02396692958086051*_x82 - 0.02396692958086051*_x85 + 0.00530703852813994*_x97 + 0.00530703852813994*_x98
    _x148 = (1.0/math.sqrt(_x146))
    _x149 = _x147/_x146**(1.5)
    _x150 = _x173**2
    _x151 = _x119*_x148
    _x152 = _x123*_x148*_x64
    _x153 = _x148*_x55
    _x154 = 0.0025147977064533143*_x10*_x11*_x12 + 0.050345455482979015*_x12*_x28*_x29 + 0.11622097556712797*_x12*_x44*_x45 + 0.2353986790647292*_x12*_x60*_x61 + 0.10372825048336794*_x12*_x76*_x77 - _x128 - 0.050345455482979015*_x26 - 0.050345455482979015*_x27 - 0.11622097556712797*_x42 - 0.11622097556712797*_x43 - 0.2353986790647292*_x58 - 0.2353986790647292*_x59 - 0.10372825048336794*_x74 - 0.10372825048336794*_x75 - 0.0025147977064533143*_x8 + 0.008208158304657426*_x87*k_c + 0.008208158304657426*_x89*g_s*m - 0.0025147977064533143*_x9 - 0.008208158304657426*_x95
    _x155 = -0.008208158304657426*_x101 + 0.005029595412906629*_x103 + 0.10069091096595803*_x104 + 0.23244195113425595*_x105 + 0.4707973581294584*_x106 + 0.20745650096673587*_x107 - 0.016416316609314852*_x108 + 0.0025147977064533143*_x16 + 0.0025147977064533143*_x17 + 0.0025147977064533143*_x21 + 0.050345455482979015*_x33 + 0.050345455482979015*_x34 + 0.050345455482979015*_x37 + 0.11622097556712797*_x49 + 0.11622097556712797*_x50 + 0.11622097556712797*_x53 + 0.2353986790647292*_x65 + 0.2353986790647292*_x66 + 0.2353986790647292*_x69 + 0.10372825048336794*_x81 + 0.10372825048336794*_x82 + 0.10372825048336794*_x85 - 0.008208158304657426*_x97 - 0.008208158304657426*_x98
    _x156 = (1.0/math.sqrt(_x154))
    _x157 = _x155/_x154**(1.5)
    _x158 = _x174**2
    _x159 = _x119*_x156
    _x160 = _x123*_x156*_x80
    _x161 = _x156*_x71
    _x162 = 0.003959513229722528*_x10*_x11*_x12 + 0.029703284805013122*_x12*_x28*_x29 + 0.10140664131431479*_x12*_x44*_x45 + 0.14531313573962065*_x12*_x60*_x61 + 0.17612158869639333*_x12*_x76*_x77 + 0.04349583621493557*_x12*_x92*_x93 - _x145 - 0.029703284805013122*_x26 - 0.029703284805013122*_x27 - 0.10140664131431479*_x42 - 0.10140664131431479*_x43 - 0.14531313573962065*_x58 - 0.14531313573962065*_x59 - 0.17612158869639333*_x74 - 0.17612158869639333*_x75 - 0.003959513229722528*_x8 - 0.003959513229722528*_x9 - 0.04349583621493557*_x90 - 0.04349583621493557*_x91
    _x163 = 0.04349583621493557*_x101 + 0.007919026459445056*_x103 + 0.059406569610026244*_x104 + 0.20281328262862958*_x105 + 0.2906262714792413*_x106 + 0.35224317739278665*_x107 + 0.08699167242987114*_x108 + 0.003959513229722528*_x16 + 0.003959513229722528*_x17 + 0.003959513229722528*_x21 + 0.029703284805013122*_x33 + 0.029703284805013122*_x34 + 0.029703284805013122*_x37 + 0.10140664131431479*_x49 + 0.10140664131431479*_x50 + 0.10140664131431479*_x53 + 0.14531313573962065*_x65 + 0.14531313573962065*_x66 + 0.14531313573962065*_x69 + 0.17612158869639333*_x81 + 0.17612158869639333*_x82 + 0.17612158869639333*_x85 + 0.04349583621493557*_x97 + 0.04349583621493557*_x98
    _x164 = (1.0/math.sqrt(_x162))
    _x165 = _x163/_x162**(1.5)
    _x166 = _x175**2
    _x167 = _x119*_x164
    _x168 = _x123*_x164*_x96
    _x169 = _x164*_x87
    _isigma0 = _x2
    _isigma0__tan = _x4
    _iF0 = _x14 + _x5 - _x8 - _x9
    _iF0__tan = _x16 + _x17 + _x18*_x20 + _x21
    _isigma1 = _x23
    _isigma1__tan = _x24
    _iF1 = -_x26 - _x27 + _x31 + _x5
    _iF1__tan = _x18*_x36 + _x33 + _x34 + _x37
    _isigma2 = _x39
    _isigma2__tan = _x40
    _iF2 = -_x42 - _x43 + _x47 + _x5
    _iF2__tan = _x18*_x52 + _x49 + _x50 + _x53
    _isigma3 = _x55
    _isigma3__tan = _x56
    _iF3 = _x5 - _x58 - _x59 + _x63
    _iF3__tan = _x18*_x68 + _x65 + _x66 + _x69
    _isigma4 = _x71
    _isigma4__tan = _x72
    _iF4 = _x5 - _x74 - _x75 + _x79
    _iF4__tan = _x18*_x84 + _x81 + _x82 + _x85
    _isigma5 = _x87
    _isigma5__tan = _x88
    _iF5 = _x5 - _x90 - _x91 + _x95
    _iF5__tan = _x100*_x18 + _x101 + _x97 + _x98
    _iPsi0 = _x102
    _iPsi0__tan = _x109
    _ift0 = _x110*_x113
    _ift0__tan = (0.5)*_D__tan*_x110*_x112*_x114 - _x115*_x116
    _ifq0 = _P0*_x117*_x120
    _ifq0__tan = (0.5)*_D__tan*_P0*_x110*_x114*_x117*_x118 - _P0*_x116*_x117*_x121 + _P0__tan*_x110*_x111*_x117*_x118 - 2.0*_x120*_x19*_x4
    _ifp0 = _x124*_x2
    _ifp0__tan = _Q0__tan*_x123*_x125*_x6 - _x116*_x127*_x15*_x2 + _x124*_x4 + _x125*_x126*_x15
    _iPsi1 = _x129
    _iPsi1__tan = _x130
    _ift1 = _x113*_x131
    _ift1__tan = (0.5)*_D__tan*_x112*_x114*_x131 - _x115*_x132
    _ifq1 = _P1*_x133*_x134
    _ifq1__tan = (0.5)*_D__tan*_P1*_x114*_x118*_x131*_x133 - _P1*_x121*_x132*_x133 + _P1__tan*_x111*_x118*_x131*_x133 - 2.0*_x134*_x24*_x35
    _ifp1 = _x135*_x23
    _ifp1__tan = _Q1__tan*_x123*_x136*_x25 + _x126*_x136*_x32 - _x127*_x132*_x23*_x32 + _x135*_x24
    _iPsi2 = _x137
    _iPsi2__tan = _x138
    _ift2 = _x113*_x139
    _ift2__tan = (0.5)*_D__tan*_x112*_x114*_x139 - _x115*_x140
    _ifq2 = _P2*_x141*_x142
    _ifq2__tan = (0.5)*_D__tan*_P2*_x114*_x118*_x139*_x141 - _P2*_x121*_x140*_x141 + _P2__tan*_x111*_x118*_x139*_x141 - 2.0*_x142*_x40*_x51
    _ifp2 = _x143*_x39
    _ifp2__tan = _Q2__tan*_x123*_x144*_x41 + _x126*_x144*_x48 - _x127*_x140*_x39*_x48 + _x143*_x40
    _iPsi3 = _x146
    _iPsi3__tan = _x147
    _ift3 = _x113*_x148
    _ift3__tan = (0.5)*_D__tan*_x112*_x114*_x148 - _x115*_x149
    _ifq3 = _P3*_x150*_x151
    _ifq3__tan = (0.5)*_D__tan*_P3*_x114*_x118*_x148*_x150 - _P3*_x121*_x149*_x150 + _P3__tan*_x111*_x118*_x148*_x150 - 2.0*_x151*_x56*_x67
    _ifp3 = _x152*_x55
    _ifp3__tan = _Q3__tan*_x123*_x153*_x57 + _x126*_x153*_x64 - _x127*_x149*_x55*_x64 + _x152*_x56
    _iPsi4 = _x154
    _iPsi4__tan = _x155
    _ift4 = _x113*_x156
    _ift4__tan = (0.5)*_D__tan*_x112*_x114*_x156 - _x115*_x157
    _ifq4 = _P4*_x158*_x159
    _ifq4__tan = (0.5)*_D__tan*_P4*_x114*_x118*_x156*_x158 - _P4*_x121*_x157*_x158 + _P4__tan*_x111*_x118*_x156*_x158 - 2.0*_x159*_x72*_x83
    _ifp4 = _x160*_x71
    _ifp4__tan = _Q4__tan*_x123*_x161*_x73 + _x126*_x161*_x80 - _x127*_x157*_x71*_x80 + _x160*_x72
    _iPsi5 = _x162
    _iPsi5__tan = _x163
    _ift5 = _x113*_x164
    _ift5__tan = (0.5)*_D__tan*_x112*_x114*_x164 - _x115*_x165
    _ifq5 = _P5*_x166*_x167
    _ifq5__tan = (0.5)*_D__tan*_P5*_x114*_x118*_x164*_x166 - _P5*_x121*_x165*_x166 + _P5__tan*_x111*_x118*_x164*_x166 - 2.0*_x167*_x88*_x99
    _ifp5 = _x168*_x87
    _ifp5__tan = _Q5__tan*_x123*_x169*_x89 + _x126*_x169*_x96 - _x127*_x165*_x87*_x96 + _x168*_x88
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi3 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi4 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi5 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x176 = m*q_rd**2
    _x177 = -q_r
    _x178 = k_c*(_x177 + l0)
    _x179 = -l0
    _x180 = -_isigma0 - _x179
    _x181 = 0.005784813099631875*k_c
    _x182 = -_isigma1 - _x179
    _x183 = 0.06111131733618721*k_c
    _x184 = -_isigma2 - _x179
    _x185 = 0.17813034617398463*k_c
    _x186 = -_isigma3 - _x179
    _x187 = 0.28978358839870644*k_c
    _x188 = -_isigma4 - _x179
    _x189 = 0.2996502557119514*k_c
    _x190 = -_isigma5 - _x179
    _x191 = 0.16553967927953847*k_c
    _x192 = 0.005784813099631875*_iF0 + 0.06111131733618721*_iF1 + 0.17813034617398463*_iF2 + 0.28978358839870644*_iF3 + 0.2996502557119514*_iF4 + 0.16553967927953847*_iF5 + _x178 - _x180*_x181 - _x182*_x183 - _x184*_x185 - _x186*_x187 - _x188*_x189 - _x190*_x191
    _x193 = math.sqrt(_x176*k_c + _x192**2)
    _x194 = _x192 + _x193
    _x195 = (1.0/_x194)
    _x196 = m*q_r**2
    _x197 = _x196*q_thd
    _x198 = _x180*k_c
    _x199 = _x182*k_c
    _x200 = _x184*k_c
    _x201 = _x186*k_c
    _x202 = _x188*k_c
    _x203 = _x190*k_c
    _x204 = (1.0/_x193)
    _x205 = _x195**2
    _x206 = _x176*_x205
    _x207 = _x192*_x204
    _x208 = 2.0*q_r
    _x209 = _x196*q_thd__tan + _x208*m*q_r__tan*q_thd
    _next_D = _x176*_x195
    _next_Q0 = 0.04283112309479259*_ifq0 + 0.19514451252126672*_ifq1 + 0.22463191657986778*_ifq2 + 0.23962582533582905*_ifq3 + 0.17752635320896998*_ifq4 + 0.08647502636084993*_ifq5 + q_th
    _next_Q1 = -0.007011245240793691*_ifq0 + 0.09019039326203465*_ifq1 + 0.2542570695795851*_ifq2 + 0.2235938110460991*_ifq3 + 0.18526797945210696*_ifq4 + 0.08430668513410011*_ifq5 + q_th
    _next_Q2 = 0.0034143235767412987*_ifq0 - 0.0156513758091757*_ifq1 + 0.11697848364317276*_ifq2 + 0.25443949503200164*_ifq3 + 0.17239079462440696*_ifq4 + 0.0877378719744515*_ifq5 + q_th
    _next_Q3 = -0.002075625784866334*_ifq0 + 0.007989991899662336*_ifq1 - 0.020482527745656096*_ifq2 + 0.11697848364317276*_ifq3 + 0.196032162333245*_ifq4 + 0.08224792261284387*_ifq5 + q_th
    _next_Q4 = 0.0013555610554850618*_ifq0 - 0.004887192928037671*_ifq1 + 0.010363156240246424*_ifq2 - 0.020300102293239586*_ifq3 + 0.09019039326203465*_ifq4 + 0.09267349143037887*_ifq5 + q_th
    _next_Q5 = -0.0008127801712647621*_ifq0 + 0.002854433315099335*_ifq1 - 0.005668858049483512*_ifq2 + 0.009325050706477751*_ifq3 - 0.014763725997197413*_ifq4 + 0.04283112309479259*_ifq5 + q_th
    _next_P0 = 0.04283112309479259*_ifp0 + 0.19514451252126672*_ifp1 + 0.22463191657986778*_ifp2 + 0.23962582533582905*_ifp3 + 0.17752635320896998*_ifp4 + 0.08647502636084993*_ifp5 + _x197
    _next_P1 = -0.007011245240793691*_ifp0 + 0.09019039326203465*_ifp1 + 0.2542570695795851*_ifp2 + 0.2235938110460991*_ifp3 + 0.18526797945210696*_ifp4 + 0.08430668513410011*_ifp5 + _x197
    _next_P2 = 0.0034143235767412987*_ifp0 - 0.0156513758091757*_ifp1 + 0.11697848364317276*_ifp2 + 0.25443949503200164*_ifp3 + 0.17239079462440696*_ifp4 + 0.0877378719744515*_ifp5 + _x197
    _next_P3 = -0.002075625784866334*_ifp0 + 0.007989991899662336*_ifp1 - 0.020482527745656096*_ifp2 + 0.11697848364317276*_ifp3 + 0.196032162333245*_ifp4 + 0.08224792261284387*_ifp5 + _x197
    _next_P4 = 0.0013555610554850618*_ifp0 - 0.004887192928037671*_ifp1 + 0.010363156240246424*_ifp2 - 0.020300102293239586*_ifp3 + 0.09019039326203465*_ifp4 + 0.09267349143037887*_ifp5 + _x197
    _next_P5 = -0.0008127801712647621*_ifp0 + 0.002854433315099335*_ifp1 - 0.005668858049483512*_ifp2 + 0.009325050706477751*_ifp3 - 0.014763725997197413*_ifp4 + 0.04283112309479259*_ifp5 + _x197
    _next_D__tan = _iF0__tan*_x206*(-_x204*(3.346406259767255e-05*_iF0 + 0.0003535175490621363*_iF1 + 0.0010304507599892272*_iF2 + 0.0016763438982271685*_iF3 + 0.001733420724550538*_iF4 + 0.0009576161052051336*_iF5 + 0.005784813099631875*_x178 - 3.346406259767255e-05*_x198 - 0.0003535175490621363*_x199 - 0.0010304507599892272*_x200 - 0.0016763438982271685*_x201 - 0.001733420724550538*_x202 - 0.0009576161052051336*_x203) - 0.005784813099631875) + _iF1__tan*_x206*(-_x204*(0.0003535175490621363*_iF0 + 0.003734593106564175*_iF1 + 0.010885780112243256*_iF2 + 0.017709056829452403*_iF3 + 0.018312021866682706*_iF4 + 0.010116347872182529*_iF5 + 0.06111131733618721*_x178 - 0.0003535175490621363*_x198 - 0.003734593106564175*_x199 - 0.010885780112243256*_x200 - 0.017709056829452403*_x201 - 0.018312021866682706*_x202 - 0.010116347872182529*_x203) - 0.06111131733618721) + _iF2__tan*_x206*(-_x204*(0.0010304507599892272*_iF0 + 0.010885780112243256*_iF1 + 0.0317304202280636*_iF2 + 0.05161925091700105*_iF3 + 0.05337680378109292*_iF4 + 0.02948764037559458*_iF5 + 0.17813034617398463*_x178 - 0.0010304507599892272*_x198 - 0.010885780112243256*_x199 - 0.0317304202280636*_x200 - 0.05161925091700105*_x201 - 0.05337680378109292*_x202 - 0.02948764037559458*_x203) - 0.17813034617398463) + _iF3__tan*_x206*(-_x204*(0.0016763438982271685*_iF0 + 0.017709056829452403*_iF1 + 0.05161925091700105*_iF2 + 0.0839745281052309*_iF3 + 0.08683372636479925*_iF4 + 0.04797068228399565*_iF5 + 0.28978358839870644*_x178 - 0.0016763438982271685*_x198 - 0.017709056829452403*_x199 - 0.05161925091700105*_x200 - 0.0839745281052309*_x201 - 0.08683372636479925*_x202 - 0.04797068228399565*_x203) - 0.28978358839870644) + _iF4__tan*_x206*(-_x204*(0.001733420724550538*_iF0 + 0.018312021866682706*_iF1 + 0.05337680378109292*_iF2 + 0.08683372636479925*_iF3 + 0.08979027574823786*_iF4 + 0.04960400722658813*_iF5 + 0.2996502557119514*_x178 - 0.001733420724550538*_x198 - 0.018312021866682706*_x199 - 0.05337680378109292*_x200 - 0.08683372636479925*_x201 - 0.08979027574823786*_x202 - 0.04960400722658813*_x203) - 0.2996502557119514) + _iF5__tan*_x206*(-_x204*(0.0009576161052051336*_iF0 + 0.010116347872182529*_iF1 + 0.02948764037559458*_iF2 + 0.04797068228399565*_iF3 + 0.04960400722658813*_iF4 + 0.027403385415972457*_iF5 + 0.16553967927953847*_x178 - 0.0009576161052051336*_x198 - 0.010116347872182529*_x199 - 0.02948764037559458*_x200 - 0.04797068228399565*_x201 - 0.04960400722658813*_x202 - 0.027403385415972457*_x203) - 0.16553967927953847) + _isigma0__tan*_x206*(-_x181*_x207 - _x181) + _isigma1__tan*_x206*(-_x183*_x207 - _x183) + _isigma2__tan*_x206*(-_x185*_x207 - _x185) + _isigma3__tan*_x206*(-_x187*_x207 - _x187) + _isigma4__tan*_x206*(-_x189*_x207 - _x189) + _isigma5__tan*_x206*(-_x191*_x207 - _x191) + _x206*k_c__tan*(-0.005784813099631875*_isigma0 - 0.06111131733618721*_isigma1 - 0.17813034617398463*_isigma2 - 0.28978358839870644*_isigma3 - 0.2996502557119514*_isigma4 - 0.16553967927953847*_isigma5 - _x177 - _x204*((0.5)*_x176 + (0.5)*_x192*(0.01156962619926375*_isigma0 + 0.12222263467237442*_isigma1 + 0.35626069234796925*_isigma2 + 0.5795671767974129*_isigma3 + 0.5993005114239028*_isigma4 + 0.33107935855907694*_isigma5 - _x208 - 1.164670302474663e-21*l0)) + 5.823351512373315e-22*l0) + _x206*q_r__tan*(_x207*k_c + k_c) + q_rd__tan*(2.0*_x195*m*q_rd - _x204*_x205*k_c*m**2*q_rd**3)
    _next_Q0__tan = 0.04283112309479259*_ifq0__tan + 0.19514451252126672*_ifq1__tan + 0.22463191657986778*_ifq2__tan + 0.23962582533582905*_ifq3__tan + 0.17752635320896998*_ifq4__tan + 0.08647502636084993*_ifq5__tan + q_th__tan
    _next_Q1__tan = -0.007011245240793691*_ifq0__tan + 0.09019039326203465*_ifq1__tan + 0.2542570695795851*_ifq2__tan + 0.2235938110460991*_ifq3__tan + 0.18526797945210696*_ifq4__tan + 0.08430668513410011*_ifq5__tan + q_th__tan
    _next_Q2__tan = 0.0034143235767412987*_ifq0__tan - 0.0156513758091757*_ifq1__tan + 0.11697848364317276*_ifq2__tan + 0.25443949503200164*_ifq3__tan + 0.17239079462440696*_ifq4__tan + 0.0877378719744515*_ifq5__tan + q_th__tan
    _next_Q3__tan = -0.002075625784866334*_ifq0__tan + 0.007989991899662336*_ifq1__tan - 0.020482527745656096*_ifq2__tan + 0.11697848364317276*_ifq3__tan + 0.196032162333245*_ifq4__tan + 0.08224792261284387*_ifq5__tan + q_th__tan
    _next_Q4__tan = 0.0013555610554850618*_ifq0__tan - 0.004887192928037671*_ifq1__tan + 0.010363156240246424*_ifq2__tan - 0.020300102293239586*_ifq3__tan + 0.09019039326203465*_ifq4__tan + 0.09267349143037887*_ifq5__tan + q_th__tan
    _next_Q5__tan = -0.0008127801712647621*_ifq0__tan + 0.002854433315099335*_ifq1__tan - 0.005668858049483512*_ifq2__tan + 0.009325050706477751*_ifq3__tan - 0.014763725997197413*_ifq4__tan + 0.04283112309479259*_ifq5__tan + q_th__tan
    _next_P0__tan = 0.04283112309479259*_ifp0__tan + 0.19514451252126672*_ifp1__tan + 0.22463191657986778*_ifp2__tan + 0.23962582533582905*_ifp3__tan + 0.17752635320896998*_ifp4__tan + 0.08647502636084993*_ifp5__tan + _x209
    _next_P1__tan = -0.007011245240793691*_ifp0__tan + 0.09019039326203465*_ifp1__tan + 0.2542570695795851*_ifp2__tan + 0.2235938110460991*_ifp3__tan + 0.18526797945210696*_ifp4__tan + 0.08430668513410011*_ifp5__tan + _x209
    _next_P2__tan = 0.0034143235767412987*_ifp0__tan - 0.0156513758091757*_ifp1__tan + 0.11697848364317276*_ifp2__tan + 0.25443949503200164*_ifp3__tan + 0.17239079462440696*_ifp4__tan + 0.0877378719744515*_ifp5__tan + _x209
    _next_P3__tan = -0.002075625784866334*_ifp0__tan + 0.007989991899662336*_ifp1__tan - 0.020482527745656096*_ifp2__tan + 0.11697848364317276*_ifp3__tan + 0.196032162333245*_ifp4__tan + 0.08224792261284387*_ifp5__tan + _x209
    _next_P4__tan = 0.0013555610554850618*_ifp0__tan - 0.004887192928037671*_ifp1__tan + 0.010363156240246424*_ifp2__tan - 0.020300102293239586*_ifp3__tan + 0.09019039326203465*_ifp4__tan + 0.09267349143037887*_ifp5__tan + _x209
    _next_P5__tan = -0.0008127801712647621*_ifp0__tan + 0.002854433315099335*_ifp1__tan - 0.005668858049483512*_ifp2__tan + 0.009325050706477751*_ifp3__tan - 0.014763725997197413*_ifp4__tan + 0.04283112309479259*_ifp5__tan + _x209
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_Q1, _next_Q2, _next_Q3, _next_Q4, _next_Q5, _next_P0, _next_P1, _next_P2, _next_P3, _next_P4, _next_P5, _next_D__tan, _next_Q0__tan, _next_Q1__tan, _next_Q2__tan, _next_Q3__tan, _next_Q4__tan, _next_Q5__tan, _next_P0__tan, _next_P1__tan, _next_P2__tan, _next_P3__tan, _next_P4__tan, _next_P5__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_13(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _P4, _P4__tan, _P5, _P5__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _Q4, _Q4__tan, _Q5, _Q5__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _P3: value of the caller's variable
        _P3__tan: value of the caller's variable
        _P4: value of the caller's variable
        _P4__tan: value of the caller's variable
        _P5: value of the caller's variable
        _P5__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _Q3: value of the caller's variable
        _Q3__tan: value of the caller's variable
        _Q4: value of the caller's variable
        _Q4__tan: value of the caller's variable
        _Q5: value of the caller's variable
        _Q5__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1213
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = -q_r
    _x1 = 0.9988599083720104*_D + _x0
    _x2 = -_x1
    _x170 = (1.0/_x2)
    _x3 = -q_r__tan
    _x4 = -0.9988599083720104*_D__tan - _x3
    _x5 = k_c*l0
    _x6 = math.cos(_Q0)
    _x7 = g_s*m
    _x8 = _x6*_x7
    _x9 = _x2*k_c
    _x10 = _x170**3
    _x11 = _P0**2
    _x12 = (1.0/m)
    _x13 = _x11*_x12
    _x14 = _x10*_x13
    _x15 = math.sin(_Q0)
    _x16 = _Q0__tan*_x15*_x7
    _x17 = k_c__tan*(_x1 + l0)
    _x18 = 2.0*_x12
    _x19 = _P0*_x10
    _x20 = _P0__tan*_x19
    _x21 = _x4*(-3.0*_x13*_x170**4 - k_c)
    _x22 = 0.9713052300453587*_D + _x0
    _x23 = -_x22
    _x171 = (1.0/_x23)
    _x24 = -0.9713052300453587*_D__tan - _x3
    _x25 = math.cos(_Q1)
    _x26 = _x25*_x7
    _x27 = _x23*k_c
    _x28 = _x171**3
    _x29 = _P1**2
    _x30 = _x12*_x29
    _x31 = _x28*_x30
    _x32 = math.sin(_Q1)
    _x33 = _Q1__tan*_x32*_x7
    _x34 = k_c__tan*(_x22 + l0)
    _x35 = _P1*_x28
    _x36 = _P1__tan*_x35
    _x37 = _x24*(-3.0*_x171**4*_x30 - k_c)
    _x38 = 0.8550748140498466*_D + _x0
    _x39 = -_x38
    _x172 = (1.0/_x39)
    _x40 = -0.8550748140498466*_D__tan - _x3
    _x41 = math.cos(_Q2)
    _x42 = _x41*_x7
    _x43 = _x39*k_c
    _x44 = _x172**3
    _x45 = _P2**2
    _x46 = _x12*_x45
    _x47 = _x44*_x46
    _x48 = math.sin(_Q2)
    _x49 = _Q2__tan*_x48*_x7
    _x50 = k_c__tan*(_x38 + l0)
    _x51 = _P2*_x44
    _x52 = _P2__tan*_x51
    _x53 = _x40*(-3.0*_x172**4*_x46 - k_c)
    _x54 = 0.6164556279666497*_D + _x0
    _x55 = -_x54
    _x173 = (1.0/_x55)
    _x56 = -0.6164556279666497*_D__tan - _x3
    _x57 = math.cos(_Q3)
    _x58 = _x57*_x7
    _x59 = _x55*k_c
    _x60 = _x173**3
    _x61 = _P3**2
    _x62 = _x12*_x61
    _x63 = _x60*_x62
    _x64 = math.sin(_Q3)
    _x65 = _Q3__tan*_x64*_x7
    _x66 = k_c__tan*(_x54 + l0)
    _x67 = _P3*_x60
    _x68 = _P3__tan*_x67
    _x69 = _x56*(-3.0*_x173**4*_x62 - k_c)
    _x70 = 0.31009584357909425*_D + _x0
    _x71 = -_x70
    _x174 = (1.0/_x71)
    _x72 = -0.31009584357909425*_D__tan - _x3
    _x73 = math.cos(_Q4)
    _x74 = _x7*_x73
    _x75 = _x71*k_c
    _x76 = _x174**3
    _x77 = _P4**2
    _x78 = _x12*_x77
    _x79 = _x76*_x78
    _x80 = math.sin(_Q4)
    _x81 = _Q4__tan*_x7*_x80
    _x82 = k_c__tan*(_x70 + l0)
    _x83 = _P4*_x76
    _x84 = _P4__tan*_x83
    _x85 = _x72*(-3.0*_x174**4*_x78 - k_c)
    _x86 = 0.0663903941688584*_D + _x0
    _x87 = -_x86
    _x175 = (1.0/_x87)
    _x88 = -0.0663903941688584*_D__tan - _x3
    _x89 = math.cos(_Q5)
    _x90 = _x7*_x89
    _x91 = _x87*k_c
    _x92 = _x175**3
    _x93 = _P5**2
    _x94 = _x12*_x93
    _x95 = _x92*_x94
    _x96 = math.sin(_Q5)
    _x97 = _Q5__tan*_x7*_x96
    _x98 = k_c__tan*(_x86 + l0)
    _x99 = _P5*_x92
    _x100 = _P5__tan*_x99
    _x101 = _x88*(-3.0*_x175**4*_x94 - k_c)
    _x102 = 0.5871580340658094*_x14 + 0.140380692261653*_x26 + 0.140380692261653*_x27 - 0.140380692261653*_x31 - 0.08683151831711133*_x42 - 0.08683151831711133*_x43 + 0.08683151831711133*_x47 + 0.5*_x5 + 0.052466581536012566*_x58 + 0.052466581536012566*_x59 - 0.052466581536012566*_x63 - 0.026354606039126004*_x74 - 0.026354606039126004*_x75 + 0.026354606039126004*_x79 - 0.5871580340658094*_x8 - 0.5871580340658094*_x9 + 0.007496884624381081*_x90 + 0.007496884624381081*_x91 - 0.007496884624381081*_x95
    _x103 = _x12*_x20
    _x104 = _x12*_x36
    _x105 = _x12*_x52
    _x106 = _x12*_x68
    _x107 = _x12*_x84
    _x108 = _x100*_x12
    _x109 = -0.007496884624381081*_x101 + 1.1743160681316187*_x103 - 0.280761384523306*_x104 + 0.17366303663422267*_x105 - 0.10493316307202513*_x106 + 0.05270921207825201*_x107 - 0.014993769248762162*_x108 + 0.5871580340658094*_x16 + 0.5871580340658094*_x17 + 0.5871580340658094*_x21 - 0.140380692261653*_x33 - 0.140380692261653*_x34 - 0.140380692261653*_x37 + 0.08683151831711133*_x49 + 0.08683151831711133*_x50 + 0.08683151831711133*_x53 - 0.052466581536012566*_x65 - 0.052466581536012566*_x66 - 0.052466581536012566*_x69 + 0.026354606039126004*_x81 + 0.026354606039126004*_x82 + 0.026354606039126004*_x85 - 0.007496884624381081*_x97 - 0.007496884624381081*_x98
    _x110 = (1.0/math.sqrt(_x102))
    _x111 = math.sqrt(_D)
    _x112 = math.sqrt(m)
    _x113 = _x111*_x112
    _x114 = (1.0/_x111)
    _x115 = (0.5)*_x113
    _x116 = _x109/_x102**(1.5)
    _x117 = _x170**2
    _x118 = (1.0/_x112)
    _x119 = _x111*_x118
    _x120 = _x110*_x119
    _x121 = (0.5)*_x119
    _x122 = g_s*m**(1.5)
    _x123 = _x111*_x122
    _x124 = _x110*_x123*_x15
    _x125 = _x110*_x2
    _x126 = (0.5)*_D__tan*_x114*_x122
    _x127 = (0.5)*_x123
    _x128 = -0.5*k_c*l0
    _x129 = 0.147790320897128*_x10*_x11*_x12 + 0.41567911405660357*_x12*_x28*_x29 + 0.05155355009455148*_x12*_x60*_x61 + 0.006904529857608445*_x12*_x92*_x93 - _x128 - 0.41567911405660357*_x26 - 0.41567911405660357*_x27 + 0.09720828549085844*_x39*k_c + 0.09720828549085844*_x41*g_s*m - 0.09720828549085844*_x47 - 0.05155355009455148*_x58 - 0.05155355009455148*_x59 + 0.024719229415033087*_x71*k_c + 0.024719229415033087*_x73*g_s*m - 0.024719229415033087*_x79 - 0.147790320897128*_x8 - 0.147790320897128*_x9 - 0.006904529857608445*_x90 - 0.006904529857608445*_x91
    _x130 = 0.006904529857608445*_x101 + 0.295580641794256*_x103 + 0.8313582281132071*_x104 - 0.19441657098171689*_x105 + 0.10310710018910296*_x106 - 0.04943845883006617*_x107 + 0.01380905971521689*_x108 + 0.147790320897128*_x16 + 0.147790320897128*_x17 + 0.147790320897128*_x21 + 0.41567911405660357*_x33 + 0.41567911405660357*_x34 + 0.41567911405660357*_x37 - 0.09720828549085844*_x49 - 0.09720828549085844*_x50 - 0.09720828549085844*_x53 + 0.05155355009455148*_x65 + 0.05155355009455148*_x66 + 0.05155355009455148*_x69 - 0.024719229415033087*_x81 - 0.024719229415033087*_x82 - 0.024719229415033087*_x85 + 0.006904529857608445*_x97 + 0.006904529857608445*_x98
    _x131 = (1.0/math.sqrt(_x129))
    _x132 = _x130/_x129**(1.5)
    _x133 = _x171**2
    _x134 = _x119*_x131
    _x135 = _x123*_x131*_x32
    _x136 = _x131*_x23
    _x137 = 0.010443786721981197*_x10*_x11*_x12 + 0.25540525119175433*_x12*_x28*_x29 + 0.2685463444140672*_x12*_x44*_x45 + 0.01951903325298492*_x12*_x76*_x77 - _x128 - 0.25540525119175433*_x26 - 0.25540525119175433*_x27 - 0.2685463444140672*_x42 - 0.2685463444140672*_x43 + 0.048794612428541204*_x55*k_c + 0.048794612428541204*_x57*g_s*m - 0.048794612428541204*_x63 - 0.01951903325298492*_x74 - 0.01951903325298492*_x75 - 0.010443786721981197*_x8 + 0.005119803152246505*_x87*k_c + 0.005119803152246505*_x89*g_s*m - 0.010443786721981197*_x9 - 0.005119803152246505*_x95
    _x138 = -0.005119803152246505*_x101 + 0.020887573443962394*_x103 + 0.5108105023835087*_x104 + 0.5370926888281344*_x105 - 0.09758922485708241*_x106 + 0.03903806650596984*_x107 - 0.01023960630449301*_x108 + 0.010443786721981197*_x16 + 0.010443786721981197*_x17 + 0.010443786721981197*_x21 + 0.25540525119175433*_x33 + 0.25540525119175433*_x34 + 0.25540525119175433*_x37 + 0.2685463444140672*_x49 + 0.2685463444140672*_x50 + 0.2685463444140672*_x53 - 0.048794612428541204*_x65 - 0.048794612428541204*_x66 - 0.048794612428541204*_x69 + 0.01951903325298492*_x81 + 0.01951903325298492*_x82 + 0.01951903325298492*_x85 - 0.005119803152246505*_x97 - 0.005119803152246505*_x98
    _x139 = (1.0/math.sqrt(_x137))
    _x140 = _x138/_x137**(1.5)
    _x141 = _x172**2
    _x142 = _x119*_x139
    _x143 = _x123*_x139*_x48
    _x144 = _x139*_x39
    _x145 = -0.5*k_c*l0
    _x146 = 0.01101839635505667*_x10*_x11*_x12 + 0.0662099828438604*_x12*_x28*_x29 + 0.2671819482314443*_x12*_x44*_x45 + 0.1742495636223592*_x12*_x60*_x61 + 0.00530703852813994*_x12*_x92*_x93 - _x145 - 0.0662099828438604*_x26 - 0.0662099828438604*_x27 - 0.2671819482314443*_x42 - 0.2671819482314443*_x43 - 0.1742495636223592*_x58 - 0.1742495636223592*_x59 + 0.02396692958086051*_x71*k_c + 0.02396692958086051*_x73*g_s*m - 0.02396692958086051*_x79 - 0.01101839635505667*_x8 - 0.01101839635505667*_x9 - 0.00530703852813994*_x90 - 0.00530703852813994*_x91
    _x147 = 0.00530703852813994*_x101 + 0.02203679271011334*_x103 + 0.1324199656877208*_x104 + 0.5343638964628886*_x105 + 0.3484991272447184*_x106 - 0.04793385916172102*_x107 + 0.01061407705627988*_x108 + 0.01101839635505667*_x16 + 0.01101839635505667*_x17 + 0.01101839635505667*_x21 + 0.0662099828438604*_x33 + 0.0662099828438604*_x34 + 0.0662099828438604*_x37 + 0.2671819482314443*_x49 + 0.2671819482314443*_x50 + 0.2671819482314443*_x53 + 0.1742495636223592*_x65 + 0.1742495636223592*_x66 + 0.1742495636223592*_x69 - 0.02396692958086051*_x81 - 0.02396692958086051*_x82 - 0.02396692958086051*_x85 + 0.00530703852813994*_x97 + 0.00530703852813994*_x98
    _x148 = (1.0/math.sqrt(_x146))
    _x149 = _x147/_x146**(1.5)
    _x150 = _x173**2
    _x151 = _x119*_x148
    _x152 = _x123*_x148*_x64
    _x153 = _x148*_x55
    _x154 = 0.0025147977064533143*_x10*_x11*_x12 + 0.050345455482979015*_x12*_x28*_x29 + 0.11622097556712797*_x12*_x44*_x45 + 0.2353986790647292*_x12*_x60*_x61 + 0.10372825048336794*_x12*_x76*_x77 - _x128 - 0.050345455482979015*_x26 - 0.050345455482979015*_x27 - 0.11622097556712797*_x42 - 0.11622097556712797*_x43 - 0.2353986790647292*_x58 - 0.2353986790647292*_x59 - 0.10372825048336794*_x74 - 0.10372825048336794*_x75 - 0.0025147977064533143*_x8 + 0.008208158304657426*_x87*k_c + 0.008208158304657426*_x89*g_s*m - 0.0025147977064533143*_x9 - 0.008208158304657426*_x95
    _x155 = -0.008208158304657426*_x101 + 0.005029595412906629*_x103 + 0.10069091096595803*_x104 + 0.23244195113425595*_x105 + 0.4707973581294584*_x106 + 0.20745650096673587*_x107 - 0.016416316609314852*_x108 + 0.0025147977064533143*_x16 + 0.0025147977064533143*_x17 + 0.0025147977064533143*_x21 + 0.050345455482979015*_x33 + 0.050345455482979015*_x34 + 0.050345455482979015*_x37 + 0.11622097556712797*_x49 + 0.11622097556712797*_x50 + 0.11622097556712797*_x53 + 0.2353986790647292*_x65 + 0.2353986790647292*_x66 + 0.2353986790647292*_x69 + 0.10372825048336794*_x81 + 0.10372825048336794*_x82 + 0.10372825048336794*_x85 - 0.008208158304657426*_x97 - 0.008208158304657426*_x98
    _x156 = (1.0/math.sqrt(_x154))
    _x157 = _x155/_x154**(1.5)
    _x158 = _x174**2
    _x159 = _x119*_x156
    _x160 = _x123*_x156*_x80
    _x161 = _x156*_x71
    _x162 = 0.003959513229722528*_x10*_x11*_x12 + 0.029703284805013122*_x12*_x28*_x29 + 0.10140664131431479*_x12*_x44*_x45 + 0.14531313573962065*_x12*_x60*_x61 + 0.17612158869639333*_x12*_x76*_x77 + 0.04349583621493557*_x12*_x92*_x93 - _x145 - 0.029703284805013122*_x26 - 0.029703284805013122*_x27 - 0.10140664131431479*_x42 - 0.10140664131431479*_x43 - 0.14531313573962065*_x58 - 0.14531313573962065*_x59 - 0.17612158869639333*_x74 - 0.17612158869639333*_x75 - 0.003959513229722528*_x8 - 0.003959513229722528*_x9 - 0.04349583621493557*_x90 - 0.04349583621493557*_x91
    _x163 = 0.04349583621493557*_x101 + 0.007919026459445056*_x103 + 0.059406569610026244*_x104 + 0.20281328262862958*_x105 + 0.2906262714792413*_x106 + 0.35224317739278665*_x107 + 0.08699167242987114*_x108 + 0.003959513229722528*_x16 + 0.003959513229722528*_x17 + 0.003959513229722528*_x21 + 0.029703284805013122*_x33 + 0.029703284805013122*_x34 + 0.029703284805013122*_x37 + 0.10140664131431479*_x49 + 0.10140664131431479*_x50 + 0.10140664131431479*_x53 + 0.14531313573962065*_x65 + 0.14531313573962065*_x66 + 0.14531313573962065*_x69 + 0.17612158869639333*_x81 + 0.17612158869639333*_x82 + 0.17612158869639333*_x85 + 0.04349583621493557*_x97 + 0.04349583621493557*_x98
    _x164 = (1.0/math.sqrt(_x162))
    _x165 = _x163/_x162**(1.5)
    _x166 = _x175**2
    _x167 = _x119*_x164
    _x168 = _x123*_x164*_x96
    _x169 = _x164*_x87
    _fsigma0 = _x2
    _fsigma0__tan = _x4
    _fF0 = _x14 + _x5 - _x8 - _x9
    _fF0__tan = _x16 + _x17 + _x18*_x20 + _x21
    _fsigma1 = _x23
    _fsigma1__tan = _x24
    _fF1 = -_x26 - _x27 + _x31 + _x5
    _fF1__tan = _x18*_x36 + _x33 + _x34 + _x37
    _fsigma2 = _x39
    _fsigma2__tan = _x40
    _fF2 = -_x42 - _x43 + _x47 + _x5
    _fF2__tan = _x18*_x52 + _x49 + _x50 + _x53
    _fsigma3 = _x55
    _fsigma3__tan = _x56
    _fF3 = _x5 - _x58 - _x59 + _x63
    _fF3__tan = _x18*_x68 + _x65 + _x66 + _x69
    _fsigma4 = _x71
    _fsigma4__tan = _x72
    _fF4 = _x5 - _x74 - _x75 + _x79
    _fF4__tan = _x18*_x84 + _x81 + _x82 + _x85
    _fsigma5 = _x87
    _fsigma5__tan = _x88
    _fF5 = _x5 - _x90 - _x91 + _x95
    _fF5__tan = _x100*_x18 + _x101 + _x97 + _x98
    _fPsi0 = _x102
    _fPsi0__tan = _x109
    _fft0 = _x110*_x113
    _fft0__tan = (0.5)*_D__tan*_x110*_x112*_x114 - _x115*_x116
    _ffq0 = _P0*_x117*_x120
    _ffq0__tan = (0.5)*_D__tan*_P0*_x110*_x114*_x117*_x118 - _P0*_x116*_x117*_x121 + _P0__tan*_x110*_x111*_x117*_x118 - 2.0*_x120*_x19*_x4
    _ffp0 = _x124*_x2
    _ffp0__tan = _Q0__tan*_x123*_x125*_x6 - _x116*_x127*_x15*_x2 + _x124*_x4 + _x125*_x126*_x15
    _fPsi1 = _x129
    _fPsi1__tan = _x130
    _fft1 = _x113*_x131
    _fft1__tan = (0.5)*_D__tan*_x112*_x114*_x131 - _x115*_x132
    _ffq1 = _P1*_x133*_x134
    _ffq1__tan = (0.5)*_D__tan*_P1*_x114*_x118*_x131*_x133 - _P1*_x121*_x132*_x133 + _P1__tan*_x111*_x118*_x131*_x133 - 2.0*_x134*_x24*_x35
    _ffp1 = _x135*_x23
    _ffp1__tan = _Q1__tan*_x123*_x136*_x25 + _x126*_x136*_x32 - _x127*_x132*_x23*_x32 + _x135*_x24
    _fPsi2 = _x137
    _fPsi2__tan = _x138
    _fft2 = _x113*_x139
    _fft2__tan = (0.5)*_D__tan*_x112*_x114*_x139 - _x115*_x140
    _ffq2 = _P2*_x141*_x142
    _ffq2__tan = (0.5)*_D__tan*_P2*_x114*_x118*_x139*_x141 - _P2*_x121*_x140*_x141 + _P2__tan*_x111*_x118*_x139*_x141 - 2.0*_x142*_x40*_x51
    _ffp2 = _x143*_x39
    _ffp2__tan = _Q2__tan*_x123*_x144*_x41 + _x126*_x144*_x48 - _x127*_x140*_x39*_x48 + _x143*_x40
    _fPsi3 = _x146
    _fPsi3__tan = _x147
    _fft3 = _x113*_x148
    _fft3__tan = (0.5)*_D__tan*_x112*_x114*_x148 - _x115*_x149
    _ffq3 = _P3*_x150*_x151
    _ffq3__tan = (0.5)*_D__tan*_P3*_x114*_x118*_x148*_x150 - _P3*_x121*_x149*_x150 + _P3__tan*_x111*_x118*_x148*_x150 - 2.0*_x151*_x56*_x67
    _ffp3 = _x152*_x55
    _ffp3__tan = _Q3__tan*_x123*_x153*_x57 + _x126*_x153*_x64 - _x127*_x149*_x55*_x64 + _x152*_x56
    _fPsi4 = _x154
    _fPsi4__tan = _x155
    _fft4 = _x113*_x156
    _fft4__tan = (0.5)*_D__tan*_x112*_x114*_x156 - _x115*_x157
    _ffq4 = _P4*_x158*_x159
    _ffq4__tan = (0.5)*_D__tan*_P4*_x114*_x118*_x156*_x158 - _P4*_x121*_x157*_x158 + _P4__tan*_x111*_x118*_x156*_x158 - 2.0*_x159*_x72*_x83
    _ffp4 = _x160*_x71
    _ffp4__tan = _Q4__tan*_x123*_x161*_x73 + _x126*_x161*_x80 - _x127*_x157*_x71*_x80 + _x160*_x72
    _fPsi5 = _x162
    _fPsi5__tan = _x163
    _fft5 = _x113*_x164
    _fft5__tan = (0.5)*_D__tan*_x112*_x114*_x164 - _x115*_x165
    _ffq5 = _P5*_x166*_x167
    _ffq5__tan = (0.5)*_D__tan*_P5*_x114*_x118*_x164*_x166 - _P5*_x121*_x165*_x166 + _P5__tan*_x111*_x118*_x164*_x166 - 2.0*_x167*_x88*_x99
    _ffp5 = _x168*_x87
    _ffp5__tan = _Q5__tan*_x123*_x169*_x89 + _x126*_x169*_x96 - _x127*_x165*_x87*_x96 + _x168*_x88
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi3 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi4 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi5 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # bottom state
    _x176 = -_D + q_r
    _x186 = (1.0/_x176)
    _x177 = -_D__tan + q_r__tan
    _x178 = q_r**2
    _x179 = 0.08566224618958518*_ffp0 + 0.1803807865240693*_ffp1 + 0.23395696728634552*_ffp2 + 0.23395696728634552*_ffp3 + 0.1803807865240693*_ffp4 + 0.08566224618958518*_ffp5 + _x178*m*q_thd
    _x180 = (1.0/m)
    _x181 = _x186**2
    _x182 = _x180*_x181
    _x183 = 0.08566224618958518*_x182
    _x184 = 0.1803807865240693*_x182
    _x185 = 0.23395696728634552*_x182
    t_half = 0.08566224618958518*_fft0 + 0.1803807865240693*_fft1 + 0.23395696728634552*_fft2 + 0.23395696728634552*_fft3 + 0.1803807865240693*_fft4 + 0.08566224618958518*_fft5
    t_half__tan = 0.08566224618958518*_fft0__tan + 0.1803807865240693*_fft1__tan + 0.23395696728634552*_fft2__tan + 0.23395696728634552*_fft3__tan + 0.1803807865240693*_fft4__tan + 0.08566224618958518*_fft5__tan
    end_q_th = 0.08566224618958518*_ffq0 + 0.1803807865240693*_ffq1 + 0.23395696728634552*_ffq2 + 0.23395696728634552*_ffq3 + 0.1803807865240693*_ffq4 + 0.08566224618958518*_ffq5 + q_th
    end_q_th__tan = 0.08566224618958518*_ffq0__tan + 0.1803807865240693*_ffq1__tan + 0.23395696728634552*_ffq2__tan + 0.23395696728634552*_ffq3__tan + 0.1803807865240693*_ffq4__tan + 0.08566224618958518*_ffq5__tan + q_th__tan
    end_q_r = _x176
    end_q_r__tan = _x177
    end_q_rd = 0.0
    end_q_thd = _x179*_x182
    end_q_thd__tan = _ffp0__tan*_x183 + _ffp1__tan*_x184 + _ffp2__tan*_x185 + _ffp3__tan*_x185 + _ffp4__tan*_x184 + _ffp5__tan*_x183 - 2.0*_x177*_x179*_x180*_x186**3 + _x178*_x181*q_thd__tan + 2.0*_x181*q_r*q_r__tan*q_thd
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_14(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 4 of schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_r: value of the caller's variable
        guess_q_r__tan: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_c: value of the caller's variable
        k_c__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_rd: value of the caller's variable
        q_rd__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_r__tan: result for the caller
        end_q_rd: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 6 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.966234757101576*guess_q_th + 0.03376524289842399*q_th
    _Q1 = 0.8306046932331322*guess_q_th + 0.16939530676686773*q_th
    _Q2 = 0.6193095930415985*guess_q_th + 0.38069040695840156*q_th
    _Q3 = 0.38069040695840156*guess_q_th + 0.6193095930415985*q_th
    _Q4 = 0.16939530676686773*guess_q_th + 0.8306046932331322*q_th
    _Q5 = 0.03376524289842399*guess_q_th + 0.966234757101576*q_th
    _P0 = 0.966234757101576*guess_q_r**2*guess_q_thd*m + 0.03376524289842399*m*q_r**2*q_thd
    _P1 = 0.8306046932331322*guess_q_r**2*guess_q_thd*m + 0.16939530676686773*m*q_r**2*q_thd
    _P2 = 0.6193095930415985*guess_q_r**2*guess_q_thd*m + 0.38069040695840156*m*q_r**2*q_thd
    _P3 = 0.38069040695840156*guess_q_r**2*guess_q_thd*m + 0.6193095930415985*m*q_r**2*q_thd
    _P4 = 0.16939530676686773*guess_q_r**2*guess_q_thd*m + 0.8306046932331322*m*q_r**2*q_thd
    _P5 = 0.03376524289842399*guess_q_r**2*guess_q_thd*m + 0.966234757101576*m*q_r**2*q_thd
    _D__tan = -guess_q_r__tan + q_r__tan
    _Q0__tan = 0.966234757101576*guess_q_th__tan + 0.03376524289842399*q_th__tan
    _Q1__tan = 0.8306046932331322*guess_q_th__tan + 0.16939530676686773*q_th__tan
    _Q2__tan = 0.6193095930415985*guess_q_th__tan + 0.38069040695840156*q_th__tan
    _Q3__tan = 0.38069040695840156*guess_q_th__tan + 0.6193095930415985*q_th__tan
    _Q4__tan = 0.16939530676686773*guess_q_th__tan + 0.8306046932331322*q_th__tan
    _Q5__tan = 0.03376524289842399*guess_q_th__tan + 0.966234757101576*q_th__tan
    _P0__tan = 0.966234757101576*guess_q_r**2*guess_q_thd__tan*m + 1.932469514203152*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.03376524289842399*m*q_r**2*q_thd__tan + 0.06753048579684798*m*q_r*q_r__tan*q_thd
    _P1__tan = 0.8306046932331322*guess_q_r**2*guess_q_thd__tan*m + 1.6612093864662645*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.16939530676686773*m*q_r**2*q_thd__tan + 0.33879061353373546*m*q_r*q_r__tan*q_thd
    _P2__tan = 0.6193095930415985*guess_q_r**2*guess_q_thd__tan*m + 1.238619186083197*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.38069040695840156*m*q_r**2*q_thd__tan + 0.7613808139168031*m*q_r*q_r__tan*q_thd
    _P3__tan = 0.38069040695840156*guess_q_r**2*guess_q_thd__tan*m + 0.7613808139168031*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.6193095930415985*m*q_r**2*q_thd__tan + 1.238619186083197*m*q_r*q_r__tan*q_thd
    _P4__tan = 0.16939530676686773*guess_q_r**2*guess_q_thd__tan*m + 0.33879061353373546*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.8306046932331322*m*q_r**2*q_thd__tan + 1.6612093864662645*m*q_r*q_r__tan*q_thd
    _P5__tan = 0.03376524289842399*guess_q_r**2*guess_q_thd__tan*m + 0.06753048579684798*guess_q_r*guess_q_r__tan*guess_q_thd*m + 0.966234757101576*m*q_r**2*q_thd__tan + 1.932469514203152*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_12(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _P4, _P4__tan, _P5, _P5__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _Q4, _Q4__tan, _Q5, _Q5__tan, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[26] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[26])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_Q1 = _c0[2]
        _next_Q2 = _c0[3]
        _next_Q3 = _c0[4]
        _next_Q4 = _c0[5]
        _next_Q5 = _c0[6]
        _next_P0 = _c0[7]
        _next_P1 = _c0[8]
        _next_P2 = _c0[9]
        _next_P3 = _c0[10]
        _next_P4 = _c0[11]
        _next_P5 = _c0[12]
        _next_D__tan = _c0[13]
        _next_Q0__tan = _c0[14]
        _next_Q1__tan = _c0[15]
        _next_Q2__tan = _c0[16]
        _next_Q3__tan = _c0[17]
        _next_Q4__tan = _c0[18]
        _next_Q5__tan = _c0[19]
        _next_P0__tan = _c0[20]
        _next_P1__tan = _c0[21]
        _next_P2__tan = _c0[22]
        _next_P3__tan = _c0[23]
        _next_P4__tan = _c0[24]
        _next_P5__tan = _c0[25]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_Q1
        _n0_3 = _next_Q2
        _n0_4 = _next_Q3
        _n0_5 = _next_Q4
        _n0_6 = _next_Q5
        _n0_7 = _next_P0
        _n0_8 = _next_P1
        _n0_9 = _next_P2
        _n0_10 = _next_P3
        _n0_11 = _next_P4
        _n0_12 = _next_P5
        _n0_13 = _next_D__tan
        _n0_14 = _next_Q0__tan
        _n0_15 = _next_Q1__tan
        _n0_16 = _next_Q2__tan
        _n0_17 = _next_Q3__tan
        _n0_18 = _next_Q4__tan
        _n0_19 = _next_Q5__tan
        _n0_20 = _next_P0__tan
        _n0_21 = _next_P1__tan
        _n0_22 = _next_P2__tan
        _n0_23 = _next_P3__tan
        _n0_24 = _next_P4__tan
        _n0_25 = _next_P5__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3) <= tol*(1.0)) and (abs(_n0_5 - _Q4) <= tol*(1.0)) and (abs(_n0_6 - _Q5) <= tol*(1.0)) and (abs(_n0_7 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_9 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_10 - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_11 - _P4) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_12 - _P5) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _Q4 = _n0_5
        _Q5 = _n0_6
        _P0 = _n0_7
        _P1 = _n0_8
        _P2 = _n0_9
        _P3 = _n0_10
        _P4 = _n0_11
        _P5 = _n0_12
        _D__tan = _n0_13
        _Q0__tan = _n0_14
        _Q1__tan = _n0_15
        _Q2__tan = _n0_16
        _Q3__tan = _n0_17
        _Q4__tan = _n0_18
        _Q5__tan = _n0_19
        _P0__tan = _n0_20
        _P1__tan = _n0_21
        _P2__tan = _n0_22
        _P3__tan = _n0_23
        _P4__tan = _n0_24
        _P5__tan = _n0_25
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_13(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _P4, _P4__tan, _P5, _P5__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _Q4, _Q4__tan, _Q5, _Q5__tan, _passes, g_s, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[22])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    t_half = _c1[12]
    t_half__tan = _c1[13]
    end_q_th = _c1[14]
    end_q_th__tan = _c1[15]
    end_q_r = _c1[16]
    end_q_r__tan = _c1[17]
    end_q_rd = _c1[18]
    end_q_thd = _c1[19]
    end_q_thd__tan = _c1[20]
    passes = _c1[21]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_r__tan, end_q_rd, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th, guess_q_thd, nodes, iterations, tol, q_r__tan, q_rd__tan, q_th__tan, q_thd__tan, k_c__tan, guess_q_r__tan, guess_q_th__tan, guess_q_thd__tan):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of p_r), with the derivative of every output along the direction (q_r__tan, q_rd__tan, q_th__tan, q_thd__tan, k_c__tan, guess_q_r__tan, guess_q_th__tan, guess_q_thd__tan).

    Report equations: 115, 116, 117, 118, 123.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        q_r: touchdown state: leg length [m]
        q_rd: touchdown state: leg length rate [m/s]
        q_th: touchdown state: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: touchdown state: leg angle rate [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        guess_q_r: zeroth iterate's bottom q_r
        guess_q_th: zeroth iterate's bottom q_th
        guess_q_thd: zeroth iterate's bottom q_thd
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]
        q_r__tan: direction: its component along q_r
        q_rd__tan: direction: its component along q_rd
        q_th__tan: direction: its component along q_th
        q_thd__tan: direction: its component along q_thd
        k_c__tan: direction: its component along k_c
        guess_q_r__tan: direction: its component along guess_q_r
        guess_q_th__tan: direction: its component along guess_q_th
        guess_q_thd__tan: direction: its component along guess_q_thd

    Returns a tuple:
        t_half: time of the compression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        t_half__tan: derivative of t_half along the direction
        end_q_r__tan: derivative of end_q_r along the direction
        end_q_rd__tan: derivative of end_q_rd along the direction
        end_q_th__tan: derivative of end_q_th along the direction
        end_q_thd__tan: derivative of end_q_thd along the direction
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s) and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(q_r__tan) and math.isfinite(q_rd__tan) and math.isfinite(q_th__tan) and math.isfinite(q_thd__tan) and math.isfinite(k_c__tan) and math.isfinite(guess_q_r__tan) and math.isfinite(guess_q_th__tan) and math.isfinite(guess_q_thd__tan) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # node count
    if nodes == 0.0:
        # branch nodes = 0
        _c0 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_2(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c0[29] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[29])
        _D = _c0[0]
        _Q0 = _c0[1]
        _P0 = _c0[2]
        _D__tan = _c0[3]
        _Q0__tan = _c0[4]
        _P0__tan = _c0[5]
        _passes = _c0[6]
        _fsigma0 = _c0[7]
        _fsigma0__tan = _c0[8]
        _fF0 = _c0[9]
        _fF0__tan = _c0[10]
        _fPsi0 = _c0[11]
        _fPsi0__tan = _c0[12]
        _fft0 = _c0[13]
        _fft0__tan = _c0[14]
        _ffq0 = _c0[15]
        _ffq0__tan = _c0[16]
        _ffp0 = _c0[17]
        _ffp0__tan = _c0[18]
        t_half = _c0[19]
        t_half__tan = _c0[20]
        end_q_th = _c0[21]
        end_q_th__tan = _c0[22]
        end_q_r = _c0[23]
        end_q_r__tan = _c0[24]
        end_q_rd = _c0[25]
        end_q_thd = _c0[26]
        end_q_thd__tan = _c0[27]
        passes = _c0[28]
    elif nodes == 1.0:
        # branch nodes = 1
        _c1 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_5(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c1[29] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[29])
        _D = _c1[0]
        _Q0 = _c1[1]
        _P0 = _c1[2]
        _D__tan = _c1[3]
        _Q0__tan = _c1[4]
        _P0__tan = _c1[5]
        _passes = _c1[6]
        _fsigma0 = _c1[7]
        _fsigma0__tan = _c1[8]
        _fF0 = _c1[9]
        _fF0__tan = _c1[10]
        _fPsi0 = _c1[11]
        _fPsi0__tan = _c1[12]
        _fft0 = _c1[13]
        _fft0__tan = _c1[14]
        _ffq0 = _c1[15]
        _ffq0__tan = _c1[16]
        _ffp0 = _c1[17]
        _ffp0__tan = _c1[18]
        t_half = _c1[19]
        t_half__tan = _c1[20]
        end_q_th = _c1[21]
        end_q_th__tan = _c1[22]
        end_q_r = _c1[23]
        end_q_r__tan = _c1[24]
        end_q_rd = _c1[25]
        end_q_thd = _c1[26]
        end_q_thd__tan = _c1[27]
        passes = _c1[28]
    elif nodes == 2.0:
        # branch nodes = 2
        _c2 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_8(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c2[29] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[29])
        _D = _c2[0]
        _Q0 = _c2[1]
        _P0 = _c2[2]
        _D__tan = _c2[3]
        _Q0__tan = _c2[4]
        _P0__tan = _c2[5]
        _passes = _c2[6]
        _fsigma0 = _c2[7]
        _fsigma0__tan = _c2[8]
        _fF0 = _c2[9]
        _fF0__tan = _c2[10]
        _fPsi0 = _c2[11]
        _fPsi0__tan = _c2[12]
        _fft0 = _c2[13]
        _fft0__tan = _c2[14]
        _ffq0 = _c2[15]
        _ffq0__tan = _c2[16]
        _ffp0 = _c2[17]
        _ffp0__tan = _c2[18]
        t_half = _c2[19]
        t_half__tan = _c2[20]
        end_q_th = _c2[21]
        end_q_th__tan = _c2[22]
        end_q_r = _c2[23]
        end_q_r__tan = _c2[24]
        end_q_rd = _c2[25]
        end_q_thd = _c2[26]
        end_q_thd__tan = _c2[27]
        passes = _c2[28]
    elif nodes == 3.0:
        # branch nodes = 3
        _c3 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_11(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c3[29] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[29])
        _D = _c3[0]
        _Q0 = _c3[1]
        _P0 = _c3[2]
        _D__tan = _c3[3]
        _Q0__tan = _c3[4]
        _P0__tan = _c3[5]
        _passes = _c3[6]
        _fsigma0 = _c3[7]
        _fsigma0__tan = _c3[8]
        _fF0 = _c3[9]
        _fF0__tan = _c3[10]
        _fPsi0 = _c3[11]
        _fPsi0__tan = _c3[12]
        _fft0 = _c3[13]
        _fft0__tan = _c3[14]
        _ffq0 = _c3[15]
        _ffq0__tan = _c3[16]
        _ffp0 = _c3[17]
        _ffp0__tan = _c3[18]
        t_half = _c3[19]
        t_half__tan = _c3[20]
        end_q_th = _c3[21]
        end_q_th__tan = _c3[22]
        end_q_r = _c3[23]
        end_q_r__tan = _c3[24]
        end_q_rd = _c3[25]
        end_q_thd = _c3[26]
        end_q_thd__tan = _c3[27]
        passes = _c3[28]
    elif nodes == 4.0:
        # branch nodes = 4
        _c4 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd_14(g_s, guess_q_r, guess_q_r__tan, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_c, k_c__tan, l0, m, q_r, q_r__tan, q_rd, q_rd__tan, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c4[29] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[29])
        _D = _c4[0]
        _Q0 = _c4[1]
        _P0 = _c4[2]
        _D__tan = _c4[3]
        _Q0__tan = _c4[4]
        _P0__tan = _c4[5]
        _passes = _c4[6]
        _fsigma0 = _c4[7]
        _fsigma0__tan = _c4[8]
        _fF0 = _c4[9]
        _fF0__tan = _c4[10]
        _fPsi0 = _c4[11]
        _fPsi0__tan = _c4[12]
        _fft0 = _c4[13]
        _fft0__tan = _c4[14]
        _ffq0 = _c4[15]
        _ffq0__tan = _c4[16]
        _ffp0 = _c4[17]
        _ffp0__tan = _c4[18]
        t_half = _c4[19]
        t_half__tan = _c4[20]
        end_q_th = _c4[21]
        end_q_th__tan = _c4[22]
        end_q_r = _c4[23]
        end_q_r__tan = _c4[24]
        end_q_rd = _c4[25]
        end_q_thd = _c4[26]
        end_q_thd__tan = _c4[27]
        passes = _c4[28]
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives that are identically zero
    end_q_rd__tan = 0.0
    passes__tan = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, t_half__tan, end_q_r__tan, end_q_rd__tan, end_q_th__tan, end_q_thd__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_0(_D, _D__tan, _P0, _P0__tan, _Q0, _Q0__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_P0: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_P0__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 134
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.25*_D + q_r
    _x33 = (1.0/_x0)
    _x1 = 0.25*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x33**3
    _x8 = (1.0/m)
    _x9 = _P0**2*_x8
    _x10 = _x7*_x9
    _x11 = math.sin(_Q0)
    _x12 = _Q0__tan*_x11*_x4
    _x13 = k_d__tan*(-_x0 + l0)
    _x14 = 2.0*_P0*_x7
    _x15 = _P0__tan*_x8
    _x16 = _x1*(-3.0*_x33**4*_x9 - k_d)
    _x17 = 0.5*_x10 + 0.5*_x2 - 0.5*_x5 - 0.5*_x6
    _x18 = 1.0*_P0*_x15*_x7 + 0.5*_x12 + 0.5*_x13 + 0.5*_x16
    _x19 = math.sqrt(_D)
    _x20 = math.sqrt(m)
    _x21 = (1.0/math.sqrt(_x17))
    _x22 = (1.0/_x19)
    _x23 = (0.5)*_x18*_x19/_x17**(1.5)
    _x24 = (1.0/_x20)
    _x25 = _x19*_x21
    _x26 = _x24*_x25
    _x27 = _x33**2
    _x28 = _P0*_x27
    _x29 = m**(1.5)
    _x30 = _x11*_x25*_x29*g_s
    _x31 = _x0*_x29*g_s
    _x32 = _x11*_x31
    _isigma0 = _x0
    _isigma0__tan = _x1
    _iF0 = _x10 + _x2 - _x5 - _x6
    _iF0__tan = _x12 + _x13 + _x14*_x15 + _x16
    _iPsi0 = _x17
    _iPsi0__tan = _x18
    _ift0 = _x19*_x20*_x21
    _ift0__tan = (0.5)*_D__tan*_x20*_x21*_x22 - _x20*_x23
    _ifq0 = _x26*_x28
    _ifq0__tan = (0.5)*_D__tan*_P0*_x21*_x22*_x24*_x27 + _P0__tan*_x19*_x21*_x24*_x27 - _x1*_x14*_x26 - _x23*_x24*_x28
    _ifp0 = _x0*_x30
    _ifp0__tan = (0.5)*_D__tan*_x21*_x22*_x32 + _Q0__tan*_x25*_x3*_x31 + _x1*_x30 - _x23*_x32
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x34 = m*q_r**2
    _next_D = _D
    _next_Q0 = 0.5*_ifq0 + q_th
    _next_P0 = 0.5*_ifp0 + _x34*q_thd
    _next_D__tan = _D__tan
    _next_Q0__tan = 0.5*_ifq0__tan + q_th__tan
    _next_P0__tan = 0.5*_ifp0__tan + _x34*q_thd__tan + 2.0*m*q_r*q_r__tan*q_thd
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_P0, _next_D__tan, _next_Q0__tan, _next_P0__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_1(_D, _D__tan, _P0, _P0__tan, _Q0, _Q0__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 156
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.25*_D + q_r
    _x33 = (1.0/_x0)
    _x1 = 0.25*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x33**3
    _x8 = (1.0/m)
    _x9 = _P0**2*_x8
    _x10 = _x7*_x9
    _x11 = math.sin(_Q0)
    _x12 = _Q0__tan*_x11*_x4
    _x13 = k_d__tan*(-_x0 + l0)
    _x14 = 2.0*_P0*_x7
    _x15 = _P0__tan*_x8
    _x16 = _x1*(-3.0*_x33**4*_x9 - k_d)
    _x17 = 0.5*_x10 + 0.5*_x2 - 0.5*_x5 - 0.5*_x6
    _x18 = 1.0*_P0*_x15*_x7 + 0.5*_x12 + 0.5*_x13 + 0.5*_x16
    _x19 = math.sqrt(_D)
    _x20 = math.sqrt(m)
    _x21 = (1.0/math.sqrt(_x17))
    _x22 = (1.0/_x19)
    _x23 = (0.5)*_x18*_x19/_x17**(1.5)
    _x24 = (1.0/_x20)
    _x25 = _x19*_x21
    _x26 = _x24*_x25
    _x27 = _x33**2
    _x28 = _P0*_x27
    _x29 = m**(1.5)
    _x30 = _x11*_x25*_x29*g_s
    _x31 = _x0*_x29*g_s
    _x32 = _x11*_x31
    _fsigma0 = _x0
    _fsigma0__tan = _x1
    _fF0 = _x10 + _x2 - _x5 - _x6
    _fF0__tan = _x12 + _x13 + _x14*_x15 + _x16
    _fPsi0 = _x17
    _fPsi0__tan = _x18
    _fft0 = _x19*_x20*_x21
    _fft0__tan = (0.5)*_D__tan*_x20*_x21*_x22 - _x20*_x23
    _ffq0 = _x26*_x28
    _ffq0__tan = (0.5)*_D__tan*_P0*_x21*_x22*_x24*_x27 + _P0__tan*_x19*_x21*_x24*_x27 - _x1*_x14*_x26 - _x23*_x24*_x28
    _ffp0 = _x0*_x30
    _ffp0__tan = (0.5)*_D__tan*_x21*_x22*_x32 + _Q0__tan*_x25*_x3*_x31 + _x1*_x30 - _x23*_x32
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    _work = 0.5*_fF0
    _work__tan = 0.5*_fF0__tan
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    _x34 = math.sqrt(_D*_work)/math.sqrt(m)
    _x35 = q_r**2
    _x36 = q_r_lo**-2
    _x37 = _x36/m
    t_half = 1.0*_fft0
    t_half__tan = 1.0*_fft0__tan
    end_q_th = 1.0*_ffq0 + q_th
    end_q_th__tan = 1.0*_ffq0__tan + q_th__tan
    end_q_r = q_r_lo
    end_q_rd = 2.0*_x34
    end_q_rd__tan = _work__tan*_x34/_work + _D__tan*_x34/_D
    end_q_thd = _x37*(1.0*_ffp0 + _x35*m*q_thd)
    end_q_thd__tan = 1.0*_ffp0__tan*_x37 + _x35*_x36*q_thd__tan + 2.0*_x36*q_r*q_r__tan*q_thd
    passes = _passes
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_2(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 0 of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 1 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.5*guess_q_th + 0.5*q_th
    _P0 = 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd
    _D__tan = -q_r__tan
    _Q0__tan = 0.5*guess_q_th__tan + 0.5*q_th__tan
    _P0__tan = 0.5*guess_q_thd__tan*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd__tan + 1.0*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_0(_D, _D__tan, _P0, _P0__tan, _Q0, _Q0__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[6] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[6])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_P0 = _c0[2]
        _next_D__tan = _c0[3]
        _next_Q0__tan = _c0[4]
        _next_P0__tan = _c0[5]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_P0
        _n0_3 = _next_D__tan
        _n0_4 = _next_Q0__tan
        _n0_5 = _next_P0__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _P0 = _n0_2
        _D__tan = _n0_3
        _Q0__tan = _n0_4
        _P0__tan = _n0_5
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_1(_D, _D__tan, _P0, _P0__tan, _Q0, _Q0__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[24])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    _work = _c1[12]
    _work__tan = _c1[13]
    t_half = _c1[14]
    t_half__tan = _c1[15]
    end_q_th = _c1[16]
    end_q_th__tan = _c1[17]
    end_q_r = _c1[18]
    end_q_rd = _c1[19]
    end_q_rd__tan = _c1[20]
    end_q_thd = _c1[21]
    end_q_thd__tan = _c1[22]
    passes = _c1[23]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_3(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_Q1: result for the caller
        _next_P0: result for the caller
        _next_P1: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_Q1__tan: result for the caller
        _next_P0__tan: result for the caller
        _next_P1__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 297
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.04465819873852045*_D + q_r
    _x65 = (1.0/_x0)
    _x1 = 0.04465819873852045*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x65**3
    _x8 = _P0**2
    _x9 = (1.0/m)
    _x10 = _x8*_x9
    _x11 = _x10*_x7
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x4
    _x14 = -l0
    _x15 = k_d__tan*(-_x0 - _x14)
    _x16 = 2.0*_x9
    _x17 = _P0*_x7
    _x18 = _P0__tan*_x17
    _x19 = _x1*(-3.0*_x10*_x65**4 - k_d)
    _x20 = 0.6220084679281462*_D + q_r
    _x66 = (1.0/_x20)
    _x21 = 0.6220084679281462*_D__tan + q_r__tan
    _x22 = math.cos(_Q1)
    _x23 = _x22*_x4
    _x24 = _x20*k_d
    _x25 = _x66**3
    _x26 = _P1**2
    _x27 = _x26*_x9
    _x28 = _x25*_x27
    _x29 = math.sin(_Q1)
    _x30 = _Q1__tan*_x29*_x4
    _x31 = k_d__tan*(-_x14 - _x20)
    _x32 = _P1*_x25
    _x33 = _P1__tan*_x32
    _x34 = _x21*(-3.0*_x27*_x66**4 - k_d)
    _x35 = 0.5610042339640731*_x11 + 0.5*_x2 + 0.06100423396407311*_x23 + 0.06100423396407311*_x24 - 0.06100423396407311*_x28 - 0.5610042339640731*_x5 - 0.5610042339640731*_x6
    _x36 = _x18*_x9
    _x37 = _x33*_x9
    _x38 = 0.5610042339640731*_x13 + 0.5610042339640731*_x15 + 0.5610042339640731*_x19 - 0.06100423396407311*_x30 - 0.06100423396407311*_x31 - 0.06100423396407311*_x34 + 1.1220084679281461*_x36 - 0.12200846792814622*_x37
    _x39 = (1.0/math.sqrt(_x35))
    _x40 = math.sqrt(_D)
    _x41 = math.sqrt(m)
    _x42 = _x40*_x41
    _x43 = (1.0/_x40)
    _x44 = (0.5)*_x42
    _x45 = _x38/_x35**(1.5)
    _x46 = _x65**2
    _x47 = (1.0/_x41)
    _x48 = _x40*_x47
    _x49 = _x39*_x48
    _x50 = (0.5)*_x48
    _x51 = g_s*m**(1.5)
    _x52 = _x40*_x51
    _x53 = _x12*_x39*_x52
    _x54 = _x0*_x39
    _x55 = (0.5)*_D__tan*_x43*_x51
    _x56 = (0.5)*_x52
    _x57 = -0.27232909936926025*_x23 - 0.27232909936926025*_x24 + 0.27232909936926025*_x25*_x26*_x9 - 0.22767090063073978*_x5 - 0.22767090063073978*_x6 + 0.22767090063073978*_x7*_x8*_x9 + 0.5*k_d*l0
    _x58 = 0.22767090063073978*_x13 + 0.22767090063073978*_x15 + 0.22767090063073978*_x19 + 0.27232909936926025*_x30 + 0.27232909936926025*_x31 + 0.27232909936926025*_x34 + 0.45534180126147955*_x36 + 0.5446581987385205*_x37
    _x59 = (1.0/math.sqrt(_x57))
    _x60 = _x58/_x57**(1.5)
    _x61 = _x66**2
    _x62 = _x48*_x59
    _x63 = _x29*_x52*_x59
    _x64 = _x20*_x59
    _isigma0 = _x0
    _isigma0__tan = _x1
    _iF0 = _x11 + _x2 - _x5 - _x6
    _iF0__tan = _x13 + _x15 + _x16*_x18 + _x19
    _isigma1 = _x20
    _isigma1__tan = _x21
    _iF1 = _x2 - _x23 - _x24 + _x28
    _iF1__tan = _x16*_x33 + _x30 + _x31 + _x34
    _iPsi0 = _x35
    _iPsi0__tan = _x38
    _ift0 = _x39*_x42
    _ift0__tan = (0.5)*_D__tan*_x39*_x41*_x43 - _x44*_x45
    _ifq0 = _P0*_x46*_x49
    _ifq0__tan = (0.5)*_D__tan*_P0*_x39*_x43*_x46*_x47 - _P0*_x45*_x46*_x50 + _P0__tan*_x39*_x40*_x46*_x47 - 2.0*_x1*_x17*_x49
    _ifp0 = _x0*_x53
    _ifp0__tan = _Q0__tan*_x3*_x52*_x54 - _x0*_x12*_x45*_x56 + _x1*_x53 + _x12*_x54*_x55
    _iPsi1 = _x57
    _iPsi1__tan = _x58
    _ift1 = _x42*_x59
    _ift1__tan = (0.5)*_D__tan*_x41*_x43*_x59 - _x44*_x60
    _ifq1 = _P1*_x61*_x62
    _ifq1__tan = (0.5)*_D__tan*_P1*_x43*_x47*_x59*_x61 - _P1*_x50*_x60*_x61 + _P1__tan*_x40*_x47*_x59*_x61 - 2.0*_x21*_x32*_x62
    _ifp1 = _x20*_x63
    _ifp1__tan = _Q1__tan*_x22*_x52*_x64 - _x20*_x29*_x56*_x60 + _x21*_x63 + _x29*_x55*_x64
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x67 = m*q_r**2
    _x68 = _x67*q_thd
    _x69 = _x67*q_thd__tan + 2.0*m*q_r*q_r__tan*q_thd
    _next_D = _D
    _next_Q0 = 0.25*_ifq0 - 0.03867513459481288*_ifq1 + q_th
    _next_Q1 = 0.5386751345948129*_ifq0 + 0.25*_ifq1 + q_th
    _next_P0 = 0.25*_ifp0 - 0.03867513459481288*_ifp1 + _x68
    _next_P1 = 0.5386751345948129*_ifp0 + 0.25*_ifp1 + _x68
    _next_D__tan = _D__tan
    _next_Q0__tan = 0.25*_ifq0__tan - 0.03867513459481288*_ifq1__tan + q_th__tan
    _next_Q1__tan = 0.5386751345948129*_ifq0__tan + 0.25*_ifq1__tan + q_th__tan
    _next_P0__tan = 0.25*_ifp0__tan - 0.03867513459481288*_ifp1__tan + _x69
    _next_P1__tan = 0.5386751345948129*_ifp0__tan + 0.25*_ifp1__tan + _x69
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_Q1, _next_P0, _next_P1, _next_D__tan, _next_Q0__tan, _next_Q1__tan, _next_P0__tan, _next_P1__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_4(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 311
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.04465819873852045*_D + q_r
    _x65 = (1.0/_x0)
    _x1 = 0.04465819873852045*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x65**3
    _x8 = _P0**2
    _x9 = (1.0/m)
    _x10 = _x8*_x9
    _x11 = _x10*_x7
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x4
    _x14 = -l0
    _x15 = k_d__tan*(-_x0 - _x14)
    _x16 = 2.0*_x9
    _x17 = _P0*_x7
    _x18 = _P0__tan*_x17
    _x19 = _x1*(-3.0*_x10*_x65**4 - k_d)
    _x20 = 0.6220084679281462*_D + q_r
    _x66 = (1.0/_x20)
    _x21 = 0.6220084679281462*_D__tan + q_r__tan
    _x22 = math.cos(_Q1)
    _x23 = _x22*_x4
    _x24 = _x20*k_d
    _x25 = _x66**3
    _x26 = _P1**2
    _x27 = _x26*_x9
    _x28 = _x25*_x27
    _x29 = math.sin(_Q1)
    _x30 = _Q1__tan*_x29*_x4
    _x31 = k_d__tan*(-_x14 - _x20)
    _x32 = _P1*_x25
    _x33 = _P1__tan*_x32
    _x34 = _x21*(-3.0*_x27*_x66**4 - k_d)
    _x35 = 0.5610042339640731*_x11 + 0.5*_x2 + 0.06100423396407311*_x23 + 0.06100423396407311*_x24 - 0.06100423396407311*_x28 - 0.5610042339640731*_x5 - 0.5610042339640731*_x6
    _x36 = _x18*_x9
    _x37 = _x33*_x9
    _x38 = 0.5610042339640731*_x13 + 0.5610042339640731*_x15 + 0.5610042339640731*_x19 - 0.06100423396407311*_x30 - 0.06100423396407311*_x31 - 0.06100423396407311*_x34 + 1.1220084679281461*_x36 - 0.12200846792814622*_x37
    _x39 = (1.0/math.sqrt(_x35))
    _x40 = math.sqrt(_D)
    _x41 = math.sqrt(m)
    _x42 = _x40*_x41
    _x43 = (1.0/_x40)
    _x44 = (0.5)*_x42
    _x45 = _x38/_x35**(1.5)
    _x46 = _x65**2
    _x47 = (1.0/_x41)
    _x48 = _x40*_x47
    _x49 = _x39*_x48
    _x50 = (0.5)*_x48
    _x51 = g_s*m**(1.5)
    _x52 = _x40*_x51
    _x53 = _x12*_x39*_x52
    _x54 = _x0*_x39
    _x55 = (0.5)*_D__tan*_x43*_x51
    _x56 = (0.5)*_x52
    _x57 = -0.27232909936926025*_x23 - 0.27232909936926025*_x24 + 0.27232909936926025*_x25*_x26*_x9 - 0.22767090063073978*_x5 - 0.22767090063073978*_x6 + 0.22767090063073978*_x7*_x8*_x9 + 0.5*k_d*l0
    _x58 = 0.22767090063073978*_x13 + 0.22767090063073978*_x15 + 0.22767090063073978*_x19 + 0.27232909936926025*_x30 + 0.27232909936926025*_x31 + 0.27232909936926025*_x34 + 0.45534180126147955*_x36 + 0.5446581987385205*_x37
    _x59 = (1.0/math.sqrt(_x57))
    _x60 = _x58/_x57**(1.5)
    _x61 = _x66**2
    _x62 = _x48*_x59
    _x63 = _x29*_x52*_x59
    _x64 = _x20*_x59
    _fsigma0 = _x0
    _fsigma0__tan = _x1
    _fF0 = _x11 + _x2 - _x5 - _x6
    _fF0__tan = _x13 + _x15 + _x16*_x18 + _x19
    _fsigma1 = _x20
    _fsigma1__tan = _x21
    _fF1 = _x2 - _x23 - _x24 + _x28
    _fF1__tan = _x16*_x33 + _x30 + _x31 + _x34
    _fPsi0 = _x35
    _fPsi0__tan = _x38
    _fft0 = _x39*_x42
    _fft0__tan = (0.5)*_D__tan*_x39*_x41*_x43 - _x44*_x45
    _ffq0 = _P0*_x46*_x49
    _ffq0__tan = (0.5)*_D__tan*_P0*_x39*_x43*_x46*_x47 - _P0*_x45*_x46*_x50 + _P0__tan*_x39*_x40*_x46*_x47 - 2.0*_x1*_x17*_x49
    _ffp0 = _x0*_x53
    _ffp0__tan = _Q0__tan*_x3*_x52*_x54 - _x0*_x12*_x45*_x56 + _x1*_x53 + _x12*_x54*_x55
    _fPsi1 = _x57
    _fPsi1__tan = _x58
    _fft1 = _x42*_x59
    _fft1__tan = (0.5)*_D__tan*_x41*_x43*_x59 - _x44*_x60
    _ffq1 = _P1*_x61*_x62
    _ffq1__tan = (0.5)*_D__tan*_P1*_x43*_x47*_x59*_x61 - _P1*_x50*_x60*_x61 + _P1__tan*_x40*_x47*_x59*_x61 - 2.0*_x21*_x32*_x62
    _ffp1 = _x20*_x63
    _ffp1__tan = _Q1__tan*_x22*_x52*_x64 - _x20*_x29*_x56*_x60 + _x21*_x63 + _x29*_x55*_x64
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    _work = 0.10566243270259355*_fF0 + 0.39433756729740643*_fF1
    _work__tan = 0.10566243270259355*_fF0__tan + 0.39433756729740643*_fF1__tan
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    _x67 = math.sqrt(_D*_work)/math.sqrt(m)
    _x68 = q_r**2
    _x69 = q_r_lo**-2
    _x70 = _x69/m
    _x71 = 0.5*_x70
    t_half = 0.5*_fft0 + 0.5*_fft1
    t_half__tan = 0.5*_fft0__tan + 0.5*_fft1__tan
    end_q_th = 0.5*_ffq0 + 0.5*_ffq1 + q_th
    end_q_th__tan = 0.5*_ffq0__tan + 0.5*_ffq1__tan + q_th__tan
    end_q_r = q_r_lo
    end_q_rd = 2.0*_x67
    end_q_rd__tan = _work__tan*_x67/_work + _D__tan*_x67/_D
    end_q_thd = _x70*(0.5*_ffp0 + 0.5*_ffp1 + _x68*m*q_thd)
    end_q_thd__tan = _ffp0__tan*_x71 + _ffp1__tan*_x71 + _x68*_x69*q_thd__tan + 2.0*_x69*q_r*q_r__tan*q_thd
    passes = _passes
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_5(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 1 of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 2 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th
    _Q1 = 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th
    _P0 = 0.2113248654051871*guess_q_thd*m*q_r_lo**2 + 0.7886751345948129*m*q_r**2*q_thd
    _P1 = 0.7886751345948129*guess_q_thd*m*q_r_lo**2 + 0.2113248654051871*m*q_r**2*q_thd
    _D__tan = -q_r__tan
    _Q0__tan = 0.2113248654051871*guess_q_th__tan + 0.7886751345948129*q_th__tan
    _Q1__tan = 0.7886751345948129*guess_q_th__tan + 0.2113248654051871*q_th__tan
    _P0__tan = 0.2113248654051871*guess_q_thd__tan*m*q_r_lo**2 + 0.7886751345948129*m*q_r**2*q_thd__tan + 1.5773502691896257*m*q_r*q_r__tan*q_thd
    _P1__tan = 0.7886751345948129*guess_q_thd__tan*m*q_r_lo**2 + 0.2113248654051871*m*q_r**2*q_thd__tan + 0.4226497308103742*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_3(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[10])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_Q1 = _c0[2]
        _next_P0 = _c0[3]
        _next_P1 = _c0[4]
        _next_D__tan = _c0[5]
        _next_Q0__tan = _c0[6]
        _next_Q1__tan = _c0[7]
        _next_P0__tan = _c0[8]
        _next_P1__tan = _c0[9]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_Q1
        _n0_3 = _next_P0
        _n0_4 = _next_P1
        _n0_5 = _next_D__tan
        _n0_6 = _next_Q0__tan
        _n0_7 = _next_Q1__tan
        _n0_8 = _next_P0__tan
        _n0_9 = _next_P1__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_4 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _P0 = _n0_3
        _P1 = _n0_4
        _D__tan = _n0_5
        _Q0__tan = _n0_6
        _Q1__tan = _n0_7
        _P0__tan = _n0_8
        _P1__tan = _n0_9
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_4(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[24])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    _work = _c1[12]
    _work__tan = _c1[13]
    t_half = _c1[14]
    t_half__tan = _c1[15]
    end_q_th = _c1[16]
    end_q_th__tan = _c1[17]
    end_q_r = _c1[18]
    end_q_rd = _c1[19]
    end_q_rd__tan = _c1[20]
    end_q_thd = _c1[21]
    end_q_thd__tan = _c1[22]
    passes = _c1[23]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_6(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_Q1: result for the caller
        _next_Q2: result for the caller
        _next_P0: result for the caller
        _next_P1: result for the caller
        _next_P2: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_Q1__tan: result for the caller
        _next_Q2__tan: result for the caller
        _next_P0__tan: result for the caller
        _next_P1__tan: result for the caller
        _next_P2__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 495
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.012701665379258311*_D + q_r
    _x89 = (1.0/_x0)
    _x1 = 0.012701665379258311*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x89**3
    _x8 = _P0**2
    _x9 = (1.0/m)
    _x10 = _x8*_x9
    _x11 = _x10*_x7
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x4
    _x14 = -l0
    _x15 = k_d__tan*(-_x0 - _x14)
    _x16 = 2.0*_x9
    _x17 = _P0*_x7
    _x18 = _P0__tan*_x17
    _x19 = _x1*(-3.0*_x10*_x89**4 - k_d)
    _x20 = 0.25*_D + q_r
    _x90 = (1.0/_x20)
    _x21 = 0.25*_D__tan + q_r__tan
    _x22 = math.cos(_Q1)
    _x23 = _x22*_x4
    _x24 = _x20*k_d
    _x25 = _x90**3
    _x26 = _P1**2
    _x27 = _x26*_x9
    _x28 = _x25*_x27
    _x29 = math.sin(_Q1)
    _x30 = _Q1__tan*_x29*_x4
    _x31 = k_d__tan*(-_x14 - _x20)
    _x32 = _P1*_x25
    _x33 = _P1__tan*_x32
    _x34 = _x21*(-3.0*_x27*_x90**4 - k_d)
    _x35 = 0.7872983346207417*_D + q_r
    _x91 = (1.0/_x35)
    _x36 = 0.7872983346207417*_D__tan + q_r__tan
    _x37 = math.cos(_Q2)
    _x38 = _x37*_x4
    _x39 = _x35*k_d
    _x40 = _x91**3
    _x41 = _P2**2
    _x42 = _x41*_x9
    _x43 = _x40*_x42
    _x44 = math.sin(_Q2)
    _x45 = _Q2__tan*_x4*_x44
    _x46 = k_d__tan*(-_x14 - _x35)
    _x47 = _P2*_x40
    _x48 = _P2__tan*_x47
    _x49 = _x36*(-3.0*_x42*_x91**4 - k_d)
    _x50 = 0.5762768525670787*_x11 + 0.5*_x2 + 0.1040546303448565*_x23 + 0.1040546303448565*_x24 - 0.1040546303448565*_x28 - 0.027777777777777776*_x38 - 0.027777777777777776*_x39 + 0.027777777777777776*_x43 - 0.5762768525670787*_x5 - 0.5762768525670787*_x6
    _x51 = _x18*_x9
    _x52 = _x33*_x9
    _x53 = _x48*_x9
    _x54 = 0.5762768525670787*_x13 + 0.5762768525670787*_x15 + 0.5762768525670787*_x19 - 0.1040546303448565*_x30 - 0.1040546303448565*_x31 - 0.1040546303448565*_x34 + 0.027777777777777776*_x45 + 0.027777777777777776*_x46 + 0.027777777777777776*_x49 + 1.1525537051341574*_x51 - 0.208109260689713*_x52 + 0.05555555555555555*_x53
    _x55 = (1.0/math.sqrt(_x50))
    _x56 = math.sqrt(_D)
    _x57 = math.sqrt(m)
    _x58 = _x56*_x57
    _x59 = (1.0/_x56)
    _x60 = (0.5)*_x58
    _x61 = _x54/_x50**(1.5)
    _x62 = _x89**2
    _x63 = (1.0/_x57)
    _x64 = _x56*_x63
    _x65 = _x55*_x64
    _x66 = (0.5)*_x64
    _x67 = g_s*m**(1.5)
    _x68 = _x56*_x67
    _x69 = _x12*_x55*_x68
    _x70 = _x0*_x55
    _x71 = (0.5)*_D__tan*_x59*_x67
    _x72 = (0.5)*_x68
    _x73 = 0.17702731517242826*_x11 + 0.5*_x2 - 0.3611111111111111*_x23 - 0.3611111111111111*_x24 + 0.3611111111111111*_x28 + 0.038138426283539355*_x38 + 0.038138426283539355*_x39 - 0.038138426283539355*_x43 - 0.17702731517242826*_x5 - 0.17702731517242826*_x6
    _x74 = 0.17702731517242826*_x13 + 0.17702731517242826*_x15 + 0.17702731517242826*_x19 + 0.3611111111111111*_x30 + 0.3611111111111111*_x31 + 0.3611111111111111*_x34 - 0.038138426283539355*_x45 - 0.038138426283539355*_x46 - 0.038138426283539355*_x49 + 0.3540546303448565*_x51 + 0.7222222222222222*_x52 - 0.07627685256707871*_x53
    _x75 = (1.0/math.sqrt(_x73))
    _x76 = _x74/_x73**(1.5)
    _x77 = _x90**2
    _x78 = _x64*_x75
    _x79 = _x29*_x68*_x75
    _x80 = _x20*_x75
    _x81 = -0.3262768525670787*_x23 - 0.3262768525670787*_x24 + 0.3262768525670787*_x25*_x26*_x9 - 0.14594536965514351*_x38 - 0.14594536965514351*_x39 + 0.14594536965514351*_x40*_x41*_x9 - 0.027777777777777776*_x5 - 0.027777777777777776*_x6 + 0.027777777777777776*_x7*_x8*_x9 + 0.5*k_d*l0
    _x82 = 0.027777777777777776*_x13 + 0.027777777777777776*_x15 + 0.027777777777777776*_x19 + 0.3262768525670787*_x30 + 0.3262768525670787*_x31 + 0.3262768525670787*_x34 + 0.14594536965514351*_x45 + 0.14594536965514351*_x46 + 0.14594536965514351*_x49 + 0.05555555555555555*_x51 + 0.6525537051341574*_x52 + 0.29189073931028703*_x53
    _x83 = (1.0/math.sqrt(_x81))
    _x84 = _x82/_x81**(1.5)
    _x85 = _x91**2
    _x86 = _x64*_x83
    _x87 = _x44*_x68*_x83
    _x88 = _x35*_x83
    _isigma0 = _x0
    _isigma0__tan = _x1
    _iF0 = _x11 + _x2 - _x5 - _x6
    _iF0__tan = _x13 + _x15 + _x16*_x18 + _x19
    _isigma1 = _x20
    _isigma1__tan = _x21
    _iF1 = _x2 - _x23 - _x24 + _x28
    _iF1__tan = _x16*_x33 + _x30 + _x31 + _x34
    _isigma2 = _x35
    _isigma2__tan = _x36
    _iF2 = _x2 - _x38 - _x39 + _x43
    _iF2__tan = _x16*_x48 + _x45 + _x46 + _x49
    _iPsi0 = _x50
    _iPsi0__tan = _x54
    _ift0 = _x55*_x58
    _ift0__tan = (0.5)*_D__tan*_x55*_x57*_x59 - _x60*_x61
    _ifq0 = _P0*_x62*_x65
    _ifq0__tan = (0.5)*_D__tan*_P0*_x55*_x59*_x62*_x63 - _P0*_x61*_x62*_x66 + _P0__tan*_x55*_x56*_x62*_x63 - 2.0*_x1*_x17*_x65
    _ifp0 = _x0*_x69
    _ifp0__tan = _Q0__tan*_x3*_x68*_x70 - _x0*_x12*_x61*_x72 + _x1*_x69 + _x12*_x70*_x71
    _iPsi1 = _x73
    _iPsi1__tan = _x74
    _ift1 = _x58*_x75
    _ift1__tan = (0.5)*_D__tan*_x57*_x59*_x75 - _x60*_x76
    _ifq1 = _P1*_x77*_x78
    _ifq1__tan = (0.5)*_D__tan*_P1*_x59*_x63*_x75*_x77 - _P1*_x66*_x76*_x77 + _P1__tan*_x56*_x63*_x75*_x77 - 2.0*_x21*_x32*_x78
    _ifp1 = _x20*_x79
    _ifp1__tan = _Q1__tan*_x22*_x68*_x80 - _x20*_x29*_x72*_x76 + _x21*_x79 + _x29*_x71*_x80
    _iPsi2 = _x81
    _iPsi2__tan = _x82
    _ift2 = _x58*_x83
    _ift2__tan = (0.5)*_D__tan*_x57*_x59*_x83 - _x60*_x84
    _ifq2 = _P2*_x85*_x86
    _ifq2__tan = (0.5)*_D__tan*_P2*_x59*_x63*_x83*_x85 - _P2*_x66*_x84*_x85 + _P2__tan*_x56*_x63*_x83*_x85 - 2.0*_x36*_x47*_x86
    _ifp2 = _x35*_x87
    _ifp2__tan = _Q2__tan*_x37*_x68*_x88 - _x35*_x44*_x72*_x84 + _x36*_x87 + _x44*_x71*_x88
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x92 = m*q_r**2
    _x93 = _x92*q_thd
    _x94 = _x92*q_thd__tan + 2.0*m*q_r*q_r__tan*q_thd
    _next_D = _D
    _next_Q0 = 0.1388888888888889*_ifq0 - 0.0359766675249389*_ifq1 + 0.009789444015308325*_ifq2 + q_th
    _next_Q1 = 0.30026319498086457*_ifq0 + 0.2222222222222222*_ifq1 - 0.022485417203086815*_ifq2 + q_th
    _next_Q2 = 0.26798833376246944*_ifq0 + 0.48042111196938336*_ifq1 + 0.1388888888888889*_ifq2 + q_th
    _next_P0 = 0.1388888888888889*_ifp0 - 0.0359766675249389*_ifp1 + 0.009789444015308325*_ifp2 + _x93
    _next_P1 = 0.30026319498086457*_ifp0 + 0.2222222222222222*_ifp1 - 0.022485417203086815*_ifp2 + _x93
    _next_P2 = 0.26798833376246944*_ifp0 + 0.48042111196938336*_ifp1 + 0.1388888888888889*_ifp2 + _x93
    _next_D__tan = _D__tan
    _next_Q0__tan = 0.1388888888888889*_ifq0__tan - 0.0359766675249389*_ifq1__tan + 0.009789444015308325*_ifq2__tan + q_th__tan
    _next_Q1__tan = 0.30026319498086457*_ifq0__tan + 0.2222222222222222*_ifq1__tan - 0.022485417203086815*_ifq2__tan + q_th__tan
    _next_Q2__tan = 0.26798833376246944*_ifq0__tan + 0.48042111196938336*_ifq1__tan + 0.1388888888888889*_ifq2__tan + q_th__tan
    _next_P0__tan = 0.1388888888888889*_ifp0__tan - 0.0359766675249389*_ifp1__tan + 0.009789444015308325*_ifp2__tan + _x94
    _next_P1__tan = 0.30026319498086457*_ifp0__tan + 0.2222222222222222*_ifp1__tan - 0.022485417203086815*_ifp2__tan + _x94
    _next_P2__tan = 0.26798833376246944*_ifp0__tan + 0.48042111196938336*_ifp1__tan + 0.1388888888888889*_ifp2__tan + _x94
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_Q1, _next_Q2, _next_P0, _next_P1, _next_P2, _next_D__tan, _next_Q0__tan, _next_Q1__tan, _next_Q2__tan, _next_P0__tan, _next_P1__tan, _next_P2__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_7(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 486
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.012701665379258311*_D + q_r
    _x89 = (1.0/_x0)
    _x1 = 0.012701665379258311*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x89**3
    _x8 = _P0**2
    _x9 = (1.0/m)
    _x10 = _x8*_x9
    _x11 = _x10*_x7
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x4
    _x14 = -l0
    _x15 = k_d__tan*(-_x0 - _x14)
    _x16 = 2.0*_x9
    _x17 = _P0*_x7
    _x18 = _P0__tan*_x17
    _x19 = _x1*(-3.0*_x10*_x89**4 - k_d)
    _x20 = 0.25*_D + q_r
    _x90 = (1.0/_x20)
    _x21 = 0.25*_D__tan + q_r__tan
    _x22 = math.cos(_Q1)
    _x23 = _x22*_x4
    _x24 = _x20*k_d
    _x25 = _x90**3
    _x26 = _P1**2
    _x27 = _x26*_x9
    _x28 = _x25*_x27
    _x29 = math.sin(_Q1)
    _x30 = _Q1__tan*_x29*_x4
    _x31 = k_d__tan*(-_x14 - _x20)
    _x32 = _P1*_x25
    _x33 = _P1__tan*_x32
    _x34 = _x21*(-3.0*_x27*_x90**4 - k_d)
    _x35 = 0.7872983346207417*_D + q_r
    _x91 = (1.0/_x35)
    _x36 = 0.7872983346207417*_D__tan + q_r__tan
    _x37 = math.cos(_Q2)
    _x38 = _x37*_x4
    _x39 = _x35*k_d
    _x40 = _x91**3
    _x41 = _P2**2
    _x42 = _x41*_x9
    _x43 = _x40*_x42
    _x44 = math.sin(_Q2)
    _x45 = _Q2__tan*_x4*_x44
    _x46 = k_d__tan*(-_x14 - _x35)
    _x47 = _P2*_x40
    _x48 = _P2__tan*_x47
    _x49 = _x36*(-3.0*_x42*_x91**4 - k_d)
    _x50 = 0.5762768525670787*_x11 + 0.5*_x2 + 0.1040546303448565*_x23 + 0.1040546303448565*_x24 - 0.1040546303448565*_x28 - 0.027777777777777776*_x38 - 0.027777777777777776*_x39 + 0.027777777777777776*_x43 - 0.5762768525670787*_x5 - 0.5762768525670787*_x6
    _x51 = _x18*_x9
    _x52 = _x33*_x9
    _x53 = _x48*_x9
    _x54 = 0.5762768525670787*_x13 + 0.5762768525670787*_x15 + 0.5762768525670787*_x19 - 0.1040546303448565*_x30 - 0.1040546303448565*_x31 - 0.1040546303448565*_x34 + 0.027777777777777776*_x45 + 0.027777777777777776*_x46 + 0.027777777777777776*_x49 + 1.1525537051341574*_x51 - 0.208109260689713*_x52 + 0.05555555555555555*_x53
    _x55 = (1.0/math.sqrt(_x50))
    _x56 = math.sqrt(_D)
    _x57 = math.sqrt(m)
    _x58 = _x56*_x57
    _x59 = (1.0/_x56)
    _x60 = (0.5)*_x58
    _x61 = _x54/_x50**(1.5)
    _x62 = _x89**2
    _x63 = (1.0/_x57)
    _x64 = _x56*_x63
    _x65 = _x55*_x64
    _x66 = (0.5)*_x64
    _x67 = g_s*m**(1.5)
    _x68 = _x56*_x67
    _x69 = _x12*_x55*_x68
    _x70 = _x0*_x55
    _x71 = (0.5)*_D__tan*_x59*_x67
    _x72 = (0.5)*_x68
    _x73 = 0.17702731517242826*_x11 + 0.5*_x2 - 0.3611111111111111*_x23 - 0.3611111111111111*_x24 + 0.3611111111111111*_x28 + 0.038138426283539355*_x38 + 0.038138426283539355*_x39 - 0.038138426283539355*_x43 - 0.17702731517242826*_x5 - 0.17702731517242826*_x6
    _x74 = 0.17702731517242826*_x13 + 0.17702731517242826*_x15 + 0.17702731517242826*_x19 + 0.3611111111111111*_x30 + 0.3611111111111111*_x31 + 0.3611111111111111*_x34 - 0.038138426283539355*_x45 - 0.038138426283539355*_x46 - 0.038138426283539355*_x49 + 0.3540546303448565*_x51 + 0.7222222222222222*_x52 - 0.07627685256707871*_x53
    _x75 = (1.0/math.sqrt(_x73))
    _x76 = _x74/_x73**(1.5)
    _x77 = _x90**2
    _x78 = _x64*_x75
    _x79 = _x29*_x68*_x75
    _x80 = _x20*_x75
    _x81 = -0.3262768525670787*_x23 - 0.3262768525670787*_x24 + 0.3262768525670787*_x25*_x26*_x9 - 0.14594536965514351*_x38 - 0.14594536965514351*_x39 + 0.14594536965514351*_x40*_x41*_x9 - 0.027777777777777776*_x5 - 0.027777777777777776*_x6 + 0.027777777777777776*_x7*_x8*_x9 + 0.5*k_d*l0
    _x82 = 0.027777777777777776*_x13 + 0.027777777777777776*_x15 + 0.027777777777777776*_x19 + 0.3262768525670787*_x30 + 0.3262768525670787*_x31 + 0.3262768525670787*_x34 + 0.14594536965514351*_x45 + 0.14594536965514351*_x46 + 0.14594536965514351*_x49 + 0.05555555555555555*_x51 + 0.6525537051341574*_x52 + 0.29189073931028703*_x53
    _x83 = (1.0/math.sqrt(_x81))
    _x84 = _x82/_x81**(1.5)
    _x85 = _x91**2
    _x86 = _x64*_x83
    _x87 = _x44*_x68*_x83
    _x88 = _x35*_x83
    _fsigma0 = _x0
    _fsigma0__tan = _x1
    _fF0 = _x11 + _x2 - _x5 - _x6
    _fF0__tan = _x13 + _x15 + _x16*_x18 + _x19
    _fsigma1 = _x20
    _fsigma1__tan = _x21
    _fF1 = _x2 - _x23 - _x24 + _x28
    _fF1__tan = _x16*_x33 + _x30 + _x31 + _x34
    _fsigma2 = _x35
    _fsigma2__tan = _x36
    _fF2 = _x2 - _x38 - _x39 + _x43
    _fF2__tan = _x16*_x48 + _x45 + _x46 + _x49
    _fPsi0 = _x50
    _fPsi0__tan = _x54
    _fft0 = _x55*_x58
    _fft0__tan = (0.5)*_D__tan*_x55*_x57*_x59 - _x60*_x61
    _ffq0 = _P0*_x62*_x65
    _ffq0__tan = (0.5)*_D__tan*_P0*_x55*_x59*_x62*_x63 - _P0*_x61*_x62*_x66 + _P0__tan*_x55*_x56*_x62*_x63 - 2.0*_x1*_x17*_x65
    _ffp0 = _x0*_x69
    _ffp0__tan = _Q0__tan*_x3*_x68*_x70 - _x0*_x12*_x61*_x72 + _x1*_x69 + _x12*_x70*_x71
    _fPsi1 = _x73
    _fPsi1__tan = _x74
    _fft1 = _x58*_x75
    _fft1__tan = (0.5)*_D__tan*_x57*_x59*_x75 - _x60*_x76
    _ffq1 = _P1*_x77*_x78
    _ffq1__tan = (0.5)*_D__tan*_P1*_x59*_x63*_x75*_x77 - _P1*_x66*_x76*_x77 + _P1__tan*_x56*_x63*_x75*_x77 - 2.0*_x21*_x32*_x78
    _ffp1 = _x20*_x79
    _ffp1__tan = _Q1__tan*_x22*_x68*_x80 - _x20*_x29*_x72*_x76 + _x21*_x79 + _x29*_x71*_x80
    _fPsi2 = _x81
    _fPsi2__tan = _x82
    _fft2 = _x58*_x83
    _fft2__tan = (0.5)*_D__tan*_x57*_x59*_x83 - _x60*_x84
    _ffq2 = _P2*_x85*_x86
    _ffq2__tan = (0.5)*_D__tan*_P2*_x59*_x63*_x83*_x85 - _P2*_x66*_x84*_x85 + _P2__tan*_x56*_x63*_x83*_x85 - 2.0*_x36*_x47*_x86
    _ffp2 = _x35*_x87
    _ffp2__tan = _Q2__tan*_x37*_x68*_x88 - _x35*_x44*_x72*_x84 + _x36*_x87 + _x44*_x71*_x88
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    _work = 0.031306018160905086*_fF0 + 0.2222222222222222*_fF1 + 0.2464717596168727*_fF2
    _work__tan = 0.031306018160905086*_fF0__tan + 0.2222222222222222*_fF1__tan + 0.2464717596168727*_fF2__tan
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    _x92 = math.sqrt(_D*_work)/math.sqrt(m)
    _x93 = q_r**2
    _x94 = q_r_lo**-2
    _x95 = _x94/m
    _x96 = 0.2777777777777778*_x95
    t_half = 0.2777777777777778*_fft0 + 0.4444444444444444*_fft1 + 0.2777777777777778*_fft2
    t_half__tan = 0.2777777777777778*_fft0__tan + 0.4444444444444444*_fft1__tan + 0.2777777777777778*_fft2__tan
    end_q_th = 0.2777777777777778*_ffq0 + 0.4444444444444444*_ffq1 + 0.2777777777777778*_ffq2 + q_th
    end_q_th__tan = 0.2777777777777778*_ffq0__tan + 0.4444444444444444*_ffq1__tan + 0.2777777777777778*_ffq2__tan + q_th__tan
    end_q_r = q_r_lo
    end_q_rd = 2.0*_x92
    end_q_rd__tan = _work__tan*_x92/_work + _D__tan*_x92/_D
    end_q_thd = _x95*(0.2777777777777778*_ffp0 + 0.4444444444444444*_ffp1 + 0.2777777777777778*_ffp2 + _x93*m*q_thd)
    end_q_thd__tan = _ffp0__tan*_x96 + 0.4444444444444444*_ffp1__tan*_x95 + _ffp2__tan*_x96 + _x93*_x94*q_thd__tan + 2.0*_x94*q_r*q_r__tan*q_thd
    passes = _passes
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_8(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 2 of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 3 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th
    _Q1 = 0.5*guess_q_th + 0.5*q_th
    _Q2 = 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th
    _P0 = 0.11270166537925831*guess_q_thd*m*q_r_lo**2 + 0.8872983346207417*m*q_r**2*q_thd
    _P1 = 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd
    _P2 = 0.8872983346207417*guess_q_thd*m*q_r_lo**2 + 0.11270166537925831*m*q_r**2*q_thd
    _D__tan = -q_r__tan
    _Q0__tan = 0.11270166537925831*guess_q_th__tan + 0.8872983346207417*q_th__tan
    _Q1__tan = 0.5*guess_q_th__tan + 0.5*q_th__tan
    _Q2__tan = 0.8872983346207417*guess_q_th__tan + 0.11270166537925831*q_th__tan
    _P0__tan = 0.11270166537925831*guess_q_thd__tan*m*q_r_lo**2 + 0.8872983346207417*m*q_r**2*q_thd__tan + 1.7745966692414834*m*q_r*q_r__tan*q_thd
    _P1__tan = 0.5*guess_q_thd__tan*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd__tan + 1.0*m*q_r*q_r__tan*q_thd
    _P2__tan = 0.8872983346207417*guess_q_thd__tan*m*q_r_lo**2 + 0.11270166537925831*m*q_r**2*q_thd__tan + 0.22540333075851662*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_6(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[14] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[14])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_Q1 = _c0[2]
        _next_Q2 = _c0[3]
        _next_P0 = _c0[4]
        _next_P1 = _c0[5]
        _next_P2 = _c0[6]
        _next_D__tan = _c0[7]
        _next_Q0__tan = _c0[8]
        _next_Q1__tan = _c0[9]
        _next_Q2__tan = _c0[10]
        _next_P0__tan = _c0[11]
        _next_P1__tan = _c0[12]
        _next_P2__tan = _c0[13]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_Q1
        _n0_3 = _next_Q2
        _n0_4 = _next_P0
        _n0_5 = _next_P1
        _n0_6 = _next_P2
        _n0_7 = _next_D__tan
        _n0_8 = _next_Q0__tan
        _n0_9 = _next_Q1__tan
        _n0_10 = _next_Q2__tan
        _n0_11 = _next_P0__tan
        _n0_12 = _next_P1__tan
        _n0_13 = _next_P2__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_5 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _P0 = _n0_4
        _P1 = _n0_5
        _P2 = _n0_6
        _D__tan = _n0_7
        _Q0__tan = _n0_8
        _Q1__tan = _n0_9
        _Q2__tan = _n0_10
        _P0__tan = _n0_11
        _P1__tan = _n0_12
        _P2__tan = _n0_13
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_7(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[24])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    _work = _c1[12]
    _work__tan = _c1[13]
    t_half = _c1[14]
    t_half__tan = _c1[15]
    end_q_th = _c1[16]
    end_q_th__tan = _c1[17]
    end_q_r = _c1[18]
    end_q_rd = _c1[19]
    end_q_rd__tan = _c1[20]
    end_q_thd = _c1[21]
    end_q_thd__tan = _c1[22]
    passes = _c1[23]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_9(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _P3: value of the caller's variable
        _P3__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _Q3: value of the caller's variable
        _Q3__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_Q1: result for the caller
        _next_Q2: result for the caller
        _next_Q3: result for the caller
        _next_P0: result for the caller
        _next_P1: result for the caller
        _next_P2: result for the caller
        _next_P3: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_Q1__tan: result for the caller
        _next_Q2__tan: result for the caller
        _next_Q3__tan: result for the caller
        _next_P0__tan: result for the caller
        _next_P1__tan: result for the caller
        _next_P2__tan: result for the caller
        _next_P3__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 757
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.004820780989426014*_D + q_r
    _x113 = (1.0/_x0)
    _x1 = 0.004820780989426014*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x113**3
    _x8 = _P0**2
    _x9 = (1.0/m)
    _x10 = _x8*_x9
    _x11 = _x10*_x7
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x4
    _x14 = -l0
    _x15 = k_d__tan*(-_x0 - _x14)
    _x16 = 2.0*_x9
    _x17 = _P0*_x7
    _x18 = _P0__tan*_x17
    _x19 = _x1*(-3.0*_x10*_x113**4 - k_d)
    _x20 = 0.10890625570683385*_D + q_r
    _x114 = (1.0/_x20)
    _x21 = 0.10890625570683385*_D__tan + q_r__tan
    _x22 = math.cos(_Q1)
    _x23 = _x22*_x4
    _x24 = _x20*k_d
    _x25 = _x114**3
    _x26 = _P1**2
    _x27 = _x26*_x9
    _x28 = _x25*_x27
    _x29 = math.sin(_Q1)
    _x30 = _Q1__tan*_x29*_x4
    _x31 = k_d__tan*(-_x14 - _x20)
    _x32 = _P1*_x25
    _x33 = _P1__tan*_x32
    _x34 = _x21*(-3.0*_x114**4*_x27 - k_d)
    _x35 = 0.44888729929169013*_D + q_r
    _x115 = (1.0/_x35)
    _x36 = 0.44888729929169013*_D__tan + q_r__tan
    _x37 = math.cos(_Q2)
    _x38 = _x37*_x4
    _x39 = _x35*k_d
    _x40 = _x115**3
    _x41 = _P2**2
    _x42 = _x41*_x9
    _x43 = _x40*_x42
    _x44 = math.sin(_Q2)
    _x45 = _Q2__tan*_x4*_x44
    _x46 = k_d__tan*(-_x14 - _x35)
    _x47 = _P2*_x40
    _x48 = _P2__tan*_x47
    _x49 = _x36*(-3.0*_x115**4*_x42 - k_d)
    _x50 = 0.8659570925834786*_D + q_r
    _x116 = (1.0/_x50)
    _x51 = 0.8659570925834786*_D__tan + q_r__tan
    _x52 = math.cos(_Q3)
    _x53 = _x4*_x52
    _x54 = _x50*k_d
    _x55 = _x116**3
    _x56 = _P3**2
    _x57 = _x56*_x9
    _x58 = _x55*_x57
    _x59 = math.sin(_Q3)
    _x60 = _Q3__tan*_x4*_x59
    _x61 = k_d__tan*(-_x14 - _x50)
    _x62 = _P3*_x55
    _x63 = _P3__tan*_x62
    _x64 = _x51*(-3.0*_x116**4*_x57 - k_d)
    _x65 = 0.582374038291501*_x11 + 0.5*_x2 + 0.12383458041329967*_x23 + 0.12383458041329967*_x24 - 0.12383458041329967*_x28 - 0.0575898635297681*_x38 - 0.0575898635297681*_x39 + 0.0575898635297681*_x43 - 0.582374038291501*_x5 + 0.016129321407969507*_x53 + 0.016129321407969507*_x54 - 0.016129321407969507*_x58 - 0.582374038291501*_x6
    _x66 = _x18*_x9
    _x67 = _x33*_x9
    _x68 = _x48*_x9
    _x69 = _x63*_x9
    _x70 = 0.582374038291501*_x13 + 0.582374038291501*_x15 + 0.582374038291501*_x19 - 0.12383458041329967*_x30 - 0.12383458041329967*_x31 - 0.12383458041329967*_x34 + 0.0575898635297681*_x45 + 0.0575898635297681*_x46 + 0.0575898635297681*_x49 - 0.016129321407969507*_x60 - 0.016129321407969507*_x61 - 0.016129321407969507*_x64 + 1.164748076583002*_x66 - 0.24766916082659934*_x67 + 0.1151797270595362*_x68 - 0.032258642815939015*_x69
    _x71 = (1.0/math.sqrt(_x65))
    _x72 = math.sqrt(_D)
    _x73 = math.sqrt(m)
    _x74 = _x72*_x73
    _x75 = (1.0/_x72)
    _x76 = (0.5)*_x74
    _x77 = _x70/_x65**(1.5)
    _x78 = _x113**2
    _x79 = (1.0/_x73)
    _x80 = _x72*_x79
    _x81 = _x71*_x80
    _x82 = (0.5)*_x80
    _x83 = g_s*m**(1.5)
    _x84 = _x72*_x83
    _x85 = _x12*_x71*_x84
    _x86 = _x0*_x71
    _x87 = (0.5)*_D__tan*_x75*_x83
    _x88 = (0.5)*_x84
    _x89 = -0.39252437029865583*_x23 - 0.39252437029865583*_x24 + 0.39252437029865583*_x25*_x26*_x9 + 0.0700094015044783*_x35*k_d + 0.0700094015044783*_x37*g_s*m - 0.0700094015044783*_x43 - 0.16000937841634696*_x5 - 0.017475652789475504*_x53 - 0.017475652789475504*_x54 + 0.017475652789475504*_x55*_x56*_x9 - 0.16000937841634696*_x6 + 0.16000937841634696*_x7*_x8*_x9 + 0.5*k_d*l0
    _x90 = 0.16000937841634696*_x13 + 0.16000937841634696*_x15 + 0.16000937841634696*_x19 + 0.39252437029865583*_x30 + 0.39252437029865583*_x31 + 0.39252437029865583*_x34 - 0.0700094015044783*_x45 - 0.0700094015044783*_x46 - 0.0700094015044783*_x49 + 0.017475652789475504*_x60 + 0.017475652789475504*_x61 + 0.017475652789475504*_x64 + 0.32001875683269393*_x66 + 0.7850487405973117*_x67 - 0.1400188030089566*_x68 + 0.03495130557895101*_x69
    _x91 = (1.0/math.sqrt(_x89))
    _x92 = _x90/_x89**(1.5)
    _x93 = _x114**2
    _x94 = _x80*_x91
    _x95 = _x29*_x84*_x91
    _x96 = _x20*_x91
    _x97 = -0.2848443432415939*_x23 - 0.2848443432415939*_x24 + 0.2848443432415939*_x25*_x26*_x9 - 0.21871326539550162*_x38 - 0.21871326539550162*_x39 + 0.21871326539550162*_x40*_x41*_x9 - 0.01613725546399532*_x5 + 0.019694864101090868*_x50*k_d + 0.019694864101090868*_x52*g_s*m - 0.019694864101090868*_x58 - 0.01613725546399532*_x6 + 0.01613725546399532*_x7*_x8*_x9 + 0.5*k_d*l0
    _x98 = 0.01613725546399532*_x13 + 0.01613725546399532*_x15 + 0.01613725546399532*_x19 + 0.2848443432415939*_x30 + 0.2848443432415939*_x31 + 0.2848443432415939*_x34 + 0.21871326539550162*_x45 + 0.21871326539550162*_x46 + 0.21871326539550162*_x49 - 0.019694864101090868*_x60 - 0.019694864101090868*_x61 - 0.019694864101090868*_x64 + 0.03227451092799064*_x66 + 0.5696886864831878*_x67 + 0.43742653079100324*_x68 - 0.039389728202181735*_x69
    _x99 = (1.0/math.sqrt(_x97))
    _x100 = _x98/_x97**(1.5)
    _x101 = _x115**2
    _x102 = _x80*_x99
    _x103 = _x44*_x84*_x99
    _x104 = _x35*_x99
    _x105 = -0.11000222456933441*_x23 - 0.11000222456933441*_x24 + 0.11000222456933441*_x25*_x26*_x9 - 0.2823150697454702*_x38 - 0.2823150697454702*_x39 + 0.2823150697454702*_x40*_x41*_x9 - 0.01796104633752054*_x5 - 0.08972165934767481*_x53 - 0.08972165934767481*_x54 + 0.08972165934767481*_x55*_x56*_x9 - 0.01796104633752054*_x6 + 0.01796104633752054*_x7*_x8*_x9 + 0.5*k_d*l0
    _x106 = 0.01796104633752054*_x13 + 0.01796104633752054*_x15 + 0.01796104633752054*_x19 + 0.11000222456933441*_x30 + 0.11000222456933441*_x31 + 0.11000222456933441*_x34 + 0.2823150697454702*_x45 + 0.2823150697454702*_x46 + 0.2823150697454702*_x49 + 0.08972165934767481*_x60 + 0.08972165934767481*_x61 + 0.08972165934767481*_x64 + 0.03592209267504108*_x66 + 0.22000444913866882*_x67 + 0.5646301394909404*_x68 + 0.17944331869534963*_x69
    _x107 = (1.0/math.sqrt(_x105))
    _x108 = _x106/_x105**(1.5)
    _x109 = _x116**2
    _x110 = _x107*_x80
    _x111 = _x107*_x59*_x84
    _x112 = _x107*_x50
    _isigma0 = _x0
    _isigma0__tan = _x1
    _iF0 = _x11 + _x2 - _x5 - _x6
    _iF0__tan = _x13 + _x15 + _x16*_x18 + _x19
    _isigma1 = _x20
    _isigma1__tan = _x21
    _iF1 = _x2 - _x23 - _x24 + _x28
    _iF1__tan = _x16*_x33 + _x30 + _x31 + _x34
    _isigma2 = _x35
    _isigma2__tan = _x36
    _iF2 = _x2 - _x38 - _x39 + _x43
    _iF2__tan = _x16*_x48 + _x45 + _x46 + _x49
    _isigma3 = _x50
    _isigma3__tan = _x51
    _iF3 = _x2 - _x53 - _x54 + _x58
    _iF3__tan = _x16*_x63 + _x60 + _x61 + _x64
    _iPsi0 = _x65
    _iPsi0__tan = _x70
    _ift0 = _x71*_x74
    _ift0__tan = (0.5)*_D__tan*_x71*_x73*_x75 - _x76*_x77
    _ifq0 = _P0*_x78*_x81
    _ifq0__tan = (0.5)*_D__tan*_P0*_x71*_x75*_x78*_x79 - _P0*_x77*_x78*_x82 + _P0__tan*_x71*_x72*_x78*_x79 - 2.0*_x1*_x17*_x81
    _ifp0 = _x0*_x85
    _ifp0__tan = _Q0__tan*_x3*_x84*_x86 - _x0*_x12*_x77*_x88 + _x1*_x85 + _x12*_x86*_x87
    _iPsi1 = _x89
    _iPsi1__tan = _x90
    _ift1 = _x74*_x91
    _ift1__tan = (0.5)*_D__tan*_x73*_x75*_x91 - _x76*_x92
    _ifq1 = _P1*_x93*_x94
    _ifq1__tan = (0.5)*_D__tan*_P1*_x75*_x79*_x91*_x93 - _P1*_x82*_x92*_x93 + _P1__tan*_x72*_x79*_x91*_x93 - 2.0*_x21*_x32*_x94
    _ifp1 = _x20*_x95
    _ifp1__tan = _Q1__tan*_x22*_x84*_x96 - _x20*_x29*_x88*_x92 + _x21*_x95 + _x29*_x87*_x96
    _iPsi2 = _x97
    _iPsi2__tan = _x98
    _ift2 = _x74*_x99
    _ift2__tan = (0.5)*_D__tan*_x73*_x75*_x99 - _x100*_x76
    _ifq2 = _P2*_x101*_x102
    _ifq2__tan = (0.5)*_D__tan*_P2*_x101*_x75*_x79*_x99 - _P2*_x100*_x101*_x82 + _P2__tan*_x101*_x72*_x79*_x99 - 2.0*_x102*_x36*_x47
    _ifp2 = _x103*_x35
    _ifp2__tan = _Q2__tan*_x104*_x37*_x84 - _x100*_x35*_x44*_x88 + _x103*_x36 + _x104*_x44*_x87
    _iPsi3 = _x105
    _iPsi3__tan = _x106
    _ift3 = _x107*_x74
    _ift3__tan = (0.5)*_D__tan*_x107*_x73*_x75 - _x108*_x76
    _ifq3 = _P3*_x109*_x110
    _ifq3__tan = (0.5)*_D__tan*_P3*_x107*_x109*_x75*_x79 - _P3*_x108*_x109*_x82 + _P3__tan*_x107*_x109*_x72*_x79 - 2.0*_x110*_x51*_x62
    _ifp3 = _x111*_x50
    _ifp3__tan = _Q3__tan*_x112*_x52*_x84 - _x108*_x50*_x59*_x88 + _x111*_x51 + _x112*_x59*_x87
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi3 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x117 = m*q_r**2
    _x118 = _x117*q_thd
    _x119 = _x117*q_thd__tan + 2.0*m*q_r*q_r__tan*q_thd
    _next_D = _D
    _next_Q0 = 0.08696371128436346*_ifq0 - 0.026604180084998794*_ifq1 + 0.012627462689404725*_ifq2 - 0.0035551496857956833*_ifq3 + q_th
    _next_Q1 = 0.18811811749986806*_ifq0 + 0.16303628871563652*_ifq1 - 0.027880428602470895*_ifq2 + 0.006735500594538156*_ifq3 + q_th
    _next_Q2 = 0.16719192197418878*_ifq0 + 0.35395300603374397*_ifq1 + 0.16303628871563652*_ifq2 - 0.014190694931141144*_ifq3 + q_th
    _next_Q3 = 0.1774825722545226*_ifq0 + 0.31344511474186837*_ifq1 + 0.35267675751627187*_ifq2 + 0.08696371128436346*_ifq3 + q_th
    _next_P0 = 0.08696371128436346*_ifp0 - 0.026604180084998794*_ifp1 + 0.012627462689404725*_ifp2 - 0.0035551496857956833*_ifp3 + _x118
    _next_P1 = 0.18811811749986806*_ifp0 + 0.16303628871563652*_ifp1 - 0.027880428602470895*_ifp2 + 0.006735500594538156*_ifp3 + _x118
    _next_P2 = 0.16719192197418878*_ifp0 + 0.35395300603374397*_ifp1 + 0.16303628871563652*_ifp2 - 0.014190694931141144*_ifp3 + _x118
    _next_P3 = 0.1774825722545226*_ifp0 + 0.31344511474186837*_ifp1 + 0.35267675751627187*_ifp2 + 0.08696371128436346*_ifp3 + _x118
    _next_D__tan = _D__tan
    _next_Q0__tan = 0.08696371128436346*_ifq0__tan - 0.026604180084998794*_ifq1__tan + 0.012627462689404725*_ifq2__tan - 0.0035551496857956833*_ifq3__tan + q_th__tan
    _next_Q1__tan = 0.18811811749986806*_ifq0__tan + 0.16303628871563652*_ifq1__tan - 0.027880428602470895*_ifq2__tan + 0.006735500594538156*_ifq3__tan + q_th__tan
    _next_Q2__tan = 0.16719192197418878*_ifq0__tan + 0.35395300603374397*_ifq1__tan + 0.16303628871563652*_ifq2__tan - 0.014190694931141144*_ifq3__tan + q_th__tan
    _next_Q3__tan = 0.1774825722545226*_ifq0__tan + 0.31344511474186837*_ifq1__tan + 0.35267675751627187*_ifq2__tan + 0.08696371128436346*_ifq3__tan + q_th__tan
    _next_P0__tan = 0.08696371128436346*_ifp0__tan - 0.026604180084998794*_ifp1__tan + 0.012627462689404725*_ifp2__tan - 0.0035551496857956833*_ifp3__tan + _x119
    _next_P1__tan = 0.18811811749986806*_ifp0__tan + 0.16303628871563652*_ifp1__tan - 0.027880428602470895*_ifp2__tan + 0.006735500594538156*_ifp3__tan + _x119
    _next_P2__tan = 0.16719192197418878*_ifp0__tan + 0.35395300603374397*_ifp1__tan + 0.16303628871563652*_ifp2__tan - 0.014190694931141144*_ifp3__tan + _x119
    _next_P3__tan = 0.1774825722545226*_ifp0__tan + 0.31344511474186837*_ifp1__tan + 0.35267675751627187*_ifp2__tan + 0.08696371128436346*_ifp3__tan + _x119
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_Q1, _next_Q2, _next_Q3, _next_P0, _next_P1, _next_P2, _next_P3, _next_D__tan, _next_Q0__tan, _next_Q1__tan, _next_Q2__tan, _next_Q3__tan, _next_P0__tan, _next_P1__tan, _next_P2__tan, _next_P3__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_10(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _P3: value of the caller's variable
        _P3__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _Q3: value of the caller's variable
        _Q3__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 708
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.004820780989426014*_D + q_r
    _x113 = (1.0/_x0)
    _x1 = 0.004820780989426014*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x113**3
    _x8 = _P0**2
    _x9 = (1.0/m)
    _x10 = _x8*_x9
    _x11 = _x10*_x7
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x4
    _x14 = -l0
    _x15 = k_d__tan*(-_x0 - _x14)
    _x16 = 2.0*_x9
    _x17 = _P0*_x7
    _x18 = _P0__tan*_x17
    _x19 = _x1*(-3.0*_x10*_x113**4 - k_d)
    _x20 = 0.10890625570683385*_D + q_r
    _x114 = (1.0/_x20)
    _x21 = 0.10890625570683385*_D__tan + q_r__tan
    _x22 = math.cos(_Q1)
    _x23 = _x22*_x4
    _x24 = _x20*k_d
    _x25 = _x114**3
    _x26 = _P1**2
    _x27 = _x26*_x9
    _x28 = _x25*_x27
    _x29 = math.sin(_Q1)
    _x30 = _Q1__tan*_x29*_x4
    _x31 = k_d__tan*(-_x14 - _x20)
    _x32 = _P1*_x25
    _x33 = _P1__tan*_x32
    _x34 = _x21*(-3.0*_x114**4*_x27 - k_d)
    _x35 = 0.44888729929169013*_D + q_r
    _x115 = (1.0/_x35)
    _x36 = 0.44888729929169013*_D__tan + q_r__tan
    _x37 = math.cos(_Q2)
    _x38 = _x37*_x4
    _x39 = _x35*k_d
    _x40 = _x115**3
    _x41 = _P2**2
    _x42 = _x41*_x9
    _x43 = _x40*_x42
    _x44 = math.sin(_Q2)
    _x45 = _Q2__tan*_x4*_x44
    _x46 = k_d__tan*(-_x14 - _x35)
    _x47 = _P2*_x40
    _x48 = _P2__tan*_x47
    _x49 = _x36*(-3.0*_x115**4*_x42 - k_d)
    _x50 = 0.8659570925834786*_D + q_r
    _x116 = (1.0/_x50)
    _x51 = 0.8659570925834786*_D__tan + q_r__tan
    _x52 = math.cos(_Q3)
    _x53 = _x4*_x52
    _x54 = _x50*k_d
    _x55 = _x116**3
    _x56 = _P3**2
    _x57 = _x56*_x9
    _x58 = _x55*_x57
    _x59 = math.sin(_Q3)
    _x60 = _Q3__tan*_x4*_x59
    _x61 = k_d__tan*(-_x14 - _x50)
    _x62 = _P3*_x55
    _x63 = _P3__tan*_x62
    _x64 = _x51*(-3.0*_x116**4*_x57 - k_d)
    _x65 = 0.582374038291501*_x11 + 0.5*_x2 + 0.12383458041329967*_x23 + 0.12383458041329967*_x24 - 0.12383458041329967*_x28 - 0.0575898635297681*_x38 - 0.0575898635297681*_x39 + 0.0575898635297681*_x43 - 0.582374038291501*_x5 + 0.016129321407969507*_x53 + 0.016129321407969507*_x54 - 0.016129321407969507*_x58 - 0.582374038291501*_x6
    _x66 = _x18*_x9
    _x67 = _x33*_x9
    _x68 = _x48*_x9
    _x69 = _x63*_x9
    _x70 = 0.582374038291501*_x13 + 0.582374038291501*_x15 + 0.582374038291501*_x19 - 0.12383458041329967*_x30 - 0.12383458041329967*_x31 - 0.12383458041329967*_x34 + 0.0575898635297681*_x45 + 0.0575898635297681*_x46 + 0.0575898635297681*_x49 - 0.016129321407969507*_x60 - 0.016129321407969507*_x61 - 0.016129321407969507*_x64 + 1.164748076583002*_x66 - 0.24766916082659934*_x67 + 0.1151797270595362*_x68 - 0.032258642815939015*_x69
    _x71 = (1.0/math.sqrt(_x65))
    _x72 = math.sqrt(_D)
    _x73 = math.sqrt(m)
    _x74 = _x72*_x73
    _x75 = (1.0/_x72)
    _x76 = (0.5)*_x74
    _x77 = _x70/_x65**(1.5)
    _x78 = _x113**2
    _x79 = (1.0/_x73)
    _x80 = _x72*_x79
    _x81 = _x71*_x80
    _x82 = (0.5)*_x80
    _x83 = g_s*m**(1.5)
    _x84 = _x72*_x83
    _x85 = _x12*_x71*_x84
    _x86 = _x0*_x71
    _x87 = (0.5)*_D__tan*_x75*_x83
    _x88 = (0.5)*_x84
    _x89 = -0.39252437029865583*_x23 - 0.39252437029865583*_x24 + 0.39252437029865583*_x25*_x26*_x9 + 0.0700094015044783*_x35*k_d + 0.0700094015044783*_x37*g_s*m - 0.0700094015044783*_x43 - 0.16000937841634696*_x5 - 0.017475652789475504*_x53 - 0.017475652789475504*_x54 + 0.017475652789475504*_x55*_x56*_x9 - 0.16000937841634696*_x6 + 0.16000937841634696*_x7*_x8*_x9 + 0.5*k_d*l0
    _x90 = 0.16000937841634696*_x13 + 0.16000937841634696*_x15 + 0.16000937841634696*_x19 + 0.39252437029865583*_x30 + 0.39252437029865583*_x31 + 0.39252437029865583*_x34 - 0.0700094015044783*_x45 - 0.0700094015044783*_x46 - 0.0700094015044783*_x49 + 0.017475652789475504*_x60 + 0.017475652789475504*_x61 + 0.017475652789475504*_x64 + 0.32001875683269393*_x66 + 0.7850487405973117*_x67 - 0.1400188030089566*_x68 + 0.03495130557895101*_x69
    _x91 = (1.0/math.sqrt(_x89))
    _x92 = _x90/_x89**(1.5)
    _x93 = _x114**2
    _x94 = _x80*_x91
    _x95 = _x29*_x84*_x91
    _x96 = _x20*_x91
    _x97 = -0.2848443432415939*_x23 - 0.2848443432415939*_x24 + 0.2848443432415939*_x25*_x26*_x9 - 0.21871326539550162*_x38 - 0.21871326539550162*_x39 + 0.21871326539550162*_x40*_x41*_x9 - 0.01613725546399532*_x5 + 0.019694864101090868*_x50*k_d + 0.019694864101090868*_x52*g_s*m - 0.019694864101090868*_x58 - 0.01613725546399532*_x6 + 0.01613725546399532*_x7*_x8*_x9 + 0.5*k_d*l0
    _x98 = 0.01613725546399532*_x13 + 0.01613725546399532*_x15 + 0.01613725546399532*_x19 + 0.2848443432415939*_x30 + 0.2848443432415939*_x31 + 0.2848443432415939*_x34 + 0.21871326539550162*_x45 + 0.21871326539550162*_x46 + 0.21871326539550162*_x49 - 0.019694864101090868*_x60 - 0.019694864101090868*_x61 - 0.019694864101090868*_x64 + 0.03227451092799064*_x66 + 0.5696886864831878*_x67 + 0.43742653079100324*_x68 - 0.039389728202181735*_x69
    _x99 = (1.0/math.sqrt(_x97))
    _x100 = _x98/_x97**(1.5)
    _x101 = _x115**2
    _x102 = _x80*_x99
    _x103 = _x44*_x84*_x99
    _x104 = _x35*_x99
    _x105 = -0.11000222456933441*_x23 - 0.11000222456933441*_x24 + 0.11000222456933441*_x25*_x26*_x9 - 0.2823150697454702*_x38 - 0.2823150697454702*_x39 + 0.2823150697454702*_x40*_x41*_x9 - 0.01796104633752054*_x5 - 0.08972165934767481*_x53 - 0.08972165934767481*_x54 + 0.08972165934767481*_x55*_x56*_x9 - 0.01796104633752054*_x6 + 0.01796104633752054*_x7*_x8*_x9 + 0.5*k_d*l0
    _x106 = 0.01796104633752054*_x13 + 0.01796104633752054*_x15 + 0.01796104633752054*_x19 + 0.11000222456933441*_x30 + 0.11000222456933441*_x31 + 0.11000222456933441*_x34 + 0.2823150697454702*_x45 + 0.2823150697454702*_x46 + 0.2823150697454702*_x49 + 0.08972165934767481*_x60 + 0.08972165934767481*_x61 + 0.08972165934767481*_x64 + 0.03592209267504108*_x66 + 0.22000444913866882*_x67 + 0.5646301394909404*_x68 + 0.17944331869534963*_x69
    _x107 = (1.0/math.sqrt(_x105))
    _x108 = _x106/_x105**(1.5)
    _x109 = _x116**2
    _x110 = _x107*_x80
    _x111 = _x107*_x59*_x84
    _x112 = _x107*_x50
    _fsigma0 = _x0
    _fsigma0__tan = _x1
    _fF0 = _x11 + _x2 - _x5 - _x6
    _fF0__tan = _x13 + _x15 + _x16*_x18 + _x19
    _fsigma1 = _x20
    _fsigma1__tan = _x21
    _fF1 = _x2 - _x23 - _x24 + _x28
    _fF1__tan = _x16*_x33 + _x30 + _x31 + _x34
    _fsigma2 = _x35
    _fsigma2__tan = _x36
    _fF2 = _x2 - _x38 - _x39 + _x43
    _fF2__tan = _x16*_x48 + _x45 + _x46 + _x49
    _fsigma3 = _x50
    _fsigma3__tan = _x51
    _fF3 = _x2 - _x53 - _x54 + _x58
    _fF3__tan = _x16*_x63 + _x60 + _x61 + _x64
    _fPsi0 = _x65
    _fPsi0__tan = _x70
    _fft0 = _x71*_x74
    _fft0__tan = (0.5)*_D__tan*_x71*_x73*_x75 - _x76*_x77
    _ffq0 = _P0*_x78*_x81
    _ffq0__tan = (0.5)*_D__tan*_P0*_x71*_x75*_x78*_x79 - _P0*_x77*_x78*_x82 + _P0__tan*_x71*_x72*_x78*_x79 - 2.0*_x1*_x17*_x81
    _ffp0 = _x0*_x85
    _ffp0__tan = _Q0__tan*_x3*_x84*_x86 - _x0*_x12*_x77*_x88 + _x1*_x85 + _x12*_x86*_x87
    _fPsi1 = _x89
    _fPsi1__tan = _x90
    _fft1 = _x74*_x91
    _fft1__tan = (0.5)*_D__tan*_x73*_x75*_x91 - _x76*_x92
    _ffq1 = _P1*_x93*_x94
    _ffq1__tan = (0.5)*_D__tan*_P1*_x75*_x79*_x91*_x93 - _P1*_x82*_x92*_x93 + _P1__tan*_x72*_x79*_x91*_x93 - 2.0*_x21*_x32*_x94
    _ffp1 = _x20*_x95
    _ffp1__tan = _Q1__tan*_x22*_x84*_x96 - _x20*_x29*_x88*_x92 + _x21*_x95 + _x29*_x87*_x96
    _fPsi2 = _x97
    _fPsi2__tan = _x98
    _fft2 = _x74*_x99
    _fft2__tan = (0.5)*_D__tan*_x73*_x75*_x99 - _x100*_x76
    _ffq2 = _P2*_x101*_x102
    _ffq2__tan = (0.5)*_D__tan*_P2*_x101*_x75*_x79*_x99 - _P2*_x100*_x101*_x82 + _P2__tan*_x101*_x72*_x79*_x99 - 2.0*_x102*_x36*_x47
    _ffp2 = _x103*_x35
    _ffp2__tan = _Q2__tan*_x104*_x37*_x84 - _x100*_x35*_x44*_x88 + _x103*_x36 + _x104*_x44*_x87
    _fPsi3 = _x105
    _fPsi3__tan = _x106
    _fft3 = _x107*_x74
    _fft3__tan = (0.5)*_D__tan*_x107*_x73*_x75 - _x108*_x76
    _ffq3 = _P3*_x109*_x110
    _ffq3__tan = (0.5)*_D__tan*_P3*_x107*_x109*_x75*_x79 - _P3*_x108*_x109*_x82 + _P3__tan*_x107*_x109*_x72*_x79 - 2.0*_x110*_x51*_x62
    _ffp3 = _x111*_x50
    _ffp3__tan = _Q3__tan*_x112*_x52*_x84 - _x108*_x50*_x59*_x88 + _x111*_x51 + _x112*_x59*_x87
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi3 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    _work = 0.012076101706416622*_fF0 + 0.1076070411358925*_fF1 + 0.21846553629538057*_fF2 + 0.1618513208623103*_fF3
    _work__tan = 0.012076101706416622*_fF0__tan + 0.1076070411358925*_fF1__tan + 0.21846553629538057*_fF2__tan + 0.1618513208623103*_fF3__tan
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    _x117 = math.sqrt(_D*_work)/math.sqrt(m)
    _x118 = q_r**2
    _x119 = q_r_lo**-2
    _x120 = _x119/m
    _x121 = 0.17392742256872692*_x120
    _x122 = 0.32607257743127305*_x120
    t_half = 0.17392742256872692*_fft0 + 0.32607257743127305*_fft1 + 0.32607257743127305*_fft2 + 0.17392742256872692*_fft3
    t_half__tan = 0.17392742256872692*_fft0__tan + 0.32607257743127305*_fft1__tan + 0.32607257743127305*_fft2__tan + 0.17392742256872692*_fft3__tan
    end_q_th = 0.17392742256872692*_ffq0 + 0.32607257743127305*_ffq1 + 0.32607257743127305*_ffq2 + 0.17392742256872692*_ffq3 + q_th
    end_q_th__tan = 0.17392742256872692*_ffq0__tan + 0.32607257743127305*_ffq1__tan + 0.32607257743127305*_ffq2__tan + 0.17392742256872692*_ffq3__tan + q_th__tan
    end_q_r = q_r_lo
    end_q_rd = 2.0*_x117
    end_q_rd__tan = _work__tan*_x117/_work + _D__tan*_x117/_D
    end_q_thd = _x120*(0.17392742256872692*_ffp0 + 0.32607257743127305*_ffp1 + 0.32607257743127305*_ffp2 + 0.17392742256872692*_ffp3 + _x118*m*q_thd)
    end_q_thd__tan = _ffp0__tan*_x121 + _ffp1__tan*_x122 + _ffp2__tan*_x122 + _ffp3__tan*_x121 + _x118*_x119*q_thd__tan + 2.0*_x119*q_r*q_r__tan*q_thd
    passes = _passes
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_11(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 3 of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 4 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.06943184420297371*guess_q_th + 0.9305681557970263*q_th
    _Q1 = 0.33000947820757187*guess_q_th + 0.6699905217924281*q_th
    _Q2 = 0.6699905217924281*guess_q_th + 0.33000947820757187*q_th
    _Q3 = 0.9305681557970263*guess_q_th + 0.06943184420297371*q_th
    _P0 = 0.06943184420297371*guess_q_thd*m*q_r_lo**2 + 0.9305681557970263*m*q_r**2*q_thd
    _P1 = 0.33000947820757187*guess_q_thd*m*q_r_lo**2 + 0.6699905217924281*m*q_r**2*q_thd
    _P2 = 0.6699905217924281*guess_q_thd*m*q_r_lo**2 + 0.33000947820757187*m*q_r**2*q_thd
    _P3 = 0.9305681557970263*guess_q_thd*m*q_r_lo**2 + 0.06943184420297371*m*q_r**2*q_thd
    _D__tan = -q_r__tan
    _Q0__tan = 0.06943184420297371*guess_q_th__tan + 0.9305681557970263*q_th__tan
    _Q1__tan = 0.33000947820757187*guess_q_th__tan + 0.6699905217924281*q_th__tan
    _Q2__tan = 0.6699905217924281*guess_q_th__tan + 0.33000947820757187*q_th__tan
    _Q3__tan = 0.9305681557970263*guess_q_th__tan + 0.06943184420297371*q_th__tan
    _P0__tan = 0.06943184420297371*guess_q_thd__tan*m*q_r_lo**2 + 0.9305681557970263*m*q_r**2*q_thd__tan + 1.8611363115940527*m*q_r*q_r__tan*q_thd
    _P1__tan = 0.33000947820757187*guess_q_thd__tan*m*q_r_lo**2 + 0.6699905217924281*m*q_r**2*q_thd__tan + 1.3399810435848563*m*q_r*q_r__tan*q_thd
    _P2__tan = 0.6699905217924281*guess_q_thd__tan*m*q_r_lo**2 + 0.33000947820757187*m*q_r**2*q_thd__tan + 0.6600189564151437*m*q_r*q_r__tan*q_thd
    _P3__tan = 0.9305681557970263*guess_q_thd__tan*m*q_r_lo**2 + 0.06943184420297371*m*q_r**2*q_thd__tan + 0.13886368840594743*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_9(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[18] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[18])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_Q1 = _c0[2]
        _next_Q2 = _c0[3]
        _next_Q3 = _c0[4]
        _next_P0 = _c0[5]
        _next_P1 = _c0[6]
        _next_P2 = _c0[7]
        _next_P3 = _c0[8]
        _next_D__tan = _c0[9]
        _next_Q0__tan = _c0[10]
        _next_Q1__tan = _c0[11]
        _next_Q2__tan = _c0[12]
        _next_Q3__tan = _c0[13]
        _next_P0__tan = _c0[14]
        _next_P1__tan = _c0[15]
        _next_P2__tan = _c0[16]
        _next_P3__tan = _c0[17]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_Q1
        _n0_3 = _next_Q2
        _n0_4 = _next_Q3
        _n0_5 = _next_P0
        _n0_6 = _next_P1
        _n0_7 = _next_P2
        _n0_8 = _next_P3
        _n0_9 = _next_D__tan
        _n0_10 = _next_Q0__tan
        _n0_11 = _next_Q1__tan
        _n0_12 = _next_Q2__tan
        _n0_13 = _next_Q3__tan
        _n0_14 = _next_P0__tan
        _n0_15 = _next_P1__tan
        _n0_16 = _next_P2__tan
        _n0_17 = _next_P3__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3) <= tol*(1.0)) and (abs(_n0_5 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_7 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _P0 = _n0_5
        _P1 = _n0_6
        _P2 = _n0_7
        _P3 = _n0_8
        _D__tan = _n0_9
        _Q0__tan = _n0_10
        _Q1__tan = _n0_11
        _Q2__tan = _n0_12
        _Q3__tan = _n0_13
        _P0__tan = _n0_14
        _P1__tan = _n0_15
        _P2__tan = _n0_16
        _P3__tan = _n0_17
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_10(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[24])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    _work = _c1[12]
    _work__tan = _c1[13]
    t_half = _c1[14]
    t_half__tan = _c1[15]
    end_q_th = _c1[16]
    end_q_th__tan = _c1[17]
    end_q_r = _c1[18]
    end_q_rd = _c1[19]
    end_q_rd__tan = _c1[20]
    end_q_thd = _c1[21]
    end_q_thd__tan = _c1[22]
    passes = _c1[23]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_12(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _P4, _P4__tan, _P5, _P5__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _Q4, _Q4__tan, _Q5, _Q5__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan):
    """loop body of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _P3: value of the caller's variable
        _P3__tan: value of the caller's variable
        _P4: value of the caller's variable
        _P4__tan: value of the caller's variable
        _P5: value of the caller's variable
        _P5__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _Q3: value of the caller's variable
        _Q3__tan: value of the caller's variable
        _Q4: value of the caller's variable
        _Q4__tan: value of the caller's variable
        _Q5: value of the caller's variable
        _Q5__tan: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _next_D: result for the caller
        _next_Q0: result for the caller
        _next_Q1: result for the caller
        _next_Q2: result for the caller
        _next_Q3: result for the caller
        _next_Q4: result for the caller
        _next_Q5: result for the caller
        _next_P0: result for the caller
        _next_P1: result for the caller
        _next_P2: result for the caller
        _next_P3: result for the caller
        _next_P4: result for the caller
        _next_P5: result for the caller
        _next_D__tan: result for the caller
        _next_Q0__tan: result for the caller
        _next_Q1__tan: result for the caller
        _next_Q2__tan: result for the caller
        _next_Q3__tan: result for the caller
        _next_Q4__tan: result for the caller
        _next_Q5__tan: result for the caller
        _next_P0__tan: result for the caller
        _next_P1__tan: result for the caller
        _next_P2__tan: result for the caller
        _next_P3__tan: result for the caller
        _next_P4__tan: result for the caller
        _next_P5__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1407
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.0011400916279895713*_D + q_r
    _x163 = (1.0/_x0)
    _x1 = 0.0011400916279895713*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x163**3
    _x8 = _P0**2
    _x9 = (1.0/m)
    _x10 = _x8*_x9
    _x11 = _x10*_x7
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x4
    _x14 = -l0
    _x15 = k_d__tan*(-_x0 - _x14)
    _x16 = 2.0*_x9
    _x17 = _P0*_x7
    _x18 = _P0__tan*_x17
    _x19 = _x1*(-3.0*_x10*_x163**4 - k_d)
    _x20 = 0.02869476995464123*_D + q_r
    _x164 = (1.0/_x20)
    _x21 = 0.02869476995464123*_D__tan + q_r__tan
    _x22 = math.cos(_Q1)
    _x23 = _x22*_x4
    _x24 = _x20*k_d
    _x25 = _x164**3
    _x26 = _P1**2
    _x27 = _x26*_x9
    _x28 = _x25*_x27
    _x29 = math.sin(_Q1)
    _x30 = _Q1__tan*_x29*_x4
    _x31 = k_d__tan*(-_x14 - _x20)
    _x32 = _P1*_x25
    _x33 = _P1__tan*_x32
    _x34 = _x21*(-3.0*_x164**4*_x27 - k_d)
    _x35 = 0.14492518595015338*_D + q_r
    _x165 = (1.0/_x35)
    _x36 = 0.14492518595015338*_D__tan + q_r__tan
    _x37 = math.cos(_Q2)
    _x38 = _x37*_x4
    _x39 = _x35*k_d
    _x40 = _x165**3
    _x41 = _P2**2
    _x42 = _x41*_x9
    _x43 = _x40*_x42
    _x44 = math.sin(_Q2)
    _x45 = _Q2__tan*_x4*_x44
    _x46 = k_d__tan*(-_x14 - _x35)
    _x47 = _P2*_x40
    _x48 = _P2__tan*_x47
    _x49 = _x36*(-3.0*_x165**4*_x42 - k_d)
    _x50 = 0.3835443720333503*_D + q_r
    _x166 = (1.0/_x50)
    _x51 = 0.3835443720333503*_D__tan + q_r__tan
    _x52 = math.cos(_Q3)
    _x53 = _x4*_x52
    _x54 = _x50*k_d
    _x55 = _x166**3
    _x56 = _P3**2
    _x57 = _x56*_x9
    _x58 = _x55*_x57
    _x59 = math.sin(_Q3)
    _x60 = _Q3__tan*_x4*_x59
    _x61 = k_d__tan*(-_x14 - _x50)
    _x62 = _P3*_x55
    _x63 = _P3__tan*_x62
    _x64 = _x51*(-3.0*_x166**4*_x57 - k_d)
    _x65 = 0.6899041564209057*_D + q_r
    _x167 = (1.0/_x65)
    _x66 = 0.6899041564209057*_D__tan + q_r__tan
    _x67 = math.cos(_Q4)
    _x68 = _x4*_x67
    _x69 = _x65*k_d
    _x70 = _x167**3
    _x71 = _P4**2
    _x72 = _x71*_x9
    _x73 = _x70*_x72
    _x74 = math.sin(_Q4)
    _x75 = _Q4__tan*_x4*_x74
    _x76 = k_d__tan*(-_x14 - _x65)
    _x77 = _P4*_x70
    _x78 = _P4__tan*_x77
    _x79 = _x66*(-3.0*_x167**4*_x72 - k_d)
    _x80 = 0.9336096058311416*_D + q_r
    _x168 = (1.0/_x80)
    _x81 = 0.9336096058311416*_D__tan + q_r__tan
    _x82 = math.cos(_Q5)
    _x83 = _x4*_x82
    _x84 = _x80*k_d
    _x85 = _x168**3
    _x86 = _P5**2
    _x87 = _x86*_x9
    _x88 = _x85*_x87
    _x89 = math.sin(_Q5)
    _x90 = _Q5__tan*_x4*_x89
    _x91 = k_d__tan*(-_x14 - _x80)
    _x92 = _P5*_x85
    _x93 = _P5__tan*_x92
    _x94 = _x81*(-3.0*_x168**4*_x87 - k_d)
    _x95 = 0.5871580340658094*_x11 + 0.5*_x2 + 0.140380692261653*_x23 + 0.140380692261653*_x24 - 0.140380692261653*_x28 - 0.08683151831711133*_x38 - 0.08683151831711133*_x39 + 0.08683151831711133*_x43 - 0.5871580340658094*_x5 + 0.052466581536012566*_x53 + 0.052466581536012566*_x54 - 0.052466581536012566*_x58 - 0.5871580340658094*_x6 - 0.026354606039126004*_x68 - 0.026354606039126004*_x69 + 0.026354606039126004*_x73 + 0.007496884624381081*_x83 + 0.007496884624381081*_x84 - 0.007496884624381081*_x88
    _x96 = _x18*_x9
    _x97 = _x33*_x9
    _x98 = _x48*_x9
    _x99 = _x63*_x9
    _x100 = _x78*_x9
    _x101 = _x9*_x93
    _x102 = 0.05270921207825201*_x100 - 0.014993769248762162*_x101 + 0.5871580340658094*_x13 + 0.5871580340658094*_x15 + 0.5871580340658094*_x19 - 0.140380692261653*_x30 - 0.140380692261653*_x31 - 0.140380692261653*_x34 + 0.08683151831711133*_x45 + 0.08683151831711133*_x46 + 0.08683151831711133*_x49 - 0.052466581536012566*_x60 - 0.052466581536012566*_x61 - 0.052466581536012566*_x64 + 0.026354606039126004*_x75 + 0.026354606039126004*_x76 + 0.026354606039126004*_x79 - 0.007496884624381081*_x90 - 0.007496884624381081*_x91 - 0.007496884624381081*_x94 + 1.1743160681316187*_x96 - 0.280761384523306*_x97 + 0.17366303663422267*_x98 - 0.10493316307202513*_x99
    _x103 = (1.0/math.sqrt(_x95))
    _x104 = math.sqrt(_D)
    _x105 = math.sqrt(m)
    _x106 = _x104*_x105
    _x107 = (1.0/_x104)
    _x108 = (0.5)*_x106
    _x109 = _x102/_x95**(1.5)
    _x110 = _x163**2
    _x111 = (1.0/_x105)
    _x112 = _x104*_x111
    _x113 = _x103*_x112
    _x114 = (0.5)*_x112
    _x115 = g_s*m**(1.5)
    _x116 = _x104*_x115
    _x117 = _x103*_x116*_x12
    _x118 = _x0*_x103
    _x119 = (0.5)*_D__tan*_x107*_x115
    _x120 = (0.5)*_x116
    _x121 = -0.5*k_d*l0
    _x122 = -_x121 - 0.41567911405660357*_x23 - 0.41567911405660357*_x24 + 0.41567911405660357*_x25*_x26*_x9 + 0.09720828549085844*_x35*k_d + 0.09720828549085844*_x37*g_s*m - 0.09720828549085844*_x43 - 0.147790320897128*_x5 - 0.05155355009455148*_x53 - 0.05155355009455148*_x54 + 0.05155355009455148*_x55*_x56*_x9 - 0.147790320897128*_x6 + 0.024719229415033087*_x65*k_d + 0.024719229415033087*_x67*g_s*m + 0.147790320897128*_x7*_x8*_x9 - 0.024719229415033087*_x73 - 0.006904529857608445*_x83 - 0.006904529857608445*_x84 + 0.006904529857608445*_x85*_x86*_x9
    _x123 = -0.04943845883006617*_x100 + 0.01380905971521689*_x101 + 0.147790320897128*_x13 + 0.147790320897128*_x15 + 0.147790320897128*_x19 + 0.41567911405660357*_x30 + 0.41567911405660357*_x31 + 0.41567911405660357*_x34 - 0.09720828549085844*_x45 - 0.09720828549085844*_x46 - 0.09720828549085844*_x49 + 0.05155355009455148*_x60 + 0.05155355009455148*_x61 + 0.05155355009455148*_x64 - 0.024719229415033087*_x75 - 0.024719229415033087*_x76 - 0.024719229415033087*_x79 + 0.006904529857608445*_x90 + 0.006904529857608445*_x91 + 0.006904529857608445*_x94 + 0.295580641794256*_x96 + 0.8313582281132071*_x97 - 0.19441657098171689*_x98 + 0.10310710018910296*_x99
    _x124 = (1.0/math.sqrt(_x122))
    _x125 = _x123/_x122**(1.5)
    _x126 = _x164**2
    _x127 = _x112*_x124
    _x128 = _x116*_x124*_x29
    _x129 = _x124*_x20
    _x130 = -_x121 - 0.25540525119175433*_x23 - 0.25540525119175433*_x24 + 0.25540525119175433*_x25*_x26*_x9 - 0.2685463444140672*_x38 - 0.2685463444140672*_x39 + 0.2685463444140672*_x40*_x41*_x9 - 0.010443786721981197*_x5 + 0.048794612428541204*_x50*k_d + 0.048794612428541204*_x52*g_s*m - 0.048794612428541204*_x58 - 0.010443786721981197*_x6 - 0.01951903325298492*_x68 - 0.01951903325298492*_x69 + 0.010443786721981197*_x7*_x8*_x9 + 0.01951903325298492*_x70*_x71*_x9 + 0.005119803152246505*_x80*k_d + 0.005119803152246505*_x82*g_s*m - 0.005119803152246505*_x88
    _x131 = 0.03903806650596984*_x100 - 0.01023960630449301*_x101 + 0.010443786721981197*_x13 + 0.010443786721981197*_x15 + 0.010443786721981197*_x19 + 0.25540525119175433*_x30 + 0.25540525119175433*_x31 + 0.25540525119175433*_x34 + 0.2685463444140672*_x45 + 0.2685463444140672*_x46 + 0.2685463444140672*_x49 - 0.048794612428541204*_x60 - 0.048794612428541204*_x61 - 0.048794612428541204*_x64 + 0.01951903325298492*_x75 + 0.01951903325298492*_x76 + 0.01951903325298492*_x79 - 0.005119803152246505*_x90 - 0.005119803152246505*_x91 - 0.005119803152246505*_x94 + 0.020887573443962394*_x96 + 0.5108105023835087*_x97 + 0.5370926888281344*_x98 - 0.09758922485708241*_x99
    _x132 = (1.0/math.sqrt(_x130))
    _x133 = _x131/_x130**(1.5)
    _x134 = _x165**2
    _x135 = _x112*_x132
    _x136 = _x116*_x132*_x44
    _x137 = _x132*_x35
    _x138 = -0.5*k_d*l0
    _x139 = -_x138 - 0.0662099828438604*_x23 - 0.0662099828438604*_x24 + 0.0662099828438604*_x25*_x26*_x9 - 0.2671819482314443*_x38 - 0.2671819482314443*_x39 + 0.2671819482314443*_x40*_x41*_x9 - 0.01101839635505667*_x5 - 0.1742495636223592*_x53 - 0.1742495636223592*_x54 + 0.1742495636223592*_x55*_x56*_x9 - 0.01101839635505667*_x6 + 0.02396692958086051*_x65*k_d + 0.02396692958086051*_x67*g_s*m + 0.01101839635505667*_x7*_x8*_x9 - 0.02396692958086051*_x73 - 0.00530703852813994*_x83 - 0.00530703852813994*_x84 + 0.00530703852813994*_x85*_x86*_x9
    _x140 = -0.04793385916172102*_x100 + 0.01061407705627988*_x101 + 0.01101839635505667*_x13 + 0.01101839635505667*_x15 + 0.01101839635505667*_x19 + 0.0662099828438604*_x30 + 0.0662099828438604*_x31 + 0.0662099828438604*_x34 + 0.2671819482314443*_x45 + 0.2671819482314443*_x46 + 0.2671819482314443*_x49 + 0.1742495636223592*_x60 + 0.1742495636223592*_x61 + 0.1742495636223592*_x64 - 0.02396692958086051*_x75 - 0.02396692958086051*_x76 - 0.02396692958086051*_x79 + 0.00530703852813994*_x90 + 0.00530703852813994*_x91 + 0.00530703852813994*_x94 + 0.02203679271011334*_x96 + 0.1324199656877208*_x97 + 0.5343638964628886*_x98 + 0.3484991272447184*_x99
    _x141 = (1.0/math.sqrt(_x139))
    _x142 = _x140/_x139**(1.5)
    _x143 = _x166**2
    _x144 = _x112*_x141
    _x145 = _x116*_x141*_x59
    _x146 = _x141*_x50
    _x147 = -_x121 - 0.050345455482979015*_x23 - 0.050345455482979015*_x24 + 0.050345455482979015*_x25*_x26*_x9 - 0.11622097556712797*_x38 - 0.11622097556712797*_x39 + 0.11622097556712797*_x40*_x41*_x9 - 0.0025147977064533143*_x5 - 0.2353986790647292*_x53 - 0.2353986790647292*_x54 + 0.2353986790647292*_x55*_x56*_x9 - 0.0025147977064533143*_x6 - 0.10372825048336794*_x68 - 0.10372825048336794*_x69 + 0.0025147977064533143*_x7*_x8*_x9 + 0.10372825048336794*_x70*_x71*_x9 + 0.008208158304657426*_x80*k_d + 0.008208158304657426*_x82*g_s*m - 0.008208158304657426*_x88
    _x148 = 0.20745650096673587*_x100 - 0.016416316609314852*_x101 + 0.0025147977064533143*_x13 + 0.0025147977064533143*_x15 + 0.0025147977064533143*_x19 + 0.050345455482979015*_x30 + 0.050345455482979015*_x31 + 0.050345455482979015*_x34 + 0.11622097556712797*_x45 + 0.11622097556712797*_x46 + 0.11622097556712797*_x49 + 0.2353986790647292*_x60 + 0.2353986790647292*_x61 + 0.2353986790647292*_x64 + 0.10372825048336794*_x75 + 0.10372825048336794*_x76 + 0.10372825048336794*_x79 - 0.008208158304657426*_x90 - 0.008208158304657426*_x91 - 0.008208158304657426*_x94 + 0.005029595412906629*_x96 + 0.10069091096595803*_x97 + 0.23244195113425595*_x98 + 0.4707973581294584*_x99
    _x149 = (1.0/math.sqrt(_x147))
    _x150 = _x148/_x147**(1.5)
    _x151 = _x167**2
    _x152 = _x112*_x149
    _x153 = _x116*_x149*_x74
    _x154 = _x149*_x65
    _x155 = -_x138 - 0.029703284805013122*_x23 - 0.029703284805013122*_x24 + 0.029703284805013122*_x25*_x26*_x9 - 0.10140664131431479*_x38 - 0.10140664131431479*_x39 + 0.10140664131431479*_x40*_x41*_x9 - 0.003959513229722528*_x5 - 0.14531313573962065*_x53 - 0.14531313573962065*_x54 + 0.14531313573962065*_x55*_x56*_x9 - 0.003959513229722528*_x6 - 0.17612158869639333*_x68 - 0.17612158869639333*_x69 + 0.003959513229722528*_x7*_x8*_x9 + 0.17612158869639333*_x70*_x71*_x9 - 0.04349583621493557*_x83 - 0.04349583621493557*_x84 + 0.04349583621493557*_x85*_x86*_x9
    _x156 = 0.35224317739278665*_x100 + 0.08699167242987114*_x101 + 0.003959513229722528*_x13 + 0.003959513229722528*_x15 + 0.003959513229722528*_x19 + 0.029703284805013122*_x30 + 0.029703284805013122*_x31 + 0.029703284805013122*_x34 + 0.10140664131431479*_x45 + 0.10140664131431479*_x46 + 0.10140664131431479*_x49 + 0.14531313573962065*_x60 + 0.14531313573962065*_x61 + 0.14531313573962065*_x64 + 0.17612158869639333*_x75 + 0.17612158869639333*_x76 + 0.17612158869639333*_x79 + 0.04349583621493557*_x90 + 0.04349583621493557*_x91 + 0.04349583621493557*_x94 + 0.007919026459445056*_x96 + 0.059406569610026244*_x97 + 0.20281328262862958*_x98 + 0.2906262714792413*_x99
    _x157 = (1.0/math.sqrt(_x155))
    _x158 = _x156/_x155**(1.5)
    _x159 = _x168**2
    _x160 = _x112*_x157
    _x161 = _x116*_x157*_x89
    _x162 = _x157*_x80
    _isigma0 = _x0
    _isigma0__tan = _x1
    _iF0 = _x11 + _x2 - _x5 - _x6
    _iF0__tan = _x13 + _x15 + _x16*_x18 + _x19
    _isigma1 = _x20
    _isigma1__tan = _x21
    _iF1 = _x2 - _x23 - _x24 + _x28
    _iF1__tan = _x16*_x33 + _x30 + _x31 + _x34
    _isigma2 = _x35
    _isigma2__tan = _x36
    _iF2 = _x2 - _x38 - _x39 + _x43
    _iF2__tan = _x16*_x48 + _x45 + _x46 + _x49
    _isigma3 = _x50
    _isigma3__tan = _x51
    _iF3 = _x2 - _x53 - _x54 + _x58
    _iF3__tan = _x16*_x63 + _x60 + _x61 + _x64
    _isigma4 = _x65
    _isigma4__tan = _x66
    _iF4 = _x2 - _x68 - _x69 + _x73
    _iF4__tan = _x16*_x78 + _x75 + _x76 + _x79
    _isigma5 = _x80
    _isigma5__tan = _x81
    _iF5 = _x2 - _x83 - _x84 + _x88
    _iF5__tan = _x16*_x93 + _x90 + _x91 + _x94
    _iPsi0 = _x95
    _iPsi0__tan = _x102
    _ift0 = _x103*_x106
    _ift0__tan = (0.5)*_D__tan*_x103*_x105*_x107 - _x108*_x109
    _ifq0 = _P0*_x110*_x113
    _ifq0__tan = (0.5)*_D__tan*_P0*_x103*_x107*_x110*_x111 - _P0*_x109*_x110*_x114 + _P0__tan*_x103*_x104*_x110*_x111 - 2.0*_x1*_x113*_x17
    _ifp0 = _x0*_x117
    _ifp0__tan = _Q0__tan*_x116*_x118*_x3 - _x0*_x109*_x12*_x120 + _x1*_x117 + _x118*_x119*_x12
    _iPsi1 = _x122
    _iPsi1__tan = _x123
    _ift1 = _x106*_x124
    _ift1__tan = (0.5)*_D__tan*_x105*_x107*_x124 - _x108*_x125
    _ifq1 = _P1*_x126*_x127
    _ifq1__tan = (0.5)*_D__tan*_P1*_x107*_x111*_x124*_x126 - _P1*_x114*_x125*_x126 + _P1__tan*_x104*_x111*_x124*_x126 - 2.0*_x127*_x21*_x32
    _ifp1 = _x128*_x20
    _ifp1__tan = _Q1__tan*_x116*_x129*_x22 + _x119*_x129*_x29 - _x120*_x125*_x20*_x29 + _x128*_x21
    _iPsi2 = _x130
    _iPsi2__tan = _x131
    _ift2 = _x106*_x132
    _ift2__tan = (0.5)*_D__tan*_x105*_x107*_x132 - _x108*_x133
    _ifq2 = _P2*_x134*_x135
    _ifq2__tan = (0.5)*_D__tan*_P2*_x107*_x111*_x132*_x134 - _P2*_x114*_x133*_x134 + _P2__tan*_x104*_x111*_x132*_x134 - 2.0*_x135*_x36*_x47
    _ifp2 = _x136*_x35
    _ifp2__tan = _Q2__tan*_x116*_x137*_x37 + _x119*_x137*_x44 - _x120*_x133*_x35*_x44 + _x136*_x36
    _iPsi3 = _x139
    _iPsi3__tan = _x140
    _ift3 = _x106*_x141
    _ift3__tan = (0.5)*_D__tan*_x105*_x107*_x141 - _x108*_x142
    _ifq3 = _P3*_x143*_x144
    _ifq3__tan = (0.5)*_D__tan*_P3*_x107*_x111*_x141*_x143 - _P3*_x114*_x142*_x143 + _P3__tan*_x104*_x111*_x141*_x143 - 2.0*_x144*_x51*_x62
    _ifp3 = _x145*_x50
    _ifp3__tan = _Q3__tan*_x116*_x146*_x52 + _x119*_x146*_x59 - _x120*_x142*_x50*_x59 + _x145*_x51
    _iPsi4 = _x147
    _iPsi4__tan = _x148
    _ift4 = _x106*_x149
    _ift4__tan = (0.5)*_D__tan*_x105*_x107*_x149 - _x108*_x150
    _ifq4 = _P4*_x151*_x152
    _ifq4__tan = (0.5)*_D__tan*_P4*_x107*_x111*_x149*_x151 - _P4*_x114*_x150*_x151 + _P4__tan*_x104*_x111*_x149*_x151 - 2.0*_x152*_x66*_x77
    _ifp4 = _x153*_x65
    _ifp4__tan = _Q4__tan*_x116*_x154*_x67 + _x119*_x154*_x74 - _x120*_x150*_x65*_x74 + _x153*_x66
    _iPsi5 = _x155
    _iPsi5__tan = _x156
    _ift5 = _x106*_x157
    _ift5__tan = (0.5)*_D__tan*_x105*_x107*_x157 - _x108*_x158
    _ifq5 = _P5*_x159*_x160
    _ifq5__tan = (0.5)*_D__tan*_P5*_x107*_x111*_x157*_x159 - _P5*_x114*_x158*_x159 + _P5__tan*_x104*_x111*_x157*_x159 - 2.0*_x160*_x81*_x92
    _ifp5 = _x161*_x80
    _ifp5__tan = _Q5__tan*_x116*_x162*_x82 + _x119*_x162*_x89 - _x120*_x158*_x80*_x89 + _x161*_x81
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi3 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi4 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_iPsi5 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # next values
    _x169 = m*q_r**2
    _x170 = _x169*q_thd
    _x171 = _x169*q_thd__tan + 2.0*m*q_r*q_r__tan*q_thd
    _next_D = _D
    _next_Q0 = 0.04283112309479259*_ifq0 - 0.014763725997197413*_ifq1 + 0.009325050706477751*_ifq2 - 0.005668858049483512*_ifq3 + 0.002854433315099335*_ifq4 - 0.0008127801712647621*_ifq5 + q_th
    _next_Q1 = 0.09267349143037887*_ifq0 + 0.09019039326203465*_ifq1 - 0.020300102293239586*_ifq2 + 0.010363156240246424*_ifq3 - 0.004887192928037671*_ifq4 + 0.0013555610554850618*_ifq5 + q_th
    _next_Q2 = 0.08224792261284387*_ifq0 + 0.196032162333245*_ifq1 + 0.11697848364317276*_ifq2 - 0.020482527745656096*_ifq3 + 0.007989991899662336*_ifq4 - 0.002075625784866334*_ifq5 + q_th
    _next_Q3 = 0.0877378719744515*_ifq0 + 0.17239079462440696*_ifq1 + 0.25443949503200164*_ifq2 + 0.11697848364317276*_ifq3 - 0.0156513758091757*_ifq4 + 0.0034143235767412987*_ifq5 + q_th
    _next_Q4 = 0.08430668513410011*_ifq0 + 0.18526797945210696*_ifq1 + 0.2235938110460991*_ifq2 + 0.2542570695795851*_ifq3 + 0.09019039326203465*_ifq4 - 0.007011245240793691*_ifq5 + q_th
    _next_Q5 = 0.08647502636084993*_ifq0 + 0.17752635320896998*_ifq1 + 0.23962582533582905*_ifq2 + 0.22463191657986778*_ifq3 + 0.19514451252126672*_ifq4 + 0.04283112309479259*_ifq5 + q_th
    _next_P0 = 0.04283112309479259*_ifp0 - 0.014763725997197413*_ifp1 + 0.009325050706477751*_ifp2 - 0.005668858049483512*_ifp3 + 0.002854433315099335*_ifp4 - 0.0008127801712647621*_ifp5 + _x170
    _next_P1 = 0.09267349143037887*_ifp0 + 0.09019039326203465*_ifp1 - 0.020300102293239586*_ifp2 + 0.010363156240246424*_ifp3 - 0.004887192928037671*_ifp4 + 0.0013555610554850618*_ifp5 + _x170
    _next_P2 = 0.08224792261284387*_ifp0 + 0.196032162333245*_ifp1 + 0.11697848364317276*_ifp2 - 0.020482527745656096*_ifp3 + 0.007989991899662336*_ifp4 - 0.002075625784866334*_ifp5 + _x170
    _next_P3 = 0.0877378719744515*_ifp0 + 0.17239079462440696*_ifp1 + 0.25443949503200164*_ifp2 + 0.11697848364317276*_ifp3 - 0.0156513758091757*_ifp4 + 0.0034143235767412987*_ifp5 + _x170
    _next_P4 = 0.08430668513410011*_ifp0 + 0.18526797945210696*_ifp1 + 0.2235938110460991*_ifp2 + 0.2542570695795851*_ifp3 + 0.09019039326203465*_ifp4 - 0.007011245240793691*_ifp5 + _x170
    _next_P5 = 0.08647502636084993*_ifp0 + 0.17752635320896998*_ifp1 + 0.23962582533582905*_ifp2 + 0.22463191657986778*_ifp3 + 0.19514451252126672*_ifp4 + 0.04283112309479259*_ifp5 + _x170
    _next_D__tan = _D__tan
    _next_Q0__tan = 0.04283112309479259*_ifq0__tan - 0.014763725997197413*_ifq1__tan + 0.009325050706477751*_ifq2__tan - 0.005668858049483512*_ifq3__tan + 0.002854433315099335*_ifq4__tan - 0.0008127801712647621*_ifq5__tan + q_th__tan
    _next_Q1__tan = 0.09267349143037887*_ifq0__tan + 0.09019039326203465*_ifq1__tan - 0.020300102293239586*_ifq2__tan + 0.010363156240246424*_ifq3__tan - 0.004887192928037671*_ifq4__tan + 0.0013555610554850618*_ifq5__tan + q_th__tan
    _next_Q2__tan = 0.08224792261284387*_ifq0__tan + 0.196032162333245*_ifq1__tan + 0.11697848364317276*_ifq2__tan - 0.020482527745656096*_ifq3__tan + 0.007989991899662336*_ifq4__tan - 0.002075625784866334*_ifq5__tan + q_th__tan
    _next_Q3__tan = 0.0877378719744515*_ifq0__tan + 0.17239079462440696*_ifq1__tan + 0.25443949503200164*_ifq2__tan + 0.11697848364317276*_ifq3__tan - 0.0156513758091757*_ifq4__tan + 0.0034143235767412987*_ifq5__tan + q_th__tan
    _next_Q4__tan = 0.08430668513410011*_ifq0__tan + 0.18526797945210696*_ifq1__tan + 0.2235938110460991*_ifq2__tan + 0.2542570695795851*_ifq3__tan + 0.09019039326203465*_ifq4__tan - 0.007011245240793691*_ifq5__tan + q_th__tan
    _next_Q5__tan = 0.08647502636084993*_ifq0__tan + 0.17752635320896998*_ifq1__tan + 0.23962582533582905*_ifq2__tan + 0.22463191657986778*_ifq3__tan + 0.19514451252126672*_ifq4__tan + 0.04283112309479259*_ifq5__tan + q_th__tan
    _next_P0__tan = 0.04283112309479259*_ifp0__tan - 0.014763725997197413*_ifp1__tan + 0.009325050706477751*_ifp2__tan - 0.005668858049483512*_ifp3__tan + 0.002854433315099335*_ifp4__tan - 0.0008127801712647621*_ifp5__tan + _x171
    _next_P1__tan = 0.09267349143037887*_ifp0__tan + 0.09019039326203465*_ifp1__tan - 0.020300102293239586*_ifp2__tan + 0.010363156240246424*_ifp3__tan - 0.004887192928037671*_ifp4__tan + 0.0013555610554850618*_ifp5__tan + _x171
    _next_P2__tan = 0.08224792261284387*_ifp0__tan + 0.196032162333245*_ifp1__tan + 0.11697848364317276*_ifp2__tan - 0.020482527745656096*_ifp3__tan + 0.007989991899662336*_ifp4__tan - 0.002075625784866334*_ifp5__tan + _x171
    _next_P3__tan = 0.0877378719744515*_ifp0__tan + 0.17239079462440696*_ifp1__tan + 0.25443949503200164*_ifp2__tan + 0.11697848364317276*_ifp3__tan - 0.0156513758091757*_ifp4__tan + 0.0034143235767412987*_ifp5__tan + _x171
    _next_P4__tan = 0.08430668513410011*_ifp0__tan + 0.18526797945210696*_ifp1__tan + 0.2235938110460991*_ifp2__tan + 0.2542570695795851*_ifp3__tan + 0.09019039326203465*_ifp4__tan - 0.007011245240793691*_ifp5__tan + _x171
    _next_P5__tan = 0.08647502636084993*_ifp0__tan + 0.17752635320896998*_ifp1__tan + 0.23962582533582905*_ifp2__tan + 0.22463191657986778*_ifp3__tan + 0.19514451252126672*_ifp4__tan + 0.04283112309479259*_ifp5__tan + _x171
    # (internal helper: its callers check that their outputs are finite)
    return (_next_D, _next_Q0, _next_Q1, _next_Q2, _next_Q3, _next_Q4, _next_Q5, _next_P0, _next_P1, _next_P2, _next_P3, _next_P4, _next_P5, _next_D__tan, _next_Q0__tan, _next_Q1__tan, _next_Q2__tan, _next_Q3__tan, _next_Q4__tan, _next_Q5__tan, _next_P0__tan, _next_P1__tan, _next_P2__tan, _next_P3__tan, _next_P4__tan, _next_P5__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_13(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _P4, _P4__tan, _P5, _P5__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _Q4, _Q4__tan, _Q5, _Q5__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan):
    """continuation of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        _D: value of the caller's variable
        _D__tan: value of the caller's variable
        _P0: value of the caller's variable
        _P0__tan: value of the caller's variable
        _P1: value of the caller's variable
        _P1__tan: value of the caller's variable
        _P2: value of the caller's variable
        _P2__tan: value of the caller's variable
        _P3: value of the caller's variable
        _P3__tan: value of the caller's variable
        _P4: value of the caller's variable
        _P4__tan: value of the caller's variable
        _P5: value of the caller's variable
        _P5__tan: value of the caller's variable
        _Q0: value of the caller's variable
        _Q0__tan: value of the caller's variable
        _Q1: value of the caller's variable
        _Q1__tan: value of the caller's variable
        _Q2: value of the caller's variable
        _Q2__tan: value of the caller's variable
        _Q3: value of the caller's variable
        _Q3__tan: value of the caller's variable
        _Q4: value of the caller's variable
        _Q4__tan: value of the caller's variable
        _Q5: value of the caller's variable
        _Q5__tan: value of the caller's variable
        _passes: value of the caller's variable
        g_s: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable

    Returns a tuple:
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1231
    # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
    _x0 = 0.0011400916279895713*_D + q_r
    _x163 = (1.0/_x0)
    _x1 = 0.0011400916279895713*_D__tan + q_r__tan
    _x2 = k_d*l0
    _x3 = math.cos(_Q0)
    _x4 = g_s*m
    _x5 = _x3*_x4
    _x6 = _x0*k_d
    _x7 = _x163**3
    _x8 = _P0**2
    _x9 = (1.0/m)
    _x10 = _x8*_x9
    _x11 = _x10*_x7
    _x12 = math.sin(_Q0)
    _x13 = _Q0__tan*_x12*_x4
    _x14 = -l0
    _x15 = k_d__tan*(-_x0 - _x14)
    _x16 = 2.0*_x9
    _x17 = _P0*_x7
    _x18 = _P0__tan*_x17
    _x19 = _x1*(-3.0*_x10*_x163**4 - k_d)
    _x20 = 0.02869476995464123*_D + q_r
    _x164 = (1.0/_x20)
    _x21 = 0.02869476995464123*_D__tan + q_r__tan
    _x22 = math.cos(_Q1)
    _x23 = _x22*_x4
    _x24 = _x20*k_d
    _x25 = _x164**3
    _x26 = _P1**2
    _x27 = _x26*_x9
    _x28 = _x25*_x27
    _x29 = math.sin(_Q1)
    _x30 = _Q1__tan*_x29*_x4
    _x31 = k_d__tan*(-_x14 - _x20)
    _x32 = _P1*_x25
    _x33 = _P1__tan*_x32
    _x34 = _x21*(-3.0*_x164**4*_x27 - k_d)
    _x35 = 0.14492518595015338*_D + q_r
    _x165 = (1.0/_x35)
    _x36 = 0.14492518595015338*_D__tan + q_r__tan
    _x37 = math.cos(_Q2)
    _x38 = _x37*_x4
    _x39 = _x35*k_d
    _x40 = _x165**3
    _x41 = _P2**2
    _x42 = _x41*_x9
    _x43 = _x40*_x42
    _x44 = math.sin(_Q2)
    _x45 = _Q2__tan*_x4*_x44
    _x46 = k_d__tan*(-_x14 - _x35)
    _x47 = _P2*_x40
    _x48 = _P2__tan*_x47
    _x49 = _x36*(-3.0*_x165**4*_x42 - k_d)
    _x50 = 0.3835443720333503*_D + q_r
    _x166 = (1.0/_x50)
    _x51 = 0.3835443720333503*_D__tan + q_r__tan
    _x52 = math.cos(_Q3)
    _x53 = _x4*_x52
    _x54 = _x50*k_d
    _x55 = _x166**3
    _x56 = _P3**2
    _x57 = _x56*_x9
    _x58 = _x55*_x57
    _x59 = math.sin(_Q3)
    _x60 = _Q3__tan*_x4*_x59
    _x61 = k_d__tan*(-_x14 - _x50)
    _x62 = _P3*_x55
    _x63 = _P3__tan*_x62
    _x64 = _x51*(-3.0*_x166**4*_x57 - k_d)
    _x65 = 0.6899041564209057*_D + q_r
    _x167 = (1.0/_x65)
    _x66 = 0.6899041564209057*_D__tan + q_r__tan
    _x67 = math.cos(_Q4)
    _x68 = _x4*_x67
    _x69 = _x65*k_d
    _x70 = _x167**3
    _x71 = _P4**2
    _x72 = _x71*_x9
    _x73 = _x70*_x72
    _x74 = math.sin(_Q4)
    _x75 = _Q4__tan*_x4*_x74
    _x76 = k_d__tan*(-_x14 - _x65)
    _x77 = _P4*_x70
    _x78 = _P4__tan*_x77
    _x79 = _x66*(-3.0*_x167**4*_x72 - k_d)
    _x80 = 0.9336096058311416*_D + q_r
    _x168 = (1.0/_x80)
    _x81 = 0.9336096058311416*_D__tan + q_r__tan
    _x82 = math.cos(_Q5)
    _x83 = _x4*_x82
    _x84 = _x80*k_d
    _x85 = _x168**3
    _x86 = _P5**2
    _x87 = _x86*_x9
    _x88 = _x85*_x87
    _x89 = math.sin(_Q5)
    _x90 = _Q5__tan*_x4*_x89
    _x91 = k_d__tan*(-_x14 - _x80)
    _x92 = _P5*_x85
    _x93 = _P5__tan*_x92
    _x94 = _x81*(-3.0*_x168**4*_x87 - k_d)
    _x95 = 0.5871580340658094*_x11 + 0.5*_x2 + 0.140380692261653*_x23 + 0.140380692261653*_x24 - 0.140380692261653*_x28 - 0.08683151831711133*_x38 - 0.08683151831711133*_x39 + 0.08683151831711133*_x43 - 0.5871580340658094*_x5 + 0.052466581536012566*_x53 + 0.052466581536012566*_x54 - 0.052466581536012566*_x58 - 0.5871580340658094*_x6 - 0.026354606039126004*_x68 - 0.026354606039126004*_x69 + 0.026354606039126004*_x73 + 0.007496884624381081*_x83 + 0.007496884624381081*_x84 - 0.007496884624381081*_x88
    _x96 = _x18*_x9
    _x97 = _x33*_x9
    _x98 = _x48*_x9
    _x99 = _x63*_x9
    _x100 = _x78*_x9
    _x101 = _x9*_x93
    _x102 = 0.05270921207825201*_x100 - 0.014993769248762162*_x101 + 0.5871580340658094*_x13 + 0.5871580340658094*_x15 + 0.5871580340658094*_x19 - 0.140380692261653*_x30 - 0.140380692261653*_x31 - 0.140380692261653*_x34 + 0.08683151831711133*_x45 + 0.08683151831711133*_x46 + 0.08683151831711133*_x49 - 0.052466581536012566*_x60 - 0.052466581536012566*_x61 - 0.052466581536012566*_x64 + 0.026354606039126004*_x75 + 0.026354606039126004*_x76 + 0.026354606039126004*_x79 - 0.007496884624381081*_x90 - 0.007496884624381081*_x91 - 0.007496884624381081*_x94 + 1.1743160681316187*_x96 - 0.280761384523306*_x97 + 0.17366303663422267*_x98 - 0.10493316307202513*_x99
    _x103 = (1.0/math.sqrt(_x95))
    _x104 = math.sqrt(_D)
    _x105 = math.sqrt(m)
    _x106 = _x104*_x105
    _x107 = (1.0/_x104)
    _x108 = (0.5)*_x106
    _x109 = _x102/_x95**(1.5)
    _x110 = _x163**2
    _x111 = (1.0/_x105)
    _x112 = _x104*_x111
    _x113 = _x103*_x112
    _x114 = (0.5)*_x112
    _x115 = g_s*m**(1.5)
    _x116 = _x104*_x115
    _x117 = _x103*_x116*_x12
    _x118 = _x0*_x103
    _x119 = (0.5)*_D__tan*_x107*_x115
    _x120 = (0.5)*_x116
    _x121 = -0.5*k_d*l0
    _x122 = -_x121 - 0.41567911405660357*_x23 - 0.41567911405660357*_x24 + 0.41567911405660357*_x25*_x26*_x9 + 0.09720828549085844*_x35*k_d + 0.09720828549085844*_x37*g_s*m - 0.09720828549085844*_x43 - 0.147790320897128*_x5 - 0.05155355009455148*_x53 - 0.05155355009455148*_x54 + 0.05155355009455148*_x55*_x56*_x9 - 0.147790320897128*_x6 + 0.024719229415033087*_x65*k_d + 0.024719229415033087*_x67*g_s*m + 0.147790320897128*_x7*_x8*_x9 - 0.024719229415033087*_x73 - 0.006904529857608445*_x83 - 0.006904529857608445*_x84 + 0.006904529857608445*_x85*_x86*_x9
    _x123 = -0.04943845883006617*_x100 + 0.01380905971521689*_x101 + 0.147790320897128*_x13 + 0.147790320897128*_x15 + 0.147790320897128*_x19 + 0.41567911405660357*_x30 + 0.41567911405660357*_x31 + 0.41567911405660357*_x34 - 0.09720828549085844*_x45 - 0.09720828549085844*_x46 - 0.09720828549085844*_x49 + 0.05155355009455148*_x60 + 0.05155355009455148*_x61 + 0.05155355009455148*_x64 - 0.024719229415033087*_x75 - 0.024719229415033087*_x76 - 0.024719229415033087*_x79 + 0.006904529857608445*_x90 + 0.006904529857608445*_x91 + 0.006904529857608445*_x94 + 0.295580641794256*_x96 + 0.8313582281132071*_x97 - 0.19441657098171689*_x98 + 0.10310710018910296*_x99
    _x124 = (1.0/math.sqrt(_x122))
    _x125 = _x123/_x122**(1.5)
    _x126 = _x164**2
    _x127 = _x112*_x124
    _x128 = _x116*_x124*_x29
    _x129 = _x124*_x20
    _x130 = -_x121 - 0.25540525119175433*_x23 - 0.25540525119175433*_x24 + 0.25540525119175433*_x25*_x26*_x9 - 0.2685463444140672*_x38 - 0.2685463444140672*_x39 + 0.2685463444140672*_x40*_x41*_x9 - 0.010443786721981197*_x5 + 0.048794612428541204*_x50*k_d + 0.048794612428541204*_x52*g_s*m - 0.048794612428541204*_x58 - 0.010443786721981197*_x6 - 0.01951903325298492*_x68 - 0.01951903325298492*_x69 + 0.010443786721981197*_x7*_x8*_x9 + 0.01951903325298492*_x70*_x71*_x9 + 0.005119803152246505*_x80*k_d + 0.005119803152246505*_x82*g_s*m - 0.005119803152246505*_x88
    _x131 = 0.03903806650596984*_x100 - 0.01023960630449301*_x101 + 0.010443786721981197*_x13 + 0.010443786721981197*_x15 + 0.010443786721981197*_x19 + 0.25540525119175433*_x30 + 0.25540525119175433*_x31 + 0.25540525119175433*_x34 + 0.2685463444140672*_x45 + 0.2685463444140672*_x46 + 0.2685463444140672*_x49 - 0.048794612428541204*_x60 - 0.048794612428541204*_x61 - 0.048794612428541204*_x64 + 0.01951903325298492*_x75 + 0.01951903325298492*_x76 + 0.01951903325298492*_x79 - 0.005119803152246505*_x90 - 0.005119803152246505*_x91 - 0.005119803152246505*_x94 + 0.020887573443962394*_x96 + 0.5108105023835087*_x97 + 0.5370926888281344*_x98 - 0.09758922485708241*_x99
    _x132 = (1.0/math.sqrt(_x130))
    _x133 = _x131/_x130**(1.5)
    _x134 = _x165**2
    _x135 = _x112*_x132
    _x136 = _x116*_x132*_x44
    _x137 = _x132*_x35
    _x138 = -0.5*k_d*l0
    _x139 = -_x138 - 0.0662099828438604*_x23 - 0.0662099828438604*_x24 + 0.0662099828438604*_x25*_x26*_x9 - 0.2671819482314443*_x38 - 0.2671819482314443*_x39 + 0.2671819482314443*_x40*_x41*_x9 - 0.01101839635505667*_x5 - 0.1742495636223592*_x53 - 0.1742495636223592*_x54 + 0.1742495636223592*_x55*_x56*_x9 - 0.01101839635505667*_x6 + 0.02396692958086051*_x65*k_d + 0.02396692958086051*_x67*g_s*m + 0.01101839635505667*_x7*_x8*_x9 - 0.02396692958086051*_x73 - 0.00530703852813994*_x83 - 0.00530703852813994*_x84 + 0.00530703852813994*_x85*_x86*_x9
    _x140 = -0.04793385916172102*_x100 + 0.01061407705627988*_x101 + 0.01101839635505667*_x13 + 0.01101839635505667*_x15 + 0.01101839635505667*_x19 + 0.0662099828438604*_x30 + 0.0662099828438604*_x31 + 0.0662099828438604*_x34 + 0.2671819482314443*_x45 + 0.2671819482314443*_x46 + 0.2671819482314443*_x49 + 0.1742495636223592*_x60 + 0.1742495636223592*_x61 + 0.1742495636223592*_x64 - 0.02396692958086051*_x75 - 0.02396692958086051*_x76 - 0.02396692958086051*_x79 + 0.00530703852813994*_x90 + 0.00530703852813994*_x91 + 0.00530703852813994*_x94 + 0.02203679271011334*_x96 + 0.1324199656877208*_x97 + 0.5343638964628886*_x98 + 0.3484991272447184*_x99
    _x141 = (1.0/math.sqrt(_x139))
    _x142 = _x140/_x139**(1.5)
    _x143 = _x166**2
    _x144 = _x112*_x141
    _x145 = _x116*_x141*_x59
    _x146 = _x141*_x50
    _x147 = -_x121 - 0.050345455482979015*_x23 - 0.050345455482979015*_x24 + 0.050345455482979015*_x25*_x26*_x9 - 0.11622097556712797*_x38 - 0.11622097556712797*_x39 + 0.11622097556712797*_x40*_x41*_x9 - 0.0025147977064533143*_x5 - 0.2353986790647292*_x53 - 0.2353986790647292*_x54 + 0.2353986790647292*_x55*_x56*_x9 - 0.0025147977064533143*_x6 - 0.10372825048336794*_x68 - 0.10372825048336794*_x69 + 0.0025147977064533143*_x7*_x8*_x9 + 0.10372825048336794*_x70*_x71*_x9 + 0.008208158304657426*_x80*k_d + 0.008208158304657426*_x82*g_s*m - 0.008208158304657426*_x88
    _x148 = 0.20745650096673587*_x100 - 0.016416316609314852*_x101 + 0.0025147977064533143*_x13 + 0.0025147977064533143*_x15 + 0.0025147977064533143*_x19 + 0.050345455482979015*_x30 + 0.050345455482979015*_x31 + 0.050345455482979015*_x34 + 0.11622097556712797*_x45 + 0.11622097556712797*_x46 + 0.11622097556712797*_x49 + 0.2353986790647292*_x60 + 0.2353986790647292*_x61 + 0.2353986790647292*_x64 + 0.10372825048336794*_x75 + 0.10372825048336794*_x76 + 0.10372825048336794*_x79 - 0.008208158304657426*_x90 - 0.008208158304657426*_x91 - 0.008208158304657426*_x94 + 0.005029595412906629*_x96 + 0.10069091096595803*_x97 + 0.23244195113425595*_x98 + 0.4707973581294584*_x99
    _x149 = (1.0/math.sqrt(_x147))
    _x150 = _x148/_x147**(1.5)
    _x151 = _x167**2
    _x152 = _x112*_x149
    _x153 = _x116*_x149*_x74
    _x154 = _x149*_x65
    _x155 = -_x138 - 0.029703284805013122*_x23 - 0.029703284805013122*_x24 + 0.029703284805013122*_x25*_x26*_x9 - 0.10140664131431479*_x38 - 0.10140664131431479*_x39 + 0.10140664131431479*_x40*_x41*_x9 - 0.003959513229722528*_x5 - 0.14531313573962065*_x53 - 0.14531313573962065*_x54 + 0.14531313573962065*_x55*_x56*_x9 - 0.003959513229722528*_x6 - 0.17612158869639333*_x68 - 0.17612158869639333*_x69 + 0.003959513229722528*_x7*_x8*_x9 + 0.17612158869639333*_x70*_x71*_x9 - 0.04349583621493557*_x83 - 0.04349583621493557*_x84 + 0.04349583621493557*_x85*_x86*_x9
    _x156 = 0.35224317739278665*_x100 + 0.08699167242987114*_x101 + 0.003959513229722528*_x13 + 0.003959513229722528*_x15 + 0.003959513229722528*_x19 + 0.029703284805013122*_x30 + 0.029703284805013122*_x31 + 0.029703284805013122*_x34 + 0.10140664131431479*_x45 + 0.10140664131431479*_x46 + 0.10140664131431479*_x49 + 0.14531313573962065*_x60 + 0.14531313573962065*_x61 + 0.14531313573962065*_x64 + 0.17612158869639333*_x75 + 0.17612158869639333*_x76 + 0.17612158869639333*_x79 + 0.04349583621493557*_x90 + 0.04349583621493557*_x91 + 0.04349583621493557*_x94 + 0.007919026459445056*_x96 + 0.059406569610026244*_x97 + 0.20281328262862958*_x98 + 0.2906262714792413*_x99
    _x157 = (1.0/math.sqrt(_x155))
    _x158 = _x156/_x155**(1.5)
    _x159 = _x168**2
    _x160 = _x112*_x157
    _x161 = _x116*_x157*_x89
    _x162 = _x157*_x80
    _fsigma0 = _x0
    _fsigma0__tan = _x1
    _fF0 = _x11 + _x2 - _x5 - _x6
    _fF0__tan = _x13 + _x15 + _x16*_x18 + _x19
    _fsigma1 = _x20
    _fsigma1__tan = _x21
    _fF1 = _x2 - _x23 - _x24 + _x28
    _fF1__tan = _x16*_x33 + _x30 + _x31 + _x34
    _fsigma2 = _x35
    _fsigma2__tan = _x36
    _fF2 = _x2 - _x38 - _x39 + _x43
    _fF2__tan = _x16*_x48 + _x45 + _x46 + _x49
    _fsigma3 = _x50
    _fsigma3__tan = _x51
    _fF3 = _x2 - _x53 - _x54 + _x58
    _fF3__tan = _x16*_x63 + _x60 + _x61 + _x64
    _fsigma4 = _x65
    _fsigma4__tan = _x66
    _fF4 = _x2 - _x68 - _x69 + _x73
    _fF4__tan = _x16*_x78 + _x75 + _x76 + _x79
    _fsigma5 = _x80
    _fsigma5__tan = _x81
    _fF5 = _x2 - _x83 - _x84 + _x88
    _fF5__tan = _x16*_x93 + _x90 + _x91 + _x94
    _fPsi0 = _x95
    _fPsi0__tan = _x102
    _fft0 = _x103*_x106
    _fft0__tan = (0.5)*_D__tan*_x103*_x105*_x107 - _x108*_x109
    _ffq0 = _P0*_x110*_x113
    _ffq0__tan = (0.5)*_D__tan*_P0*_x103*_x107*_x110*_x111 - _P0*_x109*_x110*_x114 + _P0__tan*_x103*_x104*_x110*_x111 - 2.0*_x1*_x113*_x17
    _ffp0 = _x0*_x117
    _ffp0__tan = _Q0__tan*_x116*_x118*_x3 - _x0*_x109*_x12*_x120 + _x1*_x117 + _x118*_x119*_x12
    _fPsi1 = _x122
    _fPsi1__tan = _x123
    _fft1 = _x106*_x124
    _fft1__tan = (0.5)*_D__tan*_x105*_x107*_x124 - _x108*_x125
    _ffq1 = _P1*_x126*_x127
    _ffq1__tan = (0.5)*_D__tan*_P1*_x107*_x111*_x124*_x126 - _P1*_x114*_x125*_x126 + _P1__tan*_x104*_x111*_x124*_x126 - 2.0*_x127*_x21*_x32
    _ffp1 = _x128*_x20
    _ffp1__tan = _Q1__tan*_x116*_x129*_x22 + _x119*_x129*_x29 - _x120*_x125*_x20*_x29 + _x128*_x21
    _fPsi2 = _x130
    _fPsi2__tan = _x131
    _fft2 = _x106*_x132
    _fft2__tan = (0.5)*_D__tan*_x105*_x107*_x132 - _x108*_x133
    _ffq2 = _P2*_x134*_x135
    _ffq2__tan = (0.5)*_D__tan*_P2*_x107*_x111*_x132*_x134 - _P2*_x114*_x133*_x134 + _P2__tan*_x104*_x111*_x132*_x134 - 2.0*_x135*_x36*_x47
    _ffp2 = _x136*_x35
    _ffp2__tan = _Q2__tan*_x116*_x137*_x37 + _x119*_x137*_x44 - _x120*_x133*_x35*_x44 + _x136*_x36
    _fPsi3 = _x139
    _fPsi3__tan = _x140
    _fft3 = _x106*_x141
    _fft3__tan = (0.5)*_D__tan*_x105*_x107*_x141 - _x108*_x142
    _ffq3 = _P3*_x143*_x144
    _ffq3__tan = (0.5)*_D__tan*_P3*_x107*_x111*_x141*_x143 - _P3*_x114*_x142*_x143 + _P3__tan*_x104*_x111*_x141*_x143 - 2.0*_x144*_x51*_x62
    _ffp3 = _x145*_x50
    _ffp3__tan = _Q3__tan*_x116*_x146*_x52 + _x119*_x146*_x59 - _x120*_x142*_x50*_x59 + _x145*_x51
    _fPsi4 = _x147
    _fPsi4__tan = _x148
    _fft4 = _x106*_x149
    _fft4__tan = (0.5)*_D__tan*_x105*_x107*_x149 - _x108*_x150
    _ffq4 = _P4*_x151*_x152
    _ffq4__tan = (0.5)*_D__tan*_P4*_x107*_x111*_x149*_x151 - _P4*_x114*_x150*_x151 + _P4__tan*_x104*_x111*_x149*_x151 - 2.0*_x152*_x66*_x77
    _ffp4 = _x153*_x65
    _ffp4__tan = _Q4__tan*_x116*_x154*_x67 + _x119*_x154*_x74 - _x120*_x150*_x65*_x74 + _x153*_x66
    _fPsi5 = _x155
    _fPsi5__tan = _x156
    _fft5 = _x106*_x157
    _fft5__tan = (0.5)*_D__tan*_x105*_x107*_x157 - _x108*_x158
    _ffq5 = _P5*_x159*_x160
    _ffq5__tan = (0.5)*_D__tan*_P5*_x107*_x111*_x157*_x159 - _P5*_x114*_x158*_x159 + _P5__tan*_x104*_x111*_x157*_x159 - 2.0*_x160*_x81*_x92
    _ffp5 = _x161*_x80
    _ffp5__tan = _Q5__tan*_x116*_x162*_x82 + _x119*_x162*_x89 - _x120*_x158*_x80*_x89 + _x161*_x81
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi1 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi3 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi4 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    # p_r^2 = 2 m int F_r > 0 at every node
    if not ((_fPsi5 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_IMAGINARY_MOMENTUM)
    _work = 0.0028924065498159377*_fF0 + 0.030555658668093604*_fF1 + 0.08906517308699231*_fF2 + 0.14489179419935322*_fF3 + 0.1498251278559757*_fF4 + 0.08276983963976924*_fF5
    _work__tan = 0.0028924065498159377*_fF0__tan + 0.030555658668093604*_fF1__tan + 0.08906517308699231*_fF2__tan + 0.14489179419935322*_fF3__tan + 0.1498251278559757*_fF4__tan + 0.08276983963976924*_fF5__tan
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    _x169 = math.sqrt(_D*_work)/math.sqrt(m)
    _x170 = q_r**2
    _x171 = q_r_lo**-2
    _x172 = _x171/m
    _x173 = 0.08566224618958518*_x172
    _x174 = 0.1803807865240693*_x172
    _x175 = 0.23395696728634552*_x172
    t_half = 0.08566224618958518*_fft0 + 0.1803807865240693*_fft1 + 0.23395696728634552*_fft2 + 0.23395696728634552*_fft3 + 0.1803807865240693*_fft4 + 0.08566224618958518*_fft5
    t_half__tan = 0.08566224618958518*_fft0__tan + 0.1803807865240693*_fft1__tan + 0.23395696728634552*_fft2__tan + 0.23395696728634552*_fft3__tan + 0.1803807865240693*_fft4__tan + 0.08566224618958518*_fft5__tan
    end_q_th = 0.08566224618958518*_ffq0 + 0.1803807865240693*_ffq1 + 0.23395696728634552*_ffq2 + 0.23395696728634552*_ffq3 + 0.1803807865240693*_ffq4 + 0.08566224618958518*_ffq5 + q_th
    end_q_th__tan = 0.08566224618958518*_ffq0__tan + 0.1803807865240693*_ffq1__tan + 0.23395696728634552*_ffq2__tan + 0.23395696728634552*_ffq3__tan + 0.1803807865240693*_ffq4__tan + 0.08566224618958518*_ffq5__tan + q_th__tan
    end_q_r = q_r_lo
    end_q_rd = 2.0*_x169
    end_q_rd__tan = _work__tan*_x169/_work + _D__tan*_x169/_D
    end_q_thd = _x172*(0.08566224618958518*_ffp0 + 0.1803807865240693*_ffp1 + 0.23395696728634552*_ffp2 + 0.23395696728634552*_ffp3 + 0.1803807865240693*_ffp4 + 0.08566224618958518*_ffp5 + _x170*m*q_thd)
    end_q_thd__tan = _ffp0__tan*_x173 + _ffp1__tan*_x174 + _ffp2__tan*_x175 + _ffp3__tan*_x175 + _ffp4__tan*_x174 + _ffp5__tan*_x173 + _x170*_x171*q_thd__tan + 2.0*_x171*q_r*q_r__tan*q_thd
    passes = _passes
    # (internal helper: its callers check that their outputs are finite)
    return (_fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_14(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol):
    """branch nodes = 4 of schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        g_s: value of the caller's variable
        guess_q_th: value of the caller's variable
        guess_q_th__tan: value of the caller's variable
        guess_q_thd: value of the caller's variable
        guess_q_thd__tan: value of the caller's variable
        iterations: value of the caller's variable
        k_d: value of the caller's variable
        k_d__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        q_r: value of the caller's variable
        q_r__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th: value of the caller's variable
        q_th__tan: value of the caller's variable
        q_thd: value of the caller's variable
        q_thd__tan: value of the caller's variable
        tol: value of the caller's variable

    Returns a tuple:
        _D: result for the caller
        _Q0: result for the caller
        _P0: result for the caller
        _D__tan: result for the caller
        _Q0__tan: result for the caller
        _P0__tan: result for the caller
        _passes: result for the caller
        _fsigma0: result for the caller
        _fsigma0__tan: result for the caller
        _fF0: result for the caller
        _fF0__tan: result for the caller
        _fPsi0: result for the caller
        _fPsi0__tan: result for the caller
        _fft0: result for the caller
        _fft0__tan: result for the caller
        _ffq0: result for the caller
        _ffq0__tan: result for the caller
        _ffp0: result for the caller
        _ffp0__tan: result for the caller
        _work: result for the caller
        _work__tan: result for the caller
        t_half: result for the caller
        t_half__tan: result for the caller
        end_q_th: result for the caller
        end_q_th__tan: result for the caller
        end_q_r: result for the caller
        end_q_rd: result for the caller
        end_q_rd__tan: result for the caller
        end_q_thd: result for the caller
        end_q_thd__tan: result for the caller
        passes: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # Picard passes on the 6 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.03376524289842399*guess_q_th + 0.966234757101576*q_th
    _Q1 = 0.16939530676686773*guess_q_th + 0.8306046932331322*q_th
    _Q2 = 0.38069040695840156*guess_q_th + 0.6193095930415985*q_th
    _Q3 = 0.6193095930415985*guess_q_th + 0.38069040695840156*q_th
    _Q4 = 0.8306046932331322*guess_q_th + 0.16939530676686773*q_th
    _Q5 = 0.966234757101576*guess_q_th + 0.03376524289842399*q_th
    _P0 = 0.03376524289842399*guess_q_thd*m*q_r_lo**2 + 0.966234757101576*m*q_r**2*q_thd
    _P1 = 0.16939530676686773*guess_q_thd*m*q_r_lo**2 + 0.8306046932331322*m*q_r**2*q_thd
    _P2 = 0.38069040695840156*guess_q_thd*m*q_r_lo**2 + 0.6193095930415985*m*q_r**2*q_thd
    _P3 = 0.6193095930415985*guess_q_thd*m*q_r_lo**2 + 0.38069040695840156*m*q_r**2*q_thd
    _P4 = 0.8306046932331322*guess_q_thd*m*q_r_lo**2 + 0.16939530676686773*m*q_r**2*q_thd
    _P5 = 0.966234757101576*guess_q_thd*m*q_r_lo**2 + 0.03376524289842399*m*q_r**2*q_thd
    _D__tan = -q_r__tan
    _Q0__tan = 0.03376524289842399*guess_q_th__tan + 0.966234757101576*q_th__tan
    _Q1__tan = 0.16939530676686773*guess_q_th__tan + 0.8306046932331322*q_th__tan
    _Q2__tan = 0.38069040695840156*guess_q_th__tan + 0.6193095930415985*q_th__tan
    _Q3__tan = 0.6193095930415985*guess_q_th__tan + 0.38069040695840156*q_th__tan
    _Q4__tan = 0.8306046932331322*guess_q_th__tan + 0.16939530676686773*q_th__tan
    _Q5__tan = 0.966234757101576*guess_q_th__tan + 0.03376524289842399*q_th__tan
    _P0__tan = 0.03376524289842399*guess_q_thd__tan*m*q_r_lo**2 + 0.966234757101576*m*q_r**2*q_thd__tan + 1.932469514203152*m*q_r*q_r__tan*q_thd
    _P1__tan = 0.16939530676686773*guess_q_thd__tan*m*q_r_lo**2 + 0.8306046932331322*m*q_r**2*q_thd__tan + 1.6612093864662645*m*q_r*q_r__tan*q_thd
    _P2__tan = 0.38069040695840156*guess_q_thd__tan*m*q_r_lo**2 + 0.6193095930415985*m*q_r**2*q_thd__tan + 1.238619186083197*m*q_r*q_r__tan*q_thd
    _P3__tan = 0.6193095930415985*guess_q_thd__tan*m*q_r_lo**2 + 0.38069040695840156*m*q_r**2*q_thd__tan + 0.7613808139168031*m*q_r*q_r__tan*q_thd
    _P4__tan = 0.8306046932331322*guess_q_thd__tan*m*q_r_lo**2 + 0.16939530676686773*m*q_r**2*q_thd__tan + 0.33879061353373546*m*q_r*q_r__tan*q_thd
    _P5__tan = 0.966234757101576*guess_q_thd__tan*m*q_r_lo**2 + 0.03376524289842399*m*q_r**2*q_thd__tan + 0.06753048579684798*m*q_r*q_r__tan*q_thd
    _passes = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        # loop body
        _c0 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_12(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _P4, _P4__tan, _P5, _P5__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _Q4, _Q4__tan, _Q5, _Q5__tan, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_th, q_th__tan, q_thd, q_thd__tan)
        if _c0[26] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[26])
        _next_D = _c0[0]
        _next_Q0 = _c0[1]
        _next_Q1 = _c0[2]
        _next_Q2 = _c0[3]
        _next_Q3 = _c0[4]
        _next_Q4 = _c0[5]
        _next_Q5 = _c0[6]
        _next_P0 = _c0[7]
        _next_P1 = _c0[8]
        _next_P2 = _c0[9]
        _next_P3 = _c0[10]
        _next_P4 = _c0[11]
        _next_P5 = _c0[12]
        _next_D__tan = _c0[13]
        _next_Q0__tan = _c0[14]
        _next_Q1__tan = _c0[15]
        _next_Q2__tan = _c0[16]
        _next_Q3__tan = _c0[17]
        _next_Q4__tan = _c0[18]
        _next_Q5__tan = _c0[19]
        _next_P0__tan = _c0[20]
        _next_P1__tan = _c0[21]
        _next_P2__tan = _c0[22]
        _next_P3__tan = _c0[23]
        _next_P4__tan = _c0[24]
        _next_P5__tan = _c0[25]
        _n0_0 = _next_D
        _n0_1 = _next_Q0
        _n0_2 = _next_Q1
        _n0_3 = _next_Q2
        _n0_4 = _next_Q3
        _n0_5 = _next_Q4
        _n0_6 = _next_Q5
        _n0_7 = _next_P0
        _n0_8 = _next_P1
        _n0_9 = _next_P2
        _n0_10 = _next_P3
        _n0_11 = _next_P4
        _n0_12 = _next_P5
        _n0_13 = _next_D__tan
        _n0_14 = _next_Q0__tan
        _n0_15 = _next_Q1__tan
        _n0_16 = _next_Q2__tan
        _n0_17 = _next_Q3__tan
        _n0_18 = _next_Q4__tan
        _n0_19 = _next_Q5__tan
        _n0_20 = _next_P0__tan
        _n0_21 = _next_P1__tan
        _n0_22 = _next_P2__tan
        _n0_23 = _next_P3__tan
        _n0_24 = _next_P4__tan
        _n0_25 = _next_P5__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0)) and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3) <= tol*(1.0)) and (abs(_n0_5 - _Q4) <= tol*(1.0)) and (abs(_n0_6 - _Q5) <= tol*(1.0)) and (abs(_n0_7 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_9 - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_10 - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_11 - _P4) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_12 - _P5) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _Q4 = _n0_5
        _Q5 = _n0_6
        _P0 = _n0_7
        _P1 = _n0_8
        _P2 = _n0_9
        _P3 = _n0_10
        _P4 = _n0_11
        _P5 = _n0_12
        _D__tan = _n0_13
        _Q0__tan = _n0_14
        _Q1__tan = _n0_15
        _Q2__tan = _n0_16
        _Q3__tan = _n0_17
        _Q4__tan = _n0_18
        _Q5__tan = _n0_19
        _P0__tan = _n0_20
        _P1__tan = _n0_21
        _P2__tan = _n0_22
        _P3__tan = _n0_23
        _P4__tan = _n0_24
        _P5__tan = _n0_25
        _passes += 1.0
        if _conv0:
            break
    if not _conv0 and tol > 0.0 and _passes > 0.0:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NOT_CONVERGED)
    # continuation
    _c1 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_13(_D, _D__tan, _P0, _P0__tan, _P1, _P1__tan, _P2, _P2__tan, _P3, _P3__tan, _P4, _P4__tan, _P5, _P5__tan, _Q0, _Q0__tan, _Q1, _Q1__tan, _Q2, _Q2__tan, _Q3, _Q3__tan, _Q4, _Q4__tan, _Q5, _Q5__tan, _passes, g_s, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan)
    if _c1[24] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[24])
    _fsigma0 = _c1[0]
    _fsigma0__tan = _c1[1]
    _fF0 = _c1[2]
    _fF0__tan = _c1[3]
    _fPsi0 = _c1[4]
    _fPsi0__tan = _c1[5]
    _fft0 = _c1[6]
    _fft0__tan = _c1[7]
    _ffq0 = _c1[8]
    _ffq0__tan = _c1[9]
    _ffp0 = _c1[10]
    _ffp0__tan = _c1[11]
    _work = _c1[12]
    _work__tan = _c1[13]
    t_half = _c1[14]
    t_half__tan = _c1[15]
    end_q_th = _c1[16]
    end_q_th__tan = _c1[17]
    end_q_r = _c1[18]
    end_q_rd = _c1[19]
    end_q_rd__tan = _c1[20]
    end_q_thd = _c1[21]
    end_q_thd__tan = _c1[22]
    passes = _c1[23]
    # (internal helper: its callers check that their outputs are finite)
    return (_D, _Q0, _P0, _D__tan, _Q0__tan, _P0__tan, _passes, _fsigma0, _fsigma0__tan, _fF0, _fF0__tan, _fPsi0, _fPsi0__tan, _fft0, _fft0__tan, _ffq0, _ffq0__tan, _ffp0, _ffp0__tan, _work, _work__tan, t_half, t_half__tan, end_q_th, end_q_th__tan, end_q_r, end_q_rd, end_q_rd__tan, end_q_thd, end_q_thd__tan, passes, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd(q_r, q_rd, q_th, q_thd, m, l0, k_d, g_s, q_r_lo, guess_q_th, guess_q_thd, nodes, iterations, tol, q_r__tan, q_rd__tan, q_th__tan, q_thd__tan, k_d__tan, guess_q_th__tan, guess_q_thd__tan):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of p_r), with the derivative of every output along the direction (q_r__tan, q_rd__tan, q_th__tan, q_thd__tan, k_d__tan, guess_q_th__tan, guess_q_thd__tan).

    Report equations: 29, 30, 31, 32, 37, 41.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        q_r: bottom state: leg length [m]
        q_rd: bottom state: leg length rate [m/s]
        q_th: bottom state: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: bottom state: leg angle rate [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        guess_q_th: zeroth iterate's liftoff q_th
        guess_q_thd: zeroth iterate's liftoff q_thd
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]
        q_r__tan: direction: its component along q_r
        q_rd__tan: direction: its component along q_rd
        q_th__tan: direction: its component along q_th
        q_thd__tan: direction: its component along q_thd
        k_d__tan: direction: its component along k_d
        guess_q_th__tan: direction: its component along guess_q_th
        guess_q_thd__tan: direction: its component along guess_q_thd

    Returns a tuple:
        t_half: time of the decompression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        t_half__tan: derivative of t_half along the direction
        end_q_r__tan: derivative of end_q_r along the direction
        end_q_rd__tan: derivative of end_q_rd along the direction
        end_q_th__tan: derivative of end_q_th along the direction
        end_q_thd__tan: derivative of end_q_thd along the direction
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(q_r__tan) and math.isfinite(q_rd__tan) and math.isfinite(q_th__tan) and math.isfinite(q_thd__tan) and math.isfinite(k_d__tan) and math.isfinite(guess_q_th__tan) and math.isfinite(guess_q_thd__tan) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_RECOMPRESSION)
    # node count
    if nodes == 0.0:
        # branch nodes = 0
        _c0 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_2(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c0[31] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[31])
        _D = _c0[0]
        _Q0 = _c0[1]
        _P0 = _c0[2]
        _D__tan = _c0[3]
        _Q0__tan = _c0[4]
        _P0__tan = _c0[5]
        _passes = _c0[6]
        _fsigma0 = _c0[7]
        _fsigma0__tan = _c0[8]
        _fF0 = _c0[9]
        _fF0__tan = _c0[10]
        _fPsi0 = _c0[11]
        _fPsi0__tan = _c0[12]
        _fft0 = _c0[13]
        _fft0__tan = _c0[14]
        _ffq0 = _c0[15]
        _ffq0__tan = _c0[16]
        _ffp0 = _c0[17]
        _ffp0__tan = _c0[18]
        _work = _c0[19]
        _work__tan = _c0[20]
        t_half = _c0[21]
        t_half__tan = _c0[22]
        end_q_th = _c0[23]
        end_q_th__tan = _c0[24]
        end_q_r = _c0[25]
        end_q_rd = _c0[26]
        end_q_rd__tan = _c0[27]
        end_q_thd = _c0[28]
        end_q_thd__tan = _c0[29]
        passes = _c0[30]
    elif nodes == 1.0:
        # branch nodes = 1
        _c1 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_5(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c1[31] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[31])
        _D = _c1[0]
        _Q0 = _c1[1]
        _P0 = _c1[2]
        _D__tan = _c1[3]
        _Q0__tan = _c1[4]
        _P0__tan = _c1[5]
        _passes = _c1[6]
        _fsigma0 = _c1[7]
        _fsigma0__tan = _c1[8]
        _fF0 = _c1[9]
        _fF0__tan = _c1[10]
        _fPsi0 = _c1[11]
        _fPsi0__tan = _c1[12]
        _fft0 = _c1[13]
        _fft0__tan = _c1[14]
        _ffq0 = _c1[15]
        _ffq0__tan = _c1[16]
        _ffp0 = _c1[17]
        _ffp0__tan = _c1[18]
        _work = _c1[19]
        _work__tan = _c1[20]
        t_half = _c1[21]
        t_half__tan = _c1[22]
        end_q_th = _c1[23]
        end_q_th__tan = _c1[24]
        end_q_r = _c1[25]
        end_q_rd = _c1[26]
        end_q_rd__tan = _c1[27]
        end_q_thd = _c1[28]
        end_q_thd__tan = _c1[29]
        passes = _c1[30]
    elif nodes == 2.0:
        # branch nodes = 2
        _c2 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_8(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c2[31] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[31])
        _D = _c2[0]
        _Q0 = _c2[1]
        _P0 = _c2[2]
        _D__tan = _c2[3]
        _Q0__tan = _c2[4]
        _P0__tan = _c2[5]
        _passes = _c2[6]
        _fsigma0 = _c2[7]
        _fsigma0__tan = _c2[8]
        _fF0 = _c2[9]
        _fF0__tan = _c2[10]
        _fPsi0 = _c2[11]
        _fPsi0__tan = _c2[12]
        _fft0 = _c2[13]
        _fft0__tan = _c2[14]
        _ffq0 = _c2[15]
        _ffq0__tan = _c2[16]
        _ffp0 = _c2[17]
        _ffp0__tan = _c2[18]
        _work = _c2[19]
        _work__tan = _c2[20]
        t_half = _c2[21]
        t_half__tan = _c2[22]
        end_q_th = _c2[23]
        end_q_th__tan = _c2[24]
        end_q_r = _c2[25]
        end_q_rd = _c2[26]
        end_q_rd__tan = _c2[27]
        end_q_thd = _c2[28]
        end_q_thd__tan = _c2[29]
        passes = _c2[30]
    elif nodes == 3.0:
        # branch nodes = 3
        _c3 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_11(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c3[31] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[31])
        _D = _c3[0]
        _Q0 = _c3[1]
        _P0 = _c3[2]
        _D__tan = _c3[3]
        _Q0__tan = _c3[4]
        _P0__tan = _c3[5]
        _passes = _c3[6]
        _fsigma0 = _c3[7]
        _fsigma0__tan = _c3[8]
        _fF0 = _c3[9]
        _fF0__tan = _c3[10]
        _fPsi0 = _c3[11]
        _fPsi0__tan = _c3[12]
        _fft0 = _c3[13]
        _fft0__tan = _c3[14]
        _ffq0 = _c3[15]
        _ffq0__tan = _c3[16]
        _ffp0 = _c3[17]
        _ffp0__tan = _c3[18]
        _work = _c3[19]
        _work__tan = _c3[20]
        t_half = _c3[21]
        t_half__tan = _c3[22]
        end_q_th = _c3[23]
        end_q_th__tan = _c3[24]
        end_q_r = _c3[25]
        end_q_rd = _c3[26]
        end_q_rd__tan = _c3[27]
        end_q_thd = _c3[28]
        end_q_thd__tan = _c3[29]
        passes = _c3[30]
    elif nodes == 4.0:
        # branch nodes = 4
        _c4 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd_14(g_s, guess_q_th, guess_q_th__tan, guess_q_thd, guess_q_thd__tan, iterations, k_d, k_d__tan, l0, m, q_r, q_r__tan, q_r_lo, q_th, q_th__tan, q_thd, q_thd__tan, tol)
        if _c4[31] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[31])
        _D = _c4[0]
        _Q0 = _c4[1]
        _P0 = _c4[2]
        _D__tan = _c4[3]
        _Q0__tan = _c4[4]
        _P0__tan = _c4[5]
        _passes = _c4[6]
        _fsigma0 = _c4[7]
        _fsigma0__tan = _c4[8]
        _fF0 = _c4[9]
        _fF0__tan = _c4[10]
        _fPsi0 = _c4[11]
        _fPsi0__tan = _c4[12]
        _fft0 = _c4[13]
        _fft0__tan = _c4[14]
        _ffq0 = _c4[15]
        _ffq0__tan = _c4[16]
        _ffp0 = _c4[17]
        _ffp0__tan = _c4[18]
        _work = _c4[19]
        _work__tan = _c4[20]
        t_half = _c4[21]
        t_half__tan = _c4[22]
        end_q_th = _c4[23]
        end_q_th__tan = _c4[24]
        end_q_r = _c4[25]
        end_q_rd = _c4[26]
        end_q_rd__tan = _c4[27]
        end_q_thd = _c4[28]
        end_q_thd__tan = _c4[29]
        passes = _c4[30]
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives that are identically zero
    end_q_r__tan = 0.0
    passes__tan = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, t_half__tan, end_q_r__tan, end_q_rd__tan, end_q_th__tan, end_q_thd__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_0(g_s, k_c, k_c__tan, l0, m, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 1 of iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

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
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_1(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 0 of iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

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
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_2(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 2 of iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

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
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_3(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 3 of iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

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
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_4(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 4 of iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

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
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_5(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 5 of iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

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
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_6(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 6 of iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

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
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_7(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 7 of iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

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
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_8(g_s, k_c, k_c__tan, k_d, k_d__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan):
    """branch zeroth = 8 of iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d (outlined: derive/outline.py).

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
def iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, k_d__tan):
    """Iterative stance map (Schwind and Koditschek, converging form): touchdown state -> bottom and liftoff states, with the derivative of every output along the direction (q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, k_d__tan).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

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
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs
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
        passes: Picard passes run (the larger of the two halves) [1]
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
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 41
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(zeroth) and math.isfinite(q_r_td__tan) and math.isfinite(q_rd_td__tan) and math.isfinite(q_th_td__tan) and math.isfinite(q_thd_td__tan) and math.isfinite(k_c__tan) and math.isfinite(k_d__tan) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate
    if zeroth == 1.0:
        # branch zeroth = 1
        _c0 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_0(g_s, k_c, k_c__tan, l0, m, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c0[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[10])
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
        _c1 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_1(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c1[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[10])
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
        _c2 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_2(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c2[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[10])
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
        _c3 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_3(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c3[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[10])
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
        _c4 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_4(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c4[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[10])
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
        _c5 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_5(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c5[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c5[10])
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
        _c6 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_6(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c6[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c6[10])
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
        _c7 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_7(g_s, k_c, k_c__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c7[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c7[10])
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
        _c8 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d_8(g_s, k_c, k_c__tan, k_d, k_d__tan, l0, m, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, q_thd_td, q_thd_td__tan)
        if _c8[10] != STATUS_OK:
            return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c8[10])
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
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # compression half, k_c (report 5.2.1)
    _c9 = schwind_compression_jvp_q_r_q_rd_q_th_q_thd_k_c_guess_q_r_guess_q_th_guess_q_thd(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th, z_b_q_thd, nodes, iterations, tol, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k_c__tan, z_b_q_r__tan, z_b_q_th__tan, z_b_q_thd__tan)
    if _c9[12] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c9[12])
    t_bottom = _c9[0]
    bottom_q_r = _c9[1]
    bottom_q_rd = _c9[2]
    bottom_q_th = _c9[3]
    bottom_q_thd = _c9[4]
    c_passes = _c9[5]
    t_bottom__tan = _c9[6]
    bottom_q_r__tan = _c9[7]
    bottom_q_rd__tan = _c9[8]
    bottom_q_th__tan = _c9[9]
    bottom_q_thd__tan = _c9[10]
    c_passes__tan = _c9[11]
    # zeroth iterate at liftoff
    _x0 = (zeroth == 1.0)
    _x1 = ((0.0) if _x0 else (1.0))
    _x2 = q_r_lo**-2
    _x3 = _x2*bottom_q_r**2
    g_lo_q_th = ((bottom_q_th) if _x0 else (z_lo_q_th))
    g_lo_q_th__tan = _x1*z_lo_q_th__tan + bottom_q_th__tan*((1.0) if _x0 else (0.0))
    g_lo_q_thd = ((_x3*bottom_q_thd) if _x0 else (z_lo_q_thd))
    g_lo_q_thd__tan = _x1*z_lo_q_thd__tan + bottom_q_r__tan*((2.0*_x2*bottom_q_r*bottom_q_thd) if _x0 else (0.0)) + bottom_q_thd__tan*((_x3) if _x0 else (0.0))
    # decompression half, k_d (report 3.2, 5.2.2)
    _c10 = schwind_decompression_jvp_q_r_q_rd_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, nodes, iterations, tol, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, k_d__tan, g_lo_q_th__tan, g_lo_q_thd__tan)
    if _c10[12] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c10[12])
    t_decompression = _c10[0]
    liftoff_q_r = _c10[1]
    liftoff_q_rd = _c10[2]
    liftoff_q_th = _c10[3]
    liftoff_q_thd = _c10[4]
    d_passes = _c10[5]
    t_decompression__tan = _c10[6]
    liftoff_q_r__tan = _c10[7]
    liftoff_q_rd__tan = _c10[8]
    liftoff_q_th__tan = _c10[9]
    liftoff_q_thd__tan = _c10[10]
    d_passes__tan = _c10[11]
    _x4 = c_passes - d_passes
    _x5 = (0.5)*(0.0 if _x4 == 0 else math.copysign(1, _x4))
    t_stance = t_bottom + t_decompression
    t_stance__tan = t_bottom__tan + t_decompression__tan
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(_x4)
    passes__tan = c_passes__tan*(_x5 + 0.5) + d_passes__tan*(0.5 - _x5)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

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
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs

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
        passes: Picard passes run (the larger of the two halves) [1]
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
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(zeroth) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives with respect to q_r_td
    _c0 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if _c0[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[22])
    d_t_bottom__q_r_td = _c0[11]
    d_t_stance__q_r_td = _c0[12]
    d_bottom_q_r__q_r_td = _c0[13]
    d_bottom_q_rd__q_r_td = _c0[14]
    d_bottom_q_th__q_r_td = _c0[15]
    d_bottom_q_thd__q_r_td = _c0[16]
    d_liftoff_q_r__q_r_td = _c0[17]
    d_liftoff_q_rd__q_r_td = _c0[18]
    d_liftoff_q_th__q_r_td = _c0[19]
    d_liftoff_q_thd__q_r_td = _c0[20]
    d_passes__q_r_td = _c0[21]
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
    passes = _c0[10]
    # derivatives with respect to q_rd_td
    _c1 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    if _c1[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[22])
    d_t_bottom__q_rd_td = _c1[11]
    d_t_stance__q_rd_td = _c1[12]
    d_bottom_q_r__q_rd_td = _c1[13]
    d_bottom_q_rd__q_rd_td = _c1[14]
    d_bottom_q_th__q_rd_td = _c1[15]
    d_bottom_q_thd__q_rd_td = _c1[16]
    d_liftoff_q_r__q_rd_td = _c1[17]
    d_liftoff_q_rd__q_rd_td = _c1[18]
    d_liftoff_q_th__q_rd_td = _c1[19]
    d_liftoff_q_thd__q_rd_td = _c1[20]
    d_passes__q_rd_td = _c1[21]
    # derivatives with respect to q_th_td
    _c2 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    if _c2[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[22])
    d_t_bottom__q_th_td = _c2[11]
    d_t_stance__q_th_td = _c2[12]
    d_bottom_q_r__q_th_td = _c2[13]
    d_bottom_q_rd__q_th_td = _c2[14]
    d_bottom_q_th__q_th_td = _c2[15]
    d_bottom_q_thd__q_th_td = _c2[16]
    d_liftoff_q_r__q_th_td = _c2[17]
    d_liftoff_q_rd__q_th_td = _c2[18]
    d_liftoff_q_th__q_th_td = _c2[19]
    d_liftoff_q_thd__q_th_td = _c2[20]
    d_passes__q_th_td = _c2[21]
    # derivatives with respect to q_thd_td
    _c3 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    if _c3[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[22])
    d_t_bottom__q_thd_td = _c3[11]
    d_t_stance__q_thd_td = _c3[12]
    d_bottom_q_r__q_thd_td = _c3[13]
    d_bottom_q_rd__q_thd_td = _c3[14]
    d_bottom_q_th__q_thd_td = _c3[15]
    d_bottom_q_thd__q_thd_td = _c3[16]
    d_liftoff_q_r__q_thd_td = _c3[17]
    d_liftoff_q_rd__q_thd_td = _c3[18]
    d_liftoff_q_th__q_thd_td = _c3[19]
    d_liftoff_q_thd__q_thd_td = _c3[20]
    d_passes__q_thd_td = _c3[21]
    # derivatives with respect to k_c
    _c4 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    if _c4[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[22])
    d_t_bottom__k_c = _c4[11]
    d_t_stance__k_c = _c4[12]
    d_bottom_q_r__k_c = _c4[13]
    d_bottom_q_rd__k_c = _c4[14]
    d_bottom_q_th__k_c = _c4[15]
    d_bottom_q_thd__k_c = _c4[16]
    d_liftoff_q_r__k_c = _c4[17]
    d_liftoff_q_rd__k_c = _c4[18]
    d_liftoff_q_th__k_c = _c4[19]
    d_liftoff_q_thd__k_c = _c4[20]
    d_passes__k_c = _c4[21]
    # derivatives with respect to k_d
    _c5 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    if _c5[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c5[22])
    d_t_bottom__k_d = _c5[11]
    d_t_stance__k_d = _c5[12]
    d_bottom_q_r__k_d = _c5[13]
    d_bottom_q_rd__k_d = _c5[14]
    d_bottom_q_th__k_d = _c5[15]
    d_bottom_q_thd__k_d = _c5[16]
    d_liftoff_q_r__k_d = _c5[17]
    d_liftoff_q_rd__k_d = _c5[18]
    d_liftoff_q_th__k_d = _c5[19]
    d_liftoff_q_thd__k_d = _c5[20]
    d_passes__k_d = _c5[21]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r) and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(passes) and math.isfinite(d_t_bottom__q_r_td) and math.isfinite(d_t_bottom__q_rd_td) and math.isfinite(d_t_bottom__q_th_td) and math.isfinite(d_t_bottom__q_thd_td) and math.isfinite(d_t_bottom__k_c) and math.isfinite(d_t_bottom__k_d) and math.isfinite(d_t_stance__q_r_td) and math.isfinite(d_t_stance__q_rd_td) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__q_thd_td) and math.isfinite(d_t_stance__k_c) and math.isfinite(d_t_stance__k_d) and math.isfinite(d_bottom_q_r__q_r_td) and math.isfinite(d_bottom_q_r__q_rd_td) and math.isfinite(d_bottom_q_r__q_th_td) and math.isfinite(d_bottom_q_r__q_thd_td) and math.isfinite(d_bottom_q_r__k_c) and math.isfinite(d_bottom_q_r__k_d) and math.isfinite(d_bottom_q_rd__q_r_td) and math.isfinite(d_bottom_q_rd__q_rd_td) and math.isfinite(d_bottom_q_rd__q_th_td) and math.isfinite(d_bottom_q_rd__q_thd_td) and math.isfinite(d_bottom_q_rd__k_c) and math.isfinite(d_bottom_q_rd__k_d) and math.isfinite(d_bottom_q_th__q_r_td) and math.isfinite(d_bottom_q_th__q_rd_td) and math.isfinite(d_bottom_q_th__q_th_td) and math.isfinite(d_bottom_q_th__q_thd_td) and math.isfinite(d_bottom_q_th__k_c) and math.isfinite(d_bottom_q_th__k_d) and math.isfinite(d_bottom_q_thd__q_r_td) and math.isfinite(d_bottom_q_thd__q_rd_td) and math.isfinite(d_bottom_q_thd__q_th_td) and math.isfinite(d_bottom_q_thd__q_thd_td) and math.isfinite(d_bottom_q_thd__k_c) and math.isfinite(d_bottom_q_thd__k_d) and math.isfinite(d_liftoff_q_r__q_r_td) and math.isfinite(d_liftoff_q_r__q_rd_td) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__q_thd_td) and math.isfinite(d_liftoff_q_r__k_c) and math.isfinite(d_liftoff_q_r__k_d) and math.isfinite(d_liftoff_q_rd__q_r_td) and math.isfinite(d_liftoff_q_rd__q_rd_td) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__q_thd_td) and math.isfinite(d_liftoff_q_rd__k_c) and math.isfinite(d_liftoff_q_rd__k_d) and math.isfinite(d_liftoff_q_th__q_r_td) and math.isfinite(d_liftoff_q_th__q_rd_td) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__q_thd_td) and math.isfinite(d_liftoff_q_th__k_c) and math.isfinite(d_liftoff_q_th__k_d) and math.isfinite(d_liftoff_q_thd__q_r_td) and math.isfinite(d_liftoff_q_thd__q_rd_td) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__q_thd_td) and math.isfinite(d_liftoff_q_thd__k_c) and math.isfinite(d_liftoff_q_thd__k_d) and math.isfinite(d_passes__q_r_td) and math.isfinite(d_passes__q_rd_td) and math.isfinite(d_passes__q_th_td) and math.isfinite(d_passes__q_thd_td) and math.isfinite(d_passes__k_c) and math.isfinite(d_passes__k_d)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_passes__q_r_td, d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth.
    Writes output j of row i to ``out[i, j]`` (shape (n, 77)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_passes__q_r_td, d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d.
    """
    for i in prange(out.shape[0]):
        res = iterative_stance_jacobian(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth)
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
        status[i] = res[77]


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan, k_c__tan, k_d__tan):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, converging form), with the derivative of every output along the direction (b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan, k_c__tan, k_d__tan).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

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
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs
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
        passes: Picard passes run (the larger of the two halves) [1]
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
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 5
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(zeroth) and math.isfinite(b_y_apex__tan) and math.isfinite(b_xd_apex__tan) and math.isfinite(q_th_td__tan) and math.isfinite(ground__tan) and math.isfinite(k_c__tan) and math.isfinite(k_d__tan) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td_ground(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, ground__tan)
    if _c0[12] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[12])
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
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = iterative_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, k_c__tan, k_d__tan)
    if _c1[22] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[22])
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    passes = _c1[10]
    t_stance__tan = _c1[12]
    liftoff_q_r__tan = _c1[17]
    liftoff_q_rd__tan = _c1[18]
    liftoff_q_th__tan = _c1[19]
    liftoff_q_thd__tan = _c1[20]
    passes__tan = _c1[21]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan)
    if _c2[10] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[10])
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
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, passes, apex_height__tan, apex_speed__tan, t_descent__tan, t_stance__tan, t_ascent__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, step_length__tan, foot_x__tan, foot_y__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_apex_return_jacobian(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

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
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0, 1]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 = gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 = geyer-vs

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
        passes: Picard passes run (the larger of the two halves) [1]
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
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(zeroth) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0) or (zeroth == 8.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # derivatives with respect to b_y_apex
    _c0 = iterative_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if _c0[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[26])
    d_apex_height__b_y_apex = _c0[13]
    d_apex_speed__b_y_apex = _c0[14]
    d_t_descent__b_y_apex = _c0[15]
    d_t_stance__b_y_apex = _c0[16]
    d_t_ascent__b_y_apex = _c0[17]
    d_liftoff_q_r__b_y_apex = _c0[18]
    d_liftoff_q_rd__b_y_apex = _c0[19]
    d_liftoff_q_th__b_y_apex = _c0[20]
    d_liftoff_q_thd__b_y_apex = _c0[21]
    d_step_length__b_y_apex = _c0[22]
    d_foot_x__b_y_apex = _c0[23]
    d_foot_y__b_y_apex = _c0[24]
    d_passes__b_y_apex = _c0[25]
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
    passes = _c0[12]
    # derivatives with respect to b_xd_apex
    _c1 = iterative_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    if _c1[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[26])
    d_apex_height__b_xd_apex = _c1[13]
    d_apex_speed__b_xd_apex = _c1[14]
    d_t_descent__b_xd_apex = _c1[15]
    d_t_stance__b_xd_apex = _c1[16]
    d_t_ascent__b_xd_apex = _c1[17]
    d_liftoff_q_r__b_xd_apex = _c1[18]
    d_liftoff_q_rd__b_xd_apex = _c1[19]
    d_liftoff_q_th__b_xd_apex = _c1[20]
    d_liftoff_q_thd__b_xd_apex = _c1[21]
    d_step_length__b_xd_apex = _c1[22]
    d_foot_x__b_xd_apex = _c1[23]
    d_foot_y__b_xd_apex = _c1[24]
    d_passes__b_xd_apex = _c1[25]
    # derivatives with respect to q_th_td
    _c2 = iterative_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    if _c2[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[26])
    d_apex_height__q_th_td = _c2[13]
    d_apex_speed__q_th_td = _c2[14]
    d_t_descent__q_th_td = _c2[15]
    d_t_stance__q_th_td = _c2[16]
    d_t_ascent__q_th_td = _c2[17]
    d_liftoff_q_r__q_th_td = _c2[18]
    d_liftoff_q_rd__q_th_td = _c2[19]
    d_liftoff_q_th__q_th_td = _c2[20]
    d_liftoff_q_thd__q_th_td = _c2[21]
    d_step_length__q_th_td = _c2[22]
    d_foot_x__q_th_td = _c2[23]
    d_foot_y__q_th_td = _c2[24]
    d_passes__q_th_td = _c2[25]
    # derivatives with respect to ground
    _c3 = iterative_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    if _c3[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c3[26])
    d_apex_height__ground = _c3[13]
    d_apex_speed__ground = _c3[14]
    d_t_descent__ground = _c3[15]
    d_t_stance__ground = _c3[16]
    d_t_ascent__ground = _c3[17]
    d_liftoff_q_r__ground = _c3[18]
    d_liftoff_q_rd__ground = _c3[19]
    d_liftoff_q_th__ground = _c3[20]
    d_liftoff_q_thd__ground = _c3[21]
    d_step_length__ground = _c3[22]
    d_foot_x__ground = _c3[23]
    d_foot_y__ground = _c3[24]
    d_passes__ground = _c3[25]
    # derivatives with respect to k_c
    _c4 = iterative_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    if _c4[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c4[26])
    d_apex_height__k_c = _c4[13]
    d_apex_speed__k_c = _c4[14]
    d_t_descent__k_c = _c4[15]
    d_t_stance__k_c = _c4[16]
    d_t_ascent__k_c = _c4[17]
    d_liftoff_q_r__k_c = _c4[18]
    d_liftoff_q_rd__k_c = _c4[19]
    d_liftoff_q_th__k_c = _c4[20]
    d_liftoff_q_thd__k_c = _c4[21]
    d_step_length__k_c = _c4[22]
    d_foot_x__k_c = _c4[23]
    d_foot_y__k_c = _c4[24]
    d_passes__k_c = _c4[25]
    # derivatives with respect to k_d
    _c5 = iterative_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_ground_k_c_k_d(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    if _c5[26] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c5[26])
    d_apex_height__k_d = _c5[13]
    d_apex_speed__k_d = _c5[14]
    d_t_descent__k_d = _c5[15]
    d_t_stance__k_d = _c5[16]
    d_t_ascent__k_d = _c5[17]
    d_liftoff_q_r__k_d = _c5[18]
    d_liftoff_q_rd__k_d = _c5[19]
    d_liftoff_q_th__k_d = _c5[20]
    d_liftoff_q_thd__k_d = _c5[21]
    d_step_length__k_d = _c5[22]
    d_foot_x__k_d = _c5[23]
    d_foot_y__k_d = _c5[24]
    d_passes__k_d = _c5[25]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent) and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(step_length) and math.isfinite(foot_x) and math.isfinite(foot_y) and math.isfinite(passes) and math.isfinite(d_apex_height__b_y_apex) and math.isfinite(d_apex_height__b_xd_apex) and math.isfinite(d_apex_height__q_th_td) and math.isfinite(d_apex_height__ground) and math.isfinite(d_apex_height__k_c) and math.isfinite(d_apex_height__k_d) and math.isfinite(d_apex_speed__b_y_apex) and math.isfinite(d_apex_speed__b_xd_apex) and math.isfinite(d_apex_speed__q_th_td) and math.isfinite(d_apex_speed__ground) and math.isfinite(d_apex_speed__k_c) and math.isfinite(d_apex_speed__k_d) and math.isfinite(d_t_descent__b_y_apex) and math.isfinite(d_t_descent__b_xd_apex) and math.isfinite(d_t_descent__q_th_td) and math.isfinite(d_t_descent__ground) and math.isfinite(d_t_descent__k_c) and math.isfinite(d_t_descent__k_d) and math.isfinite(d_t_stance__b_y_apex) and math.isfinite(d_t_stance__b_xd_apex) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__ground) and math.isfinite(d_t_stance__k_c) and math.isfinite(d_t_stance__k_d) and math.isfinite(d_t_ascent__b_y_apex) and math.isfinite(d_t_ascent__b_xd_apex) and math.isfinite(d_t_ascent__q_th_td) and math.isfinite(d_t_ascent__ground) and math.isfinite(d_t_ascent__k_c) and math.isfinite(d_t_ascent__k_d) and math.isfinite(d_liftoff_q_r__b_y_apex) and math.isfinite(d_liftoff_q_r__b_xd_apex) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__ground) and math.isfinite(d_liftoff_q_r__k_c) and math.isfinite(d_liftoff_q_r__k_d) and math.isfinite(d_liftoff_q_rd__b_y_apex) and math.isfinite(d_liftoff_q_rd__b_xd_apex) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__ground) and math.isfinite(d_liftoff_q_rd__k_c) and math.isfinite(d_liftoff_q_rd__k_d) and math.isfinite(d_liftoff_q_th__b_y_apex) and math.isfinite(d_liftoff_q_th__b_xd_apex) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__ground) and math.isfinite(d_liftoff_q_th__k_c) and math.isfinite(d_liftoff_q_th__k_d) and math.isfinite(d_liftoff_q_thd__b_y_apex) and math.isfinite(d_liftoff_q_thd__b_xd_apex) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__ground) and math.isfinite(d_liftoff_q_thd__k_c) and math.isfinite(d_liftoff_q_thd__k_d) and math.isfinite(d_step_length__b_y_apex) and math.isfinite(d_step_length__b_xd_apex) and math.isfinite(d_step_length__q_th_td) and math.isfinite(d_step_length__ground) and math.isfinite(d_step_length__k_c) and math.isfinite(d_step_length__k_d) and math.isfinite(d_foot_x__b_y_apex) and math.isfinite(d_foot_x__b_xd_apex) and math.isfinite(d_foot_x__q_th_td) and math.isfinite(d_foot_x__ground) and math.isfinite(d_foot_x__k_c) and math.isfinite(d_foot_x__k_d) and math.isfinite(d_foot_y__b_y_apex) and math.isfinite(d_foot_y__b_xd_apex) and math.isfinite(d_foot_y__q_th_td) and math.isfinite(d_foot_y__ground) and math.isfinite(d_foot_y__k_c) and math.isfinite(d_foot_y__k_d) and math.isfinite(d_passes__b_y_apex) and math.isfinite(d_passes__b_xd_apex) and math.isfinite(d_passes__q_th_td) and math.isfinite(d_passes__ground) and math.isfinite(d_passes__k_c) and math.isfinite(d_passes__k_d)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__k_c, d_t_descent__k_d, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__k_c, d_t_stance__k_d, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__k_c, d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__k_c, d_foot_x__k_d, d_foot_y__b_y_apex, d_foot_y__b_xd_apex, d_foot_y__q_th_td, d_foot_y__ground, d_foot_y__k_c, d_foot_y__k_d, d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__ground, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth.
    Writes output j of row i to ``out[i, j]`` (shape (n, 91)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__ground, d_t_descent__k_c, d_t_descent__k_d, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__k_c, d_t_stance__k_d, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__k_c, d_t_ascent__k_d, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__ground, d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex, d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex, d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__k_c, d_foot_x__k_d, d_foot_y__b_y_apex, d_foot_y__b_xd_apex, d_foot_y__q_th_td, d_foot_y__ground, d_foot_y__k_c, d_foot_y__k_d, d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__ground, d_passes__k_c, d_passes__k_d.
    """
    for i in prange(out.shape[0]):
        res = iterative_apex_return_jacobian(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth)
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
