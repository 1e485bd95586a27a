"""Report section 5.2.1 (rows 114-136): the compression half of the iterative map (apex to bottom,
stiffness k_c, energy E_ab, p_r = -H_ab^{-1} < 0, integrated from touchdown), with the mean-value
rule of (38)-(40) and with the variant of (128) (f = 1/H^{-1}, the weights integrated exactly).
Each check compares a transcription of a printed display, typed as printed (errors included), with
:mod:`slipmaps.derive.model.mechanics` (114, 115) or :mod:`slipmaps.derive.maps.iterative_helpers`
(the rest); the iterates with the mean-value point xi_hat_r left as a symbol, the point itself
where it is printed, (123) and (132).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ...maps import iterative_helpers
from ...maps.iterative_helpers import (
    H_INV,
    P_TH_N,
    Q_TH_N,
    Q_TH_NEXT,
    TOUCHDOWN,
    E_ab,
    p_th_td,
    q_r_b,
    sigma,
    t_td,
)
from ...model import mechanics
from ...symbols import E, g_s, k_c, k_d, l0, m, p_r, p_th, q_r, q_r_td, q_th, q_th_td
from .. import definition, equation, expect, expect_nonzero, expect_zero, forms, iterates
from .helpers import (
    COMPRESSION_SAMPLE,
    HALF,
    KG,
    METRE,
    QUARTER,
    SECOND,
    XI,
    a_,
    b_,
    check_dropped_p_th,
    check_momentum_at_xi,
    check_weighted_integrals,
    e_,
    expect_rows_zero,
    h_inv_on_iterate,
    units,
    weighted_integral_form,
    x_,
)

# ============================================================================================
# Section 5.2: iterative approximate stance map for variable stiffness, eqs 114-151.
# --------------------------------------------------------------------------------------------
# Section 5.2.1: apex to bottom (compression, k_c, E_ab), Hamiltonian (114)-(119).


@equation(
    "114",
    "compression Hamiltonian H_ab (k_c)",
    "verified",
    "Legendre transform of (1) with k = k_c; (27) with k_c.",
    derived=lambda: iterates.hamiltonian_form("H_ab", k_c),
)
def check_eq114() -> None:
    """Printed: H_ab = (p_r^2 + p_th^2/q_r^2)/(2 m) + k_c/2 (l0 - q_r)^2 + m g_s q_r cos(q_th)."""
    printed = (p_r**2 + p_th**2 / q_r**2) / (2 * m) + k_c / 2 * (l0 - q_r) ** 2 + m * g_s * q_r * sp.cos(q_th)
    expect_zero(
        printed - mechanics.hamiltonian(k_c), "eq 114 printed H_ab equals the Legendre transform of (1)"
    )


@equation(
    "115",
    "Hamiltonian vector field of H_ab",
    "verified",
    "Hamilton's equations (28) of (114).",
    derived=lambda: iterates.vector_field_forms(k_c),
)
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
    expect_rows_zero(
        printed,
        mechanics.hamiltonian_vector_field(k_c),
        "eq 115 printed X_H equals Hamilton's equations of (114)",
    )


@equation(
    "116",
    "compression dt/dq_r = m/p_r",
    "verified",
    "As (30): dq_r/dt = p_r/m of (115), p_r < 0.",
    derived=lambda: iterates.rate_form(k_c, 0),
)
@equation(
    "117",
    "compression dq_th/dq_r = p_th/(q_r^2 p_r)",
    "verified",
    "As (31), from (115).",
    derived=lambda: iterates.rate_form(k_c, 1),
)
@equation(
    "118",
    "compression dp_th/dq_r = m^2 g_s q_r sin(q_th)/p_r",
    "verified",
    "As (32), from (115).",
    derived=lambda: iterates.rate_form(k_c, 2),
)
def check_eq116_118() -> None:
    """Printed: (116) dt_s/dq_r = m/p_r; (117) dq_th/dq_r = p_th/(q_r^2 p_r);
    (118) dp_th/dq_r = m^2 g_s q_r sin(q_th)/p_r, with p_r = p_r(q_r, q_th, p_th) of (119).
    """
    printed = (m / p_r, p_th / (q_r**2 * p_r), m**2 * g_s * q_r * sp.sin(q_th) / p_r)
    expect_rows_zero(
        printed,
        iterative_helpers.leg_length_derivatives(k_c),
        "eqs 116-118 printed rates equal the rates of (115) divided by dq_r/dt = p_r/m",
    )


def _corrected_eq119():
    """(119) with the compression stiffness k_c: the negative root of H_ab = E_ab."""
    return -sp.sqrt(
        2 * m * (E_ab - k_c / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(q_th)) - p_th**2 / q_r**2
    )


@equation(
    "119",
    "compression p_r = -H_ab^{-1}(q_r, q_th, p_th, E_ab)",
    "corrected",
    "The sign is right (p_r < 0 in compression: the negative root of H_ab = E_ab), the stiffness is "
    "not: the printed root has k_d, so H_ab of (114) at it equals E_ab + (k_c - k_d)/2 (l0 - q_r)^2. "
    "Corrected: p_r = -sqrt(2 m (E_ab - k_c/2 (l0 - q_r)^2 - m g_s q_r cos q_th) - p_th^2/q_r^2). "
    "(127) and (136) print k_c.",
    derived=lambda: forms((p_r, _corrected_eq119())),
)
def check_eq119() -> None:
    """Printed: p_r = -H_ab^{-1}
    = -sqrt(2 m (E_ab - k_d/2 (l0 - q_r)^2 - m g_s q_r cos(q_th)) - p_th^2/q_r^2)."""
    printed = -sp.sqrt(
        2 * m * (E_ab - k_d / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(q_th)) - p_th**2 / q_r**2
    )
    corrected = _corrected_eq119()
    derived = iterative_helpers.radial_momentum(k_c, E_ab, -1)
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
    leading = sp.Lambda((x_, a_, b_, e_), c * sp.sqrt(x_ - q_r_b))
    rule = step.replace(H_INV, leading) - t_td
    exact = sp.integrate(-m / (c * sp.sqrt(sigma - q_r_b)), (sigma, q_r_td, q_r))
    return rule, exact


def _whole_half_point():
    """Corrected (123), (132): the point of the whole compression half, xi = 3/4 q_r_b + 1/4 q_r_td."""
    return sp.Rational(3, 4) * q_r_b + QUARTER * q_r_td


def _whole_half_point_form():
    return forms((XI, _whole_half_point()))


def _check_compression_point(key: str, weighted: bool) -> None:
    """Shared by (123) and (132): where Theorem 1 puts the point of the compression integrals."""
    printed = _printed_compression_point()
    variant = "f = 1/H^{-1}, g = 1, 1/sigma^2, sigma" if weighted else "f = integrand, g = 1"
    # Touchdown: H^{-1} = |p_r_td| > 0, the integrands are regular (r = 1, s = 0): (35) gives 1/2.
    exponents = iterative_helpers.integrand_exponents(
        k_c, "touchdown"
    )  # order of the first nonzero Taylor term
    for integral in ("38", "39", "40"):
        expect_zero(
            exponents[integral] - 1, f"eq {key} integrand of ({integral}) - its touchdown value ~ delta^1"
        )
    for integral, fraction in iterative_helpers.mean_value_fractions(k_c, "touchdown", weighted).items():
        expect_zero(fraction - HALF, f"eq {key} (35) at touchdown ({variant}) gives 1/2 for ({integral})")
    expect_nonzero(
        (printed - q_r_td) / (q_r - q_r_td) - HALF,
        f"eq {key} printed fraction from touchdown is not (35)'s 1/2",
    )
    # Bottom: H^{-1} ~ (sigma - q_r_b)^(1/2), the integrands ~ (sigma - q_r_b)^(-1/2): 1/4 from the bottom.
    for integral, fraction in iterative_helpers.mean_value_fractions(k_c, "bottom", weighted).items():
        expect_zero(fraction - QUARTER, f"eq {key} (35) at the bottom ({variant}) gives 1/4 for ({integral})")
    whole = iterative_helpers.mean_value_point(k_c, q_r_td)  # the point of int_{q_r_td}^{q_r_b}
    corrected = _whole_half_point()
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
    h_inv = iterative_helpers.radial_momentum(k_c, E_ab).subs(spring)
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
    # The corrected iterate as a function of q_r (iterative_helpers.compression_step): the difference of two
    # integrals anchored at the bottom. It starts at the touchdown state, reaches the bottom with the
    # whole-half point, and is exact on the leading term for every q_r; the printed one is not.
    step = iterative_helpers.compression_step(k_c, E_ab, weighted)
    expect_rows_zero(
        [row.subs(q_r, q_r_td) for row in step],
        TOUCHDOWN[1:],
        f"eq {key} corrected iterate equals the touchdown state at q_r = q_r_td",
    )
    whole_rule = iterative_helpers.iteration_step(k_c, whole, -1, TOUCHDOWN, E_ab, weighted)
    expect_rows_zero(
        [row.subs(q_r, q_r_b) for row in step],
        [row.subs(q_r, q_r_b) for row in whole_rule],
        f"eq {key} corrected iterate at q_r_b equals the rule with the whole-half point",
    )
    rule, exact = _leading_term_time(step[0])
    expect_zero(rule - exact, f"eq {key} corrected iterate reproduces the leading-term time integral")
    printed_step = iterative_helpers.iteration_step(k_c, printed, -1, TOUCHDOWN, E_ab, weighted)
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
    derived=lambda: _whole_half_point_form(),
)
def check_eq123() -> None:
    """Printed: xi_hat_x = 3/4 q_r_td + 1/4 q_r (for the integrals (120)-(122), from q_r_td to q_r)."""
    _check_compression_point("123", weighted=False)


def _printed_compression_iterate(energy_of_t=E_ab):
    """(124)-(126) as printed, at the symbolic point xi; (124) prints E, passed as ``energy_of_t``."""
    h_inv = h_inv_on_iterate(E_ab)
    step = q_r - q_r_td
    return (
        t_td - m / h_inv_on_iterate(energy_of_t) * step,
        q_th_td - P_TH_N(XI) / (XI**2 * h_inv) * step,
        p_th_td - m**2 * g_s * XI * sp.sin(Q_TH_N(XI)) / h_inv * step,
    )


def _compression_iterate():
    """(124)-(126) derived: (116)-(118) integrated from touchdown with (37) at the point xi."""
    return iterative_helpers.iteration_step(k_c, XI, -1, TOUCHDOWN, E_ab)


@equation(
    "124",
    "compression iterate of the time t_(n+1)(q_r)",
    "verified",
    "(116) integrated from touchdown with (120) at the point xi: t_td - m/H_ab^{-1}(xi, ...) (q_r - "
    "q_r_td); the minus sign is p_r = -H_ab^{-1}. The printed E is E_ab. Verified as the rule at xi; "
    "the point xi of (123) is corrected there, with the corrected iterate.",
    derived=lambda: iterates.iterate_form(_compression_iterate(), 0),
)
@equation(
    "125",
    "compression iterate of the leg angle q_th_(n+1)(q_r)",
    "verified",
    "(117) integrated from touchdown with (121) at xi: q_th_td - p_th_n(xi)/(xi^2 H_ab^{-1}) (q_r - "
    "q_r_td). Point: see (123).",
    derived=lambda: iterates.iterate_form(_compression_iterate(), 1),
)
@equation(
    "126",
    "compression iterate of the angular momentum p_th_(n+1)(q_r)",
    "verified",
    "(118) integrated from touchdown with (122) at xi: p_th_td - m^2 g_s xi sin(q_th_n(xi))/H_ab^{-1} "
    "(q_r - q_r_td). Point: see (123).",
    derived=lambda: iterates.iterate_form(_compression_iterate(), 2),
)
def check_eq124_126() -> None:
    """Printed, with H^{-1}_n = H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ab):
    (124) t_(n+1)(q_r) = t_td - m/H^{-1}_n (q_r - q_r_td)   (printed with E for E_ab);
    (125) q_th_(n+1)(q_r) = q_th_td - p_th_n(xi)/(xi^2 H^{-1}_n) (q_r - q_r_td);
    (126) p_th_(n+1)(q_r) = p_th_td - m^2 g_s xi sin(q_th_n(xi))/H^{-1}_n (q_r - q_r_td).
    """
    derived = _compression_iterate()
    expect_rows_zero(
        _printed_compression_iterate(),
        derived,
        "eqs 124-126 printed iterate equals (116)-(118) integrated from touchdown with (37) at xi",
    )
    expect_nonzero(
        _printed_compression_iterate(E)[0] - derived[0], "eq 124 with E distinct from E_ab differs: E is E_ab"
    )


@equation(
    "127",
    "compression iterate of the radial momentum p_r_(n+1)(q_r)",
    "corrected",
    "As (45): the printed -sqrt(2 m (E_ab - k_c/2 (l0 - xi)^2 - m g_s xi cos q_th_(n+1)(xi)) - "
    "p_th_(n+1)(xi)^2/xi^2) is p_r at the leg length xi, not at q_r. By (119) corrected (k_c, as "
    "printed here): p_r_(n+1)(q_r) = -H_ab^{-1}(q_r, q_th_(n+1)(q_r), p_th_(n+1)(q_r), E_ab). OCR: the "
    "tag (127) is printed inside the square root.",
    derived=lambda: iterates.next_momentum_form(k_c, E_ab, -1),
)
def check_eq127() -> None:
    """Printed: p_r_(n+1)(q_r) = -sqrt(2 m (E_ab - k_c/2 (l0 - xi)^2 - m g_s xi cos(q_th_(n+1)(xi)))
    - p_th_(n+1)(xi)^2/xi^2)."""
    check_momentum_at_xi("127", k_c, E_ab, -1, _printed_compression_point(), COMPRESSION_SAMPLE)


definition(
    "128",
    "second mean-value variant: f = 1/H_ab^{-1}",
    "The choice of f in Theorem 1 for all three integrals, g the rest (1, 1/sigma^2, sigma), "
    "integrated exactly; a choice, nothing to derive. Its consequences are checked in (129)-(136).",
)


@equation(
    "129",
    "variant: int_{q_r_td}^{q_r} 1/H_ab^{-1} ~ (q_r - q_r_td)/H_ab^{-1}(xi)",
    "verified",
    "(37) with f = 1/H_ab^{-1} at xi and g = 1: int g = q_r - q_r_td (sp.integrate). The same "
    "display as (120).",
    derived=lambda: weighted_integral_form(0, q_r_td, E_ab, k_c),
)
@equation(
    "130",
    "variant: int 1/(sigma^2 H_ab^{-1}) ~ (1/q_r_td - 1/q_r)/H_ab^{-1}(xi)",
    "verified",
    "(37) with f = 1/H_ab^{-1} at xi and g = 1/sigma^2: int_{q_r_td}^{q_r} sigma^-2 dsigma = "
    "1/q_r_td - 1/q_r (sp.integrate).",
    derived=lambda: weighted_integral_form(1, q_r_td, E_ab, k_c),
)
@equation(
    "131",
    "variant: int sigma/H_ab^{-1} ~ (q_r^2 - q_r_td^2)/(2 H_ab^{-1}(xi))",
    "verified",
    "(37) with f = 1/H_ab^{-1} at xi and g = sigma: int_{q_r_td}^{q_r} sigma dsigma = (q_r^2 - q_r_td^2)/2.",
    derived=lambda: weighted_integral_form(2, q_r_td, E_ab, k_c),
)
def check_eq129_131() -> None:
    """Printed, with H^{-1} = H_ab^{-1}(xi, q_th(xi), p_th(xi), E_ab): the integrals from q_r_td to q_r of
    1/H^{-1}, 1/(sigma^2 H^{-1}), sigma/H^{-1} are ~ (q_r - q_r_td)/H^{-1}, (1/q_r_td - 1/q_r)/H^{-1},
    (q_r^2 - q_r_td^2)/(2 H^{-1}).
    """
    check_weighted_integrals(("129", "130", "131"), q_r_td, E_ab, k_c)


@equation(
    "132",
    "variant: mean-value point xi = 3/4 q_r_td + 1/4 q_r",
    "corrected",
    "As (123): with f = 1/H_ab^{-1} (r = -1/2 at the bottom, r = 1 at touchdown) and g = 1, 1/sigma^2, "
    "sigma (s = 0 at both ends, computed) (35) again gives 1/2 at touchdown and 1/4 from the bottom, "
    "so the text's 'the same as previous one' holds, and the same correction applies: xi = 3/4 q_r_b "
    "+ 1/4 q_r_td for the whole half, the iterate anchored at the bottom, x(q_r) = x_td + D(q_r) - "
    "D(q_r_td) with D(x) = [state part/H_ab^{-1}] at xi(x) times int_{q_r_b}^{x} g, "
    "xi(x) = 3/4 q_r_b + 1/4 x.",
    derived=lambda: _whole_half_point_form(),
)
def check_eq132() -> None:
    """Printed: xi_hat_x = 3/4 q_r_td + 1/4 q_r (for f = 1/H_ab^{-1} of (128))."""
    _check_compression_point("132", weighted=True)


@cache
def _weighted_compression():
    return iterative_helpers.iteration_step(k_c, XI, -1, TOUCHDOWN, E_ab, weighted=True)


@equation(
    "133",
    "variant: compression iterate of the time",
    "verified",
    "The same display as (124): g = 1, so the variant changes nothing. The printed E is E_ab. Units: "
    "seconds. Point: see (132).",
    derived=lambda: iterates.iterate_form(_weighted_compression(), 0),
)
def check_eq133() -> None:
    """Printed: t_(n+1)(q_r) = t_td - m/H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi), E) (q_r - q_r_td)
    (E for E_ab)."""
    printed = t_td - m / h_inv_on_iterate(E_ab) * (q_r - q_r_td)
    derived = _weighted_compression()[0]
    expect_zero(printed - derived, "eq 133 printed iterate equals (116) by (129) from touchdown")
    expect_zero(units(printed - t_td, k_c, E_ab) - SECOND, "eq 133 the increment of t is in seconds")


def _corrected_eq134():
    """(134) corrected: the factor p_th_n(xi) kept at the point."""
    return q_th_td - P_TH_N(XI) / h_inv_on_iterate(E_ab) * (1 / q_r_td - 1 / q_r)


@equation(
    "134",
    "variant: compression iterate of the leg angle",
    "corrected",
    "The printed q_th_td - (1/q_r_td - 1/q_r)/H_ab^{-1}(xi, ...) drops p_th: the integrand of (117) is "
    "p_th/(sigma^2 p_r), and with f = 1/H^{-1}, g = 1/sigma^2 the factor p_th_n(xi) stays at the "
    "point (as sin q_th_n(xi) does in (135)). Corrected: q_th_(n+1)(q_r) = q_th_td - p_th_n(xi)/"
    "H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ab) (1/q_r_td - 1/q_r). By units: the printed increment "
    "is in s/(kg m^2), not dimensionless, the corrected one is dimensionless. Point: see (132).",
    derived=lambda: forms((Q_TH_NEXT(q_r), _corrected_eq134())),
)
def check_eq134() -> None:
    """Printed: q_th_(n+1)(q_r) = q_th_td - 1/H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ab)
    (1/q_r_td - 1/q_r)."""
    h_inv = h_inv_on_iterate(E_ab)
    printed = q_th_td - 1 / h_inv * (1 / q_r_td - 1 / q_r)
    corrected = _corrected_eq134()
    check_dropped_p_th("134", q_th_td, printed, corrected, _weighted_compression()[1], k_c, E_ab)


@equation(
    "135",
    "variant: compression iterate of the angular momentum",
    "verified",
    "(118) by (131) from touchdown: p_th_td - m^2 g_s sin(q_th_n(xi))/(2 H_ab^{-1}(xi, ...)) (q_r^2 - "
    "q_r_td^2); the minus sign is p_r = -H_ab^{-1}, the 1/2 is int sigma dsigma. Units: kg m^2/s. "
    "Point: see (132).",
    derived=lambda: iterates.iterate_form(_weighted_compression(), 2),
)
def check_eq135() -> None:
    """Printed: p_th_(n+1)(q_r) = p_th_td - m^2 g_s sin(q_th_n(xi))/(2 H_ab^{-1}(xi, q_th_n(xi), p_th_n(xi),
    E_ab)) (q_r^2 - q_r_td^2)."""
    printed = p_th_td - m**2 * g_s * sp.sin(Q_TH_N(XI)) / (2 * h_inv_on_iterate(E_ab)) * (q_r**2 - q_r_td**2)
    derived = _weighted_compression()[2]
    expect_zero(printed - derived, "eq 135 printed iterate equals (118) by (131) from touchdown")
    expect_zero(
        units(printed - p_th_td, k_c, E_ab) - KG * METRE**2 / SECOND,
        "eq 135 the increment of p_th is in kg m^2/s",
    )


@equation(
    "136",
    "variant: compression iterate of the radial momentum",
    "corrected",
    "The same display as (127), same correction: p_r_(n+1)(q_r) = -H_ab^{-1}(q_r, q_th_(n+1)(q_r), "
    "p_th_(n+1)(q_r), E_ab), not at xi. OCR: the tag (136) is printed inside the square root.",
    derived=lambda: iterates.next_momentum_form(k_c, E_ab, -1),
)
def check_eq136() -> None:
    """Printed: p_r_(n+1)(q_r) = -sqrt(2 m (E_ab - k_c/2 (l0 - xi)^2 - m g_s xi cos(q_th_(n+1)(xi)))
    - p_th_(n+1)(xi)^2/xi^2)."""
    check_momentum_at_xi("136", k_c, E_ab, -1, _printed_compression_point(), COMPRESSION_SAMPLE)
