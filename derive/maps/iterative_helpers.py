"""Helpers of the iterative maps: Schwind and Koditschek's iterative stance map (report sections 3.2
and 5.2), derived step by step. This module declares no map: the maps ``iterative`` (:mod:`.iterative`)
and ``iterative-report`` (:mod:`.iterative_report`) and the equation checks of sections 3.2 and 5.2
(derive/equations/) build on it.

From the Hamiltonian vector field (29) with the decompression stiffness k_d: the leg length q_r is
the independent variable of the decompression phase (p_r > 0), so each rate is divided by
dq_r/dt = p_r/m, giving (30)-(32); energy conservation H = E of (27) gives p_r = H^{-1} (33).
Integrating (30)-(32) from the bottom (q_r = q_r_b, p_r = 0) needs the mean-value approximation of
Theorem 1 (34)-(37): near the bottom p_r vanishes like (sigma - q_r_b)^(1/2), which fixes the
mean-value point (41); evaluating the integrands there gives the iteration (42)-(45).

Section 5.2 applies the same steps to each half of a stance with variable stiffness: the
compression half (stiffness k_c, energy E_ab, p_r = -H^{-1} < 0, integrated from touchdown, eqs
114-136) and the decompression half (k_d, E_ba, from the bottom, eqs 137-151). The helpers take the
stiffness, the energy, the sign of p_r and the starting state (:data:`BOTTOM`, :data:`TOUCHDOWN`).
Section 5.2 also uses a second mean-value variant ("weighted", (128)-(136), (144)-(151)): f = 1/H^{-1}
goes to the mean-value point together with the factors that depend on the state (p_th, sin q_th),
and the weight g(sigma) (1, 1/sigma^2 or sigma) is integrated exactly.

Near the bottom the integrands are singular, near touchdown they are regular
(:func:`integrand_exponents` with ``end``); Theorem 1 gives the fraction 1/4 at the first and 1/2 at
the second. A compression-half integral from touchdown is therefore written as the difference of two
integrals anchored at the bottom (:func:`compression_step`).

The report's H^{-1}(q_r, q_th, p_th, E) appears in (42)-(44) as the unevaluated function
:data:`H_INV`, the iterates q_th_n, p_th_n as undefined functions; :func:`radial_momentum` is its
closed form. Results are cached.

Both iterative maps start from a zeroth iterate (option ``zeroth``, :func:`zeroth_option`): the
bottom and liftoff states of any map not itself iterated from one (:func:`zeroth_maps`, derived
from the declarations), or the held touchdown / bottom state (:data:`HELD`); :func:`zeroth_bottom`,
:func:`zeroth_liftoff` and :func:`held_liftoff` compute them in a map's steps.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .. import catalog
from ..ir import Arg, Call, Field, Group, Kernel, Stage, Switch, sym
from ..mapspec import MapSpec, Option
from ..model import mechanics
from ..symbols import E, c, k_c, k_d, l0, m, p_r, p_th, q_r, q_r_td, q_rd, q_th, q_th_td, t

__all__ = [
    "sigma",
    "delta",
    "q_r_b",
    "q_th_b",
    "p_th_b",
    "t_b",
    "E_ab",
    "E_ba",
    "t_td",
    "p_th_td",
    "p_r_td",
    "BOTTOM",
    "TOUCHDOWN",
    "H_INV",
    "Q_TH_N",
    "P_TH_N",
    "Q_TH_NEXT",
    "P_TH_NEXT",
    "leg_length_derivatives",
    "radial_momentum",
    "bottom_energy",
    "touchdown_energy",
    "near_bottom",
    "near_touchdown",
    "taylor_from_bottom",
    "theorem1_fraction",
    "integrand_exponents",
    "mean_value_fractions",
    "mean_value_point",
    "weight_split",
    "iteration_step",
    "compression_step",
    "next_radial_momentum",
    "radial_force",
    "damper_force",
    "force_liftoff",
    "liftoff_symbols",
    "HELD",
    "zeroth_maps",
    "zeroth_option",
    "zeroth_bottom",
    "held_kernel",
    "zeroth_kernel",
    "held_liftoff",
    "zeroth_arguments",
    "zeroth_values",
    "zeroth_liftoff",
    "ZEROTH_OUTPUTS",
]

sigma = sp.Symbol("sigma", positive=True)  # leg length as the integration variable
delta = sp.Symbol("delta", positive=True)  # distance from an end: sigma - q_r_b, or q_r_td - sigma
q_r_b = sp.Symbol("q_r_b", positive=True)  # bottom state: leg length, angle, angular momentum, time
q_th_b, p_th_b, t_b = sp.symbols("q_th_b p_th_b t_b", real=True)
E_ab, E_ba = sp.symbols("E_ab E_ba", real=True)  # energies of the compression and decompression halves
t_td, p_th_td = sp.symbols("t_td p_th_td", real=True)  # touchdown time and angular momentum
p_r_td = sp.Symbol("p_r_td", negative=True)  # touchdown radial momentum (compression: p_r < 0)
BOTTOM = (q_r_b, t_b, q_th_b, p_th_b)  # (q_r, t, q_th, p_th) where an integration starts
TOUCHDOWN = (q_r_td, t_td, q_th_td, p_th_td)

H_INV = sp.Function("H_inv")  # H^{-1}(q_r, q_th, p_th, E) of (33), unevaluated
Q_TH_N, P_TH_N = sp.Function("q_th_n", real=True), sp.Function("p_th_n", real=True)  # n-th iterate
Q_TH_NEXT, P_TH_NEXT = sp.Function("q_th_n1", real=True), sp.Function("p_th_n1", real=True)  # (n+1)-th


@cache
def leg_length_derivatives(stiffness=k_d):
    """Eqs (30)-(32): (dt/dq_r, dq_th/dq_r, dp_th/dq_r), the rates of (29) divided by dq_r/dt = p_r/m."""
    dq_r, dq_th, _, dp_th = mechanics.hamiltonian_vector_field(stiffness)
    return tuple(sp.simplify(rate / dq_r) for rate in (sp.Integer(1), dq_th, dp_th))


@cache
def radial_momentum(stiffness=k_d, energy=E, sign=1):
    """Eq (33) (sign +1) and (119) (sign -1): p_r = sign H^{-1}(q_r, q_th, p_th, energy), H of (27) = energy.

    H is p_r^2/(2 m) plus terms free of p_r, so H^{-1} = sqrt(2 m (energy - H|_{p_r = 0})).
    """
    hamiltonian = mechanics.hamiltonian(stiffness)
    rest = hamiltonian.subs(p_r, 0)
    if sp.expand(hamiltonian - rest - p_r**2 / (2 * m)) != 0:
        raise RuntimeError(f"H is not p_r^2/(2 m) plus terms free of p_r: {hamiltonian}")
    numerator, denominator = sp.fraction(sp.together(2 * m * (energy - rest)))  # denominator q_r^2
    return sign * sp.sqrt(sp.expand(numerator)) / sp.sqrt(denominator)


@cache
def bottom_energy(stiffness=k_d):
    """E of a bottom state: H of (27) at q_r = q_r_b, q_th = q_th_b, p_th = p_th_b and p_r = 0."""
    at_bottom = {q_r: q_r_b, q_th: q_th_b, p_th: p_th_b, p_r: 0}
    return sp.expand(mechanics.hamiltonian(stiffness).subs(at_bottom))


@cache
def touchdown_energy(stiffness=k_c):
    """E of a touchdown state: H of (27) at q_r_td, q_th_td, p_th_td and p_r = p_r_td < 0."""
    at_touchdown = {q_r: q_r_td, q_th: q_th_td, p_th: p_th_td, p_r: p_r_td}
    return sp.expand(mechanics.hamiltonian(stiffness).subs(at_touchdown))


def near_touchdown(expr, stiffness=k_c):
    """``expr`` at sigma = q_r_td - delta (delta > 0 into the compression), on a touchdown energy level.

    As :func:`near_bottom`, with H^{-1} at the touchdown angle and angular momentum; H^{-1} = |p_r_td|
    at delta = 0.
    """
    expr = sp.sympify(expr).subs(p_r, radial_momentum(stiffness))
    at = {q_r: q_r_td - delta, q_th: q_th_td, p_th: p_th_td, E: touchdown_energy(stiffness)}
    return expr.subs(at, simultaneous=True)


def near_bottom(expr, stiffness=k_d):
    """``expr`` (in q_r, q_th, p_th, p_r, E) at sigma = q_r_b + delta on the energy level of a bottom state.

    p_r becomes H^{-1}(q_r_b + delta, q_th_b, p_th_b, E_b): the angle and angular momentum are held at
    their bottom values, as in the integrands of (38)-(40), where H^{-1}(sigma, q_th, p_th, E) is
    integrated over sigma alone. Along the actual trajectory they vary too, but p_r^2 has the same
    leading term 2 m (dp_r/dt)_b delta either way (see :func:`taylor_from_bottom`).
    """
    expr = sp.sympify(expr).subs(p_r, radial_momentum(stiffness))
    at = {q_r: q_r_b + delta, q_th: q_th_b, p_th: p_th_b, E: bottom_energy(stiffness)}
    return expr.subs(at, simultaneous=True)


def taylor_from_bottom(expr, order, stiffness=k_d):
    """Taylor polynomial in t, to t^order, of ``expr`` along the flow of (29) from the bottom state at t = 0.

    The bottom state is (q_r_b, q_th_b, p_r = 0, p_th_b); the n-th coefficient is the n-th Lie
    derivative of ``expr`` along the vector field (29) there, divided by n!.
    """
    field = mechanics.hamiltonian_vector_field(stiffness)
    state = (q_r, q_th, p_r, p_th)
    at_bottom = {q_r: q_r_b, q_th: q_th_b, p_r: 0, p_th: p_th_b}
    term, total = sp.sympify(expr), sp.S.Zero
    for n in range(order + 1):
        total += term.subs(at_bottom) * t**n / sp.factorial(n)
        term = sum(term.diff(x) * rate for x, rate in zip(state, field, strict=True))
    return sp.expand(total)


def theorem1_fraction(r, s):
    """Eq (35)'s limit of (xi_x - a)/(x - a): ((s + 1)/(r + s + 1))^(1/r), under Theorem 1's conditions.

    ``r`` and ``s`` are the exponents of f(t) - K ~ (t - a)^r and g(t) ~ (t - a)^s at t -> a.
    """
    r, s = sp.nsimplify(r), sp.nsimplify(s)
    if r == 0 or not s > -1 or not r + s > -1:
        raise ValueError(f"Theorem 1 needs r != 0, s > -1, r + s > -1; got r = {r}, s = {s}")
    return ((s + 1) / (r + s + 1)) ** (1 / r)


_INTEGRANDS = {"p_r": p_r, "38": 1 / p_r, "39": 1 / (q_r**2 * p_r), "40": q_r / p_r}


@cache
def integrand_exponents(stiffness=k_d, end="bottom"):
    """Exponents e of the leading terms c delta^e at an end of the stance half (delta -> 0).

    ``end="bottom"`` (delta = sigma - q_r_b): keys ``"p_r"`` for H^{-1} itself; ``"38"``, ``"39"``,
    ``"40"`` for the integrands 1/H^{-1}, 1/(sigma^2 H^{-1}), sigma/H^{-1}; ``"q_th"`` and ``"p_th"``
    for q_th(sigma) - q_th_b and p_th(sigma) - p_th_b, the integrals of (31) and (32) from the bottom
    (generic bottom: p_th_b != 0, sin q_th_b != 0).

    ``end="touchdown"`` (delta = q_r_td - sigma): the same keys, for F(sigma) - F(q_r_td), the
    increments that Theorem 1 takes as f - K; H^{-1} is finite there, so they are regular.
    """
    if end == "bottom":
        exponents = {key: near_bottom(f, stiffness).leadterm(delta)[1] for key, f in _INTEGRANDS.items()}
        _, dq_th, dp_th = leg_length_derivatives(stiffness)
        for key, rate in (("q_th", dq_th), ("p_th", dp_th)):
            coeff, power = near_bottom(rate, stiffness).leadterm(delta)
            integral = sp.integrate(coeff * sigma**power, (sigma, 0, delta))  # leading term of the increment
            exponents[key] = integral.leadterm(delta)[1]
        return exponents
    if end == "touchdown":
        exponents = {}
        for key, f in _INTEGRANDS.items():
            near = near_touchdown(f, stiffness)  # analytic at delta = 0: the first nonzero Taylor term
            exponents[key] = next(
                n for n in range(1, 4) if sp.factor(near.diff(delta, n).subs(delta, 0)) != 0
            )
        return exponents
    raise ValueError(f"end must be 'bottom' or 'touchdown', got {end!r}")


@cache
def mean_value_fractions(stiffness=k_d, end="bottom", weighted=False):
    """(xi - a)/(x - a) from (35) for each of the integrals (38)-(40), a the ``end`` (q_r_b or q_r_td).

    As printed, (38)-(40) are (37) with f the whole integrand (r = its exponent, -1/2 at the bottom)
    and g = 1 (s = 0): the right sides are f(xi) times int_a^x dsigma = x - a. ``weighted`` is the
    variant of (128)/(144): f = 1/H^{-1} for all three, g = 1, 1/sigma^2, sigma (each with s = 0,
    computed).
    """
    exponents = integrand_exponents(stiffness, end)
    anchor = q_r_b if end == "bottom" else q_r_td
    fractions = {}
    weights = [weight_split(rate)[1] for rate in leg_length_derivatives(stiffness)]
    for key, weight in zip(("38", "39", "40"), weights, strict=True):
        if weighted:
            s = weight.subs(q_r, anchor + delta).leadterm(delta)[1]
            fractions[key] = theorem1_fraction(exponents["38"], s)
        else:
            fractions[key] = theorem1_fraction(exponents[key], 0)
    return fractions


@cache
def mean_value_point(stiffness=k_d, end=q_r):
    """Eq (41): xi = q_r_b + F (end - q_r_b), F the fraction of (35) at the bottom for the integral (38).

    ``end = q_r`` gives (41), the point of int_{q_r_b}^{q_r}; ``end = q_r_td`` the point of the whole
    compression half.
    """
    return sp.expand(q_r_b + mean_value_fractions(stiffness)["38"] * (end - q_r_b))


def weight_split(rate):
    """A rate of (30)-(32) as (state part, weight g(q_r)) with rate = state part / p_r * g(q_r).

    g collects the factors of rate * p_r that depend on q_r alone (1, 1/q_r^2, q_r); the state part
    the rest (constants and factors in q_th, p_th), which goes to the mean-value point with 1/p_r.
    """
    state, weight = sp.S.One, sp.S.One
    for factor in sp.Mul.make_args(sp.factor(rate * p_r)):
        if factor.free_symbols & {q_th, p_th, p_r} or q_r not in factor.free_symbols:
            state *= factor
        else:
            weight *= factor
    return state, weight


@cache
def iteration_step(stiffness=k_d, xi=None, sign=1, start=BOTTOM, energy=E, weighted=False):
    """Eqs (42)-(44): the (n+1)-th iterate (t, q_th, p_th as functions of q_r) from the n-th.

    Each of (30)-(32) is integrated from ``start`` = (q_r_0, t_0, q_th_0, p_th_0) (default the bottom),
    x(q_r) = x_0 + int_{q_r_0}^{q_r} F(sigma) dsigma, with the integrand F evaluated on the n-th
    iterate (q_th = q_th_n(sigma), p_th = p_th_n(sigma), p_r = sign H^{-1}(sigma, q_th_n(sigma),
    p_th_n(sigma), energy)) and the integral replaced by (37): F(xi) int_{q_r_0}^{q_r} dsigma, xi of
    (41) unless given. ``weighted``: the variant of (128)-(136)/(144)-(151), F = [state part / p_r](xi)
    g(sigma) with int g dsigma exact (:func:`weight_split`). ``sign = -1``, ``start = TOUCHDOWN``,
    ``energy = E_ab``: the compression half (124)-(126), (133)-(135).
    """
    xi = mean_value_point(stiffness) if xi is None else xi
    on_iterate = {q_r: xi, q_th: Q_TH_N(xi), p_th: P_TH_N(xi)}
    on_iterate[p_r] = sign * H_INV(xi, Q_TH_N(xi), P_TH_N(xi), energy)
    q_r_0, *values_0 = start
    steps = []
    for x_0, rate in zip(values_0, leg_length_derivatives(stiffness), strict=True):
        if weighted:
            state, weight = weight_split(rate)
            at_xi = (state / p_r).subs(on_iterate, simultaneous=True)
            steps.append(x_0 + at_xi * sp.integrate(weight.subs(q_r, sigma), (sigma, q_r_0, q_r)))
        else:
            length = sp.integrate(sp.Integer(1), (sigma, q_r_0, q_r))
            steps.append(x_0 + rate.subs(on_iterate, simultaneous=True) * length)
    return tuple(steps)


@cache
def compression_step(stiffness=k_c, energy=E_ab, weighted=False):
    """Corrected (124)-(126) (``weighted``: (133)-(135)): the compression iterate anchored at the bottom.

    The integrals from touchdown are singular at the bottom, where Theorem 1 fixes the point, not at
    touchdown; so int_{q_r_td}^{q_r} F = int_{q_r_b}^{q_r} F - int_{q_r_b}^{q_r_td} F, each by (37)
    at the point (41) of its own upper limit: x(q_r) = x_td + D(q_r) - D(q_r_td), D(x) =
    F(xi(x)) (x - q_r_b), xi(x) = 3/4 q_r_b + 1/4 x, F on the n-th iterate with p_r = -H^{-1}.
    """
    from_bottom = iteration_step(
        stiffness, mean_value_point(stiffness), -1, (q_r_b, 0, 0, 0), energy, weighted
    )
    return tuple(x_td + d - d.subs(q_r, q_r_td) for x_td, d in zip(TOUCHDOWN[1:], from_bottom, strict=True))


@cache
def next_radial_momentum(stiffness=k_d, energy=E, sign=1):
    """Eq (45), corrected: p_r of the (n+1)-th iterate at q_r, i.e. (33) on that iterate.

    p_r_(n+1)(q_r) = sign H^{-1}(q_r, q_th_(n+1)(q_r), p_th_(n+1)(q_r), energy); sign -1 and E_ab for
    the compression half, (127) and (136).
    """
    on_iterate = {q_th: Q_TH_NEXT(q_r), p_th: P_TH_NEXT(q_r)}
    return radial_momentum(stiffness, energy, sign).subs(on_iterate, simultaneous=True)


# ----------------------------------------------------------------------------------------------
# The zeroth iterate of both iterative maps
# ----------------------------------------------------------------------------------------------
@cache
def radial_force(stiffness: sp.Symbol) -> sp.Basic:
    """F_r = dp_r/dt of (29) with the half's stiffness: p_th^2/(m q_r^3) + k (l0 - q_r) - m g_s cos q_th."""
    return mechanics.hamiltonian_vector_field(stiffness)[2]


@cache
def damper_force(damping=c) -> sp.Basic:
    """The leg damper's radial force in the momenta, the term it adds to F_r = dp_r/dt: m times its
    term of the polar field (:func:`~..model.mechanics.stance_polar_damping`) with q_rd = p_r/m,
    i.e. -damping p_r/m (outward, > 0, while the leg compresses)."""
    term = mechanics.stance_polar_damping(damping)[1]
    return sp.simplify(m * term.subs(q_rd, p_r / m))


def liftoff_symbols() -> tuple[sp.Symbol, sp.Symbol]:
    """``s`` and ``W`` of :func:`force_liftoff`."""
    return sp.Symbol("s", positive=True), sp.Symbol("W", positive=True)


@cache
def force_liftoff(stiffness=k_d, damping=c) -> tuple[sp.Basic, sp.Basic]:
    """Where the leg force k (l0 - q_r) + (damper's force) of a decompression half falls to 0, in the
    half's variables: ``(leg force, s)`` with q_r = q_r_b + s^2 (s = sqrt(D), D the distance from the
    bottom) and p_r = s sqrt(4 m W) (the work form at the end, W = int_0^1 F_r u du), in the symbols
    ``q_r_b``, ``W`` and ``s`` (:func:`liftoff_symbols`); the root is the positive root of the quadratic
    in s (below l0), written without the cancellation of -b + sqrt(b^2 + ...) (checked against
    ``solve``)."""
    s_, w_ = liftoff_symbols()
    leg = stiffness * (l0 - q_r) + damper_force(damping)
    force = leg.subs({q_r: q_r_b + s_**2, p_r: s_ * sp.sqrt(4 * m * w_)})
    a2, a1, a0 = sp.Poly(sp.expand(force), s_).all_coeffs()
    root = 2 * a0 / (-a1 + sp.sqrt(a1**2 - 4 * a2 * a0))  # the root of a2 < 0 < a0 that is > 0
    # the other root of solve's two is negative (their product a0/a2 < 0 below l0)
    if not any(sp.simplify(sp.radsimp(r - root)) == 0 for r in sp.solve(force, s_)):
        raise RuntimeError(f"force liftoff: {root} is not a root of {force}")
    return force, root


#: The zeroth-iterate choice that holds the touchdown (compression) or bottom (decompression) state.
HELD = "held"
#: The default zeroth iterate: Geyer et al.'s map (report section 3.1).
_DEFAULT = "geyer"
_POLAR_NAMES = tuple(f.name for f in catalog.POLAR)


def zeroth_maps() -> tuple[MapSpec, ...]:
    """The maps a zeroth iterate can come from: every declared map that is not itself iterated from
    a zeroth iterate (:func:`~slipmaps.derive.maps.starting_maps`) and models no leg damping (the
    iteration adds the damper to a lossless guess), in report order."""
    from . import starting_maps

    return tuple(s for s in starting_maps() if "c" not in s.params)


@cache
def zeroth_option() -> Option:
    """Option ``zeroth`` of the iterative maps and their compression halves: Geyer et al.'s map (the
    default), the held state, then every other map of :func:`zeroth_maps` (a choice's code is its
    index)."""
    return Option(
        "zeroth",
        "zeroth iterate: a map's bottom and liftoff states (at its default options, with k_c), linear "
        "in u between the half's ends",
        _DEFAULT,
        (
            (_DEFAULT, "Geyer et al.'s map (section 3.1) with k_c"),
            (
                HELD,
                "the touchdown state held (q_th, p_th constant), bottom from the radial work at touchdown",
            ),
            *(
                (s.name, f"{s.title} (section {s.section}) with k_c" + (", k_d" if "k_d" in s.params else ""))
                for s in zeroth_maps()
                if s.name != _DEFAULT
            ),
        ),
        roles=("accuracy-variants",),
        # each choice calls another map's stance: kernels per choice, so that a first call compiles one
        specialize=True,
    )


#: What a zeroth iterate gives the iteration: its bottom's leg length, angle and angle rate, its
#: liftoff's angle and angle rate.
ZEROTH_OUTPUTS = ("z_b_q_r", "z_b_q_th", "z_b_q_thd", "z_lo_q_th", "z_lo_q_thd")


#: What every zeroth iterate's kernel is besides its name and steps: its outputs, and
#: - ``dense_tangent``: its callers read all of its derivatives, so that the iterative maps' kernels of
#:   two choices differ in this callee only and share one body (derive/share.py);
#: - ``inline``: inlined into its callers, as a map's stance was before it had a kernel of its own (a
#:   compiled layer of its own cost a first call about 1 s: numba optimises its code again in each
#:   caller's module).
_ZEROTH_KERNEL = dict(
    outputs=Group("", tuple(Field(n, f"zeroth iterate: {n}") for n in ZEROTH_OUTPUTS)),
    module="iterative",
    check_inputs=False,
    check_outputs=False,
    dense_tangent=True,
    inline=True,
)


@cache
def held_kernel() -> Kernel:
    """The held touchdown state as a zeroth iterate, a kernel (so that every choice of ``zeroth`` is a
    call, and the iteration's kernels are one for all of them): the bottom from p_r_td^2 = 2 m F_r(td)
    D + k_c D^2, the touchdown angle and angular momentum held; the liftoff is the held bottom's,
    taken after the compression half (:func:`zeroth_liftoff`, flag ``held``)."""
    from ..catalog import TOUCHDOWN

    q_r_td, q_rd_td, q_th_td, q_thd_td = (a.symbol for a in TOUCHDOWN)
    p_td = m * q_r_td**2 * q_thd_td
    b = radial_force(k_c).subs({q_r: q_r_td, q_th: q_th_td, p_th: p_td})
    c = (m * q_rd_td) ** 2 / (2 * m)
    z_b = sym("z_b_q_r")
    return Kernel(
        name="zeroth_held",
        summary="The zeroth iterate 'held': the touchdown state held, the bottom from the radial work.",
        equations=(),
        args=_zeroth_args(),
        steps=(
            Stage(
                (
                    (z_b, q_r_td - 2 * c / (b + sp.sqrt(b**2 + 2 * k_c * c))),
                    (sym("z_b_q_th"), q_th_td),
                    (sym("z_b_q_thd"), p_td / (m * z_b**2)),
                    (sym("z_lo_q_th"), sp.S.Zero),  # replaced after the bottom
                    (sym("z_lo_q_thd"), sp.S.Zero),
                ),
                comment="held touchdown state; bottom from p_r_td^2 = 2 m F_r(td) D + k_c D^2",
            ),
        ),
        **_ZEROTH_KERNEL,
    )


#: The parameters every zeroth iterate's kernel takes (after the touchdown state), used or not.
_ZEROTH_PARAMS = ("m", "l0", "k_c", "k_d", "g_s", "q_r_lo")


def _zeroth_args() -> tuple[Arg, ...]:
    from ..catalog import PARAMS, TOUCHDOWN

    return TOUCHDOWN + tuple(PARAMS[n] for n in _ZEROTH_PARAMS)


@cache
def zeroth_kernel(name: str) -> Kernel:
    """The zeroth iterate of choice ``name`` (:func:`zeroth_option`) as a kernel of the touchdown
    state and :data:`_ZEROTH_PARAMS` returning :data:`ZEROTH_OUTPUTS`: :func:`held_kernel`, or a call
    of the map's stance at its default options with the stiffness k_c (k_d as given). Every choice's
    kernel has the same arguments and outputs (:data:`_ZEROTH_KERNEL`)."""
    if name == HELD:
        return held_kernel()
    spec = next(s for s in zeroth_maps() if s.name == name)
    args = _zeroth_args()
    touchdown = tuple(a.symbol for a in args[:4])
    p = {a.name: a.symbol for a in args[4:]}
    bind = {f"bottom_{q}": f"z_b_{q}" for q in ("q_r", "q_th", "q_thd")}
    bind.update({f"liftoff_{q}": f"z_lo_{q}" for q in ("q_th", "q_thd")})
    return Kernel(
        name=f"zeroth_{spec.ident}",
        # (one summary for every map's: their docstrings are written once, derive/generate.py)
        summary="A zeroth iterate of the iterative maps (option zeroth): a map's bottom and liftoff states "
        "with the stiffness k_c.",
        equations=(),
        args=args,
        steps=(spec.stance_call(touchdown, {**p, "k": p["k_c"]}, bind, comment=f"stance: {spec.title}"),),
        **_ZEROTH_KERNEL,
    )


def zeroth_bottom(touchdown, p: dict, q_r_lo) -> Switch:
    """The zeroth iterate (:data:`ZEROTH_OUTPUTS`) from the touchdown state, before the compression
    half: a call of the choice's :func:`zeroth_kernel` (q_r_lo as given: a compression half passes
    q_r_td, as only the bottom is used). A choice's kernels differ in this callee only (and the
    held choice's in its flag ``held``): derive/share.py renders their code once."""
    zeroth = zeroth_option()
    given = {**p, "k_d": p.get("k_d", p["k_c"]), "q_r_lo": q_r_lo}
    args = {
        a.name: x
        for a, x in zip(_zeroth_args(), (*touchdown, *(given[n] for n in _ZEROTH_PARAMS)), strict=True)
    }
    bind = {n: n for n in ZEROTH_OUTPUTS}
    cases = tuple(
        (
            zeroth.code(name),
            (Call(zeroth_kernel(name), args, bind, comment="zeroth iterate (option zeroth)"),),
        )
        for name in (HELD, *(s.name for s in zeroth_maps()))
    )
    return Switch(sym(zeroth.name), cases, comment="zeroth iterate")


def zeroth_arguments() -> tuple[Arg, ...]:
    """The zeroth iterate (:data:`ZEROTH_OUTPUTS`) and the flag ``held`` (1 for the held choice) as
    arguments of an iteration's kernel."""
    return tuple(Arg(sym(n), f"zeroth iterate: {n}") for n in ZEROTH_OUTPUTS) + (
        Arg(sym("held"), "1 when the zeroth iterate is the held touchdown state, else 0"),
    )


def zeroth_values() -> dict[str, sp.Basic]:
    """What a map's steps pass for :func:`zeroth_arguments` (after :func:`zeroth_bottom`): the
    zeroth iterate's names, and ``held`` (a number once the choice is specialized)."""
    held = sp.Piecewise((sp.S.One, zeroth_option().is_(HELD)), (sp.S.Zero, True))
    return {**{n: sym(n) for n in ZEROTH_OUTPUTS}, "held": held}


def held_liftoff(bottom: tuple, q_r_lo) -> tuple[sp.Basic, sp.Basic]:
    """The held bottom state's liftoff (q_th, q_thd): angle and angular momentum of the bottom."""
    q_r_b, _, q_th_b, q_thd_b = bottom
    return q_th_b, q_thd_b * q_r_b**2 / q_r_lo**2


def zeroth_liftoff(q_r_lo) -> Stage:
    """The zeroth iterate's liftoff ``g_lo_q_th``, ``g_lo_q_thd`` before the decompression half:
    the map's (``z_lo_*`` of :func:`zeroth_bottom`) or, held (the flag ``held`` of
    :func:`zeroth_arguments`), the computed bottom state's."""
    held = held_liftoff(tuple(sym(f"bottom_{q}") for q in _POLAR_NAMES), q_r_lo)
    is_held = sp.Eq(sym("held"), 1)
    return Stage(
        (
            (sym("g_lo_q_th"), sp.Piecewise((held[0], is_held), (sym("z_lo_q_th"), True))),
            (sym("g_lo_q_thd"), sp.Piecewise((held[1], is_held), (sym("z_lo_q_thd"), True))),
        ),
        comment="zeroth iterate at liftoff",
    )
