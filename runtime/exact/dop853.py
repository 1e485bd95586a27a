"""A compiled embedded Dormand-Prince 8(5,3) integrator (DOP853) with dense output and events.

The algorithm is scipy's ``solve_ivp(method="DOP853")`` step by step, compiled with numba so that
an integration costs microseconds instead of milliseconds:

* coefficients: ``scipy.integrate._ivp.dop853_coefficients`` (read at import, frozen into the
  compiled code as constants);
* error norm: the 5th- and 3rd-order estimates combined as scipy's ``DOP853._estimate_error_norm``
  (Hairer, Norsett and Wanner, Solving ODEs I, section II.10), scale ``atol + rtol max(|y|, |y_new|)``;
* step-size controller: scipy's ``RungeKutta._step_impl`` (safety 0.9, factors 0.2 to 10, no growth
  after a rejection, failure below ``10 ulp(t)``), the step capped at ``max_step`` and clipped at
  ``t_bound``; initial step: scipy's ``select_initial_step``;
* dense output: the 7th-order interpolant of scipy's ``DOP853._dense_output_impl`` (three extra
  stages per interpolated step) evaluated as ``Dop853DenseOutput``;
* events: evaluated at the end of every step; an event whose function changes sign in the
  requested direction (scipy's ``find_active_events``: ``g <= 0 <= g_new`` upward,
  ``g >= 0 >= g_new`` downward) is located on the dense output by Brent's method (scipy's
  ``brentq``, ``xtol = rtol = 4 eps`` as in ``solve_ivp``). Every event is terminal: the earliest
  root ends the integration and its state is the interpolant's there.

Interfaces (every function ``@njit``; nothing raises):

* ``rhs(t, y, p, dy)``: writes dy/dt at ``(t, y)`` into ``dy``; ``p`` is any numba value (a tuple
  of parameters). Passed as an njit function (a dispatcher argument: numba compiles the integrator
  once per right-hand side and inlines the call; benchmarks/bench_exact.py measured it faster than
  a first-class function-pointer call).
* ``events(t, y, pe, g)``: writes the event function values into ``g`` (length of ``direction``);
  it may read only the first ``n_control`` components of y (the root finder interpolates those).
  ``direction[e]``: +1 a root where g[e] increases, -1 where it decreases, 0 either, NaN: event ``e``
  is not watched (one events function can serve several phases: one compiled integrator).
* :func:`solve`: integrates ``y0`` from ``t0`` until ``t_bound`` or the first event; returns
  ``(code, t_end, event, steps)`` and writes the end state into ``y_end``. ``code`` is
  :data:`FINISHED` (``t_bound`` reached), :data:`EVENT` (``event`` is its index) or :data:`FAILED`
  (step size below ``10 ulp(t)``, or a non-finite state), as ``solve_ivp``'s status 0 / 1 / -1;
  :data:`SAMPLED` when asked to stop at the sample (below).
* a sample: the interpolant at one time ``t_sample`` (as ``solve_ivp``'s dense output there),
  written into ``y_sample`` (its first ``len(y_sample)`` components) by the accepted step that
  reaches it, when ``t0 <= t_sample`` and ``t_sample`` comes before the event that ends the
  integration (at an event time: not sampled; at or before ``t_bound``: sampled). It changes
  neither the steps nor the events; ``y_sample`` is left as it is when not sampled;
  ``t_sample = inf`` samples nothing. With ``sample_ends`` the integration stops there
  (:data:`SAMPLED`, ``t_end = t_sample``, ``y_end`` the sample's first components too).

The state may have any length, so the same integrator carries augmented (variational) systems:
with ``n_control`` set to the length of the original state, the steps, events and original
components are exactly those of the plain integration, and the added components are the same
Runge-Kutta scheme applied to their equations (for variational equations: the derivative of the
discrete flow at those steps).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.extending import intrinsic
from scipy.integrate._ivp import dop853_coefficients as _coef
from scipy.integrate._ivp import rk as _rk

__all__ = ["EVENT", "FAILED", "FINISHED", "SAMPLED", "dense_eval", "solve", "static"]

N_STAGES = int(_coef.N_STAGES)  # 12 stages of the 8th-order step (the 13th row holds f_new)
N_STAGES_EXTENDED = int(_coef.N_STAGES_EXTENDED)  # 16 with the 3 extra stages of the interpolant
INTERPOLATOR_POWER = int(_coef.INTERPOLATOR_POWER)  # 7 coefficient rows of the dense output
A = np.ascontiguousarray(_coef.A, dtype=np.float64)
B = np.ascontiguousarray(_coef.B, dtype=np.float64)
C = np.ascontiguousarray(_coef.C, dtype=np.float64)
E3 = np.ascontiguousarray(_coef.E3, dtype=np.float64)
E5 = np.ascontiguousarray(_coef.E5, dtype=np.float64)
D = np.ascontiguousarray(_coef.D, dtype=np.float64)
SAFETY = float(_rk.SAFETY)
MIN_FACTOR = float(_rk.MIN_FACTOR)
MAX_FACTOR = float(_rk.MAX_FACTOR)
#: scipy's DOP853 controls the error of its 7th-order estimator: exponent -1/(7 + 1).
ERROR_ESTIMATOR_ORDER = int(_rk.DOP853.error_estimator_order)
ERROR_EXPONENT = -1.0 / (ERROR_ESTIMATOR_ORDER + 1)
#: Event roots: ``solve_ivp`` calls brentq with xtol = rtol = 4 eps (brentq's default maxiter 100).
ROOT_TOL = 4.0 * float(np.finfo(np.float64).eps)
ROOT_MAXITER = 100

FINISHED = 0
EVENT = 1
FAILED = -1
SAMPLED = 2

_JIT = {"cache": True, "error_model": "numpy"}
#: Functions taking ``rhs`` / ``events`` are specialised per right-hand side and compiled into their
#: (cached) callers; cached on their own, their Dispatcher-typed signatures would never hit the cache.
_GENERIC = {"error_model": "numpy"}


def static(fn):
    """A zero-argument njit-callable returning a handle of the njit function ``fn`` to pass to
    :func:`solve` as ``rhs`` or ``events`` from a cached kernel.

    ``solve(fn, ...)`` inside a ``cache=True`` kernel would lower the dispatcher ``fn`` as a
    pointer to a Python object (a "dynamic global": numba refuses to cache the kernel). The handle
    has the same numba type (the call is resolved at compile time, by type) and no run-time
    value: a null pointer.
    """

    @intrinsic
    def handle(typingctx):
        ty = types.Dispatcher(fn)

        def codegen(context, builder, signature, args):
            return context.get_constant_null(ty)

        return ty(), codegen

    return handle


@njit(**_JIT)
def _rms(x, scale, n):
    """scipy's ``norm(x / scale)`` over the first n components: the RMS norm."""
    s = 0.0
    for i in range(n):
        v = x[i] / scale[i]
        s += v * v
    return math.sqrt(s) / math.sqrt(n)


@njit(**_JIT)
def _stage_states(K, s, y, h, ys):
    """ys = y + h * (K[:s].T @ A[s, :s]): the state at which stage ``s`` is evaluated."""
    for i in range(y.shape[0]):
        acc = 0.0
        for j in range(s):
            acc += K[j, i] * A[s, j]
        ys[i] = y[i] + acc * h


@njit(**_GENERIC)
def initial_step(rhs, p, t0, y0, f0, t_bound, max_step, rtol, atol, n_control, y1, f1, scale):
    """scipy's ``select_initial_step`` (forward in time, error estimator order 7) on the first
    ``n_control`` components."""
    n = y0.shape[0]
    interval = abs(t_bound - t0)
    if interval == 0.0:
        return 0.0
    for i in range(n_control):
        scale[i] = atol + abs(y0[i]) * rtol
    d0 = _rms(y0, scale, n_control)
    d1 = _rms(f0, scale, n_control)
    h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
    h0 = min(h0, interval)
    for i in range(n):
        y1[i] = y0[i] + h0 * f0[i]
    rhs(t0 + h0, y1, p, f1)
    s = 0.0
    for i in range(n_control):
        v = (f1[i] - f0[i]) / scale[i]
        s += v * v
    d2 = math.sqrt(s) / math.sqrt(n_control) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / (ERROR_ESTIMATOR_ORDER + 1))
    return min(100.0 * h0, h1, interval, max_step)


@njit(**_GENERIC)
def _rk_step(rhs, p, t, y, f, h, K, y_new, ys):
    """One 8th-order step from (t, y) with slope f: y_new, and f_new in K[N_STAGES] (scipy's rk_step)."""
    n = y.shape[0]
    for i in range(n):
        K[0, i] = f[i]
    for s in range(1, N_STAGES):
        _stage_states(K, s, y, h, ys)
        rhs(t + C[s] * h, ys, p, K[s])
    for i in range(n):
        acc = 0.0
        for j in range(N_STAGES):
            acc += K[j, i] * B[j]
        y_new[i] = y[i] + h * acc
    rhs(t + h, y_new, p, K[N_STAGES])


@njit(**_JIT)
def _error_norm(K, h, y, y_new, rtol, atol, n):
    """scipy's ``DOP853._estimate_error_norm`` with scale atol + rtol max(|y|, |y_new|), over the
    first n components."""
    s5 = 0.0
    s3 = 0.0
    for i in range(n):
        scale = atol + max(abs(y[i]), abs(y_new[i])) * rtol
        e5 = 0.0
        e3 = 0.0
        for j in range(N_STAGES + 1):
            e5 += K[j, i] * E5[j]
            e3 += K[j, i] * E3[j]
        e5 /= scale
        e3 /= scale
        s5 += e5 * e5
        s3 += e3 * e3
    e5_2 = math.sqrt(s5) ** 2  # np.linalg.norm(err5) ** 2, as scipy computes it
    e3_2 = math.sqrt(s3) ** 2
    if e5_2 == 0.0 and e3_2 == 0.0:
        return 0.0
    return abs(h) * e5_2 / math.sqrt((e5_2 + 0.01 * e3_2) * n)


@njit(**_GENERIC)
def dense_coefficients(rhs, p, t_old, h, y_old, y, K, F, ys):
    """The interpolant of the step (t_old, y_old) -> (t_old + h, y): F (7, n), scipy's
    ``DOP853._dense_output_impl`` (K holds the step's 13 stages; 3 more are evaluated into it)."""
    n = y.shape[0]
    for s in range(N_STAGES + 1, N_STAGES_EXTENDED):
        _stage_states(K, s, y_old, h, ys)
        rhs(t_old + C[s] * h, ys, p, K[s])
    for i in range(n):
        dy = y[i] - y_old[i]
        F[0, i] = dy
        F[1, i] = h * K[0, i] - dy
        F[2, i] = 2.0 * dy - h * (K[N_STAGES, i] + K[0, i])
        for r in range(INTERPOLATOR_POWER - 3):
            acc = 0.0
            for j in range(N_STAGES_EXTENDED):
                acc += D[r, j] * K[j, i]
            F[3 + r, i] = h * acc


@njit(**_JIT)
def dense_eval(F, t_old, h, y_old, t, out, n):
    """The first n components of the interpolant at time t (scipy's ``Dop853DenseOutput``), written
    into ``out``."""
    x = (t - t_old) / h
    for i in range(n):
        acc = 0.0
        for j in range(INTERPOLATOR_POWER):
            acc += F[INTERPOLATOR_POWER - 1 - j, i]
            if j % 2 == 0:
                acc *= x
            else:
                acc *= 1.0 - x
        out[i] = acc + y_old[i]


@njit(**_GENERIC)
def _event_value(events, pe, i, F, t_old, h, y_old, t, ys, g, n_control):
    dense_eval(F, t_old, h, y_old, t, ys, n_control)
    events(t, ys, pe, g)
    return g[i]


@njit(**_GENERIC)
def event_root(events, pe, i, F, t_old, h, y_old, xa, xb, ys, g, n_control):
    """Root of event ``i`` on the interpolant between xa and xb (scipy's brentq, xtol = rtol = 4 eps);
    the events see the first ``n_control`` components."""
    xpre = xa
    xcur = xb
    xblk = 0.0
    fblk = 0.0
    spre = 0.0
    scur = 0.0
    fpre = _event_value(events, pe, i, F, t_old, h, y_old, xpre, ys, g, n_control)
    fcur = _event_value(events, pe, i, F, t_old, h, y_old, xcur, ys, g, n_control)
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    for _ in range(ROOT_MAXITER):
        if fpre != 0.0 and fcur != 0.0 and ((fpre < 0.0) != (fcur < 0.0)):
            xblk = xpre
            fblk = fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre = xcur
            xcur = xblk
            xblk = xpre
            fpre = fcur
            fcur = fblk
            fblk = fpre
        delta = (ROOT_TOL + ROOT_TOL * abs(xcur)) / 2.0
        sbis = (xblk - xcur) / 2.0
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:
                stry = -fcur * (xcur - xpre) / (fcur - fpre)  # interpolate
            else:
                dpre = (fpre - fcur) / (xpre - xcur)  # extrapolate
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2.0 * abs(stry) < min(abs(spre), 3.0 * abs(sbis) - delta):
                spre = scur
                scur = stry
            else:
                spre = sbis
                scur = sbis
        else:
            spre = sbis
            scur = sbis
        xpre = xcur
        fpre = fcur
        if abs(scur) > delta:
            xcur += scur
        else:
            xcur += delta if sbis > 0.0 else -delta
        fcur = _event_value(events, pe, i, F, t_old, h, y_old, xcur, ys, g, n_control)
    return xcur


@njit(**_JIT)
def _finite(y):
    for i in range(y.shape[0]):
        if not math.isfinite(y[i]):
            return False
    return True


@njit(**_GENERIC)
def solve(
    rhs,
    p,
    events,
    pe,
    direction,
    t0,
    y0,
    t_bound,
    rtol,
    atol,
    max_step,
    n_control,
    y_end,
    t_sample,
    y_sample,
    sample_ends,
):
    """Integrate dy/dt = rhs from (t0, y0) forward to t_bound or the first event (module docstring).

    The first ``n_control`` components of y choose the steps (error norm, initial step); the others
    are carried along with the same steps (``n_control = len(y0)``: scipy's DOP853). Returns
    ``(code, t_end, event, steps)``; the state at ``t_end`` is written into ``y_end`` (the
    interpolant's at an event). ``event`` is -1 unless ``code`` is :data:`EVENT`; ``steps`` counts
    accepted steps. The interpolant at ``t_sample`` goes into ``y_sample`` (module docstring: a
    sample); with ``sample_ends`` the integration stops there.
    """
    n = y0.shape[0]
    n_ev = direction.shape[0]
    K = np.empty((N_STAGES_EXTENDED, n))
    F = np.empty((INTERPOLATOR_POWER, n))
    y = y0.copy()
    y_new = np.empty(n)
    f = np.empty(n)
    ys = np.empty(n)
    work = np.empty(n)
    g = np.empty(n_ev)
    g_new = np.empty(n_ev)
    g_root = np.empty(n_ev)
    for i in range(n):
        y_end[i] = math.nan
    if not _finite(y0):
        return FAILED, t0, -1, 0
    rhs(t0, y, p, f)
    events(t0, y, pe, g)
    t = t0
    h_abs = initial_step(rhs, p, t0, y, f, t_bound, max_step, rtol, atol, n_control, ys, work, y_new)
    steps = 0
    sampled = False
    while t < t_bound:
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        if h_abs > max_step:
            h_abs = max_step
        elif h_abs < min_step:
            h_abs = min_step
        rejected = False
        while True:
            if h_abs < min_step:
                return FAILED, t, -1, steps
            t_new = t + h_abs
            if t_new - t_bound > 0.0:
                t_new = t_bound
            h = t_new - t
            h_abs = abs(h)
            _rk_step(rhs, p, t, y, f, h, K, y_new, ys)
            err = _error_norm(K, h, y, y_new, rtol, atol, n_control)
            if err < 1.0:
                if err == 0.0:
                    factor = MAX_FACTOR
                else:
                    factor = SAFETY * err**ERROR_EXPONENT
                    factor = factor if factor < MAX_FACTOR else MAX_FACTOR
                if rejected and factor > 1.0:
                    factor = 1.0
                h_abs *= factor
                break
            factor = SAFETY * err**ERROR_EXPONENT
            h_abs *= factor if factor > MIN_FACTOR else MIN_FACTOR  # also when err is NaN
            rejected = True
        if not _finite(y_new):
            return FAILED, t, -1, steps
        steps += 1
        t_old = t
        t = t_new
        # y_old <- y, y <- y_new, f <- f_new (the last stage row); work keeps y_old
        for i in range(n):
            work[i] = y[i]
            y[i] = y_new[i]
            f[i] = K[N_STAGES, i]
        events(t, y, pe, g_new)
        first = -1
        t_first = math.inf
        built = False
        for e in range(n_ev):
            up = g[e] <= 0.0 and g_new[e] >= 0.0
            down = g[e] >= 0.0 and g_new[e] <= 0.0
            d = direction[e]
            if (up and d > 0.0) or (down and d < 0.0) or ((up or down) and d == 0.0):
                if not built:
                    dense_coefficients(rhs, p, t_old, h, work, y, K, F, ys)
                    built = True
                root = event_root(events, pe, e, F, t_old, h, work, t_old, t, ys, g_root, n_control)
                if root < t_first:
                    t_first = root
                    first = e
        if not sampled and t0 <= t_sample and (t_sample < t_first if first >= 0 else t_sample <= t):
            if not built:
                dense_coefficients(rhs, p, t_old, h, work, y, K, F, ys)
                built = True
            dense_eval(F, t_old, h, work, t_sample, y_sample, y_sample.shape[0])
            sampled = True
            if sample_ends:
                for i in range(y_sample.shape[0]):
                    y_end[i] = y_sample[i]
                return SAMPLED, t_sample, -1, steps
        if first >= 0:
            dense_eval(F, t_old, h, work, t_first, y_end, n)
            if not _finite(y_end):
                return FAILED, t_first, -1, steps
            return EVENT, t_first, first, steps
        for e in range(n_ev):
            g[e] = g_new[e]
    for i in range(n):
        y_end[i] = y[i]
    return FINISHED, t, -1, steps
