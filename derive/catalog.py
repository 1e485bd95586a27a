"""The names every kernel shares, written once: parameters with their domains and the output groups.

Conventions (README): SI units; leg angle ``q_th`` from the vertical, counterclockwise positive;
polar state ``(q_r, q_rd, q_th, q_thd)``; times in the stance maps run from touchdown. The runtime
reads these names from the generated index (``slipmaps.generated.maps_index``), never restates them.
"""

from __future__ import annotations

import sympy as sp

from .ir import Arg, Field, Group, positive, real, sym
from .symbols import (
    b_xd_apex,
    b_y_apex,
    g_f,
    g_s,
    k,
    k_c,
    k_d,
    l0,
    m,
    q_r_lo,
    q_r_td,
    q_rd_td,
    q_th_td,
    q_thd_td,
)

_HALF_PI = sp.pi / 2


def _leg_length(s: sp.Symbol) -> sp.Basic:
    return sp.And(positive(s), real(s) <= real(l0))


#: SLIP parameters (report Table 1) as kernel arguments, by name.
PARAMS: dict[str, Arg] = {
    "m": Arg(m, "body mass m [kg]", positive(m)),
    "l0": Arg(l0, "rest leg length l0 [m]", positive(l0)),
    "k": Arg(k, "leg stiffness k [N/m] (constant: k_c = k_d)", positive(k)),
    "k_c": Arg(k_c, "leg stiffness while compressing k_c [N/m]", positive(k_c)),
    "k_d": Arg(k_d, "leg stiffness after the bottom k_d [N/m]", positive(k_d)),
    "g_s": Arg(g_s, "gravitational acceleration in stance g_s [m/s^2], positive", positive(g_s)),
    "g_f": Arg(g_f, "gravitational acceleration in flight g_f [m/s^2], positive", positive(g_f)),
    "q_r_td": Arg(q_r_td, "touchdown leg length q_r_td [m], 0 < q_r_td <= l0", _leg_length(q_r_td)),
    "q_r_lo": Arg(q_r_lo, "liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0", _leg_length(q_r_lo)),
}

#: The polar touchdown state, the first arguments of every stance map.
TOUCHDOWN: tuple[Arg, ...] = (
    PARAMS["q_r_td"],
    Arg(q_rd_td, "touchdown leg length rate q_rd_td [m/s] (negative: compressing)"),
    Arg(q_th_td, "touchdown leg angle q_th_td [rad], |q_th_td| < pi/2", sp.Abs(q_th_td) < _HALF_PI),
    Arg(q_thd_td, "touchdown leg angle rate q_thd_td [rad/s]"),
)

#: Time since touchdown, the first argument of a map's state-at-time kernel.
TIME = Arg(sym("t"), "time since touchdown t [s], >= 0", real(sym("t")) >= 0)

#: The apex-return inputs before the parameters: the apex and the touchdown leg angle.
APEX_ARGS: tuple[Arg, ...] = (
    Arg(b_y_apex, "apex height of the body above the ground [m], >= 0", real(b_y_apex) >= 0),
    Arg(b_xd_apex, "horizontal apex speed [m/s], >= 0 (the runner moves in +x)", real(b_xd_apex) >= 0),
    TOUCHDOWN[2],
)

POLAR = (
    Field("q_r", "leg length", "m"),
    Field("q_rd", "leg length rate", "m/s"),
    Field("q_th", "leg angle from the vertical, counterclockwise positive", "rad"),
    Field("q_thd", "leg angle rate", "rad/s"),
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
        Field("apex_height", "next apex height above the ground", "m"),
        Field("apex_speed", "next apex horizontal speed", "m/s"),
        Field("t_descent", "flight time from the apex to touchdown", "s"),
        Field("t_stance", "stance time, touchdown to liftoff", "s"),
        Field("t_ascent", "flight time from liftoff to the next apex", "s"),
        Group("liftoff", POLAR, "state at liftoff (q_r = q_r_lo)"),
    ),
)

#: Outputs of a map's state-at-time kernel: the polar state a time t after touchdown.
TRAJECTORY = Group("", POLAR)

#: A touchdown leg length counts as the rest length l0 within this relative tolerance (for the
#: choices that assume it, ``Option.at_rest_length``).
REST_LENGTH_TOLERANCE = 1e-9

#: The index row of ``"exact"``, the numerical ground truth (runtime/exact/compiled.py, with
#: runtime/exact/reference.py as the solve_ivp reference; no generated kernels).
EXACT = {
    "name": "exact",
    "title": "Exact stance by numerical integration (DOP853)",
    "section": "2.2",
    "equations": ["1", "2", "3", "27"],
    "requires": [],
    "params": ["m", "l0", "k_c", "k_d", "g_s"],
    "options": [
        {
            "name": "method",
            "kind": "choice",
            "default": "compiled",
            "doc": "which DOP853 implementation integrates the stance (same algorithm, events and statuses)",
            "choices": [
                {"value": "compiled", "doc": "numba-compiled, batches in parallel"},
                {"value": "scipy", "doc": "scipy's solve_ivp, the reference"},
            ],
            "low": None,
            "high": None,
            "at_rest_length": [],
        },
        {
            "name": "rtol",
            "kind": "float",
            "default": 1e-11,
            "doc": "relative tolerance of the DOP853 integration",
            "choices": [],
            "low": 1e-14,
            "high": 1e-3,
        },
        {
            "name": "atol",
            "kind": "float",
            "default": 1e-12,
            "doc": "absolute tolerance of the DOP853 integration",
            "choices": [],
            "low": 1e-16,
            "high": 1e-3,
        },
    ],
    "summary": "the polar stance equations of motion (2)-(3) integrated with events for the bottom "
    "(k_c -> k_d), liftoff and failures: the ground truth",
    "module": None,
    "kernels": None,
    "extras": [],
}
