# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/geyer_vs.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight.py sha256:af908ea30b1fc141
#   geyer.py sha256:110e83efcc6593e2
# ----------------------------------------------------------------------------------------------
"""Simple variable-stiffness map (Geyer et al. per half) (report section 5.1): stance, state-at-time and
apex-return kernels."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import apex_to_touchdown, liftoff_to_apex
from .geyer import geyer_liftoff_phase, geyer_solution, geyer_state

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_NO_REAL_SOLUTION, STATUS_FALL,
    STATUS_RECOMPRESSION, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED, STATUS_ENERGY_DEFICIT)

NAN = math.nan
_NAN1 = (NAN,) * 1


@njit(cache=True, error_model="numpy")
def bottom_quartic(p_b, E_ab, m, l0, k_c, g_s):
    """Bottom leg length of (153): the compressing root of the quartic in (0, l0] (Newton).

    Report equations: 153.

    Arguments:
        p_b: angular momentum p_th at the bottom [kg m^2/s]
        E_ab: total energy E_ab [J]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0

    Returns a tuple:
        q_r_b: bottom leg length of (153) [m]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 64
    # inputs: finite and inside their domains
    if not (all_finite((p_b, E_ab, m, l0, k_c, g_s,)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((g_s
            > 0.0))):
        return _NAN1 + (STATUS_INVALID_INPUT,)
    # a start left of the root: V >= E there
    _x0 = g_s*m
    _x1 = _x0/k_c
    _x2 = k_c*l0**2
    _x3 = _x1 - l0
    _x4 = -_x3
    _x5 = _x4**2*k_c
    _x6 = _x0*_x4
    _x7 = math.sqrt(2.0*E_ab - _x2 + 2.0*_x4*k_c*l0 - _x5 - 2.0*_x6)/math.sqrt(k_c)
    _x8 = math.sqrt(2.0)*abs(p_b)/(math.sqrt(m)*math.sqrt(E_ab - 0.5*_x2 + _x4*k_c*l0 - 0.5*_x5 - _x6))
    q_start = -0.5*_x1 - 0.5*_x7 + (0.25)*_x8 + (0.5)*l0 + (0.5)*abs(_x3 + _x7 + (0.5)*_x8)
    # E_ab above the minimum of the potential
    if not ((E_ab > g_s*m*(-g_s*m/k_c + l0) + (0.5)*k_c*l0**2 - k_c*l0*(-g_s*m/k_c + l0)
            + (0.5)*k_c*(-g_s*m/k_c + l0)**2)):
        return _NAN1 + (STATUS_NO_REAL_SOLUTION,)
    # Newton's method on V - E: monotone from the left
    qb = q_start
    passes = 0.0
    _conv0 = False
    for _it0 in range(int(60.0)):
        slope = g_s*m - k_c*l0 + k_c*qb - p_b**2/(m*qb**3)
        # V decreasing left of the root
        if not ((slope < 0.0)):
            return _NAN1 + (STATUS_NO_REAL_SOLUTION,)
        _n0_0 = (qb - (-E_ab + g_s*m*qb + (0.5)*k_c*l0**2 - k_c*l0*qb + (0.5)*k_c*qb**2
            + (0.5)*p_b**2/(m*qb**2))/slope)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = 1e-12 > 0.0 and (abs(_n0_0 - qb) <= 1e-12*(l0))
        qb = _n0_0
        passes += 1.0
        if _conv0:
            break
    if not _conv0 and 1e-12 > 0.0 and passes > 0.0:
        return _NAN1 + (STATUS_NOT_CONVERGED,)
    q_r_b = qb
    # the bottom root is at most l0
    if not ((qb <= l0)):
        return _NAN1 + (STATUS_NO_REAL_SOLUTION,)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((q_r_b,))):
        return _NAN1 + (STATUS_NUMERICAL_RANGE,)
    return (q_r_b, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance(x, p, out):
    """Simple variable-stiffness map (Geyer et al. per half): touchdown state -> bottom and liftoff states.

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 96, 97, 98, 99, 100,
    101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113.

    Section 5.1: apex to bottom (78)-(89) with k_c, bottom to apex (90)-(105) with k_d and E_ba
    = E_ab + (k_d - k_c)(l0 - q_r_b)^2/2; option continuity chooses (103)-(104) with the
    touchdown energy (27), the constraint (111), or (103)-(104) with the energy of the first
    half; option gravity adds type 3 or 4 of section 4 on each half.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol); writes the outputs
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
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0
            = report, 1 = constrained, 2 = energy
        gravity: option gravity: virtual gravity effect on p_th per half (report 4.4-4.5 on [t_td, t_b] and
            [t_b, t_lo]); each half runs with its mean momentum, the rates with the momentum at that instant:
            0 = none, 1 = type3, 2 = type4
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
        P_c_compression: virtual gravity effect of the first half (0 unless gravity) [N m s]
        P_c_decompression: virtual gravity effect of the second half [N m s]
        passes: fixed-point passes run (0 unless gravity)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 297
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol,) = (load(p, 0, 1, 2, 3, 4, 7, 8, 9,
        10, 11))
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity,
            iterations, tol,)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m
            > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0)
            and (q_r_lo > 0.0)) & ((continuity == 0.0) or (continuity == 1.0) or (continuity == 2.0))
            & ((gravity == 0.0) or (gravity == 1.0) or (gravity == 2.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0)
            and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = (0.5)*k_c
    p_td = _x1*q_thd_td
    E_td = (_x0*_x2 + (0.5)*_x1*q_thd_td**2 + _x2*l0**2 + g_s*m*q_r_td*math.cos(q_th_td) - k_c*l0*q_r_td
        + (0.5)*m*q_rd_td**2)
    # fixed point of the two halves' virtual gravity effects, from 0 (none: no pass)
    P_c_compression = 0.0
    P_c_decompression = 0.0
    passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(((0.0) if (gravity == 0.0) else (iterations))), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # the first half's mean momentum as a touchdown rate
        i_q_thd_eff = ((0.5)*P_c_compression + p_td)/(m*q_r_td**2)
        # eqs (78), (82)-(87): Geyer's radial solution with k_c from the touchdown state
        _c0 = geyer_solution(q_r_td, q_rd_td, i_q_thd_eff, m, l0, k_c, g_s)
        if _c0[6] != STATUS_OK:
            return fail(out, _c0[6])
        i_ab_omega = _c0[0]
        i_ab_omega0_hat = _c0[1]
        i_ab_a = _c0[2]
        i_ab_b = _c0[3]
        i_ab_phase_td = _c0[4]
        i_ab_s_td = _c0[5]
        # eqs (79)-(81): the bottom at phase 3 pi/2
        _x3 = (1.0/i_ab_omega0_hat)
        _x4 = i_ab_a - i_ab_b
        _x5 = _x4 + 1.0
        _x6 = _x3*i_ab_omega
        _x7 = _x3*i_ab_phase_td
        _x8 = P_c_compression + p_td
        i_t_bottom = _x3*(-i_ab_phase_td + (1.5)*math.pi)
        i_bottom_q_r = _x5*l0
        i_bottom_q_rd = 0.0
        i_bottom_q_th = (-3.0*math.pi*_x6*i_ab_a + (1.5)*math.pi*_x6 - _x7*i_ab_omega
            + 2.0*i_ab_omega*(_x3*i_ab_b*math.sqrt(1.0 - i_ab_s_td**2) + _x7*i_ab_a) + q_th_td)
        i_p_b = _x8
        i_bottom_q_thd = _x8/(_x5**2*l0**2*m)
        i_rho_b = _x4
        # eqs (100)-(103): omega_ba from the momentum, omega0_ba^2 = k_d/m
        _x13 = (1.0/l0)
        _x9 = (1.0/m)
        _x10 = (0.5)*P_c_decompression + i_p_b
        _x11 = _x10**2
        _x12 = 3.0*_x11*_x13**4*_x9 + k_d
        i_ba_omega = _x10*_x13**2*_x9
        i_ba_omega0_hat = math.sqrt(_x12)/math.sqrt(m)
        i_ba_a_free = _x13*m*(_x11*_x13**3*_x9**2 - g_s)/_x12
        # with k_d the bottom lies below the centre a_ba of (90): the leg extends
        if not ((i_rho_b < i_ba_a_free)):
            return fail(out, STATUS_RECOMPRESSION)
        # E_ab of (98)
        if continuity == 0.0:
            # eqs (97)-(99), E_ab the energy (27)
            i_eps_ba = (2.0*E_td - (-i_bottom_q_r + l0)**2*(k_c - k_d))/(l0**2*m)
        elif continuity == 1.0:
            # as report
            i_eps_ba = (2.0*E_td - (-i_bottom_q_r + l0)**2*(k_c - k_d))/(l0**2*m)
        elif continuity == 2.0:
            # eqs (97)-(99) with E_ab Geyer's energy (8) at the bottom
            _x17 = (1.0/l0)
            _x14 = i_ba_omega**2
            _x15 = 2.0*_x17*g_s
            _x16 = (1.0/m)
            i_eps_ba = (_x14 + _x15 - _x16*_x17**2*(-i_bottom_q_r + l0)**2*(k_c - k_d) + i_rho_b**2*(3.0*_x14
                + _x16*k_c) + i_rho_b*(-2.0*_x14 + _x15))
        else:
            return fail(out, STATUS_INVALID_INPUT)
        _x18 = i_ba_omega**2
        _x19 = 3.0*_x18*m + k_d
        i_ba_b2 = -m*(_x19*l0*(2.0*g_s - l0*(-_x18 + i_eps_ba)) - m*(-_x18*l0 + g_s)**2)/(_x19**2*l0**2)
        # eq (104): real amplitude b_ba
        if not ((i_ba_b2 > 0.0)):
            return fail(out, STATUS_NO_REAL_SOLUTION)
        # eq (104); eq (103), or (111) when constrained
        _x20 = math.sqrt(i_ba_b2)
        i_ba_b = _x20
        i_ba_a = ((_x20 + i_rho_b) if (continuity == 1.0) else (i_ba_a_free))
        # eq (94): the liftoff phase of the second half
        _c1 = geyer_liftoff_phase(i_ba_a, i_ba_b, l0, q_r_lo)
        if _c1[2] != STATUS_OK:
            return fail(out, _c1[2])
        i_ba_phase_lo = _c1[0]
        i_ba_s_lo = _c1[1]
        # eqs (90)-(94) at liftoff
        _x26 = (1.0/m)
        _x21 = (1.0/i_ba_omega0_hat)
        _x22 = (1.5)*math.pi
        _x23 = _x21*i_ba_phase_lo
        _x24 = _x21*i_ba_omega
        _x25 = (-_x22*_x24 + _x23*i_ba_omega + 3.0*math.pi*_x24*i_ba_a
            - 2.0*i_ba_omega*(-_x21*i_ba_b*math.sqrt(1.0 - i_ba_s_lo**2) + _x23*i_ba_a) + i_bottom_q_th)
        _x27 = q_r_lo**2
        _x28 = (1.0/_x27)
        _x29 = P_c_decompression + i_p_b
        _x30 = _x26*k_d
        i_t_stance = _x21*(-_x22 + i_ba_phase_lo) + i_t_bottom
        i_liftoff_q_r = q_r_lo
        i_liftoff_q_th = _x25
        i_liftoff_q_thd = _x26*_x28*_x29
        i_q_rd_lo_sq = (-_x26**2*_x28*_x29**2 + 2.0*_x26*k_d*l0*q_r_lo + 2.0*_x26*(E_td - 0.5*(-i_bottom_q_r
            + l0)**2*(k_c - k_d)) - _x27*_x30 - _x30*l0**2 - 2.0*g_s*q_r_lo*math.cos(_x25))
        # the leg stays above horizontal
        if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
            return fail(out, STATUS_FALL)
        # q_rd_lo^2 from the energy
        if not ((gravity == 0.0) or (i_q_rd_lo_sq >= 0.0)):
            return fail(out, STATUS_ENERGY_DEFICIT)
        # q_rd_lo: (11) without a gravity correction, the energy with one
        i_liftoff_q_rd = ((i_ba_b*i_ba_omega0_hat*l0*math.sqrt(1.0 - i_ba_s_lo**2)) if (gravity == 0.0)
            else (math.sqrt(i_q_rd_lo_sq)))
        if _conv0 or _it0 == _last0:
            break
        # the virtual gravity effect of each half
        if gravity == 0.0:
            i_P_new1 = 0.0
            i_P_new2 = 0.0
        elif gravity == 1.0:
            # eq (65) on each half
            _x31 = g_s*m
            _x32 = _x31*i_bottom_q_r*math.sin(i_bottom_q_th)
            i_P_new1 = (0.5)*i_t_bottom*(_x31*q_r_td*math.sin(q_th_td) + _x32)
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x31*q_r_lo*math.sin(i_liftoff_q_th) + _x32)
        elif gravity == 2.0:
            # eq (76) on each half, the average leg length of (11) on it
            _x33 = (1.0/i_ab_omega0_hat)
            _x34 = i_ab_a + 1.0
            _x35 = (1.5)*math.pi
            _x36 = (_x33*l0*(_x34*_x35 - _x34*i_ab_phase_td
                + i_ab_b*math.cos(i_ab_phase_td))/(-_x33*i_ab_phase_td + (1.5)*math.pi*_x33))
            _x37 = (1.0/i_ba_omega0_hat)
            _x38 = i_ba_a + 1.0
            _x39 = (_x37*l0*(-_x35*_x38 + _x38*i_ba_phase_lo - i_ba_b*math.cos(i_ba_phase_lo))/(-_x35*_x37
                + _x37*i_ba_phase_lo))
            _x40 = math.sin(i_bottom_q_th)
            _x41 = g_s*m
            _x42 = _x36*_x41
            _x43 = _x39*_x41
            _i_L1 = _x36
            _i_L2 = _x39
            i_P_new1 = (0.5)*i_t_bottom*(_x40*_x42 + _x42*math.sin(q_th_td))
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x40*_x43 + _x43*math.sin(i_liftoff_q_th))
        else:
            return fail(out, STATUS_INVALID_INPUT)
        _n0_0 = i_P_new1
        _n0_1 = i_P_new2
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - P_c_compression) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + abs(p_td))) and (abs(_n0_1 - P_c_decompression) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + abs(p_td))))
        P_c_compression = _n0_0
        P_c_decompression = _n0_1
        passes += 1.0
    # the stance outputs: the pass at the final iterate
    t_bottom = i_t_bottom
    t_stance = i_t_stance
    bottom_q_r = i_bottom_q_r
    bottom_q_rd = i_bottom_q_rd
    bottom_q_th = i_bottom_q_th
    bottom_q_thd = i_bottom_q_thd
    liftoff_q_r = i_liftoff_q_r
    liftoff_q_rd = i_liftoff_q_rd
    liftoff_q_th = i_liftoff_q_th
    liftoff_q_thd = i_liftoff_q_thd
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
            liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c_compression, P_c_decompression, passes,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c_compression, P_c_decompression, passes,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_vs_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_vs_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_vs_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def geyer_vs_state_at(x, p, out):
    """Simple variable-stiffness map (Geyer et al. per half): the polar state a time t after touchdown.

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 96, 97, 98, 99, 100,
    101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113.

    Role kernel: reads x = (t, q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments:
        t: time since touchdown t [s], >= 0
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
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0
            = report, 1 = constrained, 2 = energy
        gravity: option gravity: virtual gravity effect on p_th per half (report 4.4-4.5 on [t_td, t_b] and
            [t_b, t_lo]); each half runs with its mean momentum, the rates with the momentum at that instant:
            0 = none, 1 = type3, 2 = type4
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
    # Total ops: 349
    (t, q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k_c, k_d, g_s, q_r_lo, continuity, gravity, iterations, tol,) = (load(p, 0, 1, 2, 3, 4, 7, 8, 9,
        10, 11))
    # inputs: finite and inside their domains
    if not (all_finite((t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity,
            gravity, iterations, tol,)) & ((t >= 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((continuity == 0.0) or (continuity == 1.0) or (continuity
            == 2.0)) & ((gravity == 0.0) or (gravity == 1.0) or (gravity == 2.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0)
            and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = (0.5)*k_c
    p_td = _x1*q_thd_td
    E_td = (_x0*_x2 + (0.5)*_x1*q_thd_td**2 + _x2*l0**2 + g_s*m*q_r_td*math.cos(q_th_td) - k_c*l0*q_r_td
        + (0.5)*m*q_rd_td**2)
    # fixed point of the two halves' virtual gravity effects, from 0 (none: no pass)
    P_c_compression = 0.0
    P_c_decompression = 0.0
    passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(((0.0) if (gravity == 0.0) else (iterations))), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # the first half's mean momentum as a touchdown rate
        i_q_thd_eff = ((0.5)*P_c_compression + p_td)/(m*q_r_td**2)
        # eqs (78), (82)-(87): Geyer's radial solution with k_c from the touchdown state
        _c0 = geyer_solution(q_r_td, q_rd_td, i_q_thd_eff, m, l0, k_c, g_s)
        if _c0[6] != STATUS_OK:
            return fail(out, _c0[6])
        i_ab_omega = _c0[0]
        i_ab_omega0_hat = _c0[1]
        i_ab_a = _c0[2]
        i_ab_b = _c0[3]
        i_ab_phase_td = _c0[4]
        i_ab_s_td = _c0[5]
        # eqs (79)-(81): the bottom at phase 3 pi/2
        _x3 = (1.0/i_ab_omega0_hat)
        _x4 = i_ab_a - i_ab_b
        _x5 = _x4 + 1.0
        _x6 = _x3*i_ab_omega
        _x7 = _x3*i_ab_phase_td
        _x8 = P_c_compression + p_td
        i_t_bottom = _x3*(-i_ab_phase_td + (1.5)*math.pi)
        i_bottom_q_r = _x5*l0
        i_bottom_q_rd = 0.0
        i_bottom_q_th = (-3.0*math.pi*_x6*i_ab_a + (1.5)*math.pi*_x6 - _x7*i_ab_omega
            + 2.0*i_ab_omega*(_x3*i_ab_b*math.sqrt(1.0 - i_ab_s_td**2) + _x7*i_ab_a) + q_th_td)
        i_p_b = _x8
        i_bottom_q_thd = _x8/(_x5**2*l0**2*m)
        i_rho_b = _x4
        # eqs (100)-(103): omega_ba from the momentum, omega0_ba^2 = k_d/m
        _x13 = (1.0/l0)
        _x9 = (1.0/m)
        _x10 = (0.5)*P_c_decompression + i_p_b
        _x11 = _x10**2
        _x12 = 3.0*_x11*_x13**4*_x9 + k_d
        i_ba_omega = _x10*_x13**2*_x9
        i_ba_omega0_hat = math.sqrt(_x12)/math.sqrt(m)
        i_ba_a_free = _x13*m*(_x11*_x13**3*_x9**2 - g_s)/_x12
        # with k_d the bottom lies below the centre a_ba of (90): the leg extends
        if not ((i_rho_b < i_ba_a_free)):
            return fail(out, STATUS_RECOMPRESSION)
        # E_ab of (98)
        if continuity == 0.0:
            # eqs (97)-(99), E_ab the energy (27)
            i_eps_ba = (2.0*E_td - (-i_bottom_q_r + l0)**2*(k_c - k_d))/(l0**2*m)
        elif continuity == 1.0:
            # as report
            i_eps_ba = (2.0*E_td - (-i_bottom_q_r + l0)**2*(k_c - k_d))/(l0**2*m)
        elif continuity == 2.0:
            # eqs (97)-(99) with E_ab Geyer's energy (8) at the bottom
            _x17 = (1.0/l0)
            _x14 = i_ba_omega**2
            _x15 = 2.0*_x17*g_s
            _x16 = (1.0/m)
            i_eps_ba = (_x14 + _x15 - _x16*_x17**2*(-i_bottom_q_r + l0)**2*(k_c - k_d) + i_rho_b**2*(3.0*_x14
                + _x16*k_c) + i_rho_b*(-2.0*_x14 + _x15))
        else:
            return fail(out, STATUS_INVALID_INPUT)
        _x18 = i_ba_omega**2
        _x19 = 3.0*_x18*m + k_d
        i_ba_b2 = -m*(_x19*l0*(2.0*g_s - l0*(-_x18 + i_eps_ba)) - m*(-_x18*l0 + g_s)**2)/(_x19**2*l0**2)
        # eq (104): real amplitude b_ba
        if not ((i_ba_b2 > 0.0)):
            return fail(out, STATUS_NO_REAL_SOLUTION)
        # eq (104); eq (103), or (111) when constrained
        _x20 = math.sqrt(i_ba_b2)
        i_ba_b = _x20
        i_ba_a = ((_x20 + i_rho_b) if (continuity == 1.0) else (i_ba_a_free))
        # eq (94): the liftoff phase of the second half
        _c1 = geyer_liftoff_phase(i_ba_a, i_ba_b, l0, q_r_lo)
        if _c1[2] != STATUS_OK:
            return fail(out, _c1[2])
        i_ba_phase_lo = _c1[0]
        i_ba_s_lo = _c1[1]
        # eqs (90)-(94) at liftoff
        _x26 = (1.0/m)
        _x21 = (1.0/i_ba_omega0_hat)
        _x22 = (1.5)*math.pi
        _x23 = _x21*i_ba_phase_lo
        _x24 = _x21*i_ba_omega
        _x25 = (-_x22*_x24 + _x23*i_ba_omega + 3.0*math.pi*_x24*i_ba_a
            - 2.0*i_ba_omega*(-_x21*i_ba_b*math.sqrt(1.0 - i_ba_s_lo**2) + _x23*i_ba_a) + i_bottom_q_th)
        _x27 = q_r_lo**2
        _x28 = (1.0/_x27)
        _x29 = P_c_decompression + i_p_b
        _x30 = _x26*k_d
        i_t_stance = _x21*(-_x22 + i_ba_phase_lo) + i_t_bottom
        i_liftoff_q_r = q_r_lo
        i_liftoff_q_th = _x25
        i_liftoff_q_thd = _x26*_x28*_x29
        i_q_rd_lo_sq = (-_x26**2*_x28*_x29**2 + 2.0*_x26*k_d*l0*q_r_lo + 2.0*_x26*(E_td - 0.5*(-i_bottom_q_r
            + l0)**2*(k_c - k_d)) - _x27*_x30 - _x30*l0**2 - 2.0*g_s*q_r_lo*math.cos(_x25))
        # the leg stays above horizontal
        if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
            return fail(out, STATUS_FALL)
        # q_rd_lo^2 from the energy
        if not ((gravity == 0.0) or (i_q_rd_lo_sq >= 0.0)):
            return fail(out, STATUS_ENERGY_DEFICIT)
        # q_rd_lo: (11) without a gravity correction, the energy with one
        i_liftoff_q_rd = ((i_ba_b*i_ba_omega0_hat*l0*math.sqrt(1.0 - i_ba_s_lo**2)) if (gravity == 0.0)
            else (math.sqrt(i_q_rd_lo_sq)))
        if _conv0 or _it0 == _last0:
            break
        # the virtual gravity effect of each half
        if gravity == 0.0:
            i_P_new1 = 0.0
            i_P_new2 = 0.0
        elif gravity == 1.0:
            # eq (65) on each half
            _x31 = g_s*m
            _x32 = _x31*i_bottom_q_r*math.sin(i_bottom_q_th)
            i_P_new1 = (0.5)*i_t_bottom*(_x31*q_r_td*math.sin(q_th_td) + _x32)
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x31*q_r_lo*math.sin(i_liftoff_q_th) + _x32)
        elif gravity == 2.0:
            # eq (76) on each half, the average leg length of (11) on it
            _x33 = (1.0/i_ab_omega0_hat)
            _x34 = i_ab_a + 1.0
            _x35 = (1.5)*math.pi
            _x36 = (_x33*l0*(_x34*_x35 - _x34*i_ab_phase_td
                + i_ab_b*math.cos(i_ab_phase_td))/(-_x33*i_ab_phase_td + (1.5)*math.pi*_x33))
            _x37 = (1.0/i_ba_omega0_hat)
            _x38 = i_ba_a + 1.0
            _x39 = (_x37*l0*(-_x35*_x38 + _x38*i_ba_phase_lo - i_ba_b*math.cos(i_ba_phase_lo))/(-_x35*_x37
                + _x37*i_ba_phase_lo))
            _x40 = math.sin(i_bottom_q_th)
            _x41 = g_s*m
            _x42 = _x36*_x41
            _x43 = _x39*_x41
            _i_L1 = _x36
            _i_L2 = _x39
            i_P_new1 = (0.5)*i_t_bottom*(_x40*_x42 + _x42*math.sin(q_th_td))
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x40*_x43 + _x43*math.sin(i_liftoff_q_th))
        else:
            return fail(out, STATUS_INVALID_INPUT)
        _n0_0 = i_P_new1
        _n0_1 = i_P_new2
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(_n0_0 - P_c_compression) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + abs(p_td))) and (abs(_n0_1 - P_c_decompression) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m
            + abs(p_td))))
        P_c_compression = _n0_0
        P_c_decompression = _n0_1
        passes += 1.0
    # the stance outputs: the pass at the final iterate
    t_bottom = i_t_bottom
    t_stance = i_t_stance
    bottom_q_r = i_bottom_q_r
    bottom_q_rd = i_bottom_q_rd
    bottom_q_th = i_bottom_q_th
    bottom_q_thd = i_bottom_q_thd
    liftoff_q_r = i_liftoff_q_r
    liftoff_q_rd = i_liftoff_q_rd
    liftoff_q_th = i_liftoff_q_th
    liftoff_q_thd = i_liftoff_q_thd
    # eqs (78)-(79): the first half
    _c2 = (geyer_state(i_ab_omega0_hat*t + i_ab_phase_td, i_ab_phase_td, q_th_td, i_ab_omega, i_ab_omega0_hat,
        i_ab_a, i_ab_b, l0))
    c_q_r = _c2[0]
    c_q_rd = _c2[1]
    c_q_th = _c2[2]
    c_q_thd = _c2[3]
    # the piecewise stance map of section 5.1 ((112)-(113)): (78)-(79) up to t_b, (90)-(92) after; the rates
    # with the momentum at t
    _x44 = (i_t_bottom >= t)
    _x45 = -i_t_bottom + t
    _x46 = _x45*i_ba_omega0_hat
    _x47 = i_ba_a - i_ba_b*math.cos(_x46) + 1.0
    _x48 = i_ba_b*math.sin(_x46)
    _x49 = (1.5)*math.pi
    _x50 = (1.0/i_ba_omega0_hat)
    _x51 = _x50*i_ba_omega
    _x52 = _x50*(_x46 + _x49)
    _x53 = (1.0/m)
    q_r = ((c_q_r) if _x44 else (_x47*l0))
    q_rd = ((c_q_rd) if _x44 else (_x48*i_ba_omega0_hat*l0))
    q_th = ((c_q_th) if _x44 else (-_x49*_x51 + 3.0*math.pi*_x51*i_ba_a + _x52*i_ba_omega
        - 2.0*i_ba_omega*(-_x48*_x50 + _x52*i_ba_a) + i_bottom_q_th))
    q_thd = ((_x53*(P_c_compression*t/i_t_bottom + p_td)/c_q_r**2) if _x44
        else (_x53*(P_c_decompression*_x45/(-i_t_bottom + i_t_stance) + i_p_b)/(_x47**2*l0**2)))
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((q_r, q_rd, q_th, q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (q_r, q_rd, q_th, q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_vs_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_vs_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_vs_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def geyer_vs_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Simple variable-stiffness map (Geyer et al. per half).

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 96, 97, 98, 99, 100,
    101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol); writes the outputs
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
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0
            = report, 1 = constrained, 2 = energy
        gravity: option gravity: virtual gravity effect on p_th per half (report 4.4-4.5 on [t_td, t_b] and
            [t_b, t_lo]); each half runs with its mean momentum, the rates with the momentum at that instant:
            0 = none, 1 = type3, 2 = type4
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
        P_c_compression: virtual gravity effect of the first half (0 unless gravity) [N m s]
        P_c_decompression: virtual gravity effect of the second half [N m s]
        passes: fixed-point passes run (0 unless gravity)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 3
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol,) = (load(p, 0, 1, 2, 3,
        4, 5, 6, 7, 8, 9, 10, 11))
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k_c, k_d, g_s, g_f,
            q_r_td, q_r_lo, continuity, gravity, iterations, tol,)) & ((b_y_apex >= 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))
            & ((continuity == 0.0) or (continuity == 1.0) or (continuity == 2.0)) & ((gravity == 0.0)
            or (gravity == 1.0) or (gravity == 2.0)) & ((iterations == math.floor(iterations)) and (iterations
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
    # stance: Simple variable-stiffness map (Geyer et al. per half)
    _x1 = carray(stack(4), 4)
    store(_x1, (td_q_r, td_q_rd, td_q_th, td_q_thd,))
    _o1 = carray(stack(13), 13)
    _c1 = geyer_vs_stance(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _o1_10, _o1_11, _o1_12,) = (load(_o1, 1,
        6, 7, 8, 9, 10, 11, 12))
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
            liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th, _o1_10, _o1_11, _o1_12,
            ))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (apex_height, apex_speed, t_descent, _o1_1, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th, _o1_10, _o1_11, _o1_12,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_vs_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_vs_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_vs_apex_return(row(X, i), p, row(OUT, i))
