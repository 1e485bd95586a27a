# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/geyer.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight.py sha256:90530e956fef316d
# ----------------------------------------------------------------------------------------------
"""Geyer et al.'s approximate stance map and apex-return map (report section 3.1, eqs 7-26)."""

import math

import numpy as np
from numba import njit, prange
from .flight import apex_to_touchdown, liftoff_to_apex

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


@njit(cache=True, error_model="numpy")
def geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo):
    """Geyer et al.'s approximate stance map: touchdown state -> bottom and liftoff states.

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Assumption 1 (small sweep: angular momentum conserved), Assumption 2 (small compression:
    1/(1+rho)^2 ~ 1 - 2 rho + 3 rho^2). Leg-angle rates use the exact (17) with the conserved
    angular momentum; the leg angle uses its linearization (18)-(19).

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s], negative (compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (k_c while compressing, k_d after the bottom)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0

    Returns a tuple:
        t_bottom: time from touchdown to the bottom (eq 13 - eq 12) [s]
        t_stance: stance time t_lo - t_td (eq 14 - eq 12; eq 20 when q_r_td = q_r_lo = l0) [s]
        b_q_r: bottom leg length l0 (1 + a - b) [m]
        b_q_rd: bottom leg length rate (0 by construction) [m/s]
        b_q_th: bottom leg angle, eq (19) [rad]
        b_q_thd: bottom leg angle rate p_th / (m q_r^2), eq (17) [rad/s]
        lo_q_r: liftoff leg length (= q_r_lo) [m]
        lo_q_rd: liftoff leg length rate l0 b omega0_hat cos(phase_lo), from (11) [m/s]
        lo_q_th: liftoff leg angle, eq (19) [rad]
        lo_q_thd: liftoff leg angle rate p_th / (m q_r_lo^2), eq (17) [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed guard; all other outputs are then NaN.
    """
    # Total ops: 131
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(q_r_lo)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    if not ((q_r_lo <= l0) and (q_r_td <= l0) and (g_s > 0.0) and (k > 0.0) and (l0 > 0.0) and (m > 0.0) and (q_r_lo > 0.0) and (q_r_td > 0.0) and (abs(q_th_td) < (0.5)*math.pi)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # eq (7) at touchdown: omega0 = sqrt(k / m), omega = p_th / (m l0^2)
    omega0 = math.sqrt(k)/math.sqrt(m)
    omega = q_r_td**2*q_thd_td/l0**2
    # stance starts compressing
    if not ((q_rd_td < 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # eq (8) at touchdown: epsilon = 2 E / (m l0^2)
    _x0 = l0**4
    _x1 = q_r_td**4*q_thd_td**2
    _x2 = l0 - q_r_td
    epsilon = (_x0*q_rd_td**2 + _x1*l0**2 + _x2*(_x2*(_x0*omega0**2 + 3.0*_x1) - 2.0*l0*(-_x1 + g_s*l0**3)) + 2.0*g_s*l0**5)/l0**6
    # eq (9)-(11): frequency, offset, squared amplitude of rho(t) = a + b sin(omega0_hat t)
    _x3 = omega**2
    _x4 = 3.0*_x3 + omega0**2
    _x5 = -_x3*l0 + g_s
    omega0_hat = math.sqrt(_x4)
    a = -_x5/(_x4*l0)
    b2 = (-_x4*l0*(2.0*g_s + l0*(_x3 - epsilon)) + _x5**2)/(_x4**2*l0**2)
    # eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0
    if not ((b2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_REAL_SOLUTION)
    # eq (12)-(14): sin(phase) at touchdown/liftoff
    _x6 = math.sqrt(b2)
    _x7 = (1.0/_x6)
    _x8 = (1.0/l0)
    _x9 = a + 1.0
    b = _x6
    s_td = _x7*(_x8*q_r_td - _x9)
    s_lo = _x7*(_x8*q_r_lo - _x9)
    # the leg collapses: bottom leg length l0 (1 + a - b) <= 0
    if not ((a - b + 1.0 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # eq (12) needs |s_td| <= 1
    if not ((abs(s_td) <= 1.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION)
    # eq (14) needs |s_lo| <= 1
    if not ((abs(s_lo) <= 1.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_LIFTOFF)
    # eq (13)-(14), (19), (17): events, then the bottom and liftoff states
    _x10 = (1.0/omega0_hat)
    _x11 = math.asin(s_td)
    _x12 = math.asin(s_lo)
    _x13 = a + 1.0
    _x14 = _x13 - b
    _x15 = math.pi*_x10*omega
    _x16 = _x10*(math.pi - _x11)
    _x17 = _x10*b
    _x18 = 2.0*omega
    _x19 = -_x16*omega + _x18*(_x16*a + _x17*math.sqrt(1.0 - s_td**2)) + q_th_td
    _x20 = _x13 + b*s_lo
    _x21 = math.sqrt(1.0 - s_lo**2)
    _x22 = _x10*(_x12 + 2.0*math.pi)
    t_bottom = _x10*(_x11 + (0.5)*math.pi)
    t_stance = _x10*(_x11 + _x12 + math.pi)
    b_q_r = _x14*l0
    b_q_rd = 0.0
    b_q_th = -3.0*_x15*a + (1.5)*_x15 + _x19
    b_q_thd = omega/_x14**2
    lo_q_r = _x20*l0
    lo_q_rd = _x21*b*l0*omega0_hat
    lo_q_th = -_x18*(-_x17*_x21 + _x22*a) + _x19 + _x22*omega
    lo_q_thd = omega/_x20**2
    # the leg stays above horizontal
    if not ((abs(lo_q_th) < (0.5)*math.pi)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(b_q_r) and math.isfinite(b_q_rd) and math.isfinite(b_q_th) and math.isfinite(b_q_thd) and math.isfinite(lo_q_r) and math.isfinite(lo_q_rd) and math.isfinite(lo_q_th) and math.isfinite(lo_q_thd)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (t_bottom, t_stance, b_q_r, b_q_rd, b_q_th, b_q_thd, lo_q_r, lo_q_rd, lo_q_th, lo_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_stance_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, out, status):
    """Parallel batch form of :func:`geyer_stance` over 1-D float64 arrays of equal length.

    Writes output j of element i to ``out[i, j]`` (shape (n, 10)) and its status code to
    ``status[i]`` (int64). Column order: t_bottom, t_stance, b_q_r, b_q_rd, b_q_th, b_q_thd, lo_q_r, lo_q_rd, lo_q_th, lo_q_thd.
    """
    for i in prange(out.shape[0]):
        res = geyer_stance(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m[i], l0[i], k[i], g_s[i], q_r_lo[i])
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
        status[i] = res[10]


@njit(cache=True, error_model="numpy")
def geyer_stance_state_at(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s):
    """Geyer et al.'s approximate stance trajectory: the polar state a time t after touchdown.

    Report equations: 11, 17, 19.

    Arguments:
        t: time since touchdown [s], >= 0
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s], negative (compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (k_c while compressing, k_d after the bottom)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive

    Returns a tuple:
        q_r_t: leg length at t, eq (11) [m]
        q_rd_t: leg length rate at t [m/s]
        q_th_t: leg angle at t, eq (19) [rad]
        q_thd_t: leg angle rate at t, eq (17) [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed guard; all other outputs are then NaN.
    """
    # Total ops: 107
    if not (math.isfinite(t) and math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s)):
        return (NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    if not ((t >= 0.0) and (q_r_td <= l0) and (g_s > 0.0) and (k > 0.0) and (l0 > 0.0) and (m > 0.0) and (q_r_td > 0.0) and (abs(q_th_td) < (0.5)*math.pi)):
        return (NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # eq (7) at touchdown: omega0 = sqrt(k / m), omega = p_th / (m l0^2)
    omega0 = math.sqrt(k)/math.sqrt(m)
    omega = q_r_td**2*q_thd_td/l0**2
    # stance starts compressing
    if not ((q_rd_td < 0.0)):
        return (NAN, NAN, NAN, NAN, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # eq (8) at touchdown: epsilon = 2 E / (m l0^2)
    _x0 = l0**4
    _x1 = q_r_td**4*q_thd_td**2
    _x2 = l0 - q_r_td
    epsilon = (_x0*q_rd_td**2 + _x1*l0**2 + _x2*(_x2*(_x0*omega0**2 + 3.0*_x1) - 2.0*l0*(-_x1 + g_s*l0**3)) + 2.0*g_s*l0**5)/l0**6
    # eq (9)-(11): frequency, offset, squared amplitude of rho(t) = a + b sin(omega0_hat t)
    _x3 = omega**2
    _x4 = 3.0*_x3 + omega0**2
    _x5 = -_x3*l0 + g_s
    omega0_hat = math.sqrt(_x4)
    a = -_x5/(_x4*l0)
    b2 = (-_x4*l0*(2.0*g_s + l0*(_x3 - epsilon)) + _x5**2)/(_x4**2*l0**2)
    # eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0
    if not ((b2 > 0.0)):
        return (NAN, NAN, NAN, NAN, STATUS_NO_REAL_SOLUTION)
    # eq (12)-(14): sin(phase) at touchdown/liftoff
    _x6 = math.sqrt(b2)
    b = _x6
    s_td = (-a - 1.0 + q_r_td/l0)/_x6
    # the leg collapses: bottom leg length l0 (1 + a - b) <= 0
    if not ((a - b + 1.0 > 0.0)):
        return (NAN, NAN, NAN, NAN, STATUS_FALL)
    # eq (12) needs |s_td| <= 1
    if not ((abs(s_td) <= 1.0)):
        return (NAN, NAN, NAN, NAN, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION)
    # eq (11), (19), (17) at t
    _x7 = math.asin(s_td)
    _x8 = -_x7 + omega0_hat*t
    _x9 = a - b*math.sin(_x8) + 1.0
    _x10 = math.cos(_x8)
    _x11 = math.pi - _x7
    _x12 = (1.0/omega0_hat)
    _x13 = _x12*omega
    _x14 = _x8 + math.pi
    _x15 = _x12*a
    _x16 = _x12*b
    _x17 = 2.0*omega
    q_r_t = _x9*l0
    q_rd_t = -_x10*b*l0*omega0_hat
    q_th_t = -_x11*_x13 + _x13*_x14 - _x17*(_x10*_x16 + _x14*_x15) + _x17*(_x11*_x15 + _x16*math.sqrt(1.0 - s_td**2)) + q_th_td
    q_thd_t = omega/_x9**2
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(q_r_t) and math.isfinite(q_rd_t) and math.isfinite(q_th_t) and math.isfinite(q_thd_t)):
        return (NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (q_r_t, q_rd_t, q_th_t, q_thd_t, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_stance_state_at_batch(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, out, status):
    """Parallel batch form of :func:`geyer_stance_state_at` over 1-D float64 arrays of equal length.

    Writes output j of element i to ``out[i, j]`` (shape (n, 4)) and its status code to
    ``status[i]`` (int64). Column order: q_r_t, q_rd_t, q_th_t, q_thd_t.
    """
    for i in prange(out.shape[0]):
        res = geyer_stance_state_at(t[i], q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m[i], l0[i], k[i], g_s[i])
        out[i, 0] = res[0]
        out[i, 1] = res[1]
        out[i, 2] = res[2]
        out[i, 3] = res[3]
        status[i] = res[4]


@njit(cache=True, error_model="numpy")
def geyer_apex_return(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo):
    """Apex-return map: exact flight, Geyer et al.'s stance map (section 3.1).

    Apex (height b_y_apex [m], speed b_xd_apex [m/s]) -> touchdown with the leg at (q_th_td [rad],
    q_r_td [m]) by exact ballistic flight (g_f), the stance by :func:`geyer_stance`
    (m, l0, k, g_s; liftoff at q_r_lo [m]), then exact flight to the next apex.

    Returns a tuple: next apex height [m], next apex speed [m/s], time apex -> touchdown [s],
    stance time [s], time liftoff -> apex [s], liftoff state (q_r, q_rd, q_th, q_thd), status.
    """
    # stance parameters first, so an invalid one is reported as such whatever the flight does
    if not (math.isfinite(m) and m > 0.0 and math.isfinite(l0) and l0 > 0.0 and math.isfinite(k) and k > 0.0 and math.isfinite(g_s) and g_s > 0.0 and math.isfinite(q_r_lo) and 0.0 < q_r_lo <= l0 and q_r_td <= l0):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    td = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f)
    if td[5] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, td[5])
    st = geyer_stance(td[0], td[1], td[2], td[3], m, l0, k, g_s, q_r_lo)
    if st[-1] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, st[-1])
    lo = (st[-5], st[-4], st[-3], st[-2])
    ap = liftoff_to_apex(lo[0], lo[1], lo[2], lo[3], g_f)
    if ap[4] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, ap[4])
    return (ap[0], ap[1], td[4], st[1], ap[2], lo[0], lo[1], lo[2], lo[3], STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_apex_return_batch(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, out, status):
    """Parallel batch form of :func:`geyer_apex_return` over 1-D float64 arrays of equal length.

    ``out`` has shape (n, 9) in the order of the scalar outputs; ``status`` is int64 of length n.
    """
    for i in prange(out.shape[0]):
        res = geyer_apex_return(
            b_y_apex[i], b_xd_apex[i], q_th_td[i], m[i], l0[i], k[i], g_s[i], g_f[i], q_r_td[i], q_r_lo[i]
        )
        out[i, 0] = res[0]
        out[i, 1] = res[1]
        out[i, 2] = res[2]
        out[i, 3] = res[3]
        out[i, 4] = res[4]
        out[i, 5] = res[5]
        out[i, 6] = res[6]
        out[i, 7] = res[7]
        out[i, 8] = res[8]
        status[i] = res[9]
