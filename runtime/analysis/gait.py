"""Periodic running gaits: every fixed point of a map's apex-return map, and its stability.

One step of map ``name`` (:func:`slipmaps.apex_return`) takes an apex (height h [m] of the body
above the ground, forward speed v [m/s]) and the touchdown leg angle q_th_td [rad, from the
vertical, counterclockwise positive; the angle of attack from the ground is 90 deg - q_th_td] to
the next apex (h', v'). A one-step periodic gait is a fixed point, (h', v') = (h, v).

Energy and the one-dimensional return map
-----------------------------------------
The flight energy of an apex is E = m (g_f h + v^2/2) [J]. When k_c == k_d, g_s == g_f and
q_r_td == q_r_lo the exact step conserves it (the stance is conservative and the spring holds the
same energy at touchdown and at liftoff), so on an energy level h' = h implies v' = v, and a gait
is a fixed point of the one-dimensional apex-height return map h -> h'(h, v_E(h)) with
v_E(h) = sqrt(2 (E/m - g_f h)) (Seyfarth, Geyer, Guenther and Blickhan, "A movement criterion for
running", J Biomech 35 (2002) 649-655). Its eigenvalue is

    lambda = dh'/dh + dh'/dv * dv/dh|_E,    dv/dh|_E = -g_f / v,

and the gait is self-stable when |lambda| < 1. Otherwise the flight energy changes every step (by
(k_d - k_c)(l0 - q_r_b)^2/2 at the stiffness switch, report eq 97, by k/2 ((l0 - q_r_td)^2 -
(l0 - q_r_lo)^2) for unequal leg lengths, by m (g_s - g_f) times the height difference of liftoff
and touchdown for unequal gravities), so for k_c != k_d at the default leg lengths no periodic gait
exists at all: :func:`fixed_points` refuses such parameters (ValueError naming the reason) instead of
searching a two-dimensional (h, v) fixed point that is not there.

Two numbers, not one: the eigenvalue and the Floquet multipliers
-----------------------------------------------------------------
``eigenvalue`` (lambda) is the slope of the one-dimensional apex-height return map on the energy
level, above; it decides self-stability (``stable``). ``multipliers`` are the eigenvalues of the 2x2
apex-return Jacobian A = d(h', v')/d(h, v) at the fixed point (:data:`DEFINITIONS`). They are
(1, lambda) exactly when the step conserves the flight energy to first order there: the energy
gradient (m g_f, m v) is then a left eigenvector of A with eigenvalue 1 (a neighbouring gait of
another energy stays on it), and the other eigenvalue is trace(A) - 1 = lambda. Conversely, with
one multiplier 1 and dh'/dv != 0, (1, lambda) implies that the gradient is a left eigenvector.
``energy_gradient_error`` measures how far it is: the larger relative difference of dE'/dh from
dE/dh and of dE'/dv from dE/dv (0 for an energy-conserving step).

Measured on docs/stability.json's grids (human runner and robot hopper at apex height l0, 3-7 m/s
and the same Froude numbers; Seyfarth et al.'s energy over angles of attack): the exact map's first
multiplier is 1 within 6.1e-11 and its second is lambda; the gravity corrections (types 0-5) and
``iterative-report`` conserve the energy to round-off (first multiplier 1 within 8e-14, second
lambda to the record's 6 digits); ``iterative`` to its iteration floor (first multiplier 1 within
8.9e-4, second within 0.016 of lambda, both worst on the robot hopper). Geyer et al.'s map (and
``geyer-vs`` at k_c == k_d) does not conserve the energy (at 1 m, 5 m/s: dE'/dh = 8.60 m/s^2 per kg
against g_f = 9.81), yet has a unit multiplier within 9.3e-14, from its curve of fixed points at a
given angle, not from the energy: its second multiplier is up to 0.30 away from lambda (0.788
against 0.856 at 5 m/s). ``speed_residual`` = v' - v says how far a step is from a
two-dimensional fixed point.

Search
------
Two uses: the apex (``apex_height`` and ``speed``, or ``energy`` and ``speed``) given, find the
touchdown angles whose step returns to the same apex (the unknown runs over (0, pi/2)); or the
``energy`` and the ``angle`` given, find the apex heights on the energy level (the unknown runs
from the touchdown height q_r_td cos q_th_td, below which there is no touchdown, to E/(m g_f),
where v = 0). Along that line, one batch call (:func:`slipmaps.apex_return_batch`, ``scan`` points)
brackets every sign change of h' - h between two neighbouring steps that complete; each bracket is
refined by Newton's method on the line with the apex-return Jacobian (:mod:`.jacobian`),
safeguarded: a Newton iterate outside the current bracket is replaced by the bracket's midpoint,
and the bracket shrinks with every evaluation. A root of even multiplicity (a tangency) or one
between a completed and a failed step is not bracketed and not found.

Tolerances (measured on the human runner at apex height 1 m, 5 m/s, angle 0.411 rad): h' - h of
the exact simulator changes by 1.87e-12 m per 1e-12 rad of touchdown angle with round-off below
1e-14 m, so a root is resolvable to about 1e-14 rad; the search stops when a Newton step is below
:data:`XTOL` (1e-10, in rad or m: the eigenvalue then changes by less than 1e-9) or |h' - h| is
below :data:`FTOL`. A bracket whose refinement ends with |h' - h| above :data:`RESIDUAL_TOL` (a jump
of h', not a root) or a step that fails inside it gives a fixed point with a failure status, never a
silent one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from slipmaps.generated.status import MESSAGES, Status

from ..api.index import get
from ..api.jacobian import apex_return_jacobian as apex_jacobian
from ..api.maps import apex_return_batch
from ..api.params import SlipParams
from ..api.validate import check_params, leg_angle, positive

__all__ = [
    "FixedPoint",
    "FixedPoints",
    "fixed_points",
    "energy_of",
    "check_conservative",
    "DEFINITIONS",
    "SCAN",
    "XTOL",
    "FTOL",
]

#: What each stability number of a :class:`FixedPoint` is (the CLI prints these under its table and
#: in its JSON).
DEFINITIONS = {
    "eigenvalue": "the eigenvalue lambda of the one-dimensional apex-height return map on the energy "
    "level, dh'/dh - dh'/dv g_f/v; self-stable when abs(lambda) < 1",
    "multipliers": "the Floquet multipliers, eigenvalues of the 2x2 apex-return Jacobian d(h', v')/d(h, v), "
    "the one nearest 1 first; they are (1, lambda) only when the step conserves the flight energy",
    "energy_gradient_error": "how far the step is from conserving the flight energy E = m (g_f h + v^2/2) "
    "at the point: the larger relative difference of dE'/dh from dE/dh and of dE'/dv from dE/dv "
    "(0: the multipliers are (1, lambda))",
}

#: Points of the bracketing scan along the unknown (one batch call).
SCAN = 96
#: Newton stops when a step is shorter than this (rad for an angle, m for a height).
XTOL = 1e-10
#: ... or when |h' - h| is below this [m].
FTOL = 1e-13
#: A refined bracket is a fixed point only if |h' - h| is below this [m] (measured residuals of
#: every map on the tests' grids: at most a few 1e-14 m; a jump of h' leaves the residual large).
RESIDUAL_TOL = 1e-9
#: Iterations of the safeguarded Newton method (bisection alone halves a 1.6e-2 rad bracket to
#: XTOL in 28).
MAX_ITER = 60
#: The scan of the touchdown angle keeps this far [rad] from 0 and pi/2.
ANGLE_MARGIN = 1e-3
#: The scan of the apex height starts this fraction of its interval above the touchdown height and
#: ends as far below the height of zero speed.
HEIGHT_MARGIN = 1e-9


@dataclass(frozen=True)
class FixedPoint:
    """One fixed point of map ``map``'s apex-return map (SI units, angle from the vertical).

    Two different stability numbers (module docstring, :data:`DEFINITIONS`): ``eigenvalue`` is
    lambda of the one-dimensional apex-height return map on the energy level (``stable`` is
    abs(lambda) < 1); ``multipliers`` are the eigenvalues of the 2x2 apex-return Jacobian
    d(h', v')/d(h, v), the one nearest 1 first. They are (1, eigenvalue) only for a step that
    conserves the flight energy (``energy_gradient_error`` 0: the exact map, the gravity
    corrections); Geyer et al.'s map has a unit multiplier but a second one up to 0.30 away from
    its eigenvalue (measured).
    """

    map: str
    apex_height: float  # [m]
    apex_speed: float  # [m/s]
    touchdown_angle: float  # q_th_td [rad]
    energy: float  # m (g_f h + v^2/2) [J]
    eigenvalue: float  # lambda of the 1-D apex-height return map on the energy level
    multipliers: tuple[complex, complex]  # eigenvalues of the 2x2 d(h', v')/d(h, v), nearest 1 first
    residual: float  # h' - h [m]
    speed_residual: float  # v' - v [m/s]
    iterations: int  # Jacobian evaluations of the refinement
    status: Status
    message: str
    energy_gradient_error: float = math.nan  # 0 when the step conserves the energy (DEFINITIONS)

    @property
    def ok(self) -> bool:
        return self.status == Status.OK

    @property
    def stable(self) -> bool:
        """True when self-stable, ``abs(eigenvalue) < 1`` (False for a failed point)."""
        return self.ok and bool(abs(self.eigenvalue) < 1.0)

    @property
    def angle_of_attack(self) -> float:
        """The leg's angle from the ground at touchdown [deg] (Seyfarth et al.'s alpha_0)."""
        return 90.0 - math.degrees(self.touchdown_angle)

    def as_dict(self) -> dict:
        """JSON-ready: numbers (None for NaN), multipliers as [re, im] pairs, the status by name
        (``eigenvalue``, ``multipliers``, ``energy_gradient_error``: :data:`DEFINITIONS`)."""

        def num(x: float):
            return float(x) if math.isfinite(x) else None

        return {
            "map": self.map,
            "apex_height": num(self.apex_height),
            "apex_speed": num(self.apex_speed),
            "touchdown_angle": num(self.touchdown_angle),
            "angle_of_attack_deg": num(self.angle_of_attack),
            "energy": num(self.energy),
            "eigenvalue": num(self.eigenvalue),
            "stable": self.stable,
            "multipliers": [[num(z.real), num(z.imag)] for z in self.multipliers],
            "energy_gradient_error": num(self.energy_gradient_error),
            "residual": num(self.residual),
            "speed_residual": num(self.speed_residual),
            "iterations": self.iterations,
            "status": self.status.name,
            "message": self.message,
        }


class FixedPoints(tuple):
    """What :func:`fixed_points` returns: the fixed points found (a tuple of :class:`FixedPoint`, in
    increasing order of the unknown; compares equal to the plain tuple) and how the search went.

    ``scan``: the map's steps of the bracketing scan per status name (most first; the whole
    line, not only the brackets). ``status``: OK when the scan could look for fixed points (some
    steps completed; an empty result is then a line without any), else why not: when every step
    of the scan failed, the most common failure (``NOT_CONVERGED`` for an iteration bounded too
    tightly, e.g. ``gravity-type2`` with ``iterations=1`` at its default ``tol``), and
    ``APEX_TOO_LOW`` when the energy does not reach the touchdown height. ``message`` says it in
    words (``every step of the scan failed (96 steps: NOT_CONVERGED 72, FALL 24): NOT_CONVERGED:
    ...``); for an OK search it counts the steps that failed, if any.
    """

    scan: dict[str, int]
    status: Status
    message: str

    def __new__(cls, points=(), *, scan=None, status: Status = Status.OK, message: str = ""):
        self = super().__new__(cls, points)
        self.scan = dict(scan or {})
        self.status = Status(status)
        self.message = message
        return self

    @property
    def ok(self) -> bool:
        """True when the search ran (its scan had completed steps), whether or not it found any."""
        return self.status == Status.OK

    def as_dict(self) -> dict:
        """JSON-ready: ``status`` by name, ``message``, ``scan`` and ``fixed_points``."""
        return {
            "status": self.status.name,
            "message": self.message,
            "scan": dict(self.scan),
            "fixed_points": [p.as_dict() for p in self],
        }

    def __repr__(self) -> str:
        return f"FixedPoints({tuple(self)!r}, status={self.status.name}, scan={self.scan!r})"


def _searched(points, counts: dict[str, int]) -> FixedPoints:
    """The search's result from its points and the scan's status counts (most first)."""
    total = sum(counts.values())
    failed = {k: n for k, n in counts.items() if k != Status.OK.name}
    if total and not counts.get(Status.OK.name):
        worst = next(iter(failed))
        steps = ", ".join(f"{k} {n}" for k, n in failed.items())
        message = (
            f"every step of the scan failed ({total} steps: {steps}): {worst}: {MESSAGES[int(Status[worst])]}"
        )
        return FixedPoints(points, scan=counts, status=Status[worst], message=message)
    found = f"found {len(points)} fixed point{'' if len(points) == 1 else 's'}"
    message = found
    if failed:
        steps = ", ".join(f"{k} {n}" for k, n in failed.items())
        ok = counts.get(Status.OK.name, 0)
        message = (
            f"{found}; the scan's step succeeded at {ok} of {total} angles "
            f"(the others leave the map's domain: {steps})"
        )
    return FixedPoints(points, scan=counts, message=message)


def energy_of(params: SlipParams, apex_height: float, apex_speed: float) -> float:
    """The flight energy m (g_f h + v^2/2) [J] of an apex."""
    return params.m * (params.g_f * apex_height + 0.5 * apex_speed**2)


def check_conservative(params: SlipParams) -> None:
    """ValueError unless a step conserves the flight energy (k_c == k_d, g_s == g_f, q_r_td == q_r_lo,
    no leg damping: c == 0: ``SlipParams.conserves_energy``), naming what breaks it."""
    check_params(params)
    if params.conserves_energy:
        return
    if params.c != 0.0:
        raise ValueError(
            f"fixed_points needs a step that conserves the apex energy (c == 0), got c={params.c!r}: the leg "
            "damping dissipates energy every step, so no periodic gait exists at k_c == k_d; "
            "slipmaps.deadbeat with controls=('touchdown_angle', 'k_d') finds the k_d of a gait"
        )
    for a, b, why in (
        (
            "k_c",
            "k_d",
            "the stiffness switch at the bottom changes the energy by (k_d - k_c)(l0 - q_r_b)^2/2",
        ),
        ("g_s", "g_f", "the energy changes by m (g_s - g_f) times the liftoff-touchdown height difference"),
        ("q_r_td", "q_r_lo", "the spring energy at touchdown and at liftoff differ"),
    ):
        if getattr(params, a) != getattr(params, b):
            raise ValueError(
                f"fixed_points needs a step that conserves the apex energy ({a} == {b}), got {a}="
                f"{getattr(params, a)!r}, {b}={getattr(params, b)!r}: {why} every step, so no periodic "
                "gait exists"
            )


# ----------------------------------------------------------------------------------------------
# The line searched: a point (h, v, q_th) and its tangent as functions of the unknown x
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class _AngleLine:
    """Apex fixed, the touchdown angle x unknown."""

    h: float
    v: float

    def grid(self, n: int) -> np.ndarray:
        return np.linspace(ANGLE_MARGIN, 0.5 * math.pi - ANGLE_MARGIN, n)

    def point(self, x):
        return self.h, self.v, x

    def tangent(self, x: float) -> dict[str, float]:
        return {"apex_height": 0.0, "apex_speed": 0.0, "touchdown_angle": 1.0}


@dataclass(frozen=True)
class _HeightLine:
    """Specific energy e = E/m [J/kg] and touchdown angle fixed, the apex height x unknown."""

    e: float
    angle: float
    g: float
    q_r_td: float

    def grid(self, n: int) -> np.ndarray:
        lo, hi = self.q_r_td * math.cos(self.angle), self.e / self.g
        if hi <= lo:  # not enough energy to reach the touchdown height
            return np.empty(0)
        t = np.linspace(0.0, 1.0, n)
        t[0], t[-1] = HEIGHT_MARGIN, 1.0 - HEIGHT_MARGIN
        return lo + (hi - lo) * t

    def speed(self, x):
        return np.sqrt(np.maximum(2.0 * (self.e - self.g * x), 0.0))

    def point(self, x):
        return x, self.speed(x), self.angle

    def tangent(self, x: float) -> dict[str, float]:
        return {"apex_height": 1.0, "apex_speed": -self.g / float(self.speed(x)), "touchdown_angle": 0.0}


def _line(params, apex_height, energy, speed, angle):
    named = (("apex_height", apex_height), ("energy", energy), ("speed", speed), ("angle", angle))
    given = {k for k, x in named if x is not None}
    g, m = params.g_f, params.m
    if given == {"apex_height", "speed"}:
        return _AngleLine(positive("apex_height", apex_height), positive("speed", speed))
    if given == {"energy", "speed"}:
        v = positive("speed", speed)
        h = (positive("energy", energy) / m - 0.5 * v**2) / g
        if h <= 0.0:
            raise ValueError(
                f"energy {energy!r} J is below the kinetic energy of speed {speed!r} m/s at height 0"
            )
        return _AngleLine(h, v)
    if given == {"energy", "angle"}:
        th = leg_angle("angle", angle)
        if th <= 0.0:
            raise ValueError(
                f"angle must be positive (the leg ahead of the body at touchdown), got {angle!r}"
            )
        return _HeightLine(positive("energy", energy) / m, th, g, params.q_r_td)
    raise ValueError(
        "fixed_points takes apex_height and speed, energy and speed, or energy and angle; got "
        + (", ".join(sorted(given)) or "none of them")
    )


# ----------------------------------------------------------------------------------------------
# Bracketing and refinement
# ----------------------------------------------------------------------------------------------
def _brackets(x: np.ndarray, f: np.ndarray, ok: np.ndarray) -> list[tuple[float, float, float, float]]:
    """(a, b, f(a), f(b)) for each sign change of ``f`` between two neighbouring completed steps; an
    exact zero at a grid point is a bracket of width 0."""
    out = []
    for i in range(len(x)):
        if ok[i] and f[i] == 0.0:
            out.append((x[i], x[i], 0.0, 0.0))
        elif i + 1 < len(x) and ok[i] and ok[i + 1] and f[i] * f[i + 1] < 0.0:
            out.append((x[i], x[i + 1], f[i], f[i + 1]))
    return out


def _derivative(jr, tangent: dict[str, float]) -> float:
    """d(h' - h)/dx along the line: sum over the inputs of dh'/d input * d input/dx, minus dh/dx."""
    return sum(jr["next_apex_height", k] * t for k, t in tangent.items() if t) - tangent["apex_height"]


def _point(name, params, line, x, jr, iterations, status) -> FixedPoint:
    h, v, th = (float(c) for c in line.point(x))
    res = jr.result
    nan = math.nan
    dh, dv = (res.next_apex_height - h, res.next_apex_speed - v) if res.ok else (nan, nan)
    lam, mult, drift = nan, (complex(nan, nan),) * 2, nan
    if status == Status.OK and jr.ok:
        a = np.array(
            [
                [jr[o, i] for i in ("apex_height", "apex_speed")]
                for o in ("next_apex_height", "next_apex_speed")
            ]
        )
        lam = float(a[0, 0] + a[0, 1] * (-params.g_f / v)) if v > 0.0 else nan
        z = sorted(np.linalg.eigvals(a).astype(complex), key=lambda c: abs(c - 1.0))
        mult = (complex(z[0]), complex(z[1]))
        grad = np.array([params.g_f, v])  # dE/d(h, v) / m
        drift = float(np.max(np.abs(grad @ a - grad) / grad)) if v > 0.0 else nan
    elif status == Status.OK:
        status = Status(int(jr.status))
    if status == Status.OK and not math.isfinite(lam):
        status = Status.NUMERICAL_RANGE
    message = MESSAGES[int(status)]
    energy = energy_of(params, h, v)
    return FixedPoint(name, h, v, th, energy, lam, mult, dh, dv, iterations, status, message, drift)


def _refine(name, params, line, a, b, fa, fb, options) -> FixedPoint:
    """Safeguarded Newton's method in the bracket [a, b] (f(a) f(b) <= 0), from the secant point."""
    x = a if fa == 0.0 else (b if fb == 0.0 else a - fa * (b - a) / (fb - fa))
    for it in range(1, MAX_ITER + 1):
        jr = apex_jacobian(name, params, *line.point(x), **options)
        if not jr.result.ok:  # a step inside the bracket fails: no fixed point to report there
            return _point(name, params, line, x, jr, it, Status(int(jr.result.status)))
        f = jr.result.next_apex_height - line.point(x)[0]
        if abs(f) <= FTOL:
            return _point(name, params, line, x, jr, it, Status.OK)
        if (f < 0.0) == (fa < 0.0):
            a, fa = x, f
        else:
            b, fb = x, f
        d = _derivative(jr, line.tangent(x)) if jr.ok else math.nan
        x_new = x - f / d if math.isfinite(d) and d != 0.0 else math.nan
        if not (min(a, b) < x_new < max(a, b)):
            x_new = 0.5 * (a + b)
        if abs(x_new - x) <= XTOL:
            jr = apex_jacobian(name, params, *line.point(x_new), **options)
            if not jr.result.ok:
                status = Status(int(jr.result.status))
            elif abs(jr.result.next_apex_height - line.point(x_new)[0]) > RESIDUAL_TOL:
                status = Status.NOT_CONVERGED  # the bracket holds a jump of h', not a root
            else:
                status = Status.OK
            return _point(name, params, line, x_new, jr, it + 1, status)
        x = x_new
    return _point(name, params, line, x, jr, MAX_ITER, Status.NOT_CONVERGED)


def fixed_points(
    name: str,
    params: SlipParams,
    *,
    apex_height: float | None = None,
    energy: float | None = None,
    speed: float | None = None,
    angle: float | None = None,
    scan: int = SCAN,
    progress: bool | None = False,
    **options,
) -> FixedPoints:
    """Every fixed point of map ``name``'s apex-return map on a line, in increasing order of the unknown.

    Give ``apex_height`` [m] and ``speed`` [m/s] (or ``energy`` [J] and ``speed``): the touchdown
    angles q_th_td in (0, pi/2) whose step returns to that apex; or ``energy`` and ``angle``
    (q_th_td [rad], from the vertical): the apex heights on the energy level m (g_f h + v^2/2) = E.
    ``options`` are the map's (``slipmaps maps``); ``progress`` shows the scan's bar (exact map).
    A fixed point whose refinement fails has a failure ``status`` (``ok`` False) and NaN stability.
    The result is a :class:`FixedPoints` (a tuple): when every step of the scan fails (the map
    fails on the whole line, not a line without gaits) its ``status`` and ``message`` say so, and
    ``scan`` has the map's status counts.
    ValueError for bad arguments and for parameters whose step does not conserve the energy
    (:func:`check_conservative`).
    """
    check_conservative(params)
    get(name)
    line = _line(params, apex_height, energy, speed, angle)
    if isinstance(scan, bool) or not isinstance(scan, int) or scan < 2:
        raise ValueError(f"scan must be an integer >= 2, got {scan!r}")
    x = line.grid(scan)
    if x.size == 0:
        top, touch = line.e / line.g, line.q_r_td * math.cos(line.angle)  # only a height line is empty
        message = (
            f"no apex on the energy level is above the touchdown height {touch:.6g} m (at zero speed "
            f"the apex is {top:.6g} m high): no touchdown"
        )
        return FixedPoints(status=Status.APEX_TOO_LOW, message=message)
    res = apex_return_batch(name, params, *line.point(x), progress=progress, **options)
    f = np.asarray(res["next_apex_height"]) - np.asarray(line.point(x)[0])
    points = [_refine(name, params, line, *br, options) for br in _brackets(x, f, np.asarray(res.ok))]
    return _searched(points, res.counts())
