# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/model/flight.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module flight: JVP kernels, and for a map
its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_APEX_TOO_LOW, STATUS_LIFTOFF_DOWNWARD,
    STATUS_LIFTOFF_BACKWARD, STATUS_NOT_CONVERGED, STATUS_NO_TOUCHDOWN)

NAN = math.nan


@njit(cache=True, error_model="numpy")
def apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate_0(_pd__0, d_t0__q_th_td, g_f,
        q_r_td, q_th_td, retraction_rate, t0, out):
    """Branch swinging = 0 of apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate
    (outlined: derive/outline.py).

    Arguments: the caller's variables of the same names.

    Writes into out:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 22
    # t0 with its first-order term in the rate (its derivative; the rate is 0 here, so the values are t0 and
    # q_th_td's, as Newton's method from t0 gives bit for bit); no pass; the touchdown angle's sine and
    # cosine: those of q_th_td
    t_td = t0
    d_t_td__q_th_td = d_t0__q_th_td
    _x0 = math.sin(q_th_td)
    d_t_td__retraction_rate = _x0*q_r_td/g_f
    t_start = t0
    t_far = t0
    foot_slope = -g_f*t0
    _x1 = _pd__0*g_f
    d_foot_slope__b_y_apex = -_x1
    d_foot_slope__q_th_td = -d_t0__q_th_td*g_f
    d_foot_slope__ground = _x1
    touchdown_angle = q_th_td
    d_touchdown_angle__retraction_rate = t0
    sin_td = _x0
    _pd__1 = 0.0
    _x2 = _pd__0*_pd__1
    d_sin_td__b_y_apex = _x2
    _x3 = math.cos(q_th_td)
    d_sin_td__q_th_td = _pd__1*d_t0__q_th_td + _x3
    d_sin_td__ground = -_x2
    d_sin_td__retraction_rate = _x3*t0
    cos_td = _x3
    _pd__2 = 0.0
    _x4 = _pd__0*_pd__2
    d_cos_td__b_y_apex = _x4
    d_cos_td__q_th_td = _pd__2*d_t0__q_th_td - _x0
    d_cos_td__ground = -_x4
    d_cos_td__retraction_rate = -_x0*t0
    # tangents as every branch names them
    _x5 = -_pd__0
    d_t_far__q_th_td = d_t0__q_th_td
    d_t_start__b_y_apex = _pd__0
    d_t_start__q_th_td = d_t0__q_th_td
    d_t_start__ground = _x5
    d_t_td__b_y_apex = _pd__0
    d_t_td__ground = _x5
    # (internal helper: its callers check that their outputs are finite)
    store(out, (t_td, d_t_td__q_th_td, d_t_td__retraction_rate, touchdown_angle, 0.0, 1.0, 0.0,
        d_touchdown_angle__retraction_rate, sin_td, d_sin_td__b_y_apex, d_sin_td__q_th_td, d_sin_td__ground,
        d_sin_td__retraction_rate, cos_td, d_cos_td__b_y_apex, d_cos_td__q_th_td, d_cos_td__ground,
        d_cos_td__retraction_rate, d_t_td__b_y_apex, d_t_td__ground,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate_1(_pd__0, d_drop__q_th_td,
        d_t0__q_th_td, drop, g_f, q_r_td, q_th_td, retraction_rate, t0, out):
    """Branch swinging = 1 of apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate
    (outlined: derive/outline.py).

    Arguments: the caller's variables of the same names.

    Writes into out:
        the names every branch defines: in the order the caller binds them
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 133
    # a start at or after the touchdown: t0 if the foot is on or below the ground then, else the time the body
    # is q_r_td below the ground
    _x0 = (1.0/math.sqrt(g_f))
    _x1 = 2.0*q_r_td
    _x2 = math.cos(q_th_td)
    _x3 = math.sqrt(_x1*_x2 + _x1 + 2.0*drop)
    _x4 = _x0*_x3
    t_far = _x4
    _x5 = _x0/_x3
    _pd__3 = _x5
    d_t_far__q_th_td = _pd__3*d_drop__q_th_td - _x5*q_r_td*math.sin(q_th_td)
    _x6 = (q_r_td*(_x2 - math.cos(q_th_td + retraction_rate*t0)) <= 0.0)
    t_start = ((t0) if _x6 else (_x4))
    _pd__4 = ((1.0) if _x6 else (0.0))
    _pd__5 = ((0.0) if _x6 else (1.0))
    _x7 = _pd__0*_pd__4 + _pd__3*_pd__5
    d_t_start__b_y_apex = _x7
    d_t_start__q_th_td = _pd__4*d_t0__q_th_td + _pd__5*d_t_far__q_th_td
    d_t_start__ground = -_x7
    # Newton's method on the foot's height (concave: monotone from the right)
    # the loop's variables in one tuple, unpacked at the top of every pass, the final one
    # included (its values are visible after the loop)
    _pki0 = (t_start, d_t_start__b_y_apex, d_t_start__q_th_td, d_t_start__ground, 0.0, )
    _pk0 = _pki0
    touchdown_passes = 0.0
    _conv0 = False
    _last0 = max(int(50.0), 0)
    for _it0 in range(_last0 + 1):
        (t_td, d_t_td__b_y_apex, d_t_td__q_th_td, d_t_td__ground, d_t_td__retraction_rate, ) = _pk0
        if _it0 == _last0 and not _conv0 and 1e-12 > 0.0 and touchdown_passes > 0.0:
            return fail(out, STATUS_NOT_CONVERGED)
        _x8 = (0.5)*g_f
        _x9 = retraction_rate*t_td
        _x10 = _x9 + q_th_td
        _x11 = q_r_td*math.sin(_x10)
        foot_slope = _x11*retraction_rate + _x8*(t0 - t_td) - _x8*(t0 + t_td)
        _x12 = math.cos(_x10)
        _pd__6 = _x12*q_r_td*retraction_rate**2 - g_f
        d_foot_slope__b_y_apex = _pd__6*d_t_td__b_y_apex
        _x13 = _x12*q_r_td
        d_foot_slope__q_th_td = _pd__6*d_t_td__q_th_td + _x13*retraction_rate
        d_foot_slope__ground = _pd__6*d_t_td__ground
        d_foot_slope__retraction_rate = _pd__6*d_t_td__retraction_rate + _x11 + _x13*_x9
        # the foot descends toward the ground
        if not ((foot_slope < 0.0)):
            return fail(out, STATUS_NO_TOUCHDOWN)
        if _conv0 or _it0 == _last0:
            break
        # next values
        _x14 = (1.0/foot_slope)
        _x15 = t0 - t_td
        _x16 = (0.5)*g_f
        _x17 = _x16*(t0 + t_td)
        _x18 = q_th_td + retraction_rate*t_td
        _x19 = _x15*_x17 + q_r_td*(-math.cos(_x18) + math.cos(q_th_td))
        t_td__next = -_x14*_x19 + t_td
        _pd__7 = _x14**2*_x19
        _x20 = _x15*_x16
        _pd__8 = -_x14*(_x17 + _x20)
        _x21 = math.sin(_x18)
        _x22 = _x21*q_r_td
        _pd__9 = -_x14*(-_x17 + _x20 + _x22*retraction_rate) + 1.0
        _x23 = _pd__0*_pd__8
        d_t_td__next__b_y_apex = _pd__7*d_foot_slope__b_y_apex + _pd__9*d_t_td__b_y_apex + _x23
        d_t_td__next__q_th_td = (_pd__7*d_foot_slope__q_th_td + _pd__8*d_t0__q_th_td + _pd__9*d_t_td__q_th_td
            - _x14*q_r_td*(_x21 - math.sin(q_th_td)))
        d_t_td__next__ground = _pd__7*d_foot_slope__ground + _pd__9*d_t_td__ground - _x23
        d_t_td__next__retraction_rate = (_pd__7*d_foot_slope__retraction_rate + _pd__9*d_t_td__retraction_rate
            - _x14*_x22*t_td)
        # converged when every variable moved by at most tol times its scale (NaN never converges;
        # tol = 0 runs every pass)
        _conv0 = 1e-12 > 0.0 and (abs(t_td__next - t_td) <= 1e-12*(t0))
        _pkn0 = (t_td__next, d_t_td__next__b_y_apex, d_t_td__next__q_th_td, d_t_td__next__ground,
            d_t_td__next__retraction_rate, )
        _pk0 = _pkn0
        touchdown_passes += 1.0
    # the leg angle at touchdown, its sine and cosine
    _x24 = q_th_td + retraction_rate*t_td
    touchdown_angle = _x24
    d_touchdown_angle__b_y_apex = d_t_td__b_y_apex*retraction_rate
    d_touchdown_angle__q_th_td = d_t_td__q_th_td*retraction_rate + 1.0
    d_touchdown_angle__ground = d_t_td__ground*retraction_rate
    d_touchdown_angle__retraction_rate = d_t_td__retraction_rate*retraction_rate + t_td
    _x25 = math.sin(_x24)
    sin_td = _x25
    _x26 = math.cos(_x24)
    _pd__10 = _x26
    d_sin_td__b_y_apex = _pd__10*d_touchdown_angle__b_y_apex
    d_sin_td__q_th_td = _pd__10*d_touchdown_angle__q_th_td
    d_sin_td__ground = _pd__10*d_touchdown_angle__ground
    d_sin_td__retraction_rate = _pd__10*d_touchdown_angle__retraction_rate
    cos_td = _x26
    _pd__11 = -_x25
    d_cos_td__b_y_apex = _pd__11*d_touchdown_angle__b_y_apex
    d_cos_td__q_th_td = _pd__11*d_touchdown_angle__q_th_td
    d_cos_td__ground = _pd__11*d_touchdown_angle__ground
    d_cos_td__retraction_rate = _pd__11*d_touchdown_angle__retraction_rate
    # (internal helper: its callers check that their outputs are finite)
    store(out, (t_td, d_t_td__q_th_td, d_t_td__retraction_rate, touchdown_angle, d_touchdown_angle__b_y_apex,
        d_touchdown_angle__q_th_td, d_touchdown_angle__ground, d_touchdown_angle__retraction_rate, sin_td,
        d_sin_td__b_y_apex, d_sin_td__q_th_td, d_sin_td__ground, d_sin_td__retraction_rate, cos_td,
        d_cos_td__b_y_apex, d_cos_td__q_th_td, d_cos_td__ground, d_cos_td__retraction_rate, d_t_td__b_y_apex,
        d_t_td__ground,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate(b_y_apex, b_xd_apex, q_th_td,
        q_r_td, g_f, ground, retraction_rate, out):
    """Ballistic descent from an apex to touchdown with the leg at q_r_td swinging from q_th_td at
    retraction_rate, and the derivatives of its outputs with respect to b_y_apex, b_xd_apex, q_th_td, ground,
    retraction_rate.

    Report equations: sec2.1-touchdown, sec2.2.2.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`flight.apex_to_touchdown`, in its order.

    Writes into out:
        <output>: each output of :func:`flight.apex_to_touchdown`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td, ground, retraction_rate (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 95
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, retraction_rate,)) & ((b_y_apex
            >= 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((q_r_td > 0.0)) & ((g_f > 0.0))):
        return fail(out, STATUS_INVALID_INPUT)
    drop = b_y_apex - ground - q_r_td*math.cos(q_th_td)
    d_drop__q_th_td = q_r_td*math.sin(q_th_td)
    # the foot above the touchdown ground at the apex
    if not ((drop > 0.0)):
        return fail(out, STATUS_APEX_TOO_LOW)
    # the descent time of a leg held still (section 2.1)
    _x0 = math.sqrt(drop)
    _x1 = math.sqrt(2.0)/math.sqrt(g_f)
    t0 = _x0*_x1
    _pd__0 = (0.5)*_x1/_x0
    d_t0__q_th_td = _pd__0*d_drop__q_th_td
    # |retraction_rate| <= sqrt(g_f/q_r_td): the foot's height concave in time
    if not ((q_r_td*retraction_rate**2 <= g_f)):
        return fail(out, STATUS_INVALID_INPUT)
    # 0: the leg held still (retraction_rate = 0), 1: a swinging leg
    swinging = ((0.0) if (retraction_rate == 0.0) else (1.0))
    # the touchdown time: closed form for a leg held still, else Newton's method
    if swinging == 0.0:
        # branch swinging = 0
        _o0 = carray(stack(20), 20)
        _c0 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate_0(_pd__0,
            d_t0__q_th_td, g_f, q_r_td, q_th_td, retraction_rate, t0, _o0))
        if _c0 != STATUS_OK:
            return fail(out, _c0)
        (t_td, d_t_td__q_th_td, d_t_td__retraction_rate, touchdown_angle, d_touchdown_angle__b_y_apex,
            d_touchdown_angle__q_th_td, d_touchdown_angle__ground, d_touchdown_angle__retraction_rate, sin_td,
            d_sin_td__b_y_apex, d_sin_td__q_th_td, d_sin_td__ground, d_sin_td__retraction_rate, cos_td,
            d_cos_td__b_y_apex, d_cos_td__q_th_td, d_cos_td__ground, d_cos_td__retraction_rate,
            d_t_td__b_y_apex, d_t_td__ground,) = (load(_o0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14,
            15, 16, 17, 18, 19))
    elif swinging == 1.0:
        # branch swinging = 1
        _o1 = carray(stack(20), 20)
        _c1 = (apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td_ground_retraction_rate_1(_pd__0,
            d_drop__q_th_td, d_t0__q_th_td, drop, g_f, q_r_td, q_th_td, retraction_rate, t0, _o1))
        if _c1 != STATUS_OK:
            return fail(out, _c1)
        (t_td, d_t_td__q_th_td, d_t_td__retraction_rate, touchdown_angle, d_touchdown_angle__b_y_apex,
            d_touchdown_angle__q_th_td, d_touchdown_angle__ground, d_touchdown_angle__retraction_rate, sin_td,
            d_sin_td__b_y_apex, d_sin_td__q_th_td, d_sin_td__ground, d_sin_td__retraction_rate, cos_td,
            d_cos_td__b_y_apex, d_cos_td__q_th_td, d_cos_td__ground, d_cos_td__retraction_rate,
            d_t_td__b_y_apex, d_t_td__ground,) = (load(_o1, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14,
            15, 16, 17, 18, 19))
    else:
        return fail(out, STATUS_INVALID_INPUT)
    # the leg above the horizontal
    if not ((abs(touchdown_angle) < (0.5)*math.pi)):
        return fail(out, STATUS_NO_TOUCHDOWN)
    # touchdown state from the derived Cartesian -> polar map
    touchdown_q_r = q_r_td
    _x2 = g_f*t_td
    touchdown_q_rd = -_x2*cos_td - b_xd_apex*sin_td
    _pd__12 = -_x2
    _pd__13 = -cos_td*g_f
    d_touchdown_q_rd__b_y_apex = (_pd__12*d_cos_td__b_y_apex + _pd__13*d_t_td__b_y_apex
        - b_xd_apex*d_sin_td__b_y_apex)
    d_touchdown_q_rd__q_th_td = (_pd__12*d_cos_td__q_th_td + _pd__13*d_t_td__q_th_td
        - b_xd_apex*d_sin_td__q_th_td)
    d_touchdown_q_rd__ground = _pd__12*d_cos_td__ground + _pd__13*d_t_td__ground - b_xd_apex*d_sin_td__ground
    d_touchdown_q_rd__retraction_rate = (_pd__12*d_cos_td__retraction_rate + _pd__13*d_t_td__retraction_rate
        - b_xd_apex*d_sin_td__retraction_rate)
    touchdown_q_th = touchdown_angle
    _x3 = (1.0/q_r_td)
    touchdown_q_thd = _x3*(-b_xd_apex*cos_td + g_f*sin_td*t_td)
    _pd__14 = -_x3*b_xd_apex
    _pd__15 = _x2*_x3
    _pd__16 = _x3*g_f*sin_td
    d_touchdown_q_thd__b_y_apex = (_pd__14*d_cos_td__b_y_apex + _pd__15*d_sin_td__b_y_apex
        + _pd__16*d_t_td__b_y_apex)
    d_touchdown_q_thd__b_xd_apex = -_x3*cos_td
    d_touchdown_q_thd__q_th_td = (_pd__14*d_cos_td__q_th_td + _pd__15*d_sin_td__q_th_td
        + _pd__16*d_t_td__q_th_td)
    d_touchdown_q_thd__ground = _pd__14*d_cos_td__ground + _pd__15*d_sin_td__ground + _pd__16*d_t_td__ground
    d_touchdown_q_thd__retraction_rate = (_pd__14*d_cos_td__retraction_rate
        + _pd__15*d_sin_td__retraction_rate + _pd__16*d_t_td__retraction_rate)
    t_flight = t_td
    foot_x = b_xd_apex*t_td + q_r_td*sin_td
    d_foot_x__b_y_apex = b_xd_apex*d_t_td__b_y_apex + d_sin_td__b_y_apex*q_r_td
    d_foot_x__q_th_td = b_xd_apex*d_t_td__q_th_td + d_sin_td__q_th_td*q_r_td
    d_foot_x__ground = b_xd_apex*d_t_td__ground + d_sin_td__ground*q_r_td
    d_foot_x__retraction_rate = b_xd_apex*d_t_td__retraction_rate + d_sin_td__retraction_rate*q_r_td
    # derivatives of the outputs
    d_touchdown_q_rd__b_xd_apex = -sin_td
    d_touchdown_q_th__b_y_apex = d_touchdown_angle__b_y_apex
    d_touchdown_q_th__q_th_td = d_touchdown_angle__q_th_td
    d_touchdown_q_th__ground = d_touchdown_angle__ground
    d_touchdown_q_th__retraction_rate = d_touchdown_angle__retraction_rate
    d_t_flight__b_y_apex = d_t_td__b_y_apex
    d_t_flight__q_th_td = d_t_td__q_th_td
    d_t_flight__ground = d_t_td__ground
    d_t_flight__retraction_rate = d_t_td__retraction_rate
    d_foot_x__b_xd_apex = t_td
    # (internal helper: its callers check that their outputs are finite)
    store(out, (touchdown_q_r, touchdown_q_rd, touchdown_q_th, touchdown_q_thd, t_flight, foot_x, 0.0, 0.0,
        0.0, 0.0, 0.0, d_touchdown_q_rd__b_y_apex, d_touchdown_q_rd__b_xd_apex, d_touchdown_q_rd__q_th_td,
        d_touchdown_q_rd__ground, d_touchdown_q_rd__retraction_rate, d_touchdown_q_th__b_y_apex, 0.0,
        d_touchdown_q_th__q_th_td, d_touchdown_q_th__ground, d_touchdown_q_th__retraction_rate,
        d_touchdown_q_thd__b_y_apex, d_touchdown_q_thd__b_xd_apex, d_touchdown_q_thd__q_th_td,
        d_touchdown_q_thd__ground, d_touchdown_q_thd__retraction_rate, d_t_flight__b_y_apex, 0.0,
        d_t_flight__q_th_td, d_t_flight__ground, d_t_flight__retraction_rate, d_foot_x__b_y_apex,
        d_foot_x__b_xd_apex, d_foot_x__q_th_td, d_foot_x__ground, d_foot_x__retraction_rate,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def liftoff_to_apex_jac_q_rd_q_th_q_thd(q_r, q_rd, q_th, q_thd, g_f, direction, out):
    """Ballistic ascent from a polar liftoff state to the next apex, and the derivatives of its outputs with
    respect to q_rd, q_th, q_thd.

    Report equations: sec2.1-apex, sec2.2.2.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`flight.liftoff_to_apex`, in its order.

    Writes into out:
        <output>: each output of :func:`flight.liftoff_to_apex`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_rd, q_th, q_thd
            (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 50
    # inputs: finite and inside their domains
    if not (all_finite((q_r, q_rd, q_th, q_thd, g_f, direction,)) & ((q_r > 0.0)) & ((g_f > 0.0))
            & ((direction == -1.0) or (direction == 0.0) or (direction == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # Cartesian liftoff state relative to the toe
    _x0 = math.sin(q_th)
    _x1 = _x0*q_r
    _x2 = -_x1
    b_x = _x2
    _x3 = math.cos(q_th)
    _x4 = _x3*q_r
    _x5 = -_x4
    d_b_x__q_th = _x5
    _x6 = -_x0*q_rd - _x4*q_thd
    b_xd = _x6
    d_b_xd__q_rd = -_x0
    _x7 = _x1*q_thd - _x3*q_rd
    d_b_xd__q_th = _x7
    d_b_xd__q_thd = _x5
    b_y = _x4
    d_b_y__q_th = _x2
    b_yd = -_x7
    d_b_yd__q_rd = _x3
    d_b_yd__q_th = _x6
    d_b_yd__q_thd = _x2
    # liftoff requires an upward velocity
    if not ((b_yd > 0.0)):
        return fail(out, STATUS_LIFTOFF_DOWNWARD)
    # the body must not move against the step's direction (a hop in place: either way)
    if not ((b_xd*direction >= -1e-09*math.sqrt(g_f*q_r))):
        return fail(out, STATUS_LIFTOFF_BACKWARD)
    # apex where b_yd(t) = 0
    _x8 = (1.0/g_f)
    apex_b_y = (0.5)*_x8*b_yd**2 + b_y
    _x9 = _x8*b_yd
    _pd__0 = _x9
    d_apex_b_y__q_rd = _pd__0*d_b_yd__q_rd
    d_apex_b_y__q_th = _pd__0*d_b_yd__q_th + d_b_y__q_th
    d_apex_b_y__q_thd = _pd__0*d_b_yd__q_thd
    apex_b_xd = b_xd
    t_flight = _x9
    _pd__1 = _x8
    d_t_flight__q_rd = _pd__1*d_b_yd__q_rd
    d_t_flight__q_th = _pd__1*d_b_yd__q_th
    d_t_flight__q_thd = _pd__1*d_b_yd__q_thd
    _x10 = _x9*b_xd
    dx_flight = _x10
    _pd__2 = _x9
    _x11 = _x8*b_xd
    _pd__3 = _x11
    d_dx_flight__q_rd = _pd__2*d_b_xd__q_rd + _pd__3*d_b_yd__q_rd
    d_dx_flight__q_th = _pd__2*d_b_xd__q_th + _pd__3*d_b_yd__q_th
    d_dx_flight__q_thd = _pd__2*d_b_xd__q_thd + _pd__3*d_b_yd__q_thd
    apex_b_x = _x10 + b_x
    _pd__4 = _x9
    _pd__5 = _x11
    d_apex_b_x__q_rd = _pd__4*d_b_xd__q_rd + _pd__5*d_b_yd__q_rd
    d_apex_b_x__q_th = _pd__4*d_b_xd__q_th + _pd__5*d_b_yd__q_th + d_b_x__q_th
    d_apex_b_x__q_thd = _pd__4*d_b_xd__q_thd + _pd__5*d_b_yd__q_thd
    # derivatives of the outputs
    d_apex_b_xd__q_rd = d_b_xd__q_rd
    d_apex_b_xd__q_th = d_b_xd__q_th
    d_apex_b_xd__q_thd = d_b_xd__q_thd
    # (internal helper: its callers check that their outputs are finite)
    store(out, (apex_b_y, apex_b_xd, t_flight, dx_flight, apex_b_x, d_apex_b_y__q_rd, d_apex_b_y__q_th,
        d_apex_b_y__q_thd, d_apex_b_xd__q_rd, d_apex_b_xd__q_th, d_apex_b_xd__q_thd, d_t_flight__q_rd,
        d_t_flight__q_th, d_t_flight__q_thd, d_dx_flight__q_rd, d_dx_flight__q_th, d_dx_flight__q_thd,
        d_apex_b_x__q_rd, d_apex_b_x__q_th, d_apex_b_x__q_thd,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def liftoff_to_apex_jac_q_r_q_rd_q_th_q_thd(q_r, q_rd, q_th, q_thd, g_f, direction, out):
    """Ballistic ascent from a polar liftoff state to the next apex, and the derivatives of its outputs with
    respect to q_r, q_rd, q_th, q_thd.

    Report equations: sec2.1-apex, sec2.2.2.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments: those of :func:`flight.liftoff_to_apex`, in its order.

    Writes into out:
        <output>: each output of :func:`flight.liftoff_to_apex`, in its order
        d_<output>__<argument>: d output / d argument for each output above and argument q_r, q_rd, q_th,
            q_thd (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 64
    # inputs: finite and inside their domains
    if not (all_finite((q_r, q_rd, q_th, q_thd, g_f, direction,)) & ((q_r > 0.0)) & ((g_f > 0.0))
            & ((direction == -1.0) or (direction == 0.0) or (direction == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # Cartesian liftoff state relative to the toe
    _x0 = math.sin(q_th)
    _x1 = _x0*q_r
    _x2 = -_x1
    b_x = _x2
    _x3 = -_x0
    d_b_x__q_r = _x3
    _x4 = math.cos(q_th)
    _x5 = _x4*q_r
    _x6 = -_x5
    d_b_x__q_th = _x6
    _x7 = -_x0*q_rd - _x5*q_thd
    b_xd = _x7
    d_b_xd__q_r = -_x4*q_thd
    d_b_xd__q_rd = _x3
    _x8 = _x1*q_thd - _x4*q_rd
    d_b_xd__q_th = _x8
    d_b_xd__q_thd = _x6
    b_y = _x5
    d_b_y__q_r = _x4
    d_b_y__q_th = _x2
    b_yd = -_x8
    d_b_yd__q_r = -_x0*q_thd
    d_b_yd__q_rd = _x4
    d_b_yd__q_th = _x7
    d_b_yd__q_thd = _x2
    # liftoff requires an upward velocity
    if not ((b_yd > 0.0)):
        return fail(out, STATUS_LIFTOFF_DOWNWARD)
    # the body must not move against the step's direction (a hop in place: either way)
    if not ((b_xd*direction >= -1e-09*math.sqrt(g_f*q_r))):
        return fail(out, STATUS_LIFTOFF_BACKWARD)
    # apex where b_yd(t) = 0
    _x9 = (1.0/g_f)
    apex_b_y = (0.5)*_x9*b_yd**2 + b_y
    _x10 = _x9*b_yd
    _pd__0 = _x10
    d_apex_b_y__q_r = _pd__0*d_b_yd__q_r + d_b_y__q_r
    d_apex_b_y__q_rd = _pd__0*d_b_yd__q_rd
    d_apex_b_y__q_th = _pd__0*d_b_yd__q_th + d_b_y__q_th
    d_apex_b_y__q_thd = _pd__0*d_b_yd__q_thd
    apex_b_xd = b_xd
    t_flight = _x10
    _pd__1 = _x9
    d_t_flight__q_r = _pd__1*d_b_yd__q_r
    d_t_flight__q_rd = _pd__1*d_b_yd__q_rd
    d_t_flight__q_th = _pd__1*d_b_yd__q_th
    d_t_flight__q_thd = _pd__1*d_b_yd__q_thd
    _x11 = _x10*b_xd
    dx_flight = _x11
    _pd__2 = _x10
    _x12 = _x9*b_xd
    _pd__3 = _x12
    d_dx_flight__q_r = _pd__2*d_b_xd__q_r + _pd__3*d_b_yd__q_r
    d_dx_flight__q_rd = _pd__2*d_b_xd__q_rd + _pd__3*d_b_yd__q_rd
    d_dx_flight__q_th = _pd__2*d_b_xd__q_th + _pd__3*d_b_yd__q_th
    d_dx_flight__q_thd = _pd__2*d_b_xd__q_thd + _pd__3*d_b_yd__q_thd
    apex_b_x = _x11 + b_x
    _pd__4 = _x10
    _pd__5 = _x12
    d_apex_b_x__q_r = _pd__4*d_b_xd__q_r + _pd__5*d_b_yd__q_r + d_b_x__q_r
    d_apex_b_x__q_rd = _pd__4*d_b_xd__q_rd + _pd__5*d_b_yd__q_rd
    d_apex_b_x__q_th = _pd__4*d_b_xd__q_th + _pd__5*d_b_yd__q_th + d_b_x__q_th
    d_apex_b_x__q_thd = _pd__4*d_b_xd__q_thd + _pd__5*d_b_yd__q_thd
    # derivatives of the outputs
    d_apex_b_xd__q_r = d_b_xd__q_r
    d_apex_b_xd__q_rd = d_b_xd__q_rd
    d_apex_b_xd__q_th = d_b_xd__q_th
    d_apex_b_xd__q_thd = d_b_xd__q_thd
    # (internal helper: its callers check that their outputs are finite)
    store(out, (apex_b_y, apex_b_xd, t_flight, dx_flight, apex_b_x, d_apex_b_y__q_r, d_apex_b_y__q_rd,
        d_apex_b_y__q_th, d_apex_b_y__q_thd, d_apex_b_xd__q_r, d_apex_b_xd__q_rd, d_apex_b_xd__q_th,
        d_apex_b_xd__q_thd, d_t_flight__q_r, d_t_flight__q_rd, d_t_flight__q_th, d_t_flight__q_thd,
        d_dx_flight__q_r, d_dx_flight__q_rd, d_dx_flight__q_th, d_dx_flight__q_thd, d_apex_b_x__q_r,
        d_apex_b_x__q_rd, d_apex_b_x__q_th, d_apex_b_x__q_thd,))
    return STATUS_OK
