# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/gravity.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight.py sha256:af908ea30b1fc141
#   geyer.py sha256:110e83efcc6593e2
# ----------------------------------------------------------------------------------------------
"""Gravity corrections types 0-4 (report sections 4.1-4.5): the stance, state-at-time and apex-return kernels
of the maps gravity-type0, gravity-type1, gravity-type2, gravity-type3, gravity-type4 (one body,
derive/share.py)."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import apex_to_touchdown, liftoff_to_apex
from .geyer import geyer_liftoff_phase, geyer_solution, geyer_state

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_FALL, STATUS_NUMERICAL_RANGE,
    STATUS_NOT_CONVERGED, STATUS_ENERGY_DEFICIT)

NAN = math.nan
_NAN1 = (NAN,) * 1


@njit(cache=True, error_model="numpy", inline="always")
def gravity_impulse_type0(_a):
    """Type 0's stance impulse P_c of the trajectory (report section 4.1).

    Report equations: 49, 51.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        samples: option samples: number of torque samples in (48): 2 (touchdown, liftoff) or 3 (and the
            bottom) in [2, 3]
        interval: option interval: the intervals [t_i, t_f] of the correction: 0 = stance, 1 = halves
        leg_length: option leg_length: the stance solution the average leg length is taken from: 0 = eq11, 1 =
            eq21, 2 = eq23
        i_a: i_a of the current iterate's trajectory
        i_b: i_b of the current iterate's trajectory
        i_bottom_q_r: i_bottom_q_r of the current iterate's trajectory
        i_bottom_q_th: i_bottom_q_th of the current iterate's trajectory
        i_liftoff_q_th: i_liftoff_q_th of the current iterate's trajectory
        i_omega0_hat: i_omega0_hat of the current iterate's trajectory
        i_phase_td: i_phase_td of the current iterate's trajectory
        i_q_thd_eff: i_q_thd_eff of the current iterate's trajectory
        i_t_bottom: i_t_bottom of the current iterate's trajectory
        i_t_stance: i_t_stance of the current iterate's trajectory

    Returns a tuple:
        i_P_new: the stance impulse of the trajectory [N m s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 21
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # eq (48) with 2 or 3 samples
    if samples == 2.0:
        _x0 = g_s*l0*m
        i_P_new = (0.5)*i_t_stance*(_x0*math.sin(i_liftoff_q_th) + _x0*math.sin(q_th_td))
    elif samples == 3.0:
        _x1 = g_s*l0*m
        i_P_new = ((0.3333333333333333)*i_t_stance*(_x1*math.sin(i_bottom_q_th) + _x1*math.sin(i_liftoff_q_th)
            + _x1*math.sin(q_th_td)))
    else:
        return _NAN1 + (STATUS_INVALID_INPUT,)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((i_P_new,))):
        return _NAN1 + (STATUS_NUMERICAL_RANGE,)
    return (i_P_new, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def gravity_stance_shared(x, p, out, gravity_impulse):
    """Gravity correction type 0 (leg length l0): touchdown state -> bottom and liftoff states.

    Report equations: 46, 47, 48, 49, 50, 51.

    The body that 5 kernels share, each passing the kernel it calls as gravity_impulse
    (derive/share.py): gravity_{type0_stance, type1_stance, type2_stance, type3_stance,
    type4_stance}.

    Arguments, returns and status: those of the kernels, then gravity_impulse.
    """
    # Total ops: 126
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k, g_s, q_r_lo, reading, samples, interval, leg_length, iterations, tol,) = (load(p, 0, 1, 2, 3,
        6, 7, 8, 9, 10, 11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, samples, interval,
            leg_length, iterations, tol,)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0)
            and (q_r_lo > 0.0)) & ((reading == 0.0) or (reading == 1.0)) & ((samples == math.floor(samples))
            and (samples >= 2.0) and (samples <= 3.0)) & ((interval == 0.0) or (interval == 1.0))
            & ((leg_length == 0.0) or (leg_length == 1.0) or (leg_length == 2.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0)
            and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # leg_length eq21/eq23 need q_r_td = l0
    if not ((leg_length == 0.0) or (abs(l0 - q_r_td) <= 1e-09*l0)):
        return fail(out, STATUS_INVALID_INPUT)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = (0.5)*k
    p_td = _x1*q_thd_td
    E_td = (_x0*_x2 + (0.5)*_x1*q_thd_td**2 + _x2*l0**2 + g_s*m*q_r_td*math.cos(q_th_td) - k*l0*q_r_td
        + (0.5)*m*q_rd_td**2)
    # trajectory momentum p_td + share P_c: the stance mean (P_c/2) or the report's
    if reading == 0.0:
        share = 0.5
        ramp = 1.0
    elif reading == 1.0:
        share = 1.0
        ramp = 0.0
    else:
        return fail(out, STATUS_INVALID_INPUT)
    # fixed point of the virtual gravity effect, from P_c = 0 (Geyer's map)
    P_c = 0.0
    passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # effective touchdown rate
        i_q_thd_eff = (P_c*share + p_td)/(m*q_r_td**2)
        # eqs (7)-(12): Geyer et al.'s radial solution from the touchdown state
        _c0 = geyer_solution(q_r_td, q_rd_td, i_q_thd_eff, m, l0, k, g_s)
        if _c0[6] != STATUS_OK:
            return fail(out, _c0[6])
        i_omega = _c0[0]
        i_omega0_hat = _c0[1]
        i_a = _c0[2]
        i_b = _c0[3]
        i_phase_td = _c0[4]
        i_s_td = _c0[5]
        _c1 = geyer_liftoff_phase(i_a, i_b, l0, q_r_lo)
        if _c1[2] != STATUS_OK:
            return fail(out, _c1[2])
        i_phase_lo = _c1[0]
        i_s_lo = _c1[1]
        # eqs (13)-(14) minus (12), (11), (19), (17) at the bottom and at liftoff
        _x3 = (1.0/i_omega0_hat)
        _x4 = i_a + 1.0
        _x5 = _x4 - i_b
        _x6 = _x3*i_omega
        _x7 = _x3*i_phase_td
        _x8 = _x3*i_b
        _x9 = 2.0*i_omega
        _x10 = -_x7*i_omega + _x9*(_x7*i_a + _x8*math.sqrt(1.0 - i_s_td**2)) + q_th_td
        _x11 = math.sqrt(1.0 - i_s_lo**2)
        _x12 = _x3*i_phase_lo
        i_t_bottom = _x3*(-i_phase_td + (1.5)*math.pi)
        i_t_stance = _x3*(i_phase_lo - i_phase_td)
        i_bottom_q_r = _x5*l0
        i_bottom_q_rd = 0.0
        i_bottom_q_th = _x10 - 3.0*math.pi*_x6*i_a + (1.5)*math.pi*_x6
        i_bottom_q_thd = i_omega/_x5**2
        i_liftoff_q_r = q_r_lo
        i_liftoff_q_rd = _x11*i_b*i_omega0_hat*l0
        i_liftoff_q_th = _x10 + _x12*i_omega - _x9*(-_x11*_x8 + _x12*i_a)
        i_liftoff_q_thd = i_omega/(_x4 + i_b*i_s_lo)**2
        # the leg stays above horizontal
        if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
            return fail(out, STATUS_FALL)
        if _conv0 or _it0 == _last0:
            break
        # the type's impulse rule
        _a2 = carray(stack(20), 20)
        store(_a2, (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b,
            i_bottom_q_r, i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom,
            i_t_stance,))
        _c2 = gravity_impulse(_a2)
        if _c2[1] != STATUS_OK:
            return fail(out, _c2[1])
        i_P_new = _c2[0]
        _n0_0 = i_P_new
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - P_c) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + abs(p_td)))
        P_c = _n0_0
        passes += 1.0
    # the rates from the momentum at that instant; p_td + P_c at liftoff, eq (50)
    _x13 = (1.0/m)
    t_bottom = i_t_bottom
    t_stance = i_t_stance
    bottom_q_r = i_bottom_q_r
    bottom_q_th = i_bottom_q_th
    bottom_q_thd = _x13*(P_c*(i_t_bottom*ramp/i_t_stance - ramp + 1.0) + p_td)/i_bottom_q_r**2
    liftoff_q_r = q_r_lo
    liftoff_q_th = i_liftoff_q_th
    liftoff_q_thd = _x13*(P_c + p_td)/q_r_lo**2
    if reading == 0.0:
        _x14 = (1.0/m)
        _x15 = _x14*k
        _x16 = q_r_lo**2
        _q_rd_lo_sq = (2.0*E_td*_x14 - _x14**2*(P_c + p_td)**2/_x16 + 2.0*_x14*k*l0*q_r_lo - _x15*_x16
            - _x15*l0**2 - 2.0*g_s*q_r_lo*math.cos(i_liftoff_q_th))
        # q_rd_lo^2 from the energy (27)
        if not ((_q_rd_lo_sq >= 0.0)):
            return fail(out, STATUS_ENERGY_DEFICIT)
        # q_rd_lo from the energy
        liftoff_q_rd = math.sqrt(_q_rd_lo_sq)
    elif reading == 1.0:
        # from (11)
        liftoff_q_rd = i_liftoff_q_rd
    else:
        return fail(out, STATUS_INVALID_INPUT)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_bottom, t_stance, bottom_q_r, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
            liftoff_q_th, liftoff_q_thd, P_c, passes,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_bottom, t_stance, bottom_q_r, 0.0, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, P_c, passes,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def gravity_type0_stance(x, p, out):
    """Gravity correction type 0 (leg length l0): touchdown state -> bottom and liftoff states.

    Report equations: 46, 47, 48, 49, 50, 51.

    Runs the shared body :func:`gravity_stance_shared` with gravity_impulse_type0.

    Geyer et al.'s map (3.1) run with a corrected angular momentum; see the module docstring of
    derive/maps/gravity.py and docs/gravity.md for the two readings of (50).

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, samples, interval, leg_length, iterations, tol); writes
    the outputs below into out, in order, and returns
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
        reading: option reading: how P_c enters Geyer's formulas, eq (50): 0 = mean, 1 = report
        samples: option samples: number of torque samples in (48): 2 (touchdown, liftoff) or 3 (and the
            bottom) in [2, 3]
        interval: option interval: the intervals [t_i, t_f] of the correction: 0 = stance, 1 = halves
        leg_length: option leg_length: the stance solution the average leg length is taken from: 0 = eq11, 1 =
            eq21, 2 = eq23
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0,
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
        P_c: virtual gravity effect: the stance impulse added to p_th [N m s]
        passes: fixed-point passes run
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return gravity_stance_shared(x, p, out, gravity_impulse_type0)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type0_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type0_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type0_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline="always")
def gravity_state_at_shared(x, p, out, gravity_impulse):
    """Gravity correction type 0 (leg length l0): the polar state a time t after touchdown.

    Report equations: 46, 47, 48, 49, 50, 51.

    The body that 5 kernels share, each passing the kernel it calls as gravity_impulse
    (derive/share.py): gravity_{type0_state_at, type1_state_at, type2_state_at, type3_state_at,
    type4_state_at}.

    Arguments, returns and status: those of the kernels, then gravity_impulse.
    """
    # Total ops: 95
    (t, q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k, g_s, q_r_lo, reading, samples, interval, leg_length, iterations, tol,) = (load(p, 0, 1, 2, 3,
        6, 7, 8, 9, 10, 11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, reading, samples,
            interval, leg_length, iterations, tol,)) & ((t >= 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0))
            & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k > 0.0)) & ((g_s > 0.0))
            & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((reading == 0.0) or (reading == 1.0)) & ((samples
            == math.floor(samples)) and (samples >= 2.0) and (samples <= 3.0)) & ((interval == 0.0)
            or (interval == 1.0)) & ((leg_length == 0.0) or (leg_length == 1.0) or (leg_length == 2.0))
            & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0))
            & ((tol >= 0.0) and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # leg_length eq21/eq23 need q_r_td = l0
    if not ((leg_length == 0.0) or (abs(l0 - q_r_td) <= 1e-09*l0)):
        return fail(out, STATUS_INVALID_INPUT)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = (0.5)*k
    p_td = _x1*q_thd_td
    E_td = (_x0*_x2 + (0.5)*_x1*q_thd_td**2 + _x2*l0**2 + g_s*m*q_r_td*math.cos(q_th_td) - k*l0*q_r_td
        + (0.5)*m*q_rd_td**2)
    # trajectory momentum p_td + share P_c: the stance mean (P_c/2) or the report's
    if reading == 0.0:
        share = 0.5
        ramp = 1.0
    elif reading == 1.0:
        share = 1.0
        ramp = 0.0
    else:
        return fail(out, STATUS_INVALID_INPUT)
    # fixed point of the virtual gravity effect, from P_c = 0 (Geyer's map)
    P_c = 0.0
    passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # effective touchdown rate
        i_q_thd_eff = (P_c*share + p_td)/(m*q_r_td**2)
        # eqs (7)-(12): Geyer et al.'s radial solution from the touchdown state
        _c0 = geyer_solution(q_r_td, q_rd_td, i_q_thd_eff, m, l0, k, g_s)
        if _c0[6] != STATUS_OK:
            return fail(out, _c0[6])
        i_omega = _c0[0]
        i_omega0_hat = _c0[1]
        i_a = _c0[2]
        i_b = _c0[3]
        i_phase_td = _c0[4]
        i_s_td = _c0[5]
        _c1 = geyer_liftoff_phase(i_a, i_b, l0, q_r_lo)
        if _c1[2] != STATUS_OK:
            return fail(out, _c1[2])
        i_phase_lo = _c1[0]
        i_s_lo = _c1[1]
        # eqs (13)-(14) minus (12), (11), (19), (17) at the bottom and at liftoff
        _x3 = (1.0/i_omega0_hat)
        _x4 = i_a + 1.0
        _x5 = _x4 - i_b
        _x6 = _x3*i_omega
        _x7 = _x3*i_phase_td
        _x8 = _x3*i_b
        _x9 = 2.0*i_omega
        _x10 = -_x7*i_omega + _x9*(_x7*i_a + _x8*math.sqrt(1.0 - i_s_td**2)) + q_th_td
        _x11 = math.sqrt(1.0 - i_s_lo**2)
        _x12 = _x3*i_phase_lo
        i_t_bottom = _x3*(-i_phase_td + (1.5)*math.pi)
        i_t_stance = _x3*(i_phase_lo - i_phase_td)
        i_bottom_q_r = _x5*l0
        i_bottom_q_rd = 0.0
        i_bottom_q_th = _x10 - 3.0*math.pi*_x6*i_a + (1.5)*math.pi*_x6
        i_bottom_q_thd = i_omega/_x5**2
        i_liftoff_q_r = q_r_lo
        i_liftoff_q_rd = _x11*i_b*i_omega0_hat*l0
        i_liftoff_q_th = _x10 + _x12*i_omega - _x9*(-_x11*_x8 + _x12*i_a)
        i_liftoff_q_thd = i_omega/(_x4 + i_b*i_s_lo)**2
        # the leg stays above horizontal
        if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
            return fail(out, STATUS_FALL)
        if _conv0 or _it0 == _last0:
            break
        # the type's impulse rule
        _a2 = carray(stack(20), 20)
        store(_a2, (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b,
            i_bottom_q_r, i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom,
            i_t_stance,))
        _c2 = gravity_impulse(_a2)
        if _c2[1] != STATUS_OK:
            return fail(out, _c2[1])
        i_P_new = _c2[0]
        _n0_0 = i_P_new
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - P_c) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + abs(p_td)))
        P_c = _n0_0
        passes += 1.0
    phase_t = i_omega0_hat*t + i_phase_td
    _c3 = geyer_state(phase_t, i_phase_td, q_th_td, i_omega, i_omega0_hat, i_a, i_b, l0)
    q_r = _c3[0]
    q_rd = _c3[1]
    q_th = _c3[2]
    # the momentum at t
    q_thd = (P_c*(-ramp + 1.0 + ramp*t/i_t_stance) + p_td)/(m*q_r**2)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((q_r, q_rd, q_th, q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (q_r, q_rd, q_th, q_thd,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def gravity_type0_state_at(x, p, out):
    """Gravity correction type 0 (leg length l0): the polar state a time t after touchdown.

    Report equations: 46, 47, 48, 49, 50, 51.

    Runs the shared body :func:`gravity_state_at_shared` with gravity_impulse_type0.

    Role kernel: reads x = (t, q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, samples, interval, leg_length, iterations, tol); writes
    the outputs below into out, in order, and returns
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
        reading: option reading: how P_c enters Geyer's formulas, eq (50): 0 = mean, 1 = report
        samples: option samples: number of torque samples in (48): 2 (touchdown, liftoff) or 3 (and the
            bottom) in [2, 3]
        interval: option interval: the intervals [t_i, t_f] of the correction: 0 = stance, 1 = halves
        leg_length: option leg_length: the stance solution the average leg length is taken from: 0 = eq11, 1 =
            eq21, 2 = eq23
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0,
            1]

    Writes into out:
        q_r: leg length [m]
        q_rd: leg length rate [m/s]
        q_th: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return gravity_state_at_shared(x, p, out, gravity_impulse_type0)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type0_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type0_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type0_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline="always")
def gravity_apex_return_shared(x, p, out, gravity_stance):
    """Apex-return map: exact flights, stance by Gravity correction type 0 (leg length l0).

    Report equations: 46, 47, 48, 49, 50, 51.

    The body that 5 kernels share, each passing the kernel it calls as gravity_stance
    (derive/share.py): gravity_{type0_apex_return, type1_apex_return, type2_apex_return,
    type3_apex_return, type4_apex_return}.

    Arguments, returns and status: those of the kernels, then gravity_stance.
    """
    # Total ops: 3
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, samples, interval, leg_length, iterations, tol,) = (load(p,
        0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k, g_s, g_f, q_r_td,
            q_r_lo, reading, samples, interval, leg_length, iterations, tol,)) & ((b_y_apex >= 0.0))
            & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k > 0.0)) & ((g_s > 0.0))
            & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))
            & ((reading == 0.0) or (reading == 1.0)) & ((samples == math.floor(samples)) and (samples >= 2.0)
            and (samples <= 3.0)) & ((interval == 0.0) or (interval == 1.0)) & ((leg_length == 0.0)
            or (leg_length == 1.0) or (leg_length == 2.0)) & ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0) and (tol <= 1.0))):
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
    # stance: Gravity corrections types 0-4
    _x1 = carray(stack(4), 4)
    store(_x1, (td_q_r, td_q_rd, td_q_th, td_q_thd,))
    _o1 = carray(stack(12), 12)
    _c1 = gravity_stance(_x1, p, _o1)
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


@njit(cache=True, error_model="numpy")
def gravity_type0_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Gravity correction type 0 (leg length l0).

    Report equations: 46, 47, 48, 49, 50, 51.

    Runs the shared body :func:`gravity_apex_return_shared` with gravity_type0_stance.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, samples, interval, leg_length, iterations, tol); writes
    the outputs below into out, in order, and returns
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
        reading: option reading: how P_c enters Geyer's formulas, eq (50): 0 = mean, 1 = report
        samples: option samples: number of torque samples in (48): 2 (touchdown, liftoff) or 3 (and the
            bottom) in [2, 3]
        interval: option interval: the intervals [t_i, t_f] of the correction: 0 = stance, 1 = halves
        leg_length: option leg_length: the stance solution the average leg length is taken from: 0 = eq11, 1 =
            eq21, 2 = eq23
        iterations: option iterations: passes of P_c <- P_c(map(P_c)) from P_c = 0 (Geyer's map) in [0, 1000]
        tol: option tol: stop when P_c moves by at most tol times the momentum scale; 0: run all passes in [0,
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
        P_c: virtual gravity effect: the stance impulse added to p_th [N m s]
        passes: fixed-point passes run
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return gravity_apex_return_shared(x, p, out, gravity_type0_stance)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type0_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type0_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type0_apex_return(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline="always")
def gravity_impulse_type1(_a):
    """Type 1's stance impulse P_c of the trajectory (report section 4.2).

    Report equations: 52, 53, 54.

    Arguments, returns and status: those of :func:`gravity_impulse_type0`.
    """
    # Total ops: 27
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # eq (48) with 2 or 3 samples
    if samples == 2.0:
        _x0 = g_s*m*((0.5)*i_bottom_q_r + (0.5)*l0)
        i_P_new = (0.5)*i_t_stance*(_x0*math.sin(i_liftoff_q_th) + _x0*math.sin(q_th_td))
    elif samples == 3.0:
        _x1 = g_s*m*((0.5)*i_bottom_q_r + (0.5)*l0)
        i_P_new = ((0.3333333333333333)*i_t_stance*(_x1*math.sin(i_bottom_q_th) + _x1*math.sin(i_liftoff_q_th)
            + _x1*math.sin(q_th_td)))
    else:
        return _NAN1 + (STATUS_INVALID_INPUT,)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((i_P_new,))):
        return _NAN1 + (STATUS_NUMERICAL_RANGE,)
    return (i_P_new, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type1_stance(x, p, out):
    """Gravity correction type 1 (leg length (l0 + q_r_b)/2): touchdown state -> bottom and liftoff states.

    Report equations: 46, 47, 48, 50, 52, 53, 54.

    Runs the shared body :func:`gravity_stance_shared` with gravity_impulse_type1. Arguments,
    returns and status: those of :func:`gravity_type0_stance`.
    """
    # Total ops: 0
    return gravity_stance_shared(x, p, out, gravity_impulse_type1)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type1_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type1_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type1_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type1_state_at(x, p, out):
    """Gravity correction type 1 (leg length (l0 + q_r_b)/2): the polar state a time t after touchdown.

    Report equations: 46, 47, 48, 50, 52, 53, 54.

    Runs the shared body :func:`gravity_state_at_shared` with gravity_impulse_type1. Arguments,
    returns and status: those of :func:`gravity_type0_state_at`.
    """
    # Total ops: 0
    return gravity_state_at_shared(x, p, out, gravity_impulse_type1)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type1_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type1_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type1_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type1_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Gravity correction type 1 (leg length (l0 + q_r_b)/2).

    Report equations: 46, 47, 48, 50, 52, 53, 54.

    Runs the shared body :func:`gravity_apex_return_shared` with gravity_type1_stance.
    Arguments, returns and status: those of :func:`gravity_type0_apex_return`.
    """
    # Total ops: 0
    return gravity_apex_return_shared(x, p, out, gravity_type1_stance)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type1_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type1_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type1_apex_return(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline="always")
def gravity_impulse_type2(_a):
    """Type 2's stance impulse P_c of the trajectory (report section 4.3).

    Report equations: 55, 56, 57, 58, 59, 60, 61, 62, 63, 64.

    Arguments, returns and status: those of :func:`gravity_impulse_type0`.
    """
    # Total ops: 84
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # average leg length, eqs (55)-(61) / (67)-(75)
    if leg_length == 0.0:
        _x0 = (1.0/i_omega0_hat)
        _x1 = i_a + 1.0
        _x2 = i_omega0_hat*(_x0*i_phase_td + i_t_stance)
        _i_L = _x0*l0*(_x1*_x2 - _x1*i_phase_td - i_b*math.cos(_x2) + i_b*math.cos(i_phase_td))/i_t_stance
    elif leg_length == 1.0:
        _x3 = i_omega0_hat*i_t_stance
        _x4 = i_b**2
        _x5 = math.sqrt((_x4 - i_a**2)/_x4)
        _i_L = (l0*(_x5*i_b*math.cos(_x3) - _x5*i_b - i_a*math.sin(_x3) + i_omega0_hat*(i_a*i_t_stance
            + i_t_stance))/(i_omega0_hat*i_t_stance))
    elif leg_length == 2.0:
        _x6 = i_omega0_hat*i_t_stance
        _x7 = math.sin(_x6)
        _x8 = i_q_thd_eff**2
        _x9 = i_t_stance*l0
        _i_L = ((-_x7*_x8*l0 + _x7*g_s + i_omega0_hat*q_rd_td - i_omega0_hat*(-_x8*_x9 - _x9*i_omega0_hat**2
            + g_s*i_t_stance + q_rd_td*math.cos(_x6)))/(i_omega0_hat**3*i_t_stance))
    else:
        return _NAN1 + (STATUS_INVALID_INPUT,)
    # eq (48) with 2 or 3 samples
    if samples == 2.0:
        _x10 = _i_L*g_s*m
        i_P_new = (0.5)*i_t_stance*(_x10*math.sin(i_liftoff_q_th) + _x10*math.sin(q_th_td))
    elif samples == 3.0:
        _x11 = _i_L*g_s*m
        i_P_new = ((0.3333333333333333)*i_t_stance*(_x11*math.sin(i_bottom_q_th)
            + _x11*math.sin(i_liftoff_q_th) + _x11*math.sin(q_th_td)))
    else:
        return _NAN1 + (STATUS_INVALID_INPUT,)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((i_P_new,))):
        return _NAN1 + (STATUS_NUMERICAL_RANGE,)
    return (i_P_new, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type2_stance(x, p, out):
    """Gravity correction type 2 (average leg length): touchdown state -> bottom and liftoff states.

    Report equations: 46, 47, 48, 50, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64.

    Runs the shared body :func:`gravity_stance_shared` with gravity_impulse_type2. Arguments,
    returns and status: those of :func:`gravity_type0_stance`.
    """
    # Total ops: 0
    return gravity_stance_shared(x, p, out, gravity_impulse_type2)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type2_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type2_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type2_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type2_state_at(x, p, out):
    """Gravity correction type 2 (average leg length): the polar state a time t after touchdown.

    Report equations: 46, 47, 48, 50, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64.

    Runs the shared body :func:`gravity_state_at_shared` with gravity_impulse_type2. Arguments,
    returns and status: those of :func:`gravity_type0_state_at`.
    """
    # Total ops: 0
    return gravity_state_at_shared(x, p, out, gravity_impulse_type2)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type2_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type2_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type2_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type2_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Gravity correction type 2 (average leg length).

    Report equations: 46, 47, 48, 50, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64.

    Runs the shared body :func:`gravity_apex_return_shared` with gravity_type2_stance.
    Arguments, returns and status: those of :func:`gravity_type0_apex_return`.
    """
    # Total ops: 0
    return gravity_apex_return_shared(x, p, out, gravity_type2_stance)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type2_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type2_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type2_apex_return(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline="always")
def gravity_impulse_type3(_a):
    """Type 3's stance impulse P_c of the trajectory (report section 4.4).

    Report equations: 65, 66.

    Arguments, returns and status: those of :func:`gravity_impulse_type0`.
    """
    # Total ops: 28
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # eq (65)
    if interval == 0.0:
        _x0 = g_s*m
        i_P_new = (0.5)*i_t_stance*(_x0*q_r_lo*math.sin(i_liftoff_q_th) + _x0*q_r_td*math.sin(q_th_td))
    elif interval == 1.0:
        _x1 = g_s*m
        _x2 = _x1*i_bottom_q_r*math.sin(i_bottom_q_th)
        i_P_new = ((0.5)*i_t_bottom*(_x1*q_r_td*math.sin(q_th_td) + _x2) + (0.5)*(-i_t_bottom
            + i_t_stance)*(_x1*q_r_lo*math.sin(i_liftoff_q_th) + _x2))
    else:
        return _NAN1 + (STATUS_INVALID_INPUT,)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((i_P_new,))):
        return _NAN1 + (STATUS_NUMERICAL_RANGE,)
    return (i_P_new, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type3_stance(x, p, out):
    """Gravity correction type 3 (trapezoid on [t_i, t_f]): touchdown state -> bottom and liftoff states.

    Report equations: 46, 47, 48, 50, 65, 66.

    Runs the shared body :func:`gravity_stance_shared` with gravity_impulse_type3. Arguments,
    returns and status: those of :func:`gravity_type0_stance`.
    """
    # Total ops: 0
    return gravity_stance_shared(x, p, out, gravity_impulse_type3)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type3_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type3_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type3_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type3_state_at(x, p, out):
    """Gravity correction type 3 (trapezoid on [t_i, t_f]): the polar state a time t after touchdown.

    Report equations: 46, 47, 48, 50, 65, 66.

    Runs the shared body :func:`gravity_state_at_shared` with gravity_impulse_type3. Arguments,
    returns and status: those of :func:`gravity_type0_state_at`.
    """
    # Total ops: 0
    return gravity_state_at_shared(x, p, out, gravity_impulse_type3)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type3_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type3_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type3_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type3_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Gravity correction type 3 (trapezoid on [t_i, t_f]).

    Report equations: 46, 47, 48, 50, 65, 66.

    Runs the shared body :func:`gravity_apex_return_shared` with gravity_type3_stance.
    Arguments, returns and status: those of :func:`gravity_type0_apex_return`.
    """
    # Total ops: 0
    return gravity_apex_return_shared(x, p, out, gravity_type3_stance)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type3_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type3_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type3_apex_return(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline="always")
def gravity_impulse_type4(_a):
    """Type 4's stance impulse P_c of the trajectory (report section 4.5).

    Report equations: 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Arguments, returns and status: those of :func:`gravity_impulse_type0`.
    """
    # Total ops: 245
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # eq (76)
    if interval == 0.0:
        # average leg length, eqs (55)-(61) / (67)-(75)
        if leg_length == 0.0:
            _x0 = (1.0/i_omega0_hat)
            _x1 = i_a + 1.0
            _x2 = i_omega0_hat*(_x0*i_phase_td + i_t_stance)
            _i_L = _x0*l0*(_x1*_x2 - _x1*i_phase_td - i_b*math.cos(_x2) + i_b*math.cos(i_phase_td))/i_t_stance
        elif leg_length == 1.0:
            _x3 = i_omega0_hat*i_t_stance
            _x4 = i_b**2
            _x5 = math.sqrt((_x4 - i_a**2)/_x4)
            _i_L = (l0*(_x5*i_b*math.cos(_x3) - _x5*i_b - i_a*math.sin(_x3) + i_omega0_hat*(i_a*i_t_stance
                + i_t_stance))/(i_omega0_hat*i_t_stance))
        elif leg_length == 2.0:
            _x6 = i_omega0_hat*i_t_stance
            _x7 = math.sin(_x6)
            _x8 = i_q_thd_eff**2
            _x9 = i_t_stance*l0
            _i_L = ((-_x7*_x8*l0 + _x7*g_s + i_omega0_hat*q_rd_td - i_omega0_hat*(-_x8*_x9
                - _x9*i_omega0_hat**2 + g_s*i_t_stance + q_rd_td*math.cos(_x6)))/(i_omega0_hat**3*i_t_stance))
        else:
            return _NAN1 + (STATUS_INVALID_INPUT,)
        _x10 = _i_L*g_s*m
        i_P_new = (0.5)*i_t_stance*(_x10*math.sin(i_liftoff_q_th) + _x10*math.sin(q_th_td))
    elif interval == 1.0:
        # average leg length, eqs (55)-(61) / (67)-(75)
        if leg_length == 0.0:
            _x11 = (1.0/i_omega0_hat)
            _x12 = i_a + 1.0
            _x13 = i_omega0_hat*(_x11*i_phase_td + i_t_bottom)
            _i_L1 = (_x11*l0*(_x12*_x13 - _x12*i_phase_td - i_b*math.cos(_x13)
                + i_b*math.cos(i_phase_td))/i_t_bottom)
        elif leg_length == 1.0:
            _x14 = i_omega0_hat*i_t_bottom
            _x15 = i_b**2
            _x16 = math.sqrt((_x15 - i_a**2)/_x15)
            _i_L1 = (l0*(_x16*i_b*math.cos(_x14) - _x16*i_b - i_a*math.sin(_x14)
                + i_omega0_hat*(i_a*i_t_bottom + i_t_bottom))/(i_omega0_hat*i_t_bottom))
        elif leg_length == 2.0:
            _x17 = i_omega0_hat*i_t_bottom
            _x18 = math.sin(_x17)
            _x19 = i_q_thd_eff**2
            _x20 = i_t_bottom*l0
            _i_L1 = ((-_x18*_x19*l0 + _x18*g_s + i_omega0_hat*q_rd_td - i_omega0_hat*(-_x19*_x20
                - _x20*i_omega0_hat**2 + g_s*i_t_bottom
                + q_rd_td*math.cos(_x17)))/(i_omega0_hat**3*i_t_bottom))
        else:
            return _NAN1 + (STATUS_INVALID_INPUT,)
        # average leg length, eqs (55)-(61) / (67)-(75)
        if leg_length == 0.0:
            _x21 = (1.0/i_omega0_hat)
            _x22 = _x21*i_phase_td
            _x23 = i_omega0_hat*(_x22 + i_t_bottom)
            _x24 = i_a + 1.0
            _x25 = i_omega0_hat*(_x22 + i_t_stance)
            _i_L2 = (_x21*l0*(-_x23*_x24 + _x24*_x25 + i_b*math.cos(_x23) - i_b*math.cos(_x25))/(-i_t_bottom
                + i_t_stance))
        elif leg_length == 1.0:
            _x26 = i_t_bottom - i_t_stance
            _x27 = i_omega0_hat*i_t_bottom
            _x28 = i_omega0_hat*i_t_stance
            _x29 = i_b**2
            _x30 = i_b*math.sqrt((_x29 - i_a**2)/_x29)
            _i_L2 = (-l0*(-_x30*math.cos(_x27) + _x30*math.cos(_x28) + i_a*math.sin(_x27) - i_a*math.sin(_x28)
                + i_omega0_hat*(-_x26 - i_a*i_t_bottom + i_a*i_t_stance))/(_x26*i_omega0_hat))
        elif leg_length == 2.0:
            _x31 = i_omega0_hat*i_t_bottom
            _x32 = math.sin(_x31)
            _x33 = i_omega0_hat*i_t_stance
            _x34 = math.sin(_x33)
            _x35 = i_q_thd_eff**2
            _x36 = i_omega0_hat**2
            _x37 = i_t_stance*l0
            _x38 = i_t_bottom*l0
            _i_L2 = ((_x32*_x35*l0 - _x32*g_s - _x34*_x35*l0 + _x34*g_s - i_omega0_hat*(-_x35*_x37 - _x36*_x37
                + g_s*i_t_stance + q_rd_td*math.cos(_x33)) + i_omega0_hat*(-_x35*_x38 - _x36*_x38
                + g_s*i_t_bottom + q_rd_td*math.cos(_x31)))/(i_omega0_hat**3*(-i_t_bottom + i_t_stance)))
        else:
            return _NAN1 + (STATUS_INVALID_INPUT,)
        _x39 = math.sin(i_bottom_q_th)
        _x40 = g_s*m
        _x41 = _i_L1*_x40
        _x42 = _i_L2*_x40
        i_P_new = ((0.5)*i_t_bottom*(_x39*_x41 + _x41*math.sin(q_th_td)) + (0.5)*(-i_t_bottom
            + i_t_stance)*(_x39*_x42 + _x42*math.sin(i_liftoff_q_th)))
    else:
        return _NAN1 + (STATUS_INVALID_INPUT,)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((i_P_new,))):
        return _NAN1 + (STATUS_NUMERICAL_RANGE,)
    return (i_P_new, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance(x, p, out):
    """Gravity correction type 4 (average leg length on [t_i, t_f]): touchdown state -> bottom and liftoff
    states.

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Runs the shared body :func:`gravity_stance_shared` with gravity_impulse_type4. Arguments,
    returns and status: those of :func:`gravity_type0_stance`.
    """
    # Total ops: 0
    return gravity_stance_shared(x, p, out, gravity_impulse_type4)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type4_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type4_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type4_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type4_state_at(x, p, out):
    """Gravity correction type 4 (average leg length on [t_i, t_f]): the polar state a time t after touchdown.

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Runs the shared body :func:`gravity_state_at_shared` with gravity_impulse_type4. Arguments,
    returns and status: those of :func:`gravity_type0_state_at`.
    """
    # Total ops: 0
    return gravity_state_at_shared(x, p, out, gravity_impulse_type4)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type4_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type4_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type4_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type4_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Gravity correction type 4 (average leg length on [t_i, t_f]).

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Runs the shared body :func:`gravity_apex_return_shared` with gravity_type4_stance.
    Arguments, returns and status: those of :func:`gravity_type0_apex_return`.
    """
    # Total ops: 0
    return gravity_apex_return_shared(x, p, out, gravity_type4_stance)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type4_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type4_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type4_apex_return(row(X, i), p, row(OUT, i))
