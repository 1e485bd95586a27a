# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative_report.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight.py sha256:8b20bd5230ccfe19
#   geyer.py sha256:4737273d6d8636d4
#   geyer_vs.py sha256:2af0829e07a0cf1b
#   gravity_type0.py sha256:307fd5b7e0072824
#   gravity_type1.py sha256:46607008446ed15d
#   gravity_type2.py sha256:97fb4f568b945f42
#   gravity_type3.py sha256:d4ac1d04e125ac4a
#   gravity_type4.py sha256:81186cbbb1247b9f
#   gravity_type5.py sha256:f4510b5010050beb
# ----------------------------------------------------------------------------------------------
"""Iterative stance map (Schwind and Koditschek, as printed) (report section 3.2): stance, state-at-time and
apex-return kernels."""

import math

import numpy as np
from numba import njit, prange
from .flight import apex_to_touchdown, liftoff_to_apex
from .geyer import geyer_stance
from .geyer_vs import bottom_quartic, geyer_vs_stance
from .gravity_type0 import gravity_type0_stance
from .gravity_type1 import gravity_type1_stance
from .gravity_type2 import gravity_type2_stance
from .gravity_type3 import gravity_type3_stance
from .gravity_type4 import gravity_type4_stance
from .gravity_type5 import gravity_type5_stance

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_NUMERICAL_RANGE, STATUS_IMAGINARY_MOMENTUM)

NAN = math.nan
_NAN10 = (NAN,) * 10
_NAN12 = (NAN,) * 12


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    (42)-(44)/(124)-(126)/(139)-(141) or (133)-(135)/(148)-(150) with (134)/(149) keeping p_th;
    liftoff p_r = H^{-1} at q_r_lo ((45) corrected); E_ba of (98). IMAGINARY_MOMENTUM wherever
    H^{-1} of an iterate is imaginary.

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
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 272
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo)
    if _c0[10] != STATUS_OK:
        return _NAN10 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # E_ab (114) of the touchdown state
    _x0 = (0.5)*k_c
    _x1 = q_r_td**2
    _x2 = (0.5)*m
    E_ab = (_x0*_x1 + _x0*l0**2 + _x1*_x2*q_thd_td**2 + _x2*q_rd_td**2 + g_s*m*q_r_td*math.cos(q_th_td)
        - k_c*l0*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[1] != STATUS_OK:
            return _NAN10 + (_c1[1],)
        bottom_q_r = _c1[0]
    else:
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x3 = 4.0**(-iterations)
    _x4 = _x3*(bottom_q_r - q_r_td)
    _x5 = (0.25)*_x4
    _x6 = _x5 + q_r_td
    _x7 = _x6**2
    _x8 = k_c*m
    _x9 = _x6**3
    _x10 = m*z_b_q_r**2*z_b_q_thd
    _x11 = math.sqrt(1.0 - 0.25*_x3)
    _x12 = -_x10 + m*q_r_td**2*q_thd_td
    _x13 = q_th_td - z_b_q_th
    _x14 = ((2.0*E_ab*_x7*m - _x6**4*_x8 - _x7*_x8*l0**2 - 2.0*_x9*g_s*m**2*math.cos(_x11*_x13 + z_b_q_th)
        + 2.0*_x9*k_c*l0*m - (_x10 + _x11*_x12)**2)/_x7)
    _x15 = math.sqrt(1.0 - _x3)
    c_e_n = _x4
    c_e_z = _x5
    c_rad_z = _x14
    c_Q0 = _x13*_x15 + z_b_q_th
    c_P0 = _x10 + _x12*_x15
    c_T0 = ((-_x4*m/math.sqrt(_x14)) if (_x14 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x16 = c_e + q_r_td
        _x17 = _x16**2
        _x18 = k_c*m
        _x19 = _x16**3
        c_x = _x16
        c_rad = ((2.0*E_ab*_x17*m - _x16**4*_x18 - _x17*_x18*l0**2 - 2.0*_x19*g_s*m**2*math.cos(c_Q)
            + 2.0*_x19*k_c*l0*m - c_P**2)/_x17)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        c_h = math.sqrt(c_rad)
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            c_wq = c_e_next/c_x**2
            c_wp = c_e_next*c_x
        elif variant == 1.0:
            c_wq = c_e_next/(q_r_td*(c_e_next + q_r_td))
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n0_0 = c_e_next
        _n0_1 = -c_P*c_wq/c_h + q_th_td
        _n0_2 = m*q_r_td**2*q_thd_td - c_wp*g_s*m**2*math.sin(c_Q)/c_h
        _n0_3 = -c_e_next*m/c_h
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_steps += 1.0
        if _conv0:
            break
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x20 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x21 = (0.25)*_x20
    _x22 = _x21 + bottom_q_r
    _x23 = _x22**2
    _x24 = k_d*m
    _x25 = _x22**3
    _x26 = bottom_q_r**2*bottom_q_thd*m
    _x27 = 4.0**(-0.5*iterations)
    _x28 = _x27*(-_x26 + g_lo_q_thd*m*q_r_lo**2)
    _x29 = _x27*(-bottom_q_th + g_lo_q_th)
    _x30 = ((2.0*E_ba*_x23*m - _x22**4*_x24 - _x23*_x24*l0**2 - 2.0*_x25*g_s*m**2*math.cos((0.5)*_x29
        + bottom_q_th) + 2.0*_x25*k_d*l0*m - (_x26 + (0.5)*_x28)**2)/_x23)
    d_e_n = _x20
    d_e_z = _x21
    d_rad_z = _x30
    d_Q0 = _x29 + bottom_q_th
    d_P0 = _x26 + _x28
    d_T0 = ((_x20*m/math.sqrt(_x30) + t_bottom) if (_x30 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv1 = False
    for _it1 in range(int(iterations)):
        _x31 = bottom_q_r + d_e
        _x32 = _x31**2
        _x33 = k_d*m
        _x34 = _x31**3
        d_x = _x31
        d_rad = ((2.0*E_ba*_x32*m - _x31**4*_x33 - _x32*_x33*l0**2 - 2.0*_x34*g_s*m**2*math.cos(d_Q)
            + 2.0*_x34*k_d*l0*m - d_P**2)/_x32)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(bottom_q_r*(bottom_q_r + d_e_next))
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n1_0 = d_e_next
        _n1_1 = bottom_q_th + d_P*d_wq/d_h
        _n1_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n1_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(_n1_0 - d_e) <= 0.0*(l0)) and (abs(_n1_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n1_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n1_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n1_0
        d_Q = _n1_1
        d_P = _n1_2
        d_T = _n1_3
        d_steps += 1.0
        if _conv1:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x35 = q_r_lo**2
    _x36 = k_d*m
    _x37 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x35*m - _x35*_x36*l0**2 - _x36*q_r_lo**4 - 2.0*_x37*g_s*m**2*math.cos(d_Q)
        + 2.0*_x37*k_d*l0*m - d_P**2)/_x35)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x38 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x38*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x38*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_stance_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_zeroth_geyer`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length.
    Writes output j of row i to ``out[i, j]`` (shape (n, 10); the columns are the outputs of
    :func:`iterative_report_stance_zeroth_geyer`, in order) and its status code to ``status[i]`` (int64).
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_geyer(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f,
        q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

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
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 3
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_zeroth_geyer(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length))
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
def iterative_report_apex_return_zeroth_geyer_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_zeroth_geyer`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td, ground.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations,
    bottom_length.
    Writes output j of row i to ``out[i, j]`` (shape (n, 12); the columns are the outputs of
    :func:`iterative_report_apex_return_zeroth_geyer`, in order) and its status code to ``status[i]`` (int64).
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_zeroth_geyer(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_zeroth_geyer`'s.
    """
    # Total ops: 307
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # E_ab (114) of the touchdown state
    _x5 = (0.5)*k_c
    _x6 = q_r_td**2
    _x7 = (0.5)*m
    E_ab = (_x5*_x6 + _x5*l0**2 + _x6*_x7*q_thd_td**2 + _x7*q_rd_td**2 + g_s*m*q_r_td*math.cos(q_th_td)
        - k_c*l0*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c0 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c0[1] != STATUS_OK:
            return _NAN10 + (_c0[1],)
        bottom_q_r = _c0[0]
    else:
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x8 = 4.0**(-iterations)
    _x9 = _x8*(bottom_q_r - q_r_td)
    _x10 = (0.25)*_x9
    _x11 = _x10 + q_r_td
    _x12 = _x11**2
    _x13 = k_c*m
    _x14 = _x11**3
    _x15 = m*z_b_q_r**2*z_b_q_thd
    _x16 = math.sqrt(1.0 - 0.25*_x8)
    _x17 = -_x15 + m*q_r_td**2*q_thd_td
    _x18 = q_th_td - z_b_q_th
    _x19 = ((2.0*E_ab*_x12*m - _x11**4*_x13 - _x12*_x13*l0**2 - 2.0*_x14*g_s*m**2*math.cos(_x16*_x18
        + z_b_q_th) + 2.0*_x14*k_c*l0*m - (_x15 + _x16*_x17)**2)/_x12)
    _x20 = math.sqrt(1.0 - _x8)
    c_e_n = _x9
    c_e_z = _x10
    c_rad_z = _x19
    c_Q0 = _x18*_x20 + z_b_q_th
    c_P0 = _x15 + _x17*_x20
    c_T0 = ((-_x9*m/math.sqrt(_x19)) if (_x19 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x21 = c_e + q_r_td
        _x22 = _x21**2
        _x23 = k_c*m
        _x24 = _x21**3
        c_x = _x21
        c_rad = ((2.0*E_ab*_x22*m - _x21**4*_x23 - _x22*_x23*l0**2 - 2.0*_x24*g_s*m**2*math.cos(c_Q)
            + 2.0*_x24*k_c*l0*m - c_P**2)/_x22)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        c_h = math.sqrt(c_rad)
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            c_wq = c_e_next/c_x**2
            c_wp = c_e_next*c_x
        elif variant == 1.0:
            c_wq = c_e_next/(q_r_td*(c_e_next + q_r_td))
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n0_0 = c_e_next
        _n0_1 = -c_P*c_wq/c_h + q_th_td
        _n0_2 = m*q_r_td**2*q_thd_td - c_wp*g_s*m**2*math.sin(c_Q)/c_h
        _n0_3 = -c_e_next*m/c_h
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_steps += 1.0
        if _conv0:
            break
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    g_lo_q_th = bottom_q_th
    g_lo_q_thd = bottom_q_r**2*bottom_q_thd/q_r_lo**2
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x25 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x26 = (0.25)*_x25
    _x27 = _x26 + bottom_q_r
    _x28 = _x27**2
    _x29 = k_d*m
    _x30 = _x27**3
    _x31 = bottom_q_r**2*bottom_q_thd*m
    _x32 = 4.0**(-0.5*iterations)
    _x33 = _x32*(-_x31 + g_lo_q_thd*m*q_r_lo**2)
    _x34 = _x32*(-bottom_q_th + g_lo_q_th)
    _x35 = ((2.0*E_ba*_x28*m - _x27**4*_x29 - _x28*_x29*l0**2 - 2.0*_x30*g_s*m**2*math.cos((0.5)*_x34
        + bottom_q_th) + 2.0*_x30*k_d*l0*m - (_x31 + (0.5)*_x33)**2)/_x28)
    d_e_n = _x25
    d_e_z = _x26
    d_rad_z = _x35
    d_Q0 = _x34 + bottom_q_th
    d_P0 = _x31 + _x33
    d_T0 = ((_x25*m/math.sqrt(_x35) + t_bottom) if (_x35 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv1 = False
    for _it1 in range(int(iterations)):
        _x36 = bottom_q_r + d_e
        _x37 = _x36**2
        _x38 = k_d*m
        _x39 = _x36**3
        d_x = _x36
        d_rad = ((2.0*E_ba*_x37*m - _x36**4*_x38 - _x37*_x38*l0**2 - 2.0*_x39*g_s*m**2*math.cos(d_Q)
            + 2.0*_x39*k_d*l0*m - d_P**2)/_x37)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(bottom_q_r*(bottom_q_r + d_e_next))
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n1_0 = d_e_next
        _n1_1 = bottom_q_th + d_P*d_wq/d_h
        _n1_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n1_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(_n1_0 - d_e) <= 0.0*(l0)) and (abs(_n1_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n1_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n1_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n1_0
        d_Q = _n1_1
        d_P = _n1_2
        d_T = _n1_3
        d_steps += 1.0
        if _conv1:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x40 = q_r_lo**2
    _x41 = k_d*m
    _x42 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x40*m - _x40*_x41*l0**2 - _x41*q_r_lo**4 - 2.0*_x42*g_s*m**2*math.cos(d_Q)
        + 2.0*_x42*k_d*l0*m - d_P**2)/_x40)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x43 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x43*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x43*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_stance_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_zeroth_held`: arguments, out and status as
    :func:`iterative_report_stance_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c,
            k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_held(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s, g_f,
        q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_zeroth_geyer`'s.
    """
    # Total ops: 3
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_zeroth_held(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length))
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
def iterative_report_apex_return_zeroth_held_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_zeroth_held`: arguments, out and status as
    :func:`iterative_report_apex_return_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_zeroth_held(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i], m,
            l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_zeroth_geyer`'s.
    """
    # Total ops: 272
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN10 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # E_ab (114) of the touchdown state
    _x0 = (0.5)*k_c
    _x1 = q_r_td**2
    _x2 = (0.5)*m
    E_ab = (_x0*_x1 + _x0*l0**2 + _x1*_x2*q_thd_td**2 + _x2*q_rd_td**2 + g_s*m*q_r_td*math.cos(q_th_td)
        - k_c*l0*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[1] != STATUS_OK:
            return _NAN10 + (_c1[1],)
        bottom_q_r = _c1[0]
    else:
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x3 = 4.0**(-iterations)
    _x4 = _x3*(bottom_q_r - q_r_td)
    _x5 = (0.25)*_x4
    _x6 = _x5 + q_r_td
    _x7 = _x6**2
    _x8 = k_c*m
    _x9 = _x6**3
    _x10 = m*z_b_q_r**2*z_b_q_thd
    _x11 = math.sqrt(1.0 - 0.25*_x3)
    _x12 = -_x10 + m*q_r_td**2*q_thd_td
    _x13 = q_th_td - z_b_q_th
    _x14 = ((2.0*E_ab*_x7*m - _x6**4*_x8 - _x7*_x8*l0**2 - 2.0*_x9*g_s*m**2*math.cos(_x11*_x13 + z_b_q_th)
        + 2.0*_x9*k_c*l0*m - (_x10 + _x11*_x12)**2)/_x7)
    _x15 = math.sqrt(1.0 - _x3)
    c_e_n = _x4
    c_e_z = _x5
    c_rad_z = _x14
    c_Q0 = _x13*_x15 + z_b_q_th
    c_P0 = _x10 + _x12*_x15
    c_T0 = ((-_x4*m/math.sqrt(_x14)) if (_x14 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x16 = c_e + q_r_td
        _x17 = _x16**2
        _x18 = k_c*m
        _x19 = _x16**3
        c_x = _x16
        c_rad = ((2.0*E_ab*_x17*m - _x16**4*_x18 - _x17*_x18*l0**2 - 2.0*_x19*g_s*m**2*math.cos(c_Q)
            + 2.0*_x19*k_c*l0*m - c_P**2)/_x17)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        c_h = math.sqrt(c_rad)
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            c_wq = c_e_next/c_x**2
            c_wp = c_e_next*c_x
        elif variant == 1.0:
            c_wq = c_e_next/(q_r_td*(c_e_next + q_r_td))
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n0_0 = c_e_next
        _n0_1 = -c_P*c_wq/c_h + q_th_td
        _n0_2 = m*q_r_td**2*q_thd_td - c_wp*g_s*m**2*math.sin(c_Q)/c_h
        _n0_3 = -c_e_next*m/c_h
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_steps += 1.0
        if _conv0:
            break
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x20 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x21 = (0.25)*_x20
    _x22 = _x21 + bottom_q_r
    _x23 = _x22**2
    _x24 = k_d*m
    _x25 = _x22**3
    _x26 = bottom_q_r**2*bottom_q_thd*m
    _x27 = 4.0**(-0.5*iterations)
    _x28 = _x27*(-_x26 + g_lo_q_thd*m*q_r_lo**2)
    _x29 = _x27*(-bottom_q_th + g_lo_q_th)
    _x30 = ((2.0*E_ba*_x23*m - _x22**4*_x24 - _x23*_x24*l0**2 - 2.0*_x25*g_s*m**2*math.cos((0.5)*_x29
        + bottom_q_th) + 2.0*_x25*k_d*l0*m - (_x26 + (0.5)*_x28)**2)/_x23)
    d_e_n = _x20
    d_e_z = _x21
    d_rad_z = _x30
    d_Q0 = _x29 + bottom_q_th
    d_P0 = _x26 + _x28
    d_T0 = ((_x20*m/math.sqrt(_x30) + t_bottom) if (_x30 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv1 = False
    for _it1 in range(int(iterations)):
        _x31 = bottom_q_r + d_e
        _x32 = _x31**2
        _x33 = k_d*m
        _x34 = _x31**3
        d_x = _x31
        d_rad = ((2.0*E_ba*_x32*m - _x31**4*_x33 - _x32*_x33*l0**2 - 2.0*_x34*g_s*m**2*math.cos(d_Q)
            + 2.0*_x34*k_d*l0*m - d_P**2)/_x32)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(bottom_q_r*(bottom_q_r + d_e_next))
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n1_0 = d_e_next
        _n1_1 = bottom_q_th + d_P*d_wq/d_h
        _n1_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n1_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(_n1_0 - d_e) <= 0.0*(l0)) and (abs(_n1_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n1_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n1_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n1_0
        d_Q = _n1_1
        d_P = _n1_2
        d_T = _n1_3
        d_steps += 1.0
        if _conv1:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x35 = q_r_lo**2
    _x36 = k_d*m
    _x37 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x35*m - _x35*_x36*l0**2 - _x36*q_r_lo**4 - 2.0*_x37*g_s*m**2*math.cos(d_Q)
        + 2.0*_x37*k_d*l0*m - d_P**2)/_x35)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x38 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x38*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x38*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_zeroth_gravity_type0`: arguments, out and status
    as :func:`iterative_report_stance_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type0(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_zeroth_geyer`'s.
    """
    # Total ops: 3
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_zeroth_gravity_type0(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length))
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
def iterative_report_apex_return_zeroth_gravity_type0_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_report_apex_return_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_zeroth_gravity_type0(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_zeroth_geyer`'s.
    """
    # Total ops: 272
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN10 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # E_ab (114) of the touchdown state
    _x0 = (0.5)*k_c
    _x1 = q_r_td**2
    _x2 = (0.5)*m
    E_ab = (_x0*_x1 + _x0*l0**2 + _x1*_x2*q_thd_td**2 + _x2*q_rd_td**2 + g_s*m*q_r_td*math.cos(q_th_td)
        - k_c*l0*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[1] != STATUS_OK:
            return _NAN10 + (_c1[1],)
        bottom_q_r = _c1[0]
    else:
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x3 = 4.0**(-iterations)
    _x4 = _x3*(bottom_q_r - q_r_td)
    _x5 = (0.25)*_x4
    _x6 = _x5 + q_r_td
    _x7 = _x6**2
    _x8 = k_c*m
    _x9 = _x6**3
    _x10 = m*z_b_q_r**2*z_b_q_thd
    _x11 = math.sqrt(1.0 - 0.25*_x3)
    _x12 = -_x10 + m*q_r_td**2*q_thd_td
    _x13 = q_th_td - z_b_q_th
    _x14 = ((2.0*E_ab*_x7*m - _x6**4*_x8 - _x7*_x8*l0**2 - 2.0*_x9*g_s*m**2*math.cos(_x11*_x13 + z_b_q_th)
        + 2.0*_x9*k_c*l0*m - (_x10 + _x11*_x12)**2)/_x7)
    _x15 = math.sqrt(1.0 - _x3)
    c_e_n = _x4
    c_e_z = _x5
    c_rad_z = _x14
    c_Q0 = _x13*_x15 + z_b_q_th
    c_P0 = _x10 + _x12*_x15
    c_T0 = ((-_x4*m/math.sqrt(_x14)) if (_x14 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x16 = c_e + q_r_td
        _x17 = _x16**2
        _x18 = k_c*m
        _x19 = _x16**3
        c_x = _x16
        c_rad = ((2.0*E_ab*_x17*m - _x16**4*_x18 - _x17*_x18*l0**2 - 2.0*_x19*g_s*m**2*math.cos(c_Q)
            + 2.0*_x19*k_c*l0*m - c_P**2)/_x17)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        c_h = math.sqrt(c_rad)
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            c_wq = c_e_next/c_x**2
            c_wp = c_e_next*c_x
        elif variant == 1.0:
            c_wq = c_e_next/(q_r_td*(c_e_next + q_r_td))
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n0_0 = c_e_next
        _n0_1 = -c_P*c_wq/c_h + q_th_td
        _n0_2 = m*q_r_td**2*q_thd_td - c_wp*g_s*m**2*math.sin(c_Q)/c_h
        _n0_3 = -c_e_next*m/c_h
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_steps += 1.0
        if _conv0:
            break
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x20 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x21 = (0.25)*_x20
    _x22 = _x21 + bottom_q_r
    _x23 = _x22**2
    _x24 = k_d*m
    _x25 = _x22**3
    _x26 = bottom_q_r**2*bottom_q_thd*m
    _x27 = 4.0**(-0.5*iterations)
    _x28 = _x27*(-_x26 + g_lo_q_thd*m*q_r_lo**2)
    _x29 = _x27*(-bottom_q_th + g_lo_q_th)
    _x30 = ((2.0*E_ba*_x23*m - _x22**4*_x24 - _x23*_x24*l0**2 - 2.0*_x25*g_s*m**2*math.cos((0.5)*_x29
        + bottom_q_th) + 2.0*_x25*k_d*l0*m - (_x26 + (0.5)*_x28)**2)/_x23)
    d_e_n = _x20
    d_e_z = _x21
    d_rad_z = _x30
    d_Q0 = _x29 + bottom_q_th
    d_P0 = _x26 + _x28
    d_T0 = ((_x20*m/math.sqrt(_x30) + t_bottom) if (_x30 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv1 = False
    for _it1 in range(int(iterations)):
        _x31 = bottom_q_r + d_e
        _x32 = _x31**2
        _x33 = k_d*m
        _x34 = _x31**3
        d_x = _x31
        d_rad = ((2.0*E_ba*_x32*m - _x31**4*_x33 - _x32*_x33*l0**2 - 2.0*_x34*g_s*m**2*math.cos(d_Q)
            + 2.0*_x34*k_d*l0*m - d_P**2)/_x32)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(bottom_q_r*(bottom_q_r + d_e_next))
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n1_0 = d_e_next
        _n1_1 = bottom_q_th + d_P*d_wq/d_h
        _n1_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n1_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(_n1_0 - d_e) <= 0.0*(l0)) and (abs(_n1_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n1_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n1_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n1_0
        d_Q = _n1_1
        d_P = _n1_2
        d_T = _n1_3
        d_steps += 1.0
        if _conv1:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x35 = q_r_lo**2
    _x36 = k_d*m
    _x37 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x35*m - _x35*_x36*l0**2 - _x36*q_r_lo**4 - 2.0*_x37*g_s*m**2*math.cos(d_Q)
        + 2.0*_x37*k_d*l0*m - d_P**2)/_x35)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x38 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x38*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x38*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_zeroth_gravity_type1`: arguments, out and status
    as :func:`iterative_report_stance_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type1(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_zeroth_geyer`'s.
    """
    # Total ops: 3
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_zeroth_gravity_type1(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length))
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
def iterative_report_apex_return_zeroth_gravity_type1_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_report_apex_return_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_zeroth_gravity_type1(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_zeroth_geyer`'s.
    """
    # Total ops: 272
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN10 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # E_ab (114) of the touchdown state
    _x0 = (0.5)*k_c
    _x1 = q_r_td**2
    _x2 = (0.5)*m
    E_ab = (_x0*_x1 + _x0*l0**2 + _x1*_x2*q_thd_td**2 + _x2*q_rd_td**2 + g_s*m*q_r_td*math.cos(q_th_td)
        - k_c*l0*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[1] != STATUS_OK:
            return _NAN10 + (_c1[1],)
        bottom_q_r = _c1[0]
    else:
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x3 = 4.0**(-iterations)
    _x4 = _x3*(bottom_q_r - q_r_td)
    _x5 = (0.25)*_x4
    _x6 = _x5 + q_r_td
    _x7 = _x6**2
    _x8 = k_c*m
    _x9 = _x6**3
    _x10 = m*z_b_q_r**2*z_b_q_thd
    _x11 = math.sqrt(1.0 - 0.25*_x3)
    _x12 = -_x10 + m*q_r_td**2*q_thd_td
    _x13 = q_th_td - z_b_q_th
    _x14 = ((2.0*E_ab*_x7*m - _x6**4*_x8 - _x7*_x8*l0**2 - 2.0*_x9*g_s*m**2*math.cos(_x11*_x13 + z_b_q_th)
        + 2.0*_x9*k_c*l0*m - (_x10 + _x11*_x12)**2)/_x7)
    _x15 = math.sqrt(1.0 - _x3)
    c_e_n = _x4
    c_e_z = _x5
    c_rad_z = _x14
    c_Q0 = _x13*_x15 + z_b_q_th
    c_P0 = _x10 + _x12*_x15
    c_T0 = ((-_x4*m/math.sqrt(_x14)) if (_x14 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x16 = c_e + q_r_td
        _x17 = _x16**2
        _x18 = k_c*m
        _x19 = _x16**3
        c_x = _x16
        c_rad = ((2.0*E_ab*_x17*m - _x16**4*_x18 - _x17*_x18*l0**2 - 2.0*_x19*g_s*m**2*math.cos(c_Q)
            + 2.0*_x19*k_c*l0*m - c_P**2)/_x17)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        c_h = math.sqrt(c_rad)
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            c_wq = c_e_next/c_x**2
            c_wp = c_e_next*c_x
        elif variant == 1.0:
            c_wq = c_e_next/(q_r_td*(c_e_next + q_r_td))
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n0_0 = c_e_next
        _n0_1 = -c_P*c_wq/c_h + q_th_td
        _n0_2 = m*q_r_td**2*q_thd_td - c_wp*g_s*m**2*math.sin(c_Q)/c_h
        _n0_3 = -c_e_next*m/c_h
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_steps += 1.0
        if _conv0:
            break
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x20 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x21 = (0.25)*_x20
    _x22 = _x21 + bottom_q_r
    _x23 = _x22**2
    _x24 = k_d*m
    _x25 = _x22**3
    _x26 = bottom_q_r**2*bottom_q_thd*m
    _x27 = 4.0**(-0.5*iterations)
    _x28 = _x27*(-_x26 + g_lo_q_thd*m*q_r_lo**2)
    _x29 = _x27*(-bottom_q_th + g_lo_q_th)
    _x30 = ((2.0*E_ba*_x23*m - _x22**4*_x24 - _x23*_x24*l0**2 - 2.0*_x25*g_s*m**2*math.cos((0.5)*_x29
        + bottom_q_th) + 2.0*_x25*k_d*l0*m - (_x26 + (0.5)*_x28)**2)/_x23)
    d_e_n = _x20
    d_e_z = _x21
    d_rad_z = _x30
    d_Q0 = _x29 + bottom_q_th
    d_P0 = _x26 + _x28
    d_T0 = ((_x20*m/math.sqrt(_x30) + t_bottom) if (_x30 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv1 = False
    for _it1 in range(int(iterations)):
        _x31 = bottom_q_r + d_e
        _x32 = _x31**2
        _x33 = k_d*m
        _x34 = _x31**3
        d_x = _x31
        d_rad = ((2.0*E_ba*_x32*m - _x31**4*_x33 - _x32*_x33*l0**2 - 2.0*_x34*g_s*m**2*math.cos(d_Q)
            + 2.0*_x34*k_d*l0*m - d_P**2)/_x32)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(bottom_q_r*(bottom_q_r + d_e_next))
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n1_0 = d_e_next
        _n1_1 = bottom_q_th + d_P*d_wq/d_h
        _n1_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n1_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(_n1_0 - d_e) <= 0.0*(l0)) and (abs(_n1_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n1_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n1_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n1_0
        d_Q = _n1_1
        d_P = _n1_2
        d_T = _n1_3
        d_steps += 1.0
        if _conv1:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x35 = q_r_lo**2
    _x36 = k_d*m
    _x37 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x35*m - _x35*_x36*l0**2 - _x36*q_r_lo**4 - 2.0*_x37*g_s*m**2*math.cos(d_Q)
        + 2.0*_x37*k_d*l0*m - d_P**2)/_x35)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x38 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x38*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x38*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_zeroth_gravity_type2`: arguments, out and status
    as :func:`iterative_report_stance_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type2(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_zeroth_geyer`'s.
    """
    # Total ops: 3
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_zeroth_gravity_type2(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length))
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
def iterative_report_apex_return_zeroth_gravity_type2_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_report_apex_return_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_zeroth_gravity_type2(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_zeroth_geyer`'s.
    """
    # Total ops: 272
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN10 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # E_ab (114) of the touchdown state
    _x0 = (0.5)*k_c
    _x1 = q_r_td**2
    _x2 = (0.5)*m
    E_ab = (_x0*_x1 + _x0*l0**2 + _x1*_x2*q_thd_td**2 + _x2*q_rd_td**2 + g_s*m*q_r_td*math.cos(q_th_td)
        - k_c*l0*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[1] != STATUS_OK:
            return _NAN10 + (_c1[1],)
        bottom_q_r = _c1[0]
    else:
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x3 = 4.0**(-iterations)
    _x4 = _x3*(bottom_q_r - q_r_td)
    _x5 = (0.25)*_x4
    _x6 = _x5 + q_r_td
    _x7 = _x6**2
    _x8 = k_c*m
    _x9 = _x6**3
    _x10 = m*z_b_q_r**2*z_b_q_thd
    _x11 = math.sqrt(1.0 - 0.25*_x3)
    _x12 = -_x10 + m*q_r_td**2*q_thd_td
    _x13 = q_th_td - z_b_q_th
    _x14 = ((2.0*E_ab*_x7*m - _x6**4*_x8 - _x7*_x8*l0**2 - 2.0*_x9*g_s*m**2*math.cos(_x11*_x13 + z_b_q_th)
        + 2.0*_x9*k_c*l0*m - (_x10 + _x11*_x12)**2)/_x7)
    _x15 = math.sqrt(1.0 - _x3)
    c_e_n = _x4
    c_e_z = _x5
    c_rad_z = _x14
    c_Q0 = _x13*_x15 + z_b_q_th
    c_P0 = _x10 + _x12*_x15
    c_T0 = ((-_x4*m/math.sqrt(_x14)) if (_x14 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x16 = c_e + q_r_td
        _x17 = _x16**2
        _x18 = k_c*m
        _x19 = _x16**3
        c_x = _x16
        c_rad = ((2.0*E_ab*_x17*m - _x16**4*_x18 - _x17*_x18*l0**2 - 2.0*_x19*g_s*m**2*math.cos(c_Q)
            + 2.0*_x19*k_c*l0*m - c_P**2)/_x17)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        c_h = math.sqrt(c_rad)
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            c_wq = c_e_next/c_x**2
            c_wp = c_e_next*c_x
        elif variant == 1.0:
            c_wq = c_e_next/(q_r_td*(c_e_next + q_r_td))
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n0_0 = c_e_next
        _n0_1 = -c_P*c_wq/c_h + q_th_td
        _n0_2 = m*q_r_td**2*q_thd_td - c_wp*g_s*m**2*math.sin(c_Q)/c_h
        _n0_3 = -c_e_next*m/c_h
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_steps += 1.0
        if _conv0:
            break
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x20 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x21 = (0.25)*_x20
    _x22 = _x21 + bottom_q_r
    _x23 = _x22**2
    _x24 = k_d*m
    _x25 = _x22**3
    _x26 = bottom_q_r**2*bottom_q_thd*m
    _x27 = 4.0**(-0.5*iterations)
    _x28 = _x27*(-_x26 + g_lo_q_thd*m*q_r_lo**2)
    _x29 = _x27*(-bottom_q_th + g_lo_q_th)
    _x30 = ((2.0*E_ba*_x23*m - _x22**4*_x24 - _x23*_x24*l0**2 - 2.0*_x25*g_s*m**2*math.cos((0.5)*_x29
        + bottom_q_th) + 2.0*_x25*k_d*l0*m - (_x26 + (0.5)*_x28)**2)/_x23)
    d_e_n = _x20
    d_e_z = _x21
    d_rad_z = _x30
    d_Q0 = _x29 + bottom_q_th
    d_P0 = _x26 + _x28
    d_T0 = ((_x20*m/math.sqrt(_x30) + t_bottom) if (_x30 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv1 = False
    for _it1 in range(int(iterations)):
        _x31 = bottom_q_r + d_e
        _x32 = _x31**2
        _x33 = k_d*m
        _x34 = _x31**3
        d_x = _x31
        d_rad = ((2.0*E_ba*_x32*m - _x31**4*_x33 - _x32*_x33*l0**2 - 2.0*_x34*g_s*m**2*math.cos(d_Q)
            + 2.0*_x34*k_d*l0*m - d_P**2)/_x32)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(bottom_q_r*(bottom_q_r + d_e_next))
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n1_0 = d_e_next
        _n1_1 = bottom_q_th + d_P*d_wq/d_h
        _n1_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n1_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(_n1_0 - d_e) <= 0.0*(l0)) and (abs(_n1_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n1_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n1_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n1_0
        d_Q = _n1_1
        d_P = _n1_2
        d_T = _n1_3
        d_steps += 1.0
        if _conv1:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x35 = q_r_lo**2
    _x36 = k_d*m
    _x37 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x35*m - _x35*_x36*l0**2 - _x36*q_r_lo**4 - 2.0*_x37*g_s*m**2*math.cos(d_Q)
        + 2.0*_x37*k_d*l0*m - d_P**2)/_x35)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x38 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x38*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x38*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_zeroth_gravity_type3`: arguments, out and status
    as :func:`iterative_report_stance_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type3(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_zeroth_geyer`'s.
    """
    # Total ops: 3
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_zeroth_gravity_type3(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length))
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
def iterative_report_apex_return_zeroth_gravity_type3_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_report_apex_return_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_zeroth_gravity_type3(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_zeroth_geyer`'s.
    """
    # Total ops: 272
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN10 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # E_ab (114) of the touchdown state
    _x0 = (0.5)*k_c
    _x1 = q_r_td**2
    _x2 = (0.5)*m
    E_ab = (_x0*_x1 + _x0*l0**2 + _x1*_x2*q_thd_td**2 + _x2*q_rd_td**2 + g_s*m*q_r_td*math.cos(q_th_td)
        - k_c*l0*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[1] != STATUS_OK:
            return _NAN10 + (_c1[1],)
        bottom_q_r = _c1[0]
    else:
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x3 = 4.0**(-iterations)
    _x4 = _x3*(bottom_q_r - q_r_td)
    _x5 = (0.25)*_x4
    _x6 = _x5 + q_r_td
    _x7 = _x6**2
    _x8 = k_c*m
    _x9 = _x6**3
    _x10 = m*z_b_q_r**2*z_b_q_thd
    _x11 = math.sqrt(1.0 - 0.25*_x3)
    _x12 = -_x10 + m*q_r_td**2*q_thd_td
    _x13 = q_th_td - z_b_q_th
    _x14 = ((2.0*E_ab*_x7*m - _x6**4*_x8 - _x7*_x8*l0**2 - 2.0*_x9*g_s*m**2*math.cos(_x11*_x13 + z_b_q_th)
        + 2.0*_x9*k_c*l0*m - (_x10 + _x11*_x12)**2)/_x7)
    _x15 = math.sqrt(1.0 - _x3)
    c_e_n = _x4
    c_e_z = _x5
    c_rad_z = _x14
    c_Q0 = _x13*_x15 + z_b_q_th
    c_P0 = _x10 + _x12*_x15
    c_T0 = ((-_x4*m/math.sqrt(_x14)) if (_x14 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x16 = c_e + q_r_td
        _x17 = _x16**2
        _x18 = k_c*m
        _x19 = _x16**3
        c_x = _x16
        c_rad = ((2.0*E_ab*_x17*m - _x16**4*_x18 - _x17*_x18*l0**2 - 2.0*_x19*g_s*m**2*math.cos(c_Q)
            + 2.0*_x19*k_c*l0*m - c_P**2)/_x17)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        c_h = math.sqrt(c_rad)
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            c_wq = c_e_next/c_x**2
            c_wp = c_e_next*c_x
        elif variant == 1.0:
            c_wq = c_e_next/(q_r_td*(c_e_next + q_r_td))
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n0_0 = c_e_next
        _n0_1 = -c_P*c_wq/c_h + q_th_td
        _n0_2 = m*q_r_td**2*q_thd_td - c_wp*g_s*m**2*math.sin(c_Q)/c_h
        _n0_3 = -c_e_next*m/c_h
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_steps += 1.0
        if _conv0:
            break
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x20 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x21 = (0.25)*_x20
    _x22 = _x21 + bottom_q_r
    _x23 = _x22**2
    _x24 = k_d*m
    _x25 = _x22**3
    _x26 = bottom_q_r**2*bottom_q_thd*m
    _x27 = 4.0**(-0.5*iterations)
    _x28 = _x27*(-_x26 + g_lo_q_thd*m*q_r_lo**2)
    _x29 = _x27*(-bottom_q_th + g_lo_q_th)
    _x30 = ((2.0*E_ba*_x23*m - _x22**4*_x24 - _x23*_x24*l0**2 - 2.0*_x25*g_s*m**2*math.cos((0.5)*_x29
        + bottom_q_th) + 2.0*_x25*k_d*l0*m - (_x26 + (0.5)*_x28)**2)/_x23)
    d_e_n = _x20
    d_e_z = _x21
    d_rad_z = _x30
    d_Q0 = _x29 + bottom_q_th
    d_P0 = _x26 + _x28
    d_T0 = ((_x20*m/math.sqrt(_x30) + t_bottom) if (_x30 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv1 = False
    for _it1 in range(int(iterations)):
        _x31 = bottom_q_r + d_e
        _x32 = _x31**2
        _x33 = k_d*m
        _x34 = _x31**3
        d_x = _x31
        d_rad = ((2.0*E_ba*_x32*m - _x31**4*_x33 - _x32*_x33*l0**2 - 2.0*_x34*g_s*m**2*math.cos(d_Q)
            + 2.0*_x34*k_d*l0*m - d_P**2)/_x32)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(bottom_q_r*(bottom_q_r + d_e_next))
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n1_0 = d_e_next
        _n1_1 = bottom_q_th + d_P*d_wq/d_h
        _n1_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n1_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(_n1_0 - d_e) <= 0.0*(l0)) and (abs(_n1_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n1_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n1_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n1_0
        d_Q = _n1_1
        d_P = _n1_2
        d_T = _n1_3
        d_steps += 1.0
        if _conv1:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x35 = q_r_lo**2
    _x36 = k_d*m
    _x37 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x35*m - _x35*_x36*l0**2 - _x36*q_r_lo**4 - 2.0*_x37*g_s*m**2*math.cos(d_Q)
        + 2.0*_x37*k_d*l0*m - d_P**2)/_x35)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x38 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x38*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x38*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_zeroth_gravity_type4`: arguments, out and status
    as :func:`iterative_report_stance_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type4(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_zeroth_geyer`'s.
    """
    # Total ops: 3
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_zeroth_gravity_type4(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length))
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
def iterative_report_apex_return_zeroth_gravity_type4_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_report_apex_return_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_zeroth_gravity_type4(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_zeroth_geyer`'s.
    """
    # Total ops: 272
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN10 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # E_ab (114) of the touchdown state
    _x0 = (0.5)*k_c
    _x1 = q_r_td**2
    _x2 = (0.5)*m
    E_ab = (_x0*_x1 + _x0*l0**2 + _x1*_x2*q_thd_td**2 + _x2*q_rd_td**2 + g_s*m*q_r_td*math.cos(q_th_td)
        - k_c*l0*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[1] != STATUS_OK:
            return _NAN10 + (_c1[1],)
        bottom_q_r = _c1[0]
    else:
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x3 = 4.0**(-iterations)
    _x4 = _x3*(bottom_q_r - q_r_td)
    _x5 = (0.25)*_x4
    _x6 = _x5 + q_r_td
    _x7 = _x6**2
    _x8 = k_c*m
    _x9 = _x6**3
    _x10 = m*z_b_q_r**2*z_b_q_thd
    _x11 = math.sqrt(1.0 - 0.25*_x3)
    _x12 = -_x10 + m*q_r_td**2*q_thd_td
    _x13 = q_th_td - z_b_q_th
    _x14 = ((2.0*E_ab*_x7*m - _x6**4*_x8 - _x7*_x8*l0**2 - 2.0*_x9*g_s*m**2*math.cos(_x11*_x13 + z_b_q_th)
        + 2.0*_x9*k_c*l0*m - (_x10 + _x11*_x12)**2)/_x7)
    _x15 = math.sqrt(1.0 - _x3)
    c_e_n = _x4
    c_e_z = _x5
    c_rad_z = _x14
    c_Q0 = _x13*_x15 + z_b_q_th
    c_P0 = _x10 + _x12*_x15
    c_T0 = ((-_x4*m/math.sqrt(_x14)) if (_x14 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x16 = c_e + q_r_td
        _x17 = _x16**2
        _x18 = k_c*m
        _x19 = _x16**3
        c_x = _x16
        c_rad = ((2.0*E_ab*_x17*m - _x16**4*_x18 - _x17*_x18*l0**2 - 2.0*_x19*g_s*m**2*math.cos(c_Q)
            + 2.0*_x19*k_c*l0*m - c_P**2)/_x17)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        c_h = math.sqrt(c_rad)
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            c_wq = c_e_next/c_x**2
            c_wp = c_e_next*c_x
        elif variant == 1.0:
            c_wq = c_e_next/(q_r_td*(c_e_next + q_r_td))
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n0_0 = c_e_next
        _n0_1 = -c_P*c_wq/c_h + q_th_td
        _n0_2 = m*q_r_td**2*q_thd_td - c_wp*g_s*m**2*math.sin(c_Q)/c_h
        _n0_3 = -c_e_next*m/c_h
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_steps += 1.0
        if _conv0:
            break
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x20 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x21 = (0.25)*_x20
    _x22 = _x21 + bottom_q_r
    _x23 = _x22**2
    _x24 = k_d*m
    _x25 = _x22**3
    _x26 = bottom_q_r**2*bottom_q_thd*m
    _x27 = 4.0**(-0.5*iterations)
    _x28 = _x27*(-_x26 + g_lo_q_thd*m*q_r_lo**2)
    _x29 = _x27*(-bottom_q_th + g_lo_q_th)
    _x30 = ((2.0*E_ba*_x23*m - _x22**4*_x24 - _x23*_x24*l0**2 - 2.0*_x25*g_s*m**2*math.cos((0.5)*_x29
        + bottom_q_th) + 2.0*_x25*k_d*l0*m - (_x26 + (0.5)*_x28)**2)/_x23)
    d_e_n = _x20
    d_e_z = _x21
    d_rad_z = _x30
    d_Q0 = _x29 + bottom_q_th
    d_P0 = _x26 + _x28
    d_T0 = ((_x20*m/math.sqrt(_x30) + t_bottom) if (_x30 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv1 = False
    for _it1 in range(int(iterations)):
        _x31 = bottom_q_r + d_e
        _x32 = _x31**2
        _x33 = k_d*m
        _x34 = _x31**3
        d_x = _x31
        d_rad = ((2.0*E_ba*_x32*m - _x31**4*_x33 - _x32*_x33*l0**2 - 2.0*_x34*g_s*m**2*math.cos(d_Q)
            + 2.0*_x34*k_d*l0*m - d_P**2)/_x32)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(bottom_q_r*(bottom_q_r + d_e_next))
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n1_0 = d_e_next
        _n1_1 = bottom_q_th + d_P*d_wq/d_h
        _n1_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n1_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(_n1_0 - d_e) <= 0.0*(l0)) and (abs(_n1_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n1_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n1_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n1_0
        d_Q = _n1_1
        d_P = _n1_2
        d_T = _n1_3
        d_steps += 1.0
        if _conv1:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x35 = q_r_lo**2
    _x36 = k_d*m
    _x37 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x35*m - _x35*_x36*l0**2 - _x36*q_r_lo**4 - 2.0*_x37*g_s*m**2*math.cos(d_Q)
        + 2.0*_x37*k_d*l0*m - d_P**2)/_x35)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x38 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x38*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x38*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_zeroth_gravity_type5`: arguments, out and status
    as :func:`iterative_report_stance_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type5(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_zeroth_geyer`'s.
    """
    # Total ops: 3
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_zeroth_gravity_type5(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d,
        g_s, q_r_lo, variant, iterations, bottom_length))
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
def iterative_report_apex_return_zeroth_gravity_type5_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c,
        k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_report_apex_return_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_zeroth_gravity_type5(b_y_apex[i], b_xd_apex[i], q_th_td[i],
            ground[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo,
        variant, iterations, bottom_length):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_stance_zeroth_geyer`'s.
    """
    # Total ops: 272
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(variant)
            and math.isfinite(iterations) and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td
            > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0))
            and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((variant == 0.0)
            or (variant == 1.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN10 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # E_ab (114) of the touchdown state
    _x0 = (0.5)*k_c
    _x1 = q_r_td**2
    _x2 = (0.5)*m
    E_ab = (_x0*_x1 + _x0*l0**2 + _x1*_x2*q_thd_td**2 + _x2*q_rd_td**2 + g_s*m*q_r_td*math.cos(q_th_td)
        - k_c*l0*q_r_td)
    # bottom leg length
    if bottom_length == 0.0:
        bottom_q_r = z_b_q_r
    elif bottom_length == 1.0:
        # (153): the vertical bottom's quartic
        _c1 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c1[1] != STATUS_OK:
            return _NAN10 + (_c1[1],)
        bottom_q_r = _c1[0]
    else:
        return _NAN10 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x3 = 4.0**(-iterations)
    _x4 = _x3*(bottom_q_r - q_r_td)
    _x5 = (0.25)*_x4
    _x6 = _x5 + q_r_td
    _x7 = _x6**2
    _x8 = k_c*m
    _x9 = _x6**3
    _x10 = m*z_b_q_r**2*z_b_q_thd
    _x11 = math.sqrt(1.0 - 0.25*_x3)
    _x12 = -_x10 + m*q_r_td**2*q_thd_td
    _x13 = q_th_td - z_b_q_th
    _x14 = ((2.0*E_ab*_x7*m - _x6**4*_x8 - _x7*_x8*l0**2 - 2.0*_x9*g_s*m**2*math.cos(_x11*_x13 + z_b_q_th)
        + 2.0*_x9*k_c*l0*m - (_x10 + _x11*_x12)**2)/_x7)
    _x15 = math.sqrt(1.0 - _x3)
    c_e_n = _x4
    c_e_z = _x5
    c_rad_z = _x14
    c_Q0 = _x13*_x15 + z_b_q_th
    c_P0 = _x10 + _x12*_x15
    c_T0 = ((-_x4*m/math.sqrt(_x14)) if (_x14 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((c_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    c_e = c_e_n
    c_Q = c_Q0
    c_P = c_P0
    c_T = c_T0
    c_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x16 = c_e + q_r_td
        _x17 = _x16**2
        _x18 = k_c*m
        _x19 = _x16**3
        c_x = _x16
        c_rad = ((2.0*E_ab*_x17*m - _x16**4*_x18 - _x17*_x18*l0**2 - 2.0*_x19*g_s*m**2*math.cos(c_Q)
            + 2.0*_x19*k_c*l0*m - c_P**2)/_x17)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((c_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        c_h = math.sqrt(c_rad)
        c_e_next = 4.0*c_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            c_wq = c_e_next/c_x**2
            c_wp = c_e_next*c_x
        elif variant == 1.0:
            c_wq = c_e_next/(q_r_td*(c_e_next + q_r_td))
            c_wp = (0.5)*c_e_next*(c_e_next + 2.0*q_r_td)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n0_0 = c_e_next
        _n0_1 = -c_P*c_wq/c_h + q_th_td
        _n0_2 = m*q_r_td**2*q_thd_td - c_wp*g_s*m**2*math.sin(c_Q)/c_h
        _n0_3 = -c_e_next*m/c_h
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - c_e) <= 0.0*(l0)) and (abs(_n0_1 - c_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - c_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - c_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        c_e = _n0_0
        c_Q = _n0_1
        c_P = _n0_2
        c_T = _n0_3
        c_steps += 1.0
        if _conv0:
            break
    # bottom state (p_r = 0)
    t_bottom = c_T
    bottom_q_rd = 0.0
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    g_lo_q_th = z_lo_q_th
    g_lo_q_thd = z_lo_q_thd
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x20 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x21 = (0.25)*_x20
    _x22 = _x21 + bottom_q_r
    _x23 = _x22**2
    _x24 = k_d*m
    _x25 = _x22**3
    _x26 = bottom_q_r**2*bottom_q_thd*m
    _x27 = 4.0**(-0.5*iterations)
    _x28 = _x27*(-_x26 + g_lo_q_thd*m*q_r_lo**2)
    _x29 = _x27*(-bottom_q_th + g_lo_q_th)
    _x30 = ((2.0*E_ba*_x23*m - _x22**4*_x24 - _x23*_x24*l0**2 - 2.0*_x25*g_s*m**2*math.cos((0.5)*_x29
        + bottom_q_th) + 2.0*_x25*k_d*l0*m - (_x26 + (0.5)*_x28)**2)/_x23)
    d_e_n = _x20
    d_e_z = _x21
    d_rad_z = _x30
    d_Q0 = _x29 + bottom_q_th
    d_P0 = _x26 + _x28
    d_T0 = ((_x20*m/math.sqrt(_x30) + t_bottom) if (_x30 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv1 = False
    for _it1 in range(int(iterations)):
        _x31 = bottom_q_r + d_e
        _x32 = _x31**2
        _x33 = k_d*m
        _x34 = _x31**3
        d_x = _x31
        d_rad = ((2.0*E_ba*_x32*m - _x31**4*_x33 - _x32*_x33*l0**2 - 2.0*_x34*g_s*m**2*math.cos(d_Q)
            + 2.0*_x34*k_d*l0*m - d_P**2)/_x32)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(bottom_q_r*(bottom_q_r + d_e_next))
            d_wp = (0.5)*d_e_next*(2.0*bottom_q_r + d_e_next)
        else:
            return _NAN10 + (STATUS_INVALID_INPUT,)
        _n1_0 = d_e_next
        _n1_1 = bottom_q_th + d_P*d_wq/d_h
        _n1_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n1_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv1 = (0.0 > 0.0 and (abs(_n1_0 - d_e) <= 0.0*(l0)) and (abs(_n1_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n1_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n1_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n1_0
        d_Q = _n1_1
        d_P = _n1_2
        d_T = _n1_3
        d_steps += 1.0
        if _conv1:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x35 = q_r_lo**2
    _x36 = k_d*m
    _x37 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x35*m - _x35*_x36*l0**2 - _x36*q_r_lo**4 - 2.0*_x37*g_s*m**2*math.cos(d_Q)
        + 2.0*_x37*k_d*l0*m - d_P**2)/_x35)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x38 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x38*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x38*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r)
            and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd)
            and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th)
            and math.isfinite(liftoff_q_thd)):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_report_stance_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_stance_zeroth_geyer_vs`: arguments, out and status as
    :func:`iterative_report_stance_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_stance_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0,
            k_c, k_d, g_s, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_geyer_vs(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d, g_s,
        g_f, q_r_td, q_r_lo, variant, iterations, bottom_length):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Arguments, returns and status: the same as :func:`iterative_report_apex_return_zeroth_geyer`'s.
    """
    # Total ops: 3
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
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _c1 = (iterative_report_stance_zeroth_geyer_vs(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s,
        q_r_lo, variant, iterations, bottom_length))
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
def iterative_report_apex_return_zeroth_geyer_vs_batch(b_y_apex, b_xd_apex, q_th_td, ground, m, l0, k_c, k_d,
        g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length, out, status):
    """Parallel batch form of :func:`iterative_report_apex_return_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_report_apex_return_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_report_apex_return_zeroth_geyer_vs(b_y_apex[i], b_xd_apex[i], q_th_td[i], ground[i],
            m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], out[i, 6], out[i, 7], out[i, 8],
            out[i, 9], out[i, 10], out[i, 11], status[i]) = res
