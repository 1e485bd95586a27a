# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/exact.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   runtime/exact/__init__.py sha256:b5581c4eb9fb8f73
#   runtime/exact/compiled.py sha256:f1ea68408082b7bb
#   runtime/exact/dop853.py sha256:6f313c10a1dd1ef4
#   runtime/exact/jacobian.py sha256:079e967891f96aa1
#   runtime/exact/kernels.py sha256:39d1598d210616fc
#   runtime/exact/reference.py sha256:1a2d2771848fe471
#   generated/flight.py sha256:8b20bd5230ccfe19
#   generated/maps_index.py sha256:ea8038b15fb7ac02
#   generated/slip_model.py sha256:1a04cccc79c2015a
# ----------------------------------------------------------------------------------------------
"""Exact decompression half (bottom to liftoff, k_d; DOP853 integration) (report section 2.2): bottom ->
liftoff."""

import math

import numpy as np
from numba import njit, prange
from slipmaps.runtime.exact.kernels import decompression

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_NUMERICAL_RANGE

NAN = math.nan
_NAN5 = (NAN,) * 5


@njit(cache=True, error_model="numpy")
def exact_decompression(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, rtol, atol):
    """Exact decompression half (bottom to liftoff, k_d; DOP853 integration): bottom state -> liftoff state.

    Report equations: 2, 3.

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
        rtol: option rtol: relative tolerance of the DOP853 integration in [1e-14, 0.001]
        atol: option atol: absolute tolerance of the DOP853 integration in [1e-16, 0.001]

    Returns a tuple:
        t_half: time from the start state to the end state [s]
        end_q_r: leg length [m]
        end_q_rd: leg length rate [m/s]
        end_q_th: leg angle from the vertical, counterclockwise positive [rad]
        end_q_thd: leg angle rate [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN.
    """
    # Total ops: 0
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_b) and math.isfinite(q_rd_b) and math.isfinite(q_th_b)
            and math.isfinite(q_thd_b) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_d)
            and math.isfinite(g_s) and math.isfinite(q_r_lo) and math.isfinite(rtol) and math.isfinite(atol)
            and ((q_r_b > 0.0)) and ((abs(q_th_b) < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_d
            > 0.0)) and ((g_s > 0.0)) and ((q_r_lo <= l0) and (q_r_lo > 0.0)) and ((rtol >= 1e-14) and (rtol
            <= 0.001)) and ((atol >= 1e-16) and (atol <= 0.001))):
        return _NAN5 + (STATUS_INVALID_INPUT,)
    # runtime/exact/kernels.py
    _c0 = decompression(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, rtol, atol)
    if _c0[5] != STATUS_OK:
        return _NAN5 + (_c0[5],)
    t_half = _c0[0]
    end_q_r = _c0[1]
    end_q_rd = _c0[2]
    end_q_th = _c0[3]
    end_q_thd = _c0[4]
    # every output finite, or the inputs were far outside a physical range
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return _NAN5 + (STATUS_NUMERICAL_RANGE,)
    return (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, STATUS_OK)


@njit(cache=True, parallel=True, error_model="numpy")
def exact_decompression_batch(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, rtol, atol, out,
        status):
    """Parallel batch form of :func:`exact_decompression`.

    Row arguments (1-D float64 arrays of equal length n, any stride): q_r_b, q_rd_b, q_th_b, q_thd_b.
    Scalar arguments shared by every row: m, l0, k_d, g_s, q_r_lo, rtol, atol.
    Writes output j of row i to ``out[i, j]`` (shape (n, 5); the columns are the outputs of
    :func:`exact_decompression`, in order) and its status code to ``status[i]`` (int64).
    """
    for i in prange(out.shape[0]):
        res = (exact_decompression(q_r_b[i], q_rd_b[i], q_th_b[i], q_thd_b[i], m, l0, k_d, g_s, q_r_lo, rtol,
            atol))
        (out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4], status[i]) = res
