# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/exact.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   exact_stance.py sha256:ffbd69c8753c546e
#   flight.py sha256:af908ea30b1fc141
# ----------------------------------------------------------------------------------------------
"""Exact stance by numerical integration (DOP853) (report section 2.2): stance, state-at-time and apex-return
kernels."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .exact_stance import stance, state_at
from .flight import apex_to_touchdown, liftoff_to_apex

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan


@njit(cache=True, error_model="numpy")
def exact_stance(x, p, out):
    """Exact stance by numerical integration (DOP853): touchdown state -> bottom and liftoff states.

    Report equations: 1, 2, 3, 27.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, rtol, atol, liftoff); writes the outputs below into
    out, in order, and returns
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
        rtol: option rtol: relative tolerance of the DOP853 integration in [1e-14, 0.001]
        atol: option atol: absolute tolerance of the DOP853 integration in [1e-16, 0.001]
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length

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
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff,) = load(p, 0, 1, 2, 3, 4, 8, 7, 9, 10, 11)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol,
            liftoff,)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0))
            & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0)) & ((q_r_lo <= l0)
            and (q_r_lo > 0.0)) & ((rtol >= 1e-14) and (rtol <= 0.001)) & ((atol >= 1e-16) and (atol
            <= 0.001)) & ((liftoff == 0.0) or (liftoff == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the exact stance (exact_stance)
    _c0 = stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff)
    if _c0[10] != STATUS_OK:
        return fail(out, _c0[10])
    t_bottom = _c0[0]
    t_stance = _c0[1]
    bottom_q_r = _c0[2]
    bottom_q_rd = _c0[3]
    bottom_q_th = _c0[4]
    bottom_q_thd = _c0[5]
    liftoff_q_r = _c0[6]
    liftoff_q_rd = _c0[7]
    liftoff_q_th = _c0[8]
    liftoff_q_thd = _c0[9]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
            liftoff_q_rd, liftoff_q_th, liftoff_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_bottom, t_stance, bottom_q_r, bottom_q_rd, bottom_q_th, bottom_q_thd, liftoff_q_r,
        liftoff_q_rd, liftoff_q_th, liftoff_q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def exact_stance_rows(X, P, OUT, STATUS):
    """Rows of :func:`exact_stance` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = exact_stance(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def exact_state_at(x, p, out):
    """Exact stance by numerical integration (DOP853): the polar state a time t after touchdown.

    Report equations: 1, 2, 3, 27.

    Role kernel: reads x = (t, q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, rtol, atol, liftoff); writes the outputs below into
    out, in order, and returns
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
        rtol: option rtol: relative tolerance of the DOP853 integration in [1e-14, 0.001]
        atol: option atol: absolute tolerance of the DOP853 integration in [1e-16, 0.001]
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length

    Writes into out:
        q_r: leg length [m]
        q_rd: leg length rate [m/s]
        q_th: leg angle from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (t, q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff,) = load(p, 0, 1, 2, 3, 4, 8, 7, 9, 10, 11)
    # inputs: finite and inside their domains
    if not (all_finite((t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol,
            liftoff,)) & ((t >= 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi))
            & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0))
            & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((rtol >= 1e-14) and (rtol <= 0.001)) & ((atol >= 1e-16)
            and (atol <= 0.001)) & ((liftoff == 0.0) or (liftoff == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the exact state at t (exact_stance)
    _c0 = (state_at(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol,
        liftoff))
    if _c0[4] != STATUS_OK:
        return fail(out, _c0[4])
    q_r = _c0[0]
    q_rd = _c0[1]
    q_th = _c0[2]
    q_thd = _c0[3]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((q_r, q_rd, q_th, q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (q_r, q_rd, q_th, q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def exact_state_at_rows(X, P, OUT, STATUS):
    """Rows of :func:`exact_state_at` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = exact_state_at(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def exact_apex_return(x, p, out):
    """Apex-return map: exact flights, stance by Exact stance by numerical integration (DOP853).

    Report equations: 1, 2, 3, 27.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate) and the parameter record
    p = (m, l0, k_c, k_d, g_s, g_f, q_r_td, q_r_lo, c, rtol, atol, liftoff); writes the outputs below into
    out, in order, and returns
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
        rtol: option rtol: relative tolerance of the DOP853 integration in [1e-14, 0.001]
        atol: option atol: absolute tolerance of the DOP853 integration in [1e-16, 0.001]
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length

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
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 3
    (b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4)
    (m, l0, k_c, k_d, g_s, c, g_f, q_r_td, q_r_lo, rtol, atol, liftoff,) = (load(p, 0, 1, 2, 3, 4, 8, 5, 6, 7,
        9, 10, 11))
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, ground, retraction_rate, m, l0, k_c, k_d, g_s, c, g_f,
            q_r_td, q_r_lo, rtol, atol, liftoff,)) & ((b_y_apex >= 0.0)) & ((abs(q_th_td) < (0.5)*math.pi))
            & ((m > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((k_d > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0))
            & ((g_f > 0.0)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0))
            & ((rtol >= 1e-14) and (rtol <= 0.001)) & ((atol >= 1e-16) and (atol <= 0.001)) & ((liftoff
            == 0.0) or (liftoff == 1.0))):
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
    # stance: Exact stance by numerical integration (DOP853)
    _x1 = carray(stack(4), 4)
    store(_x1, (td_q_r, td_q_rd, td_q_th, td_q_thd,))
    _o1 = carray(stack(10), 10)
    _c1 = exact_stance(_x1, p, _o1)
    if _c1 != STATUS_OK:
        return fail(out, _c1)
    (_o1_1, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,) = load(_o1, 1, 6, 7, 8, 9)
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
            liftoff_q_th, liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (apex_height, apex_speed, t_descent, _o1_1, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd, step_length, foot_x, foot_y, touchdown_q_th,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def exact_apex_return_rows(X, P, OUT, STATUS):
    """Rows of :func:`exact_apex_return` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(12), 12)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = exact_apex_return(row(X, i), p, row(OUT, i))
