"""The compiled side of a swing-leg policy (:mod:`.swing`): its tables' interpolation and the
touchdown of a leg whose angle follows a table of the time since the apex.

A policy row is a table of ``count`` knots in increasing time (arrays padded with NaN to a common
width): the touchdown time ``t`` [s] after the apex and a control's value ``y`` at each knot. Between
knots a control is the cubic Hermite interpolant with the slopes of the parabola through each knot
and its two neighbours (the three-point, "Bessel", slopes; at an end the parabola through the first
or last three knots): exact for a quadratic, an error of third order in the knot spacing; one knot
holds the value, two are joined by a line. Before the first knot and after the last one the end
value is held.

The touchdown (:func:`touchdown_rows`): the foot of a leg of length ``q`` [m] at angle theta(t) from
the vertical under a body falling from the apex height ``h`` [m] is at h - g t^2 / 2 - q cos theta(t)
above the apex's ground; it meets a ground ``ground`` [m] (relative to the apex's) at the first t
where that height reaches it. Before the first knot and after the last (the held end angles) the
root is in closed form; between knots the first interval whose end is at or below the ground is
bisected to the last bit (the height is above the ground at every knot before it).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

__all__ = [
    "IN_RANGE",
    "ABOVE_RANGE",
    "BELOW_RANGE",
    "NO_POLICY",
    "slopes_rows",
    "evaluate_rows",
    "touchdown_rows",
]

#: A touchdown this close to an end knot (relative) is at the knot: in the table.
_EDGE = 1e-12
#: Where a touchdown falls in its table: between its first and last knots, before the first knot
#: (a ground higher than the table's), after the last (lower), or the row has no knot.
IN_RANGE, ABOVE_RANGE, BELOW_RANGE, NO_POLICY = 0, 1, 2, 3


@njit(cache=True, error_model="numpy")
def _slopes(t, y, count, m):
    """The three-point slopes of the knots ``t[:count]``, ``y[:count]`` into ``m``."""
    if count == 1:
        m[0] = 0.0
        return
    if count == 2:
        d = (y[1] - y[0]) / (t[1] - t[0])
        m[0] = d
        m[1] = d
        return
    for i in range(1, count - 1):
        h0 = t[i] - t[i - 1]
        h1 = t[i + 1] - t[i]
        d0 = (y[i] - y[i - 1]) / h0
        d1 = (y[i + 1] - y[i]) / h1
        m[i] = (h1 * d0 + h0 * d1) / (h0 + h1)
    h0 = t[1] - t[0]
    h1 = t[2] - t[1]
    d0 = (y[1] - y[0]) / h0
    d1 = (y[2] - y[1]) / h1
    m[0] = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1)
    n = count - 1
    h0 = t[n - 1] - t[n - 2]
    h1 = t[n] - t[n - 1]
    d0 = (y[n - 1] - y[n - 2]) / h0
    d1 = (y[n] - y[n - 1]) / h1
    m[n] = ((2.0 * h1 + h0) * d1 - h1 * d0) / (h0 + h1)


@njit(cache=True, error_model="numpy")
def _value(t, y, m, count, x):
    """The interpolant of one row at time ``x`` (module docstring)."""
    if count == 0:
        return math.nan
    if x <= t[0]:
        return y[0]
    if x >= t[count - 1]:
        return y[count - 1]
    lo, hi = 0, count - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if t[mid] <= x:
            lo = mid
        else:
            hi = mid
    h = t[hi] - t[lo]
    s = (x - t[lo]) / h
    s2 = s * s
    s3 = s2 * s
    return (
        (2.0 * s3 - 3.0 * s2 + 1.0) * y[lo]
        + (s3 - 2.0 * s2 + s) * h * m[lo]
        + (-2.0 * s3 + 3.0 * s2) * y[hi]
        + (s3 - s2) * h * m[hi]
    )


@njit(cache=True, error_model="numpy", parallel=True)
def slopes_rows(T, Y, counts, M):
    """:func:`_slopes` of every row of the tables ``T``, ``Y`` (rows x knots) into ``M``."""
    for r in prange(T.shape[0]):
        if counts[r] > 0:
            _slopes(T[r], Y[r], counts[r], M[r])


@njit(cache=True, error_model="numpy")
def evaluate_rows(T, Y, M, counts, x, out):
    """The interpolant at each time ``x[i]`` into ``out[i]``: of table row i, or of the one row when the
    tables have one."""
    last = T.shape[0] - 1
    for i in range(x.shape[0]):
        r = min(i, last)
        out[i] = _value(T[r], Y[r], M[r], counts[r], x[i])


@njit(cache=True, error_model="numpy")
def _height(h, g, q, ground, t, theta):
    return h - 0.5 * g * t * t - q * math.cos(theta) - ground


@njit(cache=True, error_model="numpy")
def _held(h, g, q, ground, theta):
    """The time the foot of a leg held at ``theta`` meets the ground (NaN when it is below it at the
    apex already)."""
    a = h - q * math.cos(theta) - ground
    return math.sqrt(2.0 * a / g) if a >= 0.0 else math.nan


@njit(cache=True, error_model="numpy")
def touchdown_rows(h, ground, g, q, T, A, MA, counts, t_out, angle_out, where, knot):
    """Per row: the touchdown time ``t_out`` [s] and angle ``angle_out`` [rad] of the leg whose angle
    follows the table ``T``, ``A`` (slopes ``MA``) from apex height ``h[r]`` onto ``ground[r]``,
    ``where`` the touchdown falls (:data:`IN_RANGE`, ...) and ``knot`` the knot that begins its
    interval (-1 outside the table); module docstring. A foot below the ground at the apex gives
    t = NaN and the first knot's angle (the plant then reports the failure). With one table row,
    every apex and ground of ``h``, ``ground`` flies that one policy."""
    last = T.shape[0] - 1
    for r in range(h.shape[0]):
        k = min(r, last)
        n = counts[k]
        t, a, m = T[k], A[k], MA[k]
        knot[r] = -1
        if n == 0:
            t_out[r] = math.nan
            angle_out[r] = math.nan
            where[r] = NO_POLICY
            continue
        # before the first knot: the first angle held (a root at the knot, to round-off, is in the table)
        t0 = _held(h[r], g, q, ground[r], a[0])
        if not t0 > t[0] * (1.0 - _EDGE):
            t_out[r] = t0
            angle_out[r] = a[0]
            where[r] = ABOVE_RANGE
            continue
        if t0 <= t[0]:
            t_out[r] = t0
            angle_out[r] = a[0]
            where[r] = IN_RANGE if n > 1 else ABOVE_RANGE
            knot[r] = 0 if n > 1 else -1
            continue
        found = -1
        for k in range(n - 1):
            if _height(h[r], g, q, ground[r], t[k + 1], a[k + 1]) <= 0.0:
                found = k
                break
        if found < 0:
            t_end = _held(h[r], g, q, ground[r], a[n - 1])
            t_out[r] = t_end
            angle_out[r] = a[n - 1]
            if n > 1 and t_end <= t[n - 1] * (1.0 + _EDGE):
                where[r] = IN_RANGE  # at the last knot, to round-off
                knot[r] = n - 2
            else:
                where[r] = BELOW_RANGE
            continue
        lo, hi = t[found], t[found + 1]
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid <= lo or mid >= hi:
                break
            if _height(h[r], g, q, ground[r], mid, _value(t, a, m, n, mid)) > 0.0:
                lo = mid
            else:
                hi = mid
        t_out[r] = hi
        angle_out[r] = _value(t, a, m, n, hi)
        where[r] = IN_RANGE
        knot[r] = found


def empty_slopes(T: np.ndarray) -> np.ndarray:
    """Slope arrays shaped like the tables ``T`` (NaN)."""
    return np.full_like(T, np.nan)
