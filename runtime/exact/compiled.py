"""The exact stance compiled with numba: the default ``"exact"`` map's stance.

The same hybrid simulation as :mod:`.reference` (its docstring states the conventions, the events
and the statuses; they are not restated differently here), integrated by the compiled DOP853 of
:mod:`.dop853` instead of ``solve_ivp``:

* compression with ``k_c`` from touchdown until ``q_rd`` crosses 0 upward (the bottom; ``q_rd`` set
  to exactly 0 there, report section 2.2.1), then decompression with ``k_d`` until ``q_r`` crosses
  ``q_r_lo`` upward (liftoff); the right-hand side is the generated kernel
  ``slip_model.stance_polar_rhs`` (report eqs (2)-(3));
* failures as :mod:`.reference` reports them: ``TOUCHDOWN_NOT_COMPRESSING`` (``q_rd >= 0`` at
  touchdown), ``FALL`` (``cos q_th`` crosses 0, or ``q_r <= COLLAPSE_FRACTION l0``),
  ``NO_LIFTOFF`` (bottom leg length ``>= q_r_lo``, or ``t_max`` reached), ``RECOMPRESSION`` (the
  ``k_d`` spring cannot extend the leg at the bottom, or ``q_rd`` crosses 0 downward after it),
  ``INTEGRATION_FAILED`` (the flights, with ``APEX_TOO_LOW``, ``LIFTOFF_DOWNWARD`` and
  ``LIFTOFF_BACKWARD``, are the generated composition every map's apex return is:
  ``generated/exact.py``);
* the same tolerances (``DEFAULT_RTOL``, ``DEFAULT_ATOL``) and time limit
  (:func:`.reference.default_t_max`) as the solve_ivp reference, and at the default rtol the same
  step cap (:func:`.reference.max_step`, so the two take the same steps); at other tolerances the
  cap scales with the tolerance (:func:`step_cap`) and the events inside a step are found by the
  integrator's own checks (:mod:`.dop853`): the tolerance is what sets the cost.

One driver, :func:`hybrid_stance`, holds the hybrid stance (the events, the touchdown and bottom
checks, the failure statuses) once for every exact kernel: it takes the vector field as an
argument (a :func:`.dop853.static` handle; the integrated state may carry more than the polar
state, controlled by its first four components) and a step to run at the bottom (nothing here; the
saltation of :mod:`.jacobian`, whose own code keeps the sensitivity-specific steps).

Kernels (``@njit``, never raise; NaN outputs unless the status is OK):

* :func:`stance_into` (touchdown state -> one row of :data:`STANCE_NAMES`, returns the status;
  ``INVALID_INPUT`` for a state that is not finite, has ``q_r`` outside ``(0, l0]`` or
  ``|q_th| >= pi/2``, or parameters outside SlipParams' domain);
* :func:`half_into` (one half of the stance: touchdown -> bottom or bottom -> liftoff) and
  :func:`state_at_into` (the state a time t after touchdown);

all behind the scalar kernels of :mod:`.kernels`, which the generated code calls (batches in
parallel: the generated ``exact_*_batch`` kernels).

The halves and the state at a time are measured in tests/test_exact_compiled.py (section 5):
compression then decompression against the stance, the compression bitwise, the liftoff state to
3.5e-15 on the test steps and 2.5e-14 over 2910 random stances, t_stance to 2.5e-16 s; the state at
a time against solve_ivp's dense output to 4.6e-14 (the two simulators' bottom times differ by
~4e-16 s, times the radial acceleration there), beyond liftoff to 3.9e-14; every kernel is mirror
symmetric (x -> -x) bitwise.

Rows are laid out by the index's names (``results.columns``), never by position. Measured against
the solve_ivp reference (tests/test_exact_compiled.py): on the test steps (human runner and robot
hopper, symmetric and nonsymmetric, k_c == k_d and k_c != k_d) bottom and liftoff states agree to
3.8e-15 (relative to max(1, |value|)), t_bottom and t_stance to 4.4e-16 s; over 1463 random
stances to 6.9e-14 and 3.2e-15 s; every failure case of tests/test_simulator.py gets the same status.
The energy (27) drifts by at most 7.7e-12 (relative) within a subphase, as with solve_ivp.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from slipmaps.generated.slip_model import stance_polar_rhs
from slipmaps.generated.status import Status

from ..api.results import GROUPS, columns
from ..api.validate import POLAR_NAMES
from . import dop853
from .reference import COLLAPSE_FRACTION, DEFAULT_RTOL, max_step

__all__ = [
    "INLINE",
    "STANCE_NAMES",
    "half_into",
    "hybrid_stance",
    "stance_into",
    "state_at_into",
]

#: The columns of a stance row (the index's stance outputs).
STANCE_NAMES = columns("stance")
N_STANCE = len(STANCE_NAMES)

# Polar state components by name.
Q_R, Q_RD, Q_TH, Q_THD = (POLAR_NAMES.index(n) for n in ("q_r", "q_rd", "q_th", "q_thd"))
N_POLAR = len(POLAR_NAMES)


def _start(names: tuple[str, ...], group: str) -> int:
    """First column of a group of 4 in ``names``, checked contiguous and in polar order."""
    j = names.index(GROUPS[group][0])
    if names[j : j + len(GROUPS[group])] != GROUPS[group]:
        raise RuntimeError(f"group {group!r} is not contiguous in {names}")
    return j


# Columns of a stance row.
T_BOTTOM = STANCE_NAMES.index("t_bottom")
T_STANCE = STANCE_NAMES.index("t_stance")
BOTTOM = _start(STANCE_NAMES, "bottom")
LIFTOFF = _start(STANCE_NAMES, "liftoff")

# Events, in reference.py's order (ties go to the first); every run watches the same event functions
# with its own directions (NaN: not watched), so the integrator is compiled once per vector field.
EV_LIFTOFF, EV_RADIAL, EV_FALL, EV_COLLAPSE = 0, 1, 2, 3  # q_r - q_r_lo, q_rd, cos q_th, q_r - r_min
#: Compression: the bottom (q_rd up through 0), fall, collapse.
COMPRESSION_DIRECTIONS = np.array([math.nan, +1.0, -1.0, -1.0])
#: Decompression: liftoff (q_r up through q_r_lo), recompression (q_rd down through 0), fall, collapse.
DECOMPRESSION_DIRECTIONS = np.array([+1.0, -1.0, -1.0, -1.0])
#: The stance equations continued beyond liftoff (:func:`state_at_into`): no event.
CONTINUATION_DIRECTIONS = np.array([math.nan, math.nan, math.nan, math.nan])

OK = int(Status.OK)
INVALID_INPUT = int(Status.INVALID_INPUT)
APEX_TOO_LOW = int(Status.APEX_TOO_LOW)
TOUCHDOWN_NOT_COMPRESSING = int(Status.TOUCHDOWN_NOT_COMPRESSING)
NO_LIFTOFF = int(Status.NO_LIFTOFF)
FALL = int(Status.FALL)
RECOMPRESSION = int(Status.RECOMPRESSION)
INTEGRATION_FAILED = int(Status.INTEGRATION_FAILED)

_JIT = {"cache": True, "error_model": "numpy"}
#: The layers between a kernel and the driver are inlined into it (numba's IR inlining): each cached
#: function of a call chain re-optimises everything it links (LLVM's passes over the whole driver at
#: every layer), so the first call compiles in a third less time (benchmarks/bench_first_call.py).
#: An inlined body is compiled with its caller's options: it must not rely on its own error model.
INLINE = {**_JIT, "inline": "always"}
#: The driver takes the vector field and the bottom step as arguments: not cached itself (its
#: Dispatcher-typed signature would never hit the cache) and inlined into each caller
#: (:func:`_plain`, :func:`.jacobian.jacobian_into`); :func:`.dop853.solve` is compiled once per field.
_DRIVER = {"error_model": "numpy", "inline": "always"}


@njit(**_JIT)
def polar_field(t, y, p, dy):
    """The stance vector field (report eqs (2)-(3)) on y[:4]; p = (m, l0, k, g_s)."""
    m, l0, k, g_s = p
    d = stance_polar_rhs(y[Q_R], y[Q_RD], y[Q_TH], y[Q_THD], m, l0, k, g_s)
    dy[Q_R] = d[Q_R]
    dy[Q_RD] = d[Q_RD]
    dy[Q_TH] = d[Q_TH]
    dy[Q_THD] = d[Q_THD]


@njit(**_JIT)
def stance_events(t, y, pe, g):
    """The stance's event functions (their directions select them per subphase); pe = (q_r_lo, r_min)."""
    q_r_lo, r_min = pe
    g[EV_LIFTOFF] = y[Q_R] - q_r_lo
    g[EV_RADIAL] = y[Q_RD]
    g[EV_FALL] = math.cos(y[Q_TH])
    g[EV_COLLAPSE] = y[Q_R] - r_min


@njit(**_JIT)
def no_bottom_step(z_b, m, l0, k_c, k_d, g_s, work):
    """The plain stance's step at the bottom: nothing (the Jacobian's is its saltation)."""


POLAR_FIELD = dop853.static(polar_field, state_length=N_POLAR)
STANCE_EVENTS = dop853.static(stance_events)
NO_BOTTOM_STEP = dop853.static(no_bottom_step)


#: The tolerance at which the compiled stance's step cap is the solve_ivp reference's
#: (:func:`.reference.max_step`): at the default, both take the same steps.
CAP_RTOL = DEFAULT_RTOL


@njit(**_JIT)
def step_cap(m, l0, k, g_s, rtol):
    """The step cap of a subphase with stiffness k [s]: the reference's (1/16 of the shorter natural
    period) at rtol :data:`CAP_RTOL`, scaled as the step of an 8th-order method scales with its
    tolerance, (rtol / CAP_RTOL) ** (1/8). It binds where the error control would take steps longer
    than that fraction of the period (a slowly varying stance), by the same proportion at every
    tolerance, so that the cost follows the tolerance: at 1e-6 the cap is 4.2x the reference's, at
    1e-3 10x. The events are found by the integrator's sign checks at the steps' ends and inside
    them (:func:`.dop853.solve`), not by the cap."""
    return max_step(m, l0, k, g_s) * (rtol / CAP_RTOL) ** 0.125


@njit(**_JIT)
def failure_status(code, event):
    """The status of a subphase that did not reach its goal event (reference.py's ``failure``)."""
    if code == dop853.FAILED:
        return INTEGRATION_FAILED
    if code == dop853.FINISHED:
        return NO_LIFTOFF
    if event == EV_RADIAL:  # q_rd down through 0: only watched in the decompression
        return RECOMPRESSION
    return FALL


@njit(**_JIT)
def valid_polar(q_r, q_rd, q_th, q_thd, l0):
    """The polar_state check of api/validate.py (the reference's): finite, 0 < q_r <= l0, |q_th| < pi/2."""
    finite = math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
    return finite and 0.0 < q_r <= l0 and abs(q_th) < 0.5 * math.pi


@njit(**_JIT)
def valid_parameters(m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
    """SlipParams' domain (finite, positive, 0 < q_r_lo <= l0) and positive finite tolerances: the
    integrator's step control needs them (a NaN tolerance or m = 0 never ends a step)."""
    finite = (
        math.isfinite(m)
        and math.isfinite(l0)
        and math.isfinite(k_c)
        and math.isfinite(k_d)
        and math.isfinite(g_s)
        and math.isfinite(q_r_lo)
        and math.isfinite(rtol)
        and math.isfinite(atol)
    )
    positive = m > 0.0 and l0 > 0.0 and k_c > 0.0 and k_d > 0.0 and g_s > 0.0 and rtol > 0.0 and atol > 0.0
    return finite and positive and 0.0 < q_r_lo <= l0


@njit(**_JIT)
def touchdown_status(q_r, q_rd, q_th, q_thd, l0):
    """The checks of a touchdown state before the compression: INVALID_INPUT (not a polar state),
    TOUCHDOWN_NOT_COMPRESSING (q_rd >= 0), FALL (leg length already collapsed), else OK."""
    if not valid_polar(q_r, q_rd, q_th, q_thd, l0):
        return INVALID_INPUT
    if q_rd >= 0.0:
        return TOUCHDOWN_NOT_COMPRESSING
    if q_r <= COLLAPSE_FRACTION * l0:
        return FALL
    return OK


@njit(**_JIT)
def bottom_status(q_r_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, t_bottom, t_max):
    """The checks of a bottom state (q_rd = 0) before the decompression: NO_LIFTOFF (q_r_b >=
    q_r_lo: q_r can never cross q_r_lo upward), RECOMPRESSION (the k_d spring cannot start
    extending the leg), NO_LIFTOFF (no time left), FALL (a collapsed leg: a bottom given as such;
    the compression stops at the collapse), else OK."""
    if q_r_b >= q_r_lo:
        return NO_LIFTOFF
    if not stance_polar_rhs(q_r_b, 0.0, q_th_b, q_thd_b, m, l0, k_d, g_s)[Q_RD] > 0.0:
        return RECOMPRESSION
    if t_bottom >= t_max:
        return NO_LIFTOFF
    if q_r_b <= COLLAPSE_FRACTION * l0:
        return FALL
    return OK


@njit(**_DRIVER)
def hybrid_stance(
    field,
    p_c,
    p_d,
    bottom_step,
    work,
    z_start,
    from_touchdown,
    to_liftoff,
    m,
    l0,
    k_c,
    k_d,
    g_s,
    q_r_lo,
    rtol,
    atol,
    t_max,
    t_sample,
    y_sample,
    z_b,
    z_lo,
):
    """The hybrid stance: the one copy of its events, checks and statuses, for every exact kernel.

    Integrates the state z (the polar state in z[:4], then anything the vector field carries along
    with the same steps: the Jacobian's sensitivities) by :func:`.dop853.solve`:

    * from a touchdown state (``from_touchdown``: :func:`touchdown_status`, then the compression
      with ``field`` and parameters ``p_c`` from t = 0 until q_rd crosses 0 upward, watching the
      fall and the collapse; ``q_rd`` set to exactly 0 there) or from a bottom state (``z_start``
      with its q_rd, checked finite, replaced by 0, t = 0: the decompression half);
    * unless it stops at the bottom (``to_liftoff`` False): :func:`bottom_status`, then
      ``bottom_step(z_b, m, l0, k_c, k_d, g_s, work)`` (nothing for the plain stance,
      :func:`no_bottom_step`; the Jacobian's saltation), then the decompression with ``field``,
      ``p_d`` until q_r crosses q_r_lo upward, watching the recompression, the fall and the
      collapse.

    Each subphase's step cap is :func:`step_cap` of its stiffness and rtol; both have the time
    limit ``t_max`` (from touchdown, or from the bottom given) and the first four components of z
    as the step control (``N_POLAR``: the events read only those); the sample ``t_sample``
    (:func:`.dop853.solve`) goes into ``y_sample`` from the subphase it falls in (``inf``: none).
    Writes the bottom into ``z_b`` and the liftoff into ``z_lo``; returns ``(status, t_bottom,
    t_end, evaluations)``, ``t_end`` the liftoff time (the bottom's when stopping there),
    ``evaluations`` the field's evaluations (0 when nothing was integrated). The parameters are
    checked (:func:`valid_parameters`), the states by :func:`touchdown_status` or
    :func:`valid_polar`: INVALID_INPUT, nothing integrated.
    """
    nan = math.nan
    if not valid_parameters(m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol):
        return INVALID_INPUT, nan, nan, 0
    r_min = COLLAPSE_FRACTION * l0
    pe = (q_r_lo, r_min)
    t_bottom = 0.0
    evaluations = 0
    if from_touchdown:
        status = touchdown_status(z_start[Q_R], z_start[Q_RD], z_start[Q_TH], z_start[Q_THD], l0)
        if status != OK:
            return status, nan, nan, 0
        code, t_bottom, event, _, evaluations = dop853.solve(
            field,
            p_c,
            STANCE_EVENTS(),
            pe,
            COMPRESSION_DIRECTIONS,
            0.0,
            z_start,
            t_max,
            rtol,
            atol,
            step_cap(m, l0, k_c, g_s, rtol),
            N_POLAR,
            z_b,
            t_sample,
            y_sample,
            dop853.GOES_ON,
        )
        if code != dop853.EVENT or event != EV_RADIAL:
            return failure_status(code, event), nan, nan, evaluations
        z_b[Q_RD] = 0.0
        if not to_liftoff:
            return OK, t_bottom, t_bottom, evaluations
    else:
        if not valid_polar(z_start[Q_R], z_start[Q_RD], z_start[Q_TH], z_start[Q_THD], l0):
            return INVALID_INPUT, nan, nan, 0
        for i in range(z_b.shape[0]):
            z_b[i] = z_start[i]
        z_b[Q_RD] = 0.0
    status = bottom_status(z_b[Q_R], z_b[Q_TH], z_b[Q_THD], m, l0, k_d, g_s, q_r_lo, t_bottom, t_max)
    if status != OK:
        return status, t_bottom, nan, evaluations
    bottom_step(z_b, m, l0, k_c, k_d, g_s, work)
    code, t_lo, event, _, more = dop853.solve(
        field,
        p_d,
        STANCE_EVENTS(),
        pe,
        DECOMPRESSION_DIRECTIONS,
        t_bottom,
        z_b,
        t_max,
        rtol,
        atol,
        step_cap(m, l0, k_d, g_s, rtol),
        N_POLAR,
        z_lo,
        t_sample,
        y_sample,
        dop853.GOES_ON,
    )
    evaluations += more
    if code != dop853.EVENT or event != EV_LIFTOFF:
        return failure_status(code, event), t_bottom, nan, evaluations
    return OK, t_bottom, t_lo, evaluations


@njit(**_JIT)
def _nan(out):
    for j in range(out.shape[0]):
        out[j] = math.nan


@njit(**_JIT)
def _polar(q_r, q_rd, q_th, q_thd):
    """One array for a stance's three polar states (one allocation): the start in [0:4], then room
    for the bottom and the liftoff (:func:`_plain`)."""
    z = np.empty(3 * N_POLAR)
    z[Q_R] = q_r
    z[Q_RD] = q_rd
    z[Q_TH] = q_th
    z[Q_THD] = q_thd
    return z


@njit(**INLINE)
def _plain(
    z, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, from_touchdown, to_liftoff, t_sample, y_sample
):
    """:func:`hybrid_stance` of the polar state alone from z[:4] (z from :func:`_polar`): (status,
    t_bottom, t_end, bottom, liftoff, right-hand side evaluations), the states views of z."""
    y0 = z[:N_POLAR]
    y_b = z[N_POLAR : 2 * N_POLAR]
    y_lo = z[2 * N_POLAR :]
    status, t_bottom, t_end, evaluations = hybrid_stance(
        POLAR_FIELD(),
        (m, l0, k_c, g_s),
        (m, l0, k_d, g_s),
        NO_BOTTOM_STEP(),
        y_lo,  # the bottom step's work array: no_bottom_step does not touch it
        y0,
        from_touchdown,
        to_liftoff,
        m,
        l0,
        k_c,
        k_d,
        g_s,
        q_r_lo,
        rtol,
        atol,
        t_max,
        t_sample,
        y_sample,
        y_b,
        y_lo,
    )
    return status, t_bottom, t_end, y_b, y_lo, evaluations


@njit(**_JIT)
def stance_evaluations(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max):
    """(status, the right-hand side's evaluations) of :func:`stance_into`'s stance: what
    benchmarks/bench_exact.py multiplies by the cost of one evaluation (the stance's floor)."""
    z = _polar(q_r_td, q_rd_td, q_th_td, q_thd_td)
    status, _, _, _, _, evaluations = _plain(  # no sample (t = inf): z is never written
        z, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, True, True, math.inf, z
    )
    return status, evaluations


@njit(**INLINE)
def stance_into(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, out):
    """The exact stance from a polar touchdown state: writes the :data:`STANCE_NAMES` row into
    ``out[:N_STANCE]`` (NaN unless OK) and returns the status. Times from touchdown [s]."""
    _nan(out[:N_STANCE])
    z = _polar(q_r_td, q_rd_td, q_th_td, q_thd_td)
    status, t_bottom, t_stance, y_b, y_lo, _ = _plain(  # no sample (t = inf): z is never written
        z, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, True, True, math.inf, z
    )
    if status != OK:
        return status
    out[T_BOTTOM] = t_bottom
    out[T_STANCE] = t_stance
    for j in range(N_POLAR):
        out[BOTTOM + j] = y_b[j]
        out[LIFTOFF + j] = y_lo[j]
    return OK


@njit(**INLINE)
def half_into(q_r, q_rd, q_th, q_thd, m, l0, k, g_s, q_r_lo, rtol, atol, t_max, compression, out):
    """One half of the stance with stiffness k: the compression (touchdown -> bottom,
    ``compression`` True) or the decompression (bottom -> liftoff; q_rd is not read, 0 at the
    bottom). Writes ``(t_half, end state)`` into ``out[:5]`` (NaN unless OK), returns the status;
    ``t_half`` is the time from the half's start, ``t_max`` its own time limit."""
    _nan(out[:5])
    z = _polar(q_r, q_rd, q_th, q_thd)
    status, t_bottom, t_end, y_b, y_lo, _ = _plain(  # no sample (t = inf): z is never written
        z, m, l0, k, k, g_s, q_r_lo, rtol, atol, t_max, compression, not compression, math.inf, z
    )
    if status != OK:
        return status
    out[0] = t_end
    end = y_b if compression else y_lo
    for j in range(N_POLAR):
        out[1 + j] = end[j]
    return OK


@njit(**INLINE)
def state_at_into(
    t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, out
):
    """The polar state a time t after touchdown into ``out[:4]`` (NaN unless OK); returns the status.

    The stance of :func:`stance_into` (the same steps; its status: a stance that fails has no
    state), sampled at t on the integrator's dense output (compression with k_c for t before the
    bottom, decompression with k_d from it; at t_bottom the bottom state, q_rd = 0); beyond
    liftoff the stance equations with k_d continued from the liftoff state (no event, as the
    approximate maps' closed forms go on), sampled the same way. Domain 0 <= t <= t_max, else
    INVALID_INPUT.
    """
    _nan(out[:N_POLAR])
    if not (math.isfinite(t) and 0.0 <= t <= t_max):
        return INVALID_INPUT
    z = _polar(q_r_td, q_rd_td, q_th_td, q_thd_td)
    y_at = np.full(N_POLAR, math.nan)
    status, t_bottom, t_stance, y_b, y_lo, _ = _plain(
        z, m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, True, True, t, y_at
    )
    if status != OK:
        return status
    if t >= t_stance:  # beyond liftoff: the stance equations continued
        code, _, _, _, _ = dop853.solve(
            POLAR_FIELD(),
            (m, l0, k_d, g_s),
            STANCE_EVENTS(),
            (q_r_lo, COLLAPSE_FRACTION * l0),
            CONTINUATION_DIRECTIONS,
            t_stance,
            y_lo,
            t_max,
            rtol,
            atol,
            step_cap(m, l0, k_d, g_s, rtol),
            N_POLAR,
            z[:N_POLAR],  # the end state (the sample's, unread): over the touchdown state
            t,
            y_at,
            dop853.ENDS,
        )
        if code != dop853.SAMPLED:
            return failure_status(code, -1)
    for j in range(N_POLAR):
        out[j] = y_at[j]
    return OK
