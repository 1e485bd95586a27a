"""Report section 5 (variable stiffness): rows 78-113 (section 5.1), 114-151 (section 5.2) and
152-154 (the bottom leg length closing section 5.2).

Section 5.1 (eqs 78-113) is Geyer's map of section 3.1 split at the bottom: apex to bottom (78)-(89)
with k_c (subscript ab), bottom to apex (90)-(105) with k_d (subscript ba), the energy jump (97)-(98)
and the continuity constraint (106)-(111), then the piecewise stance map (112)-(113). Its checks
compare the printed displays with :mod:`slipmaps.derive.maps.geyer` (the half's parameters put into
(7), (11)-(14), (17)-(19)) and :mod:`slipmaps.derive.maps.geyer_vs` (the half solutions, the jump,
the constraint, the map's second half). Rows 88, 112, 113 and 152 carry no tag in the scan; their
notes say how the number was assigned; (95) is a definition row for a number with no display.

Section 5.2 splits the stance at the bottom: the compression half (apex to bottom, 5.2.1, eqs
114-136: stiffness k_c, energy E_ab, p_r = -H_ab^{-1} < 0, integrated from touchdown) and the
decompression half (bottom to apex, 5.2.2, eqs 137-151: k_d, E_ba, from the bottom, the map of
section 3.2). Each half comes twice: with the mean-value rule of (38)-(40) (f the whole integrand,
g = 1) and with the variant of (128)/(144) (f = 1/H^{-1}, the weight g = 1, 1/sigma^2, sigma
integrated exactly). Each check compares a transcription of a printed display, typed as printed
(errors included), with :mod:`slipmaps.derive.model.mechanics` (114, 115, 137) or
:mod:`slipmaps.derive.maps.iterative_helpers` (the rest). The iterates are checked with the mean-value point
xi_hat_r left as a symbol; the point itself is checked where it is printed, (123), (132) and (143).
The bottom leg length (152)-(154) is checked against the energy (27) at a vertical bottom
(:func:`~slipmaps.derive.maps.geyer_vs.bottom_quartic`) and Geyer's bottom (13).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

from ...ir import sym
from ...maps import geyer, geyer_vs, iterative_helpers
from ...maps.iterative_helpers import (
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
from ...model import mechanics
from ...symbols import (
    E,
    a,
    b,
    epsilon,
    g_s,
    k,
    k_c,
    k_d,
    l0,
    m,
    omega,
    omega0,
    omega0_hat,
    p_r,
    p_th,
    q_r,
    q_r_lo,
    q_r_td,
    q_rd,
    q_th,
    q_th_td,
    q_thd,
    rho,
    t,
)
from .. import definition, equation, expect, expect_nonzero, expect_zero

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
    h_inv = iterative_helpers.radial_momentum(stiffness, _e).subs(
        {q_r: _x, q_th: _a, p_th: _b}, simultaneous=True
    )
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
# Section 5.1: the simple variable-stiffness stance map, eqs 78-113 (geyer-vs).
#
# Each half is Geyer's solution (11), (19) with its own stiffness: k_c from touchdown to the bottom
# (subscript ab), k_d from the bottom to liftoff (subscript ba). The derivation is that of section
# 3.1 (:mod:`slipmaps.derive.maps.geyer`) with the half's parameters, and :mod:`slipmaps.derive.maps.
# geyer_vs` for what is new: the energy jump (97), the continuity constraint (111), the bottom quartic
# (153).

N = sp.Symbol("n", integer=True, nonnegative=True)  # the n in N of (80)-(81), (89), (93)-(96)
eps_ab, eps_ba = sp.symbols("epsilon_ab epsilon_ba", real=True)
w_ab, w_ba = sp.symbols("omega_ab omega_ba", real=True)  # omega_ab, omega_ba = p_th/(m l0^2)
w0_ab, w0_ba = sp.symbols("omega0_ab omega0_ba", positive=True)
wh_ab, wh_ba = sp.symbols("omega0_hat_ab omega0_hat_ba", positive=True)
# The names and assumptions of geyer_vs.continuity_constraint()'s symbols, so that they compare equal.
a_ab, b_ab, a_ba, b_ba = sp.symbols("a_ab b_ab a_ba b_ba", real=True)
t_b_ab, t_b_ba, t_lo = sp.symbols("t_b_ab t_b_ba t_lo", real=True)


@dataclass(frozen=True)
class _Half:
    """One half of the stance of section 5.1: its stiffness and the symbols of its parameters."""

    stiffness: sp.Symbol
    energy: sp.Symbol
    eps: sp.Symbol
    omega: sp.Symbol
    omega0: sp.Symbol
    omega0_hat: sp.Symbol
    a: sp.Symbol
    b: sp.Symbol

    @property
    def names(self) -> dict:
        """Geyer's symbols (11), (19) -> this half's."""
        return {omega: self.omega, omega0_hat: self.omega0_hat, a: self.a, b: self.b}

    @property
    def derived(self) -> dict:
        """This half's omega0_hat, a, b^2 from :func:`geyer_vs.half_solution` (omega0^2 = stiffness/m),
        in its epsilon and omega."""
        sol = geyer_vs.half_solution(self.stiffness)
        return {key: value.subs({epsilon: self.eps, omega: self.omega}) for key, value in sol.items()}

    @property
    def parameters(self) -> dict:
        """omega0_hat, a, b of this half's symbols -> the derived values (b the positive root)."""
        d = self.derived
        return {self.omega0_hat: d["omega0_hat"], self.a: d["a"], self.b: sp.sqrt(d["b2"])}


AB = _Half(k_c, E_ab, eps_ab, w_ab, w0_ab, wh_ab, a_ab, b_ab)
BA = _Half(k_d, E_ba, eps_ba, w_ba, w0_ba, wh_ba, a_ba, b_ba)


def _printed_radius(half: _Half, argument):
    """(78) / (90) / (106)-(108) / (112) as printed: l0 (1 + a + b sin(argument))."""
    return l0 * (1 + half.a + half.b * sp.sin(argument))


def _derived_radius(half: _Half, time=t):
    """(11) with the half's parameters: l0 (1 + rho(time))."""
    return l0 * (1 + geyer.radial_solution(time)).subs(half.names)


def _derived_angle(half: _Half, angle, start, shift=0):
    """(19) with the half's parameters at Geyer's time t + ``shift``: the leg angle starting from
    ``angle`` at Geyer's time ``start`` (the first half: q_th_td at t_td, no shift; the second: q_th_b
    at t_b_ba, shifted by t_b_ba - t_b_ab)."""
    expr, td = geyer.leg_angle()
    return expr.subs(t, t + shift).subs({td: start, q_th_td: angle}).subs(half.names)


def _expect_solves_radial_quadratic(rho_t, half: _Half, argument, what: str) -> None:
    """rho_t = a + b sin(argument) with the half's derived a, b, omega0_hat solves rho_d^2 = lambda rho^2
    + mu rho + nu of (9) with omega0^2 = stiffness/m and the half's epsilon, omega."""
    lam_, mu_, nu_ = (
        c.subs({omega0: sp.sqrt(half.stiffness / m), epsilon: half.eps, omega: half.omega})
        for c in geyer.radial_quadratic()
    )
    rho_t = rho_t.subs(half.parameters)
    residual = sp.diff(rho_t, t) ** 2 - (lam_ * rho_t**2 + mu_ * rho_t + nu_)
    argument = argument.subs(half.parameters)
    residual = sp.expand(residual.subs(sp.cos(argument) ** 2, 1 - sp.sin(argument) ** 2))
    sine = sp.Symbol("S", real=True)
    expect(not residual.has(sp.cos), f"{what}: only sines left")
    poly = sp.Poly(residual.subs(sp.sin(argument), sine), sine)
    for power, coeff in enumerate(reversed(poly.all_coeffs())):
        expect_zero(coeff, f"{what} (coefficient of sin^{power})")


# --------------------------------------------------------------------------------------------
# Section 5.1.1: apex to bottom (k_c), (78)-(89).


def _printed_eq78():
    """(78) as printed: q_r(t) = l0 (1 + a_ab + b_ab sin(omega0_hat_ab t))."""
    return _printed_radius(AB, wh_ab * t)


def _printed_eq79():
    """(79) as printed, with its unsubscripted omega in the second term."""
    return (
        q_th_td
        + omega * (1 - 2 * a_ab) * (t - t_td)
        + 2 * b_ab * w_ab / wh_ab * (sp.cos(wh_ab * t) - sp.cos(wh_ab * t_td))
    )


@equation(
    "78",
    "apex to bottom q_r(t) (k_c)",
    "verified",
    "Geyer's (11) with the compression parameters (85)-(88); checked also to solve the radial "
    "quadratic (9) with omega0^2 = k_c/m.",
)
def check_eq78() -> None:
    """Printed: q_r(t) = l0 (1 + a_ab + b_ab sin(omega0_hat_ab t))."""
    printed = _printed_eq78()
    expect_zero(printed - _derived_radius(AB), "eq 78 printed q_r(t) equals (11) with the ab parameters")
    _expect_solves_radial_quadratic(
        printed / l0 - 1, AB, wh_ab * t, "eq 78 rho(t) with (85)-(88) solves (9) with k_c"
    )


@equation(
    "79",
    "apex to bottom q_th(t)",
    "verified",
    "Geyer's (19) with the ab parameters. The first omega is printed without the subscript ab: it is "
    "the same p_th/(m l0^2) (Geyer's (7), (83), (100)).",
)
def check_eq79() -> None:
    """Printed: q_th(t) = q_th_td + omega (1 - 2 a_ab)(t - t_td)
    + 2 b_ab omega_ab/omega0_hat_ab [cos(omega0_hat_ab t) - cos(omega0_hat_ab t_td)]."""
    printed = _printed_eq79()
    derived = _derived_angle(AB, q_th_td, t_td)
    same = {omega: p_th / (m * l0**2), w_ab: p_th / (m * l0**2)}  # (7) and (83)
    expect_zero((printed - derived).subs(same), "eq 79 printed q_th(t) equals (19) with omega = omega_ab")


def _printed_event_phase(half: _Half, sign: int, ratio):
    """omega0_hat t of (80) (sign -1) and (94) without its shift (sign +1):
    (2n + 3/2) pi -+ [pi/2 + asin(ratio)]."""
    return (2 * N + sp.Rational(3, 2)) * sp.pi + sign * (sp.pi / 2 + sp.asin(ratio))


def _ratio(half: _Half, length):
    """s_x = (q_r_x/l0 - 1 - a)/b with the half's a, b (the argument of the arcsine)."""
    return geyer.leg_length_ratio(length).subs(half.names)


def _printed_eq80(length=q_r_td):
    return _printed_event_phase(AB, -1, (length / l0 - 1 - a_ab) / b_ab) / wh_ab


def _printed_eq81():
    return (2 * N + sp.Rational(3, 2)) * sp.pi / wh_ab


@equation(
    "80",
    "touchdown time t_td (k_c)",
    "verified",
    "Geyer's (12) with a_ab, b_ab, omega0_hat_ab: (78) equals q_r_td there, on the compressing branch.",
)
@equation("81", "bottom time t_b_ab", "verified", "Geyer's (13): sin = -1, dq_r/dt of (78) vanishes.")
def check_eq80_81() -> None:
    """Printed: (80) t_td = 1/omega0_hat_ab {(2n + 3/2) pi - [pi/2 + asin((q_r_td/l0 - 1 - a_ab)/b_ab)]};
    (81) t_b_ab = 1/omega0_hat_ab {(2n + 3/2) pi}, n in N."""
    ph = geyer.event_phases()
    td, bottom = _printed_eq80(), _printed_eq81()
    s_td = _ratio(AB, q_r_td)
    expect_zero(
        wh_ab * td - ph["touchdown"].subs(ph["s"], s_td) - 2 * N * sp.pi,
        "eq 80 printed phase equals (12) with the ab parameters + 2 n pi",
    )
    expect_zero(wh_ab * bottom - ph["bottom"] - 2 * N * sp.pi, "eq 81 printed phase equals (13) + 2 n pi")
    q_r78 = _printed_eq78()
    expect_zero(q_r78.subs(t, td) - q_r_td, "eq 80 (78) at the printed t_td equals q_r_td")
    expect_zero(
        sp.cos(wh_ab * td) + sp.sqrt(1 - s_td**2), "eq 80 touchdown on the compressing branch (cos < 0)"
    )
    expect_zero(sp.diff(q_r78, t).subs(t, bottom), "eq 81 dq_r/dt of (78) vanishes at the printed t_b_ab")
    expect_zero(sp.sin(wh_ab * bottom) + 1, "eq 81 sin = -1 at the printed t_b_ab: the minimum of (78)")


def _check_dimensionless(keys, half: _Half, printed) -> None:
    """(82)-(84) / (99)-(101): epsilon, omega, omega0 of Geyer's (7) for the half."""
    sub = geyer.dimensionless_substitution()
    eps_key, omega_key, omega0_key = keys
    (eps_derived,) = sp.solve(sp.Eq(half.energy, sub[E]), epsilon)
    (w_derived,) = sp.solve(sp.Eq(p_th, sub[p_th]), omega)
    (w0_derived,) = sp.solve(sp.Eq(half.stiffness, sub[k]), omega0)  # omega0 > 0: one root
    expect_zero(printed[0] - eps_derived, f"eq {eps_key} printed epsilon equals (7)'s 2 E/(m l0^2)")
    expect_zero(printed[1] - w_derived, f"eq {omega_key} printed omega equals (7)'s p_th/(m l0^2)")
    expect_zero(printed[2] - w0_derived, f"eq {omega0_key} printed omega0 solves (7)'s k = m omega0^2")


@equation("82", "epsilon_ab = 2 E_ab/(m l0^2)", "verified", "Geyer's (7) with E_ab.")
@equation("83", "omega_ab = p_th/(m l0^2)", "verified", "Geyer's (7).")
@equation("84", "omega0_ab = sqrt(k_c/m)", "verified", "Geyer's (7) with k = k_c.")
def check_eq82_84() -> None:
    """Printed: (82) epsilon_ab = 2 E_ab/(m l0^2); (83) omega_ab = p_th/(m l0^2);
    (84) omega0_ab = sqrt(k_c/m)."""
    printed = (2 * E_ab / (m * l0**2), p_th / (m * l0**2), sp.sqrt(k_c / m))
    _check_dimensionless(("82", "83", "84"), AB, printed)


def _printed_b_forms(half: _Half):
    """(87)-(88) / (104)-(105): the two printed forms of b."""
    w, w0, eps = half.omega, half.omega0, half.eps
    first = sp.sqrt((w**2 - g_s / l0) ** 2 + (w0**2 + 3 * w**2) * (eps - w**2 - 2 * g_s / l0)) / (
        w0**2 + 3 * w**2
    )
    second = sp.sqrt(half.a**2 + (eps - w**2 - 2 * g_s / l0) / half.omega0_hat**2)
    return first, second


def _check_half_parameters(keys, half: _Half) -> None:
    """(85)-(88) / (102)-(105) as printed against :func:`geyer_vs.half_solution` of the half's stiffness.

    The printed forms are in the half's omega0 (84)/(101), omega0_hat and a; those are replaced by
    their printed definitions, omega0 = sqrt(stiffness/m), and the derived omega0_hat, a."""
    hat_key, a_key, b_key, b2_key = keys
    w, w0 = half.omega, half.omega0
    derived = half.derived
    to_derived = {
        w0: sp.sqrt(half.stiffness / m),
        half.omega0_hat: derived["omega0_hat"],
        half.a: derived["a"],
    }
    hat = sp.sqrt(w0**2 + 3 * w**2)
    a_forms = ((w**2 - g_s / l0) / (w0**2 + 3 * w**2), (w**2 - g_s / l0) / half.omega0_hat**2)
    expect_zero(
        hat.subs(to_derived) - derived["omega0_hat"], f"eq {hat_key} printed omega0_hat equals sqrt(-lambda)"
    )
    for i, form in enumerate(a_forms, start=1):
        expect_zero(
            form.subs(to_derived) - derived["a"], f"eq {a_key} printed a (form {i}) equals -mu/(2 lambda)"
        )
    for key, form in zip((b_key, b2_key), _printed_b_forms(half), strict=True):
        expect_zero(
            (form**2).subs(to_derived) - derived["b2"],
            f"eq {key} printed b squared equals (mu^2 - 4 lambda nu)/(4 lambda^2)",
        )


@equation("85", "omega0_hat_ab = sqrt(omega0_ab^2 + 3 omega_ab^2)", "verified", "Geyer's (11) with k_c.")
@equation("86", "a_ab", "verified", "Geyer's (11) with k_c, both printed forms.")
@equation(
    "87",
    "b_ab (first form)",
    "verified",
    "Geyer's (11) with k_c. OCR: the display is garbled (the denominator omega0_ab^2 + 3 omega_ab^2 "
    "set as a subscript of the numerator over an empty denominator, omega_{ab^2} for omega_ab^2) and "
    "carries one tag for both forms; read as the first form of (104).",
)
@equation(
    "88",
    "b_ab = sqrt(a_ab^2 + (epsilon_ab - omega_ab^2 - 2 g_s/l0)/omega0_hat_ab^2) (second form)",
    "verified",
    "Number assumed: the scan has no tag (88); the display tagged (87) holds both forms of b_ab, and "
    "its twin (104)-(105) tags them separately, so the second form is (88) (the next tag printed is "
    "(89)).",
)
def check_eq85_88() -> None:
    """Printed: (85) omega0_hat_ab = sqrt(omega0_ab^2 + 3 omega_ab^2);
    (86) a_ab = (omega_ab^2 - g_s/l0)/(omega0_ab^2 + 3 omega_ab^2) = (omega_ab^2 - g_s/l0)/omega0_hat_ab^2;
    (87) b_ab = sqrt((omega_ab^2 - g_s/l0)^2
                     + (omega0_ab^2 + 3 omega_ab^2)(epsilon_ab - omega_ab^2 - 2 g_s/l0))
    / (omega0_ab^2 + 3 omega_ab^2)   (OCR-garbled, see the note)
    (88) = sqrt(a_ab^2 + (epsilon_ab - omega_ab^2 - 2 g_s/l0)/omega0_hat_ab^2)."""
    _check_half_parameters(("85", "86", "87", "88"), AB)


@equation(
    "89",
    "touchdown time, q_r_td = l0",
    "verified",
    "(80) at q_r_td = l0: asin(-a_ab/b_ab); Geyer's (15).",
)
def check_eq89() -> None:
    """Printed: t_td = 1/omega0_hat_ab {(2n + 3/2) pi - [pi/2 + asin(-a_ab/b_ab)]}."""
    printed = _printed_event_phase(AB, -1, -a_ab / b_ab) / wh_ab
    expect_zero(printed - _printed_eq80(l0), "eq 89 printed t_td equals (80) at q_r_td = l0")
    expect_zero(_printed_eq78().subs(t, printed) - l0, "eq 89 (78) at the printed t_td equals l0")


# --------------------------------------------------------------------------------------------
# Section 5.1.2: bottom to apex (k_d), (90)-(105).


def _printed_eq93():
    return (2 * N + sp.Rational(3, 2)) * sp.pi / wh_ba


def _printed_eq90():
    """(90) as printed: l0 (1 + a_ba + b_ba sin(omega0_hat_ba (t + t_b_ba - t_b_ab)))."""
    return _printed_radius(BA, wh_ba * (t + t_b_ba - t_b_ab))


def _printed_eq91_92():
    """(91)-(92) as printed (one display over two tags), with the unsubscripted omega of (91)."""
    return (
        q_th_b
        + omega * (1 - 2 * a_ba) * (t - t_b_ab)
        + 2 * b_ba * w_ba / wh_ba * (sp.cos(wh_ba * (t + t_b_ba - t_b_ab)) - sp.cos(wh_ba * t_b_ba))
    )


def _map_second_half(expr_index: int):
    """geyer_vs.py's second half (q_r or q_th) at time t, bottom at t_b_ab, in this module's symbols."""
    phase = geyer_vs.BOTTOM_PHASE + wh_ba * (t - t_b_ab)
    names = {
        sym("ba_omega"): w_ba,
        sym("ba_omega0_hat"): wh_ba,
        sym("ba_a"): a_ba,
        sym("ba_b"): b_ba,
        sym("bottom_q_th"): q_th_b,
    }
    return geyer_vs.second_state(phase)[expr_index].subs(names)


@equation(
    "90",
    "bottom to apex q_r(t) (k_d)",
    "verified",
    "Geyer's (11) with the decompression parameters (102)-(105), its clock shifted by t_b_ba - t_b_ab "
    "so that it is at its bottom phase (93) at t = t_b_ab; solves (9) with omega0^2 = k_d/m; equals "
    "the geyer-vs map's second half.",
)
def check_eq90() -> None:
    """Printed: q_r(t) = l0 (1 + a_ba + b_ba sin(omega0_hat_ba (t + t_b_ba - t_b_ab)))."""
    printed = _printed_eq90()
    shift = t_b_ba - t_b_ab
    expect_zero(
        printed - _derived_radius(BA, t + shift), "eq 90 printed q_r(t) equals (11) at t + t_b_ba - t_b_ab"
    )
    _expect_solves_radial_quadratic(
        printed / l0 - 1, BA, wh_ba * (t + shift), "eq 90 rho(t) with (102)-(105) solves (9) with k_d"
    )
    at_bottom = printed.subs(t_b_ba, _printed_eq93())
    expect_zero(sp.diff(at_bottom, t).subs(t, t_b_ab), "eq 90 with (93): dq_r/dt = 0 at t = t_b_ab")
    expect_zero(at_bottom.subs(t, t_b_ab) - l0 * (1 + a_ba - b_ba), "eq 90 with (93): the bottom at t_b_ab")
    expect_zero(
        at_bottom.subs(N, 0) - _map_second_half(0),
        "eq 90 printed q_r(t) (n = 0) equals the map's second half",
    )


@equation(
    "91",
    "bottom to apex q_th(t), first line",
    "verified",
    "(91)-(92) are one display over two tags: Geyer's (19) from the bottom (q_th_b at t = t_b_ab), "
    "its clock shifted by t_b_ba - t_b_ab. The first omega is printed without the subscript ba: the "
    "same p_th/(m l0^2) (100).",
)
@equation(
    "92",
    "bottom to apex q_th(t), second line",
    "verified",
    "The second line of (91): checked together.",
)
def check_eq91_92() -> None:
    """Printed: q_th(t) = q_th_b + omega (1 - 2 a_ba)(t - t_b_ab)                                    (91)
    + 2 b_ba omega_ba/omega0_hat_ba [cos(omega0_hat_ba (t + t_b_ba - t_b_ab))
                                     - cos(omega0_hat_ba t_b_ba)]                                  (92)."""
    printed = _printed_eq91_92()
    derived = _derived_angle(BA, q_th_b, t_b_ba, t_b_ba - t_b_ab)
    same = {omega: p_th / (m * l0**2), w_ba: p_th / (m * l0**2)}  # (7) and (100)
    expect_zero((printed - derived).subs(same), "eqs 91-92 printed q_th(t) equals (19) from the bottom")
    expect_zero(printed.subs(t, t_b_ab) - q_th_b, "eqs 91-92 q_th(t_b_ab) = q_th_b")
    expect_zero(
        printed.subs(omega, w_ba).subs(t_b_ba, _printed_eq93()).subs(N, 0) - _map_second_half(2),
        "eqs 91-92 printed q_th(t) (n = 0) equals the map's second half",
    )


def _printed_eq94(length=q_r_lo):
    return _printed_event_phase(BA, 1, (length / l0 - 1 - a_ba) / b_ba) / wh_ba + t_b_ab - t_b_ba


@equation("93", "bottom time t_b_ba of the second half", "verified", "Geyer's (13) with omega0_hat_ba.")
@equation(
    "94",
    "liftoff time t_lo",
    "verified",
    "Geyer's (14) with the ba parameters, shifted back by t_b_ba - t_b_ab to the clock of (90): "
    "(90) equals q_r_lo there, on the extending branch, for the same n in (93) and (94).",
)
def check_eq93_94() -> None:
    """Printed: (93) t_b_ba = 1/omega0_hat_ba {(2n + 3/2) pi};
    (94) t_lo = 1/omega0_hat_ba {(2n + 3/2) pi + [pi/2 + asin((q_r_lo/l0 - 1 - a_ba)/b_ba)]}
                + t_b_ab - t_b_ba."""
    ph = geyer.event_phases()
    bottom, lo = _printed_eq93(), _printed_eq94()
    s_lo = _ratio(BA, q_r_lo)
    expect_zero(wh_ba * bottom - ph["bottom"] - 2 * N * sp.pi, "eq 93 printed phase equals (13) + 2 n pi")
    expect_zero(sp.sin(wh_ba * bottom) + 1, "eq 93 sin = -1: the minimum of (11) with the ba parameters")
    phase_lo = wh_ba * (lo + t_b_ba - t_b_ab)  # the argument of (90) at t_lo
    expect_zero(
        phase_lo - ph["liftoff"].subs(ph["s"], s_lo) - 2 * N * sp.pi,
        "eq 94 the phase of (90) at the printed t_lo equals (14) + 2 n pi",
    )
    expect_zero(_printed_eq90().subs(t, lo) - q_r_lo, "eq 94 (90) at the printed t_lo equals q_r_lo")
    expect_zero(sp.cos(phase_lo) - sp.sqrt(1 - s_lo**2), "eq 94 liftoff on the extending branch (cos > 0)")


definition(
    "95",
    "(no display numbered (95) in the scan)",
    "The scan prints no tag (95): between (94) and (96) there is only the sentence '(94) can be "
    "simplified for a special case when liftoff leg length ... is equal to rest leg length'. Possibly "
    "a second line of the (94) display (as (91)-(92) are one display over two tags) lost in the scan; "
    "nothing to check.",
)


@equation(
    "96",
    "liftoff time, q_r_lo = l0",
    "verified",
    "(94) at q_r_lo = l0: asin(-a_ba/b_ba); Geyer's (16), shifted. OCR: the left side is printed "
    "t_{l_0} for t_lo.",
)
def check_eq96() -> None:
    """Printed: t_{l_0} = 1/omega0_hat_ba {(2n + 3/2) pi + [pi/2 + asin(-a_ba/b_ba)]} + t_b_ab - t_b_ba."""
    printed = _printed_event_phase(BA, 1, -a_ba / b_ba) / wh_ba + t_b_ab - t_b_ba
    expect_zero(printed - _printed_eq94(l0), "eq 96 printed t_lo equals (94) at q_r_lo = l0")
    expect_zero(_printed_eq90().subs(t, printed) - l0, "eq 96 (90) at the printed t_lo equals l0")


@equation(
    "97",
    "E_additional = (k_d - k_c)(l0 - q_r_b)^2/2",
    "verified",
    "The total energy (27) with k_d minus with k_c at the same state (geyer_vs.energy_jump): only "
    "the spring term changes, whatever q_rd, q_th, q_thd.",
)
def check_eq97() -> None:
    """Printed: E_additional = 1/2 (k_d - k_c)(l0 - q_r_b)^2."""
    printed = (k_d - k_c) * (l0 - q_r_b) ** 2 / 2
    jump = geyer_vs.energy_jump()
    expect(jump.free_symbols == {k_c, k_d, l0, q_r}, "eq 97 the jump depends on the leg length only")
    expect_zero(printed - jump.subs(q_r, q_r_b), "eq 97 printed E_additional equals the jump of (27)")


@equation(
    "98",
    "E_ba = E_ab + E_additional",
    "verified",
    "(97) with q_r_b = q_r(t_b) of (78) at (81); E_ba is (27) with k_d at the bottom state when E_ab "
    "is (27) with k_c there.",
)
def check_eq98() -> None:
    """Printed: E_ba = E_ab + E_additional = E_ab + 1/2 (k_d - k_c)(l0 - q_r(t_b))^2."""
    q_r_bottom = _printed_eq78().subs(t, _printed_eq81())
    expect_zero(q_r_bottom - l0 * (1 + a_ab - b_ab), "eq 98 q_r(t_b) of (78) at (81) is l0 (1 + a_ab - b_ab)")
    printed = E_ab + (k_d - k_c) * (l0 - q_r_bottom) ** 2 / 2
    state = {q_r: q_r_bottom}
    derived = E_ab + (mechanics.stance_energy(k_d) - mechanics.stance_energy(k_c)).subs(state)
    expect_zero(printed - derived, "eq 98 printed E_ba equals E_ab plus the jump of (27) at the bottom")


@equation("99", "epsilon_ba = 2 E_ba/(m l0^2)", "verified", "Geyer's (7) with E_ba.")
@equation(
    "100",
    "omega_ba = p_th/(m l0^2) = omega_ab",
    "verified",
    "Geyer's (7); omega_ba = omega_ab because p_th = dL/dq_thd of (1) does not involve the stiffness "
    "(Remark 2: position and velocity are continuous at the bottom, so p_th is).",
)
@equation("101", "omega0_ba = sqrt(k_d/m)", "verified", "Geyer's (7) with k = k_d.")
def check_eq99_101() -> None:
    """Printed: (99) epsilon_ba = 2 E_ba/(m l0^2); (100) omega_ba = p_th/(m l0^2) = omega_ab;
    (101) omega0_ba = sqrt(k_d/m)."""
    printed = (2 * E_ba / (m * l0**2), p_th / (m * l0**2), sp.sqrt(k_d / m))
    _check_dimensionless(("99", "100", "101"), BA, printed)
    momenta = [mechanics.lagrangian_polar(s).diff(q_thd) for s in (k_c, k_d)]
    expect_zero(momenta[0] - momenta[1], "eq 100 p_th = dL/dq_thd is the same with k_c and k_d")
    expect_zero(momenta[0] - m * q_r**2 * q_thd, "eq 100 p_th = m q_r^2 q_thd (Remark 2)")


@equation("102", "omega0_hat_ba", "verified", "Geyer's (11) with k_d.")
@equation("103", "a_ba", "verified", "Geyer's (11) with k_d, both printed forms.")
@equation("104", "b_ba (first form)", "verified", "Geyer's (11) with k_d.")
@equation("105", "b_ba (second form)", "verified", "Geyer's (11) with k_d.")
def check_eq102_105() -> None:
    """Printed: (102) omega0_hat_ba = sqrt(omega0_ba^2 + 3 omega_ba^2);
    (103) a_ba = (omega_ba^2 - g_s/l0)/(omega0_ba^2 + 3 omega_ba^2) = (omega_ba^2 - g_s/l0)/omega0_hat_ba^2;
    (104) b_ba = sqrt((omega_ba^2 - g_s/l0)^2
                      + (omega0_ba^2 + 3 omega_ba^2)(epsilon_ba - omega_ba^2 - 2 g_s/l0))
    / (omega0_ba^2 + 3 omega_ba^2)
    (105) = sqrt(a_ba^2 + (epsilon_ba - omega_ba^2 - 2 g_s/l0)/omega0_hat_ba^2)."""
    _check_half_parameters(("102", "103", "104", "105"), BA)


# --------------------------------------------------------------------------------------------
# Section 5.1.2, Remark 4: continuity at the bottom (106)-(111) and the stance map (112)-(113).


@equation(
    "106",
    "general q_r(t) = l0 (1 + a + b sin(omega0_hat t))",
    "corrected",
    "Printed l0 (1 + a + b sin(omega0_hat) t): the parenthesis closes after omega0_hat, so q_r grows "
    "linearly in t (a misprint: the same in (107), while the scan renders sin(omega0_hat t) correctly "
    "in (78), (90), (108)). Corrected: q_r(t) = l0 (1 + a + b sin(omega0_hat t)), Geyer's (11).",
)
def check_eq106() -> None:
    """Printed: q_r(t) = l0 (1 + a + b sin(omega0_hat) t)."""
    printed = l0 * (1 + a + b * sp.sin(omega0_hat) * t)
    corrected = l0 * (1 + a + b * sp.sin(omega0_hat * t))
    derived = l0 * (1 + geyer.radial_solution())
    expect_nonzero(printed - derived, "eq 106 printed q_r(t) differs from (11)")
    expect_zero(sp.diff(printed, t, 2), "eq 106 printed q_r(t) is linear in t")
    expect_nonzero(sp.diff(derived, t, 2), "eq 106 (11) is not linear in t")
    expect_zero(corrected - derived, "eq 106 corrected q_r(t) equals (11)")


@equation(
    "107",
    "general q_thd(t) = omega (1 - 2 a - 2 b sin(omega0_hat t))",
    "corrected",
    "Same misprint as (106): printed omega (1 - 2 a - 2 b sin(omega0_hat) t). Corrected: omega (1 - 2a - "
    "2b sin(omega0_hat t)), the linearization (17) omega (1 - 2 rho) along (11), whose integral is (19).",
)
def check_eq107() -> None:
    """Printed: q_thd(t) = omega (1 - 2 a - 2 b sin(omega0_hat) t)."""
    printed = omega * (1 - 2 * a - 2 * b * sp.sin(omega0_hat) * t)
    corrected = omega * (1 - 2 * a - 2 * b * sp.sin(omega0_hat * t))
    _, linear = geyer.angular_rate()
    derived = linear.subs(rho, geyer.radial_solution())
    expect_nonzero(printed - derived, "eq 107 printed rate differs from (17) linearized along (11)")
    expect_zero(corrected - derived, "eq 107 corrected rate equals (17) linearized along (11)")
    angle, _ = geyer.leg_angle()
    expect_zero(sp.diff(angle, t) - corrected, "eq 107 corrected rate is the derivative of (19)")


def _printed_eq108():
    """(108) as printed (t_{bba} read as t_b_ba): (left side, right side)."""
    return (
        l0 * (1 + a_ab + b_ab * sp.sin(wh_ab * t_b_ab)),
        l0 * (1 + a_ba + b_ba * sp.sin(wh_ba * t_b_ba)),
    )


def _printed_eq109():
    return (
        w_ab * (1 - 2 * a_ab - 2 * b_ab * sp.sin(wh_ab * t_b_ab)),
        w_ba * (1 - 2 * a_ba - 2 * b_ba * sp.sin(wh_ba * t_b_ba)),
    )


@equation(
    "108",
    "continuity of q_r at the bottom",
    "verified",
    "Left: (78) at t_b_ab; right: (90) at t = t_b_ab. OCR: t_{bba} for t_b_ba.",
)
@equation(
    "109",
    "continuity of q_thd at the bottom",
    "verified",
    "Left and right: the corrected (107) of each half at t = t_b_ab (the clock of (90)). With omega_ab "
    "= omega_ba (100) it is -2 omega/l0 times (108): no second condition.",
)
def check_eq108_109() -> None:
    """Printed: (108) l0 (1 + a_ab + b_ab sin(omega0_hat_ab t_b_ab))
        = l0 (1 + a_ba + b_ba sin(omega0_hat_ba t_bba));
    (109) omega_ab (1 - 2 a_ab - 2 b_ab sin(omega0_hat_ab t_b_ab))
        = omega_ba (1 - 2 a_ba - 2 b_ba sin(omega0_hat_ba t_bba))."""
    left, right = _printed_eq108()
    expect_zero(left - _derived_radius(AB).subs(t, t_b_ab), "eq 108 left side is (78) at t_b_ab")
    expect_zero(
        right - _derived_radius(BA, t + t_b_ba - t_b_ab).subs(t, t_b_ab), "eq 108 right is (90) at t_b_ab"
    )
    _, linear = geyer.angular_rate()
    rates = [
        linear.subs(rho, geyer.radial_solution(time)).subs(half.names)
        for half, time in ((AB, t_b_ab), (BA, t_b_ba))
    ]
    rate_left, rate_right = _printed_eq109()
    expect_zero(rate_left - rates[0], "eq 109 left side is the rate (17) of the first half at t_b_ab")
    expect_zero(rate_right - rates[1], "eq 109 right side is the rate (17) of the second half at t_b_ab")
    same = {w_ba: w_ab}  # (100)
    expect_zero(
        ((rate_left - rate_right) + 2 * w_ab / l0 * (left - right)).subs(same),
        "eq 109 with omega_ab = omega_ba is -2 omega/l0 times (108)",
    )


@equation(
    "110",
    "a_ab - b_ab = a_ba - b_ba",
    "verified",
    "(108)-(109) at (81), (93) (sin = -1 at both bottoms). With (103)-(104) it holds by itself only "
    "when E_ab is the energy the first half conserves (Geyer's (8), not the total energy (27) the "
    "text names): then (97)-(99) give epsilon_ba = epsilon_ab + (k_d - k_c)/m rho_b^2, the bottom "
    "rho_b = a_ab - b_ab is a root of the second half's quadratic (9), whose roots are a_ba -+ b_ba "
    "(geyer_vs.consistent_bottom_is_a_root), and (110) holds when it is the lower one.",
)
def check_eq110() -> None:
    """Printed: a_ab - b_ab = a_ba - b_ba."""
    printed = (a_ab - b_ab) - (a_ba - b_ba)
    bottoms = {t_b_ab: _printed_eq81(), t_b_ba: _printed_eq93()}
    left, right = (side.subs(bottoms) for side in _printed_eq108())
    expect_zero((left - right) - l0 * printed, "eq 110 (108) at (81), (93) is l0 times (110)")
    rate_left, rate_right = (side.subs(bottoms).subs(w_ba, w_ab) for side in _printed_eq109())
    expect_zero((rate_left - rate_right) + 2 * w_ab * printed, "eq 110 (109) at (81), (93) is -2 omega (110)")
    expect_zero(printed.subs(a_ba, geyer_vs.continuity_constraint()), "eq 110 holds at (111)")
    # The energy of the first half: the bottom is a root of the second half's quadratic.
    expect_zero(geyer_vs.consistent_bottom_is_a_root(), "eq 110 the bottom solves the second half's (9)")
    rho_b = sp.Symbol("rho_b", real=True)
    jump = geyer_vs.energy_jump().subs(q_r, l0 * (1 + rho_b))
    expect_zero(2 * jump / (m * l0**2) - (k_d - k_c) / m * rho_b**2, "eq 110 (97)-(99): the jump in epsilon")
    lam_, mu_, nu_ = (
        c.subs({omega0: sp.sqrt(k_d / m), epsilon: eps_ba, omega: w_ba}) for c in geyer.radial_quadratic()
    )
    derived = BA.derived
    quadratic = lam_ * rho**2 + mu_ * rho + nu_
    factored = lam_ * ((rho - derived["a"]) ** 2 - derived["b2"])
    expect_zero(
        quadratic - factored, "eq 110 (9) with k_d is lambda ((rho - a_ba)^2 - b_ba^2): roots a_ba -+ b_ba"
    )


@equation(
    "111",
    "a_ba = a_ab - b_ab + b_ba",
    "verified",
    "(110) solved for a_ba; geyer_vs.continuity_constraint solves (108)-(109) at (81), (93). It replaces "
    "(103): the second half then no longer solves its own (9) (the text's 'invariant under small shift').",
)
def check_eq111() -> None:
    """Printed: a_ba = a_ab - b_ab + b_ba."""
    printed = a_ab - b_ab + b_ba
    expect_zero(
        printed - geyer_vs.continuity_constraint(), "eq 111 printed a_ba solves (108)-(109) at the bottoms"
    )
    expect_nonzero(printed - BA.derived["a"], "eq 111 differs from (103) in general")


def _printed_eq112_113():
    """The piecewise stance map at the end of section 5.1 as printed: ((q_r pieces), (q_th pieces)),
    each (t_td <= t <= t_b_ab, t_b_ab <= t <= t_lo). The first q_th piece writes omega_hat_ab for
    omega0_hat_ab in one denominator (read as omega0_hat_ab)."""
    q_r_pieces = (
        l0 * (1 + a_ab + b_ab * sp.sin(wh_ab * t)),
        l0 * (1 + a_ba + b_ba * sp.sin(wh_ba * (t + t_b_ba - t_b_ab))),
    )
    q_th_pieces = (
        q_th_td
        + w_ab * (1 - 2 * a_ab) * (t - t_td)
        + 2 * b_ab * w_ab / wh_ab * (sp.cos(wh_ab * t) - sp.cos(wh_ab * t_td)),
        q_th_b
        + w_ba * (1 - 2 * a_ba) * (t - t_b_ab)
        + 2 * b_ba * w_ba / wh_ba * (sp.cos(wh_ba * (t + t_b_ba - t_b_ab)) - sp.cos(wh_ba * t_b_ba)),
    )
    return q_r_pieces, q_th_pieces


@equation(
    "112",
    "stance map q_r(t), piecewise",
    "verified",
    "Number assumed: the scan prints the closing piecewise display of section 5.1 without tags; "
    "between (111) and (114) it is the only display, so its q_r(t) is taken as (112). The pieces are "
    "(78) and (90); continuous at t_b_ab exactly when (110) holds (the constraint (111)).",
)
@equation(
    "113",
    "stance map q_th(t), piecewise",
    "verified",
    "Number assumed as for (112). The pieces are (79) and (91)-(92), here with omega_ab, omega_ba "
    "subscripted; OCR: omega_hat_ab for omega0_hat_ab in the first piece's denominator.",
)
def check_eq112_113() -> None:
    """Printed: q_r(t) = l0 (1 + a_ab + b_ab sin(omega0_hat_ab t)) if t_td <= t <= t_b_ab,
                       l0 (1 + a_ba + b_ba sin(omega0_hat_ba (t + t_b_ba - t_b_ab))) if t_b_ab <= t <= t_lo;
    q_th(t) = q_th_td + omega_ab (1 - 2 a_ab)(t - t_td)
              + 2 b_ab omega_ab/omega_hat_ab [cos(omega0_hat_ab t) - cos(omega0_hat_ab t_td)]
              if t_td <= t <= t_b_ab,
              q_th_b + omega_ba (1 - 2 a_ba)(t - t_b_ab)
              + 2 b_ba omega_ba/omega0_hat_ba [cos(omega0_hat_ba (t + t_b_ba - t_b_ab))
                                               - cos(omega0_hat_ba t_b_ba)]
              if t_b_ab <= t <= t_lo."""
    (r1, r2), (th1, th2) = _printed_eq112_113()
    expect_zero(r1 - _printed_eq78(), "eq 112 first piece is (78)")
    expect_zero(r2 - _printed_eq90(), "eq 112 second piece is (90)")
    expect_zero(r1 - _derived_radius(AB), "eq 112 first piece is (11) with the ab parameters")
    expect_zero(r2 - _derived_radius(BA, t + t_b_ba - t_b_ab), "eq 112 second piece is (11) shifted, ba")
    bottoms = {t_b_ab: _printed_eq81(), t_b_ba: _printed_eq93()}
    jump = (r2 - r1).subs(t, t_b_ab).subs(bottoms)
    expect_zero(jump - l0 * ((a_ba - b_ba) - (a_ab - b_ab)), "eq 112 the jump at t_b_ab is l0 times (110)")
    expect_zero(jump.subs(a_ba, geyer_vs.continuity_constraint()), "eq 112 continuous at t_b_ab under (111)")
    expect_zero(th1 - _printed_eq79().subs(omega, w_ab), "eq 113 first piece is (79)")
    expect_zero(th2 - _printed_eq91_92().subs(omega, w_ba), "eq 113 second piece is (91)-(92)")
    expect_zero(th1 - _derived_angle(AB, q_th_td, t_td), "eq 113 first piece is (19) with the ab parameters")
    expect_zero(
        th2 - _derived_angle(BA, q_th_b, t_b_ba, t_b_ba - t_b_ab),
        "eq 113 second piece is (19) from the bottom",
    )
    expect_zero(th2.subs(t, t_b_ab) - q_th_b, "eq 113 second piece starts at q_th_b")


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
        iterative_helpers.leg_length_derivatives(k_c),
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
    leading = sp.Lambda((_x, _a, _b, _e), c * sp.sqrt(_x - q_r_b))
    rule = step.replace(H_INV, leading) - t_td
    exact = sp.integrate(-m / (c * sp.sqrt(sigma - q_r_b)), (sigma, q_r_td, q_r))
    return rule, exact


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
    _expect_rows_zero(
        [row.subs(q_r, q_r_td) for row in step],
        TOUCHDOWN[1:],
        f"eq {key} corrected iterate equals the touchdown state at q_r = q_r_td",
    )
    whole_rule = iterative_helpers.iteration_step(k_c, whole, -1, TOUCHDOWN, E_ab, weighted)
    _expect_rows_zero(
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
    derived = iterative_helpers.iteration_step(k_c, XI, -1, TOUCHDOWN, E_ab)
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
    h_inv = iterative_helpers.radial_momentum(stiffness, energy, sign)
    at_xi = h_inv.subs({q_r: XI, q_th: Q_TH_NEXT(XI), p_th: P_TH_NEXT(XI)}, simultaneous=True)
    expect_zero(printed - at_xi, f"eq {key} printed p_r is p_r at the leg length xi on the (n+1)-th iterate")
    derived = iterative_helpers.next_radial_momentum(stiffness, energy, sign)
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
    weights = [
        iterative_helpers.weight_split(rate)[1]
        for rate in iterative_helpers.leg_length_derivatives(stiffness)
    ]
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
    return iterative_helpers.iteration_step(k_c, XI, -1, TOUCHDOWN, E_ab, weighted=True)


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
        printed - iterative_helpers.radial_momentum(k_d, E_ba),
        "eq 138 printed H_ba^{-1} is the root of H_ba = E_ba",
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
        iterative_helpers.iteration_step(k_d, XI, 1, BOTTOM, E_ba),
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
    return iterative_helpers.iteration_step(k_d, XI, 1, BOTTOM, E_ba, weighted=True)


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


# --------------------------------------------------------------------------------------------
# End of section 5.2: the bottom leg length q_r_b, (152)-(154).


def _vertical_bottom_energy():
    """The total energy (27) with k_c at a vertical bottom: q_rd = 0, q_th = 0, q_thd = p_th/(m q_r^2)."""
    return mechanics.stance_energy(k_c).subs({q_rd: 0, q_th: 0, q_thd: p_th / (m * q_r**2)})


@equation(
    "152",
    "E_ab at a vertical bottom",
    "corrected",
    "Number assumed: the scan tags only the second line of the two-line display (153); its first line "
    "is taken as (152). It prints p_th/(2 m q_r^2) for the rotational energy, which is "
    "p_th^2/(2 m q_r^2) (the printed term is in 1/s, not J). Corrected: E_ab = p_th^2/(2 m q_r^2) + "
    "k_c/2 (l0 - q_r)^2 + m g_s q_r, the energy (27) with k_c at q_rd = 0, q_th = 0; (153) is q_r^2 "
    "times the corrected form.",
)
def check_eq152() -> None:
    """Printed: E_ab = p_th/(2 m q_r^2) + k_c/2 (l0 - q_r)^2 + m g_s q_r."""
    printed = p_th / (2 * m * q_r**2) + k_c / 2 * (l0 - q_r) ** 2 + m * g_s * q_r
    corrected = p_th**2 / (2 * m * q_r**2) + k_c / 2 * (l0 - q_r) ** 2 + m * g_s * q_r
    derived = _vertical_bottom_energy()
    expect_nonzero(printed - derived, "eq 152 printed E_ab differs from (27) at a vertical bottom")
    expect_zero(corrected - derived, "eq 152 corrected E_ab equals (27) with k_c at a vertical bottom")
    kg, metre, second = _KG, _METRE, _SECOND
    scale = {m: m * kg, q_r: q_r * metre, p_th: p_th * kg * metre**2 / second}
    rotational = p_th / (2 * m * q_r**2)
    expect_zero(
        sp.simplify(rotational.subs(scale, simultaneous=True) / rotational) - 1 / second,
        "eq 152 the printed rotational term is in 1/s",
    )
    expect_zero(
        (q_r**2 * (corrected - E)).expand() - geyer_vs.bottom_quartic(),
        "eq 152 (153)'s quartic is q_r^2 times the corrected form minus E",
    )


@equation(
    "153",
    "bottom quartic in q_r",
    "verified",
    "q_r^2 (E - E_ab) with E the energy (27) with k_c at a vertical bottom (geyer_vs.bottom_quartic); "
    "follows from the corrected (152), not the printed one.",
)
def check_eq153() -> None:
    """Printed: k_c/2 q_r^4 + (m g_s - k_c l0) q_r^3 + (k_c l0^2/2 - E_ab) q_r^2 + p_th^2/(2 m) = 0."""
    printed = (
        k_c / 2 * q_r**4
        + (m * g_s - k_c * l0) * q_r**3
        + (k_c * l0**2 / 2 - E_ab) * q_r**2
        + p_th**2 / (2 * m)
    )
    expect_zero(
        printed - geyer_vs.bottom_quartic().subs(E, E_ab), "eq 153 printed quartic equals q_r^2 (E - E_ab)"
    )
    printed152 = p_th / (2 * m * q_r**2) + k_c / 2 * (l0 - q_r) ** 2 + m * g_s * q_r
    expect_nonzero(
        printed - sp.expand(q_r**2 * (printed152 - E_ab)), "eq 153 does not follow from (152) as printed"
    )


@equation(
    "154",
    "q_r_b = l0 (1 + a_ab - b_ab)",
    "verified",
    "Geyer's bottom: (78) at the bottom phase (81), 3 pi/2 + 2 n pi, with a_ab, b_ab of section 5.1.1.",
)
def check_eq154() -> None:
    """Printed: q_r_b = l0 (1 + a_ab - b_ab)."""
    printed = l0 * (1 + a_ab - b_ab)
    expect_zero(
        printed - _derived_radius(AB).subs(t, _printed_eq81()), "eq 154 printed q_r_b is (78) at (81)"
    )
    bottom = geyer.event_states()["bottom"][0].subs(AB.names)
    expect_zero(printed - bottom, "eq 154 printed q_r_b is Geyer's bottom state (13) with the ab parameters")
