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
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module gravity: JVP kernels, and for a map
its stance and apex-return Jacobians."""

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
def gravity_stance_jacobian(x, p, out):
    """Gravity corrections types 0-4: stance outputs and their derivatives with respect to the touchdown state
    and the stiffness.

    Report equations: 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67,
    68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, samples, interval, leg_length, rule, iterations, tol);
    writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`gravity.gravity_stance`, in its order.

    Writes into out:
        <output>: each output of :func:`gravity.gravity_stance`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 1712
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k, g_s, q_r_lo, reading, samples, interval, leg_length, rule, iterations, tol) = (p[0], p[1],
        p[2], p[3], p[6], p[7], p[8], p[9], p[10], p[11], p[12], p[13])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) & math.isfinite(q_rd_td) & math.isfinite(q_th_td) & math.isfinite(q_thd_td)
            & math.isfinite(m) & math.isfinite(l0) & math.isfinite(k) & math.isfinite(g_s)
            & math.isfinite(q_r_lo) & math.isfinite(reading) & math.isfinite(samples)
            & math.isfinite(interval) & math.isfinite(leg_length) & math.isfinite(rule)
            & math.isfinite(iterations) & math.isfinite(tol) & ((q_r_td <= l0) and (q_r_td > 0.0))
            & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k > 0.0)) & ((g_s > 0.0))
            & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((reading == 0.0) or (reading == 1.0)) & ((samples
            == math.floor(samples)) and (samples >= 2.0) and (samples <= 3.0)) & ((interval == 0.0)
            or (interval == 1.0)) & ((leg_length == 0.0) or (leg_length == 1.0) or (leg_length == 2.0))
            & ((rule == math.floor(rule)) and (rule >= 0.0) and (rule <= 4.0)) & ((iterations
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
        # the impulse rule of the correction type
        if rule == 0.0:
            # eq (48) with 2 or 3 samples
            if samples == 2.0:
                _x48 = g_s*l0*m
                _x49 = _x48*math.sin(i_liftoff_q_th)
                _x50 = _x48*math.sin(q_th_td)
                _x51 = (0.5)*i_t_stance
                i_P_new = _x51*(_x49 + _x50)
                _x52 = _x48*_x51
                _pd__32 = _x52*math.cos(i_liftoff_q_th)
                _pd__33 = (0.5)*_x49 + (0.5)*_x50
                _pd__34 = _x52*math.cos(q_th_td)
            elif samples == 3.0:
                _x53 = g_s*l0*m
                _x54 = _x53*math.sin(i_bottom_q_th)
                _x55 = _x53*math.sin(i_liftoff_q_th)
                _x56 = _x53*math.sin(q_th_td)
                _x57 = (0.3333333333333333)*i_t_stance
                i_P_new = _x57*(_x54 + _x55 + _x56)
                _x58 = _x53*_x57
                _pd__35 = _x58*math.cos(i_bottom_q_th)
                _pd__36 = _x58*math.cos(i_liftoff_q_th)
                _pd__37 = (0.3333333333333333)*_x54 + (0.3333333333333333)*_x55 + (0.3333333333333333)*_x56
                _pd__38 = _x58*math.cos(q_th_td)
            else:
                return fail(out, STATUS_INVALID_INPUT)
        elif rule == 1.0:
            # eq (48) with 2 or 3 samples
            if samples == 2.0:
                _x59 = math.sin(i_liftoff_q_th)
                _x60 = g_s*m
                _x61 = _x60*((0.5)*i_bottom_q_r + (0.5)*l0)
                _x62 = _x59*_x61
                _x63 = math.sin(q_th_td)
                _x64 = _x61*_x63
                _x65 = (0.5)*i_t_stance
                i_P_new = _x65*(_x62 + _x64)
                _x66 = (0.5)*_x60
                _pd__39 = _x65*(_x59*_x66 + _x63*_x66)
                _x67 = _x61*_x65
                _pd__40 = _x67*math.cos(i_liftoff_q_th)
                _pd__41 = (0.5)*_x62 + (0.5)*_x64
                _pd__42 = _x67*math.cos(q_th_td)
            elif samples == 3.0:
                _x68 = math.sin(i_bottom_q_th)
                _x69 = g_s*m
                _x70 = _x69*((0.5)*i_bottom_q_r + (0.5)*l0)
                _x71 = _x68*_x70
                _x72 = math.sin(i_liftoff_q_th)
                _x73 = _x70*_x72
                _x74 = math.sin(q_th_td)
                _x75 = _x70*_x74
                _x76 = (0.3333333333333333)*i_t_stance
                i_P_new = _x76*(_x71 + _x73 + _x75)
                _x77 = (0.5)*_x69
                _pd__43 = _x76*(_x68*_x77 + _x72*_x77 + _x74*_x77)
                _x78 = _x70*_x76
                _pd__44 = _x78*math.cos(i_bottom_q_th)
                _pd__45 = _x78*math.cos(i_liftoff_q_th)
                _pd__46 = (0.3333333333333333)*_x71 + (0.3333333333333333)*_x73 + (0.3333333333333333)*_x75
                _pd__47 = _x78*math.cos(q_th_td)
            else:
                return fail(out, STATUS_INVALID_INPUT)
        elif rule == 2.0:
            # average leg length, eqs (55)-(61) / (67)-(75)
            if leg_length == 0.0:
                _x79 = math.cos(i_phase_td)
                _x80 = i_a + 1.0
                _x81 = (1.0/i_omega0_hat)
                _x82 = _x81*i_phase_td
                _x83 = _x82 + i_t_stance
                _x84 = _x83*i_omega0_hat
                _x85 = math.cos(_x84)
                _x86 = _x79*i_b + _x80*_x84 - _x80*i_phase_td - _x85*i_b
                _x87 = (1.0/i_t_stance)
                _x88 = _x81*_x87*l0
                _i_L = _x86*_x88
                _pd__48 = _x88*(_x84 - i_phase_td)
                _pd__49 = _x88*(_x79 - _x85)
                _x89 = math.sin(_x84)
                _x90 = _x89*i_b
                _x91 = _x86*l0
                _pd__50 = -_x81**2*_x87*_x91 + _x88*(-_x80*_x82 + _x80*_x83 + _x90*i_t_stance)
                _pd__51 = _x88*(_x89*i_b - i_b*math.sin(i_phase_td))
                _pd__52 = -_x81*_x87**2*_x91 + _x88*(_x80*i_omega0_hat + _x90*i_omega0_hat)
            elif leg_length == 1.0:
                _x92 = i_omega0_hat*i_t_stance
                _x93 = math.sin(_x92)
                _x94 = i_a*i_t_stance
                _x95 = i_b**2
                _x96 = _x95 - i_a**2
                _x97 = math.sqrt(_x96/_x95)
                _x98 = _x97*i_b
                _x99 = math.cos(_x92)
                _x100 = -_x93*i_a + _x97*_x99*i_b - _x98 + i_omega0_hat*(_x94 + i_t_stance)
                _x101 = (1.0/i_omega0_hat)
                _x102 = (1.0/i_t_stance)
                _x103 = _x101*_x102*l0
                _i_L = _x100*_x103
                _x104 = (1.0/_x96)
                _pd__53 = _x103*(_x104*_x97*i_a*i_b - _x104*_x98*_x99*i_a - _x93 + i_omega0_hat*i_t_stance)
                _x105 = _x97*_x99
                _x106 = i_b**3
                _x107 = _x104*_x106*((1.0/i_b) - _x96/_x106)
                _pd__54 = _x103*(_x105*_x107 + _x105 - _x107*_x97 - _x97)
                _x108 = _x93*_x98
                _x109 = _x100*l0
                _pd__55 = (-_x101**2*_x102*_x109 + _x103*(-_x108*i_t_stance - _x94*_x99 + i_a*i_t_stance
                    + i_t_stance))
                _pd__56 = (-_x101*_x102**2*_x109 + _x103*(-_x108*i_omega0_hat - _x99*i_a*i_omega0_hat
                    + i_omega0_hat*(i_a + 1.0)))
            elif leg_length == 2.0:
                _x110 = i_omega0_hat*q_rd_td
                _x111 = i_omega0_hat*i_t_stance
                _x112 = math.sin(_x111)
                _x113 = i_q_thd_eff**2*l0
                _x114 = g_s*i_t_stance
                _x115 = math.cos(_x111)
                _x116 = _x115*q_rd_td
                _x117 = i_omega0_hat**2*l0
                _x118 = _x117*i_t_stance
                _x119 = _x113*i_t_stance
                _x120 = _x110 - _x112*_x113 + _x112*g_s - i_omega0_hat*(_x114 + _x116 - _x118 - _x119)
                _x127 = (1.0/i_omega0_hat)
                _x121 = _x127**3
                _x122 = (1.0/i_t_stance)
                _x123 = _x121*_x122
                _i_L = _x120*_x123
                _x124 = 2.0*l0
                _x125 = _x111*_x124
                _pd__57 = (-3.0*_x120*_x122*_x127**4 + _x123*(_x114*_x115 - _x114 - _x115*_x119 - _x116
                    + _x118 + _x119 - i_omega0_hat*(-_x112*i_t_stance*q_rd_td - _x125) + q_rd_td))
                _pd__58 = _x123*(-_x112*_x124*i_q_thd_eff + _x125*i_q_thd_eff)
                _x126 = _x115*i_omega0_hat
                _pd__59 = (-_x120*_x121*_x122**2 + _x123*(-_x113*_x126 + _x115*g_s*i_omega0_hat
                    - i_omega0_hat*(-_x110*_x112 - _x113 - _x117 + g_s)))
                _pd__60 = _x123*(-_x126 + i_omega0_hat)
            else:
                return fail(out, STATUS_INVALID_INPUT)
            # eq (48) with 2 or 3 samples
            if samples == 2.0:
                _x128 = g_s*m
                _x129 = _x128*math.sin(i_liftoff_q_th)
                _x130 = _i_L*_x129
                _x131 = _x128*math.sin(q_th_td)
                _x132 = _i_L*_x131
                _x133 = (0.5)*i_t_stance
                i_P_new = _x133*(_x130 + _x132)
                _pd__61 = _x133*(_x129 + _x131)
                _x134 = _i_L*_x128*_x133
                _pd__62 = _x134*math.cos(i_liftoff_q_th)
                _pd__63 = (0.5)*_x130 + (0.5)*_x132
                _pd__64 = _x134*math.cos(q_th_td)
            elif samples == 3.0:
                _x135 = g_s*m
                _x136 = _x135*math.sin(i_bottom_q_th)
                _x137 = _i_L*_x136
                _x138 = _x135*math.sin(i_liftoff_q_th)
                _x139 = _i_L*_x138
                _x140 = _x135*math.sin(q_th_td)
                _x141 = _i_L*_x140
                _x142 = (0.3333333333333333)*i_t_stance
                i_P_new = _x142*(_x137 + _x139 + _x141)
                _pd__65 = _x142*(_x136 + _x138 + _x140)
                _x143 = _i_L*_x135*_x142
                _pd__66 = _x143*math.cos(i_bottom_q_th)
                _pd__67 = _x143*math.cos(i_liftoff_q_th)
                _pd__68 = (0.3333333333333333)*_x137 + (0.3333333333333333)*_x139 + (0.3333333333333333)*_x141
                _pd__69 = _x143*math.cos(q_th_td)
            else:
                return fail(out, STATUS_INVALID_INPUT)
        elif rule == 3.0:
            # eq (65)
            if interval == 0.0:
                _x144 = g_s*m
                _x145 = _x144*q_r_lo
                _x146 = _x145*math.sin(i_liftoff_q_th)
                _x147 = _x144*math.sin(q_th_td)
                _x148 = _x147*q_r_td
                _x149 = (0.5)*i_t_stance
                i_P_new = _x149*(_x146 + _x148)
                _pd__70 = _x145*_x149*math.cos(i_liftoff_q_th)
                _pd__71 = (0.5)*_x146 + (0.5)*_x148
                _pd__72 = _x147*_x149
                _pd__73 = _x144*_x149*q_r_td*math.cos(q_th_td)
            elif interval == 1.0:
                _x150 = g_s*m
                _x151 = _x150*math.sin(i_bottom_q_th)
                _x152 = _x151*i_bottom_q_r
                _x153 = math.sin(q_th_td)
                _x154 = _x150*_x153
                _x155 = (0.5)*i_t_bottom
                _x156 = _x150*q_r_lo
                _x157 = _x156*math.sin(i_liftoff_q_th)
                _x158 = -0.5*i_t_bottom + (0.5)*i_t_stance
                i_P_new = _x155*(_x152 + _x154*q_r_td) + _x158*(_x152 + _x157)
                _pd__74 = _x151*_x155 + _x151*_x158
                _x159 = _x150*_x155
                _x160 = i_bottom_q_r*math.cos(i_bottom_q_th)
                _pd__75 = _x150*_x158*_x160 + _x159*_x160
                _pd__76 = _x156*_x158*math.cos(i_liftoff_q_th)
                _x161 = (0.5)*_x157
                _pd__77 = (0.5)*_x153*g_s*m*q_r_td - _x161
                _pd__78 = (0.5)*_x152 + _x161
                _pd__79 = _x154*_x155
                _pd__80 = _x159*q_r_td*math.cos(q_th_td)
            else:
                return fail(out, STATUS_INVALID_INPUT)
        elif rule == 4.0:
            # eq (76)
            if interval == 0.0:
                # average leg length, eqs (55)-(61) / (67)-(75)
                if leg_length == 0.0:
                    _x162 = math.cos(i_phase_td)
                    _x163 = i_a + 1.0
                    _x164 = (1.0/i_omega0_hat)
                    _x165 = _x164*i_phase_td
                    _x166 = _x165 + i_t_stance
                    _x167 = _x166*i_omega0_hat
                    _x168 = math.cos(_x167)
                    _x169 = _x162*i_b + _x163*_x167 - _x163*i_phase_td - _x168*i_b
                    _x170 = (1.0/i_t_stance)
                    _x171 = _x164*_x170*l0
                    _i_L = _x169*_x171
                    _pd__81 = _x171*(_x167 - i_phase_td)
                    _pd__82 = _x171*(_x162 - _x168)
                    _x172 = math.sin(_x167)
                    _x173 = _x172*i_b
                    _x174 = _x169*l0
                    _pd__83 = -_x164**2*_x170*_x174 + _x171*(-_x163*_x165 + _x163*_x166 + _x173*i_t_stance)
                    _pd__84 = _x171*(_x172*i_b - i_b*math.sin(i_phase_td))
                    _pd__85 = -_x164*_x170**2*_x174 + _x171*(_x163*i_omega0_hat + _x173*i_omega0_hat)
                elif leg_length == 1.0:
                    _x175 = i_omega0_hat*i_t_stance
                    _x176 = math.sin(_x175)
                    _x177 = i_a*i_t_stance
                    _x178 = i_b**2
                    _x179 = _x178 - i_a**2
                    _x180 = math.sqrt(_x179/_x178)
                    _x181 = _x180*i_b
                    _x182 = math.cos(_x175)
                    _x183 = -_x176*i_a + _x180*_x182*i_b - _x181 + i_omega0_hat*(_x177 + i_t_stance)
                    _x184 = (1.0/i_omega0_hat)
                    _x185 = (1.0/i_t_stance)
                    _x186 = _x184*_x185*l0
                    _i_L = _x183*_x186
                    _x187 = (1.0/_x179)
                    _pd__86 = (_x186*(-_x176 + _x180*_x187*i_a*i_b - _x181*_x182*_x187*i_a
                        + i_omega0_hat*i_t_stance))
                    _x188 = _x180*_x182
                    _x189 = i_b**3
                    _x190 = _x187*_x189*(-_x179/_x189 + (1.0/i_b))
                    _pd__87 = _x186*(-_x180*_x190 - _x180 + _x188*_x190 + _x188)
                    _x191 = _x176*_x181
                    _x192 = _x183*l0
                    _pd__88 = (-_x184**2*_x185*_x192 + _x186*(-_x177*_x182 - _x191*i_t_stance + i_a*i_t_stance
                        + i_t_stance))
                    _pd__89 = (-_x184*_x185**2*_x192 + _x186*(-_x182*i_a*i_omega0_hat - _x191*i_omega0_hat
                        + i_omega0_hat*(i_a + 1.0)))
                elif leg_length == 2.0:
                    _x193 = i_omega0_hat*q_rd_td
                    _x194 = i_omega0_hat*i_t_stance
                    _x195 = math.sin(_x194)
                    _x196 = i_q_thd_eff**2*l0
                    _x197 = g_s*i_t_stance
                    _x198 = math.cos(_x194)
                    _x199 = _x198*q_rd_td
                    _x200 = i_omega0_hat**2*l0
                    _x201 = _x200*i_t_stance
                    _x202 = _x196*i_t_stance
                    _x203 = _x193 - _x195*_x196 + _x195*g_s - i_omega0_hat*(_x197 + _x199 - _x201 - _x202)
                    _x210 = (1.0/i_omega0_hat)
                    _x204 = _x210**3
                    _x205 = (1.0/i_t_stance)
                    _x206 = _x204*_x205
                    _i_L = _x203*_x206
                    _x207 = 2.0*l0
                    _x208 = _x194*_x207
                    _pd__90 = (-3.0*_x203*_x205*_x210**4 + _x206*(_x197*_x198 - _x197 - _x198*_x202 - _x199
                        + _x201 + _x202 - i_omega0_hat*(-_x195*i_t_stance*q_rd_td - _x208) + q_rd_td))
                    _pd__91 = _x206*(-_x195*_x207*i_q_thd_eff + _x208*i_q_thd_eff)
                    _x209 = _x198*i_omega0_hat
                    _pd__92 = (-_x203*_x204*_x205**2 + _x206*(-_x196*_x209 + _x198*g_s*i_omega0_hat
                        - i_omega0_hat*(-_x193*_x195 - _x196 - _x200 + g_s)))
                    _pd__93 = _x206*(-_x209 + i_omega0_hat)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
                _x211 = g_s*m
                _x212 = _x211*math.sin(i_liftoff_q_th)
                _x213 = _i_L*_x212
                _x214 = _x211*math.sin(q_th_td)
                _x215 = _i_L*_x214
                _x216 = (0.5)*i_t_stance
                i_P_new = _x216*(_x213 + _x215)
                _pd__94 = _x216*(_x212 + _x214)
                _x217 = _i_L*_x211*_x216
                _pd__95 = _x217*math.cos(i_liftoff_q_th)
                _pd__96 = (0.5)*_x213 + (0.5)*_x215
                _pd__97 = _x217*math.cos(q_th_td)
            elif interval == 1.0:
                # average leg length, eqs (55)-(61) / (67)-(75)
                if leg_length == 0.0:
                    _x218 = math.cos(i_phase_td)
                    _x219 = i_a + 1.0
                    _x220 = (1.0/i_omega0_hat)
                    _x221 = _x220*i_phase_td
                    _x222 = _x221 + i_t_bottom
                    _x223 = _x222*i_omega0_hat
                    _x224 = math.cos(_x223)
                    _x225 = _x218*i_b + _x219*_x223 - _x219*i_phase_td - _x224*i_b
                    _x226 = (1.0/i_t_bottom)
                    _x227 = _x220*_x226*l0
                    _i_L1 = _x225*_x227
                    _pd__98 = _x227*(_x223 - i_phase_td)
                    _pd__99 = _x227*(_x218 - _x224)
                    _x228 = math.sin(_x223)
                    _x229 = _x228*i_b
                    _x230 = _x225*l0
                    _pd__100 = -_x220**2*_x226*_x230 + _x227*(-_x219*_x221 + _x219*_x222 + _x229*i_t_bottom)
                    _pd__101 = _x227*(_x228*i_b - i_b*math.sin(i_phase_td))
                    _pd__102 = -_x220*_x226**2*_x230 + _x227*(_x219*i_omega0_hat + _x229*i_omega0_hat)
                elif leg_length == 1.0:
                    _x231 = i_omega0_hat*i_t_bottom
                    _x232 = math.sin(_x231)
                    _x233 = i_a*i_t_bottom
                    _x234 = i_b**2
                    _x235 = _x234 - i_a**2
                    _x236 = math.sqrt(_x235/_x234)
                    _x237 = _x236*i_b
                    _x238 = math.cos(_x231)
                    _x239 = -_x232*i_a + _x236*_x238*i_b - _x237 + i_omega0_hat*(_x233 + i_t_bottom)
                    _x240 = (1.0/i_omega0_hat)
                    _x241 = (1.0/i_t_bottom)
                    _x242 = _x240*_x241*l0
                    _i_L1 = _x239*_x242
                    _x243 = (1.0/_x235)
                    _pd__103 = (_x242*(-_x232 + _x236*_x243*i_a*i_b - _x237*_x238*_x243*i_a
                        + i_omega0_hat*i_t_bottom))
                    _x244 = _x236*_x238
                    _x245 = i_b**3
                    _x246 = _x243*_x245*(-_x235/_x245 + (1.0/i_b))
                    _pd__104 = _x242*(-_x236*_x246 - _x236 + _x244*_x246 + _x244)
                    _x247 = _x232*_x237
                    _x248 = _x239*l0
                    _pd__105 = (-_x240**2*_x241*_x248 + _x242*(-_x233*_x238 - _x247*i_t_bottom
                        + i_a*i_t_bottom + i_t_bottom))
                    _pd__106 = (-_x240*_x241**2*_x248 + _x242*(-_x238*i_a*i_omega0_hat - _x247*i_omega0_hat
                        + i_omega0_hat*(i_a + 1.0)))
                elif leg_length == 2.0:
                    _x249 = i_omega0_hat*q_rd_td
                    _x250 = i_omega0_hat*i_t_bottom
                    _x251 = math.sin(_x250)
                    _x252 = i_q_thd_eff**2*l0
                    _x253 = g_s*i_t_bottom
                    _x254 = math.cos(_x250)
                    _x255 = _x254*q_rd_td
                    _x256 = i_omega0_hat**2*l0
                    _x257 = _x256*i_t_bottom
                    _x258 = _x252*i_t_bottom
                    _x259 = _x249 - _x251*_x252 + _x251*g_s - i_omega0_hat*(_x253 + _x255 - _x257 - _x258)
                    _x266 = (1.0/i_omega0_hat)
                    _x260 = _x266**3
                    _x261 = (1.0/i_t_bottom)
                    _x262 = _x260*_x261
                    _i_L1 = _x259*_x262
                    _x263 = 2.0*l0
                    _x264 = _x250*_x263
                    _pd__107 = (-3.0*_x259*_x261*_x266**4 + _x262*(_x253*_x254 - _x253 - _x254*_x258 - _x255
                        + _x257 + _x258 - i_omega0_hat*(-_x251*i_t_bottom*q_rd_td - _x264) + q_rd_td))
                    _pd__108 = _x262*(-_x251*_x263*i_q_thd_eff + _x264*i_q_thd_eff)
                    _x265 = _x254*i_omega0_hat
                    _pd__109 = (-_x259*_x260*_x261**2 + _x262*(-_x252*_x265 + _x254*g_s*i_omega0_hat
                        - i_omega0_hat*(-_x249*_x251 - _x252 - _x256 + g_s)))
                    _pd__110 = _x262*(-_x265 + i_omega0_hat)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
                # average leg length, eqs (55)-(61) / (67)-(75)
                if leg_length == 0.0:
                    _x267 = (1.0/i_omega0_hat)
                    _x268 = _x267*i_phase_td
                    _x269 = _x268 + i_t_bottom
                    _x270 = _x269*i_omega0_hat
                    _x271 = math.cos(_x270)
                    _x272 = i_a + 1.0
                    _x273 = _x268 + i_t_stance
                    _x274 = _x273*i_omega0_hat
                    _x275 = math.cos(_x274)
                    _x276 = -_x270*_x272 + _x271*i_b + _x272*_x274 - _x275*i_b
                    _x277 = -i_t_bottom + i_t_stance
                    _x278 = (1.0/_x277)
                    _x279 = _x267*_x278*l0
                    _i_L2 = _x276*_x279
                    _pd__111 = _x279*(-_x270 + _x273*i_omega0_hat)
                    _pd__112 = _x279*(_x271 - _x275)
                    _x280 = i_b*math.sin(_x270)
                    _x281 = math.sin(_x274)
                    _x282 = _x276*l0
                    _pd__113 = (-_x267**2*_x278*_x282 + _x279*(-_x269*_x272 + _x272*_x273 - _x280*i_t_bottom
                        + _x281*i_b*i_t_stance))
                    _pd__114 = _x279*(-_x280 + _x281*i_b)
                    _x283 = _x272*i_omega0_hat
                    _x284 = _x267*_x278**2*_x282
                    _pd__115 = _x279*(-_x280*i_omega0_hat - _x283) + _x284
                    _pd__116 = _x279*(_x281*i_b*i_omega0_hat + _x283) - _x284
                elif leg_length == 1.0:
                    _x285 = i_omega0_hat*i_t_bottom
                    _x286 = math.sin(_x285)
                    _x287 = i_omega0_hat*i_t_stance
                    _x288 = math.sin(_x287)
                    _x289 = i_a*i_t_bottom
                    _x290 = i_t_bottom - i_t_stance
                    _x291 = math.cos(_x287)
                    _x292 = i_b**2
                    _x293 = _x292 - i_a**2
                    _x294 = math.sqrt(_x293/_x292)
                    _x295 = _x291*_x294*i_b
                    _x296 = math.cos(_x285)
                    _x297 = _x294*_x296
                    _x298 = _x297*i_b
                    _x299 = (_x286*i_a - _x288*i_a + _x295 - _x298 + i_omega0_hat*(-_x289 - _x290
                        + i_a*i_t_stance))
                    _x300 = (1.0/i_omega0_hat)
                    _x301 = -_x290
                    _x302 = (1.0/_x301)
                    _x303 = _x300*_x302*l0
                    _i_L2 = _x299*_x303
                    _x304 = (1.0/_x293)
                    _x305 = _x304*i_a
                    _pd__117 = _x303*(_x286 - _x288 - _x295*_x305 + _x298*_x305 + _x301*i_omega0_hat)
                    _x306 = i_b**3
                    _x307 = -_x293/_x306 + (1.0/i_b)
                    _pd__118 = (_x303*(_x291*_x294*_x304*_x306*_x307 + _x291*_x294 - _x297*_x304*_x306*_x307
                        - _x297))
                    _x308 = _x299*l0
                    _x309 = i_a*i_t_stance
                    _x310 = _x294*i_b
                    _x311 = _x286*_x310
                    _x312 = _x288*_x310
                    _pd__119 = (-_x300**2*_x302*_x308 + _x303*(_x289*_x296 - _x289 - _x291*_x309 + _x309
                        + _x311*i_t_bottom - _x312*i_t_stance - i_t_bottom + i_t_stance))
                    _x313 = i_a + 1.0
                    _x314 = i_a*i_omega0_hat
                    _x315 = _x300*_x302**2*_x308
                    _pd__120 = _x303*(_x296*_x314 + _x311*i_omega0_hat - _x313*i_omega0_hat) + _x315
                    _pd__121 = _x303*(-_x291*_x314 - _x312*i_omega0_hat + _x313*i_omega0_hat) - _x315
                elif leg_length == 2.0:
                    _x316 = i_omega0_hat*i_t_bottom
                    _x317 = math.sin(_x316)
                    _x318 = i_omega0_hat*i_t_stance
                    _x319 = math.sin(_x318)
                    _x320 = i_q_thd_eff**2
                    _x321 = _x320*l0
                    _x322 = math.cos(_x318)
                    _x323 = i_omega0_hat**2*l0
                    _x324 = _x321*i_t_stance
                    _x325 = _x322*q_rd_td - _x323*i_t_stance - _x324 + g_s*i_t_stance
                    _x326 = g_s*i_t_bottom
                    _x327 = math.cos(_x316)
                    _x328 = _x323*i_t_bottom
                    _x329 = _x321*i_t_bottom
                    _x330 = (_x317*_x320*l0 - _x317*g_s - _x319*_x321 + _x319*g_s - _x325*i_omega0_hat
                        + i_omega0_hat*(_x326 + _x327*q_rd_td - _x328 - _x329))
                    _x343 = (1.0/i_omega0_hat)
                    _x331 = _x343**3
                    _x332 = -i_t_bottom + i_t_stance
                    _x333 = (1.0/_x332)
                    _x334 = _x331*_x333
                    _i_L2 = _x330*_x334
                    _x335 = 2.0*l0
                    _x336 = _x319*q_rd_td
                    _x337 = _x316*_x335
                    _x338 = _x317*q_rd_td
                    _pd__122 = (-3.0*_x330*_x333*_x343**4 + _x334*(_x320*_x327*i_t_bottom*l0 - _x322*_x324
                        + _x322*g_s*i_t_stance - _x325 - _x326*_x327 + _x327*q_rd_td - _x328 - _x329
                        + g_s*i_t_bottom + i_omega0_hat*(-_x337 - _x338*i_t_bottom)
                        - i_omega0_hat*(-_x318*_x335 - _x336*i_t_stance)))
                    _pd__123 = (_x334*(2.0*_x317*i_q_thd_eff*l0 - _x319*_x335*i_q_thd_eff - _x337*i_q_thd_eff
                        + 2.0*i_omega0_hat*i_q_thd_eff*i_t_stance*l0))
                    _x339 = _x327*i_omega0_hat
                    _x340 = _x321 + _x323 - g_s
                    _x341 = _x330*_x331*_x333**2
                    _pd__124 = (_x334*(_x321*_x339 - _x339*g_s + i_omega0_hat*(-_x338*i_omega0_hat - _x340))
                        + _x341)
                    _x342 = _x322*i_omega0_hat
                    _pd__125 = (_x334*(-_x321*_x342 + _x322*g_s*i_omega0_hat
                        - i_omega0_hat*(-_x336*i_omega0_hat - _x340)) - _x341)
                    _pd__126 = _x334*(_x339 - _x342)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
                _x344 = g_s*m
                _x345 = _x344*math.sin(i_bottom_q_th)
                _x346 = _i_L1*_x345
                _x347 = _x344*math.sin(q_th_td)
                _x348 = _i_L1*_x347
                _x349 = (0.5)*i_t_bottom
                _x350 = _i_L2*_x345
                _x351 = _x344*math.sin(i_liftoff_q_th)
                _x352 = _i_L2*_x351
                _x353 = -0.5*i_t_bottom + (0.5)*i_t_stance
                i_P_new = _x349*(_x346 + _x348) + _x353*(_x350 + _x352)
                _pd__127 = _x349*(_x345 + _x347)
                _pd__128 = _x353*(_x345 + _x351)
                _x354 = _x344*math.cos(i_bottom_q_th)
                _x355 = _i_L1*_x349
                _x356 = _i_L2*_x353
                _pd__129 = _x354*_x355 + _x354*_x356
                _pd__130 = _x344*_x356*math.cos(i_liftoff_q_th)
                _x357 = (0.5)*_x350
                _x358 = (0.5)*_x352
                _pd__131 = (0.5)*_x346 + (0.5)*_x348 - _x357 - _x358
                _pd__132 = _x357 + _x358
                _pd__133 = _x344*_x355*math.cos(q_th_td)
            else:
                return fail(out, STATUS_INVALID_INPUT)
        else:
            return fail(out, STATUS_INVALID_INPUT)
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
            # the impulse rule of the correction type
            if rule == 0.0:
                # eq (48) with 2 or 3 samples
                if samples == 2.0:
                    d_i_P_new__j = (_pd__32*d_i_liftoff_q_th__j + _pd__33*d_i_t_stance__j
                        + _pd__34*d_q_th_td__j)
                elif samples == 3.0:
                    d_i_P_new__j = (_pd__35*d_i_bottom_q_th__j + _pd__36*d_i_liftoff_q_th__j
                        + _pd__37*d_i_t_stance__j + _pd__38*d_q_th_td__j)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
            elif rule == 1.0:
                # eq (48) with 2 or 3 samples
                if samples == 2.0:
                    d_i_P_new__j = (_pd__39*d_i_bottom_q_r__j + _pd__40*d_i_liftoff_q_th__j
                        + _pd__41*d_i_t_stance__j + _pd__42*d_q_th_td__j)
                elif samples == 3.0:
                    d_i_P_new__j = (_pd__43*d_i_bottom_q_r__j + _pd__44*d_i_bottom_q_th__j
                        + _pd__45*d_i_liftoff_q_th__j + _pd__46*d_i_t_stance__j + _pd__47*d_q_th_td__j)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
            elif rule == 2.0:
                # average leg length, eqs (55)-(61) / (67)-(75)
                if leg_length == 0.0:
                    _d_i_L__j = (_pd__48*d_i_a__j + _pd__49*d_i_b__j + _pd__50*d_i_omega0_hat__j
                        + _pd__51*d_i_phase_td__j + _pd__52*d_i_t_stance__j)
                elif leg_length == 1.0:
                    _d_i_L__j = (_pd__53*d_i_a__j + _pd__54*d_i_b__j + _pd__55*d_i_omega0_hat__j
                        + _pd__56*d_i_t_stance__j)
                elif leg_length == 2.0:
                    _d_i_L__j = (_pd__57*d_i_omega0_hat__j + _pd__58*d_i_q_thd_eff__j
                        + _pd__59*d_i_t_stance__j + _pd__60*d_q_rd_td__j)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
                # eq (48) with 2 or 3 samples
                if samples == 2.0:
                    d_i_P_new__j = (_d_i_L__j*_pd__61 + _pd__62*d_i_liftoff_q_th__j + _pd__63*d_i_t_stance__j
                        + _pd__64*d_q_th_td__j)
                elif samples == 3.0:
                    d_i_P_new__j = (_d_i_L__j*_pd__65 + _pd__66*d_i_bottom_q_th__j
                        + _pd__67*d_i_liftoff_q_th__j + _pd__68*d_i_t_stance__j + _pd__69*d_q_th_td__j)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
            elif rule == 3.0:
                # eq (65)
                if interval == 0.0:
                    d_i_P_new__j = (_pd__70*d_i_liftoff_q_th__j + _pd__71*d_i_t_stance__j
                        + _pd__72*d_q_r_td__j + _pd__73*d_q_th_td__j)
                elif interval == 1.0:
                    d_i_P_new__j = (_pd__74*d_i_bottom_q_r__j + _pd__75*d_i_bottom_q_th__j
                        + _pd__76*d_i_liftoff_q_th__j + _pd__77*d_i_t_bottom__j + _pd__78*d_i_t_stance__j
                        + _pd__79*d_q_r_td__j + _pd__80*d_q_th_td__j)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
            elif rule == 4.0:
                # eq (76)
                if interval == 0.0:
                    # average leg length, eqs (55)-(61) / (67)-(75)
                    if leg_length == 0.0:
                        _d_i_L__j = (_pd__81*d_i_a__j + _pd__82*d_i_b__j + _pd__83*d_i_omega0_hat__j
                            + _pd__84*d_i_phase_td__j + _pd__85*d_i_t_stance__j)
                    elif leg_length == 1.0:
                        _d_i_L__j = (_pd__86*d_i_a__j + _pd__87*d_i_b__j + _pd__88*d_i_omega0_hat__j
                            + _pd__89*d_i_t_stance__j)
                    elif leg_length == 2.0:
                        _d_i_L__j = (_pd__90*d_i_omega0_hat__j + _pd__91*d_i_q_thd_eff__j
                            + _pd__92*d_i_t_stance__j + _pd__93*d_q_rd_td__j)
                    else:
                        return fail(out, STATUS_INVALID_INPUT)
                    d_i_P_new__j = (_d_i_L__j*_pd__94 + _pd__95*d_i_liftoff_q_th__j + _pd__96*d_i_t_stance__j
                        + _pd__97*d_q_th_td__j)
                elif interval == 1.0:
                    # average leg length, eqs (55)-(61) / (67)-(75)
                    if leg_length == 0.0:
                        _d_i_L1__j = (_pd__100*d_i_omega0_hat__j + _pd__101*d_i_phase_td__j
                            + _pd__102*d_i_t_bottom__j + _pd__98*d_i_a__j + _pd__99*d_i_b__j)
                    elif leg_length == 1.0:
                        _d_i_L1__j = (_pd__103*d_i_a__j + _pd__104*d_i_b__j + _pd__105*d_i_omega0_hat__j
                            + _pd__106*d_i_t_bottom__j)
                    elif leg_length == 2.0:
                        _d_i_L1__j = (_pd__107*d_i_omega0_hat__j + _pd__108*d_i_q_thd_eff__j
                            + _pd__109*d_i_t_bottom__j + _pd__110*d_q_rd_td__j)
                    else:
                        return fail(out, STATUS_INVALID_INPUT)
                    # average leg length, eqs (55)-(61) / (67)-(75)
                    if leg_length == 0.0:
                        _d_i_L2__j = (_pd__111*d_i_a__j + _pd__112*d_i_b__j + _pd__113*d_i_omega0_hat__j
                            + _pd__114*d_i_phase_td__j + _pd__115*d_i_t_bottom__j + _pd__116*d_i_t_stance__j)
                    elif leg_length == 1.0:
                        _d_i_L2__j = (_pd__117*d_i_a__j + _pd__118*d_i_b__j + _pd__119*d_i_omega0_hat__j
                            + _pd__120*d_i_t_bottom__j + _pd__121*d_i_t_stance__j)
                    elif leg_length == 2.0:
                        _d_i_L2__j = (_pd__122*d_i_omega0_hat__j + _pd__123*d_i_q_thd_eff__j
                            + _pd__124*d_i_t_bottom__j + _pd__125*d_i_t_stance__j + _pd__126*d_q_rd_td__j)
                    else:
                        return fail(out, STATUS_INVALID_INPUT)
                    d_i_P_new__j = (_d_i_L1__j*_pd__127 + _d_i_L2__j*_pd__128 + _pd__129*d_i_bottom_q_th__j
                        + _pd__130*d_i_liftoff_q_th__j + _pd__131*d_i_t_bottom__j + _pd__132*d_i_t_stance__j
                        + _pd__133*d_q_th_td__j)
                else:
                    return fail(out, STATUS_INVALID_INPUT)
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
    _x367 = (1.0/i_t_stance)
    _x359 = _x367*ramp
    _x360 = _x359*i_t_bottom - ramp + 1.0
    _x361 = P_c*_x360 + p_td
    _x362 = (1.0/m)
    _x366 = (1.0/i_bottom_q_r)
    _x363 = _x362*_x366**2
    bottom_q_thd = _x361*_x363
    _pd__134 = _x360*_x363
    _pd__135 = -2.0*_x361*_x362*_x366**3
    _x364 = P_c*_x363
    _pd__136 = _x359*_x364
    _pd__137 = -_x364*_x367**2*i_t_bottom*ramp
    _pd__138 = _x363
    liftoff_q_r = q_r_lo
    liftoff_q_th = i_liftoff_q_th
    _x365 = _x362/q_r_lo**2
    liftoff_q_thd = _x365*(P_c + p_td)
    _pd__139 = _x365
    _pd__140 = _x365
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
        d_bottom_q_thd__j = (_pd__134*d_P_c__j + _pd__135*d_i_bottom_q_r__j + _pd__136*d_i_t_bottom__j
            + _pd__137*d_i_t_stance__j + _pd__138*d_p_td__j)
        d_liftoff_q_thd__j = _pd__139*d_P_c__j + _pd__140*d_p_td__j
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
        _x368 = (1.0/m)
        _x369 = 2.0*g_s*q_r_lo
        _x370 = _x368*l0**2
        _x371 = q_r_lo**2
        _x372 = _x368*_x371
        _x373 = _x368**2/_x371
        _q_rd_lo_sq = (2.0*E_td*_x368 + 2.0*_x368*k*l0*q_r_lo - _x369*math.cos(i_liftoff_q_th) - _x370*k
            - _x372*k - _x373*(P_c + p_td)**2)
        _x374 = 2.0*_x368
        _pd__141 = _x374
        _x375 = -_x373*(2.0*P_c + 2.0*p_td)
        _pd__142 = _x375
        _pd__143 = _x369*math.sin(i_liftoff_q_th)
        _pd__144 = _x375
        _d_q_rd_lo_sq__q_r_td = (_pd__141*d_E_td__q_r_td + _pd__142*d_P_c__q_r_td
            + _pd__143*d_i_liftoff_q_th__q_r_td + _pd__144*d_p_td__q_r_td)
        _d_q_rd_lo_sq__q_rd_td = (_pd__141*d_E_td__q_rd_td + _pd__142*d_P_c__q_rd_td
            + _pd__143*d_i_liftoff_q_th__q_rd_td)
        _d_q_rd_lo_sq__q_th_td = (_pd__141*d_E_td__q_th_td + _pd__142*d_P_c__q_th_td
            + _pd__143*d_i_liftoff_q_th__q_th_td)
        _d_q_rd_lo_sq__q_thd_td = (_pd__141*d_E_td__q_thd_td + _pd__142*d_P_c__q_thd_td
            + _pd__143*d_i_liftoff_q_th__q_thd_td + _pd__144*d_p_td__q_thd_td)
        _d_q_rd_lo_sq__k = (_pd__141*d_E_td__k + _pd__142*d_P_c__k + _pd__143*d_i_liftoff_q_th__k - _x370
            - _x372 + _x374*l0*q_r_lo)
        # q_rd_lo^2 from the energy (27)
        if not ((_q_rd_lo_sq >= 0.0)):
            return fail(out, STATUS_ENERGY_DEFICIT)
        # q_rd_lo from the energy
        _x376 = math.sqrt(_q_rd_lo_sq)
        liftoff_q_rd = _x376
        _pd__145 = (0.5)/_x376
        d_liftoff_q_rd__q_r_td = _d_q_rd_lo_sq__q_r_td*_pd__145
        d_liftoff_q_rd__q_rd_td = _d_q_rd_lo_sq__q_rd_td*_pd__145
        d_liftoff_q_rd__q_th_td = _d_q_rd_lo_sq__q_th_td*_pd__145
        d_liftoff_q_rd__q_thd_td = _d_q_rd_lo_sq__q_thd_td*_pd__145
        d_liftoff_q_rd__k = _d_q_rd_lo_sq__k*_pd__145
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
def gravity_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = gravity_stance_jacobian(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def gravity_apex_return_jacobian(x, p, out):
    """Apex-return map by Gravity corrections types 0-4, and its derivatives with respect to the apex, the
    touchdown angle and the stiffness.

    Report equations: 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67,
    68, 69, 70, 71, 72, 73, 74, 75, 76, 77.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, samples, interval, leg_length, rule, iterations, tol);
    writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`gravity.gravity_apex_return`, in its order.

    Writes into out:
        <output>: each output of :func:`gravity.gravity_apex_return`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 244
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) = (x[0], x[1], x[2], x[3], x[4])
    (m, l0, k, g_s, g_f, q_r_td, q_r_lo, reading, samples, interval, leg_length, rule, iterations,
        tol) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], p[9], p[10], p[11], p[12], p[13])
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) & math.isfinite(b_xd_apex) & math.isfinite(q_th_td)
            & math.isfinite(ground) & math.isfinite(retraction_rate) & math.isfinite(m) & math.isfinite(l0)
            & math.isfinite(k) & math.isfinite(g_s) & math.isfinite(g_f) & math.isfinite(q_r_td)
            & math.isfinite(q_r_lo) & math.isfinite(reading) & math.isfinite(samples)
            & math.isfinite(interval) & math.isfinite(leg_length) & math.isfinite(rule)
            & math.isfinite(iterations) & math.isfinite(tol) & ((b_y_apex >= 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k > 0.0)) & ((g_s > 0.0)) & ((g_f > 0.0))
            & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((reading == 0.0)
            or (reading == 1.0)) & ((samples == math.floor(samples)) and (samples >= 2.0) and (samples
            <= 3.0)) & ((interval == 0.0) or (interval == 1.0)) & ((leg_length == 0.0) or (leg_length == 1.0)
            or (leg_length == 2.0)) & ((rule == math.floor(rule)) and (rule >= 0.0) and (rule <= 4.0))
            & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0))
            & ((tol >= 0.0) and (tol <= 1.0))):
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
    # stance: Gravity corrections types 0-4
    _x1 = carray(stack(4), 4)
    (_x1[0], _x1[1], _x1[2], _x1[3],) = (_o0[0], _o0[1], _o0[2], _o0[3],)
    _o1 = carray(stack(72), 72)
    _c1 = gravity_stance_jacobian(_x1, p, _o1)
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
def gravity_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`gravity_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = gravity_apex_return_jacobian(row(X, i), row(P, min(i, last)), row(OUT, i))
