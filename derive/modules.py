"""Which kernels go into which generated module: the specs that ``slipmaps generate`` renders.

Each builder turns derived SymPy expressions into :class:`~.kernel.Kernel` specs; nothing here
types a formula that :mod:`.mechanics`, :mod:`.flight` or :mod:`.geyer` did not derive.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from . import flight, geyer, mechanics
from .kernel import Arg, Guard, Kernel, Output, Stage, positive, real
from .symbols import (
    b,
    b_x,
    b_xd,
    b_xd_apex,
    b_y,
    b_y_apex,
    b_yd,
    g_f,
    g_s,
    k,
    l0,
    m,
    q_r,
    q_r_lo,
    q_r_td,
    q_rd,
    q_rd_td,
    q_th,
    q_th_td,
    q_thd,
    q_thd_td,
)

PARAM_ARGS = (
    Arg(m, "body mass m [kg]"),
    Arg(l0, "rest leg length l0 [m]"),
    Arg(k, "leg stiffness k [N/m] (k_c while compressing, k_d after the bottom)"),
    Arg(g_s, "gravitational acceleration in stance g_s [m/s^2], positive"),
)
POLAR_ARGS = (
    Arg(q_r, "leg length q_r [m]"),
    Arg(q_rd, "leg length rate q_rd [m/s]"),
    Arg(q_th, "leg angle q_th from the vertical, counterclockwise positive [rad]"),
    Arg(q_thd, "leg angle rate q_thd [rad/s]"),
)
CARTESIAN_ARGS = (
    Arg(b_x, "horizontal body position relative to the toe b_x [m]"),
    Arg(b_xd, "horizontal body velocity b_xd [m/s]"),
    Arg(b_y, "body height above the toe b_y [m]"),
    Arg(b_yd, "vertical body velocity b_yd [m/s]"),
)


def _sym(name: str) -> sp.Symbol:
    return sp.Symbol(name, real=True)


def _outputs(names_docs):
    return tuple(Output(_sym(n), d) for n, d in names_docs)


def _plain(name, summary, equations, args, names_docs, exprs, notes=""):
    """A kernel with one stage, no guards and no status (pure vector fields and coordinate maps)."""
    outs = _outputs(names_docs)
    return Kernel(
        name=name,
        summary=summary,
        equations=equations,
        args=args,
        stages=(Stage(tuple(zip((o.symbol for o in outs), exprs, strict=True))),),
        outputs=outs,
        with_status=False,
        batch=False,
        check_finite_inputs=False,
        notes=notes,
    )


def slip_model_kernels() -> tuple[Kernel, ...]:
    """Equations of motion, energy and coordinate maps used by the exact simulator."""
    return (
        _plain(
            "stance_polar_rhs",
            "Polar stance vector field d/dt (q_r, q_rd, q_th, q_thd) from the Euler-Lagrange equations.",
            ("1", "2", "3", "sec2.2.1-polar"),
            POLAR_ARGS + PARAM_ARGS,
            [
                ("d_q_r", "dq_r/dt [m/s]"),
                ("d_q_rd", "d^2q_r/dt^2 [m/s^2]"),
                ("d_q_th", "dq_th/dt [rad/s]"),
                ("d_q_thd", "d^2q_th/dt^2 [rad/s^2]"),
            ],
            mechanics.stance_polar_rhs(),
        ),
        _plain(
            "stance_cartesian_rhs",
            "Cartesian stance vector field d/dt (b_x, b_xd, b_y, b_yd), toe at the origin on flat ground.",
            ("sec2.2.1-cartesian",),
            CARTESIAN_ARGS + PARAM_ARGS,
            [
                ("d_b_x", "db_x/dt [m/s]"),
                ("d_b_xd", "d^2b_x/dt^2 [m/s^2]"),
                ("d_b_y", "db_y/dt [m/s]"),
                ("d_b_yd", "d^2b_y/dt^2 [m/s^2]"),
            ],
            mechanics.stance_cartesian_rhs(),
        ),
        _plain(
            "stance_energy",
            "Total stance energy, the Hamiltonian (27) evaluated at p_r = m q_rd, p_th = m q_r^2 q_thd.",
            ("27",),
            POLAR_ARGS + PARAM_ARGS,
            [("energy", "total mechanical energy E [J] (gravity potential zero at toe height)")],
            (mechanics.stance_energy(),),
        ),
        _plain(
            "polar_to_cartesian",
            "Polar stance state -> Cartesian body state relative to the toe.",
            ("sec2.2-coordinates",),
            POLAR_ARGS,
            [
                ("out_b_x", "b_x = -q_r sin q_th [m]"),
                ("out_b_xd", "b_xd [m/s]"),
                ("out_b_y", "b_y = q_r cos q_th [m]"),
                ("out_b_yd", "b_yd [m/s]"),
            ],
            mechanics.polar_to_cartesian(),
        ),
        _plain(
            "cartesian_to_polar",
            "Cartesian body state relative to the toe -> polar stance state (inverse of polar_to_cartesian).",
            ("sec2.2-coordinates",),
            CARTESIAN_ARGS,
            [
                ("out_q_r", "q_r [m]"),
                ("out_q_rd", "q_rd [m/s]"),
                ("out_q_th", "q_th = atan2(-b_x, b_y) [rad]"),
                ("out_q_thd", "q_thd [rad/s]"),
            ],
            mechanics.cartesian_to_polar(),
        ),
    )


def flight_kernels() -> tuple[Kernel, ...]:
    """Ballistic flight between apex and stance events (exact in every apex-return map)."""
    atd = flight.apex_to_touchdown()
    drop = atd["drop_symbol"]
    r_out, rd_out, th_out, thd_out = atd["state"]
    apex_to_td = Kernel(
        name="apex_to_touchdown",
        summary="Ballistic descent from an apex to touchdown with the leg held at (q_th_td, q_r_td).",
        equations=("sec2.1-touchdown", "sec2.2.2"),
        args=(
            Arg(b_y_apex, "apex height of the body above the ground [m]"),
            Arg(b_xd_apex, "horizontal apex speed [m/s]"),
            Arg(q_th_td, "touchdown leg angle from the vertical, counterclockwise positive [rad]"),
            Arg(q_r_td, "touchdown leg length [m]"),
            Arg(g_f, "gravitational acceleration in flight g_f [m/s^2], positive"),
        ),
        extra_input_guards=(
            Guard(
                sp.And(positive(q_r_td, g_f), real(b_y_apex) >= 0, sp.Abs(q_th_td) < sp.pi / 2),
                "INVALID_INPUT",
            ),
        ),
        stages=(
            Stage(
                ((drop, atd["drop"]),),
                (Guard(real(drop) > 0, "APEX_TOO_LOW", "touchdown height below apex"),),
            ),
            Stage(
                (
                    (_sym("td_q_r"), r_out),
                    (_sym("td_q_rd"), rd_out),
                    (_sym("td_q_th"), th_out),
                    (_sym("td_q_thd"), thd_out),
                    (_sym("t_flight"), atd["t_flight"]),
                ),
                comment="touchdown state from the derived Cartesian -> polar map",
            ),
        ),
        outputs=_outputs(
            [
                ("td_q_r", "touchdown leg length [m]"),
                ("td_q_rd", "touchdown leg length rate [m/s]"),
                ("td_q_th", "touchdown leg angle [rad]"),
                ("td_q_thd", "touchdown leg angle rate [rad/s]"),
                ("t_flight", "time from apex to touchdown [s]"),
            ]
        ),
    )
    lta = flight.liftoff_to_apex()
    cart = tuple(zip((b_x, b_xd, b_y, b_yd), lta["liftoff_cartesian"], strict=True))
    lo_to_apex = Kernel(
        name="liftoff_to_apex",
        summary="Ballistic ascent from a polar liftoff state to the next apex.",
        equations=("sec2.1-apex", "sec2.2.2"),
        args=POLAR_ARGS + (Arg(g_f, "gravitational acceleration in flight g_f [m/s^2], positive"),),
        extra_input_guards=(Guard(positive(q_r, g_f), "INVALID_INPUT"),),
        stages=(
            Stage(
                cart,
                (
                    Guard(b_yd > 0, "LIFTOFF_DOWNWARD", "liftoff requires an upward velocity"),
                    Guard(b_xd > 0, "LIFTOFF_BACKWARD", "the runner moves in +x"),
                ),
                comment="Cartesian liftoff state relative to the toe",
            ),
            Stage(
                (
                    (_sym("apex_b_y"), lta["b_y_apex"]),
                    (_sym("apex_b_xd"), lta["b_xd_apex"]),
                    (_sym("t_flight"), lta["t_flight"]),
                    (_sym("dx_flight"), lta["dx_flight"]),
                ),
                comment="apex where b_yd(t) = 0",
            ),
        ),
        outputs=_outputs(
            [
                ("apex_b_y", "next apex height above the ground [m]"),
                ("apex_b_xd", "next apex horizontal speed [m/s]"),
                ("t_flight", "time from liftoff to the apex [s]"),
                ("dx_flight", "horizontal distance travelled from liftoff to the apex [m]"),
            ]
        ),
    )
    return (apex_to_td, lo_to_apex)


GEYER_EQS = ("7", "8", "9", "10", "11", "12", "13", "14", "17", "18", "19", "20")


def _geyer_common_stages(with_liftoff: bool):
    """Stages shared by the Geyer kernels: (7)-(8) at touchdown, (9)-(11) parameters, guards."""
    td = geyer.touchdown_parameters()
    om0 = sp.Symbol("omega0", positive=True)
    omega, epsilon = sp.Symbol("omega", real=True), sp.Symbol("epsilon", real=True)
    w_hat, a_, b2 = sp.Symbol("omega0_hat", positive=True), sp.Symbol("a", real=True), sp.Symbol("b2")
    b_, s_td, s_lo = sp.Symbol("b", real=True), sp.Symbol("s_td", real=True), sp.Symbol("s_lo", real=True)
    sol = geyer.radial_solution_parameters()
    stages = [
        Stage(
            ((om0, td["omega0"]), (omega, td["omega"])),
            (Guard(q_rd_td < 0, "TOUCHDOWN_NOT_COMPRESSING", "stance starts compressing"),),
            comment="eq (7) at touchdown: omega0 = sqrt(k / m), omega = p_th / (m l0^2)",
        ),
        Stage(((epsilon, td["epsilon"]),), comment="eq (8) at touchdown: epsilon = 2 E / (m l0^2)"),
        Stage(
            ((w_hat, sol["omega0_hat"]), (a_, sol["a"]), (b2, sol["b2"])),
            (Guard(b2 > 0, "NO_REAL_SOLUTION", "eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0"),),
            comment="eq (9)-(11): frequency, offset, squared amplitude of rho(t) = a + b sin(omega0_hat t)",
        ),
    ]
    ratios = [(b_, sp.sqrt(b2)), (s_td, geyer.leg_length_ratio(q_r_td).subs(b, b_))]
    guards = [
        Guard(1 + a_ - b_ > 0, "FALL", "the leg collapses: bottom leg length l0 (1 + a - b) <= 0"),
        Guard(sp.Abs(s_td) <= 1, "TOUCHDOWN_OUTSIDE_OSCILLATION", "eq (12) needs |s_td| <= 1"),
    ]
    if with_liftoff:
        ratios.append((s_lo, geyer.leg_length_ratio(q_r_lo).subs(b, b_)))
        guards.append(Guard(sp.Abs(s_lo) <= 1, "NO_LIFTOFF", "eq (14) needs |s_lo| <= 1"))
    stages.append(
        Stage(tuple(ratios), tuple(guards), comment="eq (12)-(14): sin(phase) at touchdown/liftoff")
    )
    return stages, {"s_td": s_td, "s_lo": s_lo, "omega": omega, "omega0_hat": w_hat, "a": a_, "b": b_}


def _geyer_state_at_phase(phase, ph_td, sym):
    """(q_r, q_rd, q_th, q_thd) at a phase omega0_hat t of (11), (19) and (17)."""
    w_hat, omega = sym["omega0_hat"], sym["omega"]
    subs = {geyer.omega0_hat: w_hat, geyer.a: sym["a"], geyer.b: sym["b"], geyer.omega: omega}
    rho_t = geyer.radial_solution(phase / w_hat).subs(subs)
    rho_d = sp.diff(geyer.radial_solution(), geyer.t).subs(geyer.t, phase / geyer.omega0_hat).subs(subs)
    th_expr, t_td = geyer.leg_angle()
    q_th_t = th_expr.subs({geyer.t: phase / geyer.omega0_hat, t_td: ph_td / geyer.omega0_hat}).subs(subs)
    exact_rate, _ = geyer.angular_rate()
    return (l0 * (1 + rho_t), l0 * rho_d, q_th_t, exact_rate.subs(geyer.rho, rho_t).subs(subs))


STANCE_TD_ARGS = (
    Arg(q_r_td, "touchdown leg length q_r_td [m], 0 < q_r_td <= l0"),
    Arg(q_rd_td, "touchdown leg length rate q_rd_td [m/s], negative (compressing)"),
    Arg(q_th_td, "touchdown leg angle q_th_td [rad], |q_th_td| < pi/2"),
    Arg(q_thd_td, "touchdown leg angle rate q_thd_td [rad/s]"),
)
_PARAM_GUARD = Guard(
    sp.And(positive(m, l0, k, g_s, q_r_td), real(q_r_td) <= real(l0), sp.Abs(q_th_td) < sp.pi / 2),
    "INVALID_INPUT",
)


def geyer_kernels() -> tuple[Kernel, ...]:
    """Geyer et al.'s stance map (section 3.1) from a general touchdown state to bottom and liftoff."""
    stages, sym = _geyer_common_stages(with_liftoff=True)
    ph = geyer.event_phases()
    ph_td = ph["touchdown"].subs(ph["s"], sym["s_td"])
    ph_lo = ph["liftoff"].subs(ph["s"], sym["s_lo"])
    ph_b = ph["bottom"]
    w_hat = sym["omega0_hat"]
    b_state = _geyer_state_at_phase(ph_b, ph_td, sym)
    lo_state = _geyer_state_at_phase(ph_lo, ph_td, sym)
    names = ["t_bottom", "t_stance", "b_q_r", "b_q_rd", "b_q_th", "b_q_thd"]
    names += ["lo_q_r", "lo_q_rd", "lo_q_th", "lo_q_thd"]
    exprs = [(ph_b - ph_td) / w_hat, (ph_lo - ph_td) / w_hat, *b_state, *lo_state]
    lo_q_th = _sym("lo_q_th")
    stages.append(
        Stage(
            tuple((_sym(n), e) for n, e in zip(names, exprs, strict=True)),
            (Guard(sp.Abs(lo_q_th) < sp.pi / 2, "FALL", "the leg stays above horizontal"),),
            comment="eq (13)-(14), (19), (17): events, then the bottom and liftoff states",
        )
    )
    docs = [
        "time from touchdown to the bottom (eq 13 - eq 12) [s]",
        "stance time t_lo - t_td (eq 14 - eq 12; eq 20 when q_r_td = q_r_lo = l0) [s]",
        "bottom leg length l0 (1 + a - b) [m]",
        "bottom leg length rate (0 by construction) [m/s]",
        "bottom leg angle, eq (19) [rad]",
        "bottom leg angle rate p_th / (m q_r^2), eq (17) [rad/s]",
        "liftoff leg length (= q_r_lo) [m]",
        "liftoff leg length rate l0 b omega0_hat cos(phase_lo), from (11) [m/s]",
        "liftoff leg angle, eq (19) [rad]",
        "liftoff leg angle rate p_th / (m q_r_lo^2), eq (17) [rad/s]",
    ]
    stance = Kernel(
        name="geyer_stance",
        summary="Geyer et al.'s approximate stance map: touchdown state -> bottom and liftoff states.",
        equations=GEYER_EQS,
        args=STANCE_TD_ARGS + PARAM_ARGS + (Arg(q_r_lo, "liftoff leg length q_r_lo [m], 0 < q_r_lo <= l0"),),
        extra_input_guards=(
            Guard(
                sp.And(_PARAM_GUARD.condition, positive(q_r_lo), real(q_r_lo) <= real(l0)), "INVALID_INPUT"
            ),
        ),
        stages=tuple(stages),
        outputs=_outputs(list(zip(names, docs, strict=True))),
        notes=(
            "Assumption 1 (small sweep: angular momentum conserved), Assumption 2 (small compression: "
            "1/(1+rho)^2 ~ 1 - 2 rho + 3 rho^2). Leg-angle rates use the exact (17) with the conserved "
            "angular momentum; the leg angle uses its linearization (18)-(19)."
        ),
    )
    stages_t, sym_t = _geyer_common_stages(with_liftoff=False)
    tt = sp.Symbol("t", real=True)
    ph_td_t = ph["touchdown"].subs(ph["s"], sym_t["s_td"])
    state_t = _geyer_state_at_phase(ph_td_t + sym_t["omega0_hat"] * tt, ph_td_t, sym_t)
    out_t = ["q_r_t", "q_rd_t", "q_th_t", "q_thd_t"]
    stages_t.append(
        Stage(
            tuple((_sym(n), e) for n, e in zip(out_t, state_t, strict=True)),
            comment="eq (11), (19), (17) at t",
        )
    )
    state_at = Kernel(
        name="geyer_stance_state_at",
        summary="Geyer et al.'s approximate stance trajectory: the polar state a time t after touchdown.",
        equations=("11", "17", "19"),
        args=(Arg(tt, "time since touchdown [s], >= 0"),) + STANCE_TD_ARGS + PARAM_ARGS,
        extra_input_guards=(Guard(sp.And(_PARAM_GUARD.condition, real(tt) >= 0), "INVALID_INPUT"),),
        stages=tuple(stages_t),
        outputs=_outputs(
            [
                ("q_r_t", "leg length at t, eq (11) [m]"),
                ("q_rd_t", "leg length rate at t [m/s]"),
                ("q_th_t", "leg angle at t, eq (19) [rad]"),
                ("q_thd_t", "leg angle rate at t, eq (17) [rad/s]"),
            ]
        ),
    )
    return (stance, state_at)


@dataclass(frozen=True)
class ModuleSpec:
    """One generated file: its name, docstring, source module and kernel builder."""

    name: str
    doc: str
    source: str
    build: object  # () -> tuple[Kernel, ...]
    depends: tuple[str, ...] = ()
    imports: tuple[str, ...] = ()
    apex_returns: tuple[dict, ...] = ()


MODULES: tuple[ModuleSpec, ...] = (
    ModuleSpec(
        "slip_model",
        "SLIP stance equations of motion, energy and polar <-> Cartesian maps (report eqs 1-3, 27, sec 2.2).",
        "derive/mechanics.py",
        slip_model_kernels,
    ),
    ModuleSpec(
        "flight",
        "Exact ballistic flight between apex, touchdown and liftoff (report sections 2.1, 2.2.2).",
        "derive/flight.py",
        flight_kernels,
    ),
    ModuleSpec(
        "geyer",
        "Geyer et al.'s approximate stance map and apex-return map (report section 3.1, eqs 7-26).",
        "derive/geyer.py",
        geyer_kernels,
        depends=("flight",),
        imports=("from .flight import apex_to_touchdown, liftoff_to_apex",),
        apex_returns=(
            {
                "name": "geyer_apex_return",
                "stance": "geyer_stance",
                "summary": "Apex-return map: exact flight, Geyer et al.'s stance map (section 3.1).",
                "params": ["m", "l0", "k", "g_s"],
            },
        ),
    ),
)
