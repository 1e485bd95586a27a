# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/model/mechanics.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# ----------------------------------------------------------------------------------------------
"""SLIP stance equations of motion, energy and polar <-> Cartesian maps (report eqs 1-3, 27, sec 2.2)."""

import math

import numpy as np
from numba import njit


NAN = math.nan


@njit(cache=True, error_model="numpy")
def max_step(m, l0, k, g_s):
    """The step cap of a stance subphase with stiffness k: MAX_STEP_FRACTION of the shorter natural period.

    Arguments:
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k: leg stiffness k [N/m] (k_c while compressing, k_d after the bottom)
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0

    Returns:
        step: the largest step of the integration [s]
    """
    # Total ops: 15
    _x0 = 2.0*math.pi
    step = 0.0625*min(_x0*math.sqrt(l0)/math.sqrt(g_s), _x0*math.sqrt(m)/math.sqrt(k))
    return step


@njit(cache=True, error_model="numpy")
def stance_time_limit(m, l0, k_c, k_d, g_s):
    """The stance time limit: T_MAX_PERIODS times the spring period of the softer spring plus the pendulum
    period.

    Arguments:
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0

    Returns:
        t_max: the stance time limit [s]
    """
    # Total ops: 16
    _x0 = 40.0*math.pi
    t_max = _x0*math.sqrt(m)*math.sqrt((1.0/min(k_c, k_d))) + _x0*math.sqrt(l0)/math.sqrt(g_s)
    return t_max


@njit(cache=True, error_model="numpy")
def stance_polar_rhs(q_r, q_rd, q_th, q_thd, m, l0, k, g_s):
    """Polar stance vector field d/dt (q_r, q_rd, q_th, q_thd) from the Euler-Lagrange equations.

    Report equations: 1, 2, 3, sec2.2.1-polar.

    Arguments:
        q_r: leg length q_r [m]
        q_rd: leg length rate q_rd [m/s]
        q_th: leg angle q_th from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate q_thd [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k: leg stiffness k [N/m] (k_c while compressing, k_d after the bottom)
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0

    Returns a tuple:
        d_q_r: dq_r/dt [m/s]
        d_q_rd: d^2q_r/dt^2 [m/s^2]
        d_q_th: dq_th/dt [rad/s]
        d_q_thd: d^2q_th/dt^2 [rad/s^2]
    """
    # Total ops: 20
    _x0 = (1.0/m)
    _x1 = (1.0/q_r)
    d_q_r = q_rd
    d_q_rd = _x0*k*l0 - _x0*k*q_r - g_s*math.cos(q_th) + q_r*q_thd**2
    d_q_th = q_thd
    d_q_thd = _x1*g_s*math.sin(q_th) - 2.0*_x1*q_rd*q_thd
    return (d_q_r, d_q_rd, d_q_th, d_q_thd)


@njit(cache=True, error_model="numpy")
def stance_polar_tangent(q_r, q_rd, q_th, q_thd, s_q_r, s_q_rd, s_q_th, s_q_thd, s_k, m, l0, k, g_s):
    """Variational equations of the polar stance field: d/dt (dy/dw) = J dy/dw + (df/dk) dk/dw.

    Report equations: 2, 3, sec2.2.1-polar.

    Arguments:
        q_r: leg length q_r [m]
        q_rd: leg length rate q_rd [m/s]
        q_th: leg angle q_th from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate q_thd [rad/s]
        s_q_r: dq_r/dw, the state's sensitivity to an input w [m per unit of w]
        s_q_rd: dq_rd/dw, the state's sensitivity to an input w [m/s per unit of w]
        s_q_th: dq_th/dw, the state's sensitivity to an input w [rad per unit of w]
        s_q_thd: dq_thd/dw, the state's sensitivity to an input w [rad/s per unit of w]
        s_k: dk/dw, the stiffness's sensitivity to w (1 for w = k, else 0) [N/m per unit of w]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k: leg stiffness k [N/m] (k_c while compressing, k_d after the bottom)
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0

    Returns a tuple:
        ds_q_r: d/dt of dq_r/dw [m/s per unit of w]
        ds_q_rd: d/dt of dq_rd/dw [m/s^2 per unit of w]
        ds_q_th: d/dt of dq_th/dw [rad/s per unit of w]
        ds_q_thd: d/dt of dq_thd/dw [rad/s^2 per unit of w]
    """
    # Total ops: 38
    _x3 = (1.0/q_r)
    _x0 = g_s*math.sin(q_th)
    _x1 = 2.0*q_thd
    _x2 = (1.0/m)
    _x4 = _x3**2
    ds_q_r = s_q_rd
    ds_q_rd = _x0*s_q_th + _x1*q_r*s_q_thd + s_k*(_x2*l0 - _x2*q_r) + s_q_r*(-_x2*k + q_thd**2)
    ds_q_th = s_q_thd
    ds_q_thd = (-_x1*_x3*s_q_rd + _x3*g_s*s_q_th*math.cos(q_th) - 2.0*_x3*q_rd*s_q_thd + s_q_r*(-_x0*_x4
        + 2.0*_x4*q_rd*q_thd))
    return (ds_q_r, ds_q_rd, ds_q_th, ds_q_thd)


@njit(cache=True, error_model="numpy")
def stance_polar_damping(q_r, q_rd, q_th, q_thd, m, c):
    """The leg damper's term of the polar stance field: the damped field minus the lossless one.

    Report equations: sec2.2.1-damped.

    Arguments:
        q_r: leg length q_r [m]
        q_rd: leg length rate q_rd [m/s]
        q_th: leg angle q_th from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate q_thd [rad/s]
        m: body mass m [kg], > 0
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0

    Returns a tuple:
        damping_q_r: the damper's term of dq_r/dt [m/s]
        damping_q_rd: the damper's term of dq_rd/dt [m/s^2]
        damping_q_th: the damper's term of dq_th/dt [rad/s]
        damping_q_thd: the damper's term of dq_thd/dt [rad/s^2]
    """
    # Total ops: 3
    damping_q_rd = -c*q_rd/m
    return (0.0, damping_q_rd, 0.0, 0.0)


@njit(cache=True, error_model="numpy")
def stance_polar_damping_tangent(q_r, q_rd, q_th, q_thd, s_q_r, s_q_rd, s_q_th, s_q_thd, s_c, m, c):
    """The leg damper's term of the variational equations: J_D dy/dw + (dD/dc) dc/dw.

    Report equations: sec2.2.1-damped.

    Arguments:
        q_r: leg length q_r [m]
        q_rd: leg length rate q_rd [m/s]
        q_th: leg angle q_th from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate q_thd [rad/s]
        s_q_r: dq_r/dw, the state's sensitivity to an input w [m per unit of w]
        s_q_rd: dq_rd/dw, the state's sensitivity to an input w [m/s per unit of w]
        s_q_th: dq_th/dw, the state's sensitivity to an input w [rad per unit of w]
        s_q_thd: dq_thd/dw, the state's sensitivity to an input w [rad/s per unit of w]
        s_c: dc/dw, the damping's sensitivity to w (1 for w = c, else 0) [N s/m per unit of w]
        m: body mass m [kg], > 0
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0

    Returns a tuple:
        ds_q_r: the damper's term of d/dt of dq_r/dw [m/s per unit of w]
        ds_q_rd: the damper's term of d/dt of dq_rd/dw [m/s^2 per unit of w]
        ds_q_th: the damper's term of d/dt of dq_th/dw [rad/s per unit of w]
        ds_q_thd: the damper's term of d/dt of dq_thd/dw [rad/s^2 per unit of w]
    """
    # Total ops: 7
    _x0 = (1.0/m)
    ds_q_rd = -_x0*c*s_q_rd - _x0*q_rd*s_c
    return (0.0, ds_q_rd, 0.0, 0.0)


@njit(cache=True, error_model="numpy")
def stance_cartesian_rhs(b_x, b_xd, b_y, b_yd, m, l0, k, g_s):
    """Cartesian stance vector field d/dt (b_x, b_xd, b_y, b_yd), toe at the origin on flat ground.

    Report equations: sec2.2.1-cartesian.

    Arguments:
        b_x: horizontal body position relative to the toe b_x [m]
        b_xd: horizontal body velocity b_xd [m/s]
        b_y: body height above the toe b_y [m]
        b_yd: vertical body velocity b_yd [m/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k: leg stiffness k [N/m] (k_c while compressing, k_d after the bottom)
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0

    Returns a tuple:
        d_b_x: db_x/dt [m/s]
        d_b_xd: d^2b_x/dt^2 [m/s^2]
        d_b_y: db_y/dt [m/s]
        d_b_yd: d^2b_y/dt^2 [m/s^2]
    """
    # Total ops: 19
    _x0 = (1.0/m)
    _x1 = _x0*k
    _x2 = _x1*b_x
    _x3 = (1.0/math.sqrt(b_x**2 + b_y**2))
    d_b_x = b_xd
    d_b_xd = _x2*_x3*l0 - _x2
    d_b_y = b_yd
    d_b_yd = _x0*_x3*b_y*k*l0 - _x1*b_y - g_s
    return (d_b_x, d_b_xd, d_b_y, d_b_yd)


@njit(cache=True, error_model="numpy")
def stance_energy(q_r, q_rd, q_th, q_thd, m, l0, k, g_s):
    """Total stance energy, the Hamiltonian (27) evaluated at p_r = m q_rd, p_th = m q_r^2 q_thd.

    Report equations: 27.

    Arguments:
        q_r: leg length q_r [m]
        q_rd: leg length rate q_rd [m/s]
        q_th: leg angle q_th from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate q_thd [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k: leg stiffness k [N/m] (k_c while compressing, k_d after the bottom)
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0

    Returns:
        energy: total mechanical energy E (gravity potential zero at toe height) [J]
    """
    # Total ops: 22
    _x0 = (0.5)*k
    _x1 = q_r**2
    _x2 = (0.5)*m
    energy = _x0*_x1 + _x0*l0**2 + _x1*_x2*q_thd**2 + _x2*q_rd**2 + g_s*m*q_r*math.cos(q_th) - k*l0*q_r
    return energy


@njit(cache=True, error_model="numpy")
def polar_to_cartesian(q_r, q_rd, q_th, q_thd):
    """Polar stance state -> Cartesian body state relative to the toe.

    Report equations: sec2.2-coordinates.

    Arguments:
        q_r: leg length q_r [m]
        q_rd: leg length rate q_rd [m/s]
        q_th: leg angle q_th from the vertical, counterclockwise positive [rad]
        q_thd: leg angle rate q_thd [rad/s]

    Returns a tuple:
        out_b_x: b_x = -q_r sin q_th [m]
        out_b_xd: b_xd [m/s]
        out_b_y: b_y = q_r cos q_th [m]
        out_b_yd: b_yd [m/s]
    """
    # Total ops: 12
    _x0 = math.sin(q_th)
    _x1 = _x0*q_r
    _x2 = math.cos(q_th)
    _x3 = _x2*q_r
    out_b_x = -_x1
    out_b_xd = -_x0*q_rd - _x3*q_thd
    out_b_y = _x3
    out_b_yd = -_x1*q_thd + _x2*q_rd
    return (out_b_x, out_b_xd, out_b_y, out_b_yd)


@njit(cache=True, error_model="numpy")
def cartesian_to_polar(b_x, b_xd, b_y, b_yd):
    """Cartesian body state relative to the toe -> polar stance state (inverse of polar_to_cartesian).

    Report equations: sec2.2-coordinates.

    Arguments:
        b_x: horizontal body position relative to the toe b_x [m]
        b_xd: horizontal body velocity b_xd [m/s]
        b_y: body height above the toe b_y [m]
        b_yd: vertical body velocity b_yd [m/s]

    Returns a tuple:
        out_q_r: q_r [m]
        out_q_rd: q_rd [m/s]
        out_q_th: q_th = atan2(-b_x, b_y) [rad]
        out_q_thd: q_thd [rad/s]
    """
    # Total ops: 15
    _x0 = b_x**2 + b_y**2
    _x1 = math.sqrt(_x0)
    out_q_r = _x1
    out_q_rd = (b_x*b_xd + b_y*b_yd)/_x1
    out_q_th = math.atan2(-b_x, b_y)
    out_q_thd = (b_x*b_yd - b_xd*b_y)/_x0
    return (out_q_r, out_q_rd, out_q_th, out_q_thd)
