# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/gravity_type5.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight.py sha256:af908ea30b1fc141
#   geyer.py sha256:110e83efcc6593e2
# ----------------------------------------------------------------------------------------------
"""Gravity correction type 5 (time-varying momentum) (report section 4.6): stance, state-at-time and
apex-return kernels."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import apex_to_touchdown, liftoff_to_apex
from .geyer import geyer_liftoff_phase

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING,
    STATUS_NO_REAL_SOLUTION, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION, STATUS_FALL, STATUS_NUMERICAL_RANGE,
    STATUS_NOT_CONVERGED, STATUS_ENERGY_DEFICIT)

NAN = math.nan
_NAN5 = (NAN,) * 5


@njit(cache=True, error_model="numpy")
def type5_solution(q_r_td, q_rd_td, omega, g_eff, r_c, m, l0, k):
    """Type 5 radial solution: (10)-(11) for the quadratic T5.4 about r_c with g_eff.

    Report equations: 9, 10, 11, 12.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        omega: omega = p_mean / (m l0^2) [rad/s]
        g_eff: radial gravity g_s <cos q_th> [m/s^2]
        r_c: expansion point of 1/(1+rho)^2 (stance-mean compression)
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k: leg stiffness, constant (k_c = k_d = k) k [N/m], > 0

    Returns a tuple:
        omega0_hat: frequency [rad/s]
        a: offset of rho(t)
        b: amplitude of rho(t)
        phase_td: touchdown phase [rad]
        s_td: sin(phase_td)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 73
    omega0_sq = k/m
    if not ((q_rd_td < 0.0)):
        return _NAN5 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # T5.4: the quadratic about r_c with g_eff
    _x0 = (r_c + 1.0)**-4
    _x1 = 4.0*omega0_sq
    _x2 = omega**2
    _x3 = r_c**4
    _x4 = 6.0*r_c**2
    _x5 = r_c**3
    _x6 = 4.0*g_eff
    lam = -_x0*(_x1*_x5 + _x1*r_c + 3.0*_x2 + _x3*omega0_sq + _x4*omega0_sq + omega0_sq)
    mu = 2.0*_x0*(4.0*_x2*l0*r_c + _x2*l0 - _x3*g_eff - _x4*g_eff - _x5*_x6 - _x6*r_c - g_eff)/l0
    # T5.5: through the touchdown point
    _x8 = (1.0/l0)
    _x7 = _x8*q_r_td - 1.0
    nu = -_x7**2*lam - _x7*mu + _x8**2*q_rd_td**2
    # eq (10)-(11): omega0_hat, a and b^2 of rho = a + b sin(omega0_hat t)
    _x9 = (1.0/lam)
    omega0_hat = math.sqrt(-lam)
    a = -0.5*_x9*mu
    b2 = (0.25)*_x9**2*(-4.0*lam*nu + mu**2)
    # eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0
    if not ((b2 > 0.0)):
        return _NAN5 + (STATUS_NO_REAL_SOLUTION,)
    # eq (12): sin(phase) at touchdown
    _x10 = math.sqrt(b2)
    b = _x10
    s_td = (-a - 1.0 + q_r_td/l0)/_x10
    # the leg collapses: l0 (1 + a - b) <= 0
    if not ((a - b + 1.0 > 0.0)):
        return _NAN5 + (STATUS_FALL,)
    # (12) needs |s_td| <= 1
    if not ((abs(s_td) <= 1.0)):
        return _NAN5 + (STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION,)
    # eq (12), n = 0: compressing root
    phase_td = math.pi - math.asin(s_td)
    # (internal helper: its callers check that their outputs are finite)
    return (omega0_hat, a, b, phase_td, s_td, STATUS_OK)


@njit(cache=True, error_model="numpy")
def type5_leg_angle(t, q_th_td, p_td, c0, c1, c2, k0, k1, k2, omega0_hat, phase_td, m, l0):
    """Type 5 leg angle T5.6: q_th_td + int_0^t P(u) (k0 + k1 sin + k2 cos 2(.)) du / (m l0^2).

    Report equations: 17, 18, 19.

    Arguments:
        t: time since touchdown [s]
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        p_td: angular momentum at touchdown [N m s]
        c0: coefficient c0 of the torque quadratic T5.1
        c1: coefficient c1 of the torque quadratic T5.1
        c2: coefficient c2 of the torque quadratic T5.1
        k0: coefficient k0 of the rate factor T5.6
        k1: coefficient k1 of the rate factor T5.6
        k2: coefficient k2 of the rate factor T5.6
        omega0_hat: frequency omega0_hat [rad/s]
        phase_td: touchdown phase [rad]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0

    Returns:
        q_th: leg angle [rad]
    """
    # Total ops: 144
    _x4 = (1.0/omega0_hat)
    _x0 = t**2
    _x1 = (0.5)*_x0
    _x2 = t**3
    _x3 = k1*math.cos(phase_td)
    _x5 = _x4*p_td
    _x6 = _x4**2
    _x7 = math.sin(phase_td)
    _x8 = c0*k1
    _x9 = _x4**3
    _x10 = _x9*c1
    _x11 = _x4**4
    _x12 = _x11*c2
    _x13 = 2.0*phase_td
    _x14 = math.cos(_x13)
    _x15 = c0*k2
    _x16 = k2*math.sin(_x13)
    _x17 = omega0_hat*t
    _x18 = _x17 + phase_td
    _x19 = math.cos(_x18)
    _x20 = _x19*_x4
    _x21 = _x13 + 2.0*_x17
    _x22 = math.sin(_x21)
    _x23 = _x22*_x4
    _x24 = (0.5)*_x23
    _x25 = math.sin(_x18)
    _x26 = math.cos(_x21)
    _x27 = _x26*_x6
    _x28 = (0.5)*t
    _x29 = (0.5)*c1
    _x30 = _x22*_x9
    _x31 = (0.3333333333333333)*c2
    q_th = (q_th_td + (_x1*c0*k0 + (0.125)*_x10*_x16 - _x10*_x3 + (0.125)*_x12*_x14*k2 + 2.0*_x12*_x7*k1
        - 0.25*_x14*_x15*_x6 + _x15*(_x23*_x28 + (0.25)*_x27) - 0.5*_x16*_x5 + (0.16666666666666666)*_x2*c1*k0
        - _x20*k1*p_td + _x24*k2*p_td + _x29*k1*(-_x0*_x20 + 2.0*_x19*_x9 + 2.0*_x25*_x6*t)
        + _x29*k2*(_x1*_x23 + _x27*_x28 - 0.25*_x30) + _x3*_x5 + _x31*k1*(3.0*_x0*_x25*_x6 - 6.0*_x11*_x25
        + 6.0*_x19*_x9*t - _x2*_x20) + _x31*k2*((0.75)*_x0*_x27 - 0.375*_x11*_x26 + _x2*_x24 - 0.75*_x30*t)
        - _x6*_x7*_x8 + _x8*(-_x20*t + _x25*_x6) + (0.08333333333333333)*c2*k0*t**4 + k0*p_td*t)/(l0**2*m))
    return q_th


@njit(cache=True, error_model="numpy")
def gravity_type5_stance(x, p, out):
    """Gravity correction type 5 (time-varying momentum): touchdown state -> bottom and liftoff states.

    Report equations: 46, 47, 48.

    Designed in slipmaps (the report stops mid-sentence): docs/type5.md, equations T5.1-T5.8.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol); writes the outputs below into out, in order,
    and returns
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
        iterations: option iterations: fixed-point passes T5.8 from Geyer's map in [0, 1000]
        tol: option tol: stop when every state moved by at most tol times its scale; 0: run all passes in [0,
            1]

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
        P_c: stance impulse of the gravity torque P(t_lo) - p_td [N m s]
        passes: fixed-point passes run
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 238
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k, g_s, q_r_lo, iterations, tol,) = load(p, 0, 1, 2, 3, 6, 7, 8)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol,))
            & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0
            > 0.0)) & ((k > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0)
            and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = (0.5)*k
    p_td = _x1*q_thd_td
    E_td = (_x0*_x2 + (0.5)*_x1*q_thd_td**2 + _x2*l0**2 + g_s*m*q_r_td*math.cos(q_th_td) - k*l0*q_r_td
        + (0.5)*m*q_rd_td**2)
    # T5.8: fixed point on the nodal torques, the stance time, g_eff and r_c
    tau1 = 0.0
    tau2 = 0.0
    tau3 = 0.0
    T = 1.0
    g_eff = g_s
    r_c = 0.0
    passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # T5.1: the torque quadratic through the nodal torques of the previous pass
        _x5 = (1.0/T)
        _x3 = math.sqrt(15.0)
        _x4 = _x3*tau1
        i_c0 = (-0.16666666666666666*_x3*tau3 + (0.16666666666666666)*_x4 + (0.8333333333333334)*tau1
            - 0.6666666666666666*tau2 + (0.8333333333333334)*tau3)
        i_c1 = (0.3333333333333333)*_x5*(_x3*tau3 - _x4 - 10.0*tau1 + 20.0*tau2 - 10.0*tau3)
        i_c2 = (3.3333333333333335)*_x5**2*(tau1 - 2.0*tau2 + tau3)
        # T5.3: omega of the stance-mean momentum
        i_omega = (((0.08333333333333333)*T**3*i_c2 + (0.16666666666666666)*T**2*i_c1 + (0.5)*T*i_c0
            + p_td)/(l0**2*m))
        # T5.4-T5.5: radial solution
        _c0 = type5_solution(q_r_td, q_rd_td, i_omega, g_eff, r_c, m, l0, k)
        if _c0[5] != STATUS_OK:
            return fail(out, _c0[5])
        i_omega0_hat = _c0[0]
        i_a = _c0[1]
        i_b = _c0[2]
        i_phase_td = _c0[3]
        i_s_td = _c0[4]
        _c1 = geyer_liftoff_phase(i_a, i_b, l0, q_r_lo)
        if _c1[2] != STATUS_OK:
            return fail(out, _c1[2])
        i_phase_lo = _c1[0]
        # eqs (13)-(14) minus (12); T5.6: the rate factor
        _x6 = (1.0/i_omega0_hat)
        _x7 = r_c**4
        _x8 = r_c**3
        _x9 = r_c**2
        _x10 = 4.0*r_c + 1.0
        _x11 = (1.0/(_x10 + _x7 + 4.0*_x8 + 6.0*_x9))
        _x12 = 3.0*i_b**2
        _x13 = 12.0*_x9 + 8.0*r_c + 2.0
        i_t_bottom = _x6*(-i_phase_td + (1.5)*math.pi)
        i_t_stance = _x6*(i_phase_lo - i_phase_td)
        i_k0 = (0.5)*_x11*(_x12 + _x13 + 6.0*i_a**2 - 16.0*i_a*r_c - 4.0*i_a)
        i_k1 = 2.0*_x11*i_b*(-_x10 + 3.0*i_a)
        i_k2 = -_x12/(_x13 + 2.0*_x7 + 8.0*_x8)
        _c2 = (type5_leg_angle((0.5)*i_t_stance*(1.0 - 0.2*math.sqrt(15.0)), q_th_td, p_td, i_c0, i_c1, i_c2,
            i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0))
        i_th1 = _c2
        _c3 = (type5_leg_angle((0.5)*i_t_stance, q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2,
            i_omega0_hat, i_phase_td, m, l0))
        i_th2 = _c3
        _c4 = (type5_leg_angle((0.5)*i_t_stance*((0.2)*math.sqrt(15.0) + 1.0), q_th_td, p_td, i_c0, i_c1,
            i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0))
        i_th3 = _c4
        # T5.1, T5.4: the torques at the new nodes, g_s <cos q_th>, the mean compression
        _x14 = (0.2)*math.sqrt(15.0)
        _x15 = (0.5)*i_omega0_hat*i_t_stance
        _x16 = i_a + 1.0
        _x17 = g_s*l0*m
        i_tau1 = _x17*(_x16 + i_b*math.sin(_x15*(1.0 - _x14) + i_phase_td))*math.sin(i_th1)
        i_tau2 = _x17*(_x16 + i_b*math.sin(_x15 + i_phase_td))*math.sin(i_th2)
        i_tau3 = _x17*(_x16 + i_b*math.sin(_x15*(_x14 + 1.0) + i_phase_td))*math.sin(i_th3)
        i_g_eff = ((0.5)*g_s*((0.5555555555555556)*math.cos(i_th1) + (0.8888888888888888)*math.cos(i_th2)
            + (0.5555555555555556)*math.cos(i_th3)))
        i_r_c = i_a - i_b*(math.cos(i_phase_lo) - math.cos(i_phase_td))/(i_phase_lo - i_phase_td)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = i_tau1
        _n0_1 = i_tau2
        _n0_2 = i_tau3
        _n0_3 = i_t_stance
        _n0_4 = i_g_eff
        _n0_5 = i_r_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - tau1) <= tol*(g_s*l0*m)) and (abs(_n0_1 - tau2)
            <= tol*(g_s*l0*m)) and (abs(_n0_2 - tau3) <= tol*(g_s*l0*m)) and (abs(_n0_3 - T)
            <= tol*(math.sqrt(m)/math.sqrt(k))) and (abs(_n0_4 - g_eff) <= tol*(g_s)) and (abs(_n0_5 - r_c)
            <= tol*(1.0)))
        tau1 = _n0_0
        tau2 = _n0_1
        tau3 = _n0_2
        T = _n0_3
        g_eff = _n0_4
        r_c = _n0_5
        passes += 1.0
    _c5 = (type5_leg_angle(i_t_bottom, q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat,
        i_phase_td, m, l0))
    bottom_q_th = _c5
    _c6 = (type5_leg_angle(i_t_stance, q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat,
        i_phase_td, m, l0))
    liftoff_q_th = _c6
    # T5.7: bottom and liftoff states
    _x18 = i_a - i_b + 1.0
    _x19 = (1.0/m)
    _x20 = (0.5)*i_c1
    _x21 = (0.3333333333333333)*i_c2
    _x22 = _x20*i_t_stance**2 + _x21*i_t_stance**3 + i_c0*i_t_stance
    t_bottom = i_t_bottom
    t_stance = i_t_stance
    bottom_q_r = _x18*l0
    bottom_q_thd = _x19*(_x20*i_t_bottom**2 + _x21*i_t_bottom**3 + i_c0*i_t_bottom + p_td)/(_x18**2*l0**2)
    liftoff_q_r = q_r_lo
    P_c = _x22
    liftoff_q_thd = _x19*(_x22 + p_td)/q_r_lo**2
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return fail(out, STATUS_FALL)
    _x23 = (1.0/m)
    _x24 = _x23*k
    _x25 = q_r_lo**2
    _q_rd_lo_sq = (2.0*E_td*_x23 - _x23**2*(i_c0*i_t_stance + (0.5)*i_c1*i_t_stance**2
        + (0.3333333333333333)*i_c2*i_t_stance**3 + p_td)**2/_x25 + 2.0*_x23*k*l0*q_r_lo - _x24*_x25
        - _x24*l0**2 - 2.0*g_s*q_r_lo*math.cos(liftoff_q_th))
    # q_rd_lo^2 from the energy (27)
    if not ((_q_rd_lo_sq >= 0.0)):
        return fail(out, STATUS_ENERGY_DEFICIT)
    # q_rd_lo from the energy
    liftoff_q_rd = math.sqrt(_q_rd_lo_sq)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_bottom, t_stance, bottom_q_r, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
            liftoff_q_th, liftoff_q_thd, P_c, passes,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_bottom, t_stance, bottom_q_r, 0.0, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, P_c, passes,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type5_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type5_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(9), 9)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type5_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type5_state_at(x, p, out):
    """Gravity correction type 5 (time-varying momentum): the polar state a time t after touchdown.

    Report equations: 46, 47, 48.

    Role kernel: reads x = (t, q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol); writes the outputs below into out, in order,
    and returns
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
        iterations: option iterations: fixed-point passes T5.8 from Geyer's map in [0, 1000]
        tol: option tol: stop when every state moved by at most tol times its scale; 0: run all passes in [0,
            1]

    Writes into out:
        q_r: leg length [m]
        q_rd: leg length rate [m/s]
        q_th: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 197
    (t, q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k, g_s, q_r_lo, iterations, tol,) = load(p, 0, 1, 2, 3, 6, 7, 8)
    # inputs: finite and inside their domains
    if not (all_finite((t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol,)) & ((t
            >= 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0))
            & ((l0 > 0.0)) & ((k > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0)
            and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = (0.5)*k
    p_td = _x1*q_thd_td
    E_td = (_x0*_x2 + (0.5)*_x1*q_thd_td**2 + _x2*l0**2 + g_s*m*q_r_td*math.cos(q_th_td) - k*l0*q_r_td
        + (0.5)*m*q_rd_td**2)
    # T5.8: fixed point on the nodal torques, the stance time, g_eff and r_c
    tau1 = 0.0
    tau2 = 0.0
    tau3 = 0.0
    T = 1.0
    g_eff = g_s
    r_c = 0.0
    passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # T5.1: the torque quadratic through the nodal torques of the previous pass
        _x5 = (1.0/T)
        _x3 = math.sqrt(15.0)
        _x4 = _x3*tau1
        i_c0 = (-0.16666666666666666*_x3*tau3 + (0.16666666666666666)*_x4 + (0.8333333333333334)*tau1
            - 0.6666666666666666*tau2 + (0.8333333333333334)*tau3)
        i_c1 = (0.3333333333333333)*_x5*(_x3*tau3 - _x4 - 10.0*tau1 + 20.0*tau2 - 10.0*tau3)
        i_c2 = (3.3333333333333335)*_x5**2*(tau1 - 2.0*tau2 + tau3)
        # T5.3: omega of the stance-mean momentum
        i_omega = (((0.08333333333333333)*T**3*i_c2 + (0.16666666666666666)*T**2*i_c1 + (0.5)*T*i_c0
            + p_td)/(l0**2*m))
        # T5.4-T5.5: radial solution
        _c0 = type5_solution(q_r_td, q_rd_td, i_omega, g_eff, r_c, m, l0, k)
        if _c0[5] != STATUS_OK:
            return fail(out, _c0[5])
        i_omega0_hat = _c0[0]
        i_a = _c0[1]
        i_b = _c0[2]
        i_phase_td = _c0[3]
        i_s_td = _c0[4]
        _c1 = geyer_liftoff_phase(i_a, i_b, l0, q_r_lo)
        if _c1[2] != STATUS_OK:
            return fail(out, _c1[2])
        i_phase_lo = _c1[0]
        # eqs (13)-(14) minus (12); T5.6: the rate factor
        _x6 = (1.0/i_omega0_hat)
        _x7 = r_c**4
        _x8 = r_c**3
        _x9 = r_c**2
        _x10 = 4.0*r_c + 1.0
        _x11 = (1.0/(_x10 + _x7 + 4.0*_x8 + 6.0*_x9))
        _x12 = 3.0*i_b**2
        _x13 = 12.0*_x9 + 8.0*r_c + 2.0
        i_t_bottom = _x6*(-i_phase_td + (1.5)*math.pi)
        i_t_stance = _x6*(i_phase_lo - i_phase_td)
        i_k0 = (0.5)*_x11*(_x12 + _x13 + 6.0*i_a**2 - 16.0*i_a*r_c - 4.0*i_a)
        i_k1 = 2.0*_x11*i_b*(-_x10 + 3.0*i_a)
        i_k2 = -_x12/(_x13 + 2.0*_x7 + 8.0*_x8)
        _c2 = (type5_leg_angle((0.5)*i_t_stance*(1.0 - 0.2*math.sqrt(15.0)), q_th_td, p_td, i_c0, i_c1, i_c2,
            i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0))
        i_th1 = _c2
        _c3 = (type5_leg_angle((0.5)*i_t_stance, q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2,
            i_omega0_hat, i_phase_td, m, l0))
        i_th2 = _c3
        _c4 = (type5_leg_angle((0.5)*i_t_stance*((0.2)*math.sqrt(15.0) + 1.0), q_th_td, p_td, i_c0, i_c1,
            i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0))
        i_th3 = _c4
        # T5.1, T5.4: the torques at the new nodes, g_s <cos q_th>, the mean compression
        _x14 = (0.2)*math.sqrt(15.0)
        _x15 = (0.5)*i_omega0_hat*i_t_stance
        _x16 = i_a + 1.0
        _x17 = g_s*l0*m
        i_tau1 = _x17*(_x16 + i_b*math.sin(_x15*(1.0 - _x14) + i_phase_td))*math.sin(i_th1)
        i_tau2 = _x17*(_x16 + i_b*math.sin(_x15 + i_phase_td))*math.sin(i_th2)
        i_tau3 = _x17*(_x16 + i_b*math.sin(_x15*(_x14 + 1.0) + i_phase_td))*math.sin(i_th3)
        i_g_eff = ((0.5)*g_s*((0.5555555555555556)*math.cos(i_th1) + (0.8888888888888888)*math.cos(i_th2)
            + (0.5555555555555556)*math.cos(i_th3)))
        i_r_c = i_a - i_b*(math.cos(i_phase_lo) - math.cos(i_phase_td))/(i_phase_lo - i_phase_td)
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = i_tau1
        _n0_1 = i_tau2
        _n0_2 = i_tau3
        _n0_3 = i_t_stance
        _n0_4 = i_g_eff
        _n0_5 = i_r_c
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - tau1) <= tol*(g_s*l0*m)) and (abs(_n0_1 - tau2)
            <= tol*(g_s*l0*m)) and (abs(_n0_2 - tau3) <= tol*(g_s*l0*m)) and (abs(_n0_3 - T)
            <= tol*(math.sqrt(m)/math.sqrt(k))) and (abs(_n0_4 - g_eff) <= tol*(g_s)) and (abs(_n0_5 - r_c)
            <= tol*(1.0)))
        tau1 = _n0_0
        tau2 = _n0_1
        tau3 = _n0_2
        T = _n0_3
        g_eff = _n0_4
        r_c = _n0_5
        passes += 1.0
    _c5 = (type5_leg_angle(t, q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m,
        l0))
    q_th = _c5
    # (11) with T5.5, T5.2
    _x18 = i_omega0_hat*t + i_phase_td
    _x19 = i_a + i_b*math.sin(_x18) + 1.0
    q_r = _x19*l0
    q_rd = i_b*i_omega0_hat*l0*math.cos(_x18)
    q_thd = (i_c0*t + (0.5)*i_c1*t**2 + (0.3333333333333333)*i_c2*t**3 + p_td)/(_x19**2*l0**2*m)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((q_r, q_rd, q_th, q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (q_r, q_rd, q_th, q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type5_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type5_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(9), 9)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type5_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type5_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Gravity correction type 5 (time-varying momentum).

    Report equations: 46, 47, 48.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol); writes the outputs below into out, in order,
    and returns
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
        iterations: option iterations: fixed-point passes T5.8 from Geyer's map in [0, 1000]
        tol: option tol: stop when every state moved by at most tol times its scale; 0: run all passes in [0,
            1]

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
        P_c: stance impulse of the gravity torque P(t_lo) - p_td [N m s]
        passes: fixed-point passes run
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 3
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol,) = load(p, 0, 1, 2, 3, 4, 5, 6, 7, 8)
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k, g_s, g_f, q_r_td,
            q_r_lo, iterations, tol,)) & ((b_y_apex >= 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0))
            & ((l0 > 0.0)) & ((k > 0.0)) & ((g_s > 0.0)) & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0))
            & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0) and (tol <= 1.0))):
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
    # stance: Gravity correction type 5 (time-varying momentum)
    _x1 = carray(stack(4), 4)
    store(_x1, (td_q_r, td_q_rd, td_q_th, td_q_thd,))
    _o1 = carray(stack(12), 12)
    _c1 = gravity_type5_stance(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _o1_10, _o1_11,) = (load(_o1, 1, 6, 7, 8,
        9, 10, 11))
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
            liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th, _o1_10, _o1_11,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (apex_height, apex_speed, t_descent, _o1_1, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th, _o1_10, _o1_11,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type5_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type5_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(9), 9)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type5_apex_return(row(X, i), p, row(OUT, i))
