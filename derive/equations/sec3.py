"""Report section 3 (previous studies): eqs 1-26 (3.1, Geyer et al.) and 27-45 (3.2, Schwind and Koditschek).

Each check compares a transcription of a printed display, typed as printed (errors included),
with the derivation of :mod:`slipmaps.derive.model.mechanics` (eqs 1-3, 27-29),
:mod:`slipmaps.derive.maps.geyer` (eqs 4-26) or :mod:`slipmaps.derive.maps.iterative_helpers`
(eqs 30-45); corrected forms are built from the derivation or stated next to the error.
"""

from __future__ import annotations

import sympy as sp

from ..maps import geyer, geyer_damped_helpers, iterative_helpers
from ..maps.geyer_damped_helpers import DELTA
from ..maps.iterative_helpers import (
    H_INV,
    P_TH_N,
    P_TH_NEXT,
    Q_TH_N,
    Q_TH_NEXT,
    delta,
    p_th_b,
    q_r_b,
    q_th_b,
    t_b,
)
from ..model import mechanics
from ..symbols import (
    E,
    a,
    b,
    c,
    epsilon,
    g_s,
    k,
    k_d,
    l0,
    m,
    omega,
    omega0,
    omega0_hat,
    p_r,
    p_th,
    q_r,
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
from . import definition, equation, expect, expect_nonzero, expect_zero, forms, iterates

#: The report's subsections of section 3, each with its first equation number.
SUBSECTIONS = (("3.1", 1), ("3.2", 27))

q_rdd, q_thdd = sp.symbols("q_rdd q_thdd", real=True)
n_int = sp.Symbol("n", integer=True, nonnegative=True)
s_sym = sp.Symbol("s", real=True)
b_pos = sp.Symbol("b", positive=True)
t_td, t_lo = sp.symbols("t_td t_lo", real=True)
t_s = sp.Symbol("t_s", positive=True)
MU = sp.Symbol("mu", real=True)
H_OF_STATE = sp.Function("H")(q_r, q_th, p_r, p_th)  # H of (28), a function of the state
xi = iterates.XI  # the mean-value leg length of (41)


def _expect_rows_zero(printed, derived, what: str) -> None:
    """Row-by-row ``expect_zero`` of two equal-length tuples, naming the row in the message."""
    for i, (p, d) in enumerate(zip(printed, derived, strict=True), start=1):
        expect_zero(p - d, f"{what} (row {i})")


# --------------------------------------------------------------------------------------------
# Section 3.1: the Lagrangian model (1)-(3) and Assumption 1 (4)-(6).


@equation(
    "1",
    "stance Lagrangian",
    "verified",
    "T and V computed from the body at (-q_r sin q_th, q_r cos q_th).",
    derived=lambda: forms((sp.Symbol("L"), mechanics.lagrangian_polar())),
)
def check_eq1() -> None:
    """Printed: L = m/2 (q_rd^2 + q_r^2 q_thd^2) - k/2 (l0 - q_r)^2 - m g_s q_r cos(q_th)."""
    printed = m / 2 * (q_rd**2 + q_r**2 * q_thd**2) - k / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(q_th)
    expect_zero(printed - mechanics.lagrangian_polar(), "eq 1 printed L equals T - V of the body")


@equation(
    "2",
    "radial Euler-Lagrange equation",
    "verified",
    derived=lambda: forms((mechanics.euler_lagrange_polar()[0], 0)),
)
def check_eq2() -> None:
    """Printed: m q_rdd = m q_r q_thd^2 + k (l0 - q_r) - m g_s cos(q_th)."""
    el_r, _ = mechanics.euler_lagrange_polar()
    printed = m * q_rdd - (m * q_r * q_thd**2 + k * (l0 - q_r) - m * g_s * sp.cos(q_th))
    expect_zero(printed - el_r, "eq 2 printed radial equation equals d/dt dL/dq_rd - dL/dq_r of (1)")


@equation(
    "3",
    "angular Euler-Lagrange equation",
    "corrected",
    "Printed 0 = d/dt(m q_r^2 q_thd) + m g_s q_r sin q_th; from (1): d/dt(m q_r^2 q_thd) = "
    "+m g_s q_r sin q_th (sign of the gravity term), consistent with (29).",
    derived=lambda: forms((mechanics.euler_lagrange_polar()[1], 0)),
)
def check_eq3() -> None:
    """Printed: 0 = d/dt (m q_r^2 q_thd) + m g_s q_r sin(q_th)."""
    _, el_th = mechanics.euler_lagrange_polar()
    ddt_momentum = m * q_r**2 * q_thdd + 2 * m * q_r * q_rd * q_thd  # d/dt (m q_r^2 q_thd)
    printed = ddt_momentum + m * g_s * q_r * sp.sin(q_th)
    corrected = ddt_momentum - m * g_s * q_r * sp.sin(q_th)
    expect_nonzero(
        printed - el_th, "eq 3 printed angular equation differs from the Euler-Lagrange one of (1)"
    )
    expect_zero(
        corrected - el_th, "eq 3 corrected angular equation (gravity sign) equals the Euler-Lagrange one"
    )


@equation(
    "4",
    "radial equation under Assumption 1",
    "verified",
    "cos q_th = 1 in (2).",
    derived=lambda: forms((geyer.assumption1_equations()[0], 0)),
)
@equation(
    "5",
    "angular momentum conservation under Assumption 1",
    "verified",
    "sin q_th = 0 in (3).",
    derived=lambda: forms((geyer.assumption1_equations()[1], 0)),
)
def check_eq4_eq5() -> None:
    """Printed: (4) m q_rdd = m q_r q_thd^2 + k (l0 - q_r) - m g_s; (5) d/dt (m q_r^2 q_thd) = 0."""
    el_r, el_th = geyer.assumption1_equations()
    printed4 = m * q_rdd - (m * q_r * q_thd**2 + k * (l0 - q_r) - m * g_s)
    printed5 = m * q_r**2 * q_thdd + 2 * m * q_r * q_rd * q_thd
    expect_zero(printed4 - el_r, "eq 4 printed radial equation equals (2) with cos q_th = 1")
    expect_zero(printed5 - el_th, "eq 5 printed angular equation equals (3) with sin q_th = 0")


@equation(
    "6",
    "conserved energy under Assumption 1",
    "verified",
    "Energy function of (1) with cos q_th = 1; also checked to be a first integral of (4)-(5).",
    derived=lambda: forms((E, geyer.energy_assumption1())),
)
def check_eq6() -> None:
    """Printed: E = m/2 q_rd^2 + p_th^2/(2 m q_r^2) + k/2 (l0 - q_r)^2 + m g_s q_r."""
    derived = geyer.energy_assumption1()
    printed = m / 2 * q_rd**2 + p_th**2 / (2 * m * q_r**2) + k / 2 * (l0 - q_r) ** 2 + m * g_s * q_r
    expect_zero(printed - derived, "eq 6 printed E equals the energy function of (1) with cos q_th = 1")
    el_r, el_th = geyer.assumption1_equations()
    acc = sp.solve([el_r, el_th], [q_rdd, q_thdd], dict=True)[0]
    energy_v = derived.subs(p_th, m * q_r**2 * q_thd)
    d_energy = (
        energy_v.diff(q_r) * q_rd + energy_v.diff(q_rd) * acc[q_rdd] + energy_v.diff(q_thd) * acc[q_thdd]
    )
    expect_zero(d_energy, "eq 6 dE/dt vanishes along the flow of (4)-(5)")


# --------------------------------------------------------------------------------------------
# Section 3.1: dimensionless form (7)-(8), Assumption 2 and the radial solution (9)-(11).

definition(
    "7",
    "dimensionless rho, epsilon, omega, omega0",
    derived=lambda: forms(*geyer.dimensionless_substitution().items()),
)


@equation(
    "8",
    "dimensionless energy",
    "verified",
    "(7) substituted into (6).",
    derived=lambda: forms((epsilon, geyer.dimensionless_energy())),
)
def check_eq8() -> None:
    """Printed: epsilon = rho_d^2 + omega^2/(1 + rho)^2 + omega0^2 rho^2 + 2 g_s/l0 (1 + rho)."""
    printed = rho_d**2 + omega**2 / (1 + rho) ** 2 + omega0**2 * rho**2 + 2 * g_s / l0 * (1 + rho)
    expect_zero(
        printed - geyer.dimensionless_energy(), "eq 8 printed epsilon equals (6) in the variables of (7)"
    )


@equation(
    "sec3.1-taylor",
    "Assumption 2: 1/(1+rho)^2 ~ 1 - 2 rho + 3 rho^2",
    "verified",
    "The second-order Taylor polynomial holds (the next term is -4 rho^3).",
    derived=lambda: forms((1 / (1 + rho) ** 2, geyer.taylor_inverse_square() + sp.O(rho**3))),
)
def check_taylor() -> None:
    """Printed: 1/(1 + rho)^2 ~ 1 - 2 rho + 3 rho^2."""
    expect_zero(
        1 - 2 * rho + 3 * rho**2 - geyer.taylor_inverse_square(),
        "Assumption 2 printed polynomial equals the Taylor polynomial of 1/(1+rho)^2 to rho^2",
    )


@equation(
    "9",
    "quadrature and lambda, mu, nu",
    "verified",
    "Second-order expansion of (8) in rho.",
    derived=lambda: forms(*zip(sp.symbols("lambda mu nu"), geyer.radial_quadratic(), strict=True)),
)
def check_eq9() -> None:
    """Printed: lambda = -(3 omega^2 + omega0^2), mu = 2 (omega^2 - g_s/l0),
    nu = epsilon - omega^2 - 2 g_s/l0.
    """
    printed = (-(3 * omega**2 + omega0**2), 2 * (omega**2 - g_s / l0), epsilon - omega**2 - 2 * g_s / l0)
    _expect_rows_zero(
        printed, geyer.radial_quadratic(), "eq 9 printed (lambda, mu, nu) equal the rho-expansion of (8)"
    )


@equation(
    "10",
    "antiderivative of (9)",
    "corrected",
    "Printed sqrt(mu^2) - 4 lambda nu in the arcsine's denominator (OCR/typesetting); the "
    "antiderivative is -1/sqrt(-lambda) asin((2 lambda rho + mu)/sqrt(mu^2 - 4 lambda nu)), "
    "checked by differentiation for lambda < 0 < mu^2 - 4 lambda nu.",
    derived=lambda: forms((t, geyer.antiderivative())),
)
def check_eq10() -> None:
    """Printed: t = -1/sqrt(-lambda) asin((2 lambda rho + mu)/(sqrt(mu^2) - 4 lambda nu)).

    The square root covers the whole discriminant mu^2 - 4 lambda nu in the corrected form.
    """
    big_l, disc = sp.symbols("L D", positive=True)  # lambda = -L < 0, D = mu^2 - 4 lambda nu > 0
    nu_d = (disc - MU**2) / (4 * big_l)
    quad = -big_l * rho**2 + MU * rho + nu_d
    corrected = geyer.antiderivative(-big_l, MU, nu_d)
    d_corr = sp.diff(corrected, rho)
    expect_zero(
        sp.simplify(d_corr**2 * quad) - 1, "eq 10 corrected antiderivative: (dt/drho)^2 = 1/quadrature"
    )
    point = {big_l: 2, disc: 9, MU: 1, rho: sp.Rational(1, 10)}
    expect(d_corr.subs(point).evalf() > 0, f"eq 10 corrected antiderivative increases with rho at {point}")
    printed = (
        -1 / sp.sqrt(big_l) * sp.asin((2 * (-big_l) * rho + MU) / (sp.sqrt(MU**2) - 4 * (-big_l) * nu_d))
    )
    residual = sp.N((sp.diff(printed, rho) ** 2 * quad - 1).subs(point))
    expect(abs(residual) > 1e-6, f"eq 10 printed antiderivative fails (dt/drho)^2 = 1/quadrature at {point}")


@equation(
    "11",
    "radial solution q_r(t) = l0 (1 + a + b sin(omega0_hat t))",
    "verified",
    "Both printed forms of b; rho(t) checked to solve rho_d^2 = lambda rho^2 + mu rho + nu.",
    derived=lambda: forms(
        (q_r, l0 * (1 + geyer.radial_solution())),
        *((s, geyer.radial_solution_parameters()[str(s)]) for s in (omega0_hat, a)),
        (b**2, geyer.radial_solution_parameters()["b2"]),
    ),
)
def check_eq11() -> None:
    """Printed: omega0_hat = sqrt(omega0^2 + 3 omega^2), a = (omega^2 - g_s/l0)/omega0_hat^2, and
    b = sqrt((omega^2 - g_s/l0)^2 + omega0_hat^2 (epsilon - omega^2 - 2 g_s/l0))/omega0_hat^2
      = sqrt(a^2 + (epsilon - omega^2 - 2 g_s/l0)/omega0_hat^2).
    """
    sol = geyer.radial_solution_parameters()
    w_hat = sp.sqrt(omega0**2 + 3 * omega**2)
    nu_ = epsilon - omega**2 - 2 * g_s / l0
    a_ = (omega**2 - g_s / l0) / (omega0**2 + 3 * omega**2)
    b_ = sp.sqrt((omega**2 - g_s / l0) ** 2 + (omega0**2 + 3 * omega**2) * nu_) / (omega0**2 + 3 * omega**2)
    b_alt = sp.sqrt(a_**2 + nu_ / w_hat**2)
    expect_zero(w_hat - sol["omega0_hat"], "eq 11 printed omega0_hat equals sqrt(-lambda)")
    expect_zero(a_ - sol["a"], "eq 11 printed a equals -mu/(2 lambda)")
    expect_zero(
        b_**2 - sol["b2"], "eq 11 printed b (first form) squared equals (mu^2 - 4 lambda nu)/(4 lambda^2)"
    )
    expect_zero(
        b_alt**2 - sol["b2"], "eq 11 printed b (second form) squared equals (mu^2 - 4 lambda nu)/(4 lambda^2)"
    )
    lam_, mu_, nu_q = geyer.radial_quadratic()
    rho_t = a_ + b_ * sp.sin(w_hat * t)
    ode = sp.diff(rho_t, t) ** 2 - (lam_ * rho_t**2 + mu_ * rho_t + nu_q)
    ode = sp.expand(sp.expand_trig(ode)).subs(sp.cos(w_hat * t) ** 2, 1 - sp.sin(w_hat * t) ** 2)
    expect_zero(
        ode, "eq 11 rho(t) = a + b sin(omega0_hat t) solves rho_d^2 = lambda rho^2 + mu rho + nu of (9)"
    )


# --------------------------------------------------------------------------------------------
# Section 3.1: event times (12)-(16), leg angle (17)-(19), stance time (20).


def _printed_phases(s_td, s_lo):
    """Eqs (12)-(14): omega0_hat * (t_td, t_b, t_lo) as printed, for any n."""
    base = (2 * n_int + sp.Rational(3, 2)) * sp.pi
    return base - (sp.pi / 2 + sp.asin(s_td)), base, base + (sp.pi / 2 + sp.asin(s_lo))


def _phase_form(event: str, time):
    """omega0_hat ``time`` = the derived phase of ``event`` (n = 0), s_x written as s."""
    return forms((omega0_hat * time, geyer.event_phases()[event]))


@equation(
    "12",
    "touchdown time",
    "verified",
    "Compressing root of sin(omega0_hat t) = (q_r_td/l0 - 1 - a)/b, up to 2 n pi.",
    derived=lambda: _phase_form("touchdown", t_td),
)
@equation(
    "13", "bottom time", "verified", "Minimum of rho: sin = -1.", derived=lambda: _phase_form("bottom", t_b)
)
@equation(
    "14",
    "liftoff time",
    "verified",
    "Extending root after the bottom, up to 2 n pi.",
    derived=lambda: _phase_form("liftoff", t_lo),
)
def check_eq12_14() -> None:
    """Printed: omega0_hat t_td = (2n + 3/2) pi - (pi/2 + asin s_td), omega0_hat t_b = (2n + 3/2) pi,
    omega0_hat t_lo = (2n + 3/2) pi + (pi/2 + asin s_lo), s_x = (q_r_x/l0 - 1 - a)/b.
    """
    ph = geyer.event_phases()
    p_td, p_b, p_lo = _printed_phases(s_sym, s_sym)
    for name, printed, derived in (
        ("12 touchdown", p_td, ph["touchdown"]),
        ("13 bottom", p_b, ph["bottom"]),
        ("14 liftoff", p_lo, ph["liftoff"]),
    ):
        expect_zero(
            printed - derived - 2 * n_int * sp.pi, f"eq {name} printed phase equals the derived one + 2 n pi"
        )
    # The right roots: rho = q_r/l0 - 1 (sin = s), compressing before the bottom (cos < 0),
    # extending after it (cos > 0), bottom at the minimum sin = -1.
    expect_zero(sp.sin(p_td) - s_sym, "eq 12 sin(printed touchdown phase) = s_td")
    expect_zero(sp.cos(p_td) + sp.sqrt(1 - s_sym**2), "eq 12 touchdown on the compressing branch (cos < 0)")
    expect_zero(sp.sin(p_lo) - s_sym, "eq 14 sin(printed liftoff phase) = s_lo")
    expect_zero(sp.cos(p_lo) - sp.sqrt(1 - s_sym**2), "eq 14 liftoff on the extending branch (cos > 0)")
    expect_zero(sp.sin(p_b) + 1, "eq 13 sin(printed bottom phase) = -1 (minimum of rho)")


def _phases_at_rest_length():
    """(12)-(14) at q_r_td = q_r_lo = l0, n = 0: omega0_hat (t_td, t_b, t_lo)."""
    return _printed_phases(geyer.leg_length_ratio(l0), geyer.leg_length_ratio(l0))


@equation(
    "15",
    "touchdown time, q_r_td = l0",
    "verified",
    derived=lambda: forms((omega0_hat * t_td, _phases_at_rest_length()[0].subs(n_int, 0))),
)
@equation(
    "16",
    "liftoff time, q_r_lo = l0",
    "verified",
    derived=lambda: forms((omega0_hat * t_lo, _phases_at_rest_length()[2].subs(n_int, 0))),
)
def check_eq15_16() -> None:
    """Printed: (12) and (14) with s_td = s_lo = -a/b."""
    p_td, _, p_lo = _printed_phases(-a / b, -a / b)
    g_td, _, g_lo = _phases_at_rest_length()
    expect_zero(p_td - g_td, "eq 15 printed touchdown phase equals (12) at q_r_td = l0")
    expect_zero(p_lo - g_lo, "eq 16 printed liftoff phase equals (14) at q_r_lo = l0")


@equation(
    "17",
    "leg angle rate omega/(1+rho)^2",
    "verified",
    "Also its linearization omega (1 - 2 rho). The text's 'q_thd = p_th/(m q_r)' above (17) "
    "misses the square of q_r.",
    derived=lambda: forms((q_thd, geyer.angular_rate()[0]), (q_thd, geyer.angular_rate()[1] + sp.O(rho**2))),
)
def check_eq17() -> None:
    """Printed: q_thd = omega/(1 + rho)^2 ~ omega (1 - 2 rho)."""
    exact, linear = geyer.angular_rate()
    expect_zero(
        omega / (1 + rho) ** 2 - exact, "eq 17 printed rate equals p_th/(m q_r^2) in the variables of (7)"
    )
    expect_zero(
        omega * (1 - 2 * rho) - linear, "eq 17 printed linearization equals the first-order Taylor one"
    )


def _leg_angle():
    """(19) derived: the integral of (17) along (11) from the touchdown time t_td."""
    derived, td_sym = geyer.leg_angle()
    return derived.subs(td_sym, t_td)


def _leg_angle_integral():
    """(18) derived: q_th_td plus the unevaluated integral of the linearized (17) along (11)."""
    _, linear = geyer.angular_rate()
    return q_th_td + sp.Integral(linear.subs(rho, geyer.radial_solution()), (t, t_td, t))


@equation("18", "leg angle integral", "verified", derived=lambda: forms((q_th, _leg_angle_integral())))
@equation("19", "leg angle q_th(t)", "verified", derived=lambda: forms((q_th, _leg_angle())))
def check_eq18_19() -> None:
    """Printed: (18) q_th = q_th_td + int_{t_td}^t omega ((1 - 2a) - 2b sin(omega0_hat t)) dt;
    (19) q_th = q_th_td + omega (1 - 2a)(t - t_td)
                + 2 b omega/omega0_hat (cos(omega0_hat t) - cos(omega0_hat t_td)).
    """
    derived = _leg_angle()
    expect_zero(_leg_angle_integral().doit() - derived, "eq 18 the derived integral evaluates to (19)")
    printed18 = q_th_td + sp.integrate(omega * ((1 - 2 * a) - 2 * b * sp.sin(omega0_hat * t)), (t, t_td, t))
    printed19 = (
        q_th_td
        + omega * (1 - 2 * a) * (t - t_td)
        + 2 * b * omega / omega0_hat * (sp.cos(omega0_hat * t) - sp.cos(omega0_hat * t_td))
    )
    expect_zero(printed18 - derived, "eq 18 printed integral equals the integral of (17) along (11)")
    expect_zero(printed19 - derived, "eq 19 printed q_th(t) equals the integral of (17) along (11)")


def _stance_time_at_rest_length():
    """(20) derived: (14) - (12) at q_r_td = q_r_lo = l0."""
    return geyer.stance_time_general()["t_stance"].subs(geyer.q_r_lo, l0).subs(q_r_td, l0)


@equation(
    "20",
    "stance time, q_r_td = q_r_lo = l0",
    "verified",
    derived=lambda: forms((t_s, _stance_time_at_rest_length())),
)
def check_eq20() -> None:
    """Printed: t_s = t_lo - t_td = [pi + 2 asin(-a/b)]/omega0_hat."""
    derived = _stance_time_at_rest_length()
    printed = (sp.pi + 2 * sp.asin(-a / b)) / omega0_hat
    expect_zero(printed - derived, "eq 20 printed stance time equals (14) - (12) at q_r_td = q_r_lo = l0")


# --------------------------------------------------------------------------------------------
# Section 3.1: the map in touchdown time and touchdown states (21)-(26).


def _with_positive_b(expr):
    return sp.simplify(sp.sympify(expr).subs(b, b_pos))


@equation(
    "21",
    "q_r(t) with touchdown at t = 0",
    "verified",
    "Valid for q_r_td = l0 (sin(omega0_hat t_td) = -a/b) and b > 0.",
    derived=lambda: forms((q_r, _with_positive_b(geyer.touchdown_shifted_solution()[0]))),
)
@equation(
    "22",
    "q_th(t) with touchdown at t = 0",
    "verified",
    "As (21).",
    derived=lambda: forms((q_th, _with_positive_b(geyer.touchdown_shifted_solution()[1]))),
)
def check_eq21_22() -> None:
    """Printed: (21) q_r = l0 + l0 [a (1 - cos(omega0_hat t)) - sqrt(b^2 - a^2) sin(omega0_hat t)];
    (22) q_th = q_th_td + (1 - 2a) omega t
                + 2 omega/omega0_hat [a sin(omega0_hat t) + sqrt(b^2 - a^2)(1 - cos(omega0_hat t))].
    """
    q_r_t, q_th_t = geyer.touchdown_shifted_solution()
    root = sp.sqrt(b_pos**2 - a**2)
    wt = omega0_hat * t
    printed21 = l0 + l0 * (a * (1 - sp.cos(wt)) - root * sp.sin(wt))
    printed22 = (
        q_th_td
        + (1 - 2 * a) * omega * t
        + 2 * omega / omega0_hat * (a * sp.sin(wt) + root * (1 - sp.cos(wt)))
    )
    expect_zero(
        _with_positive_b(q_r_t) - printed21, "eq 21 printed q_r(t) equals (11) shifted to touchdown at t = 0"
    )
    expect_zero(
        _with_positive_b(q_th_t) - printed22,
        "eq 22 printed q_th(t) equals (19) shifted to touchdown at t = 0",
    )


#: omega0_hat of a touchdown state at q_r_td = l0, as (23)-(24) print it.
W_TOUCHDOWN = sp.sqrt(k / m + 3 * q_thd_td**2)


def _touchdown_forms(lhs, build, w_hat=W_TOUCHDOWN):
    """``lhs = build(omega0_hat)`` with omega0_hat named, and its value ``w_hat`` in touchdown states
    (what the check substitutes)."""
    return forms((lhs, build(omega0_hat)), (omega0_hat, w_hat))


def _derived_eq23_24():
    return geyer.touchdown_state_solution()


def _printed_eq23(speed, w_hat=W_TOUCHDOWN):
    wt = w_hat * t
    return l0 - sp.Abs(speed) / w_hat * sp.sin(wt) + (q_thd_td**2 * l0 - g_s) / w_hat**2 * (1 - sp.cos(wt))


@equation(
    "23",
    "q_r(t) in touchdown states",
    "corrected",
    "Printed |q_r_td| (the leg length); the amplitude is |q_rd_td|/omega0_hat "
    "(sqrt(b^2 - a^2) = |q_rd_td|/(l0 omega0_hat) at q_r_td = l0).",
    derived=lambda: _touchdown_forms(q_r, lambda w: _printed_eq23(q_rd_td, w)),
)
def check_eq23() -> None:
    """Printed: q_r = l0 - |q_r_td|/omega0_hat sin(omega0_hat t)
                      + (q_thd_td^2 l0 - g_s)/omega0_hat^2 (1 - cos(omega0_hat t)).

    Printed with |q_r_td| (the leg length); the derivation needs |q_rd_td| (the radial speed).
    """
    derived, _, _ = _derived_eq23_24()
    expect_nonzero(
        _printed_eq23(q_r_td) - derived,
        "eq 23 printed q_r(t) with |q_r_td| differs from (21) in touchdown states",
    )
    expect_zero(
        _printed_eq23(q_rd_td) - derived,
        "eq 23 corrected q_r(t) with |q_rd_td| equals (21) in touchdown states",
    )


def _printed_eq24(w_hat=W_TOUCHDOWN):
    """(24) as printed, a_p = (q_thd_td^2 - g_s/l0)/omega0_hat^2."""
    wt = w_hat * t
    a_p = (q_thd_td**2 - g_s / l0) / w_hat**2
    return (
        q_th_td
        + (1 - 2 * a_p) * q_thd_td * t
        + 2 * q_thd_td / w_hat * (a_p * sp.sin(wt) + sp.Abs(q_rd_td) / (w_hat * l0) * (1 - sp.cos(wt)))
    )


@equation(
    "24",
    "q_th(t) in touchdown states",
    "verified",
    "OCR: |q_rd_tt| read as |q_rd_td|.",
    derived=lambda: _touchdown_forms(q_th, _printed_eq24),
)
def check_eq24() -> None:
    """Printed: q_th = q_th_td + (1 - 2 a_p) q_thd_td t
    + 2 q_thd_td/omega0_hat [a_p sin(omega0_hat t) + |q_rd_td|/(omega0_hat l0) (1 - cos(omega0_hat t))],
    a_p = (q_thd_td^2 - g_s/l0)/omega0_hat^2, omega0_hat = sqrt(k/m + 3 q_thd_td^2).
    """
    _, derived, _ = _derived_eq23_24()
    expect_zero(_printed_eq24() - derived, "eq 24 printed q_th(t) equals (22) in touchdown states")


def _derived_event_times_td():
    """t_s and t_b from touchdown (q_r_td = q_r_lo = l0) in touchdown states."""
    a_td, root, w_td = geyer.touchdown_at_rest_length()
    gen = geyer.stance_time_general()
    # At q_r_td = l0: s_td = s_lo = -a/b, and a/b = a / sqrt(a^2 + (b^2 - a^2)).
    ratio = -a_td / sp.sqrt(a_td**2 + root**2)
    s_expr = geyer.leg_length_ratio(l0)
    expect_zero(s_expr + a / b, "s_td = -a/b at q_r_td = l0")
    t_s = gen["t_stance"].subs(geyer.q_r_lo, l0).subs(q_r_td, l0)
    t_b = gen["t_bottom"].subs(q_r_td, l0)
    t_s = t_s.subs(sp.asin(s_expr), sp.asin(ratio)).subs(omega0_hat, w_td)
    t_b = t_b.subs(sp.asin(s_expr), sp.asin(ratio)).subs(omega0_hat, w_td)
    return t_s, t_b, ratio, w_td


def _atan_argument(w_td):
    """(g_s - l0 q_thd_td^2)/(|q_rd_td| omega0_hat), the arctan argument of corrected (25)-(26)."""
    return (g_s - l0 * q_thd_td**2) / (sp.Abs(q_rd_td) * w_td)


def _corrected_event_time(fraction, w_td=None):
    """``fraction`` of the corrected stance time (25): [pi + 2 arctan(...)]/omega0_hat (1 for t_s,
    1/2 for t_b of (26)); omega0_hat that of the touchdown state unless given."""
    w_td = geyer.touchdown_at_rest_length()[2] if w_td is None else w_td
    return fraction * (sp.pi + 2 * sp.atan(_atan_argument(w_td))) / w_td


def _event_time_forms(lhs, fraction):
    """Corrected (25) or (26) in omega0_hat, and omega0_hat of the touchdown state."""
    w_td = geyer.touchdown_at_rest_length()[2]
    return _touchdown_forms(lhs, lambda w: _corrected_event_time(fraction, w), w_td)


def _expect_asin_is_atan(ratio, atan_arg, what: str) -> None:
    """asin(x) == atan(y) for x in (-1, 1): both lie in (-pi/2, pi/2), so equal tangents suffice."""
    expect_zero(
        sp.simplify(sp.tan(sp.asin(ratio))) - atan_arg, f"{what}: tan(asin(-a/b)) equals the arctan argument"
    )


@equation(
    "25",
    "stance time in touchdown states",
    "corrected",
    "Printed |q_r_{t+t}| lacks the dot as in (23): t_s = [pi + 2 arctan((g_s - l0 q_thd_td^2)/"
    "(|q_rd_td| omega0_hat))]/omega0_hat, valid (0 < t_s < 2 pi/omega0_hat) on the whole domain.",
    derived=lambda: _event_time_forms(t_s, 1),
)
def check_eq25() -> None:
    """Printed: t_s = [pi + 2 arctan((g_s - l0 q_thd_td^2)/(|q_r_{t+t}| omega0_hat))]/omega0_hat.

    The leg-length symbol lacks its dot again (see eq 23).
    """
    t_s, _, ratio, w_td = _derived_event_times_td()
    arg = _atan_argument(w_td)
    corrected = _corrected_event_time(1)
    printed = (sp.pi + 2 * sp.atan((g_s - l0 * q_thd_td**2) / (sp.Abs(q_r_td) * w_td))) / w_td
    _expect_asin_is_atan(ratio, arg, "eq 25")
    expect_zero(
        (t_s - corrected).subs(sp.asin(ratio), sp.atan(arg)),
        "eq 25 corrected t_s equals (20) in touchdown states",
    )
    point = {q_r_td: 1, q_rd_td: -sp.Rational(1, 2), q_thd_td: -3, g_s: 10, l0: 1, k: 20000, m: 80}
    expect_nonzero(
        (printed - corrected).subs(point),
        f"eq 25 printed t_s with |q_r_td| differs from the corrected one at {point}",
    )


@equation(
    "26",
    "bottom time in touchdown states",
    "corrected",
    "Printed arctan(|q_rd_td| omega0_hat/(q_thd_td^2 l0 - g_s))/omega0_hat is negative when "
    "q_thd_td^2 l0 < g_s (slow gaits). Correct branch: t_b = atan2(|q_rd_td| omega0_hat, "
    "q_thd_td^2 l0 - g_s)/omega0_hat = [pi/2 + arctan((g_s - l0 q_thd_td^2)/(|q_rd_td| "
    "omega0_hat))]/omega0_hat = t_s/2, so 0 < t_b < t_s.",
    derived=lambda: _event_time_forms(t_b, sp.Rational(1, 2)),
)
def check_eq26() -> None:
    """Printed: t_b = arctan(|q_rd_td| omega0_hat/(q_thd_td^2 l0 - g_s))/omega0_hat.

    Off by pi/omega0_hat when q_thd_td^2 l0 < g_s.
    """
    t_s, t_b, ratio, w_td = _derived_event_times_td()
    arg = _atan_argument(w_td)
    corrected = _corrected_event_time(sp.Rational(1, 2))  # = atan2(|q_rd| w, q_thd^2 l0 - g_s) / w
    _expect_asin_is_atan(ratio, arg, "eq 26")
    expect_zero(
        (t_b - corrected).subs(sp.asin(ratio), sp.atan(arg)),
        "eq 26 corrected t_b equals (13) - (12) in touchdown states",
    )
    expect_zero(t_s - 2 * t_b, "eq 26 t_b = t_s/2, so 0 < t_b < t_s wherever t_s > 0")
    printed = sp.atan(sp.Abs(q_rd_td) * w_td / (q_thd_td**2 * l0 - g_s)) / w_td
    atan2_form = sp.atan2(sp.Abs(q_rd_td) * w_td, q_thd_td**2 * l0 - g_s) / w_td
    slow = {q_rd_td: -sp.Rational(1, 2), q_thd_td: -2, g_s: sp.Rational(981, 100), l0: 1, k: 20000, m: 80}
    fast = {**slow, q_thd_td: -5}
    expect(
        sp.N(printed.subs(slow)) < 0 < sp.N(corrected.subs(slow)),
        "eq 26 printed t_b is negative (and the corrected one positive) for a slow gait q_thd_td^2 l0 < g_s",
    )
    expect(abs(sp.N((printed - corrected).subs(fast))) < 1e-12, "eq 26 printed t_b holds for a fast gait")
    for name, point in (("slow", slow), ("fast", fast)):
        expect(
            abs(sp.N((atan2_form - corrected).subs(point))) < 1e-12,
            f"eq 26 atan2 form equals the corrected t_b ({name} gait)",
        )


# --------------------------------------------------------------------------------------------
# Section 3.1 with leg damping (not in the report): derive/maps/geyer_damped_helpers.py.

_OMEGA_SQ = sp.Symbol("omega_n", positive=True) ** 2


@equation(
    "sec3.1-damped",
    "damped radial equation under Assumption 1, linearized (not in the report)",
    "verified",
    "Not printed in the report: (4) with the leg damper's -c q_rd (sec2.2.1-damped), in (7)'s rho "
    "and omega, 1/(1+rho)^3 ~ 1 - 3 rho: rho'' + 2 delta rho' + (omega0^2 + 3 omega^2) rho = omega^2 - "
    "g_s/l0, delta = c/(2 m). At c = 0 it is the time derivative of (9): rho'' = lambda rho + mu/2.",
    derived=lambda: forms(
        (sp.Symbol("omega_n") ** 2, geyer_damped_helpers.damped_radial_equation()[0]),
        (
            sp.Derivative(rho, (t, 2)) + 2 * DELTA * rho_d + _OMEGA_SQ * rho,
            geyer_damped_helpers.damped_radial_equation()[1],
        ),
    ),
    extension=True,
)
def check_damped_radial() -> None:
    """Printed: nothing (the report's leg is lossless).
    Stated: rho'' + 2 delta rho' + omega_n^2 rho = omega^2 - g_s / l0, omega_n^2 = omega0^2 + 3 omega^2."""
    wn2, rhs = geyer_damped_helpers.damped_radial_equation()
    expect_zero(wn2 - (omega0**2 + 3 * omega**2), "omega_n^2 = omega0^2 + 3 omega^2")
    expect_zero(rhs - (omega**2 - g_s / l0), "the constant side is omega^2 - g_s / l0")
    lam_, mu_, _ = geyer.radial_quadratic()
    expect_zero(wn2 + lam_, "at c = 0 omega_n^2 = -lambda of (9)")
    expect_zero(rhs - mu_ / 2, "at c = 0 the constant side is mu / 2 of (9)")
    lossless = geyer.assumption1_equations()[0]
    expect_zero(
        geyer_damped_helpers.damped_assumption1_radial() - lossless - c * q_rd,
        "the damped (4) is (4) plus c q_rd",
    )


@equation(
    "sec3.1-dampedrho",
    "damped radial solution rho(t) from touchdown (not in the report)",
    "verified",
    "Not printed in the report: dsolve of the damped radial equation from (rho_td, rho_d_td): rho = a + "
    "exp(-delta t) (A_c cos(omega_D t) + B_s sin(omega_D t)), omega_D^2 = omega_n^2 - delta^2, a the "
    "offset of (11), A_c = rho_td - a, B_s = (rho_d_td + delta A_c) / omega_D. At delta = 0 it solves (9).",
    derived=lambda: forms(
        (rho, geyer_damped_helpers.damped_radial_solution()[0]),
        *geyer_damped_helpers.damped_radial_solution()[1].items(),
    ),
    extension=True,
)
def check_damped_solution() -> None:
    """Printed: nothing (the report's leg is lossless).
    Stated: the solution above; checked to solve the equation and to start at the touchdown state."""
    h = geyer_damped_helpers
    rho_t, coeffs = h.damped_radial_solution()
    wn2, rhs = h.damped_radial_equation()
    full = rho_t.subs({h.A_C: coeffs[h.A_C], h.B_S: coeffs[h.B_S]})
    residual = full.diff(t, 2) + 2 * DELTA * full.diff(t) + (h.OMEGA_D**2 + DELTA**2) * (full - a)
    expect_zero(residual, "rho(t) - a solves the homogeneous damped equation")
    expect_zero(coeffs[a] * wn2 - rhs, "omega_n^2 a is the constant side: rho = a is the particular solution")
    expect_zero(full.subs(t, 0) - h.RHO_TD, "rho(0) = rho_td")
    expect_zero(full.diff(t).subs(t, 0) - h.RHO_D_TD, "rho'(0) = rho_d_td")
    expect_zero(coeffs[a] - geyer.radial_solution_parameters()["a"], "the offset is (11)'s a")
    # delta = 0: rho'^2 - (lambda rho^2 + mu rho + nu) is constant in time, the first integral (9)
    lam_, mu_ = -(h.OMEGA_D**2), 2 * a * h.OMEGA_D**2  # (9) in omega_n = omega_D at delta = 0
    lossless = full.subs(DELTA, 0)
    integral = lossless.diff(t) ** 2 - lam_ * lossless**2 - mu_ * lossless
    expect_zero(integral.diff(t), "at delta = 0, rho'^2 - lambda rho^2 - mu rho is conserved (9)")


@equation(
    "sec3.1-dampedevents",
    "damped bottom time and liftoff force (not in the report)",
    "verified",
    "Not printed in the report: rho' = exp(-delta t) (P cos(omega_D t) + R sin(omega_D t)) is 0 first at "
    "omega_D t_b = pi/2 + atan(R / P) (P = rho_d_td < 0); liftoff (option force) where the leg force "
    "k (l0 - q_r) - c q_rd = -m l0 (omega0^2 rho + 2 delta rho') falls to 0, a root, not a closed form.",
    derived=lambda: forms(
        (sp.Symbol("t_bottom"), geyer_damped_helpers.damped_events()["t_bottom"]),
        (sp.Symbol("F_leg") / (m * l0), geyer_damped_helpers.damped_events()["force"]),
    ),
    extension=True,
)
def check_damped_events() -> None:
    """Printed: nothing (the report's leg is lossless).
    Stated: the bottom time and the leg force above; rho'(t_b) = 0, P = rho_d_td, and at delta = 0
    the bottom of (13) (omega_n t_b = pi/2 + asin(A_c / b), b^2 = A_c^2 + (rho_d_td / omega_n)^2)."""
    h = geyer_damped_helpers
    ev = h.damped_events()
    _, coeffs = h.damped_radial_solution()
    expect_zero(ev["cos"].subs(h.B_S, coeffs[h.B_S]).subs(h.A_C, coeffs[h.A_C]) - h.RHO_D_TD, "P = rho_d_td")
    at_bottom = sp.expand_trig(ev["rate"].subs(t, ev["t_bottom"]))
    expect_zero(at_bottom, "rho'(t_b) = 0")
    q_r_of = l0 * (1 + rho)
    force = k * (l0 - q_r_of) - c * l0 * rho_d
    stated = ev["force"]
    rho_t, _ = h.damped_radial_solution()
    expect_zero(
        force.subs({rho: rho_t, rho_d: ev["rate"], k: m * omega0**2, c: 2 * m * DELTA}) / (m * l0) - stated,
        "the leg force over m l0 is -(omega0^2 rho + 2 delta rho')",
    )
    point = {h.RHO_TD: -0.01, h.RHO_D_TD: -0.4, a: 0.05, h.OMEGA_D: 20.0, DELTA: 0}
    amplitude = sp.sqrt(0.06**2 + (0.4 / 20.0) ** 2)
    lossless = (sp.pi / 2 + sp.asin(-0.06 / amplitude)) / 20.0
    t_b = ev["t_bottom"].subs(h.B_S, coeffs[h.B_S]).subs(h.A_C, coeffs[h.A_C]).subs(point)
    expect(abs(sp.N(t_b - lossless)) < 1e-14, "at delta = 0 the bottom time is (13)'s")


@equation(
    "sec3.1-dampedangle",
    "damped leg angle q_th(t) (not in the report)",
    "verified",
    "Not printed in the report: (18)-(19) over the damped rho, the angular momentum conserved (the damper "
    "exerts no torque about the toe): q_th - q_th_td = int_0^t omega (1 - 2 rho), closed form.",
    derived=lambda: forms((q_th - q_th_td, geyer_damped_helpers.damped_leg_angle())),
    extension=True,
)
def check_damped_angle() -> None:
    """Printed: nothing (the report's leg is lossless).
    Stated: the integral above; its derivative is omega (1 - 2 rho(t)) and it is 0 at touchdown."""
    h = geyer_damped_helpers
    angle = h.damped_leg_angle()
    rho_t, _ = h.damped_radial_solution()
    expect_zero(angle.diff(t) - omega * (1 - 2 * rho_t), "d/dt q_th = omega (1 - 2 rho)")
    expect_zero(angle.subs(t, 0), "q_th(0) = q_th_td")
    expect_zero(
        mechanics.euler_lagrange_polar(k, g_s, c)[1] - mechanics.euler_lagrange_polar()[1],
        "the damper leaves the angular equation (3), so the angular momentum under Assumption 1",
    )


# --------------------------------------------------------------------------------------------
# Section 3.2: Hamiltonian (27)-(29), printed with the decompression stiffness k_d.


@equation(
    "27",
    "stance Hamiltonian (decompression, k_d)",
    "verified",
    "Legendre transform of (1) with k = k_d.",
    derived=lambda: iterates.hamiltonian_form("H", k_d),
)
def check_eq27() -> None:
    """Printed: H = (p_r^2 + p_th^2/q_r^2)/(2 m) + k_d/2 (l0 - q_r)^2 + m g_s q_r cos(q_th)."""
    printed = (p_r**2 + p_th**2 / q_r**2) / (2 * m) + k_d / 2 * (l0 - q_r) ** 2 + m * g_s * q_r * sp.cos(q_th)
    expect_zero(printed - mechanics.hamiltonian(k_d), "eq 27 printed H equals the Legendre transform of (1)")


definition(
    "28",
    "Hamilton's equations",
    derived=lambda: forms(
        *zip(
            sp.symbols("q_rd q_thd p_rd p_thd"),
            (sp.Derivative(H_OF_STATE, p_r), sp.Derivative(H_OF_STATE, p_th))
            + (-sp.Derivative(H_OF_STATE, q_r), -sp.Derivative(H_OF_STATE, q_th)),
            strict=True,
        )
    ),
)


@equation(
    "29",
    "Hamiltonian vector field",
    "verified",
    "From (27) and (28).",
    derived=lambda: iterates.vector_field_forms(k_d),
)
def check_eq29() -> None:
    """Printed: X_H = (dq_r/dt, dq_th/dt, dp_r/dt, dp_th/dt) = (p_r/m, p_th/(m q_r^2),
    p_th^2/(m q_r^3) + k_d (l0 - q_r) - m g_s cos q_th, m g_s q_r sin q_th).
    """
    printed = (
        p_r / m,
        p_th / (m * q_r**2),
        p_th**2 / (m * q_r**3) + k_d * (l0 - q_r) - m * g_s * sp.cos(q_th),
        m * g_s * q_r * sp.sin(q_th),
    )
    _expect_rows_zero(
        printed,
        mechanics.hamiltonian_vector_field(k_d),
        "eq 29 printed X_H equals Hamilton's equations of (27)",
    )


# --------------------------------------------------------------------------------------------
# Section 3.2: Schwind and Koditschek's iterative map (30)-(45), leg length as the variable.


@equation(
    "30",
    "dt/dq_r = m/p_r",
    "verified",
    "Rate of time per leg length: 1/(dq_r/dt) with dq_r/dt = p_r/m of (29); t_s names the time.",
    derived=lambda: iterates.rate_form(k_d, 0),
)
@equation(
    "31",
    "dq_th/dq_r = p_th/(q_r^2 p_r)",
    "verified",
    "dq_th/dt of (29) divided by dq_r/dt = p_r/m.",
    derived=lambda: iterates.rate_form(k_d, 1),
)
@equation(
    "32",
    "dp_th/dq_r = m^2 g_s q_r sin(q_th)/p_r",
    "verified",
    "dp_th/dt = +m g_s q_r sin q_th of (29) divided by dq_r/dt = p_r/m; the gravity sign is the "
    "correct one (that of (29), not of (3)).",
    derived=lambda: iterates.rate_form(k_d, 2),
)
def check_eq30_32() -> None:
    """Printed: (30) dt_s/dq_r = m/p_r; (31) dq_th/dq_r = p_th/(q_r^2 p_r);
    (32) dp_th/dq_r = m^2 g_s q_r sin(q_th)/p_r (each a function of q_r, q_th, p_th via p_r of (33)).
    """
    dt, dq_th, dp_th = iterative_helpers.leg_length_derivatives(k_d)
    expect_zero(m / p_r - dt, "eq 30 printed dt/dq_r equals 1/(dq_r/dt) of (29)")
    expect_zero(p_th / (q_r**2 * p_r) - dq_th, "eq 31 printed dq_th/dq_r equals (dq_th/dt)/(dq_r/dt) of (29)")
    expect_zero(
        m**2 * g_s * q_r * sp.sin(q_th) / p_r - dp_th,
        "eq 32 printed dp_th/dq_r equals (dp_th/dt)/(dq_r/dt) of (29)",
    )


@equation(
    "33",
    "p_r = H^{-1}(q_r, q_th, p_th, E)",
    "verified",
    "The positive root (decompression, p_r > 0) of H = E with H of (27).",
    derived=lambda: forms((p_r, iterative_helpers.radial_momentum(k_d))),
)
def check_eq33() -> None:
    """Printed: p_r = H^{-1} = sqrt(2 m (E - k_d/2 (l0 - q_r)^2 - m g_s q_r cos(q_th)) - p_th^2/q_r^2)."""
    printed = sp.sqrt(
        2 * m * (E - k_d / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(q_th)) - p_th**2 / q_r**2
    )
    derived = iterative_helpers.radial_momentum(k_d)
    expect_zero(printed - derived, "eq 33 printed H^{-1} equals the positive root of H = E for p_r")
    expect_zero(
        mechanics.hamiltonian(k_d).subs(p_r, printed) - E, "eq 33 H of (27) at p_r = printed H^{-1} equals E"
    )


definition(
    "34",
    "Theorem 1, part 1: mean value point xi_x of int f g",
    "Weighted mean value theorem for integrals, quoted from Schwind and Koditschek: an existence "
    "statement (f continuous, g >= 0), nothing to derive.",
)


@equation(
    "35",
    "Theorem 1, part 2: lim (xi_x - a)/(x - a) = ((s+1)/(r+s+1))^(1/r)",
    "verified",
    "A theorem; checked on examples f - K = c (t-a)^r (1 + t - a), g = (t-a)^s (2 + t - a) for "
    "(r, s) = (1/2, -1/2), (-1/2, 0), (1, 0), (2, 1), (-1/2, 1): the limit of xi_x computed from "
    "(34) matches. The first two are the cases of (41).",
)
def check_eq35() -> None:
    """Printed: lim_{x -> a} (xi_x - a)/(x - a) = ((s + 1)/(r + s + 1))^(1/r).

    For f(t) - K ~ c (t - a)^r and g(t) ~ (t - a)^s, xi_x of (34) solves f(xi_x) - K = int (f - K) g / int g.
    With lambda = (xi_x - a)/(x - a) and u = x - a, f(xi_x) - K = c lambda^r u^r (1 + lambda u), so
    lambda^r tends to the limit of (int (f - K) g / int g)/(c u^r) as u -> 0.
    """
    tau, u, c = sp.symbols("tau u c", positive=True)  # tau = t - a, u = x - a
    half = sp.Rational(1, 2)
    for r, s in ((half, -half), (-half, 0), (1, 0), (2, 1), (-half, 1)):
        r, s = sp.S(r), sp.S(s)
        f_minus_k = c * tau**r * (1 + tau)
        g = tau**s * (2 + tau)
        mean = sp.integrate(f_minus_k * g, (tau, 0, u)) / sp.integrate(g, (tau, 0, u))
        lam_r = sp.limit(mean / (c * u**r), u, 0, "+")
        printed = ((s + 1) / (r + s + 1)) ** (1 / r)
        expect_zero(
            lam_r ** (1 / r) - printed, f"eq 35 printed limit equals the computed one for (r, s) = ({r}, {s})"
        )


definition(
    "36",
    "Observation 1: xi_x ~ a + ((s+1)/(r+s+1))^(1/r) (x - a)",
    "An approximation motivated by (35), for x near a. OCR: 'nera' for 'near'.",
)
definition(
    "37",
    "Observation 1: int f g ~ f(xi_hat_x) int g",
    "(34) with xi_x replaced by the approximation (36); an approximation, for x near a.",
)
definition(
    "38",
    "mean-value approximation of int 1/H^{-1} dsigma",
    "(37) with f = the whole integrand and g = 1, so that int g = q_r - q_r_b; the printed "
    "H^{-1}(sigma, q_th, p_th, E) stands for H^{-1}(sigma, q_th(sigma), p_th(sigma), E). An "
    "approximation; its point xi is derived in (41).",
)
definition(
    "39",
    "mean-value approximation of int 1/(sigma^2 H^{-1}) dsigma",
    "As (38), with f = 1/(sigma^2 H^{-1}).",
)
definition(
    "40",
    "mean-value approximation of int sigma/H^{-1} dsigma",
    "As (38), with f = sigma/H^{-1}.",
)


@equation(
    "41",
    "mean-value point xi = 3/4 q_r_b + 1/4 q_r",
    "verified",
    "At the bottom H^{-1}(q_r_b) = 0 and H^{-1} ~ sqrt(2 m (dp_r/dt)_b) (sigma - q_r_b)^(1/2) (SymPy "
    "series, also along the trajectory of (29)), so the integrands of (38)-(40) have r = -1/2 with "
    "g = 1 (s = 0): (35) gives ((s+1)/(r+s+1))^(1/r) = 1/4. The reading with the weight g = 1/H^{-1} "
    "(s = -1/2) and f = q_th(sigma) or p_th(sigma) (r = 1/2) gives 1/4 too. With this xi, (38) "
    "reproduces the leading term of its integral exactly. The display writes xi_hat_x, the "
    "iteration xi_hat_r.",
    derived=lambda: forms((xi, iterative_helpers.mean_value_point(k_d))),
)
def check_eq41() -> None:
    """Printed: xi_hat_x = 3/4 q_r_b + 1/4 q_r."""
    at_bottom = {q_r: q_r_b, q_th: q_th_b, p_th: p_th_b}
    dp_r_b = mechanics.hamiltonian_vector_field(k_d)[2].subs(at_bottom)  # (dp_r/dt)_b of (29)
    momentum = iterative_helpers.near_bottom(p_r, k_d)
    expect_zero(momentum.subs(delta, 0), "eq 41 H^{-1} vanishes at the bottom q_r = q_r_b")
    coeff, power = momentum.leadterm(delta)
    expect_zero(power - sp.Rational(1, 2), "eq 41 H^{-1} ~ (sigma - q_r_b)^(1/2) at the bottom")
    expect_zero(coeff**2 - 2 * m * dp_r_b, "eq 41 leading coefficient of H^{-1} equals sqrt(2 m (dp_r/dt)_b)")
    # Along the actual trajectory of (29) from the bottom (q_th, p_th varying too): p_r^2 = 2 m
    # (dp_r/dt)_b (q_r - q_r_b) up to O(t^3) while q_r - q_r_b ~ t^2, i.e. the same leading term.
    trajectory = iterative_helpers.taylor_from_bottom(p_r**2 - 2 * m * dp_r_b * (q_r - q_r_b), 2, k_d)
    expect_zero(trajectory, "eq 41 p_r^2 = 2 m (dp_r/dt)_b (q_r - q_r_b) + O(t^3) along the flow of (29)")
    exponents = iterative_helpers.integrand_exponents(k_d)
    quarter = sp.Rational(1, 4)
    for key, fraction in iterative_helpers.mean_value_fractions(k_d).items():
        expect_zero(
            exponents[key] + sp.Rational(1, 2), f"eq 41 integrand of ({key}) ~ (sigma - q_r_b)^(-1/2)"
        )
        expect_zero(fraction - quarter, f"eq 41 (35) with f = integrand of ({key}), g = 1 gives 1/4")
    for key in ("q_th", "p_th"):
        fraction = iterative_helpers.theorem1_fraction(exponents[key], -exponents["p_r"])
        expect_zero(fraction - quarter, f"eq 41 (35) with f = {key}(sigma), g = 1/H^{{-1}} gives 1/4")
    xi = iterative_helpers.mean_value_point(k_d)
    printed = sp.Rational(3, 4) * q_r_b + quarter * q_r
    expect_zero(printed - xi, "eq 41 printed xi equals q_r_b + (1/4)(q_r - q_r_b) of (35)")
    # (38) with this xi is exact on the leading term c (sigma - q_r_b)^(-1/2) of its integrand.
    u = sp.Symbol("u", positive=True)
    integral = sp.integrate(u ** sp.Rational(-1, 2), (u, 0, delta))
    approximation = ((xi - q_r_b) ** sp.Rational(-1, 2) * (q_r - q_r_b)).subs(q_r, q_r_b + delta)
    expect_zero(
        integral - approximation,
        "eq 41 (38) at this xi reproduces int (sigma - q_r_b)^(-1/2) dsigma exactly",
    )


def _printed_eq42_44():
    """Eqs (42)-(44) as printed, with H^{-1}(...) the unevaluated H_INV and the printed xi of (41)."""
    xi = sp.Rational(3, 4) * q_r_b + sp.Rational(1, 4) * q_r
    h_inv = H_INV(xi, Q_TH_N(xi), P_TH_N(xi), E)
    step = q_r - q_r_b
    return (
        t_b + m / h_inv * step,
        q_th_b + P_TH_N(xi) / (xi**2 * h_inv) * step,
        p_th_b + m**2 * g_s * xi * sp.sin(Q_TH_N(xi)) / h_inv * step,
    )


@equation(
    "42",
    "iterate of the time t_(n+1)(q_r)",
    "verified",
    "(30) integrated from the bottom with (38): t_b + [dt/dq_r of (30) at xi on the n-th iterate] "
    "(q_r - q_r_b), xi of (41). The printed t_s_(n+1) includes the bottom time t_b: it is the time "
    "at leg length q_r, not a duration.",
    derived=lambda: iterates.iterate_form(
        iterative_helpers.iteration_step(k_d, xi), 0, iterative_helpers.mean_value_point(k_d)
    ),
)
@equation(
    "43",
    "iterate of the leg angle q_th_(n+1)(q_r)",
    "verified",
    "(31) integrated from the bottom with (39): q_th_b + [dq_th/dq_r of (31) at xi on the n-th "
    "iterate] (q_r - q_r_b).",
    derived=lambda: iterates.iterate_form(
        iterative_helpers.iteration_step(k_d, xi), 1, iterative_helpers.mean_value_point(k_d)
    ),
)
@equation(
    "44",
    "iterate of the angular momentum p_th_(n+1)(q_r)",
    "verified",
    "(32) integrated from the bottom with (40): p_th_b + [dp_th/dq_r of (32) at xi on the n-th "
    "iterate] (q_r - q_r_b); sin(q_th_n(xi)) is evaluated at xi with the rest of the integrand.",
    derived=lambda: iterates.iterate_form(
        iterative_helpers.iteration_step(k_d, xi), 2, iterative_helpers.mean_value_point(k_d)
    ),
)
def check_eq42_44() -> None:
    """Printed, with H^{-1}_n = H^{-1}(xi, q_th_n(xi), p_th_n(xi), E):
    (42) t_(n+1)(q_r) = t_b + m/H^{-1}_n (q_r - q_r_b);
    (43) q_th_(n+1)(q_r) = q_th_b + p_th_n(xi)/(xi^2 H^{-1}_n) (q_r - q_r_b);
    (44) p_th_(n+1)(q_r) = p_th_b + m^2 g_s xi sin(q_th_n(xi))/H^{-1}_n (q_r - q_r_b).
    """
    derived = iterative_helpers.iteration_step(k_d)
    for key, printed, built in zip(("42", "43", "44"), _printed_eq42_44(), derived, strict=True):
        expect_zero(
            printed - built, f"eq {key} printed iterate equals (30)-(32) integrated with (37) at xi of (41)"
        )


@equation(
    "45",
    "iterate of the radial momentum p_r_(n+1)(q_r)",
    "corrected",
    "Printed sqrt(2 m (E - k_d/2 (l0 - xi)^2 - m g_s xi cos q_th_(n+1)(xi)) - p_th_(n+1)(xi)^2/xi^2) "
    "= H^{-1}(xi, q_th_(n+1)(xi), p_th_(n+1)(xi), E) is p_r at the leg length xi, not at q_r. By (33): "
    "p_r_(n+1)(q_r) = H^{-1}(q_r, q_th_(n+1)(q_r), p_th_(n+1)(q_r), E) = sqrt(2 m (E - k_d/2 (l0 - "
    "q_r)^2 - m g_s q_r cos q_th_(n+1)(q_r)) - p_th_(n+1)(q_r)^2/q_r^2). OCR: the trailing '(4' is "
    "the equation tag (45) run into the display.",
    derived=lambda: iterates.next_momentum_form(k_d, E, 1),
)
def check_eq45() -> None:
    """Printed: p_r_(n+1)(q_r) = sqrt(2 m (E - k_d/2 (l0 - xi)^2 - m g_s xi cos(q_th_(n+1)(xi)))
    - p_th_(n+1)(xi)^2/xi^2)   (OCR: followed by a stray '(4')."""
    printed = sp.sqrt(
        2 * m * (E - k_d / 2 * (l0 - xi) ** 2 - m * g_s * xi * sp.cos(Q_TH_NEXT(xi)))
        - P_TH_NEXT(xi) ** 2 / xi**2
    )
    h_inv = iterative_helpers.radial_momentum(k_d)
    at_xi = h_inv.subs({q_r: xi, q_th: Q_TH_NEXT(xi), p_th: P_TH_NEXT(xi)}, simultaneous=True)
    expect_zero(printed - at_xi, "eq 45 printed p_r is (33) at the leg length xi on the (n+1)-th iterate")
    printed = printed.subs(xi, sp.Rational(3, 4) * q_r_b + sp.Rational(1, 4) * q_r)
    derived = iterative_helpers.next_radial_momentum(k_d)  # (33) at q_r on the (n+1)-th iterate
    expect_zero(
        iterates.next_momentum(k_d, E, 1) - derived,
        "eq 45 corrected p_r equals (33) at q_r on the (n+1)-th iterate",
    )
    # Refute the printed form at a concrete state: constant iterates (q_th = 0.1, p_th = 2), q_r above
    # the bottom (so xi != q_r), on an energy level where both square roots are real.
    x = sp.Symbol("x")
    difference = (printed - derived).replace(Q_TH_NEXT, sp.Lambda(x, sp.Rational(1, 10)))
    difference = difference.replace(P_TH_NEXT, sp.Lambda(x, 2))
    point = {m: 80, k_d: 20000, l0: 1, g_s: sp.Rational(981, 100), E: 1500, q_r_b: sp.Rational(4, 5), q_r: 1}
    value = sp.N(difference.subs(point))
    expect(value.is_real is True, f"eq 45 printed and corrected p_r are real at the sample state {point}")
    expect(abs(value) > 1, f"eq 45 printed p_r differs from (33) at q_r at the sample state {point}")
