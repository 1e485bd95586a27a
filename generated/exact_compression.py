# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/exact.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   exact_stance.py sha256:ffbd69c8753c546e
# ----------------------------------------------------------------------------------------------
"""Exact compression half (touchdown to bottom, k_c; DOP853 integration) (report section 2.2): touchdown ->
bottom."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .exact_stance import compression

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan


@njit(cache=True, error_model="numpy")
def exact_compression(x, p, out):
    """Exact compression half (touchdown to bottom, k_c; DOP853 integration): touchdown state -> bottom state.

    Report equations: 2, 3.

    Role kernel: reads x = (q_r_td, q_rd_td, q_th_td, q_thd_td) and the parameter record
    p = (m, l0, k_c, g_s, q_r_lo, c, rtol, atol); writes the outputs below into out, in order, and returns
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
        q_r_lo: liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0
        c: leg damping, the radial force -c dq_r/dt in stance (0: a lossless leg) c [N s/m], >= 0
        rtol: option rtol: relative tolerance of the DOP853 integration in [1e-14, 0.001]
        atol: option atol: absolute tolerance of the DOP853 integration in [1e-16, 0.001]

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
    (q_r_td, q_rd_td, q_th_td, q_thd_td,) = load(x, 0, 1, 2, 3)
    (m, l0, k_c, g_s, q_r_lo, c, rtol, atol,) = load(p, 0, 1, 2, 3, 4, 5, 6, 7)
    # inputs: finite and inside their domains
    if not (all_finite((q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, c, rtol, atol,))
            & ((q_r_td <= l0) and (q_r_td > 0.0)) & ((abs(q_th_td) < (0.5)*math.pi)) & ((m > 0.0)) & ((l0
            > 0.0)) & ((k_c > 0.0)) & ((g_s > 0.0)) & ((q_r_lo <= l0) and (q_r_lo > 0.0)) & ((c >= 0.0))
            & ((rtol >= 1e-14) and (rtol <= 0.001)) & ((atol >= 1e-16) and (atol <= 0.001))):
        return fail(out, STATUS_INVALID_INPUT)
    # the exact half (exact_stance)
    _c0 = compression(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, c, rtol, atol)
    if _c0[5] != STATUS_OK:
        return fail(out, _c0[5])
    t_half = _c0[0]
    end_q_r = _c0[1]
    end_q_rd = _c0[2]
    end_q_th = _c0[3]
    end_q_thd = _c0[4]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def exact_compression_rows(X, P, OUT, STATUS):
    """Rows of :func:`exact_compression` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    n, last, p = X.shape[0], P.shape[0] - 1, carray(stack(8), 8)
    for b in range(last + 1):
        store(p, load(row(P, b), 0, 1, 2, 3, 4, 5, 6, 7))
        for i in range(b, n if b == last else min(b + 1, n)):
            STATUS[i] = exact_compression(row(X, i), p, row(OUT, i))
