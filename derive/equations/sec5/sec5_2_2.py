"""Report section 5.2.2 (rows 137-151): the decompression half of the iterative map (bottom to
apex, stiffness k_d, energy E_ba, from the bottom: the map of section 3.2), with the mean-value rule
and the variant of (144); checked against :mod:`slipmaps.derive.model.mechanics` (137) and
:mod:`slipmaps.derive.maps.iterative_helpers` (the rest), the point where it is printed, (143).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ...maps import iterative_helpers
from ...maps.iterative_helpers import (
    BOTTOM,
    H_INV,
    P_TH_N,
    Q_TH_N,
    Q_TH_NEXT,
    E_ba,
    p_th_b,
    q_r_b,
    q_th_b,
    t_b,
)
from ...model import mechanics
from ...symbols import g_s, k_d, l0, m, p_r, p_th, q_r, q_th
from .. import definition, equation, expect_zero, forms, iterates
from .helpers import (
    DECOMPRESSION_SAMPLE,
    KG,
    METRE,
    QUARTER,
    SECOND,
    XI,
    check_dropped_p_th,
    check_momentum_at_xi,
    check_weighted_integrals,
    expect_rows_zero,
    h_inv_on_iterate,
    units,
    weighted_integral_form,
)

# --------------------------------------------------------------------------------------------
# Section 5.2.2: bottom to apex (decompression, k_d, E_ba), (137)-(151): section 3.2's map.


@equation(
    "137",
    "decompression Hamiltonian H_ba (k_d)",
    "verified",
    "Legendre transform of (1) with k = k_d; the same as (27).",
    derived=lambda: iterates.hamiltonian_form("H_ba", k_d),
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
    derived=lambda: forms((H_INV(q_r, q_th, p_th, E_ba), iterative_helpers.radial_momentum(k_d, E_ba))),
)
def check_eq138() -> None:
    """Printed: H_ba^{-1}(q_r, q_th, p_th, E_ba) [=] sqrt(2 m (E_ba - k_d/2 (l0 - q_r)^2
    - m g_s q_r cos(q_th)) - p_th^2/q_r^2)."""
    printed = sp.sqrt(
        2 * m * (E_ba - k_d / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(q_th)) - p_th**2 / q_r**2
    )
    expect_zero(
        printed - iterative_helpers.radial_momentum(k_d, E_ba),
        "eq 138 printed H_ba^{-1} is the root of H_ba = E_ba",
    )
    expect_zero(
        mechanics.hamiltonian(k_d).subs(p_r, printed) - E_ba, "eq 138 H_ba at the printed root is E_ba"
    )


def _decompression_iterate():
    """(139)-(141) derived: (30)-(32) with E_ba integrated from the bottom with (37) at the point xi."""
    return iterative_helpers.iteration_step(k_d, XI, 1, BOTTOM, E_ba)


@equation(
    "139",
    "decompression iterate of the time",
    "verified",
    "(42) with E_ba: t_b + m/H_ba^{-1}(xi, ...) (q_r - q_r_b), (30) integrated from the bottom by (38).",
    derived=lambda: iterates.iterate_form(_decompression_iterate(), 0),
)
@equation(
    "140",
    "decompression iterate of the leg angle",
    "verified",
    "(43) with E_ba.",
    derived=lambda: iterates.iterate_form(_decompression_iterate(), 1),
)
@equation(
    "141",
    "decompression iterate of the angular momentum",
    "verified",
    "(44) with E_ba.",
    derived=lambda: iterates.iterate_form(_decompression_iterate(), 2),
)
def check_eq139_141() -> None:
    """Printed, with H^{-1}_n = H_ba^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ba):
    (139) t_(n+1)(q_r) = t_b + m/H^{-1}_n (q_r - q_r_b);
    (140) q_th_(n+1)(q_r) = q_th_b + p_th_n(xi)/(xi^2 H^{-1}_n) (q_r - q_r_b);
    (141) p_th_(n+1)(q_r) = p_th_b + m^2 g_s xi sin(q_th_n(xi))/H^{-1}_n (q_r - q_r_b).
    """
    h_inv = h_inv_on_iterate(E_ba)
    step = q_r - q_r_b
    printed = (
        t_b + m / h_inv * step,
        q_th_b + P_TH_N(XI) / (XI**2 * h_inv) * step,
        p_th_b + m**2 * g_s * XI * sp.sin(Q_TH_N(XI)) / h_inv * step,
    )
    expect_rows_zero(
        printed,
        _decompression_iterate(),
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
    derived=lambda: iterates.next_momentum_form(k_d, E_ba, 1),
)
def check_eq142() -> None:
    """Printed: p_r_(n+1)(q_r) = sqrt(2 m (E_ba - k_d/2 (l0 - xi)^2 - m g_s xi cos(q_th_(n+1)(xi)))
    - p_th_(n+1)(xi)^2/xi^2)."""
    check_momentum_at_xi("142", k_d, E_ba, 1, _printed_decompression_point(), DECOMPRESSION_SAMPLE)


@equation(
    "143",
    "decompression mean-value point xi = 3/4 q_r_b + 1/4 q_r",
    "verified",
    "(41): the integrals start at the bottom, where the integrands ~ (sigma - q_r_b)^(-1/2) (r = "
    "-1/2, s = 0): (35) gives 1/4 from the bottom; with f = 1/H_ba^{-1} and g = 1, 1/sigma^2, sigma "
    "(s = 0) also 1/4, the point of (147)-(151).",
    derived=lambda: forms((XI, iterative_helpers.mean_value_point(k_d))),
)
def check_eq143() -> None:
    """Printed: xi_hat_x = 3/4 q_r_b + 1/4 q_r."""
    for weighted in (False, True):
        for integral, fraction in iterative_helpers.mean_value_fractions(k_d, "bottom", weighted).items():
            expect_zero(
                fraction - QUARTER, f"eq 143 (35) at the bottom gives 1/4 for ({integral}), {weighted=}"
            )
    printed = _printed_decompression_point()
    expect_zero(
        printed - iterative_helpers.mean_value_point(k_d),
        "eq 143 printed xi equals q_r_b + 1/4 (q_r - q_r_b)",
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
    derived=lambda: weighted_integral_form(0, q_r_b, E_ba, k_d),
)
@equation(
    "146",
    "variant: int 1/(sigma^2 H_ba^{-1}) ~ (1/q_r_b - 1/q_r)/H_ba^{-1}(xi)",
    "verified",
    "g = 1/sigma^2: int_{q_r_b}^{q_r} sigma^-2 dsigma = 1/q_r_b - 1/q_r (sp.integrate).",
    derived=lambda: weighted_integral_form(1, q_r_b, E_ba, k_d),
)
@equation(
    "147",
    "variant: int sigma/H_ba^{-1} ~ (q_r^2 - q_r_b^2)/(2 H_ba^{-1}(xi))",
    "verified",
    "g = sigma: int_{q_r_b}^{q_r} sigma dsigma = (q_r^2 - q_r_b^2)/2 (sp.integrate).",
    derived=lambda: weighted_integral_form(2, q_r_b, E_ba, k_d),
)
def check_eq145_147() -> None:
    """Printed, with H^{-1} = H_ba^{-1}(xi, q_th(xi), p_th(xi), E_ba): the integrals from q_r_b (printed
    q_r in (145)) to q_r of 1/H^{-1}, 1/(sigma^2 H^{-1}), sigma/H^{-1} are ~ (q_r - q_r_b)/H^{-1},
    (1/q_r_b - 1/q_r)/H^{-1}, (q_r^2 - q_r_b^2)/(2 H^{-1}).
    """
    check_weighted_integrals(("145", "146", "147"), q_r_b, E_ba, k_d)


@cache
def _weighted_decompression():
    return iterative_helpers.iteration_step(k_d, XI, 1, BOTTOM, E_ba, weighted=True)


@equation(
    "148",
    "variant: decompression iterate of the time",
    "verified",
    "The same display as (139) (g = 1). Units: seconds.",
    derived=lambda: iterates.iterate_form(_weighted_decompression(), 0),
)
def check_eq148() -> None:
    """Printed: t_(n+1)(q_r) = t_b + m/H_ba^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ba) (q_r - q_r_b)."""
    printed = t_b + m / h_inv_on_iterate(E_ba) * (q_r - q_r_b)
    expect_zero(printed - _weighted_decompression()[0], "eq 148 printed iterate equals (30) by (145)")
    expect_zero(units(printed - t_b, k_d, E_ba) - SECOND, "eq 148 the increment of t is in seconds")


def _corrected_eq149():
    """(149) corrected: the factor p_th_n(xi) kept at the point."""
    return q_th_b + P_TH_N(XI) / h_inv_on_iterate(E_ba) * (1 / q_r_b - 1 / q_r)


@equation(
    "149",
    "variant: decompression iterate of the leg angle",
    "corrected",
    "As (134): the printed q_th_b + (1/q_r_b - 1/q_r)/H_ba^{-1}(xi, ...) drops p_th_n(xi) (units "
    "s/(kg m^2), not dimensionless). Corrected: q_th_(n+1)(q_r) = q_th_b + p_th_n(xi)/H_ba^{-1}(xi, "
    "q_th_n(xi), p_th_n(xi), E_ba) (1/q_r_b - 1/q_r).",
    derived=lambda: forms((Q_TH_NEXT(q_r), _corrected_eq149())),
)
def check_eq149() -> None:
    """Printed: q_th_(n+1)(q_r) = q_th_b + 1/H_ba^{-1}(xi, q_th_n(xi), p_th_n(xi), E_ba) (1/q_r_b - 1/q_r)."""
    h_inv = h_inv_on_iterate(E_ba)
    printed = q_th_b + 1 / h_inv * (1 / q_r_b - 1 / q_r)
    corrected = _corrected_eq149()
    check_dropped_p_th("149", q_th_b, printed, corrected, _weighted_decompression()[1], k_d, E_ba)


@equation(
    "150",
    "variant: decompression iterate of the angular momentum",
    "verified",
    "(32) by (147) from the bottom: p_th_b + m^2 g_s sin(q_th_n(xi))/(2 H_ba^{-1}(xi, ...)) (q_r^2 - "
    "q_r_b^2); the 1/2 is int sigma dsigma. Units: kg m^2/s.",
    derived=lambda: iterates.iterate_form(_weighted_decompression(), 2),
)
def check_eq150() -> None:
    """Printed: p_th_(n+1)(q_r) = p_th_b + m^2 g_s sin(q_th_n(xi))/(2 H_ba^{-1}(xi, q_th_n(xi), p_th_n(xi),
    E_ba)) (q_r^2 - q_r_b^2)."""
    printed = p_th_b + m**2 * g_s * sp.sin(Q_TH_N(XI)) / (2 * h_inv_on_iterate(E_ba)) * (q_r**2 - q_r_b**2)
    expect_zero(printed - _weighted_decompression()[2], "eq 150 printed iterate equals (32) by (147)")
    expect_zero(
        units(printed - p_th_b, k_d, E_ba) - KG * METRE**2 / SECOND,
        "eq 150 the increment of p_th is in kg m^2/s",
    )


@equation(
    "151",
    "variant: decompression iterate of the radial momentum",
    "corrected",
    "The same display as (142), same correction: p_r_(n+1)(q_r) = H_ba^{-1}(q_r, q_th_(n+1)(q_r), "
    "p_th_(n+1)(q_r), E_ba). OCR: the tag is printed '15150)' at the end of the display, read as (151).",
    derived=lambda: iterates.next_momentum_form(k_d, E_ba, 1),
)
def check_eq151() -> None:
    """Printed: p_r_(n+1)(q_r) = sqrt(2 m (E_ba - k_d/2 (l0 - xi)^2 - m g_s xi cos(q_th_(n+1)(xi)))
    - p_th_(n+1)(xi)^2/xi^2)   (OCR: followed by '15150)')."""
    check_momentum_at_xi("151", k_d, E_ba, 1, _printed_decompression_point(), DECOMPRESSION_SAMPLE)
