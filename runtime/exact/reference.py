"""Exact (numerical) hybrid simulation of the SLIP: the ground truth for the approximate maps.

Conventions (report Table 1, SI units throughout)
--------------------------------------------------
* Leg angle ``q_th`` is measured from the vertical, counterclockwise positive. The body sits at
  ``(b_x, b_y) = (-q_r sin q_th, q_r cos q_th)`` relative to the toe, which is at the origin of a
  flat ground ``y = 0`` during stance.
* Running toward ``+x``, at touchdown normally ``q_th > 0`` (toe ahead of the body) and
  ``q_thd < 0``; running toward ``-x`` (a negative apex speed) is its mirror image. A step's
  direction is the sign of its apex speed (0: a hop in place); the liftoff must not move against it
  (``LIFTOFF_BACKWARD``). The touchdown ground may lie ``ground`` higher than the ground under the
  apex (a step up is positive); heights after touchdown are above the new ground.
* Polar stance state, everywhere in this module: ``(q_r, q_rd, q_th, q_thd)`` (leg length, its
  rate, leg angle, its rate). Cartesian stance state: ``(b_x, b_xd, b_y, b_yd)`` of the body
  relative to the toe.
* The leg spring has stiffness ``k_c`` while compressing (from touchdown to the bottom) and ``k_d``
  after the bottom (report section 2.2.1, the force ``F_s``); gravity is ``g_s`` in stance and
  ``g_f`` in flight.

Events (report section 2.1)
---------------------------
* Apex: ``b_yd = 0`` in flight. Touchdown: the foot of the leg (length ``q_r_td``, angle
  ``q_th_td`` at the apex, swinging at ``retraction_rate`` after it) meets the ground, which needs
  the apex above the touchdown height ``ground + q_r_td cos q_th_td`` (else ``APEX_TOO_LOW``). The
  flight phases are ballistic, solved by the generated kernels ``flight.apex_to_touchdown`` (closed
  form for a leg held still, Newton's method on the foot's height for a swinging one) and
  ``flight.liftoff_to_apex``; the apex-return inputs beyond the apex and the angle (``ground``,
  ``retraction_rate``, derive/params.py) go to the descent by name.
* Bottom: ``q_rd`` crosses 0 upward during stance (end of compression). The state is continuous
  across the bottom, only the stiffness switches from ``k_c`` to ``k_d``; ``q_rd`` is set to exactly
  0 there (the event root has ``|q_rd|`` ~ 1e-15), so the stance energy jumps by
  ``1/2 (k_d - k_c)(l0 - q_r_b)^2`` (report eq 97).
* Liftoff: ``q_r`` crosses ``q_r_lo`` upward during decompression. Whether the body then moves up
  and forward is judged by ``liftoff_to_apex`` (``LIFTOFF_DOWNWARD`` / ``LIFTOFF_BACKWARD``).
* Failure events, all terminal, reported as :class:`Status` codes and never raised:
  ``FALL`` when ``cos q_th`` crosses 0 (body height ``b_y = 0``) or the leg length collapses to
  ``<= COLLAPSE_FRACTION * l0``; ``RECOMPRESSION`` when ``q_rd`` crosses 0 downward after the
  bottom (or the ``k_d`` spring cannot start extending the leg at the bottom);
  ``TOUCHDOWN_NOT_COMPRESSING`` when ``q_rd >= 0`` at touchdown (nothing is integrated);
  ``NO_LIFTOFF`` when ``t_max`` is reached, or when the bottom leg length is already ``>= q_r_lo``
  so the leg can never cross ``q_r_lo`` upward; ``INTEGRATION_FAILED`` when ``solve_ivp`` fails.

Numerics
--------
Each stance subphase is integrated with ``scipy.integrate.solve_ivp`` (DOP853), default
``rtol = 1e-11`` and ``atol = 1e-12``, the step capped at 1/16 of the shorter of the spring period
``2 pi sqrt(m/k)`` and the pendulum period ``2 pi sqrt(l0/g_s)`` so that a sign change of an
event function is not stepped over (solve_ivp checks the signs at the steps' ends only). The cap
is kept at every tolerance: this module is the reference, meant for the default tolerance, where
the cap rarely binds (40 steps each of the human-runner and Yu grids took the same evaluations
with and without it; a slow vertical hop with a soft k_d is a case where it binds); the compiled
simulator takes the same cap at the default and scales it with the tolerance elsewhere, finding
the events inside a step by its own checks (:mod:`.dop853`). Events are located by solve_ivp's
root finder on the dense output (to ~1e-15 in time). The default stance time limit is
:func:`default_t_max`. The right-hand sides, the energy and the coordinate maps are the generated kernels of
``slipmaps.generated.slip_model``, the flight maps those of ``slipmaps.generated.flight``;
:func:`simulate_stance_cartesian` integrates the same stance in Cartesian coordinates as an
independent check of the polar integration. :mod:`.compiled` runs the same stance through
the same algorithm compiled with numba (:mod:`.dop853`), the default ``"exact"`` map; this module
stays the reference (``method="scipy"``) and the dense trajectory. Measured with the defaults
(human runner and robot hopper, tests/test_simulator.py): relative energy drift within a subphase
<= 1e-11, polar vs Cartesian liftoff states <= 6e-11, stance times <= 1e-12 s.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp
from slipmaps.generated import maps_index
from slipmaps.generated.status import MESSAGES, Status
from slipmaps.runtime.api import model
from slipmaps.runtime.api.batch import BatchInterrupted
from slipmaps.runtime.api.params import SlipParams
from slipmaps.runtime.api.validate import POLAR_NAMES, PolarState, polar_state
from slipmaps.runtime.api.validate import check_params as _slip_params
from slipmaps.runtime.api.validate import leg_angle as _leg_angle
from slipmaps.runtime.api.validate import non_negative as _non_negative
from slipmaps.runtime.api.validate import positive as _positive
from slipmaps.runtime.api.validate import real as _real

__all__ = [
    "COLLAPSE_FRACTION",
    "DEFAULT_ATOL",
    "DEFAULT_RTOL",
    "PolarState",
    "StanceResult",
    "StepResult",
    "default_t_max",
    "max_step",
    "simulate_from_touchdown",
    "simulate_stance",
    "simulate_stance_cartesian",
    "simulate_step",
]

#: The simulator's settings, the compiled one's too (derive/model/simulation.py, through the index):
#: the default relative / absolute tolerances of the DOP853 integration; the stance ends with
#: ``Status.FALL`` when the leg length drops to COLLAPSE_FRACTION of ``l0``.
DEFAULT_RTOL = maps_index.SIMULATION["DEFAULT_RTOL"]
DEFAULT_ATOL = maps_index.SIMULATION["DEFAULT_ATOL"]
COLLAPSE_FRACTION = maps_index.SIMULATION["COLLAPSE_FRACTION"]
#: With ``dense=True``, each integrator step is sampled at this many equispaced points.
_DENSE_PER_STEP = 8

_NAN2 = (math.nan, math.nan)


# ----------------------------------------------------------------------------------------------
# Results
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class StanceResult:
    """Outcome of one stance phase, touchdown to liftoff (or to the failure event).

    States are polar ``(q_r, q_rd, q_th, q_thd)`` tuples, ``None`` when not reached; times are
    measured from touchdown and are NaN when not reached. With ``dense=True``, ``t`` (shape N) and
    ``states`` (shape 4 x N: q_r, q_rd, q_th, q_thd) sample the whole stance: the integrator's
    steps plus 7 equispaced points inside each step (DOP853 dense output). Samples with
    ``t <= t_bottom`` belong to the compression (``k_c``), samples with ``t >= t_bottom`` to the
    decompression (``k_d``); the bottom sample appears once, with ``q_rd = 0`` (to round-off in
    the Cartesian integration).
    """

    status: Status
    message: str
    touchdown: PolarState
    bottom: PolarState | None = None
    liftoff: PolarState | None = None
    t_bottom: float = math.nan
    t_stance: float = math.nan
    t: np.ndarray | None = field(default=None, compare=False, repr=False)
    states: np.ndarray | None = field(default=None, compare=False, repr=False)

    @property
    def ok(self) -> bool:
        """True when the stance ended at liftoff."""
        return self.status == Status.OK

    @property
    def liftoff_cartesian(self) -> tuple[float, float, float, float] | None:
        """The liftoff state as ``(b_x, b_xd, b_y, b_yd)`` relative to the toe, or None."""
        if self.liftoff is None:
            return None
        return _to_cartesian(self.liftoff)


@dataclass(frozen=True)
class StepResult:
    """Outcome of one step: apex -> touchdown -> stance -> liftoff -> next apex.

    ``apex`` and ``next_apex`` are ``(height, speed)`` pairs (NaN when unknown or not reached).
    ``t_descent`` is the flight time from the apex to touchdown, ``t_ascent`` and ``dx_ascent`` the
    flight time and horizontal distance from liftoff to the next apex; ``t_bottom`` and
    ``t_stance`` are measured from touchdown. ``step_length`` is the horizontal distance from the
    apex to the next apex, ``(foot_x, foot_y)`` the foot at touchdown relative to the apex. The
    first failing stage's status propagates; ``stance`` is the full :class:`StanceResult` (with
    the dense trajectory if requested).
    """

    status: Status
    message: str
    apex: tuple[float, float] = _NAN2
    touchdown: PolarState | None = None
    bottom: PolarState | None = None
    liftoff: PolarState | None = None
    t_bottom: float = math.nan
    t_stance: float = math.nan
    next_apex: tuple[float, float] = _NAN2
    t_descent: float = math.nan
    t_ascent: float = math.nan
    dx_ascent: float = math.nan
    step_length: float = math.nan
    foot_x: float = math.nan
    foot_y: float = math.nan
    stance: StanceResult | None = field(default=None, compare=False, repr=False)

    @property
    def ok(self) -> bool:
        """True when every stage succeeded and the next apex is known."""
        return self.status == Status.OK


# ----------------------------------------------------------------------------------------------
# Validation
# ----------------------------------------------------------------------------------------------
def _tolerances(rtol: object, atol: object) -> tuple[float, float]:
    return _positive("rtol", rtol), _positive("atol", atol)


def _check_params(params: object) -> SlipParams:
    """``params`` (a SlipParams) that this reference models: ValueError, one line, for a leg damping
    c != 0 (the compiled simulator, the exact map's default ``method="compiled"``, models it)."""
    params = _slip_params(params)
    if params.c != 0.0:
        raise ValueError(
            f"the solve_ivp reference (the exact map's method='scipy') does not model the leg damping c: "
            f"got c={params.c!r}; the compiled simulator (method='compiled', the default) does"
        )
    return params


def default_t_max(params: SlipParams) -> float:
    """Default stance time limit (:func:`stance_time_limit` of ``params``)."""
    _check_params(params)
    return float(stance_time_limit(params.m, params.l0, params.k_c, params.k_d, params.g_s))


# ----------------------------------------------------------------------------------------------
# Coordinate systems for the stance integration
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class _Coords:
    """How one coordinate system exposes the quantities the stance events need."""

    rhs: Callable[[np.ndarray, float], Sequence[float]]  # (y, k) -> dy/dt
    q_r: Callable[[np.ndarray], float]
    q_rd: Callable[[np.ndarray], float]
    q_rdd: Callable[[np.ndarray, float], float]  # radial acceleration with stiffness k
    height: Callable[[np.ndarray], float]  # > 0 while the body is above the ground
    stop_radial: Callable[[np.ndarray], np.ndarray]  # same state with q_rd = 0
    to_polar: Callable[[np.ndarray], PolarState]
    from_polar: Callable[[PolarState], np.ndarray]


def _to_cartesian(s) -> tuple[float, float, float, float]:
    """A polar state as ``(b_x, b_xd, b_y, b_yd)`` relative to the toe (the model kernel)."""
    _, out = model.call("polar_to_cartesian", **dict(zip(POLAR_NAMES, s, strict=True)))
    return tuple(out[f"out_{n}"] for n in _CARTESIAN)


_CARTESIAN = ("b_x", "b_xd", "b_y", "b_yd")


def _field(name: str, state: tuple[str, ...], p: SlipParams):
    """The stance vector field ``name`` (a model kernel) as ``rhs(y, k)`` of the state ``y`` and
    the stiffness ``k``, the other parameters ``p``'s."""
    f = model.bind(name, (*state, "k"), m=p.m, l0=p.l0, g_s=p.g_s)
    values = np.empty(len(state) + 1)

    def rhs(y: np.ndarray, k: float) -> np.ndarray:
        values[:-1] = y[: len(state)]
        values[-1] = k
        return f(values)[1]

    return rhs


def _polar_coords(p: SlipParams) -> _Coords:
    rhs = _field("stance_polar_rhs", POLAR_NAMES, p)

    def q_rdd(y: np.ndarray, k: float) -> float:
        return float(rhs(y, k)[1])

    def stop_radial(y: np.ndarray) -> np.ndarray:
        z = np.array(y, dtype=float)
        z[1] = 0.0
        return z

    return _Coords(
        rhs=rhs,
        q_r=lambda y: y[0],
        q_rd=lambda y: y[1],
        q_rdd=q_rdd,
        height=lambda y: math.cos(y[2]),
        stop_radial=stop_radial,
        to_polar=lambda y: (float(y[0]), float(y[1]), float(y[2]), float(y[3])),
        from_polar=lambda s: np.array(s, dtype=float),
    )


def _cartesian_coords(p: SlipParams) -> _Coords:
    rhs = _field("stance_cartesian_rhs", _CARTESIAN, p)

    def q_r(y: np.ndarray) -> float:
        return math.hypot(y[0], y[2])

    def q_rd(y: np.ndarray) -> float:
        return (y[0] * y[1] + y[2] * y[3]) / math.hypot(y[0], y[2])

    def q_rdd(y: np.ndarray, k: float) -> float:
        # d/dt (x.v / r) = (v.v + x.a) / r - (x.v)^2 / r^3
        _, ax, _, ay = rhs(y, k)
        r = math.hypot(y[0], y[2])
        xv = y[0] * y[1] + y[2] * y[3]
        return (y[1] ** 2 + y[3] ** 2 + y[0] * ax + y[2] * ay) / r - xv**2 / r**3

    def stop_radial(y: np.ndarray) -> np.ndarray:
        z = np.array(y, dtype=float)
        r = math.hypot(z[0], z[2])
        ux, uy = z[0] / r, z[2] / r
        v_r = z[1] * ux + z[3] * uy
        z[1] -= v_r * ux
        z[3] -= v_r * uy
        return z

    def to_polar(y: np.ndarray) -> PolarState:
        _, out = model.call("cartesian_to_polar", **dict(zip(_CARTESIAN, map(float, y), strict=True)))
        return tuple(out[f"out_{n}"] for n in POLAR_NAMES)

    def from_polar(s: PolarState) -> np.ndarray:
        return np.array(_to_cartesian(s), dtype=float)

    return _Coords(
        rhs=rhs,
        q_r=q_r,
        q_rd=q_rd,
        q_rdd=q_rdd,
        height=lambda y: y[2],
        stop_radial=stop_radial,
        to_polar=to_polar,
        from_polar=from_polar,
    )


def _event(fun: Callable[[float, np.ndarray], float], direction: float, name: str):
    fun.terminal = True  # type: ignore[attr-defined]
    fun.direction = direction  # type: ignore[attr-defined]
    fun.__name__ = name
    return fun


@dataclass
class _Phase:
    """Outcome of integrating one stance subphase."""

    event: str | None  # name of the terminal event, None if t_end was reached
    t_event: float
    y_event: np.ndarray | None
    t: np.ndarray
    y: np.ndarray
    error: str | None = None


def _integrate_phase(
    coords: _Coords,
    k: float,
    y0: np.ndarray,
    t0: float,
    t_end: float,
    events: list,
    rtol: float,
    atol: float,
    max_step: float,
    dense: bool | np.ndarray,
) -> _Phase:
    """One subphase; ``dense``: True for the steps and dense samples (:func:`_samples`), or the
    times (sorted) at which to evaluate the dense output (those inside the subphase are kept)."""

    def fun(_t: float, y: np.ndarray) -> Sequence[float]:
        return coords.rhs(y, k)

    try:
        with np.errstate(all="ignore"):
            sol = solve_ivp(
                fun,
                (t0, t_end),
                y0,
                method="DOP853",
                events=events,
                rtol=rtol,
                atol=atol,
                max_step=max_step,
                first_step=first_step(fun, t0, y0, t_end, max_step, rtol, atol),
                dense_output=dense is not False,
            )
    except (ArithmeticError, ValueError, RuntimeError, ZeroDivisionError) as exc:
        return _Phase(None, math.nan, None, np.empty(0), np.empty((4, 0)), f"{type(exc).__name__}: {exc}")
    if sol.status == -1:
        return _Phase(None, math.nan, None, sol.t, sol.y, str(sol.message))
    if not np.all(np.isfinite(sol.y)):
        return _Phase(None, math.nan, None, sol.t, sol.y, "the integrated state became non-finite")
    if sol.status == 1:
        fired = [
            (float(te[0]), i) for i, te in enumerate(sol.t_events) if len(te) > 0
        ]  # all events are terminal: normally exactly one fires
        t_ev, i = min(fired)
        y_ev = np.asarray(sol.y_events[i][0], dtype=float)
        if not np.all(np.isfinite(y_ev)):
            return _Phase(None, math.nan, None, sol.t, sol.y, "the event state is non-finite")
        t, y = _samples(sol, dense, t0, t_ev)
        return _Phase(events[i].__name__, t_ev, y_ev, t, y)
    t, y = _samples(sol, dense, t0, float(sol.t[-1]))
    return _Phase(None, float(sol.t[-1]), None, t, y)


def first_step(
    fun, t0: float, y0: np.ndarray, t_bound: float, max_step: float, rtol: float, atol: float
) -> float:
    """The first step of a subphase: scipy's ``select_initial_step`` for DOP853 (forward, error
    estimator order 7), except that its first guess leaves out the components that are exactly 0
    unless the others do not move (the compiled simulator's rule, :func:`.dop853.initial_step`,
    which says why: at the bottom, q_rd = 0 made scipy's first step 3.6e-11 s). A state with no
    zero component gets scipy's step (to round-off: h ** (1/8) as three square roots)."""
    y0 = np.asarray(y0, dtype=float)
    interval = abs(t_bound - t0)
    if interval == 0.0:
        return 0.0
    f0 = np.asarray(fun(t0, y0), dtype=float)
    scale = atol + np.abs(y0) * rtol
    nonzero = y0 != 0.0

    def rms(x: np.ndarray) -> float:
        return float(np.sqrt(np.sum(x[nonzero] ** 2)) / math.sqrt(nonzero.sum())) if nonzero.any() else 0.0

    d0, d1 = rms(y0 / scale), rms(f0 / scale)
    if d0 < 1e-5 or d1 < 1e-5:  # the nonzero components do not move: scipy's guess over all
        nonzero = np.ones_like(nonzero)
        d0, d1 = rms(y0 / scale), rms(f0 / scale)
    h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
    h0 = min(h0, interval)
    f1 = np.asarray(fun(t0 + h0, y0 + h0 * f0), dtype=float)
    d2 = float(np.sqrt(np.sum(((f1 - f0) / scale) ** 2)) / math.sqrt(y0.size)) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = math.sqrt(math.sqrt(math.sqrt(0.01 / max(d1, d2))))
    return min(100.0 * h0, h1, interval, max_step)


def _samples(sol, dense: bool | np.ndarray, t0: float, t1: float) -> tuple[np.ndarray, np.ndarray]:
    """The subphase's samples: its steps (``dense`` False), the steps plus dense samples (True),
    or its dense output at the given times inside (t0, t1] (t0 too for the first subphase, at 0)."""
    if dense is False:
        return sol.t, sol.y
    if dense is True:
        return _step_samples(sol)
    times = dense[((dense > t0) | ((dense == t0) & (t0 == 0.0))) & (dense <= t1)]
    return times, (sol.sol(times) if times.size else np.empty((sol.y.shape[0], 0)))


def _step_samples(sol) -> tuple[np.ndarray, np.ndarray]:
    """The integrator's steps plus _DENSE_PER_STEP - 1 interpolated samples inside each step."""
    ts = sol.t
    if ts.size < 2 or sol.sol is None:
        return sol.t, sol.y
    frac = np.arange(_DENSE_PER_STEP) / _DENSE_PER_STEP
    t = np.concatenate([(ts[:-1, None] + frac[None, :] * np.diff(ts)[:, None]).ravel(), ts[-1:]])
    y = sol.sol(t)
    y[:, ::_DENSE_PER_STEP] = sol.y  # exact step values at the step points
    return t, y


def max_step(m: float, l0: float, k: float, g_s: float) -> float:
    """The step cap of a stance subphase with stiffness k [s] (the model kernel ``max_step``: a
    fraction of the shorter of the spring period and the pendulum period; the compiled simulator's at
    the default rtol)."""
    return model.call("max_step", m=m, l0=l0, k=k, g_s=g_s)[1]["step"]


def stance_time_limit(m: float, l0: float, k_c: float, k_d: float, g_s: float) -> float:
    """The stance time limit [s] (the model kernel ``stance_time_limit``, shared with the compiled
    simulator): a stance still on the ground then is NO_LIFTOFF."""
    return model.call("stance_time_limit", m=m, l0=l0, k_c=k_c, k_d=k_d, g_s=g_s)[1]["t_max"]


def _max_step(p: SlipParams, k: float) -> float:
    return max_step(p.m, p.l0, k, p.g_s)


def _message(status: Status, detail: str = "") -> str:
    base = MESSAGES[int(status)]
    return f"{base} ({detail})" if detail else base


def _stance(
    params: SlipParams,
    touchdown: object,
    coords_factory: Callable[[SlipParams], _Coords],
    dense: bool,
    rtol: object,
    atol: object,
    t_max: object,
) -> StanceResult:
    _check_params(params)
    td = polar_state(params, touchdown)
    rtol_f, atol_f = _tolerances(rtol, atol)
    t_end = default_t_max(params) if t_max is None else _positive("t_max", t_max)
    at_times = not isinstance(dense, bool)
    if at_times:
        dense = np.sort(np.asarray(dense, dtype=float))

    if td[1] >= 0.0:
        return StanceResult(
            Status.TOUCHDOWN_NOT_COMPRESSING,
            _message(Status.TOUCHDOWN_NOT_COMPRESSING, f"q_rd={td[1]!r}"),
            td,
        )
    r_min = COLLAPSE_FRACTION * params.l0
    if td[0] <= r_min:
        return StanceResult(
            Status.FALL, _message(Status.FALL, f"touchdown leg length {td[0]!r} collapsed"), td
        )

    c = coords_factory(params)
    height = _event(lambda t, y: c.height(y), -1.0, "fall")
    collapse = _event(lambda t, y: c.q_r(y) - r_min, -1.0, "collapse")
    bottom_ev = _event(lambda t, y: c.q_rd(y), +1.0, "bottom")
    liftoff_ev = _event(lambda t, y: c.q_r(y) - params.q_r_lo, +1.0, "liftoff")
    recompress = _event(lambda t, y: c.q_rd(y), -1.0, "recompression")

    pieces_t: list[np.ndarray] = []
    pieces_y: list[np.ndarray] = []

    def dense_fields() -> dict:
        if dense is False:
            return {}
        t = np.concatenate(pieces_t) if pieces_t else np.empty(0)
        ys = np.concatenate(pieces_y, axis=1) if pieces_y else np.empty((4, 0))
        states = np.array([c.to_polar(ys[:, j]) for j in range(ys.shape[1])], dtype=float).T
        states = states.reshape(4, -1)
        t.setflags(write=False)
        states.setflags(write=False)
        return {"t": t, "states": states}

    def failure(ph: _Phase, stage: str, **known) -> StanceResult:
        if ph.error is not None:
            status, detail = Status.INTEGRATION_FAILED, f"{stage}: {ph.error}"
        elif ph.event is None:
            status, detail = Status.NO_LIFTOFF, f"{stage}: t_max={t_end:.6g} s reached"
        elif ph.event == "fall":
            status, detail = Status.FALL, f"{stage}: body height 0 at t={ph.t_event:.6g} s"
        elif ph.event == "collapse":
            status = Status.FALL
            detail = f"{stage}: leg length <= {COLLAPSE_FRACTION:g}*l0 at t={ph.t_event:.6g} s"
        else:  # recompression
            status, detail = Status.RECOMPRESSION, f"{stage}: q_rd = 0 again at t={ph.t_event:.6g} s"
        return StanceResult(status, _message(status, detail), td, **known, **dense_fields())

    # Compression (k_c): touchdown -> bottom.
    y0 = c.from_polar(td)
    comp = _integrate_phase(
        c,
        params.k_c,
        y0,
        0.0,
        t_end,
        [bottom_ev, height, collapse],
        rtol_f,
        atol_f,
        _max_step(params, params.k_c),
        dense,
    )
    if dense is not False:
        pieces_t.append(comp.t)
        pieces_y.append(comp.y)
    if comp.event != "bottom":
        return failure(comp, "compression")

    t_bottom = comp.t_event
    y_b = c.stop_radial(comp.y_event)
    bottom = c.to_polar(y_b)
    if dense is True and pieces_y[-1].shape[1] > 0:
        pieces_y[-1] = pieces_y[-1].copy()
        pieces_y[-1][:, -1] = y_b  # the event sample, with q_rd = 0 exactly
    known = {"bottom": bottom, "t_bottom": t_bottom}

    if c.q_r(y_b) >= params.q_r_lo:
        detail = (
            f"bottom leg length {bottom[0]!r} >= q_r_lo={params.q_r_lo!r}: q_r cannot cross q_r_lo upward"
        )
        return StanceResult(
            Status.NO_LIFTOFF, _message(Status.NO_LIFTOFF, detail), td, **known, **dense_fields()
        )
    if not c.q_rdd(y_b, params.k_d) > 0.0:
        detail = f"the k_d spring cannot extend the leg at the bottom (t={t_bottom:.6g} s)"
        return StanceResult(
            Status.RECOMPRESSION, _message(Status.RECOMPRESSION, detail), td, **known, **dense_fields()
        )
    if t_bottom >= t_end:
        return failure(_Phase(None, t_bottom, None, np.empty(0), np.empty((4, 0))), "decompression", **known)

    # Decompression (k_d): bottom -> liftoff.
    dec = _integrate_phase(
        c,
        params.k_d,
        y_b,
        t_bottom,
        t_end,
        [liftoff_ev, recompress, height, collapse],
        rtol_f,
        atol_f,
        _max_step(params, params.k_d),
        dense,
    )
    if dense is not False:
        first = 0 if at_times else 1  # the step samples start at the bottom, already sampled
        pieces_t.append(dec.t[first:])
        pieces_y.append(dec.y[:, first:])
    if dec.event != "liftoff":
        return failure(dec, "decompression", **known)

    liftoff = c.to_polar(dec.y_event)
    return StanceResult(
        Status.OK,
        _message(Status.OK),
        td,
        bottom=bottom,
        liftoff=liftoff,
        t_bottom=t_bottom,
        t_stance=dec.t_event,
        **dense_fields(),
    )


# ----------------------------------------------------------------------------------------------
# Public API
# ----------------------------------------------------------------------------------------------
def simulate_stance(
    params: SlipParams,
    touchdown: Sequence[float],
    *,
    dense: bool = False,
    rtol: float = DEFAULT_RTOL,
    atol: float = DEFAULT_ATOL,
    t_max: float | None = None,
) -> StanceResult:
    """Integrate the polar stance from a touchdown state ``(q_r, q_rd, q_th, q_thd)`` to liftoff.

    Compression with ``k_c`` until the bottom, decompression with ``k_d`` until ``q_r`` crosses
    ``params.q_r_lo`` upward. Failures (fall, recompression, no liftoff before ``t_max``, ...) are
    returned as a status and message, never raised. ValueError for invalid inputs: a touchdown
    state that is not 4 finite numbers, ``q_r`` outside ``(0, l0]``, ``|q_th| >= pi/2``,
    non-positive tolerances or ``t_max``.
    """
    return _stance(params, touchdown, _polar_coords, dense, rtol, atol, t_max)


def simulate_stance_cartesian(
    params: SlipParams,
    touchdown: Sequence[float],
    rtol: float = DEFAULT_RTOL,
    atol: float = DEFAULT_ATOL,
    *,
    dense: bool = False,
    t_max: float | None = None,
) -> StanceResult:
    """The same stance as :func:`simulate_stance`, integrated in Cartesian coordinates.

    The touchdown state is polar; it is converted with ``polar_to_cartesian``, integrated with
    ``stance_cartesian_rhs`` (toe at the origin), the events are expressed directly in Cartesian
    quantities (``q_r = |b|``, ``q_rd = b.b_dot/|b|``, fall at ``b_y = 0``) and the reported
    states are converted back to polar. An independent check of the polar integration.
    """
    return _stance(params, touchdown, _cartesian_coords, dense, rtol, atol, t_max)


def _step_from_touchdown(
    params: SlipParams,
    touchdown: Sequence[float],
    apex: tuple[float, float],
    t_descent: float,
    dense: bool,
    rtol: float,
    atol: float,
    direction: float,
    foot: tuple[float, float] = _NAN2,
) -> StepResult:
    stance = simulate_stance(params, touchdown, dense=dense, rtol=rtol, atol=atol)
    common = {
        "apex": apex,
        "touchdown": stance.touchdown,
        "bottom": stance.bottom,
        "liftoff": stance.liftoff,
        "t_bottom": stance.t_bottom,
        "t_stance": stance.t_stance,
        "t_descent": t_descent,
        "stance": stance,
    }
    if not stance.ok:
        return StepResult(stance.status, f"stance: {stance.message}", **common)
    status, up = model.call(
        "liftoff_to_apex",
        **dict(zip(POLAR_NAMES, stance.liftoff, strict=True)),
        g_f=params.g_f,
        direction=direction,
    )
    y_apex, xd_apex, t_ascent, dx_ascent, apex_b_x = (
        up[n] for n in ("apex_b_y", "apex_b_xd", "t_flight", "dx_flight", "apex_b_x")
    )
    if status != Status.OK:
        b_x, b_xd, b_y, b_yd = stance.liftoff_cartesian
        detail = f"liftoff b_xd={b_xd!r}, b_yd={b_yd!r}"
        return StepResult(status, f"liftoff -> apex: {_message(status, detail)}", **common)
    return StepResult(
        Status.OK,
        _message(Status.OK),
        next_apex=(float(y_apex), float(xd_apex)),
        t_ascent=float(t_ascent),
        dx_ascent=float(dx_ascent),
        step_length=float(foot[0] + apex_b_x),
        foot_x=float(foot[0]),
        foot_y=float(foot[1]),
        **common,
    )


def simulate_step(
    params: SlipParams,
    apex_height: float,
    apex_speed: float,
    q_th_td: float,
    *,
    ground: float = 0.0,
    dense: bool = False,
    rtol: float = DEFAULT_RTOL,
    atol: float = DEFAULT_ATOL,
    **inputs: float,
) -> StepResult:
    """One exact step: apex ``(apex_height, apex_speed)`` -> next apex, leg at ``q_th_td`` at the
    apex, touching down on ground ``ground`` higher than the ground under the apex; ``inputs`` the
    other apex-return inputs by their kernel argument names (derive/params.py, ``retraction_rate``
    among them), passed to the descent.

    The descent to the touchdown of a leg of length ``params.q_r_td`` at angle ``q_th_td`` and the
    ascent from liftoff to the next apex are ballistic with ``g_f`` (generated kernels); the stance
    is :func:`simulate_stance`. The speed is signed (module docstring). ValueError for a non-finite
    or negative apex height, a non-finite speed or ground, or ``|q_th_td| >= pi/2``; every other
    failure is a status.
    """
    _check_params(params)
    h = _non_negative("apex_height", apex_height)
    v = _real("apex_speed", apex_speed)
    th = _leg_angle("q_th_td", q_th_td)
    ground = _real("ground", ground)
    rtol_f, atol_f = _tolerances(rtol, atol)
    y_td = ground + params.q_r_td * math.cos(th)
    detail = f"apex height {h!r}, touchdown height {y_td!r}"
    if not h > y_td:
        # The touchdown event (report section 2.1) needs the body to descend to ground + q_r_td cos
        # q_th_td; checked here as well as in the kernel so that no NaN state can reach the stance.
        status = Status.APEX_TOO_LOW
        return StepResult(status, f"apex -> touchdown: {_message(status, detail)}", apex=(h, v))
    status, down = model.call(
        "apex_to_touchdown",
        b_y_apex=h,
        b_xd_apex=v,
        q_th_td=th,
        q_r_td=params.q_r_td,
        g_f=params.g_f,
        ground=ground,
        **inputs,
    )
    td = tuple(down[f"touchdown_{n}"] for n in POLAR_NAMES)
    t_descent, foot_x = down["t_flight"], down["foot_x"]
    if status == Status.OK and not all(math.isfinite(x) for x in (*td, t_descent)):
        status, detail = Status.INVALID_INPUT, f"{detail}; apex_to_touchdown returned {(*td, t_descent)!r}"
    if status != Status.OK:
        return StepResult(status, f"apex -> touchdown: {_message(status, detail)}", apex=(h, v))
    touchdown = tuple(float(x) for x in td)
    direction = float(np.sign(v))
    foot = (float(foot_x), ground - h)
    return _step_from_touchdown(
        params, touchdown, (h, v), float(t_descent), dense, rtol_f, atol_f, direction, foot
    )


def simulate_from_touchdown(
    params: SlipParams,
    touchdown: Sequence[float],
    *,
    dense: bool = False,
    rtol: float = DEFAULT_RTOL,
    atol: float = DEFAULT_ATOL,
) -> StepResult:
    """Like :func:`simulate_step` but starting from a polar touchdown state (apex fields NaN)."""
    _check_params(params)
    rtol_f, atol_f = _tolerances(rtol, atol)
    td = polar_state(params, touchdown)
    direction = float(np.sign(_to_cartesian(td)[1]))  # the touchdown's horizontal velocity
    return _step_from_touchdown(params, td, _NAN2, math.nan, dense, rtol_f, atol_f, direction)


# ----------------------------------------------------------------------------------------------
# The exact map's ``method="scipy"`` backend (runtime/api/calls.py's protocol)
# ----------------------------------------------------------------------------------------------
class _Row(tuple):
    """A backend row (outputs, then the status) that carries the simulator's own message."""

    message: str


def _row(names, values: dict, status: Status, message: str) -> _Row:
    ok = status == Status.OK
    row = _Row((*(float(values[n]) if ok else math.nan for n in names), int(status)))
    row.message = message
    return row


def stance_values(r: StanceResult | StepResult) -> dict[str, float]:
    """A stance's (or a step's stance's) outputs by the index's names (NaN where not reached)."""
    values = {"t_bottom": r.t_bottom, "t_stance": r.t_stance}
    for group, state in (("bottom", r.bottom), ("liftoff", r.liftoff)):
        values.update(zip((f"{group}_{n}" for n in POLAR_NAMES), state or (math.nan,) * 4, strict=True))
    return values


def step_values(r: StepResult) -> dict[str, float]:
    """A step's stance and apex-return outputs by the index's names (NaN where not reached)."""
    return {
        **stance_values(r),
        "apex_height": r.next_apex[0],
        "apex_speed": r.next_apex[1],
        "t_descent": r.t_descent,
        "t_ascent": r.t_ascent,
        "step_length": r.step_length,
        "foot_x": r.foot_x,
        "foot_y": r.foot_y,
        "touchdown_q_th": r.touchdown[2] if r.touchdown is not None else math.nan,
    }


class ReferenceBackend:
    """The solve_ivp simulator as the exact map's backend (option ``method="scipy"``): stance,
    apex return and the state at given times, one row at a time (rows loop in Python, with a
    progress bar); no Jacobian (the compiled simulator's variational equations give those), no leg
    damping (:meth:`check_params`)."""

    def check_params(self, params: SlipParams) -> None:
        """ValueError, one line, for parameters this backend does not model (a leg damping c != 0),
        before any row runs."""
        _check_params(params)

    def _tolerances(self, call) -> dict[str, float]:
        return {"rtol": call.values["rtol"], "atol": call.values["atol"]}

    def scalar(self, call, role: str, inputs) -> _Row:
        names = call.spec(role).outputs
        p = call.params
        if role == "stance":
            td = tuple(inputs[n] for n in call.spec("stance").x)
            r = simulate_stance(p, td, **self._tolerances(call))
            return _row(names, stance_values(r), r.status, r.message)
        if role == "apex_return":
            first = ("b_y_apex", "b_xd_apex", "q_th_td", "ground")
            others = {k: v for k, v in inputs.items() if k not in first}
            r = simulate_step(
                p, inputs["b_y_apex"], inputs["b_xd_apex"], inputs["q_th_td"], ground=inputs["ground"],
                **self._tolerances(call), **others,
            )  # fmt: skip
            return _row(names, step_values(r), r.status, r.message)
        if role.endswith("_jacobian"):
            raise ValueError(
                "the exact Jacobian comes from the compiled simulator's variational equations; "
                "method='scipy' has none (use the default method='compiled')"
            )
        raise ValueError(f"the solve_ivp reference has no {role} on its own")

    def rows(self, call, role, rows, inputs, n, show):
        from slipmaps.runtime.api.progress import progress

        if role == "state_at":
            return self._states(call, rows["t"], inputs)
        out = np.full((n, len(call.spec(role).outputs)), math.nan)
        status = np.empty(n, dtype=np.int64)
        done = 0
        try:
            for i in progress(range(n), n, f"exact {role.replace('_', ' ')}", show):
                try:
                    res = self.scalar(call, role, {**inputs, **{k: float(v[i]) for k, v in rows.items()}})
                except ValueError:
                    if role.endswith("_jacobian"):
                        raise
                    status[i] = int(Status.INVALID_INPUT)
                else:
                    status[i] = res[-1]
                    out[i] = res[:-1]
                done = i + 1
        except KeyboardInterrupt:  # the rows before done are finished
            raise BatchInterrupted(done, n, (out[:done], status[:done])) from None
        return out, status

    def _states(self, call, times: np.ndarray, inputs):
        """The state at ``times`` from solve_ivp's dense output of the stance (its 7th-order
        interpolants; a time past the stance's end is the end's status, NaN)."""
        td = tuple(inputs[n] for n in call.spec("stance").x)
        order = np.argsort(times, kind="stable")
        r = _stance(
            call.params, td, _polar_coords, times[order], call.values["rtol"], call.values["atol"], None
        )
        n = times.shape[0]
        out = np.full((n, 4), math.nan)
        status = np.full(n, int(r.status if not r.ok else Status.NO_LIFTOFF), dtype=np.int64)
        if r.t is not None and r.t.size:
            reached = order[: r.t.size]
            out[reached] = r.states.T
            status[reached] = int(Status.OK)
        return out, status


#: The backend named by the exact map's declaration (``derive/maps/exact.py``).
BACKEND = ReferenceBackend()
