# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   iterative.py sha256:6c68b56d8ea0aa73
# ----------------------------------------------------------------------------------------------
"""Iterative compression half (touchdown to bottom, k_c; converging form) (report section 5.2.1): touchdown ->
bottom."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .iterative import (schwind_compression, zeroth_geyer, zeroth_geyer_vs, zeroth_gravity_type0,
    zeroth_gravity_type1, zeroth_gravity_type2, zeroth_gravity_type3, zeroth_gravity_type4,
    zeroth_gravity_type5, zeroth_held)

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan


@njit(cache=True, error_model="numpy", inline="always")
def iterative_compression_zeroth_shared(x, p, out, zeroth):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    The body that 9 kernels share, each passing the kernel it calls as zeroth (derive/share.py):
    iterative_compression_zeroth_{geyer, held, gravity_type0, gravity_type1, gravity_type2,
    gravity_type3, gravity_type4, gravity_type5, geyer_vs}.

    Arguments, returns and status: those of the kernels, then zeroth.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, g_s, c, nodes, iterations, tol,) = load(p, 0, 1, 2, 3, 4, 5, 6, 7)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, c, nodes, iterations, tol,))
            & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0
            > 0.0)) & ((k_c > 0.0)) & ((g_s > 0.0)) & ((c >= 0.0)) & ((nodes == 0.0) or (nodes == 1.0)
            or (nodes == 2.0) or (nodes == 3.0) or (nodes == 4.0)) & ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) & ((tol >= 0.0) and (tol <= 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # zeroth iterate (option zeroth)
    _c0 = zeroth(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_c, g_s, q_r_td)
    if _c0[5] != STATUS_OK:
        return fail(out, _c0[5])
    z_b_q_r = _c0[0]
    z_b_q_th = _c0[1]
    z_b_q_thd = _c0[2]
    z_lo_q_th = _c0[3]
    z_lo_q_thd = _c0[4]
    # compression half, k_c (report 5.2.1)
    _c1 = (schwind_compression(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, c, z_b_q_r, z_b_q_th,
        z_b_q_thd, nodes, iterations, tol))
    if _c1[6] != STATUS_OK:
        return fail(out, _c1[6])
    t_half = _c1[0]
    end_q_r = _c1[1]
    end_q_rd = _c1[2]
    end_q_th = _c1[3]
    end_q_thd = _c1[4]
    passes = _c1[5]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, passes,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def iterative_compression_zeroth_geyer(x, p, out):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Report equations: 29, 30, 31, 32, 114, 115, 116, 117, 118, 123.

    Runs the shared body :func:`iterative_compression_zeroth_shared` with zeroth_geyer.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, g_s, c, nodes, iterations, tol); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments:
        q_r_td: touchdown leg length q_r_td [m], 0 < q_r_td <= l0
        q_rd_td: touchdown leg length rate q_rd_td [m/s] (negative: compressing)
        q_th_td: touchdown leg angle q_th_td [rad], |q_th_td| < pi/2
        q_thd_td: touchdown leg angle rate q_thd_td [rad/s]
        m: body mass m [kg], > 0
        l0: rest leg length l0 [m], > 0
        k_c: leg stiffness while compressing k_c [N/m], > 0
        g_s: gravitational acceleration in stance, positive (pointing down) g_s [m/s^2], > 0
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        nodes: option nodes: Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point
            (41)): 0 = 1, 1 = 2, 2 = 3, 3 = 4, 4 = 6
        iterations: option iterations: Picard passes per half-stance (0 = the zeroth iterate) in [0, 100]
        tol: option tol: stop when no node value moves by more than tol (relative; 0 = run every pass) in [0,
            1]

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
    return iterative_compression_zeroth_shared(x, p, out, zeroth_geyer)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_compression_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_compression_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_compression_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_compression_zeroth_held(x, p, out):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Runs the shared body :func:`iterative_compression_zeroth_shared` with zeroth_held.
    Equations, arguments, returns and status: those of
    :func:`iterative_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_compression_zeroth_shared(x, p, out, zeroth_held)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_compression_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_compression_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_compression_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type0(x, p, out):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Runs the shared body :func:`iterative_compression_zeroth_shared` with zeroth_gravity_type0.
    Equations, arguments, returns and status: those of
    :func:`iterative_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_compression_zeroth_shared(x, p, out, zeroth_gravity_type0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_compression_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_compression_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type1(x, p, out):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Runs the shared body :func:`iterative_compression_zeroth_shared` with zeroth_gravity_type1.
    Equations, arguments, returns and status: those of
    :func:`iterative_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_compression_zeroth_shared(x, p, out, zeroth_gravity_type1)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_compression_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_compression_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type2(x, p, out):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Runs the shared body :func:`iterative_compression_zeroth_shared` with zeroth_gravity_type2.
    Equations, arguments, returns and status: those of
    :func:`iterative_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_compression_zeroth_shared(x, p, out, zeroth_gravity_type2)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_compression_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_compression_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type3(x, p, out):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Runs the shared body :func:`iterative_compression_zeroth_shared` with zeroth_gravity_type3.
    Equations, arguments, returns and status: those of
    :func:`iterative_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_compression_zeroth_shared(x, p, out, zeroth_gravity_type3)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_compression_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_compression_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type4(x, p, out):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Runs the shared body :func:`iterative_compression_zeroth_shared` with zeroth_gravity_type4.
    Equations, arguments, returns and status: those of
    :func:`iterative_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_compression_zeroth_shared(x, p, out, zeroth_gravity_type4)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_compression_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_compression_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type5(x, p, out):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Runs the shared body :func:`iterative_compression_zeroth_shared` with zeroth_gravity_type5.
    Equations, arguments, returns and status: those of
    :func:`iterative_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_compression_zeroth_shared(x, p, out, zeroth_gravity_type5)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_compression_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_compression_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_compression_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_compression_zeroth_geyer_vs(x, p, out):
    """Iterative compression half (touchdown to bottom, k_c; converging form): touchdown state -> bottom
    state.

    Runs the shared body :func:`iterative_compression_zeroth_shared` with zeroth_geyer_vs.
    Equations, arguments, returns and status: those of
    :func:`iterative_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_compression_zeroth_shared(x, p, out, zeroth_geyer_vs)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_compression_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_compression_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if one row),
    OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_compression_zeroth_geyer_vs(row(X, i), p, row(OUT, i))
