# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/geyer.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight.py sha256:af908ea30b1fc141
# ----------------------------------------------------------------------------------------------
"""Geyer et al.'s approximate stance map (report section 3.1): stance, state-at-time and apex-return
kernels."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import apex_to_touchdown, liftoff_to_apex

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING,
    STATUS_NO_REAL_SOLUTION, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION, STATUS_NO_LIFTOFF, STATUS_FALL,
    STATUS_NUMERICAL_RANGE)

NAN = math.nan
_NAN2 = (NAN,) * 2
_NAN6 = (NAN,) * 6


@njit(cache=True, error_model="numpy")
def geyer_solution(q_r_td, q_rd_td, q_thd_td, m, l0, k, g_s):
    """Geyer et al.'s radial solution (11) from a touchdown state: omega, omega0_hat, a, b, phase.

    Report equations: 7, 8, 9, 10, 11, 12.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k: leg stiffness, constant (k_c = k_d = k) k [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0

    Returns a tuple:
        omega: omega = p_th / (m l0^2), eq (7) [rad/s]
        omega0_hat: frequency of (11) [rad/s]
        a: offset of rho(t) in (11)
        b: amplitude of rho(t) in (11)
        phase_td: touchdown phase omega0_hat t_td, eq (12) [rad]
        s_td: sin(phase_td) = (q_r_td / l0 - 1 - a) / b
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 56
    # eq (7) at touchdown: omega0^2 = k/m, omega = p_th/(m l0^2), rho and its rate
    _x0 = (1.0/l0)
    omega0_sq = k/m
    omega = _x0**2*q_r_td**2*q_thd_td
    rho_td = _x0*q_r_td - 1.0
    rho_d_td = _x0*q_rd_td
    # stance starts compressing
    if not ((q_rd_td < 0.0)):
        return _NAN6 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # eq (8) at touchdown (Taylor polynomial of Assumption 2): epsilon = 2 E / (m l0^2)
    _x1 = omega**2
    _x2 = 2.0*g_s/l0
    epsilon = _x1 + _x2 + rho_d_td**2 + rho_td**2*(3.0*_x1 + omega0_sq) + rho_td*(-2.0*_x1 + _x2)
    # eq (9): rho_d^2 = lambda rho^2 + mu rho + nu
    _x3 = omega**2
    _x4 = 2.0*g_s/l0
    lam = -3.0*_x3 - omega0_sq
    mu = 2.0*_x3 - _x4
    nu = -_x3 - _x4 + epsilon
    # eq (10)-(11): omega0_hat, a and b^2 of rho = a + b sin(omega0_hat t)
    _x5 = (1.0/lam)
    omega0_hat = math.sqrt(-lam)
    a = -0.5*_x5*mu
    b2 = (0.25)*_x5**2*(-4.0*lam*nu + mu**2)
    # eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0
    if not ((b2 > 0.0)):
        return _NAN6 + (STATUS_NO_REAL_SOLUTION,)
    # eq (12): sin(phase) at touchdown
    _x6 = math.sqrt(b2)
    b = _x6
    s_td = (-a - 1.0 + q_r_td/l0)/_x6
    # the leg collapses: l0 (1 + a - b) <= 0
    if not ((a - b + 1.0 > 0.0)):
        return _NAN6 + (STATUS_FALL,)
    # (12) needs |s_td| <= 1
    if not ((abs(s_td) <= 1.0)):
        return _NAN6 + (STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION,)
    # eq (12), n = 0: compressing root
    phase_td = math.pi - math.asin(s_td)
    # (internal helper: its callers check that their outputs are finite)
    return (omega, omega0_hat, a, b, phase_td, s_td, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_liftoff_phase(a, b, l0, q_r_lo):
    """Geyer et al.'s liftoff phase omega0_hat t_lo, eq (14) with n = 0.

    Report equations: 14.

    Arguments:
        a: offset a of (11)
        b: amplitude b of (11)
        l0: rest leg length l0 [m], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0

    Returns a tuple:
        phase_lo: liftoff phase omega0_hat t_lo, eq (14) [rad]
        s_lo: sin(phase_lo) = (q_r_lo / l0 - 1 - a) / b
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 7
    # eq (14): sin(phase) at liftoff
    s_lo = (-a - 1.0 + q_r_lo/l0)/b
    # eq (14) needs |s_lo| <= 1
    if not ((abs(s_lo) <= 1.0)):
        return _NAN2 + (STATUS_NO_LIFTOFF,)
    # eq (14), n = 0: extending root
    phase_lo = math.asin(s_lo) + 2.0*math.pi
    # (internal helper: its callers check that their outputs are finite)
    return (phase_lo, s_lo, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_state(phase, phase_td, q_th_td, omega, omega0_hat, a, b, l0):
    """Geyer et al.'s approximate stance state at the phase omega0_hat t: (11), (19), (17).

    Report equations: 11, 17, 19.

    The leg angle uses the linearization (18)-(19) of (17); the rate the exact (17) with the
    conserved angular momentum.

    Arguments:
        phase: phase omega0_hat t [rad]
        phase_td: touchdown phase omega0_hat t_td [rad]
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        omega: omega = p_th / (m l0^2) [rad/s]
        omega0_hat: frequency omega0_hat [rad/s]
        a: offset a of (11)
        b: amplitude b of (11)
        l0: rest leg length l0 [m], > 0

    Returns a tuple:
        q_r: leg length [m]
        q_rd: leg length rate [m/s]
        q_th: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate [rad/s]
    """
    # Total ops: 31
    _x0 = a + b*math.sin(phase) + 1.0
    _x1 = math.cos(phase)
    _x2 = (1.0/omega0_hat)
    _x3 = _x2*omega
    _x4 = _x2*a
    _x5 = _x2*b
    _x6 = 2.0*omega
    q_r = _x0*l0
    q_rd = _x1*b*l0*omega0_hat
    q_th = (_x3*phase - _x3*phase_td - _x6*(-_x1*_x5 + _x4*phase) + _x6*(_x4*phase_td
        - _x5*math.cos(phase_td)) + q_th_td)
    q_thd = omega/_x0**2
    return (q_r, q_rd, q_th, q_thd)


@njit(cache=True, error_model="numpy", inline="always")
def geyer_stance(x, p, out):
    """Geyer et al.'s approximate stance map: touchdown state -> bottom and liftoff states.

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Assumption 1 (small sweep: angular momentum conserved), Assumption 2 (small compression:
    1/(1+rho)^2 ~ 1 - 2 rho + 3 rho^2). Leg-angle rates use the exact (17) with the conserved
    angular momentum; the leg angle uses its linearization (18)-(19).

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k: leg stiffness, constant (k_c = k_d = k) k [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0

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
    # Total ops: 54
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k, g_s, q_r_lo,) = load(p, 0, 1, 2, 3, 6)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo,)) & ((q_r_td <= l0)
            and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k > 0.0))
            & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # eqs (7)-(12): Geyer et al.'s radial solution from the touchdown state
    _c0 = geyer_solution(q_r_td, q_rd_td, q_thd_td, m, l0, k, g_s)
    if _c0[6] != STATUS_OK:
        return fail(out, _c0[6])
    omega = _c0[0]
    omega0_hat = _c0[1]
    a = _c0[2]
    b = _c0[3]
    phase_td = _c0[4]
    s_td = _c0[5]
    _c1 = geyer_liftoff_phase(a, b, l0, q_r_lo)
    if _c1[2] != STATUS_OK:
        return fail(out, _c1[2])
    phase_lo = _c1[0]
    s_lo = _c1[1]
    # eqs (13)-(14) minus (12), (11), (19), (17) at the bottom and at liftoff
    _x0 = (1.0/omega0_hat)
    _x1 = a + 1.0
    _x2 = _x1 - b
    _x3 = _x0*omega
    _x4 = _x0*phase_td
    _x5 = _x0*b
    _x6 = 2.0*omega
    _x7 = -_x4*omega + _x6*(_x4*a + _x5*math.sqrt(1.0 - s_td**2)) + q_th_td
    _x8 = math.sqrt(1.0 - s_lo**2)
    _x9 = _x0*phase_lo
    t_bottom = _x0*(-phase_td + (1.5)*math.pi)
    t_stance = _x0*(phase_lo - phase_td)
    bottom_q_r = _x2*l0
    bottom_q_th = -3.0*math.pi*_x3*a + (1.5)*math.pi*_x3 + _x7
    bottom_q_thd = omega/_x2**2
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x8*b*l0*omega0_hat
    liftoff_q_th = -_x6*(-_x5*_x8 + _x9*a) + _x7 + _x9*omega
    liftoff_q_thd = omega/(_x1 + b*s_lo)**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return fail(out, STATUS_FALL)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_bottom, t_stance, bottom_q_r, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
            liftoff_q_th, liftoff_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_bottom, t_stance, bottom_q_r, 0.0, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline=into_rows)
def geyer_state_at(x, p, out):
    """Geyer et al.'s approximate stance map: the polar state a time t after touchdown.

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Role kernel: reads x = (t, q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments:
        t: time since touchdown t [s], >= 0
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k: leg stiffness, constant (k_c = k_d = k) k [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0

    Writes into out:
        q_r: leg length [m]
        q_rd: leg length rate [m/s]
        q_th: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 2
    (t, q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k, g_s, q_r_lo,) = load(p, 0, 1, 2, 3, 6)
    # inputs: finite and inside their domains
    if not (all_finite((t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo,)) & ((t >= 0.0))
            & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0
            > 0.0)) & ((k > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # eqs (7)-(12): Geyer et al.'s radial solution from the touchdown state
    _c0 = geyer_solution(q_r_td, q_rd_td, q_thd_td, m, l0, k, g_s)
    if _c0[6] != STATUS_OK:
        return fail(out, _c0[6])
    omega = _c0[0]
    omega0_hat = _c0[1]
    a = _c0[2]
    b = _c0[3]
    phase_td = _c0[4]
    s_td = _c0[5]
    # phase at t after touchdown
    phase_t = omega0_hat*t + phase_td
    _c1 = geyer_state(phase_t, phase_td, q_th_td, omega, omega0_hat, a, b, l0)
    q_r = _c1[0]
    q_rd = _c1[1]
    q_th = _c1[2]
    q_thd = _c1[3]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((q_r, q_rd, q_th, q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (q_r, q_rd, q_th, q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline=into_rows)
def geyer_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Geyer et al.'s approximate stance map.

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo); writes the outputs below into out, in order, and returns
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
        k: leg stiffness, constant (k_c = k_d = k) k [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0

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
    # Total ops: 3
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k, g_s, g_f, q_r_td, q_r_lo,) = load(p, 0, 1, 2, 3, 4, 5, 6)
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k, g_s, g_f, q_r_td,
            q_r_lo,)) & ((b_y_apex >= 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0))
            & ((k > 0.0)) & ((g_s > 0.0)) & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo
            <= l0) and (q_r_lo > 0.0))):
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
    # stance: Geyer et al.'s approximate stance map
    _x1 = carray(stack(4), 4)
    store(_x1, (td_q_r, td_q_rd, td_q_th, td_q_thd,))
    _o1 = carray(stack(10), 10)
    _c1 = geyer_stance(_x1, p, _o1)
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


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_apex_return(row(X, i), p, row(OUT, i))
