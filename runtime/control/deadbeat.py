"""Deadbeat step control on a map: the controls that take the current apex to a target next apex.

Given the current apex (height h [m] above the ground under it, signed speed v [m/s]), the ground
of the next touchdown (``ground`` [m], a step up positive) and a target next apex (height H above
that ground, signed speed V), :func:`deadbeat` chooses the controls of one step on a map (the
controller's model, any map of ``slipmaps.maps()``):

* ``touchdown_angle`` (q_th_td [rad], from the vertical, counterclockwise positive), set in flight;
* ``k_c`` [N/m], the leg's stiffness while it compresses (set in flight), and ``k_d`` [N/m], the
  stiffness from the bottom on; their difference is the only way a step changes its total energy,
  by (k_d - k_c)(l0 - q_r_b)^2 / 2 at the bottom (report eq 97): at k_c = k_d (and g_s = g_f,
  q_r_td = q_r_lo) the step conserves the energy, so the next apex height and speed cannot both be
  chosen;
* ``k``, for a map that needs a constant stiffness (``"constant_stiffness"`` in its ``requires``:
  ``geyer``, the gravity corrections): k_c = k_d = k together, the only stiffness such a map has.

Control sets: the angle alone (one target: the speed when ``target_speed`` is given, else the
height; the other is predicted and reported), the angle and k_d (the default), the angle and k_c,
all three (two targets, one control to spare: the stiffness nearest the nominal, below), and for a
constant-stiffness map the angle and k. Without ``controls`` (None) the solve takes the angle and
k_d, or the angle alone for a constant-stiffness map (:func:`default_controls`).

The solve (:mod:`.compiled`): Newton's method with the map's generated apex-return Jacobian (its
d/d touchdown_angle, d/d k_c, d/d k_d or d/d k columns), by default refreshed once and then updated
by Broyden's rank-one secant (``jacobian="newton"``: the generated Jacobian at every step), in the
scaled unknowns (angle / :data:`ANGLE_SCALE`, stiffness / the nominal k_c of ``params``) and the
scaled residual (height / l0, speed / sqrt(g_f l0)); every control within its bounds (projection
with an active set); a backtracking line search on the residual norm, a step where the map fails
counting as no decrease; with one control a scan of its range and a bracketed (Illinois) solve
when Newton does not reach the target. With more controls than targets, the stated preference is
the least change from the starting controls in the scaled norm, which makes the angle cheap (1 rad
of angle weighs as much as 1/ANGLE_SCALE of the nominal stiffness): the angle takes what it can,
and k_c and k_d share the rest, each as close to its nominal value (``params.k_c``, ``params.k_d``)
as the target allows.

Statuses (:class:`PlanStatus`, a string enum):

* ``REACHED``: the model's next apex (``next_apex_height``, ``next_apex_speed``) is within ``tol``
  of the target (scaled: ``tol`` m of height per metre of leg, ``tol`` sqrt(g_f l0) of speed;
  default 1e-9);
* ``UNREACHABLE``: no control within the bounds reaches it; the result holds the closest reachable
  next apex the solve found (its controls, the predicted apex, ``residual`` the scaled distance, and
  the step's energy budget: ``energy_range``, what k_d within its bounds can add or remove at the
  chosen angle and k_c, beside ``energy_needed``);
* ``MAP_FAILED``: the map fails (``map_status``, e.g. ``APEX_TOO_LOW``, ``FALL``) at every
  control the solve tried.

Bounds (:data:`DEFAULT_ANGLE_BOUNDS`, :data:`DEFAULT_STIFFNESS_RANGE`): ``bounds={"k_d": (lo, hi),
...}`` overrides any; the default angle bound is |q_th_td| <= 1.2 rad, the stiffnesses k_c, k_d and
k in [0.5, 2] x ``params.k_c``.

:class:`Deadbeat` is the controller prepared once (map, parameters, controls, bounds, options);
:func:`deadbeat` and :func:`deadbeat_batch` build one (cached) per call. Its :meth:`Deadbeat.plan`
is the fast path a run uses (a few microseconds of Python around the compiled solve).

Names as every result's (``slipmaps.runtime.api.names``): the apex a plan starts from is
``apex_height``, ``apex_speed`` (a result's ``inputs``, a batch's table columns), the model's next
apex ``next_apex_height``, ``next_apex_speed``; the former names of the next apex still read, with
a DeprecationWarning.

A plan applied (:func:`apply_plan`, :meth:`DeadbeatResult.apply`): map ``map`` (the exact map by
default: the plant) steps from the apex the plan is for (its ``inputs``) with the plan's
``touchdown_angle`` and its ``k_c`` and ``k_d`` as the step's stiffness; the result is that map's
:func:`slipmaps.apex_return`, whose ``next_apex_height``, ``next_apex_speed`` are where the plan
lands on it. The parameters are the plan's (the model's) unless ``params`` gives the plant's own (a
mass mismatch, ...), their stiffness replaced by the plan's. A constant-stiffness map takes a plan
whose k_c equals its k_d (else the ValueError of its requirement); an UNREACHABLE plan applies its
closest controls, a MAP_FAILED one has none (ValueError).
"""

from __future__ import annotations

import enum
import math
from collections.abc import Mapping
from functools import lru_cache

import numpy as np
from slipmaps.generated.status import MESSAGES, Status

from ..api import memory
from ..api.batch import BatchInterrupted
from ..api.calls import KERNELS, Call
from ..api.frames import status_columns, to_arrow, to_pandas
from ..api.index import EXACT, maps
from ..api.maps import APEX_INPUTS, apex_return
from ..api.names import NEXT, RENAMED, Renamed, public, warn_renamed
from ..api.numeric import num
from ..api.params import SlipParams
from ..api.results import Result
from ..api.validate import check_params, leg_angle, limit, non_negative, real, real_array, within_limit
from . import compiled
from .compiled import HEAD_AT as _HEAD
from .compiled import N_HEAD

__all__ = [
    "ANGLE_SCALE",
    "CONTROLS",
    "checked_controls",
    "default_controls",
    "DEFAULT_ANGLE_BOUNDS",
    "DEFAULT_STIFFNESS_RANGE",
    "Deadbeat",
    "DeadbeatBatch",
    "DeadbeatResult",
    "PlanStatus",
    "SolveStatus",
    "deadbeat",
    "deadbeat_batch",
    "apply_plan",
    "default_angle",
    "controller",
]


class PlanStatus(str, enum.Enum):
    """How a deadbeat solve ended (module docstring): ``REACHED``, ``UNREACHABLE`` or ``MAP_FAILED``."""

    REACHED = "REACHED"
    UNREACHABLE = "UNREACHABLE"
    MAP_FAILED = "MAP_FAILED"

    def __str__(self) -> str:
        return self.value


#: The code the solver writes -> the plan status.
PLAN_STATUS = {compiled.REACHED: PlanStatus.REACHED, compiled.UNREACHABLE: PlanStatus.UNREACHABLE}
PLAN_STATUS[compiled.MAP_FAILED] = PlanStatus.MAP_FAILED
#: Plan status -> the code the solver writes (batch results hold codes).
PLAN_CODES = {s: c for c, s in PLAN_STATUS.items()}

#: The control names and the kernel argument each sets.
CONTROLS = {"touchdown_angle": "q_th_td", "k_c": "k_c", "k_d": "k_d", "k": "k"}
#: Default bound of the touchdown angle [rad] (either sign: a step may brake, stop or turn).
DEFAULT_ANGLE_BOUNDS = (-1.2, 1.2)
#: Default range of every stiffness control, as multiples of ``params.k_c``.
DEFAULT_STIFFNESS_RANGE = (0.5, 2.0)
#: The angle's scale [rad] in the scaled unknowns (and in the least-change preference): large, so
#: that with a control to spare the stiffness stays nearest its nominal value.
ANGLE_SCALE = 10.0
#: Default tolerance on the scaled residual.
TOL = 1e-9
#: Points of the one-control scan.
SCAN = 24
#: Map evaluations (Jacobians and values) per solve at most.
MAX_EVALUATIONS = 200
#: Columns of a batch's result computed apart from the solver's rows (statuses and counts as
#: integers, the energies and their temporaries, the targets, the default angles), at most.
BATCH_COLUMNS = 16
#: Stance time of the angle guess, as a fraction of the spring's half period pi sqrt(m / k_c)
#: (measured: the exact stance of the human runner's 5 m/s gait lasts 0.157 s = 0.79 of 0.199 s).
STANCE_FRACTION = 0.8


def default_angle(params: SlipParams, apex_speed, k_c: float | None = None):
    """The starting touchdown angle: the neutral angle whose foot lands half a stance ahead,
    ``asin(v t_s / (2 q_r_td))`` with ``t_s = 0.8 pi sqrt(m / k_c)`` (clipped to ``|q_th| <= 1`` rad); a float
    for a float, an array for an array (the same numbers: the batch starts where the scalar does)."""
    k = params.k_c if k_c is None else k_c
    t_s = STANCE_FRACTION * math.pi * math.sqrt(params.m / k)
    x = np.arcsin(np.clip(np.asarray(apex_speed, dtype=float) * t_s / (2.0 * params.q_r_td), -_SIN1, _SIN1))
    return float(x) if x.ndim == 0 else x


_SIN1 = math.sin(1.0)
_HALF_PI = 0.5 * math.pi


class SolveStatus:
    """The status of a solve held in a solver's row ``_out`` (:class:`DeadbeatResult`, the bottom
    stage's result): ``status``, ``map_status``, ``reached``, ``ok``."""

    __slots__ = ()
    _out: np.ndarray

    def _head(self, name: str) -> float:
        """A field of the solver row's head (:data:`~.compiled.HEAD`), by name."""
        return self._out[_HEAD[name]]

    @property
    def status(self) -> PlanStatus:
        return PLAN_STATUS[int(self._head("plan_status"))]

    @property
    def map_status(self) -> Status:
        return Status(int(self._head("map_status")))

    @property
    def reached(self) -> bool:
        return int(self._head("plan_status")) == compiled.REACHED

    @property
    def ok(self) -> bool:
        """True unless the map failed (a reached or the closest reachable apex is returned)."""
        return int(self._head("plan_status")) != compiled.MAP_FAILED


class DeadbeatResult(SolveStatus):
    """One deadbeat solve (module docstring); SI units, NaN where a value does not exist. The values
    are read from the solver's row when asked for (a run asks for a few of them per step).

    ``status`` (:class:`PlanStatus`), ``message``, the controls ``touchdown_angle``, ``k_c``, ``k_d``
    (equal for a constant-stiffness map), the model's next apex at them ``next_apex_height``,
    ``next_apex_speed`` (``prediction``: every output of the map, by the map's result names),
    ``inputs`` (the apex it starts from ``apex_height``, ``apex_speed``, the ``ground`` and the
    ``retraction_rate``), ``params`` (the model's), ``residual`` (the scaled distance to the
    target), ``map_status``, the targets (``target_height`` / ``target_speed``, NaN when not a
    target), the step's energy ``energy_change`` = E' - E [J] (flight energies above the touchdown
    ground), ``energy_needed`` (of the target, when both are targets), ``energy_range`` (what k_d
    within its bounds makes of energy_change at the chosen angle and k_c), ``at_bounds``, the work
    done (``jacobians``, ``evaluations``, ``iterations``). :meth:`apply` steps a map (the exact
    one by default) with the plan's controls (module docstring).
    """

    __slots__ = ("_ctl", "_out", "_p", "_apex", "_targets", "_angle")

    def __init__(self, ctl: Deadbeat, out: np.ndarray, p: np.ndarray, apex, targets, angle: float):
        # apex: (height, speed, ground, retraction rate) as the plan was asked
        self._ctl, self._out, self._p, self._apex, self._targets = ctl, out, p, apex, targets
        self._angle = angle  # the starting (or, not a control, the fixed) touchdown angle

    # the solve
    @property
    def map(self) -> str:
        return self._ctl.name

    @property
    def controls(self) -> tuple[str, ...]:
        return self._ctl.controls

    @property
    def params(self) -> SlipParams:
        """The parameters the plan was made with (the model's; its nominal stiffness)."""
        return self._ctl.params

    @property
    def inputs(self) -> dict[str, float]:
        """The step the plan is for (``apex_height``, ``apex_speed``, ``ground``,
        ``retraction_rate``, the apex-return inputs' names)."""
        h, v, gr, rate = self._apex
        return {"apex_height": h, "apex_speed": v, "ground": gr, "retraction_rate": rate}

    @property
    def jacobians(self) -> int:
        return int(self._head("jacobians"))

    @property
    def evaluations(self) -> int:
        return int(self._head("evaluations"))

    @property
    def iterations(self) -> int:
        return int(self._head("iterations"))

    # the controls
    def _control(self, name: str) -> float:
        ctl = self._ctl
        if name in ctl.controls:
            return float(self._out[_HEAD["u0"] + ctl.controls.index(name)])
        if name == "touchdown_angle":
            return self._angle  # not a control: the fixed value
        return float(self._p[ctl.solver.p.index(CONTROLS[name])])  # a stiffness, not a control

    @property
    def touchdown_angle(self) -> float:
        return self._control("touchdown_angle")

    @property
    def k_c(self) -> float:
        return self._control("k" if "k" in self._ctl.wrt else "k_c")

    @property
    def k_d(self) -> float:
        return self._control("k" if "k" in self._ctl.wrt else "k_d")

    @property
    def at_bounds(self) -> tuple[str, ...]:
        ctl = self._ctl
        out = []
        for j, c in enumerate(ctl.controls):
            lo, hi = ctl.bounds[c]
            if self._out[_HEAD["u0"] + j] <= lo or self._out[_HEAD["u0"] + j] >= hi:
                out.append(c)
        return tuple(out)

    # the prediction
    @property
    def prediction(self) -> dict[str, float]:
        return dict(zip(self._ctl.public_outputs, map(float, self._out[N_HEAD:]), strict=True))

    @property
    def next_apex_height(self) -> float:
        return float(self._out[N_HEAD + self._ctl._out_h])

    @property
    def next_apex_speed(self) -> float:
        return float(self._out[N_HEAD + self._ctl._out_v])

    apex_height = Renamed("next_apex_height", "a deadbeat result")
    apex_speed = Renamed("next_apex_speed", "a deadbeat result")

    @property
    def residual(self) -> float:
        return float(self._head("residual"))

    @property
    def target_height(self) -> float:
        return self._targets[0]

    @property
    def target_speed(self) -> float:
        return self._targets[1]

    @property
    def height_error(self) -> float:
        return self.next_apex_height - self.target_height

    @property
    def speed_error(self) -> float:
        return self.next_apex_speed - self.target_speed

    @property
    def touchdown_limit(self) -> float:
        """The smallest touchdown angle magnitude [rad] at which the leg (length q_r_td, held still)
        reaches the ground from this apex: acos((apex height - ground) / q_r_td), the touchdown
        condition of report section 2.1 (the apex above ground + q_r_td cos q_th_td); 0 when every
        angle does."""
        h, _, gr, _ = self._apex
        ratio = (h - gr) / self._ctl.params.q_r_td
        return math.acos(ratio) if ratio < 1.0 else 0.0

    # the energy
    def _energy_in(self) -> float:
        p = self._ctl.params
        h, v, gr, _ = self._apex
        return p.m * (p.g_f * (h - gr) + 0.5 * v * v)

    @property
    def energy_change(self) -> float:
        p = self._ctl.params
        hn, vn = self.next_apex_height, self.next_apex_speed
        return p.m * (p.g_f * hn + 0.5 * vn * vn) - self._energy_in()

    @property
    def energy_needed(self) -> float:
        p = self._ctl.params
        H, V = self._targets
        return p.m * (p.g_f * H + 0.5 * V * V) - self._energy_in()

    @property
    def authority(self) -> float:
        """dE'/dk_d at the controls [J per N/m] (NaN for a constant-stiffness map)."""
        return float(self._head("authority"))

    @property
    def energy_range(self) -> tuple[float, float]:
        """E' - E with k_d at its lower and at its upper bound, the angle and k_c as found [J]
        (NaN for a constant-stiffness map, or where the map fails at the bound)."""
        e_in = self._energy_in()
        return (float(self._head("energy_low")) - e_in, float(self._head("energy_high")) - e_in)

    @property
    def message(self) -> str:
        return message_of(self, self._ctl.bounds)

    def apply(self, map: str = EXACT, params: SlipParams | None = None, **options) -> Result:  # noqa: A002
        """The step of map ``map`` (the exact map by default: the plant) with this plan's controls
        (:func:`~slipmaps.apply_plan`): ``params`` the plant's parameters (default: the plan's),
        ``options`` the map's."""
        if not self.ok:
            raise ValueError(
                f"apply_plan: plan has status {self.status} ({self.map_status.name}): the map failed at "
                "every control the solve tried, so it has no controls to apply"
            )
        base = self.params if params is None else params
        if not isinstance(base, SlipParams):
            raise TypeError(f"params must be a SlipParams, got {type(base).__name__}")
        stiffness = base.with_(k_c=self.k_c, k_d=self.k_d)
        return apex_return(map, stiffness, touchdown_angle=self.touchdown_angle, **self.inputs, **options)

    def as_dict(self) -> dict:
        """JSON-ready: every value by name (None for NaN), statuses by name."""

        def f(x):
            return float(x) if math.isfinite(x) else None

        return {
            "map": self.map,
            "status": self.status.value,
            "message": self.message,
            "controls": list(self.controls),
            "touchdown_angle": f(self.touchdown_angle),
            "k_c": f(self.k_c),
            "k_d": f(self.k_d),
            **{k: f(x) for k, x in self.inputs.items()},
            "next_apex_height": f(self.next_apex_height),
            "next_apex_speed": f(self.next_apex_speed),
            "target_height": f(self.target_height),
            "target_speed": f(self.target_speed),
            "residual": f(self.residual),
            "map_status": self.map_status.name,
            "energy_change": f(self.energy_change),
            "energy_needed": f(self.energy_needed),
            "energy_range": [f(x) for x in self.energy_range],
            "at_bounds": list(self.at_bounds),
            "jacobians": self.jacobians,
            "evaluations": self.evaluations,
            "iterations": self.iterations,
        }

    def __repr__(self) -> str:
        return (
            f"DeadbeatResult(map={self.map!r}, status={self.status.value}, touchdown_angle="
            f"{self.touchdown_angle!r}, k_c={self.k_c!r}, k_d={self.k_d!r}, next_apex_height="
            f"{self.next_apex_height!r}, next_apex_speed={self.next_apex_speed!r}, "
            f"residual={self.residual:.3g})"
        )


class DeadbeatBatch(Mapping):
    """Many deadbeat solves: columns by name in the inputs' broadcast shape (``touchdown_angle``,
    ``k_c``, ``k_d``, ``target_height``, ``target_speed``, ``residual``, ``energy_change``,
    ``energy_low``, ``energy_high``, ``authority``, ``jacobians``, ``evaluations``, ``iterations``,
    every output of the map by its result name: the next apex ``next_apex_height``,
    ``next_apex_speed``, ...), ``status`` (plan codes: 0 REACHED, 1 UNREACHABLE, 2 MAP_FAILED),
    ``map_status`` (the map's Status codes); ``inputs`` the apex each row starts from
    (``apex_height``, ``apex_speed``, ``ground``, ``retraction_rate``); ``counts()`` the rows per
    plan status; ``columns()``, ``to_pandas()``, ``to_arrow()`` a row per solve, the inputs first."""

    def __init__(
        self,
        map_name: str,
        columns: dict[str, np.ndarray],
        shape: tuple[int, ...],
        inputs: dict[str, np.ndarray] | None = None,
        former: dict[str, str] | None = None,
    ):
        self.map = map_name
        self._columns = columns
        self.shape = shape
        self.inputs = dict(inputs or {})
        self._former = RENAMED if former is None else former

    def __getitem__(self, name: str) -> np.ndarray:
        if name in self._columns:
            return self._columns[name]
        new = self._former.get(name) if isinstance(name, str) else None
        if new in self._columns:
            warn_renamed(name, new, "a deadbeat batch")
            return self._columns[new]
        raise KeyError(f"deadbeat batch has no column {name!r}; it has {', '.join(self)}")

    def __contains__(self, name) -> bool:
        return name in self._columns

    def __iter__(self):
        return iter(self._columns)

    def __len__(self) -> int:
        return len(self._columns)

    @property
    def status(self) -> np.ndarray:
        return self._columns["status"]

    @property
    def reached(self) -> np.ndarray:
        return self.status == compiled.REACHED

    def counts(self) -> dict[str, int]:
        codes, counts = np.unique(self.status, return_counts=True)
        order = np.argsort(-counts, kind="stable")
        return {PLAN_STATUS[int(codes[i])].value: int(counts[i]) for i in order}

    def columns(self) -> dict[str, np.ndarray]:
        """A 1-D column per input and per value, a row per solve (C order of the shape); the plan
        status by name (``status``) and code (``status_code``), the map's likewise (``map_status``,
        ``map_status_code``)."""
        out = {k: np.asarray(v).reshape(-1) for k, v in self.inputs.items()}
        out |= {k: np.asarray(v).reshape(-1) for k, v in self._columns.items() if k not in _STATUS_COLUMNS}
        codes = self.status.reshape(-1)
        out["status"] = np.array([PLAN_STATUS[int(c)].value for c in codes], dtype=object)
        out["status_code"] = codes
        return out | status_columns(self._columns["map_status"], "map_status")

    def to_pandas(self):
        """A pandas DataFrame of :meth:`columns` (pandas is the optional extra ``[pandas]``)."""
        return to_pandas(self.columns())

    def to_arrow(self):
        """A pyarrow Table of :meth:`columns`."""
        return to_arrow(self.columns())

    def __repr__(self) -> str:
        return f"DeadbeatBatch(map={self.map!r}, shape={self.shape}, status={self.counts()})"


_STATUS_COLUMNS = ("status", "map_status")


def former_columns(outputs: tuple[str, ...]) -> dict[str, str]:
    """A deadbeat batch's former column names -> today's: the next apex (``apex_height`` ...) and
    the map's ``outputs``, once written ``next_<kernel name>`` (``next_t_stance`` -> ``t_stance``)."""
    return {NEXT + o: public(o) for o in outputs if NEXT + o != public(o)} | RENAMED


def _const_maps() -> tuple[str, str]:
    cs = [m.name for m in maps() if "constant_stiffness" in m.requires]
    vs = [m.name for m in maps() if "constant_stiffness" not in m.requires]
    return ", ".join(cs), ", ".join(vs)


def default_controls(call: Call) -> tuple[str, ...]:
    """The controls when none are given: the angle and k_d, the angle alone for a map that needs a
    constant stiffness (it has no k_d; as the scenario runner does)."""
    if "k" in call.spec("apex_return_jacobian").wrt:
        return ("touchdown_angle",)
    return ("touchdown_angle", "k_d")


def checked_controls(call: Call, controls) -> tuple[str, ...]:
    """The controls validated against the map (ValueError naming the problem), the angle first;
    None: :func:`default_controls`."""
    if controls is None:
        return default_controls(call)
    if isinstance(controls, str):
        controls = (controls,)
    try:
        names = tuple(controls)
    except TypeError:
        raise TypeError(f"controls must be a tuple of names, got {controls!r}") from None
    if not names:
        raise ValueError("controls must name at least one of " + ", ".join(CONTROLS))
    for c in names:
        if c not in CONTROLS:
            raise ValueError(f"unknown control {c!r}: the controls are {', '.join(CONTROLS)}")
    if len(set(names)) != len(names):
        raise ValueError(f"controls name a control twice: {names!r}")
    wrt = call.spec("apex_return_jacobian").wrt
    constant = "k" in wrt
    cs, vs = _const_maps()
    for c in names:
        if c in ("k_c", "k_d") and constant:
            raise ValueError(
                f"map {call.info.name!r} needs a constant stiffness, so it has no {c} to control: give "
                f"controls=('touchdown_angle',) or ('touchdown_angle', 'k') (k_c = k_d = k together), or a "
                f"map that accepts k_c != k_d ({vs})"
            )
        if c == "k" and not constant:
            raise ValueError(
                f"control 'k' (k_c = k_d together) is for the constant-stiffness maps ({cs}); map "
                f"{call.info.name!r} has k_c and k_d: control them by name"
            )
    order = {c: i for i, c in enumerate(CONTROLS)}
    return tuple(sorted(names, key=order.__getitem__))


def control_bounds(params: SlipParams, controls: tuple[str, ...], bounds) -> dict[str, tuple[float, float]]:
    """The bounds of ``controls``: the defaults, with ``bounds`` (control -> (low, high)) over them;
    ValueError (one line naming ``bounds[control]``) for a pair that is not one (every key of
    ``bounds`` is checked, whether a control of ``controls`` or not)."""
    lo_k, hi_k = (f * params.k_c for f in DEFAULT_STIFFNESS_RANGE)
    out = {c: (DEFAULT_ANGLE_BOUNDS if c == "touchdown_angle" else (lo_k, hi_k)) for c in controls}
    for key, pair in dict(bounds or {}).items():
        if key not in CONTROLS:
            raise ValueError(f"bounds: unknown control {key!r}: the controls are {', '.join(CONTROLS)}")
        try:
            lo, hi = pair
        except (TypeError, ValueError):
            raise ValueError(f"bounds[{key!r}] must be a pair (low, high), got {pair!r}") from None
        lo, hi = real(f"bounds[{key!r}] low", lo), real(f"bounds[{key!r}] high", hi)
        if not lo < hi:
            raise ValueError(f"bounds[{key!r}] must have low < high, got ({num(lo)}, {num(hi)})")
        if key == "touchdown_angle":
            leg_angle(f"bounds[{key!r}] low", lo)
            leg_angle(f"bounds[{key!r}] high", hi)
        elif lo <= 0.0:
            raise ValueError(f"bounds[{key!r}]: a stiffness must be positive, got low {num(lo)}")
        if key in out:
            out[key] = (lo, hi)
    return out


_OPTIONS = ("tol", "jacobian", "scan", "max_evaluations", "budget")


def _finite(name: str, x) -> float:
    """``x`` as a finite float (the common case checked inline), else :func:`real`'s error."""
    if type(x) is float and math.isfinite(x):
        return x
    return real(name, x)


class Deadbeat:
    """A deadbeat controller on map ``name`` (module docstring), prepared once: validated, its
    kernels and solver compiled (the first one per map and process takes a few seconds).

    ``plan(h, v, H, V, ground=0.0)`` solves one step; ``plan_batch`` many (arrays broadcast, in
    parallel). ``touchdown_angle=``, ``k_c=``, ``k_d=``, ``k=`` of a call give the starting values of
    the controls (the angle's default: :func:`~slipmaps.runtime.control.deadbeat.default_angle`; the
    stiffness's: ``params``, which are also the nominal values of the least-change preference) and
    the fixed value of a quantity that is not a control (the touchdown angle when only stiffnesses
    are controlled). ``budget=False`` leaves out the energy budget (``energy_low``, ``energy_high``,
    ``authority`` NaN): two map evaluations fewer per solve (``slipmaps.swing_policy``'s solves).
    """

    def __init__(
        self,
        name: str,
        params: SlipParams,
        *,
        controls=None,
        bounds=None,
        tol: float = TOL,
        jacobian: str = "broyden",
        scan: int = SCAN,
        max_evaluations: int = MAX_EVALUATIONS,
        budget: bool = True,
        **options,
    ):
        check_params(params)
        call = Call.of(name, params, options)
        if call.backend is not KERNELS:
            raise ValueError(
                f"map {call.info.name!r} with options {dict(options)!r} runs outside the compiled kernels; "
                "the deadbeat solve needs them (e.g. the exact map's default method='compiled')"
            )
        self.call = call
        self.name = call.info.name
        self.params = params
        self._rate_limit = limit("retraction_rate", params)  # derive/params.py's row
        self.controls = checked_controls(call, controls)
        self.bounds = control_bounds(params, self.controls, bounds)
        if jacobian not in ("broyden", "newton"):
            raise ValueError(f"jacobian must be 'broyden' or 'newton', got {jacobian!r}")
        if not isinstance(budget, bool):
            raise ValueError(f"budget must be True or False, got {budget!r}")
        tol = real("tol", tol)
        if not tol > 0.0:
            raise ValueError(f"tol must be positive, got {num(tol)}")
        for key, value in (("scan", scan), ("max_evaluations", max_evaluations)):
            if isinstance(value, bool) or not isinstance(value, int) or value < 2:
                raise ValueError(f"{key} must be an integer >= 2, got {value!r}")
        self.options = dict(call.options)
        self.tol = tol
        apex, jac = call.spec("apex_return"), call.spec("apex_return_jacobian")
        self.solver = compiled.Solver(apex, jac)
        self.outputs = apex.outputs
        self.public_outputs = apex.public_outputs
        self.wrt = jac.wrt
        self._out_h = self.outputs.index("apex_height")
        self._out_v = self.outputs.index("apex_speed")
        # the inputs x of a row, by name: every apex-return input at its default, the apex and the
        # angle set per step (derive/params.py's APEX_INPUTS)
        defaults = {r["arg"]: float(r.get("default", math.nan)) for r in APEX_INPUTS.values()}
        self._x = np.array([defaults[a] for a in apex.x])
        self._at = {key: apex.x.index(APEX_INPUTS[key]["arg"]) for key in APEX_INPUTS}
        self._record = call.record(apex)
        # the energy budget's stiffness: k_d (none for a constant-stiffness map)
        kd = "k_d" if "k_d" in self.wrt and budget else None
        kd_bounds = self.bounds.get("k_d", tuple(f * params.k_c for f in DEFAULT_STIFFNESS_RANGE))
        names = [CONTROLS[c] for c in self.controls]
        fields = dict(
            controls=names,
            lo=[self.bounds[c][0] for c in self.controls],
            hi=[self.bounds[c][1] for c in self.controls],
            scale=[ANGLE_SCALE if c == "touchdown_angle" else params.k_c for c in self.controls],
            weight=[1.0 / params.l0, 1.0 / math.sqrt(params.g_f * params.l0)],
            tol=tol,
            kd=kd,
            kd_bounds=kd_bounds,
            mass=params.m,
            g_f=params.g_f,
            max_evaluations=max_evaluations,
            broyden=int(jacobian == "broyden"),
            scan=scan,
        )
        self.fields = fields  # the solver's settings but the targeted components (footholds' baseline)
        self._settings = {t: self.solver.settings(targeted=t, **fields) for t in ((1, 1), (1, 0), (0, 1))}
        places = [self.solver.place(n) for n in names]
        self._clip = tuple((at, *self.bounds[c]) for at, c in zip(places, self.controls, strict=True))
        self._angle_alone = "touchdown_angle" in self.controls and len(self.controls) == 1

    # ------------------------------------------------------------------------------------------
    def _targeted(self, target_height, target_speed) -> tuple[int, int]:
        """Which components are targets: both, or with one control (or a constant-stiffness map
        conserving the energy) the speed when given, else the height."""
        th, tv = target_height is not None, target_speed is not None
        if not (th or tv):
            raise ValueError("give target_height, target_speed or both")
        if len(self.controls) == 1 and th and tv:
            return 0, 1
        return int(th), int(tv)

    def _record_with(self, k_c, k_d, k) -> np.ndarray:
        """The parameter record with given starting (or fixed) stiffness values."""
        p = self._record
        for key, value in (("k_c", k_c), ("k_d", k_d), ("k", k)):
            if value is not None:
                if key not in self.solver.p:
                    raise ValueError(f"map {self.name!r} has no stiffness {key!r}")
                x = _finite(key, value)
                if x <= 0.0:
                    raise ValueError(f"{key} must be positive, got {num(x)}")
                p = p.copy() if p is self._record else p
                p[self.solver.p.index(key)] = x
        return p

    def _inputs(self, cols: dict, n: int) -> np.ndarray:
        """The rows' inputs ``x`` (n, len(x)): the given apex-return inputs by their API names, the
        others at their defaults; the controls clipped into their bounds."""
        X = np.tile(self._x, (n, 1))
        for key, j in self._at.items():
            if key in cols:
                X[:, j] = cols[key]
        for (in_p, j), lo, hi in self._clip:
            if not in_p:
                X[:, j] = np.clip(X[:, j], lo, hi)
        return X

    def _input_row(self, values: dict) -> np.ndarray:
        """:meth:`_inputs` of one row (1, len(x)) from Python floats, without array passes."""
        x = self._x.copy()
        for key, j in self._at.items():
            if key in values:
                x[j] = values[key]
        for (in_p, j), lo, hi in self._clip:
            if not in_p:
                x[j] = min(max(x[j], lo), hi)
        return x[None, :]

    def plan(
        self,
        apex_height,
        apex_speed,
        target_height,
        target_speed,
        *,
        ground=0.0,
        retraction_rate=0.0,
        touchdown_angle=None,
        k_c=None,
        k_d=None,
        k=None,
    ) -> DeadbeatResult:
        """One step (module docstring): the controls from the apex (h, v) over ``ground`` to the
        target (``target_height`` or ``target_speed`` may be None: not a target), the swing leg
        retracting at ``retraction_rate`` [rad/s] after the apex (the angle solved for is then the
        one at the apex; ValueError beyond the maps' range, ``|rate| <= sqrt(g_f/q_r_td)``); the
        other keywords are starting (or fixed) values of the controls."""
        h = _finite("apex_height", apex_height)
        if h < 0.0:
            non_negative("apex_height", h)
        v = _finite("apex_speed", apex_speed)
        gr = _finite("ground", ground)
        rate = _finite("retraction_rate", retraction_rate)
        if abs(rate) > self._rate_limit:
            within_limit("retraction_rate", "retraction_rate", rate, self.params)
        tgt = self._targeted(target_height, target_speed)
        H = _finite("target_height", target_height) if tgt[0] else math.nan
        V = _finite("target_speed", target_speed) if tgt[1] else math.nan
        th = (
            default_angle(self.params, v)
            if touchdown_angle is None
            else _finite("touchdown_angle", touchdown_angle)
        )
        if not -_HALF_PI < th < _HALF_PI:
            leg_angle("touchdown_angle", th)
        p = self._record if k_c is None and k_d is None and k is None else self._record_with(k_c, k_d, k)
        given = {"apex_height": h, "apex_speed": v, "ground": gr, "touchdown_angle": th}
        x = self._input_row(given | {"retraction_rate": rate})
        T = np.array([[H if tgt[0] else 0.0, V if tgt[1] else 0.0]])
        out = self.solver.run_one(x, p[None, :], T, self._settings[tgt])
        return DeadbeatResult(self, out, p, (h, v, gr, rate), (H, V), th)

    def plan_batch(
        self,
        apex_height,
        apex_speed,
        target_height,
        target_speed,
        *,
        ground=0.0,
        retraction_rate=0.0,
        touchdown_angle=None,
    ) -> DeadbeatBatch:
        """Many steps in parallel: the inputs broadcast (``touchdown_angle``: starting angles, default
        :func:`~slipmaps.runtime.control.deadbeat.default_angle` of each apex speed); a plan status
        per row (an invalid row, e.g. a NaN apex, is MAP_FAILED with the map's INVALID_INPUT). Its
        memory need is checked before any row is copied; Ctrl-C raises
        :class:`~slipmaps.BatchInterrupted` with the rows solved."""
        tgt = self._targeted(target_height, target_speed)
        given = {
            "apex_height": apex_height,
            "apex_speed": apex_speed,
            "touchdown_angle": 0.0 if touchdown_angle is None else touchdown_angle,
            "ground": ground,
            "retraction_rate": retraction_rate,
            "target_height": target_height if tgt[0] else 0.0,
            "target_speed": target_speed if tgt[1] else 0.0,
        }
        parts = np.broadcast_arrays(*(np.asarray(real_array(k, x), dtype=float) for k, x in given.items()))
        shape = parts[0].shape
        n = int(np.prod(shape))
        self._check_memory(n)  # before the rows are copied
        cols = {k: np.ascontiguousarray(p.reshape(n)) for k, p in zip(given, parts, strict=True)}
        if touchdown_angle is None:
            cols["touchdown_angle"] = default_angle(self.params, cols["apex_speed"])
        X = self._inputs(cols, n)
        T = np.ascontiguousarray(np.stack([cols["target_height"], cols["target_speed"]], axis=1))
        P = self._record_clipped()[None, :]
        try:
            OUT = self.solver.run(X, P, T, self._settings[tgt])
        except BatchInterrupted as stop:  # the rows finished, as a batch of their own
            done = stop.done
            finished = {k: c[:done] for k, c in cols.items()}
            stop.result = self._batch_result(stop.result, X[:done], P, finished, tgt, (done,))
            raise
        return self._batch_result(OUT, X, P, cols, tgt, shape)

    def _check_memory(self, n: int) -> int:
        """The bytes a batch of ``n`` solves allocates: per row the solver's row (its width), the
        inputs (``x``, the targets, a copy of each of the seven given quantities) and the result's
        columns computed apart from the row (``BATCH_COLUMNS``); ValueError, one line with the
        estimate, beyond the machine's available memory (``slipmaps.runtime.api.memory.check``)."""
        need = 8 * n * (self.solver.width + len(self.solver.x) + 2 + 7 + BATCH_COLUMNS)
        if need < memory.SMALL:
            return need
        return memory.check(
            need,
            f"a deadbeat batch of {n:,} rows ({self.name}) needs",
            "give fewer rows, or split them into several batches",
        )

    def _record_clipped(self) -> np.ndarray:
        """The parameter record with the stiffness controls clipped into their bounds."""
        p = self._record.copy()
        for (in_p, j), lo, hi in self._clip:
            if in_p:
                p[j] = min(max(p[j], lo), hi)
        return p

    def _batch_result(self, OUT, X, P, cols, tgt, shape) -> DeadbeatBatch:
        p = self.params
        H, V = cols["target_height"], cols["target_speed"]
        out: dict[str, np.ndarray] = {}
        out["status"] = OUT[:, _HEAD["plan_status"]].astype(np.int64)
        out["map_status"] = OUT[:, _HEAD["map_status"]].astype(np.int64)
        u = {c: OUT[:, _HEAD["u0"] + j] for j, c in enumerate(self.controls)}

        def given(name):  # a quantity that is not a control, as the rows had it
            in_p, j = self.solver.place(CONTROLS[name])
            return np.broadcast_to(P[:, j], (OUT.shape[0],)) if in_p else X[:, j]

        out["touchdown_angle"] = u.get("touchdown_angle", given("touchdown_angle"))
        if "k" in self.wrt:
            out["k_c"] = out["k_d"] = u.get("k", given("k"))
        else:
            out["k_c"] = u.get("k_c", given("k_c"))
            out["k_d"] = u.get("k_d", given("k_d"))
        for j, name in enumerate(self.public_outputs):
            out[name] = OUT[:, N_HEAD + j]
        out["target_height"] = H if tgt[0] else np.full_like(H, math.nan)
        out["target_speed"] = V if tgt[1] else np.full_like(V, math.nan)
        out["residual"] = OUT[:, _HEAD["residual"]]
        out["authority"] = OUT[:, _HEAD["authority"]]
        for name in ("jacobians", "evaluations", "iterations"):
            out[name] = OUT[:, _HEAD[name]].astype(np.int64)
        h, v, gr = cols["apex_height"], cols["apex_speed"], cols["ground"]
        e_in = p.m * (p.g_f * (h - gr) + 0.5 * v * v)
        hn, vn = out["next_apex_height"], out["next_apex_speed"]
        out["energy_change"] = p.m * (p.g_f * hn + 0.5 * vn * vn) - e_in
        out["energy_low"] = OUT[:, _HEAD["energy_low"]] - e_in
        out["energy_high"] = OUT[:, _HEAD["energy_high"]] - e_in
        shaped = {k: np.asarray(x).reshape(shape) for k, x in out.items()}
        inputs = {
            k: cols[k].reshape(shape) for k in ("apex_height", "apex_speed", "ground", "retraction_rate")
        }
        return DeadbeatBatch(self.name, shaped, shape, inputs, former_columns(self.outputs))

    def warm(self, batch: bool = False) -> Deadbeat:
        """Compile the solver now (numba compiles on the first call; a run warms it before timing
        its steps); ``batch`` the parallel form too. Returns self."""
        p = self.params
        v = math.sqrt(p.g_f * p.l0)
        self.plan(1.05 * p.l0, v, 1.05 * p.l0, v)
        if batch:
            self.plan_batch(1.05 * p.l0, v, 1.05 * p.l0, v)
        return self

    def __repr__(self) -> str:
        return f"Deadbeat({self.name!r}, controls={self.controls}, bounds={self.bounds})"


def message_of(res: DeadbeatResult, bounds: dict) -> str:
    """The result in words: reached, or the closest reachable apex and why (bounds, energy), or the
    map's failure."""
    if res.status == PlanStatus.MAP_FAILED:
        return (
            f"the map fails at every control the solve tried: {res.map_status.name}: "
            f"{MESSAGES[int(res.map_status)]}"
        )
    if res.status == PlanStatus.REACHED:
        return f"reached the target (scaled residual {res.residual:.2g})"
    parts = [
        f"unreachable: the closest next apex found is {res.next_apex_height:.6g} m, "
        f"{res.next_apex_speed:.6g} m/s"
        f" (target {_t(res.target_height, 'm')}, {_t(res.target_speed, 'm/s')}; scaled residual "
        f"{res.residual:.3g})"
    ]
    limit = res.touchdown_limit
    if "touchdown_angle" in res.controls and limit > 0.0 and abs(abs(res.touchdown_angle) - limit) < 1e-3:
        parts.append(
            f"the touchdown geometry binds: from this apex no angle below {limit:.6g} rad in magnitude "
            f"reaches the ground (acos of the apex height over the leg length), and the angle is at it"
        )
    for c in res.at_bounds:
        lo, hi = bounds[c]
        value = res.touchdown_angle if c == "touchdown_angle" else getattr(res, "k_c" if c == "k" else c)
        which = "upper" if value >= hi else "lower"
        parts.append(f"{c} at its {which} bound {value:.6g}")
    lo_e, hi_e = res.energy_range
    need = res.energy_needed
    if math.isfinite(need) and math.isfinite(hi_e) and need > hi_e:
        parts.append(
            f"the target needs {need:+.4g} J and k_d at its upper bound makes this step's energy change "
            f"{hi_e:+.4g} J"
        )
    elif math.isfinite(need) and math.isfinite(lo_e) and need < lo_e:
        parts.append(
            f"the target needs {need:+.4g} J and k_d at its lower bound makes this step's energy change "
            f"{lo_e:+.4g} J"
        )
    return "; ".join(parts)


def _t(x: float, unit: str) -> str:
    return "free" if not math.isfinite(x) else f"{x:.6g} {unit}"


@lru_cache(maxsize=64)
def _prepared(name, params, controls, bounds_key, settings, options) -> Deadbeat:
    return Deadbeat(
        name, params, controls=controls, bounds=dict(bounds_key), **dict(settings), **dict(options)
    )


def _split(options: dict) -> tuple[tuple, tuple]:
    settings = tuple(sorted((k, options.pop(k)) for k in _OPTIONS if k in options))
    return settings, tuple(sorted(options.items()))


def controller(name, params, controls=None, bounds=None, options=None) -> Deadbeat:
    """The prepared :class:`Deadbeat` of these settings (``options``: the map's and the solver's),
    cached across calls when they are hashable."""
    options = {} if options is None else options
    settings, rest = _split(dict(options))
    try:
        key_bounds = tuple(sorted((k, tuple(v)) for k, v in dict(bounds or {}).items()))
        controls_key = (
            None if controls is None else (controls,) if isinstance(controls, str) else tuple(controls)
        )
        hash((name, params, controls_key, key_bounds, settings, rest))
    except TypeError:
        return Deadbeat(name, params, controls=controls, bounds=bounds, **options)
    return _prepared(name, params, controls_key, key_bounds, settings, rest)


def apply_plan(
    plan: DeadbeatResult,
    map: str = EXACT,  # noqa: A002 - the map's name, as every map call's first argument
    params: SlipParams | None = None,
    **options,
) -> Result:
    """The step of map ``map`` (the exact map by default: the plant) from the apex ``plan`` is for,
    with its touchdown angle and its k_c and k_d (module docstring): the map's result
    (:func:`slipmaps.apex_return`). ``params``: the plant's parameters (default: the plan's, the
    model's), their stiffness replaced by the plan's; ``options``: the map's. ``plan.apply(...)``
    is the same."""
    if not isinstance(plan, DeadbeatResult):
        raise TypeError(f"plan must be a DeadbeatResult (slipmaps.deadbeat), got {type(plan).__name__}")
    return plan.apply(map, params, **options)


def deadbeat(
    name: str,
    params: SlipParams,
    apex_height,
    apex_speed,
    target_height,
    target_speed,
    *,
    ground=0.0,
    retraction_rate=0.0,
    controls=None,
    bounds=None,
    touchdown_angle=None,
    k_c=None,
    k_d=None,
    k=None,
    **map_options,
) -> DeadbeatResult:
    """The controls of one step of map ``name`` from the apex (``apex_height`` [m], signed
    ``apex_speed`` [m/s]) over ``ground`` [m] to the target next apex (``target_height`` above the
    touchdown ground, ``target_speed``; either may be None), the swing leg retracting at
    ``retraction_rate`` [rad/s] after the apex: module docstring. ``touchdown_angle``,
    ``k_c``, ``k_d``, ``k`` are starting (or, not being controls, fixed) values; ``map_options``
    the map's options and the solver's ``tol``, ``jacobian`` ("broyden" or "newton"), ``scan``,
    ``max_evaluations``."""
    ctl = controller(name, params, controls, bounds, map_options)
    return ctl.plan(
        apex_height,
        apex_speed,
        target_height,
        target_speed,
        ground=ground,
        retraction_rate=retraction_rate,
        touchdown_angle=touchdown_angle,
        k_c=k_c,
        k_d=k_d,
        k=k,
    )


def deadbeat_batch(
    name: str,
    params: SlipParams,
    apex_height,
    apex_speed,
    target_height,
    target_speed,
    *,
    ground=0.0,
    retraction_rate=0.0,
    controls=None,
    bounds=None,
    touchdown_angle=None,
    **map_options,
) -> DeadbeatBatch:
    """:func:`deadbeat` over arrays (the apex, the targets, the ground and the starting angles
    broadcast), in parallel; a plan status per row. Its memory need is checked before any row is
    copied; Ctrl-C raises :class:`~slipmaps.BatchInterrupted` with the rows solved."""
    ctl = controller(name, params, controls, bounds, map_options)
    return ctl.plan_batch(
        apex_height,
        apex_speed,
        target_height,
        target_speed,
        ground=ground,
        retraction_rate=retraction_rate,
        touchdown_angle=touchdown_angle,
    )
