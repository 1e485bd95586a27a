"""Helpers of the checks of report section 5.2, shared by its subsections (sec5_2_1, sec5_2_2,
sec5_2_bottom): the mean-value point xi as a symbol, H^{-1} on an iterate, the units of an
expression, and the checks that both halves (compression and decompression) run on their own
equations. It registers no equation.
"""

from __future__ import annotations

import sympy as sp

from ...maps import iterative_helpers
from ...maps.iterative_helpers import H_INV, P_TH_N, P_TH_NEXT, Q_TH_N, Q_TH_NEXT, E_ab, E_ba, q_r_b, sigma
from ...symbols import g_s, k_c, k_d, l0, m, p_th, q_r, q_r_td, q_th
from .. import expect, expect_nonzero, expect_zero, forms, iterates
from ..iterates import XI

QUARTER, HALF = sp.Rational(1, 4), sp.Rational(1, 2)
x_, a_, b_, e_ = sp.symbols("x a b e", real=True)  # dummy arguments of Lambdas


def expect_rows_zero(printed, derived, what: str) -> None:
    """Row-by-row ``expect_zero`` of two equal-length tuples, naming the row in the message."""
    for i, (p, d) in enumerate(zip(printed, derived, strict=True), start=1):
        expect_zero(p - d, f"{what} (row {i})")


def h_inv_on_iterate(energy, xi=XI):
    """H^{-1}(xi, q_th_n(xi), p_th_n(xi), energy), the unevaluated H^{-1} on the n-th iterate."""
    return H_INV(xi, Q_TH_N(xi), P_TH_N(xi), energy)


def closed_form(expr, stiffness):
    """``expr`` with H_INV replaced by its closed form (33) for ``stiffness`` and constant iterates
    q_th_n = q_th, p_th_n = p_th (the symbols)."""
    h_inv = iterative_helpers.radial_momentum(stiffness, e_).subs(
        {q_r: x_, q_th: a_, p_th: b_}, simultaneous=True
    )
    expr = expr.replace(H_INV, sp.Lambda((x_, a_, b_, e_), h_inv))
    return expr.replace(Q_TH_N, sp.Lambda(x_, q_th)).replace(P_TH_N, sp.Lambda(x_, p_th))


KG, METRE, SECOND = sp.symbols("kg metre second", positive=True)


def units(expr, stiffness, energy):
    """Units of ``expr`` (H_INV in closed form, constant iterates) as a monomial in kg, metre, second.

    Every symbol is scaled by its unit (m: kg; l0, q_r, q_r_td, q_r_b, xi: metre; g_s: metre/second^2;
    the stiffness: kg/second^2; the energy: kg metre^2/second^2; p_th: kg metre^2/second; q_th: none)
    and the scaled expression is divided by the unscaled one.
    """
    expr = closed_form(expr, stiffness)
    length = {s: s * METRE for s in (l0, q_r, q_r_td, q_r_b, XI)}
    scale = {
        **length,
        m: m * KG,
        g_s: g_s * METRE / SECOND**2,
        stiffness: stiffness * KG / SECOND**2,
        energy: energy * KG * METRE**2 / SECOND**2,
        p_th: p_th * KG * METRE**2 / SECOND,
    }
    return sp.simplify(expr.subs(scale, simultaneous=True) / expr)


def check_momentum_at_xi(key: str, stiffness, energy, sign: int, point, sample) -> None:
    """Shared by (127), (136), (142), (151): the printed p_r is (33) at xi, not at q_r (as (45)).

    ``point`` is the printed xi (in q_r and the start); ``sample`` a state where both roots are real.
    """
    printed = sign * sp.sqrt(
        2 * m * (energy - stiffness / 2 * (l0 - XI) ** 2 - m * g_s * XI * sp.cos(Q_TH_NEXT(XI)))
        - P_TH_NEXT(XI) ** 2 / XI**2
    )
    h_inv = iterative_helpers.radial_momentum(stiffness, energy, sign)
    at_xi = h_inv.subs({q_r: XI, q_th: Q_TH_NEXT(XI), p_th: P_TH_NEXT(XI)}, simultaneous=True)
    expect_zero(printed - at_xi, f"eq {key} printed p_r is p_r at the leg length xi on the (n+1)-th iterate")
    derived = iterative_helpers.next_radial_momentum(stiffness, energy, sign)
    corrected = iterates.next_momentum(stiffness, energy, sign)
    expect_zero(corrected - derived, f"eq {key} corrected p_r equals p_r at q_r on the (n+1)-th iterate")
    # Constant iterates (q_th = 0.1, p_th = 2), q_r away from xi.
    difference = (printed.subs(XI, point) - derived).replace(Q_TH_NEXT, sp.Lambda(x_, sp.Rational(1, 10)))
    value = sp.N(difference.replace(P_TH_NEXT, sp.Lambda(x_, 2)).subs(sample))
    expect(value.is_real is True, f"eq {key} printed and corrected p_r are real at the sample state {sample}")
    expect(abs(value) > 1, f"eq {key} printed p_r differs from p_r at q_r at the sample state {sample}")


COMPRESSION_SAMPLE = {
    m: 80,
    k_c: 20000,
    l0: 1,
    g_s: sp.Rational(981, 100),
    E_ab: 1500,
    q_r_td: 1,
    q_r: sp.Rational(9, 10),
}


DECOMPRESSION_SAMPLE = {
    m: 80,
    k_d: 20000,
    l0: 1,
    g_s: sp.Rational(981, 100),
    E_ba: 1500,
    q_r_b: sp.Rational(4, 5),
    q_r: 1,
}


def _weights(stiffness):
    """The weights g of (30)-(32) in the variant f = 1/H^{-1}: 1, 1/q_r^2, q_r."""
    return [
        iterative_helpers.weight_split(rate)[1]
        for rate in iterative_helpers.leg_length_derivatives(stiffness)
    ]


def weighted_integral_form(row: int, start, energy, stiffness):
    """Row ``row`` of (129)-(131), (145)-(147): int_start^{q_r} g/H^{-1}(xi) dsigma = f(xi) int g, int g
    computed (sp.integrate), as the check proves it."""
    h_inv = h_inv_on_iterate(energy)
    weight = _weights(stiffness)[row].subs(q_r, sigma)
    exact = sp.integrate(weight, (sigma, start, q_r)) / h_inv
    return forms((sp.Integral(weight / h_inv, (sigma, start, q_r)), exact))


def check_weighted_integrals(keys, start, energy, stiffness) -> None:
    """Shared by (129)-(131) and (145)-(147): f(xi) int_start^{q_r} g dsigma with g of the rates."""
    h_inv = h_inv_on_iterate(energy)
    printed = (
        1 / h_inv * (q_r - start),
        1 / h_inv * (1 / start - 1 / q_r),
        1 / (2 * h_inv) * (q_r**2 - start**2),
    )
    weights = _weights(stiffness)
    expect_zero(weights[0] - 1, f"eq {keys[0]} the weight of (116)/(30) is g = 1")
    expect_zero(weights[1] - 1 / q_r**2, f"eq {keys[1]} the weight of (117)/(31) is g = 1/sigma^2")
    expect_zero(weights[2] - q_r, f"eq {keys[2]} the weight of (118)/(32) is g = sigma")
    for row, (key, right) in enumerate(zip(keys, printed, strict=True)):
        (form,) = weighted_integral_form(row, start, energy, stiffness)
        expect_zero(right - form.rhs, f"eq {key} printed right side is f(xi) times the exact int g")


def check_dropped_p_th(eq, anchor, printed, corrected, derived, stiffness, energy) -> None:
    """(134), (149): the printed q_th iterate lacks the factor p_th_n(xi); the corrected one is the
    variant of the derived integral, and the units show it."""
    half = "(117) by the variant from touchdown" if eq == "134" else "(31) by the variant from the bottom"
    expect_nonzero(
        printed - derived, f"eq {eq} printed iterate differs from {half.split(' by')[0]} by the variant"
    )
    expect_zero(corrected - derived, f"eq {eq} corrected iterate equals {half}")
    expect_zero(
        (derived - anchor) - P_TH_N(XI) * (printed - anchor),
        f"eq {eq} printed increment lacks exactly p_th_n(xi)",
    )
    expect_zero(
        units(corrected - anchor, stiffness, energy) - 1,
        f"eq {eq} corrected increment of q_th is dimensionless",
    )
    expect_zero(
        units(printed - anchor, stiffness, energy) - SECOND / (KG * METRE**2),
        f"eq {eq} printed increment of q_th is in s/(kg m^2)",
    )
