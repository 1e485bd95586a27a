# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative_report.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight_jacobian.py sha256:4de4ff5a5b5282af
#   geyer_vs_jacobian.py sha256:9f039010262c20f7
#   iterative_jacobian.py sha256:db63ce5dd50fcaf8
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module iterative_report: JVP kernels, and
for a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate,
    liftoff_to_apex_jac_q_rd_q_th_q_thd)
from .geyer_vs_jacobian import bottom_quartic_jac_p_b_E_ab_k_c
from .iterative_jacobian import (zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    zeroth_geyer_vs_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    zeroth_gravity_type0_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    zeroth_gravity_type1_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    zeroth_gravity_type2_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    zeroth_gravity_type3_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    zeroth_gravity_type4_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    zeroth_gravity_type5_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d,
    zeroth_held_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d)

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_NUMERICAL_RANGE, STATUS_IMAGINARY_MOMENTUM)

NAN = math.nan


@njit(cache=True, error_model="numpy")
def report_compression_jvp6_4eaacb(_a, out):
    """Schwind and Koditschek's iteration as printed, compression half from a zeroth iterate's bottom, and the
    derivatives of its outputs along 6 directions (d_<argument>__<j>: direction j's component along an
    argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`iterative_report.report_compression`, in its order; then the components
    d_<argument>__<j> of each direction j (0 to 5) along z_b_q_r, z_b_q_th, z_b_q_thd.

    Writes into out:
        <output>: each output of :func:`iterative_report.report_compression`, in its order
        d_<output>__<direction>: d output / d direction for each output above and direction 0, 1, 2, 3, 4, 5
            (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 760
    (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th, z_b_q_thd, variant, iterations,
        bottom_length, d_z_b_q_r__0, d_z_b_q_th__0, d_z_b_q_thd__0, d_z_b_q_r__1, d_z_b_q_th__1,
        d_z_b_q_thd__1, d_z_b_q_r__2, d_z_b_q_th__2, d_z_b_q_thd__2, d_z_b_q_r__3, d_z_b_q_th__3,
        d_z_b_q_thd__3, d_z_b_q_r__4, d_z_b_q_th__4, d_z_b_q_thd__4, d_z_b_q_r__5, d_z_b_q_th__5,
        d_z_b_q_thd__5,) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20,
        21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31))
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # E_ab (114) of the touchdown state
    _x0 = k_c*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*l0 + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__0 = _x0 + _x5 + _x6*q_r_td - k_c*l0
    d_E_ab__1 = m*q_rd_td
    d_E_ab__2 = -_x4*q_r_td*math.sin(q_th_td)
    d_E_ab__3 = _x2*m*q_thd_td
    d_E_ab__4 = _x1 + _x3 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__0 = d_z_b_q_r__0
        d_bottom_q_r__1 = d_z_b_q_r__1
        d_bottom_q_r__2 = d_z_b_q_r__2
        d_bottom_q_r__3 = d_z_b_q_r__3
        d_bottom_q_r__4 = d_z_b_q_r__4
        d_bottom_q_r__5 = d_z_b_q_r__5
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c0 = bottom_quartic_jac_p_b_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c0[4] != STATUS_OK:
            return fail(out, _c0[4])
        bottom_q_r = _c0[0]
        _j_bottom_q_r__p_b = _c0[1]
        _j_bottom_q_r__E_ab = _c0[2]
        _j_bottom_q_r__k_c = _c0[3]
        # chain rule through bottom_quartic
        _x7 = _j_bottom_q_r__p_b*m
        d_bottom_q_r__0 = _j_bottom_q_r__E_ab*d_E_ab__0 + 2.0*_x7*q_r_td*q_thd_td
        d_bottom_q_r__1 = _j_bottom_q_r__E_ab*d_E_ab__1
        d_bottom_q_r__2 = _j_bottom_q_r__E_ab*d_E_ab__2
        d_bottom_q_r__3 = _j_bottom_q_r__E_ab*d_E_ab__3 + _x7*q_r_td**2
        d_bottom_q_r__4 = _j_bottom_q_r__E_ab*d_E_ab__4 + _j_bottom_q_r__k_c
        # tangents as every branch names them
        d_bottom_q_r__5 = 0.0
    else:
        return fail(out, STATUS_INVALID_INPUT)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return fail(out, STATUS_FALL)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = bottom_q_r - q_r_td
    _x10 = _x8*_x9
    c_e_n = _x10
    _pd__0 = _x8
    _x11 = -_x8
    d_c_e_n__0 = _pd__0*d_bottom_q_r__0 + _x11
    d_c_e_n__1 = _pd__0*d_bottom_q_r__1
    d_c_e_n__2 = _pd__0*d_bottom_q_r__2
    d_c_e_n__3 = _pd__0*d_bottom_q_r__3
    d_c_e_n__4 = _pd__0*d_bottom_q_r__4
    d_c_e_n__5 = _pd__0*d_bottom_q_r__5
    _x12 = (0.25)*_x10
    c_e_z = _x12
    _x13 = _x12 + q_r_td
    _x14 = _x13**2
    _x15 = (1.0/_x14)
    _x16 = _x13**4*m
    _x17 = _x13**3
    _x18 = l0**2*m
    _x19 = _x14*_x18
    _x20 = z_b_q_r**2
    _x21 = _x20*m
    _x22 = _x21*z_b_q_thd
    _x23 = (0.25)*_x8
    _x24 = math.sqrt(1.0 - _x23)
    _x25 = m*q_r_td**2
    _x26 = -_x22 + _x25*q_thd_td
    _x27 = _x22 + _x24*_x26
    _x28 = m**2
    _x29 = q_th_td - z_b_q_th
    _x30 = _x24*_x29 + z_b_q_th
    _x31 = _x28*g_s*math.cos(_x30)
    _x32 = 2.0*E_ab*_x14*m - _x16*k_c - 2.0*_x17*_x31 + 2.0*_x17*k_c*l0*m - _x19*k_c - _x27**2
    _x33 = _x15*_x32
    c_rad_z = _x33
    _x34 = (1.0/_x24)
    _x35 = (1.0/_x9)
    _x36 = _x29*_x35
    _x37 = _x28*g_s*math.sin(_x30)
    _x38 = _x17*_x34*_x36*_x37
    _x39 = _x23*_x38
    _x40 = _x26*_x35
    _x41 = _x34*_x40
    _pd__1 = _x15*(-_x23*_x27*_x41 + _x39)
    _x42 = -2.0*_x32/_x17
    _x43 = 2.0*q_r_td
    _x44 = (0.5)*_x10
    _x45 = _x43 + _x44
    _x46 = 4.0*m
    _x47 = -2.0*E_ab*_x45*m + 6.0*_x14*_x31 - 6.0*_x14*k_c*l0*m + _x17*_x46*k_c + _x18*_x45*k_c
    _pd__2 = _x15*(_x26*_x27*_x34*_x35 - _x38 - _x47) + _x42
    _x48 = z_b_q_r*z_b_q_thd
    _x49 = _x15*_x27
    _pd__3 = -_x49*(-_x24*_x46*_x48 + 4.0*m*z_b_q_r*z_b_q_thd)
    _x50 = 2.0*_x13*_x37
    _pd__4 = _x50*(1.0 - _x24)
    _pd__5 = -_x49*(2.0*_x20*m - 2.0*_x21*_x24)
    _x51 = (0.25)*_pd__2
    _x52 = 2.0*m
    d_c_rad_z__0 = (_pd__1*d_bottom_q_r__0 + _pd__3*d_z_b_q_r__0 + _pd__4*d_z_b_q_th__0
        + _pd__5*d_z_b_q_thd__0 + _x15*(-_x27*(-_x23*_x41 + _x24*_x46*q_r_td*q_thd_td) - _x39 - _x47) + _x42
        + _x51*d_c_e_n__0 + _x52*d_E_ab__0)
    d_c_rad_z__1 = (_pd__1*d_bottom_q_r__1 + _pd__3*d_z_b_q_r__1 + _pd__4*d_z_b_q_th__1
        + _pd__5*d_z_b_q_thd__1 + _x51*d_c_e_n__1 + _x52*d_E_ab__1)
    d_c_rad_z__2 = (_pd__1*d_bottom_q_r__2 + _pd__3*d_z_b_q_r__2 + _pd__4*d_z_b_q_th__2
        + _pd__5*d_z_b_q_thd__2 + _x24*_x50 + _x51*d_c_e_n__2 + _x52*d_E_ab__2)
    d_c_rad_z__3 = (_pd__1*d_bottom_q_r__3 + _pd__3*d_z_b_q_r__3 + _pd__4*d_z_b_q_th__3
        + _pd__5*d_z_b_q_thd__3 - 2.0*_x24*_x25*_x49 + _x51*d_c_e_n__3 + _x52*d_E_ab__3)
    d_c_rad_z__4 = (_pd__1*d_bottom_q_r__4 + _pd__3*d_z_b_q_r__4 + _pd__4*d_z_b_q_th__4
        + _pd__5*d_z_b_q_thd__4 + _x15*(-_x16 + 2.0*_x17*l0*m - _x19) + _x51*d_c_e_n__4 + _x52*d_E_ab__4)
    d_c_rad_z__5 = (_pd__1*d_bottom_q_r__5 + _pd__3*d_z_b_q_r__5 + _pd__4*d_z_b_q_th__5
        + _pd__5*d_z_b_q_thd__5 + _x51*d_c_e_n__5)
    _x53 = math.sqrt(_x11 + 1.0)
    c_Q0 = _x29*_x53 + z_b_q_th
    _x54 = (0.5)/_x53
    _x55 = _x36*_x54
    _x56 = _x55*_x8
    _pd__6 = _x56
    _pd__7 = -_x55
    _pd__8 = 1.0 - _x53
    d_c_Q0__0 = _pd__6*d_bottom_q_r__0 + _pd__7*d_c_e_n__0 + _pd__8*d_z_b_q_th__0 - _x56
    d_c_Q0__1 = _pd__6*d_bottom_q_r__1 + _pd__7*d_c_e_n__1 + _pd__8*d_z_b_q_th__1
    d_c_Q0__2 = _pd__6*d_bottom_q_r__2 + _pd__7*d_c_e_n__2 + _pd__8*d_z_b_q_th__2 + _x53
    d_c_Q0__3 = _pd__6*d_bottom_q_r__3 + _pd__7*d_c_e_n__3 + _pd__8*d_z_b_q_th__3
    d_c_Q0__4 = _pd__6*d_bottom_q_r__4 + _pd__7*d_c_e_n__4 + _pd__8*d_z_b_q_th__4
    d_c_Q0__5 = _pd__6*d_bottom_q_r__5 + _pd__7*d_c_e_n__5 + _pd__8*d_z_b_q_th__5
    c_P0 = _x22 + _x26*_x53
    _x57 = _x40*_x54
    _x58 = _x57*_x8
    _pd__9 = _x58
    _pd__10 = -_x57
    _pd__11 = -_x48*_x52*_x53 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__12 = _x20*m - _x21*_x53
    d_c_P0__0 = (_pd__10*d_c_e_n__0 + _pd__11*d_z_b_q_r__0 + _pd__12*d_z_b_q_thd__0 + _pd__9*d_bottom_q_r__0
        + _x43*_x53*m*q_thd_td - _x58)
    d_c_P0__1 = _pd__10*d_c_e_n__1 + _pd__11*d_z_b_q_r__1 + _pd__12*d_z_b_q_thd__1 + _pd__9*d_bottom_q_r__1
    d_c_P0__2 = _pd__10*d_c_e_n__2 + _pd__11*d_z_b_q_r__2 + _pd__12*d_z_b_q_thd__2 + _pd__9*d_bottom_q_r__2
    d_c_P0__3 = (_pd__10*d_c_e_n__3 + _pd__11*d_z_b_q_r__3 + _pd__12*d_z_b_q_thd__3 + _pd__9*d_bottom_q_r__3
        + _x25*_x53)
    d_c_P0__4 = _pd__10*d_c_e_n__4 + _pd__11*d_z_b_q_r__4 + _pd__12*d_z_b_q_thd__4 + _pd__9*d_bottom_q_r__4
    d_c_P0__5 = _pd__10*d_c_e_n__5 + _pd__11*d_z_b_q_r__5 + _pd__12*d_z_b_q_thd__5 + _pd__9*d_bottom_q_r__5
    _x59 = m/math.sqrt(_x33)
    _x60 = (_x33 > 0.0)
    c_T0 = ((-_x10*_x59) if _x60 else (0.0))
    _pd__13 = ((-_x59) if _x60 else (0.0))
    _pd__14 = ((_x44*m/(_x33*math.sqrt(_x33))) if _x60 else (0.0))
    d_c_T0__0 = _pd__13*d_c_e_n__0 + _pd__14*d_c_rad_z__0
    d_c_T0__1 = _pd__13*d_c_e_n__1 + _pd__14*d_c_rad_z__1
    d_c_T0__2 = _pd__13*d_c_e_n__2 + _pd__14*d_c_rad_z__2
    d_c_T0__3 = _pd__13*d_c_e_n__3 + _pd__14*d_c_rad_z__3
    d_c_T0__4 = _pd__13*d_c_e_n__4 + _pd__14*d_c_rad_z__4
    d_c_T0__5 = _pd__13*d_c_e_n__5 + _pd__14*d_c_rad_z__5
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return fail(out, STATUS_IMAGINARY_MOMENTUM)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__0, d_c_e_n__1, d_c_e_n__2, d_c_e_n__3, d_c_e_n__4, d_c_e_n__5,
        d_c_Q0__0, d_c_Q0__1, d_c_Q0__2, d_c_Q0__3, d_c_Q0__4, d_c_Q0__5, d_c_P0__0, d_c_P0__1, d_c_P0__2,
        d_c_P0__3, d_c_P0__4, d_c_P0__5, d_c_T0__0, d_c_T0__1, d_c_T0__2, d_c_T0__3, d_c_T0__4, d_c_T0__5, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__0, d_c_e__1, d_c_e__2, d_c_e__3, d_c_e__4, d_c_e__5, d_c_Q__0, d_c_Q__1,
            d_c_Q__2, d_c_Q__3, d_c_Q__4, d_c_Q__5, d_c_P__0, d_c_P__1, d_c_P__2, d_c_P__3, d_c_P__4,
            d_c_P__5, d_c_T__0, d_c_T__1, d_c_T__2, d_c_T__3, d_c_T__4, d_c_T__5, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x61 = c_e + q_r_td
        c_x = _x61
        d_c_x__0 = d_c_e__0 + 1.0
        _x62 = _x61**2
        _x63 = (1.0/_x62)
        _x64 = _x61**4*m
        _x65 = _x61**3
        _x66 = l0**2
        _x67 = _x62*_x66*m
        _x68 = math.cos(c_Q)
        _x69 = m**2
        _x70 = 2.0*_x69*g_s
        _x71 = 2.0*E_ab*_x62*m - _x64*k_c - _x65*_x68*_x70 + 2.0*_x65*k_c*l0*m - _x67*k_c - c_P**2
        c_rad = _x63*_x71
        _pd__15 = -2.0*_x63*c_P
        _pd__16 = _x61*_x70*math.sin(c_Q)
        _x72 = 2.0*m
        _pd__17 = (_x63*(4.0*E_ab*_x61*m - _x61*_x66*_x72*k_c - 6.0*_x62*_x68*_x69*g_s + 6.0*_x62*k_c*l0*m
            - 4.0*_x65*k_c*m) - 2.0*_x71/_x65)
        d_c_rad__0 = _pd__15*d_c_P__0 + _pd__16*d_c_Q__0 + _pd__17*d_c_x__0 + _x72*d_E_ab__0
        d_c_rad__1 = _pd__15*d_c_P__1 + _pd__16*d_c_Q__1 + _pd__17*d_c_e__1 + _x72*d_E_ab__1
        d_c_rad__2 = _pd__15*d_c_P__2 + _pd__16*d_c_Q__2 + _pd__17*d_c_e__2 + _x72*d_E_ab__2
        d_c_rad__3 = _pd__15*d_c_P__3 + _pd__16*d_c_Q__3 + _pd__17*d_c_e__3 + _x72*d_E_ab__3
        d_c_rad__4 = (_pd__15*d_c_P__4 + _pd__16*d_c_Q__4 + _pd__17*d_c_e__4 + _x63*(-_x64 + 2.0*_x65*l0*m
            - _x67) + _x72*d_E_ab__4)
        d_c_rad__5 = _pd__15*d_c_P__5 + _pd__16*d_c_Q__5 + _pd__17*d_c_e__5
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return fail(out, STATUS_IMAGINARY_MOMENTUM)
        _x73 = math.sqrt(c_rad)
        c_h = _x73
        _pd__18 = (0.5)/_x73
        d_c_h__0 = _pd__18*d_c_rad__0
        d_c_h__1 = _pd__18*d_c_rad__1
        d_c_h__2 = _pd__18*d_c_rad__2
        d_c_h__3 = _pd__18*d_c_rad__3
        d_c_h__4 = _pd__18*d_c_rad__4
        d_c_h__5 = _pd__18*d_c_rad__5
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x77 = (1.0/c_x)
            _x74 = _x77**2
            c_wq = _x74*c_e_next
            _pd__19 = _x74
            _pd__20 = -2.0*_x77**3*c_e_next
            _x75 = 4.0*_pd__19
            d_c_wq__0 = _pd__20*d_c_x__0 + _x75*d_c_e__0
            d_c_wq__1 = _pd__20*d_c_e__1 + _x75*d_c_e__1
            d_c_wq__2 = _pd__20*d_c_e__2 + _x75*d_c_e__2
            d_c_wq__3 = _pd__20*d_c_e__3 + _x75*d_c_e__3
            d_c_wq__4 = _pd__20*d_c_e__4 + _x75*d_c_e__4
            d_c_wq__5 = _pd__20*d_c_e__5 + _x75*d_c_e__5
            c_wp = c_e_next*c_x
            _x76 = 4.0*c_x
            d_c_wp__0 = _x76*d_c_e__0 + c_e_next*d_c_x__0
            d_c_wp__1 = _x76*d_c_e__1 + c_e_next*d_c_e__1
            d_c_wp__2 = _x76*d_c_e__2 + c_e_next*d_c_e__2
            d_c_wp__3 = _x76*d_c_e__3 + c_e_next*d_c_e__3
            d_c_wp__4 = _x76*d_c_e__4 + c_e_next*d_c_e__4
            d_c_wp__5 = _x76*d_c_e__5 + c_e_next*d_c_e__5
        elif variant == 1.0:
            _x78 = (1.0/q_r_td)
            _x79 = c_e_next + q_r_td
            _x80 = (1.0/_x79)
            c_wq = _x78*_x80*c_e_next
            _x81 = _x78*_x80**2*c_e_next
            _pd__21 = _x78*_x80 - _x81
            d_c_wq__0 = 4.0*_pd__21*d_c_e__0 - _x78**2*_x80*c_e_next - _x81
            _x82 = 4.0*_pd__21
            d_c_wq__1 = _x82*d_c_e__1
            d_c_wq__2 = _x82*d_c_e__2
            d_c_wq__3 = _x82*d_c_e__3
            d_c_wq__4 = _x82*d_c_e__4
            d_c_wq__5 = _x82*d_c_e__5
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__22 = _x79
            _x83 = 4.0*_pd__22
            d_c_wp__0 = _x83*d_c_e__0 + c_e_next
            d_c_wp__1 = _x83*d_c_e__1
            d_c_wp__2 = _x83*d_c_e__2
            d_c_wp__3 = _x83*d_c_e__3
            d_c_wp__4 = _x83*d_c_e__4
            d_c_wp__5 = _x83*d_c_e__5
        else:
            return fail(out, STATUS_INVALID_INPUT)
        # next values
        c_e__next = c_e_next
        _x84 = (1.0/c_h)
        _x85 = _x84*c_wq
        c_Q__next = -_x85*c_P + q_th_td
        _pd__23 = -_x85
        _x86 = _x84**2
        _pd__24 = _x86*c_P*c_wq
        _pd__25 = -_x84*c_P
        d_c_Q__next__0 = _pd__23*d_c_P__0 + _pd__24*d_c_h__0 + _pd__25*d_c_wq__0
        d_c_Q__next__1 = _pd__23*d_c_P__1 + _pd__24*d_c_h__1 + _pd__25*d_c_wq__1
        d_c_Q__next__2 = _pd__23*d_c_P__2 + _pd__24*d_c_h__2 + _pd__25*d_c_wq__2 + 1.0
        d_c_Q__next__3 = _pd__23*d_c_P__3 + _pd__24*d_c_h__3 + _pd__25*d_c_wq__3
        d_c_Q__next__4 = _pd__23*d_c_P__4 + _pd__24*d_c_h__4 + _pd__25*d_c_wq__4
        d_c_Q__next__5 = _pd__23*d_c_P__5 + _pd__24*d_c_h__5 + _pd__25*d_c_wq__5
        _x87 = m*q_r_td**2
        _x88 = math.sin(c_Q)
        _x89 = m**2
        _x90 = _x84*_x89*g_s
        _x91 = _x88*_x90
        c_P__next = _x87*q_thd_td - _x91*c_wp
        _pd__26 = -_x90*c_wp*math.cos(c_Q)
        _pd__27 = _x86*_x88*_x89*c_wp*g_s
        _pd__28 = -_x91
        d_c_P__next__0 = _pd__26*d_c_Q__0 + _pd__27*d_c_h__0 + _pd__28*d_c_wp__0 + 2.0*m*q_r_td*q_thd_td
        d_c_P__next__1 = _pd__26*d_c_Q__1 + _pd__27*d_c_h__1 + _pd__28*d_c_wp__1
        d_c_P__next__2 = _pd__26*d_c_Q__2 + _pd__27*d_c_h__2 + _pd__28*d_c_wp__2
        d_c_P__next__3 = _pd__26*d_c_Q__3 + _pd__27*d_c_h__3 + _pd__28*d_c_wp__3 + _x87
        d_c_P__next__4 = _pd__26*d_c_Q__4 + _pd__27*d_c_h__4 + _pd__28*d_c_wp__4
        d_c_P__next__5 = _pd__26*d_c_Q__5 + _pd__27*d_c_h__5 + _pd__28*d_c_wp__5
        _x92 = _x84*m
        c_T__next = -_x92*c_e_next
        _pd__29 = -_x92
        _pd__30 = _x86*c_e_next*m
        _x93 = 4.0*_pd__29
        d_c_T__next__0 = _pd__30*d_c_h__0 + _x93*d_c_e__0
        d_c_T__next__1 = _pd__30*d_c_h__1 + _x93*d_c_e__1
        d_c_T__next__2 = _pd__30*d_c_h__2 + _x93*d_c_e__2
        d_c_T__next__3 = _pd__30*d_c_h__3 + _x93*d_c_e__3
        d_c_T__next__4 = _pd__30*d_c_h__4 + _x93*d_c_e__4
        d_c_T__next__5 = _pd__30*d_c_h__5 + _x93*d_c_e__5
        _n0_4 = 4.0*d_c_e__0
        _n0_5 = 4.0*d_c_e__1
        _n0_6 = 4.0*d_c_e__2
        _n0_7 = 4.0*d_c_e__3
        _n0_8 = 4.0*d_c_e__4
        _n0_9 = 4.0*d_c_e__5
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8, _n0_9,
            d_c_Q__next__0, d_c_Q__next__1, d_c_Q__next__2, d_c_Q__next__3, d_c_Q__next__4, d_c_Q__next__5,
            d_c_P__next__0, d_c_P__next__1, d_c_P__next__2, d_c_P__next__3, d_c_P__next__4, d_c_P__next__5,
            d_c_T__next__0, d_c_T__next__1, d_c_T__next__2, d_c_T__next__3, d_c_T__next__4, d_c_T__next__5, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_th = c_Q
    _x94 = (1.0/m)
    _x96 = (1.0/bottom_q_r)
    _x95 = _x94*_x96**2
    bottom_q_thd = _x95*c_P
    _pd__31 = -2.0*_x94*_x96**3*c_P
    _pd__32 = _x95
    d_bottom_q_thd__0 = _pd__31*d_bottom_q_r__0 + _pd__32*d_c_P__0
    d_bottom_q_thd__1 = _pd__31*d_bottom_q_r__1 + _pd__32*d_c_P__1
    d_bottom_q_thd__2 = _pd__31*d_bottom_q_r__2 + _pd__32*d_c_P__2
    d_bottom_q_thd__3 = _pd__31*d_bottom_q_r__3 + _pd__32*d_c_P__3
    d_bottom_q_thd__4 = _pd__31*d_bottom_q_r__4 + _pd__32*d_c_P__4
    d_bottom_q_thd__5 = _pd__31*d_bottom_q_r__5 + _pd__32*d_c_P__5
    # derivatives of the outputs
    d_t_bottom__0 = d_c_T__0
    d_t_bottom__1 = d_c_T__1
    d_t_bottom__2 = d_c_T__2
    d_t_bottom__3 = d_c_T__3
    d_t_bottom__4 = d_c_T__4
    d_t_bottom__5 = d_c_T__5
    d_bottom_q_th__0 = d_c_Q__0
    d_bottom_q_th__1 = d_c_Q__1
    d_bottom_q_th__2 = d_c_Q__2
    d_bottom_q_th__3 = d_c_Q__3
    d_bottom_q_th__4 = d_c_Q__4
    d_bottom_q_th__5 = d_c_Q__5
    # (internal helper: its callers check that their outputs are finite)
    store(out, (t_bottom, bottom_q_r, 0.0, bottom_q_th, bottom_q_thd, E_ab, d_t_bottom__0, d_t_bottom__1,
        d_t_bottom__2, d_t_bottom__3, d_t_bottom__4, d_t_bottom__5, d_bottom_q_r__0, d_bottom_q_r__1,
        d_bottom_q_r__2, d_bottom_q_r__3, d_bottom_q_r__4, d_bottom_q_r__5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        d_bottom_q_th__0, d_bottom_q_th__1, d_bottom_q_th__2, d_bottom_q_th__3, d_bottom_q_th__4,
        d_bottom_q_th__5, d_bottom_q_thd__0, d_bottom_q_thd__1, d_bottom_q_thd__2, d_bottom_q_thd__3,
        d_bottom_q_thd__4, d_bottom_q_thd__5, d_E_ab__0, d_E_ab__1, d_E_ab__2, d_E_ab__3, d_E_ab__4, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def report_core_jvp6_b60fdf(_a, out):
    """Schwind and Koditschek's iteration as printed: the stance from the touchdown state and a zeroth
    iterate, and the derivatives of its outputs along 6 directions (d_<argument>__<j>: direction j's component
    along an argument; the arguments not listed have a fixed component, 0 or 1).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`iterative_report.report_core`, in its order; then the components
    d_<argument>__<j> of each direction j (0 to 5) along z_b_q_r, z_b_q_th, z_b_q_thd, z_lo_q_th,
    z_lo_q_thd.

    Writes into out:
        <output>: each output of :func:`iterative_report.report_core`, in its order
        d_<output>__<direction>: d output / d direction for each output above and direction 0, 1, 2, 3, 4, 5
            (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 923
    (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, z_b_q_r, z_b_q_th, z_b_q_thd,
        z_lo_q_th, z_lo_q_thd, held, variant, iterations, bottom_length, d_z_b_q_r__0, d_z_b_q_th__0,
        d_z_b_q_thd__0, d_z_lo_q_th__0, d_z_lo_q_thd__0, d_z_b_q_r__1, d_z_b_q_th__1, d_z_b_q_thd__1,
        d_z_lo_q_th__1, d_z_lo_q_thd__1, d_z_b_q_r__2, d_z_b_q_th__2, d_z_b_q_thd__2, d_z_lo_q_th__2,
        d_z_lo_q_thd__2, d_z_b_q_r__3, d_z_b_q_th__3, d_z_b_q_thd__3, d_z_lo_q_th__3, d_z_lo_q_thd__3,
        d_z_b_q_r__4, d_z_b_q_th__4, d_z_b_q_thd__4, d_z_lo_q_th__4, d_z_lo_q_thd__4, d_z_b_q_r__5,
        d_z_b_q_th__5, d_z_b_q_thd__5, d_z_lo_q_th__5, d_z_lo_q_thd__5,) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7,
        8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33,
        34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48))
    # the compression half as printed
    _a0 = carray(stack(32), 32)
    store(_a0, (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th, z_b_q_thd, variant,
        iterations, bottom_length, d_z_b_q_r__0, d_z_b_q_th__0, d_z_b_q_thd__0, d_z_b_q_r__1, d_z_b_q_th__1,
        d_z_b_q_thd__1, d_z_b_q_r__2, d_z_b_q_th__2, d_z_b_q_thd__2, d_z_b_q_r__3, d_z_b_q_th__3,
        d_z_b_q_thd__3, d_z_b_q_r__4, d_z_b_q_th__4, d_z_b_q_thd__4, d_z_b_q_r__5, d_z_b_q_th__5,
        d_z_b_q_thd__5,))
    _o0 = carray(stack(42), 42)
    _c0 = report_compression_jvp6_4eaacb(_a0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (t_bottom, bottom_q_r, _o0_2, bottom_q_th, bottom_q_thd, E_ab, d_t_bottom__0, d_t_bottom__1,
        d_t_bottom__2, d_t_bottom__3, d_t_bottom__4, d_t_bottom__5, d_bottom_q_r__0, d_bottom_q_r__1,
        d_bottom_q_r__2, d_bottom_q_r__3, d_bottom_q_r__4, d_bottom_q_r__5, d_bottom_q_th__0,
        d_bottom_q_th__1, d_bottom_q_th__2, d_bottom_q_th__3, d_bottom_q_th__4, d_bottom_q_th__5,
        d_bottom_q_thd__0, d_bottom_q_thd__1, d_bottom_q_thd__2, d_bottom_q_thd__3, d_bottom_q_thd__4,
        d_bottom_q_thd__5, d_E_ab__0, d_E_ab__1, d_E_ab__2, d_E_ab__3, d_E_ab__4,) = (load(_o0, 0, 1, 2, 3, 4,
        5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37,
        38, 39, 40))
    # E_ba of (98): the energy jump of the stiffness switch
    _x0 = (-bottom_q_r + l0)**2
    _x1 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x0*_x1
    _pd__0 = _x1*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__0 = _pd__0*d_bottom_q_r__0 + d_E_ab__0
    d_E_ba__1 = _pd__0*d_bottom_q_r__1 + d_E_ab__1
    d_E_ba__2 = _pd__0*d_bottom_q_r__2 + d_E_ab__2
    d_E_ba__3 = _pd__0*d_bottom_q_r__3 + d_E_ab__3
    _x2 = (0.5)*_x0
    d_E_ba__4 = _pd__0*d_bottom_q_r__4 - _x2 + d_E_ab__4
    d_E_ba__5 = _pd__0*d_bottom_q_r__5 + _x2
    # zeroth iterate at liftoff
    _x3 = (held == 1.0)
    g_lo_q_th = ((bottom_q_th) if _x3 else (z_lo_q_th))
    _pd__1 = ((1.0) if _x3 else (0.0))
    _x4 = ((0.0) if _x3 else (1.0))
    _pd__2 = _x4
    d_g_lo_q_th__0 = _pd__1*d_bottom_q_th__0 + _pd__2*d_z_lo_q_th__0
    d_g_lo_q_th__1 = _pd__1*d_bottom_q_th__1 + _pd__2*d_z_lo_q_th__1
    d_g_lo_q_th__2 = _pd__1*d_bottom_q_th__2 + _pd__2*d_z_lo_q_th__2
    d_g_lo_q_th__3 = _pd__1*d_bottom_q_th__3 + _pd__2*d_z_lo_q_th__3
    d_g_lo_q_th__4 = _pd__1*d_bottom_q_th__4 + _pd__2*d_z_lo_q_th__4
    d_g_lo_q_th__5 = _pd__1*d_bottom_q_th__5 + _pd__2*d_z_lo_q_th__5
    _x5 = q_r_lo**-2
    _x6 = _x5*bottom_q_r**2
    g_lo_q_thd = ((_x6*bottom_q_thd) if _x3 else (z_lo_q_thd))
    _pd__3 = ((2.0*_x5*bottom_q_r*bottom_q_thd) if _x3 else (0.0))
    _pd__4 = ((_x6) if _x3 else (0.0))
    _pd__5 = _x4
    d_g_lo_q_thd__0 = _pd__3*d_bottom_q_r__0 + _pd__4*d_bottom_q_thd__0 + _pd__5*d_z_lo_q_thd__0
    d_g_lo_q_thd__1 = _pd__3*d_bottom_q_r__1 + _pd__4*d_bottom_q_thd__1 + _pd__5*d_z_lo_q_thd__1
    d_g_lo_q_thd__2 = _pd__3*d_bottom_q_r__2 + _pd__4*d_bottom_q_thd__2 + _pd__5*d_z_lo_q_thd__2
    d_g_lo_q_thd__3 = _pd__3*d_bottom_q_r__3 + _pd__4*d_bottom_q_thd__3 + _pd__5*d_z_lo_q_thd__3
    d_g_lo_q_thd__4 = _pd__3*d_bottom_q_r__4 + _pd__4*d_bottom_q_thd__4 + _pd__5*d_z_lo_q_thd__4
    d_g_lo_q_thd__5 = _pd__3*d_bottom_q_r__5 + _pd__4*d_bottom_q_thd__5 + _pd__5*d_z_lo_q_thd__5
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return fail(out, STATUS_NO_LIFTOFF)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x7 = 4.0**(-iterations)
    _x8 = -bottom_q_r + q_r_lo
    _x9 = _x7*_x8
    d_e_n = _x9
    _pd__6 = -_x7
    d_d_e_n__0 = _pd__6*d_bottom_q_r__0
    d_d_e_n__1 = _pd__6*d_bottom_q_r__1
    d_d_e_n__2 = _pd__6*d_bottom_q_r__2
    d_d_e_n__3 = _pd__6*d_bottom_q_r__3
    d_d_e_n__4 = _pd__6*d_bottom_q_r__4
    d_d_e_n__5 = _pd__6*d_bottom_q_r__5
    _x10 = (0.25)*_x9
    d_e_z = _x10
    _x11 = _x10 + bottom_q_r
    _x12 = _x11**2
    _x13 = (1.0/_x12)
    _x14 = _x11**4*m
    _x15 = _x11**3
    _x16 = l0**2*m
    _x17 = _x12*_x16
    _x18 = bottom_q_r**2*m
    _x19 = _x18*bottom_q_thd
    _x20 = q_r_lo**2
    _x21 = -_x19 + _x20*g_lo_q_thd*m
    _x22 = 4.0**((0.5)*iterations)
    _x23 = (1.0/_x22)
    _x24 = (0.5)*_x23
    _x25 = _x21*_x24
    _x26 = _x19 + _x25
    _x27 = -bottom_q_th + g_lo_q_th
    _x28 = _x24*_x27
    _x29 = _x28 + bottom_q_th
    _x30 = m**2
    _x31 = _x30*g_s
    _x32 = _x31*math.cos(_x29)
    _x33 = 2.0*E_ba*_x12*m - _x14*k_d - 2.0*_x15*_x32 + 2.0*_x15*k_d*l0*m - _x17*k_d - _x26**2
    _x34 = _x13*_x33
    d_rad_z = _x34
    _x35 = -2.0*_x33/_x15
    _x36 = 4.0*m
    _x37 = (1.0/_x8)
    _x38 = 2.0*bottom_q_r
    _x39 = _x38*bottom_q_thd*m
    _x40 = -_x23*_x39 + _x25*_x37
    _x41 = math.sin(_x29)
    _x42 = (0.5)*_x9
    _x43 = _x38 + _x42
    _x44 = -2.0*E_ba*_x43*m + 6.0*_x12*_x32 - 6.0*_x12*k_d*l0*m + _x15*_x36*k_d + _x16*_x43*k_d
    _pd__7 = (_x13*((0.5)*_x15*_x23*_x27*_x30*_x37*_x41*g_s - _x26*(_x36*bottom_q_r*bottom_q_thd + _x40)
        - _x44) + _x35)
    _x45 = _x11*_x31*_x41
    _pd__8 = 2.0*_x45*(1.0 - _x24)
    _x46 = -_x18*_x23
    _x47 = _x13*_x26
    _pd__9 = -_x47*(2.0*_x18 + _x46)
    _x48 = _x22*_x37
    _pd__10 = _x13*(2.0*_x15*_x22*_x27*_x30*_x37*_x41*g_s - 2.0*_x21*_x26*_x48 - _x44) + _x35
    _pd__11 = _x23*_x45
    _x49 = _x20*_x23*m
    _pd__12 = -_x47*_x49
    _x50 = (0.25)*_pd__10
    _x51 = 2.0*m
    d_d_rad_z__0 = (_pd__11*d_g_lo_q_th__0 + _pd__12*d_g_lo_q_thd__0 + _pd__7*d_bottom_q_r__0
        + _pd__8*d_bottom_q_th__0 + _pd__9*d_bottom_q_thd__0 + _x50*d_d_e_n__0 + _x51*d_E_ba__0)
    d_d_rad_z__1 = (_pd__11*d_g_lo_q_th__1 + _pd__12*d_g_lo_q_thd__1 + _pd__7*d_bottom_q_r__1
        + _pd__8*d_bottom_q_th__1 + _pd__9*d_bottom_q_thd__1 + _x50*d_d_e_n__1 + _x51*d_E_ba__1)
    d_d_rad_z__2 = (_pd__11*d_g_lo_q_th__2 + _pd__12*d_g_lo_q_thd__2 + _pd__7*d_bottom_q_r__2
        + _pd__8*d_bottom_q_th__2 + _pd__9*d_bottom_q_thd__2 + _x50*d_d_e_n__2 + _x51*d_E_ba__2)
    d_d_rad_z__3 = (_pd__11*d_g_lo_q_th__3 + _pd__12*d_g_lo_q_thd__3 + _pd__7*d_bottom_q_r__3
        + _pd__8*d_bottom_q_th__3 + _pd__9*d_bottom_q_thd__3 + _x50*d_d_e_n__3 + _x51*d_E_ba__3)
    d_d_rad_z__4 = (_pd__11*d_g_lo_q_th__4 + _pd__12*d_g_lo_q_thd__4 + _pd__7*d_bottom_q_r__4
        + _pd__8*d_bottom_q_th__4 + _pd__9*d_bottom_q_thd__4 + _x50*d_d_e_n__4 + _x51*d_E_ba__4)
    d_d_rad_z__5 = (_pd__11*d_g_lo_q_th__5 + _pd__12*d_g_lo_q_thd__5 + _pd__7*d_bottom_q_r__5
        + _pd__8*d_bottom_q_th__5 + _pd__9*d_bottom_q_thd__5 + _x13*(-_x14 + 2.0*_x15*l0*m - _x17)
        + _x50*d_d_e_n__5 + _x51*d_E_ba__5)
    d_Q0 = _x23*_x27 + bottom_q_th
    _pd__13 = _x28*_x37
    _pd__14 = 1.0 - _x23
    _x52 = (0.5)*_x48
    _pd__15 = _x27*_x52
    _pd__16 = _x23
    d_d_Q0__0 = (_pd__13*d_bottom_q_r__0 + _pd__14*d_bottom_q_th__0 + _pd__15*d_d_e_n__0
        + _pd__16*d_g_lo_q_th__0)
    d_d_Q0__1 = (_pd__13*d_bottom_q_r__1 + _pd__14*d_bottom_q_th__1 + _pd__15*d_d_e_n__1
        + _pd__16*d_g_lo_q_th__1)
    d_d_Q0__2 = (_pd__13*d_bottom_q_r__2 + _pd__14*d_bottom_q_th__2 + _pd__15*d_d_e_n__2
        + _pd__16*d_g_lo_q_th__2)
    d_d_Q0__3 = (_pd__13*d_bottom_q_r__3 + _pd__14*d_bottom_q_th__3 + _pd__15*d_d_e_n__3
        + _pd__16*d_g_lo_q_th__3)
    d_d_Q0__4 = (_pd__13*d_bottom_q_r__4 + _pd__14*d_bottom_q_th__4 + _pd__15*d_d_e_n__4
        + _pd__16*d_g_lo_q_th__4)
    d_d_Q0__5 = (_pd__13*d_bottom_q_r__5 + _pd__14*d_bottom_q_th__5 + _pd__15*d_d_e_n__5
        + _pd__16*d_g_lo_q_th__5)
    d_P0 = _x19 + _x21*_x23
    _pd__17 = _x39 + _x40
    _pd__18 = _x18 + _x46
    _pd__19 = _x21*_x52
    _pd__20 = _x49
    d_d_P0__0 = (_pd__17*d_bottom_q_r__0 + _pd__18*d_bottom_q_thd__0 + _pd__19*d_d_e_n__0
        + _pd__20*d_g_lo_q_thd__0)
    d_d_P0__1 = (_pd__17*d_bottom_q_r__1 + _pd__18*d_bottom_q_thd__1 + _pd__19*d_d_e_n__1
        + _pd__20*d_g_lo_q_thd__1)
    d_d_P0__2 = (_pd__17*d_bottom_q_r__2 + _pd__18*d_bottom_q_thd__2 + _pd__19*d_d_e_n__2
        + _pd__20*d_g_lo_q_thd__2)
    d_d_P0__3 = (_pd__17*d_bottom_q_r__3 + _pd__18*d_bottom_q_thd__3 + _pd__19*d_d_e_n__3
        + _pd__20*d_g_lo_q_thd__3)
    d_d_P0__4 = (_pd__17*d_bottom_q_r__4 + _pd__18*d_bottom_q_thd__4 + _pd__19*d_d_e_n__4
        + _pd__20*d_g_lo_q_thd__4)
    d_d_P0__5 = (_pd__17*d_bottom_q_r__5 + _pd__18*d_bottom_q_thd__5 + _pd__19*d_d_e_n__5
        + _pd__20*d_g_lo_q_thd__5)
    _x53 = m/math.sqrt(_x34)
    _x54 = (_x34 > 0.0)
    d_T0 = ((_x53*_x9 + t_bottom) if _x54 else (t_bottom))
    _pd__21 = ((_x53) if _x54 else (0.0))
    _pd__22 = ((-_x42*m/(_x34*math.sqrt(_x34))) if _x54 else (0.0))
    d_d_T0__0 = _pd__21*d_d_e_n__0 + _pd__22*d_d_rad_z__0 + d_t_bottom__0
    d_d_T0__1 = _pd__21*d_d_e_n__1 + _pd__22*d_d_rad_z__1 + d_t_bottom__1
    d_d_T0__2 = _pd__21*d_d_e_n__2 + _pd__22*d_d_rad_z__2 + d_t_bottom__2
    d_d_T0__3 = _pd__21*d_d_e_n__3 + _pd__22*d_d_rad_z__3 + d_t_bottom__3
    d_d_T0__4 = _pd__21*d_d_e_n__4 + _pd__22*d_d_rad_z__4 + d_t_bottom__4
    d_d_T0__5 = _pd__21*d_d_e_n__5 + _pd__22*d_d_rad_z__5 + d_t_bottom__5
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return fail(out, STATUS_IMAGINARY_MOMENTUM)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__0, d_d_e_n__1, d_d_e_n__2, d_d_e_n__3, d_d_e_n__4, d_d_e_n__5,
        d_d_Q0__0, d_d_Q0__1, d_d_Q0__2, d_d_Q0__3, d_d_Q0__4, d_d_Q0__5, d_d_P0__0, d_d_P0__1, d_d_P0__2,
        d_d_P0__3, d_d_P0__4, d_d_P0__5, d_d_T0__0, d_d_T0__1, d_d_T0__2, d_d_T0__3, d_d_T0__4, d_d_T0__5, )
    _pk0 = _pki0
    d_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__0, d_d_e__1, d_d_e__2, d_d_e__3, d_d_e__4, d_d_e__5, d_d_Q__0, d_d_Q__1,
            d_d_Q__2, d_d_Q__3, d_d_Q__4, d_d_Q__5, d_d_P__0, d_d_P__1, d_d_P__2, d_d_P__3, d_d_P__4,
            d_d_P__5, d_d_T__0, d_d_T__1, d_d_T__2, d_d_T__3, d_d_T__4, d_d_T__5, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x55 = bottom_q_r + d_e
        d_x = _x55
        d_d_x__0 = d_bottom_q_r__0 + d_d_e__0
        d_d_x__1 = d_bottom_q_r__1 + d_d_e__1
        d_d_x__2 = d_bottom_q_r__2 + d_d_e__2
        d_d_x__3 = d_bottom_q_r__3 + d_d_e__3
        d_d_x__4 = d_bottom_q_r__4 + d_d_e__4
        d_d_x__5 = d_bottom_q_r__5 + d_d_e__5
        _x56 = _x55**2
        _x57 = (1.0/_x56)
        _x58 = _x55**4*m
        _x59 = _x55**3
        _x60 = l0**2
        _x61 = _x56*_x60*m
        _x62 = math.cos(d_Q)
        _x63 = m**2
        _x64 = 2.0*_x63*g_s
        _x65 = 2.0*E_ba*_x56*m - _x58*k_d - _x59*_x62*_x64 + 2.0*_x59*k_d*l0*m - _x61*k_d - d_P**2
        d_rad = _x57*_x65
        _pd__23 = -2.0*_x57*d_P
        _pd__24 = _x55*_x64*math.sin(d_Q)
        _x66 = 2.0*m
        _pd__25 = (_x57*(4.0*E_ba*_x55*m - _x55*_x60*_x66*k_d - 6.0*_x56*_x62*_x63*g_s + 6.0*_x56*k_d*l0*m
            - 4.0*_x59*k_d*m) - 2.0*_x65/_x59)
        d_d_rad__0 = _pd__23*d_d_P__0 + _pd__24*d_d_Q__0 + _pd__25*d_d_x__0 + _x66*d_E_ba__0
        d_d_rad__1 = _pd__23*d_d_P__1 + _pd__24*d_d_Q__1 + _pd__25*d_d_x__1 + _x66*d_E_ba__1
        d_d_rad__2 = _pd__23*d_d_P__2 + _pd__24*d_d_Q__2 + _pd__25*d_d_x__2 + _x66*d_E_ba__2
        d_d_rad__3 = _pd__23*d_d_P__3 + _pd__24*d_d_Q__3 + _pd__25*d_d_x__3 + _x66*d_E_ba__3
        d_d_rad__4 = _pd__23*d_d_P__4 + _pd__24*d_d_Q__4 + _pd__25*d_d_x__4 + _x66*d_E_ba__4
        d_d_rad__5 = (_pd__23*d_d_P__5 + _pd__24*d_d_Q__5 + _pd__25*d_d_x__5 + _x57*(-_x58 + 2.0*_x59*l0*m
            - _x61) + _x66*d_E_ba__5)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return fail(out, STATUS_IMAGINARY_MOMENTUM)
        _x67 = math.sqrt(d_rad)
        d_h = _x67
        _pd__26 = (0.5)/_x67
        d_d_h__0 = _pd__26*d_d_rad__0
        d_d_h__1 = _pd__26*d_d_rad__1
        d_d_h__2 = _pd__26*d_d_rad__2
        d_d_h__3 = _pd__26*d_d_rad__3
        d_d_h__4 = _pd__26*d_d_rad__4
        d_d_h__5 = _pd__26*d_d_rad__5
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x71 = (1.0/d_x)
            _x68 = _x71**2
            d_wq = _x68*d_e_next
            _pd__27 = _x68
            _pd__28 = -2.0*_x71**3*d_e_next
            _x69 = 4.0*_pd__27
            d_d_wq__0 = _pd__28*d_d_x__0 + _x69*d_d_e__0
            d_d_wq__1 = _pd__28*d_d_x__1 + _x69*d_d_e__1
            d_d_wq__2 = _pd__28*d_d_x__2 + _x69*d_d_e__2
            d_d_wq__3 = _pd__28*d_d_x__3 + _x69*d_d_e__3
            d_d_wq__4 = _pd__28*d_d_x__4 + _x69*d_d_e__4
            d_d_wq__5 = _pd__28*d_d_x__5 + _x69*d_d_e__5
            d_wp = d_e_next*d_x
            _x70 = 4.0*d_x
            d_d_wp__0 = _x70*d_d_e__0 + d_d_x__0*d_e_next
            d_d_wp__1 = _x70*d_d_e__1 + d_d_x__1*d_e_next
            d_d_wp__2 = _x70*d_d_e__2 + d_d_x__2*d_e_next
            d_d_wp__3 = _x70*d_d_e__3 + d_d_x__3*d_e_next
            d_d_wp__4 = _x70*d_d_e__4 + d_d_x__4*d_e_next
            d_d_wp__5 = _x70*d_d_e__5 + d_d_x__5*d_e_next
        elif variant == 1.0:
            _x72 = (1.0/bottom_q_r)
            _x73 = bottom_q_r + d_e_next
            _x74 = (1.0/_x73)
            d_wq = _x72*_x74*d_e_next
            _x75 = _x72*_x74**2*d_e_next
            _pd__29 = -_x72**2*_x74*d_e_next - _x75
            _pd__30 = _x72*_x74 - _x75
            _x76 = 4.0*_pd__30
            d_d_wq__0 = _pd__29*d_bottom_q_r__0 + _x76*d_d_e__0
            d_d_wq__1 = _pd__29*d_bottom_q_r__1 + _x76*d_d_e__1
            d_d_wq__2 = _pd__29*d_bottom_q_r__2 + _x76*d_d_e__2
            d_d_wq__3 = _pd__29*d_bottom_q_r__3 + _x76*d_d_e__3
            d_d_wq__4 = _pd__29*d_bottom_q_r__4 + _x76*d_d_e__4
            d_d_wq__5 = _pd__29*d_bottom_q_r__5 + _x76*d_d_e__5
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__31 = _x73
            _x77 = 4.0*_pd__31
            d_d_wp__0 = _x77*d_d_e__0 + d_bottom_q_r__0*d_e_next
            d_d_wp__1 = _x77*d_d_e__1 + d_bottom_q_r__1*d_e_next
            d_d_wp__2 = _x77*d_d_e__2 + d_bottom_q_r__2*d_e_next
            d_d_wp__3 = _x77*d_d_e__3 + d_bottom_q_r__3*d_e_next
            d_d_wp__4 = _x77*d_d_e__4 + d_bottom_q_r__4*d_e_next
            d_d_wp__5 = _x77*d_d_e__5 + d_bottom_q_r__5*d_e_next
        else:
            return fail(out, STATUS_INVALID_INPUT)
        # next values
        d_e__next = d_e_next
        _x78 = (1.0/d_h)
        _x79 = _x78*d_wq
        d_Q__next = _x79*d_P + bottom_q_th
        _pd__32 = _x79
        _x80 = _x78**2
        _pd__33 = -_x80*d_P*d_wq
        _pd__34 = _x78*d_P
        d_d_Q__next__0 = _pd__32*d_d_P__0 + _pd__33*d_d_h__0 + _pd__34*d_d_wq__0 + d_bottom_q_th__0
        d_d_Q__next__1 = _pd__32*d_d_P__1 + _pd__33*d_d_h__1 + _pd__34*d_d_wq__1 + d_bottom_q_th__1
        d_d_Q__next__2 = _pd__32*d_d_P__2 + _pd__33*d_d_h__2 + _pd__34*d_d_wq__2 + d_bottom_q_th__2
        d_d_Q__next__3 = _pd__32*d_d_P__3 + _pd__33*d_d_h__3 + _pd__34*d_d_wq__3 + d_bottom_q_th__3
        d_d_Q__next__4 = _pd__32*d_d_P__4 + _pd__33*d_d_h__4 + _pd__34*d_d_wq__4 + d_bottom_q_th__4
        d_d_Q__next__5 = _pd__32*d_d_P__5 + _pd__33*d_d_h__5 + _pd__34*d_d_wq__5 + d_bottom_q_th__5
        _x81 = bottom_q_r**2*m
        _x82 = math.sin(d_Q)
        _x83 = m**2
        _x84 = _x78*_x83*g_s
        _x85 = _x82*_x84
        d_P__next = _x81*bottom_q_thd + _x85*d_wp
        _pd__35 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__36 = _x81
        _pd__37 = _x84*d_wp*math.cos(d_Q)
        _pd__38 = -_x80*_x82*_x83*d_wp*g_s
        _pd__39 = _x85
        d_d_P__next__0 = (_pd__35*d_bottom_q_r__0 + _pd__36*d_bottom_q_thd__0 + _pd__37*d_d_Q__0
            + _pd__38*d_d_h__0 + _pd__39*d_d_wp__0)
        d_d_P__next__1 = (_pd__35*d_bottom_q_r__1 + _pd__36*d_bottom_q_thd__1 + _pd__37*d_d_Q__1
            + _pd__38*d_d_h__1 + _pd__39*d_d_wp__1)
        d_d_P__next__2 = (_pd__35*d_bottom_q_r__2 + _pd__36*d_bottom_q_thd__2 + _pd__37*d_d_Q__2
            + _pd__38*d_d_h__2 + _pd__39*d_d_wp__2)
        d_d_P__next__3 = (_pd__35*d_bottom_q_r__3 + _pd__36*d_bottom_q_thd__3 + _pd__37*d_d_Q__3
            + _pd__38*d_d_h__3 + _pd__39*d_d_wp__3)
        d_d_P__next__4 = (_pd__35*d_bottom_q_r__4 + _pd__36*d_bottom_q_thd__4 + _pd__37*d_d_Q__4
            + _pd__38*d_d_h__4 + _pd__39*d_d_wp__4)
        d_d_P__next__5 = (_pd__35*d_bottom_q_r__5 + _pd__36*d_bottom_q_thd__5 + _pd__37*d_d_Q__5
            + _pd__38*d_d_h__5 + _pd__39*d_d_wp__5)
        _x86 = _x78*m
        d_T__next = _x86*d_e_next + t_bottom
        _pd__40 = _x86
        _pd__41 = -_x80*d_e_next*m
        _x87 = 4.0*_pd__40
        d_d_T__next__0 = _pd__41*d_d_h__0 + _x87*d_d_e__0 + d_t_bottom__0
        d_d_T__next__1 = _pd__41*d_d_h__1 + _x87*d_d_e__1 + d_t_bottom__1
        d_d_T__next__2 = _pd__41*d_d_h__2 + _x87*d_d_e__2 + d_t_bottom__2
        d_d_T__next__3 = _pd__41*d_d_h__3 + _x87*d_d_e__3 + d_t_bottom__3
        d_d_T__next__4 = _pd__41*d_d_h__4 + _x87*d_d_e__4 + d_t_bottom__4
        d_d_T__next__5 = _pd__41*d_d_h__5 + _x87*d_d_e__5 + d_t_bottom__5
        _n0_4 = 4.0*d_d_e__0
        _n0_5 = 4.0*d_d_e__1
        _n0_6 = 4.0*d_d_e__2
        _n0_7 = 4.0*d_d_e__3
        _n0_8 = 4.0*d_d_e__4
        _n0_9 = 4.0*d_d_e__5
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8, _n0_9,
            d_d_Q__next__0, d_d_Q__next__1, d_d_Q__next__2, d_d_Q__next__3, d_d_Q__next__4, d_d_Q__next__5,
            d_d_P__next__0, d_d_P__next__1, d_d_P__next__2, d_d_P__next__3, d_d_P__next__4, d_d_P__next__5,
            d_d_T__next__0, d_d_T__next__1, d_d_T__next__2, d_d_T__next__3, d_d_T__next__4, d_d_T__next__5, )
        _pk0 = _pkn0
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x88 = q_r_lo**2
    _x89 = (1.0/_x88)
    _x90 = m*q_r_lo**4
    _x91 = q_r_lo**3
    _x92 = _x88*l0**2*m
    _x93 = 2.0*g_s*m**2
    rad_lo = (_x89*(2.0*E_ba*_x88*m - _x90*k_d - _x91*_x93*math.cos(d_Q) + 2.0*_x91*k_d*l0*m - _x92*k_d
        - d_P**2))
    _pd__42 = -2.0*_x89*d_P
    _pd__43 = _x93*q_r_lo*math.sin(d_Q)
    _x94 = 2.0*m
    d_rad_lo__0 = _pd__42*d_d_P__0 + _pd__43*d_d_Q__0 + _x94*d_E_ba__0
    d_rad_lo__1 = _pd__42*d_d_P__1 + _pd__43*d_d_Q__1 + _x94*d_E_ba__1
    d_rad_lo__2 = _pd__42*d_d_P__2 + _pd__43*d_d_Q__2 + _x94*d_E_ba__2
    d_rad_lo__3 = _pd__42*d_d_P__3 + _pd__43*d_d_Q__3 + _x94*d_E_ba__3
    d_rad_lo__4 = _pd__42*d_d_P__4 + _pd__43*d_d_Q__4 + _x94*d_E_ba__4
    d_rad_lo__5 = _pd__42*d_d_P__5 + _pd__43*d_d_Q__5 + _x89*(-_x90 + 2.0*_x91*l0*m - _x92) + _x94*d_E_ba__5
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return fail(out, STATUS_IMAGINARY_MOMENTUM)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x95 = (1.0/m)
    _x96 = math.sqrt(rad_lo)
    liftoff_q_rd = _x95*_x96
    _pd__44 = (0.5)*_x95/_x96
    d_liftoff_q_rd__0 = _pd__44*d_rad_lo__0
    d_liftoff_q_rd__1 = _pd__44*d_rad_lo__1
    d_liftoff_q_rd__2 = _pd__44*d_rad_lo__2
    d_liftoff_q_rd__3 = _pd__44*d_rad_lo__3
    d_liftoff_q_rd__4 = _pd__44*d_rad_lo__4
    d_liftoff_q_rd__5 = _pd__44*d_rad_lo__5
    liftoff_q_th = d_Q
    _x97 = _x95/q_r_lo**2
    liftoff_q_thd = _x97*d_P
    _pd__45 = _x97
    d_liftoff_q_thd__0 = _pd__45*d_d_P__0
    d_liftoff_q_thd__1 = _pd__45*d_d_P__1
    d_liftoff_q_thd__2 = _pd__45*d_d_P__2
    d_liftoff_q_thd__3 = _pd__45*d_d_P__3
    d_liftoff_q_thd__4 = _pd__45*d_d_P__4
    d_liftoff_q_thd__5 = _pd__45*d_d_P__5
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return fail(out, STATUS_FALL)
    # derivatives of the outputs
    d_t_stance__0 = d_d_T__0
    d_t_stance__1 = d_d_T__1
    d_t_stance__2 = d_d_T__2
    d_t_stance__3 = d_d_T__3
    d_t_stance__4 = d_d_T__4
    d_t_stance__5 = d_d_T__5
    d_liftoff_q_th__0 = d_d_Q__0
    d_liftoff_q_th__1 = d_d_Q__1
    d_liftoff_q_th__2 = d_d_Q__2
    d_liftoff_q_th__3 = d_d_Q__3
    d_liftoff_q_th__4 = d_d_Q__4
    d_liftoff_q_th__5 = d_d_Q__5
    # (internal helper: its callers check that their outputs are finite)
    store(out, (t_bottom, t_stance, bottom_q_r, _o0_2, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, d_t_bottom__0, d_t_bottom__1, d_t_bottom__2, d_t_bottom__3,
        d_t_bottom__4, d_t_bottom__5, d_t_stance__0, d_t_stance__1, d_t_stance__2, d_t_stance__3,
        d_t_stance__4, d_t_stance__5, d_bottom_q_r__0, d_bottom_q_r__1, d_bottom_q_r__2, d_bottom_q_r__3,
        d_bottom_q_r__4, d_bottom_q_r__5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, d_bottom_q_th__0, d_bottom_q_th__1,
        d_bottom_q_th__2, d_bottom_q_th__3, d_bottom_q_th__4, d_bottom_q_th__5, d_bottom_q_thd__0,
        d_bottom_q_thd__1, d_bottom_q_thd__2, d_bottom_q_thd__3, d_bottom_q_thd__4, d_bottom_q_thd__5, 0.0,
        0.0, 0.0, 0.0, 0.0, 0.0, d_liftoff_q_rd__0, d_liftoff_q_rd__1, d_liftoff_q_rd__2, d_liftoff_q_rd__3,
        d_liftoff_q_rd__4, d_liftoff_q_rd__5, d_liftoff_q_th__0, d_liftoff_q_th__1, d_liftoff_q_th__2,
        d_liftoff_q_th__3, d_liftoff_q_th__4, d_liftoff_q_th__5, d_liftoff_q_thd__0, d_liftoff_q_thd__1,
        d_liftoff_q_thd__2, d_liftoff_q_thd__3, d_liftoff_q_thd__4, d_liftoff_q_thd__5,))
    return STATUS_OK


@njit(cache=True, error_model="numpy", inline="always")
def iterative_report_stance_jacobian_zeroth_shared(x, p, out, zeroth_jac, constant0):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    The body that 9 kernels share, each passing the kernel it calls as zeroth_jac and its
    constant as constant0 (derive/share.py): iterative_report_stance_jacobian_zeroth_{geyer,
    held, gravity_type0, gravity_type1, gravity_type2, gravity_type3, gravity_type4,
    gravity_type5, geyer_vs}.

    Arguments, returns and status: those of the kernels, then zeroth_jac, constant0.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length,) = load(p, 0, 1, 2, 3, 4, 7, 8, 9, 10)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations,
            bottom_length,)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m
            > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0)
            and (q_r_lo > 0.0)) & ((variant == 0.0) or (variant == 1.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) & ((bottom_length
            == 0.0) or (bottom_length == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate (option zeroth)
    _o0 = carray(stack(35), 35)
    _c0 = zeroth_jac(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, _o0_3, _o0_4, _o0_5, _o0_6, _o0_7, _o0_8, _o0_9, _o0_10, _o0_11, _o0_12, _o0_13,
        _o0_14, _o0_15, _o0_16, _o0_17, _o0_18, _o0_19, _o0_20, _o0_21, _o0_22, _o0_23, _o0_24, _o0_25,
        _o0_26, _o0_27, _o0_28, _o0_29, _o0_30, _o0_31, _o0_32, _o0_33, _o0_34,) = (load(_o0, 0, 1, 2, 3, 4,
        5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31,
        32, 33, 34))
    # the iteration from the zeroth iterate
    _a1 = carray(stack(49), 49)
    store(_a1, (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, _o0_0, _o0_1, _o0_2, _o0_3,
        _o0_4, constant0, variant, iterations, bottom_length, _o0_5, _o0_11, _o0_17, _o0_23, _o0_29, _o0_6,
        _o0_12, _o0_18, _o0_24, _o0_30, _o0_7, _o0_13, _o0_19, _o0_25, _o0_31, _o0_8, _o0_14, _o0_20, _o0_26,
        _o0_32, _o0_9, _o0_15, _o0_21, _o0_27, _o0_33, _o0_10, _o0_16, _o0_22, _o0_28, _o0_34,))
    _o1 = carray(stack(70), 70)
    _c1 = report_core_jvp6_b60fdf(_a1, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_0, _o1_1, _o1_2, _o1_3, _o1_4, _o1_5, _o1_6, _o1_7, _o1_8, _o1_9, _o1_10, _o1_11, _o1_12, _o1_13,
        _o1_14, _o1_15, _o1_16, _o1_17, _o1_18, _o1_19, _o1_20, _o1_21, _o1_22, _o1_23, _o1_24, _o1_25,
        _o1_26, _o1_27, _o1_34, _o1_35, _o1_36, _o1_37, _o1_38, _o1_39, _o1_40, _o1_41, _o1_42, _o1_43,
        _o1_44, _o1_45, _o1_52, _o1_53, _o1_54, _o1_55, _o1_56, _o1_57, _o1_58, _o1_59, _o1_60, _o1_61,
        _o1_62, _o1_63, _o1_64, _o1_65, _o1_66, _o1_67, _o1_68, _o1_69,) = (load(_o1, 0, 1, 2, 3, 4, 5, 6, 7,
        8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 34, 35, 36, 37, 38, 39,
        40, 41, 42, 43, 44, 45, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69))
    # every output finite, or the inputs were far outside a physical range
    store(out, (_o1_0, _o1_1, _o1_2, _o1_3, _o1_4, _o1_5, _o1_6, _o1_7, _o1_8, _o1_9, _o1_10, _o1_11, _o1_12,
        _o1_13, _o1_14, _o1_15, _o1_16, _o1_17, _o1_18, _o1_19, _o1_20, _o1_21, _o1_22, _o1_23, _o1_24,
        _o1_25, _o1_26, _o1_27, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, _o1_34, _o1_35, _o1_36, _o1_37, _o1_38, _o1_39,
        _o1_40, _o1_41, _o1_42, _o1_43, _o1_44, _o1_45, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, _o1_52, _o1_53, _o1_54,
        _o1_55, _o1_56, _o1_57, _o1_58, _o1_59, _o1_60, _o1_61, _o1_62, _o1_63, _o1_64, _o1_65, _o1_66,
        _o1_67, _o1_68, _o1_69,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_geyer(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Runs the shared body :func:`iterative_report_stance_jacobian_zeroth_shared` with
    zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`iterative_report.iterative_report_stance_zeroth_geyer`, in its order.

    Writes into out:
        <output>: each output of :func:`iterative_report.iterative_report_stance_zeroth_geyer`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return (iterative_report_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_geyer_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_jacobian_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if
    one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_jacobian_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_tail_c70fcc(_a, out):
    """The code of iterative_report_apex_return_jacobian's kernels per choice after their choice's own calls,
    shared by the choices with the same code (derive/tangent.py).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: the per-choice caller's variables of the same names.

    Writes into out:
        <output>: each output of :func:`iterative_report.iterative_report_apex_return_zeroth_geyer`, in its
            order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 240
    (_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex, _j_foot_x__ground, _j_foot_x__q_th_td,
        _j_foot_x__retraction_rate, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d, _j_liftoff_q_rd__q_rd_td,
        _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d,
        _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td, _j_liftoff_q_thd__k_c,
        _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_descent__retraction_rate, _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td,
        _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex,
        _j_td_q_rd__ground, _j_td_q_rd__q_th_td, _j_td_q_rd__retraction_rate, _j_td_q_th__b_y_apex,
        _j_td_q_th__ground, _j_td_q_th__q_th_td, _j_td_q_th__retraction_rate, _j_td_q_thd__b_xd_apex,
        _j_td_q_thd__b_y_apex, _j_td_q_thd__ground, _j_td_q_thd__q_th_td, _j_td_q_thd__retraction_rate,
        b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        t_descent, t_stance, td_q_th,) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16,
        17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41,
        42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54))
    # chain rule through iterative_report_stance
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
    _o0 = carray(stack(20), 20)
    _c0 = (liftoff_to_apex_jac_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f,
        direction, _o0))
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, next_apex_x, _j_apex_height__q_rd, _j_apex_height__q_th, _j_apex_height__q_thd,
        _j_apex_speed__q_rd, _j_apex_speed__q_th, _j_apex_speed__q_thd, _j_t_ascent__q_rd, _j_t_ascent__q_th,
        _j_t_ascent__q_thd, _j_next_apex_x__q_rd, _j_next_apex_x__q_th, _j_next_apex_x__q_thd,) = (load(_o0,
        0, 1, 2, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 17, 18, 19))
    # chain rule through liftoff_to_apex
    d_apex_height__b_y_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_y_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_height__b_xd_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_xd_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_height__q_th_td = (_j_apex_height__q_rd*d_liftoff_q_rd__q_th_td
        + _j_apex_height__q_th*d_liftoff_q_th__q_th_td + _j_apex_height__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_height__ground = (_j_apex_height__q_rd*d_liftoff_q_rd__ground
        + _j_apex_height__q_th*d_liftoff_q_th__ground + _j_apex_height__q_thd*d_liftoff_q_thd__ground)
    d_apex_height__retraction_rate = (_j_apex_height__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_apex_height__q_th*d_liftoff_q_th__retraction_rate
        + _j_apex_height__q_thd*d_liftoff_q_thd__retraction_rate)
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
    d_apex_speed__ground = (_j_apex_speed__q_rd*d_liftoff_q_rd__ground
        + _j_apex_speed__q_th*d_liftoff_q_th__ground + _j_apex_speed__q_thd*d_liftoff_q_thd__ground)
    d_apex_speed__retraction_rate = (_j_apex_speed__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_apex_speed__q_th*d_liftoff_q_th__retraction_rate
        + _j_apex_speed__q_thd*d_liftoff_q_thd__retraction_rate)
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
    d_t_ascent__ground = (_j_t_ascent__q_rd*d_liftoff_q_rd__ground + _j_t_ascent__q_th*d_liftoff_q_th__ground
        + _j_t_ascent__q_thd*d_liftoff_q_thd__ground)
    d_t_ascent__retraction_rate = (_j_t_ascent__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_t_ascent__q_th*d_liftoff_q_th__retraction_rate
        + _j_t_ascent__q_thd*d_liftoff_q_thd__retraction_rate)
    d_t_ascent__k_c = (_j_liftoff_q_rd__k_c*_j_t_ascent__q_rd + _j_liftoff_q_th__k_c*_j_t_ascent__q_th
        + _j_liftoff_q_thd__k_c*_j_t_ascent__q_thd)
    d_t_ascent__k_d = (_j_liftoff_q_rd__k_d*_j_t_ascent__q_rd + _j_liftoff_q_th__k_d*_j_t_ascent__q_th
        + _j_liftoff_q_thd__k_d*_j_t_ascent__q_thd)
    d_next_apex_x__b_y_apex = (_j_next_apex_x__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_next_apex_x__q_th*d_liftoff_q_th__b_y_apex + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_y_apex)
    d_next_apex_x__b_xd_apex = (_j_next_apex_x__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_next_apex_x__q_th*d_liftoff_q_th__b_xd_apex + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_next_apex_x__q_th_td = (_j_next_apex_x__q_rd*d_liftoff_q_rd__q_th_td
        + _j_next_apex_x__q_th*d_liftoff_q_th__q_th_td + _j_next_apex_x__q_thd*d_liftoff_q_thd__q_th_td)
    d_next_apex_x__ground = (_j_next_apex_x__q_rd*d_liftoff_q_rd__ground
        + _j_next_apex_x__q_th*d_liftoff_q_th__ground + _j_next_apex_x__q_thd*d_liftoff_q_thd__ground)
    d_next_apex_x__retraction_rate = (_j_next_apex_x__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_next_apex_x__q_th*d_liftoff_q_th__retraction_rate
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__retraction_rate)
    d_next_apex_x__k_c = (_j_liftoff_q_rd__k_c*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_c*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_c*_j_next_apex_x__q_thd)
    d_next_apex_x__k_d = (_j_liftoff_q_rd__k_d*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_d*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_d*_j_next_apex_x__q_thd)
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    d_step_length__b_y_apex = _j_foot_x__b_y_apex + d_next_apex_x__b_y_apex
    d_step_length__b_xd_apex = _j_foot_x__b_xd_apex + d_next_apex_x__b_xd_apex
    d_step_length__q_th_td = _j_foot_x__q_th_td + d_next_apex_x__q_th_td
    d_step_length__ground = _j_foot_x__ground + d_next_apex_x__ground
    d_step_length__retraction_rate = _j_foot_x__retraction_rate + d_next_apex_x__retraction_rate
    foot_y = -b_y_apex + ground
    touchdown_q_th = td_q_th
    # derivatives of the outputs
    d_t_descent__b_y_apex = _j_t_descent__b_y_apex
    d_t_descent__q_th_td = _j_t_descent__q_th_td
    d_t_descent__ground = _j_t_descent__ground
    d_t_descent__retraction_rate = _j_t_descent__retraction_rate
    d_t_stance__k_c = _j_t_stance__k_c
    d_t_stance__k_d = _j_t_stance__k_d
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
    d_foot_x__retraction_rate = _j_foot_x__retraction_rate
    d_touchdown_q_th__b_y_apex = _j_td_q_th__b_y_apex
    d_touchdown_q_th__q_th_td = _j_td_q_th__q_th_td
    d_touchdown_q_th__ground = _j_td_q_th__ground
    d_touchdown_q_th__retraction_rate = _j_td_q_th__retraction_rate
    # every value output finite, or the inputs were far outside a physical range (the
    # derivatives are checked by the role kernels that return them)
    if not (all_finite((_o0_0, _o0_1, t_descent, t_stance, _o0_2, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
            liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (_o0_0, _o0_1, t_descent, t_stance, _o0_2, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th, d_apex_height__b_y_apex,
        d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground,
        d_apex_height__retraction_rate, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex,
        d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__retraction_rate,
        d_apex_speed__k_c, d_apex_speed__k_d, d_t_descent__b_y_apex, 0.0, d_t_descent__q_th_td,
        d_t_descent__ground, d_t_descent__retraction_rate, 0.0, 0.0, d_t_stance__b_y_apex,
        d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__retraction_rate,
        d_t_stance__k_c, d_t_stance__k_d, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td,
        d_t_ascent__ground, d_t_ascent__retraction_rate, d_t_ascent__k_c, d_t_ascent__k_d, 0.0, 0.0, 0.0, 0.0,
        0.0, 0.0, 0.0, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td,
        d_liftoff_q_rd__ground, d_liftoff_q_rd__retraction_rate, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d,
        d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground,
        d_liftoff_q_th__retraction_rate, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex,
        d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground,
        d_liftoff_q_thd__retraction_rate, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex,
        d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground,
        d_step_length__retraction_rate, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex,
        d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__retraction_rate, 0.0, 0.0, -1.0,
        0.0, 0.0, 1.0, 0.0, 0.0, 0.0, d_touchdown_q_th__b_y_apex, 0.0, d_touchdown_q_th__q_th_td,
        d_touchdown_q_th__ground, d_touchdown_q_th__retraction_rate, 0.0, 0.0,))
    return STATUS_OK


@njit(cache=True, error_model="numpy", inline="always")
def iterative_report_apex_return_jacobian_zeroth_shared(x, p, out, iterative_report_stance_jacobian_zeroth):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    The body that 9 kernels share, each passing the kernel it calls as
    iterative_report_stance_jacobian_zeroth (derive/share.py):
    iterative_report_apex_return_jacobian_zeroth_{geyer, held, gravity_type0, gravity_type1,
    gravity_type2, gravity_type3, gravity_type4, gravity_type5, geyer_vs}.

    Arguments, returns and status: those of the kernels, then iterative_report_stance_jacobian_zeroth.
    """
    # Total ops: 1
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length,) = (load(p, 0, 1, 2, 3, 4,
        5, 6, 7, 8, 9, 10))
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k_c, k_d, g_s, g_f,
            q_r_td, q_r_lo, variant, iterations, bottom_length,)) & ((b_y_apex >= 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))
            & ((variant == 0.0) or (variant == 1.0)) & ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) & ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the step's direction: the sign of the apex speed
    direction = (0.0 if b_xd_apex == 0 else math.copysign(1, b_xd_apex))
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _o0 = carray(stack(36), 36)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate(b_y_apex, b_xd_apex,
        q_th_td, q_r_td, g_f, ground, retraction_rate, _o0))
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, _o0_3, _o0_4, _o0_5, _o0_11, _o0_12, _o0_13, _o0_14, _o0_15, _o0_16, _o0_18, _o0_19,
        _o0_20, _o0_21, _o0_22, _o0_23, _o0_24, _o0_25, _o0_26, _o0_28, _o0_29, _o0_30, _o0_31, _o0_32,
        _o0_33, _o0_34, _o0_35,) = (load(_o0, 0, 1, 2, 3, 4, 5, 11, 12, 13, 14, 15, 16, 18, 19, 20, 21, 22,
        23, 24, 25, 26, 28, 29, 30, 31, 32, 33, 34, 35))
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _x1 = carray(stack(4), 4)
    store(_x1, (_o0_0, _o0_1, _o0_2, _o0_3,))
    _o1 = carray(stack(70), 70)
    _c1 = iterative_report_stance_jacobian_zeroth(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, _o1_6, _o1_7, _o1_8, _o1_9, _o1_17, _o1_18, _o1_19, _o1_20, _o1_21, _o1_53, _o1_54, _o1_55,
        _o1_56, _o1_57, _o1_59, _o1_60, _o1_61, _o1_62, _o1_63, _o1_65, _o1_66, _o1_67, _o1_68, _o1_69,
        ) = (load(_o1, 1, 6, 7, 8, 9, 17, 18, 19, 20, 21, 53, 54, 55, 56, 57, 59, 60, 61, 62, 63, 65, 66, 67,
        68, 69))
    # the code shared between choices
    _a2 = carray(stack(55), 55)
    store(_a2, (_o0_32, _o0_31, _o0_34, _o0_33, _o0_35, _o1_56, _o1_57, _o1_53, _o1_54, _o1_55, _o1_62,
        _o1_63, _o1_59, _o1_60, _o1_61, _o1_68, _o1_69, _o1_65, _o1_66, _o1_67, _o0_26, _o0_29, _o0_28,
        _o0_30, _o1_20, _o1_21, _o1_17, _o1_18, _o1_19, _o0_12, _o0_11, _o0_14, _o0_13, _o0_15, _o0_16,
        _o0_19, _o0_18, _o0_20, _o0_22, _o0_21, _o0_24, _o0_23, _o0_25, b_y_apex, direction, _o0_5, g_f,
        ground, _o1_6, _o1_7, _o1_8, _o1_9, _o0_4, _o1_1, _o0_2,))
    _status = iterative_report_apex_return_jacobian_tail_c70fcc(_a2, out)
    if _status == STATUS_OK and not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return _status


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_geyer(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Runs the shared body :func:`iterative_report_apex_return_jacobian_zeroth_shared` with
    iterative_report_stance_jacobian_zeroth_geyer.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`iterative_report.iterative_report_apex_return_zeroth_geyer`, in its
    order.

    Writes into out:
        <output>: each output of :func:`iterative_report.iterative_report_apex_return_zeroth_geyer`, in its
            order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return (iterative_report_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_report_stance_jacobian_zeroth_geyer))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_jacobian_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_jacobian_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_held(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_report_stance_jacobian_zeroth_shared` with
    zeroth_held_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 1.0. Equations, arguments, returns
    and status: those of :func:`iterative_report_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_held_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 1.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_jacobian_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_jacobian_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_held(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_report_apex_return_jacobian_zeroth_shared` with
    iterative_report_stance_jacobian_zeroth_held. Equations, arguments, returns and status:
    those of :func:`iterative_report_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_report_stance_jacobian_zeroth_held))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_jacobian_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_jacobian_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type0(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_report_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type0_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_report_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type0_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_jacobian_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i]
    (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_jacobian_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type0(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_report_apex_return_jacobian_zeroth_shared` with
    iterative_report_stance_jacobian_zeroth_gravity_type0. Equations, arguments, returns and
    status: those of :func:`iterative_report_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_report_stance_jacobian_zeroth_gravity_type0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type0` (serial, nogil): ``X[i],
    P[i] (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_jacobian_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type1(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_report_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type1_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_report_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type1_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_jacobian_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i]
    (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_jacobian_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type1(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_report_apex_return_jacobian_zeroth_shared` with
    iterative_report_stance_jacobian_zeroth_gravity_type1. Equations, arguments, returns and
    status: those of :func:`iterative_report_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_report_stance_jacobian_zeroth_gravity_type1))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type1` (serial, nogil): ``X[i],
    P[i] (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_jacobian_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type2(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_report_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type2_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_report_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type2_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_jacobian_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i]
    (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_jacobian_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type2(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_report_apex_return_jacobian_zeroth_shared` with
    iterative_report_stance_jacobian_zeroth_gravity_type2. Equations, arguments, returns and
    status: those of :func:`iterative_report_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_report_stance_jacobian_zeroth_gravity_type2))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type2` (serial, nogil): ``X[i],
    P[i] (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_jacobian_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type3(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_report_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type3_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_report_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type3_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_jacobian_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i]
    (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_jacobian_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type3(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_report_apex_return_jacobian_zeroth_shared` with
    iterative_report_stance_jacobian_zeroth_gravity_type3. Equations, arguments, returns and
    status: those of :func:`iterative_report_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_report_stance_jacobian_zeroth_gravity_type3))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type3` (serial, nogil): ``X[i],
    P[i] (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_jacobian_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type4(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_report_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type4_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_report_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type4_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_jacobian_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i]
    (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_jacobian_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type4(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_report_apex_return_jacobian_zeroth_shared` with
    iterative_report_stance_jacobian_zeroth_gravity_type4. Equations, arguments, returns and
    status: those of :func:`iterative_report_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_report_stance_jacobian_zeroth_gravity_type4))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type4` (serial, nogil): ``X[i],
    P[i] (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_jacobian_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type5(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_report_stance_jacobian_zeroth_shared` with
    zeroth_gravity_type5_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_report_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_gravity_type5_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_jacobian_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i]
    (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_jacobian_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type5(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_report_apex_return_jacobian_zeroth_shared` with
    iterative_report_stance_jacobian_zeroth_gravity_type5. Equations, arguments, returns and
    status: those of :func:`iterative_report_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_report_stance_jacobian_zeroth_gravity_type5))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type5` (serial, nogil): ``X[i],
    P[i] (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_jacobian_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_geyer_vs(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Runs the shared body :func:`iterative_report_stance_jacobian_zeroth_shared` with
    zeroth_geyer_vs_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0. Equations, arguments,
    returns and status: those of :func:`iterative_report_stance_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_stance_jacobian_zeroth_shared(x, p, out,
        zeroth_geyer_vs_jac_q_r_td_q_rd_td_q_th_td_q_thd_td_k_c_k_d, 0.0))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_jacobian_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if
    one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_jacobian_zeroth_geyer_vs(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_geyer_vs(x, p, out):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Runs the shared body :func:`iterative_report_apex_return_jacobian_zeroth_shared` with
    iterative_report_stance_jacobian_zeroth_geyer_vs. Equations, arguments, returns and status:
    those of :func:`iterative_report_apex_return_jacobian_zeroth_geyer`.
    """
    # Total ops: 0
    return (iterative_report_apex_return_jacobian_zeroth_shared(x, p, out,
        iterative_report_stance_jacobian_zeroth_geyer_vs))


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_jacobian_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i]
    (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_jacobian_zeroth_geyer_vs(row(X, i), p, row(OUT, i))
