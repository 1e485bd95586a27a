"""Property tests of every generated map's kernels and of the public map API, generic over the index.

Every map of ``slipmaps.generated.maps_index.MAPS`` contributes its stance, state-at-time and
apex-return kernels (scalar and batch); the flight kernels shared by every apex-return map join the
scalar tests. Nothing here names a map: arguments, outputs, options and their choices all come from
the index rows, so a new map is tested by adding it to ``derive/maps/``.

Kernel contract: a kernel never raises; it returns its outputs plus a status code, and either the
status is OK (0) and every output is finite, or the status is another known code and every output is
NaN. Invalid inputs (non-finite, a nonpositive parameter, a leg longer than l0 or at or below the
horizontal, a negative time or apex, an option code outside its domain) give INVALID_INPUT.

"Garbage" inputs mix NaN, +-inf, zeros, negatives and magnitudes in [MIN_MAGNITUDE, MAX_MAGNITUDE]
(1e-300 .. 1e300): kernels compile with error_model="numpy" and end with an all-outputs-finite
guard (NUMERICAL_RANGE), so overflow, underflow and cancellation are statuses, not exceptions.
"Gaits" are realistic: a human runner or a robot hopper (dimensionless stiffness k l0 / (m g) 10-40
and 8-30; HUMAN_RUNNER is 25.5, ROBOT_HOPPER 12.7), touchdown angle 0.1-0.7 rad, horizontal speed
1-8 m/s, descent speed 0.05-3 m/s.

The public API (``slipmaps.stance`` ...) validates scalar arguments (ValueError naming the argument)
and gives a bad batch row INVALID_INPUT without failing the other rows. The ``test_regression_*``
tests at the end pin the cases that used to break the contract.
"""

from __future__ import annotations

import importlib
import inspect
import itertools
import math
import re
from collections.abc import Callable
from dataclasses import dataclass

import kernels
import numpy as np
import pytest
import slipmaps
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from slipmaps.generated import flight as g_flight
from slipmaps.generated import maps_index
from slipmaps.generated.status import Status

HALF_PI = math.pi / 2
MAX_MAGNITUDE = 1e300
MIN_MAGNITUDE = 1e-300
NAN, INF = math.nan, math.inf
G = 9.81
OK = int(Status.OK)
INVALID = int(Status.INVALID_INPUT)
CODES = frozenset(int(s) for s in Status)

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
#: Each example of a batch test draws and checks up to 8 rows.
BATCH_SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
#: The public batch API of the exact map integrates every row (about 5 ms each).
API_SETTINGS = settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])

STANCE = tuple(r["name"] for r in maps_index.STANCE_OUTPUTS)
APEX = tuple(r["name"] for r in maps_index.APEX_OUTPUTS)
TRAJECTORY = tuple(r["name"] for r in maps_index.TRAJECTORY_OUTPUTS)
TOUCHDOWN = tuple(maps_index.TOUCHDOWN)
#: The batch rows of an apex-return kernel: the apex, the touchdown angle, the ground.
APEX_ROWS = tuple(maps_index.APEX_PUBLIC)


# ----------------------------------------------------------------------------------------------
# The kernels, from the index
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Kernel:
    """A generated kernel: its scalar and batch forms, argument and output names, batch rows."""

    name: str
    role: str  # "stance", "state_at", "apex_return" (a map's) or "flight"
    row: dict | None  # the map's index row; None for the flight kernels
    scalar: Callable
    batch: Callable | None
    outputs: tuple[str, ...]
    rows: tuple[str, ...] = ()
    signature: tuple[str, ...] = ()  # a flight kernel's arguments: its Python signature's

    @property
    def args(self) -> tuple[str, ...]:
        """The arguments' names: a map kernel's are its declaration's (tests/kernels.py, from the
        SymPy derivations: built once per process when a test first asks, not at collection)."""
        return self.signature or kernels.declaration(self.module, self.name).arg_names

    @property
    def options(self) -> tuple[dict, ...]:
        return tuple(self.row["options"]) if self.row else ()

    def call(self, env: dict):
        """The kernel at the arguments of ``env`` (by name, whatever its calling convention), with
        what a family member fixes (its row's ``fixed``: the family's options it does not expose)."""
        fixed = self.row["fixed"] if self.row else {}
        return kernels.invoke(kernels.declaration(self.module, self.name), {**fixed, **UNMODELLED, **env})

    @property
    def module(self) -> str:
        return self.scalar.py_func.__module__


#: The value every map assumes for a parameter only some maps model (the leg damping c = 0), for
#: the kernels that take it when an environment does not set it.
UNMODELLED = kernels.UNMODELLED


def _map_kernels(row: dict) -> list[Kernel]:
    """A map's stance, state-at-time and apex-return role kernels, as the index publishes them (the
    arguments each reads: its declaration's)."""
    extras = tuple(e["name"] for e in row["extras"])
    expected = {"stance": STANCE + extras, "state_at": TRAJECTORY, "apex_return": APEX + extras}
    out = []
    for role, outputs in expected.items():
        spec = row["kernels"].get(role)
        if spec is None:
            continue
        assert tuple(spec["out"]) == outputs, (row["name"], role)
        module = importlib.import_module(f"slipmaps.generated.{spec['module']}")
        scalar, batch = getattr(module, spec["name"]), getattr(module, f"{spec['name']}_rows")
        out.append(Kernel(spec["name"], role, row, scalar, batch, outputs, tuple(spec["x"])))
    return out


def _signature(kernel: Callable) -> tuple[str, ...]:
    return tuple(inspect.signature(kernel.py_func).parameters)


MAP_KERNELS = [k for row in maps_index.MAPS for k in _map_kernels(row)]
FLIGHT_KERNELS = [
    Kernel(
        "apex_to_touchdown",
        "flight",
        None,
        g_flight.apex_to_touchdown,
        None,
        ("touchdown_q_r", "touchdown_q_rd", "touchdown_q_th", "touchdown_q_thd", "t_flight", "foot_x"),
        signature=_signature(g_flight.apex_to_touchdown),
    ),
    Kernel(
        "liftoff_to_apex",
        "flight",
        None,
        g_flight.liftoff_to_apex,
        None,
        ("apex_b_y", "apex_b_xd", "t_flight", "dx_flight", "apex_b_x"),
        signature=_signature(g_flight.liftoff_to_apex),
    ),
]
KERNELS = MAP_KERNELS + FLIGHT_KERNELS
ROLE = {role: [k for k in MAP_KERNELS if k.role == role] for role in ("stance", "state_at", "apex_return")}


def test_kernel_sets_by_role_are_not_empty():
    """The tests below are parametrized over kernels filtered by role: an empty set would run none."""
    assert FLIGHT_KERNELS and all(ROLE[role] for role in ROLE), {r: len(k) for r, k in ROLE.items()}
    assert len(ROLE["stance"]) == len(ROLE["apex_return"]) == len(maps_index.MAPS)


def _ids(kernels):
    return [k.name for k in kernels]


def check_contract(kernel: Kernel, res) -> Status:
    """The status contract; returns the status."""
    assert isinstance(res, tuple) and len(res) == len(kernel.outputs) + 1, res
    code, out = res[-1], res[:-1]
    assert code in CODES, f"{kernel.name}: unknown status {code!r}"
    if code == OK:
        assert all(math.isfinite(x) for x in out), f"{kernel.name}: non-finite output with status OK: {res}"
    else:
        assert all(math.isnan(x) for x in out), f"{kernel.name}: {Status(code).name} with non-NaN {res}"
    return Status(code)


# ----------------------------------------------------------------------------------------------
# Options, from the index rows
# ----------------------------------------------------------------------------------------------
def option_values(option: dict) -> tuple[float, ...]:
    """The valid kernel codes tested for an option: every choice's index, iterations 0, 1 and 100,
    every value of a small integer range, a float's bounds and default."""
    if option["kind"] == "choice":
        return tuple(float(i) for i in range(len(option["choices"])))
    if option["name"] == "iterations":
        return (0.0, 1.0, 100.0)
    low, high = option["low"], option["high"]
    if option["kind"] == "int" and high - low <= 10:
        return tuple(float(v) for v in range(int(low), int(high) + 1))
    return tuple(sorted({float(low), float(option["default"]), float(high)}))


def invalid_option_values(option: dict) -> tuple[float, ...]:
    """Kernel codes outside an option's domain: a code past either end of the choices or the range,
    a non-integer code (choice or integer option), a float just outside its bounds."""
    if option["kind"] == "choice":
        n = len(option["choices"])
        return (-1.0, float(n), 0.5, float(np.nextafter(n - 1.0, INF)), 1e300)
    low, high = float(option["low"]), float(option["high"])
    bad = [low - 1.0, float(np.nextafter(low, -INF)), high + 1.0, float(np.nextafter(high, INF)), -1e300]
    if option["kind"] == "int":
        bad.append(low + 0.5)
    return tuple(bad)


def option_combinations(row: dict) -> list[tuple[float, ...]]:
    return list(itertools.product(*(option_values(o) for o in row["options"])))


def default_options(row: dict) -> dict[str, float]:
    out = {}
    for o in row["options"]:
        if o["kind"] == "choice":
            out[o["name"]] = float([c["value"] for c in o["choices"]].index(o["default"]))
        else:
            out[o["name"]] = float(o["default"])
    return out


def _at_rest_length(option: dict, code: float) -> bool:
    """Whether choice ``code`` of ``option`` needs touchdown at the rest length (index flag)."""
    choices = option["choices"]
    return code in range(len(choices)) and choices[int(code)]["value"] in option["at_rest_length"]


def needs_rest_length(kernel: Kernel, env: dict) -> bool:
    """Whether the chosen options need q_r_td = l0 while the gait touches down shorter."""
    if abs(env["q_r_td"] - env["l0"]) <= maps_index.REST_LENGTH_TOLERANCE * env["l0"]:
        return False
    return any(
        option["kind"] == "choice" and option["name"] in env and _at_rest_length(option, env[option["name"]])
        for option in kernel.options
    )


def forbidden_statuses(kernel: Kernel, env: dict) -> set[Status]:
    """The statuses a valid gait may not give: its inputs are valid (unless an option needs a
    touchdown at l0), it compresses at touchdown, its apex is above the touchdown height."""
    bad = {Status.INVALID_INPUT, Status.TOUCHDOWN_NOT_COMPRESSING, Status.APEX_TOO_LOW}
    return bad - {Status.INVALID_INPUT} if needs_rest_length(kernel, env) else bad


# ----------------------------------------------------------------------------------------------
# Strategies
# ----------------------------------------------------------------------------------------------
SPECIALS = (
    NAN,
    INF,
    -INF,
    0.0,
    -0.0,
    -1.0,
    1.0,
    HALF_PI,
    -HALF_PI,
    MAX_MAGNITUDE,
    -MAX_MAGNITUDE,
    MIN_MAGNITUDE,
)


def garbage():
    """Anything a caller might pass: non-finite, zero, negative, small or huge values.

    Finite values are 0 or have magnitudes in [MIN_MAGNITUDE, MAX_MAGNITUDE]; plausible magnitudes
    are drawn too, so that the later guards are reached.
    """
    return st.one_of(
        st.sampled_from(SPECIALS),
        st.floats(MIN_MAGNITUDE, MAX_MAGNITUDE),
        st.floats(-MAX_MAGNITUDE, -MIN_MAGNITUDE),
        st.floats(0.05, 5.0),
        st.floats(-5.0, -0.05),
    )


def garbage_for(kernel: Kernel, arg: str):
    """Garbage, and for an option also every valid and invalid code."""
    for option in kernel.options:
        if option["name"] == arg:
            codes = option_values(option) + invalid_option_values(option)
            return st.one_of(garbage(), st.sampled_from(codes))
    return garbage()


@st.composite
def slip_params(draw) -> dict[str, float]:
    """A human runner (50-100 kg, 0.8-1.2 m leg) or a robot hopper (1-10 kg, 0.15-0.5 m leg); leg
    lengths at touchdown and liftoff l0 or 0.9-1 l0."""
    if draw(st.booleans(), label="robot hopper"):
        m, l0, kappa = draw(st.floats(1.0, 10.0)), draw(st.floats(0.15, 0.5)), draw(st.floats(8.0, 30.0))
    else:
        m, l0, kappa = draw(st.floats(50.0, 100.0)), draw(st.floats(0.8, 1.2)), draw(st.floats(10.0, 40.0))
    q_r_td = l0 * draw(st.one_of(st.just(1.0), st.floats(0.9, 1.0)))
    q_r_lo = l0 * draw(st.one_of(st.just(1.0), st.floats(0.9, 1.0)))
    k = kappa * m * G / l0
    return {
        "m": m,
        "l0": l0,
        "k": k,
        "k_c": k,
        "k_d": k,
        "g_s": G,
        "g_f": G,
        "q_r_td": q_r_td,
        "q_r_lo": q_r_lo,
    }


def touchdown_from(th: float, vx: float, vy: float, q_r: float) -> dict[str, float]:
    """The polar touchdown state of a body moving at (vx, vy) onto a leg at angle th (the Cartesian ->
    polar map of flight.apex_to_touchdown)."""
    s, c = math.sin(th), math.cos(th)
    return {"q_r_td": q_r, "q_rd_td": -s * vx + c * vy, "q_th_td": th, "q_thd_td": -(c * vx + s * vy) / q_r}


def apex_from(
    th: float, vx: float, vy: float, q_r_td: float, g_f: float, ground: float = 0.0
) -> dict[str, float]:
    """The apex above a touchdown at angle th on ground ``ground`` higher, reached at (vx, vy), vy < 0
    (the inverse descent)."""
    apex = ground + q_r_td * math.cos(th) + vy**2 / (2.0 * g_f)
    return {"b_y_apex": apex, "b_xd_apex": vx, "q_th_td": th, "ground": ground}


@st.composite
def motion(draw) -> tuple[float, float, float]:
    """(touchdown angle, horizontal speed, vertical speed) of a realistic touchdown."""
    th = draw(st.floats(0.1, 0.7), label="touchdown angle")
    vx = draw(st.floats(1.0, 8.0), label="horizontal speed")
    vy = -draw(st.floats(0.05, 3.0), label="descent speed")
    return th, vx, vy


@st.composite
def gait(draw, row: dict | None = None) -> dict[str, float]:
    """Every kernel input of a realistic gait (see the module docstring), by argument name.

    The touchdown comes from the apex (b_y_apex, b_xd_apex) through an exact descent; the liftoff
    state (q_r, q_rd, q_th, q_thd; for liftoff_to_apex) mirrors the touchdown about the vertical;
    t lies in 0-1.5 spring half-periods; ``row`` adds a valid combination of the map's options.
    """
    env = draw(slip_params())
    th, vx, vy = draw(motion())
    env.update(touchdown_from(th, vx, vy, env["q_r_td"]))
    env.update(apex_from(th, vx, vy, env["q_r_td"], env["g_f"]))
    lo = touchdown_from(-th, vx, -vy, env["q_r_lo"])
    env.update(q_r=lo["q_r_td"], q_rd=lo["q_rd_td"], q_th=lo["q_th_td"], q_thd=lo["q_thd_td"], direction=1.0)
    env["t"] = draw(st.floats(0.0, 1.5)) * math.pi * math.sqrt(env["m"] / env["k"])
    if row is not None and row["options"]:
        combo = draw(st.sampled_from(option_combinations(row)), label="options")
        env.update(zip((o["name"] for o in row["options"]), combo, strict=True))
    return env


# ----------------------------------------------------------------------------------------------
# Physics of an OK result
# ----------------------------------------------------------------------------------------------
def check_physics(kernel: Kernel, env: dict, res) -> None:
    """Basic physics of an OK stance / apex-return result (nothing is checked for state_at here)."""
    v = dict(zip(kernel.outputs, res[:-1], strict=True))
    if kernel.role == "stance":
        assert 0.0 < v["t_bottom"] < v["t_stance"], v
        assert v["bottom_q_rd"] == 0.0
        assert 0.0 < v["bottom_q_r"] <= env["q_r_lo"] and v["bottom_q_r"] <= env["q_r_td"], v
        assert v["liftoff_q_r"] == env["q_r_lo"]
        assert v["liftoff_q_rd"] > 0.0, v
    elif kernel.role == "apex_return":
        assert v["t_descent"] > 0.0 and v["t_stance"] > 0.0 and v["t_ascent"] > 0.0, v
        assert v["liftoff_q_r"] == env["q_r_lo"]
        assert v["liftoff_q_rd"] > 0.0, v
        assert v["apex_height"] > 0.0
        # The body rises after liftoff, and moves forward (or hops in place: liftoff_to_apex's
        # tolerance for a vertical hop is 1e-9 sqrt(g_f q_r)).
        assert v["apex_height"] >= v["liftoff_q_r"] * math.cos(v["liftoff_q_th"]), v
        assert v["apex_speed"] >= -1e-9 * math.sqrt(env["g_f"] * env["q_r_lo"]), v
    if "passes" in v:
        iterations = env.get("iterations", math.inf)
        assert v["passes"] == math.floor(v["passes"]) and 0 <= v["passes"] <= iterations, v


# ----------------------------------------------------------------------------------------------
# The index and the kernels agree
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kernel", MAP_KERNELS, ids=_ids(MAP_KERNELS))
def test_kernel_signatures_match_the_index(kernel):
    """The argument names this file calls the kernels with are the kernels' own: role kernels of
    the index's layouts, the inputs x among the arguments, the options that are kernel arguments
    last."""
    assert _signature(kernel.scalar) == ("x", "p", "out")
    assert _signature(kernel.batch) == ("X", "P", "OUT", "STATUS")
    assert set(kernel.rows) <= set(kernel.args)
    options = tuple(o["name"] for o in kernel.options if o["kernel"])
    fixed = kernel.row["fixed"] if kernel.row else {}  # a family member's: the family's order
    tail = kernel.args[len(kernel.args) - len(options) - len(fixed) :]
    assert tuple(a for a in tail if a not in fixed) == options and set(tail) == set(options) | set(fixed)


def test_every_map_has_stance_and_apex_return_kernels():
    """(A state-at-time kernel only where the map has a trajectory.)"""
    assert len(maps_index.MAPS) >= 1
    for row in maps_index.MAPS:
        assert {"stance", "apex_return"} <= {k.role for k in MAP_KERNELS if k.row is row}


# ----------------------------------------------------------------------------------------------
# The status contract
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kernel", KERNELS, ids=_ids(KERNELS))
@SETTINGS
@given(data=st.data())
def test_garbage_never_raises_and_keeps_status_contract(kernel, data):
    args = {a: data.draw(garbage_for(kernel, a), label=a) for a in kernel.args}
    check_contract(kernel, kernel.call(args))


@pytest.mark.parametrize("kernel", KERNELS, ids=_ids(KERNELS))
@SETTINGS
@given(data=st.data())
def test_garbage_in_a_valid_gait_keeps_status_contract(kernel, data):
    """One to three arguments of a valid gait replaced by garbage (or any option code): the later
    guards see near-valid inputs."""
    env = data.draw(gait(kernel.row), label="gait")
    bad = data.draw(st.lists(st.sampled_from(kernel.args), min_size=1, max_size=3, unique=True), label="args")
    for a in bad:
        env[a] = data.draw(garbage_for(kernel, a), label=a)
    check_contract(kernel, kernel.call(env))


@pytest.mark.parametrize("kernel", KERNELS, ids=_ids(KERNELS))
@SETTINGS
@given(data=st.data())
def test_valid_gait_keeps_status_contract_and_physics(kernel, data):
    """A realistic gait with any valid option combination: the contract, and when OK, the stance
    events in order (0 < t_bottom < t_stance, bottom_q_rd = 0, 0 < bottom_q_r <= q_r_lo, q_r_td),
    liftoff at q_r_lo extending, a positive next apex above the liftoff height."""
    env = data.draw(gait(kernel.row), label="gait")
    res = kernel.call(env)
    status = check_contract(kernel, res)
    assert status not in forbidden_statuses(kernel, env), (status, env)
    if kernel.name == "liftoff_to_apex":
        # A liftoff mirroring the touchdown flies upward and forward, rises by the descent's drop and
        # keeps the apex speed (measured over 2e5 gaits: 9.9e-16 and 4.4e-16 relative).
        assert status == Status.OK
        drop = env["b_y_apex"] - env["q_r_td"] * math.cos(env["q_th_td"])
        assert res[0] == pytest.approx(env["q_r"] * math.cos(env["q_th"]) + drop, rel=1e-14)
        assert res[1] == pytest.approx(env["b_xd_apex"], rel=1e-14)
    if status == Status.OK:
        check_physics(kernel, env, res)


#: Representative gaits: both parameter sets, touchdown at l0 and shorter, slow and fast, shallow
#: and steep, each a complete step for every map; (m, l0, kappa, q_r_td/l0, q_r_lo/l0, th, vx, vy).
SWEEP_GAITS = [
    (80.0, 1.0, 25.5, 1.0, 1.0, 0.35, 5.0, -0.9),
    (80.0, 1.0, 25.5, 1.0, 1.0, 0.25, 3.0, -1.0),
    (70.0, 0.95, 15.0, 0.97, 0.95, 0.45, 6.0, -1.5),
    (90.0, 1.1, 35.0, 1.0, 0.98, 0.35, 8.0, -0.6),
    (3.0, 0.25, 12.7, 1.0, 1.0, 0.3, 1.5, -0.8),
    (3.0, 0.25, 12.7, 0.95, 1.0, 0.5, 2.5, -1.2),
    (5.0, 0.4, 20.0, 1.0, 0.96, 0.2, 1.0, -0.6),
    (1.5, 0.2, 9.0, 1.0, 1.0, 0.6, 2.0, -0.5),
]


def sweep_env(gait_row) -> dict[str, float]:
    m, l0, kappa, r_td, r_lo, th, vx, vy = gait_row
    env = {
        "m": m,
        "l0": l0,
        "k": kappa * m * G / l0,
        "k_c": kappa * m * G / l0,
        "k_d": kappa * m * G / l0,
        "g_s": G,
        "g_f": G,
        "q_r_td": r_td * l0,
        "q_r_lo": r_lo * l0,
        "direction": 1.0,
        "retraction_rate": 0.0,
    }
    env.update(touchdown_from(th, vx, vy, env["q_r_td"]))
    env.update(apex_from(th, vx, vy, env["q_r_td"], G))
    env["t"] = 0.5 * math.pi * math.sqrt(m / env["k"])
    return env


@pytest.mark.parametrize("kernel", MAP_KERNELS, ids=_ids(MAP_KERNELS))
def test_every_option_combination_keeps_status_contract_and_physics(kernel):
    """Every combination of the map's option values (index choices, iterations 0/1/100, ...) on the
    representative gaits: the contract, the physics when OK; OK, NOT_CONVERGED (too few passes
    for the tolerance) or a status the map declares its approximation returns for every
    combination, OK under the map's default options."""
    names = [o["name"] for o in kernel.options]
    for combo in option_combinations(kernel.row):
        for g in SWEEP_GAITS:
            env = {**sweep_env(g), **dict(zip(names, combo, strict=True))}
            res = kernel.call(env)
            status = check_contract(kernel, res)
            allowed = {Status.OK, Status.NOT_CONVERGED}
            allowed |= {Status[s] for s in kernel.row["approximation_statuses"]}
            if needs_rest_length(kernel, env):
                allowed.add(Status.INVALID_INPUT)
            assert status in allowed, (combo, g, status)
            if status == Status.OK:
                check_physics(kernel, env, res)
    for g in SWEEP_GAITS:
        assert kernel.call({**sweep_env(g), **default_options(kernel.row)})[-1] == OK, g


REST_LENGTH_CHOICES = [
    pytest.param(k, o["name"], float(i), id=f"{k.name}-{o['name']}={c['value']}")
    for k in MAP_KERNELS
    for o in k.options
    if o["kind"] == "choice"
    for i, c in enumerate(o["choices"])
    if c["value"] in o["at_rest_length"]
]


def test_some_choices_need_touchdown_at_l0():
    """The parametrization below is filtered (choices in ``at_rest_length``): it must not be empty."""
    assert REST_LENGTH_CHOICES


@pytest.mark.parametrize(("kernel", "option", "code"), REST_LENGTH_CHOICES)
def test_choice_needing_touchdown_at_l0_rejects_a_shorter_touchdown(kernel, option, code):
    """A choice the index documents as needing the touchdown at l0 (the other options at their
    defaults): OK at q_r_td = l0, INVALID_INPUT at q_r_td = 0.97 l0."""
    options = {**default_options(kernel.row), option: code}
    at_l0, shorter = sweep_env(SWEEP_GAITS[0]), sweep_env(SWEEP_GAITS[2])
    assert at_l0["q_r_td"] == at_l0["l0"] and shorter["q_r_td"] == 0.97 * shorter["l0"]
    assert check_contract(kernel, kernel.call({**at_l0, **options})) == Status.OK
    assert check_contract(kernel, kernel.call({**shorter, **options})) == Status.INVALID_INPUT


# ----------------------------------------------------------------------------------------------
# Invalid inputs
# ----------------------------------------------------------------------------------------------
#: Argument -> the kinds of invalid value it rejects, besides NaN and +-inf (which every argument
#: rejects). "nonpositive": <= 0; "above_l0": > l0; "angle": |x| >= pi/2; "negative": < 0.
DOMAINS = {
    **dict.fromkeys(("m", "l0", "k", "k_c", "k_d", "g_s", "g_f"), ("nonpositive",)),
    **dict.fromkeys(("q_r_td", "q_r_lo"), ("nonpositive", "above_l0")),
    "q_th_td": ("angle",),
    "t": ("negative",),
    "b_y_apex": ("negative",),
    # b_xd_apex, ground and retraction_rate: any finite value (a signed speed; a step up or down; a
    # rate, beyond sqrt(g_f/q_r_td) refused by the descent: tests/test_retraction.py)
}
#: The flight kernels have no l0 and take any apex speed and liftoff state.
FLIGHT_DOMAINS = {
    "apex_to_touchdown": {
        "b_y_apex": ("negative",),
        "q_th_td": ("angle",),
        "q_r_td": ("nonpositive",),
        "g_f": ("nonpositive",),
    },
    "liftoff_to_apex": {"q_r": ("nonpositive",), "g_f": ("nonpositive",), "direction": ("direction",)},
}
#: Representative values of each kind (l0 scales "above_l0").
INVALID_EXAMPLES = {
    "nonfinite": (NAN, INF, -INF),
    "nonpositive": (0.0, -0.0, -MIN_MAGNITUDE, -1.0, -MAX_MAGNITUDE),
    "negative": (-MIN_MAGNITUDE, -1e-9, -1.0, -MAX_MAGNITUDE),
    "angle": (HALF_PI, -HALF_PI, float(np.nextafter(HALF_PI, INF)), 2.0, -3.0, 1e3),
    "direction": (0.5, -0.5, 2.0, -2.0, 1e-300),  # a step's direction is +1, -1 or 0
}


def invalid_kinds(kernel: Kernel, arg: str) -> tuple[str, ...]:
    for option in kernel.options:
        if option["name"] == arg:
            return ("nonfinite", "option")
    domains = FLIGHT_DOMAINS[kernel.name] if kernel.role == "flight" else DOMAINS
    return ("nonfinite", *domains.get(arg, ()))


def invalid_examples(kernel: Kernel, arg: str, kind: str, env: dict) -> tuple[float, ...]:
    if kind == "option":
        return invalid_option_values(next(o for o in kernel.options if o["name"] == arg))
    if kind == "above_l0":
        return (float(np.nextafter(env["l0"], INF)), 1.5 * env["l0"], MAX_MAGNITUDE)
    return INVALID_EXAMPLES[kind]


@pytest.mark.parametrize("kernel", KERNELS, ids=_ids(KERNELS))
def test_invalid_input_every_argument_every_kind(kernel):
    """Each argument of a valid gait replaced by each kind of invalid value it has (negative mass,
    q_r_td > l0, |q_th_td| >= pi/2, non-finite, an option code outside its choices or range, a
    non-integer iteration count, a negative tol ...): INVALID_INPUT."""
    for g in SWEEP_GAITS[:2] + SWEEP_GAITS[4:5]:
        env = {**sweep_env(g), **(default_options(kernel.row) if kernel.row else {})}
        env.update(q_r=env["q_r_lo"], q_rd=1.0, q_th=-0.3, q_thd=-3.0, direction=1.0)
        for arg in kernel.args:
            for kind in invalid_kinds(kernel, arg):
                for bad in invalid_examples(kernel, arg, kind, env):
                    res = kernel.call({**env, arg: bad})
                    assert check_contract(kernel, res) == Status.INVALID_INPUT, (arg, kind, bad, res)


@pytest.mark.parametrize("kernel", KERNELS, ids=_ids(KERNELS))
@SETTINGS
@given(data=st.data())
def test_invalid_input_status(kernel, data):
    env = data.draw(gait(kernel.row), label="valid gait")
    arg = data.draw(st.sampled_from(kernel.args), label="corrupted argument")
    kind = data.draw(st.sampled_from(invalid_kinds(kernel, arg)), label="kind")
    if kind == "nonfinite":
        bad = data.draw(st.sampled_from((NAN, INF, -INF)))
    elif kind == "nonpositive":
        bad = data.draw(st.one_of(st.sampled_from((0.0, -0.0)), st.floats(-MAX_MAGNITUDE, 0.0)))
    elif kind == "negative":
        bad = -data.draw(st.floats(MIN_MAGNITUDE, MAX_MAGNITUDE))
    elif kind == "above_l0":
        bad = env["l0"] * (1.0 + data.draw(st.floats(1e-9, 1.0)))
    elif kind == "angle":
        bad = math.copysign(data.draw(st.floats(HALF_PI, 1e3)), data.draw(st.sampled_from((1.0, -1.0))))
    elif kind == "direction":
        bad = data.draw(st.floats(-1e3, 1e3).filter(lambda x: x not in (-1.0, 0.0, 1.0)))
    else:
        option = next(o for o in kernel.options if o["name"] == arg)
        bad = data.draw(st.sampled_from(invalid_option_values(option)))
    res = kernel.call({**env, arg: bad})
    assert check_contract(kernel, res) == Status.INVALID_INPUT, f"{arg}={bad!r} -> {res}"


@pytest.mark.parametrize(
    "kernel", ROLE["stance"] + ROLE["state_at"], ids=_ids(ROLE["stance"] + ROLE["state_at"])
)
@SETTINGS
@given(data=st.data())
def test_not_compressing_touchdown(kernel, data):
    env = data.draw(gait(kernel.row))
    env["q_rd_td"] = data.draw(st.one_of(st.just(0.0), st.floats(0.0, 5.0)), label="q_rd_td >= 0")
    expected = {Status.TOUCHDOWN_NOT_COMPRESSING}
    if needs_rest_length(kernel, env):
        expected.add(Status.INVALID_INPUT)
    assert check_contract(kernel, kernel.call(env)) in expected


# ----------------------------------------------------------------------------------------------
# The kernels agree with each other
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kernel", ROLE["state_at"], ids=_ids(ROLE["state_at"]))
@SETTINGS
@given(data=st.data())
def test_state_at_starts_at_touchdown_and_reaches_liftoff(kernel, data):
    """The map's trajectory passes through the touchdown state (q_r, q_rd, q_th; a map may start
    from a corrected angular momentum, so not q_thd) and, at t_stance, through the stance kernel's
    liftoff (q_r, q_th, q_thd; a map may take q_rd_lo from the energy, not the trajectory)."""
    env = data.draw(gait(kernel.row))
    stance = next(k for k in ROLE["stance"] if k.row is kernel.row)
    res = stance.call(env)
    assume(res[-1] == OK)  # a failed stance has no trajectory (Hypothesis' health check counts these)
    lo = dict(zip(stance.outputs, res[:-1], strict=True))
    r0 = kernel.call({**env, "t": 0.0})
    r1 = kernel.call({**env, "t": lo["t_stance"]})
    assert r0[-1] == OK and r1[-1] == OK, (r0, r1)
    # Measured over 28000 gaits of every map: q_r 4.6e-16 relative, q_rd 3.0e-14 relative,
    # q_th 3.3e-16 rad at touchdown; q_r 1.0e-15 relative, q_th 8.9e-16 rad, q_thd 3.5e-15 relative
    # at liftoff.
    assert r0[0] == pytest.approx(env["q_r_td"], rel=1e-14)
    assert r0[1] == pytest.approx(env["q_rd_td"], rel=1e-12)
    assert r0[2] == pytest.approx(env["q_th_td"], rel=0, abs=1e-14)
    assert r1[0] == pytest.approx(lo["liftoff_q_r"], rel=1e-14)
    assert r1[2] == pytest.approx(lo["liftoff_q_th"], rel=0, abs=1e-14)
    assert r1[3] == pytest.approx(lo["liftoff_q_thd"], rel=1e-13)


@pytest.mark.parametrize("kernel", ROLE["apex_return"], ids=_ids(ROLE["apex_return"]))
@SETTINGS
@given(data=st.data())
def test_apex_return_is_descent_then_stance_then_ascent(kernel, data):
    """The apex-return kernel is flight.apex_to_touchdown, the map's stance kernel and
    flight.liftoff_to_apex, bit for bit, and gives the first failing stage's status."""
    env = data.draw(gait(kernel.row))
    stance = next(k for k in ROLE["stance"] if k.row is kernel.row)
    got = kernel.call(env)
    td = kernels.invoke(kernels.declaration("flight", "apex_to_touchdown"), env)
    assert td[-1] == OK
    st_env = {**env, **dict(zip(TOUCHDOWN, td[:4], strict=True))}
    sres = stance.call(st_env)
    if sres[-1] != OK:
        assert got[-1] == sres[-1]
        return
    s = dict(zip(stance.outputs, sres[:-1], strict=True))
    direction = float(np.sign(env["b_xd_apex"]))
    lo = g_flight.liftoff_to_apex(*(s[f"liftoff_{q}"] for q in TRAJECTORY), env["g_f"], direction)
    assert got[-1] == lo[-1]
    if lo[-1] != OK:
        return
    expected = {**s, "apex_height": lo[0], "apex_speed": lo[1], "t_descent": td[4], "t_ascent": lo[2]}
    expected.update(step_length=td[5] + lo[4], foot_x=td[5], foot_y=env["ground"] - env["b_y_apex"])
    expected.update(touchdown_q_th=td[2])
    want = np.array([expected[n] for n in kernel.outputs])
    assert np.array(got[:-1]).tobytes() == want.tobytes(), (got, want)


# ----------------------------------------------------------------------------------------------
# Batch forms == scalar forms, row by row
# ----------------------------------------------------------------------------------------------
def run_batch(kernel: Kernel, env: dict, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The batch form over ``rows`` (one column per input of x) with the parameter record of
    ``env`` (its fields by the index's names), as the public API calls it."""
    n = rows.shape[0]
    spec = kernel.row["kernels"][kernel.role]
    X = np.ascontiguousarray(rows, dtype=float)
    env = {**kernel.row["fixed"], **UNMODELLED, **env}  # what a family member fixes (as Kernel.call)
    P = np.array([[float(env.get(f, math.nan)) for f in spec["p"]]])
    out = np.empty((n, len(kernel.outputs)))
    status = np.empty(n, dtype=np.int64)
    kernel.batch(X, P, out, status)
    return out, status


@st.composite
def batch_case(draw, kernel: Kernel) -> tuple[dict, np.ndarray]:
    """Shared inputs (a realistic gait's parameters and options; sometimes an invalid option code)
    and 1-8 rows: realistic gaits generated from a drawn seed (few draws per example), each entry
    replaced with probability 1/4 by garbage or one of its argument's out-of-domain values."""
    env = draw(gait(kernel.row))
    if kernel.options and draw(st.integers(0, 7), label="invalid option?") == 0:
        option = draw(st.sampled_from(kernel.options))
        env[option["name"]] = draw(st.sampled_from(invalid_option_values(option)))
    n = draw(st.integers(1, 8), label="rows")
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1), label="row seed"))
    th, vx, vy = rng.uniform(0.1, 0.7, n), rng.uniform(1.0, 8.0, n), -rng.uniform(0.05, 3.0, n)
    t = rng.uniform(0.0, 1.5, n) * math.pi * math.sqrt(env["m"] / env["k"])
    rates = rng.uniform(-1.0, 1.0, n)  # a swinging leg (rad/s): retracting or protracting
    rows = np.empty((n, len(kernel.rows)))
    for i in range(n):
        vals = {
            **touchdown_from(th[i], vx[i], vy[i], env["q_r_td"]),
            **apex_from(th[i], vx[i], vy[i], env["q_r_td"], env["g_f"]),
            "t": t[i],
            "retraction_rate": rates[i],
        }
        rows[i] = [vals[a] for a in kernel.rows]
    for i, j in zip(*np.nonzero(rng.random(rows.shape) < 0.25), strict=True):
        arg = kernel.rows[j]
        pool = [
            *SPECIALS,
            *(v for k in invalid_kinds(kernel, arg) for v in invalid_examples(kernel, arg, k, env)),
        ]
        magnitude = rng.choice((-1.0, 1.0)) * 10.0 ** rng.uniform(-300, 300)
        rows[i, j] = magnitude if rng.random() < 0.3 else pool[rng.integers(len(pool))]
    return env, rows


@pytest.mark.parametrize("kernel", MAP_KERNELS, ids=_ids(MAP_KERNELS))
@BATCH_SETTINGS
@given(data=st.data())
def test_batch_equals_scalar_bit_for_bit_row_by_row(kernel, data):
    """Every row of the parallel batch form is the scalar kernel's result, bit for bit, with its
    own status: a NaN or out-of-domain row is INVALID_INPUT (or another failure) while the other
    rows are computed."""
    env, rows = data.draw(batch_case(kernel))
    out, status = run_batch(kernel, env, rows)
    for i, row in enumerate(rows):
        res = kernel.call({**env, **dict(zip(kernel.rows, map(float, row), strict=True))})
        assert status[i] == res[-1], (i, row, status[i], res)
        assert out[i].tobytes() == np.array(res[:-1], dtype=float).tobytes(), (i, row, out[i], res)


@pytest.mark.parametrize("kernel", MAP_KERNELS, ids=_ids(MAP_KERNELS))
def test_batch_bad_rows_do_not_spoil_good_rows(kernel):
    """A deterministic mix: one bad row per batch argument and kind of invalid value, each followed
    by a good row (two representative gaits): the bad rows are INVALID_INPUT, the good ones OK and
    equal to the scalar results."""
    env = {**sweep_env(SWEEP_GAITS[0]), **default_options(kernel.row)}
    good = [np.array([sweep_env(SWEEP_GAITS[j])[a] for a in kernel.rows]) for j in (0, 1)]
    rows, is_bad = [], []
    for j, a in enumerate(kernel.rows):
        for kind in invalid_kinds(kernel, a):
            for value in invalid_examples(kernel, a, kind, env):
                row = good[0].copy()
                row[j] = value
                rows += [row, good[len(rows) // 2 % 2]]
                is_bad += [True, False]
    rows, is_bad = np.array(rows), np.array(is_bad)
    assert is_bad.any() and (~is_bad).any(), kernel.name
    out, status = run_batch(kernel, env, rows)
    assert np.all(status[is_bad] == INVALID) and np.all(np.isnan(out[is_bad]))
    assert np.all(status[~is_bad] == OK) and np.all(np.isfinite(out[~is_bad]))
    for i in np.flatnonzero(~is_bad):
        res = kernel.call({**env, **dict(zip(kernel.rows, map(float, rows[i]), strict=True))})
        assert out[i].tobytes() == np.array(res[:-1], dtype=float).tobytes()


# ----------------------------------------------------------------------------------------------
# The public API (runtime/api/maps.py), every map of slipmaps.maps() including "exact"
# ----------------------------------------------------------------------------------------------
API_MAPS = [m.name for m in slipmaps.maps()]
API_OPTIONS = [(m.name, o) for m in slipmaps.maps() for o in m.options]
POLAR = ("q_r", "q_rd", "q_th", "q_thd")
TD = (1.0, -1.5, 0.35, -4.5)  # a touchdown of HUMAN_RUNNER at its rest length


def _slip(env: dict) -> slipmaps.SlipParams:
    names = ("m", "l0", "k", "g_s", "g_f", "q_r_td", "q_r_lo")
    return slipmaps.SlipParams(**{n: env[n] for n in names})


def bad_touchdown_entry(l0: float):
    """(component, value) that makes a touchdown state invalid: non-finite, q_r outside (0, l0],
    |q_th| >= pi/2."""
    return st.one_of(
        st.tuples(st.integers(0, 3), st.sampled_from((NAN, INF, -INF))),
        st.tuples(st.just(0), st.sampled_from((0.0, -0.5, 1.5 * l0, 1e300))),
        st.tuples(st.just(2), st.sampled_from((HALF_PI, -HALF_PI, 2.0, -1e3))),
    )


def bad_apex_entry():
    """(argument, value) that makes an apex-return input invalid: non-finite (any of the four), a
    negative apex height, |touchdown angle| >= pi/2 (a negative speed and any ground are valid)."""
    return st.one_of(
        st.tuples(st.integers(0, 3), st.sampled_from((NAN, INF, -INF))),
        st.tuples(st.just(0), st.sampled_from((-1e-9, -1.0, -1e300))),
        st.tuples(st.just(2), st.sampled_from((HALF_PI, -HALF_PI, 2.0, -1e3))),
    )


def _same(a: float, b: float) -> bool:
    return np.float64(a).tobytes() == np.float64(b).tobytes()


@pytest.mark.parametrize("name", API_MAPS)
@API_SETTINGS
@given(data=st.data())
def test_public_stance_batch_bad_row_is_invalid_input_others_computed(name, data):
    env = data.draw(gait())
    params = _slip(env)
    n = data.draw(st.integers(2, 4), label="rows")
    tds = np.array(
        [[touchdown_from(*data.draw(motion()), env["q_r_td"])[a] for a in TOUCHDOWN] for _ in range(n)]
    )
    i_bad = data.draw(st.integers(0, n - 1), label="bad row")
    j, value = data.draw(bad_touchdown_entry(env["l0"]), label="bad entry")
    tds[i_bad, j] = value
    res = slipmaps.stance_batch(name, params, tds)
    assert res["status"].shape == (n,)
    assert res["status"][i_bad] == INVALID
    assert all(math.isnan(res[c][i_bad]) for c in res.names)
    for i in range(n):
        if i == i_bad:
            continue
        one = slipmaps.stance(name, params, tds[i])
        assert res["status"][i] == one.status, (i, res.message(i), one.message)
        assert all(_same(res[c][i], one[c]) for c in res.names), (i, one)


@pytest.mark.parametrize("name", API_MAPS)
@API_SETTINGS
@given(data=st.data())
def test_public_apex_return_batch_bad_row_is_invalid_input_others_computed(name, data):
    env = data.draw(gait())
    params = _slip(env)
    n = data.draw(st.integers(2, 4), label="rows")
    cols = np.array(
        [list(apex_from(*data.draw(motion()), env["q_r_td"], env["g_f"]).values()) for _ in range(n)]
    ).T
    i_bad = data.draw(st.integers(0, n - 1), label="bad row")
    j, value = data.draw(bad_apex_entry(), label="bad entry")
    cols[j, i_bad] = value
    height, speed, angle, ground = (np.ascontiguousarray(c) for c in cols)
    res = slipmaps.apex_return_batch(name, params, height, speed, angle, ground=ground)
    assert res["status"].shape == (n,)
    assert res["status"][i_bad] == INVALID
    assert all(math.isnan(res[c][i_bad]) for c in res.names)
    for i in range(n):
        if i == i_bad:
            continue
        one = slipmaps.apex_return(name, params, height[i], speed[i], angle[i], ground=ground[i])
        assert res["status"][i] == one.status, (i, res.message(i), one.message)
        assert all(_same(res[c][i], one[c]) for c in res.names), (i, one)


@pytest.mark.parametrize("name", [m.name for m in slipmaps.maps()])
def test_public_stance_batch_accepts_the_touchdowns_stance_accepts(name):
    """runtime/validate.L0_SLACK: touchdown leg lengths up to l0 (1 + 1e-12) are round-off of a
    conversion and accepted (as l0); the batch form must agree with the scalar form."""
    params = slipmaps.HUMAN_RUNNER
    td = (params.l0 * (1.0 + 1e-13), *TD[1:])
    one = slipmaps.stance(name, params, td)
    assert one.ok, one.message
    res = slipmaps.stance_batch(name, params, np.array([TD, td]))
    assert res["status"].tolist() == [OK, OK], res.counts()
    assert all(_same(res[c][1], one[c]) for c in res.names)


@pytest.mark.parametrize("name", API_MAPS)
@pytest.mark.parametrize("component", range(4), ids=POLAR)
def test_public_stance_rejects_bad_touchdown_naming_it(name, component):
    params = slipmaps.HUMAN_RUNNER
    values = [NAN, INF, -INF]
    if component == 0:
        values += [0.0, -1.0, 1.5]
    if component == 2:
        values += [HALF_PI, -2.0]
    for bad in values:
        td = list(TD)
        td[component] = bad
        with pytest.raises(ValueError) as exc:
            slipmaps.stance(name, params, td)
        msg = str(exc.value)
        assert re.search(rf"\b{POLAR[component]}\b", msg) and repr(float(bad)) in msg, msg


@pytest.mark.parametrize("name", API_MAPS)
@pytest.mark.parametrize("arg", ["apex_height", "apex_speed", "touchdown_angle", "ground"])
def test_public_apex_return_rejects_bad_apex_naming_it(name, arg):
    """Non-finite inputs, a negative apex height and |angle| >= pi/2 (a negative speed runs toward
    -x and any finite ground is a step up or down: both valid)."""
    params = slipmaps.HUMAN_RUNNER
    domain = {"apex_height": [-1e-9, -1.0], "touchdown_angle": [HALF_PI, -2.0]}
    for bad in [NAN, INF, -INF, *domain.get(arg, [])]:
        kwargs = {"apex_height": 1.0, "apex_speed": 5.0, "touchdown_angle": 0.35, "ground": 0.0, arg: bad}
        with pytest.raises(ValueError) as exc:
            slipmaps.apex_return(name, params, **kwargs)
        msg = str(exc.value)
        assert arg in msg and repr(float(bad)) in msg, msg


def _api_calls(name: str, **options) -> dict[str, Callable[[], object]]:
    """Each public map function called with valid inputs for map ``name`` and ``options``."""
    p = slipmaps.HUMAN_RUNNER
    one = np.array([TD])
    return {
        "stance": lambda: slipmaps.stance(name, p, TD, **options),
        "stance_batch": lambda: slipmaps.stance_batch(name, p, one, **options),
        "apex_return": lambda: slipmaps.apex_return(name, p, 1.0, 5.0, 0.35, **options),
        "apex_return_batch": lambda: slipmaps.apex_return_batch(
            name, p, np.array([1.0]), np.array([5.0]), np.array([0.35]), **options
        ),
    }


def test_public_unknown_map_names_the_maps():
    for fn, call in _api_calls("no-such-map").items():
        with pytest.raises(ValueError) as exc:
            call()
        msg = str(exc.value)
        assert "no-such-map" in msg and all(n in msg for n in API_MAPS), (fn, msg)
    with pytest.raises(ValueError, match="no-such-map"):
        slipmaps.trajectory("no-such-map", slipmaps.HUMAN_RUNNER, TD)


@pytest.mark.parametrize("name", API_MAPS)
def test_public_unknown_option_names_the_options(name):
    valid = [o.name for o in next(m for m in slipmaps.maps() if m.name == name).options]
    for fn, call in _api_calls(name, no_such_option=1).items():
        with pytest.raises(ValueError) as exc:
            call()
        msg = str(exc.value)
        named = valid or ["none"]
        assert "no_such_option" in msg and all(v in msg for v in named), (fn, msg)


def _bad_option_values(option) -> list[tuple[object, list[str]]]:
    """(bad value, what the message must name): the valid choices, or the valid range."""
    if option.kind == "choice":
        return [("no-such-choice", list(option.choices)), (0, list(option.choices))]
    bounds = [f"{option.low:g}", f"{option.high:g}"]
    bad = [
        (option.high * 2.0 + 1.0, bounds),
        (option.low - 1.0, bounds),
        (math.nan, ["finite"]),
        ("x", ["number"]),
    ]
    if option.kind == "int":
        bad.append((option.low + 0.5, ["whole"]))
    return bad


@pytest.mark.parametrize(
    ("name", "option"),
    [pytest.param(name, option, id=f"{name}-{option.name}") for name, option in API_OPTIONS],
)
def test_public_bad_option_value_names_the_valid_values(name, option):
    for value, named in _bad_option_values(option):
        for fn, call in _api_calls(name, **{option.name: value}).items():
            with pytest.raises(ValueError) as exc:
                call()
            msg = str(exc.value)
            assert option.name in msg and all(s in msg for s in named), (fn, value, msg)


def test_slip_params_negative_mass():
    with pytest.raises(ValueError, match=r"SlipParams\.m .*-1\b"):
        slipmaps.SlipParams(m=-1)


@SETTINGS
@given(
    field=st.sampled_from(["m", "l0", "k_c", "k_d", "g_s", "g_f", "q_r_td", "q_r_lo"]),
    bad=st.one_of(st.sampled_from((NAN, INF, -INF, 0.0, -0.0)), st.floats(-1e6, 0.0)),
)
def test_slip_params_reject_bad_values_naming_them(field, bad):
    with pytest.raises(ValueError) as exc:
        slipmaps.SlipParams(**{field: bad})
    msg = str(exc.value)
    assert f"SlipParams.{field}" in msg and repr(float(bad)) in msg, msg


@SETTINGS
@given(field=st.sampled_from(["q_r_td", "q_r_lo"]), excess=st.floats(1e-9, 10.0))
def test_slip_params_reject_leg_longer_than_l0(field, excess):
    bad = 1.0 + excess
    with pytest.raises(ValueError) as exc:
        slipmaps.SlipParams(l0=1.0, **{field: bad})
    assert field in str(exc.value) and repr(bad) in str(exc.value)


# ----------------------------------------------------------------------------------------------
# Regressions: cases that used to raise or report non-finite outputs as OK
# ----------------------------------------------------------------------------------------------
def _env(kernel: Kernel, **values) -> dict:
    return {**default_options(kernel.row), **values}


STANCE_LIKE = ROLE["stance"] + ROLE["state_at"]


@pytest.mark.parametrize("kernel", STANCE_LIKE, ids=_ids(STANCE_LIKE))
def test_regression_leg_collapse_is_a_fall(kernel):
    # k/m = 16 = 2 g_s + q_rd_td^2 with q_thd_td = 0: Geyer's approximate bottom leg length
    # l0 (1 + a - b) is exactly 0 (it used to divide by zero in b_q_thd = omega / 0**2).
    env = _env(kernel, t=0.1, q_r_td=1.0, q_rd_td=-2.0, q_th_td=0.0, q_thd_td=0.0, m=0.5, l0=1.0)
    env.update(k=8.0, k_c=8.0, k_d=8.0, g_s=6.0, q_r_lo=1.0)
    assert check_contract(kernel, kernel.call(env)) == Status.FALL


@pytest.mark.parametrize("kernel", STANCE_LIKE, ids=_ids(STANCE_LIKE))
def test_regression_negative_bottom_leg_length_is_a_fall(kernel):
    # Soft leg (k = 5 kN/m), hard landing (q_rd_td = -8 m/s): the approximate leg would pass through
    # the toe (Geyer's bottom q_r = -0.13 m); it used to be reported OK.
    env = _env(kernel, t=0.1, q_r_td=1.0, q_rd_td=-8.0, q_th_td=0.1, q_thd_td=-1.0, m=80.0, l0=1.0)
    env.update(k=5000.0, k_c=5000.0, k_d=5000.0, g_s=9.81, q_r_lo=1.0)
    assert check_contract(kernel, kernel.call(env)) == Status.FALL


@pytest.mark.parametrize("kernel", STANCE_LIKE, ids=_ids(STANCE_LIKE))
def test_regression_underflow_is_a_status(kernel):
    # omega0^2 = k/m underflows to 0; it used to raise ZeroDivisionError (measured: FALL everywhere).
    env = _env(kernel, t=0.1, q_r_td=1.0, q_rd_td=-0.5, q_th_td=0.3, q_thd_td=0.0, m=1e300, l0=1.0)
    env.update(k=1e-300, k_c=1e-300, k_d=1e-300, g_s=9.81, q_r_lo=1.0)
    assert check_contract(kernel, kernel.call(env)) != Status.OK


@pytest.mark.parametrize(
    ("name", "args"),
    [
        ("liftoff_to_apex", (1.0, 1e200, -0.1, 0.0, 9.81, 1.0)),
        ("apex_to_touchdown", (1.0, 1e300, 0.3, 1e-10, 9.81, 0.0, 0.0)),
    ],
)
def test_regression_flight_overflow_is_numerical_range(name, args):
    # These used to return inf / NaN outputs with status OK.
    kernel = next(k for k in FLIGHT_KERNELS if k.name == name)
    assert (
        check_contract(kernel, kernel.call(dict(zip(kernel.args, args, strict=True))))
        == Status.NUMERICAL_RANGE
    )


@pytest.mark.parametrize("kernel", ROLE["state_at"], ids=_ids(ROLE["state_at"]))
def test_regression_state_at_overflow(kernel):
    env = _env(kernel, q_r_td=1.0, q_th_td=0.3, q_thd_td=-3.0, m=80.0, l0=1.0, g_s=9.81, q_r_lo=1.0)
    env.update(k=20000.0, k_c=20000.0, k_d=20000.0)
    # t = 1e308 s: the phase overflows; it used to return inf / NaN with status OK.
    assert check_contract(kernel, kernel.call({**env, "t": 1e308, "q_rd_td": -0.5})) == Status.NUMERICAL_RANGE
    # q_rd_td = -1e200 m/s: the approximate leg collapses through the toe before anything overflows.
    assert check_contract(kernel, kernel.call({**env, "t": 0.1, "q_rd_td": -1e200})) == Status.FALL


@pytest.mark.parametrize("name", API_MAPS)
def test_public_vertical_hop_is_a_valid_gait(name):
    """Apex speed 0, leg vertical: every map hops in place (OK, not LIFTOFF_BACKWARD), at speed 0
    (measured: exactly 0 for every map) to about the same apex (measured relative change: 7.4e-16
    for the approximate maps, 8.0e-12 for the exact one)."""
    for params in (slipmaps.HUMAN_RUNNER, slipmaps.ROBOT_HOPPER):
        h = 1.2 * params.l0
        res = slipmaps.apex_return(name, params, h, 0.0, 0.0)
        assert res.status == Status.OK, res.message
        assert abs(res.next_apex_speed) <= 1e-12 and res.next_apex_height == pytest.approx(h, rel=1e-10)
