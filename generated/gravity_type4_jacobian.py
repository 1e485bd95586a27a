# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/gravity.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:cd017e56afa49b84
#   flight_jacobian.py sha256:138a95b59cb50fe8
#   geyer_jacobian.py sha256:439802d2318bb4fa
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module gravity_type4: JVP kernels, and for
a map its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import fail, finite, into_rows, row, stack
from .flight_jacobian import (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate,
    liftoff_to_apex_jac_q_rd_q_th_q_thd)
from .geyer_jacobian import geyer_liftoff_phase_jac_a_b, geyer_solution_jac_q_r_td_q_rd_td_q_thd_td_k

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_FALL, STATUS_NUMERICAL_RANGE,
    STATUS_NOT_CONVERGED, STATUS_ENERGY_DEFICIT)

NAN = math.nan


@njit(cache=True, error_model="numpy")
def gravity_type4_stance_jacobian(x, p, out):
    """Gravity correction type 4 (average leg length on [t_i, t_f]): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol); writes the
    outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`gravity_type4.gravity_type4_stance`, in its order.

    Writes into out:
        <output>: each output of :func:`gravity_type4.gravity_type4_stance`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 1216
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k, g_s, q_r_lo, reading, interval, leg_length, iterations, tol) = (p[0], p[1], p[2], p[3], p[6],
        p[7], p[8], p[9], p[10], p[11])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) & math.isfinite(q_rd_td) & math.isfinite(q_th_td) & math.isfinite(q_thd_td)
            & math.isfinite(m) & math.isfinite(l0) & math.isfinite(k) & math.isfinite(g_s)
            & math.isfinite(q_r_lo) & math.isfinite(reading) & math.isfinite(interval)
            & math.isfinite(leg_length) & math.isfinite(iterations) & math.isfinite(tol) & ((q_r_td <= l0)
            and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k > 0.0))
            & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((reading == 0.0) or (reading == 1.0))
            & ((interval == 0.0) or (interval == 1.0)) & ((leg_length == 0.0) or (leg_length == 1.0)
            or (leg_length == 2.0)) & ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 1000.0)) & ((tol >= 0.0) and (tol <= 1.0))):
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
        i_omega = _o0[0]
        i_omega0_hat = _o0[1]
        i_a = _o0[2]
        i_b = _o0[3]
        i_phase_td = _o0[4]
        i_s_td = _o0[5]
        _j_i_omega__q_r_td = _o0[6]
        _j_i_omega__q_thd_td = _o0[8]
        _j_i_omega0_hat__q_r_td = _o0[10]
        _j_i_omega0_hat__q_thd_td = _o0[12]
        _j_i_omega0_hat__k = _o0[13]
        _j_i_a__q_r_td = _o0[14]
        _j_i_a__q_thd_td = _o0[16]
        _j_i_a__k = _o0[17]
        _j_i_b__q_r_td = _o0[18]
        _j_i_b__q_rd_td = _o0[19]
        _j_i_b__q_thd_td = _o0[20]
        _j_i_b__k = _o0[21]
        _j_i_phase_td__q_r_td = _o0[22]
        _j_i_phase_td__q_rd_td = _o0[23]
        _j_i_phase_td__q_thd_td = _o0[24]
        _j_i_phase_td__k = _o0[25]
        _j_i_s_td__q_r_td = _o0[26]
        _j_i_s_td__q_rd_td = _o0[27]
        _j_i_s_td__q_thd_td = _o0[28]
        _j_i_s_td__k = _o0[29]
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
        # eq (76)
        if interval == 0.0:
            # average leg length, eqs (55)-(61) / (67)-(75)
            if leg_length == 0.0:
                _x48 = math.cos(i_phase_td)
                _x49 = i_a + 1.0
                _x50 = (1.0/i_omega0_hat)
                _x51 = _x50*i_phase_td
                _x52 = _x51 + i_t_stance
                _x53 = _x52*i_omega0_hat
                _x54 = math.cos(_x53)
                _x55 = _x48*i_b + _x49*_x53 - _x49*i_phase_td - _x54*i_b
                _x56 = (1.0/i_t_stance)
                _x57 = _x50*_x56*l0
                _i_L = _x55*_x57
                _pd__32 = _x57*(_x53 - i_phase_td)
                _pd__33 = _x57*(_x48 - _x54)
                _x58 = math.sin(_x53)
                _x59 = _x58*i_b
                _x60 = _x55*l0
                _pd__34 = -_x50**2*_x56*_x60 + _x57*(-_x49*_x51 + _x49*_x52 + _x59*i_t_stance)
                _pd__35 = _x57*(_x58*i_b - i_b*math.sin(i_phase_td))
                _pd__36 = -_x50*_x56**2*_x60 + _x57*(_x49*i_omega0_hat + _x59*i_omega0_hat)
            elif leg_length == 1.0:
                _x61 = i_omega0_hat*i_t_stance
                _x62 = math.sin(_x61)
                _x63 = i_a*i_t_stance
                _x64 = i_b**2
                _x65 = _x64 - i_a**2
                _x66 = math.sqrt(_x65/_x64)
                _x67 = _x66*i_b
                _x68 = math.cos(_x61)
                _x69 = -_x62*i_a + _x66*_x68*i_b - _x67 + i_omega0_hat*(_x63 + i_t_stance)
                _x70 = (1.0/i_omega0_hat)
                _x71 = (1.0/i_t_stance)
                _x72 = _x70*_x71*l0
                _i_L = _x69*_x72
                _x73 = (1.0/_x65)
                _pd__37 = _x72*(-_x62 + _x66*_x73*i_a*i_b - _x67*_x68*_x73*i_a + i_omega0_hat*i_t_stance)
                _x74 = _x66*_x68
                _x75 = i_b**3
                _x76 = _x73*_x75*(-_x65/_x75 + (1.0/i_b))
                _pd__38 = _x72*(-_x66*_x76 - _x66 + _x74*_x76 + _x74)
                _x77 = _x62*_x67
                _x78 = _x69*l0
                _pd__39 = (-_x70**2*_x71*_x78 + _x72*(-_x63*_x68 - _x77*i_t_stance + i_a*i_t_stance
                    + i_t_stance))
                _pd__40 = (-_x70*_x71**2*_x78 + _x72*(-_x68*i_a*i_omega0_hat - _x77*i_omega0_hat
                    + i_omega0_hat*(i_a + 1.0)))
            elif leg_length == 2.0:
                _x79 = i_omega0_hat*q_rd_td
                _x80 = i_omega0_hat*i_t_stance
                _x81 = math.sin(_x80)
                _x82 = i_q_thd_eff**2*l0
                _x83 = g_s*i_t_stance
                _x84 = math.cos(_x80)
                _x85 = _x84*q_rd_td
                _x86 = i_omega0_hat**2*l0
                _x87 = _x86*i_t_stance
                _x88 = _x82*i_t_stance
                _x89 = _x79 - _x81*_x82 + _x81*g_s - i_omega0_hat*(_x83 + _x85 - _x87 - _x88)
                _x96 = (1.0/i_omega0_hat)
                _x90 = _x96**3
                _x91 = (1.0/i_t_stance)
                _x92 = _x90*_x91
                _i_L = _x89*_x92
                _x93 = 2.0*l0
                _x94 = _x80*_x93
                _pd__41 = (-3.0*_x89*_x91*_x96**4 + _x92*(_x83*_x84 - _x83 - _x84*_x88 - _x85 + _x87 + _x88
                    - i_omega0_hat*(-_x81*i_t_stance*q_rd_td - _x94) + q_rd_td))
                _pd__42 = _x92*(-_x81*_x93*i_q_thd_eff + _x94*i_q_thd_eff)
                _x95 = _x84*i_omega0_hat
                _pd__43 = (-_x89*_x90*_x91**2 + _x92*(-_x82*_x95 + _x84*g_s*i_omega0_hat
                    - i_omega0_hat*(-_x79*_x81 - _x82 - _x86 + g_s)))
                _pd__44 = _x92*(-_x95 + i_omega0_hat)
            else:
                return fail(out, STATUS_INVALID_INPUT)
            _x97 = g_s*m
            _x98 = _x97*math.sin(i_liftoff_q_th)
            _x99 = _i_L*_x98
            _x100 = _x97*math.sin(q_th_td)
            _x101 = _i_L*_x100
            _x102 = (0.5)*i_t_stance
            i_P_new = _x102*(_x101 + _x99)
            _pd__45 = _x102*(_x100 + _x98)
            _x103 = _i_L*_x102*_x97
            _pd__46 = _x103*math.cos(i_liftoff_q_th)
            _pd__47 = (0.5)*_x101 + (0.5)*_x99
            _pd__48 = _x103*math.cos(q_th_td)
        elif interval == 1.0:
            # average leg length, eqs (55)-(61) / (67)-(75)
            if leg_length == 0.0:
                _x104 = math.cos(i_phase_td)
                _x105 = i_a + 1.0
                _x106 = (1.0/i_omega0_hat)
                _x107 = _x106*i_phase_td
                _x108 = _x107 + i_t_bottom
                _x109 = _x108*i_omega0_hat
                _x110 = math.cos(_x109)
                _x111 = _x104*i_b + _x105*_x109 - _x105*i_phase_td - _x110*i_b
                _x112 = (1.0/i_t_bottom)
                _x113 = _x106*_x112*l0
                _i_L1 = _x111*_x113
                _pd__49 = _x113*(_x109 - i_phase_td)
                _pd__50 = _x113*(_x104 - _x110)
                _x114 = math.sin(_x109)
                _x115 = _x114*i_b
                _x116 = _x111*l0
                _pd__51 = -_x106**2*_x112*_x116 + _x113*(-_x105*_x107 + _x105*_x108 + _x115*i_t_bottom)
                _pd__52 = _x113*(_x114*i_b - i_b*math.sin(i_phase_td))
                _pd__53 = -_x106*_x112**2*_x116 + _x113*(_x105*i_omega0_hat + _x115*i_omega0_hat)
            elif leg_length == 1.0:
                _x117 = i_omega0_hat*i_t_bottom
                _x118 = math.sin(_x117)
                _x119 = i_a*i_t_bottom
                _x120 = i_b**2
                _x121 = _x120 - i_a**2
                _x122 = math.sqrt(_x121/_x120)
                _x123 = _x122*i_b
                _x124 = math.cos(_x117)
                _x125 = -_x118*i_a + _x122*_x124*i_b - _x123 + i_omega0_hat*(_x119 + i_t_bottom)
                _x126 = (1.0/i_omega0_hat)
                _x127 = (1.0/i_t_bottom)
                _x128 = _x126*_x127*l0
                _i_L1 = _x125*_x128
                _x129 = (1.0/_x121)
                _pd__54 = (_x128*(-_x118 + _x122*_x129*i_a*i_b - _x123*_x124*_x129*i_a
                    + i_omega0_hat*i_t_bottom))
                _x130 = _x122*_x124
                _x131 = i_b**3
                _x132 = _x129*_x131*(-_x121/_x131 + (1.0/i_b))
                _pd__55 = _x128*(-_x122*_x132 - _x122 + _x130*_x132 + _x130)
                _x133 = _x118*_x123
                _x134 = _x125*l0
                _pd__56 = (-_x126**2*_x127*_x134 + _x128*(-_x119*_x124 - _x133*i_t_bottom + i_a*i_t_bottom
                    + i_t_bottom))
                _pd__57 = (-_x126*_x127**2*_x134 + _x128*(-_x124*i_a*i_omega0_hat - _x133*i_omega0_hat
                    + i_omega0_hat*(i_a + 1.0)))
            elif leg_length == 2.0:
                _x135 = i_omega0_hat*q_rd_td
                _x136 = i_omega0_hat*i_t_bottom
                _x137 = math.sin(_x136)
                _x138 = i_q_thd_eff**2*l0
                _x139 = g_s*i_t_bottom
                _x140 = math.cos(_x136)
                _x141 = _x140*q_rd_td
                _x142 = i_omega0_hat**2*l0
                _x143 = _x142*i_t_bottom
                _x144 = _x138*i_t_bottom
                _x145 = _x135 - _x137*_x138 + _x137*g_s - i_omega0_hat*(_x139 + _x141 - _x143 - _x144)
                _x152 = (1.0/i_omega0_hat)
                _x146 = _x152**3
                _x147 = (1.0/i_t_bottom)
                _x148 = _x146*_x147
                _i_L1 = _x145*_x148
                _x149 = 2.0*l0
                _x150 = _x136*_x149
                _pd__58 = (-3.0*_x145*_x147*_x152**4 + _x148*(_x139*_x140 - _x139 - _x140*_x144 - _x141
                    + _x143 + _x144 - i_omega0_hat*(-_x137*i_t_bottom*q_rd_td - _x150) + q_rd_td))
                _pd__59 = _x148*(-_x137*_x149*i_q_thd_eff + _x150*i_q_thd_eff)
                _x151 = _x140*i_omega0_hat
                _pd__60 = (-_x145*_x146*_x147**2 + _x148*(-_x138*_x151 + _x140*g_s*i_omega0_hat
                    - i_omega0_hat*(-_x135*_x137 - _x138 - _x142 + g_s)))
                _pd__61 = _x148*(-_x151 + i_omega0_hat)
            else:
                return fail(out, STATUS_INVALID_INPUT)
            # average leg length, eqs (55)-(61) / (67)-(75)
            if leg_length == 0.0:
                _x153 = (1.0/i_omega0_hat)
                _x154 = _x153*i_phase_td
                _x155 = _x154 + i_t_bottom
                _x156 = _x155*i_omega0_hat
                _x157 = math.cos(_x156)
                _x158 = i_a + 1.0
                _x159 = _x154 + i_t_stance
                _x160 = _x159*i_omega0_hat
                _x161 = math.cos(_x160)
                _x162 = -_x156*_x158 + _x157*i_b + _x158*_x160 - _x161*i_b
                _x163 = -i_t_bottom + i_t_stance
                _x164 = (1.0/_x163)
                _x165 = _x153*_x164*l0
                _i_L2 = _x162*_x165
                _pd__62 = _x165*(-_x156 + _x159*i_omega0_hat)
                _pd__63 = _x165*(_x157 - _x161)
                _x166 = i_b*math.sin(_x156)
                _x167 = math.sin(_x160)
                _x168 = _x162*l0
                _pd__64 = (-_x153**2*_x164*_x168 + _x165*(-_x155*_x158 + _x158*_x159 - _x166*i_t_bottom
                    + _x167*i_b*i_t_stance))
                _pd__65 = _x165*(-_x166 + _x167*i_b)
                _x169 = _x158*i_omega0_hat
                _x170 = _x153*_x164**2*_x168
                _pd__66 = _x165*(-_x166*i_omega0_hat - _x169) + _x170
                _pd__67 = _x165*(_x167*i_b*i_omega0_hat + _x169) - _x170
            elif leg_length == 1.0:
                _x171 = i_omega0_hat*i_t_bottom
                _x172 = math.sin(_x171)
                _x173 = i_omega0_hat*i_t_stance
                _x174 = math.sin(_x173)
                _x175 = i_a*i_t_bottom
                _x176 = i_t_bottom - i_t_stance
                _x177 = math.cos(_x173)
                _x178 = i_b**2
                _x179 = _x178 - i_a**2
                _x180 = math.sqrt(_x179/_x178)
                _x181 = _x177*_x180*i_b
                _x182 = math.cos(_x171)
                _x183 = _x180*_x182
                _x184 = _x183*i_b
                _x185 = _x172*i_a - _x174*i_a + _x181 - _x184 + i_omega0_hat*(-_x175 - _x176 + i_a*i_t_stance)
                _x186 = (1.0/i_omega0_hat)
                _x187 = -_x176
                _x188 = (1.0/_x187)
                _x189 = _x186*_x188*l0
                _i_L2 = _x185*_x189
                _x190 = (1.0/_x179)
                _x191 = _x190*i_a
                _pd__68 = _x189*(_x172 - _x174 - _x181*_x191 + _x184*_x191 + _x187*i_omega0_hat)
                _x192 = i_b**3
                _x193 = -_x179/_x192 + (1.0/i_b)
                _pd__69 = (_x189*(_x177*_x180*_x190*_x192*_x193 + _x177*_x180 - _x183*_x190*_x192*_x193
                    - _x183))
                _x194 = _x185*l0
                _x195 = i_a*i_t_stance
                _x196 = _x180*i_b
                _x197 = _x172*_x196
                _x198 = _x174*_x196
                _pd__70 = (-_x186**2*_x188*_x194 + _x189*(_x175*_x182 - _x175 - _x177*_x195 + _x195
                    + _x197*i_t_bottom - _x198*i_t_stance - i_t_bottom + i_t_stance))
                _x199 = i_a + 1.0
                _x200 = i_a*i_omega0_hat
                _x201 = _x186*_x188**2*_x194
                _pd__71 = _x189*(_x182*_x200 + _x197*i_omega0_hat - _x199*i_omega0_hat) + _x201
                _pd__72 = _x189*(-_x177*_x200 - _x198*i_omega0_hat + _x199*i_omega0_hat) - _x201
            elif leg_length == 2.0:
                _x202 = i_omega0_hat*i_t_bottom
                _x203 = math.sin(_x202)
                _x204 = i_omega0_hat*i_t_stance
                _x205 = math.sin(_x204)
                _x206 = i_q_thd_eff**2
                _x207 = _x206*l0
                _x208 = math.cos(_x204)
                _x209 = i_omega0_hat**2*l0
                _x210 = _x207*i_t_stance
                _x211 = _x208*q_rd_td - _x209*i_t_stance - _x210 + g_s*i_t_stance
                _x212 = g_s*i_t_bottom
                _x213 = math.cos(_x202)
                _x214 = _x209*i_t_bottom
                _x215 = _x207*i_t_bottom
                _x216 = (_x203*_x206*l0 - _x203*g_s - _x205*_x207 + _x205*g_s - _x211*i_omega0_hat
                    + i_omega0_hat*(_x212 + _x213*q_rd_td - _x214 - _x215))
                _x229 = (1.0/i_omega0_hat)
                _x217 = _x229**3
                _x218 = -i_t_bottom + i_t_stance
                _x219 = (1.0/_x218)
                _x220 = _x217*_x219
                _i_L2 = _x216*_x220
                _x221 = 2.0*l0
                _x222 = _x205*q_rd_td
                _x223 = _x202*_x221
                _x224 = _x203*q_rd_td
                _pd__73 = (-3.0*_x216*_x219*_x229**4 + _x220*(_x206*_x213*i_t_bottom*l0 - _x208*_x210
                    + _x208*g_s*i_t_stance - _x211 - _x212*_x213 + _x213*q_rd_td - _x214 - _x215
                    + g_s*i_t_bottom + i_omega0_hat*(-_x223 - _x224*i_t_bottom) - i_omega0_hat*(-_x204*_x221
                    - _x222*i_t_stance)))
                _pd__74 = (_x220*(2.0*_x203*i_q_thd_eff*l0 - _x205*_x221*i_q_thd_eff - _x223*i_q_thd_eff
                    + 2.0*i_omega0_hat*i_q_thd_eff*i_t_stance*l0))
                _x225 = _x213*i_omega0_hat
                _x226 = _x207 + _x209 - g_s
                _x227 = _x216*_x217*_x219**2
                _pd__75 = _x220*(_x207*_x225 - _x225*g_s + i_omega0_hat*(-_x224*i_omega0_hat - _x226)) + _x227
                _x228 = _x208*i_omega0_hat
                _pd__76 = (_x220*(-_x207*_x228 + _x208*g_s*i_omega0_hat - i_omega0_hat*(-_x222*i_omega0_hat
                    - _x226)) - _x227)
                _pd__77 = _x220*(_x225 - _x228)
            else:
                return fail(out, STATUS_INVALID_INPUT)
            _x230 = g_s*m
            _x231 = _x230*math.sin(i_bottom_q_th)
            _x232 = _i_L1*_x231
            _x233 = _x230*math.sin(q_th_td)
            _x234 = _i_L1*_x233
            _x235 = (0.5)*i_t_bottom
            _x236 = _i_L2*_x231
            _x237 = _x230*math.sin(i_liftoff_q_th)
            _x238 = _i_L2*_x237
            _x239 = -0.5*i_t_bottom + (0.5)*i_t_stance
            i_P_new = _x235*(_x232 + _x234) + _x239*(_x236 + _x238)
            _pd__78 = _x235*(_x231 + _x233)
            _pd__79 = _x239*(_x231 + _x237)
            _x240 = _x230*math.cos(i_bottom_q_th)
            _x241 = _i_L1*_x235
            _x242 = _i_L2*_x239
            _pd__80 = _x240*_x241 + _x240*_x242
            _pd__81 = _x230*_x242*math.cos(i_liftoff_q_th)
            _x243 = (0.5)*_x236
            _x244 = (0.5)*_x238
            _pd__82 = (0.5)*_x232 + (0.5)*_x234 - _x243 - _x244
            _pd__83 = _x243 + _x244
            _pd__84 = _x230*_x241*math.cos(q_th_td)
        else:
            return fail(out, STATUS_INVALID_INPUT)
        # next values
        P_c__next = i_P_new
        # the next state's tangents, once per direction
        for _j2 in range(5):
            d_q_rd_td__j = _T[3, _j2]
            d_q_th_td__j = _T[4, _j2]
            d_i_q_thd_eff__j = _T[6, _j2]
            d_i_omega0_hat__j = _T[7, _j2]
            d_i_a__j = _T[8, _j2]
            d_i_b__j = _T[9, _j2]
            d_i_phase_td__j = _T[10, _j2]
            d_i_t_bottom__j = _T[11, _j2]
            d_i_t_stance__j = _T[12, _j2]
            d_i_bottom_q_th__j = _T[14, _j2]
            d_i_liftoff_q_th__j = _T[16, _j2]
            # eq (76)
            if interval == 0.0:
                # average leg length, eqs (55)-(61) / (67)-(75)
                if leg_length == 0.0:
                    _d_i_L__j = (_pd__32*d_i_a__j + _pd__33*d_i_b__j + _pd__34*d_i_omega0_hat__j
                        + _pd__35*d_i_phase_td__j + _pd__36*d_i_t_stance__j)
                elif leg_length == 1.0:
                    _d_i_L__j = (_pd__37*d_i_a__j + _pd__38*d_i_b__j + _pd__39*d_i_omega0_hat__j
                        + _pd__40*d_i_t_stance__j)
                elif leg_length == 2.0:
                    _d_i_L__j = (_pd__41*d_i_omega0_hat__j + _pd__42*d_i_q_thd_eff__j
                        + _pd__43*d_i_t_stance__j + _pd__44*d_q_rd_td__j)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
                d_i_P_new__j = (_d_i_L__j*_pd__45 + _pd__46*d_i_liftoff_q_th__j + _pd__47*d_i_t_stance__j
                    + _pd__48*d_q_th_td__j)
            elif interval == 1.0:
                # average leg length, eqs (55)-(61) / (67)-(75)
                if leg_length == 0.0:
                    _d_i_L1__j = (_pd__49*d_i_a__j + _pd__50*d_i_b__j + _pd__51*d_i_omega0_hat__j
                        + _pd__52*d_i_phase_td__j + _pd__53*d_i_t_bottom__j)
                elif leg_length == 1.0:
                    _d_i_L1__j = (_pd__54*d_i_a__j + _pd__55*d_i_b__j + _pd__56*d_i_omega0_hat__j
                        + _pd__57*d_i_t_bottom__j)
                elif leg_length == 2.0:
                    _d_i_L1__j = (_pd__58*d_i_omega0_hat__j + _pd__59*d_i_q_thd_eff__j
                        + _pd__60*d_i_t_bottom__j + _pd__61*d_q_rd_td__j)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
                # average leg length, eqs (55)-(61) / (67)-(75)
                if leg_length == 0.0:
                    _d_i_L2__j = (_pd__62*d_i_a__j + _pd__63*d_i_b__j + _pd__64*d_i_omega0_hat__j
                        + _pd__65*d_i_phase_td__j + _pd__66*d_i_t_bottom__j + _pd__67*d_i_t_stance__j)
                elif leg_length == 1.0:
                    _d_i_L2__j = (_pd__68*d_i_a__j + _pd__69*d_i_b__j + _pd__70*d_i_omega0_hat__j
                        + _pd__71*d_i_t_bottom__j + _pd__72*d_i_t_stance__j)
                elif leg_length == 2.0:
                    _d_i_L2__j = (_pd__73*d_i_omega0_hat__j + _pd__74*d_i_q_thd_eff__j
                        + _pd__75*d_i_t_bottom__j + _pd__76*d_i_t_stance__j + _pd__77*d_q_rd_td__j)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
                d_i_P_new__j = (_d_i_L1__j*_pd__78 + _d_i_L2__j*_pd__79 + _pd__80*d_i_bottom_q_th__j
                    + _pd__81*d_i_liftoff_q_th__j + _pd__82*d_i_t_bottom__j + _pd__83*d_i_t_stance__j
                    + _pd__84*d_q_th_td__j)
            else:
                return fail(out, STATUS_INVALID_INPUT)
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
    _x253 = (1.0/i_t_stance)
    _x245 = _x253*ramp
    _x246 = _x245*i_t_bottom - ramp + 1.0
    _x247 = P_c*_x246 + p_td
    _x248 = (1.0/m)
    _x252 = (1.0/i_bottom_q_r)
    _x249 = _x248*_x252**2
    bottom_q_thd = _x247*_x249
    _pd__85 = _x246*_x249
    _pd__86 = -2.0*_x247*_x248*_x252**3
    _x250 = P_c*_x249
    _pd__87 = _x245*_x250
    _pd__88 = -_x250*_x253**2*i_t_bottom*ramp
    _pd__89 = _x249
    liftoff_q_r = q_r_lo
    liftoff_q_th = i_liftoff_q_th
    _x251 = _x248/q_r_lo**2
    liftoff_q_thd = _x251*(P_c + p_td)
    _pd__90 = _x251
    _pd__91 = _x251
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
        d_bottom_q_thd__j = (_pd__85*d_P_c__j + _pd__86*d_i_bottom_q_r__j + _pd__87*d_i_t_bottom__j
            + _pd__88*d_i_t_stance__j + _pd__89*d_p_td__j)
        d_liftoff_q_thd__j = _pd__90*d_P_c__j + _pd__91*d_p_td__j
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
        _x254 = (1.0/m)
        _x255 = 2.0*g_s*q_r_lo
        _x256 = _x254*l0**2
        _x257 = q_r_lo**2
        _x258 = _x254*_x257
        _x259 = _x254**2/_x257
        _q_rd_lo_sq = (2.0*E_td*_x254 + 2.0*_x254*k*l0*q_r_lo - _x255*math.cos(i_liftoff_q_th) - _x256*k
            - _x258*k - _x259*(P_c + p_td)**2)
        _x260 = 2.0*_x254
        _pd__92 = _x260
        _x261 = -_x259*(2.0*P_c + 2.0*p_td)
        _pd__93 = _x261
        _pd__94 = _x255*math.sin(i_liftoff_q_th)
        _pd__95 = _x261
        _d_q_rd_lo_sq__q_r_td = (_pd__92*d_E_td__q_r_td + _pd__93*d_P_c__q_r_td
            + _pd__94*d_i_liftoff_q_th__q_r_td + _pd__95*d_p_td__q_r_td)
        _d_q_rd_lo_sq__q_rd_td = (_pd__92*d_E_td__q_rd_td + _pd__93*d_P_c__q_rd_td
            + _pd__94*d_i_liftoff_q_th__q_rd_td)
        _d_q_rd_lo_sq__q_th_td = (_pd__92*d_E_td__q_th_td + _pd__93*d_P_c__q_th_td
            + _pd__94*d_i_liftoff_q_th__q_th_td)
        _d_q_rd_lo_sq__q_thd_td = (_pd__92*d_E_td__q_thd_td + _pd__93*d_P_c__q_thd_td
            + _pd__94*d_i_liftoff_q_th__q_thd_td + _pd__95*d_p_td__q_thd_td)
        _d_q_rd_lo_sq__k = (_pd__92*d_E_td__k + _pd__93*d_P_c__k + _pd__94*d_i_liftoff_q_th__k - _x256 - _x258
            + _x260*l0*q_r_lo)
        # q_rd_lo^2 from the energy (27)
        if not ((_q_rd_lo_sq >= 0.0)):
            return fail(out, STATUS_ENERGY_DEFICIT)
        # q_rd_lo from the energy
        _x262 = math.sqrt(_q_rd_lo_sq)
        liftoff_q_rd = _x262
        _pd__96 = (0.5)/_x262
        d_liftoff_q_rd__q_r_td = _d_q_rd_lo_sq__q_r_td*_pd__96
        d_liftoff_q_rd__q_rd_td = _d_q_rd_lo_sq__q_rd_td*_pd__96
        d_liftoff_q_rd__q_th_td = _d_q_rd_lo_sq__q_th_td*_pd__96
        d_liftoff_q_rd__q_thd_td = _d_q_rd_lo_sq__q_thd_td*_pd__96
        d_liftoff_q_rd__k = _d_q_rd_lo_sq__k*_pd__96
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
    (out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8], out[9], out[10], out[11],
        out[12], out[13], out[14], out[15], out[16], out[17], out[18], out[19], out[20], out[21], out[22],
        out[23], out[24], out[25], out[26], out[27], out[28], out[29], out[30], out[31], out[32], out[33],
        out[34], out[35], out[36], out[37], out[38], out[39], out[40], out[41], out[42], out[43], out[44],
        out[45], out[46], out[47], out[48], out[49], out[50], out[51], out[52], out[53], out[54], out[55],
        out[56], out[57], out[58], out[59], out[60], out[61], out[62], out[63], out[64], out[65], out[66],
        out[67], out[68], out[69], out[70], out[71],) = (t_bottom, t_stance, bottom_q_r, 0.0, bottom_q_th,
        bottom_q_thd, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c, passes, d_t_bottom__q_r_td,
        d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k, d_t_stance__q_r_td,
        d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td, d_t_stance__k, d_bottom_q_r__q_r_td,
        d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td, d_bottom_q_r__q_thd_td, d_bottom_q_r__k, 0.0, 0.0, 0.0,
        0.0, 0.0, d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td,
        d_bottom_q_th__q_thd_td, d_bottom_q_th__k, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td,
        d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k, 0.0, 0.0, 0.0, 0.0, 0.0,
        d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__q_thd_td,
        d_liftoff_q_rd__k, d_liftoff_q_th__q_r_td, d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td,
        d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td,
        d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k, d_P_c__q_r_td,
        d_P_c__q_rd_td, d_P_c__q_th_td, d_P_c__q_thd_td, d_P_c__k, 0.0, 0.0, 0.0, 0.0, 0.0,)
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type4_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type4_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = gravity_type4_stance_jacobian(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_type4_apex_return_jacobian(x, p, out):
    """Apex-return map by Gravity correction type 4 (average leg length on [t_i, t_f]), and its derivatives
    with respect to the apex, the touchdown angle and the stiffness.

    Report equations: 46, 47, 48, 50, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol); writes the
    outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`gravity_type4.gravity_type4_apex_return`, in its order.

    Writes into out:
        <output>: each output of :func:`gravity_type4.gravity_type4_apex_return`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 244
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) = (x[0], x[1], x[2], x[3], x[4])
    (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, interval, leg_length, iterations, tol) = (p[0], p[1], p[2],
        p[3], p[4], p[5], p[6], p[7], p[8], p[9], p[10], p[11])
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) & math.isfinite(b_xd_apex) & math.isfinite(q_th_td)
            & math.isfinite(ground) & math.isfinite(retraction_rate) & math.isfinite(m) & math.isfinite(l0)
            & math.isfinite(k) & math.isfinite(g_s) & math.isfinite(g_f) & math.isfinite(q_r_td)
            & math.isfinite(q_r_lo) & math.isfinite(reading) & math.isfinite(interval)
            & math.isfinite(leg_length) & math.isfinite(iterations) & math.isfinite(tol) & ((b_y_apex >= 0.0))
            & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k > 0.0)) & ((g_s > 0.0))
            & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))
            & ((reading == 0.0) or (reading == 1.0)) & ((interval == 0.0) or (interval == 1.0)) & ((leg_length
            == 0.0) or (leg_length == 1.0) or (leg_length == 2.0)) & ((iterations == math.floor(iterations))
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
    foot_x = _o0[5]
    _j_td_q_rd__b_y_apex = _o0[11]
    _j_td_q_rd__b_xd_apex = _o0[12]
    _j_td_q_rd__q_th_td = _o0[13]
    _j_td_q_rd__ground = _o0[14]
    _j_td_q_rd__retraction_rate = _o0[15]
    _j_td_q_th__b_y_apex = _o0[16]
    _j_td_q_th__q_th_td = _o0[18]
    _j_td_q_th__ground = _o0[19]
    _j_td_q_th__retraction_rate = _o0[20]
    _j_td_q_thd__b_y_apex = _o0[21]
    _j_td_q_thd__b_xd_apex = _o0[22]
    _j_td_q_thd__q_th_td = _o0[23]
    _j_td_q_thd__ground = _o0[24]
    _j_td_q_thd__retraction_rate = _o0[25]
    _j_foot_x__b_y_apex = _o0[31]
    _j_foot_x__b_xd_apex = _o0[32]
    _j_foot_x__q_th_td = _o0[33]
    _j_foot_x__ground = _o0[34]
    _j_foot_x__retraction_rate = _o0[35]
    # stance: Gravity correction type 4 (average leg length on [t_i, t_f])
    _x1 = carray(stack(4), 4)
    (_x1[0], _x1[1], _x1[2], _x1[3],) = (_o0[0], _o0[1], _o0[2], _o0[3],)
    _o1 = carray(stack(72), 72)
    _c1 = gravity_type4_stance_jacobian(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    liftoff_q_r = _o1[6]
    liftoff_q_rd = _o1[7]
    liftoff_q_th = _o1[8]
    liftoff_q_thd = _o1[9]
    _j_t_stance__q_rd_td = _o1[18]
    _j_t_stance__q_th_td = _o1[19]
    _j_t_stance__q_thd_td = _o1[20]
    _j_liftoff_q_rd__q_rd_td = _o1[48]
    _j_liftoff_q_rd__q_th_td = _o1[49]
    _j_liftoff_q_rd__q_thd_td = _o1[50]
    _j_liftoff_q_rd__k = _o1[51]
    _j_liftoff_q_th__q_rd_td = _o1[53]
    _j_liftoff_q_th__q_th_td = _o1[54]
    _j_liftoff_q_th__q_thd_td = _o1[55]
    _j_liftoff_q_th__k = _o1[56]
    _j_liftoff_q_thd__q_rd_td = _o1[58]
    _j_liftoff_q_thd__q_th_td = _o1[59]
    _j_liftoff_q_thd__q_thd_td = _o1[60]
    _j_liftoff_q_thd__k = _o1[61]
    _j_P_c__q_rd_td = _o1[63]
    _j_P_c__q_th_td = _o1[64]
    _j_P_c__q_thd_td = _o1[65]
    # chain rule through gravity_type4_stance
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
    next_apex_x = _o2[4]
    _j_apex_height__q_rd = _o2[5]
    _j_apex_height__q_th = _o2[6]
    _j_apex_height__q_thd = _o2[7]
    _j_apex_speed__q_rd = _o2[8]
    _j_apex_speed__q_th = _o2[9]
    _j_apex_speed__q_thd = _o2[10]
    _j_t_ascent__q_rd = _o2[11]
    _j_t_ascent__q_th = _o2[12]
    _j_t_ascent__q_thd = _o2[13]
    _j_next_apex_x__q_rd = _o2[17]
    _j_next_apex_x__q_th = _o2[18]
    _j_next_apex_x__q_thd = _o2[19]
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
    (out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8], out[9], out[10], out[11],
        out[12], out[13], out[14], out[15], out[16], out[17], out[18], out[19], out[20], out[21], out[22],
        out[23], out[24], out[25], out[26], out[27], out[28], out[29], out[30], out[31], out[32], out[33],
        out[34], out[35], out[36], out[37], out[38], out[39], out[40], out[41], out[42], out[43], out[44],
        out[45], out[46], out[47], out[48], out[49], out[50], out[51], out[52], out[53], out[54], out[55],
        out[56], out[57], out[58], out[59], out[60], out[61], out[62], out[63], out[64], out[65], out[66],
        out[67], out[68], out[69], out[70], out[71], out[72], out[73], out[74], out[75], out[76], out[77],
        out[78], out[79], out[80], out[81], out[82], out[83], out[84], out[85], out[86], out[87], out[88],
        out[89], out[90], out[91], out[92], out[93], out[94], out[95], out[96], out[97], out[98], out[99],
        out[100], out[101], out[102], out[103], out[104],) = (_o2[0], _o2[1], _o0[4], _o1[1], _o2[2],
        liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, _o0[2], _o1[10],
        _o1[11], d_apex_height__b_y_apex, d_apex_height__b_xd_apex, d_apex_height__q_th_td,
        d_apex_height__ground, d_apex_height__retraction_rate, d_apex_height__k, d_apex_speed__b_y_apex,
        d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__retraction_rate,
        d_apex_speed__k, _o0[26], 0.0, _o0[28], _o0[29], _o0[30], 0.0, d_t_stance__b_y_apex,
        d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground, d_t_stance__retraction_rate, _o1[21],
        d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex, d_t_ascent__q_th_td, d_t_ascent__ground,
        d_t_ascent__retraction_rate, d_t_ascent__k, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, d_liftoff_q_rd__b_y_apex,
        d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground,
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
        d_P_c__ground, d_P_c__retraction_rate, _o1[66], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,)
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def gravity_type4_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_type4_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = gravity_type4_apex_return_jacobian(row(X, i), row(P, min(i, last)), row(OUT, i))
