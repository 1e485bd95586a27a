"""The report's equations as printed, checked against the derivations (registry entries).

The ``printed_*`` expressions are transcriptions of the report's displays (the one place in
slipmaps where formulas are typed rather than derived): each check compares a transcription
with what :mod:`.mechanics`, :mod:`.flight` or :mod:`.geyer` derived. Transcriptions keep the
report's errors; the corrected forms are built from the derivation or stated next to the error.
"""

from __future__ import annotations

import sympy as sp

from . import geyer, mechanics
from .registry import Entry, all_zero, is_zero
from .symbols import (
    a,
    b,
    b_x,
    b_xd,
    b_y,
    b_yd,
    epsilon,
    g_f,
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

q_rdd, q_thdd = sp.symbols("q_rdd q_thdd", real=True)
n_int = sp.Symbol("n", integer=True, nonnegative=True)
s_sym = sp.Symbol("s", real=True)
b_pos = sp.Symbol("b", positive=True)
t_td = sp.Symbol("t_td", real=True)
LAM, MU, NU = sp.symbols("lambda mu nu", real=True)


def _spring_force(stiffness=k):
    return stiffness * (l0 - q_r)


# --------------------------------------------------------------------------------------------
# Section 2.2: stance and flight dynamics displays (unnumbered).


def check_stance_polar_display() -> bool:
    """Printed: q_thdd = -g_s sin(q_th)/q_r - 2 q_r q_thd/q_r; q_rdd = F_s/m + q_r q_thd^2 - g_s cos q_th."""
    _, rdd, _, thdd = mechanics.stance_polar_rhs()
    printed_thdd = -g_s * sp.sin(q_th) / q_r - 2 * q_r * q_thd / q_r
    printed_rdd = _spring_force() / m + q_r * q_thd**2 - g_s * sp.cos(q_th)
    corrected_thdd = g_s * sp.sin(q_th) / q_r - 2 * q_rd * q_thd / q_r
    return is_zero(printed_rdd - rdd) and not is_zero(printed_thdd - thdd) and is_zero(corrected_thdd - thdd)


def check_stance_cartesian_display() -> bool:
    """Printed (flat ground): b_xdd = -F_s sin(atan(b_y/b_x))/m, b_ydd = F_s cos(atan(b_y/b_x))/m - g_s."""
    _, xdd, _, ydd = mechanics.stance_cartesian_rhs()
    radius = sp.sqrt(b_x**2 + b_y**2)
    force = k * (l0 - radius)
    printed_angle = sp.atan(b_y / b_x)
    printed = (-force * sp.sin(printed_angle) / m, force * sp.cos(printed_angle) / m - g_s)
    corrected_angle = sp.atan2(-b_x, b_y)  # q_th of the Table 1 convention
    corrected = (-force * sp.sin(corrected_angle) / m, force * sp.cos(corrected_angle) / m - g_s)
    # The first-line (polar) form b_xdd = -F sin(q_th)/m, b_ydd = F cos(q_th)/m - g_s holds; the
    # angle arctan(b_y / b_x) measured from the horizontal is not q_th. Check at a body above the toe.
    point = {b_x: sp.Rational(-3, 10), b_y: sp.Rational(9, 10), b_xd: 2, b_yd: -1}
    printed_ok = all_zero([(p - d).subs(point) for p, d in zip(printed, (xdd, ydd), strict=True)])
    corrected_ok = all_zero([sp.simplify(c - d) for c, d in zip(corrected, (xdd, ydd), strict=True)])
    return corrected_ok and not printed_ok


def check_flight_display() -> bool:
    """Printed: d/dt (b_x, b_xd, b_y, b_yd, b_tx) = (b_xd, 0, b_yd, -g_f, b_xd)."""
    printed = (b_xd, 0, b_yd, -g_f)
    return all_zero([p - d for p, d in zip(printed, mechanics.flight_rhs(), strict=True)])


# --------------------------------------------------------------------------------------------
# Section 3.1: eqs 1-26.


def printed_eq1():
    return m / 2 * (q_rd**2 + q_r**2 * q_thd**2) - k / 2 * (l0 - q_r) ** 2 - m * g_s * q_r * sp.cos(q_th)


def check_eq1() -> bool:
    return is_zero(printed_eq1() - mechanics.lagrangian_polar())


def check_eq2() -> bool:
    el_r, _ = mechanics.euler_lagrange_polar()
    printed = m * q_rdd - (m * q_r * q_thd**2 + k * (l0 - q_r) - m * g_s * sp.cos(q_th))
    return is_zero(printed - el_r)


def check_eq3() -> bool:
    _, el_th = mechanics.euler_lagrange_polar()
    ddt_momentum = m * q_r**2 * q_thdd + 2 * m * q_r * q_rd * q_thd  # d/dt (m q_r^2 q_thd)
    printed = ddt_momentum + m * g_s * q_r * sp.sin(q_th)
    corrected = ddt_momentum - m * g_s * q_r * sp.sin(q_th)
    return not is_zero(printed - el_th) and is_zero(corrected - el_th)


def check_eq4_eq5() -> bool:
    el_r, el_th = geyer.assumption1_equations()
    printed4 = m * q_rdd - (m * q_r * q_thd**2 + k * (l0 - q_r) - m * g_s)
    printed5 = m * q_r**2 * q_thdd + 2 * m * q_r * q_rd * q_thd
    return is_zero(printed4 - el_r) and is_zero(printed5 - el_th)


def printed_eq6():
    return m / 2 * q_rd**2 + p_th**2 / (2 * m * q_r**2) + k / 2 * (l0 - q_r) ** 2 + m * g_s * q_r


def check_eq6() -> bool:
    derived = geyer.energy_assumption1()
    if not is_zero(printed_eq6() - derived):
        return False
    # And it is a first integral of (4)-(5): dE/dt = 0 along the Assumption-1 flow.
    el_r, el_th = geyer.assumption1_equations()
    acc = sp.solve([el_r, el_th], [q_rdd, q_thdd], dict=True)[0]
    energy_v = derived.subs(p_th, m * q_r**2 * q_thd)
    d_energy = (
        energy_v.diff(q_r) * q_rd + energy_v.diff(q_rd) * acc[q_rdd] + energy_v.diff(q_thd) * acc[q_thdd]
    )
    return is_zero(d_energy)


def check_eq8() -> bool:
    printed = rho_d**2 + omega**2 / (1 + rho) ** 2 + omega0**2 * rho**2 + 2 * g_s / l0 * (1 + rho)
    return is_zero(printed - geyer.dimensionless_energy())


def check_taylor() -> bool:
    return is_zero(1 - 2 * rho + 3 * rho**2 - geyer.taylor_inverse_square())


def check_eq9() -> bool:
    printed = (-(3 * omega**2 + omega0**2), 2 * (omega**2 - g_s / l0), epsilon - omega**2 - 2 * g_s / l0)
    return all_zero([p - d for p, d in zip(printed, geyer.radial_quadratic(), strict=True)])


def check_eq10() -> bool:
    """Corrected: the square root covers the whole discriminant mu^2 - 4 lambda nu."""
    big_l, disc = sp.symbols("L D", positive=True)  # lambda = -L < 0, D = mu^2 - 4 lambda nu > 0
    nu_d = (disc - MU**2) / (4 * big_l)
    quad = -big_l * rho**2 + MU * rho + nu_d
    corrected = geyer.antiderivative(-big_l, MU, nu_d)
    d_corr = sp.diff(corrected, rho)
    corrected_ok = is_zero(sp.simplify(d_corr**2 * quad) - 1)
    # Sign: positive derivative at an interior point.
    point = {big_l: 2, disc: 9, MU: 1, rho: sp.Rational(1, 10)}
    corrected_ok = corrected_ok and d_corr.subs(point).evalf() > 0
    printed = (
        -1 / sp.sqrt(big_l) * sp.asin((2 * (-big_l) * rho + MU) / (sp.sqrt(MU**2) - 4 * (-big_l) * nu_d))
    )
    d_printed = sp.diff(printed, rho)
    printed_ok = abs(sp.N((d_printed**2 * quad - 1).subs(point))) < 1e-12
    return corrected_ok and not printed_ok


def printed_eq11():
    w_hat = sp.sqrt(omega0**2 + 3 * omega**2)
    a_ = (omega**2 - g_s / l0) / (omega0**2 + 3 * omega**2)
    b_ = sp.sqrt(
        (omega**2 - g_s / l0) ** 2 + (omega0**2 + 3 * omega**2) * (epsilon - omega**2 - 2 * g_s / l0)
    ) / (omega0**2 + 3 * omega**2)
    b_alt = sp.sqrt(a_**2 + (epsilon - omega**2 - 2 * g_s / l0) / w_hat**2)
    return w_hat, a_, b_, b_alt


def check_eq11() -> bool:
    sol = geyer.radial_solution_parameters()
    w_hat, a_, b_, b_alt = printed_eq11()
    same = all_zero([w_hat - sol["omega0_hat"], a_ - sol["a"], b_**2 - sol["b2"], b_alt**2 - sol["b2"]])
    # rho(t) = a + b sin(omega0_hat t) solves rho_d^2 = lambda rho^2 + mu rho + nu of (9).
    lam_, mu_, nu_ = geyer.radial_quadratic()
    rho_t = a_ + b_ * sp.sin(w_hat * t)
    ode = sp.diff(rho_t, t) ** 2 - (lam_ * rho_t**2 + mu_ * rho_t + nu_)
    return same and is_zero(
        sp.expand(sp.expand_trig(ode)).subs(sp.cos(w_hat * t) ** 2, 1 - sp.sin(w_hat * t) ** 2)
    )


def _printed_phases(s_td, s_lo):
    """Eqs (12)-(14): omega0_hat * (t_td, t_b, t_lo) as printed, for any n."""
    base = (2 * n_int + sp.Rational(3, 2)) * sp.pi
    return base - (sp.pi / 2 + sp.asin(s_td)), base, base + (sp.pi / 2 + sp.asin(s_lo))


def check_eq12_14() -> bool:
    ph = geyer.event_phases()
    p_td, p_b, p_lo = _printed_phases(s_sym, s_sym)
    ok = True
    # Each printed phase is the derived one plus 2 n pi.
    for printed, derived in ((p_td, ph["touchdown"]), (p_b, ph["bottom"]), (p_lo, ph["liftoff"])):
        ok &= is_zero(printed - derived - 2 * n_int * sp.pi)
    # And they are the right roots: rho = q_r/l0 - 1 (sin = s), compressing before the bottom
    # (cos < 0), extending after it (cos > 0), bottom at the minimum sin = -1.
    ok &= is_zero(sp.sin(p_td) - s_sym) and is_zero(sp.cos(p_td) + sp.sqrt(1 - s_sym**2))
    ok &= is_zero(sp.sin(p_lo) - s_sym) and is_zero(sp.cos(p_lo) - sp.sqrt(1 - s_sym**2))
    ok &= sp.simplify(sp.sin(p_b)) == -1
    return bool(ok)


def check_eq15_16() -> bool:
    p_td, _, p_lo = _printed_phases(-a / b, -a / b)
    g_td, _, g_lo = _printed_phases(geyer.leg_length_ratio(l0), geyer.leg_length_ratio(l0))
    return is_zero(p_td - g_td) and is_zero(p_lo - g_lo)


def check_eq17() -> bool:
    exact, linear = geyer.angular_rate()
    return is_zero(omega / (1 + rho) ** 2 - exact) and is_zero(omega * (1 - 2 * rho) - linear)


def check_eq18_19() -> bool:
    derived, td_sym = geyer.leg_angle()
    derived = derived.subs(td_sym, t_td)
    printed18 = q_th_td + sp.integrate(omega * ((1 - 2 * a) - 2 * b * sp.sin(omega0_hat * t)), (t, t_td, t))
    printed19 = (
        q_th_td
        + omega * (1 - 2 * a) * (t - t_td)
        + 2 * b * omega / omega0_hat * (sp.cos(omega0_hat * t) - sp.cos(omega0_hat * t_td))
    )
    return is_zero(printed18 - derived) and is_zero(printed19 - derived)


def check_eq20() -> bool:
    gen = geyer.stance_time_general()
    derived = gen["t_stance"].subs(geyer.q_r_lo, l0).subs(q_r_td, l0)
    printed = (sp.pi + 2 * sp.asin(-a / b)) / omega0_hat
    return is_zero(printed - derived)


def _with_positive_b(expr):
    return sp.simplify(sp.sympify(expr).subs(b, b_pos))


def check_eq21_22() -> bool:
    q_r_t, q_th_t = geyer.touchdown_shifted_solution()
    root = sp.sqrt(b_pos**2 - a**2)
    printed21 = l0 + l0 * (a * (1 - sp.cos(omega0_hat * t)) - root * sp.sin(omega0_hat * t))
    printed22 = (
        q_th_td
        + (1 - 2 * a) * omega * t
        + 2 * omega / omega0_hat * (a * sp.sin(omega0_hat * t) + root * (1 - sp.cos(omega0_hat * t)))
    )
    return is_zero(_with_positive_b(q_r_t) - printed21) and is_zero(_with_positive_b(q_th_t) - printed22)


def _touchdown_at_rest_length():
    """a, sqrt(b^2 - a^2) and omega0_hat from a touchdown state with q_r_td = l0 (eqs 7-11)."""
    td = geyer.touchdown_parameters()
    sol = geyer.radial_solution_parameters()
    sub = {omega: td["omega"], epsilon: td["epsilon"], omega0: td["omega0"]}
    at_l0 = {q_r_td: l0}
    a_td = sp.simplify(sol["a"].subs(sub).subs(at_l0))
    b2_td = sp.simplify(sol["b2"].subs(sub).subs(at_l0))
    w_td = sp.simplify(sol["omega0_hat"].subs(sub).subs(at_l0))
    root = sp.sqrt(sp.factor(sp.simplify(b2_td - a_td**2)))
    return a_td, root, w_td


def _derived_eq23_24():
    a_td, root, w_td = _touchdown_at_rest_length()
    q_r_t, q_th_t = geyer.touchdown_shifted_solution()
    sub = {a: a_td, omega0_hat: w_td, omega: q_thd_td}
    # sqrt(b^2 - a^2) = |q_rd_td| / (l0 omega0_hat): the touchdown radial speed fixes the amplitude.
    q_r_t = _with_positive_b(q_r_t).subs(sp.sqrt(b_pos**2 - a**2), root).subs(sub)
    q_th_t = _with_positive_b(q_th_t).subs(sp.sqrt(b_pos**2 - a**2), root).subs(sub)
    return q_r_t, q_th_t, w_td


def _printed_eq23(speed):
    w_hat = sp.sqrt(k / m + 3 * q_thd_td**2)
    wt = w_hat * t
    return l0 - sp.Abs(speed) / w_hat * sp.sin(wt) + (q_thd_td**2 * l0 - g_s) / w_hat**2 * (1 - sp.cos(wt))


def check_eq23() -> bool:
    """Printed with |q_r_td| (the leg length); the derivation needs |q_rd_td| (the radial speed)."""
    derived, _, _ = _derived_eq23_24()
    return not is_zero(_printed_eq23(q_r_td) - derived) and is_zero(_printed_eq23(q_rd_td) - derived)


def check_eq24() -> bool:
    _, derived, _ = _derived_eq23_24()
    w_hat = sp.sqrt(k / m + 3 * q_thd_td**2)
    wt = w_hat * t
    a_p = (q_thd_td**2 - g_s / l0) / w_hat**2
    printed = (
        q_th_td
        + (1 - 2 * a_p) * q_thd_td * t
        + 2 * q_thd_td / w_hat * (a_p * sp.sin(wt) + sp.Abs(q_rd_td) / (w_hat * l0) * (1 - sp.cos(wt)))
    )
    return is_zero(printed - derived)


def _derived_event_times_td():
    """t_s and t_b from touchdown (q_r_td = q_r_lo = l0) in touchdown states."""
    a_td, root, w_td = _touchdown_at_rest_length()
    gen = geyer.stance_time_general()
    # At q_r_td = l0: s_td = s_lo = -a/b, and a/b = a / sqrt(a^2 + (b^2 - a^2)).
    ratio = -a_td / sp.sqrt(a_td**2 + root**2)
    s_expr = geyer.leg_length_ratio(l0)
    t_s = gen["t_stance"].subs(geyer.q_r_lo, l0).subs(q_r_td, l0)
    t_b = gen["t_bottom"].subs(q_r_td, l0)
    assert is_zero(s_expr + a / b)
    t_s = t_s.subs(sp.asin(s_expr), sp.asin(ratio)).subs(omega0_hat, w_td)
    t_b = t_b.subs(sp.asin(s_expr), sp.asin(ratio)).subs(omega0_hat, w_td)
    return t_s, t_b, ratio, w_td, a_td, root


def _asin_as_atan_ok(ratio, atan_arg) -> bool:
    """asin(x) == atan(y) for x in (-1, 1): both lie in (-pi/2, pi/2), so equal tangents suffice."""
    return is_zero(sp.simplify(sp.tan(sp.asin(ratio))) - atan_arg)


def check_eq25() -> bool:
    """Printed with |q_r_{t+t}|: the leg-length symbol again lacks its dot (see eq 23)."""
    t_s, _, ratio, w_td, _, _ = _derived_event_times_td()
    arg = (g_s - l0 * q_thd_td**2) / (sp.Abs(q_rd_td) * w_td)
    corrected = (sp.pi + 2 * sp.atan(arg)) / w_td
    printed = (sp.pi + 2 * sp.atan((g_s - l0 * q_thd_td**2) / (sp.Abs(q_r_td) * w_td))) / w_td
    structure = is_zero((t_s - corrected).subs(sp.asin(ratio), sp.atan(arg)))
    point = {q_r_td: 1, q_rd_td: -sp.Rational(1, 2), q_thd_td: -3, g_s: 10, l0: 1, k: 20000, m: 80}
    return _asin_as_atan_ok(ratio, arg) and structure and not is_zero((printed - corrected).subs(point))


def check_eq26() -> bool:
    """Printed t_b = atan(|q_rd| w / (q_thd^2 l0 - g_s)) / w: off by pi/w when q_thd^2 l0 < g_s."""
    t_s, t_b, ratio, w_td, _, _ = _derived_event_times_td()
    arg = (g_s - l0 * q_thd_td**2) / (sp.Abs(q_rd_td) * w_td)
    corrected = (sp.pi / 2 + sp.atan(arg)) / w_td  # = atan2(|q_rd| w, q_thd^2 l0 - g_s) / w
    structure = is_zero((t_b - corrected).subs(sp.asin(ratio), sp.atan(arg)))
    symmetric = is_zero(t_s - 2 * t_b)  # t_b = t_s / 2, so 0 < t_b < t_s wherever t_s > 0
    printed = sp.atan(sp.Abs(q_rd_td) * w_td / (q_thd_td**2 * l0 - g_s)) / w_td
    atan2_form = sp.atan2(sp.Abs(q_rd_td) * w_td, q_thd_td**2 * l0 - g_s) / w_td
    slow = {q_rd_td: -sp.Rational(1, 2), q_thd_td: -2, g_s: sp.Rational(981, 100), l0: 1, k: 20000, m: 80}
    fast = {**slow, q_thd_td: -5}
    printed_fails_slow = sp.N(printed.subs(slow)) < 0 < sp.N(corrected.subs(slow))
    printed_holds_fast = abs(sp.N((printed - corrected).subs(fast))) < 1e-12
    atan2_holds = all(abs(sp.N((atan2_form - corrected).subs(p))) < 1e-12 for p in (slow, fast))
    return (
        _asin_as_atan_ok(ratio, arg)
        and structure
        and symmetric
        and printed_fails_slow
        and printed_holds_fast
        and atan2_holds
    )


# --------------------------------------------------------------------------------------------
# Section 3.2: Hamiltonian (27)-(29), printed with the decompression stiffness k_d.


def check_eq27() -> bool:
    printed = (p_r**2 + p_th**2 / q_r**2) / (2 * m) + k_d / 2 * (l0 - q_r) ** 2 + m * g_s * q_r * sp.cos(q_th)
    return is_zero(printed - mechanics.hamiltonian(k_d))


def check_eq29() -> bool:
    printed = (
        p_r / m,
        p_th / (m * q_r**2),
        p_th**2 / (m * q_r**3) + k_d * (l0 - q_r) - m * g_s * sp.cos(q_th),
        m * g_s * q_r * sp.sin(q_th),
    )
    return all_zero([p - d for p, d in zip(printed, mechanics.hamiltonian_vector_field(k_d), strict=True)])


def entries() -> list[Entry]:
    return [
        Entry(
            "sec2.2.1-polar",
            "polar stance dynamics (first display of 2.2.1)",
            "corrected",
            "Printed q_thdd = -g_s sin(q_th)/q_r - 2 q_r q_thd/q_r. The Euler-Lagrange equations of (1) give "
            "q_thdd = +g_s sin(q_th)/q_r - 2 q_rd q_thd/q_r: gravity tips the leg away from the vertical "
            "(as dp_th/dt = m g_s q_r sin q_th in (29)), and the Coriolis term has q_rd, not q_r. "
            "The q_rdd row is right.",
            check_stance_polar_display,
        ),
        Entry(
            "sec2.2.1-cartesian",
            "Cartesian stance dynamics, flat ground",
            "corrected",
            "b_xdd = -F_s sin(q_th)/m, b_ydd = F_s cos(q_th)/m - g_s hold, but the display substitutes "
            "q_th = arctan(b_y/b_x), the angle from the horizontal. With the Table 1 convention "
            "q_th = atan2(-b_x, b_y) (so sin q_th = -b_x/q_r, cos q_th = b_y/q_r). OCR noise in the "
            "square roots (b_y for b_y^2) ignored.",
            check_stance_cartesian_display,
        ),
        Entry(
            "sec2.2.2",
            "ballistic flight dynamics",
            "verified",
            "From L = m/2 (b_xd^2 + b_yd^2) - m g_f b_y; the toe state b_tx is bookkeeping.",
            check_flight_display,
        ),
        Entry(
            "1",
            "stance Lagrangian",
            "verified",
            "T and V computed from the body at (-q_r sin q_th, q_r cos q_th).",
            check_eq1,
        ),
        Entry("2", "radial Euler-Lagrange equation", "verified", "", check_eq2),
        Entry(
            "3",
            "angular Euler-Lagrange equation",
            "corrected",
            "Printed 0 = d/dt(m q_r^2 q_thd) + m g_s q_r sin q_th; from (1): d/dt(m q_r^2 q_thd) = "
            "+m g_s q_r sin q_th (sign of the gravity term), consistent with (29).",
            check_eq3,
        ),
        Entry("4", "radial equation under Assumption 1", "verified", "cos q_th = 1 in (2).", check_eq4_eq5),
        Entry(
            "5",
            "angular momentum conservation under Assumption 1",
            "verified",
            "sin q_th = 0 in (3).",
            check_eq4_eq5,
        ),
        Entry(
            "6",
            "conserved energy under Assumption 1",
            "verified",
            "Energy function of (1) with cos q_th = 1; also checked to be a first integral of (4)-(5).",
            check_eq6,
        ),
        Entry("7", "dimensionless rho, epsilon, omega, omega0", "definition", "", None),
        Entry("8", "dimensionless energy", "verified", "(7) substituted into (6).", check_eq8),
        Entry(
            "sec3.1-taylor",
            "Assumption 2: 1/(1+rho)^2 ~ 1 - 2 rho + 3 rho^2",
            "verified",
            "The second-order Taylor polynomial holds (the next term is -4 rho^3).",
            check_taylor,
        ),
        Entry(
            "9",
            "quadrature and lambda, mu, nu",
            "verified",
            "Second-order expansion of (8) in rho.",
            check_eq9,
        ),
        Entry(
            "10",
            "antiderivative of (9)",
            "corrected",
            "Printed sqrt(mu^2) - 4 lambda nu in the arcsine's denominator (OCR/typesetting); the "
            "antiderivative is -1/sqrt(-lambda) asin((2 lambda rho + mu)/sqrt(mu^2 - 4 lambda nu)), "
            "checked by differentiation for lambda < 0 < mu^2 - 4 lambda nu.",
            check_eq10,
        ),
        Entry(
            "11",
            "radial solution q_r(t) = l0 (1 + a + b sin(omega0_hat t))",
            "verified",
            "Both printed forms of b; rho(t) checked to solve rho_d^2 = lambda rho^2 + mu rho + nu.",
            check_eq11,
        ),
        Entry(
            "12",
            "touchdown time",
            "verified",
            "Compressing root of sin(omega0_hat t) = (q_r_td/l0 - 1 - a)/b, up to 2 n pi.",
            check_eq12_14,
        ),
        Entry("13", "bottom time", "verified", "Minimum of rho: sin = -1.", check_eq12_14),
        Entry(
            "14", "liftoff time", "verified", "Extending root after the bottom, up to 2 n pi.", check_eq12_14
        ),
        Entry("15", "touchdown time, q_r_td = l0", "verified", "", check_eq15_16),
        Entry("16", "liftoff time, q_r_lo = l0", "verified", "", check_eq15_16),
        Entry(
            "17",
            "leg angle rate omega/(1+rho)^2",
            "verified",
            "Also its linearization omega (1 - 2 rho). The text's 'q_thd = p_th/(m q_r)' above (17) "
            "misses the square of q_r.",
            check_eq17,
        ),
        Entry("18", "leg angle integral", "verified", "", check_eq18_19),
        Entry("19", "leg angle q_th(t)", "verified", "", check_eq18_19),
        Entry("20", "stance time, q_r_td = q_r_lo = l0", "verified", "", check_eq20),
        Entry(
            "21",
            "q_r(t) with touchdown at t = 0",
            "verified",
            "Valid for q_r_td = l0 (sin(omega0_hat t_td) = -a/b) and b > 0.",
            check_eq21_22,
        ),
        Entry("22", "q_th(t) with touchdown at t = 0", "verified", "As (21).", check_eq21_22),
        Entry(
            "23",
            "q_r(t) in touchdown states",
            "corrected",
            "Printed |q_r_td| (the leg length); the amplitude is |q_rd_td|/omega0_hat "
            "(sqrt(b^2 - a^2) = |q_rd_td|/(l0 omega0_hat) at q_r_td = l0).",
            check_eq23,
        ),
        Entry(
            "24",
            "q_th(t) in touchdown states",
            "verified",
            "OCR: |q_rd_tt| read as |q_rd_td|.",
            check_eq24,
        ),
        Entry(
            "25",
            "stance time in touchdown states",
            "corrected",
            "Printed |q_r_{t+t}| lacks the dot as in (23): t_s = [pi + 2 arctan((g_s - l0 q_thd_td^2)/"
            "(|q_rd_td| omega0_hat))]/omega0_hat, valid (0 < t_s < 2 pi/omega0_hat) on the whole domain.",
            check_eq25,
        ),
        Entry(
            "26",
            "bottom time in touchdown states",
            "corrected",
            "Printed arctan(|q_rd_td| omega0_hat/(q_thd_td^2 l0 - g_s))/omega0_hat is negative when "
            "q_thd_td^2 l0 < g_s (slow gaits). Correct branch: t_b = atan2(|q_rd_td| omega0_hat, "
            "q_thd_td^2 l0 - g_s)/omega0_hat = [pi/2 + arctan((g_s - l0 q_thd_td^2)/(|q_rd_td| "
            "omega0_hat))]/omega0_hat = t_s/2, so 0 < t_b < t_s.",
            check_eq26,
        ),
        Entry(
            "27",
            "stance Hamiltonian (decompression, k_d)",
            "verified",
            "Legendre transform of (1) with k = k_d.",
            check_eq27,
        ),
        Entry("28", "Hamilton's equations", "definition", "", None),
        Entry("29", "Hamiltonian vector field", "verified", "From (27) and (28).", check_eq29),
    ]
