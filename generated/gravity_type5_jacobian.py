# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/gravity_type5.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   flight_jacobian.py sha256:e58e885f76eb1aa8
#   geyer_jacobian.py sha256:849e7410cc446e23
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module gravity_type5: JVP kernels, and for a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange
from .flight_jacobian import apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td, liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd
from .geyer_jacobian import geyer_liftoff_phase_jvp_a_b

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_REAL_SOLUTION, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION, STATUS_FALL, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED, STATUS_ENERGY_DEFICIT

NAN = math.nan
_NAN10 = (NAN,) * 10
_NAN22 = (NAN,) * 22
_NAN23 = (NAN,) * 23
_NAN24 = (NAN,) * 24
_NAN36 = (NAN,) * 36
_NAN55 = (NAN,) * 55
_NAN72 = (NAN,) * 72


@njit(cache=True, error_model="numpy")
def type5_solution_jvp_q_r_td_q_rd_td_omega_g_eff_r_c_k(q_r_td, q_rd_td, omega, g_eff, r_c, m, l0, k, q_r_td__tan, q_rd_td__tan, omega__tan, g_eff__tan, r_c__tan, k__tan):
    """Type 5 radial solution: (10)-(11) for the quadratic T5.4 about r_c with g_eff, with the derivative of every output along the direction (q_r_td__tan, q_rd_td__tan, omega__tan, g_eff__tan, r_c__tan, k__tan).

    Report equations: 9, 10, 11, 12.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        omega: omega = p_mean / (m l0^2) [rad/s]
        g_eff: radial gravity g_s <cos q_th> [m/s^2]
        r_c: expansion point of 1/(1+rho)^2 (stance-mean compression)
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        k: leg stiffness k [N/m] (constant: k_c = k_d)
        q_r_td__tan: direction: its component along q_r_td
        q_rd_td__tan: direction: its component along q_rd_td
        omega__tan: direction: its component along omega
        g_eff__tan: direction: its component along g_eff
        r_c__tan: direction: its component along r_c
        k__tan: direction: its component along k

    Returns a tuple:
        omega0_hat: frequency [rad/s]
        a: offset of rho(t)
        b: amplitude of rho(t)
        phase_td: touchdown phase [rad]
        s_td: sin(phase_td)
        omega0_hat__tan: derivative of omega0_hat along the direction
        a__tan: derivative of a along the direction
        b__tan: derivative of b along the direction
        phase_td__tan: derivative of phase_td along the direction
        s_td__tan: derivative of s_td along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 183
    _x0 = (1.0/m)
    omega0_sq = _x0*k
    omega0_sq__tan = _x0*k__tan
    if not ((q_rd_td < 0.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_NOT_COMPRESSING,)
    # T5.4: the quadratic about r_c with g_eff
    _x1 = r_c + 1.0
    _x24 = (1.0/_x1)
    _x2 = _x24**4
    _x3 = 4.0*omega0_sq
    _x4 = omega**2
    _x5 = r_c**4
    _x6 = r_c**2
    _x7 = 6.0*_x6
    _x8 = r_c**3
    _x9 = _x3*_x8
    _x10 = _x3*r_c + 3.0*_x4 + _x5*omega0_sq + _x7*omega0_sq + _x9 + omega0_sq
    _x11 = _x2*omega__tan
    _x12 = 4.0*r_c
    _x13 = 4.0*_x8
    _x14 = _x12 + _x13 + _x5 + _x7 + 1.0
    _x15 = 12.0*omega0_sq
    _x16 = _x24**5
    _x17 = (1.0/l0)
    _x18 = _x13*g_eff
    _x19 = _x17*(-_x12*g_eff - _x18 + 4.0*_x4*l0*r_c + _x4*l0 - _x5*g_eff - _x7*g_eff - g_eff)
    _x20 = 2.0*_x2
    _x21 = l0*omega
    _x22 = _x17*_x20
    _x23 = 12.0*g_eff
    lam = -_x10*_x2
    lam__tan = -6.0*_x11*omega - _x14*_x2*omega0_sq__tan + r_c__tan*(4.0*_x10*_x16 - _x2*(_x15*_x6 + _x15*r_c + _x3 + _x9))
    mu = _x19*_x20
    mu__tan = 2.0*_x11*_x17*(8.0*_x21*r_c + 2.0*_x21) - _x14*_x22*g_eff__tan + r_c__tan*(-8.0*_x16*_x19 + _x22*(-_x18 - _x23*_x6 - _x23*r_c + 4.0*_x4*l0 - 4.0*g_eff))
    # T5.5: through the touchdown point
    _x26 = (1.0/l0)
    _x25 = _x26**2
    _x27 = -_x26*q_r_td + 1.0
    _x28 = -_x27
    _x29 = _x28**2
    nu = _x25*q_rd_td**2 - _x28*mu - _x29*lam
    nu__tan = 2.0*_x25*q_rd_td*q_rd_td__tan + _x27*mu__tan - _x29*lam__tan + q_r_td__tan*(-2.0*_x26*_x28*lam - _x26*mu)
    # eq (10)-(11): omega0_hat, a and b^2 of rho = a + b sin(omega0_hat t)
    _x31 = (1.0/lam)
    _x30 = math.sqrt(-lam)
    _x32 = (0.5)*_x31
    _x33 = _x31**2
    _x34 = -4.0*lam*nu + mu**2
    omega0_hat = _x30
    omega0_hat__tan = _x30*_x32*lam__tan
    a = -_x32*mu
    a__tan = -_x32*mu__tan + (0.5)*_x33*lam__tan*mu
    b2 = (0.25)*_x33*_x34
    b2__tan = -_x31*nu__tan + (0.5)*_x33*mu*mu__tan + lam__tan*(-0.5*_x31**3*_x34 - _x33*nu)
    # eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0
    if not ((b2 > 0.0)):
        return _NAN10 + (STATUS_NO_REAL_SOLUTION,)
    # eq (12): sin(phase) at touchdown
    _x35 = math.sqrt(b2)
    _x36 = (1.0/_x35)
    _x37 = (0.5)*b2__tan
    _x38 = (1.0/l0)
    _x39 = _x38*q_r_td - a - 1.0
    b = _x35
    b__tan = _x36*_x37
    s_td = _x36*_x39
    s_td__tan = _x36*_x38*q_r_td__tan - _x36*a__tan - _x37*_x39/b2**(1.5)
    # the leg collapses: l0 (1 + a - b) <= 0
    if not ((a - b + 1.0 > 0.0)):
        return _NAN10 + (STATUS_FALL,)
    # (12) needs |s_td| <= 1
    if not ((abs(s_td) <= 1.0)):
        return _NAN10 + (STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION,)
    # eq (12), n = 0: compressing root
    phase_td = math.pi - math.asin(s_td)
    phase_td__tan = -s_td__tan/math.sqrt(1.0 - s_td**2)
    # (internal helper: its callers check that their outputs are finite)
    return (omega0_hat, a, b, phase_td, s_td, omega0_hat__tan, a__tan, b__tan, phase_td__tan, s_td__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def type5_leg_angle_jvp_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td(t, q_th_td, p_td, c0, c1, c2, k0, k1, k2, omega0_hat, phase_td, m, l0, t__tan, q_th_td__tan, p_td__tan, c0__tan, c1__tan, c2__tan, k0__tan, k1__tan, k2__tan, omega0_hat__tan, phase_td__tan):
    """Type 5 leg angle T5.6: q_th_td + int_0^t P(u) (k0 + k1 sin + k2 cos 2(.)) du / (m l0^2), with the derivative of every output along the direction (t__tan, q_th_td__tan, p_td__tan, c0__tan, c1__tan, c2__tan, k0__tan, k1__tan, k2__tan, omega0_hat__tan, phase_td__tan).

    Report equations: 17, 18, 19.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py); through
    an iteration, of the iterate it stops at.

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
        m: body mass m [kg]
        l0: rest leg length l0 [m]
        t__tan: direction: its component along t
        q_th_td__tan: direction: its component along q_th_td
        p_td__tan: direction: its component along p_td
        c0__tan: direction: its component along c0
        c1__tan: direction: its component along c1
        c2__tan: direction: its component along c2
        k0__tan: direction: its component along k0
        k1__tan: direction: its component along k1
        k2__tan: direction: its component along k2
        omega0_hat__tan: direction: its component along omega0_hat
        phase_td__tan: direction: its component along phase_td

    Returns a tuple:
        q_th: leg angle [rad]
        q_th__tan: derivative of q_th along the direction
    """
    # Total ops: 444
    _x10 = (1.0/omega0_hat)
    _x0 = p_td*t
    _x1 = t**2
    _x2 = (0.5)*_x1
    _x3 = _x2*k0
    _x4 = t**3
    _x5 = (0.16666666666666666)*_x4
    _x6 = _x5*k0
    _x7 = t**4
    _x8 = (0.08333333333333333)*_x7
    _x9 = _x8*k0
    _x11 = math.cos(phase_td)
    _x12 = _x10*_x11
    _x13 = _x12*p_td
    _x14 = _x10**2
    _x15 = math.sin(phase_td)
    _x16 = _x14*_x15
    _x17 = _x16*k1
    _x18 = _x10**3
    _x19 = _x11*_x18
    _x20 = _x19*k1
    _x21 = _x15*k1
    _x22 = _x10**4
    _x23 = 2.0*_x22
    _x24 = _x21*_x23
    _x25 = c0*k2
    _x26 = 2.0*phase_td
    _x27 = math.cos(_x26)
    _x28 = (0.25)*_x14
    _x29 = _x27*_x28
    _x30 = math.sin(_x26)
    _x31 = _x30*k2
    _x32 = (0.125)*_x18
    _x33 = _x31*_x32
    _x34 = _x27*k2
    _x35 = (0.125)*_x22
    _x36 = _x34*_x35
    _x37 = (0.5)*_x30
    _x38 = k2*p_td
    _x39 = _x10*_x38
    _x40 = omega0_hat*t
    _x41 = _x40 + phase_td
    _x42 = math.cos(_x41)
    _x43 = _x10*_x42
    _x44 = _x43*p_td
    _x45 = _x26 + 2.0*_x40
    _x46 = math.sin(_x45)
    _x47 = (0.5)*_x46
    _x48 = _x10*_x47
    _x49 = math.sin(_x41)
    _x50 = _x14*_x49 - _x43*t
    _x51 = _x50*k1
    _x52 = math.cos(_x45)
    _x53 = _x14*_x52
    _x54 = _x10*t
    _x55 = _x47*_x54 + (0.25)*_x53
    _x56 = _x55*k2
    _x57 = 2.0*_x18
    _x58 = 2.0*t
    _x59 = -0.5*_x1*_x43 + (0.5)*_x14*_x49*_x58 + (0.5)*_x42*_x57
    _x60 = _x59*k1
    _x61 = _x18*_x46
    _x62 = (0.5)*_x10*_x2*_x46 + (0.25)*_x53*t - 0.125*_x61
    _x63 = _x62*k2
    _x64 = 6.0*_x22
    _x65 = _x1*_x14*_x49 + 2.0*_x18*_x42*t - 0.3333333333333333*_x4*_x43 - 0.3333333333333333*_x49*_x64
    _x66 = _x65*k1
    _x67 = (0.375)*_x22
    _x68 = _x10*_x4
    _x69 = (0.25)*_x1*_x53 + (0.3333333333333333)*_x47*_x68 - 0.3333333333333333*_x52*_x67 - 0.25*_x61*t
    _x70 = _x69*k2
    _x71 = 1.0/(l0**2*m)
    _x72 = k0*t
    _x73 = (0.3333333333333333)*c2
    _x74 = k1*p_td
    _x75 = _x49*_x74
    _x76 = c0*k1
    _x77 = _x49*t
    _x78 = _x38*_x52
    _x79 = _x49*k1
    _x80 = _x2*c1
    _x81 = _x73*k1
    _x82 = _x52*k2
    _x83 = _x73*k2
    _x84 = _x23*c2
    _x85 = _x10*p_td
    _x86 = _x18*c1
    _x87 = _x11*_x14
    _x88 = _x11*k1
    _x89 = _x14*_x37
    _x90 = _x14*_x42
    _x91 = _x14*_x46
    _x92 = (0.5)*_x91
    _x93 = _x1*_x10*_x49 - _x49*_x57 + _x58*_x90
    _x94 = (0.5)*c1
    _x95 = _x18*_x52
    _x96 = _x1*_x10*_x52 - _x91*t - 0.5*_x95
    _x97 = _x94*k2
    _x98 = 3.0*_x1
    _x99 = k1*(-6.0*_x18*_x77 - _x42*_x64 + _x49*_x68 + _x90*_x98)
    _x100 = _x22*_x46
    _x101 = -1.5*_x1*_x91 + (0.75)*_x100 + _x52*_x68 - 1.5*_x95*t
    _x102 = _x10**5
    _x103 = _x102*c2
    _x104 = _x0*_x10
    _x105 = _x10*_x7
    q_th = _x71*(_x0*k0 + _x13*k1 - _x17*c0 - _x20*c1 + _x24*c2 - _x25*_x29 + _x3*c0 + _x33*c1 + _x36*c2 - _x37*_x39 + _x38*_x48 - _x44*k1 + _x51*c0 + _x56*c0 + _x6*c1 + _x60*c1 + _x63*c1 + _x66*c2 + _x70*c2 + _x9*c2) + q_th_td
    q_th__tan = _x71*c0__tan*(-_x17 - _x28*_x34 + _x3 + _x51 + _x56) + _x71*c1__tan*(-_x20 + _x33 + _x6 + _x60 + _x63) + _x71*c2__tan*(_x24 + _x36 + _x66 + _x70 + _x9) + _x71*k0__tan*(_x0 + _x2*c0 + _x5*c1 + _x8*c2) + _x71*k1__tan*(_x13 + _x15*_x84 - _x16*c0 - _x19*c1 - _x44 + _x50*c0 + _x59*c1 + _x65*c2) + _x71*k2__tan*(_x27*_x35*c2 - _x29*c0 + _x30*_x32*c1 - _x37*_x85 + _x47*_x85 + _x55*c0 + _x62*c1 + _x69*c2) + _x71*omega0_hat__tan*(_x101*_x97 - 8.0*_x103*_x21 - 0.5*_x103*_x34 + _x104*_x79 + _x104*_x82 + _x15*_x57*_x76 + (0.5)*_x18*_x25*_x27 + 3.0*_x22*_x88*c1 + _x25*_x96 - _x31*_x67*c1 + _x38*_x89 - _x38*_x92 - _x74*_x87 + _x74*_x90 + _x76*_x93 + _x81*(-12.0*_x1*_x18*_x49 + 24.0*_x102*_x49 + _x105*_x49 - 24.0*_x22*_x42*t + 4.0*_x4*_x90) + _x83*(3.0*_x100*t + (1.5)*_x102*_x52 + _x105*_x52 - 2.0*_x4*_x91 - _x95*_x98) + _x94*_x99) + _x71*p_td__tan*(-0.5*_x10*_x31 + _x12*k1 - _x43*k1 + _x48*k2 + _x72) + _x71*phase_td__tan*(-_x10*_x15*_x74 + _x10*_x75 + _x10*_x78 + _x101*_x83 + _x21*_x86 - 0.25*_x22*_x31*c2 + _x25*_x89 + _x25*(_x52*_x54 - _x92) - _x27*_x39 + (0.25)*_x34*_x86 + _x73*_x99 - _x76*_x87 + _x76*(_x49*_x54 + _x90) + _x84*_x88 + _x93*_x94*k1 + _x96*_x97) + _x71*t__tan*(_x25*_x52*t + _x3*c1 + _x4*_x49*_x81 + _x4*_x52*_x83 + _x4*_x73*k0 + _x72*c0 + _x75 + _x76*_x77 + _x78 + _x79*_x80 + _x80*_x82 + k0*p_td) + q_th_td__tan
    return (q_th, q_th__tan)


@njit(cache=True, error_model="numpy")
def gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_0(T, T__tan, g_eff, g_eff__tan, g_s, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, r_c, r_c__tan, tau1, tau1__tan, tau2, tau2__tan, tau3, tau3__tan):
    """evaluation and update of gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        T: value of the caller's variable
        T__tan: value of the caller's variable
        g_eff: value of the caller's variable
        g_eff__tan: value of the caller's variable
        g_s: value of the caller's variable
        k: value of the caller's variable
        k__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        p_td: value of the caller's variable
        p_td__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_r_td: value of the caller's variable
        q_r_td__tan: value of the caller's variable
        q_rd_td: value of the caller's variable
        q_rd_td__tan: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable
        r_c: value of the caller's variable
        r_c__tan: value of the caller's variable
        tau1: value of the caller's variable
        tau1__tan: value of the caller's variable
        tau2: value of the caller's variable
        tau2__tan: value of the caller's variable
        tau3: value of the caller's variable
        tau3__tan: value of the caller's variable

    Returns a tuple:
        i_c0: result for the caller
        i_c0__tan: result for the caller
        i_c1: result for the caller
        i_c1__tan: result for the caller
        i_c2: result for the caller
        i_c2__tan: result for the caller
        i_omega0_hat: result for the caller
        i_a: result for the caller
        i_b: result for the caller
        i_phase_td: result for the caller
        i_omega0_hat__tan: result for the caller
        i_a__tan: result for the caller
        i_b__tan: result for the caller
        i_phase_td__tan: result for the caller
        i_t_bottom: result for the caller
        i_t_bottom__tan: result for the caller
        i_t_stance: result for the caller
        i_t_stance__tan: result for the caller
        i_k0: result for the caller
        i_k0__tan: result for the caller
        i_k1: result for the caller
        i_k1__tan: result for the caller
        i_k2: result for the caller
        i_k2__tan: result for the caller
        _next_tau1: result for the caller
        _next_tau2: result for the caller
        _next_tau3: result for the caller
        _next_T: result for the caller
        _next_g_eff: result for the caller
        _next_r_c: result for the caller
        _next_tau1__tan: result for the caller
        _next_tau2__tan: result for the caller
        _next_tau3__tan: result for the caller
        _next_T__tan: result for the caller
        _next_g_eff__tan: result for the caller
        _next_r_c__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 362
    # T5.1: the torque quadratic through the nodal torques of the previous pass
    _x2 = (1.0/T)
    _x0 = math.sqrt(15.0)
    _x1 = (0.16666666666666666)*_x0
    _x3 = -0.3333333333333333*_x0*tau1 + (0.3333333333333333)*_x0*tau3 - 3.3333333333333335*tau1 + (6.666666666666667)*tau2 - 3.3333333333333335*tau3
    _x4 = (6.666666666666667)*tau2__tan
    _x5 = (0.3333333333333333)*_x2
    _x6 = _x2**2
    _x7 = tau1 - 2.0*tau2 + tau3
    _x8 = (3.3333333333333335)*_x6
    i_c0 = _x1*tau1 - _x1*tau3 + (0.8333333333333334)*tau1 - 0.6666666666666666*tau2 + (0.8333333333333334)*tau3
    i_c0__tan = tau1__tan*(_x1 + 0.8333333333333334) - 0.6666666666666666*tau2__tan + tau3__tan*(0.8333333333333334 - _x1)
    i_c1 = _x2*_x3
    i_c1__tan = -T__tan*_x3*_x6 + _x2*_x4 + _x5*tau1__tan*(-_x0 - 10.0) + _x5*tau3__tan*(_x0 - 10.0)
    i_c2 = _x7*_x8
    i_c2__tan = -6.666666666666667*T__tan*_x2**3*_x7 - _x4*_x6 + _x8*tau1__tan + _x8*tau3__tan
    # T5.3: omega of the stance-mean momentum
    _x9 = (0.5)*i_c0
    _x10 = T**2
    _x11 = (0.16666666666666666)*_x10
    _x12 = (0.08333333333333333)*T**3
    _x13 = 1.0/(l0**2*m)
    i_omega = _x13*(T*_x9 + _x11*i_c1 + _x12*i_c2 + p_td)
    i_omega__tan = (0.5)*T*_x13*i_c0__tan + T__tan*_x13*((0.3333333333333333)*T*i_c1 + (0.25)*_x10*i_c2 + _x9) + _x11*_x13*i_c1__tan + _x12*_x13*i_c2__tan + _x13*p_td__tan
    # T5.4-T5.5: radial solution
    _c0 = type5_solution_jvp_q_r_td_q_rd_td_omega_g_eff_r_c_k(q_r_td, q_rd_td, i_omega, g_eff, r_c, m, l0, k, q_r_td__tan, q_rd_td__tan, i_omega__tan, g_eff__tan, r_c__tan, k__tan)
    if _c0[10] != STATUS_OK:
        return _NAN36 + (_c0[10],)
    (i_omega0_hat, i_a, i_b, i_phase_td, i_s_td, i_omega0_hat__tan, i_a__tan, i_b__tan, i_phase_td__tan, i_s_td__tan, _) = _c0
    _c1 = geyer_liftoff_phase_jvp_a_b(i_a, i_b, l0, q_r_lo, i_a__tan, i_b__tan)
    if _c1[4] != STATUS_OK:
        return _NAN36 + (_c1[4],)
    i_phase_lo = _c1[0]
    i_phase_lo__tan = _c1[2]
    # eqs (13)-(14) minus (12); T5.6: the rate factor
    _x14 = (1.0/i_omega0_hat)
    _x15 = -i_phase_td + (1.5)*math.pi
    _x16 = _x14*i_phase_td__tan
    _x17 = _x14**2*i_omega0_hat__tan
    _x18 = i_phase_lo - i_phase_td
    _x19 = 3.0*i_b**2
    _x20 = 16.0*i_a
    _x21 = r_c**2
    _x22 = 12.0*_x21
    _x23 = _x22 + 8.0*r_c + 2.0
    _x24 = _x19 - _x20*r_c + _x23 + 6.0*i_a**2 - 4.0*i_a
    _x25 = r_c**3
    _x26 = 4.0*_x25
    _x27 = r_c**4
    _x28 = 4.0*r_c + 1.0
    _x29 = 6.0*_x21 + _x26 + _x27 + _x28
    _x30 = (1.0/_x29)
    _x31 = (0.5)*_x30
    _x32 = _x30*i_b
    _x33 = 24.0*r_c + 8.0
    _x34 = _x30**2*(-_x22 - _x26 - 12.0*r_c - 4.0)
    _x35 = -2.0*_x28 + 6.0*i_a
    _x36 = 8.0*_x25
    _x37 = _x23 + 2.0*_x27 + _x36
    _x38 = (1.0/_x37)
    i_t_bottom = _x14*_x15
    i_t_bottom__tan = -_x15*_x17 - _x16
    i_t_stance = _x14*_x18
    i_t_stance__tan = _x14*i_phase_lo__tan - _x16 - _x17*_x18
    i_k0 = _x24*_x31
    i_k0__tan = _x31*i_a__tan*(12.0*i_a - 16.0*r_c - 4.0) + 3.0*_x32*i_b__tan + r_c__tan*((0.5)*_x24*_x34 + _x31*(-_x20 + _x33))
    i_k1 = _x32*_x35
    i_k1__tan = _x30*_x35*i_b__tan + 6.0*_x32*i_a__tan + r_c__tan*(-8.0*_x32 + _x34*_x35*i_b)
    i_k2 = -_x19*_x38
    i_k2__tan = -_x19*_x38**2*r_c__tan*(-24.0*_x21 - _x33 - _x36) - 6.0*_x38*i_b*i_b__tan
    _c2 = type5_leg_angle_jvp_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td((0.5)*i_t_stance*(1.0 - 0.2*math.sqrt(15.0)), q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0, i_t_stance__tan*(0.5 - 0.1*math.sqrt(15.0)), q_th_td__tan, p_td__tan, i_c0__tan, i_c1__tan, i_c2__tan, i_k0__tan, i_k1__tan, i_k2__tan, i_omega0_hat__tan, i_phase_td__tan)
    i_th1 = _c2[0]
    i_th1__tan = _c2[1]
    _c3 = type5_leg_angle_jvp_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td((0.5)*i_t_stance, q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0, (0.5)*i_t_stance__tan, q_th_td__tan, p_td__tan, i_c0__tan, i_c1__tan, i_c2__tan, i_k0__tan, i_k1__tan, i_k2__tan, i_omega0_hat__tan, i_phase_td__tan)
    i_th2 = _c3[0]
    i_th2__tan = _c3[1]
    _c4 = type5_leg_angle_jvp_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td((0.5)*i_t_stance*((0.2)*math.sqrt(15.0) + 1.0), q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0, i_t_stance__tan*((0.1)*math.sqrt(15.0) + 0.5), q_th_td__tan, p_td__tan, i_c0__tan, i_c1__tan, i_c2__tan, i_k0__tan, i_k1__tan, i_k2__tan, i_omega0_hat__tan, i_phase_td__tan)
    i_th3 = _c4[0]
    i_th3__tan = _c4[1]
    # T5.1, T5.4: the torques at the new nodes, g_s <cos q_th>, the mean compression
    _x39 = (0.2)*math.sqrt(15.0)
    _x40 = 1.0 - _x39
    _x41 = (0.5)*i_omega0_hat
    _x42 = _x41*i_t_stance
    _x43 = _x40*_x42 + i_phase_td
    _x44 = math.sin(_x43)
    _x45 = i_a + 1.0
    _x46 = _x44*i_b + _x45
    _x47 = math.sin(i_th1)
    _x48 = l0*m
    _x49 = _x48*g_s
    _x50 = _x47*_x49
    _x51 = i_b*i_phase_td__tan
    _x52 = math.cos(_x43)
    _x53 = _x50*_x52
    _x54 = math.cos(i_th1)
    _x55 = _x41*i_b*i_t_stance__tan
    _x56 = (0.5)*g_s
    _x57 = _x48*_x56*i_b*i_omega0_hat__tan*i_t_stance
    _x58 = _x42 + i_phase_td
    _x59 = math.sin(_x58)
    _x60 = _x45 + _x59*i_b
    _x61 = math.sin(i_th2)
    _x62 = _x61*g_s
    _x63 = _x48*_x62
    _x64 = math.cos(_x58)
    _x65 = _x63*_x64
    _x66 = math.cos(i_th2)
    _x67 = _x39 + 1.0
    _x68 = _x42*_x67 + i_phase_td
    _x69 = math.sin(_x68)
    _x70 = _x45 + _x69*i_b
    _x71 = math.sin(i_th3)
    _x72 = _x49*_x71
    _x73 = math.cos(_x68)
    _x74 = _x72*_x73
    _x75 = math.cos(i_th3)
    _x76 = (0.2777777777777778)*g_s
    _x77 = math.cos(i_phase_lo) - math.cos(i_phase_td)
    _x78 = i_phase_lo - i_phase_td
    _x79 = (1.0/_x78)
    _x80 = _x79*i_b
    _x81 = _x77*_x79**2*i_b
    i_tau1 = _x46*_x50
    i_tau1__tan = _x40*_x47*_x52*_x57 + _x40*_x53*_x55 + _x44*_x50*i_b__tan + _x46*_x49*_x54*i_th1__tan + _x50*i_a__tan + _x51*_x53
    i_tau2 = _x60*_x63
    i_tau2__tan = _x49*_x60*_x66*i_th2__tan + _x51*_x65 + _x55*_x65 + _x57*_x61*_x64 + _x59*_x63*i_b__tan + _x63*i_a__tan
    i_tau3 = _x70*_x72
    i_tau3__tan = _x49*_x70*_x75*i_th3__tan + _x51*_x74 + _x55*_x67*_x74 + _x57*_x67*_x71*_x73 + _x69*_x72*i_b__tan + _x72*i_a__tan
    i_g_eff = _x56*((0.5555555555555556)*_x54 + (0.8888888888888888)*_x66 + (0.5555555555555556)*_x75)
    i_g_eff__tan = -_x47*_x76*i_th1__tan - 0.4444444444444444*_x62*i_th2__tan - _x71*_x76*i_th3__tan
    i_r_c = -_x77*_x80 + i_a
    i_r_c__tan = -_x77*_x79*i_b__tan + i_a__tan + i_phase_lo__tan*(_x80*math.sin(i_phase_lo) + _x81) + i_phase_td__tan*(-_x80*math.sin(i_phase_td) - _x81)
    # next values
    _next_tau1 = i_tau1
    _next_tau2 = i_tau2
    _next_tau3 = i_tau3
    _next_T = i_t_stance
    _next_g_eff = i_g_eff
    _next_r_c = i_r_c
    _next_tau1__tan = i_tau1__tan
    _next_tau2__tan = i_tau2__tan
    _next_tau3__tan = i_tau3__tan
    _next_T__tan = i_t_stance__tan
    _next_g_eff__tan = i_g_eff__tan
    _next_r_c__tan = i_r_c__tan
    # (internal helper: its callers check that their outputs are finite)
    return (i_c0, i_c0__tan, i_c1, i_c1__tan, i_c2, i_c2__tan, i_omega0_hat, i_a, i_b, i_phase_td, i_omega0_hat__tan, i_a__tan, i_b__tan, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, i_k0, i_k0__tan, i_k1, i_k1__tan, i_k2, i_k2__tan, _next_tau1, _next_tau2, _next_tau3, _next_T, _next_g_eff, _next_r_c, _next_tau1__tan, _next_tau2__tan, _next_tau3__tan, _next_T__tan, _next_g_eff__tan, _next_r_c__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_1(E_td, E_td__tan, g_s, i_a, i_a__tan, i_b, i_b__tan, i_c0, i_c0__tan, i_c1, i_c1__tan, i_c2, i_c2__tan, i_k0, i_k0__tan, i_k1, i_k1__tan, i_k2, i_k2__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo, q_th_td, q_th_td__tan):
    """continuation of gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k (outlined: derive/outline.py).

    Report equations: .

    Arguments:
        E_td: value of the caller's variable
        E_td__tan: value of the caller's variable
        g_s: value of the caller's variable
        i_a: value of the caller's variable
        i_a__tan: value of the caller's variable
        i_b: value of the caller's variable
        i_b__tan: value of the caller's variable
        i_c0: value of the caller's variable
        i_c0__tan: value of the caller's variable
        i_c1: value of the caller's variable
        i_c1__tan: value of the caller's variable
        i_c2: value of the caller's variable
        i_c2__tan: value of the caller's variable
        i_k0: value of the caller's variable
        i_k0__tan: value of the caller's variable
        i_k1: value of the caller's variable
        i_k1__tan: value of the caller's variable
        i_k2: value of the caller's variable
        i_k2__tan: value of the caller's variable
        i_omega0_hat: value of the caller's variable
        i_omega0_hat__tan: value of the caller's variable
        i_phase_td: value of the caller's variable
        i_phase_td__tan: value of the caller's variable
        i_t_bottom: value of the caller's variable
        i_t_bottom__tan: value of the caller's variable
        i_t_stance: value of the caller's variable
        i_t_stance__tan: value of the caller's variable
        k: value of the caller's variable
        k__tan: value of the caller's variable
        l0: value of the caller's variable
        m: value of the caller's variable
        p_td: value of the caller's variable
        p_td__tan: value of the caller's variable
        q_r_lo: value of the caller's variable
        q_th_td: value of the caller's variable
        q_th_td__tan: value of the caller's variable

    Returns a tuple:
        t_bottom: result for the caller
        t_stance: result for the caller
        bottom_q_r: result for the caller
        bottom_q_rd: result for the caller
        bottom_q_th: result for the caller
        bottom_q_thd: result for the caller
        liftoff_q_r: result for the caller
        liftoff_q_rd: result for the caller
        liftoff_q_th: result for the caller
        liftoff_q_thd: result for the caller
        P_c: result for the caller
        t_bottom__tan: result for the caller
        t_stance__tan: result for the caller
        bottom_q_r__tan: result for the caller
        bottom_q_rd__tan: result for the caller
        bottom_q_th__tan: result for the caller
        bottom_q_thd__tan: result for the caller
        liftoff_q_r__tan: result for the caller
        liftoff_q_rd__tan: result for the caller
        liftoff_q_th__tan: result for the caller
        liftoff_q_thd__tan: result for the caller
        P_c__tan: result for the caller
        passes__tan: result for the caller
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 170
    _c0 = type5_leg_angle_jvp_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td(i_t_bottom, q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0, i_t_bottom__tan, q_th_td__tan, p_td__tan, i_c0__tan, i_c1__tan, i_c2__tan, i_k0__tan, i_k1__tan, i_k2__tan, i_omega0_hat__tan, i_phase_td__tan)
    bottom_q_th = _c0[0]
    bottom_q_th__tan = _c0[1]
    _c1 = type5_leg_angle_jvp_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td(i_t_stance, q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0, i_t_stance__tan, q_th_td__tan, p_td__tan, i_c0__tan, i_c1__tan, i_c2__tan, i_k0__tan, i_k1__tan, i_k2__tan, i_omega0_hat__tan, i_phase_td__tan)
    liftoff_q_th = _c1[0]
    liftoff_q_th__tan = _c1[1]
    # T5.7: bottom and liftoff states
    _x0 = i_a - i_b + 1.0
    _x20 = (1.0/_x0)
    _x1 = i_t_bottom**2
    _x2 = (0.5)*i_c1
    _x3 = i_t_bottom**3
    _x4 = (0.3333333333333333)*i_c2
    _x5 = _x1*_x2 + _x3*_x4 + i_c0*i_t_bottom + p_td
    _x6 = (1.0/m)
    _x7 = l0**-2
    _x8 = _x20**2*_x6*_x7
    _x9 = (0.5)*i_c1__tan
    _x10 = (0.3333333333333333)*i_c2__tan
    _x11 = 2.0*_x20**3*_x5*_x6*_x7
    _x12 = i_t_stance**2
    _x13 = i_t_stance**3
    _x14 = _x12*_x2 + _x13*_x4 + i_c0*i_t_stance
    _x15 = i_c0__tan*i_t_stance
    _x16 = _x12*_x9
    _x17 = _x10*_x13
    _x18 = i_t_stance__tan*(_x12*i_c2 + i_c0 + i_c1*i_t_stance)
    _x19 = _x6/q_r_lo**2
    t_bottom = i_t_bottom
    t_bottom__tan = i_t_bottom__tan
    t_stance = i_t_stance
    t_stance__tan = i_t_stance__tan
    bottom_q_r = _x0*l0
    bottom_q_r__tan = i_a__tan*l0 - i_b__tan*l0
    bottom_q_rd = 0.0
    bottom_q_thd = _x5*_x8
    bottom_q_thd__tan = _x1*_x8*_x9 + _x10*_x3*_x8 - _x11*i_a__tan + _x11*i_b__tan + _x8*i_c0__tan*i_t_bottom + _x8*i_t_bottom__tan*(_x1*i_c2 + i_c0 + i_c1*i_t_bottom) + _x8*p_td__tan
    liftoff_q_r = q_r_lo
    P_c = _x14
    P_c__tan = _x15 + _x16 + _x17 + _x18
    liftoff_q_thd = _x19*(_x14 + p_td)
    liftoff_q_thd__tan = _x15*_x19 + _x16*_x19 + _x17*_x19 + _x18*_x19 + _x19*p_td__tan
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return _NAN23 + (STATUS_FALL,)
    _x21 = (1.0/m)
    _x22 = _x21*l0**2
    _x23 = q_r_lo**2
    _x24 = _x21*_x23
    _x25 = i_c0*i_t_stance
    _x26 = i_t_stance**2
    _x27 = _x26*i_c1
    _x28 = i_t_stance**3
    _x29 = _x28*i_c2
    _x30 = _x25 + (0.5)*_x27 + (0.3333333333333333)*_x29 + p_td
    _x31 = _x21**2/_x23
    _x32 = 2.0*i_t_stance
    _x33 = _x30*_x31
    _q_rd_lo_sq = 2.0*E_td*_x21 + 2.0*_x21*k*l0*q_r_lo - _x22*k - _x24*k - _x30**2*_x31 - 2.0*g_s*q_r_lo*math.cos(liftoff_q_th)
    _q_rd_lo_sq__tan = 2.0*E_td__tan*_x21 - _x26*_x33*i_c1__tan - 0.6666666666666666*_x28*_x33*i_c2__tan - _x31*p_td__tan*(2.0*_x25 + _x27 + (0.6666666666666666)*_x29 + 2.0*p_td) - _x32*_x33*i_c0__tan - _x33*i_t_stance__tan*(2.0*_x26*i_c2 + _x32*i_c1 + 2.0*i_c0) + 2.0*g_s*liftoff_q_th__tan*q_r_lo*math.sin(liftoff_q_th) + k__tan*(2.0*_x21*l0*q_r_lo - _x22 - _x24)
    # q_rd_lo^2 from the energy (27)
    if not ((_q_rd_lo_sq >= 0.0)):
        return _NAN23 + (STATUS_ENERGY_DEFICIT,)
    # q_rd_lo from the energy
    _x34 = math.sqrt(_q_rd_lo_sq)
    liftoff_q_rd = _x34
    liftoff_q_rd__tan = (0.5)*_q_rd_lo_sq__tan/_x34
    # derivatives that are identically zero
    bottom_q_rd__tan = 0.0
    liftoff_q_r__tan = 0.0
    passes__tan = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, P_c__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol, q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k__tan):
    """Gravity correction type 5 (time-varying momentum): touchdown state -> bottom and liftoff states, with the derivative of every output along the direction (q_r_td__tan, q_rd_td__tan, q_th_td__tan, q_thd_td__tan, k__tan).

    Report equations: 46, 47, 48.

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
        iterations: option iterations: fixed-point passes T5.8 from Geyer's map in [0, 1000]
        tol: option tol: stop when every state moved by at most tol times its scale; 0: run all passes in [0, 1]
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
        P_c: stance impulse of the gravity torque P(t_lo) - p_td [N m s]
        passes: fixed-point passes run
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
        P_c__tan: derivative of P_c along the direction
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 52
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(q_r_td__tan) and math.isfinite(q_rd_td__tan) and math.isfinite(q_th_td__tan) and math.isfinite(q_thd_td__tan) and math.isfinite(k__tan) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN24 + (STATUS_INVALID_INPUT,)
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = _x1*q_thd_td
    _x3 = l0*q_r_td
    _x4 = (0.5)*l0**2
    _x5 = (0.5)*_x0
    _x6 = g_s*m
    _x7 = _x6*math.cos(q_th_td)
    _x8 = m*q_thd_td**2
    p_td = _x2
    p_td__tan = _x1*q_thd_td__tan + 2.0*m*q_r_td*q_r_td__tan*q_thd_td
    E_td = -_x3*k + _x4*k + _x5*_x8 + _x5*k + _x7*q_r_td + (0.5)*m*q_rd_td**2
    E_td__tan = _x2*q_thd_td__tan - _x6*q_r_td*q_th_td__tan*math.sin(q_th_td) + k__tan*(-_x3 + _x4 + _x5) + m*q_rd_td*q_rd_td__tan + q_r_td__tan*(_x7 + _x8*q_r_td - k*l0 + k*q_r_td)
    # T5.8: fixed point on the nodal torques, the stance time, g_eff and r_c
    tau1 = 0.0
    tau2 = 0.0
    tau3 = 0.0
    T = 1.0
    g_eff = g_s
    r_c = 0.0
    tau1__tan = 0.0
    tau2__tan = 0.0
    tau3__tan = 0.0
    T__tan = 0.0
    g_eff__tan = 0.0
    r_c__tan = 0.0
    passes = 0.0
    _conv0 = False
    # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
    # final iterate is evaluated too, so its values are visible after the loop
    _last0 = max(int(iterations), 0)
    for _it0 in range(_last0 + 1):
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return _NAN24 + (STATUS_NOT_CONVERGED,)
        # evaluation and update
        _c0 = gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_0(T, T__tan, g_eff, g_eff__tan, g_s, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo, q_r_td, q_r_td__tan, q_rd_td, q_rd_td__tan, q_th_td, q_th_td__tan, r_c, r_c__tan, tau1, tau1__tan, tau2, tau2__tan, tau3, tau3__tan)
        if _c0[36] != STATUS_OK:
            return _NAN24 + (_c0[36],)
        (i_c0, i_c0__tan, i_c1, i_c1__tan, i_c2, i_c2__tan, i_omega0_hat, i_a, i_b, i_phase_td, i_omega0_hat__tan, i_a__tan, i_b__tan, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, i_k0, i_k0__tan, i_k1, i_k1__tan, i_k2, i_k2__tan, _next_tau1, _next_tau2, _next_tau3, _next_T, _next_g_eff, _next_r_c, _next_tau1__tan, _next_tau2__tan, _next_tau3__tan, _next_T__tan, _next_g_eff__tan, _next_r_c__tan, _) = _c0
        if _conv0 or _it0 == _last0:
            break
        _n0_0 = _next_tau1
        _n0_1 = _next_tau2
        _n0_2 = _next_tau3
        _n0_3 = _next_T
        _n0_4 = _next_g_eff
        _n0_5 = _next_r_c
        _n0_6 = _next_tau1__tan
        _n0_7 = _next_tau2__tan
        _n0_8 = _next_tau3__tan
        _n0_9 = _next_T__tan
        _n0_10 = _next_g_eff__tan
        _n0_11 = _next_r_c__tan
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - tau1) <= tol*(g_s*l0*m)) and (abs(_n0_1 - tau2) <= tol*(g_s*l0*m)) and (abs(_n0_2 - tau3) <= tol*(g_s*l0*m)) and (abs(_n0_3 - T) <= tol*(math.sqrt(m)/math.sqrt(k))) and (abs(_n0_4 - g_eff) <= tol*(g_s)) and (abs(_n0_5 - r_c) <= tol*(1.0))
        tau1 = _n0_0
        tau2 = _n0_1
        tau3 = _n0_2
        T = _n0_3
        g_eff = _n0_4
        r_c = _n0_5
        tau1__tan = _n0_6
        tau2__tan = _n0_7
        tau3__tan = _n0_8
        T__tan = _n0_9
        g_eff__tan = _n0_10
        r_c__tan = _n0_11
        passes += 1.0
    # continuation
    _c1 = gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k_1(E_td, E_td__tan, g_s, i_a, i_a__tan, i_b, i_b__tan, i_c0, i_c0__tan, i_c1, i_c1__tan, i_c2, i_c2__tan, i_k0, i_k0__tan, i_k1, i_k1__tan, i_k2, i_k2__tan, i_omega0_hat, i_omega0_hat__tan, i_phase_td, i_phase_td__tan, i_t_bottom, i_t_bottom__tan, i_t_stance, i_t_stance__tan, k, k__tan, l0, m, p_td, p_td__tan, q_r_lo, q_th_td, q_th_td__tan)
    if _c1[23] != STATUS_OK:
        return _NAN24 + (_c1[23],)
    (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, P_c__tan, passes__tan, _) = _c1
    # (internal helper: its callers check that their outputs are finite)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, t_bottom__tan, t_stance__tan, bottom_q_r__tan, bottom_q_rd__tan, bottom_q_th__tan, bottom_q_thd__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, P_c__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type5_stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol):
    """Gravity correction type 5 (time-varying momentum): stance outputs and their derivatives with respect to the touchdown state and the stiffness.

    Report equations: 46, 47, 48.

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
        iterations: option iterations: fixed-point passes T5.8 from Geyer's map in [0, 1000]
        tol: option tol: stop when every state moved by at most tol times its scale; 0: run all passes in [0, 1]

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
        P_c: stance impulse of the gravity torque P(t_lo) - p_td [N m s]
        passes: fixed-point passes run
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
        d_P_c__q_r_td: d P_c / d q_r_td
        d_P_c__q_rd_td: d P_c / d q_rd_td
        d_P_c__q_th_td: d P_c / d q_th_td
        d_P_c__q_thd_td: d P_c / d q_thd_td
        d_P_c__k: d P_c / d k
        d_passes__q_r_td: d passes / d q_r_td
        d_passes__q_rd_td: d passes / d q_rd_td
        d_passes__q_th_td: d passes / d q_th_td
        d_passes__q_thd_td: d passes / d q_thd_td
        d_passes__k: d passes / d k
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td) and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN72 + (STATUS_INVALID_INPUT,)
    # derivatives with respect to q_r_td
    _c0 = gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol, 1.0, 0.0, 0.0, 0.0, 0.0)
    if _c0[24] != STATUS_OK:
        return _NAN72 + (_c0[24],)
    (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_t_bottom__q_r_td, d_t_stance__q_r_td, d_bottom_q_r__q_r_td, d_bottom_q_rd__q_r_td, d_bottom_q_th__q_r_td, d_bottom_q_thd__q_r_td, d_liftoff_q_r__q_r_td, d_liftoff_q_rd__q_r_td, d_liftoff_q_th__q_r_td, d_liftoff_q_thd__q_r_td, d_P_c__q_r_td, d_passes__q_r_td, _) = _c0
    # derivatives with respect to q_rd_td
    _c1 = gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol, 0.0, 1.0, 0.0, 0.0, 0.0)
    if _c1[24] != STATUS_OK:
        return _NAN72 + (_c1[24],)
    (_, _, _, _, _, _, _, _, _, _, _, _, d_t_bottom__q_rd_td, d_t_stance__q_rd_td, d_bottom_q_r__q_rd_td, d_bottom_q_rd__q_rd_td, d_bottom_q_th__q_rd_td, d_bottom_q_thd__q_rd_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_thd__q_rd_td, d_P_c__q_rd_td, d_passes__q_rd_td, _) = _c1
    # derivatives with respect to q_th_td
    _c2 = gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol, 0.0, 0.0, 1.0, 0.0, 0.0)
    if _c2[24] != STATUS_OK:
        return _NAN72 + (_c2[24],)
    (_, _, _, _, _, _, _, _, _, _, _, _, d_t_bottom__q_th_td, d_t_stance__q_th_td, d_bottom_q_r__q_th_td, d_bottom_q_rd__q_th_td, d_bottom_q_th__q_th_td, d_bottom_q_thd__q_th_td, d_liftoff_q_r__q_th_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_th__q_th_td, d_liftoff_q_thd__q_th_td, d_P_c__q_th_td, d_passes__q_th_td, _) = _c2
    # derivatives with respect to q_thd_td
    _c3 = gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol, 0.0, 0.0, 0.0, 1.0, 0.0)
    if _c3[24] != STATUS_OK:
        return _NAN72 + (_c3[24],)
    (_, _, _, _, _, _, _, _, _, _, _, _, d_t_bottom__q_thd_td, d_t_stance__q_thd_td, d_bottom_q_r__q_thd_td, d_bottom_q_rd__q_thd_td, d_bottom_q_th__q_thd_td, d_bottom_q_thd__q_thd_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_thd__q_thd_td, d_P_c__q_thd_td, d_passes__q_thd_td, _) = _c3
    # derivatives with respect to k
    _c4 = gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol, 0.0, 0.0, 0.0, 0.0, 1.0)
    if _c4[24] != STATUS_OK:
        return _NAN72 + (_c4[24],)
    (_, _, _, _, _, _, _, _, _, _, _, _, d_t_bottom__k, d_t_stance__k, d_bottom_q_r__k, d_bottom_q_rd__k, d_bottom_q_th__k, d_bottom_q_thd__k, d_liftoff_q_r__k, d_liftoff_q_rd__k, d_liftoff_q_th__k, d_liftoff_q_thd__k, d_P_c__k, d_passes__k, _) = _c4
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_bottom) and math.isfinite(t_stance) and math.isfinite(bottom_q_r) and math.isfinite(bottom_q_rd) and math.isfinite(bottom_q_th) and math.isfinite(bottom_q_thd) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(P_c) and math.isfinite(passes) and math.isfinite(d_t_bottom__q_r_td) and math.isfinite(d_t_bottom__q_rd_td) and math.isfinite(d_t_bottom__q_th_td) and math.isfinite(d_t_bottom__q_thd_td) and math.isfinite(d_t_bottom__k) and math.isfinite(d_t_stance__q_r_td) and math.isfinite(d_t_stance__q_rd_td) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__q_thd_td) and math.isfinite(d_t_stance__k) and math.isfinite(d_bottom_q_r__q_r_td) and math.isfinite(d_bottom_q_r__q_rd_td) and math.isfinite(d_bottom_q_r__q_th_td) and math.isfinite(d_bottom_q_r__q_thd_td) and math.isfinite(d_bottom_q_r__k) and math.isfinite(d_bottom_q_rd__q_r_td) and math.isfinite(d_bottom_q_rd__q_rd_td) and math.isfinite(d_bottom_q_rd__q_th_td) and math.isfinite(d_bottom_q_rd__q_thd_td) and math.isfinite(d_bottom_q_rd__k) and math.isfinite(d_bottom_q_th__q_r_td) and math.isfinite(d_bottom_q_th__q_rd_td) and math.isfinite(d_bottom_q_th__q_th_td) and math.isfinite(d_bottom_q_th__q_thd_td) and math.isfinite(d_bottom_q_th__k) and math.isfinite(d_bottom_q_thd__q_r_td) and math.isfinite(d_bottom_q_thd__q_rd_td) and math.isfinite(d_bottom_q_thd__q_th_td) and math.isfinite(d_bottom_q_thd__q_thd_td) and math.isfinite(d_bottom_q_thd__k) and math.isfinite(d_liftoff_q_r__q_r_td) and math.isfinite(d_liftoff_q_r__q_rd_td) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__q_thd_td) and math.isfinite(d_liftoff_q_r__k) and math.isfinite(d_liftoff_q_rd__q_r_td) and math.isfinite(d_liftoff_q_rd__q_rd_td) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__q_thd_td) and math.isfinite(d_liftoff_q_rd__k) and math.isfinite(d_liftoff_q_th__q_r_td) and math.isfinite(d_liftoff_q_th__q_rd_td) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__q_thd_td) and math.isfinite(d_liftoff_q_th__k) and math.isfinite(d_liftoff_q_thd__q_r_td) and math.isfinite(d_liftoff_q_thd__q_rd_td) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__q_thd_td) and math.isfinite(d_liftoff_q_thd__k) and math.isfinite(d_P_c__q_r_td) and math.isfinite(d_P_c__q_rd_td) and math.isfinite(d_P_c__q_th_td) and math.isfinite(d_P_c__q_thd_td) and math.isfinite(d_P_c__k) and math.isfinite(d_passes__q_r_td) and math.isfinite(d_passes__q_rd_td) and math.isfinite(d_passes__q_th_td) and math.isfinite(d_passes__q_thd_td) and math.isfinite(d_passes__k)):
        return _NAN72 + (STATUS_NUMERICAL_RANGE,)
    return (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k, d_P_c__q_r_td, d_P_c__q_rd_td, d_P_c__q_th_td, d_P_c__q_thd_td, d_P_c__k, d_passes__q_r_td, d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def gravity_type5_stance_jacobian_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`gravity_type5_stance_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k, g_s, q_r_lo, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 72)) and its status code to
    ``status[i]`` (int64). Columns: t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k, d_bottom_q_rd__q_r_td, d_bottom_q_rd__q_rd_td, d_bottom_q_rd__q_th_td, d_bottom_q_rd__q_thd_td, d_bottom_q_rd__k, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td, d_bottom_q_th__k, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k, d_liftoff_q_r__q_r_td, d_liftoff_q_r__q_rd_td, d_liftoff_q_r__q_th_td, d_liftoff_q_r__q_thd_td, d_liftoff_q_r__k, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k, d_P_c__q_r_td, d_P_c__q_rd_td, d_P_c__q_th_td, d_P_c__q_thd_td, d_P_c__k, d_passes__q_r_td, d_passes__q_rd_td, d_passes__q_th_td, d_passes__q_thd_td, d_passes__k.
    """
    for i in prange(out.shape[0]):
        res = gravity_type5_stance_jacobian(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m, l0, k, g_s, q_r_lo, iterations, tol)
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
        out[i, 60] = res[60]
        out[i, 61] = res[61]
        out[i, 62] = res[62]
        out[i, 63] = res[63]
        out[i, 64] = res[64]
        out[i, 65] = res[65]
        out[i, 66] = res[66]
        out[i, 67] = res[67]
        out[i, 68] = res[68]
        out[i, 69] = res[69]
        out[i, 70] = res[70]
        out[i, 71] = res[71]
        status[i] = res[72]


@njit(cache=True, error_model="numpy")
def gravity_type5_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, k__tan):
    """Apex-return map: exact flights, stance by Gravity correction type 5 (time-varying momentum), with the derivative of every output along the direction (b_y_apex__tan, b_xd_apex__tan, q_th_td__tan, k__tan).

    Report equations: 46, 47, 48.

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
        iterations: option iterations: fixed-point passes T5.8 from Geyer's map in [0, 1000]
        tol: option tol: stop when every state moved by at most tol times its scale; 0: run all passes in [0, 1]
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
        P_c: stance impulse of the gravity torque P(t_lo) - p_td [N m s]
        passes: fixed-point passes run
        apex_height__tan: derivative of apex_height along the direction
        apex_speed__tan: derivative of apex_speed along the direction
        t_descent__tan: derivative of t_descent along the direction
        t_stance__tan: derivative of t_stance along the direction
        t_ascent__tan: derivative of t_ascent along the direction
        liftoff_q_r__tan: derivative of liftoff_q_r along the direction
        liftoff_q_rd__tan: derivative of liftoff_q_rd along the direction
        liftoff_q_th__tan: derivative of liftoff_q_th along the direction
        liftoff_q_thd__tan: derivative of liftoff_q_thd along the direction
        P_c__tan: derivative of P_c along the direction
        passes__tan: derivative of passes along the direction
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and math.isfinite(b_y_apex__tan) and math.isfinite(b_xd_apex__tan) and math.isfinite(q_th_td__tan) and math.isfinite(k__tan) and ((b_y_apex >= 0.0)) and ((b_xd_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN22 + (STATUS_INVALID_INPUT,)
    # apex -> touchdown: exact ballistic descent (sections 2.1, 2.2.2)
    _c0 = apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, b_y_apex__tan, b_xd_apex__tan, q_th_td__tan)
    if _c0[10] != STATUS_OK:
        return _NAN22 + (_c0[10],)
    (td_q_r, td_q_rd, td_q_th, td_q_thd, t_descent, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, t_descent__tan, _) = _c0
    # stance: Gravity correction type 5 (time-varying momentum)
    _c1 = gravity_type5_stance_jvp_q_r_td_q_rd_td_q_th_td_q_thd_td_k(td_q_r, td_q_rd, td_q_th, td_q_thd, m, l0, k, g_s, q_r_lo, iterations, tol, td_q_r__tan, td_q_rd__tan, td_q_th__tan, td_q_thd__tan, k__tan)
    if _c1[24] != STATUS_OK:
        return _NAN22 + (_c1[24],)
    (_, t_stance, _, _, _, _, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, _, t_stance__tan, _, _, _, _, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, P_c__tan, passes__tan, _) = _c1
    # liftoff -> next apex: exact ballistic ascent
    _c2 = liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan)
    if _c2[8] != STATUS_OK:
        return _NAN22 + (_c2[8],)
    apex_height = _c2[0]
    apex_speed = _c2[1]
    t_ascent = _c2[2]
    apex_height__tan = _c2[4]
    apex_speed__tan = _c2[5]
    t_ascent__tan = _c2[6]
    # (internal helper: its callers check that their outputs are finite)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, apex_height__tan, apex_speed__tan, t_descent__tan, t_stance__tan, t_ascent__tan, liftoff_q_r__tan, liftoff_q_rd__tan, liftoff_q_th__tan, liftoff_q_thd__tan, P_c__tan, passes__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type5_apex_return_jacobian(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol):
    """Apex-return map by Gravity correction type 5 (time-varying momentum), and its derivatives with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48.

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
        iterations: option iterations: fixed-point passes T5.8 from Geyer's map in [0, 1000]
        tol: option tol: stop when every state moved by at most tol times its scale; 0: run all passes in [0, 1]

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
        P_c: stance impulse of the gravity torque P(t_lo) - p_td [N m s]
        passes: fixed-point passes run
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
        d_P_c__b_y_apex: d P_c / d b_y_apex
        d_P_c__b_xd_apex: d P_c / d b_xd_apex
        d_P_c__q_th_td: d P_c / d q_th_td
        d_P_c__k: d P_c / d k
        d_passes__b_y_apex: d passes / d b_y_apex
        d_passes__b_xd_apex: d passes / d b_xd_apex
        d_passes__q_th_td: d passes / d q_th_td
        d_passes__k: d passes / d k
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k) and math.isfinite(g_s) and math.isfinite(g_f) and math.isfinite(q_r_td) and math.isfinite(q_r_lo) and math.isfinite(iterations) and math.isfinite(tol) and ((b_y_apex >= 0.0)) and ((b_xd_apex >= 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k > 0.0)) and ((g_s > 0.0)) and ((g_f > 0.0)) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN55 + (STATUS_INVALID_INPUT,)
    # derivatives with respect to b_y_apex
    _c0 = gravity_type5_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol, 1.0, 0.0, 0.0, 0.0)
    if _c0[22] != STATUS_OK:
        return _NAN55 + (_c0[22],)
    (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_apex_height__b_y_apex, d_apex_speed__b_y_apex, d_t_descent__b_y_apex, d_t_stance__b_y_apex, d_t_ascent__b_y_apex, d_liftoff_q_r__b_y_apex, d_liftoff_q_rd__b_y_apex, d_liftoff_q_th__b_y_apex, d_liftoff_q_thd__b_y_apex, d_P_c__b_y_apex, d_passes__b_y_apex, _) = _c0
    # derivatives with respect to b_xd_apex
    _c1 = gravity_type5_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol, 0.0, 1.0, 0.0, 0.0)
    if _c1[22] != STATUS_OK:
        return _NAN55 + (_c1[22],)
    (_, _, _, _, _, _, _, _, _, _, _, d_apex_height__b_xd_apex, d_apex_speed__b_xd_apex, d_t_descent__b_xd_apex, d_t_stance__b_xd_apex, d_t_ascent__b_xd_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_thd__b_xd_apex, d_P_c__b_xd_apex, d_passes__b_xd_apex, _) = _c1
    # derivatives with respect to q_th_td
    _c2 = gravity_type5_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol, 0.0, 0.0, 1.0, 0.0)
    if _c2[22] != STATUS_OK:
        return _NAN55 + (_c2[22],)
    (_, _, _, _, _, _, _, _, _, _, _, d_apex_height__q_th_td, d_apex_speed__q_th_td, d_t_descent__q_th_td, d_t_stance__q_th_td, d_t_ascent__q_th_td, d_liftoff_q_r__q_th_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_th__q_th_td, d_liftoff_q_thd__q_th_td, d_P_c__q_th_td, d_passes__q_th_td, _) = _c2
    # derivatives with respect to k
    _c3 = gravity_type5_apex_return_jvp_b_y_apex_b_xd_apex_q_th_td_k(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol, 0.0, 0.0, 0.0, 1.0)
    if _c3[22] != STATUS_OK:
        return _NAN55 + (_c3[22],)
    (_, _, _, _, _, _, _, _, _, _, _, d_apex_height__k, d_apex_speed__k, d_t_descent__k, d_t_stance__k, d_t_ascent__k, d_liftoff_q_r__k, d_liftoff_q_rd__k, d_liftoff_q_th__k, d_liftoff_q_thd__k, d_P_c__k, d_passes__k, _) = _c3
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(apex_height) and math.isfinite(apex_speed) and math.isfinite(t_descent) and math.isfinite(t_stance) and math.isfinite(t_ascent) and math.isfinite(liftoff_q_r) and math.isfinite(liftoff_q_rd) and math.isfinite(liftoff_q_th) and math.isfinite(liftoff_q_thd) and math.isfinite(P_c) and math.isfinite(passes) and math.isfinite(d_apex_height__b_y_apex) and math.isfinite(d_apex_height__b_xd_apex) and math.isfinite(d_apex_height__q_th_td) and math.isfinite(d_apex_height__k) and math.isfinite(d_apex_speed__b_y_apex) and math.isfinite(d_apex_speed__b_xd_apex) and math.isfinite(d_apex_speed__q_th_td) and math.isfinite(d_apex_speed__k) and math.isfinite(d_t_descent__b_y_apex) and math.isfinite(d_t_descent__b_xd_apex) and math.isfinite(d_t_descent__q_th_td) and math.isfinite(d_t_descent__k) and math.isfinite(d_t_stance__b_y_apex) and math.isfinite(d_t_stance__b_xd_apex) and math.isfinite(d_t_stance__q_th_td) and math.isfinite(d_t_stance__k) and math.isfinite(d_t_ascent__b_y_apex) and math.isfinite(d_t_ascent__b_xd_apex) and math.isfinite(d_t_ascent__q_th_td) and math.isfinite(d_t_ascent__k) and math.isfinite(d_liftoff_q_r__b_y_apex) and math.isfinite(d_liftoff_q_r__b_xd_apex) and math.isfinite(d_liftoff_q_r__q_th_td) and math.isfinite(d_liftoff_q_r__k) and math.isfinite(d_liftoff_q_rd__b_y_apex) and math.isfinite(d_liftoff_q_rd__b_xd_apex) and math.isfinite(d_liftoff_q_rd__q_th_td) and math.isfinite(d_liftoff_q_rd__k) and math.isfinite(d_liftoff_q_th__b_y_apex) and math.isfinite(d_liftoff_q_th__b_xd_apex) and math.isfinite(d_liftoff_q_th__q_th_td) and math.isfinite(d_liftoff_q_th__k) and math.isfinite(d_liftoff_q_thd__b_y_apex) and math.isfinite(d_liftoff_q_thd__b_xd_apex) and math.isfinite(d_liftoff_q_thd__q_th_td) and math.isfinite(d_liftoff_q_thd__k) and math.isfinite(d_P_c__b_y_apex) and math.isfinite(d_P_c__b_xd_apex) and math.isfinite(d_P_c__q_th_td) and math.isfinite(d_P_c__k) and math.isfinite(d_passes__b_y_apex) and math.isfinite(d_passes__b_xd_apex) and math.isfinite(d_passes__q_th_td) and math.isfinite(d_passes__k)):
        return _NAN55 + (STATUS_NUMERICAL_RANGE,)
    return (apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__k, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__k, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__k, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__k, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__k, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__k, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__k, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__k, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__k, d_P_c__b_y_apex, d_P_c__b_xd_apex, d_P_c__q_th_td, d_P_c__k, d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__k, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def gravity_type5_apex_return_jacobian_batch(b_y_apex, b_xd_apex, q_th_td, m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol, out, status):
    """Parallel batch form of :func:`gravity_type5_apex_return_jacobian`.

    Row arguments (1-D float64 arrays of equal length n, any stride): b_y_apex, b_xd_apex, q_th_td.
    Scalar arguments shared by every row: m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 55)) and its status code to
    ``status[i]`` (int64). Columns: apex_height, apex_speed, t_descent, t_stance, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__k, d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__k, d_t_descent__b_y_apex, d_t_descent__b_xd_apex, d_t_descent__q_th_td, d_t_descent__k, d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__k, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__k, d_liftoff_q_r__b_y_apex, d_liftoff_q_r__b_xd_apex, d_liftoff_q_r__q_th_td, d_liftoff_q_r__k, d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__k, d_liftoff_q_th__b_y_apex, d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__k, d_liftoff_q_thd__b_y_apex, d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__k, d_P_c__b_y_apex, d_P_c__b_xd_apex, d_P_c__q_th_td, d_P_c__k, d_passes__b_y_apex, d_passes__b_xd_apex, d_passes__q_th_td, d_passes__k.
    """
    for i in prange(out.shape[0]):
        res = gravity_type5_apex_return_jacobian(b_y_apex[i], b_xd_apex[i], q_th_td[i], m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol)
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
        status[i] = res[55]
