# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/geyer_vs.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight_jacobian.py sha256:4de4ff5a5b5282af
#   geyer_jacobian.py sha256:a1c9347d955c37d0
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module geyer_vs: JVP kernels, and for a map
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
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_NO_REAL_SOLUTION, STATUS_FALL,
    STATUS_RECOMPRESSION, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED, STATUS_ENERGY_DEFICIT)

NAN = math.nan
_NAN4 = (NAN,) * 4


@njit(cache=True, error_model="numpy")
def bottom_quartic_jac_p_b_E_ab_k_c(p_b, E_ab, m, l0, k_c, g_s):
    """Bottom leg length of (153): the compressing root of the quartic in (0, l0] (Newton), and the
    derivatives of its outputs with respect to p_b, E_ab, k_c.

    Report equations: 153.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`geyer_vs.bottom_quartic`, in its order.

    Returns a tuple:
        <output>: each output of :func:`geyer_vs.bottom_quartic`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument p_b, E_ab, k_c
            (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 309
    # inputs: finite and inside their domains
    if not (all_finite((p_b, E_ab, m, l0, k_c, g_s,)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((g_s
            > 0.0))):
        return _NAN4 + (STATUS_INVALID_INPUT,)
    # a start left of the root: V >= E there
    _x0 = (0.5)*l0
    _x1 = g_s*m
    _x73 = (1.0/k_c)
    _x2 = _x1*_x73
    _x3 = (0.5)*_x2
    _x4 = (1.0/math.sqrt(k_c))
    _x5 = _x2 - l0
    _x6 = -_x5
    _x7 = _x6**2
    _x8 = _x7*k_c
    _x9 = _x1*_x6
    _x10 = l0**2
    _x11 = _x10*k_c
    _x12 = -2.0*E_ab + _x11
    _x13 = -_x12 + 2.0*_x6*k_c*l0 - _x8 - 2.0*_x9
    _x14 = math.sqrt(_x13)
    _x15 = _x14*_x4
    _x16 = abs(p_b)
    _x17 = -E_ab + (0.5)*_x11
    _x18 = -_x17 + _x6*k_c*l0 - 0.5*_x8 - _x9
    _x19 = math.sqrt(2.0)
    _x20 = (1.0/math.sqrt(m))
    _x21 = _x19*_x20
    _x22 = _x21/math.sqrt(_x18)
    _x23 = _x16*_x22
    _x24 = _x15 + _x5
    q_start = _x0 - 0.5*_x15 + (0.25)*_x23 - _x3 + (0.5)*abs((0.5)*_x23 + _x24)
    _x25 = (0.0 if p_b == 0 else math.copysign(1, p_b))
    _x28 = _x5**2
    _x29 = _x28*k_c
    _x30 = _x1*_x5
    _x31 = _x5*l0
    _x32 = _x31*k_c
    _x40 = _x17 + (0.5)*_x29 - _x30 + _x32
    _x41 = (0.0 if _x40 == 0 else math.copysign(1, _x40))
    _x42 = _x40/_x41
    _x43 = (1.0/math.sqrt(_x42))
    _x38 = (0.5)*math.atan2(0.0, _x18)
    _x39 = math.sin(_x38)
    _x44 = _x21*_x43
    _x45 = _x39*_x44
    _x26 = (0.5)*math.atan2(0.0, _x13)
    _x27 = math.sin(_x26)
    _x33 = _x12 + _x29 - 2.0*_x30 + 2.0*_x32
    _x34 = (0.0 if _x33 == 0 else math.copysign(1, _x33))
    _x35 = math.sqrt(_x33/_x34)
    _x36 = p_b/_x25
    _x37 = (0.5)*_x36
    _x46 = _x27*_x35*_x4 - _x37*_x45
    _x47 = math.cos(_x38)
    _x48 = math.cos(_x26)
    _x49 = _x35*_x4*_x48 + _x37*_x44*_x47 + _x5
    _x50 = _x22*_x37 + _x24
    _x51 = (1.0/_x50)
    _x52 = (0.0 if _x50 == 0 else math.copysign(1, _x50))
    _x53 = (0.5)*_x51*_x52
    d_q_start__p_b = (0.25)*_x22*_x25 + _x53*((0.5)*_x19*_x20*_x25*_x43*_x47*_x49 - 0.5*_x25*_x45*_x46)
    _x54 = (0.5)*_x4
    _x55 = _x54/_x14
    _x56 = _x16*_x21/(_x18*math.sqrt(_x18))
    _x57 = (1.0/_x35)
    _x58 = _x34*_x57
    _x59 = _x4*_x58
    _x60 = (0.25)*_x21*_x36*_x41/(_x42*math.sqrt(_x42))
    _x61 = _x39*_x60
    _x62 = _x47*_x60
    d_q_start__E_ab = ((0.5)*_x51*_x52*(_x46*(-_x27*_x59 - _x61) + _x49*(-_x48*_x59 + _x62)) - _x55
        - 0.125*_x56)
    _x63 = _x73**2
    _x64 = _x1*_x63
    _x65 = (1.0/(k_c*math.sqrt(k_c)))
    _x66 = _x63*g_s**2*m**2
    _x67 = _x2*l0
    _x68 = (0.5)*_x10 + _x66 - _x67
    _x69 = (0.5)*_x35*_x65
    _x70 = _x2*_x5
    _x71 = _x10 + _x28 + 2.0*_x31 + 2.0*_x66 - 2.0*_x67 - 2.0*_x70
    _x72 = (0.5)*_x28 + _x31 + _x68 - _x70
    d_q_start__k_c = ((0.25)*_x14*_x65 + _x53*(_x46*(_x27*_x54*_x58*_x71 - _x27*_x69 + _x61*_x72)
        + _x49*((0.5)*_x34*_x4*_x48*_x57*_x71 - _x48*_x69 - _x62*_x72 - _x64)) - _x55*(-_x2*_x6 + _x6*l0
        - _x68 - 0.5*_x7) + (0.25)*_x56*(-_x0*_x2 - _x0*_x6 + (0.25)*_x10 + _x3*_x6 + (0.5)*_x66 + (0.25)*_x7)
        + (0.5)*_x64)
    # E_ab above the minimum of the potential
    if not ((E_ab > g_s*m*(-g_s*m/k_c + l0) + (0.5)*k_c*l0**2 - k_c*l0*(-g_s*m/k_c + l0)
            + (0.5)*k_c*(-g_s*m/k_c + l0)**2)):
        return _NAN4 + (STATUS_NO_REAL_SOLUTION,)
    # Newton's method on V - E: monotone from the left
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (q_start, d_q_start__p_b, d_q_start__E_ab, d_q_start__k_c, )
    _pk0 = _pki0
    passes = 0.0
    _conv0 = False
    _last0 = max(int(60.0), 0)
    for _it0 in range(_last0 + 1):
        (qb, d_qb__p_b, d_qb__E_ab, d_qb__k_c, ) = _pk0
        if _it0 == _last0 and not _conv0 and 1e-12 > 0.0 and passes > 0.0:
            return _NAN4 + (STATUS_NOT_CONVERGED,)
        if _conv0 or _it0 == _last0:
            break
        _x77 = (1.0/qb)
        _x74 = _x77**3
        _x75 = (1.0/m)
        _x76 = _x75*p_b**2
        slope = -_x74*_x76 + g_s*m - k_c*l0 + k_c*qb
        _pd__0 = 3.0*_x76*_x77**4 + k_c
        d_slope__p_b = _pd__0*d_qb__p_b - 2.0*_x74*_x75*p_b
        d_slope__E_ab = _pd__0*d_qb__E_ab
        d_slope__k_c = _pd__0*d_qb__k_c - l0 + qb
        # V decreasing left of the root
        if not ((slope < 0.0)):
            return _NAN4 + (STATUS_NO_REAL_SOLUTION,)
        # next values
        _x78 = (1.0/slope)
        _x79 = g_s*m
        _x80 = k_c*qb
        _x81 = (0.5)*l0**2
        _x82 = qb**2
        _x83 = (0.5)*_x82
        _x84 = (1.0/_x82)
        _x85 = (1.0/m)
        _x86 = _x85*p_b**2
        _x87 = -E_ab + _x79*qb - _x80*l0 + _x81*k_c + _x83*k_c + (0.5)*_x84*_x86
        qb__next = -_x78*_x87 + qb
        _pd__1 = -_x78*(_x79 + _x80 - _x86/qb**3 - k_c*l0) + 1.0
        _pd__2 = _x78**2*_x87
        d_qb__next__p_b = _pd__1*d_qb__p_b + _pd__2*d_slope__p_b - _x78*_x84*_x85*p_b
        d_qb__next__E_ab = _pd__1*d_qb__E_ab + _pd__2*d_slope__E_ab + _x78
        d_qb__next__k_c = _pd__1*d_qb__k_c + _pd__2*d_slope__k_c - _x78*(_x81 + _x83 - l0*qb)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = 1e-12 > 0.0 and (abs(qb__next - qb) <= 1e-12*(l0))
        _pkn0 = (qb__next, d_qb__next__p_b, d_qb__next__E_ab, d_qb__next__k_c, )
        _pk0 = _pkn0
        passes += 1.0
    q_r_b = qb
    # the bottom root is at most l0
    if not ((qb <= l0)):
        return _NAN4 + (STATUS_NO_REAL_SOLUTION,)
    # derivatives of the outputs
    d_q_r_b__p_b = d_qb__p_b
    d_q_r_b__E_ab = d_qb__E_ab
    d_q_r_b__k_c = d_qb__k_c
    # (internal helper: its callers check that their outputs are finite)
    return (q_r_b, d_q_r_b__p_b, d_q_r_b__E_ab, d_q_r_b__k_c, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_vs_stance_jacobian(x, p, out):
    """Simple variable-stiffness map (Geyer et al. per half): stance outputs and their derivatives with
    respect to the touchdown state and the stiffness.

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 96, 97, 98, 99, 100,
    101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`geyer_vs.geyer_vs_stance`, in its order.

    Writes into out:
        <output>: each output of :func:`geyer_vs.geyer_vs_stance`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r_td, q_rd_td,
            q_th_td, q_thd_td, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 1472
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
    _x2 = _x1*q_thd_td
    p_td = _x2
    _x3 = m*q_r_td
    d_p_td__q_r_td = 2.0*_x3*q_thd_td
    d_p_td__q_thd_td = _x1
    _x4 = k_c*q_r_td
    _x5 = (0.5)*l0**2
    _x6 = (0.5)*_x0
    _x7 = g_s*m
    _x8 = _x7*math.cos(q_th_td)
    _x9 = q_thd_td**2
    E_td = (0.5)*_x1*_x9 - _x4*l0 + _x5*k_c + _x6*k_c + _x8*q_r_td + (0.5)*m*q_rd_td**2
    d_E_td__q_r_td = _x3*_x9 + _x4 + _x8 - k_c*l0
    d_E_td__q_rd_td = m*q_rd_td
    d_E_td__q_th_td = -_x7*q_r_td*math.sin(q_th_td)
    d_E_td__q_thd_td = _x2
    d_E_td__k_c = _x5 + _x6 - l0*q_r_td
    # fixed point of the two halves' virtual gravity effects, from 0 (none: no pass)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, )
    _pk0 = _pki0
    passes = 0.0
    _conv0 = False
    _last0 = max(int(((0.0) if (gravity == 0.0) else (iterations))), 0)
    for _it0 in range(_last0 + 1):
        (P_c_compression, P_c_decompression, d_P_c_compression__q_r_td, d_P_c_compression__q_rd_td,
            d_P_c_compression__q_th_td, d_P_c_compression__q_thd_td, d_P_c_compression__k_c,
            d_P_c_compression__k_d, d_P_c_decompression__q_r_td, d_P_c_decompression__q_rd_td,
            d_P_c_decompression__q_th_td, d_P_c_decompression__q_thd_td, d_P_c_decompression__k_c,
            d_P_c_decompression__k_d, ) = _pk0
        if _it0 == _last0 and not _conv0 and tol > 0.0 and passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        # the first half's mean momentum as a touchdown rate
        _x10 = (0.5)*P_c_compression + p_td
        _x11 = (1.0/m)
        _x13 = (1.0/q_r_td)
        _x12 = _x11*_x13**2
        i_q_thd_eff = _x10*_x12
        _pd__0 = (0.5)*_x12
        _pd__1 = _x12
        d_i_q_thd_eff__q_r_td = (_pd__0*d_P_c_compression__q_r_td + _pd__1*d_p_td__q_r_td
            - 2.0*_x10*_x11*_x13**3)
        d_i_q_thd_eff__q_rd_td = _pd__0*d_P_c_compression__q_rd_td
        d_i_q_thd_eff__q_th_td = _pd__0*d_P_c_compression__q_th_td
        d_i_q_thd_eff__q_thd_td = _pd__0*d_P_c_compression__q_thd_td + _pd__1*d_p_td__q_thd_td
        d_i_q_thd_eff__k_c = _pd__0*d_P_c_compression__k_c
        d_i_q_thd_eff__k_d = _pd__0*d_P_c_compression__k_d
        # eqs (78), (82)-(87): Geyer's radial solution with k_c from the touchdown state
        _o0 = carray(stack(30), 30)
        _c0 = geyer_solution_jac_q_r_td_q_rd_td_q_thd_td_k(q_r_td, q_rd_td, i_q_thd_eff, m, l0, k_c, g_s, _o0)
        if _c0 != STATUS_OK:
            return fail(out, _c0)
        (i_ab_omega, i_ab_omega0_hat, i_ab_a, i_ab_b, i_ab_phase_td, i_ab_s_td, _j_i_ab_omega__q_r_td,
            _j_i_ab_omega__q_thd_td, _j_i_ab_omega0_hat__q_r_td, _j_i_ab_omega0_hat__q_thd_td,
            _j_i_ab_omega0_hat__k, _j_i_ab_a__q_r_td, _j_i_ab_a__q_thd_td, _j_i_ab_a__k, _j_i_ab_b__q_r_td,
            _j_i_ab_b__q_rd_td, _j_i_ab_b__q_thd_td, _j_i_ab_b__k, _j_i_ab_phase_td__q_r_td,
            _j_i_ab_phase_td__q_rd_td, _j_i_ab_phase_td__q_thd_td, _j_i_ab_phase_td__k, _j_i_ab_s_td__q_r_td,
            _j_i_ab_s_td__q_rd_td, _j_i_ab_s_td__q_thd_td, _j_i_ab_s_td__k,) = (load(_o0, 0, 1, 2, 3, 4, 5, 6,
            8, 10, 12, 13, 14, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29))
        # chain rule through geyer_solution
        d_i_ab_omega__q_r_td = _j_i_ab_omega__q_r_td + _j_i_ab_omega__q_thd_td*d_i_q_thd_eff__q_r_td
        d_i_ab_omega__q_rd_td = _j_i_ab_omega__q_thd_td*d_i_q_thd_eff__q_rd_td
        d_i_ab_omega__q_th_td = _j_i_ab_omega__q_thd_td*d_i_q_thd_eff__q_th_td
        d_i_ab_omega__q_thd_td = _j_i_ab_omega__q_thd_td*d_i_q_thd_eff__q_thd_td
        d_i_ab_omega__k_c = _j_i_ab_omega__q_thd_td*d_i_q_thd_eff__k_c
        d_i_ab_omega__k_d = _j_i_ab_omega__q_thd_td*d_i_q_thd_eff__k_d
        d_i_ab_omega0_hat__q_r_td = (_j_i_ab_omega0_hat__q_r_td
            + _j_i_ab_omega0_hat__q_thd_td*d_i_q_thd_eff__q_r_td)
        d_i_ab_omega0_hat__q_rd_td = _j_i_ab_omega0_hat__q_thd_td*d_i_q_thd_eff__q_rd_td
        d_i_ab_omega0_hat__q_th_td = _j_i_ab_omega0_hat__q_thd_td*d_i_q_thd_eff__q_th_td
        d_i_ab_omega0_hat__q_thd_td = _j_i_ab_omega0_hat__q_thd_td*d_i_q_thd_eff__q_thd_td
        d_i_ab_omega0_hat__k_c = _j_i_ab_omega0_hat__k + _j_i_ab_omega0_hat__q_thd_td*d_i_q_thd_eff__k_c
        d_i_ab_omega0_hat__k_d = _j_i_ab_omega0_hat__q_thd_td*d_i_q_thd_eff__k_d
        d_i_ab_a__q_r_td = _j_i_ab_a__q_r_td + _j_i_ab_a__q_thd_td*d_i_q_thd_eff__q_r_td
        d_i_ab_a__q_rd_td = _j_i_ab_a__q_thd_td*d_i_q_thd_eff__q_rd_td
        d_i_ab_a__q_th_td = _j_i_ab_a__q_thd_td*d_i_q_thd_eff__q_th_td
        d_i_ab_a__q_thd_td = _j_i_ab_a__q_thd_td*d_i_q_thd_eff__q_thd_td
        d_i_ab_a__k_c = _j_i_ab_a__k + _j_i_ab_a__q_thd_td*d_i_q_thd_eff__k_c
        d_i_ab_a__k_d = _j_i_ab_a__q_thd_td*d_i_q_thd_eff__k_d
        d_i_ab_b__q_r_td = _j_i_ab_b__q_r_td + _j_i_ab_b__q_thd_td*d_i_q_thd_eff__q_r_td
        d_i_ab_b__q_rd_td = _j_i_ab_b__q_rd_td + _j_i_ab_b__q_thd_td*d_i_q_thd_eff__q_rd_td
        d_i_ab_b__q_th_td = _j_i_ab_b__q_thd_td*d_i_q_thd_eff__q_th_td
        d_i_ab_b__q_thd_td = _j_i_ab_b__q_thd_td*d_i_q_thd_eff__q_thd_td
        d_i_ab_b__k_c = _j_i_ab_b__k + _j_i_ab_b__q_thd_td*d_i_q_thd_eff__k_c
        d_i_ab_b__k_d = _j_i_ab_b__q_thd_td*d_i_q_thd_eff__k_d
        d_i_ab_phase_td__q_r_td = _j_i_ab_phase_td__q_r_td + _j_i_ab_phase_td__q_thd_td*d_i_q_thd_eff__q_r_td
        d_i_ab_phase_td__q_rd_td = (_j_i_ab_phase_td__q_rd_td
            + _j_i_ab_phase_td__q_thd_td*d_i_q_thd_eff__q_rd_td)
        d_i_ab_phase_td__q_th_td = _j_i_ab_phase_td__q_thd_td*d_i_q_thd_eff__q_th_td
        d_i_ab_phase_td__q_thd_td = _j_i_ab_phase_td__q_thd_td*d_i_q_thd_eff__q_thd_td
        d_i_ab_phase_td__k_c = _j_i_ab_phase_td__k + _j_i_ab_phase_td__q_thd_td*d_i_q_thd_eff__k_c
        d_i_ab_phase_td__k_d = _j_i_ab_phase_td__q_thd_td*d_i_q_thd_eff__k_d
        d_i_ab_s_td__q_r_td = _j_i_ab_s_td__q_r_td + _j_i_ab_s_td__q_thd_td*d_i_q_thd_eff__q_r_td
        d_i_ab_s_td__q_rd_td = _j_i_ab_s_td__q_rd_td + _j_i_ab_s_td__q_thd_td*d_i_q_thd_eff__q_rd_td
        d_i_ab_s_td__q_th_td = _j_i_ab_s_td__q_thd_td*d_i_q_thd_eff__q_th_td
        d_i_ab_s_td__q_thd_td = _j_i_ab_s_td__q_thd_td*d_i_q_thd_eff__q_thd_td
        d_i_ab_s_td__k_c = _j_i_ab_s_td__k + _j_i_ab_s_td__q_thd_td*d_i_q_thd_eff__k_c
        d_i_ab_s_td__k_d = _j_i_ab_s_td__q_thd_td*d_i_q_thd_eff__k_d
        # eqs (79)-(81): the bottom at phase 3 pi/2
        _x14 = (1.0/i_ab_omega0_hat)
        _x15 = -i_ab_phase_td + (1.5)*math.pi
        i_t_bottom = _x14*_x15
        _x16 = _x14**2
        _pd__2 = -_x15*_x16
        _pd__3 = -_x14
        d_i_t_bottom__q_r_td = _pd__2*d_i_ab_omega0_hat__q_r_td + _pd__3*d_i_ab_phase_td__q_r_td
        d_i_t_bottom__q_rd_td = _pd__2*d_i_ab_omega0_hat__q_rd_td + _pd__3*d_i_ab_phase_td__q_rd_td
        d_i_t_bottom__q_th_td = _pd__2*d_i_ab_omega0_hat__q_th_td + _pd__3*d_i_ab_phase_td__q_th_td
        d_i_t_bottom__q_thd_td = _pd__2*d_i_ab_omega0_hat__q_thd_td + _pd__3*d_i_ab_phase_td__q_thd_td
        d_i_t_bottom__k_c = _pd__2*d_i_ab_omega0_hat__k_c + _pd__3*d_i_ab_phase_td__k_c
        d_i_t_bottom__k_d = _pd__2*d_i_ab_omega0_hat__k_d + _pd__3*d_i_ab_phase_td__k_d
        _x17 = i_ab_a - i_ab_b
        _x18 = _x17 + 1.0
        i_bottom_q_r = _x18*l0
        d_i_bottom_q_r__q_r_td = d_i_ab_a__q_r_td*l0 - d_i_ab_b__q_r_td*l0
        d_i_bottom_q_r__q_rd_td = d_i_ab_a__q_rd_td*l0 - d_i_ab_b__q_rd_td*l0
        d_i_bottom_q_r__q_th_td = d_i_ab_a__q_th_td*l0 - d_i_ab_b__q_th_td*l0
        d_i_bottom_q_r__q_thd_td = d_i_ab_a__q_thd_td*l0 - d_i_ab_b__q_thd_td*l0
        d_i_bottom_q_r__k_c = d_i_ab_a__k_c*l0 - d_i_ab_b__k_c*l0
        d_i_bottom_q_r__k_d = d_i_ab_a__k_d*l0 - d_i_ab_b__k_d*l0
        i_bottom_q_rd = 0.0
        _x19 = (1.5)*math.pi
        _x20 = _x14*i_ab_omega
        _x21 = _x14*i_ab_phase_td
        _x22 = 3.0*math.pi
        _x23 = _x20*_x22
        _x24 = _x21*i_ab_a
        _x25 = math.sqrt(1.0 - i_ab_s_td**2)
        _x26 = _x25*i_ab_b
        _x27 = _x14*_x26
        _x28 = 2.0*i_ab_omega
        i_bottom_q_th = _x19*_x20 - _x21*i_ab_omega - _x23*i_ab_a + _x28*(_x24 + _x27) + q_th_td
        _pd__4 = _x21*_x28 - _x23
        _x29 = 2.0*_x20
        _pd__5 = _x25*_x29
        _x30 = _x22*i_ab_a
        _pd__6 = _x14*_x19 - _x14*_x30 - _x21 + 2.0*_x24 + 2.0*_x27
        _x31 = _x16*i_ab_phase_td
        _x32 = _x16*i_ab_omega
        _pd__7 = -_x19*_x32 + _x28*(-_x16*_x26 - _x31*i_ab_a) + _x30*_x32 + _x31*i_ab_omega
        _pd__8 = -_x20 + _x29*i_ab_a
        _pd__9 = -_x29*i_ab_b*i_ab_s_td/_x25
        d_i_bottom_q_th__q_r_td = (_pd__4*d_i_ab_a__q_r_td + _pd__5*d_i_ab_b__q_r_td
            + _pd__6*d_i_ab_omega__q_r_td + _pd__7*d_i_ab_omega0_hat__q_r_td + _pd__8*d_i_ab_phase_td__q_r_td
            + _pd__9*d_i_ab_s_td__q_r_td)
        d_i_bottom_q_th__q_rd_td = (_pd__4*d_i_ab_a__q_rd_td + _pd__5*d_i_ab_b__q_rd_td
            + _pd__6*d_i_ab_omega__q_rd_td + _pd__7*d_i_ab_omega0_hat__q_rd_td
            + _pd__8*d_i_ab_phase_td__q_rd_td + _pd__9*d_i_ab_s_td__q_rd_td)
        d_i_bottom_q_th__q_th_td = (_pd__4*d_i_ab_a__q_th_td + _pd__5*d_i_ab_b__q_th_td
            + _pd__6*d_i_ab_omega__q_th_td + _pd__7*d_i_ab_omega0_hat__q_th_td
            + _pd__8*d_i_ab_phase_td__q_th_td + _pd__9*d_i_ab_s_td__q_th_td + 1.0)
        d_i_bottom_q_th__q_thd_td = (_pd__4*d_i_ab_a__q_thd_td + _pd__5*d_i_ab_b__q_thd_td
            + _pd__6*d_i_ab_omega__q_thd_td + _pd__7*d_i_ab_omega0_hat__q_thd_td
            + _pd__8*d_i_ab_phase_td__q_thd_td + _pd__9*d_i_ab_s_td__q_thd_td)
        d_i_bottom_q_th__k_c = (_pd__4*d_i_ab_a__k_c + _pd__5*d_i_ab_b__k_c + _pd__6*d_i_ab_omega__k_c
            + _pd__7*d_i_ab_omega0_hat__k_c + _pd__8*d_i_ab_phase_td__k_c + _pd__9*d_i_ab_s_td__k_c)
        d_i_bottom_q_th__k_d = (_pd__4*d_i_ab_a__k_d + _pd__5*d_i_ab_b__k_d + _pd__6*d_i_ab_omega__k_d
            + _pd__7*d_i_ab_omega0_hat__k_d + _pd__8*d_i_ab_phase_td__k_d + _pd__9*d_i_ab_s_td__k_d)
        _x33 = P_c_compression + p_td
        i_p_b = _x33
        d_i_p_b__q_r_td = d_P_c_compression__q_r_td + d_p_td__q_r_td
        d_i_p_b__q_thd_td = d_P_c_compression__q_thd_td + d_p_td__q_thd_td
        _x34 = (1.0/m)
        _x36 = (1.0/_x18)
        _x37 = (1.0/l0)
        _x35 = _x34*_x36**2*_x37**2
        i_bottom_q_thd = _x33*_x35
        _pd__10 = -2.0*_x33*_x34*_x36**3*_x37**3
        _pd__11 = _x35
        d_i_bottom_q_thd__q_r_td = _pd__10*d_i_bottom_q_r__q_r_td + _pd__11*d_i_p_b__q_r_td
        d_i_bottom_q_thd__q_rd_td = _pd__10*d_i_bottom_q_r__q_rd_td + _pd__11*d_P_c_compression__q_rd_td
        d_i_bottom_q_thd__q_th_td = _pd__10*d_i_bottom_q_r__q_th_td + _pd__11*d_P_c_compression__q_th_td
        d_i_bottom_q_thd__q_thd_td = _pd__10*d_i_bottom_q_r__q_thd_td + _pd__11*d_i_p_b__q_thd_td
        d_i_bottom_q_thd__k_c = _pd__10*d_i_bottom_q_r__k_c + _pd__11*d_P_c_compression__k_c
        d_i_bottom_q_thd__k_d = _pd__10*d_i_bottom_q_r__k_d + _pd__11*d_P_c_compression__k_d
        i_rho_b = _x17
        _pd__12 = _x37
        d_i_rho_b__q_r_td = _pd__12*d_i_bottom_q_r__q_r_td
        d_i_rho_b__q_rd_td = _pd__12*d_i_bottom_q_r__q_rd_td
        d_i_rho_b__q_th_td = _pd__12*d_i_bottom_q_r__q_th_td
        d_i_rho_b__q_thd_td = _pd__12*d_i_bottom_q_r__q_thd_td
        d_i_rho_b__k_c = _pd__12*d_i_bottom_q_r__k_c
        d_i_rho_b__k_d = _pd__12*d_i_bottom_q_r__k_d
        # eqs (100)-(103): omega_ba from the momentum, omega0_ba^2 = k_d/m
        _x38 = (0.5)*P_c_decompression + i_p_b
        _x53 = (1.0/l0)
        _x39 = _x53**2
        _x40 = (1.0/m)
        _x41 = _x39*_x40
        i_ba_omega = _x38*_x41
        _pd__13 = (0.5)*_x41
        _pd__14 = _x41
        d_i_ba_omega__q_r_td = _pd__13*d_P_c_decompression__q_r_td + _pd__14*d_i_p_b__q_r_td
        d_i_ba_omega__q_rd_td = _pd__13*d_P_c_decompression__q_rd_td + _pd__14*d_P_c_compression__q_rd_td
        d_i_ba_omega__q_th_td = _pd__13*d_P_c_decompression__q_th_td + _pd__14*d_P_c_compression__q_th_td
        d_i_ba_omega__q_thd_td = _pd__13*d_P_c_decompression__q_thd_td + _pd__14*d_i_p_b__q_thd_td
        d_i_ba_omega__k_c = _pd__13*d_P_c_decompression__k_c + _pd__14*d_P_c_compression__k_c
        d_i_ba_omega__k_d = _pd__13*d_P_c_decompression__k_d + _pd__14*d_P_c_compression__k_d
        _x42 = (1.0/math.sqrt(m))
        _x43 = _x38**2
        _x44 = 3.0*_x40*_x43*_x53**4 + k_d
        _x45 = math.sqrt(_x44)
        i_ba_omega0_hat = _x42*_x45
        _x46 = _x42/_x45
        _x47 = _x38*_x39
        _pd__15 = 3.0*_x46*_x47
        d_i_ba_omega0_hat__q_r_td = _pd__15*d_i_ba_omega__q_r_td
        d_i_ba_omega0_hat__q_rd_td = _pd__15*d_i_ba_omega__q_rd_td
        d_i_ba_omega0_hat__q_th_td = _pd__15*d_i_ba_omega__q_th_td
        d_i_ba_omega0_hat__q_thd_td = _pd__15*d_i_ba_omega__q_thd_td
        d_i_ba_omega0_hat__k_c = _pd__15*d_i_ba_omega__k_c
        d_i_ba_omega0_hat__k_d = _pd__15*d_i_ba_omega__k_d + (0.5)*_x46
        _x48 = (1.0/_x44)
        _x49 = _x53**3
        _x50 = m*(_x40**2*_x43*_x49 - g_s)
        _x51 = _x50*_x53
        i_ba_a_free = _x48*_x51
        _x52 = _x48**2
        _pd__16 = -6.0*_x38*_x49*_x50*_x52 + 2.0*_x47*_x48
        d_i_ba_a_free__q_r_td = _pd__16*d_i_ba_omega__q_r_td
        d_i_ba_a_free__q_rd_td = _pd__16*d_i_ba_omega__q_rd_td
        d_i_ba_a_free__q_th_td = _pd__16*d_i_ba_omega__q_th_td
        d_i_ba_a_free__q_thd_td = _pd__16*d_i_ba_omega__q_thd_td
        d_i_ba_a_free__k_c = _pd__16*d_i_ba_omega__k_c
        d_i_ba_a_free__k_d = _pd__16*d_i_ba_omega__k_d - _x51*_x52
        # with k_d the bottom lies below the centre a_ba of (90): the leg extends
        if not ((i_rho_b < i_ba_a_free)):
            return fail(out, STATUS_RECOMPRESSION)
        # E_ab of (98)
        if continuity == 0.0:
            # eqs (97)-(99), E_ab the energy (27)
            _x54 = k_c - k_d
            _x55 = (-i_bottom_q_r + l0)**2
            _x56 = 1.0/(l0**2*m)
            i_eps_ba = _x56*(2.0*E_td - _x54*_x55)
            _pd__17 = 2.0*_x56
            _pd__18 = -_x54*_x56*(2.0*i_bottom_q_r - 2.0*l0)
            d_i_eps_ba__q_r_td = _pd__17*d_E_td__q_r_td + _pd__18*d_i_bottom_q_r__q_r_td
            d_i_eps_ba__q_rd_td = _pd__17*d_E_td__q_rd_td + _pd__18*d_i_bottom_q_r__q_rd_td
            d_i_eps_ba__q_th_td = _pd__17*d_E_td__q_th_td + _pd__18*d_i_bottom_q_r__q_th_td
            d_i_eps_ba__q_thd_td = _pd__17*d_E_td__q_thd_td + _pd__18*d_i_bottom_q_r__q_thd_td
            _x57 = _x55*_x56
            d_i_eps_ba__k_c = _pd__17*d_E_td__k_c + _pd__18*d_i_bottom_q_r__k_c - _x57
            d_i_eps_ba__k_d = _pd__18*d_i_bottom_q_r__k_d + _x57
        elif continuity == 1.0:
            # as report
            _x58 = k_c - k_d
            _x59 = (-i_bottom_q_r + l0)**2
            _x60 = 1.0/(l0**2*m)
            i_eps_ba = _x60*(2.0*E_td - _x58*_x59)
            _pd__19 = 2.0*_x60
            _pd__20 = -_x58*_x60*(2.0*i_bottom_q_r - 2.0*l0)
            d_i_eps_ba__q_r_td = _pd__19*d_E_td__q_r_td + _pd__20*d_i_bottom_q_r__q_r_td
            d_i_eps_ba__q_rd_td = _pd__19*d_E_td__q_rd_td + _pd__20*d_i_bottom_q_r__q_rd_td
            d_i_eps_ba__q_th_td = _pd__19*d_E_td__q_th_td + _pd__20*d_i_bottom_q_r__q_th_td
            d_i_eps_ba__q_thd_td = _pd__19*d_E_td__q_thd_td + _pd__20*d_i_bottom_q_r__q_thd_td
            _x61 = _x59*_x60
            d_i_eps_ba__k_c = _pd__19*d_E_td__k_c + _pd__20*d_i_bottom_q_r__k_c - _x61
            d_i_eps_ba__k_d = _pd__20*d_i_bottom_q_r__k_d + _x61
        elif continuity == 2.0:
            # eqs (97)-(99) with E_ab Geyer's energy (8) at the bottom
            _x62 = i_ba_omega**2
            _x71 = (1.0/l0)
            _x63 = 2.0*_x71*g_s
            _x64 = -2.0*_x62 + _x63
            _x65 = i_rho_b**2
            _x66 = (1.0/m)
            _x67 = 3.0*_x62 + _x66*k_c
            _x68 = k_c - k_d
            _x69 = _x66*_x71**2
            _x70 = _x69*(-i_bottom_q_r + l0)**2
            i_eps_ba = _x62 + _x63 + _x64*i_rho_b + _x65*_x67 - _x68*_x70
            _pd__21 = 6.0*_x65*i_ba_omega - 4.0*i_ba_omega*i_rho_b + 2.0*i_ba_omega
            _pd__22 = -_x68*_x69*(2.0*i_bottom_q_r - 2.0*l0)
            _pd__23 = _x64 + 2.0*_x67*i_rho_b
            d_i_eps_ba__q_r_td = (_pd__21*d_i_ba_omega__q_r_td + _pd__22*d_i_bottom_q_r__q_r_td
                + _pd__23*d_i_rho_b__q_r_td)
            d_i_eps_ba__q_rd_td = (_pd__21*d_i_ba_omega__q_rd_td + _pd__22*d_i_bottom_q_r__q_rd_td
                + _pd__23*d_i_rho_b__q_rd_td)
            d_i_eps_ba__q_th_td = (_pd__21*d_i_ba_omega__q_th_td + _pd__22*d_i_bottom_q_r__q_th_td
                + _pd__23*d_i_rho_b__q_th_td)
            d_i_eps_ba__q_thd_td = (_pd__21*d_i_ba_omega__q_thd_td + _pd__22*d_i_bottom_q_r__q_thd_td
                + _pd__23*d_i_rho_b__q_thd_td)
            d_i_eps_ba__k_c = (_pd__21*d_i_ba_omega__k_c + _pd__22*d_i_bottom_q_r__k_c
                + _pd__23*d_i_rho_b__k_c + _x65*_x66 - _x70)
            d_i_eps_ba__k_d = (_pd__21*d_i_ba_omega__k_d + _pd__22*d_i_bottom_q_r__k_d
                + _pd__23*d_i_rho_b__k_d + _x70)
        else:
            return fail(out, STATUS_INVALID_INPUT)
        _x72 = i_ba_omega**2
        _x73 = 3.0*_x72*m + k_d
        _x83 = (1.0/_x73)
        _x74 = _x83**2*m
        _x75 = l0**2
        _x76 = (1.0/_x75)
        _x77 = -_x72*l0 + g_s
        _x78 = 2.0*g_s - l0*(-_x72 + i_eps_ba)
        _x79 = _x78*l0
        _x80 = _x76*(_x73*_x79 - _x77**2*m)
        i_ba_b2 = -_x74*_x80
        _x81 = _x80*_x83**3
        _x82 = i_ba_omega*m
        _pd__24 = (-_x74*_x76*(2.0*_x73*_x75*i_ba_omega + 4.0*_x77*_x82*l0 + 6.0*_x79*_x82)
            + 12.0*_x81*i_ba_omega*m**2)
        _pd__25 = _x83*m
        d_i_ba_b2__q_r_td = _pd__24*d_i_ba_omega__q_r_td + _pd__25*d_i_eps_ba__q_r_td
        d_i_ba_b2__q_rd_td = _pd__24*d_i_ba_omega__q_rd_td + _pd__25*d_i_eps_ba__q_rd_td
        d_i_ba_b2__q_th_td = _pd__24*d_i_ba_omega__q_th_td + _pd__25*d_i_eps_ba__q_th_td
        d_i_ba_b2__q_thd_td = _pd__24*d_i_ba_omega__q_thd_td + _pd__25*d_i_eps_ba__q_thd_td
        d_i_ba_b2__k_c = _pd__24*d_i_ba_omega__k_c + _pd__25*d_i_eps_ba__k_c
        d_i_ba_b2__k_d = _pd__24*d_i_ba_omega__k_d + _pd__25*d_i_eps_ba__k_d - _x74*_x78/l0 + 2.0*_x81*m
        # eq (104): real amplitude b_ba
        if not ((i_ba_b2 > 0.0)):
            return fail(out, STATUS_NO_REAL_SOLUTION)
        # eq (104); eq (103), or (111) when constrained
        _x84 = math.sqrt(i_ba_b2)
        i_ba_b = _x84
        _pd__26 = (0.5)/_x84
        d_i_ba_b__q_r_td = _pd__26*d_i_ba_b2__q_r_td
        d_i_ba_b__q_rd_td = _pd__26*d_i_ba_b2__q_rd_td
        d_i_ba_b__q_th_td = _pd__26*d_i_ba_b2__q_th_td
        d_i_ba_b__q_thd_td = _pd__26*d_i_ba_b2__q_thd_td
        d_i_ba_b__k_c = _pd__26*d_i_ba_b2__k_c
        d_i_ba_b__k_d = _pd__26*d_i_ba_b2__k_d
        _x85 = (continuity == 1.0)
        i_ba_a = ((_x84 + i_rho_b) if _x85 else (i_ba_a_free))
        _pd__27 = ((0.0) if _x85 else (1.0))
        _x86 = ((1.0) if _x85 else (0.0))
        _pd__28 = _x86
        _pd__29 = _x86
        d_i_ba_a__q_r_td = (_pd__27*d_i_ba_a_free__q_r_td + _pd__28*d_i_ba_b__q_r_td
            + _pd__29*d_i_rho_b__q_r_td)
        d_i_ba_a__q_rd_td = (_pd__27*d_i_ba_a_free__q_rd_td + _pd__28*d_i_ba_b__q_rd_td
            + _pd__29*d_i_rho_b__q_rd_td)
        d_i_ba_a__q_th_td = (_pd__27*d_i_ba_a_free__q_th_td + _pd__28*d_i_ba_b__q_th_td
            + _pd__29*d_i_rho_b__q_th_td)
        d_i_ba_a__q_thd_td = (_pd__27*d_i_ba_a_free__q_thd_td + _pd__28*d_i_ba_b__q_thd_td
            + _pd__29*d_i_rho_b__q_thd_td)
        d_i_ba_a__k_c = _pd__27*d_i_ba_a_free__k_c + _pd__28*d_i_ba_b__k_c + _pd__29*d_i_rho_b__k_c
        d_i_ba_a__k_d = _pd__27*d_i_ba_a_free__k_d + _pd__28*d_i_ba_b__k_d + _pd__29*d_i_rho_b__k_d
        # eq (94): the liftoff phase of the second half
        _c1 = geyer_liftoff_phase_jac_a_b(i_ba_a, i_ba_b, l0, q_r_lo)
        if _c1[6] != STATUS_OK:
            return fail(out, _c1[6])
        i_ba_phase_lo = _c1[0]
        i_ba_s_lo = _c1[1]
        _j_i_ba_phase_lo__a = _c1[2]
        _j_i_ba_phase_lo__b = _c1[3]
        _j_i_ba_s_lo__a = _c1[4]
        _j_i_ba_s_lo__b = _c1[5]
        # chain rule through geyer_liftoff_phase
        d_i_ba_phase_lo__q_r_td = _j_i_ba_phase_lo__a*d_i_ba_a__q_r_td + _j_i_ba_phase_lo__b*d_i_ba_b__q_r_td
        d_i_ba_phase_lo__q_rd_td = (_j_i_ba_phase_lo__a*d_i_ba_a__q_rd_td
            + _j_i_ba_phase_lo__b*d_i_ba_b__q_rd_td)
        d_i_ba_phase_lo__q_th_td = (_j_i_ba_phase_lo__a*d_i_ba_a__q_th_td
            + _j_i_ba_phase_lo__b*d_i_ba_b__q_th_td)
        d_i_ba_phase_lo__q_thd_td = (_j_i_ba_phase_lo__a*d_i_ba_a__q_thd_td
            + _j_i_ba_phase_lo__b*d_i_ba_b__q_thd_td)
        d_i_ba_phase_lo__k_c = _j_i_ba_phase_lo__a*d_i_ba_a__k_c + _j_i_ba_phase_lo__b*d_i_ba_b__k_c
        d_i_ba_phase_lo__k_d = _j_i_ba_phase_lo__a*d_i_ba_a__k_d + _j_i_ba_phase_lo__b*d_i_ba_b__k_d
        d_i_ba_s_lo__q_r_td = _j_i_ba_s_lo__a*d_i_ba_a__q_r_td + _j_i_ba_s_lo__b*d_i_ba_b__q_r_td
        d_i_ba_s_lo__q_rd_td = _j_i_ba_s_lo__a*d_i_ba_a__q_rd_td + _j_i_ba_s_lo__b*d_i_ba_b__q_rd_td
        d_i_ba_s_lo__q_th_td = _j_i_ba_s_lo__a*d_i_ba_a__q_th_td + _j_i_ba_s_lo__b*d_i_ba_b__q_th_td
        d_i_ba_s_lo__q_thd_td = _j_i_ba_s_lo__a*d_i_ba_a__q_thd_td + _j_i_ba_s_lo__b*d_i_ba_b__q_thd_td
        d_i_ba_s_lo__k_c = _j_i_ba_s_lo__a*d_i_ba_a__k_c + _j_i_ba_s_lo__b*d_i_ba_b__k_c
        d_i_ba_s_lo__k_d = _j_i_ba_s_lo__a*d_i_ba_a__k_d + _j_i_ba_s_lo__b*d_i_ba_b__k_d
        # eqs (90)-(94) at liftoff
        _x87 = (1.0/i_ba_omega0_hat)
        _x88 = (1.5)*math.pi
        _x89 = -_x88 + i_ba_phase_lo
        i_t_stance = _x87*_x89 + i_t_bottom
        _x90 = _x87**2
        _pd__30 = -_x89*_x90
        _pd__31 = _x87
        d_i_t_stance__q_r_td = (_pd__30*d_i_ba_omega0_hat__q_r_td + _pd__31*d_i_ba_phase_lo__q_r_td
            + d_i_t_bottom__q_r_td)
        d_i_t_stance__q_rd_td = (_pd__30*d_i_ba_omega0_hat__q_rd_td + _pd__31*d_i_ba_phase_lo__q_rd_td
            + d_i_t_bottom__q_rd_td)
        d_i_t_stance__q_th_td = (_pd__30*d_i_ba_omega0_hat__q_th_td + _pd__31*d_i_ba_phase_lo__q_th_td
            + d_i_t_bottom__q_th_td)
        d_i_t_stance__q_thd_td = (_pd__30*d_i_ba_omega0_hat__q_thd_td + _pd__31*d_i_ba_phase_lo__q_thd_td
            + d_i_t_bottom__q_thd_td)
        d_i_t_stance__k_c = _pd__30*d_i_ba_omega0_hat__k_c + _pd__31*d_i_ba_phase_lo__k_c + d_i_t_bottom__k_c
        d_i_t_stance__k_d = _pd__30*d_i_ba_omega0_hat__k_d + _pd__31*d_i_ba_phase_lo__k_d + d_i_t_bottom__k_d
        i_liftoff_q_r = q_r_lo
        _x91 = _x87*i_ba_phase_lo
        _x92 = _x87*i_ba_omega
        _x93 = 3.0*math.pi
        _x94 = _x91*i_ba_a
        _x95 = math.sqrt(1.0 - i_ba_s_lo**2)
        _x96 = _x87*_x95*i_ba_b
        _x97 = 2.0*i_ba_omega
        _x98 = -_x88*_x92 + _x91*i_ba_omega + _x92*_x93*i_ba_a - _x97*(_x94 - _x96) + i_bottom_q_th
        i_liftoff_q_th = _x98
        _pd__32 = 3.0*math.pi*_x87*i_ba_omega - _x91*_x97
        _x99 = 2.0*_x92
        _pd__33 = _x95*_x99
        _x100 = _x93*i_ba_a
        _pd__34 = _x100*_x87 - _x87*_x88 + _x91 - 2.0*_x94 + 2.0*_x96
        _x101 = _x90*i_ba_phase_lo
        _pd__35 = (-_x100*_x90*i_ba_omega - _x101*i_ba_omega + (1.5)*math.pi*_x90*i_ba_omega
            - _x97*(-_x101*i_ba_a + _x90*_x95*i_ba_b))
        _pd__36 = _x87*i_ba_omega - _x99*i_ba_a
        _pd__37 = -_x99*i_ba_b*i_ba_s_lo/_x95
        d_i_liftoff_q_th__q_r_td = (_pd__32*d_i_ba_a__q_r_td + _pd__33*d_i_ba_b__q_r_td
            + _pd__34*d_i_ba_omega__q_r_td + _pd__35*d_i_ba_omega0_hat__q_r_td
            + _pd__36*d_i_ba_phase_lo__q_r_td + _pd__37*d_i_ba_s_lo__q_r_td + d_i_bottom_q_th__q_r_td)
        d_i_liftoff_q_th__q_rd_td = (_pd__32*d_i_ba_a__q_rd_td + _pd__33*d_i_ba_b__q_rd_td
            + _pd__34*d_i_ba_omega__q_rd_td + _pd__35*d_i_ba_omega0_hat__q_rd_td
            + _pd__36*d_i_ba_phase_lo__q_rd_td + _pd__37*d_i_ba_s_lo__q_rd_td + d_i_bottom_q_th__q_rd_td)
        d_i_liftoff_q_th__q_th_td = (_pd__32*d_i_ba_a__q_th_td + _pd__33*d_i_ba_b__q_th_td
            + _pd__34*d_i_ba_omega__q_th_td + _pd__35*d_i_ba_omega0_hat__q_th_td
            + _pd__36*d_i_ba_phase_lo__q_th_td + _pd__37*d_i_ba_s_lo__q_th_td + d_i_bottom_q_th__q_th_td)
        d_i_liftoff_q_th__q_thd_td = (_pd__32*d_i_ba_a__q_thd_td + _pd__33*d_i_ba_b__q_thd_td
            + _pd__34*d_i_ba_omega__q_thd_td + _pd__35*d_i_ba_omega0_hat__q_thd_td
            + _pd__36*d_i_ba_phase_lo__q_thd_td + _pd__37*d_i_ba_s_lo__q_thd_td + d_i_bottom_q_th__q_thd_td)
        d_i_liftoff_q_th__k_c = (_pd__32*d_i_ba_a__k_c + _pd__33*d_i_ba_b__k_c + _pd__34*d_i_ba_omega__k_c
            + _pd__35*d_i_ba_omega0_hat__k_c + _pd__36*d_i_ba_phase_lo__k_c + _pd__37*d_i_ba_s_lo__k_c
            + d_i_bottom_q_th__k_c)
        d_i_liftoff_q_th__k_d = (_pd__32*d_i_ba_a__k_d + _pd__33*d_i_ba_b__k_d + _pd__34*d_i_ba_omega__k_d
            + _pd__35*d_i_ba_omega0_hat__k_d + _pd__36*d_i_ba_phase_lo__k_d + _pd__37*d_i_ba_s_lo__k_d
            + d_i_bottom_q_th__k_d)
        _x102 = P_c_decompression + i_p_b
        _x103 = (1.0/m)
        _x104 = q_r_lo**2
        _x105 = (1.0/_x104)
        _x106 = _x103*_x105
        i_liftoff_q_thd = _x102*_x106
        _pd__38 = _x106
        _pd__39 = _x106
        d_i_liftoff_q_thd__q_r_td = _pd__38*d_P_c_decompression__q_r_td + _pd__39*d_i_p_b__q_r_td
        d_i_liftoff_q_thd__q_rd_td = _pd__38*d_P_c_decompression__q_rd_td + _pd__39*d_P_c_compression__q_rd_td
        d_i_liftoff_q_thd__q_th_td = _pd__38*d_P_c_decompression__q_th_td + _pd__39*d_P_c_compression__q_th_td
        d_i_liftoff_q_thd__q_thd_td = _pd__38*d_P_c_decompression__q_thd_td + _pd__39*d_i_p_b__q_thd_td
        d_i_liftoff_q_thd__k_c = _pd__38*d_P_c_decompression__k_c + _pd__39*d_P_c_compression__k_c
        d_i_liftoff_q_thd__k_d = _pd__38*d_P_c_decompression__k_d + _pd__39*d_P_c_compression__k_d
        _x107 = _x103*l0**2
        _x108 = _x103*_x104
        _x109 = _x103**2*_x105
        _x110 = k_c - k_d
        _x111 = (-i_bottom_q_r + l0)**2
        _x112 = 2.0*g_s*q_r_lo
        i_q_rd_lo_sq = (-_x102**2*_x109 + 2.0*_x103*k_d*l0*q_r_lo + 2.0*_x103*(E_td - 0.5*_x110*_x111)
            - _x107*k_d - _x108*k_d - _x112*math.cos(_x98))
        _x113 = 2.0*_x103
        _pd__40 = _x113
        _x114 = -_x109*(2.0*P_c_decompression + 2.0*i_p_b)
        _pd__41 = _x114
        _pd__42 = -_x103*_x110*(2.0*i_bottom_q_r - 2.0*l0)
        _pd__43 = _x112*math.sin(_x98)
        _pd__44 = _x114
        d_i_q_rd_lo_sq__q_r_td = (_pd__40*d_E_td__q_r_td + _pd__41*d_P_c_decompression__q_r_td
            + _pd__42*d_i_bottom_q_r__q_r_td + _pd__43*d_i_liftoff_q_th__q_r_td + _pd__44*d_i_p_b__q_r_td)
        d_i_q_rd_lo_sq__q_rd_td = (_pd__40*d_E_td__q_rd_td + _pd__41*d_P_c_decompression__q_rd_td
            + _pd__42*d_i_bottom_q_r__q_rd_td + _pd__43*d_i_liftoff_q_th__q_rd_td
            + _pd__44*d_P_c_compression__q_rd_td)
        d_i_q_rd_lo_sq__q_th_td = (_pd__40*d_E_td__q_th_td + _pd__41*d_P_c_decompression__q_th_td
            + _pd__42*d_i_bottom_q_r__q_th_td + _pd__43*d_i_liftoff_q_th__q_th_td
            + _pd__44*d_P_c_compression__q_th_td)
        d_i_q_rd_lo_sq__q_thd_td = (_pd__40*d_E_td__q_thd_td + _pd__41*d_P_c_decompression__q_thd_td
            + _pd__42*d_i_bottom_q_r__q_thd_td + _pd__43*d_i_liftoff_q_th__q_thd_td
            + _pd__44*d_i_p_b__q_thd_td)
        _x115 = _x103*_x111
        d_i_q_rd_lo_sq__k_c = (_pd__40*d_E_td__k_c + _pd__41*d_P_c_decompression__k_c
            + _pd__42*d_i_bottom_q_r__k_c + _pd__43*d_i_liftoff_q_th__k_c + _pd__44*d_P_c_compression__k_c
            - _x115)
        d_i_q_rd_lo_sq__k_d = (_pd__41*d_P_c_decompression__k_d + _pd__42*d_i_bottom_q_r__k_d
            + _pd__43*d_i_liftoff_q_th__k_d + _pd__44*d_P_c_compression__k_d - _x107 - _x108 + _x113*l0*q_r_lo
            + _x115)
        # the leg stays above horizontal
        if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
            return fail(out, STATUS_FALL)
        # q_rd_lo^2 from the energy
        if not ((gravity == 0.0) or (i_q_rd_lo_sq >= 0.0)):
            return fail(out, STATUS_ENERGY_DEFICIT)
        # q_rd_lo: (11) without a gravity correction, the energy with one
        _x116 = math.sqrt(1.0 - i_ba_s_lo**2)
        _x117 = _x116*l0
        _x118 = _x117*i_ba_omega0_hat
        _x119 = (gravity == 0.0)
        _x120 = math.sqrt(i_q_rd_lo_sq)
        i_liftoff_q_rd = ((_x118*i_ba_b) if _x119 else (_x120))
        _pd__45 = ((_x118) if _x119 else (0.0))
        _pd__46 = ((_x117*i_ba_b) if _x119 else (0.0))
        _pd__47 = ((-i_ba_b*i_ba_omega0_hat*i_ba_s_lo*l0/_x116) if _x119 else (0.0))
        _pd__48 = ((0.0) if _x119 else ((0.5)/_x120))
        d_i_liftoff_q_rd__q_r_td = (_pd__45*d_i_ba_b__q_r_td + _pd__46*d_i_ba_omega0_hat__q_r_td
            + _pd__47*d_i_ba_s_lo__q_r_td + _pd__48*d_i_q_rd_lo_sq__q_r_td)
        d_i_liftoff_q_rd__q_rd_td = (_pd__45*d_i_ba_b__q_rd_td + _pd__46*d_i_ba_omega0_hat__q_rd_td
            + _pd__47*d_i_ba_s_lo__q_rd_td + _pd__48*d_i_q_rd_lo_sq__q_rd_td)
        d_i_liftoff_q_rd__q_th_td = (_pd__45*d_i_ba_b__q_th_td + _pd__46*d_i_ba_omega0_hat__q_th_td
            + _pd__47*d_i_ba_s_lo__q_th_td + _pd__48*d_i_q_rd_lo_sq__q_th_td)
        d_i_liftoff_q_rd__q_thd_td = (_pd__45*d_i_ba_b__q_thd_td + _pd__46*d_i_ba_omega0_hat__q_thd_td
            + _pd__47*d_i_ba_s_lo__q_thd_td + _pd__48*d_i_q_rd_lo_sq__q_thd_td)
        d_i_liftoff_q_rd__k_c = (_pd__45*d_i_ba_b__k_c + _pd__46*d_i_ba_omega0_hat__k_c
            + _pd__47*d_i_ba_s_lo__k_c + _pd__48*d_i_q_rd_lo_sq__k_c)
        d_i_liftoff_q_rd__k_d = (_pd__45*d_i_ba_b__k_d + _pd__46*d_i_ba_omega0_hat__k_d
            + _pd__47*d_i_ba_s_lo__k_d + _pd__48*d_i_q_rd_lo_sq__k_d)
        if _conv0 or _it0 == _last0:
            break
        # the virtual gravity effect of each half
        if gravity == 0.0:
            i_P_new1 = 0.0
            i_P_new2 = 0.0
            # tangents as every branch names them
            d_i_P_new1__q_r_td = 0.0
            d_i_P_new1__q_rd_td = 0.0
            d_i_P_new1__q_th_td = 0.0
            d_i_P_new1__q_thd_td = 0.0
            d_i_P_new1__k_c = 0.0
            d_i_P_new1__k_d = 0.0
            d_i_P_new2__q_r_td = 0.0
            d_i_P_new2__q_rd_td = 0.0
            d_i_P_new2__q_th_td = 0.0
            d_i_P_new2__q_thd_td = 0.0
            d_i_P_new2__k_c = 0.0
            d_i_P_new2__k_d = 0.0
        elif gravity == 1.0:
            # eq (65) on each half
            _x121 = g_s*m
            _x122 = _x121*math.sin(i_bottom_q_th)
            _x123 = _x122*i_bottom_q_r
            _x124 = _x121*math.sin(q_th_td)
            _x125 = _x124*q_r_td
            _x126 = (0.5)*i_t_bottom
            i_P_new1 = _x126*(_x123 + _x125)
            _pd__49 = _x122*_x126
            _x127 = _x121*_x126
            _x128 = i_bottom_q_r*math.cos(i_bottom_q_th)
            _pd__50 = _x127*_x128
            _x129 = (0.5)*_x123
            _pd__51 = (0.5)*_x125 + _x129
            d_i_P_new1__q_r_td = (_pd__49*d_i_bottom_q_r__q_r_td + _pd__50*d_i_bottom_q_th__q_r_td
                + _pd__51*d_i_t_bottom__q_r_td + _x124*_x126)
            d_i_P_new1__q_rd_td = (_pd__49*d_i_bottom_q_r__q_rd_td + _pd__50*d_i_bottom_q_th__q_rd_td
                + _pd__51*d_i_t_bottom__q_rd_td)
            d_i_P_new1__q_th_td = (_pd__49*d_i_bottom_q_r__q_th_td + _pd__50*d_i_bottom_q_th__q_th_td
                + _pd__51*d_i_t_bottom__q_th_td + _x127*q_r_td*math.cos(q_th_td))
            d_i_P_new1__q_thd_td = (_pd__49*d_i_bottom_q_r__q_thd_td + _pd__50*d_i_bottom_q_th__q_thd_td
                + _pd__51*d_i_t_bottom__q_thd_td)
            d_i_P_new1__k_c = (_pd__49*d_i_bottom_q_r__k_c + _pd__50*d_i_bottom_q_th__k_c
                + _pd__51*d_i_t_bottom__k_c)
            d_i_P_new1__k_d = (_pd__49*d_i_bottom_q_r__k_d + _pd__50*d_i_bottom_q_th__k_d
                + _pd__51*d_i_t_bottom__k_d)
            _x130 = _x121*q_r_lo
            _x131 = _x130*math.sin(i_liftoff_q_th)
            _x132 = -0.5*i_t_bottom + (0.5)*i_t_stance
            i_P_new2 = _x132*(_x123 + _x131)
            _pd__52 = _x122*_x132
            _pd__53 = _x121*_x128*_x132
            _pd__54 = _x130*_x132*math.cos(i_liftoff_q_th)
            _x133 = _x129 + (0.5)*_x131
            _pd__55 = -_x133
            _pd__56 = _x133
            d_i_P_new2__q_r_td = (_pd__52*d_i_bottom_q_r__q_r_td + _pd__53*d_i_bottom_q_th__q_r_td
                + _pd__54*d_i_liftoff_q_th__q_r_td + _pd__55*d_i_t_bottom__q_r_td
                + _pd__56*d_i_t_stance__q_r_td)
            d_i_P_new2__q_rd_td = (_pd__52*d_i_bottom_q_r__q_rd_td + _pd__53*d_i_bottom_q_th__q_rd_td
                + _pd__54*d_i_liftoff_q_th__q_rd_td + _pd__55*d_i_t_bottom__q_rd_td
                + _pd__56*d_i_t_stance__q_rd_td)
            d_i_P_new2__q_th_td = (_pd__52*d_i_bottom_q_r__q_th_td + _pd__53*d_i_bottom_q_th__q_th_td
                + _pd__54*d_i_liftoff_q_th__q_th_td + _pd__55*d_i_t_bottom__q_th_td
                + _pd__56*d_i_t_stance__q_th_td)
            d_i_P_new2__q_thd_td = (_pd__52*d_i_bottom_q_r__q_thd_td + _pd__53*d_i_bottom_q_th__q_thd_td
                + _pd__54*d_i_liftoff_q_th__q_thd_td + _pd__55*d_i_t_bottom__q_thd_td
                + _pd__56*d_i_t_stance__q_thd_td)
            d_i_P_new2__k_c = (_pd__52*d_i_bottom_q_r__k_c + _pd__53*d_i_bottom_q_th__k_c
                + _pd__54*d_i_liftoff_q_th__k_c + _pd__55*d_i_t_bottom__k_c + _pd__56*d_i_t_stance__k_c)
            d_i_P_new2__k_d = (_pd__52*d_i_bottom_q_r__k_d + _pd__53*d_i_bottom_q_th__k_d
                + _pd__54*d_i_liftoff_q_th__k_d + _pd__55*d_i_t_bottom__k_d + _pd__56*d_i_t_stance__k_d)
        elif gravity == 2.0:
            # eq (76) on each half, the average leg length of (11) on it
            _x134 = math.cos(i_ab_phase_td)
            _x135 = i_ab_a + 1.0
            _x136 = (1.5)*math.pi
            _x137 = l0*(_x134*i_ab_b + _x135*_x136 - _x135*i_ab_phase_td)
            _x138 = (1.0/i_ab_omega0_hat)
            _x139 = -_x138*i_ab_phase_td + (1.5)*math.pi*_x138
            _x140 = (1.0/_x139)
            _x141 = _x138*_x140
            _x142 = _x137*_x141
            _i_L1 = _x142
            _x143 = -_x136
            _x144 = _x141*l0
            _pd__57 = _x144*(-_x143 - i_ab_phase_td)
            _pd__58 = _x134*_x144
            _x145 = _x138**2
            _x146 = _x137*_x145
            _x147 = _x140**2
            _pd__59 = _x137*_x138*_x147*(-_x145*i_ab_phase_td + (1.5)*math.pi*_x145) - _x140*_x146
            _pd__60 = _x144*(-_x135 - i_ab_b*math.sin(i_ab_phase_td)) + _x146*_x147
            _d_i_L1__q_r_td = (_pd__57*d_i_ab_a__q_r_td + _pd__58*d_i_ab_b__q_r_td
                + _pd__59*d_i_ab_omega0_hat__q_r_td + _pd__60*d_i_ab_phase_td__q_r_td)
            _d_i_L1__q_rd_td = (_pd__57*d_i_ab_a__q_rd_td + _pd__58*d_i_ab_b__q_rd_td
                + _pd__59*d_i_ab_omega0_hat__q_rd_td + _pd__60*d_i_ab_phase_td__q_rd_td)
            _d_i_L1__q_th_td = (_pd__57*d_i_ab_a__q_th_td + _pd__58*d_i_ab_b__q_th_td
                + _pd__59*d_i_ab_omega0_hat__q_th_td + _pd__60*d_i_ab_phase_td__q_th_td)
            _d_i_L1__q_thd_td = (_pd__57*d_i_ab_a__q_thd_td + _pd__58*d_i_ab_b__q_thd_td
                + _pd__59*d_i_ab_omega0_hat__q_thd_td + _pd__60*d_i_ab_phase_td__q_thd_td)
            _d_i_L1__k_c = (_pd__57*d_i_ab_a__k_c + _pd__58*d_i_ab_b__k_c + _pd__59*d_i_ab_omega0_hat__k_c
                + _pd__60*d_i_ab_phase_td__k_c)
            _d_i_L1__k_d = (_pd__57*d_i_ab_a__k_d + _pd__58*d_i_ab_b__k_d + _pd__59*d_i_ab_omega0_hat__k_d
                + _pd__60*d_i_ab_phase_td__k_d)
            _x148 = math.cos(i_ba_phase_lo)
            _x149 = i_ba_a + 1.0
            _x150 = l0*(-_x136*_x149 - _x148*i_ba_b + _x149*i_ba_phase_lo)
            _x151 = (1.0/i_ba_omega0_hat)
            _x152 = -_x136*_x151 + _x151*i_ba_phase_lo
            _x153 = (1.0/_x152)
            _x154 = _x151*_x153
            _x155 = _x150*_x154
            _i_L2 = _x155
            _x156 = _x154*l0
            _pd__61 = _x156*(_x143 + i_ba_phase_lo)
            _pd__62 = -_x148*_x156
            _x157 = _x151**2
            _x158 = _x150*_x157
            _x159 = _x153**2
            _pd__63 = _x150*_x151*_x159*(-_x136*_x157 + _x157*i_ba_phase_lo) - _x153*_x158
            _pd__64 = _x156*(_x149 + i_ba_b*math.sin(i_ba_phase_lo)) - _x158*_x159
            _d_i_L2__q_r_td = (_pd__61*d_i_ba_a__q_r_td + _pd__62*d_i_ba_b__q_r_td
                + _pd__63*d_i_ba_omega0_hat__q_r_td + _pd__64*d_i_ba_phase_lo__q_r_td)
            _d_i_L2__q_rd_td = (_pd__61*d_i_ba_a__q_rd_td + _pd__62*d_i_ba_b__q_rd_td
                + _pd__63*d_i_ba_omega0_hat__q_rd_td + _pd__64*d_i_ba_phase_lo__q_rd_td)
            _d_i_L2__q_th_td = (_pd__61*d_i_ba_a__q_th_td + _pd__62*d_i_ba_b__q_th_td
                + _pd__63*d_i_ba_omega0_hat__q_th_td + _pd__64*d_i_ba_phase_lo__q_th_td)
            _d_i_L2__q_thd_td = (_pd__61*d_i_ba_a__q_thd_td + _pd__62*d_i_ba_b__q_thd_td
                + _pd__63*d_i_ba_omega0_hat__q_thd_td + _pd__64*d_i_ba_phase_lo__q_thd_td)
            _d_i_L2__k_c = (_pd__61*d_i_ba_a__k_c + _pd__62*d_i_ba_b__k_c + _pd__63*d_i_ba_omega0_hat__k_c
                + _pd__64*d_i_ba_phase_lo__k_c)
            _d_i_L2__k_d = (_pd__61*d_i_ba_a__k_d + _pd__62*d_i_ba_b__k_d + _pd__63*d_i_ba_omega0_hat__k_d
                + _pd__64*d_i_ba_phase_lo__k_d)
            _x160 = g_s*m
            _x161 = _x160*math.sin(i_bottom_q_th)
            _x162 = _x142*_x161
            _x163 = _x160*math.sin(q_th_td)
            _x164 = _x142*_x163
            _x165 = (0.5)*i_t_bottom
            i_P_new1 = _x165*(_x162 + _x164)
            _pd__65 = _x165*(_x161 + _x163)
            _x166 = _x160*math.cos(i_bottom_q_th)
            _x167 = _x142*_x165
            _pd__66 = _x166*_x167
            _pd__67 = (0.5)*_x162 + (0.5)*_x164
            d_i_P_new1__q_r_td = (_d_i_L1__q_r_td*_pd__65 + _pd__66*d_i_bottom_q_th__q_r_td
                + _pd__67*d_i_t_bottom__q_r_td)
            d_i_P_new1__q_rd_td = (_d_i_L1__q_rd_td*_pd__65 + _pd__66*d_i_bottom_q_th__q_rd_td
                + _pd__67*d_i_t_bottom__q_rd_td)
            d_i_P_new1__q_th_td = (_d_i_L1__q_th_td*_pd__65 + _pd__66*d_i_bottom_q_th__q_th_td
                + _pd__67*d_i_t_bottom__q_th_td + _x160*_x167*math.cos(q_th_td))
            d_i_P_new1__q_thd_td = (_d_i_L1__q_thd_td*_pd__65 + _pd__66*d_i_bottom_q_th__q_thd_td
                + _pd__67*d_i_t_bottom__q_thd_td)
            d_i_P_new1__k_c = _d_i_L1__k_c*_pd__65 + _pd__66*d_i_bottom_q_th__k_c + _pd__67*d_i_t_bottom__k_c
            d_i_P_new1__k_d = _d_i_L1__k_d*_pd__65 + _pd__66*d_i_bottom_q_th__k_d + _pd__67*d_i_t_bottom__k_d
            _x168 = _x155*_x161
            _x169 = _x160*math.sin(i_liftoff_q_th)
            _x170 = _x155*_x169
            _x171 = -0.5*i_t_bottom + (0.5)*i_t_stance
            i_P_new2 = _x171*(_x168 + _x170)
            _pd__68 = _x171*(_x161 + _x169)
            _x172 = _x155*_x171
            _pd__69 = _x166*_x172
            _pd__70 = _x160*_x172*math.cos(i_liftoff_q_th)
            _x173 = (0.5)*_x168 + (0.5)*_x170
            _pd__71 = -_x173
            _pd__72 = _x173
            d_i_P_new2__q_r_td = (_d_i_L2__q_r_td*_pd__68 + _pd__69*d_i_bottom_q_th__q_r_td
                + _pd__70*d_i_liftoff_q_th__q_r_td + _pd__71*d_i_t_bottom__q_r_td
                + _pd__72*d_i_t_stance__q_r_td)
            d_i_P_new2__q_rd_td = (_d_i_L2__q_rd_td*_pd__68 + _pd__69*d_i_bottom_q_th__q_rd_td
                + _pd__70*d_i_liftoff_q_th__q_rd_td + _pd__71*d_i_t_bottom__q_rd_td
                + _pd__72*d_i_t_stance__q_rd_td)
            d_i_P_new2__q_th_td = (_d_i_L2__q_th_td*_pd__68 + _pd__69*d_i_bottom_q_th__q_th_td
                + _pd__70*d_i_liftoff_q_th__q_th_td + _pd__71*d_i_t_bottom__q_th_td
                + _pd__72*d_i_t_stance__q_th_td)
            d_i_P_new2__q_thd_td = (_d_i_L2__q_thd_td*_pd__68 + _pd__69*d_i_bottom_q_th__q_thd_td
                + _pd__70*d_i_liftoff_q_th__q_thd_td + _pd__71*d_i_t_bottom__q_thd_td
                + _pd__72*d_i_t_stance__q_thd_td)
            d_i_P_new2__k_c = (_d_i_L2__k_c*_pd__68 + _pd__69*d_i_bottom_q_th__k_c
                + _pd__70*d_i_liftoff_q_th__k_c + _pd__71*d_i_t_bottom__k_c + _pd__72*d_i_t_stance__k_c)
            d_i_P_new2__k_d = (_d_i_L2__k_d*_pd__68 + _pd__69*d_i_bottom_q_th__k_d
                + _pd__70*d_i_liftoff_q_th__k_d + _pd__71*d_i_t_bottom__k_d + _pd__72*d_i_t_stance__k_d)
        else:
            return fail(out, STATUS_INVALID_INPUT)
        # next values
        P_c_compression__next = i_P_new1
        P_c_decompression__next = i_P_new2
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (tol > 0.0 and (abs(P_c_compression__next - P_c_compression)
            <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + abs(p_td))) and (abs(P_c_decompression__next
            - P_c_decompression) <= tol*(math.sqrt(g_s)*(l0*math.sqrt(l0))*m + abs(p_td))))
        _pkn0 = (P_c_compression__next, P_c_decompression__next, d_i_P_new1__q_r_td, d_i_P_new1__q_rd_td,
            d_i_P_new1__q_th_td, d_i_P_new1__q_thd_td, d_i_P_new1__k_c, d_i_P_new1__k_d, d_i_P_new2__q_r_td,
            d_i_P_new2__q_rd_td, d_i_P_new2__q_th_td, d_i_P_new2__q_thd_td, d_i_P_new2__k_c, d_i_P_new2__k_d,
            )
        _pk0 = _pkn0
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
    # derivatives of the outputs
    d_t_bottom__q_r_td = d_i_t_bottom__q_r_td
    d_t_bottom__q_rd_td = d_i_t_bottom__q_rd_td
    d_t_bottom__q_th_td = d_i_t_bottom__q_th_td
    d_t_bottom__q_thd_td = d_i_t_bottom__q_thd_td
    d_t_bottom__k_c = d_i_t_bottom__k_c
    d_t_bottom__k_d = d_i_t_bottom__k_d
    d_t_stance__q_r_td = d_i_t_stance__q_r_td
    d_t_stance__q_rd_td = d_i_t_stance__q_rd_td
    d_t_stance__q_th_td = d_i_t_stance__q_th_td
    d_t_stance__q_thd_td = d_i_t_stance__q_thd_td
    d_t_stance__k_c = d_i_t_stance__k_c
    d_t_stance__k_d = d_i_t_stance__k_d
    d_bottom_q_r__q_r_td = d_i_bottom_q_r__q_r_td
    d_bottom_q_r__q_rd_td = d_i_bottom_q_r__q_rd_td
    d_bottom_q_r__q_th_td = d_i_bottom_q_r__q_th_td
    d_bottom_q_r__q_thd_td = d_i_bottom_q_r__q_thd_td
    d_bottom_q_r__k_c = d_i_bottom_q_r__k_c
    d_bottom_q_r__k_d = d_i_bottom_q_r__k_d
    d_bottom_q_th__q_r_td = d_i_bottom_q_th__q_r_td
    d_bottom_q_th__q_rd_td = d_i_bottom_q_th__q_rd_td
    d_bottom_q_th__q_th_td = d_i_bottom_q_th__q_th_td
    d_bottom_q_th__q_thd_td = d_i_bottom_q_th__q_thd_td
    d_bottom_q_th__k_c = d_i_bottom_q_th__k_c
    d_bottom_q_th__k_d = d_i_bottom_q_th__k_d
    d_bottom_q_thd__q_r_td = d_i_bottom_q_thd__q_r_td
    d_bottom_q_thd__q_rd_td = d_i_bottom_q_thd__q_rd_td
    d_bottom_q_thd__q_th_td = d_i_bottom_q_thd__q_th_td
    d_bottom_q_thd__q_thd_td = d_i_bottom_q_thd__q_thd_td
    d_bottom_q_thd__k_c = d_i_bottom_q_thd__k_c
    d_bottom_q_thd__k_d = d_i_bottom_q_thd__k_d
    d_liftoff_q_rd__q_r_td = d_i_liftoff_q_rd__q_r_td
    d_liftoff_q_rd__q_rd_td = d_i_liftoff_q_rd__q_rd_td
    d_liftoff_q_rd__q_th_td = d_i_liftoff_q_rd__q_th_td
    d_liftoff_q_rd__q_thd_td = d_i_liftoff_q_rd__q_thd_td
    d_liftoff_q_rd__k_c = d_i_liftoff_q_rd__k_c
    d_liftoff_q_rd__k_d = d_i_liftoff_q_rd__k_d
    d_liftoff_q_th__q_r_td = d_i_liftoff_q_th__q_r_td
    d_liftoff_q_th__q_rd_td = d_i_liftoff_q_th__q_rd_td
    d_liftoff_q_th__q_th_td = d_i_liftoff_q_th__q_th_td
    d_liftoff_q_th__q_thd_td = d_i_liftoff_q_th__q_thd_td
    d_liftoff_q_th__k_c = d_i_liftoff_q_th__k_c
    d_liftoff_q_th__k_d = d_i_liftoff_q_th__k_d
    d_liftoff_q_thd__q_r_td = d_i_liftoff_q_thd__q_r_td
    d_liftoff_q_thd__q_rd_td = d_i_liftoff_q_thd__q_rd_td
    d_liftoff_q_thd__q_th_td = d_i_liftoff_q_thd__q_th_td
    d_liftoff_q_thd__q_thd_td = d_i_liftoff_q_thd__q_thd_td
    d_liftoff_q_thd__k_c = d_i_liftoff_q_thd__k_c
    d_liftoff_q_thd__k_d = d_i_liftoff_q_thd__k_d
    # every output finite, or the inputs were far outside a physical range
    store(out, (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd, P_c_compression, P_c_decompression, passes,
        d_t_bottom__q_r_td, d_t_bottom__q_rd_td, d_t_bottom__q_th_td, d_t_bottom__q_thd_td, d_t_bottom__k_c,
        d_t_bottom__k_d, d_t_stance__q_r_td, d_t_stance__q_rd_td, d_t_stance__q_th_td, d_t_stance__q_thd_td,
        d_t_stance__k_c, d_t_stance__k_d, d_bottom_q_r__q_r_td, d_bottom_q_r__q_rd_td, d_bottom_q_r__q_th_td,
        d_bottom_q_r__q_thd_td, d_bottom_q_r__k_c, d_bottom_q_r__k_d, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        d_bottom_q_th__q_r_td, d_bottom_q_th__q_rd_td, d_bottom_q_th__q_th_td, d_bottom_q_th__q_thd_td,
        d_bottom_q_th__k_c, d_bottom_q_th__k_d, d_bottom_q_thd__q_r_td, d_bottom_q_thd__q_rd_td,
        d_bottom_q_thd__q_th_td, d_bottom_q_thd__q_thd_td, d_bottom_q_thd__k_c, d_bottom_q_thd__k_d, 0.0, 0.0,
        0.0, 0.0, 0.0, 0.0, d_liftoff_q_rd__q_r_td, d_liftoff_q_rd__q_rd_td, d_liftoff_q_rd__q_th_td,
        d_liftoff_q_rd__q_thd_td, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__q_r_td,
        d_liftoff_q_th__q_rd_td, d_liftoff_q_th__q_th_td, d_liftoff_q_th__q_thd_td, d_liftoff_q_th__k_c,
        d_liftoff_q_th__k_d, d_liftoff_q_thd__q_r_td, d_liftoff_q_thd__q_rd_td, d_liftoff_q_thd__q_th_td,
        d_liftoff_q_thd__q_thd_td, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_P_c_compression__q_r_td,
        d_P_c_compression__q_rd_td, d_P_c_compression__q_th_td, d_P_c_compression__q_thd_td,
        d_P_c_compression__k_c, d_P_c_compression__k_d, d_P_c_decompression__q_r_td,
        d_P_c_decompression__q_rd_td, d_P_c_decompression__q_th_td, d_P_c_decompression__q_thd_td,
        d_P_c_decompression__k_c, d_P_c_decompression__k_d, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_vs_stance_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_vs_stance_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_vs_stance_jacobian(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def geyer_vs_apex_return_jacobian(x, p, out):
    """Apex-return map by Simple variable-stiffness map (Geyer et al. per half), and its derivatives with
    respect to the apex, the touchdown angle and the stiffness.

    Report equations: 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 96, 97, 98, 99, 100,
    101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, continuity, gravity, iterations, tol); writes the outputs
    below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of :func:`geyer_vs.geyer_vs_apex_return`, in its order.

    Writes into out:
        <output>: each output of :func:`geyer_vs.geyer_vs_apex_return`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate, k_c, k_d (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 287
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
    # stance: Simple variable-stiffness map (Geyer et al. per half)
    _x1 = carray(stack(4), 4)
    store(_x1, (_o0_0, _o0_1, _o0_2, _o0_3,))
    _o1 = carray(stack(91), 91)
    _c1 = geyer_vs_stance_jacobian(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, _o1_10, _o1_11, _o1_12,
        _j_t_stance__q_rd_td, _j_t_stance__q_th_td, _j_t_stance__q_thd_td, _o1_23, _o1_24,
        _j_liftoff_q_rd__q_rd_td, _j_liftoff_q_rd__q_th_td, _j_liftoff_q_rd__q_thd_td, _j_liftoff_q_rd__k_c,
        _j_liftoff_q_rd__k_d, _j_liftoff_q_th__q_rd_td, _j_liftoff_q_th__q_th_td, _j_liftoff_q_th__q_thd_td,
        _j_liftoff_q_th__k_c, _j_liftoff_q_th__k_d, _j_liftoff_q_thd__q_rd_td, _j_liftoff_q_thd__q_th_td,
        _j_liftoff_q_thd__q_thd_td, _j_liftoff_q_thd__k_c, _j_liftoff_q_thd__k_d, _j_P_c_compression__q_rd_td,
        _j_P_c_compression__q_th_td, _j_P_c_compression__q_thd_td, _o1_77, _o1_78,
        _j_P_c_decompression__q_rd_td, _j_P_c_decompression__q_th_td, _j_P_c_decompression__q_thd_td, _o1_83,
        _o1_84,) = (load(_o1, 1, 6, 7, 8, 9, 10, 11, 12, 20, 21, 22, 23, 24, 56, 57, 58, 59, 60, 62, 63, 64,
        65, 66, 68, 69, 70, 71, 72, 74, 75, 76, 77, 78, 80, 81, 82, 83, 84))
    # chain rule through geyer_vs_stance
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
    d_P_c_compression__b_y_apex = (_j_P_c_compression__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_P_c_compression__q_th_td*_j_td_q_th__b_y_apex
        + _j_P_c_compression__q_thd_td*_j_td_q_thd__b_y_apex)
    d_P_c_compression__b_xd_apex = (_j_P_c_compression__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_P_c_compression__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_P_c_compression__q_th_td = (_j_P_c_compression__q_rd_td*_j_td_q_rd__q_th_td
        + _j_P_c_compression__q_th_td*_j_td_q_th__q_th_td + _j_P_c_compression__q_thd_td*_j_td_q_thd__q_th_td)
    d_P_c_compression__ground = (_j_P_c_compression__q_rd_td*_j_td_q_rd__ground
        + _j_P_c_compression__q_th_td*_j_td_q_th__ground + _j_P_c_compression__q_thd_td*_j_td_q_thd__ground)
    d_P_c_compression__retraction_rate = (_j_P_c_compression__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_P_c_compression__q_th_td*_j_td_q_th__retraction_rate
        + _j_P_c_compression__q_thd_td*_j_td_q_thd__retraction_rate)
    d_P_c_decompression__b_y_apex = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__b_y_apex
        + _j_P_c_decompression__q_th_td*_j_td_q_th__b_y_apex
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__b_y_apex)
    d_P_c_decompression__b_xd_apex = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__b_xd_apex
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__b_xd_apex)
    d_P_c_decompression__q_th_td = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__q_th_td
        + _j_P_c_decompression__q_th_td*_j_td_q_th__q_th_td
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__q_th_td)
    d_P_c_decompression__ground = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__ground
        + _j_P_c_decompression__q_th_td*_j_td_q_th__ground
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__ground)
    d_P_c_decompression__retraction_rate = (_j_P_c_decompression__q_rd_td*_j_td_q_rd__retraction_rate
        + _j_P_c_decompression__q_th_td*_j_td_q_th__retraction_rate
        + _j_P_c_decompression__q_thd_td*_j_td_q_thd__retraction_rate)
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
    d_apex_height__k_c = (_j_apex_height__q_rd*_j_liftoff_q_rd__k_c
        + _j_apex_height__q_th*_j_liftoff_q_th__k_c + _j_apex_height__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_height__k_d = (_j_apex_height__q_rd*_j_liftoff_q_rd__k_d
        + _j_apex_height__q_th*_j_liftoff_q_th__k_d + _j_apex_height__q_thd*_j_liftoff_q_thd__k_d)
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
    d_apex_speed__k_c = (_j_apex_speed__q_rd*_j_liftoff_q_rd__k_c + _j_apex_speed__q_th*_j_liftoff_q_th__k_c
        + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_c)
    d_apex_speed__k_d = (_j_apex_speed__q_rd*_j_liftoff_q_rd__k_d + _j_apex_speed__q_th*_j_liftoff_q_th__k_d
        + _j_apex_speed__q_thd*_j_liftoff_q_thd__k_d)
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
    d_t_ascent__k_c = (_j_liftoff_q_rd__k_c*_j_t_ascent__q_rd + _j_liftoff_q_th__k_c*_j_t_ascent__q_th
        + _j_liftoff_q_thd__k_c*_j_t_ascent__q_thd)
    d_t_ascent__k_d = (_j_liftoff_q_rd__k_d*_j_t_ascent__q_rd + _j_liftoff_q_th__k_d*_j_t_ascent__q_th
        + _j_liftoff_q_thd__k_d*_j_t_ascent__q_thd)
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
    d_next_apex_x__k_c = (_j_liftoff_q_rd__k_c*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_c*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_c*_j_next_apex_x__q_thd)
    d_next_apex_x__k_d = (_j_liftoff_q_rd__k_d*_j_next_apex_x__q_rd
        + _j_liftoff_q_th__k_d*_j_next_apex_x__q_th + _j_liftoff_q_thd__k_d*_j_next_apex_x__q_thd)
    # the step: apex to the foot, the foot to the next apex
    step_length = foot_x + next_apex_x
    d_step_length__b_y_apex = _j_foot_x__b_y_apex + d_next_apex_x__b_y_apex
    d_step_length__b_xd_apex = _j_foot_x__b_xd_apex + d_next_apex_x__b_xd_apex
    d_step_length__q_th_td = _j_foot_x__q_th_td + d_next_apex_x__q_th_td
    d_step_length__ground = _j_foot_x__ground + d_next_apex_x__ground
    d_step_length__retraction_rate = _j_foot_x__retraction_rate + d_next_apex_x__retraction_rate
    foot_y = -b_y_apex + ground
    # derivatives of the outputs
    d_liftoff_q_rd__k_c = _j_liftoff_q_rd__k_c
    d_liftoff_q_rd__k_d = _j_liftoff_q_rd__k_d
    d_liftoff_q_th__k_c = _j_liftoff_q_th__k_c
    d_liftoff_q_th__k_d = _j_liftoff_q_th__k_d
    d_liftoff_q_thd__k_c = _j_liftoff_q_thd__k_c
    d_liftoff_q_thd__k_d = _j_liftoff_q_thd__k_d
    d_step_length__k_c = d_next_apex_x__k_c
    d_step_length__k_d = d_next_apex_x__k_d
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
        step_length, foot_x, foot_y, _o0_2, _o1_10, _o1_11, _o1_12, d_apex_height__b_y_apex,
        d_apex_height__b_xd_apex, d_apex_height__q_th_td, d_apex_height__ground,
        d_apex_height__retraction_rate, d_apex_height__k_c, d_apex_height__k_d, d_apex_speed__b_y_apex,
        d_apex_speed__b_xd_apex, d_apex_speed__q_th_td, d_apex_speed__ground, d_apex_speed__retraction_rate,
        d_apex_speed__k_c, d_apex_speed__k_d, _o0_26, 0.0, _o0_28, _o0_29, _o0_30, 0.0, 0.0,
        d_t_stance__b_y_apex, d_t_stance__b_xd_apex, d_t_stance__q_th_td, d_t_stance__ground,
        d_t_stance__retraction_rate, _o1_23, _o1_24, d_t_ascent__b_y_apex, d_t_ascent__b_xd_apex,
        d_t_ascent__q_th_td, d_t_ascent__ground, d_t_ascent__retraction_rate, d_t_ascent__k_c,
        d_t_ascent__k_d, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, d_liftoff_q_rd__b_y_apex,
        d_liftoff_q_rd__b_xd_apex, d_liftoff_q_rd__q_th_td, d_liftoff_q_rd__ground,
        d_liftoff_q_rd__retraction_rate, d_liftoff_q_rd__k_c, d_liftoff_q_rd__k_d, d_liftoff_q_th__b_y_apex,
        d_liftoff_q_th__b_xd_apex, d_liftoff_q_th__q_th_td, d_liftoff_q_th__ground,
        d_liftoff_q_th__retraction_rate, d_liftoff_q_th__k_c, d_liftoff_q_th__k_d, d_liftoff_q_thd__b_y_apex,
        d_liftoff_q_thd__b_xd_apex, d_liftoff_q_thd__q_th_td, d_liftoff_q_thd__ground,
        d_liftoff_q_thd__retraction_rate, d_liftoff_q_thd__k_c, d_liftoff_q_thd__k_d, d_step_length__b_y_apex,
        d_step_length__b_xd_apex, d_step_length__q_th_td, d_step_length__ground,
        d_step_length__retraction_rate, d_step_length__k_c, d_step_length__k_d, d_foot_x__b_y_apex,
        d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__retraction_rate, 0.0, 0.0, -1.0,
        0.0, 0.0, 1.0, 0.0, 0.0, 0.0, d_touchdown_q_th__b_y_apex, 0.0, d_touchdown_q_th__q_th_td,
        d_touchdown_q_th__ground, d_touchdown_q_th__retraction_rate, 0.0, 0.0, d_P_c_compression__b_y_apex,
        d_P_c_compression__b_xd_apex, d_P_c_compression__q_th_td, d_P_c_compression__ground,
        d_P_c_compression__retraction_rate, _o1_77, _o1_78, d_P_c_decompression__b_y_apex,
        d_P_c_decompression__b_xd_apex, d_P_c_decompression__q_th_td, d_P_c_decompression__ground,
        d_P_c_decompression__retraction_rate, _o1_83, _o1_84, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,))
    if not finite(out):
        return fail(out, STATUS_NUMERICAL_RANGE)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_vs_apex_return_jacobian_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_vs_apex_return_jacobian` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i]
    -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_vs_apex_return_jacobian(row(X, i), p, row(OUT, i))
