# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/gravity.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight_jacobian.py sha256:4de4ff5a5b5282af
#   geyer_jacobian.py sha256:a1c9347d955c37d0
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module gravity: JVP kernels, and for a map
its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate,
    liftoff_to_apex_jac_q_rd_q_th_q_thd)
from .geyer_jacobian import geyer_liftoff_phase_jac_a_b, geyer_solution_jac_q_r_td_q_rd_td_q_thd_td_k

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_FALL, STATUS_NUMERICAL_RANGE,
    STATUS_NOT_CONVERGED, STATUS_ENERGY_DEFICIT)

NAN = math.nan
_NAN14 = (NAN,) * 14


@njit(cache=True, error_model="numpy")
def gravity_impulse_type0_jac13_8638ac(_a):
    """Type 0's stance impulse P_c of the trajectory (report section 4.1), and the derivatives of its outputs
    with respect to q_r_td, q_rd_td, q_th_td, i_a, i_b, i_bottom_q_r, i_bottom_q_th, i_liftoff_q_th,
    i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance.

    Report equations: 49, 51.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`gravity.gravity_impulse_type0`, in its order.

    Returns a tuple:
        <output>: each output of :func:`gravity.gravity_impulse_type0`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, i_a, i_b, i_bottom_q_r, i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td,
            i_q_thd_eff, i_t_bottom, i_t_stance (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 41
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # eq (48) with 2 or 3 samples
    if samples == 2.0:
        _x0 = g_s*l0*m
        _x1 = _x0*math.sin(i_liftoff_q_th)
        _x2 = _x0*math.sin(q_th_td)
        _x3 = (0.5)*i_t_stance
        i_P_new = _x3*(_x1 + _x2)
        _x4 = _x0*_x3
        d_i_P_new__q_th_td = _x4*math.cos(q_th_td)
        d_i_P_new__i_liftoff_q_th = _x4*math.cos(i_liftoff_q_th)
        d_i_P_new__i_t_stance = (0.5)*_x1 + (0.5)*_x2
        # tangents as every branch names them
        d_i_P_new__i_bottom_q_th = 0.0
    elif samples == 3.0:
        _x5 = g_s*l0*m
        _x6 = _x5*math.sin(i_bottom_q_th)
        _x7 = _x5*math.sin(i_liftoff_q_th)
        _x8 = _x5*math.sin(q_th_td)
        _x9 = (0.3333333333333333)*i_t_stance
        i_P_new = _x9*(_x6 + _x7 + _x8)
        _x10 = _x5*_x9
        d_i_P_new__q_th_td = _x10*math.cos(q_th_td)
        d_i_P_new__i_bottom_q_th = _x10*math.cos(i_bottom_q_th)
        d_i_P_new__i_liftoff_q_th = _x10*math.cos(i_liftoff_q_th)
        d_i_P_new__i_t_stance = (0.3333333333333333)*_x6 + (0.3333333333333333)*_x7 + (0.3333333333333333)*_x8
    else:
        return _NAN14 + (STATUS_INVALID_INPUT,)
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new, 0.0, 0.0, d_i_P_new__q_th_td, 0.0, 0.0, 0.0, d_i_P_new__i_bottom_q_th,
        d_i_P_new__i_liftoff_q_th, 0.0, 0.0, 0.0, 0.0, d_i_P_new__i_t_stance, STATUS_OK)


@njit(cache=True, error_model="numpy", inline="always")
def gravity_stance_jacobian_shared(x, p, out, gravity_impulse_jac13):
    """Gravity correction type 0 (leg length l0): stance outputs and their derivatives with respect to the
    touchdown state and the stiffness.

    Report equations: 46, 47, 48, 49, 50, 51.

    The body that 5 kernels share, each passing the kernel it calls as gravity_impulse_jac13
    (derive/share.py): gravity_{type0_stance_jacobian, type1_stance_jacobian,
    type2_stance_jacobian, type3_stance_jacobian, type4_stance_jacobian}.

    Arguments, returns and status: those of the kernels, then gravity_impulse_jac13.
    """
    # Total ops: 410
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
    # the tangents the loops compute once per direction: _T[row, direction], on the stack
    _T = carray(stack(120), (24, 5))
    # leg_length eq21/eq23 need q_r_td = l0
    if not ((leg_length == 0.0) or (abs(l0 - q_r_td) <= 1e-09*l0)):
        return fail(out, STATUS_INVALID_INPUT)
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
    # trajectory momentum p_td + share P_c: the stance mean (P_c/2) or the report's
    if reading == 0.0:
        share = 0.5
        ramp = 1.0
    elif reading == 1.0:
        share = 1.0
        ramp = 0.0
    else:
        return fail(out, STATUS_INVALID_INPUT)
    (_T[0, 0], _T[0, 1], _T[0, 2], _T[0, 3], _T[0, 4], ) = (0.0, 0.0, 0.0, 0.0, 1.0, )
    (_T[1, 0], _T[1, 1], _T[1, 2], _T[1, 3], _T[1, 4], ) = (d_p_td__q_r_td, 0.0, 0.0, d_p_td__q_thd_td, 0.0, )
    (_T[2, 0], _T[2, 1], _T[2, 2], _T[2, 3], _T[2, 4], ) = (1.0, 0.0, 0.0, 0.0, 0.0, )
    (_T[3, 0], _T[3, 1], _T[3, 2], _T[3, 3], _T[3, 4], ) = (0.0, 1.0, 0.0, 0.0, 0.0, )
    (_T[4, 0], _T[4, 1], _T[4, 2], _T[4, 3], _T[4, 4], ) = (0.0, 0.0, 1.0, 0.0, 0.0, )
    for _j0 in range(5):
        _T[5, _j0] = 0.0
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
        _x10 = P_c*share + p_td
        _x11 = (1.0/m)
        _x13 = (1.0/q_r_td)
        _x12 = _x11*_x13**2
        i_q_thd_eff = _x10*_x12
        _pd__0 = _x12*share
        _pd__1 = _x12
        _pd__2 = -2.0*_x10*_x11*_x13**3
        # eqs (7)-(12): Geyer et al.'s radial solution from the touchdown state
        _o0 = carray(stack(30), 30)
        _c0 = geyer_solution_jac_q_r_td_q_rd_td_q_thd_td_k(q_r_td, q_rd_td, i_q_thd_eff, m, l0, k, g_s, _o0)
        if _c0 != STATUS_OK:
            return fail(out, _c0)
        (i_omega, i_omega0_hat, i_a, i_b, i_phase_td, i_s_td, _j_i_omega__q_r_td, _j_i_omega__q_thd_td,
            _j_i_omega0_hat__q_r_td, _j_i_omega0_hat__q_thd_td, _j_i_omega0_hat__k, _j_i_a__q_r_td,
            _j_i_a__q_thd_td, _j_i_a__k, _j_i_b__q_r_td, _j_i_b__q_rd_td, _j_i_b__q_thd_td, _j_i_b__k,
            _j_i_phase_td__q_r_td, _j_i_phase_td__q_rd_td, _j_i_phase_td__q_thd_td, _j_i_phase_td__k,
            _j_i_s_td__q_r_td, _j_i_s_td__q_rd_td, _j_i_s_td__q_thd_td, _j_i_s_td__k,) = (load(_o0, 0, 1, 2,
            3, 4, 5, 6, 8, 10, 12, 13, 14, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29))
        _c1 = geyer_liftoff_phase_jac_a_b(i_a, i_b, l0, q_r_lo)
        if _c1[6] != STATUS_OK:
            return fail(out, _c1[6])
        i_phase_lo = _c1[0]
        i_s_lo = _c1[1]
        _j_i_phase_lo__a = _c1[2]
        _j_i_phase_lo__b = _c1[3]
        _j_i_s_lo__a = _c1[4]
        _j_i_s_lo__b = _c1[5]
        # eqs (13)-(14) minus (12), (11), (19), (17) at the bottom and at liftoff
        _x14 = (1.0/i_omega0_hat)
        _x15 = -i_phase_td + (1.5)*math.pi
        i_t_bottom = _x14*_x15
        _x16 = _x14**2
        _pd__3 = -_x15*_x16
        _x17 = -_x14
        _pd__4 = _x17
        _x18 = i_phase_lo - i_phase_td
        i_t_stance = _x14*_x18
        _pd__5 = -_x16*_x18
        _pd__6 = _x14
        _pd__7 = _x17
        i_bottom_q_r = l0*(i_a - i_b + 1.0)
        _x19 = (1.5)*math.pi
        _x20 = _x14*i_omega
        _x21 = 3.0*math.pi
        _x22 = _x20*_x21
        _x23 = _x14*i_phase_td
        _x24 = _x23*i_a
        _x25 = math.sqrt(1.0 - i_s_td**2)
        _x26 = _x25*i_b
        _x27 = _x14*_x26
        _x28 = 2.0*i_omega
        _x29 = -_x23*i_omega + _x28*(_x24 + _x27) + q_th_td
        i_bottom_q_th = _x19*_x20 - _x22*i_a + _x29
        _pd__8 = -_x22 + _x23*_x28
        _x30 = 2.0*_x20
        _x31 = _x25*_x30
        _pd__9 = _x31
        _x32 = _x21*i_a
        _x33 = -_x23 + 2.0*_x24 + 2.0*_x27
        _pd__10 = _x14*_x19 - _x14*_x32 + _x33
        _x34 = _x16*i_phase_td
        _x35 = _x16*i_omega
        _x36 = -_x16*_x26 - _x34*i_a
        _pd__11 = -_x19*_x35 + _x28*_x36 + _x32*_x35 + _x34*i_omega
        _x37 = -_x20 + _x30*i_a
        _pd__12 = _x37
        _x38 = -_x30*i_b*i_s_td/_x25
        _pd__13 = _x38
        _x39 = math.sqrt(1.0 - i_s_lo**2)
        _x40 = _x39*l0
        _x41 = _x40*i_omega0_hat
        i_liftoff_q_rd = _x41*i_b
        _pd__17 = _x41
        _pd__18 = _x40*i_b
        _x42 = i_b*i_s_lo/_x39
        _pd__19 = -_x42*i_omega0_hat*l0
        _x43 = _x14*i_phase_lo
        _x44 = _x43*i_a
        _x45 = _x14*_x39*i_b
        _x46 = _x20*i_phase_lo
        i_liftoff_q_th = -_x28*(_x44 - _x45) + _x29 + _x46
        _pd__20 = 2.0*_x14*i_omega*i_phase_td - 2.0*_x46
        _pd__21 = _x30*_x39 + _x31
        _pd__22 = _x33 + _x43 - 2.0*_x44 + 2.0*_x45
        _x47 = _x16*i_phase_lo
        _pd__23 = _x16*i_omega*i_phase_td - _x28*(_x16*_x39*i_b - _x47*i_a) + 2.0*_x36*i_omega - _x47*i_omega
        _pd__24 = -_x37
        _pd__25 = _x37
        _pd__26 = -_x30*_x42
        _pd__27 = _x38
        # the leg stays above horizontal
        if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
            return fail(out, STATUS_FALL)
        # the evaluation's tangents, once per direction
        for _j1 in range(5):
            d_k__j = _T[0, _j1]
            d_p_td__j = _T[1, _j1]
            d_q_r_td__j = _T[2, _j1]
            d_q_rd_td__j = _T[3, _j1]
            d_q_th_td__j = _T[4, _j1]
            d_P_c__j = _T[5, _j1]
            # effective touchdown rate
            d_i_q_thd_eff__j = _pd__0*d_P_c__j + _pd__1*d_p_td__j + _pd__2*d_q_r_td__j
            # chain rule through geyer_solution
            d_i_omega__j = _j_i_omega__q_r_td*d_q_r_td__j + _j_i_omega__q_thd_td*d_i_q_thd_eff__j
            d_i_omega0_hat__j = (_j_i_omega0_hat__k*d_k__j + _j_i_omega0_hat__q_r_td*d_q_r_td__j
                + _j_i_omega0_hat__q_thd_td*d_i_q_thd_eff__j)
            d_i_a__j = _j_i_a__k*d_k__j + _j_i_a__q_r_td*d_q_r_td__j + _j_i_a__q_thd_td*d_i_q_thd_eff__j
            d_i_b__j = (_j_i_b__k*d_k__j + _j_i_b__q_r_td*d_q_r_td__j + _j_i_b__q_rd_td*d_q_rd_td__j
                + _j_i_b__q_thd_td*d_i_q_thd_eff__j)
            d_i_phase_td__j = (_j_i_phase_td__k*d_k__j + _j_i_phase_td__q_r_td*d_q_r_td__j
                + _j_i_phase_td__q_rd_td*d_q_rd_td__j + _j_i_phase_td__q_thd_td*d_i_q_thd_eff__j)
            d_i_s_td__j = (_j_i_s_td__k*d_k__j + _j_i_s_td__q_r_td*d_q_r_td__j
                + _j_i_s_td__q_rd_td*d_q_rd_td__j + _j_i_s_td__q_thd_td*d_i_q_thd_eff__j)
            # chain rule through geyer_liftoff_phase
            d_i_phase_lo__j = _j_i_phase_lo__a*d_i_a__j + _j_i_phase_lo__b*d_i_b__j
            d_i_s_lo__j = _j_i_s_lo__a*d_i_a__j + _j_i_s_lo__b*d_i_b__j
            # eqs (13)-(14) minus (12), (11), (19), (17) at the bottom and at liftoff
            d_i_t_bottom__j = _pd__3*d_i_omega0_hat__j + _pd__4*d_i_phase_td__j
            d_i_t_stance__j = _pd__5*d_i_omega0_hat__j + _pd__6*d_i_phase_lo__j + _pd__7*d_i_phase_td__j
            d_i_bottom_q_r__j = d_i_a__j*l0 - d_i_b__j*l0
            d_i_bottom_q_th__j = (_pd__10*d_i_omega__j + _pd__11*d_i_omega0_hat__j + _pd__12*d_i_phase_td__j
                + _pd__13*d_i_s_td__j + _pd__8*d_i_a__j + _pd__9*d_i_b__j + d_q_th_td__j)
            d_i_liftoff_q_rd__j = _pd__17*d_i_b__j + _pd__18*d_i_omega0_hat__j + _pd__19*d_i_s_lo__j
            d_i_liftoff_q_th__j = (_pd__20*d_i_a__j + _pd__21*d_i_b__j + _pd__22*d_i_omega__j
                + _pd__23*d_i_omega0_hat__j + _pd__24*d_i_phase_lo__j + _pd__25*d_i_phase_td__j
                + _pd__26*d_i_s_lo__j + _pd__27*d_i_s_td__j + d_q_th_td__j)
            _T[6, _j1] = d_i_q_thd_eff__j
            _T[7, _j1] = d_i_omega0_hat__j
            _T[8, _j1] = d_i_a__j
            _T[9, _j1] = d_i_b__j
            _T[10, _j1] = d_i_phase_td__j
            _T[11, _j1] = d_i_t_bottom__j
            _T[12, _j1] = d_i_t_stance__j
            _T[13, _j1] = d_i_bottom_q_r__j
            _T[14, _j1] = d_i_bottom_q_th__j
            _T[15, _j1] = d_i_liftoff_q_rd__j
            _T[16, _j1] = d_i_liftoff_q_th__j
        if _conv0 or _it0 == _last0:
            break
        # the type's impulse rule
        _a2 = carray(stack(20), 20)
        store(_a2, (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b,
            i_bottom_q_r, i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom,
            i_t_stance,))
        _c2 = gravity_impulse_jac13(_a2)
        if _c2[14] != STATUS_OK:
            return fail(out, _c2[14])
        i_P_new = _c2[0]
        _j_i_P_new__q_r_td = _c2[1]
        _j_i_P_new__q_rd_td = _c2[2]
        _j_i_P_new__q_th_td = _c2[3]
        _j_i_P_new__i_a = _c2[4]
        _j_i_P_new__i_b = _c2[5]
        _j_i_P_new__i_bottom_q_r = _c2[6]
        _j_i_P_new__i_bottom_q_th = _c2[7]
        _j_i_P_new__i_liftoff_q_th = _c2[8]
        _j_i_P_new__i_omega0_hat = _c2[9]
        _j_i_P_new__i_phase_td = _c2[10]
        _j_i_P_new__i_q_thd_eff = _c2[11]
        _j_i_P_new__i_t_bottom = _c2[12]
        _j_i_P_new__i_t_stance = _c2[13]
        # next values
        P_c__next = i_P_new
        # the next state's tangents, once per direction
        for _j2 in range(5):
            d_q_r_td__j = _T[2, _j2]
            d_q_rd_td__j = _T[3, _j2]
            d_q_th_td__j = _T[4, _j2]
            d_i_q_thd_eff__j = _T[6, _j2]
            d_i_omega0_hat__j = _T[7, _j2]
            d_i_a__j = _T[8, _j2]
            d_i_b__j = _T[9, _j2]
            d_i_phase_td__j = _T[10, _j2]
            d_i_t_bottom__j = _T[11, _j2]
            d_i_t_stance__j = _T[12, _j2]
            d_i_bottom_q_r__j = _T[13, _j2]
            d_i_bottom_q_th__j = _T[14, _j2]
            d_i_liftoff_q_th__j = _T[16, _j2]
            # chain rule through gravity_impulse_jac13
            d_i_P_new__j = (_j_i_P_new__i_a*d_i_a__j + _j_i_P_new__i_b*d_i_b__j
                + _j_i_P_new__i_bottom_q_r*d_i_bottom_q_r__j + _j_i_P_new__i_bottom_q_th*d_i_bottom_q_th__j
                + _j_i_P_new__i_liftoff_q_th*d_i_liftoff_q_th__j + _j_i_P_new__i_omega0_hat*d_i_omega0_hat__j
                + _j_i_P_new__i_phase_td*d_i_phase_td__j + _j_i_P_new__i_q_thd_eff*d_i_q_thd_eff__j
                + _j_i_P_new__i_t_bottom*d_i_t_bottom__j + _j_i_P_new__i_t_stance*d_i_t_stance__j
                + _j_i_P_new__q_r_td*d_q_r_td__j + _j_i_P_new__q_rd_td*d_q_rd_td__j
                + _j_i_P_new__q_th_td*d_q_th_td__j)
            _T[5, _j2] = d_i_P_new__j
        _n0_0 = P_c__next
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = tol > 0.0 and (abs(_n0_0 - P_c) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + abs(p_td)))
        P_c = _n0_0
        passes += 1.0
    # the rates from the momentum at that instant; p_td + P_c at liftoff, eq (50)
    t_bottom = i_t_bottom
    t_stance = i_t_stance
    bottom_q_r = i_bottom_q_r
    bottom_q_th = i_bottom_q_th
    _x56 = (1.0/i_t_stance)
    _x48 = _x56*ramp
    _x49 = _x48*i_t_bottom - ramp + 1.0
    _x50 = P_c*_x49 + p_td
    _x51 = (1.0/m)
    _x55 = (1.0/i_bottom_q_r)
    _x52 = _x51*_x55**2
    bottom_q_thd = _x50*_x52
    _pd__32 = _x49*_x52
    _pd__33 = -2.0*_x50*_x51*_x55**3
    _x53 = P_c*_x52
    _pd__34 = _x48*_x53
    _pd__35 = -_x53*_x56**2*i_t_bottom*ramp
    _pd__36 = _x52
    liftoff_q_r = q_r_lo
    liftoff_q_th = i_liftoff_q_th
    _x54 = _x51/q_r_lo**2
    liftoff_q_thd = _x54*(P_c + p_td)
    _pd__37 = _x54
    _pd__38 = _x54
    # their tangents, once per direction
    for _j3 in range(5):
        d_p_td__j = _T[1, _j3]
        d_P_c__j = _T[5, _j3]
        d_i_t_bottom__j = _T[11, _j3]
        d_i_t_stance__j = _T[12, _j3]
        d_i_bottom_q_r__j = _T[13, _j3]
        d_i_bottom_q_th__j = _T[14, _j3]
        d_i_liftoff_q_th__j = _T[16, _j3]
        # the rates from the momentum at that instant; p_td + P_c at liftoff, eq (50)
        d_bottom_q_thd__j = (_pd__32*d_P_c__j + _pd__33*d_i_bottom_q_r__j + _pd__34*d_i_t_bottom__j
            + _pd__35*d_i_t_stance__j + _pd__36*d_p_td__j)
        d_liftoff_q_thd__j = _pd__37*d_P_c__j + _pd__38*d_p_td__j
        _T[17, _j3] = d_i_t_bottom__j
        _T[18, _j3] = d_i_t_stance__j
        _T[19, _j3] = d_i_bottom_q_r__j
        _T[20, _j3] = d_i_bottom_q_th__j
        _T[21, _j3] = d_bottom_q_thd__j
        _T[22, _j3] = d_i_liftoff_q_th__j
        _T[23, _j3] = d_liftoff_q_thd__j
    (d_P_c__q_r_td, d_P_c__q_rd_td, d_P_c__q_th_td, d_P_c__q_thd_td, d_P_c__k, ) = (_T[5, 0], _T[5, 1], _T[5,
        2], _T[5, 3], _T[5, 4], )
    (d_i_liftoff_q_rd__q_r_td, d_i_liftoff_q_rd__q_rd_td, d_i_liftoff_q_rd__q_th_td,
        d_i_liftoff_q_rd__q_thd_td, d_i_liftoff_q_rd__k, ) = (_T[15, 0], _T[15, 1], _T[15, 2], _T[15, 3],
        _T[15, 4], )
    (d_i_liftoff_q_th__q_r_td, d_i_liftoff_q_th__q_rd_td, d_i_liftoff_q_th__q_th_td,
        d_i_liftoff_q_th__q_thd_td, d_i_liftoff_q_th__k, ) = (_T[16, 0], _T[16, 1], _T[16, 2], _T[16, 3],
        _T[16, 4], )
    (d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k,
        ) = (_T[17, 0], _T[17, 1], _T[17, 2], _T[17, 3], _T[17, 4], )
    (d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k,
        ) = (_T[18, 0], _T[18, 1], _T[18, 2], _T[18, 3], _T[18, 4], )
    (d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td,
        d_bottom_q_r__k, ) = (_T[19, 0], _T[19, 1], _T[19, 2], _T[19, 3], _T[19, 4], )
    (d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k, ) = (_T[20, 0], _T[20, 1], _T[20, 2], _T[20, 3], _T[20, 4], )
    (d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td, d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td,
        d_bottom_q_thd__k, ) = (_T[21, 0], _T[21, 1], _T[21, 2], _T[21, 3], _T[21, 4], )
    (d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td,
        d_liftoff_q_th__k, ) = (_T[22, 0], _T[22, 1], _T[22, 2], _T[22, 3], _T[22, 4], )
    (d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td,
        d_liftoff_q_thd__k, ) = (_T[23, 0], _T[23, 1], _T[23, 2], _T[23, 3], _T[23, 4], )
    if reading == 0.0:
        _x57 = (1.0/m)
        _x58 = 2.0*g_s*q_r_lo
        _x59 = _x57*l0**2
        _x60 = q_r_lo**2
        _x61 = _x57*_x60
        _x62 = _x57**2/_x60
        _q_rd_lo_sq = (2.0*E_td*_x57 + 2.0*_x57*k*l0*q_r_lo - _x58*math.cos(i_liftoff_q_th) - _x59*k - _x61*k
            - _x62*(P_c + p_td)**2)
        _x63 = 2.0*_x57
        _pd__39 = _x63
        _x64 = -_x62*(2.0*P_c + 2.0*p_td)
        _pd__40 = _x64
        _pd__41 = _x58*math.sin(i_liftoff_q_th)
        _pd__42 = _x64
        _d_q_rd_lo_sq__q_r_td = (_pd__39*d_E_td__q_r_td + _pd__40*d_P_c__q_r_td
            + _pd__41*d_i_liftoff_q_th__q_r_td + _pd__42*d_p_td__q_r_td)
        _d_q_rd_lo_sq__q_rd_td = (_pd__39*d_E_td__q_rd_td + _pd__40*d_P_c__q_rd_td
            + _pd__41*d_i_liftoff_q_th__q_rd_td)
        _d_q_rd_lo_sq__q_th_td = (_pd__39*d_E_td__q_th_td + _pd__40*d_P_c__q_th_td
            + _pd__41*d_i_liftoff_q_th__q_th_td)
        _d_q_rd_lo_sq__q_thd_td = (_pd__39*d_E_td__q_thd_td + _pd__40*d_P_c__q_thd_td
            + _pd__41*d_i_liftoff_q_th__q_thd_td + _pd__42*d_p_td__q_thd_td)
        _d_q_rd_lo_sq__k = (_pd__39*d_E_td__k + _pd__40*d_P_c__k + _pd__41*d_i_liftoff_q_th__k - _x59 - _x61
            + _x63*l0*q_r_lo)
        # q_rd_lo^2 from the energy (27)
        if not ((_q_rd_lo_sq >= 0.0)):
            return fail(out, STATUS_ENERGY_DEFICIT)
        # q_rd_lo from the energy
        _x65 = math.sqrt(_q_rd_lo_sq)
        liftoff_q_rd = _x65
        _pd__43 = (0.5)/_x65
        d_liftoff_q_rd__q_r_td = _d_q_rd_lo_sq__q_r_td*_pd__43
        d_liftoff_q_rd__q_rd_td = _d_q_rd_lo_sq__q_rd_td*_pd__43
        d_liftoff_q_rd__q_th_td = _d_q_rd_lo_sq__q_th_td*_pd__43
        d_liftoff_q_rd__q_thd_td = _d_q_rd_lo_sq__q_thd_td*_pd__43
        d_liftoff_q_rd__k = _d_q_rd_lo_sq__k*_pd__43
    elif reading == 1.0:
        # from (11)
        liftoff_q_rd = i_liftoff_q_rd
        # tangents as every branch names them
        d_liftoff_q_rd__q_r_td = d_i_liftoff_q_rd__q_r_td
        d_liftoff_q_rd__q_rd_td = d_i_liftoff_q_rd__q_rd_td
        d_liftoff_q_rd__q_th_td = d_i_liftoff_q_rd__q_th_td
        d_liftoff_q_rd__q_thd_td = d_i_liftoff_q_rd__q_thd_td
        d_liftoff_q_rd__k = d_i_liftoff_q_rd__k
    else:
        return fail(out, STATUS_INVALID_INPUT)
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


@njit(cache=True, error_model="numpy")
def gravity_type0_stance_jacobian(x, p, out):
    """Gravity correction type 0 (leg length l0): stance outputs and their derivatives with respect to the
    touchdown state and the stiffness.

    Report equations: 46, 47, 48, 49, 50, 51.

    Runs the shared body :func:`gravity_stance_jacobian_shared` with
    gravity_impulse_type0_jac13_8638ac.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, samples, interval, leg_length, iterations, tol); writes
    the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`gravity.gravity_type0_stance`, in its order.

    Writes into out:
        <output>: each output of :func:`gravity.gravity_type0_stance`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return gravity_stance_jacobian_shared(x, p, out, gravity_impulse_type0_jac13_8638ac)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type0_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type0_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type0_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_impulse_type1_jac13_8638ac(_a):
    """Type 1's stance impulse P_c of the trajectory (report section 4.2), and the derivatives of its outputs
    with respect to q_r_td, q_rd_td, q_th_td, i_a, i_b, i_bottom_q_r, i_bottom_q_th, i_liftoff_q_th,
    i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance.

    Report equations: 52, 53, 54.

    Arguments, returns and status: those of :func:`gravity_impulse_type0_jac13_8638ac`.
    """
    # Total ops: 59
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # eq (48) with 2 or 3 samples
    if samples == 2.0:
        _x0 = math.sin(i_liftoff_q_th)
        _x1 = g_s*m
        _x2 = _x1*((0.5)*i_bottom_q_r + (0.5)*l0)
        _x3 = _x0*_x2
        _x4 = math.sin(q_th_td)
        _x5 = _x2*_x4
        _x6 = (0.5)*i_t_stance
        i_P_new = _x6*(_x3 + _x5)
        _x7 = _x2*_x6
        d_i_P_new__q_th_td = _x7*math.cos(q_th_td)
        _x8 = (0.5)*_x1
        d_i_P_new__i_bottom_q_r = _x6*(_x0*_x8 + _x4*_x8)
        d_i_P_new__i_liftoff_q_th = _x7*math.cos(i_liftoff_q_th)
        d_i_P_new__i_t_stance = (0.5)*_x3 + (0.5)*_x5
        # tangents as every branch names them
        d_i_P_new__i_bottom_q_th = 0.0
    elif samples == 3.0:
        _x9 = math.sin(i_bottom_q_th)
        _x10 = g_s*m
        _x11 = _x10*((0.5)*i_bottom_q_r + (0.5)*l0)
        _x12 = _x11*_x9
        _x13 = math.sin(i_liftoff_q_th)
        _x14 = _x11*_x13
        _x15 = math.sin(q_th_td)
        _x16 = _x11*_x15
        _x17 = (0.3333333333333333)*i_t_stance
        i_P_new = _x17*(_x12 + _x14 + _x16)
        _x18 = _x11*_x17
        d_i_P_new__q_th_td = _x18*math.cos(q_th_td)
        _x19 = (0.5)*_x10
        d_i_P_new__i_bottom_q_r = _x17*(_x13*_x19 + _x15*_x19 + _x19*_x9)
        d_i_P_new__i_bottom_q_th = _x18*math.cos(i_bottom_q_th)
        d_i_P_new__i_liftoff_q_th = _x18*math.cos(i_liftoff_q_th)
        d_i_P_new__i_t_stance = ((0.3333333333333333)*_x12 + (0.3333333333333333)*_x14
            + (0.3333333333333333)*_x16)
    else:
        return _NAN14 + (STATUS_INVALID_INPUT,)
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new, 0.0, 0.0, d_i_P_new__q_th_td, 0.0, 0.0, d_i_P_new__i_bottom_q_r,
        d_i_P_new__i_bottom_q_th, d_i_P_new__i_liftoff_q_th, 0.0, 0.0, 0.0, 0.0, d_i_P_new__i_t_stance,
        STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type1_stance_jacobian(x, p, out):
    """Gravity correction type 1 (leg length (l0 + q_r_b)/2): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 46, 47, 48, 50, 52, 53, 54.

    Runs the shared body :func:`gravity_stance_jacobian_shared` with
    gravity_impulse_type1_jac13_8638ac. Arguments, returns and status: those of
    :func:`gravity_type0_stance_jacobian`.
    """
    # Total ops: 0
    return gravity_stance_jacobian_shared(x, p, out, gravity_impulse_type1_jac13_8638ac)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type1_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type1_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type1_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_impulse_type2_jac13_8638ac(_a):
    """Type 2's stance impulse P_c of the trajectory (report section 4.3), and the derivatives of its outputs
    with respect to q_r_td, q_rd_td, q_th_td, i_a, i_b, i_bottom_q_r, i_bottom_q_th, i_liftoff_q_th,
    i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance.

    Report equations: 55, 56, 57, 58, 59, 60, 61, 62, 63, 64.

    Arguments, returns and status: those of :func:`gravity_impulse_type0_jac13_8638ac`.
    """
    # Total ops: 260
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # average leg length, eqs (55)-(61) / (67)-(75)
    if leg_length == 0.0:
        _x0 = math.cos(i_phase_td)
        _x1 = i_a + 1.0
        _x2 = (1.0/i_omega0_hat)
        _x3 = _x2*i_phase_td
        _x4 = _x3 + i_t_stance
        _x5 = _x4*i_omega0_hat
        _x6 = math.cos(_x5)
        _x7 = _x0*i_b + _x1*_x5 - _x1*i_phase_td - _x6*i_b
        _x8 = (1.0/i_t_stance)
        _x9 = _x2*_x8*l0
        _i_L = _x7*_x9
        _d_i_L__i_a = _x9*(_x5 - i_phase_td)
        _d_i_L__i_b = _x9*(_x0 - _x6)
        _x10 = math.sin(_x5)
        _x11 = _x10*i_b
        _x12 = _x7*l0
        _d_i_L__i_omega0_hat = -_x12*_x2**2*_x8 + _x9*(-_x1*_x3 + _x1*_x4 + _x11*i_t_stance)
        _d_i_L__i_phase_td = _x9*(_x10*i_b - i_b*math.sin(i_phase_td))
        _d_i_L__i_t_stance = -_x12*_x2*_x8**2 + _x9*(_x1*i_omega0_hat + _x11*i_omega0_hat)
        # tangents as every branch names them
        _d_i_L__q_rd_td = 0.0
        _d_i_L__i_q_thd_eff = 0.0
    elif leg_length == 1.0:
        _x13 = i_omega0_hat*i_t_stance
        _x14 = math.sin(_x13)
        _x15 = i_a*i_t_stance
        _x16 = i_b**2
        _x17 = _x16 - i_a**2
        _x18 = math.sqrt(_x17/_x16)
        _x19 = _x18*i_b
        _x20 = math.cos(_x13)
        _x21 = -_x14*i_a + _x18*_x20*i_b - _x19 + i_omega0_hat*(_x15 + i_t_stance)
        _x22 = (1.0/i_omega0_hat)
        _x23 = (1.0/i_t_stance)
        _x24 = _x22*_x23*l0
        _i_L = _x21*_x24
        _x25 = (1.0/_x17)
        _d_i_L__i_a = _x24*(-_x14 + _x18*_x25*i_a*i_b - _x19*_x20*_x25*i_a + i_omega0_hat*i_t_stance)
        _x26 = _x18*_x20
        _x27 = i_b**3
        _x28 = _x25*_x27*(-_x17/_x27 + (1.0/i_b))
        _d_i_L__i_b = _x24*(-_x18*_x28 - _x18 + _x26*_x28 + _x26)
        _x29 = _x14*_x19
        _x30 = _x21*l0
        _d_i_L__i_omega0_hat = (-_x22**2*_x23*_x30 + _x24*(-_x15*_x20 - _x29*i_t_stance + i_a*i_t_stance
            + i_t_stance))
        _d_i_L__i_t_stance = (-_x22*_x23**2*_x30 + _x24*(-_x20*i_a*i_omega0_hat - _x29*i_omega0_hat
            + i_omega0_hat*(i_a + 1.0)))
        # tangents as every branch names them
        _d_i_L__q_rd_td = 0.0
        _d_i_L__i_phase_td = 0.0
        _d_i_L__i_q_thd_eff = 0.0
    elif leg_length == 2.0:
        _x31 = i_omega0_hat*q_rd_td
        _x32 = i_omega0_hat*i_t_stance
        _x33 = math.sin(_x32)
        _x34 = i_q_thd_eff**2*l0
        _x35 = g_s*i_t_stance
        _x36 = math.cos(_x32)
        _x37 = _x36*q_rd_td
        _x38 = i_omega0_hat**2*l0
        _x39 = _x38*i_t_stance
        _x40 = _x34*i_t_stance
        _x41 = _x31 - _x33*_x34 + _x33*g_s - i_omega0_hat*(_x35 + _x37 - _x39 - _x40)
        _x48 = (1.0/i_omega0_hat)
        _x42 = _x48**3
        _x43 = (1.0/i_t_stance)
        _x44 = _x42*_x43
        _i_L = _x41*_x44
        _x45 = _x36*i_omega0_hat
        _d_i_L__q_rd_td = _x44*(-_x45 + i_omega0_hat)
        _x46 = 2.0*l0
        _x47 = _x32*_x46
        _d_i_L__i_omega0_hat = (-3.0*_x41*_x43*_x48**4 + _x44*(_x35*_x36 - _x35 - _x36*_x40 - _x37 + _x39
            + _x40 - i_omega0_hat*(-_x33*i_t_stance*q_rd_td - _x47) + q_rd_td))
        _d_i_L__i_q_thd_eff = _x44*(-_x33*_x46*i_q_thd_eff + _x47*i_q_thd_eff)
        _d_i_L__i_t_stance = (-_x41*_x42*_x43**2 + _x44*(-_x34*_x45 + _x36*g_s*i_omega0_hat
            - i_omega0_hat*(-_x31*_x33 - _x34 - _x38 + g_s)))
        # tangents as every branch names them
        _d_i_L__i_a = 0.0
        _d_i_L__i_b = 0.0
        _d_i_L__i_phase_td = 0.0
    else:
        return _NAN14 + (STATUS_INVALID_INPUT,)
    # eq (48) with 2 or 3 samples
    if samples == 2.0:
        _x49 = g_s*m
        _x50 = _x49*math.sin(i_liftoff_q_th)
        _x51 = _i_L*_x50
        _x52 = _x49*math.sin(q_th_td)
        _x53 = _i_L*_x52
        _x54 = (0.5)*i_t_stance
        i_P_new = _x54*(_x51 + _x53)
        _pd__0 = _x54*(_x50 + _x52)
        d_i_P_new__q_rd_td = _d_i_L__q_rd_td*_pd__0
        _x55 = _i_L*_x49*_x54
        d_i_P_new__q_th_td = _x55*math.cos(q_th_td)
        d_i_P_new__i_a = _d_i_L__i_a*_pd__0
        d_i_P_new__i_b = _d_i_L__i_b*_pd__0
        d_i_P_new__i_liftoff_q_th = _x55*math.cos(i_liftoff_q_th)
        d_i_P_new__i_omega0_hat = _d_i_L__i_omega0_hat*_pd__0
        d_i_P_new__i_phase_td = _d_i_L__i_phase_td*_pd__0
        d_i_P_new__i_q_thd_eff = _d_i_L__i_q_thd_eff*_pd__0
        d_i_P_new__i_t_stance = _d_i_L__i_t_stance*_pd__0 + (0.5)*_x51 + (0.5)*_x53
        # tangents as every branch names them
        d_i_P_new__i_bottom_q_th = 0.0
    elif samples == 3.0:
        _x56 = g_s*m
        _x57 = _x56*math.sin(i_bottom_q_th)
        _x58 = _i_L*_x57
        _x59 = _x56*math.sin(i_liftoff_q_th)
        _x60 = _i_L*_x59
        _x61 = _x56*math.sin(q_th_td)
        _x62 = _i_L*_x61
        _x63 = (0.3333333333333333)*i_t_stance
        i_P_new = _x63*(_x58 + _x60 + _x62)
        _pd__1 = _x63*(_x57 + _x59 + _x61)
        d_i_P_new__q_rd_td = _d_i_L__q_rd_td*_pd__1
        _x64 = _i_L*_x56*_x63
        d_i_P_new__q_th_td = _x64*math.cos(q_th_td)
        d_i_P_new__i_a = _d_i_L__i_a*_pd__1
        d_i_P_new__i_b = _d_i_L__i_b*_pd__1
        d_i_P_new__i_bottom_q_th = _x64*math.cos(i_bottom_q_th)
        d_i_P_new__i_liftoff_q_th = _x64*math.cos(i_liftoff_q_th)
        d_i_P_new__i_omega0_hat = _d_i_L__i_omega0_hat*_pd__1
        d_i_P_new__i_phase_td = _d_i_L__i_phase_td*_pd__1
        d_i_P_new__i_q_thd_eff = _d_i_L__i_q_thd_eff*_pd__1
        d_i_P_new__i_t_stance = (_d_i_L__i_t_stance*_pd__1 + (0.3333333333333333)*_x58
            + (0.3333333333333333)*_x60 + (0.3333333333333333)*_x62)
    else:
        return _NAN14 + (STATUS_INVALID_INPUT,)
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new, 0.0, d_i_P_new__q_rd_td, d_i_P_new__q_th_td, d_i_P_new__i_a, d_i_P_new__i_b, 0.0,
        d_i_P_new__i_bottom_q_th, d_i_P_new__i_liftoff_q_th, d_i_P_new__i_omega0_hat, d_i_P_new__i_phase_td,
        d_i_P_new__i_q_thd_eff, 0.0, d_i_P_new__i_t_stance, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type2_stance_jacobian(x, p, out):
    """Gravity correction type 2 (average leg length): stance outputs and their derivatives with respect to
    the touchdown state and the stiffness.

    Report equations: 46, 47, 48, 50, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64.

    Runs the shared body :func:`gravity_stance_jacobian_shared` with
    gravity_impulse_type2_jac13_8638ac. Arguments, returns and status: those of
    :func:`gravity_type0_stance_jacobian`.
    """
    # Total ops: 0
    return gravity_stance_jacobian_shared(x, p, out, gravity_impulse_type2_jac13_8638ac)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type2_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type2_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type2_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_impulse_type3_jac13_8638ac(_a):
    """Type 3's stance impulse P_c of the trajectory (report section 4.4), and the derivatives of its outputs
    with respect to q_r_td, q_rd_td, q_th_td, i_a, i_b, i_bottom_q_r, i_bottom_q_th, i_liftoff_q_th,
    i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance.

    Report equations: 65, 66.

    Arguments, returns and status: those of :func:`gravity_impulse_type0_jac13_8638ac`.
    """
    # Total ops: 65
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # eq (65)
    if interval == 0.0:
        _x0 = g_s*m
        _x1 = _x0*q_r_lo
        _x2 = _x1*math.sin(i_liftoff_q_th)
        _x3 = _x0*math.sin(q_th_td)
        _x4 = _x3*q_r_td
        _x5 = (0.5)*i_t_stance
        i_P_new = _x5*(_x2 + _x4)
        d_i_P_new__q_r_td = _x3*_x5
        d_i_P_new__q_th_td = _x0*_x5*q_r_td*math.cos(q_th_td)
        d_i_P_new__i_liftoff_q_th = _x1*_x5*math.cos(i_liftoff_q_th)
        d_i_P_new__i_t_stance = (0.5)*_x2 + (0.5)*_x4
        # tangents as every branch names them
        d_i_P_new__i_bottom_q_r = 0.0
        d_i_P_new__i_bottom_q_th = 0.0
        d_i_P_new__i_t_bottom = 0.0
    elif interval == 1.0:
        _x6 = g_s*m
        _x7 = _x6*math.sin(i_bottom_q_th)
        _x8 = _x7*i_bottom_q_r
        _x9 = math.sin(q_th_td)
        _x10 = _x6*_x9
        _x11 = (0.5)*i_t_bottom
        _x12 = _x6*q_r_lo
        _x13 = _x12*math.sin(i_liftoff_q_th)
        _x14 = -0.5*i_t_bottom + (0.5)*i_t_stance
        i_P_new = _x11*(_x10*q_r_td + _x8) + _x14*(_x13 + _x8)
        d_i_P_new__q_r_td = _x10*_x11
        _x15 = _x11*_x6
        d_i_P_new__q_th_td = _x15*q_r_td*math.cos(q_th_td)
        d_i_P_new__i_bottom_q_r = _x11*_x7 + _x14*_x7
        _x16 = i_bottom_q_r*math.cos(i_bottom_q_th)
        d_i_P_new__i_bottom_q_th = _x14*_x16*_x6 + _x15*_x16
        d_i_P_new__i_liftoff_q_th = _x12*_x14*math.cos(i_liftoff_q_th)
        _x17 = (0.5)*_x13
        d_i_P_new__i_t_bottom = -_x17 + (0.5)*_x9*g_s*m*q_r_td
        d_i_P_new__i_t_stance = _x17 + (0.5)*_x8
    else:
        return _NAN14 + (STATUS_INVALID_INPUT,)
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new, d_i_P_new__q_r_td, 0.0, d_i_P_new__q_th_td, 0.0, 0.0, d_i_P_new__i_bottom_q_r,
        d_i_P_new__i_bottom_q_th, d_i_P_new__i_liftoff_q_th, 0.0, 0.0, 0.0, d_i_P_new__i_t_bottom,
        d_i_P_new__i_t_stance, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type3_stance_jacobian(x, p, out):
    """Gravity correction type 3 (trapezoid on [t_i, t_f]): stance outputs and their derivatives with respect
    to the touchdown state and the stiffness.

    Report equations: 46, 47, 48, 50, 65, 66.

    Runs the shared body :func:`gravity_stance_jacobian_shared` with
    gravity_impulse_type3_jac13_8638ac. Arguments, returns and status: those of
    :func:`gravity_type0_stance_jacobian`.
    """
    # Total ops: 0
    return gravity_stance_jacobian_shared(x, p, out, gravity_impulse_type3_jac13_8638ac)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type3_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type3_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type3_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_impulse_type4_jac13_8638ac(_a):
    """Type 4's stance impulse P_c of the trajectory (report section 4.5), and the derivatives of its outputs
    with respect to q_r_td, q_rd_td, q_th_td, i_a, i_b, i_bottom_q_r, i_bottom_q_th, i_liftoff_q_th,
    i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance.

    Report equations: 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Arguments, returns and status: those of :func:`gravity_impulse_type0_jac13_8638ac`.
    """
    # Total ops: 767
    (q_r_td, q_rd_td, q_th_td, m, l0, g_s, q_r_lo, samples, interval, leg_length, i_a, i_b, i_bottom_q_r,
        i_bottom_q_th, i_liftoff_q_th, i_omega0_hat, i_phase_td, i_q_thd_eff, i_t_bottom, i_t_stance,
        ) = (load(_a, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19))
    # eq (76)
    if interval == 0.0:
        # average leg length, eqs (55)-(61) / (67)-(75)
        if leg_length == 0.0:
            _x0 = math.cos(i_phase_td)
            _x1 = i_a + 1.0
            _x2 = (1.0/i_omega0_hat)
            _x3 = _x2*i_phase_td
            _x4 = _x3 + i_t_stance
            _x5 = _x4*i_omega0_hat
            _x6 = math.cos(_x5)
            _x7 = _x0*i_b + _x1*_x5 - _x1*i_phase_td - _x6*i_b
            _x8 = (1.0/i_t_stance)
            _x9 = _x2*_x8*l0
            _i_L = _x7*_x9
            _d_i_L__i_a = _x9*(_x5 - i_phase_td)
            _d_i_L__i_b = _x9*(_x0 - _x6)
            _x10 = math.sin(_x5)
            _x11 = _x10*i_b
            _x12 = _x7*l0
            _d_i_L__i_omega0_hat = -_x12*_x2**2*_x8 + _x9*(-_x1*_x3 + _x1*_x4 + _x11*i_t_stance)
            _d_i_L__i_phase_td = _x9*(_x10*i_b - i_b*math.sin(i_phase_td))
            _d_i_L__i_t_stance = -_x12*_x2*_x8**2 + _x9*(_x1*i_omega0_hat + _x11*i_omega0_hat)
            # tangents as every branch names them
            _d_i_L__q_rd_td = 0.0
            _d_i_L__i_q_thd_eff = 0.0
        elif leg_length == 1.0:
            _x13 = i_omega0_hat*i_t_stance
            _x14 = math.sin(_x13)
            _x15 = i_a*i_t_stance
            _x16 = i_b**2
            _x17 = _x16 - i_a**2
            _x18 = math.sqrt(_x17/_x16)
            _x19 = _x18*i_b
            _x20 = math.cos(_x13)
            _x21 = -_x14*i_a + _x18*_x20*i_b - _x19 + i_omega0_hat*(_x15 + i_t_stance)
            _x22 = (1.0/i_omega0_hat)
            _x23 = (1.0/i_t_stance)
            _x24 = _x22*_x23*l0
            _i_L = _x21*_x24
            _x25 = (1.0/_x17)
            _d_i_L__i_a = _x24*(-_x14 + _x18*_x25*i_a*i_b - _x19*_x20*_x25*i_a + i_omega0_hat*i_t_stance)
            _x26 = _x18*_x20
            _x27 = i_b**3
            _x28 = _x25*_x27*(-_x17/_x27 + (1.0/i_b))
            _d_i_L__i_b = _x24*(-_x18*_x28 - _x18 + _x26*_x28 + _x26)
            _x29 = _x14*_x19
            _x30 = _x21*l0
            _d_i_L__i_omega0_hat = (-_x22**2*_x23*_x30 + _x24*(-_x15*_x20 - _x29*i_t_stance + i_a*i_t_stance
                + i_t_stance))
            _d_i_L__i_t_stance = (-_x22*_x23**2*_x30 + _x24*(-_x20*i_a*i_omega0_hat - _x29*i_omega0_hat
                + i_omega0_hat*(i_a + 1.0)))
            # tangents as every branch names them
            _d_i_L__q_rd_td = 0.0
            _d_i_L__i_phase_td = 0.0
            _d_i_L__i_q_thd_eff = 0.0
        elif leg_length == 2.0:
            _x31 = i_omega0_hat*q_rd_td
            _x32 = i_omega0_hat*i_t_stance
            _x33 = math.sin(_x32)
            _x34 = i_q_thd_eff**2*l0
            _x35 = g_s*i_t_stance
            _x36 = math.cos(_x32)
            _x37 = _x36*q_rd_td
            _x38 = i_omega0_hat**2*l0
            _x39 = _x38*i_t_stance
            _x40 = _x34*i_t_stance
            _x41 = _x31 - _x33*_x34 + _x33*g_s - i_omega0_hat*(_x35 + _x37 - _x39 - _x40)
            _x48 = (1.0/i_omega0_hat)
            _x42 = _x48**3
            _x43 = (1.0/i_t_stance)
            _x44 = _x42*_x43
            _i_L = _x41*_x44
            _x45 = _x36*i_omega0_hat
            _d_i_L__q_rd_td = _x44*(-_x45 + i_omega0_hat)
            _x46 = 2.0*l0
            _x47 = _x32*_x46
            _d_i_L__i_omega0_hat = (-3.0*_x41*_x43*_x48**4 + _x44*(_x35*_x36 - _x35 - _x36*_x40 - _x37 + _x39
                + _x40 - i_omega0_hat*(-_x33*i_t_stance*q_rd_td - _x47) + q_rd_td))
            _d_i_L__i_q_thd_eff = _x44*(-_x33*_x46*i_q_thd_eff + _x47*i_q_thd_eff)
            _d_i_L__i_t_stance = (-_x41*_x42*_x43**2 + _x44*(-_x34*_x45 + _x36*g_s*i_omega0_hat
                - i_omega0_hat*(-_x31*_x33 - _x34 - _x38 + g_s)))
            # tangents as every branch names them
            _d_i_L__i_a = 0.0
            _d_i_L__i_b = 0.0
            _d_i_L__i_phase_td = 0.0
        else:
            return _NAN14 + (STATUS_INVALID_INPUT,)
        _x49 = g_s*m
        _x50 = _x49*math.sin(i_liftoff_q_th)
        _x51 = _i_L*_x50
        _x52 = _x49*math.sin(q_th_td)
        _x53 = _i_L*_x52
        _x54 = (0.5)*i_t_stance
        i_P_new = _x54*(_x51 + _x53)
        _pd__0 = _x54*(_x50 + _x52)
        d_i_P_new__q_rd_td = _d_i_L__q_rd_td*_pd__0
        _x55 = _i_L*_x49*_x54
        d_i_P_new__q_th_td = _x55*math.cos(q_th_td)
        d_i_P_new__i_a = _d_i_L__i_a*_pd__0
        d_i_P_new__i_b = _d_i_L__i_b*_pd__0
        d_i_P_new__i_liftoff_q_th = _x55*math.cos(i_liftoff_q_th)
        d_i_P_new__i_omega0_hat = _d_i_L__i_omega0_hat*_pd__0
        d_i_P_new__i_phase_td = _d_i_L__i_phase_td*_pd__0
        d_i_P_new__i_q_thd_eff = _d_i_L__i_q_thd_eff*_pd__0
        d_i_P_new__i_t_stance = _d_i_L__i_t_stance*_pd__0 + (0.5)*_x51 + (0.5)*_x53
        # tangents as every branch names them
        d_i_P_new__i_bottom_q_th = 0.0
        d_i_P_new__i_t_bottom = 0.0
    elif interval == 1.0:
        # average leg length, eqs (55)-(61) / (67)-(75)
        if leg_length == 0.0:
            _x56 = math.cos(i_phase_td)
            _x57 = i_a + 1.0
            _x58 = (1.0/i_omega0_hat)
            _x59 = _x58*i_phase_td
            _x60 = _x59 + i_t_bottom
            _x61 = _x60*i_omega0_hat
            _x62 = math.cos(_x61)
            _x63 = _x56*i_b + _x57*_x61 - _x57*i_phase_td - _x62*i_b
            _x64 = (1.0/i_t_bottom)
            _x65 = _x58*_x64*l0
            _i_L1 = _x63*_x65
            _d_i_L1__i_a = _x65*(_x61 - i_phase_td)
            _d_i_L1__i_b = _x65*(_x56 - _x62)
            _x66 = math.sin(_x61)
            _x67 = _x66*i_b
            _x68 = _x63*l0
            _d_i_L1__i_omega0_hat = -_x58**2*_x64*_x68 + _x65*(-_x57*_x59 + _x57*_x60 + _x67*i_t_bottom)
            _d_i_L1__i_phase_td = _x65*(_x66*i_b - i_b*math.sin(i_phase_td))
            _d_i_L1__i_t_bottom = -_x58*_x64**2*_x68 + _x65*(_x57*i_omega0_hat + _x67*i_omega0_hat)
            # tangents as every branch names them
            _d_i_L1__q_rd_td = 0.0
            _d_i_L1__i_q_thd_eff = 0.0
        elif leg_length == 1.0:
            _x69 = i_omega0_hat*i_t_bottom
            _x70 = math.sin(_x69)
            _x71 = i_a*i_t_bottom
            _x72 = i_b**2
            _x73 = _x72 - i_a**2
            _x74 = math.sqrt(_x73/_x72)
            _x75 = _x74*i_b
            _x76 = math.cos(_x69)
            _x77 = -_x70*i_a + _x74*_x76*i_b - _x75 + i_omega0_hat*(_x71 + i_t_bottom)
            _x78 = (1.0/i_omega0_hat)
            _x79 = (1.0/i_t_bottom)
            _x80 = _x78*_x79*l0
            _i_L1 = _x77*_x80
            _x81 = (1.0/_x73)
            _d_i_L1__i_a = _x80*(-_x70 + _x74*_x81*i_a*i_b - _x75*_x76*_x81*i_a + i_omega0_hat*i_t_bottom)
            _x82 = _x74*_x76
            _x83 = i_b**3
            _x84 = _x81*_x83*(-_x73/_x83 + (1.0/i_b))
            _d_i_L1__i_b = _x80*(-_x74*_x84 - _x74 + _x82*_x84 + _x82)
            _x85 = _x70*_x75
            _x86 = _x77*l0
            _d_i_L1__i_omega0_hat = (-_x78**2*_x79*_x86 + _x80*(-_x71*_x76 - _x85*i_t_bottom + i_a*i_t_bottom
                + i_t_bottom))
            _d_i_L1__i_t_bottom = (-_x78*_x79**2*_x86 + _x80*(-_x76*i_a*i_omega0_hat - _x85*i_omega0_hat
                + i_omega0_hat*(i_a + 1.0)))
            # tangents as every branch names them
            _d_i_L1__q_rd_td = 0.0
            _d_i_L1__i_phase_td = 0.0
            _d_i_L1__i_q_thd_eff = 0.0
        elif leg_length == 2.0:
            _x87 = i_omega0_hat*q_rd_td
            _x88 = i_omega0_hat*i_t_bottom
            _x89 = math.sin(_x88)
            _x90 = i_q_thd_eff**2*l0
            _x91 = g_s*i_t_bottom
            _x92 = math.cos(_x88)
            _x93 = _x92*q_rd_td
            _x94 = i_omega0_hat**2*l0
            _x95 = _x94*i_t_bottom
            _x96 = _x90*i_t_bottom
            _x97 = _x87 - _x89*_x90 + _x89*g_s - i_omega0_hat*(_x91 + _x93 - _x95 - _x96)
            _x104 = (1.0/i_omega0_hat)
            _x98 = _x104**3
            _x99 = (1.0/i_t_bottom)
            _x100 = _x98*_x99
            _i_L1 = _x100*_x97
            _x101 = _x92*i_omega0_hat
            _d_i_L1__q_rd_td = _x100*(-_x101 + i_omega0_hat)
            _x102 = 2.0*l0
            _x103 = _x102*_x88
            _d_i_L1__i_omega0_hat = (_x100*(_x91*_x92 - _x91 - _x92*_x96 - _x93 + _x95 + _x96
                - i_omega0_hat*(-_x103 - _x89*i_t_bottom*q_rd_td) + q_rd_td) - 3.0*_x104**4*_x97*_x99)
            _d_i_L1__i_q_thd_eff = _x100*(-_x102*_x89*i_q_thd_eff + _x103*i_q_thd_eff)
            _d_i_L1__i_t_bottom = (_x100*(-_x101*_x90 + _x92*g_s*i_omega0_hat - i_omega0_hat*(-_x87*_x89
                - _x90 - _x94 + g_s)) - _x97*_x98*_x99**2)
            # tangents as every branch names them
            _d_i_L1__i_a = 0.0
            _d_i_L1__i_b = 0.0
            _d_i_L1__i_phase_td = 0.0
        else:
            return _NAN14 + (STATUS_INVALID_INPUT,)
        # average leg length, eqs (55)-(61) / (67)-(75)
        if leg_length == 0.0:
            _x105 = (1.0/i_omega0_hat)
            _x106 = _x105*i_phase_td
            _x107 = _x106 + i_t_bottom
            _x108 = _x107*i_omega0_hat
            _x109 = math.cos(_x108)
            _x110 = i_a + 1.0
            _x111 = _x106 + i_t_stance
            _x112 = _x111*i_omega0_hat
            _x113 = math.cos(_x112)
            _x114 = -_x108*_x110 + _x109*i_b + _x110*_x112 - _x113*i_b
            _x115 = -i_t_bottom + i_t_stance
            _x116 = (1.0/_x115)
            _x117 = _x105*_x116*l0
            _i_L2 = _x114*_x117
            _d_i_L2__i_a = _x117*(-_x108 + _x111*i_omega0_hat)
            _d_i_L2__i_b = _x117*(_x109 - _x113)
            _x118 = i_b*math.sin(_x108)
            _x119 = math.sin(_x112)
            _x120 = _x114*l0
            _d_i_L2__i_omega0_hat = (-_x105**2*_x116*_x120 + _x117*(-_x107*_x110 + _x110*_x111
                - _x118*i_t_bottom + _x119*i_b*i_t_stance))
            _d_i_L2__i_phase_td = _x117*(-_x118 + _x119*i_b)
            _x121 = _x110*i_omega0_hat
            _x122 = _x105*_x116**2*_x120
            _d_i_L2__i_t_bottom = _x117*(-_x118*i_omega0_hat - _x121) + _x122
            _d_i_L2__i_t_stance = _x117*(_x119*i_b*i_omega0_hat + _x121) - _x122
            # tangents as every branch names them
            _d_i_L2__q_rd_td = 0.0
            _d_i_L2__i_q_thd_eff = 0.0
        elif leg_length == 1.0:
            _x123 = i_omega0_hat*i_t_bottom
            _x124 = math.sin(_x123)
            _x125 = i_omega0_hat*i_t_stance
            _x126 = math.sin(_x125)
            _x127 = i_a*i_t_bottom
            _x128 = i_t_bottom - i_t_stance
            _x129 = math.cos(_x125)
            _x130 = i_b**2
            _x131 = _x130 - i_a**2
            _x132 = math.sqrt(_x131/_x130)
            _x133 = _x129*_x132*i_b
            _x134 = math.cos(_x123)
            _x135 = _x132*_x134
            _x136 = _x135*i_b
            _x137 = _x124*i_a - _x126*i_a + _x133 - _x136 + i_omega0_hat*(-_x127 - _x128 + i_a*i_t_stance)
            _x138 = (1.0/i_omega0_hat)
            _x139 = -_x128
            _x140 = (1.0/_x139)
            _x141 = _x138*_x140*l0
            _i_L2 = _x137*_x141
            _x142 = (1.0/_x131)
            _x143 = _x142*i_a
            _d_i_L2__i_a = _x141*(_x124 - _x126 - _x133*_x143 + _x136*_x143 + _x139*i_omega0_hat)
            _x144 = i_b**3
            _x145 = -_x131/_x144 + (1.0/i_b)
            _d_i_L2__i_b = (_x141*(_x129*_x132*_x142*_x144*_x145 + _x129*_x132 - _x135*_x142*_x144*_x145
                - _x135))
            _x146 = _x137*l0
            _x147 = i_a*i_t_stance
            _x148 = _x132*i_b
            _x149 = _x124*_x148
            _x150 = _x126*_x148
            _d_i_L2__i_omega0_hat = (-_x138**2*_x140*_x146 + _x141*(_x127*_x134 - _x127 - _x129*_x147 + _x147
                + _x149*i_t_bottom - _x150*i_t_stance - i_t_bottom + i_t_stance))
            _x151 = i_a + 1.0
            _x152 = i_a*i_omega0_hat
            _x153 = _x138*_x140**2*_x146
            _d_i_L2__i_t_bottom = _x141*(_x134*_x152 + _x149*i_omega0_hat - _x151*i_omega0_hat) + _x153
            _d_i_L2__i_t_stance = _x141*(-_x129*_x152 - _x150*i_omega0_hat + _x151*i_omega0_hat) - _x153
            # tangents as every branch names them
            _d_i_L2__q_rd_td = 0.0
            _d_i_L2__i_phase_td = 0.0
            _d_i_L2__i_q_thd_eff = 0.0
        elif leg_length == 2.0:
            _x154 = i_omega0_hat*i_t_bottom
            _x155 = math.sin(_x154)
            _x156 = i_omega0_hat*i_t_stance
            _x157 = math.sin(_x156)
            _x158 = i_q_thd_eff**2
            _x159 = _x158*l0
            _x160 = math.cos(_x156)
            _x161 = i_omega0_hat**2*l0
            _x162 = _x159*i_t_stance
            _x163 = _x160*q_rd_td - _x161*i_t_stance - _x162 + g_s*i_t_stance
            _x164 = g_s*i_t_bottom
            _x165 = math.cos(_x154)
            _x166 = _x161*i_t_bottom
            _x167 = _x159*i_t_bottom
            _x168 = (_x155*_x158*l0 - _x155*g_s - _x157*_x159 + _x157*g_s - _x163*i_omega0_hat
                + i_omega0_hat*(_x164 + _x165*q_rd_td - _x166 - _x167))
            _x181 = (1.0/i_omega0_hat)
            _x169 = _x181**3
            _x170 = -i_t_bottom + i_t_stance
            _x171 = (1.0/_x170)
            _x172 = _x169*_x171
            _i_L2 = _x168*_x172
            _x173 = _x165*i_omega0_hat
            _x174 = _x160*i_omega0_hat
            _d_i_L2__q_rd_td = _x172*(_x173 - _x174)
            _x175 = 2.0*l0
            _x176 = _x157*q_rd_td
            _x177 = _x154*_x175
            _x178 = _x155*q_rd_td
            _d_i_L2__i_omega0_hat = (-3.0*_x168*_x171*_x181**4 + _x172*(_x158*_x165*i_t_bottom*l0
                - _x160*_x162 + _x160*g_s*i_t_stance - _x163 - _x164*_x165 + _x165*q_rd_td - _x166 - _x167
                + g_s*i_t_bottom + i_omega0_hat*(-_x177 - _x178*i_t_bottom) - i_omega0_hat*(-_x156*_x175
                - _x176*i_t_stance)))
            _d_i_L2__i_q_thd_eff = (_x172*(2.0*_x155*i_q_thd_eff*l0 - _x157*_x175*i_q_thd_eff
                - _x177*i_q_thd_eff + 2.0*i_omega0_hat*i_q_thd_eff*i_t_stance*l0))
            _x179 = _x159 + _x161 - g_s
            _x180 = _x168*_x169*_x171**2
            _d_i_L2__i_t_bottom = (_x172*(_x159*_x173 - _x173*g_s + i_omega0_hat*(-_x178*i_omega0_hat
                - _x179)) + _x180)
            _d_i_L2__i_t_stance = (_x172*(-_x159*_x174 + _x160*g_s*i_omega0_hat
                - i_omega0_hat*(-_x176*i_omega0_hat - _x179)) - _x180)
            # tangents as every branch names them
            _d_i_L2__i_a = 0.0
            _d_i_L2__i_b = 0.0
            _d_i_L2__i_phase_td = 0.0
        else:
            return _NAN14 + (STATUS_INVALID_INPUT,)
        _x182 = g_s*m
        _x183 = _x182*math.sin(i_bottom_q_th)
        _x184 = _i_L1*_x183
        _x185 = _x182*math.sin(q_th_td)
        _x186 = _i_L1*_x185
        _x187 = (0.5)*i_t_bottom
        _x188 = _i_L2*_x183
        _x189 = _x182*math.sin(i_liftoff_q_th)
        _x190 = _i_L2*_x189
        _x191 = -0.5*i_t_bottom + (0.5)*i_t_stance
        i_P_new = _x187*(_x184 + _x186) + _x191*(_x188 + _x190)
        _pd__1 = _x187*(_x183 + _x185)
        _pd__2 = _x191*(_x183 + _x189)
        d_i_P_new__q_rd_td = _d_i_L1__q_rd_td*_pd__1 + _d_i_L2__q_rd_td*_pd__2
        _x192 = _i_L1*_x182*_x187
        d_i_P_new__q_th_td = _x192*math.cos(q_th_td)
        d_i_P_new__i_a = _d_i_L1__i_a*_pd__1 + _d_i_L2__i_a*_pd__2
        d_i_P_new__i_b = _d_i_L1__i_b*_pd__1 + _d_i_L2__i_b*_pd__2
        _x193 = math.cos(i_bottom_q_th)
        _x194 = _i_L2*_x182*_x191
        d_i_P_new__i_bottom_q_th = _x192*_x193 + _x193*_x194
        d_i_P_new__i_liftoff_q_th = _x194*math.cos(i_liftoff_q_th)
        d_i_P_new__i_omega0_hat = _d_i_L1__i_omega0_hat*_pd__1 + _d_i_L2__i_omega0_hat*_pd__2
        d_i_P_new__i_phase_td = _d_i_L1__i_phase_td*_pd__1 + _d_i_L2__i_phase_td*_pd__2
        d_i_P_new__i_q_thd_eff = _d_i_L1__i_q_thd_eff*_pd__1 + _d_i_L2__i_q_thd_eff*_pd__2
        _x195 = (0.5)*_x188
        _x196 = (0.5)*_x190
        d_i_P_new__i_t_bottom = (_d_i_L1__i_t_bottom*_pd__1 + _d_i_L2__i_t_bottom*_pd__2 + (0.5)*_x184
            + (0.5)*_x186 - _x195 - _x196)
        d_i_P_new__i_t_stance = _d_i_L2__i_t_stance*_pd__2 + _x195 + _x196
    else:
        return _NAN14 + (STATUS_INVALID_INPUT,)
    # (internal helper: its callers check that their outputs are finite)
    return (i_P_new, 0.0, d_i_P_new__q_rd_td, d_i_P_new__q_th_td, d_i_P_new__i_a, d_i_P_new__i_b, 0.0,
        d_i_P_new__i_bottom_q_th, d_i_P_new__i_liftoff_q_th, d_i_P_new__i_omega0_hat, d_i_P_new__i_phase_td,
        d_i_P_new__i_q_thd_eff, d_i_P_new__i_t_bottom, d_i_P_new__i_t_stance, STATUS_OK)


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jacobian(x, p, out):
    """Gravity correction type 4 (average leg length on [t_i, t_f]): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Runs the shared body :func:`gravity_stance_jacobian_shared` with
    gravity_impulse_type4_jac13_8638ac. Arguments, returns and status: those of
    :func:`gravity_type0_stance_jacobian`.
    """
    # Total ops: 0
    return gravity_stance_jacobian_shared(x, p, out, gravity_impulse_type4_jac13_8638ac)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type4_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type4_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type4_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy", inline="always")
def gravity_apex_return_jacobian_shared(x, p, out, gravity_stance):
    """Apex-return map by Gravity correction type 0 (leg length l0), and its derivatives with respect to the
    apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48, 49, 50, 51.

    The body that 5 kernels share, each passing the kernel it calls as gravity_stance
    (derive/share.py): gravity_{type0_apex_return_jacobian, type1_apex_return_jacobian,
    type2_apex_return_jacobian, type3_apex_return_jacobian, type4_apex_return_jacobian}.

    Arguments, returns and status: those of the kernels, then gravity_stance.
    """
    # Total ops: 244
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
    # stance: Gravity corrections types 0-4
    _x1 = carray(stack(4), 4)
    store(_x1, (_o0_0, _o0_1, _o0_2, _o0_3,))
    _o1 = carray(stack(72), 72)
    _c1 = gravity_stance(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _o1_10, _o1_11, _j_t_stance__q_rd_td,
        _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _o1_21, _j_liftoff_q_rd__q_rd_td,
        _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k, _j_liftoff_q_th__q_rd_td,
        _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td, _j_liftoff_q_th__k, _j_liftoff_q_thd__q_rd_td,
        _j_liftoff_q_thd__q_th_td, _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k, _j_P_c__q_rd_td,
        _j_P_c__q_th_td, _j_P_c__q_thd_td, _o1_66,) = (load(_o1, 1, 6, 7, 8, 9, 10, 11, 18, 19, 20, 21, 48,
        49, 50, 51, 53, 54, 55, 56, 58, 59, 60, 61, 63, 64, 65, 66))
    # chain rule through gravity_stance
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


@njit(cache=True, error_model="numpy")
def gravity_type0_apex_return_jacobian(x, p, out):
    """Apex-return map by Gravity correction type 0 (leg length l0), and its derivatives with respect to the
    apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48, 49, 50, 51.

    Runs the shared body :func:`gravity_apex_return_jacobian_shared` with
    gravity_type0_stance_jacobian.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, samples, interval, leg_length, iterations, tol); writes
    the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`gravity.gravity_type0_apex_return`, in its order.

    Writes into out:
        <output>: each output of :func:`gravity.gravity_type0_apex_return`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return gravity_apex_return_jacobian_shared(x, p, out, gravity_type0_stance_jacobian)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type0_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type0_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type0_apex_return_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type1_apex_return_jacobian(x, p, out):
    """Apex-return map by Gravity correction type 1 (leg length (l0 + q_r_b)/2), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48, 50, 52, 53, 54.

    Runs the shared body :func:`gravity_apex_return_jacobian_shared` with
    gravity_type1_stance_jacobian. Arguments, returns and status: those of
    :func:`gravity_type0_apex_return_jacobian`.
    """
    # Total ops: 0
    return gravity_apex_return_jacobian_shared(x, p, out, gravity_type1_stance_jacobian)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type1_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type1_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type1_apex_return_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type2_apex_return_jacobian(x, p, out):
    """Apex-return map by Gravity correction type 2 (average leg length), and its derivatives with respect to
    the apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48, 50, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64.

    Runs the shared body :func:`gravity_apex_return_jacobian_shared` with
    gravity_type2_stance_jacobian. Arguments, returns and status: those of
    :func:`gravity_type0_apex_return_jacobian`.
    """
    # Total ops: 0
    return gravity_apex_return_jacobian_shared(x, p, out, gravity_type2_stance_jacobian)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type2_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type2_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type2_apex_return_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type3_apex_return_jacobian(x, p, out):
    """Apex-return map by Gravity correction type 3 (trapezoid on [t_i, t_f]), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48, 50, 65, 66.

    Runs the shared body :func:`gravity_apex_return_jacobian_shared` with
    gravity_type3_stance_jacobian. Arguments, returns and status: those of
    :func:`gravity_type0_apex_return_jacobian`.
    """
    # Total ops: 0
    return gravity_apex_return_jacobian_shared(x, p, out, gravity_type3_stance_jacobian)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type3_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type3_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type3_apex_return_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type4_apex_return_jacobian(x, p, out):
    """Apex-return map by Gravity correction type 4 (average leg length on [t_i, t_f]), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Runs the shared body :func:`gravity_apex_return_jacobian_shared` with
    gravity_type4_stance_jacobian. Arguments, returns and status: those of
    :func:`gravity_type0_apex_return_jacobian`.
    """
    # Total ops: 0
    return gravity_apex_return_jacobian_shared(x, p, out, gravity_type4_stance_jacobian)


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type4_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type4_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = gravity_type4_apex_return_jacobian(row(X, i), p, row(OUT, i))
