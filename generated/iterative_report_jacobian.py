# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative_report.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:2e171e0cb588eb80
#   geyer_jacobian.py sha256:12a4ff7e62097af8
#   geyer_vs_jacobian.py sha256:a5a2252ad71dc27c
#   gravity_type0_jacobian.py sha256:bff7df6075bb5069
#   gravity_type1_jacobian.py sha256:b3cd806c9fc2efd5
#   gravity_type2_jacobian.py sha256:2d17230dc5d640de
#   gravity_type3_jacobian.py sha256:8dce411e26663470
#   gravity_type4_jacobian.py sha256:b77de7700c2a41d7
#   gravity_type5_jacobian.py sha256:fce3784e57318524
#   rows.py sha256:0089f4b891692c1b
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module iterative_report: JVP kernels, and
for a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground,
    liftoff_to_apex_jac_q_rd_q_th_q_thd)
from .geyer_jacobian import geyer_stance_jacobian
from .geyer_vs_jacobian import bottom_quartic_jac_p_E_ab_k_c, geyer_vs_stance_jacobian
from .gravity_type0_jacobian import gravity_type0_stance_jacobian
from .gravity_type1_jacobian import gravity_type1_stance_jacobian
from .gravity_type2_jacobian import gravity_type2_stance_jacobian
from .gravity_type3_jacobian import gravity_type3_stance_jacobian
from .gravity_type4_jacobian import gravity_type4_stance_jacobian
from .gravity_type5_jacobian import gravity_type5_stance_jacobian
from .rows import store_row_10_70, store_row_12_84

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_NUMERICAL_RANGE, STATUS_IMAGINARY_MOMENTUM)

NAN = math.nan
_NAN70 = (NAN,) * 70
_NAN84 = (NAN,) * 84


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

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
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]
        bottom_length: option bottom_length: the bottom leg length q_r_b the chains run to and from (section
            5.2, closing estimates): 0 = zeroth, 1 = eq153

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
    # Total ops: 1510
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN70 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[60] != STATUS_OK:
        return _NAN70 + (_c0[60],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _, _, _, _, _,
        _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _, _j_z_b_q_thd__q_thd_td,
        _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k, _j_z_lo_q_thd__q_r_td,
        _j_z_lo_q_thd__q_rd_td, _, _j_z_lo_q_thd__q_thd_td, _j_z_lo_q_thd__k, _) = _c0
    # E_ab (114) of the touchdown state
    _x0 = k_c*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*l0 + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__q_r_td = _x0 + _x5 + _x6*q_r_td - k_c*l0
    d_E_ab__q_rd_td = m*q_rd_td
    d_E_ab__q_th_td = -_x4*q_r_td*math.sin(q_th_td)
    d_E_ab__q_thd_td = _x2*m*q_thd_td
    d_E_ab__k_c = _x1 + _x3 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_bottom_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_bottom_q_r__q_th_td = 0.0
        d_bottom_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_bottom_q_r__k_c = _j_z_b_q_r__k
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic_jac_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[4] != STATUS_OK:
            return _NAN70 + (_c1[4],)
        bottom_q_r = _c1[0]
        _j_bottom_q_r__p = _c1[1]
        _j_bottom_q_r__E_ab = _c1[2]
        _j_bottom_q_r__k_c = _c1[3]
        # chain rule through bottom_quartic
        _x7 = _j_bottom_q_r__p*m
        d_bottom_q_r__q_r_td = _j_bottom_q_r__E_ab*d_E_ab__q_r_td + 2.0*_x7*q_r_td*q_thd_td
        d_bottom_q_r__q_rd_td = _j_bottom_q_r__E_ab*d_E_ab__q_rd_td
        d_bottom_q_r__q_th_td = _j_bottom_q_r__E_ab*d_E_ab__q_th_td
        d_bottom_q_r__q_thd_td = _j_bottom_q_r__E_ab*d_E_ab__q_thd_td + _x7*q_r_td**2
        d_bottom_q_r__k_c = _j_bottom_q_r__E_ab*d_E_ab__k_c + _j_bottom_q_r__k_c
    else:
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN70 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = bottom_q_r - q_r_td
    _x10 = _x8*_x9
    c_e_n = _x10
    _pd__0 = _x8
    _x11 = -_x8
    d_c_e_n__q_r_td = _pd__0*d_bottom_q_r__q_r_td + _x11
    d_c_e_n__q_rd_td = _pd__0*d_bottom_q_r__q_rd_td
    d_c_e_n__q_th_td = _pd__0*d_bottom_q_r__q_th_td
    d_c_e_n__q_thd_td = _pd__0*d_bottom_q_r__q_thd_td
    d_c_e_n__k_c = _pd__0*d_bottom_q_r__k_c
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
    d_c_rad_z__q_r_td = (_j_z_b_q_r__q_r_td*_pd__3 + _j_z_b_q_th__q_r_td*_pd__4 + _j_z_b_q_thd__q_r_td*_pd__5
        + _pd__1*d_bottom_q_r__q_r_td + _x15*(-_x27*(-_x23*_x41 + _x24*_x46*q_r_td*q_thd_td) - _x39 - _x47)
        + _x42 + _x51*d_c_e_n__q_r_td + _x52*d_E_ab__q_r_td)
    d_c_rad_z__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__3 + _j_z_b_q_th__q_rd_td*_pd__4
        + _j_z_b_q_thd__q_rd_td*_pd__5 + _pd__1*d_bottom_q_r__q_rd_td + _x51*d_c_e_n__q_rd_td
        + _x52*d_E_ab__q_rd_td)
    d_c_rad_z__q_th_td = (_j_z_b_q_th__q_th_td*_pd__4 + _pd__1*d_bottom_q_r__q_th_td + _x24*_x50
        + _x51*d_c_e_n__q_th_td + _x52*d_E_ab__q_th_td)
    d_c_rad_z__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__3 + _j_z_b_q_th__q_thd_td*_pd__4
        + _j_z_b_q_thd__q_thd_td*_pd__5 + _pd__1*d_bottom_q_r__q_thd_td - 2.0*_x24*_x25*_x49
        + _x51*d_c_e_n__q_thd_td + _x52*d_E_ab__q_thd_td)
    d_c_rad_z__k_c = (_j_z_b_q_r__k*_pd__3 + _j_z_b_q_th__k*_pd__4 + _j_z_b_q_thd__k*_pd__5
        + _pd__1*d_bottom_q_r__k_c + _x15*(-_x16 + 2.0*_x17*l0*m - _x19) + _x51*d_c_e_n__k_c
        + _x52*d_E_ab__k_c)
    _x53 = math.sqrt(_x11 + 1.0)
    c_Q0 = _x29*_x53 + z_b_q_th
    _x54 = (0.5)/_x53
    _x55 = _x36*_x54
    _x56 = _x55*_x8
    _pd__6 = _x56
    _pd__7 = -_x55
    _pd__8 = 1.0 - _x53
    d_c_Q0__q_r_td = _j_z_b_q_th__q_r_td*_pd__8 + _pd__6*d_bottom_q_r__q_r_td + _pd__7*d_c_e_n__q_r_td - _x56
    d_c_Q0__q_rd_td = _j_z_b_q_th__q_rd_td*_pd__8 + _pd__6*d_bottom_q_r__q_rd_td + _pd__7*d_c_e_n__q_rd_td
    d_c_Q0__q_th_td = (_j_z_b_q_th__q_th_td*_pd__8 + _pd__6*d_bottom_q_r__q_th_td + _pd__7*d_c_e_n__q_th_td
        + _x53)
    d_c_Q0__q_thd_td = _j_z_b_q_th__q_thd_td*_pd__8 + _pd__6*d_bottom_q_r__q_thd_td + _pd__7*d_c_e_n__q_thd_td
    d_c_Q0__k_c = _j_z_b_q_th__k*_pd__8 + _pd__6*d_bottom_q_r__k_c + _pd__7*d_c_e_n__k_c
    c_P0 = _x22 + _x26*_x53
    _x57 = _x40*_x54
    _x58 = _x57*_x8
    _pd__9 = _x58
    _pd__10 = -_x57
    _pd__11 = -_x48*_x52*_x53 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__12 = _x20*m - _x21*_x53
    d_c_P0__q_r_td = (_j_z_b_q_r__q_r_td*_pd__11 + _j_z_b_q_thd__q_r_td*_pd__12 + _pd__10*d_c_e_n__q_r_td
        + _pd__9*d_bottom_q_r__q_r_td + _x43*_x53*m*q_thd_td - _x58)
    d_c_P0__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__11 + _j_z_b_q_thd__q_rd_td*_pd__12 + _pd__10*d_c_e_n__q_rd_td
        + _pd__9*d_bottom_q_r__q_rd_td)
    d_c_P0__q_th_td = _pd__10*d_c_e_n__q_th_td + _pd__9*d_bottom_q_r__q_th_td
    d_c_P0__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__11 + _j_z_b_q_thd__q_thd_td*_pd__12
        + _pd__10*d_c_e_n__q_thd_td + _pd__9*d_bottom_q_r__q_thd_td + _x25*_x53)
    d_c_P0__k_c = (_j_z_b_q_r__k*_pd__11 + _j_z_b_q_thd__k*_pd__12 + _pd__10*d_c_e_n__k_c
        + _pd__9*d_bottom_q_r__k_c)
    _x59 = m/math.sqrt(_x33)
    _x60 = (_x33 > 0.0)
    c_T0 = ((-_x10*_x59) if _x60 else (0.0))
    _pd__13 = ((-_x59) if _x60 else (0.0))
    _pd__14 = ((_x44*m/(_x33*math.sqrt(_x33))) if _x60 else (0.0))
    d_c_T0__q_r_td = _pd__13*d_c_e_n__q_r_td + _pd__14*d_c_rad_z__q_r_td
    d_c_T0__q_rd_td = _pd__13*d_c_e_n__q_rd_td + _pd__14*d_c_rad_z__q_rd_td
    d_c_T0__q_th_td = _pd__13*d_c_e_n__q_th_td + _pd__14*d_c_rad_z__q_th_td
    d_c_T0__q_thd_td = _pd__13*d_c_e_n__q_thd_td + _pd__14*d_c_rad_z__q_thd_td
    d_c_T0__k_c = _pd__13*d_c_e_n__k_c + _pd__14*d_c_rad_z__k_c
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__q_r_td, d_c_e_n__q_rd_td, d_c_e_n__q_th_td, d_c_e_n__q_thd_td,
        d_c_e_n__k_c, d_c_Q0__q_r_td, d_c_Q0__q_rd_td, d_c_Q0__q_th_td, d_c_Q0__q_thd_td, d_c_Q0__k_c,
        d_c_P0__q_r_td, d_c_P0__q_rd_td, d_c_P0__q_th_td, d_c_P0__q_thd_td, d_c_P0__k_c, d_c_T0__q_r_td,
        d_c_T0__q_rd_td, d_c_T0__q_th_td, d_c_T0__q_thd_td, d_c_T0__k_c, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__q_r_td, d_c_e__q_rd_td, d_c_e__q_th_td, d_c_e__q_thd_td, d_c_e__k_c,
            d_c_Q__q_r_td, d_c_Q__q_rd_td, d_c_Q__q_th_td, d_c_Q__q_thd_td, d_c_Q__k_c, d_c_P__q_r_td,
            d_c_P__q_rd_td, d_c_P__q_th_td, d_c_P__q_thd_td, d_c_P__k_c, d_c_T__q_r_td, d_c_T__q_rd_td,
            d_c_T__q_th_td, d_c_T__q_thd_td, d_c_T__k_c, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x61 = c_e + q_r_td
        c_x = _x61
        d_c_x__q_r_td = d_c_e__q_r_td + 1.0
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
        d_c_rad__q_r_td = (_pd__15*d_c_P__q_r_td + _pd__16*d_c_Q__q_r_td + _pd__17*d_c_x__q_r_td
            + _x72*d_E_ab__q_r_td)
        d_c_rad__q_rd_td = (_pd__15*d_c_P__q_rd_td + _pd__16*d_c_Q__q_rd_td + _pd__17*d_c_e__q_rd_td
            + _x72*d_E_ab__q_rd_td)
        d_c_rad__q_th_td = (_pd__15*d_c_P__q_th_td + _pd__16*d_c_Q__q_th_td + _pd__17*d_c_e__q_th_td
            + _x72*d_E_ab__q_th_td)
        d_c_rad__q_thd_td = (_pd__15*d_c_P__q_thd_td + _pd__16*d_c_Q__q_thd_td + _pd__17*d_c_e__q_thd_td
            + _x72*d_E_ab__q_thd_td)
        d_c_rad__k_c = (_pd__15*d_c_P__k_c + _pd__16*d_c_Q__k_c + _pd__17*d_c_e__k_c + _x63*(-_x64
            + 2.0*_x65*l0*m - _x67) + _x72*d_E_ab__k_c)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x73 = math.sqrt(c_rad)
        c_h = _x73
        _pd__18 = (0.5)/_x73
        d_c_h__q_r_td = _pd__18*d_c_rad__q_r_td
        d_c_h__q_rd_td = _pd__18*d_c_rad__q_rd_td
        d_c_h__q_th_td = _pd__18*d_c_rad__q_th_td
        d_c_h__q_thd_td = _pd__18*d_c_rad__q_thd_td
        d_c_h__k_c = _pd__18*d_c_rad__k_c
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x77 = (1.0/c_x)
            _x74 = _x77**2
            c_wq = _x74*c_e_next
            _pd__19 = _x74
            _pd__20 = -2.0*_x77**3*c_e_next
            _x75 = 4.0*_pd__19
            d_c_wq__q_r_td = _pd__20*d_c_x__q_r_td + _x75*d_c_e__q_r_td
            d_c_wq__q_rd_td = _pd__20*d_c_e__q_rd_td + _x75*d_c_e__q_rd_td
            d_c_wq__q_th_td = _pd__20*d_c_e__q_th_td + _x75*d_c_e__q_th_td
            d_c_wq__q_thd_td = _pd__20*d_c_e__q_thd_td + _x75*d_c_e__q_thd_td
            d_c_wq__k_c = _pd__20*d_c_e__k_c + _x75*d_c_e__k_c
            c_wp = c_e_next*c_x
            _x76 = 4.0*c_x
            d_c_wp__q_r_td = _x76*d_c_e__q_r_td + c_e_next*d_c_x__q_r_td
            d_c_wp__q_rd_td = _x76*d_c_e__q_rd_td + c_e_next*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x76*d_c_e__q_th_td + c_e_next*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x76*d_c_e__q_thd_td + c_e_next*d_c_e__q_thd_td
            d_c_wp__k_c = _x76*d_c_e__k_c + c_e_next*d_c_e__k_c
        elif variant == 1.0:
            _x78 = (1.0/q_r_td)
            _x79 = c_e_next + q_r_td
            _x80 = (1.0/_x79)
            c_wq = _x78*_x80*c_e_next
            _x81 = _x78*_x80**2*c_e_next
            _pd__21 = _x78*_x80 - _x81
            d_c_wq__q_r_td = 4.0*_pd__21*d_c_e__q_r_td - _x78**2*_x80*c_e_next - _x81
            _x82 = 4.0*_pd__21
            d_c_wq__q_rd_td = _x82*d_c_e__q_rd_td
            d_c_wq__q_th_td = _x82*d_c_e__q_th_td
            d_c_wq__q_thd_td = _x82*d_c_e__q_thd_td
            d_c_wq__k_c = _x82*d_c_e__k_c
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__22 = _x79
            _x83 = 4.0*_pd__22
            d_c_wp__q_r_td = _x83*d_c_e__q_r_td + c_e_next
            d_c_wp__q_rd_td = _x83*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x83*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x83*d_c_e__q_thd_td
            d_c_wp__k_c = _x83*d_c_e__k_c
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        c_e__next = c_e_next
        _x84 = (1.0/c_h)
        _x85 = _x84*c_wq
        c_Q__next = -_x85*c_P + q_th_td
        _pd__23 = -_x85
        _x86 = _x84**2
        _pd__24 = _x86*c_P*c_wq
        _pd__25 = -_x84*c_P
        d_c_Q__next__q_r_td = _pd__23*d_c_P__q_r_td + _pd__24*d_c_h__q_r_td + _pd__25*d_c_wq__q_r_td
        d_c_Q__next__q_rd_td = _pd__23*d_c_P__q_rd_td + _pd__24*d_c_h__q_rd_td + _pd__25*d_c_wq__q_rd_td
        d_c_Q__next__q_th_td = _pd__23*d_c_P__q_th_td + _pd__24*d_c_h__q_th_td + _pd__25*d_c_wq__q_th_td + 1.0
        d_c_Q__next__q_thd_td = _pd__23*d_c_P__q_thd_td + _pd__24*d_c_h__q_thd_td + _pd__25*d_c_wq__q_thd_td
        d_c_Q__next__k_c = _pd__23*d_c_P__k_c + _pd__24*d_c_h__k_c + _pd__25*d_c_wq__k_c
        _x87 = m*q_r_td**2
        _x88 = math.sin(c_Q)
        _x89 = m**2
        _x90 = _x84*_x89*g_s
        _x91 = _x88*_x90
        c_P__next = _x87*q_thd_td - _x91*c_wp
        _pd__26 = -_x90*c_wp*math.cos(c_Q)
        _pd__27 = _x86*_x88*_x89*c_wp*g_s
        _pd__28 = -_x91
        d_c_P__next__q_r_td = (_pd__26*d_c_Q__q_r_td + _pd__27*d_c_h__q_r_td + _pd__28*d_c_wp__q_r_td
            + 2.0*m*q_r_td*q_thd_td)
        d_c_P__next__q_rd_td = _pd__26*d_c_Q__q_rd_td + _pd__27*d_c_h__q_rd_td + _pd__28*d_c_wp__q_rd_td
        d_c_P__next__q_th_td = _pd__26*d_c_Q__q_th_td + _pd__27*d_c_h__q_th_td + _pd__28*d_c_wp__q_th_td
        d_c_P__next__q_thd_td = (_pd__26*d_c_Q__q_thd_td + _pd__27*d_c_h__q_thd_td + _pd__28*d_c_wp__q_thd_td
            + _x87)
        d_c_P__next__k_c = _pd__26*d_c_Q__k_c + _pd__27*d_c_h__k_c + _pd__28*d_c_wp__k_c
        _x92 = _x84*m
        c_T__next = -_x92*c_e_next
        _pd__29 = -_x92
        _pd__30 = _x86*c_e_next*m
        _x93 = 4.0*_pd__29
        d_c_T__next__q_r_td = _pd__30*d_c_h__q_r_td + _x93*d_c_e__q_r_td
        d_c_T__next__q_rd_td = _pd__30*d_c_h__q_rd_td + _x93*d_c_e__q_rd_td
        d_c_T__next__q_th_td = _pd__30*d_c_h__q_th_td + _x93*d_c_e__q_th_td
        d_c_T__next__q_thd_td = _pd__30*d_c_h__q_thd_td + _x93*d_c_e__q_thd_td
        d_c_T__next__k_c = _pd__30*d_c_h__k_c + _x93*d_c_e__k_c
        _n0_4 = 4.0*d_c_e__q_r_td
        _n0_5 = 4.0*d_c_e__q_rd_td
        _n0_6 = 4.0*d_c_e__q_th_td
        _n0_7 = 4.0*d_c_e__q_thd_td
        _n0_8 = 4.0*d_c_e__k_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8,
            d_c_Q__next__q_r_td, d_c_Q__next__q_rd_td, d_c_Q__next__q_th_td, d_c_Q__next__q_thd_td,
            d_c_Q__next__k_c, d_c_P__next__q_r_td, d_c_P__next__q_rd_td, d_c_P__next__q_th_td,
            d_c_P__next__q_thd_td, d_c_P__next__k_c, d_c_T__next__q_r_td, d_c_T__next__q_rd_td,
            d_c_T__next__q_th_td, d_c_T__next__q_thd_td, d_c_T__next__k_c, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    _x94 = (1.0/m)
    _x96 = (1.0/bottom_q_r)
    _x95 = _x94*_x96**2
    bottom_q_thd = _x95*c_P
    _pd__31 = -2.0*_x94*_x96**3*c_P
    _pd__32 = _x95
    d_bottom_q_thd__q_r_td = _pd__31*d_bottom_q_r__q_r_td + _pd__32*d_c_P__q_r_td
    d_bottom_q_thd__q_rd_td = _pd__31*d_bottom_q_r__q_rd_td + _pd__32*d_c_P__q_rd_td
    d_bottom_q_thd__q_th_td = _pd__31*d_bottom_q_r__q_th_td + _pd__32*d_c_P__q_th_td
    d_bottom_q_thd__q_thd_td = _pd__31*d_bottom_q_r__q_thd_td + _pd__32*d_c_P__q_thd_td
    d_bottom_q_thd__k_c = _pd__31*d_bottom_q_r__k_c + _pd__32*d_c_P__k_c
    # E_ba of (98): the energy jump of the stiffness switch
    _x97 = (-bottom_q_r + l0)**2
    _x98 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x97*_x98
    _pd__33 = _x98*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__q_r_td = _pd__33*d_bottom_q_r__q_r_td + d_E_ab__q_r_td
    d_E_ba__q_rd_td = _pd__33*d_bottom_q_r__q_rd_td + d_E_ab__q_rd_td
    d_E_ba__q_th_td = _pd__33*d_bottom_q_r__q_th_td + d_E_ab__q_th_td
    d_E_ba__q_thd_td = _pd__33*d_bottom_q_r__q_thd_td + d_E_ab__q_thd_td
    _x99 = (0.5)*_x97
    d_E_ba__k_c = _pd__33*d_bottom_q_r__k_c - _x99 + d_E_ab__k_c
    d_E_ba__k_d = _x99
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN70 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x100 = 4.0**(-iterations)
    _x101 = -bottom_q_r + q_r_lo
    _x102 = _x100*_x101
    d_e_n = _x102
    _pd__34 = -_x100
    d_d_e_n__q_r_td = _pd__34*d_bottom_q_r__q_r_td
    d_d_e_n__q_rd_td = _pd__34*d_bottom_q_r__q_rd_td
    d_d_e_n__q_th_td = _pd__34*d_bottom_q_r__q_th_td
    d_d_e_n__q_thd_td = _pd__34*d_bottom_q_r__q_thd_td
    d_d_e_n__k_c = _pd__34*d_bottom_q_r__k_c
    _x103 = (0.25)*_x102
    d_e_z = _x103
    _x104 = _x103 + bottom_q_r
    _x105 = _x104**2
    _x106 = (1.0/_x105)
    _x107 = _x104**4*m
    _x108 = _x104**3
    _x109 = l0**2*m
    _x110 = _x105*_x109
    _x111 = bottom_q_r**2*m
    _x112 = _x111*bottom_q_thd
    _x113 = q_r_lo**2
    _x114 = -_x112 + _x113*g_lo_q_thd*m
    _x115 = 4.0**((0.5)*iterations)
    _x116 = (1.0/_x115)
    _x117 = (0.5)*_x116
    _x118 = _x114*_x117
    _x119 = _x112 + _x118
    _x120 = -bottom_q_th + g_lo_q_th
    _x121 = _x117*_x120
    _x122 = _x121 + bottom_q_th
    _x123 = m**2
    _x124 = _x123*g_s
    _x125 = _x124*math.cos(_x122)
    _x126 = 2.0*E_ba*_x105*m - _x107*k_d - 2.0*_x108*_x125 + 2.0*_x108*k_d*l0*m - _x110*k_d - _x119**2
    _x127 = _x106*_x126
    d_rad_z = _x127
    _x128 = -2.0*_x126/_x108
    _x129 = 4.0*m
    _x130 = (1.0/_x101)
    _x131 = 2.0*bottom_q_r
    _x132 = _x131*bottom_q_thd*m
    _x133 = -_x116*_x132 + _x118*_x130
    _x134 = math.sin(_x122)
    _x135 = (0.5)*_x102
    _x136 = _x131 + _x135
    _x137 = -2.0*E_ba*_x136*m + 6.0*_x105*_x125 - 6.0*_x105*k_d*l0*m + _x108*_x129*k_d + _x109*_x136*k_d
    _pd__35 = (_x106*((0.5)*_x108*_x116*_x120*_x123*_x130*_x134*g_s - _x119*(_x129*bottom_q_r*bottom_q_thd
        + _x133) - _x137) + _x128)
    _x138 = _x104*_x124*_x134
    _pd__36 = 2.0*_x138*(1.0 - _x117)
    _x139 = -_x111*_x116
    _x140 = _x106*_x119
    _pd__37 = -_x140*(2.0*_x111 + _x139)
    _x141 = _x115*_x130
    _pd__38 = _x106*(2.0*_x108*_x115*_x120*_x123*_x130*_x134*g_s - 2.0*_x114*_x119*_x141 - _x137) + _x128
    _pd__39 = _x116*_x138
    _x142 = _x113*_x116*m
    _pd__40 = -_x140*_x142
    _x143 = (0.25)*_pd__38
    _x144 = 2.0*m
    d_d_rad_z__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__39 + _j_z_lo_q_thd__q_r_td*_pd__40
        + _pd__35*d_bottom_q_r__q_r_td + _pd__36*d_c_Q__q_r_td + _pd__37*d_bottom_q_thd__q_r_td
        + _x143*d_d_e_n__q_r_td + _x144*d_E_ba__q_r_td)
    d_d_rad_z__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__39 + _j_z_lo_q_thd__q_rd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_rd_td + _pd__36*d_c_Q__q_rd_td + _pd__37*d_bottom_q_thd__q_rd_td
        + _x143*d_d_e_n__q_rd_td + _x144*d_E_ba__q_rd_td)
    d_d_rad_z__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__39 + _pd__35*d_bottom_q_r__q_th_td
        + _pd__36*d_c_Q__q_th_td + _pd__37*d_bottom_q_thd__q_th_td + _x143*d_d_e_n__q_th_td
        + _x144*d_E_ba__q_th_td)
    d_d_rad_z__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__39 + _j_z_lo_q_thd__q_thd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_thd_td + _pd__36*d_c_Q__q_thd_td + _pd__37*d_bottom_q_thd__q_thd_td
        + _x143*d_d_e_n__q_thd_td + _x144*d_E_ba__q_thd_td)
    d_d_rad_z__k_c = (_j_z_lo_q_th__k*_pd__39 + _j_z_lo_q_thd__k*_pd__40 + _pd__35*d_bottom_q_r__k_c
        + _pd__36*d_c_Q__k_c + _pd__37*d_bottom_q_thd__k_c + _x143*d_d_e_n__k_c + _x144*d_E_ba__k_c)
    d_d_rad_z__k_d = _x106*(-_x107 + 2.0*_x108*l0*m - _x110) + _x144*d_E_ba__k_d
    d_Q0 = _x116*_x120 + bottom_q_th
    _pd__41 = _x121*_x130
    _pd__42 = 1.0 - _x116
    _x145 = (0.5)*_x141
    _pd__43 = _x120*_x145
    _pd__44 = _x116
    d_d_Q0__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__44 + _pd__41*d_bottom_q_r__q_r_td + _pd__42*d_c_Q__q_r_td
        + _pd__43*d_d_e_n__q_r_td)
    d_d_Q0__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__44 + _pd__41*d_bottom_q_r__q_rd_td + _pd__42*d_c_Q__q_rd_td
        + _pd__43*d_d_e_n__q_rd_td)
    d_d_Q0__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__44 + _pd__41*d_bottom_q_r__q_th_td + _pd__42*d_c_Q__q_th_td
        + _pd__43*d_d_e_n__q_th_td)
    d_d_Q0__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__44 + _pd__41*d_bottom_q_r__q_thd_td
        + _pd__42*d_c_Q__q_thd_td + _pd__43*d_d_e_n__q_thd_td)
    d_d_Q0__k_c = (_j_z_lo_q_th__k*_pd__44 + _pd__41*d_bottom_q_r__k_c + _pd__42*d_c_Q__k_c
        + _pd__43*d_d_e_n__k_c)
    d_P0 = _x112 + _x114*_x116
    _pd__45 = _x132 + _x133
    _pd__46 = _x111 + _x139
    _pd__47 = _x114*_x145
    _pd__48 = _x142
    d_d_P0__q_r_td = (_j_z_lo_q_thd__q_r_td*_pd__48 + _pd__45*d_bottom_q_r__q_r_td
        + _pd__46*d_bottom_q_thd__q_r_td + _pd__47*d_d_e_n__q_r_td)
    d_d_P0__q_rd_td = (_j_z_lo_q_thd__q_rd_td*_pd__48 + _pd__45*d_bottom_q_r__q_rd_td
        + _pd__46*d_bottom_q_thd__q_rd_td + _pd__47*d_d_e_n__q_rd_td)
    d_d_P0__q_th_td = (_pd__45*d_bottom_q_r__q_th_td + _pd__46*d_bottom_q_thd__q_th_td
        + _pd__47*d_d_e_n__q_th_td)
    d_d_P0__q_thd_td = (_j_z_lo_q_thd__q_thd_td*_pd__48 + _pd__45*d_bottom_q_r__q_thd_td
        + _pd__46*d_bottom_q_thd__q_thd_td + _pd__47*d_d_e_n__q_thd_td)
    d_d_P0__k_c = (_j_z_lo_q_thd__k*_pd__48 + _pd__45*d_bottom_q_r__k_c + _pd__46*d_bottom_q_thd__k_c
        + _pd__47*d_d_e_n__k_c)
    _x146 = m/math.sqrt(_x127)
    _x147 = (_x127 > 0.0)
    d_T0 = ((_x102*_x146 + t_bottom) if _x147 else (t_bottom))
    _pd__49 = ((_x146) if _x147 else (0.0))
    _pd__50 = ((-_x135*m/(_x127*math.sqrt(_x127))) if _x147 else (0.0))
    d_d_T0__q_r_td = _pd__49*d_d_e_n__q_r_td + _pd__50*d_d_rad_z__q_r_td + d_c_T__q_r_td
    d_d_T0__q_rd_td = _pd__49*d_d_e_n__q_rd_td + _pd__50*d_d_rad_z__q_rd_td + d_c_T__q_rd_td
    d_d_T0__q_th_td = _pd__49*d_d_e_n__q_th_td + _pd__50*d_d_rad_z__q_th_td + d_c_T__q_th_td
    d_d_T0__q_thd_td = _pd__49*d_d_e_n__q_thd_td + _pd__50*d_d_rad_z__q_thd_td + d_c_T__q_thd_td
    d_d_T0__k_c = _pd__49*d_d_e_n__k_c + _pd__50*d_d_rad_z__k_c + d_c_T__k_c
    d_d_T0__k_d = _pd__50*d_d_rad_z__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki1 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__q_r_td, d_d_e_n__q_rd_td, d_d_e_n__q_th_td, d_d_e_n__q_thd_td,
        d_d_e_n__k_c, 0.0, d_d_Q0__q_r_td, d_d_Q0__q_rd_td, d_d_Q0__q_th_td, d_d_Q0__q_thd_td, d_d_Q0__k_c,
        0.0, d_d_P0__q_r_td, d_d_P0__q_rd_td, d_d_P0__q_th_td, d_d_P0__q_thd_td, d_d_P0__k_c, 0.0,
        d_d_T0__q_r_td, d_d_T0__q_rd_td, d_d_T0__q_th_td, d_d_T0__q_thd_td, d_d_T0__k_c, d_d_T0__k_d, )
    _pk1 = _pki1
    d_steps = 0.0
    _conv1 = False
    _last1 = max(int(iterations), 0)
    for _it1 in range(_last1 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__q_r_td, d_d_e__q_rd_td, d_d_e__q_th_td, d_d_e__q_thd_td, d_d_e__k_c,
            d_d_e__k_d, d_d_Q__q_r_td, d_d_Q__q_rd_td, d_d_Q__q_th_td, d_d_Q__q_thd_td, d_d_Q__k_c,
            d_d_Q__k_d, d_d_P__q_r_td, d_d_P__q_rd_td, d_d_P__q_th_td, d_d_P__q_thd_td, d_d_P__k_c,
            d_d_P__k_d, d_d_T__q_r_td, d_d_T__q_rd_td, d_d_T__q_th_td, d_d_T__q_thd_td, d_d_T__k_c,
            d_d_T__k_d, ) = _pk1
        if _conv1 or _it1 == _last1:
            break
        _x148 = bottom_q_r + d_e
        d_x = _x148
        d_d_x__q_r_td = d_bottom_q_r__q_r_td + d_d_e__q_r_td
        d_d_x__q_rd_td = d_bottom_q_r__q_rd_td + d_d_e__q_rd_td
        d_d_x__q_th_td = d_bottom_q_r__q_th_td + d_d_e__q_th_td
        d_d_x__q_thd_td = d_bottom_q_r__q_thd_td + d_d_e__q_thd_td
        d_d_x__k_c = d_bottom_q_r__k_c + d_d_e__k_c
        _x149 = _x148**2
        _x150 = (1.0/_x149)
        _x151 = _x148**4*m
        _x152 = _x148**3
        _x153 = l0**2
        _x154 = _x149*_x153*m
        _x155 = math.cos(d_Q)
        _x156 = m**2
        _x157 = 2.0*_x156*g_s
        _x158 = 2.0*E_ba*_x149*m - _x151*k_d - _x152*_x155*_x157 + 2.0*_x152*k_d*l0*m - _x154*k_d - d_P**2
        d_rad = _x150*_x158
        _pd__51 = -2.0*_x150*d_P
        _pd__52 = _x148*_x157*math.sin(d_Q)
        _x159 = 2.0*m
        _pd__53 = (_x150*(4.0*E_ba*_x148*m - _x148*_x153*_x159*k_d - 6.0*_x149*_x155*_x156*g_s
            + 6.0*_x149*k_d*l0*m - 4.0*_x152*k_d*m) - 2.0*_x158/_x152)
        d_d_rad__q_r_td = (_pd__51*d_d_P__q_r_td + _pd__52*d_d_Q__q_r_td + _pd__53*d_d_x__q_r_td
            + _x159*d_E_ba__q_r_td)
        d_d_rad__q_rd_td = (_pd__51*d_d_P__q_rd_td + _pd__52*d_d_Q__q_rd_td + _pd__53*d_d_x__q_rd_td
            + _x159*d_E_ba__q_rd_td)
        d_d_rad__q_th_td = (_pd__51*d_d_P__q_th_td + _pd__52*d_d_Q__q_th_td + _pd__53*d_d_x__q_th_td
            + _x159*d_E_ba__q_th_td)
        d_d_rad__q_thd_td = (_pd__51*d_d_P__q_thd_td + _pd__52*d_d_Q__q_thd_td + _pd__53*d_d_x__q_thd_td
            + _x159*d_E_ba__q_thd_td)
        d_d_rad__k_c = _pd__51*d_d_P__k_c + _pd__52*d_d_Q__k_c + _pd__53*d_d_x__k_c + _x159*d_E_ba__k_c
        d_d_rad__k_d = (_pd__51*d_d_P__k_d + _pd__52*d_d_Q__k_d + _pd__53*d_d_e__k_d + _x150*(-_x151
            + 2.0*_x152*l0*m - _x154) + _x159*d_E_ba__k_d)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x160 = math.sqrt(d_rad)
        d_h = _x160
        _pd__54 = (0.5)/_x160
        d_d_h__q_r_td = _pd__54*d_d_rad__q_r_td
        d_d_h__q_rd_td = _pd__54*d_d_rad__q_rd_td
        d_d_h__q_th_td = _pd__54*d_d_rad__q_th_td
        d_d_h__q_thd_td = _pd__54*d_d_rad__q_thd_td
        d_d_h__k_c = _pd__54*d_d_rad__k_c
        d_d_h__k_d = _pd__54*d_d_rad__k_d
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x164 = (1.0/d_x)
            _x161 = _x164**2
            d_wq = _x161*d_e_next
            _pd__55 = _x161
            _pd__56 = -2.0*_x164**3*d_e_next
            _x162 = 4.0*_pd__55
            d_d_wq__q_r_td = _pd__56*d_d_x__q_r_td + _x162*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__56*d_d_x__q_rd_td + _x162*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__56*d_d_x__q_th_td + _x162*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__56*d_d_x__q_thd_td + _x162*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__56*d_d_x__k_c + _x162*d_d_e__k_c
            d_d_wq__k_d = _pd__56*d_d_e__k_d + _x162*d_d_e__k_d
            d_wp = d_e_next*d_x
            _x163 = 4.0*d_x
            d_d_wp__q_r_td = _x163*d_d_e__q_r_td + d_d_x__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x163*d_d_e__q_rd_td + d_d_x__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x163*d_d_e__q_th_td + d_d_x__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x163*d_d_e__q_thd_td + d_d_x__q_thd_td*d_e_next
            d_d_wp__k_c = _x163*d_d_e__k_c + d_d_x__k_c*d_e_next
            d_d_wp__k_d = _x163*d_d_e__k_d + d_d_e__k_d*d_e_next
        elif variant == 1.0:
            _x165 = (1.0/bottom_q_r)
            _x166 = bottom_q_r + d_e_next
            _x167 = (1.0/_x166)
            d_wq = _x165*_x167*d_e_next
            _x168 = _x165*_x167**2*d_e_next
            _pd__57 = -_x165**2*_x167*d_e_next - _x168
            _pd__58 = _x165*_x167 - _x168
            _x169 = 4.0*_pd__58
            d_d_wq__q_r_td = _pd__57*d_bottom_q_r__q_r_td + _x169*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__57*d_bottom_q_r__q_rd_td + _x169*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__57*d_bottom_q_r__q_th_td + _x169*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__57*d_bottom_q_r__q_thd_td + _x169*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__57*d_bottom_q_r__k_c + _x169*d_d_e__k_c
            d_d_wq__k_d = _x169*d_d_e__k_d
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__59 = _x166
            _x170 = 4.0*_pd__59
            d_d_wp__q_r_td = _x170*d_d_e__q_r_td + d_bottom_q_r__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x170*d_d_e__q_rd_td + d_bottom_q_r__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x170*d_d_e__q_th_td + d_bottom_q_r__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x170*d_d_e__q_thd_td + d_bottom_q_r__q_thd_td*d_e_next
            d_d_wp__k_c = _x170*d_d_e__k_c + d_bottom_q_r__k_c*d_e_next
            d_d_wp__k_d = _x170*d_d_e__k_d
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        d_e__next = d_e_next
        _x171 = (1.0/d_h)
        _x172 = _x171*d_wq
        d_Q__next = _x172*d_P + bottom_q_th
        _pd__60 = _x172
        _x173 = _x171**2
        _pd__61 = -_x173*d_P*d_wq
        _pd__62 = _x171*d_P
        d_d_Q__next__q_r_td = (_pd__60*d_d_P__q_r_td + _pd__61*d_d_h__q_r_td + _pd__62*d_d_wq__q_r_td
            + d_c_Q__q_r_td)
        d_d_Q__next__q_rd_td = (_pd__60*d_d_P__q_rd_td + _pd__61*d_d_h__q_rd_td + _pd__62*d_d_wq__q_rd_td
            + d_c_Q__q_rd_td)
        d_d_Q__next__q_th_td = (_pd__60*d_d_P__q_th_td + _pd__61*d_d_h__q_th_td + _pd__62*d_d_wq__q_th_td
            + d_c_Q__q_th_td)
        d_d_Q__next__q_thd_td = (_pd__60*d_d_P__q_thd_td + _pd__61*d_d_h__q_thd_td + _pd__62*d_d_wq__q_thd_td
            + d_c_Q__q_thd_td)
        d_d_Q__next__k_c = _pd__60*d_d_P__k_c + _pd__61*d_d_h__k_c + _pd__62*d_d_wq__k_c + d_c_Q__k_c
        d_d_Q__next__k_d = _pd__60*d_d_P__k_d + _pd__61*d_d_h__k_d + _pd__62*d_d_wq__k_d
        _x174 = bottom_q_r**2*m
        _x175 = math.sin(d_Q)
        _x176 = m**2
        _x177 = _x171*_x176*g_s
        _x178 = _x175*_x177
        d_P__next = _x174*bottom_q_thd + _x178*d_wp
        _pd__63 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__64 = _x174
        _pd__65 = _x177*d_wp*math.cos(d_Q)
        _pd__66 = -_x173*_x175*_x176*d_wp*g_s
        _pd__67 = _x178
        d_d_P__next__q_r_td = (_pd__63*d_bottom_q_r__q_r_td + _pd__64*d_bottom_q_thd__q_r_td
            + _pd__65*d_d_Q__q_r_td + _pd__66*d_d_h__q_r_td + _pd__67*d_d_wp__q_r_td)
        d_d_P__next__q_rd_td = (_pd__63*d_bottom_q_r__q_rd_td + _pd__64*d_bottom_q_thd__q_rd_td
            + _pd__65*d_d_Q__q_rd_td + _pd__66*d_d_h__q_rd_td + _pd__67*d_d_wp__q_rd_td)
        d_d_P__next__q_th_td = (_pd__63*d_bottom_q_r__q_th_td + _pd__64*d_bottom_q_thd__q_th_td
            + _pd__65*d_d_Q__q_th_td + _pd__66*d_d_h__q_th_td + _pd__67*d_d_wp__q_th_td)
        d_d_P__next__q_thd_td = (_pd__63*d_bottom_q_r__q_thd_td + _pd__64*d_bottom_q_thd__q_thd_td
            + _pd__65*d_d_Q__q_thd_td + _pd__66*d_d_h__q_thd_td + _pd__67*d_d_wp__q_thd_td)
        d_d_P__next__k_c = (_pd__63*d_bottom_q_r__k_c + _pd__64*d_bottom_q_thd__k_c + _pd__65*d_d_Q__k_c
            + _pd__66*d_d_h__k_c + _pd__67*d_d_wp__k_c)
        d_d_P__next__k_d = _pd__65*d_d_Q__k_d + _pd__66*d_d_h__k_d + _pd__67*d_d_wp__k_d
        _x179 = _x171*m
        d_T__next = _x179*d_e_next + t_bottom
        _pd__68 = _x179
        _pd__69 = -_x173*d_e_next*m
        _x180 = 4.0*_pd__68
        d_d_T__next__q_r_td = _pd__69*d_d_h__q_r_td + _x180*d_d_e__q_r_td + d_c_T__q_r_td
        d_d_T__next__q_rd_td = _pd__69*d_d_h__q_rd_td + _x180*d_d_e__q_rd_td + d_c_T__q_rd_td
        d_d_T__next__q_th_td = _pd__69*d_d_h__q_th_td + _x180*d_d_e__q_th_td + d_c_T__q_th_td
        d_d_T__next__q_thd_td = _pd__69*d_d_h__q_thd_td + _x180*d_d_e__q_thd_td + d_c_T__q_thd_td
        d_d_T__next__k_c = _pd__69*d_d_h__k_c + _x180*d_d_e__k_c + d_c_T__k_c
        d_d_T__next__k_d = _pd__69*d_d_h__k_d + _x180*d_d_e__k_d
        _n1_4 = 4.0*d_d_e__q_r_td
        _n1_5 = 4.0*d_d_e__q_rd_td
        _n1_6 = 4.0*d_d_e__q_th_td
        _n1_7 = 4.0*d_d_e__q_thd_td
        _n1_8 = 4.0*d_d_e__k_c
        _n1_9 = 4.0*d_d_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn1 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n1_4, _n1_5, _n1_6, _n1_7, _n1_8, _n1_9,
            d_d_Q__next__q_r_td, d_d_Q__next__q_rd_td, d_d_Q__next__q_th_td, d_d_Q__next__q_thd_td,
            d_d_Q__next__k_c, d_d_Q__next__k_d, d_d_P__next__q_r_td, d_d_P__next__q_rd_td,
            d_d_P__next__q_th_td, d_d_P__next__q_thd_td, d_d_P__next__k_c, d_d_P__next__k_d,
            d_d_T__next__q_r_td, d_d_T__next__q_rd_td, d_d_T__next__q_th_td, d_d_T__next__q_thd_td,
            d_d_T__next__k_c, d_d_T__next__k_d, )
        _pk1 = _pkn1
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x181 = q_r_lo**2
    _x182 = (1.0/_x181)
    _x183 = m*q_r_lo**4
    _x184 = q_r_lo**3
    _x185 = _x181*l0**2*m
    _x186 = 2.0*g_s*m**2
    rad_lo = (_x182*(2.0*E_ba*_x181*m - _x183*k_d - _x184*_x186*math.cos(d_Q) + 2.0*_x184*k_d*l0*m - _x185*k_d
        - d_P**2))
    _pd__70 = -2.0*_x182*d_P
    _pd__71 = _x186*q_r_lo*math.sin(d_Q)
    _x187 = 2.0*m
    d_rad_lo__q_r_td = _pd__70*d_d_P__q_r_td + _pd__71*d_d_Q__q_r_td + _x187*d_E_ba__q_r_td
    d_rad_lo__q_rd_td = _pd__70*d_d_P__q_rd_td + _pd__71*d_d_Q__q_rd_td + _x187*d_E_ba__q_rd_td
    d_rad_lo__q_th_td = _pd__70*d_d_P__q_th_td + _pd__71*d_d_Q__q_th_td + _x187*d_E_ba__q_th_td
    d_rad_lo__q_thd_td = _pd__70*d_d_P__q_thd_td + _pd__71*d_d_Q__q_thd_td + _x187*d_E_ba__q_thd_td
    d_rad_lo__k_c = _pd__70*d_d_P__k_c + _pd__71*d_d_Q__k_c + _x187*d_E_ba__k_c
    d_rad_lo__k_d = (_pd__70*d_d_P__k_d + _pd__71*d_d_Q__k_d + _x182*(-_x183 + 2.0*_x184*l0*m - _x185)
        + _x187*d_E_ba__k_d)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x188 = (1.0/m)
    _x189 = math.sqrt(rad_lo)
    liftoff_q_rd = _x188*_x189
    _pd__72 = (0.5)*_x188/_x189
    d_liftoff_q_rd__q_r_td = _pd__72*d_rad_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _pd__72*d_rad_lo__q_rd_td
    d_liftoff_q_rd__q_th_td = _pd__72*d_rad_lo__q_th_td
    d_liftoff_q_rd__q_thd_td = _pd__72*d_rad_lo__q_thd_td
    d_liftoff_q_rd__k_c = _pd__72*d_rad_lo__k_c
    d_liftoff_q_rd__k_d = _pd__72*d_rad_lo__k_d
    liftoff_q_th = d_Q
    _x190 = _x188/q_r_lo**2
    liftoff_q_thd = _x190*d_P
    _pd__73 = _x190
    d_liftoff_q_thd__q_r_td = _pd__73*d_d_P__q_r_td
    d_liftoff_q_thd__q_rd_td = _pd__73*d_d_P__q_rd_td
    d_liftoff_q_thd__q_th_td = _pd__73*d_d_P__q_th_td
    d_liftoff_q_thd__q_thd_td = _pd__73*d_d_P__q_thd_td
    d_liftoff_q_thd__k_c = _pd__73*d_d_P__k_c
    d_liftoff_q_thd__k_d = _pd__73*d_d_P__k_d
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN70 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_c_T__q_r_td
    d_t_bottom__q_rd_td = d_c_T__q_rd_td
    d_t_bottom__q_th_td = d_c_T__q_th_td
    d_t_bottom__q_thd_td = d_c_T__q_thd_td
    d_t_bottom__k_c = d_c_T__k_c
    d_t_bottom__k_d = 0.0
    d_t_stance__q_r_td = d_d_T__q_r_td
    d_t_stance__q_rd_td = d_d_T__q_rd_td
    d_t_stance__q_th_td = d_d_T__q_th_td
    d_t_stance__q_thd_td = d_d_T__q_thd_td
    d_t_stance__k_c = d_d_T__k_c
    d_t_stance__k_d = d_d_T__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__q_r_td = d_c_Q__q_r_td
    d_bottom_q_th__q_rd_td = d_c_Q__q_rd_td
    d_bottom_q_th__q_th_td = d_c_Q__q_th_td
    d_bottom_q_th__q_thd_td = d_c_Q__q_thd_td
    d_bottom_q_th__k_c = d_c_Q__k_c
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_th__q_r_td = d_d_Q__q_r_td
    d_liftoff_q_th__q_rd_td = d_d_Q__q_rd_td
    d_liftoff_q_th__q_th_td = d_d_Q__q_th_td
    d_liftoff_q_th__q_thd_td = d_d_Q__q_thd_td
    d_liftoff_q_th__k_c = d_d_Q__k_c
    d_liftoff_q_th__k_d = d_d_Q__k_d
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
def iterative_report_stance_jacobian_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian_zeroth_geyer`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length.
    Writes output j of row i to ``out[i, j]`` (shape (n, 70); the columns are the outputs of
    :func:`iterative_report_stance_jacobian_zeroth_geyer`, in order) and its status code to ``status[i]``
    (int64).
    A row whose values exist but a derivative does not is NUMERICAL_RANGE (:func:`store_row_10_70`).
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_jacobian_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance):
    """The code of iterative_report_apex_return_jacobian's kernels per choice after their choice's own calls,
    shared by the choices with the same code (derive/tangent.py).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: the per-choice caller's variables of the same names.

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
    # Total ops: 183
    # chain rule through iterative_report_stance
    d_t_stance__b_y_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_y_apex)
    d_t_stance__b_xd_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_t_stance__q_th_td = (_j_t_stance__q_rd_td*_j_td_q_rd__q_th_td + _j_t_stance__q_th_td*_j_td_q_th__q_th_td
        + _j_t_stance__q_thd_td*_j_td_q_thd__q_th_td)
    d_t_stance__ground = _j_t_stance__q_rd_td*_j_td_q_rd__ground + _j_t_stance__q_thd_td*_j_td_q_thd__ground
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
    _c0 = (liftoff_to_apex_jac_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f,
        direction))
    if _c0[20] != STATUS_OK:
        return _NAN84 + (_c0[20],)
    (apex_height, apex_speed, t_ascent, _, next_apex_x, _j_apex_height__q_rd, _j_apex_height__q_th,
        _j_apex_height__q_thd, _j_apex_speed__q_rd, _j_apex_speed__q_th, _j_apex_speed__q_thd,
        _j_t_ascent__q_rd, _j_t_ascent__q_th, _j_t_ascent__q_thd, _, _, _, _j_next_apex_x__q_rd,
        _j_next_apex_x__q_th, _j_next_apex_x__q_thd, _) = _c0
    # chain rule through liftoff_to_apex
    d_apex_height__b_y_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_y_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_height__b_xd_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_xd_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_height__q_th_td = (_j_apex_height__q_rd*d_liftoff_q_rd__q_th_td
        + _j_apex_height__q_th*d_liftoff_q_th__q_th_td + _j_apex_height__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_height__ground = (_j_apex_height__q_rd*d_liftoff_q_rd__ground
        + _j_apex_height__q_th*d_liftoff_q_th__ground + _j_apex_height__q_thd*d_liftoff_q_thd__ground)
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
    d_liftoff_q_r__b_y_apex = 0.0
    d_liftoff_q_r__b_xd_apex = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__ground = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
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


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

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
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]
        bottom_length: option bottom_length: the bottom leg length q_r_b the chains run to and from (section
            5.2, closing estimates): 0 = zeroth, 1 = eq153

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
    # Total ops: 1
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
            and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f
            > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_jacobian_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length))
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # the code shared between choices
    return (iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian_zeroth_geyer`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations,
    bottom_length.
    Writes output j of row i to ``out[i, j]`` (shape (n, 84); the columns are the outputs of
    :func:`iterative_report_apex_return_jacobian_zeroth_geyer`, in order) and its status code to ``status[i]``
    (int64).
    A row whose values exist but a derivative does not is NUMERICAL_RANGE (:func:`store_row_12_84`).
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_jacobian_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        store_row_12_84(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1624
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN70 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
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
    # E_ab (114) of the touchdown state
    _x25 = k_c*q_r_td
    _x26 = (0.5)*l0**2
    _x27 = q_r_td**2
    _x28 = (0.5)*_x27
    _x29 = g_s*m
    _x30 = _x29*math.cos(q_th_td)
    _x31 = m*q_thd_td**2
    E_ab = -_x25*l0 + _x26*k_c + _x28*_x31 + _x28*k_c + _x30*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__q_r_td = _x25 + _x30 + _x31*q_r_td - k_c*l0
    d_E_ab__q_rd_td = m*q_rd_td
    d_E_ab__q_th_td = -_x29*q_r_td*math.sin(q_th_td)
    d_E_ab__q_thd_td = _x27*m*q_thd_td
    d_E_ab__k_c = _x26 + _x28 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__q_r_td = d_z_b_q_r__q_r_td
        d_bottom_q_r__q_rd_td = d_z_b_q_r__q_rd_td
        d_bottom_q_r__q_th_td = d_z_b_q_r__q_th_td
        d_bottom_q_r__q_thd_td = d_z_b_q_r__q_thd_td
        d_bottom_q_r__k_c = d_z_b_q_r__k_c
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c0 = bottom_quartic_jac_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c0[4] != STATUS_OK:
            return _NAN70 + (_c0[4],)
        bottom_q_r = _c0[0]
        _j_bottom_q_r__p = _c0[1]
        _j_bottom_q_r__E_ab = _c0[2]
        _j_bottom_q_r__k_c = _c0[3]
        # chain rule through bottom_quartic
        _x32 = _j_bottom_q_r__p*m
        d_bottom_q_r__q_r_td = _j_bottom_q_r__E_ab*d_E_ab__q_r_td + 2.0*_x32*q_r_td*q_thd_td
        d_bottom_q_r__q_rd_td = _j_bottom_q_r__E_ab*d_E_ab__q_rd_td
        d_bottom_q_r__q_th_td = _j_bottom_q_r__E_ab*d_E_ab__q_th_td
        d_bottom_q_r__q_thd_td = _j_bottom_q_r__E_ab*d_E_ab__q_thd_td + _x32*q_r_td**2
        d_bottom_q_r__k_c = _j_bottom_q_r__E_ab*d_E_ab__k_c + _j_bottom_q_r__k_c
    else:
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN70 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x33 = 4.0**(-iterations)
    _x34 = bottom_q_r - q_r_td
    _x35 = _x33*_x34
    c_e_n = _x35
    _pd__1 = _x33
    _x36 = -_x33
    d_c_e_n__q_r_td = _pd__1*d_bottom_q_r__q_r_td + _x36
    d_c_e_n__q_rd_td = _pd__1*d_bottom_q_r__q_rd_td
    d_c_e_n__q_th_td = _pd__1*d_bottom_q_r__q_th_td
    d_c_e_n__q_thd_td = _pd__1*d_bottom_q_r__q_thd_td
    d_c_e_n__k_c = _pd__1*d_bottom_q_r__k_c
    _x37 = (0.25)*_x35
    c_e_z = _x37
    _x38 = _x37 + q_r_td
    _x39 = _x38**2
    _x40 = (1.0/_x39)
    _x41 = _x38**4*m
    _x42 = _x38**3
    _x43 = l0**2*m
    _x44 = _x39*_x43
    _x45 = z_b_q_r**2
    _x46 = _x45*m
    _x47 = _x46*z_b_q_thd
    _x48 = (0.25)*_x33
    _x49 = math.sqrt(1.0 - _x48)
    _x50 = m*q_r_td**2
    _x51 = -_x47 + _x50*q_thd_td
    _x52 = _x47 + _x49*_x51
    _x53 = m**2
    _x54 = q_th_td - z_b_q_th
    _x55 = _x49*_x54 + z_b_q_th
    _x56 = _x53*g_s*math.cos(_x55)
    _x57 = 2.0*E_ab*_x39*m - _x41*k_c - 2.0*_x42*_x56 + 2.0*_x42*k_c*l0*m - _x44*k_c - _x52**2
    _x58 = _x40*_x57
    c_rad_z = _x58
    _x59 = (1.0/_x49)
    _x60 = (1.0/_x34)
    _x61 = _x54*_x60
    _x62 = _x53*g_s*math.sin(_x55)
    _x63 = _x42*_x59*_x61*_x62
    _x64 = _x48*_x63
    _x65 = _x51*_x60
    _x66 = _x59*_x65
    _pd__2 = _x40*(-_x48*_x52*_x66 + _x64)
    _x67 = -2.0*_x57/_x42
    _x68 = 2.0*q_r_td
    _x69 = (0.5)*_x35
    _x70 = _x68 + _x69
    _x71 = 4.0*m
    _x72 = -2.0*E_ab*_x70*m + 6.0*_x39*_x56 - 6.0*_x39*k_c*l0*m + _x42*_x71*k_c + _x43*_x70*k_c
    _pd__3 = _x40*(_x51*_x52*_x59*_x60 - _x63 - _x72) + _x67
    _x73 = z_b_q_r*z_b_q_thd
    _x74 = _x40*_x52
    _pd__4 = -_x74*(-_x49*_x71*_x73 + 4.0*m*z_b_q_r*z_b_q_thd)
    _pd__5 = -_x74*(2.0*_x45*m - 2.0*_x46*_x49)
    _x75 = (0.25)*_pd__3
    _x76 = 2.0*m
    d_c_rad_z__q_r_td = (_pd__2*d_bottom_q_r__q_r_td + _pd__4*d_z_b_q_r__q_r_td + _pd__5*d_z_b_q_thd__q_r_td
        + _x40*(-_x52*(-_x48*_x66 + _x49*_x71*q_r_td*q_thd_td) - _x64 - _x72) + _x67 + _x75*d_c_e_n__q_r_td
        + _x76*d_E_ab__q_r_td)
    d_c_rad_z__q_rd_td = (_pd__2*d_bottom_q_r__q_rd_td + _pd__4*d_z_b_q_r__q_rd_td
        + _pd__5*d_z_b_q_thd__q_rd_td + _x75*d_c_e_n__q_rd_td + _x76*d_E_ab__q_rd_td)
    _x77 = 2.0*_x49
    _x78 = _x38*_x62
    d_c_rad_z__q_th_td = (_pd__2*d_bottom_q_r__q_th_td + _pd__4*d_z_b_q_r__q_th_td
        + _pd__5*d_z_b_q_thd__q_th_td + _x75*d_c_e_n__q_th_td + _x76*d_E_ab__q_th_td + _x77*_x78
        + 2.0*_x78*(1.0 - _x49))
    d_c_rad_z__q_thd_td = (_pd__2*d_bottom_q_r__q_thd_td + _pd__4*d_z_b_q_r__q_thd_td
        + _pd__5*d_z_b_q_thd__q_thd_td - _x50*_x74*_x77 + _x75*d_c_e_n__q_thd_td + _x76*d_E_ab__q_thd_td)
    d_c_rad_z__k_c = (_pd__2*d_bottom_q_r__k_c + _pd__4*d_z_b_q_r__k_c + _pd__5*d_z_b_q_thd__k_c + _x40*(-_x41
        + 2.0*_x42*l0*m - _x44) + _x75*d_c_e_n__k_c + _x76*d_E_ab__k_c)
    _x79 = math.sqrt(_x36 + 1.0)
    c_Q0 = _x54*_x79 + z_b_q_th
    _x80 = (0.5)/_x79
    _x81 = _x61*_x80
    _x82 = _x33*_x81
    _pd__6 = _x82
    _pd__7 = -_x81
    d_c_Q0__q_r_td = _pd__6*d_bottom_q_r__q_r_td + _pd__7*d_c_e_n__q_r_td - _x82
    d_c_Q0__q_rd_td = _pd__6*d_bottom_q_r__q_rd_td + _pd__7*d_c_e_n__q_rd_td
    d_c_Q0__q_th_td = _pd__6*d_bottom_q_r__q_th_td + _pd__7*d_c_e_n__q_th_td + 1.0
    d_c_Q0__q_thd_td = _pd__6*d_bottom_q_r__q_thd_td + _pd__7*d_c_e_n__q_thd_td
    d_c_Q0__k_c = _pd__6*d_bottom_q_r__k_c + _pd__7*d_c_e_n__k_c
    c_P0 = _x47 + _x51*_x79
    _x83 = _x65*_x80
    _x84 = _x33*_x83
    _pd__8 = _x84
    _pd__9 = -_x83
    _pd__10 = -_x73*_x76*_x79 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__11 = _x45*m - _x46*_x79
    d_c_P0__q_r_td = (_pd__10*d_z_b_q_r__q_r_td + _pd__11*d_z_b_q_thd__q_r_td + _pd__8*d_bottom_q_r__q_r_td
        + _pd__9*d_c_e_n__q_r_td + _x68*_x79*m*q_thd_td - _x84)
    d_c_P0__q_rd_td = (_pd__10*d_z_b_q_r__q_rd_td + _pd__11*d_z_b_q_thd__q_rd_td
        + _pd__8*d_bottom_q_r__q_rd_td + _pd__9*d_c_e_n__q_rd_td)
    d_c_P0__q_th_td = (_pd__10*d_z_b_q_r__q_th_td + _pd__11*d_z_b_q_thd__q_th_td
        + _pd__8*d_bottom_q_r__q_th_td + _pd__9*d_c_e_n__q_th_td)
    d_c_P0__q_thd_td = (_pd__10*d_z_b_q_r__q_thd_td + _pd__11*d_z_b_q_thd__q_thd_td
        + _pd__8*d_bottom_q_r__q_thd_td + _pd__9*d_c_e_n__q_thd_td + _x50*_x79)
    d_c_P0__k_c = (_pd__10*d_z_b_q_r__k_c + _pd__11*d_z_b_q_thd__k_c + _pd__8*d_bottom_q_r__k_c
        + _pd__9*d_c_e_n__k_c)
    _x85 = m/math.sqrt(_x58)
    _x86 = (_x58 > 0.0)
    c_T0 = ((-_x35*_x85) if _x86 else (0.0))
    _pd__12 = ((-_x85) if _x86 else (0.0))
    _pd__13 = ((_x69*m/(_x58*math.sqrt(_x58))) if _x86 else (0.0))
    d_c_T0__q_r_td = _pd__12*d_c_e_n__q_r_td + _pd__13*d_c_rad_z__q_r_td
    d_c_T0__q_rd_td = _pd__12*d_c_e_n__q_rd_td + _pd__13*d_c_rad_z__q_rd_td
    d_c_T0__q_th_td = _pd__12*d_c_e_n__q_th_td + _pd__13*d_c_rad_z__q_th_td
    d_c_T0__q_thd_td = _pd__12*d_c_e_n__q_thd_td + _pd__13*d_c_rad_z__q_thd_td
    d_c_T0__k_c = _pd__12*d_c_e_n__k_c + _pd__13*d_c_rad_z__k_c
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__q_r_td, d_c_e_n__q_rd_td, d_c_e_n__q_th_td, d_c_e_n__q_thd_td,
        d_c_e_n__k_c, d_c_Q0__q_r_td, d_c_Q0__q_rd_td, d_c_Q0__q_th_td, d_c_Q0__q_thd_td, d_c_Q0__k_c,
        d_c_P0__q_r_td, d_c_P0__q_rd_td, d_c_P0__q_th_td, d_c_P0__q_thd_td, d_c_P0__k_c, d_c_T0__q_r_td,
        d_c_T0__q_rd_td, d_c_T0__q_th_td, d_c_T0__q_thd_td, d_c_T0__k_c, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__q_r_td, d_c_e__q_rd_td, d_c_e__q_th_td, d_c_e__q_thd_td, d_c_e__k_c,
            d_c_Q__q_r_td, d_c_Q__q_rd_td, d_c_Q__q_th_td, d_c_Q__q_thd_td, d_c_Q__k_c, d_c_P__q_r_td,
            d_c_P__q_rd_td, d_c_P__q_th_td, d_c_P__q_thd_td, d_c_P__k_c, d_c_T__q_r_td, d_c_T__q_rd_td,
            d_c_T__q_th_td, d_c_T__q_thd_td, d_c_T__k_c, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x87 = c_e + q_r_td
        c_x = _x87
        d_c_x__q_r_td = d_c_e__q_r_td + 1.0
        _x88 = _x87**2
        _x89 = (1.0/_x88)
        _x90 = _x87**4*m
        _x91 = _x87**3
        _x92 = l0**2
        _x93 = _x88*_x92*m
        _x94 = math.cos(c_Q)
        _x95 = m**2
        _x96 = 2.0*_x95*g_s
        _x97 = 2.0*E_ab*_x88*m - _x90*k_c - _x91*_x94*_x96 + 2.0*_x91*k_c*l0*m - _x93*k_c - c_P**2
        c_rad = _x89*_x97
        _pd__14 = -2.0*_x89*c_P
        _pd__15 = _x87*_x96*math.sin(c_Q)
        _x98 = 2.0*m
        _pd__16 = (_x89*(4.0*E_ab*_x87*m - _x87*_x92*_x98*k_c - 6.0*_x88*_x94*_x95*g_s + 6.0*_x88*k_c*l0*m
            - 4.0*_x91*k_c*m) - 2.0*_x97/_x91)
        d_c_rad__q_r_td = (_pd__14*d_c_P__q_r_td + _pd__15*d_c_Q__q_r_td + _pd__16*d_c_x__q_r_td
            + _x98*d_E_ab__q_r_td)
        d_c_rad__q_rd_td = (_pd__14*d_c_P__q_rd_td + _pd__15*d_c_Q__q_rd_td + _pd__16*d_c_e__q_rd_td
            + _x98*d_E_ab__q_rd_td)
        d_c_rad__q_th_td = (_pd__14*d_c_P__q_th_td + _pd__15*d_c_Q__q_th_td + _pd__16*d_c_e__q_th_td
            + _x98*d_E_ab__q_th_td)
        d_c_rad__q_thd_td = (_pd__14*d_c_P__q_thd_td + _pd__15*d_c_Q__q_thd_td + _pd__16*d_c_e__q_thd_td
            + _x98*d_E_ab__q_thd_td)
        d_c_rad__k_c = (_pd__14*d_c_P__k_c + _pd__15*d_c_Q__k_c + _pd__16*d_c_e__k_c + _x89*(-_x90
            + 2.0*_x91*l0*m - _x93) + _x98*d_E_ab__k_c)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x99 = math.sqrt(c_rad)
        c_h = _x99
        _pd__17 = (0.5)/_x99
        d_c_h__q_r_td = _pd__17*d_c_rad__q_r_td
        d_c_h__q_rd_td = _pd__17*d_c_rad__q_rd_td
        d_c_h__q_th_td = _pd__17*d_c_rad__q_th_td
        d_c_h__q_thd_td = _pd__17*d_c_rad__q_thd_td
        d_c_h__k_c = _pd__17*d_c_rad__k_c
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x103 = (1.0/c_x)
            _x100 = _x103**2
            c_wq = _x100*c_e_next
            _pd__18 = _x100
            _pd__19 = -2.0*_x103**3*c_e_next
            _x101 = 4.0*_pd__18
            d_c_wq__q_r_td = _pd__19*d_c_x__q_r_td + _x101*d_c_e__q_r_td
            d_c_wq__q_rd_td = _pd__19*d_c_e__q_rd_td + _x101*d_c_e__q_rd_td
            d_c_wq__q_th_td = _pd__19*d_c_e__q_th_td + _x101*d_c_e__q_th_td
            d_c_wq__q_thd_td = _pd__19*d_c_e__q_thd_td + _x101*d_c_e__q_thd_td
            d_c_wq__k_c = _pd__19*d_c_e__k_c + _x101*d_c_e__k_c
            c_wp = c_e_next*c_x
            _x102 = 4.0*c_x
            d_c_wp__q_r_td = _x102*d_c_e__q_r_td + c_e_next*d_c_x__q_r_td
            d_c_wp__q_rd_td = _x102*d_c_e__q_rd_td + c_e_next*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x102*d_c_e__q_th_td + c_e_next*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x102*d_c_e__q_thd_td + c_e_next*d_c_e__q_thd_td
            d_c_wp__k_c = _x102*d_c_e__k_c + c_e_next*d_c_e__k_c
        elif variant == 1.0:
            _x104 = (1.0/q_r_td)
            _x105 = c_e_next + q_r_td
            _x106 = (1.0/_x105)
            c_wq = _x104*_x106*c_e_next
            _x107 = _x104*_x106**2*c_e_next
            _pd__20 = _x104*_x106 - _x107
            d_c_wq__q_r_td = 4.0*_pd__20*d_c_e__q_r_td - _x104**2*_x106*c_e_next - _x107
            _x108 = 4.0*_pd__20
            d_c_wq__q_rd_td = _x108*d_c_e__q_rd_td
            d_c_wq__q_th_td = _x108*d_c_e__q_th_td
            d_c_wq__q_thd_td = _x108*d_c_e__q_thd_td
            d_c_wq__k_c = _x108*d_c_e__k_c
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__21 = _x105
            _x109 = 4.0*_pd__21
            d_c_wp__q_r_td = _x109*d_c_e__q_r_td + c_e_next
            d_c_wp__q_rd_td = _x109*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x109*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x109*d_c_e__q_thd_td
            d_c_wp__k_c = _x109*d_c_e__k_c
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        c_e__next = c_e_next
        _x110 = (1.0/c_h)
        _x111 = _x110*c_wq
        c_Q__next = -_x111*c_P + q_th_td
        _pd__22 = -_x111
        _x112 = _x110**2
        _pd__23 = _x112*c_P*c_wq
        _pd__24 = -_x110*c_P
        d_c_Q__next__q_r_td = _pd__22*d_c_P__q_r_td + _pd__23*d_c_h__q_r_td + _pd__24*d_c_wq__q_r_td
        d_c_Q__next__q_rd_td = _pd__22*d_c_P__q_rd_td + _pd__23*d_c_h__q_rd_td + _pd__24*d_c_wq__q_rd_td
        d_c_Q__next__q_th_td = _pd__22*d_c_P__q_th_td + _pd__23*d_c_h__q_th_td + _pd__24*d_c_wq__q_th_td + 1.0
        d_c_Q__next__q_thd_td = _pd__22*d_c_P__q_thd_td + _pd__23*d_c_h__q_thd_td + _pd__24*d_c_wq__q_thd_td
        d_c_Q__next__k_c = _pd__22*d_c_P__k_c + _pd__23*d_c_h__k_c + _pd__24*d_c_wq__k_c
        _x113 = m*q_r_td**2
        _x114 = math.sin(c_Q)
        _x115 = m**2
        _x116 = _x110*_x115*g_s
        _x117 = _x114*_x116
        c_P__next = _x113*q_thd_td - _x117*c_wp
        _pd__25 = -_x116*c_wp*math.cos(c_Q)
        _pd__26 = _x112*_x114*_x115*c_wp*g_s
        _pd__27 = -_x117
        d_c_P__next__q_r_td = (_pd__25*d_c_Q__q_r_td + _pd__26*d_c_h__q_r_td + _pd__27*d_c_wp__q_r_td
            + 2.0*m*q_r_td*q_thd_td)
        d_c_P__next__q_rd_td = _pd__25*d_c_Q__q_rd_td + _pd__26*d_c_h__q_rd_td + _pd__27*d_c_wp__q_rd_td
        d_c_P__next__q_th_td = _pd__25*d_c_Q__q_th_td + _pd__26*d_c_h__q_th_td + _pd__27*d_c_wp__q_th_td
        d_c_P__next__q_thd_td = (_pd__25*d_c_Q__q_thd_td + _pd__26*d_c_h__q_thd_td + _pd__27*d_c_wp__q_thd_td
            + _x113)
        d_c_P__next__k_c = _pd__25*d_c_Q__k_c + _pd__26*d_c_h__k_c + _pd__27*d_c_wp__k_c
        _x118 = _x110*m
        c_T__next = -_x118*c_e_next
        _pd__28 = -_x118
        _pd__29 = _x112*c_e_next*m
        _x119 = 4.0*_pd__28
        d_c_T__next__q_r_td = _pd__29*d_c_h__q_r_td + _x119*d_c_e__q_r_td
        d_c_T__next__q_rd_td = _pd__29*d_c_h__q_rd_td + _x119*d_c_e__q_rd_td
        d_c_T__next__q_th_td = _pd__29*d_c_h__q_th_td + _x119*d_c_e__q_th_td
        d_c_T__next__q_thd_td = _pd__29*d_c_h__q_thd_td + _x119*d_c_e__q_thd_td
        d_c_T__next__k_c = _pd__29*d_c_h__k_c + _x119*d_c_e__k_c
        _n0_4 = 4.0*d_c_e__q_r_td
        _n0_5 = 4.0*d_c_e__q_rd_td
        _n0_6 = 4.0*d_c_e__q_th_td
        _n0_7 = 4.0*d_c_e__q_thd_td
        _n0_8 = 4.0*d_c_e__k_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8,
            d_c_Q__next__q_r_td, d_c_Q__next__q_rd_td, d_c_Q__next__q_th_td, d_c_Q__next__q_thd_td,
            d_c_Q__next__k_c, d_c_P__next__q_r_td, d_c_P__next__q_rd_td, d_c_P__next__q_th_td,
            d_c_P__next__q_thd_td, d_c_P__next__k_c, d_c_T__next__q_r_td, d_c_T__next__q_rd_td,
            d_c_T__next__q_th_td, d_c_T__next__q_thd_td, d_c_T__next__k_c, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    _x120 = (1.0/m)
    _x122 = (1.0/bottom_q_r)
    _x121 = _x120*_x122**2
    bottom_q_thd = _x121*c_P
    _pd__30 = -2.0*_x120*_x122**3*c_P
    _pd__31 = _x121
    d_bottom_q_thd__q_r_td = _pd__30*d_bottom_q_r__q_r_td + _pd__31*d_c_P__q_r_td
    d_bottom_q_thd__q_rd_td = _pd__30*d_bottom_q_r__q_rd_td + _pd__31*d_c_P__q_rd_td
    d_bottom_q_thd__q_th_td = _pd__30*d_bottom_q_r__q_th_td + _pd__31*d_c_P__q_th_td
    d_bottom_q_thd__q_thd_td = _pd__30*d_bottom_q_r__q_thd_td + _pd__31*d_c_P__q_thd_td
    d_bottom_q_thd__k_c = _pd__30*d_bottom_q_r__k_c + _pd__31*d_c_P__k_c
    # E_ba of (98): the energy jump of the stiffness switch
    _x123 = (-bottom_q_r + l0)**2
    _x124 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x123*_x124
    _pd__32 = _x124*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__q_r_td = _pd__32*d_bottom_q_r__q_r_td + d_E_ab__q_r_td
    d_E_ba__q_rd_td = _pd__32*d_bottom_q_r__q_rd_td + d_E_ab__q_rd_td
    d_E_ba__q_th_td = _pd__32*d_bottom_q_r__q_th_td + d_E_ab__q_th_td
    d_E_ba__q_thd_td = _pd__32*d_bottom_q_r__q_thd_td + d_E_ab__q_thd_td
    _x125 = (0.5)*_x123
    d_E_ba__k_c = _pd__32*d_bottom_q_r__k_c - _x125 + d_E_ab__k_c
    d_E_ba__k_d = _x125
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    _x126 = q_r_lo**-2
    _x127 = _x126*bottom_q_r**2
    g_lo_q_thd = _x127*bottom_q_thd
    _pd__33 = 2.0*_x126*bottom_q_r*bottom_q_thd
    _pd__34 = _x127
    d_g_lo_q_thd__q_r_td = _pd__33*d_bottom_q_r__q_r_td + _pd__34*d_bottom_q_thd__q_r_td
    d_g_lo_q_thd__q_rd_td = _pd__33*d_bottom_q_r__q_rd_td + _pd__34*d_bottom_q_thd__q_rd_td
    d_g_lo_q_thd__q_th_td = _pd__33*d_bottom_q_r__q_th_td + _pd__34*d_bottom_q_thd__q_th_td
    d_g_lo_q_thd__q_thd_td = _pd__33*d_bottom_q_r__q_thd_td + _pd__34*d_bottom_q_thd__q_thd_td
    d_g_lo_q_thd__k_c = _pd__33*d_bottom_q_r__k_c + _pd__34*d_bottom_q_thd__k_c
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN70 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x128 = 4.0**(-iterations)
    _x129 = -bottom_q_r + q_r_lo
    _x130 = _x128*_x129
    d_e_n = _x130
    _pd__35 = -_x128
    d_d_e_n__q_r_td = _pd__35*d_bottom_q_r__q_r_td
    d_d_e_n__q_rd_td = _pd__35*d_bottom_q_r__q_rd_td
    d_d_e_n__q_th_td = _pd__35*d_bottom_q_r__q_th_td
    d_d_e_n__q_thd_td = _pd__35*d_bottom_q_r__q_thd_td
    d_d_e_n__k_c = _pd__35*d_bottom_q_r__k_c
    _x131 = (0.25)*_x130
    d_e_z = _x131
    _x132 = _x131 + bottom_q_r
    _x133 = _x132**2
    _x134 = (1.0/_x133)
    _x135 = _x132**4*m
    _x136 = _x132**3
    _x137 = l0**2*m
    _x138 = _x133*_x137
    _x139 = bottom_q_r**2*m
    _x140 = _x139*bottom_q_thd
    _x141 = q_r_lo**2
    _x142 = -_x140 + _x141*g_lo_q_thd*m
    _x143 = 4.0**((0.5)*iterations)
    _x144 = (1.0/_x143)
    _x145 = (0.5)*_x144
    _x146 = _x142*_x145
    _x147 = _x140 + _x146
    _x148 = -bottom_q_th + g_lo_q_th
    _x149 = _x145*_x148
    _x150 = _x149 + bottom_q_th
    _x151 = m**2
    _x152 = _x151*g_s
    _x153 = _x152*math.cos(_x150)
    _x154 = 2.0*E_ba*_x133*m - _x135*k_d - 2.0*_x136*_x153 + 2.0*_x136*k_d*l0*m - _x138*k_d - _x147**2
    _x155 = _x134*_x154
    d_rad_z = _x155
    _x156 = -2.0*_x154/_x136
    _x157 = 4.0*m
    _x158 = (1.0/_x129)
    _x159 = 2.0*bottom_q_r
    _x160 = _x159*bottom_q_thd*m
    _x161 = -_x144*_x160 + _x146*_x158
    _x162 = math.sin(_x150)
    _x163 = (0.5)*_x130
    _x164 = _x159 + _x163
    _x165 = -2.0*E_ba*_x164*m + 6.0*_x133*_x153 - 6.0*_x133*k_d*l0*m + _x136*_x157*k_d + _x137*_x164*k_d
    _pd__36 = (_x134*((0.5)*_x136*_x144*_x148*_x151*_x158*_x162*g_s - _x147*(_x157*bottom_q_r*bottom_q_thd
        + _x161) - _x165) + _x156)
    _x166 = _x132*_x152*_x162
    _pd__37 = 2.0*_x166*(1.0 - _x145)
    _x167 = -_x139*_x144
    _x168 = _x134*_x147
    _pd__38 = -_x168*(2.0*_x139 + _x167)
    _x169 = _x143*_x158
    _pd__39 = _x134*(2.0*_x136*_x143*_x148*_x151*_x158*_x162*g_s - 2.0*_x142*_x147*_x169 - _x165) + _x156
    _pd__40 = _x144*_x166
    _x170 = _x141*_x144*m
    _pd__41 = -_x168*_x170
    _x171 = (0.25)*_pd__39
    _x172 = 2.0*m
    d_d_rad_z__q_r_td = (_pd__36*d_bottom_q_r__q_r_td + _pd__37*d_c_Q__q_r_td + _pd__38*d_bottom_q_thd__q_r_td
        + _pd__40*d_c_Q__q_r_td + _pd__41*d_g_lo_q_thd__q_r_td + _x171*d_d_e_n__q_r_td + _x172*d_E_ba__q_r_td)
    d_d_rad_z__q_rd_td = (_pd__36*d_bottom_q_r__q_rd_td + _pd__37*d_c_Q__q_rd_td
        + _pd__38*d_bottom_q_thd__q_rd_td + _pd__40*d_c_Q__q_rd_td + _pd__41*d_g_lo_q_thd__q_rd_td
        + _x171*d_d_e_n__q_rd_td + _x172*d_E_ba__q_rd_td)
    d_d_rad_z__q_th_td = (_pd__36*d_bottom_q_r__q_th_td + _pd__37*d_c_Q__q_th_td
        + _pd__38*d_bottom_q_thd__q_th_td + _pd__40*d_c_Q__q_th_td + _pd__41*d_g_lo_q_thd__q_th_td
        + _x171*d_d_e_n__q_th_td + _x172*d_E_ba__q_th_td)
    d_d_rad_z__q_thd_td = (_pd__36*d_bottom_q_r__q_thd_td + _pd__37*d_c_Q__q_thd_td
        + _pd__38*d_bottom_q_thd__q_thd_td + _pd__40*d_c_Q__q_thd_td + _pd__41*d_g_lo_q_thd__q_thd_td
        + _x171*d_d_e_n__q_thd_td + _x172*d_E_ba__q_thd_td)
    d_d_rad_z__k_c = (_pd__36*d_bottom_q_r__k_c + _pd__37*d_c_Q__k_c + _pd__38*d_bottom_q_thd__k_c
        + _pd__40*d_c_Q__k_c + _pd__41*d_g_lo_q_thd__k_c + _x171*d_d_e_n__k_c + _x172*d_E_ba__k_c)
    d_d_rad_z__k_d = _x134*(-_x135 + 2.0*_x136*l0*m - _x138) + _x172*d_E_ba__k_d
    d_Q0 = _x144*_x148 + bottom_q_th
    _pd__42 = _x149*_x158
    _pd__43 = 1.0 - _x144
    _x173 = (0.5)*_x169
    _pd__44 = _x148*_x173
    _pd__45 = _x144
    d_d_Q0__q_r_td = (_pd__42*d_bottom_q_r__q_r_td + _pd__43*d_c_Q__q_r_td + _pd__44*d_d_e_n__q_r_td
        + _pd__45*d_c_Q__q_r_td)
    d_d_Q0__q_rd_td = (_pd__42*d_bottom_q_r__q_rd_td + _pd__43*d_c_Q__q_rd_td + _pd__44*d_d_e_n__q_rd_td
        + _pd__45*d_c_Q__q_rd_td)
    d_d_Q0__q_th_td = (_pd__42*d_bottom_q_r__q_th_td + _pd__43*d_c_Q__q_th_td + _pd__44*d_d_e_n__q_th_td
        + _pd__45*d_c_Q__q_th_td)
    d_d_Q0__q_thd_td = (_pd__42*d_bottom_q_r__q_thd_td + _pd__43*d_c_Q__q_thd_td + _pd__44*d_d_e_n__q_thd_td
        + _pd__45*d_c_Q__q_thd_td)
    d_d_Q0__k_c = _pd__42*d_bottom_q_r__k_c + _pd__43*d_c_Q__k_c + _pd__44*d_d_e_n__k_c + _pd__45*d_c_Q__k_c
    d_P0 = _x140 + _x142*_x144
    _pd__46 = _x160 + _x161
    _pd__47 = _x139 + _x167
    _pd__48 = _x142*_x173
    _pd__49 = _x170
    d_d_P0__q_r_td = (_pd__46*d_bottom_q_r__q_r_td + _pd__47*d_bottom_q_thd__q_r_td + _pd__48*d_d_e_n__q_r_td
        + _pd__49*d_g_lo_q_thd__q_r_td)
    d_d_P0__q_rd_td = (_pd__46*d_bottom_q_r__q_rd_td + _pd__47*d_bottom_q_thd__q_rd_td
        + _pd__48*d_d_e_n__q_rd_td + _pd__49*d_g_lo_q_thd__q_rd_td)
    d_d_P0__q_th_td = (_pd__46*d_bottom_q_r__q_th_td + _pd__47*d_bottom_q_thd__q_th_td
        + _pd__48*d_d_e_n__q_th_td + _pd__49*d_g_lo_q_thd__q_th_td)
    d_d_P0__q_thd_td = (_pd__46*d_bottom_q_r__q_thd_td + _pd__47*d_bottom_q_thd__q_thd_td
        + _pd__48*d_d_e_n__q_thd_td + _pd__49*d_g_lo_q_thd__q_thd_td)
    d_d_P0__k_c = (_pd__46*d_bottom_q_r__k_c + _pd__47*d_bottom_q_thd__k_c + _pd__48*d_d_e_n__k_c
        + _pd__49*d_g_lo_q_thd__k_c)
    _x174 = m/math.sqrt(_x155)
    _x175 = (_x155 > 0.0)
    d_T0 = ((_x130*_x174 + t_bottom) if _x175 else (t_bottom))
    _pd__50 = ((_x174) if _x175 else (0.0))
    _pd__51 = ((-_x163*m/(_x155*math.sqrt(_x155))) if _x175 else (0.0))
    d_d_T0__q_r_td = _pd__50*d_d_e_n__q_r_td + _pd__51*d_d_rad_z__q_r_td + d_c_T__q_r_td
    d_d_T0__q_rd_td = _pd__50*d_d_e_n__q_rd_td + _pd__51*d_d_rad_z__q_rd_td + d_c_T__q_rd_td
    d_d_T0__q_th_td = _pd__50*d_d_e_n__q_th_td + _pd__51*d_d_rad_z__q_th_td + d_c_T__q_th_td
    d_d_T0__q_thd_td = _pd__50*d_d_e_n__q_thd_td + _pd__51*d_d_rad_z__q_thd_td + d_c_T__q_thd_td
    d_d_T0__k_c = _pd__50*d_d_e_n__k_c + _pd__51*d_d_rad_z__k_c + d_c_T__k_c
    d_d_T0__k_d = _pd__51*d_d_rad_z__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki1 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__q_r_td, d_d_e_n__q_rd_td, d_d_e_n__q_th_td, d_d_e_n__q_thd_td,
        d_d_e_n__k_c, 0.0, d_d_Q0__q_r_td, d_d_Q0__q_rd_td, d_d_Q0__q_th_td, d_d_Q0__q_thd_td, d_d_Q0__k_c,
        0.0, d_d_P0__q_r_td, d_d_P0__q_rd_td, d_d_P0__q_th_td, d_d_P0__q_thd_td, d_d_P0__k_c, 0.0,
        d_d_T0__q_r_td, d_d_T0__q_rd_td, d_d_T0__q_th_td, d_d_T0__q_thd_td, d_d_T0__k_c, d_d_T0__k_d, )
    _pk1 = _pki1
    d_steps = 0.0
    _conv1 = False
    _last1 = max(int(iterations), 0)
    for _it1 in range(_last1 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__q_r_td, d_d_e__q_rd_td, d_d_e__q_th_td, d_d_e__q_thd_td, d_d_e__k_c,
            d_d_e__k_d, d_d_Q__q_r_td, d_d_Q__q_rd_td, d_d_Q__q_th_td, d_d_Q__q_thd_td, d_d_Q__k_c,
            d_d_Q__k_d, d_d_P__q_r_td, d_d_P__q_rd_td, d_d_P__q_th_td, d_d_P__q_thd_td, d_d_P__k_c,
            d_d_P__k_d, d_d_T__q_r_td, d_d_T__q_rd_td, d_d_T__q_th_td, d_d_T__q_thd_td, d_d_T__k_c,
            d_d_T__k_d, ) = _pk1
        if _conv1 or _it1 == _last1:
            break
        _x176 = bottom_q_r + d_e
        d_x = _x176
        d_d_x__q_r_td = d_bottom_q_r__q_r_td + d_d_e__q_r_td
        d_d_x__q_rd_td = d_bottom_q_r__q_rd_td + d_d_e__q_rd_td
        d_d_x__q_th_td = d_bottom_q_r__q_th_td + d_d_e__q_th_td
        d_d_x__q_thd_td = d_bottom_q_r__q_thd_td + d_d_e__q_thd_td
        d_d_x__k_c = d_bottom_q_r__k_c + d_d_e__k_c
        _x177 = _x176**2
        _x178 = (1.0/_x177)
        _x179 = _x176**4*m
        _x180 = _x176**3
        _x181 = l0**2
        _x182 = _x177*_x181*m
        _x183 = math.cos(d_Q)
        _x184 = m**2
        _x185 = 2.0*_x184*g_s
        _x186 = 2.0*E_ba*_x177*m - _x179*k_d - _x180*_x183*_x185 + 2.0*_x180*k_d*l0*m - _x182*k_d - d_P**2
        d_rad = _x178*_x186
        _pd__52 = -2.0*_x178*d_P
        _pd__53 = _x176*_x185*math.sin(d_Q)
        _x187 = 2.0*m
        _pd__54 = (_x178*(4.0*E_ba*_x176*m - _x176*_x181*_x187*k_d - 6.0*_x177*_x183*_x184*g_s
            + 6.0*_x177*k_d*l0*m - 4.0*_x180*k_d*m) - 2.0*_x186/_x180)
        d_d_rad__q_r_td = (_pd__52*d_d_P__q_r_td + _pd__53*d_d_Q__q_r_td + _pd__54*d_d_x__q_r_td
            + _x187*d_E_ba__q_r_td)
        d_d_rad__q_rd_td = (_pd__52*d_d_P__q_rd_td + _pd__53*d_d_Q__q_rd_td + _pd__54*d_d_x__q_rd_td
            + _x187*d_E_ba__q_rd_td)
        d_d_rad__q_th_td = (_pd__52*d_d_P__q_th_td + _pd__53*d_d_Q__q_th_td + _pd__54*d_d_x__q_th_td
            + _x187*d_E_ba__q_th_td)
        d_d_rad__q_thd_td = (_pd__52*d_d_P__q_thd_td + _pd__53*d_d_Q__q_thd_td + _pd__54*d_d_x__q_thd_td
            + _x187*d_E_ba__q_thd_td)
        d_d_rad__k_c = _pd__52*d_d_P__k_c + _pd__53*d_d_Q__k_c + _pd__54*d_d_x__k_c + _x187*d_E_ba__k_c
        d_d_rad__k_d = (_pd__52*d_d_P__k_d + _pd__53*d_d_Q__k_d + _pd__54*d_d_e__k_d + _x178*(-_x179
            + 2.0*_x180*l0*m - _x182) + _x187*d_E_ba__k_d)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x188 = math.sqrt(d_rad)
        d_h = _x188
        _pd__55 = (0.5)/_x188
        d_d_h__q_r_td = _pd__55*d_d_rad__q_r_td
        d_d_h__q_rd_td = _pd__55*d_d_rad__q_rd_td
        d_d_h__q_th_td = _pd__55*d_d_rad__q_th_td
        d_d_h__q_thd_td = _pd__55*d_d_rad__q_thd_td
        d_d_h__k_c = _pd__55*d_d_rad__k_c
        d_d_h__k_d = _pd__55*d_d_rad__k_d
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x192 = (1.0/d_x)
            _x189 = _x192**2
            d_wq = _x189*d_e_next
            _pd__56 = _x189
            _pd__57 = -2.0*_x192**3*d_e_next
            _x190 = 4.0*_pd__56
            d_d_wq__q_r_td = _pd__57*d_d_x__q_r_td + _x190*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__57*d_d_x__q_rd_td + _x190*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__57*d_d_x__q_th_td + _x190*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__57*d_d_x__q_thd_td + _x190*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__57*d_d_x__k_c + _x190*d_d_e__k_c
            d_d_wq__k_d = _pd__57*d_d_e__k_d + _x190*d_d_e__k_d
            d_wp = d_e_next*d_x
            _x191 = 4.0*d_x
            d_d_wp__q_r_td = _x191*d_d_e__q_r_td + d_d_x__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x191*d_d_e__q_rd_td + d_d_x__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x191*d_d_e__q_th_td + d_d_x__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x191*d_d_e__q_thd_td + d_d_x__q_thd_td*d_e_next
            d_d_wp__k_c = _x191*d_d_e__k_c + d_d_x__k_c*d_e_next
            d_d_wp__k_d = _x191*d_d_e__k_d + d_d_e__k_d*d_e_next
        elif variant == 1.0:
            _x193 = (1.0/bottom_q_r)
            _x194 = bottom_q_r + d_e_next
            _x195 = (1.0/_x194)
            d_wq = _x193*_x195*d_e_next
            _x196 = _x193*_x195**2*d_e_next
            _pd__58 = -_x193**2*_x195*d_e_next - _x196
            _pd__59 = _x193*_x195 - _x196
            _x197 = 4.0*_pd__59
            d_d_wq__q_r_td = _pd__58*d_bottom_q_r__q_r_td + _x197*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__58*d_bottom_q_r__q_rd_td + _x197*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__58*d_bottom_q_r__q_th_td + _x197*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__58*d_bottom_q_r__q_thd_td + _x197*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__58*d_bottom_q_r__k_c + _x197*d_d_e__k_c
            d_d_wq__k_d = _x197*d_d_e__k_d
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__60 = _x194
            _x198 = 4.0*_pd__60
            d_d_wp__q_r_td = _x198*d_d_e__q_r_td + d_bottom_q_r__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x198*d_d_e__q_rd_td + d_bottom_q_r__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x198*d_d_e__q_th_td + d_bottom_q_r__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x198*d_d_e__q_thd_td + d_bottom_q_r__q_thd_td*d_e_next
            d_d_wp__k_c = _x198*d_d_e__k_c + d_bottom_q_r__k_c*d_e_next
            d_d_wp__k_d = _x198*d_d_e__k_d
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        d_e__next = d_e_next
        _x199 = (1.0/d_h)
        _x200 = _x199*d_wq
        d_Q__next = _x200*d_P + bottom_q_th
        _pd__61 = _x200
        _x201 = _x199**2
        _pd__62 = -_x201*d_P*d_wq
        _pd__63 = _x199*d_P
        d_d_Q__next__q_r_td = (_pd__61*d_d_P__q_r_td + _pd__62*d_d_h__q_r_td + _pd__63*d_d_wq__q_r_td
            + d_c_Q__q_r_td)
        d_d_Q__next__q_rd_td = (_pd__61*d_d_P__q_rd_td + _pd__62*d_d_h__q_rd_td + _pd__63*d_d_wq__q_rd_td
            + d_c_Q__q_rd_td)
        d_d_Q__next__q_th_td = (_pd__61*d_d_P__q_th_td + _pd__62*d_d_h__q_th_td + _pd__63*d_d_wq__q_th_td
            + d_c_Q__q_th_td)
        d_d_Q__next__q_thd_td = (_pd__61*d_d_P__q_thd_td + _pd__62*d_d_h__q_thd_td + _pd__63*d_d_wq__q_thd_td
            + d_c_Q__q_thd_td)
        d_d_Q__next__k_c = _pd__61*d_d_P__k_c + _pd__62*d_d_h__k_c + _pd__63*d_d_wq__k_c + d_c_Q__k_c
        d_d_Q__next__k_d = _pd__61*d_d_P__k_d + _pd__62*d_d_h__k_d + _pd__63*d_d_wq__k_d
        _x202 = bottom_q_r**2*m
        _x203 = math.sin(d_Q)
        _x204 = m**2
        _x205 = _x199*_x204*g_s
        _x206 = _x203*_x205
        d_P__next = _x202*bottom_q_thd + _x206*d_wp
        _pd__64 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__65 = _x202
        _pd__66 = _x205*d_wp*math.cos(d_Q)
        _pd__67 = -_x201*_x203*_x204*d_wp*g_s
        _pd__68 = _x206
        d_d_P__next__q_r_td = (_pd__64*d_bottom_q_r__q_r_td + _pd__65*d_bottom_q_thd__q_r_td
            + _pd__66*d_d_Q__q_r_td + _pd__67*d_d_h__q_r_td + _pd__68*d_d_wp__q_r_td)
        d_d_P__next__q_rd_td = (_pd__64*d_bottom_q_r__q_rd_td + _pd__65*d_bottom_q_thd__q_rd_td
            + _pd__66*d_d_Q__q_rd_td + _pd__67*d_d_h__q_rd_td + _pd__68*d_d_wp__q_rd_td)
        d_d_P__next__q_th_td = (_pd__64*d_bottom_q_r__q_th_td + _pd__65*d_bottom_q_thd__q_th_td
            + _pd__66*d_d_Q__q_th_td + _pd__67*d_d_h__q_th_td + _pd__68*d_d_wp__q_th_td)
        d_d_P__next__q_thd_td = (_pd__64*d_bottom_q_r__q_thd_td + _pd__65*d_bottom_q_thd__q_thd_td
            + _pd__66*d_d_Q__q_thd_td + _pd__67*d_d_h__q_thd_td + _pd__68*d_d_wp__q_thd_td)
        d_d_P__next__k_c = (_pd__64*d_bottom_q_r__k_c + _pd__65*d_bottom_q_thd__k_c + _pd__66*d_d_Q__k_c
            + _pd__67*d_d_h__k_c + _pd__68*d_d_wp__k_c)
        d_d_P__next__k_d = _pd__66*d_d_Q__k_d + _pd__67*d_d_h__k_d + _pd__68*d_d_wp__k_d
        _x207 = _x199*m
        d_T__next = _x207*d_e_next + t_bottom
        _pd__69 = _x207
        _pd__70 = -_x201*d_e_next*m
        _x208 = 4.0*_pd__69
        d_d_T__next__q_r_td = _pd__70*d_d_h__q_r_td + _x208*d_d_e__q_r_td + d_c_T__q_r_td
        d_d_T__next__q_rd_td = _pd__70*d_d_h__q_rd_td + _x208*d_d_e__q_rd_td + d_c_T__q_rd_td
        d_d_T__next__q_th_td = _pd__70*d_d_h__q_th_td + _x208*d_d_e__q_th_td + d_c_T__q_th_td
        d_d_T__next__q_thd_td = _pd__70*d_d_h__q_thd_td + _x208*d_d_e__q_thd_td + d_c_T__q_thd_td
        d_d_T__next__k_c = _pd__70*d_d_h__k_c + _x208*d_d_e__k_c + d_c_T__k_c
        d_d_T__next__k_d = _pd__70*d_d_h__k_d + _x208*d_d_e__k_d
        _n1_4 = 4.0*d_d_e__q_r_td
        _n1_5 = 4.0*d_d_e__q_rd_td
        _n1_6 = 4.0*d_d_e__q_th_td
        _n1_7 = 4.0*d_d_e__q_thd_td
        _n1_8 = 4.0*d_d_e__k_c
        _n1_9 = 4.0*d_d_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn1 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n1_4, _n1_5, _n1_6, _n1_7, _n1_8, _n1_9,
            d_d_Q__next__q_r_td, d_d_Q__next__q_rd_td, d_d_Q__next__q_th_td, d_d_Q__next__q_thd_td,
            d_d_Q__next__k_c, d_d_Q__next__k_d, d_d_P__next__q_r_td, d_d_P__next__q_rd_td,
            d_d_P__next__q_th_td, d_d_P__next__q_thd_td, d_d_P__next__k_c, d_d_P__next__k_d,
            d_d_T__next__q_r_td, d_d_T__next__q_rd_td, d_d_T__next__q_th_td, d_d_T__next__q_thd_td,
            d_d_T__next__k_c, d_d_T__next__k_d, )
        _pk1 = _pkn1
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x209 = q_r_lo**2
    _x210 = (1.0/_x209)
    _x211 = m*q_r_lo**4
    _x212 = q_r_lo**3
    _x213 = _x209*l0**2*m
    _x214 = 2.0*g_s*m**2
    rad_lo = (_x210*(2.0*E_ba*_x209*m - _x211*k_d - _x212*_x214*math.cos(d_Q) + 2.0*_x212*k_d*l0*m - _x213*k_d
        - d_P**2))
    _pd__71 = -2.0*_x210*d_P
    _pd__72 = _x214*q_r_lo*math.sin(d_Q)
    _x215 = 2.0*m
    d_rad_lo__q_r_td = _pd__71*d_d_P__q_r_td + _pd__72*d_d_Q__q_r_td + _x215*d_E_ba__q_r_td
    d_rad_lo__q_rd_td = _pd__71*d_d_P__q_rd_td + _pd__72*d_d_Q__q_rd_td + _x215*d_E_ba__q_rd_td
    d_rad_lo__q_th_td = _pd__71*d_d_P__q_th_td + _pd__72*d_d_Q__q_th_td + _x215*d_E_ba__q_th_td
    d_rad_lo__q_thd_td = _pd__71*d_d_P__q_thd_td + _pd__72*d_d_Q__q_thd_td + _x215*d_E_ba__q_thd_td
    d_rad_lo__k_c = _pd__71*d_d_P__k_c + _pd__72*d_d_Q__k_c + _x215*d_E_ba__k_c
    d_rad_lo__k_d = (_pd__71*d_d_P__k_d + _pd__72*d_d_Q__k_d + _x210*(-_x211 + 2.0*_x212*l0*m - _x213)
        + _x215*d_E_ba__k_d)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x216 = (1.0/m)
    _x217 = math.sqrt(rad_lo)
    liftoff_q_rd = _x216*_x217
    _pd__73 = (0.5)*_x216/_x217
    d_liftoff_q_rd__q_r_td = _pd__73*d_rad_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _pd__73*d_rad_lo__q_rd_td
    d_liftoff_q_rd__q_th_td = _pd__73*d_rad_lo__q_th_td
    d_liftoff_q_rd__q_thd_td = _pd__73*d_rad_lo__q_thd_td
    d_liftoff_q_rd__k_c = _pd__73*d_rad_lo__k_c
    d_liftoff_q_rd__k_d = _pd__73*d_rad_lo__k_d
    liftoff_q_th = d_Q
    _x218 = _x216/q_r_lo**2
    liftoff_q_thd = _x218*d_P
    _pd__74 = _x218
    d_liftoff_q_thd__q_r_td = _pd__74*d_d_P__q_r_td
    d_liftoff_q_thd__q_rd_td = _pd__74*d_d_P__q_rd_td
    d_liftoff_q_thd__q_th_td = _pd__74*d_d_P__q_th_td
    d_liftoff_q_thd__q_thd_td = _pd__74*d_d_P__q_thd_td
    d_liftoff_q_thd__k_c = _pd__74*d_d_P__k_c
    d_liftoff_q_thd__k_d = _pd__74*d_d_P__k_d
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN70 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_c_T__q_r_td
    d_t_bottom__q_rd_td = d_c_T__q_rd_td
    d_t_bottom__q_th_td = d_c_T__q_th_td
    d_t_bottom__q_thd_td = d_c_T__q_thd_td
    d_t_bottom__k_c = d_c_T__k_c
    d_t_bottom__k_d = 0.0
    d_t_stance__q_r_td = d_d_T__q_r_td
    d_t_stance__q_rd_td = d_d_T__q_rd_td
    d_t_stance__q_th_td = d_d_T__q_th_td
    d_t_stance__q_thd_td = d_d_T__q_thd_td
    d_t_stance__k_c = d_d_T__k_c
    d_t_stance__k_d = d_d_T__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__q_r_td = d_c_Q__q_r_td
    d_bottom_q_th__q_rd_td = d_c_Q__q_rd_td
    d_bottom_q_th__q_th_td = d_c_Q__q_th_td
    d_bottom_q_th__q_thd_td = d_c_Q__q_thd_td
    d_bottom_q_th__k_c = d_c_Q__k_c
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_th__q_r_td = d_d_Q__q_r_td
    d_liftoff_q_th__q_rd_td = d_d_Q__q_rd_td
    d_liftoff_q_th__q_th_td = d_d_Q__q_th_td
    d_liftoff_q_th__q_thd_td = d_d_Q__q_thd_td
    d_liftoff_q_th__k_c = d_d_Q__k_c
    d_liftoff_q_th__k_d = d_d_Q__k_d
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
def iterative_report_stance_jacobian_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian_zeroth_held`: arguments, out and status
    as :func:`iterative_report_stance_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_jacobian_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
            and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f
            > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_jacobian_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length))
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # the code shared between choices
    return (iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian_zeroth_held`: arguments, out and
    status as :func:`iterative_report_apex_return_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_jacobian_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        store_row_12_84(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1522
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN70 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 1.0, 0.0))
    if _c0[72] != STATUS_OK:
        return _NAN70 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # E_ab (114) of the touchdown state
    _x0 = k_c*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*l0 + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__q_r_td = _x0 + _x5 + _x6*q_r_td - k_c*l0
    d_E_ab__q_rd_td = m*q_rd_td
    d_E_ab__q_th_td = -_x4*q_r_td*math.sin(q_th_td)
    d_E_ab__q_thd_td = _x2*m*q_thd_td
    d_E_ab__k_c = _x1 + _x3 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_bottom_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_bottom_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_bottom_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_bottom_q_r__k_c = _j_z_b_q_r__k
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic_jac_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[4] != STATUS_OK:
            return _NAN70 + (_c1[4],)
        bottom_q_r = _c1[0]
        _j_bottom_q_r__p = _c1[1]
        _j_bottom_q_r__E_ab = _c1[2]
        _j_bottom_q_r__k_c = _c1[3]
        # chain rule through bottom_quartic
        _x7 = _j_bottom_q_r__p*m
        d_bottom_q_r__q_r_td = _j_bottom_q_r__E_ab*d_E_ab__q_r_td + 2.0*_x7*q_r_td*q_thd_td
        d_bottom_q_r__q_rd_td = _j_bottom_q_r__E_ab*d_E_ab__q_rd_td
        d_bottom_q_r__q_th_td = _j_bottom_q_r__E_ab*d_E_ab__q_th_td
        d_bottom_q_r__q_thd_td = _j_bottom_q_r__E_ab*d_E_ab__q_thd_td + _x7*q_r_td**2
        d_bottom_q_r__k_c = _j_bottom_q_r__E_ab*d_E_ab__k_c + _j_bottom_q_r__k_c
    else:
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN70 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = bottom_q_r - q_r_td
    _x10 = _x8*_x9
    c_e_n = _x10
    _pd__0 = _x8
    _x11 = -_x8
    d_c_e_n__q_r_td = _pd__0*d_bottom_q_r__q_r_td + _x11
    d_c_e_n__q_rd_td = _pd__0*d_bottom_q_r__q_rd_td
    d_c_e_n__q_th_td = _pd__0*d_bottom_q_r__q_th_td
    d_c_e_n__q_thd_td = _pd__0*d_bottom_q_r__q_thd_td
    d_c_e_n__k_c = _pd__0*d_bottom_q_r__k_c
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
    d_c_rad_z__q_r_td = (_j_z_b_q_r__q_r_td*_pd__3 + _j_z_b_q_th__q_r_td*_pd__4 + _j_z_b_q_thd__q_r_td*_pd__5
        + _pd__1*d_bottom_q_r__q_r_td + _x15*(-_x27*(-_x23*_x41 + _x24*_x46*q_r_td*q_thd_td) - _x39 - _x47)
        + _x42 + _x51*d_c_e_n__q_r_td + _x52*d_E_ab__q_r_td)
    d_c_rad_z__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__3 + _j_z_b_q_th__q_rd_td*_pd__4
        + _j_z_b_q_thd__q_rd_td*_pd__5 + _pd__1*d_bottom_q_r__q_rd_td + _x51*d_c_e_n__q_rd_td
        + _x52*d_E_ab__q_rd_td)
    d_c_rad_z__q_th_td = (_j_z_b_q_r__q_th_td*_pd__3 + _j_z_b_q_th__q_th_td*_pd__4
        + _j_z_b_q_thd__q_th_td*_pd__5 + _pd__1*d_bottom_q_r__q_th_td + _x24*_x50 + _x51*d_c_e_n__q_th_td
        + _x52*d_E_ab__q_th_td)
    d_c_rad_z__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__3 + _j_z_b_q_th__q_thd_td*_pd__4
        + _j_z_b_q_thd__q_thd_td*_pd__5 + _pd__1*d_bottom_q_r__q_thd_td - 2.0*_x24*_x25*_x49
        + _x51*d_c_e_n__q_thd_td + _x52*d_E_ab__q_thd_td)
    d_c_rad_z__k_c = (_j_z_b_q_r__k*_pd__3 + _j_z_b_q_th__k*_pd__4 + _j_z_b_q_thd__k*_pd__5
        + _pd__1*d_bottom_q_r__k_c + _x15*(-_x16 + 2.0*_x17*l0*m - _x19) + _x51*d_c_e_n__k_c
        + _x52*d_E_ab__k_c)
    _x53 = math.sqrt(_x11 + 1.0)
    c_Q0 = _x29*_x53 + z_b_q_th
    _x54 = (0.5)/_x53
    _x55 = _x36*_x54
    _x56 = _x55*_x8
    _pd__6 = _x56
    _pd__7 = -_x55
    _pd__8 = 1.0 - _x53
    d_c_Q0__q_r_td = _j_z_b_q_th__q_r_td*_pd__8 + _pd__6*d_bottom_q_r__q_r_td + _pd__7*d_c_e_n__q_r_td - _x56
    d_c_Q0__q_rd_td = _j_z_b_q_th__q_rd_td*_pd__8 + _pd__6*d_bottom_q_r__q_rd_td + _pd__7*d_c_e_n__q_rd_td
    d_c_Q0__q_th_td = (_j_z_b_q_th__q_th_td*_pd__8 + _pd__6*d_bottom_q_r__q_th_td + _pd__7*d_c_e_n__q_th_td
        + _x53)
    d_c_Q0__q_thd_td = _j_z_b_q_th__q_thd_td*_pd__8 + _pd__6*d_bottom_q_r__q_thd_td + _pd__7*d_c_e_n__q_thd_td
    d_c_Q0__k_c = _j_z_b_q_th__k*_pd__8 + _pd__6*d_bottom_q_r__k_c + _pd__7*d_c_e_n__k_c
    c_P0 = _x22 + _x26*_x53
    _x57 = _x40*_x54
    _x58 = _x57*_x8
    _pd__9 = _x58
    _pd__10 = -_x57
    _pd__11 = -_x48*_x52*_x53 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__12 = _x20*m - _x21*_x53
    d_c_P0__q_r_td = (_j_z_b_q_r__q_r_td*_pd__11 + _j_z_b_q_thd__q_r_td*_pd__12 + _pd__10*d_c_e_n__q_r_td
        + _pd__9*d_bottom_q_r__q_r_td + _x43*_x53*m*q_thd_td - _x58)
    d_c_P0__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__11 + _j_z_b_q_thd__q_rd_td*_pd__12 + _pd__10*d_c_e_n__q_rd_td
        + _pd__9*d_bottom_q_r__q_rd_td)
    d_c_P0__q_th_td = (_j_z_b_q_r__q_th_td*_pd__11 + _j_z_b_q_thd__q_th_td*_pd__12 + _pd__10*d_c_e_n__q_th_td
        + _pd__9*d_bottom_q_r__q_th_td)
    d_c_P0__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__11 + _j_z_b_q_thd__q_thd_td*_pd__12
        + _pd__10*d_c_e_n__q_thd_td + _pd__9*d_bottom_q_r__q_thd_td + _x25*_x53)
    d_c_P0__k_c = (_j_z_b_q_r__k*_pd__11 + _j_z_b_q_thd__k*_pd__12 + _pd__10*d_c_e_n__k_c
        + _pd__9*d_bottom_q_r__k_c)
    _x59 = m/math.sqrt(_x33)
    _x60 = (_x33 > 0.0)
    c_T0 = ((-_x10*_x59) if _x60 else (0.0))
    _pd__13 = ((-_x59) if _x60 else (0.0))
    _pd__14 = ((_x44*m/(_x33*math.sqrt(_x33))) if _x60 else (0.0))
    d_c_T0__q_r_td = _pd__13*d_c_e_n__q_r_td + _pd__14*d_c_rad_z__q_r_td
    d_c_T0__q_rd_td = _pd__13*d_c_e_n__q_rd_td + _pd__14*d_c_rad_z__q_rd_td
    d_c_T0__q_th_td = _pd__13*d_c_e_n__q_th_td + _pd__14*d_c_rad_z__q_th_td
    d_c_T0__q_thd_td = _pd__13*d_c_e_n__q_thd_td + _pd__14*d_c_rad_z__q_thd_td
    d_c_T0__k_c = _pd__13*d_c_e_n__k_c + _pd__14*d_c_rad_z__k_c
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__q_r_td, d_c_e_n__q_rd_td, d_c_e_n__q_th_td, d_c_e_n__q_thd_td,
        d_c_e_n__k_c, d_c_Q0__q_r_td, d_c_Q0__q_rd_td, d_c_Q0__q_th_td, d_c_Q0__q_thd_td, d_c_Q0__k_c,
        d_c_P0__q_r_td, d_c_P0__q_rd_td, d_c_P0__q_th_td, d_c_P0__q_thd_td, d_c_P0__k_c, d_c_T0__q_r_td,
        d_c_T0__q_rd_td, d_c_T0__q_th_td, d_c_T0__q_thd_td, d_c_T0__k_c, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__q_r_td, d_c_e__q_rd_td, d_c_e__q_th_td, d_c_e__q_thd_td, d_c_e__k_c,
            d_c_Q__q_r_td, d_c_Q__q_rd_td, d_c_Q__q_th_td, d_c_Q__q_thd_td, d_c_Q__k_c, d_c_P__q_r_td,
            d_c_P__q_rd_td, d_c_P__q_th_td, d_c_P__q_thd_td, d_c_P__k_c, d_c_T__q_r_td, d_c_T__q_rd_td,
            d_c_T__q_th_td, d_c_T__q_thd_td, d_c_T__k_c, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x61 = c_e + q_r_td
        c_x = _x61
        d_c_x__q_r_td = d_c_e__q_r_td + 1.0
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
        d_c_rad__q_r_td = (_pd__15*d_c_P__q_r_td + _pd__16*d_c_Q__q_r_td + _pd__17*d_c_x__q_r_td
            + _x72*d_E_ab__q_r_td)
        d_c_rad__q_rd_td = (_pd__15*d_c_P__q_rd_td + _pd__16*d_c_Q__q_rd_td + _pd__17*d_c_e__q_rd_td
            + _x72*d_E_ab__q_rd_td)
        d_c_rad__q_th_td = (_pd__15*d_c_P__q_th_td + _pd__16*d_c_Q__q_th_td + _pd__17*d_c_e__q_th_td
            + _x72*d_E_ab__q_th_td)
        d_c_rad__q_thd_td = (_pd__15*d_c_P__q_thd_td + _pd__16*d_c_Q__q_thd_td + _pd__17*d_c_e__q_thd_td
            + _x72*d_E_ab__q_thd_td)
        d_c_rad__k_c = (_pd__15*d_c_P__k_c + _pd__16*d_c_Q__k_c + _pd__17*d_c_e__k_c + _x63*(-_x64
            + 2.0*_x65*l0*m - _x67) + _x72*d_E_ab__k_c)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x73 = math.sqrt(c_rad)
        c_h = _x73
        _pd__18 = (0.5)/_x73
        d_c_h__q_r_td = _pd__18*d_c_rad__q_r_td
        d_c_h__q_rd_td = _pd__18*d_c_rad__q_rd_td
        d_c_h__q_th_td = _pd__18*d_c_rad__q_th_td
        d_c_h__q_thd_td = _pd__18*d_c_rad__q_thd_td
        d_c_h__k_c = _pd__18*d_c_rad__k_c
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x77 = (1.0/c_x)
            _x74 = _x77**2
            c_wq = _x74*c_e_next
            _pd__19 = _x74
            _pd__20 = -2.0*_x77**3*c_e_next
            _x75 = 4.0*_pd__19
            d_c_wq__q_r_td = _pd__20*d_c_x__q_r_td + _x75*d_c_e__q_r_td
            d_c_wq__q_rd_td = _pd__20*d_c_e__q_rd_td + _x75*d_c_e__q_rd_td
            d_c_wq__q_th_td = _pd__20*d_c_e__q_th_td + _x75*d_c_e__q_th_td
            d_c_wq__q_thd_td = _pd__20*d_c_e__q_thd_td + _x75*d_c_e__q_thd_td
            d_c_wq__k_c = _pd__20*d_c_e__k_c + _x75*d_c_e__k_c
            c_wp = c_e_next*c_x
            _x76 = 4.0*c_x
            d_c_wp__q_r_td = _x76*d_c_e__q_r_td + c_e_next*d_c_x__q_r_td
            d_c_wp__q_rd_td = _x76*d_c_e__q_rd_td + c_e_next*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x76*d_c_e__q_th_td + c_e_next*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x76*d_c_e__q_thd_td + c_e_next*d_c_e__q_thd_td
            d_c_wp__k_c = _x76*d_c_e__k_c + c_e_next*d_c_e__k_c
        elif variant == 1.0:
            _x78 = (1.0/q_r_td)
            _x79 = c_e_next + q_r_td
            _x80 = (1.0/_x79)
            c_wq = _x78*_x80*c_e_next
            _x81 = _x78*_x80**2*c_e_next
            _pd__21 = _x78*_x80 - _x81
            d_c_wq__q_r_td = 4.0*_pd__21*d_c_e__q_r_td - _x78**2*_x80*c_e_next - _x81
            _x82 = 4.0*_pd__21
            d_c_wq__q_rd_td = _x82*d_c_e__q_rd_td
            d_c_wq__q_th_td = _x82*d_c_e__q_th_td
            d_c_wq__q_thd_td = _x82*d_c_e__q_thd_td
            d_c_wq__k_c = _x82*d_c_e__k_c
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__22 = _x79
            _x83 = 4.0*_pd__22
            d_c_wp__q_r_td = _x83*d_c_e__q_r_td + c_e_next
            d_c_wp__q_rd_td = _x83*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x83*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x83*d_c_e__q_thd_td
            d_c_wp__k_c = _x83*d_c_e__k_c
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        c_e__next = c_e_next
        _x84 = (1.0/c_h)
        _x85 = _x84*c_wq
        c_Q__next = -_x85*c_P + q_th_td
        _pd__23 = -_x85
        _x86 = _x84**2
        _pd__24 = _x86*c_P*c_wq
        _pd__25 = -_x84*c_P
        d_c_Q__next__q_r_td = _pd__23*d_c_P__q_r_td + _pd__24*d_c_h__q_r_td + _pd__25*d_c_wq__q_r_td
        d_c_Q__next__q_rd_td = _pd__23*d_c_P__q_rd_td + _pd__24*d_c_h__q_rd_td + _pd__25*d_c_wq__q_rd_td
        d_c_Q__next__q_th_td = _pd__23*d_c_P__q_th_td + _pd__24*d_c_h__q_th_td + _pd__25*d_c_wq__q_th_td + 1.0
        d_c_Q__next__q_thd_td = _pd__23*d_c_P__q_thd_td + _pd__24*d_c_h__q_thd_td + _pd__25*d_c_wq__q_thd_td
        d_c_Q__next__k_c = _pd__23*d_c_P__k_c + _pd__24*d_c_h__k_c + _pd__25*d_c_wq__k_c
        _x87 = m*q_r_td**2
        _x88 = math.sin(c_Q)
        _x89 = m**2
        _x90 = _x84*_x89*g_s
        _x91 = _x88*_x90
        c_P__next = _x87*q_thd_td - _x91*c_wp
        _pd__26 = -_x90*c_wp*math.cos(c_Q)
        _pd__27 = _x86*_x88*_x89*c_wp*g_s
        _pd__28 = -_x91
        d_c_P__next__q_r_td = (_pd__26*d_c_Q__q_r_td + _pd__27*d_c_h__q_r_td + _pd__28*d_c_wp__q_r_td
            + 2.0*m*q_r_td*q_thd_td)
        d_c_P__next__q_rd_td = _pd__26*d_c_Q__q_rd_td + _pd__27*d_c_h__q_rd_td + _pd__28*d_c_wp__q_rd_td
        d_c_P__next__q_th_td = _pd__26*d_c_Q__q_th_td + _pd__27*d_c_h__q_th_td + _pd__28*d_c_wp__q_th_td
        d_c_P__next__q_thd_td = (_pd__26*d_c_Q__q_thd_td + _pd__27*d_c_h__q_thd_td + _pd__28*d_c_wp__q_thd_td
            + _x87)
        d_c_P__next__k_c = _pd__26*d_c_Q__k_c + _pd__27*d_c_h__k_c + _pd__28*d_c_wp__k_c
        _x92 = _x84*m
        c_T__next = -_x92*c_e_next
        _pd__29 = -_x92
        _pd__30 = _x86*c_e_next*m
        _x93 = 4.0*_pd__29
        d_c_T__next__q_r_td = _pd__30*d_c_h__q_r_td + _x93*d_c_e__q_r_td
        d_c_T__next__q_rd_td = _pd__30*d_c_h__q_rd_td + _x93*d_c_e__q_rd_td
        d_c_T__next__q_th_td = _pd__30*d_c_h__q_th_td + _x93*d_c_e__q_th_td
        d_c_T__next__q_thd_td = _pd__30*d_c_h__q_thd_td + _x93*d_c_e__q_thd_td
        d_c_T__next__k_c = _pd__30*d_c_h__k_c + _x93*d_c_e__k_c
        _n0_4 = 4.0*d_c_e__q_r_td
        _n0_5 = 4.0*d_c_e__q_rd_td
        _n0_6 = 4.0*d_c_e__q_th_td
        _n0_7 = 4.0*d_c_e__q_thd_td
        _n0_8 = 4.0*d_c_e__k_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8,
            d_c_Q__next__q_r_td, d_c_Q__next__q_rd_td, d_c_Q__next__q_th_td, d_c_Q__next__q_thd_td,
            d_c_Q__next__k_c, d_c_P__next__q_r_td, d_c_P__next__q_rd_td, d_c_P__next__q_th_td,
            d_c_P__next__q_thd_td, d_c_P__next__k_c, d_c_T__next__q_r_td, d_c_T__next__q_rd_td,
            d_c_T__next__q_th_td, d_c_T__next__q_thd_td, d_c_T__next__k_c, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    _x94 = (1.0/m)
    _x96 = (1.0/bottom_q_r)
    _x95 = _x94*_x96**2
    bottom_q_thd = _x95*c_P
    _pd__31 = -2.0*_x94*_x96**3*c_P
    _pd__32 = _x95
    d_bottom_q_thd__q_r_td = _pd__31*d_bottom_q_r__q_r_td + _pd__32*d_c_P__q_r_td
    d_bottom_q_thd__q_rd_td = _pd__31*d_bottom_q_r__q_rd_td + _pd__32*d_c_P__q_rd_td
    d_bottom_q_thd__q_th_td = _pd__31*d_bottom_q_r__q_th_td + _pd__32*d_c_P__q_th_td
    d_bottom_q_thd__q_thd_td = _pd__31*d_bottom_q_r__q_thd_td + _pd__32*d_c_P__q_thd_td
    d_bottom_q_thd__k_c = _pd__31*d_bottom_q_r__k_c + _pd__32*d_c_P__k_c
    # E_ba of (98): the energy jump of the stiffness switch
    _x97 = (-bottom_q_r + l0)**2
    _x98 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x97*_x98
    _pd__33 = _x98*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__q_r_td = _pd__33*d_bottom_q_r__q_r_td + d_E_ab__q_r_td
    d_E_ba__q_rd_td = _pd__33*d_bottom_q_r__q_rd_td + d_E_ab__q_rd_td
    d_E_ba__q_th_td = _pd__33*d_bottom_q_r__q_th_td + d_E_ab__q_th_td
    d_E_ba__q_thd_td = _pd__33*d_bottom_q_r__q_thd_td + d_E_ab__q_thd_td
    _x99 = (0.5)*_x97
    d_E_ba__k_c = _pd__33*d_bottom_q_r__k_c - _x99 + d_E_ab__k_c
    d_E_ba__k_d = _x99
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN70 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x100 = 4.0**(-iterations)
    _x101 = -bottom_q_r + q_r_lo
    _x102 = _x100*_x101
    d_e_n = _x102
    _pd__34 = -_x100
    d_d_e_n__q_r_td = _pd__34*d_bottom_q_r__q_r_td
    d_d_e_n__q_rd_td = _pd__34*d_bottom_q_r__q_rd_td
    d_d_e_n__q_th_td = _pd__34*d_bottom_q_r__q_th_td
    d_d_e_n__q_thd_td = _pd__34*d_bottom_q_r__q_thd_td
    d_d_e_n__k_c = _pd__34*d_bottom_q_r__k_c
    _x103 = (0.25)*_x102
    d_e_z = _x103
    _x104 = _x103 + bottom_q_r
    _x105 = _x104**2
    _x106 = (1.0/_x105)
    _x107 = _x104**4*m
    _x108 = _x104**3
    _x109 = l0**2*m
    _x110 = _x105*_x109
    _x111 = bottom_q_r**2*m
    _x112 = _x111*bottom_q_thd
    _x113 = q_r_lo**2
    _x114 = -_x112 + _x113*g_lo_q_thd*m
    _x115 = 4.0**((0.5)*iterations)
    _x116 = (1.0/_x115)
    _x117 = (0.5)*_x116
    _x118 = _x114*_x117
    _x119 = _x112 + _x118
    _x120 = -bottom_q_th + g_lo_q_th
    _x121 = _x117*_x120
    _x122 = _x121 + bottom_q_th
    _x123 = m**2
    _x124 = _x123*g_s
    _x125 = _x124*math.cos(_x122)
    _x126 = 2.0*E_ba*_x105*m - _x107*k_d - 2.0*_x108*_x125 + 2.0*_x108*k_d*l0*m - _x110*k_d - _x119**2
    _x127 = _x106*_x126
    d_rad_z = _x127
    _x128 = -2.0*_x126/_x108
    _x129 = 4.0*m
    _x130 = (1.0/_x101)
    _x131 = 2.0*bottom_q_r
    _x132 = _x131*bottom_q_thd*m
    _x133 = -_x116*_x132 + _x118*_x130
    _x134 = math.sin(_x122)
    _x135 = (0.5)*_x102
    _x136 = _x131 + _x135
    _x137 = -2.0*E_ba*_x136*m + 6.0*_x105*_x125 - 6.0*_x105*k_d*l0*m + _x108*_x129*k_d + _x109*_x136*k_d
    _pd__35 = (_x106*((0.5)*_x108*_x116*_x120*_x123*_x130*_x134*g_s - _x119*(_x129*bottom_q_r*bottom_q_thd
        + _x133) - _x137) + _x128)
    _x138 = _x104*_x124*_x134
    _pd__36 = 2.0*_x138*(1.0 - _x117)
    _x139 = -_x111*_x116
    _x140 = _x106*_x119
    _pd__37 = -_x140*(2.0*_x111 + _x139)
    _x141 = _x115*_x130
    _pd__38 = _x106*(2.0*_x108*_x115*_x120*_x123*_x130*_x134*g_s - 2.0*_x114*_x119*_x141 - _x137) + _x128
    _pd__39 = _x116*_x138
    _x142 = _x113*_x116*m
    _pd__40 = -_x140*_x142
    _x143 = (0.25)*_pd__38
    _x144 = 2.0*m
    d_d_rad_z__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__39 + _j_z_lo_q_thd__q_r_td*_pd__40
        + _pd__35*d_bottom_q_r__q_r_td + _pd__36*d_c_Q__q_r_td + _pd__37*d_bottom_q_thd__q_r_td
        + _x143*d_d_e_n__q_r_td + _x144*d_E_ba__q_r_td)
    d_d_rad_z__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__39 + _j_z_lo_q_thd__q_rd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_rd_td + _pd__36*d_c_Q__q_rd_td + _pd__37*d_bottom_q_thd__q_rd_td
        + _x143*d_d_e_n__q_rd_td + _x144*d_E_ba__q_rd_td)
    d_d_rad_z__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__39 + _j_z_lo_q_thd__q_th_td*_pd__40
        + _pd__35*d_bottom_q_r__q_th_td + _pd__36*d_c_Q__q_th_td + _pd__37*d_bottom_q_thd__q_th_td
        + _x143*d_d_e_n__q_th_td + _x144*d_E_ba__q_th_td)
    d_d_rad_z__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__39 + _j_z_lo_q_thd__q_thd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_thd_td + _pd__36*d_c_Q__q_thd_td + _pd__37*d_bottom_q_thd__q_thd_td
        + _x143*d_d_e_n__q_thd_td + _x144*d_E_ba__q_thd_td)
    d_d_rad_z__k_c = (_j_z_lo_q_th__k*_pd__39 + _j_z_lo_q_thd__k*_pd__40 + _pd__35*d_bottom_q_r__k_c
        + _pd__36*d_c_Q__k_c + _pd__37*d_bottom_q_thd__k_c + _x143*d_d_e_n__k_c + _x144*d_E_ba__k_c)
    d_d_rad_z__k_d = _x106*(-_x107 + 2.0*_x108*l0*m - _x110) + _x144*d_E_ba__k_d
    d_Q0 = _x116*_x120 + bottom_q_th
    _pd__41 = _x121*_x130
    _pd__42 = 1.0 - _x116
    _x145 = (0.5)*_x141
    _pd__43 = _x120*_x145
    _pd__44 = _x116
    d_d_Q0__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__44 + _pd__41*d_bottom_q_r__q_r_td + _pd__42*d_c_Q__q_r_td
        + _pd__43*d_d_e_n__q_r_td)
    d_d_Q0__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__44 + _pd__41*d_bottom_q_r__q_rd_td + _pd__42*d_c_Q__q_rd_td
        + _pd__43*d_d_e_n__q_rd_td)
    d_d_Q0__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__44 + _pd__41*d_bottom_q_r__q_th_td + _pd__42*d_c_Q__q_th_td
        + _pd__43*d_d_e_n__q_th_td)
    d_d_Q0__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__44 + _pd__41*d_bottom_q_r__q_thd_td
        + _pd__42*d_c_Q__q_thd_td + _pd__43*d_d_e_n__q_thd_td)
    d_d_Q0__k_c = (_j_z_lo_q_th__k*_pd__44 + _pd__41*d_bottom_q_r__k_c + _pd__42*d_c_Q__k_c
        + _pd__43*d_d_e_n__k_c)
    d_P0 = _x112 + _x114*_x116
    _pd__45 = _x132 + _x133
    _pd__46 = _x111 + _x139
    _pd__47 = _x114*_x145
    _pd__48 = _x142
    d_d_P0__q_r_td = (_j_z_lo_q_thd__q_r_td*_pd__48 + _pd__45*d_bottom_q_r__q_r_td
        + _pd__46*d_bottom_q_thd__q_r_td + _pd__47*d_d_e_n__q_r_td)
    d_d_P0__q_rd_td = (_j_z_lo_q_thd__q_rd_td*_pd__48 + _pd__45*d_bottom_q_r__q_rd_td
        + _pd__46*d_bottom_q_thd__q_rd_td + _pd__47*d_d_e_n__q_rd_td)
    d_d_P0__q_th_td = (_j_z_lo_q_thd__q_th_td*_pd__48 + _pd__45*d_bottom_q_r__q_th_td
        + _pd__46*d_bottom_q_thd__q_th_td + _pd__47*d_d_e_n__q_th_td)
    d_d_P0__q_thd_td = (_j_z_lo_q_thd__q_thd_td*_pd__48 + _pd__45*d_bottom_q_r__q_thd_td
        + _pd__46*d_bottom_q_thd__q_thd_td + _pd__47*d_d_e_n__q_thd_td)
    d_d_P0__k_c = (_j_z_lo_q_thd__k*_pd__48 + _pd__45*d_bottom_q_r__k_c + _pd__46*d_bottom_q_thd__k_c
        + _pd__47*d_d_e_n__k_c)
    _x146 = m/math.sqrt(_x127)
    _x147 = (_x127 > 0.0)
    d_T0 = ((_x102*_x146 + t_bottom) if _x147 else (t_bottom))
    _pd__49 = ((_x146) if _x147 else (0.0))
    _pd__50 = ((-_x135*m/(_x127*math.sqrt(_x127))) if _x147 else (0.0))
    d_d_T0__q_r_td = _pd__49*d_d_e_n__q_r_td + _pd__50*d_d_rad_z__q_r_td + d_c_T__q_r_td
    d_d_T0__q_rd_td = _pd__49*d_d_e_n__q_rd_td + _pd__50*d_d_rad_z__q_rd_td + d_c_T__q_rd_td
    d_d_T0__q_th_td = _pd__49*d_d_e_n__q_th_td + _pd__50*d_d_rad_z__q_th_td + d_c_T__q_th_td
    d_d_T0__q_thd_td = _pd__49*d_d_e_n__q_thd_td + _pd__50*d_d_rad_z__q_thd_td + d_c_T__q_thd_td
    d_d_T0__k_c = _pd__49*d_d_e_n__k_c + _pd__50*d_d_rad_z__k_c + d_c_T__k_c
    d_d_T0__k_d = _pd__50*d_d_rad_z__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki1 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__q_r_td, d_d_e_n__q_rd_td, d_d_e_n__q_th_td, d_d_e_n__q_thd_td,
        d_d_e_n__k_c, 0.0, d_d_Q0__q_r_td, d_d_Q0__q_rd_td, d_d_Q0__q_th_td, d_d_Q0__q_thd_td, d_d_Q0__k_c,
        0.0, d_d_P0__q_r_td, d_d_P0__q_rd_td, d_d_P0__q_th_td, d_d_P0__q_thd_td, d_d_P0__k_c, 0.0,
        d_d_T0__q_r_td, d_d_T0__q_rd_td, d_d_T0__q_th_td, d_d_T0__q_thd_td, d_d_T0__k_c, d_d_T0__k_d, )
    _pk1 = _pki1
    d_steps = 0.0
    _conv1 = False
    _last1 = max(int(iterations), 0)
    for _it1 in range(_last1 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__q_r_td, d_d_e__q_rd_td, d_d_e__q_th_td, d_d_e__q_thd_td, d_d_e__k_c,
            d_d_e__k_d, d_d_Q__q_r_td, d_d_Q__q_rd_td, d_d_Q__q_th_td, d_d_Q__q_thd_td, d_d_Q__k_c,
            d_d_Q__k_d, d_d_P__q_r_td, d_d_P__q_rd_td, d_d_P__q_th_td, d_d_P__q_thd_td, d_d_P__k_c,
            d_d_P__k_d, d_d_T__q_r_td, d_d_T__q_rd_td, d_d_T__q_th_td, d_d_T__q_thd_td, d_d_T__k_c,
            d_d_T__k_d, ) = _pk1
        if _conv1 or _it1 == _last1:
            break
        _x148 = bottom_q_r + d_e
        d_x = _x148
        d_d_x__q_r_td = d_bottom_q_r__q_r_td + d_d_e__q_r_td
        d_d_x__q_rd_td = d_bottom_q_r__q_rd_td + d_d_e__q_rd_td
        d_d_x__q_th_td = d_bottom_q_r__q_th_td + d_d_e__q_th_td
        d_d_x__q_thd_td = d_bottom_q_r__q_thd_td + d_d_e__q_thd_td
        d_d_x__k_c = d_bottom_q_r__k_c + d_d_e__k_c
        _x149 = _x148**2
        _x150 = (1.0/_x149)
        _x151 = _x148**4*m
        _x152 = _x148**3
        _x153 = l0**2
        _x154 = _x149*_x153*m
        _x155 = math.cos(d_Q)
        _x156 = m**2
        _x157 = 2.0*_x156*g_s
        _x158 = 2.0*E_ba*_x149*m - _x151*k_d - _x152*_x155*_x157 + 2.0*_x152*k_d*l0*m - _x154*k_d - d_P**2
        d_rad = _x150*_x158
        _pd__51 = -2.0*_x150*d_P
        _pd__52 = _x148*_x157*math.sin(d_Q)
        _x159 = 2.0*m
        _pd__53 = (_x150*(4.0*E_ba*_x148*m - _x148*_x153*_x159*k_d - 6.0*_x149*_x155*_x156*g_s
            + 6.0*_x149*k_d*l0*m - 4.0*_x152*k_d*m) - 2.0*_x158/_x152)
        d_d_rad__q_r_td = (_pd__51*d_d_P__q_r_td + _pd__52*d_d_Q__q_r_td + _pd__53*d_d_x__q_r_td
            + _x159*d_E_ba__q_r_td)
        d_d_rad__q_rd_td = (_pd__51*d_d_P__q_rd_td + _pd__52*d_d_Q__q_rd_td + _pd__53*d_d_x__q_rd_td
            + _x159*d_E_ba__q_rd_td)
        d_d_rad__q_th_td = (_pd__51*d_d_P__q_th_td + _pd__52*d_d_Q__q_th_td + _pd__53*d_d_x__q_th_td
            + _x159*d_E_ba__q_th_td)
        d_d_rad__q_thd_td = (_pd__51*d_d_P__q_thd_td + _pd__52*d_d_Q__q_thd_td + _pd__53*d_d_x__q_thd_td
            + _x159*d_E_ba__q_thd_td)
        d_d_rad__k_c = _pd__51*d_d_P__k_c + _pd__52*d_d_Q__k_c + _pd__53*d_d_x__k_c + _x159*d_E_ba__k_c
        d_d_rad__k_d = (_pd__51*d_d_P__k_d + _pd__52*d_d_Q__k_d + _pd__53*d_d_e__k_d + _x150*(-_x151
            + 2.0*_x152*l0*m - _x154) + _x159*d_E_ba__k_d)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x160 = math.sqrt(d_rad)
        d_h = _x160
        _pd__54 = (0.5)/_x160
        d_d_h__q_r_td = _pd__54*d_d_rad__q_r_td
        d_d_h__q_rd_td = _pd__54*d_d_rad__q_rd_td
        d_d_h__q_th_td = _pd__54*d_d_rad__q_th_td
        d_d_h__q_thd_td = _pd__54*d_d_rad__q_thd_td
        d_d_h__k_c = _pd__54*d_d_rad__k_c
        d_d_h__k_d = _pd__54*d_d_rad__k_d
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x164 = (1.0/d_x)
            _x161 = _x164**2
            d_wq = _x161*d_e_next
            _pd__55 = _x161
            _pd__56 = -2.0*_x164**3*d_e_next
            _x162 = 4.0*_pd__55
            d_d_wq__q_r_td = _pd__56*d_d_x__q_r_td + _x162*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__56*d_d_x__q_rd_td + _x162*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__56*d_d_x__q_th_td + _x162*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__56*d_d_x__q_thd_td + _x162*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__56*d_d_x__k_c + _x162*d_d_e__k_c
            d_d_wq__k_d = _pd__56*d_d_e__k_d + _x162*d_d_e__k_d
            d_wp = d_e_next*d_x
            _x163 = 4.0*d_x
            d_d_wp__q_r_td = _x163*d_d_e__q_r_td + d_d_x__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x163*d_d_e__q_rd_td + d_d_x__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x163*d_d_e__q_th_td + d_d_x__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x163*d_d_e__q_thd_td + d_d_x__q_thd_td*d_e_next
            d_d_wp__k_c = _x163*d_d_e__k_c + d_d_x__k_c*d_e_next
            d_d_wp__k_d = _x163*d_d_e__k_d + d_d_e__k_d*d_e_next
        elif variant == 1.0:
            _x165 = (1.0/bottom_q_r)
            _x166 = bottom_q_r + d_e_next
            _x167 = (1.0/_x166)
            d_wq = _x165*_x167*d_e_next
            _x168 = _x165*_x167**2*d_e_next
            _pd__57 = -_x165**2*_x167*d_e_next - _x168
            _pd__58 = _x165*_x167 - _x168
            _x169 = 4.0*_pd__58
            d_d_wq__q_r_td = _pd__57*d_bottom_q_r__q_r_td + _x169*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__57*d_bottom_q_r__q_rd_td + _x169*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__57*d_bottom_q_r__q_th_td + _x169*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__57*d_bottom_q_r__q_thd_td + _x169*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__57*d_bottom_q_r__k_c + _x169*d_d_e__k_c
            d_d_wq__k_d = _x169*d_d_e__k_d
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__59 = _x166
            _x170 = 4.0*_pd__59
            d_d_wp__q_r_td = _x170*d_d_e__q_r_td + d_bottom_q_r__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x170*d_d_e__q_rd_td + d_bottom_q_r__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x170*d_d_e__q_th_td + d_bottom_q_r__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x170*d_d_e__q_thd_td + d_bottom_q_r__q_thd_td*d_e_next
            d_d_wp__k_c = _x170*d_d_e__k_c + d_bottom_q_r__k_c*d_e_next
            d_d_wp__k_d = _x170*d_d_e__k_d
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        d_e__next = d_e_next
        _x171 = (1.0/d_h)
        _x172 = _x171*d_wq
        d_Q__next = _x172*d_P + bottom_q_th
        _pd__60 = _x172
        _x173 = _x171**2
        _pd__61 = -_x173*d_P*d_wq
        _pd__62 = _x171*d_P
        d_d_Q__next__q_r_td = (_pd__60*d_d_P__q_r_td + _pd__61*d_d_h__q_r_td + _pd__62*d_d_wq__q_r_td
            + d_c_Q__q_r_td)
        d_d_Q__next__q_rd_td = (_pd__60*d_d_P__q_rd_td + _pd__61*d_d_h__q_rd_td + _pd__62*d_d_wq__q_rd_td
            + d_c_Q__q_rd_td)
        d_d_Q__next__q_th_td = (_pd__60*d_d_P__q_th_td + _pd__61*d_d_h__q_th_td + _pd__62*d_d_wq__q_th_td
            + d_c_Q__q_th_td)
        d_d_Q__next__q_thd_td = (_pd__60*d_d_P__q_thd_td + _pd__61*d_d_h__q_thd_td + _pd__62*d_d_wq__q_thd_td
            + d_c_Q__q_thd_td)
        d_d_Q__next__k_c = _pd__60*d_d_P__k_c + _pd__61*d_d_h__k_c + _pd__62*d_d_wq__k_c + d_c_Q__k_c
        d_d_Q__next__k_d = _pd__60*d_d_P__k_d + _pd__61*d_d_h__k_d + _pd__62*d_d_wq__k_d
        _x174 = bottom_q_r**2*m
        _x175 = math.sin(d_Q)
        _x176 = m**2
        _x177 = _x171*_x176*g_s
        _x178 = _x175*_x177
        d_P__next = _x174*bottom_q_thd + _x178*d_wp
        _pd__63 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__64 = _x174
        _pd__65 = _x177*d_wp*math.cos(d_Q)
        _pd__66 = -_x173*_x175*_x176*d_wp*g_s
        _pd__67 = _x178
        d_d_P__next__q_r_td = (_pd__63*d_bottom_q_r__q_r_td + _pd__64*d_bottom_q_thd__q_r_td
            + _pd__65*d_d_Q__q_r_td + _pd__66*d_d_h__q_r_td + _pd__67*d_d_wp__q_r_td)
        d_d_P__next__q_rd_td = (_pd__63*d_bottom_q_r__q_rd_td + _pd__64*d_bottom_q_thd__q_rd_td
            + _pd__65*d_d_Q__q_rd_td + _pd__66*d_d_h__q_rd_td + _pd__67*d_d_wp__q_rd_td)
        d_d_P__next__q_th_td = (_pd__63*d_bottom_q_r__q_th_td + _pd__64*d_bottom_q_thd__q_th_td
            + _pd__65*d_d_Q__q_th_td + _pd__66*d_d_h__q_th_td + _pd__67*d_d_wp__q_th_td)
        d_d_P__next__q_thd_td = (_pd__63*d_bottom_q_r__q_thd_td + _pd__64*d_bottom_q_thd__q_thd_td
            + _pd__65*d_d_Q__q_thd_td + _pd__66*d_d_h__q_thd_td + _pd__67*d_d_wp__q_thd_td)
        d_d_P__next__k_c = (_pd__63*d_bottom_q_r__k_c + _pd__64*d_bottom_q_thd__k_c + _pd__65*d_d_Q__k_c
            + _pd__66*d_d_h__k_c + _pd__67*d_d_wp__k_c)
        d_d_P__next__k_d = _pd__65*d_d_Q__k_d + _pd__66*d_d_h__k_d + _pd__67*d_d_wp__k_d
        _x179 = _x171*m
        d_T__next = _x179*d_e_next + t_bottom
        _pd__68 = _x179
        _pd__69 = -_x173*d_e_next*m
        _x180 = 4.0*_pd__68
        d_d_T__next__q_r_td = _pd__69*d_d_h__q_r_td + _x180*d_d_e__q_r_td + d_c_T__q_r_td
        d_d_T__next__q_rd_td = _pd__69*d_d_h__q_rd_td + _x180*d_d_e__q_rd_td + d_c_T__q_rd_td
        d_d_T__next__q_th_td = _pd__69*d_d_h__q_th_td + _x180*d_d_e__q_th_td + d_c_T__q_th_td
        d_d_T__next__q_thd_td = _pd__69*d_d_h__q_thd_td + _x180*d_d_e__q_thd_td + d_c_T__q_thd_td
        d_d_T__next__k_c = _pd__69*d_d_h__k_c + _x180*d_d_e__k_c + d_c_T__k_c
        d_d_T__next__k_d = _pd__69*d_d_h__k_d + _x180*d_d_e__k_d
        _n1_4 = 4.0*d_d_e__q_r_td
        _n1_5 = 4.0*d_d_e__q_rd_td
        _n1_6 = 4.0*d_d_e__q_th_td
        _n1_7 = 4.0*d_d_e__q_thd_td
        _n1_8 = 4.0*d_d_e__k_c
        _n1_9 = 4.0*d_d_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn1 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n1_4, _n1_5, _n1_6, _n1_7, _n1_8, _n1_9,
            d_d_Q__next__q_r_td, d_d_Q__next__q_rd_td, d_d_Q__next__q_th_td, d_d_Q__next__q_thd_td,
            d_d_Q__next__k_c, d_d_Q__next__k_d, d_d_P__next__q_r_td, d_d_P__next__q_rd_td,
            d_d_P__next__q_th_td, d_d_P__next__q_thd_td, d_d_P__next__k_c, d_d_P__next__k_d,
            d_d_T__next__q_r_td, d_d_T__next__q_rd_td, d_d_T__next__q_th_td, d_d_T__next__q_thd_td,
            d_d_T__next__k_c, d_d_T__next__k_d, )
        _pk1 = _pkn1
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x181 = q_r_lo**2
    _x182 = (1.0/_x181)
    _x183 = m*q_r_lo**4
    _x184 = q_r_lo**3
    _x185 = _x181*l0**2*m
    _x186 = 2.0*g_s*m**2
    rad_lo = (_x182*(2.0*E_ba*_x181*m - _x183*k_d - _x184*_x186*math.cos(d_Q) + 2.0*_x184*k_d*l0*m - _x185*k_d
        - d_P**2))
    _pd__70 = -2.0*_x182*d_P
    _pd__71 = _x186*q_r_lo*math.sin(d_Q)
    _x187 = 2.0*m
    d_rad_lo__q_r_td = _pd__70*d_d_P__q_r_td + _pd__71*d_d_Q__q_r_td + _x187*d_E_ba__q_r_td
    d_rad_lo__q_rd_td = _pd__70*d_d_P__q_rd_td + _pd__71*d_d_Q__q_rd_td + _x187*d_E_ba__q_rd_td
    d_rad_lo__q_th_td = _pd__70*d_d_P__q_th_td + _pd__71*d_d_Q__q_th_td + _x187*d_E_ba__q_th_td
    d_rad_lo__q_thd_td = _pd__70*d_d_P__q_thd_td + _pd__71*d_d_Q__q_thd_td + _x187*d_E_ba__q_thd_td
    d_rad_lo__k_c = _pd__70*d_d_P__k_c + _pd__71*d_d_Q__k_c + _x187*d_E_ba__k_c
    d_rad_lo__k_d = (_pd__70*d_d_P__k_d + _pd__71*d_d_Q__k_d + _x182*(-_x183 + 2.0*_x184*l0*m - _x185)
        + _x187*d_E_ba__k_d)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x188 = (1.0/m)
    _x189 = math.sqrt(rad_lo)
    liftoff_q_rd = _x188*_x189
    _pd__72 = (0.5)*_x188/_x189
    d_liftoff_q_rd__q_r_td = _pd__72*d_rad_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _pd__72*d_rad_lo__q_rd_td
    d_liftoff_q_rd__q_th_td = _pd__72*d_rad_lo__q_th_td
    d_liftoff_q_rd__q_thd_td = _pd__72*d_rad_lo__q_thd_td
    d_liftoff_q_rd__k_c = _pd__72*d_rad_lo__k_c
    d_liftoff_q_rd__k_d = _pd__72*d_rad_lo__k_d
    liftoff_q_th = d_Q
    _x190 = _x188/q_r_lo**2
    liftoff_q_thd = _x190*d_P
    _pd__73 = _x190
    d_liftoff_q_thd__q_r_td = _pd__73*d_d_P__q_r_td
    d_liftoff_q_thd__q_rd_td = _pd__73*d_d_P__q_rd_td
    d_liftoff_q_thd__q_th_td = _pd__73*d_d_P__q_th_td
    d_liftoff_q_thd__q_thd_td = _pd__73*d_d_P__q_thd_td
    d_liftoff_q_thd__k_c = _pd__73*d_d_P__k_c
    d_liftoff_q_thd__k_d = _pd__73*d_d_P__k_d
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN70 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_c_T__q_r_td
    d_t_bottom__q_rd_td = d_c_T__q_rd_td
    d_t_bottom__q_th_td = d_c_T__q_th_td
    d_t_bottom__q_thd_td = d_c_T__q_thd_td
    d_t_bottom__k_c = d_c_T__k_c
    d_t_bottom__k_d = 0.0
    d_t_stance__q_r_td = d_d_T__q_r_td
    d_t_stance__q_rd_td = d_d_T__q_rd_td
    d_t_stance__q_th_td = d_d_T__q_th_td
    d_t_stance__q_thd_td = d_d_T__q_thd_td
    d_t_stance__k_c = d_d_T__k_c
    d_t_stance__k_d = d_d_T__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__q_r_td = d_c_Q__q_r_td
    d_bottom_q_th__q_rd_td = d_c_Q__q_rd_td
    d_bottom_q_th__q_th_td = d_c_Q__q_th_td
    d_bottom_q_th__q_thd_td = d_c_Q__q_thd_td
    d_bottom_q_th__k_c = d_c_Q__k_c
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_th__q_r_td = d_d_Q__q_r_td
    d_liftoff_q_th__q_rd_td = d_d_Q__q_rd_td
    d_liftoff_q_th__q_th_td = d_d_Q__q_th_td
    d_liftoff_q_th__q_thd_td = d_d_Q__q_thd_td
    d_liftoff_q_th__k_c = d_d_Q__k_c
    d_liftoff_q_th__k_d = d_d_Q__k_d
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
def iterative_report_stance_jacobian_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian_zeroth_gravity_type0`: arguments, out
    and status as :func:`iterative_report_stance_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_jacobian_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
            and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f
            > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_jacobian_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # the code shared between choices
    return (iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type0`: arguments,
    out and status as :func:`iterative_report_apex_return_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_jacobian_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations,
            bottom_length))
        store_row_12_84(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1522
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN70 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN70 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # E_ab (114) of the touchdown state
    _x0 = k_c*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*l0 + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__q_r_td = _x0 + _x5 + _x6*q_r_td - k_c*l0
    d_E_ab__q_rd_td = m*q_rd_td
    d_E_ab__q_th_td = -_x4*q_r_td*math.sin(q_th_td)
    d_E_ab__q_thd_td = _x2*m*q_thd_td
    d_E_ab__k_c = _x1 + _x3 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_bottom_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_bottom_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_bottom_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_bottom_q_r__k_c = _j_z_b_q_r__k
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic_jac_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[4] != STATUS_OK:
            return _NAN70 + (_c1[4],)
        bottom_q_r = _c1[0]
        _j_bottom_q_r__p = _c1[1]
        _j_bottom_q_r__E_ab = _c1[2]
        _j_bottom_q_r__k_c = _c1[3]
        # chain rule through bottom_quartic
        _x7 = _j_bottom_q_r__p*m
        d_bottom_q_r__q_r_td = _j_bottom_q_r__E_ab*d_E_ab__q_r_td + 2.0*_x7*q_r_td*q_thd_td
        d_bottom_q_r__q_rd_td = _j_bottom_q_r__E_ab*d_E_ab__q_rd_td
        d_bottom_q_r__q_th_td = _j_bottom_q_r__E_ab*d_E_ab__q_th_td
        d_bottom_q_r__q_thd_td = _j_bottom_q_r__E_ab*d_E_ab__q_thd_td + _x7*q_r_td**2
        d_bottom_q_r__k_c = _j_bottom_q_r__E_ab*d_E_ab__k_c + _j_bottom_q_r__k_c
    else:
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN70 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = bottom_q_r - q_r_td
    _x10 = _x8*_x9
    c_e_n = _x10
    _pd__0 = _x8
    _x11 = -_x8
    d_c_e_n__q_r_td = _pd__0*d_bottom_q_r__q_r_td + _x11
    d_c_e_n__q_rd_td = _pd__0*d_bottom_q_r__q_rd_td
    d_c_e_n__q_th_td = _pd__0*d_bottom_q_r__q_th_td
    d_c_e_n__q_thd_td = _pd__0*d_bottom_q_r__q_thd_td
    d_c_e_n__k_c = _pd__0*d_bottom_q_r__k_c
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
    d_c_rad_z__q_r_td = (_j_z_b_q_r__q_r_td*_pd__3 + _j_z_b_q_th__q_r_td*_pd__4 + _j_z_b_q_thd__q_r_td*_pd__5
        + _pd__1*d_bottom_q_r__q_r_td + _x15*(-_x27*(-_x23*_x41 + _x24*_x46*q_r_td*q_thd_td) - _x39 - _x47)
        + _x42 + _x51*d_c_e_n__q_r_td + _x52*d_E_ab__q_r_td)
    d_c_rad_z__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__3 + _j_z_b_q_th__q_rd_td*_pd__4
        + _j_z_b_q_thd__q_rd_td*_pd__5 + _pd__1*d_bottom_q_r__q_rd_td + _x51*d_c_e_n__q_rd_td
        + _x52*d_E_ab__q_rd_td)
    d_c_rad_z__q_th_td = (_j_z_b_q_r__q_th_td*_pd__3 + _j_z_b_q_th__q_th_td*_pd__4
        + _j_z_b_q_thd__q_th_td*_pd__5 + _pd__1*d_bottom_q_r__q_th_td + _x24*_x50 + _x51*d_c_e_n__q_th_td
        + _x52*d_E_ab__q_th_td)
    d_c_rad_z__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__3 + _j_z_b_q_th__q_thd_td*_pd__4
        + _j_z_b_q_thd__q_thd_td*_pd__5 + _pd__1*d_bottom_q_r__q_thd_td - 2.0*_x24*_x25*_x49
        + _x51*d_c_e_n__q_thd_td + _x52*d_E_ab__q_thd_td)
    d_c_rad_z__k_c = (_j_z_b_q_r__k*_pd__3 + _j_z_b_q_th__k*_pd__4 + _j_z_b_q_thd__k*_pd__5
        + _pd__1*d_bottom_q_r__k_c + _x15*(-_x16 + 2.0*_x17*l0*m - _x19) + _x51*d_c_e_n__k_c
        + _x52*d_E_ab__k_c)
    _x53 = math.sqrt(_x11 + 1.0)
    c_Q0 = _x29*_x53 + z_b_q_th
    _x54 = (0.5)/_x53
    _x55 = _x36*_x54
    _x56 = _x55*_x8
    _pd__6 = _x56
    _pd__7 = -_x55
    _pd__8 = 1.0 - _x53
    d_c_Q0__q_r_td = _j_z_b_q_th__q_r_td*_pd__8 + _pd__6*d_bottom_q_r__q_r_td + _pd__7*d_c_e_n__q_r_td - _x56
    d_c_Q0__q_rd_td = _j_z_b_q_th__q_rd_td*_pd__8 + _pd__6*d_bottom_q_r__q_rd_td + _pd__7*d_c_e_n__q_rd_td
    d_c_Q0__q_th_td = (_j_z_b_q_th__q_th_td*_pd__8 + _pd__6*d_bottom_q_r__q_th_td + _pd__7*d_c_e_n__q_th_td
        + _x53)
    d_c_Q0__q_thd_td = _j_z_b_q_th__q_thd_td*_pd__8 + _pd__6*d_bottom_q_r__q_thd_td + _pd__7*d_c_e_n__q_thd_td
    d_c_Q0__k_c = _j_z_b_q_th__k*_pd__8 + _pd__6*d_bottom_q_r__k_c + _pd__7*d_c_e_n__k_c
    c_P0 = _x22 + _x26*_x53
    _x57 = _x40*_x54
    _x58 = _x57*_x8
    _pd__9 = _x58
    _pd__10 = -_x57
    _pd__11 = -_x48*_x52*_x53 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__12 = _x20*m - _x21*_x53
    d_c_P0__q_r_td = (_j_z_b_q_r__q_r_td*_pd__11 + _j_z_b_q_thd__q_r_td*_pd__12 + _pd__10*d_c_e_n__q_r_td
        + _pd__9*d_bottom_q_r__q_r_td + _x43*_x53*m*q_thd_td - _x58)
    d_c_P0__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__11 + _j_z_b_q_thd__q_rd_td*_pd__12 + _pd__10*d_c_e_n__q_rd_td
        + _pd__9*d_bottom_q_r__q_rd_td)
    d_c_P0__q_th_td = (_j_z_b_q_r__q_th_td*_pd__11 + _j_z_b_q_thd__q_th_td*_pd__12 + _pd__10*d_c_e_n__q_th_td
        + _pd__9*d_bottom_q_r__q_th_td)
    d_c_P0__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__11 + _j_z_b_q_thd__q_thd_td*_pd__12
        + _pd__10*d_c_e_n__q_thd_td + _pd__9*d_bottom_q_r__q_thd_td + _x25*_x53)
    d_c_P0__k_c = (_j_z_b_q_r__k*_pd__11 + _j_z_b_q_thd__k*_pd__12 + _pd__10*d_c_e_n__k_c
        + _pd__9*d_bottom_q_r__k_c)
    _x59 = m/math.sqrt(_x33)
    _x60 = (_x33 > 0.0)
    c_T0 = ((-_x10*_x59) if _x60 else (0.0))
    _pd__13 = ((-_x59) if _x60 else (0.0))
    _pd__14 = ((_x44*m/(_x33*math.sqrt(_x33))) if _x60 else (0.0))
    d_c_T0__q_r_td = _pd__13*d_c_e_n__q_r_td + _pd__14*d_c_rad_z__q_r_td
    d_c_T0__q_rd_td = _pd__13*d_c_e_n__q_rd_td + _pd__14*d_c_rad_z__q_rd_td
    d_c_T0__q_th_td = _pd__13*d_c_e_n__q_th_td + _pd__14*d_c_rad_z__q_th_td
    d_c_T0__q_thd_td = _pd__13*d_c_e_n__q_thd_td + _pd__14*d_c_rad_z__q_thd_td
    d_c_T0__k_c = _pd__13*d_c_e_n__k_c + _pd__14*d_c_rad_z__k_c
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__q_r_td, d_c_e_n__q_rd_td, d_c_e_n__q_th_td, d_c_e_n__q_thd_td,
        d_c_e_n__k_c, d_c_Q0__q_r_td, d_c_Q0__q_rd_td, d_c_Q0__q_th_td, d_c_Q0__q_thd_td, d_c_Q0__k_c,
        d_c_P0__q_r_td, d_c_P0__q_rd_td, d_c_P0__q_th_td, d_c_P0__q_thd_td, d_c_P0__k_c, d_c_T0__q_r_td,
        d_c_T0__q_rd_td, d_c_T0__q_th_td, d_c_T0__q_thd_td, d_c_T0__k_c, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__q_r_td, d_c_e__q_rd_td, d_c_e__q_th_td, d_c_e__q_thd_td, d_c_e__k_c,
            d_c_Q__q_r_td, d_c_Q__q_rd_td, d_c_Q__q_th_td, d_c_Q__q_thd_td, d_c_Q__k_c, d_c_P__q_r_td,
            d_c_P__q_rd_td, d_c_P__q_th_td, d_c_P__q_thd_td, d_c_P__k_c, d_c_T__q_r_td, d_c_T__q_rd_td,
            d_c_T__q_th_td, d_c_T__q_thd_td, d_c_T__k_c, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x61 = c_e + q_r_td
        c_x = _x61
        d_c_x__q_r_td = d_c_e__q_r_td + 1.0
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
        d_c_rad__q_r_td = (_pd__15*d_c_P__q_r_td + _pd__16*d_c_Q__q_r_td + _pd__17*d_c_x__q_r_td
            + _x72*d_E_ab__q_r_td)
        d_c_rad__q_rd_td = (_pd__15*d_c_P__q_rd_td + _pd__16*d_c_Q__q_rd_td + _pd__17*d_c_e__q_rd_td
            + _x72*d_E_ab__q_rd_td)
        d_c_rad__q_th_td = (_pd__15*d_c_P__q_th_td + _pd__16*d_c_Q__q_th_td + _pd__17*d_c_e__q_th_td
            + _x72*d_E_ab__q_th_td)
        d_c_rad__q_thd_td = (_pd__15*d_c_P__q_thd_td + _pd__16*d_c_Q__q_thd_td + _pd__17*d_c_e__q_thd_td
            + _x72*d_E_ab__q_thd_td)
        d_c_rad__k_c = (_pd__15*d_c_P__k_c + _pd__16*d_c_Q__k_c + _pd__17*d_c_e__k_c + _x63*(-_x64
            + 2.0*_x65*l0*m - _x67) + _x72*d_E_ab__k_c)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x73 = math.sqrt(c_rad)
        c_h = _x73
        _pd__18 = (0.5)/_x73
        d_c_h__q_r_td = _pd__18*d_c_rad__q_r_td
        d_c_h__q_rd_td = _pd__18*d_c_rad__q_rd_td
        d_c_h__q_th_td = _pd__18*d_c_rad__q_th_td
        d_c_h__q_thd_td = _pd__18*d_c_rad__q_thd_td
        d_c_h__k_c = _pd__18*d_c_rad__k_c
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x77 = (1.0/c_x)
            _x74 = _x77**2
            c_wq = _x74*c_e_next
            _pd__19 = _x74
            _pd__20 = -2.0*_x77**3*c_e_next
            _x75 = 4.0*_pd__19
            d_c_wq__q_r_td = _pd__20*d_c_x__q_r_td + _x75*d_c_e__q_r_td
            d_c_wq__q_rd_td = _pd__20*d_c_e__q_rd_td + _x75*d_c_e__q_rd_td
            d_c_wq__q_th_td = _pd__20*d_c_e__q_th_td + _x75*d_c_e__q_th_td
            d_c_wq__q_thd_td = _pd__20*d_c_e__q_thd_td + _x75*d_c_e__q_thd_td
            d_c_wq__k_c = _pd__20*d_c_e__k_c + _x75*d_c_e__k_c
            c_wp = c_e_next*c_x
            _x76 = 4.0*c_x
            d_c_wp__q_r_td = _x76*d_c_e__q_r_td + c_e_next*d_c_x__q_r_td
            d_c_wp__q_rd_td = _x76*d_c_e__q_rd_td + c_e_next*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x76*d_c_e__q_th_td + c_e_next*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x76*d_c_e__q_thd_td + c_e_next*d_c_e__q_thd_td
            d_c_wp__k_c = _x76*d_c_e__k_c + c_e_next*d_c_e__k_c
        elif variant == 1.0:
            _x78 = (1.0/q_r_td)
            _x79 = c_e_next + q_r_td
            _x80 = (1.0/_x79)
            c_wq = _x78*_x80*c_e_next
            _x81 = _x78*_x80**2*c_e_next
            _pd__21 = _x78*_x80 - _x81
            d_c_wq__q_r_td = 4.0*_pd__21*d_c_e__q_r_td - _x78**2*_x80*c_e_next - _x81
            _x82 = 4.0*_pd__21
            d_c_wq__q_rd_td = _x82*d_c_e__q_rd_td
            d_c_wq__q_th_td = _x82*d_c_e__q_th_td
            d_c_wq__q_thd_td = _x82*d_c_e__q_thd_td
            d_c_wq__k_c = _x82*d_c_e__k_c
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__22 = _x79
            _x83 = 4.0*_pd__22
            d_c_wp__q_r_td = _x83*d_c_e__q_r_td + c_e_next
            d_c_wp__q_rd_td = _x83*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x83*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x83*d_c_e__q_thd_td
            d_c_wp__k_c = _x83*d_c_e__k_c
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        c_e__next = c_e_next
        _x84 = (1.0/c_h)
        _x85 = _x84*c_wq
        c_Q__next = -_x85*c_P + q_th_td
        _pd__23 = -_x85
        _x86 = _x84**2
        _pd__24 = _x86*c_P*c_wq
        _pd__25 = -_x84*c_P
        d_c_Q__next__q_r_td = _pd__23*d_c_P__q_r_td + _pd__24*d_c_h__q_r_td + _pd__25*d_c_wq__q_r_td
        d_c_Q__next__q_rd_td = _pd__23*d_c_P__q_rd_td + _pd__24*d_c_h__q_rd_td + _pd__25*d_c_wq__q_rd_td
        d_c_Q__next__q_th_td = _pd__23*d_c_P__q_th_td + _pd__24*d_c_h__q_th_td + _pd__25*d_c_wq__q_th_td + 1.0
        d_c_Q__next__q_thd_td = _pd__23*d_c_P__q_thd_td + _pd__24*d_c_h__q_thd_td + _pd__25*d_c_wq__q_thd_td
        d_c_Q__next__k_c = _pd__23*d_c_P__k_c + _pd__24*d_c_h__k_c + _pd__25*d_c_wq__k_c
        _x87 = m*q_r_td**2
        _x88 = math.sin(c_Q)
        _x89 = m**2
        _x90 = _x84*_x89*g_s
        _x91 = _x88*_x90
        c_P__next = _x87*q_thd_td - _x91*c_wp
        _pd__26 = -_x90*c_wp*math.cos(c_Q)
        _pd__27 = _x86*_x88*_x89*c_wp*g_s
        _pd__28 = -_x91
        d_c_P__next__q_r_td = (_pd__26*d_c_Q__q_r_td + _pd__27*d_c_h__q_r_td + _pd__28*d_c_wp__q_r_td
            + 2.0*m*q_r_td*q_thd_td)
        d_c_P__next__q_rd_td = _pd__26*d_c_Q__q_rd_td + _pd__27*d_c_h__q_rd_td + _pd__28*d_c_wp__q_rd_td
        d_c_P__next__q_th_td = _pd__26*d_c_Q__q_th_td + _pd__27*d_c_h__q_th_td + _pd__28*d_c_wp__q_th_td
        d_c_P__next__q_thd_td = (_pd__26*d_c_Q__q_thd_td + _pd__27*d_c_h__q_thd_td + _pd__28*d_c_wp__q_thd_td
            + _x87)
        d_c_P__next__k_c = _pd__26*d_c_Q__k_c + _pd__27*d_c_h__k_c + _pd__28*d_c_wp__k_c
        _x92 = _x84*m
        c_T__next = -_x92*c_e_next
        _pd__29 = -_x92
        _pd__30 = _x86*c_e_next*m
        _x93 = 4.0*_pd__29
        d_c_T__next__q_r_td = _pd__30*d_c_h__q_r_td + _x93*d_c_e__q_r_td
        d_c_T__next__q_rd_td = _pd__30*d_c_h__q_rd_td + _x93*d_c_e__q_rd_td
        d_c_T__next__q_th_td = _pd__30*d_c_h__q_th_td + _x93*d_c_e__q_th_td
        d_c_T__next__q_thd_td = _pd__30*d_c_h__q_thd_td + _x93*d_c_e__q_thd_td
        d_c_T__next__k_c = _pd__30*d_c_h__k_c + _x93*d_c_e__k_c
        _n0_4 = 4.0*d_c_e__q_r_td
        _n0_5 = 4.0*d_c_e__q_rd_td
        _n0_6 = 4.0*d_c_e__q_th_td
        _n0_7 = 4.0*d_c_e__q_thd_td
        _n0_8 = 4.0*d_c_e__k_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8,
            d_c_Q__next__q_r_td, d_c_Q__next__q_rd_td, d_c_Q__next__q_th_td, d_c_Q__next__q_thd_td,
            d_c_Q__next__k_c, d_c_P__next__q_r_td, d_c_P__next__q_rd_td, d_c_P__next__q_th_td,
            d_c_P__next__q_thd_td, d_c_P__next__k_c, d_c_T__next__q_r_td, d_c_T__next__q_rd_td,
            d_c_T__next__q_th_td, d_c_T__next__q_thd_td, d_c_T__next__k_c, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    _x94 = (1.0/m)
    _x96 = (1.0/bottom_q_r)
    _x95 = _x94*_x96**2
    bottom_q_thd = _x95*c_P
    _pd__31 = -2.0*_x94*_x96**3*c_P
    _pd__32 = _x95
    d_bottom_q_thd__q_r_td = _pd__31*d_bottom_q_r__q_r_td + _pd__32*d_c_P__q_r_td
    d_bottom_q_thd__q_rd_td = _pd__31*d_bottom_q_r__q_rd_td + _pd__32*d_c_P__q_rd_td
    d_bottom_q_thd__q_th_td = _pd__31*d_bottom_q_r__q_th_td + _pd__32*d_c_P__q_th_td
    d_bottom_q_thd__q_thd_td = _pd__31*d_bottom_q_r__q_thd_td + _pd__32*d_c_P__q_thd_td
    d_bottom_q_thd__k_c = _pd__31*d_bottom_q_r__k_c + _pd__32*d_c_P__k_c
    # E_ba of (98): the energy jump of the stiffness switch
    _x97 = (-bottom_q_r + l0)**2
    _x98 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x97*_x98
    _pd__33 = _x98*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__q_r_td = _pd__33*d_bottom_q_r__q_r_td + d_E_ab__q_r_td
    d_E_ba__q_rd_td = _pd__33*d_bottom_q_r__q_rd_td + d_E_ab__q_rd_td
    d_E_ba__q_th_td = _pd__33*d_bottom_q_r__q_th_td + d_E_ab__q_th_td
    d_E_ba__q_thd_td = _pd__33*d_bottom_q_r__q_thd_td + d_E_ab__q_thd_td
    _x99 = (0.5)*_x97
    d_E_ba__k_c = _pd__33*d_bottom_q_r__k_c - _x99 + d_E_ab__k_c
    d_E_ba__k_d = _x99
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN70 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x100 = 4.0**(-iterations)
    _x101 = -bottom_q_r + q_r_lo
    _x102 = _x100*_x101
    d_e_n = _x102
    _pd__34 = -_x100
    d_d_e_n__q_r_td = _pd__34*d_bottom_q_r__q_r_td
    d_d_e_n__q_rd_td = _pd__34*d_bottom_q_r__q_rd_td
    d_d_e_n__q_th_td = _pd__34*d_bottom_q_r__q_th_td
    d_d_e_n__q_thd_td = _pd__34*d_bottom_q_r__q_thd_td
    d_d_e_n__k_c = _pd__34*d_bottom_q_r__k_c
    _x103 = (0.25)*_x102
    d_e_z = _x103
    _x104 = _x103 + bottom_q_r
    _x105 = _x104**2
    _x106 = (1.0/_x105)
    _x107 = _x104**4*m
    _x108 = _x104**3
    _x109 = l0**2*m
    _x110 = _x105*_x109
    _x111 = bottom_q_r**2*m
    _x112 = _x111*bottom_q_thd
    _x113 = q_r_lo**2
    _x114 = -_x112 + _x113*g_lo_q_thd*m
    _x115 = 4.0**((0.5)*iterations)
    _x116 = (1.0/_x115)
    _x117 = (0.5)*_x116
    _x118 = _x114*_x117
    _x119 = _x112 + _x118
    _x120 = -bottom_q_th + g_lo_q_th
    _x121 = _x117*_x120
    _x122 = _x121 + bottom_q_th
    _x123 = m**2
    _x124 = _x123*g_s
    _x125 = _x124*math.cos(_x122)
    _x126 = 2.0*E_ba*_x105*m - _x107*k_d - 2.0*_x108*_x125 + 2.0*_x108*k_d*l0*m - _x110*k_d - _x119**2
    _x127 = _x106*_x126
    d_rad_z = _x127
    _x128 = -2.0*_x126/_x108
    _x129 = 4.0*m
    _x130 = (1.0/_x101)
    _x131 = 2.0*bottom_q_r
    _x132 = _x131*bottom_q_thd*m
    _x133 = -_x116*_x132 + _x118*_x130
    _x134 = math.sin(_x122)
    _x135 = (0.5)*_x102
    _x136 = _x131 + _x135
    _x137 = -2.0*E_ba*_x136*m + 6.0*_x105*_x125 - 6.0*_x105*k_d*l0*m + _x108*_x129*k_d + _x109*_x136*k_d
    _pd__35 = (_x106*((0.5)*_x108*_x116*_x120*_x123*_x130*_x134*g_s - _x119*(_x129*bottom_q_r*bottom_q_thd
        + _x133) - _x137) + _x128)
    _x138 = _x104*_x124*_x134
    _pd__36 = 2.0*_x138*(1.0 - _x117)
    _x139 = -_x111*_x116
    _x140 = _x106*_x119
    _pd__37 = -_x140*(2.0*_x111 + _x139)
    _x141 = _x115*_x130
    _pd__38 = _x106*(2.0*_x108*_x115*_x120*_x123*_x130*_x134*g_s - 2.0*_x114*_x119*_x141 - _x137) + _x128
    _pd__39 = _x116*_x138
    _x142 = _x113*_x116*m
    _pd__40 = -_x140*_x142
    _x143 = (0.25)*_pd__38
    _x144 = 2.0*m
    d_d_rad_z__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__39 + _j_z_lo_q_thd__q_r_td*_pd__40
        + _pd__35*d_bottom_q_r__q_r_td + _pd__36*d_c_Q__q_r_td + _pd__37*d_bottom_q_thd__q_r_td
        + _x143*d_d_e_n__q_r_td + _x144*d_E_ba__q_r_td)
    d_d_rad_z__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__39 + _j_z_lo_q_thd__q_rd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_rd_td + _pd__36*d_c_Q__q_rd_td + _pd__37*d_bottom_q_thd__q_rd_td
        + _x143*d_d_e_n__q_rd_td + _x144*d_E_ba__q_rd_td)
    d_d_rad_z__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__39 + _j_z_lo_q_thd__q_th_td*_pd__40
        + _pd__35*d_bottom_q_r__q_th_td + _pd__36*d_c_Q__q_th_td + _pd__37*d_bottom_q_thd__q_th_td
        + _x143*d_d_e_n__q_th_td + _x144*d_E_ba__q_th_td)
    d_d_rad_z__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__39 + _j_z_lo_q_thd__q_thd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_thd_td + _pd__36*d_c_Q__q_thd_td + _pd__37*d_bottom_q_thd__q_thd_td
        + _x143*d_d_e_n__q_thd_td + _x144*d_E_ba__q_thd_td)
    d_d_rad_z__k_c = (_j_z_lo_q_th__k*_pd__39 + _j_z_lo_q_thd__k*_pd__40 + _pd__35*d_bottom_q_r__k_c
        + _pd__36*d_c_Q__k_c + _pd__37*d_bottom_q_thd__k_c + _x143*d_d_e_n__k_c + _x144*d_E_ba__k_c)
    d_d_rad_z__k_d = _x106*(-_x107 + 2.0*_x108*l0*m - _x110) + _x144*d_E_ba__k_d
    d_Q0 = _x116*_x120 + bottom_q_th
    _pd__41 = _x121*_x130
    _pd__42 = 1.0 - _x116
    _x145 = (0.5)*_x141
    _pd__43 = _x120*_x145
    _pd__44 = _x116
    d_d_Q0__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__44 + _pd__41*d_bottom_q_r__q_r_td + _pd__42*d_c_Q__q_r_td
        + _pd__43*d_d_e_n__q_r_td)
    d_d_Q0__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__44 + _pd__41*d_bottom_q_r__q_rd_td + _pd__42*d_c_Q__q_rd_td
        + _pd__43*d_d_e_n__q_rd_td)
    d_d_Q0__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__44 + _pd__41*d_bottom_q_r__q_th_td + _pd__42*d_c_Q__q_th_td
        + _pd__43*d_d_e_n__q_th_td)
    d_d_Q0__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__44 + _pd__41*d_bottom_q_r__q_thd_td
        + _pd__42*d_c_Q__q_thd_td + _pd__43*d_d_e_n__q_thd_td)
    d_d_Q0__k_c = (_j_z_lo_q_th__k*_pd__44 + _pd__41*d_bottom_q_r__k_c + _pd__42*d_c_Q__k_c
        + _pd__43*d_d_e_n__k_c)
    d_P0 = _x112 + _x114*_x116
    _pd__45 = _x132 + _x133
    _pd__46 = _x111 + _x139
    _pd__47 = _x114*_x145
    _pd__48 = _x142
    d_d_P0__q_r_td = (_j_z_lo_q_thd__q_r_td*_pd__48 + _pd__45*d_bottom_q_r__q_r_td
        + _pd__46*d_bottom_q_thd__q_r_td + _pd__47*d_d_e_n__q_r_td)
    d_d_P0__q_rd_td = (_j_z_lo_q_thd__q_rd_td*_pd__48 + _pd__45*d_bottom_q_r__q_rd_td
        + _pd__46*d_bottom_q_thd__q_rd_td + _pd__47*d_d_e_n__q_rd_td)
    d_d_P0__q_th_td = (_j_z_lo_q_thd__q_th_td*_pd__48 + _pd__45*d_bottom_q_r__q_th_td
        + _pd__46*d_bottom_q_thd__q_th_td + _pd__47*d_d_e_n__q_th_td)
    d_d_P0__q_thd_td = (_j_z_lo_q_thd__q_thd_td*_pd__48 + _pd__45*d_bottom_q_r__q_thd_td
        + _pd__46*d_bottom_q_thd__q_thd_td + _pd__47*d_d_e_n__q_thd_td)
    d_d_P0__k_c = (_j_z_lo_q_thd__k*_pd__48 + _pd__45*d_bottom_q_r__k_c + _pd__46*d_bottom_q_thd__k_c
        + _pd__47*d_d_e_n__k_c)
    _x146 = m/math.sqrt(_x127)
    _x147 = (_x127 > 0.0)
    d_T0 = ((_x102*_x146 + t_bottom) if _x147 else (t_bottom))
    _pd__49 = ((_x146) if _x147 else (0.0))
    _pd__50 = ((-_x135*m/(_x127*math.sqrt(_x127))) if _x147 else (0.0))
    d_d_T0__q_r_td = _pd__49*d_d_e_n__q_r_td + _pd__50*d_d_rad_z__q_r_td + d_c_T__q_r_td
    d_d_T0__q_rd_td = _pd__49*d_d_e_n__q_rd_td + _pd__50*d_d_rad_z__q_rd_td + d_c_T__q_rd_td
    d_d_T0__q_th_td = _pd__49*d_d_e_n__q_th_td + _pd__50*d_d_rad_z__q_th_td + d_c_T__q_th_td
    d_d_T0__q_thd_td = _pd__49*d_d_e_n__q_thd_td + _pd__50*d_d_rad_z__q_thd_td + d_c_T__q_thd_td
    d_d_T0__k_c = _pd__49*d_d_e_n__k_c + _pd__50*d_d_rad_z__k_c + d_c_T__k_c
    d_d_T0__k_d = _pd__50*d_d_rad_z__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki1 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__q_r_td, d_d_e_n__q_rd_td, d_d_e_n__q_th_td, d_d_e_n__q_thd_td,
        d_d_e_n__k_c, 0.0, d_d_Q0__q_r_td, d_d_Q0__q_rd_td, d_d_Q0__q_th_td, d_d_Q0__q_thd_td, d_d_Q0__k_c,
        0.0, d_d_P0__q_r_td, d_d_P0__q_rd_td, d_d_P0__q_th_td, d_d_P0__q_thd_td, d_d_P0__k_c, 0.0,
        d_d_T0__q_r_td, d_d_T0__q_rd_td, d_d_T0__q_th_td, d_d_T0__q_thd_td, d_d_T0__k_c, d_d_T0__k_d, )
    _pk1 = _pki1
    d_steps = 0.0
    _conv1 = False
    _last1 = max(int(iterations), 0)
    for _it1 in range(_last1 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__q_r_td, d_d_e__q_rd_td, d_d_e__q_th_td, d_d_e__q_thd_td, d_d_e__k_c,
            d_d_e__k_d, d_d_Q__q_r_td, d_d_Q__q_rd_td, d_d_Q__q_th_td, d_d_Q__q_thd_td, d_d_Q__k_c,
            d_d_Q__k_d, d_d_P__q_r_td, d_d_P__q_rd_td, d_d_P__q_th_td, d_d_P__q_thd_td, d_d_P__k_c,
            d_d_P__k_d, d_d_T__q_r_td, d_d_T__q_rd_td, d_d_T__q_th_td, d_d_T__q_thd_td, d_d_T__k_c,
            d_d_T__k_d, ) = _pk1
        if _conv1 or _it1 == _last1:
            break
        _x148 = bottom_q_r + d_e
        d_x = _x148
        d_d_x__q_r_td = d_bottom_q_r__q_r_td + d_d_e__q_r_td
        d_d_x__q_rd_td = d_bottom_q_r__q_rd_td + d_d_e__q_rd_td
        d_d_x__q_th_td = d_bottom_q_r__q_th_td + d_d_e__q_th_td
        d_d_x__q_thd_td = d_bottom_q_r__q_thd_td + d_d_e__q_thd_td
        d_d_x__k_c = d_bottom_q_r__k_c + d_d_e__k_c
        _x149 = _x148**2
        _x150 = (1.0/_x149)
        _x151 = _x148**4*m
        _x152 = _x148**3
        _x153 = l0**2
        _x154 = _x149*_x153*m
        _x155 = math.cos(d_Q)
        _x156 = m**2
        _x157 = 2.0*_x156*g_s
        _x158 = 2.0*E_ba*_x149*m - _x151*k_d - _x152*_x155*_x157 + 2.0*_x152*k_d*l0*m - _x154*k_d - d_P**2
        d_rad = _x150*_x158
        _pd__51 = -2.0*_x150*d_P
        _pd__52 = _x148*_x157*math.sin(d_Q)
        _x159 = 2.0*m
        _pd__53 = (_x150*(4.0*E_ba*_x148*m - _x148*_x153*_x159*k_d - 6.0*_x149*_x155*_x156*g_s
            + 6.0*_x149*k_d*l0*m - 4.0*_x152*k_d*m) - 2.0*_x158/_x152)
        d_d_rad__q_r_td = (_pd__51*d_d_P__q_r_td + _pd__52*d_d_Q__q_r_td + _pd__53*d_d_x__q_r_td
            + _x159*d_E_ba__q_r_td)
        d_d_rad__q_rd_td = (_pd__51*d_d_P__q_rd_td + _pd__52*d_d_Q__q_rd_td + _pd__53*d_d_x__q_rd_td
            + _x159*d_E_ba__q_rd_td)
        d_d_rad__q_th_td = (_pd__51*d_d_P__q_th_td + _pd__52*d_d_Q__q_th_td + _pd__53*d_d_x__q_th_td
            + _x159*d_E_ba__q_th_td)
        d_d_rad__q_thd_td = (_pd__51*d_d_P__q_thd_td + _pd__52*d_d_Q__q_thd_td + _pd__53*d_d_x__q_thd_td
            + _x159*d_E_ba__q_thd_td)
        d_d_rad__k_c = _pd__51*d_d_P__k_c + _pd__52*d_d_Q__k_c + _pd__53*d_d_x__k_c + _x159*d_E_ba__k_c
        d_d_rad__k_d = (_pd__51*d_d_P__k_d + _pd__52*d_d_Q__k_d + _pd__53*d_d_e__k_d + _x150*(-_x151
            + 2.0*_x152*l0*m - _x154) + _x159*d_E_ba__k_d)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x160 = math.sqrt(d_rad)
        d_h = _x160
        _pd__54 = (0.5)/_x160
        d_d_h__q_r_td = _pd__54*d_d_rad__q_r_td
        d_d_h__q_rd_td = _pd__54*d_d_rad__q_rd_td
        d_d_h__q_th_td = _pd__54*d_d_rad__q_th_td
        d_d_h__q_thd_td = _pd__54*d_d_rad__q_thd_td
        d_d_h__k_c = _pd__54*d_d_rad__k_c
        d_d_h__k_d = _pd__54*d_d_rad__k_d
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x164 = (1.0/d_x)
            _x161 = _x164**2
            d_wq = _x161*d_e_next
            _pd__55 = _x161
            _pd__56 = -2.0*_x164**3*d_e_next
            _x162 = 4.0*_pd__55
            d_d_wq__q_r_td = _pd__56*d_d_x__q_r_td + _x162*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__56*d_d_x__q_rd_td + _x162*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__56*d_d_x__q_th_td + _x162*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__56*d_d_x__q_thd_td + _x162*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__56*d_d_x__k_c + _x162*d_d_e__k_c
            d_d_wq__k_d = _pd__56*d_d_e__k_d + _x162*d_d_e__k_d
            d_wp = d_e_next*d_x
            _x163 = 4.0*d_x
            d_d_wp__q_r_td = _x163*d_d_e__q_r_td + d_d_x__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x163*d_d_e__q_rd_td + d_d_x__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x163*d_d_e__q_th_td + d_d_x__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x163*d_d_e__q_thd_td + d_d_x__q_thd_td*d_e_next
            d_d_wp__k_c = _x163*d_d_e__k_c + d_d_x__k_c*d_e_next
            d_d_wp__k_d = _x163*d_d_e__k_d + d_d_e__k_d*d_e_next
        elif variant == 1.0:
            _x165 = (1.0/bottom_q_r)
            _x166 = bottom_q_r + d_e_next
            _x167 = (1.0/_x166)
            d_wq = _x165*_x167*d_e_next
            _x168 = _x165*_x167**2*d_e_next
            _pd__57 = -_x165**2*_x167*d_e_next - _x168
            _pd__58 = _x165*_x167 - _x168
            _x169 = 4.0*_pd__58
            d_d_wq__q_r_td = _pd__57*d_bottom_q_r__q_r_td + _x169*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__57*d_bottom_q_r__q_rd_td + _x169*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__57*d_bottom_q_r__q_th_td + _x169*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__57*d_bottom_q_r__q_thd_td + _x169*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__57*d_bottom_q_r__k_c + _x169*d_d_e__k_c
            d_d_wq__k_d = _x169*d_d_e__k_d
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__59 = _x166
            _x170 = 4.0*_pd__59
            d_d_wp__q_r_td = _x170*d_d_e__q_r_td + d_bottom_q_r__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x170*d_d_e__q_rd_td + d_bottom_q_r__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x170*d_d_e__q_th_td + d_bottom_q_r__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x170*d_d_e__q_thd_td + d_bottom_q_r__q_thd_td*d_e_next
            d_d_wp__k_c = _x170*d_d_e__k_c + d_bottom_q_r__k_c*d_e_next
            d_d_wp__k_d = _x170*d_d_e__k_d
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        d_e__next = d_e_next
        _x171 = (1.0/d_h)
        _x172 = _x171*d_wq
        d_Q__next = _x172*d_P + bottom_q_th
        _pd__60 = _x172
        _x173 = _x171**2
        _pd__61 = -_x173*d_P*d_wq
        _pd__62 = _x171*d_P
        d_d_Q__next__q_r_td = (_pd__60*d_d_P__q_r_td + _pd__61*d_d_h__q_r_td + _pd__62*d_d_wq__q_r_td
            + d_c_Q__q_r_td)
        d_d_Q__next__q_rd_td = (_pd__60*d_d_P__q_rd_td + _pd__61*d_d_h__q_rd_td + _pd__62*d_d_wq__q_rd_td
            + d_c_Q__q_rd_td)
        d_d_Q__next__q_th_td = (_pd__60*d_d_P__q_th_td + _pd__61*d_d_h__q_th_td + _pd__62*d_d_wq__q_th_td
            + d_c_Q__q_th_td)
        d_d_Q__next__q_thd_td = (_pd__60*d_d_P__q_thd_td + _pd__61*d_d_h__q_thd_td + _pd__62*d_d_wq__q_thd_td
            + d_c_Q__q_thd_td)
        d_d_Q__next__k_c = _pd__60*d_d_P__k_c + _pd__61*d_d_h__k_c + _pd__62*d_d_wq__k_c + d_c_Q__k_c
        d_d_Q__next__k_d = _pd__60*d_d_P__k_d + _pd__61*d_d_h__k_d + _pd__62*d_d_wq__k_d
        _x174 = bottom_q_r**2*m
        _x175 = math.sin(d_Q)
        _x176 = m**2
        _x177 = _x171*_x176*g_s
        _x178 = _x175*_x177
        d_P__next = _x174*bottom_q_thd + _x178*d_wp
        _pd__63 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__64 = _x174
        _pd__65 = _x177*d_wp*math.cos(d_Q)
        _pd__66 = -_x173*_x175*_x176*d_wp*g_s
        _pd__67 = _x178
        d_d_P__next__q_r_td = (_pd__63*d_bottom_q_r__q_r_td + _pd__64*d_bottom_q_thd__q_r_td
            + _pd__65*d_d_Q__q_r_td + _pd__66*d_d_h__q_r_td + _pd__67*d_d_wp__q_r_td)
        d_d_P__next__q_rd_td = (_pd__63*d_bottom_q_r__q_rd_td + _pd__64*d_bottom_q_thd__q_rd_td
            + _pd__65*d_d_Q__q_rd_td + _pd__66*d_d_h__q_rd_td + _pd__67*d_d_wp__q_rd_td)
        d_d_P__next__q_th_td = (_pd__63*d_bottom_q_r__q_th_td + _pd__64*d_bottom_q_thd__q_th_td
            + _pd__65*d_d_Q__q_th_td + _pd__66*d_d_h__q_th_td + _pd__67*d_d_wp__q_th_td)
        d_d_P__next__q_thd_td = (_pd__63*d_bottom_q_r__q_thd_td + _pd__64*d_bottom_q_thd__q_thd_td
            + _pd__65*d_d_Q__q_thd_td + _pd__66*d_d_h__q_thd_td + _pd__67*d_d_wp__q_thd_td)
        d_d_P__next__k_c = (_pd__63*d_bottom_q_r__k_c + _pd__64*d_bottom_q_thd__k_c + _pd__65*d_d_Q__k_c
            + _pd__66*d_d_h__k_c + _pd__67*d_d_wp__k_c)
        d_d_P__next__k_d = _pd__65*d_d_Q__k_d + _pd__66*d_d_h__k_d + _pd__67*d_d_wp__k_d
        _x179 = _x171*m
        d_T__next = _x179*d_e_next + t_bottom
        _pd__68 = _x179
        _pd__69 = -_x173*d_e_next*m
        _x180 = 4.0*_pd__68
        d_d_T__next__q_r_td = _pd__69*d_d_h__q_r_td + _x180*d_d_e__q_r_td + d_c_T__q_r_td
        d_d_T__next__q_rd_td = _pd__69*d_d_h__q_rd_td + _x180*d_d_e__q_rd_td + d_c_T__q_rd_td
        d_d_T__next__q_th_td = _pd__69*d_d_h__q_th_td + _x180*d_d_e__q_th_td + d_c_T__q_th_td
        d_d_T__next__q_thd_td = _pd__69*d_d_h__q_thd_td + _x180*d_d_e__q_thd_td + d_c_T__q_thd_td
        d_d_T__next__k_c = _pd__69*d_d_h__k_c + _x180*d_d_e__k_c + d_c_T__k_c
        d_d_T__next__k_d = _pd__69*d_d_h__k_d + _x180*d_d_e__k_d
        _n1_4 = 4.0*d_d_e__q_r_td
        _n1_5 = 4.0*d_d_e__q_rd_td
        _n1_6 = 4.0*d_d_e__q_th_td
        _n1_7 = 4.0*d_d_e__q_thd_td
        _n1_8 = 4.0*d_d_e__k_c
        _n1_9 = 4.0*d_d_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn1 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n1_4, _n1_5, _n1_6, _n1_7, _n1_8, _n1_9,
            d_d_Q__next__q_r_td, d_d_Q__next__q_rd_td, d_d_Q__next__q_th_td, d_d_Q__next__q_thd_td,
            d_d_Q__next__k_c, d_d_Q__next__k_d, d_d_P__next__q_r_td, d_d_P__next__q_rd_td,
            d_d_P__next__q_th_td, d_d_P__next__q_thd_td, d_d_P__next__k_c, d_d_P__next__k_d,
            d_d_T__next__q_r_td, d_d_T__next__q_rd_td, d_d_T__next__q_th_td, d_d_T__next__q_thd_td,
            d_d_T__next__k_c, d_d_T__next__k_d, )
        _pk1 = _pkn1
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x181 = q_r_lo**2
    _x182 = (1.0/_x181)
    _x183 = m*q_r_lo**4
    _x184 = q_r_lo**3
    _x185 = _x181*l0**2*m
    _x186 = 2.0*g_s*m**2
    rad_lo = (_x182*(2.0*E_ba*_x181*m - _x183*k_d - _x184*_x186*math.cos(d_Q) + 2.0*_x184*k_d*l0*m - _x185*k_d
        - d_P**2))
    _pd__70 = -2.0*_x182*d_P
    _pd__71 = _x186*q_r_lo*math.sin(d_Q)
    _x187 = 2.0*m
    d_rad_lo__q_r_td = _pd__70*d_d_P__q_r_td + _pd__71*d_d_Q__q_r_td + _x187*d_E_ba__q_r_td
    d_rad_lo__q_rd_td = _pd__70*d_d_P__q_rd_td + _pd__71*d_d_Q__q_rd_td + _x187*d_E_ba__q_rd_td
    d_rad_lo__q_th_td = _pd__70*d_d_P__q_th_td + _pd__71*d_d_Q__q_th_td + _x187*d_E_ba__q_th_td
    d_rad_lo__q_thd_td = _pd__70*d_d_P__q_thd_td + _pd__71*d_d_Q__q_thd_td + _x187*d_E_ba__q_thd_td
    d_rad_lo__k_c = _pd__70*d_d_P__k_c + _pd__71*d_d_Q__k_c + _x187*d_E_ba__k_c
    d_rad_lo__k_d = (_pd__70*d_d_P__k_d + _pd__71*d_d_Q__k_d + _x182*(-_x183 + 2.0*_x184*l0*m - _x185)
        + _x187*d_E_ba__k_d)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x188 = (1.0/m)
    _x189 = math.sqrt(rad_lo)
    liftoff_q_rd = _x188*_x189
    _pd__72 = (0.5)*_x188/_x189
    d_liftoff_q_rd__q_r_td = _pd__72*d_rad_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _pd__72*d_rad_lo__q_rd_td
    d_liftoff_q_rd__q_th_td = _pd__72*d_rad_lo__q_th_td
    d_liftoff_q_rd__q_thd_td = _pd__72*d_rad_lo__q_thd_td
    d_liftoff_q_rd__k_c = _pd__72*d_rad_lo__k_c
    d_liftoff_q_rd__k_d = _pd__72*d_rad_lo__k_d
    liftoff_q_th = d_Q
    _x190 = _x188/q_r_lo**2
    liftoff_q_thd = _x190*d_P
    _pd__73 = _x190
    d_liftoff_q_thd__q_r_td = _pd__73*d_d_P__q_r_td
    d_liftoff_q_thd__q_rd_td = _pd__73*d_d_P__q_rd_td
    d_liftoff_q_thd__q_th_td = _pd__73*d_d_P__q_th_td
    d_liftoff_q_thd__q_thd_td = _pd__73*d_d_P__q_thd_td
    d_liftoff_q_thd__k_c = _pd__73*d_d_P__k_c
    d_liftoff_q_thd__k_d = _pd__73*d_d_P__k_d
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN70 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_c_T__q_r_td
    d_t_bottom__q_rd_td = d_c_T__q_rd_td
    d_t_bottom__q_th_td = d_c_T__q_th_td
    d_t_bottom__q_thd_td = d_c_T__q_thd_td
    d_t_bottom__k_c = d_c_T__k_c
    d_t_bottom__k_d = 0.0
    d_t_stance__q_r_td = d_d_T__q_r_td
    d_t_stance__q_rd_td = d_d_T__q_rd_td
    d_t_stance__q_th_td = d_d_T__q_th_td
    d_t_stance__q_thd_td = d_d_T__q_thd_td
    d_t_stance__k_c = d_d_T__k_c
    d_t_stance__k_d = d_d_T__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__q_r_td = d_c_Q__q_r_td
    d_bottom_q_th__q_rd_td = d_c_Q__q_rd_td
    d_bottom_q_th__q_th_td = d_c_Q__q_th_td
    d_bottom_q_th__q_thd_td = d_c_Q__q_thd_td
    d_bottom_q_th__k_c = d_c_Q__k_c
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_th__q_r_td = d_d_Q__q_r_td
    d_liftoff_q_th__q_rd_td = d_d_Q__q_rd_td
    d_liftoff_q_th__q_th_td = d_d_Q__q_th_td
    d_liftoff_q_th__q_thd_td = d_d_Q__q_thd_td
    d_liftoff_q_th__k_c = d_d_Q__k_c
    d_liftoff_q_th__k_d = d_d_Q__k_d
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
def iterative_report_stance_jacobian_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian_zeroth_gravity_type1`: arguments, out
    and status as :func:`iterative_report_stance_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_jacobian_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
            and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f
            > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_jacobian_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # the code shared between choices
    return (iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type1`: arguments,
    out and status as :func:`iterative_report_apex_return_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_jacobian_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations,
            bottom_length))
        store_row_12_84(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1522
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN70 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        2.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN70 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # E_ab (114) of the touchdown state
    _x0 = k_c*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*l0 + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__q_r_td = _x0 + _x5 + _x6*q_r_td - k_c*l0
    d_E_ab__q_rd_td = m*q_rd_td
    d_E_ab__q_th_td = -_x4*q_r_td*math.sin(q_th_td)
    d_E_ab__q_thd_td = _x2*m*q_thd_td
    d_E_ab__k_c = _x1 + _x3 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_bottom_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_bottom_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_bottom_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_bottom_q_r__k_c = _j_z_b_q_r__k
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic_jac_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[4] != STATUS_OK:
            return _NAN70 + (_c1[4],)
        bottom_q_r = _c1[0]
        _j_bottom_q_r__p = _c1[1]
        _j_bottom_q_r__E_ab = _c1[2]
        _j_bottom_q_r__k_c = _c1[3]
        # chain rule through bottom_quartic
        _x7 = _j_bottom_q_r__p*m
        d_bottom_q_r__q_r_td = _j_bottom_q_r__E_ab*d_E_ab__q_r_td + 2.0*_x7*q_r_td*q_thd_td
        d_bottom_q_r__q_rd_td = _j_bottom_q_r__E_ab*d_E_ab__q_rd_td
        d_bottom_q_r__q_th_td = _j_bottom_q_r__E_ab*d_E_ab__q_th_td
        d_bottom_q_r__q_thd_td = _j_bottom_q_r__E_ab*d_E_ab__q_thd_td + _x7*q_r_td**2
        d_bottom_q_r__k_c = _j_bottom_q_r__E_ab*d_E_ab__k_c + _j_bottom_q_r__k_c
    else:
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN70 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = bottom_q_r - q_r_td
    _x10 = _x8*_x9
    c_e_n = _x10
    _pd__0 = _x8
    _x11 = -_x8
    d_c_e_n__q_r_td = _pd__0*d_bottom_q_r__q_r_td + _x11
    d_c_e_n__q_rd_td = _pd__0*d_bottom_q_r__q_rd_td
    d_c_e_n__q_th_td = _pd__0*d_bottom_q_r__q_th_td
    d_c_e_n__q_thd_td = _pd__0*d_bottom_q_r__q_thd_td
    d_c_e_n__k_c = _pd__0*d_bottom_q_r__k_c
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
    d_c_rad_z__q_r_td = (_j_z_b_q_r__q_r_td*_pd__3 + _j_z_b_q_th__q_r_td*_pd__4 + _j_z_b_q_thd__q_r_td*_pd__5
        + _pd__1*d_bottom_q_r__q_r_td + _x15*(-_x27*(-_x23*_x41 + _x24*_x46*q_r_td*q_thd_td) - _x39 - _x47)
        + _x42 + _x51*d_c_e_n__q_r_td + _x52*d_E_ab__q_r_td)
    d_c_rad_z__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__3 + _j_z_b_q_th__q_rd_td*_pd__4
        + _j_z_b_q_thd__q_rd_td*_pd__5 + _pd__1*d_bottom_q_r__q_rd_td + _x51*d_c_e_n__q_rd_td
        + _x52*d_E_ab__q_rd_td)
    d_c_rad_z__q_th_td = (_j_z_b_q_r__q_th_td*_pd__3 + _j_z_b_q_th__q_th_td*_pd__4
        + _j_z_b_q_thd__q_th_td*_pd__5 + _pd__1*d_bottom_q_r__q_th_td + _x24*_x50 + _x51*d_c_e_n__q_th_td
        + _x52*d_E_ab__q_th_td)
    d_c_rad_z__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__3 + _j_z_b_q_th__q_thd_td*_pd__4
        + _j_z_b_q_thd__q_thd_td*_pd__5 + _pd__1*d_bottom_q_r__q_thd_td - 2.0*_x24*_x25*_x49
        + _x51*d_c_e_n__q_thd_td + _x52*d_E_ab__q_thd_td)
    d_c_rad_z__k_c = (_j_z_b_q_r__k*_pd__3 + _j_z_b_q_th__k*_pd__4 + _j_z_b_q_thd__k*_pd__5
        + _pd__1*d_bottom_q_r__k_c + _x15*(-_x16 + 2.0*_x17*l0*m - _x19) + _x51*d_c_e_n__k_c
        + _x52*d_E_ab__k_c)
    _x53 = math.sqrt(_x11 + 1.0)
    c_Q0 = _x29*_x53 + z_b_q_th
    _x54 = (0.5)/_x53
    _x55 = _x36*_x54
    _x56 = _x55*_x8
    _pd__6 = _x56
    _pd__7 = -_x55
    _pd__8 = 1.0 - _x53
    d_c_Q0__q_r_td = _j_z_b_q_th__q_r_td*_pd__8 + _pd__6*d_bottom_q_r__q_r_td + _pd__7*d_c_e_n__q_r_td - _x56
    d_c_Q0__q_rd_td = _j_z_b_q_th__q_rd_td*_pd__8 + _pd__6*d_bottom_q_r__q_rd_td + _pd__7*d_c_e_n__q_rd_td
    d_c_Q0__q_th_td = (_j_z_b_q_th__q_th_td*_pd__8 + _pd__6*d_bottom_q_r__q_th_td + _pd__7*d_c_e_n__q_th_td
        + _x53)
    d_c_Q0__q_thd_td = _j_z_b_q_th__q_thd_td*_pd__8 + _pd__6*d_bottom_q_r__q_thd_td + _pd__7*d_c_e_n__q_thd_td
    d_c_Q0__k_c = _j_z_b_q_th__k*_pd__8 + _pd__6*d_bottom_q_r__k_c + _pd__7*d_c_e_n__k_c
    c_P0 = _x22 + _x26*_x53
    _x57 = _x40*_x54
    _x58 = _x57*_x8
    _pd__9 = _x58
    _pd__10 = -_x57
    _pd__11 = -_x48*_x52*_x53 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__12 = _x20*m - _x21*_x53
    d_c_P0__q_r_td = (_j_z_b_q_r__q_r_td*_pd__11 + _j_z_b_q_thd__q_r_td*_pd__12 + _pd__10*d_c_e_n__q_r_td
        + _pd__9*d_bottom_q_r__q_r_td + _x43*_x53*m*q_thd_td - _x58)
    d_c_P0__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__11 + _j_z_b_q_thd__q_rd_td*_pd__12 + _pd__10*d_c_e_n__q_rd_td
        + _pd__9*d_bottom_q_r__q_rd_td)
    d_c_P0__q_th_td = (_j_z_b_q_r__q_th_td*_pd__11 + _j_z_b_q_thd__q_th_td*_pd__12 + _pd__10*d_c_e_n__q_th_td
        + _pd__9*d_bottom_q_r__q_th_td)
    d_c_P0__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__11 + _j_z_b_q_thd__q_thd_td*_pd__12
        + _pd__10*d_c_e_n__q_thd_td + _pd__9*d_bottom_q_r__q_thd_td + _x25*_x53)
    d_c_P0__k_c = (_j_z_b_q_r__k*_pd__11 + _j_z_b_q_thd__k*_pd__12 + _pd__10*d_c_e_n__k_c
        + _pd__9*d_bottom_q_r__k_c)
    _x59 = m/math.sqrt(_x33)
    _x60 = (_x33 > 0.0)
    c_T0 = ((-_x10*_x59) if _x60 else (0.0))
    _pd__13 = ((-_x59) if _x60 else (0.0))
    _pd__14 = ((_x44*m/(_x33*math.sqrt(_x33))) if _x60 else (0.0))
    d_c_T0__q_r_td = _pd__13*d_c_e_n__q_r_td + _pd__14*d_c_rad_z__q_r_td
    d_c_T0__q_rd_td = _pd__13*d_c_e_n__q_rd_td + _pd__14*d_c_rad_z__q_rd_td
    d_c_T0__q_th_td = _pd__13*d_c_e_n__q_th_td + _pd__14*d_c_rad_z__q_th_td
    d_c_T0__q_thd_td = _pd__13*d_c_e_n__q_thd_td + _pd__14*d_c_rad_z__q_thd_td
    d_c_T0__k_c = _pd__13*d_c_e_n__k_c + _pd__14*d_c_rad_z__k_c
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__q_r_td, d_c_e_n__q_rd_td, d_c_e_n__q_th_td, d_c_e_n__q_thd_td,
        d_c_e_n__k_c, d_c_Q0__q_r_td, d_c_Q0__q_rd_td, d_c_Q0__q_th_td, d_c_Q0__q_thd_td, d_c_Q0__k_c,
        d_c_P0__q_r_td, d_c_P0__q_rd_td, d_c_P0__q_th_td, d_c_P0__q_thd_td, d_c_P0__k_c, d_c_T0__q_r_td,
        d_c_T0__q_rd_td, d_c_T0__q_th_td, d_c_T0__q_thd_td, d_c_T0__k_c, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__q_r_td, d_c_e__q_rd_td, d_c_e__q_th_td, d_c_e__q_thd_td, d_c_e__k_c,
            d_c_Q__q_r_td, d_c_Q__q_rd_td, d_c_Q__q_th_td, d_c_Q__q_thd_td, d_c_Q__k_c, d_c_P__q_r_td,
            d_c_P__q_rd_td, d_c_P__q_th_td, d_c_P__q_thd_td, d_c_P__k_c, d_c_T__q_r_td, d_c_T__q_rd_td,
            d_c_T__q_th_td, d_c_T__q_thd_td, d_c_T__k_c, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x61 = c_e + q_r_td
        c_x = _x61
        d_c_x__q_r_td = d_c_e__q_r_td + 1.0
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
        d_c_rad__q_r_td = (_pd__15*d_c_P__q_r_td + _pd__16*d_c_Q__q_r_td + _pd__17*d_c_x__q_r_td
            + _x72*d_E_ab__q_r_td)
        d_c_rad__q_rd_td = (_pd__15*d_c_P__q_rd_td + _pd__16*d_c_Q__q_rd_td + _pd__17*d_c_e__q_rd_td
            + _x72*d_E_ab__q_rd_td)
        d_c_rad__q_th_td = (_pd__15*d_c_P__q_th_td + _pd__16*d_c_Q__q_th_td + _pd__17*d_c_e__q_th_td
            + _x72*d_E_ab__q_th_td)
        d_c_rad__q_thd_td = (_pd__15*d_c_P__q_thd_td + _pd__16*d_c_Q__q_thd_td + _pd__17*d_c_e__q_thd_td
            + _x72*d_E_ab__q_thd_td)
        d_c_rad__k_c = (_pd__15*d_c_P__k_c + _pd__16*d_c_Q__k_c + _pd__17*d_c_e__k_c + _x63*(-_x64
            + 2.0*_x65*l0*m - _x67) + _x72*d_E_ab__k_c)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x73 = math.sqrt(c_rad)
        c_h = _x73
        _pd__18 = (0.5)/_x73
        d_c_h__q_r_td = _pd__18*d_c_rad__q_r_td
        d_c_h__q_rd_td = _pd__18*d_c_rad__q_rd_td
        d_c_h__q_th_td = _pd__18*d_c_rad__q_th_td
        d_c_h__q_thd_td = _pd__18*d_c_rad__q_thd_td
        d_c_h__k_c = _pd__18*d_c_rad__k_c
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x77 = (1.0/c_x)
            _x74 = _x77**2
            c_wq = _x74*c_e_next
            _pd__19 = _x74
            _pd__20 = -2.0*_x77**3*c_e_next
            _x75 = 4.0*_pd__19
            d_c_wq__q_r_td = _pd__20*d_c_x__q_r_td + _x75*d_c_e__q_r_td
            d_c_wq__q_rd_td = _pd__20*d_c_e__q_rd_td + _x75*d_c_e__q_rd_td
            d_c_wq__q_th_td = _pd__20*d_c_e__q_th_td + _x75*d_c_e__q_th_td
            d_c_wq__q_thd_td = _pd__20*d_c_e__q_thd_td + _x75*d_c_e__q_thd_td
            d_c_wq__k_c = _pd__20*d_c_e__k_c + _x75*d_c_e__k_c
            c_wp = c_e_next*c_x
            _x76 = 4.0*c_x
            d_c_wp__q_r_td = _x76*d_c_e__q_r_td + c_e_next*d_c_x__q_r_td
            d_c_wp__q_rd_td = _x76*d_c_e__q_rd_td + c_e_next*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x76*d_c_e__q_th_td + c_e_next*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x76*d_c_e__q_thd_td + c_e_next*d_c_e__q_thd_td
            d_c_wp__k_c = _x76*d_c_e__k_c + c_e_next*d_c_e__k_c
        elif variant == 1.0:
            _x78 = (1.0/q_r_td)
            _x79 = c_e_next + q_r_td
            _x80 = (1.0/_x79)
            c_wq = _x78*_x80*c_e_next
            _x81 = _x78*_x80**2*c_e_next
            _pd__21 = _x78*_x80 - _x81
            d_c_wq__q_r_td = 4.0*_pd__21*d_c_e__q_r_td - _x78**2*_x80*c_e_next - _x81
            _x82 = 4.0*_pd__21
            d_c_wq__q_rd_td = _x82*d_c_e__q_rd_td
            d_c_wq__q_th_td = _x82*d_c_e__q_th_td
            d_c_wq__q_thd_td = _x82*d_c_e__q_thd_td
            d_c_wq__k_c = _x82*d_c_e__k_c
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__22 = _x79
            _x83 = 4.0*_pd__22
            d_c_wp__q_r_td = _x83*d_c_e__q_r_td + c_e_next
            d_c_wp__q_rd_td = _x83*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x83*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x83*d_c_e__q_thd_td
            d_c_wp__k_c = _x83*d_c_e__k_c
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        c_e__next = c_e_next
        _x84 = (1.0/c_h)
        _x85 = _x84*c_wq
        c_Q__next = -_x85*c_P + q_th_td
        _pd__23 = -_x85
        _x86 = _x84**2
        _pd__24 = _x86*c_P*c_wq
        _pd__25 = -_x84*c_P
        d_c_Q__next__q_r_td = _pd__23*d_c_P__q_r_td + _pd__24*d_c_h__q_r_td + _pd__25*d_c_wq__q_r_td
        d_c_Q__next__q_rd_td = _pd__23*d_c_P__q_rd_td + _pd__24*d_c_h__q_rd_td + _pd__25*d_c_wq__q_rd_td
        d_c_Q__next__q_th_td = _pd__23*d_c_P__q_th_td + _pd__24*d_c_h__q_th_td + _pd__25*d_c_wq__q_th_td + 1.0
        d_c_Q__next__q_thd_td = _pd__23*d_c_P__q_thd_td + _pd__24*d_c_h__q_thd_td + _pd__25*d_c_wq__q_thd_td
        d_c_Q__next__k_c = _pd__23*d_c_P__k_c + _pd__24*d_c_h__k_c + _pd__25*d_c_wq__k_c
        _x87 = m*q_r_td**2
        _x88 = math.sin(c_Q)
        _x89 = m**2
        _x90 = _x84*_x89*g_s
        _x91 = _x88*_x90
        c_P__next = _x87*q_thd_td - _x91*c_wp
        _pd__26 = -_x90*c_wp*math.cos(c_Q)
        _pd__27 = _x86*_x88*_x89*c_wp*g_s
        _pd__28 = -_x91
        d_c_P__next__q_r_td = (_pd__26*d_c_Q__q_r_td + _pd__27*d_c_h__q_r_td + _pd__28*d_c_wp__q_r_td
            + 2.0*m*q_r_td*q_thd_td)
        d_c_P__next__q_rd_td = _pd__26*d_c_Q__q_rd_td + _pd__27*d_c_h__q_rd_td + _pd__28*d_c_wp__q_rd_td
        d_c_P__next__q_th_td = _pd__26*d_c_Q__q_th_td + _pd__27*d_c_h__q_th_td + _pd__28*d_c_wp__q_th_td
        d_c_P__next__q_thd_td = (_pd__26*d_c_Q__q_thd_td + _pd__27*d_c_h__q_thd_td + _pd__28*d_c_wp__q_thd_td
            + _x87)
        d_c_P__next__k_c = _pd__26*d_c_Q__k_c + _pd__27*d_c_h__k_c + _pd__28*d_c_wp__k_c
        _x92 = _x84*m
        c_T__next = -_x92*c_e_next
        _pd__29 = -_x92
        _pd__30 = _x86*c_e_next*m
        _x93 = 4.0*_pd__29
        d_c_T__next__q_r_td = _pd__30*d_c_h__q_r_td + _x93*d_c_e__q_r_td
        d_c_T__next__q_rd_td = _pd__30*d_c_h__q_rd_td + _x93*d_c_e__q_rd_td
        d_c_T__next__q_th_td = _pd__30*d_c_h__q_th_td + _x93*d_c_e__q_th_td
        d_c_T__next__q_thd_td = _pd__30*d_c_h__q_thd_td + _x93*d_c_e__q_thd_td
        d_c_T__next__k_c = _pd__30*d_c_h__k_c + _x93*d_c_e__k_c
        _n0_4 = 4.0*d_c_e__q_r_td
        _n0_5 = 4.0*d_c_e__q_rd_td
        _n0_6 = 4.0*d_c_e__q_th_td
        _n0_7 = 4.0*d_c_e__q_thd_td
        _n0_8 = 4.0*d_c_e__k_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8,
            d_c_Q__next__q_r_td, d_c_Q__next__q_rd_td, d_c_Q__next__q_th_td, d_c_Q__next__q_thd_td,
            d_c_Q__next__k_c, d_c_P__next__q_r_td, d_c_P__next__q_rd_td, d_c_P__next__q_th_td,
            d_c_P__next__q_thd_td, d_c_P__next__k_c, d_c_T__next__q_r_td, d_c_T__next__q_rd_td,
            d_c_T__next__q_th_td, d_c_T__next__q_thd_td, d_c_T__next__k_c, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    _x94 = (1.0/m)
    _x96 = (1.0/bottom_q_r)
    _x95 = _x94*_x96**2
    bottom_q_thd = _x95*c_P
    _pd__31 = -2.0*_x94*_x96**3*c_P
    _pd__32 = _x95
    d_bottom_q_thd__q_r_td = _pd__31*d_bottom_q_r__q_r_td + _pd__32*d_c_P__q_r_td
    d_bottom_q_thd__q_rd_td = _pd__31*d_bottom_q_r__q_rd_td + _pd__32*d_c_P__q_rd_td
    d_bottom_q_thd__q_th_td = _pd__31*d_bottom_q_r__q_th_td + _pd__32*d_c_P__q_th_td
    d_bottom_q_thd__q_thd_td = _pd__31*d_bottom_q_r__q_thd_td + _pd__32*d_c_P__q_thd_td
    d_bottom_q_thd__k_c = _pd__31*d_bottom_q_r__k_c + _pd__32*d_c_P__k_c
    # E_ba of (98): the energy jump of the stiffness switch
    _x97 = (-bottom_q_r + l0)**2
    _x98 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x97*_x98
    _pd__33 = _x98*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__q_r_td = _pd__33*d_bottom_q_r__q_r_td + d_E_ab__q_r_td
    d_E_ba__q_rd_td = _pd__33*d_bottom_q_r__q_rd_td + d_E_ab__q_rd_td
    d_E_ba__q_th_td = _pd__33*d_bottom_q_r__q_th_td + d_E_ab__q_th_td
    d_E_ba__q_thd_td = _pd__33*d_bottom_q_r__q_thd_td + d_E_ab__q_thd_td
    _x99 = (0.5)*_x97
    d_E_ba__k_c = _pd__33*d_bottom_q_r__k_c - _x99 + d_E_ab__k_c
    d_E_ba__k_d = _x99
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN70 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x100 = 4.0**(-iterations)
    _x101 = -bottom_q_r + q_r_lo
    _x102 = _x100*_x101
    d_e_n = _x102
    _pd__34 = -_x100
    d_d_e_n__q_r_td = _pd__34*d_bottom_q_r__q_r_td
    d_d_e_n__q_rd_td = _pd__34*d_bottom_q_r__q_rd_td
    d_d_e_n__q_th_td = _pd__34*d_bottom_q_r__q_th_td
    d_d_e_n__q_thd_td = _pd__34*d_bottom_q_r__q_thd_td
    d_d_e_n__k_c = _pd__34*d_bottom_q_r__k_c
    _x103 = (0.25)*_x102
    d_e_z = _x103
    _x104 = _x103 + bottom_q_r
    _x105 = _x104**2
    _x106 = (1.0/_x105)
    _x107 = _x104**4*m
    _x108 = _x104**3
    _x109 = l0**2*m
    _x110 = _x105*_x109
    _x111 = bottom_q_r**2*m
    _x112 = _x111*bottom_q_thd
    _x113 = q_r_lo**2
    _x114 = -_x112 + _x113*g_lo_q_thd*m
    _x115 = 4.0**((0.5)*iterations)
    _x116 = (1.0/_x115)
    _x117 = (0.5)*_x116
    _x118 = _x114*_x117
    _x119 = _x112 + _x118
    _x120 = -bottom_q_th + g_lo_q_th
    _x121 = _x117*_x120
    _x122 = _x121 + bottom_q_th
    _x123 = m**2
    _x124 = _x123*g_s
    _x125 = _x124*math.cos(_x122)
    _x126 = 2.0*E_ba*_x105*m - _x107*k_d - 2.0*_x108*_x125 + 2.0*_x108*k_d*l0*m - _x110*k_d - _x119**2
    _x127 = _x106*_x126
    d_rad_z = _x127
    _x128 = -2.0*_x126/_x108
    _x129 = 4.0*m
    _x130 = (1.0/_x101)
    _x131 = 2.0*bottom_q_r
    _x132 = _x131*bottom_q_thd*m
    _x133 = -_x116*_x132 + _x118*_x130
    _x134 = math.sin(_x122)
    _x135 = (0.5)*_x102
    _x136 = _x131 + _x135
    _x137 = -2.0*E_ba*_x136*m + 6.0*_x105*_x125 - 6.0*_x105*k_d*l0*m + _x108*_x129*k_d + _x109*_x136*k_d
    _pd__35 = (_x106*((0.5)*_x108*_x116*_x120*_x123*_x130*_x134*g_s - _x119*(_x129*bottom_q_r*bottom_q_thd
        + _x133) - _x137) + _x128)
    _x138 = _x104*_x124*_x134
    _pd__36 = 2.0*_x138*(1.0 - _x117)
    _x139 = -_x111*_x116
    _x140 = _x106*_x119
    _pd__37 = -_x140*(2.0*_x111 + _x139)
    _x141 = _x115*_x130
    _pd__38 = _x106*(2.0*_x108*_x115*_x120*_x123*_x130*_x134*g_s - 2.0*_x114*_x119*_x141 - _x137) + _x128
    _pd__39 = _x116*_x138
    _x142 = _x113*_x116*m
    _pd__40 = -_x140*_x142
    _x143 = (0.25)*_pd__38
    _x144 = 2.0*m
    d_d_rad_z__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__39 + _j_z_lo_q_thd__q_r_td*_pd__40
        + _pd__35*d_bottom_q_r__q_r_td + _pd__36*d_c_Q__q_r_td + _pd__37*d_bottom_q_thd__q_r_td
        + _x143*d_d_e_n__q_r_td + _x144*d_E_ba__q_r_td)
    d_d_rad_z__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__39 + _j_z_lo_q_thd__q_rd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_rd_td + _pd__36*d_c_Q__q_rd_td + _pd__37*d_bottom_q_thd__q_rd_td
        + _x143*d_d_e_n__q_rd_td + _x144*d_E_ba__q_rd_td)
    d_d_rad_z__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__39 + _j_z_lo_q_thd__q_th_td*_pd__40
        + _pd__35*d_bottom_q_r__q_th_td + _pd__36*d_c_Q__q_th_td + _pd__37*d_bottom_q_thd__q_th_td
        + _x143*d_d_e_n__q_th_td + _x144*d_E_ba__q_th_td)
    d_d_rad_z__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__39 + _j_z_lo_q_thd__q_thd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_thd_td + _pd__36*d_c_Q__q_thd_td + _pd__37*d_bottom_q_thd__q_thd_td
        + _x143*d_d_e_n__q_thd_td + _x144*d_E_ba__q_thd_td)
    d_d_rad_z__k_c = (_j_z_lo_q_th__k*_pd__39 + _j_z_lo_q_thd__k*_pd__40 + _pd__35*d_bottom_q_r__k_c
        + _pd__36*d_c_Q__k_c + _pd__37*d_bottom_q_thd__k_c + _x143*d_d_e_n__k_c + _x144*d_E_ba__k_c)
    d_d_rad_z__k_d = _x106*(-_x107 + 2.0*_x108*l0*m - _x110) + _x144*d_E_ba__k_d
    d_Q0 = _x116*_x120 + bottom_q_th
    _pd__41 = _x121*_x130
    _pd__42 = 1.0 - _x116
    _x145 = (0.5)*_x141
    _pd__43 = _x120*_x145
    _pd__44 = _x116
    d_d_Q0__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__44 + _pd__41*d_bottom_q_r__q_r_td + _pd__42*d_c_Q__q_r_td
        + _pd__43*d_d_e_n__q_r_td)
    d_d_Q0__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__44 + _pd__41*d_bottom_q_r__q_rd_td + _pd__42*d_c_Q__q_rd_td
        + _pd__43*d_d_e_n__q_rd_td)
    d_d_Q0__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__44 + _pd__41*d_bottom_q_r__q_th_td + _pd__42*d_c_Q__q_th_td
        + _pd__43*d_d_e_n__q_th_td)
    d_d_Q0__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__44 + _pd__41*d_bottom_q_r__q_thd_td
        + _pd__42*d_c_Q__q_thd_td + _pd__43*d_d_e_n__q_thd_td)
    d_d_Q0__k_c = (_j_z_lo_q_th__k*_pd__44 + _pd__41*d_bottom_q_r__k_c + _pd__42*d_c_Q__k_c
        + _pd__43*d_d_e_n__k_c)
    d_P0 = _x112 + _x114*_x116
    _pd__45 = _x132 + _x133
    _pd__46 = _x111 + _x139
    _pd__47 = _x114*_x145
    _pd__48 = _x142
    d_d_P0__q_r_td = (_j_z_lo_q_thd__q_r_td*_pd__48 + _pd__45*d_bottom_q_r__q_r_td
        + _pd__46*d_bottom_q_thd__q_r_td + _pd__47*d_d_e_n__q_r_td)
    d_d_P0__q_rd_td = (_j_z_lo_q_thd__q_rd_td*_pd__48 + _pd__45*d_bottom_q_r__q_rd_td
        + _pd__46*d_bottom_q_thd__q_rd_td + _pd__47*d_d_e_n__q_rd_td)
    d_d_P0__q_th_td = (_j_z_lo_q_thd__q_th_td*_pd__48 + _pd__45*d_bottom_q_r__q_th_td
        + _pd__46*d_bottom_q_thd__q_th_td + _pd__47*d_d_e_n__q_th_td)
    d_d_P0__q_thd_td = (_j_z_lo_q_thd__q_thd_td*_pd__48 + _pd__45*d_bottom_q_r__q_thd_td
        + _pd__46*d_bottom_q_thd__q_thd_td + _pd__47*d_d_e_n__q_thd_td)
    d_d_P0__k_c = (_j_z_lo_q_thd__k*_pd__48 + _pd__45*d_bottom_q_r__k_c + _pd__46*d_bottom_q_thd__k_c
        + _pd__47*d_d_e_n__k_c)
    _x146 = m/math.sqrt(_x127)
    _x147 = (_x127 > 0.0)
    d_T0 = ((_x102*_x146 + t_bottom) if _x147 else (t_bottom))
    _pd__49 = ((_x146) if _x147 else (0.0))
    _pd__50 = ((-_x135*m/(_x127*math.sqrt(_x127))) if _x147 else (0.0))
    d_d_T0__q_r_td = _pd__49*d_d_e_n__q_r_td + _pd__50*d_d_rad_z__q_r_td + d_c_T__q_r_td
    d_d_T0__q_rd_td = _pd__49*d_d_e_n__q_rd_td + _pd__50*d_d_rad_z__q_rd_td + d_c_T__q_rd_td
    d_d_T0__q_th_td = _pd__49*d_d_e_n__q_th_td + _pd__50*d_d_rad_z__q_th_td + d_c_T__q_th_td
    d_d_T0__q_thd_td = _pd__49*d_d_e_n__q_thd_td + _pd__50*d_d_rad_z__q_thd_td + d_c_T__q_thd_td
    d_d_T0__k_c = _pd__49*d_d_e_n__k_c + _pd__50*d_d_rad_z__k_c + d_c_T__k_c
    d_d_T0__k_d = _pd__50*d_d_rad_z__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki1 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__q_r_td, d_d_e_n__q_rd_td, d_d_e_n__q_th_td, d_d_e_n__q_thd_td,
        d_d_e_n__k_c, 0.0, d_d_Q0__q_r_td, d_d_Q0__q_rd_td, d_d_Q0__q_th_td, d_d_Q0__q_thd_td, d_d_Q0__k_c,
        0.0, d_d_P0__q_r_td, d_d_P0__q_rd_td, d_d_P0__q_th_td, d_d_P0__q_thd_td, d_d_P0__k_c, 0.0,
        d_d_T0__q_r_td, d_d_T0__q_rd_td, d_d_T0__q_th_td, d_d_T0__q_thd_td, d_d_T0__k_c, d_d_T0__k_d, )
    _pk1 = _pki1
    d_steps = 0.0
    _conv1 = False
    _last1 = max(int(iterations), 0)
    for _it1 in range(_last1 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__q_r_td, d_d_e__q_rd_td, d_d_e__q_th_td, d_d_e__q_thd_td, d_d_e__k_c,
            d_d_e__k_d, d_d_Q__q_r_td, d_d_Q__q_rd_td, d_d_Q__q_th_td, d_d_Q__q_thd_td, d_d_Q__k_c,
            d_d_Q__k_d, d_d_P__q_r_td, d_d_P__q_rd_td, d_d_P__q_th_td, d_d_P__q_thd_td, d_d_P__k_c,
            d_d_P__k_d, d_d_T__q_r_td, d_d_T__q_rd_td, d_d_T__q_th_td, d_d_T__q_thd_td, d_d_T__k_c,
            d_d_T__k_d, ) = _pk1
        if _conv1 or _it1 == _last1:
            break
        _x148 = bottom_q_r + d_e
        d_x = _x148
        d_d_x__q_r_td = d_bottom_q_r__q_r_td + d_d_e__q_r_td
        d_d_x__q_rd_td = d_bottom_q_r__q_rd_td + d_d_e__q_rd_td
        d_d_x__q_th_td = d_bottom_q_r__q_th_td + d_d_e__q_th_td
        d_d_x__q_thd_td = d_bottom_q_r__q_thd_td + d_d_e__q_thd_td
        d_d_x__k_c = d_bottom_q_r__k_c + d_d_e__k_c
        _x149 = _x148**2
        _x150 = (1.0/_x149)
        _x151 = _x148**4*m
        _x152 = _x148**3
        _x153 = l0**2
        _x154 = _x149*_x153*m
        _x155 = math.cos(d_Q)
        _x156 = m**2
        _x157 = 2.0*_x156*g_s
        _x158 = 2.0*E_ba*_x149*m - _x151*k_d - _x152*_x155*_x157 + 2.0*_x152*k_d*l0*m - _x154*k_d - d_P**2
        d_rad = _x150*_x158
        _pd__51 = -2.0*_x150*d_P
        _pd__52 = _x148*_x157*math.sin(d_Q)
        _x159 = 2.0*m
        _pd__53 = (_x150*(4.0*E_ba*_x148*m - _x148*_x153*_x159*k_d - 6.0*_x149*_x155*_x156*g_s
            + 6.0*_x149*k_d*l0*m - 4.0*_x152*k_d*m) - 2.0*_x158/_x152)
        d_d_rad__q_r_td = (_pd__51*d_d_P__q_r_td + _pd__52*d_d_Q__q_r_td + _pd__53*d_d_x__q_r_td
            + _x159*d_E_ba__q_r_td)
        d_d_rad__q_rd_td = (_pd__51*d_d_P__q_rd_td + _pd__52*d_d_Q__q_rd_td + _pd__53*d_d_x__q_rd_td
            + _x159*d_E_ba__q_rd_td)
        d_d_rad__q_th_td = (_pd__51*d_d_P__q_th_td + _pd__52*d_d_Q__q_th_td + _pd__53*d_d_x__q_th_td
            + _x159*d_E_ba__q_th_td)
        d_d_rad__q_thd_td = (_pd__51*d_d_P__q_thd_td + _pd__52*d_d_Q__q_thd_td + _pd__53*d_d_x__q_thd_td
            + _x159*d_E_ba__q_thd_td)
        d_d_rad__k_c = _pd__51*d_d_P__k_c + _pd__52*d_d_Q__k_c + _pd__53*d_d_x__k_c + _x159*d_E_ba__k_c
        d_d_rad__k_d = (_pd__51*d_d_P__k_d + _pd__52*d_d_Q__k_d + _pd__53*d_d_e__k_d + _x150*(-_x151
            + 2.0*_x152*l0*m - _x154) + _x159*d_E_ba__k_d)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x160 = math.sqrt(d_rad)
        d_h = _x160
        _pd__54 = (0.5)/_x160
        d_d_h__q_r_td = _pd__54*d_d_rad__q_r_td
        d_d_h__q_rd_td = _pd__54*d_d_rad__q_rd_td
        d_d_h__q_th_td = _pd__54*d_d_rad__q_th_td
        d_d_h__q_thd_td = _pd__54*d_d_rad__q_thd_td
        d_d_h__k_c = _pd__54*d_d_rad__k_c
        d_d_h__k_d = _pd__54*d_d_rad__k_d
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x164 = (1.0/d_x)
            _x161 = _x164**2
            d_wq = _x161*d_e_next
            _pd__55 = _x161
            _pd__56 = -2.0*_x164**3*d_e_next
            _x162 = 4.0*_pd__55
            d_d_wq__q_r_td = _pd__56*d_d_x__q_r_td + _x162*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__56*d_d_x__q_rd_td + _x162*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__56*d_d_x__q_th_td + _x162*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__56*d_d_x__q_thd_td + _x162*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__56*d_d_x__k_c + _x162*d_d_e__k_c
            d_d_wq__k_d = _pd__56*d_d_e__k_d + _x162*d_d_e__k_d
            d_wp = d_e_next*d_x
            _x163 = 4.0*d_x
            d_d_wp__q_r_td = _x163*d_d_e__q_r_td + d_d_x__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x163*d_d_e__q_rd_td + d_d_x__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x163*d_d_e__q_th_td + d_d_x__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x163*d_d_e__q_thd_td + d_d_x__q_thd_td*d_e_next
            d_d_wp__k_c = _x163*d_d_e__k_c + d_d_x__k_c*d_e_next
            d_d_wp__k_d = _x163*d_d_e__k_d + d_d_e__k_d*d_e_next
        elif variant == 1.0:
            _x165 = (1.0/bottom_q_r)
            _x166 = bottom_q_r + d_e_next
            _x167 = (1.0/_x166)
            d_wq = _x165*_x167*d_e_next
            _x168 = _x165*_x167**2*d_e_next
            _pd__57 = -_x165**2*_x167*d_e_next - _x168
            _pd__58 = _x165*_x167 - _x168
            _x169 = 4.0*_pd__58
            d_d_wq__q_r_td = _pd__57*d_bottom_q_r__q_r_td + _x169*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__57*d_bottom_q_r__q_rd_td + _x169*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__57*d_bottom_q_r__q_th_td + _x169*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__57*d_bottom_q_r__q_thd_td + _x169*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__57*d_bottom_q_r__k_c + _x169*d_d_e__k_c
            d_d_wq__k_d = _x169*d_d_e__k_d
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__59 = _x166
            _x170 = 4.0*_pd__59
            d_d_wp__q_r_td = _x170*d_d_e__q_r_td + d_bottom_q_r__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x170*d_d_e__q_rd_td + d_bottom_q_r__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x170*d_d_e__q_th_td + d_bottom_q_r__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x170*d_d_e__q_thd_td + d_bottom_q_r__q_thd_td*d_e_next
            d_d_wp__k_c = _x170*d_d_e__k_c + d_bottom_q_r__k_c*d_e_next
            d_d_wp__k_d = _x170*d_d_e__k_d
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        d_e__next = d_e_next
        _x171 = (1.0/d_h)
        _x172 = _x171*d_wq
        d_Q__next = _x172*d_P + bottom_q_th
        _pd__60 = _x172
        _x173 = _x171**2
        _pd__61 = -_x173*d_P*d_wq
        _pd__62 = _x171*d_P
        d_d_Q__next__q_r_td = (_pd__60*d_d_P__q_r_td + _pd__61*d_d_h__q_r_td + _pd__62*d_d_wq__q_r_td
            + d_c_Q__q_r_td)
        d_d_Q__next__q_rd_td = (_pd__60*d_d_P__q_rd_td + _pd__61*d_d_h__q_rd_td + _pd__62*d_d_wq__q_rd_td
            + d_c_Q__q_rd_td)
        d_d_Q__next__q_th_td = (_pd__60*d_d_P__q_th_td + _pd__61*d_d_h__q_th_td + _pd__62*d_d_wq__q_th_td
            + d_c_Q__q_th_td)
        d_d_Q__next__q_thd_td = (_pd__60*d_d_P__q_thd_td + _pd__61*d_d_h__q_thd_td + _pd__62*d_d_wq__q_thd_td
            + d_c_Q__q_thd_td)
        d_d_Q__next__k_c = _pd__60*d_d_P__k_c + _pd__61*d_d_h__k_c + _pd__62*d_d_wq__k_c + d_c_Q__k_c
        d_d_Q__next__k_d = _pd__60*d_d_P__k_d + _pd__61*d_d_h__k_d + _pd__62*d_d_wq__k_d
        _x174 = bottom_q_r**2*m
        _x175 = math.sin(d_Q)
        _x176 = m**2
        _x177 = _x171*_x176*g_s
        _x178 = _x175*_x177
        d_P__next = _x174*bottom_q_thd + _x178*d_wp
        _pd__63 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__64 = _x174
        _pd__65 = _x177*d_wp*math.cos(d_Q)
        _pd__66 = -_x173*_x175*_x176*d_wp*g_s
        _pd__67 = _x178
        d_d_P__next__q_r_td = (_pd__63*d_bottom_q_r__q_r_td + _pd__64*d_bottom_q_thd__q_r_td
            + _pd__65*d_d_Q__q_r_td + _pd__66*d_d_h__q_r_td + _pd__67*d_d_wp__q_r_td)
        d_d_P__next__q_rd_td = (_pd__63*d_bottom_q_r__q_rd_td + _pd__64*d_bottom_q_thd__q_rd_td
            + _pd__65*d_d_Q__q_rd_td + _pd__66*d_d_h__q_rd_td + _pd__67*d_d_wp__q_rd_td)
        d_d_P__next__q_th_td = (_pd__63*d_bottom_q_r__q_th_td + _pd__64*d_bottom_q_thd__q_th_td
            + _pd__65*d_d_Q__q_th_td + _pd__66*d_d_h__q_th_td + _pd__67*d_d_wp__q_th_td)
        d_d_P__next__q_thd_td = (_pd__63*d_bottom_q_r__q_thd_td + _pd__64*d_bottom_q_thd__q_thd_td
            + _pd__65*d_d_Q__q_thd_td + _pd__66*d_d_h__q_thd_td + _pd__67*d_d_wp__q_thd_td)
        d_d_P__next__k_c = (_pd__63*d_bottom_q_r__k_c + _pd__64*d_bottom_q_thd__k_c + _pd__65*d_d_Q__k_c
            + _pd__66*d_d_h__k_c + _pd__67*d_d_wp__k_c)
        d_d_P__next__k_d = _pd__65*d_d_Q__k_d + _pd__66*d_d_h__k_d + _pd__67*d_d_wp__k_d
        _x179 = _x171*m
        d_T__next = _x179*d_e_next + t_bottom
        _pd__68 = _x179
        _pd__69 = -_x173*d_e_next*m
        _x180 = 4.0*_pd__68
        d_d_T__next__q_r_td = _pd__69*d_d_h__q_r_td + _x180*d_d_e__q_r_td + d_c_T__q_r_td
        d_d_T__next__q_rd_td = _pd__69*d_d_h__q_rd_td + _x180*d_d_e__q_rd_td + d_c_T__q_rd_td
        d_d_T__next__q_th_td = _pd__69*d_d_h__q_th_td + _x180*d_d_e__q_th_td + d_c_T__q_th_td
        d_d_T__next__q_thd_td = _pd__69*d_d_h__q_thd_td + _x180*d_d_e__q_thd_td + d_c_T__q_thd_td
        d_d_T__next__k_c = _pd__69*d_d_h__k_c + _x180*d_d_e__k_c + d_c_T__k_c
        d_d_T__next__k_d = _pd__69*d_d_h__k_d + _x180*d_d_e__k_d
        _n1_4 = 4.0*d_d_e__q_r_td
        _n1_5 = 4.0*d_d_e__q_rd_td
        _n1_6 = 4.0*d_d_e__q_th_td
        _n1_7 = 4.0*d_d_e__q_thd_td
        _n1_8 = 4.0*d_d_e__k_c
        _n1_9 = 4.0*d_d_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn1 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n1_4, _n1_5, _n1_6, _n1_7, _n1_8, _n1_9,
            d_d_Q__next__q_r_td, d_d_Q__next__q_rd_td, d_d_Q__next__q_th_td, d_d_Q__next__q_thd_td,
            d_d_Q__next__k_c, d_d_Q__next__k_d, d_d_P__next__q_r_td, d_d_P__next__q_rd_td,
            d_d_P__next__q_th_td, d_d_P__next__q_thd_td, d_d_P__next__k_c, d_d_P__next__k_d,
            d_d_T__next__q_r_td, d_d_T__next__q_rd_td, d_d_T__next__q_th_td, d_d_T__next__q_thd_td,
            d_d_T__next__k_c, d_d_T__next__k_d, )
        _pk1 = _pkn1
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x181 = q_r_lo**2
    _x182 = (1.0/_x181)
    _x183 = m*q_r_lo**4
    _x184 = q_r_lo**3
    _x185 = _x181*l0**2*m
    _x186 = 2.0*g_s*m**2
    rad_lo = (_x182*(2.0*E_ba*_x181*m - _x183*k_d - _x184*_x186*math.cos(d_Q) + 2.0*_x184*k_d*l0*m - _x185*k_d
        - d_P**2))
    _pd__70 = -2.0*_x182*d_P
    _pd__71 = _x186*q_r_lo*math.sin(d_Q)
    _x187 = 2.0*m
    d_rad_lo__q_r_td = _pd__70*d_d_P__q_r_td + _pd__71*d_d_Q__q_r_td + _x187*d_E_ba__q_r_td
    d_rad_lo__q_rd_td = _pd__70*d_d_P__q_rd_td + _pd__71*d_d_Q__q_rd_td + _x187*d_E_ba__q_rd_td
    d_rad_lo__q_th_td = _pd__70*d_d_P__q_th_td + _pd__71*d_d_Q__q_th_td + _x187*d_E_ba__q_th_td
    d_rad_lo__q_thd_td = _pd__70*d_d_P__q_thd_td + _pd__71*d_d_Q__q_thd_td + _x187*d_E_ba__q_thd_td
    d_rad_lo__k_c = _pd__70*d_d_P__k_c + _pd__71*d_d_Q__k_c + _x187*d_E_ba__k_c
    d_rad_lo__k_d = (_pd__70*d_d_P__k_d + _pd__71*d_d_Q__k_d + _x182*(-_x183 + 2.0*_x184*l0*m - _x185)
        + _x187*d_E_ba__k_d)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x188 = (1.0/m)
    _x189 = math.sqrt(rad_lo)
    liftoff_q_rd = _x188*_x189
    _pd__72 = (0.5)*_x188/_x189
    d_liftoff_q_rd__q_r_td = _pd__72*d_rad_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _pd__72*d_rad_lo__q_rd_td
    d_liftoff_q_rd__q_th_td = _pd__72*d_rad_lo__q_th_td
    d_liftoff_q_rd__q_thd_td = _pd__72*d_rad_lo__q_thd_td
    d_liftoff_q_rd__k_c = _pd__72*d_rad_lo__k_c
    d_liftoff_q_rd__k_d = _pd__72*d_rad_lo__k_d
    liftoff_q_th = d_Q
    _x190 = _x188/q_r_lo**2
    liftoff_q_thd = _x190*d_P
    _pd__73 = _x190
    d_liftoff_q_thd__q_r_td = _pd__73*d_d_P__q_r_td
    d_liftoff_q_thd__q_rd_td = _pd__73*d_d_P__q_rd_td
    d_liftoff_q_thd__q_th_td = _pd__73*d_d_P__q_th_td
    d_liftoff_q_thd__q_thd_td = _pd__73*d_d_P__q_thd_td
    d_liftoff_q_thd__k_c = _pd__73*d_d_P__k_c
    d_liftoff_q_thd__k_d = _pd__73*d_d_P__k_d
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN70 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_c_T__q_r_td
    d_t_bottom__q_rd_td = d_c_T__q_rd_td
    d_t_bottom__q_th_td = d_c_T__q_th_td
    d_t_bottom__q_thd_td = d_c_T__q_thd_td
    d_t_bottom__k_c = d_c_T__k_c
    d_t_bottom__k_d = 0.0
    d_t_stance__q_r_td = d_d_T__q_r_td
    d_t_stance__q_rd_td = d_d_T__q_rd_td
    d_t_stance__q_th_td = d_d_T__q_th_td
    d_t_stance__q_thd_td = d_d_T__q_thd_td
    d_t_stance__k_c = d_d_T__k_c
    d_t_stance__k_d = d_d_T__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__q_r_td = d_c_Q__q_r_td
    d_bottom_q_th__q_rd_td = d_c_Q__q_rd_td
    d_bottom_q_th__q_th_td = d_c_Q__q_th_td
    d_bottom_q_th__q_thd_td = d_c_Q__q_thd_td
    d_bottom_q_th__k_c = d_c_Q__k_c
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_th__q_r_td = d_d_Q__q_r_td
    d_liftoff_q_th__q_rd_td = d_d_Q__q_rd_td
    d_liftoff_q_th__q_th_td = d_d_Q__q_th_td
    d_liftoff_q_th__q_thd_td = d_d_Q__q_thd_td
    d_liftoff_q_th__k_c = d_d_Q__k_c
    d_liftoff_q_th__k_d = d_d_Q__k_d
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
def iterative_report_stance_jacobian_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian_zeroth_gravity_type2`: arguments, out
    and status as :func:`iterative_report_stance_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_jacobian_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
            and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f
            > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_jacobian_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # the code shared between choices
    return (iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type2`: arguments,
    out and status as :func:`iterative_report_apex_return_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_jacobian_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations,
            bottom_length))
        store_row_12_84(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1522
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN70 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN70 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # E_ab (114) of the touchdown state
    _x0 = k_c*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*l0 + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__q_r_td = _x0 + _x5 + _x6*q_r_td - k_c*l0
    d_E_ab__q_rd_td = m*q_rd_td
    d_E_ab__q_th_td = -_x4*q_r_td*math.sin(q_th_td)
    d_E_ab__q_thd_td = _x2*m*q_thd_td
    d_E_ab__k_c = _x1 + _x3 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_bottom_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_bottom_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_bottom_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_bottom_q_r__k_c = _j_z_b_q_r__k
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic_jac_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[4] != STATUS_OK:
            return _NAN70 + (_c1[4],)
        bottom_q_r = _c1[0]
        _j_bottom_q_r__p = _c1[1]
        _j_bottom_q_r__E_ab = _c1[2]
        _j_bottom_q_r__k_c = _c1[3]
        # chain rule through bottom_quartic
        _x7 = _j_bottom_q_r__p*m
        d_bottom_q_r__q_r_td = _j_bottom_q_r__E_ab*d_E_ab__q_r_td + 2.0*_x7*q_r_td*q_thd_td
        d_bottom_q_r__q_rd_td = _j_bottom_q_r__E_ab*d_E_ab__q_rd_td
        d_bottom_q_r__q_th_td = _j_bottom_q_r__E_ab*d_E_ab__q_th_td
        d_bottom_q_r__q_thd_td = _j_bottom_q_r__E_ab*d_E_ab__q_thd_td + _x7*q_r_td**2
        d_bottom_q_r__k_c = _j_bottom_q_r__E_ab*d_E_ab__k_c + _j_bottom_q_r__k_c
    else:
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN70 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = bottom_q_r - q_r_td
    _x10 = _x8*_x9
    c_e_n = _x10
    _pd__0 = _x8
    _x11 = -_x8
    d_c_e_n__q_r_td = _pd__0*d_bottom_q_r__q_r_td + _x11
    d_c_e_n__q_rd_td = _pd__0*d_bottom_q_r__q_rd_td
    d_c_e_n__q_th_td = _pd__0*d_bottom_q_r__q_th_td
    d_c_e_n__q_thd_td = _pd__0*d_bottom_q_r__q_thd_td
    d_c_e_n__k_c = _pd__0*d_bottom_q_r__k_c
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
    d_c_rad_z__q_r_td = (_j_z_b_q_r__q_r_td*_pd__3 + _j_z_b_q_th__q_r_td*_pd__4 + _j_z_b_q_thd__q_r_td*_pd__5
        + _pd__1*d_bottom_q_r__q_r_td + _x15*(-_x27*(-_x23*_x41 + _x24*_x46*q_r_td*q_thd_td) - _x39 - _x47)
        + _x42 + _x51*d_c_e_n__q_r_td + _x52*d_E_ab__q_r_td)
    d_c_rad_z__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__3 + _j_z_b_q_th__q_rd_td*_pd__4
        + _j_z_b_q_thd__q_rd_td*_pd__5 + _pd__1*d_bottom_q_r__q_rd_td + _x51*d_c_e_n__q_rd_td
        + _x52*d_E_ab__q_rd_td)
    d_c_rad_z__q_th_td = (_j_z_b_q_r__q_th_td*_pd__3 + _j_z_b_q_th__q_th_td*_pd__4
        + _j_z_b_q_thd__q_th_td*_pd__5 + _pd__1*d_bottom_q_r__q_th_td + _x24*_x50 + _x51*d_c_e_n__q_th_td
        + _x52*d_E_ab__q_th_td)
    d_c_rad_z__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__3 + _j_z_b_q_th__q_thd_td*_pd__4
        + _j_z_b_q_thd__q_thd_td*_pd__5 + _pd__1*d_bottom_q_r__q_thd_td - 2.0*_x24*_x25*_x49
        + _x51*d_c_e_n__q_thd_td + _x52*d_E_ab__q_thd_td)
    d_c_rad_z__k_c = (_j_z_b_q_r__k*_pd__3 + _j_z_b_q_th__k*_pd__4 + _j_z_b_q_thd__k*_pd__5
        + _pd__1*d_bottom_q_r__k_c + _x15*(-_x16 + 2.0*_x17*l0*m - _x19) + _x51*d_c_e_n__k_c
        + _x52*d_E_ab__k_c)
    _x53 = math.sqrt(_x11 + 1.0)
    c_Q0 = _x29*_x53 + z_b_q_th
    _x54 = (0.5)/_x53
    _x55 = _x36*_x54
    _x56 = _x55*_x8
    _pd__6 = _x56
    _pd__7 = -_x55
    _pd__8 = 1.0 - _x53
    d_c_Q0__q_r_td = _j_z_b_q_th__q_r_td*_pd__8 + _pd__6*d_bottom_q_r__q_r_td + _pd__7*d_c_e_n__q_r_td - _x56
    d_c_Q0__q_rd_td = _j_z_b_q_th__q_rd_td*_pd__8 + _pd__6*d_bottom_q_r__q_rd_td + _pd__7*d_c_e_n__q_rd_td
    d_c_Q0__q_th_td = (_j_z_b_q_th__q_th_td*_pd__8 + _pd__6*d_bottom_q_r__q_th_td + _pd__7*d_c_e_n__q_th_td
        + _x53)
    d_c_Q0__q_thd_td = _j_z_b_q_th__q_thd_td*_pd__8 + _pd__6*d_bottom_q_r__q_thd_td + _pd__7*d_c_e_n__q_thd_td
    d_c_Q0__k_c = _j_z_b_q_th__k*_pd__8 + _pd__6*d_bottom_q_r__k_c + _pd__7*d_c_e_n__k_c
    c_P0 = _x22 + _x26*_x53
    _x57 = _x40*_x54
    _x58 = _x57*_x8
    _pd__9 = _x58
    _pd__10 = -_x57
    _pd__11 = -_x48*_x52*_x53 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__12 = _x20*m - _x21*_x53
    d_c_P0__q_r_td = (_j_z_b_q_r__q_r_td*_pd__11 + _j_z_b_q_thd__q_r_td*_pd__12 + _pd__10*d_c_e_n__q_r_td
        + _pd__9*d_bottom_q_r__q_r_td + _x43*_x53*m*q_thd_td - _x58)
    d_c_P0__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__11 + _j_z_b_q_thd__q_rd_td*_pd__12 + _pd__10*d_c_e_n__q_rd_td
        + _pd__9*d_bottom_q_r__q_rd_td)
    d_c_P0__q_th_td = (_j_z_b_q_r__q_th_td*_pd__11 + _j_z_b_q_thd__q_th_td*_pd__12 + _pd__10*d_c_e_n__q_th_td
        + _pd__9*d_bottom_q_r__q_th_td)
    d_c_P0__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__11 + _j_z_b_q_thd__q_thd_td*_pd__12
        + _pd__10*d_c_e_n__q_thd_td + _pd__9*d_bottom_q_r__q_thd_td + _x25*_x53)
    d_c_P0__k_c = (_j_z_b_q_r__k*_pd__11 + _j_z_b_q_thd__k*_pd__12 + _pd__10*d_c_e_n__k_c
        + _pd__9*d_bottom_q_r__k_c)
    _x59 = m/math.sqrt(_x33)
    _x60 = (_x33 > 0.0)
    c_T0 = ((-_x10*_x59) if _x60 else (0.0))
    _pd__13 = ((-_x59) if _x60 else (0.0))
    _pd__14 = ((_x44*m/(_x33*math.sqrt(_x33))) if _x60 else (0.0))
    d_c_T0__q_r_td = _pd__13*d_c_e_n__q_r_td + _pd__14*d_c_rad_z__q_r_td
    d_c_T0__q_rd_td = _pd__13*d_c_e_n__q_rd_td + _pd__14*d_c_rad_z__q_rd_td
    d_c_T0__q_th_td = _pd__13*d_c_e_n__q_th_td + _pd__14*d_c_rad_z__q_th_td
    d_c_T0__q_thd_td = _pd__13*d_c_e_n__q_thd_td + _pd__14*d_c_rad_z__q_thd_td
    d_c_T0__k_c = _pd__13*d_c_e_n__k_c + _pd__14*d_c_rad_z__k_c
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__q_r_td, d_c_e_n__q_rd_td, d_c_e_n__q_th_td, d_c_e_n__q_thd_td,
        d_c_e_n__k_c, d_c_Q0__q_r_td, d_c_Q0__q_rd_td, d_c_Q0__q_th_td, d_c_Q0__q_thd_td, d_c_Q0__k_c,
        d_c_P0__q_r_td, d_c_P0__q_rd_td, d_c_P0__q_th_td, d_c_P0__q_thd_td, d_c_P0__k_c, d_c_T0__q_r_td,
        d_c_T0__q_rd_td, d_c_T0__q_th_td, d_c_T0__q_thd_td, d_c_T0__k_c, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__q_r_td, d_c_e__q_rd_td, d_c_e__q_th_td, d_c_e__q_thd_td, d_c_e__k_c,
            d_c_Q__q_r_td, d_c_Q__q_rd_td, d_c_Q__q_th_td, d_c_Q__q_thd_td, d_c_Q__k_c, d_c_P__q_r_td,
            d_c_P__q_rd_td, d_c_P__q_th_td, d_c_P__q_thd_td, d_c_P__k_c, d_c_T__q_r_td, d_c_T__q_rd_td,
            d_c_T__q_th_td, d_c_T__q_thd_td, d_c_T__k_c, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x61 = c_e + q_r_td
        c_x = _x61
        d_c_x__q_r_td = d_c_e__q_r_td + 1.0
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
        d_c_rad__q_r_td = (_pd__15*d_c_P__q_r_td + _pd__16*d_c_Q__q_r_td + _pd__17*d_c_x__q_r_td
            + _x72*d_E_ab__q_r_td)
        d_c_rad__q_rd_td = (_pd__15*d_c_P__q_rd_td + _pd__16*d_c_Q__q_rd_td + _pd__17*d_c_e__q_rd_td
            + _x72*d_E_ab__q_rd_td)
        d_c_rad__q_th_td = (_pd__15*d_c_P__q_th_td + _pd__16*d_c_Q__q_th_td + _pd__17*d_c_e__q_th_td
            + _x72*d_E_ab__q_th_td)
        d_c_rad__q_thd_td = (_pd__15*d_c_P__q_thd_td + _pd__16*d_c_Q__q_thd_td + _pd__17*d_c_e__q_thd_td
            + _x72*d_E_ab__q_thd_td)
        d_c_rad__k_c = (_pd__15*d_c_P__k_c + _pd__16*d_c_Q__k_c + _pd__17*d_c_e__k_c + _x63*(-_x64
            + 2.0*_x65*l0*m - _x67) + _x72*d_E_ab__k_c)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x73 = math.sqrt(c_rad)
        c_h = _x73
        _pd__18 = (0.5)/_x73
        d_c_h__q_r_td = _pd__18*d_c_rad__q_r_td
        d_c_h__q_rd_td = _pd__18*d_c_rad__q_rd_td
        d_c_h__q_th_td = _pd__18*d_c_rad__q_th_td
        d_c_h__q_thd_td = _pd__18*d_c_rad__q_thd_td
        d_c_h__k_c = _pd__18*d_c_rad__k_c
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x77 = (1.0/c_x)
            _x74 = _x77**2
            c_wq = _x74*c_e_next
            _pd__19 = _x74
            _pd__20 = -2.0*_x77**3*c_e_next
            _x75 = 4.0*_pd__19
            d_c_wq__q_r_td = _pd__20*d_c_x__q_r_td + _x75*d_c_e__q_r_td
            d_c_wq__q_rd_td = _pd__20*d_c_e__q_rd_td + _x75*d_c_e__q_rd_td
            d_c_wq__q_th_td = _pd__20*d_c_e__q_th_td + _x75*d_c_e__q_th_td
            d_c_wq__q_thd_td = _pd__20*d_c_e__q_thd_td + _x75*d_c_e__q_thd_td
            d_c_wq__k_c = _pd__20*d_c_e__k_c + _x75*d_c_e__k_c
            c_wp = c_e_next*c_x
            _x76 = 4.0*c_x
            d_c_wp__q_r_td = _x76*d_c_e__q_r_td + c_e_next*d_c_x__q_r_td
            d_c_wp__q_rd_td = _x76*d_c_e__q_rd_td + c_e_next*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x76*d_c_e__q_th_td + c_e_next*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x76*d_c_e__q_thd_td + c_e_next*d_c_e__q_thd_td
            d_c_wp__k_c = _x76*d_c_e__k_c + c_e_next*d_c_e__k_c
        elif variant == 1.0:
            _x78 = (1.0/q_r_td)
            _x79 = c_e_next + q_r_td
            _x80 = (1.0/_x79)
            c_wq = _x78*_x80*c_e_next
            _x81 = _x78*_x80**2*c_e_next
            _pd__21 = _x78*_x80 - _x81
            d_c_wq__q_r_td = 4.0*_pd__21*d_c_e__q_r_td - _x78**2*_x80*c_e_next - _x81
            _x82 = 4.0*_pd__21
            d_c_wq__q_rd_td = _x82*d_c_e__q_rd_td
            d_c_wq__q_th_td = _x82*d_c_e__q_th_td
            d_c_wq__q_thd_td = _x82*d_c_e__q_thd_td
            d_c_wq__k_c = _x82*d_c_e__k_c
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__22 = _x79
            _x83 = 4.0*_pd__22
            d_c_wp__q_r_td = _x83*d_c_e__q_r_td + c_e_next
            d_c_wp__q_rd_td = _x83*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x83*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x83*d_c_e__q_thd_td
            d_c_wp__k_c = _x83*d_c_e__k_c
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        c_e__next = c_e_next
        _x84 = (1.0/c_h)
        _x85 = _x84*c_wq
        c_Q__next = -_x85*c_P + q_th_td
        _pd__23 = -_x85
        _x86 = _x84**2
        _pd__24 = _x86*c_P*c_wq
        _pd__25 = -_x84*c_P
        d_c_Q__next__q_r_td = _pd__23*d_c_P__q_r_td + _pd__24*d_c_h__q_r_td + _pd__25*d_c_wq__q_r_td
        d_c_Q__next__q_rd_td = _pd__23*d_c_P__q_rd_td + _pd__24*d_c_h__q_rd_td + _pd__25*d_c_wq__q_rd_td
        d_c_Q__next__q_th_td = _pd__23*d_c_P__q_th_td + _pd__24*d_c_h__q_th_td + _pd__25*d_c_wq__q_th_td + 1.0
        d_c_Q__next__q_thd_td = _pd__23*d_c_P__q_thd_td + _pd__24*d_c_h__q_thd_td + _pd__25*d_c_wq__q_thd_td
        d_c_Q__next__k_c = _pd__23*d_c_P__k_c + _pd__24*d_c_h__k_c + _pd__25*d_c_wq__k_c
        _x87 = m*q_r_td**2
        _x88 = math.sin(c_Q)
        _x89 = m**2
        _x90 = _x84*_x89*g_s
        _x91 = _x88*_x90
        c_P__next = _x87*q_thd_td - _x91*c_wp
        _pd__26 = -_x90*c_wp*math.cos(c_Q)
        _pd__27 = _x86*_x88*_x89*c_wp*g_s
        _pd__28 = -_x91
        d_c_P__next__q_r_td = (_pd__26*d_c_Q__q_r_td + _pd__27*d_c_h__q_r_td + _pd__28*d_c_wp__q_r_td
            + 2.0*m*q_r_td*q_thd_td)
        d_c_P__next__q_rd_td = _pd__26*d_c_Q__q_rd_td + _pd__27*d_c_h__q_rd_td + _pd__28*d_c_wp__q_rd_td
        d_c_P__next__q_th_td = _pd__26*d_c_Q__q_th_td + _pd__27*d_c_h__q_th_td + _pd__28*d_c_wp__q_th_td
        d_c_P__next__q_thd_td = (_pd__26*d_c_Q__q_thd_td + _pd__27*d_c_h__q_thd_td + _pd__28*d_c_wp__q_thd_td
            + _x87)
        d_c_P__next__k_c = _pd__26*d_c_Q__k_c + _pd__27*d_c_h__k_c + _pd__28*d_c_wp__k_c
        _x92 = _x84*m
        c_T__next = -_x92*c_e_next
        _pd__29 = -_x92
        _pd__30 = _x86*c_e_next*m
        _x93 = 4.0*_pd__29
        d_c_T__next__q_r_td = _pd__30*d_c_h__q_r_td + _x93*d_c_e__q_r_td
        d_c_T__next__q_rd_td = _pd__30*d_c_h__q_rd_td + _x93*d_c_e__q_rd_td
        d_c_T__next__q_th_td = _pd__30*d_c_h__q_th_td + _x93*d_c_e__q_th_td
        d_c_T__next__q_thd_td = _pd__30*d_c_h__q_thd_td + _x93*d_c_e__q_thd_td
        d_c_T__next__k_c = _pd__30*d_c_h__k_c + _x93*d_c_e__k_c
        _n0_4 = 4.0*d_c_e__q_r_td
        _n0_5 = 4.0*d_c_e__q_rd_td
        _n0_6 = 4.0*d_c_e__q_th_td
        _n0_7 = 4.0*d_c_e__q_thd_td
        _n0_8 = 4.0*d_c_e__k_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8,
            d_c_Q__next__q_r_td, d_c_Q__next__q_rd_td, d_c_Q__next__q_th_td, d_c_Q__next__q_thd_td,
            d_c_Q__next__k_c, d_c_P__next__q_r_td, d_c_P__next__q_rd_td, d_c_P__next__q_th_td,
            d_c_P__next__q_thd_td, d_c_P__next__k_c, d_c_T__next__q_r_td, d_c_T__next__q_rd_td,
            d_c_T__next__q_th_td, d_c_T__next__q_thd_td, d_c_T__next__k_c, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    _x94 = (1.0/m)
    _x96 = (1.0/bottom_q_r)
    _x95 = _x94*_x96**2
    bottom_q_thd = _x95*c_P
    _pd__31 = -2.0*_x94*_x96**3*c_P
    _pd__32 = _x95
    d_bottom_q_thd__q_r_td = _pd__31*d_bottom_q_r__q_r_td + _pd__32*d_c_P__q_r_td
    d_bottom_q_thd__q_rd_td = _pd__31*d_bottom_q_r__q_rd_td + _pd__32*d_c_P__q_rd_td
    d_bottom_q_thd__q_th_td = _pd__31*d_bottom_q_r__q_th_td + _pd__32*d_c_P__q_th_td
    d_bottom_q_thd__q_thd_td = _pd__31*d_bottom_q_r__q_thd_td + _pd__32*d_c_P__q_thd_td
    d_bottom_q_thd__k_c = _pd__31*d_bottom_q_r__k_c + _pd__32*d_c_P__k_c
    # E_ba of (98): the energy jump of the stiffness switch
    _x97 = (-bottom_q_r + l0)**2
    _x98 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x97*_x98
    _pd__33 = _x98*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__q_r_td = _pd__33*d_bottom_q_r__q_r_td + d_E_ab__q_r_td
    d_E_ba__q_rd_td = _pd__33*d_bottom_q_r__q_rd_td + d_E_ab__q_rd_td
    d_E_ba__q_th_td = _pd__33*d_bottom_q_r__q_th_td + d_E_ab__q_th_td
    d_E_ba__q_thd_td = _pd__33*d_bottom_q_r__q_thd_td + d_E_ab__q_thd_td
    _x99 = (0.5)*_x97
    d_E_ba__k_c = _pd__33*d_bottom_q_r__k_c - _x99 + d_E_ab__k_c
    d_E_ba__k_d = _x99
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN70 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x100 = 4.0**(-iterations)
    _x101 = -bottom_q_r + q_r_lo
    _x102 = _x100*_x101
    d_e_n = _x102
    _pd__34 = -_x100
    d_d_e_n__q_r_td = _pd__34*d_bottom_q_r__q_r_td
    d_d_e_n__q_rd_td = _pd__34*d_bottom_q_r__q_rd_td
    d_d_e_n__q_th_td = _pd__34*d_bottom_q_r__q_th_td
    d_d_e_n__q_thd_td = _pd__34*d_bottom_q_r__q_thd_td
    d_d_e_n__k_c = _pd__34*d_bottom_q_r__k_c
    _x103 = (0.25)*_x102
    d_e_z = _x103
    _x104 = _x103 + bottom_q_r
    _x105 = _x104**2
    _x106 = (1.0/_x105)
    _x107 = _x104**4*m
    _x108 = _x104**3
    _x109 = l0**2*m
    _x110 = _x105*_x109
    _x111 = bottom_q_r**2*m
    _x112 = _x111*bottom_q_thd
    _x113 = q_r_lo**2
    _x114 = -_x112 + _x113*g_lo_q_thd*m
    _x115 = 4.0**((0.5)*iterations)
    _x116 = (1.0/_x115)
    _x117 = (0.5)*_x116
    _x118 = _x114*_x117
    _x119 = _x112 + _x118
    _x120 = -bottom_q_th + g_lo_q_th
    _x121 = _x117*_x120
    _x122 = _x121 + bottom_q_th
    _x123 = m**2
    _x124 = _x123*g_s
    _x125 = _x124*math.cos(_x122)
    _x126 = 2.0*E_ba*_x105*m - _x107*k_d - 2.0*_x108*_x125 + 2.0*_x108*k_d*l0*m - _x110*k_d - _x119**2
    _x127 = _x106*_x126
    d_rad_z = _x127
    _x128 = -2.0*_x126/_x108
    _x129 = 4.0*m
    _x130 = (1.0/_x101)
    _x131 = 2.0*bottom_q_r
    _x132 = _x131*bottom_q_thd*m
    _x133 = -_x116*_x132 + _x118*_x130
    _x134 = math.sin(_x122)
    _x135 = (0.5)*_x102
    _x136 = _x131 + _x135
    _x137 = -2.0*E_ba*_x136*m + 6.0*_x105*_x125 - 6.0*_x105*k_d*l0*m + _x108*_x129*k_d + _x109*_x136*k_d
    _pd__35 = (_x106*((0.5)*_x108*_x116*_x120*_x123*_x130*_x134*g_s - _x119*(_x129*bottom_q_r*bottom_q_thd
        + _x133) - _x137) + _x128)
    _x138 = _x104*_x124*_x134
    _pd__36 = 2.0*_x138*(1.0 - _x117)
    _x139 = -_x111*_x116
    _x140 = _x106*_x119
    _pd__37 = -_x140*(2.0*_x111 + _x139)
    _x141 = _x115*_x130
    _pd__38 = _x106*(2.0*_x108*_x115*_x120*_x123*_x130*_x134*g_s - 2.0*_x114*_x119*_x141 - _x137) + _x128
    _pd__39 = _x116*_x138
    _x142 = _x113*_x116*m
    _pd__40 = -_x140*_x142
    _x143 = (0.25)*_pd__38
    _x144 = 2.0*m
    d_d_rad_z__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__39 + _j_z_lo_q_thd__q_r_td*_pd__40
        + _pd__35*d_bottom_q_r__q_r_td + _pd__36*d_c_Q__q_r_td + _pd__37*d_bottom_q_thd__q_r_td
        + _x143*d_d_e_n__q_r_td + _x144*d_E_ba__q_r_td)
    d_d_rad_z__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__39 + _j_z_lo_q_thd__q_rd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_rd_td + _pd__36*d_c_Q__q_rd_td + _pd__37*d_bottom_q_thd__q_rd_td
        + _x143*d_d_e_n__q_rd_td + _x144*d_E_ba__q_rd_td)
    d_d_rad_z__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__39 + _j_z_lo_q_thd__q_th_td*_pd__40
        + _pd__35*d_bottom_q_r__q_th_td + _pd__36*d_c_Q__q_th_td + _pd__37*d_bottom_q_thd__q_th_td
        + _x143*d_d_e_n__q_th_td + _x144*d_E_ba__q_th_td)
    d_d_rad_z__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__39 + _j_z_lo_q_thd__q_thd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_thd_td + _pd__36*d_c_Q__q_thd_td + _pd__37*d_bottom_q_thd__q_thd_td
        + _x143*d_d_e_n__q_thd_td + _x144*d_E_ba__q_thd_td)
    d_d_rad_z__k_c = (_j_z_lo_q_th__k*_pd__39 + _j_z_lo_q_thd__k*_pd__40 + _pd__35*d_bottom_q_r__k_c
        + _pd__36*d_c_Q__k_c + _pd__37*d_bottom_q_thd__k_c + _x143*d_d_e_n__k_c + _x144*d_E_ba__k_c)
    d_d_rad_z__k_d = _x106*(-_x107 + 2.0*_x108*l0*m - _x110) + _x144*d_E_ba__k_d
    d_Q0 = _x116*_x120 + bottom_q_th
    _pd__41 = _x121*_x130
    _pd__42 = 1.0 - _x116
    _x145 = (0.5)*_x141
    _pd__43 = _x120*_x145
    _pd__44 = _x116
    d_d_Q0__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__44 + _pd__41*d_bottom_q_r__q_r_td + _pd__42*d_c_Q__q_r_td
        + _pd__43*d_d_e_n__q_r_td)
    d_d_Q0__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__44 + _pd__41*d_bottom_q_r__q_rd_td + _pd__42*d_c_Q__q_rd_td
        + _pd__43*d_d_e_n__q_rd_td)
    d_d_Q0__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__44 + _pd__41*d_bottom_q_r__q_th_td + _pd__42*d_c_Q__q_th_td
        + _pd__43*d_d_e_n__q_th_td)
    d_d_Q0__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__44 + _pd__41*d_bottom_q_r__q_thd_td
        + _pd__42*d_c_Q__q_thd_td + _pd__43*d_d_e_n__q_thd_td)
    d_d_Q0__k_c = (_j_z_lo_q_th__k*_pd__44 + _pd__41*d_bottom_q_r__k_c + _pd__42*d_c_Q__k_c
        + _pd__43*d_d_e_n__k_c)
    d_P0 = _x112 + _x114*_x116
    _pd__45 = _x132 + _x133
    _pd__46 = _x111 + _x139
    _pd__47 = _x114*_x145
    _pd__48 = _x142
    d_d_P0__q_r_td = (_j_z_lo_q_thd__q_r_td*_pd__48 + _pd__45*d_bottom_q_r__q_r_td
        + _pd__46*d_bottom_q_thd__q_r_td + _pd__47*d_d_e_n__q_r_td)
    d_d_P0__q_rd_td = (_j_z_lo_q_thd__q_rd_td*_pd__48 + _pd__45*d_bottom_q_r__q_rd_td
        + _pd__46*d_bottom_q_thd__q_rd_td + _pd__47*d_d_e_n__q_rd_td)
    d_d_P0__q_th_td = (_j_z_lo_q_thd__q_th_td*_pd__48 + _pd__45*d_bottom_q_r__q_th_td
        + _pd__46*d_bottom_q_thd__q_th_td + _pd__47*d_d_e_n__q_th_td)
    d_d_P0__q_thd_td = (_j_z_lo_q_thd__q_thd_td*_pd__48 + _pd__45*d_bottom_q_r__q_thd_td
        + _pd__46*d_bottom_q_thd__q_thd_td + _pd__47*d_d_e_n__q_thd_td)
    d_d_P0__k_c = (_j_z_lo_q_thd__k*_pd__48 + _pd__45*d_bottom_q_r__k_c + _pd__46*d_bottom_q_thd__k_c
        + _pd__47*d_d_e_n__k_c)
    _x146 = m/math.sqrt(_x127)
    _x147 = (_x127 > 0.0)
    d_T0 = ((_x102*_x146 + t_bottom) if _x147 else (t_bottom))
    _pd__49 = ((_x146) if _x147 else (0.0))
    _pd__50 = ((-_x135*m/(_x127*math.sqrt(_x127))) if _x147 else (0.0))
    d_d_T0__q_r_td = _pd__49*d_d_e_n__q_r_td + _pd__50*d_d_rad_z__q_r_td + d_c_T__q_r_td
    d_d_T0__q_rd_td = _pd__49*d_d_e_n__q_rd_td + _pd__50*d_d_rad_z__q_rd_td + d_c_T__q_rd_td
    d_d_T0__q_th_td = _pd__49*d_d_e_n__q_th_td + _pd__50*d_d_rad_z__q_th_td + d_c_T__q_th_td
    d_d_T0__q_thd_td = _pd__49*d_d_e_n__q_thd_td + _pd__50*d_d_rad_z__q_thd_td + d_c_T__q_thd_td
    d_d_T0__k_c = _pd__49*d_d_e_n__k_c + _pd__50*d_d_rad_z__k_c + d_c_T__k_c
    d_d_T0__k_d = _pd__50*d_d_rad_z__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki1 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__q_r_td, d_d_e_n__q_rd_td, d_d_e_n__q_th_td, d_d_e_n__q_thd_td,
        d_d_e_n__k_c, 0.0, d_d_Q0__q_r_td, d_d_Q0__q_rd_td, d_d_Q0__q_th_td, d_d_Q0__q_thd_td, d_d_Q0__k_c,
        0.0, d_d_P0__q_r_td, d_d_P0__q_rd_td, d_d_P0__q_th_td, d_d_P0__q_thd_td, d_d_P0__k_c, 0.0,
        d_d_T0__q_r_td, d_d_T0__q_rd_td, d_d_T0__q_th_td, d_d_T0__q_thd_td, d_d_T0__k_c, d_d_T0__k_d, )
    _pk1 = _pki1
    d_steps = 0.0
    _conv1 = False
    _last1 = max(int(iterations), 0)
    for _it1 in range(_last1 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__q_r_td, d_d_e__q_rd_td, d_d_e__q_th_td, d_d_e__q_thd_td, d_d_e__k_c,
            d_d_e__k_d, d_d_Q__q_r_td, d_d_Q__q_rd_td, d_d_Q__q_th_td, d_d_Q__q_thd_td, d_d_Q__k_c,
            d_d_Q__k_d, d_d_P__q_r_td, d_d_P__q_rd_td, d_d_P__q_th_td, d_d_P__q_thd_td, d_d_P__k_c,
            d_d_P__k_d, d_d_T__q_r_td, d_d_T__q_rd_td, d_d_T__q_th_td, d_d_T__q_thd_td, d_d_T__k_c,
            d_d_T__k_d, ) = _pk1
        if _conv1 or _it1 == _last1:
            break
        _x148 = bottom_q_r + d_e
        d_x = _x148
        d_d_x__q_r_td = d_bottom_q_r__q_r_td + d_d_e__q_r_td
        d_d_x__q_rd_td = d_bottom_q_r__q_rd_td + d_d_e__q_rd_td
        d_d_x__q_th_td = d_bottom_q_r__q_th_td + d_d_e__q_th_td
        d_d_x__q_thd_td = d_bottom_q_r__q_thd_td + d_d_e__q_thd_td
        d_d_x__k_c = d_bottom_q_r__k_c + d_d_e__k_c
        _x149 = _x148**2
        _x150 = (1.0/_x149)
        _x151 = _x148**4*m
        _x152 = _x148**3
        _x153 = l0**2
        _x154 = _x149*_x153*m
        _x155 = math.cos(d_Q)
        _x156 = m**2
        _x157 = 2.0*_x156*g_s
        _x158 = 2.0*E_ba*_x149*m - _x151*k_d - _x152*_x155*_x157 + 2.0*_x152*k_d*l0*m - _x154*k_d - d_P**2
        d_rad = _x150*_x158
        _pd__51 = -2.0*_x150*d_P
        _pd__52 = _x148*_x157*math.sin(d_Q)
        _x159 = 2.0*m
        _pd__53 = (_x150*(4.0*E_ba*_x148*m - _x148*_x153*_x159*k_d - 6.0*_x149*_x155*_x156*g_s
            + 6.0*_x149*k_d*l0*m - 4.0*_x152*k_d*m) - 2.0*_x158/_x152)
        d_d_rad__q_r_td = (_pd__51*d_d_P__q_r_td + _pd__52*d_d_Q__q_r_td + _pd__53*d_d_x__q_r_td
            + _x159*d_E_ba__q_r_td)
        d_d_rad__q_rd_td = (_pd__51*d_d_P__q_rd_td + _pd__52*d_d_Q__q_rd_td + _pd__53*d_d_x__q_rd_td
            + _x159*d_E_ba__q_rd_td)
        d_d_rad__q_th_td = (_pd__51*d_d_P__q_th_td + _pd__52*d_d_Q__q_th_td + _pd__53*d_d_x__q_th_td
            + _x159*d_E_ba__q_th_td)
        d_d_rad__q_thd_td = (_pd__51*d_d_P__q_thd_td + _pd__52*d_d_Q__q_thd_td + _pd__53*d_d_x__q_thd_td
            + _x159*d_E_ba__q_thd_td)
        d_d_rad__k_c = _pd__51*d_d_P__k_c + _pd__52*d_d_Q__k_c + _pd__53*d_d_x__k_c + _x159*d_E_ba__k_c
        d_d_rad__k_d = (_pd__51*d_d_P__k_d + _pd__52*d_d_Q__k_d + _pd__53*d_d_e__k_d + _x150*(-_x151
            + 2.0*_x152*l0*m - _x154) + _x159*d_E_ba__k_d)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x160 = math.sqrt(d_rad)
        d_h = _x160
        _pd__54 = (0.5)/_x160
        d_d_h__q_r_td = _pd__54*d_d_rad__q_r_td
        d_d_h__q_rd_td = _pd__54*d_d_rad__q_rd_td
        d_d_h__q_th_td = _pd__54*d_d_rad__q_th_td
        d_d_h__q_thd_td = _pd__54*d_d_rad__q_thd_td
        d_d_h__k_c = _pd__54*d_d_rad__k_c
        d_d_h__k_d = _pd__54*d_d_rad__k_d
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x164 = (1.0/d_x)
            _x161 = _x164**2
            d_wq = _x161*d_e_next
            _pd__55 = _x161
            _pd__56 = -2.0*_x164**3*d_e_next
            _x162 = 4.0*_pd__55
            d_d_wq__q_r_td = _pd__56*d_d_x__q_r_td + _x162*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__56*d_d_x__q_rd_td + _x162*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__56*d_d_x__q_th_td + _x162*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__56*d_d_x__q_thd_td + _x162*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__56*d_d_x__k_c + _x162*d_d_e__k_c
            d_d_wq__k_d = _pd__56*d_d_e__k_d + _x162*d_d_e__k_d
            d_wp = d_e_next*d_x
            _x163 = 4.0*d_x
            d_d_wp__q_r_td = _x163*d_d_e__q_r_td + d_d_x__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x163*d_d_e__q_rd_td + d_d_x__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x163*d_d_e__q_th_td + d_d_x__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x163*d_d_e__q_thd_td + d_d_x__q_thd_td*d_e_next
            d_d_wp__k_c = _x163*d_d_e__k_c + d_d_x__k_c*d_e_next
            d_d_wp__k_d = _x163*d_d_e__k_d + d_d_e__k_d*d_e_next
        elif variant == 1.0:
            _x165 = (1.0/bottom_q_r)
            _x166 = bottom_q_r + d_e_next
            _x167 = (1.0/_x166)
            d_wq = _x165*_x167*d_e_next
            _x168 = _x165*_x167**2*d_e_next
            _pd__57 = -_x165**2*_x167*d_e_next - _x168
            _pd__58 = _x165*_x167 - _x168
            _x169 = 4.0*_pd__58
            d_d_wq__q_r_td = _pd__57*d_bottom_q_r__q_r_td + _x169*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__57*d_bottom_q_r__q_rd_td + _x169*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__57*d_bottom_q_r__q_th_td + _x169*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__57*d_bottom_q_r__q_thd_td + _x169*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__57*d_bottom_q_r__k_c + _x169*d_d_e__k_c
            d_d_wq__k_d = _x169*d_d_e__k_d
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__59 = _x166
            _x170 = 4.0*_pd__59
            d_d_wp__q_r_td = _x170*d_d_e__q_r_td + d_bottom_q_r__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x170*d_d_e__q_rd_td + d_bottom_q_r__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x170*d_d_e__q_th_td + d_bottom_q_r__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x170*d_d_e__q_thd_td + d_bottom_q_r__q_thd_td*d_e_next
            d_d_wp__k_c = _x170*d_d_e__k_c + d_bottom_q_r__k_c*d_e_next
            d_d_wp__k_d = _x170*d_d_e__k_d
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        d_e__next = d_e_next
        _x171 = (1.0/d_h)
        _x172 = _x171*d_wq
        d_Q__next = _x172*d_P + bottom_q_th
        _pd__60 = _x172
        _x173 = _x171**2
        _pd__61 = -_x173*d_P*d_wq
        _pd__62 = _x171*d_P
        d_d_Q__next__q_r_td = (_pd__60*d_d_P__q_r_td + _pd__61*d_d_h__q_r_td + _pd__62*d_d_wq__q_r_td
            + d_c_Q__q_r_td)
        d_d_Q__next__q_rd_td = (_pd__60*d_d_P__q_rd_td + _pd__61*d_d_h__q_rd_td + _pd__62*d_d_wq__q_rd_td
            + d_c_Q__q_rd_td)
        d_d_Q__next__q_th_td = (_pd__60*d_d_P__q_th_td + _pd__61*d_d_h__q_th_td + _pd__62*d_d_wq__q_th_td
            + d_c_Q__q_th_td)
        d_d_Q__next__q_thd_td = (_pd__60*d_d_P__q_thd_td + _pd__61*d_d_h__q_thd_td + _pd__62*d_d_wq__q_thd_td
            + d_c_Q__q_thd_td)
        d_d_Q__next__k_c = _pd__60*d_d_P__k_c + _pd__61*d_d_h__k_c + _pd__62*d_d_wq__k_c + d_c_Q__k_c
        d_d_Q__next__k_d = _pd__60*d_d_P__k_d + _pd__61*d_d_h__k_d + _pd__62*d_d_wq__k_d
        _x174 = bottom_q_r**2*m
        _x175 = math.sin(d_Q)
        _x176 = m**2
        _x177 = _x171*_x176*g_s
        _x178 = _x175*_x177
        d_P__next = _x174*bottom_q_thd + _x178*d_wp
        _pd__63 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__64 = _x174
        _pd__65 = _x177*d_wp*math.cos(d_Q)
        _pd__66 = -_x173*_x175*_x176*d_wp*g_s
        _pd__67 = _x178
        d_d_P__next__q_r_td = (_pd__63*d_bottom_q_r__q_r_td + _pd__64*d_bottom_q_thd__q_r_td
            + _pd__65*d_d_Q__q_r_td + _pd__66*d_d_h__q_r_td + _pd__67*d_d_wp__q_r_td)
        d_d_P__next__q_rd_td = (_pd__63*d_bottom_q_r__q_rd_td + _pd__64*d_bottom_q_thd__q_rd_td
            + _pd__65*d_d_Q__q_rd_td + _pd__66*d_d_h__q_rd_td + _pd__67*d_d_wp__q_rd_td)
        d_d_P__next__q_th_td = (_pd__63*d_bottom_q_r__q_th_td + _pd__64*d_bottom_q_thd__q_th_td
            + _pd__65*d_d_Q__q_th_td + _pd__66*d_d_h__q_th_td + _pd__67*d_d_wp__q_th_td)
        d_d_P__next__q_thd_td = (_pd__63*d_bottom_q_r__q_thd_td + _pd__64*d_bottom_q_thd__q_thd_td
            + _pd__65*d_d_Q__q_thd_td + _pd__66*d_d_h__q_thd_td + _pd__67*d_d_wp__q_thd_td)
        d_d_P__next__k_c = (_pd__63*d_bottom_q_r__k_c + _pd__64*d_bottom_q_thd__k_c + _pd__65*d_d_Q__k_c
            + _pd__66*d_d_h__k_c + _pd__67*d_d_wp__k_c)
        d_d_P__next__k_d = _pd__65*d_d_Q__k_d + _pd__66*d_d_h__k_d + _pd__67*d_d_wp__k_d
        _x179 = _x171*m
        d_T__next = _x179*d_e_next + t_bottom
        _pd__68 = _x179
        _pd__69 = -_x173*d_e_next*m
        _x180 = 4.0*_pd__68
        d_d_T__next__q_r_td = _pd__69*d_d_h__q_r_td + _x180*d_d_e__q_r_td + d_c_T__q_r_td
        d_d_T__next__q_rd_td = _pd__69*d_d_h__q_rd_td + _x180*d_d_e__q_rd_td + d_c_T__q_rd_td
        d_d_T__next__q_th_td = _pd__69*d_d_h__q_th_td + _x180*d_d_e__q_th_td + d_c_T__q_th_td
        d_d_T__next__q_thd_td = _pd__69*d_d_h__q_thd_td + _x180*d_d_e__q_thd_td + d_c_T__q_thd_td
        d_d_T__next__k_c = _pd__69*d_d_h__k_c + _x180*d_d_e__k_c + d_c_T__k_c
        d_d_T__next__k_d = _pd__69*d_d_h__k_d + _x180*d_d_e__k_d
        _n1_4 = 4.0*d_d_e__q_r_td
        _n1_5 = 4.0*d_d_e__q_rd_td
        _n1_6 = 4.0*d_d_e__q_th_td
        _n1_7 = 4.0*d_d_e__q_thd_td
        _n1_8 = 4.0*d_d_e__k_c
        _n1_9 = 4.0*d_d_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn1 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n1_4, _n1_5, _n1_6, _n1_7, _n1_8, _n1_9,
            d_d_Q__next__q_r_td, d_d_Q__next__q_rd_td, d_d_Q__next__q_th_td, d_d_Q__next__q_thd_td,
            d_d_Q__next__k_c, d_d_Q__next__k_d, d_d_P__next__q_r_td, d_d_P__next__q_rd_td,
            d_d_P__next__q_th_td, d_d_P__next__q_thd_td, d_d_P__next__k_c, d_d_P__next__k_d,
            d_d_T__next__q_r_td, d_d_T__next__q_rd_td, d_d_T__next__q_th_td, d_d_T__next__q_thd_td,
            d_d_T__next__k_c, d_d_T__next__k_d, )
        _pk1 = _pkn1
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x181 = q_r_lo**2
    _x182 = (1.0/_x181)
    _x183 = m*q_r_lo**4
    _x184 = q_r_lo**3
    _x185 = _x181*l0**2*m
    _x186 = 2.0*g_s*m**2
    rad_lo = (_x182*(2.0*E_ba*_x181*m - _x183*k_d - _x184*_x186*math.cos(d_Q) + 2.0*_x184*k_d*l0*m - _x185*k_d
        - d_P**2))
    _pd__70 = -2.0*_x182*d_P
    _pd__71 = _x186*q_r_lo*math.sin(d_Q)
    _x187 = 2.0*m
    d_rad_lo__q_r_td = _pd__70*d_d_P__q_r_td + _pd__71*d_d_Q__q_r_td + _x187*d_E_ba__q_r_td
    d_rad_lo__q_rd_td = _pd__70*d_d_P__q_rd_td + _pd__71*d_d_Q__q_rd_td + _x187*d_E_ba__q_rd_td
    d_rad_lo__q_th_td = _pd__70*d_d_P__q_th_td + _pd__71*d_d_Q__q_th_td + _x187*d_E_ba__q_th_td
    d_rad_lo__q_thd_td = _pd__70*d_d_P__q_thd_td + _pd__71*d_d_Q__q_thd_td + _x187*d_E_ba__q_thd_td
    d_rad_lo__k_c = _pd__70*d_d_P__k_c + _pd__71*d_d_Q__k_c + _x187*d_E_ba__k_c
    d_rad_lo__k_d = (_pd__70*d_d_P__k_d + _pd__71*d_d_Q__k_d + _x182*(-_x183 + 2.0*_x184*l0*m - _x185)
        + _x187*d_E_ba__k_d)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x188 = (1.0/m)
    _x189 = math.sqrt(rad_lo)
    liftoff_q_rd = _x188*_x189
    _pd__72 = (0.5)*_x188/_x189
    d_liftoff_q_rd__q_r_td = _pd__72*d_rad_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _pd__72*d_rad_lo__q_rd_td
    d_liftoff_q_rd__q_th_td = _pd__72*d_rad_lo__q_th_td
    d_liftoff_q_rd__q_thd_td = _pd__72*d_rad_lo__q_thd_td
    d_liftoff_q_rd__k_c = _pd__72*d_rad_lo__k_c
    d_liftoff_q_rd__k_d = _pd__72*d_rad_lo__k_d
    liftoff_q_th = d_Q
    _x190 = _x188/q_r_lo**2
    liftoff_q_thd = _x190*d_P
    _pd__73 = _x190
    d_liftoff_q_thd__q_r_td = _pd__73*d_d_P__q_r_td
    d_liftoff_q_thd__q_rd_td = _pd__73*d_d_P__q_rd_td
    d_liftoff_q_thd__q_th_td = _pd__73*d_d_P__q_th_td
    d_liftoff_q_thd__q_thd_td = _pd__73*d_d_P__q_thd_td
    d_liftoff_q_thd__k_c = _pd__73*d_d_P__k_c
    d_liftoff_q_thd__k_d = _pd__73*d_d_P__k_d
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN70 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_c_T__q_r_td
    d_t_bottom__q_rd_td = d_c_T__q_rd_td
    d_t_bottom__q_th_td = d_c_T__q_th_td
    d_t_bottom__q_thd_td = d_c_T__q_thd_td
    d_t_bottom__k_c = d_c_T__k_c
    d_t_bottom__k_d = 0.0
    d_t_stance__q_r_td = d_d_T__q_r_td
    d_t_stance__q_rd_td = d_d_T__q_rd_td
    d_t_stance__q_th_td = d_d_T__q_th_td
    d_t_stance__q_thd_td = d_d_T__q_thd_td
    d_t_stance__k_c = d_d_T__k_c
    d_t_stance__k_d = d_d_T__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__q_r_td = d_c_Q__q_r_td
    d_bottom_q_th__q_rd_td = d_c_Q__q_rd_td
    d_bottom_q_th__q_th_td = d_c_Q__q_th_td
    d_bottom_q_th__q_thd_td = d_c_Q__q_thd_td
    d_bottom_q_th__k_c = d_c_Q__k_c
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_th__q_r_td = d_d_Q__q_r_td
    d_liftoff_q_th__q_rd_td = d_d_Q__q_rd_td
    d_liftoff_q_th__q_th_td = d_d_Q__q_th_td
    d_liftoff_q_th__q_thd_td = d_d_Q__q_thd_td
    d_liftoff_q_th__k_c = d_d_Q__k_c
    d_liftoff_q_th__k_d = d_d_Q__k_d
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
def iterative_report_stance_jacobian_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian_zeroth_gravity_type3`: arguments, out
    and status as :func:`iterative_report_stance_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_jacobian_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
            and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f
            > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_jacobian_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # the code shared between choices
    return (iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type3`: arguments,
    out and status as :func:`iterative_report_apex_return_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_jacobian_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations,
            bottom_length))
        store_row_12_84(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1522
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN70 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0,
        1.0, 0.0, 100.0, 1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN70 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # E_ab (114) of the touchdown state
    _x0 = k_c*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*l0 + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__q_r_td = _x0 + _x5 + _x6*q_r_td - k_c*l0
    d_E_ab__q_rd_td = m*q_rd_td
    d_E_ab__q_th_td = -_x4*q_r_td*math.sin(q_th_td)
    d_E_ab__q_thd_td = _x2*m*q_thd_td
    d_E_ab__k_c = _x1 + _x3 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_bottom_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_bottom_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_bottom_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_bottom_q_r__k_c = _j_z_b_q_r__k
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic_jac_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[4] != STATUS_OK:
            return _NAN70 + (_c1[4],)
        bottom_q_r = _c1[0]
        _j_bottom_q_r__p = _c1[1]
        _j_bottom_q_r__E_ab = _c1[2]
        _j_bottom_q_r__k_c = _c1[3]
        # chain rule through bottom_quartic
        _x7 = _j_bottom_q_r__p*m
        d_bottom_q_r__q_r_td = _j_bottom_q_r__E_ab*d_E_ab__q_r_td + 2.0*_x7*q_r_td*q_thd_td
        d_bottom_q_r__q_rd_td = _j_bottom_q_r__E_ab*d_E_ab__q_rd_td
        d_bottom_q_r__q_th_td = _j_bottom_q_r__E_ab*d_E_ab__q_th_td
        d_bottom_q_r__q_thd_td = _j_bottom_q_r__E_ab*d_E_ab__q_thd_td + _x7*q_r_td**2
        d_bottom_q_r__k_c = _j_bottom_q_r__E_ab*d_E_ab__k_c + _j_bottom_q_r__k_c
    else:
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN70 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = bottom_q_r - q_r_td
    _x10 = _x8*_x9
    c_e_n = _x10
    _pd__0 = _x8
    _x11 = -_x8
    d_c_e_n__q_r_td = _pd__0*d_bottom_q_r__q_r_td + _x11
    d_c_e_n__q_rd_td = _pd__0*d_bottom_q_r__q_rd_td
    d_c_e_n__q_th_td = _pd__0*d_bottom_q_r__q_th_td
    d_c_e_n__q_thd_td = _pd__0*d_bottom_q_r__q_thd_td
    d_c_e_n__k_c = _pd__0*d_bottom_q_r__k_c
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
    d_c_rad_z__q_r_td = (_j_z_b_q_r__q_r_td*_pd__3 + _j_z_b_q_th__q_r_td*_pd__4 + _j_z_b_q_thd__q_r_td*_pd__5
        + _pd__1*d_bottom_q_r__q_r_td + _x15*(-_x27*(-_x23*_x41 + _x24*_x46*q_r_td*q_thd_td) - _x39 - _x47)
        + _x42 + _x51*d_c_e_n__q_r_td + _x52*d_E_ab__q_r_td)
    d_c_rad_z__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__3 + _j_z_b_q_th__q_rd_td*_pd__4
        + _j_z_b_q_thd__q_rd_td*_pd__5 + _pd__1*d_bottom_q_r__q_rd_td + _x51*d_c_e_n__q_rd_td
        + _x52*d_E_ab__q_rd_td)
    d_c_rad_z__q_th_td = (_j_z_b_q_r__q_th_td*_pd__3 + _j_z_b_q_th__q_th_td*_pd__4
        + _j_z_b_q_thd__q_th_td*_pd__5 + _pd__1*d_bottom_q_r__q_th_td + _x24*_x50 + _x51*d_c_e_n__q_th_td
        + _x52*d_E_ab__q_th_td)
    d_c_rad_z__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__3 + _j_z_b_q_th__q_thd_td*_pd__4
        + _j_z_b_q_thd__q_thd_td*_pd__5 + _pd__1*d_bottom_q_r__q_thd_td - 2.0*_x24*_x25*_x49
        + _x51*d_c_e_n__q_thd_td + _x52*d_E_ab__q_thd_td)
    d_c_rad_z__k_c = (_j_z_b_q_r__k*_pd__3 + _j_z_b_q_th__k*_pd__4 + _j_z_b_q_thd__k*_pd__5
        + _pd__1*d_bottom_q_r__k_c + _x15*(-_x16 + 2.0*_x17*l0*m - _x19) + _x51*d_c_e_n__k_c
        + _x52*d_E_ab__k_c)
    _x53 = math.sqrt(_x11 + 1.0)
    c_Q0 = _x29*_x53 + z_b_q_th
    _x54 = (0.5)/_x53
    _x55 = _x36*_x54
    _x56 = _x55*_x8
    _pd__6 = _x56
    _pd__7 = -_x55
    _pd__8 = 1.0 - _x53
    d_c_Q0__q_r_td = _j_z_b_q_th__q_r_td*_pd__8 + _pd__6*d_bottom_q_r__q_r_td + _pd__7*d_c_e_n__q_r_td - _x56
    d_c_Q0__q_rd_td = _j_z_b_q_th__q_rd_td*_pd__8 + _pd__6*d_bottom_q_r__q_rd_td + _pd__7*d_c_e_n__q_rd_td
    d_c_Q0__q_th_td = (_j_z_b_q_th__q_th_td*_pd__8 + _pd__6*d_bottom_q_r__q_th_td + _pd__7*d_c_e_n__q_th_td
        + _x53)
    d_c_Q0__q_thd_td = _j_z_b_q_th__q_thd_td*_pd__8 + _pd__6*d_bottom_q_r__q_thd_td + _pd__7*d_c_e_n__q_thd_td
    d_c_Q0__k_c = _j_z_b_q_th__k*_pd__8 + _pd__6*d_bottom_q_r__k_c + _pd__7*d_c_e_n__k_c
    c_P0 = _x22 + _x26*_x53
    _x57 = _x40*_x54
    _x58 = _x57*_x8
    _pd__9 = _x58
    _pd__10 = -_x57
    _pd__11 = -_x48*_x52*_x53 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__12 = _x20*m - _x21*_x53
    d_c_P0__q_r_td = (_j_z_b_q_r__q_r_td*_pd__11 + _j_z_b_q_thd__q_r_td*_pd__12 + _pd__10*d_c_e_n__q_r_td
        + _pd__9*d_bottom_q_r__q_r_td + _x43*_x53*m*q_thd_td - _x58)
    d_c_P0__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__11 + _j_z_b_q_thd__q_rd_td*_pd__12 + _pd__10*d_c_e_n__q_rd_td
        + _pd__9*d_bottom_q_r__q_rd_td)
    d_c_P0__q_th_td = (_j_z_b_q_r__q_th_td*_pd__11 + _j_z_b_q_thd__q_th_td*_pd__12 + _pd__10*d_c_e_n__q_th_td
        + _pd__9*d_bottom_q_r__q_th_td)
    d_c_P0__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__11 + _j_z_b_q_thd__q_thd_td*_pd__12
        + _pd__10*d_c_e_n__q_thd_td + _pd__9*d_bottom_q_r__q_thd_td + _x25*_x53)
    d_c_P0__k_c = (_j_z_b_q_r__k*_pd__11 + _j_z_b_q_thd__k*_pd__12 + _pd__10*d_c_e_n__k_c
        + _pd__9*d_bottom_q_r__k_c)
    _x59 = m/math.sqrt(_x33)
    _x60 = (_x33 > 0.0)
    c_T0 = ((-_x10*_x59) if _x60 else (0.0))
    _pd__13 = ((-_x59) if _x60 else (0.0))
    _pd__14 = ((_x44*m/(_x33*math.sqrt(_x33))) if _x60 else (0.0))
    d_c_T0__q_r_td = _pd__13*d_c_e_n__q_r_td + _pd__14*d_c_rad_z__q_r_td
    d_c_T0__q_rd_td = _pd__13*d_c_e_n__q_rd_td + _pd__14*d_c_rad_z__q_rd_td
    d_c_T0__q_th_td = _pd__13*d_c_e_n__q_th_td + _pd__14*d_c_rad_z__q_th_td
    d_c_T0__q_thd_td = _pd__13*d_c_e_n__q_thd_td + _pd__14*d_c_rad_z__q_thd_td
    d_c_T0__k_c = _pd__13*d_c_e_n__k_c + _pd__14*d_c_rad_z__k_c
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__q_r_td, d_c_e_n__q_rd_td, d_c_e_n__q_th_td, d_c_e_n__q_thd_td,
        d_c_e_n__k_c, d_c_Q0__q_r_td, d_c_Q0__q_rd_td, d_c_Q0__q_th_td, d_c_Q0__q_thd_td, d_c_Q0__k_c,
        d_c_P0__q_r_td, d_c_P0__q_rd_td, d_c_P0__q_th_td, d_c_P0__q_thd_td, d_c_P0__k_c, d_c_T0__q_r_td,
        d_c_T0__q_rd_td, d_c_T0__q_th_td, d_c_T0__q_thd_td, d_c_T0__k_c, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__q_r_td, d_c_e__q_rd_td, d_c_e__q_th_td, d_c_e__q_thd_td, d_c_e__k_c,
            d_c_Q__q_r_td, d_c_Q__q_rd_td, d_c_Q__q_th_td, d_c_Q__q_thd_td, d_c_Q__k_c, d_c_P__q_r_td,
            d_c_P__q_rd_td, d_c_P__q_th_td, d_c_P__q_thd_td, d_c_P__k_c, d_c_T__q_r_td, d_c_T__q_rd_td,
            d_c_T__q_th_td, d_c_T__q_thd_td, d_c_T__k_c, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x61 = c_e + q_r_td
        c_x = _x61
        d_c_x__q_r_td = d_c_e__q_r_td + 1.0
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
        d_c_rad__q_r_td = (_pd__15*d_c_P__q_r_td + _pd__16*d_c_Q__q_r_td + _pd__17*d_c_x__q_r_td
            + _x72*d_E_ab__q_r_td)
        d_c_rad__q_rd_td = (_pd__15*d_c_P__q_rd_td + _pd__16*d_c_Q__q_rd_td + _pd__17*d_c_e__q_rd_td
            + _x72*d_E_ab__q_rd_td)
        d_c_rad__q_th_td = (_pd__15*d_c_P__q_th_td + _pd__16*d_c_Q__q_th_td + _pd__17*d_c_e__q_th_td
            + _x72*d_E_ab__q_th_td)
        d_c_rad__q_thd_td = (_pd__15*d_c_P__q_thd_td + _pd__16*d_c_Q__q_thd_td + _pd__17*d_c_e__q_thd_td
            + _x72*d_E_ab__q_thd_td)
        d_c_rad__k_c = (_pd__15*d_c_P__k_c + _pd__16*d_c_Q__k_c + _pd__17*d_c_e__k_c + _x63*(-_x64
            + 2.0*_x65*l0*m - _x67) + _x72*d_E_ab__k_c)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x73 = math.sqrt(c_rad)
        c_h = _x73
        _pd__18 = (0.5)/_x73
        d_c_h__q_r_td = _pd__18*d_c_rad__q_r_td
        d_c_h__q_rd_td = _pd__18*d_c_rad__q_rd_td
        d_c_h__q_th_td = _pd__18*d_c_rad__q_th_td
        d_c_h__q_thd_td = _pd__18*d_c_rad__q_thd_td
        d_c_h__k_c = _pd__18*d_c_rad__k_c
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x77 = (1.0/c_x)
            _x74 = _x77**2
            c_wq = _x74*c_e_next
            _pd__19 = _x74
            _pd__20 = -2.0*_x77**3*c_e_next
            _x75 = 4.0*_pd__19
            d_c_wq__q_r_td = _pd__20*d_c_x__q_r_td + _x75*d_c_e__q_r_td
            d_c_wq__q_rd_td = _pd__20*d_c_e__q_rd_td + _x75*d_c_e__q_rd_td
            d_c_wq__q_th_td = _pd__20*d_c_e__q_th_td + _x75*d_c_e__q_th_td
            d_c_wq__q_thd_td = _pd__20*d_c_e__q_thd_td + _x75*d_c_e__q_thd_td
            d_c_wq__k_c = _pd__20*d_c_e__k_c + _x75*d_c_e__k_c
            c_wp = c_e_next*c_x
            _x76 = 4.0*c_x
            d_c_wp__q_r_td = _x76*d_c_e__q_r_td + c_e_next*d_c_x__q_r_td
            d_c_wp__q_rd_td = _x76*d_c_e__q_rd_td + c_e_next*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x76*d_c_e__q_th_td + c_e_next*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x76*d_c_e__q_thd_td + c_e_next*d_c_e__q_thd_td
            d_c_wp__k_c = _x76*d_c_e__k_c + c_e_next*d_c_e__k_c
        elif variant == 1.0:
            _x78 = (1.0/q_r_td)
            _x79 = c_e_next + q_r_td
            _x80 = (1.0/_x79)
            c_wq = _x78*_x80*c_e_next
            _x81 = _x78*_x80**2*c_e_next
            _pd__21 = _x78*_x80 - _x81
            d_c_wq__q_r_td = 4.0*_pd__21*d_c_e__q_r_td - _x78**2*_x80*c_e_next - _x81
            _x82 = 4.0*_pd__21
            d_c_wq__q_rd_td = _x82*d_c_e__q_rd_td
            d_c_wq__q_th_td = _x82*d_c_e__q_th_td
            d_c_wq__q_thd_td = _x82*d_c_e__q_thd_td
            d_c_wq__k_c = _x82*d_c_e__k_c
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__22 = _x79
            _x83 = 4.0*_pd__22
            d_c_wp__q_r_td = _x83*d_c_e__q_r_td + c_e_next
            d_c_wp__q_rd_td = _x83*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x83*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x83*d_c_e__q_thd_td
            d_c_wp__k_c = _x83*d_c_e__k_c
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        c_e__next = c_e_next
        _x84 = (1.0/c_h)
        _x85 = _x84*c_wq
        c_Q__next = -_x85*c_P + q_th_td
        _pd__23 = -_x85
        _x86 = _x84**2
        _pd__24 = _x86*c_P*c_wq
        _pd__25 = -_x84*c_P
        d_c_Q__next__q_r_td = _pd__23*d_c_P__q_r_td + _pd__24*d_c_h__q_r_td + _pd__25*d_c_wq__q_r_td
        d_c_Q__next__q_rd_td = _pd__23*d_c_P__q_rd_td + _pd__24*d_c_h__q_rd_td + _pd__25*d_c_wq__q_rd_td
        d_c_Q__next__q_th_td = _pd__23*d_c_P__q_th_td + _pd__24*d_c_h__q_th_td + _pd__25*d_c_wq__q_th_td + 1.0
        d_c_Q__next__q_thd_td = _pd__23*d_c_P__q_thd_td + _pd__24*d_c_h__q_thd_td + _pd__25*d_c_wq__q_thd_td
        d_c_Q__next__k_c = _pd__23*d_c_P__k_c + _pd__24*d_c_h__k_c + _pd__25*d_c_wq__k_c
        _x87 = m*q_r_td**2
        _x88 = math.sin(c_Q)
        _x89 = m**2
        _x90 = _x84*_x89*g_s
        _x91 = _x88*_x90
        c_P__next = _x87*q_thd_td - _x91*c_wp
        _pd__26 = -_x90*c_wp*math.cos(c_Q)
        _pd__27 = _x86*_x88*_x89*c_wp*g_s
        _pd__28 = -_x91
        d_c_P__next__q_r_td = (_pd__26*d_c_Q__q_r_td + _pd__27*d_c_h__q_r_td + _pd__28*d_c_wp__q_r_td
            + 2.0*m*q_r_td*q_thd_td)
        d_c_P__next__q_rd_td = _pd__26*d_c_Q__q_rd_td + _pd__27*d_c_h__q_rd_td + _pd__28*d_c_wp__q_rd_td
        d_c_P__next__q_th_td = _pd__26*d_c_Q__q_th_td + _pd__27*d_c_h__q_th_td + _pd__28*d_c_wp__q_th_td
        d_c_P__next__q_thd_td = (_pd__26*d_c_Q__q_thd_td + _pd__27*d_c_h__q_thd_td + _pd__28*d_c_wp__q_thd_td
            + _x87)
        d_c_P__next__k_c = _pd__26*d_c_Q__k_c + _pd__27*d_c_h__k_c + _pd__28*d_c_wp__k_c
        _x92 = _x84*m
        c_T__next = -_x92*c_e_next
        _pd__29 = -_x92
        _pd__30 = _x86*c_e_next*m
        _x93 = 4.0*_pd__29
        d_c_T__next__q_r_td = _pd__30*d_c_h__q_r_td + _x93*d_c_e__q_r_td
        d_c_T__next__q_rd_td = _pd__30*d_c_h__q_rd_td + _x93*d_c_e__q_rd_td
        d_c_T__next__q_th_td = _pd__30*d_c_h__q_th_td + _x93*d_c_e__q_th_td
        d_c_T__next__q_thd_td = _pd__30*d_c_h__q_thd_td + _x93*d_c_e__q_thd_td
        d_c_T__next__k_c = _pd__30*d_c_h__k_c + _x93*d_c_e__k_c
        _n0_4 = 4.0*d_c_e__q_r_td
        _n0_5 = 4.0*d_c_e__q_rd_td
        _n0_6 = 4.0*d_c_e__q_th_td
        _n0_7 = 4.0*d_c_e__q_thd_td
        _n0_8 = 4.0*d_c_e__k_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8,
            d_c_Q__next__q_r_td, d_c_Q__next__q_rd_td, d_c_Q__next__q_th_td, d_c_Q__next__q_thd_td,
            d_c_Q__next__k_c, d_c_P__next__q_r_td, d_c_P__next__q_rd_td, d_c_P__next__q_th_td,
            d_c_P__next__q_thd_td, d_c_P__next__k_c, d_c_T__next__q_r_td, d_c_T__next__q_rd_td,
            d_c_T__next__q_th_td, d_c_T__next__q_thd_td, d_c_T__next__k_c, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    _x94 = (1.0/m)
    _x96 = (1.0/bottom_q_r)
    _x95 = _x94*_x96**2
    bottom_q_thd = _x95*c_P
    _pd__31 = -2.0*_x94*_x96**3*c_P
    _pd__32 = _x95
    d_bottom_q_thd__q_r_td = _pd__31*d_bottom_q_r__q_r_td + _pd__32*d_c_P__q_r_td
    d_bottom_q_thd__q_rd_td = _pd__31*d_bottom_q_r__q_rd_td + _pd__32*d_c_P__q_rd_td
    d_bottom_q_thd__q_th_td = _pd__31*d_bottom_q_r__q_th_td + _pd__32*d_c_P__q_th_td
    d_bottom_q_thd__q_thd_td = _pd__31*d_bottom_q_r__q_thd_td + _pd__32*d_c_P__q_thd_td
    d_bottom_q_thd__k_c = _pd__31*d_bottom_q_r__k_c + _pd__32*d_c_P__k_c
    # E_ba of (98): the energy jump of the stiffness switch
    _x97 = (-bottom_q_r + l0)**2
    _x98 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x97*_x98
    _pd__33 = _x98*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__q_r_td = _pd__33*d_bottom_q_r__q_r_td + d_E_ab__q_r_td
    d_E_ba__q_rd_td = _pd__33*d_bottom_q_r__q_rd_td + d_E_ab__q_rd_td
    d_E_ba__q_th_td = _pd__33*d_bottom_q_r__q_th_td + d_E_ab__q_th_td
    d_E_ba__q_thd_td = _pd__33*d_bottom_q_r__q_thd_td + d_E_ab__q_thd_td
    _x99 = (0.5)*_x97
    d_E_ba__k_c = _pd__33*d_bottom_q_r__k_c - _x99 + d_E_ab__k_c
    d_E_ba__k_d = _x99
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN70 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x100 = 4.0**(-iterations)
    _x101 = -bottom_q_r + q_r_lo
    _x102 = _x100*_x101
    d_e_n = _x102
    _pd__34 = -_x100
    d_d_e_n__q_r_td = _pd__34*d_bottom_q_r__q_r_td
    d_d_e_n__q_rd_td = _pd__34*d_bottom_q_r__q_rd_td
    d_d_e_n__q_th_td = _pd__34*d_bottom_q_r__q_th_td
    d_d_e_n__q_thd_td = _pd__34*d_bottom_q_r__q_thd_td
    d_d_e_n__k_c = _pd__34*d_bottom_q_r__k_c
    _x103 = (0.25)*_x102
    d_e_z = _x103
    _x104 = _x103 + bottom_q_r
    _x105 = _x104**2
    _x106 = (1.0/_x105)
    _x107 = _x104**4*m
    _x108 = _x104**3
    _x109 = l0**2*m
    _x110 = _x105*_x109
    _x111 = bottom_q_r**2*m
    _x112 = _x111*bottom_q_thd
    _x113 = q_r_lo**2
    _x114 = -_x112 + _x113*g_lo_q_thd*m
    _x115 = 4.0**((0.5)*iterations)
    _x116 = (1.0/_x115)
    _x117 = (0.5)*_x116
    _x118 = _x114*_x117
    _x119 = _x112 + _x118
    _x120 = -bottom_q_th + g_lo_q_th
    _x121 = _x117*_x120
    _x122 = _x121 + bottom_q_th
    _x123 = m**2
    _x124 = _x123*g_s
    _x125 = _x124*math.cos(_x122)
    _x126 = 2.0*E_ba*_x105*m - _x107*k_d - 2.0*_x108*_x125 + 2.0*_x108*k_d*l0*m - _x110*k_d - _x119**2
    _x127 = _x106*_x126
    d_rad_z = _x127
    _x128 = -2.0*_x126/_x108
    _x129 = 4.0*m
    _x130 = (1.0/_x101)
    _x131 = 2.0*bottom_q_r
    _x132 = _x131*bottom_q_thd*m
    _x133 = -_x116*_x132 + _x118*_x130
    _x134 = math.sin(_x122)
    _x135 = (0.5)*_x102
    _x136 = _x131 + _x135
    _x137 = -2.0*E_ba*_x136*m + 6.0*_x105*_x125 - 6.0*_x105*k_d*l0*m + _x108*_x129*k_d + _x109*_x136*k_d
    _pd__35 = (_x106*((0.5)*_x108*_x116*_x120*_x123*_x130*_x134*g_s - _x119*(_x129*bottom_q_r*bottom_q_thd
        + _x133) - _x137) + _x128)
    _x138 = _x104*_x124*_x134
    _pd__36 = 2.0*_x138*(1.0 - _x117)
    _x139 = -_x111*_x116
    _x140 = _x106*_x119
    _pd__37 = -_x140*(2.0*_x111 + _x139)
    _x141 = _x115*_x130
    _pd__38 = _x106*(2.0*_x108*_x115*_x120*_x123*_x130*_x134*g_s - 2.0*_x114*_x119*_x141 - _x137) + _x128
    _pd__39 = _x116*_x138
    _x142 = _x113*_x116*m
    _pd__40 = -_x140*_x142
    _x143 = (0.25)*_pd__38
    _x144 = 2.0*m
    d_d_rad_z__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__39 + _j_z_lo_q_thd__q_r_td*_pd__40
        + _pd__35*d_bottom_q_r__q_r_td + _pd__36*d_c_Q__q_r_td + _pd__37*d_bottom_q_thd__q_r_td
        + _x143*d_d_e_n__q_r_td + _x144*d_E_ba__q_r_td)
    d_d_rad_z__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__39 + _j_z_lo_q_thd__q_rd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_rd_td + _pd__36*d_c_Q__q_rd_td + _pd__37*d_bottom_q_thd__q_rd_td
        + _x143*d_d_e_n__q_rd_td + _x144*d_E_ba__q_rd_td)
    d_d_rad_z__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__39 + _j_z_lo_q_thd__q_th_td*_pd__40
        + _pd__35*d_bottom_q_r__q_th_td + _pd__36*d_c_Q__q_th_td + _pd__37*d_bottom_q_thd__q_th_td
        + _x143*d_d_e_n__q_th_td + _x144*d_E_ba__q_th_td)
    d_d_rad_z__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__39 + _j_z_lo_q_thd__q_thd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_thd_td + _pd__36*d_c_Q__q_thd_td + _pd__37*d_bottom_q_thd__q_thd_td
        + _x143*d_d_e_n__q_thd_td + _x144*d_E_ba__q_thd_td)
    d_d_rad_z__k_c = (_j_z_lo_q_th__k*_pd__39 + _j_z_lo_q_thd__k*_pd__40 + _pd__35*d_bottom_q_r__k_c
        + _pd__36*d_c_Q__k_c + _pd__37*d_bottom_q_thd__k_c + _x143*d_d_e_n__k_c + _x144*d_E_ba__k_c)
    d_d_rad_z__k_d = _x106*(-_x107 + 2.0*_x108*l0*m - _x110) + _x144*d_E_ba__k_d
    d_Q0 = _x116*_x120 + bottom_q_th
    _pd__41 = _x121*_x130
    _pd__42 = 1.0 - _x116
    _x145 = (0.5)*_x141
    _pd__43 = _x120*_x145
    _pd__44 = _x116
    d_d_Q0__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__44 + _pd__41*d_bottom_q_r__q_r_td + _pd__42*d_c_Q__q_r_td
        + _pd__43*d_d_e_n__q_r_td)
    d_d_Q0__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__44 + _pd__41*d_bottom_q_r__q_rd_td + _pd__42*d_c_Q__q_rd_td
        + _pd__43*d_d_e_n__q_rd_td)
    d_d_Q0__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__44 + _pd__41*d_bottom_q_r__q_th_td + _pd__42*d_c_Q__q_th_td
        + _pd__43*d_d_e_n__q_th_td)
    d_d_Q0__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__44 + _pd__41*d_bottom_q_r__q_thd_td
        + _pd__42*d_c_Q__q_thd_td + _pd__43*d_d_e_n__q_thd_td)
    d_d_Q0__k_c = (_j_z_lo_q_th__k*_pd__44 + _pd__41*d_bottom_q_r__k_c + _pd__42*d_c_Q__k_c
        + _pd__43*d_d_e_n__k_c)
    d_P0 = _x112 + _x114*_x116
    _pd__45 = _x132 + _x133
    _pd__46 = _x111 + _x139
    _pd__47 = _x114*_x145
    _pd__48 = _x142
    d_d_P0__q_r_td = (_j_z_lo_q_thd__q_r_td*_pd__48 + _pd__45*d_bottom_q_r__q_r_td
        + _pd__46*d_bottom_q_thd__q_r_td + _pd__47*d_d_e_n__q_r_td)
    d_d_P0__q_rd_td = (_j_z_lo_q_thd__q_rd_td*_pd__48 + _pd__45*d_bottom_q_r__q_rd_td
        + _pd__46*d_bottom_q_thd__q_rd_td + _pd__47*d_d_e_n__q_rd_td)
    d_d_P0__q_th_td = (_j_z_lo_q_thd__q_th_td*_pd__48 + _pd__45*d_bottom_q_r__q_th_td
        + _pd__46*d_bottom_q_thd__q_th_td + _pd__47*d_d_e_n__q_th_td)
    d_d_P0__q_thd_td = (_j_z_lo_q_thd__q_thd_td*_pd__48 + _pd__45*d_bottom_q_r__q_thd_td
        + _pd__46*d_bottom_q_thd__q_thd_td + _pd__47*d_d_e_n__q_thd_td)
    d_d_P0__k_c = (_j_z_lo_q_thd__k*_pd__48 + _pd__45*d_bottom_q_r__k_c + _pd__46*d_bottom_q_thd__k_c
        + _pd__47*d_d_e_n__k_c)
    _x146 = m/math.sqrt(_x127)
    _x147 = (_x127 > 0.0)
    d_T0 = ((_x102*_x146 + t_bottom) if _x147 else (t_bottom))
    _pd__49 = ((_x146) if _x147 else (0.0))
    _pd__50 = ((-_x135*m/(_x127*math.sqrt(_x127))) if _x147 else (0.0))
    d_d_T0__q_r_td = _pd__49*d_d_e_n__q_r_td + _pd__50*d_d_rad_z__q_r_td + d_c_T__q_r_td
    d_d_T0__q_rd_td = _pd__49*d_d_e_n__q_rd_td + _pd__50*d_d_rad_z__q_rd_td + d_c_T__q_rd_td
    d_d_T0__q_th_td = _pd__49*d_d_e_n__q_th_td + _pd__50*d_d_rad_z__q_th_td + d_c_T__q_th_td
    d_d_T0__q_thd_td = _pd__49*d_d_e_n__q_thd_td + _pd__50*d_d_rad_z__q_thd_td + d_c_T__q_thd_td
    d_d_T0__k_c = _pd__49*d_d_e_n__k_c + _pd__50*d_d_rad_z__k_c + d_c_T__k_c
    d_d_T0__k_d = _pd__50*d_d_rad_z__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki1 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__q_r_td, d_d_e_n__q_rd_td, d_d_e_n__q_th_td, d_d_e_n__q_thd_td,
        d_d_e_n__k_c, 0.0, d_d_Q0__q_r_td, d_d_Q0__q_rd_td, d_d_Q0__q_th_td, d_d_Q0__q_thd_td, d_d_Q0__k_c,
        0.0, d_d_P0__q_r_td, d_d_P0__q_rd_td, d_d_P0__q_th_td, d_d_P0__q_thd_td, d_d_P0__k_c, 0.0,
        d_d_T0__q_r_td, d_d_T0__q_rd_td, d_d_T0__q_th_td, d_d_T0__q_thd_td, d_d_T0__k_c, d_d_T0__k_d, )
    _pk1 = _pki1
    d_steps = 0.0
    _conv1 = False
    _last1 = max(int(iterations), 0)
    for _it1 in range(_last1 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__q_r_td, d_d_e__q_rd_td, d_d_e__q_th_td, d_d_e__q_thd_td, d_d_e__k_c,
            d_d_e__k_d, d_d_Q__q_r_td, d_d_Q__q_rd_td, d_d_Q__q_th_td, d_d_Q__q_thd_td, d_d_Q__k_c,
            d_d_Q__k_d, d_d_P__q_r_td, d_d_P__q_rd_td, d_d_P__q_th_td, d_d_P__q_thd_td, d_d_P__k_c,
            d_d_P__k_d, d_d_T__q_r_td, d_d_T__q_rd_td, d_d_T__q_th_td, d_d_T__q_thd_td, d_d_T__k_c,
            d_d_T__k_d, ) = _pk1
        if _conv1 or _it1 == _last1:
            break
        _x148 = bottom_q_r + d_e
        d_x = _x148
        d_d_x__q_r_td = d_bottom_q_r__q_r_td + d_d_e__q_r_td
        d_d_x__q_rd_td = d_bottom_q_r__q_rd_td + d_d_e__q_rd_td
        d_d_x__q_th_td = d_bottom_q_r__q_th_td + d_d_e__q_th_td
        d_d_x__q_thd_td = d_bottom_q_r__q_thd_td + d_d_e__q_thd_td
        d_d_x__k_c = d_bottom_q_r__k_c + d_d_e__k_c
        _x149 = _x148**2
        _x150 = (1.0/_x149)
        _x151 = _x148**4*m
        _x152 = _x148**3
        _x153 = l0**2
        _x154 = _x149*_x153*m
        _x155 = math.cos(d_Q)
        _x156 = m**2
        _x157 = 2.0*_x156*g_s
        _x158 = 2.0*E_ba*_x149*m - _x151*k_d - _x152*_x155*_x157 + 2.0*_x152*k_d*l0*m - _x154*k_d - d_P**2
        d_rad = _x150*_x158
        _pd__51 = -2.0*_x150*d_P
        _pd__52 = _x148*_x157*math.sin(d_Q)
        _x159 = 2.0*m
        _pd__53 = (_x150*(4.0*E_ba*_x148*m - _x148*_x153*_x159*k_d - 6.0*_x149*_x155*_x156*g_s
            + 6.0*_x149*k_d*l0*m - 4.0*_x152*k_d*m) - 2.0*_x158/_x152)
        d_d_rad__q_r_td = (_pd__51*d_d_P__q_r_td + _pd__52*d_d_Q__q_r_td + _pd__53*d_d_x__q_r_td
            + _x159*d_E_ba__q_r_td)
        d_d_rad__q_rd_td = (_pd__51*d_d_P__q_rd_td + _pd__52*d_d_Q__q_rd_td + _pd__53*d_d_x__q_rd_td
            + _x159*d_E_ba__q_rd_td)
        d_d_rad__q_th_td = (_pd__51*d_d_P__q_th_td + _pd__52*d_d_Q__q_th_td + _pd__53*d_d_x__q_th_td
            + _x159*d_E_ba__q_th_td)
        d_d_rad__q_thd_td = (_pd__51*d_d_P__q_thd_td + _pd__52*d_d_Q__q_thd_td + _pd__53*d_d_x__q_thd_td
            + _x159*d_E_ba__q_thd_td)
        d_d_rad__k_c = _pd__51*d_d_P__k_c + _pd__52*d_d_Q__k_c + _pd__53*d_d_x__k_c + _x159*d_E_ba__k_c
        d_d_rad__k_d = (_pd__51*d_d_P__k_d + _pd__52*d_d_Q__k_d + _pd__53*d_d_e__k_d + _x150*(-_x151
            + 2.0*_x152*l0*m - _x154) + _x159*d_E_ba__k_d)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x160 = math.sqrt(d_rad)
        d_h = _x160
        _pd__54 = (0.5)/_x160
        d_d_h__q_r_td = _pd__54*d_d_rad__q_r_td
        d_d_h__q_rd_td = _pd__54*d_d_rad__q_rd_td
        d_d_h__q_th_td = _pd__54*d_d_rad__q_th_td
        d_d_h__q_thd_td = _pd__54*d_d_rad__q_thd_td
        d_d_h__k_c = _pd__54*d_d_rad__k_c
        d_d_h__k_d = _pd__54*d_d_rad__k_d
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x164 = (1.0/d_x)
            _x161 = _x164**2
            d_wq = _x161*d_e_next
            _pd__55 = _x161
            _pd__56 = -2.0*_x164**3*d_e_next
            _x162 = 4.0*_pd__55
            d_d_wq__q_r_td = _pd__56*d_d_x__q_r_td + _x162*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__56*d_d_x__q_rd_td + _x162*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__56*d_d_x__q_th_td + _x162*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__56*d_d_x__q_thd_td + _x162*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__56*d_d_x__k_c + _x162*d_d_e__k_c
            d_d_wq__k_d = _pd__56*d_d_e__k_d + _x162*d_d_e__k_d
            d_wp = d_e_next*d_x
            _x163 = 4.0*d_x
            d_d_wp__q_r_td = _x163*d_d_e__q_r_td + d_d_x__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x163*d_d_e__q_rd_td + d_d_x__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x163*d_d_e__q_th_td + d_d_x__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x163*d_d_e__q_thd_td + d_d_x__q_thd_td*d_e_next
            d_d_wp__k_c = _x163*d_d_e__k_c + d_d_x__k_c*d_e_next
            d_d_wp__k_d = _x163*d_d_e__k_d + d_d_e__k_d*d_e_next
        elif variant == 1.0:
            _x165 = (1.0/bottom_q_r)
            _x166 = bottom_q_r + d_e_next
            _x167 = (1.0/_x166)
            d_wq = _x165*_x167*d_e_next
            _x168 = _x165*_x167**2*d_e_next
            _pd__57 = -_x165**2*_x167*d_e_next - _x168
            _pd__58 = _x165*_x167 - _x168
            _x169 = 4.0*_pd__58
            d_d_wq__q_r_td = _pd__57*d_bottom_q_r__q_r_td + _x169*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__57*d_bottom_q_r__q_rd_td + _x169*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__57*d_bottom_q_r__q_th_td + _x169*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__57*d_bottom_q_r__q_thd_td + _x169*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__57*d_bottom_q_r__k_c + _x169*d_d_e__k_c
            d_d_wq__k_d = _x169*d_d_e__k_d
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__59 = _x166
            _x170 = 4.0*_pd__59
            d_d_wp__q_r_td = _x170*d_d_e__q_r_td + d_bottom_q_r__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x170*d_d_e__q_rd_td + d_bottom_q_r__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x170*d_d_e__q_th_td + d_bottom_q_r__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x170*d_d_e__q_thd_td + d_bottom_q_r__q_thd_td*d_e_next
            d_d_wp__k_c = _x170*d_d_e__k_c + d_bottom_q_r__k_c*d_e_next
            d_d_wp__k_d = _x170*d_d_e__k_d
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        d_e__next = d_e_next
        _x171 = (1.0/d_h)
        _x172 = _x171*d_wq
        d_Q__next = _x172*d_P + bottom_q_th
        _pd__60 = _x172
        _x173 = _x171**2
        _pd__61 = -_x173*d_P*d_wq
        _pd__62 = _x171*d_P
        d_d_Q__next__q_r_td = (_pd__60*d_d_P__q_r_td + _pd__61*d_d_h__q_r_td + _pd__62*d_d_wq__q_r_td
            + d_c_Q__q_r_td)
        d_d_Q__next__q_rd_td = (_pd__60*d_d_P__q_rd_td + _pd__61*d_d_h__q_rd_td + _pd__62*d_d_wq__q_rd_td
            + d_c_Q__q_rd_td)
        d_d_Q__next__q_th_td = (_pd__60*d_d_P__q_th_td + _pd__61*d_d_h__q_th_td + _pd__62*d_d_wq__q_th_td
            + d_c_Q__q_th_td)
        d_d_Q__next__q_thd_td = (_pd__60*d_d_P__q_thd_td + _pd__61*d_d_h__q_thd_td + _pd__62*d_d_wq__q_thd_td
            + d_c_Q__q_thd_td)
        d_d_Q__next__k_c = _pd__60*d_d_P__k_c + _pd__61*d_d_h__k_c + _pd__62*d_d_wq__k_c + d_c_Q__k_c
        d_d_Q__next__k_d = _pd__60*d_d_P__k_d + _pd__61*d_d_h__k_d + _pd__62*d_d_wq__k_d
        _x174 = bottom_q_r**2*m
        _x175 = math.sin(d_Q)
        _x176 = m**2
        _x177 = _x171*_x176*g_s
        _x178 = _x175*_x177
        d_P__next = _x174*bottom_q_thd + _x178*d_wp
        _pd__63 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__64 = _x174
        _pd__65 = _x177*d_wp*math.cos(d_Q)
        _pd__66 = -_x173*_x175*_x176*d_wp*g_s
        _pd__67 = _x178
        d_d_P__next__q_r_td = (_pd__63*d_bottom_q_r__q_r_td + _pd__64*d_bottom_q_thd__q_r_td
            + _pd__65*d_d_Q__q_r_td + _pd__66*d_d_h__q_r_td + _pd__67*d_d_wp__q_r_td)
        d_d_P__next__q_rd_td = (_pd__63*d_bottom_q_r__q_rd_td + _pd__64*d_bottom_q_thd__q_rd_td
            + _pd__65*d_d_Q__q_rd_td + _pd__66*d_d_h__q_rd_td + _pd__67*d_d_wp__q_rd_td)
        d_d_P__next__q_th_td = (_pd__63*d_bottom_q_r__q_th_td + _pd__64*d_bottom_q_thd__q_th_td
            + _pd__65*d_d_Q__q_th_td + _pd__66*d_d_h__q_th_td + _pd__67*d_d_wp__q_th_td)
        d_d_P__next__q_thd_td = (_pd__63*d_bottom_q_r__q_thd_td + _pd__64*d_bottom_q_thd__q_thd_td
            + _pd__65*d_d_Q__q_thd_td + _pd__66*d_d_h__q_thd_td + _pd__67*d_d_wp__q_thd_td)
        d_d_P__next__k_c = (_pd__63*d_bottom_q_r__k_c + _pd__64*d_bottom_q_thd__k_c + _pd__65*d_d_Q__k_c
            + _pd__66*d_d_h__k_c + _pd__67*d_d_wp__k_c)
        d_d_P__next__k_d = _pd__65*d_d_Q__k_d + _pd__66*d_d_h__k_d + _pd__67*d_d_wp__k_d
        _x179 = _x171*m
        d_T__next = _x179*d_e_next + t_bottom
        _pd__68 = _x179
        _pd__69 = -_x173*d_e_next*m
        _x180 = 4.0*_pd__68
        d_d_T__next__q_r_td = _pd__69*d_d_h__q_r_td + _x180*d_d_e__q_r_td + d_c_T__q_r_td
        d_d_T__next__q_rd_td = _pd__69*d_d_h__q_rd_td + _x180*d_d_e__q_rd_td + d_c_T__q_rd_td
        d_d_T__next__q_th_td = _pd__69*d_d_h__q_th_td + _x180*d_d_e__q_th_td + d_c_T__q_th_td
        d_d_T__next__q_thd_td = _pd__69*d_d_h__q_thd_td + _x180*d_d_e__q_thd_td + d_c_T__q_thd_td
        d_d_T__next__k_c = _pd__69*d_d_h__k_c + _x180*d_d_e__k_c + d_c_T__k_c
        d_d_T__next__k_d = _pd__69*d_d_h__k_d + _x180*d_d_e__k_d
        _n1_4 = 4.0*d_d_e__q_r_td
        _n1_5 = 4.0*d_d_e__q_rd_td
        _n1_6 = 4.0*d_d_e__q_th_td
        _n1_7 = 4.0*d_d_e__q_thd_td
        _n1_8 = 4.0*d_d_e__k_c
        _n1_9 = 4.0*d_d_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn1 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n1_4, _n1_5, _n1_6, _n1_7, _n1_8, _n1_9,
            d_d_Q__next__q_r_td, d_d_Q__next__q_rd_td, d_d_Q__next__q_th_td, d_d_Q__next__q_thd_td,
            d_d_Q__next__k_c, d_d_Q__next__k_d, d_d_P__next__q_r_td, d_d_P__next__q_rd_td,
            d_d_P__next__q_th_td, d_d_P__next__q_thd_td, d_d_P__next__k_c, d_d_P__next__k_d,
            d_d_T__next__q_r_td, d_d_T__next__q_rd_td, d_d_T__next__q_th_td, d_d_T__next__q_thd_td,
            d_d_T__next__k_c, d_d_T__next__k_d, )
        _pk1 = _pkn1
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x181 = q_r_lo**2
    _x182 = (1.0/_x181)
    _x183 = m*q_r_lo**4
    _x184 = q_r_lo**3
    _x185 = _x181*l0**2*m
    _x186 = 2.0*g_s*m**2
    rad_lo = (_x182*(2.0*E_ba*_x181*m - _x183*k_d - _x184*_x186*math.cos(d_Q) + 2.0*_x184*k_d*l0*m - _x185*k_d
        - d_P**2))
    _pd__70 = -2.0*_x182*d_P
    _pd__71 = _x186*q_r_lo*math.sin(d_Q)
    _x187 = 2.0*m
    d_rad_lo__q_r_td = _pd__70*d_d_P__q_r_td + _pd__71*d_d_Q__q_r_td + _x187*d_E_ba__q_r_td
    d_rad_lo__q_rd_td = _pd__70*d_d_P__q_rd_td + _pd__71*d_d_Q__q_rd_td + _x187*d_E_ba__q_rd_td
    d_rad_lo__q_th_td = _pd__70*d_d_P__q_th_td + _pd__71*d_d_Q__q_th_td + _x187*d_E_ba__q_th_td
    d_rad_lo__q_thd_td = _pd__70*d_d_P__q_thd_td + _pd__71*d_d_Q__q_thd_td + _x187*d_E_ba__q_thd_td
    d_rad_lo__k_c = _pd__70*d_d_P__k_c + _pd__71*d_d_Q__k_c + _x187*d_E_ba__k_c
    d_rad_lo__k_d = (_pd__70*d_d_P__k_d + _pd__71*d_d_Q__k_d + _x182*(-_x183 + 2.0*_x184*l0*m - _x185)
        + _x187*d_E_ba__k_d)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x188 = (1.0/m)
    _x189 = math.sqrt(rad_lo)
    liftoff_q_rd = _x188*_x189
    _pd__72 = (0.5)*_x188/_x189
    d_liftoff_q_rd__q_r_td = _pd__72*d_rad_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _pd__72*d_rad_lo__q_rd_td
    d_liftoff_q_rd__q_th_td = _pd__72*d_rad_lo__q_th_td
    d_liftoff_q_rd__q_thd_td = _pd__72*d_rad_lo__q_thd_td
    d_liftoff_q_rd__k_c = _pd__72*d_rad_lo__k_c
    d_liftoff_q_rd__k_d = _pd__72*d_rad_lo__k_d
    liftoff_q_th = d_Q
    _x190 = _x188/q_r_lo**2
    liftoff_q_thd = _x190*d_P
    _pd__73 = _x190
    d_liftoff_q_thd__q_r_td = _pd__73*d_d_P__q_r_td
    d_liftoff_q_thd__q_rd_td = _pd__73*d_d_P__q_rd_td
    d_liftoff_q_thd__q_th_td = _pd__73*d_d_P__q_th_td
    d_liftoff_q_thd__q_thd_td = _pd__73*d_d_P__q_thd_td
    d_liftoff_q_thd__k_c = _pd__73*d_d_P__k_c
    d_liftoff_q_thd__k_d = _pd__73*d_d_P__k_d
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN70 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_c_T__q_r_td
    d_t_bottom__q_rd_td = d_c_T__q_rd_td
    d_t_bottom__q_th_td = d_c_T__q_th_td
    d_t_bottom__q_thd_td = d_c_T__q_thd_td
    d_t_bottom__k_c = d_c_T__k_c
    d_t_bottom__k_d = 0.0
    d_t_stance__q_r_td = d_d_T__q_r_td
    d_t_stance__q_rd_td = d_d_T__q_rd_td
    d_t_stance__q_th_td = d_d_T__q_th_td
    d_t_stance__q_thd_td = d_d_T__q_thd_td
    d_t_stance__k_c = d_d_T__k_c
    d_t_stance__k_d = d_d_T__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__q_r_td = d_c_Q__q_r_td
    d_bottom_q_th__q_rd_td = d_c_Q__q_rd_td
    d_bottom_q_th__q_th_td = d_c_Q__q_th_td
    d_bottom_q_th__q_thd_td = d_c_Q__q_thd_td
    d_bottom_q_th__k_c = d_c_Q__k_c
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_th__q_r_td = d_d_Q__q_r_td
    d_liftoff_q_th__q_rd_td = d_d_Q__q_rd_td
    d_liftoff_q_th__q_th_td = d_d_Q__q_th_td
    d_liftoff_q_th__q_thd_td = d_d_Q__q_thd_td
    d_liftoff_q_th__k_c = d_d_Q__k_c
    d_liftoff_q_th__k_d = d_d_Q__k_d
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
def iterative_report_stance_jacobian_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian_zeroth_gravity_type4`: arguments, out
    and status as :func:`iterative_report_stance_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_jacobian_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
            and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f
            > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_jacobian_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # the code shared between choices
    return (iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type4`: arguments,
    out and status as :func:`iterative_report_apex_return_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_jacobian_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations,
            bottom_length))
        store_row_12_84(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1522
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN70 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = (gravity_type5_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0,
        1e-12))
    if _c0[72] != STATUS_OK:
        return _NAN70 + (_c0[72],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td, _j_z_b_q_r__k, _,
        _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td, _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td,
        _j_z_b_q_th__k, _j_z_b_q_thd__q_r_td, _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td,
        _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td,
        _j_z_lo_q_th__q_rd_td, _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # E_ab (114) of the touchdown state
    _x0 = k_c*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*l0 + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__q_r_td = _x0 + _x5 + _x6*q_r_td - k_c*l0
    d_E_ab__q_rd_td = m*q_rd_td
    d_E_ab__q_th_td = -_x4*q_r_td*math.sin(q_th_td)
    d_E_ab__q_thd_td = _x2*m*q_thd_td
    d_E_ab__k_c = _x1 + _x3 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_bottom_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_bottom_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_bottom_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_bottom_q_r__k_c = _j_z_b_q_r__k
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic_jac_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[4] != STATUS_OK:
            return _NAN70 + (_c1[4],)
        bottom_q_r = _c1[0]
        _j_bottom_q_r__p = _c1[1]
        _j_bottom_q_r__E_ab = _c1[2]
        _j_bottom_q_r__k_c = _c1[3]
        # chain rule through bottom_quartic
        _x7 = _j_bottom_q_r__p*m
        d_bottom_q_r__q_r_td = _j_bottom_q_r__E_ab*d_E_ab__q_r_td + 2.0*_x7*q_r_td*q_thd_td
        d_bottom_q_r__q_rd_td = _j_bottom_q_r__E_ab*d_E_ab__q_rd_td
        d_bottom_q_r__q_th_td = _j_bottom_q_r__E_ab*d_E_ab__q_th_td
        d_bottom_q_r__q_thd_td = _j_bottom_q_r__E_ab*d_E_ab__q_thd_td + _x7*q_r_td**2
        d_bottom_q_r__k_c = _j_bottom_q_r__E_ab*d_E_ab__k_c + _j_bottom_q_r__k_c
    else:
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN70 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = bottom_q_r - q_r_td
    _x10 = _x8*_x9
    c_e_n = _x10
    _pd__0 = _x8
    _x11 = -_x8
    d_c_e_n__q_r_td = _pd__0*d_bottom_q_r__q_r_td + _x11
    d_c_e_n__q_rd_td = _pd__0*d_bottom_q_r__q_rd_td
    d_c_e_n__q_th_td = _pd__0*d_bottom_q_r__q_th_td
    d_c_e_n__q_thd_td = _pd__0*d_bottom_q_r__q_thd_td
    d_c_e_n__k_c = _pd__0*d_bottom_q_r__k_c
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
    d_c_rad_z__q_r_td = (_j_z_b_q_r__q_r_td*_pd__3 + _j_z_b_q_th__q_r_td*_pd__4 + _j_z_b_q_thd__q_r_td*_pd__5
        + _pd__1*d_bottom_q_r__q_r_td + _x15*(-_x27*(-_x23*_x41 + _x24*_x46*q_r_td*q_thd_td) - _x39 - _x47)
        + _x42 + _x51*d_c_e_n__q_r_td + _x52*d_E_ab__q_r_td)
    d_c_rad_z__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__3 + _j_z_b_q_th__q_rd_td*_pd__4
        + _j_z_b_q_thd__q_rd_td*_pd__5 + _pd__1*d_bottom_q_r__q_rd_td + _x51*d_c_e_n__q_rd_td
        + _x52*d_E_ab__q_rd_td)
    d_c_rad_z__q_th_td = (_j_z_b_q_r__q_th_td*_pd__3 + _j_z_b_q_th__q_th_td*_pd__4
        + _j_z_b_q_thd__q_th_td*_pd__5 + _pd__1*d_bottom_q_r__q_th_td + _x24*_x50 + _x51*d_c_e_n__q_th_td
        + _x52*d_E_ab__q_th_td)
    d_c_rad_z__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__3 + _j_z_b_q_th__q_thd_td*_pd__4
        + _j_z_b_q_thd__q_thd_td*_pd__5 + _pd__1*d_bottom_q_r__q_thd_td - 2.0*_x24*_x25*_x49
        + _x51*d_c_e_n__q_thd_td + _x52*d_E_ab__q_thd_td)
    d_c_rad_z__k_c = (_j_z_b_q_r__k*_pd__3 + _j_z_b_q_th__k*_pd__4 + _j_z_b_q_thd__k*_pd__5
        + _pd__1*d_bottom_q_r__k_c + _x15*(-_x16 + 2.0*_x17*l0*m - _x19) + _x51*d_c_e_n__k_c
        + _x52*d_E_ab__k_c)
    _x53 = math.sqrt(_x11 + 1.0)
    c_Q0 = _x29*_x53 + z_b_q_th
    _x54 = (0.5)/_x53
    _x55 = _x36*_x54
    _x56 = _x55*_x8
    _pd__6 = _x56
    _pd__7 = -_x55
    _pd__8 = 1.0 - _x53
    d_c_Q0__q_r_td = _j_z_b_q_th__q_r_td*_pd__8 + _pd__6*d_bottom_q_r__q_r_td + _pd__7*d_c_e_n__q_r_td - _x56
    d_c_Q0__q_rd_td = _j_z_b_q_th__q_rd_td*_pd__8 + _pd__6*d_bottom_q_r__q_rd_td + _pd__7*d_c_e_n__q_rd_td
    d_c_Q0__q_th_td = (_j_z_b_q_th__q_th_td*_pd__8 + _pd__6*d_bottom_q_r__q_th_td + _pd__7*d_c_e_n__q_th_td
        + _x53)
    d_c_Q0__q_thd_td = _j_z_b_q_th__q_thd_td*_pd__8 + _pd__6*d_bottom_q_r__q_thd_td + _pd__7*d_c_e_n__q_thd_td
    d_c_Q0__k_c = _j_z_b_q_th__k*_pd__8 + _pd__6*d_bottom_q_r__k_c + _pd__7*d_c_e_n__k_c
    c_P0 = _x22 + _x26*_x53
    _x57 = _x40*_x54
    _x58 = _x57*_x8
    _pd__9 = _x58
    _pd__10 = -_x57
    _pd__11 = -_x48*_x52*_x53 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__12 = _x20*m - _x21*_x53
    d_c_P0__q_r_td = (_j_z_b_q_r__q_r_td*_pd__11 + _j_z_b_q_thd__q_r_td*_pd__12 + _pd__10*d_c_e_n__q_r_td
        + _pd__9*d_bottom_q_r__q_r_td + _x43*_x53*m*q_thd_td - _x58)
    d_c_P0__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__11 + _j_z_b_q_thd__q_rd_td*_pd__12 + _pd__10*d_c_e_n__q_rd_td
        + _pd__9*d_bottom_q_r__q_rd_td)
    d_c_P0__q_th_td = (_j_z_b_q_r__q_th_td*_pd__11 + _j_z_b_q_thd__q_th_td*_pd__12 + _pd__10*d_c_e_n__q_th_td
        + _pd__9*d_bottom_q_r__q_th_td)
    d_c_P0__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__11 + _j_z_b_q_thd__q_thd_td*_pd__12
        + _pd__10*d_c_e_n__q_thd_td + _pd__9*d_bottom_q_r__q_thd_td + _x25*_x53)
    d_c_P0__k_c = (_j_z_b_q_r__k*_pd__11 + _j_z_b_q_thd__k*_pd__12 + _pd__10*d_c_e_n__k_c
        + _pd__9*d_bottom_q_r__k_c)
    _x59 = m/math.sqrt(_x33)
    _x60 = (_x33 > 0.0)
    c_T0 = ((-_x10*_x59) if _x60 else (0.0))
    _pd__13 = ((-_x59) if _x60 else (0.0))
    _pd__14 = ((_x44*m/(_x33*math.sqrt(_x33))) if _x60 else (0.0))
    d_c_T0__q_r_td = _pd__13*d_c_e_n__q_r_td + _pd__14*d_c_rad_z__q_r_td
    d_c_T0__q_rd_td = _pd__13*d_c_e_n__q_rd_td + _pd__14*d_c_rad_z__q_rd_td
    d_c_T0__q_th_td = _pd__13*d_c_e_n__q_th_td + _pd__14*d_c_rad_z__q_th_td
    d_c_T0__q_thd_td = _pd__13*d_c_e_n__q_thd_td + _pd__14*d_c_rad_z__q_thd_td
    d_c_T0__k_c = _pd__13*d_c_e_n__k_c + _pd__14*d_c_rad_z__k_c
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__q_r_td, d_c_e_n__q_rd_td, d_c_e_n__q_th_td, d_c_e_n__q_thd_td,
        d_c_e_n__k_c, d_c_Q0__q_r_td, d_c_Q0__q_rd_td, d_c_Q0__q_th_td, d_c_Q0__q_thd_td, d_c_Q0__k_c,
        d_c_P0__q_r_td, d_c_P0__q_rd_td, d_c_P0__q_th_td, d_c_P0__q_thd_td, d_c_P0__k_c, d_c_T0__q_r_td,
        d_c_T0__q_rd_td, d_c_T0__q_th_td, d_c_T0__q_thd_td, d_c_T0__k_c, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__q_r_td, d_c_e__q_rd_td, d_c_e__q_th_td, d_c_e__q_thd_td, d_c_e__k_c,
            d_c_Q__q_r_td, d_c_Q__q_rd_td, d_c_Q__q_th_td, d_c_Q__q_thd_td, d_c_Q__k_c, d_c_P__q_r_td,
            d_c_P__q_rd_td, d_c_P__q_th_td, d_c_P__q_thd_td, d_c_P__k_c, d_c_T__q_r_td, d_c_T__q_rd_td,
            d_c_T__q_th_td, d_c_T__q_thd_td, d_c_T__k_c, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x61 = c_e + q_r_td
        c_x = _x61
        d_c_x__q_r_td = d_c_e__q_r_td + 1.0
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
        d_c_rad__q_r_td = (_pd__15*d_c_P__q_r_td + _pd__16*d_c_Q__q_r_td + _pd__17*d_c_x__q_r_td
            + _x72*d_E_ab__q_r_td)
        d_c_rad__q_rd_td = (_pd__15*d_c_P__q_rd_td + _pd__16*d_c_Q__q_rd_td + _pd__17*d_c_e__q_rd_td
            + _x72*d_E_ab__q_rd_td)
        d_c_rad__q_th_td = (_pd__15*d_c_P__q_th_td + _pd__16*d_c_Q__q_th_td + _pd__17*d_c_e__q_th_td
            + _x72*d_E_ab__q_th_td)
        d_c_rad__q_thd_td = (_pd__15*d_c_P__q_thd_td + _pd__16*d_c_Q__q_thd_td + _pd__17*d_c_e__q_thd_td
            + _x72*d_E_ab__q_thd_td)
        d_c_rad__k_c = (_pd__15*d_c_P__k_c + _pd__16*d_c_Q__k_c + _pd__17*d_c_e__k_c + _x63*(-_x64
            + 2.0*_x65*l0*m - _x67) + _x72*d_E_ab__k_c)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x73 = math.sqrt(c_rad)
        c_h = _x73
        _pd__18 = (0.5)/_x73
        d_c_h__q_r_td = _pd__18*d_c_rad__q_r_td
        d_c_h__q_rd_td = _pd__18*d_c_rad__q_rd_td
        d_c_h__q_th_td = _pd__18*d_c_rad__q_th_td
        d_c_h__q_thd_td = _pd__18*d_c_rad__q_thd_td
        d_c_h__k_c = _pd__18*d_c_rad__k_c
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x77 = (1.0/c_x)
            _x74 = _x77**2
            c_wq = _x74*c_e_next
            _pd__19 = _x74
            _pd__20 = -2.0*_x77**3*c_e_next
            _x75 = 4.0*_pd__19
            d_c_wq__q_r_td = _pd__20*d_c_x__q_r_td + _x75*d_c_e__q_r_td
            d_c_wq__q_rd_td = _pd__20*d_c_e__q_rd_td + _x75*d_c_e__q_rd_td
            d_c_wq__q_th_td = _pd__20*d_c_e__q_th_td + _x75*d_c_e__q_th_td
            d_c_wq__q_thd_td = _pd__20*d_c_e__q_thd_td + _x75*d_c_e__q_thd_td
            d_c_wq__k_c = _pd__20*d_c_e__k_c + _x75*d_c_e__k_c
            c_wp = c_e_next*c_x
            _x76 = 4.0*c_x
            d_c_wp__q_r_td = _x76*d_c_e__q_r_td + c_e_next*d_c_x__q_r_td
            d_c_wp__q_rd_td = _x76*d_c_e__q_rd_td + c_e_next*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x76*d_c_e__q_th_td + c_e_next*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x76*d_c_e__q_thd_td + c_e_next*d_c_e__q_thd_td
            d_c_wp__k_c = _x76*d_c_e__k_c + c_e_next*d_c_e__k_c
        elif variant == 1.0:
            _x78 = (1.0/q_r_td)
            _x79 = c_e_next + q_r_td
            _x80 = (1.0/_x79)
            c_wq = _x78*_x80*c_e_next
            _x81 = _x78*_x80**2*c_e_next
            _pd__21 = _x78*_x80 - _x81
            d_c_wq__q_r_td = 4.0*_pd__21*d_c_e__q_r_td - _x78**2*_x80*c_e_next - _x81
            _x82 = 4.0*_pd__21
            d_c_wq__q_rd_td = _x82*d_c_e__q_rd_td
            d_c_wq__q_th_td = _x82*d_c_e__q_th_td
            d_c_wq__q_thd_td = _x82*d_c_e__q_thd_td
            d_c_wq__k_c = _x82*d_c_e__k_c
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__22 = _x79
            _x83 = 4.0*_pd__22
            d_c_wp__q_r_td = _x83*d_c_e__q_r_td + c_e_next
            d_c_wp__q_rd_td = _x83*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x83*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x83*d_c_e__q_thd_td
            d_c_wp__k_c = _x83*d_c_e__k_c
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        c_e__next = c_e_next
        _x84 = (1.0/c_h)
        _x85 = _x84*c_wq
        c_Q__next = -_x85*c_P + q_th_td
        _pd__23 = -_x85
        _x86 = _x84**2
        _pd__24 = _x86*c_P*c_wq
        _pd__25 = -_x84*c_P
        d_c_Q__next__q_r_td = _pd__23*d_c_P__q_r_td + _pd__24*d_c_h__q_r_td + _pd__25*d_c_wq__q_r_td
        d_c_Q__next__q_rd_td = _pd__23*d_c_P__q_rd_td + _pd__24*d_c_h__q_rd_td + _pd__25*d_c_wq__q_rd_td
        d_c_Q__next__q_th_td = _pd__23*d_c_P__q_th_td + _pd__24*d_c_h__q_th_td + _pd__25*d_c_wq__q_th_td + 1.0
        d_c_Q__next__q_thd_td = _pd__23*d_c_P__q_thd_td + _pd__24*d_c_h__q_thd_td + _pd__25*d_c_wq__q_thd_td
        d_c_Q__next__k_c = _pd__23*d_c_P__k_c + _pd__24*d_c_h__k_c + _pd__25*d_c_wq__k_c
        _x87 = m*q_r_td**2
        _x88 = math.sin(c_Q)
        _x89 = m**2
        _x90 = _x84*_x89*g_s
        _x91 = _x88*_x90
        c_P__next = _x87*q_thd_td - _x91*c_wp
        _pd__26 = -_x90*c_wp*math.cos(c_Q)
        _pd__27 = _x86*_x88*_x89*c_wp*g_s
        _pd__28 = -_x91
        d_c_P__next__q_r_td = (_pd__26*d_c_Q__q_r_td + _pd__27*d_c_h__q_r_td + _pd__28*d_c_wp__q_r_td
            + 2.0*m*q_r_td*q_thd_td)
        d_c_P__next__q_rd_td = _pd__26*d_c_Q__q_rd_td + _pd__27*d_c_h__q_rd_td + _pd__28*d_c_wp__q_rd_td
        d_c_P__next__q_th_td = _pd__26*d_c_Q__q_th_td + _pd__27*d_c_h__q_th_td + _pd__28*d_c_wp__q_th_td
        d_c_P__next__q_thd_td = (_pd__26*d_c_Q__q_thd_td + _pd__27*d_c_h__q_thd_td + _pd__28*d_c_wp__q_thd_td
            + _x87)
        d_c_P__next__k_c = _pd__26*d_c_Q__k_c + _pd__27*d_c_h__k_c + _pd__28*d_c_wp__k_c
        _x92 = _x84*m
        c_T__next = -_x92*c_e_next
        _pd__29 = -_x92
        _pd__30 = _x86*c_e_next*m
        _x93 = 4.0*_pd__29
        d_c_T__next__q_r_td = _pd__30*d_c_h__q_r_td + _x93*d_c_e__q_r_td
        d_c_T__next__q_rd_td = _pd__30*d_c_h__q_rd_td + _x93*d_c_e__q_rd_td
        d_c_T__next__q_th_td = _pd__30*d_c_h__q_th_td + _x93*d_c_e__q_th_td
        d_c_T__next__q_thd_td = _pd__30*d_c_h__q_thd_td + _x93*d_c_e__q_thd_td
        d_c_T__next__k_c = _pd__30*d_c_h__k_c + _x93*d_c_e__k_c
        _n0_4 = 4.0*d_c_e__q_r_td
        _n0_5 = 4.0*d_c_e__q_rd_td
        _n0_6 = 4.0*d_c_e__q_th_td
        _n0_7 = 4.0*d_c_e__q_thd_td
        _n0_8 = 4.0*d_c_e__k_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8,
            d_c_Q__next__q_r_td, d_c_Q__next__q_rd_td, d_c_Q__next__q_th_td, d_c_Q__next__q_thd_td,
            d_c_Q__next__k_c, d_c_P__next__q_r_td, d_c_P__next__q_rd_td, d_c_P__next__q_th_td,
            d_c_P__next__q_thd_td, d_c_P__next__k_c, d_c_T__next__q_r_td, d_c_T__next__q_rd_td,
            d_c_T__next__q_th_td, d_c_T__next__q_thd_td, d_c_T__next__k_c, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    _x94 = (1.0/m)
    _x96 = (1.0/bottom_q_r)
    _x95 = _x94*_x96**2
    bottom_q_thd = _x95*c_P
    _pd__31 = -2.0*_x94*_x96**3*c_P
    _pd__32 = _x95
    d_bottom_q_thd__q_r_td = _pd__31*d_bottom_q_r__q_r_td + _pd__32*d_c_P__q_r_td
    d_bottom_q_thd__q_rd_td = _pd__31*d_bottom_q_r__q_rd_td + _pd__32*d_c_P__q_rd_td
    d_bottom_q_thd__q_th_td = _pd__31*d_bottom_q_r__q_th_td + _pd__32*d_c_P__q_th_td
    d_bottom_q_thd__q_thd_td = _pd__31*d_bottom_q_r__q_thd_td + _pd__32*d_c_P__q_thd_td
    d_bottom_q_thd__k_c = _pd__31*d_bottom_q_r__k_c + _pd__32*d_c_P__k_c
    # E_ba of (98): the energy jump of the stiffness switch
    _x97 = (-bottom_q_r + l0)**2
    _x98 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x97*_x98
    _pd__33 = _x98*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__q_r_td = _pd__33*d_bottom_q_r__q_r_td + d_E_ab__q_r_td
    d_E_ba__q_rd_td = _pd__33*d_bottom_q_r__q_rd_td + d_E_ab__q_rd_td
    d_E_ba__q_th_td = _pd__33*d_bottom_q_r__q_th_td + d_E_ab__q_th_td
    d_E_ba__q_thd_td = _pd__33*d_bottom_q_r__q_thd_td + d_E_ab__q_thd_td
    _x99 = (0.5)*_x97
    d_E_ba__k_c = _pd__33*d_bottom_q_r__k_c - _x99 + d_E_ab__k_c
    d_E_ba__k_d = _x99
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN70 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x100 = 4.0**(-iterations)
    _x101 = -bottom_q_r + q_r_lo
    _x102 = _x100*_x101
    d_e_n = _x102
    _pd__34 = -_x100
    d_d_e_n__q_r_td = _pd__34*d_bottom_q_r__q_r_td
    d_d_e_n__q_rd_td = _pd__34*d_bottom_q_r__q_rd_td
    d_d_e_n__q_th_td = _pd__34*d_bottom_q_r__q_th_td
    d_d_e_n__q_thd_td = _pd__34*d_bottom_q_r__q_thd_td
    d_d_e_n__k_c = _pd__34*d_bottom_q_r__k_c
    _x103 = (0.25)*_x102
    d_e_z = _x103
    _x104 = _x103 + bottom_q_r
    _x105 = _x104**2
    _x106 = (1.0/_x105)
    _x107 = _x104**4*m
    _x108 = _x104**3
    _x109 = l0**2*m
    _x110 = _x105*_x109
    _x111 = bottom_q_r**2*m
    _x112 = _x111*bottom_q_thd
    _x113 = q_r_lo**2
    _x114 = -_x112 + _x113*g_lo_q_thd*m
    _x115 = 4.0**((0.5)*iterations)
    _x116 = (1.0/_x115)
    _x117 = (0.5)*_x116
    _x118 = _x114*_x117
    _x119 = _x112 + _x118
    _x120 = -bottom_q_th + g_lo_q_th
    _x121 = _x117*_x120
    _x122 = _x121 + bottom_q_th
    _x123 = m**2
    _x124 = _x123*g_s
    _x125 = _x124*math.cos(_x122)
    _x126 = 2.0*E_ba*_x105*m - _x107*k_d - 2.0*_x108*_x125 + 2.0*_x108*k_d*l0*m - _x110*k_d - _x119**2
    _x127 = _x106*_x126
    d_rad_z = _x127
    _x128 = -2.0*_x126/_x108
    _x129 = 4.0*m
    _x130 = (1.0/_x101)
    _x131 = 2.0*bottom_q_r
    _x132 = _x131*bottom_q_thd*m
    _x133 = -_x116*_x132 + _x118*_x130
    _x134 = math.sin(_x122)
    _x135 = (0.5)*_x102
    _x136 = _x131 + _x135
    _x137 = -2.0*E_ba*_x136*m + 6.0*_x105*_x125 - 6.0*_x105*k_d*l0*m + _x108*_x129*k_d + _x109*_x136*k_d
    _pd__35 = (_x106*((0.5)*_x108*_x116*_x120*_x123*_x130*_x134*g_s - _x119*(_x129*bottom_q_r*bottom_q_thd
        + _x133) - _x137) + _x128)
    _x138 = _x104*_x124*_x134
    _pd__36 = 2.0*_x138*(1.0 - _x117)
    _x139 = -_x111*_x116
    _x140 = _x106*_x119
    _pd__37 = -_x140*(2.0*_x111 + _x139)
    _x141 = _x115*_x130
    _pd__38 = _x106*(2.0*_x108*_x115*_x120*_x123*_x130*_x134*g_s - 2.0*_x114*_x119*_x141 - _x137) + _x128
    _pd__39 = _x116*_x138
    _x142 = _x113*_x116*m
    _pd__40 = -_x140*_x142
    _x143 = (0.25)*_pd__38
    _x144 = 2.0*m
    d_d_rad_z__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__39 + _j_z_lo_q_thd__q_r_td*_pd__40
        + _pd__35*d_bottom_q_r__q_r_td + _pd__36*d_c_Q__q_r_td + _pd__37*d_bottom_q_thd__q_r_td
        + _x143*d_d_e_n__q_r_td + _x144*d_E_ba__q_r_td)
    d_d_rad_z__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__39 + _j_z_lo_q_thd__q_rd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_rd_td + _pd__36*d_c_Q__q_rd_td + _pd__37*d_bottom_q_thd__q_rd_td
        + _x143*d_d_e_n__q_rd_td + _x144*d_E_ba__q_rd_td)
    d_d_rad_z__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__39 + _j_z_lo_q_thd__q_th_td*_pd__40
        + _pd__35*d_bottom_q_r__q_th_td + _pd__36*d_c_Q__q_th_td + _pd__37*d_bottom_q_thd__q_th_td
        + _x143*d_d_e_n__q_th_td + _x144*d_E_ba__q_th_td)
    d_d_rad_z__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__39 + _j_z_lo_q_thd__q_thd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_thd_td + _pd__36*d_c_Q__q_thd_td + _pd__37*d_bottom_q_thd__q_thd_td
        + _x143*d_d_e_n__q_thd_td + _x144*d_E_ba__q_thd_td)
    d_d_rad_z__k_c = (_j_z_lo_q_th__k*_pd__39 + _j_z_lo_q_thd__k*_pd__40 + _pd__35*d_bottom_q_r__k_c
        + _pd__36*d_c_Q__k_c + _pd__37*d_bottom_q_thd__k_c + _x143*d_d_e_n__k_c + _x144*d_E_ba__k_c)
    d_d_rad_z__k_d = _x106*(-_x107 + 2.0*_x108*l0*m - _x110) + _x144*d_E_ba__k_d
    d_Q0 = _x116*_x120 + bottom_q_th
    _pd__41 = _x121*_x130
    _pd__42 = 1.0 - _x116
    _x145 = (0.5)*_x141
    _pd__43 = _x120*_x145
    _pd__44 = _x116
    d_d_Q0__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__44 + _pd__41*d_bottom_q_r__q_r_td + _pd__42*d_c_Q__q_r_td
        + _pd__43*d_d_e_n__q_r_td)
    d_d_Q0__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__44 + _pd__41*d_bottom_q_r__q_rd_td + _pd__42*d_c_Q__q_rd_td
        + _pd__43*d_d_e_n__q_rd_td)
    d_d_Q0__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__44 + _pd__41*d_bottom_q_r__q_th_td + _pd__42*d_c_Q__q_th_td
        + _pd__43*d_d_e_n__q_th_td)
    d_d_Q0__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__44 + _pd__41*d_bottom_q_r__q_thd_td
        + _pd__42*d_c_Q__q_thd_td + _pd__43*d_d_e_n__q_thd_td)
    d_d_Q0__k_c = (_j_z_lo_q_th__k*_pd__44 + _pd__41*d_bottom_q_r__k_c + _pd__42*d_c_Q__k_c
        + _pd__43*d_d_e_n__k_c)
    d_P0 = _x112 + _x114*_x116
    _pd__45 = _x132 + _x133
    _pd__46 = _x111 + _x139
    _pd__47 = _x114*_x145
    _pd__48 = _x142
    d_d_P0__q_r_td = (_j_z_lo_q_thd__q_r_td*_pd__48 + _pd__45*d_bottom_q_r__q_r_td
        + _pd__46*d_bottom_q_thd__q_r_td + _pd__47*d_d_e_n__q_r_td)
    d_d_P0__q_rd_td = (_j_z_lo_q_thd__q_rd_td*_pd__48 + _pd__45*d_bottom_q_r__q_rd_td
        + _pd__46*d_bottom_q_thd__q_rd_td + _pd__47*d_d_e_n__q_rd_td)
    d_d_P0__q_th_td = (_j_z_lo_q_thd__q_th_td*_pd__48 + _pd__45*d_bottom_q_r__q_th_td
        + _pd__46*d_bottom_q_thd__q_th_td + _pd__47*d_d_e_n__q_th_td)
    d_d_P0__q_thd_td = (_j_z_lo_q_thd__q_thd_td*_pd__48 + _pd__45*d_bottom_q_r__q_thd_td
        + _pd__46*d_bottom_q_thd__q_thd_td + _pd__47*d_d_e_n__q_thd_td)
    d_d_P0__k_c = (_j_z_lo_q_thd__k*_pd__48 + _pd__45*d_bottom_q_r__k_c + _pd__46*d_bottom_q_thd__k_c
        + _pd__47*d_d_e_n__k_c)
    _x146 = m/math.sqrt(_x127)
    _x147 = (_x127 > 0.0)
    d_T0 = ((_x102*_x146 + t_bottom) if _x147 else (t_bottom))
    _pd__49 = ((_x146) if _x147 else (0.0))
    _pd__50 = ((-_x135*m/(_x127*math.sqrt(_x127))) if _x147 else (0.0))
    d_d_T0__q_r_td = _pd__49*d_d_e_n__q_r_td + _pd__50*d_d_rad_z__q_r_td + d_c_T__q_r_td
    d_d_T0__q_rd_td = _pd__49*d_d_e_n__q_rd_td + _pd__50*d_d_rad_z__q_rd_td + d_c_T__q_rd_td
    d_d_T0__q_th_td = _pd__49*d_d_e_n__q_th_td + _pd__50*d_d_rad_z__q_th_td + d_c_T__q_th_td
    d_d_T0__q_thd_td = _pd__49*d_d_e_n__q_thd_td + _pd__50*d_d_rad_z__q_thd_td + d_c_T__q_thd_td
    d_d_T0__k_c = _pd__49*d_d_e_n__k_c + _pd__50*d_d_rad_z__k_c + d_c_T__k_c
    d_d_T0__k_d = _pd__50*d_d_rad_z__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki1 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__q_r_td, d_d_e_n__q_rd_td, d_d_e_n__q_th_td, d_d_e_n__q_thd_td,
        d_d_e_n__k_c, 0.0, d_d_Q0__q_r_td, d_d_Q0__q_rd_td, d_d_Q0__q_th_td, d_d_Q0__q_thd_td, d_d_Q0__k_c,
        0.0, d_d_P0__q_r_td, d_d_P0__q_rd_td, d_d_P0__q_th_td, d_d_P0__q_thd_td, d_d_P0__k_c, 0.0,
        d_d_T0__q_r_td, d_d_T0__q_rd_td, d_d_T0__q_th_td, d_d_T0__q_thd_td, d_d_T0__k_c, d_d_T0__k_d, )
    _pk1 = _pki1
    d_steps = 0.0
    _conv1 = False
    _last1 = max(int(iterations), 0)
    for _it1 in range(_last1 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__q_r_td, d_d_e__q_rd_td, d_d_e__q_th_td, d_d_e__q_thd_td, d_d_e__k_c,
            d_d_e__k_d, d_d_Q__q_r_td, d_d_Q__q_rd_td, d_d_Q__q_th_td, d_d_Q__q_thd_td, d_d_Q__k_c,
            d_d_Q__k_d, d_d_P__q_r_td, d_d_P__q_rd_td, d_d_P__q_th_td, d_d_P__q_thd_td, d_d_P__k_c,
            d_d_P__k_d, d_d_T__q_r_td, d_d_T__q_rd_td, d_d_T__q_th_td, d_d_T__q_thd_td, d_d_T__k_c,
            d_d_T__k_d, ) = _pk1
        if _conv1 or _it1 == _last1:
            break
        _x148 = bottom_q_r + d_e
        d_x = _x148
        d_d_x__q_r_td = d_bottom_q_r__q_r_td + d_d_e__q_r_td
        d_d_x__q_rd_td = d_bottom_q_r__q_rd_td + d_d_e__q_rd_td
        d_d_x__q_th_td = d_bottom_q_r__q_th_td + d_d_e__q_th_td
        d_d_x__q_thd_td = d_bottom_q_r__q_thd_td + d_d_e__q_thd_td
        d_d_x__k_c = d_bottom_q_r__k_c + d_d_e__k_c
        _x149 = _x148**2
        _x150 = (1.0/_x149)
        _x151 = _x148**4*m
        _x152 = _x148**3
        _x153 = l0**2
        _x154 = _x149*_x153*m
        _x155 = math.cos(d_Q)
        _x156 = m**2
        _x157 = 2.0*_x156*g_s
        _x158 = 2.0*E_ba*_x149*m - _x151*k_d - _x152*_x155*_x157 + 2.0*_x152*k_d*l0*m - _x154*k_d - d_P**2
        d_rad = _x150*_x158
        _pd__51 = -2.0*_x150*d_P
        _pd__52 = _x148*_x157*math.sin(d_Q)
        _x159 = 2.0*m
        _pd__53 = (_x150*(4.0*E_ba*_x148*m - _x148*_x153*_x159*k_d - 6.0*_x149*_x155*_x156*g_s
            + 6.0*_x149*k_d*l0*m - 4.0*_x152*k_d*m) - 2.0*_x158/_x152)
        d_d_rad__q_r_td = (_pd__51*d_d_P__q_r_td + _pd__52*d_d_Q__q_r_td + _pd__53*d_d_x__q_r_td
            + _x159*d_E_ba__q_r_td)
        d_d_rad__q_rd_td = (_pd__51*d_d_P__q_rd_td + _pd__52*d_d_Q__q_rd_td + _pd__53*d_d_x__q_rd_td
            + _x159*d_E_ba__q_rd_td)
        d_d_rad__q_th_td = (_pd__51*d_d_P__q_th_td + _pd__52*d_d_Q__q_th_td + _pd__53*d_d_x__q_th_td
            + _x159*d_E_ba__q_th_td)
        d_d_rad__q_thd_td = (_pd__51*d_d_P__q_thd_td + _pd__52*d_d_Q__q_thd_td + _pd__53*d_d_x__q_thd_td
            + _x159*d_E_ba__q_thd_td)
        d_d_rad__k_c = _pd__51*d_d_P__k_c + _pd__52*d_d_Q__k_c + _pd__53*d_d_x__k_c + _x159*d_E_ba__k_c
        d_d_rad__k_d = (_pd__51*d_d_P__k_d + _pd__52*d_d_Q__k_d + _pd__53*d_d_e__k_d + _x150*(-_x151
            + 2.0*_x152*l0*m - _x154) + _x159*d_E_ba__k_d)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x160 = math.sqrt(d_rad)
        d_h = _x160
        _pd__54 = (0.5)/_x160
        d_d_h__q_r_td = _pd__54*d_d_rad__q_r_td
        d_d_h__q_rd_td = _pd__54*d_d_rad__q_rd_td
        d_d_h__q_th_td = _pd__54*d_d_rad__q_th_td
        d_d_h__q_thd_td = _pd__54*d_d_rad__q_thd_td
        d_d_h__k_c = _pd__54*d_d_rad__k_c
        d_d_h__k_d = _pd__54*d_d_rad__k_d
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x164 = (1.0/d_x)
            _x161 = _x164**2
            d_wq = _x161*d_e_next
            _pd__55 = _x161
            _pd__56 = -2.0*_x164**3*d_e_next
            _x162 = 4.0*_pd__55
            d_d_wq__q_r_td = _pd__56*d_d_x__q_r_td + _x162*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__56*d_d_x__q_rd_td + _x162*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__56*d_d_x__q_th_td + _x162*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__56*d_d_x__q_thd_td + _x162*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__56*d_d_x__k_c + _x162*d_d_e__k_c
            d_d_wq__k_d = _pd__56*d_d_e__k_d + _x162*d_d_e__k_d
            d_wp = d_e_next*d_x
            _x163 = 4.0*d_x
            d_d_wp__q_r_td = _x163*d_d_e__q_r_td + d_d_x__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x163*d_d_e__q_rd_td + d_d_x__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x163*d_d_e__q_th_td + d_d_x__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x163*d_d_e__q_thd_td + d_d_x__q_thd_td*d_e_next
            d_d_wp__k_c = _x163*d_d_e__k_c + d_d_x__k_c*d_e_next
            d_d_wp__k_d = _x163*d_d_e__k_d + d_d_e__k_d*d_e_next
        elif variant == 1.0:
            _x165 = (1.0/bottom_q_r)
            _x166 = bottom_q_r + d_e_next
            _x167 = (1.0/_x166)
            d_wq = _x165*_x167*d_e_next
            _x168 = _x165*_x167**2*d_e_next
            _pd__57 = -_x165**2*_x167*d_e_next - _x168
            _pd__58 = _x165*_x167 - _x168
            _x169 = 4.0*_pd__58
            d_d_wq__q_r_td = _pd__57*d_bottom_q_r__q_r_td + _x169*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__57*d_bottom_q_r__q_rd_td + _x169*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__57*d_bottom_q_r__q_th_td + _x169*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__57*d_bottom_q_r__q_thd_td + _x169*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__57*d_bottom_q_r__k_c + _x169*d_d_e__k_c
            d_d_wq__k_d = _x169*d_d_e__k_d
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__59 = _x166
            _x170 = 4.0*_pd__59
            d_d_wp__q_r_td = _x170*d_d_e__q_r_td + d_bottom_q_r__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x170*d_d_e__q_rd_td + d_bottom_q_r__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x170*d_d_e__q_th_td + d_bottom_q_r__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x170*d_d_e__q_thd_td + d_bottom_q_r__q_thd_td*d_e_next
            d_d_wp__k_c = _x170*d_d_e__k_c + d_bottom_q_r__k_c*d_e_next
            d_d_wp__k_d = _x170*d_d_e__k_d
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        d_e__next = d_e_next
        _x171 = (1.0/d_h)
        _x172 = _x171*d_wq
        d_Q__next = _x172*d_P + bottom_q_th
        _pd__60 = _x172
        _x173 = _x171**2
        _pd__61 = -_x173*d_P*d_wq
        _pd__62 = _x171*d_P
        d_d_Q__next__q_r_td = (_pd__60*d_d_P__q_r_td + _pd__61*d_d_h__q_r_td + _pd__62*d_d_wq__q_r_td
            + d_c_Q__q_r_td)
        d_d_Q__next__q_rd_td = (_pd__60*d_d_P__q_rd_td + _pd__61*d_d_h__q_rd_td + _pd__62*d_d_wq__q_rd_td
            + d_c_Q__q_rd_td)
        d_d_Q__next__q_th_td = (_pd__60*d_d_P__q_th_td + _pd__61*d_d_h__q_th_td + _pd__62*d_d_wq__q_th_td
            + d_c_Q__q_th_td)
        d_d_Q__next__q_thd_td = (_pd__60*d_d_P__q_thd_td + _pd__61*d_d_h__q_thd_td + _pd__62*d_d_wq__q_thd_td
            + d_c_Q__q_thd_td)
        d_d_Q__next__k_c = _pd__60*d_d_P__k_c + _pd__61*d_d_h__k_c + _pd__62*d_d_wq__k_c + d_c_Q__k_c
        d_d_Q__next__k_d = _pd__60*d_d_P__k_d + _pd__61*d_d_h__k_d + _pd__62*d_d_wq__k_d
        _x174 = bottom_q_r**2*m
        _x175 = math.sin(d_Q)
        _x176 = m**2
        _x177 = _x171*_x176*g_s
        _x178 = _x175*_x177
        d_P__next = _x174*bottom_q_thd + _x178*d_wp
        _pd__63 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__64 = _x174
        _pd__65 = _x177*d_wp*math.cos(d_Q)
        _pd__66 = -_x173*_x175*_x176*d_wp*g_s
        _pd__67 = _x178
        d_d_P__next__q_r_td = (_pd__63*d_bottom_q_r__q_r_td + _pd__64*d_bottom_q_thd__q_r_td
            + _pd__65*d_d_Q__q_r_td + _pd__66*d_d_h__q_r_td + _pd__67*d_d_wp__q_r_td)
        d_d_P__next__q_rd_td = (_pd__63*d_bottom_q_r__q_rd_td + _pd__64*d_bottom_q_thd__q_rd_td
            + _pd__65*d_d_Q__q_rd_td + _pd__66*d_d_h__q_rd_td + _pd__67*d_d_wp__q_rd_td)
        d_d_P__next__q_th_td = (_pd__63*d_bottom_q_r__q_th_td + _pd__64*d_bottom_q_thd__q_th_td
            + _pd__65*d_d_Q__q_th_td + _pd__66*d_d_h__q_th_td + _pd__67*d_d_wp__q_th_td)
        d_d_P__next__q_thd_td = (_pd__63*d_bottom_q_r__q_thd_td + _pd__64*d_bottom_q_thd__q_thd_td
            + _pd__65*d_d_Q__q_thd_td + _pd__66*d_d_h__q_thd_td + _pd__67*d_d_wp__q_thd_td)
        d_d_P__next__k_c = (_pd__63*d_bottom_q_r__k_c + _pd__64*d_bottom_q_thd__k_c + _pd__65*d_d_Q__k_c
            + _pd__66*d_d_h__k_c + _pd__67*d_d_wp__k_c)
        d_d_P__next__k_d = _pd__65*d_d_Q__k_d + _pd__66*d_d_h__k_d + _pd__67*d_d_wp__k_d
        _x179 = _x171*m
        d_T__next = _x179*d_e_next + t_bottom
        _pd__68 = _x179
        _pd__69 = -_x173*d_e_next*m
        _x180 = 4.0*_pd__68
        d_d_T__next__q_r_td = _pd__69*d_d_h__q_r_td + _x180*d_d_e__q_r_td + d_c_T__q_r_td
        d_d_T__next__q_rd_td = _pd__69*d_d_h__q_rd_td + _x180*d_d_e__q_rd_td + d_c_T__q_rd_td
        d_d_T__next__q_th_td = _pd__69*d_d_h__q_th_td + _x180*d_d_e__q_th_td + d_c_T__q_th_td
        d_d_T__next__q_thd_td = _pd__69*d_d_h__q_thd_td + _x180*d_d_e__q_thd_td + d_c_T__q_thd_td
        d_d_T__next__k_c = _pd__69*d_d_h__k_c + _x180*d_d_e__k_c + d_c_T__k_c
        d_d_T__next__k_d = _pd__69*d_d_h__k_d + _x180*d_d_e__k_d
        _n1_4 = 4.0*d_d_e__q_r_td
        _n1_5 = 4.0*d_d_e__q_rd_td
        _n1_6 = 4.0*d_d_e__q_th_td
        _n1_7 = 4.0*d_d_e__q_thd_td
        _n1_8 = 4.0*d_d_e__k_c
        _n1_9 = 4.0*d_d_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn1 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n1_4, _n1_5, _n1_6, _n1_7, _n1_8, _n1_9,
            d_d_Q__next__q_r_td, d_d_Q__next__q_rd_td, d_d_Q__next__q_th_td, d_d_Q__next__q_thd_td,
            d_d_Q__next__k_c, d_d_Q__next__k_d, d_d_P__next__q_r_td, d_d_P__next__q_rd_td,
            d_d_P__next__q_th_td, d_d_P__next__q_thd_td, d_d_P__next__k_c, d_d_P__next__k_d,
            d_d_T__next__q_r_td, d_d_T__next__q_rd_td, d_d_T__next__q_th_td, d_d_T__next__q_thd_td,
            d_d_T__next__k_c, d_d_T__next__k_d, )
        _pk1 = _pkn1
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x181 = q_r_lo**2
    _x182 = (1.0/_x181)
    _x183 = m*q_r_lo**4
    _x184 = q_r_lo**3
    _x185 = _x181*l0**2*m
    _x186 = 2.0*g_s*m**2
    rad_lo = (_x182*(2.0*E_ba*_x181*m - _x183*k_d - _x184*_x186*math.cos(d_Q) + 2.0*_x184*k_d*l0*m - _x185*k_d
        - d_P**2))
    _pd__70 = -2.0*_x182*d_P
    _pd__71 = _x186*q_r_lo*math.sin(d_Q)
    _x187 = 2.0*m
    d_rad_lo__q_r_td = _pd__70*d_d_P__q_r_td + _pd__71*d_d_Q__q_r_td + _x187*d_E_ba__q_r_td
    d_rad_lo__q_rd_td = _pd__70*d_d_P__q_rd_td + _pd__71*d_d_Q__q_rd_td + _x187*d_E_ba__q_rd_td
    d_rad_lo__q_th_td = _pd__70*d_d_P__q_th_td + _pd__71*d_d_Q__q_th_td + _x187*d_E_ba__q_th_td
    d_rad_lo__q_thd_td = _pd__70*d_d_P__q_thd_td + _pd__71*d_d_Q__q_thd_td + _x187*d_E_ba__q_thd_td
    d_rad_lo__k_c = _pd__70*d_d_P__k_c + _pd__71*d_d_Q__k_c + _x187*d_E_ba__k_c
    d_rad_lo__k_d = (_pd__70*d_d_P__k_d + _pd__71*d_d_Q__k_d + _x182*(-_x183 + 2.0*_x184*l0*m - _x185)
        + _x187*d_E_ba__k_d)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x188 = (1.0/m)
    _x189 = math.sqrt(rad_lo)
    liftoff_q_rd = _x188*_x189
    _pd__72 = (0.5)*_x188/_x189
    d_liftoff_q_rd__q_r_td = _pd__72*d_rad_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _pd__72*d_rad_lo__q_rd_td
    d_liftoff_q_rd__q_th_td = _pd__72*d_rad_lo__q_th_td
    d_liftoff_q_rd__q_thd_td = _pd__72*d_rad_lo__q_thd_td
    d_liftoff_q_rd__k_c = _pd__72*d_rad_lo__k_c
    d_liftoff_q_rd__k_d = _pd__72*d_rad_lo__k_d
    liftoff_q_th = d_Q
    _x190 = _x188/q_r_lo**2
    liftoff_q_thd = _x190*d_P
    _pd__73 = _x190
    d_liftoff_q_thd__q_r_td = _pd__73*d_d_P__q_r_td
    d_liftoff_q_thd__q_rd_td = _pd__73*d_d_P__q_rd_td
    d_liftoff_q_thd__q_th_td = _pd__73*d_d_P__q_th_td
    d_liftoff_q_thd__q_thd_td = _pd__73*d_d_P__q_thd_td
    d_liftoff_q_thd__k_c = _pd__73*d_d_P__k_c
    d_liftoff_q_thd__k_d = _pd__73*d_d_P__k_d
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN70 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_c_T__q_r_td
    d_t_bottom__q_rd_td = d_c_T__q_rd_td
    d_t_bottom__q_th_td = d_c_T__q_th_td
    d_t_bottom__q_thd_td = d_c_T__q_thd_td
    d_t_bottom__k_c = d_c_T__k_c
    d_t_bottom__k_d = 0.0
    d_t_stance__q_r_td = d_d_T__q_r_td
    d_t_stance__q_rd_td = d_d_T__q_rd_td
    d_t_stance__q_th_td = d_d_T__q_th_td
    d_t_stance__q_thd_td = d_d_T__q_thd_td
    d_t_stance__k_c = d_d_T__k_c
    d_t_stance__k_d = d_d_T__k_d
    d_bottom_q_r__k_d = 0.0
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__q_r_td = d_c_Q__q_r_td
    d_bottom_q_th__q_rd_td = d_c_Q__q_rd_td
    d_bottom_q_th__q_th_td = d_c_Q__q_th_td
    d_bottom_q_th__q_thd_td = d_c_Q__q_thd_td
    d_bottom_q_th__k_c = d_c_Q__k_c
    d_bottom_q_th__k_d = 0.0
    d_bottom_q_thd__k_d = 0.0
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_th__q_r_td = d_d_Q__q_r_td
    d_liftoff_q_th__q_rd_td = d_d_Q__q_rd_td
    d_liftoff_q_th__q_th_td = d_d_Q__q_th_td
    d_liftoff_q_th__q_thd_td = d_d_Q__q_thd_td
    d_liftoff_q_th__k_c = d_d_Q__k_c
    d_liftoff_q_th__k_d = d_d_Q__k_d
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
def iterative_report_stance_jacobian_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian_zeroth_gravity_type5`: arguments, out
    and status as :func:`iterative_report_stance_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_jacobian_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
            and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f
            > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_jacobian_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0,
        k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # the code shared between choices
    return (iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m,
        l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian_zeroth_gravity_type5`: arguments,
    out and status as :func:`iterative_report_apex_return_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_jacobian_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i],
            q_th_td[i], ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations,
            bottom_length))
        store_row_12_84(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_stance_jacobian_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1620
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN70 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0,
        0.0, 100.0, 1e-12))
    if _c0[91] != STATUS_OK:
        return _NAN70 + (_c0[91],)
    (_, _, z_b_q_r, _, z_b_q_th, z_b_q_thd, _, _, z_lo_q_th, z_lo_q_thd, _, _, _, _, _, _, _, _, _, _, _, _,
        _, _, _, _j_z_b_q_r__q_r_td, _j_z_b_q_r__q_rd_td, _j_z_b_q_r__q_th_td, _j_z_b_q_r__q_thd_td,
        _j_z_b_q_r__k_c, _j_z_b_q_r__k_d, _, _, _, _, _, _, _j_z_b_q_th__q_r_td, _j_z_b_q_th__q_rd_td,
        _j_z_b_q_th__q_th_td, _j_z_b_q_th__q_thd_td, _j_z_b_q_th__k_c, _j_z_b_q_th__k_d, _j_z_b_q_thd__q_r_td,
        _j_z_b_q_thd__q_rd_td, _j_z_b_q_thd__q_th_td, _j_z_b_q_thd__q_thd_td, _j_z_b_q_thd__k_c,
        _j_z_b_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _j_z_lo_q_th__q_r_td, _j_z_lo_q_th__q_rd_td,
        _j_z_lo_q_th__q_th_td, _j_z_lo_q_th__q_thd_td, _j_z_lo_q_th__k_c, _j_z_lo_q_th__k_d,
        _j_z_lo_q_thd__q_r_td, _j_z_lo_q_thd__q_rd_td, _j_z_lo_q_thd__q_th_td, _j_z_lo_q_thd__q_thd_td,
        _j_z_lo_q_thd__k_c, _j_z_lo_q_thd__k_d, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _) = _c0
    # E_ab (114) of the touchdown state
    _x0 = k_c*q_r_td
    _x1 = (0.5)*l0**2
    _x2 = q_r_td**2
    _x3 = (0.5)*_x2
    _x4 = g_s*m
    _x5 = _x4*math.cos(q_th_td)
    _x6 = m*q_thd_td**2
    E_ab = -_x0*l0 + _x1*k_c + _x3*_x6 + _x3*k_c + _x5*q_r_td + (0.5)*m*q_rd_td**2
    d_E_ab__q_r_td = _x0 + _x5 + _x6*q_r_td - k_c*l0
    d_E_ab__q_rd_td = m*q_rd_td
    d_E_ab__q_th_td = -_x4*q_r_td*math.sin(q_th_td)
    d_E_ab__q_thd_td = _x2*m*q_thd_td
    d_E_ab__k_c = _x1 + _x3 - l0*q_r_td
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
        # tangents as every branch names them
        d_bottom_q_r__q_r_td = _j_z_b_q_r__q_r_td
        d_bottom_q_r__q_rd_td = _j_z_b_q_r__q_rd_td
        d_bottom_q_r__q_th_td = _j_z_b_q_r__q_th_td
        d_bottom_q_r__q_thd_td = _j_z_b_q_r__q_thd_td
        d_bottom_q_r__k_c = _j_z_b_q_r__k_c
        d_bottom_q_r__k_d = _j_z_b_q_r__k_d
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic_jac_p_E_ab_k_c(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[4] != STATUS_OK:
            return _NAN70 + (_c1[4],)
        bottom_q_r = _c1[0]
        _j_bottom_q_r__p = _c1[1]
        _j_bottom_q_r__E_ab = _c1[2]
        _j_bottom_q_r__k_c = _c1[3]
        # chain rule through bottom_quartic
        _x7 = _j_bottom_q_r__p*m
        d_bottom_q_r__q_r_td = _j_bottom_q_r__E_ab*d_E_ab__q_r_td + 2.0*_x7*q_r_td*q_thd_td
        d_bottom_q_r__q_rd_td = _j_bottom_q_r__E_ab*d_E_ab__q_rd_td
        d_bottom_q_r__q_th_td = _j_bottom_q_r__E_ab*d_E_ab__q_th_td
        d_bottom_q_r__q_thd_td = _j_bottom_q_r__E_ab*d_E_ab__q_thd_td + _x7*q_r_td**2
        d_bottom_q_r__k_c = _j_bottom_q_r__E_ab*d_E_ab__k_c + _j_bottom_q_r__k_c
        # tangents as every branch names them
        d_bottom_q_r__k_d = 0.0
    else:
        return _NAN70 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN70 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN70 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = bottom_q_r - q_r_td
    _x10 = _x8*_x9
    c_e_n = _x10
    _pd__0 = _x8
    _x11 = -_x8
    d_c_e_n__q_r_td = _pd__0*d_bottom_q_r__q_r_td + _x11
    d_c_e_n__q_rd_td = _pd__0*d_bottom_q_r__q_rd_td
    d_c_e_n__q_th_td = _pd__0*d_bottom_q_r__q_th_td
    d_c_e_n__q_thd_td = _pd__0*d_bottom_q_r__q_thd_td
    d_c_e_n__k_c = _pd__0*d_bottom_q_r__k_c
    d_c_e_n__k_d = _pd__0*d_bottom_q_r__k_d
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
    d_c_rad_z__q_r_td = (_j_z_b_q_r__q_r_td*_pd__3 + _j_z_b_q_th__q_r_td*_pd__4 + _j_z_b_q_thd__q_r_td*_pd__5
        + _pd__1*d_bottom_q_r__q_r_td + _x15*(-_x27*(-_x23*_x41 + _x24*_x46*q_r_td*q_thd_td) - _x39 - _x47)
        + _x42 + _x51*d_c_e_n__q_r_td + _x52*d_E_ab__q_r_td)
    d_c_rad_z__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__3 + _j_z_b_q_th__q_rd_td*_pd__4
        + _j_z_b_q_thd__q_rd_td*_pd__5 + _pd__1*d_bottom_q_r__q_rd_td + _x51*d_c_e_n__q_rd_td
        + _x52*d_E_ab__q_rd_td)
    d_c_rad_z__q_th_td = (_j_z_b_q_r__q_th_td*_pd__3 + _j_z_b_q_th__q_th_td*_pd__4
        + _j_z_b_q_thd__q_th_td*_pd__5 + _pd__1*d_bottom_q_r__q_th_td + _x24*_x50 + _x51*d_c_e_n__q_th_td
        + _x52*d_E_ab__q_th_td)
    d_c_rad_z__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__3 + _j_z_b_q_th__q_thd_td*_pd__4
        + _j_z_b_q_thd__q_thd_td*_pd__5 + _pd__1*d_bottom_q_r__q_thd_td - 2.0*_x24*_x25*_x49
        + _x51*d_c_e_n__q_thd_td + _x52*d_E_ab__q_thd_td)
    d_c_rad_z__k_c = (_j_z_b_q_r__k_c*_pd__3 + _j_z_b_q_th__k_c*_pd__4 + _j_z_b_q_thd__k_c*_pd__5
        + _pd__1*d_bottom_q_r__k_c + _x15*(-_x16 + 2.0*_x17*l0*m - _x19) + _x51*d_c_e_n__k_c
        + _x52*d_E_ab__k_c)
    d_c_rad_z__k_d = (_j_z_b_q_r__k_d*_pd__3 + _j_z_b_q_th__k_d*_pd__4 + _j_z_b_q_thd__k_d*_pd__5
        + _pd__1*d_bottom_q_r__k_d + _x51*d_c_e_n__k_d)
    _x53 = math.sqrt(_x11 + 1.0)
    c_Q0 = _x29*_x53 + z_b_q_th
    _x54 = (0.5)/_x53
    _x55 = _x36*_x54
    _x56 = _x55*_x8
    _pd__6 = _x56
    _pd__7 = -_x55
    _pd__8 = 1.0 - _x53
    d_c_Q0__q_r_td = _j_z_b_q_th__q_r_td*_pd__8 + _pd__6*d_bottom_q_r__q_r_td + _pd__7*d_c_e_n__q_r_td - _x56
    d_c_Q0__q_rd_td = _j_z_b_q_th__q_rd_td*_pd__8 + _pd__6*d_bottom_q_r__q_rd_td + _pd__7*d_c_e_n__q_rd_td
    d_c_Q0__q_th_td = (_j_z_b_q_th__q_th_td*_pd__8 + _pd__6*d_bottom_q_r__q_th_td + _pd__7*d_c_e_n__q_th_td
        + _x53)
    d_c_Q0__q_thd_td = _j_z_b_q_th__q_thd_td*_pd__8 + _pd__6*d_bottom_q_r__q_thd_td + _pd__7*d_c_e_n__q_thd_td
    d_c_Q0__k_c = _j_z_b_q_th__k_c*_pd__8 + _pd__6*d_bottom_q_r__k_c + _pd__7*d_c_e_n__k_c
    d_c_Q0__k_d = _j_z_b_q_th__k_d*_pd__8 + _pd__6*d_bottom_q_r__k_d + _pd__7*d_c_e_n__k_d
    c_P0 = _x22 + _x26*_x53
    _x57 = _x40*_x54
    _x58 = _x57*_x8
    _pd__9 = _x58
    _pd__10 = -_x57
    _pd__11 = -_x48*_x52*_x53 + 2.0*m*z_b_q_r*z_b_q_thd
    _pd__12 = _x20*m - _x21*_x53
    d_c_P0__q_r_td = (_j_z_b_q_r__q_r_td*_pd__11 + _j_z_b_q_thd__q_r_td*_pd__12 + _pd__10*d_c_e_n__q_r_td
        + _pd__9*d_bottom_q_r__q_r_td + _x43*_x53*m*q_thd_td - _x58)
    d_c_P0__q_rd_td = (_j_z_b_q_r__q_rd_td*_pd__11 + _j_z_b_q_thd__q_rd_td*_pd__12 + _pd__10*d_c_e_n__q_rd_td
        + _pd__9*d_bottom_q_r__q_rd_td)
    d_c_P0__q_th_td = (_j_z_b_q_r__q_th_td*_pd__11 + _j_z_b_q_thd__q_th_td*_pd__12 + _pd__10*d_c_e_n__q_th_td
        + _pd__9*d_bottom_q_r__q_th_td)
    d_c_P0__q_thd_td = (_j_z_b_q_r__q_thd_td*_pd__11 + _j_z_b_q_thd__q_thd_td*_pd__12
        + _pd__10*d_c_e_n__q_thd_td + _pd__9*d_bottom_q_r__q_thd_td + _x25*_x53)
    d_c_P0__k_c = (_j_z_b_q_r__k_c*_pd__11 + _j_z_b_q_thd__k_c*_pd__12 + _pd__10*d_c_e_n__k_c
        + _pd__9*d_bottom_q_r__k_c)
    d_c_P0__k_d = (_j_z_b_q_r__k_d*_pd__11 + _j_z_b_q_thd__k_d*_pd__12 + _pd__10*d_c_e_n__k_d
        + _pd__9*d_bottom_q_r__k_d)
    _x59 = m/math.sqrt(_x33)
    _x60 = (_x33 > 0.0)
    c_T0 = ((-_x10*_x59) if _x60 else (0.0))
    _pd__13 = ((-_x59) if _x60 else (0.0))
    _pd__14 = ((_x44*m/(_x33*math.sqrt(_x33))) if _x60 else (0.0))
    d_c_T0__q_r_td = _pd__13*d_c_e_n__q_r_td + _pd__14*d_c_rad_z__q_r_td
    d_c_T0__q_rd_td = _pd__13*d_c_e_n__q_rd_td + _pd__14*d_c_rad_z__q_rd_td
    d_c_T0__q_th_td = _pd__13*d_c_e_n__q_th_td + _pd__14*d_c_rad_z__q_th_td
    d_c_T0__q_thd_td = _pd__13*d_c_e_n__q_thd_td + _pd__14*d_c_rad_z__q_thd_td
    d_c_T0__k_c = _pd__13*d_c_e_n__k_c + _pd__14*d_c_rad_z__k_c
    d_c_T0__k_d = _pd__13*d_c_e_n__k_d + _pd__14*d_c_rad_z__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (c_e_n, c_Q0, c_P0, c_T0, d_c_e_n__q_r_td, d_c_e_n__q_rd_td, d_c_e_n__q_th_td, d_c_e_n__q_thd_td,
        d_c_e_n__k_c, d_c_e_n__k_d, d_c_Q0__q_r_td, d_c_Q0__q_rd_td, d_c_Q0__q_th_td, d_c_Q0__q_thd_td,
        d_c_Q0__k_c, d_c_Q0__k_d, d_c_P0__q_r_td, d_c_P0__q_rd_td, d_c_P0__q_th_td, d_c_P0__q_thd_td,
        d_c_P0__k_c, d_c_P0__k_d, d_c_T0__q_r_td, d_c_T0__q_rd_td, d_c_T0__q_th_td, d_c_T0__q_thd_td,
        d_c_T0__k_c, d_c_T0__k_d, )
    _pk0 = _pki0
    c_steps = 0.0
    _conv0 = False
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        (c_e, c_Q, c_P, c_T, d_c_e__q_r_td, d_c_e__q_rd_td, d_c_e__q_th_td, d_c_e__q_thd_td, d_c_e__k_c,
            d_c_e__k_d, d_c_Q__q_r_td, d_c_Q__q_rd_td, d_c_Q__q_th_td, d_c_Q__q_thd_td, d_c_Q__k_c,
            d_c_Q__k_d, d_c_P__q_r_td, d_c_P__q_rd_td, d_c_P__q_th_td, d_c_P__q_thd_td, d_c_P__k_c,
            d_c_P__k_d, d_c_T__q_r_td, d_c_T__q_rd_td, d_c_T__q_th_td, d_c_T__q_thd_td, d_c_T__k_c,
            d_c_T__k_d, ) = _pk0
        if _conv0 or _it0 == _last0:
            break
        _x61 = c_e + q_r_td
        c_x = _x61
        d_c_x__q_r_td = d_c_e__q_r_td + 1.0
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
        d_c_rad__q_r_td = (_pd__15*d_c_P__q_r_td + _pd__16*d_c_Q__q_r_td + _pd__17*d_c_x__q_r_td
            + _x72*d_E_ab__q_r_td)
        d_c_rad__q_rd_td = (_pd__15*d_c_P__q_rd_td + _pd__16*d_c_Q__q_rd_td + _pd__17*d_c_e__q_rd_td
            + _x72*d_E_ab__q_rd_td)
        d_c_rad__q_th_td = (_pd__15*d_c_P__q_th_td + _pd__16*d_c_Q__q_th_td + _pd__17*d_c_e__q_th_td
            + _x72*d_E_ab__q_th_td)
        d_c_rad__q_thd_td = (_pd__15*d_c_P__q_thd_td + _pd__16*d_c_Q__q_thd_td + _pd__17*d_c_e__q_thd_td
            + _x72*d_E_ab__q_thd_td)
        d_c_rad__k_c = (_pd__15*d_c_P__k_c + _pd__16*d_c_Q__k_c + _pd__17*d_c_e__k_c + _x63*(-_x64
            + 2.0*_x65*l0*m - _x67) + _x72*d_E_ab__k_c)
        d_c_rad__k_d = _pd__15*d_c_P__k_d + _pd__16*d_c_Q__k_d + _pd__17*d_c_e__k_d
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x73 = math.sqrt(c_rad)
        c_h = _x73
        _pd__18 = (0.5)/_x73
        d_c_h__q_r_td = _pd__18*d_c_rad__q_r_td
        d_c_h__q_rd_td = _pd__18*d_c_rad__q_rd_td
        d_c_h__q_th_td = _pd__18*d_c_rad__q_th_td
        d_c_h__q_thd_td = _pd__18*d_c_rad__q_thd_td
        d_c_h__k_c = _pd__18*d_c_rad__k_c
        d_c_h__k_d = _pd__18*d_c_rad__k_d
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x77 = (1.0/c_x)
            _x74 = _x77**2
            c_wq = _x74*c_e_next
            _pd__19 = _x74
            _pd__20 = -2.0*_x77**3*c_e_next
            _x75 = 4.0*_pd__19
            d_c_wq__q_r_td = _pd__20*d_c_x__q_r_td + _x75*d_c_e__q_r_td
            d_c_wq__q_rd_td = _pd__20*d_c_e__q_rd_td + _x75*d_c_e__q_rd_td
            d_c_wq__q_th_td = _pd__20*d_c_e__q_th_td + _x75*d_c_e__q_th_td
            d_c_wq__q_thd_td = _pd__20*d_c_e__q_thd_td + _x75*d_c_e__q_thd_td
            d_c_wq__k_c = _pd__20*d_c_e__k_c + _x75*d_c_e__k_c
            d_c_wq__k_d = _pd__20*d_c_e__k_d + _x75*d_c_e__k_d
            c_wp = c_e_next*c_x
            _x76 = 4.0*c_x
            d_c_wp__q_r_td = _x76*d_c_e__q_r_td + c_e_next*d_c_x__q_r_td
            d_c_wp__q_rd_td = _x76*d_c_e__q_rd_td + c_e_next*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x76*d_c_e__q_th_td + c_e_next*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x76*d_c_e__q_thd_td + c_e_next*d_c_e__q_thd_td
            d_c_wp__k_c = _x76*d_c_e__k_c + c_e_next*d_c_e__k_c
            d_c_wp__k_d = _x76*d_c_e__k_d + c_e_next*d_c_e__k_d
        elif variant == 1.0:
            _x78 = (1.0/q_r_td)
            _x79 = c_e_next + q_r_td
            _x80 = (1.0/_x79)
            c_wq = _x78*_x80*c_e_next
            _x81 = _x78*_x80**2*c_e_next
            _pd__21 = _x78*_x80 - _x81
            d_c_wq__q_r_td = 4.0*_pd__21*d_c_e__q_r_td - _x78**2*_x80*c_e_next - _x81
            _x82 = 4.0*_pd__21
            d_c_wq__q_rd_td = _x82*d_c_e__q_rd_td
            d_c_wq__q_th_td = _x82*d_c_e__q_th_td
            d_c_wq__q_thd_td = _x82*d_c_e__q_thd_td
            d_c_wq__k_c = _x82*d_c_e__k_c
            d_c_wq__k_d = _x82*d_c_e__k_d
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
            _pd__22 = _x79
            _x83 = 4.0*_pd__22
            d_c_wp__q_r_td = _x83*d_c_e__q_r_td + c_e_next
            d_c_wp__q_rd_td = _x83*d_c_e__q_rd_td
            d_c_wp__q_th_td = _x83*d_c_e__q_th_td
            d_c_wp__q_thd_td = _x83*d_c_e__q_thd_td
            d_c_wp__k_c = _x83*d_c_e__k_c
            d_c_wp__k_d = _x83*d_c_e__k_d
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        c_e__next = c_e_next
        _x84 = (1.0/c_h)
        _x85 = _x84*c_wq
        c_Q__next = -_x85*c_P + q_th_td
        _pd__23 = -_x85
        _x86 = _x84**2
        _pd__24 = _x86*c_P*c_wq
        _pd__25 = -_x84*c_P
        d_c_Q__next__q_r_td = _pd__23*d_c_P__q_r_td + _pd__24*d_c_h__q_r_td + _pd__25*d_c_wq__q_r_td
        d_c_Q__next__q_rd_td = _pd__23*d_c_P__q_rd_td + _pd__24*d_c_h__q_rd_td + _pd__25*d_c_wq__q_rd_td
        d_c_Q__next__q_th_td = _pd__23*d_c_P__q_th_td + _pd__24*d_c_h__q_th_td + _pd__25*d_c_wq__q_th_td + 1.0
        d_c_Q__next__q_thd_td = _pd__23*d_c_P__q_thd_td + _pd__24*d_c_h__q_thd_td + _pd__25*d_c_wq__q_thd_td
        d_c_Q__next__k_c = _pd__23*d_c_P__k_c + _pd__24*d_c_h__k_c + _pd__25*d_c_wq__k_c
        d_c_Q__next__k_d = _pd__23*d_c_P__k_d + _pd__24*d_c_h__k_d + _pd__25*d_c_wq__k_d
        _x87 = m*q_r_td**2
        _x88 = math.sin(c_Q)
        _x89 = m**2
        _x90 = _x84*_x89*g_s
        _x91 = _x88*_x90
        c_P__next = _x87*q_thd_td - _x91*c_wp
        _pd__26 = -_x90*c_wp*math.cos(c_Q)
        _pd__27 = _x86*_x88*_x89*c_wp*g_s
        _pd__28 = -_x91
        d_c_P__next__q_r_td = (_pd__26*d_c_Q__q_r_td + _pd__27*d_c_h__q_r_td + _pd__28*d_c_wp__q_r_td
            + 2.0*m*q_r_td*q_thd_td)
        d_c_P__next__q_rd_td = _pd__26*d_c_Q__q_rd_td + _pd__27*d_c_h__q_rd_td + _pd__28*d_c_wp__q_rd_td
        d_c_P__next__q_th_td = _pd__26*d_c_Q__q_th_td + _pd__27*d_c_h__q_th_td + _pd__28*d_c_wp__q_th_td
        d_c_P__next__q_thd_td = (_pd__26*d_c_Q__q_thd_td + _pd__27*d_c_h__q_thd_td + _pd__28*d_c_wp__q_thd_td
            + _x87)
        d_c_P__next__k_c = _pd__26*d_c_Q__k_c + _pd__27*d_c_h__k_c + _pd__28*d_c_wp__k_c
        d_c_P__next__k_d = _pd__26*d_c_Q__k_d + _pd__27*d_c_h__k_d + _pd__28*d_c_wp__k_d
        _x92 = _x84*m
        c_T__next = -_x92*c_e_next
        _pd__29 = -_x92
        _pd__30 = _x86*c_e_next*m
        _x93 = 4.0*_pd__29
        d_c_T__next__q_r_td = _pd__30*d_c_h__q_r_td + _x93*d_c_e__q_r_td
        d_c_T__next__q_rd_td = _pd__30*d_c_h__q_rd_td + _x93*d_c_e__q_rd_td
        d_c_T__next__q_th_td = _pd__30*d_c_h__q_th_td + _x93*d_c_e__q_th_td
        d_c_T__next__q_thd_td = _pd__30*d_c_h__q_thd_td + _x93*d_c_e__q_thd_td
        d_c_T__next__k_c = _pd__30*d_c_h__k_c + _x93*d_c_e__k_c
        d_c_T__next__k_d = _pd__30*d_c_h__k_d + _x93*d_c_e__k_d
        _n0_4 = 4.0*d_c_e__q_r_td
        _n0_5 = 4.0*d_c_e__q_rd_td
        _n0_6 = 4.0*d_c_e__q_th_td
        _n0_7 = 4.0*d_c_e__q_thd_td
        _n0_8 = 4.0*d_c_e__k_c
        _n0_9 = 4.0*d_c_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(c_e__next - c_e) <= 0.0*(l0)) and (abs(c_Q__next - c_Q) <= 0.0*(1.0))
            and (abs(c_P__next - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(c_T__next - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn0 = (c_e__next, c_Q__next, c_P__next, c_T__next, _n0_4, _n0_5, _n0_6, _n0_7, _n0_8, _n0_9,
            d_c_Q__next__q_r_td, d_c_Q__next__q_rd_td, d_c_Q__next__q_th_td, d_c_Q__next__q_thd_td,
            d_c_Q__next__k_c, d_c_Q__next__k_d, d_c_P__next__q_r_td, d_c_P__next__q_rd_td,
            d_c_P__next__q_th_td, d_c_P__next__q_thd_td, d_c_P__next__k_c, d_c_P__next__k_d,
            d_c_T__next__q_r_td, d_c_T__next__q_rd_td, d_c_T__next__q_th_td, d_c_T__next__q_thd_td,
            d_c_T__next__k_c, d_c_T__next__k_d, )
        _pk0 = _pkn0
        c_steps += 1.0
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    _x94 = (1.0/m)
    _x96 = (1.0/bottom_q_r)
    _x95 = _x94*_x96**2
    bottom_q_thd = _x95*c_P
    _pd__31 = -2.0*_x94*_x96**3*c_P
    _pd__32 = _x95
    d_bottom_q_thd__q_r_td = _pd__31*d_bottom_q_r__q_r_td + _pd__32*d_c_P__q_r_td
    d_bottom_q_thd__q_rd_td = _pd__31*d_bottom_q_r__q_rd_td + _pd__32*d_c_P__q_rd_td
    d_bottom_q_thd__q_th_td = _pd__31*d_bottom_q_r__q_th_td + _pd__32*d_c_P__q_th_td
    d_bottom_q_thd__q_thd_td = _pd__31*d_bottom_q_r__q_thd_td + _pd__32*d_c_P__q_thd_td
    d_bottom_q_thd__k_c = _pd__31*d_bottom_q_r__k_c + _pd__32*d_c_P__k_c
    d_bottom_q_thd__k_d = _pd__31*d_bottom_q_r__k_d + _pd__32*d_c_P__k_d
    # E_ba of (98): the energy jump of the stiffness switch
    _x97 = (-bottom_q_r + l0)**2
    _x98 = -0.5*k_c + (0.5)*k_d
    E_ba = E_ab + _x97*_x98
    _pd__33 = _x98*(2.0*bottom_q_r - 2.0*l0)
    d_E_ba__q_r_td = _pd__33*d_bottom_q_r__q_r_td + d_E_ab__q_r_td
    d_E_ba__q_rd_td = _pd__33*d_bottom_q_r__q_rd_td + d_E_ab__q_rd_td
    d_E_ba__q_th_td = _pd__33*d_bottom_q_r__q_th_td + d_E_ab__q_th_td
    d_E_ba__q_thd_td = _pd__33*d_bottom_q_r__q_thd_td + d_E_ab__q_thd_td
    _x99 = (0.5)*_x97
    d_E_ba__k_c = _pd__33*d_bottom_q_r__k_c - _x99 + d_E_ab__k_c
    d_E_ba__k_d = _pd__33*d_bottom_q_r__k_d + _x99
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN70 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x100 = 4.0**(-iterations)
    _x101 = -bottom_q_r + q_r_lo
    _x102 = _x100*_x101
    d_e_n = _x102
    _pd__34 = -_x100
    d_d_e_n__q_r_td = _pd__34*d_bottom_q_r__q_r_td
    d_d_e_n__q_rd_td = _pd__34*d_bottom_q_r__q_rd_td
    d_d_e_n__q_th_td = _pd__34*d_bottom_q_r__q_th_td
    d_d_e_n__q_thd_td = _pd__34*d_bottom_q_r__q_thd_td
    d_d_e_n__k_c = _pd__34*d_bottom_q_r__k_c
    d_d_e_n__k_d = _pd__34*d_bottom_q_r__k_d
    _x103 = (0.25)*_x102
    d_e_z = _x103
    _x104 = _x103 + bottom_q_r
    _x105 = _x104**2
    _x106 = (1.0/_x105)
    _x107 = _x104**4*m
    _x108 = _x104**3
    _x109 = l0**2*m
    _x110 = _x105*_x109
    _x111 = bottom_q_r**2*m
    _x112 = _x111*bottom_q_thd
    _x113 = q_r_lo**2
    _x114 = -_x112 + _x113*g_lo_q_thd*m
    _x115 = 4.0**((0.5)*iterations)
    _x116 = (1.0/_x115)
    _x117 = (0.5)*_x116
    _x118 = _x114*_x117
    _x119 = _x112 + _x118
    _x120 = -bottom_q_th + g_lo_q_th
    _x121 = _x117*_x120
    _x122 = _x121 + bottom_q_th
    _x123 = m**2
    _x124 = _x123*g_s
    _x125 = _x124*math.cos(_x122)
    _x126 = 2.0*E_ba*_x105*m - _x107*k_d - 2.0*_x108*_x125 + 2.0*_x108*k_d*l0*m - _x110*k_d - _x119**2
    _x127 = _x106*_x126
    d_rad_z = _x127
    _x128 = -2.0*_x126/_x108
    _x129 = 4.0*m
    _x130 = (1.0/_x101)
    _x131 = 2.0*bottom_q_r
    _x132 = _x131*bottom_q_thd*m
    _x133 = -_x116*_x132 + _x118*_x130
    _x134 = math.sin(_x122)
    _x135 = (0.5)*_x102
    _x136 = _x131 + _x135
    _x137 = -2.0*E_ba*_x136*m + 6.0*_x105*_x125 - 6.0*_x105*k_d*l0*m + _x108*_x129*k_d + _x109*_x136*k_d
    _pd__35 = (_x106*((0.5)*_x108*_x116*_x120*_x123*_x130*_x134*g_s - _x119*(_x129*bottom_q_r*bottom_q_thd
        + _x133) - _x137) + _x128)
    _x138 = _x104*_x124*_x134
    _pd__36 = 2.0*_x138*(1.0 - _x117)
    _x139 = -_x111*_x116
    _x140 = _x106*_x119
    _pd__37 = -_x140*(2.0*_x111 + _x139)
    _x141 = _x115*_x130
    _pd__38 = _x106*(2.0*_x108*_x115*_x120*_x123*_x130*_x134*g_s - 2.0*_x114*_x119*_x141 - _x137) + _x128
    _pd__39 = _x116*_x138
    _x142 = _x113*_x116*m
    _pd__40 = -_x140*_x142
    _x143 = (0.25)*_pd__38
    _x144 = 2.0*m
    d_d_rad_z__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__39 + _j_z_lo_q_thd__q_r_td*_pd__40
        + _pd__35*d_bottom_q_r__q_r_td + _pd__36*d_c_Q__q_r_td + _pd__37*d_bottom_q_thd__q_r_td
        + _x143*d_d_e_n__q_r_td + _x144*d_E_ba__q_r_td)
    d_d_rad_z__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__39 + _j_z_lo_q_thd__q_rd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_rd_td + _pd__36*d_c_Q__q_rd_td + _pd__37*d_bottom_q_thd__q_rd_td
        + _x143*d_d_e_n__q_rd_td + _x144*d_E_ba__q_rd_td)
    d_d_rad_z__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__39 + _j_z_lo_q_thd__q_th_td*_pd__40
        + _pd__35*d_bottom_q_r__q_th_td + _pd__36*d_c_Q__q_th_td + _pd__37*d_bottom_q_thd__q_th_td
        + _x143*d_d_e_n__q_th_td + _x144*d_E_ba__q_th_td)
    d_d_rad_z__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__39 + _j_z_lo_q_thd__q_thd_td*_pd__40
        + _pd__35*d_bottom_q_r__q_thd_td + _pd__36*d_c_Q__q_thd_td + _pd__37*d_bottom_q_thd__q_thd_td
        + _x143*d_d_e_n__q_thd_td + _x144*d_E_ba__q_thd_td)
    d_d_rad_z__k_c = (_j_z_lo_q_th__k_c*_pd__39 + _j_z_lo_q_thd__k_c*_pd__40 + _pd__35*d_bottom_q_r__k_c
        + _pd__36*d_c_Q__k_c + _pd__37*d_bottom_q_thd__k_c + _x143*d_d_e_n__k_c + _x144*d_E_ba__k_c)
    d_d_rad_z__k_d = (_j_z_lo_q_th__k_d*_pd__39 + _j_z_lo_q_thd__k_d*_pd__40 + _pd__35*d_bottom_q_r__k_d
        + _pd__36*d_c_Q__k_d + _pd__37*d_bottom_q_thd__k_d + _x106*(-_x107 + 2.0*_x108*l0*m - _x110)
        + _x143*d_d_e_n__k_d + _x144*d_E_ba__k_d)
    d_Q0 = _x116*_x120 + bottom_q_th
    _pd__41 = _x121*_x130
    _pd__42 = 1.0 - _x116
    _x145 = (0.5)*_x141
    _pd__43 = _x120*_x145
    _pd__44 = _x116
    d_d_Q0__q_r_td = (_j_z_lo_q_th__q_r_td*_pd__44 + _pd__41*d_bottom_q_r__q_r_td + _pd__42*d_c_Q__q_r_td
        + _pd__43*d_d_e_n__q_r_td)
    d_d_Q0__q_rd_td = (_j_z_lo_q_th__q_rd_td*_pd__44 + _pd__41*d_bottom_q_r__q_rd_td + _pd__42*d_c_Q__q_rd_td
        + _pd__43*d_d_e_n__q_rd_td)
    d_d_Q0__q_th_td = (_j_z_lo_q_th__q_th_td*_pd__44 + _pd__41*d_bottom_q_r__q_th_td + _pd__42*d_c_Q__q_th_td
        + _pd__43*d_d_e_n__q_th_td)
    d_d_Q0__q_thd_td = (_j_z_lo_q_th__q_thd_td*_pd__44 + _pd__41*d_bottom_q_r__q_thd_td
        + _pd__42*d_c_Q__q_thd_td + _pd__43*d_d_e_n__q_thd_td)
    d_d_Q0__k_c = (_j_z_lo_q_th__k_c*_pd__44 + _pd__41*d_bottom_q_r__k_c + _pd__42*d_c_Q__k_c
        + _pd__43*d_d_e_n__k_c)
    d_d_Q0__k_d = (_j_z_lo_q_th__k_d*_pd__44 + _pd__41*d_bottom_q_r__k_d + _pd__42*d_c_Q__k_d
        + _pd__43*d_d_e_n__k_d)
    d_P0 = _x112 + _x114*_x116
    _pd__45 = _x132 + _x133
    _pd__46 = _x111 + _x139
    _pd__47 = _x114*_x145
    _pd__48 = _x142
    d_d_P0__q_r_td = (_j_z_lo_q_thd__q_r_td*_pd__48 + _pd__45*d_bottom_q_r__q_r_td
        + _pd__46*d_bottom_q_thd__q_r_td + _pd__47*d_d_e_n__q_r_td)
    d_d_P0__q_rd_td = (_j_z_lo_q_thd__q_rd_td*_pd__48 + _pd__45*d_bottom_q_r__q_rd_td
        + _pd__46*d_bottom_q_thd__q_rd_td + _pd__47*d_d_e_n__q_rd_td)
    d_d_P0__q_th_td = (_j_z_lo_q_thd__q_th_td*_pd__48 + _pd__45*d_bottom_q_r__q_th_td
        + _pd__46*d_bottom_q_thd__q_th_td + _pd__47*d_d_e_n__q_th_td)
    d_d_P0__q_thd_td = (_j_z_lo_q_thd__q_thd_td*_pd__48 + _pd__45*d_bottom_q_r__q_thd_td
        + _pd__46*d_bottom_q_thd__q_thd_td + _pd__47*d_d_e_n__q_thd_td)
    d_d_P0__k_c = (_j_z_lo_q_thd__k_c*_pd__48 + _pd__45*d_bottom_q_r__k_c + _pd__46*d_bottom_q_thd__k_c
        + _pd__47*d_d_e_n__k_c)
    d_d_P0__k_d = (_j_z_lo_q_thd__k_d*_pd__48 + _pd__45*d_bottom_q_r__k_d + _pd__46*d_bottom_q_thd__k_d
        + _pd__47*d_d_e_n__k_d)
    _x146 = m/math.sqrt(_x127)
    _x147 = (_x127 > 0.0)
    d_T0 = ((_x102*_x146 + t_bottom) if _x147 else (t_bottom))
    _pd__49 = ((_x146) if _x147 else (0.0))
    _pd__50 = ((-_x135*m/(_x127*math.sqrt(_x127))) if _x147 else (0.0))
    d_d_T0__q_r_td = _pd__49*d_d_e_n__q_r_td + _pd__50*d_d_rad_z__q_r_td + d_c_T__q_r_td
    d_d_T0__q_rd_td = _pd__49*d_d_e_n__q_rd_td + _pd__50*d_d_rad_z__q_rd_td + d_c_T__q_rd_td
    d_d_T0__q_th_td = _pd__49*d_d_e_n__q_th_td + _pd__50*d_d_rad_z__q_th_td + d_c_T__q_th_td
    d_d_T0__q_thd_td = _pd__49*d_d_e_n__q_thd_td + _pd__50*d_d_rad_z__q_thd_td + d_c_T__q_thd_td
    d_d_T0__k_c = _pd__49*d_d_e_n__k_c + _pd__50*d_d_rad_z__k_c + d_c_T__k_c
    d_d_T0__k_d = _pd__49*d_d_e_n__k_d + _pd__50*d_d_rad_z__k_d + d_c_T__k_d
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki1 = (d_e_n, d_Q0, d_P0, d_T0, d_d_e_n__q_r_td, d_d_e_n__q_rd_td, d_d_e_n__q_th_td, d_d_e_n__q_thd_td,
        d_d_e_n__k_c, d_d_e_n__k_d, d_d_Q0__q_r_td, d_d_Q0__q_rd_td, d_d_Q0__q_th_td, d_d_Q0__q_thd_td,
        d_d_Q0__k_c, d_d_Q0__k_d, d_d_P0__q_r_td, d_d_P0__q_rd_td, d_d_P0__q_th_td, d_d_P0__q_thd_td,
        d_d_P0__k_c, d_d_P0__k_d, d_d_T0__q_r_td, d_d_T0__q_rd_td, d_d_T0__q_th_td, d_d_T0__q_thd_td,
        d_d_T0__k_c, d_d_T0__k_d, )
    _pk1 = _pki1
    d_steps = 0.0
    _conv1 = False
    _last1 = max(int(iterations), 0)
    for _it1 in range(_last1 + 1):
        (d_e, d_Q, d_P, d_T, d_d_e__q_r_td, d_d_e__q_rd_td, d_d_e__q_th_td, d_d_e__q_thd_td, d_d_e__k_c,
            d_d_e__k_d, d_d_Q__q_r_td, d_d_Q__q_rd_td, d_d_Q__q_th_td, d_d_Q__q_thd_td, d_d_Q__k_c,
            d_d_Q__k_d, d_d_P__q_r_td, d_d_P__q_rd_td, d_d_P__q_th_td, d_d_P__q_thd_td, d_d_P__k_c,
            d_d_P__k_d, d_d_T__q_r_td, d_d_T__q_rd_td, d_d_T__q_th_td, d_d_T__q_thd_td, d_d_T__k_c,
            d_d_T__k_d, ) = _pk1
        if _conv1 or _it1 == _last1:
            break
        _x148 = bottom_q_r + d_e
        d_x = _x148
        d_d_x__q_r_td = d_bottom_q_r__q_r_td + d_d_e__q_r_td
        d_d_x__q_rd_td = d_bottom_q_r__q_rd_td + d_d_e__q_rd_td
        d_d_x__q_th_td = d_bottom_q_r__q_th_td + d_d_e__q_th_td
        d_d_x__q_thd_td = d_bottom_q_r__q_thd_td + d_d_e__q_thd_td
        d_d_x__k_c = d_bottom_q_r__k_c + d_d_e__k_c
        d_d_x__k_d = d_bottom_q_r__k_d + d_d_e__k_d
        _x149 = _x148**2
        _x150 = (1.0/_x149)
        _x151 = _x148**4*m
        _x152 = _x148**3
        _x153 = l0**2
        _x154 = _x149*_x153*m
        _x155 = math.cos(d_Q)
        _x156 = m**2
        _x157 = 2.0*_x156*g_s
        _x158 = 2.0*E_ba*_x149*m - _x151*k_d - _x152*_x155*_x157 + 2.0*_x152*k_d*l0*m - _x154*k_d - d_P**2
        d_rad = _x150*_x158
        _pd__51 = -2.0*_x150*d_P
        _pd__52 = _x148*_x157*math.sin(d_Q)
        _x159 = 2.0*m
        _pd__53 = (_x150*(4.0*E_ba*_x148*m - _x148*_x153*_x159*k_d - 6.0*_x149*_x155*_x156*g_s
            + 6.0*_x149*k_d*l0*m - 4.0*_x152*k_d*m) - 2.0*_x158/_x152)
        d_d_rad__q_r_td = (_pd__51*d_d_P__q_r_td + _pd__52*d_d_Q__q_r_td + _pd__53*d_d_x__q_r_td
            + _x159*d_E_ba__q_r_td)
        d_d_rad__q_rd_td = (_pd__51*d_d_P__q_rd_td + _pd__52*d_d_Q__q_rd_td + _pd__53*d_d_x__q_rd_td
            + _x159*d_E_ba__q_rd_td)
        d_d_rad__q_th_td = (_pd__51*d_d_P__q_th_td + _pd__52*d_d_Q__q_th_td + _pd__53*d_d_x__q_th_td
            + _x159*d_E_ba__q_th_td)
        d_d_rad__q_thd_td = (_pd__51*d_d_P__q_thd_td + _pd__52*d_d_Q__q_thd_td + _pd__53*d_d_x__q_thd_td
            + _x159*d_E_ba__q_thd_td)
        d_d_rad__k_c = _pd__51*d_d_P__k_c + _pd__52*d_d_Q__k_c + _pd__53*d_d_x__k_c + _x159*d_E_ba__k_c
        d_d_rad__k_d = (_pd__51*d_d_P__k_d + _pd__52*d_d_Q__k_d + _pd__53*d_d_x__k_d + _x150*(-_x151
            + 2.0*_x152*l0*m - _x154) + _x159*d_E_ba__k_d)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
        _x160 = math.sqrt(d_rad)
        d_h = _x160
        _pd__54 = (0.5)/_x160
        d_d_h__q_r_td = _pd__54*d_d_rad__q_r_td
        d_d_h__q_rd_td = _pd__54*d_d_rad__q_rd_td
        d_d_h__q_th_td = _pd__54*d_d_rad__q_th_td
        d_d_h__q_thd_td = _pd__54*d_d_rad__q_thd_td
        d_d_h__k_c = _pd__54*d_d_rad__k_c
        d_d_h__k_d = _pd__54*d_d_rad__k_d
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            _x164 = (1.0/d_x)
            _x161 = _x164**2
            d_wq = _x161*d_e_next
            _pd__55 = _x161
            _pd__56 = -2.0*_x164**3*d_e_next
            _x162 = 4.0*_pd__55
            d_d_wq__q_r_td = _pd__56*d_d_x__q_r_td + _x162*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__56*d_d_x__q_rd_td + _x162*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__56*d_d_x__q_th_td + _x162*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__56*d_d_x__q_thd_td + _x162*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__56*d_d_x__k_c + _x162*d_d_e__k_c
            d_d_wq__k_d = _pd__56*d_d_x__k_d + _x162*d_d_e__k_d
            d_wp = d_e_next*d_x
            _x163 = 4.0*d_x
            d_d_wp__q_r_td = _x163*d_d_e__q_r_td + d_d_x__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x163*d_d_e__q_rd_td + d_d_x__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x163*d_d_e__q_th_td + d_d_x__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x163*d_d_e__q_thd_td + d_d_x__q_thd_td*d_e_next
            d_d_wp__k_c = _x163*d_d_e__k_c + d_d_x__k_c*d_e_next
            d_d_wp__k_d = _x163*d_d_e__k_d + d_d_x__k_d*d_e_next
        elif variant == 1.0:
            _x165 = (1.0/bottom_q_r)
            _x166 = bottom_q_r + d_e_next
            _x167 = (1.0/_x166)
            d_wq = _x165*_x167*d_e_next
            _x168 = _x165*_x167**2*d_e_next
            _pd__57 = -_x165**2*_x167*d_e_next - _x168
            _pd__58 = _x165*_x167 - _x168
            _x169 = 4.0*_pd__58
            d_d_wq__q_r_td = _pd__57*d_bottom_q_r__q_r_td + _x169*d_d_e__q_r_td
            d_d_wq__q_rd_td = _pd__57*d_bottom_q_r__q_rd_td + _x169*d_d_e__q_rd_td
            d_d_wq__q_th_td = _pd__57*d_bottom_q_r__q_th_td + _x169*d_d_e__q_th_td
            d_d_wq__q_thd_td = _pd__57*d_bottom_q_r__q_thd_td + _x169*d_d_e__q_thd_td
            d_d_wq__k_c = _pd__57*d_bottom_q_r__k_c + _x169*d_d_e__k_c
            d_d_wq__k_d = _pd__57*d_bottom_q_r__k_d + _x169*d_d_e__k_d
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
            _pd__59 = _x166
            _x170 = 4.0*_pd__59
            d_d_wp__q_r_td = _x170*d_d_e__q_r_td + d_bottom_q_r__q_r_td*d_e_next
            d_d_wp__q_rd_td = _x170*d_d_e__q_rd_td + d_bottom_q_r__q_rd_td*d_e_next
            d_d_wp__q_th_td = _x170*d_d_e__q_th_td + d_bottom_q_r__q_th_td*d_e_next
            d_d_wp__q_thd_td = _x170*d_d_e__q_thd_td + d_bottom_q_r__q_thd_td*d_e_next
            d_d_wp__k_c = _x170*d_d_e__k_c + d_bottom_q_r__k_c*d_e_next
            d_d_wp__k_d = _x170*d_d_e__k_d + d_bottom_q_r__k_d*d_e_next
        else:
            return _NAN70 + (STATUS_INVALID_INPUT,)
        # next values
        d_e__next = d_e_next
        _x171 = (1.0/d_h)
        _x172 = _x171*d_wq
        d_Q__next = _x172*d_P + bottom_q_th
        _pd__60 = _x172
        _x173 = _x171**2
        _pd__61 = -_x173*d_P*d_wq
        _pd__62 = _x171*d_P
        d_d_Q__next__q_r_td = (_pd__60*d_d_P__q_r_td + _pd__61*d_d_h__q_r_td + _pd__62*d_d_wq__q_r_td
            + d_c_Q__q_r_td)
        d_d_Q__next__q_rd_td = (_pd__60*d_d_P__q_rd_td + _pd__61*d_d_h__q_rd_td + _pd__62*d_d_wq__q_rd_td
            + d_c_Q__q_rd_td)
        d_d_Q__next__q_th_td = (_pd__60*d_d_P__q_th_td + _pd__61*d_d_h__q_th_td + _pd__62*d_d_wq__q_th_td
            + d_c_Q__q_th_td)
        d_d_Q__next__q_thd_td = (_pd__60*d_d_P__q_thd_td + _pd__61*d_d_h__q_thd_td + _pd__62*d_d_wq__q_thd_td
            + d_c_Q__q_thd_td)
        d_d_Q__next__k_c = _pd__60*d_d_P__k_c + _pd__61*d_d_h__k_c + _pd__62*d_d_wq__k_c + d_c_Q__k_c
        d_d_Q__next__k_d = _pd__60*d_d_P__k_d + _pd__61*d_d_h__k_d + _pd__62*d_d_wq__k_d + d_c_Q__k_d
        _x174 = bottom_q_r**2*m
        _x175 = math.sin(d_Q)
        _x176 = m**2
        _x177 = _x171*_x176*g_s
        _x178 = _x175*_x177
        d_P__next = _x174*bottom_q_thd + _x178*d_wp
        _pd__63 = 2.0*bottom_q_r*bottom_q_thd*m
        _pd__64 = _x174
        _pd__65 = _x177*d_wp*math.cos(d_Q)
        _pd__66 = -_x173*_x175*_x176*d_wp*g_s
        _pd__67 = _x178
        d_d_P__next__q_r_td = (_pd__63*d_bottom_q_r__q_r_td + _pd__64*d_bottom_q_thd__q_r_td
            + _pd__65*d_d_Q__q_r_td + _pd__66*d_d_h__q_r_td + _pd__67*d_d_wp__q_r_td)
        d_d_P__next__q_rd_td = (_pd__63*d_bottom_q_r__q_rd_td + _pd__64*d_bottom_q_thd__q_rd_td
            + _pd__65*d_d_Q__q_rd_td + _pd__66*d_d_h__q_rd_td + _pd__67*d_d_wp__q_rd_td)
        d_d_P__next__q_th_td = (_pd__63*d_bottom_q_r__q_th_td + _pd__64*d_bottom_q_thd__q_th_td
            + _pd__65*d_d_Q__q_th_td + _pd__66*d_d_h__q_th_td + _pd__67*d_d_wp__q_th_td)
        d_d_P__next__q_thd_td = (_pd__63*d_bottom_q_r__q_thd_td + _pd__64*d_bottom_q_thd__q_thd_td
            + _pd__65*d_d_Q__q_thd_td + _pd__66*d_d_h__q_thd_td + _pd__67*d_d_wp__q_thd_td)
        d_d_P__next__k_c = (_pd__63*d_bottom_q_r__k_c + _pd__64*d_bottom_q_thd__k_c + _pd__65*d_d_Q__k_c
            + _pd__66*d_d_h__k_c + _pd__67*d_d_wp__k_c)
        d_d_P__next__k_d = (_pd__63*d_bottom_q_r__k_d + _pd__64*d_bottom_q_thd__k_d + _pd__65*d_d_Q__k_d
            + _pd__66*d_d_h__k_d + _pd__67*d_d_wp__k_d)
        _x179 = _x171*m
        d_T__next = _x179*d_e_next + t_bottom
        _pd__68 = _x179
        _pd__69 = -_x173*d_e_next*m
        _x180 = 4.0*_pd__68
        d_d_T__next__q_r_td = _pd__69*d_d_h__q_r_td + _x180*d_d_e__q_r_td + d_c_T__q_r_td
        d_d_T__next__q_rd_td = _pd__69*d_d_h__q_rd_td + _x180*d_d_e__q_rd_td + d_c_T__q_rd_td
        d_d_T__next__q_th_td = _pd__69*d_d_h__q_th_td + _x180*d_d_e__q_th_td + d_c_T__q_th_td
        d_d_T__next__q_thd_td = _pd__69*d_d_h__q_thd_td + _x180*d_d_e__q_thd_td + d_c_T__q_thd_td
        d_d_T__next__k_c = _pd__69*d_d_h__k_c + _x180*d_d_e__k_c + d_c_T__k_c
        d_d_T__next__k_d = _pd__69*d_d_h__k_d + _x180*d_d_e__k_d + d_c_T__k_d
        _n1_4 = 4.0*d_d_e__q_r_td
        _n1_5 = 4.0*d_d_e__q_rd_td
        _n1_6 = 4.0*d_d_e__q_th_td
        _n1_7 = 4.0*d_d_e__q_thd_td
        _n1_8 = 4.0*d_d_e__k_c
        _n1_9 = 4.0*d_d_e__k_d
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(d_e__next - d_e) <= 0.0*(l0)) and (abs(d_Q__next - d_Q) <= 0.0*(1.0))
            and (abs(d_P__next - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(d_T__next - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        _pkn1 = (d_e__next, d_Q__next, d_P__next, d_T__next, _n1_4, _n1_5, _n1_6, _n1_7, _n1_8, _n1_9,
            d_d_Q__next__q_r_td, d_d_Q__next__q_rd_td, d_d_Q__next__q_th_td, d_d_Q__next__q_thd_td,
            d_d_Q__next__k_c, d_d_Q__next__k_d, d_d_P__next__q_r_td, d_d_P__next__q_rd_td,
            d_d_P__next__q_th_td, d_d_P__next__q_thd_td, d_d_P__next__k_c, d_d_P__next__k_d,
            d_d_T__next__q_r_td, d_d_T__next__q_rd_td, d_d_T__next__q_th_td, d_d_T__next__q_thd_td,
            d_d_T__next__k_c, d_d_T__next__k_d, )
        _pk1 = _pkn1
        d_steps += 1.0
    # (45) corrected: p_r of the iterate at q_r_lo
    _x181 = q_r_lo**2
    _x182 = (1.0/_x181)
    _x183 = m*q_r_lo**4
    _x184 = q_r_lo**3
    _x185 = _x181*l0**2*m
    _x186 = 2.0*g_s*m**2
    rad_lo = (_x182*(2.0*E_ba*_x181*m - _x183*k_d - _x184*_x186*math.cos(d_Q) + 2.0*_x184*k_d*l0*m - _x185*k_d
        - d_P**2))
    _pd__70 = -2.0*_x182*d_P
    _pd__71 = _x186*q_r_lo*math.sin(d_Q)
    _x187 = 2.0*m
    d_rad_lo__q_r_td = _pd__70*d_d_P__q_r_td + _pd__71*d_d_Q__q_r_td + _x187*d_E_ba__q_r_td
    d_rad_lo__q_rd_td = _pd__70*d_d_P__q_rd_td + _pd__71*d_d_Q__q_rd_td + _x187*d_E_ba__q_rd_td
    d_rad_lo__q_th_td = _pd__70*d_d_P__q_th_td + _pd__71*d_d_Q__q_th_td + _x187*d_E_ba__q_th_td
    d_rad_lo__q_thd_td = _pd__70*d_d_P__q_thd_td + _pd__71*d_d_Q__q_thd_td + _x187*d_E_ba__q_thd_td
    d_rad_lo__k_c = _pd__70*d_d_P__k_c + _pd__71*d_d_Q__k_c + _x187*d_E_ba__k_c
    d_rad_lo__k_d = (_pd__70*d_d_P__k_d + _pd__71*d_d_Q__k_d + _x182*(-_x183 + 2.0*_x184*l0*m - _x185)
        + _x187*d_E_ba__k_d)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN70 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    t_stance = d_T
    liftoff_q_r = q_r_lo
    _x188 = (1.0/m)
    _x189 = math.sqrt(rad_lo)
    liftoff_q_rd = _x188*_x189
    _pd__72 = (0.5)*_x188/_x189
    d_liftoff_q_rd__q_r_td = _pd__72*d_rad_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _pd__72*d_rad_lo__q_rd_td
    d_liftoff_q_rd__q_th_td = _pd__72*d_rad_lo__q_th_td
    d_liftoff_q_rd__q_thd_td = _pd__72*d_rad_lo__q_thd_td
    d_liftoff_q_rd__k_c = _pd__72*d_rad_lo__k_c
    d_liftoff_q_rd__k_d = _pd__72*d_rad_lo__k_d
    liftoff_q_th = d_Q
    _x190 = _x188/q_r_lo**2
    liftoff_q_thd = _x190*d_P
    _pd__73 = _x190
    d_liftoff_q_thd__q_r_td = _pd__73*d_d_P__q_r_td
    d_liftoff_q_thd__q_rd_td = _pd__73*d_d_P__q_rd_td
    d_liftoff_q_thd__q_th_td = _pd__73*d_d_P__q_th_td
    d_liftoff_q_thd__q_thd_td = _pd__73*d_d_P__q_thd_td
    d_liftoff_q_thd__k_c = _pd__73*d_d_P__k_c
    d_liftoff_q_thd__k_d = _pd__73*d_d_P__k_d
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN70 + (STATUS_FALL,)
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_c_T__q_r_td
    d_t_bottom__q_rd_td = d_c_T__q_rd_td
    d_t_bottom__q_th_td = d_c_T__q_th_td
    d_t_bottom__q_thd_td = d_c_T__q_thd_td
    d_t_bottom__k_c = d_c_T__k_c
    d_t_bottom__k_d = d_c_T__k_d
    d_t_stance__q_r_td = d_d_T__q_r_td
    d_t_stance__q_rd_td = d_d_T__q_rd_td
    d_t_stance__q_th_td = d_d_T__q_th_td
    d_t_stance__q_thd_td = d_d_T__q_thd_td
    d_t_stance__k_c = d_d_T__k_c
    d_t_stance__k_d = d_d_T__k_d
    d_bottom_q_rd__q_r_td = 0.0
    d_bottom_q_rd__q_rd_td = 0.0
    d_bottom_q_rd__q_th_td = 0.0
    d_bottom_q_rd__q_thd_td = 0.0
    d_bottom_q_rd__k_c = 0.0
    d_bottom_q_rd__k_d = 0.0
    d_bottom_q_th__q_r_td = d_c_Q__q_r_td
    d_bottom_q_th__q_rd_td = d_c_Q__q_rd_td
    d_bottom_q_th__q_th_td = d_c_Q__q_th_td
    d_bottom_q_th__q_thd_td = d_c_Q__q_thd_td
    d_bottom_q_th__k_c = d_c_Q__k_c
    d_bottom_q_th__k_d = d_c_Q__k_d
    d_liftoff_q_r__q_r_td = 0.0
    d_liftoff_q_r__q_rd_td = 0.0
    d_liftoff_q_r__q_th_td = 0.0
    d_liftoff_q_r__q_thd_td = 0.0
    d_liftoff_q_r__k_c = 0.0
    d_liftoff_q_r__k_d = 0.0
    d_liftoff_q_th__q_r_td = d_d_Q__q_r_td
    d_liftoff_q_th__q_rd_td = d_d_Q__q_rd_td
    d_liftoff_q_th__q_th_td = d_d_Q__q_th_td
    d_liftoff_q_th__q_thd_td = d_d_Q__q_thd_td
    d_liftoff_q_th__k_c = d_d_Q__k_c
    d_liftoff_q_th__k_d = d_d_Q__k_d
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
def iterative_report_stance_jacobian_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        k_d, g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_jacobian_zeroth_geyer_vs`: arguments, out and
    status as :func:`iterative_report_stance_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_jacobian_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        store_row_10_70(out, status, i, res)


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map by Iterative stance map (Schwind and Koditschek, as printed), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_jacobian_zeroth_geyer`'s.
    """
    # Total ops: 1
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(ground) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td)
            and math.isfinite(q_r_lo) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((b_y_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi))
            and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f
            > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_jacobian_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c,
        k_d, g_s, q_r_lo, variant, iterations, bottom_length))
    if _c1[70] != STATUS_OK:
        return _NAN84 + (_c1[70],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, _, _, _, _, _, _,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _j_t_stance__k_c, _j_t_stance__k_d,
        _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _, _,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td,
        _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d,
        _) = _c1
    # the code shared between choices
    return (iterative_report_apex_return_jacobian_tail_063bb0(_j_foot_x__b_xd_apex, _j_foot_x__b_y_apex,
        _j_foot_x__ground, _j_foot_x__q_th_td, _j_liftoff_q_rd__k_c, _j_liftoff_q_rd__k_d,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_th__k_c,
        _j_liftoff_q_th__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_t_descent__b_y_apex, _j_t_descent__ground, _j_t_descent__q_th_td,
        _j_t_stance__k_c, _j_t_stance__k_d, _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td,
        _j_td_q_rd__b_xd_apex, _j_td_q_rd__b_y_apex, _j_td_q_rd__ground, _j_td_q_rd__q_th_td,
        _j_td_q_th__q_th_td, _j_td_q_thd__b_xd_apex, _j_td_q_thd__b_y_apex, _j_td_q_thd__ground,
        _j_td_q_thd__q_th_td, b_y_apex, direction, foot_x, g_f, ground, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, t_descent, t_stance))


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_apex_return_jacobian_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0,
        k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_jacobian_zeroth_geyer_vs`: arguments, out
    and status as :func:`iterative_report_apex_return_jacobian_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_jacobian_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        store_row_12_84(out, status, i, res)
