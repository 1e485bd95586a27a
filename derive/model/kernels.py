"""Kernels of the SLIP model itself: the exact simulator's vector fields and coordinate maps
(``generated/slip_model.py``) and the exact ballistic flight between apex and stance events
(``generated/flight.py``). Every formula comes from :mod:`.mechanics` or :mod:`.flight`.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ..catalog import PARAMS
from ..ir import Arg, Call, Field, Group, Kernel, Layout, Module, Stage, real, sym
from ..symbols import b_x, b_xd, b_y, b_yd, k, q_r, q_rd, q_th, q_thd
from . import mechanics, simulation
from .flight import flight_kernels

_STIFFNESS = Arg(k, "leg stiffness k [N/m] (k_c while compressing, k_d after the bottom)")
_MODEL_PARAMS = (PARAMS["m"], PARAMS["l0"], _STIFFNESS, PARAMS["g_s"])
_POLAR_ARGS = (
    Arg(q_r, "leg length q_r [m]"),
    Arg(q_rd, "leg length rate q_rd [m/s]"),
    Arg(q_th, "leg angle q_th from the vertical, counterclockwise positive [rad]"),
    Arg(q_thd, "leg angle rate q_thd [rad/s]"),
)
_CARTESIAN_ARGS = (
    Arg(b_x, "horizontal body position relative to the toe b_x [m]"),
    Arg(b_xd, "horizontal body velocity b_xd [m/s]"),
    Arg(b_y, "body height above the toe b_y [m]"),
    Arg(b_yd, "vertical body velocity b_yd [m/s]"),
)


def _plain(name, summary, equations, args, fields, exprs) -> Kernel:
    """A kernel with one stage, no checks and no status (vector fields and coordinate maps)."""
    outputs = Group("", tuple(Field(n, d, u) for n, d, u in fields))
    return Kernel(
        name=name,
        summary=summary,
        equations=equations,
        args=args,
        steps=(Stage(tuple(zip((sym(n) for n in outputs.names()), exprs, strict=True))),),
        outputs=outputs,
        status=False,
        check_inputs=False,
        module="slip_model",
    )


#: The polar state, component by component: its unit and its rate's.
_STATE = (
    ("q_r", "m", "m/s"),
    ("q_rd", "m/s", "m/s^2"),
    ("q_th", "rad", "rad/s"),
    ("q_thd", "rad/s", "rad/s^2"),
)


def _stance_polar_tangent() -> Kernel:
    """The variational equations' right-hand side for one column s of the sensitivity S = dy/dw of
    the polar stance state: ds/dt = J s + f_k s_k, J = d(stance_polar_rhs)/d(state) and f_k =
    d(stance_polar_rhs)/dk, s_k = dk/dw (1 for the stiffness's own column, else 0). Written out,
    the Jacobian's structural zeros and ones dropped (the exact simulator's Jacobian carries six
    columns through every stage of its integration: generated/exact_stance.py)."""
    rhs = sp.Matrix(mechanics.stance_polar_rhs())
    states = (q_r, q_rd, q_th, q_thd)
    column = [sym(f"s_{name}") for name, _, _ in _STATE]
    s_k = sym("s_k")
    tangent = rhs.jacobian(states) * sp.Matrix(column) + sp.diff(rhs, k) * s_k
    args = tuple(
        Arg(c, f"d{name}/dw, the state's sensitivity to an input w [{unit} per unit of w]")
        for c, (name, unit, _) in zip(column, _STATE, strict=True)
    ) + (Arg(s_k, "dk/dw, the stiffness's sensitivity to w (1 for w = k, else 0) [N/m per unit of w]"),)
    fields = [(f"ds_{name}", f"d/dt of d{name}/dw", f"{rate} per unit of w") for name, _, rate in _STATE]
    return _plain(
        "stance_polar_tangent",
        "Variational equations of the polar stance field: d/dt (dy/dw) = J dy/dw + (df/dk) dk/dw.",
        ("2", "3", "sec2.2.1-polar"),
        _POLAR_ARGS + args + _MODEL_PARAMS,
        fields,
        list(tangent),
    )


_DAMPER_PARAMS = (PARAMS["m"], PARAMS["c"])


def _stance_polar_damping() -> Kernel:
    """The leg damper's term of the polar stance field (:func:`.mechanics.stance_polar_damping`): the
    damped field is ``stance_polar_rhs`` plus it (the exact simulator adds it only for c != 0, so a
    lossless leg's arithmetic is the report's)."""
    return _plain(
        "stance_polar_damping",
        "The leg damper's term of the polar stance field: the damped field minus the lossless one.",
        ("sec2.2.1-damped",),
        _POLAR_ARGS + _DAMPER_PARAMS,
        [(f"damping_{name}", f"the damper's term of d{name}/dt", rate) for name, _, rate in _STATE],
        mechanics.stance_polar_damping(),
    )


def _stance_polar_damping_tangent() -> Kernel:
    """The leg damper's term of the variational equations for one column s of S = dy/dw: J_D s +
    (dD/dc) s_c, D the damper's term of the field (:func:`_stance_polar_damping`), s_c = dc/dw."""
    term = sp.Matrix(mechanics.stance_polar_damping())
    states = (q_r, q_rd, q_th, q_thd)
    column = [sym(f"s_{name}") for name, _, _ in _STATE]
    s_c = sym("s_c")
    tangent = term.jacobian(states) * sp.Matrix(column) + sp.diff(term, PARAMS["c"].symbol) * s_c
    args = tuple(
        Arg(col, f"d{name}/dw, the state's sensitivity to an input w [{unit} per unit of w]")
        for col, (name, unit, _) in zip(column, _STATE, strict=True)
    ) + (Arg(s_c, "dc/dw, the damping's sensitivity to w (1 for w = c, else 0) [N s/m per unit of w]"),)
    fields = [
        (f"ds_{name}", f"the damper's term of d/dt of d{name}/dw", f"{rate} per unit of w")
        for name, _, rate in _STATE
    ]
    return _plain(
        "stance_polar_damping_tangent",
        "The leg damper's term of the variational equations: J_D dy/dw + (dD/dc) dc/dw.",
        ("sec2.2.1-damped",),
        _POLAR_ARGS + args + _DAMPER_PARAMS,
        fields,
        list(tangent),
    )


def _periods(k_: sp.Basic) -> tuple[sp.Basic, sp.Basic]:
    """The stance's natural periods [s]: the spring's 2 pi sqrt(m/k) and the pendulum's 2 pi sqrt(l0/g_s)."""
    m, l0, g_s = (PARAMS[n].symbol for n in ("m", "l0", "g_s"))
    return 2 * sp.pi * sp.sqrt(m / k_), 2 * sp.pi * sp.sqrt(l0 / g_s)


def _simulation_kernels() -> tuple[Kernel, ...]:
    """The exact simulator's step cap and stance time limit (derive/model/simulation.py)."""
    k_c, k_d = PARAMS["k_c"].symbol, PARAMS["k_d"].symbol
    spring, pendulum = _periods(k)
    softer, _ = _periods(sp.Min(real(k_c), real(k_d)))
    return (
        _plain(
            "max_step",
            "The step cap of a stance subphase with stiffness k: MAX_STEP_FRACTION of the shorter natural "
            "period.",
            (),
            _MODEL_PARAMS,
            [("step", "the largest step of the integration", "s")],
            (simulation.MAX_STEP_FRACTION * sp.Min(spring, pendulum),),
        ),
        _plain(
            "stance_time_limit",
            "The stance time limit: T_MAX_PERIODS times the spring period of the softer spring plus the "
            "pendulum period.",
            (),
            (PARAMS["m"], PARAMS["l0"], PARAMS["k_c"], PARAMS["k_d"], PARAMS["g_s"]),
            [("t_max", "the stance time limit", "s")],
            (simulation.T_MAX_PERIODS * (softer + pendulum),),
        ),
    )


@cache
def slip_model_kernels() -> tuple[Kernel, ...]:
    """Equations of motion, energy, coordinate maps and the settings of the exact simulator."""
    return _simulation_kernels() + (
        _plain(
            "stance_polar_rhs",
            "Polar stance vector field d/dt (q_r, q_rd, q_th, q_thd) from the Euler-Lagrange equations.",
            ("1", "2", "3", "sec2.2.1-polar"),
            _POLAR_ARGS + _MODEL_PARAMS,
            [
                ("d_q_r", "dq_r/dt", "m/s"),
                ("d_q_rd", "d^2q_r/dt^2", "m/s^2"),
                ("d_q_th", "dq_th/dt", "rad/s"),
                ("d_q_thd", "d^2q_th/dt^2", "rad/s^2"),
            ],
            mechanics.stance_polar_rhs(),
        ),
        _stance_polar_tangent(),
        _stance_polar_damping(),
        _stance_polar_damping_tangent(),
        _plain(
            "stance_cartesian_rhs",
            "Cartesian stance vector field d/dt (b_x, b_xd, b_y, b_yd), toe at the origin on flat ground.",
            ("sec2.2.1-cartesian",),
            _CARTESIAN_ARGS + _MODEL_PARAMS,
            [
                ("d_b_x", "db_x/dt", "m/s"),
                ("d_b_xd", "d^2b_x/dt^2", "m/s^2"),
                ("d_b_y", "db_y/dt", "m/s"),
                ("d_b_yd", "d^2b_y/dt^2", "m/s^2"),
            ],
            mechanics.stance_cartesian_rhs(),
        ),
        _plain(
            "stance_energy",
            "Total stance energy, the Hamiltonian (27) evaluated at p_r = m q_rd, p_th = m q_r^2 q_thd.",
            ("27",),
            _POLAR_ARGS + _MODEL_PARAMS,
            [("energy", "total mechanical energy E (gravity potential zero at toe height)", "J")],
            (mechanics.stance_energy(),),
        ),
        _plain(
            "polar_to_cartesian",
            "Polar stance state -> Cartesian body state relative to the toe.",
            ("sec2.2-coordinates",),
            _POLAR_ARGS,
            [
                ("out_b_x", "b_x = -q_r sin q_th", "m"),
                ("out_b_xd", "b_xd", "m/s"),
                ("out_b_y", "b_y = q_r cos q_th", "m"),
                ("out_b_yd", "b_yd", "m/s"),
            ],
            mechanics.polar_to_cartesian(),
        ),
        _plain(
            "cartesian_to_polar",
            "Cartesian body state relative to the toe -> polar stance state (inverse of polar_to_cartesian).",
            ("sec2.2-coordinates",),
            _CARTESIAN_ARGS,
            [
                ("out_q_r", "q_r", "m"),
                ("out_q_rd", "q_rd", "m/s"),
                ("out_q_th", "q_th = atan2(-b_x, b_y)", "rad"),
                ("out_q_thd", "q_thd", "rad/s"),
            ],
            mechanics.cartesian_to_polar(),
        ),
    )


def role_form(kernel: Kernel, module: str = "model") -> Kernel:
    """``kernel`` as a role kernel ``<name>_entry`` of module ``module``: ``x`` all its arguments in
    order, an empty parameter record, its outputs into ``out`` (every one checked to be finite),
    for the runtime to call by name (the generated index's ``MODEL``)."""
    return Kernel(
        name=f"{kernel.name}_entry",
        summary=kernel.summary,
        equations=kernel.equations,
        args=kernel.args,
        steps=(
            Call(
                kernel,
                {a.name: a.symbol for a in kernel.args},
                {n: n for n in kernel.output_names},
                comment=f"{kernel.module}.{kernel.name}",
            ),
        ),
        outputs=kernel.outputs,
        layout=Layout(kernel.arg_names, ()),
        module=module,
        check_inputs=False,
        doc_args=f"those of {kernel.module}.{kernel.name}, in x.",
    )


@cache
def public_kernels() -> dict[str, Kernel]:
    """The model's kernels the runtime calls by name (flights, equations of motion, energy,
    coordinate maps, the bottom of (153)), each as a role kernel (:func:`role_form`)."""
    from ..maps.geyer_vs import quartic_kernel

    flights = flight_kernels()
    model = {k.name: k for k in slip_model_kernels()}
    chosen = [
        flights["apex_to_touchdown"],
        flights["liftoff_to_apex"],
        model["stance_polar_rhs"],
        model["stance_cartesian_rhs"],
        model["stance_energy"],
        model["polar_to_cartesian"],
        model["cartesian_to_polar"],
        model["max_step"],
        model["stance_time_limit"],
        quartic_kernel(),
    ]
    return {k.name: role_form(k) for k in chosen}


#: The module of the public model kernels (generated after the maps: it calls one of geyer_vs).
PUBLIC = Module(
    "model",
    "The model's kernels the runtime calls by name (the index's MODEL), as role kernels.",
    "derive/model/kernels.py",
    lambda: tuple(public_kernels().values()),
)

MODULES = (
    Module(
        "slip_model",
        "SLIP stance equations of motion, energy and polar <-> Cartesian maps (report eqs 1-3, 27, sec 2.2).",
        "derive/model/mechanics.py",
        slip_model_kernels,
    ),
    Module(
        "flight",
        "Exact ballistic flight between apex, touchdown and liftoff (report sections 2.1, 2.2.2).",
        "derive/model/flight.py",
        lambda: tuple(flight_kernels().values()),
    ),
)
