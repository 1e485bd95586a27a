# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/maps/iterative_report.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:cd017e56afa49b84
#   geyer.py sha256:d4de65ad7b7743ae
#   geyer_vs.py sha256:2938ab68f64ec8b9
#   gravity_type0.py sha256:aeeaedd4e957536b
#   gravity_type1.py sha256:0c9da4f0c6ce0a10
#   gravity_type2.py sha256:a9520b2072c5248a
#   gravity_type3.py sha256:f6ec00956f584345
#   gravity_type4.py sha256:0434fb7f17ccb53b
#   gravity_type5.py sha256:98f4266d17071a0b
#   iterative.py sha256:4337c496c76156d9
#   iterative_report.py sha256:70ba3810f201bca7
# ----------------------------------------------------------------------------------------------
"""Iterative compression half as printed (touchdown to bottom, k_c) (report section 5.2.1): touchdown ->
bottom."""

import math

import numpy as np
from numba import carray, njit

from .support import fail, finite, into_rows, row, stack
from .geyer import geyer_stance
from .geyer_vs import geyer_vs_stance
from .gravity_type0 import gravity_type0_stance
from .gravity_type1 import gravity_type1_stance
from .gravity_type2 import gravity_type2_stance
from .gravity_type3 import gravity_type3_stance
from .gravity_type4 import gravity_type4_stance
from .gravity_type5 import gravity_type5_stance
from .iterative import zeroth_held
from .iterative_report import report_compression

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_INVALID_INPUT, STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_NUMERICAL_RANGE

NAN = math.nan


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_geyer(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

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
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, g_s, variant, iterations, bottom_length) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate: Geyer et al.'s approximate stance map
    _x0 = carray(stack(4), 4)
    (_x0[0], _x0[1], _x0[2], _x0[3],) = (q_r_td, q_rd_td, q_th_td, q_thd_td,)
    _p0 = carray(stack(7), 7)
    (_p0[0], _p0[1], _p0[2], _p0[3], _p0[4], _p0[5], _p0[6],) = (m, l0, k_c, g_s, NAN, q_r_td, q_r_td,)
    _o0 = carray(stack(10), 10)
    _c0 = geyer_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    z_b_q_r = _o0[2]
    z_b_q_th = _o0[4]
    z_b_q_thd = _o0[5]
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
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    (out[0], out[1], out[2], out[3], out[4],) = (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_geyer_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_geyer` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = iterative_report_compression_zeroth_geyer(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_held(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Arguments, returns and status: the same as :func:`iterative_report_compression_zeroth_geyer`'s.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, g_s, variant, iterations, bottom_length) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate: held
    _c0 = zeroth_held(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s)
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
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    (out[0], out[1], out[2], out[3], out[4],) = (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_held_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_held` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = iterative_report_compression_zeroth_held(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type0(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Arguments, returns and status: the same as :func:`iterative_report_compression_zeroth_geyer`'s.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, g_s, variant, iterations, bottom_length) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate: Gravity correction type 0 (leg length l0)
    _x0 = carray(stack(4), 4)
    (_x0[0], _x0[1], _x0[2], _x0[3],) = (q_r_td, q_rd_td, q_th_td, q_thd_td,)
    _p0 = carray(stack(11), 11)
    (_p0[0], _p0[1], _p0[2], _p0[3], _p0[4], _p0[5], _p0[6], _p0[7], _p0[8], _p0[9], _p0[10],) = (m, l0, k_c,
        g_s, NAN, q_r_td, q_r_td, 0.0, 2.0, 1.0, 0.0,)
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type0_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    z_b_q_r = _o0[2]
    z_b_q_th = _o0[4]
    z_b_q_thd = _o0[5]
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
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    (out[0], out[1], out[2], out[3], out[4],) = (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type0_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type0` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = (iterative_report_compression_zeroth_gravity_type0(row(X, i), row(P, min(i, last)),
            row(OUT, i)))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type1(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Arguments, returns and status: the same as :func:`iterative_report_compression_zeroth_geyer`'s.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, g_s, variant, iterations, bottom_length) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate: Gravity correction type 1 (leg length (l0 + q_r_b)/2)
    _x0 = carray(stack(4), 4)
    (_x0[0], _x0[1], _x0[2], _x0[3],) = (q_r_td, q_rd_td, q_th_td, q_thd_td,)
    _p0 = carray(stack(11), 11)
    (_p0[0], _p0[1], _p0[2], _p0[3], _p0[4], _p0[5], _p0[6], _p0[7], _p0[8], _p0[9], _p0[10],) = (m, l0, k_c,
        g_s, NAN, q_r_td, q_r_td, 0.0, 2.0, 100.0, 1e-12,)
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type1_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    z_b_q_r = _o0[2]
    z_b_q_th = _o0[4]
    z_b_q_thd = _o0[5]
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
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    (out[0], out[1], out[2], out[3], out[4],) = (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type1_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type1` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = (iterative_report_compression_zeroth_gravity_type1(row(X, i), row(P, min(i, last)),
            row(OUT, i)))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type2(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Arguments, returns and status: the same as :func:`iterative_report_compression_zeroth_geyer`'s.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, g_s, variant, iterations, bottom_length) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate: Gravity correction type 2 (average leg length)
    _x0 = carray(stack(4), 4)
    (_x0[0], _x0[1], _x0[2], _x0[3],) = (q_r_td, q_rd_td, q_th_td, q_thd_td,)
    _p0 = carray(stack(12), 12)
    (_p0[0], _p0[1], _p0[2], _p0[3], _p0[4], _p0[5], _p0[6], _p0[7], _p0[8], _p0[9], _p0[10], _p0[11],) = (m,
        l0, k_c, g_s, NAN, q_r_td, q_r_td, 0.0, 2.0, 0.0, 100.0, 1e-12,)
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type2_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    z_b_q_r = _o0[2]
    z_b_q_th = _o0[4]
    z_b_q_thd = _o0[5]
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
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    (out[0], out[1], out[2], out[3], out[4],) = (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type2_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type2` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = (iterative_report_compression_zeroth_gravity_type2(row(X, i), row(P, min(i, last)),
            row(OUT, i)))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type3(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Arguments, returns and status: the same as :func:`iterative_report_compression_zeroth_geyer`'s.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, g_s, variant, iterations, bottom_length) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate: Gravity correction type 3 (trapezoid on [t_i, t_f])
    _x0 = carray(stack(4), 4)
    (_x0[0], _x0[1], _x0[2], _x0[3],) = (q_r_td, q_rd_td, q_th_td, q_thd_td,)
    _p0 = carray(stack(11), 11)
    (_p0[0], _p0[1], _p0[2], _p0[3], _p0[4], _p0[5], _p0[6], _p0[7], _p0[8], _p0[9], _p0[10],) = (m, l0, k_c,
        g_s, NAN, q_r_td, q_r_td, 0.0, 1.0, 100.0, 1e-12,)
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type3_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    z_b_q_r = _o0[2]
    z_b_q_th = _o0[4]
    z_b_q_thd = _o0[5]
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
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    (out[0], out[1], out[2], out[3], out[4],) = (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type3_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type3` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = (iterative_report_compression_zeroth_gravity_type3(row(X, i), row(P, min(i, last)),
            row(OUT, i)))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type4(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Arguments, returns and status: the same as :func:`iterative_report_compression_zeroth_geyer`'s.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, g_s, variant, iterations, bottom_length) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate: Gravity correction type 4 (average leg length on [t_i, t_f])
    _x0 = carray(stack(4), 4)
    (_x0[0], _x0[1], _x0[2], _x0[3],) = (q_r_td, q_rd_td, q_th_td, q_thd_td,)
    _p0 = carray(stack(12), 12)
    (_p0[0], _p0[1], _p0[2], _p0[3], _p0[4], _p0[5], _p0[6], _p0[7], _p0[8], _p0[9], _p0[10], _p0[11],) = (m,
        l0, k_c, g_s, NAN, q_r_td, q_r_td, 0.0, 1.0, 0.0, 100.0, 1e-12,)
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type4_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    z_b_q_r = _o0[2]
    z_b_q_th = _o0[4]
    z_b_q_thd = _o0[5]
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
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    (out[0], out[1], out[2], out[3], out[4],) = (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type4_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type4` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = (iterative_report_compression_zeroth_gravity_type4(row(X, i), row(P, min(i, last)),
            row(OUT, i)))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type5(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Arguments, returns and status: the same as :func:`iterative_report_compression_zeroth_geyer`'s.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, g_s, variant, iterations, bottom_length) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate: Gravity correction type 5 (time-varying momentum)
    _x0 = carray(stack(4), 4)
    (_x0[0], _x0[1], _x0[2], _x0[3],) = (q_r_td, q_rd_td, q_th_td, q_thd_td,)
    _p0 = carray(stack(9), 9)
    (_p0[0], _p0[1], _p0[2], _p0[3], _p0[4], _p0[5], _p0[6], _p0[7], _p0[8],) = (m, l0, k_c, g_s, NAN, q_r_td,
        q_r_td, 100.0, 1e-12,)
    _o0 = carray(stack(12), 12)
    _c0 = gravity_type5_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    z_b_q_r = _o0[2]
    z_b_q_th = _o0[4]
    z_b_q_thd = _o0[5]
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
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    (out[0], out[1], out[2], out[3], out[4],) = (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_gravity_type5_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_gravity_type5` (serial, nogil): ``X[i], P[i] (P[0]
    if one row), OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = (iterative_report_compression_zeroth_gravity_type5(row(X, i), row(P, min(i, last)),
            row(OUT, i)))


@njit(cache=True, error_model="numpy")
def iterative_report_compression_zeroth_geyer_vs(x, p, out):
    """Iterative compression half as printed (touchdown to bottom, k_c): touchdown state -> bottom state.

    Report equations: 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 128, 129, 130, 131,
    132, 133, 134, 135, 154.

    Arguments, returns and status: the same as :func:`iterative_report_compression_zeroth_geyer`'s.
    """
    # Total ops: 0
    (q_r_td, q_rd_td, q_th_td, q_thd_td) = (x[0], x[1], x[2], x[3])
    (m, l0, k_c, g_s, variant, iterations, bottom_length) = (p[0], p[1], p[2], p[3], p[4], p[5], p[6])
    # inputs: finite and inside their domains
    if not (math.isfinite(q_r_td) and math.isfinite(q_rd_td) and math.isfinite(q_th_td)
            and math.isfinite(q_thd_td) and math.isfinite(m) and math.isfinite(l0) and math.isfinite(k_c)
            and math.isfinite(g_s) and math.isfinite(variant) and math.isfinite(iterations)
            and math.isfinite(bottom_length) and ((q_r_td <= l0) and (q_r_td > 0.0)) and ((abs(q_th_td)
            < (0.5)*math.pi)) and ((m > 0.0)) and ((l0 > 0.0)) and ((k_c > 0.0)) and ((g_s > 0.0))
            and ((variant == 0.0) or (variant == 1.0)) and ((iterations == math.floor(iterations))
            and (iterations >= 0.0) and (iterations <= 100.0)) and ((bottom_length == 0.0) or (bottom_length
            == 1.0))):
        return fail(out, STATUS_INVALID_INPUT)
    # q_rd_td < 0
    if not ((q_rd_td < 0.0)):
        return fail(out, STATUS_TOUCHDOWN_NOT_COMPRESSING)
    # zeroth iterate: Simple variable-stiffness map (Geyer et al. per half)
    _x0 = carray(stack(4), 4)
    (_x0[0], _x0[1], _x0[2], _x0[3],) = (q_r_td, q_rd_td, q_th_td, q_thd_td,)
    _p0 = carray(stack(12), 12)
    (_p0[0], _p0[1], _p0[2], _p0[3], _p0[4], _p0[5], _p0[6], _p0[7], _p0[8], _p0[9], _p0[10], _p0[11],) = (m,
        l0, k_c, k_c, g_s, NAN, q_r_td, q_r_td, 2.0, 0.0, 100.0, 1e-12,)
    _o0 = carray(stack(13), 13)
    _c0 = geyer_vs_stance(_x0, _p0, _o0)
    if _c0 != STATUS_OK:
        return fail(out, _c0)
    z_b_q_r = _o0[2]
    z_b_q_th = _o0[4]
    z_b_q_thd = _o0[5]
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
    if not (math.isfinite(t_half) and math.isfinite(end_q_r) and math.isfinite(end_q_rd)
            and math.isfinite(end_q_th) and math.isfinite(end_q_thd)):
        return fail(out, STATUS_NUMERICAL_RANGE)
    (out[0], out[1], out[2], out[3], out[4],) = (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd,)
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def iterative_report_compression_zeroth_geyer_vs_rows(X, P, OUT, STATUS):
    """Rows of :func:`iterative_report_compression_zeroth_geyer_vs` (serial, nogil): ``X[i], P[i] (P[0] if one
    row), OUT[i] -> STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = iterative_report_compression_zeroth_geyer_vs(row(X, i), row(P, min(i, last)), row(OUT, i))
