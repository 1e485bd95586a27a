# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/model/flight.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# ----------------------------------------------------------------------------------------------
"""Derivatives (forward mode, derive/tangent.py) of the kernels of module flight: JVP kernels, and for a map
its stance and apex-return Jacobians."""

import math

import numpy as np
from numba import njit, prange

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import (STATUS_OK, STATUS_INVALID_INPUT, STATUS_APEX_TOO_LOW, STATUS_LIFTOFF_DOWNWARD,
    STATUS_LIFTOFF_BACKWARD)

NAN = math.nan
_NAN8 = (NAN,) * 8
_NAN10 = (NAN,) * 10
_NAN16 = (NAN,) * 16
_NAN20 = (NAN,) * 20


@njit(cache=True, error_model="numpy")
def apex_to_touchdown_jac_b_y_apex_b_xd_apex_q_th_td(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f):
    """Ballistic descent from an apex to touchdown with the leg held at (q_th_td, q_r_td), and the derivatives
    of its outputs with respect to b_y_apex, b_xd_apex, q_th_td.

    Report equations: sec2.1-touchdown, sec2.2.2.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground [m], >= 0
        b_xd_apex: horizontal apex speed [m/s]
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_r_td: touchdown leg length [m], > 0
        g_f: gravitational acceleration in flight g_f [m/s^2], positive

    Returns a tuple:
        touchdown_q_r: leg length [m]
        touchdown_q_rd: leg length rate [m/s]
        touchdown_q_th: leg angle from the vertical, counterclockwise positive [rad]
        touchdown_q_thd: leg angle rate [rad/s]
        t_flight: time from the apex to touchdown [s]
        d_<output>__<argument>: d output / d argument for each output above and argument b_y_apex, b_xd_apex,
            q_th_td (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 47
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(q_r_td) and math.isfinite(g_f) and ((b_y_apex >= 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((q_r_td > 0.0)) and ((g_f > 0.0))):
        return _NAN20 + (STATUS_INVALID_INPUT,)
    drop = b_y_apex - q_r_td*math.cos(q_th_td)
    d_drop__q_th_td = q_r_td*math.sin(q_th_td)
    # touchdown height below apex
    if not ((drop > 0.0)):
        return _NAN20 + (STATUS_APEX_TOO_LOW,)
    # touchdown state from the derived Cartesian -> polar map
    touchdown_q_r = q_r_td
    _x0 = math.sin(q_th_td)
    _x1 = math.cos(q_th_td)
    _x2 = math.sqrt(g_f)
    _x3 = math.sqrt(2.0)
    _x4 = math.sqrt(drop)
    _x5 = _x3*_x4
    _x6 = _x2*_x5
    _x7 = _x0*b_xd_apex + _x1*_x6
    touchdown_q_rd = -_x7
    _x8 = (0.5)*_x3/_x4
    _x9 = _x2*_x8
    _pd__0 = -_x1*_x9
    d_touchdown_q_rd__b_xd_apex = -_x0
    _x10 = _x1*b_xd_apex
    d_touchdown_q_rd__q_th_td = _pd__0*d_drop__q_th_td + _x0*_x6 - _x10
    touchdown_q_th = q_th_td
    _x11 = (1.0/q_r_td)
    touchdown_q_thd = _x11*(_x0*_x2*_x3*_x4 - _x10)
    _pd__1 = _x0*_x11*_x9
    d_touchdown_q_thd__b_xd_apex = -_x1*_x11
    d_touchdown_q_thd__q_th_td = _pd__1*d_drop__q_th_td + _x11*_x7
    _x12 = (1.0/_x2)
    t_flight = _x12*_x5
    _pd__2 = _x12*_x8
    d_t_flight__q_th_td = _pd__2*d_drop__q_th_td
    # derivatives of the outputs
    d_touchdown_q_r__b_y_apex = 0.0
    d_touchdown_q_r__b_xd_apex = 0.0
    d_touchdown_q_r__q_th_td = 0.0
    d_touchdown_q_rd__b_y_apex = _pd__0
    d_touchdown_q_th__b_y_apex = 0.0
    d_touchdown_q_th__b_xd_apex = 0.0
    d_touchdown_q_th__q_th_td = 1.0
    d_touchdown_q_thd__b_y_apex = _pd__1
    d_t_flight__b_y_apex = _pd__2
    d_t_flight__b_xd_apex = 0.0
    # (internal helper: its callers check that their outputs are finite)
    return (touchdown_q_r, touchdown_q_rd, touchdown_q_th, touchdown_q_thd, t_flight,
        d_touchdown_q_r__b_y_apex, d_touchdown_q_r__b_xd_apex, d_touchdown_q_r__q_th_td,
        d_touchdown_q_rd__b_y_apex, d_touchdown_q_rd__b_xd_apex, d_touchdown_q_rd__q_th_td,
        d_touchdown_q_th__b_y_apex, d_touchdown_q_th__b_xd_apex, d_touchdown_q_th__q_th_td,
        d_touchdown_q_thd__b_y_apex, d_touchdown_q_thd__b_xd_apex, d_touchdown_q_thd__q_th_td,
        d_t_flight__b_y_apex, d_t_flight__b_xd_apex, d_t_flight__q_th_td, STATUS_OK)


@njit(cache=True, error_model="numpy")
def liftoff_to_apex_jac_q_rd_q_th_q_thd(q_r, q_rd, q_th, q_thd, g_f):
    """Ballistic ascent from a polar liftoff state to the next apex, and the derivatives of its outputs with
    respect to q_rd, q_th, q_thd.

    Report equations: sec2.1-apex, sec2.2.2.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        q_r: liftoff leg length q_r [m], > 0
        q_rd: leg length rate q_rd [m/s]
        q_th: leg angle q_th from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate q_thd [rad/s]
        g_f: gravitational acceleration in flight g_f [m/s^2], positive

    Returns a tuple:
        apex_b_y: next apex height above the ground [m]
        apex_b_xd: next apex horizontal speed [m/s]
        t_flight: time from liftoff to the apex [s]
        dx_flight: horizontal distance travelled from liftoff to the apex [m]
        d_<output>__<argument>: d output / d argument for each output above and argument q_rd, q_th, q_thd
            (row-major)
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 39
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(g_f) and ((q_r > 0.0)) and ((g_f > 0.0))):
        return _NAN16 + (STATUS_INVALID_INPUT,)
    # Cartesian liftoff state relative to the toe
    _x0 = math.sin(q_th)
    _x1 = math.cos(q_th)
    _x2 = _x1*q_r
    _x3 = -_x0*q_rd - _x2*q_thd
    b_xd = _x3
    d_b_xd__q_rd = -_x0
    _x4 = _x0*q_r
    _x5 = -_x1*q_rd + _x4*q_thd
    d_b_xd__q_th = _x5
    d_b_xd__q_thd = -_x2
    b_y = _x2
    _x6 = -_x4
    d_b_y__q_th = _x6
    b_yd = -_x5
    d_b_yd__q_rd = _x1
    d_b_yd__q_th = _x3
    d_b_yd__q_thd = _x6
    # liftoff requires an upward velocity
    if not ((b_yd > 0.0)):
        return _NAN16 + (STATUS_LIFTOFF_DOWNWARD,)
    # the runner moves in +x; a vertical hop (b_xd ~ 0) is a valid gait
    if not ((b_xd >= -1e-09*math.sqrt(g_f*q_r))):
        return _NAN16 + (STATUS_LIFTOFF_BACKWARD,)
    # apex where b_yd(t) = 0
    _x7 = (1.0/g_f)
    apex_b_y = (0.5)*_x7*b_yd**2 + b_y
    _x8 = _x7*b_yd
    _pd__0 = _x8
    d_apex_b_y__q_rd = _pd__0*d_b_yd__q_rd
    d_apex_b_y__q_th = _pd__0*d_b_yd__q_th + d_b_y__q_th
    d_apex_b_y__q_thd = _pd__0*d_b_yd__q_thd
    apex_b_xd = b_xd
    t_flight = _x8
    _pd__1 = _x7
    d_t_flight__q_rd = _pd__1*d_b_yd__q_rd
    d_t_flight__q_th = _pd__1*d_b_yd__q_th
    d_t_flight__q_thd = _pd__1*d_b_yd__q_thd
    dx_flight = _x8*b_xd
    _pd__2 = _x8
    _pd__3 = _x7*b_xd
    d_dx_flight__q_rd = _pd__2*d_b_xd__q_rd + _pd__3*d_b_yd__q_rd
    d_dx_flight__q_th = _pd__2*d_b_xd__q_th + _pd__3*d_b_yd__q_th
    d_dx_flight__q_thd = _pd__2*d_b_xd__q_thd + _pd__3*d_b_yd__q_thd
    # derivatives of the outputs
    d_apex_b_xd__q_rd = d_b_xd__q_rd
    d_apex_b_xd__q_th = d_b_xd__q_th
    d_apex_b_xd__q_thd = d_b_xd__q_thd
    # (internal helper: its callers check that their outputs are finite)
    return (apex_b_y, apex_b_xd, t_flight, dx_flight, d_apex_b_y__q_rd, d_apex_b_y__q_th, d_apex_b_y__q_thd,
        d_apex_b_xd__q_rd, d_apex_b_xd__q_th, d_apex_b_xd__q_thd, d_t_flight__q_rd, d_t_flight__q_th,
        d_t_flight__q_thd, d_dx_flight__q_rd, d_dx_flight__q_th, d_dx_flight__q_thd, STATUS_OK)


@njit(cache=True, error_model="numpy")
def apex_to_touchdown_jvp_b_y_apex_b_xd_apex_q_th_td(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, b_y_apex__tan,
        b_xd_apex__tan, q_th_td__tan):
    """Ballistic descent from an apex to touchdown with the leg held at (q_th_td, q_r_td), with the derivative
    of every output along the direction (b_y_apex__tan, b_xd_apex__tan, q_th_td__tan).

    Report equations: sec2.1-touchdown, sec2.2.2.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        b_y_apex: apex height of the body above the ground [m], >= 0
        b_xd_apex: horizontal apex speed [m/s]
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_r_td: touchdown leg length [m], > 0
        g_f: gravitational acceleration in flight g_f [m/s^2], positive
        b_y_apex__tan: direction: its component along b_y_apex
        b_xd_apex__tan: direction: its component along b_xd_apex
        q_th_td__tan: direction: its component along q_th_td

    Returns a tuple:
        touchdown_q_r: leg length [m]
        touchdown_q_rd: leg length rate [m/s]
        touchdown_q_th: leg angle from the vertical, counterclockwise positive [rad]
        touchdown_q_thd: leg angle rate [rad/s]
        t_flight: time from the apex to touchdown [s]
        <output>__tan: the derivative of each output above along the direction, in order
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 48
    # inputs: finite and inside their domains
    if not (math.isfinite(b_y_apex) and math.isfinite(b_xd_apex) and math.isfinite(q_th_td)
            and math.isfinite(q_r_td) and math.isfinite(g_f) and ((b_y_apex >= 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((q_r_td > 0.0)) and ((g_f > 0.0))):
        return _NAN10 + (STATUS_INVALID_INPUT,)
    drop = b_y_apex - q_r_td*math.cos(q_th_td)
    drop__tan = b_y_apex__tan + q_r_td*q_th_td__tan*math.sin(q_th_td)
    # touchdown height below apex
    if not ((drop > 0.0)):
        return _NAN10 + (STATUS_APEX_TOO_LOW,)
    # touchdown state from the derived Cartesian -> polar map
    touchdown_q_r = q_r_td
    _x0 = math.sin(q_th_td)
    _x1 = math.cos(q_th_td)
    _x2 = math.sqrt(g_f)
    _x3 = math.sqrt(2.0)
    _x4 = math.sqrt(drop)
    _x5 = _x3*_x4
    _x6 = _x0*b_xd_apex + _x1*_x2*_x5
    touchdown_q_rd = -_x6
    _x7 = (0.5)*_x3*drop__tan/_x4
    _x8 = _x2*_x7
    _x9 = _x0*_x2*_x3*_x4 - _x1*b_xd_apex
    touchdown_q_rd__tan = -_x0*b_xd_apex__tan - _x1*_x8 + _x9*q_th_td__tan
    touchdown_q_th = q_th_td
    _x10 = (1.0/q_r_td)
    touchdown_q_thd = _x10*_x9
    touchdown_q_thd__tan = _x0*_x10*_x8 - _x1*_x10*b_xd_apex__tan + _x10*_x6*q_th_td__tan
    _x11 = (1.0/_x2)
    t_flight = _x11*_x5
    t_flight__tan = _x11*_x7
    # derivatives of the outputs
    touchdown_q_r__tan = 0.0
    touchdown_q_th__tan = q_th_td__tan
    # (internal helper: its callers check that their outputs are finite)
    return (touchdown_q_r, touchdown_q_rd, touchdown_q_th, touchdown_q_thd, t_flight, touchdown_q_r__tan,
        touchdown_q_rd__tan, touchdown_q_th__tan, touchdown_q_thd__tan, t_flight__tan, STATUS_OK)


@njit(cache=True, error_model="numpy")
def liftoff_to_apex_jvp_q_r_q_rd_q_th_q_thd(q_r, q_rd, q_th, q_thd, g_f, q_r__tan, q_rd__tan, q_th__tan,
        q_thd__tan):
    """Ballistic ascent from a polar liftoff state to the next apex, with the derivative of every output along
    the direction (q_r__tan, q_rd__tan, q_th__tan, q_thd__tan).

    Report equations: sec2.1-apex, sec2.2.2.

    Derivatives by forward-mode differentiation of the declaration (derive/tangent.py), every
    direction in one pass; through an iteration, of the iterate it stops at.

    Arguments:
        q_r: liftoff leg length q_r [m], > 0
        q_rd: leg length rate q_rd [m/s]
        q_th: leg angle q_th from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate q_thd [rad/s]
        g_f: gravitational acceleration in flight g_f [m/s^2], positive
        q_r__tan: direction: its component along q_r
        q_rd__tan: direction: its component along q_rd
        q_th__tan: direction: its component along q_th
        q_thd__tan: direction: its component along q_thd

    Returns a tuple:
        apex_b_y: next apex height above the ground [m]
        apex_b_xd: next apex horizontal speed [m/s]
        t_flight: time from liftoff to the apex [s]
        dx_flight: horizontal distance travelled from liftoff to the apex [m]
        <output>__tan: the derivative of each output above along the direction, in order
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 44
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
            and math.isfinite(g_f) and ((q_r > 0.0)) and ((g_f > 0.0))):
        return _NAN8 + (STATUS_INVALID_INPUT,)
    # Cartesian liftoff state relative to the toe
    _x0 = math.sin(q_th)
    _x1 = math.cos(q_th)
    _x2 = _x1*q_r
    _x3 = -_x0*q_rd - _x2*q_thd
    b_xd = _x3
    _x4 = _x0*q_r
    _x5 = -_x1*q_rd + _x4*q_thd
    b_xd__tan = -_x0*q_rd__tan - _x1*q_r__tan*q_thd - _x2*q_thd__tan + _x5*q_th__tan
    b_y = _x2
    b_y__tan = _x1*q_r__tan - _x4*q_th__tan
    b_yd = -_x5
    b_yd__tan = -_x0*q_r__tan*q_thd + _x1*q_rd__tan + _x3*q_th__tan - _x4*q_thd__tan
    # liftoff requires an upward velocity
    if not ((b_yd > 0.0)):
        return _NAN8 + (STATUS_LIFTOFF_DOWNWARD,)
    # the runner moves in +x; a vertical hop (b_xd ~ 0) is a valid gait
    if not ((b_xd >= -1e-09*math.sqrt(g_f*q_r))):
        return _NAN8 + (STATUS_LIFTOFF_BACKWARD,)
    # apex where b_yd(t) = 0
    _x6 = (1.0/g_f)
    apex_b_y = (0.5)*_x6*b_yd**2 + b_y
    _x7 = _x6*b_yd
    apex_b_y__tan = _x7*b_yd__tan + b_y__tan
    apex_b_xd = b_xd
    t_flight = _x7
    _x8 = _x6*b_yd__tan
    t_flight__tan = _x8
    dx_flight = _x7*b_xd
    dx_flight__tan = _x7*b_xd__tan + _x8*b_xd
    # derivatives of the outputs
    apex_b_xd__tan = b_xd__tan
    # (internal helper: its callers check that their outputs are finite)
    return (apex_b_y, apex_b_xd, t_flight, dx_flight, apex_b_y__tan, apex_b_xd__tan, t_flight__tan,
        dx_flight__tan, STATUS_OK)
