"""Gravity correction type 5 (report 4.6, unfinished there): a time-varying angular momentum.

The report names type 5 ("time-variant virtual effect, a 5th-degree polynomial of leg length and
angle") and stops mid-sentence. The design here (docs/type5.md, equations T5.1-T5.8) keeps the
report's idea: the gravity torque (47) along the approximate stance, tau(t) = m g_s q_r sin q_th,
is sampled at the three Gauss-Legendre nodes of the stance, the rule that integrates a
5th-degree polynomial of time exactly, and interpolated by the quadratic through them (T5.1), so
the momentum P(t) = p_td + int_0^t tau is a cubic (T5.2) instead of Geyer's constant. Then:

- radial motion (T5.3-T5.5): Geyer's quadrature (9) with the time-mean of P, the radial gravity
  g_s <cos q_th> (its Gauss-Legendre mean over the stance) and 1/(1+rho)^2 expanded to second
  order about the stance-mean compression r_c instead of 0 (with P constant, g_eff = g_s and
  r_c = 0 this is Geyer's (9)-(11) exactly);
- leg angle (T5.6): q_th = q_th_td + int_0^t P(u) / (m q_r(u)^2) du with the same expansion of
  1/(1+rho)^2, integrated in closed form by SymPy;
- liftoff (T5.7): rate P(t_lo) / (m q_r_lo^2), radial speed from the exact energy (27);
- fixed point (T5.8) on the nodal torques, the stance time, g_eff and r_c, from Geyer's map.

A prototype study (docs/type5.md) measured the simpler design (Geyer's linearized rate with the
cubic momentum) at 6.9 % mean error on the Yu protocol, worse than type 2: resolving P(t) exposes
the error of Geyer's 1 - 2 rho, so the radial solution must improve with it.
"""

from __future__ import annotations

from functools import cache

import sympy as sp
from sympy.integrals.manualintegrate import manualintegrate

from .. import catalog
from ..ir import Arg, Call, Field, Group, Guard, Iterate, Kernel, Stage, Step, sym
from ..mapspec import MapBuild, MapInputs, MapSpec, Option
from ..symbols import (
    g_s,
    k,
    l0,
    m,
    q_r,
    q_r_lo,
    q_r_td,
    q_rd_td,
    q_th,
    q_th_td,
    rho,
    rho_d,
)
from . import geyer
from .gravity import liftoff_speed_from_energy, torque, touchdown_invariants

#: Gauss-Legendre nodes and weights on [-1, 1]: exact for polynomials of degree 5.
GL_X = (-sp.sqrt(sp.Rational(3, 5)), sp.S.Zero, sp.sqrt(sp.Rational(3, 5)))
GL_W = (sp.Rational(5, 9), sp.Rational(8, 9), sp.Rational(5, 9))

U, T_PREV, T_NOW = sym("u"), sym("T"), sym("t")
TAU = tuple(sym(f"tau{i}") for i in (1, 2, 3))
C = tuple(sym(f"c{i}") for i in range(3))
K = tuple(sym(f"k{i}") for i in range(3))
OMEGA, G_EFF, R_C = sym("omega"), sym("g_eff"), sym("r_c")
W_HAT, A_, B_, PH_TD = sym("omega0_hat"), sym("a"), sym("b"), sym("phase_td")
P_TD = sym("p_td")
LAM, MU, NU = sym("lam"), sym("mu"), sym("nu")


# --------------------------------------------------------------------------------------------
# Derivation


def nodes(duration) -> tuple[sp.Basic, ...]:
    """T5.1: the Gauss-Legendre nodes of [0, duration]."""
    return tuple(duration * (1 + x) / 2 for x in GL_X)


@cache
def torque_quadratic() -> tuple[sp.Basic, sp.Basic, sp.Basic]:
    """T5.1: c0, c1, c2 of tau(t) = c0 + c1 t + c2 t^2 through (t_i, tau_i) at the nodes of [0, T]."""
    vandermonde = sp.Matrix([[1, ti, ti**2] for ti in nodes(T_PREV)])
    coeffs = vandermonde.LUsolve(sp.Matrix(TAU))
    return tuple(sp.simplify(c) for c in coeffs)


def momentum(time) -> sp.Basic:
    """T5.2: P(t) = p_td + int_0^t (c0 + c1 u + c2 u^2) du, a cubic in t."""
    return P_TD + sp.integrate(C[0] + C[1] * U + C[2] * U**2, (U, 0, time))


@cache
def mean_momentum() -> sp.Basic:
    """T5.3: the time-mean of P over the previous stance [0, T]."""
    return sp.expand(sp.integrate(momentum(U), (U, 0, T_PREV)) / T_PREV)


@cache
def inverse_square_expansion() -> sp.Basic:
    """T5.4: 1/(1+rho)^2 to second order about rho = r_c (Assumption 2 about r_c instead of 0)."""
    return sp.series(1 / (1 + rho) ** 2, rho, R_C, 3).removeO()


@cache
def radial_quadratic() -> tuple[sp.Basic, sp.Basic]:
    """T5.4: lambda, mu of rho_d^2 = lambda rho^2 + mu rho + nu from (8) with g_eff and T5.4.

    (8): epsilon = rho_d^2 + omega^2/(1+rho)^2 + omega0^2 rho^2 + 2 g/l0 (1+rho); nu follows from
    the touchdown state (the quadratic passes through (rho_td, rho_d_td)), as in Geyer's map.
    """
    energy = sp.expand(geyer.dimensionless_energy().subs(g_s, G_EFF))
    centrifugal = energy.coeff(geyer.omega, 2)  # the 1/(1+rho)^2 of (8)
    assert sp.simplify(centrifugal - 1 / (1 + rho) ** 2) == 0, centrifugal
    f = sp.expand(energy - geyer.omega**2 * centrifugal + geyer.omega**2 * inverse_square_expansion())
    rho_d2 = sp.expand(geyer.epsilon - (f - rho_d**2))
    poly = sp.Poly(rho_d2, rho)
    lam_, mu_, _ = poly.all_coeffs()
    return sp.factor(lam_), sp.factor(mu_)


@cache
def quadratic_at_touchdown() -> tuple[sp.Basic, sp.Basic, sp.Basic]:
    """T5.5: lambda, mu of T5.4 and nu through the touchdown point (rho_td, rho_d_td)."""
    lam_, mu_ = (
        e.subs({geyer.omega: OMEGA, geyer.omega0: sp.sqrt(sym("omega0_sq"))}) for e in radial_quadratic()
    )
    rho_td, rho_d_td = q_r_td / l0 - 1, q_rd_td / l0
    return lam_, mu_, rho_d_td**2 - LAM * rho_td**2 - MU * rho_td


@cache
def rate_factor() -> tuple[sp.Basic, sp.Basic, sp.Basic]:
    """T5.6: k0, k1, k2 with T5.4 at rho = a + b sin x equal to k0 + k1 sin x + k2 cos 2x."""
    x = sp.Symbol("x", real=True)
    f = sp.expand(inverse_square_expansion().subs(rho, A_ + B_ * sp.sin(x)))
    f = sp.expand(f.subs(sp.sin(x) ** 2, (1 - sp.cos(2 * x)) / 2))
    k2 = f.coeff(sp.cos(2 * x))
    k1 = f.coeff(sp.sin(x))
    k0 = sp.expand(f - k1 * sp.sin(x) - k2 * sp.cos(2 * x))
    return sp.simplify(k0), sp.simplify(k1), sp.simplify(k2)


@cache
def leg_angle() -> sp.Basic:
    """T5.6: q_th(t) = q_th_td + int_0^t P(u) (k0 + k1 sin(x) + k2 cos(2x)) du / (m l0^2), x = w u + phase."""
    w = sp.Symbol("omega0_hat", positive=True)
    x = w * U + PH_TD
    integrand = sp.expand(momentum(U) * (K[0] + K[1] * sp.sin(x) + K[2] * sp.cos(2 * x)))
    antiderivative = sum(manualintegrate(term, U) for term in integrand.args)
    integral = antiderivative.subs(U, T_NOW) - antiderivative.subs(U, 0)
    return q_th_td + integral.subs(w, W_HAT) / (m * l0**2)


# --------------------------------------------------------------------------------------------
# Kernels


@cache
def solution_kernel() -> Kernel:
    """T5.5 from the touchdown radial state: omega0_hat, a, b, touchdown phase (guards as Geyer's)."""
    lam_, mu_, nu_ = quadratic_at_touchdown()
    return Kernel(
        name="type5_solution",
        summary="Type 5 radial solution: (10)-(11) for the quadratic T5.4 about r_c with g_eff.",
        equations=("9", "10", "11", "12"),
        args=(
            catalog.TOUCHDOWN[0],
            catalog.TOUCHDOWN[1],
            Arg(OMEGA, "omega = p_mean / (m l0^2) [rad/s]"),
            Arg(G_EFF, "radial gravity g_s <cos q_th> [m/s^2]"),
            Arg(R_C, "expansion point of 1/(1+rho)^2 (stance-mean compression)"),
            *(catalog.PARAMS[p] for p in ("m", "l0", "k")),
        ),
        steps=(
            Stage(((sym("omega0_sq"), k / m),), (Guard(q_rd_td < 0, "TOUCHDOWN_NOT_COMPRESSING"),)),
            Stage(((LAM, lam_), (MU, mu_)), comment="T5.4: the quadratic about r_c with g_eff"),
            Stage(((NU, nu_),), comment="T5.5: through the touchdown point"),
            *geyer.inversion_stages(),
        ),
        outputs=Group(
            "",
            (
                Field("omega0_hat", "frequency", "rad/s"),
                Field("a", "offset of rho(t)"),
                Field("b", "amplitude of rho(t)"),
                Field("phase_td", "touchdown phase", "rad"),
                Field("s_td", "sin(phase_td)"),
            ),
        ),
        check_inputs=False,
        check_outputs=False,
        module="gravity_type5",
    )


@cache
def leg_angle_kernel() -> Kernel:
    """T5.6: the leg angle a time t after touchdown, in closed form."""
    args = (
        Arg(T_NOW, "time since touchdown [s]"),
        catalog.TOUCHDOWN[2],
        Arg(P_TD, "angular momentum at touchdown [N m s]"),
        *(Arg(c, f"coefficient {c.name} of the torque quadratic T5.1") for c in C),
        *(Arg(kk, f"coefficient {kk.name} of the rate factor T5.6") for kk in K),
        Arg(W_HAT, "frequency omega0_hat [rad/s]"),
        Arg(PH_TD, "touchdown phase [rad]"),
        catalog.PARAMS["m"],
        catalog.PARAMS["l0"],
    )
    return Kernel(
        name="type5_leg_angle",
        summary="Type 5 leg angle T5.6: q_th_td + int_0^t P(u) (k0 + k1 sin + k2 cos 2(.)) du / (m l0^2).",
        equations=("17", "18", "19"),
        args=args,
        steps=(Stage(((sym("q_th"), leg_angle()),)),),
        outputs=Group("", (Field("q_th", "leg angle", "rad"),)),
        status=False,
        check_inputs=False,
        module="gravity_type5",
    )


def _angle_call(prefix: str, time: sp.Basic, out: str) -> Call:
    """T5.6 at ``time`` for the trajectory named by ``prefix``, bound to ``out``."""
    args = {
        name: sym(prefix + name) for name in ("c0", "c1", "c2", "k0", "k1", "k2", "omega0_hat", "phase_td")
    }
    args.update({"t": time, "q_th_td": q_th_td, "p_td": P_TD, "m": m, "l0": l0})
    return Call(leg_angle_kernel(), args, {"q_th": out})


def _trajectory(prefix: str) -> tuple[Step, ...]:
    """The stance of one pass from the state (tau_i, T, g_eff, r_c): names ``<prefix>...``."""

    def n(name):
        return sym(prefix + name)

    c0, c1, c2 = torque_quadratic()
    k0, k1, k2 = rate_factor()
    sol, lo = solution_kernel(), geyer.liftoff_phase_kernel()
    names = {A_: n("a"), B_: n("b")}
    radius = l0 * (1 + n("a") + n("b") * sp.sin(n("omega0_hat") * U + n("phase_td")))
    t_nodes = nodes(n("t_stance"))
    return (
        Stage(
            ((n("c0"), c0), (n("c1"), c1), (n("c2"), c2)),
            comment="T5.1: the torque quadratic through the nodal torques of the previous pass",
        ),
        Stage(
            (
                (
                    n("omega"),
                    mean_momentum().subs({C[0]: n("c0"), C[1]: n("c1"), C[2]: n("c2")}) / (m * l0**2),
                ),
            ),
            comment="T5.3: omega of the stance-mean momentum",
        ),
        Call(
            sol,
            {
                "q_r_td": q_r_td,
                "q_rd_td": q_rd_td,
                "omega": n("omega"),
                "g_eff": G_EFF,
                "r_c": R_C,
                "m": m,
                "l0": l0,
                "k": k,
            },
            {o: prefix + o for o in sol.output_names},
            comment="T5.4-T5.5: radial solution",
        ),
        Call(lo, {"a": n("a"), "b": n("b"), "l0": l0, "q_r_lo": q_r_lo}, {"phase_lo": prefix + "phase_lo"}),
        Stage(
            (
                *geyer.event_times(prefix),
                (n("k0"), k0.subs(names)),
                (n("k1"), k1.subs(names)),
                (n("k2"), k2.subs(names)),
            ),
            comment="eqs (13)-(14) minus (12); T5.6: the rate factor",
        ),
        *(_angle_call(prefix, ti, prefix + f"th{i + 1}") for i, ti in enumerate(t_nodes)),
        Stage(
            (
                *(
                    (n(f"tau{i + 1}"), torque().subs({q_r: radius.subs(U, ti), q_th: n(f"th{i + 1}")}))
                    for i, ti in enumerate(t_nodes)
                ),
                (n("g_eff"), g_s * sum(w * sp.cos(n(f"th{i + 1}")) for i, w in enumerate(GL_W)) / 2),
                (
                    n("r_c"),
                    n("a")
                    - n("b")
                    * (sp.cos(n("phase_lo")) - sp.cos(n("phase_td")))
                    / (n("phase_lo") - n("phase_td")),
                ),
            ),
            comment="T5.1, T5.4: the torques at the new nodes, g_s <cos q_th>, the mean compression",
        ),
    )


def _build(inp: MapInputs) -> MapBuild:
    # The pass from tau = 0, T arbitrary, g_eff = g_s, r_c = 0 is Geyer's radial solution.
    state = tuple((s, v) for s, v in zip(TAU, (0, 0, 0), strict=True)) + (
        (T_PREV, sp.S.One),
        (G_EFF, g_s),
        (R_C, sp.S.Zero),
    )
    torque_scale = m * g_s * l0
    setup: tuple[Step, ...] = (
        touchdown_invariants(),
        Iterate(
            state=tuple((s, sp.sympify(v)) for s, v in state),
            # the trajectory at every iterate, the final one included (visible after the loop)
            evaluate=_trajectory("i_"),
            body=(),
            update=(*(sym(f"i_tau{i}") for i in (1, 2, 3)), sym("i_t_stance"), sym("i_g_eff"), sym("i_r_c")),
            max_iter=inp.opt("iterations"),
            tol=inp.opt("tol"),
            scales=(torque_scale, torque_scale, torque_scale, sp.sqrt(m / k), g_s, sp.S.One),
            count=sym("passes"),
            comment="T5.8: fixed point on the nodal torques, the stance time, g_eff and r_c",
        ),
    )
    f = {
        name: sym("i_" + name)
        for name in ("a", "b", "omega0_hat", "phase_td", "t_bottom", "t_stance", "c0", "c1", "c2")
    }
    p_of = momentum(U).subs({C[0]: f["c0"], C[1]: f["c1"], C[2]: f["c2"]})

    def angle_at(time, out):
        return _angle_call("i_", time, out)

    q_r_b = l0 * (1 + f["a"] - f["b"])
    outputs = (
        angle_at(f["t_bottom"], "bottom_q_th"),
        angle_at(f["t_stance"], "liftoff_q_th"),
        Stage(
            (
                (sym("t_bottom"), f["t_bottom"]),
                (sym("t_stance"), f["t_stance"]),
                (sym("bottom_q_r"), q_r_b),
                (sym("bottom_q_rd"), sp.S.Zero),
                (sym("bottom_q_thd"), p_of.subs(U, f["t_bottom"]) / (m * q_r_b**2)),
                (sym("liftoff_q_r"), q_r_lo),
                (sym("P_c"), p_of.subs(U, f["t_stance"]) - P_TD),
                (sym("liftoff_q_thd"), p_of.subs(U, f["t_stance"]) / (m * q_r_lo**2)),
            ),
            (Guard(sp.Abs(sym("liftoff_q_th")) < sp.pi / 2, "FALL", "the leg stays above horizontal"),),
            comment="T5.7: bottom and liftoff states",
        ),
        *liftoff_speed_from_energy(sym("liftoff_q_th"), p_of.subs(U, f["t_stance"])),
    )

    def state_at(time: sp.Symbol) -> tuple[Step, ...]:
        phase = f["omega0_hat"] * time + f["phase_td"]
        return setup + (
            angle_at(time, "q_th"),
            Stage(
                (
                    (sym("q_r"), l0 * (1 + f["a"] + f["b"] * sp.sin(phase))),
                    (sym("q_rd"), l0 * f["b"] * f["omega0_hat"] * sp.cos(phase)),
                    (
                        sym("q_thd"),
                        p_of.subs(U, time) / (m * (l0 * (1 + f["a"] + f["b"] * sp.sin(phase))) ** 2),
                    ),
                ),
                comment="(11) with T5.5, T5.2",
            ),
        )

    return MapBuild(steps=setup + outputs, state_at=state_at, helpers=(solution_kernel(), leg_angle_kernel()))


#: The family page of this module's map (derive/maps/__init__.py: :func:`~slipmaps.derive.maps.family_pages`).
PAGE = "type5"

MAPS = (
    MapSpec(
        name="gravity-type5",
        title="Gravity correction type 5 (time-varying momentum)",
        section="4.6",
        equations=("46", "47", "48"),
        params=("m", "l0", "k", "g_s"),
        requires=("constant_stiffness",),
        build=_build,
        options=(
            Option(
                "iterations",
                "fixed-point passes T5.8 from Geyer's map",
                100,
                low=0,
                high=1000,
                integer=True,
                roles=("accuracy-passes", "convergence-passes"),
            ),
            Option(
                "tol",
                "stop when every state moved by at most tol times its scale; 0: run all passes",
                1e-12,
                low=0.0,
                high=1.0,
                roles=("tolerance",),
            ),
        ),
        extras=(
            Field("P_c", "stance impulse of the gravity torque P(t_lo) - p_td", "N m s", odd=True),
            Field("passes", "fixed-point passes run", ""),
        ),
        summary="the gravity torque at the 3 Gauss-Legendre nodes of the stance, interpolated: a cubic "
        "momentum P(t); radial solution about the mean compression; leg angle in closed form (docs/type5.md)",
        notes="Designed in slipmaps (the report stops mid-sentence): docs/type5.md, equations T5.1-T5.8.",
        roles=("yu-target", "accuracy-figure", "region"),
    ),
)
