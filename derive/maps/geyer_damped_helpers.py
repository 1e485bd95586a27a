"""Geyer et al.'s radial solution with leg damping (report section 3.1, extended): derivation.

Not in the report: its leg is lossless, and (6)-(9) come from the energy integral, which a damper
removes. With the leg damping ``c`` (derive/params.py) the radial equation (4) gains -c q_rd
(:func:`..model.mechanics.euler_lagrange_polar` with ``damping``); the angular momentum stays
conserved (the damper exerts no torque about the toe). Under Assumption 1 (cos q_th ~ 1) and the
first-order Taylor step 1/(1+rho)^3 ~ 1 - 3 rho (the derivative of Assumption 2's polynomial), (4)
becomes a damped linear oscillator in rho = q_r / l0 - 1 (:func:`damped_radial_equation`):

    rho'' + 2 delta rho' + omega_n^2 rho = omega^2 - g_s / l0,
    delta = c / (2 m), omega_n^2 = omega0^2 + 3 omega^2,

whose solution (:func:`damped_radial_solution`, by ``dsolve``) from the touchdown state is
rho(t) = a + exp(-delta t) (A cos(omega_D t) + B sin(omega_D t)), omega_D^2 = omega_n^2 - delta^2,
with Geyer's offset a of (11). At c = 0 it is (11): the quadratic (9) is this equation's first
integral. The events (:func:`damped_events`): the bottom where rho' = 0 (tan(omega_D t_b) in closed
form); liftoff where the leg force k (l0 - q_r) - c q_rd falls to 0 (omega0^2 rho + 2 delta rho' = 0)
or where q_r = q_r_lo, both transcendental once a != 0 (a root, not a closed form). The leg angle
(:func:`damped_leg_angle`): (18)-(19)'s integral of omega (1 - 2 rho) over the damped rho, closed form.

Each function returns its (cached) result; :mod:`slipmaps.derive.equations` checks them
(``sec3.1-damped*``, extensions). Time t is measured from touchdown.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ..model import mechanics
from ..symbols import a, c, g_s, k, l0, m, omega, omega0, p_th, q_r, q_rd, q_thd, rho, rho_d, t
from .geyer import SMALL_ANGLE

__all__ = [
    "DELTA",
    "OMEGA_D",
    "OMEGA_N",
    "RHO_TD",
    "RHO_D_TD",
    "A_C",
    "B_S",
    "damped_assumption1_radial",
    "damped_radial_equation",
    "damped_radial_solution",
    "damped_events",
    "damped_leg_angle",
]

#: delta = c / (2 m), the decay rate of the damped oscillation.
DELTA = sp.Symbol("delta", nonnegative=True)
#: omega_n = sqrt(omega0^2 + 3 omega^2), the undamped frequency (Geyer's omega0_hat of (11)).
OMEGA_N = sp.Symbol("omega_n", positive=True)
#: omega_D = sqrt(omega_n^2 - delta^2), the damped frequency (an underdamped leg: delta < omega_n).
OMEGA_D = sp.Symbol("omega_D", positive=True)
#: rho and rho' at touchdown.
RHO_TD, RHO_D_TD = sp.symbols("rho_td rho_d_td", real=True)
#: The coefficients of exp(-delta t) cos(omega_D t) and exp(-delta t) sin(omega_D t).
A_C, B_S = sp.symbols("A_c B_s", real=True)

_RHO_DD = sp.Symbol("rho_dd", real=True)
_Q_RDD = sp.Symbol("q_rdd", real=True)


@cache
def damped_assumption1_radial():
    """Eq (4) with the damper: (2) with damping ``c`` and cos q_th ~ 1 (an expression equal to 0)."""
    el_r, _ = mechanics.euler_lagrange_polar(k, g_s, c)
    return sp.expand(el_r.subs(SMALL_ANGLE))


@cache
def damped_radial_equation():
    """(4) damped, dimensionless ((7): q_r = l0 (1 + rho), q_thd = omega / (1 + rho)^2, k = m omega0^2,
    c = 2 m delta) and divided by m l0, 1/(1+rho)^3 by its first-order Taylor polynomial: returns
    (omega_n^2, the constant right side), the equation being rho'' + 2 delta rho' + omega_n^2 rho = rhs."""
    sub = {
        q_thd: p_th / (m * q_r**2),
        q_rd: l0 * rho_d,
        _Q_RDD: l0 * _RHO_DD,
        k: m * omega0**2,
        c: 2 * m * DELTA,
    }
    expr = damped_assumption1_radial().subs(sub).subs({q_r: l0 * (1 + rho), p_th: m * l0**2 * omega})
    expr = sp.expand(expr / (m * l0))
    linear = sp.expand(sp.series(expr, rho, 0, 2).removeO())
    poly = sp.Poly(linear, _RHO_DD, rho_d, rho)
    assert poly.coeff_monomial(_RHO_DD) == 1 and poly.coeff_monomial(rho_d) == 2 * DELTA, linear
    return sp.expand(poly.coeff_monomial(rho)), sp.expand(-poly.coeff_monomial(1))


@cache
def damped_radial_solution():
    """rho(t) from the touchdown state (rho_td, rho_d_td) by ``dsolve`` (underdamped: omega_n^2 =
    omega_D^2 + delta^2), and its coefficients: returns (rho(t), {a, A_c, B_s}) with
    rho(t) = a + exp(-delta t) (A_c cos(omega_D t) + B_s sin(omega_D t))."""
    wn2, rhs = damped_radial_equation()
    f = sp.Function("rho")
    ode = sp.Eq(f(t).diff(t, 2) + 2 * DELTA * f(t).diff(t) + (OMEGA_D**2 + DELTA**2) * f(t), rhs)
    general = sp.dsolve(
        ode, f(t), hint="nth_linear_constant_coeff_undetermined_coefficients", simplify=False
    ).rhs
    constants = sorted(general.free_symbols - ode.free_symbols - {t}, key=str)
    ics = (sp.Eq(general.subs(t, 0), RHO_TD), sp.Eq(general.diff(t).subs(t, 0), RHO_D_TD))
    sol = general.subs(sp.solve(ics, constants, dict=True)[0])
    offset = sp.simplify(rhs / wn2)
    coeffs = {
        a: offset,
        A_C: RHO_TD - a,
        B_S: (RHO_D_TD + DELTA * (RHO_TD - a)) / OMEGA_D,
    }
    form = a + sp.exp(-DELTA * t) * (A_C * sp.cos(OMEGA_D * t) + B_S * sp.sin(OMEGA_D * t))
    # dsolve's constant is rhs / (omega_D^2 + delta^2): Geyer's a once omega_n^2 is written out.
    amplitudes = {A_C: coeffs[A_C], B_S: coeffs[B_S]}
    assert sp.simplify(sol - form.subs(amplitudes).subs(a, rhs / (OMEGA_D**2 + DELTA**2))) == 0, sol
    return sp.expand(form), coeffs


@cache
def damped_events():
    """The bottom and liftoff conditions of the damped rho(t) (time from touchdown).

    Returns ``rate`` (rho'(t)), ``t_bottom`` (the first root of rho' = 0: omega_D t_b = pi/2 + psi
    for tan(psi) = ..., the closed form), ``force`` (the leg force k (l0 - q_r) - c q_rd over m l0:
    -(omega0^2 rho + 2 delta rho')), the liftoff condition of option ``force``.
    """
    rho_t, _ = damped_radial_solution()
    rate = sp.expand(rho_t.diff(t))
    # rho' = exp(-delta t) (P cos(omega_D t) + R sin(omega_D t)), P = rho_d_td < 0 (compressing):
    # zero where tan(omega_D t) = -P / R, first at omega_D t_b = pi/2 + atan(R / P) in (0, pi).
    scaled = sp.expand(sp.simplify(rate * sp.exp(DELTA * t)))
    cos_coef = sp.simplify(scaled.coeff(sp.cos(OMEGA_D * t)))
    sin_coef = sp.simplify(scaled.coeff(sp.sin(OMEGA_D * t)))
    assert sp.simplify(scaled - cos_coef * sp.cos(OMEGA_D * t) - sin_coef * sp.sin(OMEGA_D * t)) == 0
    t_bottom = (sp.pi / 2 + sp.atan(sin_coef / cos_coef)) / OMEGA_D
    force = -(omega0**2 * rho_t + 2 * DELTA * rate)
    return {"rate": rate, "cos": cos_coef, "sin": sin_coef, "t_bottom": t_bottom, "force": sp.expand(force)}


@cache
def damped_leg_angle():
    """(18)-(19) with the damped rho: q_th(t) - q_th_td = int_0^t omega (1 - 2 rho(tau)) dtau, the
    angular momentum conserved (no torque about the toe), 1/(1+rho)^2 ~ 1 - 2 rho."""
    tau = sp.Symbol("tau", real=True)
    rho_t, _ = damped_radial_solution()
    integrand = omega * (1 - 2 * rho_t.subs(t, tau))
    return sp.simplify(sp.integrate(sp.expand(integrand), (tau, 0, t)))
