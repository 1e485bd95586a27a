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
"""Exact ballistic flight between apex, touchdown and liftoff (report sections 2.1, 2.2.2)."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_APEX_TOO_LOW, STATUS_LIFTOFF_DOWNWARD,
    STATUS_LIFTOFF_BACKWARD, STATUS_NUMERICAL_RANGE, STATUS_NOT_CONVERGED, STATUS_NO_TOUCHDOWN)

NAN = math.nan
_NAN5 = (NAN,) * 5
_NAN6 = (NAN,) * 6


@njit(cache=True, error_model="numpy")
def apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, retraction_rate):
    """Ballistic descent from an apex to touchdown with the leg at q_r_td swinging from q_th_td at
    retraction_rate.

    Report equations: sec2.1-touchdown, sec2.2.2.

    Arguments:
        b_y_apex: apex height of the body above the ground under it b_y_apex [m], >= 0
        b_xd_apex: horizontal apex speed [m/s], signed
        q_th_td: touchdown leg angle from the vertical, counterclockwise positive q_th_td [rad]
        q_r_td: touchdown leg length [m], > 0
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0
        ground: height of the touchdown ground above the ground under the apex (a step up is positive) ground
            [m]
        retraction_rate: swing-leg retraction rate: after the apex the leg angle is touchdown_angle +
            retraction_rate * t (counterclockwise positive like the angle: a forward runner's retracting leg
            has a negative rate; Seyfarth, Geyer and Herr 2003); 0 holds the leg at touchdown_angle
            retraction_rate [rad/s]

    Returns a tuple:
        touchdown_q_r: leg length [m]
        touchdown_q_rd: leg length rate [m/s]
        touchdown_q_th: leg angle from the vertical, counterclockwise positive [rad]
        touchdown_q_thd: leg angle rate [rad/s]
        t_flight: time from the apex to touchdown [s]
        foot_x: horizontal position of the toe at touchdown relative to the apex [m]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 63
    # inputs: finite and inside their domains
    if not (all_finite((b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, retraction_rate,)) & ((b_y_apex
            >= 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((q_r_td > 0.0)) & ((g_f > 0.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    drop = b_y_apex - ground - q_r_td*math.cos(q_th_td)
    # the foot above the touchdown ground at the apex
    if not ((drop > 0.0)):
        return _NAN6 + (STATUS_APEX_TOO_LOW,)
    # the descent time of a leg held still (section 2.1)
    t0 = math.sqrt(2.0)*math.sqrt(drop)/math.sqrt(g_f)
    # |retraction_rate| <= sqrt(g_f/q_r_td): the foot's height concave in time
    if not ((q_r_td*retraction_rate**2 <= g_f)):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # 0: the leg held still (retraction_rate = 0), 1: a swinging leg
    swinging = ((0.0) if (retraction_rate == 0.0) else (1.0))
    # the touchdown time: closed form for a leg held still, else Newton's method
    if swinging == 0.0:
        # t0 with its first-order term in the rate (its derivative; the rate is 0 here, so the values are t0
        # and q_th_td's, as Newton's method from t0 gives bit for bit); no pass; the touchdown angle's sine
        # and cosine: those of q_th_td
        t_td = t0
        t_start = t0
        t_far = t0
        foot_slope = -g_f*t0
        touchdown_passes = 0.0
        touchdown_angle = q_th_td
        sin_td = math.sin(q_th_td)
        cos_td = math.cos(q_th_td)
    elif swinging == 1.0:
        # a start at or after the touchdown: t0 if the foot is on or below the ground then, else the time the
        # body is q_r_td below the ground
        _x0 = 2.0*q_r_td
        _x1 = math.cos(q_th_td)
        _x2 = math.sqrt(_x0*_x1 + _x0 + 2.0*drop)/math.sqrt(g_f)
        t_far = _x2
        t_start = ((t0) if (q_r_td*(_x1 - math.cos(q_th_td + retraction_rate*t0)) <= 0.0) else (_x2))
        # Newton's method on the foot's height (concave: monotone from the right)
        t_td = t_start
        touchdown_passes = 0.0
        _conv0 = False
        # a pass evaluates the current iterate, then (unless the loop stops there) updates it: the
        # final iterate is evaluated too, so its values are visible after the loop
        _last0 = max(int(50.0), 0)
        for _it0 in range(_last0 + 1):
            if _it0 == _last0 and not _conv0 and 1e-12 > 0.0 and touchdown_passes > 0.0:
                return _NAN6 + (STATUS_NOT_CONVERGED,)
            _x3 = (0.5)*g_f
            foot_slope = (_x3*(t0 - t_td) - _x3*(t0 + t_td) + q_r_td*retraction_rate*math.sin(q_th_td
                + retraction_rate*t_td))
            # the foot descends toward the ground
            if not ((foot_slope < 0.0)):
                return _NAN6 + (STATUS_NO_TOUCHDOWN,)
            if _conv0 or _it0 == _last0:
                break
            _n0_0 = (t_td - ((0.5)*g_f*(t0 - t_td)*(t0 + t_td) + q_r_td*(math.cos(q_th_td) - math.cos(q_th_td
                + retraction_rate*t_td)))/foot_slope)
            # converged when every variable moved by at most tol times its scale (NaN never converges;
            # tol = 0 runs every pass)
            _conv0 = 1e-12 > 0.0 and (abs(_n0_0 - t_td) <= 1e-12*(t0))
            t_td = _n0_0
            touchdown_passes += 1.0
        # the leg angle at touchdown, its sine and cosine
        _x4 = q_th_td + retraction_rate*t_td
        touchdown_angle = _x4
        sin_td = math.sin(_x4)
        cos_td = math.cos(_x4)
    else:
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # the leg above the horizontal
    if not ((abs(touchdown_angle) < (0.5)*math.pi)):
        return _NAN6 + (STATUS_NO_TOUCHDOWN,)
    # touchdown state from the derived Cartesian -> polar map
    touchdown_q_r = q_r_td
    touchdown_q_rd = -b_xd_apex*sin_td - cos_td*g_f*t_td
    touchdown_q_th = touchdown_angle
    touchdown_q_thd = (-b_xd_apex*cos_td + g_f*sin_td*t_td)/q_r_td
    t_flight = t_td
    foot_x = b_xd_apex*t_td + q_r_td*sin_td
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((touchdown_q_r, touchdown_q_rd, touchdown_q_th, touchdown_q_thd, t_flight, foot_x,))):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (touchdown_q_r, touchdown_q_rd, touchdown_q_th, touchdown_q_thd, t_flight, foot_x, STATUS_OK)


@njit(cache=True, error_model="numpy")
def liftoff_to_apex(q_r, q_rd, q_th, q_thd, g_f, direction):
    """Ballistic ascent from a polar liftoff state to the next apex.

    Report equations: sec2.1-apex, sec2.2.2.

    Arguments:
        q_r: liftoff leg length q_r [m], > 0
        q_rd: leg length rate q_rd [m/s]
        q_th: leg angle q_th from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate q_thd [rad/s]
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0
        direction: direction of the step: +1 (toward +x), -1 (toward -x) or 0 (a hop in place: either way)

    Returns a tuple:
        apex_b_y: next apex height above the ground [m]
        apex_b_xd: next apex horizontal speed [m/s]
        t_flight: time from liftoff to the apex [s]
        dx_flight: horizontal distance travelled from liftoff to the apex [m]
        apex_b_x: horizontal position of the next apex relative to the toe [m]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 20
    # inputs: finite and inside their domains
    if not (all_finite((q_r, q_rd, q_th, q_thd, g_f, direction,)) & ((q_r > 0.0)) & ((g_f > 0.0))
            & ((direction == -1.0) or (direction == 0.0) or (direction == 1.0))):
        return _NAN5 + (STATUS_INVALID_INPUT,)
    # Cartesian liftoff state relative to the toe
    _x0 = math.sin(q_th)
    _x1 = _x0*q_r
    _x2 = math.cos(q_th)
    _x3 = _x2*q_r
    b_x = -_x1
    b_xd = -_x0*q_rd - _x3*q_thd
    b_y = _x3
    b_yd = -_x1*q_thd + _x2*q_rd
    # liftoff requires an upward velocity
    if not ((b_yd > 0.0)):
        return _NAN5 + (STATUS_LIFTOFF_DOWNWARD,)
    # the body must not move against the step's direction (a hop in place: either way)
    if not ((b_xd*direction >= -1e-09*math.sqrt(g_f*q_r))):
        return _NAN5 + (STATUS_LIFTOFF_BACKWARD,)
    # apex where b_yd(t) = 0
    _x4 = (1.0/g_f)
    _x5 = _x4*b_yd
    _x6 = _x5*b_xd
    apex_b_y = (0.5)*_x4*b_yd**2 + b_y
    apex_b_xd = b_xd
    t_flight = _x5
    dx_flight = _x6
    apex_b_x = _x6 + b_x
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((apex_b_y, apex_b_xd, t_flight, dx_flight, apex_b_x,))):
        return _NAN5 + (STATUS_NUMERICAL_RANGE,)
    return (apex_b_y, apex_b_xd, t_flight, dx_flight, apex_b_x, STATUS_OK)
