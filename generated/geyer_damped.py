# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/geyer_damped.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight.py sha256:af908ea30b1fc141
# ----------------------------------------------------------------------------------------------
"""Geyer et al.'s map with leg damping (damped radial oscillator per half) (report section 3.1): stance,
state-at-time and apex-return kernels."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import apex_to_touchdown, liftoff_to_apex

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NO_LIFTOFF,
    STATUS_FALL, STATUS_RECOMPRESSION, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED, STATUS_OVERDAMPED)

NAN = math.nan
_NAN5 = (NAN,) * 5


@njit(cache=True, error_model="numpy")
def damped_liftoff(a, omega_D, A_c, B_s, delta, m, l0, k_d, q_r_lo, liftoff):
    """Liftoff of the damped decompression half: the first zero of the leg force (or of q_r - q_r_lo) after
    the bottom, safeguarded Halley.

    Arguments:
        a: offset a of the decompression half's rho(t)
        omega_D: its damped frequency omega_D [rad/s]
        A_c: its amplitude A of exp(-delta t) cos(omega_D t)
        B_s: its amplitude B of exp(-delta t) sin(omega_D t)
        delta: decay rate delta = c / (2 m) [1/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length

    Returns a tuple:
        tau: liftoff time after the bottom [s]
        cos_t: cos(omega_D tau)
        sin_t: sin(omega_D tau)
        exp_t: exp(-delta tau)
        by_force: 1: the leg force's zero, 0: q_r = q_r_lo
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 238
    # liftoff lies in (0, pi / omega_D) after the bottom, where rho increases
    _x0 = math.pi/omega_D
    _half = _x0
    _decay_quarter = math.exp(-0.5*_x0*delta)
    # the k_d spring extends the leg at the bottom
    if not ((A_c < 0.0)):
        return _NAN5 + (STATUS_RECOMPRESSION,)
    # the bottom lies below the liftoff
    if not ((A_c + a + ((2.0*delta*m*(-A_c*delta + B_s*omega_D)/k_d) if (liftoff == 0.0) and (q_r_lo/l0
            >= -2.0*delta*m*(-A_c*delta + B_s*omega_D)/k_d + 1.0) else (1.0 - q_r_lo/l0)) < 0.0)):
        return _NAN5 + (STATUS_NO_LIFTOFF,)
    # the leg reaches liftoff within half a damped period
    if not ((-A_c*_decay_quarter**2 + a + ((2.0*delta*m*(A_c*_decay_quarter**2*delta
            - B_s*_decay_quarter**2*omega_D)/k_d) if (liftoff == 0.0) and (q_r_lo/l0
            >= -2.0*delta*m*(A_c*_decay_quarter**2*delta - B_s*_decay_quarter**2*omega_D)/k_d + 1.0) else (1.0
            - q_r_lo/l0)) > 0.0)):
        return _NAN5 + (STATUS_NO_LIFTOFF,)
    # the form of the condition the first iterate solves
    _x1 = (liftoff == 0.0) and (l0 <= q_r_lo) and (delta > 0.0)
    _x2 = 2.0*m/k_d
    _x3 = _x2*delta*omega_D
    _x4 = _x2*delta**2
    _form_c = ((a) if _x1 else (a + 1.0 - q_r_lo/l0))
    _form_p = ((-A_c*_x4 + A_c + B_s*_x3) if _x1 else (A_c))
    _form_q = ((-A_c*_x3 - B_s*_x4 + B_s) if _x1 else (B_s))
    # the root with the decay frozen at a quarter period (the root itself at c = 0)
    _x5 = _form_c/(_decay_quarter*math.sqrt(_form_p**2 + _form_q**2))
    _first = ((math.acos(((-1.0) if (_x5 < -1.0) else (1.0) if (_x5 > 1.0) else (_x5)))
        + _form_q/_form_p)/omega_D)
    # the first iterate, inside the bracket
    _x6 = min(_half, max(0.0, _first))
    _x7 = _x6*omega_D
    _tau0 = _x6
    _cos0 = math.cos(_x7)
    _sin0 = math.sin(_x7)
    _exp0 = math.exp(-_x6*delta)
    # Halley's method on g, safeguarded by bisection on its bracket
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (_tau0, 0.0, 0.0, _half, _cos0, _sin0, _exp0, )
    _pk0 = _pki0
    _passes = 0.0
    _conv0 = False
    _last0 = max(int(60.0), 0)
    for _it0 in range(_last0 + 1):
        (tau, _bisections, _lo, _hi, cos_t, sin_t, exp_t, ) = _pk0
        if _it0 == _last0 and not _conv0 and 1e-06 > 0.0 and _passes > 0.0:
            return _NAN5 + (STATUS_NOT_CONVERGED,)
        if _conv0 or _it0 == _last0:
            break
        # g and its derivatives at the iterate
        _x8 = cos_t*exp_t
        _x9 = A_c*_x8
        _x10 = exp_t*sin_t
        _x11 = B_s*_x10
        _x12 = A_c*_x10*omega_D
        _x13 = -B_s*cos_t*exp_t*omega_D + _x11*delta + _x12 + _x9*delta
        _x14 = 2.0*delta
        _x15 = _x14*m/k_d
        _x16 = -_x13*_x15
        _x17 = q_r_lo/l0
        _x18 = (liftoff == 0.0) and (_x17 >= 1.0 - _x16)
        _x19 = delta**2
        _x20 = B_s*_x8
        _x21 = omega_D**2
        _x22 = _x11*_x19 - _x11*_x21 + _x12*_x14 - _x14*_x20*omega_D + _x19*_x9 - _x21*_x9
        _x23 = delta**3
        _x24 = omega_D**3
        _g = _x11 + _x9 + a + ((_x16) if _x18 else (1.0 - _x17))
        _dg = -_x13 + ((_x15*_x22) if _x18 else (0.0))
        _ddg = (_x22 + ((_x15*(3.0*A_c*_x21*cos_t*delta*exp_t + A_c*_x24*exp_t*sin_t
            + 3.0*B_s*_x19*cos_t*exp_t*omega_D + 3.0*B_s*_x21*delta*exp_t*sin_t - _x11*_x23 - 3.0*_x12*_x19
            - _x20*_x24 - _x23*_x9)) if _x18 else (0.0)))
        # the bracket and Halley's step
        _x25 = (_g < 0.0)
        _lo_next = ((tau) if _x25 else (_lo))
        _hi_next = ((_hi) if _x25 else (tau))
        _halley = -2.0*_dg*_g/(-_ddg*_g + 2.0*_dg**2) + tau
        # Halley's step where it is safe, else bisection (counted: the loop stops on Halley steps only)
        _x26 = (_halley >= _lo_next) and (_halley <= _hi_next) and (_dg > 0.0)
        _x27 = ((0.0) if _x26 else (1.0))
        _bisect = _x27
        _tau_next = ((_halley) if _x26 else ((0.5)*_hi_next + (0.5)*_lo_next))
        _bisections_next = _bisections + _x27
        # the step in omega_D t and in -delta t
        _x28 = _tau_next - tau
        _du = _x28*omega_D
        _dv = -_x28*delta
        # cos, sin, exp at the next iterate: Taylor steps when it is close
        _x29 = -0.001388888888888889*_du**6 + (0.041666666666666664)*_du**4 - 0.5*_du**2 + 1.0
        _x30 = (-0.0001984126984126984*_du**7 + (0.008333333333333333)*_du**5 - 0.16666666666666666*_du**3
            + _du)
        _x31 = (abs(_du) <= 0.01) and (abs(_dv) <= 0.01)
        _x32 = _tau_next*omega_D
        _cos_next = ((_x29*cos_t - _x30*sin_t) if _x31 else (math.cos(_x32)))
        _sin_next = ((_x29*sin_t + _x30*cos_t) if _x31 else (math.sin(_x32)))
        _exp_next = ((exp_t*((0.0001984126984126984)*_dv**7 + (0.001388888888888889)*_dv**6
            + (0.008333333333333333)*_dv**5 + (0.041666666666666664)*_dv**4 + (0.16666666666666666)*_dv**3
            + (0.5)*_dv**2 + _dv + 1.0)) if _x31 else (math.exp(-_tau_next*delta)))
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = (1e-06 > 0.0 and (abs(_tau_next - tau) <= 1e-06*(_half)) and (abs(_bisections_next
            - _bisections) <= 1e-06*(1.0)))
        _pkn0 = (_tau_next, _bisections_next, _lo_next, _hi_next, _cos_next, _sin_next, _exp_next, )
        _pk0 = _pkn0
        _passes += 1.0
    # 1 where the leg force decides liftoff, 0 where q_r = q_r_lo does
    _x33 = exp_t*sin_t
    by_force = ((1.0) if (liftoff == 0.0) and (q_r_lo/l0 >= -2.0*delta*m*(-A_c*_x33*omega_D
        - A_c*cos_t*delta*exp_t - B_s*_x33*delta + B_s*cos_t*exp_t*omega_D)/k_d + 1.0) else (0.0))
    # (internal helper: its callers check that their outputs are finite)
    return (tau, cos_t, sin_t, exp_t, by_force, STATUS_OK)


@njit(cache=True, error_model="numpy")
def geyer_damped_stance(x, p, out):
    """Geyer et al.'s map with leg damping (damped radial oscillator per half): touchdown state -> bottom and
    liftoff states.

    Report equations: 4, 7, 17, 18, 19, 48, 65, 76.

    Not in the report: (4) with the damper -c q_rd, linearised to rho'' + 2 delta rho' +
    omega_n^2 rho = omega^2 - g_s / l0 (delta = c / (2 m), omega_n^2 = k / m + 3 omega^2),
    solved from the touchdown state with k_c and from the bottom with k_d; the bottom in closed
    form; the leg angle (18)-(19) integrated over the damped rho; liftoff where the leg force or
    q_r - q_r_lo reaches 0 (option liftoff), by Halley's method safeguarded by bisection; option
    gravity adds a virtual gravity effect of section 4 (types 0-4) on each half.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, liftoff, gravity, iterations, tol); writes the outputs
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
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length
        gravity: option gravity: virtual gravity effect on p_th per half (report section 4 on [t_td, t_b] and
            [t_b, t_lo], as geyer-vs's types 3-4): (48) from the torque at each half's two ends with the
            type's leg length; each half runs with its mean momentum, the rates with the momentum at that
            instant: 0 = none, 1 = type0, 2 = type1, 3 = type2, 4 = type3, 5 = type4
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
    # Total ops: 341
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, k_d, g_s, c, q_r_lo, liftoff, gravity, iterations, tol,) = (load(p, 0, 1, 2, 3, 4, 8, 7, 9,
        10, 11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, liftoff, gravity,
            iterations, tol,)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m
            > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0)) & ((q_r_lo
            <= l0) and (q_r_lo > 0.0)) & ((liftoff == 0.0) or (liftoff == 1.0)) & ((gravity == 0.0)
            or (gravity == 1.0) or (gravity == 2.0) or (gravity == 3.0) or (gravity == 4.0) or (gravity
            == 5.0)) & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations
            <= 1000.0)) & ((tol >= 0.0) and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the touchdown angular momentum; delta = c / (2 m)
    p_td = m*q_r_td**2*q_thd_td
    delta = (0.5)*c/m
    # stance starts compressing
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
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
        # eq (7): omega of the first half, from its mean momentum
        i_omega_c = ((0.5)*P_c_compression + p_td)/(l0**2*m)
        # the damped radial solution of the c half
        _x0 = i_omega_c**2
        _x1 = (1.0/l0)
        _x2 = 3.0*_x0 + k_c/m
        _x3 = (_x0 - _x1*g_s)/_x2
        _x4 = _x2 - delta**2
        _x5 = math.sqrt(_x4)
        _x6 = _x1*q_r_td - _x3 - 1.0
        i_c_a = _x3
        i_c_omega_D2 = _x4
        i_c_omega_D = _x5
        i_c_A_c = _x6
        i_c_B_s = (_x1*q_rd_td + _x6*delta)/_x5
        # omega_D^2 = omega_n^2 - delta^2 > 0 (an underdamped leg)
        if not ((i_c_omega_D2 > 0.0)):
            return fail(out, STATUS_OVERDAMPED)
        # the bottom (rho' = 0) in closed form; (19)'s angle, (17)'s rate
        _x7 = delta*i_c_A_c
        _x8 = -_x7 + i_c_B_s*i_c_omega_D
        _x20 = (1.0/_x8)
        _x9 = -delta*i_c_B_s - i_c_A_c*i_c_omega_D
        _x10 = _x20*_x9
        _x11 = (1.0/math.sqrt(_x20**2*_x9**2 + 1.0))
        _x12 = (math.atan(_x10) + (0.5)*math.pi)/i_c_omega_D
        _x13 = _x10*_x11
        _x14 = math.exp(-_x12*delta)
        _x15 = _x11*_x14*i_c_B_s - _x13*_x14*i_c_A_c + i_c_a + 1.0
        _x16 = _x11*delta
        _x17 = _x11*i_c_omega_D
        _x18 = P_c_compression + p_td
        _x19 = 1.0/(l0**2*m)
        i__P = _x8
        i__R = _x9
        i__r = _x10
        i__s = _x11
        i_t_bottom = _x12
        i_cos_b = -_x13
        i_sin_b = _x11
        i_exp_b = _x14
        i_bottom_q_r = _x15*l0
        i_bottom_q_rd = 0.0
        i_bottom_q_th = (i_omega_c*(_x12*(1.0 - 2.0*i_c_a) + (2.0*_x14*(i_c_A_c*(-_x10*_x16 - _x17)
            + i_c_B_s*(-_x10*_x17 + _x16)) - 2.0*_x7 - 2.0*i_c_B_s*i_c_omega_D)/(delta**2 + i_c_omega_D**2))
            + q_th_td)
        i_p_b = _x18
        i_bottom_q_thd = _x18*_x19/_x15**2
        i_omega_d = _x19*((0.5)*P_c_decompression + _x18)
        # the leg collapses: bottom leg length q_r_b > 0
        if not ((i_bottom_q_r > 0.0)):
            return fail(out, STATUS_FALL)
        # the damped radial solution of the d half
        _x21 = i_omega_d**2
        _x22 = (1.0/l0)
        _x23 = 3.0*_x21 + k_d/m
        _x24 = (_x21 - _x22*g_s)/_x23
        _x25 = _x23 - delta**2
        _x26 = math.sqrt(_x25)
        _x27 = _x22*i_bottom_q_r - _x24 - 1.0
        i_d_a = _x24
        i_d_omega_D2 = _x25
        i_d_omega_D = _x26
        i_d_A_c = _x27
        i_d_B_s = _x27*delta/_x26
        # omega_D^2 = omega_n^2 - delta^2 > 0 (an underdamped leg)
        if not ((i_d_omega_D2 > 0.0)):
            return fail(out, STATUS_OVERDAMPED)
        # liftoff: the leg force's zero (or q_r = q_r_lo) after the bottom
        _c0 = damped_liftoff(i_d_a, i_d_omega_D, i_d_A_c, i_d_B_s, delta, m, l0, k_d, q_r_lo, liftoff)
        if _c0[5] != STATUS_OK:
            return fail(out, _c0[5])
        i_tau = _c0[0]
        i_cos_t = _c0[1]
        i_sin_t = _c0[2]
        i_exp_t = _c0[3]
        i_by_force = _c0[4]
        # the liftoff state: the damped solution at the root, (19)'s angle, (17)'s rate
        _x28 = delta*i_cos_t
        _x29 = i_d_A_c*i_exp_t
        _x30 = delta*i_sin_t
        _x31 = i_d_omega_D*i_sin_t
        _x32 = -_x28*_x29 - _x29*_x31 - _x30*i_d_B_s*i_exp_t + i_cos_t*i_d_B_s*i_d_omega_D*i_exp_t
        _x33 = 2.0*delta
        _x34 = -_x32*_x33*m/k_d + 1.0
        _x35 = (i_by_force == 1.0)
        i_t_stance = i_t_bottom + i_tau
        i_liftoff_q_r = ((_x34*l0) if _x35 else (q_r_lo))
        i_liftoff_q_rd = _x32*l0
        i_liftoff_q_th = (i_bottom_q_th + i_omega_d*(i_tau*(1.0 - 2.0*i_d_a) + (-_x33*i_d_A_c
            - 2.0*i_d_B_s*i_d_omega_D + 2.0*i_exp_t*(i_d_A_c*(_x28 - _x31) + i_d_B_s*(_x30
            + i_cos_t*i_d_omega_D)))/(delta**2 + i_d_omega_D**2)))
        i_liftoff_q_thd = (P_c_decompression + i_p_b)*((1.0/(_x34**2*l0**2)) if _x35 else (q_r_lo**-2))/m
        # the leg stays above horizontal
        if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
            return fail(out, STATUS_FALL)
        if _conv0 or _it0 == _last0:
            break
        # the virtual gravity effect of each half
        if gravity == 0.0:
            i_P_new1 = 0.0
            i_P_new2 = 0.0
        elif gravity == 1.0:
            # eq (48) on each half at l0, as (49)
            _x36 = g_s*l0*m
            _x37 = _x36*math.sin(i_bottom_q_th)
            i_P_new1 = (0.5)*i_t_bottom*(_x36*math.sin(q_th_td) + _x37)
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x36*math.sin(i_liftoff_q_th) + _x37)
        elif gravity == 2.0:
            # eq (48) on each half at (l0 + q_r_b)/2, as (52)
            _x38 = g_s*m*((0.5)*i_bottom_q_r + (0.5)*l0)
            _x39 = _x38*math.sin(i_bottom_q_th)
            i_P_new1 = (0.5)*i_t_bottom*(_x38*math.sin(q_th_td) + _x39)
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x38*math.sin(i_liftoff_q_th) + _x39)
        elif gravity == 3.0:
            # eq (48) on each half at the stance-average leg length of the damped rho(t), as (62)
            _x40 = delta**2
            _x41 = (l0*(i_c_a + 1.0 + (i_c_A_c*(delta + i_exp_b*(-delta*i_cos_b + i_c_omega_D*i_sin_b))
                + i_c_B_s*(i_c_omega_D - i_exp_b*(delta*i_sin_b + i_c_omega_D*i_cos_b)))/(i_t_bottom*(_x40
                + i_c_omega_D**2))))
            _x42 = (l0*(i_d_a + 1.0 + (i_d_A_c*(delta + i_exp_t*(-delta*i_cos_t + i_d_omega_D*i_sin_t))
                + i_d_B_s*(i_d_omega_D - i_exp_t*(delta*i_sin_t + i_cos_t*i_d_omega_D)))/(i_tau*(_x40
                + i_d_omega_D**2))))
            _x43 = -i_t_bottom + i_t_stance
            _x44 = (_x41*i_t_bottom + _x42*_x43)/i_t_stance
            _x45 = _x44*g_s*m
            _x46 = _x45*math.sin(i_bottom_q_th)
            _i_L1 = _x41
            _i_L2 = _x42
            _i_L = _x44
            i_P_new1 = (0.5)*i_t_bottom*(_x45*math.sin(q_th_td) + _x46)
            i_P_new2 = (0.5)*_x43*(_x45*math.sin(i_liftoff_q_th) + _x46)
        elif gravity == 4.0:
            # eq (65) on each half
            _x47 = g_s*m
            _x48 = _x47*i_bottom_q_r*math.sin(i_bottom_q_th)
            i_P_new1 = (0.5)*i_t_bottom*(_x47*q_r_td*math.sin(q_th_td) + _x48)
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x47*i_liftoff_q_r*math.sin(i_liftoff_q_th) + _x48)
        elif gravity == 5.0:
            # eq (76) on each half, the average leg length of the damped rho(t) on it
            _x49 = delta**2
            _x50 = (l0*(i_c_a + 1.0 + (i_c_A_c*(delta + i_exp_b*(-delta*i_cos_b + i_c_omega_D*i_sin_b))
                + i_c_B_s*(i_c_omega_D - i_exp_b*(delta*i_sin_b + i_c_omega_D*i_cos_b)))/(i_t_bottom*(_x49
                + i_c_omega_D**2))))
            _x51 = (l0*(i_d_a + 1.0 + (i_d_A_c*(delta + i_exp_t*(-delta*i_cos_t + i_d_omega_D*i_sin_t))
                + i_d_B_s*(i_d_omega_D - i_exp_t*(delta*i_sin_t + i_cos_t*i_d_omega_D)))/(i_tau*(_x49
                + i_d_omega_D**2))))
            _x52 = math.sin(i_bottom_q_th)
            _x53 = g_s*m
            _x54 = _x50*_x53
            _x55 = _x51*_x53
            _i_L1 = _x50
            _i_L2 = _x51
            i_P_new1 = (0.5)*i_t_bottom*(_x52*_x54 + _x54*math.sin(q_th_td))
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x52*_x55 + _x55*math.sin(i_liftoff_q_th))
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
def geyer_damped_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_damped_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_damped_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def geyer_damped_state_at(x, p, out):
    """Geyer et al.'s map with leg damping (damped radial oscillator per half): the polar state a time t after
    touchdown.

    Report equations: 4, 7, 17, 18, 19, 48, 65, 76.

    Role kernel: reads x = (t, q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, liftoff, gravity, iterations, tol); writes the outputs
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
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length
        gravity: option gravity: virtual gravity effect on p_th per half (report section 4 on [t_td, t_b] and
            [t_b, t_lo], as geyer-vs's types 3-4): (48) from the torque at each half's two ends with the
            type's leg length; each half runs with its mean momentum, the rates with the momentum at that
            instant: 0 = none, 1 = type0, 2 = type1, 3 = type2, 4 = type3, 5 = type4
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
    # Total ops: 463
    (t, q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k_c, k_d, g_s, c, q_r_lo, liftoff, gravity, iterations, tol,) = (load(p, 0, 1, 2, 3, 4, 8, 7, 9,
        10, 11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, liftoff,
            gravity, iterations, tol,)) & ((t >= 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((c >= 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((liftoff == 0.0) or (liftoff == 1.0))
            & ((gravity == 0.0) or (gravity == 1.0) or (gravity == 2.0) or (gravity == 3.0) or (gravity
            == 4.0) or (gravity == 5.0)) & ((iterations == math.floor(iterations)) and (iterations >= 0.0)
            and (iterations <= 1000.0)) & ((tol >= 0.0) and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the touchdown angular momentum; delta = c / (2 m)
    p_td = m*q_r_td**2*q_thd_td
    delta = (0.5)*c/m
    # stance starts compressing
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
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
        # eq (7): omega of the first half, from its mean momentum
        i_omega_c = ((0.5)*P_c_compression + p_td)/(l0**2*m)
        # the damped radial solution of the c half
        _x0 = i_omega_c**2
        _x1 = (1.0/l0)
        _x2 = 3.0*_x0 + k_c/m
        _x3 = (_x0 - _x1*g_s)/_x2
        _x4 = _x2 - delta**2
        _x5 = math.sqrt(_x4)
        _x6 = _x1*q_r_td - _x3 - 1.0
        i_c_a = _x3
        i_c_omega_D2 = _x4
        i_c_omega_D = _x5
        i_c_A_c = _x6
        i_c_B_s = (_x1*q_rd_td + _x6*delta)/_x5
        # omega_D^2 = omega_n^2 - delta^2 > 0 (an underdamped leg)
        if not ((i_c_omega_D2 > 0.0)):
            return fail(out, STATUS_OVERDAMPED)
        # the bottom (rho' = 0) in closed form; (19)'s angle, (17)'s rate
        _x7 = delta*i_c_A_c
        _x8 = -_x7 + i_c_B_s*i_c_omega_D
        _x20 = (1.0/_x8)
        _x9 = -delta*i_c_B_s - i_c_A_c*i_c_omega_D
        _x10 = _x20*_x9
        _x11 = (1.0/math.sqrt(_x20**2*_x9**2 + 1.0))
        _x12 = (math.atan(_x10) + (0.5)*math.pi)/i_c_omega_D
        _x13 = _x10*_x11
        _x14 = math.exp(-_x12*delta)
        _x15 = _x11*_x14*i_c_B_s - _x13*_x14*i_c_A_c + i_c_a + 1.0
        _x16 = _x11*delta
        _x17 = _x11*i_c_omega_D
        _x18 = P_c_compression + p_td
        _x19 = 1.0/(l0**2*m)
        i__P = _x8
        i__R = _x9
        i__r = _x10
        i__s = _x11
        i_t_bottom = _x12
        i_cos_b = -_x13
        i_sin_b = _x11
        i_exp_b = _x14
        i_bottom_q_r = _x15*l0
        i_bottom_q_rd = 0.0
        i_bottom_q_th = (i_omega_c*(_x12*(1.0 - 2.0*i_c_a) + (2.0*_x14*(i_c_A_c*(-_x10*_x16 - _x17)
            + i_c_B_s*(-_x10*_x17 + _x16)) - 2.0*_x7 - 2.0*i_c_B_s*i_c_omega_D)/(delta**2 + i_c_omega_D**2))
            + q_th_td)
        i_p_b = _x18
        i_bottom_q_thd = _x18*_x19/_x15**2
        i_omega_d = _x19*((0.5)*P_c_decompression + _x18)
        # the leg collapses: bottom leg length q_r_b > 0
        if not ((i_bottom_q_r > 0.0)):
            return fail(out, STATUS_FALL)
        # the damped radial solution of the d half
        _x21 = i_omega_d**2
        _x22 = (1.0/l0)
        _x23 = 3.0*_x21 + k_d/m
        _x24 = (_x21 - _x22*g_s)/_x23
        _x25 = _x23 - delta**2
        _x26 = math.sqrt(_x25)
        _x27 = _x22*i_bottom_q_r - _x24 - 1.0
        i_d_a = _x24
        i_d_omega_D2 = _x25
        i_d_omega_D = _x26
        i_d_A_c = _x27
        i_d_B_s = _x27*delta/_x26
        # omega_D^2 = omega_n^2 - delta^2 > 0 (an underdamped leg)
        if not ((i_d_omega_D2 > 0.0)):
            return fail(out, STATUS_OVERDAMPED)
        # liftoff: the leg force's zero (or q_r = q_r_lo) after the bottom
        _c0 = damped_liftoff(i_d_a, i_d_omega_D, i_d_A_c, i_d_B_s, delta, m, l0, k_d, q_r_lo, liftoff)
        if _c0[5] != STATUS_OK:
            return fail(out, _c0[5])
        i_tau = _c0[0]
        i_cos_t = _c0[1]
        i_sin_t = _c0[2]
        i_exp_t = _c0[3]
        i_by_force = _c0[4]
        # the liftoff state: the damped solution at the root, (19)'s angle, (17)'s rate
        _x28 = delta*i_cos_t
        _x29 = i_d_A_c*i_exp_t
        _x30 = delta*i_sin_t
        _x31 = i_d_omega_D*i_sin_t
        _x32 = -_x28*_x29 - _x29*_x31 - _x30*i_d_B_s*i_exp_t + i_cos_t*i_d_B_s*i_d_omega_D*i_exp_t
        _x33 = 2.0*delta
        _x34 = -_x32*_x33*m/k_d + 1.0
        _x35 = (i_by_force == 1.0)
        i_t_stance = i_t_bottom + i_tau
        i_liftoff_q_r = ((_x34*l0) if _x35 else (q_r_lo))
        i_liftoff_q_rd = _x32*l0
        i_liftoff_q_th = (i_bottom_q_th + i_omega_d*(i_tau*(1.0 - 2.0*i_d_a) + (-_x33*i_d_A_c
            - 2.0*i_d_B_s*i_d_omega_D + 2.0*i_exp_t*(i_d_A_c*(_x28 - _x31) + i_d_B_s*(_x30
            + i_cos_t*i_d_omega_D)))/(delta**2 + i_d_omega_D**2)))
        i_liftoff_q_thd = (P_c_decompression + i_p_b)*((1.0/(_x34**2*l0**2)) if _x35 else (q_r_lo**-2))/m
        # the leg stays above horizontal
        if not ((abs(i_liftoff_q_th) < (0.5)*math.pi)):
            return fail(out, STATUS_FALL)
        if _conv0 or _it0 == _last0:
            break
        # the virtual gravity effect of each half
        if gravity == 0.0:
            i_P_new1 = 0.0
            i_P_new2 = 0.0
        elif gravity == 1.0:
            # eq (48) on each half at l0, as (49)
            _x36 = g_s*l0*m
            _x37 = _x36*math.sin(i_bottom_q_th)
            i_P_new1 = (0.5)*i_t_bottom*(_x36*math.sin(q_th_td) + _x37)
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x36*math.sin(i_liftoff_q_th) + _x37)
        elif gravity == 2.0:
            # eq (48) on each half at (l0 + q_r_b)/2, as (52)
            _x38 = g_s*m*((0.5)*i_bottom_q_r + (0.5)*l0)
            _x39 = _x38*math.sin(i_bottom_q_th)
            i_P_new1 = (0.5)*i_t_bottom*(_x38*math.sin(q_th_td) + _x39)
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x38*math.sin(i_liftoff_q_th) + _x39)
        elif gravity == 3.0:
            # eq (48) on each half at the stance-average leg length of the damped rho(t), as (62)
            _x40 = delta**2
            _x41 = (l0*(i_c_a + 1.0 + (i_c_A_c*(delta + i_exp_b*(-delta*i_cos_b + i_c_omega_D*i_sin_b))
                + i_c_B_s*(i_c_omega_D - i_exp_b*(delta*i_sin_b + i_c_omega_D*i_cos_b)))/(i_t_bottom*(_x40
                + i_c_omega_D**2))))
            _x42 = (l0*(i_d_a + 1.0 + (i_d_A_c*(delta + i_exp_t*(-delta*i_cos_t + i_d_omega_D*i_sin_t))
                + i_d_B_s*(i_d_omega_D - i_exp_t*(delta*i_sin_t + i_cos_t*i_d_omega_D)))/(i_tau*(_x40
                + i_d_omega_D**2))))
            _x43 = -i_t_bottom + i_t_stance
            _x44 = (_x41*i_t_bottom + _x42*_x43)/i_t_stance
            _x45 = _x44*g_s*m
            _x46 = _x45*math.sin(i_bottom_q_th)
            _i_L1 = _x41
            _i_L2 = _x42
            _i_L = _x44
            i_P_new1 = (0.5)*i_t_bottom*(_x45*math.sin(q_th_td) + _x46)
            i_P_new2 = (0.5)*_x43*(_x45*math.sin(i_liftoff_q_th) + _x46)
        elif gravity == 4.0:
            # eq (65) on each half
            _x47 = g_s*m
            _x48 = _x47*i_bottom_q_r*math.sin(i_bottom_q_th)
            i_P_new1 = (0.5)*i_t_bottom*(_x47*q_r_td*math.sin(q_th_td) + _x48)
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x47*i_liftoff_q_r*math.sin(i_liftoff_q_th) + _x48)
        elif gravity == 5.0:
            # eq (76) on each half, the average leg length of the damped rho(t) on it
            _x49 = delta**2
            _x50 = (l0*(i_c_a + 1.0 + (i_c_A_c*(delta + i_exp_b*(-delta*i_cos_b + i_c_omega_D*i_sin_b))
                + i_c_B_s*(i_c_omega_D - i_exp_b*(delta*i_sin_b + i_c_omega_D*i_cos_b)))/(i_t_bottom*(_x49
                + i_c_omega_D**2))))
            _x51 = (l0*(i_d_a + 1.0 + (i_d_A_c*(delta + i_exp_t*(-delta*i_cos_t + i_d_omega_D*i_sin_t))
                + i_d_B_s*(i_d_omega_D - i_exp_t*(delta*i_sin_t + i_cos_t*i_d_omega_D)))/(i_tau*(_x49
                + i_d_omega_D**2))))
            _x52 = math.sin(i_bottom_q_th)
            _x53 = g_s*m
            _x54 = _x50*_x53
            _x55 = _x51*_x53
            _i_L1 = _x50
            _i_L2 = _x51
            i_P_new1 = (0.5)*i_t_bottom*(_x52*_x54 + _x54*math.sin(q_th_td))
            i_P_new2 = (0.5)*(-i_t_bottom + i_t_stance)*(_x52*_x55 + _x55*math.sin(i_liftoff_q_th))
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
    # the damped solution of the half that holds t; the rate with the momentum at t
    _x56 = i_c_omega_D*t
    _x57 = math.cos(_x56)
    _x58 = math.exp(-delta*t)
    _x59 = _x58*i_c_A_c
    _x60 = math.sin(_x56)
    _x61 = _x58*i_c_B_s
    _x62 = _x57*_x59 + _x60*_x61 + i_c_a + 1.0
    _x63 = (i_t_bottom > t)
    _x64 = -i_t_bottom + t
    _x65 = _x64*i_d_omega_D
    _x66 = math.cos(_x65)
    _x67 = math.exp(-_x64*delta)
    _x68 = _x67*i_d_A_c
    _x69 = math.sin(_x65)
    _x70 = _x67*i_d_B_s
    _x71 = _x66*_x68 + _x69*_x70 + i_d_a + 1.0
    _x72 = _x57*delta
    _x73 = _x60*delta
    _x74 = _x60*i_c_omega_D
    _x75 = _x66*delta
    _x76 = _x69*delta
    _x77 = _x69*i_d_omega_D
    _x78 = delta**2
    _x79 = 2.0*delta
    _x80 = l0**-2
    q_r = ((_x62*l0) if _x63 else (_x71*l0))
    q_rd = ((l0*(_x57*_x58*i_c_B_s*i_c_omega_D - _x59*_x72 - _x59*_x74 - _x61*_x73)) if _x63
        else (l0*(_x66*_x67*i_d_B_s*i_d_omega_D - _x68*_x75 - _x68*_x77 - _x70*_x76)))
    q_th = ((i_omega_c*(t*(1.0 - 2.0*i_c_a) + (2.0*_x58*(i_c_A_c*(_x72 - _x74) + i_c_B_s*(_x57*i_c_omega_D
        + _x73)) - _x79*i_c_A_c - 2.0*i_c_B_s*i_c_omega_D)/(_x78 + i_c_omega_D**2)) + q_th_td) if _x63
        else (i_bottom_q_th + i_omega_d*(_x64*(1.0 - 2.0*i_d_a) + (2.0*_x67*(i_d_A_c*(_x75 - _x77)
        + i_d_B_s*(_x66*i_d_omega_D + _x76)) - _x79*i_d_A_c - 2.0*i_d_B_s*i_d_omega_D)/(_x78
        + i_d_omega_D**2))))
    q_thd = (((_x80/_x62**2) if _x63 else (_x80/_x71**2))*((P_c_compression*t/i_t_bottom + p_td) if _x63
        else (P_c_decompression*_x64/(-i_t_bottom + i_t_stance) + i_p_b))/m)
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((q_r, q_rd, q_th, q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (q_r, q_rd, q_th, q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def geyer_damped_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_damped_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_damped_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def geyer_damped_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Geyer et al.'s map with leg damping (damped radial oscillator
    per half).

    Report equations: 4, 7, 17, 18, 19, 48, 65, 76.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, liftoff, gravity, iterations, tol); writes the outputs
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
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length
        gravity: option gravity: virtual gravity effect on p_th per half (report section 4 on [t_td, t_b] and
            [t_b, t_lo], as geyer-vs's types 3-4): (48) from the torque at each half's two ends with the
            type's leg length; each half runs with its mean momentum, the rates with the momentum at that
            instant: 0 = none, 1 = type0, 2 = type1, 3 = type2, 4 = type3, 5 = type4
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
    (m, l0, k_c, k_d, g_s, c, g_f, q_r_td, q_r_lo, liftoff, gravity, iterations, tol,) = (load(p, 0, 1, 2, 3,
        4, 8, 5, 6, 7, 9, 10, 11, 12))
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k_c, k_d, g_s, c, g_f,
            q_r_td, q_r_lo, liftoff, gravity, iterations, tol,)) & ((b_y_apex >= 0.0)) & ((abs(q_th_td)
            < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0))
            & ((c >= 0.0)) & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo
            > 0.0)) & ((liftoff == 0.0) or (liftoff == 1.0)) & ((gravity == 0.0) or (gravity == 1.0)
            or (gravity == 2.0) or (gravity == 3.0) or (gravity == 4.0) or (gravity == 5.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 1000.0)) & ((tol >= 0.0)
            and (tol <= 1.0))):
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
    # stance: Geyer et al.'s map with leg damping (damped radial oscillator per half)
    _x1 = carray(stack(4), 4)
    store(_x1, (td_q_r, td_q_rd, td_q_th, td_q_thd,))
    _o1 = carray(stack(13), 13)
    _c1 = geyer_damped_stance(_x1, p, _o1)
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
def geyer_damped_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`geyer_damped_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(13), 13)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = geyer_damped_apex_return(row(X, i), p, row(OUT, i))
