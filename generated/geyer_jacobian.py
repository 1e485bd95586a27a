# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/geyer.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight_jacobian.py sha256:4de4ff5a5b5282af
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module geyer: JVP kernels, and for a map
its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate,
    liftoff_to_apex_jac_q_rd_q_th_q_thd)

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING,
    STATUS_NO_REAL_SOLUTION, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION, STATUS_NO_LIFTOFF, STATUS_FALL,
    STATUS_NUMERICAL_RANGE)

NAN = math.nan
_NAN6 = (NAN,) * 6


@njit(cache=True, error_model="numpy")
def geyer_solution_jac_q_r_td_q_rd_td_q_thd_td_k(q_r_td, q_rd_td, q_thd_td, m, l0, k, g_s, out):
    """Geyer et al.'s radial solution (11) from a touchdown state: omega, omega0_hat, a, b, phase, and the
    derivatives of its outputs with respect to q_r_td, q_rd_td, q_thd_td, k.

    Report equations: 7, 8, 9, 10, 11, 12.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`geyer.geyer_solution`, in its order.

    Writes into out:
        <output>: each output of :func:`geyer.geyer_solution`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_thd_td, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 159
    # eq (7) at touchdown: omega0^2 = k/m, omega = p_th/(m l0^2), rho and its rate
    _x0 = (1.0/m)
    omega0_sq = _x0*k
    d_omega0_sq__k = _x0
    _x3 = (1.0/l0)
    _x1 = _x3**2
    _x2 = _x1*q_r_td**2
    omega = _x2*q_thd_td
    d_omega__q_r_td = 2.0*_x1*q_r_td*q_thd_td
    d_omega__q_thd_td = _x2
    rho_td = _x3*q_r_td - 1.0
    d_rho_td__q_r_td = _x3
    rho_d_td = _x3*q_rd_td
    d_rho_d_td__q_rd_td = _x3
    # stance starts compressing
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # eq (8) at touchdown (Taylor polynomial of Assumption 2): epsilon = 2 E / (m l0^2)
    _x4 = omega**2
    _x5 = 2.0*g_s/l0
    _x6 = rho_td**2
    _x7 = 3.0*_x4 + omega0_sq
    _x8 = -2.0*_x4 + _x5
    epsilon = _x4 + _x5 + _x6*_x7 + _x8*rho_td + rho_d_td**2
    _pd__0 = 6.0*_x6*omega - 4.0*omega*rho_td + 2.0*omega
    d_epsilon__q_r_td = _pd__0*d_omega__q_r_td + d_rho_td__q_r_td*(2.0*_x7*rho_td + _x8)
    d_epsilon__q_rd_td = 2.0*d_rho_d_td__q_rd_td*rho_d_td
    d_epsilon__q_thd_td = _pd__0*d_omega__q_thd_td
    d_epsilon__k = _x6*d_omega0_sq__k
    # eq (9): rho_d^2 = lambda rho^2 + mu rho + nu
    _x9 = omega**2
    lam = -3.0*_x9 - omega0_sq
    _x10 = 6.0*omega
    d_lam__q_r_td = -_x10*d_omega__q_r_td
    d_lam__q_thd_td = -_x10*d_omega__q_thd_td
    _x11 = 2.0*g_s/l0
    mu = -_x11 + 2.0*_x9
    _x12 = 4.0*omega
    d_mu__q_r_td = _x12*d_omega__q_r_td
    d_mu__q_thd_td = _x12*d_omega__q_thd_td
    nu = -_x11 - _x9 + epsilon
    _x13 = 2.0*omega
    d_nu__q_r_td = -_x13*d_omega__q_r_td + d_epsilon__q_r_td
    d_nu__q_thd_td = -_x13*d_omega__q_thd_td + d_epsilon__q_thd_td
    # eq (10)-(11): omega0_hat, a and b^2 of rho = a + b sin(omega0_hat t)
    _x14 = math.sqrt(-lam)
    omega0_hat = _x14
    _x15 = (1.0/lam)
    _x16 = (0.5)*_x15
    _pd__1 = _x14*_x16
    d_omega0_hat__q_r_td = _pd__1*d_lam__q_r_td
    d_omega0_hat__q_thd_td = _pd__1*d_lam__q_thd_td
    d_omega0_hat__k = -_pd__1*d_omega0_sq__k
    a = -_x16*mu
    _x17 = _x15**2
    _x18 = (0.5)*_x17*mu
    _pd__2 = _x18
    _pd__3 = -_x16
    d_a__q_r_td = _pd__2*d_lam__q_r_td + _pd__3*d_mu__q_r_td
    d_a__q_thd_td = _pd__2*d_lam__q_thd_td + _pd__3*d_mu__q_thd_td
    d_a__k = -_pd__2*d_omega0_sq__k
    _x19 = -4.0*lam*nu + mu**2
    b2 = (0.25)*_x17*_x19
    _pd__4 = -0.5*_x15**3*_x19 - _x17*nu
    _pd__5 = _x18
    _pd__6 = -_x15
    d_b2__q_r_td = _pd__4*d_lam__q_r_td + _pd__5*d_mu__q_r_td + _pd__6*d_nu__q_r_td
    d_b2__q_rd_td = _pd__6*d_epsilon__q_rd_td
    d_b2__q_thd_td = _pd__4*d_lam__q_thd_td + _pd__5*d_mu__q_thd_td + _pd__6*d_nu__q_thd_td
    d_b2__k = -_pd__4*d_omega0_sq__k + _pd__6*d_epsilon__k
    # eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0
    if not ((b2 > 0.0)):
        return fail(out, STATUS_NO_REAL_SOLUTION)
    # eq (12): sin(phase) at touchdown
    _x20 = math.sqrt(b2)
    b = _x20
    _x21 = (1.0/_x20)
    _pd__7 = (0.5)*_x21
    d_b__q_r_td = _pd__7*d_b2__q_r_td
    d_b__q_rd_td = _pd__7*d_b2__q_rd_td
    d_b__q_thd_td = _pd__7*d_b2__q_thd_td
    d_b__k = _pd__7*d_b2__k
    _x22 = (1.0/l0)
    _x23 = _x22*q_r_td - a - 1.0
    s_td = _x21*_x23
    _pd__8 = -_x21
    _pd__9 = -_x23/b2
    d_s_td__q_r_td = _pd__8*d_a__q_r_td + _pd__9*d_b__q_r_td + _x21*_x22
    d_s_td__q_rd_td = _pd__9*d_b__q_rd_td
    d_s_td__q_thd_td = _pd__8*d_a__q_thd_td + _pd__9*d_b__q_thd_td
    d_s_td__k = _pd__8*d_a__k + _pd__9*d_b__k
    # the leg collapses: l0 (1 + a - b) <= 0
    if not ((a - b + 1.0 > 0.0)):
        return fail(out, STATUS_FALL)
    # (12) needs |s_td| <= 1
    if not ((abs(s_td) <= 1.0)):
        return fail(out, STATUS_TOUCHDOWN_OUTSIDE_OSCILLATION)
    # eq (12), n = 0: compressing root
    phase_td = math.pi - math.asin(s_td)
    _pd__10 = -1.0/math.sqrt(1.0 - s_td**2)
    d_phase_td__q_r_td = _pd__10*d_s_td__q_r_td
    d_phase_td__q_rd_td = _pd__10*d_s_td__q_rd_td
    d_phase_td__q_thd_td = _pd__10*d_s_td__q_thd_td
    d_phase_td__k = _pd__10*d_s_td__k
    # (internal helper: its callers check that their outputs are finite)
    store(out, (omega, omega0_hat, a, b, phase_td, s_td, d_omega__q_r_td, 0.0, d_omega__q_thd_td, 0.0,
        d_omega0_hat__q_r_td, 0.0, d_omega0_hat__q_thd_td, d_omega0_hat__k, d_a__q_r_td, 0.0, d_a__q_thd_td,
        d_a__k, d_b__q_r_td, d_b__q_rd_td, d_b__q_thd_td, d_b__k, d_phase_td__q_r_td, d_phase_td__q_rd_td,
        d_phase_td__q_thd_td, d_phase_td__k, d_s_td__q_r_td, d_s_td__q_rd_td, d_s_td__q_thd_td, d_s_td__k,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def geyer_liftoff_phase_jac_a_b(a, b, l0, q_r_lo):
    """Geyer et al.'s liftoff phase omega0_hat t_lo, eq (14) with n = 0, and the derivatives of its outputs
    with respect to a, b.

    Report equations: 14.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`geyer.geyer_liftoff_phase`, in its order.

    Returns a tuple:
        <output>: each output of :func:`geyer.geyer_liftoff_phase`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument a, b (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 19
    # eq (14): sin(phase) at liftoff
    _x0 = (1.0/b)
    _x1 = -a - 1.0 + q_r_lo/l0
    s_lo = _x0*_x1
    d_s_lo__a = -_x0
    d_s_lo__b = -_x0**2*_x1
    # eq (14) needs |s_lo| <= 1
    if not ((abs(s_lo) <= 1.0)):
        return _NAN6 + (STATUS_NO_LIFTOFF,)
    # eq (14), n = 0: extending root
    phase_lo = math.asin(s_lo) + 2.0*math.pi
    _pd__0 = (1.0/math.sqrt(1.0 - s_lo**2))
    d_phase_lo__a = _pd__0*d_s_lo__a
    d_phase_lo__b = _pd__0*d_s_lo__b
    # (internal helper: its callers check that their outputs are finite)
    return (phase_lo, s_lo, d_phase_lo__a, d_phase_lo__b, d_s_lo__a, d_s_lo__b, STATUS_OK)


@njit(cache=True, error_model="numpy", inline=into_rows)
def geyer_stance_jacobian(x, p, out):
    """Geyer et al.'s approximate stance map: stance outputs and their derivatives with respect to the
    touchdown state and the stiffness.

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`geyer.geyer_stance`, in its order.

    Writes into out:
        <output>: each output of :func:`geyer.geyer_stance`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 340
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k, g_s, q_r_lo,) = load(p, 0, 1, 2, 3, 6)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k, g_s, q_r_lo,)) & ((q_r_td <= l0)
            and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k > 0.0))
            & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # eqs (7)-(12): Geyer et al.'s radial solution from the touchdown state
    _o0 = carray(stack(30), 30)
    _c0 = geyer_solution_jac_q_r_td_q_rd_td_q_thd_td_k(q_r_td, q_rd_td, q_thd_td, m, l0, k, g_s, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (omega, omega0_hat, a, b, phase_td, s_td, _j_omega__q_r_td, _j_omega__q_thd_td, _j_omega0_hat__q_r_td,
        _j_omega0_hat__q_thd_td, _j_omega0_hat__k, _j_a__q_r_td, _j_a__q_thd_td, _j_a__k, _j_b__q_r_td,
        _j_b__q_rd_td, _j_b__q_thd_td, _j_b__k, _j_phase_td__q_r_td, _j_phase_td__q_rd_td,
        _j_phase_td__q_thd_td, _j_phase_td__k, _j_s_td__q_r_td, _j_s_td__q_rd_td, _j_s_td__q_thd_td,
        _j_s_td__k,) = (load(_o0, 0, 1, 2, 3, 4, 5, 6, 8, 10, 12, 13, 14, 16, 17, 18, 19, 20, 21, 22, 23, 24,
        25, 26, 27, 28, 29))
    _c1 = geyer_liftoff_phase_jac_a_b(a, b, l0, q_r_lo)
    if _c1[6] != STATUS_OK:
        return fail(out, _c1[6])
    phase_lo = _c1[0]
    s_lo = _c1[1]
    _j_phase_lo__a = _c1[2]
    _j_phase_lo__b = _c1[3]
    _j_s_lo__a = _c1[4]
    _j_s_lo__b = _c1[5]
    # chain rule through geyer_liftoff_phase
    d_phase_lo__q_r_td = _j_a__q_r_td*_j_phase_lo__a + _j_b__q_r_td*_j_phase_lo__b
    d_phase_lo__q_rd_td = _j_b__q_rd_td*_j_phase_lo__b
    d_phase_lo__q_thd_td = _j_a__q_thd_td*_j_phase_lo__a + _j_b__q_thd_td*_j_phase_lo__b
    d_phase_lo__k = _j_a__k*_j_phase_lo__a + _j_b__k*_j_phase_lo__b
    d_s_lo__q_r_td = _j_a__q_r_td*_j_s_lo__a + _j_b__q_r_td*_j_s_lo__b
    d_s_lo__q_rd_td = _j_b__q_rd_td*_j_s_lo__b
    d_s_lo__q_thd_td = _j_a__q_thd_td*_j_s_lo__a + _j_b__q_thd_td*_j_s_lo__b
    d_s_lo__k = _j_a__k*_j_s_lo__a + _j_b__k*_j_s_lo__b
    # eqs (13)-(14) minus (12), (11), (19), (17) at the bottom and at liftoff
    _x0 = (1.0/omega0_hat)
    _x1 = -phase_td + (1.5)*math.pi
    t_bottom = _x0*_x1
    _x2 = _x0**2
    _pd__0 = -_x1*_x2
    _x3 = -_x0
    _pd__1 = _x3
    d_t_bottom__q_r_td = _j_omega0_hat__q_r_td*_pd__0 + _j_phase_td__q_r_td*_pd__1
    d_t_bottom__q_rd_td = _j_phase_td__q_rd_td*_pd__1
    d_t_bottom__q_thd_td = _j_omega0_hat__q_thd_td*_pd__0 + _j_phase_td__q_thd_td*_pd__1
    d_t_bottom__k = _j_omega0_hat__k*_pd__0 + _j_phase_td__k*_pd__1
    _x4 = phase_lo - phase_td
    t_stance = _x0*_x4
    _pd__2 = -_x2*_x4
    _pd__3 = _x0
    _pd__4 = _x3
    d_t_stance__q_r_td = _j_omega0_hat__q_r_td*_pd__2 + _j_phase_td__q_r_td*_pd__4 + _pd__3*d_phase_lo__q_r_td
    d_t_stance__q_rd_td = _j_phase_td__q_rd_td*_pd__4 + _pd__3*d_phase_lo__q_rd_td
    d_t_stance__q_thd_td = (_j_omega0_hat__q_thd_td*_pd__2 + _j_phase_td__q_thd_td*_pd__4
        + _pd__3*d_phase_lo__q_thd_td)
    d_t_stance__k = _j_omega0_hat__k*_pd__2 + _j_phase_td__k*_pd__4 + _pd__3*d_phase_lo__k
    _x5 = a + 1.0
    _x6 = _x5 - b
    bottom_q_r = _x6*l0
    d_bottom_q_r__q_r_td = _j_a__q_r_td*l0 - _j_b__q_r_td*l0
    d_bottom_q_r__q_rd_td = -_j_b__q_rd_td*l0
    d_bottom_q_r__q_thd_td = _j_a__q_thd_td*l0 - _j_b__q_thd_td*l0
    d_bottom_q_r__k = _j_a__k*l0 - _j_b__k*l0
    _x7 = (1.5)*math.pi
    _x8 = _x0*omega
    _x9 = 3.0*math.pi
    _x10 = _x8*_x9
    _x11 = _x0*phase_td
    _x12 = _x11*a
    _x13 = math.sqrt(1.0 - s_td**2)
    _x14 = _x13*b
    _x15 = _x0*_x14
    _x16 = 2.0*omega
    _x17 = -_x11*omega + _x16*(_x12 + _x15) + q_th_td
    bottom_q_th = -_x10*a + _x17 + _x7*_x8
    _pd__5 = -_x10 + _x11*_x16
    _x18 = 2.0*_x8
    _x19 = _x13*_x18
    _pd__6 = _x19
    _x20 = _x9*a
    _x21 = -_x11 + 2.0*_x12 + 2.0*_x15
    _pd__7 = -_x0*_x20 + _x0*_x7 + _x21
    _x22 = _x2*phase_td
    _x23 = _x2*omega
    _x24 = -_x14*_x2 - _x22*a
    _pd__8 = _x16*_x24 + _x20*_x23 + _x22*omega - _x23*_x7
    _x25 = _x18*a - _x8
    _pd__9 = _x25
    _x26 = -_x18*b*s_td/_x13
    _pd__10 = _x26
    d_bottom_q_th__q_r_td = (_j_a__q_r_td*_pd__5 + _j_b__q_r_td*_pd__6 + _j_omega0_hat__q_r_td*_pd__8
        + _j_omega__q_r_td*_pd__7 + _j_phase_td__q_r_td*_pd__9 + _j_s_td__q_r_td*_pd__10)
    d_bottom_q_th__q_rd_td = _j_b__q_rd_td*_pd__6 + _j_phase_td__q_rd_td*_pd__9 + _j_s_td__q_rd_td*_pd__10
    d_bottom_q_th__q_thd_td = (_j_a__q_thd_td*_pd__5 + _j_b__q_thd_td*_pd__6 + _j_omega0_hat__q_thd_td*_pd__8
        + _j_omega__q_thd_td*_pd__7 + _j_phase_td__q_thd_td*_pd__9 + _j_s_td__q_thd_td*_pd__10)
    d_bottom_q_th__k = (_j_a__k*_pd__5 + _j_b__k*_pd__6 + _j_omega0_hat__k*_pd__8 + _j_phase_td__k*_pd__9
        + _j_s_td__k*_pd__10)
    _x43 = (1.0/_x6)
    _x27 = _x43**2
    bottom_q_thd = _x27*omega
    _x28 = _x16*_x43**3
    _pd__11 = -_x28
    _pd__12 = _x28
    _pd__13 = _x27
    d_bottom_q_thd__q_r_td = _j_a__q_r_td*_pd__11 + _j_b__q_r_td*_pd__12 + _j_omega__q_r_td*_pd__13
    d_bottom_q_thd__q_rd_td = _j_b__q_rd_td*_pd__12
    d_bottom_q_thd__q_thd_td = _j_a__q_thd_td*_pd__11 + _j_b__q_thd_td*_pd__12 + _j_omega__q_thd_td*_pd__13
    d_bottom_q_thd__k = _j_a__k*_pd__11 + _j_b__k*_pd__12
    liftoff_q_r = q_r_lo
    _x29 = math.sqrt(1.0 - s_lo**2)
    _x30 = _x29*l0
    _x31 = _x30*omega0_hat
    liftoff_q_rd = _x31*b
    _pd__14 = _x31
    _pd__15 = _x30*b
    _x32 = b*s_lo
    _x33 = _x32/_x29
    _pd__16 = -_x33*l0*omega0_hat
    d_liftoff_q_rd__q_r_td = _j_b__q_r_td*_pd__14 + _j_omega0_hat__q_r_td*_pd__15 + _pd__16*d_s_lo__q_r_td
    d_liftoff_q_rd__q_rd_td = _j_b__q_rd_td*_pd__14 + _pd__16*d_s_lo__q_rd_td
    d_liftoff_q_rd__q_thd_td = (_j_b__q_thd_td*_pd__14 + _j_omega0_hat__q_thd_td*_pd__15
        + _pd__16*d_s_lo__q_thd_td)
    d_liftoff_q_rd__k = _j_b__k*_pd__14 + _j_omega0_hat__k*_pd__15 + _pd__16*d_s_lo__k
    _x34 = _x0*phase_lo
    _x35 = _x34*a
    _x36 = _x0*_x29*b
    _x37 = _x8*phase_lo
    liftoff_q_th = -_x16*(_x35 - _x36) + _x17 + _x37
    _pd__17 = 2.0*_x0*omega*phase_td - 2.0*_x37
    _pd__18 = _x18*_x29 + _x19
    _pd__19 = _x21 + _x34 - 2.0*_x35 + 2.0*_x36
    _x38 = _x2*phase_lo
    _pd__20 = -_x16*(_x2*_x29*b - _x38*a) + _x2*omega*phase_td + 2.0*_x24*omega - _x38*omega
    _pd__21 = -_x25
    _pd__22 = _x25
    _pd__23 = -_x18*_x33
    _pd__24 = _x26
    d_liftoff_q_th__q_r_td = (_j_a__q_r_td*_pd__17 + _j_b__q_r_td*_pd__18 + _j_omega0_hat__q_r_td*_pd__20
        + _j_omega__q_r_td*_pd__19 + _j_phase_td__q_r_td*_pd__22 + _j_s_td__q_r_td*_pd__24
        + _pd__21*d_phase_lo__q_r_td + _pd__23*d_s_lo__q_r_td)
    d_liftoff_q_th__q_rd_td = (_j_b__q_rd_td*_pd__18 + _j_phase_td__q_rd_td*_pd__22 + _j_s_td__q_rd_td*_pd__24
        + _pd__21*d_phase_lo__q_rd_td + _pd__23*d_s_lo__q_rd_td)
    d_liftoff_q_th__q_thd_td = (_j_a__q_thd_td*_pd__17 + _j_b__q_thd_td*_pd__18
        + _j_omega0_hat__q_thd_td*_pd__20 + _j_omega__q_thd_td*_pd__19 + _j_phase_td__q_thd_td*_pd__22
        + _j_s_td__q_thd_td*_pd__24 + _pd__21*d_phase_lo__q_thd_td + _pd__23*d_s_lo__q_thd_td)
    d_liftoff_q_th__k = (_j_a__k*_pd__17 + _j_b__k*_pd__18 + _j_omega0_hat__k*_pd__20 + _j_phase_td__k*_pd__22
        + _j_s_td__k*_pd__24 + _pd__21*d_phase_lo__k + _pd__23*d_s_lo__k)
    _x39 = _x32 + _x5
    _x42 = (1.0/_x39)
    _x40 = _x42**2
    liftoff_q_thd = _x40*omega
    _x41 = _x16*_x42**3
    _pd__25 = -_x41
    _pd__26 = -_x41*s_lo
    _pd__27 = _x40
    _pd__28 = -_x41*b
    d_liftoff_q_thd__q_r_td = (_j_a__q_r_td*_pd__25 + _j_b__q_r_td*_pd__26 + _j_omega__q_r_td*_pd__27
        + _pd__28*d_s_lo__q_r_td)
    d_liftoff_q_thd__q_rd_td = _j_b__q_rd_td*_pd__26 + _pd__28*d_s_lo__q_rd_td
    d_liftoff_q_thd__q_thd_td = (_j_a__q_thd_td*_pd__25 + _j_b__q_thd_td*_pd__26 + _j_omega__q_thd_td*_pd__27
        + _pd__28*d_s_lo__q_thd_td)
    d_liftoff_q_thd__k = _j_a__k*_pd__25 + _j_b__k*_pd__26 + _pd__28*d_s_lo__k
    # the leg stays above horizontal
    if not ((abs(liftoff_q_th) < (0.5)*math.pi)):
        return fail(out, STATUS_FALL)
    # every output finite, or the inputs were far outside a physical range
    store(out, (t_bottom, t_stance, bottom_q_r, 0.0, bottom_q_th, bottom_q_thd, liftoff_q_r, liftoff_q_rd,
        liftoff_q_th, liftoff_q_thd, d_t_bottom__q_r_td, d_t_bottom__q_rd_td, 0.0, d_t_bottom__q_thd_td,
        d_t_bottom__k, d_t_stance__q_r_td, d_t_stance__q_rd_td, 0.0, d_t_stance__q_thd_td, d_t_stance__k,
        d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, 0.0, d_bottom_q_r__q_thd_td, d_bottom_q_r__k, 0.0, 0.0,
        0.0, 0.0, 0.0, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, 1.0, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, 0.0, d_bottom_q_thd__q_thd_td,
        d_bottom_q_thd__k, 0.0, 0.0, 0.0, 0.0, 0.0, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, 0.0,
        d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, 1.0,
        d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, 0.0,
        d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline=into_rows)
def geyer_apex_return_jacobian(x, p, out):
    """Apex-return map by Geyer et al.'s approximate stance map, and its derivatives with respect to the apex,
    the touchdown angle and the stiffness.

    Report equations: 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`geyer.geyer_apex_return`, in its order.

    Writes into out:
        <output>: each output of :func:`geyer.geyer_apex_return`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 197
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
    # stance: Geyer et al.'s approximate stance map
    _x1 = carray(stack(4), 4)
    store(_x1, (_o0_0, _o0_1, _o0_2, _o0_3,))
    _o1 = carray(stack(60), 60)
    _c1 = geyer_stance_jacobian(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _j_t_stance__q_rd_td,
        _j_t_stance__q_thd_td, _o1_19, _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_thd_td,
        _j_liftoff_q_rd__k, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_th__k, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k,
        ) = (load(_o1, 1, 6, 7, 8, 9, 16, 18, 19, 46, 48, 49, 51, 52, 53, 54, 56, 58, 59))
    # chain rule through geyer_stance
    d_t_stance__b_y_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_y_apex)
    d_t_stance__b_xd_apex = (_j_t_stance__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_t_stance__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_t_stance__q_th_td = (_j_t_stance__q_rd_td*_j_td_q_rd__q_th_td
        + _j_t_stance__q_thd_td*_j_td_q_thd__q_th_td)
    d_t_stance__ground = _j_t_stance__q_rd_td*_j_td_q_rd__ground + _j_t_stance__q_thd_td*_j_td_q_thd__ground
    d_t_stance__retraction_rate = (_j_t_stance__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_t_stance__q_thd_td*_j_td_q_thd__retraction_rate)
    d_liftoff_q_rd__b_y_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_rd__b_xd_apex = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_rd__q_th_td = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_rd__ground = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_rd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_rd__retraction_rate = (_j_liftoff_q_rd__q_rd_td*_j_td_q_rd__retraction_rate
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
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_y_apex)
    d_liftoff_q_thd__b_xd_apex = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_liftoff_q_thd__q_th_td = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__q_th_td
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__q_th_td)
    d_liftoff_q_thd__ground = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__ground
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__ground)
    d_liftoff_q_thd__retraction_rate = (_j_liftoff_q_thd__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_liftoff_q_thd__q_thd_td*_j_td_q_thd__retraction_rate)
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
        step_length, foot_x, foot_y, _o0_2, d_apex_height__b_y_apex, d_apex_height__b_xd_apex,
        d_apex_height__q_th_td, d_apex_height__ground, d_apex_height__retraction_rate, d_apex_height__k,
        d_apex_speed__b_y_apex, d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground,
        d_apex_speed__retraction_rate, d_apex_speed__k, _o0_26, 0.0, _o0_28, _o0_29, _o0_30, 0.0,
        d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground,
        d_t_stance__retraction_rate, _o1_19, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td,
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
        d_touchdown_q_th__retraction_rate, 0.0,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_apex_return_jacobian(row(X, i), p, row(OUT, i))
