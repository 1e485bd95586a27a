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
#   geyer_vs_jacobian.py sha256:c5074fd92cda4b80
#   gravity_type0_jacobian.py sha256:398a3a66fde67744
#   gravity_type1_jacobian.py sha256:66fa45d9056d598f
#   gravity_type2_jacobian.py sha256:3f778c1f7c92dffa
#   gravity_type3_jacobian.py sha256:d97a8bb64898cff5
#   gravity_type4_jacobian.py sha256:dd980cac01ca0fb2
#   gravity_type5_jacobian.py sha256:a3c8e01c4c5fb72e
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
    # Total ops: 227
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((17, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 0.0
    _T[0, 4] = 1.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = 0.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 1.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 1.0 - d_guess_q_r__0
    _T[5, 1] = -d_guess_q_r__1
    _T[5, 2] = -d_guess_q_r__2
    _T[5, 3] = -d_guess_q_r__3
    _T[5, 4] = -d_guess_q_r__4
    _T[5, 5] = -d_guess_q_r__5
    _T[6, 0] = 0.5*d_guess_q_th__0
    _T[6, 1] = 0.5*d_guess_q_th__1
    _T[6, 2] = 0.5*d_guess_q_th__2 + 0.5
    _T[6, 3] = 0.5*d_guess_q_th__3
    _T[6, 4] = 0.5*d_guess_q_th__4
    _T[6, 5] = 0.5*d_guess_q_th__5
    _T[7, 0] = (1.0*d_guess_q_r__0*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__0*guess_q_r**2*m
        + 1.0*m*q_r*q_thd)
    _T[7, 1] = 1.0*d_guess_q_r__1*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__1*guess_q_r**2*m
    _T[7, 2] = 1.0*d_guess_q_r__2*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__2*guess_q_r**2*m
    _T[7, 3] = 1.0*d_guess_q_r__3*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__3*guess_q_r**2*m + 0.5*m*q_r**2
    _T[7, 4] = 1.0*d_guess_q_r__4*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__4*guess_q_r**2*m
    _T[7, 5] = 1.0*d_guess_q_r__5*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__5*guess_q_r**2*m
    # Picard passes on the 1 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.5*guess_q_th + 0.5*q_th
    _P0 = 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.75*_D - q_r
        _x1 = -_x0
        _isigma0 = _x1
        _x2 = k_c*l0
        _x3 = math.cos(_Q0)
        _x4 = g_s*m
        _x5 = _x3*_x4
        _x6 = _x1*k_c
        _x7 = _P0**2
        _x8 = (1.0/m)
        _x31 = (1.0/_x1)
        _x9 = _x31**3
        _x10 = _x8*_x9
        _x11 = _x10*_x7
        _iF0 = _x11 + _x2 - _x5 - _x6
        _x12 = 2.0*_P0
        _pd__0 = _x10*_x12
        _x13 = math.sin(_Q0)
        _pd__1 = _x13*_x4
        _pd__2 = -3.0*_x31**4*_x7*_x8 - k_c
        _pd__3 = _x0 + l0
        _x14 = 0.5*_x11 + 0.5*_x2 - 0.5*_x5 - 0.5*_x6
        _iPsi0 = _x14
        _x15 = math.sqrt(_D)
        _x16 = math.sqrt(m)
        _x17 = (1.0/math.sqrt(_x14))
        _x18 = _x16*_x17
        _ift0 = _x15*_x18
        _x19 = (0.5)/_x15
        _pd__4 = _x18*_x19
        _x20 = (0.5)*_x15/_x14**(1.5)
        _pd__5 = -_x16*_x20
        _x21 = _x15*_x17
        _x22 = (1.0/_x16)
        _x23 = _x22*_x31**2
        _x24 = _x21*_x23
        _ifq0 = _P0*_x24
        _x25 = _P0*_x23
        _x26 = _x17*_x19
        _pd__6 = _x25*_x26
        _pd__7 = _x24
        _pd__8 = -_x20*_x25
        _pd__9 = -_x12*_x21*_x22*_x9
        _x27 = m**(1.5)
        _x28 = _x21*_x27*g_s
        _x29 = _x13*_x28
        _ifp0 = _x1*_x29
        _x30 = _x1*_x13*_x27*g_s
        _pd__10 = _x26*_x30
        _pd__11 = _x1*_x28*_x3
        _pd__12 = -_x20*_x30
        _pd__13 = _x29
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_c__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[5, _j0]
            _d_Q0__j = _T[6, _j0]
            _d_P0__j = _T[7, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _d_isigma0__j = -0.75*_d_D__j + d_q_r__j
            _d_iF0__j = _d_P0__j*_pd__0 + _d_Q0__j*_pd__1 + _d_isigma0__j*_pd__2 + _pd__3*d_k_c__j
            _x32 = 0.5*_d_iF0__j
            _d_ift0__j = _d_D__j*_pd__4 + _pd__5*_x32
            _d_ifq0__j = _d_D__j*_pd__6 + _d_P0__j*_pd__7 + _d_isigma0__j*_pd__9 + _pd__8*_x32
            _d_ifp0__j = _d_D__j*_pd__10 + _d_Q0__j*_pd__11 + _d_isigma0__j*_pd__13 + _pd__12*_x32
            _T[8, _j0] = _d_isigma0__j
            _T[9, _j0] = _d_iF0__j
            _T[10, _j0] = _d_ift0__j
            _T[11, _j0] = _d_ifq0__j
            _T[12, _j0] = _d_ifp0__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x33 = m*q_rd**2
        _x34 = -q_r
        _x35 = k_c*(_x34 + l0)
        _x36 = 1.0*k_c
        _x37 = 1.0*_iF0 - _x36*(-_isigma0 + l0)
        _x38 = _x35 + _x37
        _x39 = math.sqrt(_x33*k_c + _x38**2)
        _x40 = _x38 + _x39
        _x41 = (1.0/_x40)
        _D__next = _x33*_x41
        _x42 = (1.0/_x39)
        _x43 = _x41**2
        _x44 = _x33*_x43
        _pd__14 = _x44*(-_x42*(1.0*_x35 + _x37) - 1.0)
        _x45 = _x38*_x42
        _pd__15 = _x44*(-_x36*_x45 - _x36)
        _x46 = 2.0*q_r
        _pd__16 = _x44*(-1.0*_isigma0 - _x34 - _x42*((0.5)*_x33 + (0.5)*_x38*(2.0*_isigma0 - _x46)))
        _pd__17 = _x44*(_x45*k_c + k_c)
        _pd__18 = 2.0*_x41*m*q_rd - _x42*_x43*k_c*m**2*q_rd**3
        _Q0__next = 0.5*_ifq0 + q_th
        _x47 = m*q_r**2
        _P0__next = 0.5*_ifp0 + _x47*q_thd
        _pd__19 = _x46*m*q_thd
        _pd__20 = _x47
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_k_c__j = _T[0, _j1]
            d_q_r__j = _T[1, _j1]
            d_q_rd__j = _T[2, _j1]
            d_q_th__j = _T[3, _j1]
            d_q_thd__j = _T[4, _j1]
            _d_isigma0__j = _T[8, _j1]
            _d_iF0__j = _T[9, _j1]
            _d_ifq0__j = _T[11, _j1]
            _d_ifp0__j = _T[12, _j1]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__14 + _d_isigma0__j*_pd__15 + _pd__16*d_k_c__j + _pd__17*d_q_r__j
                + _pd__18*d_q_rd__j)
            _d_Q0__next__j = 0.5*_d_ifq0__j + d_q_th__j
            _d_P0__next__j = 0.5*_d_ifp0__j + _pd__19*d_q_r__j + _pd__20*d_q_thd__j
            _T[5, _j1] = _d_D__next__j
            _T[6, _j1] = _d_Q0__next__j
            _T[7, _j1] = _d_P0__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _P0__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _P0 = _n0_2
        _passes += 1.0
    # bottom state
    t_half = 1.0*_ift0
    end_q_th = 1.0*_ifq0 + q_th
    _x48 = -_D + q_r
    end_q_r = _x48
    end_q_rd = 0.0
    _x49 = q_r**2
    _x50 = 1.0*_ifp0 + _x49*m*q_thd
    _x54 = (1.0/_x48)
    _x51 = _x54**2
    _x52 = (1.0/m)
    _x53 = _x51*_x52
    end_q_thd = _x50*_x53
    _pd__21 = 1.0*_x53
    _pd__22 = -2.0*_x50*_x52*_x54**3
    _pd__23 = 2.0*_x51*q_r*q_thd
    _pd__24 = _x49*_x51
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[3, _j2]
        d_q_thd__j = _T[4, _j2]
        _d_D__j = _T[5, _j2]
        _d_ift0__j = _T[10, _j2]
        _d_ifq0__j = _T[11, _j2]
        _d_ifp0__j = _T[12, _j2]
        # bottom state
        d_end_q_th__j = 1.0*_d_ifq0__j + d_q_th__j
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = _d_ifp0__j*_pd__21 + _pd__22*d_end_q_r__j + _pd__23*d_q_r__j + _pd__24*d_q_thd__j
        _T[13, _j2] = 1.0*_d_ift0__j
        _T[14, _j2] = d_end_q_th__j
        _T[15, _j2] = d_end_q_r__j
        _T[16, _j2] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, d_t_half__5, ) = (_T[13, 0], _T[13, 1],
        _T[13, 2], _T[13, 3], _T[13, 4], _T[13, 5], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, ) = (_T[14, 0],
        _T[14, 1], _T[14, 2], _T[14, 3], _T[14, 4], _T[14, 5], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, ) = (_T[15, 0],
        _T[15, 1], _T[15, 2], _T[15, 3], _T[15, 4], _T[15, 5], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5,
        ) = (_T[16, 0], _T[16, 1], _T[16, 2], _T[16, 3], _T[16, 4], _T[16, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, STATUS_OK)


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
    # Total ops: 438
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((24, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 0.0
    _T[0, 4] = 1.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = 0.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 1.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 1.0 - d_guess_q_r__0
    _T[5, 1] = -d_guess_q_r__1
    _T[5, 2] = -d_guess_q_r__2
    _T[5, 3] = -d_guess_q_r__3
    _T[5, 4] = -d_guess_q_r__4
    _T[5, 5] = -d_guess_q_r__5
    _T[6, 0] = 0.7886751345948129*d_guess_q_th__0
    _T[6, 1] = 0.7886751345948129*d_guess_q_th__1
    _T[6, 2] = 0.7886751345948129*d_guess_q_th__2 + 0.2113248654051871
    _T[6, 3] = 0.7886751345948129*d_guess_q_th__3
    _T[6, 4] = 0.7886751345948129*d_guess_q_th__4
    _T[6, 5] = 0.7886751345948129*d_guess_q_th__5
    _T[7, 0] = 0.2113248654051871*d_guess_q_th__0
    _T[7, 1] = 0.2113248654051871*d_guess_q_th__1
    _T[7, 2] = 0.2113248654051871*d_guess_q_th__2 + 0.7886751345948129
    _T[7, 3] = 0.2113248654051871*d_guess_q_th__3
    _T[7, 4] = 0.2113248654051871*d_guess_q_th__4
    _T[7, 5] = 0.2113248654051871*d_guess_q_th__5
    _T[8, 0] = (1.5773502691896257*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__0*guess_q_r**2*m + 0.4226497308103742*m*q_r*q_thd)
    _T[8, 1] = (1.5773502691896257*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__1*guess_q_r**2*m)
    _T[8, 2] = (1.5773502691896257*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__2*guess_q_r**2*m)
    _T[8, 3] = (1.5773502691896257*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__3*guess_q_r**2*m + 0.2113248654051871*m*q_r**2)
    _T[8, 4] = (1.5773502691896257*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__4*guess_q_r**2*m)
    _T[8, 5] = (1.5773502691896257*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.7886751345948129*d_guess_q_thd__5*guess_q_r**2*m)
    _T[9, 0] = (0.4226497308103742*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__0*guess_q_r**2*m + 1.5773502691896257*m*q_r*q_thd)
    _T[9, 1] = (0.4226497308103742*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__1*guess_q_r**2*m)
    _T[9, 2] = (0.4226497308103742*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__2*guess_q_r**2*m)
    _T[9, 3] = (0.4226497308103742*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__3*guess_q_r**2*m + 0.7886751345948129*m*q_r**2)
    _T[9, 4] = (0.4226497308103742*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__4*guess_q_r**2*m)
    _T[9, 5] = (0.4226497308103742*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.2113248654051871*d_guess_q_thd__5*guess_q_r**2*m)
    # Picard passes on the 2 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th
    _Q1 = 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th
    _P0 = 0.7886751345948129*guess_q_r**2*guess_q_thd*m + 0.2113248654051871*m*q_r**2*q_thd
    _P1 = 0.2113248654051871*guess_q_r**2*guess_q_thd*m + 0.7886751345948129*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9553418012614795*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x60 = (1.0/_x2)
        _x10 = _x60**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__25 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__26 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__27 = -_x15*_x60**4*_x8 - k_c
        _pd__28 = _x1 + l0
        _x16 = 0.37799153207185376*_D + _x0
        _x17 = -_x16
        _isigma1 = _x17
        _x18 = math.cos(_Q1)
        _x19 = _x18*_x5
        _x20 = _x17*k_c
        _x21 = _P1**2
        _x59 = (1.0/_x17)
        _x22 = _x59**3
        _x23 = _x22*_x9
        _x24 = _x21*_x23
        _iF1 = -_x19 - _x20 + _x24 + _x3
        _x25 = 2.0*_P1
        _pd__29 = _x23*_x25
        _x26 = math.sin(_Q1)
        _pd__30 = _x26*_x5
        _pd__31 = -_x15*_x21*_x59**4 - k_c
        _pd__32 = _x16 + l0
        _x27 = (0.5610042339640731*_x12 + 0.06100423396407311*_x19 + 0.06100423396407311*_x20
            - 0.06100423396407311*_x24 + 0.5*_x3 - 0.5610042339640731*_x6 - 0.5610042339640731*_x7)
        _iPsi0 = _x27
        _x28 = (1.0/math.sqrt(_x27))
        _x29 = math.sqrt(_D)
        _x30 = math.sqrt(m)
        _x31 = _x29*_x30
        _ift0 = _x28*_x31
        _x32 = (0.5)/_x29
        _x33 = _x30*_x32
        _pd__33 = _x28*_x33
        _x34 = _x27**(-1.5)
        _x35 = (0.5)*_x31
        _pd__34 = -_x34*_x35
        _x36 = (1.0/_x30)
        _x37 = _x29*_x36
        _x38 = _x60**2
        _x39 = _x28*_x38
        _x40 = _x37*_x39
        _ifq0 = _P0*_x40
        _x41 = _x32*_x36
        _pd__35 = _P0*_x39*_x41
        _pd__36 = _x40
        _x42 = (0.5)*_x37
        _pd__37 = -_P0*_x34*_x38*_x42
        _pd__38 = -_x10*_x13*_x28*_x37
        _x43 = g_s*m**(1.5)
        _x44 = _x29*_x43
        _x45 = _x28*_x44
        _x46 = _x14*_x45
        _ifp0 = _x2*_x46
        _x47 = _x14*_x2
        _x48 = _x32*_x43
        _pd__39 = _x28*_x47*_x48
        _pd__40 = _x2*_x4*_x45
        _x49 = (0.5)*_x44
        _pd__41 = -_x34*_x47*_x49
        _pd__42 = _x46
        _x50 = (0.22767090063073978*_x10*_x8*_x9 - 0.27232909936926025*_x19 - 0.27232909936926025*_x20
            + 0.27232909936926025*_x21*_x22*_x9 - 0.22767090063073978*_x6 - 0.22767090063073978*_x7
            + 0.5*k_c*l0)
        _iPsi1 = _x50
        _x51 = (1.0/math.sqrt(_x50))
        _ift1 = _x31*_x51
        _pd__43 = _x33*_x51
        _x52 = _x50**(-1.5)
        _pd__44 = -_x35*_x52
        _x53 = _x59**2
        _x54 = _x51*_x53
        _x55 = _x37*_x54
        _ifq1 = _P1*_x55
        _pd__45 = _P1*_x41*_x54
        _pd__46 = _x55
        _pd__47 = -_P1*_x42*_x52*_x53
        _pd__48 = -_x22*_x25*_x37*_x51
        _x56 = _x44*_x51
        _x57 = _x26*_x56
        _ifp1 = _x17*_x57
        _x58 = _x17*_x26
        _pd__49 = _x48*_x51*_x58
        _pd__50 = _x17*_x18*_x56
        _pd__51 = -_x49*_x52*_x58
        _pd__52 = _x57
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_c__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[5, _j0]
            _d_Q0__j = _T[6, _j0]
            _d_Q1__j = _T[7, _j0]
            _d_P0__j = _T[8, _j0]
            _d_P1__j = _T[9, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x61 = -d_q_r__j
            _d_isigma0__j = -0.9553418012614795*_d_D__j - _x61
            _d_iF0__j = _d_P0__j*_pd__25 + _d_Q0__j*_pd__26 + _d_isigma0__j*_pd__27 + _pd__28*d_k_c__j
            _d_isigma1__j = -0.37799153207185376*_d_D__j - _x61
            _d_iF1__j = _d_P1__j*_pd__29 + _d_Q1__j*_pd__30 + _d_isigma1__j*_pd__31 + _pd__32*d_k_c__j
            _d_iPsi0__j = 0.5610042339640731*_d_iF0__j - 0.06100423396407311*_d_iF1__j
            _d_ift0__j = _d_D__j*_pd__33 + _d_iPsi0__j*_pd__34
            _d_ifq0__j = _d_D__j*_pd__35 + _d_P0__j*_pd__36 + _d_iPsi0__j*_pd__37 + _d_isigma0__j*_pd__38
            _d_ifp0__j = _d_D__j*_pd__39 + _d_Q0__j*_pd__40 + _d_iPsi0__j*_pd__41 + _d_isigma0__j*_pd__42
            _d_iPsi1__j = 0.22767090063073978*_d_iF0__j + 0.27232909936926025*_d_iF1__j
            _d_ift1__j = _d_D__j*_pd__43 + _d_iPsi1__j*_pd__44
            _d_ifq1__j = _d_D__j*_pd__45 + _d_P1__j*_pd__46 + _d_iPsi1__j*_pd__47 + _d_isigma1__j*_pd__48
            _d_ifp1__j = _d_D__j*_pd__49 + _d_Q1__j*_pd__50 + _d_iPsi1__j*_pd__51 + _d_isigma1__j*_pd__52
            _T[10, _j0] = _d_isigma0__j
            _T[11, _j0] = _d_iF0__j
            _T[12, _j0] = _d_isigma1__j
            _T[13, _j0] = _d_iF1__j
            _T[14, _j0] = _d_ift0__j
            _T[15, _j0] = _d_ifq0__j
            _T[16, _j0] = _d_ifp0__j
            _T[17, _j0] = _d_ift1__j
            _T[18, _j0] = _d_ifq1__j
            _T[19, _j0] = _d_ifp1__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x62 = m*q_rd**2
        _x63 = -q_r
        _x64 = k_c*(_x63 + l0)
        _x65 = -l0
        _x66 = -_isigma0 - _x65
        _x67 = 0.2113248654051871*k_c
        _x68 = -_isigma1 - _x65
        _x69 = 0.7886751345948129*k_c
        _x70 = 0.2113248654051871*_iF0 + 0.7886751345948129*_iF1 + _x64 - _x66*_x67 - _x68*_x69
        _x71 = math.sqrt(_x62*k_c + _x70**2)
        _x72 = _x70 + _x71
        _x73 = (1.0/_x72)
        _D__next = _x62*_x73
        _x74 = _x66*k_c
        _x75 = _x68*k_c
        _x76 = (1.0/_x71)
        _x77 = _x73**2
        _x78 = _x62*_x77
        _pd__53 = (_x78*(-_x76*(0.04465819873852045*_iF0 + 0.16666666666666666*_iF1 + 0.2113248654051871*_x64
            - 0.04465819873852045*_x74 - 0.16666666666666666*_x75) - 0.2113248654051871))
        _pd__54 = (_x78*(-_x76*(0.16666666666666666*_iF0 + 0.6220084679281462*_iF1 + 0.7886751345948129*_x64
            - 0.16666666666666666*_x74 - 0.6220084679281462*_x75) - 0.7886751345948129))
        _x79 = _x70*_x76
        _pd__55 = _x78*(-_x67*_x79 - _x67)
        _pd__56 = _x78*(-_x69*_x79 - _x69)
        _x80 = 2.0*q_r
        _pd__57 = (_x78*(-0.2113248654051871*_isigma0 - 0.7886751345948129*_isigma1 - _x63 - _x76*((0.5)*_x62
            + (0.5)*_x70*(0.4226497308103742*_isigma0 + 1.5773502691896257*_isigma1 - _x80
            - 8.470329472543003e-22*l0)) + 4.235164736271502e-22*l0))
        _pd__58 = _x78*(_x79*k_c + k_c)
        _pd__59 = 2.0*_x73*m*q_rd - _x76*_x77*k_c*m**2*q_rd**3
        _Q0__next = 0.25*_ifq0 + 0.5386751345948129*_ifq1 + q_th
        _Q1__next = -0.03867513459481288*_ifq0 + 0.25*_ifq1 + q_th
        _x81 = m*q_r**2
        _x82 = _x81*q_thd
        _P0__next = 0.25*_ifp0 + 0.5386751345948129*_ifp1 + _x82
        _x83 = _x80*m*q_thd
        _pd__60 = _x83
        _pd__61 = _x81
        _P1__next = -0.03867513459481288*_ifp0 + 0.25*_ifp1 + _x82
        _pd__62 = _x83
        _pd__63 = _x81
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_k_c__j = _T[0, _j1]
            d_q_r__j = _T[1, _j1]
            d_q_rd__j = _T[2, _j1]
            d_q_th__j = _T[3, _j1]
            d_q_thd__j = _T[4, _j1]
            _d_isigma0__j = _T[10, _j1]
            _d_iF0__j = _T[11, _j1]
            _d_isigma1__j = _T[12, _j1]
            _d_iF1__j = _T[13, _j1]
            _d_ifq0__j = _T[15, _j1]
            _d_ifp0__j = _T[16, _j1]
            _d_ifq1__j = _T[18, _j1]
            _d_ifp1__j = _T[19, _j1]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__53 + _d_iF1__j*_pd__54 + _d_isigma0__j*_pd__55
                + _d_isigma1__j*_pd__56 + _pd__57*d_k_c__j + _pd__58*d_q_r__j + _pd__59*d_q_rd__j)
            _d_Q0__next__j = 0.25*_d_ifq0__j + 0.5386751345948129*_d_ifq1__j + d_q_th__j
            _d_Q1__next__j = -0.03867513459481288*_d_ifq0__j + 0.25*_d_ifq1__j + d_q_th__j
            _d_P0__next__j = (0.25*_d_ifp0__j + 0.5386751345948129*_d_ifp1__j + _pd__60*d_q_r__j
                + _pd__61*d_q_thd__j)
            _d_P1__next__j = (-0.03867513459481288*_d_ifp0__j + 0.25*_d_ifp1__j + _pd__62*d_q_r__j
                + _pd__63*d_q_thd__j)
            _T[5, _j1] = _d_D__next__j
            _T[6, _j1] = _d_Q0__next__j
            _T[7, _j1] = _d_Q1__next__j
            _T[8, _j1] = _d_P0__next__j
            _T[9, _j1] = _d_P1__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _P0__next
        _n0_4 = _P1__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))) and (abs(_n0_4 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _P0 = _n0_3
        _P1 = _n0_4
        _passes += 1.0
    # bottom state
    t_half = 0.5*_ift0 + 0.5*_ift1
    end_q_th = 0.5*_ifq0 + 0.5*_ifq1 + q_th
    _x84 = -_D + q_r
    end_q_r = _x84
    end_q_rd = 0.0
    _x85 = q_r**2
    _x86 = 0.5*_ifp0 + 0.5*_ifp1 + _x85*m*q_thd
    _x91 = (1.0/_x84)
    _x87 = _x91**2
    _x88 = (1.0/m)
    _x89 = _x87*_x88
    end_q_thd = _x86*_x89
    _x90 = 0.5*_x89
    _pd__64 = _x90
    _pd__65 = _x90
    _pd__66 = -2.0*_x86*_x88*_x91**3
    _pd__67 = 2.0*_x87*q_r*q_thd
    _pd__68 = _x85*_x87
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[3, _j2]
        d_q_thd__j = _T[4, _j2]
        _d_D__j = _T[5, _j2]
        _d_ift0__j = _T[14, _j2]
        _d_ifq0__j = _T[15, _j2]
        _d_ifp0__j = _T[16, _j2]
        _d_ift1__j = _T[17, _j2]
        _d_ifq1__j = _T[18, _j2]
        _d_ifp1__j = _T[19, _j2]
        # bottom state
        d_t_half__j = 0.5*_d_ift0__j + 0.5*_d_ift1__j
        d_end_q_th__j = 0.5*_d_ifq0__j + 0.5*_d_ifq1__j + d_q_th__j
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__64 + _d_ifp1__j*_pd__65 + _pd__66*d_end_q_r__j + _pd__67*d_q_r__j
            + _pd__68*d_q_thd__j)
        _T[20, _j2] = d_t_half__j
        _T[21, _j2] = d_end_q_th__j
        _T[22, _j2] = d_end_q_r__j
        _T[23, _j2] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, d_t_half__5, ) = (_T[20, 0], _T[20, 1],
        _T[20, 2], _T[20, 3], _T[20, 4], _T[20, 5], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, ) = (_T[21, 0],
        _T[21, 1], _T[21, 2], _T[21, 3], _T[21, 4], _T[21, 5], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, ) = (_T[22, 0],
        _T[22, 1], _T[22, 2], _T[22, 3], _T[22, 4], _T[22, 5], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5,
        ) = (_T[23, 0], _T[23, 1], _T[23, 2], _T[23, 3], _T[23, 4], _T[23, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, STATUS_OK)


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
    # Total ops: 664
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((31, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 0.0
    _T[0, 4] = 1.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = 0.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 1.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 1.0 - d_guess_q_r__0
    _T[5, 1] = -d_guess_q_r__1
    _T[5, 2] = -d_guess_q_r__2
    _T[5, 3] = -d_guess_q_r__3
    _T[5, 4] = -d_guess_q_r__4
    _T[5, 5] = -d_guess_q_r__5
    _T[6, 0] = 0.8872983346207417*d_guess_q_th__0
    _T[6, 1] = 0.8872983346207417*d_guess_q_th__1
    _T[6, 2] = 0.8872983346207417*d_guess_q_th__2 + 0.11270166537925831
    _T[6, 3] = 0.8872983346207417*d_guess_q_th__3
    _T[6, 4] = 0.8872983346207417*d_guess_q_th__4
    _T[6, 5] = 0.8872983346207417*d_guess_q_th__5
    _T[7, 0] = 0.5*d_guess_q_th__0
    _T[7, 1] = 0.5*d_guess_q_th__1
    _T[7, 2] = 0.5*d_guess_q_th__2 + 0.5
    _T[7, 3] = 0.5*d_guess_q_th__3
    _T[7, 4] = 0.5*d_guess_q_th__4
    _T[7, 5] = 0.5*d_guess_q_th__5
    _T[8, 0] = 0.11270166537925831*d_guess_q_th__0
    _T[8, 1] = 0.11270166537925831*d_guess_q_th__1
    _T[8, 2] = 0.11270166537925831*d_guess_q_th__2 + 0.8872983346207417
    _T[8, 3] = 0.11270166537925831*d_guess_q_th__3
    _T[8, 4] = 0.11270166537925831*d_guess_q_th__4
    _T[8, 5] = 0.11270166537925831*d_guess_q_th__5
    _T[9, 0] = (1.7745966692414834*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__0*guess_q_r**2*m + 0.22540333075851662*m*q_r*q_thd)
    _T[9, 1] = (1.7745966692414834*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__1*guess_q_r**2*m)
    _T[9, 2] = (1.7745966692414834*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__2*guess_q_r**2*m)
    _T[9, 3] = (1.7745966692414834*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__3*guess_q_r**2*m + 0.11270166537925831*m*q_r**2)
    _T[9, 4] = (1.7745966692414834*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__4*guess_q_r**2*m)
    _T[9, 5] = (1.7745966692414834*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.8872983346207417*d_guess_q_thd__5*guess_q_r**2*m)
    _T[10, 0] = (1.0*d_guess_q_r__0*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__0*guess_q_r**2*m
        + 1.0*m*q_r*q_thd)
    _T[10, 1] = 1.0*d_guess_q_r__1*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__1*guess_q_r**2*m
    _T[10, 2] = 1.0*d_guess_q_r__2*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__2*guess_q_r**2*m
    _T[10, 3] = (1.0*d_guess_q_r__3*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__3*guess_q_r**2*m
        + 0.5*m*q_r**2)
    _T[10, 4] = 1.0*d_guess_q_r__4*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__4*guess_q_r**2*m
    _T[10, 5] = 1.0*d_guess_q_r__5*guess_q_r*guess_q_thd*m + 0.5*d_guess_q_thd__5*guess_q_r**2*m
    _T[11, 0] = (0.22540333075851662*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__0*guess_q_r**2*m + 1.7745966692414834*m*q_r*q_thd)
    _T[11, 1] = (0.22540333075851662*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__1*guess_q_r**2*m)
    _T[11, 2] = (0.22540333075851662*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__2*guess_q_r**2*m)
    _T[11, 3] = (0.22540333075851662*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__3*guess_q_r**2*m + 0.8872983346207417*m*q_r**2)
    _T[11, 4] = (0.22540333075851662*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__4*guess_q_r**2*m)
    _T[11, 5] = (0.22540333075851662*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.11270166537925831*d_guess_q_thd__5*guess_q_r**2*m)
    # Picard passes on the 3 node values (collocation in u)
    _D = -guess_q_r + q_r
    _Q0 = 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th
    _Q1 = 0.5*guess_q_th + 0.5*q_th
    _Q2 = 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th
    _P0 = 0.8872983346207417*guess_q_r**2*guess_q_thd*m + 0.11270166537925831*m*q_r**2*q_thd
    _P1 = 0.5*guess_q_r**2*guess_q_thd*m + 0.5*m*q_r**2*q_thd
    _P2 = 0.11270166537925831*guess_q_r**2*guess_q_thd*m + 0.8872983346207417*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9872983346207417*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x80 = (1.0/_x2)
        _x10 = _x80**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__69 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__70 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__71 = -_x15*_x8*_x80**4 - k_c
        _pd__72 = _x1 + l0
        _x16 = 0.75*_D + _x0
        _x17 = -_x16
        _isigma1 = _x17
        _x18 = math.cos(_Q1)
        _x19 = _x18*_x5
        _x20 = _x17*k_c
        _x21 = _P1**2
        _x79 = (1.0/_x17)
        _x22 = _x79**3
        _x23 = _x22*_x9
        _x24 = _x21*_x23
        _iF1 = -_x19 - _x20 + _x24 + _x3
        _x25 = 2.0*_P1
        _pd__73 = _x23*_x25
        _x26 = math.sin(_Q1)
        _pd__74 = _x26*_x5
        _pd__75 = -_x15*_x21*_x79**4 - k_c
        _pd__76 = _x16 + l0
        _x27 = 0.2127016653792583*_D + _x0
        _x28 = -_x27
        _isigma2 = _x28
        _x29 = math.cos(_Q2)
        _x30 = _x29*_x5
        _x31 = _x28*k_c
        _x32 = _P2**2
        _x81 = (1.0/_x28)
        _x33 = _x81**3
        _x34 = _x33*_x9
        _x35 = _x32*_x34
        _iF2 = _x3 - _x30 - _x31 + _x35
        _x36 = 2.0*_P2
        _pd__77 = _x34*_x36
        _x37 = math.sin(_Q2)
        _pd__78 = _x37*_x5
        _pd__79 = -_x15*_x32*_x81**4 - k_c
        _pd__80 = _x27 + l0
        _x38 = (0.5762768525670787*_x12 + 0.1040546303448565*_x19 + 0.1040546303448565*_x20
            - 0.1040546303448565*_x24 + 0.5*_x3 - 0.027777777777777776*_x30 - 0.027777777777777776*_x31
            + 0.027777777777777776*_x35 - 0.5762768525670787*_x6 - 0.5762768525670787*_x7)
        _iPsi0 = _x38
        _x39 = (1.0/math.sqrt(_x38))
        _x40 = math.sqrt(_D)
        _x41 = math.sqrt(m)
        _x42 = _x40*_x41
        _ift0 = _x39*_x42
        _x43 = (0.5)/_x40
        _x44 = _x41*_x43
        _pd__81 = _x39*_x44
        _x45 = _x38**(-1.5)
        _x46 = (0.5)*_x42
        _pd__82 = -_x45*_x46
        _x47 = (1.0/_x41)
        _x48 = _x40*_x47
        _x49 = _x80**2
        _x50 = _x39*_x49
        _x51 = _x48*_x50
        _ifq0 = _P0*_x51
        _x52 = _x43*_x47
        _pd__83 = _P0*_x50*_x52
        _pd__84 = _x51
        _x53 = (0.5)*_x48
        _pd__85 = -_P0*_x45*_x49*_x53
        _pd__86 = -_x10*_x13*_x39*_x48
        _x54 = g_s*m**(1.5)
        _x55 = _x40*_x54
        _x56 = _x39*_x55
        _x57 = _x14*_x56
        _ifp0 = _x2*_x57
        _x58 = _x14*_x2
        _x59 = _x43*_x54
        _pd__87 = _x39*_x58*_x59
        _pd__88 = _x2*_x4*_x56
        _x60 = (0.5)*_x55
        _pd__89 = -_x45*_x58*_x60
        _pd__90 = _x57
        _x61 = (0.17702731517242826*_x12 - 0.3611111111111111*_x19 - 0.3611111111111111*_x20
            + 0.3611111111111111*_x24 + 0.5*_x3 + 0.038138426283539355*_x30 + 0.038138426283539355*_x31
            - 0.038138426283539355*_x35 - 0.17702731517242826*_x6 - 0.17702731517242826*_x7)
        _iPsi1 = _x61
        _x62 = (1.0/math.sqrt(_x61))
        _ift1 = _x42*_x62
        _pd__91 = _x44*_x62
        _x63 = _x61**(-1.5)
        _pd__92 = -_x46*_x63
        _x64 = _x79**2
        _x65 = _x62*_x64
        _x66 = _x48*_x65
        _ifq1 = _P1*_x66
        _pd__93 = _P1*_x52*_x65
        _pd__94 = _x66
        _pd__95 = -_P1*_x53*_x63*_x64
        _pd__96 = -_x22*_x25*_x48*_x62
        _x67 = _x55*_x62
        _x68 = _x26*_x67
        _ifp1 = _x17*_x68
        _x69 = _x17*_x26
        _pd__97 = _x59*_x62*_x69
        _pd__98 = _x17*_x18*_x67
        _pd__99 = -_x60*_x63*_x69
        _pd__100 = _x68
        _x70 = (0.027777777777777776*_x10*_x8*_x9 - 0.3262768525670787*_x19 - 0.3262768525670787*_x20
            + 0.3262768525670787*_x21*_x22*_x9 - 0.14594536965514351*_x30 - 0.14594536965514351*_x31
            + 0.14594536965514351*_x32*_x33*_x9 - 0.027777777777777776*_x6 - 0.027777777777777776*_x7
            + 0.5*k_c*l0)
        _iPsi2 = _x70
        _x71 = (1.0/math.sqrt(_x70))
        _ift2 = _x42*_x71
        _pd__101 = _x44*_x71
        _x72 = _x70**(-1.5)
        _pd__102 = -_x46*_x72
        _x73 = _x81**2
        _x74 = _x71*_x73
        _x75 = _x48*_x74
        _ifq2 = _P2*_x75
        _pd__103 = _P2*_x52*_x74
        _pd__104 = _x75
        _pd__105 = -_P2*_x53*_x72*_x73
        _pd__106 = -_x33*_x36*_x48*_x71
        _x76 = _x55*_x71
        _x77 = _x37*_x76
        _ifp2 = _x28*_x77
        _x78 = _x28*_x37
        _pd__107 = _x59*_x71*_x78
        _pd__108 = _x28*_x29*_x76
        _pd__109 = -_x60*_x72*_x78
        _pd__110 = _x77
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_c__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[5, _j0]
            _d_Q0__j = _T[6, _j0]
            _d_Q1__j = _T[7, _j0]
            _d_Q2__j = _T[8, _j0]
            _d_P0__j = _T[9, _j0]
            _d_P1__j = _T[10, _j0]
            _d_P2__j = _T[11, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x82 = -d_q_r__j
            _d_isigma0__j = -0.9872983346207417*_d_D__j - _x82
            _d_iF0__j = _d_P0__j*_pd__69 + _d_Q0__j*_pd__70 + _d_isigma0__j*_pd__71 + _pd__72*d_k_c__j
            _d_isigma1__j = -0.75*_d_D__j - _x82
            _d_iF1__j = _d_P1__j*_pd__73 + _d_Q1__j*_pd__74 + _d_isigma1__j*_pd__75 + _pd__76*d_k_c__j
            _d_isigma2__j = -0.2127016653792583*_d_D__j - _x82
            _d_iF2__j = _d_P2__j*_pd__77 + _d_Q2__j*_pd__78 + _d_isigma2__j*_pd__79 + _pd__80*d_k_c__j
            _d_iPsi0__j = (0.5762768525670787*_d_iF0__j - 0.1040546303448565*_d_iF1__j
                + 0.027777777777777776*_d_iF2__j)
            _d_ift0__j = _d_D__j*_pd__81 + _d_iPsi0__j*_pd__82
            _d_ifq0__j = _d_D__j*_pd__83 + _d_P0__j*_pd__84 + _d_iPsi0__j*_pd__85 + _d_isigma0__j*_pd__86
            _d_ifp0__j = _d_D__j*_pd__87 + _d_Q0__j*_pd__88 + _d_iPsi0__j*_pd__89 + _d_isigma0__j*_pd__90
            _d_iPsi1__j = (0.17702731517242826*_d_iF0__j + 0.3611111111111111*_d_iF1__j
                - 0.038138426283539355*_d_iF2__j)
            _d_ift1__j = _d_D__j*_pd__91 + _d_iPsi1__j*_pd__92
            _d_ifq1__j = _d_D__j*_pd__93 + _d_P1__j*_pd__94 + _d_iPsi1__j*_pd__95 + _d_isigma1__j*_pd__96
            _d_ifp1__j = _d_D__j*_pd__97 + _d_Q1__j*_pd__98 + _d_iPsi1__j*_pd__99 + _d_isigma1__j*_pd__100
            _d_iPsi2__j = (0.027777777777777776*_d_iF0__j + 0.3262768525670787*_d_iF1__j
                + 0.14594536965514351*_d_iF2__j)
            _d_ift2__j = _d_D__j*_pd__101 + _d_iPsi2__j*_pd__102
            _d_ifq2__j = _d_D__j*_pd__103 + _d_P2__j*_pd__104 + _d_iPsi2__j*_pd__105 + _d_isigma2__j*_pd__106
            _d_ifp2__j = _d_D__j*_pd__107 + _d_Q2__j*_pd__108 + _d_iPsi2__j*_pd__109 + _d_isigma2__j*_pd__110
            _T[12, _j0] = _d_isigma0__j
            _T[13, _j0] = _d_iF0__j
            _T[14, _j0] = _d_isigma1__j
            _T[15, _j0] = _d_iF1__j
            _T[16, _j0] = _d_isigma2__j
            _T[17, _j0] = _d_iF2__j
            _T[18, _j0] = _d_ift0__j
            _T[19, _j0] = _d_ifq0__j
            _T[20, _j0] = _d_ifp0__j
            _T[21, _j0] = _d_ift1__j
            _T[22, _j0] = _d_ifq1__j
            _T[23, _j0] = _d_ifp1__j
            _T[24, _j0] = _d_ift2__j
            _T[25, _j0] = _d_ifq2__j
            _T[26, _j0] = _d_ifp2__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x83 = m*q_rd**2
        _x84 = -q_r
        _x85 = k_c*(_x84 + l0)
        _x86 = -l0
        _x87 = -_isigma0 - _x86
        _x88 = 0.06261203632181017*k_c
        _x89 = -_isigma1 - _x86
        _x90 = 0.4444444444444444*k_c
        _x91 = -_isigma2 - _x86
        _x92 = 0.4929435192337454*k_c
        _x93 = (0.06261203632181017*_iF0 + 0.4444444444444444*_iF1 + 0.4929435192337454*_iF2 + _x85
            - _x87*_x88 - _x89*_x90 - _x91*_x92)
        _x94 = math.sqrt(_x83*k_c + _x93**2)
        _x95 = _x93 + _x94
        _x96 = (1.0/_x95)
        _D__next = _x83*_x96
        _x97 = _x87*k_c
        _x98 = _x89*k_c
        _x99 = _x91*k_c
        _x100 = (1.0/_x94)
        _x101 = _x96**2
        _x102 = _x101*_x83
        _pd__111 = (_x102*(-_x100*(0.0039202670923636765*_iF0 + 0.0278275716985823*_iF1
            + 0.030864197530864196*_iF2 + 0.06261203632181017*_x85 - 0.0039202670923636765*_x97
            - 0.0278275716985823*_x98 - 0.030864197530864196*_x99) - 0.06261203632181017))
        _pd__112 = (_x102*(-_x100*(0.0278275716985823*_iF0 + 0.19753086419753085*_iF1
            + 0.21908600854833127*_iF2 + 0.4444444444444444*_x85 - 0.0278275716985823*_x97
            - 0.19753086419753085*_x98 - 0.21908600854833127*_x99) - 0.4444444444444444))
        _pd__113 = (_x102*(-_x100*(0.030864197530864196*_iF0 + 0.21908600854833127*_iF1
            + 0.24299331315454992*_iF2 + 0.4929435192337454*_x85 - 0.030864197530864196*_x97
            - 0.21908600854833127*_x98 - 0.24299331315454992*_x99) - 0.4929435192337454))
        _x103 = _x100*_x93
        _pd__114 = _x102*(-_x103*_x88 - _x88)
        _pd__115 = _x102*(-_x103*_x90 - _x90)
        _pd__116 = _x102*(-_x103*_x92 - _x92)
        _x104 = 2.0*q_r
        _pd__117 = (_x102*(-0.06261203632181017*_isigma0 - 0.4444444444444444*_isigma1
            - 0.4929435192337454*_isigma2 - _x100*((0.5)*_x83 + (0.5)*_x93*(0.12522407264362034*_isigma0
            + 0.8888888888888888*_isigma1 + 0.9858870384674908*_isigma2 - _x104)) - _x84))
        _pd__118 = _x102*(_x103*k_c + k_c)
        _pd__119 = -_x100*_x101*k_c*m**2*q_rd**3 + 2.0*_x96*m*q_rd
        _Q0__next = 0.1388888888888889*_ifq0 + 0.48042111196938336*_ifq1 + 0.26798833376246944*_ifq2 + q_th
        _Q1__next = -0.022485417203086815*_ifq0 + 0.2222222222222222*_ifq1 + 0.30026319498086457*_ifq2 + q_th
        _Q2__next = 0.009789444015308325*_ifq0 - 0.0359766675249389*_ifq1 + 0.1388888888888889*_ifq2 + q_th
        _x105 = m*q_r**2
        _x106 = _x105*q_thd
        _P0__next = 0.1388888888888889*_ifp0 + 0.48042111196938336*_ifp1 + 0.26798833376246944*_ifp2 + _x106
        _x107 = _x104*m*q_thd
        _pd__120 = _x107
        _pd__121 = _x105
        _P1__next = -0.022485417203086815*_ifp0 + 0.2222222222222222*_ifp1 + 0.30026319498086457*_ifp2 + _x106
        _pd__122 = _x107
        _pd__123 = _x105
        _P2__next = 0.009789444015308325*_ifp0 - 0.0359766675249389*_ifp1 + 0.1388888888888889*_ifp2 + _x106
        _pd__124 = _x107
        _pd__125 = _x105
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_k_c__j = _T[0, _j1]
            d_q_r__j = _T[1, _j1]
            d_q_rd__j = _T[2, _j1]
            d_q_th__j = _T[3, _j1]
            d_q_thd__j = _T[4, _j1]
            _d_isigma0__j = _T[12, _j1]
            _d_iF0__j = _T[13, _j1]
            _d_isigma1__j = _T[14, _j1]
            _d_iF1__j = _T[15, _j1]
            _d_isigma2__j = _T[16, _j1]
            _d_iF2__j = _T[17, _j1]
            _d_ifq0__j = _T[19, _j1]
            _d_ifp0__j = _T[20, _j1]
            _d_ifq1__j = _T[22, _j1]
            _d_ifp1__j = _T[23, _j1]
            _d_ifq2__j = _T[25, _j1]
            _d_ifp2__j = _T[26, _j1]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__111 + _d_iF1__j*_pd__112 + _d_iF2__j*_pd__113
                + _d_isigma0__j*_pd__114 + _d_isigma1__j*_pd__115 + _d_isigma2__j*_pd__116 + _pd__117*d_k_c__j
                + _pd__118*d_q_r__j + _pd__119*d_q_rd__j)
            _d_Q0__next__j = (0.1388888888888889*_d_ifq0__j + 0.48042111196938336*_d_ifq1__j
                + 0.26798833376246944*_d_ifq2__j + d_q_th__j)
            _d_Q1__next__j = (-0.022485417203086815*_d_ifq0__j + 0.2222222222222222*_d_ifq1__j
                + 0.30026319498086457*_d_ifq2__j + d_q_th__j)
            _d_Q2__next__j = (0.009789444015308325*_d_ifq0__j - 0.0359766675249389*_d_ifq1__j
                + 0.1388888888888889*_d_ifq2__j + d_q_th__j)
            _d_P0__next__j = (0.1388888888888889*_d_ifp0__j + 0.48042111196938336*_d_ifp1__j
                + 0.26798833376246944*_d_ifp2__j + _pd__120*d_q_r__j + _pd__121*d_q_thd__j)
            _d_P1__next__j = (-0.022485417203086815*_d_ifp0__j + 0.2222222222222222*_d_ifp1__j
                + 0.30026319498086457*_d_ifp2__j + _pd__122*d_q_r__j + _pd__123*d_q_thd__j)
            _d_P2__next__j = (0.009789444015308325*_d_ifp0__j - 0.0359766675249389*_d_ifp1__j
                + 0.1388888888888889*_d_ifp2__j + _pd__124*d_q_r__j + _pd__125*d_q_thd__j)
            _T[5, _j1] = _d_D__next__j
            _T[6, _j1] = _d_Q0__next__j
            _T[7, _j1] = _d_Q1__next__j
            _T[8, _j1] = _d_Q2__next__j
            _T[9, _j1] = _d_P0__next__j
            _T[10, _j1] = _d_P1__next__j
            _T[11, _j1] = _d_P2__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _P0__next
        _n0_5 = _P1__next
        _n0_6 = _P2__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_5 - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _P0 = _n0_4
        _P1 = _n0_5
        _P2 = _n0_6
        _passes += 1.0
    # bottom state
    t_half = 0.2777777777777778*_ift0 + 0.4444444444444444*_ift1 + 0.2777777777777778*_ift2
    end_q_th = 0.2777777777777778*_ifq0 + 0.4444444444444444*_ifq1 + 0.2777777777777778*_ifq2 + q_th
    _x108 = -_D + q_r
    end_q_r = _x108
    end_q_rd = 0.0
    _x109 = q_r**2
    _x110 = 0.2777777777777778*_ifp0 + 0.4444444444444444*_ifp1 + 0.2777777777777778*_ifp2 + _x109*m*q_thd
    _x115 = (1.0/_x108)
    _x111 = _x115**2
    _x112 = (1.0/m)
    _x113 = _x111*_x112
    end_q_thd = _x110*_x113
    _x114 = 0.2777777777777778*_x113
    _pd__126 = _x114
    _pd__127 = 0.4444444444444444*_x113
    _pd__128 = _x114
    _pd__129 = -2.0*_x110*_x112*_x115**3
    _pd__130 = 2.0*_x111*q_r*q_thd
    _pd__131 = _x109*_x111
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[3, _j2]
        d_q_thd__j = _T[4, _j2]
        _d_D__j = _T[5, _j2]
        _d_ift0__j = _T[18, _j2]
        _d_ifq0__j = _T[19, _j2]
        _d_ifp0__j = _T[20, _j2]
        _d_ift1__j = _T[21, _j2]
        _d_ifq1__j = _T[22, _j2]
        _d_ifp1__j = _T[23, _j2]
        _d_ift2__j = _T[24, _j2]
        _d_ifq2__j = _T[25, _j2]
        _d_ifp2__j = _T[26, _j2]
        # bottom state
        d_t_half__j = (0.2777777777777778*_d_ift0__j + 0.4444444444444444*_d_ift1__j
            + 0.2777777777777778*_d_ift2__j)
        d_end_q_th__j = (0.2777777777777778*_d_ifq0__j + 0.4444444444444444*_d_ifq1__j
            + 0.2777777777777778*_d_ifq2__j + d_q_th__j)
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__126 + _d_ifp1__j*_pd__127 + _d_ifp2__j*_pd__128
            + _pd__129*d_end_q_r__j + _pd__130*d_q_r__j + _pd__131*d_q_thd__j)
        _T[27, _j2] = d_t_half__j
        _T[28, _j2] = d_end_q_th__j
        _T[29, _j2] = d_end_q_r__j
        _T[30, _j2] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, d_t_half__5, ) = (_T[27, 0], _T[27, 1],
        _T[27, 2], _T[27, 3], _T[27, 4], _T[27, 5], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, ) = (_T[28, 0],
        _T[28, 1], _T[28, 2], _T[28, 3], _T[28, 4], _T[28, 5], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, ) = (_T[29, 0],
        _T[29, 1], _T[29, 2], _T[29, 3], _T[29, 4], _T[29, 5], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5,
        ) = (_T[30, 0], _T[30, 1], _T[30, 2], _T[30, 3], _T[30, 4], _T[30, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, STATUS_OK)


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
    # Total ops: 956
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((38, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 0.0
    _T[0, 4] = 1.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = 0.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 1.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 1.0 - d_guess_q_r__0
    _T[5, 1] = -d_guess_q_r__1
    _T[5, 2] = -d_guess_q_r__2
    _T[5, 3] = -d_guess_q_r__3
    _T[5, 4] = -d_guess_q_r__4
    _T[5, 5] = -d_guess_q_r__5
    _T[6, 0] = 0.9305681557970263*d_guess_q_th__0
    _T[6, 1] = 0.9305681557970263*d_guess_q_th__1
    _T[6, 2] = 0.9305681557970263*d_guess_q_th__2 + 0.06943184420297371
    _T[6, 3] = 0.9305681557970263*d_guess_q_th__3
    _T[6, 4] = 0.9305681557970263*d_guess_q_th__4
    _T[6, 5] = 0.9305681557970263*d_guess_q_th__5
    _T[7, 0] = 0.6699905217924281*d_guess_q_th__0
    _T[7, 1] = 0.6699905217924281*d_guess_q_th__1
    _T[7, 2] = 0.6699905217924281*d_guess_q_th__2 + 0.33000947820757187
    _T[7, 3] = 0.6699905217924281*d_guess_q_th__3
    _T[7, 4] = 0.6699905217924281*d_guess_q_th__4
    _T[7, 5] = 0.6699905217924281*d_guess_q_th__5
    _T[8, 0] = 0.33000947820757187*d_guess_q_th__0
    _T[8, 1] = 0.33000947820757187*d_guess_q_th__1
    _T[8, 2] = 0.33000947820757187*d_guess_q_th__2 + 0.6699905217924281
    _T[8, 3] = 0.33000947820757187*d_guess_q_th__3
    _T[8, 4] = 0.33000947820757187*d_guess_q_th__4
    _T[8, 5] = 0.33000947820757187*d_guess_q_th__5
    _T[9, 0] = 0.06943184420297371*d_guess_q_th__0
    _T[9, 1] = 0.06943184420297371*d_guess_q_th__1
    _T[9, 2] = 0.06943184420297371*d_guess_q_th__2 + 0.9305681557970263
    _T[9, 3] = 0.06943184420297371*d_guess_q_th__3
    _T[9, 4] = 0.06943184420297371*d_guess_q_th__4
    _T[9, 5] = 0.06943184420297371*d_guess_q_th__5
    _T[10, 0] = (1.8611363115940527*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__0*guess_q_r**2*m + 0.13886368840594743*m*q_r*q_thd)
    _T[10, 1] = (1.8611363115940527*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__1*guess_q_r**2*m)
    _T[10, 2] = (1.8611363115940527*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__2*guess_q_r**2*m)
    _T[10, 3] = (1.8611363115940527*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__3*guess_q_r**2*m + 0.06943184420297371*m*q_r**2)
    _T[10, 4] = (1.8611363115940527*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__4*guess_q_r**2*m)
    _T[10, 5] = (1.8611363115940527*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.9305681557970263*d_guess_q_thd__5*guess_q_r**2*m)
    _T[11, 0] = (1.3399810435848563*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__0*guess_q_r**2*m + 0.6600189564151437*m*q_r*q_thd)
    _T[11, 1] = (1.3399810435848563*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__1*guess_q_r**2*m)
    _T[11, 2] = (1.3399810435848563*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__2*guess_q_r**2*m)
    _T[11, 3] = (1.3399810435848563*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__3*guess_q_r**2*m + 0.33000947820757187*m*q_r**2)
    _T[11, 4] = (1.3399810435848563*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__4*guess_q_r**2*m)
    _T[11, 5] = (1.3399810435848563*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.6699905217924281*d_guess_q_thd__5*guess_q_r**2*m)
    _T[12, 0] = (0.6600189564151437*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__0*guess_q_r**2*m + 1.3399810435848563*m*q_r*q_thd)
    _T[12, 1] = (0.6600189564151437*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__1*guess_q_r**2*m)
    _T[12, 2] = (0.6600189564151437*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__2*guess_q_r**2*m)
    _T[12, 3] = (0.6600189564151437*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__3*guess_q_r**2*m + 0.6699905217924281*m*q_r**2)
    _T[12, 4] = (0.6600189564151437*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__4*guess_q_r**2*m)
    _T[12, 5] = (0.6600189564151437*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.33000947820757187*d_guess_q_thd__5*guess_q_r**2*m)
    _T[13, 0] = (0.13886368840594743*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__0*guess_q_r**2*m + 1.8611363115940527*m*q_r*q_thd)
    _T[13, 1] = (0.13886368840594743*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__1*guess_q_r**2*m)
    _T[13, 2] = (0.13886368840594743*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__2*guess_q_r**2*m)
    _T[13, 3] = (0.13886368840594743*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__3*guess_q_r**2*m + 0.9305681557970263*m*q_r**2)
    _T[13, 4] = (0.13886368840594743*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__4*guess_q_r**2*m)
    _T[13, 5] = (0.13886368840594743*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.06943184420297371*d_guess_q_thd__5*guess_q_r**2*m)
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
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9951792190105739*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x100 = (1.0/_x2)
        _x10 = _x100**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__132 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__133 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__134 = -_x100**4*_x15*_x8 - k_c
        _pd__135 = _x1 + l0
        _x16 = 0.8910937442931661*_D + _x0
        _x17 = -_x16
        _isigma1 = _x17
        _x18 = math.cos(_Q1)
        _x19 = _x18*_x5
        _x20 = _x17*k_c
        _x21 = _P1**2
        _x99 = (1.0/_x17)
        _x22 = _x99**3
        _x23 = _x22*_x9
        _x24 = _x21*_x23
        _iF1 = -_x19 - _x20 + _x24 + _x3
        _x25 = 2.0*_P1
        _pd__136 = _x23*_x25
        _x26 = math.sin(_Q1)
        _pd__137 = _x26*_x5
        _pd__138 = -_x15*_x21*_x99**4 - k_c
        _pd__139 = _x16 + l0
        _x27 = 0.5511127007083099*_D + _x0
        _x28 = -_x27
        _isigma2 = _x28
        _x29 = math.cos(_Q2)
        _x30 = _x29*_x5
        _x31 = _x28*k_c
        _x32 = _P2**2
        _x101 = (1.0/_x28)
        _x33 = _x101**3
        _x34 = _x33*_x9
        _x35 = _x32*_x34
        _iF2 = _x3 - _x30 - _x31 + _x35
        _x36 = 2.0*_P2
        _pd__140 = _x34*_x36
        _x37 = math.sin(_Q2)
        _pd__141 = _x37*_x5
        _pd__142 = -_x101**4*_x15*_x32 - k_c
        _pd__143 = _x27 + l0
        _x38 = 0.13404290741652142*_D + _x0
        _x39 = -_x38
        _isigma3 = _x39
        _x40 = math.cos(_Q3)
        _x41 = _x40*_x5
        _x42 = _x39*k_c
        _x43 = _P3**2
        _x102 = (1.0/_x39)
        _x44 = _x102**3
        _x45 = _x44*_x9
        _x46 = _x43*_x45
        _iF3 = _x3 - _x41 - _x42 + _x46
        _x47 = 2.0*_P3
        _pd__144 = _x45*_x47
        _x48 = math.sin(_Q3)
        _pd__145 = _x48*_x5
        _pd__146 = -_x102**4*_x15*_x43 - k_c
        _pd__147 = _x38 + l0
        _x49 = (0.582374038291501*_x12 + 0.12383458041329967*_x19 + 0.12383458041329967*_x20
            - 0.12383458041329967*_x24 + 0.5*_x3 - 0.0575898635297681*_x30 - 0.0575898635297681*_x31
            + 0.0575898635297681*_x35 + 0.016129321407969507*_x41 + 0.016129321407969507*_x42
            - 0.016129321407969507*_x46 - 0.582374038291501*_x6 - 0.582374038291501*_x7)
        _iPsi0 = _x49
        _x50 = (1.0/math.sqrt(_x49))
        _x51 = math.sqrt(_D)
        _x52 = math.sqrt(m)
        _x53 = _x51*_x52
        _ift0 = _x50*_x53
        _x54 = (0.5)/_x51
        _x55 = _x52*_x54
        _pd__148 = _x50*_x55
        _x56 = _x49**(-1.5)
        _x57 = (0.5)*_x53
        _pd__149 = -_x56*_x57
        _x58 = (1.0/_x52)
        _x59 = _x51*_x58
        _x60 = _x100**2
        _x61 = _x50*_x60
        _x62 = _x59*_x61
        _ifq0 = _P0*_x62
        _x63 = _x54*_x58
        _pd__150 = _P0*_x61*_x63
        _pd__151 = _x62
        _x64 = (0.5)*_x59
        _pd__152 = -_P0*_x56*_x60*_x64
        _pd__153 = -_x10*_x13*_x50*_x59
        _x65 = g_s*m**(1.5)
        _x66 = _x51*_x65
        _x67 = _x50*_x66
        _x68 = _x14*_x67
        _ifp0 = _x2*_x68
        _x69 = _x14*_x2
        _x70 = _x54*_x65
        _pd__154 = _x50*_x69*_x70
        _pd__155 = _x2*_x4*_x67
        _x71 = (0.5)*_x66
        _pd__156 = -_x56*_x69*_x71
        _pd__157 = _x68
        _x72 = (0.16000937841634696*_x10*_x8*_x9 - 0.39252437029865583*_x19 - 0.39252437029865583*_x20
            + 0.39252437029865583*_x21*_x22*_x9 + 0.0700094015044783*_x28*k_c + 0.0700094015044783*_x29*g_s*m
            - 0.0700094015044783*_x35 - 0.017475652789475504*_x41 - 0.017475652789475504*_x42
            + 0.017475652789475504*_x43*_x44*_x9 - 0.16000937841634696*_x6 - 0.16000937841634696*_x7
            + 0.5*k_c*l0)
        _iPsi1 = _x72
        _x73 = (1.0/math.sqrt(_x72))
        _ift1 = _x53*_x73
        _pd__158 = _x55*_x73
        _x74 = _x72**(-1.5)
        _pd__159 = -_x57*_x74
        _x75 = _x99**2
        _x76 = _x73*_x75
        _x77 = _x59*_x76
        _ifq1 = _P1*_x77
        _pd__160 = _P1*_x63*_x76
        _pd__161 = _x77
        _pd__162 = -_P1*_x64*_x74*_x75
        _pd__163 = -_x22*_x25*_x59*_x73
        _x78 = _x66*_x73
        _x79 = _x26*_x78
        _ifp1 = _x17*_x79
        _x80 = _x17*_x26
        _pd__164 = _x70*_x73*_x80
        _pd__165 = _x17*_x18*_x78
        _pd__166 = -_x71*_x74*_x80
        _pd__167 = _x79
        _x81 = (0.01613725546399532*_x10*_x8*_x9 - 0.2848443432415939*_x19 - 0.2848443432415939*_x20
            + 0.2848443432415939*_x21*_x22*_x9 - 0.21871326539550162*_x30 - 0.21871326539550162*_x31
            + 0.21871326539550162*_x32*_x33*_x9 + 0.019694864101090868*_x39*k_c
            + 0.019694864101090868*_x40*g_s*m - 0.019694864101090868*_x46 - 0.01613725546399532*_x6
            - 0.01613725546399532*_x7 + 0.5*k_c*l0)
        _iPsi2 = _x81
        _x82 = (1.0/math.sqrt(_x81))
        _ift2 = _x53*_x82
        _pd__168 = _x55*_x82
        _x83 = _x81**(-1.5)
        _pd__169 = -_x57*_x83
        _x84 = _x101**2
        _x85 = _x82*_x84
        _x86 = _x59*_x85
        _ifq2 = _P2*_x86
        _pd__170 = _P2*_x63*_x85
        _pd__171 = _x86
        _pd__172 = -_P2*_x64*_x83*_x84
        _pd__173 = -_x33*_x36*_x59*_x82
        _x87 = _x66*_x82
        _x88 = _x37*_x87
        _ifp2 = _x28*_x88
        _x89 = _x28*_x37
        _pd__174 = _x70*_x82*_x89
        _pd__175 = _x28*_x29*_x87
        _pd__176 = -_x71*_x83*_x89
        _pd__177 = _x88
        _x90 = (0.01796104633752054*_x10*_x8*_x9 - 0.11000222456933441*_x19 - 0.11000222456933441*_x20
            + 0.11000222456933441*_x21*_x22*_x9 - 0.2823150697454702*_x30 - 0.2823150697454702*_x31
            + 0.2823150697454702*_x32*_x33*_x9 - 0.08972165934767481*_x41 - 0.08972165934767481*_x42
            + 0.08972165934767481*_x43*_x44*_x9 - 0.01796104633752054*_x6 - 0.01796104633752054*_x7
            + 0.5*k_c*l0)
        _iPsi3 = _x90
        _x91 = (1.0/math.sqrt(_x90))
        _ift3 = _x53*_x91
        _pd__178 = _x55*_x91
        _x92 = _x90**(-1.5)
        _pd__179 = -_x57*_x92
        _x93 = _x102**2
        _x94 = _x91*_x93
        _x95 = _x59*_x94
        _ifq3 = _P3*_x95
        _pd__180 = _P3*_x63*_x94
        _pd__181 = _x95
        _pd__182 = -_P3*_x64*_x92*_x93
        _pd__183 = -_x44*_x47*_x59*_x91
        _x96 = _x66*_x91
        _x97 = _x48*_x96
        _ifp3 = _x39*_x97
        _x98 = _x39*_x48
        _pd__184 = _x70*_x91*_x98
        _pd__185 = _x39*_x40*_x96
        _pd__186 = -_x71*_x92*_x98
        _pd__187 = _x97
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
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_c__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[5, _j0]
            _d_Q0__j = _T[6, _j0]
            _d_Q1__j = _T[7, _j0]
            _d_Q2__j = _T[8, _j0]
            _d_Q3__j = _T[9, _j0]
            _d_P0__j = _T[10, _j0]
            _d_P1__j = _T[11, _j0]
            _d_P2__j = _T[12, _j0]
            _d_P3__j = _T[13, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x103 = -d_q_r__j
            _d_isigma0__j = -0.9951792190105739*_d_D__j - _x103
            _d_iF0__j = _d_P0__j*_pd__132 + _d_Q0__j*_pd__133 + _d_isigma0__j*_pd__134 + _pd__135*d_k_c__j
            _d_isigma1__j = -0.8910937442931661*_d_D__j - _x103
            _d_iF1__j = _d_P1__j*_pd__136 + _d_Q1__j*_pd__137 + _d_isigma1__j*_pd__138 + _pd__139*d_k_c__j
            _d_isigma2__j = -0.5511127007083099*_d_D__j - _x103
            _d_iF2__j = _d_P2__j*_pd__140 + _d_Q2__j*_pd__141 + _d_isigma2__j*_pd__142 + _pd__143*d_k_c__j
            _d_isigma3__j = -0.13404290741652142*_d_D__j - _x103
            _d_iF3__j = _d_P3__j*_pd__144 + _d_Q3__j*_pd__145 + _d_isigma3__j*_pd__146 + _pd__147*d_k_c__j
            _d_iPsi0__j = (0.582374038291501*_d_iF0__j - 0.12383458041329967*_d_iF1__j
                + 0.0575898635297681*_d_iF2__j - 0.016129321407969507*_d_iF3__j)
            _d_ift0__j = _d_D__j*_pd__148 + _d_iPsi0__j*_pd__149
            _d_ifq0__j = _d_D__j*_pd__150 + _d_P0__j*_pd__151 + _d_iPsi0__j*_pd__152 + _d_isigma0__j*_pd__153
            _d_ifp0__j = _d_D__j*_pd__154 + _d_Q0__j*_pd__155 + _d_iPsi0__j*_pd__156 + _d_isigma0__j*_pd__157
            _d_iPsi1__j = (0.16000937841634696*_d_iF0__j + 0.39252437029865583*_d_iF1__j
                - 0.0700094015044783*_d_iF2__j + 0.017475652789475504*_d_iF3__j)
            _d_ift1__j = _d_D__j*_pd__158 + _d_iPsi1__j*_pd__159
            _d_ifq1__j = _d_D__j*_pd__160 + _d_P1__j*_pd__161 + _d_iPsi1__j*_pd__162 + _d_isigma1__j*_pd__163
            _d_ifp1__j = _d_D__j*_pd__164 + _d_Q1__j*_pd__165 + _d_iPsi1__j*_pd__166 + _d_isigma1__j*_pd__167
            _d_iPsi2__j = (0.01613725546399532*_d_iF0__j + 0.2848443432415939*_d_iF1__j
                + 0.21871326539550162*_d_iF2__j - 0.019694864101090868*_d_iF3__j)
            _d_ift2__j = _d_D__j*_pd__168 + _d_iPsi2__j*_pd__169
            _d_ifq2__j = _d_D__j*_pd__170 + _d_P2__j*_pd__171 + _d_iPsi2__j*_pd__172 + _d_isigma2__j*_pd__173
            _d_ifp2__j = _d_D__j*_pd__174 + _d_Q2__j*_pd__175 + _d_iPsi2__j*_pd__176 + _d_isigma2__j*_pd__177
            _d_iPsi3__j = (0.01796104633752054*_d_iF0__j + 0.11000222456933441*_d_iF1__j
                + 0.2823150697454702*_d_iF2__j + 0.08972165934767481*_d_iF3__j)
            _d_ift3__j = _d_D__j*_pd__178 + _d_iPsi3__j*_pd__179
            _d_ifq3__j = _d_D__j*_pd__180 + _d_P3__j*_pd__181 + _d_iPsi3__j*_pd__182 + _d_isigma3__j*_pd__183
            _d_ifp3__j = _d_D__j*_pd__184 + _d_Q3__j*_pd__185 + _d_iPsi3__j*_pd__186 + _d_isigma3__j*_pd__187
            _T[14, _j0] = _d_isigma0__j
            _T[15, _j0] = _d_iF0__j
            _T[16, _j0] = _d_isigma1__j
            _T[17, _j0] = _d_iF1__j
            _T[18, _j0] = _d_isigma2__j
            _T[19, _j0] = _d_iF2__j
            _T[20, _j0] = _d_isigma3__j
            _T[21, _j0] = _d_iF3__j
            _T[22, _j0] = _d_ift0__j
            _T[23, _j0] = _d_ifq0__j
            _T[24, _j0] = _d_ifp0__j
            _T[25, _j0] = _d_ift1__j
            _T[26, _j0] = _d_ifq1__j
            _T[27, _j0] = _d_ifp1__j
            _T[28, _j0] = _d_ift2__j
            _T[29, _j0] = _d_ifq2__j
            _T[30, _j0] = _d_ifp2__j
            _T[31, _j0] = _d_ift3__j
            _T[32, _j0] = _d_ifq3__j
            _T[33, _j0] = _d_ifp3__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x104 = m*q_rd**2
        _x105 = -q_r
        _x106 = k_c*(_x105 + l0)
        _x107 = -l0
        _x108 = -_isigma0 - _x107
        _x109 = 0.024152203412833244*k_c
        _x110 = -_isigma1 - _x107
        _x111 = 0.215214082271785*k_c
        _x112 = -_isigma2 - _x107
        _x113 = 0.43693107259076114*k_c
        _x114 = -_isigma3 - _x107
        _x115 = 0.3237026417246206*k_c
        _x116 = (0.024152203412833244*_iF0 + 0.215214082271785*_iF1 + 0.43693107259076114*_iF2
            + 0.3237026417246206*_iF3 + _x106 - _x108*_x109 - _x110*_x111 - _x112*_x113 - _x114*_x115)
        _x117 = math.sqrt(_x104*k_c + _x116**2)
        _x118 = _x116 + _x117
        _x119 = (1.0/_x118)
        _D__next = _x104*_x119
        _x120 = _x108*k_c
        _x121 = 0.0051978942923343804*k_c
        _x122 = _x112*k_c
        _x123 = _x114*k_c
        _x124 = (1.0/_x117)
        _x125 = _x119**2
        _x126 = _x104*_x125
        _pd__188 = (_x126*(-_x124*(0.0005833289296948737*_iF0 + 0.0051978942923343804*_iF1
            + 0.01055284814259947*_iF2 + 0.007818132048204519*_iF3 + 0.024152203412833244*_x106 - _x110*_x121
            - 0.0005833289296948737*_x120 - 0.01055284814259947*_x122 - 0.007818132048204519*_x123)
            - 0.024152203412833244))
        _x127 = _x110*k_c
        _pd__189 = (_x126*(-_x124*(0.0051978942923343804*_iF0 + 0.046317101208086645*_iF1
            + 0.09403371980364733*_iF2 + 0.06966536696771665*_iF3 + 0.215214082271785*_x106 - _x108*_x121
            - 0.09403371980364733*_x122 - 0.06966536696771665*_x123 - 0.046317101208086645*_x127)
            - 0.215214082271785))
        _pd__190 = (_x126*(-_x124*(0.01055284814259947*_iF0 + 0.09403371980364733*_iF1
            + 0.19090876219531297*_iF2 + 0.14143574244920135*_iF3 + 0.43693107259076114*_x106
            - 0.01055284814259947*_x120 - 0.19090876219531297*_x122 - 0.14143574244920135*_x123
            - 0.09403371980364733*_x127) - 0.43693107259076114))
        _pd__191 = (_x126*(-_x124*(0.007818132048204519*_iF0 + 0.06966536696771665*_iF1
            + 0.14143574244920135*_iF2 + 0.10478340025949809*_iF3 + 0.3237026417246206*_x106
            - 0.007818132048204519*_x120 - 0.14143574244920135*_x122 - 0.10478340025949809*_x123
            - 0.06966536696771665*_x127) - 0.3237026417246206))
        _x128 = _x116*_x124
        _pd__192 = _x126*(-_x109*_x128 - _x109)
        _pd__193 = _x126*(-_x111*_x128 - _x111)
        _pd__194 = _x126*(-_x113*_x128 - _x113)
        _pd__195 = _x126*(-_x115*_x128 - _x115)
        _x129 = 2.0*q_r
        _pd__196 = (_x126*(-0.024152203412833244*_isigma0 - 0.215214082271785*_isigma1
            - 0.43693107259076114*_isigma2 - 0.3237026417246206*_isigma3 - _x105 - _x124*((0.5)*_x104
            + (0.5)*_x116*(0.04830440682566649*_isigma0 + 0.43042816454357*_isigma1
            + 0.8738621451815223*_isigma2 + 0.6474052834492412*_isigma3 - _x129 - 8.470329472543003e-22*l0))
            + 4.235164736271502e-22*l0))
        _pd__197 = _x126*(_x128*k_c + k_c)
        _pd__198 = 2.0*_x119*m*q_rd - _x124*_x125*k_c*m**2*q_rd**3
        _Q0__next = (0.08696371128436346*_ifq0 + 0.35267675751627187*_ifq1 + 0.31344511474186837*_ifq2
            + 0.1774825722545226*_ifq3 + q_th)
        _Q1__next = (-0.014190694931141144*_ifq0 + 0.16303628871563652*_ifq1 + 0.35395300603374397*_ifq2
            + 0.16719192197418878*_ifq3 + q_th)
        _Q2__next = (0.006735500594538156*_ifq0 - 0.027880428602470895*_ifq1 + 0.16303628871563652*_ifq2
            + 0.18811811749986806*_ifq3 + q_th)
        _Q3__next = (-0.0035551496857956833*_ifq0 + 0.012627462689404725*_ifq1 - 0.026604180084998794*_ifq2
            + 0.08696371128436346*_ifq3 + q_th)
        _x130 = m*q_r**2
        _x131 = _x130*q_thd
        _P0__next = (0.08696371128436346*_ifp0 + 0.35267675751627187*_ifp1 + 0.31344511474186837*_ifp2
            + 0.1774825722545226*_ifp3 + _x131)
        _x132 = _x129*m*q_thd
        _pd__199 = _x132
        _pd__200 = _x130
        _P1__next = (-0.014190694931141144*_ifp0 + 0.16303628871563652*_ifp1 + 0.35395300603374397*_ifp2
            + 0.16719192197418878*_ifp3 + _x131)
        _pd__201 = _x132
        _pd__202 = _x130
        _P2__next = (0.006735500594538156*_ifp0 - 0.027880428602470895*_ifp1 + 0.16303628871563652*_ifp2
            + 0.18811811749986806*_ifp3 + _x131)
        _pd__203 = _x132
        _pd__204 = _x130
        _P3__next = (-0.0035551496857956833*_ifp0 + 0.012627462689404725*_ifp1 - 0.026604180084998794*_ifp2
            + 0.08696371128436346*_ifp3 + _x131)
        _pd__205 = _x132
        _pd__206 = _x130
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_k_c__j = _T[0, _j1]
            d_q_r__j = _T[1, _j1]
            d_q_rd__j = _T[2, _j1]
            d_q_th__j = _T[3, _j1]
            d_q_thd__j = _T[4, _j1]
            _d_isigma0__j = _T[14, _j1]
            _d_iF0__j = _T[15, _j1]
            _d_isigma1__j = _T[16, _j1]
            _d_iF1__j = _T[17, _j1]
            _d_isigma2__j = _T[18, _j1]
            _d_iF2__j = _T[19, _j1]
            _d_isigma3__j = _T[20, _j1]
            _d_iF3__j = _T[21, _j1]
            _d_ifq0__j = _T[23, _j1]
            _d_ifp0__j = _T[24, _j1]
            _d_ifq1__j = _T[26, _j1]
            _d_ifp1__j = _T[27, _j1]
            _d_ifq2__j = _T[29, _j1]
            _d_ifp2__j = _T[30, _j1]
            _d_ifq3__j = _T[32, _j1]
            _d_ifp3__j = _T[33, _j1]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__188 + _d_iF1__j*_pd__189 + _d_iF2__j*_pd__190 + _d_iF3__j*_pd__191
                + _d_isigma0__j*_pd__192 + _d_isigma1__j*_pd__193 + _d_isigma2__j*_pd__194
                + _d_isigma3__j*_pd__195 + _pd__196*d_k_c__j + _pd__197*d_q_r__j + _pd__198*d_q_rd__j)
            _d_Q0__next__j = (0.08696371128436346*_d_ifq0__j + 0.35267675751627187*_d_ifq1__j
                + 0.31344511474186837*_d_ifq2__j + 0.1774825722545226*_d_ifq3__j + d_q_th__j)
            _d_Q1__next__j = (-0.014190694931141144*_d_ifq0__j + 0.16303628871563652*_d_ifq1__j
                + 0.35395300603374397*_d_ifq2__j + 0.16719192197418878*_d_ifq3__j + d_q_th__j)
            _d_Q2__next__j = (0.006735500594538156*_d_ifq0__j - 0.027880428602470895*_d_ifq1__j
                + 0.16303628871563652*_d_ifq2__j + 0.18811811749986806*_d_ifq3__j + d_q_th__j)
            _d_Q3__next__j = (-0.0035551496857956833*_d_ifq0__j + 0.012627462689404725*_d_ifq1__j
                - 0.026604180084998794*_d_ifq2__j + 0.08696371128436346*_d_ifq3__j + d_q_th__j)
            _d_P0__next__j = (0.08696371128436346*_d_ifp0__j + 0.35267675751627187*_d_ifp1__j
                + 0.31344511474186837*_d_ifp2__j + 0.1774825722545226*_d_ifp3__j + _pd__199*d_q_r__j
                + _pd__200*d_q_thd__j)
            _d_P1__next__j = (-0.014190694931141144*_d_ifp0__j + 0.16303628871563652*_d_ifp1__j
                + 0.35395300603374397*_d_ifp2__j + 0.16719192197418878*_d_ifp3__j + _pd__201*d_q_r__j
                + _pd__202*d_q_thd__j)
            _d_P2__next__j = (0.006735500594538156*_d_ifp0__j - 0.027880428602470895*_d_ifp1__j
                + 0.16303628871563652*_d_ifp2__j + 0.18811811749986806*_d_ifp3__j + _pd__203*d_q_r__j
                + _pd__204*d_q_thd__j)
            _d_P3__next__j = (-0.0035551496857956833*_d_ifp0__j + 0.012627462689404725*_d_ifp1__j
                - 0.026604180084998794*_d_ifp2__j + 0.08696371128436346*_d_ifp3__j + _pd__205*d_q_r__j
                + _pd__206*d_q_thd__j)
            _T[5, _j1] = _d_D__next__j
            _T[6, _j1] = _d_Q0__next__j
            _T[7, _j1] = _d_Q1__next__j
            _T[8, _j1] = _d_Q2__next__j
            _T[9, _j1] = _d_Q3__next__j
            _T[10, _j1] = _d_P0__next__j
            _T[11, _j1] = _d_P1__next__j
            _T[12, _j1] = _d_P2__next__j
            _T[13, _j1] = _d_P3__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _P0__next
        _n0_6 = _P1__next
        _n0_7 = _P2__next
        _n0_8 = _P3__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_6 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_7
            - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _P0 = _n0_5
        _P1 = _n0_6
        _P2 = _n0_7
        _P3 = _n0_8
        _passes += 1.0
    # bottom state
    t_half = (0.17392742256872692*_ift0 + 0.32607257743127305*_ift1 + 0.32607257743127305*_ift2
        + 0.17392742256872692*_ift3)
    end_q_th = (0.17392742256872692*_ifq0 + 0.32607257743127305*_ifq1 + 0.32607257743127305*_ifq2
        + 0.17392742256872692*_ifq3 + q_th)
    _x133 = -_D + q_r
    end_q_r = _x133
    end_q_rd = 0.0
    _x134 = q_r**2
    _x135 = (0.17392742256872692*_ifp0 + 0.32607257743127305*_ifp1 + 0.32607257743127305*_ifp2
        + 0.17392742256872692*_ifp3 + _x134*m*q_thd)
    _x141 = (1.0/_x133)
    _x136 = _x141**2
    _x137 = (1.0/m)
    _x138 = _x136*_x137
    end_q_thd = _x135*_x138
    _x139 = 0.17392742256872692*_x138
    _pd__207 = _x139
    _x140 = 0.32607257743127305*_x138
    _pd__208 = _x140
    _pd__209 = _x140
    _pd__210 = _x139
    _pd__211 = -2.0*_x135*_x137*_x141**3
    _pd__212 = 2.0*_x136*q_r*q_thd
    _pd__213 = _x134*_x136
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[3, _j2]
        d_q_thd__j = _T[4, _j2]
        _d_D__j = _T[5, _j2]
        _d_ift0__j = _T[22, _j2]
        _d_ifq0__j = _T[23, _j2]
        _d_ifp0__j = _T[24, _j2]
        _d_ift1__j = _T[25, _j2]
        _d_ifq1__j = _T[26, _j2]
        _d_ifp1__j = _T[27, _j2]
        _d_ift2__j = _T[28, _j2]
        _d_ifq2__j = _T[29, _j2]
        _d_ifp2__j = _T[30, _j2]
        _d_ift3__j = _T[31, _j2]
        _d_ifq3__j = _T[32, _j2]
        _d_ifp3__j = _T[33, _j2]
        # bottom state
        d_t_half__j = (0.17392742256872692*_d_ift0__j + 0.32607257743127305*_d_ift1__j
            + 0.32607257743127305*_d_ift2__j + 0.17392742256872692*_d_ift3__j)
        d_end_q_th__j = (0.17392742256872692*_d_ifq0__j + 0.32607257743127305*_d_ifq1__j
            + 0.32607257743127305*_d_ifq2__j + 0.17392742256872692*_d_ifq3__j + d_q_th__j)
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__207 + _d_ifp1__j*_pd__208 + _d_ifp2__j*_pd__209
            + _d_ifp3__j*_pd__210 + _pd__211*d_end_q_r__j + _pd__212*d_q_r__j + _pd__213*d_q_thd__j)
        _T[34, _j2] = d_t_half__j
        _T[35, _j2] = d_end_q_th__j
        _T[36, _j2] = d_end_q_r__j
        _T[37, _j2] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, d_t_half__5, ) = (_T[34, 0], _T[34, 1],
        _T[34, 2], _T[34, 3], _T[34, 4], _T[34, 5], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, ) = (_T[35, 0],
        _T[35, 1], _T[35, 2], _T[35, 3], _T[35, 4], _T[35, 5], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, ) = (_T[36, 0],
        _T[36, 1], _T[36, 2], _T[36, 3], _T[36, 4], _T[36, 5], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5,
        ) = (_T[37, 0], _T[37, 1], _T[37, 2], _T[37, 3], _T[37, 4], _T[37, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, STATUS_OK)


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
    # Total ops: 1646
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((52, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 0.0
    _T[0, 4] = 1.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = 0.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 1.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 1.0 - d_guess_q_r__0
    _T[5, 1] = -d_guess_q_r__1
    _T[5, 2] = -d_guess_q_r__2
    _T[5, 3] = -d_guess_q_r__3
    _T[5, 4] = -d_guess_q_r__4
    _T[5, 5] = -d_guess_q_r__5
    _T[6, 0] = 0.966234757101576*d_guess_q_th__0
    _T[6, 1] = 0.966234757101576*d_guess_q_th__1
    _T[6, 2] = 0.966234757101576*d_guess_q_th__2 + 0.03376524289842399
    _T[6, 3] = 0.966234757101576*d_guess_q_th__3
    _T[6, 4] = 0.966234757101576*d_guess_q_th__4
    _T[6, 5] = 0.966234757101576*d_guess_q_th__5
    _T[7, 0] = 0.8306046932331322*d_guess_q_th__0
    _T[7, 1] = 0.8306046932331322*d_guess_q_th__1
    _T[7, 2] = 0.8306046932331322*d_guess_q_th__2 + 0.16939530676686773
    _T[7, 3] = 0.8306046932331322*d_guess_q_th__3
    _T[7, 4] = 0.8306046932331322*d_guess_q_th__4
    _T[7, 5] = 0.8306046932331322*d_guess_q_th__5
    _T[8, 0] = 0.6193095930415985*d_guess_q_th__0
    _T[8, 1] = 0.6193095930415985*d_guess_q_th__1
    _T[8, 2] = 0.6193095930415985*d_guess_q_th__2 + 0.38069040695840156
    _T[8, 3] = 0.6193095930415985*d_guess_q_th__3
    _T[8, 4] = 0.6193095930415985*d_guess_q_th__4
    _T[8, 5] = 0.6193095930415985*d_guess_q_th__5
    _T[9, 0] = 0.38069040695840156*d_guess_q_th__0
    _T[9, 1] = 0.38069040695840156*d_guess_q_th__1
    _T[9, 2] = 0.38069040695840156*d_guess_q_th__2 + 0.6193095930415985
    _T[9, 3] = 0.38069040695840156*d_guess_q_th__3
    _T[9, 4] = 0.38069040695840156*d_guess_q_th__4
    _T[9, 5] = 0.38069040695840156*d_guess_q_th__5
    _T[10, 0] = 0.16939530676686773*d_guess_q_th__0
    _T[10, 1] = 0.16939530676686773*d_guess_q_th__1
    _T[10, 2] = 0.16939530676686773*d_guess_q_th__2 + 0.8306046932331322
    _T[10, 3] = 0.16939530676686773*d_guess_q_th__3
    _T[10, 4] = 0.16939530676686773*d_guess_q_th__4
    _T[10, 5] = 0.16939530676686773*d_guess_q_th__5
    _T[11, 0] = 0.03376524289842399*d_guess_q_th__0
    _T[11, 1] = 0.03376524289842399*d_guess_q_th__1
    _T[11, 2] = 0.03376524289842399*d_guess_q_th__2 + 0.966234757101576
    _T[11, 3] = 0.03376524289842399*d_guess_q_th__3
    _T[11, 4] = 0.03376524289842399*d_guess_q_th__4
    _T[11, 5] = 0.03376524289842399*d_guess_q_th__5
    _T[12, 0] = (1.932469514203152*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__0*guess_q_r**2*m + 0.06753048579684798*m*q_r*q_thd)
    _T[12, 1] = (1.932469514203152*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__1*guess_q_r**2*m)
    _T[12, 2] = (1.932469514203152*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__2*guess_q_r**2*m)
    _T[12, 3] = (1.932469514203152*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__3*guess_q_r**2*m + 0.03376524289842399*m*q_r**2)
    _T[12, 4] = (1.932469514203152*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__4*guess_q_r**2*m)
    _T[12, 5] = (1.932469514203152*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.966234757101576*d_guess_q_thd__5*guess_q_r**2*m)
    _T[13, 0] = (1.6612093864662645*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__0*guess_q_r**2*m + 0.33879061353373546*m*q_r*q_thd)
    _T[13, 1] = (1.6612093864662645*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__1*guess_q_r**2*m)
    _T[13, 2] = (1.6612093864662645*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__2*guess_q_r**2*m)
    _T[13, 3] = (1.6612093864662645*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__3*guess_q_r**2*m + 0.16939530676686773*m*q_r**2)
    _T[13, 4] = (1.6612093864662645*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__4*guess_q_r**2*m)
    _T[13, 5] = (1.6612093864662645*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.8306046932331322*d_guess_q_thd__5*guess_q_r**2*m)
    _T[14, 0] = (1.238619186083197*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__0*guess_q_r**2*m + 0.7613808139168031*m*q_r*q_thd)
    _T[14, 1] = (1.238619186083197*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__1*guess_q_r**2*m)
    _T[14, 2] = (1.238619186083197*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__2*guess_q_r**2*m)
    _T[14, 3] = (1.238619186083197*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__3*guess_q_r**2*m + 0.38069040695840156*m*q_r**2)
    _T[14, 4] = (1.238619186083197*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__4*guess_q_r**2*m)
    _T[14, 5] = (1.238619186083197*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.6193095930415985*d_guess_q_thd__5*guess_q_r**2*m)
    _T[15, 0] = (0.7613808139168031*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__0*guess_q_r**2*m + 1.238619186083197*m*q_r*q_thd)
    _T[15, 1] = (0.7613808139168031*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__1*guess_q_r**2*m)
    _T[15, 2] = (0.7613808139168031*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__2*guess_q_r**2*m)
    _T[15, 3] = (0.7613808139168031*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__3*guess_q_r**2*m + 0.6193095930415985*m*q_r**2)
    _T[15, 4] = (0.7613808139168031*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__4*guess_q_r**2*m)
    _T[15, 5] = (0.7613808139168031*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.38069040695840156*d_guess_q_thd__5*guess_q_r**2*m)
    _T[16, 0] = (0.33879061353373546*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__0*guess_q_r**2*m + 1.6612093864662645*m*q_r*q_thd)
    _T[16, 1] = (0.33879061353373546*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__1*guess_q_r**2*m)
    _T[16, 2] = (0.33879061353373546*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__2*guess_q_r**2*m)
    _T[16, 3] = (0.33879061353373546*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__3*guess_q_r**2*m + 0.8306046932331322*m*q_r**2)
    _T[16, 4] = (0.33879061353373546*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__4*guess_q_r**2*m)
    _T[16, 5] = (0.33879061353373546*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.16939530676686773*d_guess_q_thd__5*guess_q_r**2*m)
    _T[17, 0] = (0.06753048579684798*d_guess_q_r__0*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__0*guess_q_r**2*m + 1.932469514203152*m*q_r*q_thd)
    _T[17, 1] = (0.06753048579684798*d_guess_q_r__1*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__1*guess_q_r**2*m)
    _T[17, 2] = (0.06753048579684798*d_guess_q_r__2*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__2*guess_q_r**2*m)
    _T[17, 3] = (0.06753048579684798*d_guess_q_r__3*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__3*guess_q_r**2*m + 0.966234757101576*m*q_r**2)
    _T[17, 4] = (0.06753048579684798*d_guess_q_r__4*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__4*guess_q_r**2*m)
    _T[17, 5] = (0.06753048579684798*d_guess_q_r__5*guess_q_r*guess_q_thd*m
        + 0.03376524289842399*d_guess_q_thd__5*guess_q_r**2*m)
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
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = -q_r
        _x1 = 0.9988599083720104*_D + _x0
        _x2 = -_x1
        _isigma0 = _x2
        _x3 = k_c*l0
        _x4 = math.cos(_Q0)
        _x5 = g_s*m
        _x6 = _x4*_x5
        _x7 = _x2*k_c
        _x8 = _P0**2
        _x9 = (1.0/m)
        _x142 = (1.0/_x2)
        _x10 = _x142**3
        _x11 = _x10*_x9
        _x12 = _x11*_x8
        _iF0 = _x12 + _x3 - _x6 - _x7
        _x13 = 2.0*_P0
        _pd__214 = _x11*_x13
        _x14 = math.sin(_Q0)
        _pd__215 = _x14*_x5
        _x15 = 3.0*_x9
        _pd__216 = -_x142**4*_x15*_x8 - k_c
        _pd__217 = _x1 + l0
        _x16 = 0.9713052300453587*_D + _x0
        _x17 = -_x16
        _isigma1 = _x17
        _x18 = math.cos(_Q1)
        _x19 = _x18*_x5
        _x20 = _x17*k_c
        _x21 = _P1**2
        _x141 = (1.0/_x17)
        _x22 = _x141**3
        _x23 = _x22*_x9
        _x24 = _x21*_x23
        _iF1 = -_x19 - _x20 + _x24 + _x3
        _x25 = 2.0*_P1
        _pd__218 = _x23*_x25
        _x26 = math.sin(_Q1)
        _pd__219 = _x26*_x5
        _pd__220 = -_x141**4*_x15*_x21 - k_c
        _pd__221 = _x16 + l0
        _x27 = 0.8550748140498466*_D + _x0
        _x28 = -_x27
        _isigma2 = _x28
        _x29 = math.cos(_Q2)
        _x30 = _x29*_x5
        _x31 = _x28*k_c
        _x32 = _P2**2
        _x143 = (1.0/_x28)
        _x33 = _x143**3
        _x34 = _x33*_x9
        _x35 = _x32*_x34
        _iF2 = _x3 - _x30 - _x31 + _x35
        _x36 = 2.0*_P2
        _pd__222 = _x34*_x36
        _x37 = math.sin(_Q2)
        _pd__223 = _x37*_x5
        _pd__224 = -_x143**4*_x15*_x32 - k_c
        _pd__225 = _x27 + l0
        _x38 = 0.6164556279666497*_D + _x0
        _x39 = -_x38
        _isigma3 = _x39
        _x40 = math.cos(_Q3)
        _x41 = _x40*_x5
        _x42 = _x39*k_c
        _x43 = _P3**2
        _x144 = (1.0/_x39)
        _x44 = _x144**3
        _x45 = _x44*_x9
        _x46 = _x43*_x45
        _iF3 = _x3 - _x41 - _x42 + _x46
        _x47 = 2.0*_P3
        _pd__226 = _x45*_x47
        _x48 = math.sin(_Q3)
        _pd__227 = _x48*_x5
        _pd__228 = -_x144**4*_x15*_x43 - k_c
        _pd__229 = _x38 + l0
        _x49 = 0.31009584357909425*_D + _x0
        _x50 = -_x49
        _isigma4 = _x50
        _x51 = math.cos(_Q4)
        _x52 = _x5*_x51
        _x53 = _x50*k_c
        _x54 = _P4**2
        _x145 = (1.0/_x50)
        _x55 = _x145**3
        _x56 = _x55*_x9
        _x57 = _x54*_x56
        _iF4 = _x3 - _x52 - _x53 + _x57
        _x58 = 2.0*_P4
        _pd__230 = _x56*_x58
        _x59 = math.sin(_Q4)
        _pd__231 = _x5*_x59
        _pd__232 = -_x145**4*_x15*_x54 - k_c
        _pd__233 = _x49 + l0
        _x60 = 0.0663903941688584*_D + _x0
        _x61 = -_x60
        _isigma5 = _x61
        _x62 = math.cos(_Q5)
        _x63 = _x5*_x62
        _x64 = _x61*k_c
        _x65 = _P5**2
        _x146 = (1.0/_x61)
        _x66 = _x146**3
        _x67 = _x66*_x9
        _x68 = _x65*_x67
        _iF5 = _x3 - _x63 - _x64 + _x68
        _x69 = 2.0*_P5
        _pd__234 = _x67*_x69
        _x70 = math.sin(_Q5)
        _pd__235 = _x5*_x70
        _pd__236 = -_x146**4*_x15*_x65 - k_c
        _pd__237 = _x60 + l0
        _x71 = (0.5871580340658094*_x12 + 0.140380692261653*_x19 + 0.140380692261653*_x20
            - 0.140380692261653*_x24 + 0.5*_x3 - 0.08683151831711133*_x30 - 0.08683151831711133*_x31
            + 0.08683151831711133*_x35 + 0.052466581536012566*_x41 + 0.052466581536012566*_x42
            - 0.052466581536012566*_x46 - 0.026354606039126004*_x52 - 0.026354606039126004*_x53
            + 0.026354606039126004*_x57 - 0.5871580340658094*_x6 + 0.007496884624381081*_x63
            + 0.007496884624381081*_x64 - 0.007496884624381081*_x68 - 0.5871580340658094*_x7)
        _iPsi0 = _x71
        _x72 = (1.0/math.sqrt(_x71))
        _x73 = math.sqrt(_D)
        _x74 = math.sqrt(m)
        _x75 = _x73*_x74
        _ift0 = _x72*_x75
        _x76 = (0.5)/_x73
        _x77 = _x74*_x76
        _pd__238 = _x72*_x77
        _x78 = _x71**(-1.5)
        _x79 = (0.5)*_x75
        _pd__239 = -_x78*_x79
        _x80 = (1.0/_x74)
        _x81 = _x73*_x80
        _x82 = _x142**2
        _x83 = _x72*_x82
        _x84 = _x81*_x83
        _ifq0 = _P0*_x84
        _x85 = _x76*_x80
        _pd__240 = _P0*_x83*_x85
        _pd__241 = _x84
        _x86 = (0.5)*_x81
        _pd__242 = -_P0*_x78*_x82*_x86
        _pd__243 = -_x10*_x13*_x72*_x81
        _x87 = g_s*m**(1.5)
        _x88 = _x73*_x87
        _x89 = _x72*_x88
        _x90 = _x14*_x89
        _ifp0 = _x2*_x90
        _x91 = _x14*_x2
        _x92 = _x76*_x87
        _pd__244 = _x72*_x91*_x92
        _pd__245 = _x2*_x4*_x89
        _x93 = (0.5)*_x88
        _pd__246 = -_x78*_x91*_x93
        _pd__247 = _x90
        _x94 = -0.5*k_c*l0
        _x95 = (0.147790320897128*_x10*_x8*_x9 - 0.41567911405660357*_x19 - 0.41567911405660357*_x20
            + 0.41567911405660357*_x21*_x22*_x9 + 0.09720828549085844*_x28*k_c
            + 0.09720828549085844*_x29*g_s*m - 0.09720828549085844*_x35 - 0.05155355009455148*_x41
            - 0.05155355009455148*_x42 + 0.05155355009455148*_x43*_x44*_x9 + 0.024719229415033087*_x50*k_c
            + 0.024719229415033087*_x51*g_s*m - 0.024719229415033087*_x57 - 0.147790320897128*_x6
            - 0.006904529857608445*_x63 - 0.006904529857608445*_x64 + 0.006904529857608445*_x65*_x66*_x9
            - 0.147790320897128*_x7 - _x94)
        _iPsi1 = _x95
        _x96 = (1.0/math.sqrt(_x95))
        _ift1 = _x75*_x96
        _pd__248 = _x77*_x96
        _x97 = _x95**(-1.5)
        _pd__249 = -_x79*_x97
        _x98 = _x141**2
        _x99 = _x96*_x98
        _x100 = _x81*_x99
        _ifq1 = _P1*_x100
        _pd__250 = _P1*_x85*_x99
        _pd__251 = _x100
        _pd__252 = -_P1*_x86*_x97*_x98
        _pd__253 = -_x22*_x25*_x81*_x96
        _x101 = _x88*_x96
        _x102 = _x101*_x26
        _ifp1 = _x102*_x17
        _x103 = _x17*_x26
        _pd__254 = _x103*_x92*_x96
        _pd__255 = _x101*_x17*_x18
        _pd__256 = -_x103*_x93*_x97
        _pd__257 = _x102
        _x104 = (0.010443786721981197*_x10*_x8*_x9 - 0.25540525119175433*_x19 - 0.25540525119175433*_x20
            + 0.25540525119175433*_x21*_x22*_x9 - 0.2685463444140672*_x30 - 0.2685463444140672*_x31
            + 0.2685463444140672*_x32*_x33*_x9 + 0.048794612428541204*_x39*k_c
            + 0.048794612428541204*_x40*g_s*m - 0.048794612428541204*_x46 - 0.01951903325298492*_x52
            - 0.01951903325298492*_x53 + 0.01951903325298492*_x54*_x55*_x9 - 0.010443786721981197*_x6
            + 0.005119803152246505*_x61*k_c + 0.005119803152246505*_x62*g_s*m - 0.005119803152246505*_x68
            - 0.010443786721981197*_x7 - _x94)
        _iPsi2 = _x104
        _x105 = (1.0/math.sqrt(_x104))
        _ift2 = _x105*_x75
        _pd__258 = _x105*_x77
        _x106 = _x104**(-1.5)
        _pd__259 = -_x106*_x79
        _x107 = _x143**2
        _x108 = _x105*_x107
        _x109 = _x108*_x81
        _ifq2 = _P2*_x109
        _pd__260 = _P2*_x108*_x85
        _pd__261 = _x109
        _pd__262 = -_P2*_x106*_x107*_x86
        _pd__263 = -_x105*_x33*_x36*_x81
        _x110 = _x105*_x88
        _x111 = _x110*_x37
        _ifp2 = _x111*_x28
        _x112 = _x28*_x37
        _pd__264 = _x105*_x112*_x92
        _pd__265 = _x110*_x28*_x29
        _pd__266 = -_x106*_x112*_x93
        _pd__267 = _x111
        _x113 = -0.5*k_c*l0
        _x114 = (0.01101839635505667*_x10*_x8*_x9 - _x113 - 0.0662099828438604*_x19 - 0.0662099828438604*_x20
            + 0.0662099828438604*_x21*_x22*_x9 - 0.2671819482314443*_x30 - 0.2671819482314443*_x31
            + 0.2671819482314443*_x32*_x33*_x9 - 0.1742495636223592*_x41 - 0.1742495636223592*_x42
            + 0.1742495636223592*_x43*_x44*_x9 + 0.02396692958086051*_x50*k_c + 0.02396692958086051*_x51*g_s*m
            - 0.02396692958086051*_x57 - 0.01101839635505667*_x6 - 0.00530703852813994*_x63
            - 0.00530703852813994*_x64 + 0.00530703852813994*_x65*_x66*_x9 - 0.01101839635505667*_x7)
        _iPsi3 = _x114
        _x115 = (1.0/math.sqrt(_x114))
        _ift3 = _x115*_x75
        _pd__268 = _x115*_x77
        _x116 = _x114**(-1.5)
        _pd__269 = -_x116*_x79
        _x117 = _x144**2
        _x118 = _x115*_x117
        _x119 = _x118*_x81
        _ifq3 = _P3*_x119
        _pd__270 = _P3*_x118*_x85
        _pd__271 = _x119
        _pd__272 = -_P3*_x116*_x117*_x86
        _pd__273 = -_x115*_x44*_x47*_x81
        _x120 = _x115*_x88
        _x121 = _x120*_x48
        _ifp3 = _x121*_x39
        _x122 = _x39*_x48
        _pd__274 = _x115*_x122*_x92
        _pd__275 = _x120*_x39*_x40
        _pd__276 = -_x116*_x122*_x93
        _pd__277 = _x121
        _x123 = (0.0025147977064533143*_x10*_x8*_x9 - 0.050345455482979015*_x19 - 0.050345455482979015*_x20
            + 0.050345455482979015*_x21*_x22*_x9 - 0.11622097556712797*_x30 - 0.11622097556712797*_x31
            + 0.11622097556712797*_x32*_x33*_x9 - 0.2353986790647292*_x41 - 0.2353986790647292*_x42
            + 0.2353986790647292*_x43*_x44*_x9 - 0.10372825048336794*_x52 - 0.10372825048336794*_x53
            + 0.10372825048336794*_x54*_x55*_x9 - 0.0025147977064533143*_x6 + 0.008208158304657426*_x61*k_c
            + 0.008208158304657426*_x62*g_s*m - 0.008208158304657426*_x68 - 0.0025147977064533143*_x7 - _x94)
        _iPsi4 = _x123
        _x124 = (1.0/math.sqrt(_x123))
        _ift4 = _x124*_x75
        _pd__278 = _x124*_x77
        _x125 = _x123**(-1.5)
        _pd__279 = -_x125*_x79
        _x126 = _x145**2
        _x127 = _x124*_x126
        _x128 = _x127*_x81
        _ifq4 = _P4*_x128
        _pd__280 = _P4*_x127*_x85
        _pd__281 = _x128
        _pd__282 = -_P4*_x125*_x126*_x86
        _pd__283 = -_x124*_x55*_x58*_x81
        _x129 = _x124*_x88
        _x130 = _x129*_x59
        _ifp4 = _x130*_x50
        _x131 = _x50*_x59
        _pd__284 = _x124*_x131*_x92
        _pd__285 = _x129*_x50*_x51
        _pd__286 = -_x125*_x131*_x93
        _pd__287 = _x130
        _x132 = (0.003959513229722528*_x10*_x8*_x9 - _x113 - 0.029703284805013122*_x19
            - 0.029703284805013122*_x20 + 0.029703284805013122*_x21*_x22*_x9 - 0.10140664131431479*_x30
            - 0.10140664131431479*_x31 + 0.10140664131431479*_x32*_x33*_x9 - 0.14531313573962065*_x41
            - 0.14531313573962065*_x42 + 0.14531313573962065*_x43*_x44*_x9 - 0.17612158869639333*_x52
            - 0.17612158869639333*_x53 + 0.17612158869639333*_x54*_x55*_x9 - 0.003959513229722528*_x6
            - 0.04349583621493557*_x63 - 0.04349583621493557*_x64 + 0.04349583621493557*_x65*_x66*_x9
            - 0.003959513229722528*_x7)
        _iPsi5 = _x132
        _x133 = (1.0/math.sqrt(_x132))
        _ift5 = _x133*_x75
        _pd__288 = _x133*_x77
        _x134 = _x132**(-1.5)
        _pd__289 = -_x134*_x79
        _x135 = _x146**2
        _x136 = _x133*_x135
        _x137 = _x136*_x81
        _ifq5 = _P5*_x137
        _pd__290 = _P5*_x136*_x85
        _pd__291 = _x137
        _pd__292 = -_P5*_x134*_x135*_x86
        _pd__293 = -_x133*_x66*_x69*_x81
        _x138 = _x133*_x88
        _x139 = _x138*_x70
        _ifp5 = _x139*_x61
        _x140 = _x61*_x70
        _pd__294 = _x133*_x140*_x92
        _pd__295 = _x138*_x61*_x62
        _pd__296 = -_x134*_x140*_x93
        _pd__297 = _x139
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
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_c__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[5, _j0]
            _d_Q0__j = _T[6, _j0]
            _d_Q1__j = _T[7, _j0]
            _d_Q2__j = _T[8, _j0]
            _d_Q3__j = _T[9, _j0]
            _d_Q4__j = _T[10, _j0]
            _d_Q5__j = _T[11, _j0]
            _d_P0__j = _T[12, _j0]
            _d_P1__j = _T[13, _j0]
            _d_P2__j = _T[14, _j0]
            _d_P3__j = _T[15, _j0]
            _d_P4__j = _T[16, _j0]
            _d_P5__j = _T[17, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _x147 = -d_q_r__j
            _d_isigma0__j = -0.9988599083720104*_d_D__j - _x147
            _d_iF0__j = _d_P0__j*_pd__214 + _d_Q0__j*_pd__215 + _d_isigma0__j*_pd__216 + _pd__217*d_k_c__j
            _d_isigma1__j = -0.9713052300453587*_d_D__j - _x147
            _d_iF1__j = _d_P1__j*_pd__218 + _d_Q1__j*_pd__219 + _d_isigma1__j*_pd__220 + _pd__221*d_k_c__j
            _d_isigma2__j = -0.8550748140498466*_d_D__j - _x147
            _d_iF2__j = _d_P2__j*_pd__222 + _d_Q2__j*_pd__223 + _d_isigma2__j*_pd__224 + _pd__225*d_k_c__j
            _d_isigma3__j = -0.6164556279666497*_d_D__j - _x147
            _d_iF3__j = _d_P3__j*_pd__226 + _d_Q3__j*_pd__227 + _d_isigma3__j*_pd__228 + _pd__229*d_k_c__j
            _d_isigma4__j = -0.31009584357909425*_d_D__j - _x147
            _d_iF4__j = _d_P4__j*_pd__230 + _d_Q4__j*_pd__231 + _d_isigma4__j*_pd__232 + _pd__233*d_k_c__j
            _d_isigma5__j = -0.0663903941688584*_d_D__j - _x147
            _d_iF5__j = _d_P5__j*_pd__234 + _d_Q5__j*_pd__235 + _d_isigma5__j*_pd__236 + _pd__237*d_k_c__j
            _d_iPsi0__j = (0.5871580340658094*_d_iF0__j - 0.140380692261653*_d_iF1__j
                + 0.08683151831711133*_d_iF2__j - 0.052466581536012566*_d_iF3__j
                + 0.026354606039126004*_d_iF4__j - 0.007496884624381081*_d_iF5__j)
            _d_ift0__j = _d_D__j*_pd__238 + _d_iPsi0__j*_pd__239
            _d_ifq0__j = _d_D__j*_pd__240 + _d_P0__j*_pd__241 + _d_iPsi0__j*_pd__242 + _d_isigma0__j*_pd__243
            _d_ifp0__j = _d_D__j*_pd__244 + _d_Q0__j*_pd__245 + _d_iPsi0__j*_pd__246 + _d_isigma0__j*_pd__247
            _d_iPsi1__j = (0.147790320897128*_d_iF0__j + 0.41567911405660357*_d_iF1__j
                - 0.09720828549085844*_d_iF2__j + 0.05155355009455148*_d_iF3__j
                - 0.024719229415033087*_d_iF4__j + 0.006904529857608445*_d_iF5__j)
            _d_ift1__j = _d_D__j*_pd__248 + _d_iPsi1__j*_pd__249
            _d_ifq1__j = _d_D__j*_pd__250 + _d_P1__j*_pd__251 + _d_iPsi1__j*_pd__252 + _d_isigma1__j*_pd__253
            _d_ifp1__j = _d_D__j*_pd__254 + _d_Q1__j*_pd__255 + _d_iPsi1__j*_pd__256 + _d_isigma1__j*_pd__257
            _d_iPsi2__j = (0.010443786721981197*_d_iF0__j + 0.25540525119175433*_d_iF1__j
                + 0.2685463444140672*_d_iF2__j - 0.048794612428541204*_d_iF3__j
                + 0.01951903325298492*_d_iF4__j - 0.005119803152246505*_d_iF5__j)
            _d_ift2__j = _d_D__j*_pd__258 + _d_iPsi2__j*_pd__259
            _d_ifq2__j = _d_D__j*_pd__260 + _d_P2__j*_pd__261 + _d_iPsi2__j*_pd__262 + _d_isigma2__j*_pd__263
            _d_ifp2__j = _d_D__j*_pd__264 + _d_Q2__j*_pd__265 + _d_iPsi2__j*_pd__266 + _d_isigma2__j*_pd__267
            _d_iPsi3__j = (0.01101839635505667*_d_iF0__j + 0.0662099828438604*_d_iF1__j
                + 0.2671819482314443*_d_iF2__j + 0.1742495636223592*_d_iF3__j - 0.02396692958086051*_d_iF4__j
                + 0.00530703852813994*_d_iF5__j)
            _d_ift3__j = _d_D__j*_pd__268 + _d_iPsi3__j*_pd__269
            _d_ifq3__j = _d_D__j*_pd__270 + _d_P3__j*_pd__271 + _d_iPsi3__j*_pd__272 + _d_isigma3__j*_pd__273
            _d_ifp3__j = _d_D__j*_pd__274 + _d_Q3__j*_pd__275 + _d_iPsi3__j*_pd__276 + _d_isigma3__j*_pd__277
            _d_iPsi4__j = (0.0025147977064533143*_d_iF0__j + 0.050345455482979015*_d_iF1__j
                + 0.11622097556712797*_d_iF2__j + 0.2353986790647292*_d_iF3__j + 0.10372825048336794*_d_iF4__j
                - 0.008208158304657426*_d_iF5__j)
            _d_ift4__j = _d_D__j*_pd__278 + _d_iPsi4__j*_pd__279
            _d_ifq4__j = _d_D__j*_pd__280 + _d_P4__j*_pd__281 + _d_iPsi4__j*_pd__282 + _d_isigma4__j*_pd__283
            _d_ifp4__j = _d_D__j*_pd__284 + _d_Q4__j*_pd__285 + _d_iPsi4__j*_pd__286 + _d_isigma4__j*_pd__287
            _d_iPsi5__j = (0.003959513229722528*_d_iF0__j + 0.029703284805013122*_d_iF1__j
                + 0.10140664131431479*_d_iF2__j + 0.14531313573962065*_d_iF3__j
                + 0.17612158869639333*_d_iF4__j + 0.04349583621493557*_d_iF5__j)
            _d_ift5__j = _d_D__j*_pd__288 + _d_iPsi5__j*_pd__289
            _d_ifq5__j = _d_D__j*_pd__290 + _d_P5__j*_pd__291 + _d_iPsi5__j*_pd__292 + _d_isigma5__j*_pd__293
            _d_ifp5__j = _d_D__j*_pd__294 + _d_Q5__j*_pd__295 + _d_iPsi5__j*_pd__296 + _d_isigma5__j*_pd__297
            _T[18, _j0] = _d_isigma0__j
            _T[19, _j0] = _d_iF0__j
            _T[20, _j0] = _d_isigma1__j
            _T[21, _j0] = _d_iF1__j
            _T[22, _j0] = _d_isigma2__j
            _T[23, _j0] = _d_iF2__j
            _T[24, _j0] = _d_isigma3__j
            _T[25, _j0] = _d_iF3__j
            _T[26, _j0] = _d_isigma4__j
            _T[27, _j0] = _d_iF4__j
            _T[28, _j0] = _d_isigma5__j
            _T[29, _j0] = _d_iF5__j
            _T[30, _j0] = _d_ift0__j
            _T[31, _j0] = _d_ifq0__j
            _T[32, _j0] = _d_ifp0__j
            _T[33, _j0] = _d_ift1__j
            _T[34, _j0] = _d_ifq1__j
            _T[35, _j0] = _d_ifp1__j
            _T[36, _j0] = _d_ift2__j
            _T[37, _j0] = _d_ifq2__j
            _T[38, _j0] = _d_ifp2__j
            _T[39, _j0] = _d_ift3__j
            _T[40, _j0] = _d_ifq3__j
            _T[41, _j0] = _d_ifp3__j
            _T[42, _j0] = _d_ift4__j
            _T[43, _j0] = _d_ifq4__j
            _T[44, _j0] = _d_ifp4__j
            _T[45, _j0] = _d_ift5__j
            _T[46, _j0] = _d_ifq5__j
            _T[47, _j0] = _d_ifp5__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x148 = m*q_rd**2
        _x149 = -q_r
        _x150 = k_c*(_x149 + l0)
        _x151 = -l0
        _x152 = -_isigma0 - _x151
        _x153 = 0.005784813099631875*k_c
        _x154 = -_isigma1 - _x151
        _x155 = 0.06111131733618721*k_c
        _x156 = -_isigma2 - _x151
        _x157 = 0.17813034617398463*k_c
        _x158 = -_isigma3 - _x151
        _x159 = 0.28978358839870644*k_c
        _x160 = -_isigma4 - _x151
        _x161 = 0.2996502557119514*k_c
        _x162 = -_isigma5 - _x151
        _x163 = 0.16553967927953847*k_c
        _x164 = (0.005784813099631875*_iF0 + 0.06111131733618721*_iF1 + 0.17813034617398463*_iF2
            + 0.28978358839870644*_iF3 + 0.2996502557119514*_iF4 + 0.16553967927953847*_iF5 + _x150
            - _x152*_x153 - _x154*_x155 - _x156*_x157 - _x158*_x159 - _x160*_x161 - _x162*_x163)
        _x165 = math.sqrt(_x148*k_c + _x164**2)
        _x166 = _x164 + _x165
        _x167 = (1.0/_x166)
        _D__next = _x148*_x167
        _x168 = _x152*k_c
        _x169 = _x154*k_c
        _x170 = _x156*k_c
        _x171 = _x158*k_c
        _x172 = _x160*k_c
        _x173 = _x162*k_c
        _x174 = (1.0/_x165)
        _x175 = _x167**2
        _x176 = _x148*_x175
        _pd__298 = (_x176*(-_x174*(3.346406259767255e-05*_iF0 + 0.0003535175490621363*_iF1
            + 0.0010304507599892272*_iF2 + 0.0016763438982271685*_iF3 + 0.001733420724550538*_iF4
            + 0.0009576161052051336*_iF5 + 0.005784813099631875*_x150 - 3.346406259767255e-05*_x168
            - 0.0003535175490621363*_x169 - 0.0010304507599892272*_x170 - 0.0016763438982271685*_x171
            - 0.001733420724550538*_x172 - 0.0009576161052051336*_x173) - 0.005784813099631875))
        _pd__299 = (_x176*(-_x174*(0.0003535175490621363*_iF0 + 0.003734593106564175*_iF1
            + 0.010885780112243256*_iF2 + 0.017709056829452403*_iF3 + 0.018312021866682706*_iF4
            + 0.010116347872182529*_iF5 + 0.06111131733618721*_x150 - 0.0003535175490621363*_x168
            - 0.003734593106564175*_x169 - 0.010885780112243256*_x170 - 0.017709056829452403*_x171
            - 0.018312021866682706*_x172 - 0.010116347872182529*_x173) - 0.06111131733618721))
        _pd__300 = (_x176*(-_x174*(0.0010304507599892272*_iF0 + 0.010885780112243256*_iF1
            + 0.0317304202280636*_iF2 + 0.05161925091700105*_iF3 + 0.05337680378109292*_iF4
            + 0.02948764037559458*_iF5 + 0.17813034617398463*_x150 - 0.0010304507599892272*_x168
            - 0.010885780112243256*_x169 - 0.0317304202280636*_x170 - 0.05161925091700105*_x171
            - 0.05337680378109292*_x172 - 0.02948764037559458*_x173) - 0.17813034617398463))
        _pd__301 = (_x176*(-_x174*(0.0016763438982271685*_iF0 + 0.017709056829452403*_iF1
            + 0.05161925091700105*_iF2 + 0.0839745281052309*_iF3 + 0.08683372636479925*_iF4
            + 0.04797068228399565*_iF5 + 0.28978358839870644*_x150 - 0.0016763438982271685*_x168
            - 0.017709056829452403*_x169 - 0.05161925091700105*_x170 - 0.0839745281052309*_x171
            - 0.08683372636479925*_x172 - 0.04797068228399565*_x173) - 0.28978358839870644))
        _pd__302 = (_x176*(-_x174*(0.001733420724550538*_iF0 + 0.018312021866682706*_iF1
            + 0.05337680378109292*_iF2 + 0.08683372636479925*_iF3 + 0.08979027574823786*_iF4
            + 0.04960400722658813*_iF5 + 0.2996502557119514*_x150 - 0.001733420724550538*_x168
            - 0.018312021866682706*_x169 - 0.05337680378109292*_x170 - 0.08683372636479925*_x171
            - 0.08979027574823786*_x172 - 0.04960400722658813*_x173) - 0.2996502557119514))
        _pd__303 = (_x176*(-_x174*(0.0009576161052051336*_iF0 + 0.010116347872182529*_iF1
            + 0.02948764037559458*_iF2 + 0.04797068228399565*_iF3 + 0.04960400722658813*_iF4
            + 0.027403385415972457*_iF5 + 0.16553967927953847*_x150 - 0.0009576161052051336*_x168
            - 0.010116347872182529*_x169 - 0.02948764037559458*_x170 - 0.04797068228399565*_x171
            - 0.04960400722658813*_x172 - 0.027403385415972457*_x173) - 0.16553967927953847))
        _x177 = _x164*_x174
        _pd__304 = _x176*(-_x153*_x177 - _x153)
        _pd__305 = _x176*(-_x155*_x177 - _x155)
        _pd__306 = _x176*(-_x157*_x177 - _x157)
        _pd__307 = _x176*(-_x159*_x177 - _x159)
        _pd__308 = _x176*(-_x161*_x177 - _x161)
        _pd__309 = _x176*(-_x163*_x177 - _x163)
        _x178 = 2.0*q_r
        _pd__310 = (_x176*(-0.005784813099631875*_isigma0 - 0.06111131733618721*_isigma1
            - 0.17813034617398463*_isigma2 - 0.28978358839870644*_isigma3 - 0.2996502557119514*_isigma4
            - 0.16553967927953847*_isigma5 - _x149 - _x174*((0.5)*_x148
            + (0.5)*_x164*(0.01156962619926375*_isigma0 + 0.12222263467237442*_isigma1
            + 0.35626069234796925*_isigma2 + 0.5795671767974129*_isigma3 + 0.5993005114239028*_isigma4
            + 0.33107935855907694*_isigma5 - _x178 - 1.164670302474663e-21*l0)) + 5.823351512373315e-22*l0))
        _pd__311 = _x176*(_x177*k_c + k_c)
        _pd__312 = 2.0*_x167*m*q_rd - _x174*_x175*k_c*m**2*q_rd**3
        _Q0__next = (0.04283112309479259*_ifq0 + 0.19514451252126672*_ifq1 + 0.22463191657986778*_ifq2
            + 0.23962582533582905*_ifq3 + 0.17752635320896998*_ifq4 + 0.08647502636084993*_ifq5 + q_th)
        _Q1__next = (-0.007011245240793691*_ifq0 + 0.09019039326203465*_ifq1 + 0.2542570695795851*_ifq2
            + 0.2235938110460991*_ifq3 + 0.18526797945210696*_ifq4 + 0.08430668513410011*_ifq5 + q_th)
        _Q2__next = (0.0034143235767412987*_ifq0 - 0.0156513758091757*_ifq1 + 0.11697848364317276*_ifq2
            + 0.25443949503200164*_ifq3 + 0.17239079462440696*_ifq4 + 0.0877378719744515*_ifq5 + q_th)
        _Q3__next = (-0.002075625784866334*_ifq0 + 0.007989991899662336*_ifq1 - 0.020482527745656096*_ifq2
            + 0.11697848364317276*_ifq3 + 0.196032162333245*_ifq4 + 0.08224792261284387*_ifq5 + q_th)
        _Q4__next = (0.0013555610554850618*_ifq0 - 0.004887192928037671*_ifq1 + 0.010363156240246424*_ifq2
            - 0.020300102293239586*_ifq3 + 0.09019039326203465*_ifq4 + 0.09267349143037887*_ifq5 + q_th)
        _Q5__next = (-0.0008127801712647621*_ifq0 + 0.002854433315099335*_ifq1 - 0.005668858049483512*_ifq2
            + 0.009325050706477751*_ifq3 - 0.014763725997197413*_ifq4 + 0.04283112309479259*_ifq5 + q_th)
        _x179 = m*q_r**2
        _x180 = _x179*q_thd
        _P0__next = (0.04283112309479259*_ifp0 + 0.19514451252126672*_ifp1 + 0.22463191657986778*_ifp2
            + 0.23962582533582905*_ifp3 + 0.17752635320896998*_ifp4 + 0.08647502636084993*_ifp5 + _x180)
        _x181 = _x178*m*q_thd
        _pd__313 = _x181
        _pd__314 = _x179
        _P1__next = (-0.007011245240793691*_ifp0 + 0.09019039326203465*_ifp1 + 0.2542570695795851*_ifp2
            + 0.2235938110460991*_ifp3 + 0.18526797945210696*_ifp4 + 0.08430668513410011*_ifp5 + _x180)
        _pd__315 = _x181
        _pd__316 = _x179
        _P2__next = (0.0034143235767412987*_ifp0 - 0.0156513758091757*_ifp1 + 0.11697848364317276*_ifp2
            + 0.25443949503200164*_ifp3 + 0.17239079462440696*_ifp4 + 0.0877378719744515*_ifp5 + _x180)
        _pd__317 = _x181
        _pd__318 = _x179
        _P3__next = (-0.002075625784866334*_ifp0 + 0.007989991899662336*_ifp1 - 0.020482527745656096*_ifp2
            + 0.11697848364317276*_ifp3 + 0.196032162333245*_ifp4 + 0.08224792261284387*_ifp5 + _x180)
        _pd__319 = _x181
        _pd__320 = _x179
        _P4__next = (0.0013555610554850618*_ifp0 - 0.004887192928037671*_ifp1 + 0.010363156240246424*_ifp2
            - 0.020300102293239586*_ifp3 + 0.09019039326203465*_ifp4 + 0.09267349143037887*_ifp5 + _x180)
        _pd__321 = _x181
        _pd__322 = _x179
        _P5__next = (-0.0008127801712647621*_ifp0 + 0.002854433315099335*_ifp1 - 0.005668858049483512*_ifp2
            + 0.009325050706477751*_ifp3 - 0.014763725997197413*_ifp4 + 0.04283112309479259*_ifp5 + _x180)
        _pd__323 = _x181
        _pd__324 = _x179
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_k_c__j = _T[0, _j1]
            d_q_r__j = _T[1, _j1]
            d_q_rd__j = _T[2, _j1]
            d_q_th__j = _T[3, _j1]
            d_q_thd__j = _T[4, _j1]
            _d_isigma0__j = _T[18, _j1]
            _d_iF0__j = _T[19, _j1]
            _d_isigma1__j = _T[20, _j1]
            _d_iF1__j = _T[21, _j1]
            _d_isigma2__j = _T[22, _j1]
            _d_iF2__j = _T[23, _j1]
            _d_isigma3__j = _T[24, _j1]
            _d_iF3__j = _T[25, _j1]
            _d_isigma4__j = _T[26, _j1]
            _d_iF4__j = _T[27, _j1]
            _d_isigma5__j = _T[28, _j1]
            _d_iF5__j = _T[29, _j1]
            _d_ifq0__j = _T[31, _j1]
            _d_ifp0__j = _T[32, _j1]
            _d_ifq1__j = _T[34, _j1]
            _d_ifp1__j = _T[35, _j1]
            _d_ifq2__j = _T[37, _j1]
            _d_ifp2__j = _T[38, _j1]
            _d_ifq3__j = _T[40, _j1]
            _d_ifp3__j = _T[41, _j1]
            _d_ifq4__j = _T[43, _j1]
            _d_ifp4__j = _T[44, _j1]
            _d_ifq5__j = _T[46, _j1]
            _d_ifp5__j = _T[47, _j1]
            # next values
            _d_D__next__j = (_d_iF0__j*_pd__298 + _d_iF1__j*_pd__299 + _d_iF2__j*_pd__300 + _d_iF3__j*_pd__301
                + _d_iF4__j*_pd__302 + _d_iF5__j*_pd__303 + _d_isigma0__j*_pd__304 + _d_isigma1__j*_pd__305
                + _d_isigma2__j*_pd__306 + _d_isigma3__j*_pd__307 + _d_isigma4__j*_pd__308
                + _d_isigma5__j*_pd__309 + _pd__310*d_k_c__j + _pd__311*d_q_r__j + _pd__312*d_q_rd__j)
            _d_Q0__next__j = (0.04283112309479259*_d_ifq0__j + 0.19514451252126672*_d_ifq1__j
                + 0.22463191657986778*_d_ifq2__j + 0.23962582533582905*_d_ifq3__j
                + 0.17752635320896998*_d_ifq4__j + 0.08647502636084993*_d_ifq5__j + d_q_th__j)
            _d_Q1__next__j = (-0.007011245240793691*_d_ifq0__j + 0.09019039326203465*_d_ifq1__j
                + 0.2542570695795851*_d_ifq2__j + 0.2235938110460991*_d_ifq3__j
                + 0.18526797945210696*_d_ifq4__j + 0.08430668513410011*_d_ifq5__j + d_q_th__j)
            _d_Q2__next__j = (0.0034143235767412987*_d_ifq0__j - 0.0156513758091757*_d_ifq1__j
                + 0.11697848364317276*_d_ifq2__j + 0.25443949503200164*_d_ifq3__j
                + 0.17239079462440696*_d_ifq4__j + 0.0877378719744515*_d_ifq5__j + d_q_th__j)
            _d_Q3__next__j = (-0.002075625784866334*_d_ifq0__j + 0.007989991899662336*_d_ifq1__j
                - 0.020482527745656096*_d_ifq2__j + 0.11697848364317276*_d_ifq3__j
                + 0.196032162333245*_d_ifq4__j + 0.08224792261284387*_d_ifq5__j + d_q_th__j)
            _d_Q4__next__j = (0.0013555610554850618*_d_ifq0__j - 0.004887192928037671*_d_ifq1__j
                + 0.010363156240246424*_d_ifq2__j - 0.020300102293239586*_d_ifq3__j
                + 0.09019039326203465*_d_ifq4__j + 0.09267349143037887*_d_ifq5__j + d_q_th__j)
            _d_Q5__next__j = (-0.0008127801712647621*_d_ifq0__j + 0.002854433315099335*_d_ifq1__j
                - 0.005668858049483512*_d_ifq2__j + 0.009325050706477751*_d_ifq3__j
                - 0.014763725997197413*_d_ifq4__j + 0.04283112309479259*_d_ifq5__j + d_q_th__j)
            _d_P0__next__j = (0.04283112309479259*_d_ifp0__j + 0.19514451252126672*_d_ifp1__j
                + 0.22463191657986778*_d_ifp2__j + 0.23962582533582905*_d_ifp3__j
                + 0.17752635320896998*_d_ifp4__j + 0.08647502636084993*_d_ifp5__j + _pd__313*d_q_r__j
                + _pd__314*d_q_thd__j)
            _d_P1__next__j = (-0.007011245240793691*_d_ifp0__j + 0.09019039326203465*_d_ifp1__j
                + 0.2542570695795851*_d_ifp2__j + 0.2235938110460991*_d_ifp3__j
                + 0.18526797945210696*_d_ifp4__j + 0.08430668513410011*_d_ifp5__j + _pd__315*d_q_r__j
                + _pd__316*d_q_thd__j)
            _d_P2__next__j = (0.0034143235767412987*_d_ifp0__j - 0.0156513758091757*_d_ifp1__j
                + 0.11697848364317276*_d_ifp2__j + 0.25443949503200164*_d_ifp3__j
                + 0.17239079462440696*_d_ifp4__j + 0.0877378719744515*_d_ifp5__j + _pd__317*d_q_r__j
                + _pd__318*d_q_thd__j)
            _d_P3__next__j = (-0.002075625784866334*_d_ifp0__j + 0.007989991899662336*_d_ifp1__j
                - 0.020482527745656096*_d_ifp2__j + 0.11697848364317276*_d_ifp3__j
                + 0.196032162333245*_d_ifp4__j + 0.08224792261284387*_d_ifp5__j + _pd__319*d_q_r__j
                + _pd__320*d_q_thd__j)
            _d_P4__next__j = (0.0013555610554850618*_d_ifp0__j - 0.004887192928037671*_d_ifp1__j
                + 0.010363156240246424*_d_ifp2__j - 0.020300102293239586*_d_ifp3__j
                + 0.09019039326203465*_d_ifp4__j + 0.09267349143037887*_d_ifp5__j + _pd__321*d_q_r__j
                + _pd__322*d_q_thd__j)
            _d_P5__next__j = (-0.0008127801712647621*_d_ifp0__j + 0.002854433315099335*_d_ifp1__j
                - 0.005668858049483512*_d_ifp2__j + 0.009325050706477751*_d_ifp3__j
                - 0.014763725997197413*_d_ifp4__j + 0.04283112309479259*_d_ifp5__j + _pd__323*d_q_r__j
                + _pd__324*d_q_thd__j)
            _T[5, _j1] = _d_D__next__j
            _T[6, _j1] = _d_Q0__next__j
            _T[7, _j1] = _d_Q1__next__j
            _T[8, _j1] = _d_Q2__next__j
            _T[9, _j1] = _d_Q3__next__j
            _T[10, _j1] = _d_Q4__next__j
            _T[11, _j1] = _d_Q5__next__j
            _T[12, _j1] = _d_P0__next__j
            _T[13, _j1] = _d_P1__next__j
            _T[14, _j1] = _d_P2__next__j
            _T[15, _j1] = _d_P3__next__j
            _T[16, _j1] = _d_P4__next__j
            _T[17, _j1] = _d_P5__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _Q4__next
        _n0_6 = _Q5__next
        _n0_7 = _P0__next
        _n0_8 = _P1__next
        _n0_9 = _P2__next
        _n0_10 = _P3__next
        _n0_11 = _P4__next
        _n0_12 = _P5__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _Q4) <= tol*(1.0)) and (abs(_n0_6 - _Q5) <= tol*(1.0))
            and (abs(_n0_7 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8
            - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_9 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_10 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_11 - _P4)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_12 - _P5)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
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
        _passes += 1.0
    # bottom state
    t_half = (0.08566224618958518*_ift0 + 0.1803807865240693*_ift1 + 0.23395696728634552*_ift2
        + 0.23395696728634552*_ift3 + 0.1803807865240693*_ift4 + 0.08566224618958518*_ift5)
    end_q_th = (0.08566224618958518*_ifq0 + 0.1803807865240693*_ifq1 + 0.23395696728634552*_ifq2
        + 0.23395696728634552*_ifq3 + 0.1803807865240693*_ifq4 + 0.08566224618958518*_ifq5 + q_th)
    _x182 = -_D + q_r
    end_q_r = _x182
    end_q_rd = 0.0
    _x183 = q_r**2
    _x184 = (0.08566224618958518*_ifp0 + 0.1803807865240693*_ifp1 + 0.23395696728634552*_ifp2
        + 0.23395696728634552*_ifp3 + 0.1803807865240693*_ifp4 + 0.08566224618958518*_ifp5 + _x183*m*q_thd)
    _x191 = (1.0/_x182)
    _x185 = _x191**2
    _x186 = (1.0/m)
    _x187 = _x185*_x186
    end_q_thd = _x184*_x187
    _x188 = 0.08566224618958518*_x187
    _pd__325 = _x188
    _x189 = 0.1803807865240693*_x187
    _pd__326 = _x189
    _x190 = 0.23395696728634552*_x187
    _pd__327 = _x190
    _pd__328 = _x190
    _pd__329 = _x189
    _pd__330 = _x188
    _pd__331 = -2.0*_x184*_x186*_x191**3
    _pd__332 = 2.0*_x185*q_r*q_thd
    _pd__333 = _x183*_x185
    passes = _passes
    # bottom leg length q_r_b > 0
    if not ((end_q_r > 0.0)):
        return _NAN30 + (STATUS_FALL,)
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[3, _j2]
        d_q_thd__j = _T[4, _j2]
        _d_D__j = _T[5, _j2]
        _d_ift0__j = _T[30, _j2]
        _d_ifq0__j = _T[31, _j2]
        _d_ifp0__j = _T[32, _j2]
        _d_ift1__j = _T[33, _j2]
        _d_ifq1__j = _T[34, _j2]
        _d_ifp1__j = _T[35, _j2]
        _d_ift2__j = _T[36, _j2]
        _d_ifq2__j = _T[37, _j2]
        _d_ifp2__j = _T[38, _j2]
        _d_ift3__j = _T[39, _j2]
        _d_ifq3__j = _T[40, _j2]
        _d_ifp3__j = _T[41, _j2]
        _d_ift4__j = _T[42, _j2]
        _d_ifq4__j = _T[43, _j2]
        _d_ifp4__j = _T[44, _j2]
        _d_ift5__j = _T[45, _j2]
        _d_ifq5__j = _T[46, _j2]
        _d_ifp5__j = _T[47, _j2]
        # bottom state
        d_t_half__j = (0.08566224618958518*_d_ift0__j + 0.1803807865240693*_d_ift1__j
            + 0.23395696728634552*_d_ift2__j + 0.23395696728634552*_d_ift3__j + 0.1803807865240693*_d_ift4__j
            + 0.08566224618958518*_d_ift5__j)
        d_end_q_th__j = (0.08566224618958518*_d_ifq0__j + 0.1803807865240693*_d_ifq1__j
            + 0.23395696728634552*_d_ifq2__j + 0.23395696728634552*_d_ifq3__j + 0.1803807865240693*_d_ifq4__j
            + 0.08566224618958518*_d_ifq5__j + d_q_th__j)
        d_end_q_r__j = -_d_D__j + d_q_r__j
        d_end_q_thd__j = (_d_ifp0__j*_pd__325 + _d_ifp1__j*_pd__326 + _d_ifp2__j*_pd__327
            + _d_ifp3__j*_pd__328 + _d_ifp4__j*_pd__329 + _d_ifp5__j*_pd__330 + _pd__331*d_end_q_r__j
            + _pd__332*d_q_r__j + _pd__333*d_q_thd__j)
        _T[48, _j2] = d_t_half__j
        _T[49, _j2] = d_end_q_th__j
        _T[50, _j2] = d_end_q_r__j
        _T[51, _j2] = d_end_q_thd__j
    (d_t_half__0, d_t_half__1, d_t_half__2, d_t_half__3, d_t_half__4, d_t_half__5, ) = (_T[48, 0], _T[48, 1],
        _T[48, 2], _T[48, 3], _T[48, 4], _T[48, 5], )
    (d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3, d_end_q_th__4, d_end_q_th__5, ) = (_T[49, 0],
        _T[49, 1], _T[49, 2], _T[49, 3], _T[49, 4], _T[49, 5], )
    (d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4, d_end_q_r__5, ) = (_T[50, 0],
        _T[50, 1], _T[50, 2], _T[50, 3], _T[50, 4], _T[50, 5], )
    (d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4, d_end_q_thd__5,
        ) = (_T[51, 0], _T[51, 1], _T[51, 2], _T[51, 3], _T[51, 4], _T[51, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
        d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
        d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3, d_end_q_r__4,
        d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3, d_end_q_thd__4,
        d_end_q_thd__5, STATUS_OK)


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
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
            d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
            d_end_q_r__4, d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3,
            d_end_q_thd__4, d_end_q_thd__5, _) = _c0
    elif nodes == 1.0:
        # branch nodes = 1
        _c1 = (schwind_compression_jvp6_4eaacb_1(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
            d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
            d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1,
            d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r,
            guess_q_th, guess_q_thd, iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol))
        if _c1[30] != STATUS_OK:
            return _NAN42 + (_c1[30],)
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
            d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
            d_end_q_r__4, d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3,
            d_end_q_thd__4, d_end_q_thd__5, _) = _c1
    elif nodes == 2.0:
        # branch nodes = 2
        _c2 = (schwind_compression_jvp6_4eaacb_2(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
            d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
            d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1,
            d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r,
            guess_q_th, guess_q_thd, iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol))
        if _c2[30] != STATUS_OK:
            return _NAN42 + (_c2[30],)
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
            d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
            d_end_q_r__4, d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3,
            d_end_q_thd__4, d_end_q_thd__5, _) = _c2
    elif nodes == 3.0:
        # branch nodes = 3
        _c3 = (schwind_compression_jvp6_4eaacb_3(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
            d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
            d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1,
            d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r,
            guess_q_th, guess_q_thd, iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol))
        if _c3[30] != STATUS_OK:
            return _NAN42 + (_c3[30],)
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
            d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
            d_end_q_r__4, d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3,
            d_end_q_thd__4, d_end_q_thd__5, _) = _c3
    elif nodes == 4.0:
        # branch nodes = 4
        _c4 = (schwind_compression_jvp6_4eaacb_4(d_guess_q_r__0, d_guess_q_r__1, d_guess_q_r__2,
            d_guess_q_r__3, d_guess_q_r__4, d_guess_q_r__5, d_guess_q_th__0, d_guess_q_th__1, d_guess_q_th__2,
            d_guess_q_th__3, d_guess_q_th__4, d_guess_q_th__5, d_guess_q_thd__0, d_guess_q_thd__1,
            d_guess_q_thd__2, d_guess_q_thd__3, d_guess_q_thd__4, d_guess_q_thd__5, g_s, guess_q_r,
            guess_q_th, guess_q_thd, iterations, k_c, l0, m, q_r, q_rd, q_th, q_thd, tol))
        if _c4[30] != STATUS_OK:
            return _NAN42 + (_c4[30],)
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__0, d_t_half__1, d_t_half__2,
            d_t_half__3, d_t_half__4, d_t_half__5, d_end_q_th__0, d_end_q_th__1, d_end_q_th__2, d_end_q_th__3,
            d_end_q_th__4, d_end_q_th__5, d_end_q_r__0, d_end_q_r__1, d_end_q_r__2, d_end_q_r__3,
            d_end_q_r__4, d_end_q_r__5, d_end_q_thd__0, d_end_q_thd__1, d_end_q_thd__2, d_end_q_thd__3,
            d_end_q_thd__4, d_end_q_thd__5, _) = _c4
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
    # Total ops: 163
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((15, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 1.0
    _T[0, 4] = 0.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = -1.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 0.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 0.0
    _T[5, 1] = 0.5
    _T[5, 2] = 0.0
    _T[5, 3] = 0.0
    _T[5, 4] = 0.5
    _T[5, 5] = 0.0
    _T[6, 0] = 1.0*m*q_r*q_thd
    _T[6, 1] = 0.0
    _T[6, 2] = 0.5*m*q_r**2
    _T[6, 3] = 0.0
    _T[6, 4] = 0.0
    _T[6, 5] = 0.5*m*q_r_lo**2
    # Picard passes on the 1 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.5*guess_q_th + 0.5*q_th
    _P0 = 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.25*_D + q_r
        _isigma0 = _x0
        _x1 = k_d*l0
        _x2 = math.cos(_Q0)
        _x3 = g_s*m
        _x4 = _x2*_x3
        _x5 = _x0*k_d
        _x6 = _P0**2
        _x7 = (1.0/m)
        _x30 = (1.0/_x0)
        _x8 = _x30**3
        _x9 = _x7*_x8
        _x10 = _x6*_x9
        _iF0 = _x1 + _x10 - _x4 - _x5
        _x11 = 2.0*_P0
        _pd__0 = _x11*_x9
        _x12 = math.sin(_Q0)
        _pd__1 = _x12*_x3
        _pd__2 = -3.0*_x30**4*_x6*_x7 - k_d
        _pd__3 = -_x0 + l0
        _x13 = 0.5*_x1 + 0.5*_x10 - 0.5*_x4 - 0.5*_x5
        _iPsi0 = _x13
        _x14 = math.sqrt(_D)
        _x15 = math.sqrt(m)
        _x16 = (1.0/math.sqrt(_x13))
        _x17 = _x15*_x16
        _ift0 = _x14*_x17
        _x18 = (0.5)/_x14
        _pd__4 = _x17*_x18
        _x19 = (0.5)*_x14/_x13**(1.5)
        _pd__5 = -_x15*_x19
        _x20 = _x14*_x16
        _x21 = (1.0/_x15)
        _x22 = _x21*_x30**2
        _x23 = _x20*_x22
        _ifq0 = _P0*_x23
        _x24 = _P0*_x22
        _x25 = _x16*_x18
        _pd__6 = _x24*_x25
        _pd__7 = _x23
        _pd__8 = -_x19*_x24
        _pd__9 = -_x11*_x20*_x21*_x8
        _x26 = m**(1.5)
        _x27 = _x20*_x26*g_s
        _x28 = _x12*_x27
        _ifp0 = _x0*_x28
        _x29 = _x0*_x12*_x26*g_s
        _pd__10 = _x25*_x29
        _pd__11 = _x0*_x2*_x27
        _pd__12 = -_x19*_x29
        _pd__13 = _x28
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_d__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[4, _j0]
            _d_Q0__j = _T[5, _j0]
            _d_P0__j = _T[6, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _d_isigma0__j = 0.25*_d_D__j + d_q_r__j
            _d_iF0__j = _d_P0__j*_pd__0 + _d_Q0__j*_pd__1 + _d_isigma0__j*_pd__2 + _pd__3*d_k_d__j
            _x31 = 0.5*_d_iF0__j
            _d_ift0__j = _d_D__j*_pd__4 + _pd__5*_x31
            _d_ifq0__j = _d_D__j*_pd__6 + _d_P0__j*_pd__7 + _d_isigma0__j*_pd__9 + _pd__8*_x31
            _d_ifp0__j = _d_D__j*_pd__10 + _d_Q0__j*_pd__11 + _d_isigma0__j*_pd__13 + _pd__12*_x31
            _T[7, _j0] = _d_iF0__j
            _T[8, _j0] = _d_ift0__j
            _T[9, _j0] = _d_ifq0__j
            _T[10, _j0] = _d_ifp0__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = 0.5*_ifq0 + q_th
        _x32 = m*q_r**2
        _P0__next = 0.5*_ifp0 + _x32*q_thd
        _pd__14 = 2.0*m*q_r*q_thd
        _pd__15 = _x32
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_q_r__j = _T[1, _j1]
            d_q_th__j = _T[2, _j1]
            d_q_thd__j = _T[3, _j1]
            _d_D__j = _T[4, _j1]
            _d_ifq0__j = _T[9, _j1]
            _d_ifp0__j = _T[10, _j1]
            # next values
            _d_Q0__next__j = 0.5*_d_ifq0__j + d_q_th__j
            _d_P0__next__j = 0.5*_d_ifp0__j + _pd__14*d_q_r__j + _pd__15*d_q_thd__j
            _T[4, _j1] = _d_D__j
            _T[5, _j1] = _d_Q0__next__j
            _T[6, _j1] = _d_P0__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _P0__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _P0 = _n0_2
        _passes += 1.0
    _work = 0.5*_iF0
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 1.0*_ift0
    end_q_th = 1.0*_ifq0 + q_th
    end_q_r = q_r_lo
    _x33 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x33
    _pd__16 = _x33/_D
    _pd__17 = _x33/_work
    _x34 = q_r**2
    _x35 = q_r_lo**-2
    _x36 = _x35/m
    end_q_thd = _x36*(1.0*_ifp0 + _x34*m*q_thd)
    _pd__18 = 1.0*_x36
    _pd__19 = 2.0*_x35*q_r*q_thd
    _pd__20 = _x34*_x35
    passes = _passes
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[2, _j2]
        d_q_thd__j = _T[3, _j2]
        _d_D__j = _T[4, _j2]
        _d_iF0__j = _T[7, _j2]
        _d_ift0__j = _T[8, _j2]
        _d_ifq0__j = _T[9, _j2]
        _d_ifp0__j = _T[10, _j2]
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        d_end_q_th__j = 1.0*_d_ifq0__j + d_q_th__j
        d_end_q_rd__j = _d_D__j*_pd__16 + 0.5*_d_iF0__j*_pd__17
        d_end_q_thd__j = _d_ifp0__j*_pd__18 + _pd__19*d_q_r__j + _pd__20*d_q_thd__j
        _T[11, _j2] = 1.0*_d_ift0__j
        _T[12, _j2] = d_end_q_th__j
        _T[13, _j2] = d_end_q_rd__j
        _T[14, _j2] = d_end_q_thd__j
    (d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th,
        d_t_half__guess_q_thd, ) = (_T[11, 0], _T[11, 1], _T[11, 2], _T[11, 3], _T[11, 4], _T[11, 5], )
    (d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
        d_end_q_th__guess_q_thd, ) = (_T[12, 0], _T[12, 1], _T[12, 2], _T[12, 3], _T[12, 4], _T[12, 5], )
    (d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, ) = (_T[13, 0], _T[13, 1], _T[13, 2], _T[13, 3], _T[13, 4], _T[13, 5], )
    (d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, ) = (_T[14, 0], _T[14, 1], _T[14, 2], _T[14, 3], _T[14, 4], _T[14, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
        d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
        d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, STATUS_OK)


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
    # Total ops: 330
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((21, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 1.0
    _T[0, 4] = 0.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = -1.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 0.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 0.0
    _T[5, 1] = 0.7886751345948129
    _T[5, 2] = 0.0
    _T[5, 3] = 0.0
    _T[5, 4] = 0.2113248654051871
    _T[5, 5] = 0.0
    _T[6, 0] = 0.0
    _T[6, 1] = 0.2113248654051871
    _T[6, 2] = 0.0
    _T[6, 3] = 0.0
    _T[6, 4] = 0.7886751345948129
    _T[6, 5] = 0.0
    _T[7, 0] = 1.5773502691896257*m*q_r*q_thd
    _T[7, 1] = 0.0
    _T[7, 2] = 0.7886751345948129*m*q_r**2
    _T[7, 3] = 0.0
    _T[7, 4] = 0.0
    _T[7, 5] = 0.2113248654051871*m*q_r_lo**2
    _T[8, 0] = 0.4226497308103742*m*q_r*q_thd
    _T[8, 1] = 0.0
    _T[8, 2] = 0.2113248654051871*m*q_r**2
    _T[8, 3] = 0.0
    _T[8, 4] = 0.0
    _T[8, 5] = 0.7886751345948129*m*q_r_lo**2
    # Picard passes on the 2 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.2113248654051871*guess_q_th + 0.7886751345948129*q_th
    _Q1 = 0.7886751345948129*guess_q_th + 0.2113248654051871*q_th
    _P0 = 0.2113248654051871*guess_q_thd*m*q_r_lo**2 + 0.7886751345948129*m*q_r**2*q_thd
    _P1 = 0.7886751345948129*guess_q_thd*m*q_r_lo**2 + 0.2113248654051871*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.04465819873852045*_D + q_r
        _isigma0 = _x0
        _x1 = k_d*l0
        _x2 = math.cos(_Q0)
        _x3 = g_s*m
        _x4 = _x2*_x3
        _x5 = _x0*k_d
        _x6 = _P0**2
        _x7 = (1.0/m)
        _x57 = (1.0/_x0)
        _x8 = _x57**3
        _x9 = _x7*_x8
        _x10 = _x6*_x9
        _iF0 = _x1 + _x10 - _x4 - _x5
        _x11 = 2.0*_P0
        _pd__21 = _x11*_x9
        _x12 = math.sin(_Q0)
        _pd__22 = _x12*_x3
        _x13 = 3.0*_x7
        _pd__23 = -_x13*_x57**4*_x6 - k_d
        _x14 = -l0
        _pd__24 = -_x0 - _x14
        _x15 = 0.6220084679281462*_D + q_r
        _isigma1 = _x15
        _x16 = math.cos(_Q1)
        _x17 = _x16*_x3
        _x18 = _x15*k_d
        _x19 = _P1**2
        _x58 = (1.0/_x15)
        _x20 = _x58**3
        _x21 = _x20*_x7
        _x22 = _x19*_x21
        _iF1 = _x1 - _x17 - _x18 + _x22
        _x23 = 2.0*_P1
        _pd__25 = _x21*_x23
        _x24 = math.sin(_Q1)
        _pd__26 = _x24*_x3
        _pd__27 = -_x13*_x19*_x58**4 - k_d
        _pd__28 = -_x14 - _x15
        _x25 = (0.5*_x1 + 0.5610042339640731*_x10 + 0.06100423396407311*_x17 + 0.06100423396407311*_x18
            - 0.06100423396407311*_x22 - 0.5610042339640731*_x4 - 0.5610042339640731*_x5)
        _iPsi0 = _x25
        _x26 = (1.0/math.sqrt(_x25))
        _x27 = math.sqrt(_D)
        _x28 = math.sqrt(m)
        _x29 = _x27*_x28
        _ift0 = _x26*_x29
        _x30 = (0.5)/_x27
        _x31 = _x28*_x30
        _pd__29 = _x26*_x31
        _x32 = _x25**(-1.5)
        _x33 = (0.5)*_x29
        _pd__30 = -_x32*_x33
        _x34 = (1.0/_x28)
        _x35 = _x27*_x34
        _x36 = _x57**2
        _x37 = _x26*_x36
        _x38 = _x35*_x37
        _ifq0 = _P0*_x38
        _x39 = _x30*_x34
        _pd__31 = _P0*_x37*_x39
        _pd__32 = _x38
        _x40 = (0.5)*_x35
        _pd__33 = -_P0*_x32*_x36*_x40
        _pd__34 = -_x11*_x26*_x35*_x8
        _x41 = g_s*m**(1.5)
        _x42 = _x27*_x41
        _x43 = _x26*_x42
        _x44 = _x12*_x43
        _ifp0 = _x0*_x44
        _x45 = _x0*_x12
        _x46 = _x30*_x41
        _pd__35 = _x26*_x45*_x46
        _pd__36 = _x0*_x2*_x43
        _x47 = (0.5)*_x42
        _pd__37 = -_x32*_x45*_x47
        _pd__38 = _x44
        _x48 = (-0.27232909936926025*_x17 - 0.27232909936926025*_x18 + 0.27232909936926025*_x19*_x20*_x7
            - 0.22767090063073978*_x4 - 0.22767090063073978*_x5 + 0.22767090063073978*_x6*_x7*_x8
            + 0.5*k_d*l0)
        _iPsi1 = _x48
        _x49 = (1.0/math.sqrt(_x48))
        _ift1 = _x29*_x49
        _pd__39 = _x31*_x49
        _x50 = _x48**(-1.5)
        _pd__40 = -_x33*_x50
        _x51 = _x58**2
        _x52 = _x49*_x51
        _x53 = _x35*_x52
        _ifq1 = _P1*_x53
        _pd__41 = _P1*_x39*_x52
        _pd__42 = _x53
        _pd__43 = -_P1*_x40*_x50*_x51
        _pd__44 = -_x20*_x23*_x35*_x49
        _x54 = _x42*_x49
        _x55 = _x24*_x54
        _ifp1 = _x15*_x55
        _x56 = _x15*_x24
        _pd__45 = _x46*_x49*_x56
        _pd__46 = _x15*_x16*_x54
        _pd__47 = -_x47*_x50*_x56
        _pd__48 = _x55
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_d__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[4, _j0]
            _d_Q0__j = _T[5, _j0]
            _d_Q1__j = _T[6, _j0]
            _d_P0__j = _T[7, _j0]
            _d_P1__j = _T[8, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _d_isigma0__j = 0.04465819873852045*_d_D__j + d_q_r__j
            _d_iF0__j = _d_P0__j*_pd__21 + _d_Q0__j*_pd__22 + _d_isigma0__j*_pd__23 + _pd__24*d_k_d__j
            _d_isigma1__j = 0.6220084679281462*_d_D__j + d_q_r__j
            _d_iF1__j = _d_P1__j*_pd__25 + _d_Q1__j*_pd__26 + _d_isigma1__j*_pd__27 + _pd__28*d_k_d__j
            _d_iPsi0__j = 0.5610042339640731*_d_iF0__j - 0.06100423396407311*_d_iF1__j
            _d_ift0__j = _d_D__j*_pd__29 + _d_iPsi0__j*_pd__30
            _d_ifq0__j = _d_D__j*_pd__31 + _d_P0__j*_pd__32 + _d_iPsi0__j*_pd__33 + _d_isigma0__j*_pd__34
            _d_ifp0__j = _d_D__j*_pd__35 + _d_Q0__j*_pd__36 + _d_iPsi0__j*_pd__37 + _d_isigma0__j*_pd__38
            _d_iPsi1__j = 0.22767090063073978*_d_iF0__j + 0.27232909936926025*_d_iF1__j
            _d_ift1__j = _d_D__j*_pd__39 + _d_iPsi1__j*_pd__40
            _d_ifq1__j = _d_D__j*_pd__41 + _d_P1__j*_pd__42 + _d_iPsi1__j*_pd__43 + _d_isigma1__j*_pd__44
            _d_ifp1__j = _d_D__j*_pd__45 + _d_Q1__j*_pd__46 + _d_iPsi1__j*_pd__47 + _d_isigma1__j*_pd__48
            _T[9, _j0] = _d_iF0__j
            _T[10, _j0] = _d_iF1__j
            _T[11, _j0] = _d_ift0__j
            _T[12, _j0] = _d_ifq0__j
            _T[13, _j0] = _d_ifp0__j
            _T[14, _j0] = _d_ift1__j
            _T[15, _j0] = _d_ifq1__j
            _T[16, _j0] = _d_ifp1__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = 0.25*_ifq0 - 0.03867513459481288*_ifq1 + q_th
        _Q1__next = 0.5386751345948129*_ifq0 + 0.25*_ifq1 + q_th
        _x59 = m*q_r**2
        _x60 = _x59*q_thd
        _P0__next = 0.25*_ifp0 - 0.03867513459481288*_ifp1 + _x60
        _x61 = 2.0*m*q_r*q_thd
        _pd__49 = _x61
        _pd__50 = _x59
        _P1__next = 0.5386751345948129*_ifp0 + 0.25*_ifp1 + _x60
        _pd__51 = _x61
        _pd__52 = _x59
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_q_r__j = _T[1, _j1]
            d_q_th__j = _T[2, _j1]
            d_q_thd__j = _T[3, _j1]
            _d_D__j = _T[4, _j1]
            _d_ifq0__j = _T[12, _j1]
            _d_ifp0__j = _T[13, _j1]
            _d_ifq1__j = _T[15, _j1]
            _d_ifp1__j = _T[16, _j1]
            # next values
            _d_Q0__next__j = 0.25*_d_ifq0__j - 0.03867513459481288*_d_ifq1__j + d_q_th__j
            _d_Q1__next__j = 0.5386751345948129*_d_ifq0__j + 0.25*_d_ifq1__j + d_q_th__j
            _d_P0__next__j = (0.25*_d_ifp0__j - 0.03867513459481288*_d_ifp1__j + _pd__49*d_q_r__j
                + _pd__50*d_q_thd__j)
            _d_P1__next__j = (0.5386751345948129*_d_ifp0__j + 0.25*_d_ifp1__j + _pd__51*d_q_r__j
                + _pd__52*d_q_thd__j)
            _T[4, _j1] = _d_D__j
            _T[5, _j1] = _d_Q0__next__j
            _T[6, _j1] = _d_Q1__next__j
            _T[7, _j1] = _d_P0__next__j
            _T[8, _j1] = _d_P1__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _P0__next
        _n0_4 = _P1__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))) and (abs(_n0_4 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m
            + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _P0 = _n0_3
        _P1 = _n0_4
        _passes += 1.0
    _work = 0.10566243270259355*_iF0 + 0.39433756729740643*_iF1
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 0.5*_ift0 + 0.5*_ift1
    end_q_th = 0.5*_ifq0 + 0.5*_ifq1 + q_th
    end_q_r = q_r_lo
    _x62 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x62
    _pd__53 = _x62/_D
    _pd__54 = _x62/_work
    _x63 = q_r**2
    _x64 = q_r_lo**-2
    _x65 = _x64/m
    end_q_thd = _x65*(0.5*_ifp0 + 0.5*_ifp1 + _x63*m*q_thd)
    _x66 = 0.5*_x65
    _pd__55 = _x66
    _pd__56 = _x66
    _pd__57 = 2.0*_x64*q_r*q_thd
    _pd__58 = _x63*_x64
    passes = _passes
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[2, _j2]
        d_q_thd__j = _T[3, _j2]
        _d_D__j = _T[4, _j2]
        _d_iF0__j = _T[9, _j2]
        _d_iF1__j = _T[10, _j2]
        _d_ift0__j = _T[11, _j2]
        _d_ifq0__j = _T[12, _j2]
        _d_ifp0__j = _T[13, _j2]
        _d_ift1__j = _T[14, _j2]
        _d_ifq1__j = _T[15, _j2]
        _d_ifp1__j = _T[16, _j2]
        _d_work__j = 0.10566243270259355*_d_iF0__j + 0.39433756729740643*_d_iF1__j
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        d_t_half__j = 0.5*_d_ift0__j + 0.5*_d_ift1__j
        d_end_q_th__j = 0.5*_d_ifq0__j + 0.5*_d_ifq1__j + d_q_th__j
        d_end_q_rd__j = _d_D__j*_pd__53 + _d_work__j*_pd__54
        d_end_q_thd__j = _d_ifp0__j*_pd__55 + _d_ifp1__j*_pd__56 + _pd__57*d_q_r__j + _pd__58*d_q_thd__j
        _T[17, _j2] = d_t_half__j
        _T[18, _j2] = d_end_q_th__j
        _T[19, _j2] = d_end_q_rd__j
        _T[20, _j2] = d_end_q_thd__j
    (d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th,
        d_t_half__guess_q_thd, ) = (_T[17, 0], _T[17, 1], _T[17, 2], _T[17, 3], _T[17, 4], _T[17, 5], )
    (d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
        d_end_q_th__guess_q_thd, ) = (_T[18, 0], _T[18, 1], _T[18, 2], _T[18, 3], _T[18, 4], _T[18, 5], )
    (d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, ) = (_T[19, 0], _T[19, 1], _T[19, 2], _T[19, 3], _T[19, 4], _T[19, 5], )
    (d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, ) = (_T[20, 0], _T[20, 1], _T[20, 2], _T[20, 3], _T[20, 4], _T[20, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
        d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
        d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, STATUS_OK)


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
    # Total ops: 517
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((27, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 1.0
    _T[0, 4] = 0.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = -1.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 0.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 0.0
    _T[5, 1] = 0.8872983346207417
    _T[5, 2] = 0.0
    _T[5, 3] = 0.0
    _T[5, 4] = 0.11270166537925831
    _T[5, 5] = 0.0
    _T[6, 0] = 0.0
    _T[6, 1] = 0.5
    _T[6, 2] = 0.0
    _T[6, 3] = 0.0
    _T[6, 4] = 0.5
    _T[6, 5] = 0.0
    _T[7, 0] = 0.0
    _T[7, 1] = 0.11270166537925831
    _T[7, 2] = 0.0
    _T[7, 3] = 0.0
    _T[7, 4] = 0.8872983346207417
    _T[7, 5] = 0.0
    _T[8, 0] = 1.7745966692414834*m*q_r*q_thd
    _T[8, 1] = 0.0
    _T[8, 2] = 0.8872983346207417*m*q_r**2
    _T[8, 3] = 0.0
    _T[8, 4] = 0.0
    _T[8, 5] = 0.11270166537925831*m*q_r_lo**2
    _T[9, 0] = 1.0*m*q_r*q_thd
    _T[9, 1] = 0.0
    _T[9, 2] = 0.5*m*q_r**2
    _T[9, 3] = 0.0
    _T[9, 4] = 0.0
    _T[9, 5] = 0.5*m*q_r_lo**2
    _T[10, 0] = 0.22540333075851662*m*q_r*q_thd
    _T[10, 1] = 0.0
    _T[10, 2] = 0.11270166537925831*m*q_r**2
    _T[10, 3] = 0.0
    _T[10, 4] = 0.0
    _T[10, 5] = 0.8872983346207417*m*q_r_lo**2
    # Picard passes on the 3 node values (collocation in u)
    _D = -q_r + q_r_lo
    _Q0 = 0.11270166537925831*guess_q_th + 0.8872983346207417*q_th
    _Q1 = 0.5*guess_q_th + 0.5*q_th
    _Q2 = 0.8872983346207417*guess_q_th + 0.11270166537925831*q_th
    _P0 = 0.11270166537925831*guess_q_thd*m*q_r_lo**2 + 0.8872983346207417*m*q_r**2*q_thd
    _P1 = 0.5*guess_q_thd*m*q_r_lo**2 + 0.5*m*q_r**2*q_thd
    _P2 = 0.8872983346207417*guess_q_thd*m*q_r_lo**2 + 0.11270166537925831*m*q_r**2*q_thd
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.012701665379258311*_D + q_r
        _isigma0 = _x0
        _x1 = k_d*l0
        _x2 = math.cos(_Q0)
        _x3 = g_s*m
        _x4 = _x2*_x3
        _x5 = _x0*k_d
        _x6 = _P0**2
        _x7 = (1.0/m)
        _x76 = (1.0/_x0)
        _x8 = _x76**3
        _x9 = _x7*_x8
        _x10 = _x6*_x9
        _iF0 = _x1 + _x10 - _x4 - _x5
        _x11 = 2.0*_P0
        _pd__59 = _x11*_x9
        _x12 = math.sin(_Q0)
        _pd__60 = _x12*_x3
        _x13 = 3.0*_x7
        _pd__61 = -_x13*_x6*_x76**4 - k_d
        _x14 = -l0
        _pd__62 = -_x0 - _x14
        _x15 = 0.25*_D + q_r
        _isigma1 = _x15
        _x16 = math.cos(_Q1)
        _x17 = _x16*_x3
        _x18 = _x15*k_d
        _x19 = _P1**2
        _x77 = (1.0/_x15)
        _x20 = _x77**3
        _x21 = _x20*_x7
        _x22 = _x19*_x21
        _iF1 = _x1 - _x17 - _x18 + _x22
        _x23 = 2.0*_P1
        _pd__63 = _x21*_x23
        _x24 = math.sin(_Q1)
        _pd__64 = _x24*_x3
        _pd__65 = -_x13*_x19*_x77**4 - k_d
        _pd__66 = -_x14 - _x15
        _x25 = 0.7872983346207417*_D + q_r
        _isigma2 = _x25
        _x26 = math.cos(_Q2)
        _x27 = _x26*_x3
        _x28 = _x25*k_d
        _x29 = _P2**2
        _x78 = (1.0/_x25)
        _x30 = _x78**3
        _x31 = _x30*_x7
        _x32 = _x29*_x31
        _iF2 = _x1 - _x27 - _x28 + _x32
        _x33 = 2.0*_P2
        _pd__67 = _x31*_x33
        _x34 = math.sin(_Q2)
        _pd__68 = _x3*_x34
        _pd__69 = -_x13*_x29*_x78**4 - k_d
        _pd__70 = -_x14 - _x25
        _x35 = (0.5*_x1 + 0.5762768525670787*_x10 + 0.1040546303448565*_x17 + 0.1040546303448565*_x18
            - 0.1040546303448565*_x22 - 0.027777777777777776*_x27 - 0.027777777777777776*_x28
            + 0.027777777777777776*_x32 - 0.5762768525670787*_x4 - 0.5762768525670787*_x5)
        _iPsi0 = _x35
        _x36 = (1.0/math.sqrt(_x35))
        _x37 = math.sqrt(_D)
        _x38 = math.sqrt(m)
        _x39 = _x37*_x38
        _ift0 = _x36*_x39
        _x40 = (0.5)/_x37
        _x41 = _x38*_x40
        _pd__71 = _x36*_x41
        _x42 = _x35**(-1.5)
        _x43 = (0.5)*_x39
        _pd__72 = -_x42*_x43
        _x44 = (1.0/_x38)
        _x45 = _x37*_x44
        _x46 = _x76**2
        _x47 = _x36*_x46
        _x48 = _x45*_x47
        _ifq0 = _P0*_x48
        _x49 = _x40*_x44
        _pd__73 = _P0*_x47*_x49
        _pd__74 = _x48
        _x50 = (0.5)*_x45
        _pd__75 = -_P0*_x42*_x46*_x50
        _pd__76 = -_x11*_x36*_x45*_x8
        _x51 = g_s*m**(1.5)
        _x52 = _x37*_x51
        _x53 = _x36*_x52
        _x54 = _x12*_x53
        _ifp0 = _x0*_x54
        _x55 = _x0*_x12
        _x56 = _x40*_x51
        _pd__77 = _x36*_x55*_x56
        _pd__78 = _x0*_x2*_x53
        _x57 = (0.5)*_x52
        _pd__79 = -_x42*_x55*_x57
        _pd__80 = _x54
        _x58 = (0.5*_x1 + 0.17702731517242826*_x10 - 0.3611111111111111*_x17 - 0.3611111111111111*_x18
            + 0.3611111111111111*_x22 + 0.038138426283539355*_x27 + 0.038138426283539355*_x28
            - 0.038138426283539355*_x32 - 0.17702731517242826*_x4 - 0.17702731517242826*_x5)
        _iPsi1 = _x58
        _x59 = (1.0/math.sqrt(_x58))
        _ift1 = _x39*_x59
        _pd__81 = _x41*_x59
        _x60 = _x58**(-1.5)
        _pd__82 = -_x43*_x60
        _x61 = _x77**2
        _x62 = _x59*_x61
        _x63 = _x45*_x62
        _ifq1 = _P1*_x63
        _pd__83 = _P1*_x49*_x62
        _pd__84 = _x63
        _pd__85 = -_P1*_x50*_x60*_x61
        _pd__86 = -_x20*_x23*_x45*_x59
        _x64 = _x52*_x59
        _x65 = _x24*_x64
        _ifp1 = _x15*_x65
        _x66 = _x15*_x24
        _pd__87 = _x56*_x59*_x66
        _pd__88 = _x15*_x16*_x64
        _pd__89 = -_x57*_x60*_x66
        _pd__90 = _x65
        _x67 = (-0.3262768525670787*_x17 - 0.3262768525670787*_x18 + 0.3262768525670787*_x19*_x20*_x7
            - 0.14594536965514351*_x27 - 0.14594536965514351*_x28 + 0.14594536965514351*_x29*_x30*_x7
            - 0.027777777777777776*_x4 - 0.027777777777777776*_x5 + 0.027777777777777776*_x6*_x7*_x8
            + 0.5*k_d*l0)
        _iPsi2 = _x67
        _x68 = (1.0/math.sqrt(_x67))
        _ift2 = _x39*_x68
        _pd__91 = _x41*_x68
        _x69 = _x67**(-1.5)
        _pd__92 = -_x43*_x69
        _x70 = _x78**2
        _x71 = _x68*_x70
        _x72 = _x45*_x71
        _ifq2 = _P2*_x72
        _pd__93 = _P2*_x49*_x71
        _pd__94 = _x72
        _pd__95 = -_P2*_x50*_x69*_x70
        _pd__96 = -_x30*_x33*_x45*_x68
        _x73 = _x52*_x68
        _x74 = _x34*_x73
        _ifp2 = _x25*_x74
        _x75 = _x25*_x34
        _pd__97 = _x56*_x68*_x75
        _pd__98 = _x25*_x26*_x73
        _pd__99 = -_x57*_x69*_x75
        _pd__100 = _x74
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi0 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi1 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # p_r^2 = 2 m int F_r > 0 at every node
        if not ((_iPsi2 > 0.0)):
            return _NAN30 + (STATUS_IMAGINARY_MOMENTUM,)
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_d__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[4, _j0]
            _d_Q0__j = _T[5, _j0]
            _d_Q1__j = _T[6, _j0]
            _d_Q2__j = _T[7, _j0]
            _d_P0__j = _T[8, _j0]
            _d_P1__j = _T[9, _j0]
            _d_P2__j = _T[10, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _d_isigma0__j = 0.012701665379258311*_d_D__j + d_q_r__j
            _d_iF0__j = _d_P0__j*_pd__59 + _d_Q0__j*_pd__60 + _d_isigma0__j*_pd__61 + _pd__62*d_k_d__j
            _d_isigma1__j = 0.25*_d_D__j + d_q_r__j
            _d_iF1__j = _d_P1__j*_pd__63 + _d_Q1__j*_pd__64 + _d_isigma1__j*_pd__65 + _pd__66*d_k_d__j
            _d_isigma2__j = 0.7872983346207417*_d_D__j + d_q_r__j
            _d_iF2__j = _d_P2__j*_pd__67 + _d_Q2__j*_pd__68 + _d_isigma2__j*_pd__69 + _pd__70*d_k_d__j
            _d_iPsi0__j = (0.5762768525670787*_d_iF0__j - 0.1040546303448565*_d_iF1__j
                + 0.027777777777777776*_d_iF2__j)
            _d_ift0__j = _d_D__j*_pd__71 + _d_iPsi0__j*_pd__72
            _d_ifq0__j = _d_D__j*_pd__73 + _d_P0__j*_pd__74 + _d_iPsi0__j*_pd__75 + _d_isigma0__j*_pd__76
            _d_ifp0__j = _d_D__j*_pd__77 + _d_Q0__j*_pd__78 + _d_iPsi0__j*_pd__79 + _d_isigma0__j*_pd__80
            _d_iPsi1__j = (0.17702731517242826*_d_iF0__j + 0.3611111111111111*_d_iF1__j
                - 0.038138426283539355*_d_iF2__j)
            _d_ift1__j = _d_D__j*_pd__81 + _d_iPsi1__j*_pd__82
            _d_ifq1__j = _d_D__j*_pd__83 + _d_P1__j*_pd__84 + _d_iPsi1__j*_pd__85 + _d_isigma1__j*_pd__86
            _d_ifp1__j = _d_D__j*_pd__87 + _d_Q1__j*_pd__88 + _d_iPsi1__j*_pd__89 + _d_isigma1__j*_pd__90
            _d_iPsi2__j = (0.027777777777777776*_d_iF0__j + 0.3262768525670787*_d_iF1__j
                + 0.14594536965514351*_d_iF2__j)
            _d_ift2__j = _d_D__j*_pd__91 + _d_iPsi2__j*_pd__92
            _d_ifq2__j = _d_D__j*_pd__93 + _d_P2__j*_pd__94 + _d_iPsi2__j*_pd__95 + _d_isigma2__j*_pd__96
            _d_ifp2__j = _d_D__j*_pd__97 + _d_Q2__j*_pd__98 + _d_iPsi2__j*_pd__99 + _d_isigma2__j*_pd__100
            _T[11, _j0] = _d_iF0__j
            _T[12, _j0] = _d_iF1__j
            _T[13, _j0] = _d_iF2__j
            _T[14, _j0] = _d_ift0__j
            _T[15, _j0] = _d_ifq0__j
            _T[16, _j0] = _d_ifp0__j
            _T[17, _j0] = _d_ift1__j
            _T[18, _j0] = _d_ifq1__j
            _T[19, _j0] = _d_ifp1__j
            _T[20, _j0] = _d_ift2__j
            _T[21, _j0] = _d_ifq2__j
            _T[22, _j0] = _d_ifp2__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = 0.1388888888888889*_ifq0 - 0.0359766675249389*_ifq1 + 0.009789444015308325*_ifq2 + q_th
        _Q1__next = 0.30026319498086457*_ifq0 + 0.2222222222222222*_ifq1 - 0.022485417203086815*_ifq2 + q_th
        _Q2__next = 0.26798833376246944*_ifq0 + 0.48042111196938336*_ifq1 + 0.1388888888888889*_ifq2 + q_th
        _x79 = m*q_r**2
        _x80 = _x79*q_thd
        _P0__next = 0.1388888888888889*_ifp0 - 0.0359766675249389*_ifp1 + 0.009789444015308325*_ifp2 + _x80
        _x81 = 2.0*m*q_r*q_thd
        _pd__101 = _x81
        _pd__102 = _x79
        _P1__next = 0.30026319498086457*_ifp0 + 0.2222222222222222*_ifp1 - 0.022485417203086815*_ifp2 + _x80
        _pd__103 = _x81
        _pd__104 = _x79
        _P2__next = 0.26798833376246944*_ifp0 + 0.48042111196938336*_ifp1 + 0.1388888888888889*_ifp2 + _x80
        _pd__105 = _x81
        _pd__106 = _x79
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_q_r__j = _T[1, _j1]
            d_q_th__j = _T[2, _j1]
            d_q_thd__j = _T[3, _j1]
            _d_D__j = _T[4, _j1]
            _d_ifq0__j = _T[15, _j1]
            _d_ifp0__j = _T[16, _j1]
            _d_ifq1__j = _T[18, _j1]
            _d_ifp1__j = _T[19, _j1]
            _d_ifq2__j = _T[21, _j1]
            _d_ifp2__j = _T[22, _j1]
            # next values
            _d_Q0__next__j = (0.1388888888888889*_d_ifq0__j - 0.0359766675249389*_d_ifq1__j
                + 0.009789444015308325*_d_ifq2__j + d_q_th__j)
            _d_Q1__next__j = (0.30026319498086457*_d_ifq0__j + 0.2222222222222222*_d_ifq1__j
                - 0.022485417203086815*_d_ifq2__j + d_q_th__j)
            _d_Q2__next__j = (0.26798833376246944*_d_ifq0__j + 0.48042111196938336*_d_ifq1__j
                + 0.1388888888888889*_d_ifq2__j + d_q_th__j)
            _d_P0__next__j = (0.1388888888888889*_d_ifp0__j - 0.0359766675249389*_d_ifp1__j
                + 0.009789444015308325*_d_ifp2__j + _pd__101*d_q_r__j + _pd__102*d_q_thd__j)
            _d_P1__next__j = (0.30026319498086457*_d_ifp0__j + 0.2222222222222222*_d_ifp1__j
                - 0.022485417203086815*_d_ifp2__j + _pd__103*d_q_r__j + _pd__104*d_q_thd__j)
            _d_P2__next__j = (0.26798833376246944*_d_ifp0__j + 0.48042111196938336*_d_ifp1__j
                + 0.1388888888888889*_d_ifp2__j + _pd__105*d_q_r__j + _pd__106*d_q_thd__j)
            _T[4, _j1] = _d_D__j
            _T[5, _j1] = _d_Q0__next__j
            _T[6, _j1] = _d_Q1__next__j
            _T[7, _j1] = _d_Q2__next__j
            _T[8, _j1] = _d_P0__next__j
            _T[9, _j1] = _d_P1__next__j
            _T[10, _j1] = _d_P2__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _P0__next
        _n0_5 = _P1__next
        _n0_6 = _P2__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _P0)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_5 - _P1)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_6 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _P0 = _n0_4
        _P1 = _n0_5
        _P2 = _n0_6
        _passes += 1.0
    _work = 0.031306018160905086*_iF0 + 0.2222222222222222*_iF1 + 0.2464717596168727*_iF2
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = 0.2777777777777778*_ift0 + 0.4444444444444444*_ift1 + 0.2777777777777778*_ift2
    end_q_th = 0.2777777777777778*_ifq0 + 0.4444444444444444*_ifq1 + 0.2777777777777778*_ifq2 + q_th
    end_q_r = q_r_lo
    _x82 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x82
    _pd__107 = _x82/_D
    _pd__108 = _x82/_work
    _x83 = q_r**2
    _x84 = q_r_lo**-2
    _x85 = _x84/m
    end_q_thd = (_x85*(0.2777777777777778*_ifp0 + 0.4444444444444444*_ifp1 + 0.2777777777777778*_ifp2
        + _x83*m*q_thd))
    _x86 = 0.2777777777777778*_x85
    _pd__109 = _x86
    _pd__110 = 0.4444444444444444*_x85
    _pd__111 = _x86
    _pd__112 = 2.0*_x84*q_r*q_thd
    _pd__113 = _x83*_x84
    passes = _passes
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[2, _j2]
        d_q_thd__j = _T[3, _j2]
        _d_D__j = _T[4, _j2]
        _d_iF0__j = _T[11, _j2]
        _d_iF1__j = _T[12, _j2]
        _d_iF2__j = _T[13, _j2]
        _d_ift0__j = _T[14, _j2]
        _d_ifq0__j = _T[15, _j2]
        _d_ifp0__j = _T[16, _j2]
        _d_ift1__j = _T[17, _j2]
        _d_ifq1__j = _T[18, _j2]
        _d_ifp1__j = _T[19, _j2]
        _d_ift2__j = _T[20, _j2]
        _d_ifq2__j = _T[21, _j2]
        _d_ifp2__j = _T[22, _j2]
        _d_work__j = (0.031306018160905086*_d_iF0__j + 0.2222222222222222*_d_iF1__j
            + 0.2464717596168727*_d_iF2__j)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        d_t_half__j = (0.2777777777777778*_d_ift0__j + 0.4444444444444444*_d_ift1__j
            + 0.2777777777777778*_d_ift2__j)
        d_end_q_th__j = (0.2777777777777778*_d_ifq0__j + 0.4444444444444444*_d_ifq1__j
            + 0.2777777777777778*_d_ifq2__j + d_q_th__j)
        d_end_q_rd__j = _d_D__j*_pd__107 + _d_work__j*_pd__108
        d_end_q_thd__j = (_d_ifp0__j*_pd__109 + _d_ifp1__j*_pd__110 + _d_ifp2__j*_pd__111 + _pd__112*d_q_r__j
            + _pd__113*d_q_thd__j)
        _T[23, _j2] = d_t_half__j
        _T[24, _j2] = d_end_q_th__j
        _T[25, _j2] = d_end_q_rd__j
        _T[26, _j2] = d_end_q_thd__j
    (d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th,
        d_t_half__guess_q_thd, ) = (_T[23, 0], _T[23, 1], _T[23, 2], _T[23, 3], _T[23, 4], _T[23, 5], )
    (d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
        d_end_q_th__guess_q_thd, ) = (_T[24, 0], _T[24, 1], _T[24, 2], _T[24, 3], _T[24, 4], _T[24, 5], )
    (d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, ) = (_T[25, 0], _T[25, 1], _T[25, 2], _T[25, 3], _T[25, 4], _T[25, 5], )
    (d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, ) = (_T[26, 0], _T[26, 1], _T[26, 2], _T[26, 3], _T[26, 4], _T[26, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
        d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
        d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, STATUS_OK)


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
    # Total ops: 755
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((33, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 1.0
    _T[0, 4] = 0.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = -1.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 0.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 0.0
    _T[5, 1] = 0.9305681557970263
    _T[5, 2] = 0.0
    _T[5, 3] = 0.0
    _T[5, 4] = 0.06943184420297371
    _T[5, 5] = 0.0
    _T[6, 0] = 0.0
    _T[6, 1] = 0.6699905217924281
    _T[6, 2] = 0.0
    _T[6, 3] = 0.0
    _T[6, 4] = 0.33000947820757187
    _T[6, 5] = 0.0
    _T[7, 0] = 0.0
    _T[7, 1] = 0.33000947820757187
    _T[7, 2] = 0.0
    _T[7, 3] = 0.0
    _T[7, 4] = 0.6699905217924281
    _T[7, 5] = 0.0
    _T[8, 0] = 0.0
    _T[8, 1] = 0.06943184420297371
    _T[8, 2] = 0.0
    _T[8, 3] = 0.0
    _T[8, 4] = 0.9305681557970263
    _T[8, 5] = 0.0
    _T[9, 0] = 1.8611363115940527*m*q_r*q_thd
    _T[9, 1] = 0.0
    _T[9, 2] = 0.9305681557970263*m*q_r**2
    _T[9, 3] = 0.0
    _T[9, 4] = 0.0
    _T[9, 5] = 0.06943184420297371*m*q_r_lo**2
    _T[10, 0] = 1.3399810435848563*m*q_r*q_thd
    _T[10, 1] = 0.0
    _T[10, 2] = 0.6699905217924281*m*q_r**2
    _T[10, 3] = 0.0
    _T[10, 4] = 0.0
    _T[10, 5] = 0.33000947820757187*m*q_r_lo**2
    _T[11, 0] = 0.6600189564151437*m*q_r*q_thd
    _T[11, 1] = 0.0
    _T[11, 2] = 0.33000947820757187*m*q_r**2
    _T[11, 3] = 0.0
    _T[11, 4] = 0.0
    _T[11, 5] = 0.6699905217924281*m*q_r_lo**2
    _T[12, 0] = 0.13886368840594743*m*q_r*q_thd
    _T[12, 1] = 0.0
    _T[12, 2] = 0.06943184420297371*m*q_r**2
    _T[12, 3] = 0.0
    _T[12, 4] = 0.0
    _T[12, 5] = 0.9305681557970263*m*q_r_lo**2
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
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.004820780989426014*_D + q_r
        _isigma0 = _x0
        _x1 = k_d*l0
        _x2 = math.cos(_Q0)
        _x3 = g_s*m
        _x4 = _x2*_x3
        _x5 = _x0*k_d
        _x6 = _P0**2
        _x7 = (1.0/m)
        _x95 = (1.0/_x0)
        _x8 = _x95**3
        _x9 = _x7*_x8
        _x10 = _x6*_x9
        _iF0 = _x1 + _x10 - _x4 - _x5
        _x11 = 2.0*_P0
        _pd__114 = _x11*_x9
        _x12 = math.sin(_Q0)
        _pd__115 = _x12*_x3
        _x13 = 3.0*_x7
        _pd__116 = -_x13*_x6*_x95**4 - k_d
        _x14 = -l0
        _pd__117 = -_x0 - _x14
        _x15 = 0.10890625570683385*_D + q_r
        _isigma1 = _x15
        _x16 = math.cos(_Q1)
        _x17 = _x16*_x3
        _x18 = _x15*k_d
        _x19 = _P1**2
        _x96 = (1.0/_x15)
        _x20 = _x96**3
        _x21 = _x20*_x7
        _x22 = _x19*_x21
        _iF1 = _x1 - _x17 - _x18 + _x22
        _x23 = 2.0*_P1
        _pd__118 = _x21*_x23
        _x24 = math.sin(_Q1)
        _pd__119 = _x24*_x3
        _pd__120 = -_x13*_x19*_x96**4 - k_d
        _pd__121 = -_x14 - _x15
        _x25 = 0.44888729929169013*_D + q_r
        _isigma2 = _x25
        _x26 = math.cos(_Q2)
        _x27 = _x26*_x3
        _x28 = _x25*k_d
        _x29 = _P2**2
        _x97 = (1.0/_x25)
        _x30 = _x97**3
        _x31 = _x30*_x7
        _x32 = _x29*_x31
        _iF2 = _x1 - _x27 - _x28 + _x32
        _x33 = 2.0*_P2
        _pd__122 = _x31*_x33
        _x34 = math.sin(_Q2)
        _pd__123 = _x3*_x34
        _pd__124 = -_x13*_x29*_x97**4 - k_d
        _pd__125 = -_x14 - _x25
        _x35 = 0.8659570925834786*_D + q_r
        _isigma3 = _x35
        _x36 = math.cos(_Q3)
        _x37 = _x3*_x36
        _x38 = _x35*k_d
        _x39 = _P3**2
        _x98 = (1.0/_x35)
        _x40 = _x98**3
        _x41 = _x40*_x7
        _x42 = _x39*_x41
        _iF3 = _x1 - _x37 - _x38 + _x42
        _x43 = 2.0*_P3
        _pd__126 = _x41*_x43
        _x44 = math.sin(_Q3)
        _pd__127 = _x3*_x44
        _pd__128 = -_x13*_x39*_x98**4 - k_d
        _pd__129 = -_x14 - _x35
        _x45 = (0.5*_x1 + 0.582374038291501*_x10 + 0.12383458041329967*_x17 + 0.12383458041329967*_x18
            - 0.12383458041329967*_x22 - 0.0575898635297681*_x27 - 0.0575898635297681*_x28
            + 0.0575898635297681*_x32 + 0.016129321407969507*_x37 + 0.016129321407969507*_x38
            - 0.582374038291501*_x4 - 0.016129321407969507*_x42 - 0.582374038291501*_x5)
        _iPsi0 = _x45
        _x46 = (1.0/math.sqrt(_x45))
        _x47 = math.sqrt(_D)
        _x48 = math.sqrt(m)
        _x49 = _x47*_x48
        _ift0 = _x46*_x49
        _x50 = (0.5)/_x47
        _x51 = _x48*_x50
        _pd__130 = _x46*_x51
        _x52 = _x45**(-1.5)
        _x53 = (0.5)*_x49
        _pd__131 = -_x52*_x53
        _x54 = (1.0/_x48)
        _x55 = _x47*_x54
        _x56 = _x95**2
        _x57 = _x46*_x56
        _x58 = _x55*_x57
        _ifq0 = _P0*_x58
        _x59 = _x50*_x54
        _pd__132 = _P0*_x57*_x59
        _pd__133 = _x58
        _x60 = (0.5)*_x55
        _pd__134 = -_P0*_x52*_x56*_x60
        _pd__135 = -_x11*_x46*_x55*_x8
        _x61 = g_s*m**(1.5)
        _x62 = _x47*_x61
        _x63 = _x46*_x62
        _x64 = _x12*_x63
        _ifp0 = _x0*_x64
        _x65 = _x0*_x12
        _x66 = _x50*_x61
        _pd__136 = _x46*_x65*_x66
        _pd__137 = _x0*_x2*_x63
        _x67 = (0.5)*_x62
        _pd__138 = -_x52*_x65*_x67
        _pd__139 = _x64
        _x68 = (-0.39252437029865583*_x17 - 0.39252437029865583*_x18 + 0.39252437029865583*_x19*_x20*_x7
            + 0.0700094015044783*_x25*k_d + 0.0700094015044783*_x26*g_s*m - 0.0700094015044783*_x32
            - 0.017475652789475504*_x37 - 0.017475652789475504*_x38 + 0.017475652789475504*_x39*_x40*_x7
            - 0.16000937841634696*_x4 - 0.16000937841634696*_x5 + 0.16000937841634696*_x6*_x7*_x8
            + 0.5*k_d*l0)
        _iPsi1 = _x68
        _x69 = (1.0/math.sqrt(_x68))
        _ift1 = _x49*_x69
        _pd__140 = _x51*_x69
        _x70 = _x68**(-1.5)
        _pd__141 = -_x53*_x70
        _x71 = _x96**2
        _x72 = _x69*_x71
        _x73 = _x55*_x72
        _ifq1 = _P1*_x73
        _pd__142 = _P1*_x59*_x72
        _pd__143 = _x73
        _pd__144 = -_P1*_x60*_x70*_x71
        _pd__145 = -_x20*_x23*_x55*_x69
        _x74 = _x62*_x69
        _x75 = _x24*_x74
        _ifp1 = _x15*_x75
        _x76 = _x15*_x24
        _pd__146 = _x66*_x69*_x76
        _pd__147 = _x15*_x16*_x74
        _pd__148 = -_x67*_x70*_x76
        _pd__149 = _x75
        _x77 = (-0.2848443432415939*_x17 - 0.2848443432415939*_x18 + 0.2848443432415939*_x19*_x20*_x7
            - 0.21871326539550162*_x27 - 0.21871326539550162*_x28 + 0.21871326539550162*_x29*_x30*_x7
            + 0.019694864101090868*_x35*k_d + 0.019694864101090868*_x36*g_s*m - 0.01613725546399532*_x4
            - 0.019694864101090868*_x42 - 0.01613725546399532*_x5 + 0.01613725546399532*_x6*_x7*_x8
            + 0.5*k_d*l0)
        _iPsi2 = _x77
        _x78 = (1.0/math.sqrt(_x77))
        _ift2 = _x49*_x78
        _pd__150 = _x51*_x78
        _x79 = _x77**(-1.5)
        _pd__151 = -_x53*_x79
        _x80 = _x97**2
        _x81 = _x78*_x80
        _x82 = _x55*_x81
        _ifq2 = _P2*_x82
        _pd__152 = _P2*_x59*_x81
        _pd__153 = _x82
        _pd__154 = -_P2*_x60*_x79*_x80
        _pd__155 = -_x30*_x33*_x55*_x78
        _x83 = _x62*_x78
        _x84 = _x34*_x83
        _ifp2 = _x25*_x84
        _x85 = _x25*_x34
        _pd__156 = _x66*_x78*_x85
        _pd__157 = _x25*_x26*_x83
        _pd__158 = -_x67*_x79*_x85
        _pd__159 = _x84
        _x86 = (-0.11000222456933441*_x17 - 0.11000222456933441*_x18 + 0.11000222456933441*_x19*_x20*_x7
            - 0.2823150697454702*_x27 - 0.2823150697454702*_x28 + 0.2823150697454702*_x29*_x30*_x7
            - 0.08972165934767481*_x37 - 0.08972165934767481*_x38 + 0.08972165934767481*_x39*_x40*_x7
            - 0.01796104633752054*_x4 - 0.01796104633752054*_x5 + 0.01796104633752054*_x6*_x7*_x8
            + 0.5*k_d*l0)
        _iPsi3 = _x86
        _x87 = (1.0/math.sqrt(_x86))
        _ift3 = _x49*_x87
        _pd__160 = _x51*_x87
        _x88 = _x86**(-1.5)
        _pd__161 = -_x53*_x88
        _x89 = _x98**2
        _x90 = _x87*_x89
        _x91 = _x55*_x90
        _ifq3 = _P3*_x91
        _pd__162 = _P3*_x59*_x90
        _pd__163 = _x91
        _pd__164 = -_P3*_x60*_x88*_x89
        _pd__165 = -_x40*_x43*_x55*_x87
        _x92 = _x62*_x87
        _x93 = _x44*_x92
        _ifp3 = _x35*_x93
        _x94 = _x35*_x44
        _pd__166 = _x66*_x87*_x94
        _pd__167 = _x35*_x36*_x92
        _pd__168 = -_x67*_x88*_x94
        _pd__169 = _x93
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
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_d__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[4, _j0]
            _d_Q0__j = _T[5, _j0]
            _d_Q1__j = _T[6, _j0]
            _d_Q2__j = _T[7, _j0]
            _d_Q3__j = _T[8, _j0]
            _d_P0__j = _T[9, _j0]
            _d_P1__j = _T[10, _j0]
            _d_P2__j = _T[11, _j0]
            _d_P3__j = _T[12, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _d_isigma0__j = 0.004820780989426014*_d_D__j + d_q_r__j
            _d_iF0__j = _d_P0__j*_pd__114 + _d_Q0__j*_pd__115 + _d_isigma0__j*_pd__116 + _pd__117*d_k_d__j
            _d_isigma1__j = 0.10890625570683385*_d_D__j + d_q_r__j
            _d_iF1__j = _d_P1__j*_pd__118 + _d_Q1__j*_pd__119 + _d_isigma1__j*_pd__120 + _pd__121*d_k_d__j
            _d_isigma2__j = 0.44888729929169013*_d_D__j + d_q_r__j
            _d_iF2__j = _d_P2__j*_pd__122 + _d_Q2__j*_pd__123 + _d_isigma2__j*_pd__124 + _pd__125*d_k_d__j
            _d_isigma3__j = 0.8659570925834786*_d_D__j + d_q_r__j
            _d_iF3__j = _d_P3__j*_pd__126 + _d_Q3__j*_pd__127 + _d_isigma3__j*_pd__128 + _pd__129*d_k_d__j
            _d_iPsi0__j = (0.582374038291501*_d_iF0__j - 0.12383458041329967*_d_iF1__j
                + 0.0575898635297681*_d_iF2__j - 0.016129321407969507*_d_iF3__j)
            _d_ift0__j = _d_D__j*_pd__130 + _d_iPsi0__j*_pd__131
            _d_ifq0__j = _d_D__j*_pd__132 + _d_P0__j*_pd__133 + _d_iPsi0__j*_pd__134 + _d_isigma0__j*_pd__135
            _d_ifp0__j = _d_D__j*_pd__136 + _d_Q0__j*_pd__137 + _d_iPsi0__j*_pd__138 + _d_isigma0__j*_pd__139
            _d_iPsi1__j = (0.16000937841634696*_d_iF0__j + 0.39252437029865583*_d_iF1__j
                - 0.0700094015044783*_d_iF2__j + 0.017475652789475504*_d_iF3__j)
            _d_ift1__j = _d_D__j*_pd__140 + _d_iPsi1__j*_pd__141
            _d_ifq1__j = _d_D__j*_pd__142 + _d_P1__j*_pd__143 + _d_iPsi1__j*_pd__144 + _d_isigma1__j*_pd__145
            _d_ifp1__j = _d_D__j*_pd__146 + _d_Q1__j*_pd__147 + _d_iPsi1__j*_pd__148 + _d_isigma1__j*_pd__149
            _d_iPsi2__j = (0.01613725546399532*_d_iF0__j + 0.2848443432415939*_d_iF1__j
                + 0.21871326539550162*_d_iF2__j - 0.019694864101090868*_d_iF3__j)
            _d_ift2__j = _d_D__j*_pd__150 + _d_iPsi2__j*_pd__151
            _d_ifq2__j = _d_D__j*_pd__152 + _d_P2__j*_pd__153 + _d_iPsi2__j*_pd__154 + _d_isigma2__j*_pd__155
            _d_ifp2__j = _d_D__j*_pd__156 + _d_Q2__j*_pd__157 + _d_iPsi2__j*_pd__158 + _d_isigma2__j*_pd__159
            _d_iPsi3__j = (0.01796104633752054*_d_iF0__j + 0.11000222456933441*_d_iF1__j
                + 0.2823150697454702*_d_iF2__j + 0.08972165934767481*_d_iF3__j)
            _d_ift3__j = _d_D__j*_pd__160 + _d_iPsi3__j*_pd__161
            _d_ifq3__j = _d_D__j*_pd__162 + _d_P3__j*_pd__163 + _d_iPsi3__j*_pd__164 + _d_isigma3__j*_pd__165
            _d_ifp3__j = _d_D__j*_pd__166 + _d_Q3__j*_pd__167 + _d_iPsi3__j*_pd__168 + _d_isigma3__j*_pd__169
            _T[13, _j0] = _d_iF0__j
            _T[14, _j0] = _d_iF1__j
            _T[15, _j0] = _d_iF2__j
            _T[16, _j0] = _d_iF3__j
            _T[17, _j0] = _d_ift0__j
            _T[18, _j0] = _d_ifq0__j
            _T[19, _j0] = _d_ifp0__j
            _T[20, _j0] = _d_ift1__j
            _T[21, _j0] = _d_ifq1__j
            _T[22, _j0] = _d_ifp1__j
            _T[23, _j0] = _d_ift2__j
            _T[24, _j0] = _d_ifq2__j
            _T[25, _j0] = _d_ifp2__j
            _T[26, _j0] = _d_ift3__j
            _T[27, _j0] = _d_ifq3__j
            _T[28, _j0] = _d_ifp3__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = (0.08696371128436346*_ifq0 - 0.026604180084998794*_ifq1 + 0.012627462689404725*_ifq2
            - 0.0035551496857956833*_ifq3 + q_th)
        _Q1__next = (0.18811811749986806*_ifq0 + 0.16303628871563652*_ifq1 - 0.027880428602470895*_ifq2
            + 0.006735500594538156*_ifq3 + q_th)
        _Q2__next = (0.16719192197418878*_ifq0 + 0.35395300603374397*_ifq1 + 0.16303628871563652*_ifq2
            - 0.014190694931141144*_ifq3 + q_th)
        _Q3__next = (0.1774825722545226*_ifq0 + 0.31344511474186837*_ifq1 + 0.35267675751627187*_ifq2
            + 0.08696371128436346*_ifq3 + q_th)
        _x99 = m*q_r**2
        _x100 = _x99*q_thd
        _P0__next = (0.08696371128436346*_ifp0 - 0.026604180084998794*_ifp1 + 0.012627462689404725*_ifp2
            - 0.0035551496857956833*_ifp3 + _x100)
        _x101 = 2.0*m*q_r*q_thd
        _pd__170 = _x101
        _pd__171 = _x99
        _P1__next = (0.18811811749986806*_ifp0 + 0.16303628871563652*_ifp1 - 0.027880428602470895*_ifp2
            + 0.006735500594538156*_ifp3 + _x100)
        _pd__172 = _x101
        _pd__173 = _x99
        _P2__next = (0.16719192197418878*_ifp0 + 0.35395300603374397*_ifp1 + 0.16303628871563652*_ifp2
            - 0.014190694931141144*_ifp3 + _x100)
        _pd__174 = _x101
        _pd__175 = _x99
        _P3__next = (0.1774825722545226*_ifp0 + 0.31344511474186837*_ifp1 + 0.35267675751627187*_ifp2
            + 0.08696371128436346*_ifp3 + _x100)
        _pd__176 = _x101
        _pd__177 = _x99
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_q_r__j = _T[1, _j1]
            d_q_th__j = _T[2, _j1]
            d_q_thd__j = _T[3, _j1]
            _d_D__j = _T[4, _j1]
            _d_ifq0__j = _T[18, _j1]
            _d_ifp0__j = _T[19, _j1]
            _d_ifq1__j = _T[21, _j1]
            _d_ifp1__j = _T[22, _j1]
            _d_ifq2__j = _T[24, _j1]
            _d_ifp2__j = _T[25, _j1]
            _d_ifq3__j = _T[27, _j1]
            _d_ifp3__j = _T[28, _j1]
            # next values
            _d_Q0__next__j = (0.08696371128436346*_d_ifq0__j - 0.026604180084998794*_d_ifq1__j
                + 0.012627462689404725*_d_ifq2__j - 0.0035551496857956833*_d_ifq3__j + d_q_th__j)
            _d_Q1__next__j = (0.18811811749986806*_d_ifq0__j + 0.16303628871563652*_d_ifq1__j
                - 0.027880428602470895*_d_ifq2__j + 0.006735500594538156*_d_ifq3__j + d_q_th__j)
            _d_Q2__next__j = (0.16719192197418878*_d_ifq0__j + 0.35395300603374397*_d_ifq1__j
                + 0.16303628871563652*_d_ifq2__j - 0.014190694931141144*_d_ifq3__j + d_q_th__j)
            _d_Q3__next__j = (0.1774825722545226*_d_ifq0__j + 0.31344511474186837*_d_ifq1__j
                + 0.35267675751627187*_d_ifq2__j + 0.08696371128436346*_d_ifq3__j + d_q_th__j)
            _d_P0__next__j = (0.08696371128436346*_d_ifp0__j - 0.026604180084998794*_d_ifp1__j
                + 0.012627462689404725*_d_ifp2__j - 0.0035551496857956833*_d_ifp3__j + _pd__170*d_q_r__j
                + _pd__171*d_q_thd__j)
            _d_P1__next__j = (0.18811811749986806*_d_ifp0__j + 0.16303628871563652*_d_ifp1__j
                - 0.027880428602470895*_d_ifp2__j + 0.006735500594538156*_d_ifp3__j + _pd__172*d_q_r__j
                + _pd__173*d_q_thd__j)
            _d_P2__next__j = (0.16719192197418878*_d_ifp0__j + 0.35395300603374397*_d_ifp1__j
                + 0.16303628871563652*_d_ifp2__j - 0.014190694931141144*_d_ifp3__j + _pd__174*d_q_r__j
                + _pd__175*d_q_thd__j)
            _d_P3__next__j = (0.1774825722545226*_d_ifp0__j + 0.31344511474186837*_d_ifp1__j
                + 0.35267675751627187*_d_ifp2__j + 0.08696371128436346*_d_ifp3__j + _pd__176*d_q_r__j
                + _pd__177*d_q_thd__j)
            _T[4, _j1] = _d_D__j
            _T[5, _j1] = _d_Q0__next__j
            _T[6, _j1] = _d_Q1__next__j
            _T[7, _j1] = _d_Q2__next__j
            _T[8, _j1] = _d_Q3__next__j
            _T[9, _j1] = _d_P0__next__j
            _T[10, _j1] = _d_P1__next__j
            _T[11, _j1] = _d_P2__next__j
            _T[12, _j1] = _d_P3__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _P0__next
        _n0_6 = _P1__next
        _n0_7 = _P2__next
        _n0_8 = _P3__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd)))
            and (abs(_n0_6 - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_7
            - _P2) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
        _D = _n0_0
        _Q0 = _n0_1
        _Q1 = _n0_2
        _Q2 = _n0_3
        _Q3 = _n0_4
        _P0 = _n0_5
        _P1 = _n0_6
        _P2 = _n0_7
        _P3 = _n0_8
        _passes += 1.0
    _work = (0.012076101706416622*_iF0 + 0.1076070411358925*_iF1 + 0.21846553629538057*_iF2
        + 0.1618513208623103*_iF3)
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = (0.17392742256872692*_ift0 + 0.32607257743127305*_ift1 + 0.32607257743127305*_ift2
        + 0.17392742256872692*_ift3)
    end_q_th = (0.17392742256872692*_ifq0 + 0.32607257743127305*_ifq1 + 0.32607257743127305*_ifq2
        + 0.17392742256872692*_ifq3 + q_th)
    end_q_r = q_r_lo
    _x102 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x102
    _pd__178 = _x102/_D
    _pd__179 = _x102/_work
    _x103 = q_r**2
    _x104 = q_r_lo**-2
    _x105 = _x104/m
    end_q_thd = (_x105*(0.17392742256872692*_ifp0 + 0.32607257743127305*_ifp1 + 0.32607257743127305*_ifp2
        + 0.17392742256872692*_ifp3 + _x103*m*q_thd))
    _x106 = 0.17392742256872692*_x105
    _pd__180 = _x106
    _x107 = 0.32607257743127305*_x105
    _pd__181 = _x107
    _pd__182 = _x107
    _pd__183 = _x106
    _pd__184 = 2.0*_x104*q_r*q_thd
    _pd__185 = _x103*_x104
    passes = _passes
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[2, _j2]
        d_q_thd__j = _T[3, _j2]
        _d_D__j = _T[4, _j2]
        _d_iF0__j = _T[13, _j2]
        _d_iF1__j = _T[14, _j2]
        _d_iF2__j = _T[15, _j2]
        _d_iF3__j = _T[16, _j2]
        _d_ift0__j = _T[17, _j2]
        _d_ifq0__j = _T[18, _j2]
        _d_ifp0__j = _T[19, _j2]
        _d_ift1__j = _T[20, _j2]
        _d_ifq1__j = _T[21, _j2]
        _d_ifp1__j = _T[22, _j2]
        _d_ift2__j = _T[23, _j2]
        _d_ifq2__j = _T[24, _j2]
        _d_ifp2__j = _T[25, _j2]
        _d_ift3__j = _T[26, _j2]
        _d_ifq3__j = _T[27, _j2]
        _d_ifp3__j = _T[28, _j2]
        _d_work__j = (0.012076101706416622*_d_iF0__j + 0.1076070411358925*_d_iF1__j
            + 0.21846553629538057*_d_iF2__j + 0.1618513208623103*_d_iF3__j)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        d_t_half__j = (0.17392742256872692*_d_ift0__j + 0.32607257743127305*_d_ift1__j
            + 0.32607257743127305*_d_ift2__j + 0.17392742256872692*_d_ift3__j)
        d_end_q_th__j = (0.17392742256872692*_d_ifq0__j + 0.32607257743127305*_d_ifq1__j
            + 0.32607257743127305*_d_ifq2__j + 0.17392742256872692*_d_ifq3__j + d_q_th__j)
        d_end_q_rd__j = _d_D__j*_pd__178 + _d_work__j*_pd__179
        d_end_q_thd__j = (_d_ifp0__j*_pd__180 + _d_ifp1__j*_pd__181 + _d_ifp2__j*_pd__182
            + _d_ifp3__j*_pd__183 + _pd__184*d_q_r__j + _pd__185*d_q_thd__j)
        _T[29, _j2] = d_t_half__j
        _T[30, _j2] = d_end_q_th__j
        _T[31, _j2] = d_end_q_rd__j
        _T[32, _j2] = d_end_q_thd__j
    (d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th,
        d_t_half__guess_q_thd, ) = (_T[29, 0], _T[29, 1], _T[29, 2], _T[29, 3], _T[29, 4], _T[29, 5], )
    (d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
        d_end_q_th__guess_q_thd, ) = (_T[30, 0], _T[30, 1], _T[30, 2], _T[30, 3], _T[30, 4], _T[30, 5], )
    (d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, ) = (_T[31, 0], _T[31, 1], _T[31, 2], _T[31, 3], _T[31, 4], _T[31, 5], )
    (d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, ) = (_T[32, 0], _T[32, 1], _T[32, 2], _T[32, 3], _T[32, 4], _T[32, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
        d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
        d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, STATUS_OK)


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
    # Total ops: 1322
    # the tangents the loops compute once per direction: _T[row, direction]
    _T = np.empty((45, 6))
    _T[0, 0] = 0.0
    _T[0, 1] = 0.0
    _T[0, 2] = 0.0
    _T[0, 3] = 1.0
    _T[0, 4] = 0.0
    _T[0, 5] = 0.0
    _T[1, 0] = 1.0
    _T[1, 1] = 0.0
    _T[1, 2] = 0.0
    _T[1, 3] = 0.0
    _T[1, 4] = 0.0
    _T[1, 5] = 0.0
    _T[2, 0] = 0.0
    _T[2, 1] = 1.0
    _T[2, 2] = 0.0
    _T[2, 3] = 0.0
    _T[2, 4] = 0.0
    _T[2, 5] = 0.0
    _T[3, 0] = 0.0
    _T[3, 1] = 0.0
    _T[3, 2] = 1.0
    _T[3, 3] = 0.0
    _T[3, 4] = 0.0
    _T[3, 5] = 0.0
    _T[4, 0] = -1.0
    _T[4, 1] = 0.0
    _T[4, 2] = 0.0
    _T[4, 3] = 0.0
    _T[4, 4] = 0.0
    _T[4, 5] = 0.0
    _T[5, 0] = 0.0
    _T[5, 1] = 0.966234757101576
    _T[5, 2] = 0.0
    _T[5, 3] = 0.0
    _T[5, 4] = 0.03376524289842399
    _T[5, 5] = 0.0
    _T[6, 0] = 0.0
    _T[6, 1] = 0.8306046932331322
    _T[6, 2] = 0.0
    _T[6, 3] = 0.0
    _T[6, 4] = 0.16939530676686773
    _T[6, 5] = 0.0
    _T[7, 0] = 0.0
    _T[7, 1] = 0.6193095930415985
    _T[7, 2] = 0.0
    _T[7, 3] = 0.0
    _T[7, 4] = 0.38069040695840156
    _T[7, 5] = 0.0
    _T[8, 0] = 0.0
    _T[8, 1] = 0.38069040695840156
    _T[8, 2] = 0.0
    _T[8, 3] = 0.0
    _T[8, 4] = 0.6193095930415985
    _T[8, 5] = 0.0
    _T[9, 0] = 0.0
    _T[9, 1] = 0.16939530676686773
    _T[9, 2] = 0.0
    _T[9, 3] = 0.0
    _T[9, 4] = 0.8306046932331322
    _T[9, 5] = 0.0
    _T[10, 0] = 0.0
    _T[10, 1] = 0.03376524289842399
    _T[10, 2] = 0.0
    _T[10, 3] = 0.0
    _T[10, 4] = 0.966234757101576
    _T[10, 5] = 0.0
    _T[11, 0] = 1.932469514203152*m*q_r*q_thd
    _T[11, 1] = 0.0
    _T[11, 2] = 0.966234757101576*m*q_r**2
    _T[11, 3] = 0.0
    _T[11, 4] = 0.0
    _T[11, 5] = 0.03376524289842399*m*q_r_lo**2
    _T[12, 0] = 1.6612093864662645*m*q_r*q_thd
    _T[12, 1] = 0.0
    _T[12, 2] = 0.8306046932331322*m*q_r**2
    _T[12, 3] = 0.0
    _T[12, 4] = 0.0
    _T[12, 5] = 0.16939530676686773*m*q_r_lo**2
    _T[13, 0] = 1.238619186083197*m*q_r*q_thd
    _T[13, 1] = 0.0
    _T[13, 2] = 0.6193095930415985*m*q_r**2
    _T[13, 3] = 0.0
    _T[13, 4] = 0.0
    _T[13, 5] = 0.38069040695840156*m*q_r_lo**2
    _T[14, 0] = 0.7613808139168031*m*q_r*q_thd
    _T[14, 1] = 0.0
    _T[14, 2] = 0.38069040695840156*m*q_r**2
    _T[14, 3] = 0.0
    _T[14, 4] = 0.0
    _T[14, 5] = 0.6193095930415985*m*q_r_lo**2
    _T[15, 0] = 0.33879061353373546*m*q_r*q_thd
    _T[15, 1] = 0.0
    _T[15, 2] = 0.16939530676686773*m*q_r**2
    _T[15, 3] = 0.0
    _T[15, 4] = 0.0
    _T[15, 5] = 0.8306046932331322*m*q_r_lo**2
    _T[16, 0] = 0.06753048579684798*m*q_r*q_thd
    _T[16, 1] = 0.0
    _T[16, 2] = 0.03376524289842399*m*q_r**2
    _T[16, 3] = 0.0
    _T[16, 4] = 0.0
    _T[16, 5] = 0.966234757101576*m*q_r_lo**2
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
    _passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and _passes > 0.0:
            return _NAN30 + (STATUS_NOT_CONVERGED,)
        # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
        _x0 = 0.0011400916279895713*_D + q_r
        _isigma0 = _x0
        _x1 = k_d*l0
        _x2 = math.cos(_Q0)
        _x3 = g_s*m
        _x4 = _x2*_x3
        _x5 = _x0*k_d
        _x6 = _P0**2
        _x7 = (1.0/m)
        _x135 = (1.0/_x0)
        _x8 = _x135**3
        _x9 = _x7*_x8
        _x10 = _x6*_x9
        _iF0 = _x1 + _x10 - _x4 - _x5
        _x11 = 2.0*_P0
        _pd__186 = _x11*_x9
        _x12 = math.sin(_Q0)
        _pd__187 = _x12*_x3
        _x13 = 3.0*_x7
        _pd__188 = -_x13*_x135**4*_x6 - k_d
        _x14 = -l0
        _pd__189 = -_x0 - _x14
        _x15 = 0.02869476995464123*_D + q_r
        _isigma1 = _x15
        _x16 = math.cos(_Q1)
        _x17 = _x16*_x3
        _x18 = _x15*k_d
        _x19 = _P1**2
        _x136 = (1.0/_x15)
        _x20 = _x136**3
        _x21 = _x20*_x7
        _x22 = _x19*_x21
        _iF1 = _x1 - _x17 - _x18 + _x22
        _x23 = 2.0*_P1
        _pd__190 = _x21*_x23
        _x24 = math.sin(_Q1)
        _pd__191 = _x24*_x3
        _pd__192 = -_x13*_x136**4*_x19 - k_d
        _pd__193 = -_x14 - _x15
        _x25 = 0.14492518595015338*_D + q_r
        _isigma2 = _x25
        _x26 = math.cos(_Q2)
        _x27 = _x26*_x3
        _x28 = _x25*k_d
        _x29 = _P2**2
        _x137 = (1.0/_x25)
        _x30 = _x137**3
        _x31 = _x30*_x7
        _x32 = _x29*_x31
        _iF2 = _x1 - _x27 - _x28 + _x32
        _x33 = 2.0*_P2
        _pd__194 = _x31*_x33
        _x34 = math.sin(_Q2)
        _pd__195 = _x3*_x34
        _pd__196 = -_x13*_x137**4*_x29 - k_d
        _pd__197 = -_x14 - _x25
        _x35 = 0.3835443720333503*_D + q_r
        _isigma3 = _x35
        _x36 = math.cos(_Q3)
        _x37 = _x3*_x36
        _x38 = _x35*k_d
        _x39 = _P3**2
        _x138 = (1.0/_x35)
        _x40 = _x138**3
        _x41 = _x40*_x7
        _x42 = _x39*_x41
        _iF3 = _x1 - _x37 - _x38 + _x42
        _x43 = 2.0*_P3
        _pd__198 = _x41*_x43
        _x44 = math.sin(_Q3)
        _pd__199 = _x3*_x44
        _pd__200 = -_x13*_x138**4*_x39 - k_d
        _pd__201 = -_x14 - _x35
        _x45 = 0.6899041564209057*_D + q_r
        _isigma4 = _x45
        _x46 = math.cos(_Q4)
        _x47 = _x3*_x46
        _x48 = _x45*k_d
        _x49 = _P4**2
        _x139 = (1.0/_x45)
        _x50 = _x139**3
        _x51 = _x50*_x7
        _x52 = _x49*_x51
        _iF4 = _x1 - _x47 - _x48 + _x52
        _x53 = 2.0*_P4
        _pd__202 = _x51*_x53
        _x54 = math.sin(_Q4)
        _pd__203 = _x3*_x54
        _pd__204 = -_x13*_x139**4*_x49 - k_d
        _pd__205 = -_x14 - _x45
        _x55 = 0.9336096058311416*_D + q_r
        _isigma5 = _x55
        _x56 = math.cos(_Q5)
        _x57 = _x3*_x56
        _x58 = _x55*k_d
        _x59 = _P5**2
        _x140 = (1.0/_x55)
        _x60 = _x140**3
        _x61 = _x60*_x7
        _x62 = _x59*_x61
        _iF5 = _x1 - _x57 - _x58 + _x62
        _x63 = 2.0*_P5
        _pd__206 = _x61*_x63
        _x64 = math.sin(_Q5)
        _pd__207 = _x3*_x64
        _pd__208 = -_x13*_x140**4*_x59 - k_d
        _pd__209 = -_x14 - _x55
        _x65 = (0.5*_x1 + 0.5871580340658094*_x10 + 0.140380692261653*_x17 + 0.140380692261653*_x18
            - 0.140380692261653*_x22 - 0.08683151831711133*_x27 - 0.08683151831711133*_x28
            + 0.08683151831711133*_x32 + 0.052466581536012566*_x37 + 0.052466581536012566*_x38
            - 0.5871580340658094*_x4 - 0.052466581536012566*_x42 - 0.026354606039126004*_x47
            - 0.026354606039126004*_x48 - 0.5871580340658094*_x5 + 0.026354606039126004*_x52
            + 0.007496884624381081*_x57 + 0.007496884624381081*_x58 - 0.007496884624381081*_x62)
        _iPsi0 = _x65
        _x66 = (1.0/math.sqrt(_x65))
        _x67 = math.sqrt(_D)
        _x68 = math.sqrt(m)
        _x69 = _x67*_x68
        _ift0 = _x66*_x69
        _x70 = (0.5)/_x67
        _x71 = _x68*_x70
        _pd__210 = _x66*_x71
        _x72 = _x65**(-1.5)
        _x73 = (0.5)*_x69
        _pd__211 = -_x72*_x73
        _x74 = (1.0/_x68)
        _x75 = _x67*_x74
        _x76 = _x135**2
        _x77 = _x66*_x76
        _x78 = _x75*_x77
        _ifq0 = _P0*_x78
        _x79 = _x70*_x74
        _pd__212 = _P0*_x77*_x79
        _pd__213 = _x78
        _x80 = (0.5)*_x75
        _pd__214 = -_P0*_x72*_x76*_x80
        _pd__215 = -_x11*_x66*_x75*_x8
        _x81 = g_s*m**(1.5)
        _x82 = _x67*_x81
        _x83 = _x66*_x82
        _x84 = _x12*_x83
        _ifp0 = _x0*_x84
        _x85 = _x0*_x12
        _x86 = _x70*_x81
        _pd__216 = _x66*_x85*_x86
        _pd__217 = _x0*_x2*_x83
        _x87 = (0.5)*_x82
        _pd__218 = -_x72*_x85*_x87
        _pd__219 = _x84
        _x88 = -0.5*k_d*l0
        _x89 = (-0.41567911405660357*_x17 - 0.41567911405660357*_x18 + 0.41567911405660357*_x19*_x20*_x7
            + 0.09720828549085844*_x25*k_d + 0.09720828549085844*_x26*g_s*m - 0.09720828549085844*_x32
            - 0.05155355009455148*_x37 - 0.05155355009455148*_x38 + 0.05155355009455148*_x39*_x40*_x7
            - 0.147790320897128*_x4 + 0.024719229415033087*_x45*k_d + 0.024719229415033087*_x46*g_s*m
            - 0.147790320897128*_x5 - 0.024719229415033087*_x52 - 0.006904529857608445*_x57
            - 0.006904529857608445*_x58 + 0.006904529857608445*_x59*_x60*_x7 + 0.147790320897128*_x6*_x7*_x8
            - _x88)
        _iPsi1 = _x89
        _x90 = (1.0/math.sqrt(_x89))
        _ift1 = _x69*_x90
        _pd__220 = _x71*_x90
        _x91 = _x89**(-1.5)
        _pd__221 = -_x73*_x91
        _x92 = _x136**2
        _x93 = _x90*_x92
        _x94 = _x75*_x93
        _ifq1 = _P1*_x94
        _pd__222 = _P1*_x79*_x93
        _pd__223 = _x94
        _pd__224 = -_P1*_x80*_x91*_x92
        _pd__225 = -_x20*_x23*_x75*_x90
        _x95 = _x82*_x90
        _x96 = _x24*_x95
        _ifp1 = _x15*_x96
        _x97 = _x15*_x24
        _pd__226 = _x86*_x90*_x97
        _pd__227 = _x15*_x16*_x95
        _pd__228 = -_x87*_x91*_x97
        _pd__229 = _x96
        _x98 = (-0.25540525119175433*_x17 - 0.25540525119175433*_x18 + 0.25540525119175433*_x19*_x20*_x7
            - 0.2685463444140672*_x27 - 0.2685463444140672*_x28 + 0.2685463444140672*_x29*_x30*_x7
            + 0.048794612428541204*_x35*k_d + 0.048794612428541204*_x36*g_s*m - 0.010443786721981197*_x4
            - 0.048794612428541204*_x42 - 0.01951903325298492*_x47 - 0.01951903325298492*_x48
            + 0.01951903325298492*_x49*_x50*_x7 - 0.010443786721981197*_x5 + 0.005119803152246505*_x55*k_d
            + 0.005119803152246505*_x56*g_s*m + 0.010443786721981197*_x6*_x7*_x8 - 0.005119803152246505*_x62
            - _x88)
        _iPsi2 = _x98
        _x99 = (1.0/math.sqrt(_x98))
        _ift2 = _x69*_x99
        _pd__230 = _x71*_x99
        _x100 = _x98**(-1.5)
        _pd__231 = -_x100*_x73
        _x101 = _x137**2
        _x102 = _x101*_x99
        _x103 = _x102*_x75
        _ifq2 = _P2*_x103
        _pd__232 = _P2*_x102*_x79
        _pd__233 = _x103
        _pd__234 = -_P2*_x100*_x101*_x80
        _pd__235 = -_x30*_x33*_x75*_x99
        _x104 = _x82*_x99
        _x105 = _x104*_x34
        _ifp2 = _x105*_x25
        _x106 = _x25*_x34
        _pd__236 = _x106*_x86*_x99
        _pd__237 = _x104*_x25*_x26
        _pd__238 = -_x100*_x106*_x87
        _pd__239 = _x105
        _x107 = -0.5*k_d*l0
        _x108 = (-_x107 - 0.0662099828438604*_x17 - 0.0662099828438604*_x18 + 0.0662099828438604*_x19*_x20*_x7
            - 0.2671819482314443*_x27 - 0.2671819482314443*_x28 + 0.2671819482314443*_x29*_x30*_x7
            - 0.1742495636223592*_x37 - 0.1742495636223592*_x38 + 0.1742495636223592*_x39*_x40*_x7
            - 0.01101839635505667*_x4 + 0.02396692958086051*_x45*k_d + 0.02396692958086051*_x46*g_s*m
            - 0.01101839635505667*_x5 - 0.02396692958086051*_x52 - 0.00530703852813994*_x57
            - 0.00530703852813994*_x58 + 0.00530703852813994*_x59*_x60*_x7 + 0.01101839635505667*_x6*_x7*_x8)
        _iPsi3 = _x108
        _x109 = (1.0/math.sqrt(_x108))
        _ift3 = _x109*_x69
        _pd__240 = _x109*_x71
        _x110 = _x108**(-1.5)
        _pd__241 = -_x110*_x73
        _x111 = _x138**2
        _x112 = _x109*_x111
        _x113 = _x112*_x75
        _ifq3 = _P3*_x113
        _pd__242 = _P3*_x112*_x79
        _pd__243 = _x113
        _pd__244 = -_P3*_x110*_x111*_x80
        _pd__245 = -_x109*_x40*_x43*_x75
        _x114 = _x109*_x82
        _x115 = _x114*_x44
        _ifp3 = _x115*_x35
        _x116 = _x35*_x44
        _pd__246 = _x109*_x116*_x86
        _pd__247 = _x114*_x35*_x36
        _pd__248 = -_x110*_x116*_x87
        _pd__249 = _x115
        _x117 = (-0.050345455482979015*_x17 - 0.050345455482979015*_x18 + 0.050345455482979015*_x19*_x20*_x7
            - 0.11622097556712797*_x27 - 0.11622097556712797*_x28 + 0.11622097556712797*_x29*_x30*_x7
            - 0.2353986790647292*_x37 - 0.2353986790647292*_x38 + 0.2353986790647292*_x39*_x40*_x7
            - 0.0025147977064533143*_x4 - 0.10372825048336794*_x47 - 0.10372825048336794*_x48
            + 0.10372825048336794*_x49*_x50*_x7 - 0.0025147977064533143*_x5 + 0.008208158304657426*_x55*k_d
            + 0.008208158304657426*_x56*g_s*m + 0.0025147977064533143*_x6*_x7*_x8 - 0.008208158304657426*_x62
            - _x88)
        _iPsi4 = _x117
        _x118 = (1.0/math.sqrt(_x117))
        _ift4 = _x118*_x69
        _pd__250 = _x118*_x71
        _x119 = _x117**(-1.5)
        _pd__251 = -_x119*_x73
        _x120 = _x139**2
        _x121 = _x118*_x120
        _x122 = _x121*_x75
        _ifq4 = _P4*_x122
        _pd__252 = _P4*_x121*_x79
        _pd__253 = _x122
        _pd__254 = -_P4*_x119*_x120*_x80
        _pd__255 = -_x118*_x50*_x53*_x75
        _x123 = _x118*_x82
        _x124 = _x123*_x54
        _ifp4 = _x124*_x45
        _x125 = _x45*_x54
        _pd__256 = _x118*_x125*_x86
        _pd__257 = _x123*_x45*_x46
        _pd__258 = -_x119*_x125*_x87
        _pd__259 = _x124
        _x126 = (-_x107 - 0.029703284805013122*_x17 - 0.029703284805013122*_x18
            + 0.029703284805013122*_x19*_x20*_x7 - 0.10140664131431479*_x27 - 0.10140664131431479*_x28
            + 0.10140664131431479*_x29*_x30*_x7 - 0.14531313573962065*_x37 - 0.14531313573962065*_x38
            + 0.14531313573962065*_x39*_x40*_x7 - 0.003959513229722528*_x4 - 0.17612158869639333*_x47
            - 0.17612158869639333*_x48 + 0.17612158869639333*_x49*_x50*_x7 - 0.003959513229722528*_x5
            - 0.04349583621493557*_x57 - 0.04349583621493557*_x58 + 0.04349583621493557*_x59*_x60*_x7
            + 0.003959513229722528*_x6*_x7*_x8)
        _iPsi5 = _x126
        _x127 = (1.0/math.sqrt(_x126))
        _ift5 = _x127*_x69
        _pd__260 = _x127*_x71
        _x128 = _x126**(-1.5)
        _pd__261 = -_x128*_x73
        _x129 = _x140**2
        _x130 = _x127*_x129
        _x131 = _x130*_x75
        _ifq5 = _P5*_x131
        _pd__262 = _P5*_x130*_x79
        _pd__263 = _x131
        _pd__264 = -_P5*_x128*_x129*_x80
        _pd__265 = -_x127*_x60*_x63*_x75
        _x132 = _x127*_x82
        _x133 = _x132*_x64
        _ifp5 = _x133*_x55
        _x134 = _x55*_x64
        _pd__266 = _x127*_x134*_x86
        _pd__267 = _x132*_x55*_x56
        _pd__268 = -_x128*_x134*_x87
        _pd__269 = _x133
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
        # the evaluation's tangents, once per direction
        for _j0 in range(6):
            d_k_d__j = _T[0, _j0]
            d_q_r__j = _T[1, _j0]
            _d_D__j = _T[4, _j0]
            _d_Q0__j = _T[5, _j0]
            _d_Q1__j = _T[6, _j0]
            _d_Q2__j = _T[7, _j0]
            _d_Q3__j = _T[8, _j0]
            _d_Q4__j = _T[9, _j0]
            _d_Q5__j = _T[10, _j0]
            _d_P0__j = _T[11, _j0]
            _d_P1__j = _T[12, _j0]
            _d_P2__j = _T[13, _j0]
            _d_P3__j = _T[14, _j0]
            _d_P4__j = _T[15, _j0]
            _d_P5__j = _T[16, _j0]
            # node values: sigma, F_r (29), Psi, u-rates of (30)-(32)
            _d_isigma0__j = 0.0011400916279895713*_d_D__j + d_q_r__j
            _d_iF0__j = _d_P0__j*_pd__186 + _d_Q0__j*_pd__187 + _d_isigma0__j*_pd__188 + _pd__189*d_k_d__j
            _d_isigma1__j = 0.02869476995464123*_d_D__j + d_q_r__j
            _d_iF1__j = _d_P1__j*_pd__190 + _d_Q1__j*_pd__191 + _d_isigma1__j*_pd__192 + _pd__193*d_k_d__j
            _d_isigma2__j = 0.14492518595015338*_d_D__j + d_q_r__j
            _d_iF2__j = _d_P2__j*_pd__194 + _d_Q2__j*_pd__195 + _d_isigma2__j*_pd__196 + _pd__197*d_k_d__j
            _d_isigma3__j = 0.3835443720333503*_d_D__j + d_q_r__j
            _d_iF3__j = _d_P3__j*_pd__198 + _d_Q3__j*_pd__199 + _d_isigma3__j*_pd__200 + _pd__201*d_k_d__j
            _d_isigma4__j = 0.6899041564209057*_d_D__j + d_q_r__j
            _d_iF4__j = _d_P4__j*_pd__202 + _d_Q4__j*_pd__203 + _d_isigma4__j*_pd__204 + _pd__205*d_k_d__j
            _d_isigma5__j = 0.9336096058311416*_d_D__j + d_q_r__j
            _d_iF5__j = _d_P5__j*_pd__206 + _d_Q5__j*_pd__207 + _d_isigma5__j*_pd__208 + _pd__209*d_k_d__j
            _d_iPsi0__j = (0.5871580340658094*_d_iF0__j - 0.140380692261653*_d_iF1__j
                + 0.08683151831711133*_d_iF2__j - 0.052466581536012566*_d_iF3__j
                + 0.026354606039126004*_d_iF4__j - 0.007496884624381081*_d_iF5__j)
            _d_ift0__j = _d_D__j*_pd__210 + _d_iPsi0__j*_pd__211
            _d_ifq0__j = _d_D__j*_pd__212 + _d_P0__j*_pd__213 + _d_iPsi0__j*_pd__214 + _d_isigma0__j*_pd__215
            _d_ifp0__j = _d_D__j*_pd__216 + _d_Q0__j*_pd__217 + _d_iPsi0__j*_pd__218 + _d_isigma0__j*_pd__219
            _d_iPsi1__j = (0.147790320897128*_d_iF0__j + 0.41567911405660357*_d_iF1__j
                - 0.09720828549085844*_d_iF2__j + 0.05155355009455148*_d_iF3__j
                - 0.024719229415033087*_d_iF4__j + 0.006904529857608445*_d_iF5__j)
            _d_ift1__j = _d_D__j*_pd__220 + _d_iPsi1__j*_pd__221
            _d_ifq1__j = _d_D__j*_pd__222 + _d_P1__j*_pd__223 + _d_iPsi1__j*_pd__224 + _d_isigma1__j*_pd__225
            _d_ifp1__j = _d_D__j*_pd__226 + _d_Q1__j*_pd__227 + _d_iPsi1__j*_pd__228 + _d_isigma1__j*_pd__229
            _d_iPsi2__j = (0.010443786721981197*_d_iF0__j + 0.25540525119175433*_d_iF1__j
                + 0.2685463444140672*_d_iF2__j - 0.048794612428541204*_d_iF3__j
                + 0.01951903325298492*_d_iF4__j - 0.005119803152246505*_d_iF5__j)
            _d_ift2__j = _d_D__j*_pd__230 + _d_iPsi2__j*_pd__231
            _d_ifq2__j = _d_D__j*_pd__232 + _d_P2__j*_pd__233 + _d_iPsi2__j*_pd__234 + _d_isigma2__j*_pd__235
            _d_ifp2__j = _d_D__j*_pd__236 + _d_Q2__j*_pd__237 + _d_iPsi2__j*_pd__238 + _d_isigma2__j*_pd__239
            _d_iPsi3__j = (0.01101839635505667*_d_iF0__j + 0.0662099828438604*_d_iF1__j
                + 0.2671819482314443*_d_iF2__j + 0.1742495636223592*_d_iF3__j - 0.02396692958086051*_d_iF4__j
                + 0.00530703852813994*_d_iF5__j)
            _d_ift3__j = _d_D__j*_pd__240 + _d_iPsi3__j*_pd__241
            _d_ifq3__j = _d_D__j*_pd__242 + _d_P3__j*_pd__243 + _d_iPsi3__j*_pd__244 + _d_isigma3__j*_pd__245
            _d_ifp3__j = _d_D__j*_pd__246 + _d_Q3__j*_pd__247 + _d_iPsi3__j*_pd__248 + _d_isigma3__j*_pd__249
            _d_iPsi4__j = (0.0025147977064533143*_d_iF0__j + 0.050345455482979015*_d_iF1__j
                + 0.11622097556712797*_d_iF2__j + 0.2353986790647292*_d_iF3__j + 0.10372825048336794*_d_iF4__j
                - 0.008208158304657426*_d_iF5__j)
            _d_ift4__j = _d_D__j*_pd__250 + _d_iPsi4__j*_pd__251
            _d_ifq4__j = _d_D__j*_pd__252 + _d_P4__j*_pd__253 + _d_iPsi4__j*_pd__254 + _d_isigma4__j*_pd__255
            _d_ifp4__j = _d_D__j*_pd__256 + _d_Q4__j*_pd__257 + _d_iPsi4__j*_pd__258 + _d_isigma4__j*_pd__259
            _d_iPsi5__j = (0.003959513229722528*_d_iF0__j + 0.029703284805013122*_d_iF1__j
                + 0.10140664131431479*_d_iF2__j + 0.14531313573962065*_d_iF3__j
                + 0.17612158869639333*_d_iF4__j + 0.04349583621493557*_d_iF5__j)
            _d_ift5__j = _d_D__j*_pd__260 + _d_iPsi5__j*_pd__261
            _d_ifq5__j = _d_D__j*_pd__262 + _d_P5__j*_pd__263 + _d_iPsi5__j*_pd__264 + _d_isigma5__j*_pd__265
            _d_ifp5__j = _d_D__j*_pd__266 + _d_Q5__j*_pd__267 + _d_iPsi5__j*_pd__268 + _d_isigma5__j*_pd__269
            _T[17, _j0] = _d_iF0__j
            _T[18, _j0] = _d_iF1__j
            _T[19, _j0] = _d_iF2__j
            _T[20, _j0] = _d_iF3__j
            _T[21, _j0] = _d_iF4__j
            _T[22, _j0] = _d_iF5__j
            _T[23, _j0] = _d_ift0__j
            _T[24, _j0] = _d_ifq0__j
            _T[25, _j0] = _d_ifp0__j
            _T[26, _j0] = _d_ift1__j
            _T[27, _j0] = _d_ifq1__j
            _T[28, _j0] = _d_ifp1__j
            _T[29, _j0] = _d_ift2__j
            _T[30, _j0] = _d_ifq2__j
            _T[31, _j0] = _d_ifp2__j
            _T[32, _j0] = _d_ift3__j
            _T[33, _j0] = _d_ifq3__j
            _T[34, _j0] = _d_ifp3__j
            _T[35, _j0] = _d_ift4__j
            _T[36, _j0] = _d_ifq4__j
            _T[37, _j0] = _d_ifp4__j
            _T[38, _j0] = _d_ift5__j
            _T[39, _j0] = _d_ifq5__j
            _T[40, _j0] = _d_ifp5__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        _D__next = _D
        _Q0__next = (0.04283112309479259*_ifq0 - 0.014763725997197413*_ifq1 + 0.009325050706477751*_ifq2
            - 0.005668858049483512*_ifq3 + 0.002854433315099335*_ifq4 - 0.0008127801712647621*_ifq5 + q_th)
        _Q1__next = (0.09267349143037887*_ifq0 + 0.09019039326203465*_ifq1 - 0.020300102293239586*_ifq2
            + 0.010363156240246424*_ifq3 - 0.004887192928037671*_ifq4 + 0.0013555610554850618*_ifq5 + q_th)
        _Q2__next = (0.08224792261284387*_ifq0 + 0.196032162333245*_ifq1 + 0.11697848364317276*_ifq2
            - 0.020482527745656096*_ifq3 + 0.007989991899662336*_ifq4 - 0.002075625784866334*_ifq5 + q_th)
        _Q3__next = (0.0877378719744515*_ifq0 + 0.17239079462440696*_ifq1 + 0.25443949503200164*_ifq2
            + 0.11697848364317276*_ifq3 - 0.0156513758091757*_ifq4 + 0.0034143235767412987*_ifq5 + q_th)
        _Q4__next = (0.08430668513410011*_ifq0 + 0.18526797945210696*_ifq1 + 0.2235938110460991*_ifq2
            + 0.2542570695795851*_ifq3 + 0.09019039326203465*_ifq4 - 0.007011245240793691*_ifq5 + q_th)
        _Q5__next = (0.08647502636084993*_ifq0 + 0.17752635320896998*_ifq1 + 0.23962582533582905*_ifq2
            + 0.22463191657986778*_ifq3 + 0.19514451252126672*_ifq4 + 0.04283112309479259*_ifq5 + q_th)
        _x141 = m*q_r**2
        _x142 = _x141*q_thd
        _P0__next = (0.04283112309479259*_ifp0 - 0.014763725997197413*_ifp1 + 0.009325050706477751*_ifp2
            - 0.005668858049483512*_ifp3 + 0.002854433315099335*_ifp4 - 0.0008127801712647621*_ifp5 + _x142)
        _x143 = 2.0*m*q_r*q_thd
        _pd__270 = _x143
        _pd__271 = _x141
        _P1__next = (0.09267349143037887*_ifp0 + 0.09019039326203465*_ifp1 - 0.020300102293239586*_ifp2
            + 0.010363156240246424*_ifp3 - 0.004887192928037671*_ifp4 + 0.0013555610554850618*_ifp5 + _x142)
        _pd__272 = _x143
        _pd__273 = _x141
        _P2__next = (0.08224792261284387*_ifp0 + 0.196032162333245*_ifp1 + 0.11697848364317276*_ifp2
            - 0.020482527745656096*_ifp3 + 0.007989991899662336*_ifp4 - 0.002075625784866334*_ifp5 + _x142)
        _pd__274 = _x143
        _pd__275 = _x141
        _P3__next = (0.0877378719744515*_ifp0 + 0.17239079462440696*_ifp1 + 0.25443949503200164*_ifp2
            + 0.11697848364317276*_ifp3 - 0.0156513758091757*_ifp4 + 0.0034143235767412987*_ifp5 + _x142)
        _pd__276 = _x143
        _pd__277 = _x141
        _P4__next = (0.08430668513410011*_ifp0 + 0.18526797945210696*_ifp1 + 0.2235938110460991*_ifp2
            + 0.2542570695795851*_ifp3 + 0.09019039326203465*_ifp4 - 0.007011245240793691*_ifp5 + _x142)
        _pd__278 = _x143
        _pd__279 = _x141
        _P5__next = (0.08647502636084993*_ifp0 + 0.17752635320896998*_ifp1 + 0.23962582533582905*_ifp2
            + 0.22463191657986778*_ifp3 + 0.19514451252126672*_ifp4 + 0.04283112309479259*_ifp5 + _x142)
        _pd__280 = _x143
        _pd__281 = _x141
        # the next state's tangents, once per direction
        for _j1 in range(6):
            d_q_r__j = _T[1, _j1]
            d_q_th__j = _T[2, _j1]
            d_q_thd__j = _T[3, _j1]
            _d_D__j = _T[4, _j1]
            _d_ifq0__j = _T[24, _j1]
            _d_ifp0__j = _T[25, _j1]
            _d_ifq1__j = _T[27, _j1]
            _d_ifp1__j = _T[28, _j1]
            _d_ifq2__j = _T[30, _j1]
            _d_ifp2__j = _T[31, _j1]
            _d_ifq3__j = _T[33, _j1]
            _d_ifp3__j = _T[34, _j1]
            _d_ifq4__j = _T[36, _j1]
            _d_ifp4__j = _T[37, _j1]
            _d_ifq5__j = _T[39, _j1]
            _d_ifp5__j = _T[40, _j1]
            # next values
            _d_Q0__next__j = (0.04283112309479259*_d_ifq0__j - 0.014763725997197413*_d_ifq1__j
                + 0.009325050706477751*_d_ifq2__j - 0.005668858049483512*_d_ifq3__j
                + 0.002854433315099335*_d_ifq4__j - 0.0008127801712647621*_d_ifq5__j + d_q_th__j)
            _d_Q1__next__j = (0.09267349143037887*_d_ifq0__j + 0.09019039326203465*_d_ifq1__j
                - 0.020300102293239586*_d_ifq2__j + 0.010363156240246424*_d_ifq3__j
                - 0.004887192928037671*_d_ifq4__j + 0.0013555610554850618*_d_ifq5__j + d_q_th__j)
            _d_Q2__next__j = (0.08224792261284387*_d_ifq0__j + 0.196032162333245*_d_ifq1__j
                + 0.11697848364317276*_d_ifq2__j - 0.020482527745656096*_d_ifq3__j
                + 0.007989991899662336*_d_ifq4__j - 0.002075625784866334*_d_ifq5__j + d_q_th__j)
            _d_Q3__next__j = (0.0877378719744515*_d_ifq0__j + 0.17239079462440696*_d_ifq1__j
                + 0.25443949503200164*_d_ifq2__j + 0.11697848364317276*_d_ifq3__j
                - 0.0156513758091757*_d_ifq4__j + 0.0034143235767412987*_d_ifq5__j + d_q_th__j)
            _d_Q4__next__j = (0.08430668513410011*_d_ifq0__j + 0.18526797945210696*_d_ifq1__j
                + 0.2235938110460991*_d_ifq2__j + 0.2542570695795851*_d_ifq3__j
                + 0.09019039326203465*_d_ifq4__j - 0.007011245240793691*_d_ifq5__j + d_q_th__j)
            _d_Q5__next__j = (0.08647502636084993*_d_ifq0__j + 0.17752635320896998*_d_ifq1__j
                + 0.23962582533582905*_d_ifq2__j + 0.22463191657986778*_d_ifq3__j
                + 0.19514451252126672*_d_ifq4__j + 0.04283112309479259*_d_ifq5__j + d_q_th__j)
            _d_P0__next__j = (0.04283112309479259*_d_ifp0__j - 0.014763725997197413*_d_ifp1__j
                + 0.009325050706477751*_d_ifp2__j - 0.005668858049483512*_d_ifp3__j
                + 0.002854433315099335*_d_ifp4__j - 0.0008127801712647621*_d_ifp5__j + _pd__270*d_q_r__j
                + _pd__271*d_q_thd__j)
            _d_P1__next__j = (0.09267349143037887*_d_ifp0__j + 0.09019039326203465*_d_ifp1__j
                - 0.020300102293239586*_d_ifp2__j + 0.010363156240246424*_d_ifp3__j
                - 0.004887192928037671*_d_ifp4__j + 0.0013555610554850618*_d_ifp5__j + _pd__272*d_q_r__j
                + _pd__273*d_q_thd__j)
            _d_P2__next__j = (0.08224792261284387*_d_ifp0__j + 0.196032162333245*_d_ifp1__j
                + 0.11697848364317276*_d_ifp2__j - 0.020482527745656096*_d_ifp3__j
                + 0.007989991899662336*_d_ifp4__j - 0.002075625784866334*_d_ifp5__j + _pd__274*d_q_r__j
                + _pd__275*d_q_thd__j)
            _d_P3__next__j = (0.0877378719744515*_d_ifp0__j + 0.17239079462440696*_d_ifp1__j
                + 0.25443949503200164*_d_ifp2__j + 0.11697848364317276*_d_ifp3__j
                - 0.0156513758091757*_d_ifp4__j + 0.0034143235767412987*_d_ifp5__j + _pd__276*d_q_r__j
                + _pd__277*d_q_thd__j)
            _d_P4__next__j = (0.08430668513410011*_d_ifp0__j + 0.18526797945210696*_d_ifp1__j
                + 0.2235938110460991*_d_ifp2__j + 0.2542570695795851*_d_ifp3__j
                + 0.09019039326203465*_d_ifp4__j - 0.007011245240793691*_d_ifp5__j + _pd__278*d_q_r__j
                + _pd__279*d_q_thd__j)
            _d_P5__next__j = (0.08647502636084993*_d_ifp0__j + 0.17752635320896998*_d_ifp1__j
                + 0.23962582533582905*_d_ifp2__j + 0.22463191657986778*_d_ifp3__j
                + 0.19514451252126672*_d_ifp4__j + 0.04283112309479259*_d_ifp5__j + _pd__280*d_q_r__j
                + _pd__281*d_q_thd__j)
            _T[4, _j1] = _d_D__j
            _T[5, _j1] = _d_Q0__next__j
            _T[6, _j1] = _d_Q1__next__j
            _T[7, _j1] = _d_Q2__next__j
            _T[8, _j1] = _d_Q3__next__j
            _T[9, _j1] = _d_Q4__next__j
            _T[10, _j1] = _d_Q5__next__j
            _T[11, _j1] = _d_P0__next__j
            _T[12, _j1] = _d_P1__next__j
            _T[13, _j1] = _d_P2__next__j
            _T[14, _j1] = _d_P3__next__j
            _T[15, _j1] = _d_P4__next__j
            _T[16, _j1] = _d_P5__next__j
        _n0_0 = _D__next
        _n0_1 = _Q0__next
        _n0_2 = _Q1__next
        _n0_3 = _Q2__next
        _n0_4 = _Q3__next
        _n0_5 = _Q4__next
        _n0_6 = _Q5__next
        _n0_7 = _P0__next
        _n0_8 = _P1__next
        _n0_9 = _P2__next
        _n0_10 = _P3__next
        _n0_11 = _P4__next
        _n0_12 = _P5__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - _D) <= tol*(l0)) and (abs(_n0_1 - _Q0) <= tol*(1.0))
            and (abs(_n0_2 - _Q1) <= tol*(1.0)) and (abs(_n0_3 - _Q2) <= tol*(1.0)) and (abs(_n0_4 - _Q3)
            <= tol*(1.0)) and (abs(_n0_5 - _Q4) <= tol*(1.0)) and (abs(_n0_6 - _Q5) <= tol*(1.0))
            and (abs(_n0_7 - _P0) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_8
            - _P1) <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_9 - _P2)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_10 - _P3)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_11 - _P4)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))) and (abs(_n0_12 - _P5)
            <= tol*(math.sqrt(g_s)*l0**(1.5)*m + m*q_r**2*abs(q_thd))))
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
        _passes += 1.0
    _work = (0.0028924065498159377*_iF0 + 0.030555658668093604*_iF1 + 0.08906517308699231*_iF2
        + 0.14489179419935322*_iF3 + 0.1498251278559757*_iF4 + 0.08276983963976924*_iF5)
    # p_r_lo^2 = 4 m D int_0^1 F_r u du > 0
    if not ((_work > 0.0)):
        return _NAN30 + (STATUS_NO_LIFTOFF,)
    # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
    t_half = (0.08566224618958518*_ift0 + 0.1803807865240693*_ift1 + 0.23395696728634552*_ift2
        + 0.23395696728634552*_ift3 + 0.1803807865240693*_ift4 + 0.08566224618958518*_ift5)
    end_q_th = (0.08566224618958518*_ifq0 + 0.1803807865240693*_ifq1 + 0.23395696728634552*_ifq2
        + 0.23395696728634552*_ifq3 + 0.1803807865240693*_ifq4 + 0.08566224618958518*_ifq5 + q_th)
    end_q_r = q_r_lo
    _x144 = math.sqrt(_D*_work)/math.sqrt(m)
    end_q_rd = 2.0*_x144
    _pd__282 = _x144/_D
    _pd__283 = _x144/_work
    _x145 = q_r**2
    _x146 = q_r_lo**-2
    _x147 = _x146/m
    end_q_thd = (_x147*(0.08566224618958518*_ifp0 + 0.1803807865240693*_ifp1 + 0.23395696728634552*_ifp2
        + 0.23395696728634552*_ifp3 + 0.1803807865240693*_ifp4 + 0.08566224618958518*_ifp5 + _x145*m*q_thd))
    _x148 = 0.08566224618958518*_x147
    _pd__284 = _x148
    _x149 = 0.1803807865240693*_x147
    _pd__285 = _x149
    _x150 = 0.23395696728634552*_x147
    _pd__286 = _x150
    _pd__287 = _x150
    _pd__288 = _x149
    _pd__289 = _x148
    _pd__290 = 2.0*_x146*q_r*q_thd
    _pd__291 = _x145*_x146
    passes = _passes
    # their tangents, once per direction
    for _j2 in range(6):
        d_q_r__j = _T[1, _j2]
        d_q_th__j = _T[2, _j2]
        d_q_thd__j = _T[3, _j2]
        _d_D__j = _T[4, _j2]
        _d_iF0__j = _T[17, _j2]
        _d_iF1__j = _T[18, _j2]
        _d_iF2__j = _T[19, _j2]
        _d_iF3__j = _T[20, _j2]
        _d_iF4__j = _T[21, _j2]
        _d_iF5__j = _T[22, _j2]
        _d_ift0__j = _T[23, _j2]
        _d_ifq0__j = _T[24, _j2]
        _d_ifp0__j = _T[25, _j2]
        _d_ift1__j = _T[26, _j2]
        _d_ifq1__j = _T[27, _j2]
        _d_ifp1__j = _T[28, _j2]
        _d_ift2__j = _T[29, _j2]
        _d_ifq2__j = _T[30, _j2]
        _d_ifp2__j = _T[31, _j2]
        _d_ift3__j = _T[32, _j2]
        _d_ifq3__j = _T[33, _j2]
        _d_ifp3__j = _T[34, _j2]
        _d_ift4__j = _T[35, _j2]
        _d_ifq4__j = _T[36, _j2]
        _d_ifp4__j = _T[37, _j2]
        _d_ift5__j = _T[38, _j2]
        _d_ifq5__j = _T[39, _j2]
        _d_ifp5__j = _T[40, _j2]
        _d_work__j = (0.0028924065498159377*_d_iF0__j + 0.030555658668093604*_d_iF1__j
            + 0.08906517308699231*_d_iF2__j + 0.14489179419935322*_d_iF3__j + 0.1498251278559757*_d_iF4__j
            + 0.08276983963976924*_d_iF5__j)
        # liftoff state: p_r_lo^2 = 2 m int F_r (work form)
        d_t_half__j = (0.08566224618958518*_d_ift0__j + 0.1803807865240693*_d_ift1__j
            + 0.23395696728634552*_d_ift2__j + 0.23395696728634552*_d_ift3__j + 0.1803807865240693*_d_ift4__j
            + 0.08566224618958518*_d_ift5__j)
        d_end_q_th__j = (0.08566224618958518*_d_ifq0__j + 0.1803807865240693*_d_ifq1__j
            + 0.23395696728634552*_d_ifq2__j + 0.23395696728634552*_d_ifq3__j + 0.1803807865240693*_d_ifq4__j
            + 0.08566224618958518*_d_ifq5__j + d_q_th__j)
        d_end_q_rd__j = _d_D__j*_pd__282 + _d_work__j*_pd__283
        d_end_q_thd__j = (_d_ifp0__j*_pd__284 + _d_ifp1__j*_pd__285 + _d_ifp2__j*_pd__286
            + _d_ifp3__j*_pd__287 + _d_ifp4__j*_pd__288 + _d_ifp5__j*_pd__289 + _pd__290*d_q_r__j
            + _pd__291*d_q_thd__j)
        _T[41, _j2] = d_t_half__j
        _T[42, _j2] = d_end_q_th__j
        _T[43, _j2] = d_end_q_rd__j
        _T[44, _j2] = d_end_q_thd__j
    (d_t_half__q_r, d_t_half__q_th, d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th,
        d_t_half__guess_q_thd, ) = (_T[41, 0], _T[41, 1], _T[41, 2], _T[41, 3], _T[41, 4], _T[41, 5], )
    (d_end_q_th__q_r, d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
        d_end_q_th__guess_q_thd, ) = (_T[42, 0], _T[42, 1], _T[42, 2], _T[42, 3], _T[42, 4], _T[42, 5], )
    (d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, ) = (_T[43, 0], _T[43, 1], _T[43, 2], _T[43, 3], _T[43, 4], _T[43, 5], )
    (d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th,
        d_end_q_thd__guess_q_thd, ) = (_T[44, 0], _T[44, 1], _T[44, 2], _T[44, 3], _T[44, 4], _T[44, 5], )
    # (internal helper: its callers check that their outputs are finite)
    return (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
        d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
        d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th, d_end_q_th__guess_q_thd,
        d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d, d_end_q_rd__guess_q_th,
        d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th, d_end_q_thd__q_thd, d_end_q_thd__k_d,
        d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, STATUS_OK)


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
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
            d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
            d_end_q_th__guess_q_thd, d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d,
            d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
            d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, _) = _c0
    elif nodes == 1.0:
        # branch nodes = 1
        _c1 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_1(g_s, guess_q_th,
            guess_q_thd, iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol))
        if _c1[30] != STATUS_OK:
            return _NAN42 + (_c1[30],)
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
            d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
            d_end_q_th__guess_q_thd, d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d,
            d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
            d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, _) = _c1
    elif nodes == 2.0:
        # branch nodes = 2
        _c2 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_2(g_s, guess_q_th,
            guess_q_thd, iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol))
        if _c2[30] != STATUS_OK:
            return _NAN42 + (_c2[30],)
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
            d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
            d_end_q_th__guess_q_thd, d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d,
            d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
            d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, _) = _c2
    elif nodes == 3.0:
        # branch nodes = 3
        _c3 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_3(g_s, guess_q_th,
            guess_q_thd, iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol))
        if _c3[30] != STATUS_OK:
            return _NAN42 + (_c3[30],)
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
            d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
            d_end_q_th__guess_q_thd, d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d,
            d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
            d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, _) = _c3
    elif nodes == 4.0:
        # branch nodes = 4
        _c4 = (schwind_decompression_jac_q_r_q_th_q_thd_k_d_guess_q_th_guess_q_thd_4(g_s, guess_q_th,
            guess_q_thd, iterations, k_d, l0, m, q_r, q_r_lo, q_th, q_thd, tol))
        if _c4[30] != STATUS_OK:
            return _NAN42 + (_c4[30],)
        (t_half, end_q_th, end_q_r, end_q_rd, end_q_thd, passes, d_t_half__q_r, d_t_half__q_th,
            d_t_half__q_thd, d_t_half__k_d, d_t_half__guess_q_th, d_t_half__guess_q_thd, d_end_q_th__q_r,
            d_end_q_th__q_th, d_end_q_th__q_thd, d_end_q_th__k_d, d_end_q_th__guess_q_th,
            d_end_q_th__guess_q_thd, d_end_q_rd__q_r, d_end_q_rd__q_th, d_end_q_rd__q_thd, d_end_q_rd__k_d,
            d_end_q_rd__guess_q_th, d_end_q_rd__guess_q_thd, d_end_q_thd__q_r, d_end_q_thd__q_th,
            d_end_q_thd__q_thd, d_end_q_thd__k_d, d_end_q_thd__guess_q_th, d_end_q_thd__guess_q_thd, _) = _c4
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
