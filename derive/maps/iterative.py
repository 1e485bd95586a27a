"""Schwind and Koditschek's iterative stance map in a converging form (report sections 3.2 and 5.2).

The report integrates (30)-(32) over the leg length from the turning point (the bottom), with one
mean-value point per half-stance ((38)-(45), (120)-(151)). Measured, that iteration does not
converge to the exact stance (docs/iterative.md). Two changes make it converge:

1. **Radial momentum from the work of the radial force** instead of the energy inverse (33):
   p_r(sigma)^2 = 2 m int_{q_r_b}^{sigma} F_r ds with F_r = dp_r/dt of (29) (p_r dp_r/dq_r =
   m dp_r/dt). On the exact trajectory both are equal; on an approximate iterate, (33) loses the
   cancellation of the O((sigma - q_r_b)^(1/2)) terms between the potential and the angular
   kinetic energy, so near the bottom its square root goes negative; the work form stays
   O(sigma - q_r_b) and positive whatever the iterate.
2. **N-node Gauss-Legendre collocation in u = sqrt((sigma - q_r_b)/(x - q_r_b))**, whose one-node
   rule is the report's mean value xi = 3/4 q_r_b + 1/4 x of (41) (module :mod:`.quadrature_helpers`). The
   integrands of (30)-(32) in u are regular at the bottom; the iterates are the values at the
   nodes and each pass is a Picard step of Schwind and Koditschek's integral operator.

Each half (:func:`half_kernel`): the compression half runs from the touchdown state with k_c;
its bottom leg length q_r_b = q_r_td - D comes from p_r_td^2 = 2 m int F_r, the spring part
integrated exactly (a quadratic in D) each pass. The decompression half runs from that bottom
state with k_d to q_r = q_r_lo, where p_r_lo^2 = 2 m int F_r. The zeroth iterate is a declared
map's bottom and liftoff states (or the held touchdown/bottom state), linear in u between the
half's ends: the leading behaviour q_th - q_th_b ~ (sigma - q_r_b)^(1/2) of (41).

The leg damping ``c`` (derive/params.py) adds the damper's force -c p_r/m to F_r
(:func:`~.iterative_helpers.damper_force`); d(p_r^2)/dq_r = 2 m F_r holds for any F_r, so the work
form stands, but F_r at a node now depends on p_r there. Each pass takes it at the previous pass's
p_r: a carried node array (the decompression half's Psi, p_r = u sqrt(4 m D Psi); the compression
half's shape Psi/Psi(1), p_r = u p_r_td sqrt(Psi/Psi(1)), so that p_r follows a new D without a
lag). The compression half's D keeps its exact spring part, the damper's work is in the
numerically integrated rest. Option ``liftoff`` is the exact map's (:data:`.exact.LIFTOFF`): with
``"force"`` the decompression half ends where the leg force k_d (l0 - q_r) - c q_rd falls to 0,
D = s^2 from the quadratic in s of :func:`~.iterative_helpers.force_liftoff` with the pass's
W = int_0^1 F_r u du, iterated with the passes, or at q_r_lo if the force there is not negative
(q_r_lo first, or a tie). At c = 0 every term of the damper is 0 and the lossless arithmetic is
untouched: the values are the lossless map's, bit for bit (tests/test_iterative_damped.py).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .. import catalog
from ..halfspec import HalfInputs, HalfSpec
from ..ir import Arg, Call, Field, Group, Guard, Iterate, Kernel, Lookup, Nodes, Reduce, Stage, Step, sym
from ..mapspec import MapBuild, MapInputs, MapSpec, Option
from ..model import mechanics
from ..symbols import g_s, k_c, k_d, l0, m, p_r, p_th, q_r, q_th
from . import quadrature_helpers
from .exact import LIFTOFF
from .iterative_helpers import (
    damper_force,
    force_liftoff,
    held_liftoff,
    leg_length_derivatives,
    liftoff_symbols,
    q_r_b,
    radial_force,
    zeroth_arguments,
    zeroth_bottom,
    zeroth_liftoff,
    zeroth_option,
    zeroth_values,
)

__all__ = ["NODE_COUNTS", "u_rates", "half_kernel", "declare_maps", "declare_halves"]

#: Node counts a kernel is generated for (option ``nodes``).
NODE_COUNTS = (1, 2, 3, 4, 6)

_D, _PSI, _U = sp.symbols("D Psi u", positive=True)


@cache
def u_rates(stiffness: sp.Symbol) -> tuple[sp.Basic, sp.Basic, sp.Basic]:
    """(dt/du, dq_th/du, dp_th/du) for sigma = q_r_b + D u^2, going away from the bottom.

    (30)-(32) times dsigma/du = 2 D u, with p_r = u sqrt(4 m D Psi) (the work form: p_r^2 =
    2 m int_{q_r_b}^{sigma} F_r = 4 m D int_0^u F_r v dv = 4 m D Psi u^2, Psi the F_r-weighted
    mean (1/u^2) int_0^u F_r v dv). The result has no 1/u: regular at the bottom.
    """
    p_r = mechanics.p_r
    momentum = _U * sp.sqrt(4 * m * _D * _PSI)
    rates = leg_length_derivatives(stiffness)
    return tuple(sp.simplify((r * 2 * _D * _U).subs(p_r, momentum)) for r in rates)


def rule_tables(selector: sp.Symbol) -> Lookup:
    """The Gauss-Legendre rules of every node count as data (:mod:`.quadrature_helpers`), chosen by
    option ``nodes``' code: the count ``nq``, the nodes ``u``, the weights ``w`` (of int_0^1) and
    ``w1`` (of int_0^1 v), the integration matrices ``S`` and ``S1`` (of int_0^{u_j})."""
    rules = {NODES.code(str(n)): quadrature_helpers.rule(n) for n in NODE_COUNTS}

    def table(get) -> tuple:
        return tuple((code, get(r)) for code, r in rules.items())

    def vector(v) -> tuple:
        return tuple(float(x) for x in v)

    return Lookup(
        selector,
        (
            ("nq", table(lambda r: float(r.n))),
            ("u", table(lambda r: vector(r.nodes))),
            ("w", table(lambda r: vector(r.w))),
            ("w1", table(lambda r: vector(r.w1))),
            ("S", table(lambda r: tuple(vector(row) for row in r.S))),
            ("S1", table(lambda r: tuple(vector(row) for row in r.S1))),
        ),
        comment="the Gauss-Legendre rule of the node count: nodes u, weights, integration matrices",
    )


def _half_steps(kind: str, a: dict) -> tuple[Step, ...]:
    """Steps of one half-stance (``kind`` "compression" or "decompression"): Picard passes on the
    node values Q_j = q_th(u_j), P_j = p_th(u_j) of the rule chosen by option ``nodes`` (node
    loops over the rule's data: one kernel for every node count)."""
    compress = kind == "compression"
    stiffness = k_c if compress else k_d
    nq, u, D = sym("nq"), sym("_u"), sym("_D")
    Q, P = sym("_Qj"), sym("_Pj")
    th0, pth0 = a["q_th"], m * a["q_r"] ** 2 * a["q_thd"]
    # zeroth iterate: linear in u between the bottom (u = 0) and the far end (u = 1)
    if compress:
        guess_b = m * a["guess_q_r"] ** 2 * a["guess_q_thd"]
        start_q = a["guess_q_th"] + (th0 - a["guess_q_th"]) * u
        start_p = guess_b + (pth0 - guess_b) * u
    else:
        guess_lo = m * catalog.PARAMS["q_r_lo"].symbol ** 2 * a["guess_q_thd"]
        start_q = th0 + (a["guess_q_th"] - th0) * u
        start_p = pth0 + (guess_lo - pth0) * u
    top = a["q_r"]
    F_r, (dt, dq, dp) = radial_force(stiffness), u_rates(stiffness)
    # the carried array's zeroth iterate (the damper's, below): p_r linear in u (shape 1), or Psi
    # near the bottom, p_r^2 = 2 m F_r(bottom) (sigma - q_r_b) = 4 m D (F_r(bottom)/2) u^2
    psi0 = sp.S.One if compress else F_r.subs({q_r: top, q_th: th0, p_th: pth0}) / 2
    if compress:
        d0, base = top - a["guess_q_r"], top - D
    else:
        d0, base = catalog.PARAMS["q_r_lo"].symbol - top, top
    sigma, F, psi, s1f = sym("_sigma"), sym("_F"), sym("_Psi"), sym("_S1F")
    carried = sym("_Psr")
    # The damper's force -c p_r/m at the nodes' p_r from the previous pass: the compression half
    # carries the shape Psi/W (W = Psi(1), p_r^2 = 4 m D Psi u^2 = p_r_td^2 u^2 Psi/W: p_r_td is
    # known, p_r < 0 in time), the decompression half Psi (p_r = u sqrt(4 m D Psi) at this pass's D).
    # Either way p_r does not follow the pass's D with a lag: in the compression half Psi does (Psi(1)
    # = p_r_td^2/(4 m D)), and carrying it made D converge at about 0.35 per pass at 20 % of the
    # critical damping.
    if compress:
        node_p_r = u * m * a["q_rd"] * sp.sqrt(carried)
    else:
        node_p_r = u * sp.sqrt(4 * m * D * carried)
    damper = damper_force().subs(p_r, node_p_r)
    at = {_D: D, _PSI: psi, _U: u, q_r: sigma, q_th: Q, p_th: P}
    # sin Q_j beside cos Q_j (in F_r): one sincos call per node and pass instead of a sin and a cos
    sin_q = sym("_sinQ")
    evaluate = (
        Nodes(
            nq,
            ((Q, "Q"), (P, "P"), (u, "u"), (carried, "Psr")),
            (),
            (
                Stage(
                    (
                        (sigma, base + D * u**2),
                        (F, F_r.subs({q_r: sigma, q_th: Q, p_th: P})),
                        (sin_q, sp.sin(Q)),
                    )
                ),
            ),
            # F_r with the damper's force at the previous pass's p_r (+ 0 at c = 0)
            ((sigma, "sigma"), (F + damper, "F"), (sin_q, "sinQ")),
            comment="node values of the pass: sigma, F_r (29) and the damper's force, sin Q",
        ),
        Nodes(
            nq,
            ((Q, "Q"), (P, "P"), (u, "u"), (sigma, "sigma"), (sin_q, "sinQ")),
            ((s1f, "S1", "F"),),
            (
                Stage(
                    (
                        (psi, s1f / u**2),
                        (sym("_ft"), dt.subs(at)),
                        (sym("_fq"), dq.subs(at)),
                        (sym("_fp"), dp.subs(at).subs(sp.sin(Q), sin_q)),
                    ),
                    (Guard(psi > 0, "IMAGINARY_MOMENTUM", "p_r^2 = 2 m int F_r > 0 at every node"),),
                ),
            ),
            ((sym("_ft"), "ft"), (sym("_fq"), "fq"), (sym("_fp"), "fp"), (psi, "Psi")),
            comment="Psi and the u-rates of (30)-(32) at the nodes",
        ),
    )
    sfq, sfp, wfq, wfp = sym("_Sfq"), sym("_Sfp"), sym("_wfq"), sym("_wfp")
    work_pass = sym("_Wpass")
    if compress:  # from the touchdown end: y(u_j) = y_td + int_{u_j}^1
        new_q, new_p = th0 + wfq - sfq, pth0 + wfp - sfp
        rbar = sym("_rbar")
        spring = Nodes(
            nq,
            ((F, "F"), (sigma, "sigma")),
            (),
            (),
            ((F - stiffness * (l0 - sigma), "G"),),
            comment="F_r minus its spring term",
        )
        b, kinetic = stiffness * (l0 - top) + 2 * rbar, (m * a["q_rd"]) ** 2 / (2 * m)
        new_d = 2 * kinetic / (b + sp.sqrt(b**2 + 2 * stiffness * kinetic))
        update_d = (spring, Reduce(rbar, "w1", "G", nq), Reduce(work_pass, "w1", "F", nq))
    else:  # from the bottom: y(u_j) = y_b + int_0^{u_j}
        new_q, new_p = th0 + sfq, pth0 + sfp
        new_d, update_d = _liftoff_distance(a, top, work_pass), (Reduce(work_pass, "w1", "F", nq),)
    body = (
        Reduce(wfq, "w", "fq", nq),
        Reduce(wfp, "w", "fp", nq),
        *update_d,
        Nodes(
            nq,
            (),
            ((sfq, "S", "fq"), (sfp, "S", "fp")),
            (),
            ((new_q, "Q_next"), (new_p, "P_next")),
            comment="the next iterate at the nodes",
        ),
        Stage(
            ((sym("_D_next"), new_d),),
            comment="D = q_r_td - q_r_b from the radial work"
            if compress
            else "D = q_r_lo - q_r_b, or to the leg force's zero (liftoff force)",
        ),
    )
    if compress:
        body += (
            Nodes(nq, ((psi, "Psi"),), (), (), ((psi / work_pass, "Shape"),), comment="the shape Psi/W"),
        )
    scale_p = sp.Abs(pth0) + m * l0 * sp.sqrt(g_s * l0)
    iterate = Iterate(
        state=((D, d0),),
        arrays=(("Q", "Q0", "Q_next", sp.S.One), ("P", "P0", "P_next", scale_p)),
        # Psi (or its shape) for the damper's force of the next pass: outside the convergence test
        # (the force, c times it, follows Q, P and D; at c = 0 it is not used)
        array_carry=(("Psr", "Psr0", "Shape" if compress else "Psi"),),
        nodes=nq,
        evaluate=evaluate,
        body=body,
        update=(sym("_D_next"),),
        max_iter=sym("iterations"),
        tol=sym("tol"),
        scales=(l0,),
        count=sym("_passes"),
        comment="Picard passes on the node values (collocation in u)",
    )
    start = Nodes(
        nq, ((u, "u"),), (), (), ((start_q, "Q0"), (start_p, "P0")), comment="the zeroth iterate at the nodes"
    )
    start_psi = Nodes(nq, (), (), (), ((psi0, "Psr0"),), comment="Psi at the nodes, zeroth iterate")
    # Both halves: y_end = y_anchor + int_0^1 (the compression half runs toward u = 0 in time, the
    # decompression half toward u = 1; in both the u-rates point along the motion).
    t_half, q_end, p_end = sym("_t_end"), sym("_q_end"), sym("_p_end")
    sums = (Reduce(t_half, "w", "ft", nq), Reduce(q_end, "w", "fq", nq), Reduce(p_end, "w", "fp", nq))
    common = ((sym("t_half"), t_half), (sym("end_q_th"), th0 + q_end))
    steps = (rule_tables(sym("nodes")), start, start_psi, iterate, *sums)
    if compress:
        q_r_b = sym("end_q_r")
        return steps + (
            Stage(
                (
                    *common,
                    (q_r_b, top - D),
                    (sym("end_q_rd"), sp.S.Zero),
                    (sym("end_q_thd"), (pth0 + p_end) / (m * q_r_b**2)),
                    (sym("passes"), sym("_passes")),
                ),
                (Guard(q_r_b > 0, "FALL", "bottom leg length q_r_b > 0"),),
                comment="bottom state",
            ),
        )
    work, q_r_lo = sym("_work"), catalog.PARAMS["q_r_lo"].symbol
    # the liftoff at q_r_lo as without the damper (its arithmetic, its derivatives' too), then at the
    # leg force's zero where D stopped short of q_r_lo (liftoff "force", c > 0)
    lo_q_thd, short = sym("_lo_q_thd"), D < q_r_lo - top
    return steps + (
        Reduce(work, "w1", "F", nq),
        Stage((), (Guard(work > 0, "NO_LIFTOFF", "p_r_lo^2 = 4 m D int_0^1 F_r u du > 0"),)),
        Stage(
            (
                *common,
                (sym("end_q_rd"), sp.sqrt(4 * m * D * work) / m),
                (lo_q_thd, (pth0 + p_end) / (m * q_r_lo**2)),
                (sym("passes"), sym("_passes")),
            ),
            comment="liftoff state: p_r_lo^2 = 2 m int F_r (work form)",
        ),
        Stage(
            (
                (sym("end_q_r"), sp.Piecewise((top + D, short), (q_r_lo, True))),
                (
                    sym("end_q_thd"),
                    sp.Piecewise(((pth0 + p_end) / (m * (top + D) ** 2), short), (lo_q_thd, True)),
                ),
            ),
            comment="liftoff at q_r_lo, or at q_r_b + D short of it",
        ),
    )


def _liftoff_distance(a: dict, top: sp.Basic, work: sp.Symbol) -> sp.Basic:
    """D of the next pass of a decompression half: q_r_lo - q_r_b, or with option liftoff "force"
    the distance to the leg force's zero (:func:`~.iterative_helpers.force_liftoff`, with the pass's
    W = int_0^1 F_r u du) when the leg force at q_r_lo, p_r there from the same W, is negative
    (q_r_lo first, or a tie: q_r_lo)."""
    q_r_lo = catalog.PARAMS["q_r_lo"].symbol
    force, root = force_liftoff()
    s, w = liftoff_symbols()
    at = {q_r_b: top, w: work}
    at_lo = force.subs(at).subs(s, sp.sqrt(q_r_lo - top))
    pulls = sp.And(LIFTOFF.is_("force"), at_lo < 0)
    return sp.Piecewise((root.subs(at) ** 2, pulls), (q_r_lo - top, True))


NODES = Option(
    "nodes",
    "Gauss-Legendre nodes in u per half-stance (1 = the report's mean-value point (41))",
    "4",
    tuple((str(n), f"{n} node{'s' if n > 1 else ''}") for n in NODE_COUNTS),
    roles=("accuracy-variants",),
)
ITERATIONS = Option(
    "iterations",
    "Picard passes per half-stance (0 = the zeroth iterate)",
    6,
    low=0,
    high=100,
    integer=True,
    roles=("accuracy-passes", "convergence-passes"),
)
TOL = Option(
    "tol",
    "stop when no node value moves by more than tol (relative; 0 = run every pass)",
    0.0,
    low=0.0,
    high=1.0,
    roles=("tolerance",),
)


def _polar_args(prefix: str, what: str) -> tuple[Arg, ...]:
    return tuple(Arg(sym(f"{prefix}{f.name}"), f"{what}: {f.doc} [{f.unit}]", None) for f in catalog.POLAR)


@cache
def half_kernel(kind: str) -> Kernel:
    """The compression half (touchdown -> bottom, k_c; report 5.2.1) or the decompression half
    (bottom -> liftoff at q_r_lo or, option liftoff "force", the leg force's zero, k_d; report 3.2
    and 5.2.2), collocation with NODES nodes; the leg damping c in both (module docstring)."""
    compress = kind == "compression"
    anchor = _polar_args("", "touchdown state" if compress else "bottom state")
    names = {f.name: a.symbol for f, a in zip(catalog.POLAR, anchor, strict=True)}
    guess_fields = ("q_r", "q_th", "q_thd") if compress else ("q_th", "q_thd")
    end = "bottom" if compress else "liftoff"
    guess = tuple(Arg(sym(f"guess_{f}"), f"zeroth iterate's {end} {f}", None) for f in guess_fields)
    a = {**names, **{f"guess_{f}": g.symbol for f, g in zip(guess_fields, guess, strict=True)}}
    stiffness = catalog.PARAMS["k_c" if compress else "k_d"]
    params = (catalog.PARAMS["m"], catalog.PARAMS["l0"], stiffness, catalog.PARAMS["g_s"])
    if not compress:
        params += (catalog.PARAMS["q_r_lo"],)
    params += (catalog.PARAMS["c"],)
    options = (NODES.arg(), ITERATIONS.arg(), TOL.arg()) + (() if compress else (LIFTOFF.arg(),))
    q_r_lo = catalog.PARAMS["q_r_lo"].symbol
    at_start = {q_r: names["q_r"], q_th: names["q_th"], p_th: m * names["q_r"] ** 2 * names["q_thd"]}
    first = (
        (Guard(names["q_rd"] < 0, "TOUCHDOWN_NOT_COMPRESSING", "q_rd_td < 0"),)
        if compress
        else (
            Guard(q_r_lo - names["q_r"] > 0, "NO_LIFTOFF", "bottom below q_r_lo"),
            # as the exact simulator: the k_d spring must start extending the leg at the bottom
            Guard(radial_force(k_d).subs(at_start) > 0, "RECOMPRESSION", "F_r > 0 at the bottom with k_d"),
        )
    )
    outputs = Group(
        "",
        (
            Field("t_half", f"time of the {kind} half", "s"),
            Group("end", catalog.POLAR, f"state at the {end}"),
            Field("passes", "Picard passes run", "1"),
        ),
    )
    return Kernel(
        name=f"schwind_{kind}",
        summary=f"Schwind and Koditschek's iteration, {kind} half, converging form (collocation in u, "
        "work form of p_r).",
        equations=("29", "30", "31", "32", "37", "41")
        if not compress
        else ("115", "116", "117", "118", "123"),
        args=anchor + params + guess + options,
        steps=(Stage((), first), *_half_steps(kind, a)),
        outputs=outputs,
        module="iterative",
    )


_POLAR_NAMES = tuple(f.name for f in catalog.POLAR)


@cache
def core_kernel() -> Kernel:
    """The whole stance from the touchdown state and a zeroth iterate (:func:`~.iterative_helpers.
    zeroth_arguments`): the compression half, the zeroth iterate's liftoff, the decompression half.
    One kernel for every choice of ``zeroth``: a choice's stance calls its zeroth map, then this."""
    from ..catalog import PARAMS, TOUCHDOWN

    q_r_td, q_rd_td, q_th_td, q_thd_td = (a.symbol for a in TOUCHDOWN)
    p = {n: PARAMS[n].symbol for n in ("m", "l0", "k_c", "k_d", "g_s", "q_r_lo", "c")}
    options = {o: sym(o) for o in ("nodes", "iterations", "tol")}
    compression, decompression = half_kernel("compression"), half_kernel("decompression")
    physical = {q: p[q] for q in ("m", "l0", "g_s", "c")}
    steps = (
        Call(
            compression,
            {
                "q_r": q_r_td,
                "q_rd": q_rd_td,
                "q_th": q_th_td,
                "q_thd": q_thd_td,
                **physical,
                "k_c": p["k_c"],
                **{f"guess_{q}": sym(f"z_b_{q}") for q in ("q_r", "q_th", "q_thd")},
                **options,
            },
            {
                "t_half": "t_bottom",
                **{f"end_{q}": f"bottom_{q}" for q in _POLAR_NAMES},
                "passes": "c_passes",
            },
            comment="compression half, k_c (report 5.2.1)",
        ),
        zeroth_liftoff(p["q_r_lo"]),
        Call(
            decompression,
            {
                **{q: sym(f"bottom_{q}") for q in _POLAR_NAMES},
                **physical,
                "k_d": p["k_d"],
                "q_r_lo": p["q_r_lo"],
                "guess_q_th": sym("g_lo_q_th"),
                "guess_q_thd": sym("g_lo_q_thd"),
                **options,
                LIFTOFF.name: LIFTOFF.symbol,
            },
            {
                "t_half": "t_decompression",
                **{f"end_{q}": f"liftoff_{q}" for q in _POLAR_NAMES},
                "passes": "d_passes",
            },
            comment="decompression half, k_d (report 3.2, 5.2.2)",
        ),
        Stage(
            (
                (sym("t_stance"), sym("t_bottom") + sym("t_decompression")),
                # the larger of the two halves' pass counts: at most the option iterations
                (
                    sym("passes"),
                    (sym("c_passes") + sym("d_passes") + sp.Abs(sym("c_passes") - sym("d_passes"))) / 2,
                ),
            ),
            (Guard(sp.Abs(sym("liftoff_q_th")) < sp.pi / 2, "FALL", "the leg stays above horizontal"),),
        ),
    )
    return Kernel(
        name="iterative_core",
        summary="Schwind and Koditschek's iteration, converging form: the stance from the touchdown state "
        "and a zeroth iterate.",
        equations=_EQUATIONS,
        args=TOUCHDOWN
        + tuple(PARAMS[n] for n in p)
        + zeroth_arguments()
        + (NODES.arg(), ITERATIONS.arg(), TOL.arg(), LIFTOFF.arg()),
        steps=steps,
        outputs=catalog.STANCE + Group("", (_PASSES_WHOLE,)),
        module="iterative",
        check_inputs=False,
    )


def _parameters(kernel: Kernel, given) -> dict:
    """The parameters ``kernel`` takes from the build's ``given`` (name -> expression: the
    declaration's parameters), in its order; its other arguments (the start state, the guesses, the
    options) the caller binds, and an argument left unbound is refused at generation."""
    return {a.name: given[a.name] for a in kernel.args if a.name in given}


def _build(inp: MapInputs) -> MapBuild:
    q_r_td, q_rd_td, q_th_td, q_thd_td = inp.touchdown
    p = inp.params
    core = core_kernel()
    args = {
        **dict(zip((a.name for a in catalog.TOUCHDOWN), inp.touchdown, strict=True)),
        **_parameters(core, p),
        **zeroth_values(),
        **{o: inp.opt(o) for o in ("nodes", "iterations", "tol", LIFTOFF.name)},
    }
    steps = (
        Stage((), (Guard(q_rd_td < 0, "TOUCHDOWN_NOT_COMPRESSING", "q_rd_td < 0"),)),
        zeroth_bottom(inp.touchdown, p, p["q_r_lo"]),
        Call(core, args, {n: n for n in core.output_names}, comment="the iteration from the zeroth iterate"),
    )
    return MapBuild(steps=steps, helpers=(half_kernel("compression"), half_kernel("decompression")))


_EQUATIONS = ("27", "29", "30", "31", "32", "33", "35", "37", "41", "114", "115", "116", "117", "118", "137")


@cache
def declare_maps() -> tuple[MapSpec, ...]:
    """This module's ``MAPS``: declared once every map that can be a zeroth iterate is known (the
    choices of option ``zeroth``, :func:`~.iterative_helpers.zeroth_option`)."""
    return (
        MapSpec(
            name="iterative",
            title="Iterative stance map (Schwind and Koditschek, converging form)",
            section="5.2",
            equations=tuple(sorted(_EQUATIONS, key=int)),
            params=("m", "l0", "k_c", "k_d", "g_s", "c"),
            build=_build,
            options=(NODES, ITERATIONS, TOL, zeroth_option(), LIFTOFF),
            extras=(_PASSES_WHOLE,),
            summary="both halves by Picard passes on Gauss nodes in u = sqrt(q_r - q_r_b); p_r from the "
            "radial work; k_c before the bottom, k_d after",
            notes="Converging form of (30)-(45) and (116)-(151): p_r^2 = 2 m int F_r (work form) instead "
            "of (33); N Gauss-Legendre nodes in u (N = 1 is the mean value (41)); bottom leg length from "
            "p_r_td^2 = 2 m int F_r.",
            roles=("region", "accuracy-figure"),
        ),
    )


_PASSES_WHOLE = Field("passes", "Picard passes run (the larger of the two halves)", "1")
_HALF_OUTPUTS = {"t_half": "t_half", **{f"end_{q}": f"end_{q}" for q in _POLAR_NAMES}, "passes": "passes"}
_PASSES = Field("passes", "Picard passes run", "1")


def _compression_half(inp: HalfInputs) -> tuple[Step, ...]:
    """Touchdown -> bottom with k_c; the zeroth iterate from the touchdown state (its Geyer call
    takes q_r_lo = q_r_td: only its bottom is used)."""
    p = inp.params
    options = {o: inp.opt(o) for o in ("nodes", "iterations", "tol")}
    return (
        zeroth_bottom(inp.state, p, inp.state[0]),
        Call(
            half_kernel("compression"),
            {
                **dict(zip(_POLAR_NAMES, inp.state, strict=True)),
                **_parameters(half_kernel("compression"), p),
                **{f"guess_{q}": sym(f"z_b_{q}") for q in ("q_r", "q_th", "q_thd")},
                **options,
            },
            _HALF_OUTPUTS,
            comment="compression half, k_c (report 5.2.1)",
        ),
    )


def _decompression_half(inp: HalfInputs) -> tuple[Step, ...]:
    """Bottom -> liftoff with k_d; zeroth iterate: the bottom's angle and angular momentum held."""
    p = inp.params
    guess_q_th, guess_q_thd = held_liftoff(inp.state, p["q_r_lo"])
    return (
        Call(
            half_kernel("decompression"),
            {
                **dict(zip(_POLAR_NAMES, inp.state, strict=True)),
                **_parameters(half_kernel("decompression"), p),
                "guess_q_th": guess_q_th,
                "guess_q_thd": guess_q_thd,
                **{o: inp.opt(o) for o in ("nodes", "iterations", "tol", LIFTOFF.name)},
            },
            _HALF_OUTPUTS,
            comment="decompression half, k_d (report 5.2.2)",
        ),
    )


@cache
def declare_halves() -> tuple[HalfSpec, ...]:
    """This module's ``HALVES`` (the compression half takes option ``zeroth`` too)."""
    return (
        HalfSpec(
            name="iterative-compression",
            title="Iterative compression half (touchdown to bottom, k_c; converging form)",
            section="5.2.1",
            equations=("29", "30", "31", "32", "114", "115", "116", "117", "118", "123"),
            whole="iterative",
            start="touchdown",
            params=("m", "l0", "k_c", "g_s", "c"),
            build=_compression_half,
            options=(NODES, ITERATIONS, TOL, zeroth_option()),
            extras=(_PASSES,),
            summary="the compression half of `iterative`: bottom leg length from the radial work, Picard "
            "passes on Gauss nodes in u",
        ),
        HalfSpec(
            name="iterative-decompression",
            title="Iterative decompression half (bottom to liftoff, k_d; converging form)",
            section="5.2.2",
            equations=("29", "30", "31", "32", "37", "41", "137", "138", "139", "140", "141", "143"),
            whole="iterative",
            start="bottom",
            params=("m", "l0", "k_d", "g_s", "q_r_lo", "c"),
            build=_decompression_half,
            options=(NODES, ITERATIONS, TOL, LIFTOFF),
            extras=(_PASSES,),
            summary="the decompression half of `iterative` from any bottom state: zeroth iterate the "
            "bottom's angle and angular momentum held, liftoff p_r from the radial work",
        ),
    )
