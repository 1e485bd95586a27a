"""Scenarios of a run: what to run (steps, targets, terrain, model, plant, mismatch, noise), from a
TOML file or in Python, validated with one-line errors naming the key.

A :class:`Scenario` holds everything per step: the nominal target of each step's next apex
(``target_height`` above that step's touchdown ground, signed ``target_speed``) and the ground of
each touchdown (``ground``: absolute heights, the ground under the start apex at 0). In TOML
(``examples/*.toml``, ``slipmaps run FILE``), SI units::

    name = "speed up"
    steps = 14
    model = "iterative"          # the controller's model (any map of `slipmaps maps`)
    plant = "exact"              # the plant (any map; two-stage steps need its half maps)
    start = { height = 1.0, speed = 3.0 }
    [targets]                    # a number, a list per step (the last value held), or a ramp
    height = 1.0
    speed = { from = 3.0, to = 7.0, steps = 10 }    # from step 0 (start = k: from step k), then held
    [terrain]                    # kind: flat, steps (heights = [...]), stairs, random, stones
    kind = "stairs"
    rise = 0.1                   # m per stair; `before` flat steps, `up` stairs, `flat` on top, `down`
    up = 4
    known = 3                    # touchdown grounds known ahead (0: unknown, the controller assumes flat)
    [control]                    # controls, bounds, two_stage, decompression, aim, min_height, fixed_angle
    controls = ["touchdown_angle", "k_d"]   # default; the angle alone for a constant-stiffness model
    bounds = { k_d = [10000.0, 40000.0] }
    policy = "apex"              # the swing leg: apex, retraction (retraction_rate), time-based, ...
    [params]                     # SlipParams fields (the controller's); default the human runner
    [mismatch]                   # the plant's mass and stiffness off by a fraction: mass = 0.05
    [noise]                      # apex measurement noise (standard deviations) and its seed
    height = 0.001
    speed = 0.01
    seed = 1
    [model_options]              # the model map's options;  [plant_options]: the plant's

``kind = "random"`` draws each step's ground change uniformly in +-``amplitude`` [m] (seeded by the
terrain's ``seed``); ``stairs`` rises by ``rise`` per stair (``before``, ``up``, ``flat``, ``down``
steps); ``stones`` is a course of stepping stones (:mod:`.stones`: ``stones = [[x_a, x_b, height],
...]`` listed, or drawn from ``count``, ``width``, ``gap``, ``rise``, ``seed``; a ``margin``; the
controller sees ``lookahead`` stones ahead), hopped by ``policy = "footholds"`` only
(:mod:`.footholds_runs`; ``horizon`` the hops it plans ahead).

The swing leg (``[control] policy``): ``"apex"`` (the deadbeat at the apex sets the touchdown angle,
held until the foot meets the ground), ``"retraction"`` (the same solve with the leg retracting at
``retraction_rate`` [rad/s] from the apex on: the ground met sets the angle it touches down with;
Seyfarth, Geyer and Herr 2003), ``"time-based"`` (at the apex, a swing policy over the grounds
``grounds`` = [low, high] [m] around the ground the controller expects, ``knots`` of them: the
controls as functions of the time since the apex, read at the touchdown: :mod:`.swing`; Wu and Geyer
2013). ``two_stage`` composes with each.

:func:`load` reads a file, :func:`from_dict` a table of the same keys; unknown keys are refused
naming the accepted ones. Every key with its type, default, unit and meaning: the site's scenario
reference (docs/scenarios.md, from :mod:`.scenario_keys`).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field, fields, replace
from dataclasses import fields as dataclass_fields
from pathlib import Path

import numpy as np

from ..api.files import read_toml
from ..api.index import get, get_half
from ..api.numeric import is_real, num
from ..api.params import FIELDS, HUMAN_RUNNER, ParamError, ParamTypeError, SlipParams
from ..api.validate import limit, limit_text
from .deadbeat import CONTROLS, control_bounds
from .plant import ROBOT
from .policies import POLICIES as _POLICIES
from .raibert import RaibertGains
from .scenario_keys import KEY_DOCS
from .stones import LOOKAHEAD, Course, CourseError, random_course

__all__ = ["Scenario", "ScenarioError", "from_dict", "load", "load_scenario", "read_toml", "resized", "KEYS"]

#: The accepted keys: top level and per table.
KEYS = {
    "": (
        "name",
        "description",
        "steps",
        "model",
        "plant",
        "start",
        "targets",
        "terrain",
        "control",
        "params",
        "mismatch",
        "noise",
        "model_options",
        "plant_options",
    ),
    "start": ("height", "speed"),
    "targets": ("height", "speed"),
    "terrain": (
        "kind",
        "heights",
        "rise",
        "before",
        "up",
        "flat",
        "down",
        "amplitude",
        "seed",
        "known",
        "stones",
        "count",
        "width",
        "gap",
        "margin",
        "lookahead",
    ),
    "control": (
        "controls",
        "bounds",
        "two_stage",
        "decompression",
        "aim",
        "min_height",
        "fixed_angle",
        "jacobian",
        "tol",
        "policy",
        "retraction_rate",
        "grounds",
        "knots",
        "raibert",
        "correction",
        "correction_gate",
        "model_loss",
        "horizon",
    ),
    "mismatch": ("mass", "stiffness"),
    "noise": ("height", "speed", "seed"),
    "params": (*FIELDS, "k"),
}
TERRAINS = ("flat", "steps", "stairs", "random", "stones")
#: The policies, by name (:mod:`.policies`; module docstring).
POLICIES = tuple(_POLICIES)


@dataclass(frozen=True)
class Scenario:
    """A run's definition (module docstring); build it with
    :func:`~slipmaps.runtime.control.scenarios.from_dict`,
    :func:`~slipmaps.runtime.control.scenarios.load` or directly (arrays per step as tuples of
    floats)."""

    name: str = "run"
    description: str = ""
    steps: int = 10
    start_height: float = 1.0
    start_speed: float = 5.0
    target_height: tuple[float, ...] = ()
    target_speed: tuple[float, ...] = ()
    ground: tuple[float, ...] = ()  # the ground of each touchdown (absolute; the start apex over 0)
    known: int = 3  # touchdown grounds known ahead; 0: unknown (the controller assumes flat ground)
    model: str = "iterative"
    model_options: dict = field(default_factory=dict)
    plant: str = "exact"
    plant_options: dict = field(default_factory=dict)
    params: SlipParams = HUMAN_RUNNER
    controls: tuple[str, ...] | None = (
        None  # None: the angle and k_d, the angle alone for a constant-stiffness model
    )
    bounds: dict = field(default_factory=dict)
    two_stage: bool = False
    decompression: str = "iterative-decompression"
    aim: str = "both"
    min_height: float | None = None  # the planner's floor above the next ground (default l0)
    fixed_angle: float | None = None  # no controller: this angle and the nominal stiffness every step
    jacobian: str = "broyden"
    tol: float = 1e-9
    policy: str = "apex"  # the swing leg: apex, retraction or time-based (module docstring)
    retraction_rate: float = 0.0  # rad/s after the apex (policy retraction, or with fixed_angle)
    grounds: tuple[float, float] | None = None  # time-based: the grounds [m] of the policy (default +-0.3 l0)
    knots: int = 64  # time-based: the grounds of the policy's table
    raibert: RaibertGains = RaibertGains()  # policy raibert: its gains
    correction: int = 0  # the last hops whose prediction residuals shift the target (0: none)
    correction_gate: float = 0.01  # m: a hop whose ground changed by more is not averaged
    model_loss: float = 0.0  # the model's loss: the fraction of the apex speed lost per step
    stones: Course | None = None  # kind stones: the course (stones.py); policy footholds on it
    lookahead: int = LOOKAHEAD  # kind stones: the stones the controller sees ahead
    horizon: int = 2  # policy footholds: the hops planned ahead (0: the deadbeat aimed at a stone's centre)
    mismatch_mass: float = 0.0  # the plant's mass is (1 + this) times the controller's
    mismatch_stiffness: float = 0.0  # the plant's springs are (1 + this) times what is commanded
    noise_height: float = 0.0  # standard deviation of the apex height measurement [m]
    noise_speed: float = 0.0  # ... of the apex speed [m/s]
    seed: int = 0

    def __post_init__(self):
        _validate(self)

    @property
    def policy_grounds(self) -> tuple[float, float]:
        """The time-based policy's ground range [m], relative to the ground the controller expects."""
        if self.grounds is None:
            return (-0.3 * self.params.l0, 0.3 * self.params.l0)
        return self.grounds

    @property
    def floor(self) -> float:
        return self.params.l0 if self.min_height is None else self.min_height

    def with_(self, **changes) -> Scenario:
        """A copy with fields changed (validated again)."""
        return replace(self, **changes)

    def as_dict(self) -> dict:
        out = {}
        for f in fields(self):
            value = getattr(self, f.name)
            out[f.name] = value.as_dict() if isinstance(value, SlipParams) else value
        out["raibert"] = asdict(self.raibert)
        out["target_height"] = list(self.target_height)
        out["target_speed"] = list(self.target_speed)
        out["ground"] = list(self.ground)
        out["controls"] = None if self.controls is None else list(self.controls)
        out["grounds"] = None if self.grounds is None else list(self.grounds)
        out["stones"] = None if self.stones is None else self.stones.as_dict()
        return out


class ScenarioError(ValueError):
    """A scenario field out of its domain, one line: ``scenario 'run': steps must be a whole number
    >= 1, got 2.5``. ``field`` is the :class:`Scenario` field, ``problem`` the words after it; the
    TOML loader names the file and the key instead (``s.toml: [control] aim: must be ...``)."""

    def __init__(self, scenario: str, field: str, problem: str, form: str = "after") -> None:
        self.field, self.problem, self.form = field, problem, form
        text = {"after": f"{field} {problem}", "colon": f"{field}: {problem}", "named": problem}[form]
        super().__init__(f"scenario {scenario!r}: {text}")


class _Refused(Exception):
    """A field's problem: the words after its name (``form`` "after"), a message of its own after
    the name and a colon ("colon"), or one that names the field itself ("named")."""

    def __init__(self, problem: str, form: str = "after") -> None:
        super().__init__(problem)
        self.problem, self.form = problem, form


def _text(x, sc=None):
    if not isinstance(x, str):
        raise _Refused(f"must be a string, got {x!r}")
    return x


def _whole(minimum: int):
    def check(x, sc=None):
        whole = isinstance(x, (int, np.integer)) and not isinstance(x, bool)
        if not whole or x < minimum:
            raise _Refused(f"must be a whole number >= {minimum}, got {repr(int(x)) if whole else num(x)}")
        return int(x)

    return check


def _number(low: float | None = None, *, strict: bool = False, words: str = "", optional: bool = False):
    """A finite number, at least (``strict``: above) ``low``; ``words`` the domain in words."""

    def check(x, sc=None):
        if x is None and optional:
            return None
        if not is_real(x) or not math.isfinite(x):
            raise _Refused(f"must be a finite number, got {num(x)}")
        if low is not None and (x <= low if strict else x < low):
            raise _Refused(f"{words}, got {num(x)}")
        return float(x)

    return check


def _choice(*choices: str):
    def check(x, sc=None):
        if x not in choices:
            raise _Refused(f"must be one of {', '.join(choices)}, got {x!r}")
        return x

    return check


def _flag(x, sc=None):
    if not isinstance(x, bool):
        raise _Refused(f"must be true or false, got {x!r}")
    return x


def _table(x, sc=None):
    if not isinstance(x, dict):
        raise _Refused(f"must be a table (a dict) of options, got {x!r}")
    return dict(x)


def _map(lookup):
    def check(x, sc=None):
        try:
            lookup(x)
        except (ValueError, TypeError) as exc:
            raise _Refused(str(exc), "colon") from None
        return x

    return check


def _plant(x, sc=None):
    """A map, or the MuJoCo robot (:data:`~.plant.ROBOT`)."""
    if x == ROBOT:
        return x
    try:
        get(x)
    except (ValueError, TypeError) as exc:
        raise _Refused(f"{exc}; or {ROBOT!r}, the MuJoCo robot", "colon") from None
    return x


def _gains(x, sc=None):
    """Raibert's gains: RaibertGains, or a table of them (its own error naming the gain)."""
    if isinstance(x, dict):
        unknown = sorted(set(x) - {f.name for f in dataclass_fields(RaibertGains)})
        if unknown:
            raise _Refused(f"has no gain {unknown[0]!r}; Raibert's controller's gains: k_v, k_h, k_i")
        try:
            return RaibertGains(**x)
        except ValueError as exc:
            raise _Refused(str(exc), "colon") from None
    if not isinstance(x, RaibertGains):
        raise _Refused(f"must be RaibertGains or a table of its gains, got {x!r}")
    return x


def _params(x, sc=None):
    """A SlipParams, or a table of its fields (as the TOML's ``[params]``: the human runner's values
    where not given, the leg lengths following l0): SlipParams' own error naming the field."""
    if isinstance(x, SlipParams):
        return x
    if isinstance(x, dict):
        return HUMAN_RUNNER.with_(**x)
    raise _Refused(f"must be a SlipParams or a table of its fields, got {x!r}")


def _controls(x, sc=None):
    if x is None:
        return None
    names = (x,) if isinstance(x, str) else x
    if not isinstance(names, (list, tuple)) or not names or not all(isinstance(c, str) for c in names):
        raise _Refused(f"must be a list of control names ({', '.join(CONTROLS)}), got {x!r}")
    for c in names:
        if c not in CONTROLS:
            raise _Refused(f"has an unknown control {c!r}; the controls are {', '.join(CONTROLS)}")
    return tuple(names)


def _bounds(x, sc):
    if not isinstance(x, dict):
        raise _Refused(f"must be a table of control: (low, high), got {x!r}")
    try:
        control_bounds(sc.params, (), x)  # every key and pair checked, one line naming it
    except ValueError as exc:
        raise _Refused(str(exc), "named") from None
    return {k: tuple(float(v) for v in pair) for k, pair in x.items()}


def _angle(x, sc=None):
    x = _number(optional=True)(x)
    if x is not None and abs(x) >= 0.5 * math.pi:
        raise _Refused(f"must lie in (-pi/2, pi/2), got {num(x)}")
    return x


def _grounds(x, sc=None):
    if x is None:
        return None
    try:
        low, high = x
    except (TypeError, ValueError):
        raise _Refused(f"must be a pair (low, high) [m], got {x!r}") from None
    if not (is_real(low) and is_real(high) and math.isfinite(low) and math.isfinite(high) and low < high):
        raise _Refused(f"must be finite with low < high, got {x!r}")
    return (float(low), float(high))


def _stones(x, sc=None):
    """A course (:class:`~.stones.Course`, or a list of [x_a, x_b, height]), or None."""
    if x is None or isinstance(x, Course):
        return x
    try:
        return Course.of(x)
    except CourseError as exc:
        raise _Refused(str(exc), "colon") from None


def _profile(x, sc):
    """Per-step values: as many as steps (none: the default), each a finite number."""
    try:
        values = tuple(x)
    except TypeError:
        raise _Refused(f"must be a sequence of numbers, one per step, got {x!r}") from None
    if values and len(values) != sc.steps:
        raise _Refused(f"has {len(values)} values for {sc.steps} steps")
    bad = next((v for v in values if not is_real(v) or not math.isfinite(v)), None)
    if bad is not None:
        raise _Refused(f"must hold finite numbers, got {num(bad)}")
    return tuple(float(v) for v in values)


_POSITIVE = "must be positive"
_FRACTION = "must be a fraction above -1 (the plant's {} is (1 + it) times the model's)"

#: Each field's check, in the fields' order (steps before the per-step profiles, params before the
#: bounds): the value it stores, or :class:`_Refused`.
_CHECKS = {
    "name": _text,
    "description": _text,
    "steps": _whole(1),
    "start_height": _number(0.0, words="must not be negative"),
    "start_speed": _number(),
    "target_height": _profile,
    "target_speed": _profile,
    "ground": _profile,
    "known": _whole(0),
    "model": _map(get),
    "model_options": _table,
    "plant": _plant,
    "plant_options": _table,
    "params": _params,
    "controls": _controls,
    "bounds": _bounds,
    "two_stage": _flag,
    "decompression": _map(get_half),
    "aim": _choice("both", "height", "speed"),
    "min_height": _number(0.0, strict=True, words=_POSITIVE, optional=True),
    "fixed_angle": _angle,
    "jacobian": _choice("broyden", "newton"),
    "tol": _number(0.0, strict=True, words=_POSITIVE),
    "policy": _choice(*POLICIES),
    "retraction_rate": _number(),
    "grounds": _grounds,
    "knots": _whole(2),
    "raibert": _gains,
    "correction": _whole(0),
    "correction_gate": _number(0.0, strict=True, words=_POSITIVE),
    "model_loss": _number(0.0, words="must be a fraction in [0, 1)"),
    "stones": _stones,
    "lookahead": _whole(1),
    "horizon": _whole(0),
    "mismatch_mass": _number(-1.0, strict=True, words=_FRACTION.format("mass")),
    "mismatch_stiffness": _number(-1.0, strict=True, words=_FRACTION.format("stiffness")),
    "noise_height": _number(0.0, words="must not be negative"),
    "noise_speed": _number(0.0, words="must not be negative"),
    "seed": _whole(0),
}


def _validate(sc: Scenario) -> None:
    """Every field checked (:data:`_CHECKS`) and stored as checked (tuples of floats...), the
    per-step profiles filled, then the settings that must go together (a robot plant has no mass or
    stiffness mismatch, and without parameters given its controller's are the robot's nominal
    SLIP; the swing-leg settings); ScenarioError (one line naming the field) for the first that is
    wrong."""
    name = sc.name if isinstance(sc.name, str) else "run"
    for f, check in _CHECKS.items():
        try:
            object.__setattr__(sc, f, check(getattr(sc, f), sc))
        except _Refused as bad:
            raise ScenarioError(name, f, bad.problem, bad.form) from None
    if sc.model_loss >= 1.0:
        raise ScenarioError(name, "model_loss", f"must be a fraction in [0, 1), got {num(sc.model_loss)}")
    if sc.plant == ROBOT:
        for key in ("mismatch_mass", "mismatch_stiffness"):
            if getattr(sc, key) != 0.0:
                problem = "is for a map plant; the robot's masses and springs are its own (its plant options)"
                raise ScenarioError(name, key, problem)
        if sc.params is HUMAN_RUNNER:  # not given: the model is the robot's nominal SLIP
            from ..robot.settings import robot_settings

            object.__setattr__(sc, "params", robot_settings(sc.plant_options).params.slip_params())
    defaults = {"target_height": sc.start_height, "target_speed": sc.start_speed, "ground": 0.0}
    for f, default in defaults.items():
        if not getattr(sc, f):
            object.__setattr__(sc, f, (float(default),) * sc.steps)
    rate = sc.retraction_rate
    if rate != 0.0 and sc.policy != "retraction" and sc.fixed_angle is None:
        raise ScenarioError(
            name,
            "retraction_rate",
            f"is the rate of policy 'retraction' (or of a fixed_angle run); policy is {sc.policy!r}",
        )
    if abs(rate) > limit("retraction_rate", sc.params):  # the maps' range (derive/params.py)
        raise ScenarioError(
            name,
            "retraction_rate",
            f"must lie in {limit_text('retraction_rate', sc.params)}, got {num(rate)}",
        )
    if sc.policy in ("time-based", "raibert", "footholds") and sc.fixed_angle is not None:
        raise ScenarioError(name, "policy", f"{sc.policy!r} is a controller: it cannot go with fixed_angle")
    if sc.policy == "footholds" and sc.stones is None:
        raise ScenarioError(name, "policy", "'footholds' aims at stepping stones: it needs a stones course "
                            '([terrain] kind = "stones")')  # fmt: skip
    if sc.stones is not None and sc.policy != "footholds":
        raise ScenarioError(
            name, "stones", f'a stones course needs policy "footholds" (the controller that aims at stones), '
            f"got policy {sc.policy!r}"
        )  # fmt: skip


class _Keys:
    """Reads one table with errors naming the key (``[targets] speed: ...``)."""

    def __init__(self, where: str, table: str, data) -> None:
        self.where, self.name = where, table
        self.label = f"[{table}] " if table else ""
        if not isinstance(data, dict):
            raise ValueError(f"{where}: {self.label or 'the file '}must be a table, got {data!r}")
        accepted = KEYS.get(table)
        if accepted is not None:
            unknown = sorted(set(data) - set(accepted))
            if unknown:
                raise ValueError(
                    f"{where}: unknown key {self.label}{unknown[0]}; accepted: {', '.join(accepted)}"
                )
        self.data = data

    def fail(self, key: str, problem: str):
        raise ValueError(f"{self.where}: {self.label}{key}: {problem}")

    def field(self, key: str, field: str, default):
        """The key's value checked as the Scenario field ``field`` is (:data:`_CHECKS`)."""
        try:
            return _CHECKS[field](self.data.get(key, default))
        except _Refused as bad:
            self.fail(key, bad.problem)

    def number(self, key: str, default=None, *, positive=False, non_negative=False, value=None):
        x = self.data.get(key, default) if value is None else value
        if x is None:
            return None
        if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
            self.fail(key, f"must be a finite number, got {x!r}")
        if positive and x <= 0:
            self.fail(key, f"must be positive, got {x!r}")
        if non_negative and x < 0:
            self.fail(key, f"must not be negative, got {x!r}")
        return float(x)

    def integer(self, key: str, default=None, *, minimum=0):
        x = self.data.get(key, default)
        if x is None:
            return None
        if isinstance(x, bool) or not isinstance(x, int) or x < minimum:
            self.fail(key, f"must be a whole number >= {minimum}, got {x!r}")
        return int(x)

    def text(self, key: str, default=None):
        x = self.data.get(key, default)
        if x is not None and not isinstance(x, str):
            self.fail(key, f"must be a string, got {x!r}")
        return x

    def table(self, key: str) -> _Keys:
        return _Keys(self.where, key if not self.name else f"{self.name}.{key}", self.data.get(key, {}))


def _profile_of(keys: _Keys, key: str, steps: int, start: float) -> tuple[float, ...]:
    """A number, a list per step (the last value held), or a ramp {from, to, steps, start}."""
    x = keys.data.get(key, start)
    if isinstance(x, dict):
        ramp = _Keys(keys.where, f"{keys.name}.{key}", x)
        unknown = sorted(set(x) - {"from", "to", "steps", "start"})
        if unknown:
            ramp.fail(unknown[0], "unknown key; a ramp has from, to, steps, start")
        a = ramp.number("from", start)
        b = ramp.number("to")
        if b is None:
            ramp.fail("to", "a ramp needs its end value `to`")
        n = ramp.integer("steps", steps, minimum=1)
        k0 = ramp.integer("start", 0)
        out = []
        for i in range(steps):
            frac = min(max((i - k0 + 1) / n, 0.0), 1.0)
            out.append(a + (b - a) * frac)
        return tuple(out)
    if isinstance(x, list):
        if not x:
            keys.fail(key, "an empty list")
        values = [keys.number(f"{key}[{i}]", value=v) for i, v in enumerate(x)]
        if len(values) > steps:
            keys.fail(key, f"{len(values)} values for {steps} steps")
        return tuple(values + [values[-1]] * (steps - len(values)))
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        keys.fail(key, f"must be a number, a list or a ramp {{from, to, steps}}, got {x!r}")
    return (keys.number(key, value=x),) * steps


def _terrain(keys: _Keys, steps: int) -> tuple[tuple[float, ...], int]:
    kind = keys.text("kind", "flat")
    if kind not in TERRAINS:
        keys.fail("kind", f"must be one of {', '.join(TERRAINS)}, got {kind!r}")
    known = keys.field("known", "known", 3)
    allowed = {
        "flat": {"kind", "known"},
        "steps": {"kind", "known", "heights"},
        "stairs": {"kind", "known", "rise", "before", "up", "flat", "down"},
        "random": {"kind", "known", "amplitude", "seed"},
        "stones": {"kind", "known", "stones", "count", "width", "gap", "rise", "seed", "margin", "lookahead"},
    }[kind]
    extra = sorted(set(keys.data) - allowed)
    if extra:
        keys.fail(extra[0], f"is not a key of kind {kind!r} (its keys: {', '.join(sorted(allowed))})")
    if kind in ("flat", "stones"):  # a stones course's grounds are the stones' (footholds_runs.py)
        return (0.0,) * steps, known
    if kind == "steps":
        if "heights" not in keys.data:
            keys.fail("heights", "kind 'steps' needs the ground height of each touchdown, heights = [...]")
        return _profile_of(keys, "heights", steps, 0.0), known
    if kind == "stairs":
        rise = keys.number("rise", 0.1)
        before = keys.integer("before", 2)
        up = keys.integer("up", 4)
        flat = keys.integer("flat", 2)
        down = keys.integer("down", up)
        level, out = 0.0, []
        plan = [0.0] * before + [rise] * up + [0.0] * flat + [-rise] * down
        for i in range(steps):
            level += plan[i] if i < len(plan) else 0.0
            out.append(level)
        return tuple(out), known
    amplitude = keys.number("amplitude", 0.1, non_negative=True)
    seed = keys.integer("seed", 0)
    changes = np.random.default_rng(seed).uniform(-amplitude, amplitude, steps)
    return tuple(float(x) for x in np.cumsum(changes)), known


#: The TOML key of each Scenario field: the scenario reference's (:mod:`.scenario_keys`), and the
#: keys whose values the loader shapes into a field (the profiles, the terrain's grounds, params).
_KEY_OF = {doc[4]: key for key, doc in KEY_DOCS.items() if doc[4] is not None} | {
    "name": ("", "name"),
    "target_height": ("targets", "height"),
    "target_speed": ("targets", "speed"),
    "ground": ("terrain", "heights"),
    "params": ("", "params"),
    "raibert": ("control", "raibert"),
    "stones": ("terrain", "stones"),
}


def _course_of(keys: _Keys) -> dict:
    """``[terrain]`` of kind stones: the course, listed (``stones``) or drawn (``count``, ``width``,
    ``gap``, ``rise``, ``seed``), its ``margin``, and ``lookahead``; {} for another kind."""
    if keys.data.get("kind") != "stones":
        return {}
    margin = keys.number("margin", 0.0, non_negative=True)
    listed = "stones" in keys.data
    drawn = sorted({"count", "width", "gap", "rise", "seed"} & set(keys.data))
    if listed and drawn:
        keys.fail(drawn[0], "is a key of a drawn course; this one lists its stones (stones = [...])")
    where = f"{keys.where}: [{keys.name}] stones"
    try:
        if listed:
            course = Course.of(keys.data["stones"], margin, where=where)
        else:
            pairs = {}
            for key, default in (("width", (0.3, 0.6)), ("gap", (0.2, 0.8))):
                pair = keys.data.get(key, list(default))
                if not (isinstance(pair, list) and len(pair) == 2):
                    keys.fail(key, f"must be a pair [low, high] [m], got {pair!r}")
                pairs[key] = tuple(
                    keys.number(f"{key}[{i}]", value=v, non_negative=True) for i, v in enumerate(pair)
                )
            course = random_course(
                keys.integer("seed", 0),
                count=keys.integer("count", 60, minimum=1),
                width=pairs["width"],
                gap=pairs["gap"],
                rise=keys.number("rise", 0.0, non_negative=True),
                margin=margin,
            )
    except CourseError as exc:
        text = str(exc)
        raise ValueError(text if text.startswith(where) else f"{where}: {text}") from None
    return {"stones": course, "lookahead": keys.integer("lookahead", LOOKAHEAD, minimum=1)}


def _plant_of(top: _Keys) -> tuple[str, dict]:
    """The plant and its options: ``plant = "NAME"`` with ``[plant_options]``, or a table ``[plant]``
    of ``kind`` and the options (a map's, or the robot's: ``slipmaps.runtime.robot``)."""
    raw = top.data.get("plant", "exact")
    options = top.data.get("plant_options", {})
    if not isinstance(options, dict):
        top.fail("plant_options", f"must be a table of the plant's options, got {options!r}")
    if isinstance(raw, dict):
        if "plant_options" in top.data:
            top.fail("plant_options", "give the options in the [plant] table (beside kind), not both")
        table = top.table("plant")
        kind = table.text("kind")
        if kind is None:
            table.fail("kind", f"the plant's kind: a map name or {ROBOT!r}")
        options = {k: v for k, v in raw.items() if k != "kind"}
    else:
        kind = top.text("plant", "exact")
    if kind != ROBOT:
        try:
            get(kind)
        except ValueError as exc:
            top.fail("plant", f"{exc}; or {ROBOT!r}, the MuJoCo robot")
    else:
        from ..robot.settings import robot_settings

        try:
            robot_settings(options)
        except ValueError as exc:
            top.fail("plant", str(exc))
    return kind, dict(options)


def _raibert_of(control: _Keys) -> RaibertGains:
    """``[control.raibert]``: the gains of Raibert's controller (k_v, k_h, k_i), each >= 0."""
    gains = control.table("raibert")
    unknown = sorted(set(gains.data) - {f.name for f in dataclass_fields(RaibertGains)})
    if unknown:
        gains.fail(unknown[0], "is not a gain of Raibert's controller (k_v, k_h, k_i)")
    return RaibertGains(**{k: gains.number(k, non_negative=True) for k in gains.data})


def _params_table(keys: _Keys) -> SlipParams:
    """``[params]``: SlipParams fields over the human runner's (leg lengths following l0)."""
    values = {k: keys.number(k) for k in keys.data}
    try:
        return HUMAN_RUNNER.with_(**values) if values else HUMAN_RUNNER
    except (ParamError, ParamTypeError) as exc:
        keys.fail(exc.field, f"{exc.problem}, got {num(exc.value)}")
    except ValueError as exc:  # k with k_c or k_d: SlipParams names them
        keys.fail(next(iter(keys.data)), str(exc))


def from_dict(data: dict, where: str = "scenario") -> Scenario:
    """A scenario from a table of the TOML keys (module docstring); ValueError naming the key."""
    top = _Keys(where, "", data)
    tables = {t: top.table(t) for t in KEYS if t and t != "params"}
    steps = top.field("steps", "steps", 10)
    start = tables["start"]
    h0 = start.field("height", "start_height", 1.0)
    v0 = start.field("speed", "start_speed", 5.0)
    ground, known = _terrain(tables["terrain"], steps)
    given = {}
    for (table, key), doc in KEY_DOCS.items():
        source = data if not table else tables[table].data
        if doc[4] is not None and key in source:
            given[doc[4]] = source[key]
    given |= {
        "name": data.get("name", Path(where).stem if where != "scenario" else "run"),
        "steps": steps,
        "start_height": h0,
        "start_speed": v0,
        "target_height": _profile_of(tables["targets"], "height", steps, h0),
        "target_speed": _profile_of(tables["targets"], "speed", steps, v0),
        "ground": ground,
        "known": known,
        "params": _params_table(top.table("params")),
        "raibert": _raibert_of(tables["control"]),
    }
    given["plant"], given["plant_options"] = _plant_of(top)
    given |= _course_of(tables["terrain"])
    try:
        return Scenario(**given)
    except ScenarioError as exc:
        table, key = _KEY_OF[exc.field]
        label = f"[{table}] " if table else ""
        if exc.form == "named":
            raise ValueError(f"{where}: {label}{exc.problem}") from None
        raise ValueError(f"{where}: {label}{key}: {exc.problem}") from None


def resized(sc: Scenario, steps: int) -> Scenario:
    """The scenario with ``steps`` steps: its per-step profiles cut, or their last value held
    (ScenarioError for a ``steps`` that is not a whole number >= 1)."""
    try:
        steps = _CHECKS["steps"](steps)
    except _Refused as bad:
        raise ScenarioError(sc.name, "steps", bad.problem) from None

    def fit(values):
        values = list(values)
        return tuple(values[:steps] + [values[-1]] * max(steps - len(values), 0))

    return sc.with_(
        steps=steps,
        target_height=fit(sc.target_height),
        target_speed=fit(sc.target_speed),
        ground=fit(sc.ground),
    )


def load(path: str | Path) -> Scenario:
    """A scenario from a TOML file (module docstring); ValueError naming the file and the key."""
    return from_dict(read_toml(path), where=str(path))


#: :func:`~slipmaps.runtime.control.scenarios.load` under its public name (``slipmaps.load_scenario``).
load_scenario = load
