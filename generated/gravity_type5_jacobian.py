# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/gravity_type5.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight_jacobian.py sha256:4de4ff5a5b5282af
#   geyer_jacobian.py sha256:a1c9347d955c37d0
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module gravity_type5: JVP kernels, and for
a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate,
    liftoff_to_apex_jac_q_rd_q_th_q_thd)
from .geyer_jacobian import geyer_liftoff_phase_jac_a_b

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING,
    STATUS_NO_REAL_SOLUTION, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION, STATUS_FALL, STATUS_NUMERICAL_RANGE,
    STATUS_NOT_CONVERGED, STATUS_ENERGY_DEFICIT)

NAN = math.nan


@njit(cache=True, error_model="numpy")
def type5_solution_jac_q_r_td_q_rd_td_omega_g_eff_r_c_k(q_r_td, q_rd_td, omega, g_eff, r_c, m, l0, k, out):
    """Type 5 radial solution: (10)-(11) for the quadratic T5.4 about r_c with g_eff, and the derivatives of
    its outputs with respect to q_r_td, q_rd_td, omega, g_eff, r_c, k.

    Report equations: 9, 10, 11, 12.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`gravity_type5.type5_solution`, in its order.

    Writes into out:
        <output>: each output of :func:`gravity_type5.type5_solution`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            omega, g_eff, r_c, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 218
    _x0 = (1.0/m)
    omega0_sq = _x0*k
    d_omega0_sq__k = _x0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # T5.4: the quadratic about r_c with g_eff
    _x1 = r_c + 1.0
    _x23 = (1.0/_x1)
    _x2 = _x23**4
    _x3 = 4.0*omega0_sq
    _x4 = omega**2
    _x5 = r_c**4
    _x6 = r_c**2
    _x7 = 6.0*_x6
    _x8 = r_c**3
    _x9 = _x3*_x8
    _x10 = _x3*r_c + 3.0*_x4 + _x5*omega0_sq + _x7*omega0_sq + _x9 + omega0_sq
    lam = -_x10*_x2
    d_lam__omega = -6.0*_x2*omega
    _x11 = 12.0*omega0_sq
    _x12 = _x23**5
    d_lam__r_c = 4.0*_x10*_x12 - _x2*(_x11*_x6 + _x11*r_c + _x3 + _x9)
    _x13 = 4.0*r_c
    _x14 = 4.0*_x8
    _x15 = _x13 + _x14 + _x5 + _x7 + 1.0
    d_lam__k = -_x15*_x2*d_omega0_sq__k
    _x16 = (1.0/l0)
    _x17 = _x14*g_eff
    _x18 = _x16*(-_x13*g_eff - _x17 + 4.0*_x4*l0*r_c + _x4*l0 - _x5*g_eff - _x7*g_eff - g_eff)
    _x19 = 2.0*_x2
    mu = _x18*_x19
    _x20 = l0*omega
    _x21 = _x16*_x19
    d_mu__omega = _x21*(8.0*_x20*r_c + 2.0*_x20)
    d_mu__g_eff = -_x15*_x21
    _x22 = 12.0*g_eff
    d_mu__r_c = -8.0*_x12*_x18 + _x21*(-_x17 - _x22*_x6 - _x22*r_c + 4.0*_x4*l0 - 4.0*g_eff)
    # T5.5: through the touchdown point
    _x25 = (1.0/l0)
    _x24 = _x25**2
    _x26 = -_x25*q_r_td + 1.0
    _x27 = -_x26
    _x28 = _x27**2
    nu = _x24*q_rd_td**2 - _x27*mu - _x28*lam
    _pd__0 = -_x28
    _pd__1 = _x26
    d_nu__q_r_td = -2.0*_x25*_x27*lam - _x25*mu
    d_nu__q_rd_td = 2.0*_x24*q_rd_td
    d_nu__omega = _pd__0*d_lam__omega + _pd__1*d_mu__omega
    d_nu__g_eff = _pd__1*d_mu__g_eff
    d_nu__r_c = _pd__0*d_lam__r_c + _pd__1*d_mu__r_c
    d_nu__k = _pd__0*d_lam__k
    # eq (10)-(11): omega0_hat, a and b^2 of rho = a + b sin(omega0_hat t)
    _x29 = math.sqrt(-lam)
    omega0_hat = _x29
    _x30 = (1.0/lam)
    _x31 = (0.5)*_x30
    _pd__2 = _x29*_x31
    d_omega0_hat__omega = _pd__2*d_lam__omega
    d_omega0_hat__r_c = _pd__2*d_lam__r_c
    d_omega0_hat__k = _pd__2*d_lam__k
    a = -_x31*mu
    _x32 = _x30**2
    _x33 = (0.5)*_x32*mu
    _pd__3 = _x33
    _pd__4 = -_x31
    d_a__omega = _pd__3*d_lam__omega + _pd__4*d_mu__omega
    d_a__g_eff = _pd__4*d_mu__g_eff
    d_a__r_c = _pd__3*d_lam__r_c + _pd__4*d_mu__r_c
    d_a__k = _pd__3*d_lam__k
    _x34 = -4.0*lam*nu + mu**2
    b2 = (0.25)*_x32*_x34
    _pd__5 = -0.5*_x30**3*_x34 - _x32*nu
    _pd__6 = _x33
    _pd__7 = -_x30
    d_b2__q_r_td = _pd__7*d_nu__q_r_td
    d_b2__q_rd_td = _pd__7*d_nu__q_rd_td
    d_b2__omega = _pd__5*d_lam__omega + _pd__6*d_mu__omega + _pd__7*d_nu__omega
    d_b2__g_eff = _pd__6*d_mu__g_eff + _pd__7*d_nu__g_eff
    d_b2__r_c = _pd__5*d_lam__r_c + _pd__6*d_mu__r_c + _pd__7*d_nu__r_c
    d_b2__k = _pd__5*d_lam__k + _pd__7*d_nu__k
    # eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0
    if not ((b2 > 0.0)):
        return fail(out, STATUS_NO_REAL_SOLUTION)
    # eq (12): sin(phase) at touchdown
    _x35 = math.sqrt(b2)
    b = _x35
    _x36 = (1.0/_x35)
    _pd__8 = (0.5)*_x36
    d_b__q_r_td = _pd__8*d_b2__q_r_td
    d_b__q_rd_td = _pd__8*d_b2__q_rd_td
    d_b__omega = _pd__8*d_b2__omega
    d_b__g_eff = _pd__8*d_b2__g_eff
    d_b__r_c = _pd__8*d_b2__r_c
    d_b__k = _pd__8*d_b2__k
    _x37 = (1.0/l0)
    _x38 = _x37*q_r_td - a - 1.0
    s_td = _x36*_x38
    _pd__9 = -_x36
    _pd__10 = -_x38/b2
    d_s_td__q_r_td = _pd__10*d_b__q_r_td + _x36*_x37
    d_s_td__q_rd_td = _pd__10*d_b__q_rd_td
    d_s_td__omega = _pd__10*d_b__omega + _pd__9*d_a__omega
    d_s_td__g_eff = _pd__10*d_b__g_eff + _pd__9*d_a__g_eff
    d_s_td__r_c = _pd__10*d_b__r_c + _pd__9*d_a__r_c
    d_s_td__k = _pd__10*d_b__k + _pd__9*d_a__k
    # the leg collapses: l0 (1 + a - b) <= 0
    if not ((a - b + 1.0 > 0.0)):
        return fail(out, STATUS_FALL)
    # (12) needs |s_td| <= 1
    if not ((abs(s_td) <= 1.0)):
        return fail(out, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION)
    # eq (12), n = 0: compressing root
    phase_td = math.pi - math.asin(s_td)
    _pd__11 = -1.0/math.sqrt(1.0 - s_td**2)
    d_phase_td__q_r_td = _pd__11*d_s_td__q_r_td
    d_phase_td__q_rd_td = _pd__11*d_s_td__q_rd_td
    d_phase_td__omega = _pd__11*d_s_td__omega
    d_phase_td__g_eff = _pd__11*d_s_td__g_eff
    d_phase_td__r_c = _pd__11*d_s_td__r_c
    d_phase_td__k = _pd__11*d_s_td__k
    # (internal helper: its callers check that their outputs are finite)
    store(out, (omega0_hat, a, b, phase_td, s_td, 0.0, 0.0, d_omega0_hat__omega, 0.0, d_omega0_hat__r_c,
        d_omega0_hat__k, 0.0, 0.0, d_a__omega, d_a__g_eff, d_a__r_c, d_a__k, d_b__q_r_td, d_b__q_rd_td,
        d_b__omega, d_b__g_eff, d_b__r_c, d_b__k, d_phase_td__q_r_td, d_phase_td__q_rd_td, d_phase_td__omega,
        d_phase_td__g_eff, d_phase_td__r_c, d_phase_td__k, d_s_td__q_r_td, d_s_td__q_rd_td, d_s_td__omega,
        d_s_td__g_eff, d_s_td__r_c, d_s_td__k,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def type5_leg_angle_jac_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td(t, q_th_td, p_td, c0, c1, c2, k0,
        k1, k2, omega0_hat, phase_td, m, l0):
    """Type 5 leg angle T5.6: q_th_td + int_0^t P(u) (k0 + k1 sin + k2 cos 2(.)) du / (m l0^2), and the
    derivatives of its outputs with respect to t, q_th_td, p_td, c0, c1, c2, k0, k1, k2, omega0_hat, phase_td.

    Report equations: 17, 18, 19.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`gravity_type5.type5_leg_angle`, in its order.

    Returns a tuple:
        <output>: each output of :func:`gravity_type5.type5_leg_angle`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument t, q_th_td, p_td, c0,
            c1, c2, k0, k1, k2, omega0_hat, phase_td (row-major)
    """
    # Total ops: 421
    _x0 = k0*p_td
    _x1 = t**2
    _x2 = (0.5)*_x1
    _x3 = _x2*k0
    _x4 = t**3
    _x5 = (0.16666666666666666)*_x4
    _x6 = _x5*k0
    _x7 = t**4
    _x8 = (0.08333333333333333)*_x7
    _x9 = _x8*k0
    _x10 = k1*p_td
    _x11 = (1.0/omega0_hat)
    _x12 = math.cos(phase_td)
    _x13 = _x11*_x12
    _x14 = _x11**2
    _x15 = math.sin(phase_td)
    _x16 = _x14*_x15
    _x17 = _x16*k1
    _x18 = _x11**3
    _x19 = _x12*k1
    _x20 = _x18*_x19
    _x21 = _x15*k1
    _x22 = _x11**4
    _x23 = 2.0*_x22
    _x24 = _x21*_x23
    _x25 = c0*k2
    _x26 = 2.0*phase_td
    _x27 = math.cos(_x26)
    _x28 = (0.25)*_x14
    _x29 = _x27*_x28
    _x30 = _x18*c1
    _x31 = math.sin(_x26)
    _x32 = (0.125)*_x31
    _x33 = _x32*k2
    _x34 = _x27*k2
    _x35 = (0.125)*_x22
    _x36 = _x34*_x35
    _x37 = _x11*k2
    _x38 = (0.5)*_x31
    _x39 = _x37*_x38
    _x40 = omega0_hat*t
    _x41 = _x40 + phase_td
    _x42 = math.cos(_x41)
    _x43 = _x11*_x42
    _x44 = _x26 + 2.0*_x40
    _x45 = math.sin(_x44)
    _x46 = (0.5)*_x45
    _x47 = _x37*_x46
    _x48 = math.sin(_x41)
    _x49 = _x14*_x48 - _x43*t
    _x50 = _x49*k1
    _x51 = math.cos(_x44)
    _x52 = _x14*_x51
    _x53 = _x11*t
    _x54 = _x46*_x53 + (0.25)*_x52
    _x55 = _x54*k2
    _x56 = 2.0*_x18
    _x57 = 2.0*t
    _x58 = -0.5*_x1*_x43 + (0.5)*_x14*_x48*_x57 + (0.5)*_x42*_x56
    _x59 = _x58*k1
    _x60 = _x18*_x45
    _x61 = (0.5)*_x11*_x2*_x45 + (0.25)*_x52*t - 0.125*_x60
    _x62 = _x61*k2
    _x63 = 6.0*_x22
    _x64 = _x1*_x14*_x48 + 2.0*_x18*_x42*t - 0.3333333333333333*_x4*_x43 - 0.3333333333333333*_x48*_x63
    _x65 = _x64*k1
    _x66 = (0.375)*_x22
    _x67 = _x11*_x4
    _x68 = (0.25)*_x1*_x52 + (0.3333333333333333)*_x46*_x67 - 0.3333333333333333*_x51*_x66 - 0.25*_x60*t
    _x69 = _x68*k2
    _x70 = 1.0/(l0**2*m)
    q_th = (_x70*(_x0*t + _x10*_x13 - _x10*_x43 - _x17*c0 - _x20*c1 + _x24*c2 - _x25*_x29 + _x3*c0 + _x30*_x33
        + _x36*c2 - _x39*p_td + _x47*p_td + _x50*c0 + _x55*c0 + _x59*c1 + _x6*c1 + _x62*c1 + _x65*c2 + _x69*c2
        + _x9*c2) + q_th_td)
    _x71 = k0*t
    _x72 = (0.3333333333333333)*c2
    _x73 = _x4*_x72
    _x74 = _x10*_x48
    _x75 = c0*k1
    _x76 = _x48*t
    _x77 = _x51*k2
    _x78 = _x77*p_td
    _x79 = _x2*c1
    _x80 = _x48*k1
    d_q_th__t = (_x70*(_x0 + _x3*c1 + _x71*c0 + _x73*_x77 + _x73*_x80 + _x73*k0 + _x74 + _x75*_x76 + _x77*_x79
        + _x77*c0*t + _x78 + _x79*_x80))
    d_q_th__p_td = _x70*(_x11*_x19 - _x39 - _x43*k1 + _x47 + _x71)
    d_q_th__c0 = _x70*(-_x17 - _x28*_x34 + _x3 + _x50 + _x55)
    d_q_th__c1 = _x70*(_x18*_x33 - _x20 + _x59 + _x6 + _x62)
    d_q_th__c2 = _x70*(_x24 + _x36 + _x65 + _x69 + _x9)
    _x81 = p_td*t
    d_q_th__k0 = _x70*(_x2*c0 + _x5*c1 + _x8*c2 + _x81)
    _x82 = _x23*c2
    d_q_th__k1 = _x70*(-_x12*_x30 + _x13*p_td + _x15*_x82 - _x16*c0 - _x43*p_td + _x49*c0 + _x58*c1 + _x64*c2)
    _x83 = _x11*p_td
    d_q_th__k2 = (_x70*(_x27*_x35*c2 - _x29*c0 + _x30*_x32 - _x38*_x83 + _x46*_x83 + _x54*c0 + _x61*c1
        + _x68*c2))
    _x84 = _x11**5
    _x85 = _x84*c2
    _x86 = _x31*k2
    _x87 = k2*p_td
    _x88 = _x14*_x38
    _x89 = _x14*_x42
    _x90 = _x11*_x81
    _x91 = _x14*_x45
    _x92 = (0.5)*_x91
    _x93 = _x1*_x11*_x48 - _x48*_x56 + _x57*_x89
    _x94 = _x18*_x51
    _x95 = _x1*_x11*_x51 - _x91*t - 0.5*_x94
    _x96 = (0.5)*c1
    _x97 = 3.0*_x1
    _x98 = k1*(-6.0*_x18*_x76 - _x42*_x63 + _x48*_x67 + _x89*_x97)
    _x99 = _x22*_x45
    _x100 = -1.5*_x1*_x91 + _x51*_x67 - 1.5*_x94*t + (0.75)*_x99
    _x101 = _x96*k2
    _x102 = _x11*_x7
    _x103 = _x72*k2
    d_q_th__omega0_hat = (_x70*(-_x10*_x12*_x14 + _x10*_x89 + _x100*_x101 + _x103*(_x102*_x51 - 2.0*_x4*_x91
        + (1.5)*_x51*_x84 - _x94*_x97 + 3.0*_x99*t) + _x15*_x56*_x75 + (0.5)*_x18*_x25*_x27 + 3.0*_x19*_x22*c1
        - 8.0*_x21*_x85 + _x25*_x95 - 0.5*_x34*_x85 - _x66*_x86*c1 + _x72*k1*(-12.0*_x1*_x18*_x48 + _x102*_x48
        - 24.0*_x22*_x42*t + 4.0*_x4*_x89 + 24.0*_x48*_x84) + _x75*_x93 + _x77*_x90 + _x80*_x90 + _x87*_x88
        - _x87*_x92 + _x96*_x98))
    d_q_th__phase_td = (_x70*(-_x10*_x11*_x15 + _x100*_x103 + _x101*_x95 + _x11*_x74 + _x11*_x78
        - _x14*_x19*c0 + _x19*_x82 + _x21*_x30 - 0.25*_x22*_x86*c2 + _x25*_x88 + _x25*(_x51*_x53 - _x92)
        - _x27*_x37*p_td + (0.25)*_x30*_x34 + _x72*_x98 + _x75*(_x48*_x53 + _x89) + _x93*_x96*k1))
    return (q_th, d_q_th__t, 1.0, d_q_th__p_td, d_q_th__c0, d_q_th__c1, d_q_th__c2, d_q_th__k0, d_q_th__k1,
        d_q_th__k2, d_q_th__omega0_hat, d_q_th__phase_td)


@njit(cache=True, error_model="numpy")
def gravity_type5_stance_jacobian(x, p, out):
    """Gravity correction type 5 (time-varying momentum): stance outputs and their derivatives with respect to
    the touchdown state and the stiffness.

    Report equations: 46, 47, 48.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol); writes the outputs below into out, in order,
    and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`gravity_type5.gravity_type5_stance`, in its order.

    Writes into out:
        <output>: each output of :func:`gravity_type5.gravity_type5_stance`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 752
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k, g_s, q_r_lo, iterations, tol,) = load(p, 0, 1, 2, 3, 6, 7, 8)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo, iterations, tol,))
            & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0
            > 0.0)) & ((k > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0)
            and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the tangents the loops compute once per direction: _T[row, direction], on the stack
    _T = carray(stack(190), (38, 5))
    # angular momentum and total energy (27) at touchdown
    _x0 = q_r_td**2
    _x1 = _x0*m
    _x2 = _x1*q_thd_td
    p_td = _x2
    _x3 = m*q_r_td
    d_p_td__q_r_td = 2.0*_x3*q_thd_td
    d_p_td__q_thd_td = _x1
    _x4 = k*q_r_td
    _x5 = (0.5)*l0**2
    _x6 = (0.5)*_x0
    _x7 = g_s*m
    _x8 = _x7*math.cos(q_th_td)
    _x9 = q_thd_td**2
    E_td = (0.5)*_x1*_x9 - _x4*l0 + _x5*k + _x6*k + _x8*q_r_td + (0.5)*m*q_rd_td**2
    d_E_td__q_r_td = _x3*_x9 + _x4 + _x8 - k*l0
    d_E_td__q_rd_td = m*q_rd_td
    d_E_td__q_th_td = -_x7*q_r_td*math.sin(q_th_td)
    d_E_td__q_thd_td = _x2
    d_E_td__k = _x5 + _x6 - l0*q_r_td
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], ) = (d_E_td__q_r_td, d_E_td__q_rd_td, d_E_td__q_th_td,
        d_E_td__q_thd_td, d_E_td__k, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], ) = (0.0, 0.0, 0.0, 0.0, 1.0, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], ) = (d_p_td__q_r_td, 0.0, 0.0, d_p_td__q_thd_td, 0.0, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], ) = (1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], ) = (0.0, 1.0, 0.0, 0.0, 0.0, )
    (_T[5, 0], _T[5, 1], _T[5, 2], _T[5, 3], _T[5, 4], ) = (0.0, 0.0, 1.0, 0.0, 0.0, )
    for _j0 in range(5):
        _T[6, _j0] = 0.0
        _T[7, _j0] = 0.0
        _T[8, _j0] = 0.0
        _T[9, _j0] = 0.0
        _T[10, _j0] = 0.0
        _T[11, _j0] = 0.0
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
        _x10 = math.sqrt(15.0)
        _x11 = (0.16666666666666666)*_x10
        i_c0 = (_x11*tau1 - _x11*tau3 + (0.8333333333333334)*tau1 - 0.6666666666666666*tau2
            + (0.8333333333333334)*tau3)
        _pd__0 = _x11 + 0.8333333333333334
        _pd__1 = 0.8333333333333334 - _x11
        _x12 = (1.0/T)
        _x13 = (-0.3333333333333333*_x10*tau1 + (0.3333333333333333)*_x10*tau3 - 3.3333333333333335*tau1
            + (6.666666666666667)*tau2 - 3.3333333333333335*tau3)
        i_c1 = _x12*_x13
        _x14 = _x12**2
        _pd__2 = -_x13*_x14
        _x15 = (0.3333333333333333)*_x12
        _pd__3 = _x15*(-_x10 - 10.0)
        _pd__4 = (6.666666666666667)*_x12
        _pd__5 = _x15*(_x10 - 10.0)
        _x16 = tau1 - 2.0*tau2 + tau3
        _x17 = (3.3333333333333335)*_x14
        i_c2 = _x16*_x17
        _pd__6 = -6.666666666666667*_x12**3*_x16
        _pd__7 = _x17
        _pd__8 = -6.666666666666667*_x14
        _pd__9 = _x17
        # T5.3: omega of the stance-mean momentum
        _x18 = (0.5)*i_c0
        _x19 = T**2
        _x20 = (0.16666666666666666)*_x19
        _x21 = (0.08333333333333333)*T**3
        _x22 = 1.0/(l0**2*m)
        i_omega = _x22*(T*_x18 + _x20*i_c1 + _x21*i_c2 + p_td)
        _pd__10 = _x22*((0.3333333333333333)*T*i_c1 + _x18 + (0.25)*_x19*i_c2)
        _pd__11 = (0.5)*T*_x22
        _pd__12 = _x20*_x22
        _pd__13 = _x21*_x22
        _pd__14 = _x22
        # T5.4-T5.5: radial solution
        _o0 = carray(stack(35), 35)
        _c0 = (type5_solution_jac_q_r_td_q_rd_td_omega_g_eff_r_c_k(q_r_td, q_rd_td, i_omega, g_eff, r_c, m,
            l0, k, _o0))
        if _c0 != STATUS_OK:
            return fail(out, _c0)
        (i_omega0_hat, i_a, i_b, i_phase_td, _j_i_omega0_hat__omega, _j_i_omega0_hat__r_c, _j_i_omega0_hat__k,
            _j_i_a__omega, _j_i_a__g_eff, _j_i_a__r_c, _j_i_a__k, _j_i_b__q_r_td, _j_i_b__q_rd_td,
            _j_i_b__omega, _j_i_b__g_eff, _j_i_b__r_c, _j_i_b__k, _j_i_phase_td__q_r_td,
            _j_i_phase_td__q_rd_td, _j_i_phase_td__omega, _j_i_phase_td__g_eff, _j_i_phase_td__r_c,
            _j_i_phase_td__k,) = (load(_o0, 0, 1, 2, 3, 7, 9, 10, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23,
            24, 25, 26, 27, 28))
        _c1 = geyer_liftoff_phase_jac_a_b(i_a, i_b, l0, q_r_lo)
        if _c1[6] != STATUS_OK:
            return fail(out, _c1[6])
        i_phase_lo = _c1[0]
        _j_i_phase_lo__a = _c1[2]
        _j_i_phase_lo__b = _c1[3]
        # eqs (13)-(14) minus (12); T5.6: the rate factor
        _x23 = (1.0/i_omega0_hat)
        _x24 = -i_phase_td + (1.5)*math.pi
        i_t_bottom = _x23*_x24
        _x25 = _x23**2
        _pd__15 = -_x24*_x25
        _x26 = -_x23
        _pd__16 = _x26
        _x27 = i_phase_lo - i_phase_td
        i_t_stance = _x23*_x27
        _pd__17 = -_x25*_x27
        _pd__18 = _x23
        _pd__19 = _x26
        _x28 = 3.0*i_b**2
        _x29 = 16.0*r_c
        _x30 = r_c**2
        _x31 = 12.0*_x30
        _x32 = _x31 + 8.0*r_c + 2.0
        _x33 = _x28 - _x29*i_a + _x32 + 6.0*i_a**2 - 4.0*i_a
        _x34 = r_c**3
        _x35 = 4.0*_x34
        _x36 = r_c**4
        _x37 = 4.0*r_c + 1.0
        _x38 = 6.0*_x30 + _x35 + _x36 + _x37
        _x39 = (1.0/_x38)
        _x40 = (0.5)*_x39
        i_k0 = _x33*_x40
        _pd__20 = _x40*(-_x29 + 12.0*i_a - 4.0)
        _x41 = _x39*i_b
        _pd__21 = 3.0*_x41
        _x42 = 24.0*r_c + 8.0
        _x43 = _x39**2*(-_x31 - _x35 - 12.0*r_c - 4.0)
        _pd__22 = (0.5)*_x33*_x43 + _x40*(_x42 - 16.0*i_a)
        _x44 = -2.0*_x37 + 6.0*i_a
        i_k1 = _x41*_x44
        _pd__23 = 6.0*_x41
        _pd__24 = _x39*_x44
        _pd__25 = -8.0*_x41 + _x43*_x44*i_b
        _x45 = 8.0*_x34
        _x46 = _x32 + 2.0*_x36 + _x45
        _x47 = (1.0/_x46)
        i_k2 = -_x28*_x47
        _pd__26 = -6.0*_x47*i_b
        _pd__27 = -_x28*_x47**2*(-24.0*_x30 - _x42 - _x45)
        _c2 = (type5_leg_angle_jac_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td((0.5)*i_t_stance*(1.0
            - 0.2*math.sqrt(15.0)), q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat,
            i_phase_td, m, l0))
        i_th1 = _c2[0]
        _j_i_th1__t = _c2[1]
        _j_i_th1__q_th_td = _c2[2]
        _j_i_th1__p_td = _c2[3]
        _j_i_th1__c0 = _c2[4]
        _j_i_th1__c1 = _c2[5]
        _j_i_th1__c2 = _c2[6]
        _j_i_th1__k0 = _c2[7]
        _j_i_th1__k1 = _c2[8]
        _j_i_th1__k2 = _c2[9]
        _j_i_th1__omega0_hat = _c2[10]
        _j_i_th1__phase_td = _c2[11]
        _c3 = (type5_leg_angle_jac_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td((0.5)*i_t_stance,
            q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0))
        i_th2 = _c3[0]
        _j_i_th2__t = _c3[1]
        _j_i_th2__q_th_td = _c3[2]
        _j_i_th2__p_td = _c3[3]
        _j_i_th2__c0 = _c3[4]
        _j_i_th2__c1 = _c3[5]
        _j_i_th2__c2 = _c3[6]
        _j_i_th2__k0 = _c3[7]
        _j_i_th2__k1 = _c3[8]
        _j_i_th2__k2 = _c3[9]
        _j_i_th2__omega0_hat = _c3[10]
        _j_i_th2__phase_td = _c3[11]
        _c4 = (type5_leg_angle_jac_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td((0.5)*i_t_stance*((0.2
            )*math.sqrt(15.0) + 1.0), q_th_td, p_td, i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat,
            i_phase_td, m, l0))
        i_th3 = _c4[0]
        _j_i_th3__t = _c4[1]
        _j_i_th3__q_th_td = _c4[2]
        _j_i_th3__p_td = _c4[3]
        _j_i_th3__c0 = _c4[4]
        _j_i_th3__c1 = _c4[5]
        _j_i_th3__c2 = _c4[6]
        _j_i_th3__k0 = _c4[7]
        _j_i_th3__k1 = _c4[8]
        _j_i_th3__k2 = _c4[9]
        _j_i_th3__omega0_hat = _c4[10]
        _j_i_th3__phase_td = _c4[11]
        # T5.1, T5.4: the torques at the new nodes, g_s <cos q_th>, the mean compression
        _x48 = (0.2)*math.sqrt(15.0)
        _x49 = 1.0 - _x48
        _x50 = (0.5)*i_t_stance
        _x51 = _x50*i_omega0_hat
        _x52 = _x49*_x51 + i_phase_td
        _x53 = math.sin(_x52)
        _x54 = i_a + 1.0
        _x55 = _x53*i_b + _x54
        _x56 = math.sin(i_th1)
        _x57 = l0*m
        _x58 = _x57*g_s
        _x59 = _x56*_x58
        i_tau1 = _x55*_x59
        _pd__28 = _x59
        _pd__29 = _x53*_x59
        _x60 = i_b*math.cos(_x52)
        _x61 = _x59*_x60
        _pd__30 = _x49*_x50*_x61
        _pd__31 = _x61
        _x62 = (0.5)*g_s
        _x63 = _x57*_x62*i_omega0_hat
        _pd__32 = _x49*_x56*_x60*_x63
        _x64 = math.cos(i_th1)
        _pd__33 = _x55*_x58*_x64
        _x65 = _x51 + i_phase_td
        _x66 = math.sin(_x65)
        _x67 = _x54 + _x66*i_b
        _x68 = math.sin(i_th2)
        _x69 = _x68*g_s
        _x70 = _x57*_x69
        i_tau2 = _x67*_x70
        _pd__34 = _x70
        _pd__35 = _x66*_x70
        _x71 = i_b*math.cos(_x65)
        _x72 = _x70*_x71
        _pd__36 = _x50*_x72
        _pd__37 = _x72
        _pd__38 = _x63*_x68*_x71
        _x73 = math.cos(i_th2)
        _pd__39 = _x58*_x67*_x73
        _x74 = _x48 + 1.0
        _x75 = _x51*_x74 + i_phase_td
        _x76 = math.sin(_x75)
        _x77 = _x54 + _x76*i_b
        _x78 = math.sin(i_th3)
        _x79 = _x58*_x78
        i_tau3 = _x77*_x79
        _pd__40 = _x79
        _pd__41 = _x76*_x79
        _x80 = i_b*math.cos(_x75)
        _x81 = _x79*_x80
        _pd__42 = _x50*_x74*_x81
        _pd__43 = _x81
        _pd__44 = _x63*_x74*_x78*_x80
        _x82 = math.cos(i_th3)
        _pd__45 = _x58*_x77*_x82
        i_g_eff = _x62*((0.5555555555555556)*_x64 + (0.8888888888888888)*_x73 + (0.5555555555555556)*_x82)
        _x83 = (0.2777777777777778)*g_s
        _pd__46 = -_x56*_x83
        _pd__47 = -0.4444444444444444*_x69
        _pd__48 = -_x78*_x83
        _x84 = i_phase_lo - i_phase_td
        _x85 = (1.0/_x84)
        _x86 = math.cos(i_phase_lo) - math.cos(i_phase_td)
        _x87 = _x85*_x86
        i_r_c = -_x87*i_b + i_a
        _pd__49 = -_x87
        _x88 = _x85*i_b
        _x89 = _x85**2*_x86*i_b
        _pd__50 = _x88*math.sin(i_phase_lo) + _x89
        _pd__51 = -_x88*math.sin(i_phase_td) - _x89
        # the evaluation's tangents, once per direction
        for _j1 in range(5):
            d_k__j = _T[1, _j1]
            d_p_td__j = _T[2, _j1]
            d_q_r_td__j = _T[3, _j1]
            d_q_rd_td__j = _T[4, _j1]
            d_q_th_td__j = _T[5, _j1]
            d_tau1__j = _T[6, _j1]
            d_tau2__j = _T[7, _j1]
            d_tau3__j = _T[8, _j1]
            d_T__j = _T[9, _j1]
            d_g_eff__j = _T[10, _j1]
            d_r_c__j = _T[11, _j1]
            # T5.1: the torque quadratic through the nodal torques of the previous pass
            d_i_c0__j = _pd__0*d_tau1__j + _pd__1*d_tau3__j - 0.6666666666666666*d_tau2__j
            d_i_c1__j = _pd__2*d_T__j + _pd__3*d_tau1__j + _pd__4*d_tau2__j + _pd__5*d_tau3__j
            d_i_c2__j = _pd__6*d_T__j + _pd__7*d_tau1__j + _pd__8*d_tau2__j + _pd__9*d_tau3__j
            # T5.3: omega of the stance-mean momentum
            d_i_omega__j = (_pd__10*d_T__j + _pd__11*d_i_c0__j + _pd__12*d_i_c1__j + _pd__13*d_i_c2__j
                + _pd__14*d_p_td__j)
            # chain rule through type5_solution
            d_i_omega0_hat__j = (_j_i_omega0_hat__k*d_k__j + _j_i_omega0_hat__omega*d_i_omega__j
                + _j_i_omega0_hat__r_c*d_r_c__j)
            d_i_a__j = (_j_i_a__g_eff*d_g_eff__j + _j_i_a__k*d_k__j + _j_i_a__omega*d_i_omega__j
                + _j_i_a__r_c*d_r_c__j)
            d_i_b__j = (_j_i_b__g_eff*d_g_eff__j + _j_i_b__k*d_k__j + _j_i_b__omega*d_i_omega__j
                + _j_i_b__q_r_td*d_q_r_td__j + _j_i_b__q_rd_td*d_q_rd_td__j + _j_i_b__r_c*d_r_c__j)
            d_i_phase_td__j = (_j_i_phase_td__g_eff*d_g_eff__j + _j_i_phase_td__k*d_k__j
                + _j_i_phase_td__omega*d_i_omega__j + _j_i_phase_td__q_r_td*d_q_r_td__j
                + _j_i_phase_td__q_rd_td*d_q_rd_td__j + _j_i_phase_td__r_c*d_r_c__j)
            # chain rule through geyer_liftoff_phase
            d_i_phase_lo__j = _j_i_phase_lo__a*d_i_a__j + _j_i_phase_lo__b*d_i_b__j
            # eqs (13)-(14) minus (12); T5.6: the rate factor
            d_i_t_bottom__j = _pd__15*d_i_omega0_hat__j + _pd__16*d_i_phase_td__j
            d_i_t_stance__j = _pd__17*d_i_omega0_hat__j + _pd__18*d_i_phase_lo__j + _pd__19*d_i_phase_td__j
            d_i_k0__j = _pd__20*d_i_a__j + _pd__21*d_i_b__j + _pd__22*d_r_c__j
            d_i_k1__j = _pd__23*d_i_a__j + _pd__24*d_i_b__j + _pd__25*d_r_c__j
            d_i_k2__j = _pd__26*d_i_b__j + _pd__27*d_r_c__j
            # chain rule through type5_leg_angle
            d_i_th1__j = (_j_i_th1__c0*d_i_c0__j + _j_i_th1__c1*d_i_c1__j + _j_i_th1__c2*d_i_c2__j
                + _j_i_th1__k0*d_i_k0__j + _j_i_th1__k1*d_i_k1__j + _j_i_th1__k2*d_i_k2__j
                + _j_i_th1__omega0_hat*d_i_omega0_hat__j + _j_i_th1__p_td*d_p_td__j
                + _j_i_th1__phase_td*d_i_phase_td__j + _j_i_th1__q_th_td*d_q_th_td__j
                + _j_i_th1__t*d_i_t_stance__j*(0.5 - 0.1*math.sqrt(15.0)))
            # chain rule through type5_leg_angle
            d_i_th2__j = (_j_i_th2__c0*d_i_c0__j + _j_i_th2__c1*d_i_c1__j + _j_i_th2__c2*d_i_c2__j
                + _j_i_th2__k0*d_i_k0__j + _j_i_th2__k1*d_i_k1__j + _j_i_th2__k2*d_i_k2__j
                + _j_i_th2__omega0_hat*d_i_omega0_hat__j + _j_i_th2__p_td*d_p_td__j
                + _j_i_th2__phase_td*d_i_phase_td__j + _j_i_th2__q_th_td*d_q_th_td__j
                + (0.5)*_j_i_th2__t*d_i_t_stance__j)
            # chain rule through type5_leg_angle
            d_i_th3__j = (_j_i_th3__c0*d_i_c0__j + _j_i_th3__c1*d_i_c1__j + _j_i_th3__c2*d_i_c2__j
                + _j_i_th3__k0*d_i_k0__j + _j_i_th3__k1*d_i_k1__j + _j_i_th3__k2*d_i_k2__j
                + _j_i_th3__omega0_hat*d_i_omega0_hat__j + _j_i_th3__p_td*d_p_td__j
                + _j_i_th3__phase_td*d_i_phase_td__j + _j_i_th3__q_th_td*d_q_th_td__j
                + _j_i_th3__t*d_i_t_stance__j*((0.1)*math.sqrt(15.0) + 0.5))
            # T5.1, T5.4: the torques at the new nodes, g_s <cos q_th>, the mean compression
            d_i_tau1__j = (_pd__28*d_i_a__j + _pd__29*d_i_b__j + _pd__30*d_i_omega0_hat__j
                + _pd__31*d_i_phase_td__j + _pd__32*d_i_t_stance__j + _pd__33*d_i_th1__j)
            d_i_tau2__j = (_pd__34*d_i_a__j + _pd__35*d_i_b__j + _pd__36*d_i_omega0_hat__j
                + _pd__37*d_i_phase_td__j + _pd__38*d_i_t_stance__j + _pd__39*d_i_th2__j)
            d_i_tau3__j = (_pd__40*d_i_a__j + _pd__41*d_i_b__j + _pd__42*d_i_omega0_hat__j
                + _pd__43*d_i_phase_td__j + _pd__44*d_i_t_stance__j + _pd__45*d_i_th3__j)
            d_i_g_eff__j = _pd__46*d_i_th1__j + _pd__47*d_i_th2__j + _pd__48*d_i_th3__j
            d_i_r_c__j = _pd__49*d_i_b__j + _pd__50*d_i_phase_lo__j + _pd__51*d_i_phase_td__j + d_i_a__j
            _T[12, _j1] = d_i_c0__j
            _T[13, _j1] = d_i_c1__j
            _T[14, _j1] = d_i_c2__j
            _T[15, _j1] = d_i_omega0_hat__j
            _T[16, _j1] = d_i_a__j
            _T[17, _j1] = d_i_b__j
            _T[18, _j1] = d_i_phase_td__j
            _T[19, _j1] = d_i_t_bottom__j
            _T[20, _j1] = d_i_t_stance__j
            _T[21, _j1] = d_i_k0__j
            _T[22, _j1] = d_i_k1__j
            _T[23, _j1] = d_i_k2__j
            _T[24, _j1] = d_i_tau1__j
            _T[25, _j1] = d_i_tau2__j
            _T[26, _j1] = d_i_tau3__j
            _T[27, _j1] = d_i_g_eff__j
            _T[28, _j1] = d_i_r_c__j
        if _conv0 or _it0 == _last0:
            break
        # next values
        tau1__next = i_tau1
        tau2__next = i_tau2
        tau3__next = i_tau3
        T__next = i_t_stance
        g_eff__next = i_g_eff
        r_c__next = i_r_c
        # the next state's tangents, once per direction
        for _j2 in range(5):
            d_i_t_stance__j = _T[20, _j2]
            d_i_tau1__j = _T[24, _j2]
            d_i_tau2__j = _T[25, _j2]
            d_i_tau3__j = _T[26, _j2]
            d_i_g_eff__j = _T[27, _j2]
            d_i_r_c__j = _T[28, _j2]
            _T[6, _j2] = d_i_tau1__j
            _T[7, _j2] = d_i_tau2__j
            _T[8, _j2] = d_i_tau3__j
            _T[9, _j2] = d_i_t_stance__j
            _T[10, _j2] = d_i_g_eff__j
            _T[11, _j2] = d_i_r_c__j
        _n0_0 = tau1__next
        _n0_1 = tau2__next
        _n0_2 = tau3__next
        _n0_3 = T__next
        _n0_4 = g_eff__next
        _n0_5 = r_c__next
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
    _c5 = (type5_leg_angle_jac_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td(i_t_bottom, q_th_td, p_td,
        i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0))
    bottom_q_th = _c5[0]
    _j_bottom_q_th__t = _c5[1]
    _j_bottom_q_th__q_th_td = _c5[2]
    _j_bottom_q_th__p_td = _c5[3]
    _j_bottom_q_th__c0 = _c5[4]
    _j_bottom_q_th__c1 = _c5[5]
    _j_bottom_q_th__c2 = _c5[6]
    _j_bottom_q_th__k0 = _c5[7]
    _j_bottom_q_th__k1 = _c5[8]
    _j_bottom_q_th__k2 = _c5[9]
    _j_bottom_q_th__omega0_hat = _c5[10]
    _j_bottom_q_th__phase_td = _c5[11]
    _c6 = (type5_leg_angle_jac_t_q_th_td_p_td_c0_c1_c2_k0_k1_k2_omega0_hat_phase_td(i_t_stance, q_th_td, p_td,
        i_c0, i_c1, i_c2, i_k0, i_k1, i_k2, i_omega0_hat, i_phase_td, m, l0))
    liftoff_q_th = _c6[0]
    _j_liftoff_q_th__t = _c6[1]
    _j_liftoff_q_th__q_th_td = _c6[2]
    _j_liftoff_q_th__p_td = _c6[3]
    _j_liftoff_q_th__c0 = _c6[4]
    _j_liftoff_q_th__c1 = _c6[5]
    _j_liftoff_q_th__c2 = _c6[6]
    _j_liftoff_q_th__k0 = _c6[7]
    _j_liftoff_q_th__k1 = _c6[8]
    _j_liftoff_q_th__k2 = _c6[9]
    _j_liftoff_q_th__omega0_hat = _c6[10]
    _j_liftoff_q_th__phase_td = _c6[11]
    # T5.7: bottom and liftoff states
    t_bottom = i_t_bottom
    t_stance = i_t_stance
    _x90 = i_a - i_b + 1.0
    bottom_q_r = _x90*l0
    _x91 = i_t_bottom**2
    _x92 = (0.5)*_x91
    _x93 = (0.3333333333333333)*i_t_bottom**3
    _x94 = _x92*i_c1 + _x93*i_c2 + i_c0*i_t_bottom + p_td
    _x95 = (1.0/m)
    _x96 = _x95/l0**2
    _x105 = (1.0/_x90)
    _x97 = _x105**2*_x96
    bottom_q_thd = _x94*_x97
    _x98 = 2.0*_x105**3*_x94*_x96
    _pd__52 = -_x98
    _pd__53 = _x98
    _pd__54 = _x97*i_t_bottom
    _pd__55 = _x92*_x97
    _pd__56 = _x93*_x97
    _pd__57 = _x97*(_x91*i_c2 + i_c0 + i_c1*i_t_bottom)
    _pd__58 = _x97
    liftoff_q_r = q_r_lo
    _x99 = i_t_stance**2
    _x100 = (0.5)*_x99
    _x101 = (0.3333333333333333)*i_t_stance**3
    _x102 = _x100*i_c1 + _x101*i_c2 + i_c0*i_t_stance
    P_c = _x102
    _pd__59 = _x100
    _pd__60 = _x101
    _x103 = _x99*i_c2 + i_c0 + i_c1*i_t_stance
    _pd__61 = _x103
    _x104 = _x95/q_r_lo**2
    liftoff_q_thd = _x104*(_x102 + p_td)
    _pd__62 = _x104*i_t_stance
    _pd__63 = _x100*_x104
    _pd__64 = _x101*_x104
    _pd__65 = _x103*_x104
    _pd__66 = _x104
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return fail(out, STATUS_FALL)
    _x106 = (1.0/m)
    _x107 = 2.0*g_s*q_r_lo
    _x108 = _x106*l0**2
    _x109 = q_r_lo**2
    _x110 = _x106*_x109
    _x111 = i_c0*i_t_stance
    _x112 = i_t_stance**2
    _x113 = _x112*i_c1
    _x114 = i_t_stance**3
    _x115 = _x114*i_c2
    _x116 = _x111 + (0.5)*_x113 + (0.3333333333333333)*_x115 + p_td
    _x117 = _x106**2/_x109
    _q_rd_lo_sq = (2.0*E_td*_x106 + 2.0*_x106*k*l0*q_r_lo - _x107*math.cos(liftoff_q_th) - _x108*k - _x110*k
        - _x116**2*_x117)
    _pd__67 = 2.0*_x106
    _x118 = 2.0*i_t_stance
    _x119 = _x116*_x117
    _pd__68 = -_x118*_x119
    _pd__69 = -_x112*_x119
    _pd__70 = -0.6666666666666666*_x114*_x119
    _pd__71 = -_x119*(2.0*_x112*i_c2 + _x118*i_c1 + 2.0*i_c0)
    _pd__72 = 2.0*_x106*l0*q_r_lo - _x108 - _x110
    _pd__73 = _x107*math.sin(liftoff_q_th)
    _pd__74 = -_x117*(2.0*_x111 + _x113 + (0.6666666666666666)*_x115 + 2.0*p_td)
    # q_rd_lo^2 from the energy (27)
    if not ((_q_rd_lo_sq >= 0.0)):
        return fail(out, STATUS_ENERGY_DEFICIT)
    # q_rd_lo from the energy
    _x120 = math.sqrt(_q_rd_lo_sq)
    liftoff_q_rd = _x120
    _pd__75 = (0.5)/_x120
    # their tangents, once per direction
    for _j3 in range(5):
        d_E_td__j = _T[0, _j3]
        d_k__j = _T[1, _j3]
        d_p_td__j = _T[2, _j3]
        d_q_th_td__j = _T[5, _j3]
        d_i_c0__j = _T[12, _j3]
        d_i_c1__j = _T[13, _j3]
        d_i_c2__j = _T[14, _j3]
        d_i_omega0_hat__j = _T[15, _j3]
        d_i_a__j = _T[16, _j3]
        d_i_b__j = _T[17, _j3]
        d_i_phase_td__j = _T[18, _j3]
        d_i_t_bottom__j = _T[19, _j3]
        d_i_t_stance__j = _T[20, _j3]
        d_i_k0__j = _T[21, _j3]
        d_i_k1__j = _T[22, _j3]
        d_i_k2__j = _T[23, _j3]
        # chain rule through type5_leg_angle
        d_bottom_q_th__j = (_j_bottom_q_th__c0*d_i_c0__j + _j_bottom_q_th__c1*d_i_c1__j
            + _j_bottom_q_th__c2*d_i_c2__j + _j_bottom_q_th__k0*d_i_k0__j + _j_bottom_q_th__k1*d_i_k1__j
            + _j_bottom_q_th__k2*d_i_k2__j + _j_bottom_q_th__omega0_hat*d_i_omega0_hat__j
            + _j_bottom_q_th__p_td*d_p_td__j + _j_bottom_q_th__phase_td*d_i_phase_td__j
            + _j_bottom_q_th__q_th_td*d_q_th_td__j + _j_bottom_q_th__t*d_i_t_bottom__j)
        # chain rule through type5_leg_angle
        d_liftoff_q_th__j = (_j_liftoff_q_th__c0*d_i_c0__j + _j_liftoff_q_th__c1*d_i_c1__j
            + _j_liftoff_q_th__c2*d_i_c2__j + _j_liftoff_q_th__k0*d_i_k0__j + _j_liftoff_q_th__k1*d_i_k1__j
            + _j_liftoff_q_th__k2*d_i_k2__j + _j_liftoff_q_th__omega0_hat*d_i_omega0_hat__j
            + _j_liftoff_q_th__p_td*d_p_td__j + _j_liftoff_q_th__phase_td*d_i_phase_td__j
            + _j_liftoff_q_th__q_th_td*d_q_th_td__j + _j_liftoff_q_th__t*d_i_t_stance__j)
        # T5.7: bottom and liftoff states
        d_bottom_q_r__j = d_i_a__j*l0 - d_i_b__j*l0
        d_bottom_q_thd__j = (_pd__52*d_i_a__j + _pd__53*d_i_b__j + _pd__54*d_i_c0__j + _pd__55*d_i_c1__j
            + _pd__56*d_i_c2__j + _pd__57*d_i_t_bottom__j + _pd__58*d_p_td__j)
        d_P_c__j = _pd__59*d_i_c1__j + _pd__60*d_i_c2__j + _pd__61*d_i_t_stance__j + d_i_c0__j*i_t_stance
        d_liftoff_q_thd__j = (_pd__62*d_i_c0__j + _pd__63*d_i_c1__j + _pd__64*d_i_c2__j
            + _pd__65*d_i_t_stance__j + _pd__66*d_p_td__j)
        _d_q_rd_lo_sq__j = (_pd__67*d_E_td__j + _pd__68*d_i_c0__j + _pd__69*d_i_c1__j + _pd__70*d_i_c2__j
            + _pd__71*d_i_t_stance__j + _pd__72*d_k__j + _pd__73*d_liftoff_q_th__j + _pd__74*d_p_td__j)
        # q_rd_lo from the energy
        d_liftoff_q_rd__j = _d_q_rd_lo_sq__j*_pd__75
        _T[29, _j3] = d_bottom_q_th__j
        _T[30, _j3] = d_liftoff_q_th__j
        _T[31, _j3] = d_i_t_bottom__j
        _T[32, _j3] = d_i_t_stance__j
        _T[33, _j3] = d_bottom_q_r__j
        _T[34, _j3] = d_bottom_q_thd__j
        _T[35, _j3] = d_P_c__j
        _T[36, _j3] = d_liftoff_q_thd__j
        _T[37, _j3] = d_liftoff_q_rd__j
    (d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k, ) = (_T[29, 0], _T[29, 1], _T[29, 2], _T[29, 3], _T[29, 4], )
    (d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td,
        d_liftoff_q_th__k, ) = (_T[30, 0], _T[30, 1], _T[30, 2], _T[30, 3], _T[30, 4], )
    (d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k,
        ) = (_T[31, 0], _T[31, 1], _T[31, 2], _T[31, 3], _T[31, 4], )
    (d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k,
        ) = (_T[32, 0], _T[32, 1], _T[32, 2], _T[32, 3], _T[32, 4], )
    (d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_r__k, ) = (_T[33, 0], _T[33, 1], _T[33, 2], _T[33, 3], _T[33, 4], )
    (d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_bottom_q_thd__k, ) = (_T[34, 0], _T[34, 1], _T[34, 2], _T[34, 3], _T[34, 4], )
    (d_P_c__q_r_td, d_P_c__q_rd_td, d_P_c__q_th_td, d_P_c__q_thd_td, d_P_c__k, ) = (_T[35, 0], _T[35, 1],
        _T[35, 2], _T[35, 3], _T[35, 4], )
    (d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td,
        d_liftoff_q_thd__k, ) = (_T[36, 0], _T[36, 1], _T[36, 2], _T[36, 3], _T[36, 4], )
    (d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td,
        d_liftoff_q_rd__k, ) = (_T[37, 0], _T[37, 1], _T[37, 2], _T[37, 3], _T[37, 4], )
    # every output finite, or the inputs were far outside a physical range
    store(out, (t_bottom, t_stance, bottom_q_r, 0.0, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, P_c, passes, d_t_bottom__q_r_td, d_t_bottom__q_rd_td,
        d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k, d_t_stance__q_r_td, d_t_stance__q_rd_td,
        d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td,
        d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k, 0.0, 0.0, 0.0, 0.0, 0.0,
        d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td,
        d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k, 0.0, 0.0, 0.0, 0.0, 0.0, d_liftoff_q_rd__q_r_td,
        d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k,
        d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td,
        d_liftoff_q_th__k, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td,
        d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k, d_P_c__q_r_td, d_P_c__q_rd_td, d_P_c__q_th_td,
        d_P_c__q_thd_td, d_P_c__k, 0.0, 0.0, 0.0, 0.0, 0.0,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type5_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type5_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(9), 9)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type5_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type5_apex_return_jacobian(x, p, out):
    """Apex-return map by Gravity correction type 5 (time-varying momentum), and its derivatives with respect
    to the apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, iterations, tol); writes the outputs below into out, in order,
    and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`gravity_type5.gravity_type5_apex_return`, in its order.

    Writes into out:
        <output>: each output of :func:`gravity_type5.gravity_type5_apex_return`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 244
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
    _o0 = carray(stack(36), 36)
    _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate(b_y_apex, b_xd_apex,
        q_th_td, q_r_td, g_f, ground, retraction_rate, _o0))
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, _o0_1, _o0_2, _o0_3, _o0_4, foot_x, _j_td_q_rd__b_y_apex, _j_td_q_rd__b_xd_apex,
        _j_td_q_rd__q_th_td, _j_td_q_rd__ground, _j_td_q_rd__retraction_rate, _j_td_q_th__b_y_apex,
        _j_td_q_th__q_th_td, _j_td_q_th__ground, _j_td_q_th__retraction_rate, _j_td_q_thd__b_y_apex,
        _j_td_q_thd__b_xd_apex, _j_td_q_thd__q_th_td, _j_td_q_thd__ground, _j_td_q_thd__retraction_rate,
        _o0_26, _o0_28, _o0_29, _o0_30, _j_foot_x__b_y_apex, _j_foot_x__b_xd_apex, _j_foot_x__q_th_td,
        _j_foot_x__ground, _j_foot_x__retraction_rate,) = (load(_o0, 0, 1, 2, 3, 4, 5, 11, 12, 13, 14, 15, 16,
        18, 19, 20, 21, 22, 23, 24, 25, 26, 28, 29, 30, 31, 32, 33, 34, 35))
    # stance: Gravity correction type 5 (time-varying momentum)
    _x1 = carray(stack(4), 4)
    store(_x1, (_o0_0, _o0_1, _o0_2, _o0_3,))
    _o1 = carray(stack(72), 72)
    _c1 = gravity_type5_stance_jacobian(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _o1_10, _o1_11, _j_t_stance__q_rd_td,
        _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _o1_21, _j_liftoff_q_rd__q_rd_td,
        _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k, _j_liftoff_q_th__q_rd_td,
        _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k, _j_P_c__q_rd_td,
        _j_P_c__q_th_td, _j_P_c__q_thd_td, _o1_66,) = (load(_o1, 1, 6, 7, 8, 9, 10, 11, 18, 19, 20, 21, 48,
        49, 50, 51, 53, 54, 55, 56, 58, 59, 60, 61, 63, 64, 65, 66))
    # chain rule through gravity_type5_stance
    d_t_stance__b_y_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_t_stance__q_th_td*_j_td_q_th__b_y_apex + _j_t_stance__q_thd_td*_j_td_q_thd__b_y_apex)
    d_t_stance__b_xd_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_t_stance__q_th_td = (_j_t_stance__q_rd_td*_j_td_q_rd__q_th_td + _j_t_stance__q_th_td*_j_td_q_th__q_th_td
        + _j_t_stance__q_thd_td*_j_td_q_thd__q_th_td)
    d_t_stance__ground = (_j_t_stance__q_rd_td*_j_td_q_rd__ground + _j_t_stance__q_th_td*_j_td_q_th__ground
        + _j_t_stance__q_thd_td*_j_td_q_thd__ground)
    d_t_stance__retraction_rate = (_j_t_stance__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_t_stance__q_th_td*_j_td_q_th__retraction_rate
        + _j_t_stance__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_rd__b_y_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_rd__b_xd_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_rd__ground = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__ground + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_rd__retraction_rate = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_rd__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_th__b_y_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_th__b_xd_apex = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_th__q_th_td = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_th__ground = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__ground + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_th__retraction_rate = (_j_liftoff_q_th__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_th__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_th__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_thd__b_y_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__b_y_apex + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_thd__b_xd_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__q_th_td + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_thd__ground = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__ground + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_thd__retraction_rate = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_thd__q_th_td*_j_td_q_th__retraction_rate
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__retraction_rate)
    d_P_c__b_y_apex = (_j_P_c__q_rd_td*_j_td_q_rd__b_y_apex + _j_P_c__q_th_td*_j_td_q_th__b_y_apex
        + _j_P_c__q_thd_td*_j_td_q_thd__b_y_apex)
    d_P_c__b_xd_apex = _j_P_c__q_rd_td*_j_td_q_rd__b_xd_apex + _j_P_c__q_thd_td*_j_td_q_thd__b_xd_apex
    d_P_c__q_th_td = (_j_P_c__q_rd_td*_j_td_q_rd__q_th_td + _j_P_c__q_th_td*_j_td_q_th__q_th_td
        + _j_P_c__q_thd_td*_j_td_q_thd__q_th_td)
    d_P_c__ground = (_j_P_c__q_rd_td*_j_td_q_rd__ground + _j_P_c__q_th_td*_j_td_q_th__ground
        + _j_P_c__q_thd_td*_j_td_q_thd__ground)
    d_P_c__retraction_rate = (_j_P_c__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_P_c__q_th_td*_j_td_q_th__retraction_rate + _j_P_c__q_thd_td*_j_td_q_thd__retraction_rate)
    # liftoff -> next apex: exact ballistic ascent
    _o2 = carray(stack(20), 20)
    _c2 = (liftoff_to_apex_jac_q_rd_q_th_q_thd(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f,
        direction, _o2))
    if _c2 != STATUS_OK:
        return fail(out, _c2)
    (_o2_0, _o2_1, _o2_2, next_apex_x, _j_apex_height__q_rd, _j_apex_height__q_th, _j_apex_height__q_thd,
        _j_apex_speed__q_rd, _j_apex_speed__q_th, _j_apex_speed__q_thd, _j_t_ascent__q_rd, _j_t_ascent__q_th,
        _j_t_ascent__q_thd, _j_next_apex_x__q_rd, _j_next_apex_x__q_th, _j_next_apex_x__q_thd,) = (load(_o2,
        0, 1, 2, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 17, 18, 19))
    # chain rule through liftoff_to_apex
    d_apex_height__b_y_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_y_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_height__b_xd_apex = (_j_apex_height__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_apex_height__q_th*d_liftoff_q_th__b_xd_apex + _j_apex_height__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_height__q_th_td = (_j_apex_height__q_rd*d_liftoff_q_rd__q_th_td
        + _j_apex_height__q_th*d_liftoff_q_th__q_th_td + _j_apex_height__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_height__ground = (_j_apex_height__q_rd*d_liftoff_q_rd__ground
        + _j_apex_height__q_th*d_liftoff_q_th__ground + _j_apex_height__q_thd*d_liftoff_q_thd__ground)
    d_apex_height__retraction_rate = (_j_apex_height__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_apex_height__q_th*d_liftoff_q_th__retraction_rate
        + _j_apex_height__q_thd*d_liftoff_q_thd__retraction_rate)
    d_apex_height__k = (_j_apex_height__q_rd*_j_liftoff_q_rd__k + _j_apex_height__q_th*_j_liftoff_q_th__k
        + _j_apex_height__q_thd*_j_liftoff_q_thd__k)
    d_apex_speed__b_y_apex = (_j_apex_speed__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_apex_speed__q_th*d_liftoff_q_th__b_y_apex + _j_apex_speed__q_thd*d_liftoff_q_thd__b_y_apex)
    d_apex_speed__b_xd_apex = (_j_apex_speed__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_apex_speed__q_th*d_liftoff_q_th__b_xd_apex + _j_apex_speed__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_apex_speed__q_th_td = (_j_apex_speed__q_rd*d_liftoff_q_rd__q_th_td
        + _j_apex_speed__q_th*d_liftoff_q_th__q_th_td + _j_apex_speed__q_thd*d_liftoff_q_thd__q_th_td)
    d_apex_speed__ground = (_j_apex_speed__q_rd*d_liftoff_q_rd__ground
        + _j_apex_speed__q_th*d_liftoff_q_th__ground + _j_apex_speed__q_thd*d_liftoff_q_thd__ground)
    d_apex_speed__retraction_rate = (_j_apex_speed__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_apex_speed__q_th*d_liftoff_q_th__retraction_rate
        + _j_apex_speed__q_thd*d_liftoff_q_thd__retraction_rate)
    d_apex_speed__k = (_j_apex_speed__q_rd*_j_liftoff_q_rd__k + _j_apex_speed__q_th*_j_liftoff_q_th__k
        + _j_apex_speed__q_thd*_j_liftoff_q_thd__k)
    d_t_ascent__b_y_apex = (_j_t_ascent__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_t_ascent__q_th*d_liftoff_q_th__b_y_apex + _j_t_ascent__q_thd*d_liftoff_q_thd__b_y_apex)
    d_t_ascent__b_xd_apex = (_j_t_ascent__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_t_ascent__q_th*d_liftoff_q_th__b_xd_apex + _j_t_ascent__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_t_ascent__q_th_td = (_j_t_ascent__q_rd*d_liftoff_q_rd__q_th_td
        + _j_t_ascent__q_th*d_liftoff_q_th__q_th_td + _j_t_ascent__q_thd*d_liftoff_q_thd__q_th_td)
    d_t_ascent__ground = (_j_t_ascent__q_rd*d_liftoff_q_rd__ground + _j_t_ascent__q_th*d_liftoff_q_th__ground
        + _j_t_ascent__q_thd*d_liftoff_q_thd__ground)
    d_t_ascent__retraction_rate = (_j_t_ascent__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_t_ascent__q_th*d_liftoff_q_th__retraction_rate
        + _j_t_ascent__q_thd*d_liftoff_q_thd__retraction_rate)
    d_t_ascent__k = (_j_liftoff_q_rd__k*_j_t_ascent__q_rd + _j_liftoff_q_th__k*_j_t_ascent__q_th
        + _j_liftoff_q_thd__k*_j_t_ascent__q_thd)
    d_next_apex_x__b_y_apex = (_j_next_apex_x__q_rd*d_liftoff_q_rd__b_y_apex
        + _j_next_apex_x__q_th*d_liftoff_q_th__b_y_apex + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_y_apex)
    d_next_apex_x__b_xd_apex = (_j_next_apex_x__q_rd*d_liftoff_q_rd__b_xd_apex
        + _j_next_apex_x__q_th*d_liftoff_q_th__b_xd_apex + _j_next_apex_x__q_thd*d_liftoff_q_thd__b_xd_apex)
    d_next_apex_x__q_th_td = (_j_next_apex_x__q_rd*d_liftoff_q_rd__q_th_td
        + _j_next_apex_x__q_th*d_liftoff_q_th__q_th_td + _j_next_apex_x__q_thd*d_liftoff_q_thd__q_th_td)
    d_next_apex_x__ground = (_j_next_apex_x__q_rd*d_liftoff_q_rd__ground
        + _j_next_apex_x__q_th*d_liftoff_q_th__ground + _j_next_apex_x__q_thd*d_liftoff_q_thd__ground)
    d_next_apex_x__retraction_rate = (_j_next_apex_x__q_rd*d_liftoff_q_rd__retraction_rate
        + _j_next_apex_x__q_th*d_liftoff_q_th__retraction_rate
        + _j_next_apex_x__q_thd*d_liftoff_q_thd__retraction_rate)
    d_next_apex_x__k = (_j_liftoff_q_rd__k*_j_next_apex_x__q_rd + _j_liftoff_q_th__k*_j_next_apex_x__q_th
        + _j_liftoff_q_thd__k*_j_next_apex_x__q_thd)
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    d_step_length__b_y_apex = _j_foot_x__b_y_apex + d_next_apex_x__b_y_apex
    d_step_length__b_xd_apex = _j_foot_x__b_xd_apex + d_next_apex_x__b_xd_apex
    d_step_length__q_th_td = _j_foot_x__q_th_td + d_next_apex_x__q_th_td
    d_step_length__ground = _j_foot_x__ground + d_next_apex_x__ground
    d_step_length__retraction_rate = _j_foot_x__retraction_rate + d_next_apex_x__retraction_rate
    foot_y = -b_y_apex + ground
    # derivatives of the outputs
    d_liftoff_q_rd__k = _j_liftoff_q_rd__k
    d_liftoff_q_th__k = _j_liftoff_q_th__k
    d_liftoff_q_thd__k = _j_liftoff_q_thd__k
    d_step_length__k = d_next_apex_x__k
    d_foot_x__b_y_apex = _j_foot_x__b_y_apex
    d_foot_x__b_xd_apex = _j_foot_x__b_xd_apex
    d_foot_x__q_th_td = _j_foot_x__q_th_td
    d_foot_x__ground = _j_foot_x__ground
    d_foot_x__retraction_rate = _j_foot_x__retraction_rate
    d_touchdown_q_th__b_y_apex = _j_td_q_th__b_y_apex
    d_touchdown_q_th__q_th_td = _j_td_q_th__q_th_td
    d_touchdown_q_th__ground = _j_td_q_th__ground
    d_touchdown_q_th__retraction_rate = _j_td_q_th__retraction_rate
    # every output finite, or the inputs were far outside a physical range
    store(out, (_o2_0, _o2_1, _o0_4, _o1_1, _o2_2, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,
        step_length, foot_x, foot_y, _o0_2, _o1_10, _o1_11, d_apex_height__b_y_apex, d_apex_height__b_xd_apex,
        d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__retraction_rate, d_apex_height__k,
        d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground,
        d_apex_speed__retraction_rate, d_apex_speed__k, _o0_26, 0.0, _o0_28, _o0_29, _o0_30, 0.0,
        d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground,
        d_t_stance__retraction_rate, _o1_21, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td,
        d_t_ascent__ground, d_t_ascent__retraction_rate, d_t_ascent__k, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        d_liftoff_q_rd__b_y_apex, d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground,
        d_liftoff_q_rd__retraction_rate, d_liftoff_q_rd__k, d_liftoff_q_th__b_y_apex,
        d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground,
        d_liftoff_q_th__retraction_rate, d_liftoff_q_th__k, d_liftoff_q_thd__b_y_apex,
        d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground,
        d_liftoff_q_thd__retraction_rate, d_liftoff_q_thd__k, d_step_length__b_y_apex,
        d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground,
        d_step_length__retraction_rate, d_step_length__k, d_foot_x__b_y_apex, d_foot_x__b_xd_apex,
        d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__retraction_rate, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0,
        d_touchdown_q_th__b_y_apex, 0.0, d_touchdown_q_th__q_th_td, d_touchdown_q_th__ground,
        d_touchdown_q_th__retraction_rate, 0.0, d_P_c__b_y_apex, d_P_c__b_xd_apex, d_P_c__q_th_td,
        d_P_c__ground, d_P_c__retraction_rate, _o1_66, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type5_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type5_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(9), 9)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type5_apex_return_jacobian(row(X, i), p, row(OUT, i))
