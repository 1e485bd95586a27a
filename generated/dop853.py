# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/numerics.py
# Template:  derive/templates/dop853.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   support.py sha256:4a3d44d95d3e4300
# ----------------------------------------------------------------------------------------------
"""A compiled embedded Dormand-Prince 8(5,3) integrator (DOP853) with dense output and events: scipy's
``solve_ivp(method="DOP853")`` step by step, compiled with numba (the support module of the exact
map's kernels, rendered by derive/numerics.py from derive/templates/dop853.py.j2).
The algorithm is scipy's ``solve_ivp(method="DOP853")`` step by step, compiled with numba so that
an integration costs microseconds instead of milliseconds:

* coefficients: ``scipy.integrate._ivp.dop853_coefficients`` (read at generation, literals in
  the step below);
* error norm: the 5th- and 3rd-order estimates combined as scipy's ``DOP853._estimate_error_norm``
  (Hairer, Norsett and Wanner, Solving ODEs I, section II.10), scale ``atol + rtol max(|y|, |y_new|)``;
* step-size controller: scipy's ``RungeKutta._step_impl`` (safety 0.9, factors 0.2 to 10, no growth
  after a rejection, failure below ``10 ulp(t)``), the step capped at ``max_step`` and clipped at
  ``t_bound``; initial step: scipy's ``select_initial_step``;
* the step itself: the tableau's sums written out with literal coefficients and its zeros left
  out (derive/numerics.py; the polar state's 4 components written out too, for a field registered
  with :func:`static`'s ``state_length``), summed in scipy's order: the values of the loops over
  the tableau, bitwise, with fewer operations (benchmarks/bench_exact.py measures the step);
* dense output: the 7th-order interpolant of scipy's ``DOP853._dense_output_impl`` (three extra
  stages per interpolated step) evaluated as ``Dop853DenseOutput``;
* events: evaluated at the end of every step; an event whose function changes sign in the
  requested direction (scipy's ``find_active_events``: ``g <= 0 <= g_new`` upward,
  ``g >= 0 >= g_new`` downward) is located on the dense output by Brent's method (scipy's
  ``brentq``, ``xtol = rtol = 4 eps`` as in ``solve_ivp``). Every event is terminal: the earliest
  root ends the integration and its state is the interpolant's there.
* events inside a step (not in scipy: what lets a step be longer than the events' own time
  scale): a function on the same side of 0 at both ends of a step may have crossed 0 twice inside
  it (a grazing liftoff: the leg reaches the liftoff length and shortens again within one step).
  The events' rates dg/dt at every step's end (a forward difference along the slope, one more
  events call per step) flag a valley toward 0 (moving toward 0 at the start, away at the end);
  when the cubic through the ends' values and rates dips below half the nearer end's distance to
  0 (:func:`valley_reaches`), the step's interpolant is built and searched for the valley's bottom
  (:func:`valley_crossing`, golden section); if it reaches 0, the crossing in the watched
  direction (the first, into the valley, or the second, out of it) is located by Brent's method
  like any other. The premise is at most one extremum of an event function per step (true of
  functions that oscillate no faster than the step: tests/test_exact_rtol.py's hard cases).

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
  ``(code, t_end, event, steps, evaluations)`` (accepted steps, right-hand side evaluations) and
  writes the end state into ``y_end``. ``code`` is
  :data:`FINISHED` (``t_bound`` reached), :data:`EVENT` (``event`` is its index) or :data:`FAILED`
  (step size below ``10 ulp(t)``, or a non-finite state), as ``solve_ivp``'s status 0 / 1 / -1;
  :data:`SAMPLED` when asked to stop at the sample (below).
* a sample: the interpolant at one time ``t_sample`` (as ``solve_ivp``'s dense output there),
  written into ``y_sample`` (its first ``len(y_sample)`` components) by the accepted step that
  reaches it, when ``t0 <= t_sample`` and ``t_sample`` comes before the event that ends the
  integration (at an event time: not sampled; at or before ``t_bound``: sampled). It changes
  neither the steps nor the events; ``y_sample`` is left as it is when not sampled;
  ``t_sample = inf`` samples nothing. With ``sample_ends`` :data:`ENDS` the integration stops there
  (:data:`SAMPLED`, ``t_end = t_sample``, ``y_end`` the sample's first components too).

The state may have any length (a field registered with :func:`static`'s ``state_length``: exactly
:data:`UNROLLED`), so the same integrator carries augmented (variational) systems:
with ``n_control`` set to the length of the original state, the steps, events and original
components are exactly those of the plain integration, and the added components are the same
Runge-Kutta scheme applied to their equations (for variational equations: the derivative of the
discrete flow at those steps).
"""

import math

import numpy as np
from numba import njit, types
from numba.extending import intrinsic, overload

from .support import load, store

__all__ = ["ENDS", "EVENT", "FAILED", "FINISHED", "GOES_ON", "SAMPLED", "dense_eval", "solve", "static"]

N_STAGES = 12  # stages of the 8th-order step (the next row holds f_new)
N_STAGES_EXTENDED = 16  # with the 3 extra stages of the interpolant
INTERPOLATOR_POWER = 7  # coefficient rows of the dense output
SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
#: Event roots: ``solve_ivp`` calls brentq with xtol = rtol = 4 eps (brentq's default maxiter 100).
ROOT_TOL = 4.0 * float(np.finfo(np.float64).eps)
ROOT_MAXITER = 100

FINISHED = 0
EVENT = 1
FAILED = -1
SAMPLED = 2
#: :func:`solve`'s ``sample_ends``: the integration stops at the sample, or goes on. Floats, not
#: bools: numba types a bool constant as its literal value, compiling :func:`solve` once per value.
ENDS = 1.0
GOES_ON = 0.0

_JIT = {"cache": True, "error_model": "numpy"}
#: Functions taking ``rhs`` / ``events`` are specialised per right-hand side and compiled into their
#: (cached) callers; cached on their own, their Dispatcher-typed signatures would never hit the cache.
_GENERIC = {"error_model": "numpy"}


def static(fn, state_length=None):
    """A zero-argument njit-callable returning a handle of the njit function ``fn`` to pass to
    :func:`solve` as ``rhs`` or ``events`` from a cached kernel.

    ``solve(fn, ...)`` inside a ``cache=True`` kernel would lower the dispatcher ``fn`` as a
    pointer to a Python object (a "dynamic global": numba refuses to cache the kernel). The handle
    has the same numba type (the call is resolved at compile time, by type) and no run-time
    value: a null pointer.

    ``state_length`` :data:`UNROLLED` registers ``fn`` as a field whose every state has exactly
    that many components: :func:`solve` then runs the step with its components written out
    (:func:`_rk_step`; the registration is per function, for all its handles and for ``fn`` passed
    itself). Another length, or a field registered twice with different lengths, is a ValueError.
    """
    if state_length is not None:
        if state_length != UNROLLED:
            raise ValueError(f"static: state_length {state_length}; only {UNROLLED} is written out")
        _UNROLLED_FIELDS.add(fn)
    elif fn in _UNROLLED_FIELDS:
        raise ValueError(f"static: {fn} has state_length {UNROLLED} (per function): pass it here too")

    @intrinsic
    def handle(typingctx):
        ty = types.Dispatcher(fn)

        def codegen(context, builder, signature, args):
            return context.get_constant_null(ty)

        return ty(), codegen

    return handle


#: The step of a field registered with this state length (the polar stance: :func:`static`'s
#: ``state_length``) has its components written out; any other field's loops over its own (the
#: choice is made by the field's type, at compile time: one body compiled per field, not both).
UNROLLED = 4
#: The right-hand sides :func:`static` was told have :data:`UNROLLED` components.
_UNROLLED_FIELDS: set = set()


# The step, the error norm and the interpolant's coefficients, written out from scipy's tableau
# (derive/numerics.py): plain functions, compiled as the overload below and the njit forms after it.
def _rk_step_unrolled(rhs, p, t, y, f, h, K, y_new, ys, dy):
    (y_0, y_1, y_2, y_3,) = load(y, 0, 1, 2, 3)
    (k0_0, k0_1, k0_2, k0_3,) = load(f, 0, 1, 2, 3)
    store(K[0], (k0_0, k0_1, k0_2, k0_3,))
    v1_0 = y_0 + (k0_0 * 0.05260015195876773) * h
    v1_1 = y_1 + (k0_1 * 0.05260015195876773) * h
    v1_2 = y_2 + (k0_2 * 0.05260015195876773) * h
    v1_3 = y_3 + (k0_3 * 0.05260015195876773) * h
    store(ys, (v1_0, v1_1, v1_2, v1_3,))
    rhs(t + 0.05260015195876773 * h, ys, p, K[1])
    (k1_0, k1_1, k1_2, k1_3,) = load(K[1], 0, 1, 2, 3)
    v2_0 = y_0 + (k0_0 * 0.0197250569845379 + k1_0 * 0.0591751709536137) * h
    v2_1 = y_1 + (k0_1 * 0.0197250569845379 + k1_1 * 0.0591751709536137) * h
    v2_2 = y_2 + (k0_2 * 0.0197250569845379 + k1_2 * 0.0591751709536137) * h
    v2_3 = y_3 + (k0_3 * 0.0197250569845379 + k1_3 * 0.0591751709536137) * h
    store(ys, (v2_0, v2_1, v2_2, v2_3,))
    rhs(t + 0.0789002279381516 * h, ys, p, K[2])
    (k2_0, k2_1, k2_2, k2_3,) = load(K[2], 0, 1, 2, 3)
    v3_0 = y_0 + (k0_0 * 0.02958758547680685 + k2_0 * 0.08876275643042054) * h
    v3_1 = y_1 + (k0_1 * 0.02958758547680685 + k2_1 * 0.08876275643042054) * h
    v3_2 = y_2 + (k0_2 * 0.02958758547680685 + k2_2 * 0.08876275643042054) * h
    v3_3 = y_3 + (k0_3 * 0.02958758547680685 + k2_3 * 0.08876275643042054) * h
    store(ys, (v3_0, v3_1, v3_2, v3_3,))
    rhs(t + 0.1183503419072274 * h, ys, p, K[3])
    (k3_0, k3_1, k3_2, k3_3,) = load(K[3], 0, 1, 2, 3)
    v4_0 = y_0 + (k0_0 * 0.2413651341592667 + k2_0 * -0.8845494793282861 + k3_0 * 0.924834003261792) * h
    v4_1 = y_1 + (k0_1 * 0.2413651341592667 + k2_1 * -0.8845494793282861 + k3_1 * 0.924834003261792) * h
    v4_2 = y_2 + (k0_2 * 0.2413651341592667 + k2_2 * -0.8845494793282861 + k3_2 * 0.924834003261792) * h
    v4_3 = y_3 + (k0_3 * 0.2413651341592667 + k2_3 * -0.8845494793282861 + k3_3 * 0.924834003261792) * h
    store(ys, (v4_0, v4_1, v4_2, v4_3,))
    rhs(t + 0.2816496580927726 * h, ys, p, K[4])
    (k4_0, k4_1, k4_2, k4_3,) = load(K[4], 0, 1, 2, 3)
    v5_0 = y_0 + (k0_0 * 0.037037037037037035 + k3_0 * 0.17082860872947386 + k4_0 * 0.12546768756682242) * h
    v5_1 = y_1 + (k0_1 * 0.037037037037037035 + k3_1 * 0.17082860872947386 + k4_1 * 0.12546768756682242) * h
    v5_2 = y_2 + (k0_2 * 0.037037037037037035 + k3_2 * 0.17082860872947386 + k4_2 * 0.12546768756682242) * h
    v5_3 = y_3 + (k0_3 * 0.037037037037037035 + k3_3 * 0.17082860872947386 + k4_3 * 0.12546768756682242) * h
    store(ys, (v5_0, v5_1, v5_2, v5_3,))
    rhs(t + 0.3333333333333333 * h, ys, p, K[5])
    (k5_0, k5_1, k5_2, k5_3,) = load(K[5], 0, 1, 2, 3)
    v6_0 = (y_0 + (k0_0 * 0.037109375 + k3_0 * 0.17025221101954405 + k4_0 * 0.06021653898045596 + k5_0 *
        -0.017578125) * h)
    v6_1 = (y_1 + (k0_1 * 0.037109375 + k3_1 * 0.17025221101954405 + k4_1 * 0.06021653898045596 + k5_1 *
        -0.017578125) * h)
    v6_2 = (y_2 + (k0_2 * 0.037109375 + k3_2 * 0.17025221101954405 + k4_2 * 0.06021653898045596 + k5_2 *
        -0.017578125) * h)
    v6_3 = (y_3 + (k0_3 * 0.037109375 + k3_3 * 0.17025221101954405 + k4_3 * 0.06021653898045596 + k5_3 *
        -0.017578125) * h)
    store(ys, (v6_0, v6_1, v6_2, v6_3,))
    rhs(t + 0.25 * h, ys, p, K[6])
    (k6_0, k6_1, k6_2, k6_3,) = load(K[6], 0, 1, 2, 3)
    v7_0 = (y_0 + (k0_0 * 0.03709200011850479 + k3_0 * 0.17038392571223998 + k4_0 * 0.10726203044637328
        + k5_0 * -0.015319437748624402 + k6_0 * 0.008273789163814023) * h)
    v7_1 = (y_1 + (k0_1 * 0.03709200011850479 + k3_1 * 0.17038392571223998 + k4_1 * 0.10726203044637328
        + k5_1 * -0.015319437748624402 + k6_1 * 0.008273789163814023) * h)
    v7_2 = (y_2 + (k0_2 * 0.03709200011850479 + k3_2 * 0.17038392571223998 + k4_2 * 0.10726203044637328
        + k5_2 * -0.015319437748624402 + k6_2 * 0.008273789163814023) * h)
    v7_3 = (y_3 + (k0_3 * 0.03709200011850479 + k3_3 * 0.17038392571223998 + k4_3 * 0.10726203044637328
        + k5_3 * -0.015319437748624402 + k6_3 * 0.008273789163814023) * h)
    store(ys, (v7_0, v7_1, v7_2, v7_3,))
    rhs(t + 0.3076923076923077 * h, ys, p, K[7])
    (k7_0, k7_1, k7_2, k7_3,) = load(K[7], 0, 1, 2, 3)
    v8_0 = (y_0 + (k0_0 * 0.6241109587160757 + k3_0 * -3.3608926294469414 + k4_0 * -0.868219346841726
        + k5_0 * 27.59209969944671 + k6_0 * 20.154067550477894 + k7_0 * -43.48988418106996) * h)
    v8_1 = (y_1 + (k0_1 * 0.6241109587160757 + k3_1 * -3.3608926294469414 + k4_1 * -0.868219346841726
        + k5_1 * 27.59209969944671 + k6_1 * 20.154067550477894 + k7_1 * -43.48988418106996) * h)
    v8_2 = (y_2 + (k0_2 * 0.6241109587160757 + k3_2 * -3.3608926294469414 + k4_2 * -0.868219346841726
        + k5_2 * 27.59209969944671 + k6_2 * 20.154067550477894 + k7_2 * -43.48988418106996) * h)
    v8_3 = (y_3 + (k0_3 * 0.6241109587160757 + k3_3 * -3.3608926294469414 + k4_3 * -0.868219346841726
        + k5_3 * 27.59209969944671 + k6_3 * 20.154067550477894 + k7_3 * -43.48988418106996) * h)
    store(ys, (v8_0, v8_1, v8_2, v8_3,))
    rhs(t + 0.6512820512820513 * h, ys, p, K[8])
    (k8_0, k8_1, k8_2, k8_3,) = load(K[8], 0, 1, 2, 3)
    v9_0 = (y_0 + (k0_0 * 0.47766253643826434 + k3_0 * -2.4881146199716677 + k4_0 * -0.590290826836843
        + k5_0 * 21.230051448181193 + k6_0 * 15.279233632882423 + k7_0 * -33.28821096898486 + k8_0 *
        -0.020331201708508627) * h)
    v9_1 = (y_1 + (k0_1 * 0.47766253643826434 + k3_1 * -2.4881146199716677 + k4_1 * -0.590290826836843
        + k5_1 * 21.230051448181193 + k6_1 * 15.279233632882423 + k7_1 * -33.28821096898486 + k8_1 *
        -0.020331201708508627) * h)
    v9_2 = (y_2 + (k0_2 * 0.47766253643826434 + k3_2 * -2.4881146199716677 + k4_2 * -0.590290826836843
        + k5_2 * 21.230051448181193 + k6_2 * 15.279233632882423 + k7_2 * -33.28821096898486 + k8_2 *
        -0.020331201708508627) * h)
    v9_3 = (y_3 + (k0_3 * 0.47766253643826434 + k3_3 * -2.4881146199716677 + k4_3 * -0.590290826836843
        + k5_3 * 21.230051448181193 + k6_3 * 15.279233632882423 + k7_3 * -33.28821096898486 + k8_3 *
        -0.020331201708508627) * h)
    store(ys, (v9_0, v9_1, v9_2, v9_3,))
    rhs(t + 0.6 * h, ys, p, K[9])
    (k9_0, k9_1, k9_2, k9_3,) = load(K[9], 0, 1, 2, 3)
    v10_0 = (y_0 + (k0_0 * -0.9371424300859873 + k3_0 * 5.186372428844064 + k4_0 * 1.0914373489967295 + k5_0 *
        -8.149787010746927 + k6_0 * -18.52006565999696 + k7_0 * 22.739487099350505 + k8_0 * 2.4936055526796523
        + k9_0 * -3.0467644718982196) * h)
    v10_1 = (y_1 + (k0_1 * -0.9371424300859873 + k3_1 * 5.186372428844064 + k4_1 * 1.0914373489967295 + k5_1 *
        -8.149787010746927 + k6_1 * -18.52006565999696 + k7_1 * 22.739487099350505 + k8_1 * 2.4936055526796523
        + k9_1 * -3.0467644718982196) * h)
    v10_2 = (y_2 + (k0_2 * -0.9371424300859873 + k3_2 * 5.186372428844064 + k4_2 * 1.0914373489967295 + k5_2 *
        -8.149787010746927 + k6_2 * -18.52006565999696 + k7_2 * 22.739487099350505 + k8_2 * 2.4936055526796523
        + k9_2 * -3.0467644718982196) * h)
    v10_3 = (y_3 + (k0_3 * -0.9371424300859873 + k3_3 * 5.186372428844064 + k4_3 * 1.0914373489967295 + k5_3 *
        -8.149787010746927 + k6_3 * -18.52006565999696 + k7_3 * 22.739487099350505 + k8_3 * 2.4936055526796523
        + k9_3 * -3.0467644718982196) * h)
    store(ys, (v10_0, v10_1, v10_2, v10_3,))
    rhs(t + 0.8571428571428571 * h, ys, p, K[10])
    (k10_0, k10_1, k10_2, k10_3,) = load(K[10], 0, 1, 2, 3)
    v11_0 = (y_0 + (k0_0 * 2.273310147516538 + k3_0 * -10.53449546673725 + k4_0 * -2.0008720582248625 + k5_0 *
        -17.9589318631188 + k6_0 * 27.94888452941996 + k7_0 * -2.8589982771350235 + k8_0 * -8.87285693353063
        + k9_0 * 12.360567175794303 + k10_0 * 0.6433927460157636) * h)
    v11_1 = (y_1 + (k0_1 * 2.273310147516538 + k3_1 * -10.53449546673725 + k4_1 * -2.0008720582248625 + k5_1 *
        -17.9589318631188 + k6_1 * 27.94888452941996 + k7_1 * -2.8589982771350235 + k8_1 * -8.87285693353063
        + k9_1 * 12.360567175794303 + k10_1 * 0.6433927460157636) * h)
    v11_2 = (y_2 + (k0_2 * 2.273310147516538 + k3_2 * -10.53449546673725 + k4_2 * -2.0008720582248625 + k5_2 *
        -17.9589318631188 + k6_2 * 27.94888452941996 + k7_2 * -2.8589982771350235 + k8_2 * -8.87285693353063
        + k9_2 * 12.360567175794303 + k10_2 * 0.6433927460157636) * h)
    v11_3 = (y_3 + (k0_3 * 2.273310147516538 + k3_3 * -10.53449546673725 + k4_3 * -2.0008720582248625 + k5_3 *
        -17.9589318631188 + k6_3 * 27.94888452941996 + k7_3 * -2.8589982771350235 + k8_3 * -8.87285693353063
        + k9_3 * 12.360567175794303 + k10_3 * 0.6433927460157636) * h)
    store(ys, (v11_0, v11_1, v11_2, v11_3,))
    rhs(t + 1.0 * h, ys, p, K[11])
    (k11_0, k11_1, k11_2, k11_3,) = load(K[11], 0, 1, 2, 3)
    v12_0 = (y_0 + (k0_0 * 0.054293734116568765 + k5_0 * 4.450312892752409 + k6_0 * 1.8915178993145003
        + k7_0 * -5.801203960010585 + k8_0 * 0.3111643669578199 + k9_0 * -0.1521609496625161
        + k10_0 * 0.20136540080403034 + k11_0 * 0.04471061572777259) * h)
    v12_1 = (y_1 + (k0_1 * 0.054293734116568765 + k5_1 * 4.450312892752409 + k6_1 * 1.8915178993145003
        + k7_1 * -5.801203960010585 + k8_1 * 0.3111643669578199 + k9_1 * -0.1521609496625161
        + k10_1 * 0.20136540080403034 + k11_1 * 0.04471061572777259) * h)
    v12_2 = (y_2 + (k0_2 * 0.054293734116568765 + k5_2 * 4.450312892752409 + k6_2 * 1.8915178993145003
        + k7_2 * -5.801203960010585 + k8_2 * 0.3111643669578199 + k9_2 * -0.1521609496625161
        + k10_2 * 0.20136540080403034 + k11_2 * 0.04471061572777259) * h)
    v12_3 = (y_3 + (k0_3 * 0.054293734116568765 + k5_3 * 4.450312892752409 + k6_3 * 1.8915178993145003
        + k7_3 * -5.801203960010585 + k8_3 * 0.3111643669578199 + k9_3 * -0.1521609496625161
        + k10_3 * 0.20136540080403034 + k11_3 * 0.04471061572777259) * h)
    store(y_new, (v12_0, v12_1, v12_2, v12_3,))
    rhs(t + h, y_new, p, K[12])


def _rk_step_loop(rhs, p, t, y, f, h, K, y_new, ys, dy):
    n = y.shape[0]
    for i in range(n):
        K[0, i] = f[i]
    for i in range(n):
        ys[i] = y[i] + (K[0, i] * 0.05260015195876773) * h
    rhs(t + 0.05260015195876773 * h, ys, p, K[1])
    for i in range(n):
        ys[i] = y[i] + (K[0, i] * 0.0197250569845379 + K[1, i] * 0.0591751709536137) * h
    rhs(t + 0.0789002279381516 * h, ys, p, K[2])
    for i in range(n):
        ys[i] = y[i] + (K[0, i] * 0.02958758547680685 + K[2, i] * 0.08876275643042054) * h
    rhs(t + 0.1183503419072274 * h, ys, p, K[3])
    for i in range(n):
        ys[i] = (y[i] + (K[0, i] * 0.2413651341592667 + K[2, i] * -0.8845494793282861 + K[3,
            i] * 0.924834003261792) * h)
    rhs(t + 0.2816496580927726 * h, ys, p, K[4])
    for i in range(n):
        ys[i] = (y[i] + (K[0, i] * 0.037037037037037035 + K[3, i] * 0.17082860872947386 + K[4,
            i] * 0.12546768756682242) * h)
    rhs(t + 0.3333333333333333 * h, ys, p, K[5])
    for i in range(n):
        ys[i] = (y[i] + (K[0, i] * 0.037109375 + K[3, i] * 0.17025221101954405 + K[4, i] * 0.06021653898045596
            + K[5, i] * -0.017578125) * h)
    rhs(t + 0.25 * h, ys, p, K[6])
    for i in range(n):
        ys[i] = (y[i] + (K[0, i] * 0.03709200011850479 + K[3, i] * 0.17038392571223998 + K[4,
            i] * 0.10726203044637328 + K[5, i] * -0.015319437748624402 + K[6, i] * 0.008273789163814023) * h)
    rhs(t + 0.3076923076923077 * h, ys, p, K[7])
    for i in range(n):
        ys[i] = (y[i] + (K[0, i] * 0.6241109587160757 + K[3, i] * -3.3608926294469414 + K[4, i] *
            -0.868219346841726 + K[5, i] * 27.59209969944671 + K[6, i] * 20.154067550477894 + K[7, i] *
            -43.48988418106996) * h)
    rhs(t + 0.6512820512820513 * h, ys, p, K[8])
    for i in range(n):
        ys[i] = (y[i] + (K[0, i] * 0.47766253643826434 + K[3, i] * -2.4881146199716677 + K[4, i] *
            -0.590290826836843 + K[5, i] * 21.230051448181193 + K[6, i] * 15.279233632882423 + K[7, i] *
            -33.28821096898486 + K[8, i] * -0.020331201708508627) * h)
    rhs(t + 0.6 * h, ys, p, K[9])
    for i in range(n):
        ys[i] = (y[i] + (K[0, i] * -0.9371424300859873 + K[3, i] * 5.186372428844064 + K[4,
            i] * 1.0914373489967295 + K[5, i] * -8.149787010746927 + K[6, i] * -18.52006565999696 + K[7,
            i] * 22.739487099350505 + K[8, i] * 2.4936055526796523 + K[9, i] * -3.0467644718982196) * h)
    rhs(t + 0.8571428571428571 * h, ys, p, K[10])
    for i in range(n):
        ys[i] = (y[i] + (K[0, i] * 2.273310147516538 + K[3, i] * -10.53449546673725 + K[4, i] *
            -2.0008720582248625 + K[5, i] * -17.9589318631188 + K[6, i] * 27.94888452941996 + K[7, i] *
            -2.8589982771350235 + K[8, i] * -8.87285693353063 + K[9, i] * 12.360567175794303 + K[10,
            i] * 0.6433927460157636) * h)
    rhs(t + 1.0 * h, ys, p, K[11])
    for i in range(n):
        y_new[i] = (y[i] + (K[0, i] * 0.054293734116568765 + K[5, i] * 4.450312892752409 + K[6,
            i] * 1.8915178993145003 + K[7, i] * -5.801203960010585 + K[8, i] * 0.3111643669578199 + K[9, i] *
            -0.1521609496625161 + K[10, i] * 0.20136540080403034 + K[11, i] * 0.04471061572777259) * h)
    rhs(t + h, y_new, p, K[12])


def _error_norm_py(K, h, y, y_new, rtol, atol, n):
    s5 = 0.0
    s3 = 0.0
    if n == 4:
        for i in range(4):
            scale = atol + max(abs(y[i]), abs(y_new[i])) * rtol
            e5 = ((K[0, i] * 0.01312004499419488 + K[5, i] * -1.2251564463762044 + K[6, i] *
                -0.4957589496572502 + K[7, i] * 1.6643771824549864 + K[8, i] * -0.35032884874997366 + K[9,
                i] * 0.3341791187130175 + K[10, i] * 0.08192320648511571 + K[11, i] *
                -0.022355307863886294) / scale)
            e3 = ((K[0, i] * -0.18980075407240762 + K[5, i] * 4.450312892752409 + K[6, i] * 1.8915178993145003
                + K[7, i] * -5.801203960010585 + K[8, i] * -0.4226823213237919 + K[9, i] * -0.1521609496625161
                + K[10, i] * 0.20136540080403034 + K[11, i] * 0.02265179219836082) / scale)
            s5 += e5 * e5
            s3 += e3 * e3
    else:
        for i in range(n):
            scale = atol + max(abs(y[i]), abs(y_new[i])) * rtol
            e5 = ((K[0, i] * 0.01312004499419488 + K[5, i] * -1.2251564463762044 + K[6, i] *
                -0.4957589496572502 + K[7, i] * 1.6643771824549864 + K[8, i] * -0.35032884874997366 + K[9,
                i] * 0.3341791187130175 + K[10, i] * 0.08192320648511571 + K[11, i] *
                -0.022355307863886294) / scale)
            e3 = ((K[0, i] * -0.18980075407240762 + K[5, i] * 4.450312892752409 + K[6, i] * 1.8915178993145003
                + K[7, i] * -5.801203960010585 + K[8, i] * -0.4226823213237919 + K[9, i] * -0.1521609496625161
                + K[10, i] * 0.20136540080403034 + K[11, i] * 0.02265179219836082) / scale)
            s5 += e5 * e5
            s3 += e3 * e3
    e5_2 = math.sqrt(s5) ** 2
    e3_2 = math.sqrt(s3) ** 2
    if e5_2 == 0.0 and e3_2 == 0.0:
        return 0.0
    return abs(h) * e5_2 / math.sqrt((e5_2 + 0.01 * e3_2) * n)


def _dense_coefficients_py(rhs, p, t_old, h, y_old, y, K, F, ys, dy):
    n = y.shape[0]
    for i in range(n):
        ys[i] = (y_old[i] + (K[0, i] * 0.056167502283047954 + K[6, i] * 0.25350021021662483 + K[7, i] *
            -0.2462390374708025 + K[8, i] * -0.12419142326381637 + K[9, i] * 0.15329179827876568 + K[10,
            i] * 0.00820105229563469 + K[11, i] * 0.007567897660545699 + K[12, i] * -0.008298) * h)
    rhs(t_old + 0.1 * h, ys, p, K[13])
    for i in range(n):
        ys[i] = (y_old[i] + (K[0, i] * 0.03183464816350214 + K[5, i] * 0.028300909672366776 + K[6,
            i] * 0.053541988307438566 + K[7, i] * -0.05492374857139099 + K[10, i] * -0.00010834732869724932
            + K[11, i] * 0.0003825710908356584 + K[12, i] * -0.00034046500868740456 + K[13,
            i] * 0.1413124436746325) * h)
    rhs(t_old + 0.2 * h, ys, p, K[14])
    for i in range(n):
        ys[i] = (y_old[i] + (K[0, i] * -0.42889630158379194 + K[5, i] * -4.697621415361164 + K[6,
            i] * 7.683421196062599 + K[7, i] * 4.06898981839711 + K[8, i] * 0.3567271874552811 + K[12, i] *
            -0.0013990241651590145 + K[13, i] * 2.9475147891527724 + K[14, i] * -9.15095847217987) * h)
    rhs(t_old + 0.7777777777777778 * h, ys, p, K[15])
    for i in range(n):
        d = y[i] - y_old[i]
        F[0, i] = d
        F[1, i] = h * K[0, i] - d
        F[2, i] = 2.0 * d - h * (K[12, i] + K[0, i])
        F[3, i] = (h * (K[0, i] * -8.428938276109013 + K[5, i] * 0.5667149535193777 + K[6, i] *
            -3.0689499459498917 + K[7, i] * 2.38466765651207 + K[8, i] * 2.117034582445028 + K[9, i] *
            -0.871391583777973 + K[10, i] * 2.2404374302607883 + K[11, i] * 0.6315787787694688 + K[12, i] *
            -0.08899033645133331 + K[13, i] * 18.148505520854727 + K[14, i] * -9.194632392478356 + K[15, i] *
            -4.436036387594894))
        F[4, i] = (h * (K[0, i] * 10.427508642579134 + K[5, i] * 242.28349177525817 + K[6,
            i] * 165.20045171727028 + K[7, i] * -374.5467547226902 + K[8, i] * -22.113666853125306 + K[9,
            i] * 7.733432668472264 + K[10, i] * -30.674084731089398 + K[11, i] * -9.332130526430229 + K[12,
            i] * 15.697238121770845 + K[13, i] * -31.139403219565178 + K[14, i] * -9.35292435884448 + K[15,
            i] * 35.81684148639408))
        F[5, i] = (h * (K[0, i] * 19.985053242002433 + K[5, i] * -387.0373087493518 + K[6, i] *
            -189.17813819516758 + K[7, i] * 527.8081592054236 + K[8, i] * -11.57390253995963 + K[9,
            i] * 6.8812326946963 + K[10, i] * -1.0006050966910838 + K[11, i] * 0.7777137798053443 + K[12, i] *
            -2.778205752353508 + K[13, i] * -60.19669523126412 + K[14, i] * 84.32040550667716 + K[15,
            i] * 11.99229113618279))
        F[6, i] = (h * (K[0, i] * -25.69393346270375 + K[5, i] * -154.18974869023643 + K[6, i] *
            -231.5293791760455 + K[7, i] * 357.6391179106141 + K[8, i] * 93.40532418362432 + K[9, i] *
            -37.45832313645163 + K[10, i] * 104.0996495089623 + K[11, i] * 29.8402934266605 + K[12, i] *
            -43.53345659001114 + K[13, i] * 96.32455395918828 + K[14, i] * -39.17726167561544 + K[15, i] *
            -149.72683625798564))


#: One 8th-order step from (t, y) with slope f: y_new, and f_new in K[N_STAGES] (scipy's rk_step);
#: ``dy`` is scratch (the right-hand side writes there; copied into K's rows).
def _rk_step(rhs, p, t, y, f, h, K, y_new, ys, dy):  # pragma: no cover - njit-only (overload below)
    raise NotImplementedError("_rk_step runs inside compiled code only")


@overload(_rk_step, jit_options={"error_model": "numpy"})
def _rk_step_impl(rhs, p, t, y, f, h, K, y_new, ys, dy):
    """The step for this right-hand side: components written out for a field :func:`static` was
    told has :data:`UNROLLED` components, the loops otherwise (chosen by type, at compile time:
    one body compiled per field instead of both)."""
    if getattr(rhs, "dispatcher", None) in _UNROLLED_FIELDS:
        return _rk_step_unrolled
    return _rk_step_loop


#: scipy's ``DOP853._estimate_error_norm`` (scale atol + rtol max(|y|, |y_new|)) over the first n
#: components; ``math.sqrt(s5) ** 2`` is np.linalg.norm(err5) ** 2, as scipy computes it.
_error_norm = njit(**_GENERIC)(_error_norm_py)
#: The interpolant of the step (t_old, y_old) -> (t_old + h, y): F (7, n), scipy's
#: ``DOP853._dense_output_impl`` (K holds the step's 13 stages; 3 more are evaluated into it).
_dense_coefficients = njit(**_GENERIC)(_dense_coefficients_py)


#: A finite difference along the slope f over this fraction of the step gives the events' rates.
RATE_STEP = 1e-6


@njit(**_JIT)
def _rms(x, scale, n):
    """scipy's ``norm(x / scale)`` over the first n components: the RMS norm."""
    s = 0.0
    for i in range(n):
        v = x[i] / scale[i]
        s += v * v
    return math.sqrt(s) / math.sqrt(n)


@njit(**_JIT)
def _rms_where_nonzero(x, y0, scale, n):
    """The RMS norm of x / scale over the first n components where y0 is not 0 (0 when none is)."""
    s = 0.0
    count = 0
    for i in range(n):
        if y0[i] != 0.0:
            v = x[i] / scale[i]
            s += v * v
            count += 1
    return math.sqrt(s) / math.sqrt(count) if count > 0 else 0.0


@njit(**_GENERIC)
def initial_step(rhs, p, t0, y0, f0, t_bound, max_step, rtol, atol, n_control, y1, f1, scale):
    """scipy's ``select_initial_step`` (forward in time, error estimator order 7) on the first
    ``n_control`` components, except that its first guess (the time over which the state moves by
    1 % of itself, ``0.01 d0 / d1``) leaves out the components that are exactly 0 (scipy's guess
    over all of them when the others do not move: a vertical hop's bottom). One such (q_rd at the
    bottom) has the scale atol alone, and scipy's guess 3.6e-11 s there makes the controller
    (growth 10x per step at most) take about ten steps, 110 evaluations, to reach its own step at
    every tolerance. ``reference.first_step`` is the same rule for solve_ivp."""
    n = y0.shape[0]
    interval = abs(t_bound - t0)
    if interval == 0.0:
        return 0.0
    for i in range(n_control):
        scale[i] = atol + abs(y0[i]) * rtol
    d0 = _rms_where_nonzero(y0, y0, scale, n_control)
    d1 = _rms_where_nonzero(f0, y0, scale, n_control)
    if d0 < 1e-5 or d1 < 1e-5:  # the nonzero components do not move: scipy's guess over all
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
        h1 = math.sqrt(math.sqrt(math.sqrt(0.01 / max(d1, d2))))  # ** (1 / (7 + 1))
    return min(100.0 * h0, h1, interval, max_step)


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


#: Golden-section search for an event function's extremum inside a step: the bracket shrinks by
#: this factor per evaluation, to VALLEY_XTOL of the step (at most VALLEY_MAXITER evaluations).
GOLDEN = 0.5 * (3.0 - math.sqrt(5.0))
VALLEY_XTOL = 1e-12
VALLEY_MAXITER = 80


@njit(**_JIT)
def valley_reaches(g0, g1, s0, s1):
    """Whether the cubic through a positive function's values g0, g1 at the ends of a step and its
    slopes s0 < 0, s1 > 0 there (per unit step) dips below the lower end by at least half that end's
    height: a valley that may cross 0 once the cubic's own error (far smaller than the dip: its
    ratio to the dip falls as the step squared) is allowed for. The minimum of
    p(x) = g0 + s0 x + a x^2 + b x^3 on (0, 1) is at the root of p' = s0 + 2 a x + 3 b x^2 there."""
    a = 3.0 * (g1 - g0) - 2.0 * s0 - s1
    b = 2.0 * (g0 - g1) + s0 + s1
    if b == 0.0:
        x = -s0 / (2.0 * a)
    else:
        disc = a * a - 3.0 * b * s0
        if disc < 0.0:
            disc = 0.0
        x = (-a + math.sqrt(disc)) / (3.0 * b)  # the root where p' goes from - to +
    if not 0.0 <= x <= 1.0:
        x = 0.5
    lowest = g0 + x * (s0 + x * (a + x * b))
    low_end = min(g0, g1)
    return not lowest > 0.5 * low_end


@njit(**_GENERIC)
def valley_crossing(events, pe, i, F, t_old, h, y_old, sign, ys, g, n_control):
    """A point of the step (t_old, t_old + h) where event ``i``'s function, ``sign`` times it
    positive at both ends and moving toward 0 at the start and away from it at the end, is at or
    past 0 on the interpolant: a golden-section search for the minimum of ``sign * g_i``, stopped
    at the first point where it is <= 0. Returns that time, or NaN when the valley stays above 0
    (no crossing within the step)."""
    a = t_old
    b = t_old + h
    x1 = a + GOLDEN * (b - a)
    x2 = b - GOLDEN * (b - a)
    f1 = sign * _event_value(events, pe, i, F, t_old, h, y_old, x1, ys, g, n_control)
    if not f1 > 0.0:
        return x1
    f2 = sign * _event_value(events, pe, i, F, t_old, h, y_old, x2, ys, g, n_control)
    if not f2 > 0.0:
        return x2
    for _ in range(VALLEY_MAXITER):
        if b - a <= VALLEY_XTOL * h:
            break
        if f1 < f2:
            b = x2
            x2 = x1
            f2 = f1
            x1 = a + GOLDEN * (b - a)
            f1 = sign * _event_value(events, pe, i, F, t_old, h, y_old, x1, ys, g, n_control)
            if not f1 > 0.0:
                return x1
        else:
            a = x1
            x1 = x2
            f1 = f2
            x2 = b - GOLDEN * (b - a)
            f2 = sign * _event_value(events, pe, i, F, t_old, h, y_old, x2, ys, g, n_control)
            if not f2 > 0.0:
                return x2
    return math.nan


@njit(**_GENERIC)
def _event_rates(events, pe, t, y, f, delta, g, ys, g_step, rate, n_control):
    """The events' rates dg/dt at (t, y) with slope f: a forward difference over ``delta`` along f."""
    for i in range(n_control):
        ys[i] = y[i] + delta * f[i]
    events(t + delta, ys, pe, g_step)
    for e in range(g.shape[0]):
        rate[e] = (g_step[e] - g[e]) / delta


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
    ``(code, t_end, event, steps, evaluations)``; the state at ``t_end`` is written into ``y_end``
    (the interpolant's at an event). ``event`` is -1 unless ``code`` is :data:`EVENT`; ``steps``
    counts accepted steps, ``evaluations`` the right-hand side's evaluations. The interpolant at
    ``t_sample`` goes into ``y_sample`` (module docstring: a sample); with ``sample_ends``
    :data:`ENDS` the integration stops there (:data:`GOES_ON`: it does not).
    """
    n = y0.shape[0]
    n_ev = direction.shape[0]
    # One allocation for every work array (the stages, the interpolant, states, event values).
    buf = np.empty((N_STAGES_EXTENDED + INTERPOLATOR_POWER + 6) * n + 6 * n_ev)
    K = buf[: N_STAGES_EXTENDED * n].reshape((N_STAGES_EXTENDED, n))
    o = N_STAGES_EXTENDED * n
    F = buf[o : o + INTERPOLATOR_POWER * n].reshape((INTERPOLATOR_POWER, n))
    o += INTERPOLATOR_POWER * n
    y = buf[o : o + n]
    y_new = buf[o + n : o + 2 * n]
    f = buf[o + 2 * n : o + 3 * n]
    ys = buf[o + 3 * n : o + 4 * n]
    work = buf[o + 4 * n : o + 5 * n]
    dy = buf[o + 5 * n : o + 6 * n]
    o += 6 * n
    g = buf[o : o + n_ev]
    g_new = buf[o + n_ev : o + 2 * n_ev]
    g_root = buf[o + 2 * n_ev : o + 3 * n_ev]
    rate = buf[o + 3 * n_ev : o + 4 * n_ev]
    rate_new = buf[o + 4 * n_ev : o + 5 * n_ev]
    g_step = buf[o + 5 * n_ev : o + 6 * n_ev]
    for i in range(n):
        y[i] = y0[i]
        y_end[i] = math.nan
    if not _finite(y0):
        return FAILED, t0, -1, 0, 0
    rhs(t0, y, p, f)
    events(t0, y, pe, g)
    t = t0
    h_abs = initial_step(rhs, p, t0, y, f, t_bound, max_step, rtol, atol, n_control, ys, work, y_new)
    evaluations = 2
    _event_rates(events, pe, t, y, f, RATE_STEP * h_abs, g, ys, g_step, rate, n_control)
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
                return FAILED, t, -1, steps, evaluations
            t_new = t + h_abs
            if t_new - t_bound > 0.0:
                t_new = t_bound
            h = t_new - t
            h_abs = abs(h)
            _rk_step(rhs, p, t, y, f, h, K, y_new, ys, dy)
            evaluations += N_STAGES
            err = _error_norm(K, h, y, y_new, rtol, atol, n_control)
            if err < 1.0:
                if err == 0.0:
                    factor = MAX_FACTOR
                else:
                    factor = SAFETY / math.sqrt(math.sqrt(math.sqrt(err)))
                    factor = factor if factor < MAX_FACTOR else MAX_FACTOR
                if rejected and factor > 1.0:
                    factor = 1.0
                h_abs *= factor
                break
            factor = SAFETY / math.sqrt(math.sqrt(math.sqrt(err)))
            h_abs *= factor if factor > MIN_FACTOR else MIN_FACTOR  # also when err is NaN
            rejected = True
        if not _finite(y_new):
            return FAILED, t, -1, steps, evaluations
        steps += 1
        t_old = t
        t = t_new
        # y_old <- y, y <- y_new, f <- f_new (the last stage row); work keeps y_old
        for i in range(n):
            work[i] = y[i]
            y[i] = y_new[i]
            f[i] = K[N_STAGES, i]
        events(t, y, pe, g_new)
        _event_rates(events, pe, t, y, f, RATE_STEP * h, g_new, ys, g_step, rate_new, n_control)
        first = -1
        t_first = math.inf
        built = False
        for e in range(n_ev):
            d = direction[e]
            if not (d == d):
                continue  # NaN: not watched
            up = g[e] <= 0.0 and g_new[e] >= 0.0
            down = g[e] >= 0.0 and g_new[e] <= 0.0
            if (up and d > 0.0) or (down and d < 0.0) or ((up or down) and d == 0.0):
                if not built:
                    _dense_coefficients(rhs, p, t_old, h, work, y, K, F, ys, dy)
                    evaluations += N_STAGES_EXTENDED - N_STAGES - 1
                    built = True
                root = event_root(events, pe, e, F, t_old, h, work, t_old, t, ys, g_root, n_control)
                if root < t_first:
                    t_first = root
                    first = e
            elif not (up or down):
                # Both ends on the same side of 0: a valley toward 0 inside the step (the function
                # moves toward 0 at the start and away from it at the end) may cross it twice.
                sign = 1.0 if g[e] > 0.0 else -1.0
                if (
                    sign * rate[e] < 0.0
                    and sign * rate_new[e] > 0.0
                    and valley_reaches(
                        sign * g[e], sign * g_new[e], sign * rate[e] * h, sign * rate_new[e] * h
                    )
                ):
                    if not built:
                        _dense_coefficients(rhs, p, t_old, h, work, y, K, F, ys, dy)
                        evaluations += N_STAGES_EXTENDED - N_STAGES - 1
                        built = True
                    x = valley_crossing(events, pe, e, F, t_old, h, work, sign, ys, g_root, n_control)
                    if x == x:
                        # the first crossing (t_old, x) goes against sign, the second (x, t) with it
                        first_crossing = d == 0.0 or d * sign < 0.0
                        xa = t_old if first_crossing else x
                        xb = x if first_crossing else t
                        root = event_root(events, pe, e, F, t_old, h, work, xa, xb, ys, g_root, n_control)
                        if root < t_first:
                            t_first = root
                            first = e
        if not sampled and t0 <= t_sample and (t_sample < t_first if first >= 0 else t_sample <= t):
            if not built:
                _dense_coefficients(rhs, p, t_old, h, work, y, K, F, ys, dy)
                evaluations += N_STAGES_EXTENDED - N_STAGES - 1
                built = True
            dense_eval(F, t_old, h, work, t_sample, y_sample, y_sample.shape[0])
            sampled = True
            if sample_ends == ENDS:
                for i in range(y_sample.shape[0]):
                    y_end[i] = y_sample[i]
                return SAMPLED, t_sample, -1, steps, evaluations
        if first >= 0:
            dense_eval(F, t_old, h, work, t_first, y_end, n)
            if not _finite(y_end):
                return FAILED, t_first, -1, steps, evaluations
            return EVENT, t_first, first, steps, evaluations
        for e in range(n_ev):
            g[e] = g_new[e]
            rate[e] = rate_new[e]
    for i in range(n):
        y_end[i] = y[i]
    return FINISHED, t, -1, steps, evaluations
