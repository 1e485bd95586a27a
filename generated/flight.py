# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/model/flight.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# ----------------------------------------------------------------------------------------------
"""Exact ballistic flight between apex, touchdown and liftoff (report sections 2.1, 2.2.2)."""

import math

import numpy as np
from numba import njit

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_APEX_TOO_LOW, STATUS_LIFTOFF_DOWNWARD,
    STATUS_LIFTOFF_BACKWARD, STATUS_NUMERICAL_RANGE)

NAN = math.nan
_NAN5 = (NAN,) * 5
_NAN6 = (NAN,) * 6


@njit(cache=True, error_model="numpy")
def apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground):
    """Ballistic descent from an apex to touchdown with the leg held at (q_th_td, q_r_td).

    Report equations: sec2.1-touchdown, sec2.2.2.

    Arguments:
        b_y_apex: apex height of the body above the ground under it b_y_apex [m], >= 0
        b_xd_apex: horizontal apex speed [m/s], signed
        q_th_td: touchdown leg angle from the vertical, counterclockwise positive q_th_td [rad]
        q_r_td: touchdown leg length [m], > 0
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0
        ground: height of the touchdown ground above the ground under the apex (a step up is positive) ground
            [m]

    Returns a tuple:
        touchdown_q_r: leg length [m]
        touchdown_q_rd: leg length rate [m/s]
        touchdown_q_th: leg angle from the vertical, counterclockwise positive [rad]
        touchdown_q_thd: leg angle rate [rad/s]
        t_flight: time from the apex to touchdown [s]
        foot_x: horizontal position of the toe at touchdown relative to the apex [m]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 28
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(q_r_td) and math.isfinite(g_f) and math.isfinite(ground) and ((b_y_apex >= 0.0))
            and ((abs(q_th_td) < (0.5)*math.pi)) and ((q_r_td > 0.0)) and ((g_f > 0.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    drop = b_y_apex - ground - q_r_td*math.cos(q_th_td)
    # touchdown height below apex
    if not ((drop > 0.0)):
        return _NAN6 + (STATUS_APEX_TOO_LOW,)
    # touchdown state from the derived Cartesian -> polar map
    _x0 = math.sin(q_th_td)
    _x1 = math.cos(q_th_td)
    _x2 = math.sqrt(g_f)
    _x3 = math.sqrt(2.0)
    _x4 = math.sqrt(drop)
    _x5 = _x3*_x4
    _x6 = _x5/_x2
    touchdown_q_r = q_r_td
    touchdown_q_rd = -_x0*b_xd_apex - _x1*_x2*_x5
    touchdown_q_th = q_th_td
    touchdown_q_thd = (_x0*_x2*_x3*_x4 - _x1*b_xd_apex)/q_r_td
    t_flight = _x6
    foot_x = _x0*q_r_td + _x6*b_xd_apex
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(touchdown_q_r) and math.isfinite(touchdown_q_rd) and math.isfinite(touchdown_q_th)
            and math.isfinite(touchdown_q_thd) and math.isfinite(t_flight) and math.isfinite(foot_x)):
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
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(g_f) and math.isfinite(direction) and ((q_r > 0.0)) and ((g_f > 0.0))
            and ((direction == -1.0) or (direction == 0.0) or (direction == 1.0))):
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
    if not (math.isfinite(apex_b_y) and math.isfinite(apex_b_xd) and math.isfinite(t_flight)
            and math.isfinite(dx_flight) and math.isfinite(apex_b_x)):
        return _NAN5 + (STATUS_NUMERICAL_RANGE,)
    return (apex_b_y, apex_b_xd, t_flight, dx_flight, apex_b_x, STATUS_OK)
