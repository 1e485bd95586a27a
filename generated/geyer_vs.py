# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/variable.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight.py sha256:c042f0c9cf6a9745
#   geyer.py sha256:b93d5e8ad96a402f
# ----------------------------------------------------------------------------------------------
"""Simple variable-stiffness map (Geyer et al. per half) (report section 5.1): stance, state-at-time and apex-return kernels."""

import math

import numpy as np
from numba import njit, prange
from .flight import apex_to_touchdown, liftoff_to_apex
from .geyer import geyer_liftoff_phase, geyer_solution, geyer_state

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
STATUS_NOT_CONVERGED = 13
STATUS_ENERGY_DEFICIT = 14
STATUS_IMAGINARY_MOMENTUM = 15


@njit(cache=True, error_model="numpy")
def bottom_quartic(p, E_ab, m, l0, k_c, g_s):
    """Bottom leg length of (153): the compressing root of the quartic in (0, l0] (Newton).

    Report equations: 153.

    Arguments:
        p: angular momentum p_th [kg m^2/s]
        E_ab: total energy E_ab [J]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k_c: leg stiffness while compressing k_c [N/m]
        g_s: gravitational acceleration in stance g_s [m/s^2], positive

    Returns a tuple:
        q_r_b: bottom leg length of (153) [m]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 57
    # inputs: finite and inside their domains
    if not (math.isfinite(p) and math.isfinite(E_ab) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(g_s) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))):
        return (NAN, STATUS_INVALID_INPUT)
    # a start left of the root: V >= E there
    _x0 = (1.0/k_c)
    _x1 = g_s*m
    _x2 = _x0*_x1
    _x3 = _x0*g_s**2*m**2
    _x4 = _x2 - l0
    _x5 = -_x1*_x4
    _x6 = math.sqrt(2.0*E_ab - _x3 - 2.0*_x5)/math.sqrt(k_c)
    _x7 = math.sqrt(2.0)*abs(p)/(math.sqrt(m)*math.sqrt(E_ab - 0.5*_x3 - _x5))
    q_start = -0.5*_x2 - 0.5*_x6 + (0.25)*_x7 + (0.5)*l0 + (0.5)*abs(_x4 + _x6 + (0.5)*_x7)
    # E_ab above the minimum of the potential
    if not ((E_ab > (0.5)*g_s**2*m**2/k_c + g_s*m*(-g_s*m/k_c + l0))):
        return (NAN, STATUS_NO_REAL_SOLUTION)
    # Newton's method on V - E: monotone from the left
    qb = q_start
    passes = 0.0
    _conv0 = False
    for _it0 in range(int(60.0)):
        slope = g_s*m + (0.5)*k_c*(-2.0*l0 + 2.0*qb) - p**2/(m*qb**3)
        # V decreasing left of the root
        if not ((slope < 0.0)):
            return (NAN, STATUS_NO_REAL_SOLUTION)
        _n0_0 = qb - (-E_ab + g_s*m*qb + (0.5)*k_c*(l0 - qb)**2 + (0.5)*p**2/(m*qb**2))/slope
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = 1e-15 > 0.0 and (abs(_n0_0 - qb) <= 1e-15*(l0))
        qb = _n0_0
        passes += 1.0
        if _conv0:
            break
    if not _conv0 and 1e-15 > 0.0 and passes > 0.0:
        return (NAN, STATUS_NOT_CONVERGED)
    q_r_b = qb
    # the bottom root is at most l0
    if not ((qb <= l0)):
        return (NAN, STATUS_NO_REAL_SOLUTION)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(q_r_b)):
        return (NAN, STATUS_NUMERICAL_RANGE)
    return (q_r_b, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity):
    """Simple variable-stiffness map (Geyer et al. per half): touchdown state -> bottom and liftoff states.

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 90, 91, 92, 93, 94, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111.

    Section 5.1: apex to bottom (78)-(89) with k_c, bottom to apex (90)-(105) with k_d and E_ba
    = E_ab + (k_d - k_c)(l0 - q_r_b)^2/2; option continuity chooses (103)-(104) with the
    touchdown energy (27), the constraint (111), or (103)-(104) with the energy of the first
    half.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k_c: leg stiffness while compressing k_c [N/m]
        k_d: leg stiffness after the bottom k_d [N/m]
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0 = report, 1 = constrained, 2 = energy

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
    # Total ops: 175
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(continuity) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((continuity == 0.0) or (continuity == 1.0) or (continuity == 2.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = (0.5)*k_c
    p_td = _x1*q_thd_td
    E_td = _x0*_x2 + (0.5)*_x1*q_thd_td**2 + _x2*l0**2 + g_s*m*q_r_td*math.cos(q_th_td) - k_c*l0*q_r_td + (0.5)*m*q_rd_td**2
    # eqs (78), (82)-(87): Geyer's radial solution with k_c from the touchdown state
    _c0 = geyer_solution(q_r_td, q_rd_td, q_thd_td, m, l0, k_c, g_s)
    if _c0[6] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[6])
    ab_omega = _c0[0]
    ab_omega0_hat = _c0[1]
    ab_a = _c0[2]
    ab_b = _c0[3]
    ab_phase_td = _c0[4]
    ab_s_td = _c0[5]
    # eqs (79)-(81): the bottom at phase 3 pi/2; p_th conserved (Remark 2)
    _x3 = (1.0/ab_omega0_hat)
    _x4 = ab_a - ab_b
    _x5 = _x4 + 1.0
    _x6 = _x3*ab_omega
    _x7 = _x3*ab_phase_td
    t_bottom = _x3*(-ab_phase_td + (1.5)*math.pi)
    bottom_q_r = _x5*l0
    bottom_q_rd = 0.0
    bottom_q_th = -3.0*math.pi*_x6*ab_a + (1.5)*math.pi*_x6 - _x7*ab_omega + 2.0*ab_omega*(_x3*ab_b*math.sqrt(1.0 - ab_s_td**2) + _x7*ab_a) + q_th_td
    bottom_q_thd = p_td/(_x5**2*l0**2*m)
    rho_b = _x4
    # eqs (100)-(103): omega_ba = omega_ab, omega0_ba^2 = k_d/m
    _x8 = ab_omega**2
    _x9 = 3.0*_x8*m + k_d
    ba_omega0_hat = math.sqrt(_x9)/math.sqrt(m)
    ba_a_free = m*(_x8*l0 - g_s)/(_x9*l0)
    # with k_d the bottom lies below the centre of (90): the leg extends
    if not ((rho_b < ba_a_free)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_RECOMPRESSION)
    # E_ab of (98)
    if continuity == 0.0:
        # eqs (97)-(99): E_ba = E_ab + E_additional, E_ab the energy (27)
        eps_ba = (2.0*E_td - (-bottom_q_r + l0)**2*(k_c - k_d))/(l0**2*m)
    elif continuity == 1.0:
        # as report
        eps_ba = (2.0*E_td - (-bottom_q_r + l0)**2*(k_c - k_d))/(l0**2*m)
    elif continuity == 2.0:
        # eqs (97)-(99) with E_ab Geyer's energy (8) of the first half
        _x11 = (1.0/l0)
        _x10 = ab_omega**2
        _x12 = (1.0/m)
        eps_ba = _x10 - _x11**2*_x12*(-bottom_q_r + l0)**2*(k_c - k_d) + 2.0*_x11*g_s + rho_b**2*(3.0*_x10 + _x12*k_c) + rho_b*(-2.0*_x10 + 2.0*_x11*g_s)
    else:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    _x13 = ab_omega**2
    _x14 = 3.0*_x13*m + k_d
    ba_b2 = -m*(_x14*l0*(2.0*g_s - l0*(-_x13 + eps_ba)) - m*(-_x13*l0 + g_s)**2)/(_x14**2*l0**2)
    # eq (104): real amplitude b_ba
    if not ((ba_b2 > 0.0)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NO_REAL_SOLUTION)
    # eq (104); eq (103), or (111) when constrained
    _x15 = math.sqrt(ba_b2)
    ba_b = _x15
    ba_a = ((_x15 + rho_b) if (continuity == 1.0) else (ba_a_free))
    # eq (94): the liftoff phase of the second half
    _c1 = geyer_liftoff_phase(ba_a, ba_b, l0, q_r_lo)
    if _c1[2] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[2])
    ba_phase_lo = _c1[0]
    ba_s_lo = _c1[1]
    # eqs (90)-(94) at liftoff; p_th conserved (Remark 2)
    _x16 = (1.0/ba_omega0_hat)
    _x17 = (1.5)*math.pi
    _x18 = ba_b*math.sqrt(1.0 - ba_s_lo**2)
    _x19 = _x16*ba_phase_lo
    _x20 = _x16*ab_omega
    t_stance = _x16*(-_x17 + ba_phase_lo) + t_bottom
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x18*ba_omega0_hat*l0
    liftoff_q_th = -_x17*_x20 + _x19*ab_omega + 3.0*math.pi*_x20*ba_a - 2.0*ab_omega*(-_x16*_x18 + _x19*ba_a) + bottom_q_th
    liftoff_q_thd = p_td/(m*q_r_lo**2)
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_FALL)
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r) and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_vs_stance_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, out, status):
    """Parallel batch form of :func:`geyer_vs_stance`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, q_r_lo, continuity.
    Writes output j of row i to ``out[i, j]`` (shape (n, 10)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd.
    """
    for i in prange(out.shape[0]):
        res = geyer_vs_stance(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k_c, k_d, g_s, q_r_lo, continuity)
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
def geyer_vs_state_at(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity):
    """Simple variable-stiffness map (Geyer et al. per half): the polar state a time t after touchdown.

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 90, 91, 92, 93, 94, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111.

    Arguments:
        t: time since touchdown t [s], >= 0
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k_c: leg stiffness while compressing k_c [N/m]
        k_d: leg stiffness after the bottom k_d [N/m]
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0 = report, 1 = constrained, 2 = energy

    Returns a tuple:
        q_r: leg length [m]
        q_rd: leg length rate [m/s]
        q_th: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 184
    # inputs: finite and inside their domains
    if not (math.isfinite(t) and math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(continuity) and ((t >= 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((continuity == 0.0) or (continuity == 1.0) or (continuity == 2.0))):
        return (NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = (0.5)*k_c
    p_td = _x1*q_thd_td
    E_td = _x0*_x2 + (0.5)*_x1*q_thd_td**2 + _x2*l0**2 + g_s*m*q_r_td*math.cos(q_th_td) - k_c*l0*q_r_td + (0.5)*m*q_rd_td**2
    # eqs (78), (82)-(87): Geyer's radial solution with k_c from the touchdown state
    _c0 = geyer_solution(q_r_td, q_rd_td, q_thd_td, m, l0, k_c, g_s)
    if _c0[6] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, _c0[6])
    ab_omega = _c0[0]
    ab_omega0_hat = _c0[1]
    ab_a = _c0[2]
    ab_b = _c0[3]
    ab_phase_td = _c0[4]
    ab_s_td = _c0[5]
    # eqs (79)-(81): the bottom at phase 3 pi/2; p_th conserved (Remark 2)
    _x3 = (1.0/ab_omega0_hat)
    _x4 = ab_a - ab_b
    _x5 = _x4 + 1.0
    _x6 = _x3*ab_omega
    _x7 = _x3*ab_phase_td
    t_bottom = _x3*(-ab_phase_td + (1.5)*math.pi)
    bottom_q_r = _x5*l0
    bottom_q_rd = 0.0
    bottom_q_th = -3.0*math.pi*_x6*ab_a + (1.5)*math.pi*_x6 - _x7*ab_omega + 2.0*ab_omega*(_x3*ab_b*math.sqrt(1.0 - ab_s_td**2) + _x7*ab_a) + q_th_td
    bottom_q_thd = p_td/(_x5**2*l0**2*m)
    rho_b = _x4
    # eqs (100)-(103): omega_ba = omega_ab, omega0_ba^2 = k_d/m
    _x8 = ab_omega**2
    _x9 = 3.0*_x8*m + k_d
    ba_omega0_hat = math.sqrt(_x9)/math.sqrt(m)
    ba_a_free = m*(_x8*l0 - g_s)/(_x9*l0)
    # with k_d the bottom lies below the centre of (90): the leg extends
    if not ((rho_b < ba_a_free)):
        return (NAN, NAN, NAN, NAN, STATUS_RECOMPRESSION)
    # E_ab of (98)
    if continuity == 0.0:
        # eqs (97)-(99): E_ba = E_ab + E_additional, E_ab the energy (27)
        eps_ba = (2.0*E_td - (-bottom_q_r + l0)**2*(k_c - k_d))/(l0**2*m)
    elif continuity == 1.0:
        # as report
        eps_ba = (2.0*E_td - (-bottom_q_r + l0)**2*(k_c - k_d))/(l0**2*m)
    elif continuity == 2.0:
        # eqs (97)-(99) with E_ab Geyer's energy (8) of the first half
        _x11 = (1.0/l0)
        _x10 = ab_omega**2
        _x12 = (1.0/m)
        eps_ba = _x10 - _x11**2*_x12*(-bottom_q_r + l0)**2*(k_c - k_d) + 2.0*_x11*g_s + rho_b**2*(3.0*_x10 + _x12*k_c) + rho_b*(-2.0*_x10 + 2.0*_x11*g_s)
    else:
        return (NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    _x13 = ab_omega**2
    _x14 = 3.0*_x13*m + k_d
    ba_b2 = -m*(_x14*l0*(2.0*g_s - l0*(-_x13 + eps_ba)) - m*(-_x13*l0 + g_s)**2)/(_x14**2*l0**2)
    # eq (104): real amplitude b_ba
    if not ((ba_b2 > 0.0)):
        return (NAN, NAN, NAN, NAN, STATUS_NO_REAL_SOLUTION)
    # eq (104); eq (103), or (111) when constrained
    _x15 = math.sqrt(ba_b2)
    ba_b = _x15
    ba_a = ((_x15 + rho_b) if (continuity == 1.0) else (ba_a_free))
    # eq (94): the liftoff phase of the second half
    _c1 = geyer_liftoff_phase(ba_a, ba_b, l0, q_r_lo)
    if _c1[2] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, _c1[2])
    ba_phase_lo = _c1[0]
    ba_s_lo = _c1[1]
    # eqs (78)-(79): the first half
    _c2 = geyer_state(ab_omega0_hat*t + ab_phase_td, ab_phase_td, q_th_td, ab_omega, ab_omega0_hat, ab_a, ab_b, l0)
    c_q_r = _c2[0]
    c_q_rd = _c2[1]
    c_q_th = _c2[2]
    c_q_thd = _c2[3]
    # the piecewise stance map of section 5.1: (78)-(79) up to t_b, (90)-(92) after
    _x16 = (t <= t_bottom)
    _x17 = ba_omega0_hat*(t - t_bottom)
    _x18 = ba_a - ba_b*math.cos(_x17) + 1.0
    _x19 = ba_b*math.sin(_x17)
    _x20 = (1.5)*math.pi
    _x21 = (1.0/ba_omega0_hat)
    _x22 = _x21*ab_omega
    _x23 = _x21*(_x17 + _x20)
    q_r = ((c_q_r) if _x16 else (_x18*l0))
    q_rd = ((c_q_rd) if _x16 else (_x19*ba_omega0_hat*l0))
    q_th = ((c_q_th) if _x16 else (-_x20*_x22 + 3.0*math.pi*_x22*ba_a + _x23*ab_omega - 2.0*ab_omega*(-_x19*_x21 + _x23*ba_a) + bottom_q_th))
    q_thd = ((c_q_thd) if _x16 else (p_td/(_x18**2*l0**2*m)))
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)):
        return (NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (q_r, q_rd, q_th, q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_vs_state_at_batch(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity, out, status):
    """Parallel batch form of :func:`geyer_vs_state_at`.

    Row arguments (1-D float64 arrays of equal length n, any stride): t.
    Scalar arguments shared by every row: q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity.
    Writes output j of row i to ``out[i, j]`` (shape (n, 4)) and its status code to
    ``status[i]`` (int64). Columns: q_r, q_rd, q_th, q_thd.
    """
    for i in prange(out.shape[0]):
        res = geyer_vs_state_at(t[i], q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, continuity)
        out[i, 0] = res[0]
        out[i, 1] = res[1]
        out[i, 2] = res[2]
        out[i, 3] = res[3]
        status[i] = res[4]


@njit(cache=True, error_model="numpy")
def geyer_vs_apex_return(b_y_apex, b_xd_apex, q_th_td, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity):
    """Apex-return map: exact flights, stance by Simple variable-stiffness map (Geyer et al. per half).

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 90, 91, 92, 93, 94, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111.

    Arguments:
        b_y_apex: apex height of the body above the ground [m], >= 0
        b_xd_apex: horizontal apex speed [m/s], >= 0 (the runner moves in +x)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k_c: leg stiffness while compressing k_c [N/m]
        k_d: leg stiffness after the bottom k_d [N/m]
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        g_f: gravitational acceleration in flight g_f [m/s^2], positive
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        continuity: option continuity: the second half's a_ba, b_ba: how the leg length joins at the bottom: 0 = report, 1 = constrained, 2 = energy

    Returns a tuple:
        apex_height: next apex height above the ground [m]
        apex_speed: next apex horizontal speed [m/s]
        t_descent: flight time from the apex to touchdown [s]
        t_stance: stance time, touchdown to liftoff [s]
        t_ascent: flight time from liftoff to the next apex [s]
        liftoff_q_r: leg length [m]
        liftoff_q_rd: leg length rate [m/s]
        liftoff_q_th: leg angle from the vertical, counterclockwise positive [rad]
        liftoff_q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c) and math.isfinite(k_d) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(continuity) and ((b_y_apex >= 0.0)) and ((b_xd_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((continuity == 0.0) or (continuity == 1.0) or (continuity == 2.0))):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_INVALID_INPUT)
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f)
    if _c0[5] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c0[5])
    td_q_r = _c0[0]
    td_q_rd = _c0[1]
    td_q_th = _c0[2]
    td_q_thd = _c0[3]
    t_descent = _c0[4]
    # stance: Simple variable-stiffness map (Geyer et al. per half)
    _c1 = geyer_vs_stance(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k_c, k_d, g_s, q_r_lo, continuity)
    if _c1[10] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c1[10])
    t_stance = _c1[1]
    liftoff_q_r = _c1[6]
    liftoff_q_rd = _c1[7]
    liftoff_q_th = _c1[8]
    liftoff_q_thd = _c1[9]
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f)
    if _c2[4] != STATUS_OK:
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, _c2[4])
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent) and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd)):
        return (NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, STATUS_NUMERICAL_RANGE)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_vs_apex_return_batch(b_y_apex, b_xd_apex, q_th_td, m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, out, status):
    """Parallel batch form of :func:`geyer_vs_apex_return`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td.
    Scalar arguments shared by every row: m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity.
    Writes output j of row i to ``out[i, j]`` (shape (n, 9)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd.
    """
    for i in prange(out.shape[0]):
        res = geyer_vs_apex_return(b_y_apex[i], b_xd_apex[i], q_th_td[i], m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity)
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
