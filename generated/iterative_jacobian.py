# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/schwind.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:5e86edc951466ed7
#   geyer_jacobian.py sha256:71e01de102ad80c3
#   geyer_vs_jacobian.py sha256:da043c6f2c55db7e
#   gravity_type0_jacobian.py sha256:398a3a66fde67744
#   gravity_type1_jacobian.py sha256:66fa45d9056d598f
#   gravity_type2_jacobian.py sha256:3f778c1f7c92dffa
#   gravity_type3_jacobian.py sha256:d97a8bb64898cff5
#   gravity_type4_jacobian.py sha256:dd980cac01ca0fb2
#   gravity_type5_jacobian.py sha256:bd04a2eb4419898d
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module iterative: JVP kernels, and for a
map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td,
    liftoff_to_apex_jac_q_rd_q_th_q_thd)
from .geyer_jacobian import geyer_stance_jacobian
from .geyer_vs_jacobian import geyer_vs_stance_jacobian
from .gravity_type0_jacobian import gravity_type0_stance_jacobian
from .gravity_type1_jacobian import gravity_type1_stance_jacobian
from .gravity_type2_jacobian import gravity_type2_stance_jacobian
from .gravity_type3_jacobian import gravity_type3_stance_jacobian
from .gravity_type4_jacobian import gravity_type4_stance_jacobian
from .gravity_type5_jacobian import gravity_type5_stance_jacobian

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_RECOMPRESSION, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED,
    STATUS_IMAGINARY_MOMENTUM)

NAN = math.nan
_NAN30 = (NAN,) * 30
_NAN42 = (NAN,) * 42
_NAN60 = (NAN,) * 60
_NAN77 = (NAN,) * 77


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp6_4eaacb_0(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2, d_guess_q_r__3,
        d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2, d_guess_q_th__3,
        d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1, d_guess_q_thd__2,
        d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol):
    """Branch nodes = 0 of schwind_compression_jvp6_4eaacb (outlined: derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 382
    # Picard passes on the 1 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 0.5*guess_q_th + 0.5*q_th, 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd,
        1.0 - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2, -d_guess_q_r__3, -d_guess_q_r__4,
        -d_guess_q_r__5, 0.5*d_guess_q_th__0, 0.5*d_guess_q_th__1, 0.5*d_guess_q_th__2 + 0.5,
        0.5*d_guess_q_th__3, 0.5*d_guess_q_th__4, 0.5*d_guess_q_th__5,
        1.0*d_guess_q_r__0*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__0*guess_q_r**2*m + 1.0*m*q_r*q_thd,
        1.0*d_guess_q_r__1*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__1*guess_q_r**2*m,
        1.0*d_guess_q_r__2*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__2*guess_q_r**2*m,
        1.0*d_guess_q_r__3*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__3*guess_q_r**2*m + 0.5*m*q_r**2,
        1.0*d_guess_q_r__4*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__4*guess_q_r**2*m,
        1.0*d_guess_q_r__5*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__5*guess_q_r**2*m, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _P0, _d_D__0, _d_D__1, _d_D__2, _d_D__3, _d_D__4, _d_D__5, _d_Q0__0, _d_Q0__1, _d_Q0__2,
            _d_Q0__3, _d_Q0__4, _d_Q0__5, _d_P0__0, _d_P0__1, _d_P0__2, _d_P0__3, _d_P0__4, _d_P0__5, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.75*_D - q_r
        _x1 = -_x0
        _isigma0 = _x1
        _d_isigma0__0 = 1.0 - 0.75*_d_D__0
        _x2 = k_c*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_c
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x37 = (1.0/_x1)
        _x9 = _x37**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__0 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__1 = _x13*_x4
        _pd__2 = -3.0*_x37**4*_x7*_x8 - k_c
        _d_iF0__0 = _d_P0__0*_pd__0 + _d_Q0__0*_pd__1 + _d_isigma0__0*_pd__2
        _x14 = 0.75*_pd__2
        _d_iF0__1 = -_d_D__1*_x14 + _d_P0__1*_pd__0 + _d_Q0__1*_pd__1
        _d_iF0__2 = -_d_D__2*_x14 + _d_P0__2*_pd__0 + _d_Q0__2*_pd__1
        _d_iF0__3 = -_d_D__3*_x14 + _d_P0__3*_pd__0 + _d_Q0__3*_pd__1
        _d_iF0__4 = -_d_D__4*_x14 + _d_P0__4*_pd__0 + _d_Q0__4*_pd__1 + _x0 + l0
        _d_iF0__5 = -_d_D__5*_x14 + _d_P0__5*_pd__0 + _d_Q0__5*_pd__1
        _x15 = 0.5*_x11 + 0.5*_x2 - 0.5*_x5 - 0.5*_x6
        _iPsi0 = _x15
        _x16 = math.sqrt(_D)
        _x17 = math.sqrt(m)
        _x18 = (1.0/math.sqrt(_x15))
        _x19 = _x17*_x18
        _ift0 = _x16*_x19
        _x20 = (0.5)/_x16
        _pd__3 = _x19*_x20
        _x21 = (0.5)*_x16/_x15**(1.5)
        _pd__4 = -_x17*_x21
        _x22 = 0.5*_pd__4
        _d_ift0__0 = _d_D__0*_pd__3 + _d_iF0__0*_x22
        _d_ift0__1 = _d_D__1*_pd__3 + _d_iF0__1*_x22
        _d_ift0__2 = _d_D__2*_pd__3 + _d_iF0__2*_x22
        _d_ift0__3 = _d_D__3*_pd__3 + _d_iF0__3*_x22
        _d_ift0__4 = _d_D__4*_pd__3 + _d_iF0__4*_x22
        _d_ift0__5 = _d_D__5*_pd__3 + _d_iF0__5*_x22
        _x23 = _x16*_x18
        _x24 = (1.0/_x17)
        _x25 = _x24*_x37**2
        _x26 = _x23*_x25
        _ifq0 = _P0*_x26
        _x27 = _P0*_x25
        _x28 = _x18*_x20
        _pd__5 = _x27*_x28
        _pd__6 = _x26
        _pd__7 = -_x21*_x27
        _pd__8 = -_x12*_x23*_x24*_x9
        _x29 = 0.5*_pd__7
        _d_ifq0__0 = _d_D__0*_pd__5 + _d_P0__0*_pd__6 + _d_iF0__0*_x29 + _d_isigma0__0*_pd__8
        _x30 = 0.75*_pd__8
        _d_ifq0__1 = _d_D__1*_pd__5 - _d_D__1*_x30 + _d_P0__1*_pd__6 + _d_iF0__1*_x29
        _d_ifq0__2 = _d_D__2*_pd__5 - _d_D__2*_x30 + _d_P0__2*_pd__6 + _d_iF0__2*_x29
        _d_ifq0__3 = _d_D__3*_pd__5 - _d_D__3*_x30 + _d_P0__3*_pd__6 + _d_iF0__3*_x29
        _d_ifq0__4 = _d_D__4*_pd__5 - _d_D__4*_x30 + _d_P0__4*_pd__6 + _d_iF0__4*_x29
        _d_ifq0__5 = _d_D__5*_pd__5 - _d_D__5*_x30 + _d_P0__5*_pd__6 + _d_iF0__5*_x29
        _x31 = m**(1.5)
        _x32 = _x23*_x31*g_s
        _x33 = _x13*_x32
        _ifp0 = _x1*_x33
        _x34 = _x1*_x13*_x31*g_s
        _pd__9 = _x28*_x34
        _pd__10 = _x1*_x3*_x32
        _pd__11 = -_x21*_x34
        _pd__12 = _x33
        _x35 = 0.5*_pd__11
        _d_ifp0__0 = _d_D__0*_pd__9 + _d_Q0__0*_pd__10 + _d_iF0__0*_x35 + _d_isigma0__0*_pd__12
        _x36 = 0.75*_pd__12
        _d_ifp0__1 = _d_D__1*_pd__9 - _d_D__1*_x36 + _d_Q0__1*_pd__10 + _d_iF0__1*_x35
        _d_ifp0__2 = _d_D__2*_pd__9 - _d_D__2*_x36 + _d_Q0__2*_pd__10 + _d_iF0__2*_x35
        _d_ifp0__3 = _d_D__3*_pd__9 - _d_D__3*_x36 + _d_Q0__3*_pd__10 + _d_iF0__3*_x35
        _d_ifp0__4 = _d_D__4*_pd__9 - _d_D__4*_x36 + _d_Q0__4*_pd__10 + _d_iF0__4*_x35
        _d_ifp0__5 = _d_D__5*_pd__9 - _d_D__5*_x36 + _d_Q0__5*_pd__10 + _d_iF0__5*_x35
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x38 = m*q_rd**2
        _x39 = -q_r
        _x40 = k_c*(_x39 + l0)
        _x41 = 1.0*k_c
        _x42 = 1.0*_iF0 - _x41*(-_isigma0 + l0)
        _x43 = _x40 + _x42
        _x44 = math.sqrt(_x38*k_c + _x43**2)
        _x45 = _x43 + _x44
        _x46 = (1.0/_x45)
        _D__next = _x38*_x46
        _x47 = (1.0/_x44)
        _x48 = _x46**2
        _x49 = _x38*_x48
        _pd__13 = _x49*(-_x47*(1.0*_x40 + _x42) - 1.0)
        _x50 = _x43*_x47
        _pd__14 = _x49*(-_x41*_x50 - _x41)
        _d_D__next__0 = _d_iF0__0*_pd__13 + _d_isigma0__0*_pd__14 + _x49*(_x50*k_c + k_c)
        _x51 = 0.75*_pd__14
        _d_D__next__1 = -_d_D__1*_x51 + _d_iF0__1*_pd__13 + 2.0*_x46*m*q_rd - _x47*_x48*k_c*m**2*q_rd**3
        _d_D__next__2 = -_d_D__2*_x51 + _d_iF0__2*_pd__13
        _d_D__next__3 = -_d_D__3*_x51 + _d_iF0__3*_pd__13
        _x52 = 2.0*q_r
        _d_D__next__4 = (-_d_D__4*_x51 + _d_iF0__4*_pd__13 + _x49*(-1.0*_isigma0 - _x39 - _x47*((0.5)*_x38
            + (0.5)*_x43*(2.0*_isigma0 - _x52))))
        _d_D__next__5 = -_d_D__5*_x51 + _d_iF0__5*_pd__13
        _Q0__next = 0.5*_ifq0 + q_th
        _d_Q0__next__2 = 0.5*_d_ifq0__2 + 1.0
        _x53 = m*q_r**2
        _P0__next = 0.5*_ifp0 + _x53*q_thd
        _d_P0__next__0 = 0.5*_d_ifp0__0 + _x52*m*q_thd
        _d_P0__next__3 = 0.5*_d_ifp0__3 + _x53
        _n0_9 = 0.5*_d_ifq0__0
        _n0_10 = 0.5*_d_ifq0__1
        _n0_12 = 0.5*_d_ifq0__3
        _n0_13 = 0.5*_d_ifq0__4
        _n0_14 = 0.5*_d_ifq0__5
        _n0_16 = 0.5*_d_ifp0__1
        _n0_17 = 0.5*_d_ifp0__2
        _n0_19 = 0.5*_d_ifp0__4
        _n0_20 = 0.5*_d_ifp0__5
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_P0__next - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _P0__next, _d_D__next__0, _d_D__next__1, _d_D__next__2, _d_D__next__3,
            _d_D__next__4, _d_D__next__5, _n0_9, _n0_10, _d_Q0__next__2, _n0_12, _n0_13, _n0_14,
            _d_P0__next__0, _n0_16, _n0_17, _d_P0__next__3, _n0_19, _n0_20, )
        _pk0 = _pkn0
        _passes += 1.0
    # bottom state
    t_half = 1.0*_ift0
    end_q_th = 1.0*_ifq0 + q_th
    d_end_q_th__2 = 1.0*_d_ifq0__2 + 1.0
    _x54 = -_D + q_r
    end_q_r = _x54
    d_end_q_r__0 = 1.0 - _d_D__0
    end_q_rd = 0.0
    _x55 = q_r**2
    _x56 = 1.0*_ifp0 + _x55*m*q_thd
    _x60 = (1.0/_x54)
    _x57 = _x60**2
    _x58 = (1.0/m)
    _x59 = _x57*_x58
    end_q_thd = _x56*_x59
    _pd__15 = 1.0*_x59
    _pd__16 = -2.0*_x56*_x58*_x60**3
    d_end_q_thd__0 = _d_ifp0__0*_pd__15 + _pd__16*d_end_q_r__0 + 2.0*_x57*q_r*q_thd
    d_end_q_thd__1 = -_d_D__1*_pd__16 + _d_ifp0__1*_pd__15
    d_end_q_thd__2 = -_d_D__2*_pd__16 + _d_ifp0__2*_pd__15
    d_end_q_thd__3 = -_d_D__3*_pd__16 + _d_ifp0__3*_pd__15 + _x55*_x57
    d_end_q_thd__4 = -_d_D__4*_pd__16 + _d_ifp0__4*_pd__15
    d_end_q_thd__5 = -_d_D__5*_pd__16 + _d_ifp0__5*_pd__15
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # tangents as every branch names them
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_r__5 = -_d_D__5
    d_end_q_th__0 = 1.0*_d_ifq0__0
    d_end_q_th__1 = 1.0*_d_ifq0__1
    d_end_q_th__3 = 1.0*_d_ifq0__3
    d_end_q_th__4 = 1.0*_d_ifq0__4
    d_end_q_th__5 = 1.0*_d_ifq0__5
    d_t_half__0 = 1.0*_d_ift0__0
    d_t_half__1 = 1.0*_d_ift0__1
    d_t_half__2 = 1.0*_d_ift0__2
    d_t_half__3 = 1.0*_d_ift0__3
    d_t_half__4 = 1.0*_d_ift0__4
    d_t_half__5 = 1.0*_d_ift0__5
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
        d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes, d_end_q_r__1,
        d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4,
        d_t_half__5, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp6_4eaacb_1(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2, d_guess_q_r__3,
        d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2, d_guess_q_th__3,
        d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1, d_guess_q_thd__2,
        d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol):
    """Branch nodes = 1 of schwind_compression_jvp6_4eaacb (outlined: derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 837
    # Picard passes on the 2 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th,
        0.2113248654051871*guess_q_th + 0.7886751345948129*q_th, 0.7886751345948129*guess_q_r**2*guess_q_thd*m
        + 0.2113248654051871*m*q_r**2*q_thd, 0.2113248654051871*guess_q_r**2*guess_q_thd*m
        + 0.7886751345948129*m*q_r**2*q_thd, 1.0 - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2,
        -d_guess_q_r__3, -d_guess_q_r__4, -d_guess_q_r__5, 0.7886751345948129*d_guess_q_th__0,
        0.7886751345948129*d_guess_q_th__1, 0.7886751345948129*d_guess_q_th__2 + 0.2113248654051871,
        0.7886751345948129*d_guess_q_th__3, 0.7886751345948129*d_guess_q_th__4,
        0.7886751345948129*d_guess_q_th__5, 0.2113248654051871*d_guess_q_th__0,
        0.2113248654051871*d_guess_q_th__1, 0.2113248654051871*d_guess_q_th__2 + 0.7886751345948129,
        0.2113248654051871*d_guess_q_th__3, 0.2113248654051871*d_guess_q_th__4,
        0.2113248654051871*d_guess_q_th__5, 1.5773502691896257*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__0*guess_q_r**2*m + 0.4226497308103742*m*q_r*q_thd,
        1.5773502691896257*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__1*guess_q_r**2*m,
        1.5773502691896257*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__2*guess_q_r**2*m,
        1.5773502691896257*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__3*guess_q_r**2*m + 0.2113248654051871*m*q_r**2,
        1.5773502691896257*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__4*guess_q_r**2*m,
        1.5773502691896257*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__5*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__0*guess_q_r**2*m + 1.5773502691896257*m*q_r*q_thd,
        0.4226497308103742*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__1*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__2*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__3*guess_q_r**2*m + 0.7886751345948129*m*q_r**2,
        0.4226497308103742*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__4*guess_q_r**2*m,
        0.4226497308103742*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__5*guess_q_r**2*m, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _P0, _P1, _d_D__0, _d_D__1, _d_D__2, _d_D__3, _d_D__4, _d_D__5, _d_Q0__0, _d_Q0__1,
            _d_Q0__2, _d_Q0__3, _d_Q0__4, _d_Q0__5, _d_Q1__0, _d_Q1__1, _d_Q1__2, _d_Q1__3, _d_Q1__4,
            _d_Q1__5, _d_P0__0, _d_P0__1, _d_P0__2, _d_P0__3, _d_P0__4, _d_P0__5, _d_P1__0, _d_P1__1,
            _d_P1__2, _d_P1__3, _d_P1__4, _d_P1__5, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9553418012614795*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _d_isigma0__0 = 1.0 - 0.9553418012614795*_d_D__0
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x66 = (1.0/_x2)
        _x10 = _x66**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__17 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__18 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__19 = -_x15*_x66**4*_x8 - k_c
        _d_iF0__0 = _d_P0__0*_pd__17 + _d_Q0__0*_pd__18 + _d_isigma0__0*_pd__19
        _x16 = 0.9553418012614795*_pd__19
        _d_iF0__1 = -_d_D__1*_x16 + _d_P0__1*_pd__17 + _d_Q0__1*_pd__18
        _d_iF0__2 = -_d_D__2*_x16 + _d_P0__2*_pd__17 + _d_Q0__2*_pd__18
        _d_iF0__3 = -_d_D__3*_x16 + _d_P0__3*_pd__17 + _d_Q0__3*_pd__18
        _d_iF0__4 = -_d_D__4*_x16 + _d_P0__4*_pd__17 + _d_Q0__4*_pd__18 + _x1 + l0
        _d_iF0__5 = -_d_D__5*_x16 + _d_P0__5*_pd__17 + _d_Q0__5*_pd__18
        _x17 = 0.37799153207185376*_D + _x0
        _x18 = -_x17
        _isigma1 = _x18
        _d_isigma1__0 = 1.0 - 0.37799153207185376*_d_D__0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x5
        _x21 = _x18*k_c
        _x22 = _P1**2
        _x65 = (1.0/_x18)
        _x23 = _x65**3
        _x24 = _x23*_x9
        _x25 = _x22*_x24
        _iF1 = -_x20 - _x21 + _x25 + _x3
        _x26 = 2.0*_P1
        _pd__20 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__21 = _x27*_x5
        _pd__22 = -_x15*_x22*_x65**4 - k_c
        _d_iF1__0 = _d_P1__0*_pd__20 + _d_Q1__0*_pd__21 + _d_isigma1__0*_pd__22
        _x28 = 0.37799153207185376*_pd__22
        _d_iF1__1 = -_d_D__1*_x28 + _d_P1__1*_pd__20 + _d_Q1__1*_pd__21
        _d_iF1__2 = -_d_D__2*_x28 + _d_P1__2*_pd__20 + _d_Q1__2*_pd__21
        _d_iF1__3 = -_d_D__3*_x28 + _d_P1__3*_pd__20 + _d_Q1__3*_pd__21
        _d_iF1__4 = -_d_D__4*_x28 + _d_P1__4*_pd__20 + _d_Q1__4*_pd__21 + _x17 + l0
        _d_iF1__5 = -_d_D__5*_x28 + _d_P1__5*_pd__20 + _d_Q1__5*_pd__21
        _x29 = (0.5610042339640731*_x12 + 0.06100423396407311*_x20 + 0.06100423396407311*_x21
            - 0.06100423396407311*_x25 + 0.5*_x3 - 0.5610042339640731*_x6 - 0.5610042339640731*_x7)
        _iPsi0 = _x29
        _d_iPsi0__0 = 0.5610042339640731*_d_iF0__0 - 0.06100423396407311*_d_iF1__0
        _d_iPsi0__1 = 0.5610042339640731*_d_iF0__1 - 0.06100423396407311*_d_iF1__1
        _d_iPsi0__2 = 0.5610042339640731*_d_iF0__2 - 0.06100423396407311*_d_iF1__2
        _d_iPsi0__3 = 0.5610042339640731*_d_iF0__3 - 0.06100423396407311*_d_iF1__3
        _d_iPsi0__4 = 0.5610042339640731*_d_iF0__4 - 0.06100423396407311*_d_iF1__4
        _d_iPsi0__5 = 0.5610042339640731*_d_iF0__5 - 0.06100423396407311*_d_iF1__5
        _x30 = (1.0/math.sqrt(_x29))
        _x31 = math.sqrt(_D)
        _x32 = math.sqrt(m)
        _x33 = _x31*_x32
        _ift0 = _x30*_x33
        _x34 = (0.5)/_x31
        _x35 = _x32*_x34
        _pd__23 = _x30*_x35
        _x36 = _x29**(-1.5)
        _x37 = (0.5)*_x33
        _pd__24 = -_x36*_x37
        _d_ift0__0 = _d_D__0*_pd__23 + _d_iPsi0__0*_pd__24
        _d_ift0__1 = _d_D__1*_pd__23 + _d_iPsi0__1*_pd__24
        _d_ift0__2 = _d_D__2*_pd__23 + _d_iPsi0__2*_pd__24
        _d_ift0__3 = _d_D__3*_pd__23 + _d_iPsi0__3*_pd__24
        _d_ift0__4 = _d_D__4*_pd__23 + _d_iPsi0__4*_pd__24
        _d_ift0__5 = _d_D__5*_pd__23 + _d_iPsi0__5*_pd__24
        _x38 = (1.0/_x32)
        _x39 = _x31*_x38
        _x40 = _x66**2
        _x41 = _x30*_x40
        _x42 = _x39*_x41
        _ifq0 = _P0*_x42
        _x43 = _x34*_x38
        _pd__25 = _P0*_x41*_x43
        _pd__26 = _x42
        _x44 = (0.5)*_x39
        _pd__27 = -_P0*_x36*_x40*_x44
        _pd__28 = -_x10*_x13*_x30*_x39
        _d_ifq0__0 = _d_D__0*_pd__25 + _d_P0__0*_pd__26 + _d_iPsi0__0*_pd__27 + _d_isigma0__0*_pd__28
        _x45 = 0.9553418012614795*_pd__28
        _d_ifq0__1 = _d_D__1*_pd__25 - _d_D__1*_x45 + _d_P0__1*_pd__26 + _d_iPsi0__1*_pd__27
        _d_ifq0__2 = _d_D__2*_pd__25 - _d_D__2*_x45 + _d_P0__2*_pd__26 + _d_iPsi0__2*_pd__27
        _d_ifq0__3 = _d_D__3*_pd__25 - _d_D__3*_x45 + _d_P0__3*_pd__26 + _d_iPsi0__3*_pd__27
        _d_ifq0__4 = _d_D__4*_pd__25 - _d_D__4*_x45 + _d_P0__4*_pd__26 + _d_iPsi0__4*_pd__27
        _d_ifq0__5 = _d_D__5*_pd__25 - _d_D__5*_x45 + _d_P0__5*_pd__26 + _d_iPsi0__5*_pd__27
        _x46 = g_s*m**(1.5)
        _x47 = _x31*_x46
        _x48 = _x30*_x47
        _x49 = _x14*_x48
        _ifp0 = _x2*_x49
        _x50 = _x14*_x2
        _x51 = _x34*_x46
        _pd__29 = _x30*_x50*_x51
        _pd__30 = _x2*_x4*_x48
        _x52 = (0.5)*_x47
        _pd__31 = -_x36*_x50*_x52
        _pd__32 = _x49
        _d_ifp0__0 = _d_D__0*_pd__29 + _d_Q0__0*_pd__30 + _d_iPsi0__0*_pd__31 + _d_isigma0__0*_pd__32
        _x53 = 0.9553418012614795*_pd__32
        _d_ifp0__1 = _d_D__1*_pd__29 - _d_D__1*_x53 + _d_Q0__1*_pd__30 + _d_iPsi0__1*_pd__31
        _d_ifp0__2 = _d_D__2*_pd__29 - _d_D__2*_x53 + _d_Q0__2*_pd__30 + _d_iPsi0__2*_pd__31
        _d_ifp0__3 = _d_D__3*_pd__29 - _d_D__3*_x53 + _d_Q0__3*_pd__30 + _d_iPsi0__3*_pd__31
        _d_ifp0__4 = _d_D__4*_pd__29 - _d_D__4*_x53 + _d_Q0__4*_pd__30 + _d_iPsi0__4*_pd__31
        _d_ifp0__5 = _d_D__5*_pd__29 - _d_D__5*_x53 + _d_Q0__5*_pd__30 + _d_iPsi0__5*_pd__31
        _x54 = (0.22767090063073978*_x10*_x8*_x9 - 0.27232909936926025*_x20 - 0.27232909936926025*_x21
            + 0.27232909936926025*_x22*_x23*_x9 - 0.22767090063073978*_x6 - 0.22767090063073978*_x7
            + 0.5*k_c*l0)
        _iPsi1 = _x54
        _d_iPsi1__0 = 0.22767090063073978*_d_iF0__0 + 0.27232909936926025*_d_iF1__0
        _d_iPsi1__1 = 0.22767090063073978*_d_iF0__1 + 0.27232909936926025*_d_iF1__1
        _d_iPsi1__2 = 0.22767090063073978*_d_iF0__2 + 0.27232909936926025*_d_iF1__2
        _d_iPsi1__3 = 0.22767090063073978*_d_iF0__3 + 0.27232909936926025*_d_iF1__3
        _d_iPsi1__4 = 0.22767090063073978*_d_iF0__4 + 0.27232909936926025*_d_iF1__4
        _d_iPsi1__5 = 0.22767090063073978*_d_iF0__5 + 0.27232909936926025*_d_iF1__5
        _x55 = (1.0/math.sqrt(_x54))
        _ift1 = _x33*_x55
        _pd__33 = _x35*_x55
        _x56 = _x54**(-1.5)
        _pd__34 = -_x37*_x56
        _d_ift1__0 = _d_D__0*_pd__33 + _d_iPsi1__0*_pd__34
        _d_ift1__1 = _d_D__1*_pd__33 + _d_iPsi1__1*_pd__34
        _d_ift1__2 = _d_D__2*_pd__33 + _d_iPsi1__2*_pd__34
        _d_ift1__3 = _d_D__3*_pd__33 + _d_iPsi1__3*_pd__34
        _d_ift1__4 = _d_D__4*_pd__33 + _d_iPsi1__4*_pd__34
        _d_ift1__5 = _d_D__5*_pd__33 + _d_iPsi1__5*_pd__34
        _x57 = _x65**2
        _x58 = _x55*_x57
        _x59 = _x39*_x58
        _ifq1 = _P1*_x59
        _pd__35 = _P1*_x43*_x58
        _pd__36 = _x59
        _pd__37 = -_P1*_x44*_x56*_x57
        _pd__38 = -_x23*_x26*_x39*_x55
        _d_ifq1__0 = _d_D__0*_pd__35 + _d_P1__0*_pd__36 + _d_iPsi1__0*_pd__37 + _d_isigma1__0*_pd__38
        _x60 = 0.37799153207185376*_pd__38
        _d_ifq1__1 = _d_D__1*_pd__35 - _d_D__1*_x60 + _d_P1__1*_pd__36 + _d_iPsi1__1*_pd__37
        _d_ifq1__2 = _d_D__2*_pd__35 - _d_D__2*_x60 + _d_P1__2*_pd__36 + _d_iPsi1__2*_pd__37
        _d_ifq1__3 = _d_D__3*_pd__35 - _d_D__3*_x60 + _d_P1__3*_pd__36 + _d_iPsi1__3*_pd__37
        _d_ifq1__4 = _d_D__4*_pd__35 - _d_D__4*_x60 + _d_P1__4*_pd__36 + _d_iPsi1__4*_pd__37
        _d_ifq1__5 = _d_D__5*_pd__35 - _d_D__5*_x60 + _d_P1__5*_pd__36 + _d_iPsi1__5*_pd__37
        _x61 = _x47*_x55
        _x62 = _x27*_x61
        _ifp1 = _x18*_x62
        _x63 = _x18*_x27
        _pd__39 = _x51*_x55*_x63
        _pd__40 = _x18*_x19*_x61
        _pd__41 = -_x52*_x56*_x63
        _pd__42 = _x62
        _d_ifp1__0 = _d_D__0*_pd__39 + _d_Q1__0*_pd__40 + _d_iPsi1__0*_pd__41 + _d_isigma1__0*_pd__42
        _x64 = 0.37799153207185376*_pd__42
        _d_ifp1__1 = _d_D__1*_pd__39 - _d_D__1*_x64 + _d_Q1__1*_pd__40 + _d_iPsi1__1*_pd__41
        _d_ifp1__2 = _d_D__2*_pd__39 - _d_D__2*_x64 + _d_Q1__2*_pd__40 + _d_iPsi1__2*_pd__41
        _d_ifp1__3 = _d_D__3*_pd__39 - _d_D__3*_x64 + _d_Q1__3*_pd__40 + _d_iPsi1__3*_pd__41
        _d_ifp1__4 = _d_D__4*_pd__39 - _d_D__4*_x64 + _d_Q1__4*_pd__40 + _d_iPsi1__4*_pd__41
        _d_ifp1__5 = _d_D__5*_pd__39 - _d_D__5*_x64 + _d_Q1__5*_pd__40 + _d_iPsi1__5*_pd__41
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x67 = m*q_rd**2
        _x68 = -q_r
        _x69 = k_c*(_x68 + l0)
        _x70 = -l0
        _x71 = -_isigma0 - _x70
        _x72 = 0.2113248654051871*k_c
        _x73 = -_isigma1 - _x70
        _x74 = 0.7886751345948129*k_c
        _x75 = 0.2113248654051871*_iF0 + 0.7886751345948129*_iF1 + _x69 - _x71*_x72 - _x73*_x74
        _x76 = math.sqrt(_x67*k_c + _x75**2)
        _x77 = _x75 + _x76
        _x78 = (1.0/_x77)
        _D__next = _x67*_x78
        _x79 = _x71*k_c
        _x80 = _x73*k_c
        _x81 = (1.0/_x76)
        _x82 = _x78**2
        _x83 = _x67*_x82
        _pd__43 = (_x83*(-_x81*(0.04465819873852045*_iF0 + 0.16666666666666666*_iF1 + 0.2113248654051871*_x69
            - 0.04465819873852045*_x79 - 0.16666666666666666*_x80) - 0.2113248654051871))
        _pd__44 = (_x83*(-_x81*(0.16666666666666666*_iF0 + 0.6220084679281462*_iF1 + 0.7886751345948129*_x69
            - 0.16666666666666666*_x79 - 0.6220084679281462*_x80) - 0.7886751345948129))
        _x84 = _x75*_x81
        _pd__45 = _x83*(-_x72*_x84 - _x72)
        _pd__46 = _x83*(-_x74*_x84 - _x74)
        _d_D__next__0 = (_d_iF0__0*_pd__43 + _d_iF1__0*_pd__44 + _d_isigma0__0*_pd__45 + _d_isigma1__0*_pd__46
            + _x83*(_x84*k_c + k_c))
        _x85 = 0.9553418012614795*_pd__45
        _x86 = 0.37799153207185376*_pd__46
        _d_D__next__1 = (-_d_D__1*_x85 - _d_D__1*_x86 + _d_iF0__1*_pd__43 + _d_iF1__1*_pd__44
            + 2.0*_x78*m*q_rd - _x81*_x82*k_c*m**2*q_rd**3)
        _d_D__next__2 = -_d_D__2*_x85 - _d_D__2*_x86 + _d_iF0__2*_pd__43 + _d_iF1__2*_pd__44
        _d_D__next__3 = -_d_D__3*_x85 - _d_D__3*_x86 + _d_iF0__3*_pd__43 + _d_iF1__3*_pd__44
        _x87 = 2.0*q_r
        _d_D__next__4 = (-_d_D__4*_x85 - _d_D__4*_x86 + _d_iF0__4*_pd__43 + _d_iF1__4*_pd__44
            + _x83*(-0.2113248654051871*_isigma0 - 0.7886751345948129*_isigma1 - _x68 - _x81*((0.5)*_x67
            + (0.5)*_x75*(0.4226497308103742*_isigma0 + 1.5773502691896257*_isigma1 - _x87
            - 8.470329472543003e-22*l0)) + 4.235164736271502e-22*l0))
        _d_D__next__5 = -_d_D__5*_x85 - _d_D__5*_x86 + _d_iF0__5*_pd__43 + _d_iF1__5*_pd__44
        _Q0__next = 0.25*_ifq0 + 0.5386751345948129*_ifq1 + q_th
        _d_Q0__next__0 = 0.25*_d_ifq0__0 + 0.5386751345948129*_d_ifq1__0
        _d_Q0__next__1 = 0.25*_d_ifq0__1 + 0.5386751345948129*_d_ifq1__1
        _d_Q0__next__2 = 0.25*_d_ifq0__2 + 0.5386751345948129*_d_ifq1__2 + 1.0
        _d_Q0__next__3 = 0.25*_d_ifq0__3 + 0.5386751345948129*_d_ifq1__3
        _d_Q0__next__4 = 0.25*_d_ifq0__4 + 0.5386751345948129*_d_ifq1__4
        _d_Q0__next__5 = 0.25*_d_ifq0__5 + 0.5386751345948129*_d_ifq1__5
        _Q1__next = -0.03867513459481288*_ifq0 + 0.25*_ifq1 + q_th
        _d_Q1__next__0 = -0.03867513459481288*_d_ifq0__0 + 0.25*_d_ifq1__0
        _d_Q1__next__1 = -0.03867513459481288*_d_ifq0__1 + 0.25*_d_ifq1__1
        _d_Q1__next__2 = -0.03867513459481288*_d_ifq0__2 + 0.25*_d_ifq1__2 + 1.0
        _d_Q1__next__3 = -0.03867513459481288*_d_ifq0__3 + 0.25*_d_ifq1__3
        _d_Q1__next__4 = -0.03867513459481288*_d_ifq0__4 + 0.25*_d_ifq1__4
        _d_Q1__next__5 = -0.03867513459481288*_d_ifq0__5 + 0.25*_d_ifq1__5
        _x88 = m*q_r**2
        _x89 = _x88*q_thd
        _P0__next = 0.25*_ifp0 + 0.5386751345948129*_ifp1 + _x89
        _x90 = _x87*m*q_thd
        _d_P0__next__0 = 0.25*_d_ifp0__0 + 0.5386751345948129*_d_ifp1__0 + _x90
        _d_P0__next__1 = 0.25*_d_ifp0__1 + 0.5386751345948129*_d_ifp1__1
        _d_P0__next__2 = 0.25*_d_ifp0__2 + 0.5386751345948129*_d_ifp1__2
        _d_P0__next__3 = 0.25*_d_ifp0__3 + 0.5386751345948129*_d_ifp1__3 + _x88
        _d_P0__next__4 = 0.25*_d_ifp0__4 + 0.5386751345948129*_d_ifp1__4
        _d_P0__next__5 = 0.25*_d_ifp0__5 + 0.5386751345948129*_d_ifp1__5
        _P1__next = -0.03867513459481288*_ifp0 + 0.25*_ifp1 + _x89
        _d_P1__next__0 = -0.03867513459481288*_d_ifp0__0 + 0.25*_d_ifp1__0 + _x90
        _d_P1__next__1 = -0.03867513459481288*_d_ifp0__1 + 0.25*_d_ifp1__1
        _d_P1__next__2 = -0.03867513459481288*_d_ifp0__2 + 0.25*_d_ifp1__2
        _d_P1__next__3 = -0.03867513459481288*_d_ifp0__3 + 0.25*_d_ifp1__3 + _x88
        _d_P1__next__4 = -0.03867513459481288*_d_ifp0__4 + 0.25*_d_ifp1__4
        _d_P1__next__5 = -0.03867513459481288*_d_ifp0__5 + 0.25*_d_ifp1__5
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_P0__next - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_P1__next - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _P0__next, _P1__next, _d_D__next__0, _d_D__next__1,
            _d_D__next__2, _d_D__next__3, _d_D__next__4, _d_D__next__5, _d_Q0__next__0, _d_Q0__next__1,
            _d_Q0__next__2, _d_Q0__next__3, _d_Q0__next__4, _d_Q0__next__5, _d_Q1__next__0, _d_Q1__next__1,
            _d_Q1__next__2, _d_Q1__next__3, _d_Q1__next__4, _d_Q1__next__5, _d_P0__next__0, _d_P0__next__1,
            _d_P0__next__2, _d_P0__next__3, _d_P0__next__4, _d_P0__next__5, _d_P1__next__0, _d_P1__next__1,
            _d_P1__next__2, _d_P1__next__3, _d_P1__next__4, _d_P1__next__5, )
        _pk0 = _pkn0
        _passes += 1.0
    # bottom state
    t_half = 0.5*_ift0 + 0.5*_ift1
    d_t_half__0 = 0.5*_d_ift0__0 + 0.5*_d_ift1__0
    d_t_half__1 = 0.5*_d_ift0__1 + 0.5*_d_ift1__1
    d_t_half__2 = 0.5*_d_ift0__2 + 0.5*_d_ift1__2
    d_t_half__3 = 0.5*_d_ift0__3 + 0.5*_d_ift1__3
    d_t_half__4 = 0.5*_d_ift0__4 + 0.5*_d_ift1__4
    d_t_half__5 = 0.5*_d_ift0__5 + 0.5*_d_ift1__5
    end_q_th = 0.5*_ifq0 + 0.5*_ifq1 + q_th
    d_end_q_th__0 = 0.5*_d_ifq0__0 + 0.5*_d_ifq1__0
    d_end_q_th__1 = 0.5*_d_ifq0__1 + 0.5*_d_ifq1__1
    d_end_q_th__2 = 0.5*_d_ifq0__2 + 0.5*_d_ifq1__2 + 1.0
    d_end_q_th__3 = 0.5*_d_ifq0__3 + 0.5*_d_ifq1__3
    d_end_q_th__4 = 0.5*_d_ifq0__4 + 0.5*_d_ifq1__4
    d_end_q_th__5 = 0.5*_d_ifq0__5 + 0.5*_d_ifq1__5
    _x91 = -_D + q_r
    end_q_r = _x91
    d_end_q_r__0 = 1.0 - _d_D__0
    end_q_rd = 0.0
    _x92 = q_r**2
    _x93 = 0.5*_ifp0 + 0.5*_ifp1 + _x92*m*q_thd
    _x98 = (1.0/_x91)
    _x94 = _x98**2
    _x95 = (1.0/m)
    _x96 = _x94*_x95
    end_q_thd = _x93*_x96
    _x97 = 0.5*_x96
    _pd__47 = _x97
    _pd__48 = _x97
    _pd__49 = -2.0*_x93*_x95*_x98**3
    d_end_q_thd__0 = _d_ifp0__0*_pd__47 + _d_ifp1__0*_pd__48 + _pd__49*d_end_q_r__0 + 2.0*_x94*q_r*q_thd
    d_end_q_thd__1 = -_d_D__1*_pd__49 + _d_ifp0__1*_pd__47 + _d_ifp1__1*_pd__48
    d_end_q_thd__2 = -_d_D__2*_pd__49 + _d_ifp0__2*_pd__47 + _d_ifp1__2*_pd__48
    d_end_q_thd__3 = -_d_D__3*_pd__49 + _d_ifp0__3*_pd__47 + _d_ifp1__3*_pd__48 + _x92*_x94
    d_end_q_thd__4 = -_d_D__4*_pd__49 + _d_ifp0__4*_pd__47 + _d_ifp1__4*_pd__48
    d_end_q_thd__5 = -_d_D__5*_pd__49 + _d_ifp0__5*_pd__47 + _d_ifp1__5*_pd__48
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # tangents as every branch names them
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_r__5 = -_d_D__5
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
        d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes, d_end_q_r__1,
        d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4,
        d_t_half__5, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp6_4eaacb_2(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2, d_guess_q_r__3,
        d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2, d_guess_q_th__3,
        d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1, d_guess_q_thd__2,
        d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol):
    """Branch nodes = 2 of schwind_compression_jvp6_4eaacb (outlined: derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1358
    # Picard passes on the 3 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th, 0.5*guess_q_th
        + 0.5*q_th, 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th,
        0.8872983346207417*guess_q_r**2*guess_q_thd*m + 0.11270166537925831*m*q_r**2*q_thd,
        0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd, 0.11270166537925831*guess_q_r**2*guess_q_thd*m
        + 0.8872983346207417*m*q_r**2*q_thd, 1.0 - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2,
        -d_guess_q_r__3, -d_guess_q_r__4, -d_guess_q_r__5, 0.8872983346207417*d_guess_q_th__0,
        0.8872983346207417*d_guess_q_th__1, 0.8872983346207417*d_guess_q_th__2 + 0.11270166537925831,
        0.8872983346207417*d_guess_q_th__3, 0.8872983346207417*d_guess_q_th__4,
        0.8872983346207417*d_guess_q_th__5, 0.5*d_guess_q_th__0, 0.5*d_guess_q_th__1, 0.5*d_guess_q_th__2
        + 0.5, 0.5*d_guess_q_th__3, 0.5*d_guess_q_th__4, 0.5*d_guess_q_th__5,
        0.11270166537925831*d_guess_q_th__0, 0.11270166537925831*d_guess_q_th__1,
        0.11270166537925831*d_guess_q_th__2 + 0.8872983346207417, 0.11270166537925831*d_guess_q_th__3,
        0.11270166537925831*d_guess_q_th__4, 0.11270166537925831*d_guess_q_th__5,
        1.7745966692414834*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__0*guess_q_r**2*m + 0.22540333075851662*m*q_r*q_thd,
        1.7745966692414834*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__1*guess_q_r**2*m,
        1.7745966692414834*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__2*guess_q_r**2*m,
        1.7745966692414834*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__3*guess_q_r**2*m + 0.11270166537925831*m*q_r**2,
        1.7745966692414834*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__4*guess_q_r**2*m,
        1.7745966692414834*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__5*guess_q_r**2*m, 1.0*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.5*d_guess_q_thd__0*guess_q_r**2*m + 1.0*m*q_r*q_thd, 1.0*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.5*d_guess_q_thd__1*guess_q_r**2*m, 1.0*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.5*d_guess_q_thd__2*guess_q_r**2*m, 1.0*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.5*d_guess_q_thd__3*guess_q_r**2*m + 0.5*m*q_r**2, 1.0*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.5*d_guess_q_thd__4*guess_q_r**2*m, 1.0*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.5*d_guess_q_thd__5*guess_q_r**2*m, 0.22540333075851662*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__0*guess_q_r**2*m + 1.7745966692414834*m*q_r*q_thd,
        0.22540333075851662*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__1*guess_q_r**2*m,
        0.22540333075851662*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__2*guess_q_r**2*m,
        0.22540333075851662*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__3*guess_q_r**2*m + 0.8872983346207417*m*q_r**2,
        0.22540333075851662*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__4*guess_q_r**2*m,
        0.22540333075851662*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__5*guess_q_r**2*m, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _Q2, _P0, _P1, _P2, _d_D__0, _d_D__1, _d_D__2, _d_D__3, _d_D__4, _d_D__5, _d_Q0__0,
            _d_Q0__1, _d_Q0__2, _d_Q0__3, _d_Q0__4, _d_Q0__5, _d_Q1__0, _d_Q1__1, _d_Q1__2, _d_Q1__3,
            _d_Q1__4, _d_Q1__5, _d_Q2__0, _d_Q2__1, _d_Q2__2, _d_Q2__3, _d_Q2__4, _d_Q2__5, _d_P0__0,
            _d_P0__1, _d_P0__2, _d_P0__3, _d_P0__4, _d_P0__5, _d_P1__0, _d_P1__1, _d_P1__2, _d_P1__3,
            _d_P1__4, _d_P1__5, _d_P2__0, _d_P2__1, _d_P2__2, _d_P2__3, _d_P2__4, _d_P2__5, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9872983346207417*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _d_isigma0__0 = 1.0 - 0.9872983346207417*_d_D__0
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x89 = (1.0/_x2)
        _x10 = _x89**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__50 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__51 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__52 = -_x15*_x8*_x89**4 - k_c
        _d_iF0__0 = _d_P0__0*_pd__50 + _d_Q0__0*_pd__51 + _d_isigma0__0*_pd__52
        _x16 = 0.9872983346207417*_pd__52
        _d_iF0__1 = -_d_D__1*_x16 + _d_P0__1*_pd__50 + _d_Q0__1*_pd__51
        _d_iF0__2 = -_d_D__2*_x16 + _d_P0__2*_pd__50 + _d_Q0__2*_pd__51
        _d_iF0__3 = -_d_D__3*_x16 + _d_P0__3*_pd__50 + _d_Q0__3*_pd__51
        _d_iF0__4 = -_d_D__4*_x16 + _d_P0__4*_pd__50 + _d_Q0__4*_pd__51 + _x1 + l0
        _d_iF0__5 = -_d_D__5*_x16 + _d_P0__5*_pd__50 + _d_Q0__5*_pd__51
        _x17 = 0.75*_D + _x0
        _x18 = -_x17
        _isigma1 = _x18
        _d_isigma1__0 = 1.0 - 0.75*_d_D__0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x5
        _x21 = _x18*k_c
        _x22 = _P1**2
        _x88 = (1.0/_x18)
        _x23 = _x88**3
        _x24 = _x23*_x9
        _x25 = _x22*_x24
        _iF1 = -_x20 - _x21 + _x25 + _x3
        _x26 = 2.0*_P1
        _pd__53 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__54 = _x27*_x5
        _pd__55 = -_x15*_x22*_x88**4 - k_c
        _d_iF1__0 = _d_P1__0*_pd__53 + _d_Q1__0*_pd__54 + _d_isigma1__0*_pd__55
        _x28 = 0.75*_pd__55
        _d_iF1__1 = -_d_D__1*_x28 + _d_P1__1*_pd__53 + _d_Q1__1*_pd__54
        _d_iF1__2 = -_d_D__2*_x28 + _d_P1__2*_pd__53 + _d_Q1__2*_pd__54
        _d_iF1__3 = -_d_D__3*_x28 + _d_P1__3*_pd__53 + _d_Q1__3*_pd__54
        _d_iF1__4 = -_d_D__4*_x28 + _d_P1__4*_pd__53 + _d_Q1__4*_pd__54 + _x17 + l0
        _d_iF1__5 = -_d_D__5*_x28 + _d_P1__5*_pd__53 + _d_Q1__5*_pd__54
        _x29 = 0.2127016653792583*_D + _x0
        _x30 = -_x29
        _isigma2 = _x30
        _d_isigma2__0 = 1.0 - 0.2127016653792583*_d_D__0
        _x31 = math.cos(_Q2)
        _x32 = _x31*_x5
        _x33 = _x30*k_c
        _x34 = _P2**2
        _x90 = (1.0/_x30)
        _x35 = _x90**3
        _x36 = _x35*_x9
        _x37 = _x34*_x36
        _iF2 = _x3 - _x32 - _x33 + _x37
        _x38 = 2.0*_P2
        _pd__56 = _x36*_x38
        _x39 = math.sin(_Q2)
        _pd__57 = _x39*_x5
        _pd__58 = -_x15*_x34*_x90**4 - k_c
        _d_iF2__0 = _d_P2__0*_pd__56 + _d_Q2__0*_pd__57 + _d_isigma2__0*_pd__58
        _x40 = 0.2127016653792583*_pd__58
        _d_iF2__1 = -_d_D__1*_x40 + _d_P2__1*_pd__56 + _d_Q2__1*_pd__57
        _d_iF2__2 = -_d_D__2*_x40 + _d_P2__2*_pd__56 + _d_Q2__2*_pd__57
        _d_iF2__3 = -_d_D__3*_x40 + _d_P2__3*_pd__56 + _d_Q2__3*_pd__57
        _d_iF2__4 = -_d_D__4*_x40 + _d_P2__4*_pd__56 + _d_Q2__4*_pd__57 + _x29 + l0
        _d_iF2__5 = -_d_D__5*_x40 + _d_P2__5*_pd__56 + _d_Q2__5*_pd__57
        _x41 = (0.5762768525670787*_x12 + 0.1040546303448565*_x20 + 0.1040546303448565*_x21
            - 0.1040546303448565*_x25 + 0.5*_x3 - 0.027777777777777776*_x32 - 0.027777777777777776*_x33
            + 0.027777777777777776*_x37 - 0.5762768525670787*_x6 - 0.5762768525670787*_x7)
        _iPsi0 = _x41
        _d_iPsi0__0 = (0.5762768525670787*_d_iF0__0 - 0.1040546303448565*_d_iF1__0
            + 0.027777777777777776*_d_iF2__0)
        _d_iPsi0__1 = (0.5762768525670787*_d_iF0__1 - 0.1040546303448565*_d_iF1__1
            + 0.027777777777777776*_d_iF2__1)
        _d_iPsi0__2 = (0.5762768525670787*_d_iF0__2 - 0.1040546303448565*_d_iF1__2
            + 0.027777777777777776*_d_iF2__2)
        _d_iPsi0__3 = (0.5762768525670787*_d_iF0__3 - 0.1040546303448565*_d_iF1__3
            + 0.027777777777777776*_d_iF2__3)
        _d_iPsi0__4 = (0.5762768525670787*_d_iF0__4 - 0.1040546303448565*_d_iF1__4
            + 0.027777777777777776*_d_iF2__4)
        _d_iPsi0__5 = (0.5762768525670787*_d_iF0__5 - 0.1040546303448565*_d_iF1__5
            + 0.027777777777777776*_d_iF2__5)
        _x42 = (1.0/math.sqrt(_x41))
        _x43 = math.sqrt(_D)
        _x44 = math.sqrt(m)
        _x45 = _x43*_x44
        _ift0 = _x42*_x45
        _x46 = (0.5)/_x43
        _x47 = _x44*_x46
        _pd__59 = _x42*_x47
        _x48 = _x41**(-1.5)
        _x49 = (0.5)*_x45
        _pd__60 = -_x48*_x49
        _d_ift0__0 = _d_D__0*_pd__59 + _d_iPsi0__0*_pd__60
        _d_ift0__1 = _d_D__1*_pd__59 + _d_iPsi0__1*_pd__60
        _d_ift0__2 = _d_D__2*_pd__59 + _d_iPsi0__2*_pd__60
        _d_ift0__3 = _d_D__3*_pd__59 + _d_iPsi0__3*_pd__60
        _d_ift0__4 = _d_D__4*_pd__59 + _d_iPsi0__4*_pd__60
        _d_ift0__5 = _d_D__5*_pd__59 + _d_iPsi0__5*_pd__60
        _x50 = (1.0/_x44)
        _x51 = _x43*_x50
        _x52 = _x89**2
        _x53 = _x42*_x52
        _x54 = _x51*_x53
        _ifq0 = _P0*_x54
        _x55 = _x46*_x50
        _pd__61 = _P0*_x53*_x55
        _pd__62 = _x54
        _x56 = (0.5)*_x51
        _pd__63 = -_P0*_x48*_x52*_x56
        _pd__64 = -_x10*_x13*_x42*_x51
        _d_ifq0__0 = _d_D__0*_pd__61 + _d_P0__0*_pd__62 + _d_iPsi0__0*_pd__63 + _d_isigma0__0*_pd__64
        _x57 = 0.9872983346207417*_pd__64
        _d_ifq0__1 = _d_D__1*_pd__61 - _d_D__1*_x57 + _d_P0__1*_pd__62 + _d_iPsi0__1*_pd__63
        _d_ifq0__2 = _d_D__2*_pd__61 - _d_D__2*_x57 + _d_P0__2*_pd__62 + _d_iPsi0__2*_pd__63
        _d_ifq0__3 = _d_D__3*_pd__61 - _d_D__3*_x57 + _d_P0__3*_pd__62 + _d_iPsi0__3*_pd__63
        _d_ifq0__4 = _d_D__4*_pd__61 - _d_D__4*_x57 + _d_P0__4*_pd__62 + _d_iPsi0__4*_pd__63
        _d_ifq0__5 = _d_D__5*_pd__61 - _d_D__5*_x57 + _d_P0__5*_pd__62 + _d_iPsi0__5*_pd__63
        _x58 = g_s*m**(1.5)
        _x59 = _x43*_x58
        _x60 = _x42*_x59
        _x61 = _x14*_x60
        _ifp0 = _x2*_x61
        _x62 = _x14*_x2
        _x63 = _x46*_x58
        _pd__65 = _x42*_x62*_x63
        _pd__66 = _x2*_x4*_x60
        _x64 = (0.5)*_x59
        _pd__67 = -_x48*_x62*_x64
        _pd__68 = _x61
        _d_ifp0__0 = _d_D__0*_pd__65 + _d_Q0__0*_pd__66 + _d_iPsi0__0*_pd__67 + _d_isigma0__0*_pd__68
        _x65 = 0.9872983346207417*_pd__68
        _d_ifp0__1 = _d_D__1*_pd__65 - _d_D__1*_x65 + _d_Q0__1*_pd__66 + _d_iPsi0__1*_pd__67
        _d_ifp0__2 = _d_D__2*_pd__65 - _d_D__2*_x65 + _d_Q0__2*_pd__66 + _d_iPsi0__2*_pd__67
        _d_ifp0__3 = _d_D__3*_pd__65 - _d_D__3*_x65 + _d_Q0__3*_pd__66 + _d_iPsi0__3*_pd__67
        _d_ifp0__4 = _d_D__4*_pd__65 - _d_D__4*_x65 + _d_Q0__4*_pd__66 + _d_iPsi0__4*_pd__67
        _d_ifp0__5 = _d_D__5*_pd__65 - _d_D__5*_x65 + _d_Q0__5*_pd__66 + _d_iPsi0__5*_pd__67
        _x66 = (0.17702731517242826*_x12 - 0.3611111111111111*_x20 - 0.3611111111111111*_x21
            + 0.3611111111111111*_x25 + 0.5*_x3 + 0.038138426283539355*_x32 + 0.038138426283539355*_x33
            - 0.038138426283539355*_x37 - 0.17702731517242826*_x6 - 0.17702731517242826*_x7)
        _iPsi1 = _x66
        _d_iPsi1__0 = (0.17702731517242826*_d_iF0__0 + 0.3611111111111111*_d_iF1__0
            - 0.038138426283539355*_d_iF2__0)
        _d_iPsi1__1 = (0.17702731517242826*_d_iF0__1 + 0.3611111111111111*_d_iF1__1
            - 0.038138426283539355*_d_iF2__1)
        _d_iPsi1__2 = (0.17702731517242826*_d_iF0__2 + 0.3611111111111111*_d_iF1__2
            - 0.038138426283539355*_d_iF2__2)
        _d_iPsi1__3 = (0.17702731517242826*_d_iF0__3 + 0.3611111111111111*_d_iF1__3
            - 0.038138426283539355*_d_iF2__3)
        _d_iPsi1__4 = (0.17702731517242826*_d_iF0__4 + 0.3611111111111111*_d_iF1__4
            - 0.038138426283539355*_d_iF2__4)
        _d_iPsi1__5 = (0.17702731517242826*_d_iF0__5 + 0.3611111111111111*_d_iF1__5
            - 0.038138426283539355*_d_iF2__5)
        _x67 = (1.0/math.sqrt(_x66))
        _ift1 = _x45*_x67
        _pd__69 = _x47*_x67
        _x68 = _x66**(-1.5)
        _pd__70 = -_x49*_x68
        _d_ift1__0 = _d_D__0*_pd__69 + _d_iPsi1__0*_pd__70
        _d_ift1__1 = _d_D__1*_pd__69 + _d_iPsi1__1*_pd__70
        _d_ift1__2 = _d_D__2*_pd__69 + _d_iPsi1__2*_pd__70
        _d_ift1__3 = _d_D__3*_pd__69 + _d_iPsi1__3*_pd__70
        _d_ift1__4 = _d_D__4*_pd__69 + _d_iPsi1__4*_pd__70
        _d_ift1__5 = _d_D__5*_pd__69 + _d_iPsi1__5*_pd__70
        _x69 = _x88**2
        _x70 = _x67*_x69
        _x71 = _x51*_x70
        _ifq1 = _P1*_x71
        _pd__71 = _P1*_x55*_x70
        _pd__72 = _x71
        _pd__73 = -_P1*_x56*_x68*_x69
        _pd__74 = -_x23*_x26*_x51*_x67
        _d_ifq1__0 = _d_D__0*_pd__71 + _d_P1__0*_pd__72 + _d_iPsi1__0*_pd__73 + _d_isigma1__0*_pd__74
        _x72 = 0.75*_pd__74
        _d_ifq1__1 = _d_D__1*_pd__71 - _d_D__1*_x72 + _d_P1__1*_pd__72 + _d_iPsi1__1*_pd__73
        _d_ifq1__2 = _d_D__2*_pd__71 - _d_D__2*_x72 + _d_P1__2*_pd__72 + _d_iPsi1__2*_pd__73
        _d_ifq1__3 = _d_D__3*_pd__71 - _d_D__3*_x72 + _d_P1__3*_pd__72 + _d_iPsi1__3*_pd__73
        _d_ifq1__4 = _d_D__4*_pd__71 - _d_D__4*_x72 + _d_P1__4*_pd__72 + _d_iPsi1__4*_pd__73
        _d_ifq1__5 = _d_D__5*_pd__71 - _d_D__5*_x72 + _d_P1__5*_pd__72 + _d_iPsi1__5*_pd__73
        _x73 = _x59*_x67
        _x74 = _x27*_x73
        _ifp1 = _x18*_x74
        _x75 = _x18*_x27
        _pd__75 = _x63*_x67*_x75
        _pd__76 = _x18*_x19*_x73
        _pd__77 = -_x64*_x68*_x75
        _pd__78 = _x74
        _d_ifp1__0 = _d_D__0*_pd__75 + _d_Q1__0*_pd__76 + _d_iPsi1__0*_pd__77 + _d_isigma1__0*_pd__78
        _x76 = 0.75*_pd__78
        _d_ifp1__1 = _d_D__1*_pd__75 - _d_D__1*_x76 + _d_Q1__1*_pd__76 + _d_iPsi1__1*_pd__77
        _d_ifp1__2 = _d_D__2*_pd__75 - _d_D__2*_x76 + _d_Q1__2*_pd__76 + _d_iPsi1__2*_pd__77
        _d_ifp1__3 = _d_D__3*_pd__75 - _d_D__3*_x76 + _d_Q1__3*_pd__76 + _d_iPsi1__3*_pd__77
        _d_ifp1__4 = _d_D__4*_pd__75 - _d_D__4*_x76 + _d_Q1__4*_pd__76 + _d_iPsi1__4*_pd__77
        _d_ifp1__5 = _d_D__5*_pd__75 - _d_D__5*_x76 + _d_Q1__5*_pd__76 + _d_iPsi1__5*_pd__77
        _x77 = (0.027777777777777776*_x10*_x8*_x9 - 0.3262768525670787*_x20 - 0.3262768525670787*_x21
            + 0.3262768525670787*_x22*_x23*_x9 - 0.14594536965514351*_x32 - 0.14594536965514351*_x33
            + 0.14594536965514351*_x34*_x35*_x9 - 0.027777777777777776*_x6 - 0.027777777777777776*_x7
            + 0.5*k_c*l0)
        _iPsi2 = _x77
        _d_iPsi2__0 = (0.027777777777777776*_d_iF0__0 + 0.3262768525670787*_d_iF1__0
            + 0.14594536965514351*_d_iF2__0)
        _d_iPsi2__1 = (0.027777777777777776*_d_iF0__1 + 0.3262768525670787*_d_iF1__1
            + 0.14594536965514351*_d_iF2__1)
        _d_iPsi2__2 = (0.027777777777777776*_d_iF0__2 + 0.3262768525670787*_d_iF1__2
            + 0.14594536965514351*_d_iF2__2)
        _d_iPsi2__3 = (0.027777777777777776*_d_iF0__3 + 0.3262768525670787*_d_iF1__3
            + 0.14594536965514351*_d_iF2__3)
        _d_iPsi2__4 = (0.027777777777777776*_d_iF0__4 + 0.3262768525670787*_d_iF1__4
            + 0.14594536965514351*_d_iF2__4)
        _d_iPsi2__5 = (0.027777777777777776*_d_iF0__5 + 0.3262768525670787*_d_iF1__5
            + 0.14594536965514351*_d_iF2__5)
        _x78 = (1.0/math.sqrt(_x77))
        _ift2 = _x45*_x78
        _pd__79 = _x47*_x78
        _x79 = _x77**(-1.5)
        _pd__80 = -_x49*_x79
        _d_ift2__0 = _d_D__0*_pd__79 + _d_iPsi2__0*_pd__80
        _d_ift2__1 = _d_D__1*_pd__79 + _d_iPsi2__1*_pd__80
        _d_ift2__2 = _d_D__2*_pd__79 + _d_iPsi2__2*_pd__80
        _d_ift2__3 = _d_D__3*_pd__79 + _d_iPsi2__3*_pd__80
        _d_ift2__4 = _d_D__4*_pd__79 + _d_iPsi2__4*_pd__80
        _d_ift2__5 = _d_D__5*_pd__79 + _d_iPsi2__5*_pd__80
        _x80 = _x90**2
        _x81 = _x78*_x80
        _x82 = _x51*_x81
        _ifq2 = _P2*_x82
        _pd__81 = _P2*_x55*_x81
        _pd__82 = _x82
        _pd__83 = -_P2*_x56*_x79*_x80
        _pd__84 = -_x35*_x38*_x51*_x78
        _d_ifq2__0 = _d_D__0*_pd__81 + _d_P2__0*_pd__82 + _d_iPsi2__0*_pd__83 + _d_isigma2__0*_pd__84
        _x83 = 0.2127016653792583*_pd__84
        _d_ifq2__1 = _d_D__1*_pd__81 - _d_D__1*_x83 + _d_P2__1*_pd__82 + _d_iPsi2__1*_pd__83
        _d_ifq2__2 = _d_D__2*_pd__81 - _d_D__2*_x83 + _d_P2__2*_pd__82 + _d_iPsi2__2*_pd__83
        _d_ifq2__3 = _d_D__3*_pd__81 - _d_D__3*_x83 + _d_P2__3*_pd__82 + _d_iPsi2__3*_pd__83
        _d_ifq2__4 = _d_D__4*_pd__81 - _d_D__4*_x83 + _d_P2__4*_pd__82 + _d_iPsi2__4*_pd__83
        _d_ifq2__5 = _d_D__5*_pd__81 - _d_D__5*_x83 + _d_P2__5*_pd__82 + _d_iPsi2__5*_pd__83
        _x84 = _x59*_x78
        _x85 = _x39*_x84
        _ifp2 = _x30*_x85
        _x86 = _x30*_x39
        _pd__85 = _x63*_x78*_x86
        _pd__86 = _x30*_x31*_x84
        _pd__87 = -_x64*_x79*_x86
        _pd__88 = _x85
        _d_ifp2__0 = _d_D__0*_pd__85 + _d_Q2__0*_pd__86 + _d_iPsi2__0*_pd__87 + _d_isigma2__0*_pd__88
        _x87 = 0.2127016653792583*_pd__88
        _d_ifp2__1 = _d_D__1*_pd__85 - _d_D__1*_x87 + _d_Q2__1*_pd__86 + _d_iPsi2__1*_pd__87
        _d_ifp2__2 = _d_D__2*_pd__85 - _d_D__2*_x87 + _d_Q2__2*_pd__86 + _d_iPsi2__2*_pd__87
        _d_ifp2__3 = _d_D__3*_pd__85 - _d_D__3*_x87 + _d_Q2__3*_pd__86 + _d_iPsi2__3*_pd__87
        _d_ifp2__4 = _d_D__4*_pd__85 - _d_D__4*_x87 + _d_Q2__4*_pd__86 + _d_iPsi2__4*_pd__87
        _d_ifp2__5 = _d_D__5*_pd__85 - _d_D__5*_x87 + _d_Q2__5*_pd__86 + _d_iPsi2__5*_pd__87
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x91 = m*q_rd**2
        _x92 = -q_r
        _x93 = k_c*(_x92 + l0)
        _x94 = -l0
        _x95 = -_isigma0 - _x94
        _x96 = 0.06261203632181017*k_c
        _x97 = -_isigma1 - _x94
        _x98 = 0.4444444444444444*k_c
        _x99 = -_isigma2 - _x94
        _x100 = 0.4929435192337454*k_c
        _x101 = (0.06261203632181017*_iF0 + 0.4444444444444444*_iF1 + 0.4929435192337454*_iF2 - _x100*_x99
            + _x93 - _x95*_x96 - _x97*_x98)
        _x102 = math.sqrt(_x101**2 + _x91*k_c)
        _x103 = _x101 + _x102
        _x104 = (1.0/_x103)
        _D__next = _x104*_x91
        _x105 = _x95*k_c
        _x106 = _x97*k_c
        _x107 = _x99*k_c
        _x108 = (1.0/_x102)
        _x109 = _x104**2
        _x110 = _x109*_x91
        _pd__89 = (_x110*(-_x108*(0.0039202670923636765*_iF0 + 0.0278275716985823*_iF1
            + 0.030864197530864196*_iF2 - 0.0039202670923636765*_x105 - 0.0278275716985823*_x106
            - 0.030864197530864196*_x107 + 0.06261203632181017*_x93) - 0.06261203632181017))
        _pd__90 = (_x110*(-_x108*(0.0278275716985823*_iF0 + 0.19753086419753085*_iF1
            + 0.21908600854833127*_iF2 - 0.0278275716985823*_x105 - 0.19753086419753085*_x106
            - 0.21908600854833127*_x107 + 0.4444444444444444*_x93) - 0.4444444444444444))
        _pd__91 = (_x110*(-_x108*(0.030864197530864196*_iF0 + 0.21908600854833127*_iF1
            + 0.24299331315454992*_iF2 - 0.030864197530864196*_x105 - 0.21908600854833127*_x106
            - 0.24299331315454992*_x107 + 0.4929435192337454*_x93) - 0.4929435192337454))
        _x111 = _x101*_x108
        _pd__92 = _x110*(-_x111*_x96 - _x96)
        _pd__93 = _x110*(-_x111*_x98 - _x98)
        _pd__94 = _x110*(-_x100*_x111 - _x100)
        _d_D__next__0 = (_d_iF0__0*_pd__89 + _d_iF1__0*_pd__90 + _d_iF2__0*_pd__91 + _d_isigma0__0*_pd__92
            + _d_isigma1__0*_pd__93 + _d_isigma2__0*_pd__94 + _x110*(_x111*k_c + k_c))
        _x112 = 0.9872983346207417*_pd__92
        _x113 = 0.75*_pd__93
        _x114 = 0.2127016653792583*_pd__94
        _d_D__next__1 = (-_d_D__1*_x112 - _d_D__1*_x113 - _d_D__1*_x114 + _d_iF0__1*_pd__89
            + _d_iF1__1*_pd__90 + _d_iF2__1*_pd__91 + 2.0*_x104*m*q_rd - _x108*_x109*k_c*m**2*q_rd**3)
        _d_D__next__2 = (-_d_D__2*_x112 - _d_D__2*_x113 - _d_D__2*_x114 + _d_iF0__2*_pd__89
            + _d_iF1__2*_pd__90 + _d_iF2__2*_pd__91)
        _d_D__next__3 = (-_d_D__3*_x112 - _d_D__3*_x113 - _d_D__3*_x114 + _d_iF0__3*_pd__89
            + _d_iF1__3*_pd__90 + _d_iF2__3*_pd__91)
        _x115 = 2.0*q_r
        _d_D__next__4 = (-_d_D__4*_x112 - _d_D__4*_x113 - _d_D__4*_x114 + _d_iF0__4*_pd__89
            + _d_iF1__4*_pd__90 + _d_iF2__4*_pd__91 + _x110*(-0.06261203632181017*_isigma0
            - 0.4444444444444444*_isigma1 - 0.4929435192337454*_isigma2
            - _x108*((0.5)*_x101*(0.12522407264362034*_isigma0 + 0.8888888888888888*_isigma1
            + 0.9858870384674908*_isigma2 - _x115) + (0.5)*_x91) - _x92))
        _d_D__next__5 = (-_d_D__5*_x112 - _d_D__5*_x113 - _d_D__5*_x114 + _d_iF0__5*_pd__89
            + _d_iF1__5*_pd__90 + _d_iF2__5*_pd__91)
        _Q0__next = 0.1388888888888889*_ifq0 + 0.48042111196938336*_ifq1 + 0.26798833376246944*_ifq2 + q_th
        _d_Q0__next__0 = (0.1388888888888889*_d_ifq0__0 + 0.48042111196938336*_d_ifq1__0
            + 0.26798833376246944*_d_ifq2__0)
        _d_Q0__next__1 = (0.1388888888888889*_d_ifq0__1 + 0.48042111196938336*_d_ifq1__1
            + 0.26798833376246944*_d_ifq2__1)
        _d_Q0__next__2 = (0.1388888888888889*_d_ifq0__2 + 0.48042111196938336*_d_ifq1__2
            + 0.26798833376246944*_d_ifq2__2 + 1.0)
        _d_Q0__next__3 = (0.1388888888888889*_d_ifq0__3 + 0.48042111196938336*_d_ifq1__3
            + 0.26798833376246944*_d_ifq2__3)
        _d_Q0__next__4 = (0.1388888888888889*_d_ifq0__4 + 0.48042111196938336*_d_ifq1__4
            + 0.26798833376246944*_d_ifq2__4)
        _d_Q0__next__5 = (0.1388888888888889*_d_ifq0__5 + 0.48042111196938336*_d_ifq1__5
            + 0.26798833376246944*_d_ifq2__5)
        _Q1__next = -0.022485417203086815*_ifq0 + 0.2222222222222222*_ifq1 + 0.30026319498086457*_ifq2 + q_th
        _d_Q1__next__0 = (-0.022485417203086815*_d_ifq0__0 + 0.2222222222222222*_d_ifq1__0
            + 0.30026319498086457*_d_ifq2__0)
        _d_Q1__next__1 = (-0.022485417203086815*_d_ifq0__1 + 0.2222222222222222*_d_ifq1__1
            + 0.30026319498086457*_d_ifq2__1)
        _d_Q1__next__2 = (-0.022485417203086815*_d_ifq0__2 + 0.2222222222222222*_d_ifq1__2
            + 0.30026319498086457*_d_ifq2__2 + 1.0)
        _d_Q1__next__3 = (-0.022485417203086815*_d_ifq0__3 + 0.2222222222222222*_d_ifq1__3
            + 0.30026319498086457*_d_ifq2__3)
        _d_Q1__next__4 = (-0.022485417203086815*_d_ifq0__4 + 0.2222222222222222*_d_ifq1__4
            + 0.30026319498086457*_d_ifq2__4)
        _d_Q1__next__5 = (-0.022485417203086815*_d_ifq0__5 + 0.2222222222222222*_d_ifq1__5
            + 0.30026319498086457*_d_ifq2__5)
        _Q2__next = 0.009789444015308325*_ifq0 - 0.0359766675249389*_ifq1 + 0.1388888888888889*_ifq2 + q_th
        _d_Q2__next__0 = (0.009789444015308325*_d_ifq0__0 - 0.0359766675249389*_d_ifq1__0
            + 0.1388888888888889*_d_ifq2__0)
        _d_Q2__next__1 = (0.009789444015308325*_d_ifq0__1 - 0.0359766675249389*_d_ifq1__1
            + 0.1388888888888889*_d_ifq2__1)
        _d_Q2__next__2 = (0.009789444015308325*_d_ifq0__2 - 0.0359766675249389*_d_ifq1__2
            + 0.1388888888888889*_d_ifq2__2 + 1.0)
        _d_Q2__next__3 = (0.009789444015308325*_d_ifq0__3 - 0.0359766675249389*_d_ifq1__3
            + 0.1388888888888889*_d_ifq2__3)
        _d_Q2__next__4 = (0.009789444015308325*_d_ifq0__4 - 0.0359766675249389*_d_ifq1__4
            + 0.1388888888888889*_d_ifq2__4)
        _d_Q2__next__5 = (0.009789444015308325*_d_ifq0__5 - 0.0359766675249389*_d_ifq1__5
            + 0.1388888888888889*_d_ifq2__5)
        _x116 = m*q_r**2
        _x117 = _x116*q_thd
        _P0__next = 0.1388888888888889*_ifp0 + 0.48042111196938336*_ifp1 + 0.26798833376246944*_ifp2 + _x117
        _x118 = _x115*m*q_thd
        _d_P0__next__0 = (0.1388888888888889*_d_ifp0__0 + 0.48042111196938336*_d_ifp1__0
            + 0.26798833376246944*_d_ifp2__0 + _x118)
        _d_P0__next__1 = (0.1388888888888889*_d_ifp0__1 + 0.48042111196938336*_d_ifp1__1
            + 0.26798833376246944*_d_ifp2__1)
        _d_P0__next__2 = (0.1388888888888889*_d_ifp0__2 + 0.48042111196938336*_d_ifp1__2
            + 0.26798833376246944*_d_ifp2__2)
        _d_P0__next__3 = (0.1388888888888889*_d_ifp0__3 + 0.48042111196938336*_d_ifp1__3
            + 0.26798833376246944*_d_ifp2__3 + _x116)
        _d_P0__next__4 = (0.1388888888888889*_d_ifp0__4 + 0.48042111196938336*_d_ifp1__4
            + 0.26798833376246944*_d_ifp2__4)
        _d_P0__next__5 = (0.1388888888888889*_d_ifp0__5 + 0.48042111196938336*_d_ifp1__5
            + 0.26798833376246944*_d_ifp2__5)
        _P1__next = -0.022485417203086815*_ifp0 + 0.2222222222222222*_ifp1 + 0.30026319498086457*_ifp2 + _x117
        _d_P1__next__0 = (-0.022485417203086815*_d_ifp0__0 + 0.2222222222222222*_d_ifp1__0
            + 0.30026319498086457*_d_ifp2__0 + _x118)
        _d_P1__next__1 = (-0.022485417203086815*_d_ifp0__1 + 0.2222222222222222*_d_ifp1__1
            + 0.30026319498086457*_d_ifp2__1)
        _d_P1__next__2 = (-0.022485417203086815*_d_ifp0__2 + 0.2222222222222222*_d_ifp1__2
            + 0.30026319498086457*_d_ifp2__2)
        _d_P1__next__3 = (-0.022485417203086815*_d_ifp0__3 + 0.2222222222222222*_d_ifp1__3
            + 0.30026319498086457*_d_ifp2__3 + _x116)
        _d_P1__next__4 = (-0.022485417203086815*_d_ifp0__4 + 0.2222222222222222*_d_ifp1__4
            + 0.30026319498086457*_d_ifp2__4)
        _d_P1__next__5 = (-0.022485417203086815*_d_ifp0__5 + 0.2222222222222222*_d_ifp1__5
            + 0.30026319498086457*_d_ifp2__5)
        _P2__next = 0.009789444015308325*_ifp0 - 0.0359766675249389*_ifp1 + 0.1388888888888889*_ifp2 + _x117
        _d_P2__next__0 = (0.009789444015308325*_d_ifp0__0 - 0.0359766675249389*_d_ifp1__0
            + 0.1388888888888889*_d_ifp2__0 + _x118)
        _d_P2__next__1 = (0.009789444015308325*_d_ifp0__1 - 0.0359766675249389*_d_ifp1__1
            + 0.1388888888888889*_d_ifp2__1)
        _d_P2__next__2 = (0.009789444015308325*_d_ifp0__2 - 0.0359766675249389*_d_ifp1__2
            + 0.1388888888888889*_d_ifp2__2)
        _d_P2__next__3 = (0.009789444015308325*_d_ifp0__3 - 0.0359766675249389*_d_ifp1__3
            + 0.1388888888888889*_d_ifp2__3 + _x116)
        _d_P2__next__4 = (0.009789444015308325*_d_ifp0__4 - 0.0359766675249389*_d_ifp1__4
            + 0.1388888888888889*_d_ifp2__4)
        _d_P2__next__5 = (0.009789444015308325*_d_ifp0__5 - 0.0359766675249389*_d_ifp1__5
            + 0.1388888888888889*_d_ifp2__5)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_Q2__next - _Q2) <= tol*(1.0)) and (abs(_P0__next
            - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_P1__next - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_P2__next - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _Q2__next, _P0__next, _P1__next, _P2__next, _d_D__next__0,
            _d_D__next__1, _d_D__next__2, _d_D__next__3, _d_D__next__4, _d_D__next__5, _d_Q0__next__0,
            _d_Q0__next__1, _d_Q0__next__2, _d_Q0__next__3, _d_Q0__next__4, _d_Q0__next__5, _d_Q1__next__0,
            _d_Q1__next__1, _d_Q1__next__2, _d_Q1__next__3, _d_Q1__next__4, _d_Q1__next__5, _d_Q2__next__0,
            _d_Q2__next__1, _d_Q2__next__2, _d_Q2__next__3, _d_Q2__next__4, _d_Q2__next__5, _d_P0__next__0,
            _d_P0__next__1, _d_P0__next__2, _d_P0__next__3, _d_P0__next__4, _d_P0__next__5, _d_P1__next__0,
            _d_P1__next__1, _d_P1__next__2, _d_P1__next__3, _d_P1__next__4, _d_P1__next__5, _d_P2__next__0,
            _d_P2__next__1, _d_P2__next__2, _d_P2__next__3, _d_P2__next__4, _d_P2__next__5, )
        _pk0 = _pkn0
        _passes += 1.0
    # bottom state
    t_half = 0.2777777777777778*_ift0 + 0.4444444444444444*_ift1 + 0.2777777777777778*_ift2
    d_t_half__0 = (0.2777777777777778*_d_ift0__0 + 0.4444444444444444*_d_ift1__0
        + 0.2777777777777778*_d_ift2__0)
    d_t_half__1 = (0.2777777777777778*_d_ift0__1 + 0.4444444444444444*_d_ift1__1
        + 0.2777777777777778*_d_ift2__1)
    d_t_half__2 = (0.2777777777777778*_d_ift0__2 + 0.4444444444444444*_d_ift1__2
        + 0.2777777777777778*_d_ift2__2)
    d_t_half__3 = (0.2777777777777778*_d_ift0__3 + 0.4444444444444444*_d_ift1__3
        + 0.2777777777777778*_d_ift2__3)
    d_t_half__4 = (0.2777777777777778*_d_ift0__4 + 0.4444444444444444*_d_ift1__4
        + 0.2777777777777778*_d_ift2__4)
    d_t_half__5 = (0.2777777777777778*_d_ift0__5 + 0.4444444444444444*_d_ift1__5
        + 0.2777777777777778*_d_ift2__5)
    end_q_th = 0.2777777777777778*_ifq0 + 0.4444444444444444*_ifq1 + 0.2777777777777778*_ifq2 + q_th
    d_end_q_th__0 = (0.2777777777777778*_d_ifq0__0 + 0.4444444444444444*_d_ifq1__0
        + 0.2777777777777778*_d_ifq2__0)
    d_end_q_th__1 = (0.2777777777777778*_d_ifq0__1 + 0.4444444444444444*_d_ifq1__1
        + 0.2777777777777778*_d_ifq2__1)
    d_end_q_th__2 = (0.2777777777777778*_d_ifq0__2 + 0.4444444444444444*_d_ifq1__2
        + 0.2777777777777778*_d_ifq2__2 + 1.0)
    d_end_q_th__3 = (0.2777777777777778*_d_ifq0__3 + 0.4444444444444444*_d_ifq1__3
        + 0.2777777777777778*_d_ifq2__3)
    d_end_q_th__4 = (0.2777777777777778*_d_ifq0__4 + 0.4444444444444444*_d_ifq1__4
        + 0.2777777777777778*_d_ifq2__4)
    d_end_q_th__5 = (0.2777777777777778*_d_ifq0__5 + 0.4444444444444444*_d_ifq1__5
        + 0.2777777777777778*_d_ifq2__5)
    _x119 = -_D + q_r
    end_q_r = _x119
    d_end_q_r__0 = 1.0 - _d_D__0
    end_q_rd = 0.0
    _x120 = q_r**2
    _x121 = 0.2777777777777778*_ifp0 + 0.4444444444444444*_ifp1 + 0.2777777777777778*_ifp2 + _x120*m*q_thd
    _x126 = (1.0/_x119)
    _x122 = _x126**2
    _x123 = (1.0/m)
    _x124 = _x122*_x123
    end_q_thd = _x121*_x124
    _x125 = 0.2777777777777778*_x124
    _pd__95 = _x125
    _pd__96 = 0.4444444444444444*_x124
    _pd__97 = _x125
    _pd__98 = -2.0*_x121*_x123*_x126**3
    d_end_q_thd__0 = (_d_ifp0__0*_pd__95 + _d_ifp1__0*_pd__96 + _d_ifp2__0*_pd__97 + _pd__98*d_end_q_r__0
        + 2.0*_x122*q_r*q_thd)
    d_end_q_thd__1 = -_d_D__1*_pd__98 + _d_ifp0__1*_pd__95 + _d_ifp1__1*_pd__96 + _d_ifp2__1*_pd__97
    d_end_q_thd__2 = -_d_D__2*_pd__98 + _d_ifp0__2*_pd__95 + _d_ifp1__2*_pd__96 + _d_ifp2__2*_pd__97
    d_end_q_thd__3 = (-_d_D__3*_pd__98 + _d_ifp0__3*_pd__95 + _d_ifp1__3*_pd__96 + _d_ifp2__3*_pd__97
        + _x120*_x122)
    d_end_q_thd__4 = -_d_D__4*_pd__98 + _d_ifp0__4*_pd__95 + _d_ifp1__4*_pd__96 + _d_ifp2__4*_pd__97
    d_end_q_thd__5 = -_d_D__5*_pd__98 + _d_ifp0__5*_pd__95 + _d_ifp1__5*_pd__96 + _d_ifp2__5*_pd__97
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # tangents as every branch names them
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_r__5 = -_d_D__5
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
        d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes, d_end_q_r__1,
        d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4,
        d_t_half__5, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp6_4eaacb_3(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2, d_guess_q_r__3,
        d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2, d_guess_q_th__3,
        d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1, d_guess_q_thd__2,
        d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol):
    """Branch nodes = 3 of schwind_compression_jvp6_4eaacb (outlined: derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 2005
    # Picard passes on the 4 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 0.9305681557970263*guess_q_th + 0.06943184420297371*q_th,
        0.6699905217924281*guess_q_th + 0.33000947820757187*q_th, 0.33000947820757187*guess_q_th
        + 0.6699905217924281*q_th, 0.06943184420297371*guess_q_th + 0.9305681557970263*q_th,
        0.9305681557970263*guess_q_r**2*guess_q_thd*m + 0.06943184420297371*m*q_r**2*q_thd,
        0.6699905217924281*guess_q_r**2*guess_q_thd*m + 0.33000947820757187*m*q_r**2*q_thd,
        0.33000947820757187*guess_q_r**2*guess_q_thd*m + 0.6699905217924281*m*q_r**2*q_thd,
        0.06943184420297371*guess_q_r**2*guess_q_thd*m + 0.9305681557970263*m*q_r**2*q_thd, 1.0
        - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2, -d_guess_q_r__3, -d_guess_q_r__4, -d_guess_q_r__5,
        0.9305681557970263*d_guess_q_th__0, 0.9305681557970263*d_guess_q_th__1,
        0.9305681557970263*d_guess_q_th__2 + 0.06943184420297371, 0.9305681557970263*d_guess_q_th__3,
        0.9305681557970263*d_guess_q_th__4, 0.9305681557970263*d_guess_q_th__5,
        0.6699905217924281*d_guess_q_th__0, 0.6699905217924281*d_guess_q_th__1,
        0.6699905217924281*d_guess_q_th__2 + 0.33000947820757187, 0.6699905217924281*d_guess_q_th__3,
        0.6699905217924281*d_guess_q_th__4, 0.6699905217924281*d_guess_q_th__5,
        0.33000947820757187*d_guess_q_th__0, 0.33000947820757187*d_guess_q_th__1,
        0.33000947820757187*d_guess_q_th__2 + 0.6699905217924281, 0.33000947820757187*d_guess_q_th__3,
        0.33000947820757187*d_guess_q_th__4, 0.33000947820757187*d_guess_q_th__5,
        0.06943184420297371*d_guess_q_th__0, 0.06943184420297371*d_guess_q_th__1,
        0.06943184420297371*d_guess_q_th__2 + 0.9305681557970263, 0.06943184420297371*d_guess_q_th__3,
        0.06943184420297371*d_guess_q_th__4, 0.06943184420297371*d_guess_q_th__5,
        1.8611363115940527*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__0*guess_q_r**2*m + 0.13886368840594743*m*q_r*q_thd,
        1.8611363115940527*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__1*guess_q_r**2*m,
        1.8611363115940527*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__2*guess_q_r**2*m,
        1.8611363115940527*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__3*guess_q_r**2*m + 0.06943184420297371*m*q_r**2,
        1.8611363115940527*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__4*guess_q_r**2*m,
        1.8611363115940527*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__5*guess_q_r**2*m,
        1.3399810435848563*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__0*guess_q_r**2*m + 0.6600189564151437*m*q_r*q_thd,
        1.3399810435848563*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__1*guess_q_r**2*m,
        1.3399810435848563*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__2*guess_q_r**2*m,
        1.3399810435848563*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__3*guess_q_r**2*m + 0.33000947820757187*m*q_r**2,
        1.3399810435848563*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__4*guess_q_r**2*m,
        1.3399810435848563*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__5*guess_q_r**2*m,
        0.6600189564151437*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__0*guess_q_r**2*m + 1.3399810435848563*m*q_r*q_thd,
        0.6600189564151437*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__1*guess_q_r**2*m,
        0.6600189564151437*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__2*guess_q_r**2*m,
        0.6600189564151437*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__3*guess_q_r**2*m + 0.6699905217924281*m*q_r**2,
        0.6600189564151437*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__4*guess_q_r**2*m,
        0.6600189564151437*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__5*guess_q_r**2*m,
        0.13886368840594743*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__0*guess_q_r**2*m + 1.8611363115940527*m*q_r*q_thd,
        0.13886368840594743*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__1*guess_q_r**2*m,
        0.13886368840594743*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__2*guess_q_r**2*m,
        0.13886368840594743*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__3*guess_q_r**2*m + 0.9305681557970263*m*q_r**2,
        0.13886368840594743*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__4*guess_q_r**2*m,
        0.13886368840594743*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__5*guess_q_r**2*m, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _Q2, _Q3, _P0, _P1, _P2, _P3, _d_D__0, _d_D__1, _d_D__2, _d_D__3, _d_D__4, _d_D__5,
            _d_Q0__0, _d_Q0__1, _d_Q0__2, _d_Q0__3, _d_Q0__4, _d_Q0__5, _d_Q1__0, _d_Q1__1, _d_Q1__2,
            _d_Q1__3, _d_Q1__4, _d_Q1__5, _d_Q2__0, _d_Q2__1, _d_Q2__2, _d_Q2__3, _d_Q2__4, _d_Q2__5,
            _d_Q3__0, _d_Q3__1, _d_Q3__2, _d_Q3__3, _d_Q3__4, _d_Q3__5, _d_P0__0, _d_P0__1, _d_P0__2,
            _d_P0__3, _d_P0__4, _d_P0__5, _d_P1__0, _d_P1__1, _d_P1__2, _d_P1__3, _d_P1__4, _d_P1__5,
            _d_P2__0, _d_P2__1, _d_P2__2, _d_P2__3, _d_P2__4, _d_P2__5, _d_P3__0, _d_P3__1, _d_P3__2,
            _d_P3__3, _d_P3__4, _d_P3__5, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9951792190105739*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _d_isigma0__0 = 1.0 - 0.9951792190105739*_d_D__0
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x112 = (1.0/_x2)
        _x10 = _x112**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__99 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__100 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__101 = -_x112**4*_x15*_x8 - k_c
        _d_iF0__0 = _d_P0__0*_pd__99 + _d_Q0__0*_pd__100 + _d_isigma0__0*_pd__101
        _x16 = 0.9951792190105739*_pd__101
        _d_iF0__1 = -_d_D__1*_x16 + _d_P0__1*_pd__99 + _d_Q0__1*_pd__100
        _d_iF0__2 = -_d_D__2*_x16 + _d_P0__2*_pd__99 + _d_Q0__2*_pd__100
        _d_iF0__3 = -_d_D__3*_x16 + _d_P0__3*_pd__99 + _d_Q0__3*_pd__100
        _d_iF0__4 = -_d_D__4*_x16 + _d_P0__4*_pd__99 + _d_Q0__4*_pd__100 + _x1 + l0
        _d_iF0__5 = -_d_D__5*_x16 + _d_P0__5*_pd__99 + _d_Q0__5*_pd__100
        _x17 = 0.8910937442931661*_D + _x0
        _x18 = -_x17
        _isigma1 = _x18
        _d_isigma1__0 = 1.0 - 0.8910937442931661*_d_D__0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x5
        _x21 = _x18*k_c
        _x22 = _P1**2
        _x111 = (1.0/_x18)
        _x23 = _x111**3
        _x24 = _x23*_x9
        _x25 = _x22*_x24
        _iF1 = -_x20 - _x21 + _x25 + _x3
        _x26 = 2.0*_P1
        _pd__102 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__103 = _x27*_x5
        _pd__104 = -_x111**4*_x15*_x22 - k_c
        _d_iF1__0 = _d_P1__0*_pd__102 + _d_Q1__0*_pd__103 + _d_isigma1__0*_pd__104
        _x28 = 0.8910937442931661*_pd__104
        _d_iF1__1 = -_d_D__1*_x28 + _d_P1__1*_pd__102 + _d_Q1__1*_pd__103
        _d_iF1__2 = -_d_D__2*_x28 + _d_P1__2*_pd__102 + _d_Q1__2*_pd__103
        _d_iF1__3 = -_d_D__3*_x28 + _d_P1__3*_pd__102 + _d_Q1__3*_pd__103
        _d_iF1__4 = -_d_D__4*_x28 + _d_P1__4*_pd__102 + _d_Q1__4*_pd__103 + _x17 + l0
        _d_iF1__5 = -_d_D__5*_x28 + _d_P1__5*_pd__102 + _d_Q1__5*_pd__103
        _x29 = 0.5511127007083099*_D + _x0
        _x30 = -_x29
        _isigma2 = _x30
        _d_isigma2__0 = 1.0 - 0.5511127007083099*_d_D__0
        _x31 = math.cos(_Q2)
        _x32 = _x31*_x5
        _x33 = _x30*k_c
        _x34 = _P2**2
        _x113 = (1.0/_x30)
        _x35 = _x113**3
        _x36 = _x35*_x9
        _x37 = _x34*_x36
        _iF2 = _x3 - _x32 - _x33 + _x37
        _x38 = 2.0*_P2
        _pd__105 = _x36*_x38
        _x39 = math.sin(_Q2)
        _pd__106 = _x39*_x5
        _pd__107 = -_x113**4*_x15*_x34 - k_c
        _d_iF2__0 = _d_P2__0*_pd__105 + _d_Q2__0*_pd__106 + _d_isigma2__0*_pd__107
        _x40 = 0.5511127007083099*_pd__107
        _d_iF2__1 = -_d_D__1*_x40 + _d_P2__1*_pd__105 + _d_Q2__1*_pd__106
        _d_iF2__2 = -_d_D__2*_x40 + _d_P2__2*_pd__105 + _d_Q2__2*_pd__106
        _d_iF2__3 = -_d_D__3*_x40 + _d_P2__3*_pd__105 + _d_Q2__3*_pd__106
        _d_iF2__4 = -_d_D__4*_x40 + _d_P2__4*_pd__105 + _d_Q2__4*_pd__106 + _x29 + l0
        _d_iF2__5 = -_d_D__5*_x40 + _d_P2__5*_pd__105 + _d_Q2__5*_pd__106
        _x41 = 0.13404290741652142*_D + _x0
        _x42 = -_x41
        _isigma3 = _x42
        _d_isigma3__0 = 1.0 - 0.13404290741652142*_d_D__0
        _x43 = math.cos(_Q3)
        _x44 = _x43*_x5
        _x45 = _x42*k_c
        _x46 = _P3**2
        _x114 = (1.0/_x42)
        _x47 = _x114**3
        _x48 = _x47*_x9
        _x49 = _x46*_x48
        _iF3 = _x3 - _x44 - _x45 + _x49
        _x50 = 2.0*_P3
        _pd__108 = _x48*_x50
        _x51 = math.sin(_Q3)
        _pd__109 = _x5*_x51
        _pd__110 = -_x114**4*_x15*_x46 - k_c
        _d_iF3__0 = _d_P3__0*_pd__108 + _d_Q3__0*_pd__109 + _d_isigma3__0*_pd__110
        _x52 = 0.13404290741652142*_pd__110
        _d_iF3__1 = -_d_D__1*_x52 + _d_P3__1*_pd__108 + _d_Q3__1*_pd__109
        _d_iF3__2 = -_d_D__2*_x52 + _d_P3__2*_pd__108 + _d_Q3__2*_pd__109
        _d_iF3__3 = -_d_D__3*_x52 + _d_P3__3*_pd__108 + _d_Q3__3*_pd__109
        _d_iF3__4 = -_d_D__4*_x52 + _d_P3__4*_pd__108 + _d_Q3__4*_pd__109 + _x41 + l0
        _d_iF3__5 = -_d_D__5*_x52 + _d_P3__5*_pd__108 + _d_Q3__5*_pd__109
        _x53 = (0.582374038291501*_x12 + 0.12383458041329967*_x20 + 0.12383458041329967*_x21
            - 0.12383458041329967*_x25 + 0.5*_x3 - 0.0575898635297681*_x32 - 0.0575898635297681*_x33
            + 0.0575898635297681*_x37 + 0.016129321407969507*_x44 + 0.016129321407969507*_x45
            - 0.016129321407969507*_x49 - 0.582374038291501*_x6 - 0.582374038291501*_x7)
        _iPsi0 = _x53
        _d_iPsi0__0 = (0.582374038291501*_d_iF0__0 - 0.12383458041329967*_d_iF1__0
            + 0.0575898635297681*_d_iF2__0 - 0.016129321407969507*_d_iF3__0)
        _d_iPsi0__1 = (0.582374038291501*_d_iF0__1 - 0.12383458041329967*_d_iF1__1
            + 0.0575898635297681*_d_iF2__1 - 0.016129321407969507*_d_iF3__1)
        _d_iPsi0__2 = (0.582374038291501*_d_iF0__2 - 0.12383458041329967*_d_iF1__2
            + 0.0575898635297681*_d_iF2__2 - 0.016129321407969507*_d_iF3__2)
        _d_iPsi0__3 = (0.582374038291501*_d_iF0__3 - 0.12383458041329967*_d_iF1__3
            + 0.0575898635297681*_d_iF2__3 - 0.016129321407969507*_d_iF3__3)
        _d_iPsi0__4 = (0.582374038291501*_d_iF0__4 - 0.12383458041329967*_d_iF1__4
            + 0.0575898635297681*_d_iF2__4 - 0.016129321407969507*_d_iF3__4)
        _d_iPsi0__5 = (0.582374038291501*_d_iF0__5 - 0.12383458041329967*_d_iF1__5
            + 0.0575898635297681*_d_iF2__5 - 0.016129321407969507*_d_iF3__5)
        _x54 = (1.0/math.sqrt(_x53))
        _x55 = math.sqrt(_D)
        _x56 = math.sqrt(m)
        _x57 = _x55*_x56
        _ift0 = _x54*_x57
        _x58 = (0.5)/_x55
        _x59 = _x56*_x58
        _pd__111 = _x54*_x59
        _x60 = _x53**(-1.5)
        _x61 = (0.5)*_x57
        _pd__112 = -_x60*_x61
        _d_ift0__0 = _d_D__0*_pd__111 + _d_iPsi0__0*_pd__112
        _d_ift0__1 = _d_D__1*_pd__111 + _d_iPsi0__1*_pd__112
        _d_ift0__2 = _d_D__2*_pd__111 + _d_iPsi0__2*_pd__112
        _d_ift0__3 = _d_D__3*_pd__111 + _d_iPsi0__3*_pd__112
        _d_ift0__4 = _d_D__4*_pd__111 + _d_iPsi0__4*_pd__112
        _d_ift0__5 = _d_D__5*_pd__111 + _d_iPsi0__5*_pd__112
        _x62 = (1.0/_x56)
        _x63 = _x55*_x62
        _x64 = _x112**2
        _x65 = _x54*_x64
        _x66 = _x63*_x65
        _ifq0 = _P0*_x66
        _x67 = _x58*_x62
        _pd__113 = _P0*_x65*_x67
        _pd__114 = _x66
        _x68 = (0.5)*_x63
        _pd__115 = -_P0*_x60*_x64*_x68
        _pd__116 = -_x10*_x13*_x54*_x63
        _d_ifq0__0 = _d_D__0*_pd__113 + _d_P0__0*_pd__114 + _d_iPsi0__0*_pd__115 + _d_isigma0__0*_pd__116
        _x69 = 0.9951792190105739*_pd__116
        _d_ifq0__1 = _d_D__1*_pd__113 - _d_D__1*_x69 + _d_P0__1*_pd__114 + _d_iPsi0__1*_pd__115
        _d_ifq0__2 = _d_D__2*_pd__113 - _d_D__2*_x69 + _d_P0__2*_pd__114 + _d_iPsi0__2*_pd__115
        _d_ifq0__3 = _d_D__3*_pd__113 - _d_D__3*_x69 + _d_P0__3*_pd__114 + _d_iPsi0__3*_pd__115
        _d_ifq0__4 = _d_D__4*_pd__113 - _d_D__4*_x69 + _d_P0__4*_pd__114 + _d_iPsi0__4*_pd__115
        _d_ifq0__5 = _d_D__5*_pd__113 - _d_D__5*_x69 + _d_P0__5*_pd__114 + _d_iPsi0__5*_pd__115
        _x70 = g_s*m**(1.5)
        _x71 = _x55*_x70
        _x72 = _x54*_x71
        _x73 = _x14*_x72
        _ifp0 = _x2*_x73
        _x74 = _x14*_x2
        _x75 = _x58*_x70
        _pd__117 = _x54*_x74*_x75
        _pd__118 = _x2*_x4*_x72
        _x76 = (0.5)*_x71
        _pd__119 = -_x60*_x74*_x76
        _pd__120 = _x73
        _d_ifp0__0 = _d_D__0*_pd__117 + _d_Q0__0*_pd__118 + _d_iPsi0__0*_pd__119 + _d_isigma0__0*_pd__120
        _x77 = 0.9951792190105739*_pd__120
        _d_ifp0__1 = _d_D__1*_pd__117 - _d_D__1*_x77 + _d_Q0__1*_pd__118 + _d_iPsi0__1*_pd__119
        _d_ifp0__2 = _d_D__2*_pd__117 - _d_D__2*_x77 + _d_Q0__2*_pd__118 + _d_iPsi0__2*_pd__119
        _d_ifp0__3 = _d_D__3*_pd__117 - _d_D__3*_x77 + _d_Q0__3*_pd__118 + _d_iPsi0__3*_pd__119
        _d_ifp0__4 = _d_D__4*_pd__117 - _d_D__4*_x77 + _d_Q0__4*_pd__118 + _d_iPsi0__4*_pd__119
        _d_ifp0__5 = _d_D__5*_pd__117 - _d_D__5*_x77 + _d_Q0__5*_pd__118 + _d_iPsi0__5*_pd__119
        _x78 = (0.16000937841634696*_x10*_x8*_x9 - 0.39252437029865583*_x20 - 0.39252437029865583*_x21
            + 0.39252437029865583*_x22*_x23*_x9 + 0.0700094015044783*_x30*k_c + 0.0700094015044783*_x31*g_s*m
            - 0.0700094015044783*_x37 - 0.017475652789475504*_x44 - 0.017475652789475504*_x45
            + 0.017475652789475504*_x46*_x47*_x9 - 0.16000937841634696*_x6 - 0.16000937841634696*_x7
            + 0.5*k_c*l0)
        _iPsi1 = _x78
        _d_iPsi1__0 = (0.16000937841634696*_d_iF0__0 + 0.39252437029865583*_d_iF1__0
            - 0.0700094015044783*_d_iF2__0 + 0.017475652789475504*_d_iF3__0)
        _d_iPsi1__1 = (0.16000937841634696*_d_iF0__1 + 0.39252437029865583*_d_iF1__1
            - 0.0700094015044783*_d_iF2__1 + 0.017475652789475504*_d_iF3__1)
        _d_iPsi1__2 = (0.16000937841634696*_d_iF0__2 + 0.39252437029865583*_d_iF1__2
            - 0.0700094015044783*_d_iF2__2 + 0.017475652789475504*_d_iF3__2)
        _d_iPsi1__3 = (0.16000937841634696*_d_iF0__3 + 0.39252437029865583*_d_iF1__3
            - 0.0700094015044783*_d_iF2__3 + 0.017475652789475504*_d_iF3__3)
        _d_iPsi1__4 = (0.16000937841634696*_d_iF0__4 + 0.39252437029865583*_d_iF1__4
            - 0.0700094015044783*_d_iF2__4 + 0.017475652789475504*_d_iF3__4)
        _d_iPsi1__5 = (0.16000937841634696*_d_iF0__5 + 0.39252437029865583*_d_iF1__5
            - 0.0700094015044783*_d_iF2__5 + 0.017475652789475504*_d_iF3__5)
        _x79 = (1.0/math.sqrt(_x78))
        _ift1 = _x57*_x79
        _pd__121 = _x59*_x79
        _x80 = _x78**(-1.5)
        _pd__122 = -_x61*_x80
        _d_ift1__0 = _d_D__0*_pd__121 + _d_iPsi1__0*_pd__122
        _d_ift1__1 = _d_D__1*_pd__121 + _d_iPsi1__1*_pd__122
        _d_ift1__2 = _d_D__2*_pd__121 + _d_iPsi1__2*_pd__122
        _d_ift1__3 = _d_D__3*_pd__121 + _d_iPsi1__3*_pd__122
        _d_ift1__4 = _d_D__4*_pd__121 + _d_iPsi1__4*_pd__122
        _d_ift1__5 = _d_D__5*_pd__121 + _d_iPsi1__5*_pd__122
        _x81 = _x111**2
        _x82 = _x79*_x81
        _x83 = _x63*_x82
        _ifq1 = _P1*_x83
        _pd__123 = _P1*_x67*_x82
        _pd__124 = _x83
        _pd__125 = -_P1*_x68*_x80*_x81
        _pd__126 = -_x23*_x26*_x63*_x79
        _d_ifq1__0 = _d_D__0*_pd__123 + _d_P1__0*_pd__124 + _d_iPsi1__0*_pd__125 + _d_isigma1__0*_pd__126
        _x84 = 0.8910937442931661*_pd__126
        _d_ifq1__1 = _d_D__1*_pd__123 - _d_D__1*_x84 + _d_P1__1*_pd__124 + _d_iPsi1__1*_pd__125
        _d_ifq1__2 = _d_D__2*_pd__123 - _d_D__2*_x84 + _d_P1__2*_pd__124 + _d_iPsi1__2*_pd__125
        _d_ifq1__3 = _d_D__3*_pd__123 - _d_D__3*_x84 + _d_P1__3*_pd__124 + _d_iPsi1__3*_pd__125
        _d_ifq1__4 = _d_D__4*_pd__123 - _d_D__4*_x84 + _d_P1__4*_pd__124 + _d_iPsi1__4*_pd__125
        _d_ifq1__5 = _d_D__5*_pd__123 - _d_D__5*_x84 + _d_P1__5*_pd__124 + _d_iPsi1__5*_pd__125
        _x85 = _x71*_x79
        _x86 = _x27*_x85
        _ifp1 = _x18*_x86
        _x87 = _x18*_x27
        _pd__127 = _x75*_x79*_x87
        _pd__128 = _x18*_x19*_x85
        _pd__129 = -_x76*_x80*_x87
        _pd__130 = _x86
        _d_ifp1__0 = _d_D__0*_pd__127 + _d_Q1__0*_pd__128 + _d_iPsi1__0*_pd__129 + _d_isigma1__0*_pd__130
        _x88 = 0.8910937442931661*_pd__130
        _d_ifp1__1 = _d_D__1*_pd__127 - _d_D__1*_x88 + _d_Q1__1*_pd__128 + _d_iPsi1__1*_pd__129
        _d_ifp1__2 = _d_D__2*_pd__127 - _d_D__2*_x88 + _d_Q1__2*_pd__128 + _d_iPsi1__2*_pd__129
        _d_ifp1__3 = _d_D__3*_pd__127 - _d_D__3*_x88 + _d_Q1__3*_pd__128 + _d_iPsi1__3*_pd__129
        _d_ifp1__4 = _d_D__4*_pd__127 - _d_D__4*_x88 + _d_Q1__4*_pd__128 + _d_iPsi1__4*_pd__129
        _d_ifp1__5 = _d_D__5*_pd__127 - _d_D__5*_x88 + _d_Q1__5*_pd__128 + _d_iPsi1__5*_pd__129
        _x89 = (0.01613725546399532*_x10*_x8*_x9 - 0.2848443432415939*_x20 - 0.2848443432415939*_x21
            + 0.2848443432415939*_x22*_x23*_x9 - 0.21871326539550162*_x32 - 0.21871326539550162*_x33
            + 0.21871326539550162*_x34*_x35*_x9 + 0.019694864101090868*_x42*k_c
            + 0.019694864101090868*_x43*g_s*m - 0.019694864101090868*_x49 - 0.01613725546399532*_x6
            - 0.01613725546399532*_x7 + 0.5*k_c*l0)
        _iPsi2 = _x89
        _d_iPsi2__0 = (0.01613725546399532*_d_iF0__0 + 0.2848443432415939*_d_iF1__0
            + 0.21871326539550162*_d_iF2__0 - 0.019694864101090868*_d_iF3__0)
        _d_iPsi2__1 = (0.01613725546399532*_d_iF0__1 + 0.2848443432415939*_d_iF1__1
            + 0.21871326539550162*_d_iF2__1 - 0.019694864101090868*_d_iF3__1)
        _d_iPsi2__2 = (0.01613725546399532*_d_iF0__2 + 0.2848443432415939*_d_iF1__2
            + 0.21871326539550162*_d_iF2__2 - 0.019694864101090868*_d_iF3__2)
        _d_iPsi2__3 = (0.01613725546399532*_d_iF0__3 + 0.2848443432415939*_d_iF1__3
            + 0.21871326539550162*_d_iF2__3 - 0.019694864101090868*_d_iF3__3)
        _d_iPsi2__4 = (0.01613725546399532*_d_iF0__4 + 0.2848443432415939*_d_iF1__4
            + 0.21871326539550162*_d_iF2__4 - 0.019694864101090868*_d_iF3__4)
        _d_iPsi2__5 = (0.01613725546399532*_d_iF0__5 + 0.2848443432415939*_d_iF1__5
            + 0.21871326539550162*_d_iF2__5 - 0.019694864101090868*_d_iF3__5)
        _x90 = (1.0/math.sqrt(_x89))
        _ift2 = _x57*_x90
        _pd__131 = _x59*_x90
        _x91 = _x89**(-1.5)
        _pd__132 = -_x61*_x91
        _d_ift2__0 = _d_D__0*_pd__131 + _d_iPsi2__0*_pd__132
        _d_ift2__1 = _d_D__1*_pd__131 + _d_iPsi2__1*_pd__132
        _d_ift2__2 = _d_D__2*_pd__131 + _d_iPsi2__2*_pd__132
        _d_ift2__3 = _d_D__3*_pd__131 + _d_iPsi2__3*_pd__132
        _d_ift2__4 = _d_D__4*_pd__131 + _d_iPsi2__4*_pd__132
        _d_ift2__5 = _d_D__5*_pd__131 + _d_iPsi2__5*_pd__132
        _x92 = _x113**2
        _x93 = _x90*_x92
        _x94 = _x63*_x93
        _ifq2 = _P2*_x94
        _pd__133 = _P2*_x67*_x93
        _pd__134 = _x94
        _pd__135 = -_P2*_x68*_x91*_x92
        _pd__136 = -_x35*_x38*_x63*_x90
        _d_ifq2__0 = _d_D__0*_pd__133 + _d_P2__0*_pd__134 + _d_iPsi2__0*_pd__135 + _d_isigma2__0*_pd__136
        _x95 = 0.5511127007083099*_pd__136
        _d_ifq2__1 = _d_D__1*_pd__133 - _d_D__1*_x95 + _d_P2__1*_pd__134 + _d_iPsi2__1*_pd__135
        _d_ifq2__2 = _d_D__2*_pd__133 - _d_D__2*_x95 + _d_P2__2*_pd__134 + _d_iPsi2__2*_pd__135
        _d_ifq2__3 = _d_D__3*_pd__133 - _d_D__3*_x95 + _d_P2__3*_pd__134 + _d_iPsi2__3*_pd__135
        _d_ifq2__4 = _d_D__4*_pd__133 - _d_D__4*_x95 + _d_P2__4*_pd__134 + _d_iPsi2__4*_pd__135
        _d_ifq2__5 = _d_D__5*_pd__133 - _d_D__5*_x95 + _d_P2__5*_pd__134 + _d_iPsi2__5*_pd__135
        _x96 = _x71*_x90
        _x97 = _x39*_x96
        _ifp2 = _x30*_x97
        _x98 = _x30*_x39
        _pd__137 = _x75*_x90*_x98
        _pd__138 = _x30*_x31*_x96
        _pd__139 = -_x76*_x91*_x98
        _pd__140 = _x97
        _d_ifp2__0 = _d_D__0*_pd__137 + _d_Q2__0*_pd__138 + _d_iPsi2__0*_pd__139 + _d_isigma2__0*_pd__140
        _x99 = 0.5511127007083099*_pd__140
        _d_ifp2__1 = _d_D__1*_pd__137 - _d_D__1*_x99 + _d_Q2__1*_pd__138 + _d_iPsi2__1*_pd__139
        _d_ifp2__2 = _d_D__2*_pd__137 - _d_D__2*_x99 + _d_Q2__2*_pd__138 + _d_iPsi2__2*_pd__139
        _d_ifp2__3 = _d_D__3*_pd__137 - _d_D__3*_x99 + _d_Q2__3*_pd__138 + _d_iPsi2__3*_pd__139
        _d_ifp2__4 = _d_D__4*_pd__137 - _d_D__4*_x99 + _d_Q2__4*_pd__138 + _d_iPsi2__4*_pd__139
        _d_ifp2__5 = _d_D__5*_pd__137 - _d_D__5*_x99 + _d_Q2__5*_pd__138 + _d_iPsi2__5*_pd__139
        _x100 = (0.01796104633752054*_x10*_x8*_x9 - 0.11000222456933441*_x20 - 0.11000222456933441*_x21
            + 0.11000222456933441*_x22*_x23*_x9 - 0.2823150697454702*_x32 - 0.2823150697454702*_x33
            + 0.2823150697454702*_x34*_x35*_x9 - 0.08972165934767481*_x44 - 0.08972165934767481*_x45
            + 0.08972165934767481*_x46*_x47*_x9 - 0.01796104633752054*_x6 - 0.01796104633752054*_x7
            + 0.5*k_c*l0)
        _iPsi3 = _x100
        _d_iPsi3__0 = (0.01796104633752054*_d_iF0__0 + 0.11000222456933441*_d_iF1__0
            + 0.2823150697454702*_d_iF2__0 + 0.08972165934767481*_d_iF3__0)
        _d_iPsi3__1 = (0.01796104633752054*_d_iF0__1 + 0.11000222456933441*_d_iF1__1
            + 0.2823150697454702*_d_iF2__1 + 0.08972165934767481*_d_iF3__1)
        _d_iPsi3__2 = (0.01796104633752054*_d_iF0__2 + 0.11000222456933441*_d_iF1__2
            + 0.2823150697454702*_d_iF2__2 + 0.08972165934767481*_d_iF3__2)
        _d_iPsi3__3 = (0.01796104633752054*_d_iF0__3 + 0.11000222456933441*_d_iF1__3
            + 0.2823150697454702*_d_iF2__3 + 0.08972165934767481*_d_iF3__3)
        _d_iPsi3__4 = (0.01796104633752054*_d_iF0__4 + 0.11000222456933441*_d_iF1__4
            + 0.2823150697454702*_d_iF2__4 + 0.08972165934767481*_d_iF3__4)
        _d_iPsi3__5 = (0.01796104633752054*_d_iF0__5 + 0.11000222456933441*_d_iF1__5
            + 0.2823150697454702*_d_iF2__5 + 0.08972165934767481*_d_iF3__5)
        _x101 = (1.0/math.sqrt(_x100))
        _ift3 = _x101*_x57
        _pd__141 = _x101*_x59
        _x102 = _x100**(-1.5)
        _pd__142 = -_x102*_x61
        _d_ift3__0 = _d_D__0*_pd__141 + _d_iPsi3__0*_pd__142
        _d_ift3__1 = _d_D__1*_pd__141 + _d_iPsi3__1*_pd__142
        _d_ift3__2 = _d_D__2*_pd__141 + _d_iPsi3__2*_pd__142
        _d_ift3__3 = _d_D__3*_pd__141 + _d_iPsi3__3*_pd__142
        _d_ift3__4 = _d_D__4*_pd__141 + _d_iPsi3__4*_pd__142
        _d_ift3__5 = _d_D__5*_pd__141 + _d_iPsi3__5*_pd__142
        _x103 = _x114**2
        _x104 = _x101*_x103
        _x105 = _x104*_x63
        _ifq3 = _P3*_x105
        _pd__143 = _P3*_x104*_x67
        _pd__144 = _x105
        _pd__145 = -_P3*_x102*_x103*_x68
        _pd__146 = -_x101*_x47*_x50*_x63
        _d_ifq3__0 = _d_D__0*_pd__143 + _d_P3__0*_pd__144 + _d_iPsi3__0*_pd__145 + _d_isigma3__0*_pd__146
        _x106 = 0.13404290741652142*_pd__146
        _d_ifq3__1 = _d_D__1*_pd__143 - _d_D__1*_x106 + _d_P3__1*_pd__144 + _d_iPsi3__1*_pd__145
        _d_ifq3__2 = _d_D__2*_pd__143 - _d_D__2*_x106 + _d_P3__2*_pd__144 + _d_iPsi3__2*_pd__145
        _d_ifq3__3 = _d_D__3*_pd__143 - _d_D__3*_x106 + _d_P3__3*_pd__144 + _d_iPsi3__3*_pd__145
        _d_ifq3__4 = _d_D__4*_pd__143 - _d_D__4*_x106 + _d_P3__4*_pd__144 + _d_iPsi3__4*_pd__145
        _d_ifq3__5 = _d_D__5*_pd__143 - _d_D__5*_x106 + _d_P3__5*_pd__144 + _d_iPsi3__5*_pd__145
        _x107 = _x101*_x71
        _x108 = _x107*_x51
        _ifp3 = _x108*_x42
        _x109 = _x42*_x51
        _pd__147 = _x101*_x109*_x75
        _pd__148 = _x107*_x42*_x43
        _pd__149 = -_x102*_x109*_x76
        _pd__150 = _x108
        _d_ifp3__0 = _d_D__0*_pd__147 + _d_Q3__0*_pd__148 + _d_iPsi3__0*_pd__149 + _d_isigma3__0*_pd__150
        _x110 = 0.13404290741652142*_pd__150
        _d_ifp3__1 = _d_D__1*_pd__147 - _d_D__1*_x110 + _d_Q3__1*_pd__148 + _d_iPsi3__1*_pd__149
        _d_ifp3__2 = _d_D__2*_pd__147 - _d_D__2*_x110 + _d_Q3__2*_pd__148 + _d_iPsi3__2*_pd__149
        _d_ifp3__3 = _d_D__3*_pd__147 - _d_D__3*_x110 + _d_Q3__3*_pd__148 + _d_iPsi3__3*_pd__149
        _d_ifp3__4 = _d_D__4*_pd__147 - _d_D__4*_x110 + _d_Q3__4*_pd__148 + _d_iPsi3__4*_pd__149
        _d_ifp3__5 = _d_D__5*_pd__147 - _d_D__5*_x110 + _d_Q3__5*_pd__148 + _d_iPsi3__5*_pd__149
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x115 = m*q_rd**2
        _x116 = -q_r
        _x117 = k_c*(_x116 + l0)
        _x118 = -l0
        _x119 = -_isigma0 - _x118
        _x120 = 0.024152203412833244*k_c
        _x121 = -_isigma1 - _x118
        _x122 = 0.215214082271785*k_c
        _x123 = -_isigma2 - _x118
        _x124 = 0.43693107259076114*k_c
        _x125 = -_isigma3 - _x118
        _x126 = 0.3237026417246206*k_c
        _x127 = (0.024152203412833244*_iF0 + 0.215214082271785*_iF1 + 0.43693107259076114*_iF2
            + 0.3237026417246206*_iF3 + _x117 - _x119*_x120 - _x121*_x122 - _x123*_x124 - _x125*_x126)
        _x128 = math.sqrt(_x115*k_c + _x127**2)
        _x129 = _x127 + _x128
        _x130 = (1.0/_x129)
        _D__next = _x115*_x130
        _x131 = _x119*k_c
        _x132 = 0.0051978942923343804*k_c
        _x133 = _x123*k_c
        _x134 = _x125*k_c
        _x135 = (1.0/_x128)
        _x136 = _x130**2
        _x137 = _x115*_x136
        _pd__151 = (_x137*(-_x135*(0.0005833289296948737*_iF0 + 0.0051978942923343804*_iF1
            + 0.01055284814259947*_iF2 + 0.007818132048204519*_iF3 + 0.024152203412833244*_x117 - _x121*_x132
            - 0.0005833289296948737*_x131 - 0.01055284814259947*_x133 - 0.007818132048204519*_x134)
            - 0.024152203412833244))
        _x138 = _x121*k_c
        _pd__152 = (_x137*(-_x135*(0.0051978942923343804*_iF0 + 0.046317101208086645*_iF1
            + 0.09403371980364733*_iF2 + 0.06966536696771665*_iF3 + 0.215214082271785*_x117 - _x119*_x132
            - 0.09403371980364733*_x133 - 0.06966536696771665*_x134 - 0.046317101208086645*_x138)
            - 0.215214082271785))
        _pd__153 = (_x137*(-_x135*(0.01055284814259947*_iF0 + 0.09403371980364733*_iF1
            + 0.19090876219531297*_iF2 + 0.14143574244920135*_iF3 + 0.43693107259076114*_x117
            - 0.01055284814259947*_x131 - 0.19090876219531297*_x133 - 0.14143574244920135*_x134
            - 0.09403371980364733*_x138) - 0.43693107259076114))
        _pd__154 = (_x137*(-_x135*(0.007818132048204519*_iF0 + 0.06966536696771665*_iF1
            + 0.14143574244920135*_iF2 + 0.10478340025949809*_iF3 + 0.3237026417246206*_x117
            - 0.007818132048204519*_x131 - 0.14143574244920135*_x133 - 0.10478340025949809*_x134
            - 0.06966536696771665*_x138) - 0.3237026417246206))
        _x139 = _x127*_x135
        _pd__155 = _x137*(-_x120*_x139 - _x120)
        _pd__156 = _x137*(-_x122*_x139 - _x122)
        _pd__157 = _x137*(-_x124*_x139 - _x124)
        _pd__158 = _x137*(-_x126*_x139 - _x126)
        _d_D__next__0 = (_d_iF0__0*_pd__151 + _d_iF1__0*_pd__152 + _d_iF2__0*_pd__153 + _d_iF3__0*_pd__154
            + _d_isigma0__0*_pd__155 + _d_isigma1__0*_pd__156 + _d_isigma2__0*_pd__157
            + _d_isigma3__0*_pd__158 + _x137*(_x139*k_c + k_c))
        _x140 = 0.9951792190105739*_pd__155
        _x141 = 0.8910937442931661*_pd__156
        _x142 = 0.5511127007083099*_pd__157
        _x143 = 0.13404290741652142*_pd__158
        _d_D__next__1 = (-_d_D__1*_x140 - _d_D__1*_x141 - _d_D__1*_x142 - _d_D__1*_x143 + _d_iF0__1*_pd__151
            + _d_iF1__1*_pd__152 + _d_iF2__1*_pd__153 + _d_iF3__1*_pd__154 + 2.0*_x130*m*q_rd
            - _x135*_x136*k_c*m**2*q_rd**3)
        _d_D__next__2 = (-_d_D__2*_x140 - _d_D__2*_x141 - _d_D__2*_x142 - _d_D__2*_x143 + _d_iF0__2*_pd__151
            + _d_iF1__2*_pd__152 + _d_iF2__2*_pd__153 + _d_iF3__2*_pd__154)
        _d_D__next__3 = (-_d_D__3*_x140 - _d_D__3*_x141 - _d_D__3*_x142 - _d_D__3*_x143 + _d_iF0__3*_pd__151
            + _d_iF1__3*_pd__152 + _d_iF2__3*_pd__153 + _d_iF3__3*_pd__154)
        _x144 = 2.0*q_r
        _d_D__next__4 = (-_d_D__4*_x140 - _d_D__4*_x141 - _d_D__4*_x142 - _d_D__4*_x143 + _d_iF0__4*_pd__151
            + _d_iF1__4*_pd__152 + _d_iF2__4*_pd__153 + _d_iF3__4*_pd__154
            + _x137*(-0.024152203412833244*_isigma0 - 0.215214082271785*_isigma1
            - 0.43693107259076114*_isigma2 - 0.3237026417246206*_isigma3 - _x116 - _x135*((0.5)*_x115
            + (0.5)*_x127*(0.04830440682566649*_isigma0 + 0.43042816454357*_isigma1
            + 0.8738621451815223*_isigma2 + 0.6474052834492412*_isigma3 - _x144 - 8.470329472543003e-22*l0))
            + 4.235164736271502e-22*l0))
        _d_D__next__5 = (-_d_D__5*_x140 - _d_D__5*_x141 - _d_D__5*_x142 - _d_D__5*_x143 + _d_iF0__5*_pd__151
            + _d_iF1__5*_pd__152 + _d_iF2__5*_pd__153 + _d_iF3__5*_pd__154)
        _Q0__next = (0.08696371128436346*_ifq0 + 0.35267675751627187*_ifq1 + 0.31344511474186837*_ifq2
            + 0.1774825722545226*_ifq3 + q_th)
        _d_Q0__next__0 = (0.08696371128436346*_d_ifq0__0 + 0.35267675751627187*_d_ifq1__0
            + 0.31344511474186837*_d_ifq2__0 + 0.1774825722545226*_d_ifq3__0)
        _d_Q0__next__1 = (0.08696371128436346*_d_ifq0__1 + 0.35267675751627187*_d_ifq1__1
            + 0.31344511474186837*_d_ifq2__1 + 0.1774825722545226*_d_ifq3__1)
        _d_Q0__next__2 = (0.08696371128436346*_d_ifq0__2 + 0.35267675751627187*_d_ifq1__2
            + 0.31344511474186837*_d_ifq2__2 + 0.1774825722545226*_d_ifq3__2 + 1.0)
        _d_Q0__next__3 = (0.08696371128436346*_d_ifq0__3 + 0.35267675751627187*_d_ifq1__3
            + 0.31344511474186837*_d_ifq2__3 + 0.1774825722545226*_d_ifq3__3)
        _d_Q0__next__4 = (0.08696371128436346*_d_ifq0__4 + 0.35267675751627187*_d_ifq1__4
            + 0.31344511474186837*_d_ifq2__4 + 0.1774825722545226*_d_ifq3__4)
        _d_Q0__next__5 = (0.08696371128436346*_d_ifq0__5 + 0.35267675751627187*_d_ifq1__5
            + 0.31344511474186837*_d_ifq2__5 + 0.1774825722545226*_d_ifq3__5)
        _Q1__next = (-0.014190694931141144*_ifq0 + 0.16303628871563652*_ifq1 + 0.35395300603374397*_ifq2
            + 0.16719192197418878*_ifq3 + q_th)
        _d_Q1__next__0 = (-0.014190694931141144*_d_ifq0__0 + 0.16303628871563652*_d_ifq1__0
            + 0.35395300603374397*_d_ifq2__0 + 0.16719192197418878*_d_ifq3__0)
        _d_Q1__next__1 = (-0.014190694931141144*_d_ifq0__1 + 0.16303628871563652*_d_ifq1__1
            + 0.35395300603374397*_d_ifq2__1 + 0.16719192197418878*_d_ifq3__1)
        _d_Q1__next__2 = (-0.014190694931141144*_d_ifq0__2 + 0.16303628871563652*_d_ifq1__2
            + 0.35395300603374397*_d_ifq2__2 + 0.16719192197418878*_d_ifq3__2 + 1.0)
        _d_Q1__next__3 = (-0.014190694931141144*_d_ifq0__3 + 0.16303628871563652*_d_ifq1__3
            + 0.35395300603374397*_d_ifq2__3 + 0.16719192197418878*_d_ifq3__3)
        _d_Q1__next__4 = (-0.014190694931141144*_d_ifq0__4 + 0.16303628871563652*_d_ifq1__4
            + 0.35395300603374397*_d_ifq2__4 + 0.16719192197418878*_d_ifq3__4)
        _d_Q1__next__5 = (-0.014190694931141144*_d_ifq0__5 + 0.16303628871563652*_d_ifq1__5
            + 0.35395300603374397*_d_ifq2__5 + 0.16719192197418878*_d_ifq3__5)
        _Q2__next = (0.006735500594538156*_ifq0 - 0.027880428602470895*_ifq1 + 0.16303628871563652*_ifq2
            + 0.18811811749986806*_ifq3 + q_th)
        _d_Q2__next__0 = (0.006735500594538156*_d_ifq0__0 - 0.027880428602470895*_d_ifq1__0
            + 0.16303628871563652*_d_ifq2__0 + 0.18811811749986806*_d_ifq3__0)
        _d_Q2__next__1 = (0.006735500594538156*_d_ifq0__1 - 0.027880428602470895*_d_ifq1__1
            + 0.16303628871563652*_d_ifq2__1 + 0.18811811749986806*_d_ifq3__1)
        _d_Q2__next__2 = (0.006735500594538156*_d_ifq0__2 - 0.027880428602470895*_d_ifq1__2
            + 0.16303628871563652*_d_ifq2__2 + 0.18811811749986806*_d_ifq3__2 + 1.0)
        _d_Q2__next__3 = (0.006735500594538156*_d_ifq0__3 - 0.027880428602470895*_d_ifq1__3
            + 0.16303628871563652*_d_ifq2__3 + 0.18811811749986806*_d_ifq3__3)
        _d_Q2__next__4 = (0.006735500594538156*_d_ifq0__4 - 0.027880428602470895*_d_ifq1__4
            + 0.16303628871563652*_d_ifq2__4 + 0.18811811749986806*_d_ifq3__4)
        _d_Q2__next__5 = (0.006735500594538156*_d_ifq0__5 - 0.027880428602470895*_d_ifq1__5
            + 0.16303628871563652*_d_ifq2__5 + 0.18811811749986806*_d_ifq3__5)
        _Q3__next = (-0.0035551496857956833*_ifq0 + 0.012627462689404725*_ifq1 - 0.026604180084998794*_ifq2
            + 0.08696371128436346*_ifq3 + q_th)
        _d_Q3__next__0 = (-0.0035551496857956833*_d_ifq0__0 + 0.012627462689404725*_d_ifq1__0
            - 0.026604180084998794*_d_ifq2__0 + 0.08696371128436346*_d_ifq3__0)
        _d_Q3__next__1 = (-0.0035551496857956833*_d_ifq0__1 + 0.012627462689404725*_d_ifq1__1
            - 0.026604180084998794*_d_ifq2__1 + 0.08696371128436346*_d_ifq3__1)
        _d_Q3__next__2 = (-0.0035551496857956833*_d_ifq0__2 + 0.012627462689404725*_d_ifq1__2
            - 0.026604180084998794*_d_ifq2__2 + 0.08696371128436346*_d_ifq3__2 + 1.0)
        _d_Q3__next__3 = (-0.0035551496857956833*_d_ifq0__3 + 0.012627462689404725*_d_ifq1__3
            - 0.026604180084998794*_d_ifq2__3 + 0.08696371128436346*_d_ifq3__3)
        _d_Q3__next__4 = (-0.0035551496857956833*_d_ifq0__4 + 0.012627462689404725*_d_ifq1__4
            - 0.026604180084998794*_d_ifq2__4 + 0.08696371128436346*_d_ifq3__4)
        _d_Q3__next__5 = (-0.0035551496857956833*_d_ifq0__5 + 0.012627462689404725*_d_ifq1__5
            - 0.026604180084998794*_d_ifq2__5 + 0.08696371128436346*_d_ifq3__5)
        _x145 = m*q_r**2
        _x146 = _x145*q_thd
        _P0__next = (0.08696371128436346*_ifp0 + 0.35267675751627187*_ifp1 + 0.31344511474186837*_ifp2
            + 0.1774825722545226*_ifp3 + _x146)
        _x147 = _x144*m*q_thd
        _d_P0__next__0 = (0.08696371128436346*_d_ifp0__0 + 0.35267675751627187*_d_ifp1__0
            + 0.31344511474186837*_d_ifp2__0 + 0.1774825722545226*_d_ifp3__0 + _x147)
        _d_P0__next__1 = (0.08696371128436346*_d_ifp0__1 + 0.35267675751627187*_d_ifp1__1
            + 0.31344511474186837*_d_ifp2__1 + 0.1774825722545226*_d_ifp3__1)
        _d_P0__next__2 = (0.08696371128436346*_d_ifp0__2 + 0.35267675751627187*_d_ifp1__2
            + 0.31344511474186837*_d_ifp2__2 + 0.1774825722545226*_d_ifp3__2)
        _d_P0__next__3 = (0.08696371128436346*_d_ifp0__3 + 0.35267675751627187*_d_ifp1__3
            + 0.31344511474186837*_d_ifp2__3 + 0.1774825722545226*_d_ifp3__3 + _x145)
        _d_P0__next__4 = (0.08696371128436346*_d_ifp0__4 + 0.35267675751627187*_d_ifp1__4
            + 0.31344511474186837*_d_ifp2__4 + 0.1774825722545226*_d_ifp3__4)
        _d_P0__next__5 = (0.08696371128436346*_d_ifp0__5 + 0.35267675751627187*_d_ifp1__5
            + 0.31344511474186837*_d_ifp2__5 + 0.1774825722545226*_d_ifp3__5)
        _P1__next = (-0.014190694931141144*_ifp0 + 0.16303628871563652*_ifp1 + 0.35395300603374397*_ifp2
            + 0.16719192197418878*_ifp3 + _x146)
        _d_P1__next__0 = (-0.014190694931141144*_d_ifp0__0 + 0.16303628871563652*_d_ifp1__0
            + 0.35395300603374397*_d_ifp2__0 + 0.16719192197418878*_d_ifp3__0 + _x147)
        _d_P1__next__1 = (-0.014190694931141144*_d_ifp0__1 + 0.16303628871563652*_d_ifp1__1
            + 0.35395300603374397*_d_ifp2__1 + 0.16719192197418878*_d_ifp3__1)
        _d_P1__next__2 = (-0.014190694931141144*_d_ifp0__2 + 0.16303628871563652*_d_ifp1__2
            + 0.35395300603374397*_d_ifp2__2 + 0.16719192197418878*_d_ifp3__2)
        _d_P1__next__3 = (-0.014190694931141144*_d_ifp0__3 + 0.16303628871563652*_d_ifp1__3
            + 0.35395300603374397*_d_ifp2__3 + 0.16719192197418878*_d_ifp3__3 + _x145)
        _d_P1__next__4 = (-0.014190694931141144*_d_ifp0__4 + 0.16303628871563652*_d_ifp1__4
            + 0.35395300603374397*_d_ifp2__4 + 0.16719192197418878*_d_ifp3__4)
        _d_P1__next__5 = (-0.014190694931141144*_d_ifp0__5 + 0.16303628871563652*_d_ifp1__5
            + 0.35395300603374397*_d_ifp2__5 + 0.16719192197418878*_d_ifp3__5)
        _P2__next = (0.006735500594538156*_ifp0 - 0.027880428602470895*_ifp1 + 0.16303628871563652*_ifp2
            + 0.18811811749986806*_ifp3 + _x146)
        _d_P2__next__0 = (0.006735500594538156*_d_ifp0__0 - 0.027880428602470895*_d_ifp1__0
            + 0.16303628871563652*_d_ifp2__0 + 0.18811811749986806*_d_ifp3__0 + _x147)
        _d_P2__next__1 = (0.006735500594538156*_d_ifp0__1 - 0.027880428602470895*_d_ifp1__1
            + 0.16303628871563652*_d_ifp2__1 + 0.18811811749986806*_d_ifp3__1)
        _d_P2__next__2 = (0.006735500594538156*_d_ifp0__2 - 0.027880428602470895*_d_ifp1__2
            + 0.16303628871563652*_d_ifp2__2 + 0.18811811749986806*_d_ifp3__2)
        _d_P2__next__3 = (0.006735500594538156*_d_ifp0__3 - 0.027880428602470895*_d_ifp1__3
            + 0.16303628871563652*_d_ifp2__3 + 0.18811811749986806*_d_ifp3__3 + _x145)
        _d_P2__next__4 = (0.006735500594538156*_d_ifp0__4 - 0.027880428602470895*_d_ifp1__4
            + 0.16303628871563652*_d_ifp2__4 + 0.18811811749986806*_d_ifp3__4)
        _d_P2__next__5 = (0.006735500594538156*_d_ifp0__5 - 0.027880428602470895*_d_ifp1__5
            + 0.16303628871563652*_d_ifp2__5 + 0.18811811749986806*_d_ifp3__5)
        _P3__next = (-0.0035551496857956833*_ifp0 + 0.012627462689404725*_ifp1 - 0.026604180084998794*_ifp2
            + 0.08696371128436346*_ifp3 + _x146)
        _d_P3__next__0 = (-0.0035551496857956833*_d_ifp0__0 + 0.012627462689404725*_d_ifp1__0
            - 0.026604180084998794*_d_ifp2__0 + 0.08696371128436346*_d_ifp3__0 + _x147)
        _d_P3__next__1 = (-0.0035551496857956833*_d_ifp0__1 + 0.012627462689404725*_d_ifp1__1
            - 0.026604180084998794*_d_ifp2__1 + 0.08696371128436346*_d_ifp3__1)
        _d_P3__next__2 = (-0.0035551496857956833*_d_ifp0__2 + 0.012627462689404725*_d_ifp1__2
            - 0.026604180084998794*_d_ifp2__2 + 0.08696371128436346*_d_ifp3__2)
        _d_P3__next__3 = (-0.0035551496857956833*_d_ifp0__3 + 0.012627462689404725*_d_ifp1__3
            - 0.026604180084998794*_d_ifp2__3 + 0.08696371128436346*_d_ifp3__3 + _x145)
        _d_P3__next__4 = (-0.0035551496857956833*_d_ifp0__4 + 0.012627462689404725*_d_ifp1__4
            - 0.026604180084998794*_d_ifp2__4 + 0.08696371128436346*_d_ifp3__4)
        _d_P3__next__5 = (-0.0035551496857956833*_d_ifp0__5 + 0.012627462689404725*_d_ifp1__5
            - 0.026604180084998794*_d_ifp2__5 + 0.08696371128436346*_d_ifp3__5)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_Q2__next - _Q2) <= tol*(1.0)) and (abs(_Q3__next
            - _Q3) <= tol*(1.0)) and (abs(_P0__next - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))) and (abs(_P1__next - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))) and (abs(_P2__next - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))) and (abs(_P3__next - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _Q2__next, _Q3__next, _P0__next, _P1__next, _P2__next,
            _P3__next, _d_D__next__0, _d_D__next__1, _d_D__next__2, _d_D__next__3, _d_D__next__4,
            _d_D__next__5, _d_Q0__next__0, _d_Q0__next__1, _d_Q0__next__2, _d_Q0__next__3, _d_Q0__next__4,
            _d_Q0__next__5, _d_Q1__next__0, _d_Q1__next__1, _d_Q1__next__2, _d_Q1__next__3, _d_Q1__next__4,
            _d_Q1__next__5, _d_Q2__next__0, _d_Q2__next__1, _d_Q2__next__2, _d_Q2__next__3, _d_Q2__next__4,
            _d_Q2__next__5, _d_Q3__next__0, _d_Q3__next__1, _d_Q3__next__2, _d_Q3__next__3, _d_Q3__next__4,
            _d_Q3__next__5, _d_P0__next__0, _d_P0__next__1, _d_P0__next__2, _d_P0__next__3, _d_P0__next__4,
            _d_P0__next__5, _d_P1__next__0, _d_P1__next__1, _d_P1__next__2, _d_P1__next__3, _d_P1__next__4,
            _d_P1__next__5, _d_P2__next__0, _d_P2__next__1, _d_P2__next__2, _d_P2__next__3, _d_P2__next__4,
            _d_P2__next__5, _d_P3__next__0, _d_P3__next__1, _d_P3__next__2, _d_P3__next__3, _d_P3__next__4,
            _d_P3__next__5, )
        _pk0 = _pkn0
        _passes += 1.0
    # bottom state
    t_half = (0.17392742256872692*_ift0 + 0.32607257743127305*_ift1 + 0.32607257743127305*_ift2
        + 0.17392742256872692*_ift3)
    d_t_half__0 = (0.17392742256872692*_d_ift0__0 + 0.32607257743127305*_d_ift1__0
        + 0.32607257743127305*_d_ift2__0 + 0.17392742256872692*_d_ift3__0)
    d_t_half__1 = (0.17392742256872692*_d_ift0__1 + 0.32607257743127305*_d_ift1__1
        + 0.32607257743127305*_d_ift2__1 + 0.17392742256872692*_d_ift3__1)
    d_t_half__2 = (0.17392742256872692*_d_ift0__2 + 0.32607257743127305*_d_ift1__2
        + 0.32607257743127305*_d_ift2__2 + 0.17392742256872692*_d_ift3__2)
    d_t_half__3 = (0.17392742256872692*_d_ift0__3 + 0.32607257743127305*_d_ift1__3
        + 0.32607257743127305*_d_ift2__3 + 0.17392742256872692*_d_ift3__3)
    d_t_half__4 = (0.17392742256872692*_d_ift0__4 + 0.32607257743127305*_d_ift1__4
        + 0.32607257743127305*_d_ift2__4 + 0.17392742256872692*_d_ift3__4)
    d_t_half__5 = (0.17392742256872692*_d_ift0__5 + 0.32607257743127305*_d_ift1__5
        + 0.32607257743127305*_d_ift2__5 + 0.17392742256872692*_d_ift3__5)
    end_q_th = (0.17392742256872692*_ifq0 + 0.32607257743127305*_ifq1 + 0.32607257743127305*_ifq2
        + 0.17392742256872692*_ifq3 + q_th)
    d_end_q_th__0 = (0.17392742256872692*_d_ifq0__0 + 0.32607257743127305*_d_ifq1__0
        + 0.32607257743127305*_d_ifq2__0 + 0.17392742256872692*_d_ifq3__0)
    d_end_q_th__1 = (0.17392742256872692*_d_ifq0__1 + 0.32607257743127305*_d_ifq1__1
        + 0.32607257743127305*_d_ifq2__1 + 0.17392742256872692*_d_ifq3__1)
    d_end_q_th__2 = (0.17392742256872692*_d_ifq0__2 + 0.32607257743127305*_d_ifq1__2
        + 0.32607257743127305*_d_ifq2__2 + 0.17392742256872692*_d_ifq3__2 + 1.0)
    d_end_q_th__3 = (0.17392742256872692*_d_ifq0__3 + 0.32607257743127305*_d_ifq1__3
        + 0.32607257743127305*_d_ifq2__3 + 0.17392742256872692*_d_ifq3__3)
    d_end_q_th__4 = (0.17392742256872692*_d_ifq0__4 + 0.32607257743127305*_d_ifq1__4
        + 0.32607257743127305*_d_ifq2__4 + 0.17392742256872692*_d_ifq3__4)
    d_end_q_th__5 = (0.17392742256872692*_d_ifq0__5 + 0.32607257743127305*_d_ifq1__5
        + 0.32607257743127305*_d_ifq2__5 + 0.17392742256872692*_d_ifq3__5)
    _x148 = -_D + q_r
    end_q_r = _x148
    d_end_q_r__0 = 1.0 - _d_D__0
    end_q_rd = 0.0
    _x149 = q_r**2
    _x150 = (0.17392742256872692*_ifp0 + 0.32607257743127305*_ifp1 + 0.32607257743127305*_ifp2
        + 0.17392742256872692*_ifp3 + _x149*m*q_thd)
    _x156 = (1.0/_x148)
    _x151 = _x156**2
    _x152 = (1.0/m)
    _x153 = _x151*_x152
    end_q_thd = _x150*_x153
    _x154 = 0.17392742256872692*_x153
    _pd__159 = _x154
    _x155 = 0.32607257743127305*_x153
    _pd__160 = _x155
    _pd__161 = _x155
    _pd__162 = _x154
    _pd__163 = -2.0*_x150*_x152*_x156**3
    d_end_q_thd__0 = (_d_ifp0__0*_pd__159 + _d_ifp1__0*_pd__160 + _d_ifp2__0*_pd__161 + _d_ifp3__0*_pd__162
        + _pd__163*d_end_q_r__0 + 2.0*_x151*q_r*q_thd)
    d_end_q_thd__1 = (-_d_D__1*_pd__163 + _d_ifp0__1*_pd__159 + _d_ifp1__1*_pd__160 + _d_ifp2__1*_pd__161
        + _d_ifp3__1*_pd__162)
    d_end_q_thd__2 = (-_d_D__2*_pd__163 + _d_ifp0__2*_pd__159 + _d_ifp1__2*_pd__160 + _d_ifp2__2*_pd__161
        + _d_ifp3__2*_pd__162)
    d_end_q_thd__3 = (-_d_D__3*_pd__163 + _d_ifp0__3*_pd__159 + _d_ifp1__3*_pd__160 + _d_ifp2__3*_pd__161
        + _d_ifp3__3*_pd__162 + _x149*_x151)
    d_end_q_thd__4 = (-_d_D__4*_pd__163 + _d_ifp0__4*_pd__159 + _d_ifp1__4*_pd__160 + _d_ifp2__4*_pd__161
        + _d_ifp3__4*_pd__162)
    d_end_q_thd__5 = (-_d_D__5*_pd__163 + _d_ifp0__5*_pd__159 + _d_ifp1__5*_pd__160 + _d_ifp2__5*_pd__161
        + _d_ifp3__5*_pd__162)
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # tangents as every branch names them
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_r__5 = -_d_D__5
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
        d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes, d_end_q_r__1,
        d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4,
        d_t_half__5, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp6_4eaacb_4(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2, d_guess_q_r__3,
        d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2, d_guess_q_th__3,
        d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1, d_guess_q_thd__2,
        d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r, guess_q_th, guess_q_thd,
        iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol):
    """Branch nodes = 4 of schwind_compression_jvp6_4eaacb (outlined: derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 3585
    # Picard passes on the 6 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-guess_q_r + q_r, 0.966234757101576*guess_q_th + 0.03376524289842399*q_th,
        0.8306046932331322*guess_q_th + 0.16939530676686773*q_th, 0.6193095930415985*guess_q_th
        + 0.38069040695840156*q_th, 0.38069040695840156*guess_q_th + 0.6193095930415985*q_th,
        0.16939530676686773*guess_q_th + 0.8306046932331322*q_th, 0.03376524289842399*guess_q_th
        + 0.966234757101576*q_th, 0.966234757101576*guess_q_r**2*guess_q_thd*m
        + 0.03376524289842399*m*q_r**2*q_thd, 0.8306046932331322*guess_q_r**2*guess_q_thd*m
        + 0.16939530676686773*m*q_r**2*q_thd, 0.6193095930415985*guess_q_r**2*guess_q_thd*m
        + 0.38069040695840156*m*q_r**2*q_thd, 0.38069040695840156*guess_q_r**2*guess_q_thd*m
        + 0.6193095930415985*m*q_r**2*q_thd, 0.16939530676686773*guess_q_r**2*guess_q_thd*m
        + 0.8306046932331322*m*q_r**2*q_thd, 0.03376524289842399*guess_q_r**2*guess_q_thd*m
        + 0.966234757101576*m*q_r**2*q_thd, 1.0 - d_guess_q_r__0, -d_guess_q_r__1, -d_guess_q_r__2,
        -d_guess_q_r__3, -d_guess_q_r__4, -d_guess_q_r__5, 0.966234757101576*d_guess_q_th__0,
        0.966234757101576*d_guess_q_th__1, 0.966234757101576*d_guess_q_th__2 + 0.03376524289842399,
        0.966234757101576*d_guess_q_th__3, 0.966234757101576*d_guess_q_th__4,
        0.966234757101576*d_guess_q_th__5, 0.8306046932331322*d_guess_q_th__0,
        0.8306046932331322*d_guess_q_th__1, 0.8306046932331322*d_guess_q_th__2 + 0.16939530676686773,
        0.8306046932331322*d_guess_q_th__3, 0.8306046932331322*d_guess_q_th__4,
        0.8306046932331322*d_guess_q_th__5, 0.6193095930415985*d_guess_q_th__0,
        0.6193095930415985*d_guess_q_th__1, 0.6193095930415985*d_guess_q_th__2 + 0.38069040695840156,
        0.6193095930415985*d_guess_q_th__3, 0.6193095930415985*d_guess_q_th__4,
        0.6193095930415985*d_guess_q_th__5, 0.38069040695840156*d_guess_q_th__0,
        0.38069040695840156*d_guess_q_th__1, 0.38069040695840156*d_guess_q_th__2 + 0.6193095930415985,
        0.38069040695840156*d_guess_q_th__3, 0.38069040695840156*d_guess_q_th__4,
        0.38069040695840156*d_guess_q_th__5, 0.16939530676686773*d_guess_q_th__0,
        0.16939530676686773*d_guess_q_th__1, 0.16939530676686773*d_guess_q_th__2 + 0.8306046932331322,
        0.16939530676686773*d_guess_q_th__3, 0.16939530676686773*d_guess_q_th__4,
        0.16939530676686773*d_guess_q_th__5, 0.03376524289842399*d_guess_q_th__0,
        0.03376524289842399*d_guess_q_th__1, 0.03376524289842399*d_guess_q_th__2 + 0.966234757101576,
        0.03376524289842399*d_guess_q_th__3, 0.03376524289842399*d_guess_q_th__4,
        0.03376524289842399*d_guess_q_th__5, 1.932469514203152*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__0*guess_q_r**2*m + 0.06753048579684798*m*q_r*q_thd,
        1.932469514203152*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__1*guess_q_r**2*m,
        1.932469514203152*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__2*guess_q_r**2*m,
        1.932469514203152*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__3*guess_q_r**2*m + 0.03376524289842399*m*q_r**2,
        1.932469514203152*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__4*guess_q_r**2*m,
        1.932469514203152*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__5*guess_q_r**2*m,
        1.6612093864662645*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__0*guess_q_r**2*m + 0.33879061353373546*m*q_r*q_thd,
        1.6612093864662645*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__1*guess_q_r**2*m,
        1.6612093864662645*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__2*guess_q_r**2*m,
        1.6612093864662645*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__3*guess_q_r**2*m + 0.16939530676686773*m*q_r**2,
        1.6612093864662645*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__4*guess_q_r**2*m,
        1.6612093864662645*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__5*guess_q_r**2*m,
        1.238619186083197*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__0*guess_q_r**2*m + 0.7613808139168031*m*q_r*q_thd,
        1.238619186083197*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__1*guess_q_r**2*m,
        1.238619186083197*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__2*guess_q_r**2*m,
        1.238619186083197*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__3*guess_q_r**2*m + 0.38069040695840156*m*q_r**2,
        1.238619186083197*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__4*guess_q_r**2*m,
        1.238619186083197*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__5*guess_q_r**2*m,
        0.7613808139168031*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__0*guess_q_r**2*m + 1.238619186083197*m*q_r*q_thd,
        0.7613808139168031*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__1*guess_q_r**2*m,
        0.7613808139168031*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__2*guess_q_r**2*m,
        0.7613808139168031*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__3*guess_q_r**2*m + 0.6193095930415985*m*q_r**2,
        0.7613808139168031*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__4*guess_q_r**2*m,
        0.7613808139168031*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__5*guess_q_r**2*m,
        0.33879061353373546*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__0*guess_q_r**2*m + 1.6612093864662645*m*q_r*q_thd,
        0.33879061353373546*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__1*guess_q_r**2*m,
        0.33879061353373546*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__2*guess_q_r**2*m,
        0.33879061353373546*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__3*guess_q_r**2*m + 0.8306046932331322*m*q_r**2,
        0.33879061353373546*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__4*guess_q_r**2*m,
        0.33879061353373546*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__5*guess_q_r**2*m,
        0.06753048579684798*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__0*guess_q_r**2*m + 1.932469514203152*m*q_r*q_thd,
        0.06753048579684798*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__1*guess_q_r**2*m,
        0.06753048579684798*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__2*guess_q_r**2*m,
        0.06753048579684798*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__3*guess_q_r**2*m + 0.966234757101576*m*q_r**2,
        0.06753048579684798*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__4*guess_q_r**2*m,
        0.06753048579684798*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__5*guess_q_r**2*m, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _Q2, _Q3, _Q4, _Q5, _P0, _P1, _P2, _P3, _P4, _P5, _d_D__0, _d_D__1, _d_D__2, _d_D__3,
            _d_D__4, _d_D__5, _d_Q0__0, _d_Q0__1, _d_Q0__2, _d_Q0__3, _d_Q0__4, _d_Q0__5, _d_Q1__0, _d_Q1__1,
            _d_Q1__2, _d_Q1__3, _d_Q1__4, _d_Q1__5, _d_Q2__0, _d_Q2__1, _d_Q2__2, _d_Q2__3, _d_Q2__4,
            _d_Q2__5, _d_Q3__0, _d_Q3__1, _d_Q3__2, _d_Q3__3, _d_Q3__4, _d_Q3__5, _d_Q4__0, _d_Q4__1,
            _d_Q4__2, _d_Q4__3, _d_Q4__4, _d_Q4__5, _d_Q5__0, _d_Q5__1, _d_Q5__2, _d_Q5__3, _d_Q5__4,
            _d_Q5__5, _d_P0__0, _d_P0__1, _d_P0__2, _d_P0__3, _d_P0__4, _d_P0__5, _d_P1__0, _d_P1__1,
            _d_P1__2, _d_P1__3, _d_P1__4, _d_P1__5, _d_P2__0, _d_P2__1, _d_P2__2, _d_P2__3, _d_P2__4,
            _d_P2__5, _d_P3__0, _d_P3__1, _d_P3__2, _d_P3__3, _d_P3__4, _d_P3__5, _d_P4__0, _d_P4__1,
            _d_P4__2, _d_P4__3, _d_P4__4, _d_P4__5, _d_P5__0, _d_P5__1, _d_P5__2, _d_P5__3, _d_P5__4,
            _d_P5__5, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9988599083720104*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _d_isigma0__0 = 1.0 - 0.9988599083720104*_d_D__0
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x160 = (1.0/_x2)
        _x10 = _x160**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__164 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__165 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__166 = -_x15*_x160**4*_x8 - k_c
        _d_iF0__0 = _d_P0__0*_pd__164 + _d_Q0__0*_pd__165 + _d_isigma0__0*_pd__166
        _x16 = 0.9988599083720104*_pd__166
        _d_iF0__1 = -_d_D__1*_x16 + _d_P0__1*_pd__164 + _d_Q0__1*_pd__165
        _d_iF0__2 = -_d_D__2*_x16 + _d_P0__2*_pd__164 + _d_Q0__2*_pd__165
        _d_iF0__3 = -_d_D__3*_x16 + _d_P0__3*_pd__164 + _d_Q0__3*_pd__165
        _d_iF0__4 = -_d_D__4*_x16 + _d_P0__4*_pd__164 + _d_Q0__4*_pd__165 + _x1 + l0
        _d_iF0__5 = -_d_D__5*_x16 + _d_P0__5*_pd__164 + _d_Q0__5*_pd__165
        _x17 = 0.9713052300453587*_D + _x0
        _x18 = -_x17
        _isigma1 = _x18
        _d_isigma1__0 = 1.0 - 0.9713052300453587*_d_D__0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x5
        _x21 = _x18*k_c
        _x22 = _P1**2
        _x159 = (1.0/_x18)
        _x23 = _x159**3
        _x24 = _x23*_x9
        _x25 = _x22*_x24
        _iF1 = -_x20 - _x21 + _x25 + _x3
        _x26 = 2.0*_P1
        _pd__167 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__168 = _x27*_x5
        _pd__169 = -_x15*_x159**4*_x22 - k_c
        _d_iF1__0 = _d_P1__0*_pd__167 + _d_Q1__0*_pd__168 + _d_isigma1__0*_pd__169
        _x28 = 0.9713052300453587*_pd__169
        _d_iF1__1 = -_d_D__1*_x28 + _d_P1__1*_pd__167 + _d_Q1__1*_pd__168
        _d_iF1__2 = -_d_D__2*_x28 + _d_P1__2*_pd__167 + _d_Q1__2*_pd__168
        _d_iF1__3 = -_d_D__3*_x28 + _d_P1__3*_pd__167 + _d_Q1__3*_pd__168
        _d_iF1__4 = -_d_D__4*_x28 + _d_P1__4*_pd__167 + _d_Q1__4*_pd__168 + _x17 + l0
        _d_iF1__5 = -_d_D__5*_x28 + _d_P1__5*_pd__167 + _d_Q1__5*_pd__168
        _x29 = 0.8550748140498466*_D + _x0
        _x30 = -_x29
        _isigma2 = _x30
        _d_isigma2__0 = 1.0 - 0.8550748140498466*_d_D__0
        _x31 = math.cos(_Q2)
        _x32 = _x31*_x5
        _x33 = _x30*k_c
        _x34 = _P2**2
        _x161 = (1.0/_x30)
        _x35 = _x161**3
        _x36 = _x35*_x9
        _x37 = _x34*_x36
        _iF2 = _x3 - _x32 - _x33 + _x37
        _x38 = 2.0*_P2
        _pd__170 = _x36*_x38
        _x39 = math.sin(_Q2)
        _pd__171 = _x39*_x5
        _pd__172 = -_x15*_x161**4*_x34 - k_c
        _d_iF2__0 = _d_P2__0*_pd__170 + _d_Q2__0*_pd__171 + _d_isigma2__0*_pd__172
        _x40 = 0.8550748140498466*_pd__172
        _d_iF2__1 = -_d_D__1*_x40 + _d_P2__1*_pd__170 + _d_Q2__1*_pd__171
        _d_iF2__2 = -_d_D__2*_x40 + _d_P2__2*_pd__170 + _d_Q2__2*_pd__171
        _d_iF2__3 = -_d_D__3*_x40 + _d_P2__3*_pd__170 + _d_Q2__3*_pd__171
        _d_iF2__4 = -_d_D__4*_x40 + _d_P2__4*_pd__170 + _d_Q2__4*_pd__171 + _x29 + l0
        _d_iF2__5 = -_d_D__5*_x40 + _d_P2__5*_pd__170 + _d_Q2__5*_pd__171
        _x41 = 0.6164556279666497*_D + _x0
        _x42 = -_x41
        _isigma3 = _x42
        _d_isigma3__0 = 1.0 - 0.6164556279666497*_d_D__0
        _x43 = math.cos(_Q3)
        _x44 = _x43*_x5
        _x45 = _x42*k_c
        _x46 = _P3**2
        _x162 = (1.0/_x42)
        _x47 = _x162**3
        _x48 = _x47*_x9
        _x49 = _x46*_x48
        _iF3 = _x3 - _x44 - _x45 + _x49
        _x50 = 2.0*_P3
        _pd__173 = _x48*_x50
        _x51 = math.sin(_Q3)
        _pd__174 = _x5*_x51
        _pd__175 = -_x15*_x162**4*_x46 - k_c
        _d_iF3__0 = _d_P3__0*_pd__173 + _d_Q3__0*_pd__174 + _d_isigma3__0*_pd__175
        _x52 = 0.6164556279666497*_pd__175
        _d_iF3__1 = -_d_D__1*_x52 + _d_P3__1*_pd__173 + _d_Q3__1*_pd__174
        _d_iF3__2 = -_d_D__2*_x52 + _d_P3__2*_pd__173 + _d_Q3__2*_pd__174
        _d_iF3__3 = -_d_D__3*_x52 + _d_P3__3*_pd__173 + _d_Q3__3*_pd__174
        _d_iF3__4 = -_d_D__4*_x52 + _d_P3__4*_pd__173 + _d_Q3__4*_pd__174 + _x41 + l0
        _d_iF3__5 = -_d_D__5*_x52 + _d_P3__5*_pd__173 + _d_Q3__5*_pd__174
        _x53 = 0.31009584357909425*_D + _x0
        _x54 = -_x53
        _isigma4 = _x54
        _d_isigma4__0 = 1.0 - 0.31009584357909425*_d_D__0
        _x55 = math.cos(_Q4)
        _x56 = _x5*_x55
        _x57 = _x54*k_c
        _x58 = _P4**2
        _x163 = (1.0/_x54)
        _x59 = _x163**3
        _x60 = _x59*_x9
        _x61 = _x58*_x60
        _iF4 = _x3 - _x56 - _x57 + _x61
        _x62 = 2.0*_P4
        _pd__176 = _x60*_x62
        _x63 = math.sin(_Q4)
        _pd__177 = _x5*_x63
        _pd__178 = -_x15*_x163**4*_x58 - k_c
        _d_iF4__0 = _d_P4__0*_pd__176 + _d_Q4__0*_pd__177 + _d_isigma4__0*_pd__178
        _x64 = 0.31009584357909425*_pd__178
        _d_iF4__1 = -_d_D__1*_x64 + _d_P4__1*_pd__176 + _d_Q4__1*_pd__177
        _d_iF4__2 = -_d_D__2*_x64 + _d_P4__2*_pd__176 + _d_Q4__2*_pd__177
        _d_iF4__3 = -_d_D__3*_x64 + _d_P4__3*_pd__176 + _d_Q4__3*_pd__177
        _d_iF4__4 = -_d_D__4*_x64 + _d_P4__4*_pd__176 + _d_Q4__4*_pd__177 + _x53 + l0
        _d_iF4__5 = -_d_D__5*_x64 + _d_P4__5*_pd__176 + _d_Q4__5*_pd__177
        _x65 = 0.0663903941688584*_D + _x0
        _x66 = -_x65
        _isigma5 = _x66
        _d_isigma5__0 = 1.0 - 0.0663903941688584*_d_D__0
        _x67 = math.cos(_Q5)
        _x68 = _x5*_x67
        _x69 = _x66*k_c
        _x70 = _P5**2
        _x164 = (1.0/_x66)
        _x71 = _x164**3
        _x72 = _x71*_x9
        _x73 = _x70*_x72
        _iF5 = _x3 - _x68 - _x69 + _x73
        _x74 = 2.0*_P5
        _pd__179 = _x72*_x74
        _x75 = math.sin(_Q5)
        _pd__180 = _x5*_x75
        _pd__181 = -_x15*_x164**4*_x70 - k_c
        _d_iF5__0 = _d_P5__0*_pd__179 + _d_Q5__0*_pd__180 + _d_isigma5__0*_pd__181
        _x76 = 0.0663903941688584*_pd__181
        _d_iF5__1 = -_d_D__1*_x76 + _d_P5__1*_pd__179 + _d_Q5__1*_pd__180
        _d_iF5__2 = -_d_D__2*_x76 + _d_P5__2*_pd__179 + _d_Q5__2*_pd__180
        _d_iF5__3 = -_d_D__3*_x76 + _d_P5__3*_pd__179 + _d_Q5__3*_pd__180
        _d_iF5__4 = -_d_D__4*_x76 + _d_P5__4*_pd__179 + _d_Q5__4*_pd__180 + _x65 + l0
        _d_iF5__5 = -_d_D__5*_x76 + _d_P5__5*_pd__179 + _d_Q5__5*_pd__180
        _x77 = (0.5871580340658094*_x12 + 0.140380692261653*_x20 + 0.140380692261653*_x21
            - 0.140380692261653*_x25 + 0.5*_x3 - 0.08683151831711133*_x32 - 0.08683151831711133*_x33
            + 0.08683151831711133*_x37 + 0.052466581536012566*_x44 + 0.052466581536012566*_x45
            - 0.052466581536012566*_x49 - 0.026354606039126004*_x56 - 0.026354606039126004*_x57
            - 0.5871580340658094*_x6 + 0.026354606039126004*_x61 + 0.007496884624381081*_x68
            + 0.007496884624381081*_x69 - 0.5871580340658094*_x7 - 0.007496884624381081*_x73)
        _iPsi0 = _x77
        _d_iPsi0__0 = (0.5871580340658094*_d_iF0__0 - 0.140380692261653*_d_iF1__0
            + 0.08683151831711133*_d_iF2__0 - 0.052466581536012566*_d_iF3__0 + 0.026354606039126004*_d_iF4__0
            - 0.007496884624381081*_d_iF5__0)
        _d_iPsi0__1 = (0.5871580340658094*_d_iF0__1 - 0.140380692261653*_d_iF1__1
            + 0.08683151831711133*_d_iF2__1 - 0.052466581536012566*_d_iF3__1 + 0.026354606039126004*_d_iF4__1
            - 0.007496884624381081*_d_iF5__1)
        _d_iPsi0__2 = (0.5871580340658094*_d_iF0__2 - 0.140380692261653*_d_iF1__2
            + 0.08683151831711133*_d_iF2__2 - 0.052466581536012566*_d_iF3__2 + 0.026354606039126004*_d_iF4__2
            - 0.007496884624381081*_d_iF5__2)
        _d_iPsi0__3 = (0.5871580340658094*_d_iF0__3 - 0.140380692261653*_d_iF1__3
            + 0.08683151831711133*_d_iF2__3 - 0.052466581536012566*_d_iF3__3 + 0.026354606039126004*_d_iF4__3
            - 0.007496884624381081*_d_iF5__3)
        _d_iPsi0__4 = (0.5871580340658094*_d_iF0__4 - 0.140380692261653*_d_iF1__4
            + 0.08683151831711133*_d_iF2__4 - 0.052466581536012566*_d_iF3__4 + 0.026354606039126004*_d_iF4__4
            - 0.007496884624381081*_d_iF5__4)
        _d_iPsi0__5 = (0.5871580340658094*_d_iF0__5 - 0.140380692261653*_d_iF1__5
            + 0.08683151831711133*_d_iF2__5 - 0.052466581536012566*_d_iF3__5 + 0.026354606039126004*_d_iF4__5
            - 0.007496884624381081*_d_iF5__5)
        _x78 = (1.0/math.sqrt(_x77))
        _x79 = math.sqrt(_D)
        _x80 = math.sqrt(m)
        _x81 = _x79*_x80
        _ift0 = _x78*_x81
        _x82 = (0.5)/_x79
        _x83 = _x80*_x82
        _pd__182 = _x78*_x83
        _x84 = _x77**(-1.5)
        _x85 = (0.5)*_x81
        _pd__183 = -_x84*_x85
        _d_ift0__0 = _d_D__0*_pd__182 + _d_iPsi0__0*_pd__183
        _d_ift0__1 = _d_D__1*_pd__182 + _d_iPsi0__1*_pd__183
        _d_ift0__2 = _d_D__2*_pd__182 + _d_iPsi0__2*_pd__183
        _d_ift0__3 = _d_D__3*_pd__182 + _d_iPsi0__3*_pd__183
        _d_ift0__4 = _d_D__4*_pd__182 + _d_iPsi0__4*_pd__183
        _d_ift0__5 = _d_D__5*_pd__182 + _d_iPsi0__5*_pd__183
        _x86 = (1.0/_x80)
        _x87 = _x79*_x86
        _x88 = _x160**2
        _x89 = _x78*_x88
        _x90 = _x87*_x89
        _ifq0 = _P0*_x90
        _x91 = _x82*_x86
        _pd__184 = _P0*_x89*_x91
        _pd__185 = _x90
        _x92 = (0.5)*_x87
        _pd__186 = -_P0*_x84*_x88*_x92
        _pd__187 = -_x10*_x13*_x78*_x87
        _d_ifq0__0 = _d_D__0*_pd__184 + _d_P0__0*_pd__185 + _d_iPsi0__0*_pd__186 + _d_isigma0__0*_pd__187
        _x93 = 0.9988599083720104*_pd__187
        _d_ifq0__1 = _d_D__1*_pd__184 - _d_D__1*_x93 + _d_P0__1*_pd__185 + _d_iPsi0__1*_pd__186
        _d_ifq0__2 = _d_D__2*_pd__184 - _d_D__2*_x93 + _d_P0__2*_pd__185 + _d_iPsi0__2*_pd__186
        _d_ifq0__3 = _d_D__3*_pd__184 - _d_D__3*_x93 + _d_P0__3*_pd__185 + _d_iPsi0__3*_pd__186
        _d_ifq0__4 = _d_D__4*_pd__184 - _d_D__4*_x93 + _d_P0__4*_pd__185 + _d_iPsi0__4*_pd__186
        _d_ifq0__5 = _d_D__5*_pd__184 - _d_D__5*_x93 + _d_P0__5*_pd__185 + _d_iPsi0__5*_pd__186
        _x94 = g_s*m**(1.5)
        _x95 = _x79*_x94
        _x96 = _x78*_x95
        _x97 = _x14*_x96
        _ifp0 = _x2*_x97
        _x98 = _x14*_x2
        _x99 = _x82*_x94
        _pd__188 = _x78*_x98*_x99
        _pd__189 = _x2*_x4*_x96
        _x100 = (0.5)*_x95
        _pd__190 = -_x100*_x84*_x98
        _pd__191 = _x97
        _d_ifp0__0 = _d_D__0*_pd__188 + _d_Q0__0*_pd__189 + _d_iPsi0__0*_pd__190 + _d_isigma0__0*_pd__191
        _x101 = 0.9988599083720104*_pd__191
        _d_ifp0__1 = _d_D__1*_pd__188 - _d_D__1*_x101 + _d_Q0__1*_pd__189 + _d_iPsi0__1*_pd__190
        _d_ifp0__2 = _d_D__2*_pd__188 - _d_D__2*_x101 + _d_Q0__2*_pd__189 + _d_iPsi0__2*_pd__190
        _d_ifp0__3 = _d_D__3*_pd__188 - _d_D__3*_x101 + _d_Q0__3*_pd__189 + _d_iPsi0__3*_pd__190
        _d_ifp0__4 = _d_D__4*_pd__188 - _d_D__4*_x101 + _d_Q0__4*_pd__189 + _d_iPsi0__4*_pd__190
        _d_ifp0__5 = _d_D__5*_pd__188 - _d_D__5*_x101 + _d_Q0__5*_pd__189 + _d_iPsi0__5*_pd__190
        _x102 = -0.5*k_c*l0
        _x103 = (0.147790320897128*_x10*_x8*_x9 - _x102 - 0.41567911405660357*_x20 - 0.41567911405660357*_x21
            + 0.41567911405660357*_x22*_x23*_x9 + 0.09720828549085844*_x30*k_c
            + 0.09720828549085844*_x31*g_s*m - 0.09720828549085844*_x37 - 0.05155355009455148*_x44
            - 0.05155355009455148*_x45 + 0.05155355009455148*_x46*_x47*_x9 + 0.024719229415033087*_x54*k_c
            + 0.024719229415033087*_x55*g_s*m - 0.147790320897128*_x6 - 0.024719229415033087*_x61
            - 0.006904529857608445*_x68 - 0.006904529857608445*_x69 - 0.147790320897128*_x7
            + 0.006904529857608445*_x70*_x71*_x9)
        _iPsi1 = _x103
        _d_iPsi1__0 = (0.147790320897128*_d_iF0__0 + 0.41567911405660357*_d_iF1__0
            - 0.09720828549085844*_d_iF2__0 + 0.05155355009455148*_d_iF3__0 - 0.024719229415033087*_d_iF4__0
            + 0.006904529857608445*_d_iF5__0)
        _d_iPsi1__1 = (0.147790320897128*_d_iF0__1 + 0.41567911405660357*_d_iF1__1
            - 0.09720828549085844*_d_iF2__1 + 0.05155355009455148*_d_iF3__1 - 0.024719229415033087*_d_iF4__1
            + 0.006904529857608445*_d_iF5__1)
        _d_iPsi1__2 = (0.147790320897128*_d_iF0__2 + 0.41567911405660357*_d_iF1__2
            - 0.09720828549085844*_d_iF2__2 + 0.05155355009455148*_d_iF3__2 - 0.024719229415033087*_d_iF4__2
            + 0.006904529857608445*_d_iF5__2)
        _d_iPsi1__3 = (0.147790320897128*_d_iF0__3 + 0.41567911405660357*_d_iF1__3
            - 0.09720828549085844*_d_iF2__3 + 0.05155355009455148*_d_iF3__3 - 0.024719229415033087*_d_iF4__3
            + 0.006904529857608445*_d_iF5__3)
        _d_iPsi1__4 = (0.147790320897128*_d_iF0__4 + 0.41567911405660357*_d_iF1__4
            - 0.09720828549085844*_d_iF2__4 + 0.05155355009455148*_d_iF3__4 - 0.024719229415033087*_d_iF4__4
            + 0.006904529857608445*_d_iF5__4)
        _d_iPsi1__5 = (0.147790320897128*_d_iF0__5 + 0.41567911405660357*_d_iF1__5
            - 0.09720828549085844*_d_iF2__5 + 0.05155355009455148*_d_iF3__5 - 0.024719229415033087*_d_iF4__5
            + 0.006904529857608445*_d_iF5__5)
        _x104 = (1.0/math.sqrt(_x103))
        _ift1 = _x104*_x81
        _pd__192 = _x104*_x83
        _x105 = _x103**(-1.5)
        _pd__193 = -_x105*_x85
        _d_ift1__0 = _d_D__0*_pd__192 + _d_iPsi1__0*_pd__193
        _d_ift1__1 = _d_D__1*_pd__192 + _d_iPsi1__1*_pd__193
        _d_ift1__2 = _d_D__2*_pd__192 + _d_iPsi1__2*_pd__193
        _d_ift1__3 = _d_D__3*_pd__192 + _d_iPsi1__3*_pd__193
        _d_ift1__4 = _d_D__4*_pd__192 + _d_iPsi1__4*_pd__193
        _d_ift1__5 = _d_D__5*_pd__192 + _d_iPsi1__5*_pd__193
        _x106 = _x159**2
        _x107 = _x104*_x106
        _x108 = _x107*_x87
        _ifq1 = _P1*_x108
        _pd__194 = _P1*_x107*_x91
        _pd__195 = _x108
        _pd__196 = -_P1*_x105*_x106*_x92
        _pd__197 = -_x104*_x23*_x26*_x87
        _d_ifq1__0 = _d_D__0*_pd__194 + _d_P1__0*_pd__195 + _d_iPsi1__0*_pd__196 + _d_isigma1__0*_pd__197
        _x109 = 0.9713052300453587*_pd__197
        _d_ifq1__1 = _d_D__1*_pd__194 - _d_D__1*_x109 + _d_P1__1*_pd__195 + _d_iPsi1__1*_pd__196
        _d_ifq1__2 = _d_D__2*_pd__194 - _d_D__2*_x109 + _d_P1__2*_pd__195 + _d_iPsi1__2*_pd__196
        _d_ifq1__3 = _d_D__3*_pd__194 - _d_D__3*_x109 + _d_P1__3*_pd__195 + _d_iPsi1__3*_pd__196
        _d_ifq1__4 = _d_D__4*_pd__194 - _d_D__4*_x109 + _d_P1__4*_pd__195 + _d_iPsi1__4*_pd__196
        _d_ifq1__5 = _d_D__5*_pd__194 - _d_D__5*_x109 + _d_P1__5*_pd__195 + _d_iPsi1__5*_pd__196
        _x110 = _x104*_x95
        _x111 = _x110*_x27
        _ifp1 = _x111*_x18
        _x112 = _x18*_x27
        _pd__198 = _x104*_x112*_x99
        _pd__199 = _x110*_x18*_x19
        _pd__200 = -_x100*_x105*_x112
        _pd__201 = _x111
        _d_ifp1__0 = _d_D__0*_pd__198 + _d_Q1__0*_pd__199 + _d_iPsi1__0*_pd__200 + _d_isigma1__0*_pd__201
        _x113 = 0.9713052300453587*_pd__201
        _d_ifp1__1 = _d_D__1*_pd__198 - _d_D__1*_x113 + _d_Q1__1*_pd__199 + _d_iPsi1__1*_pd__200
        _d_ifp1__2 = _d_D__2*_pd__198 - _d_D__2*_x113 + _d_Q1__2*_pd__199 + _d_iPsi1__2*_pd__200
        _d_ifp1__3 = _d_D__3*_pd__198 - _d_D__3*_x113 + _d_Q1__3*_pd__199 + _d_iPsi1__3*_pd__200
        _d_ifp1__4 = _d_D__4*_pd__198 - _d_D__4*_x113 + _d_Q1__4*_pd__199 + _d_iPsi1__4*_pd__200
        _d_ifp1__5 = _d_D__5*_pd__198 - _d_D__5*_x113 + _d_Q1__5*_pd__199 + _d_iPsi1__5*_pd__200
        _x114 = (0.010443786721981197*_x10*_x8*_x9 - _x102 - 0.25540525119175433*_x20
            - 0.25540525119175433*_x21 + 0.25540525119175433*_x22*_x23*_x9 - 0.2685463444140672*_x32
            - 0.2685463444140672*_x33 + 0.2685463444140672*_x34*_x35*_x9 + 0.048794612428541204*_x42*k_c
            + 0.048794612428541204*_x43*g_s*m - 0.048794612428541204*_x49 - 0.01951903325298492*_x56
            - 0.01951903325298492*_x57 + 0.01951903325298492*_x58*_x59*_x9 - 0.010443786721981197*_x6
            + 0.005119803152246505*_x66*k_c + 0.005119803152246505*_x67*g_s*m - 0.010443786721981197*_x7
            - 0.005119803152246505*_x73)
        _iPsi2 = _x114
        _d_iPsi2__0 = (0.010443786721981197*_d_iF0__0 + 0.25540525119175433*_d_iF1__0
            + 0.2685463444140672*_d_iF2__0 - 0.048794612428541204*_d_iF3__0 + 0.01951903325298492*_d_iF4__0
            - 0.005119803152246505*_d_iF5__0)
        _d_iPsi2__1 = (0.010443786721981197*_d_iF0__1 + 0.25540525119175433*_d_iF1__1
            + 0.2685463444140672*_d_iF2__1 - 0.048794612428541204*_d_iF3__1 + 0.01951903325298492*_d_iF4__1
            - 0.005119803152246505*_d_iF5__1)
        _d_iPsi2__2 = (0.010443786721981197*_d_iF0__2 + 0.25540525119175433*_d_iF1__2
            + 0.2685463444140672*_d_iF2__2 - 0.048794612428541204*_d_iF3__2 + 0.01951903325298492*_d_iF4__2
            - 0.005119803152246505*_d_iF5__2)
        _d_iPsi2__3 = (0.010443786721981197*_d_iF0__3 + 0.25540525119175433*_d_iF1__3
            + 0.2685463444140672*_d_iF2__3 - 0.048794612428541204*_d_iF3__3 + 0.01951903325298492*_d_iF4__3
            - 0.005119803152246505*_d_iF5__3)
        _d_iPsi2__4 = (0.010443786721981197*_d_iF0__4 + 0.25540525119175433*_d_iF1__4
            + 0.2685463444140672*_d_iF2__4 - 0.048794612428541204*_d_iF3__4 + 0.01951903325298492*_d_iF4__4
            - 0.005119803152246505*_d_iF5__4)
        _d_iPsi2__5 = (0.010443786721981197*_d_iF0__5 + 0.25540525119175433*_d_iF1__5
            + 0.2685463444140672*_d_iF2__5 - 0.048794612428541204*_d_iF3__5 + 0.01951903325298492*_d_iF4__5
            - 0.005119803152246505*_d_iF5__5)
        _x115 = (1.0/math.sqrt(_x114))
        _ift2 = _x115*_x81
        _pd__202 = _x115*_x83
        _x116 = _x114**(-1.5)
        _pd__203 = -_x116*_x85
        _d_ift2__0 = _d_D__0*_pd__202 + _d_iPsi2__0*_pd__203
        _d_ift2__1 = _d_D__1*_pd__202 + _d_iPsi2__1*_pd__203
        _d_ift2__2 = _d_D__2*_pd__202 + _d_iPsi2__2*_pd__203
        _d_ift2__3 = _d_D__3*_pd__202 + _d_iPsi2__3*_pd__203
        _d_ift2__4 = _d_D__4*_pd__202 + _d_iPsi2__4*_pd__203
        _d_ift2__5 = _d_D__5*_pd__202 + _d_iPsi2__5*_pd__203
        _x117 = _x161**2
        _x118 = _x115*_x117
        _x119 = _x118*_x87
        _ifq2 = _P2*_x119
        _pd__204 = _P2*_x118*_x91
        _pd__205 = _x119
        _pd__206 = -_P2*_x116*_x117*_x92
        _pd__207 = -_x115*_x35*_x38*_x87
        _d_ifq2__0 = _d_D__0*_pd__204 + _d_P2__0*_pd__205 + _d_iPsi2__0*_pd__206 + _d_isigma2__0*_pd__207
        _x120 = 0.8550748140498466*_pd__207
        _d_ifq2__1 = _d_D__1*_pd__204 - _d_D__1*_x120 + _d_P2__1*_pd__205 + _d_iPsi2__1*_pd__206
        _d_ifq2__2 = _d_D__2*_pd__204 - _d_D__2*_x120 + _d_P2__2*_pd__205 + _d_iPsi2__2*_pd__206
        _d_ifq2__3 = _d_D__3*_pd__204 - _d_D__3*_x120 + _d_P2__3*_pd__205 + _d_iPsi2__3*_pd__206
        _d_ifq2__4 = _d_D__4*_pd__204 - _d_D__4*_x120 + _d_P2__4*_pd__205 + _d_iPsi2__4*_pd__206
        _d_ifq2__5 = _d_D__5*_pd__204 - _d_D__5*_x120 + _d_P2__5*_pd__205 + _d_iPsi2__5*_pd__206
        _x121 = _x115*_x95
        _x122 = _x121*_x39
        _ifp2 = _x122*_x30
        _x123 = _x30*_x39
        _pd__208 = _x115*_x123*_x99
        _pd__209 = _x121*_x30*_x31
        _pd__210 = -_x100*_x116*_x123
        _pd__211 = _x122
        _d_ifp2__0 = _d_D__0*_pd__208 + _d_Q2__0*_pd__209 + _d_iPsi2__0*_pd__210 + _d_isigma2__0*_pd__211
        _x124 = 0.8550748140498466*_pd__211
        _d_ifp2__1 = _d_D__1*_pd__208 - _d_D__1*_x124 + _d_Q2__1*_pd__209 + _d_iPsi2__1*_pd__210
        _d_ifp2__2 = _d_D__2*_pd__208 - _d_D__2*_x124 + _d_Q2__2*_pd__209 + _d_iPsi2__2*_pd__210
        _d_ifp2__3 = _d_D__3*_pd__208 - _d_D__3*_x124 + _d_Q2__3*_pd__209 + _d_iPsi2__3*_pd__210
        _d_ifp2__4 = _d_D__4*_pd__208 - _d_D__4*_x124 + _d_Q2__4*_pd__209 + _d_iPsi2__4*_pd__210
        _d_ifp2__5 = _d_D__5*_pd__208 - _d_D__5*_x124 + _d_Q2__5*_pd__209 + _d_iPsi2__5*_pd__210
        _x125 = -0.5*k_c*l0
        _x126 = (0.01101839635505667*_x10*_x8*_x9 - _x125 - 0.0662099828438604*_x20 - 0.0662099828438604*_x21
            + 0.0662099828438604*_x22*_x23*_x9 - 0.2671819482314443*_x32 - 0.2671819482314443*_x33
            + 0.2671819482314443*_x34*_x35*_x9 - 0.1742495636223592*_x44 - 0.1742495636223592*_x45
            + 0.1742495636223592*_x46*_x47*_x9 + 0.02396692958086051*_x54*k_c + 0.02396692958086051*_x55*g_s*m
            - 0.01101839635505667*_x6 - 0.02396692958086051*_x61 - 0.00530703852813994*_x68
            - 0.00530703852813994*_x69 - 0.01101839635505667*_x7 + 0.00530703852813994*_x70*_x71*_x9)
        _iPsi3 = _x126
        _d_iPsi3__0 = (0.01101839635505667*_d_iF0__0 + 0.0662099828438604*_d_iF1__0
            + 0.2671819482314443*_d_iF2__0 + 0.1742495636223592*_d_iF3__0 - 0.02396692958086051*_d_iF4__0
            + 0.00530703852813994*_d_iF5__0)
        _d_iPsi3__1 = (0.01101839635505667*_d_iF0__1 + 0.0662099828438604*_d_iF1__1
            + 0.2671819482314443*_d_iF2__1 + 0.1742495636223592*_d_iF3__1 - 0.02396692958086051*_d_iF4__1
            + 0.00530703852813994*_d_iF5__1)
        _d_iPsi3__2 = (0.01101839635505667*_d_iF0__2 + 0.0662099828438604*_d_iF1__2
            + 0.2671819482314443*_d_iF2__2 + 0.1742495636223592*_d_iF3__2 - 0.02396692958086051*_d_iF4__2
            + 0.00530703852813994*_d_iF5__2)
        _d_iPsi3__3 = (0.01101839635505667*_d_iF0__3 + 0.0662099828438604*_d_iF1__3
            + 0.2671819482314443*_d_iF2__3 + 0.1742495636223592*_d_iF3__3 - 0.02396692958086051*_d_iF4__3
            + 0.00530703852813994*_d_iF5__3)
        _d_iPsi3__4 = (0.01101839635505667*_d_iF0__4 + 0.0662099828438604*_d_iF1__4
            + 0.2671819482314443*_d_iF2__4 + 0.1742495636223592*_d_iF3__4 - 0.02396692958086051*_d_iF4__4
            + 0.00530703852813994*_d_iF5__4)
        _d_iPsi3__5 = (0.01101839635505667*_d_iF0__5 + 0.0662099828438604*_d_iF1__5
            + 0.2671819482314443*_d_iF2__5 + 0.1742495636223592*_d_iF3__5 - 0.02396692958086051*_d_iF4__5
            + 0.00530703852813994*_d_iF5__5)
        _x127 = (1.0/math.sqrt(_x126))
        _ift3 = _x127*_x81
        _pd__212 = _x127*_x83
        _x128 = _x126**(-1.5)
        _pd__213 = -_x128*_x85
        _d_ift3__0 = _d_D__0*_pd__212 + _d_iPsi3__0*_pd__213
        _d_ift3__1 = _d_D__1*_pd__212 + _d_iPsi3__1*_pd__213
        _d_ift3__2 = _d_D__2*_pd__212 + _d_iPsi3__2*_pd__213
        _d_ift3__3 = _d_D__3*_pd__212 + _d_iPsi3__3*_pd__213
        _d_ift3__4 = _d_D__4*_pd__212 + _d_iPsi3__4*_pd__213
        _d_ift3__5 = _d_D__5*_pd__212 + _d_iPsi3__5*_pd__213
        _x129 = _x162**2
        _x130 = _x127*_x129
        _x131 = _x130*_x87
        _ifq3 = _P3*_x131
        _pd__214 = _P3*_x130*_x91
        _pd__215 = _x131
        _pd__216 = -_P3*_x128*_x129*_x92
        _pd__217 = -_x127*_x47*_x50*_x87
        _d_ifq3__0 = _d_D__0*_pd__214 + _d_P3__0*_pd__215 + _d_iPsi3__0*_pd__216 + _d_isigma3__0*_pd__217
        _x132 = 0.6164556279666497*_pd__217
        _d_ifq3__1 = _d_D__1*_pd__214 - _d_D__1*_x132 + _d_P3__1*_pd__215 + _d_iPsi3__1*_pd__216
        _d_ifq3__2 = _d_D__2*_pd__214 - _d_D__2*_x132 + _d_P3__2*_pd__215 + _d_iPsi3__2*_pd__216
        _d_ifq3__3 = _d_D__3*_pd__214 - _d_D__3*_x132 + _d_P3__3*_pd__215 + _d_iPsi3__3*_pd__216
        _d_ifq3__4 = _d_D__4*_pd__214 - _d_D__4*_x132 + _d_P3__4*_pd__215 + _d_iPsi3__4*_pd__216
        _d_ifq3__5 = _d_D__5*_pd__214 - _d_D__5*_x132 + _d_P3__5*_pd__215 + _d_iPsi3__5*_pd__216
        _x133 = _x127*_x95
        _x134 = _x133*_x51
        _ifp3 = _x134*_x42
        _x135 = _x42*_x51
        _pd__218 = _x127*_x135*_x99
        _pd__219 = _x133*_x42*_x43
        _pd__220 = -_x100*_x128*_x135
        _pd__221 = _x134
        _d_ifp3__0 = _d_D__0*_pd__218 + _d_Q3__0*_pd__219 + _d_iPsi3__0*_pd__220 + _d_isigma3__0*_pd__221
        _x136 = 0.6164556279666497*_pd__221
        _d_ifp3__1 = _d_D__1*_pd__218 - _d_D__1*_x136 + _d_Q3__1*_pd__219 + _d_iPsi3__1*_pd__220
        _d_ifp3__2 = _d_D__2*_pd__218 - _d_D__2*_x136 + _d_Q3__2*_pd__219 + _d_iPsi3__2*_pd__220
        _d_ifp3__3 = _d_D__3*_pd__218 - _d_D__3*_x136 + _d_Q3__3*_pd__219 + _d_iPsi3__3*_pd__220
        _d_ifp3__4 = _d_D__4*_pd__218 - _d_D__4*_x136 + _d_Q3__4*_pd__219 + _d_iPsi3__4*_pd__220
        _d_ifp3__5 = _d_D__5*_pd__218 - _d_D__5*_x136 + _d_Q3__5*_pd__219 + _d_iPsi3__5*_pd__220
        _x137 = (0.0025147977064533143*_x10*_x8*_x9 - _x102 - 0.050345455482979015*_x20
            - 0.050345455482979015*_x21 + 0.050345455482979015*_x22*_x23*_x9 - 0.11622097556712797*_x32
            - 0.11622097556712797*_x33 + 0.11622097556712797*_x34*_x35*_x9 - 0.2353986790647292*_x44
            - 0.2353986790647292*_x45 + 0.2353986790647292*_x46*_x47*_x9 - 0.10372825048336794*_x56
            - 0.10372825048336794*_x57 + 0.10372825048336794*_x58*_x59*_x9 - 0.0025147977064533143*_x6
            + 0.008208158304657426*_x66*k_c + 0.008208158304657426*_x67*g_s*m - 0.0025147977064533143*_x7
            - 0.008208158304657426*_x73)
        _iPsi4 = _x137
        _d_iPsi4__0 = (0.0025147977064533143*_d_iF0__0 + 0.050345455482979015*_d_iF1__0
            + 0.11622097556712797*_d_iF2__0 + 0.2353986790647292*_d_iF3__0 + 0.10372825048336794*_d_iF4__0
            - 0.008208158304657426*_d_iF5__0)
        _d_iPsi4__1 = (0.0025147977064533143*_d_iF0__1 + 0.050345455482979015*_d_iF1__1
            + 0.11622097556712797*_d_iF2__1 + 0.2353986790647292*_d_iF3__1 + 0.10372825048336794*_d_iF4__1
            - 0.008208158304657426*_d_iF5__1)
        _d_iPsi4__2 = (0.0025147977064533143*_d_iF0__2 + 0.050345455482979015*_d_iF1__2
            + 0.11622097556712797*_d_iF2__2 + 0.2353986790647292*_d_iF3__2 + 0.10372825048336794*_d_iF4__2
            - 0.008208158304657426*_d_iF5__2)
        _d_iPsi4__3 = (0.0025147977064533143*_d_iF0__3 + 0.050345455482979015*_d_iF1__3
            + 0.11622097556712797*_d_iF2__3 + 0.2353986790647292*_d_iF3__3 + 0.10372825048336794*_d_iF4__3
            - 0.008208158304657426*_d_iF5__3)
        _d_iPsi4__4 = (0.0025147977064533143*_d_iF0__4 + 0.050345455482979015*_d_iF1__4
            + 0.11622097556712797*_d_iF2__4 + 0.2353986790647292*_d_iF3__4 + 0.10372825048336794*_d_iF4__4
            - 0.008208158304657426*_d_iF5__4)
        _d_iPsi4__5 = (0.0025147977064533143*_d_iF0__5 + 0.050345455482979015*_d_iF1__5
            + 0.11622097556712797*_d_iF2__5 + 0.2353986790647292*_d_iF3__5 + 0.10372825048336794*_d_iF4__5
            - 0.008208158304657426*_d_iF5__5)
        _x138 = (1.0/math.sqrt(_x137))
        _ift4 = _x138*_x81
        _pd__222 = _x138*_x83
        _x139 = _x137**(-1.5)
        _pd__223 = -_x139*_x85
        _d_ift4__0 = _d_D__0*_pd__222 + _d_iPsi4__0*_pd__223
        _d_ift4__1 = _d_D__1*_pd__222 + _d_iPsi4__1*_pd__223
        _d_ift4__2 = _d_D__2*_pd__222 + _d_iPsi4__2*_pd__223
        _d_ift4__3 = _d_D__3*_pd__222 + _d_iPsi4__3*_pd__223
        _d_ift4__4 = _d_D__4*_pd__222 + _d_iPsi4__4*_pd__223
        _d_ift4__5 = _d_D__5*_pd__222 + _d_iPsi4__5*_pd__223
        _x140 = _x163**2
        _x141 = _x138*_x140
        _x142 = _x141*_x87
        _ifq4 = _P4*_x142
        _pd__224 = _P4*_x141*_x91
        _pd__225 = _x142
        _pd__226 = -_P4*_x139*_x140*_x92
        _pd__227 = -_x138*_x59*_x62*_x87
        _d_ifq4__0 = _d_D__0*_pd__224 + _d_P4__0*_pd__225 + _d_iPsi4__0*_pd__226 + _d_isigma4__0*_pd__227
        _x143 = 0.31009584357909425*_pd__227
        _d_ifq4__1 = _d_D__1*_pd__224 - _d_D__1*_x143 + _d_P4__1*_pd__225 + _d_iPsi4__1*_pd__226
        _d_ifq4__2 = _d_D__2*_pd__224 - _d_D__2*_x143 + _d_P4__2*_pd__225 + _d_iPsi4__2*_pd__226
        _d_ifq4__3 = _d_D__3*_pd__224 - _d_D__3*_x143 + _d_P4__3*_pd__225 + _d_iPsi4__3*_pd__226
        _d_ifq4__4 = _d_D__4*_pd__224 - _d_D__4*_x143 + _d_P4__4*_pd__225 + _d_iPsi4__4*_pd__226
        _d_ifq4__5 = _d_D__5*_pd__224 - _d_D__5*_x143 + _d_P4__5*_pd__225 + _d_iPsi4__5*_pd__226
        _x144 = _x138*_x95
        _x145 = _x144*_x63
        _ifp4 = _x145*_x54
        _x146 = _x54*_x63
        _pd__228 = _x138*_x146*_x99
        _pd__229 = _x144*_x54*_x55
        _pd__230 = -_x100*_x139*_x146
        _pd__231 = _x145
        _d_ifp4__0 = _d_D__0*_pd__228 + _d_Q4__0*_pd__229 + _d_iPsi4__0*_pd__230 + _d_isigma4__0*_pd__231
        _x147 = 0.31009584357909425*_pd__231
        _d_ifp4__1 = _d_D__1*_pd__228 - _d_D__1*_x147 + _d_Q4__1*_pd__229 + _d_iPsi4__1*_pd__230
        _d_ifp4__2 = _d_D__2*_pd__228 - _d_D__2*_x147 + _d_Q4__2*_pd__229 + _d_iPsi4__2*_pd__230
        _d_ifp4__3 = _d_D__3*_pd__228 - _d_D__3*_x147 + _d_Q4__3*_pd__229 + _d_iPsi4__3*_pd__230
        _d_ifp4__4 = _d_D__4*_pd__228 - _d_D__4*_x147 + _d_Q4__4*_pd__229 + _d_iPsi4__4*_pd__230
        _d_ifp4__5 = _d_D__5*_pd__228 - _d_D__5*_x147 + _d_Q4__5*_pd__229 + _d_iPsi4__5*_pd__230
        _x148 = (0.003959513229722528*_x10*_x8*_x9 - _x125 - 0.029703284805013122*_x20
            - 0.029703284805013122*_x21 + 0.029703284805013122*_x22*_x23*_x9 - 0.10140664131431479*_x32
            - 0.10140664131431479*_x33 + 0.10140664131431479*_x34*_x35*_x9 - 0.14531313573962065*_x44
            - 0.14531313573962065*_x45 + 0.14531313573962065*_x46*_x47*_x9 - 0.17612158869639333*_x56
            - 0.17612158869639333*_x57 + 0.17612158869639333*_x58*_x59*_x9 - 0.003959513229722528*_x6
            - 0.04349583621493557*_x68 - 0.04349583621493557*_x69 - 0.003959513229722528*_x7
            + 0.04349583621493557*_x70*_x71*_x9)
        _iPsi5 = _x148
        _d_iPsi5__0 = (0.003959513229722528*_d_iF0__0 + 0.029703284805013122*_d_iF1__0
            + 0.10140664131431479*_d_iF2__0 + 0.14531313573962065*_d_iF3__0 + 0.17612158869639333*_d_iF4__0
            + 0.04349583621493557*_d_iF5__0)
        _d_iPsi5__1 = (0.003959513229722528*_d_iF0__1 + 0.029703284805013122*_d_iF1__1
            + 0.10140664131431479*_d_iF2__1 + 0.14531313573962065*_d_iF3__1 + 0.17612158869639333*_d_iF4__1
            + 0.04349583621493557*_d_iF5__1)
        _d_iPsi5__2 = (0.003959513229722528*_d_iF0__2 + 0.029703284805013122*_d_iF1__2
            + 0.10140664131431479*_d_iF2__2 + 0.14531313573962065*_d_iF3__2 + 0.17612158869639333*_d_iF4__2
            + 0.04349583621493557*_d_iF5__2)
        _d_iPsi5__3 = (0.003959513229722528*_d_iF0__3 + 0.029703284805013122*_d_iF1__3
            + 0.10140664131431479*_d_iF2__3 + 0.14531313573962065*_d_iF3__3 + 0.17612158869639333*_d_iF4__3
            + 0.04349583621493557*_d_iF5__3)
        _d_iPsi5__4 = (0.003959513229722528*_d_iF0__4 + 0.029703284805013122*_d_iF1__4
            + 0.10140664131431479*_d_iF2__4 + 0.14531313573962065*_d_iF3__4 + 0.17612158869639333*_d_iF4__4
            + 0.04349583621493557*_d_iF5__4)
        _d_iPsi5__5 = (0.003959513229722528*_d_iF0__5 + 0.029703284805013122*_d_iF1__5
            + 0.10140664131431479*_d_iF2__5 + 0.14531313573962065*_d_iF3__5 + 0.17612158869639333*_d_iF4__5
            + 0.04349583621493557*_d_iF5__5)
        _x149 = (1.0/math.sqrt(_x148))
        _ift5 = _x149*_x81
        _pd__232 = _x149*_x83
        _x150 = _x148**(-1.5)
        _pd__233 = -_x150*_x85
        _d_ift5__0 = _d_D__0*_pd__232 + _d_iPsi5__0*_pd__233
        _d_ift5__1 = _d_D__1*_pd__232 + _d_iPsi5__1*_pd__233
        _d_ift5__2 = _d_D__2*_pd__232 + _d_iPsi5__2*_pd__233
        _d_ift5__3 = _d_D__3*_pd__232 + _d_iPsi5__3*_pd__233
        _d_ift5__4 = _d_D__4*_pd__232 + _d_iPsi5__4*_pd__233
        _d_ift5__5 = _d_D__5*_pd__232 + _d_iPsi5__5*_pd__233
        _x151 = _x164**2
        _x152 = _x149*_x151
        _x153 = _x152*_x87
        _ifq5 = _P5*_x153
        _pd__234 = _P5*_x152*_x91
        _pd__235 = _x153
        _pd__236 = -_P5*_x150*_x151*_x92
        _pd__237 = -_x149*_x71*_x74*_x87
        _d_ifq5__0 = _d_D__0*_pd__234 + _d_P5__0*_pd__235 + _d_iPsi5__0*_pd__236 + _d_isigma5__0*_pd__237
        _x154 = 0.0663903941688584*_pd__237
        _d_ifq5__1 = _d_D__1*_pd__234 - _d_D__1*_x154 + _d_P5__1*_pd__235 + _d_iPsi5__1*_pd__236
        _d_ifq5__2 = _d_D__2*_pd__234 - _d_D__2*_x154 + _d_P5__2*_pd__235 + _d_iPsi5__2*_pd__236
        _d_ifq5__3 = _d_D__3*_pd__234 - _d_D__3*_x154 + _d_P5__3*_pd__235 + _d_iPsi5__3*_pd__236
        _d_ifq5__4 = _d_D__4*_pd__234 - _d_D__4*_x154 + _d_P5__4*_pd__235 + _d_iPsi5__4*_pd__236
        _d_ifq5__5 = _d_D__5*_pd__234 - _d_D__5*_x154 + _d_P5__5*_pd__235 + _d_iPsi5__5*_pd__236
        _x155 = _x149*_x95
        _x156 = _x155*_x75
        _ifp5 = _x156*_x66
        _x157 = _x66*_x75
        _pd__238 = _x149*_x157*_x99
        _pd__239 = _x155*_x66*_x67
        _pd__240 = -_x100*_x150*_x157
        _pd__241 = _x156
        _d_ifp5__0 = _d_D__0*_pd__238 + _d_Q5__0*_pd__239 + _d_iPsi5__0*_pd__240 + _d_isigma5__0*_pd__241
        _x158 = 0.0663903941688584*_pd__241
        _d_ifp5__1 = _d_D__1*_pd__238 - _d_D__1*_x158 + _d_Q5__1*_pd__239 + _d_iPsi5__1*_pd__240
        _d_ifp5__2 = _d_D__2*_pd__238 - _d_D__2*_x158 + _d_Q5__2*_pd__239 + _d_iPsi5__2*_pd__240
        _d_ifp5__3 = _d_D__3*_pd__238 - _d_D__3*_x158 + _d_Q5__3*_pd__239 + _d_iPsi5__3*_pd__240
        _d_ifp5__4 = _d_D__4*_pd__238 - _d_D__4*_x158 + _d_Q5__4*_pd__239 + _d_iPsi5__4*_pd__240
        _d_ifp5__5 = _d_D__5*_pd__238 - _d_D__5*_x158 + _d_Q5__5*_pd__239 + _d_iPsi5__5*_pd__240
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi4 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi5 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x165 = m*q_rd**2
        _x166 = -q_r
        _x167 = k_c*(_x166 + l0)
        _x168 = -l0
        _x169 = -_isigma0 - _x168
        _x170 = 0.005784813099631875*k_c
        _x171 = -_isigma1 - _x168
        _x172 = 0.06111131733618721*k_c
        _x173 = -_isigma2 - _x168
        _x174 = 0.17813034617398463*k_c
        _x175 = -_isigma3 - _x168
        _x176 = 0.28978358839870644*k_c
        _x177 = -_isigma4 - _x168
        _x178 = 0.2996502557119514*k_c
        _x179 = -_isigma5 - _x168
        _x180 = 0.16553967927953847*k_c
        _x181 = (0.005784813099631875*_iF0 + 0.06111131733618721*_iF1 + 0.17813034617398463*_iF2
            + 0.28978358839870644*_iF3 + 0.2996502557119514*_iF4 + 0.16553967927953847*_iF5 + _x167
            - _x169*_x170 - _x171*_x172 - _x173*_x174 - _x175*_x176 - _x177*_x178 - _x179*_x180)
        _x182 = math.sqrt(_x165*k_c + _x181**2)
        _x183 = _x181 + _x182
        _x184 = (1.0/_x183)
        _D__next = _x165*_x184
        _x185 = _x169*k_c
        _x186 = _x171*k_c
        _x187 = _x173*k_c
        _x188 = _x175*k_c
        _x189 = _x177*k_c
        _x190 = _x179*k_c
        _x191 = (1.0/_x182)
        _x192 = _x184**2
        _x193 = _x165*_x192
        _pd__242 = (_x193*(-_x191*(3.346406259767255e-05*_iF0 + 0.0003535175490621363*_iF1
            + 0.0010304507599892272*_iF2 + 0.0016763438982271685*_iF3 + 0.001733420724550538*_iF4
            + 0.0009576161052051336*_iF5 + 0.005784813099631875*_x167 - 3.346406259767255e-05*_x185
            - 0.0003535175490621363*_x186 - 0.0010304507599892272*_x187 - 0.0016763438982271685*_x188
            - 0.001733420724550538*_x189 - 0.0009576161052051336*_x190) - 0.005784813099631875))
        _pd__243 = (_x193*(-_x191*(0.0003535175490621363*_iF0 + 0.003734593106564175*_iF1
            + 0.010885780112243256*_iF2 + 0.017709056829452403*_iF3 + 0.018312021866682706*_iF4
            + 0.010116347872182529*_iF5 + 0.06111131733618721*_x167 - 0.0003535175490621363*_x185
            - 0.003734593106564175*_x186 - 0.010885780112243256*_x187 - 0.017709056829452403*_x188
            - 0.018312021866682706*_x189 - 0.010116347872182529*_x190) - 0.06111131733618721))
        _pd__244 = (_x193*(-_x191*(0.0010304507599892272*_iF0 + 0.010885780112243256*_iF1
            + 0.0317304202280636*_iF2 + 0.05161925091700105*_iF3 + 0.05337680378109292*_iF4
            + 0.02948764037559458*_iF5 + 0.17813034617398463*_x167 - 0.0010304507599892272*_x185
            - 0.010885780112243256*_x186 - 0.0317304202280636*_x187 - 0.05161925091700105*_x188
            - 0.05337680378109292*_x189 - 0.02948764037559458*_x190) - 0.17813034617398463))
        _pd__245 = (_x193*(-_x191*(0.0016763438982271685*_iF0 + 0.017709056829452403*_iF1
            + 0.05161925091700105*_iF2 + 0.0839745281052309*_iF3 + 0.08683372636479925*_iF4
            + 0.04797068228399565*_iF5 + 0.28978358839870644*_x167 - 0.0016763438982271685*_x185
            - 0.017709056829452403*_x186 - 0.05161925091700105*_x187 - 0.0839745281052309*_x188
            - 0.08683372636479925*_x189 - 0.04797068228399565*_x190) - 0.28978358839870644))
        _pd__246 = (_x193*(-_x191*(0.001733420724550538*_iF0 + 0.018312021866682706*_iF1
            + 0.05337680378109292*_iF2 + 0.08683372636479925*_iF3 + 0.08979027574823786*_iF4
            + 0.04960400722658813*_iF5 + 0.2996502557119514*_x167 - 0.001733420724550538*_x185
            - 0.018312021866682706*_x186 - 0.05337680378109292*_x187 - 0.08683372636479925*_x188
            - 0.08979027574823786*_x189 - 0.04960400722658813*_x190) - 0.2996502557119514))
        _pd__247 = (_x193*(-_x191*(0.0009576161052051336*_iF0 + 0.010116347872182529*_iF1
            + 0.02948764037559458*_iF2 + 0.04797068228399565*_iF3 + 0.04960400722658813*_iF4
            + 0.027403385415972457*_iF5 + 0.16553967927953847*_x167 - 0.0009576161052051336*_x185
            - 0.010116347872182529*_x186 - 0.02948764037559458*_x187 - 0.04797068228399565*_x188
            - 0.04960400722658813*_x189 - 0.027403385415972457*_x190) - 0.16553967927953847))
        _x194 = _x181*_x191
        _pd__248 = _x193*(-_x170*_x194 - _x170)
        _pd__249 = _x193*(-_x172*_x194 - _x172)
        _pd__250 = _x193*(-_x174*_x194 - _x174)
        _pd__251 = _x193*(-_x176*_x194 - _x176)
        _pd__252 = _x193*(-_x178*_x194 - _x178)
        _pd__253 = _x193*(-_x180*_x194 - _x180)
        _d_D__next__0 = (_d_iF0__0*_pd__242 + _d_iF1__0*_pd__243 + _d_iF2__0*_pd__244 + _d_iF3__0*_pd__245
            + _d_iF4__0*_pd__246 + _d_iF5__0*_pd__247 + _d_isigma0__0*_pd__248 + _d_isigma1__0*_pd__249
            + _d_isigma2__0*_pd__250 + _d_isigma3__0*_pd__251 + _d_isigma4__0*_pd__252
            + _d_isigma5__0*_pd__253 + _x193*(_x194*k_c + k_c))
        _x195 = 0.9988599083720104*_pd__248
        _x196 = 0.9713052300453587*_pd__249
        _x197 = 0.8550748140498466*_pd__250
        _x198 = 0.6164556279666497*_pd__251
        _x199 = 0.31009584357909425*_pd__252
        _x200 = 0.0663903941688584*_pd__253
        _d_D__next__1 = (-_d_D__1*_x195 - _d_D__1*_x196 - _d_D__1*_x197 - _d_D__1*_x198 - _d_D__1*_x199
            - _d_D__1*_x200 + _d_iF0__1*_pd__242 + _d_iF1__1*_pd__243 + _d_iF2__1*_pd__244
            + _d_iF3__1*_pd__245 + _d_iF4__1*_pd__246 + _d_iF5__1*_pd__247 + 2.0*_x184*m*q_rd
            - _x191*_x192*k_c*m**2*q_rd**3)
        _d_D__next__2 = (-_d_D__2*_x195 - _d_D__2*_x196 - _d_D__2*_x197 - _d_D__2*_x198 - _d_D__2*_x199
            - _d_D__2*_x200 + _d_iF0__2*_pd__242 + _d_iF1__2*_pd__243 + _d_iF2__2*_pd__244
            + _d_iF3__2*_pd__245 + _d_iF4__2*_pd__246 + _d_iF5__2*_pd__247)
        _d_D__next__3 = (-_d_D__3*_x195 - _d_D__3*_x196 - _d_D__3*_x197 - _d_D__3*_x198 - _d_D__3*_x199
            - _d_D__3*_x200 + _d_iF0__3*_pd__242 + _d_iF1__3*_pd__243 + _d_iF2__3*_pd__244
            + _d_iF3__3*_pd__245 + _d_iF4__3*_pd__246 + _d_iF5__3*_pd__247)
        _x201 = 2.0*q_r
        _d_D__next__4 = (-_d_D__4*_x195 - _d_D__4*_x196 - _d_D__4*_x197 - _d_D__4*_x198 - _d_D__4*_x199
            - _d_D__4*_x200 + _d_iF0__4*_pd__242 + _d_iF1__4*_pd__243 + _d_iF2__4*_pd__244
            + _d_iF3__4*_pd__245 + _d_iF4__4*_pd__246 + _d_iF5__4*_pd__247
            + _x193*(-0.005784813099631875*_isigma0 - 0.06111131733618721*_isigma1
            - 0.17813034617398463*_isigma2 - 0.28978358839870644*_isigma3 - 0.2996502557119514*_isigma4
            - 0.16553967927953847*_isigma5 - _x166 - _x191*((0.5)*_x165
            + (0.5)*_x181*(0.01156962619926375*_isigma0 + 0.12222263467237442*_isigma1
            + 0.35626069234796925*_isigma2 + 0.5795671767974129*_isigma3 + 0.5993005114239028*_isigma4
            + 0.33107935855907694*_isigma5 - _x201 - 1.164670302474663e-21*l0)) + 5.823351512373315e-22*l0))
        _d_D__next__5 = (-_d_D__5*_x195 - _d_D__5*_x196 - _d_D__5*_x197 - _d_D__5*_x198 - _d_D__5*_x199
            - _d_D__5*_x200 + _d_iF0__5*_pd__242 + _d_iF1__5*_pd__243 + _d_iF2__5*_pd__244
            + _d_iF3__5*_pd__245 + _d_iF4__5*_pd__246 + _d_iF5__5*_pd__247)
        _Q0__next = (0.04283112309479259*_ifq0 + 0.19514451252126672*_ifq1 + 0.22463191657986778*_ifq2
            + 0.23962582533582905*_ifq3 + 0.17752635320896998*_ifq4 + 0.08647502636084993*_ifq5 + q_th)
        _d_Q0__next__0 = (0.04283112309479259*_d_ifq0__0 + 0.19514451252126672*_d_ifq1__0
            + 0.22463191657986778*_d_ifq2__0 + 0.23962582533582905*_d_ifq3__0 + 0.17752635320896998*_d_ifq4__0
            + 0.08647502636084993*_d_ifq5__0)
        _d_Q0__next__1 = (0.04283112309479259*_d_ifq0__1 + 0.19514451252126672*_d_ifq1__1
            + 0.22463191657986778*_d_ifq2__1 + 0.23962582533582905*_d_ifq3__1 + 0.17752635320896998*_d_ifq4__1
            + 0.08647502636084993*_d_ifq5__1)
        _d_Q0__next__2 = (0.04283112309479259*_d_ifq0__2 + 0.19514451252126672*_d_ifq1__2
            + 0.22463191657986778*_d_ifq2__2 + 0.23962582533582905*_d_ifq3__2 + 0.17752635320896998*_d_ifq4__2
            + 0.08647502636084993*_d_ifq5__2 + 1.0)
        _d_Q0__next__3 = (0.04283112309479259*_d_ifq0__3 + 0.19514451252126672*_d_ifq1__3
            + 0.22463191657986778*_d_ifq2__3 + 0.23962582533582905*_d_ifq3__3 + 0.17752635320896998*_d_ifq4__3
            + 0.08647502636084993*_d_ifq5__3)
        _d_Q0__next__4 = (0.04283112309479259*_d_ifq0__4 + 0.19514451252126672*_d_ifq1__4
            + 0.22463191657986778*_d_ifq2__4 + 0.23962582533582905*_d_ifq3__4 + 0.17752635320896998*_d_ifq4__4
            + 0.08647502636084993*_d_ifq5__4)
        _d_Q0__next__5 = (0.04283112309479259*_d_ifq0__5 + 0.19514451252126672*_d_ifq1__5
            + 0.22463191657986778*_d_ifq2__5 + 0.23962582533582905*_d_ifq3__5 + 0.17752635320896998*_d_ifq4__5
            + 0.08647502636084993*_d_ifq5__5)
        _Q1__next = (-0.007011245240793691*_ifq0 + 0.09019039326203465*_ifq1 + 0.2542570695795851*_ifq2
            + 0.2235938110460991*_ifq3 + 0.18526797945210696*_ifq4 + 0.08430668513410011*_ifq5 + q_th)
        _d_Q1__next__0 = (-0.007011245240793691*_d_ifq0__0 + 0.09019039326203465*_d_ifq1__0
            + 0.2542570695795851*_d_ifq2__0 + 0.2235938110460991*_d_ifq3__0 + 0.18526797945210696*_d_ifq4__0
            + 0.08430668513410011*_d_ifq5__0)
        _d_Q1__next__1 = (-0.007011245240793691*_d_ifq0__1 + 0.09019039326203465*_d_ifq1__1
            + 0.2542570695795851*_d_ifq2__1 + 0.2235938110460991*_d_ifq3__1 + 0.18526797945210696*_d_ifq4__1
            + 0.08430668513410011*_d_ifq5__1)
        _d_Q1__next__2 = (-0.007011245240793691*_d_ifq0__2 + 0.09019039326203465*_d_ifq1__2
            + 0.2542570695795851*_d_ifq2__2 + 0.2235938110460991*_d_ifq3__2 + 0.18526797945210696*_d_ifq4__2
            + 0.08430668513410011*_d_ifq5__2 + 1.0)
        _d_Q1__next__3 = (-0.007011245240793691*_d_ifq0__3 + 0.09019039326203465*_d_ifq1__3
            + 0.2542570695795851*_d_ifq2__3 + 0.2235938110460991*_d_ifq3__3 + 0.18526797945210696*_d_ifq4__3
            + 0.08430668513410011*_d_ifq5__3)
        _d_Q1__next__4 = (-0.007011245240793691*_d_ifq0__4 + 0.09019039326203465*_d_ifq1__4
            + 0.2542570695795851*_d_ifq2__4 + 0.2235938110460991*_d_ifq3__4 + 0.18526797945210696*_d_ifq4__4
            + 0.08430668513410011*_d_ifq5__4)
        _d_Q1__next__5 = (-0.007011245240793691*_d_ifq0__5 + 0.09019039326203465*_d_ifq1__5
            + 0.2542570695795851*_d_ifq2__5 + 0.2235938110460991*_d_ifq3__5 + 0.18526797945210696*_d_ifq4__5
            + 0.08430668513410011*_d_ifq5__5)
        _Q2__next = (0.0034143235767412987*_ifq0 - 0.0156513758091757*_ifq1 + 0.11697848364317276*_ifq2
            + 0.25443949503200164*_ifq3 + 0.17239079462440696*_ifq4 + 0.0877378719744515*_ifq5 + q_th)
        _d_Q2__next__0 = (0.0034143235767412987*_d_ifq0__0 - 0.0156513758091757*_d_ifq1__0
            + 0.11697848364317276*_d_ifq2__0 + 0.25443949503200164*_d_ifq3__0 + 0.17239079462440696*_d_ifq4__0
            + 0.0877378719744515*_d_ifq5__0)
        _d_Q2__next__1 = (0.0034143235767412987*_d_ifq0__1 - 0.0156513758091757*_d_ifq1__1
            + 0.11697848364317276*_d_ifq2__1 + 0.25443949503200164*_d_ifq3__1 + 0.17239079462440696*_d_ifq4__1
            + 0.0877378719744515*_d_ifq5__1)
        _d_Q2__next__2 = (0.0034143235767412987*_d_ifq0__2 - 0.0156513758091757*_d_ifq1__2
            + 0.11697848364317276*_d_ifq2__2 + 0.25443949503200164*_d_ifq3__2 + 0.17239079462440696*_d_ifq4__2
            + 0.0877378719744515*_d_ifq5__2 + 1.0)
        _d_Q2__next__3 = (0.0034143235767412987*_d_ifq0__3 - 0.0156513758091757*_d_ifq1__3
            + 0.11697848364317276*_d_ifq2__3 + 0.25443949503200164*_d_ifq3__3 + 0.17239079462440696*_d_ifq4__3
            + 0.0877378719744515*_d_ifq5__3)
        _d_Q2__next__4 = (0.0034143235767412987*_d_ifq0__4 - 0.0156513758091757*_d_ifq1__4
            + 0.11697848364317276*_d_ifq2__4 + 0.25443949503200164*_d_ifq3__4 + 0.17239079462440696*_d_ifq4__4
            + 0.0877378719744515*_d_ifq5__4)
        _d_Q2__next__5 = (0.0034143235767412987*_d_ifq0__5 - 0.0156513758091757*_d_ifq1__5
            + 0.11697848364317276*_d_ifq2__5 + 0.25443949503200164*_d_ifq3__5 + 0.17239079462440696*_d_ifq4__5
            + 0.0877378719744515*_d_ifq5__5)
        _Q3__next = (-0.002075625784866334*_ifq0 + 0.007989991899662336*_ifq1 - 0.020482527745656096*_ifq2
            + 0.11697848364317276*_ifq3 + 0.196032162333245*_ifq4 + 0.08224792261284387*_ifq5 + q_th)
        _d_Q3__next__0 = (-0.002075625784866334*_d_ifq0__0 + 0.007989991899662336*_d_ifq1__0
            - 0.020482527745656096*_d_ifq2__0 + 0.11697848364317276*_d_ifq3__0 + 0.196032162333245*_d_ifq4__0
            + 0.08224792261284387*_d_ifq5__0)
        _d_Q3__next__1 = (-0.002075625784866334*_d_ifq0__1 + 0.007989991899662336*_d_ifq1__1
            - 0.020482527745656096*_d_ifq2__1 + 0.11697848364317276*_d_ifq3__1 + 0.196032162333245*_d_ifq4__1
            + 0.08224792261284387*_d_ifq5__1)
        _d_Q3__next__2 = (-0.002075625784866334*_d_ifq0__2 + 0.007989991899662336*_d_ifq1__2
            - 0.020482527745656096*_d_ifq2__2 + 0.11697848364317276*_d_ifq3__2 + 0.196032162333245*_d_ifq4__2
            + 0.08224792261284387*_d_ifq5__2 + 1.0)
        _d_Q3__next__3 = (-0.002075625784866334*_d_ifq0__3 + 0.007989991899662336*_d_ifq1__3
            - 0.020482527745656096*_d_ifq2__3 + 0.11697848364317276*_d_ifq3__3 + 0.196032162333245*_d_ifq4__3
            + 0.08224792261284387*_d_ifq5__3)
        _d_Q3__next__4 = (-0.002075625784866334*_d_ifq0__4 + 0.007989991899662336*_d_ifq1__4
            - 0.020482527745656096*_d_ifq2__4 + 0.11697848364317276*_d_ifq3__4 + 0.196032162333245*_d_ifq4__4
            + 0.08224792261284387*_d_ifq5__4)
        _d_Q3__next__5 = (-0.002075625784866334*_d_ifq0__5 + 0.007989991899662336*_d_ifq1__5
            - 0.020482527745656096*_d_ifq2__5 + 0.11697848364317276*_d_ifq3__5 + 0.196032162333245*_d_ifq4__5
            + 0.08224792261284387*_d_ifq5__5)
        _Q4__next = (0.0013555610554850618*_ifq0 - 0.004887192928037671*_ifq1 + 0.010363156240246424*_ifq2
            - 0.020300102293239586*_ifq3 + 0.09019039326203465*_ifq4 + 0.09267349143037887*_ifq5 + q_th)
        _d_Q4__next__0 = (0.0013555610554850618*_d_ifq0__0 - 0.004887192928037671*_d_ifq1__0
            + 0.010363156240246424*_d_ifq2__0 - 0.020300102293239586*_d_ifq3__0
            + 0.09019039326203465*_d_ifq4__0 + 0.09267349143037887*_d_ifq5__0)
        _d_Q4__next__1 = (0.0013555610554850618*_d_ifq0__1 - 0.004887192928037671*_d_ifq1__1
            + 0.010363156240246424*_d_ifq2__1 - 0.020300102293239586*_d_ifq3__1
            + 0.09019039326203465*_d_ifq4__1 + 0.09267349143037887*_d_ifq5__1)
        _d_Q4__next__2 = (0.0013555610554850618*_d_ifq0__2 - 0.004887192928037671*_d_ifq1__2
            + 0.010363156240246424*_d_ifq2__2 - 0.020300102293239586*_d_ifq3__2
            + 0.09019039326203465*_d_ifq4__2 + 0.09267349143037887*_d_ifq5__2 + 1.0)
        _d_Q4__next__3 = (0.0013555610554850618*_d_ifq0__3 - 0.004887192928037671*_d_ifq1__3
            + 0.010363156240246424*_d_ifq2__3 - 0.020300102293239586*_d_ifq3__3
            + 0.09019039326203465*_d_ifq4__3 + 0.09267349143037887*_d_ifq5__3)
        _d_Q4__next__4 = (0.0013555610554850618*_d_ifq0__4 - 0.004887192928037671*_d_ifq1__4
            + 0.010363156240246424*_d_ifq2__4 - 0.020300102293239586*_d_ifq3__4
            + 0.09019039326203465*_d_ifq4__4 + 0.09267349143037887*_d_ifq5__4)
        _d_Q4__next__5 = (0.0013555610554850618*_d_ifq0__5 - 0.004887192928037671*_d_ifq1__5
            + 0.010363156240246424*_d_ifq2__5 - 0.020300102293239586*_d_ifq3__5
            + 0.09019039326203465*_d_ifq4__5 + 0.09267349143037887*_d_ifq5__5)
        _Q5__next = (-0.0008127801712647621*_ifq0 + 0.002854433315099335*_ifq1 - 0.005668858049483512*_ifq2
            + 0.009325050706477751*_ifq3 - 0.014763725997197413*_ifq4 + 0.04283112309479259*_ifq5 + q_th)
        _d_Q5__next__0 = (-0.0008127801712647621*_d_ifq0__0 + 0.002854433315099335*_d_ifq1__0
            - 0.005668858049483512*_d_ifq2__0 + 0.009325050706477751*_d_ifq3__0
            - 0.014763725997197413*_d_ifq4__0 + 0.04283112309479259*_d_ifq5__0)
        _d_Q5__next__1 = (-0.0008127801712647621*_d_ifq0__1 + 0.002854433315099335*_d_ifq1__1
            - 0.005668858049483512*_d_ifq2__1 + 0.009325050706477751*_d_ifq3__1
            - 0.014763725997197413*_d_ifq4__1 + 0.04283112309479259*_d_ifq5__1)
        _d_Q5__next__2 = (-0.0008127801712647621*_d_ifq0__2 + 0.002854433315099335*_d_ifq1__2
            - 0.005668858049483512*_d_ifq2__2 + 0.009325050706477751*_d_ifq3__2
            - 0.014763725997197413*_d_ifq4__2 + 0.04283112309479259*_d_ifq5__2 + 1.0)
        _d_Q5__next__3 = (-0.0008127801712647621*_d_ifq0__3 + 0.002854433315099335*_d_ifq1__3
            - 0.005668858049483512*_d_ifq2__3 + 0.009325050706477751*_d_ifq3__3
            - 0.014763725997197413*_d_ifq4__3 + 0.04283112309479259*_d_ifq5__3)
        _d_Q5__next__4 = (-0.0008127801712647621*_d_ifq0__4 + 0.002854433315099335*_d_ifq1__4
            - 0.005668858049483512*_d_ifq2__4 + 0.009325050706477751*_d_ifq3__4
            - 0.014763725997197413*_d_ifq4__4 + 0.04283112309479259*_d_ifq5__4)
        _d_Q5__next__5 = (-0.0008127801712647621*_d_ifq0__5 + 0.002854433315099335*_d_ifq1__5
            - 0.005668858049483512*_d_ifq2__5 + 0.009325050706477751*_d_ifq3__5
            - 0.014763725997197413*_d_ifq4__5 + 0.04283112309479259*_d_ifq5__5)
        _x202 = m*q_r**2
        _x203 = _x202*q_thd
        _P0__next = (0.04283112309479259*_ifp0 + 0.19514451252126672*_ifp1 + 0.22463191657986778*_ifp2
            + 0.23962582533582905*_ifp3 + 0.17752635320896998*_ifp4 + 0.08647502636084993*_ifp5 + _x203)
        _x204 = _x201*m*q_thd
        _d_P0__next__0 = (0.04283112309479259*_d_ifp0__0 + 0.19514451252126672*_d_ifp1__0
            + 0.22463191657986778*_d_ifp2__0 + 0.23962582533582905*_d_ifp3__0 + 0.17752635320896998*_d_ifp4__0
            + 0.08647502636084993*_d_ifp5__0 + _x204)
        _d_P0__next__1 = (0.04283112309479259*_d_ifp0__1 + 0.19514451252126672*_d_ifp1__1
            + 0.22463191657986778*_d_ifp2__1 + 0.23962582533582905*_d_ifp3__1 + 0.17752635320896998*_d_ifp4__1
            + 0.08647502636084993*_d_ifp5__1)
        _d_P0__next__2 = (0.04283112309479259*_d_ifp0__2 + 0.19514451252126672*_d_ifp1__2
            + 0.22463191657986778*_d_ifp2__2 + 0.23962582533582905*_d_ifp3__2 + 0.17752635320896998*_d_ifp4__2
            + 0.08647502636084993*_d_ifp5__2)
        _d_P0__next__3 = (0.04283112309479259*_d_ifp0__3 + 0.19514451252126672*_d_ifp1__3
            + 0.22463191657986778*_d_ifp2__3 + 0.23962582533582905*_d_ifp3__3 + 0.17752635320896998*_d_ifp4__3
            + 0.08647502636084993*_d_ifp5__3 + _x202)
        _d_P0__next__4 = (0.04283112309479259*_d_ifp0__4 + 0.19514451252126672*_d_ifp1__4
            + 0.22463191657986778*_d_ifp2__4 + 0.23962582533582905*_d_ifp3__4 + 0.17752635320896998*_d_ifp4__4
            + 0.08647502636084993*_d_ifp5__4)
        _d_P0__next__5 = (0.04283112309479259*_d_ifp0__5 + 0.19514451252126672*_d_ifp1__5
            + 0.22463191657986778*_d_ifp2__5 + 0.23962582533582905*_d_ifp3__5 + 0.17752635320896998*_d_ifp4__5
            + 0.08647502636084993*_d_ifp5__5)
        _P1__next = (-0.007011245240793691*_ifp0 + 0.09019039326203465*_ifp1 + 0.2542570695795851*_ifp2
            + 0.2235938110460991*_ifp3 + 0.18526797945210696*_ifp4 + 0.08430668513410011*_ifp5 + _x203)
        _d_P1__next__0 = (-0.007011245240793691*_d_ifp0__0 + 0.09019039326203465*_d_ifp1__0
            + 0.2542570695795851*_d_ifp2__0 + 0.2235938110460991*_d_ifp3__0 + 0.18526797945210696*_d_ifp4__0
            + 0.08430668513410011*_d_ifp5__0 + _x204)
        _d_P1__next__1 = (-0.007011245240793691*_d_ifp0__1 + 0.09019039326203465*_d_ifp1__1
            + 0.2542570695795851*_d_ifp2__1 + 0.2235938110460991*_d_ifp3__1 + 0.18526797945210696*_d_ifp4__1
            + 0.08430668513410011*_d_ifp5__1)
        _d_P1__next__2 = (-0.007011245240793691*_d_ifp0__2 + 0.09019039326203465*_d_ifp1__2
            + 0.2542570695795851*_d_ifp2__2 + 0.2235938110460991*_d_ifp3__2 + 0.18526797945210696*_d_ifp4__2
            + 0.08430668513410011*_d_ifp5__2)
        _d_P1__next__3 = (-0.007011245240793691*_d_ifp0__3 + 0.09019039326203465*_d_ifp1__3
            + 0.2542570695795851*_d_ifp2__3 + 0.2235938110460991*_d_ifp3__3 + 0.18526797945210696*_d_ifp4__3
            + 0.08430668513410011*_d_ifp5__3 + _x202)
        _d_P1__next__4 = (-0.007011245240793691*_d_ifp0__4 + 0.09019039326203465*_d_ifp1__4
            + 0.2542570695795851*_d_ifp2__4 + 0.2235938110460991*_d_ifp3__4 + 0.18526797945210696*_d_ifp4__4
            + 0.08430668513410011*_d_ifp5__4)
        _d_P1__next__5 = (-0.007011245240793691*_d_ifp0__5 + 0.09019039326203465*_d_ifp1__5
            + 0.2542570695795851*_d_ifp2__5 + 0.2235938110460991*_d_ifp3__5 + 0.18526797945210696*_d_ifp4__5
            + 0.08430668513410011*_d_ifp5__5)
        _P2__next = (0.0034143235767412987*_ifp0 - 0.0156513758091757*_ifp1 + 0.11697848364317276*_ifp2
            + 0.25443949503200164*_ifp3 + 0.17239079462440696*_ifp4 + 0.0877378719744515*_ifp5 + _x203)
        _d_P2__next__0 = (0.0034143235767412987*_d_ifp0__0 - 0.0156513758091757*_d_ifp1__0
            + 0.11697848364317276*_d_ifp2__0 + 0.25443949503200164*_d_ifp3__0 + 0.17239079462440696*_d_ifp4__0
            + 0.0877378719744515*_d_ifp5__0 + _x204)
        _d_P2__next__1 = (0.0034143235767412987*_d_ifp0__1 - 0.0156513758091757*_d_ifp1__1
            + 0.11697848364317276*_d_ifp2__1 + 0.25443949503200164*_d_ifp3__1 + 0.17239079462440696*_d_ifp4__1
            + 0.0877378719744515*_d_ifp5__1)
        _d_P2__next__2 = (0.0034143235767412987*_d_ifp0__2 - 0.0156513758091757*_d_ifp1__2
            + 0.11697848364317276*_d_ifp2__2 + 0.25443949503200164*_d_ifp3__2 + 0.17239079462440696*_d_ifp4__2
            + 0.0877378719744515*_d_ifp5__2)
        _d_P2__next__3 = (0.0034143235767412987*_d_ifp0__3 - 0.0156513758091757*_d_ifp1__3
            + 0.11697848364317276*_d_ifp2__3 + 0.25443949503200164*_d_ifp3__3 + 0.17239079462440696*_d_ifp4__3
            + 0.0877378719744515*_d_ifp5__3 + _x202)
        _d_P2__next__4 = (0.0034143235767412987*_d_ifp0__4 - 0.0156513758091757*_d_ifp1__4
            + 0.11697848364317276*_d_ifp2__4 + 0.25443949503200164*_d_ifp3__4 + 0.17239079462440696*_d_ifp4__4
            + 0.0877378719744515*_d_ifp5__4)
        _d_P2__next__5 = (0.0034143235767412987*_d_ifp0__5 - 0.0156513758091757*_d_ifp1__5
            + 0.11697848364317276*_d_ifp2__5 + 0.25443949503200164*_d_ifp3__5 + 0.17239079462440696*_d_ifp4__5
            + 0.0877378719744515*_d_ifp5__5)
        _P3__next = (-0.002075625784866334*_ifp0 + 0.007989991899662336*_ifp1 - 0.020482527745656096*_ifp2
            + 0.11697848364317276*_ifp3 + 0.196032162333245*_ifp4 + 0.08224792261284387*_ifp5 + _x203)
        _d_P3__next__0 = (-0.002075625784866334*_d_ifp0__0 + 0.007989991899662336*_d_ifp1__0
            - 0.020482527745656096*_d_ifp2__0 + 0.11697848364317276*_d_ifp3__0 + 0.196032162333245*_d_ifp4__0
            + 0.08224792261284387*_d_ifp5__0 + _x204)
        _d_P3__next__1 = (-0.002075625784866334*_d_ifp0__1 + 0.007989991899662336*_d_ifp1__1
            - 0.020482527745656096*_d_ifp2__1 + 0.11697848364317276*_d_ifp3__1 + 0.196032162333245*_d_ifp4__1
            + 0.08224792261284387*_d_ifp5__1)
        _d_P3__next__2 = (-0.002075625784866334*_d_ifp0__2 + 0.007989991899662336*_d_ifp1__2
            - 0.020482527745656096*_d_ifp2__2 + 0.11697848364317276*_d_ifp3__2 + 0.196032162333245*_d_ifp4__2
            + 0.08224792261284387*_d_ifp5__2)
        _d_P3__next__3 = (-0.002075625784866334*_d_ifp0__3 + 0.007989991899662336*_d_ifp1__3
            - 0.020482527745656096*_d_ifp2__3 + 0.11697848364317276*_d_ifp3__3 + 0.196032162333245*_d_ifp4__3
            + 0.08224792261284387*_d_ifp5__3 + _x202)
        _d_P3__next__4 = (-0.002075625784866334*_d_ifp0__4 + 0.007989991899662336*_d_ifp1__4
            - 0.020482527745656096*_d_ifp2__4 + 0.11697848364317276*_d_ifp3__4 + 0.196032162333245*_d_ifp4__4
            + 0.08224792261284387*_d_ifp5__4)
        _d_P3__next__5 = (-0.002075625784866334*_d_ifp0__5 + 0.007989991899662336*_d_ifp1__5
            - 0.020482527745656096*_d_ifp2__5 + 0.11697848364317276*_d_ifp3__5 + 0.196032162333245*_d_ifp4__5
            + 0.08224792261284387*_d_ifp5__5)
        _P4__next = (0.0013555610554850618*_ifp0 - 0.004887192928037671*_ifp1 + 0.010363156240246424*_ifp2
            - 0.020300102293239586*_ifp3 + 0.09019039326203465*_ifp4 + 0.09267349143037887*_ifp5 + _x203)
        _d_P4__next__0 = (0.0013555610554850618*_d_ifp0__0 - 0.004887192928037671*_d_ifp1__0
            + 0.010363156240246424*_d_ifp2__0 - 0.020300102293239586*_d_ifp3__0
            + 0.09019039326203465*_d_ifp4__0 + 0.09267349143037887*_d_ifp5__0 + _x204)
        _d_P4__next__1 = (0.0013555610554850618*_d_ifp0__1 - 0.004887192928037671*_d_ifp1__1
            + 0.010363156240246424*_d_ifp2__1 - 0.020300102293239586*_d_ifp3__1
            + 0.09019039326203465*_d_ifp4__1 + 0.09267349143037887*_d_ifp5__1)
        _d_P4__next__2 = (0.0013555610554850618*_d_ifp0__2 - 0.004887192928037671*_d_ifp1__2
            + 0.010363156240246424*_d_ifp2__2 - 0.020300102293239586*_d_ifp3__2
            + 0.09019039326203465*_d_ifp4__2 + 0.09267349143037887*_d_ifp5__2)
        _d_P4__next__3 = (0.0013555610554850618*_d_ifp0__3 - 0.004887192928037671*_d_ifp1__3
            + 0.010363156240246424*_d_ifp2__3 - 0.020300102293239586*_d_ifp3__3
            + 0.09019039326203465*_d_ifp4__3 + 0.09267349143037887*_d_ifp5__3 + _x202)
        _d_P4__next__4 = (0.0013555610554850618*_d_ifp0__4 - 0.004887192928037671*_d_ifp1__4
            + 0.010363156240246424*_d_ifp2__4 - 0.020300102293239586*_d_ifp3__4
            + 0.09019039326203465*_d_ifp4__4 + 0.09267349143037887*_d_ifp5__4)
        _d_P4__next__5 = (0.0013555610554850618*_d_ifp0__5 - 0.004887192928037671*_d_ifp1__5
            + 0.010363156240246424*_d_ifp2__5 - 0.020300102293239586*_d_ifp3__5
            + 0.09019039326203465*_d_ifp4__5 + 0.09267349143037887*_d_ifp5__5)
        _P5__next = (-0.0008127801712647621*_ifp0 + 0.002854433315099335*_ifp1 - 0.005668858049483512*_ifp2
            + 0.009325050706477751*_ifp3 - 0.014763725997197413*_ifp4 + 0.04283112309479259*_ifp5 + _x203)
        _d_P5__next__0 = (-0.0008127801712647621*_d_ifp0__0 + 0.002854433315099335*_d_ifp1__0
            - 0.005668858049483512*_d_ifp2__0 + 0.009325050706477751*_d_ifp3__0
            - 0.014763725997197413*_d_ifp4__0 + 0.04283112309479259*_d_ifp5__0 + _x204)
        _d_P5__next__1 = (-0.0008127801712647621*_d_ifp0__1 + 0.002854433315099335*_d_ifp1__1
            - 0.005668858049483512*_d_ifp2__1 + 0.009325050706477751*_d_ifp3__1
            - 0.014763725997197413*_d_ifp4__1 + 0.04283112309479259*_d_ifp5__1)
        _d_P5__next__2 = (-0.0008127801712647621*_d_ifp0__2 + 0.002854433315099335*_d_ifp1__2
            - 0.005668858049483512*_d_ifp2__2 + 0.009325050706477751*_d_ifp3__2
            - 0.014763725997197413*_d_ifp4__2 + 0.04283112309479259*_d_ifp5__2)
        _d_P5__next__3 = (-0.0008127801712647621*_d_ifp0__3 + 0.002854433315099335*_d_ifp1__3
            - 0.005668858049483512*_d_ifp2__3 + 0.009325050706477751*_d_ifp3__3
            - 0.014763725997197413*_d_ifp4__3 + 0.04283112309479259*_d_ifp5__3 + _x202)
        _d_P5__next__4 = (-0.0008127801712647621*_d_ifp0__4 + 0.002854433315099335*_d_ifp1__4
            - 0.005668858049483512*_d_ifp2__4 + 0.009325050706477751*_d_ifp3__4
            - 0.014763725997197413*_d_ifp4__4 + 0.04283112309479259*_d_ifp5__4)
        _d_P5__next__5 = (-0.0008127801712647621*_d_ifp0__5 + 0.002854433315099335*_d_ifp1__5
            - 0.005668858049483512*_d_ifp2__5 + 0.009325050706477751*_d_ifp3__5
            - 0.014763725997197413*_d_ifp4__5 + 0.04283112309479259*_d_ifp5__5)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_Q2__next - _Q2) <= tol*(1.0)) and (abs(_Q3__next
            - _Q3) <= tol*(1.0)) and (abs(_Q4__next - _Q4) <= tol*(1.0)) and (abs(_Q5__next - _Q5)
            <= tol*(1.0)) and (abs(_P0__next - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P1__next - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P2__next - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P3__next - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P4__next - _P4) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P5__next - _P5) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _Q2__next, _Q3__next, _Q4__next, _Q5__next, _P0__next,
            _P1__next, _P2__next, _P3__next, _P4__next, _P5__next, _d_D__next__0, _d_D__next__1,
            _d_D__next__2, _d_D__next__3, _d_D__next__4, _d_D__next__5, _d_Q0__next__0, _d_Q0__next__1,
            _d_Q0__next__2, _d_Q0__next__3, _d_Q0__next__4, _d_Q0__next__5, _d_Q1__next__0, _d_Q1__next__1,
            _d_Q1__next__2, _d_Q1__next__3, _d_Q1__next__4, _d_Q1__next__5, _d_Q2__next__0, _d_Q2__next__1,
            _d_Q2__next__2, _d_Q2__next__3, _d_Q2__next__4, _d_Q2__next__5, _d_Q3__next__0, _d_Q3__next__1,
            _d_Q3__next__2, _d_Q3__next__3, _d_Q3__next__4, _d_Q3__next__5, _d_Q4__next__0, _d_Q4__next__1,
            _d_Q4__next__2, _d_Q4__next__3, _d_Q4__next__4, _d_Q4__next__5, _d_Q5__next__0, _d_Q5__next__1,
            _d_Q5__next__2, _d_Q5__next__3, _d_Q5__next__4, _d_Q5__next__5, _d_P0__next__0, _d_P0__next__1,
            _d_P0__next__2, _d_P0__next__3, _d_P0__next__4, _d_P0__next__5, _d_P1__next__0, _d_P1__next__1,
            _d_P1__next__2, _d_P1__next__3, _d_P1__next__4, _d_P1__next__5, _d_P2__next__0, _d_P2__next__1,
            _d_P2__next__2, _d_P2__next__3, _d_P2__next__4, _d_P2__next__5, _d_P3__next__0, _d_P3__next__1,
            _d_P3__next__2, _d_P3__next__3, _d_P3__next__4, _d_P3__next__5, _d_P4__next__0, _d_P4__next__1,
            _d_P4__next__2, _d_P4__next__3, _d_P4__next__4, _d_P4__next__5, _d_P5__next__0, _d_P5__next__1,
            _d_P5__next__2, _d_P5__next__3, _d_P5__next__4, _d_P5__next__5, )
        _pk0 = _pkn0
        _passes += 1.0
    # bottom state
    t_half = (0.08566224618958518*_ift0 + 0.1803807865240693*_ift1 + 0.23395696728634552*_ift2
        + 0.23395696728634552*_ift3 + 0.1803807865240693*_ift4 + 0.08566224618958518*_ift5)
    d_t_half__0 = (0.08566224618958518*_d_ift0__0 + 0.1803807865240693*_d_ift1__0
        + 0.23395696728634552*_d_ift2__0 + 0.23395696728634552*_d_ift3__0 + 0.1803807865240693*_d_ift4__0
        + 0.08566224618958518*_d_ift5__0)
    d_t_half__1 = (0.08566224618958518*_d_ift0__1 + 0.1803807865240693*_d_ift1__1
        + 0.23395696728634552*_d_ift2__1 + 0.23395696728634552*_d_ift3__1 + 0.1803807865240693*_d_ift4__1
        + 0.08566224618958518*_d_ift5__1)
    d_t_half__2 = (0.08566224618958518*_d_ift0__2 + 0.1803807865240693*_d_ift1__2
        + 0.23395696728634552*_d_ift2__2 + 0.23395696728634552*_d_ift3__2 + 0.1803807865240693*_d_ift4__2
        + 0.08566224618958518*_d_ift5__2)
    d_t_half__3 = (0.08566224618958518*_d_ift0__3 + 0.1803807865240693*_d_ift1__3
        + 0.23395696728634552*_d_ift2__3 + 0.23395696728634552*_d_ift3__3 + 0.1803807865240693*_d_ift4__3
        + 0.08566224618958518*_d_ift5__3)
    d_t_half__4 = (0.08566224618958518*_d_ift0__4 + 0.1803807865240693*_d_ift1__4
        + 0.23395696728634552*_d_ift2__4 + 0.23395696728634552*_d_ift3__4 + 0.1803807865240693*_d_ift4__4
        + 0.08566224618958518*_d_ift5__4)
    d_t_half__5 = (0.08566224618958518*_d_ift0__5 + 0.1803807865240693*_d_ift1__5
        + 0.23395696728634552*_d_ift2__5 + 0.23395696728634552*_d_ift3__5 + 0.1803807865240693*_d_ift4__5
        + 0.08566224618958518*_d_ift5__5)
    end_q_th = (0.08566224618958518*_ifq0 + 0.1803807865240693*_ifq1 + 0.23395696728634552*_ifq2
        + 0.23395696728634552*_ifq3 + 0.1803807865240693*_ifq4 + 0.08566224618958518*_ifq5 + q_th)
    d_end_q_th__0 = (0.08566224618958518*_d_ifq0__0 + 0.1803807865240693*_d_ifq1__0
        + 0.23395696728634552*_d_ifq2__0 + 0.23395696728634552*_d_ifq3__0 + 0.1803807865240693*_d_ifq4__0
        + 0.08566224618958518*_d_ifq5__0)
    d_end_q_th__1 = (0.08566224618958518*_d_ifq0__1 + 0.1803807865240693*_d_ifq1__1
        + 0.23395696728634552*_d_ifq2__1 + 0.23395696728634552*_d_ifq3__1 + 0.1803807865240693*_d_ifq4__1
        + 0.08566224618958518*_d_ifq5__1)
    d_end_q_th__2 = (0.08566224618958518*_d_ifq0__2 + 0.1803807865240693*_d_ifq1__2
        + 0.23395696728634552*_d_ifq2__2 + 0.23395696728634552*_d_ifq3__2 + 0.1803807865240693*_d_ifq4__2
        + 0.08566224618958518*_d_ifq5__2 + 1.0)
    d_end_q_th__3 = (0.08566224618958518*_d_ifq0__3 + 0.1803807865240693*_d_ifq1__3
        + 0.23395696728634552*_d_ifq2__3 + 0.23395696728634552*_d_ifq3__3 + 0.1803807865240693*_d_ifq4__3
        + 0.08566224618958518*_d_ifq5__3)
    d_end_q_th__4 = (0.08566224618958518*_d_ifq0__4 + 0.1803807865240693*_d_ifq1__4
        + 0.23395696728634552*_d_ifq2__4 + 0.23395696728634552*_d_ifq3__4 + 0.1803807865240693*_d_ifq4__4
        + 0.08566224618958518*_d_ifq5__4)
    d_end_q_th__5 = (0.08566224618958518*_d_ifq0__5 + 0.1803807865240693*_d_ifq1__5
        + 0.23395696728634552*_d_ifq2__5 + 0.23395696728634552*_d_ifq3__5 + 0.1803807865240693*_d_ifq4__5
        + 0.08566224618958518*_d_ifq5__5)
    _x205 = -_D + q_r
    end_q_r = _x205
    d_end_q_r__0 = 1.0 - _d_D__0
    end_q_rd = 0.0
    _x206 = q_r**2
    _x207 = (0.08566224618958518*_ifp0 + 0.1803807865240693*_ifp1 + 0.23395696728634552*_ifp2
        + 0.23395696728634552*_ifp3 + 0.1803807865240693*_ifp4 + 0.08566224618958518*_ifp5 + _x206*m*q_thd)
    _x214 = (1.0/_x205)
    _x208 = _x214**2
    _x209 = (1.0/m)
    _x210 = _x208*_x209
    end_q_thd = _x207*_x210
    _x211 = 0.08566224618958518*_x210
    _pd__254 = _x211
    _x212 = 0.1803807865240693*_x210
    _pd__255 = _x212
    _x213 = 0.23395696728634552*_x210
    _pd__256 = _x213
    _pd__257 = _x213
    _pd__258 = _x212
    _pd__259 = _x211
    _pd__260 = -2.0*_x207*_x209*_x214**3
    d_end_q_thd__0 = (_d_ifp0__0*_pd__254 + _d_ifp1__0*_pd__255 + _d_ifp2__0*_pd__256 + _d_ifp3__0*_pd__257
        + _d_ifp4__0*_pd__258 + _d_ifp5__0*_pd__259 + _pd__260*d_end_q_r__0 + 2.0*_x208*q_r*q_thd)
    d_end_q_thd__1 = (-_d_D__1*_pd__260 + _d_ifp0__1*_pd__254 + _d_ifp1__1*_pd__255 + _d_ifp2__1*_pd__256
        + _d_ifp3__1*_pd__257 + _d_ifp4__1*_pd__258 + _d_ifp5__1*_pd__259)
    d_end_q_thd__2 = (-_d_D__2*_pd__260 + _d_ifp0__2*_pd__254 + _d_ifp1__2*_pd__255 + _d_ifp2__2*_pd__256
        + _d_ifp3__2*_pd__257 + _d_ifp4__2*_pd__258 + _d_ifp5__2*_pd__259)
    d_end_q_thd__3 = (-_d_D__3*_pd__260 + _d_ifp0__3*_pd__254 + _d_ifp1__3*_pd__255 + _d_ifp2__3*_pd__256
        + _d_ifp3__3*_pd__257 + _d_ifp4__3*_pd__258 + _d_ifp5__3*_pd__259 + _x206*_x208)
    d_end_q_thd__4 = (-_d_D__4*_pd__260 + _d_ifp0__4*_pd__254 + _d_ifp1__4*_pd__255 + _d_ifp2__4*_pd__256
        + _d_ifp3__4*_pd__257 + _d_ifp4__4*_pd__258 + _d_ifp5__4*_pd__259)
    d_end_q_thd__5 = (-_d_D__5*_pd__260 + _d_ifp0__5*_pd__254 + _d_ifp1__5*_pd__255 + _d_ifp2__5*_pd__256
        + _d_ifp3__5*_pd__257 + _d_ifp4__5*_pd__258 + _d_ifp5__5*_pd__259)
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # tangents as every branch names them
    d_end_q_r__1 = -_d_D__1
    d_end_q_r__2 = -_d_D__2
    d_end_q_r__3 = -_d_D__3
    d_end_q_r__4 = -_d_D__4
    d_end_q_r__5 = -_d_D__5
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
        d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes, d_end_q_r__1,
        d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4,
        d_t_half__5, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_compression_jvp6_4eaacb(q_r, q_rd, q_th, q_thd, m, l0, k_c, g_s, guess_q_r, guess_q_th,
        guess_q_thd, nodes, iterations, tol, d_guess_q_r__0, d_guess_q_th__0, d_guess_q_thd__0,
        d_guess_q_r__1, d_guess_q_th__1, d_guess_q_thd__1, d_guess_q_r__2, d_guess_q_th__2, d_guess_q_thd__2,
        d_guess_q_r__3, d_guess_q_th__3, d_guess_q_thd__3, d_guess_q_r__4, d_guess_q_th__4, d_guess_q_thd__4,
        d_guess_q_r__5, d_guess_q_th__5, d_guess_q_thd__5):
    """Schwind and Koditschek's iteration, compression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs along 6 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 115, 116, 117, 118, 123.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        q_r: touchdown state: leg length [m]
        q_rd: touchdown state: leg length rate [m/s]
        q_th: touchdown state: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: touchdown state: leg angle rate [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k_c: leg stiffness while compressing k_c [N/m]
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        guess_q_r: zeroth iterate's bottom q_r
        guess_q_th: zeroth iterate's bottom q_th
        guess_q_thd: zeroth iterate's bottom q_thd
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]
        d_guess_q_r__0: direction 0: its component along guess_q_r
        d_guess_q_th__0: direction 0: its component along guess_q_th
        d_guess_q_thd__0: direction 0: its component along guess_q_thd
        d_guess_q_r__1: direction 1: its component along guess_q_r
        d_guess_q_th__1: direction 1: its component along guess_q_th
        d_guess_q_thd__1: direction 1: its component along guess_q_thd
        d_guess_q_r__2: direction 2: its component along guess_q_r
        d_guess_q_th__2: direction 2: its component along guess_q_th
        d_guess_q_thd__2: direction 2: its component along guess_q_thd
        d_guess_q_r__3: direction 3: its component along guess_q_r
        d_guess_q_th__3: direction 3: its component along guess_q_th
        d_guess_q_thd__3: direction 3: its component along guess_q_thd
        d_guess_q_r__4: direction 4: its component along guess_q_r
        d_guess_q_th__4: direction 4: its component along guess_q_th
        d_guess_q_thd__4: direction 4: its component along guess_q_thd
        d_guess_q_r__5: direction 5: its component along guess_q_r
        d_guess_q_th__5: direction 5: its component along guess_q_th
        d_guess_q_thd__5: direction 5: its component along guess_q_thd

    Returns a tuple:
        t_half: time of the compression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        d_<output>__<direction>: d output / d direction for each output above and direction 0, 1, 2, 3, 4, 5
            (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s)
            and math.isfinite(guess_q_r) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0))
            and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0)) and ((nodes == 0.0) or (nodes == 1.0)
            or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd < 0.0)):
        return _NAN42 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # node count
    if nodes == 0.0:
        # branch nodes = 0
        _c0 = (schwind_compression_jvp6_4eaacb_0(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
            d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
            d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1,
            d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r,
            guess_q_th, guess_q_thd, iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol))
        if _c0[30] != STATUS_OK:
            return _NAN42 + (_c0[30],)
        (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
            d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes,
            d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0,
            d_end_q_th__1, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, _) = _c0
    elif nodes == 1.0:
        # branch nodes = 1
        _c1 = (schwind_compression_jvp6_4eaacb_1(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
            d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
            d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1,
            d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r,
            guess_q_th, guess_q_thd, iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol))
        if _c1[30] != STATUS_OK:
            return _NAN42 + (_c1[30],)
        (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
            d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes,
            d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0,
            d_end_q_th__1, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, _) = _c1
    elif nodes == 2.0:
        # branch nodes = 2
        _c2 = (schwind_compression_jvp6_4eaacb_2(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
            d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
            d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1,
            d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r,
            guess_q_th, guess_q_thd, iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol))
        if _c2[30] != STATUS_OK:
            return _NAN42 + (_c2[30],)
        (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
            d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes,
            d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0,
            d_end_q_th__1, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, _) = _c2
    elif nodes == 3.0:
        # branch nodes = 3
        _c3 = (schwind_compression_jvp6_4eaacb_3(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
            d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
            d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1,
            d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r,
            guess_q_th, guess_q_thd, iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol))
        if _c3[30] != STATUS_OK:
            return _NAN42 + (_c3[30],)
        (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
            d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes,
            d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0,
            d_end_q_th__1, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, _) = _c3
    elif nodes == 4.0:
        # branch nodes = 4
        _c4 = (schwind_compression_jvp6_4eaacb_4(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
            d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
            d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1,
            d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r,
            guess_q_th, guess_q_thd, iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol))
        if _c4[30] != STATUS_OK:
            return _NAN42 + (_c4[30],)
        (t_half, end_q_th, d_end_q_th__2, end_q_r, d_end_q_r__0, end_q_rd, end_q_thd, d_end_q_thd__0,
            d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5, passes,
            d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, d_end_q_th__0,
            d_end_q_th__1, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, _) = _c4
    else:
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # derivatives of the outputs
    d_end_q_rd__0 = 0.0
    d_end_q_rd__1 = 0.0
    d_end_q_rd__2 = 0.0
    d_end_q_rd__3 = 0.0
    d_end_q_rd__4 = 0.0
    d_end_q_rd__5 = 0.0
    d_passes__0 = 0.0
    d_passes__1 = 0.0
    d_passes__2 = 0.0
    d_passes__3 = 0.0
    d_passes__4 = 0.0
    d_passes__5 = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
        d_end_q_r__4, d_end_q_r__5, d_end_q_rd__0, d_end_q_rd__1, d_end_q_rd__2, d_end_q_rd__3, d_end_q_rd__4,
        d_end_q_rd__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4,
        d_end_q_th__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, d_passes__0, d_passes__1, d_passes__2, d_passes__3, d_passes__4, d_passes__5,
        STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_0(g_s, guess_q_th, guess_q_thd,
        iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol):
    """Branch nodes = 0 of schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined:
    derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 306
    # Picard passes on the 1 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-q_r + q_r_lo, 0.5*guess_q_th + 0.5*q_th, 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd, -1.0,
        0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.5, 0.0, 1.0*m*q_r*q_thd, 0.0, 0.5*m*q_r**2, 0.0, 0.0,
        0.5*m*q_r_lo**2, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _P0, _d_D__q_r, _d_D__q_th, _d_D__q_thd, _d_D__k_d, _d_D__guess_q_th, _d_D__guess_q_thd,
            _d_Q0__q_r, _d_Q0__q_th, _d_Q0__q_thd, _d_Q0__k_d, _d_Q0__guess_q_th, _d_Q0__guess_q_thd,
            _d_P0__q_r, _d_P0__q_th, _d_P0__q_thd, _d_P0__k_d, _d_P0__guess_q_th, _d_P0__guess_q_thd, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.25*_D
        _x1 = _x0 + q_r
        _isigma0 = _x1
        _d_isigma0__q_r = 0.25*_d_D__q_r + 1.0
        _x2 = k_d*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_d
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x37 = (1.0/_x1)
        _x9 = _x37**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__0 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__1 = _x13*_x4
        _pd__2 = -3.0*_x37**4*_x7*_x8 - k_d
        _d_iF0__q_r = _d_P0__q_r*_pd__0 + _d_Q0__q_r*_pd__1 + _d_isigma0__q_r*_pd__2
        _x14 = 0.25*_pd__2
        _d_iF0__q_th = _d_D__q_th*_x14 + _d_P0__q_th*_pd__0 + _d_Q0__q_th*_pd__1
        _d_iF0__q_thd = _d_D__q_thd*_x14 + _d_P0__q_thd*_pd__0 + _d_Q0__q_thd*_pd__1
        _d_iF0__k_d = _d_D__k_d*_x14 + _d_P0__k_d*_pd__0 + _d_Q0__k_d*_pd__1 - _x0 + l0 - q_r
        _d_iF0__guess_q_th = _d_D__guess_q_th*_x14 + _d_P0__guess_q_th*_pd__0 + _d_Q0__guess_q_th*_pd__1
        _d_iF0__guess_q_thd = _d_D__guess_q_thd*_x14 + _d_P0__guess_q_thd*_pd__0 + _d_Q0__guess_q_thd*_pd__1
        _x15 = 0.5*_x11 + 0.5*_x2 - 0.5*_x5 - 0.5*_x6
        _iPsi0 = _x15
        _x16 = math.sqrt(_D)
        _x17 = math.sqrt(m)
        _x18 = (1.0/math.sqrt(_x15))
        _x19 = _x17*_x18
        _ift0 = _x16*_x19
        _x20 = (0.5)/_x16
        _pd__3 = _x19*_x20
        _x21 = (0.5)*_x16/_x15**(1.5)
        _pd__4 = -_x17*_x21
        _x22 = 0.5*_pd__4
        _d_ift0__q_r = _d_D__q_r*_pd__3 + _d_iF0__q_r*_x22
        _d_ift0__q_th = _d_D__q_th*_pd__3 + _d_iF0__q_th*_x22
        _d_ift0__q_thd = _d_D__q_thd*_pd__3 + _d_iF0__q_thd*_x22
        _d_ift0__k_d = _d_D__k_d*_pd__3 + _d_iF0__k_d*_x22
        _d_ift0__guess_q_th = _d_D__guess_q_th*_pd__3 + _d_iF0__guess_q_th*_x22
        _d_ift0__guess_q_thd = _d_D__guess_q_thd*_pd__3 + _d_iF0__guess_q_thd*_x22
        _x23 = _x16*_x18
        _x24 = (1.0/_x17)
        _x25 = _x24*_x37**2
        _x26 = _x23*_x25
        _ifq0 = _P0*_x26
        _x27 = _P0*_x25
        _x28 = _x18*_x20
        _pd__5 = _x27*_x28
        _pd__6 = _x26
        _pd__7 = -_x21*_x27
        _pd__8 = -_x12*_x23*_x24*_x9
        _x29 = 0.5*_pd__7
        _d_ifq0__q_r = _d_D__q_r*_pd__5 + _d_P0__q_r*_pd__6 + _d_iF0__q_r*_x29 + _d_isigma0__q_r*_pd__8
        _x30 = 0.25*_pd__8
        _d_ifq0__q_th = _d_D__q_th*_pd__5 + _d_D__q_th*_x30 + _d_P0__q_th*_pd__6 + _d_iF0__q_th*_x29
        _d_ifq0__q_thd = _d_D__q_thd*_pd__5 + _d_D__q_thd*_x30 + _d_P0__q_thd*_pd__6 + _d_iF0__q_thd*_x29
        _d_ifq0__k_d = _d_D__k_d*_pd__5 + _d_D__k_d*_x30 + _d_P0__k_d*_pd__6 + _d_iF0__k_d*_x29
        _d_ifq0__guess_q_th = (_d_D__guess_q_th*_pd__5 + _d_D__guess_q_th*_x30 + _d_P0__guess_q_th*_pd__6
            + _d_iF0__guess_q_th*_x29)
        _d_ifq0__guess_q_thd = (_d_D__guess_q_thd*_pd__5 + _d_D__guess_q_thd*_x30 + _d_P0__guess_q_thd*_pd__6
            + _d_iF0__guess_q_thd*_x29)
        _x31 = m**(1.5)
        _x32 = _x23*_x31*g_s
        _x33 = _x13*_x32
        _ifp0 = _x1*_x33
        _x34 = _x1*_x13*_x31*g_s
        _pd__9 = _x28*_x34
        _pd__10 = _x1*_x3*_x32
        _pd__11 = -_x21*_x34
        _pd__12 = _x33
        _x35 = 0.5*_pd__11
        _d_ifp0__q_r = _d_D__q_r*_pd__9 + _d_Q0__q_r*_pd__10 + _d_iF0__q_r*_x35 + _d_isigma0__q_r*_pd__12
        _x36 = 0.25*_pd__12
        _d_ifp0__q_th = _d_D__q_th*_pd__9 + _d_D__q_th*_x36 + _d_Q0__q_th*_pd__10 + _d_iF0__q_th*_x35
        _d_ifp0__q_thd = _d_D__q_thd*_pd__9 + _d_D__q_thd*_x36 + _d_Q0__q_thd*_pd__10 + _d_iF0__q_thd*_x35
        _d_ifp0__k_d = _d_D__k_d*_pd__9 + _d_D__k_d*_x36 + _d_Q0__k_d*_pd__10 + _d_iF0__k_d*_x35
        _d_ifp0__guess_q_th = (_d_D__guess_q_th*_pd__9 + _d_D__guess_q_th*_x36 + _d_Q0__guess_q_th*_pd__10
            + _d_iF0__guess_q_th*_x35)
        _d_ifp0__guess_q_thd = (_d_D__guess_q_thd*_pd__9 + _d_D__guess_q_thd*_x36 + _d_Q0__guess_q_thd*_pd__10
            + _d_iF0__guess_q_thd*_x35)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = 0.5*_ifq0 + q_th
        _d_Q0__next__q_th = 0.5*_d_ifq0__q_th + 1.0
        _x38 = m*q_r**2
        _P0__next = 0.5*_ifp0 + _x38*q_thd
        _d_P0__next__q_r = 0.5*_d_ifp0__q_r + 2.0*m*q_r*q_thd
        _d_P0__next__q_thd = 0.5*_d_ifp0__q_thd + _x38
        _n0_3 = _d_D__q_r
        _n0_4 = _d_D__q_th
        _n0_5 = _d_D__q_thd
        _n0_6 = _d_D__k_d
        _n0_7 = _d_D__guess_q_th
        _n0_8 = _d_D__guess_q_thd
        _n0_9 = 0.5*_d_ifq0__q_r
        _n0_11 = 0.5*_d_ifq0__q_thd
        _n0_12 = 0.5*_d_ifq0__k_d
        _n0_13 = 0.5*_d_ifq0__guess_q_th
        _n0_14 = 0.5*_d_ifq0__guess_q_thd
        _n0_16 = 0.5*_d_ifp0__q_th
        _n0_18 = 0.5*_d_ifp0__k_d
        _n0_19 = 0.5*_d_ifp0__guess_q_th
        _n0_20 = 0.5*_d_ifp0__guess_q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_P0__next - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _P0__next, _n0_3, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8, _n0_9,
            _d_Q0__next__q_th, _n0_11, _n0_12, _n0_13, _n0_14, _d_P0__next__q_r, _n0_16, _d_P0__next__q_thd,
            _n0_18, _n0_19, _n0_20, )
        _pk0 = _pkn0
        _passes += 1.0
    _work = 0.5*_iF0
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 1.0*_ift0
    end_q_th = 1.0*_ifq0 + q_th
    d_end_q_th__q_th = 1.0*_d_ifq0__q_th + 1.0
    end_q_r = q_r_lo
    _x39 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x39
    _pd__13 = _x39/_D
    _pd__14 = _x39/_work
    _x40 = 0.5*_pd__14
    d_end_q_rd__q_r = _d_D__q_r*_pd__13 + _d_iF0__q_r*_x40
    d_end_q_rd__q_th = _d_D__q_th*_pd__13 + _d_iF0__q_th*_x40
    d_end_q_rd__q_thd = _d_D__q_thd*_pd__13 + _d_iF0__q_thd*_x40
    d_end_q_rd__k_d = _d_D__k_d*_pd__13 + _d_iF0__k_d*_x40
    d_end_q_rd__guess_q_th = _d_D__guess_q_th*_pd__13 + _d_iF0__guess_q_th*_x40
    d_end_q_rd__guess_q_thd = _d_D__guess_q_thd*_pd__13 + _d_iF0__guess_q_thd*_x40
    _x41 = q_r**2
    _x42 = q_r_lo**-2
    _x43 = _x42/m
    end_q_thd = _x43*(1.0*_ifp0 + _x41*m*q_thd)
    _pd__15 = 1.0*_x43
    d_end_q_thd__q_r = _d_ifp0__q_r*_pd__15 + 2.0*_x42*q_r*q_thd
    d_end_q_thd__q_th = _d_ifp0__q_th*_pd__15
    d_end_q_thd__q_thd = _d_ifp0__q_thd*_pd__15 + _x41*_x42
    d_end_q_thd__k_d = _d_ifp0__k_d*_pd__15
    d_end_q_thd__guess_q_th = _d_ifp0__guess_q_th*_pd__15
    d_end_q_thd__guess_q_thd = _d_ifp0__guess_q_thd*_pd__15
    passes = _passes
    # tangents as every branch names them
    d_end_q_th__q_r = 1.0*_d_ifq0__q_r
    d_end_q_th__q_thd = 1.0*_d_ifq0__q_thd
    d_end_q_th__k_d = 1.0*_d_ifq0__k_d
    d_end_q_th__guess_q_th = 1.0*_d_ifq0__guess_q_th
    d_end_q_th__guess_q_thd = 1.0*_d_ifq0__guess_q_thd
    d_t_half__q_r = 1.0*_d_ift0__q_r
    d_t_half__q_th = 1.0*_d_ift0__q_th
    d_t_half__q_thd = 1.0*_d_ift0__q_thd
    d_t_half__k_d = 1.0*_d_ift0__k_d
    d_t_half__guess_q_th = 1.0*_d_ift0__guess_q_th
    d_t_half__guess_q_thd = 1.0*_d_ift0__guess_q_thd
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
        d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
        d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd,
        d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_1(g_s, guess_q_th, guess_q_thd,
        iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol):
    """Branch nodes = 1 of schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined:
    derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 711
    # Picard passes on the 2 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-q_r + q_r_lo, 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th,
        0.7886751345948129*guess_q_th + 0.2113248654051871*q_th, 0.2113248654051871*guess_q_thd*m*q_r_lo**2
        + 0.7886751345948129*m*q_r**2*q_thd, 0.7886751345948129*guess_q_thd*m*q_r_lo**2
        + 0.2113248654051871*m*q_r**2*q_thd, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.7886751345948129, 0.0, 0.0,
        0.2113248654051871, 0.0, 0.0, 0.2113248654051871, 0.0, 0.0, 0.7886751345948129, 0.0,
        1.5773502691896257*m*q_r*q_thd, 0.0, 0.7886751345948129*m*q_r**2, 0.0, 0.0,
        0.2113248654051871*m*q_r_lo**2, 0.4226497308103742*m*q_r*q_thd, 0.0, 0.2113248654051871*m*q_r**2, 0.0,
        0.0, 0.7886751345948129*m*q_r_lo**2, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _P0, _P1, _d_D__q_r, _d_D__q_th, _d_D__q_thd, _d_D__k_d, _d_D__guess_q_th,
            _d_D__guess_q_thd, _d_Q0__q_r, _d_Q0__q_th, _d_Q0__q_thd, _d_Q0__k_d, _d_Q0__guess_q_th,
            _d_Q0__guess_q_thd, _d_Q1__q_r, _d_Q1__q_th, _d_Q1__q_thd, _d_Q1__k_d, _d_Q1__guess_q_th,
            _d_Q1__guess_q_thd, _d_P0__q_r, _d_P0__q_th, _d_P0__q_thd, _d_P0__k_d, _d_P0__guess_q_th,
            _d_P0__guess_q_thd, _d_P1__q_r, _d_P1__q_th, _d_P1__q_thd, _d_P1__k_d, _d_P1__guess_q_th,
            _d_P1__guess_q_thd, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.04465819873852045*_D
        _x1 = _x0 + q_r
        _isigma0 = _x1
        _d_isigma0__q_r = 0.04465819873852045*_d_D__q_r + 1.0
        _x2 = k_d*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_d
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x65 = (1.0/_x1)
        _x9 = _x65**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__16 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__17 = _x13*_x4
        _x14 = 3.0*_x8
        _pd__18 = -_x14*_x65**4*_x7 - k_d
        _d_iF0__q_r = _d_P0__q_r*_pd__16 + _d_Q0__q_r*_pd__17 + _d_isigma0__q_r*_pd__18
        _x15 = 0.04465819873852045*_pd__18
        _d_iF0__q_th = _d_D__q_th*_x15 + _d_P0__q_th*_pd__16 + _d_Q0__q_th*_pd__17
        _d_iF0__q_thd = _d_D__q_thd*_x15 + _d_P0__q_thd*_pd__16 + _d_Q0__q_thd*_pd__17
        _x16 = l0 - q_r
        _d_iF0__k_d = _d_D__k_d*_x15 + _d_P0__k_d*_pd__16 + _d_Q0__k_d*_pd__17 - _x0 + _x16
        _d_iF0__guess_q_th = _d_D__guess_q_th*_x15 + _d_P0__guess_q_th*_pd__16 + _d_Q0__guess_q_th*_pd__17
        _d_iF0__guess_q_thd = _d_D__guess_q_thd*_x15 + _d_P0__guess_q_thd*_pd__16 + _d_Q0__guess_q_thd*_pd__17
        _x17 = 0.6220084679281462*_D
        _x18 = _x17 + q_r
        _isigma1 = _x18
        _d_isigma1__q_r = 0.6220084679281462*_d_D__q_r + 1.0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x4
        _x21 = _x18*k_d
        _x22 = _P1**2
        _x66 = (1.0/_x18)
        _x23 = _x66**3
        _x24 = _x23*_x8
        _x25 = _x22*_x24
        _iF1 = _x2 - _x20 - _x21 + _x25
        _x26 = 2.0*_P1
        _pd__19 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__20 = _x27*_x4
        _pd__21 = -_x14*_x22*_x66**4 - k_d
        _d_iF1__q_r = _d_P1__q_r*_pd__19 + _d_Q1__q_r*_pd__20 + _d_isigma1__q_r*_pd__21
        _x28 = 0.6220084679281462*_pd__21
        _d_iF1__q_th = _d_D__q_th*_x28 + _d_P1__q_th*_pd__19 + _d_Q1__q_th*_pd__20
        _d_iF1__q_thd = _d_D__q_thd*_x28 + _d_P1__q_thd*_pd__19 + _d_Q1__q_thd*_pd__20
        _d_iF1__k_d = _d_D__k_d*_x28 + _d_P1__k_d*_pd__19 + _d_Q1__k_d*_pd__20 + _x16 - _x17
        _d_iF1__guess_q_th = _d_D__guess_q_th*_x28 + _d_P1__guess_q_th*_pd__19 + _d_Q1__guess_q_th*_pd__20
        _d_iF1__guess_q_thd = _d_D__guess_q_thd*_x28 + _d_P1__guess_q_thd*_pd__19 + _d_Q1__guess_q_thd*_pd__20
        _x29 = (0.5610042339640731*_x11 + 0.5*_x2 + 0.06100423396407311*_x20 + 0.06100423396407311*_x21
            - 0.06100423396407311*_x25 - 0.5610042339640731*_x5 - 0.5610042339640731*_x6)
        _iPsi0 = _x29
        _d_iPsi0__q_r = 0.5610042339640731*_d_iF0__q_r - 0.06100423396407311*_d_iF1__q_r
        _d_iPsi0__q_th = 0.5610042339640731*_d_iF0__q_th - 0.06100423396407311*_d_iF1__q_th
        _d_iPsi0__q_thd = 0.5610042339640731*_d_iF0__q_thd - 0.06100423396407311*_d_iF1__q_thd
        _d_iPsi0__k_d = 0.5610042339640731*_d_iF0__k_d - 0.06100423396407311*_d_iF1__k_d
        _d_iPsi0__guess_q_th = 0.5610042339640731*_d_iF0__guess_q_th - 0.06100423396407311*_d_iF1__guess_q_th
        _d_iPsi0__guess_q_thd = (0.5610042339640731*_d_iF0__guess_q_thd
            - 0.06100423396407311*_d_iF1__guess_q_thd)
        _x30 = (1.0/math.sqrt(_x29))
        _x31 = math.sqrt(_D)
        _x32 = math.sqrt(m)
        _x33 = _x31*_x32
        _ift0 = _x30*_x33
        _x34 = (0.5)/_x31
        _x35 = _x32*_x34
        _pd__22 = _x30*_x35
        _x36 = _x29**(-1.5)
        _x37 = (0.5)*_x33
        _pd__23 = -_x36*_x37
        _d_ift0__q_r = _d_D__q_r*_pd__22 + _d_iPsi0__q_r*_pd__23
        _d_ift0__q_th = _d_D__q_th*_pd__22 + _d_iPsi0__q_th*_pd__23
        _d_ift0__q_thd = _d_D__q_thd*_pd__22 + _d_iPsi0__q_thd*_pd__23
        _d_ift0__k_d = _d_D__k_d*_pd__22 + _d_iPsi0__k_d*_pd__23
        _d_ift0__guess_q_th = _d_D__guess_q_th*_pd__22 + _d_iPsi0__guess_q_th*_pd__23
        _d_ift0__guess_q_thd = _d_D__guess_q_thd*_pd__22 + _d_iPsi0__guess_q_thd*_pd__23
        _x38 = (1.0/_x32)
        _x39 = _x31*_x38
        _x40 = _x65**2
        _x41 = _x30*_x40
        _x42 = _x39*_x41
        _ifq0 = _P0*_x42
        _x43 = _x34*_x38
        _pd__24 = _P0*_x41*_x43
        _pd__25 = _x42
        _x44 = (0.5)*_x39
        _pd__26 = -_P0*_x36*_x40*_x44
        _pd__27 = -_x12*_x30*_x39*_x9
        _d_ifq0__q_r = (_d_D__q_r*_pd__24 + _d_P0__q_r*_pd__25 + _d_iPsi0__q_r*_pd__26
            + _d_isigma0__q_r*_pd__27)
        _x45 = 0.04465819873852045*_pd__27
        _d_ifq0__q_th = _d_D__q_th*_pd__24 + _d_D__q_th*_x45 + _d_P0__q_th*_pd__25 + _d_iPsi0__q_th*_pd__26
        _d_ifq0__q_thd = (_d_D__q_thd*_pd__24 + _d_D__q_thd*_x45 + _d_P0__q_thd*_pd__25
            + _d_iPsi0__q_thd*_pd__26)
        _d_ifq0__k_d = _d_D__k_d*_pd__24 + _d_D__k_d*_x45 + _d_P0__k_d*_pd__25 + _d_iPsi0__k_d*_pd__26
        _d_ifq0__guess_q_th = (_d_D__guess_q_th*_pd__24 + _d_D__guess_q_th*_x45 + _d_P0__guess_q_th*_pd__25
            + _d_iPsi0__guess_q_th*_pd__26)
        _d_ifq0__guess_q_thd = (_d_D__guess_q_thd*_pd__24 + _d_D__guess_q_thd*_x45
            + _d_P0__guess_q_thd*_pd__25 + _d_iPsi0__guess_q_thd*_pd__26)
        _x46 = g_s*m**(1.5)
        _x47 = _x31*_x46
        _x48 = _x30*_x47
        _x49 = _x13*_x48
        _ifp0 = _x1*_x49
        _x50 = _x1*_x13
        _x51 = _x34*_x46
        _pd__28 = _x30*_x50*_x51
        _pd__29 = _x1*_x3*_x48
        _x52 = (0.5)*_x47
        _pd__30 = -_x36*_x50*_x52
        _pd__31 = _x49
        _d_ifp0__q_r = (_d_D__q_r*_pd__28 + _d_Q0__q_r*_pd__29 + _d_iPsi0__q_r*_pd__30
            + _d_isigma0__q_r*_pd__31)
        _x53 = 0.04465819873852045*_pd__31
        _d_ifp0__q_th = _d_D__q_th*_pd__28 + _d_D__q_th*_x53 + _d_Q0__q_th*_pd__29 + _d_iPsi0__q_th*_pd__30
        _d_ifp0__q_thd = (_d_D__q_thd*_pd__28 + _d_D__q_thd*_x53 + _d_Q0__q_thd*_pd__29
            + _d_iPsi0__q_thd*_pd__30)
        _d_ifp0__k_d = _d_D__k_d*_pd__28 + _d_D__k_d*_x53 + _d_Q0__k_d*_pd__29 + _d_iPsi0__k_d*_pd__30
        _d_ifp0__guess_q_th = (_d_D__guess_q_th*_pd__28 + _d_D__guess_q_th*_x53 + _d_Q0__guess_q_th*_pd__29
            + _d_iPsi0__guess_q_th*_pd__30)
        _d_ifp0__guess_q_thd = (_d_D__guess_q_thd*_pd__28 + _d_D__guess_q_thd*_x53
            + _d_Q0__guess_q_thd*_pd__29 + _d_iPsi0__guess_q_thd*_pd__30)
        _x54 = (-0.27232909936926025*_x20 - 0.27232909936926025*_x21 + 0.27232909936926025*_x22*_x23*_x8
            - 0.22767090063073978*_x5 - 0.22767090063073978*_x6 + 0.22767090063073978*_x7*_x8*_x9
            + 0.5*k_d*l0)
        _iPsi1 = _x54
        _d_iPsi1__q_r = 0.22767090063073978*_d_iF0__q_r + 0.27232909936926025*_d_iF1__q_r
        _d_iPsi1__q_th = 0.22767090063073978*_d_iF0__q_th + 0.27232909936926025*_d_iF1__q_th
        _d_iPsi1__q_thd = 0.22767090063073978*_d_iF0__q_thd + 0.27232909936926025*_d_iF1__q_thd
        _d_iPsi1__k_d = 0.22767090063073978*_d_iF0__k_d + 0.27232909936926025*_d_iF1__k_d
        _d_iPsi1__guess_q_th = 0.22767090063073978*_d_iF0__guess_q_th + 0.27232909936926025*_d_iF1__guess_q_th
        _d_iPsi1__guess_q_thd = (0.22767090063073978*_d_iF0__guess_q_thd
            + 0.27232909936926025*_d_iF1__guess_q_thd)
        _x55 = (1.0/math.sqrt(_x54))
        _ift1 = _x33*_x55
        _pd__32 = _x35*_x55
        _x56 = _x54**(-1.5)
        _pd__33 = -_x37*_x56
        _d_ift1__q_r = _d_D__q_r*_pd__32 + _d_iPsi1__q_r*_pd__33
        _d_ift1__q_th = _d_D__q_th*_pd__32 + _d_iPsi1__q_th*_pd__33
        _d_ift1__q_thd = _d_D__q_thd*_pd__32 + _d_iPsi1__q_thd*_pd__33
        _d_ift1__k_d = _d_D__k_d*_pd__32 + _d_iPsi1__k_d*_pd__33
        _d_ift1__guess_q_th = _d_D__guess_q_th*_pd__32 + _d_iPsi1__guess_q_th*_pd__33
        _d_ift1__guess_q_thd = _d_D__guess_q_thd*_pd__32 + _d_iPsi1__guess_q_thd*_pd__33
        _x57 = _x66**2
        _x58 = _x55*_x57
        _x59 = _x39*_x58
        _ifq1 = _P1*_x59
        _pd__34 = _P1*_x43*_x58
        _pd__35 = _x59
        _pd__36 = -_P1*_x44*_x56*_x57
        _pd__37 = -_x23*_x26*_x39*_x55
        _d_ifq1__q_r = (_d_D__q_r*_pd__34 + _d_P1__q_r*_pd__35 + _d_iPsi1__q_r*_pd__36
            + _d_isigma1__q_r*_pd__37)
        _x60 = 0.6220084679281462*_pd__37
        _d_ifq1__q_th = _d_D__q_th*_pd__34 + _d_D__q_th*_x60 + _d_P1__q_th*_pd__35 + _d_iPsi1__q_th*_pd__36
        _d_ifq1__q_thd = (_d_D__q_thd*_pd__34 + _d_D__q_thd*_x60 + _d_P1__q_thd*_pd__35
            + _d_iPsi1__q_thd*_pd__36)
        _d_ifq1__k_d = _d_D__k_d*_pd__34 + _d_D__k_d*_x60 + _d_P1__k_d*_pd__35 + _d_iPsi1__k_d*_pd__36
        _d_ifq1__guess_q_th = (_d_D__guess_q_th*_pd__34 + _d_D__guess_q_th*_x60 + _d_P1__guess_q_th*_pd__35
            + _d_iPsi1__guess_q_th*_pd__36)
        _d_ifq1__guess_q_thd = (_d_D__guess_q_thd*_pd__34 + _d_D__guess_q_thd*_x60
            + _d_P1__guess_q_thd*_pd__35 + _d_iPsi1__guess_q_thd*_pd__36)
        _x61 = _x47*_x55
        _x62 = _x27*_x61
        _ifp1 = _x18*_x62
        _x63 = _x18*_x27
        _pd__38 = _x51*_x55*_x63
        _pd__39 = _x18*_x19*_x61
        _pd__40 = -_x52*_x56*_x63
        _pd__41 = _x62
        _d_ifp1__q_r = (_d_D__q_r*_pd__38 + _d_Q1__q_r*_pd__39 + _d_iPsi1__q_r*_pd__40
            + _d_isigma1__q_r*_pd__41)
        _x64 = 0.6220084679281462*_pd__41
        _d_ifp1__q_th = _d_D__q_th*_pd__38 + _d_D__q_th*_x64 + _d_Q1__q_th*_pd__39 + _d_iPsi1__q_th*_pd__40
        _d_ifp1__q_thd = (_d_D__q_thd*_pd__38 + _d_D__q_thd*_x64 + _d_Q1__q_thd*_pd__39
            + _d_iPsi1__q_thd*_pd__40)
        _d_ifp1__k_d = _d_D__k_d*_pd__38 + _d_D__k_d*_x64 + _d_Q1__k_d*_pd__39 + _d_iPsi1__k_d*_pd__40
        _d_ifp1__guess_q_th = (_d_D__guess_q_th*_pd__38 + _d_D__guess_q_th*_x64 + _d_Q1__guess_q_th*_pd__39
            + _d_iPsi1__guess_q_th*_pd__40)
        _d_ifp1__guess_q_thd = (_d_D__guess_q_thd*_pd__38 + _d_D__guess_q_thd*_x64
            + _d_Q1__guess_q_thd*_pd__39 + _d_iPsi1__guess_q_thd*_pd__40)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = 0.25*_ifq0 - 0.03867513459481288*_ifq1 + q_th
        _d_Q0__next__q_r = 0.25*_d_ifq0__q_r - 0.03867513459481288*_d_ifq1__q_r
        _d_Q0__next__q_th = 0.25*_d_ifq0__q_th - 0.03867513459481288*_d_ifq1__q_th + 1.0
        _d_Q0__next__q_thd = 0.25*_d_ifq0__q_thd - 0.03867513459481288*_d_ifq1__q_thd
        _d_Q0__next__k_d = 0.25*_d_ifq0__k_d - 0.03867513459481288*_d_ifq1__k_d
        _d_Q0__next__guess_q_th = 0.25*_d_ifq0__guess_q_th - 0.03867513459481288*_d_ifq1__guess_q_th
        _d_Q0__next__guess_q_thd = 0.25*_d_ifq0__guess_q_thd - 0.03867513459481288*_d_ifq1__guess_q_thd
        _Q1__next = 0.5386751345948129*_ifq0 + 0.25*_ifq1 + q_th
        _d_Q1__next__q_r = 0.5386751345948129*_d_ifq0__q_r + 0.25*_d_ifq1__q_r
        _d_Q1__next__q_th = 0.5386751345948129*_d_ifq0__q_th + 0.25*_d_ifq1__q_th + 1.0
        _d_Q1__next__q_thd = 0.5386751345948129*_d_ifq0__q_thd + 0.25*_d_ifq1__q_thd
        _d_Q1__next__k_d = 0.5386751345948129*_d_ifq0__k_d + 0.25*_d_ifq1__k_d
        _d_Q1__next__guess_q_th = 0.5386751345948129*_d_ifq0__guess_q_th + 0.25*_d_ifq1__guess_q_th
        _d_Q1__next__guess_q_thd = 0.5386751345948129*_d_ifq0__guess_q_thd + 0.25*_d_ifq1__guess_q_thd
        _x67 = m*q_r**2
        _x68 = _x67*q_thd
        _P0__next = 0.25*_ifp0 - 0.03867513459481288*_ifp1 + _x68
        _x69 = 2.0*m*q_r*q_thd
        _d_P0__next__q_r = 0.25*_d_ifp0__q_r - 0.03867513459481288*_d_ifp1__q_r + _x69
        _d_P0__next__q_th = 0.25*_d_ifp0__q_th - 0.03867513459481288*_d_ifp1__q_th
        _d_P0__next__q_thd = 0.25*_d_ifp0__q_thd - 0.03867513459481288*_d_ifp1__q_thd + _x67
        _d_P0__next__k_d = 0.25*_d_ifp0__k_d - 0.03867513459481288*_d_ifp1__k_d
        _d_P0__next__guess_q_th = 0.25*_d_ifp0__guess_q_th - 0.03867513459481288*_d_ifp1__guess_q_th
        _d_P0__next__guess_q_thd = 0.25*_d_ifp0__guess_q_thd - 0.03867513459481288*_d_ifp1__guess_q_thd
        _P1__next = 0.5386751345948129*_ifp0 + 0.25*_ifp1 + _x68
        _d_P1__next__q_r = 0.5386751345948129*_d_ifp0__q_r + 0.25*_d_ifp1__q_r + _x69
        _d_P1__next__q_th = 0.5386751345948129*_d_ifp0__q_th + 0.25*_d_ifp1__q_th
        _d_P1__next__q_thd = 0.5386751345948129*_d_ifp0__q_thd + 0.25*_d_ifp1__q_thd + _x67
        _d_P1__next__k_d = 0.5386751345948129*_d_ifp0__k_d + 0.25*_d_ifp1__k_d
        _d_P1__next__guess_q_th = 0.5386751345948129*_d_ifp0__guess_q_th + 0.25*_d_ifp1__guess_q_th
        _d_P1__next__guess_q_thd = 0.5386751345948129*_d_ifp0__guess_q_thd + 0.25*_d_ifp1__guess_q_thd
        _n0_5 = _d_D__q_r
        _n0_6 = _d_D__q_th
        _n0_7 = _d_D__q_thd
        _n0_8 = _d_D__k_d
        _n0_9 = _d_D__guess_q_th
        _n0_10 = _d_D__guess_q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_P0__next - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_P1__next - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _P0__next, _P1__next, _n0_5, _n0_6, _n0_7, _n0_8, _n0_9,
            _n0_10, _d_Q0__next__q_r, _d_Q0__next__q_th, _d_Q0__next__q_thd, _d_Q0__next__k_d,
            _d_Q0__next__guess_q_th, _d_Q0__next__guess_q_thd, _d_Q1__next__q_r, _d_Q1__next__q_th,
            _d_Q1__next__q_thd, _d_Q1__next__k_d, _d_Q1__next__guess_q_th, _d_Q1__next__guess_q_thd,
            _d_P0__next__q_r, _d_P0__next__q_th, _d_P0__next__q_thd, _d_P0__next__k_d,
            _d_P0__next__guess_q_th, _d_P0__next__guess_q_thd, _d_P1__next__q_r, _d_P1__next__q_th,
            _d_P1__next__q_thd, _d_P1__next__k_d, _d_P1__next__guess_q_th, _d_P1__next__guess_q_thd, )
        _pk0 = _pkn0
        _passes += 1.0
    _work = 0.10566243270259355*_iF0 + 0.39433756729740643*_iF1
    _d_work__q_r = 0.10566243270259355*_d_iF0__q_r + 0.39433756729740643*_d_iF1__q_r
    _d_work__q_th = 0.10566243270259355*_d_iF0__q_th + 0.39433756729740643*_d_iF1__q_th
    _d_work__q_thd = 0.10566243270259355*_d_iF0__q_thd + 0.39433756729740643*_d_iF1__q_thd
    _d_work__k_d = 0.10566243270259355*_d_iF0__k_d + 0.39433756729740643*_d_iF1__k_d
    _d_work__guess_q_th = 0.10566243270259355*_d_iF0__guess_q_th + 0.39433756729740643*_d_iF1__guess_q_th
    _d_work__guess_q_thd = 0.10566243270259355*_d_iF0__guess_q_thd + 0.39433756729740643*_d_iF1__guess_q_thd
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 0.5*_ift0 + 0.5*_ift1
    d_t_half__q_r = 0.5*_d_ift0__q_r + 0.5*_d_ift1__q_r
    d_t_half__q_th = 0.5*_d_ift0__q_th + 0.5*_d_ift1__q_th
    d_t_half__q_thd = 0.5*_d_ift0__q_thd + 0.5*_d_ift1__q_thd
    d_t_half__k_d = 0.5*_d_ift0__k_d + 0.5*_d_ift1__k_d
    d_t_half__guess_q_th = 0.5*_d_ift0__guess_q_th + 0.5*_d_ift1__guess_q_th
    d_t_half__guess_q_thd = 0.5*_d_ift0__guess_q_thd + 0.5*_d_ift1__guess_q_thd
    end_q_th = 0.5*_ifq0 + 0.5*_ifq1 + q_th
    d_end_q_th__q_r = 0.5*_d_ifq0__q_r + 0.5*_d_ifq1__q_r
    d_end_q_th__q_th = 0.5*_d_ifq0__q_th + 0.5*_d_ifq1__q_th + 1.0
    d_end_q_th__q_thd = 0.5*_d_ifq0__q_thd + 0.5*_d_ifq1__q_thd
    d_end_q_th__k_d = 0.5*_d_ifq0__k_d + 0.5*_d_ifq1__k_d
    d_end_q_th__guess_q_th = 0.5*_d_ifq0__guess_q_th + 0.5*_d_ifq1__guess_q_th
    d_end_q_th__guess_q_thd = 0.5*_d_ifq0__guess_q_thd + 0.5*_d_ifq1__guess_q_thd
    end_q_r = q_r_lo
    _x70 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x70
    _pd__42 = _x70/_D
    _pd__43 = _x70/_work
    d_end_q_rd__q_r = _d_D__q_r*_pd__42 + _d_work__q_r*_pd__43
    d_end_q_rd__q_th = _d_D__q_th*_pd__42 + _d_work__q_th*_pd__43
    d_end_q_rd__q_thd = _d_D__q_thd*_pd__42 + _d_work__q_thd*_pd__43
    d_end_q_rd__k_d = _d_D__k_d*_pd__42 + _d_work__k_d*_pd__43
    d_end_q_rd__guess_q_th = _d_D__guess_q_th*_pd__42 + _d_work__guess_q_th*_pd__43
    d_end_q_rd__guess_q_thd = _d_D__guess_q_thd*_pd__42 + _d_work__guess_q_thd*_pd__43
    _x71 = q_r**2
    _x72 = q_r_lo**-2
    _x73 = _x72/m
    end_q_thd = _x73*(0.5*_ifp0 + 0.5*_ifp1 + _x71*m*q_thd)
    _x74 = 0.5*_x73
    _pd__44 = _x74
    _pd__45 = _x74
    d_end_q_thd__q_r = _d_ifp0__q_r*_pd__44 + _d_ifp1__q_r*_pd__45 + 2.0*_x72*q_r*q_thd
    d_end_q_thd__q_th = _d_ifp0__q_th*_pd__44 + _d_ifp1__q_th*_pd__45
    d_end_q_thd__q_thd = _d_ifp0__q_thd*_pd__44 + _d_ifp1__q_thd*_pd__45 + _x71*_x72
    d_end_q_thd__k_d = _d_ifp0__k_d*_pd__44 + _d_ifp1__k_d*_pd__45
    d_end_q_thd__guess_q_th = _d_ifp0__guess_q_th*_pd__44 + _d_ifp1__guess_q_th*_pd__45
    d_end_q_thd__guess_q_thd = _d_ifp0__guess_q_thd*_pd__44 + _d_ifp1__guess_q_thd*_pd__45
    passes = _passes
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
        d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
        d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd,
        d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_2(g_s, guess_q_th, guess_q_thd,
        iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol):
    """Branch nodes = 2 of schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined:
    derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1182
    # Picard passes on the 3 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-q_r + q_r_lo, 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th, 0.5*guess_q_th
        + 0.5*q_th, 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th,
        0.11270166537925831*guess_q_thd*m*q_r_lo**2 + 0.8872983346207417*m*q_r**2*q_thd,
        0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd, 0.8872983346207417*guess_q_thd*m*q_r_lo**2
        + 0.11270166537925831*m*q_r**2*q_thd, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.8872983346207417, 0.0,
        0.0, 0.11270166537925831, 0.0, 0.0, 0.5, 0.0, 0.0, 0.5, 0.0, 0.0, 0.11270166537925831, 0.0, 0.0,
        0.8872983346207417, 0.0, 1.7745966692414834*m*q_r*q_thd, 0.0, 0.8872983346207417*m*q_r**2, 0.0, 0.0,
        0.11270166537925831*m*q_r_lo**2, 1.0*m*q_r*q_thd, 0.0, 0.5*m*q_r**2, 0.0, 0.0, 0.5*m*q_r_lo**2,
        0.22540333075851662*m*q_r*q_thd, 0.0, 0.11270166537925831*m*q_r**2, 0.0, 0.0,
        0.8872983346207417*m*q_r_lo**2, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _Q2, _P0, _P1, _P2, _d_D__q_r, _d_D__q_th, _d_D__q_thd, _d_D__k_d, _d_D__guess_q_th,
            _d_D__guess_q_thd, _d_Q0__q_r, _d_Q0__q_th, _d_Q0__q_thd, _d_Q0__k_d, _d_Q0__guess_q_th,
            _d_Q0__guess_q_thd, _d_Q1__q_r, _d_Q1__q_th, _d_Q1__q_thd, _d_Q1__k_d, _d_Q1__guess_q_th,
            _d_Q1__guess_q_thd, _d_Q2__q_r, _d_Q2__q_th, _d_Q2__q_thd, _d_Q2__k_d, _d_Q2__guess_q_th,
            _d_Q2__guess_q_thd, _d_P0__q_r, _d_P0__q_th, _d_P0__q_thd, _d_P0__k_d, _d_P0__guess_q_th,
            _d_P0__guess_q_thd, _d_P1__q_r, _d_P1__q_th, _d_P1__q_thd, _d_P1__k_d, _d_P1__guess_q_th,
            _d_P1__guess_q_thd, _d_P2__q_r, _d_P2__q_th, _d_P2__q_thd, _d_P2__k_d, _d_P2__guess_q_th,
            _d_P2__guess_q_thd, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.012701665379258311*_D
        _x1 = _x0 + q_r
        _isigma0 = _x1
        _d_isigma0__q_r = 0.012701665379258311*_d_D__q_r + 1.0
        _x2 = k_d*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_d
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x88 = (1.0/_x1)
        _x9 = _x88**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__46 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__47 = _x13*_x4
        _x14 = 3.0*_x8
        _pd__48 = -_x14*_x7*_x88**4 - k_d
        _d_iF0__q_r = _d_P0__q_r*_pd__46 + _d_Q0__q_r*_pd__47 + _d_isigma0__q_r*_pd__48
        _x15 = 0.012701665379258311*_pd__48
        _d_iF0__q_th = _d_D__q_th*_x15 + _d_P0__q_th*_pd__46 + _d_Q0__q_th*_pd__47
        _d_iF0__q_thd = _d_D__q_thd*_x15 + _d_P0__q_thd*_pd__46 + _d_Q0__q_thd*_pd__47
        _x16 = l0 - q_r
        _d_iF0__k_d = _d_D__k_d*_x15 + _d_P0__k_d*_pd__46 + _d_Q0__k_d*_pd__47 - _x0 + _x16
        _d_iF0__guess_q_th = _d_D__guess_q_th*_x15 + _d_P0__guess_q_th*_pd__46 + _d_Q0__guess_q_th*_pd__47
        _d_iF0__guess_q_thd = _d_D__guess_q_thd*_x15 + _d_P0__guess_q_thd*_pd__46 + _d_Q0__guess_q_thd*_pd__47
        _x17 = 0.25*_D
        _x18 = _x17 + q_r
        _isigma1 = _x18
        _d_isigma1__q_r = 0.25*_d_D__q_r + 1.0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x4
        _x21 = _x18*k_d
        _x22 = _P1**2
        _x89 = (1.0/_x18)
        _x23 = _x89**3
        _x24 = _x23*_x8
        _x25 = _x22*_x24
        _iF1 = _x2 - _x20 - _x21 + _x25
        _x26 = 2.0*_P1
        _pd__49 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__50 = _x27*_x4
        _pd__51 = -_x14*_x22*_x89**4 - k_d
        _d_iF1__q_r = _d_P1__q_r*_pd__49 + _d_Q1__q_r*_pd__50 + _d_isigma1__q_r*_pd__51
        _x28 = 0.25*_pd__51
        _d_iF1__q_th = _d_D__q_th*_x28 + _d_P1__q_th*_pd__49 + _d_Q1__q_th*_pd__50
        _d_iF1__q_thd = _d_D__q_thd*_x28 + _d_P1__q_thd*_pd__49 + _d_Q1__q_thd*_pd__50
        _d_iF1__k_d = _d_D__k_d*_x28 + _d_P1__k_d*_pd__49 + _d_Q1__k_d*_pd__50 + _x16 - _x17
        _d_iF1__guess_q_th = _d_D__guess_q_th*_x28 + _d_P1__guess_q_th*_pd__49 + _d_Q1__guess_q_th*_pd__50
        _d_iF1__guess_q_thd = _d_D__guess_q_thd*_x28 + _d_P1__guess_q_thd*_pd__49 + _d_Q1__guess_q_thd*_pd__50
        _x29 = 0.7872983346207417*_D
        _x30 = _x29 + q_r
        _isigma2 = _x30
        _d_isigma2__q_r = 0.7872983346207417*_d_D__q_r + 1.0
        _x31 = math.cos(_Q2)
        _x32 = _x31*_x4
        _x33 = _x30*k_d
        _x34 = _P2**2
        _x90 = (1.0/_x30)
        _x35 = _x90**3
        _x36 = _x35*_x8
        _x37 = _x34*_x36
        _iF2 = _x2 - _x32 - _x33 + _x37
        _x38 = 2.0*_P2
        _pd__52 = _x36*_x38
        _x39 = math.sin(_Q2)
        _pd__53 = _x39*_x4
        _pd__54 = -_x14*_x34*_x90**4 - k_d
        _d_iF2__q_r = _d_P2__q_r*_pd__52 + _d_Q2__q_r*_pd__53 + _d_isigma2__q_r*_pd__54
        _x40 = 0.7872983346207417*_pd__54
        _d_iF2__q_th = _d_D__q_th*_x40 + _d_P2__q_th*_pd__52 + _d_Q2__q_th*_pd__53
        _d_iF2__q_thd = _d_D__q_thd*_x40 + _d_P2__q_thd*_pd__52 + _d_Q2__q_thd*_pd__53
        _d_iF2__k_d = _d_D__k_d*_x40 + _d_P2__k_d*_pd__52 + _d_Q2__k_d*_pd__53 + _x16 - _x29
        _d_iF2__guess_q_th = _d_D__guess_q_th*_x40 + _d_P2__guess_q_th*_pd__52 + _d_Q2__guess_q_th*_pd__53
        _d_iF2__guess_q_thd = _d_D__guess_q_thd*_x40 + _d_P2__guess_q_thd*_pd__52 + _d_Q2__guess_q_thd*_pd__53
        _x41 = (0.5762768525670787*_x11 + 0.5*_x2 + 0.1040546303448565*_x20 + 0.1040546303448565*_x21
            - 0.1040546303448565*_x25 - 0.027777777777777776*_x32 - 0.027777777777777776*_x33
            + 0.027777777777777776*_x37 - 0.5762768525670787*_x5 - 0.5762768525670787*_x6)
        _iPsi0 = _x41
        _d_iPsi0__q_r = (0.5762768525670787*_d_iF0__q_r - 0.1040546303448565*_d_iF1__q_r
            + 0.027777777777777776*_d_iF2__q_r)
        _d_iPsi0__q_th = (0.5762768525670787*_d_iF0__q_th - 0.1040546303448565*_d_iF1__q_th
            + 0.027777777777777776*_d_iF2__q_th)
        _d_iPsi0__q_thd = (0.5762768525670787*_d_iF0__q_thd - 0.1040546303448565*_d_iF1__q_thd
            + 0.027777777777777776*_d_iF2__q_thd)
        _d_iPsi0__k_d = (0.5762768525670787*_d_iF0__k_d - 0.1040546303448565*_d_iF1__k_d
            + 0.027777777777777776*_d_iF2__k_d)
        _d_iPsi0__guess_q_th = (0.5762768525670787*_d_iF0__guess_q_th - 0.1040546303448565*_d_iF1__guess_q_th
            + 0.027777777777777776*_d_iF2__guess_q_th)
        _d_iPsi0__guess_q_thd = (0.5762768525670787*_d_iF0__guess_q_thd
            - 0.1040546303448565*_d_iF1__guess_q_thd + 0.027777777777777776*_d_iF2__guess_q_thd)
        _x42 = (1.0/math.sqrt(_x41))
        _x43 = math.sqrt(_D)
        _x44 = math.sqrt(m)
        _x45 = _x43*_x44
        _ift0 = _x42*_x45
        _x46 = (0.5)/_x43
        _x47 = _x44*_x46
        _pd__55 = _x42*_x47
        _x48 = _x41**(-1.5)
        _x49 = (0.5)*_x45
        _pd__56 = -_x48*_x49
        _d_ift0__q_r = _d_D__q_r*_pd__55 + _d_iPsi0__q_r*_pd__56
        _d_ift0__q_th = _d_D__q_th*_pd__55 + _d_iPsi0__q_th*_pd__56
        _d_ift0__q_thd = _d_D__q_thd*_pd__55 + _d_iPsi0__q_thd*_pd__56
        _d_ift0__k_d = _d_D__k_d*_pd__55 + _d_iPsi0__k_d*_pd__56
        _d_ift0__guess_q_th = _d_D__guess_q_th*_pd__55 + _d_iPsi0__guess_q_th*_pd__56
        _d_ift0__guess_q_thd = _d_D__guess_q_thd*_pd__55 + _d_iPsi0__guess_q_thd*_pd__56
        _x50 = (1.0/_x44)
        _x51 = _x43*_x50
        _x52 = _x88**2
        _x53 = _x42*_x52
        _x54 = _x51*_x53
        _ifq0 = _P0*_x54
        _x55 = _x46*_x50
        _pd__57 = _P0*_x53*_x55
        _pd__58 = _x54
        _x56 = (0.5)*_x51
        _pd__59 = -_P0*_x48*_x52*_x56
        _pd__60 = -_x12*_x42*_x51*_x9
        _d_ifq0__q_r = (_d_D__q_r*_pd__57 + _d_P0__q_r*_pd__58 + _d_iPsi0__q_r*_pd__59
            + _d_isigma0__q_r*_pd__60)
        _x57 = 0.012701665379258311*_pd__60
        _d_ifq0__q_th = _d_D__q_th*_pd__57 + _d_D__q_th*_x57 + _d_P0__q_th*_pd__58 + _d_iPsi0__q_th*_pd__59
        _d_ifq0__q_thd = (_d_D__q_thd*_pd__57 + _d_D__q_thd*_x57 + _d_P0__q_thd*_pd__58
            + _d_iPsi0__q_thd*_pd__59)
        _d_ifq0__k_d = _d_D__k_d*_pd__57 + _d_D__k_d*_x57 + _d_P0__k_d*_pd__58 + _d_iPsi0__k_d*_pd__59
        _d_ifq0__guess_q_th = (_d_D__guess_q_th*_pd__57 + _d_D__guess_q_th*_x57 + _d_P0__guess_q_th*_pd__58
            + _d_iPsi0__guess_q_th*_pd__59)
        _d_ifq0__guess_q_thd = (_d_D__guess_q_thd*_pd__57 + _d_D__guess_q_thd*_x57
            + _d_P0__guess_q_thd*_pd__58 + _d_iPsi0__guess_q_thd*_pd__59)
        _x58 = g_s*m**(1.5)
        _x59 = _x43*_x58
        _x60 = _x42*_x59
        _x61 = _x13*_x60
        _ifp0 = _x1*_x61
        _x62 = _x1*_x13
        _x63 = _x46*_x58
        _pd__61 = _x42*_x62*_x63
        _pd__62 = _x1*_x3*_x60
        _x64 = (0.5)*_x59
        _pd__63 = -_x48*_x62*_x64
        _pd__64 = _x61
        _d_ifp0__q_r = (_d_D__q_r*_pd__61 + _d_Q0__q_r*_pd__62 + _d_iPsi0__q_r*_pd__63
            + _d_isigma0__q_r*_pd__64)
        _x65 = 0.012701665379258311*_pd__64
        _d_ifp0__q_th = _d_D__q_th*_pd__61 + _d_D__q_th*_x65 + _d_Q0__q_th*_pd__62 + _d_iPsi0__q_th*_pd__63
        _d_ifp0__q_thd = (_d_D__q_thd*_pd__61 + _d_D__q_thd*_x65 + _d_Q0__q_thd*_pd__62
            + _d_iPsi0__q_thd*_pd__63)
        _d_ifp0__k_d = _d_D__k_d*_pd__61 + _d_D__k_d*_x65 + _d_Q0__k_d*_pd__62 + _d_iPsi0__k_d*_pd__63
        _d_ifp0__guess_q_th = (_d_D__guess_q_th*_pd__61 + _d_D__guess_q_th*_x65 + _d_Q0__guess_q_th*_pd__62
            + _d_iPsi0__guess_q_th*_pd__63)
        _d_ifp0__guess_q_thd = (_d_D__guess_q_thd*_pd__61 + _d_D__guess_q_thd*_x65
            + _d_Q0__guess_q_thd*_pd__62 + _d_iPsi0__guess_q_thd*_pd__63)
        _x66 = (0.17702731517242826*_x11 + 0.5*_x2 - 0.3611111111111111*_x20 - 0.3611111111111111*_x21
            + 0.3611111111111111*_x25 + 0.038138426283539355*_x32 + 0.038138426283539355*_x33
            - 0.038138426283539355*_x37 - 0.17702731517242826*_x5 - 0.17702731517242826*_x6)
        _iPsi1 = _x66
        _d_iPsi1__q_r = (0.17702731517242826*_d_iF0__q_r + 0.3611111111111111*_d_iF1__q_r
            - 0.038138426283539355*_d_iF2__q_r)
        _d_iPsi1__q_th = (0.17702731517242826*_d_iF0__q_th + 0.3611111111111111*_d_iF1__q_th
            - 0.038138426283539355*_d_iF2__q_th)
        _d_iPsi1__q_thd = (0.17702731517242826*_d_iF0__q_thd + 0.3611111111111111*_d_iF1__q_thd
            - 0.038138426283539355*_d_iF2__q_thd)
        _d_iPsi1__k_d = (0.17702731517242826*_d_iF0__k_d + 0.3611111111111111*_d_iF1__k_d
            - 0.038138426283539355*_d_iF2__k_d)
        _d_iPsi1__guess_q_th = (0.17702731517242826*_d_iF0__guess_q_th + 0.3611111111111111*_d_iF1__guess_q_th
            - 0.038138426283539355*_d_iF2__guess_q_th)
        _d_iPsi1__guess_q_thd = (0.17702731517242826*_d_iF0__guess_q_thd
            + 0.3611111111111111*_d_iF1__guess_q_thd - 0.038138426283539355*_d_iF2__guess_q_thd)
        _x67 = (1.0/math.sqrt(_x66))
        _ift1 = _x45*_x67
        _pd__65 = _x47*_x67
        _x68 = _x66**(-1.5)
        _pd__66 = -_x49*_x68
        _d_ift1__q_r = _d_D__q_r*_pd__65 + _d_iPsi1__q_r*_pd__66
        _d_ift1__q_th = _d_D__q_th*_pd__65 + _d_iPsi1__q_th*_pd__66
        _d_ift1__q_thd = _d_D__q_thd*_pd__65 + _d_iPsi1__q_thd*_pd__66
        _d_ift1__k_d = _d_D__k_d*_pd__65 + _d_iPsi1__k_d*_pd__66
        _d_ift1__guess_q_th = _d_D__guess_q_th*_pd__65 + _d_iPsi1__guess_q_th*_pd__66
        _d_ift1__guess_q_thd = _d_D__guess_q_thd*_pd__65 + _d_iPsi1__guess_q_thd*_pd__66
        _x69 = _x89**2
        _x70 = _x67*_x69
        _x71 = _x51*_x70
        _ifq1 = _P1*_x71
        _pd__67 = _P1*_x55*_x70
        _pd__68 = _x71
        _pd__69 = -_P1*_x56*_x68*_x69
        _pd__70 = -_x23*_x26*_x51*_x67
        _d_ifq1__q_r = (_d_D__q_r*_pd__67 + _d_P1__q_r*_pd__68 + _d_iPsi1__q_r*_pd__69
            + _d_isigma1__q_r*_pd__70)
        _x72 = 0.25*_pd__70
        _d_ifq1__q_th = _d_D__q_th*_pd__67 + _d_D__q_th*_x72 + _d_P1__q_th*_pd__68 + _d_iPsi1__q_th*_pd__69
        _d_ifq1__q_thd = (_d_D__q_thd*_pd__67 + _d_D__q_thd*_x72 + _d_P1__q_thd*_pd__68
            + _d_iPsi1__q_thd*_pd__69)
        _d_ifq1__k_d = _d_D__k_d*_pd__67 + _d_D__k_d*_x72 + _d_P1__k_d*_pd__68 + _d_iPsi1__k_d*_pd__69
        _d_ifq1__guess_q_th = (_d_D__guess_q_th*_pd__67 + _d_D__guess_q_th*_x72 + _d_P1__guess_q_th*_pd__68
            + _d_iPsi1__guess_q_th*_pd__69)
        _d_ifq1__guess_q_thd = (_d_D__guess_q_thd*_pd__67 + _d_D__guess_q_thd*_x72
            + _d_P1__guess_q_thd*_pd__68 + _d_iPsi1__guess_q_thd*_pd__69)
        _x73 = _x59*_x67
        _x74 = _x27*_x73
        _ifp1 = _x18*_x74
        _x75 = _x18*_x27
        _pd__71 = _x63*_x67*_x75
        _pd__72 = _x18*_x19*_x73
        _pd__73 = -_x64*_x68*_x75
        _pd__74 = _x74
        _d_ifp1__q_r = (_d_D__q_r*_pd__71 + _d_Q1__q_r*_pd__72 + _d_iPsi1__q_r*_pd__73
            + _d_isigma1__q_r*_pd__74)
        _x76 = 0.25*_pd__74
        _d_ifp1__q_th = _d_D__q_th*_pd__71 + _d_D__q_th*_x76 + _d_Q1__q_th*_pd__72 + _d_iPsi1__q_th*_pd__73
        _d_ifp1__q_thd = (_d_D__q_thd*_pd__71 + _d_D__q_thd*_x76 + _d_Q1__q_thd*_pd__72
            + _d_iPsi1__q_thd*_pd__73)
        _d_ifp1__k_d = _d_D__k_d*_pd__71 + _d_D__k_d*_x76 + _d_Q1__k_d*_pd__72 + _d_iPsi1__k_d*_pd__73
        _d_ifp1__guess_q_th = (_d_D__guess_q_th*_pd__71 + _d_D__guess_q_th*_x76 + _d_Q1__guess_q_th*_pd__72
            + _d_iPsi1__guess_q_th*_pd__73)
        _d_ifp1__guess_q_thd = (_d_D__guess_q_thd*_pd__71 + _d_D__guess_q_thd*_x76
            + _d_Q1__guess_q_thd*_pd__72 + _d_iPsi1__guess_q_thd*_pd__73)
        _x77 = (-0.3262768525670787*_x20 - 0.3262768525670787*_x21 + 0.3262768525670787*_x22*_x23*_x8
            - 0.14594536965514351*_x32 - 0.14594536965514351*_x33 + 0.14594536965514351*_x34*_x35*_x8
            - 0.027777777777777776*_x5 - 0.027777777777777776*_x6 + 0.027777777777777776*_x7*_x8*_x9
            + 0.5*k_d*l0)
        _iPsi2 = _x77
        _d_iPsi2__q_r = (0.027777777777777776*_d_iF0__q_r + 0.3262768525670787*_d_iF1__q_r
            + 0.14594536965514351*_d_iF2__q_r)
        _d_iPsi2__q_th = (0.027777777777777776*_d_iF0__q_th + 0.3262768525670787*_d_iF1__q_th
            + 0.14594536965514351*_d_iF2__q_th)
        _d_iPsi2__q_thd = (0.027777777777777776*_d_iF0__q_thd + 0.3262768525670787*_d_iF1__q_thd
            + 0.14594536965514351*_d_iF2__q_thd)
        _d_iPsi2__k_d = (0.027777777777777776*_d_iF0__k_d + 0.3262768525670787*_d_iF1__k_d
            + 0.14594536965514351*_d_iF2__k_d)
        _d_iPsi2__guess_q_th = (0.027777777777777776*_d_iF0__guess_q_th
            + 0.3262768525670787*_d_iF1__guess_q_th + 0.14594536965514351*_d_iF2__guess_q_th)
        _d_iPsi2__guess_q_thd = (0.027777777777777776*_d_iF0__guess_q_thd
            + 0.3262768525670787*_d_iF1__guess_q_thd + 0.14594536965514351*_d_iF2__guess_q_thd)
        _x78 = (1.0/math.sqrt(_x77))
        _ift2 = _x45*_x78
        _pd__75 = _x47*_x78
        _x79 = _x77**(-1.5)
        _pd__76 = -_x49*_x79
        _d_ift2__q_r = _d_D__q_r*_pd__75 + _d_iPsi2__q_r*_pd__76
        _d_ift2__q_th = _d_D__q_th*_pd__75 + _d_iPsi2__q_th*_pd__76
        _d_ift2__q_thd = _d_D__q_thd*_pd__75 + _d_iPsi2__q_thd*_pd__76
        _d_ift2__k_d = _d_D__k_d*_pd__75 + _d_iPsi2__k_d*_pd__76
        _d_ift2__guess_q_th = _d_D__guess_q_th*_pd__75 + _d_iPsi2__guess_q_th*_pd__76
        _d_ift2__guess_q_thd = _d_D__guess_q_thd*_pd__75 + _d_iPsi2__guess_q_thd*_pd__76
        _x80 = _x90**2
        _x81 = _x78*_x80
        _x82 = _x51*_x81
        _ifq2 = _P2*_x82
        _pd__77 = _P2*_x55*_x81
        _pd__78 = _x82
        _pd__79 = -_P2*_x56*_x79*_x80
        _pd__80 = -_x35*_x38*_x51*_x78
        _d_ifq2__q_r = (_d_D__q_r*_pd__77 + _d_P2__q_r*_pd__78 + _d_iPsi2__q_r*_pd__79
            + _d_isigma2__q_r*_pd__80)
        _x83 = 0.7872983346207417*_pd__80
        _d_ifq2__q_th = _d_D__q_th*_pd__77 + _d_D__q_th*_x83 + _d_P2__q_th*_pd__78 + _d_iPsi2__q_th*_pd__79
        _d_ifq2__q_thd = (_d_D__q_thd*_pd__77 + _d_D__q_thd*_x83 + _d_P2__q_thd*_pd__78
            + _d_iPsi2__q_thd*_pd__79)
        _d_ifq2__k_d = _d_D__k_d*_pd__77 + _d_D__k_d*_x83 + _d_P2__k_d*_pd__78 + _d_iPsi2__k_d*_pd__79
        _d_ifq2__guess_q_th = (_d_D__guess_q_th*_pd__77 + _d_D__guess_q_th*_x83 + _d_P2__guess_q_th*_pd__78
            + _d_iPsi2__guess_q_th*_pd__79)
        _d_ifq2__guess_q_thd = (_d_D__guess_q_thd*_pd__77 + _d_D__guess_q_thd*_x83
            + _d_P2__guess_q_thd*_pd__78 + _d_iPsi2__guess_q_thd*_pd__79)
        _x84 = _x59*_x78
        _x85 = _x39*_x84
        _ifp2 = _x30*_x85
        _x86 = _x30*_x39
        _pd__81 = _x63*_x78*_x86
        _pd__82 = _x30*_x31*_x84
        _pd__83 = -_x64*_x79*_x86
        _pd__84 = _x85
        _d_ifp2__q_r = (_d_D__q_r*_pd__81 + _d_Q2__q_r*_pd__82 + _d_iPsi2__q_r*_pd__83
            + _d_isigma2__q_r*_pd__84)
        _x87 = 0.7872983346207417*_pd__84
        _d_ifp2__q_th = _d_D__q_th*_pd__81 + _d_D__q_th*_x87 + _d_Q2__q_th*_pd__82 + _d_iPsi2__q_th*_pd__83
        _d_ifp2__q_thd = (_d_D__q_thd*_pd__81 + _d_D__q_thd*_x87 + _d_Q2__q_thd*_pd__82
            + _d_iPsi2__q_thd*_pd__83)
        _d_ifp2__k_d = _d_D__k_d*_pd__81 + _d_D__k_d*_x87 + _d_Q2__k_d*_pd__82 + _d_iPsi2__k_d*_pd__83
        _d_ifp2__guess_q_th = (_d_D__guess_q_th*_pd__81 + _d_D__guess_q_th*_x87 + _d_Q2__guess_q_th*_pd__82
            + _d_iPsi2__guess_q_th*_pd__83)
        _d_ifp2__guess_q_thd = (_d_D__guess_q_thd*_pd__81 + _d_D__guess_q_thd*_x87
            + _d_Q2__guess_q_thd*_pd__82 + _d_iPsi2__guess_q_thd*_pd__83)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = 0.1388888888888889*_ifq0 - 0.0359766675249389*_ifq1 + 0.009789444015308325*_ifq2 + q_th
        _d_Q0__next__q_r = (0.1388888888888889*_d_ifq0__q_r - 0.0359766675249389*_d_ifq1__q_r
            + 0.009789444015308325*_d_ifq2__q_r)
        _d_Q0__next__q_th = (0.1388888888888889*_d_ifq0__q_th - 0.0359766675249389*_d_ifq1__q_th
            + 0.009789444015308325*_d_ifq2__q_th + 1.0)
        _d_Q0__next__q_thd = (0.1388888888888889*_d_ifq0__q_thd - 0.0359766675249389*_d_ifq1__q_thd
            + 0.009789444015308325*_d_ifq2__q_thd)
        _d_Q0__next__k_d = (0.1388888888888889*_d_ifq0__k_d - 0.0359766675249389*_d_ifq1__k_d
            + 0.009789444015308325*_d_ifq2__k_d)
        _d_Q0__next__guess_q_th = (0.1388888888888889*_d_ifq0__guess_q_th
            - 0.0359766675249389*_d_ifq1__guess_q_th + 0.009789444015308325*_d_ifq2__guess_q_th)
        _d_Q0__next__guess_q_thd = (0.1388888888888889*_d_ifq0__guess_q_thd
            - 0.0359766675249389*_d_ifq1__guess_q_thd + 0.009789444015308325*_d_ifq2__guess_q_thd)
        _Q1__next = 0.30026319498086457*_ifq0 + 0.2222222222222222*_ifq1 - 0.022485417203086815*_ifq2 + q_th
        _d_Q1__next__q_r = (0.30026319498086457*_d_ifq0__q_r + 0.2222222222222222*_d_ifq1__q_r
            - 0.022485417203086815*_d_ifq2__q_r)
        _d_Q1__next__q_th = (0.30026319498086457*_d_ifq0__q_th + 0.2222222222222222*_d_ifq1__q_th
            - 0.022485417203086815*_d_ifq2__q_th + 1.0)
        _d_Q1__next__q_thd = (0.30026319498086457*_d_ifq0__q_thd + 0.2222222222222222*_d_ifq1__q_thd
            - 0.022485417203086815*_d_ifq2__q_thd)
        _d_Q1__next__k_d = (0.30026319498086457*_d_ifq0__k_d + 0.2222222222222222*_d_ifq1__k_d
            - 0.022485417203086815*_d_ifq2__k_d)
        _d_Q1__next__guess_q_th = (0.30026319498086457*_d_ifq0__guess_q_th
            + 0.2222222222222222*_d_ifq1__guess_q_th - 0.022485417203086815*_d_ifq2__guess_q_th)
        _d_Q1__next__guess_q_thd = (0.30026319498086457*_d_ifq0__guess_q_thd
            + 0.2222222222222222*_d_ifq1__guess_q_thd - 0.022485417203086815*_d_ifq2__guess_q_thd)
        _Q2__next = 0.26798833376246944*_ifq0 + 0.48042111196938336*_ifq1 + 0.1388888888888889*_ifq2 + q_th
        _d_Q2__next__q_r = (0.26798833376246944*_d_ifq0__q_r + 0.48042111196938336*_d_ifq1__q_r
            + 0.1388888888888889*_d_ifq2__q_r)
        _d_Q2__next__q_th = (0.26798833376246944*_d_ifq0__q_th + 0.48042111196938336*_d_ifq1__q_th
            + 0.1388888888888889*_d_ifq2__q_th + 1.0)
        _d_Q2__next__q_thd = (0.26798833376246944*_d_ifq0__q_thd + 0.48042111196938336*_d_ifq1__q_thd
            + 0.1388888888888889*_d_ifq2__q_thd)
        _d_Q2__next__k_d = (0.26798833376246944*_d_ifq0__k_d + 0.48042111196938336*_d_ifq1__k_d
            + 0.1388888888888889*_d_ifq2__k_d)
        _d_Q2__next__guess_q_th = (0.26798833376246944*_d_ifq0__guess_q_th
            + 0.48042111196938336*_d_ifq1__guess_q_th + 0.1388888888888889*_d_ifq2__guess_q_th)
        _d_Q2__next__guess_q_thd = (0.26798833376246944*_d_ifq0__guess_q_thd
            + 0.48042111196938336*_d_ifq1__guess_q_thd + 0.1388888888888889*_d_ifq2__guess_q_thd)
        _x91 = m*q_r**2
        _x92 = _x91*q_thd
        _P0__next = 0.1388888888888889*_ifp0 - 0.0359766675249389*_ifp1 + 0.009789444015308325*_ifp2 + _x92
        _x93 = 2.0*m*q_r*q_thd
        _d_P0__next__q_r = (0.1388888888888889*_d_ifp0__q_r - 0.0359766675249389*_d_ifp1__q_r
            + 0.009789444015308325*_d_ifp2__q_r + _x93)
        _d_P0__next__q_th = (0.1388888888888889*_d_ifp0__q_th - 0.0359766675249389*_d_ifp1__q_th
            + 0.009789444015308325*_d_ifp2__q_th)
        _d_P0__next__q_thd = (0.1388888888888889*_d_ifp0__q_thd - 0.0359766675249389*_d_ifp1__q_thd
            + 0.009789444015308325*_d_ifp2__q_thd + _x91)
        _d_P0__next__k_d = (0.1388888888888889*_d_ifp0__k_d - 0.0359766675249389*_d_ifp1__k_d
            + 0.009789444015308325*_d_ifp2__k_d)
        _d_P0__next__guess_q_th = (0.1388888888888889*_d_ifp0__guess_q_th
            - 0.0359766675249389*_d_ifp1__guess_q_th + 0.009789444015308325*_d_ifp2__guess_q_th)
        _d_P0__next__guess_q_thd = (0.1388888888888889*_d_ifp0__guess_q_thd
            - 0.0359766675249389*_d_ifp1__guess_q_thd + 0.009789444015308325*_d_ifp2__guess_q_thd)
        _P1__next = 0.30026319498086457*_ifp0 + 0.2222222222222222*_ifp1 - 0.022485417203086815*_ifp2 + _x92
        _d_P1__next__q_r = (0.30026319498086457*_d_ifp0__q_r + 0.2222222222222222*_d_ifp1__q_r
            - 0.022485417203086815*_d_ifp2__q_r + _x93)
        _d_P1__next__q_th = (0.30026319498086457*_d_ifp0__q_th + 0.2222222222222222*_d_ifp1__q_th
            - 0.022485417203086815*_d_ifp2__q_th)
        _d_P1__next__q_thd = (0.30026319498086457*_d_ifp0__q_thd + 0.2222222222222222*_d_ifp1__q_thd
            - 0.022485417203086815*_d_ifp2__q_thd + _x91)
        _d_P1__next__k_d = (0.30026319498086457*_d_ifp0__k_d + 0.2222222222222222*_d_ifp1__k_d
            - 0.022485417203086815*_d_ifp2__k_d)
        _d_P1__next__guess_q_th = (0.30026319498086457*_d_ifp0__guess_q_th
            + 0.2222222222222222*_d_ifp1__guess_q_th - 0.022485417203086815*_d_ifp2__guess_q_th)
        _d_P1__next__guess_q_thd = (0.30026319498086457*_d_ifp0__guess_q_thd
            + 0.2222222222222222*_d_ifp1__guess_q_thd - 0.022485417203086815*_d_ifp2__guess_q_thd)
        _P2__next = 0.26798833376246944*_ifp0 + 0.48042111196938336*_ifp1 + 0.1388888888888889*_ifp2 + _x92
        _d_P2__next__q_r = (0.26798833376246944*_d_ifp0__q_r + 0.48042111196938336*_d_ifp1__q_r
            + 0.1388888888888889*_d_ifp2__q_r + _x93)
        _d_P2__next__q_th = (0.26798833376246944*_d_ifp0__q_th + 0.48042111196938336*_d_ifp1__q_th
            + 0.1388888888888889*_d_ifp2__q_th)
        _d_P2__next__q_thd = (0.26798833376246944*_d_ifp0__q_thd + 0.48042111196938336*_d_ifp1__q_thd
            + 0.1388888888888889*_d_ifp2__q_thd + _x91)
        _d_P2__next__k_d = (0.26798833376246944*_d_ifp0__k_d + 0.48042111196938336*_d_ifp1__k_d
            + 0.1388888888888889*_d_ifp2__k_d)
        _d_P2__next__guess_q_th = (0.26798833376246944*_d_ifp0__guess_q_th
            + 0.48042111196938336*_d_ifp1__guess_q_th + 0.1388888888888889*_d_ifp2__guess_q_th)
        _d_P2__next__guess_q_thd = (0.26798833376246944*_d_ifp0__guess_q_thd
            + 0.48042111196938336*_d_ifp1__guess_q_thd + 0.1388888888888889*_d_ifp2__guess_q_thd)
        _n0_7 = _d_D__q_r
        _n0_8 = _d_D__q_th
        _n0_9 = _d_D__q_thd
        _n0_10 = _d_D__k_d
        _n0_11 = _d_D__guess_q_th
        _n0_12 = _d_D__guess_q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_Q2__next - _Q2) <= tol*(1.0)) and (abs(_P0__next
            - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_P1__next - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_P2__next - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _Q2__next, _P0__next, _P1__next, _P2__next, _n0_7, _n0_8,
            _n0_9, _n0_10, _n0_11, _n0_12, _d_Q0__next__q_r, _d_Q0__next__q_th, _d_Q0__next__q_thd,
            _d_Q0__next__k_d, _d_Q0__next__guess_q_th, _d_Q0__next__guess_q_thd, _d_Q1__next__q_r,
            _d_Q1__next__q_th, _d_Q1__next__q_thd, _d_Q1__next__k_d, _d_Q1__next__guess_q_th,
            _d_Q1__next__guess_q_thd, _d_Q2__next__q_r, _d_Q2__next__q_th, _d_Q2__next__q_thd,
            _d_Q2__next__k_d, _d_Q2__next__guess_q_th, _d_Q2__next__guess_q_thd, _d_P0__next__q_r,
            _d_P0__next__q_th, _d_P0__next__q_thd, _d_P0__next__k_d, _d_P0__next__guess_q_th,
            _d_P0__next__guess_q_thd, _d_P1__next__q_r, _d_P1__next__q_th, _d_P1__next__q_thd,
            _d_P1__next__k_d, _d_P1__next__guess_q_th, _d_P1__next__guess_q_thd, _d_P2__next__q_r,
            _d_P2__next__q_th, _d_P2__next__q_thd, _d_P2__next__k_d, _d_P2__next__guess_q_th,
            _d_P2__next__guess_q_thd, )
        _pk0 = _pkn0
        _passes += 1.0
    _work = 0.031306018160905086*_iF0 + 0.2222222222222222*_iF1 + 0.2464717596168727*_iF2
    _d_work__q_r = (0.031306018160905086*_d_iF0__q_r + 0.2222222222222222*_d_iF1__q_r
        + 0.2464717596168727*_d_iF2__q_r)
    _d_work__q_th = (0.031306018160905086*_d_iF0__q_th + 0.2222222222222222*_d_iF1__q_th
        + 0.2464717596168727*_d_iF2__q_th)
    _d_work__q_thd = (0.031306018160905086*_d_iF0__q_thd + 0.2222222222222222*_d_iF1__q_thd
        + 0.2464717596168727*_d_iF2__q_thd)
    _d_work__k_d = (0.031306018160905086*_d_iF0__k_d + 0.2222222222222222*_d_iF1__k_d
        + 0.2464717596168727*_d_iF2__k_d)
    _d_work__guess_q_th = (0.031306018160905086*_d_iF0__guess_q_th + 0.2222222222222222*_d_iF1__guess_q_th
        + 0.2464717596168727*_d_iF2__guess_q_th)
    _d_work__guess_q_thd = (0.031306018160905086*_d_iF0__guess_q_thd + 0.2222222222222222*_d_iF1__guess_q_thd
        + 0.2464717596168727*_d_iF2__guess_q_thd)
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 0.2777777777777778*_ift0 + 0.4444444444444444*_ift1 + 0.2777777777777778*_ift2
    d_t_half__q_r = (0.2777777777777778*_d_ift0__q_r + 0.4444444444444444*_d_ift1__q_r
        + 0.2777777777777778*_d_ift2__q_r)
    d_t_half__q_th = (0.2777777777777778*_d_ift0__q_th + 0.4444444444444444*_d_ift1__q_th
        + 0.2777777777777778*_d_ift2__q_th)
    d_t_half__q_thd = (0.2777777777777778*_d_ift0__q_thd + 0.4444444444444444*_d_ift1__q_thd
        + 0.2777777777777778*_d_ift2__q_thd)
    d_t_half__k_d = (0.2777777777777778*_d_ift0__k_d + 0.4444444444444444*_d_ift1__k_d
        + 0.2777777777777778*_d_ift2__k_d)
    d_t_half__guess_q_th = (0.2777777777777778*_d_ift0__guess_q_th + 0.4444444444444444*_d_ift1__guess_q_th
        + 0.2777777777777778*_d_ift2__guess_q_th)
    d_t_half__guess_q_thd = (0.2777777777777778*_d_ift0__guess_q_thd + 0.4444444444444444*_d_ift1__guess_q_thd
        + 0.2777777777777778*_d_ift2__guess_q_thd)
    end_q_th = 0.2777777777777778*_ifq0 + 0.4444444444444444*_ifq1 + 0.2777777777777778*_ifq2 + q_th
    d_end_q_th__q_r = (0.2777777777777778*_d_ifq0__q_r + 0.4444444444444444*_d_ifq1__q_r
        + 0.2777777777777778*_d_ifq2__q_r)
    d_end_q_th__q_th = (0.2777777777777778*_d_ifq0__q_th + 0.4444444444444444*_d_ifq1__q_th
        + 0.2777777777777778*_d_ifq2__q_th + 1.0)
    d_end_q_th__q_thd = (0.2777777777777778*_d_ifq0__q_thd + 0.4444444444444444*_d_ifq1__q_thd
        + 0.2777777777777778*_d_ifq2__q_thd)
    d_end_q_th__k_d = (0.2777777777777778*_d_ifq0__k_d + 0.4444444444444444*_d_ifq1__k_d
        + 0.2777777777777778*_d_ifq2__k_d)
    d_end_q_th__guess_q_th = (0.2777777777777778*_d_ifq0__guess_q_th + 0.4444444444444444*_d_ifq1__guess_q_th
        + 0.2777777777777778*_d_ifq2__guess_q_th)
    d_end_q_th__guess_q_thd = (0.2777777777777778*_d_ifq0__guess_q_thd
        + 0.4444444444444444*_d_ifq1__guess_q_thd + 0.2777777777777778*_d_ifq2__guess_q_thd)
    end_q_r = q_r_lo
    _x94 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x94
    _pd__85 = _x94/_D
    _pd__86 = _x94/_work
    d_end_q_rd__q_r = _d_D__q_r*_pd__85 + _d_work__q_r*_pd__86
    d_end_q_rd__q_th = _d_D__q_th*_pd__85 + _d_work__q_th*_pd__86
    d_end_q_rd__q_thd = _d_D__q_thd*_pd__85 + _d_work__q_thd*_pd__86
    d_end_q_rd__k_d = _d_D__k_d*_pd__85 + _d_work__k_d*_pd__86
    d_end_q_rd__guess_q_th = _d_D__guess_q_th*_pd__85 + _d_work__guess_q_th*_pd__86
    d_end_q_rd__guess_q_thd = _d_D__guess_q_thd*_pd__85 + _d_work__guess_q_thd*_pd__86
    _x95 = q_r**2
    _x96 = q_r_lo**-2
    _x97 = _x96/m
    end_q_thd = (_x97*(0.2777777777777778*_ifp0 + 0.4444444444444444*_ifp1 + 0.2777777777777778*_ifp2
        + _x95*m*q_thd))
    _x98 = 0.2777777777777778*_x97
    _pd__87 = _x98
    _pd__88 = 0.4444444444444444*_x97
    _pd__89 = _x98
    d_end_q_thd__q_r = _d_ifp0__q_r*_pd__87 + _d_ifp1__q_r*_pd__88 + _d_ifp2__q_r*_pd__89 + 2.0*_x96*q_r*q_thd
    d_end_q_thd__q_th = _d_ifp0__q_th*_pd__87 + _d_ifp1__q_th*_pd__88 + _d_ifp2__q_th*_pd__89
    d_end_q_thd__q_thd = _d_ifp0__q_thd*_pd__87 + _d_ifp1__q_thd*_pd__88 + _d_ifp2__q_thd*_pd__89 + _x95*_x96
    d_end_q_thd__k_d = _d_ifp0__k_d*_pd__87 + _d_ifp1__k_d*_pd__88 + _d_ifp2__k_d*_pd__89
    d_end_q_thd__guess_q_th = (_d_ifp0__guess_q_th*_pd__87 + _d_ifp1__guess_q_th*_pd__88
        + _d_ifp2__guess_q_th*_pd__89)
    d_end_q_thd__guess_q_thd = (_d_ifp0__guess_q_thd*_pd__87 + _d_ifp1__guess_q_thd*_pd__88
        + _d_ifp2__guess_q_thd*_pd__89)
    passes = _passes
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
        d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
        d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd,
        d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_3(g_s, guess_q_th, guess_q_thd,
        iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol):
    """Branch nodes = 3 of schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined:
    derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 1764
    # Picard passes on the 4 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-q_r + q_r_lo, 0.06943184420297371*guess_q_th + 0.9305681557970263*q_th,
        0.33000947820757187*guess_q_th + 0.6699905217924281*q_th, 0.6699905217924281*guess_q_th
        + 0.33000947820757187*q_th, 0.9305681557970263*guess_q_th + 0.06943184420297371*q_th,
        0.06943184420297371*guess_q_thd*m*q_r_lo**2 + 0.9305681557970263*m*q_r**2*q_thd,
        0.33000947820757187*guess_q_thd*m*q_r_lo**2 + 0.6699905217924281*m*q_r**2*q_thd,
        0.6699905217924281*guess_q_thd*m*q_r_lo**2 + 0.33000947820757187*m*q_r**2*q_thd,
        0.9305681557970263*guess_q_thd*m*q_r_lo**2 + 0.06943184420297371*m*q_r**2*q_thd, -1.0, 0.0, 0.0, 0.0,
        0.0, 0.0, 0.0, 0.9305681557970263, 0.0, 0.0, 0.06943184420297371, 0.0, 0.0, 0.6699905217924281, 0.0,
        0.0, 0.33000947820757187, 0.0, 0.0, 0.33000947820757187, 0.0, 0.0, 0.6699905217924281, 0.0, 0.0,
        0.06943184420297371, 0.0, 0.0, 0.9305681557970263, 0.0, 1.8611363115940527*m*q_r*q_thd, 0.0,
        0.9305681557970263*m*q_r**2, 0.0, 0.0, 0.06943184420297371*m*q_r_lo**2,
        1.3399810435848563*m*q_r*q_thd, 0.0, 0.6699905217924281*m*q_r**2, 0.0, 0.0,
        0.33000947820757187*m*q_r_lo**2, 0.6600189564151437*m*q_r*q_thd, 0.0, 0.33000947820757187*m*q_r**2,
        0.0, 0.0, 0.6699905217924281*m*q_r_lo**2, 0.13886368840594743*m*q_r*q_thd, 0.0,
        0.06943184420297371*m*q_r**2, 0.0, 0.0, 0.9305681557970263*m*q_r_lo**2, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _Q2, _Q3, _P0, _P1, _P2, _P3, _d_D__q_r, _d_D__q_th, _d_D__q_thd, _d_D__k_d,
            _d_D__guess_q_th, _d_D__guess_q_thd, _d_Q0__q_r, _d_Q0__q_th, _d_Q0__q_thd, _d_Q0__k_d,
            _d_Q0__guess_q_th, _d_Q0__guess_q_thd, _d_Q1__q_r, _d_Q1__q_th, _d_Q1__q_thd, _d_Q1__k_d,
            _d_Q1__guess_q_th, _d_Q1__guess_q_thd, _d_Q2__q_r, _d_Q2__q_th, _d_Q2__q_thd, _d_Q2__k_d,
            _d_Q2__guess_q_th, _d_Q2__guess_q_thd, _d_Q3__q_r, _d_Q3__q_th, _d_Q3__q_thd, _d_Q3__k_d,
            _d_Q3__guess_q_th, _d_Q3__guess_q_thd, _d_P0__q_r, _d_P0__q_th, _d_P0__q_thd, _d_P0__k_d,
            _d_P0__guess_q_th, _d_P0__guess_q_thd, _d_P1__q_r, _d_P1__q_th, _d_P1__q_thd, _d_P1__k_d,
            _d_P1__guess_q_th, _d_P1__guess_q_thd, _d_P2__q_r, _d_P2__q_th, _d_P2__q_thd, _d_P2__k_d,
            _d_P2__guess_q_th, _d_P2__guess_q_thd, _d_P3__q_r, _d_P3__q_th, _d_P3__q_thd, _d_P3__k_d,
            _d_P3__guess_q_th, _d_P3__guess_q_thd, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.004820780989426014*_D
        _x1 = _x0 + q_r
        _isigma0 = _x1
        _d_isigma0__q_r = 0.004820780989426014*_d_D__q_r + 1.0
        _x2 = k_d*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_d
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x111 = (1.0/_x1)
        _x9 = _x111**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__90 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__91 = _x13*_x4
        _x14 = 3.0*_x8
        _pd__92 = -_x111**4*_x14*_x7 - k_d
        _d_iF0__q_r = _d_P0__q_r*_pd__90 + _d_Q0__q_r*_pd__91 + _d_isigma0__q_r*_pd__92
        _x15 = 0.004820780989426014*_pd__92
        _d_iF0__q_th = _d_D__q_th*_x15 + _d_P0__q_th*_pd__90 + _d_Q0__q_th*_pd__91
        _d_iF0__q_thd = _d_D__q_thd*_x15 + _d_P0__q_thd*_pd__90 + _d_Q0__q_thd*_pd__91
        _x16 = l0 - q_r
        _d_iF0__k_d = _d_D__k_d*_x15 + _d_P0__k_d*_pd__90 + _d_Q0__k_d*_pd__91 - _x0 + _x16
        _d_iF0__guess_q_th = _d_D__guess_q_th*_x15 + _d_P0__guess_q_th*_pd__90 + _d_Q0__guess_q_th*_pd__91
        _d_iF0__guess_q_thd = _d_D__guess_q_thd*_x15 + _d_P0__guess_q_thd*_pd__90 + _d_Q0__guess_q_thd*_pd__91
        _x17 = 0.10890625570683385*_D
        _x18 = _x17 + q_r
        _isigma1 = _x18
        _d_isigma1__q_r = 0.10890625570683385*_d_D__q_r + 1.0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x4
        _x21 = _x18*k_d
        _x22 = _P1**2
        _x112 = (1.0/_x18)
        _x23 = _x112**3
        _x24 = _x23*_x8
        _x25 = _x22*_x24
        _iF1 = _x2 - _x20 - _x21 + _x25
        _x26 = 2.0*_P1
        _pd__93 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__94 = _x27*_x4
        _pd__95 = -_x112**4*_x14*_x22 - k_d
        _d_iF1__q_r = _d_P1__q_r*_pd__93 + _d_Q1__q_r*_pd__94 + _d_isigma1__q_r*_pd__95
        _x28 = 0.10890625570683385*_pd__95
        _d_iF1__q_th = _d_D__q_th*_x28 + _d_P1__q_th*_pd__93 + _d_Q1__q_th*_pd__94
        _d_iF1__q_thd = _d_D__q_thd*_x28 + _d_P1__q_thd*_pd__93 + _d_Q1__q_thd*_pd__94
        _d_iF1__k_d = _d_D__k_d*_x28 + _d_P1__k_d*_pd__93 + _d_Q1__k_d*_pd__94 + _x16 - _x17
        _d_iF1__guess_q_th = _d_D__guess_q_th*_x28 + _d_P1__guess_q_th*_pd__93 + _d_Q1__guess_q_th*_pd__94
        _d_iF1__guess_q_thd = _d_D__guess_q_thd*_x28 + _d_P1__guess_q_thd*_pd__93 + _d_Q1__guess_q_thd*_pd__94
        _x29 = 0.44888729929169013*_D
        _x30 = _x29 + q_r
        _isigma2 = _x30
        _d_isigma2__q_r = 0.44888729929169013*_d_D__q_r + 1.0
        _x31 = math.cos(_Q2)
        _x32 = _x31*_x4
        _x33 = _x30*k_d
        _x34 = _P2**2
        _x113 = (1.0/_x30)
        _x35 = _x113**3
        _x36 = _x35*_x8
        _x37 = _x34*_x36
        _iF2 = _x2 - _x32 - _x33 + _x37
        _x38 = 2.0*_P2
        _pd__96 = _x36*_x38
        _x39 = math.sin(_Q2)
        _pd__97 = _x39*_x4
        _pd__98 = -_x113**4*_x14*_x34 - k_d
        _d_iF2__q_r = _d_P2__q_r*_pd__96 + _d_Q2__q_r*_pd__97 + _d_isigma2__q_r*_pd__98
        _x40 = 0.44888729929169013*_pd__98
        _d_iF2__q_th = _d_D__q_th*_x40 + _d_P2__q_th*_pd__96 + _d_Q2__q_th*_pd__97
        _d_iF2__q_thd = _d_D__q_thd*_x40 + _d_P2__q_thd*_pd__96 + _d_Q2__q_thd*_pd__97
        _d_iF2__k_d = _d_D__k_d*_x40 + _d_P2__k_d*_pd__96 + _d_Q2__k_d*_pd__97 + _x16 - _x29
        _d_iF2__guess_q_th = _d_D__guess_q_th*_x40 + _d_P2__guess_q_th*_pd__96 + _d_Q2__guess_q_th*_pd__97
        _d_iF2__guess_q_thd = _d_D__guess_q_thd*_x40 + _d_P2__guess_q_thd*_pd__96 + _d_Q2__guess_q_thd*_pd__97
        _x41 = 0.8659570925834786*_D
        _x42 = _x41 + q_r
        _isigma3 = _x42
        _d_isigma3__q_r = 0.8659570925834786*_d_D__q_r + 1.0
        _x43 = math.cos(_Q3)
        _x44 = _x4*_x43
        _x45 = _x42*k_d
        _x46 = _P3**2
        _x114 = (1.0/_x42)
        _x47 = _x114**3
        _x48 = _x47*_x8
        _x49 = _x46*_x48
        _iF3 = _x2 - _x44 - _x45 + _x49
        _x50 = 2.0*_P3
        _pd__99 = _x48*_x50
        _x51 = math.sin(_Q3)
        _pd__100 = _x4*_x51
        _pd__101 = -_x114**4*_x14*_x46 - k_d
        _d_iF3__q_r = _d_P3__q_r*_pd__99 + _d_Q3__q_r*_pd__100 + _d_isigma3__q_r*_pd__101
        _x52 = 0.8659570925834786*_pd__101
        _d_iF3__q_th = _d_D__q_th*_x52 + _d_P3__q_th*_pd__99 + _d_Q3__q_th*_pd__100
        _d_iF3__q_thd = _d_D__q_thd*_x52 + _d_P3__q_thd*_pd__99 + _d_Q3__q_thd*_pd__100
        _d_iF3__k_d = _d_D__k_d*_x52 + _d_P3__k_d*_pd__99 + _d_Q3__k_d*_pd__100 + _x16 - _x41
        _d_iF3__guess_q_th = _d_D__guess_q_th*_x52 + _d_P3__guess_q_th*_pd__99 + _d_Q3__guess_q_th*_pd__100
        _d_iF3__guess_q_thd = (_d_D__guess_q_thd*_x52 + _d_P3__guess_q_thd*_pd__99
            + _d_Q3__guess_q_thd*_pd__100)
        _x53 = (0.582374038291501*_x11 + 0.5*_x2 + 0.12383458041329967*_x20 + 0.12383458041329967*_x21
            - 0.12383458041329967*_x25 - 0.0575898635297681*_x32 - 0.0575898635297681*_x33
            + 0.0575898635297681*_x37 + 0.016129321407969507*_x44 + 0.016129321407969507*_x45
            - 0.016129321407969507*_x49 - 0.582374038291501*_x5 - 0.582374038291501*_x6)
        _iPsi0 = _x53
        _d_iPsi0__q_r = (0.582374038291501*_d_iF0__q_r - 0.12383458041329967*_d_iF1__q_r
            + 0.0575898635297681*_d_iF2__q_r - 0.016129321407969507*_d_iF3__q_r)
        _d_iPsi0__q_th = (0.582374038291501*_d_iF0__q_th - 0.12383458041329967*_d_iF1__q_th
            + 0.0575898635297681*_d_iF2__q_th - 0.016129321407969507*_d_iF3__q_th)
        _d_iPsi0__q_thd = (0.582374038291501*_d_iF0__q_thd - 0.12383458041329967*_d_iF1__q_thd
            + 0.0575898635297681*_d_iF2__q_thd - 0.016129321407969507*_d_iF3__q_thd)
        _d_iPsi0__k_d = (0.582374038291501*_d_iF0__k_d - 0.12383458041329967*_d_iF1__k_d
            + 0.0575898635297681*_d_iF2__k_d - 0.016129321407969507*_d_iF3__k_d)
        _d_iPsi0__guess_q_th = (0.582374038291501*_d_iF0__guess_q_th - 0.12383458041329967*_d_iF1__guess_q_th
            + 0.0575898635297681*_d_iF2__guess_q_th - 0.016129321407969507*_d_iF3__guess_q_th)
        _d_iPsi0__guess_q_thd = (0.582374038291501*_d_iF0__guess_q_thd
            - 0.12383458041329967*_d_iF1__guess_q_thd + 0.0575898635297681*_d_iF2__guess_q_thd
            - 0.016129321407969507*_d_iF3__guess_q_thd)
        _x54 = (1.0/math.sqrt(_x53))
        _x55 = math.sqrt(_D)
        _x56 = math.sqrt(m)
        _x57 = _x55*_x56
        _ift0 = _x54*_x57
        _x58 = (0.5)/_x55
        _x59 = _x56*_x58
        _pd__102 = _x54*_x59
        _x60 = _x53**(-1.5)
        _x61 = (0.5)*_x57
        _pd__103 = -_x60*_x61
        _d_ift0__q_r = _d_D__q_r*_pd__102 + _d_iPsi0__q_r*_pd__103
        _d_ift0__q_th = _d_D__q_th*_pd__102 + _d_iPsi0__q_th*_pd__103
        _d_ift0__q_thd = _d_D__q_thd*_pd__102 + _d_iPsi0__q_thd*_pd__103
        _d_ift0__k_d = _d_D__k_d*_pd__102 + _d_iPsi0__k_d*_pd__103
        _d_ift0__guess_q_th = _d_D__guess_q_th*_pd__102 + _d_iPsi0__guess_q_th*_pd__103
        _d_ift0__guess_q_thd = _d_D__guess_q_thd*_pd__102 + _d_iPsi0__guess_q_thd*_pd__103
        _x62 = (1.0/_x56)
        _x63 = _x55*_x62
        _x64 = _x111**2
        _x65 = _x54*_x64
        _x66 = _x63*_x65
        _ifq0 = _P0*_x66
        _x67 = _x58*_x62
        _pd__104 = _P0*_x65*_x67
        _pd__105 = _x66
        _x68 = (0.5)*_x63
        _pd__106 = -_P0*_x60*_x64*_x68
        _pd__107 = -_x12*_x54*_x63*_x9
        _d_ifq0__q_r = (_d_D__q_r*_pd__104 + _d_P0__q_r*_pd__105 + _d_iPsi0__q_r*_pd__106
            + _d_isigma0__q_r*_pd__107)
        _x69 = 0.004820780989426014*_pd__107
        _d_ifq0__q_th = _d_D__q_th*_pd__104 + _d_D__q_th*_x69 + _d_P0__q_th*_pd__105 + _d_iPsi0__q_th*_pd__106
        _d_ifq0__q_thd = (_d_D__q_thd*_pd__104 + _d_D__q_thd*_x69 + _d_P0__q_thd*_pd__105
            + _d_iPsi0__q_thd*_pd__106)
        _d_ifq0__k_d = _d_D__k_d*_pd__104 + _d_D__k_d*_x69 + _d_P0__k_d*_pd__105 + _d_iPsi0__k_d*_pd__106
        _d_ifq0__guess_q_th = (_d_D__guess_q_th*_pd__104 + _d_D__guess_q_th*_x69 + _d_P0__guess_q_th*_pd__105
            + _d_iPsi0__guess_q_th*_pd__106)
        _d_ifq0__guess_q_thd = (_d_D__guess_q_thd*_pd__104 + _d_D__guess_q_thd*_x69
            + _d_P0__guess_q_thd*_pd__105 + _d_iPsi0__guess_q_thd*_pd__106)
        _x70 = g_s*m**(1.5)
        _x71 = _x55*_x70
        _x72 = _x54*_x71
        _x73 = _x13*_x72
        _ifp0 = _x1*_x73
        _x74 = _x1*_x13
        _x75 = _x58*_x70
        _pd__108 = _x54*_x74*_x75
        _pd__109 = _x1*_x3*_x72
        _x76 = (0.5)*_x71
        _pd__110 = -_x60*_x74*_x76
        _pd__111 = _x73
        _d_ifp0__q_r = (_d_D__q_r*_pd__108 + _d_Q0__q_r*_pd__109 + _d_iPsi0__q_r*_pd__110
            + _d_isigma0__q_r*_pd__111)
        _x77 = 0.004820780989426014*_pd__111
        _d_ifp0__q_th = _d_D__q_th*_pd__108 + _d_D__q_th*_x77 + _d_Q0__q_th*_pd__109 + _d_iPsi0__q_th*_pd__110
        _d_ifp0__q_thd = (_d_D__q_thd*_pd__108 + _d_D__q_thd*_x77 + _d_Q0__q_thd*_pd__109
            + _d_iPsi0__q_thd*_pd__110)
        _d_ifp0__k_d = _d_D__k_d*_pd__108 + _d_D__k_d*_x77 + _d_Q0__k_d*_pd__109 + _d_iPsi0__k_d*_pd__110
        _d_ifp0__guess_q_th = (_d_D__guess_q_th*_pd__108 + _d_D__guess_q_th*_x77 + _d_Q0__guess_q_th*_pd__109
            + _d_iPsi0__guess_q_th*_pd__110)
        _d_ifp0__guess_q_thd = (_d_D__guess_q_thd*_pd__108 + _d_D__guess_q_thd*_x77
            + _d_Q0__guess_q_thd*_pd__109 + _d_iPsi0__guess_q_thd*_pd__110)
        _x78 = (-0.39252437029865583*_x20 - 0.39252437029865583*_x21 + 0.39252437029865583*_x22*_x23*_x8
            + 0.0700094015044783*_x30*k_d + 0.0700094015044783*_x31*g_s*m - 0.0700094015044783*_x37
            - 0.017475652789475504*_x44 - 0.017475652789475504*_x45 + 0.017475652789475504*_x46*_x47*_x8
            - 0.16000937841634696*_x5 - 0.16000937841634696*_x6 + 0.16000937841634696*_x7*_x8*_x9
            + 0.5*k_d*l0)
        _iPsi1 = _x78
        _d_iPsi1__q_r = (0.16000937841634696*_d_iF0__q_r + 0.39252437029865583*_d_iF1__q_r
            - 0.0700094015044783*_d_iF2__q_r + 0.017475652789475504*_d_iF3__q_r)
        _d_iPsi1__q_th = (0.16000937841634696*_d_iF0__q_th + 0.39252437029865583*_d_iF1__q_th
            - 0.0700094015044783*_d_iF2__q_th + 0.017475652789475504*_d_iF3__q_th)
        _d_iPsi1__q_thd = (0.16000937841634696*_d_iF0__q_thd + 0.39252437029865583*_d_iF1__q_thd
            - 0.0700094015044783*_d_iF2__q_thd + 0.017475652789475504*_d_iF3__q_thd)
        _d_iPsi1__k_d = (0.16000937841634696*_d_iF0__k_d + 0.39252437029865583*_d_iF1__k_d
            - 0.0700094015044783*_d_iF2__k_d + 0.017475652789475504*_d_iF3__k_d)
        _d_iPsi1__guess_q_th = (0.16000937841634696*_d_iF0__guess_q_th
            + 0.39252437029865583*_d_iF1__guess_q_th - 0.0700094015044783*_d_iF2__guess_q_th
            + 0.017475652789475504*_d_iF3__guess_q_th)
        _d_iPsi1__guess_q_thd = (0.16000937841634696*_d_iF0__guess_q_thd
            + 0.39252437029865583*_d_iF1__guess_q_thd - 0.0700094015044783*_d_iF2__guess_q_thd
            + 0.017475652789475504*_d_iF3__guess_q_thd)
        _x79 = (1.0/math.sqrt(_x78))
        _ift1 = _x57*_x79
        _pd__112 = _x59*_x79
        _x80 = _x78**(-1.5)
        _pd__113 = -_x61*_x80
        _d_ift1__q_r = _d_D__q_r*_pd__112 + _d_iPsi1__q_r*_pd__113
        _d_ift1__q_th = _d_D__q_th*_pd__112 + _d_iPsi1__q_th*_pd__113
        _d_ift1__q_thd = _d_D__q_thd*_pd__112 + _d_iPsi1__q_thd*_pd__113
        _d_ift1__k_d = _d_D__k_d*_pd__112 + _d_iPsi1__k_d*_pd__113
        _d_ift1__guess_q_th = _d_D__guess_q_th*_pd__112 + _d_iPsi1__guess_q_th*_pd__113
        _d_ift1__guess_q_thd = _d_D__guess_q_thd*_pd__112 + _d_iPsi1__guess_q_thd*_pd__113
        _x81 = _x112**2
        _x82 = _x79*_x81
        _x83 = _x63*_x82
        _ifq1 = _P1*_x83
        _pd__114 = _P1*_x67*_x82
        _pd__115 = _x83
        _pd__116 = -_P1*_x68*_x80*_x81
        _pd__117 = -_x23*_x26*_x63*_x79
        _d_ifq1__q_r = (_d_D__q_r*_pd__114 + _d_P1__q_r*_pd__115 + _d_iPsi1__q_r*_pd__116
            + _d_isigma1__q_r*_pd__117)
        _x84 = 0.10890625570683385*_pd__117
        _d_ifq1__q_th = _d_D__q_th*_pd__114 + _d_D__q_th*_x84 + _d_P1__q_th*_pd__115 + _d_iPsi1__q_th*_pd__116
        _d_ifq1__q_thd = (_d_D__q_thd*_pd__114 + _d_D__q_thd*_x84 + _d_P1__q_thd*_pd__115
            + _d_iPsi1__q_thd*_pd__116)
        _d_ifq1__k_d = _d_D__k_d*_pd__114 + _d_D__k_d*_x84 + _d_P1__k_d*_pd__115 + _d_iPsi1__k_d*_pd__116
        _d_ifq1__guess_q_th = (_d_D__guess_q_th*_pd__114 + _d_D__guess_q_th*_x84 + _d_P1__guess_q_th*_pd__115
            + _d_iPsi1__guess_q_th*_pd__116)
        _d_ifq1__guess_q_thd = (_d_D__guess_q_thd*_pd__114 + _d_D__guess_q_thd*_x84
            + _d_P1__guess_q_thd*_pd__115 + _d_iPsi1__guess_q_thd*_pd__116)
        _x85 = _x71*_x79
        _x86 = _x27*_x85
        _ifp1 = _x18*_x86
        _x87 = _x18*_x27
        _pd__118 = _x75*_x79*_x87
        _pd__119 = _x18*_x19*_x85
        _pd__120 = -_x76*_x80*_x87
        _pd__121 = _x86
        _d_ifp1__q_r = (_d_D__q_r*_pd__118 + _d_Q1__q_r*_pd__119 + _d_iPsi1__q_r*_pd__120
            + _d_isigma1__q_r*_pd__121)
        _x88 = 0.10890625570683385*_pd__121
        _d_ifp1__q_th = _d_D__q_th*_pd__118 + _d_D__q_th*_x88 + _d_Q1__q_th*_pd__119 + _d_iPsi1__q_th*_pd__120
        _d_ifp1__q_thd = (_d_D__q_thd*_pd__118 + _d_D__q_thd*_x88 + _d_Q1__q_thd*_pd__119
            + _d_iPsi1__q_thd*_pd__120)
        _d_ifp1__k_d = _d_D__k_d*_pd__118 + _d_D__k_d*_x88 + _d_Q1__k_d*_pd__119 + _d_iPsi1__k_d*_pd__120
        _d_ifp1__guess_q_th = (_d_D__guess_q_th*_pd__118 + _d_D__guess_q_th*_x88 + _d_Q1__guess_q_th*_pd__119
            + _d_iPsi1__guess_q_th*_pd__120)
        _d_ifp1__guess_q_thd = (_d_D__guess_q_thd*_pd__118 + _d_D__guess_q_thd*_x88
            + _d_Q1__guess_q_thd*_pd__119 + _d_iPsi1__guess_q_thd*_pd__120)
        _x89 = (-0.2848443432415939*_x20 - 0.2848443432415939*_x21 + 0.2848443432415939*_x22*_x23*_x8
            - 0.21871326539550162*_x32 - 0.21871326539550162*_x33 + 0.21871326539550162*_x34*_x35*_x8
            + 0.019694864101090868*_x42*k_d + 0.019694864101090868*_x43*g_s*m - 0.019694864101090868*_x49
            - 0.01613725546399532*_x5 - 0.01613725546399532*_x6 + 0.01613725546399532*_x7*_x8*_x9
            + 0.5*k_d*l0)
        _iPsi2 = _x89
        _d_iPsi2__q_r = (0.01613725546399532*_d_iF0__q_r + 0.2848443432415939*_d_iF1__q_r
            + 0.21871326539550162*_d_iF2__q_r - 0.019694864101090868*_d_iF3__q_r)
        _d_iPsi2__q_th = (0.01613725546399532*_d_iF0__q_th + 0.2848443432415939*_d_iF1__q_th
            + 0.21871326539550162*_d_iF2__q_th - 0.019694864101090868*_d_iF3__q_th)
        _d_iPsi2__q_thd = (0.01613725546399532*_d_iF0__q_thd + 0.2848443432415939*_d_iF1__q_thd
            + 0.21871326539550162*_d_iF2__q_thd - 0.019694864101090868*_d_iF3__q_thd)
        _d_iPsi2__k_d = (0.01613725546399532*_d_iF0__k_d + 0.2848443432415939*_d_iF1__k_d
            + 0.21871326539550162*_d_iF2__k_d - 0.019694864101090868*_d_iF3__k_d)
        _d_iPsi2__guess_q_th = (0.01613725546399532*_d_iF0__guess_q_th + 0.2848443432415939*_d_iF1__guess_q_th
            + 0.21871326539550162*_d_iF2__guess_q_th - 0.019694864101090868*_d_iF3__guess_q_th)
        _d_iPsi2__guess_q_thd = (0.01613725546399532*_d_iF0__guess_q_thd
            + 0.2848443432415939*_d_iF1__guess_q_thd + 0.21871326539550162*_d_iF2__guess_q_thd
            - 0.019694864101090868*_d_iF3__guess_q_thd)
        _x90 = (1.0/math.sqrt(_x89))
        _ift2 = _x57*_x90
        _pd__122 = _x59*_x90
        _x91 = _x89**(-1.5)
        _pd__123 = -_x61*_x91
        _d_ift2__q_r = _d_D__q_r*_pd__122 + _d_iPsi2__q_r*_pd__123
        _d_ift2__q_th = _d_D__q_th*_pd__122 + _d_iPsi2__q_th*_pd__123
        _d_ift2__q_thd = _d_D__q_thd*_pd__122 + _d_iPsi2__q_thd*_pd__123
        _d_ift2__k_d = _d_D__k_d*_pd__122 + _d_iPsi2__k_d*_pd__123
        _d_ift2__guess_q_th = _d_D__guess_q_th*_pd__122 + _d_iPsi2__guess_q_th*_pd__123
        _d_ift2__guess_q_thd = _d_D__guess_q_thd*_pd__122 + _d_iPsi2__guess_q_thd*_pd__123
        _x92 = _x113**2
        _x93 = _x90*_x92
        _x94 = _x63*_x93
        _ifq2 = _P2*_x94
        _pd__124 = _P2*_x67*_x93
        _pd__125 = _x94
        _pd__126 = -_P2*_x68*_x91*_x92
        _pd__127 = -_x35*_x38*_x63*_x90
        _d_ifq2__q_r = (_d_D__q_r*_pd__124 + _d_P2__q_r*_pd__125 + _d_iPsi2__q_r*_pd__126
            + _d_isigma2__q_r*_pd__127)
        _x95 = 0.44888729929169013*_pd__127
        _d_ifq2__q_th = _d_D__q_th*_pd__124 + _d_D__q_th*_x95 + _d_P2__q_th*_pd__125 + _d_iPsi2__q_th*_pd__126
        _d_ifq2__q_thd = (_d_D__q_thd*_pd__124 + _d_D__q_thd*_x95 + _d_P2__q_thd*_pd__125
            + _d_iPsi2__q_thd*_pd__126)
        _d_ifq2__k_d = _d_D__k_d*_pd__124 + _d_D__k_d*_x95 + _d_P2__k_d*_pd__125 + _d_iPsi2__k_d*_pd__126
        _d_ifq2__guess_q_th = (_d_D__guess_q_th*_pd__124 + _d_D__guess_q_th*_x95 + _d_P2__guess_q_th*_pd__125
            + _d_iPsi2__guess_q_th*_pd__126)
        _d_ifq2__guess_q_thd = (_d_D__guess_q_thd*_pd__124 + _d_D__guess_q_thd*_x95
            + _d_P2__guess_q_thd*_pd__125 + _d_iPsi2__guess_q_thd*_pd__126)
        _x96 = _x71*_x90
        _x97 = _x39*_x96
        _ifp2 = _x30*_x97
        _x98 = _x30*_x39
        _pd__128 = _x75*_x90*_x98
        _pd__129 = _x30*_x31*_x96
        _pd__130 = -_x76*_x91*_x98
        _pd__131 = _x97
        _d_ifp2__q_r = (_d_D__q_r*_pd__128 + _d_Q2__q_r*_pd__129 + _d_iPsi2__q_r*_pd__130
            + _d_isigma2__q_r*_pd__131)
        _x99 = 0.44888729929169013*_pd__131
        _d_ifp2__q_th = _d_D__q_th*_pd__128 + _d_D__q_th*_x99 + _d_Q2__q_th*_pd__129 + _d_iPsi2__q_th*_pd__130
        _d_ifp2__q_thd = (_d_D__q_thd*_pd__128 + _d_D__q_thd*_x99 + _d_Q2__q_thd*_pd__129
            + _d_iPsi2__q_thd*_pd__130)
        _d_ifp2__k_d = _d_D__k_d*_pd__128 + _d_D__k_d*_x99 + _d_Q2__k_d*_pd__129 + _d_iPsi2__k_d*_pd__130
        _d_ifp2__guess_q_th = (_d_D__guess_q_th*_pd__128 + _d_D__guess_q_th*_x99 + _d_Q2__guess_q_th*_pd__129
            + _d_iPsi2__guess_q_th*_pd__130)
        _d_ifp2__guess_q_thd = (_d_D__guess_q_thd*_pd__128 + _d_D__guess_q_thd*_x99
            + _d_Q2__guess_q_thd*_pd__129 + _d_iPsi2__guess_q_thd*_pd__130)
        _x100 = (-0.11000222456933441*_x20 - 0.11000222456933441*_x21 + 0.11000222456933441*_x22*_x23*_x8
            - 0.2823150697454702*_x32 - 0.2823150697454702*_x33 + 0.2823150697454702*_x34*_x35*_x8
            - 0.08972165934767481*_x44 - 0.08972165934767481*_x45 + 0.08972165934767481*_x46*_x47*_x8
            - 0.01796104633752054*_x5 - 0.01796104633752054*_x6 + 0.01796104633752054*_x7*_x8*_x9
            + 0.5*k_d*l0)
        _iPsi3 = _x100
        _d_iPsi3__q_r = (0.01796104633752054*_d_iF0__q_r + 0.11000222456933441*_d_iF1__q_r
            + 0.2823150697454702*_d_iF2__q_r + 0.08972165934767481*_d_iF3__q_r)
        _d_iPsi3__q_th = (0.01796104633752054*_d_iF0__q_th + 0.11000222456933441*_d_iF1__q_th
            + 0.2823150697454702*_d_iF2__q_th + 0.08972165934767481*_d_iF3__q_th)
        _d_iPsi3__q_thd = (0.01796104633752054*_d_iF0__q_thd + 0.11000222456933441*_d_iF1__q_thd
            + 0.2823150697454702*_d_iF2__q_thd + 0.08972165934767481*_d_iF3__q_thd)
        _d_iPsi3__k_d = (0.01796104633752054*_d_iF0__k_d + 0.11000222456933441*_d_iF1__k_d
            + 0.2823150697454702*_d_iF2__k_d + 0.08972165934767481*_d_iF3__k_d)
        _d_iPsi3__guess_q_th = (0.01796104633752054*_d_iF0__guess_q_th
            + 0.11000222456933441*_d_iF1__guess_q_th + 0.2823150697454702*_d_iF2__guess_q_th
            + 0.08972165934767481*_d_iF3__guess_q_th)
        _d_iPsi3__guess_q_thd = (0.01796104633752054*_d_iF0__guess_q_thd
            + 0.11000222456933441*_d_iF1__guess_q_thd + 0.2823150697454702*_d_iF2__guess_q_thd
            + 0.08972165934767481*_d_iF3__guess_q_thd)
        _x101 = (1.0/math.sqrt(_x100))
        _ift3 = _x101*_x57
        _pd__132 = _x101*_x59
        _x102 = _x100**(-1.5)
        _pd__133 = -_x102*_x61
        _d_ift3__q_r = _d_D__q_r*_pd__132 + _d_iPsi3__q_r*_pd__133
        _d_ift3__q_th = _d_D__q_th*_pd__132 + _d_iPsi3__q_th*_pd__133
        _d_ift3__q_thd = _d_D__q_thd*_pd__132 + _d_iPsi3__q_thd*_pd__133
        _d_ift3__k_d = _d_D__k_d*_pd__132 + _d_iPsi3__k_d*_pd__133
        _d_ift3__guess_q_th = _d_D__guess_q_th*_pd__132 + _d_iPsi3__guess_q_th*_pd__133
        _d_ift3__guess_q_thd = _d_D__guess_q_thd*_pd__132 + _d_iPsi3__guess_q_thd*_pd__133
        _x103 = _x114**2
        _x104 = _x101*_x103
        _x105 = _x104*_x63
        _ifq3 = _P3*_x105
        _pd__134 = _P3*_x104*_x67
        _pd__135 = _x105
        _pd__136 = -_P3*_x102*_x103*_x68
        _pd__137 = -_x101*_x47*_x50*_x63
        _d_ifq3__q_r = (_d_D__q_r*_pd__134 + _d_P3__q_r*_pd__135 + _d_iPsi3__q_r*_pd__136
            + _d_isigma3__q_r*_pd__137)
        _x106 = 0.8659570925834786*_pd__137
        _d_ifq3__q_th = (_d_D__q_th*_pd__134 + _d_D__q_th*_x106 + _d_P3__q_th*_pd__135
            + _d_iPsi3__q_th*_pd__136)
        _d_ifq3__q_thd = (_d_D__q_thd*_pd__134 + _d_D__q_thd*_x106 + _d_P3__q_thd*_pd__135
            + _d_iPsi3__q_thd*_pd__136)
        _d_ifq3__k_d = _d_D__k_d*_pd__134 + _d_D__k_d*_x106 + _d_P3__k_d*_pd__135 + _d_iPsi3__k_d*_pd__136
        _d_ifq3__guess_q_th = (_d_D__guess_q_th*_pd__134 + _d_D__guess_q_th*_x106 + _d_P3__guess_q_th*_pd__135
            + _d_iPsi3__guess_q_th*_pd__136)
        _d_ifq3__guess_q_thd = (_d_D__guess_q_thd*_pd__134 + _d_D__guess_q_thd*_x106
            + _d_P3__guess_q_thd*_pd__135 + _d_iPsi3__guess_q_thd*_pd__136)
        _x107 = _x101*_x71
        _x108 = _x107*_x51
        _ifp3 = _x108*_x42
        _x109 = _x42*_x51
        _pd__138 = _x101*_x109*_x75
        _pd__139 = _x107*_x42*_x43
        _pd__140 = -_x102*_x109*_x76
        _pd__141 = _x108
        _d_ifp3__q_r = (_d_D__q_r*_pd__138 + _d_Q3__q_r*_pd__139 + _d_iPsi3__q_r*_pd__140
            + _d_isigma3__q_r*_pd__141)
        _x110 = 0.8659570925834786*_pd__141
        _d_ifp3__q_th = (_d_D__q_th*_pd__138 + _d_D__q_th*_x110 + _d_Q3__q_th*_pd__139
            + _d_iPsi3__q_th*_pd__140)
        _d_ifp3__q_thd = (_d_D__q_thd*_pd__138 + _d_D__q_thd*_x110 + _d_Q3__q_thd*_pd__139
            + _d_iPsi3__q_thd*_pd__140)
        _d_ifp3__k_d = _d_D__k_d*_pd__138 + _d_D__k_d*_x110 + _d_Q3__k_d*_pd__139 + _d_iPsi3__k_d*_pd__140
        _d_ifp3__guess_q_th = (_d_D__guess_q_th*_pd__138 + _d_D__guess_q_th*_x110 + _d_Q3__guess_q_th*_pd__139
            + _d_iPsi3__guess_q_th*_pd__140)
        _d_ifp3__guess_q_thd = (_d_D__guess_q_thd*_pd__138 + _d_D__guess_q_thd*_x110
            + _d_Q3__guess_q_thd*_pd__139 + _d_iPsi3__guess_q_thd*_pd__140)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = (0.08696371128436346*_ifq0 - 0.026604180084998794*_ifq1 + 0.012627462689404725*_ifq2
            - 0.0035551496857956833*_ifq3 + q_th)
        _d_Q0__next__q_r = (0.08696371128436346*_d_ifq0__q_r - 0.026604180084998794*_d_ifq1__q_r
            + 0.012627462689404725*_d_ifq2__q_r - 0.0035551496857956833*_d_ifq3__q_r)
        _d_Q0__next__q_th = (0.08696371128436346*_d_ifq0__q_th - 0.026604180084998794*_d_ifq1__q_th
            + 0.012627462689404725*_d_ifq2__q_th - 0.0035551496857956833*_d_ifq3__q_th + 1.0)
        _d_Q0__next__q_thd = (0.08696371128436346*_d_ifq0__q_thd - 0.026604180084998794*_d_ifq1__q_thd
            + 0.012627462689404725*_d_ifq2__q_thd - 0.0035551496857956833*_d_ifq3__q_thd)
        _d_Q0__next__k_d = (0.08696371128436346*_d_ifq0__k_d - 0.026604180084998794*_d_ifq1__k_d
            + 0.012627462689404725*_d_ifq2__k_d - 0.0035551496857956833*_d_ifq3__k_d)
        _d_Q0__next__guess_q_th = (0.08696371128436346*_d_ifq0__guess_q_th
            - 0.026604180084998794*_d_ifq1__guess_q_th + 0.012627462689404725*_d_ifq2__guess_q_th
            - 0.0035551496857956833*_d_ifq3__guess_q_th)
        _d_Q0__next__guess_q_thd = (0.08696371128436346*_d_ifq0__guess_q_thd
            - 0.026604180084998794*_d_ifq1__guess_q_thd + 0.012627462689404725*_d_ifq2__guess_q_thd
            - 0.0035551496857956833*_d_ifq3__guess_q_thd)
        _Q1__next = (0.18811811749986806*_ifq0 + 0.16303628871563652*_ifq1 - 0.027880428602470895*_ifq2
            + 0.006735500594538156*_ifq3 + q_th)
        _d_Q1__next__q_r = (0.18811811749986806*_d_ifq0__q_r + 0.16303628871563652*_d_ifq1__q_r
            - 0.027880428602470895*_d_ifq2__q_r + 0.006735500594538156*_d_ifq3__q_r)
        _d_Q1__next__q_th = (0.18811811749986806*_d_ifq0__q_th + 0.16303628871563652*_d_ifq1__q_th
            - 0.027880428602470895*_d_ifq2__q_th + 0.006735500594538156*_d_ifq3__q_th + 1.0)
        _d_Q1__next__q_thd = (0.18811811749986806*_d_ifq0__q_thd + 0.16303628871563652*_d_ifq1__q_thd
            - 0.027880428602470895*_d_ifq2__q_thd + 0.006735500594538156*_d_ifq3__q_thd)
        _d_Q1__next__k_d = (0.18811811749986806*_d_ifq0__k_d + 0.16303628871563652*_d_ifq1__k_d
            - 0.027880428602470895*_d_ifq2__k_d + 0.006735500594538156*_d_ifq3__k_d)
        _d_Q1__next__guess_q_th = (0.18811811749986806*_d_ifq0__guess_q_th
            + 0.16303628871563652*_d_ifq1__guess_q_th - 0.027880428602470895*_d_ifq2__guess_q_th
            + 0.006735500594538156*_d_ifq3__guess_q_th)
        _d_Q1__next__guess_q_thd = (0.18811811749986806*_d_ifq0__guess_q_thd
            + 0.16303628871563652*_d_ifq1__guess_q_thd - 0.027880428602470895*_d_ifq2__guess_q_thd
            + 0.006735500594538156*_d_ifq3__guess_q_thd)
        _Q2__next = (0.16719192197418878*_ifq0 + 0.35395300603374397*_ifq1 + 0.16303628871563652*_ifq2
            - 0.014190694931141144*_ifq3 + q_th)
        _d_Q2__next__q_r = (0.16719192197418878*_d_ifq0__q_r + 0.35395300603374397*_d_ifq1__q_r
            + 0.16303628871563652*_d_ifq2__q_r - 0.014190694931141144*_d_ifq3__q_r)
        _d_Q2__next__q_th = (0.16719192197418878*_d_ifq0__q_th + 0.35395300603374397*_d_ifq1__q_th
            + 0.16303628871563652*_d_ifq2__q_th - 0.014190694931141144*_d_ifq3__q_th + 1.0)
        _d_Q2__next__q_thd = (0.16719192197418878*_d_ifq0__q_thd + 0.35395300603374397*_d_ifq1__q_thd
            + 0.16303628871563652*_d_ifq2__q_thd - 0.014190694931141144*_d_ifq3__q_thd)
        _d_Q2__next__k_d = (0.16719192197418878*_d_ifq0__k_d + 0.35395300603374397*_d_ifq1__k_d
            + 0.16303628871563652*_d_ifq2__k_d - 0.014190694931141144*_d_ifq3__k_d)
        _d_Q2__next__guess_q_th = (0.16719192197418878*_d_ifq0__guess_q_th
            + 0.35395300603374397*_d_ifq1__guess_q_th + 0.16303628871563652*_d_ifq2__guess_q_th
            - 0.014190694931141144*_d_ifq3__guess_q_th)
        _d_Q2__next__guess_q_thd = (0.16719192197418878*_d_ifq0__guess_q_thd
            + 0.35395300603374397*_d_ifq1__guess_q_thd + 0.16303628871563652*_d_ifq2__guess_q_thd
            - 0.014190694931141144*_d_ifq3__guess_q_thd)
        _Q3__next = (0.1774825722545226*_ifq0 + 0.31344511474186837*_ifq1 + 0.35267675751627187*_ifq2
            + 0.08696371128436346*_ifq3 + q_th)
        _d_Q3__next__q_r = (0.1774825722545226*_d_ifq0__q_r + 0.31344511474186837*_d_ifq1__q_r
            + 0.35267675751627187*_d_ifq2__q_r + 0.08696371128436346*_d_ifq3__q_r)
        _d_Q3__next__q_th = (0.1774825722545226*_d_ifq0__q_th + 0.31344511474186837*_d_ifq1__q_th
            + 0.35267675751627187*_d_ifq2__q_th + 0.08696371128436346*_d_ifq3__q_th + 1.0)
        _d_Q3__next__q_thd = (0.1774825722545226*_d_ifq0__q_thd + 0.31344511474186837*_d_ifq1__q_thd
            + 0.35267675751627187*_d_ifq2__q_thd + 0.08696371128436346*_d_ifq3__q_thd)
        _d_Q3__next__k_d = (0.1774825722545226*_d_ifq0__k_d + 0.31344511474186837*_d_ifq1__k_d
            + 0.35267675751627187*_d_ifq2__k_d + 0.08696371128436346*_d_ifq3__k_d)
        _d_Q3__next__guess_q_th = (0.1774825722545226*_d_ifq0__guess_q_th
            + 0.31344511474186837*_d_ifq1__guess_q_th + 0.35267675751627187*_d_ifq2__guess_q_th
            + 0.08696371128436346*_d_ifq3__guess_q_th)
        _d_Q3__next__guess_q_thd = (0.1774825722545226*_d_ifq0__guess_q_thd
            + 0.31344511474186837*_d_ifq1__guess_q_thd + 0.35267675751627187*_d_ifq2__guess_q_thd
            + 0.08696371128436346*_d_ifq3__guess_q_thd)
        _x115 = m*q_r**2
        _x116 = _x115*q_thd
        _P0__next = (0.08696371128436346*_ifp0 - 0.026604180084998794*_ifp1 + 0.012627462689404725*_ifp2
            - 0.0035551496857956833*_ifp3 + _x116)
        _x117 = 2.0*m*q_r*q_thd
        _d_P0__next__q_r = (0.08696371128436346*_d_ifp0__q_r - 0.026604180084998794*_d_ifp1__q_r
            + 0.012627462689404725*_d_ifp2__q_r - 0.0035551496857956833*_d_ifp3__q_r + _x117)
        _d_P0__next__q_th = (0.08696371128436346*_d_ifp0__q_th - 0.026604180084998794*_d_ifp1__q_th
            + 0.012627462689404725*_d_ifp2__q_th - 0.0035551496857956833*_d_ifp3__q_th)
        _d_P0__next__q_thd = (0.08696371128436346*_d_ifp0__q_thd - 0.026604180084998794*_d_ifp1__q_thd
            + 0.012627462689404725*_d_ifp2__q_thd - 0.0035551496857956833*_d_ifp3__q_thd + _x115)
        _d_P0__next__k_d = (0.08696371128436346*_d_ifp0__k_d - 0.026604180084998794*_d_ifp1__k_d
            + 0.012627462689404725*_d_ifp2__k_d - 0.0035551496857956833*_d_ifp3__k_d)
        _d_P0__next__guess_q_th = (0.08696371128436346*_d_ifp0__guess_q_th
            - 0.026604180084998794*_d_ifp1__guess_q_th + 0.012627462689404725*_d_ifp2__guess_q_th
            - 0.0035551496857956833*_d_ifp3__guess_q_th)
        _d_P0__next__guess_q_thd = (0.08696371128436346*_d_ifp0__guess_q_thd
            - 0.026604180084998794*_d_ifp1__guess_q_thd + 0.012627462689404725*_d_ifp2__guess_q_thd
            - 0.0035551496857956833*_d_ifp3__guess_q_thd)
        _P1__next = (0.18811811749986806*_ifp0 + 0.16303628871563652*_ifp1 - 0.027880428602470895*_ifp2
            + 0.006735500594538156*_ifp3 + _x116)
        _d_P1__next__q_r = (0.18811811749986806*_d_ifp0__q_r + 0.16303628871563652*_d_ifp1__q_r
            - 0.027880428602470895*_d_ifp2__q_r + 0.006735500594538156*_d_ifp3__q_r + _x117)
        _d_P1__next__q_th = (0.18811811749986806*_d_ifp0__q_th + 0.16303628871563652*_d_ifp1__q_th
            - 0.027880428602470895*_d_ifp2__q_th + 0.006735500594538156*_d_ifp3__q_th)
        _d_P1__next__q_thd = (0.18811811749986806*_d_ifp0__q_thd + 0.16303628871563652*_d_ifp1__q_thd
            - 0.027880428602470895*_d_ifp2__q_thd + 0.006735500594538156*_d_ifp3__q_thd + _x115)
        _d_P1__next__k_d = (0.18811811749986806*_d_ifp0__k_d + 0.16303628871563652*_d_ifp1__k_d
            - 0.027880428602470895*_d_ifp2__k_d + 0.006735500594538156*_d_ifp3__k_d)
        _d_P1__next__guess_q_th = (0.18811811749986806*_d_ifp0__guess_q_th
            + 0.16303628871563652*_d_ifp1__guess_q_th - 0.027880428602470895*_d_ifp2__guess_q_th
            + 0.006735500594538156*_d_ifp3__guess_q_th)
        _d_P1__next__guess_q_thd = (0.18811811749986806*_d_ifp0__guess_q_thd
            + 0.16303628871563652*_d_ifp1__guess_q_thd - 0.027880428602470895*_d_ifp2__guess_q_thd
            + 0.006735500594538156*_d_ifp3__guess_q_thd)
        _P2__next = (0.16719192197418878*_ifp0 + 0.35395300603374397*_ifp1 + 0.16303628871563652*_ifp2
            - 0.014190694931141144*_ifp3 + _x116)
        _d_P2__next__q_r = (0.16719192197418878*_d_ifp0__q_r + 0.35395300603374397*_d_ifp1__q_r
            + 0.16303628871563652*_d_ifp2__q_r - 0.014190694931141144*_d_ifp3__q_r + _x117)
        _d_P2__next__q_th = (0.16719192197418878*_d_ifp0__q_th + 0.35395300603374397*_d_ifp1__q_th
            + 0.16303628871563652*_d_ifp2__q_th - 0.014190694931141144*_d_ifp3__q_th)
        _d_P2__next__q_thd = (0.16719192197418878*_d_ifp0__q_thd + 0.35395300603374397*_d_ifp1__q_thd
            + 0.16303628871563652*_d_ifp2__q_thd - 0.014190694931141144*_d_ifp3__q_thd + _x115)
        _d_P2__next__k_d = (0.16719192197418878*_d_ifp0__k_d + 0.35395300603374397*_d_ifp1__k_d
            + 0.16303628871563652*_d_ifp2__k_d - 0.014190694931141144*_d_ifp3__k_d)
        _d_P2__next__guess_q_th = (0.16719192197418878*_d_ifp0__guess_q_th
            + 0.35395300603374397*_d_ifp1__guess_q_th + 0.16303628871563652*_d_ifp2__guess_q_th
            - 0.014190694931141144*_d_ifp3__guess_q_th)
        _d_P2__next__guess_q_thd = (0.16719192197418878*_d_ifp0__guess_q_thd
            + 0.35395300603374397*_d_ifp1__guess_q_thd + 0.16303628871563652*_d_ifp2__guess_q_thd
            - 0.014190694931141144*_d_ifp3__guess_q_thd)
        _P3__next = (0.1774825722545226*_ifp0 + 0.31344511474186837*_ifp1 + 0.35267675751627187*_ifp2
            + 0.08696371128436346*_ifp3 + _x116)
        _d_P3__next__q_r = (0.1774825722545226*_d_ifp0__q_r + 0.31344511474186837*_d_ifp1__q_r
            + 0.35267675751627187*_d_ifp2__q_r + 0.08696371128436346*_d_ifp3__q_r + _x117)
        _d_P3__next__q_th = (0.1774825722545226*_d_ifp0__q_th + 0.31344511474186837*_d_ifp1__q_th
            + 0.35267675751627187*_d_ifp2__q_th + 0.08696371128436346*_d_ifp3__q_th)
        _d_P3__next__q_thd = (0.1774825722545226*_d_ifp0__q_thd + 0.31344511474186837*_d_ifp1__q_thd
            + 0.35267675751627187*_d_ifp2__q_thd + 0.08696371128436346*_d_ifp3__q_thd + _x115)
        _d_P3__next__k_d = (0.1774825722545226*_d_ifp0__k_d + 0.31344511474186837*_d_ifp1__k_d
            + 0.35267675751627187*_d_ifp2__k_d + 0.08696371128436346*_d_ifp3__k_d)
        _d_P3__next__guess_q_th = (0.1774825722545226*_d_ifp0__guess_q_th
            + 0.31344511474186837*_d_ifp1__guess_q_th + 0.35267675751627187*_d_ifp2__guess_q_th
            + 0.08696371128436346*_d_ifp3__guess_q_th)
        _d_P3__next__guess_q_thd = (0.1774825722545226*_d_ifp0__guess_q_thd
            + 0.31344511474186837*_d_ifp1__guess_q_thd + 0.35267675751627187*_d_ifp2__guess_q_thd
            + 0.08696371128436346*_d_ifp3__guess_q_thd)
        _n0_9 = _d_D__q_r
        _n0_10 = _d_D__q_th
        _n0_11 = _d_D__q_thd
        _n0_12 = _d_D__k_d
        _n0_13 = _d_D__guess_q_th
        _n0_14 = _d_D__guess_q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_Q2__next - _Q2) <= tol*(1.0)) and (abs(_Q3__next
            - _Q3) <= tol*(1.0)) and (abs(_P0__next - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))) and (abs(_P1__next - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))) and (abs(_P2__next - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))) and (abs(_P3__next - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _Q2__next, _Q3__next, _P0__next, _P1__next, _P2__next,
            _P3__next, _n0_9, _n0_10, _n0_11, _n0_12, _n0_13, _n0_14, _d_Q0__next__q_r, _d_Q0__next__q_th,
            _d_Q0__next__q_thd, _d_Q0__next__k_d, _d_Q0__next__guess_q_th, _d_Q0__next__guess_q_thd,
            _d_Q1__next__q_r, _d_Q1__next__q_th, _d_Q1__next__q_thd, _d_Q1__next__k_d,
            _d_Q1__next__guess_q_th, _d_Q1__next__guess_q_thd, _d_Q2__next__q_r, _d_Q2__next__q_th,
            _d_Q2__next__q_thd, _d_Q2__next__k_d, _d_Q2__next__guess_q_th, _d_Q2__next__guess_q_thd,
            _d_Q3__next__q_r, _d_Q3__next__q_th, _d_Q3__next__q_thd, _d_Q3__next__k_d,
            _d_Q3__next__guess_q_th, _d_Q3__next__guess_q_thd, _d_P0__next__q_r, _d_P0__next__q_th,
            _d_P0__next__q_thd, _d_P0__next__k_d, _d_P0__next__guess_q_th, _d_P0__next__guess_q_thd,
            _d_P1__next__q_r, _d_P1__next__q_th, _d_P1__next__q_thd, _d_P1__next__k_d,
            _d_P1__next__guess_q_th, _d_P1__next__guess_q_thd, _d_P2__next__q_r, _d_P2__next__q_th,
            _d_P2__next__q_thd, _d_P2__next__k_d, _d_P2__next__guess_q_th, _d_P2__next__guess_q_thd,
            _d_P3__next__q_r, _d_P3__next__q_th, _d_P3__next__q_thd, _d_P3__next__k_d,
            _d_P3__next__guess_q_th, _d_P3__next__guess_q_thd, )
        _pk0 = _pkn0
        _passes += 1.0
    _work = (0.012076101706416622*_iF0 + 0.1076070411358925*_iF1 + 0.21846553629538057*_iF2
        + 0.1618513208623103*_iF3)
    _d_work__q_r = (0.012076101706416622*_d_iF0__q_r + 0.1076070411358925*_d_iF1__q_r
        + 0.21846553629538057*_d_iF2__q_r + 0.1618513208623103*_d_iF3__q_r)
    _d_work__q_th = (0.012076101706416622*_d_iF0__q_th + 0.1076070411358925*_d_iF1__q_th
        + 0.21846553629538057*_d_iF2__q_th + 0.1618513208623103*_d_iF3__q_th)
    _d_work__q_thd = (0.012076101706416622*_d_iF0__q_thd + 0.1076070411358925*_d_iF1__q_thd
        + 0.21846553629538057*_d_iF2__q_thd + 0.1618513208623103*_d_iF3__q_thd)
    _d_work__k_d = (0.012076101706416622*_d_iF0__k_d + 0.1076070411358925*_d_iF1__k_d
        + 0.21846553629538057*_d_iF2__k_d + 0.1618513208623103*_d_iF3__k_d)
    _d_work__guess_q_th = (0.012076101706416622*_d_iF0__guess_q_th + 0.1076070411358925*_d_iF1__guess_q_th
        + 0.21846553629538057*_d_iF2__guess_q_th + 0.1618513208623103*_d_iF3__guess_q_th)
    _d_work__guess_q_thd = (0.012076101706416622*_d_iF0__guess_q_thd + 0.1076070411358925*_d_iF1__guess_q_thd
        + 0.21846553629538057*_d_iF2__guess_q_thd + 0.1618513208623103*_d_iF3__guess_q_thd)
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = (0.17392742256872692*_ift0 + 0.32607257743127305*_ift1 + 0.32607257743127305*_ift2
        + 0.17392742256872692*_ift3)
    d_t_half__q_r = (0.17392742256872692*_d_ift0__q_r + 0.32607257743127305*_d_ift1__q_r
        + 0.32607257743127305*_d_ift2__q_r + 0.17392742256872692*_d_ift3__q_r)
    d_t_half__q_th = (0.17392742256872692*_d_ift0__q_th + 0.32607257743127305*_d_ift1__q_th
        + 0.32607257743127305*_d_ift2__q_th + 0.17392742256872692*_d_ift3__q_th)
    d_t_half__q_thd = (0.17392742256872692*_d_ift0__q_thd + 0.32607257743127305*_d_ift1__q_thd
        + 0.32607257743127305*_d_ift2__q_thd + 0.17392742256872692*_d_ift3__q_thd)
    d_t_half__k_d = (0.17392742256872692*_d_ift0__k_d + 0.32607257743127305*_d_ift1__k_d
        + 0.32607257743127305*_d_ift2__k_d + 0.17392742256872692*_d_ift3__k_d)
    d_t_half__guess_q_th = (0.17392742256872692*_d_ift0__guess_q_th + 0.32607257743127305*_d_ift1__guess_q_th
        + 0.32607257743127305*_d_ift2__guess_q_th + 0.17392742256872692*_d_ift3__guess_q_th)
    d_t_half__guess_q_thd = (0.17392742256872692*_d_ift0__guess_q_thd
        + 0.32607257743127305*_d_ift1__guess_q_thd + 0.32607257743127305*_d_ift2__guess_q_thd
        + 0.17392742256872692*_d_ift3__guess_q_thd)
    end_q_th = (0.17392742256872692*_ifq0 + 0.32607257743127305*_ifq1 + 0.32607257743127305*_ifq2
        + 0.17392742256872692*_ifq3 + q_th)
    d_end_q_th__q_r = (0.17392742256872692*_d_ifq0__q_r + 0.32607257743127305*_d_ifq1__q_r
        + 0.32607257743127305*_d_ifq2__q_r + 0.17392742256872692*_d_ifq3__q_r)
    d_end_q_th__q_th = (0.17392742256872692*_d_ifq0__q_th + 0.32607257743127305*_d_ifq1__q_th
        + 0.32607257743127305*_d_ifq2__q_th + 0.17392742256872692*_d_ifq3__q_th + 1.0)
    d_end_q_th__q_thd = (0.17392742256872692*_d_ifq0__q_thd + 0.32607257743127305*_d_ifq1__q_thd
        + 0.32607257743127305*_d_ifq2__q_thd + 0.17392742256872692*_d_ifq3__q_thd)
    d_end_q_th__k_d = (0.17392742256872692*_d_ifq0__k_d + 0.32607257743127305*_d_ifq1__k_d
        + 0.32607257743127305*_d_ifq2__k_d + 0.17392742256872692*_d_ifq3__k_d)
    d_end_q_th__guess_q_th = (0.17392742256872692*_d_ifq0__guess_q_th
        + 0.32607257743127305*_d_ifq1__guess_q_th + 0.32607257743127305*_d_ifq2__guess_q_th
        + 0.17392742256872692*_d_ifq3__guess_q_th)
    d_end_q_th__guess_q_thd = (0.17392742256872692*_d_ifq0__guess_q_thd
        + 0.32607257743127305*_d_ifq1__guess_q_thd + 0.32607257743127305*_d_ifq2__guess_q_thd
        + 0.17392742256872692*_d_ifq3__guess_q_thd)
    end_q_r = q_r_lo
    _x118 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x118
    _pd__142 = _x118/_D
    _pd__143 = _x118/_work
    d_end_q_rd__q_r = _d_D__q_r*_pd__142 + _d_work__q_r*_pd__143
    d_end_q_rd__q_th = _d_D__q_th*_pd__142 + _d_work__q_th*_pd__143
    d_end_q_rd__q_thd = _d_D__q_thd*_pd__142 + _d_work__q_thd*_pd__143
    d_end_q_rd__k_d = _d_D__k_d*_pd__142 + _d_work__k_d*_pd__143
    d_end_q_rd__guess_q_th = _d_D__guess_q_th*_pd__142 + _d_work__guess_q_th*_pd__143
    d_end_q_rd__guess_q_thd = _d_D__guess_q_thd*_pd__142 + _d_work__guess_q_thd*_pd__143
    _x119 = q_r**2
    _x120 = q_r_lo**-2
    _x121 = _x120/m
    end_q_thd = (_x121*(0.17392742256872692*_ifp0 + 0.32607257743127305*_ifp1 + 0.32607257743127305*_ifp2
        + 0.17392742256872692*_ifp3 + _x119*m*q_thd))
    _x122 = 0.17392742256872692*_x121
    _pd__144 = _x122
    _x123 = 0.32607257743127305*_x121
    _pd__145 = _x123
    _pd__146 = _x123
    _pd__147 = _x122
    d_end_q_thd__q_r = (_d_ifp0__q_r*_pd__144 + _d_ifp1__q_r*_pd__145 + _d_ifp2__q_r*_pd__146
        + _d_ifp3__q_r*_pd__147 + 2.0*_x120*q_r*q_thd)
    d_end_q_thd__q_th = (_d_ifp0__q_th*_pd__144 + _d_ifp1__q_th*_pd__145 + _d_ifp2__q_th*_pd__146
        + _d_ifp3__q_th*_pd__147)
    d_end_q_thd__q_thd = (_d_ifp0__q_thd*_pd__144 + _d_ifp1__q_thd*_pd__145 + _d_ifp2__q_thd*_pd__146
        + _d_ifp3__q_thd*_pd__147 + _x119*_x120)
    d_end_q_thd__k_d = (_d_ifp0__k_d*_pd__144 + _d_ifp1__k_d*_pd__145 + _d_ifp2__k_d*_pd__146
        + _d_ifp3__k_d*_pd__147)
    d_end_q_thd__guess_q_th = (_d_ifp0__guess_q_th*_pd__144 + _d_ifp1__guess_q_th*_pd__145
        + _d_ifp2__guess_q_th*_pd__146 + _d_ifp3__guess_q_th*_pd__147)
    d_end_q_thd__guess_q_thd = (_d_ifp0__guess_q_thd*_pd__144 + _d_ifp1__guess_q_thd*_pd__145
        + _d_ifp2__guess_q_thd*_pd__146 + _d_ifp3__guess_q_thd*_pd__147)
    passes = _passes
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
        d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
        d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd,
        d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_4(g_s, guess_q_th, guess_q_thd,
        iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol):
    """Branch nodes = 4 of schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd (outlined:
    derive/outline.py).

    Arguments: the caller's variables of the same names.

    Returns a tuple:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 3199
    # Picard passes on the 6 node values (collocation in u)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (-q_r + q_r_lo, 0.03376524289842399*guess_q_th + 0.966234757101576*q_th,
        0.16939530676686773*guess_q_th + 0.8306046932331322*q_th, 0.38069040695840156*guess_q_th
        + 0.6193095930415985*q_th, 0.6193095930415985*guess_q_th + 0.38069040695840156*q_th,
        0.8306046932331322*guess_q_th + 0.16939530676686773*q_th, 0.966234757101576*guess_q_th
        + 0.03376524289842399*q_th, 0.03376524289842399*guess_q_thd*m*q_r_lo**2
        + 0.966234757101576*m*q_r**2*q_thd, 0.16939530676686773*guess_q_thd*m*q_r_lo**2
        + 0.8306046932331322*m*q_r**2*q_thd, 0.38069040695840156*guess_q_thd*m*q_r_lo**2
        + 0.6193095930415985*m*q_r**2*q_thd, 0.6193095930415985*guess_q_thd*m*q_r_lo**2
        + 0.38069040695840156*m*q_r**2*q_thd, 0.8306046932331322*guess_q_thd*m*q_r_lo**2
        + 0.16939530676686773*m*q_r**2*q_thd, 0.966234757101576*guess_q_thd*m*q_r_lo**2
        + 0.03376524289842399*m*q_r**2*q_thd, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.966234757101576, 0.0, 0.0,
        0.03376524289842399, 0.0, 0.0, 0.8306046932331322, 0.0, 0.0, 0.16939530676686773, 0.0, 0.0,
        0.6193095930415985, 0.0, 0.0, 0.38069040695840156, 0.0, 0.0, 0.38069040695840156, 0.0, 0.0,
        0.6193095930415985, 0.0, 0.0, 0.16939530676686773, 0.0, 0.0, 0.8306046932331322, 0.0, 0.0,
        0.03376524289842399, 0.0, 0.0, 0.966234757101576, 0.0, 1.932469514203152*m*q_r*q_thd, 0.0,
        0.966234757101576*m*q_r**2, 0.0, 0.0, 0.03376524289842399*m*q_r_lo**2, 1.6612093864662645*m*q_r*q_thd,
        0.0, 0.8306046932331322*m*q_r**2, 0.0, 0.0, 0.16939530676686773*m*q_r_lo**2,
        1.238619186083197*m*q_r*q_thd, 0.0, 0.6193095930415985*m*q_r**2, 0.0, 0.0,
        0.38069040695840156*m*q_r_lo**2, 0.7613808139168031*m*q_r*q_thd, 0.0, 0.38069040695840156*m*q_r**2,
        0.0, 0.0, 0.6193095930415985*m*q_r_lo**2, 0.33879061353373546*m*q_r*q_thd, 0.0,
        0.16939530676686773*m*q_r**2, 0.0, 0.0, 0.8306046932331322*m*q_r_lo**2,
        0.06753048579684798*m*q_r*q_thd, 0.0, 0.03376524289842399*m*q_r**2, 0.0, 0.0,
        0.966234757101576*m*q_r_lo**2, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (_D, _Q0, _Q1, _Q2, _Q3, _Q4, _Q5, _P0, _P1, _P2, _P3, _P4, _P5, _d_D__q_r, _d_D__q_th, _d_D__q_thd,
            _d_D__k_d, _d_D__guess_q_th, _d_D__guess_q_thd, _d_Q0__q_r, _d_Q0__q_th, _d_Q0__q_thd, _d_Q0__k_d,
            _d_Q0__guess_q_th, _d_Q0__guess_q_thd, _d_Q1__q_r, _d_Q1__q_th, _d_Q1__q_thd, _d_Q1__k_d,
            _d_Q1__guess_q_th, _d_Q1__guess_q_thd, _d_Q2__q_r, _d_Q2__q_th, _d_Q2__q_thd, _d_Q2__k_d,
            _d_Q2__guess_q_th, _d_Q2__guess_q_thd, _d_Q3__q_r, _d_Q3__q_th, _d_Q3__q_thd, _d_Q3__k_d,
            _d_Q3__guess_q_th, _d_Q3__guess_q_thd, _d_Q4__q_r, _d_Q4__q_th, _d_Q4__q_thd, _d_Q4__k_d,
            _d_Q4__guess_q_th, _d_Q4__guess_q_thd, _d_Q5__q_r, _d_Q5__q_th, _d_Q5__q_thd, _d_Q5__k_d,
            _d_Q5__guess_q_th, _d_Q5__guess_q_thd, _d_P0__q_r, _d_P0__q_th, _d_P0__q_thd, _d_P0__k_d,
            _d_P0__guess_q_th, _d_P0__guess_q_thd, _d_P1__q_r, _d_P1__q_th, _d_P1__q_thd, _d_P1__k_d,
            _d_P1__guess_q_th, _d_P1__guess_q_thd, _d_P2__q_r, _d_P2__q_th, _d_P2__q_thd, _d_P2__k_d,
            _d_P2__guess_q_th, _d_P2__guess_q_thd, _d_P3__q_r, _d_P3__q_th, _d_P3__q_thd, _d_P3__k_d,
            _d_P3__guess_q_th, _d_P3__guess_q_thd, _d_P4__q_r, _d_P4__q_th, _d_P4__q_thd, _d_P4__k_d,
            _d_P4__guess_q_th, _d_P4__guess_q_thd, _d_P5__q_r, _d_P5__q_th, _d_P5__q_thd, _d_P5__k_d,
            _d_P5__guess_q_th, _d_P5__guess_q_thd, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.0011400916279895713*_D
        _x1 = _x0 + q_r
        _isigma0 = _x1
        _d_isigma0__q_r = 0.0011400916279895713*_d_D__q_r + 1.0
        _x2 = k_d*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_d
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x159 = (1.0/_x1)
        _x9 = _x159**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__148 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__149 = _x13*_x4
        _x14 = 3.0*_x8
        _pd__150 = -_x14*_x159**4*_x7 - k_d
        _d_iF0__q_r = _d_P0__q_r*_pd__148 + _d_Q0__q_r*_pd__149 + _d_isigma0__q_r*_pd__150
        _x15 = 0.0011400916279895713*_pd__150
        _d_iF0__q_th = _d_D__q_th*_x15 + _d_P0__q_th*_pd__148 + _d_Q0__q_th*_pd__149
        _d_iF0__q_thd = _d_D__q_thd*_x15 + _d_P0__q_thd*_pd__148 + _d_Q0__q_thd*_pd__149
        _x16 = l0 - q_r
        _d_iF0__k_d = _d_D__k_d*_x15 + _d_P0__k_d*_pd__148 + _d_Q0__k_d*_pd__149 - _x0 + _x16
        _d_iF0__guess_q_th = _d_D__guess_q_th*_x15 + _d_P0__guess_q_th*_pd__148 + _d_Q0__guess_q_th*_pd__149
        _d_iF0__guess_q_thd = (_d_D__guess_q_thd*_x15 + _d_P0__guess_q_thd*_pd__148
            + _d_Q0__guess_q_thd*_pd__149)
        _x17 = 0.02869476995464123*_D
        _x18 = _x17 + q_r
        _isigma1 = _x18
        _d_isigma1__q_r = 0.02869476995464123*_d_D__q_r + 1.0
        _x19 = math.cos(_Q1)
        _x20 = _x19*_x4
        _x21 = _x18*k_d
        _x22 = _P1**2
        _x160 = (1.0/_x18)
        _x23 = _x160**3
        _x24 = _x23*_x8
        _x25 = _x22*_x24
        _iF1 = _x2 - _x20 - _x21 + _x25
        _x26 = 2.0*_P1
        _pd__151 = _x24*_x26
        _x27 = math.sin(_Q1)
        _pd__152 = _x27*_x4
        _pd__153 = -_x14*_x160**4*_x22 - k_d
        _d_iF1__q_r = _d_P1__q_r*_pd__151 + _d_Q1__q_r*_pd__152 + _d_isigma1__q_r*_pd__153
        _x28 = 0.02869476995464123*_pd__153
        _d_iF1__q_th = _d_D__q_th*_x28 + _d_P1__q_th*_pd__151 + _d_Q1__q_th*_pd__152
        _d_iF1__q_thd = _d_D__q_thd*_x28 + _d_P1__q_thd*_pd__151 + _d_Q1__q_thd*_pd__152
        _d_iF1__k_d = _d_D__k_d*_x28 + _d_P1__k_d*_pd__151 + _d_Q1__k_d*_pd__152 + _x16 - _x17
        _d_iF1__guess_q_th = _d_D__guess_q_th*_x28 + _d_P1__guess_q_th*_pd__151 + _d_Q1__guess_q_th*_pd__152
        _d_iF1__guess_q_thd = (_d_D__guess_q_thd*_x28 + _d_P1__guess_q_thd*_pd__151
            + _d_Q1__guess_q_thd*_pd__152)
        _x29 = 0.14492518595015338*_D
        _x30 = _x29 + q_r
        _isigma2 = _x30
        _d_isigma2__q_r = 0.14492518595015338*_d_D__q_r + 1.0
        _x31 = math.cos(_Q2)
        _x32 = _x31*_x4
        _x33 = _x30*k_d
        _x34 = _P2**2
        _x161 = (1.0/_x30)
        _x35 = _x161**3
        _x36 = _x35*_x8
        _x37 = _x34*_x36
        _iF2 = _x2 - _x32 - _x33 + _x37
        _x38 = 2.0*_P2
        _pd__154 = _x36*_x38
        _x39 = math.sin(_Q2)
        _pd__155 = _x39*_x4
        _pd__156 = -_x14*_x161**4*_x34 - k_d
        _d_iF2__q_r = _d_P2__q_r*_pd__154 + _d_Q2__q_r*_pd__155 + _d_isigma2__q_r*_pd__156
        _x40 = 0.14492518595015338*_pd__156
        _d_iF2__q_th = _d_D__q_th*_x40 + _d_P2__q_th*_pd__154 + _d_Q2__q_th*_pd__155
        _d_iF2__q_thd = _d_D__q_thd*_x40 + _d_P2__q_thd*_pd__154 + _d_Q2__q_thd*_pd__155
        _d_iF2__k_d = _d_D__k_d*_x40 + _d_P2__k_d*_pd__154 + _d_Q2__k_d*_pd__155 + _x16 - _x29
        _d_iF2__guess_q_th = _d_D__guess_q_th*_x40 + _d_P2__guess_q_th*_pd__154 + _d_Q2__guess_q_th*_pd__155
        _d_iF2__guess_q_thd = (_d_D__guess_q_thd*_x40 + _d_P2__guess_q_thd*_pd__154
            + _d_Q2__guess_q_thd*_pd__155)
        _x41 = 0.3835443720333503*_D
        _x42 = _x41 + q_r
        _isigma3 = _x42
        _d_isigma3__q_r = 0.3835443720333503*_d_D__q_r + 1.0
        _x43 = math.cos(_Q3)
        _x44 = _x4*_x43
        _x45 = _x42*k_d
        _x46 = _P3**2
        _x162 = (1.0/_x42)
        _x47 = _x162**3
        _x48 = _x47*_x8
        _x49 = _x46*_x48
        _iF3 = _x2 - _x44 - _x45 + _x49
        _x50 = 2.0*_P3
        _pd__157 = _x48*_x50
        _x51 = math.sin(_Q3)
        _pd__158 = _x4*_x51
        _pd__159 = -_x14*_x162**4*_x46 - k_d
        _d_iF3__q_r = _d_P3__q_r*_pd__157 + _d_Q3__q_r*_pd__158 + _d_isigma3__q_r*_pd__159
        _x52 = 0.3835443720333503*_pd__159
        _d_iF3__q_th = _d_D__q_th*_x52 + _d_P3__q_th*_pd__157 + _d_Q3__q_th*_pd__158
        _d_iF3__q_thd = _d_D__q_thd*_x52 + _d_P3__q_thd*_pd__157 + _d_Q3__q_thd*_pd__158
        _d_iF3__k_d = _d_D__k_d*_x52 + _d_P3__k_d*_pd__157 + _d_Q3__k_d*_pd__158 + _x16 - _x41
        _d_iF3__guess_q_th = _d_D__guess_q_th*_x52 + _d_P3__guess_q_th*_pd__157 + _d_Q3__guess_q_th*_pd__158
        _d_iF3__guess_q_thd = (_d_D__guess_q_thd*_x52 + _d_P3__guess_q_thd*_pd__157
            + _d_Q3__guess_q_thd*_pd__158)
        _x53 = 0.6899041564209057*_D
        _x54 = _x53 + q_r
        _isigma4 = _x54
        _d_isigma4__q_r = 0.6899041564209057*_d_D__q_r + 1.0
        _x55 = math.cos(_Q4)
        _x56 = _x4*_x55
        _x57 = _x54*k_d
        _x58 = _P4**2
        _x163 = (1.0/_x54)
        _x59 = _x163**3
        _x60 = _x59*_x8
        _x61 = _x58*_x60
        _iF4 = _x2 - _x56 - _x57 + _x61
        _x62 = 2.0*_P4
        _pd__160 = _x60*_x62
        _x63 = math.sin(_Q4)
        _pd__161 = _x4*_x63
        _pd__162 = -_x14*_x163**4*_x58 - k_d
        _d_iF4__q_r = _d_P4__q_r*_pd__160 + _d_Q4__q_r*_pd__161 + _d_isigma4__q_r*_pd__162
        _x64 = 0.6899041564209057*_pd__162
        _d_iF4__q_th = _d_D__q_th*_x64 + _d_P4__q_th*_pd__160 + _d_Q4__q_th*_pd__161
        _d_iF4__q_thd = _d_D__q_thd*_x64 + _d_P4__q_thd*_pd__160 + _d_Q4__q_thd*_pd__161
        _d_iF4__k_d = _d_D__k_d*_x64 + _d_P4__k_d*_pd__160 + _d_Q4__k_d*_pd__161 + _x16 - _x53
        _d_iF4__guess_q_th = _d_D__guess_q_th*_x64 + _d_P4__guess_q_th*_pd__160 + _d_Q4__guess_q_th*_pd__161
        _d_iF4__guess_q_thd = (_d_D__guess_q_thd*_x64 + _d_P4__guess_q_thd*_pd__160
            + _d_Q4__guess_q_thd*_pd__161)
        _x65 = 0.9336096058311416*_D
        _x66 = _x65 + q_r
        _isigma5 = _x66
        _d_isigma5__q_r = 0.9336096058311416*_d_D__q_r + 1.0
        _x67 = math.cos(_Q5)
        _x68 = _x4*_x67
        _x69 = _x66*k_d
        _x70 = _P5**2
        _x164 = (1.0/_x66)
        _x71 = _x164**3
        _x72 = _x71*_x8
        _x73 = _x70*_x72
        _iF5 = _x2 - _x68 - _x69 + _x73
        _x74 = 2.0*_P5
        _pd__163 = _x72*_x74
        _x75 = math.sin(_Q5)
        _pd__164 = _x4*_x75
        _pd__165 = -_x14*_x164**4*_x70 - k_d
        _d_iF5__q_r = _d_P5__q_r*_pd__163 + _d_Q5__q_r*_pd__164 + _d_isigma5__q_r*_pd__165
        _x76 = 0.9336096058311416*_pd__165
        _d_iF5__q_th = _d_D__q_th*_x76 + _d_P5__q_th*_pd__163 + _d_Q5__q_th*_pd__164
        _d_iF5__q_thd = _d_D__q_thd*_x76 + _d_P5__q_thd*_pd__163 + _d_Q5__q_thd*_pd__164
        _d_iF5__k_d = _d_D__k_d*_x76 + _d_P5__k_d*_pd__163 + _d_Q5__k_d*_pd__164 + _x16 - _x65
        _d_iF5__guess_q_th = _d_D__guess_q_th*_x76 + _d_P5__guess_q_th*_pd__163 + _d_Q5__guess_q_th*_pd__164
        _d_iF5__guess_q_thd = (_d_D__guess_q_thd*_x76 + _d_P5__guess_q_thd*_pd__163
            + _d_Q5__guess_q_thd*_pd__164)
        _x77 = (0.5871580340658094*_x11 + 0.5*_x2 + 0.140380692261653*_x20 + 0.140380692261653*_x21
            - 0.140380692261653*_x25 - 0.08683151831711133*_x32 - 0.08683151831711133*_x33
            + 0.08683151831711133*_x37 + 0.052466581536012566*_x44 + 0.052466581536012566*_x45
            - 0.052466581536012566*_x49 - 0.5871580340658094*_x5 - 0.026354606039126004*_x56
            - 0.026354606039126004*_x57 - 0.5871580340658094*_x6 + 0.026354606039126004*_x61
            + 0.007496884624381081*_x68 + 0.007496884624381081*_x69 - 0.007496884624381081*_x73)
        _iPsi0 = _x77
        _d_iPsi0__q_r = (0.5871580340658094*_d_iF0__q_r - 0.140380692261653*_d_iF1__q_r
            + 0.08683151831711133*_d_iF2__q_r - 0.052466581536012566*_d_iF3__q_r
            + 0.026354606039126004*_d_iF4__q_r - 0.007496884624381081*_d_iF5__q_r)
        _d_iPsi0__q_th = (0.5871580340658094*_d_iF0__q_th - 0.140380692261653*_d_iF1__q_th
            + 0.08683151831711133*_d_iF2__q_th - 0.052466581536012566*_d_iF3__q_th
            + 0.026354606039126004*_d_iF4__q_th - 0.007496884624381081*_d_iF5__q_th)
        _d_iPsi0__q_thd = (0.5871580340658094*_d_iF0__q_thd - 0.140380692261653*_d_iF1__q_thd
            + 0.08683151831711133*_d_iF2__q_thd - 0.052466581536012566*_d_iF3__q_thd
            + 0.026354606039126004*_d_iF4__q_thd - 0.007496884624381081*_d_iF5__q_thd)
        _d_iPsi0__k_d = (0.5871580340658094*_d_iF0__k_d - 0.140380692261653*_d_iF1__k_d
            + 0.08683151831711133*_d_iF2__k_d - 0.052466581536012566*_d_iF3__k_d
            + 0.026354606039126004*_d_iF4__k_d - 0.007496884624381081*_d_iF5__k_d)
        _d_iPsi0__guess_q_th = (0.5871580340658094*_d_iF0__guess_q_th - 0.140380692261653*_d_iF1__guess_q_th
            + 0.08683151831711133*_d_iF2__guess_q_th - 0.052466581536012566*_d_iF3__guess_q_th
            + 0.026354606039126004*_d_iF4__guess_q_th - 0.007496884624381081*_d_iF5__guess_q_th)
        _d_iPsi0__guess_q_thd = (0.5871580340658094*_d_iF0__guess_q_thd
            - 0.140380692261653*_d_iF1__guess_q_thd + 0.08683151831711133*_d_iF2__guess_q_thd
            - 0.052466581536012566*_d_iF3__guess_q_thd + 0.026354606039126004*_d_iF4__guess_q_thd
            - 0.007496884624381081*_d_iF5__guess_q_thd)
        _x78 = (1.0/math.sqrt(_x77))
        _x79 = math.sqrt(_D)
        _x80 = math.sqrt(m)
        _x81 = _x79*_x80
        _ift0 = _x78*_x81
        _x82 = (0.5)/_x79
        _x83 = _x80*_x82
        _pd__166 = _x78*_x83
        _x84 = _x77**(-1.5)
        _x85 = (0.5)*_x81
        _pd__167 = -_x84*_x85
        _d_ift0__q_r = _d_D__q_r*_pd__166 + _d_iPsi0__q_r*_pd__167
        _d_ift0__q_th = _d_D__q_th*_pd__166 + _d_iPsi0__q_th*_pd__167
        _d_ift0__q_thd = _d_D__q_thd*_pd__166 + _d_iPsi0__q_thd*_pd__167
        _d_ift0__k_d = _d_D__k_d*_pd__166 + _d_iPsi0__k_d*_pd__167
        _d_ift0__guess_q_th = _d_D__guess_q_th*_pd__166 + _d_iPsi0__guess_q_th*_pd__167
        _d_ift0__guess_q_thd = _d_D__guess_q_thd*_pd__166 + _d_iPsi0__guess_q_thd*_pd__167
        _x86 = (1.0/_x80)
        _x87 = _x79*_x86
        _x88 = _x159**2
        _x89 = _x78*_x88
        _x90 = _x87*_x89
        _ifq0 = _P0*_x90
        _x91 = _x82*_x86
        _pd__168 = _P0*_x89*_x91
        _pd__169 = _x90
        _x92 = (0.5)*_x87
        _pd__170 = -_P0*_x84*_x88*_x92
        _pd__171 = -_x12*_x78*_x87*_x9
        _d_ifq0__q_r = (_d_D__q_r*_pd__168 + _d_P0__q_r*_pd__169 + _d_iPsi0__q_r*_pd__170
            + _d_isigma0__q_r*_pd__171)
        _x93 = 0.0011400916279895713*_pd__171
        _d_ifq0__q_th = _d_D__q_th*_pd__168 + _d_D__q_th*_x93 + _d_P0__q_th*_pd__169 + _d_iPsi0__q_th*_pd__170
        _d_ifq0__q_thd = (_d_D__q_thd*_pd__168 + _d_D__q_thd*_x93 + _d_P0__q_thd*_pd__169
            + _d_iPsi0__q_thd*_pd__170)
        _d_ifq0__k_d = _d_D__k_d*_pd__168 + _d_D__k_d*_x93 + _d_P0__k_d*_pd__169 + _d_iPsi0__k_d*_pd__170
        _d_ifq0__guess_q_th = (_d_D__guess_q_th*_pd__168 + _d_D__guess_q_th*_x93 + _d_P0__guess_q_th*_pd__169
            + _d_iPsi0__guess_q_th*_pd__170)
        _d_ifq0__guess_q_thd = (_d_D__guess_q_thd*_pd__168 + _d_D__guess_q_thd*_x93
            + _d_P0__guess_q_thd*_pd__169 + _d_iPsi0__guess_q_thd*_pd__170)
        _x94 = g_s*m**(1.5)
        _x95 = _x79*_x94
        _x96 = _x78*_x95
        _x97 = _x13*_x96
        _ifp0 = _x1*_x97
        _x98 = _x1*_x13
        _x99 = _x82*_x94
        _pd__172 = _x78*_x98*_x99
        _pd__173 = _x1*_x3*_x96
        _x100 = (0.5)*_x95
        _pd__174 = -_x100*_x84*_x98
        _pd__175 = _x97
        _d_ifp0__q_r = (_d_D__q_r*_pd__172 + _d_Q0__q_r*_pd__173 + _d_iPsi0__q_r*_pd__174
            + _d_isigma0__q_r*_pd__175)
        _x101 = 0.0011400916279895713*_pd__175
        _d_ifp0__q_th = (_d_D__q_th*_pd__172 + _d_D__q_th*_x101 + _d_Q0__q_th*_pd__173
            + _d_iPsi0__q_th*_pd__174)
        _d_ifp0__q_thd = (_d_D__q_thd*_pd__172 + _d_D__q_thd*_x101 + _d_Q0__q_thd*_pd__173
            + _d_iPsi0__q_thd*_pd__174)
        _d_ifp0__k_d = _d_D__k_d*_pd__172 + _d_D__k_d*_x101 + _d_Q0__k_d*_pd__173 + _d_iPsi0__k_d*_pd__174
        _d_ifp0__guess_q_th = (_d_D__guess_q_th*_pd__172 + _d_D__guess_q_th*_x101 + _d_Q0__guess_q_th*_pd__173
            + _d_iPsi0__guess_q_th*_pd__174)
        _d_ifp0__guess_q_thd = (_d_D__guess_q_thd*_pd__172 + _d_D__guess_q_thd*_x101
            + _d_Q0__guess_q_thd*_pd__173 + _d_iPsi0__guess_q_thd*_pd__174)
        _x102 = -0.5*k_d*l0
        _x103 = (-_x102 - 0.41567911405660357*_x20 - 0.41567911405660357*_x21
            + 0.41567911405660357*_x22*_x23*_x8 + 0.09720828549085844*_x30*k_d
            + 0.09720828549085844*_x31*g_s*m - 0.09720828549085844*_x37 - 0.05155355009455148*_x44
            - 0.05155355009455148*_x45 + 0.05155355009455148*_x46*_x47*_x8 - 0.147790320897128*_x5
            + 0.024719229415033087*_x54*k_d + 0.024719229415033087*_x55*g_s*m - 0.147790320897128*_x6
            - 0.024719229415033087*_x61 - 0.006904529857608445*_x68 - 0.006904529857608445*_x69
            + 0.147790320897128*_x7*_x8*_x9 + 0.006904529857608445*_x70*_x71*_x8)
        _iPsi1 = _x103
        _d_iPsi1__q_r = (0.147790320897128*_d_iF0__q_r + 0.41567911405660357*_d_iF1__q_r
            - 0.09720828549085844*_d_iF2__q_r + 0.05155355009455148*_d_iF3__q_r
            - 0.024719229415033087*_d_iF4__q_r + 0.006904529857608445*_d_iF5__q_r)
        _d_iPsi1__q_th = (0.147790320897128*_d_iF0__q_th + 0.41567911405660357*_d_iF1__q_th
            - 0.09720828549085844*_d_iF2__q_th + 0.05155355009455148*_d_iF3__q_th
            - 0.024719229415033087*_d_iF4__q_th + 0.006904529857608445*_d_iF5__q_th)
        _d_iPsi1__q_thd = (0.147790320897128*_d_iF0__q_thd + 0.41567911405660357*_d_iF1__q_thd
            - 0.09720828549085844*_d_iF2__q_thd + 0.05155355009455148*_d_iF3__q_thd
            - 0.024719229415033087*_d_iF4__q_thd + 0.006904529857608445*_d_iF5__q_thd)
        _d_iPsi1__k_d = (0.147790320897128*_d_iF0__k_d + 0.41567911405660357*_d_iF1__k_d
            - 0.09720828549085844*_d_iF2__k_d + 0.05155355009455148*_d_iF3__k_d
            - 0.024719229415033087*_d_iF4__k_d + 0.006904529857608445*_d_iF5__k_d)
        _d_iPsi1__guess_q_th = (0.147790320897128*_d_iF0__guess_q_th + 0.41567911405660357*_d_iF1__guess_q_th
            - 0.09720828549085844*_d_iF2__guess_q_th + 0.05155355009455148*_d_iF3__guess_q_th
            - 0.024719229415033087*_d_iF4__guess_q_th + 0.006904529857608445*_d_iF5__guess_q_th)
        _d_iPsi1__guess_q_thd = (0.147790320897128*_d_iF0__guess_q_thd
            + 0.41567911405660357*_d_iF1__guess_q_thd - 0.09720828549085844*_d_iF2__guess_q_thd
            + 0.05155355009455148*_d_iF3__guess_q_thd - 0.024719229415033087*_d_iF4__guess_q_thd
            + 0.006904529857608445*_d_iF5__guess_q_thd)
        _x104 = (1.0/math.sqrt(_x103))
        _ift1 = _x104*_x81
        _pd__176 = _x104*_x83
        _x105 = _x103**(-1.5)
        _pd__177 = -_x105*_x85
        _d_ift1__q_r = _d_D__q_r*_pd__176 + _d_iPsi1__q_r*_pd__177
        _d_ift1__q_th = _d_D__q_th*_pd__176 + _d_iPsi1__q_th*_pd__177
        _d_ift1__q_thd = _d_D__q_thd*_pd__176 + _d_iPsi1__q_thd*_pd__177
        _d_ift1__k_d = _d_D__k_d*_pd__176 + _d_iPsi1__k_d*_pd__177
        _d_ift1__guess_q_th = _d_D__guess_q_th*_pd__176 + _d_iPsi1__guess_q_th*_pd__177
        _d_ift1__guess_q_thd = _d_D__guess_q_thd*_pd__176 + _d_iPsi1__guess_q_thd*_pd__177
        _x106 = _x160**2
        _x107 = _x104*_x106
        _x108 = _x107*_x87
        _ifq1 = _P1*_x108
        _pd__178 = _P1*_x107*_x91
        _pd__179 = _x108
        _pd__180 = -_P1*_x105*_x106*_x92
        _pd__181 = -_x104*_x23*_x26*_x87
        _d_ifq1__q_r = (_d_D__q_r*_pd__178 + _d_P1__q_r*_pd__179 + _d_iPsi1__q_r*_pd__180
            + _d_isigma1__q_r*_pd__181)
        _x109 = 0.02869476995464123*_pd__181
        _d_ifq1__q_th = (_d_D__q_th*_pd__178 + _d_D__q_th*_x109 + _d_P1__q_th*_pd__179
            + _d_iPsi1__q_th*_pd__180)
        _d_ifq1__q_thd = (_d_D__q_thd*_pd__178 + _d_D__q_thd*_x109 + _d_P1__q_thd*_pd__179
            + _d_iPsi1__q_thd*_pd__180)
        _d_ifq1__k_d = _d_D__k_d*_pd__178 + _d_D__k_d*_x109 + _d_P1__k_d*_pd__179 + _d_iPsi1__k_d*_pd__180
        _d_ifq1__guess_q_th = (_d_D__guess_q_th*_pd__178 + _d_D__guess_q_th*_x109 + _d_P1__guess_q_th*_pd__179
            + _d_iPsi1__guess_q_th*_pd__180)
        _d_ifq1__guess_q_thd = (_d_D__guess_q_thd*_pd__178 + _d_D__guess_q_thd*_x109
            + _d_P1__guess_q_thd*_pd__179 + _d_iPsi1__guess_q_thd*_pd__180)
        _x110 = _x104*_x95
        _x111 = _x110*_x27
        _ifp1 = _x111*_x18
        _x112 = _x18*_x27
        _pd__182 = _x104*_x112*_x99
        _pd__183 = _x110*_x18*_x19
        _pd__184 = -_x100*_x105*_x112
        _pd__185 = _x111
        _d_ifp1__q_r = (_d_D__q_r*_pd__182 + _d_Q1__q_r*_pd__183 + _d_iPsi1__q_r*_pd__184
            + _d_isigma1__q_r*_pd__185)
        _x113 = 0.02869476995464123*_pd__185
        _d_ifp1__q_th = (_d_D__q_th*_pd__182 + _d_D__q_th*_x113 + _d_Q1__q_th*_pd__183
            + _d_iPsi1__q_th*_pd__184)
        _d_ifp1__q_thd = (_d_D__q_thd*_pd__182 + _d_D__q_thd*_x113 + _d_Q1__q_thd*_pd__183
            + _d_iPsi1__q_thd*_pd__184)
        _d_ifp1__k_d = _d_D__k_d*_pd__182 + _d_D__k_d*_x113 + _d_Q1__k_d*_pd__183 + _d_iPsi1__k_d*_pd__184
        _d_ifp1__guess_q_th = (_d_D__guess_q_th*_pd__182 + _d_D__guess_q_th*_x113 + _d_Q1__guess_q_th*_pd__183
            + _d_iPsi1__guess_q_th*_pd__184)
        _d_ifp1__guess_q_thd = (_d_D__guess_q_thd*_pd__182 + _d_D__guess_q_thd*_x113
            + _d_Q1__guess_q_thd*_pd__183 + _d_iPsi1__guess_q_thd*_pd__184)
        _x114 = (-_x102 - 0.25540525119175433*_x20 - 0.25540525119175433*_x21
            + 0.25540525119175433*_x22*_x23*_x8 - 0.2685463444140672*_x32 - 0.2685463444140672*_x33
            + 0.2685463444140672*_x34*_x35*_x8 + 0.048794612428541204*_x42*k_d
            + 0.048794612428541204*_x43*g_s*m - 0.048794612428541204*_x49 - 0.010443786721981197*_x5
            - 0.01951903325298492*_x56 - 0.01951903325298492*_x57 + 0.01951903325298492*_x58*_x59*_x8
            - 0.010443786721981197*_x6 + 0.005119803152246505*_x66*k_d + 0.005119803152246505*_x67*g_s*m
            + 0.010443786721981197*_x7*_x8*_x9 - 0.005119803152246505*_x73)
        _iPsi2 = _x114
        _d_iPsi2__q_r = (0.010443786721981197*_d_iF0__q_r + 0.25540525119175433*_d_iF1__q_r
            + 0.2685463444140672*_d_iF2__q_r - 0.048794612428541204*_d_iF3__q_r
            + 0.01951903325298492*_d_iF4__q_r - 0.005119803152246505*_d_iF5__q_r)
        _d_iPsi2__q_th = (0.010443786721981197*_d_iF0__q_th + 0.25540525119175433*_d_iF1__q_th
            + 0.2685463444140672*_d_iF2__q_th - 0.048794612428541204*_d_iF3__q_th
            + 0.01951903325298492*_d_iF4__q_th - 0.005119803152246505*_d_iF5__q_th)
        _d_iPsi2__q_thd = (0.010443786721981197*_d_iF0__q_thd + 0.25540525119175433*_d_iF1__q_thd
            + 0.2685463444140672*_d_iF2__q_thd - 0.048794612428541204*_d_iF3__q_thd
            + 0.01951903325298492*_d_iF4__q_thd - 0.005119803152246505*_d_iF5__q_thd)
        _d_iPsi2__k_d = (0.010443786721981197*_d_iF0__k_d + 0.25540525119175433*_d_iF1__k_d
            + 0.2685463444140672*_d_iF2__k_d - 0.048794612428541204*_d_iF3__k_d
            + 0.01951903325298492*_d_iF4__k_d - 0.005119803152246505*_d_iF5__k_d)
        _d_iPsi2__guess_q_th = (0.010443786721981197*_d_iF0__guess_q_th
            + 0.25540525119175433*_d_iF1__guess_q_th + 0.2685463444140672*_d_iF2__guess_q_th
            - 0.048794612428541204*_d_iF3__guess_q_th + 0.01951903325298492*_d_iF4__guess_q_th
            - 0.005119803152246505*_d_iF5__guess_q_th)
        _d_iPsi2__guess_q_thd = (0.010443786721981197*_d_iF0__guess_q_thd
            + 0.25540525119175433*_d_iF1__guess_q_thd + 0.2685463444140672*_d_iF2__guess_q_thd
            - 0.048794612428541204*_d_iF3__guess_q_thd + 0.01951903325298492*_d_iF4__guess_q_thd
            - 0.005119803152246505*_d_iF5__guess_q_thd)
        _x115 = (1.0/math.sqrt(_x114))
        _ift2 = _x115*_x81
        _pd__186 = _x115*_x83
        _x116 = _x114**(-1.5)
        _pd__187 = -_x116*_x85
        _d_ift2__q_r = _d_D__q_r*_pd__186 + _d_iPsi2__q_r*_pd__187
        _d_ift2__q_th = _d_D__q_th*_pd__186 + _d_iPsi2__q_th*_pd__187
        _d_ift2__q_thd = _d_D__q_thd*_pd__186 + _d_iPsi2__q_thd*_pd__187
        _d_ift2__k_d = _d_D__k_d*_pd__186 + _d_iPsi2__k_d*_pd__187
        _d_ift2__guess_q_th = _d_D__guess_q_th*_pd__186 + _d_iPsi2__guess_q_th*_pd__187
        _d_ift2__guess_q_thd = _d_D__guess_q_thd*_pd__186 + _d_iPsi2__guess_q_thd*_pd__187
        _x117 = _x161**2
        _x118 = _x115*_x117
        _x119 = _x118*_x87
        _ifq2 = _P2*_x119
        _pd__188 = _P2*_x118*_x91
        _pd__189 = _x119
        _pd__190 = -_P2*_x116*_x117*_x92
        _pd__191 = -_x115*_x35*_x38*_x87
        _d_ifq2__q_r = (_d_D__q_r*_pd__188 + _d_P2__q_r*_pd__189 + _d_iPsi2__q_r*_pd__190
            + _d_isigma2__q_r*_pd__191)
        _x120 = 0.14492518595015338*_pd__191
        _d_ifq2__q_th = (_d_D__q_th*_pd__188 + _d_D__q_th*_x120 + _d_P2__q_th*_pd__189
            + _d_iPsi2__q_th*_pd__190)
        _d_ifq2__q_thd = (_d_D__q_thd*_pd__188 + _d_D__q_thd*_x120 + _d_P2__q_thd*_pd__189
            + _d_iPsi2__q_thd*_pd__190)
        _d_ifq2__k_d = _d_D__k_d*_pd__188 + _d_D__k_d*_x120 + _d_P2__k_d*_pd__189 + _d_iPsi2__k_d*_pd__190
        _d_ifq2__guess_q_th = (_d_D__guess_q_th*_pd__188 + _d_D__guess_q_th*_x120 + _d_P2__guess_q_th*_pd__189
            + _d_iPsi2__guess_q_th*_pd__190)
        _d_ifq2__guess_q_thd = (_d_D__guess_q_thd*_pd__188 + _d_D__guess_q_thd*_x120
            + _d_P2__guess_q_thd*_pd__189 + _d_iPsi2__guess_q_thd*_pd__190)
        _x121 = _x115*_x95
        _x122 = _x121*_x39
        _ifp2 = _x122*_x30
        _x123 = _x30*_x39
        _pd__192 = _x115*_x123*_x99
        _pd__193 = _x121*_x30*_x31
        _pd__194 = -_x100*_x116*_x123
        _pd__195 = _x122
        _d_ifp2__q_r = (_d_D__q_r*_pd__192 + _d_Q2__q_r*_pd__193 + _d_iPsi2__q_r*_pd__194
            + _d_isigma2__q_r*_pd__195)
        _x124 = 0.14492518595015338*_pd__195
        _d_ifp2__q_th = (_d_D__q_th*_pd__192 + _d_D__q_th*_x124 + _d_Q2__q_th*_pd__193
            + _d_iPsi2__q_th*_pd__194)
        _d_ifp2__q_thd = (_d_D__q_thd*_pd__192 + _d_D__q_thd*_x124 + _d_Q2__q_thd*_pd__193
            + _d_iPsi2__q_thd*_pd__194)
        _d_ifp2__k_d = _d_D__k_d*_pd__192 + _d_D__k_d*_x124 + _d_Q2__k_d*_pd__193 + _d_iPsi2__k_d*_pd__194
        _d_ifp2__guess_q_th = (_d_D__guess_q_th*_pd__192 + _d_D__guess_q_th*_x124 + _d_Q2__guess_q_th*_pd__193
            + _d_iPsi2__guess_q_th*_pd__194)
        _d_ifp2__guess_q_thd = (_d_D__guess_q_thd*_pd__192 + _d_D__guess_q_thd*_x124
            + _d_Q2__guess_q_thd*_pd__193 + _d_iPsi2__guess_q_thd*_pd__194)
        _x125 = -0.5*k_d*l0
        _x126 = (-_x125 - 0.0662099828438604*_x20 - 0.0662099828438604*_x21 + 0.0662099828438604*_x22*_x23*_x8
            - 0.2671819482314443*_x32 - 0.2671819482314443*_x33 + 0.2671819482314443*_x34*_x35*_x8
            - 0.1742495636223592*_x44 - 0.1742495636223592*_x45 + 0.1742495636223592*_x46*_x47*_x8
            - 0.01101839635505667*_x5 + 0.02396692958086051*_x54*k_d + 0.02396692958086051*_x55*g_s*m
            - 0.01101839635505667*_x6 - 0.02396692958086051*_x61 - 0.00530703852813994*_x68
            - 0.00530703852813994*_x69 + 0.01101839635505667*_x7*_x8*_x9 + 0.00530703852813994*_x70*_x71*_x8)
        _iPsi3 = _x126
        _d_iPsi3__q_r = (0.01101839635505667*_d_iF0__q_r + 0.0662099828438604*_d_iF1__q_r
            + 0.2671819482314443*_d_iF2__q_r + 0.1742495636223592*_d_iF3__q_r
            - 0.02396692958086051*_d_iF4__q_r + 0.00530703852813994*_d_iF5__q_r)
        _d_iPsi3__q_th = (0.01101839635505667*_d_iF0__q_th + 0.0662099828438604*_d_iF1__q_th
            + 0.2671819482314443*_d_iF2__q_th + 0.1742495636223592*_d_iF3__q_th
            - 0.02396692958086051*_d_iF4__q_th + 0.00530703852813994*_d_iF5__q_th)
        _d_iPsi3__q_thd = (0.01101839635505667*_d_iF0__q_thd + 0.0662099828438604*_d_iF1__q_thd
            + 0.2671819482314443*_d_iF2__q_thd + 0.1742495636223592*_d_iF3__q_thd
            - 0.02396692958086051*_d_iF4__q_thd + 0.00530703852813994*_d_iF5__q_thd)
        _d_iPsi3__k_d = (0.01101839635505667*_d_iF0__k_d + 0.0662099828438604*_d_iF1__k_d
            + 0.2671819482314443*_d_iF2__k_d + 0.1742495636223592*_d_iF3__k_d
            - 0.02396692958086051*_d_iF4__k_d + 0.00530703852813994*_d_iF5__k_d)
        _d_iPsi3__guess_q_th = (0.01101839635505667*_d_iF0__guess_q_th + 0.0662099828438604*_d_iF1__guess_q_th
            + 0.2671819482314443*_d_iF2__guess_q_th + 0.1742495636223592*_d_iF3__guess_q_th
            - 0.02396692958086051*_d_iF4__guess_q_th + 0.00530703852813994*_d_iF5__guess_q_th)
        _d_iPsi3__guess_q_thd = (0.01101839635505667*_d_iF0__guess_q_thd
            + 0.0662099828438604*_d_iF1__guess_q_thd + 0.2671819482314443*_d_iF2__guess_q_thd
            + 0.1742495636223592*_d_iF3__guess_q_thd - 0.02396692958086051*_d_iF4__guess_q_thd
            + 0.00530703852813994*_d_iF5__guess_q_thd)
        _x127 = (1.0/math.sqrt(_x126))
        _ift3 = _x127*_x81
        _pd__196 = _x127*_x83
        _x128 = _x126**(-1.5)
        _pd__197 = -_x128*_x85
        _d_ift3__q_r = _d_D__q_r*_pd__196 + _d_iPsi3__q_r*_pd__197
        _d_ift3__q_th = _d_D__q_th*_pd__196 + _d_iPsi3__q_th*_pd__197
        _d_ift3__q_thd = _d_D__q_thd*_pd__196 + _d_iPsi3__q_thd*_pd__197
        _d_ift3__k_d = _d_D__k_d*_pd__196 + _d_iPsi3__k_d*_pd__197
        _d_ift3__guess_q_th = _d_D__guess_q_th*_pd__196 + _d_iPsi3__guess_q_th*_pd__197
        _d_ift3__guess_q_thd = _d_D__guess_q_thd*_pd__196 + _d_iPsi3__guess_q_thd*_pd__197
        _x129 = _x162**2
        _x130 = _x127*_x129
        _x131 = _x130*_x87
        _ifq3 = _P3*_x131
        _pd__198 = _P3*_x130*_x91
        _pd__199 = _x131
        _pd__200 = -_P3*_x128*_x129*_x92
        _pd__201 = -_x127*_x47*_x50*_x87
        _d_ifq3__q_r = (_d_D__q_r*_pd__198 + _d_P3__q_r*_pd__199 + _d_iPsi3__q_r*_pd__200
            + _d_isigma3__q_r*_pd__201)
        _x132 = 0.3835443720333503*_pd__201
        _d_ifq3__q_th = (_d_D__q_th*_pd__198 + _d_D__q_th*_x132 + _d_P3__q_th*_pd__199
            + _d_iPsi3__q_th*_pd__200)
        _d_ifq3__q_thd = (_d_D__q_thd*_pd__198 + _d_D__q_thd*_x132 + _d_P3__q_thd*_pd__199
            + _d_iPsi3__q_thd*_pd__200)
        _d_ifq3__k_d = _d_D__k_d*_pd__198 + _d_D__k_d*_x132 + _d_P3__k_d*_pd__199 + _d_iPsi3__k_d*_pd__200
        _d_ifq3__guess_q_th = (_d_D__guess_q_th*_pd__198 + _d_D__guess_q_th*_x132 + _d_P3__guess_q_th*_pd__199
            + _d_iPsi3__guess_q_th*_pd__200)
        _d_ifq3__guess_q_thd = (_d_D__guess_q_thd*_pd__198 + _d_D__guess_q_thd*_x132
            + _d_P3__guess_q_thd*_pd__199 + _d_iPsi3__guess_q_thd*_pd__200)
        _x133 = _x127*_x95
        _x134 = _x133*_x51
        _ifp3 = _x134*_x42
        _x135 = _x42*_x51
        _pd__202 = _x127*_x135*_x99
        _pd__203 = _x133*_x42*_x43
        _pd__204 = -_x100*_x128*_x135
        _pd__205 = _x134
        _d_ifp3__q_r = (_d_D__q_r*_pd__202 + _d_Q3__q_r*_pd__203 + _d_iPsi3__q_r*_pd__204
            + _d_isigma3__q_r*_pd__205)
        _x136 = 0.3835443720333503*_pd__205
        _d_ifp3__q_th = (_d_D__q_th*_pd__202 + _d_D__q_th*_x136 + _d_Q3__q_th*_pd__203
            + _d_iPsi3__q_th*_pd__204)
        _d_ifp3__q_thd = (_d_D__q_thd*_pd__202 + _d_D__q_thd*_x136 + _d_Q3__q_thd*_pd__203
            + _d_iPsi3__q_thd*_pd__204)
        _d_ifp3__k_d = _d_D__k_d*_pd__202 + _d_D__k_d*_x136 + _d_Q3__k_d*_pd__203 + _d_iPsi3__k_d*_pd__204
        _d_ifp3__guess_q_th = (_d_D__guess_q_th*_pd__202 + _d_D__guess_q_th*_x136 + _d_Q3__guess_q_th*_pd__203
            + _d_iPsi3__guess_q_th*_pd__204)
        _d_ifp3__guess_q_thd = (_d_D__guess_q_thd*_pd__202 + _d_D__guess_q_thd*_x136
            + _d_Q3__guess_q_thd*_pd__203 + _d_iPsi3__guess_q_thd*_pd__204)
        _x137 = (-_x102 - 0.050345455482979015*_x20 - 0.050345455482979015*_x21
            + 0.050345455482979015*_x22*_x23*_x8 - 0.11622097556712797*_x32 - 0.11622097556712797*_x33
            + 0.11622097556712797*_x34*_x35*_x8 - 0.2353986790647292*_x44 - 0.2353986790647292*_x45
            + 0.2353986790647292*_x46*_x47*_x8 - 0.0025147977064533143*_x5 - 0.10372825048336794*_x56
            - 0.10372825048336794*_x57 + 0.10372825048336794*_x58*_x59*_x8 - 0.0025147977064533143*_x6
            + 0.008208158304657426*_x66*k_d + 0.008208158304657426*_x67*g_s*m
            + 0.0025147977064533143*_x7*_x8*_x9 - 0.008208158304657426*_x73)
        _iPsi4 = _x137
        _d_iPsi4__q_r = (0.0025147977064533143*_d_iF0__q_r + 0.050345455482979015*_d_iF1__q_r
            + 0.11622097556712797*_d_iF2__q_r + 0.2353986790647292*_d_iF3__q_r
            + 0.10372825048336794*_d_iF4__q_r - 0.008208158304657426*_d_iF5__q_r)
        _d_iPsi4__q_th = (0.0025147977064533143*_d_iF0__q_th + 0.050345455482979015*_d_iF1__q_th
            + 0.11622097556712797*_d_iF2__q_th + 0.2353986790647292*_d_iF3__q_th
            + 0.10372825048336794*_d_iF4__q_th - 0.008208158304657426*_d_iF5__q_th)
        _d_iPsi4__q_thd = (0.0025147977064533143*_d_iF0__q_thd + 0.050345455482979015*_d_iF1__q_thd
            + 0.11622097556712797*_d_iF2__q_thd + 0.2353986790647292*_d_iF3__q_thd
            + 0.10372825048336794*_d_iF4__q_thd - 0.008208158304657426*_d_iF5__q_thd)
        _d_iPsi4__k_d = (0.0025147977064533143*_d_iF0__k_d + 0.050345455482979015*_d_iF1__k_d
            + 0.11622097556712797*_d_iF2__k_d + 0.2353986790647292*_d_iF3__k_d
            + 0.10372825048336794*_d_iF4__k_d - 0.008208158304657426*_d_iF5__k_d)
        _d_iPsi4__guess_q_th = (0.0025147977064533143*_d_iF0__guess_q_th
            + 0.050345455482979015*_d_iF1__guess_q_th + 0.11622097556712797*_d_iF2__guess_q_th
            + 0.2353986790647292*_d_iF3__guess_q_th + 0.10372825048336794*_d_iF4__guess_q_th
            - 0.008208158304657426*_d_iF5__guess_q_th)
        _d_iPsi4__guess_q_thd = (0.0025147977064533143*_d_iF0__guess_q_thd
            + 0.050345455482979015*_d_iF1__guess_q_thd + 0.11622097556712797*_d_iF2__guess_q_thd
            + 0.2353986790647292*_d_iF3__guess_q_thd + 0.10372825048336794*_d_iF4__guess_q_thd
            - 0.008208158304657426*_d_iF5__guess_q_thd)
        _x138 = (1.0/math.sqrt(_x137))
        _ift4 = _x138*_x81
        _pd__206 = _x138*_x83
        _x139 = _x137**(-1.5)
        _pd__207 = -_x139*_x85
        _d_ift4__q_r = _d_D__q_r*_pd__206 + _d_iPsi4__q_r*_pd__207
        _d_ift4__q_th = _d_D__q_th*_pd__206 + _d_iPsi4__q_th*_pd__207
        _d_ift4__q_thd = _d_D__q_thd*_pd__206 + _d_iPsi4__q_thd*_pd__207
        _d_ift4__k_d = _d_D__k_d*_pd__206 + _d_iPsi4__k_d*_pd__207
        _d_ift4__guess_q_th = _d_D__guess_q_th*_pd__206 + _d_iPsi4__guess_q_th*_pd__207
        _d_ift4__guess_q_thd = _d_D__guess_q_thd*_pd__206 + _d_iPsi4__guess_q_thd*_pd__207
        _x140 = _x163**2
        _x141 = _x138*_x140
        _x142 = _x141*_x87
        _ifq4 = _P4*_x142
        _pd__208 = _P4*_x141*_x91
        _pd__209 = _x142
        _pd__210 = -_P4*_x139*_x140*_x92
        _pd__211 = -_x138*_x59*_x62*_x87
        _d_ifq4__q_r = (_d_D__q_r*_pd__208 + _d_P4__q_r*_pd__209 + _d_iPsi4__q_r*_pd__210
            + _d_isigma4__q_r*_pd__211)
        _x143 = 0.6899041564209057*_pd__211
        _d_ifq4__q_th = (_d_D__q_th*_pd__208 + _d_D__q_th*_x143 + _d_P4__q_th*_pd__209
            + _d_iPsi4__q_th*_pd__210)
        _d_ifq4__q_thd = (_d_D__q_thd*_pd__208 + _d_D__q_thd*_x143 + _d_P4__q_thd*_pd__209
            + _d_iPsi4__q_thd*_pd__210)
        _d_ifq4__k_d = _d_D__k_d*_pd__208 + _d_D__k_d*_x143 + _d_P4__k_d*_pd__209 + _d_iPsi4__k_d*_pd__210
        _d_ifq4__guess_q_th = (_d_D__guess_q_th*_pd__208 + _d_D__guess_q_th*_x143 + _d_P4__guess_q_th*_pd__209
            + _d_iPsi4__guess_q_th*_pd__210)
        _d_ifq4__guess_q_thd = (_d_D__guess_q_thd*_pd__208 + _d_D__guess_q_thd*_x143
            + _d_P4__guess_q_thd*_pd__209 + _d_iPsi4__guess_q_thd*_pd__210)
        _x144 = _x138*_x95
        _x145 = _x144*_x63
        _ifp4 = _x145*_x54
        _x146 = _x54*_x63
        _pd__212 = _x138*_x146*_x99
        _pd__213 = _x144*_x54*_x55
        _pd__214 = -_x100*_x139*_x146
        _pd__215 = _x145
        _d_ifp4__q_r = (_d_D__q_r*_pd__212 + _d_Q4__q_r*_pd__213 + _d_iPsi4__q_r*_pd__214
            + _d_isigma4__q_r*_pd__215)
        _x147 = 0.6899041564209057*_pd__215
        _d_ifp4__q_th = (_d_D__q_th*_pd__212 + _d_D__q_th*_x147 + _d_Q4__q_th*_pd__213
            + _d_iPsi4__q_th*_pd__214)
        _d_ifp4__q_thd = (_d_D__q_thd*_pd__212 + _d_D__q_thd*_x147 + _d_Q4__q_thd*_pd__213
            + _d_iPsi4__q_thd*_pd__214)
        _d_ifp4__k_d = _d_D__k_d*_pd__212 + _d_D__k_d*_x147 + _d_Q4__k_d*_pd__213 + _d_iPsi4__k_d*_pd__214
        _d_ifp4__guess_q_th = (_d_D__guess_q_th*_pd__212 + _d_D__guess_q_th*_x147 + _d_Q4__guess_q_th*_pd__213
            + _d_iPsi4__guess_q_th*_pd__214)
        _d_ifp4__guess_q_thd = (_d_D__guess_q_thd*_pd__212 + _d_D__guess_q_thd*_x147
            + _d_Q4__guess_q_thd*_pd__213 + _d_iPsi4__guess_q_thd*_pd__214)
        _x148 = (-_x125 - 0.029703284805013122*_x20 - 0.029703284805013122*_x21
            + 0.029703284805013122*_x22*_x23*_x8 - 0.10140664131431479*_x32 - 0.10140664131431479*_x33
            + 0.10140664131431479*_x34*_x35*_x8 - 0.14531313573962065*_x44 - 0.14531313573962065*_x45
            + 0.14531313573962065*_x46*_x47*_x8 - 0.003959513229722528*_x5 - 0.17612158869639333*_x56
            - 0.17612158869639333*_x57 + 0.17612158869639333*_x58*_x59*_x8 - 0.003959513229722528*_x6
            - 0.04349583621493557*_x68 - 0.04349583621493557*_x69 + 0.003959513229722528*_x7*_x8*_x9
            + 0.04349583621493557*_x70*_x71*_x8)
        _iPsi5 = _x148
        _d_iPsi5__q_r = (0.003959513229722528*_d_iF0__q_r + 0.029703284805013122*_d_iF1__q_r
            + 0.10140664131431479*_d_iF2__q_r + 0.14531313573962065*_d_iF3__q_r
            + 0.17612158869639333*_d_iF4__q_r + 0.04349583621493557*_d_iF5__q_r)
        _d_iPsi5__q_th = (0.003959513229722528*_d_iF0__q_th + 0.029703284805013122*_d_iF1__q_th
            + 0.10140664131431479*_d_iF2__q_th + 0.14531313573962065*_d_iF3__q_th
            + 0.17612158869639333*_d_iF4__q_th + 0.04349583621493557*_d_iF5__q_th)
        _d_iPsi5__q_thd = (0.003959513229722528*_d_iF0__q_thd + 0.029703284805013122*_d_iF1__q_thd
            + 0.10140664131431479*_d_iF2__q_thd + 0.14531313573962065*_d_iF3__q_thd
            + 0.17612158869639333*_d_iF4__q_thd + 0.04349583621493557*_d_iF5__q_thd)
        _d_iPsi5__k_d = (0.003959513229722528*_d_iF0__k_d + 0.029703284805013122*_d_iF1__k_d
            + 0.10140664131431479*_d_iF2__k_d + 0.14531313573962065*_d_iF3__k_d
            + 0.17612158869639333*_d_iF4__k_d + 0.04349583621493557*_d_iF5__k_d)
        _d_iPsi5__guess_q_th = (0.003959513229722528*_d_iF0__guess_q_th
            + 0.029703284805013122*_d_iF1__guess_q_th + 0.10140664131431479*_d_iF2__guess_q_th
            + 0.14531313573962065*_d_iF3__guess_q_th + 0.17612158869639333*_d_iF4__guess_q_th
            + 0.04349583621493557*_d_iF5__guess_q_th)
        _d_iPsi5__guess_q_thd = (0.003959513229722528*_d_iF0__guess_q_thd
            + 0.029703284805013122*_d_iF1__guess_q_thd + 0.10140664131431479*_d_iF2__guess_q_thd
            + 0.14531313573962065*_d_iF3__guess_q_thd + 0.17612158869639333*_d_iF4__guess_q_thd
            + 0.04349583621493557*_d_iF5__guess_q_thd)
        _x149 = (1.0/math.sqrt(_x148))
        _ift5 = _x149*_x81
        _pd__216 = _x149*_x83
        _x150 = _x148**(-1.5)
        _pd__217 = -_x150*_x85
        _d_ift5__q_r = _d_D__q_r*_pd__216 + _d_iPsi5__q_r*_pd__217
        _d_ift5__q_th = _d_D__q_th*_pd__216 + _d_iPsi5__q_th*_pd__217
        _d_ift5__q_thd = _d_D__q_thd*_pd__216 + _d_iPsi5__q_thd*_pd__217
        _d_ift5__k_d = _d_D__k_d*_pd__216 + _d_iPsi5__k_d*_pd__217
        _d_ift5__guess_q_th = _d_D__guess_q_th*_pd__216 + _d_iPsi5__guess_q_th*_pd__217
        _d_ift5__guess_q_thd = _d_D__guess_q_thd*_pd__216 + _d_iPsi5__guess_q_thd*_pd__217
        _x151 = _x164**2
        _x152 = _x149*_x151
        _x153 = _x152*_x87
        _ifq5 = _P5*_x153
        _pd__218 = _P5*_x152*_x91
        _pd__219 = _x153
        _pd__220 = -_P5*_x150*_x151*_x92
        _pd__221 = -_x149*_x71*_x74*_x87
        _d_ifq5__q_r = (_d_D__q_r*_pd__218 + _d_P5__q_r*_pd__219 + _d_iPsi5__q_r*_pd__220
            + _d_isigma5__q_r*_pd__221)
        _x154 = 0.9336096058311416*_pd__221
        _d_ifq5__q_th = (_d_D__q_th*_pd__218 + _d_D__q_th*_x154 + _d_P5__q_th*_pd__219
            + _d_iPsi5__q_th*_pd__220)
        _d_ifq5__q_thd = (_d_D__q_thd*_pd__218 + _d_D__q_thd*_x154 + _d_P5__q_thd*_pd__219
            + _d_iPsi5__q_thd*_pd__220)
        _d_ifq5__k_d = _d_D__k_d*_pd__218 + _d_D__k_d*_x154 + _d_P5__k_d*_pd__219 + _d_iPsi5__k_d*_pd__220
        _d_ifq5__guess_q_th = (_d_D__guess_q_th*_pd__218 + _d_D__guess_q_th*_x154 + _d_P5__guess_q_th*_pd__219
            + _d_iPsi5__guess_q_th*_pd__220)
        _d_ifq5__guess_q_thd = (_d_D__guess_q_thd*_pd__218 + _d_D__guess_q_thd*_x154
            + _d_P5__guess_q_thd*_pd__219 + _d_iPsi5__guess_q_thd*_pd__220)
        _x155 = _x149*_x95
        _x156 = _x155*_x75
        _ifp5 = _x156*_x66
        _x157 = _x66*_x75
        _pd__222 = _x149*_x157*_x99
        _pd__223 = _x155*_x66*_x67
        _pd__224 = -_x100*_x150*_x157
        _pd__225 = _x156
        _d_ifp5__q_r = (_d_D__q_r*_pd__222 + _d_Q5__q_r*_pd__223 + _d_iPsi5__q_r*_pd__224
            + _d_isigma5__q_r*_pd__225)
        _x158 = 0.9336096058311416*_pd__225
        _d_ifp5__q_th = (_d_D__q_th*_pd__222 + _d_D__q_th*_x158 + _d_Q5__q_th*_pd__223
            + _d_iPsi5__q_th*_pd__224)
        _d_ifp5__q_thd = (_d_D__q_thd*_pd__222 + _d_D__q_thd*_x158 + _d_Q5__q_thd*_pd__223
            + _d_iPsi5__q_thd*_pd__224)
        _d_ifp5__k_d = _d_D__k_d*_pd__222 + _d_D__k_d*_x158 + _d_Q5__k_d*_pd__223 + _d_iPsi5__k_d*_pd__224
        _d_ifp5__guess_q_th = (_d_D__guess_q_th*_pd__222 + _d_D__guess_q_th*_x158 + _d_Q5__guess_q_th*_pd__223
            + _d_iPsi5__guess_q_th*_pd__224)
        _d_ifp5__guess_q_thd = (_d_D__guess_q_thd*_pd__222 + _d_D__guess_q_thd*_x158
            + _d_Q5__guess_q_thd*_pd__223 + _d_iPsi5__guess_q_thd*_pd__224)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi3 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi4 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi5 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = (0.04283112309479259*_ifq0 - 0.014763725997197413*_ifq1 + 0.009325050706477751*_ifq2
            - 0.005668858049483512*_ifq3 + 0.002854433315099335*_ifq4 - 0.0008127801712647621*_ifq5 + q_th)
        _d_Q0__next__q_r = (0.04283112309479259*_d_ifq0__q_r - 0.014763725997197413*_d_ifq1__q_r
            + 0.009325050706477751*_d_ifq2__q_r - 0.005668858049483512*_d_ifq3__q_r
            + 0.002854433315099335*_d_ifq4__q_r - 0.0008127801712647621*_d_ifq5__q_r)
        _d_Q0__next__q_th = (0.04283112309479259*_d_ifq0__q_th - 0.014763725997197413*_d_ifq1__q_th
            + 0.009325050706477751*_d_ifq2__q_th - 0.005668858049483512*_d_ifq3__q_th
            + 0.002854433315099335*_d_ifq4__q_th - 0.0008127801712647621*_d_ifq5__q_th + 1.0)
        _d_Q0__next__q_thd = (0.04283112309479259*_d_ifq0__q_thd - 0.014763725997197413*_d_ifq1__q_thd
            + 0.009325050706477751*_d_ifq2__q_thd - 0.005668858049483512*_d_ifq3__q_thd
            + 0.002854433315099335*_d_ifq4__q_thd - 0.0008127801712647621*_d_ifq5__q_thd)
        _d_Q0__next__k_d = (0.04283112309479259*_d_ifq0__k_d - 0.014763725997197413*_d_ifq1__k_d
            + 0.009325050706477751*_d_ifq2__k_d - 0.005668858049483512*_d_ifq3__k_d
            + 0.002854433315099335*_d_ifq4__k_d - 0.0008127801712647621*_d_ifq5__k_d)
        _d_Q0__next__guess_q_th = (0.04283112309479259*_d_ifq0__guess_q_th
            - 0.014763725997197413*_d_ifq1__guess_q_th + 0.009325050706477751*_d_ifq2__guess_q_th
            - 0.005668858049483512*_d_ifq3__guess_q_th + 0.002854433315099335*_d_ifq4__guess_q_th
            - 0.0008127801712647621*_d_ifq5__guess_q_th)
        _d_Q0__next__guess_q_thd = (0.04283112309479259*_d_ifq0__guess_q_thd
            - 0.014763725997197413*_d_ifq1__guess_q_thd + 0.009325050706477751*_d_ifq2__guess_q_thd
            - 0.005668858049483512*_d_ifq3__guess_q_thd + 0.002854433315099335*_d_ifq4__guess_q_thd
            - 0.0008127801712647621*_d_ifq5__guess_q_thd)
        _Q1__next = (0.09267349143037887*_ifq0 + 0.09019039326203465*_ifq1 - 0.020300102293239586*_ifq2
            + 0.010363156240246424*_ifq3 - 0.004887192928037671*_ifq4 + 0.0013555610554850618*_ifq5 + q_th)
        _d_Q1__next__q_r = (0.09267349143037887*_d_ifq0__q_r + 0.09019039326203465*_d_ifq1__q_r
            - 0.020300102293239586*_d_ifq2__q_r + 0.010363156240246424*_d_ifq3__q_r
            - 0.004887192928037671*_d_ifq4__q_r + 0.0013555610554850618*_d_ifq5__q_r)
        _d_Q1__next__q_th = (0.09267349143037887*_d_ifq0__q_th + 0.09019039326203465*_d_ifq1__q_th
            - 0.020300102293239586*_d_ifq2__q_th + 0.010363156240246424*_d_ifq3__q_th
            - 0.004887192928037671*_d_ifq4__q_th + 0.0013555610554850618*_d_ifq5__q_th + 1.0)
        _d_Q1__next__q_thd = (0.09267349143037887*_d_ifq0__q_thd + 0.09019039326203465*_d_ifq1__q_thd
            - 0.020300102293239586*_d_ifq2__q_thd + 0.010363156240246424*_d_ifq3__q_thd
            - 0.004887192928037671*_d_ifq4__q_thd + 0.0013555610554850618*_d_ifq5__q_thd)
        _d_Q1__next__k_d = (0.09267349143037887*_d_ifq0__k_d + 0.09019039326203465*_d_ifq1__k_d
            - 0.020300102293239586*_d_ifq2__k_d + 0.010363156240246424*_d_ifq3__k_d
            - 0.004887192928037671*_d_ifq4__k_d + 0.0013555610554850618*_d_ifq5__k_d)
        _d_Q1__next__guess_q_th = (0.09267349143037887*_d_ifq0__guess_q_th
            + 0.09019039326203465*_d_ifq1__guess_q_th - 0.020300102293239586*_d_ifq2__guess_q_th
            + 0.010363156240246424*_d_ifq3__guess_q_th - 0.004887192928037671*_d_ifq4__guess_q_th
            + 0.0013555610554850618*_d_ifq5__guess_q_th)
        _d_Q1__next__guess_q_thd = (0.09267349143037887*_d_ifq0__guess_q_thd
            + 0.09019039326203465*_d_ifq1__guess_q_thd - 0.020300102293239586*_d_ifq2__guess_q_thd
            + 0.010363156240246424*_d_ifq3__guess_q_thd - 0.004887192928037671*_d_ifq4__guess_q_thd
            + 0.0013555610554850618*_d_ifq5__guess_q_thd)
        _Q2__next = (0.08224792261284387*_ifq0 + 0.196032162333245*_ifq1 + 0.11697848364317276*_ifq2
            - 0.020482527745656096*_ifq3 + 0.007989991899662336*_ifq4 - 0.002075625784866334*_ifq5 + q_th)
        _d_Q2__next__q_r = (0.08224792261284387*_d_ifq0__q_r + 0.196032162333245*_d_ifq1__q_r
            + 0.11697848364317276*_d_ifq2__q_r - 0.020482527745656096*_d_ifq3__q_r
            + 0.007989991899662336*_d_ifq4__q_r - 0.002075625784866334*_d_ifq5__q_r)
        _d_Q2__next__q_th = (0.08224792261284387*_d_ifq0__q_th + 0.196032162333245*_d_ifq1__q_th
            + 0.11697848364317276*_d_ifq2__q_th - 0.020482527745656096*_d_ifq3__q_th
            + 0.007989991899662336*_d_ifq4__q_th - 0.002075625784866334*_d_ifq5__q_th + 1.0)
        _d_Q2__next__q_thd = (0.08224792261284387*_d_ifq0__q_thd + 0.196032162333245*_d_ifq1__q_thd
            + 0.11697848364317276*_d_ifq2__q_thd - 0.020482527745656096*_d_ifq3__q_thd
            + 0.007989991899662336*_d_ifq4__q_thd - 0.002075625784866334*_d_ifq5__q_thd)
        _d_Q2__next__k_d = (0.08224792261284387*_d_ifq0__k_d + 0.196032162333245*_d_ifq1__k_d
            + 0.11697848364317276*_d_ifq2__k_d - 0.020482527745656096*_d_ifq3__k_d
            + 0.007989991899662336*_d_ifq4__k_d - 0.002075625784866334*_d_ifq5__k_d)
        _d_Q2__next__guess_q_th = (0.08224792261284387*_d_ifq0__guess_q_th
            + 0.196032162333245*_d_ifq1__guess_q_th + 0.11697848364317276*_d_ifq2__guess_q_th
            - 0.020482527745656096*_d_ifq3__guess_q_th + 0.007989991899662336*_d_ifq4__guess_q_th
            - 0.002075625784866334*_d_ifq5__guess_q_th)
        _d_Q2__next__guess_q_thd = (0.08224792261284387*_d_ifq0__guess_q_thd
            + 0.196032162333245*_d_ifq1__guess_q_thd + 0.11697848364317276*_d_ifq2__guess_q_thd
            - 0.020482527745656096*_d_ifq3__guess_q_thd + 0.007989991899662336*_d_ifq4__guess_q_thd
            - 0.002075625784866334*_d_ifq5__guess_q_thd)
        _Q3__next = (0.0877378719744515*_ifq0 + 0.17239079462440696*_ifq1 + 0.25443949503200164*_ifq2
            + 0.11697848364317276*_ifq3 - 0.0156513758091757*_ifq4 + 0.0034143235767412987*_ifq5 + q_th)
        _d_Q3__next__q_r = (0.0877378719744515*_d_ifq0__q_r + 0.17239079462440696*_d_ifq1__q_r
            + 0.25443949503200164*_d_ifq2__q_r + 0.11697848364317276*_d_ifq3__q_r
            - 0.0156513758091757*_d_ifq4__q_r + 0.0034143235767412987*_d_ifq5__q_r)
        _d_Q3__next__q_th = (0.0877378719744515*_d_ifq0__q_th + 0.17239079462440696*_d_ifq1__q_th
            + 0.25443949503200164*_d_ifq2__q_th + 0.11697848364317276*_d_ifq3__q_th
            - 0.0156513758091757*_d_ifq4__q_th + 0.0034143235767412987*_d_ifq5__q_th + 1.0)
        _d_Q3__next__q_thd = (0.0877378719744515*_d_ifq0__q_thd + 0.17239079462440696*_d_ifq1__q_thd
            + 0.25443949503200164*_d_ifq2__q_thd + 0.11697848364317276*_d_ifq3__q_thd
            - 0.0156513758091757*_d_ifq4__q_thd + 0.0034143235767412987*_d_ifq5__q_thd)
        _d_Q3__next__k_d = (0.0877378719744515*_d_ifq0__k_d + 0.17239079462440696*_d_ifq1__k_d
            + 0.25443949503200164*_d_ifq2__k_d + 0.11697848364317276*_d_ifq3__k_d
            - 0.0156513758091757*_d_ifq4__k_d + 0.0034143235767412987*_d_ifq5__k_d)
        _d_Q3__next__guess_q_th = (0.0877378719744515*_d_ifq0__guess_q_th
            + 0.17239079462440696*_d_ifq1__guess_q_th + 0.25443949503200164*_d_ifq2__guess_q_th
            + 0.11697848364317276*_d_ifq3__guess_q_th - 0.0156513758091757*_d_ifq4__guess_q_th
            + 0.0034143235767412987*_d_ifq5__guess_q_th)
        _d_Q3__next__guess_q_thd = (0.0877378719744515*_d_ifq0__guess_q_thd
            + 0.17239079462440696*_d_ifq1__guess_q_thd + 0.25443949503200164*_d_ifq2__guess_q_thd
            + 0.11697848364317276*_d_ifq3__guess_q_thd - 0.0156513758091757*_d_ifq4__guess_q_thd
            + 0.0034143235767412987*_d_ifq5__guess_q_thd)
        _Q4__next = (0.08430668513410011*_ifq0 + 0.18526797945210696*_ifq1 + 0.2235938110460991*_ifq2
            + 0.2542570695795851*_ifq3 + 0.09019039326203465*_ifq4 - 0.007011245240793691*_ifq5 + q_th)
        _d_Q4__next__q_r = (0.08430668513410011*_d_ifq0__q_r + 0.18526797945210696*_d_ifq1__q_r
            + 0.2235938110460991*_d_ifq2__q_r + 0.2542570695795851*_d_ifq3__q_r
            + 0.09019039326203465*_d_ifq4__q_r - 0.007011245240793691*_d_ifq5__q_r)
        _d_Q4__next__q_th = (0.08430668513410011*_d_ifq0__q_th + 0.18526797945210696*_d_ifq1__q_th
            + 0.2235938110460991*_d_ifq2__q_th + 0.2542570695795851*_d_ifq3__q_th
            + 0.09019039326203465*_d_ifq4__q_th - 0.007011245240793691*_d_ifq5__q_th + 1.0)
        _d_Q4__next__q_thd = (0.08430668513410011*_d_ifq0__q_thd + 0.18526797945210696*_d_ifq1__q_thd
            + 0.2235938110460991*_d_ifq2__q_thd + 0.2542570695795851*_d_ifq3__q_thd
            + 0.09019039326203465*_d_ifq4__q_thd - 0.007011245240793691*_d_ifq5__q_thd)
        _d_Q4__next__k_d = (0.08430668513410011*_d_ifq0__k_d + 0.18526797945210696*_d_ifq1__k_d
            + 0.2235938110460991*_d_ifq2__k_d + 0.2542570695795851*_d_ifq3__k_d
            + 0.09019039326203465*_d_ifq4__k_d - 0.007011245240793691*_d_ifq5__k_d)
        _d_Q4__next__guess_q_th = (0.08430668513410011*_d_ifq0__guess_q_th
            + 0.18526797945210696*_d_ifq1__guess_q_th + 0.2235938110460991*_d_ifq2__guess_q_th
            + 0.2542570695795851*_d_ifq3__guess_q_th + 0.09019039326203465*_d_ifq4__guess_q_th
            - 0.007011245240793691*_d_ifq5__guess_q_th)
        _d_Q4__next__guess_q_thd = (0.08430668513410011*_d_ifq0__guess_q_thd
            + 0.18526797945210696*_d_ifq1__guess_q_thd + 0.2235938110460991*_d_ifq2__guess_q_thd
            + 0.2542570695795851*_d_ifq3__guess_q_thd + 0.09019039326203465*_d_ifq4__guess_q_thd
            - 0.007011245240793691*_d_ifq5__guess_q_thd)
        _Q5__next = (0.08647502636084993*_ifq0 + 0.17752635320896998*_ifq1 + 0.23962582533582905*_ifq2
            + 0.22463191657986778*_ifq3 + 0.19514451252126672*_ifq4 + 0.04283112309479259*_ifq5 + q_th)
        _d_Q5__next__q_r = (0.08647502636084993*_d_ifq0__q_r + 0.17752635320896998*_d_ifq1__q_r
            + 0.23962582533582905*_d_ifq2__q_r + 0.22463191657986778*_d_ifq3__q_r
            + 0.19514451252126672*_d_ifq4__q_r + 0.04283112309479259*_d_ifq5__q_r)
        _d_Q5__next__q_th = (0.08647502636084993*_d_ifq0__q_th + 0.17752635320896998*_d_ifq1__q_th
            + 0.23962582533582905*_d_ifq2__q_th + 0.22463191657986778*_d_ifq3__q_th
            + 0.19514451252126672*_d_ifq4__q_th + 0.04283112309479259*_d_ifq5__q_th + 1.0)
        _d_Q5__next__q_thd = (0.08647502636084993*_d_ifq0__q_thd + 0.17752635320896998*_d_ifq1__q_thd
            + 0.23962582533582905*_d_ifq2__q_thd + 0.22463191657986778*_d_ifq3__q_thd
            + 0.19514451252126672*_d_ifq4__q_thd + 0.04283112309479259*_d_ifq5__q_thd)
        _d_Q5__next__k_d = (0.08647502636084993*_d_ifq0__k_d + 0.17752635320896998*_d_ifq1__k_d
            + 0.23962582533582905*_d_ifq2__k_d + 0.22463191657986778*_d_ifq3__k_d
            + 0.19514451252126672*_d_ifq4__k_d + 0.04283112309479259*_d_ifq5__k_d)
        _d_Q5__next__guess_q_th = (0.08647502636084993*_d_ifq0__guess_q_th
            + 0.17752635320896998*_d_ifq1__guess_q_th + 0.23962582533582905*_d_ifq2__guess_q_th
            + 0.22463191657986778*_d_ifq3__guess_q_th + 0.19514451252126672*_d_ifq4__guess_q_th
            + 0.04283112309479259*_d_ifq5__guess_q_th)
        _d_Q5__next__guess_q_thd = (0.08647502636084993*_d_ifq0__guess_q_thd
            + 0.17752635320896998*_d_ifq1__guess_q_thd + 0.23962582533582905*_d_ifq2__guess_q_thd
            + 0.22463191657986778*_d_ifq3__guess_q_thd + 0.19514451252126672*_d_ifq4__guess_q_thd
            + 0.04283112309479259*_d_ifq5__guess_q_thd)
        _x165 = m*q_r**2
        _x166 = _x165*q_thd
        _P0__next = (0.04283112309479259*_ifp0 - 0.014763725997197413*_ifp1 + 0.009325050706477751*_ifp2
            - 0.005668858049483512*_ifp3 + 0.002854433315099335*_ifp4 - 0.0008127801712647621*_ifp5 + _x166)
        _x167 = 2.0*m*q_r*q_thd
        _d_P0__next__q_r = (0.04283112309479259*_d_ifp0__q_r - 0.014763725997197413*_d_ifp1__q_r
            + 0.009325050706477751*_d_ifp2__q_r - 0.005668858049483512*_d_ifp3__q_r
            + 0.002854433315099335*_d_ifp4__q_r - 0.0008127801712647621*_d_ifp5__q_r + _x167)
        _d_P0__next__q_th = (0.04283112309479259*_d_ifp0__q_th - 0.014763725997197413*_d_ifp1__q_th
            + 0.009325050706477751*_d_ifp2__q_th - 0.005668858049483512*_d_ifp3__q_th
            + 0.002854433315099335*_d_ifp4__q_th - 0.0008127801712647621*_d_ifp5__q_th)
        _d_P0__next__q_thd = (0.04283112309479259*_d_ifp0__q_thd - 0.014763725997197413*_d_ifp1__q_thd
            + 0.009325050706477751*_d_ifp2__q_thd - 0.005668858049483512*_d_ifp3__q_thd
            + 0.002854433315099335*_d_ifp4__q_thd - 0.0008127801712647621*_d_ifp5__q_thd + _x165)
        _d_P0__next__k_d = (0.04283112309479259*_d_ifp0__k_d - 0.014763725997197413*_d_ifp1__k_d
            + 0.009325050706477751*_d_ifp2__k_d - 0.005668858049483512*_d_ifp3__k_d
            + 0.002854433315099335*_d_ifp4__k_d - 0.0008127801712647621*_d_ifp5__k_d)
        _d_P0__next__guess_q_th = (0.04283112309479259*_d_ifp0__guess_q_th
            - 0.014763725997197413*_d_ifp1__guess_q_th + 0.009325050706477751*_d_ifp2__guess_q_th
            - 0.005668858049483512*_d_ifp3__guess_q_th + 0.002854433315099335*_d_ifp4__guess_q_th
            - 0.0008127801712647621*_d_ifp5__guess_q_th)
        _d_P0__next__guess_q_thd = (0.04283112309479259*_d_ifp0__guess_q_thd
            - 0.014763725997197413*_d_ifp1__guess_q_thd + 0.009325050706477751*_d_ifp2__guess_q_thd
            - 0.005668858049483512*_d_ifp3__guess_q_thd + 0.002854433315099335*_d_ifp4__guess_q_thd
            - 0.0008127801712647621*_d_ifp5__guess_q_thd)
        _P1__next = (0.09267349143037887*_ifp0 + 0.09019039326203465*_ifp1 - 0.020300102293239586*_ifp2
            + 0.010363156240246424*_ifp3 - 0.004887192928037671*_ifp4 + 0.0013555610554850618*_ifp5 + _x166)
        _d_P1__next__q_r = (0.09267349143037887*_d_ifp0__q_r + 0.09019039326203465*_d_ifp1__q_r
            - 0.020300102293239586*_d_ifp2__q_r + 0.010363156240246424*_d_ifp3__q_r
            - 0.004887192928037671*_d_ifp4__q_r + 0.0013555610554850618*_d_ifp5__q_r + _x167)
        _d_P1__next__q_th = (0.09267349143037887*_d_ifp0__q_th + 0.09019039326203465*_d_ifp1__q_th
            - 0.020300102293239586*_d_ifp2__q_th + 0.010363156240246424*_d_ifp3__q_th
            - 0.004887192928037671*_d_ifp4__q_th + 0.0013555610554850618*_d_ifp5__q_th)
        _d_P1__next__q_thd = (0.09267349143037887*_d_ifp0__q_thd + 0.09019039326203465*_d_ifp1__q_thd
            - 0.020300102293239586*_d_ifp2__q_thd + 0.010363156240246424*_d_ifp3__q_thd
            - 0.004887192928037671*_d_ifp4__q_thd + 0.0013555610554850618*_d_ifp5__q_thd + _x165)
        _d_P1__next__k_d = (0.09267349143037887*_d_ifp0__k_d + 0.09019039326203465*_d_ifp1__k_d
            - 0.020300102293239586*_d_ifp2__k_d + 0.010363156240246424*_d_ifp3__k_d
            - 0.004887192928037671*_d_ifp4__k_d + 0.0013555610554850618*_d_ifp5__k_d)
        _d_P1__next__guess_q_th = (0.09267349143037887*_d_ifp0__guess_q_th
            + 0.09019039326203465*_d_ifp1__guess_q_th - 0.020300102293239586*_d_ifp2__guess_q_th
            + 0.010363156240246424*_d_ifp3__guess_q_th - 0.004887192928037671*_d_ifp4__guess_q_th
            + 0.0013555610554850618*_d_ifp5__guess_q_th)
        _d_P1__next__guess_q_thd = (0.09267349143037887*_d_ifp0__guess_q_thd
            + 0.09019039326203465*_d_ifp1__guess_q_thd - 0.020300102293239586*_d_ifp2__guess_q_thd
            + 0.010363156240246424*_d_ifp3__guess_q_thd - 0.004887192928037671*_d_ifp4__guess_q_thd
            + 0.0013555610554850618*_d_ifp5__guess_q_thd)
        _P2__next = (0.08224792261284387*_ifp0 + 0.196032162333245*_ifp1 + 0.11697848364317276*_ifp2
            - 0.020482527745656096*_ifp3 + 0.007989991899662336*_ifp4 - 0.002075625784866334*_ifp5 + _x166)
        _d_P2__next__q_r = (0.08224792261284387*_d_ifp0__q_r + 0.196032162333245*_d_ifp1__q_r
            + 0.11697848364317276*_d_ifp2__q_r - 0.020482527745656096*_d_ifp3__q_r
            + 0.007989991899662336*_d_ifp4__q_r - 0.002075625784866334*_d_ifp5__q_r + _x167)
        _d_P2__next__q_th = (0.08224792261284387*_d_ifp0__q_th + 0.196032162333245*_d_ifp1__q_th
            + 0.11697848364317276*_d_ifp2__q_th - 0.020482527745656096*_d_ifp3__q_th
            + 0.007989991899662336*_d_ifp4__q_th - 0.002075625784866334*_d_ifp5__q_th)
        _d_P2__next__q_thd = (0.08224792261284387*_d_ifp0__q_thd + 0.196032162333245*_d_ifp1__q_thd
            + 0.11697848364317276*_d_ifp2__q_thd - 0.020482527745656096*_d_ifp3__q_thd
            + 0.007989991899662336*_d_ifp4__q_thd - 0.002075625784866334*_d_ifp5__q_thd + _x165)
        _d_P2__next__k_d = (0.08224792261284387*_d_ifp0__k_d + 0.196032162333245*_d_ifp1__k_d
            + 0.11697848364317276*_d_ifp2__k_d - 0.020482527745656096*_d_ifp3__k_d
            + 0.007989991899662336*_d_ifp4__k_d - 0.002075625784866334*_d_ifp5__k_d)
        _d_P2__next__guess_q_th = (0.08224792261284387*_d_ifp0__guess_q_th
            + 0.196032162333245*_d_ifp1__guess_q_th + 0.11697848364317276*_d_ifp2__guess_q_th
            - 0.020482527745656096*_d_ifp3__guess_q_th + 0.007989991899662336*_d_ifp4__guess_q_th
            - 0.002075625784866334*_d_ifp5__guess_q_th)
        _d_P2__next__guess_q_thd = (0.08224792261284387*_d_ifp0__guess_q_thd
            + 0.196032162333245*_d_ifp1__guess_q_thd + 0.11697848364317276*_d_ifp2__guess_q_thd
            - 0.020482527745656096*_d_ifp3__guess_q_thd + 0.007989991899662336*_d_ifp4__guess_q_thd
            - 0.002075625784866334*_d_ifp5__guess_q_thd)
        _P3__next = (0.0877378719744515*_ifp0 + 0.17239079462440696*_ifp1 + 0.25443949503200164*_ifp2
            + 0.11697848364317276*_ifp3 - 0.0156513758091757*_ifp4 + 0.0034143235767412987*_ifp5 + _x166)
        _d_P3__next__q_r = (0.0877378719744515*_d_ifp0__q_r + 0.17239079462440696*_d_ifp1__q_r
            + 0.25443949503200164*_d_ifp2__q_r + 0.11697848364317276*_d_ifp3__q_r
            - 0.0156513758091757*_d_ifp4__q_r + 0.0034143235767412987*_d_ifp5__q_r + _x167)
        _d_P3__next__q_th = (0.0877378719744515*_d_ifp0__q_th + 0.17239079462440696*_d_ifp1__q_th
            + 0.25443949503200164*_d_ifp2__q_th + 0.11697848364317276*_d_ifp3__q_th
            - 0.0156513758091757*_d_ifp4__q_th + 0.0034143235767412987*_d_ifp5__q_th)
        _d_P3__next__q_thd = (0.0877378719744515*_d_ifp0__q_thd + 0.17239079462440696*_d_ifp1__q_thd
            + 0.25443949503200164*_d_ifp2__q_thd + 0.11697848364317276*_d_ifp3__q_thd
            - 0.0156513758091757*_d_ifp4__q_thd + 0.0034143235767412987*_d_ifp5__q_thd + _x165)
        _d_P3__next__k_d = (0.0877378719744515*_d_ifp0__k_d + 0.17239079462440696*_d_ifp1__k_d
            + 0.25443949503200164*_d_ifp2__k_d + 0.11697848364317276*_d_ifp3__k_d
            - 0.0156513758091757*_d_ifp4__k_d + 0.0034143235767412987*_d_ifp5__k_d)
        _d_P3__next__guess_q_th = (0.0877378719744515*_d_ifp0__guess_q_th
            + 0.17239079462440696*_d_ifp1__guess_q_th + 0.25443949503200164*_d_ifp2__guess_q_th
            + 0.11697848364317276*_d_ifp3__guess_q_th - 0.0156513758091757*_d_ifp4__guess_q_th
            + 0.0034143235767412987*_d_ifp5__guess_q_th)
        _d_P3__next__guess_q_thd = (0.0877378719744515*_d_ifp0__guess_q_thd
            + 0.17239079462440696*_d_ifp1__guess_q_thd + 0.25443949503200164*_d_ifp2__guess_q_thd
            + 0.11697848364317276*_d_ifp3__guess_q_thd - 0.0156513758091757*_d_ifp4__guess_q_thd
            + 0.0034143235767412987*_d_ifp5__guess_q_thd)
        _P4__next = (0.08430668513410011*_ifp0 + 0.18526797945210696*_ifp1 + 0.2235938110460991*_ifp2
            + 0.2542570695795851*_ifp3 + 0.09019039326203465*_ifp4 - 0.007011245240793691*_ifp5 + _x166)
        _d_P4__next__q_r = (0.08430668513410011*_d_ifp0__q_r + 0.18526797945210696*_d_ifp1__q_r
            + 0.2235938110460991*_d_ifp2__q_r + 0.2542570695795851*_d_ifp3__q_r
            + 0.09019039326203465*_d_ifp4__q_r - 0.007011245240793691*_d_ifp5__q_r + _x167)
        _d_P4__next__q_th = (0.08430668513410011*_d_ifp0__q_th + 0.18526797945210696*_d_ifp1__q_th
            + 0.2235938110460991*_d_ifp2__q_th + 0.2542570695795851*_d_ifp3__q_th
            + 0.09019039326203465*_d_ifp4__q_th - 0.007011245240793691*_d_ifp5__q_th)
        _d_P4__next__q_thd = (0.08430668513410011*_d_ifp0__q_thd + 0.18526797945210696*_d_ifp1__q_thd
            + 0.2235938110460991*_d_ifp2__q_thd + 0.2542570695795851*_d_ifp3__q_thd
            + 0.09019039326203465*_d_ifp4__q_thd - 0.007011245240793691*_d_ifp5__q_thd + _x165)
        _d_P4__next__k_d = (0.08430668513410011*_d_ifp0__k_d + 0.18526797945210696*_d_ifp1__k_d
            + 0.2235938110460991*_d_ifp2__k_d + 0.2542570695795851*_d_ifp3__k_d
            + 0.09019039326203465*_d_ifp4__k_d - 0.007011245240793691*_d_ifp5__k_d)
        _d_P4__next__guess_q_th = (0.08430668513410011*_d_ifp0__guess_q_th
            + 0.18526797945210696*_d_ifp1__guess_q_th + 0.2235938110460991*_d_ifp2__guess_q_th
            + 0.2542570695795851*_d_ifp3__guess_q_th + 0.09019039326203465*_d_ifp4__guess_q_th
            - 0.007011245240793691*_d_ifp5__guess_q_th)
        _d_P4__next__guess_q_thd = (0.08430668513410011*_d_ifp0__guess_q_thd
            + 0.18526797945210696*_d_ifp1__guess_q_thd + 0.2235938110460991*_d_ifp2__guess_q_thd
            + 0.2542570695795851*_d_ifp3__guess_q_thd + 0.09019039326203465*_d_ifp4__guess_q_thd
            - 0.007011245240793691*_d_ifp5__guess_q_thd)
        _P5__next = (0.08647502636084993*_ifp0 + 0.17752635320896998*_ifp1 + 0.23962582533582905*_ifp2
            + 0.22463191657986778*_ifp3 + 0.19514451252126672*_ifp4 + 0.04283112309479259*_ifp5 + _x166)
        _d_P5__next__q_r = (0.08647502636084993*_d_ifp0__q_r + 0.17752635320896998*_d_ifp1__q_r
            + 0.23962582533582905*_d_ifp2__q_r + 0.22463191657986778*_d_ifp3__q_r
            + 0.19514451252126672*_d_ifp4__q_r + 0.04283112309479259*_d_ifp5__q_r + _x167)
        _d_P5__next__q_th = (0.08647502636084993*_d_ifp0__q_th + 0.17752635320896998*_d_ifp1__q_th
            + 0.23962582533582905*_d_ifp2__q_th + 0.22463191657986778*_d_ifp3__q_th
            + 0.19514451252126672*_d_ifp4__q_th + 0.04283112309479259*_d_ifp5__q_th)
        _d_P5__next__q_thd = (0.08647502636084993*_d_ifp0__q_thd + 0.17752635320896998*_d_ifp1__q_thd
            + 0.23962582533582905*_d_ifp2__q_thd + 0.22463191657986778*_d_ifp3__q_thd
            + 0.19514451252126672*_d_ifp4__q_thd + 0.04283112309479259*_d_ifp5__q_thd + _x165)
        _d_P5__next__k_d = (0.08647502636084993*_d_ifp0__k_d + 0.17752635320896998*_d_ifp1__k_d
            + 0.23962582533582905*_d_ifp2__k_d + 0.22463191657986778*_d_ifp3__k_d
            + 0.19514451252126672*_d_ifp4__k_d + 0.04283112309479259*_d_ifp5__k_d)
        _d_P5__next__guess_q_th = (0.08647502636084993*_d_ifp0__guess_q_th
            + 0.17752635320896998*_d_ifp1__guess_q_th + 0.23962582533582905*_d_ifp2__guess_q_th
            + 0.22463191657986778*_d_ifp3__guess_q_th + 0.19514451252126672*_d_ifp4__guess_q_th
            + 0.04283112309479259*_d_ifp5__guess_q_th)
        _d_P5__next__guess_q_thd = (0.08647502636084993*_d_ifp0__guess_q_thd
            + 0.17752635320896998*_d_ifp1__guess_q_thd + 0.23962582533582905*_d_ifp2__guess_q_thd
            + 0.22463191657986778*_d_ifp3__guess_q_thd + 0.19514451252126672*_d_ifp4__guess_q_thd
            + 0.04283112309479259*_d_ifp5__guess_q_thd)
        _n0_13 = _d_D__q_r
        _n0_14 = _d_D__q_th
        _n0_15 = _d_D__q_thd
        _n0_16 = _d_D__k_d
        _n0_17 = _d_D__guess_q_th
        _n0_18 = _d_D__guess_q_thd
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_D__next - _D) <= tol*(l0)) and (abs(_Q0__next - _Q0) <= tol*(1.0))
            and (abs(_Q1__next - _Q1) <= tol*(1.0)) and (abs(_Q2__next - _Q2) <= tol*(1.0)) and (abs(_Q3__next
            - _Q3) <= tol*(1.0)) and (abs(_Q4__next - _Q4) <= tol*(1.0)) and (abs(_Q5__next - _Q5)
            <= tol*(1.0)) and (abs(_P0__next - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P1__next - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P2__next - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P3__next - _P3) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P4__next - _P4) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_P5__next - _P5) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _pkn0 = (_D__next, _Q0__next, _Q1__next, _Q2__next, _Q3__next, _Q4__next, _Q5__next, _P0__next,
            _P1__next, _P2__next, _P3__next, _P4__next, _P5__next, _n0_13, _n0_14, _n0_15, _n0_16, _n0_17,
            _n0_18, _d_Q0__next__q_r, _d_Q0__next__q_th, _d_Q0__next__q_thd, _d_Q0__next__k_d,
            _d_Q0__next__guess_q_th, _d_Q0__next__guess_q_thd, _d_Q1__next__q_r, _d_Q1__next__q_th,
            _d_Q1__next__q_thd, _d_Q1__next__k_d, _d_Q1__next__guess_q_th, _d_Q1__next__guess_q_thd,
            _d_Q2__next__q_r, _d_Q2__next__q_th, _d_Q2__next__q_thd, _d_Q2__next__k_d,
            _d_Q2__next__guess_q_th, _d_Q2__next__guess_q_thd, _d_Q3__next__q_r, _d_Q3__next__q_th,
            _d_Q3__next__q_thd, _d_Q3__next__k_d, _d_Q3__next__guess_q_th, _d_Q3__next__guess_q_thd,
            _d_Q4__next__q_r, _d_Q4__next__q_th, _d_Q4__next__q_thd, _d_Q4__next__k_d,
            _d_Q4__next__guess_q_th, _d_Q4__next__guess_q_thd, _d_Q5__next__q_r, _d_Q5__next__q_th,
            _d_Q5__next__q_thd, _d_Q5__next__k_d, _d_Q5__next__guess_q_th, _d_Q5__next__guess_q_thd,
            _d_P0__next__q_r, _d_P0__next__q_th, _d_P0__next__q_thd, _d_P0__next__k_d,
            _d_P0__next__guess_q_th, _d_P0__next__guess_q_thd, _d_P1__next__q_r, _d_P1__next__q_th,
            _d_P1__next__q_thd, _d_P1__next__k_d, _d_P1__next__guess_q_th, _d_P1__next__guess_q_thd,
            _d_P2__next__q_r, _d_P2__next__q_th, _d_P2__next__q_thd, _d_P2__next__k_d,
            _d_P2__next__guess_q_th, _d_P2__next__guess_q_thd, _d_P3__next__q_r, _d_P3__next__q_th,
            _d_P3__next__q_thd, _d_P3__next__k_d, _d_P3__next__guess_q_th, _d_P3__next__guess_q_thd,
            _d_P4__next__q_r, _d_P4__next__q_th, _d_P4__next__q_thd, _d_P4__next__k_d,
            _d_P4__next__guess_q_th, _d_P4__next__guess_q_thd, _d_P5__next__q_r, _d_P5__next__q_th,
            _d_P5__next__q_thd, _d_P5__next__k_d, _d_P5__next__guess_q_th, _d_P5__next__guess_q_thd, )
        _pk0 = _pkn0
        _passes += 1.0
    _work = (0.0028924065498159377*_iF0 + 0.030555658668093604*_iF1 + 0.08906517308699231*_iF2
        + 0.14489179419935322*_iF3 + 0.1498251278559757*_iF4 + 0.08276983963976924*_iF5)
    _d_work__q_r = (0.0028924065498159377*_d_iF0__q_r + 0.030555658668093604*_d_iF1__q_r
        + 0.08906517308699231*_d_iF2__q_r + 0.14489179419935322*_d_iF3__q_r + 0.1498251278559757*_d_iF4__q_r
        + 0.08276983963976924*_d_iF5__q_r)
    _d_work__q_th = (0.0028924065498159377*_d_iF0__q_th + 0.030555658668093604*_d_iF1__q_th
        + 0.08906517308699231*_d_iF2__q_th + 0.14489179419935322*_d_iF3__q_th
        + 0.1498251278559757*_d_iF4__q_th + 0.08276983963976924*_d_iF5__q_th)
    _d_work__q_thd = (0.0028924065498159377*_d_iF0__q_thd + 0.030555658668093604*_d_iF1__q_thd
        + 0.08906517308699231*_d_iF2__q_thd + 0.14489179419935322*_d_iF3__q_thd
        + 0.1498251278559757*_d_iF4__q_thd + 0.08276983963976924*_d_iF5__q_thd)
    _d_work__k_d = (0.0028924065498159377*_d_iF0__k_d + 0.030555658668093604*_d_iF1__k_d
        + 0.08906517308699231*_d_iF2__k_d + 0.14489179419935322*_d_iF3__k_d + 0.1498251278559757*_d_iF4__k_d
        + 0.08276983963976924*_d_iF5__k_d)
    _d_work__guess_q_th = (0.0028924065498159377*_d_iF0__guess_q_th + 0.030555658668093604*_d_iF1__guess_q_th
        + 0.08906517308699231*_d_iF2__guess_q_th + 0.14489179419935322*_d_iF3__guess_q_th
        + 0.1498251278559757*_d_iF4__guess_q_th + 0.08276983963976924*_d_iF5__guess_q_th)
    _d_work__guess_q_thd = (0.0028924065498159377*_d_iF0__guess_q_thd
        + 0.030555658668093604*_d_iF1__guess_q_thd + 0.08906517308699231*_d_iF2__guess_q_thd
        + 0.14489179419935322*_d_iF3__guess_q_thd + 0.1498251278559757*_d_iF4__guess_q_thd
        + 0.08276983963976924*_d_iF5__guess_q_thd)
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = (0.08566224618958518*_ift0 + 0.1803807865240693*_ift1 + 0.23395696728634552*_ift2
        + 0.23395696728634552*_ift3 + 0.1803807865240693*_ift4 + 0.08566224618958518*_ift5)
    d_t_half__q_r = (0.08566224618958518*_d_ift0__q_r + 0.1803807865240693*_d_ift1__q_r
        + 0.23395696728634552*_d_ift2__q_r + 0.23395696728634552*_d_ift3__q_r
        + 0.1803807865240693*_d_ift4__q_r + 0.08566224618958518*_d_ift5__q_r)
    d_t_half__q_th = (0.08566224618958518*_d_ift0__q_th + 0.1803807865240693*_d_ift1__q_th
        + 0.23395696728634552*_d_ift2__q_th + 0.23395696728634552*_d_ift3__q_th
        + 0.1803807865240693*_d_ift4__q_th + 0.08566224618958518*_d_ift5__q_th)
    d_t_half__q_thd = (0.08566224618958518*_d_ift0__q_thd + 0.1803807865240693*_d_ift1__q_thd
        + 0.23395696728634552*_d_ift2__q_thd + 0.23395696728634552*_d_ift3__q_thd
        + 0.1803807865240693*_d_ift4__q_thd + 0.08566224618958518*_d_ift5__q_thd)
    d_t_half__k_d = (0.08566224618958518*_d_ift0__k_d + 0.1803807865240693*_d_ift1__k_d
        + 0.23395696728634552*_d_ift2__k_d + 0.23395696728634552*_d_ift3__k_d
        + 0.1803807865240693*_d_ift4__k_d + 0.08566224618958518*_d_ift5__k_d)
    d_t_half__guess_q_th = (0.08566224618958518*_d_ift0__guess_q_th + 0.1803807865240693*_d_ift1__guess_q_th
        + 0.23395696728634552*_d_ift2__guess_q_th + 0.23395696728634552*_d_ift3__guess_q_th
        + 0.1803807865240693*_d_ift4__guess_q_th + 0.08566224618958518*_d_ift5__guess_q_th)
    d_t_half__guess_q_thd = (0.08566224618958518*_d_ift0__guess_q_thd
        + 0.1803807865240693*_d_ift1__guess_q_thd + 0.23395696728634552*_d_ift2__guess_q_thd
        + 0.23395696728634552*_d_ift3__guess_q_thd + 0.1803807865240693*_d_ift4__guess_q_thd
        + 0.08566224618958518*_d_ift5__guess_q_thd)
    end_q_th = (0.08566224618958518*_ifq0 + 0.1803807865240693*_ifq1 + 0.23395696728634552*_ifq2
        + 0.23395696728634552*_ifq3 + 0.1803807865240693*_ifq4 + 0.08566224618958518*_ifq5 + q_th)
    d_end_q_th__q_r = (0.08566224618958518*_d_ifq0__q_r + 0.1803807865240693*_d_ifq1__q_r
        + 0.23395696728634552*_d_ifq2__q_r + 0.23395696728634552*_d_ifq3__q_r
        + 0.1803807865240693*_d_ifq4__q_r + 0.08566224618958518*_d_ifq5__q_r)
    d_end_q_th__q_th = (0.08566224618958518*_d_ifq0__q_th + 0.1803807865240693*_d_ifq1__q_th
        + 0.23395696728634552*_d_ifq2__q_th + 0.23395696728634552*_d_ifq3__q_th
        + 0.1803807865240693*_d_ifq4__q_th + 0.08566224618958518*_d_ifq5__q_th + 1.0)
    d_end_q_th__q_thd = (0.08566224618958518*_d_ifq0__q_thd + 0.1803807865240693*_d_ifq1__q_thd
        + 0.23395696728634552*_d_ifq2__q_thd + 0.23395696728634552*_d_ifq3__q_thd
        + 0.1803807865240693*_d_ifq4__q_thd + 0.08566224618958518*_d_ifq5__q_thd)
    d_end_q_th__k_d = (0.08566224618958518*_d_ifq0__k_d + 0.1803807865240693*_d_ifq1__k_d
        + 0.23395696728634552*_d_ifq2__k_d + 0.23395696728634552*_d_ifq3__k_d
        + 0.1803807865240693*_d_ifq4__k_d + 0.08566224618958518*_d_ifq5__k_d)
    d_end_q_th__guess_q_th = (0.08566224618958518*_d_ifq0__guess_q_th + 0.1803807865240693*_d_ifq1__guess_q_th
        + 0.23395696728634552*_d_ifq2__guess_q_th + 0.23395696728634552*_d_ifq3__guess_q_th
        + 0.1803807865240693*_d_ifq4__guess_q_th + 0.08566224618958518*_d_ifq5__guess_q_th)
    d_end_q_th__guess_q_thd = (0.08566224618958518*_d_ifq0__guess_q_thd
        + 0.1803807865240693*_d_ifq1__guess_q_thd + 0.23395696728634552*_d_ifq2__guess_q_thd
        + 0.23395696728634552*_d_ifq3__guess_q_thd + 0.1803807865240693*_d_ifq4__guess_q_thd
        + 0.08566224618958518*_d_ifq5__guess_q_thd)
    end_q_r = q_r_lo
    _x168 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x168
    _pd__226 = _x168/_D
    _pd__227 = _x168/_work
    d_end_q_rd__q_r = _d_D__q_r*_pd__226 + _d_work__q_r*_pd__227
    d_end_q_rd__q_th = _d_D__q_th*_pd__226 + _d_work__q_th*_pd__227
    d_end_q_rd__q_thd = _d_D__q_thd*_pd__226 + _d_work__q_thd*_pd__227
    d_end_q_rd__k_d = _d_D__k_d*_pd__226 + _d_work__k_d*_pd__227
    d_end_q_rd__guess_q_th = _d_D__guess_q_th*_pd__226 + _d_work__guess_q_th*_pd__227
    d_end_q_rd__guess_q_thd = _d_D__guess_q_thd*_pd__226 + _d_work__guess_q_thd*_pd__227
    _x169 = q_r**2
    _x170 = q_r_lo**-2
    _x171 = _x170/m
    end_q_thd = (_x171*(0.08566224618958518*_ifp0 + 0.1803807865240693*_ifp1 + 0.23395696728634552*_ifp2
        + 0.23395696728634552*_ifp3 + 0.1803807865240693*_ifp4 + 0.08566224618958518*_ifp5 + _x169*m*q_thd))
    _x172 = 0.08566224618958518*_x171
    _pd__228 = _x172
    _x173 = 0.1803807865240693*_x171
    _pd__229 = _x173
    _x174 = 0.23395696728634552*_x171
    _pd__230 = _x174
    _pd__231 = _x174
    _pd__232 = _x173
    _pd__233 = _x172
    d_end_q_thd__q_r = (_d_ifp0__q_r*_pd__228 + _d_ifp1__q_r*_pd__229 + _d_ifp2__q_r*_pd__230
        + _d_ifp3__q_r*_pd__231 + _d_ifp4__q_r*_pd__232 + _d_ifp5__q_r*_pd__233 + 2.0*_x170*q_r*q_thd)
    d_end_q_thd__q_th = (_d_ifp0__q_th*_pd__228 + _d_ifp1__q_th*_pd__229 + _d_ifp2__q_th*_pd__230
        + _d_ifp3__q_th*_pd__231 + _d_ifp4__q_th*_pd__232 + _d_ifp5__q_th*_pd__233)
    d_end_q_thd__q_thd = (_d_ifp0__q_thd*_pd__228 + _d_ifp1__q_thd*_pd__229 + _d_ifp2__q_thd*_pd__230
        + _d_ifp3__q_thd*_pd__231 + _d_ifp4__q_thd*_pd__232 + _d_ifp5__q_thd*_pd__233 + _x169*_x170)
    d_end_q_thd__k_d = (_d_ifp0__k_d*_pd__228 + _d_ifp1__k_d*_pd__229 + _d_ifp2__k_d*_pd__230
        + _d_ifp3__k_d*_pd__231 + _d_ifp4__k_d*_pd__232 + _d_ifp5__k_d*_pd__233)
    d_end_q_thd__guess_q_th = (_d_ifp0__guess_q_th*_pd__228 + _d_ifp1__guess_q_th*_pd__229
        + _d_ifp2__guess_q_th*_pd__230 + _d_ifp3__guess_q_th*_pd__231 + _d_ifp4__guess_q_th*_pd__232
        + _d_ifp5__guess_q_th*_pd__233)
    d_end_q_thd__guess_q_thd = (_d_ifp0__guess_q_thd*_pd__228 + _d_ifp1__guess_q_thd*_pd__229
        + _d_ifp2__guess_q_thd*_pd__230 + _d_ifp3__guess_q_thd*_pd__231 + _d_ifp4__guess_q_thd*_pd__232
        + _d_ifp5__guess_q_thd*_pd__233)
    passes = _passes
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
        d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
        d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd,
        d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(q_r, q_rd, q_th, q_thd, m, l0, k_d,
        g_s, q_r_lo, guess_q_th, guess_q_thd, nodes, iterations, tol):
    """Schwind and Koditschek's iteration, decompression half, converging form (collocation in u, work form of
    p_r), and the derivatives of its outputs with respect to q_r, q_th, q_thd, k_d, guess_q_th, guess_q_thd.

    Report equations: 29, 30, 31, 32, 37, 41.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        q_r: bottom state: leg length [m]
        q_rd: bottom state: leg length rate [m/s]
        q_th: bottom state: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: bottom state: leg angle rate [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k_d: leg stiffness after the bottom k_d [N/m]
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        guess_q_th: zeroth iterate's liftoff q_th
        guess_q_thd: zeroth iterate's liftoff q_thd
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]

    Returns a tuple:
        t_half: time of the decompression half [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        d_<output>__<argument>: d output / d argument for each output above and argument q_r, q_th, q_thd,
            k_d, guess_q_th, guess_q_thd (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d) and math.isfinite(g_s)
            and math.isfinite(q_r_lo) and math.isfinite(guess_q_th) and math.isfinite(guess_q_thd)
            and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol) and ((m > 0.0))
            and ((l0 > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0))
            and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # bottom below q_r_lo
    if not ((-q_r + q_r_lo > 0.0)):
        return _NAN42 + (STATUS_NO_LIFTOFF,)
    # F_r > 0 at the bottom with k_d
    if not ((-g_s*m*math.cos(q_th) + k_d*l0 - k_d*q_r + m*q_r*q_thd**2 > 0.0)):
        return _NAN42 + (STATUS_RECOMPRESSION,)
    # node count
    if nodes == 0.0:
        # branch nodes = 0
        _c0 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_0(g_s, guess_q_th,
            guess_q_thd, iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol))
        if _c0[30] != STATUS_OK:
            return _NAN42 + (_c0[30],)
        (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
            d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
            d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
            d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd,
            d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, _) = _c0
    elif nodes == 1.0:
        # branch nodes = 1
        _c1 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_1(g_s, guess_q_th,
            guess_q_thd, iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol))
        if _c1[30] != STATUS_OK:
            return _NAN42 + (_c1[30],)
        (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
            d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
            d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
            d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd,
            d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, _) = _c1
    elif nodes == 2.0:
        # branch nodes = 2
        _c2 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_2(g_s, guess_q_th,
            guess_q_thd, iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol))
        if _c2[30] != STATUS_OK:
            return _NAN42 + (_c2[30],)
        (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
            d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
            d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
            d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd,
            d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, _) = _c2
    elif nodes == 3.0:
        # branch nodes = 3
        _c3 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_3(g_s, guess_q_th,
            guess_q_thd, iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol))
        if _c3[30] != STATUS_OK:
            return _NAN42 + (_c3[30],)
        (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
            d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
            d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
            d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd,
            d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, _) = _c3
    elif nodes == 4.0:
        # branch nodes = 4
        _c4 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_4(g_s, guess_q_th,
            guess_q_thd, iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol))
        if _c4[30] != STATUS_OK:
            return _NAN42 + (_c4[30],)
        (t_half, end_q_th, d_end_q_th__q_th, end_q_r, end_q_rd, d_end_q_rd__q_r, d_end_q_rd__q_th,
            d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, end_q_thd,
            d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
            d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, passes, d_end_q_th__q_r, d_end_q_th__q_thd,
            d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, _) = _c4
    else:
        return _NAN42 + (STATUS_INVALID_INPUT,)
    # derivatives of the outputs
    d_end_q_r__q_r = 0.0
    d_end_q_r__q_th = 0.0
    d_end_q_r__q_thd = 0.0
    d_end_q_r__k_d = 0.0
    d_end_q_r__guess_q_th = 0.0
    d_end_q_r__guess_q_thd = 0.0
    d_passes__q_r = 0.0
    d_passes__q_th = 0.0
    d_passes__q_thd = 0.0
    d_passes__k_d = 0.0
    d_passes__guess_q_th = 0.0
    d_passes__guess_q_thd = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_r__q_r,
        d_end_q_r__q_th, d_end_q_r__q_thd, d_end_q_r__k_d, d_end_q_r__guess_q_th, d_end_q_r__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d,
        d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
        d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd,
        d_passes__q_r, d_passes__q_th, d_passes__q_thd, d_passes__k_d, d_passes__guess_q_th,
        d_passes__guess_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def iterative_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes,
        iterations, tol, zeroth):
    """Iterative stance map (Schwind and Koditschek, converging form): stance outputs and their derivatives
    with respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k_c: leg stiffness while compressing k_c [N/m]
        k_d: leg stiffness after the bottom k_d [N/m]
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with
            k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 =
            gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 =
            geyer-vs

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
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 396
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(nodes)
            and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(zeroth) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0))
            and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            and ((tol >= 0.0) and (tol <= 1.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth == 2.0)
            or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth == 7.0)
            or (zeroth == 8.0))):
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN77 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate
    if zeroth == 1.0:
        # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
        _x0 = -q_r_td
        _x6 = m*q_rd_td**2
        _x1 = k_c*q_r_td
        _x2 = g_s*m
        _x3 = _x2*math.cos(q_th_td)
        _x4 = q_thd_td**2
        _x5 = _x4*m
        _x7 = -_x1 - _x3 + _x4*m*q_r_td + k_c*l0
        _x8 = math.sqrt(_x6*k_c + _x7**2)
        _x9 = -_x1 - _x3 + _x5*q_r_td + _x8 + k_c*l0
        _x10 = (1.0/_x9)
        _x11 = -_x0 - _x10*_x6
        z_b_q_r = _x11
        _x12 = (1.0/_x8)
        _x13 = (0.5)*_x7
        _x14 = _x10**2
        _x15 = _x14*_x6
        d_z_b_q_r__q_r_td = -_x15*(-_x12*_x13*(2.0*_x4*m - 2.0*k_c) - _x5 + k_c) + 1.0
        d_z_b_q_r__q_rd_td = -2.0*_x10*m*q_rd_td + _x12*_x14*k_c*m**2*q_rd_td**3
        _x16 = _x2*math.sin(q_th_td)
        _x17 = _x12*_x7
        d_z_b_q_r__q_th_td = -_x15*(-_x16*_x17 - _x16)
        _x18 = 2.0*q_r_td
        _x19 = _x18*q_thd_td
        _x20 = _x19*m
        d_z_b_q_r__q_thd_td = -_x15*(-_x17*_x20 - _x20)
        d_z_b_q_r__k_c = -_x15*(-_x0 - _x12*(_x13*(-_x18 + 2.0*l0) + (0.5)*_x6) - l0)
        z_b_q_th = q_th_td
        _x21 = q_r_td**2
        _x24 = (1.0/_x11)
        _x22 = _x24**2
        _x23 = _x21*_x22
        z_b_q_thd = _x23*q_thd_td
        _pd__0 = -2.0*_x21*_x24**3*q_thd_td
        d_z_b_q_thd__q_r_td = _pd__0*d_z_b_q_r__q_r_td + _x19*_x22
        d_z_b_q_thd__q_rd_td = _pd__0*d_z_b_q_r__q_rd_td
        d_z_b_q_thd__q_th_td = _pd__0*d_z_b_q_r__q_th_td
        d_z_b_q_thd__q_thd_td = _pd__0*d_z_b_q_r__q_thd_td + _x23
        d_z_b_q_thd__k_c = _pd__0*d_z_b_q_r__k_c
        z_lo_q_th = 0.0
        z_lo_q_thd = 0.0
        # tangents as every branch names them
        d_z_b_q_r__k_d = 0.0
        d_z_b_q_th__q_r_td = 0.0
        d_z_b_q_th__q_rd_td = 0.0
        d_z_b_q_th__q_th_td = 1.0
        d_z_b_q_th__q_thd_td = 0.0
        d_z_b_q_th__k_c = 0.0
        d_z_b_q_th__k_d = 0.0
        d_z_b_q_thd__k_d = 0.0
        d_z_lo_q_th__q_r_td = 0.0
        d_z_lo_q_th__q_rd_td = 0.0
        d_z_lo_q_th__q_th_td = 0.0
        d_z_lo_q_th__q_thd_td = 0.0
        d_z_lo_q_th__k_c = 0.0
        d_z_lo_q_th__k_d = 0.0
        d_z_lo_q_thd__q_r_td = 0.0
        d_z_lo_q_thd__q_rd_td = 0.0
        d_z_lo_q_thd__q_th_td = 0.0
        d_z_lo_q_thd__q_thd_td = 0.0
        d_z_lo_q_thd__k_c = 0.0
        d_z_lo_q_thd__k_d = 0.0
    elif zeroth == 0.0:
        # zeroth iterate: Geyer et al.'s approximate stance map
        _c0 = geyer_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
        if _c0[60] != STATUS_OK:
            return _NAN77 + (_c0[60],)
        (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _,
            _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _, _, _, _, _,
            _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
            _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _, _j_z_b_q_thd__q_thd_td,
            _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
            _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td,
            _j_z_lo_q_thd__q_rd_td, _, _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _) = _c0
        # tangents as every branch names them
        d_z_b_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_z_b_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_z_b_q_r__q_th_td = 0.0
        d_z_b_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_z_b_q_r__k_c = _j_z_b_q_r__k
        d_z_b_q_r__k_d = 0.0
        d_z_b_q_th__q_r_td = _j_z_b_q_th__q_r_td
        d_z_b_q_th__q_rd_td = _j_z_b_q_th__q_rd_td
        d_z_b_q_th__q_th_td = _j_z_b_q_th__q_th_td
        d_z_b_q_th__q_thd_td = _j_z_b_q_th__q_thd_td
        d_z_b_q_th__k_c = _j_z_b_q_th__k
        d_z_b_q_th__k_d = 0.0
        d_z_b_q_thd__q_r_td = _j_z_b_q_thd__q_r_td
        d_z_b_q_thd__q_rd_td = _j_z_b_q_thd__q_rd_td
        d_z_b_q_thd__q_th_td = 0.0
        d_z_b_q_thd__q_thd_td = _j_z_b_q_thd__q_thd_td
        d_z_b_q_thd__k_c = _j_z_b_q_thd__k
        d_z_b_q_thd__k_d = 0.0
        d_z_lo_q_th__q_r_td = _j_z_lo_q_th__q_r_td
        d_z_lo_q_th__q_rd_td = _j_z_lo_q_th__q_rd_td
        d_z_lo_q_th__q_th_td = _j_z_lo_q_th__q_th_td
        d_z_lo_q_th__q_thd_td = _j_z_lo_q_th__q_thd_td
        d_z_lo_q_th__k_c = _j_z_lo_q_th__k
        d_z_lo_q_th__k_d = 0.0
        d_z_lo_q_thd__q_r_td = _j_z_lo_q_thd__q_r_td
        d_z_lo_q_thd__q_rd_td = _j_z_lo_q_thd__q_rd_td
        d_z_lo_q_thd__q_th_td = 0.0
        d_z_lo_q_thd__q_thd_td = _j_z_lo_q_thd__q_thd_td
        d_z_lo_q_thd__k_c = _j_z_lo_q_thd__k
        d_z_lo_q_thd__k_d = 0.0
    elif zeroth == 2.0:
        # zeroth iterate: Gravity correction type 0 (leg length l0)
        _c1 = (gravity_type0_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
            2.0, 1.0, 0.0))
        if _c1[72] != STATUS_OK:
            return _NAN77 + (_c1[72],)
        (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _,
            _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
            _j_z_b_q_r__k, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td,
            _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td,
            _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _,
            _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td,
            _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td,
            _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c1
        # tangents as every branch names them
        d_z_b_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_z_b_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_z_b_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_z_b_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_z_b_q_r__k_c = _j_z_b_q_r__k
        d_z_b_q_r__k_d = 0.0
        d_z_b_q_th__q_r_td = _j_z_b_q_th__q_r_td
        d_z_b_q_th__q_rd_td = _j_z_b_q_th__q_rd_td
        d_z_b_q_th__q_th_td = _j_z_b_q_th__q_th_td
        d_z_b_q_th__q_thd_td = _j_z_b_q_th__q_thd_td
        d_z_b_q_th__k_c = _j_z_b_q_th__k
        d_z_b_q_th__k_d = 0.0
        d_z_b_q_thd__q_r_td = _j_z_b_q_thd__q_r_td
        d_z_b_q_thd__q_rd_td = _j_z_b_q_thd__q_rd_td
        d_z_b_q_thd__q_th_td = _j_z_b_q_thd__q_th_td
        d_z_b_q_thd__q_thd_td = _j_z_b_q_thd__q_thd_td
        d_z_b_q_thd__k_c = _j_z_b_q_thd__k
        d_z_b_q_thd__k_d = 0.0
        d_z_lo_q_th__q_r_td = _j_z_lo_q_th__q_r_td
        d_z_lo_q_th__q_rd_td = _j_z_lo_q_th__q_rd_td
        d_z_lo_q_th__q_th_td = _j_z_lo_q_th__q_th_td
        d_z_lo_q_th__q_thd_td = _j_z_lo_q_th__q_thd_td
        d_z_lo_q_th__k_c = _j_z_lo_q_th__k
        d_z_lo_q_th__k_d = 0.0
        d_z_lo_q_thd__q_r_td = _j_z_lo_q_thd__q_r_td
        d_z_lo_q_thd__q_rd_td = _j_z_lo_q_thd__q_rd_td
        d_z_lo_q_thd__q_th_td = _j_z_lo_q_thd__q_th_td
        d_z_lo_q_thd__q_thd_td = _j_z_lo_q_thd__q_thd_td
        d_z_lo_q_thd__k_c = _j_z_lo_q_thd__k
        d_z_lo_q_thd__k_d = 0.0
    elif zeroth == 3.0:
        # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
        _c2 = (gravity_type1_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
            2.0, 100.0, 1e-12))
        if _c2[72] != STATUS_OK:
            return _NAN77 + (_c2[72],)
        (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _,
            _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
            _j_z_b_q_r__k, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td,
            _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td,
            _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _,
            _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td,
            _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td,
            _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c2
        # tangents as every branch names them
        d_z_b_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_z_b_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_z_b_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_z_b_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_z_b_q_r__k_c = _j_z_b_q_r__k
        d_z_b_q_r__k_d = 0.0
        d_z_b_q_th__q_r_td = _j_z_b_q_th__q_r_td
        d_z_b_q_th__q_rd_td = _j_z_b_q_th__q_rd_td
        d_z_b_q_th__q_th_td = _j_z_b_q_th__q_th_td
        d_z_b_q_th__q_thd_td = _j_z_b_q_th__q_thd_td
        d_z_b_q_th__k_c = _j_z_b_q_th__k
        d_z_b_q_th__k_d = 0.0
        d_z_b_q_thd__q_r_td = _j_z_b_q_thd__q_r_td
        d_z_b_q_thd__q_rd_td = _j_z_b_q_thd__q_rd_td
        d_z_b_q_thd__q_th_td = _j_z_b_q_thd__q_th_td
        d_z_b_q_thd__q_thd_td = _j_z_b_q_thd__q_thd_td
        d_z_b_q_thd__k_c = _j_z_b_q_thd__k
        d_z_b_q_thd__k_d = 0.0
        d_z_lo_q_th__q_r_td = _j_z_lo_q_th__q_r_td
        d_z_lo_q_th__q_rd_td = _j_z_lo_q_th__q_rd_td
        d_z_lo_q_th__q_th_td = _j_z_lo_q_th__q_th_td
        d_z_lo_q_th__q_thd_td = _j_z_lo_q_th__q_thd_td
        d_z_lo_q_th__k_c = _j_z_lo_q_th__k
        d_z_lo_q_th__k_d = 0.0
        d_z_lo_q_thd__q_r_td = _j_z_lo_q_thd__q_r_td
        d_z_lo_q_thd__q_rd_td = _j_z_lo_q_thd__q_rd_td
        d_z_lo_q_thd__q_th_td = _j_z_lo_q_thd__q_th_td
        d_z_lo_q_thd__q_thd_td = _j_z_lo_q_thd__q_thd_td
        d_z_lo_q_thd__k_c = _j_z_lo_q_thd__k
        d_z_lo_q_thd__k_d = 0.0
    elif zeroth == 4.0:
        # zeroth iterate: Gravity correction type 2 (average leg length)
        _c3 = (gravity_type2_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
            2.0, 0.0, 100.0, 1e-12))
        if _c3[72] != STATUS_OK:
            return _NAN77 + (_c3[72],)
        (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _,
            _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
            _j_z_b_q_r__k, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td,
            _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td,
            _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _,
            _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td,
            _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td,
            _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c3
        # tangents as every branch names them
        d_z_b_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_z_b_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_z_b_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_z_b_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_z_b_q_r__k_c = _j_z_b_q_r__k
        d_z_b_q_r__k_d = 0.0
        d_z_b_q_th__q_r_td = _j_z_b_q_th__q_r_td
        d_z_b_q_th__q_rd_td = _j_z_b_q_th__q_rd_td
        d_z_b_q_th__q_th_td = _j_z_b_q_th__q_th_td
        d_z_b_q_th__q_thd_td = _j_z_b_q_th__q_thd_td
        d_z_b_q_th__k_c = _j_z_b_q_th__k
        d_z_b_q_th__k_d = 0.0
        d_z_b_q_thd__q_r_td = _j_z_b_q_thd__q_r_td
        d_z_b_q_thd__q_rd_td = _j_z_b_q_thd__q_rd_td
        d_z_b_q_thd__q_th_td = _j_z_b_q_thd__q_th_td
        d_z_b_q_thd__q_thd_td = _j_z_b_q_thd__q_thd_td
        d_z_b_q_thd__k_c = _j_z_b_q_thd__k
        d_z_b_q_thd__k_d = 0.0
        d_z_lo_q_th__q_r_td = _j_z_lo_q_th__q_r_td
        d_z_lo_q_th__q_rd_td = _j_z_lo_q_th__q_rd_td
        d_z_lo_q_th__q_th_td = _j_z_lo_q_th__q_th_td
        d_z_lo_q_th__q_thd_td = _j_z_lo_q_th__q_thd_td
        d_z_lo_q_th__k_c = _j_z_lo_q_th__k
        d_z_lo_q_th__k_d = 0.0
        d_z_lo_q_thd__q_r_td = _j_z_lo_q_thd__q_r_td
        d_z_lo_q_thd__q_rd_td = _j_z_lo_q_thd__q_rd_td
        d_z_lo_q_thd__q_th_td = _j_z_lo_q_thd__q_th_td
        d_z_lo_q_thd__q_thd_td = _j_z_lo_q_thd__q_thd_td
        d_z_lo_q_thd__k_c = _j_z_lo_q_thd__k
        d_z_lo_q_thd__k_d = 0.0
    elif zeroth == 5.0:
        # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
        _c4 = (gravity_type3_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
            1.0, 100.0, 1e-12))
        if _c4[72] != STATUS_OK:
            return _NAN77 + (_c4[72],)
        (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _,
            _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
            _j_z_b_q_r__k, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td,
            _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td,
            _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _,
            _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td,
            _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td,
            _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c4
        # tangents as every branch names them
        d_z_b_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_z_b_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_z_b_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_z_b_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_z_b_q_r__k_c = _j_z_b_q_r__k
        d_z_b_q_r__k_d = 0.0
        d_z_b_q_th__q_r_td = _j_z_b_q_th__q_r_td
        d_z_b_q_th__q_rd_td = _j_z_b_q_th__q_rd_td
        d_z_b_q_th__q_th_td = _j_z_b_q_th__q_th_td
        d_z_b_q_th__q_thd_td = _j_z_b_q_th__q_thd_td
        d_z_b_q_th__k_c = _j_z_b_q_th__k
        d_z_b_q_th__k_d = 0.0
        d_z_b_q_thd__q_r_td = _j_z_b_q_thd__q_r_td
        d_z_b_q_thd__q_rd_td = _j_z_b_q_thd__q_rd_td
        d_z_b_q_thd__q_th_td = _j_z_b_q_thd__q_th_td
        d_z_b_q_thd__q_thd_td = _j_z_b_q_thd__q_thd_td
        d_z_b_q_thd__k_c = _j_z_b_q_thd__k
        d_z_b_q_thd__k_d = 0.0
        d_z_lo_q_th__q_r_td = _j_z_lo_q_th__q_r_td
        d_z_lo_q_th__q_rd_td = _j_z_lo_q_th__q_rd_td
        d_z_lo_q_th__q_th_td = _j_z_lo_q_th__q_th_td
        d_z_lo_q_th__q_thd_td = _j_z_lo_q_th__q_thd_td
        d_z_lo_q_th__k_c = _j_z_lo_q_th__k
        d_z_lo_q_th__k_d = 0.0
        d_z_lo_q_thd__q_r_td = _j_z_lo_q_thd__q_r_td
        d_z_lo_q_thd__q_rd_td = _j_z_lo_q_thd__q_rd_td
        d_z_lo_q_thd__q_th_td = _j_z_lo_q_thd__q_th_td
        d_z_lo_q_thd__q_thd_td = _j_z_lo_q_thd__q_thd_td
        d_z_lo_q_thd__k_c = _j_z_lo_q_thd__k
        d_z_lo_q_thd__k_d = 0.0
    elif zeroth == 6.0:
        # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
        _c5 = (gravity_type4_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
            1.0, 0.0, 100.0, 1e-12))
        if _c5[72] != STATUS_OK:
            return _NAN77 + (_c5[72],)
        (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _,
            _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
            _j_z_b_q_r__k, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td,
            _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td,
            _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _,
            _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td,
            _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td,
            _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c5
        # tangents as every branch names them
        d_z_b_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_z_b_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_z_b_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_z_b_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_z_b_q_r__k_c = _j_z_b_q_r__k
        d_z_b_q_r__k_d = 0.0
        d_z_b_q_th__q_r_td = _j_z_b_q_th__q_r_td
        d_z_b_q_th__q_rd_td = _j_z_b_q_th__q_rd_td
        d_z_b_q_th__q_th_td = _j_z_b_q_th__q_th_td
        d_z_b_q_th__q_thd_td = _j_z_b_q_th__q_thd_td
        d_z_b_q_th__k_c = _j_z_b_q_th__k
        d_z_b_q_th__k_d = 0.0
        d_z_b_q_thd__q_r_td = _j_z_b_q_thd__q_r_td
        d_z_b_q_thd__q_rd_td = _j_z_b_q_thd__q_rd_td
        d_z_b_q_thd__q_th_td = _j_z_b_q_thd__q_th_td
        d_z_b_q_thd__q_thd_td = _j_z_b_q_thd__q_thd_td
        d_z_b_q_thd__k_c = _j_z_b_q_thd__k
        d_z_b_q_thd__k_d = 0.0
        d_z_lo_q_th__q_r_td = _j_z_lo_q_th__q_r_td
        d_z_lo_q_th__q_rd_td = _j_z_lo_q_th__q_rd_td
        d_z_lo_q_th__q_th_td = _j_z_lo_q_th__q_th_td
        d_z_lo_q_th__q_thd_td = _j_z_lo_q_th__q_thd_td
        d_z_lo_q_th__k_c = _j_z_lo_q_th__k
        d_z_lo_q_th__k_d = 0.0
        d_z_lo_q_thd__q_r_td = _j_z_lo_q_thd__q_r_td
        d_z_lo_q_thd__q_rd_td = _j_z_lo_q_thd__q_rd_td
        d_z_lo_q_thd__q_th_td = _j_z_lo_q_thd__q_th_td
        d_z_lo_q_thd__q_thd_td = _j_z_lo_q_thd__q_thd_td
        d_z_lo_q_thd__k_c = _j_z_lo_q_thd__k
        d_z_lo_q_thd__k_d = 0.0
    elif zeroth == 7.0:
        # zeroth iterate: Gravity correction type 5 (time-varying momentum)
        _c6 = (gravity_type5_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo,
            100.0, 1e-12))
        if _c6[72] != STATUS_OK:
            return _NAN77 + (_c6[72],)
        (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _,
            _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
            _j_z_b_q_r__k, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td,
            _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td,
            _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _,
            _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td,
            _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td,
            _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c6
        # tangents as every branch names them
        d_z_b_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_z_b_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_z_b_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_z_b_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_z_b_q_r__k_c = _j_z_b_q_r__k
        d_z_b_q_r__k_d = 0.0
        d_z_b_q_th__q_r_td = _j_z_b_q_th__q_r_td
        d_z_b_q_th__q_rd_td = _j_z_b_q_th__q_rd_td
        d_z_b_q_th__q_th_td = _j_z_b_q_th__q_th_td
        d_z_b_q_th__q_thd_td = _j_z_b_q_th__q_thd_td
        d_z_b_q_th__k_c = _j_z_b_q_th__k
        d_z_b_q_th__k_d = 0.0
        d_z_b_q_thd__q_r_td = _j_z_b_q_thd__q_r_td
        d_z_b_q_thd__q_rd_td = _j_z_b_q_thd__q_rd_td
        d_z_b_q_thd__q_th_td = _j_z_b_q_thd__q_th_td
        d_z_b_q_thd__q_thd_td = _j_z_b_q_thd__q_thd_td
        d_z_b_q_thd__k_c = _j_z_b_q_thd__k
        d_z_b_q_thd__k_d = 0.0
        d_z_lo_q_th__q_r_td = _j_z_lo_q_th__q_r_td
        d_z_lo_q_th__q_rd_td = _j_z_lo_q_th__q_rd_td
        d_z_lo_q_th__q_th_td = _j_z_lo_q_th__q_th_td
        d_z_lo_q_th__q_thd_td = _j_z_lo_q_th__q_thd_td
        d_z_lo_q_th__k_c = _j_z_lo_q_th__k
        d_z_lo_q_th__k_d = 0.0
        d_z_lo_q_thd__q_r_td = _j_z_lo_q_thd__q_r_td
        d_z_lo_q_thd__q_rd_td = _j_z_lo_q_thd__q_rd_td
        d_z_lo_q_thd__q_th_td = _j_z_lo_q_thd__q_th_td
        d_z_lo_q_thd__q_thd_td = _j_z_lo_q_thd__q_thd_td
        d_z_lo_q_thd__k_c = _j_z_lo_q_thd__k
        d_z_lo_q_thd__k_d = 0.0
    elif zeroth == 8.0:
        # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
        _c7 = (geyer_vs_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0,
            0.0, 100.0, 1e-12))
        if _c7[91] != STATUS_OK:
            return _NAN77 + (_c7[91],)
        (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _,
            _, _, _, _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
            _j_z_b_q_r__k_c, _j_z_b_q_r__k_d, _, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td,
            _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k_c, _j_z_b_q_th__k_d,
            _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td,
            _j_z_b_q_thd__k_c, _j_z_b_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
            _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k_c,
            _j_z_lo_q_th__k_d, _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td,
            _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _,
            _, _, _, _, _, _, _, _) = _c7
        # tangents as every branch names them
        d_z_b_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_z_b_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_z_b_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_z_b_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_z_b_q_r__k_c = _j_z_b_q_r__k_c
        d_z_b_q_r__k_d = _j_z_b_q_r__k_d
        d_z_b_q_th__q_r_td = _j_z_b_q_th__q_r_td
        d_z_b_q_th__q_rd_td = _j_z_b_q_th__q_rd_td
        d_z_b_q_th__q_th_td = _j_z_b_q_th__q_th_td
        d_z_b_q_th__q_thd_td = _j_z_b_q_th__q_thd_td
        d_z_b_q_th__k_c = _j_z_b_q_th__k_c
        d_z_b_q_th__k_d = _j_z_b_q_th__k_d
        d_z_b_q_thd__q_r_td = _j_z_b_q_thd__q_r_td
        d_z_b_q_thd__q_rd_td = _j_z_b_q_thd__q_rd_td
        d_z_b_q_thd__q_th_td = _j_z_b_q_thd__q_th_td
        d_z_b_q_thd__q_thd_td = _j_z_b_q_thd__q_thd_td
        d_z_b_q_thd__k_c = _j_z_b_q_thd__k_c
        d_z_b_q_thd__k_d = _j_z_b_q_thd__k_d
        d_z_lo_q_th__q_r_td = _j_z_lo_q_th__q_r_td
        d_z_lo_q_th__q_rd_td = _j_z_lo_q_th__q_rd_td
        d_z_lo_q_th__q_th_td = _j_z_lo_q_th__q_th_td
        d_z_lo_q_th__q_thd_td = _j_z_lo_q_th__q_thd_td
        d_z_lo_q_th__k_c = _j_z_lo_q_th__k_c
        d_z_lo_q_th__k_d = _j_z_lo_q_th__k_d
        d_z_lo_q_thd__q_r_td = _j_z_lo_q_thd__q_r_td
        d_z_lo_q_thd__q_rd_td = _j_z_lo_q_thd__q_rd_td
        d_z_lo_q_thd__q_th_td = _j_z_lo_q_thd__q_th_td
        d_z_lo_q_thd__q_thd_td = _j_z_lo_q_thd__q_thd_td
        d_z_lo_q_thd__k_c = _j_z_lo_q_thd__k_c
        d_z_lo_q_thd__k_d = _j_z_lo_q_thd__k_d
    else:
        return _NAN77 + (STATUS_INVALID_INPUT,)
    # compression half, k_c (report 5.2.1)
    _c8 = (schwind_compression_jvp6_4eaacb(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r,
        z_b_q_th, z_b_q_thd, nodes, iterations, tol, d_z_b_q_r__q_r_td, d_z_b_q_th__q_r_td,
        d_z_b_q_thd__q_r_td, d_z_b_q_r__q_rd_td, d_z_b_q_th__q_rd_td, d_z_b_q_thd__q_rd_td,
        d_z_b_q_r__q_th_td, d_z_b_q_th__q_th_td, d_z_b_q_thd__q_th_td, d_z_b_q_r__q_thd_td,
        d_z_b_q_th__q_thd_td, d_z_b_q_thd__q_thd_td, d_z_b_q_r__k_c, d_z_b_q_th__k_c, d_z_b_q_thd__k_c,
        d_z_b_q_r__k_d, d_z_b_q_th__k_d, d_z_b_q_thd__k_d))
    if _c8[42] != STATUS_OK:
        return _NAN77 + (_c8[42],)
    (t_bottom, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, c_passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_r__k_c, d_bottom_q_r__k_d, _, _, _, _, _, _, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td,
        d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k_c, d_bottom_q_th__k_d,
        d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, _, _, _, _, _, _, _) = _c8
    # zeroth iterate at liftoff
    _x25 = (zeroth == 1.0)
    g_lo_q_th = ((bottom_q_th) if _x25 else (z_lo_q_th))
    _pd__1 = ((1.0) if _x25 else (0.0))
    _x26 = ((0.0) if _x25 else (1.0))
    _pd__2 = _x26
    d_g_lo_q_th__q_r_td = _pd__1*d_bottom_q_th__q_r_td + _pd__2*d_z_lo_q_th__q_r_td
    d_g_lo_q_th__q_rd_td = _pd__1*d_bottom_q_th__q_rd_td + _pd__2*d_z_lo_q_th__q_rd_td
    d_g_lo_q_th__q_th_td = _pd__1*d_bottom_q_th__q_th_td + _pd__2*d_z_lo_q_th__q_th_td
    d_g_lo_q_th__q_thd_td = _pd__1*d_bottom_q_th__q_thd_td + _pd__2*d_z_lo_q_th__q_thd_td
    d_g_lo_q_th__k_c = _pd__1*d_bottom_q_th__k_c + _pd__2*d_z_lo_q_th__k_c
    d_g_lo_q_th__k_d = _pd__1*d_bottom_q_th__k_d + _pd__2*d_z_lo_q_th__k_d
    _x27 = q_r_lo**-2
    _x28 = _x27*bottom_q_r**2
    g_lo_q_thd = ((_x28*bottom_q_thd) if _x25 else (z_lo_q_thd))
    _pd__3 = ((2.0*_x27*bottom_q_r*bottom_q_thd) if _x25 else (0.0))
    _pd__4 = ((_x28) if _x25 else (0.0))
    _pd__5 = _x26
    d_g_lo_q_thd__q_r_td = (_pd__3*d_bottom_q_r__q_r_td + _pd__4*d_bottom_q_thd__q_r_td
        + _pd__5*d_z_lo_q_thd__q_r_td)
    d_g_lo_q_thd__q_rd_td = (_pd__3*d_bottom_q_r__q_rd_td + _pd__4*d_bottom_q_thd__q_rd_td
        + _pd__5*d_z_lo_q_thd__q_rd_td)
    d_g_lo_q_thd__q_th_td = (_pd__3*d_bottom_q_r__q_th_td + _pd__4*d_bottom_q_thd__q_th_td
        + _pd__5*d_z_lo_q_thd__q_th_td)
    d_g_lo_q_thd__q_thd_td = (_pd__3*d_bottom_q_r__q_thd_td + _pd__4*d_bottom_q_thd__q_thd_td
        + _pd__5*d_z_lo_q_thd__q_thd_td)
    d_g_lo_q_thd__k_c = _pd__3*d_bottom_q_r__k_c + _pd__4*d_bottom_q_thd__k_c + _pd__5*d_z_lo_q_thd__k_c
    d_g_lo_q_thd__k_d = _pd__3*d_bottom_q_r__k_d + _pd__4*d_bottom_q_thd__k_d + _pd__5*d_z_lo_q_thd__k_d
    # decompression half, k_d (report 3.2, 5.2.2)
    _c9 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd(bottom_q_r, bottom_q_rd,
        bottom_q_th, bottom_q_thd, m, l0, k_d, g_s, q_r_lo, g_lo_q_th, g_lo_q_thd, nodes, iterations, tol))
    if _c9[42] != STATUS_OK:
        return _NAN77 + (_c9[42],)
    (t_decompression, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_passes,
        _j_t_decompression__q_r, _j_t_decompression__q_th, _j_t_decompression__q_thd, _j_t_decompression__k_d,
        _j_t_decompression__guess_q_th, _j_t_decompression__guess_q_thd, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_r, _j_liftoff_q_rd__q_th, _j_liftoff_q_rd__q_thd, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__guess_q_th, _j_liftoff_q_rd__guess_q_thd, _j_liftoff_q_th__q_r,
        _j_liftoff_q_th__q_th, _j_liftoff_q_th__q_thd, _j_liftoff_q_th__k_d, _j_liftoff_q_th__guess_q_th,
        _j_liftoff_q_th__guess_q_thd, _j_liftoff_q_thd__q_r, _j_liftoff_q_thd__q_th, _j_liftoff_q_thd__q_thd,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__guess_q_th, _j_liftoff_q_thd__guess_q_thd, _, _, _, _, _, _,
        _) = _c9
    # chain rule through schwind_decompression
    d_t_decompression__q_r_td = (_j_t_decompression__guess_q_th*d_g_lo_q_th__q_r_td
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__q_r_td + _j_t_decompression__q_r*d_bottom_q_r__q_r_td
        + _j_t_decompression__q_th*d_bottom_q_th__q_r_td + _j_t_decompression__q_thd*d_bottom_q_thd__q_r_td)
    d_t_decompression__q_rd_td = (_j_t_decompression__guess_q_th*d_g_lo_q_th__q_rd_td
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__q_rd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_rd_td + _j_t_decompression__q_th*d_bottom_q_th__q_rd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_rd_td)
    d_t_decompression__q_th_td = (_j_t_decompression__guess_q_th*d_g_lo_q_th__q_th_td
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__q_th_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_th_td + _j_t_decompression__q_th*d_bottom_q_th__q_th_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_th_td)
    d_t_decompression__q_thd_td = (_j_t_decompression__guess_q_th*d_g_lo_q_th__q_thd_td
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__q_thd_td
        + _j_t_decompression__q_r*d_bottom_q_r__q_thd_td + _j_t_decompression__q_th*d_bottom_q_th__q_thd_td
        + _j_t_decompression__q_thd*d_bottom_q_thd__q_thd_td)
    d_t_decompression__k_c = (_j_t_decompression__guess_q_th*d_g_lo_q_th__k_c
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__k_c + _j_t_decompression__q_r*d_bottom_q_r__k_c
        + _j_t_decompression__q_th*d_bottom_q_th__k_c + _j_t_decompression__q_thd*d_bottom_q_thd__k_c)
    d_t_decompression__k_d = (_j_t_decompression__guess_q_th*d_g_lo_q_th__k_d
        + _j_t_decompression__guess_q_thd*d_g_lo_q_thd__k_d + _j_t_decompression__k_d
        + _j_t_decompression__q_r*d_bottom_q_r__k_d + _j_t_decompression__q_th*d_bottom_q_th__k_d
        + _j_t_decompression__q_thd*d_bottom_q_thd__k_d)
    d_liftoff_q_rd__q_r_td = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__q_r_td
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__q_r_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_rd__q_rd_td = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__q_rd_td
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__q_rd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__q_th_td
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__q_th_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_rd__q_thd_td = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__q_thd_td
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__q_thd_td + _j_liftoff_q_rd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_rd__k_c = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__k_c
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__k_c + _j_liftoff_q_rd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_rd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_rd__k_d = (_j_liftoff_q_rd__guess_q_th*d_g_lo_q_th__k_d
        + _j_liftoff_q_rd__guess_q_thd*d_g_lo_q_thd__k_d + _j_liftoff_q_rd__k_d
        + _j_liftoff_q_rd__q_r*d_bottom_q_r__k_d + _j_liftoff_q_rd__q_th*d_bottom_q_th__k_d
        + _j_liftoff_q_rd__q_thd*d_bottom_q_thd__k_d)
    d_liftoff_q_th__q_r_td = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__q_r_td
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__q_r_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_th__q_rd_td = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__q_rd_td
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__q_rd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__q_th_td
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__q_th_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_th__q_thd_td = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__q_thd_td
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__q_thd_td + _j_liftoff_q_th__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_th__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_th__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_th__k_c = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__k_c
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__k_c + _j_liftoff_q_th__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_th__q_th*d_bottom_q_th__k_c + _j_liftoff_q_th__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_th__k_d = (_j_liftoff_q_th__guess_q_th*d_g_lo_q_th__k_d
        + _j_liftoff_q_th__guess_q_thd*d_g_lo_q_thd__k_d + _j_liftoff_q_th__k_d
        + _j_liftoff_q_th__q_r*d_bottom_q_r__k_d + _j_liftoff_q_th__q_th*d_bottom_q_th__k_d
        + _j_liftoff_q_th__q_thd*d_bottom_q_thd__k_d)
    d_liftoff_q_thd__q_r_td = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__q_r_td
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__q_r_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_r_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_r_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_r_td)
    d_liftoff_q_thd__q_rd_td = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__q_rd_td
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__q_rd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_rd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_rd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_rd_td)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__q_th_td
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__q_th_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_th_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_th_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_th_td)
    d_liftoff_q_thd__q_thd_td = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__q_thd_td
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__q_thd_td + _j_liftoff_q_thd__q_r*d_bottom_q_r__q_thd_td
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__q_thd_td + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__q_thd_td)
    d_liftoff_q_thd__k_c = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__k_c
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__k_c + _j_liftoff_q_thd__q_r*d_bottom_q_r__k_c
        + _j_liftoff_q_thd__q_th*d_bottom_q_th__k_c + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__k_c)
    d_liftoff_q_thd__k_d = (_j_liftoff_q_thd__guess_q_th*d_g_lo_q_th__k_d
        + _j_liftoff_q_thd__guess_q_thd*d_g_lo_q_thd__k_d + _j_liftoff_q_thd__k_d
        + _j_liftoff_q_thd__q_r*d_bottom_q_r__k_d + _j_liftoff_q_thd__q_th*d_bottom_q_th__k_d
        + _j_liftoff_q_thd__q_thd*d_bottom_q_thd__k_d)
    t_stance = t_bottom + t_decompression
    d_t_stance__q_r_td = d_t_bottom__q_r_td + d_t_decompression__q_r_td
    d_t_stance__q_rd_td = d_t_bottom__q_rd_td + d_t_decompression__q_rd_td
    d_t_stance__q_th_td = d_t_bottom__q_th_td + d_t_decompression__q_th_td
    d_t_stance__q_thd_td = d_t_bottom__q_thd_td + d_t_decompression__q_thd_td
    d_t_stance__k_c = d_t_bottom__k_c + d_t_decompression__k_c
    d_t_stance__k_d = d_t_bottom__k_d + d_t_decompression__k_d
    passes = (0.5)*c_passes + (0.5)*d_passes + (0.5)*abs(c_passes - d_passes)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN77 + (STATUS_FALL,)
    # derivatives of the outputs
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_passes__q_r_td = 0.0
    d_passes__q_rd_td = 0.0
    d_passes__q_th_td = 0.0
    d_passes__q_thd_td = 0.0
    d_passes__k_c = 0.0
    d_passes__k_d = 0.0
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by their users: runtime/jacobian.py)
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd) and math.isfinite(passes)):
        return _NAN77 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td,
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
        d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_passes__q_r_td,
        d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_stance_jacobian_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, nodes,
        iterations, tol, zeroth, out, status):
    """Parallel batch form of :func:`iterative_stance_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, nodes, iterations, tol, zeroth.
    Writes output j of row i to ``out[i, j]`` (shape (n, 77)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd,
    liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td,
    d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c, d_t_bottom__k_d, d_t_stance__q_r_td,
    d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k_c, d_t_stance__k_d,
    d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
    d_bottom_q_r__k_c, d_bottom_q_r__k_d, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td,
    d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k_c, d_bottom_q_rd__k_d,
    d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
    d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td,
    d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d,
    d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td,
    d_liftoff_q_r__k_c, d_liftoff_q_r__k_d, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td,
    d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d,
    d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td,
    d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td,
    d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d,
    d_passes__q_r_td, d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k_c, d_passes__k_d.
    """
    for i in prange(out.shape[0]):
        res = (iterative_stance_jacobian(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c, k_d, g_s,
            q_r_lo, nodes, iterations, tol, zeroth))
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
def iterative_apex_return_jacobian(b_y_apex, b_xd_apex, q_th_td, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo,
        nodes, iterations, tol, zeroth):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, converging form), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 41, 114, 115, 116, 117, 118, 137.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground [m], >= 0
        b_xd_apex: horizontal apex speed [m/s], >= 0 (the runner moves in +x)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k_c: leg stiffness while compressing k_c [N/m]
        k_d: leg stiffness after the bottom k_d [N/m]
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        g_f: gravitational acceleration in flight g_f [m/s^2], positive
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]
        zeroth: option zeroth: zeroth iterate: a map's bottom and liftoff states (at its default options, with
            k_c), linear in u between the half's ends: 0 = geyer, 1 = held, 2 = gravity-type0, 3 =
            gravity-type1, 4 = gravity-type2, 5 = gravity-type3, 6 = gravity-type4, 7 = gravity-type5, 8 =
            geyer-vs

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
        passes: Picard passes run (the larger of the two halves) [1]
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 119
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d)
            and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo)
            and math.isfinite(nodes) and math.isfinite(iterations) and math.isfinite(tol)
            and math.isfinite(zeroth) and ((b_y_apex >= 0.0)) and ((b_xd_apex >= 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s
            > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo
            > 0.0)) and ((nodes == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes
            == 4.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations
            <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0)) and ((zeroth == 0.0) or (zeroth == 1.0) or (zeroth
            == 2.0) or (zeroth == 3.0) or (zeroth == 4.0) or (zeroth == 5.0) or (zeroth == 6.0) or (zeroth
            == 7.0) or (zeroth == 8.0))):
        return _NAN60 + (STATUS_INVALID_INPUT,)
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f)
    if _c0[20] != STATUS_OK:
        return _NAN60 + (_c0[20],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, _, _, _, _j_td_q_rd__b_y_apex, _j_td_q_rd__b_xd_apex,
        _j_td_q_rd__q_th_td, _, _, _j_td_q_th__q_th_td, _j_td_q_thd__b_y_apex, _j_td_q_thd__b_xd_apex,
        _j_td_q_thd__q_th_td, _j_t_descent__b_y_apex, _, _j_t_descent__q_th_td, _) = _c0
    # stance: Iterative stance map (Schwind and Koditschek, converging form)
    _c1 = (iterative_stance_jacobian(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s, q_r_lo, nodes,
        iterations, tol, zeroth))
    if _c1[77] != STATUS_OK:
        return _NAN60 + (_c1[77],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, _, _, _, _, _,
        _, _, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c,
        _j_t_stance__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _, _, _, _, _, _, _) = _c1
    # chain rule through iterative_stance
    d_t_stance__b_y_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_y_apex)
    d_t_stance__b_xd_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_t_stance__q_th_td = (_j_t_stance__q_rd_td*_j_td_q_rd__q_th_td + _j_t_stance__q_th_td*_j_td_q_th__q_th_td
        + _j_t_stance__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_rd__b_y_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_rd__b_xd_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_th__b_y_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_th__b_xd_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_thd__b_y_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_thd__b_xd_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__q_th_td)
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex_jac_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f)
    if _c2[16] != STATUS_OK:
        return _NAN60 + (_c2[16],)
    (apex_height, apex_speed, t_ascent, _, _j_apex_height__q_rd, _j_apex_height__q_th, _j_apex_height__q_thd,
        _j_apex_speed__q_rd, _j_apex_speed__q_th, _j_apex_speed__q_thd, _j_t_ascent__q_rd, _j_t_ascent__q_th,
        _j_t_ascent__q_thd, _, _, _, _) = _c2
    # chain rule through liftoff_to_apex
    d_apex_height__b_y_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_y_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_height__b_xd_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_xd_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_height__q_th_td = (_j_apex_height__q_rd*d_liftoff_q_rd__q_th_td
        + _j_apex_height__q_th*d_liftoff_q_th__q_th_td + _j_apex_height__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_height__k_c = (_j_apex_height__q_rd*_j_liftoff_q_rd__k_c
        + _j_apex_height__q_th*_j_liftoff_q_th__k_c + _j_apex_height__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_height__k_d = (_j_apex_height__q_rd*_j_liftoff_q_rd__k_d
        + _j_apex_height__q_th*_j_liftoff_q_th__k_d + _j_apex_height__q_thd*_j_liftoff_q_thd__k_d)
    d_apex_speed__b_y_apex = (_j_apex_speed__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_apex_speed__q_th*d_liftoff_q_th__b_y_apex + _j_apex_speed__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_speed__b_xd_apex = (_j_apex_speed__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_apex_speed__q_th*d_liftoff_q_th__b_xd_apex + _j_apex_speed__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_speed__q_th_td = (_j_apex_speed__q_rd*d_liftoff_q_rd__q_th_td
        + _j_apex_speed__q_th*d_liftoff_q_th__q_th_td + _j_apex_speed__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_speed__k_c = (_j_apex_speed__q_rd*_j_liftoff_q_rd__k_c + _j_apex_speed__q_th*_j_liftoff_q_th__k_c
        + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_speed__k_d = (_j_apex_speed__q_rd*_j_liftoff_q_rd__k_d + _j_apex_speed__q_th*_j_liftoff_q_th__k_d
        + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_d)
    d_t_ascent__b_y_apex = (_j_t_ascent__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_t_ascent__q_th*d_liftoff_q_th__b_y_apex + _j_t_ascent__q_thd*d_liftoff_q_thd__b_y_apex)
    d_t_ascent__b_xd_apex = (_j_t_ascent__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_t_ascent__q_th*d_liftoff_q_th__b_xd_apex + _j_t_ascent__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_t_ascent__q_th_td = (_j_t_ascent__q_rd*d_liftoff_q_rd__q_th_td
        + _j_t_ascent__q_th*d_liftoff_q_th__q_th_td + _j_t_ascent__q_thd*d_liftoff_q_thd__q_th_td)
    d_t_ascent__k_c = (_j_liftoff_q_rd__k_c*_j_t_ascent__q_rd + _j_liftoff_q_th__k_c*_j_t_ascent__q_th
        + _j_liftoff_q_thd__k_c*_j_t_ascent__q_thd)
    d_t_ascent__k_d = (_j_liftoff_q_rd__k_d*_j_t_ascent__q_rd + _j_liftoff_q_th__k_d*_j_t_ascent__q_th
        + _j_liftoff_q_thd__k_d*_j_t_ascent__q_thd)
    # derivatives of the outputs
    d_t_descent__b_y_apex = _j_t_descent__b_y_apex
    d_t_descent__b_xd_apex = 0.0
    d_t_descent__q_th_td = _j_t_descent__q_th_td
    d_t_descent__k_c = 0.0
    d_t_descent__k_d = 0.0
    d_t_stance__k_c = _j_t_stance__k_c
    d_t_stance__k_d = _j_t_stance__k_d
    d_liftoff_q_r__b_y_apex = 0.0
    d_liftoff_q_r__b_xd_apex = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_rd__k_c = _j_liftoff_q_rd__k_c
    d_liftoff_q_rd__k_d = _j_liftoff_q_rd__k_d
    d_liftoff_q_th__k_c = _j_liftoff_q_th__k_c
    d_liftoff_q_th__k_d = _j_liftoff_q_th__k_d
    d_liftoff_q_thd__k_c = _j_liftoff_q_thd__k_c
    d_liftoff_q_thd__k_d = _j_liftoff_q_thd__k_d
    d_passes__b_y_apex = 0.0
    d_passes__b_xd_apex = 0.0
    d_passes__q_th_td = 0.0
    d_passes__k_c = 0.0
    d_passes__k_d = 0.0
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by their users: runtime/jacobian.py)
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent)
            and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r)
            and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)
            and math.isfinite(passes)):
        return _NAN60 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td,
        d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex,
        d_apex_speed__q_th_td, d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex,
        d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__k_c, d_t_descent__k_d,
        d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__k_c, d_t_stance__k_d,
        d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__k_c, d_t_ascent__k_d,
        d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__k_c,
        d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td,
        d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex,
        d_liftoff_q_th__q_th_td, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex,
        d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d,
        d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__k_c, d_passes__k_d, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_apex_return_jacobian_batch(b_y_apex, b_xd_apex, q_th_td, m, l0, k_c, k_d, g_s, g_f, q_r_td,
        q_r_lo, nodes, iterations, tol, zeroth, out, status):
    """Parallel batch form of :func:`iterative_apex_return_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, nodes, iterations, tol,
    zeroth.
    Writes output j of row i to ``out[i, j]`` (shape (n, 60)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r,
    liftoff_q_rd, liftoff_q_th, liftoff_q_thd, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex,
    d_apex_height__q_th_td, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex,
    d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__k_c, d_apex_speed__k_d,
    d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__k_c, d_t_descent__k_d,
    d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__k_c, d_t_stance__k_d,
    d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__k_c, d_t_ascent__k_d,
    d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__k_c,
    d_liftoff_q_r__k_d, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td,
    d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex,
    d_liftoff_q_th__q_th_td, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex,
    d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d,
    d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__k_c, d_passes__k_d.
    """
    for i in prange(out.shape[0]):
        res = (iterative_apex_return_jacobian(b_y_apex[i], b_xd_apex[i], q_th_td[i], m, l0, k_c, k_d, g_s,
            g_f, q_r_td, q_r_lo, nodes, iterations, tol, zeroth))
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
        status[i] = res[60]
