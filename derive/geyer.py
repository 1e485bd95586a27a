"""Geyer et al.'s approximate stance map (report section 3.1, eqs 4-26), derived step by step.

Each function performs one step of the report's derivation with SymPy and returns its result;
:mod:`slipmaps.derive.report_eqs` compares the results with the printed equations and
:mod:`slipmaps.derive.modules` turns them into kernels. Results are cached.

Time origin: as in (11), the radial solution is rho(t) = a + b sin(omega0_hat t); touchdown,
bottom and liftoff happen at the phases omega0_hat t = pi - asin(s_td), 3 pi / 2 and
2 pi + asin(s_lo) (n = 0 in (12)-(14)), with s_x = (q_r_x / l0 - 1 - a) / b. Kernels report times
measured from touchdown.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from . import mechanics
from .symbols import (
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


@cache
def radial_solution_parameters():
    """Eq (11): omega0_hat, a, b of rho(t) = a + b sin(omega0_hat t), the inverse of (10).

    Inverting t = F(rho) of (10) gives rho = -mu / (2 lambda) + sqrt(mu^2 - 4 lambda nu) / (-2 lambda)
    sin(sqrt(-lambda) (t - t0)); the time origin t0 = 0 is the report's choice.
    """
    lam_, mu_, nu_ = radial_quadratic()
    w_hat = sp.sqrt(-lam_)
    a_ = -mu_ / (2 * lam_)
    b_ = sp.sqrt(mu_**2 - 4 * lam_ * nu_) / (-2 * lam_)
    return {"omega0_hat": sp.simplify(w_hat), "a": sp.simplify(a_), "b": b_, "b2": sp.simplify(b_**2)}


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


__all__ = [
    "assumption1_equations",
    "energy_assumption1",
    "dimensionless_energy",
    "taylor_inverse_square",
    "radial_quadratic",
    "antiderivative",
    "radial_solution_parameters",
    "radial_solution",
    "event_phases",
    "leg_length_ratio",
    "angular_rate",
    "leg_angle",
    "stance_time_general",
    "touchdown_parameters",
    "touchdown_shifted_solution",
]
