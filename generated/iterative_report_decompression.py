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
# ----------------------------------------------------------------------------------------------
"""Iterative decompression half as printed (bottom to liftoff, k_d) (report section 5.2.2): bottom ->
liftoff."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import liftoff_to_apex

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_NO_LIFTOFF, STATUS_FALL, STATUS_NUMERICAL_RANGE,
    STATUS_IMAGINARY_MOMENTUM)

NAN = math.nan


@njit(cache=True, error_model="numpy")
def iterative_report_decompression(x, p, out):
    """Iterative decompression half as printed (bottom to liftoff, k_d): bottom state -> liftoff state.

    Report equations: 137, 138, 139, 140, 141, 143, 144, 145, 146, 147, 148, 149, 150.

    Role kernel: reads x = (q_r_b, q_rd_b, q_th_b, q_thd_b) and the parameter record
    p = (m, l0, k_d, g_s, q_r_lo, variant, iterations); writes the outputs below into out, in order, and
    returns
    the status (out all NaN unless OK).

    Arguments:
        q_r_b: bottom leg length [m], > 0
        q_rd_b: bottom leg length rate [m/s] (not read: 0 at the bottom)
        q_th_b: bottom leg angle from the vertical, counterclockwise positive [rad], |q_th_b| < pi/2
        q_thd_b: bottom leg angle rate [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]

    Writes into out:
        t_half: time from the start state to the end state [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 140
    (q_r_b, q_rd_b, q_th_b, q_thd_b,) = load(x, 0, 1, 2, 3)
    (m, l0, k_d, g_s, q_r_lo, variant, iterations,) = load(p, 0, 1, 2, 3, 4, 5, 6)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, variant, iterations,))
            & ((q_r_b > 0.0)) & ((abs(q_th_b) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_d > 0.0))
            & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((variant == 0.0) or (variant == 1.0))
            & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # E_ba (137)
    _x0 = (0.5)*k_d
    _x1 = q_r_b**2
    E_ba = _x0*_x1 + _x0*l0**2 + (0.5)*_x1*m*q_thd_b**2 + g_s*m*q_r_b*math.cos(q_th_b) - k_d*l0*q_r_b
    # bottom below q_r_lo
    if not ((-q_r_b + q_r_lo > 0.0)):
        return fail(out, STATUS_NO_LIFTOFF)
    # x_n = a + e_n: the chain's innermost point; x_{n+1} only for the time at iterations = 0
    _x2 = 4.0**(-iterations)*(-q_r_b + q_r_lo)
    _x3 = (0.25)*_x2
    _x4 = _x3 + q_r_b
    _x5 = _x4**2
    _x6 = m**2
    _x7 = k_d*m
    _x8 = _x4**3
    _x9 = ((2.0*E_ba*_x5*m - _x4**4*_x7 - _x5*_x7*l0**2 - 2.0*_x6*_x8*g_s*math.cos(q_th_b)
        - _x6*q_r_b**4*q_thd_b**2 + 2.0*_x8*k_d*l0*m)/_x5)
    d_e_n = _x2
    d_e_z = _x3
    d_rad_z = _x9
    d_Q0 = q_th_b
    d_P0 = m*q_r_b**2*q_thd_b
    d_T0 = ((_x2*m/math.sqrt(_x9)) if (_x9 > 0.0) else (0.0))
    # iterations = 0: H^{-1} real on the zeroth iterate at the point of x_0 (for its time)
    if not ((d_rad_z > 0.0) or (iterations > 0.0)):
        return fail(out, STATUS_IMAGINARY_MOMENTUM)
    # the chain: from x_{j+1} to x_j = a + 4 (x_{j+1} - a), one iterate higher each step
    d_e = d_e_n
    d_Q = d_Q0
    d_P = d_P0
    d_T = d_T0
    d_steps = 0.0
    _conv0 = False
    for _it0 in range(int(iterations)):
        _x10 = d_e + q_r_b
        _x11 = _x10**2
        _x12 = k_d*m
        _x13 = _x10**3
        d_x = _x10
        d_rad = ((2.0*E_ba*_x11*m - _x10**4*_x12 - _x11*_x12*l0**2 - 2.0*_x13*g_s*m**2*math.cos(d_Q)
            + 2.0*_x13*k_d*l0*m - d_P**2)/_x11)
        # H^{-1} real at x_{j+1} on the current iterate
        if not ((d_rad > 0.0)):
            return fail(out, STATUS_IMAGINARY_MOMENTUM)
        d_h = math.sqrt(d_rad)
        d_e_next = 4.0*d_e
        # weights of P/h and m^2 g_s sin(q_th)/h: (42)-(44) or (148)-(150)
        if variant == 0.0:
            d_wq = d_e_next/d_x**2
            d_wp = d_e_next*d_x
        elif variant == 1.0:
            d_wq = d_e_next/(q_r_b*(d_e_next + q_r_b))
            d_wp = (0.5)*d_e_next*(d_e_next + 2.0*q_r_b)
        else:
            return fail(out, STATUS_INVALID_INPUT)
        _n0_0 = d_e_next
        _n0_1 = d_P*d_wq/d_h + q_th_b
        _n0_2 = m*q_r_b**2*q_thd_b + d_wp*g_s*m**2*math.sin(d_Q)/d_h
        _n0_3 = d_e_next*m/d_h
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
    _x14 = q_r_lo**2
    _x15 = k_d*m
    _x16 = q_r_lo**3
    rad_lo = ((2.0*E_ba*_x14*m - _x14*_x15*l0**2 - _x15*q_r_lo**4 - 2.0*_x16*g_s*m**2*math.cos(d_Q)
        + 2.0*_x16*k_d*l0*m - d_P**2)/_x14)
    # p_r_lo = H^{-1}(q_r_lo, q_th, p_th, E_ba) real
    if not ((rad_lo > 0.0)):
        return fail(out, STATUS_IMAGINARY_MOMENTUM)
    # liftoff state
    _x17 = (1.0/m)
    t_stance = d_T
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x17*math.sqrt(rad_lo)
    liftoff_q_th = d_Q
    liftoff_q_thd = _x17*d_P/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return fail(out, STATUS_FALL)
    # the liftoff state
    t_half = t_stance
    end_q_r = liftoff_q_r
    end_q_rd = liftoff_q_rd
    end_q_th = liftoff_q_th
    end_q_thd = liftoff_q_thd
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_decompression_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_decompression` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_decompression(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_decompression_apex(x, p, out):
    """Iterative decompression half as printed (bottom to liftoff, k_d), then the exact flight to the next
    apex: bottom state -> next apex.

    Report equations: 137, 138, 139, 140, 141, 143, 144, 145, 146, 147, 148, 149, 150.

    Role kernel: reads x = (q_r_b, q_rd_b, q_th_b, q_thd_b) and the parameter record
    p = (m, l0, k_d, g_s, g_f, q_r_lo, variant, iterations); writes the outputs below into out, in order, and
    returns
    the status (out all NaN unless OK).

    Arguments:
        q_r_b: bottom leg length [m], > 0
        q_rd_b: bottom leg length rate [m/s] (not read: 0 at the bottom)
        q_th_b: bottom leg angle from the vertical, counterclockwise positive [rad], |q_th_b| < pi/2
        q_thd_b: bottom leg angle rate [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0

    Writes into out:
        apex_height: next apex height above the ground the foot stood on [m]
        apex_speed: next apex horizontal speed (signed) [m/s]
        t_half: time from the bottom to liftoff [s]
        t_ascent: flight time from liftoff to the next apex [s]
        liftoff_q_r: leg length [m]
        liftoff_q_rd: leg length rate [m/s]
        liftoff_q_th: leg angle from the vertical, counterclockwise positive [rad]
        liftoff_q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 8
    (q_r_b, q_rd_b, q_th_b, q_thd_b,) = load(x, 0, 1, 2, 3)
    (m, l0, k_d, g_s, q_r_lo, variant, iterations, g_f,) = load(p, 0, 1, 2, 3, 5, 6, 7, 4)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, variant, iterations, g_f,))
            & ((q_r_b > 0.0)) & ((abs(q_th_b) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_d > 0.0))
            & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((variant == 0.0) or (variant == 1.0))
            & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            & ((g_f > 0.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the half: Iterative decompression half as printed (bottom to liftoff, k_d)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_b, q_rd_b, q_th_b, q_thd_b,))
    _p0 = carray(stack(7), 7)
    store(_p0, (m, l0, k_d, g_s, q_r_lo, variant, iterations,))
    _o0 = carray(stack(5), 5)
    _c0 = iterative_report_decompression(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,) = load(_o0, 0, 1, 2, 3, 4)
    # the direction the body moves at liftoff
    direction = (0.0 if -liftoff_q_r*liftoff_q_thd*math.cos(liftoff_q_th)
        - liftoff_q_rd*math.sin(liftoff_q_th) == 0 else math.copysign(1,
        -liftoff_q_r*liftoff_q_thd*math.cos(liftoff_q_th) - liftoff_q_rd*math.sin(liftoff_q_th)))
    # liftoff -> next apex: exact ballistic ascent
    _c1 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c1[5] != STATUS_OK:
        return fail(out, _c1[5])
    apex_height = _c1[0]
    apex_speed = _c1[1]
    t_ascent = _c1[2]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((apex_height, apex_speed, _o0_0, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
            liftoff_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (apex_height, apex_speed, _o0_0, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_decompression_apex_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_decompression_apex` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_decompression_apex(row(X, i), p, row(OUT, i))
