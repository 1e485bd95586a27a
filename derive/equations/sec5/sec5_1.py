"""Report section 5.1 (rows 78-113): the simple variable-stiffness stance map ``geyer-vs``.

Geyer's map of section 3.1 split at the bottom: apex to bottom (78)-(89) with k_c (subscript ab),
bottom to apex (90)-(105) with k_d (subscript ba), the energy jump (97)-(98) and the continuity
constraint (106)-(111), then the piecewise stance map (112)-(113). Its checks compare the printed
displays with :mod:`slipmaps.derive.maps.geyer` (the half's parameters put into (7), (11)-(14),
(17)-(19)) and :mod:`slipmaps.derive.maps.geyer_vs` (the half solutions, the jump, the constraint,
the map's second half). Rows 88, 112 and 113 carry no tag in the scan; their notes say how the
number was assigned; (95) is a definition row for a number with no display.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ...ir import sym
from ...maps import geyer, geyer_vs
from ...maps.iterative_helpers import E_ab, E_ba, q_r_b, q_th_b, t_td
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
    p_th,
    q_r,
    q_r_lo,
    q_r_td,
    q_th,
    q_th_td,
    q_thd,
    rho,
    t,
)
from .. import definition, equation, expect, expect_nonzero, expect_zero, forms

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


def derived_radius(half: _Half, time=t):
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
    derived=lambda: forms((q_r, derived_radius(AB))),
)
def check_eq78() -> None:
    """Printed: q_r(t) = l0 (1 + a_ab + b_ab sin(omega0_hat_ab t))."""
    printed = _printed_eq78()
    expect_zero(printed - derived_radius(AB), "eq 78 printed q_r(t) equals (11) with the ab parameters")
    _expect_solves_radial_quadratic(
        printed / l0 - 1, AB, wh_ab * t, "eq 78 rho(t) with (85)-(88) solves (9) with k_c"
    )


@equation(
    "79",
    "apex to bottom q_th(t)",
    "verified",
    "Geyer's (19) with the ab parameters. The first omega is printed without the subscript ab: it is "
    "the same p_th/(m l0^2) (Geyer's (7), (83), (100)).",
    derived=lambda: forms((q_th, _derived_angle(AB, q_th_td, t_td))),
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


def printed_eq81():
    return (2 * N + sp.Rational(3, 2)) * sp.pi / wh_ab


@equation(
    "80",
    "touchdown time t_td (k_c)",
    "verified",
    "Geyer's (12) with a_ab, b_ab, omega0_hat_ab: (78) equals q_r_td there, on the compressing branch.",
    derived=lambda: _phase_form(wh_ab * t_td, "touchdown", AB, q_r_td),
)
@equation(
    "81",
    "bottom time t_b_ab",
    "verified",
    "Geyer's (13): sin = -1, dq_r/dt of (78) vanishes.",
    derived=lambda: _phase_form(wh_ab * t_b_ab, "bottom"),
)
def check_eq80_81() -> None:
    """Printed: (80) t_td = 1/omega0_hat_ab {(2n + 3/2) pi - [pi/2 + asin((q_r_td/l0 - 1 - a_ab)/b_ab)]};
    (81) t_b_ab = 1/omega0_hat_ab {(2n + 3/2) pi}, n in N."""
    ph = geyer.event_phases()
    td, bottom = _printed_eq80(), printed_eq81()
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


def _dimensionless(half: _Half):
    """epsilon, omega, omega0 of Geyer's (7) for the half: (82)-(84) / (99)-(101) derived."""
    sub = geyer.dimensionless_substitution()
    (eps_derived,) = sp.solve(sp.Eq(half.energy, sub[E]), epsilon)
    (w_derived,) = sp.solve(sp.Eq(p_th, sub[p_th]), omega)
    (w0_derived,) = sp.solve(sp.Eq(half.stiffness, sub[k]), omega0)  # omega0 > 0: one root
    return eps_derived, w_derived, w0_derived


def _dimensionless_form(half: _Half, row: int):
    return forms(((half.eps, half.omega, half.omega0)[row], _dimensionless(half)[row]))


def _parameter_form(half: _Half, name: str):
    """The half's omega0_hat, a or b^2 (``name``) as :func:`geyer_vs.half_solution` derives it."""
    lhs = {"omega0_hat": half.omega0_hat, "a": half.a, "b2": half.b**2}[name]
    return forms((lhs, half.derived[name]))


def _phase_form(lhs, event: str, half: _Half | None = None, length=None):
    """``lhs`` = the phase of Geyer's (12)-(14) ``event`` (n = 0), at the leg length ``length`` with the
    half's a, b."""
    ph = geyer.event_phases()
    phase = ph[event] if half is None else ph[event].subs(ph["s"], _ratio(half, length))
    return forms((lhs, phase))


def _check_dimensionless(keys, half: _Half, printed) -> None:
    """(82)-(84) / (99)-(101): epsilon, omega, omega0 of Geyer's (7) for the half."""
    eps_key, omega_key, omega0_key = keys
    eps_derived, w_derived, w0_derived = _dimensionless(half)
    expect_zero(printed[0] - eps_derived, f"eq {eps_key} printed epsilon equals (7)'s 2 E/(m l0^2)")
    expect_zero(printed[1] - w_derived, f"eq {omega_key} printed omega equals (7)'s p_th/(m l0^2)")
    expect_zero(printed[2] - w0_derived, f"eq {omega0_key} printed omega0 solves (7)'s k = m omega0^2")


@equation(
    "82",
    "epsilon_ab = 2 E_ab/(m l0^2)",
    "verified",
    "Geyer's (7) with E_ab.",
    derived=lambda: _dimensionless_form(AB, 0),
)
@equation(
    "83", "omega_ab = p_th/(m l0^2)", "verified", "Geyer's (7).", derived=lambda: _dimensionless_form(AB, 1)
)
@equation(
    "84",
    "omega0_ab = sqrt(k_c/m)",
    "verified",
    "Geyer's (7) with k = k_c.",
    derived=lambda: _dimensionless_form(AB, 2),
)
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


@equation(
    "85",
    "omega0_hat_ab = sqrt(omega0_ab^2 + 3 omega_ab^2)",
    "verified",
    "Geyer's (11) with k_c.",
    derived=lambda: _parameter_form(AB, "omega0_hat"),
)
@equation(
    "86",
    "a_ab",
    "verified",
    "Geyer's (11) with k_c, both printed forms.",
    derived=lambda: _parameter_form(AB, "a"),
)
@equation(
    "87",
    "b_ab (first form)",
    "verified",
    "Geyer's (11) with k_c. OCR: the display is garbled (the denominator omega0_ab^2 + 3 omega_ab^2 "
    "set as a subscript of the numerator over an empty denominator, omega_{ab^2} for omega_ab^2) and "
    "carries one tag for both forms; read as the first form of (104).",
    derived=lambda: _parameter_form(AB, "b2"),
)
@equation(
    "88",
    "b_ab = sqrt(a_ab^2 + (epsilon_ab - omega_ab^2 - 2 g_s/l0)/omega0_hat_ab^2) (second form)",
    "verified",
    "Number assumed: the scan has no tag (88); the display tagged (87) holds both forms of b_ab, and "
    "its twin (104)-(105) tags them separately, so the second form is (88) (the next tag printed is "
    "(89)).",
    derived=lambda: _parameter_form(AB, "b2"),
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
    derived=lambda: _phase_form(wh_ab * t_td, "touchdown", AB, l0),
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
    derived=lambda: forms((q_r, derived_radius(BA, t + t_b_ba - t_b_ab))),
)
def check_eq90() -> None:
    """Printed: q_r(t) = l0 (1 + a_ba + b_ba sin(omega0_hat_ba (t + t_b_ba - t_b_ab)))."""
    printed = _printed_eq90()
    shift = t_b_ba - t_b_ab
    expect_zero(
        printed - derived_radius(BA, t + shift), "eq 90 printed q_r(t) equals (11) at t + t_b_ba - t_b_ab"
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
    derived=lambda: forms((q_th, _derived_angle(BA, q_th_b, t_b_ba, t_b_ba - t_b_ab))),
)
@equation(
    "92",
    "bottom to apex q_th(t), second line",
    "verified",
    "The second line of (91): checked together.",
    derived=lambda: forms((q_th, _derived_angle(BA, q_th_b, t_b_ba, t_b_ba - t_b_ab))),
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


@equation(
    "93",
    "bottom time t_b_ba of the second half",
    "verified",
    "Geyer's (13) with omega0_hat_ba.",
    derived=lambda: _phase_form(wh_ba * t_b_ba, "bottom"),
)
@equation(
    "94",
    "liftoff time t_lo",
    "verified",
    "Geyer's (14) with the ba parameters, shifted back by t_b_ba - t_b_ab to the clock of (90): "
    "(90) equals q_r_lo there, on the extending branch, for the same n in (93) and (94).",
    derived=lambda: _phase_form(wh_ba * (t_lo + t_b_ba - t_b_ab), "liftoff", BA, q_r_lo),
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
    derived=lambda: _phase_form(wh_ba * (t_lo + t_b_ba - t_b_ab), "liftoff", BA, l0),
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
    derived=lambda: forms((sp.Symbol("E_additional"), geyer_vs.energy_jump().subs(q_r, q_r_b))),
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
    derived=lambda: forms((E_ba, _energy_after_jump())),
)
def check_eq98() -> None:
    """Printed: E_ba = E_ab + E_additional = E_ab + 1/2 (k_d - k_c)(l0 - q_r(t_b))^2."""
    q_r_bottom = _printed_eq78().subs(t, printed_eq81())
    expect_zero(q_r_bottom - l0 * (1 + a_ab - b_ab), "eq 98 q_r(t_b) of (78) at (81) is l0 (1 + a_ab - b_ab)")
    printed = E_ab + (k_d - k_c) * (l0 - q_r_bottom) ** 2 / 2
    derived = _energy_after_jump()
    expect_zero(printed - derived, "eq 98 printed E_ba equals E_ab plus the jump of (27) at the bottom")


def _energy_after_jump():
    """(98) derived: E_ab plus the jump of (27) at the bottom l0 (1 + a_ab - b_ab) of (78) at (81)."""
    state = {q_r: _printed_eq78().subs(t, printed_eq81())}
    return E_ab + sp.factor((mechanics.stance_energy(k_d) - mechanics.stance_energy(k_c)).subs(state))


@equation(
    "99",
    "epsilon_ba = 2 E_ba/(m l0^2)",
    "verified",
    "Geyer's (7) with E_ba.",
    derived=lambda: _dimensionless_form(BA, 0),
)
@equation(
    "100",
    "omega_ba = p_th/(m l0^2) = omega_ab",
    "verified",
    "Geyer's (7); omega_ba = omega_ab because p_th = dL/dq_thd of (1) does not involve the stiffness "
    "(Remark 2: position and velocity are continuous at the bottom, so p_th is).",
    derived=lambda: _dimensionless_form(BA, 1),
)
@equation(
    "101",
    "omega0_ba = sqrt(k_d/m)",
    "verified",
    "Geyer's (7) with k = k_d.",
    derived=lambda: _dimensionless_form(BA, 2),
)
def check_eq99_101() -> None:
    """Printed: (99) epsilon_ba = 2 E_ba/(m l0^2); (100) omega_ba = p_th/(m l0^2) = omega_ab;
    (101) omega0_ba = sqrt(k_d/m)."""
    printed = (2 * E_ba / (m * l0**2), p_th / (m * l0**2), sp.sqrt(k_d / m))
    _check_dimensionless(("99", "100", "101"), BA, printed)
    momenta = [mechanics.lagrangian_polar(s).diff(q_thd) for s in (k_c, k_d)]
    expect_zero(momenta[0] - momenta[1], "eq 100 p_th = dL/dq_thd is the same with k_c and k_d")
    expect_zero(momenta[0] - m * q_r**2 * q_thd, "eq 100 p_th = m q_r^2 q_thd (Remark 2)")


@equation(
    "102",
    "omega0_hat_ba",
    "verified",
    "Geyer's (11) with k_d.",
    derived=lambda: _parameter_form(BA, "omega0_hat"),
)
@equation(
    "103",
    "a_ba",
    "verified",
    "Geyer's (11) with k_d, both printed forms.",
    derived=lambda: _parameter_form(BA, "a"),
)
@equation(
    "104",
    "b_ba (first form)",
    "verified",
    "Geyer's (11) with k_d.",
    derived=lambda: _parameter_form(BA, "b2"),
)
@equation(
    "105",
    "b_ba (second form)",
    "verified",
    "Geyer's (11) with k_d.",
    derived=lambda: _parameter_form(BA, "b2"),
)
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
    expect_zero(left - derived_radius(AB).subs(t, t_b_ab), "eq 108 left side is (78) at t_b_ab")
    expect_zero(
        right - derived_radius(BA, t + t_b_ba - t_b_ab).subs(t, t_b_ab), "eq 108 right is (90) at t_b_ab"
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
    bottoms = {t_b_ab: printed_eq81(), t_b_ba: _printed_eq93()}
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
    expect_zero(r1 - derived_radius(AB), "eq 112 first piece is (11) with the ab parameters")
    expect_zero(r2 - derived_radius(BA, t + t_b_ba - t_b_ab), "eq 112 second piece is (11) shifted, ba")
    bottoms = {t_b_ab: printed_eq81(), t_b_ba: _printed_eq93()}
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
