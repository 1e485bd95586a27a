"""Report section 5 (variable stiffness): section 5.2, the iterative stance map, rows 114-151.

Section 5.2 splits the stance at the bottom: the compression half (apex to bottom, 5.2.1, eqs
114-136: stiffness k_c, energy E_ab, p_r = -H_ab^{-1} < 0, integrated from touchdown) and the
decompression half (bottom to apex, 5.2.2, eqs 137-151: k_d, E_ba, from the bottom, the map of
section 3.2). Each half comes twice: with the mean-value rule of (38)-(40) (f the whole integrand,
g = 1) and with the variant of (128)/(144) (f = 1/H^{-1}, the weight g = 1, 1/sigma^2, sigma
integrated exactly). Each check compares a transcription of a printed display, typed as printed
(errors included), with :mod:`slipmaps.derive.model.mechanics` (114, 115, 137) or
:mod:`slipmaps.derive.maps.iterative` (the rest). The iterates are checked with the mean-value point
xi_hat_r left as a symbol; the point itself is checked where it is printed, (123), (132) and (143).

Rows 78-113 (section 5.1) and 152-154 (the bottom leg length closing section 5.2) belong to this
module too; they are not registered yet.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ..maps import iterative
from ..maps.iterative import (
    BOTTOM,
    H_INV,
    P_TH_N,
    P_TH_NEXT,
    Q_TH_N,
    Q_TH_NEXT,
    TOUCHDOWN,
    E_ab,
    E_ba,
    p_th_b,
    p_th_td,
    q_r_b,
    q_th_b,
    sigma,
    t_b,
    t_td,
)
from ..model import mechanics
from ..symbols import E, g_s, k_c, k_d, l0, m, p_r, p_th, q_r, q_r_td, q_th, q_th_td
from . import definition, equation, expect, expect_nonzero, expect_zero

XI = sp.Symbol("xi", positive=True)  # the mean-value point xi_hat_r, as a symbol
QUARTER, HALF = sp.Rational(1, 4), sp.Rational(1, 2)
_x, _a, _b, _e = sp.symbols("x a b e", real=True)  # dummy arguments of Lambdas


def _expect_rows_zero(printed, derived, what: str) -> None:
    """Row-by-row ``expect_zero`` of two equal-length tuples, naming the row in the message."""
    for i, (p, d) in enumerate(zip(printed, derived, strict=True), start=1):
        expect_zero(p - d, f"{what} (row {i})")


def _h_inv(energy, xi=XI):
    """H^{-1}(xi, q_th_n(xi), p_th_n(xi), energy), the unevaluated H^{-1} on the n-th iterate."""
    return H_INV(xi, Q_TH_N(xi), P_TH_N(xi), energy)


def _closed_form(expr, stiffness):
    """``expr`` with H_INV replaced by its closed form (33) for ``stiffness`` and constant iterates
    q_th_n = q_th, p_th_n = p_th (the symbols)."""
    h_inv = iterative.radial_momentum(stiffness, _e).subs({q_r: _x, q_th: _a, p_th: _b}, simultaneous=True)
    expr = expr.replace(H_INV, sp.Lambda((_x, _a, _b, _e), h_inv))
    return expr.replace(Q_TH_N, sp.Lambda(_x, q_th)).replace(P_TH_N, sp.Lambda(_x, p_th))


_KG, _METRE, _SECOND = sp.symbols("kg metre second", positive=True)


def _units(expr, stiffness, energy):
    """Units of ``expr`` (H_INV in closed form, constant iterates) as a monomial in kg, metre, second.

    Every symbol is scaled by its unit (m: kg; l0, q_r, q_r_td, q_r_b, xi: metre; g_s: metre/second^2;
    the stiffness: kg/second^2; the energy: kg metre^2/second^2; p_th: kg metre^2/second; q_th: none)
    and the scaled expression is divided by the unscaled one.
    """
    expr = _closed_form(expr, stiffness)
    length = {s: s * _METRE for s in (l0, q_r, q_r_td, q_r_b, XI)}
    scale = {
        **length,
        m: m * _KG,
        g_s: g_s * _METRE / _SECOND**2,
        stiffness: stiffness * _KG / _SECOND**2,
        energy: energy * _KG * _METRE**2 / _SECOND**2,
        p_th: p_th * _KG * _METRE**2 / _SECOND,
    }
    return sp.simplify(expr.subs(scale, simultaneous=True) / expr)


# ============================================================================================
# Section 5.2: iterative approximate stance map for variable stiffness, eqs 114-151.
# --------------------------------------------------------------------------------------------
# Section 5.2.1: apex to bottom (compression, k_c, E_ab), Hamiltonian (114)-(119).


@equation(
    "114",
    "compression Hamiltonian H_ab (k_c)",
    "verified",
    "Legendre transform of (1) with k = k_c; (27) with k_c.",
)
def check_eq114() -> None:
    """Printed: H_ab = (p_r^2 + p_th^2/q_r^2)/(2 m) + k_c/2 (l0 - q_r)^2 + m g_s q_r cos(q_th)."""
    printed = (p_r**2 + p_th**2 / q_r**2) / (2 * m) + k_c / 2 * (l0 - q_r) ** 2 + m * g_s * q_r * sp.cos(q_th)
    expect_zero(
        printed - mechanics.hamiltonian(k_c), "eq 114 printed H_ab equals the Legendre transform of (1)"
    )


@equation("115", "Hamiltonian vector field of H_ab", "verified", "Hamilton's equations (28) of (114).")
def check_eq115() -> None:
    """Printed: X_H_ab = (p_r/m, p_th/(m q_r^2), p_th^2/(m q_r^3) + k_c (l0 - q_r) - m g_s cos q_th,
    m g_s q_r sin q_th).
    """
    printed = (
        p_r / m,
        p_th / (m * q_r**2),
        p_th**2 / (m * q_r**3) + k_c * (l0 - q_r) - m * g_s * sp.cos(q_th),
        m * g_s * q_r * sp.sin(q_th),
    )
    _expect_rows_zero(
        printed,
        mechanics.hamiltonian_vector_field(k_c),
        "eq 115 printed X_H equals Hamilton's equations of (114)",
    )


@equation("116", "compression dt/dq_r = m/p_r", "verified", "As (30): dq_r/dt = p_r/m of (115), p_r < 0.")
@equation("117", "compression dq_th/dq_r = p_th/(q_r^2 p_r)", "verified", "As (31), from (115).")
@equation("118", "compression dp_th/dq_r = m^2 g_s q_r sin(q_th)/p_r", "verified", "As (32), from (115).")
def check_eq116_118() -> None:
    """Printed: (116) dt_s/dq_r = m/p_r; (117) dq_th/dq_r = p_th/(q_r^2 p_r);
    (118) dp_th/dq_r = m^2 g_s q_r sin(q_th)/p_r, with p_r = p_r(q_r, q_th, p_th) of (119).
    """
    printed = (m / p_r, p_th / (q_r**2 * p_r), m**2 * g_s * q_r * sp.sin(q_th) / p_r)
    _expect_rows_zero(
        printed,
        iterative.leg_length_derivatives(k_c),
        "eqs 116-118 printed rates equal the rates of (115) divided by dq_r/dt = p_r/m",
    )


@equation(
    "119",
    "compression p_r = -H_ab^{-1}(q_r, q_th, p_th, E_ab)",
    "corrected",
    "The sign is right (p_r < 0 in compression: the negative root of H_ab = E_ab), the stiffness is "
    "not: the printed root has k_d, so H_ab of (114) at it equals E_ab + (k_c - k_d)/2 (l0 - q_r)^2. "
    "Corrected: p_r = -sqrt(2 m (E_ab - k_c/2 (l0 - q_r)^2 - m g_s q_r cos q_th) - p_th^2/q_r^2). "
    "(127) and (136) print k_c.",
)
def check_eq119() -> None:
    """Printed: p_r = -H_ab^{-1}
    = -sqrt(2 m (E_ab - k_d/2 (l0 - q_r)^2 - m g_s q_r cos(q_th)) - p_th^2/q_r^2)."""
    printed = -sp.sqrt(
        2 * m * (E_ab - k_d / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(q_th)) - p_th**2 / q_r**2
    )
    corrected = -sp.sqrt(
        2 * m * (E_ab - k_c / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(q_th)) - p_th**2 / q_r**2
    )
    derived = iterative.radial_momentum(k_c, E_ab, -1)
    hamiltonian = mechanics.hamiltonian(k_c)
    # Both roots are negative: they differ exactly when their squares do.
    expect_zero(
        printed**2 - derived**2 - m * (k_c - k_d) * (l0 - q_r) ** 2,
        "eq 119 printed p_r^2 exceeds the root's by m (k_c - k_d) (l0 - q_r)^2",
    )
    expect_nonzero(printed**2 - derived**2, "eq 119 printed p_r differs from the root of H_ab = E_ab")
    expect_zero(
        hamiltonian.subs(p_r, printed) - E_ab - (k_c - k_d) / 2 * (l0 - q_r) ** 2,
        "eq 119 H_ab at the printed p_r equals E_ab + (k_c - k_d)/2 (l0 - q_r)^2",
    )
    expect_zero(corrected - derived, "eq 119 corrected p_r equals the negative root of H_ab = E_ab")
    expect_zero(hamiltonian.subs(p_r, corrected) - E_ab, "eq 119 H_ab at the corrected p_r equals E_ab")
    sample = {m: 80, k_c: 20000, l0: 1, g_s: sp.Rational(981, 100), E_ab: 1500, q_r: 1, q_th: 0, p_th: 0}
    expect(
        bool(corrected.subs(sample) < 0), "eq 119 corrected p_r is negative (compression) at a sample state"
    )


definition(
    "120",
    "mean-value approximation of int_{q_r_td}^{q_r} 1/H_ab^{-1} dsigma",
    "(37) with f = the whole integrand and g = 1, from touchdown: (38) for the compression half. An "
    "approximation; its point is (123).",
)
definition(
    "121",
    "mean-value approximation of int_{q_r_td}^{q_r} 1/(sigma^2 H_ab^{-1}) dsigma",
    "As (120), f = 1/(sigma^2 H_ab^{-1}); (39). OCR: 'q_th xi_x)' for q_th(xi_x) (a dropped parenthesis).",
)
definition(
    "122",
    "mean-value approximation of int_{q_r_td}^{q_r} sigma/H_ab^{-1} dsigma",
    "As (120), f = sigma/H_ab^{-1}; (40).",
)


# --------------------------------------------------------------------------------------------
# Section 5.2.1: the mean-value point (123)/(132) and the iterates (124)-(127), (133)-(136).


def _printed_compression_point():
    """(123) = (132) as printed: xi_hat_x = 3/4 q_r_td + 1/4 q_r."""
    return sp.Rational(3, 4) * q_r_td + QUARTER * q_r


@cache
def _leading_term_time(step):
    """Time row of a compression iterate minus t_td on the leading term of H^{-1} at the bottom.

    H^{-1}(sigma, ...) -> c (sigma - q_r_b)^(1/2) (c > 0, the coefficient of (41)); returns the
    iterate's t(q_r) - t_td and the exact int_{q_r_td}^{q_r} m/(-c (sigma - q_r_b)^(1/2)) dsigma.
    """
    c = sp.Symbol("c", positive=True)
    leading = sp.Lambda((_x, _a, _b, _e), c * sp.sqrt(_x - q_r_b))
    rule = step.replace(H_INV, leading) - t_td
    exact = sp.integrate(-m / (c * sp.sqrt(sigma - q_r_b)), (sigma, q_r_td, q_r))
    return rule, exact


def _check_compression_point(key: str, weighted: bool) -> None:
    """Shared by (123) and (132): where Theorem 1 puts the point of the compression integrals."""
    printed = _printed_compression_point()
    variant = "f = 1/H^{-1}, g = 1, 1/sigma^2, sigma" if weighted else "f = integrand, g = 1"
    # Touchdown: H^{-1} = |p_r_td| > 0, the integrands are regular (r = 1, s = 0): (35) gives 1/2.
    exponents = iterative.integrand_exponents(k_c, "touchdown")  # order of the first nonzero Taylor term
    for integral in ("38", "39", "40"):
        expect_zero(
            exponents[integral] - 1, f"eq {key} integrand of ({integral}) - its touchdown value ~ delta^1"
        )
    for integral, fraction in iterative.mean_value_fractions(k_c, "touchdown", weighted).items():
        expect_zero(fraction - HALF, f"eq {key} (35) at touchdown ({variant}) gives 1/2 for ({integral})")
    expect_nonzero(
        (printed - q_r_td) / (q_r - q_r_td) - HALF,
        f"eq {key} printed fraction from touchdown is not (35)'s 1/2",
    )
    # Bottom: H^{-1} ~ (sigma - q_r_b)^(1/2), the integrands ~ (sigma - q_r_b)^(-1/2): 1/4 from the bottom.
    for integral, fraction in iterative.mean_value_fractions(k_c, "bottom", weighted).items():
        expect_zero(fraction - QUARTER, f"eq {key} (35) at the bottom ({variant}) gives 1/4 for ({integral})")
    whole = iterative.mean_value_point(k_c, q_r_td)  # the point of int_{q_r_td}^{q_r_b}
    corrected = sp.Rational(3, 4) * q_r_b + QUARTER * q_r_td
    expect_zero(
        corrected - whole, f"eq {key} corrected xi of the whole half equals q_r_b + 1/4 (q_r_td - q_r_b)"
    )
    printed_whole = printed.subs(q_r, q_r_b)
    expect_nonzero(printed_whole - whole, f"eq {key} printed xi at q_r = q_r_b differs from (35)'s point")
    expect_zero(printed_whole - (q_r_b + q_r_td - whole), f"eq {key} printed xi at q_r_b is the mirror image")
    # Leading term c (sigma - q_r_b)^(-1/2) over the whole half: exact at the corrected xi, a fraction
    # 1/sqrt(3) of it at the printed one.
    span = q_r_td - q_r_b
    exact = sp.integrate((sigma - q_r_b) ** -HALF, (sigma, q_r_b, q_r_td))
    expect_zero((whole - q_r_b) ** -HALF * span - exact, f"eq {key} corrected xi reproduces the leading term")
    ratio = (printed_whole - q_r_b) ** -HALF * span / exact
    expect_zero(ratio - 1 / sp.sqrt(3), f"eq {key} printed xi gives 1/sqrt(3) of the leading-term integral")
    # Linear spring, no gravity, p_th = 0, touchdown at l0 with amplitude A: the time from touchdown to
    # the bottom is pi/2 sqrt(m/k_c); the rule gives 4/sqrt(7) sqrt(m/k_c) at the corrected xi and
    # 4/sqrt(15) sqrt(m/k_c) at the printed one.
    amplitude, u = sp.symbols("A u", positive=True)
    spring = {q_th: 0, p_th: 0, g_s: 0, E_ab: k_c * amplitude**2 / 2}
    h_inv = iterative.radial_momentum(k_c, E_ab).subs(spring)
    expect_zero(
        (h_inv**2).subs(q_r, l0 - amplitude * u) - m * k_c * amplitude**2 * (1 - u**2),
        f"eq {key} spring: H^{{-1}} = sqrt(m k_c) A sqrt(1 - u^2) at sigma = l0 - A u",
    )
    exact = m / sp.sqrt(m * k_c) * sp.integrate(1 / sp.sqrt(1 - u**2), (u, 0, 1))  # int m/H^{-1} dsigma
    bottom = sp.Symbol("b", positive=True)  # q_r_b = l0 - A > 0
    limits = {q_r_b: bottom, q_r_td: bottom + amplitude}
    for name, xi, value in (
        ("corrected", whole, 4 / sp.sqrt(7)),
        ("printed", printed_whole, 4 / sp.sqrt(15)),
    ):
        square = sp.factor((h_inv**2).subs(q_r, xi.subs(limits)).subs(l0, bottom + amplitude))
        time = m / sp.sqrt(square) * amplitude  # (38) over the whole half: m/H^{-1}(xi) (q_r_td - q_r_b)
        expect_zero(time - value * sp.sqrt(m / k_c), f"eq {key} spring: the rule at the {name} xi")
    # The corrected iterate as a function of q_r (iterative.compression_step): the difference of two
    # integrals anchored at the bottom. It starts at the touchdown state, reaches the bottom with the
    # whole-half point, and is exact on the leading term for every q_r; the printed one is not.
    step = iterative.compression_step(k_c, E_ab, weighted)
    _expect_rows_zero(
        [row.subs(q_r, q_r_td) for row in step],
        TOUCHDOWN[1:],
        f"eq {key} corrected iterate equals the touchdown state at q_r = q_r_td",
    )
    whole_rule = iterative.iteration_step(k_c, whole, -1, TOUCHDOWN, E_ab, weighted)
    _expect_rows_zero(
        [row.subs(q_r, q_r_b) for row in step],
        [row.subs(q_r, q_r_b) for row in whole_rule],
        f"eq {key} corrected iterate at q_r_b equals the rule with the whole-half point",
    )
    rule, exact = _leading_term_time(step[0])
    expect_zero(rule - exact, f"eq {key} corrected iterate reproduces the leading-term time integral")
    printed_step = iterative.iteration_step(k_c, printed, -1, TOUCHDOWN, E_ab, weighted)
    rule, exact = _leading_term_time(printed_step[0])
    expect_nonzero(rule - exact, f"eq {key} printed iterate misses the leading-term time integral")


@equation(
    "123",
    "compression mean-value point xi = 3/4 q_r_td + 1/4 q_r",
    "corrected",
    "The point of (41) put at the wrong end. Theorem 1 (35) is a limit at the lower end a of the "
    "integral: at touchdown the integrands of (120)-(122) are regular (H^{-1} = |p_r_td| > 0, r = 1, "
    "s = 0) and (35) gives the midpoint fraction 1/2, not 1/4; the 1/4 belongs to the singular end, "
    "the bottom (H^{-1} ~ (sigma - q_r_b)^(1/2), r = -1/2), measured from there. For the whole half "
    "the point is xi = 3/4 q_r_b + 1/4 q_r_td; the printed one, at q_r = q_r_b, is its mirror image "
    "3/4 q_r_td + 1/4 q_r_b. On the leading term c (sigma - q_r_b)^(-1/2) the corrected point is "
    "exact, the printed one gives 1/sqrt(3) = 0.577 of the integral; for a linear spring (g_s = 0, "
    "p_th = 0) touchdown to bottom takes pi/2 sqrt(m/k_c), the rule gives 4/sqrt(7) (-3.7%) at the "
    "corrected and 4/sqrt(15) (-34%) at the printed point. Registered corrected iterate (q_r between "
    "q_r_b and q_r_td): int_{q_r_td}^{q_r} F = int_{q_r_b}^{q_r} F - int_{q_r_b}^{q_r_td} F, each by "
    "(37) at (41)'s point of its upper limit: x(q_r) = x_td + F(xi(q_r)) (q_r - q_r_b) - "
    "F(xi(q_r_td)) (q_r_td - q_r_b), xi(x) = 3/4 q_r_b + 1/4 x, F the integrand of (116)-(118) on the "
    "n-th iterate; it is x_td at touchdown and exact on the leading term for every q_r.",
)
def check_eq123() -> None:
    """Printed: xi_hat_x = 3/4 q_r_td + 1/4 q_r (for the integrals (120)-(122), from q_r_td to q_r)."""
    _check_compression_point("123", weighted=False)


def _printed_compression_iterate(energy_of_t=E_ab):
    """(124)-(126) as printed, at the symbolic point xi; (124) prints E, passed as ``energy_of_t``."""
    h_inv = _h_inv(E_ab)
    step = q_r - q_r_td
    return (
        t_td - m / _h_inv(energy_of_t) * step,
        q_th_td - P_TH_N(XI) / (XI**2 * h_inv) * step,
        p_th_td - m**2 * g_s * XI * sp.sin(Q_TH_N(XI)) / h_inv * step,
    )


@equation(
    "124",
    "compression iterate of the time t_(n+1)(q_r)",
    "verified",
    "(116) integrated from touchdown with (120) at the point xi: t_td - m/H_ab^{-1}(xi, ...) (q_r - "
    "q_r_td); the minus sign is p_r = -H_ab^{-1}. The printed E is E_ab. Verified as the rule at xi; "
    "the point xi of (123) is corrected there, with the corrected iterate.",
)
@equation(
    "125",
    "compression iterate of the leg angle q_th_(n+1)(q_r)",
    "verified",
    "(117) integrated from touchdown with (121) at xi: q_th_td - p_th_n(xi)/(xi^2 H_ab^{-1}) (q_r - "
    "q_r_td). Point: see (123).",
)
@equation(
    "126",
    "compression iterate of the angular momentum p_th_(n+1)(q_r)",
    "verified",
    "(118) integrated from touchdown with (122) at xi: p_th_td - m^2 g_s xi sin(q_th_n(xi))/H_ab^{-1} "
    "(q_r - q_r_td). Point: see (123).",
)
def check_eq124_126() -> None:
    """Printed, with H^{-1}_n = H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ab):
    (124) t_(n+1)(q_r) = t_td - m/H^{-1}_n (q_r - q_r_td)   (printed with E for E_ab);
    (125) q_th_(n+1)(q_r) = q_th_td - p_th_n(xi)/(xi^2 H^{-1}_n) (q_r - q_r_td);
    (126) p_th_(n+1)(q_r) = p_th_td - m^2 g_s xi sin(q_th_n(xi))/H^{-1}_n (q_r - q_r_td).
    """
    derived = iterative.iteration_step(k_c, XI, -1, TOUCHDOWN, E_ab)
    _expect_rows_zero(
        _printed_compression_iterate(),
        derived,
        "eqs 124-126 printed iterate equals (116)-(118) integrated from touchdown with (37) at xi",
    )
    expect_nonzero(
        _printed_compression_iterate(E)[0] - derived[0], "eq 124 with E distinct from E_ab differs: E is E_ab"
    )


def _check_momentum_at_xi(key: str, stiffness, energy, sign: int, point, sample) -> None:
    """Shared by (127), (136), (142), (151): the printed p_r is (33) at xi, not at q_r (as (45)).

    ``point`` is the printed xi (in q_r and the start); ``sample`` a state where both roots are real.
    """
    printed = sign * sp.sqrt(
        2 * m * (energy - stiffness / 2 * (l0 - XI) ** 2 - m * g_s * XI * sp.cos(Q_TH_NEXT(XI)))
        - P_TH_NEXT(XI) ** 2 / XI**2
    )
    h_inv = iterative.radial_momentum(stiffness, energy, sign)
    at_xi = h_inv.subs({q_r: XI, q_th: Q_TH_NEXT(XI), p_th: P_TH_NEXT(XI)}, simultaneous=True)
    expect_zero(printed - at_xi, f"eq {key} printed p_r is p_r at the leg length xi on the (n+1)-th iterate")
    derived = iterative.next_radial_momentum(stiffness, energy, sign)
    corrected = sign * sp.sqrt(
        2 * m * (energy - stiffness / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(Q_TH_NEXT(q_r)))
        - P_TH_NEXT(q_r) ** 2 / q_r**2
    )
    expect_zero(corrected - derived, f"eq {key} corrected p_r equals p_r at q_r on the (n+1)-th iterate")
    # Constant iterates (q_th = 0.1, p_th = 2), q_r away from xi.
    difference = (printed.subs(XI, point) - derived).replace(Q_TH_NEXT, sp.Lambda(_x, sp.Rational(1, 10)))
    value = sp.N(difference.replace(P_TH_NEXT, sp.Lambda(_x, 2)).subs(sample))
    expect(value.is_real is True, f"eq {key} printed and corrected p_r are real at the sample state {sample}")
    expect(abs(value) > 1, f"eq {key} printed p_r differs from p_r at q_r at the sample state {sample}")


_COMPRESSION_SAMPLE = {
    m: 80,
    k_c: 20000,
    l0: 1,
    g_s: sp.Rational(981, 100),
    E_ab: 1500,
    q_r_td: 1,
    q_r: sp.Rational(9, 10),
}
_DECOMPRESSION_SAMPLE = {
    m: 80,
    k_d: 20000,
    l0: 1,
    g_s: sp.Rational(981, 100),
    E_ba: 1500,
    q_r_b: sp.Rational(4, 5),
    q_r: 1,
}


@equation(
    "127",
    "compression iterate of the radial momentum p_r_(n+1)(q_r)",
    "corrected",
    "As (45): the printed -sqrt(2 m (E_ab - k_c/2 (l0 - xi)^2 - m g_s xi cos q_th_(n+1)(xi)) - "
    "p_th_(n+1)(xi)^2/xi^2) is p_r at the leg length xi, not at q_r. By (119) corrected (k_c, as "
    "printed here): p_r_(n+1)(q_r) = -H_ab^{-1}(q_r, q_th_(n+1)(q_r), p_th_(n+1)(q_r), E_ab). OCR: the "
    "tag (127) is printed inside the square root.",
)
def check_eq127() -> None:
    """Printed: p_r_(n+1)(q_r) = -sqrt(2 m (E_ab - k_c/2 (l0 - xi)^2 - m g_s xi cos(q_th_(n+1)(xi)))
    - p_th_(n+1)(xi)^2/xi^2)."""
    _check_momentum_at_xi("127", k_c, E_ab, -1, _printed_compression_point(), _COMPRESSION_SAMPLE)


definition(
    "128",
    "second mean-value variant: f = 1/H_ab^{-1}",
    "The choice of f in Theorem 1 for all three integrals, g the rest (1, 1/sigma^2, sigma), "
    "integrated exactly; a choice, nothing to derive. Its consequences are checked in (129)-(136).",
)


def _check_weighted_integrals(keys, start, energy, stiffness) -> None:
    """Shared by (129)-(131) and (145)-(147): f(xi) int_start^{q_r} g dsigma with g of the rates."""
    h_inv = _h_inv(energy)
    printed = (
        1 / h_inv * (q_r - start),
        1 / h_inv * (1 / start - 1 / q_r),
        1 / (2 * h_inv) * (q_r**2 - start**2),
    )
    weights = [iterative.weight_split(rate)[1] for rate in iterative.leg_length_derivatives(stiffness)]
    expect_zero(weights[0] - 1, f"eq {keys[0]} the weight of (116)/(30) is g = 1")
    expect_zero(weights[1] - 1 / q_r**2, f"eq {keys[1]} the weight of (117)/(31) is g = 1/sigma^2")
    expect_zero(weights[2] - q_r, f"eq {keys[2]} the weight of (118)/(32) is g = sigma")
    for key, right, weight in zip(keys, printed, weights, strict=True):
        integral = sp.integrate(weight.subs(q_r, sigma), (sigma, start, q_r))
        expect_zero(right - integral / h_inv, f"eq {key} printed right side is f(xi) times the exact int g")


@equation(
    "129",
    "variant: int_{q_r_td}^{q_r} 1/H_ab^{-1} ~ (q_r - q_r_td)/H_ab^{-1}(xi)",
    "verified",
    "(37) with f = 1/H_ab^{-1} at xi and g = 1: int g = q_r - q_r_td (sp.integrate). The same "
    "display as (120).",
)
@equation(
    "130",
    "variant: int 1/(sigma^2 H_ab^{-1}) ~ (1/q_r_td - 1/q_r)/H_ab^{-1}(xi)",
    "verified",
    "(37) with f = 1/H_ab^{-1} at xi and g = 1/sigma^2: int_{q_r_td}^{q_r} sigma^-2 dsigma = "
    "1/q_r_td - 1/q_r (sp.integrate).",
)
@equation(
    "131",
    "variant: int sigma/H_ab^{-1} ~ (q_r^2 - q_r_td^2)/(2 H_ab^{-1}(xi))",
    "verified",
    "(37) with f = 1/H_ab^{-1} at xi and g = sigma: int_{q_r_td}^{q_r} sigma dsigma = (q_r^2 - q_r_td^2)/2.",
)
def check_eq129_131() -> None:
    """Printed, with H^{-1} = H_ab^{-1}(xi, q_th(xi), p_th(xi), E_ab): the integrals from q_r_td to q_r of
    1/H^{-1}, 1/(sigma^2 H^{-1}), sigma/H^{-1} are ~ (q_r - q_r_td)/H^{-1}, (1/q_r_td - 1/q_r)/H^{-1},
    (q_r^2 - q_r_td^2)/(2 H^{-1}).
    """
    _check_weighted_integrals(("129", "130", "131"), q_r_td, E_ab, k_c)


@equation(
    "132",
    "variant: mean-value point xi = 3/4 q_r_td + 1/4 q_r",
    "corrected",
    "As (123): with f = 1/H_ab^{-1} (r = -1/2 at the bottom, r = 1 at touchdown) and g = 1, 1/sigma^2, "
    "sigma (s = 0 at both ends, computed) (35) again gives 1/2 at touchdown and 1/4 from the bottom, "
    "so the text's 'the same as previous one' holds, and the same correction applies: xi = 3/4 q_r_b "
    "+ 1/4 q_r_td for the whole half, the iterate anchored at the bottom, x(q_r) = x_td + D(q_r) - "
    "D(q_r_td) with D(x) = [state part/H_ab^{-1}](xi(x)) int_{q_r_b}^{x} g, xi(x) = 3/4 q_r_b + 1/4 x.",
)
def check_eq132() -> None:
    """Printed: xi_hat_x = 3/4 q_r_td + 1/4 q_r (for f = 1/H_ab^{-1} of (128))."""
    _check_compression_point("132", weighted=True)


@cache
def _weighted_compression():
    return iterative.iteration_step(k_c, XI, -1, TOUCHDOWN, E_ab, weighted=True)


@equation(
    "133",
    "variant: compression iterate of the time",
    "verified",
    "The same display as (124): g = 1, so the variant changes nothing. The printed E is E_ab. Units: "
    "seconds. Point: see (132).",
)
def check_eq133() -> None:
    """Printed: t_(n+1)(q_r) = t_td - m/H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi), E) (q_r - q_r_td)
    (E for E_ab)."""
    printed = t_td - m / _h_inv(E_ab) * (q_r - q_r_td)
    derived = _weighted_compression()[0]
    expect_zero(printed - derived, "eq 133 printed iterate equals (116) by (129) from touchdown")
    expect_zero(_units(printed - t_td, k_c, E_ab) - _SECOND, "eq 133 the increment of t is in seconds")


@equation(
    "134",
    "variant: compression iterate of the leg angle",
    "corrected",
    "The printed q_th_td - (1/q_r_td - 1/q_r)/H_ab^{-1}(xi, ...) drops p_th: the integrand of (117) is "
    "p_th/(sigma^2 p_r), and with f = 1/H^{-1}, g = 1/sigma^2 the factor p_th_n(xi) stays at the "
    "point (as sin q_th_n(xi) does in (135)). Corrected: q_th_(n+1)(q_r) = q_th_td - p_th_n(xi)/"
    "H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ab) (1/q_r_td - 1/q_r). By units: the printed increment "
    "is in s/(kg m^2), not dimensionless, the corrected one is dimensionless. Point: see (132).",
)
def check_eq134() -> None:
    """Printed: q_th_(n+1)(q_r) = q_th_td - 1/H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ab)
    (1/q_r_td - 1/q_r)."""
    h_inv = _h_inv(E_ab)
    printed = q_th_td - 1 / h_inv * (1 / q_r_td - 1 / q_r)
    corrected = q_th_td - P_TH_N(XI) / h_inv * (1 / q_r_td - 1 / q_r)
    _check_dropped_p_th("134", q_th_td, printed, corrected, _weighted_compression()[1], k_c, E_ab)


def _check_dropped_p_th(eq, anchor, printed, corrected, derived, stiffness, energy) -> None:
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
        _units(corrected - anchor, stiffness, energy) - 1,
        f"eq {eq} corrected increment of q_th is dimensionless",
    )
    expect_zero(
        _units(printed - anchor, stiffness, energy) - _SECOND / (_KG * _METRE**2),
        f"eq {eq} printed increment of q_th is in s/(kg m^2)",
    )


@equation(
    "135",
    "variant: compression iterate of the angular momentum",
    "verified",
    "(118) by (131) from touchdown: p_th_td - m^2 g_s sin(q_th_n(xi))/(2 H_ab^{-1}(xi, ...)) (q_r^2 - "
    "q_r_td^2); the minus sign is p_r = -H_ab^{-1}, the 1/2 is int sigma dsigma. Units: kg m^2/s. "
    "Point: see (132).",
)
def check_eq135() -> None:
    """Printed: p_th_(n+1)(q_r) = p_th_td - m^2 g_s sin(q_th_n(xi))/(2 H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi),
    E_ab)) (q_r^2 - q_r_td^2)."""
    printed = p_th_td - m**2 * g_s * sp.sin(Q_TH_N(XI)) / (2 * _h_inv(E_ab)) * (q_r**2 - q_r_td**2)
    derived = _weighted_compression()[2]
    expect_zero(printed - derived, "eq 135 printed iterate equals (118) by (131) from touchdown")
    expect_zero(
        _units(printed - p_th_td, k_c, E_ab) - _KG * _METRE**2 / _SECOND,
        "eq 135 the increment of p_th is in kg m^2/s",
    )


@equation(
    "136",
    "variant: compression iterate of the radial momentum",
    "corrected",
    "The same display as (127), same correction: p_r_(n+1)(q_r) = -H_ab^{-1}(q_r, q_th_(n+1)(q_r), "
    "p_th_(n+1)(q_r), E_ab), not at xi. OCR: the tag (136) is printed inside the square root.",
)
def check_eq136() -> None:
    """Printed: p_r_(n+1)(q_r) = -sqrt(2 m (E_ab - k_c/2 (l0 - xi)^2 - m g_s xi cos(q_th_(n+1)(xi)))
    - p_th_(n+1)(xi)^2/xi^2)."""
    _check_momentum_at_xi("136", k_c, E_ab, -1, _printed_compression_point(), _COMPRESSION_SAMPLE)


# --------------------------------------------------------------------------------------------
# Section 5.2.2: bottom to apex (decompression, k_d, E_ba), (137)-(151): section 3.2's map.


@equation(
    "137",
    "decompression Hamiltonian H_ba (k_d)",
    "verified",
    "Legendre transform of (1) with k = k_d; the same as (27).",
)
def check_eq137() -> None:
    """Printed: H_ba = (p_r^2 + p_th^2/q_r^2)/(2 m) + k_d/2 (l0 - q_r)^2 + m g_s q_r cos(q_th)."""
    printed = (p_r**2 + p_th**2 / q_r**2) / (2 * m) + k_d / 2 * (l0 - q_r) ** 2 + m * g_s * q_r * sp.cos(q_th)
    expect_zero(
        printed - mechanics.hamiltonian(k_d), "eq 137 printed H_ba equals the Legendre transform of (1)"
    )


@equation(
    "138",
    "H_ba^{-1}(q_r, q_th, p_th, E_ba)",
    "verified",
    "The positive root (decompression) of H_ba = E_ba; (33) with E_ba. OCR: the '=' between "
    "H_ba^{-1}(...) and the square root is missing. The sentence after it calls E_ba the energy "
    "'during compression phase'; it is the decompression energy.",
)
def check_eq138() -> None:
    """Printed: H_ba^{-1}(q_r, q_th, p_th, E_ba) [=] sqrt(2 m (E_ba - k_d/2 (l0 - q_r)^2
    - m g_s q_r cos(q_th)) - p_th^2/q_r^2)."""
    printed = sp.sqrt(
        2 * m * (E_ba - k_d / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(q_th)) - p_th**2 / q_r**2
    )
    expect_zero(
        printed - iterative.radial_momentum(k_d, E_ba), "eq 138 printed H_ba^{-1} is the root of H_ba = E_ba"
    )
    expect_zero(
        mechanics.hamiltonian(k_d).subs(p_r, printed) - E_ba, "eq 138 H_ba at the printed root is E_ba"
    )


@equation(
    "139",
    "decompression iterate of the time",
    "verified",
    "(42) with E_ba: t_b + m/H_ba^{-1}(xi, ...) (q_r - q_r_b), (30) integrated from the bottom by (38).",
)
@equation("140", "decompression iterate of the leg angle", "verified", "(43) with E_ba.")
@equation("141", "decompression iterate of the angular momentum", "verified", "(44) with E_ba.")
def check_eq139_141() -> None:
    """Printed, with H^{-1}_n = H_ba^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ba):
    (139) t_(n+1)(q_r) = t_b + m/H^{-1}_n (q_r - q_r_b);
    (140) q_th_(n+1)(q_r) = q_th_b + p_th_n(xi)/(xi^2 H^{-1}_n) (q_r - q_r_b);
    (141) p_th_(n+1)(q_r) = p_th_b + m^2 g_s xi sin(q_th_n(xi))/H^{-1}_n (q_r - q_r_b).
    """
    h_inv = _h_inv(E_ba)
    step = q_r - q_r_b
    printed = (
        t_b + m / h_inv * step,
        q_th_b + P_TH_N(XI) / (XI**2 * h_inv) * step,
        p_th_b + m**2 * g_s * XI * sp.sin(Q_TH_N(XI)) / h_inv * step,
    )
    _expect_rows_zero(
        printed,
        iterative.iteration_step(k_d, XI, 1, BOTTOM, E_ba),
        "eqs 139-141 printed iterate equals (30)-(32) integrated from the bottom with (37) at xi",
    )


def _printed_decompression_point():
    """(143) as printed: xi_hat_x = 3/4 q_r_b + 1/4 q_r."""
    return sp.Rational(3, 4) * q_r_b + QUARTER * q_r


@equation(
    "142",
    "decompression iterate of the radial momentum",
    "corrected",
    "(45) with E_ba, same error: the printed sqrt(...) is H_ba^{-1} at xi; corrected p_r_(n+1)(q_r) = "
    "H_ba^{-1}(q_r, q_th_(n+1)(q_r), p_th_(n+1)(q_r), E_ba). OCR: the tag (142) is printed inside the "
    "square root.",
)
def check_eq142() -> None:
    """Printed: p_r_(n+1)(q_r) = sqrt(2 m (E_ba - k_d/2 (l0 - xi)^2 - m g_s xi cos(q_th_(n+1)(xi)))
    - p_th_(n+1)(xi)^2/xi^2)."""
    _check_momentum_at_xi("142", k_d, E_ba, 1, _printed_decompression_point(), _DECOMPRESSION_SAMPLE)


@equation(
    "143",
    "decompression mean-value point xi = 3/4 q_r_b + 1/4 q_r",
    "verified",
    "(41): the integrals start at the bottom, where the integrands ~ (sigma - q_r_b)^(-1/2) (r = "
    "-1/2, s = 0): (35) gives 1/4 from the bottom; with f = 1/H_ba^{-1} and g = 1, 1/sigma^2, sigma "
    "(s = 0) also 1/4, the point of (147)-(151).",
)
def check_eq143() -> None:
    """Printed: xi_hat_x = 3/4 q_r_b + 1/4 q_r."""
    for weighted in (False, True):
        for integral, fraction in iterative.mean_value_fractions(k_d, "bottom", weighted).items():
            expect_zero(
                fraction - QUARTER, f"eq 143 (35) at the bottom gives 1/4 for ({integral}), {weighted=}"
            )
    printed = _printed_decompression_point()
    expect_zero(
        printed - iterative.mean_value_point(k_d), "eq 143 printed xi equals q_r_b + 1/4 (q_r - q_r_b)"
    )


definition(
    "144",
    "second mean-value variant: f = 1/H_ba^{-1}",
    "As (128), for the decompression half: a choice of f; its consequences are checked in (145)-(151).",
)


@equation(
    "145",
    "variant: int_{q_r_b}^{q_r} 1/H_ba^{-1} ~ (q_r - q_r_b)/H_ba^{-1}(xi)",
    "verified",
    "(37) with f = 1/H_ba^{-1} at xi and g = 1. OCR: the lower limit is printed q_r; it is q_r_b, as "
    "the factor (q_r - q_r_b) and (146), (147) say.",
)
@equation(
    "146",
    "variant: int 1/(sigma^2 H_ba^{-1}) ~ (1/q_r_b - 1/q_r)/H_ba^{-1}(xi)",
    "verified",
    "g = 1/sigma^2: int_{q_r_b}^{q_r} sigma^-2 dsigma = 1/q_r_b - 1/q_r (sp.integrate).",
)
@equation(
    "147",
    "variant: int sigma/H_ba^{-1} ~ (q_r^2 - q_r_b^2)/(2 H_ba^{-1}(xi))",
    "verified",
    "g = sigma: int_{q_r_b}^{q_r} sigma dsigma = (q_r^2 - q_r_b^2)/2 (sp.integrate).",
)
def check_eq145_147() -> None:
    """Printed, with H^{-1} = H_ba^{-1}(xi, q_th(xi), p_th(xi), E_ba): the integrals from q_r_b (printed
    q_r in (145)) to q_r of 1/H^{-1}, 1/(sigma^2 H^{-1}), sigma/H^{-1} are ~ (q_r - q_r_b)/H^{-1},
    (1/q_r_b - 1/q_r)/H^{-1}, (q_r^2 - q_r_b^2)/(2 H^{-1}).
    """
    _check_weighted_integrals(("145", "146", "147"), q_r_b, E_ba, k_d)


@cache
def _weighted_decompression():
    return iterative.iteration_step(k_d, XI, 1, BOTTOM, E_ba, weighted=True)


@equation(
    "148",
    "variant: decompression iterate of the time",
    "verified",
    "The same display as (139) (g = 1). Units: seconds.",
)
def check_eq148() -> None:
    """Printed: t_(n+1)(q_r) = t_b + m/H_ba^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ba) (q_r - q_r_b)."""
    printed = t_b + m / _h_inv(E_ba) * (q_r - q_r_b)
    expect_zero(printed - _weighted_decompression()[0], "eq 148 printed iterate equals (30) by (145)")
    expect_zero(_units(printed - t_b, k_d, E_ba) - _SECOND, "eq 148 the increment of t is in seconds")


@equation(
    "149",
    "variant: decompression iterate of the leg angle",
    "corrected",
    "As (134): the printed q_th_b + (1/q_r_b - 1/q_r)/H_ba^{-1}(xi, ...) drops p_th_n(xi) (units "
    "s/(kg m^2), not dimensionless). Corrected: q_th_(n+1)(q_r) = q_th_b + p_th_n(xi)/H_ba^{-1}(xi, "
    "q_th_n(xi), p_th_n(xi), E_ba) (1/q_r_b - 1/q_r).",
)
def check_eq149() -> None:
    """Printed: q_th_(n+1)(q_r) = q_th_b + 1/H_ba^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ba) (1/q_r_b - 1/q_r)."""
    h_inv = _h_inv(E_ba)
    printed = q_th_b + 1 / h_inv * (1 / q_r_b - 1 / q_r)
    corrected = q_th_b + P_TH_N(XI) / h_inv * (1 / q_r_b - 1 / q_r)
    _check_dropped_p_th("149", q_th_b, printed, corrected, _weighted_decompression()[1], k_d, E_ba)


@equation(
    "150",
    "variant: decompression iterate of the angular momentum",
    "verified",
    "(32) by (147) from the bottom: p_th_b + m^2 g_s sin(q_th_n(xi))/(2 H_ba^{-1}(xi, ...)) (q_r^2 - "
    "q_r_b^2); the 1/2 is int sigma dsigma. Units: kg m^2/s.",
)
def check_eq150() -> None:
    """Printed: p_th_(n+1)(q_r) = p_th_b + m^2 g_s sin(q_th_n(xi))/(2 H_ba^{-1}(xi, q_th_n(xi), p_th_n(xi),
    E_ba)) (q_r^2 - q_r_b^2)."""
    printed = p_th_b + m**2 * g_s * sp.sin(Q_TH_N(XI)) / (2 * _h_inv(E_ba)) * (q_r**2 - q_r_b**2)
    expect_zero(printed - _weighted_decompression()[2], "eq 150 printed iterate equals (32) by (147)")
    expect_zero(
        _units(printed - p_th_b, k_d, E_ba) - _KG * _METRE**2 / _SECOND,
        "eq 150 the increment of p_th is in kg m^2/s",
    )


@equation(
    "151",
    "variant: decompression iterate of the radial momentum",
    "corrected",
    "The same display as (142), same correction: p_r_(n+1)(q_r) = H_ba^{-1}(q_r, q_th_(n+1)(q_r), "
    "p_th_(n+1)(q_r), E_ba). OCR: the tag is printed '15150)' at the end of the display, read as (151).",
)
def check_eq151() -> None:
    """Printed: p_r_(n+1)(q_r) = sqrt(2 m (E_ba - k_d/2 (l0 - xi)^2 - m g_s xi cos(q_th_(n+1)(xi)))
    - p_th_(n+1)(xi)^2/xi^2)   (OCR: followed by '15150)')."""
    _check_momentum_at_xi("151", k_d, E_ba, 1, _printed_decompression_point(), _DECOMPRESSION_SAMPLE)
