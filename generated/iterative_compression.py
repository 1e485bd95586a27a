# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   geyer.py sha256:4737273d6d8636d4
#   geyer_vs.py sha256:2af0829e07a0cf1b
#   gravity_type0.py sha256:307fd5b7e0072824
#   gravity_type1.py sha256:46607008446ed15d
#   gravity_type2.py sha256:97fb4f568b945f42
#   gravity_type3.py sha256:d4ac1d04e125ac4a
#   gravity_type4.py sha256:81186cbbb1247b9f
#   gravity_type5.py sha256:f4510b5010050beb
#   iterative.py sha256:308e9d4f124ced69
# ----------------------------------------------------------------------------------------------
"""Iterative compression half (touchdown to bottom, k_c; converging form) (report section 5.2.1): touchdown ->
bottom."""

import math

import numpy as np
from numba import njit, prange
from .geyer import geyer_stance
from .geyer_vs import geyer_vs_stance
from .gravity_type0 import gravity_type0_stance
from .gravity_type1 import gravity_type1_stance
from .gravity_type2 import gravity_type2_stance
from .gravity_type3 import gravity_type3_stance
from .gravity_type4 import gravity_type4_stance
from .gravity_type5 import gravity_type5_stance
from .iterative import (schwind_compression_nodes_1, schwind_compression_nodes_2, schwind_compression_nodes_3,
    schwind_compression_nodes_4, schwind_compression_nodes_6)

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan
_NAN6 = (NAN,) * 6


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]

    Returns a tuple:
        t_half: time from the start state to the end state [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td)
    if _c0[10] != STATUS_OK:
        return _NAN6 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_4_zeroth_geyer`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_td, q_rd_td, q_th_td, q_thd_td.
    Scalar arguments shared by every row: m, l0, k_c, g_s, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 6); the columns are the outputs of
    :func:`iterative_compression_nodes_4_zeroth_geyer`, in order) and its status code to ``status[i]``
    (int64).
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_4_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, iterations,
        tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 31
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN6 + (_c0[6],)
    t_half = _c0[0]
    end_q_r = _c0[1]
    end_q_rd = _c0[2]
    end_q_th = _c0[3]
    end_q_thd = _c0[4]
    passes = _c0[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_4_zeroth_held`: arguments, out and status as
    :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_4_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_4_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_4_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_4_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_4_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_4_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_4_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_4_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_4_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_4_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_4_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_4_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_4_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_c, g_s, q_r_td, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN6 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_4_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_4_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_4_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td)
    if _c0[10] != STATUS_OK:
        return _NAN6 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_1_zeroth_geyer`: arguments, out and status as
    :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_1_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, iterations,
        tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 31
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN6 + (_c0[6],)
    t_half = _c0[0]
    end_q_r = _c0[1]
    end_q_rd = _c0[2]
    end_q_th = _c0[3]
    end_q_thd = _c0[4]
    passes = _c0[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_1_zeroth_held`: arguments, out and status as
    :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_1_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_1_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_1_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_1_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_1_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_1_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_1_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_1_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_1_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_1_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_1_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_1_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_1_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_c, g_s, q_r_td, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN6 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_1_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_1_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_1_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td)
    if _c0[10] != STATUS_OK:
        return _NAN6 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_2_zeroth_geyer`: arguments, out and status as
    :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_2_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, iterations,
        tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 31
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN6 + (_c0[6],)
    t_half = _c0[0]
    end_q_r = _c0[1]
    end_q_rd = _c0[2]
    end_q_th = _c0[3]
    end_q_thd = _c0[4]
    passes = _c0[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_2_zeroth_held`: arguments, out and status as
    :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_2_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_2_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_2_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_2_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_2_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_2_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_2_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_2_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_2_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_2_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_2_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_2_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_2_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_c, g_s, q_r_td, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN6 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_2_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_2_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_2_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td)
    if _c0[10] != STATUS_OK:
        return _NAN6 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_3_zeroth_geyer`: arguments, out and status as
    :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_3_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, iterations,
        tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 31
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN6 + (_c0[6],)
    t_half = _c0[0]
    end_q_r = _c0[1]
    end_q_rd = _c0[2]
    end_q_th = _c0[3]
    end_q_thd = _c0[4]
    passes = _c0[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_3_zeroth_held`: arguments, out and status as
    :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_3_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_3_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_3_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_3_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_3_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_3_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_3_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_3_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_3_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_3_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_3_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_3_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_3_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_c, g_s, q_r_td, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN6 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_3_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_3_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_3_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_geyer(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _c0 = geyer_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td)
    if _c0[10] != STATUS_OK:
        return _NAN6 + (_c0[10],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_geyer_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_6_zeroth_geyer`: arguments, out and status as
    :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_6_zeroth_geyer(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, iterations,
        tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 31
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2
    _x0 = k_c*q_r_td
    _x1 = g_s*m*math.cos(q_th_td)
    _x2 = q_thd_td**2
    _x3 = m*q_rd_td**2
    _x4 = (-_x3/(-_x0 - _x1 + _x2*m*q_r_td + k_c*l0 + math.sqrt(_x3*k_c + (-_x0 - _x1 + _x2*m*q_r_td
        + k_c*l0)**2)) + q_r_td)
    z_b_q_r = _x4
    z_b_q_th = q_th_td
    z_b_q_thd = q_r_td**2*q_thd_td/_x4**2
    z_lo_q_th = 0.0
    z_lo_q_thd = 0.0
    # compression half, k_c (report 5.2.1)
    _c0 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c0[6] != STATUS_OK:
        return _NAN6 + (_c0[6],)
    t_half = _c0[0]
    end_q_r = _c0[1]
    end_q_rd = _c0[2]
    end_q_th = _c0[3]
    end_q_thd = _c0[4]
    passes = _c0[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_held_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_6_zeroth_held`: arguments, out and status as
    :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_6_zeroth_held(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i], m,
            l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type0(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _c0 = (gravity_type0_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 1.0,
        0.0))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type0_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_6_zeroth_gravity_type0`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_6_zeroth_gravity_type0(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type1(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _c0 = (gravity_type1_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type1_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_6_zeroth_gravity_type1`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_6_zeroth_gravity_type1(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type2(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _c0 = (gravity_type2_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 2.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type2_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_6_zeroth_gravity_type2`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_6_zeroth_gravity_type2(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type3(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _c0 = (gravity_type3_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 100.0,
        1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type3_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_6_zeroth_gravity_type3`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_6_zeroth_gravity_type3(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type4(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _c0 = (gravity_type4_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 0.0, 1.0, 0.0,
        100.0, 1e-12))
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type4_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_6_zeroth_gravity_type4`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_6_zeroth_gravity_type4(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type5(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _c0 = gravity_type5_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_td, 100.0, 1e-12)
    if _c0[12] != STATUS_OK:
        return _NAN6 + (_c0[12],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_gravity_type5_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c,
        g_s, iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_6_zeroth_gravity_type5`: arguments, out and
    status as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_6_zeroth_gravity_type5(q_r_td[i], q_rd_td[i], q_th_td[i],
            q_thd_td[i], m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_geyer_vs(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Arguments, returns and status: the same as :func:`iterative_compression_nodes_4_zeroth_geyer`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(iterations) and math.isfinite(tol) and ((q_r_td <= l0)
            and (q_r_td > 0.0)) and ((abs(q_th_td) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0))
            and ((k_c > 0.0)) and ((g_s > 0.0)) and ((iterations == math.floor(iterations)) and (iterations
            >= 0.0) and (iterations <= 100.0)) and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _c0 = (geyer_vs_stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_c, g_s, q_r_td, 2.0, 0.0, 100.0,
        1e-12))
    if _c0[13] != STATUS_OK:
        return _NAN6 + (_c0[13],)
    z_b_q_r = _c0[2]
    z_b_q_th = _c0[4]
    z_b_q_thd = _c0[5]
    z_lo_q_th = _c0[8]
    z_lo_q_thd = _c0[9]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression_nodes_6(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, iterations, tol))
    if _c1[6] != STATUS_OK:
        return _NAN6 + (_c1[6],)
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd) and math.isfinite(passes)):
        return _NAN6 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def iterative_compression_nodes_6_zeroth_geyer_vs_batch(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s,
        iterations, tol, out, status):
    """Parallel batch form of :func:`iterative_compression_nodes_6_zeroth_geyer_vs`: arguments, out and status
    as :func:`iterative_compression_nodes_4_zeroth_geyer_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_compression_nodes_6_zeroth_geyer_vs(q_r_td[i], q_rd_td[i], q_th_td[i], q_thd_td[i],
            m, l0, k_c, g_s, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res
