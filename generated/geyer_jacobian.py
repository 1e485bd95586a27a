# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/geyer.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:e58e885f76eb1aa8
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module geyer: JVP kernels, and for a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td, liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_REAL_SOLUTION, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION, STATUS_NO_LIFTOFF, STATUS_FALL, STATUS_NUMERICAL_RANGE

NAN = math.nan
_NAN4 = (NAN,) * 4
_NAN12 = (NAN,) * 12
_NAN18 = (NAN,) * 18
_NAN20 = (NAN,) * 20
_NAN45 = (NAN,) * 45
_NAN60 = (NAN,) * 60


@njit(cache=True, error_model="numpy")
def geyer_solution_jvp_q_r_td_q_rd_td_q_thd_td_k(q_r_td, q_rd_td, q_thd_td, m, l0, k, g_s, q_r_td__tan, q_rd_td__tan, q_thd_td__tan, k__tan):
    """Geyer et al.'s radial solution (11) from a touchdown state: omega, omega0_hat, a, b, phase, with the derivative of every output along the direction (q_r_td__tan, q_rd_td__tan, q_thd_td__tan, k__tan).

    Report equations: 7, 8, 9, 10, 11, 12.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_td__tan: direction: its component along q_r_td
        q_rd_td__tan: direction: its component along q_rd_td
        q_thd_td__tan: direction: its component along q_thd_td
        k__tan: direction: its component along k

    Returns a tuple:
        omega: omega = p_th / (m l0^2), eq (7) [rad/s]
        omega0_hat: frequency of (11) [rad/s]
        a: offset of rho(t) in (11)
        b: amplitude of rho(t) in (11)
        phase_td: touchdown phase omega0_hat t_td, eq (12) [rad]
        s_td: sin(phase_td) = (q_r_td / l0 - 1 - a) / b
        omega__tan: derivative of omega along the direction
        omega0_hat__tan: derivative of omega0_hat along the direction
        a__tan: derivative of a along the direction
        b__tan: derivative of b along the direction
        phase_td__tan: derivative of phase_td along the direction
        s_td__tan: derivative of s_td along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 130
    # eq (7) at touchdown: omega0^2 = k/m, omega = p_th/(m l0^2), rho and its rate
    _x3 = (1.0/l0)
    _x0 = (1.0/m)
    _x1 = _x3**2
    _x2 = _x1*q_r_td**2
    omega0_sq = _x0*k
    omega0_sq__tan = _x0*k__tan
    omega = _x2*q_thd_td
    omega__tan = 2.0*_x1*q_r_td*q_r_td__tan*q_thd_td + _x2*q_thd_td__tan
    rho_td = _x3*q_r_td - 1.0
    rho_td__tan = _x3*q_r_td__tan
    rho_d_td = _x3*q_rd_td
    rho_d_td__tan = _x3*q_rd_td__tan
    # stance starts compressing
    if not ((q_rd_td < 0.0)):
        return _NAN12 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # eq (8) at touchdown (Taylor polynomial of Assumption 2): epsilon = 2 E / (m l0^2)
    _x4 = omega**2
    _x5 = 2.0*g_s/l0
    _x6 = rho_td**2
    _x7 = 3.0*_x4 + omega0_sq
    _x8 = -2.0*_x4 + _x5
    epsilon = _x4 + _x5 + _x6*_x7 + _x8*rho_td + rho_d_td**2
    epsilon__tan = _x6*omega0_sq__tan + omega__tan*(6.0*_x6*omega - 4.0*omega*rho_td + 2.0*omega) + 2.0*rho_d_td*rho_d_td__tan + rho_td__tan*(2.0*_x7*rho_td + _x8)
    # eq (9): rho_d^2 = lambda rho^2 + mu rho + nu
    _x9 = omega**2
    _x10 = omega*omega__tan
    _x11 = 2.0*g_s/l0
    lam = -3.0*_x9 - omega0_sq
    lam__tan = -6.0*_x10 - omega0_sq__tan
    mu = -_x11 + 2.0*_x9
    mu__tan = 4.0*_x10
    nu = -_x11 - _x9 + epsilon
    nu__tan = -2.0*_x10 + epsilon__tan
    # eq (10)-(11): omega0_hat, a and b^2 of rho = a + b sin(omega0_hat t)
    _x13 = (1.0/lam)
    _x12 = math.sqrt(-lam)
    _x14 = (0.5)*_x13
    _x15 = _x13**2
    _x16 = -4.0*lam*nu + mu**2
    omega0_hat = _x12
    omega0_hat__tan = _x12*_x14*lam__tan
    a = -_x14*mu
    a__tan = -_x14*mu__tan + (0.5)*_x15*lam__tan*mu
    b2 = (0.25)*_x15*_x16
    b2__tan = -_x13*nu__tan + (0.5)*_x15*mu*mu__tan + lam__tan*(-0.5*_x13**3*_x16 - _x15*nu)
    # eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0
    if not ((b2 > 0.0)):
        return _NAN12 + (STATUS_NO_REAL_SOLUTION,)
    # eq (12): sin(phase) at touchdown
    _x17 = math.sqrt(b2)
    _x18 = (1.0/_x17)
    _x19 = (0.5)*b2__tan
    _x20 = (1.0/l0)
    _x21 = _x20*q_r_td - a - 1.0
    b = _x17
    b__tan = _x18*_x19
    s_td = _x18*_x21
    s_td__tan = _x18*_x20*q_r_td__tan - _x18*a__tan - _x19*_x21/b2**(1.5)
    # the leg collapses: l0 (1 + a - b) <= 0
    if not ((a - b + 1.0 > 0.0)):
        return _NAN12 + (STATUS_FALL,)
    # (12) needs |s_td| <= 1
    if not ((abs(s_td) <= 1.0)):
        return _NAN12 + (STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION,)
    # eq (12), n = 0: compressing root
    phase_td = math.pi - math.asin(s_td)
    phase_td__tan = -s_td__tan/math.sqrt(1.0 - s_td**2)
    # (internal helper: its callers check that their outputs are finite)
    return (omega, omega0_hat, a, b, phase_td, s_td, omega__tan, omega0_hat__tan, a__tan, b__tan, phase_td__tan, s_td__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_liftoff_phase_jvp_a_b(a, b, l0, q_r_lo, a__tan, b__tan):
    """Geyer et al.'s liftoff phase omega0_hat t_lo, eq (14) with n = 0, with the derivative of every output along the direction (a__tan, b__tan).

    Report equations: 14.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        a: offset a of (11)
        b: amplitude b of (11)
        l0: rest leg length l0 [m]
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        a__tan: direction: its component along a
        b__tan: direction: its component along b

    Returns a tuple:
        phase_lo: liftoff phase omega0_hat t_lo, eq (14) [rad]
        s_lo: sin(phase_lo) = (q_r_lo / l0 - 1 - a) / b
        phase_lo__tan: derivative of phase_lo along the direction
        s_lo__tan: derivative of s_lo along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 19
    # eq (14): sin(phase) at liftoff
    _x0 = (1.0/b)
    _x1 = -a - 1.0 + q_r_lo/l0
    s_lo = _x0*_x1
    s_lo__tan = -_x0**2*_x1*b__tan - _x0*a__tan
    # eq (14) needs |s_lo| <= 1
    if not ((abs(s_lo) <= 1.0)):
        return _NAN4 + (STATUS_NO_LIFTOFF,)
    # eq (14), n = 0: extending root
    phase_lo = math.asin(s_lo) + 2.0*math.pi
    phase_lo__tan = s_lo__tan/math.sqrt(1.0 - s_lo**2)
    # (internal helper: its callers check that their outputs are finite)
    return (phase_lo, s_lo, phase_lo__tan, s_lo__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k__tan):
    """Geyer et al.'s approximate stance map: touchdown state -> bottom and liftoff states, with the derivative of every output along the direction (q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k__tan).

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        q_r_td__tan: direction: its component along q_r_td
        q_rd_td__tan: direction: its component along q_rd_td
        q_th_td__tan: direction: its component along q_th_td
        q_thd_td__tan: direction: its component along q_thd_td
        k__tan: direction: its component along k

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
        t_bottom__tan: derivative of t_bottom along the direction
        t_stance__tan: derivative of t_stance along the direction
        bottom_q_r__tan: derivative of bottom_q_r along the direction
        bottom_q_rd__tan: derivative of bottom_q_rd along the direction
        bottom_q_th__tan: derivative of bottom_q_th along the direction
        bottom_q_thd__tan: derivative of bottom_q_thd along the direction
        liftoff_q_r__tan: derivative of liftoff_q_r along the direction
        liftoff_q_rd__tan: derivative of liftoff_q_rd along the direction
        liftoff_q_th__tan: derivative of liftoff_q_th along the direction
        liftoff_q_thd__tan: derivative of liftoff_q_thd along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 177
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(q_r_td__tan) and math.isfinite(q_rd_td__tan) and math.isfinite(q_th_td__tan) and math.isfinite(q_thd_td__tan) and math.isfinite(k__tan) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))):
        return _NAN20 + (STATUS_INVALID_INPUT,)
    # eqs (7)-(12): Geyer et al.'s radial solution from the touchdown state
    _c0 = geyer_solution_jvp_q_r_td_q_rd_td_q_thd_td_k(q_r_td, q_rd_td, q_thd_td, m, l0, k, g_s, q_r_td__tan, q_rd_td__tan, q_thd_td__tan, k__tan)
    if _c0[12] != STATUS_OK:
        return _NAN20 + (_c0[12],)
    (omega, omega0_hat, a, b, phase_td, s_td, omega__tan, omega0_hat__tan, a__tan, b__tan, phase_td__tan, s_td__tan, _) = _c0
    _c1 = geyer_liftoff_phase_jvp_a_b(a, b, l0, q_r_lo, a__tan, b__tan)
    if _c1[4] != STATUS_OK:
        return _NAN20 + (_c1[4],)
    phase_lo = _c1[0]
    s_lo = _c1[1]
    phase_lo__tan = _c1[2]
    s_lo__tan = _c1[3]
    # eqs (13)-(14) minus (12), (11), (19), (17) at the bottom and at liftoff
    _x0 = (1.0/omega0_hat)
    _x1 = -phase_td + (1.5)*math.pi
    _x2 = _x0*phase_td__tan
    _x3 = _x0**2
    _x4 = _x3*omega0_hat__tan
    _x5 = phase_lo - phase_td
    _x6 = a + 1.0
    _x7 = _x6 - b
    _x45 = (1.0/_x7)
    _x8 = b__tan*l0
    _x9 = (1.5)*math.pi
    _x10 = _x0*omega
    _x11 = 3.0*math.pi
    _x12 = _x10*_x11
    _x13 = _x0*phase_td
    _x14 = _x13*a
    _x15 = math.sqrt(1.0 - s_td**2)
    _x16 = _x15*b
    _x17 = _x0*_x16
    _x18 = 2.0*omega
    _x19 = -_x13*omega + _x18*(_x14 + _x17) + q_th_td
    _x20 = _x3*phase_td
    _x21 = _x3*omega
    _x22 = _x11*a
    _x23 = -_x16*_x3 - _x20*a
    _x24 = -_x13 + 2.0*_x14 + 2.0*_x17
    _x25 = 2.0*_x10
    _x26 = _x15*_x25
    _x27 = -_x10 + _x25*a
    _x28 = _x27*phase_td__tan + q_th_td__tan - _x25*b*s_td*s_td__tan/_x15
    _x29 = _x45**2
    _x30 = _x18*_x45**3
    _x31 = math.sqrt(1.0 - s_lo**2)
    _x32 = _x31*b
    _x33 = _x32*l0
    _x34 = b*s_lo
    _x35 = _x34*s_lo__tan/_x31
    _x36 = _x0*phase_lo
    _x37 = _x36*a
    _x38 = _x0*_x32
    _x39 = _x10*phase_lo
    _x40 = _x3*phase_lo
    _x41 = _x34 + _x6
    _x44 = (1.0/_x41)
    _x42 = _x44**2
    _x43 = _x18*_x44**3
    t_bottom = _x0*_x1
    t_bottom__tan = -_x1*_x4 - _x2
    t_stance = _x0*_x5
    t_stance__tan = _x0*phase_lo__tan - _x2 - _x4*_x5
    bottom_q_r = _x7*l0
    bottom_q_r__tan = -_x8 + a__tan*l0
    bottom_q_rd = 0.0
    bottom_q_th = _x10*_x9 - _x12*a + _x19
    bottom_q_th__tan = _x26*b__tan + _x28 + a__tan*(-_x12 + _x13*_x18) + omega0_hat__tan*(_x18*_x23 + _x20*omega + _x21*_x22 - _x21*_x9) + omega__tan*(-_x0*_x22 + _x0*_x9 + _x24)
    bottom_q_thd = _x29*omega
    bottom_q_thd__tan = _x29*omega__tan - _x30*a__tan + _x30*b__tan
    liftoff_q_r = q_r_lo
    liftoff_q_rd = _x33*omega0_hat
    liftoff_q_rd__tan = _x31*_x8*omega0_hat + _x33*omega0_hat__tan - _x35*l0*omega0_hat
    liftoff_q_th = -_x18*(_x37 - _x38) + _x19 + _x39
    liftoff_q_th__tan = -_x25*_x35 - _x27*phase_lo__tan + _x28 + a__tan*(2.0*_x0*omega*phase_td - 2.0*_x39) + b__tan*(_x25*_x31 + _x26) + omega0_hat__tan*(-_x18*(_x3*_x31*b - _x40*a) + 2.0*_x23*omega + _x3*omega*phase_td - _x40*omega) + omega__tan*(_x24 + _x36 - 2.0*_x37 + 2.0*_x38)
    liftoff_q_thd = _x42*omega
    liftoff_q_thd__tan = _x42*omega__tan - _x43*a__tan - _x43*b*s_lo__tan - _x43*b__tan*s_lo
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN20 + (STATUS_FALL,)
    # derivatives that are identically zero
    bottom_q_rd__tan = 0.0
    liftoff_q_r__tan = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo):
    """Geyer et al.'s approximate stance map: stance outputs and their derivatives with respect to the touchdown state and the stiffness.

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0

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
        d_t_bottom__q_r_td: d t_bottom / d q_r_td
        d_t_bottom__q_rd_td: d t_bottom / d q_rd_td
        d_t_bottom__q_th_td: d t_bottom / d q_th_td
        d_t_bottom__q_thd_td: d t_bottom / d q_thd_td
        d_t_bottom__k: d t_bottom / d k
        d_t_stance__q_r_td: d t_stance / d q_r_td
        d_t_stance__q_rd_td: d t_stance / d q_rd_td
        d_t_stance__q_th_td: d t_stance / d q_th_td
        d_t_stance__q_thd_td: d t_stance / d q_thd_td
        d_t_stance__k: d t_stance / d k
        d_bottom_q_r__q_r_td: d bottom_q_r / d q_r_td
        d_bottom_q_r__q_rd_td: d bottom_q_r / d q_rd_td
        d_bottom_q_r__q_th_td: d bottom_q_r / d q_th_td
        d_bottom_q_r__q_thd_td: d bottom_q_r / d q_thd_td
        d_bottom_q_r__k: d bottom_q_r / d k
        d_bottom_q_rd__q_r_td: d bottom_q_rd / d q_r_td
        d_bottom_q_rd__q_rd_td: d bottom_q_rd / d q_rd_td
        d_bottom_q_rd__q_th_td: d bottom_q_rd / d q_th_td
        d_bottom_q_rd__q_thd_td: d bottom_q_rd / d q_thd_td
        d_bottom_q_rd__k: d bottom_q_rd / d k
        d_bottom_q_th__q_r_td: d bottom_q_th / d q_r_td
        d_bottom_q_th__q_rd_td: d bottom_q_th / d q_rd_td
        d_bottom_q_th__q_th_td: d bottom_q_th / d q_th_td
        d_bottom_q_th__q_thd_td: d bottom_q_th / d q_thd_td
        d_bottom_q_th__k: d bottom_q_th / d k
        d_bottom_q_thd__q_r_td: d bottom_q_thd / d q_r_td
        d_bottom_q_thd__q_rd_td: d bottom_q_thd / d q_rd_td
        d_bottom_q_thd__q_th_td: d bottom_q_thd / d q_th_td
        d_bottom_q_thd__q_thd_td: d bottom_q_thd / d q_thd_td
        d_bottom_q_thd__k: d bottom_q_thd / d k
        d_liftoff_q_r__q_r_td: d liftoff_q_r / d q_r_td
        d_liftoff_q_r__q_rd_td: d liftoff_q_r / d q_rd_td
        d_liftoff_q_r__q_th_td: d liftoff_q_r / d q_th_td
        d_liftoff_q_r__q_thd_td: d liftoff_q_r / d q_thd_td
        d_liftoff_q_r__k: d liftoff_q_r / d k
        d_liftoff_q_rd__q_r_td: d liftoff_q_rd / d q_r_td
        d_liftoff_q_rd__q_rd_td: d liftoff_q_rd / d q_rd_td
        d_liftoff_q_rd__q_th_td: d liftoff_q_rd / d q_th_td
        d_liftoff_q_rd__q_thd_td: d liftoff_q_rd / d q_thd_td
        d_liftoff_q_rd__k: d liftoff_q_rd / d k
        d_liftoff_q_th__q_r_td: d liftoff_q_th / d q_r_td
        d_liftoff_q_th__q_rd_td: d liftoff_q_th / d q_rd_td
        d_liftoff_q_th__q_th_td: d liftoff_q_th / d q_th_td
        d_liftoff_q_th__q_thd_td: d liftoff_q_th / d q_thd_td
        d_liftoff_q_th__k: d liftoff_q_th / d k
        d_liftoff_q_thd__q_r_td: d liftoff_q_thd / d q_r_td
        d_liftoff_q_thd__q_rd_td: d liftoff_q_thd / d q_rd_td
        d_liftoff_q_thd__q_th_td: d liftoff_q_thd / d q_th_td
        d_liftoff_q_thd__q_thd_td: d liftoff_q_thd / d q_thd_td
        d_liftoff_q_thd__k: d liftoff_q_thd / d k
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(q_r_lo) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))):
        return _NAN60 + (STATUS_INVALID_INPUT,)
    # derivatives with respect to q_r_td
    _c0 = geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, 1.0, 0.0, 0.0, 0.0, 0.0)
    if _c0[20] != STATUS_OK:
        return _NAN60 + (_c0[20],)
    (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_t_bottom__q_r_td, d_t_stance__q_r_td, d_bottom_q_r__q_r_td, d_bottom_q_rd__q_r_td, d_bottom_q_th__q_r_td, d_bottom_q_thd__q_r_td, d_liftoff_q_r__q_r_td, d_liftoff_q_rd__q_r_td, d_liftoff_q_th__q_r_td, d_liftoff_q_thd__q_r_td, _) = _c0
    # derivatives with respect to q_rd_td
    _c1 = geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, 0.0, 1.0, 0.0, 0.0, 0.0)
    if _c1[20] != STATUS_OK:
        return _NAN60 + (_c1[20],)
    (_, _, _, _, _, _, _, _, _, _, d_t_bottom__q_rd_td, d_t_stance__q_rd_td, d_bottom_q_r__q_rd_td, d_bottom_q_rd__q_rd_td, d_bottom_q_th__q_rd_td, d_bottom_q_thd__q_rd_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_thd__q_rd_td, _) = _c1
    # derivatives with respect to q_th_td
    _c2 = geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, 0.0, 0.0, 1.0, 0.0, 0.0)
    if _c2[20] != STATUS_OK:
        return _NAN60 + (_c2[20],)
    (_, _, _, _, _, _, _, _, _, _, d_t_bottom__q_th_td, d_t_stance__q_th_td, d_bottom_q_r__q_th_td, d_bottom_q_rd__q_th_td, d_bottom_q_th__q_th_td, d_bottom_q_thd__q_th_td, d_liftoff_q_r__q_th_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_th__q_th_td, d_liftoff_q_thd__q_th_td, _) = _c2
    # derivatives with respect to q_thd_td
    _c3 = geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, 0.0, 0.0, 0.0, 1.0, 0.0)
    if _c3[20] != STATUS_OK:
        return _NAN60 + (_c3[20],)
    (_, _, _, _, _, _, _, _, _, _, d_t_bottom__q_thd_td, d_t_stance__q_thd_td, d_bottom_q_r__q_thd_td, d_bottom_q_rd__q_thd_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__q_thd_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_thd__q_thd_td, _) = _c3
    # derivatives with respect to k
    _c4 = geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, 0.0, 0.0, 0.0, 0.0, 1.0)
    if _c4[20] != STATUS_OK:
        return _NAN60 + (_c4[20],)
    (_, _, _, _, _, _, _, _, _, _, d_t_bottom__k, d_t_stance__k, d_bottom_q_r__k, d_bottom_q_rd__k, d_bottom_q_th__k, d_bottom_q_thd__k, d_liftoff_q_r__k, d_liftoff_q_rd__k, d_liftoff_q_th__k, d_liftoff_q_thd__k, _) = _c4
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r) and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(d_t_bottom__q_r_td) and math.isfinite(d_t_bottom__q_rd_td) and math.isfinite(d_t_bottom__q_th_td) and math.isfinite(d_t_bottom__q_thd_td) and math.isfinite(d_t_bottom__k) and math.isfinite(d_t_stance__q_r_td) and math.isfinite(d_t_stance__q_rd_td) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__q_thd_td) and math.isfinite(d_t_stance__k) and math.isfinite(d_bottom_q_r__q_r_td) and math.isfinite(d_bottom_q_r__q_rd_td) and math.isfinite(d_bottom_q_r__q_th_td) and math.isfinite(d_bottom_q_r__q_thd_td) and math.isfinite(d_bottom_q_r__k) and math.isfinite(d_bottom_q_rd__q_r_td) and math.isfinite(d_bottom_q_rd__q_rd_td) and math.isfinite(d_bottom_q_rd__q_th_td) and math.isfinite(d_bottom_q_rd__q_thd_td) and math.isfinite(d_bottom_q_rd__k) and math.isfinite(d_bottom_q_th__q_r_td) and math.isfinite(d_bottom_q_th__q_rd_td) and math.isfinite(d_bottom_q_th__q_th_td) and math.isfinite(d_bottom_q_th__q_thd_td) and math.isfinite(d_bottom_q_th__k) and math.isfinite(d_bottom_q_thd__q_r_td) and math.isfinite(d_bottom_q_thd__q_rd_td) and math.isfinite(d_bottom_q_thd__q_th_td) and math.isfinite(d_bottom_q_thd__q_thd_td) and math.isfinite(d_bottom_q_thd__k) and math.isfinite(d_liftoff_q_r__q_r_td) and math.isfinite(d_liftoff_q_r__q_rd_td) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__q_thd_td) and math.isfinite(d_liftoff_q_r__k) and math.isfinite(d_liftoff_q_rd__q_r_td) and math.isfinite(d_liftoff_q_rd__q_rd_td) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__q_thd_td) and math.isfinite(d_liftoff_q_rd__k) and math.isfinite(d_liftoff_q_th__q_r_td) and math.isfinite(d_liftoff_q_th__q_rd_td) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__q_thd_td) and math.isfinite(d_liftoff_q_th__k) and math.isfinite(d_liftoff_q_thd__q_r_td) and math.isfinite(d_liftoff_q_thd__q_rd_td) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__q_thd_td) and math.isfinite(d_liftoff_q_thd__k)):
        return _NAN60 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_stance_jacobian_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, out, status):
    """Parallel batch form of :func:`geyer_stance_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k, g_s, q_r_lo.
    Writes output j of row i to ``out[i, j]`` (shape (n, 60)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k.
    """
    for i in prange(out.shape[0]):
        res = geyer_stance_jacobian(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k, g_s, q_r_lo)
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
        out[i, 10] = res[10]
        out[i, 11] = res[11]
        out[i, 12] = res[12]
        out[i, 13] = res[13]
        out[i, 14] = res[14]
        out[i, 15] = res[15]
        out[i, 16] = res[16]
        out[i, 17] = res[17]
        out[i, 18] = res[18]
        out[i, 19] = res[19]
        out[i, 20] = res[20]
        out[i, 21] = res[21]
        out[i, 22] = res[22]
        out[i, 23] = res[23]
        out[i, 24] = res[24]
        out[i, 25] = res[25]
        out[i, 26] = res[26]
        out[i, 27] = res[27]
        out[i, 28] = res[28]
        out[i, 29] = res[29]
        out[i, 30] = res[30]
        out[i, 31] = res[31]
        out[i, 32] = res[32]
        out[i, 33] = res[33]
        out[i, 34] = res[34]
        out[i, 35] = res[35]
        out[i, 36] = res[36]
        out[i, 37] = res[37]
        out[i, 38] = res[38]
        out[i, 39] = res[39]
        out[i, 40] = res[40]
        out[i, 41] = res[41]
        out[i, 42] = res[42]
        out[i, 43] = res[43]
        out[i, 44] = res[44]
        out[i, 45] = res[45]
        out[i, 46] = res[46]
        out[i, 47] = res[47]
        out[i, 48] = res[48]
        out[i, 49] = res[49]
        out[i, 50] = res[50]
        out[i, 51] = res[51]
        out[i, 52] = res[52]
        out[i, 53] = res[53]
        out[i, 54] = res[54]
        out[i, 55] = res[55]
        out[i, 56] = res[56]
        out[i, 57] = res[57]
        out[i, 58] = res[58]
        out[i, 59] = res[59]
        status[i] = res[60]


@njit(cache=True, error_model="numpy")
def geyer_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, k__tan):
    """Apex-return map: exact flights, stance by Geyer et al.'s approximate stance map, with the derivative of every output along the direction (b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, k__tan).

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground [m], >= 0
        b_xd_apex: horizontal apex speed [m/s], >= 0 (the runner moves in +x)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        g_f: gravitational acceleration in flight g_f [m/s^2], positive
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        b_y_apex__tan: direction: its component along b_y_apex
        b_xd_apex__tan: direction: its component along b_xd_apex
        q_th_td__tan: direction: its component along q_th_td
        k__tan: direction: its component along k

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
        apex_height__tan: derivative of apex_height along the direction
        apex_speed__tan: derivative of apex_speed along the direction
        t_descent__tan: derivative of t_descent along the direction
        t_stance__tan: derivative of t_stance along the direction
        t_ascent__tan: derivative of t_ascent along the direction
        liftoff_q_r__tan: derivative of liftoff_q_r along the direction
        liftoff_q_rd__tan: derivative of liftoff_q_rd along the direction
        liftoff_q_th__tan: derivative of liftoff_q_th along the direction
        liftoff_q_thd__tan: derivative of liftoff_q_thd along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(b_y_apex__tan) and math.isfinite(b_xd_apex__tan) and math.isfinite(q_th_td__tan) and math.isfinite(k__tan) and ((b_y_apex >= 0.0)) and ((b_xd_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))):
        return _NAN18 + (STATUS_INVALID_INPUT,)
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan)
    if _c0[10] != STATUS_OK:
        return _NAN18 + (_c0[10],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, t_descent__tan, _) = _c0
    # stance: Geyer et al.'s approximate stance map
    _c1 = geyer_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k, g_s, q_r_lo, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, k__tan)
    if _c1[20] != STATUS_OK:
        return _NAN18 + (_c1[20],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _, t_stance__tan, _, _, _, _, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, _) = _c1
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan)
    if _c2[8] != STATUS_OK:
        return _NAN18 + (_c2[8],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    apex_height__tan = _c2[4]
    apex_speed__tan = _c2[5]
    t_ascent__tan = _c2[6]
    # (internal helper: its callers check that their outputs are finite)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, apex_height__tan, apex_speed__tan, t_descent__tan, t_stance__tan, t_ascent__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_apex_return_jacobian(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo):
    """Apex-return map by Geyer et al.'s approximate stance map, and its derivatives with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground [m], >= 0
        b_xd_apex: horizontal apex speed [m/s], >= 0 (the runner moves in +x)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        g_s: gravitational acceleration in stance g_s [m/s^2], positive
        g_f: gravitational acceleration in flight g_f [m/s^2], positive
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0

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
        d_apex_height__b_y_apex: d apex_height / d b_y_apex
        d_apex_height__b_xd_apex: d apex_height / d b_xd_apex
        d_apex_height__q_th_td: d apex_height / d q_th_td
        d_apex_height__k: d apex_height / d k
        d_apex_speed__b_y_apex: d apex_speed / d b_y_apex
        d_apex_speed__b_xd_apex: d apex_speed / d b_xd_apex
        d_apex_speed__q_th_td: d apex_speed / d q_th_td
        d_apex_speed__k: d apex_speed / d k
        d_t_descent__b_y_apex: d t_descent / d b_y_apex
        d_t_descent__b_xd_apex: d t_descent / d b_xd_apex
        d_t_descent__q_th_td: d t_descent / d q_th_td
        d_t_descent__k: d t_descent / d k
        d_t_stance__b_y_apex: d t_stance / d b_y_apex
        d_t_stance__b_xd_apex: d t_stance / d b_xd_apex
        d_t_stance__q_th_td: d t_stance / d q_th_td
        d_t_stance__k: d t_stance / d k
        d_t_ascent__b_y_apex: d t_ascent / d b_y_apex
        d_t_ascent__b_xd_apex: d t_ascent / d b_xd_apex
        d_t_ascent__q_th_td: d t_ascent / d q_th_td
        d_t_ascent__k: d t_ascent / d k
        d_liftoff_q_r__b_y_apex: d liftoff_q_r / d b_y_apex
        d_liftoff_q_r__b_xd_apex: d liftoff_q_r / d b_xd_apex
        d_liftoff_q_r__q_th_td: d liftoff_q_r / d q_th_td
        d_liftoff_q_r__k: d liftoff_q_r / d k
        d_liftoff_q_rd__b_y_apex: d liftoff_q_rd / d b_y_apex
        d_liftoff_q_rd__b_xd_apex: d liftoff_q_rd / d b_xd_apex
        d_liftoff_q_rd__q_th_td: d liftoff_q_rd / d q_th_td
        d_liftoff_q_rd__k: d liftoff_q_rd / d k
        d_liftoff_q_th__b_y_apex: d liftoff_q_th / d b_y_apex
        d_liftoff_q_th__b_xd_apex: d liftoff_q_th / d b_xd_apex
        d_liftoff_q_th__q_th_td: d liftoff_q_th / d q_th_td
        d_liftoff_q_th__k: d liftoff_q_th / d k
        d_liftoff_q_thd__b_y_apex: d liftoff_q_thd / d b_y_apex
        d_liftoff_q_thd__b_xd_apex: d liftoff_q_thd / d b_xd_apex
        d_liftoff_q_thd__q_th_td: d liftoff_q_thd / d q_th_td
        d_liftoff_q_thd__k: d liftoff_q_thd / d k
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and ((b_y_apex >= 0.0)) and ((b_xd_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))):
        return _NAN45 + (STATUS_INVALID_INPUT,)
    # derivatives with respect to b_y_apex
    _c0 = geyer_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, 1.0, 0.0, 0.0, 0.0)
    if _c0[18] != STATUS_OK:
        return _NAN45 + (_c0[18],)
    (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_apex_height__b_y_apex, d_apex_speed__b_y_apex, d_t_descent__b_y_apex, d_t_stance__b_y_apex, d_t_ascent__b_y_apex, d_liftoff_q_r__b_y_apex, d_liftoff_q_rd__b_y_apex, d_liftoff_q_th__b_y_apex, d_liftoff_q_thd__b_y_apex, _) = _c0
    # derivatives with respect to b_xd_apex
    _c1 = geyer_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, 0.0, 1.0, 0.0, 0.0)
    if _c1[18] != STATUS_OK:
        return _NAN45 + (_c1[18],)
    (_, _, _, _, _, _, _, _, _, d_apex_height__b_xd_apex, d_apex_speed__b_xd_apex, d_t_descent__b_xd_apex, d_t_stance__b_xd_apex, d_t_ascent__b_xd_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_thd__b_xd_apex, _) = _c1
    # derivatives with respect to q_th_td
    _c2 = geyer_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, 0.0, 0.0, 1.0, 0.0)
    if _c2[18] != STATUS_OK:
        return _NAN45 + (_c2[18],)
    (_, _, _, _, _, _, _, _, _, d_apex_height__q_th_td, d_apex_speed__q_th_td, d_t_descent__q_th_td, d_t_stance__q_th_td, d_t_ascent__q_th_td, d_liftoff_q_r__q_th_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_th__q_th_td, d_liftoff_q_thd__q_th_td, _) = _c2
    # derivatives with respect to k
    _c3 = geyer_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, 0.0, 0.0, 0.0, 1.0)
    if _c3[18] != STATUS_OK:
        return _NAN45 + (_c3[18],)
    (_, _, _, _, _, _, _, _, _, d_apex_height__k, d_apex_speed__k, d_t_descent__k, d_t_stance__k, d_t_ascent__k, d_liftoff_q_r__k, d_liftoff_q_rd__k, d_liftoff_q_th__k, d_liftoff_q_thd__k, _) = _c3
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent) and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(d_apex_height__b_y_apex) and math.isfinite(d_apex_height__b_xd_apex) and math.isfinite(d_apex_height__q_th_td) and math.isfinite(d_apex_height__k) and math.isfinite(d_apex_speed__b_y_apex) and math.isfinite(d_apex_speed__b_xd_apex) and math.isfinite(d_apex_speed__q_th_td) and math.isfinite(d_apex_speed__k) and math.isfinite(d_t_descent__b_y_apex) and math.isfinite(d_t_descent__b_xd_apex) and math.isfinite(d_t_descent__q_th_td) and math.isfinite(d_t_descent__k) and math.isfinite(d_t_stance__b_y_apex) and math.isfinite(d_t_stance__b_xd_apex) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__k) and math.isfinite(d_t_ascent__b_y_apex) and math.isfinite(d_t_ascent__b_xd_apex) and math.isfinite(d_t_ascent__q_th_td) and math.isfinite(d_t_ascent__k) and math.isfinite(d_liftoff_q_r__b_y_apex) and math.isfinite(d_liftoff_q_r__b_xd_apex) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__k) and math.isfinite(d_liftoff_q_rd__b_y_apex) and math.isfinite(d_liftoff_q_rd__b_xd_apex) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__k) and math.isfinite(d_liftoff_q_th__b_y_apex) and math.isfinite(d_liftoff_q_th__b_xd_apex) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__k) and math.isfinite(d_liftoff_q_thd__b_y_apex) and math.isfinite(d_liftoff_q_thd__b_xd_apex) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__k)):
        return _NAN45 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__k, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__k, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__k, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__k, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__k, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__k, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__k, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__k, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__k, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def geyer_apex_return_jacobian_batch(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, out, status):
    """Parallel batch form of :func:`geyer_apex_return_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td.
    Scalar arguments shared by every row: m, l0, k, g_s, g_f, q_r_td, q_r_lo.
    Writes output j of row i to ``out[i, j]`` (shape (n, 45)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__k, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__k, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__k, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__k, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__k, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__k, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__k, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__k, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__k.
    """
    for i in prange(out.shape[0]):
        res = geyer_apex_return_jacobian(b_y_apex[i], b_xd_apex[i], q_th_td[i], m, l0, k, g_s, g_f, q_r_td, q_r_lo)
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
        out[i, 10] = res[10]
        out[i, 11] = res[11]
        out[i, 12] = res[12]
        out[i, 13] = res[13]
        out[i, 14] = res[14]
        out[i, 15] = res[15]
        out[i, 16] = res[16]
        out[i, 17] = res[17]
        out[i, 18] = res[18]
        out[i, 19] = res[19]
        out[i, 20] = res[20]
        out[i, 21] = res[21]
        out[i, 22] = res[22]
        out[i, 23] = res[23]
        out[i, 24] = res[24]
        out[i, 25] = res[25]
        out[i, 26] = res[26]
        out[i, 27] = res[27]
        out[i, 28] = res[28]
        out[i, 29] = res[29]
        out[i, 30] = res[30]
        out[i, 31] = res[31]
        out[i, 32] = res[32]
        out[i, 33] = res[33]
        out[i, 34] = res[34]
        out[i, 35] = res[35]
        out[i, 36] = res[36]
        out[i, 37] = res[37]
        out[i, 38] = res[38]
        out[i, 39] = res[39]
        out[i, 40] = res[40]
        out[i, 41] = res[41]
        out[i, 42] = res[42]
        out[i, 43] = res[43]
        out[i, 44] = res[44]
        status[i] = res[45]
