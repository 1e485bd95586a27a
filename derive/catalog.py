"""The names every kernel shares, written once: parameters with their domains and the output groups.

Conventions (README): SI units; leg angle ``q_th`` from the vertical, counterclockwise positive;
polar state ``(q_r, q_rd, q_th, q_thd)``; times in the stance maps run from touchdown. The runtime
reads these names from the generated index (``slipmaps.generated.maps_index``), never restates them.
"""

from __future__ import annotations

import sympy as sp

from . import params, symbols
from .ir import Arg, Field, Group, Guard, positive, real, sym
from .symbols import (
    l0,
    q_rd_td,
    q_th_td,
    q_thd_td,
)

_HALF_PI = sp.pi / 2


def domain(kind: str, s: sp.Symbol) -> sp.Basic | None:
    """The run-time check of a :mod:`.params` domain on symbol ``s`` (None: finite is enough)."""
    x = real(s)
    checks = {
        "positive": positive(s),
        "leg_length": sp.And(positive(s), x <= real(l0)),
        "non_negative": x >= 0,
        "leg_angle": sp.Abs(x) < _HALF_PI,
        "real": None,
    }
    return checks[kind]


def _describe(row: dict) -> str:
    limits = {"leg_length": f", 0 < {row['name']} <= l0", "positive": ", > 0", "non_negative": ", >= 0"}
    return f"{row['doc']} {row['name']} [{row['unit']}]{limits.get(row['domain'], '')}"


def _symbol(name: str) -> sp.Symbol:
    """The symbol of a parameter or an input: derive/symbols.py's (with its assumptions)."""
    return getattr(symbols, name, None) or sym(name)


#: SLIP parameters (report Table 1) as kernel arguments, by name: the rows of :mod:`.params`, and
#: its alias ``k`` (a constant stiffness).
PARAMS: dict[str, Arg] = {
    r["name"]: Arg(_symbol(r["name"]), _describe(r), domain(r["domain"], _symbol(r["name"])))
    for r in params.PARAMETERS
} | {
    name: Arg(_symbol(name), _describe({**a, "name": name, "domain": "positive"}), positive(_symbol(name)))
    for name, a in params.ALIASES.items()
}

#: The parameters in the order of a parameter record (a role kernel's ``p``, :class:`~.ir.Layout`):
#: the table's, each alias just before the first field it sets (``k`` before ``k_c``).
PARAM_ORDER: tuple[str, ...] = tuple(
    name
    for r in params.PARAMETERS
    for name in (*(a for a, row in params.ALIASES.items() if row["sets"][0] == r["name"]), r["name"])
)

#: The polar touchdown state, the first arguments of every stance map.
TOUCHDOWN: tuple[Arg, ...] = (
    PARAMS["q_r_td"],
    Arg(q_rd_td, "touchdown leg length rate q_rd_td [m/s] (negative: compressing)"),
    Arg(q_th_td, "touchdown leg angle q_th_td [rad], |q_th_td| < pi/2", sp.Abs(q_th_td) < _HALF_PI),
    Arg(q_thd_td, "touchdown leg angle rate q_thd_td [rad/s]"),
)

#: Time since touchdown, the first argument of a map's state-at-time kernel.
TIME = Arg(sym("t"), "time since touchdown t [s], >= 0", real(sym("t")) >= 0)

#: The apex-return inputs before the parameters (the rows of :mod:`.params`' ``APEX_INPUTS``): the
#: apex, the touchdown leg angle, the ground.
APEX_ARGS: tuple[Arg, ...] = tuple(
    Arg(_symbol(r["arg"]), _describe({**r, "name": r["arg"]}), domain(r["domain"], _symbol(r["arg"])))
    for r in params.APEX_INPUTS
)
GROUND = next(a for a in APEX_ARGS if a.name == "ground")


def limit(name: str) -> Guard:
    """The guard of an apex-return input's ``limit`` (its row in :mod:`.params`): ``|x| <= sqrt(a/b)``
    as ``x**2 b <= a`` (no square root, no division), else ``INVALID_INPUT``."""
    row = next(r for r in params.APEX_INPUTS if r["name"] == name)
    a, b = row["limit"]["sqrt_ratio"]
    x = _symbol(row["arg"])
    return Guard(
        real(x) ** 2 * real(_symbol(b)) <= real(_symbol(a)),
        "INVALID_INPUT",
        f"|{row['arg']}| <= sqrt({a}/{b}): {row['limit']['why']}",
    )


#: The public name of an apex-return input (the API's argument and Jacobian column) by kernel argument.
APEX_PUBLIC = {r["arg"]: r["name"] for r in params.APEX_INPUTS}

#: The direction of a step, from the sign of its apex speed (+1, -1, or 0 for a hop in place): the
#: liftoff must not move against it (LIFTOFF_BACKWARD).
DIRECTION = Arg(
    sym("direction"),
    "direction of the step: +1 (toward +x), -1 (toward -x) or 0 (a hop in place: either way)",
    sp.Or(
        sp.Eq(real(sym("direction")), 1), sp.Eq(real(sym("direction")), -1), sp.Eq(real(sym("direction")), 0)
    ),
)

POLAR = (
    Field("q_r", "leg length", "m"),
    Field("q_rd", "leg length rate", "m/s"),
    Field("q_th", "leg angle from the vertical, counterclockwise positive", "rad", odd=True),
    Field("q_thd", "leg angle rate", "rad/s", odd=True),
)

#: Outputs of every stance map (a map may append extras).
STANCE = Group(
    "",
    (
        Field("t_bottom", "time from touchdown to the bottom", "s"),
        Field("t_stance", "stance time, touchdown to liftoff", "s"),
        Group("bottom", POLAR, "state at the bottom (q_rd = 0)"),
        Group("liftoff", POLAR, "state at liftoff (q_r = q_r_lo)"),
    ),
)

#: Outputs of every apex-return map (a map may append extras).
APEX_RETURN = Group(
    "",
    (
        Field("apex_height", "next apex height above the ground the foot stood on", "m"),
        Field("apex_speed", "next apex horizontal speed (signed)", "m/s", odd=True),
        Field("t_descent", "flight time from the apex to touchdown", "s"),
        Field("t_stance", "stance time, touchdown to liftoff", "s"),
        Field("t_ascent", "flight time from liftoff to the next apex", "s"),
        Group("liftoff", POLAR, "state at liftoff (q_r = q_r_lo)"),
        Field("step_length", "horizontal distance from the apex to the next apex (signed)", "m", odd=True),
        Field("foot_x", "horizontal position of the foot at touchdown relative to the apex", "m", odd=True),
        Field(
            "foot_y",
            "height of the foot (the touchdown ground) relative to the apex: ground - apex height",
            "m",
        ),
        Field(
            "touchdown_q_th",
            "leg angle the foot touched down with: touchdown_angle + retraction_rate * t_descent",
            "rad",
            odd=True,
        ),
    ),
)

#: Outputs of a map's state-at-time kernel: the polar state a time t after touchdown.
TRAJECTORY = Group("", POLAR)

#: A touchdown leg length counts as the rest length l0 within this relative tolerance (for the
#: choices that assume it, ``Option.at_rest_length``).
REST_LENGTH_TOLERANCE = 1e-9
