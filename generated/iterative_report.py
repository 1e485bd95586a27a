# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative_report.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight.py sha256:af908ea30b1fc141
#   geyer_vs.py sha256:ef01b987d9b927b3
#   iterative.py sha256:6c68b56d8ea0aa73
# ----------------------------------------------------------------------------------------------
"""Iterative stance map (Schwind and Koditschek, as printed) (report section 3.2): stance, state-at-time and
apex-return kernels."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import apex_to_touchdown, liftoff_to_apex
from .geyer_vs import bottom_quartic
from .iterative import (zeroth_geyer, zeroth_geyer_vs, zeroth_gravity_type0, zeroth_gravity_type1,
    zeroth_gravity_type2, zeroth_gravity_type3, zeroth_gravity_type4, zeroth_gravity_type5, zeroth_held)

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_NUMERICAL_RANGE, STATUS_IMAGINARY_MOMENTUM)

NAN = math.nan
_NAN6 = (NAN,) * 6
_NAN10 = (NAN,) * 10


@njit(cache=True, error_model="numpy")
def report_compression(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th, z_b_q_thd,
        variant, iterations, bottom_length):
    """Schwind and Koditschek's iteration as printed, compression half from a zeroth iterate's bottom.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        z_b_q_r: zeroth iterate: z_b_q_r
        z_b_q_th: zeroth iterate: z_b_q_th
        z_b_q_thd: zeroth iterate: z_b_q_thd
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]
        bottom_length: option bottom_length: the bottom leg length q_r_b the chains run to and from (section
            5.2, closing estimates): 0 = zeroth, 1 = eq153

    Returns a tuple:
        t_bottom: time from touchdown to the bottom [s]
        bottom_q_r: leg length [m]
        bottom_q_rd: leg length rate [m/s]
        bottom_q_th: leg angle from the vertical, counterclockwise positive [rad]
        bottom_q_thd: leg angle rate [rad/s]
        E_ab: the energy (114) of the touchdown state [J]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 130
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return _NAN6 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
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
        _c0 = bottom_quartic(m*q_r_td**2*q_thd_td, E_ab, m, l0, k_c, g_s)
        if _c0[1] != STATUS_OK:
            return _NAN6 + (_c0[1],)
        bottom_q_r = _c0[0]
    else:
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # bottom leg length q_r_b > 0
    if not ((bottom_q_r > 0.0)):
        return _NAN6 + (STATUS_FALL,)
    # bottom below touchdown
    if not ((-bottom_q_r + q_r_td > 0.0)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
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
        return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
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
            return _NAN6 + (STATUS_IMAGINARY_MOMENTUM,)
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
            return _NAN6 + (STATUS_INVALID_INPUT,)
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
    bottom_q_th = c_Q
    bottom_q_thd = c_P/(bottom_q_r**2*m)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_bottom, bottom_q_r, bottom_q_th, bottom_q_thd, E_ab,))):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, bottom_q_r, 0.0, bottom_q_th, bottom_q_thd, E_ab, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def report_core(_a):
    """Schwind and Koditschek's iteration as printed: the stance from the touchdown state and a zeroth
    iterate.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

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
        z_b_q_r: zeroth iterate: z_b_q_r
        z_b_q_th: zeroth iterate: z_b_q_th
        z_b_q_thd: zeroth iterate: z_b_q_thd
        z_lo_q_th: zeroth iterate: z_lo_q_th
        z_lo_q_thd: zeroth iterate: z_lo_q_thd
        held: 1 when the zeroth iterate is the held touchdown state, else 0
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
    # Total ops: 149
    (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, z_b_q_r, z_b_q_th, z_b_q_thd,
        z_lo_q_th, z_lo_q_thd, held, variant, iterations, bottom_length,) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7,
        8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18))
    # the compression half as printed
    _c0 = (report_compression(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, variant, iterations, bottom_length))
    if _c0[6] != STATUS_OK:
        return _NAN10 + (_c0[6],)
    t_bottom = _c0[0]
    bottom_q_r = _c0[1]
    bottom_q_rd = _c0[2]
    bottom_q_th = _c0[3]
    bottom_q_thd = _c0[4]
    E_ab = _c0[5]
    # E_ba of (98): the energy jump of the stiffness switch
    E_ba = E_ab + (-bottom_q_r + l0)**2*(-0.5*k_c + (0.5)*k_d)
    # zeroth iterate at liftoff
    _x0 = (held == 1.0)
    g_lo_q_th = ((bottom_q_th) if _x0 else (z_lo_q_th))
    g_lo_q_thd = ((bottom_q_r**2*bottom_q_thd/q_r_lo**2) if _x0 else (z_lo_q_thd))
    # bottom below q_r_lo
    if not ((-bottom_q_r + q_r_lo > 0.0)):
        return _NAN10 + (STATUS_NO_LIFTOFF,)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x1 = 4.0**(-iterations)*(-bottom_q_r + q_r_lo)
    _x2 = (0.25)*_x1
    _x3 = _x2 + bottom_q_r
    _x4 = _x3**2
    _x5 = k_d*m
    _x6 = _x3**3
    _x7 = bottom_q_r**2*bottom_q_thd*m
    _x8 = 4.0**(-0.5*iterations)
    _x9 = _x8*(-_x7 + g_lo_q_thd*m*q_r_lo**2)
    _x10 = _x8*(-bottom_q_th + g_lo_q_th)
    _x11 = ((2.0*E_ba*_x4*m - _x3**4*_x5 - _x4*_x5*l0**2 - 2.0*_x6*g_s*m**2*math.cos((0.5)*_x10 + bottom_q_th)
        + 2.0*_x6*k_d*l0*m - (_x7 + (0.5)*_x9)**2)/_x4)
    d_e_n = _x1
    d_e_z = _x2
    d_rad_z = _x11
    d_Q0 = _x10 + bottom_q_th
    d_P0 = _x7 + _x9
    d_T0 = ((_x1*m/math.sqrt(_x11) + t_bottom) if (_x11 > 0.0) else (t_bottom))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x12 = bottom_q_r + d_e
        _x13 = _x12**2
        _x14 = k_d*m
        _x15 = _x12**3
        d_x = _x12
        d_rad = ((2.0*E_ba*_x13*m - _x12**4*_x14 - _x13*_x14*l0**2 - 2.0*_x15*g_s*m**2*math.cos(d_Q)
            + 2.0*_x15*k_d*l0*m - d_P**2)/_x13)
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
        _n0_0 = d_e_next
        _n0_1 = bottom_q_th + d_P*d_wq/d_h
        _n0_2 = bottom_q_r**2*bottom_q_thd*m + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n0_3 = d_e_next*m/d_h + t_bottom
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (0.0 > 0.0 and (abs(_n0_0 - d_e) <= 0.0*(l0)) and (abs(_n0_1 - d_Q) <= 0.0*(1.0))
            and (abs(_n0_2 - d_P) <= 0.0*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m)) and (abs(_n0_3 - d_T)
            <= 0.0*(math.sqrt(l0)/math.sqrt(g_s))))
        d_e = _n0_0
        d_Q = _n0_1
        d_P = _n0_2
        d_T = _n0_3
        d_steps += 1.0
        if _conv0:
            break
    # (45) corrected: p_r of the iterate at q_r_lo
    _x16 = q_r_lo**2
    _x17 = k_d*m
    _x18 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x16*m - _x16*_x17*l0**2 - _x17*q_r_lo**4 - 2.0*_x18*g_s*m**2*math.cos(d_Q)
        + 2.0*_x18*k_d*l0*m - d_P**2)/_x16)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return _NAN10 + (STATUS_IMAGINARY_MOMENTUM,)
    # liftoff state
    _x19 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x19*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x19*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN10 + (STATUS_FALL,)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
            liftoff_q_rd, liftoff_q_th, liftoff_q_thd,))):
        return _NAN10 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def iterative_report_stance_zeroth_shared(x, p, out, zeroth, constant0):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    The body that 9 kernels share, each passing the kernel it calls as zeroth and its constant
    as constant0 (derive/share.py): iterative_report_stance_zeroth_{geyer, held, gravity_type0,
    gravity_type1, gravity_type2, gravity_type3, gravity_type4, gravity_type5, geyer_vs}.

    Arguments, returns and status: those of the kernels, then zeroth, constant0.
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
    _c0 = zeroth(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo)
    if _c0[5] != STATUS_OK:
        return fail(out, _c0[5])
    z_b_q_r = _c0[0]
    z_b_q_th = _c0[1]
    z_b_q_thd = _c0[2]
    z_lo_q_th = _c0[3]
    z_lo_q_thd = _c0[4]
    # the iteration from the zeroth iterate
    _a1 = carray(stack(19), 19)
    store(_a1, (q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, z_b_q_r, z_b_q_th,
        z_b_q_thd, z_lo_q_th, z_lo_q_thd, constant0, variant, iterations, bottom_length,))
    _c1 = report_core(_a1)
    if _c1[10] != STATUS_OK:
        return fail(out, _c1[10])
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
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
            liftoff_q_rd, liftoff_q_th, liftoff_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_geyer(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Runs the shared body :func:`iterative_report_stance_zeroth_shared` with zeroth_geyer, 0.0.

    (42)-(44)/(124)-(126)/(139)-(141) or (133)-(135)/(148)-(150) with (134)/(149) keeping p_th;
    liftoff p_r = H^{-1} at q_r_lo ((45) corrected); E_ba of (98). IMAGINARY_MOMENTUM wherever
    H^{-1} of an iterate is imaginary.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

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

    Writes into out:
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
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return iterative_report_stance_zeroth_shared(x, p, out, zeroth_geyer, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline="always")
def iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    The body that 9 kernels share, each passing the kernel it calls as
    iterative_report_stance_zeroth (derive/share.py):
    iterative_report_apex_return_zeroth_{geyer, held, gravity_type0, gravity_type1,
    gravity_type2, gravity_type3, gravity_type4, gravity_type5, geyer_vs}.

    Arguments, returns and status: those of the kernels, then iterative_report_stance_zeroth.
    """
    # Total ops: 3
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
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, retraction_rate)
    if _c0[6] != STATUS_OK:
        return fail(out, _c0[6])
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    foot_x = _c0[5]
    # stance: Iterative stance map (Schwind and Koditschek, as printed)
    _x1 = carray(stack(4), 4)
    store(_x1, (td_q_r, td_q_rd, td_q_th, td_q_thd,))
    _o1 = carray(stack(10), 10)
    _c1 = iterative_report_stance_zeroth(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,) = load(_o1, 1, 6, 7, 8, 9)
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c2[5] != STATUS_OK:
        return fail(out, _c2[5])
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    next_apex_x = _c2[4]
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    foot_y = -b_y_apex + ground
    touchdown_q_th = td_q_th
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((apex_height, apex_speed, t_descent, _o1_1, t_ascent, liftoff_q_r, liftoff_q_rd,
            liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (apex_height, apex_speed, t_descent, _o1_1, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_geyer(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Report equations: 27, 29, 30, 31, 32, 33, 35, 37, 38, 39, 40, 41, 42, 43, 44, 45, 98, 114, 115, 116, 117,
    118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131, 132, 133, 134, 135, 137, 138, 139, 140,
    141, 143, 144, 145, 146, 147, 148, 149, 150, 154.

    Runs the shared body :func:`iterative_report_apex_return_zeroth_shared` with
    iterative_report_stance_zeroth_geyer.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, variant, iterations, bottom_length); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments:
        b_y_apex: apex height of the body above the ground under it b_y_apex [m], >= 0
        b_xd_apex: horizontal apex speed, signed: negative runs toward -x (the mirror image of running toward
            +x, with the touchdown angle mirrored too); 0 is a hop in place b_xd_apex [m/s]
        q_th_td: touchdown leg angle from the vertical, counterclockwise positive q_th_td [rad]
        ground: height of the touchdown ground above the ground under the apex (a step up is positive) ground
            [m]
        retraction_rate: swing-leg retraction rate: after the apex the leg angle is touchdown_angle +
            retraction_rate * t (counterclockwise positive like the angle: a forward runner's retracting leg
            has a negative rate; Seyfarth, Geyer and Herr 2003); 0 holds the leg at touchdown_angle
            retraction_rate [rad/s]
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

    Writes into out:
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
        touchdown_q_th: leg angle the foot touched down with: touchdown_angle + retraction_rate * t_descent
            [rad]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth_geyer)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_held(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_report_stance_zeroth_shared` with zeroth_held, 1.0.
    Equations, arguments, returns and status: those of
    :func:`iterative_report_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_stance_zeroth_shared(x, p, out, zeroth_held, 1.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_held(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Runs the shared body :func:`iterative_report_apex_return_zeroth_shared` with
    iterative_report_stance_zeroth_held. Equations, arguments, returns and status: those of
    :func:`iterative_report_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth_held)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type0(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_report_stance_zeroth_shared` with
    zeroth_gravity_type0, 0.0. Equations, arguments, returns and status: those of
    :func:`iterative_report_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_stance_zeroth_shared(x, p, out, zeroth_gravity_type0, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type0(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Runs the shared body :func:`iterative_report_apex_return_zeroth_shared` with
    iterative_report_stance_zeroth_gravity_type0. Equations, arguments, returns and status:
    those of :func:`iterative_report_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth_gravity_type0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type1(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_report_stance_zeroth_shared` with
    zeroth_gravity_type1, 0.0. Equations, arguments, returns and status: those of
    :func:`iterative_report_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_stance_zeroth_shared(x, p, out, zeroth_gravity_type1, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type1(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Runs the shared body :func:`iterative_report_apex_return_zeroth_shared` with
    iterative_report_stance_zeroth_gravity_type1. Equations, arguments, returns and status:
    those of :func:`iterative_report_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth_gravity_type1)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type2(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_report_stance_zeroth_shared` with
    zeroth_gravity_type2, 0.0. Equations, arguments, returns and status: those of
    :func:`iterative_report_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_stance_zeroth_shared(x, p, out, zeroth_gravity_type2, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type2(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Runs the shared body :func:`iterative_report_apex_return_zeroth_shared` with
    iterative_report_stance_zeroth_gravity_type2. Equations, arguments, returns and status:
    those of :func:`iterative_report_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth_gravity_type2)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type3(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_report_stance_zeroth_shared` with
    zeroth_gravity_type3, 0.0. Equations, arguments, returns and status: those of
    :func:`iterative_report_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_stance_zeroth_shared(x, p, out, zeroth_gravity_type3, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type3(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Runs the shared body :func:`iterative_report_apex_return_zeroth_shared` with
    iterative_report_stance_zeroth_gravity_type3. Equations, arguments, returns and status:
    those of :func:`iterative_report_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth_gravity_type3)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type4(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_report_stance_zeroth_shared` with
    zeroth_gravity_type4, 0.0. Equations, arguments, returns and status: those of
    :func:`iterative_report_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_stance_zeroth_shared(x, p, out, zeroth_gravity_type4, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type4(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Runs the shared body :func:`iterative_report_apex_return_zeroth_shared` with
    iterative_report_stance_zeroth_gravity_type4. Equations, arguments, returns and status:
    those of :func:`iterative_report_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth_gravity_type4)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type5(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_report_stance_zeroth_shared` with
    zeroth_gravity_type5, 0.0. Equations, arguments, returns and status: those of
    :func:`iterative_report_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_stance_zeroth_shared(x, p, out, zeroth_gravity_type5, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type5(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Runs the shared body :func:`iterative_report_apex_return_zeroth_shared` with
    iterative_report_stance_zeroth_gravity_type5. Equations, arguments, returns and status:
    those of :func:`iterative_report_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth_gravity_type5)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_stance_zeroth_geyer_vs(x, p, out):
    """Iterative stance map (Schwind and Koditschek, as printed): touchdown state -> bottom and liftoff
    states.

    Runs the shared body :func:`iterative_report_stance_zeroth_shared` with zeroth_geyer_vs,
    0.0. Equations, arguments, returns and status: those of
    :func:`iterative_report_stance_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_stance_zeroth_shared(x, p, out, zeroth_geyer_vs, 0.0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_stance_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_stance_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_stance_zeroth_geyer_vs(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_apex_return_zeroth_geyer_vs(x, p, out):
    """Apex-return map: exact flights, stance by Iterative stance map (Schwind and Koditschek, as printed).

    Runs the shared body :func:`iterative_report_apex_return_zeroth_shared` with
    iterative_report_stance_zeroth_geyer_vs. Equations, arguments, returns and status: those of
    :func:`iterative_report_apex_return_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_apex_return_zeroth_shared(x, p, out, iterative_report_stance_zeroth_geyer_vs)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_apex_return_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_apex_return_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_apex_return_zeroth_geyer_vs(row(X, i), p, row(OUT, i))
