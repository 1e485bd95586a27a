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
    [terrain]                    # kind: flat, steps (heights = [...]), stairs, random
    kind = "stairs"
    rise = 0.1                   # m per stair; `before` flat steps, `up` stairs, `flat` on top, `down`
    up = 4
    known = 3                    # touchdown grounds known ahead (0: unknown, the controller assumes flat)
    [control]                    # controls, bounds, two_stage, decompression, aim, min_height, fixed_angle
    controls = ["touchdown_angle", "k_d"]   # default; the angle alone for a constant-stiffness model
    bounds = { k_d = [10000.0, 40000.0] }
    policy = "apex"              # the swing leg: apex, retraction (retraction_rate), time-based
    [params]                     # SlipParams fields (the controller's); default the human runner
    [mismatch]                   # the plant's mass and stiffness off by a fraction: mass = 0.05
    [noise]                      # apex measurement noise (standard deviations) and its seed
    height = 0.001
    speed = 0.01
    seed = 1
    [model_options]              # the model map's options;  [plant_options]: the plant's

``kind = "random"`` draws each step's ground change uniformly in +-``amplitude`` [m] (seeded by the
terrain's ``seed``); ``stairs`` rises by ``rise`` per stair (``before``, ``up``, ``flat``, ``down``
steps).

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
from ..api.params import FIELDS, HUMAN_RUNNER, ParamError, ParamTypeError, SlipParams
from .deadbeat import CONTROLS
from .plant import ROBOT
from .raibert import RaibertGains

__all__ = ["Scenario", "from_dict", "load", "load_scenario", "read_toml", "resized", "KEYS"]

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
    "terrain": ("kind", "heights", "rise", "before", "up", "flat", "down", "amplitude", "seed", "known"),
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
    ),
    "mismatch": ("mass", "stiffness"),
    "noise": ("height", "speed", "seed"),
    "params": (*FIELDS, "k"),
}
TERRAINS = ("flat", "steps", "stairs", "random")
#: The swing-leg policies (module docstring).
POLICIES = ("apex", "retraction", "time-based", "raibert")


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
    mismatch_mass: float = 0.0  # the plant's mass is (1 + this) times the controller's
    mismatch_stiffness: float = 0.0  # the plant's springs are (1 + this) times what is commanded
    noise_height: float = 0.0  # standard deviation of the apex height measurement [m]
    noise_speed: float = 0.0  # ... of the apex speed [m/s]
    seed: int = 0

    def __post_init__(self):
        _check_policy(self)
        _check_plant(self)
        n = self.steps
        for name in ("target_height", "target_speed", "ground"):
            value = getattr(self, name)
            if len(value) == 0:
                default = {
                    "target_height": self.start_height,
                    "target_speed": self.start_speed,
                    "ground": 0.0,
                }
                object.__setattr__(self, name, (float(default[name]),) * n)
            elif len(value) != n:
                raise ValueError(f"scenario {self.name!r}: {name} has {len(value)} values for {n} steps")
            else:
                object.__setattr__(self, name, tuple(float(x) for x in value))

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
        return out


def _check_policy(sc: Scenario) -> None:
    """ValueError (one line) for swing-leg settings that do not go together (module docstring)."""
    where = f"scenario {sc.name!r}"
    if sc.policy not in POLICIES:
        raise ValueError(f"{where}: policy must be one of {', '.join(POLICIES)}, got {sc.policy!r}")
    rate = sc.retraction_rate
    if isinstance(rate, bool) or not isinstance(rate, (int, float)) or not math.isfinite(rate):
        raise ValueError(f"{where}: retraction_rate must be a finite number [rad/s], got {rate!r}")
    if rate != 0.0 and sc.policy != "retraction" and sc.fixed_angle is None:
        raise ValueError(
            f"{where}: retraction_rate is the rate of policy 'retraction' (or of a fixed_angle run); "
            f"policy is {sc.policy!r}"
        )
    if sc.policy in ("time-based", "raibert") and sc.fixed_angle is not None:
        raise ValueError(f"{where}: policy {sc.policy!r} is a controller: it cannot go with fixed_angle")
    if isinstance(sc.raibert, dict):
        object.__setattr__(sc, "raibert", RaibertGains(**sc.raibert))
    if not isinstance(sc.raibert, RaibertGains):
        raise ValueError(f"{where}: raibert must be RaibertGains or a dict of its gains, got {sc.raibert!r}")
    c = sc.correction
    if isinstance(c, bool) or not isinstance(c, int) or c < 0:
        raise ValueError(f"{where}: correction must be a whole number of hops >= 0, got {c!r}")
    gate = sc.correction_gate
    if (
        isinstance(gate, bool)
        or not isinstance(gate, (int, float))
        or not gate > 0
        or not math.isfinite(gate)
    ):
        raise ValueError(f"{where}: correction_gate must be a positive number [m], got {gate!r}")
    loss = sc.model_loss
    if isinstance(loss, bool) or not isinstance(loss, (int, float)) or not 0.0 <= loss < 1.0:
        raise ValueError(f"{where}: model_loss must be a fraction in [0, 1), got {loss!r}")
    if isinstance(sc.knots, bool) or not isinstance(sc.knots, int) or sc.knots < 2:
        raise ValueError(f"{where}: knots must be an integer >= 2, got {sc.knots!r}")
    if sc.grounds is not None:
        try:
            low, high = (float(x) for x in sc.grounds)
        except (TypeError, ValueError):
            raise ValueError(f"{where}: grounds must be a pair (low, high) [m], got {sc.grounds!r}") from None
        if not (math.isfinite(low) and math.isfinite(high) and low < high):
            raise ValueError(f"{where}: grounds must be finite with low < high, got {sc.grounds!r}")


def _check_plant(sc: Scenario) -> None:
    """ValueError (one line) for a plant that is neither a map nor the robot, or a robot scenario
    with a model mismatch (the robot's parameters are its own); the controller's parameters of a
    robot scenario that gives none: the robot's nominal SLIP."""
    where = f"scenario {sc.name!r}"
    if sc.plant != ROBOT:
        try:
            get(sc.plant)
        except ValueError as exc:
            raise ValueError(f"{where}: plant: {exc}; or {ROBOT!r}, the MuJoCo robot") from None
        return
    for key in ("mismatch_mass", "mismatch_stiffness"):
        if getattr(sc, key) != 0.0:
            raise ValueError(
                f"{where}: {key} is for a map plant; the robot's masses and springs are its own "
                "(its plant options)"
            )
    if sc.params is HUMAN_RUNNER:  # not given: the model is the robot's nominal SLIP
        from ..robot.settings import robot_settings

        object.__setattr__(sc, "params", robot_settings(sc.plant_options).params.slip_params())


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

    def flag(self, key: str, default=False):
        x = self.data.get(key, default)
        if not isinstance(x, bool):
            self.fail(key, f"must be true or false, got {x!r}")
        return x

    def table(self, key: str) -> _Keys:
        return _Keys(self.where, key if not self.name else f"{self.name}.{key}", self.data.get(key, {}))


def _profile(keys: _Keys, key: str, steps: int, start: float) -> tuple[float, ...]:
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
    known = keys.integer("known", 3)
    allowed = {
        "flat": {"kind", "known"},
        "steps": {"kind", "known", "heights"},
        "stairs": {"kind", "known", "rise", "before", "up", "flat", "down"},
        "random": {"kind", "known", "amplitude", "seed"},
    }[kind]
    extra = sorted(set(keys.data) - allowed)
    if extra:
        keys.fail(extra[0], f"is not a key of kind {kind!r} (its keys: {', '.join(sorted(allowed))})")
    if kind == "flat":
        return (0.0,) * steps, known
    if kind == "steps":
        if "heights" not in keys.data:
            keys.fail("heights", "kind 'steps' needs the ground height of each touchdown, heights = [...]")
        return _profile(keys, "heights", steps, 0.0), known
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


def _plant(top: _Keys) -> tuple[str, dict]:
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


def _loss(keys: _Keys) -> float:
    x = keys.number("model_loss", 0.0, non_negative=True)
    if x >= 1.0:
        keys.fail("model_loss", f"a fraction of the apex speed in [0, 1), got {x!r}")
    return x


def _fraction(keys: _Keys, key: str) -> float:
    x = keys.number(key, 0.0)
    if x <= -1.0:
        keys.fail(key, f"a fraction above -1 (the plant's {key} is (1 + it) times the model's), got {x!r}")
    return x


def from_dict(data: dict, where: str = "scenario") -> Scenario:
    """A scenario from a table of the TOML keys (module docstring); ValueError naming the key."""
    top = _Keys(where, "", data)
    steps = top.integer("steps", 10, minimum=1)
    start = top.table("start")
    h0 = start.number("height", 1.0, non_negative=True)
    v0 = start.number("speed", 5.0)
    targets = top.table("targets")
    terrain = top.table("terrain")
    ground, known = _terrain(terrain, steps)
    control = top.table("control")
    pk = top.table("params")
    try:
        params = (
            HUMAN_RUNNER.with_(**{k: pk.number(k, positive=True) for k in pk.data})
            if pk.data
            else HUMAN_RUNNER
        )
    except (ParamError, ParamTypeError) as exc:
        pk.fail(exc.field, f"{exc.problem}, got {exc.value!r}")
    except ValueError as exc:
        pk.fail(next(iter(pk.data)), str(exc))
    mismatch = top.table("mismatch")
    noise = top.table("noise")
    name = top.text("name", Path(where).stem if where != "scenario" else "run")
    model = top.text("model", "iterative")
    try:
        get(model)
    except ValueError as exc:
        top.fail("model", str(exc))
    plant, plant_options = _plant(top)
    controls = control.data.get("controls")
    if isinstance(controls, str):
        controls = [controls]
    if controls is not None and (
        not isinstance(controls, list) or not all(isinstance(c, str) for c in controls)
    ):
        control.fail("controls", f"must be a list of control names, got {controls!r}")
    for c in controls or ():
        if c not in CONTROLS:
            control.fail("controls", f"unknown control {c!r}; the controls are {', '.join(CONTROLS)}")
    bounds_keys = control.table("bounds")
    bounds = {}
    for key, pair in bounds_keys.data.items():
        if key not in CONTROLS:
            bounds_keys.fail(key, f"is not a control; the controls are {', '.join(CONTROLS)}")
        if not (isinstance(pair, list) and len(pair) == 2):
            bounds_keys.fail(key, f"must be a pair [low, high], got {pair!r}")
        bounds[key] = tuple(bounds_keys.number(key, value=x) for x in pair)
    decompression = control.text("decompression", "iterative-decompression")
    try:
        get_half(decompression)
    except ValueError as exc:
        control.fail("decompression", str(exc))
    aim = control.text("aim", "both")
    if aim not in ("both", "height", "speed"):
        control.fail("aim", f"must be both, height or speed, got {aim!r}")
    jacobian = control.text("jacobian", "broyden")
    if jacobian not in ("broyden", "newton"):
        control.fail("jacobian", f"must be broyden or newton, got {jacobian!r}")
    fixed = control.number("fixed_angle")
    if fixed is not None and abs(fixed) >= 0.5 * math.pi:
        control.fail("fixed_angle", f"must satisfy |angle| < pi/2, got {fixed!r}")
    if not isinstance(data.get("model_options", {}), dict):
        top.fail("model_options", f"must be a table of the map's options, got {data['model_options']!r}")
    policy = control.text("policy", "apex")
    if policy not in POLICIES:
        control.fail("policy", f"must be one of {', '.join(POLICIES)}, got {policy!r}")
    rate = control.number("retraction_rate", 0.0)
    if rate != 0.0 and policy != "retraction" and fixed is None:
        control.fail(
            "retraction_rate",
            f"is the rate of policy 'retraction' (or of a fixed_angle run); policy is {policy!r}",
        )
    if policy in ("time-based", "raibert") and fixed is not None:
        control.fail("policy", f"policy {policy!r} is a controller: it cannot go with fixed_angle")
    gains = control.table("raibert")
    unknown = sorted(set(gains.data) - {f.name for f in dataclass_fields(RaibertGains)})
    if unknown:
        gains.fail(unknown[0], "is not a gain of Raibert's controller (k_v, k_h, k_i)")
    raibert = RaibertGains(**{k: gains.number(k, non_negative=True) for k in gains.data})
    grounds = control.data.get("grounds")
    if grounds is not None:
        if not (isinstance(grounds, list) and len(grounds) == 2):
            control.fail("grounds", f"must be a pair [low, high] [m], got {grounds!r}")
        grounds = tuple(control.number("grounds", value=x) for x in grounds)
        if not grounds[0] < grounds[1]:
            control.fail("grounds", f"must have low < high, got {list(grounds)!r}")
    knots = control.integer("knots", 64, minimum=2)
    return Scenario(
        name=name,
        description=top.text("description", ""),
        steps=steps,
        start_height=h0,
        start_speed=v0,
        target_height=_profile(targets, "height", steps, h0),
        target_speed=_profile(targets, "speed", steps, v0),
        ground=ground,
        known=known,
        model=model,
        model_options=dict(data.get("model_options", {})),
        plant=plant,
        plant_options=plant_options,
        params=params,
        controls=None if controls is None else tuple(controls),
        bounds=bounds,
        two_stage=control.flag("two_stage", False),
        decompression=decompression,
        aim=aim,
        min_height=control.number("min_height", positive=True),
        fixed_angle=fixed,
        jacobian=jacobian,
        tol=control.number("tol", 1e-9, positive=True),
        policy=policy,
        retraction_rate=rate,
        grounds=grounds,
        knots=knots,
        raibert=raibert,
        correction=control.integer("correction", 0),
        correction_gate=control.number("correction_gate", 0.01, positive=True),
        model_loss=_loss(control),
        mismatch_mass=_fraction(mismatch, "mass"),
        mismatch_stiffness=_fraction(mismatch, "stiffness"),
        noise_height=noise.number("height", 0.0, non_negative=True),
        noise_speed=noise.number("speed", 0.0, non_negative=True),
        seed=noise.integer("seed", 0),
    )


def resized(sc: Scenario, steps: int) -> Scenario:
    """The scenario with ``steps`` steps: its per-step profiles cut, or their last value held."""

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
