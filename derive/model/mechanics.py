"""The SLIP model from first principles (report sections 2.2 and 3.1, eqs 1-3, 27-29).

The leg damping ``c`` (not in the report) enters as a Rayleigh dissipation function
R = c q_rd^2 / 2 (:func:`dissipation`): the Euler-Lagrange equations gain dR/dq_rd on the radial
row, the generalized force -c q_rd along the leg (no torque about the toe). Every function takes it
as ``damping`` (default 0, the report's lossless leg, whose expressions are unchanged).

Everything here is derived, not typed: the Lagrangian (1) is built from the Cartesian kinetic
and potential energies of the body at (-q_r sin q_th, q_r cos q_th); its Euler-Lagrange
equations give (2)-(3); the Legendre transform gives the Hamiltonian (27) and Hamilton's
equations (28) its vector field (29). The Cartesian stance dynamics and the ballistic flight of
section 2.2 come from the same energies written in Cartesian coordinates. Results are cached:
each function returns the same SymPy objects on every call.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from ..symbols import (
    b_x,
    b_x_t,
    b_xd,
    b_y,
    b_y_t,
    b_yd,
    c,
    g_f,
    g_s,
    k,
    l0,
    m,
    p_r,
    p_th,
    q_r,
    q_r_t,
    q_rd,
    q_th,
    q_th_t,
    q_thd,
    t,
)

__all__ = [
    "body_position",
    "lagrangian_polar",
    "dissipation",
    "euler_lagrange_polar",
    "stance_polar_rhs",
    "stance_polar_damping",
    "hamiltonian",
    "hamiltonian_vector_field",
    "stance_energy",
    "stance_cartesian_rhs",
    "flight_rhs",
    "polar_to_cartesian",
    "cartesian_to_polar",
    "ballistic_flight",
]


def body_position(r, th):
    """Body position relative to the toe (Table 1 convention): (-r sin th, r cos th)."""
    return sp.Matrix([-r * sp.sin(th), r * sp.cos(th)])


def _functions_to_symbols(expr):
    """Replace q_r(t), q_th(t) and their derivatives by the plain state symbols."""
    d2 = {q_r_t.diff(t, 2): sp.Symbol("q_rdd", real=True), q_th_t.diff(t, 2): sp.Symbol("q_thdd", real=True)}
    d1 = {q_r_t.diff(t): q_rd, q_th_t.diff(t): q_thd}
    d0 = {q_r_t: q_r, q_th_t: q_th}
    return sp.sympify(expr).subs(d2).subs(d1).subs(d0)


@cache
def lagrangian_polar(stiffness=k, gravity=g_s):
    """Eq (1): L = T - V, with T and V computed from the Cartesian body position.

    Returned in plain state symbols (q_r, q_rd, q_th, q_thd).
    """
    pos = body_position(q_r_t, q_th_t)
    vel = pos.diff(t)
    kinetic = sp.Rational(1, 2) * m * (vel.T * vel)[0, 0]
    potential = sp.Rational(1, 2) * stiffness * (l0 - q_r_t) ** 2 + m * gravity * pos[1]
    return sp.simplify(_functions_to_symbols(kinetic - potential))


@cache
def dissipation(damping=0):
    """The Rayleigh dissipation function of the leg damper, R = damping q_rd^2 / 2 (in q_r(t)): the
    power it takes from the body is 2 R = damping q_rd^2."""
    return sp.Rational(1, 2) * damping * q_r_t.diff(t) ** 2


@cache
def euler_lagrange_polar(stiffness=k, gravity=g_s, damping=0):
    """Eqs (2)-(3): d/dt(dL/dqdot_j) - dL/dq_j + dR/dqdot_j for j = r, theta (expressions equal to
    zero), R the leg damper's :func:`dissipation` (none at ``damping`` 0: the report's equations)."""
    pos = body_position(q_r_t, q_th_t)
    vel = pos.diff(t)
    lag = sp.Rational(1, 2) * m * (vel.T * vel)[0, 0] - (
        sp.Rational(1, 2) * stiffness * (l0 - q_r_t) ** 2 + m * gravity * pos[1]
    )
    rayleigh = dissipation(damping)
    eqs = []
    for coord in (q_r_t, q_th_t):
        el = sp.diff(lag.diff(coord.diff(t)), t) - lag.diff(coord)
        if damping != 0:
            el = el + rayleigh.diff(coord.diff(t))
        eqs.append(sp.expand(sp.simplify(_functions_to_symbols(el))))
    return tuple(eqs)


@cache
def stance_polar_rhs(stiffness=k, gravity=g_s, damping=0):
    """First-order polar stance dynamics (q_rd, q_rdd, q_thd, q_thdd), solved from (2)-(3).

    This is the corrected form of the report's first stance-dynamics display (section 2.2.1); with
    ``damping`` the leg's radial force is -stiffness (q_r - l0) - damping q_rd.
    """
    q_rdd, q_thdd = sp.symbols("q_rdd q_thdd", real=True)
    el_r, el_th = euler_lagrange_polar(stiffness, gravity, damping)
    sol = sp.solve([el_r, el_th], [q_rdd, q_thdd], dict=True)[0]
    return (q_rd, sp.expand(sol[q_rdd]), q_thd, sp.expand(sol[q_thdd]))


@cache
def stance_polar_damping(damping=c):
    """What the leg damper adds to the polar stance field: :func:`stance_polar_rhs` with ``damping``
    minus without, simplified (the damped field is the lossless one plus this term, so a damping of
    0 leaves the lossless field's arithmetic as it is)."""
    damped = stance_polar_rhs(k, g_s, damping)
    lossless = stance_polar_rhs(k, g_s)
    return tuple(sp.simplify(d - u) for d, u in zip(damped, lossless, strict=True))


@cache
def hamiltonian(stiffness=k, gravity=g_s):
    """Eq (27): H(q_r, q_th, p_r, p_th) by the Legendre transform of (1)."""
    lag = lagrangian_polar(stiffness, gravity)
    mom_r = lag.diff(q_rd)
    mom_th = lag.diff(q_thd)
    vel = sp.solve([sp.Eq(p_r, mom_r), sp.Eq(p_th, mom_th)], [q_rd, q_thd], dict=True)[0]
    ham = (p_r * q_rd + p_th * q_thd - lag).subs(vel)
    return sp.simplify(ham)


@cache
def hamiltonian_vector_field(stiffness=k, gravity=g_s):
    """Eqs (28)-(29): (dq_r/dt, dq_th/dt, dp_r/dt, dp_th/dt) = (dH/dp_r, dH/dp_th, -dH/dq_r, -dH/dq_th)."""
    ham = hamiltonian(stiffness, gravity)
    return tuple(sp.simplify(e) for e in (ham.diff(p_r), ham.diff(p_th), -ham.diff(q_r), -ham.diff(q_th)))


@cache
def stance_energy(stiffness=k, gravity=g_s):
    """Total stance energy in the polar state: H of (27) with p_r = m q_rd, p_th = m q_r^2 q_thd."""
    ham = hamiltonian(stiffness, gravity)
    lag = lagrangian_polar(stiffness, gravity)
    return sp.expand(ham.subs({p_r: lag.diff(q_rd), p_th: lag.diff(q_thd)}))


@cache
def stance_cartesian_rhs(stiffness=k, gravity=g_s):
    """Cartesian stance dynamics (section 2.2.1, flat ground, toe at the origin).

    Derived from the Lagrangian in Cartesian coordinates with leg length sqrt(b_x^2 + b_y^2);
    returns (b_xd, b_xdd, b_yd, b_ydd).
    """
    radius = sp.sqrt(b_x_t**2 + b_y_t**2)
    lag = sp.Rational(1, 2) * m * (b_x_t.diff(t) ** 2 + b_y_t.diff(t) ** 2) - (
        sp.Rational(1, 2) * stiffness * (l0 - radius) ** 2 + m * gravity * b_y_t
    )
    accel = []
    for coord in (b_x_t, b_y_t):
        el = sp.diff(lag.diff(coord.diff(t)), t) - lag.diff(coord)
        acc = sp.solve(el, coord.diff(t, 2))[0]
        accel.append(acc)
    subs2 = {b_x_t.diff(t): b_xd, b_y_t.diff(t): b_yd}
    subs0 = {b_x_t: b_x, b_y_t: b_y}
    ax, ay = (sp.simplify(a.subs(subs2).subs(subs0)) for a in accel)
    return (b_xd, ax, b_yd, ay)


@cache
def flight_rhs(gravity=g_f):
    """Ballistic flight dynamics (section 2.2.2): (b_xd, 0, b_yd, -g_f), from L = T - m g_f b_y."""
    lag = sp.Rational(1, 2) * m * (b_x_t.diff(t) ** 2 + b_y_t.diff(t) ** 2) - m * gravity * b_y_t
    accel = [sp.solve(sp.diff(lag.diff(c.diff(t)), t) - lag.diff(c), c.diff(t, 2))[0] for c in (b_x_t, b_y_t)]
    return (b_xd, sp.simplify(accel[0]), b_yd, sp.simplify(accel[1]))


@cache
def polar_to_cartesian():
    """(q_r, q_rd, q_th, q_thd) -> (b_x, b_xd, b_y, b_yd), by differentiating the body position."""
    pos = body_position(q_r_t, q_th_t)
    vel = pos.diff(t)
    out = (pos[0], vel[0], pos[1], vel[1])
    return tuple(_functions_to_symbols(e) for e in out)


@cache
def cartesian_to_polar():
    """(b_x, b_xd, b_y, b_yd) -> (q_r, q_rd, q_th, q_thd), the inverse of :func:`polar_to_cartesian`.

    The rates are solved from the linear velocity map; the angle uses atan2(-b_x, b_y), which
    lies in (-pi, pi) and equals q_th for a body above the ground.
    """
    x_, xd_, y_, yd_ = polar_to_cartesian()
    rates = sp.solve([sp.Eq(b_xd, xd_), sp.Eq(b_yd, yd_)], [q_rd, q_thd], dict=True)[0]
    radius = sp.sqrt(b_x**2 + b_y**2)
    # On the image of the map: r = radius, sin(th) = -b_x/r, cos(th) = b_y/r.
    on_image = {sp.sin(q_th): -b_x / radius, sp.cos(q_th): b_y / radius, q_r: radius}
    q_rd_expr = sp.simplify(rates[q_rd].subs(on_image))
    q_thd_expr = sp.simplify(rates[q_thd].subs(on_image))
    return (radius, q_rd_expr, sp.atan2(-b_x, b_y), q_thd_expr)


@cache
def ballistic_flight():
    """Closed-form flight (section 2.2.2) solved by dsolve: (b_x(t), b_xd(t), b_y(t), b_yd(t)).

    Initial state symbols: (b_x, b_xd, b_y, b_yd) at t = 0.
    """
    bx_f, by_f = sp.Function("bx"), sp.Function("by")
    _, ax, _, ay = flight_rhs()
    sols = sp.dsolve(
        [sp.Eq(bx_f(t).diff(t, 2), ax), sp.Eq(by_f(t).diff(t, 2), ay)],
        [bx_f(t), by_f(t)],
        ics={
            bx_f(0): b_x,
            by_f(0): b_y,
            bx_f(t).diff(t).subs(t, 0): b_xd,
            by_f(t).diff(t).subs(t, 0): b_yd,
        },
    )
    xs = {s.lhs: s.rhs for s in sols}
    x_t, y_t = sp.expand(xs[bx_f(t)]), sp.expand(xs[by_f(t)])
    return (x_t, x_t.diff(t), y_t, y_t.diff(t))
