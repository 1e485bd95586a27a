# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/model/kernels.py
# Template:  derive/templates/kernels.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
#   flight.py sha256:af908ea30b1fc141
#   geyer_vs.py sha256:ef01b987d9b927b3
#   slip_model.py sha256:4cc44e1baaa041ba
# ----------------------------------------------------------------------------------------------
"""The model's kernels the runtime calls by name (the index's MODEL), as role kernels."""

import math

import numpy as np
from numba import carray, njit

from .support import all_finite, fail, finite, into_rows, load, node_arrays, row, stack, store
from .flight import apex_to_touchdown, liftoff_to_apex
from .geyer_vs import bottom_quartic
from .slip_model import (cartesian_to_polar, max_step, polar_to_cartesian, stance_cartesian_rhs,
    stance_energy, stance_polar_rhs, stance_time_limit)

# The status codes are fixed constants (derive/status.py: append-only, never renumbered), so numba may
# freeze them into this module's cached machine code although its cache does not see status.py.
from .status import STATUS_OK, STATUS_NUMERICAL_RANGE

NAN = math.nan


@njit(cache=True, error_model="numpy")
def apex_to_touchdown_entry(x, p, out):
    """Ballistic descent from an apex to touchdown with the leg at q_r_td swinging from q_th_td at
    retraction_rate.

    Report equations: sec2.1-touchdown, sec2.2.2.

    Role kernel: reads x = (b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, retraction_rate) and the
    parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of flight.apex_to_touchdown, in x.

    Writes into out:
        touchdown_q_r: leg length [m]
        touchdown_q_rd: leg length rate [m/s]
        touchdown_q_th: leg angle from the vertical, counterclockwise positive [rad]
        touchdown_q_thd: leg angle rate [rad/s]
        t_flight: time from the apex to touchdown [s]
        foot_x: horizontal position of the toe at touchdown relative to the apex [m]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, retraction_rate,) = load(x, 0, 1, 2, 3, 4, 5, 6)
    # flight.apex_to_touchdown
    _c0 = apex_to_touchdown(b_y_apex, b_xd_apex, q_th_td, q_r_td, g_f, ground, retraction_rate)
    if _c0[6] != STATUS_OK:
        return fail(out, _c0[6])
    touchdown_q_r = _c0[0]
    touchdown_q_rd = _c0[1]
    touchdown_q_th = _c0[2]
    touchdown_q_thd = _c0[3]
    t_flight = _c0[4]
    foot_x = _c0[5]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((touchdown_q_r, touchdown_q_rd, touchdown_q_th, touchdown_q_thd, t_flight, foot_x,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (touchdown_q_r, touchdown_q_rd, touchdown_q_th, touchdown_q_thd, t_flight, foot_x,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def apex_to_touchdown_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`apex_to_touchdown_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = apex_to_touchdown_entry(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def liftoff_to_apex_entry(x, p, out):
    """Ballistic ascent from a polar liftoff state to the next apex.

    Report equations: sec2.1-apex, sec2.2.2.

    Role kernel: reads x = (q_r, q_rd, q_th, q_thd, g_f, direction) and the parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of flight.liftoff_to_apex, in x.

    Writes into out:
        apex_b_y: next apex height above the ground [m]
        apex_b_xd: next apex horizontal speed [m/s]
        t_flight: time from liftoff to the apex [s]
        dx_flight: horizontal distance travelled from liftoff to the apex [m]
        apex_b_x: horizontal position of the next apex relative to the toe [m]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (q_r, q_rd, q_th, q_thd, g_f, direction,) = load(x, 0, 1, 2, 3, 4, 5)
    # flight.liftoff_to_apex
    _c0 = liftoff_to_apex(q_r, q_rd, q_th, q_thd, g_f, direction)
    if _c0[5] != STATUS_OK:
        return fail(out, _c0[5])
    apex_b_y = _c0[0]
    apex_b_xd = _c0[1]
    t_flight = _c0[2]
    dx_flight = _c0[3]
    apex_b_x = _c0[4]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((apex_b_y, apex_b_xd, t_flight, dx_flight, apex_b_x,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (apex_b_y, apex_b_xd, t_flight, dx_flight, apex_b_x,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def liftoff_to_apex_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`liftoff_to_apex_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = liftoff_to_apex_entry(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def stance_polar_rhs_entry(x, p, out):
    """Polar stance vector field d/dt (q_r, q_rd, q_th, q_thd) from the Euler-Lagrange equations.

    Report equations: 1, 2, 3, sec2.2.1-polar.

    Role kernel: reads x = (q_r, q_rd, q_th, q_thd, m, l0, k, g_s) and the parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of slip_model.stance_polar_rhs, in x.

    Writes into out:
        d_q_r: dq_r/dt [m/s]
        d_q_rd: d^2q_r/dt^2 [m/s^2]
        d_q_th: dq_th/dt [rad/s]
        d_q_thd: d^2q_th/dt^2 [rad/s^2]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (q_r, q_rd, q_th, q_thd, m, l0, k, g_s,) = load(x, 0, 1, 2, 3, 4, 5, 6, 7)
    # slip_model.stance_polar_rhs
    _c0 = stance_polar_rhs(q_r, q_rd, q_th, q_thd, m, l0, k, g_s)
    d_q_r = _c0[0]
    d_q_rd = _c0[1]
    d_q_th = _c0[2]
    d_q_thd = _c0[3]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((d_q_r, d_q_rd, d_q_th, d_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (d_q_r, d_q_rd, d_q_th, d_q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def stance_polar_rhs_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`stance_polar_rhs_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = stance_polar_rhs_entry(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def stance_cartesian_rhs_entry(x, p, out):
    """Cartesian stance vector field d/dt (b_x, b_xd, b_y, b_yd), toe at the origin on flat ground.

    Report equations: sec2.2.1-cartesian.

    Role kernel: reads x = (b_x, b_xd, b_y, b_yd, m, l0, k, g_s) and the parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of slip_model.stance_cartesian_rhs, in x.

    Writes into out:
        d_b_x: db_x/dt [m/s]
        d_b_xd: d^2b_x/dt^2 [m/s^2]
        d_b_y: db_y/dt [m/s]
        d_b_yd: d^2b_y/dt^2 [m/s^2]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (b_x, b_xd, b_y, b_yd, m, l0, k, g_s,) = load(x, 0, 1, 2, 3, 4, 5, 6, 7)
    # slip_model.stance_cartesian_rhs
    _c0 = stance_cartesian_rhs(b_x, b_xd, b_y, b_yd, m, l0, k, g_s)
    d_b_x = _c0[0]
    d_b_xd = _c0[1]
    d_b_y = _c0[2]
    d_b_yd = _c0[3]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((d_b_x, d_b_xd, d_b_y, d_b_yd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (d_b_x, d_b_xd, d_b_y, d_b_yd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def stance_cartesian_rhs_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`stance_cartesian_rhs_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = stance_cartesian_rhs_entry(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def stance_energy_entry(x, p, out):
    """Total stance energy, the Hamiltonian (27) evaluated at p_r = m q_rd, p_th = m q_r^2 q_thd.

    Report equations: 27.

    Role kernel: reads x = (q_r, q_rd, q_th, q_thd, m, l0, k, g_s) and the parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of slip_model.stance_energy, in x.

    Writes into out:
        energy: total mechanical energy E (gravity potential zero at toe height) [J]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (q_r, q_rd, q_th, q_thd, m, l0, k, g_s,) = load(x, 0, 1, 2, 3, 4, 5, 6, 7)
    # slip_model.stance_energy
    _c0 = stance_energy(q_r, q_rd, q_th, q_thd, m, l0, k, g_s)
    energy = _c0
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((energy,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (energy,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def stance_energy_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`stance_energy_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = stance_energy_entry(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def polar_to_cartesian_entry(x, p, out):
    """Polar stance state -> Cartesian body state relative to the toe.

    Report equations: sec2.2-coordinates.

    Role kernel: reads x = (q_r, q_rd, q_th, q_thd) and the parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of slip_model.polar_to_cartesian, in x.

    Writes into out:
        out_b_x: b_x = -q_r sin q_th [m]
        out_b_xd: b_xd [m/s]
        out_b_y: b_y = q_r cos q_th [m]
        out_b_yd: b_yd [m/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (q_r, q_rd, q_th, q_thd,) = load(x, 0, 1, 2, 3)
    # slip_model.polar_to_cartesian
    _c0 = polar_to_cartesian(q_r, q_rd, q_th, q_thd)
    out_b_x = _c0[0]
    out_b_xd = _c0[1]
    out_b_y = _c0[2]
    out_b_yd = _c0[3]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((out_b_x, out_b_xd, out_b_y, out_b_yd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (out_b_x, out_b_xd, out_b_y, out_b_yd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def polar_to_cartesian_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`polar_to_cartesian_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = polar_to_cartesian_entry(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def cartesian_to_polar_entry(x, p, out):
    """Cartesian body state relative to the toe -> polar stance state (inverse of polar_to_cartesian).

    Report equations: sec2.2-coordinates.

    Role kernel: reads x = (b_x, b_xd, b_y, b_yd) and the parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of slip_model.cartesian_to_polar, in x.

    Writes into out:
        out_q_r: q_r [m]
        out_q_rd: q_rd [m/s]
        out_q_th: q_th = atan2(-b_x, b_y) [rad]
        out_q_thd: q_thd [rad/s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (b_x, b_xd, b_y, b_yd,) = load(x, 0, 1, 2, 3)
    # slip_model.cartesian_to_polar
    _c0 = cartesian_to_polar(b_x, b_xd, b_y, b_yd)
    out_q_r = _c0[0]
    out_q_rd = _c0[1]
    out_q_th = _c0[2]
    out_q_thd = _c0[3]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((out_q_r, out_q_rd, out_q_th, out_q_thd,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (out_q_r, out_q_rd, out_q_th, out_q_thd,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def cartesian_to_polar_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`cartesian_to_polar_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = cartesian_to_polar_entry(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def max_step_entry(x, p, out):
    """The step cap of a stance subphase with stiffness k: MAX_STEP_FRACTION of the shorter natural period.

    Role kernel: reads x = (m, l0, k, g_s) and the parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of slip_model.max_step, in x.

    Writes into out:
        step: the largest step of the integration [s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (m, l0, k, g_s,) = load(x, 0, 1, 2, 3)
    # slip_model.max_step
    _c0 = max_step(m, l0, k, g_s)
    step = _c0
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((step,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (step,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def max_step_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`max_step_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = max_step_entry(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def stance_time_limit_entry(x, p, out):
    """The stance time limit: T_MAX_PERIODS times the spring period of the softer spring plus the pendulum
    period.

    Role kernel: reads x = (m, l0, k_c, k_d, g_s) and the parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of slip_model.stance_time_limit, in x.

    Writes into out:
        t_max: the stance time limit [s]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (m, l0, k_c, k_d, g_s,) = load(x, 0, 1, 2, 3, 4)
    # slip_model.stance_time_limit
    _c0 = stance_time_limit(m, l0, k_c, k_d, g_s)
    t_max = _c0
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((t_max,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (t_max,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def stance_time_limit_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`stance_time_limit_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = stance_time_limit_entry(row(X, i), row(P, min(i, last)), row(OUT, i))


@njit(cache=True, error_model="numpy")
def bottom_quartic_entry(x, p, out):
    """Bottom leg length of (153): the compressing root of the quartic in (0, l0] (Newton).

    Report equations: 153.

    Role kernel: reads x = (p_b, E_ab, m, l0, k_c, g_s) and the parameter record
    p = (); writes the outputs below into out, in order, and returns
    the status (out all NaN unless OK).

    Arguments: those of geyer_vs.bottom_quartic, in x.

    Writes into out:
        q_r_b: bottom leg length of (153) [m]
        status: 0 (STATUS_OK) or the code of the first failed check; all other outputs are then NaN
            (returned).
    """
    # Total ops: 0
    (p_b, E_ab, m, l0, k_c, g_s,) = load(x, 0, 1, 2, 3, 4, 5)
    # geyer_vs.bottom_quartic
    _c0 = bottom_quartic(p_b, E_ab, m, l0, k_c, g_s)
    if _c0[1] != STATUS_OK:
        return fail(out, _c0[1])
    q_r_b = _c0[0]
    # every output finite, or the inputs were far outside a physical range
    if not (all_finite((q_r_b,))):
        return fail(out, STATUS_NUMERICAL_RANGE)
    store(out, (q_r_b,))
    return STATUS_OK


@njit(cache=True, nogil=True, error_model="numpy")
def bottom_quartic_entry_rows(X, P, OUT, STATUS):
    """Rows of :func:`bottom_quartic_entry` (serial, nogil): ``X[i], P[i] (P[0] if one row), OUT[i] ->
    STATUS[i]``."""
    last = P.shape[0] - 1
    for i in range(X.shape[0]):
        STATUS[i] = bottom_quartic_entry(row(X, i), row(P, min(i, last)), row(OUT, i))
