"""Runs: many consecutive steps, the controller planning with a model map, the plant stepping.

Each step of a run (:func:`run`, :func:`run_batch` for many runs in lockstep):

1. the controller measures the apex (the plant's, plus seeded Gaussian noise of the scenario's
   standard deviations);
2. the ground of the next touchdown, relative to the ground under the apex: the true one when the
   terrain is known (``known`` >= 1, with the grounds of that many touchdowns for the planner), else
   0 (the controller assumes flat ground);
3. the step's target: the scenario's nominal target, with two rules of the maps' step (which keeps
   the direction of the apex speed): a target across zero speed is replaced by a hop in place (0)
   while the measured speed exceeds :data:`V_REVERSE`; below it the step is planned from a hop in
   place (apex speed 0), so that a run stops, then turns; then, with known terrain, the planner
   (:mod:`.planner`) moves it where the coming steps need it;
4. the controller on the model, by the scenario's swing-leg policy (``policy``): ``apex``, the
   deadbeat solve (:class:`~.deadbeat.Deadbeat`, warm-started from the previous step's angle), its
   angle held through the flight; ``retraction``, the same solve with the leg retracting at
   ``retraction_rate`` after the apex; ``time-based``, a swing policy (:mod:`.swing`) over the
   scenario's ``grounds`` around the expected ground, its controls read where the leg meets the true
   ground; ``footholds`` on a stones course, the stones and the controls of the next ``horizon``
   hops planned (:mod:`.footholds_runs`: a foot outside every stone is MISSED). A solve's controls
   are applied whatever its status (the closest reachable ones when UNREACHABLE; when the map
   failed, the previous step's angle and the nominal stiffness);
5. the plant step (:class:`~.plant.Plant`: the exact simulator by default; with the scenario's mass
   and stiffness mismatch: the plant's mass is (1 + mismatch) times the model's, its springs (1 +
   mismatch) times the commanded stiffness); two-stage: the plant's compression half, the k_d chosen
   again at the measured bottom (:class:`~.bottom.BottomDeadbeat`), the decompression half;
6. the next apex; a plant step that fails (a fall, no touchdown, no liftoff...) ends the run there.

Records (:class:`RunBatch`, arrays runs x steps; :class:`Run` one run with its steps as rows):
the apex (true and measured), the ground, the nominal and the planned target, the controls (the
leg's angle at the apex ``swing_angle`` and at the touchdown ``touchdown_angle``; ``swing``: the
leg's angle at :data:`SWING_SAMPLES` evenly spaced times of each descent), the plan status
(:data:`PLAN_MEANINGS`: what the controller's solve promises on its model. ``REACHED``, the model's
next apex on the target from the measured apex on the true ground; ``BLIND``, the same on the flat
ground the controller assumed where the ground is unknown (``known = 0``) and differs: the plant
meets the true ground at another time and angle, so its apex misses by the ground's effect (up to
166 mm on ``examples/blind_running.toml`` with ``policy = "retraction"``, ``retraction_rate =
-1.0``; a time-based step reads its status where the leg met the true ground, so it is never
BLIND); ``UNREACHABLE``, ``MAP_FAILED``; ``OUT_OF_RANGE`` for a time-based step whose ground lies
outside its policy's; ``FIXED`` for a fixed-angle run, the self-stable baseline; ``FEEDBACK`` for
Raibert's controller, which plans nothing; ``FOOTHOLD`` and ``NO_FOOTHOLD`` for the footholds
policy, its feet inside their stones over its horizon or not), the plant
status, the next apex (``next_apex_height``, ``next_apex_speed``: the names of every result,
``slipmaps.runtime.api.names``; the former ``next_height``, ``next_speed`` still read, with a
DeprecationWarning) and its error against the planned target, the step length, the controller's
solve time (us; the scalar run times :meth:`Deadbeat.plan` itself, a batch the parallel call per
run, a time-based step its policy per run), and the stance states and times that make the
continuous path (:meth:`Run.path`, for the figures).

A run's memory is estimated before any work (:func:`memory_estimate`, bytes); one beyond the
machine's memory is refused with the estimate (ValueError). Ctrl-C during a run raises
:class:`RunInterrupted` (a KeyboardInterrupt) whose ``batch`` holds the steps already run.
"""

from __future__ import annotations

import difflib
import math
import time
from dataclasses import dataclass, fields
from pathlib import Path

import numpy as np
from slipmaps.generated.status import Status

from ..api import memory
from ..api.frames import flat_columns, status_columns, to_pandas
from ..api.index import get
from ..api.names import RUN_RENAMED, RenamedKeys, warn_renamed
from ..api.numeric import num
from ..api.progress import Bar
from ..api.validate import POLAR_NAMES, real_array
from . import compiled
from .bottom import BottomDeadbeat
from .deadbeat import DEFAULT_STIFFNESS_RANGE, Deadbeat, PlanStatus, default_angle
from .footholds_runs import FOOTHOLD, NO_FOOTHOLD, StonesRuns
from .planner import plan_targets
from .plant import ROBOT, Plant
from .raibert import raibert_controls
from .scenarios import Scenario, from_dict, load, resized
from .stones import MISSED, MISSED_NAME
from .swing import policy_tables

__all__ = [
    "Run",
    "RunBatch",
    "RunInterrupted",
    "V_REVERSE",
    "check",
    "check_memory",
    "make_plant",
    "memory_estimate",
    "run",
    "run_batch",
    "PLAN_MEANINGS",
    "PLAN_NAMES",
    "plant_status_name",
    "scenario_of",
]

#: Below this measured apex speed [m/s] a step that reverses the direction is planned from a hop in
#: place; above it the target becomes a hop in place first.
V_REVERSE = 0.05
#: Plan status codes in the records: the solver's, the swing policy's OUT_OF_RANGE, and those a
#: record adds: BLIND (a solve, so >= 0 as the solver's), FIXED, NOT_RUN and FEEDBACK (no solve).
BLIND, FIXED, NOT_RUN, FEEDBACK = 4, -1, -2, -3
PLAN_NAMES = {
    0: "REACHED",
    1: "UNREACHABLE",
    2: "MAP_FAILED",
    3: "OUT_OF_RANGE",
    BLIND: "BLIND",
    FIXED: "FIXED",
    NOT_RUN: "-",
    FEEDBACK: "FEEDBACK",
    FOOTHOLD: "FOOTHOLD",
    NO_FOOTHOLD: "NO_FOOTHOLD",
}
#: What each plan status promises (the table's legend): the controller's, on its model.
PLAN_MEANINGS = {
    "REACHED": "the model's next apex on the target, from the measured apex on the true ground",
    "BLIND": "the model's next apex on the target on the flat ground the controller assumed (the "
    "ground unknown, known = 0); the plant met the true ground, so its apex misses by that ground's effect",
    "UNREACHABLE": "the model's closest apex to the target within the bounds",
    "MAP_FAILED": "the model failed at every control tried (the previous angle, the nominal stiffness)",
    "OUT_OF_RANGE": "the ground outside the time-based policy's grounds (its end controls held)",
    "FIXED": "no controller: the fixed angle and the nominal stiffness",
    "FEEDBACK": "Raibert's feedback controller: no model, nothing planned",
    "FOOTHOLD": "the model's feet inside their stones' usable parts over the footholds' horizon",
    "NO_FOOTHOLD": "no stone sequence keeps the model's feet inside their stones: the closest one's controls",
}
#: The name of a plant status code in the records: the plant's (Status), or a run's own (MISSED).
_PLANT_NAMES = {int(s): s.name for s in Status} | {MISSED: MISSED_NAME}


def plant_status_name(code: int) -> str:
    """The name of a plant status code of a run's records (``Status``'s, or ``MISSED``)."""
    return _PLANT_NAMES[int(code)]


#: What a former name's warning says it was read on.
_WHERE = "a run"
#: The leg's angle recorded at this many evenly spaced times of each descent (``swing``).
SWING_SAMPLES = 9

_FIELDS = (
    "apex_height",
    "apex_speed",
    "measured_height",
    "measured_speed",
    "ground",
    "nominal_height",
    "nominal_speed",
    "target_height",
    "target_speed",
    "touchdown_angle",
    "swing_angle",
    "k_c",
    "k_d",
    "k_d_planned",
    "predicted_height",
    "predicted_speed",
    "residual",
    "next_apex_height",
    "next_apex_speed",
    "step_length",
    "solve_us",
    "bottom_us",
    "t_descent",
    "t_bottom",
    "t_stance",
    "t_ascent",
    "foot_x",
    "energy_low",
    "energy_high",
)
_STATES = ("touchdown", "bottom", "liftoff")
_CODES = ("plan_status", "bottom_status", "plant_status")


def scenario_of(scenario, overrides: dict) -> Scenario:
    """A :class:`Scenario` from a Scenario, a TOML path or a dict, with fields overridden: every
    override checked before any work (TypeError for a name that is no field, naming the fields;
    :class:`~.scenarios.ScenarioError`, a ValueError, for a value out of its field's domain)."""
    names = [f.name for f in fields(Scenario)]
    for key in overrides:
        if key not in names:
            close = difflib.get_close_matches(key, names, n=1)
            hint = f" (did you mean {close[0]}?)" if close else ""
            raise TypeError(f"unknown scenario field {key!r}{hint}; the fields: {', '.join(names)}")
    if scenario is None:
        sc = Scenario()
    elif isinstance(scenario, Scenario):
        sc = scenario
    elif isinstance(scenario, (str, Path)):
        sc = load(scenario)
    elif isinstance(scenario, dict):
        sc = from_dict(scenario)
    else:
        raise TypeError(f"scenario must be a Scenario, a TOML path or a dict, got {type(scenario).__name__}")
    overrides = dict(overrides)
    if "steps" in overrides:  # the per-step profiles cut, or their last value held
        sc = resized(sc, overrides.pop("steps"))
    return sc.with_(**overrides) if overrides else sc


class RunInterrupted(KeyboardInterrupt):
    """Ctrl-C during :func:`run_batch`: ``batch`` (a :class:`RunBatch`) holds the steps already run."""

    def __init__(self, batch: RunBatch):
        super().__init__("interrupted")
        self.batch = batch


#: Bytes a scenario holds per step besides the records (its target and ground profiles as tuples of
#: Python floats, about 32 bytes an entry, three of them).
_SCENARIO_BYTES_PER_STEP = 3 * 32


def memory_estimate(runs: int, steps: int) -> int:
    """The bytes a run of ``runs`` x ``steps`` allocates for its records (float64 values, the three
    stance states of 4 floats, int64 codes, the noise and the grounds) and its scenario's profiles."""
    per = 8 * len(_FIELDS) + 8 * 4 * len(_STATES) + 8 * SWING_SAMPLES + 8 * len(_CODES) + 8 * 2 + 8
    return int(runs) * int(steps) * per + int(steps) * _SCENARIO_BYTES_PER_STEP


def check_memory(runs: int, steps: int, available: int | None = None) -> int:
    """The estimate of :func:`memory_estimate`; ValueError (one line with the estimate) when it
    exceeds ``available`` bytes (default: the machine's available memory;
    :func:`slipmaps.runtime.api.memory.check`)."""
    return memory.check(
        memory_estimate(runs, steps), f"{runs} run(s) of {steps} steps need", "run fewer steps", available
    )


@dataclass
class RunBatch:
    """Many runs of one scenario (arrays runs x steps, NaN where a step did not run; module
    docstring). ``fell`` (runs,): a plant step failed; ``completed``: steps run; ``grounds``: the
    terrain of each run; ``swing`` (runs x steps x ``SWING_SAMPLES``): the leg's angle over each
    descent; ``plant``: the plant the runs ran on (the robot plant keeps its robots and their
    logged trajectories)."""

    scenario: Scenario
    grounds: np.ndarray
    values: dict[str, np.ndarray]
    states: dict[str, np.ndarray]
    codes: dict[str, np.ndarray]
    swing: np.ndarray | None = None
    plant: object = None

    @property
    def runs(self) -> int:
        return self.grounds.shape[0]

    @property
    def plant_ok(self) -> np.ndarray:
        return self.codes["plant_status"] == int(Status.OK)

    @property
    def fell(self) -> np.ndarray:
        ran = self.codes["plant_status"] >= 0
        return (ran & ~self.plant_ok).any(axis=1)

    @property
    def completed(self) -> np.ndarray:
        return self.plant_ok.sum(axis=1)

    def __getitem__(self, name: str) -> np.ndarray:
        return self._get(name, 2)

    def _get(self, name: str, stacklevel: int) -> np.ndarray:
        for table in (self.values, self.states, self.codes):
            if name in table:
                return table[name]
        if name in RUN_RENAMED:
            warn_renamed(name, RUN_RENAMED[name], _WHERE, stacklevel + 1)
            return self.values[RUN_RENAMED[name]]
        raise KeyError(
            f"a run records no {name!r}; it records {', '.join([*self.values, *self.states, *self.codes])}"
        )

    def errors(self) -> tuple[np.ndarray, np.ndarray]:
        """Next apex minus the planned target, height [m] and speed [m/s] (NaN where the step failed)."""
        h, v = self["next_apex_height"], self["next_apex_speed"]
        return h - self["target_height"], v - self["target_speed"]

    def run(self, i: int = 0) -> Run:
        return Run(self, i)


class Run:
    """One run of a :class:`RunBatch` (module docstring): ``steps`` (a dict per step), ``table()``,
    ``path()`` (the continuous body and foot path), ``as_dict()``."""

    def __init__(self, batch: RunBatch, index: int = 0):
        self.batch, self.index = batch, index

    @property
    def scenario(self) -> Scenario:
        return self.batch.scenario

    @property
    def fell(self) -> bool:
        return bool(self.batch.fell[self.index])

    def __len__(self) -> int:
        return int((self.batch.codes["plant_status"][self.index] >= 0).sum())

    def column(self, name: str) -> np.ndarray:
        return self.batch._get(name, 2)[self.index][: len(self)]

    @property
    def steps(self) -> list[dict]:
        out = []
        for n in range(len(self)):
            row = {k: float(v[self.index, n]) for k, v in self.batch.values.items()}
            row = RenamedKeys(row, RUN_RENAMED, _WHERE)
            row |= {k: v[self.index, n].tolist() for k, v in self.batch.states.items()}
            row["plan_status"] = PLAN_NAMES[int(self.batch.codes["plan_status"][self.index, n])]
            row["bottom_status"] = PLAN_NAMES[int(self.batch.codes["bottom_status"][self.index, n])]
            row["plant_status"] = plant_status_name(self.batch.codes["plant_status"][self.index, n])
            row["step"] = n
            out.append(row)
        return out

    def columns(self) -> dict[str, np.ndarray]:
        """A row per step run: ``step``, every value, the stance states split into a column per
        coordinate (``touchdown_q_r``, ...), the statuses by name (``slipmaps.runtime.api.frames``)."""
        n, i = len(self), self.index
        out = {"step": np.arange(n)}
        out |= {k: v[i, :n] for k, v in self.batch.values.items()}
        states = {k: v[i, :n] for k, v in self.batch.states.items()}
        out |= flat_columns(states, 1, {k: [f"{k}_{q}" for q in POLAR_NAMES] for k in states})
        for k in ("plan_status", "bottom_status"):
            out[k] = np.array([PLAN_NAMES[int(c)] for c in self.batch.codes[k][i, :n]], dtype=object)
        codes = self.batch.codes["plant_status"][i, :n]
        if (codes == MISSED).any():  # a run's own status (a stones course): named here
            names = np.array([plant_status_name(c) for c in codes], dtype=object)
            return out | {"plant_status": names, "plant_status_code": codes}
        return out | status_columns(codes, "plant_status")

    def to_pandas(self):
        """A pandas DataFrame of :meth:`columns`, a row per step."""
        return to_pandas(self.columns())

    @property
    def status(self) -> str:
        n = len(self)
        if not self.fell:
            return f"completed {n} steps"
        last = plant_status_name(self.batch.codes["plant_status"][self.index, n - 1])
        return f"fell at step {n - 1}: {last}"

    def errors(self) -> tuple[np.ndarray, np.ndarray]:
        dh, dv = self.batch.errors()
        return dh[self.index][: len(self)], dv[self.index][: len(self)]

    def table(self) -> str:
        """The run as a table, a row per step: the next apex's errors against the target in mm and
        mm/s (absolute, so a target speed of 0, a stop, has one too); under it the run's status and
        a legend line per plan status shown (``slipmaps.runtime.control.runs.PLAN_MEANINGS``)."""
        sc = self.scenario
        head = (
            f"{'step':>4} {'ground':>7} {'apex h':>8} {'apex v':>8} {'target h':>9} {'target v':>9} "
            f"{'angle':>8} {'k_c':>8} {'k_d':>8} {'plan':>11} {'next h':>8} {'next v':>8} {'err h mm':>9} "
            f"{'err v mm/s':>10} {'plant':>16} {'length':>7} {'us':>6}"
        )
        lines = [head, "-" * len(head)]
        for r in self.steps:
            err_h = 1000.0 * (r["next_apex_height"] - r["target_height"])
            err_v = 1000.0 * (r["next_apex_speed"] - r["target_speed"])  # absolute: a target of 0 is common
            plan = r["plan_status"] + ("*" if r["bottom_status"] not in ("-",) else "")
            lines.append(
                f"{r['step']:4d} {_zero(r['ground']):7.3f} {r['apex_height']:8.4f} {r['apex_speed']:8.4f} "
                f"{r['target_height']:9.4f} {r['target_speed']:9.4f} {r['touchdown_angle']:8.4f} "
                f"{r['k_c']:8.0f} {r['k_d']:8.0f} {plan:>11} {r['next_apex_height']:8.4f} "
                f"{r['next_apex_speed']:8.4f} "
                f"{err_h:9.3f} {err_v:10.3f} {r['plant_status']:>16} {r['step_length']:7.3f} "
                f"{r['solve_us'] + (r['bottom_us'] if math.isfinite(r['bottom_us']) else 0.0):6.0f}"
            )
        lines.append("")
        lines.append(
            f"{sc.name}: model {sc.model}, plant {sc.plant}; {self.status}"
            + ("; * k_d chosen again at the bottom" if sc.two_stage else "")
        )
        shown = {r["plan_status"] for r in self.steps}
        lines += [f"plan {name}: {text}" for name, text in PLAN_MEANINGS.items() if name in shown]
        return "\n".join(lines)

    def as_dict(self) -> dict:
        def clean(x):
            if isinstance(x, float):
                return x if math.isfinite(x) else None
            if isinstance(x, list):
                return [clean(y) for y in x]
            return x

        return {
            "scenario": self.scenario.as_dict(),
            "status": self.status,
            "fell": self.fell,
            "steps": [{k: clean(v) for k, v in r.items()} for r in self.steps],
        }

    def path(self, samples: int = 40):
        """The continuous body and foot path (:func:`~slipmaps.runtime.control.motion.path`)."""
        from .motion import path

        return path(self, samples)


def _zero(x: float) -> float:
    """x, with the round-off of a sum of ground changes back to 0 (never printed as -0.000)."""
    return 0.0 if abs(x) < 5e-13 else x


def _noise(sc: Scenario, runs: int, seeds) -> np.ndarray:
    out = np.zeros((runs, sc.steps, 2))
    if sc.noise_height == 0.0 and sc.noise_speed == 0.0:
        return out
    for r in range(runs):
        z = np.random.default_rng([sc.seed, int(seeds[r])]).normal(size=(sc.steps, 2))
        out[r] = z * np.array([sc.noise_height, sc.noise_speed])
    return out


class _Controller:
    """The scenario's controller: the apex stage on the model, the bottom stage (two-stage), the
    planner's settings; the plant (a map with the mismatch, or the robot)."""

    def __init__(self, sc: Scenario):
        p = sc.params
        self.sc = sc
        self.params = p
        self.fixed = sc.fixed_angle is not None
        self.raibert = sc.policy == "raibert"
        self.deadbeat = None
        if not (self.fixed or self.raibert or sc.policy == "footholds"):
            self.deadbeat = Deadbeat(
                sc.model,
                p,
                controls=sc.controls,  # None: the map's default (deadbeat.default_controls)
                bounds=sc.bounds,
                tol=sc.tol,
                jacobian=sc.jacobian,
                **sc.model_options,
            )
        kd = "k_d" if self.deadbeat is None or "k_d" in self.deadbeat.wrt else "k"
        lo_k, hi_k = (f * p.k_c for f in DEFAULT_STIFFNESS_RANGE)
        self.k_d_bounds = tuple(sc.bounds.get(kd, (lo_k, hi_k)))
        self.energy = self.deadbeat is not None and any(c in self.deadbeat.controls for c in ("k_d", "k_c"))
        self.bottom = (
            BottomDeadbeat(sc.decompression, p, bounds=self.k_d_bounds, aim=sc.aim) if sc.two_stage else None
        )
        self.plant = make_plant(sc)
        # stepping stones: the footholds planner, each run's x and its landings (footholds_runs.py)
        self.footholds = StonesRuns(sc, self.plant) if sc.policy == "footholds" else None
        self.stiff = 1.0 + sc.mismatch_stiffness
        if sc.two_stage and not self.plant.has_halves:
            self.plant._half("touchdown")  # the error naming the plants that have halves
        # the swing leg: a retraction rate after the apex, or a time-based policy on the model
        self.rate = sc.retraction_rate if sc.policy == "retraction" or self.fixed else 0.0
        self.policy = None
        if sc.policy == "time-based":
            self.policy = Deadbeat(
                sc.model,
                p,
                controls=sc.controls,
                bounds=sc.bounds,
                tol=sc.tol,
                jacobian=sc.jacobian,
                budget=False,
                **sc.model_options,
            )
            low, high = sc.policy_grounds
            self.grid = np.linspace(high, low, sc.knots)  # the highest ground first (swing.py)
            self.model_plant = Plant(sc.model, p, **sc.model_options)


def make_plant(scenario):
    """The plant of a scenario (:class:`~.scenarios.Scenario`): its map, with the model mismatch
    (the mass (1 + ``mismatch_mass``) times the controller's), or the MuJoCo robot (:data:`ROBOT`)."""
    if scenario.plant == ROBOT:
        from .robot_plant import RobotPlant  # MuJoCo, only for a robot scenario

        return RobotPlant(scenario)
    p = scenario.params
    return Plant(scenario.plant, p.with_(m=p.m * (1.0 + scenario.mismatch_mass)), **scenario.plant_options)


def check(sc: Scenario) -> None:
    """ValueError (one line) for a scenario whose maps, options or settings cannot run, before any
    work: the model and its options, the plant and its options, the bottom stage's half map."""
    from ..api.calls import Call

    p = sc.params
    Call.of(
        sc.model, p.with_(k=p.k_c) if "constant_stiffness" in get(sc.model).requires else p, sc.model_options
    )
    if sc.plant != ROBOT:
        Call.of(sc.plant, p.with_(k=p.k_c), sc.plant_options)
    if sc.two_stage:
        Call.of(sc.decompression, p, {}, half=True)


def _warm(ctl: _Controller, scalar: bool) -> None:
    if ctl.policy is not None:
        ctl.policy.warm(batch=True)
    if ctl.deadbeat is not None:
        ctl.deadbeat.warm(batch=not scalar)
    if ctl.bottom is not None:
        ctl.bottom.warm(batch=not scalar)
    if ctl.footholds is not None:
        ctl.footholds.warm()


def run_batch(
    scenario=None, grounds=None, *, seeds=None, scalar: bool | None = None, progress=None, **overrides
) -> RunBatch:
    """Many runs of a scenario in lockstep (module docstring): ``grounds`` (runs, steps) the absolute
    touchdown grounds of each run (default: the scenario's, one run), ``seeds`` the noise seed of each
    run (default 0, 1, ...). ``scalar`` (default: one run) plans with the scalar solve, timed per step.
    """
    sc = scenario_of(scenario, overrides)
    G = np.atleast_2d(real_array("grounds", sc.ground if grounds is None else grounds))
    if G.ndim != 2 or G.shape[1] != sc.steps:
        raise ValueError(f"grounds must have {sc.steps} columns (one per step), got shape {G.shape}")
    if not np.isfinite(G).all():
        raise ValueError(f"grounds must be finite, got {num(G[~np.isfinite(G)][0])}")
    R, S = G.shape
    check_memory(R, S)
    seeds = np.arange(R) if seeds is None else np.atleast_1d(real_array("seeds", seeds))
    if seeds.shape != (R,) or not np.all((seeds >= 0) & (seeds == np.round(seeds))):
        raise ValueError(f"seeds must be {R} whole numbers >= 0 (one per run), got {seeds.tolist()!r}")
    for name, flag in (("scalar", scalar), ("progress", progress)):
        if flag is not None and not isinstance(flag, bool):
            raise TypeError(f"{name} must be True, False or None, got {flag!r}")
    scalar = (R == 1) if scalar is None else scalar
    ctl = _Controller(sc)
    _warm(ctl, scalar)
    ctl.plant.start(sc, G, seeds)
    extras = tuple(ctl.plant.columns)
    if ctl.footholds is not None:
        ctl.footholds.start(R)
        extras += ctl.footholds.columns
    batch = RunBatch(
        sc,
        G,
        values=RenamedKeys({k: np.full((R, S), math.nan) for k in (*_FIELDS, *extras)}, RUN_RENAMED, _WHERE),
        states={k: np.full((R, S, 4), math.nan) for k in _STATES},
        codes={k: np.full((R, S), NOT_RUN, dtype=np.int64) for k in _CODES},
        swing=np.full((R, S, SWING_SAMPLES), math.nan),
        plant=ctl.plant,
    )
    live = _Live(
        h=np.full(R, sc.start_height),
        v=np.full(R, sc.start_speed),
        ground_prev=np.zeros(R),
        angle_prev=np.full(R, math.nan),
        authority=np.full(R, math.nan),
        noise=_noise(sc, R, seeds),
        integral=np.zeros(R),
    )
    alive = np.ones(R, dtype=bool)
    values, codes = batch.values, batch.codes
    try:
        with Bar(S, f"{sc.name} ({R} runs)", progress) as bar:
            for n in range(S):
                if not alive.any():
                    break
                idx = np.flatnonzero(alive)
                _step(ctl, n, idx, live, batch, scalar)
                ok = codes["plant_status"][idx, n] == int(Status.OK)
                alive[idx[~ok]] = False
                live.h[idx] = values["next_apex_height"][idx, n]
                live.v[idx] = values["next_apex_speed"][idx, n]
                live.ground_prev[idx] = values["ground"][idx, n]
                bar.update(1)
    except KeyboardInterrupt:
        raise RunInterrupted(batch) from None
    return batch


@dataclass
class _Live:
    """The runs between steps (arrays of runs): the true apex, the ground under it, the previous
    step's angle and the energy authority (the solve's warm start), the measurement noise (runs x
    steps x 2), Raibert's height integral."""

    h: np.ndarray
    v: np.ndarray
    ground_prev: np.ndarray
    angle_prev: np.ndarray
    authority: np.ndarray
    noise: np.ndarray
    integral: np.ndarray


def _correction(sc: Scenario, n: int, idx: np.ndarray, values: dict) -> tuple[np.ndarray, np.ndarray]:
    """The step-to-step correction of the rows ``idx`` at step ``n`` (``sc.correction`` > 0): the
    mean prediction residual (next apex minus the model's prediction, height and speed) of the last
    ``sc.correction`` steps whose touchdown ground differed from the ground under their apex by at
    most ``sc.correction_gate`` (a terrain change is not a model error); zero without such steps."""
    m = idx.size
    if sc.correction == 0 or n == 0:
        return np.zeros(m), np.zeros(m)
    lo = max(0, n - sc.correction)
    past = slice(lo, n)
    ground = values["ground"][idx, :n]
    before = np.concatenate([np.zeros((m, 1)), ground[:, :-1]], axis=1)
    level = np.abs(ground - before)[:, past] <= sc.correction_gate
    out = []
    for key in ("height", "speed"):
        r = values[f"next_apex_{key}"][idx, past] - values[f"predicted_{key}"][idx, past]
        use = level & np.isfinite(r)
        count = use.sum(axis=1)
        total = np.where(use, r, 0.0).sum(axis=1)
        out.append(np.where(count > 0, total / np.maximum(count, 1), 0.0))
    return out[0], out[1]


def _step(ctl: _Controller, n: int, idx: np.ndarray, live: _Live, batch: RunBatch, scalar: bool) -> None:
    """Step ``n`` of the runs ``idx`` (module docstring), written into ``batch``'s records."""
    sc = ctl.sc
    h, v, ground_prev, noise = live.h, live.v, live.ground_prev, live.noise
    angle_prev, authority = live.angle_prev, live.authority
    G, values, states, codes, swing = batch.grounds, batch.values, batch.states, batch.codes, batch.swing
    Ht_all, Vt_all = np.asarray(sc.target_height), np.asarray(sc.target_speed)
    p = sc.params
    S = sc.steps
    m = idx.size
    hm = np.maximum(h[idx] + noise[idx, n, 0], 0.0)
    vm = v[idx] + noise[idx, n, 1]
    gr_true = G[idx, n] - ground_prev[idx]
    gr_model = gr_true if sc.known >= 1 else np.zeros(m)
    Hn = np.full(m, Ht_all[n])
    Vn = np.full(m, Vt_all[n])
    # a step keeps the direction of its apex speed: stop first, then turn from a hop in place
    opposite = Vn * vm < 0.0
    near = np.abs(vm) <= V_REVERSE
    V_step = np.where(opposite & ~near, 0.0, Vn)
    v_plan = np.where(opposite & near, 0.0, vm)
    # the model's loss: the apex speed it plans from is what is left after the step's loss
    v_model = v_plan * (1.0 - sc.model_loss) if sc.model_loss else v_plan
    H_step = Hn.copy()
    values["apex_height"][idx, n] = h[idx]
    values["apex_speed"][idx, n] = v[idx]
    values["measured_height"][idx, n] = hm
    values["measured_speed"][idx, n] = vm
    values["nominal_height"][idx, n] = Hn
    values["nominal_speed"][idx, n] = Vn
    t0 = time.perf_counter()
    tables = None
    nan = np.full(m, math.nan)
    if ctl.fixed or ctl.raibert:
        kc = np.full(m, p.k_c)
        if ctl.fixed:
            th, kd, plan = np.full(m, sc.fixed_angle), np.full(m, p.k_d), np.full(m, FIXED)
        else:
            t_last = values["t_stance"][idx, n - 1] if n else nan
            th, kd = raibert_controls(
                sc.raibert, p, hm, vm, H_step, V_step, t_last, live.integral[idx], ctl.k_d_bounds
            )
            live.integral[idx] += (H_step - hm) / p.l0
            plan = np.full(m, FEEDBACK)
        pred_h = pred_v = resid = elo = ehi = nan
        solve = np.zeros(m) if ctl.fixed else np.full(m, (time.perf_counter() - t0) * 1e6 / m)
    elif ctl.footholds is not None:
        # the footholds policy: the first hop of each run's plan; its next apex is the step's target
        planned = ctl.footholds.plan(n, idx, hm, v_model, ground_prev[idx])
        th, kc, kd, plan = planned["touchdown_angle"], planned["k_c"], planned["k_d"], planned["status"]
        H_step, V_step = planned["next_apex_height"], planned["next_apex_speed"]
        pred_h, pred_v, resid, elo, ehi = H_step, V_step, nan, nan, nan
        solve, gr_model = planned["solve_us"], planned["ground"]
        gr_true = ctl.footholds.ground(idx, h[idx], v[idx], th, ground_prev[idx], gr_model)
        ctl.footholds.record(idx, n, planned, values)
    else:
        start = np.where(np.isfinite(angle_prev[idx]), angle_prev[idx], default_angle(p, v_model))
        if sc.known >= 1:
            if ctl.energy and not np.isfinite(authority[idx]).all():
                pre = _plan(ctl.deadbeat, hm, v_model, H_step, V_step, gr_model, start, scalar)
                authority[idx] = np.where(np.isfinite(authority[idx]), authority[idx], pre["authority"])
            cols = [min(n + k, S - 1) for k in range(sc.known)]
            future = G[idx][:, cols] - ground_prev[idx][:, None]
            Hf = np.tile(Ht_all[cols], (m, 1))
            Vf = np.tile(Vt_all[cols], (m, 1))
            Vf[:, 0] = V_step

            def planned(rows, auth):
                kw = {"mass": p.m, "g": p.g_f, "l0": p.l0, "min_height": sc.floor}
                args = (
                    hm[rows],
                    v_model[rows],
                    future[rows],
                    Hf[rows],
                    Vf[rows],
                    auth,
                    p.k_c,
                    ctl.k_d_bounds,
                )
                return plan_targets(*args, **kw)

            every = np.arange(m)
            H_step, V_step = planned(every, authority[idx] if ctl.energy else np.full(m, math.nan))
        dh, dv = _correction(sc, n, idx, values)
        H_aim, V_aim = H_step - dh, V_step - dv
        if ctl.policy is not None:
            tables, solve = _time_based_tables(ctl, hm, v_model, H_aim, V_aim, gr_model)
            th, kc, kd = default_angle(p, v_model), np.full(m, p.k_c), np.full(m, p.k_d)  # no table value
            resid = elo = ehi = nan
        else:
            res = _plan(ctl.deadbeat, hm, v_model, H_aim, V_aim, gr_model, start, scalar, ctl.rate)
    if ctl.deadbeat is not None and ctl.policy is None:
        if sc.known >= 1 and ctl.energy:
            # the authority changes with the angle: where the plan fell short, plan once more with
            # the authority of this solve
            again = np.flatnonzero((res["status"] == compiled.UNREACHABLE) & np.isfinite(res["authority"]))
            if again.size:
                H2, V2 = planned(again, res["authority"][again])
                args = (hm[again], v_model[again], H2 - dh[again], V2 - dv[again], gr_model[again])
                res2 = _plan(ctl.deadbeat, *args, res["touchdown_angle"][again], scalar, ctl.rate)
                H_step[again], V_step[again] = H2, V2
                for k in res:
                    res[k][again] = res[k][again] + res2[k] if k == "solve_us" else res2[k]
        # what the solve promises: REACHED on the ground it planned on; BLIND where that was the flat
        # ground assumed (the ground unknown) and the true one differs
        plan = np.where((res["status"] == compiled.REACHED) & (gr_model != gr_true), BLIND, res["status"])
        failed = plan == compiled.MAP_FAILED
        th = np.where(failed, start, res["touchdown_angle"])
        kc = np.where(failed, p.k_c, res["k_c"])
        kd = np.where(failed, p.k_d, res["k_d"])
        # the model's own prediction at the controls it chose (for the corrected aim, when corrected)
        pred_h, pred_v, resid = res["next_apex_height"], res["next_apex_speed"], res["residual"]
        elo, ehi = res["energy_low"], res["energy_high"]
        authority[idx] = np.where(np.isfinite(res["authority"]), res["authority"], authority[idx])
        solve = res["solve_us"]
        if not scalar:
            solve = np.full(m, (time.perf_counter() - t0) * 1e6 / m)
    values["target_height"][idx, n] = H_step
    values["target_speed"][idx, n] = V_step
    values["solve_us"][idx, n] = solve
    f = ctl.stiff
    leg = {"swing": tables, "scale": f, "rows": idx}
    if ctl.bottom is not None:
        first = ctl.plant.compress(h[idx], v[idx], th, gr_true, kc * f, ctl.rate, **leg)
        if tables is not None:
            kd = _read_tables(tables, h[idx], first.ground, p)["k_d"]
        ok = first.ok
        t1 = time.perf_counter()
        kd_b = kd.copy()
        bstat = np.full(m, NOT_RUN)
        if ok.any():
            rows = np.flatnonzero(ok)
            if scalar:
                for i in rows:
                    b = ctl.bottom.plan(first.bottom[i], H_step[i], V_step[i], k_d=kd[i])
                    bstat[i] = (
                        compiled.MAP_FAILED
                        if b.status == PlanStatus.MAP_FAILED
                        else (0 if b.status == PlanStatus.REACHED else 1)
                    )
                    if b.status != PlanStatus.MAP_FAILED:
                        kd_b[i] = b.k_d
            else:
                out = ctl.bottom.plan_batch(first.bottom[rows], H_step[rows], V_step[rows], k_d=kd[rows])
                bstat[rows] = out["status"]
                good = out["status"] != compiled.MAP_FAILED
                kd_b[rows[good]] = out["k_d"][good]
        values["bottom_us"][idx, n] = (time.perf_counter() - t1) * 1e6 / max(int(ok.sum()), 1)
        codes["bottom_status"][idx, n] = bstat
        steps = ctl.plant.decompress(first, kd_b * f, rows=idx)
    else:
        steps = ctl.plant.step(h[idx], v[idx], th, gr_true, kc * f, kd * f, ctl.rate, **leg)
        kd_b = None
    if ctl.footholds is not None:  # a foot outside every stone is a miss; the ground the foot met
        steps = ctl.footholds.land(idx, steps, values, n)
        values["ground"][idx, n] = ground_prev[idx] + steps.ground
    met = steps.ground
    if ctl.footholds is None:
        values["ground"][idx, n] = np.where(met == gr_true, G[idx, n], ground_prev[idx] + met)
    if tables is not None:
        # the time-based policy: the controls its tables gave where the leg met the ground, the
        # plan's status there, and the model's prediction at those controls from the measured apex
        td = _read_tables(tables, h[idx], met, p)
        th = np.where(np.isfinite(td["touchdown_angle"]), td["touchdown_angle"], th)
        kc, kd = td["k_c"], td["k_d"]
        plan = np.where(tables.counts > 0, td["status"], compiled.MAP_FAILED)
        model = ctl.model_plant.step(hm, v_model, th, np.where(np.isfinite(met), met, gr_true), kc, kd)
        pred_h, pred_v = model.next_apex_height, model.next_apex_speed
    values["swing_angle"][idx, n] = th if tables is None else _swing_at(tables, np.zeros(m))
    values["k_c"][idx, n] = kc
    values["k_d_planned"][idx, n] = kd
    values["predicted_height"][idx, n] = pred_h
    values["predicted_speed"][idx, n] = pred_v
    values["residual"][idx, n] = resid
    values["energy_low"][idx, n] = elo
    values["energy_high"][idx, n] = ehi
    codes["plan_status"][idx, n] = plan
    values["k_d"][idx, n] = kd if kd_b is None else kd_b
    codes["plant_status"][idx, n] = steps.status
    for name, attr in (
        ("next_apex_height", "next_apex_height"),
        ("next_apex_speed", "next_apex_speed"),
        ("step_length", "step_length"),
        ("t_descent", "t_descent"),
        ("t_bottom", "t_bottom"),
        ("t_stance", "t_stance"),
        ("t_ascent", "t_ascent"),
        ("foot_x", "foot_x"),
    ):
        values[name][idx, n] = getattr(steps, attr)
    for name, column in steps.extras.items():
        values[name][idx, n] = column
    for name in _STATES:
        states[name][idx, n] = getattr(steps, name)
    # the leg's angle: at the touchdown (the plant's), and over the descent
    td_angle = steps.touchdown[:, 2]
    values["touchdown_angle"][idx, n] = np.where(np.isfinite(td_angle), td_angle, th)
    frac = np.linspace(0.0, 1.0, SWING_SAMPLES)
    times = steps.t_descent[:, None] * frac[None, :]
    if tables is None:
        swing[idx, n] = th[:, None] + ctl.rate * times
    else:
        for k in range(SWING_SAMPLES):
            swing[idx, n, k] = _swing_at(tables, np.where(np.isfinite(times[:, k]), times[:, k], 0.0))
        swing[idx[~np.isfinite(steps.t_descent)], n] = math.nan
    angle_prev[idx] = values["swing_angle"][idx, n]


def _swing_at(tables, t) -> np.ndarray:
    """The time-based policies' leg angles at times ``t`` (one per row)."""
    return tables.controls_at(t)["touchdown_angle"]


def _read_tables(tables, h_true, ground, p) -> dict:
    """The time-based policies' controls where the leg from the true apex meets ``ground`` (the
    nominal stiffness where a table has none), and the plan status there."""
    td = tables.touchdown(h_true, np.where(np.isfinite(ground), ground, 0.0))
    td["k_c"] = np.where(np.isfinite(td["k_c"]), td["k_c"], p.k_c)
    td["k_d"] = np.where(np.isfinite(td["k_d"]), td["k_d"], p.k_d)
    return td


def _time_based_tables(ctl: _Controller, hm, vm, H, V, gr_model):
    """A time-based step's policies, one per row: at the measured apex over the grounds around the
    expected one (:mod:`.swing`), and the time they took per row [us]."""
    sc = ctl.sc
    t0 = time.perf_counter()
    targeted = ctl.policy._targeted(None if sc.aim == "speed" else H, None if sc.aim == "height" else V)
    tables = policy_tables(
        ctl.policy,
        hm,
        vm,
        H if targeted[0] else None,
        V if targeted[1] else None,
        gr_model[:, None] + ctl.grid[None, :],
    )
    return tables, np.full(hm.size, (time.perf_counter() - t0) * 1e6 / hm.size)


def _plan(ctl: Deadbeat, hm, vm, H, V, gr, start, scalar, rate=0.0) -> dict[str, np.ndarray]:
    """The deadbeat solves of the rows: the scalar solve (timed) or one parallel batch; the leg
    retracting at ``rate`` after the apex."""
    if not scalar:
        b = ctl.plan_batch(hm, vm, H, V, ground=gr, touchdown_angle=start, retraction_rate=rate)
        cols = {
            k: np.array(b[k])
            for k in ("status", "touchdown_angle", "k_c", "k_d", "next_apex_height", "next_apex_speed")
        }
        cols |= {k: np.array(b[k]) for k in ("residual", "energy_low", "energy_high", "authority")}
        cols["solve_us"] = np.full(hm.size, math.nan)
        return cols
    keys = (
        "touchdown_angle",
        "k_c",
        "k_d",
        "next_apex_height",
        "next_apex_speed",
        "residual",
        "authority",
        "solve_us",
    )
    out = {k: np.empty(hm.size) for k in (*keys, "energy_low", "energy_high")}
    out["status"] = np.empty(hm.size, dtype=np.int64)
    for i in range(hm.size):
        t = time.perf_counter()
        r = ctl.plan(
            float(hm[i]),
            float(vm[i]),
            float(H[i]),
            float(V[i]),
            ground=float(gr[i]),
            retraction_rate=rate,
            touchdown_angle=float(start[i]),
        )
        dt = (time.perf_counter() - t) * 1e6
        out["status"][i] = int(r._out[0])
        for k in keys[:-1]:
            out[k][i] = getattr(r, k)
        out["solve_us"][i] = dt
        out["energy_low"][i], out["energy_high"][i] = r.energy_range
    return out


def run(scenario=None, /, **overrides) -> Run:
    """One run of a scenario (a :class:`~.scenarios.Scenario`, a TOML path or a dict; keywords
    override its fields, e.g. ``model="geyer"``, ``steps=5``): module docstring."""
    return run_batch(scenario, **overrides).run(0)
