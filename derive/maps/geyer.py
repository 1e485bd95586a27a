"""Geyer et al.'s approximate stance map (report section 3.1, eqs 4-26): derivation and declaration.

Each function performs one step of the report's derivation with SymPy and returns its result
(cached); :mod:`slipmaps.derive.equations` compares the results with the printed equations. The
end of the module declares the map (:data:`MAPS`) and three helper kernels that other maps call:
``geyer_solution`` (touchdown state -> omega, omega0_hat, a, b and the touchdown phase, eqs 7-12),
``geyer_liftoff_phase`` (eq 14) and ``geyer_state`` (the state at a phase, eqs 11, 17, 19).
A variant with another leg angle than (19) is :func:`build_from` that angle (the map of
docs/adding_a_map.md, ``derive/maps/geyer_angle2.py`` when added).

Time origin: as in (11), the radial solution is rho(t) = a + b sin(omega0_hat t); touchdown,
bottom and liftoff happen at the phases omega0_hat t = pi - asin(s_td), 3 pi / 2 and
2 pi + asin(s_lo) (n = 0 in (12)-(14)), with s_x = (q_r_x / l0 - 1 - a) / b. Kernels report times
measured from touchdown.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .. import catalog
from ..ir import Arg, Call, Field, Group, Guard, Kernel, Stage, Step, sym
from ..mapspec import MapBuild, MapInputs, MapSpec
from ..model import mechanics
from ..symbols import (
    E,
    a,
    b,
    epsilon,
    k,
    l0,
    lam,
    m,
    mu,
    nu,
    omega,
    omega0,
    omega0_hat,
    p_th,
    q_r,
    q_r_lo,
    q_r_td,
    q_rd,
    q_rd_td,
    q_th,
    q_th_td,
    q_thd,
    q_thd_td,
    rho,
    rho_d,
    t,
)

SMALL_ANGLE = {sp.cos(q_th): 1, sp.sin(q_th): 0}


@cache
def assumption1_equations():
    """Eqs (4)-(5): the Euler-Lagrange equations (2)-(3) with cos q_th ~ 1, sin q_th ~ 0."""
    el_r, el_th = mechanics.euler_lagrange_polar()
    return (sp.expand(el_r.subs(SMALL_ANGLE)), sp.expand(el_th.subs(SMALL_ANGLE)))


@cache
def energy_assumption1():
    """Eq (6): the energy of the Assumption-1 Lagrangian, with q_thd = p_th / (m q_r^2).

    E = q_rd dL/dq_rd + q_thd dL/dq_thd - L for L = (1) with cos q_th = 1.
    """
    lag = mechanics.lagrangian_polar().subs(SMALL_ANGLE)
    energy = q_rd * lag.diff(q_rd) + q_thd * lag.diff(q_thd) - lag
    return sp.expand(energy.subs(q_thd, p_th / (m * q_r**2)))


def dimensionless_substitution():
    """Eq (7) as a substitution.

    q_r = l0 (1 + rho), q_rd = l0 rho_d, p_th = m l0^2 omega, E = m l0^2 epsilon / 2, k = m omega0^2.
    """
    return {
        q_r: l0 * (1 + rho),
        q_rd: l0 * rho_d,
        p_th: m * l0**2 * omega,
        E: m * l0**2 * epsilon / 2,
        k: m * omega0**2,
    }


@cache
def dimensionless_energy():
    """Eq (8), solved for epsilon: epsilon = 2 E / (m l0^2) with (7) substituted into (6)."""
    sub = dimensionless_substitution()
    eq = sp.Eq(E.subs(sub), energy_assumption1().subs(sub))
    return sp.expand(sp.solve(eq, epsilon)[0])


@cache
def taylor_inverse_square():
    """Assumption 2: 1 / (1 + rho)^2 ~ 1 - 2 rho + 3 rho^2 (Taylor series at rho = 0)."""
    return sp.series(1 / (1 + rho) ** 2, rho, 0, 3).removeO()


@cache
def radial_quadratic():
    """Eq (9): rho_d^2 = lambda rho^2 + mu rho + nu after Assumption 2; returns (lambda, mu, nu)."""
    eps_expr = dimensionless_energy()
    # (8) solved for rho_d^2; its only non-polynomial term is omega^2 / (1 + rho)^2. Expanding the
    # whole right side to second order in rho is exactly the Taylor step of Assumption 2.
    rho_d2 = sp.expand(epsilon - (eps_expr - rho_d**2))
    rho_d2 = sp.series(rho_d2, rho, 0, 3).removeO()
    poly = sp.Poly(sp.expand(rho_d2), rho)
    coeffs = poly.all_coeffs()
    assert len(coeffs) == 3, coeffs
    return tuple(sp.expand(c) for c in coeffs)


def antiderivative(lam_=lam, mu_=mu, nu_=nu):
    """Eq (10), corrected: int drho / sqrt(lambda rho^2 + mu rho + nu).

    Valid for lambda < 0 < mu^2 - 4 lambda nu.
    """
    return -1 / sp.sqrt(-lam_) * sp.asin((2 * lam_ * rho + mu_) / sp.sqrt(mu_**2 - 4 * lam_ * nu_))


def solution_from_quadratic(lam_, mu_, nu_):
    """Eqs (10)-(11) for any rho_d^2 = lambda rho^2 + mu rho + nu with lambda < 0.

    Inverting t = F(rho) of (10) gives rho = -mu / (2 lambda) + sqrt(mu^2 - 4 lambda nu) / (-2 lambda)
    sin(sqrt(-lambda) (t - t0)); the time origin t0 = 0 is the report's choice.
    """
    w_hat = sp.sqrt(-lam_)
    a_ = -mu_ / (2 * lam_)
    b_ = sp.sqrt(mu_**2 - 4 * lam_ * nu_) / (-2 * lam_)
    return {"omega0_hat": w_hat, "a": a_, "b": b_, "b2": (mu_**2 - 4 * lam_ * nu_) / (4 * lam_**2)}


@cache
def radial_solution_parameters():
    """Eq (11): omega0_hat, a, b of rho(t) = a + b sin(omega0_hat t), the inverse of (10) for (9)."""
    sol = solution_from_quadratic(*radial_quadratic())
    return {
        "omega0_hat": sp.simplify(sol["omega0_hat"]),
        "a": sp.simplify(sol["a"]),
        "b": sol["b"],
        "b2": sp.simplify(sol["b2"]),
    }


def radial_solution(time=t):
    """rho(t) = a + b sin(omega0_hat t) in the symbols a, b, omega0_hat (eq 11)."""
    return a + b * sp.sin(omega0_hat * time)


@cache
def event_phases():
    """Eqs (12)-(14) with n = 0: phases omega0_hat t of touchdown, bottom and liftoff.

    Touchdown and liftoff solve rho(t) = q_r_x / l0 - 1, i.e. sin(phase) = s_x; touchdown is the
    root on the compressing branch (cos < 0), liftoff the root on the extending branch (cos > 0)
    after the bottom; the bottom is the minimum of rho (drho/dt = 0 and sin = -1).
    """
    s = sp.Symbol("s", real=True)
    x = sp.Symbol("x", real=True)
    roots = sp.solve(sp.Eq(sp.sin(x), s), x)
    compressing = [r for r in roots if sp.simplify(sp.cos(r) + sp.sqrt(1 - s**2)) == 0][0]
    extending = [r for r in roots if sp.simplify(sp.cos(r) - sp.sqrt(1 - s**2)) == 0][0]
    stationary = sp.solve(sp.Eq(sp.diff(sp.sin(x), x), 0), x)
    bottom = [r for r in stationary if sp.sin(r) == -1]
    bottom = bottom[0] if bottom else [r + sp.pi for r in stationary if sp.sin(r + sp.pi) == -1][0]
    return {
        "s": s,
        "touchdown": compressing,
        "bottom": bottom,
        "liftoff": extending + 2 * sp.pi,
    }


def leg_length_ratio(q_r_x):
    """s_x = (q_r_x / l0 - 1 - a) / b, so that rho = q_r_x / l0 - 1 at sin(phase) = s_x."""
    return (q_r_x / l0 - 1 - a) / b


@cache
def angular_rate():
    """Eq (17) and its linearization: q_thd = omega / (1 + rho)^2 ~ omega (1 - 2 rho)."""
    exact = (p_th / (m * q_r**2)).subs(dimensionless_substitution())
    linear = sp.series(exact, rho, 0, 2).removeO()
    return sp.simplify(exact), sp.expand(linear)


@cache
def leg_angle(t_td=None):
    """Eqs (18)-(19): q_th(t) = q_th_td + int_{t_td}^{t} omega (1 - 2 rho(tau)) dtau."""
    t_td = sp.Symbol("t_td", real=True) if t_td is None else t_td
    tau = sp.Symbol("tau", real=True)
    _, linear = angular_rate()
    integrand = linear.subs(rho, radial_solution(tau))
    return q_th_td + sp.integrate(integrand, (tau, t_td, t)), t_td


@cache
def stance_time_general():
    """Stance time (t_lo - t_td) and bottom time (t_b - t_td) for any touchdown/liftoff leg length."""
    ph = event_phases()
    s = ph["s"]
    ph_td = ph["touchdown"].subs(s, leg_length_ratio(q_r_td))
    ph_lo = ph["liftoff"].subs(s, leg_length_ratio(q_r_lo))
    return {
        "phase_td": ph_td,
        "phase_b": ph["bottom"],
        "phase_lo": ph_lo,
        "t_stance": (ph_lo - ph_td) / omega0_hat,
        "t_bottom": (ph["bottom"] - ph_td) / omega0_hat,
    }


@cache
def touchdown_parameters():
    """omega, epsilon from a touchdown state (q_r_td, q_rd_td, q_thd_td) via (7)-(8).

    p_th = m q_r_td^2 q_thd_td and rho_td = q_r_td / l0 - 1. epsilon is the energy (8) of the
    approximated system, i.e. with Assumption 2's Taylor polynomial for 1/(1+rho)^2, evaluated at
    touchdown: then the quadratic (9) passes through (rho_td, rho_d_td), so the approximate
    solution (11) starts at the given touchdown leg length *and* rate. At q_r_td = l0 (rho_td = 0,
    the report's setting) this is the exact (8); for a shorter touchdown leg the exact (8) would
    make (11) start with a slightly different q_rd.
    """
    omega_td = q_r_td**2 * q_thd_td / l0**2
    rho_td = q_r_td / l0 - 1
    # Second order in rho, exactly as in radial_quadratic (only omega^2/(1+rho)^2 is not polynomial).
    taylor_energy = sp.series(dimensionless_energy(), rho, 0, 3).removeO()
    eps_td = taylor_energy.subs({rho: rho_td, rho_d: q_rd_td / l0, omega: omega_td})
    return {"omega": omega_td, "epsilon": sp.simplify(eps_td), "rho_td": rho_td, "omega0": sp.sqrt(k / m)}


@cache
def touchdown_shifted_solution():
    """Eqs (21)-(22): q_r(t), q_th(t) with touchdown at t = 0, for q_r_td = l0 (b > 0).

    Substitutes t -> t + t_td into (11) and (19) with sin(omega0_hat t_td) = -a / b and
    cos(omega0_hat t_td) = -sqrt(b^2 - a^2) / b (compressing branch).
    """
    bp = sp.Symbol("b", positive=True)
    ph = event_phases()
    ph_td = ph["touchdown"].subs(ph["s"], -a / bp)
    q_r_t = l0 * (1 + radial_solution(t + ph_td / omega0_hat)).subs(b, bp)
    th_expr, t_td = leg_angle()
    q_th_t = th_expr.subs(t, t + t_td).subs(t_td, ph_td / omega0_hat).subs(b, bp)
    q_r_t = sp.expand(sp.expand_trig(sp.expand(q_r_t)))
    q_th_t = sp.expand(sp.expand_trig(sp.expand(q_th_t)))
    return q_r_t.subs(bp, b), q_th_t.subs(bp, b)


@cache
def touchdown_at_rest_length():
    """a, sqrt(b^2 - a^2) and omega0_hat from a touchdown state with q_r_td = l0 (eqs 7-11)."""
    td = touchdown_parameters()
    sol = radial_solution_parameters()
    sub = {omega: td["omega"], epsilon: td["epsilon"], omega0: td["omega0"]}
    at_l0 = {q_r_td: l0}
    a_td = sp.simplify(sol["a"].subs(sub).subs(at_l0))
    b2_td = sp.simplify(sol["b2"].subs(sub).subs(at_l0))
    w_td = sp.simplify(sol["omega0_hat"].subs(sub).subs(at_l0))
    root = sp.sqrt(sp.factor(sp.simplify(b2_td - a_td**2)))
    return a_td, root, w_td


@cache
def touchdown_state_solution():
    """Eqs (23)-(24): (21)-(22) with a, b, omega0_hat from the touchdown state (q_r_td = l0).

    sqrt(b^2 - a^2) = |q_rd_td| / (l0 omega0_hat): the touchdown radial speed fixes the amplitude.
    Returns (q_r(t), q_th(t), omega0_hat) with t from touchdown.
    """
    bp = sp.Symbol("b", positive=True)
    a_td, root, w_td = touchdown_at_rest_length()
    q_r_t, q_th_t = touchdown_shifted_solution()
    sub = {a: a_td, omega0_hat: w_td, omega: q_thd_td}

    def shift(expr):
        return sp.simplify(expr.subs(b, bp)).subs(sp.sqrt(bp**2 - a**2), root).subs(sub)

    return shift(q_r_t), shift(q_th_t), w_td


# --------------------------------------------------------------------------------------------
# Declaration: the helper kernels (called by this map and by the maps built on it) and the map.

_W0SQ = sp.Symbol("omega0_sq", positive=True)  # omega0^2 = k/m: omega0 itself only appears squared
_B2 = sym("b2")
_LAM, _MU, _NU = sym("lam"), sym("mu"), sym("nu")
_RHO_TD, _RHO_D_TD = sym("rho_td"), sym("rho_d_td")
PHASE, PHASE_TD, PHASE_LO = sym("phase"), sym("phase_td"), sym("phase_lo")
S_TD, S_LO = sym("s_td"), sym("s_lo")
_STANCE_PARAMS = ("m", "l0", "k", "g_s")


def _fields(*rows) -> Group:
    return Group("", tuple(Field(n, d, u) for n, d, u in rows))


def inversion_stages() -> tuple[Stage, ...]:
    """From lambda, mu, nu (named ``lam``, ``mu``, ``nu``) to omega0_hat, a, b and the touchdown phase.

    Eqs (10)-(12) with their guards: a real amplitude, a bottom leg length above 0, the touchdown
    leg length inside the oscillation. Shared by every radial solution of the form (9).
    """
    sol = solution_from_quadratic(_LAM, _MU, _NU)
    ph = event_phases()
    return (
        Stage(
            ((omega0_hat, sol["omega0_hat"]), (a, sol["a"]), (_B2, sol["b2"])),
            (
                Guard(
                    _B2 > 0,
                    "NO_REAL_SOLUTION",
                    "eq (10)-(11): real amplitude needs mu^2 - 4 lambda nu > 0",
                ),
            ),
            comment="eq (10)-(11): omega0_hat, a and b^2 of rho = a + b sin(omega0_hat t)",
        ),
        Stage(
            ((b, sp.sqrt(_B2)), (S_TD, leg_length_ratio(q_r_td))),
            (
                Guard(1 + a - b > 0, "FALL", "the leg collapses: l0 (1 + a - b) <= 0"),
                Guard(sp.Abs(S_TD) <= 1, "TOUCHDOWN_OUTSIDE_OSCILLATION", "(12) needs |s_td| <= 1"),
            ),
            comment="eq (12): sin(phase) at touchdown",
        ),
        Stage(
            ((PHASE_TD, ph["touchdown"].subs(ph["s"], S_TD)),),
            comment="eq (12), n = 0: compressing root",
        ),
    )


@cache
def solution_kernel() -> Kernel:
    """Touchdown state -> omega, omega0_hat, a, b of (11) and the touchdown phase of (12)."""
    to_w0sq = {omega0: sp.sqrt(_W0SQ)}
    # (8) at touchdown with Assumption 2's Taylor polynomial (see touchdown_parameters), written in
    # the dimensionless touchdown state, then (9)'s lambda, mu, nu and (10)-(11)'s inversion.
    taylor_energy = sp.series(dimensionless_energy(), rho, 0, 3).removeO()
    lam_, mu_, nu_ = radial_quadratic()
    return Kernel(
        name="geyer_solution",
        summary="Geyer et al.'s radial solution (11) from a touchdown state: omega, omega0_hat, a, b, phase.",
        equations=("7", "8", "9", "10", "11", "12"),
        args=tuple(catalog.TOUCHDOWN[i] for i in (0, 1, 3))
        + tuple(catalog.PARAMS[p] for p in _STANCE_PARAMS),
        steps=(
            Stage(
                (
                    (_W0SQ, k / m),
                    (omega, q_r_td**2 * q_thd_td / l0**2),
                    (_RHO_TD, q_r_td / l0 - 1),
                    (_RHO_D_TD, q_rd_td / l0),
                ),
                (Guard(q_rd_td < 0, "TOUCHDOWN_NOT_COMPRESSING", "stance starts compressing"),),
                comment="eq (7) at touchdown: omega0^2 = k/m, omega = p_th/(m l0^2), rho and its rate",
            ),
            Stage(
                ((epsilon, taylor_energy.subs({rho: _RHO_TD, rho_d: _RHO_D_TD}).subs(to_w0sq)),),
                comment="eq (8) at touchdown (Taylor polynomial of Assumption 2): epsilon = 2 E / (m l0^2)",
            ),
            Stage(
                ((_LAM, lam_.subs(to_w0sq)), (_MU, mu_.subs(to_w0sq)), (_NU, nu_)),
                comment="eq (9): rho_d^2 = lambda rho^2 + mu rho + nu",
            ),
            *inversion_stages(),
        ),
        outputs=_fields(
            ("omega", "omega = p_th / (m l0^2), eq (7)", "rad/s"),
            ("omega0_hat", "frequency of (11)", "rad/s"),
            ("a", "offset of rho(t) in (11)", ""),
            ("b", "amplitude of rho(t) in (11)", ""),
            ("phase_td", "touchdown phase omega0_hat t_td, eq (12)", "rad"),
            ("s_td", "sin(phase_td) = (q_r_td / l0 - 1 - a) / b", ""),
        ),
        check_inputs=False,
        check_outputs=False,
        module="geyer",
    )


@cache
def liftoff_phase_kernel() -> Kernel:
    """The liftoff phase of (14) (n = 0): the extending root of rho = q_r_lo / l0 - 1."""
    ph = event_phases()
    return Kernel(
        name="geyer_liftoff_phase",
        summary="Geyer et al.'s liftoff phase omega0_hat t_lo, eq (14) with n = 0.",
        equations=("14",),
        args=(
            Arg(a, "offset a of (11)"),
            Arg(b, "amplitude b of (11)"),
            catalog.PARAMS["l0"],
            catalog.PARAMS["q_r_lo"],
        ),
        steps=(
            Stage(
                ((S_LO, leg_length_ratio(q_r_lo)),),
                (Guard(sp.Abs(S_LO) <= 1, "NO_LIFTOFF", "eq (14) needs |s_lo| <= 1"),),
                comment="eq (14): sin(phase) at liftoff",
            ),
            Stage(((PHASE_LO, ph["liftoff"].subs(ph["s"], S_LO)),), comment="eq (14), n = 0: extending root"),
        ),
        outputs=_fields(
            ("phase_lo", "liftoff phase omega0_hat t_lo, eq (14)", "rad"),
            ("s_lo", "sin(phase_lo) = (q_r_lo / l0 - 1 - a) / b", ""),
        ),
        check_inputs=False,
        check_outputs=False,
        module="geyer",
    )


@cache
def state_at_phase(angle: tuple[sp.Basic, sp.Symbol] | None = None) -> tuple[sp.Basic, ...]:
    """(q_r, q_rd, q_th, q_thd) at the phase omega0_hat t = PHASE: (11), (19) and (17).

    ``angle``: another leg angle than (19), as :func:`leg_angle` returns it (q_th(t) and the
    symbol of the touchdown time), for a variant of the map."""
    rho_t = radial_solution(PHASE / omega0_hat)
    rho_dot = sp.diff(radial_solution(), t).subs(t, PHASE / omega0_hat)
    th_expr, t_td = angle or leg_angle()
    q_th_t = th_expr.subs({t: PHASE / omega0_hat, t_td: PHASE_TD / omega0_hat})
    exact_rate, _ = angular_rate()
    return (l0 * (1 + rho_t), l0 * rho_dot, q_th_t, exact_rate.subs(rho, rho_t))


@cache
def event_states(angle: tuple[sp.Basic, sp.Symbol] | None = None) -> dict[str, tuple[sp.Basic, ...]]:
    """The bottom (13) and liftoff (14) states, with the trigonometry of the event phases resolved.

    At the bottom sin = -1 and cos = 0; at liftoff sin(phase_lo) = s_lo and cos(phase_lo) =
    +sqrt(1 - s_lo^2) (the extending branch), at touchdown sin(phase_td) = s_td and cos(phase_td) =
    -sqrt(1 - s_td^2) (the compressing branch): no sine or cosine is left to evaluate at run time.
    ``angle``: as in :func:`state_at_phase`.
    """
    ph = event_phases()
    trig_td = {sp.cos(PHASE_TD): sp.cos(ph["touchdown"].subs(ph["s"], S_TD)), sp.sin(PHASE_TD): S_TD}
    phase_lo = ph["liftoff"].subs(ph["s"], S_LO)
    trig_lo = {sp.sin(PHASE_LO): sp.sin(phase_lo), sp.cos(PHASE_LO): sp.cos(phase_lo)}
    state = state_at_phase(angle)
    bottom = tuple(e.subs(PHASE, ph["bottom"]).subs(trig_td) for e in state)
    liftoff = tuple(e.subs(PHASE, PHASE_LO).subs(trig_lo).subs(trig_td) for e in state)
    for e in bottom + liftoff:
        assert not e.has(sp.sin, sp.cos), e
    return {"bottom": bottom, "liftoff": liftoff}


@cache
def state_kernel(angle: tuple[sp.Basic, sp.Symbol] | None = None) -> Kernel:
    """(q_r, q_rd, q_th, q_thd) at a phase omega0_hat t of (11), (19) and (17) (``angle``: as in
    :func:`state_at_phase`; a variant renames the kernel into its module, ``dataclasses.replace``)."""
    exprs = state_at_phase(angle)
    return Kernel(
        name="geyer_state",
        summary="Geyer et al.'s approximate stance state at the phase omega0_hat t: (11), (19), (17).",
        equations=("11", "17", "19"),
        args=(
            Arg(PHASE, "phase omega0_hat t [rad]"),
            Arg(PHASE_TD, "touchdown phase omega0_hat t_td [rad]"),
            catalog.TOUCHDOWN[2],
            Arg(omega, "omega = p_th / (m l0^2) [rad/s]"),
            Arg(omega0_hat, "frequency omega0_hat [rad/s]"),
            Arg(a, "offset a of (11)"),
            Arg(b, "amplitude b of (11)"),
            catalog.PARAMS["l0"],
        ),
        steps=(Stage(tuple(zip((sym(f.name) for f in catalog.POLAR), exprs, strict=True))),),
        outputs=catalog.TRAJECTORY,
        status=False,
        check_inputs=False,
        module="geyer",
        notes="The leg angle uses the linearization (18)-(19) of (17); the rate the exact (17) with the "
        "conserved angular momentum.",
    )


def event_times(prefix: str = "") -> tuple[tuple[sp.Symbol, sp.Basic], ...]:
    """``<prefix>t_bottom`` and ``<prefix>t_stance``: eqs (13)-(14) minus (12), times from touchdown."""
    ph = event_phases()
    w, ph_td = sym(prefix + "omega0_hat"), sym(prefix + "phase_td")
    return (
        (sym(prefix + "t_bottom"), (ph["bottom"] - ph_td) / w),
        (sym(prefix + "t_stance"), (sym(prefix + "phase_lo") - ph_td) / w),
    )


def stance_steps(
    q_thd: sp.Basic, prefix: str = "", angle: tuple[sp.Basic, sp.Symbol] | None = None
) -> tuple[Step, ...]:
    """Steps of Geyer et al.'s map from the touchdown state with leg angle rate ``q_thd``.

    Defines ``<prefix>`` + omega, omega0_hat, a, b, phase_td, phase_lo, t_bottom, t_stance and the
    bottom and liftoff states (``<prefix>bottom_q_r``, ...). Maps built on Geyer's call this with a
    corrected rate (a corrected angular momentum) and their own prefix; a variant with another leg
    angle than (19) passes it (``angle``, as in :func:`state_at_phase`).
    """
    sol, lo = solution_kernel(), liftoff_phase_kernel()

    def n(name: str) -> sp.Symbol:
        return sym(prefix + name)

    params = {p: catalog.PARAMS[p].symbol for p in _STANCE_PARAMS}
    states = event_states(angle)
    names = {x: n(x.name) for x in (omega, omega0_hat, a, b, PHASE_TD, PHASE_LO, S_TD, S_LO)}
    bottom = dict(zip((f.name for f in catalog.POLAR), states["bottom"], strict=True))
    liftoff = dict(zip((f.name for f in catalog.POLAR), states["liftoff"], strict=True))
    # The events' own definitions: q_rd = 0 at the bottom (13), q_r = q_r_lo at liftoff (14).
    bottom["q_rd"], liftoff["q_r"] = sp.S.Zero, q_r_lo
    return (
        Call(
            sol,
            {"q_r_td": q_r_td, "q_rd_td": q_rd_td, "q_thd_td": q_thd, **params},
            {o: prefix + o for o in sol.output_names},
            comment="eqs (7)-(12): Geyer et al.'s radial solution from the touchdown state",
        ),
        Call(
            lo,
            {"a": n("a"), "b": n("b"), "l0": l0, "q_r_lo": q_r_lo},
            {o: prefix + o for o in lo.output_names},
        ),
        Stage(
            (
                *event_times(prefix),
                *((n(f"bottom_{q}"), e.subs(names)) for q, e in bottom.items()),
                *((n(f"liftoff_{q}"), e.subs(names)) for q, e in liftoff.items()),
            ),
            (Guard(sp.Abs(n("liftoff_q_th")) < sp.pi / 2, "FALL", "the leg stays above horizontal"),),
            comment="eqs (13)-(14) minus (12), (11), (19), (17) at the bottom and at liftoff",
        ),
    )


def build_from(
    state: Kernel, helpers: tuple[Kernel, ...], angle: tuple[sp.Basic, sp.Symbol] | None = None
) -> MapBuild:
    """Geyer et al.'s map with the leg angle ``angle`` (None: (19); else as in :func:`state_at_phase`)
    and ``state``, the :func:`state_kernel` of that angle: the stance steps and the state a time after
    touchdown. ``helpers``: the kernels placed in the map's module."""

    def state_at(time: sp.Symbol) -> tuple[Step, ...]:
        return (
            stance_steps(q_thd_td)[0],
            Stage(((sym("phase_t"), PHASE_TD + omega0_hat * time),), comment="phase at t after touchdown"),
            Call(
                state,
                {
                    "phase": sym("phase_t"),
                    "phase_td": PHASE_TD,
                    "q_th_td": q_th_td,
                    "omega": omega,
                    "omega0_hat": omega0_hat,
                    "a": a,
                    "b": b,
                    "l0": l0,
                },
                {f.name: f.name for f in catalog.POLAR},
            ),
        )

    return MapBuild(steps=stance_steps(q_thd_td, angle=angle), state_at=state_at, helpers=helpers)


def _build(inp: MapInputs) -> MapBuild:
    return build_from(state_kernel(), (solution_kernel(), liftoff_phase_kernel(), state_kernel()))


MAPS = (
    MapSpec(
        name="geyer",
        title="Geyer et al.'s approximate stance map",
        section="3.1",
        equations=("7", "8", "9", "10", "11", "12", "13", "14", "17", "18", "19", "20"),
        params=_STANCE_PARAMS,
        requires=("constant_stiffness",),
        build=_build,
        inline=True,
        roles=("baseline", "accuracy-figure", "region", "default"),
        summary="angular momentum conserved (small sweep), 1/(1+rho)^2 by its Taylor polynomial (small "
        "compression)",
        notes="Assumption 1 (small sweep: angular momentum conserved), Assumption 2 (small compression: "
        "1/(1+rho)^2 ~ 1 - 2 rho + 3 rho^2). Leg-angle rates use the exact (17) with the conserved "
        "angular momentum; the leg angle uses its linearization (18)-(19).",
    ),
)
