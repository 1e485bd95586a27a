# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight.py sha256:af908ea30b1fc141
#   iterative.py sha256:6c68b56d8ea0aa73
# ----------------------------------------------------------------------------------------------
"""Iterative decompression half (bottom to liftoff, k_d; converging form) (report section 5.2.2): bottom ->
liftoff."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import liftoff_to_apex
from .iterative import schwind_decompression

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan


@njit(cache=True, error_model="numpy")
def iterative_decompression(x, p, out):
    """Iterative decompression half (bottom to liftoff, k_d; converging form): bottom state -> liftoff state.

    Report equations: 29, 30, 31, 32, 37, 41, 137, 138, 139, 140, 141, 143.

    Role kernel: reads x = (q_r_b, q_rd_b, q_th_b, q_thd_b) and the parameter record
    p = (m, l0, k_d, g_s, q_r_lo, c, nodes, iterations, tol, liftoff); writes the outputs below into out, in
    order, and returns
    the status (out all NaN unless OK).

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
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length

    Writes into out:
        t_half: time from the start state to the end state [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        passes: Picard passes run [1]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (q_r_b, q_rd_b, q_th_b, q_thd_b,) = load(x, 0, 1, 2, 3)
    (m, l0, k_d, g_s, q_r_lo, c, nodes, iterations, tol, liftoff,) = load(p, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, c, nodes, iterations, tol,
            liftoff,)) & ((q_r_b > 0.0)) & ((abs(q_th_b) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0))
            & ((k_d > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((c >= 0.0)) & ((nodes
            == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) & ((tol >= 0.0)
            and (tol <= 1.0)) & ((liftoff == 0.0) or (liftoff == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # decompression half, k_d (report 5.2.2)
    _c0 = (schwind_decompression(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, c, q_th_b,
        q_r_b**2*q_thd_b/q_r_lo**2, nodes, iterations, tol, liftoff))
    if _c0[6] != STATUS_OK:
        return fail(out, _c0[6])
    t_half = _c0[0]
    end_q_r = _c0[1]
    end_q_rd = _c0[2]
    end_q_th = _c0[3]
    end_q_thd = _c0[4]
    passes = _c0[5]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_decompression_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_decompression` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(10), 10)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_decompression(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_decompression_apex(x, p, out):
    """Iterative decompression half (bottom to liftoff, k_d; converging form), then the exact flight to the
    next apex: bottom state -> next apex.

    Report equations: 29, 30, 31, 32, 37, 41, 137, 138, 139, 140, 141, 143.

    Role kernel: reads x = (q_r_b, q_rd_b, q_th_b, q_thd_b) and the parameter record
    p = (m, l0, k_d, g_s, g_f, q_r_lo, c, nodes, iterations, tol, liftoff); writes the outputs below into out,
    in order, and returns
    the status (out all NaN unless OK).

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
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]
        liftoff: option liftoff: where a damped leg lifts off (the same liftoff at c = 0): 0 = force, 1 =
            length
        g_f: gravitational acceleration in flight, positive (pointing down) g_f [m/s^2], > 0

    Writes into out:
        apex_height: next apex height above the ground the foot stood on [m]
        apex_speed: next apex horizontal speed (signed) [m/s]
        t_half: time from the bottom to liftoff [s]
        t_ascent: flight time from liftoff to the next apex [s]
        liftoff_q_r: leg length [m]
        liftoff_q_rd: leg length rate [m/s]
        liftoff_q_th: leg angle from the vertical, counterclockwise positive [rad]
        liftoff_q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 8
    (q_r_b, q_rd_b, q_th_b, q_thd_b,) = load(x, 0, 1, 2, 3)
    (m, l0, k_d, g_s, q_r_lo, c, nodes, iterations, tol, liftoff, g_f,) = (load(p, 0, 1, 2, 3, 5, 6, 7, 8, 9,
        10, 4))
    # inputs: finite and inside their domains
    if not (all_finite((q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, c, nodes, iterations, tol,
            liftoff, g_f,)) & ((q_r_b > 0.0)) & ((abs(q_th_b) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0 > 0.0))
            & ((k_d > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((c >= 0.0)) & ((nodes
            == 0.0) or (nodes == 1.0) or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) & ((iterations
            == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0)) & ((tol >= 0.0)
            and (tol <= 1.0)) & ((liftoff == 0.0) or (liftoff == 1.0)) & ((g_f > 0.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # the half: Iterative decompression half (bottom to liftoff, k_d; converging form)
    _x0 = carray(stack(4), 4)
    store(_x0, (q_r_b, q_rd_b, q_th_b, q_thd_b,))
    _p0 = carray(stack(10), 10)
    store(_p0, (m, l0, k_d, g_s, q_r_lo, c, nodes, iterations, tol, liftoff,))
    _o0 = carray(stack(6), 6)
    _c0 = iterative_decompression(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    (_o0_0, liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd,) = load(_o0, 0, 1, 2, 3, 4)
    # the direction the body moves at liftoff
    direction = (0.0 if -liftoff_q_r*liftoff_q_thd*math.cos(liftoff_q_th)
        - liftoff_q_rd*math.sin(liftoff_q_th) == 0 else math.copysign(1,
        -liftoff_q_r*liftoff_q_thd*math.cos(liftoff_q_th) - liftoff_q_rd*math.sin(liftoff_q_th)))
    # liftoff -> next apex: exact ballistic ascent
    _c1 = liftoff_to_apex(liftoff_q_r, liftoff_q_rd, liftoff_q_th, liftoff_q_thd, g_f, direction)
    if _c1[5] != STATUS_OK:
        return fail(out, _c1[5])
    apex_height = _c1[0]
    apex_speed = _c1[1]
    t_ascent = _c1[2]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((apex_height, apex_speed, _o0_0, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
            liftoff_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (apex_height, apex_speed, _o0_0, t_ascent, liftoff_q_r, liftoff_q_rd, liftoff_q_th,
        liftoff_q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_decompression_apex_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_decompression_apex` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(11), 11)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_decompression_apex(row(X, i), p, row(OUT, i))
