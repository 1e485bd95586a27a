# ----------------------------------------------------------------------------------------------
# GENERATED FILE -- DO NOT EDIT. Any hand edit is overwritten and fails `slipmaps generate --check`.
# Source:    derive/numerics.py
# Template:  derive/templates/exact_stance.py.j2
# Rebuild:   slipmaps generate        (check: slipmaps generate --check)
# Tools:     sympy 1.14.0, jinja2 3.1.6
# Lines:     at most 110 characters (derive/wrap.py breaks longer statements inside their brackets)
# Depends on (content hashes; a change here re-keys numba's cache of this file):
#   dop853.py sha256:5e34e44e22581374
#   slip_model.py sha256:4cc44e1baaa041ba
# ----------------------------------------------------------------------------------------------
"""The exact stance: the stance equations of motion (2)-(3) integrated by DOP853 (:mod:`.dop853`), the
support module of the map ``"exact"`` (rendered from derive/templates/exact_stance.py.j2).

The same hybrid simulation as the ``solve_ivp`` reference (runtime/exact/reference.py; its
docstring states the conventions, the events and the statuses):

* compression with ``k_c`` from touchdown until ``q_rd`` crosses 0 upward (the bottom; ``q_rd`` set
  to exactly 0 there, report section 2.2.1), then decompression with ``k_d`` until ``q_r`` crosses
  ``q_r_lo`` upward (liftoff); the right-hand side is the generated ``slip_model.stance_polar_rhs``
  plus, with a leg damping ``c > 0``, the damper's term ``slip_model.stance_polar_damping`` (radial
  force -k (q_r - l0) - c q_rd; at c = 0 the lossless field's arithmetic, untouched);
* liftoff with damping (option ``liftoff``): ``"force"`` ends the stance where the leg force
  ``k_d (l0 - q_r) - c q_rd`` falls through 0 (the ground cannot pull) or at ``q_r = q_r_lo``,
  whichever comes first (in one step, the earlier root; a tie goes to the length); ``"length"`` at
  ``q_r = q_r_lo`` only. At c = 0 the force is ``k_d (l0 - q_r) > 0`` before ``q_r`` reaches
  ``l0 >= q_r_lo``: the force event is not watched and both give the lossless stance;
* failures: ``TOUCHDOWN_NOT_COMPRESSING`` (``q_rd >= 0`` at touchdown), ``FALL`` (``cos q_th``
  crosses 0, or ``q_r <= COLLAPSE_FRACTION l0``), ``NO_LIFTOFF`` (bottom leg length ``>= q_r_lo``,
  or the stance time limit reached), ``RECOMPRESSION`` (the ``k_d`` spring cannot extend the leg at
  the bottom, or ``q_rd`` crosses 0 downward after it), ``INTEGRATION_FAILED``;
* the reference's tolerances and time limit (derive/model/simulation.py, the model kernels
  ``stance_time_limit`` and ``max_step``) and, at the default rtol, its step cap (the two take the
  same steps); at other tolerances the cap scales with the tolerance (:func:`step_cap`) and the
  events inside a step are found by the integrator's own checks.

One driver, :func:`hybrid_stance`, holds the hybrid stance (events, checks, statuses) for every
kernel: it takes the vector field (a :func:`.dop853.static` handle; the integrated state may carry
more than the polar state, controlled by its first four components), a step to run at the bottom
(nothing, or the Jacobian's saltation) and the stance's parameter record :class:`Stance`. The
Jacobian integrates the state with its sensitivity S = dy/dw (w = the touchdown state, k_c, k_d, c)
by the variational equations (``slip_model.stance_polar_tangent``, plus the damper's
``stance_polar_damping_tangent`` for c > 0 and in c's own column), with the saltation matrix at the
bottom and the map to the liftoff surface (q_r = q_r_lo, or the zero of the leg force, which also
depends on k_d and c): the same steps, events and states as the stance.

The external kernels the generated code calls (derive/maps/exact.py declares them), each inlined
into its caller, never raising (NaN and a status unless OK; INVALID_INPUT, nothing integrated, for
a non-finite argument, a state outside its domain, parameters outside SlipParams' or non-positive
tolerances): :func:`stance`, :func:`stance_jacobian` (its values into ``out``), :func:`compression`,
:func:`decompression` (q_rd_b not read: 0 at a bottom) and :func:`state_at`.
"""

import math
from collections import namedtuple

import numpy as np
from numba import njit

from . import dop853
from .slip_model import (max_step, stance_polar_damping, stance_polar_damping_tangent, stance_polar_rhs,
    stance_polar_tangent, stance_time_limit)
from .status import (STATUS_FALL, STATUS_INTEGRATION_FAILED, STATUS_INVALID_INPUT, STATUS_NO_LIFTOFF,
    STATUS_OK, STATUS_RECOMPRESSION, STATUS_TOUCHDOWN_NOT_COMPRESSING)

__all__ = ["STANCE_NAMES", "Stance", "compression", "decompression", "hybrid_stance", "stance",
    "stance_jacobian", "state_at"]

#: A stance row's columns (the index's stance outputs) and where its times and states are.
STANCE_NAMES = ('t_bottom', 't_stance', 'bottom_q_r', 'bottom_q_rd', 'bottom_q_th', 'bottom_q_thd',
    'liftoff_q_r', 'liftoff_q_rd', 'liftoff_q_th', 'liftoff_q_thd')
N_STANCE = 10
T_BOTTOM, T_STANCE, BOTTOM, LIFTOFF = 0, 1, 2, 6
# The polar state q_r, q_rd, q_th, q_thd: its components by position.
Q_R, Q_RD, Q_TH, Q_THD = 0, 1, 2, 3
N_POLAR = 4
#: The Jacobian's inputs (its columns): the touchdown state, then the two stiffnesses and the damping.
INPUTS = ('q_r_td', 'q_rd_td', 'q_th_td', 'q_thd_td', 'k_c', 'k_d', 'c')
N_IN = len(INPUTS)
K_C, K_D, C = INPUTS.index("k_c"), INPUTS.index("k_d"), INPUTS.index("c")
#: The codes of the option ``liftoff`` (derive/maps/exact.py): the leg force's zero or q_r = q_r_lo.
LIFTOFF_FORCE, LIFTOFF_LENGTH = 0, 1
#: The augmented state: the polar state, then S row by row (S[i, j] at N_POLAR + N_IN i + j).
N_AUG = N_POLAR + N_POLAR * N_IN
#: The leg has collapsed (FALL) at this fraction of l0.
COLLAPSE_FRACTION = 0.001
#: The tolerance at which the step cap is the solve_ivp reference's (the model kernel ``max_step``).
CAP_RTOL = 1e-11

# Events, in the reference's order (ties go to the first); every run watches the same event functions
# with its own directions (NaN: not watched), so the integrator is compiled once per vector field.
# q_r - q_r_lo, q_rd, cos q_th, q_r - r_min, the leg force k_d (l0 - q_r) - c q_rd
EV_LIFTOFF, EV_RADIAL, EV_FALL, EV_COLLAPSE, EV_FORCE = 0, 1, 2, 3, 4
#: Compression: the bottom (q_rd up through 0), fall, collapse.
COMPRESSION_DIRECTIONS = np.array([math.nan, +1.0, -1.0, -1.0, math.nan])
#: Decompression: liftoff (q_r up through q_r_lo), recompression (q_rd down through 0), fall, collapse.
DECOMPRESSION_DIRECTIONS = np.array([+1.0, -1.0, -1.0, -1.0, math.nan])
#: Decompression of a damped leg with ``liftoff="force"``: also the leg force down through 0.
FORCE_DECOMPRESSION_DIRECTIONS = np.array([+1.0, -1.0, -1.0, -1.0, -1.0])
#: The stance equations continued beyond liftoff (:func:`state_at_into`): no event.
CONTINUATION_DIRECTIONS = np.array([math.nan, math.nan, math.nan, math.nan, math.nan])

OK, INVALID_INPUT, NO_LIFTOFF, FALL = STATUS_OK, STATUS_INVALID_INPUT, STATUS_NO_LIFTOFF, STATUS_FALL
TOUCHDOWN_NOT_COMPRESSING, RECOMPRESSION = STATUS_TOUCHDOWN_NOT_COMPRESSING, STATUS_RECOMPRESSION
INTEGRATION_FAILED = STATUS_INTEGRATION_FAILED

#: A stance's parameters, one record through the integrator's layers: the SLIP parameters, the
#: tolerances, the time limit [s], the leg damping c [N s/m] (default 0) and the liftoff option's
#: code (default :data:`LIFTOFF_FORCE`) (a half's stiffness in both k_c and k_d).
Stance = namedtuple(
    "Stance",
    ("m", "l0", "k_c", "k_d", "g_s", "q_r_lo", "rtol", "atol", "t_max", "c", "liftoff"),
    defaults=(0.0, float(LIFTOFF_FORCE)),
)

_JIT = {"cache": True, "error_model": "numpy"}
#: The layers between a kernel and the driver are inlined into it (numba's IR inlining): each cached
#: function of a call chain re-optimises everything it links, so the first call compiles in a third
#: less time. An inlined body is compiled with its caller's options.
INLINE = {**_JIT, "inline": "always"}
#: The driver takes the vector field and the bottom step as arguments: not cached itself (its
#: Dispatcher-typed signature would never hit the cache) and inlined into each caller.
_DRIVER = {"error_model": "numpy", "inline": "always"}


@njit(**_JIT)
def polar_field(t, y, p, dy):
    """The stance vector field (report eqs (2)-(3), with the leg damper's term for c != 0) on y[:4];
    p = (m, l0, k, g_s, c)."""
    m, l0, k, g_s, c = p
    d = stance_polar_rhs(y[Q_R], y[Q_RD], y[Q_TH], y[Q_THD], m, l0, k, g_s)
    dy[Q_R] = d[Q_R]
    dy[Q_RD] = d[Q_RD]
    dy[Q_TH] = d[Q_TH]
    dy[Q_THD] = d[Q_THD]
    if c != 0.0:
        e = stance_polar_damping(y[Q_R], y[Q_RD], y[Q_TH], y[Q_THD], m, c)
        dy[Q_R] += e[Q_R]
        dy[Q_RD] += e[Q_RD]
        dy[Q_TH] += e[Q_TH]
        dy[Q_THD] += e[Q_THD]


@njit(**_JIT)
def stance_events(t, y, pe, g):
    """The stance's event functions (their directions select them per subphase); pe = (q_r_lo, r_min,
    k_d, l0, c)."""
    q_r_lo, r_min, k_d, l0, c = pe
    g[EV_LIFTOFF] = y[Q_R] - q_r_lo
    g[EV_RADIAL] = y[Q_RD]
    g[EV_FALL] = math.cos(y[Q_TH])
    g[EV_COLLAPSE] = y[Q_R] - r_min
    g[EV_FORCE] = leg_force(y[Q_R], y[Q_RD], k_d, l0, c)


@njit(**_JIT)
def leg_force(q_r, q_rd, k, l0, c):
    """The leg's push on the ground [N]: k (l0 - q_r) - c q_rd (the ground cannot pull)."""
    return k * (l0 - q_r) - c * q_rd


@njit(**_JIT)
def event_record(s):
    """The event functions' parameters of the stance ``s`` (:func:`stance_events`' ``pe``)."""
    return (s.q_r_lo, COLLAPSE_FRACTION * s.l0, s.k_d, s.l0, s.c)


@njit(**_JIT)
def decompression_directions(s):
    """The decompression's events: with ``liftoff="force"`` and c > 0 also the leg force's zero."""
    if s.liftoff == LIFTOFF_FORCE and s.c > 0.0:
        return FORCE_DECOMPRESSION_DIRECTIONS
    return DECOMPRESSION_DIRECTIONS


@njit(**_JIT)
def no_bottom_step(z_b, s, work):
    """The plain stance's step at the bottom: nothing (the Jacobian's is its saltation)."""


POLAR_FIELD = dop853.static(polar_field, state_length=N_POLAR)
STANCE_EVENTS = dop853.static(stance_events)
NO_BOTTOM_STEP = dop853.static(no_bottom_step)


@njit(**_JIT)
def step_cap(m, l0, k, g_s, rtol):
    """The step cap of a subphase with stiffness k [s]: the reference's (``max_step``) at rtol
    :data:`CAP_RTOL`, scaled as the step of an 8th-order method scales with its tolerance, (rtol /
    CAP_RTOL) ** (1/8): at 1e-6 the cap is 4.2x the reference's, at 1e-3 10x. The events are found by
    the integrator's sign checks at the steps' ends and inside them, not by the cap."""
    return max_step(m, l0, k, g_s) * (rtol / CAP_RTOL) ** 0.125


@njit(**_JIT)
def failure_status(code, event):
    """The status of a subphase that did not reach its goal event (the reference's ``failure``)."""
    if code == dop853.FAILED:
        return INTEGRATION_FAILED
    if code == dop853.FINISHED:
        return NO_LIFTOFF
    if event == EV_RADIAL:  # q_rd down through 0: only watched in the decompression
        return RECOMPRESSION
    return FALL


@njit(**_JIT)
def valid_polar(q_r, q_rd, q_th, q_thd, l0):
    """A polar state: finite, 0 < q_r <= l0, |q_th| < pi/2 (the API's check)."""
    finite = math.isfinite(q_r) and math.isfinite(q_rd) and math.isfinite(q_th) and math.isfinite(q_thd)
    return finite and 0.0 < q_r <= l0 and abs(q_th) < 0.5 * math.pi


@njit(**_JIT)
def valid_parameters(s):
    """SlipParams' domain (finite, positive, 0 < q_r_lo <= l0, c >= 0), positive finite tolerances
    (the integrator's step control needs them: a NaN tolerance or m = 0 never ends a step) and a
    liftoff option's code."""
    finite = True
    for v in s:
        finite = finite and math.isfinite(v)
    positive = s.m > 0.0 and s.l0 > 0.0 and s.k_c > 0.0 and s.k_d > 0.0 and s.g_s > 0.0
    option = s.liftoff == LIFTOFF_FORCE or s.liftoff == LIFTOFF_LENGTH
    return (finite and positive and s.rtol > 0.0 and s.atol > 0.0 and 0.0 < s.q_r_lo <= s.l0 and s.c >= 0.0
        and option)


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
def bottom_status(q_r_b, q_th_b, q_thd_b, s, t_bottom):
    """The checks of a bottom state (q_rd = 0) before the decompression: NO_LIFTOFF (q_r_b >=
    q_r_lo: q_r can never cross q_r_lo upward), RECOMPRESSION (the k_d spring cannot start
    extending the leg), NO_LIFTOFF (no time left), FALL (a collapsed leg), else OK."""
    if q_r_b >= s.q_r_lo:
        return NO_LIFTOFF
    if not stance_polar_rhs(q_r_b, 0.0, q_th_b, q_thd_b, s.m, s.l0, s.k_d,
        s.g_s)[Q_RD] > 0.0:  # q_rd = 0: no damping
        return RECOMPRESSION
    if t_bottom >= s.t_max:
        return NO_LIFTOFF
    if q_r_b <= COLLAPSE_FRACTION * s.l0:
        return FALL
    return OK


@njit(**_DRIVER)
def hybrid_stance(
    field, p_c, p_d, bottom_step, work, z_start, from_touchdown, to_liftoff, s, t_sample, y_sample, z_b, z_lo
):
    """The hybrid stance: the one copy of its events, checks and statuses, for every kernel.

    Integrates the state z (the polar state in z[:4], then what the vector field carries along with
    the same steps) by :func:`.dop853.solve`, the parameters the record ``s`` (:class:`Stance`):

    * from a touchdown state (``from_touchdown``: :func:`touchdown_status`, then the compression
      with ``field`` and parameters ``p_c`` until q_rd crosses 0 upward; ``q_rd`` set to exactly 0
      there) or from a bottom state (``z_start``, its q_rd replaced by 0, t = 0: the decompression);
    * unless it stops at the bottom (``to_liftoff`` False): :func:`bottom_status`, then
      ``bottom_step(z_b, s, work)``, then the decompression with ``field``, ``p_d`` until q_r
      crosses q_r_lo upward (or the leg force falls through 0: :func:`decompression_directions`),
      watching the recompression, the fall and the collapse.

    Each subphase's step cap is :func:`step_cap` of its stiffness; both have the time limit
    ``s.t_max`` and the first four components of z as the step control; the sample ``t_sample``
    goes into ``y_sample`` (``inf``: none). Writes the bottom into ``z_b``, the liftoff into
    ``z_lo``; returns ``(status, t_bottom, t_end, evaluations, the event that ended the stance)``
    (the event -1 unless it reached liftoff: :data:`EV_LIFTOFF` or :data:`EV_FORCE`).
    """
    nan = math.nan
    if not valid_parameters(s):
        return INVALID_INPUT, nan, nan, 0, -1
    pe = event_record(s)
    t_bottom = 0.0
    evaluations = 0
    if from_touchdown:
        status = touchdown_status(z_start[Q_R], z_start[Q_RD], z_start[Q_TH], z_start[Q_THD], s.l0)
        if status != OK:
            return status, nan, nan, 0, -1
        code, t_bottom, event, _, evaluations = dop853.solve(
            field, p_c, STANCE_EVENTS(), pe, COMPRESSION_DIRECTIONS, 0.0, z_start, s.t_max, s.rtol, s.atol,
            step_cap(s.m, s.l0, s.k_c, s.g_s, s.rtol), N_POLAR, z_b, t_sample, y_sample, dop853.GOES_ON,
        )  # fmt: skip
        if code != dop853.EVENT or event != EV_RADIAL:
            return failure_status(code, event), nan, nan, evaluations, -1
        z_b[Q_RD] = 0.0
        if not to_liftoff:
            return OK, t_bottom, t_bottom, evaluations, -1
    else:
        if not valid_polar(z_start[Q_R], z_start[Q_RD], z_start[Q_TH], z_start[Q_THD], s.l0):
            return INVALID_INPUT, nan, nan, 0, -1
        for i in range(z_b.shape[0]):
            z_b[i] = z_start[i]
        z_b[Q_RD] = 0.0
    status = bottom_status(z_b[Q_R], z_b[Q_TH], z_b[Q_THD], s, t_bottom)
    if status != OK:
        return status, t_bottom, nan, evaluations, -1
    bottom_step(z_b, s, work)
    code, t_lo, event, _, more = dop853.solve(
        field, p_d, STANCE_EVENTS(), pe, decompression_directions(s), t_bottom, z_b, s.t_max, s.rtol, s.atol,
        step_cap(s.m, s.l0, s.k_d, s.g_s, s.rtol), N_POLAR, z_lo, t_sample, y_sample, dop853.GOES_ON,
    )  # fmt: skip
    evaluations += more
    if code != dop853.EVENT or not (event == EV_LIFTOFF or event == EV_FORCE):
        return failure_status(code, event), t_bottom, nan, evaluations, -1
    return OK, t_bottom, t_lo, evaluations, event


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
def _plain(z, s, from_touchdown, to_liftoff, t_sample, y_sample):
    """:func:`hybrid_stance` of the polar state alone from z[:4] (z from :func:`_polar`): (status,
    t_bottom, t_end, bottom, liftoff, right-hand side evaluations), the states views of z."""
    y0 = z[:N_POLAR]
    y_b = z[N_POLAR : 2 * N_POLAR]
    y_lo = z[2 * N_POLAR :]
    status, t_bottom, t_end, evaluations, _ = hybrid_stance(
        POLAR_FIELD(), (s.m, s.l0, s.k_c, s.g_s, s.c), (s.m, s.l0, s.k_d, s.g_s, s.c), NO_BOTTOM_STEP(),
        y_lo,  # the bottom step's work array: no_bottom_step does not touch it
        y0, from_touchdown, to_liftoff, s, t_sample, y_sample, y_b, y_lo,
    )  # fmt: skip
    return status, t_bottom, t_end, y_b, y_lo, evaluations


@njit(**_JIT)
def stance_evaluations(q_r_td, q_rd_td, q_th_td, q_thd_td, s):
    """(status, the right-hand side's evaluations) of :func:`stance_into`'s stance: what
    benchmarks/bench_exact.py multiplies by the cost of one evaluation (the stance's floor)."""
    z = _polar(q_r_td, q_rd_td, q_th_td, q_thd_td)
    status, _, _, _, _, evaluations = _plain(z, s, True, True, math.inf, z)  # no sample: z never written
    return status, evaluations


@njit(**INLINE)
def stance_into(q_r_td, q_rd_td, q_th_td, q_thd_td, s, out):
    """The exact stance from a polar touchdown state: writes the :data:`STANCE_NAMES` row into
    ``out[:N_STANCE]`` (NaN unless OK) and returns the status. Times from touchdown [s]."""
    _nan(out[:N_STANCE])
    z = _polar(q_r_td, q_rd_td, q_th_td, q_thd_td)
    status, t_bottom, t_stance, y_b, y_lo, _ = _plain(z, s, True, True, math.inf, z)
    if status != OK:
        return status
    out[T_BOTTOM] = t_bottom
    out[T_STANCE] = t_stance
    for j in range(N_POLAR):
        out[BOTTOM + j] = y_b[j]
        out[LIFTOFF + j] = y_lo[j]
    return OK


@njit(**INLINE)
def half_into(q_r, q_rd, q_th, q_thd, s, compression, out):
    """One half of the stance with the stiffness of ``s`` (k_c = k_d): the compression (touchdown ->
    bottom, ``compression`` True) or the decompression (bottom -> liftoff; q_rd not read). Writes
    ``(t_half, end state)`` into ``out[:5]`` (NaN unless OK), returns the status; ``t_half`` from
    the half's start."""
    _nan(out[:5])
    z = _polar(q_r, q_rd, q_th, q_thd)
    status, _, t_end, y_b, y_lo, _ = _plain(z, s, compression, not compression, math.inf, z)
    if status != OK:
        return status
    out[0] = t_end
    end = y_b if compression else y_lo
    for j in range(N_POLAR):
        out[1 + j] = end[j]
    return OK


@njit(**INLINE)
def state_at_into(t, q_r_td, q_rd_td, q_th_td, q_thd_td, s, out):
    """The polar state a time t after touchdown into ``out[:4]`` (NaN unless OK); returns the status:
    the stance of :func:`stance_into` (the same steps and status) sampled at t on the integrator's
    dense output; beyond liftoff the stance equations with k_d continued from the liftoff state (no
    event, as the approximate maps' closed forms go on). Domain 0 <= t <= t_max, else INVALID_INPUT."""
    _nan(out[:N_POLAR])
    if not (math.isfinite(t) and 0.0 <= t <= s.t_max):
        return INVALID_INPUT
    z = _polar(q_r_td, q_rd_td, q_th_td, q_thd_td)
    y_at = np.full(N_POLAR, math.nan)
    status, _, t_stance, _, y_lo, _ = _plain(z, s, True, True, t, y_at)
    if status != OK:
        return status
    if t >= t_stance:  # beyond liftoff: the stance equations continued
        code, _, _, _, _ = dop853.solve(
            POLAR_FIELD(), (s.m, s.l0, s.k_d, s.g_s, s.c), STANCE_EVENTS(), event_record(s),
            CONTINUATION_DIRECTIONS, t_stance, y_lo, s.t_max, s.rtol, s.atol,
            step_cap(s.m, s.l0, s.k_d, s.g_s, s.rtol), N_POLAR,
            z[:N_POLAR],  # the end state (the sample's, unread): over the touchdown state
            t, y_at, dop853.ENDS,
        )  # fmt: skip
        if code != dop853.SAMPLED:
            return failure_status(code, -1)
    for j in range(N_POLAR):
        out[j] = y_at[j]
    return OK


# ----------------------------------------------------------------------------------------------
# The Jacobian: variational equations with saltation
# ----------------------------------------------------------------------------------------------
@njit(**_JIT)
def augmented_field(t, z, p, dz):
    """d/dt (y, S): the stance field and its variational equations, S column by column
    (``slip_model.stance_polar_tangent``, and the damper's ``stance_polar_damping_tangent`` for
    c != 0 and in c's own column); p = (m, l0, k, g_s, column of k, c)."""
    m, l0, k, g_s, k_column, c = p
    polar_field(t, z, (m, l0, k, g_s, c), dz)
    q_r, q_rd, q_th, q_thd = z[Q_R], z[Q_RD], z[Q_TH], z[Q_THD]
    col = int(k_column)
    for j in range(N_IN):
        at = N_POLAR + j
        d = stance_polar_tangent(
            q_r, q_rd, q_th, q_thd, z[at], z[at + N_IN], z[at + 2 * N_IN], z[at + 3 * N_IN],
            1.0 if j == col else 0.0, m, l0, k, g_s,
        )  # fmt: skip
        dz[at] = d[Q_R]
        dz[at + N_IN] = d[Q_RD]
        dz[at + 2 * N_IN] = d[Q_TH]
        dz[at + 3 * N_IN] = d[Q_THD]
        if c != 0.0 or j == C:
            e = stance_polar_damping_tangent(
                q_r, q_rd, q_th, q_thd, z[at], z[at + N_IN], z[at + 2 * N_IN], z[at + 3 * N_IN],
                1.0 if j == C else 0.0, m, c,
            )  # fmt: skip
            dz[at] += e[Q_R]
            dz[at + N_IN] += e[Q_RD]
            dz[at + 2 * N_IN] += e[Q_TH]
            dz[at + 3 * N_IN] += e[Q_THD]


AUGMENTED_FIELD = dop853.static(augmented_field)


@njit(**_JIT)
def _event_time_gradient(z, component, rate, dt):
    """dt_event/dw = -(dg/dy) S / (dg/dy . f) for g = y[component] - const (rate = dg/dt)."""
    for j in range(N_IN):
        dt[j] = -z[N_POLAR + N_IN * component + j] / rate


@njit(**_JIT)
def _force_time_gradient(z, f, s, dt):
    """dt_event/dw of the leg force's zero, g = k_d (l0 - q_r) - c q_rd: -((dg/dy) S + dg/dw) /
    (dg/dy . f), dg/dy = (-k_d, -c, 0, 0), dg/dk_d = l0 - q_r, dg/dc = -q_rd."""
    rate = -s.k_d * f[Q_R] - s.c * f[Q_RD]
    for j in range(N_IN):
        grad = -s.k_d * z[N_POLAR + N_IN * Q_R + j] - s.c * z[N_POLAR + N_IN * Q_RD + j]
        if j == K_D:
            grad += s.l0 - z[Q_R]
        if j == C:
            grad -= z[Q_RD]
        dt[j] = -grad / rate


#: The bottom step's record: dt_bottom/dw (N_IN), then d(bottom)/dw row by row (N_POLAR x N_IN).
N_WORK = N_IN + N_POLAR * N_IN


@njit(**_JIT)
def bottom_saltation(z_b, s, work):
    """The Jacobian's step at the bottom (g = q_rd = 0, the switch f_c -> f_d), after the hybrid
    stance's bottom checks: the event time's gradient into ``work[:N_IN]``, the bottom state's
    derivative on the surface q_rd = 0 into ``work[N_IN:]``, and S- -> S+ (the saltation matrix
    I + (f_d - f_c) (dg/dy)^T / (dg/dy . f_c)) in ``z_b``."""
    f_c = np.empty(N_POLAR)
    f_d = np.empty(N_POLAR)
    polar_field(0.0, z_b, (s.m, s.l0, s.k_c, s.g_s, s.c), f_c)
    polar_field(0.0, z_b, (s.m, s.l0, s.k_d, s.g_s, s.c), f_d)
    dt_b = work[:N_IN]
    _event_time_gradient(z_b, Q_RD, f_c[Q_RD], dt_b)
    for i in range(N_POLAR):
        for j in range(N_IN):
            s_ij = z_b[N_POLAR + N_IN * i + j]
            work[N_IN + N_IN * i + j] = s_ij + f_c[i] * dt_b[j]
            z_b[N_POLAR + N_IN * i + j] = s_ij - (f_d[i] - f_c[i]) * dt_b[j]


BOTTOM_SALTATION = dop853.static(bottom_saltation)


@njit(**INLINE)
def jacobian_into(q_r_td, q_rd_td, q_th_td, q_thd_td, s, out, jac):
    """The stance (the :data:`STANCE_NAMES` row into ``out``, as :func:`stance_into`) and its Jacobian
    d(stance row)/d(:data:`INPUTS`) into ``jac`` (N_STANCE x N_IN); NaN unless OK; returns the
    status. S = [I | 0 | 0] at touchdown; at liftoff dt_lo/dw = -((dg/dy) S + dg/dw) / (dg/dy . f_d)
    and d(liftoff)/dw = S + f_d dt_lo/dw (the map to the liftoff surface: g = q_r - q_r_lo, or the
    leg force g = k_d (l0 - q_r) - c q_rd when it ended the stance, whose dg/dw has k_d's and c's)."""
    for i in range(N_STANCE):
        out[i] = math.nan
        for j in range(N_IN):
            jac[i, j] = math.nan
    z = np.zeros(N_AUG)
    z[Q_R] = q_r_td
    z[Q_RD] = q_rd_td
    z[Q_TH] = q_th_td
    z[Q_THD] = q_thd_td
    for i in range(N_POLAR):
        z[N_POLAR + N_IN * i + i] = 1.0
    z_b = np.empty(N_AUG)
    z_lo = np.empty(N_AUG)
    work = np.empty(N_WORK)
    status, t_bottom, t_stance, _, ended = hybrid_stance(
        AUGMENTED_FIELD(), (s.m, s.l0, s.k_c, s.g_s, float(K_C), s.c), (s.m, s.l0, s.k_d, s.g_s, float(K_D),
            s.c),
        BOTTOM_SALTATION(), work, z, True, True, s,
        math.inf, work,  # no sample: the sample array (work) is never written by the integrator
        z_b, z_lo,
    )  # fmt: skip
    if status != OK:
        return status
    f_lo = np.empty(N_POLAR)
    polar_field(0.0, z_lo, (s.m, s.l0, s.k_d, s.g_s, s.c), f_lo)
    dt_lo = np.empty(N_IN)
    if ended == EV_FORCE:
        _force_time_gradient(z_lo, f_lo, s, dt_lo)
    else:
        _event_time_gradient(z_lo, Q_R, f_lo[Q_R], dt_lo)
        if s.liftoff == LIFTOFF_FORCE and s.c == 0.0 and s.q_r_lo == s.l0:
            # c = 0 at the rest length: any c > 0 lifts off on the force's zero, which meets q_r = l0
            # here; c's column is the derivative from c > 0 (the force surface; the others agree)
            by_force = np.empty(N_IN)
            _force_time_gradient(z_lo, f_lo, s, by_force)
            dt_lo[C] = by_force[C]
    out[T_BOTTOM] = t_bottom
    out[T_STANCE] = t_stance
    for i in range(N_POLAR):
        out[BOTTOM + i] = z_b[i]
        out[LIFTOFF + i] = z_lo[i]
    for j in range(N_IN):
        jac[T_BOTTOM, j] = work[j]
        jac[T_STANCE, j] = dt_lo[j]
        for i in range(N_POLAR):
            jac[BOTTOM + i, j] = work[N_IN + N_IN * i + j]
            jac[LIFTOFF + i, j] = z_lo[N_POLAR + N_IN * i + j] + f_lo[i] * dt_lo[j]
    return OK


# ----------------------------------------------------------------------------------------------
# The external kernels (derive/maps/exact.py declares their arguments and outputs)
# ----------------------------------------------------------------------------------------------
@njit(**INLINE)
def _stance(m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, c, liftoff):
    """The parameter record of a stance (its time limit from the parameters)."""
    t_max = stance_time_limit(m, l0, k_c, k_d, g_s)
    return Stance(m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, t_max, c, liftoff)


@njit(**INLINE)
def stance(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff):
    """The exact stance from a polar touchdown state: the stance row, then the status."""
    out = np.empty(N_STANCE)
    s = _stance(m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, c, liftoff)
    code = stance_into(q_r_td, q_rd_td, q_th_td, q_thd_td, s, out)
    return (out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8], out[9], code)


@njit(**INLINE)
def stance_jacobian(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff,
        out):
    """The exact stance and its Jacobian with respect to :data:`INPUTS` into ``out``: the stance row,
    then the Jacobian row-major; returns the status (``out`` all NaN unless OK)."""
    values = np.empty(N_STANCE)
    jac = np.empty((N_STANCE, N_IN))
    s = _stance(m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, c, liftoff)
    code = jacobian_into(q_r_td, q_rd_td, q_th_td, q_thd_td, s, values, jac)
    out[:N_STANCE] = values
    out[N_STANCE:] = jac.ravel()
    return code


@njit(**INLINE)
def compression(q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, g_s, q_r_lo, c, rtol, atol):
    """The compression half, touchdown -> bottom with k_c: (t_half, end_q_r, end_q_rd, end_q_th,
    end_q_thd, status), t_half the time of the bottom; its time limit with k_c for both springs."""
    out = np.empty(5)
    s = _stance(m, l0, k_c, k_c, g_s, q_r_lo, rtol, atol, c, float(LIFTOFF_FORCE))  # no liftoff
    code = half_into(q_r_td, q_rd_td, q_th_td, q_thd_td, s, True, out)
    return (out[0], out[1], out[2], out[3], out[4], code)


@njit(**INLINE)
def decompression(q_r_b, q_rd_b, q_th_b, q_thd_b, m, l0, k_d, g_s, q_r_lo, c, rtol, atol, liftoff):
    """The decompression half, bottom -> liftoff with k_d (q_rd_b not read, 0 at the bottom):
    (t_half, end_q_r, end_q_rd, end_q_th, end_q_thd, status), t_half from the bottom."""
    out = np.empty(5)
    s = _stance(m, l0, k_d, k_d, g_s, q_r_lo, rtol, atol, c, liftoff)
    code = half_into(q_r_b, q_rd_b, q_th_b, q_thd_b, s, False, out)
    return (out[0], out[1], out[2], out[3], out[4], code)


@njit(**INLINE)
def state_at(t, q_r_td, q_rd_td, q_th_td, q_thd_td, m, l0, k_c, k_d, g_s, c, q_r_lo, rtol, atol, liftoff):
    """The polar state a time t after touchdown: (q_r, q_rd, q_th, q_thd, status) (k_c until the
    bottom, then k_d; beyond liftoff the stance equations continued; the status is the stance's)."""
    out = np.empty(N_POLAR)
    s = _stance(m, l0, k_c, k_d, g_s, q_r_lo, rtol, atol, c, liftoff)
    code = state_at_into(t, q_r_td, q_rd_td, q_th_td, q_thd_td, s, out)
    return (out[0], out[1], out[2], out[3], code)
