# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   iterative.py sha256:308e9d4f124ced69
# ----------------------------------------------------------------------------------------------
"""Iterative decompression half (bottom to liftoff, k_d; converging form) (report section 5.2.2): bottom ->
liftoff."""

import math

import numpy as np
from numba import njit, prange
from .iterative import (schwind_decompression_nodes_1, schwind_decompression_nodes_2,
    schwind_decompression_nodes_3, schwind_decompression_nodes_4, schwind_decompression_nodes_6)

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan
_NAN6 = (NAN,) * 6


@njit(cache=True, error_model="numpy")
def iterative_decompression_nodes_4(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations, tol):
    """Iterative decompression half (bottom to liftoff, k_d; converging form): bottom state -> liftoff state.

    Report equations: 29, 30, 31, 32, 37, 41, 137, 138, 139, 140, 141, 143.

    Arguments:
        q_r_b: bottom leg length [m], > 0
        q_rd_b: bottom leg length rate [m/s] (not read: 0 at the bottom)
        q_th_b: bottom leg angle from the vertical, counterclockwise positive [rad], |q_th_b| < pi/2
        q_thd_b: bottom leg angle rate [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_d: leg stiffness after the bottom k_d [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
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
    if not (math.isfinite(q_r_b) and math.isfinite(q_rd_b) and math.isfinite(q_th_b)
            and math.isfinite(q_thd_b) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d)
            and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(iterations)
            and math.isfinite(tol) and ((q_r_b > 0.0)) and ((abs(q_th_b) < (0.5)*math.pi)) and ((m > 0.0))
            and ((l0 > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # decompression half, k_d (report 5.2.2)
    _c0 = (schwind_decompression_nodes_4(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, q_th_b,
        q_r_b**2*q_thd_b/q_r_lo**2, iterations, tol))
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
def iterative_decompression_nodes_4_batch(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations,
        tol, out, status):
    """Parallel batch form of :func:`iterative_decompression_nodes_4`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_b, q_rd_b, q_th_b, q_thd_b.
    Scalar arguments shared by every row: m, l0, k_d, g_s, q_r_lo, iterations, tol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 6); the columns are the outputs of
    :func:`iterative_decompression_nodes_4`, in order) and its status code to ``status[i]`` (int64).
    """
    for i in prange(out.shape[0]):
        res = (iterative_decompression_nodes_4(q_r_b[i], q_rd_b[i], q_th_b[i], q_thd_b[i], m, l0, k_d, g_s,
            q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_decompression_nodes_1(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations, tol):
    """Iterative decompression half (bottom to liftoff, k_d; converging form): bottom state -> liftoff state.

    Report equations: 29, 30, 31, 32, 37, 41, 137, 138, 139, 140, 141, 143.

    Arguments, returns and status: the same as :func:`iterative_decompression_nodes_4`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_b) and math.isfinite(q_rd_b) and math.isfinite(q_th_b)
            and math.isfinite(q_thd_b) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d)
            and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(iterations)
            and math.isfinite(tol) and ((q_r_b > 0.0)) and ((abs(q_th_b) < (0.5)*math.pi)) and ((m > 0.0))
            and ((l0 > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # decompression half, k_d (report 5.2.2)
    _c0 = (schwind_decompression_nodes_1(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, q_th_b,
        q_r_b**2*q_thd_b/q_r_lo**2, iterations, tol))
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
def iterative_decompression_nodes_1_batch(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations,
        tol, out, status):
    """Parallel batch form of :func:`iterative_decompression_nodes_1`: arguments, out and status as
    :func:`iterative_decompression_nodes_4_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_decompression_nodes_1(q_r_b[i], q_rd_b[i], q_th_b[i], q_thd_b[i], m, l0, k_d, g_s,
            q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_decompression_nodes_2(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations, tol):
    """Iterative decompression half (bottom to liftoff, k_d; converging form): bottom state -> liftoff state.

    Report equations: 29, 30, 31, 32, 37, 41, 137, 138, 139, 140, 141, 143.

    Arguments, returns and status: the same as :func:`iterative_decompression_nodes_4`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_b) and math.isfinite(q_rd_b) and math.isfinite(q_th_b)
            and math.isfinite(q_thd_b) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d)
            and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(iterations)
            and math.isfinite(tol) and ((q_r_b > 0.0)) and ((abs(q_th_b) < (0.5)*math.pi)) and ((m > 0.0))
            and ((l0 > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # decompression half, k_d (report 5.2.2)
    _c0 = (schwind_decompression_nodes_2(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, q_th_b,
        q_r_b**2*q_thd_b/q_r_lo**2, iterations, tol))
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
def iterative_decompression_nodes_2_batch(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations,
        tol, out, status):
    """Parallel batch form of :func:`iterative_decompression_nodes_2`: arguments, out and status as
    :func:`iterative_decompression_nodes_4_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_decompression_nodes_2(q_r_b[i], q_rd_b[i], q_th_b[i], q_thd_b[i], m, l0, k_d, g_s,
            q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_decompression_nodes_3(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations, tol):
    """Iterative decompression half (bottom to liftoff, k_d; converging form): bottom state -> liftoff state.

    Report equations: 29, 30, 31, 32, 37, 41, 137, 138, 139, 140, 141, 143.

    Arguments, returns and status: the same as :func:`iterative_decompression_nodes_4`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_b) and math.isfinite(q_rd_b) and math.isfinite(q_th_b)
            and math.isfinite(q_thd_b) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d)
            and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(iterations)
            and math.isfinite(tol) and ((q_r_b > 0.0)) and ((abs(q_th_b) < (0.5)*math.pi)) and ((m > 0.0))
            and ((l0 > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # decompression half, k_d (report 5.2.2)
    _c0 = (schwind_decompression_nodes_3(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, q_th_b,
        q_r_b**2*q_thd_b/q_r_lo**2, iterations, tol))
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
def iterative_decompression_nodes_3_batch(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations,
        tol, out, status):
    """Parallel batch form of :func:`iterative_decompression_nodes_3`: arguments, out and status as
    :func:`iterative_decompression_nodes_4_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_decompression_nodes_3(q_r_b[i], q_rd_b[i], q_th_b[i], q_thd_b[i], m, l0, k_d, g_s,
            q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res


@njit(cache=True, error_model="numpy")
def iterative_decompression_nodes_6(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations, tol):
    """Iterative decompression half (bottom to liftoff, k_d; converging form): bottom state -> liftoff state.

    Report equations: 29, 30, 31, 32, 37, 41, 137, 138, 139, 140, 141, 143.

    Arguments, returns and status: the same as :func:`iterative_decompression_nodes_4`'s.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_b) and math.isfinite(q_rd_b) and math.isfinite(q_th_b)
            and math.isfinite(q_thd_b) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d)
            and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(iterations)
            and math.isfinite(tol) and ((q_r_b > 0.0)) and ((abs(q_th_b) < (0.5)*math.pi)) and ((m > 0.0))
            and ((l0 > 0.0)) and ((k_d > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0))
            and ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            and ((tol >= 0.0) and (tol <= 1.0))):
        return _NAN6 + (STATUS_INVALID_INPUT,)
    # decompression half, k_d (report 5.2.2)
    _c0 = (schwind_decompression_nodes_6(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, q_th_b,
        q_r_b**2*q_thd_b/q_r_lo**2, iterations, tol))
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
def iterative_decompression_nodes_6_batch(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, iterations,
        tol, out, status):
    """Parallel batch form of :func:`iterative_decompression_nodes_6`: arguments, out and status as
    :func:`iterative_decompression_nodes_4_batch`'s.
    """
    for i in prange(out.shape[0]):
        res = (iterative_decompression_nodes_6(q_r_b[i], q_rd_b[i], q_th_b[i], q_thd_b[i], m, l0, k_d, g_s,
            q_r_lo, iterations, tol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], out[i, 5], status[i]) = res
