# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative_report.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   iterative.py sha256:6c68b56d8ea0aa73
#   iterative_report.py sha256:18114aff3d2f5d54
# ----------------------------------------------------------------------------------------------
"""Iterative compression half as printed (touchdown to bottom, k_c) (report section 5.2.1): touchdown ->
bottom."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .iterative import (zeroth_geyer, zeroth_geyer_vs, zeroth_gravity_type0, zeroth_gravity_type1,
    zeroth_gravity_type2, zeroth_gravity_type3, zeroth_gravity_type4, zeroth_gravity_type5, zeroth_held)
from .iterative_report import report_compression

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NUMERICAL_RANGE

NAN = math.nan


@njit(cache=True, error_model="numpy", inline="always")
def iterative_report_compression_zeroth_shared(x, p, out, zeroth):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    The body that 9 kernels share, each passing the kernel it calls as zeroth (derive/share.py):
    iterative_report_compression_zeroth_{geyer, held, gravity_type0, gravity_type1,
    gravity_type2, gravity_type3, gravity_type4, gravity_type5, geyer_vs}.

    Arguments, returns and status: those of the kernels, then zeroth.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, g_s, variant, iterations, bottom_length,) = load(p, 0, 1, 2, 3, 4, 5, 6)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, variant, iterations,
            bottom_length,)) & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m
            > 0.0)) & ((l0 > 0.0)) & ((k_c > 0.0)) & ((g_s > 0.0)) & ((variant == 0.0) or (variant == 1.0))
            & ((iterations == math.floor(iterations)) and (iterations >= 0.0) and (iterations <= 100.0))
            & ((bottom_length == 0.0) or (bottom_length == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate (option zeroth)
    _c0 = zeroth(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_c, g_s, q_r_td)
    if _c0[5] != STATUS_OK:
        return fail(out, _c0[5])
    z_b_q_r = _c0[0]
    z_b_q_th = _c0[1]
    z_b_q_thd = _c0[2]
    z_lo_q_th = _c0[3]
    z_lo_q_thd = _c0[4]
    # the compression half as printed
    _c1 = (report_compression(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, z_b_q_r, z_b_q_th,
        z_b_q_thd, variant, iterations, bottom_length))
    if _c1[6] != STATUS_OK:
        return fail(out, _c1[6])
    t_bottom = _c1[0]
    bottom_q_r = _c1[1]
    bottom_q_rd = _c1[2]
    bottom_q_th = _c1[3]
    bottom_q_thd = _c1[4]
    E_ab = _c1[5]
    # the bottom state
    t_half = t_bottom
    end_q_r = bottom_q_r
    end_q_rd = bottom_q_rd
    end_q_th = bottom_q_th
    end_q_thd = bottom_q_thd
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,))
    return STATUS_OK


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_geyer(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Runs the shared body :func:`iterative_report_compression_zeroth_shared` with zeroth_geyer.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, g_s, variant, iterations, bottom_length); writes the outputs below into out, in order,
    and returns
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
        variant: option variant: which mean-value form each step uses: 0 = integrand, 1 = factor
        iterations: option iterations: iterations n of each half's chain (0 = the zeroth iterate) in [0, 100]
        bottom_length: option bottom_length: the bottom leg length q_r_b the chains run to and from (section
            5.2, closing estimates): 0 = zeroth, 1 = eq153

    Writes into out:
        t_half: time from the start state to the end state [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    return iterative_report_compression_zeroth_shared(x, p, out, zeroth_geyer)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_compression_zeroth_geyer(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_held(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Runs the shared body :func:`iterative_report_compression_zeroth_shared` with zeroth_held.
    Equations, arguments, returns and status: those of
    :func:`iterative_report_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_compression_zeroth_shared(x, p, out, zeroth_held)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_compression_zeroth_held(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type0(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Runs the shared body :func:`iterative_report_compression_zeroth_shared` with
    zeroth_gravity_type0. Equations, arguments, returns and status: those of
    :func:`iterative_report_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_compression_zeroth_shared(x, p, out, zeroth_gravity_type0)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_compression_zeroth_gravity_type0(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type1(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Runs the shared body :func:`iterative_report_compression_zeroth_shared` with
    zeroth_gravity_type1. Equations, arguments, returns and status: those of
    :func:`iterative_report_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_compression_zeroth_shared(x, p, out, zeroth_gravity_type1)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_compression_zeroth_gravity_type1(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type2(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Runs the shared body :func:`iterative_report_compression_zeroth_shared` with
    zeroth_gravity_type2. Equations, arguments, returns and status: those of
    :func:`iterative_report_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_compression_zeroth_shared(x, p, out, zeroth_gravity_type2)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_compression_zeroth_gravity_type2(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type3(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Runs the shared body :func:`iterative_report_compression_zeroth_shared` with
    zeroth_gravity_type3. Equations, arguments, returns and status: those of
    :func:`iterative_report_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_compression_zeroth_shared(x, p, out, zeroth_gravity_type3)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_compression_zeroth_gravity_type3(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type4(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Runs the shared body :func:`iterative_report_compression_zeroth_shared` with
    zeroth_gravity_type4. Equations, arguments, returns and status: those of
    :func:`iterative_report_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_compression_zeroth_shared(x, p, out, zeroth_gravity_type4)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_compression_zeroth_gravity_type4(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type5(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Runs the shared body :func:`iterative_report_compression_zeroth_shared` with
    zeroth_gravity_type5. Equations, arguments, returns and status: those of
    :func:`iterative_report_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_compression_zeroth_shared(x, p, out, zeroth_gravity_type5)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_compression_zeroth_gravity_type5(row(X, i), p, row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_geyer_vs(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Runs the shared body :func:`iterative_report_compression_zeroth_shared` with
    zeroth_geyer_vs. Equations, arguments, returns and status: those of
    :func:`iterative_report_compression_zeroth_geyer`.
    """
    # Total ops: 0
    return iterative_report_compression_zeroth_shared(x, p, out, zeroth_geyer_vs)


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(7), 7)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = iterative_report_compression_zeroth_geyer_vs(row(X, i), p, row(OUT, i))
