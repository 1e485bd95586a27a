"""Schwind and Koditschek's iterative stance map (report section 3.2, eqs 30-45), derived step by step.

From the Hamiltonian vector field (29) with the decompression stiffness k_d: the leg length q_r is
the independent variable of the decompression phase (p_r > 0), so each rate is divided by
dq_r/dt = p_r/m, giving (30)-(32); energy conservation H = E of (27) gives p_r = H^{-1} (33).
Integrating (30)-(32) from the bottom (q_r = q_r_b, p_r = 0) needs the mean-value approximation of
Theorem 1 (34)-(37): near the bottom p_r vanishes like (sigma - q_r_b)^(1/2), which fixes the
mean-value point (41); evaluating the integrands there gives the iteration (42)-(45).

The report's H^{-1}(q_r, q_th, p_th, E) appears in (42)-(44) as the unevaluated function
:data:`H_INV`, the iterates q_th_n, p_th_n as undefined functions; :func:`radial_momentum` is its
closed form. Results are cached.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ..model import mechanics
from ..symbols import E, g_s, k_d, l0, m, p_r, p_th, q_r, q_th, t

__all__ = [
    "sigma",
    "delta",
    "q_r_b",
    "q_th_b",
    "p_th_b",
    "t_b",
    "H_INV",
    "Q_TH_N",
    "P_TH_N",
    "Q_TH_NEXT",
    "P_TH_NEXT",
    "leg_length_derivatives",
    "radial_momentum",
    "bottom_energy",
    "near_bottom",
    "taylor_from_bottom",
    "theorem1_fraction",
    "integrand_exponents",
    "mean_value_fractions",
    "mean_value_point",
    "iteration_step",
    "next_radial_momentum",
]

sigma = sp.Symbol("sigma", positive=True)  # leg length as the integration variable
delta = sp.Symbol("delta", positive=True)  # sigma - q_r_b, the distance from the bottom
q_r_b = sp.Symbol("q_r_b", positive=True)  # bottom state: leg length, angle, angular momentum, time
q_th_b, p_th_b, t_b = sp.symbols("q_th_b p_th_b t_b", real=True)

H_INV = sp.Function("H_inv")  # H^{-1}(q_r, q_th, p_th, E) of (33), unevaluated
Q_TH_N, P_TH_N = sp.Function("q_th_n", real=True), sp.Function("p_th_n", real=True)  # n-th iterate
Q_TH_NEXT, P_TH_NEXT = sp.Function("q_th_n1", real=True), sp.Function("p_th_n1", real=True)  # (n+1)-th


@cache
def leg_length_derivatives(stiffness=k_d):
    """Eqs (30)-(32): (dt/dq_r, dq_th/dq_r, dp_th/dq_r), the rates of (29) divided by dq_r/dt = p_r/m."""
    dq_r, dq_th, _, dp_th = mechanics.hamiltonian_vector_field(stiffness)
    return tuple(sp.simplify(rate / dq_r) for rate in (sp.Integer(1), dq_th, dp_th))


@cache
def radial_momentum(stiffness=k_d):
    """Eq (33): p_r = H^{-1}(q_r, q_th, p_th, E), the root p_r > 0 (decompression) of H = E, H of (27)."""
    roots = sp.solve(sp.Eq(mechanics.hamiltonian(stiffness), E), p_r)
    # The two roots are +-sqrt(...); keep the positive one, told apart at a state where both are real.
    sample = {m: 1, l0: 1, stiffness: 1, g_s: 1, q_r: 1, q_th: 0, p_th: 0, E: 10}
    positive = [r for r in roots if r.subs(sample) > 0]
    if len(positive) != 1:
        raise RuntimeError(f"expected one positive root of H = E for p_r, got {roots}")
    return positive[0]


@cache
def bottom_energy(stiffness=k_d):
    """E of a bottom state: H of (27) at q_r = q_r_b, q_th = q_th_b, p_th = p_th_b and p_r = 0."""
    at_bottom = {q_r: q_r_b, q_th: q_th_b, p_th: p_th_b, p_r: 0}
    return sp.expand(mechanics.hamiltonian(stiffness).subs(at_bottom))


def near_bottom(expr, stiffness=k_d):
    """``expr`` (in q_r, q_th, p_th, p_r, E) at sigma = q_r_b + delta on the energy level of a bottom state.

    p_r becomes H^{-1}(q_r_b + delta, q_th_b, p_th_b, E_b): the angle and angular momentum are held at
    their bottom values, as in the integrands of (38)-(40), where H^{-1}(sigma, q_th, p_th, E) is
    integrated over sigma alone. Along the actual trajectory they vary too, but p_r^2 has the same
    leading term 2 m (dp_r/dt)_b delta either way (see :func:`taylor_from_bottom`).
    """
    expr = sp.sympify(expr).subs(p_r, radial_momentum(stiffness))
    at = {q_r: q_r_b + delta, q_th: q_th_b, p_th: p_th_b, E: bottom_energy(stiffness)}
    return expr.subs(at, simultaneous=True)


def taylor_from_bottom(expr, order, stiffness=k_d):
    """Taylor polynomial in t, to t^order, of ``expr`` along the flow of (29) from the bottom state at t = 0.

    The bottom state is (q_r_b, q_th_b, p_r = 0, p_th_b); the n-th coefficient is the n-th Lie
    derivative of ``expr`` along the vector field (29) there, divided by n!.
    """
    field = mechanics.hamiltonian_vector_field(stiffness)
    state = (q_r, q_th, p_r, p_th)
    at_bottom = {q_r: q_r_b, q_th: q_th_b, p_r: 0, p_th: p_th_b}
    term, total = sp.sympify(expr), sp.S.Zero
    for n in range(order + 1):
        total += term.subs(at_bottom) * t**n / sp.factorial(n)
        term = sum(term.diff(x) * rate for x, rate in zip(state, field, strict=True))
    return sp.expand(total)


def theorem1_fraction(r, s):
    """Eq (35)'s limit of (xi_x - a)/(x - a): ((s + 1)/(r + s + 1))^(1/r), under Theorem 1's conditions.

    ``r`` and ``s`` are the exponents of f(t) - K ~ (t - a)^r and g(t) ~ (t - a)^s at t -> a.
    """
    r, s = sp.nsimplify(r), sp.nsimplify(s)
    if r == 0 or not s > -1 or not r + s > -1:
        raise ValueError(f"Theorem 1 needs r != 0, s > -1, r + s > -1; got r = {r}, s = {s}")
    return ((s + 1) / (r + s + 1)) ** (1 / r)


@cache
def integrand_exponents(stiffness=k_d):
    """Exponents e of the leading terms c delta^e at the bottom (delta = sigma - q_r_b -> 0).

    Keys: ``"p_r"`` for H^{-1} itself; ``"38"``, ``"39"``, ``"40"`` for the integrands 1/H^{-1},
    1/(sigma^2 H^{-1}), sigma/H^{-1}; ``"q_th"`` and ``"p_th"`` for q_th(sigma) - q_th_b and
    p_th(sigma) - p_th_b, the integrals of (31) and (32) from the bottom (generic bottom:
    p_th_b != 0, sin q_th_b != 0).
    """
    integrands = {"p_r": p_r, "38": 1 / p_r, "39": 1 / (q_r**2 * p_r), "40": q_r / p_r}
    exponents = {key: near_bottom(expr, stiffness).leadterm(delta)[1] for key, expr in integrands.items()}
    _, dq_th, dp_th = leg_length_derivatives(stiffness)
    for key, rate in (("q_th", dq_th), ("p_th", dp_th)):
        coeff, power = near_bottom(rate, stiffness).leadterm(delta)
        integral = sp.integrate(coeff * sigma**power, (sigma, 0, delta))  # leading term of the increment
        exponents[key] = integral.leadterm(delta)[1]
    return exponents


@cache
def mean_value_fractions(stiffness=k_d):
    """(xi - q_r_b)/(q_r - q_r_b) from (35) for each of the integrals (38)-(40).

    As printed, (38)-(40) are (37) with f the whole integrand (r = its exponent, -1/2) and g = 1
    (s = 0): the right sides are f(xi) times int_{q_r_b}^{q_r} dsigma = q_r - q_r_b.
    """
    exponents = integrand_exponents(stiffness)
    return {key: theorem1_fraction(exponents[key], 0) for key in ("38", "39", "40")}


@cache
def mean_value_point(stiffness=k_d):
    """Eq (41): xi = q_r_b + F (q_r - q_r_b), F the fraction of (35) for the integral (38)."""
    return sp.expand(q_r_b + mean_value_fractions(stiffness)["38"] * (q_r - q_r_b))


@cache
def iteration_step(stiffness=k_d):
    """Eqs (42)-(44): the (n+1)-th iterate (t, q_th, p_th as functions of q_r) from the n-th.

    Each of (30)-(32) is integrated from the bottom, x(q_r) = x_b + int_{q_r_b}^{q_r} F(sigma) dsigma,
    with the integrand F evaluated on the n-th iterate (q_th = q_th_n(sigma), p_th = p_th_n(sigma),
    p_r = H^{-1}(sigma, q_th_n(sigma), p_th_n(sigma), E)) and the integral replaced by (37):
    F(xi) int_{q_r_b}^{q_r} dsigma, xi of (41).
    """
    xi = mean_value_point(stiffness)
    on_iterate = {q_r: xi, q_th: Q_TH_N(xi), p_th: P_TH_N(xi)}
    on_iterate[p_r] = H_INV(xi, Q_TH_N(xi), P_TH_N(xi), E)
    length = sp.integrate(sp.Integer(1), (sigma, q_r_b, q_r))
    bottom = (t_b, q_th_b, p_th_b)
    rates = leg_length_derivatives(stiffness)
    return tuple(
        x_b + rate.subs(on_iterate, simultaneous=True) * length
        for x_b, rate in zip(bottom, rates, strict=True)
    )


@cache
def next_radial_momentum(stiffness=k_d):
    """Eq (45), corrected: p_r of the (n+1)-th iterate at q_r, i.e. (33) on that iterate.

    p_r_(n+1)(q_r) = H^{-1}(q_r, q_th_(n+1)(q_r), p_th_(n+1)(q_r), E).
    """
    on_iterate = {q_th: Q_TH_NEXT(q_r), p_th: P_TH_NEXT(q_r)}
    return radial_momentum(stiffness).subs(on_iterate, simultaneous=True)
